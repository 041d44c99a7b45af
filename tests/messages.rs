//! Messages are data: every text a person reads comes from the catalogue (`core::msg`,
//! lib/locales/*/*.ftl). The conversion goes file by file, so this test keeps a ratchet:
//! `tests/messages_baseline.txt` holds, per source file, how many message literals still
//! bypass the catalogue, and a file may only go down. It also checks that every id the source
//! asks for is in the catalogue and every id of the catalogue is asked for.
//!
//! A *message literal* (what the ratchet counts) is a Rust string literal in `src/` that
//! - holds prose: two words of at least two lower-case ASCII letters side by side
//!   (`"cannot open {path}"`, `"a value is missing"`; not `"{} ms"`, `"VW0"`, `"tcp://{a}"`);
//! - is not in a comment, a doc comment or an attribute (`#[…]`: clap's help texts are
//!   counted by their own slice later), nor on a line (or right after a line) that is a
//!   developer's text: `expect(`, `panic!`, `unreachable!`, `assert`, `debug_assert`;
//! - comes before the file's `#[cfg(test)]` (tests' texts are not shown to users), in a file
//!   that is not a test (`tests.rs`, `…/tests/…`, a module declared `#[cfg(test)] mod NAME;`),
//!   a benchmark (`src/bin/`) or the fuzzing entry points (`src/fuzzing.rs`).
//!
//! `PLCSH_BLESS=1 cargo test --test messages` lowers the baseline to what the source has now;
//! it never raises it (docs/development.md, "How to add a message").

use std::collections::BTreeMap;
use std::path::{Path, PathBuf};

fn root() -> &'static Path {
    Path::new(env!("CARGO_MANIFEST_DIR"))
}

fn rust_files(dir: &Path, out: &mut Vec<PathBuf>) {
    for e in std::fs::read_dir(dir).unwrap() {
        let p = e.unwrap().path();
        if p.is_dir() {
            rust_files(&p, out);
        } else if p.extension().is_some_and(|x| x == "rs") {
            out.push(p);
        }
    }
}

/// The string literals of `src` with the line each starts on (0-based). Handles escapes,
/// raw strings (`r"…"`, `r#"…"#`), byte strings and char literals (`'"'`).
fn literals(src: &str) -> Vec<(usize, String)> {
    let b = src.as_bytes();
    let mut out = Vec::new();
    let (mut i, mut line) = (0, 0);
    while i < b.len() {
        match b[i] {
            b'\n' => {
                line += 1;
                i += 1;
            }
            b'/' if b.get(i + 1) == Some(&b'/') => {
                while i < b.len() && b[i] != b'\n' {
                    i += 1;
                }
            }
            b'\'' => {
                // A char literal ('"', '\'', 'x') or a lifetime ('a).
                if b.get(i + 1) == Some(&b'\\') {
                    i += 2;
                    while i < b.len() && b[i] != b'\'' {
                        i += 1;
                    }
                    i += 1;
                } else if b.get(i + 2) == Some(&b'\'') {
                    i += 3;
                } else {
                    i += 1;
                }
            }
            b'r' if (b.get(i + 1) == Some(&b'"') || b.get(i + 1) == Some(&b'#'))
                && (i == 0 || !(b[i - 1].is_ascii_alphanumeric() || b[i - 1] == b'_')) =>
            {
                let mut j = i + 1;
                let mut hashes = 0;
                while b.get(j) == Some(&b'#') {
                    hashes += 1;
                    j += 1;
                }
                if b.get(j) != Some(&b'"') {
                    i += 1;
                    continue;
                }
                let close: Vec<u8> = std::iter::once(b'"').chain(std::iter::repeat_n(b'#', hashes)).collect();
                let start = j + 1;
                let end = src[start..].find(std::str::from_utf8(&close).unwrap()).map_or(b.len(), |k| start + k);
                out.push((line, src[start..end].to_string()));
                line += src[i..end].matches('\n').count();
                i = end + close.len();
            }
            b'"' => {
                let start = i + 1;
                let mut j = start;
                while j < b.len() && b[j] != b'"' {
                    j += if b[j] == b'\\' { 2 } else { 1 };
                }
                let end = j.min(b.len());
                out.push((line, src[start..end].to_string()));
                line += src[i..end].matches('\n').count();
                i = end + 1;
            }
            _ => i += 1,
        }
    }
    out
}

/// Two words of two or more lower-case letters side by side.
fn is_prose(s: &str) -> bool {
    let words: Vec<&str> = s.split(' ').collect();
    words.windows(2).any(|w| {
        let word = |x: &str| x.len() >= 2 && x.bytes().all(|c| c.is_ascii_lowercase());
        word(w[0].trim_start_matches(['(', '`'])) && word(w[1].trim_end_matches([',', ':', ';', ')', '`']))
    })
}

