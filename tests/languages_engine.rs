//! The IL scan engine in Russian and Simplified Chinese: a load error (an unknown
//! instruction, with its suggestion) and a runtime fault (the scan watchdog, K2 §2.2.1's
//! serious error that stops the CPU; K80S 5.2.4 "看门狗定时器"), each checked word for word in
//! the three languages, with the same JSON `code` / `kind` in every language. Technical words
//! follow ../shared/spec/glossary.md (инструкция, цикл сканирования, сторожевой таймер,
//! неисправность; 指令, 看门狗, 故障); operands, mnemonics and file names stay as written.

mod common;
use common::*;

/// Runs a one-shot `plcsh --lang LANG --time stepped [--json] -c CMD` in `dir`; returns the
/// exit status, stdout and stderr.
fn run(dir: &std::path::Path, lang: &str, json: bool, cmd: &str) -> (Option<i32>, String, String) {
    let mut c = plcsh();
    c.current_dir(dir).args(["--lang", lang, "--time", "stepped"]);
    if json {
        c.arg("--json");
    }
    let o = c.args(["-c", cmd]).output().unwrap();
    (o.status.code(), String::from_utf8_lossy(&o.stdout).into_owned(), String::from_utf8_lossy(&o.stderr).into_owned())
}

/// A folder of this test's own with two programs: one that does not load (line 3 misspells
/// TON) and one that loops without end once M0.0 is on.
fn world(name: &str) -> std::path::PathBuf {
    let dir = std::env::temp_dir().join(format!("plcsh-languages-engine-{name}-{}", std::process::id()));
    let _ = std::fs::remove_dir_all(&dir);
    std::fs::create_dir_all(&dir).unwrap();
    std::fs::write(dir.join("bad.il"), "LD %SM0.0\nMOVE 1, %VW0\n  TONN T37, 10\n").unwrap();
    std::fs::write(dir.join("wd.il"), "LD %SM0.0\nS %Q0.0, 1\nLD %M0.0\nJMPC L\nJMP E\nL: LD %SM0.0\nJMP L\nE:\n")
        .unwrap();
    dir
}

#[test]
fn an_il_load_error_reads_the_same_in_three_languages() {
    let dir = world("load");
    let cases = [
        (
            "en",
            "error[syntax]: K205-16DT: bad.il:3:3: unknown instruction TONN\n  \
             hint: did you mean TON? (docs/il.md lists the instructions)\n",
        ),
        (
            "ru",
            "error[syntax]: K205-16DT: bad.il:3:3: неизвестная инструкция TONN\n  \
             подсказка: может быть, TON? (список инструкций — в docs/il.md)\n",
        ),
        (
            "zh-CN",
            "error[syntax]: K205-16DT: bad.il:3:3: 未知指令 TONN\n  \
             提示：是否想用 TON？（docs/il.md 列出了所有指令）\n",
        ),
    ];
    for (lang, want) in cases {
        let (status, out, err) = run(&dir, lang, false, "sim program load bad.il");
        assert_eq!(status, Some(1), "{lang}: {out}{err}");
        assert_eq!(format!("{out}{err}"), want, "{lang}");
        // The code is the message's id, whatever the language.
        let (_, out, err) = run(&dir, lang, true, "sim program load bad.il");
        let v: serde_json::Value = serde_json::from_str(out.lines().next().unwrap_or("")).unwrap_or_else(|_| {
            panic!("{lang}: not JSON: {out}{err}");
        });
        assert_eq!(v["error"]["code"], "engine-unknown-instruction", "{lang}: {v}");
    }
    let _ = std::fs::remove_dir_all(&dir);
}

#[test]
fn a_scan_fault_reads_the_same_in_three_languages() {
    let dir = world("fault");
    let cmd = "sim program load wd.il; set M0.0=1; sim step 5ms; sim program";
    let cases = [
        (
            "en",
            "fault 1 (watchdog): the scan ran past the watchdog limit of 300 ms (an endless loop?) at line 7 `JMP L`",
        ),
        (
            "ru",
            "неисправность 1 (сторожевой таймер): цикл сканирования превысил предел сторожевого таймера 300 мс \
             (бесконечный цикл?), строка 7 `JMP L`",
        ),
        ("zh-CN", "故障 1（看门狗）：扫描时间超过看门狗限制 300 ms（死循环？），位于第 7 行 `JMP L`"),
    ];
    for (lang, want) in cases {
        let (status, out, err) = run(&dir, lang, false, cmd);
        assert_eq!(status, Some(0), "{lang}: {out}{err}");
        let line = out.lines().last().unwrap_or("");
        assert!(line.ends_with(want), "{lang}: the last line is {line:?}, expected it to end with {want:?}");
        // JSON keeps its fixed English `kind` and the numeric code in every language.
        let (_, out, _) = run(&dir, lang, true, cmd);
        let st: serde_json::Value = serde_json::from_str(out.lines().last().unwrap_or("")).unwrap();
        assert_eq!(st["faults"][0]["kind"], "watchdog", "{lang}: {st}");
        assert_eq!(st["faults"][0]["code"], 1, "{lang}: {st}");
        assert_eq!(st["mode"], "STOP", "{lang}: {st}");
    }
    let _ = std::fs::remove_dir_all(&dir);
}
