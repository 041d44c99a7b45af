//! Tag tables (docs/tags.md): the three formats in the encodings people save them in, the
//! problems each bad file gets (one message per problem, `file:line:column`), `plcsh tags`
//! listing, checking and exporting (a round trip), and IL programs with symbols: every K2
//! program of the project rewritten with generated names — declared in a `VAR_GLOBAL` block,
//! and in a separate CP1251 CSV — compiles to the same instructions and runs scan for scan
//! like the program written with addresses.

mod common;

use plcsh::core::{Clock, OperandSpace};
use plcsh::engine::source::{self, Stmt};
use plcsh::k2::catalog;
use plcsh::k2::operand::Area;
use plcsh::k2::sim::K2Sim;
use plcsh::k2::space::K2Space;
use plcsh::tags::{name, TagFormat, TagTable, TagType};
use std::path::{Path, PathBuf};
use std::time::{Duration, Instant};

fn world(test: &str) -> PathBuf {
    let d = std::env::temp_dir().join(format!("plcsh-tags-{}-{test}", std::process::id()));
    let _ = std::fs::remove_dir_all(&d);
    std::fs::create_dir_all(&d).unwrap();
    d
}

/// Windows-1251 bytes of `s` (ASCII, А–я, Ё, ё, №): what a Russian Windows saves.
fn cp1251(s: &str) -> Vec<u8> {
    s.chars()
        .map(|c| match c {
            c if c.is_ascii() => c as u8,
            'А'..='я' => (c as u32 - 0x0410 + 0xC0) as u8,
            'Ё' => 0xA8,
            'ё' => 0xB8,
            '№' => 0xB9,
            c => panic!("{c} is not in this test's Windows-1251 table"),
        })
        .collect()
}

fn utf16le_bom(s: &str) -> Vec<u8> {
    [0xFF, 0xFE].into_iter().chain(s.encode_utf16().flat_map(|u| u.to_le_bytes())).collect()
}

fn k2() -> K2Space {
    K2Space::new(catalog::find(catalog::DEFAULT_MODEL).unwrap())
}

/// Every problem loading `bytes` as the file `origin` (in the test's folder, named as given)
/// for the simulated K2 finds, as the lines a person reads.
fn problems(bytes: &[u8], origin: &str) -> Vec<String> {
    let dir = world(&format!("problems-{origin}"));
    std::fs::write(dir.join(origin), bytes).unwrap();
    let r = plcsh::profile::tags::load(&dir.join(origin), None, &k2());
    let _ = std::fs::remove_dir_all(&dir);
    let prefix = format!("{}{}", dir.display(), std::path::MAIN_SEPARATOR);
    match r {
        Ok(_) => Vec::new(),
        Err(p) => p.0.iter().map(|p| p.to_string().replacen(&prefix, "", 1)).collect(),
    }
}

#[test]
fn every_format_and_encoding_loads() {
    let space = k2();
    // A CP1251 CSV with Cyrillic names and comments, as a Russian spreadsheet saves it.
    let ru =
        "Имя;Адрес;Тип;Комментарий\r\nМотор_1_Пуск;Q0.0;BOOL;Пуск мотора №1\r\nУровень_Бак2;VD200;REAL;Уровень, м\r\n";
    let t = TagTable::parse(&cp1251(ru), "press.csv", None).unwrap();
    assert_eq!(t.encoding(), Some(plcsh::core::encoding::Encoding::Windows1251));
    let m = t.get("мотор_1_пуск").expect("names are case-insensitive in every script");
    assert_eq!((m.address.as_str(), m.comment.as_str()), ("Q0.0", "Пуск мотора №1"));
    assert_eq!(t.get("УРОВЕНЬ_БАК2").unwrap().resolve(&space).unwrap().dtype, plcsh::core::DataType::Real);
    // Chinese names in UTF-16 with its byte-order mark (Notepad's "Unicode"), tab-separated.
    let zh = "名称\t地址\t数据类型\t注释\n电机_启动\t%MX0.3\tBOOL\t启动按钮\n液位_2\t%VW10\tINT\t\n";
    let t = TagTable::parse(&utf16le_bom(zh), "线.csv", None).unwrap();
    assert_eq!(t.get("电机_启动").unwrap().address, "M0.3");
    // The same in UTF-8, with and without the BOM.
    let bom = [&[0xEF, 0xBB, 0xBF][..], zh.as_bytes()].concat();
    assert_eq!(TagTable::parse(&bom, "z.csv", None).unwrap().len(), 2);
    assert_eq!(TagTable::parse(zh.as_bytes(), "z.csv", None).unwrap().len(), 2);
    // TOML and IEC, told by their text when the name does not say.
    let toml =
        "[tags]\nConveyor_Run = \"M0.3\"\nTank2_Level = { address = \"VD200\", type = \"REAL\", comment = \"m\" }\n";
    let t = TagTable::parse(toml.as_bytes(), "tags.txt.x", None).unwrap();
    assert_eq!(t.format(), Some(TagFormat::Toml));
    assert_eq!(t.get("tank2_level").unwrap().dtype, TagType::Of(plcsh::core::DataType::Real));
    let iec = "VAR_GLOBAL\n  Conveyor_Run AT %MX0.3 : BOOL; (* belt *)\n  Tank2_Level AT %VD200 : REAL;\nEND_VAR\n";
    let t = TagTable::parse(iec.as_bytes(), "vars.exp", None).unwrap();
    assert_eq!(t.format(), Some(TagFormat::Iec));
    assert_eq!(t.get("CONVEYOR_RUN").unwrap().comment, "belt");
    assert_eq!(t.suggest("Conveyr_Run"), ["Conveyor_Run"]);
}

