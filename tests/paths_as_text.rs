//! Paths are text (docs/commands.md, "Quoting"): every command that takes a file or a folder —
//! the shell's (the command registry's `TEXT_ARGS`) and the command line's (every path argument
//! clap knows) — runs with paths that hold Cyrillic letters, spaces and quotes, each test in a
//! folder of its own under the temp folder (on Windows that brings a drive letter and
//! backslashes). In the shell a path is written bare (Cyrillic look-alike letters only, which
//! the manual's spelling must not touch), in single quotes, in double quotes as typed and in
//! double quotes with escapes, in `-c` and in a command file on stdin. The cases are checked
//! against the registry's and clap's own lists, so a new command that takes a file fails
//! `every_command_that_takes_a_file_has_a_case` until it has one here. Lua files saved with a
//! byte-order mark load wherever plcsh loads Lua from a file.

mod common;
use common::*;
use std::path::{Path, PathBuf};
use std::process::{Output, Stdio};

/// The shell's file-taking words: `TEXT_ARGS` entries whose placeholder is a file or folder
/// (`FILE…`, `LAB`, `SUBMISSIONS…`, the NAME of `lab new` and `sim snapshot`), as
/// `command sub-words placeholder`.
fn shell_file_args() -> Vec<String> {
    plcsh::shell::commands::TEXT_ARGS
        .iter()
        .filter(|t| {
            let p = t.placeholder;
            p.contains("FILE")
                || p == "LAB"
                || p.starts_with("SUBMISSIONS")
                || p == "NAME" && ["lab", "sim"].contains(&t.cmd)
        })
        .map(|t| [&[t.cmd][..], t.after, &[t.placeholder]].concat().join(" "))
        .collect()
}

/// The command line's file-taking arguments: every argument of every sub-command that clap
/// reads as a path, or whose value names a FILE, DIR, LINK or PATH, as `plcsh sub --long` or
/// `plcsh sub <id>`.
fn cli_file_args() -> Vec<String> {
    use clap::CommandFactory;
    fn walk(cmd: &clap::Command, path: &str, out: &mut Vec<String>) {
        for a in cmd.get_arguments() {
            if a.is_global_set() && path != "plcsh" {
                continue; // listed once, where it is declared
            }
            let is_path = a.get_value_parser().type_id() == std::any::TypeId::of::<PathBuf>();
            let named =
                a.get_value_names().unwrap_or_default().iter().any(|n| {
                    ["FILE", "DIR", "LINK", "PATH"].iter().any(|k| n.as_str().split(['|', '.']).any(|p| p == *k))
                });
            if is_path || named {
                let name = a.get_long().map_or_else(|| format!("<{}>", a.get_id()), |l| format!("--{l}"));
                out.push(format!("{path} {name}"));
            }
        }
        for s in cmd.get_subcommands() {
            walk(s, &format!("{path} {}", s.get_name()), out);
        }
    }
    let mut out = Vec::new();
    walk(&plcsh::cli::Cli::command(), "plcsh", &mut out);
    out
}

/// Every case below and the file-taking words and arguments it runs.
const CASES: &[(&str, &[&str])] = &[
    ("sim_program_load_and_break", &["sim program load FILE.il", "sim break FILE:LINE"]),
    ("sim_snapshot_save_and_restore", &["sim snapshot save NAME", "sim snapshot restore NAME"]),
    ("eeprom_dump_and_restore", &["eeprom dump FILE", "eeprom restore FILE"]),
    ("servo_parameter_sets", &["servo params save FILE", "servo params diff FILE", "servo params load FILE"]),
    ("trace_and_plot_files", &["trace to=FILE.csv", "plot to=FILE.png"]),
    ("profile_plan_file", &["profile to=FILE.png"]),
    ("umpk_program_file", &["umpk program FILE.hex"]),
    ("lab_in_the_shell", &["lab new NAME", "lab check LAB", "lab grade SUBMISSIONS…"]),
    ("run_a_script", &["plcsh run <script>", "plcsh run --write-dir"]),
    ("config_state_and_bench_files", &["plcsh --config", "plcsh --state", "plcsh --bench"]),
    (
        "record_show_and_replay",
        &["plcsh --record", "plcsh record show <file>", "plcsh replay <file>", "plcsh replay --snapshot"],
    ),
    (
        "lab_on_the_command_line",
        &[
            "plcsh lab new <name>",
            "plcsh lab check <lab>",
            "plcsh lab grade <lab>",
            "plcsh lab grade <submissions>",
            "plcsh lab grade --junit",
            "plcsh lab worker <lab>",
            "plcsh lab worker --report",
            "plcsh lab worker --write-dir",
        ],
    ),
    ("completion_scripts_folder", &["plcsh completions --write"]),
    (
        "tag_files",
        &["plcsh tags <file>", "plcsh tags check <file>", "plcsh tags export <file>", "plcsh tags export --output"],
    ),
    ("probe_report_file", &["plcsh probe --report"]),
    (
        "served_simulators_files",
        &[
            "plcsh sim serve --program",
            "plcsh sim serve --fx-program",
            "plcsh sim serve --umpk-program",
            "plcsh sim serve --umpk-state",
            "plcsh sim serve --k2-control",
            "plcsh sim serve --servo-control",
            "plcsh sim serve --fx-control",
            "plcsh sim serve --umpk-control",
            "plcsh sim control <path>",
        ],
    ),
    (
        "served_simulators_pty_links",
        &[
            "plcsh sim serve --rtu-pty",
            "plcsh sim serve --servo-pty",
            "plcsh sim serve --fx-pty",
            "plcsh sim serve --fx-link-pty",
            "plcsh sim serve --umpk-pty",
        ],
    ),
];

