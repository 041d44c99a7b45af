//! plcsh in Russian and Simplified Chinese: the same commands in each language, with the
//! output checked, and the language chosen as documented (`--lang`, `PLCSH_LANG`, then the
//! system's `LC_ALL` / `LC_MESSAGES` / `LANG`; English when none names ru or zh-CN). The JSON
//! `code` is the same in every language; only `message` follows it.

mod common;
use common::*;

/// Runs `plcsh ARGS` with `env` set on top of the test's own world (which sets PLCSH_LANG=en;
/// an empty value in `env` removes a variable); returns the exit status, stdout and stderr.
fn run(args: &[&str], env: &[(&str, &str)]) -> (Option<i32>, String, String) {
    let mut c = plcsh();
    c.env_remove("LC_ALL").env_remove("LC_MESSAGES").env_remove("LANG");
    for (k, v) in env {
        if v.is_empty() {
            c.env_remove(k);
        } else {
            c.env(k, v);
        }
    }
    let o = c.args(args).output().unwrap();
    (o.status.code(), String::from_utf8_lossy(&o.stdout).into_owned(), String::from_utf8_lossy(&o.stderr).into_owned())
}

const SESSION: &str = "set VB2=300; get VX0; get Q9.9; fo";

#[test]
fn a_first_mistake_reads_the_same_in_three_languages() {
    // Each command of a one-shot runs on its own line here, so every error shows.
    let cases: [(&str, [&str; 4]); 3] = [
        (
            "en",
            [
                "error[value]: plc: VB2: 300 is out of range for BYTE (0…255)\n",
                "error[operand]: plc: V needs a bit (`V0.0`) or a size letter (`VB0`, `VW0`, `VD0`)\n",
                "error[range]: plc: Q9.9: bit 9 does not exist (bits are 0…7), and byte 9 is past the end of the Q area on K205-16DT (last bit is Q1.7)\n  hint: digital outputs on K205-16DT: Q0.0 … Q1.7\n",
                "error[usage]: unknown command `fo`\n  hint: did you mean `pto`? `help` lists the commands\n",
            ],
        ),
        (
            "ru",
            [
                "error[value]: plc: VB2: 300 вне диапазона BYTE (0…255)\n",
                "error[operand]: plc: после V нужен бит (`V0.0`) или буква размера (`VB0`, `VW0`, `VD0`)\n",
                "error[range]: plc: Q9.9: бита 9 нет (биты 0…7), а байт 9 за концом области Q на K205-16DT (последний бит — Q1.7)\n  подсказка: дискретные выходы на K205-16DT: Q0.0 … Q1.7\n",
                "error[usage]: неизвестная команда `fo`\n  подсказка: может быть, `pto`? `help` перечисляет команды\n",
            ],
        ),
        (
            "zh-CN",
            [
                "error[value]: plc: VB2: 300 超出 BYTE 的范围 (0…255)\n",
                "error[operand]: plc: V 之后需要位 (`V0.0`) 或大小字母 (`VB0`、`VW0`、`VD0`)\n",
                "error[range]: plc: Q9.9：位 9 不存在 (位号为 0…7)，而且字节 9 超出 K205-16DT 上 Q 存储区的末尾 (最后一位是 Q1.7)\n  提示：K205-16DT 上的开关量输出：Q0.0 … Q1.7\n",
                "error[usage]: 未知的命令 `fo`\n  提示：是否想输入 `pto`？`help` 列出所有命令\n",
            ],
        ),
    ];
    for (lang, want) in cases {
        for (cmd, want) in SESSION.split("; ").zip(want) {
            let (code, out, err) = run(&["--lang", lang, "-c", cmd], &[]);
            assert_eq!(code, Some(1), "{lang} {cmd}: {out}{err}");
            assert!(err.ends_with(want), "{lang} `{cmd}`:\n{err}\nwanted the end:\n{want}");
        }
    }
}

#[test]
fn json_codes_do_not_depend_on_the_language() {
    let mut codes = Vec::new();
    for lang in ["en", "ru", "zh-CN"] {
        let (code, out, _) = run(&["--json", "--lang", lang, "-c", "set VB2=300"], &[]);
        assert_eq!(code, Some(1));
        let v: serde_json::Value = serde_json::from_str(out.trim()).unwrap();
        assert_eq!(v["error"]["kind"], "value", "{out}");
        codes.push(v["error"]["code"].as_str().unwrap().to_string());
    }
    assert_eq!(codes, ["value-out-of-range"; 3]);
    let code = |cmd: &str| {
        let (_, out, _) = run(&["--json", "-c", cmd], &[]);
        let v: serde_json::Value = serde_json::from_str(out.trim()).unwrap();
        v["error"]["code"].as_str().unwrap().to_string()
    };
    assert_eq!(code("frobnicate"), "shell-unknown-command");
    // A message not in the catalogue yet has its kind's code.
    assert_eq!(code("sim wirse"), "kind-usage");
}