#[test]
fn every_bad_file_gets_one_message_per_problem_with_its_place() {
    // Duplicates (case does not make a name new), operand-like and command-word names.
    let p = problems(b"name,address\nLevel,VW0\nLEVEL,VW2\nVW1,VW4\nX0,VW6\nwatch,VW8\n", "d.csv");
    assert_eq!(p.len(), 4, "{p:#?}");
    assert!(p[0].starts_with("d.csv:3:1: `LEVEL` is defined again (as `Level` at line 2"), "{p:#?}");
    assert!(p[1].starts_with("d.csv:4:1: `VW1` reads as an operand of K2"), "{p:#?}");
    assert!(p[2].starts_with("d.csv:5:1: `X0` reads as an operand of FX"), "{p:#?}");
    assert!(p[3].starts_with("d.csv:6:1: `watch` is a command word"), "{p:#?}");
    // Overlaps of different sizes (reported by the check; the table still loads, with them
    // as its warnings); the same operand under two names is an alias.
    let overlaps = b"name,address,type\nLevel,VD200,REAL\nFlags,VW202,\nBit,V200.1,\nAlias,VD200,DINT\n";
    let t = TagTable::parse(overlaps, "o.csv", None).unwrap();
    let p: Vec<String> = t.check(&[&k2()]).iter().map(|p| p.to_string()).collect();
    assert_eq!(p.len(), 2, "{p:#?}");
    assert!(p[0].starts_with("o.csv:3:1: `Flags` (VW202) overlaps `Level` (VD200, line 2)"), "{p:#?}");
    assert!(p[1].starts_with("o.csv:4:1: `Bit` (V200.1) overlaps"), "{p:#?}");
    let t = plcsh::profile::tags::check(t, &k2()).unwrap();
    assert_eq!(t.warnings().len(), 2);
    // A type that does not fit its address, and an address that is no operand.
    let p = problems(b"[tags]\nA = { address = \"VW0\", type = \"REAL\" }\nB = \"VX0\"\n", "t.toml");
    assert_eq!(p.len(), 2, "{p:#?}");
    assert!(p[0].starts_with("t.toml:2:1: `A`: type REAL does not fit VW0 (16 bits)"), "{p:#?}");
    assert!(p[1].starts_with("t.toml:3:1: `B`: VX0 is not an operand here"), "{p:#?}");
    // Broken encodings: UTF-16 cut in the middle of a character.
    let p = problems(&[0xFF, 0xFE, b'A', 0, b',', 0, b'V'], "u.csv");
    assert_eq!(p.len(), 1, "{p:#?}");
    assert!(p[0].starts_with("u.csv:1:1: UTF-16 text") && p[0].contains("byte 6"), "{p:#?}");
    // Control characters in a name are written out, never sent to the terminal raw.
    let p = problems(b"name,address\nA\x1b[31m,VW0\n", "c.csv");
    assert!(p[0].contains("\\u{1B}") && !p[0].contains('\x1b'), "{p:#?}");
}