#[test]
fn every_command_that_takes_a_file_has_a_case() {
    let covered: Vec<&str> = CASES.iter().flat_map(|c| c.1.iter().copied()).collect();
    let shell = shell_file_args();
    let cli = cli_file_args();
    assert!(shell.len() >= 10 && cli.len() >= 20, "the lists are read: {shell:?} {cli:?}");
    for k in shell.iter().chain(&cli) {
        assert!(covered.contains(&k.as_str()), "`{k}` takes a file: give it a case in tests/paths_as_text.rs");
    }
    for k in &covered {
        assert!(shell.iter().chain(&cli).any(|x| x == k), "`{k}` is no longer a file-taking word or argument");
    }
}

// --- Places and spellings ---------------------------------------------------------------

/// One way to write a path in a shell line.
#[derive(Clone, Copy, Debug)]
enum Spelling {
    Bare,
    Single,
    DoubleAsTyped,
    DoubleEscaped,
}

impl Spelling {
    fn write(self, p: &Path) -> String {
        let p = p.to_str().expect("a UTF-8 path");
        assert!(self.fits(p), "{self:?} cannot write {p}");
        match self {
            Spelling::Bare => p.to_string(),
            Spelling::Single => format!("'{p}'"),
            Spelling::DoubleAsTyped => format!("\"{p}\""),
            Spelling::DoubleEscaped => format!("\"{}\"", p.replace('\\', "\\\\").replace('"', "\\\"")),
        }
    }

    fn fits(self, p: &str) -> bool {
        match self {
            Spelling::Bare => !p.contains(|c: char| c.is_whitespace() || "\"',;#()[]{}=".contains(c)),
            Spelling::Single => !p.contains('\''),
            Spelling::DoubleAsTyped => !p.contains('"') && !p.contains("\\\\") && !p.ends_with('\\'),
            Spelling::DoubleEscaped => true,
        }
    }
}

/// A folder of this test's own (removed first: a rerun starts clean).
fn own_dir(test: &str) -> PathBuf {
    let d = std::env::temp_dir().join(format!("plcsh-paths-{}-{test}", std::process::id()));
    let _ = std::fs::remove_dir_all(&d);
    std::fs::create_dir_all(&d).unwrap();
    d
}

/// Folder names as they come on a lab PC, each with the spellings a shell line can use for
/// it: Cyrillic look-alike letters only (bare), a space (single quotes, double quotes as
/// typed), a quote (double quotes with escapes; Windows names hold no `"`).
const PLACES: &[(&str, Spelling)] = &[
    ("Проверка", Spelling::Bare),
    ("Лаб 1", Spelling::Single),
    ("Лаб 2", Spelling::DoubleAsTyped),
    (if cfg!(windows) { "Иванов's лаб" } else { "Иванов's \"лаб\"" }, Spelling::DoubleEscaped),
];

