//! Every command is strict: the whole command registry is walked, every form of every command
//! and sub-command is typed at its fullest with one word more, and the real binary must refuse
//! that word — naming the form, with the JSON `column` and the caret at the word — before the
//! command does anything (`servo save x` must not store the drive's parameters).

mod common;

use plcsh::shell::commands::forms;
use std::process::Output;

/// Forms that take any number of words at their end (a list of operands, ranges, objects,
/// bytes, submissions, costs or STOP values, or terminals after `->`): no word can be extra.
const OPEN_ENDED: &[&str] = &[
    "get OPERAND…",
    "set OPERAND=VALUE[, OPERAND=VALUE…]",
    "read RANGE…",
    "sim retain RANGE…|none",
    "sim program costs [bit=200ns] …",
    "sim program stop-outputs QB0=16#05 …",
    "sim wire FROM -> TO[,TO…] [lines=N] [delay=D]",
    "sim fault KIND … [at=TIME] [after=D] [for=D] [times=N]",
    "watch OPERAND… [every=200ms] [count=N]",
    "trace OPERAND… every=10ms for=2s [to=FILE.csv]",
    "plot [OPERAND…] [to=FILE.png|FILE.svg] [size=900x340] [width=60] [height=8]",
    "servo read OBJ…",
    "servo params save FILE [group…]",
    "data save FILE OPERAND…",
    "servo raw BYTES…",
    "umpk monitor [OPERAND…] [count=N] [for=2s] [every=100ms] [quiet]",
    "lua CODE…",
    "lab grade LAB SUBMISSIONS… [jobs=N]",
];

fn run(json: bool, line: &str) -> Output {
    let mut c = common::plcsh();
    if json {
        c.arg("--json");
    }
    c.args(["-c", line]).output().expect("run plcsh")
}

/// Each form with a trailing word: refused at that word, the form in the message.
#[test]
fn a_word_after_every_form_of_every_command_is_refused_at_that_word() {
    let mut lines = Vec::new();
    let mut open = Vec::new();
    for (c, f) in forms::all() {
        match forms::longest_line(c, &f, "1") {
            // A line that another form takes as it stands (`connect PROFILE` with a word more
            // is `connect NAME URL`) is that form's, not an extra word.
            Some(l) if forms::fitting(c, &format!("{l} x")[c.name.len()..]).iter().any(|g| *g != f.text) => {}
            Some(l) => lines.push((c.name, f.text.clone(), format!("{l} x"))),
            None => open.push(f.text.clone()),
        }
    }
    let mut want: Vec<String> = OPEN_ENDED.iter().map(|s| s.to_string()).collect();
    want.sort();
    open.sort();
    assert_eq!(open, want, "the forms that take any number of words");
    // Lines a technician types, each with the form it must be refused against.
    for (cmd, form, line) in [
        ("servo", "servo save", "servo save x"),
        ("servo", "servo params diff FILE [FILE2]", "servo params diff a.toml b.toml x"),
        ("sim", "sim wires", "sim wires x"),
        ("sim", "sim snapshots", "sim snapshots x"),
        ("sim", "sim cpu run|stop|pause", "sim cpu run x"),
        ("sim", "sim stop", "sim stop x"),
        ("sim", "sim pause", "sim pause x"),
        ("sim", "sim switch run|stop", "sim switch run x"),
        ("servo", "servo mode NAME", "servo mode pp x"),
        ("servo", "servo sim fault no-reply|bad-checksum|drop-echo [count=N] [all]", "servo sim fault no-reply x"),
        ("sim", "sim program unload", "sim program unload x"),
        ("sim", "sim step DURATION", "sim step 1s x"),
    ] {
        assert!(forms::all().any(|(c, f)| c.name == cmd && f.text == form), "no form `{form}`");
        lines.push((cmd, form.to_string(), line.to_string()));
    }
    std::thread::scope(|s| {
        for chunk in lines.chunks(lines.len().div_ceil(4)) {
            s.spawn(move || {
                for (cmd, form, line) in chunk {
                    let col = line.len() - 1;
                    let o = run(true, line);
                    let v = common::json_lines(&o);
                    let e = v.last().unwrap_or_else(|| panic!("{line}: no output"));
                    assert_eq!(e["ok"], false, "{line}: {e}");
                    assert_eq!(e["cmd"], *cmd, "{line}: {e}");
                    assert_eq!(e["error"]["kind"], "usage", "{line}: {e}");
                    assert_eq!(e["error"]["column"], col, "{line}: the column of the extra word: {e}");
                    let msg = e["error"]["message"].as_str().unwrap_or("");
                    assert!(msg.contains("unexpected `x`") && msg.contains(form.as_str()), "{line}: {msg}");
                    // The caret under the word, for a person.
                    let o = run(false, line);
                    let err = common::stderr(&o);
                    let caret = format!("  {}^", " ".repeat(col));
                    assert!(err.lines().any(|l| l == caret), "{line}: no caret under `x`:\n{err}");
                }
            });
        }
    });
}

/// The column is that of the word the error is about: `sim step 1 s` points at `s`.
#[test]
fn the_column_points_at_the_word() {
    let o = run(true, "sim step 1 s");
    let v = common::json_lines(&o);
    assert_eq!(v[0]["error"]["column"], 11, "{}", v[0]);
    let o = run(false, "sim step 1 s");
    assert!(common::stderr(&o).contains(&format!("  {}^", " ".repeat(11))), "{}", common::stderr(&o));
}