#[test]
fn a_hundred_thousand_tags_read_and_check_in_linear_time() {
    let space = k2();
    let n = 100_000;
    let mut csv = String::from("name,address,type,comment\n");
    for i in 0..n {
        // Every tag on one of 2048 words: the same operand under many names is allowed.
        csv.push_str(&format!("Tag_{i},VW{},INT,comment {i}\n", (i % 2048) * 2));
    }
    let start = Instant::now();
    let t = TagTable::parse(csv.as_bytes(), "big.csv", None).unwrap();
    let t = plcsh::profile::tags::check(t, &space).unwrap();
    assert_eq!(t.len(), n);
    assert!(t.get("tag_99999").is_some());
    // 100 000 problems: one message each, no panic.
    let dup: String =
        std::iter::once("name,address\n".to_string()).chain((0..n).map(|_| "Same,VW0\n".to_string())).collect();
    let p = TagTable::parse(dup.as_bytes(), "dup.csv", None).unwrap_err();
    assert_eq!(p.0.len(), n - 1);
    assert!(start.elapsed() < Duration::from_secs(60), "{:?}", start.elapsed());
}

fn plcsh_in(dir: &Path, args: &[&str]) -> std::process::Output {
    let mut c = common::plcsh();
    c.current_dir(dir).args(args);
    c.output().unwrap()
}

#[test]
fn tags_lists_checks_and_exports_with_a_round_trip() {
    let dir = world("cli");
    std::fs::write(
        dir.join("press.csv"),
        cp1251("Имя;Адрес;Тип;Комментарий\nМотор_1_Пуск;Q0.0;BOOL;Пуск, мотор 1\nУровень;VD200;REAL;\nСчёт;VW10;;\n"),
    )
    .unwrap();
    let o = plcsh_in(&dir, &["tags", "press.csv"]);
    assert!(o.status.success(), "{}", common::both(&o));
    let out = common::stdout(&o);
    assert!(out.contains("Мотор_1_Пуск") && out.contains("VD200/REAL") && out.contains("Пуск, мотор 1"), "{out}");
    let o = plcsh_in(&dir, &["--json", "tags", "press.csv"]);
    let v = &common::json_lines(&o)[0];
    assert_eq!(v["tags"][2]["name"], "Счёт");
    assert_eq!(v["tags"][2]["type"], "WORD");
    assert_eq!(v["tags"][1]["operand"], "VD200/REAL");
    let o = plcsh_in(&dir, &["tags", "check", "press.csv"]);
    assert_eq!(o.status.code(), Some(0), "{}", common::both(&o));
    assert!(common::stdout(&o).contains("3 tags, no problems"));
    // Export to each form and read it back: the same tags.
    let first = TagTable::load(&dir.join("press.csv")).unwrap();
    for (to, file) in [("csv", "back.csv"), ("iec", "back.st")] {
        let o = plcsh_in(&dir, &["tags", "export", "press.csv", "--to", to, "-o", file]);
        assert!(o.status.success(), "{to}: {}", common::both(&o));
        let back = TagTable::load(&dir.join(file)).unwrap();
        assert_eq!(back.len(), first.len());
        for (a, b) in first.iter().zip(back.iter()) {
            assert_eq!((&a.name, &a.address, &a.comment), (&b.name, &b.address, &b.comment), "{to}");
            let want = a.resolve(&k2()).unwrap();
            assert_eq!(b.resolve(&k2()).unwrap(), want, "{to}: the same operand");
        }
    }
    // A bad file: exit status 1, one line per problem.
    std::fs::write(dir.join("bad.csv"), "name,address\nA,VW0\na,VW2\nQ0,VW4\n").unwrap();
    std::fs::write(dir.join("over.csv"), "name,address\nA,VW0\nB,VB1\n").unwrap();
    let o = plcsh_in(&dir, &["tags", "check", "over.csv"]);
    assert_eq!(o.status.code(), Some(1), "check reports overlaps: {}", common::both(&o));
    let o = plcsh_in(&dir, &["tags", "over.csv"]);
    assert!(o.status.success() && common::stderr(&o).contains("overlaps"), "listed, with a note: {}", common::both(&o));
    let o = plcsh_in(&dir, &["tags", "check", "bad.csv"]);
    assert_eq!(o.status.code(), Some(1));
    let lines: Vec<String> = common::stdout(&o).lines().map(String::from).collect();
    assert_eq!(lines.len(), 2, "{lines:?}");
    assert!(lines[0].starts_with("bad.csv:3:1: ") && lines[1].starts_with("bad.csv:4:1: "), "{lines:?}");
    let o = plcsh_in(&dir, &["--json", "tags", "check", "bad.csv"]);
    let v = &common::json_lines(&o)[0];
    assert_eq!(v["ok"], false);
    assert_eq!(v["problems"][1]["code"], "tags-name-is-operand");
    let _ = std::fs::remove_dir_all(&dir);
}