#[test]
fn the_language_comes_from_the_flag_then_plcsh_lang_then_the_locale() {
    let said = |args: &[&str], env: &[(&str, &str)]| {
        let mut a = args.to_vec();
        a.extend(["-c", "set VB2=300"]);
        let (_, _, err) = run(&a, env);
        if err.contains("вне диапазона") {
            "ru"
        } else if err.contains("超出") {
            "zh-CN"
        } else if err.contains("is out of range") {
            "en"
        } else {
            panic!("{args:?} {env:?}: {err}")
        }
    };
    assert_eq!(said(&["--lang", "zh-CN"], &[("PLCSH_LANG", "ru")]), "zh-CN");
    assert_eq!(said(&[], &[("PLCSH_LANG", "ru")]), "ru");
    assert_eq!(said(&[], &[("PLCSH_LANG", ""), ("LANG", "ru_RU.UTF-8")]), "ru");
    assert_eq!(said(&[], &[("PLCSH_LANG", ""), ("LANG", "ru_RU.UTF-8"), ("LC_ALL", "zh_CN.UTF-8")]), "zh-CN");
    assert_eq!(said(&[], &[("PLCSH_LANG", ""), ("LANG", "ru_RU.UTF-8"), ("LC_MESSAGES", "C")]), "en");
    assert_eq!(said(&[], &[("PLCSH_LANG", ""), ("LANG", "de_DE.UTF-8")]), "en");
    assert_eq!(said(&[], &[("PLCSH_LANG", ""), ("LANG", "zh_TW.UTF-8")]), "en");
    assert_eq!(said(&[], &[("PLCSH_LANG", "")]), "en");
    // A language plcsh does not speak is a usage error (status 2), in the flag's words.
    let (code, _, err) = run(&["--lang", "de", "-c", "get VW0"], &[]);
    assert_eq!(code, Some(2), "{err}");
    assert!(err.contains("unknown language `de`"), "{err}");
}

#[test]
fn a_labs_language_is_checked_with_its_file() {
    // `language` in lab.toml is checked with the rest of the file: a language plcsh does not
    // speak is refused with the key's name.
    let dir = std::env::temp_dir().join(format!("plcsh-lang-lab-{}", std::process::id()));
    let _ = std::fs::remove_dir_all(&dir);
    let (code, out, err) = run(&["lab", "new", dir.to_str().unwrap()], &[]);
    assert_eq!(code, Some(0), "{out}{err}");
    let toml = dir.join("lab.toml");
    let text = std::fs::read_to_string(&toml).unwrap();
    std::fs::write(&toml, format!("language = \"xx\"\n{text}")).unwrap();
    let (code, _, err) = run(&["lab", "check", dir.to_str().unwrap()], &[]);
    assert_eq!(code, Some(2), "{err}");
    assert!(err.contains("lab.toml: unknown language `xx`"), "{err}");
    std::fs::write(&toml, format!("language = \"ru\"\n{text}")).unwrap();
    let (code, out, err) = run(&["lab", "check", dir.to_str().unwrap()], &[]);
    assert_eq!(code, Some(0), "{out}{err}");
    let _ = std::fs::remove_dir_all(&dir);
}

#[test]
fn a_one_shot_that_prints_values_parses_no_catalogue() {
    // Start-up cost: the catalogue is parsed on the first message, never for values alone.
    use plcsh::core::msg::catalogues_parsed;
    let mut s = plcsh::session::Session::new(plcsh::core::Clock::stepped());
    s.open("plc", "sim:K205-16DT").unwrap();
    let mut sh = plcsh::shell::Shell::new(s, plcsh::output::Style::detect(true));
    for r in sh.exec("set VW0=5; get VW0..VW18; get I0.0 SMB67 K4M0 VD4/REAL VW0[4] T5 C3 Q0.0") {
        assert!(r.is_ok(), "{:?}", r.err());
    }
    assert_eq!(catalogues_parsed(), 0);
    assert!(sh.exec("set VB2=300").into_iter().any(|r| r.is_err()));
    assert_eq!(catalogues_parsed(), 1);
}