/// The places for a test: (folder, spelling, whether the line goes by `-c` or on stdin).
fn places(test: &str) -> Vec<(PathBuf, Spelling, bool)> {
    let base = own_dir(test);
    PLACES
        .iter()
        .enumerate()
        .map(|(i, (name, sp))| {
            let d = base.join(name);
            std::fs::create_dir_all(&d).unwrap();
            // A temp folder with a space (`C:\Documents and Settings`) cannot be written bare.
            let sp = if sp.fits(d.to_str().unwrap()) { *sp } else { Spelling::DoubleEscaped };
            (d, sp, i % 2 == 0)
        })
        .collect()
}

/// The folder with everything at once, for the command line's arguments (no spelling there).
fn odd_dir(test: &str) -> PathBuf {
    let d = own_dir(test).join(PLACES[3].0).join("Проверка 1");
    std::fs::create_dir_all(&d).unwrap();
    d
}

/// Runs `line` in the shell (stepped clock, JSON), by `-c` or as a command file on stdin,
/// with `args` before it; fails naming the line when any command fails.
fn shell(args: &[&str], line: &str, by_c: bool) -> Vec<serde_json::Value> {
    let mut c = plcsh();
    c.args(["--time", "stepped", "--json"]).args(args);
    let o = if by_c {
        c.args(["-c", line]).stdin(Stdio::null()).output_retrying().unwrap()
    } else {
        run_with_stdin(c, line)
    };
    assert!(o.status.success(), "`{line}` failed:\n{}", both(&o));
    json_lines(&o)
}

fn run_with_stdin(mut c: std::process::Command, input: &str) -> Output {
    let child = c.stdin(Stdio::piped()).stdout(Stdio::piped()).stderr(Stdio::piped()).spawn_retrying().unwrap();
    output_with_input(child, format!("{input}\n").as_bytes())
}

fn repo(rel: &str) -> PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR")).join(rel)
}

fn shown(p: &Path) -> String {
    p.display().to_string()
}

// --- The shell's commands -----------------------------------------------------------------

#[test]
fn sim_program_load_and_break() {
    for (dir, sp, by_c) in places("program") {
        let k2 = dir.join("светофор.il");
        std::fs::write(&k2, "LD %I0.0\n= %Q0.0\nLD %I0.1\n= %Q0.1\n").unwrap();
        let at_line = PathBuf::from(format!("{}:3", k2.display()));
        let l = shell(&[], &format!("sim program load {}; sim break {}", sp.write(&k2), sp.write(&at_line)), by_c);
        assert_eq!(l[0]["program"], shown(&k2), "{sp:?}: {l:?}");
        assert_eq!(l[1]["message"], format!("breakpoint at {}:3: LD %I0.1", k2.display()), "{sp:?}");
        // The UMPK's and the FX PLC's loaders read the same words.
        for (url, src, name) in [
            ("u=sim-umpk:", "scripts/umpk_lab1.il", "лаб_УМПК.il"),
            ("f=sim-fx:FX2N", "scripts/fx_blink.il", "мигалка.il"),
        ] {
            let p = dir.join(name);
            std::fs::copy(repo(src), &p).unwrap();
            let dev = &url[..1];
            let l = shell(&["-d", url], &format!("use {dev}; sim program load {}", sp.write(&p)), by_c);
            let msg = l[1]["message"].as_str().unwrap_or_default();
            assert!(msg.starts_with(&format!("{}: ", p.display())) && msg.contains("instructions loaded"), "{l:?}");
        }
    }
}

#[test]
fn sim_snapshot_save_and_restore() {
    for (dir, sp, by_c) in places("snapshot") {
        let snap = dir.join("до_пуска.json");
        let w = sp.write(&snap);
        let l = shell(
            &[],
            &format!("set VW0=321; sim snapshot save {w}; set VW0=0; sim snapshot restore {w}; get VW0"),
            by_c,
        );
        assert_eq!(l[1]["file"], shown(&snap), "{sp:?}: {l:?}");
        assert!(snap.is_file());
        assert_eq!(l[4]["values"][0]["value"], 321, "{l:?}");
    }
}

#[test]
fn eeprom_dump_and_restore() {
    for (dir, sp, by_c) in places("eeprom") {
        let file = dir.join("резерв.bin");
        let w = sp.write(&file);
        let l =
            shell(&[], &format!("set VB3648=165; eeprom dump {w}; set VB3648=0; eeprom restore {w}; get VB3648"), by_c);
        assert_eq!(std::fs::read(&file).unwrap().first(), Some(&165), "{sp:?}");
        assert_eq!(l[4]["values"][0]["value"], 165, "{l:?}");
    }
}