/// A program with its operands replaced by generated names (Latin and Cyrillic), and the tags:
/// (name, address, natural type). Operands are found by the engine's own lexer; literals,
/// labels, POU names, views (`/REAL`) and pointers' targets stay as written.
fn symbolize(text: &str, space: &dyn OperandSpace) -> (String, Vec<(String, String, String)>) {
    let stmts = source::parse(text).expect("the program lexes");
    let mut lines: Vec<Vec<char>> = text.split('\n').map(|l| l.chars().collect()).collect();
    let mut tags: Vec<(String, String, String)> = Vec::new();
    let mut edits: Vec<(usize, usize, usize, String)> = Vec::new();
    for s in &stmts {
        let Stmt::Instr { operands, .. } = s else { continue };
        for o in operands {
            let skip = o.text.len() - o.text.trim_start_matches(['*', '&']).len();
            let inner = &o.text[skip..];
            if inner.contains(['/', '#']) || inner.starts_with(|c: char| c.is_ascii_digit() || c == '-' || c == '+') {
                continue;
            }
            let Ok(ops) = space.parse(inner) else { continue };
            if ops.len() != 1 {
                continue;
            }
            let (line, col) = (o.pos.line as usize - 1, o.pos.col as usize - 1 + skip);
            let width = inner.chars().count();
            let written: String = lines[line].get(col..col + width).map(|c| c.iter().collect()).unwrap_or_default();
            if !written.eq_ignore_ascii_case(inner) {
                continue;
            }
            let address = name::address_text(inner);
            let i = match tags.iter().position(|t| t.1 == address) {
                Some(i) => i,
                None => {
                    let prefix = if tags.len().is_multiple_of(2) { "Tag" } else { "Тег" };
                    let n = format!("{prefix}_{}", address.replace('.', "_"));
                    tags.push((n, address.clone(), ops[0].dtype.name().to_string()));
                    tags.len() - 1
                }
            };
            edits.push((line, col, width, tags[i].0.clone()));
        }
    }
    // From the end of each line, so earlier columns stay right.
    edits.sort_by_key(|e| std::cmp::Reverse((e.0, e.1)));
    for (line, col, width, name) in edits {
        lines[line].splice(col..col + width, name.chars());
    }
    let out: Vec<String> = lines.into_iter().map(|l| l.into_iter().collect()).collect();
    (out.join("\n"), tags)
}

/// Runs `n` scans with inputs that change every few scans (the same for every version) and
/// returns every area's bytes after each scan.
fn run(sim: &mut K2Sim, n: usize) -> Vec<Vec<u8>> {
    let mut trace = Vec::new();
    for i in 0..n {
        let pattern = [(i / 7 % 256) as u8, (i * 37 / 11 % 256) as u8];
        sim.mem.area_mut(Area::I)[..2].copy_from_slice(&pattern);
        sim.scan_n(1).expect("a scan");
        let m = &sim.mem;
        let mut all = Vec::new();
        for a in [Area::Q, Area::M, Area::V, Area::SM, Area::AQ] {
            all.extend_from_slice(m.area(a));
        }
        all.extend(m.t.iter().chain(&m.c).flat_map(|v| v.to_le_bytes()));
        all.extend_from_slice(&m.tq);
        all.extend_from_slice(&m.cq);
        trace.push(all);
    }
    trace
}