const DEVELOPER: &[&str] = &["expect(", "panic!", "unreachable!", "assert", "debug_assert", "todo!", "unimplemented!"];

/// Lines whose literals are the command language, which stays as it is in every language
/// (commands, options, operands): a command's `usage:` line and the Lua bridge's `row(`
/// templates (`"data save {}"`), which are commands plcsh runs, not sentences a person reads.
const COMMAND_TEXT: &[&str] = &["usage:", "row("];

/// The files of modules compiled for tests only: declared `#[cfg(test)] mod NAME;` (the
/// attribute on the line before), as `NAME.rs` or `NAME/mod.rs` beside a `mod.rs`/`lib.rs`, or
/// in the folder named after any other file.
fn test_modules(files: &[PathBuf]) -> Vec<PathBuf> {
    let mut out = Vec::new();
    for f in files {
        let text = std::fs::read_to_string(f).unwrap();
        let lines: Vec<&str> = text.lines().map(str::trim).collect();
        for w in lines.windows(2) {
            let Some(name) = w[1].strip_prefix("mod ").and_then(|r| r.strip_suffix(';')) else { continue };
            if w[0] != "#[cfg(test)]" {
                continue;
            }
            let stem = f.file_stem().unwrap().to_string_lossy();
            let dir =
                if stem == "mod" || stem == "lib" { f.parent().unwrap().to_path_buf() } else { f.with_extension("") };
            out.push(dir.join(format!("{name}.rs")));
            out.push(dir.join(name).join("mod.rs"));
        }
    }
    out
}

/// Message literals per file (relative path with `/`).
fn counts() -> BTreeMap<String, usize> {
    let mut files = Vec::new();
    rust_files(&root().join("src"), &mut files);
    let test_modules = test_modules(&files);
    let mut out = BTreeMap::new();
    for f in files {
        let rel = f.strip_prefix(root()).unwrap().to_string_lossy().replace('\\', "/");
        if rel.ends_with("/tests.rs")
            || rel.contains("/tests/")
            || rel.starts_with("src/bin/")
            || rel == "src/fuzzing.rs"
            || test_modules.contains(&f)
        {
            continue;
        }
        let text = std::fs::read_to_string(&f).unwrap();
        let body = match text.find("\n#[cfg(test)]") {
            Some(at) => &text[..at],
            None => &text[..],
        };
        let lines: Vec<&str> = body.lines().collect();
        let n = literals(body)
            .into_iter()
            .filter(|(l, s)| {
                let here = lines.get(*l).copied().unwrap_or("").trim_start();
                let before = if *l > 0 { lines[*l - 1].trim_end() } else { "" };
                is_prose(s)
                    && !here.starts_with("#[")
                    && !here.starts_with("//")
                    && !COMMAND_TEXT.iter().any(|c| here.starts_with(c))
                    && !DEVELOPER
                        .iter()
                        .any(|d| here.contains(d) || before.ends_with(d) || before.ends_with(&format!("{d}(")))
            })
            .count();
        if n > 0 {
            out.insert(rel, n);
        }
    }
    out
}

const BASELINE: &str = "tests/messages_baseline.txt";

fn baseline() -> BTreeMap<String, usize> {
    let text = std::fs::read_to_string(root().join(BASELINE)).unwrap_or_default();
    text.lines()
        .filter(|l| !l.starts_with('#') && !l.trim().is_empty())
        .map(|l| {
            let (n, path) = l.split_once(' ').unwrap();
            (path.to_string(), n.parse().unwrap())
        })
        .collect()
}

fn write_baseline(b: &BTreeMap<String, usize>) {
    let mut s = String::from(
        "# Message literals that still bypass the catalogue, per file (tests/messages.rs says what\n\
         # counts). A number may only go down: PLCSH_BLESS=1 cargo test --test messages lowers them.\n",
    );
    s.push_str(&format!("# total {}\n", b.values().sum::<usize>()));
    for (path, n) in b {
        s.push_str(&format!("{n} {path}\n"));
    }
    std::fs::write(root().join(BASELINE), s).unwrap();
}