#[test]
fn servo_parameter_sets() {
    for (dir, sp, by_c) in places("params") {
        let file = dir.join("привод.toml");
        let w = sp.write(&file);
        let line = format!(
            "servo params save {w}; set servo:profile_velocity=1234; servo params diff {w}; servo params load {w}"
        );
        let l = shell(&[], &line, by_c);
        assert!(std::fs::read_to_string(&file).unwrap().contains("profile_velocity"), "{sp:?}");
        assert_eq!(l[0]["file"], shown(&file), "{sp:?}: {l:?}");
        assert_eq!(l[2]["count"], 1, "{sp:?}: {l:?}");
        assert_eq!(l[3]["written"][0]["name"], "profile_velocity", "{sp:?}: {l:?}");
    }
}

#[test]
fn trace_and_plot_files() {
    for (dir, sp, by_c) in places("trace") {
        let (csv, svg) = (dir.join("журнал.csv"), dir.join("график.svg"));
        let line = format!("trace VW0 every=10ms count=3 to={}; plot VW0 to={}", sp.write(&csv), sp.write(&svg));
        let l = shell(&[], &line, by_c);
        assert_eq!((&l[0]["file"], &l[1]["file"]), (&shown(&csv).into(), &shown(&svg).into()), "{sp:?}: {l:?}");
        assert!(std::fs::read_to_string(&csv).unwrap().contains("VW0"), "{sp:?}");
        assert!(std::fs::read_to_string(&svg).unwrap().contains("<svg"), "{sp:?}");
    }
}

#[test]
fn profile_plan_file() {
    for (dir, sp, by_c) in places("profile") {
        let svg = dir.join("профиль.svg");
        shell(&[], &format!("profile 0 at VB3001 [(cycle=500us, count=100)] plan to={}", sp.write(&svg)), by_c);
        assert!(std::fs::read_to_string(&svg).unwrap().contains("<svg"), "{sp:?}");
    }
}

#[test]
fn umpk_program_file() {
    for (dir, sp, by_c) in places("umpk") {
        let hex = dir.join("прошивка.hex");
        std::fs::copy(repo("docs/umpk-demo.hex"), &hex).unwrap();
        let l = shell(&["-d", "u=sim-umpk:"], &format!("umpk u program {}", sp.write(&hex)), by_c);
        assert!(l[0]["message"].as_str().unwrap_or_default().starts_with("programmed"), "{sp:?}: {l:?}");
    }
}

#[test]
fn lab_in_the_shell() {
    for (dir, sp, by_c) in places("lab") {
        let lab = dir.join("лаб");
        let w = sp.write(&lab);
        let sub = dir.join("Иванов.il");
        let l = shell(&[], &format!("lab new {w}; lab check {w}"), by_c);
        assert_eq!(l[1]["passed"], true, "{sp:?}: {l:?}");
        std::fs::copy(lab.join("reference.il"), &sub).unwrap();
        let l = shell(&[], &format!("lab grade {w} {} jobs=1", sp.write(&sub)), by_c);
        let r = &l[0]["submissions"][0];
        assert_eq!((&r["student"], &r["verdict"]), (&"Иванов".into(), &"passed".into()), "{sp:?}: {l:?}");
    }
}

/// A path with a space and no quotes is refused with the quoted form, never cut at the space.
#[test]
fn a_path_with_a_space_and_no_quotes_is_refused_with_the_quoted_form() {
    let dir = own_dir("unquoted").join("Лаб 1");
    std::fs::create_dir_all(&dir).unwrap();
    let p = dir.join("светофор.il");
    std::fs::write(&p, "LD %I0.0\n= %Q0.0\n").unwrap();
    let o = plcsh().args(["--json", "-c", &format!("sim program load {}", p.display())]).output_retrying().unwrap();
    let l = json_lines(&o);
    assert_eq!(l[0]["error"]["kind"], "usage", "{l:?}");
    let hint = l[0]["error"]["hint"].as_str().unwrap_or_default();
    assert!(hint.contains(&format!("'{}'", p.display())), "{hint}");
}

// --- The command line's arguments ---------------------------------------------------------

fn ok(o: &Output) -> String {
    assert!(o.status.success(), "{}", both(o));
    stdout(o)
}