#[test]
fn programs_with_symbols_run_like_programs_with_addresses() {
    let root = Path::new(env!("CARGO_MANIFEST_DIR"));
    let model = catalog::find(catalog::DEFAULT_MODEL).unwrap();
    let space = K2Space::new(model);
    let mut programs: Vec<(String, String)> = vec![("k2_agent.il".into(), plcsh::k2::agent::il::program(model, 3000))];
    for dir in ["scripts", "tests/lab/submissions", "tests/lab/conveyor"] {
        let mut files: Vec<PathBuf> = std::fs::read_dir(root.join(dir)).unwrap().map(|e| e.unwrap().path()).collect();
        files.sort();
        for f in files.into_iter().filter(|f| f.extension().is_some_and(|e| e == "il")) {
            let text = plcsh::core::encoding::read_source(&f).unwrap();
            programs.push((f.file_name().unwrap().to_string_lossy().into_owned(), text));
        }
    }
    let dir = world("differential");
    let mut compared = 0;
    for (file, text) in &programs {
        let mut plain = K2Sim::new(model, Clock::stepped());
        let Ok(want) = plain.compile(text, file) else { continue }; // another family's, or a bad submission
        let (named, tags) = symbolize(text, &space);
        assert!(!tags.is_empty(), "{file}: no operand found");
        // (1) The tags declared in the program, as an exported program declares them.
        let mut block = String::from("VAR_GLOBAL\n");
        for (n, a, t) in &tags {
            block.push_str(&format!("    {n} AT %{a} : {t}; (* {a} *)\n"));
        }
        block.push_str("END_VAR\n");
        let declared = format!("{block}{named}");
        // (2) The tags in a CSV beside the program, saved in Windows-1251.
        let csv: String = std::iter::once("Имя;Адрес;Тип\n".to_string())
            .chain(tags.iter().map(|(n, a, t)| format!("{n};{a};{t}\n")))
            .collect();
        let csv_path = dir.join(format!("{file}.csv"));
        std::fs::write(&csv_path, cp1251(&csv)).unwrap();
        let table = plcsh::profile::tags::load(&csv_path, None, &space).unwrap_or_else(|p| panic!("{file}: {p}"));
        let mut by_block = K2Sim::new(model, Clock::stepped());
        let mut by_file = K2Sim::new(model, Clock::stepped());
        let a = by_block.compile(&declared, file).unwrap_or_else(|e| panic!("{file}: {e}"));
        let b = by_file.compile_with_tags(&named, file, Some(&table)).unwrap_or_else(|e| panic!("{file}: {e}"));
        assert_eq!(a.code, want.code, "{file}: VAR_GLOBAL version compiles to other instructions");
        assert_eq!(b.code, want.code, "{file}: tag-file version compiles to other instructions");
        plain.load_program(text, file).unwrap();
        by_block.load_program(&declared, file).unwrap();
        by_file.load_program_with_tags(&named, file, Some(&table)).unwrap();
        let t0 = run(&mut plain, 300);
        assert_eq!(run(&mut by_block, 300), t0, "{file}: the VAR_GLOBAL version runs differently");
        assert_eq!(run(&mut by_file, 300), t0, "{file}: the tag-file version runs differently");
        compared += 1;
    }
    assert!(compared >= 5, "only {compared} programs compared");
    let _ = std::fs::remove_dir_all(&dir);
}

/// The UMPK loads through the same engine: its lab programs with symbols (a `VAR_GLOBAL`
/// block, and a UTF-16 CSV beside them) compile to the instructions of the address version.
#[test]
fn umpk_programs_with_symbols_compile_like_programs_with_addresses() {
    use plcsh::umpk::sim::program::UmpkFamily;
    let root = Path::new(env!("CARGO_MANIFEST_DIR"));
    let model = plcsh::umpk::model::find("UMPK16").unwrap();
    let fam = UmpkFamily::new(model);
    let mut compared = 0;
    for f in [root.join("scripts/umpk_lab1.il"), root.join("tests/lab/umpk/reference.il")] {
        let text = plcsh::core::encoding::read_source(&f).unwrap();
        let want = plcsh::engine::compile(&text, "p.il", &fam).unwrap_or_else(|e| panic!("{}: {e}", f.display()));
        let (named, tags) = symbolize(&text, &fam.space);
        assert!(!tags.is_empty(), "{}: no operand found", f.display());
        let block: String = tags.iter().map(|(n, a, t)| format!("  {n} AT %{a} : {t};\n")).collect();
        let declared = format!("VAR_GLOBAL\n{block}END_VAR\n{named}");
        let a = plcsh::engine::compile(&declared, "p.il", &fam).unwrap_or_else(|e| panic!("{}: {e}", f.display()));
        assert_eq!(a.code, want.code, "{}", f.display());
        let csv: String = std::iter::once("名称,地址,类型\n".to_string())
            .chain(tags.iter().map(|(n, a, t)| format!("{n},{a},{t}\n")))
            .collect();
        let table = TagTable::parse(&utf16le_bom(&csv), "t.csv", None).unwrap();
        let table = plcsh::profile::tags::check(table, &fam.space).unwrap_or_else(|p| panic!("{p}"));
        let b = plcsh::engine::compile_with_tags(&named, "p.il", &fam, Some(&table)).unwrap();
        assert_eq!(b.code, want.code, "{}", f.display());
        compared += 1;
    }
    assert_eq!(compared, 2);
}