#[test]
fn the_scanner_sees_message_literals_and_only_those() {
    let src = r#####"
fn f() -> Result<()> {
    let c = '"';
    Err(Error::usage(format!("cannot open {path}")))?;
    let e = Error::new(ErrorKind::Value, msg!("value-out-of-range", value = v));
    let raw = r#"a raw text with "quotes""#;
    let s = format!("{} ms", n);
    x.expect("the lock is never poisoned");
    let url = "tcp://host"; // a comment with some words
    panic!(
        "a developer's words here"
    );
}
#[cfg(test)]
mod tests { fn t() { let _ = "words in a test"; } }
"#####;
    let body = &src[..src.find("\n#[cfg(test)]").unwrap()];
    let found: Vec<String> = literals(body).into_iter().map(|(_, s)| s).filter(|s| is_prose(s)).collect();
    assert_eq!(
        found,
        vec![
            "cannot open {path}",
            "a raw text with \"quotes\"",
            "the lock is never poisoned",
            "a developer's words here"
        ]
    );
    assert!(!is_prose("value-out-of-range"));
    assert!(!is_prose("{} ms"));
    assert!(is_prose("`{original}` is not a K2 operand"));
}

#[test]
fn message_literals_bypassing_the_catalogue_only_go_down() {
    let now = counts();
    let base = baseline();
    let bless = std::env::var_os("PLCSH_BLESS").is_some();
    let mut grown = Vec::new();
    let mut shrunk = Vec::new();
    for (path, &n) in &now {
        let was = base.get(path).copied().unwrap_or(0);
        if n > was {
            grown.push(format!("{path}: {n} message literals, the baseline allows {was}"));
        }
    }
    for (path, &was) in &base {
        let n = now.get(path).copied().unwrap_or(0);
        if n < was {
            shrunk.push(format!("{path}: {was} → {n}"));
        }
    }
    eprintln!(
        "message literals outside the catalogue: {} in {} files (baseline {})",
        now.values().sum::<usize>(),
        now.len(),
        base.values().sum::<usize>()
    );
    assert!(
        grown.is_empty(),
        "new message text outside the catalogue (write it into lib/locales/*/*.ftl and use msg!; \
         docs/development.md, \"How to add a message\"):\n{}",
        grown.join("\n")
    );
    if !shrunk.is_empty() {
        if bless {
            let lowered: BTreeMap<String, usize> = base
                .iter()
                .map(|(p, &was)| (p.clone(), now.get(p).copied().unwrap_or(0).min(was)))
                .filter(|(_, n)| *n > 0)
                .collect();
            write_baseline(&lowered);
        } else {
            panic!(
                "fewer message literals than the baseline (good): lower it with PLCSH_BLESS=1 cargo test --test messages\n{}",
                shrunk.join("\n")
            );
        }
    }
}

/// The ids of a catalogue file, in order.
fn catalogue_ids(lang: &str) -> Vec<String> {
    // The files of a catalogue, in core::msg::CATALOGUE_FILES's order.
    let text: String = plcsh::core::msg::CATALOGUE_FILES
        .iter()
        .map(|f| std::fs::read_to_string(root().join(format!("lib/locales/{lang}/{f}.ftl"))).unwrap() + "\n")
        .collect();
    text.lines()
        .filter_map(|l| l.split_once(" =").map(|(id, _)| id))
        .filter(|id| !id.is_empty() && id.bytes().all(|c| c.is_ascii_lowercase() || c.is_ascii_digit() || c == b'-'))
        .map(str::to_string)
        .collect()
}

/// The ids the source asks for: `msg!("id"` and `msg!(lang: …, "id"`.
fn source_ids() -> BTreeMap<String, String> {
    let mut files = Vec::new();
    rust_files(&root().join("src"), &mut files);
    let mut out = BTreeMap::new();
    for f in files {
        let text = std::fs::read_to_string(&f).unwrap();
        for (at, _) in text.match_indices("msg!(") {
            let rest = &text[at + 5..];
            let rest = rest.trim_start();
            let rest = match rest.strip_prefix("lang:") {
                Some(r) => &r[r.find(',').map_or(r.len(), |k| k + 1)..],
                None => rest,
            };
            if let Some(r) = rest.trim_start().strip_prefix('"') {
                let id = &r[..r.find('"').unwrap_or(0)];
                out.insert(id.to_string(), f.strip_prefix(root()).unwrap().display().to_string());
            }
        }
    }
    out.remove("id");
    out
}

#[test]
fn every_id_the_source_asks_for_is_in_the_catalogue_and_the_other_way() {
    let ids = catalogue_ids("en");
    assert!(ids.len() > 50, "{}", ids.len());
    let asked = source_ids();
    for (id, file) in &asked {
        assert!(ids.contains(id), "{file} asks for `{id}`, which lib/locales/en/*.ftl does not have");
    }
    for id in &ids {
        assert!(asked.contains_key(id), "`{id}` is in the catalogue but no msg! in src/ asks for it");
    }
    for lang in ["ru", "zh-CN"] {
        assert_eq!(catalogue_ids(lang), ids, "lib/locales/{lang}/*.ftl has other ids, or another order, than en");
    }
}