#[test]
fn run_a_script() {
    let dir = odd_dir("run");
    let script = dir.join("проверка.lua");
    std::fs::write(&script, "print('аргумент: ' .. arg[1])\nlocal f = assert(io.open(plcsh.write_dir .. '/итог.txt', 'w'))\nf:write('ok')\nf:close()\n").unwrap();
    let out = dir.join("итоги");
    std::fs::create_dir_all(&out).unwrap();
    let s = script.to_str().unwrap();
    let text = ok(&plcsh()
        .args(["run", "--sandbox", "--write-dir", out.to_str().unwrap(), s, "один"])
        .output_retrying()
        .unwrap());
    assert_eq!(text, "аргумент: один\n");
    assert_eq!(std::fs::read_to_string(out.join("итог.txt")).unwrap(), "ok");
}

#[test]
fn config_state_and_bench_files() {
    let dir = odd_dir("config");
    let config = dir.join("устройства.toml");
    std::fs::write(&config, "[devices.press]\nurl = \"sim:K209M-56DT\"\n").unwrap();
    let c = config.to_str().unwrap();
    let l = json_lines(
        &plcsh().args(["--json", "--config", c, "-c", "connect press; use press; get VW0"]).output_retrying().unwrap(),
    );
    assert_eq!(l[2]["device"], "press", "{l:?}");
    let state = dir.join("состояние.json");
    let st = state.to_str().unwrap();
    ok(&plcsh().args(["--state", st, "-c", "set VB3648=77"]).output_retrying().unwrap());
    assert!(state.is_file());
    let l = json_lines(&plcsh().args(["--json", "--state", st, "-c", "get VB3648"]).output_retrying().unwrap());
    assert_eq!(l[0]["values"][0]["value"], 77, "the state file kept the backup area: {l:?}");
    let bench = dir.join("стенд 1.toml");
    let text =
        "name = \"стенд\"\ncurrent = \"press1\"\ninit = [\"press1:VW0=5\"]\n[devices]\npress1 = \"sim:K205-16DT\"\n";
    std::fs::write(&bench, text).unwrap();
    let b = bench.to_str().unwrap();
    let l = json_lines(
        &plcsh().args(["--json", "--time", "stepped", "--bench", b, "-c", "get VW0"]).output_retrying().unwrap(),
    );
    assert_eq!(l[0]["values"][0]["value"], 5, "{l:?}");
}

#[test]
fn record_show_and_replay() {
    let dir = odd_dir("record");
    let rec = dir.join("запись.pcapng");
    let snap = dir.join("снимок.json");
    let line =
        format!("servo enable; get servo:statusword; sim snapshot save {}", Spelling::DoubleEscaped.write(&snap));
    ok(&plcsh()
        .args(["--time", "stepped", "--record", rec.to_str().unwrap(), "-c", &line])
        .stdin(Stdio::null())
        .output_retrying()
        .unwrap());
    let text = ok(&plcsh().args(["record", "show", rec.to_str().unwrap()]).output_retrying().unwrap());
    assert!(text.contains("statusword"), "{text}");
    let text = ok(&plcsh()
        .args(["replay", rec.to_str().unwrap(), "--snapshot", snap.to_str().unwrap()])
        .output_retrying()
        .unwrap());
    assert!(text.trim_end().ends_with(" 0 difference(s)"), "{text}");
}

#[test]
fn lab_on_the_command_line() {
    let dir = odd_dir("labcli");
    let lab = dir.join("лаб 1");
    let l = lab.to_str().unwrap();
    ok(&plcsh().args(["lab", "new", l]).output_retrying().unwrap());
    let text = ok(&plcsh().args(["lab", "check", l]).output_retrying().unwrap());
    assert!(text.contains("gets 10/10 points"), "{text}");
    let sub = dir.join("Петров П.П.il");
    std::fs::copy(lab.join("reference.il"), &sub).unwrap();
    let junit = dir.join("итог.xml");
    // The workers' reports (`lab worker --report FILE`) and write directories (`--write-dir
    // DIR`) go to a folder in the temporary folder: one with Cyrillic letters and a space here.
    let tmp = dir.join("врем енно");
    std::fs::create_dir_all(&tmp).unwrap();
    let o = plcsh()
        .env("TMPDIR", &tmp)
        .env("TEMP", &tmp)
        .env("TMP", &tmp)
        .args(["--json", "lab", "grade", l, sub.to_str().unwrap(), "--jobs", "1", "--junit", junit.to_str().unwrap()])
        .output_retrying()
        .unwrap();
    let r = &json_lines(&o)[0];
    assert_eq!((&r["student"], &r["points"]), (&"Петров П.П".into(), &10.0.into()), "{r}");
    assert!(std::fs::read_to_string(&junit).unwrap().contains("Петров П.П"));
}