#[test]
fn load_errors_name_the_unknown_symbol_and_the_nearest_tag() {
    let model = catalog::find(catalog::DEFAULT_MODEL).unwrap();
    let sim = K2Sim::new(model, Clock::stepped());
    let prog = "VAR_GLOBAL\n  Start_Button AT %I0.0 : BOOL;\n  Motor_Run AT %Q0.0 : BOOL;\nEND_VAR\nLD Start_Button\nST Motr_Run\n";
    let e = sim.compile(prog, "p.il").unwrap_err();
    assert!(e.message.contains("p.il:6:4") && e.message.contains("Motr_Run") && e.message.contains("Motor_Run"), "{e}");
    // A declaration whose address is no operand of this PLC: at the declaration.
    let e = sim.compile("VAR_GLOBAL\n  X_1 AT %VW99999 : INT;\nEND_VAR\nLD %SM0.0\n", "q.il").unwrap_err();
    assert!(e.message.starts_with("q.il:2:3: tag `X_1`"), "{e}");
    // A bad declaration: the tag file's message with its place.
    let e = sim.compile("VAR_GLOBAL\n  A AT %VW0 : FLOAT;\nEND_VAR\n", "r.il").unwrap_err();
    assert!(e.message.starts_with("r.il:2:15: `A`: unknown type `FLOAT`"), "{e}");
    // The same name in the program and in the tag file.
    let t = TagTable::parse(b"name,address\nStart_Button,I0.1\n", "t.csv", None).unwrap();
    let e = sim.compile_with_tags(prog, "p.il", Some(&t)).unwrap_err();
    assert!(
        e.message.starts_with("p.il:2:3: tag `Start_Button` is declared in the program and in t.csv (line 2)"),
        "{e}"
    );
}

/// A command word cannot name a tag (`get get` would read two ways): the list the tag
/// module keeps is the shell's command registry (names and aliases) and the program's
/// sub-commands, no more and no less.
#[test]
fn the_taken_command_words_are_the_registry_s() {
    use clap::CommandFactory;
    let mut words: Vec<String> = Vec::new();
    for c in plcsh::shell::commands::COMMANDS {
        words.push(c.name.to_string());
        words.extend(c.aliases.iter().map(|a| a.to_string()));
    }
    for sub in plcsh::cli::Cli::command().get_subcommands() {
        words.push(sub.get_name().to_string());
    }
    words.retain(|w| w != "help" || plcsh::shell::commands::find("help").is_some());
    words.retain(|w| w.chars().all(|c| c.is_alphanumeric() || c == '_'));
    words.sort();
    words.dedup();
    let mut kept: Vec<String> = name::COMMAND_WORDS.iter().map(|w| w.to_string()).collect();
    kept.sort();
    assert_eq!(kept, words, "plcsh::tags::name::COMMAND_WORDS differs from the command registry");
}

/// A program loaded with a tag file beside it is kept with the tags, so a snapshot restores
/// it without the file (the docs' example program and tag file).
#[test]
fn a_snapshot_of_a_program_with_a_tag_file_restores_without_the_file() {
    let dir = world("snapshot");
    let root = Path::new(env!("CARGO_MANIFEST_DIR"));
    for f in ["batch.il", "press1.csv"] {
        std::fs::copy(root.join("docs/tags").join(f), dir.join(f)).unwrap();
    }
    let line = "sim program load batch.il tags=press1.csv; sim scan 2; sim snapshot save snap.json";
    let o = plcsh_in(&dir, &["--time", "stepped", "--state", "none", "-c", line]);
    assert!(o.status.success(), "{}", common::both(&o));
    std::fs::remove_file(dir.join("press1.csv")).unwrap();
    let o = plcsh_in(
        &dir,
        &["--time", "stepped", "--state", "none", "-c", "sim snapshot restore snap.json; sim scan 2; get VW10"],
    );
    assert!(o.status.success(), "{}", common::both(&o));
    assert!(common::stdout(&o).contains("VW10  5"), "{}", common::both(&o));
    let _ = std::fs::remove_dir_all(&dir);
}

