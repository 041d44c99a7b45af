//! The K2's refusals in Russian and Simplified Chinese: a PLS refusal (manual §3.4.2.2: «Время
//! цикла и количество импульсов должны быть больше 1»), a value out of range of a pulse
//! helper (§3.4.2.1) and a snapshot refusal, each checked word for word in the three
//! languages, with the same JSON `code` in every language. The Russian words are the K2
//! manual's («время цикла», «количество импульсов», «бит состояния»); the Chinese follow
//! ../shared/spec/glossary.md (周期时间, 脉冲数, 状态位).

mod common;
use common::*;

/// Runs a one-shot `plcsh --lang LANG [--json] -c CMD` in `dir`; returns the exit status,
/// stdout and stderr.
fn run(dir: &std::path::Path, lang: &str, json: bool, cmd: &str) -> (Option<i32>, String, String) {
    let mut c = plcsh();
    c.current_dir(dir).args(["--lang", lang]);
    if json {
        c.arg("--json");
    }
    let o = c.args(["-c", cmd]).output().unwrap();
    (o.status.code(), String::from_utf8_lossy(&o.stdout).into_owned(), String::from_utf8_lossy(&o.stderr).into_owned())
}

/// A folder of this test's own, with a snapshot file of a version newer than this plcsh reads.
fn world(name: &str) -> std::path::PathBuf {
    let dir = std::env::temp_dir().join(format!("plcsh-languages-k2-{name}-{}", std::process::id()));
    let _ = std::fs::remove_dir_all(&dir);
    std::fs::create_dir_all(&dir).unwrap();
    std::fs::write(
        dir.join("newer.json"),
        r#"{"format":"plcsh-snapshot","version":99,"clock_us":0,"stepped":false,"devices":{}}"#,
    )
    .unwrap();
    dir
}

/// The three refusals: (command, JSON code, [en, ru, zh-CN] stderr).
const CASES: [(&str, &str, [&str; 3]); 3] = [
    (
        "set SMB67=16#85, SMW68=1, SMD72=10; pls 0",
        "k2-pls-refused",
        [
            "error[refused]: plc: SMW68: PLS 0: cycle time 1 is below 2 (cycle and count must both be > 1, §3.4.2.2); status bit SM66.4 set\n  hint: load SMW68 with SM67.0 set (e.g. SMB67=16#85), then PLS again\n",
            "error[refused]: plc: SMW68: PLS 0: время цикла 1 меньше 2 (время цикла и количество импульсов должны быть больше 1, §3.4.2.2); бит состояния SM66.4 установлен\n  подсказка: загрузите SMW68 с установленным SM67.0 (например, SMB67=16#85), затем снова PLS\n",
            "error[refused]: plc: SMW68: PLS 0：周期时间 1 小于 2（周期时间和脉冲数都须大于 1，§3.4.2.2）；状态位 SM66.4 已置位\n  提示：在 SM67.0 置位时装入 SMW68（例如 SMB67=16#85），然后再执行 PLS\n",
        ],
    ),
    (
        "pto 0 freq=1000 count=1",
        "k2-pto-count-range",
        [
            "error[value]: plc: count=1: a PTO needs 2 … 4 294 967 295 pulses (§3.4.2.1)\n",
            "error[value]: plc: count=1: PTO нужно от 2 до 4 294 967 295 импульсов (§3.4.2.1)\n",
            "error[value]: plc: count=1：PTO 的脉冲数须为 2 … 4 294 967 295（§3.4.2.1）\n",
        ],
    ),
    (
        "sim snapshot restore ./newer.json",
        "snapshot-newer-version",
        [
            "error[usage]: the snapshot is version 99, this plcsh reads up to version 2\n  hint: restore it with the newer plcsh that saved it\n",
            "error[usage]: снимок версии 99, этот plcsh читает версии до 2\n  подсказка: восстановите его более новым plcsh, которым он сохранён\n",
            "error[usage]: 快照版本为 99，此 plcsh 最多读取版本 2\n  提示：用保存它的较新 plcsh 恢复\n",
        ],
    ),
];

#[test]
fn k2_refusals_read_in_three_languages() {
    let dir = world("text");
    for (cmd, _, want) in CASES {
        for (lang, want) in ["en", "ru", "zh-CN"].into_iter().zip(want) {
            let (code, out, err) = run(&dir, lang, false, cmd);
            assert_eq!(code, Some(1), "{lang} `{cmd}`: {out}{err}");
            assert!(err.ends_with(want), "{lang} `{cmd}`:\n{err}\nwanted the end:\n{want}");
        }
    }
    let _ = std::fs::remove_dir_all(&dir);
}

#[test]
fn k2_refusals_keep_their_code_in_every_language() {
    let dir = world("json");
    for (cmd, want, _) in CASES {
        for lang in ["en", "ru", "zh-CN"] {
            let (code, out, err) = run(&dir, lang, true, cmd);
            assert_eq!(code, Some(1), "{lang} `{cmd}`: {out}{err}");
            let line = out.lines().last().unwrap_or_default();
            let v: serde_json::Value =
                serde_json::from_str(line).unwrap_or_else(|e| panic!("{lang} `{cmd}`: {e}: {out}"));
            assert_eq!(v["error"]["code"], want, "{lang} `{cmd}`: {out}");
        }
    }
    let _ = std::fs::remove_dir_all(&dir);
}