#[test]
fn completion_scripts_folder() {
    let dir = odd_dir("completions").join("дополнения");
    ok(&plcsh().args(["completions", "--write", dir.to_str().unwrap()]).output_retrying().unwrap());
    assert!(dir.join("plcsh.bash").is_file());
}

#[test]
fn tag_files() {
    let dir = odd_dir("tags");
    let tags = dir.join("теги пресса.csv");
    std::fs::write(&tags, "name,address,comment\nStart_Button,I0.0,\"кнопка \"\"пуск\"\"\"\nScans,VW20,\n").unwrap();
    let t = tags.to_str().unwrap();
    assert!(ok(&plcsh().args(["tags", t]).output_retrying().unwrap()).contains("Start_Button"));
    assert!(ok(&plcsh().args(["tags", "check", t]).output_retrying().unwrap()).contains("2 tags"));
    let iec = dir.join("экспорт 'теги'.st");
    ok(&plcsh()
        .args(["tags", "export", t, "--to", "iec", "--output", iec.to_str().unwrap()])
        .output_retrying()
        .unwrap());
    assert!(std::fs::read_to_string(&iec).unwrap().contains("Start_Button AT %IX0.0 : BOOL;"));
    // In the shell: the program and its tag file, each a path with spaces, in quotes.
    let prog = dir.join("программа 1.il");
    std::fs::write(&prog, "LD %SM0.0\nINC Scans\n").unwrap();
    let line = format!(
        "sim program load {} tags={}; sim scan 2; get VW20",
        Spelling::DoubleEscaped.write(&prog),
        Spelling::DoubleEscaped.write(&tags)
    );
    let text = ok(&plcsh().args(["--time", "stepped", "--state", "none", "-c", &line]).output_retrying().unwrap());
    assert!(text.contains("VW20  3"), "{text}");
}

#[test]
fn probe_report_file() {
    let dir = odd_dir("probe");
    let served = serve(&["--tcp", "127.0.0.1:0"]);
    let url = format!("tcp://{}?model=K205-16DT", served.ready["tcp"].as_str().unwrap());
    // A double quote cannot stand in a Windows file name.
    let report =
        dir.join(if cfg!(windows) { "отчёт о 'пробе'.md" } else { "отчёт о \"пробе\".md" });
    ok(&plcsh().args(["probe", &url, "--reads", "3", "--report", report.to_str().unwrap()]).output_retrying().unwrap());
    assert!(std::fs::read_to_string(&report).unwrap().contains("K205-16DT"));
}

#[test]
fn served_simulators_files() {
    let dir = odd_dir("serve");
    let p = |n: &str| dir.join(n).to_str().unwrap().to_string();
    std::fs::write(p("пуск.il"), "LD %I0.0\n= %Q0.0\n").unwrap();
    std::fs::copy(repo("scripts/fx_blink.il"), p("мигалка.il")).unwrap();
    std::fs::copy(repo("scripts/umpk_lab1.il"), p("лаб_УМПК.il")).unwrap();
    #[rustfmt::skip]
    let args = [
        "--tcp", "127.0.0.1:0", "--program", &p("пуск.il"), "--k2-control", &p("к2.ctl"),
        "--servo-tcp", "127.0.0.1:0", "--servo-control", &p("привод.ctl"),
        "--fx-tcp", "127.0.0.1:0", "--fx-program", &p("мигалка.il"), "--fx-control", &p("фх.ctl"),
        "--umpk-tcp", "127.0.0.1:0", "--umpk-state", &p("умпк.json"), "--umpk-program", &p("лаб_УМПК.il"),
        "--umpk-control", &p("умпк.ctl"),
    ];
    let served = serve(&args);
    for (key, file) in [("program", "пуск.il"), ("fx_program", "мигалка.il"), ("umpk_state", "умпк.json")]
    {
        assert_eq!(served.ready[key], p(file), "{key}: {}", served.ready);
    }
    for ctl in ["к2.ctl", "фх.ctl", "умпк.ctl"] {
        let text = ok(&plcsh().args(["sim", "control", &p(ctl), "faults"]).output_retrying().unwrap());
        assert!(text.contains("no injected faults"), "{ctl}: {text}");
    }
    let text = ok(&plcsh().args(["sim", "control", &p("привод.ctl"), "fault", "clear"]).output_retrying().unwrap());
    assert!(!text.is_empty(), "the drive line's channel answers");
}