/// An FX list with its operands replaced by generated names (Latin, Cyrillic and Chinese), and
/// the tags (name, address, natural type). FX lists separate operands with spaces, so each
/// operand text of the engine's lexer is split as the FX front end splits it; constants
/// (`K50`, `H1F`) and the step numbers of a list export stay as written.
fn symbolize_fx(text: &str, space: &dyn OperandSpace) -> (String, Vec<(String, String, String)>) {
    let stmts = source::parse(text).expect("the list lexes");
    let mut lines: Vec<Vec<char>> = text.split('\n').map(|l| l.chars().collect()).collect();
    let mut tags: Vec<(String, String, String)> = Vec::new();
    let mut edits: Vec<(usize, usize, usize, String)> = Vec::new();
    for s in &stmts {
        let Stmt::Instr { operands, .. } = s else { continue };
        for o in operands {
            let mut col = o.pos.col as usize - 1;
            for part in o.text.split(' ') {
                let width = part.chars().count();
                let at = col;
                col += width + 1;
                let constant = part.starts_with(['K', 'H', 'k', 'h']) && !part.contains(['X', 'Y', 'M', 'S']);
                if part.is_empty() || constant {
                    continue;
                }
                let Ok(ops) = space.parse(part) else { continue };
                if ops.len() != 1 {
                    continue;
                }
                let line = o.pos.line as usize - 1;
                let address = part.to_ascii_uppercase();
                let i = match tags.iter().position(|t| t.1 == address) {
                    Some(i) => i,
                    None => {
                        let prefix = ["Tag", "Тег", "标签"][tags.len() % 3];
                        tags.push((format!("{prefix}_{address}"), address.clone(), ops[0].dtype.name().to_string()));
                        tags.len() - 1
                    }
                };
                edits.push((line, at, width, tags[i].0.clone()));
            }
        }
    }
    edits.sort_by_key(|e| std::cmp::Reverse((e.0, e.1)));
    for (line, col, width, name) in edits {
        lines[line].splice(col..col + width, name.chars());
    }
    let out: Vec<String> = lines.into_iter().map(|l| l.into_iter().collect()).collect();
    (out.join("\n"), tags)
}

/// Runs an FX PLC for `n` steps of 10 ms with inputs X0–X7 that change every few steps (the
/// same for every version) and returns its outputs, relays, states, timers, counters and
/// data registers after each.
fn run_fx(program: plcsh::fx::program::Loaded, model: &'static plcsh::fx::model::Model, n: usize) -> Vec<Vec<u32>> {
    use plcsh::fx::operand::Area;
    let clock = Clock::stepped();
    let mut m = plcsh::fx::memory::Memory::with_clock(model, clock.clone());
    m.load_program(program);
    let mut trace = Vec::new();
    for i in 0..n {
        let pattern = (i / 3 % 256) as u8 ^ (i * 37 / 11 % 256) as u8;
        for x in 0..8u16 {
            m.set_input(x, pattern >> x & 1 == 1);
        }
        clock.step(Duration::from_millis(10));
        m.advance();
        let mut all = Vec::new();
        for (area, count) in [(Area::Y, 64u16), (Area::M, 1024), (Area::S, 64), (Area::TS, 256), (Area::CS, 256)] {
            all.extend((0..count).map(|k| u32::from(m.bit(area, k).unwrap_or(false))));
        }
        for (area, count) in [(Area::TN, 256u16), (Area::CN, 256), (Area::D, 512)] {
            all.extend((0..count).map(|k| m.word(area, k).unwrap_or(0)));
        }
        trace.push(all);
    }
    trace
}

/// The FX front end reads symbols as the engine's loaders do: every FX list of the project
/// rewritten with generated names — declared in a `VAR_GLOBAL` block, and in a UTF-16 CSV
/// beside it — compiles to the instructions of the list written with addresses and runs the
/// same, step for step; the list kept for a snapshot (the tag file's tags appended) loads again
/// without the file.
#[test]
fn fx_programs_with_symbols_run_like_programs_with_addresses() {
    use plcsh::fx::program::Loaded;
    let root = Path::new(env!("CARGO_MANIFEST_DIR"));
    let model = plcsh::fx::model::Model::find("FX3U").unwrap();
    let space = plcsh::fx::space::FxSpace::new(model, plcsh::fx::space::Proto::Port);
    let dir = world("fx-differential");
    let mut compared = 0;
    for folder in ["scripts", "fuzz/corpus/fx_il"] {
        let mut files: Vec<PathBuf> =
            std::fs::read_dir(root.join(folder)).unwrap().map(|e| e.unwrap().path()).collect();
        files.sort();
        for f in files.into_iter().filter(|f| f.extension().is_some_and(|e| e == "il")) {
            let file = f.file_name().unwrap().to_string_lossy().into_owned();
            let text = plcsh::core::encoding::read_source(&f).unwrap();
            let Ok(want) = Loaded::load(&text, &file, model) else { continue }; // a K2 list, or a bad one
            let (named, tags) = symbolize_fx(&text, &space);
            assert!(!tags.is_empty(), "{file}: no operand found");
            let block: String = tags.iter().map(|(n, a, t)| format!("    {n} AT %{a} : {t};\n")).collect();
            let declared = format!("VAR_GLOBAL\n{block}END_VAR\n{named}");
            let csv: String = std::iter::once("Имя;Адрес;Тип\n".to_string())
                .chain(tags.iter().map(|(n, a, t)| format!("{n};{a};{t}\n")))
                .collect();
            let csv_path = dir.join(format!("{file}.csv"));
            std::fs::write(&csv_path, utf16le_bom(&csv)).unwrap();
            let table = plcsh::profile::tags::load(&csv_path, None, &space).unwrap_or_else(|p| panic!("{file}: {p}"));
            let a = Loaded::load(&declared, &file, model).unwrap_or_else(|e| panic!("{file}: {e}\n{declared}"));
            let b =
                Loaded::load_with_tags(&named, &file, model, Some(&table)).unwrap_or_else(|e| panic!("{file}: {e}"));
            assert_eq!(a.prog.code, want.prog.code, "{file}: VAR_GLOBAL version compiles to other instructions");
            assert_eq!(b.prog.code, want.prog.code, "{file}: tag-file version compiles to other instructions");
            assert_eq!(b.prog.pos, want.prog.pos, "{file}: tag-file version: other source lines");
            // The block above the list moves its lines down by the block's, no more.
            let shift = tags.len() as u32 + 2;
            let moved: Vec<u32> = want.prog.pos.iter().map(|p| if p.line > 0 { p.line + shift } else { 0 }).collect();
            assert_eq!(
                a.prog.pos.iter().map(|p| p.line).collect::<Vec<_>>(),
                moved,
                "{file}: VAR_GLOBAL version's lines"
            );
            let kept = Loaded::load(&b.text, &file, model).unwrap_or_else(|e| panic!("{file}: kept: {e}\n{}", b.text));
            assert_eq!(kept.prog.code, want.prog.code, "{file}: the kept list");
            let t0 = run_fx(want, model, 400);
            assert_eq!(run_fx(a, model, 400), t0, "{file}: the VAR_GLOBAL version runs differently");
            assert_eq!(run_fx(b, model, 400), t0, "{file}: the tag-file version runs differently");
            compared += 1;
        }
    }
    assert!(compared >= 2, "only {compared} FX lists compared");
    let _ = std::fs::remove_dir_all(&dir);
}

/// An FX list's unknown symbol is refused at its line and column with the nearest tag; a
/// declaration whose address is no FX operand, at the declaration.
#[test]
fn fx_load_errors_name_the_unknown_symbol_and_the_nearest_tag() {
    use plcsh::fx::program::Loaded;
    let model = plcsh::fx::model::Model::find("FX2N").unwrap();
    let prog = "VAR_GLOBAL\n  Start_Button AT %X0 : BOOL;\n  Motor_Run AT %Y0 : BOOL;\nEND_VAR\nLD Start_Button\nOUT Motr_Run\n";
    let e = Loaded::load(prog, "p.il", model).unwrap_err();
    assert!(
        e.message.starts_with("p.il:6:5: ") && e.message.contains("Motr_Run") && e.message.contains("Motor_Run"),
        "{e}"
    );
    let e = Loaded::load("VAR_GLOBAL\n  Пуск AT %X0 : BOOL;\nEND_VAR\nLD Пуск\nMOV K1 Рецепт\n", "q.il", model)
        .unwrap_err();
    assert!(e.message.starts_with("q.il:5:8: ") && e.message.contains("`Рецепт`"), "{e}");
    let e = Loaded::load("VAR_GLOBAL\n  X_1 AT %X9 : BOOL;\nEND_VAR\nLD X_1\n", "r.il", model).unwrap_err();
    assert!(e.message.starts_with("r.il:2:3: tag `X_1`"), "{e}");
    // Without symbols a list is refused as before (no unknown-symbol wording).
    let e = Loaded::load("LD X0\nOUT Motor\n", "s.il", model).unwrap_err();
    assert!(!e.message.contains("not a tag"), "{e}");
}