#[cfg(unix)]
#[test]
fn served_simulators_pty_links() {
    let dir = odd_dir("ptys");
    let p = |n: &str| dir.join(n).to_str().unwrap().to_string();
    #[rustfmt::skip]
    let served = serve(&[
        "--rtu-pty", &p("пресс rtu"), "--servo-pty", &p("привод"), "--fx-pty", &p("фх"),
        "--fx-link-pty", &p("фх связь"), "--umpk-pty", &p("умпк"), "--umpk-state", "none",
    ]);
    for link in ["пресс rtu", "привод", "фх", "фх связь", "умпк"] {
        let meta = std::fs::symlink_metadata(p(link)).unwrap_or_else(|e| panic!("{link}: {e}: {}", served.ready));
        assert!(meta.file_type().is_symlink(), "{link}");
    }
    let url = format!("rtu:{}?unit=1", p("пресс rtu"));
    let l =
        json_lines(&plcsh().args(["--json", "-d", &format!("x={url}"), "-c", "get x:VW0"]).output_retrying().unwrap());
    assert_eq!(l[0]["values"][0]["value"], 0, "the link's path reaches the port: {l:?}");
}

// --- Lua files with a byte-order mark -----------------------------------------------------

/// Notepad's old default (UTF-8 with a BOM) and a `#!` first line load as the stock `lua`
/// loads them: `plcsh run`, a `require`d module, `dofile` in the shell, a lab's grader and a
/// Lua submission.
#[test]
fn lua_files_with_a_byte_order_mark_load_everywhere() {
    const BOM: &str = "\u{feff}";
    let dir = odd_dir("bom");
    std::fs::write(dir.join("модуль.lua"), format!("{BOM}return {{ x = 'из модуля' }}\n")).unwrap();
    let script = dir.join("скрипт.lua");
    std::fs::write(&script, format!("{BOM}#!/usr/bin/env plcsh run\nprint(require('модуль').x)\nerror('line 3')\n"))
        .unwrap();
    let o = plcsh().args(["run", script.to_str().unwrap()]).output_retrying().unwrap();
    assert_eq!(stdout(&o), "из модуля\n", "{}", both(&o));
    assert!(stderr(&o).contains("скрипт.lua:3:"), "line numbers stay the file's: {}", stderr(&o));
    let shell_file = dir.join("из оболочки.lua");
    std::fs::write(&shell_file, format!("{BOM}print('dofile')\n")).unwrap();
    let line = format!("lua dofile({:?})", shell_file.to_str().unwrap());
    assert_eq!(ok(&plcsh().args(["-c", &line]).output_retrying().unwrap()), "dofile\n");
    // A lab whose grader and a student's Lua submission were saved with a BOM.
    let lab = dir.join("лаб");
    ok(&plcsh().args(["lab", "new", lab.to_str().unwrap()]).output_retrying().unwrap());
    let grader = std::fs::read_to_string(lab.join("grade.lua")).unwrap();
    std::fs::write(lab.join("grade.lua"), format!("{BOM}{grader}")).unwrap();
    // The lab takes Lua submissions too, which may load a program; a folder submission reads
    // its own files only, so it brings its IL program with it.
    let toml = std::fs::read_to_string(lab.join("lab.toml")).unwrap();
    let toml =
        toml.replacen("\ndevice = ", "\naccepts = [\"k2-il\", \"lua\"]\ngrants = [\"sim program\"]\ndevice = ", 1);
    std::fs::write(lab.join("lab.toml"), toml).unwrap();
    let sub = dir.join("Сидоров");
    std::fs::create_dir_all(&sub).unwrap();
    std::fs::copy(lab.join("reference.il"), sub.join("программа.il")).unwrap();
    let load = format!("sim program load {}", Spelling::DoubleEscaped.write(&sub.join("программа.il")));
    std::fs::write(sub.join("main.lua"), format!("{BOM}plcsh.exec({load:?})\n")).unwrap();
    let o = plcsh()
        .args(["--json", "lab", "grade", lab.to_str().unwrap(), sub.to_str().unwrap(), "--jobs", "1"])
        .output_retrying()
        .unwrap();
    let r = &json_lines(&o)[0];
    assert_eq!(r["verdict"], "passed", "{r}");
}
