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
    // A message that is not the catalogue's (a script's own error text) has its kind's code.
    assert_eq!(code("lua error(\"boom\")"), "kind-script");
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
    // The locale variables are the system's language on Unix only: Windows has the user's UI
    // language instead (`under_wine_the_windows_ui_language_chooses` sets that one).
    // On Unix: `LC_ALL`, then `LC_MESSAGES`, then `LANG` (POSIX's order for messages).
    if cfg!(unix) {
        assert_eq!(said(&[], &[("PLCSH_LANG", ""), ("LANG", "ru_RU.UTF-8")]), "ru");
        assert_eq!(said(&[], &[("PLCSH_LANG", ""), ("LANG", "ru_RU.UTF-8"), ("LC_ALL", "zh_CN.UTF-8")]), "zh-CN");
        assert_eq!(said(&[], &[("PLCSH_LANG", ""), ("LANG", "ru_RU.UTF-8"), ("LC_MESSAGES", "C")]), "en");
        assert_eq!(said(&[], &[("PLCSH_LANG", ""), ("LANG", "de_DE.UTF-8")]), "en");
        assert_eq!(said(&[], &[("PLCSH_LANG", ""), ("LANG", "zh_TW.UTF-8")]), "en");
        assert_eq!(said(&[], &[("PLCSH_LANG", "")]), "en");
    }
    // A language plcsh does not speak is a usage error (status 2), in the flag's words.
    let (code, _, err) = run(&["--lang", "de", "-c", "get VW0"], &[]);
    assert_eq!(code, Some(2), "{err}");
    assert!(err.contains("unknown language `de`"), "{err}");
}

/// The Windows user's UI language (GetUserDefaultUILanguage) chooses when neither `--lang`
/// nor `PLCSH_LANG` does: Russian, Simplified Chinese, and English for a language plcsh does
/// not speak (German) or Traditional Chinese. Run under Wine (`.ci/windows`), where a Wine
/// process's UI language is the Unix locale it starts with (`LC_ALL`), the way a user of Wine
/// sets it. A Windows process started from Windows code inherits its parent's language,
/// whatever the environment it is given, so each plcsh.exe starts in a Wine process of its own,
/// from a Unix shell (Wine runs a Unix program as it is). Wine gives such a program its own
/// standard streams (not the pipes a Windows parent made) and no process handle to wait on:
/// the shell writes plcsh's stderr to a file under /tmp (`Z:\tmp` here) and renames it when
/// plcsh is done, and the test waits for that file.
#[cfg(windows)]
#[test]
fn under_wine_the_windows_ui_language_chooses() {
    if std::env::var_os("PLCSH_WINE").is_none() {
        skipped("Wine to set the UI language of a new process (.ci/windows runs this test; on Windows, set the display language in Settings)");
        return;
    }
    // Wine's loader for 64-bit programs, where Debian puts it; else `wine` on the PATH.
    let loader = if std::path::Path::new(r"Z:\usr\lib\wine\wine64").exists() { "/usr/lib/wine/wine64" } else { "wine" };
    // No double quotes in the script: the Windows command line carries it to the shell whole.
    const SCRIPT: &str = "f=$1 l=$2 x=$3 c=$4; env -u PLCSH_LANG -u LANGUAGE -u LC_MESSAGES -u LANG \
        LC_ALL=$c PLCSH_STATE=none $l $x -c 'set VB2=300' </dev/null >$f.out 2>$f.part; mv $f.part $f";
    // A fresh folder of this test's own under /tmp (`Z:\tmp` here): the shell writes there by
    // its Unix path, the test reads there by its Windows path.
    let own = format!("plcsh-wine-lang-{}", std::process::id());
    let _ = std::fs::remove_dir_all(format!(r"Z:\tmp\{own}"));
    std::fs::create_dir_all(format!(r"Z:\tmp\{own}")).unwrap();
    let said = |locale: &str| {
        let name = format!(r"{own}\{}", locale.replace('.', "-"));
        let unix = format!("/tmp/{}", name.replace('\\', "/"));
        let windows = std::path::PathBuf::from(format!(r"Z:\tmp\{name}"));
        let _ = std::fs::remove_file(&windows);
        let mut child = std::process::Command::new(r"Z:\bin\sh")
            .args(["-c", SCRIPT, "sh", &unix, loader, bin(), locale])
            .stdin(std::process::Stdio::null())
            .spawn()
            .unwrap();
        let deadline = std::time::Instant::now() + std::time::Duration::from_secs(60);
        while !windows.exists() {
            assert!(std::time::Instant::now() < deadline, "LC_ALL={locale}: plcsh.exe did not finish within 60 s");
            std::thread::sleep(std::time::Duration::from_millis(50));
        }
        let _ = child.try_wait();
        let err = std::fs::read_to_string(&windows).unwrap_or_default();
        let out = std::fs::read_to_string(format!(r"Z:\tmp\{name}.out")).unwrap_or_default();
        let _ = std::fs::remove_file(&windows);
        let _ = std::fs::remove_file(format!(r"Z:\tmp\{name}.out"));
        if err.contains("вне диапазона") {
            "ru"
        } else if err.contains("超出") {
            "zh-CN"
        } else if err.contains("is out of range") {
            "en"
        } else {
            panic!("LC_ALL={locale}: no error in any language: {err}{out}")
        }
    };
    assert_eq!(said("ru_RU.UTF-8"), "ru");
    assert_eq!(said("zh_CN.UTF-8"), "zh-CN");
    assert_eq!(said("de_DE.UTF-8"), "en");
    assert_eq!(said("zh_TW.UTF-8"), "en");
    assert_eq!(said("C"), "en");
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

/// Terminal columns of `s` (a Chinese character takes two).
fn columns(s: &str) -> usize {
    unicode_width::UnicodeWidthStr::width(s)
}

/// The command names of the shell, as `help all` lists them in English.
fn command_names() -> Vec<String> {
    plcsh::shell::commands::COMMANDS.iter().map(|c| c.name.to_string()).collect()
}

/// `help`, `help all` and `--help` in each language: the screen's own words in that language,
/// every command and option still named, every line within 80 columns, and the command lists
/// of `help` in one column whatever the width of the group names (Chinese ones are two columns
/// a character).
#[test]
fn help_and_the_command_lines_help_in_three_languages() {
    let cases = [
        ("en", "commands by group", "commands (`help COMMAND`", "Usage:", "Global options:", "Print help"),
        (
            "ru",
            "команды по группам",
            "команды (`help COMMAND`",
            "Использование:",
            "Общие параметры:",
            "Показать справку",
        ),
        ("zh-CN", "按用途分组的命令", "命令（`help COMMAND`", "用法:", "全局选项:", "显示帮助"),
    ];
    let (_, en_help, _) = run(&["--help"], &[]);
    // The options, from the lines that name them (`  -c, --command <COMMANDS>`).
    let options: Vec<&str> = en_help
        .lines()
        .filter(|l| l.trim_start().starts_with('-'))
        .flat_map(|l| l.split_whitespace().filter(|w| w.starts_with("--")).map(|w| w.trim_end_matches(',')))
        .collect();
    assert!(options.len() > 10, "{en_help}");
    for (lang, heading, all_heading, usage, global, help_flag) in cases {
        let (code, out, err) = run(&["--lang", lang, "-c", "help"], &[]);
        assert_eq!(code, Some(0), "{lang}: {err}");
        assert!(out.starts_with(heading), "{lang}:\n{out}");
        let groups: Vec<&str> = out.lines().skip(1).take_while(|l| !l.is_empty()).collect();
        assert_eq!(groups.len(), 10, "{lang}:\n{out}");
        // The column where each group's command list starts, in terminal columns.
        let starts: Vec<usize> = groups
            .iter()
            .map(|l| {
                let at = l.rfind("  ").expect("a gap before the commands") + 2;
                columns(&l[..at])
            })
            .collect();
        assert!(starts.iter().all(|&s| s == starts[0]), "{lang}: the command lists do not line up:\n{out}");
        let (_, all, _) = run(&["--lang", lang, "-c", "help all"], &[]);
        assert!(all.starts_with(all_heading), "{lang}:\n{all}");
        for text in [&out, &all] {
            for l in text.lines() {
                assert!(columns(l) <= 80, "{lang}: wider than 80 columns ({}): {l}", columns(l));
            }
        }
        for name in command_names() {
            assert!(out.contains(&name) && all.lines().any(|l| l.trim_start().starts_with(&name)), "{lang}: {name}");
        }
        let (code, help, _) = run(&["--lang", lang, "--help"], &[]);
        assert_eq!(code, Some(0));
        for want in [usage, global, help_flag] {
            assert!(help.contains(want), "{lang}: `{want}` missing:\n{help}");
        }
        for o in &options {
            assert!(help.contains(o), "{lang}: {o} missing:\n{help}");
        }
        // A subcommand's help has the same headings, and PLCSH_LANG chooses as --lang does.
        let (_, lab, _) = run(&["lab", "--help"], &[("PLCSH_LANG", lang)]);
        assert!(lab.contains(usage) && lab.contains(global), "{lang}:\n{lab}");
        if lang != "en" {
            assert!(!help.contains("Run these commands"), "{lang}: an English option text:\n{help}");
            assert!(!lab.contains("Write a working example lab"), "{lang}: an English subcommand text:\n{lab}");
            let (_, grade, _) = run(&["--lang", lang, "lab", "grade", "--help"], &[]);
            assert!(grade.contains("--jobs") && !grade.contains("Worker processes"), "{lang}:\n{grade}");
            assert!(!grade.contains("Arguments:") && grade.contains("<SUBMISSIONS>"), "{lang}:\n{grade}");
        }
    }
    // The man page follows the language too (its roff writes non-ASCII as \[uXXXX]).
    let (_, en_man, _) = run(&["man"], &[]);
    let (_, ru_man, _) = run(&["--lang", "ru", "man"], &[]);
    assert!(en_man.contains(".SH \"SHELL COMMANDS\""));
    assert!(ru_man.contains(".SH \"\\[u041A]\\[u041E]\\[u041C]") && !ru_man.contains("SHELL COMMANDS"), "{ru_man}");
}

/// A line of `lab grade`'s or `lab check`'s table split into its cells.
fn cells(line: &str) -> Vec<String> {
    line.trim().trim_matches('|').split('|').map(|c| c.trim().to_string()).collect()
}

/// A whole lab in each language: `lab new` writes the example, `lab check` grades the
/// reference solution, `lab grade` a right and a wrong submission; the head lines, the table
/// headings, the verdicts and the reasons are in the language, and the tables line up.
#[test]
fn a_whole_lab_in_three_languages() {
    struct Want {
        lang: &'static str,
        wrote: &'static str,
        check_head: &'static str,
        check_columns: [&'static str; 3],
        ok: &'static str,
        grade_head: &'static str,
        grade_columns: [&'static str; 6],
        verdicts: [&'static str; 2],
        why: &'static str,
    }
    const TITLE: &str = "Conveyor start/stop with drive interlock";
    let wants = [
        Want {
            lang: "en",
            wrote: "wrote ",
            check_head: "the reference solution gets 10/10 points in 2.42 simulated s",
            check_columns: ["criterion", "points", "result"],
            ok: "ok",
            grade_head: "2 submission(s), 1 passed every criterion",
            grade_columns: ["student", "points", "passed", "failed", "verdict", "simulated time"],
            verdicts: ["passed", "failed"],
            why: "bad: start latches the motor: Q0.0 after the start button is released: expected true, got false at 0.1 s",
        },
        Want {
            lang: "ru",
            wrote: "записана работа ",
            check_head: "эталонное решение набирает 10 из 10 баллов за 2.42 с симуляции",
            check_columns: ["критерий", "баллы", "результат"],
            ok: "выполнен",
            grade_head: "2 сданные работы, все критерии выполнены в 1",
            grade_columns: ["студент", "баллы", "выполнено", "не выполнено", "итог", "время симуляции"],
            verdicts: ["зачтено", "не зачтено"],
            why: "bad: start latches the motor: Q0.0 after the start button is released: ожидалось true, получено false в момент 0.1 с",
        },
        Want {
            lang: "zh-CN",
            wrote: "已写入 ",
            check_head: "参考答案在 2.42 s 仿真时间内得到 10/10 分",
            check_columns: ["评分标准", "分数", "结果"],
            ok: "通过",
            grade_head: "2 份提交的作业，1 份通过全部评分标准",
            grade_columns: ["学生", "分数", "通过", "未通过", "结论", "仿真时间"],
            verdicts: ["通过", "未通过"],
            why: "bad: start latches the motor: Q0.0 after the start button is released：期望 true，实际为 false（0.1 s 时）",
        },
    ];
    let root = std::env::temp_dir().join(format!("plcsh-lang-walk-{}", std::process::id()));
    let _ = std::fs::remove_dir_all(&root);
    std::fs::create_dir_all(&root).unwrap();
    for w in &wants {
        let dir = root.join(w.lang);
        let d = dir.to_str().unwrap();
        let (code, out, err) = run(&["--lang", w.lang, "lab", "new", d], &[]);
        assert_eq!(code, Some(0), "{out}{err}");
        assert!(out.starts_with(w.wrote) && out.contains(&format!("plcsh lab check {d}")), "{}: {out}", w.lang);

        let (code, out, err) = run(&["--lang", w.lang, "lab", "check", d], &[]);
        assert_eq!(code, Some(0), "{}: {out}{err}", w.lang);
        let lines: Vec<&str> = out.lines().collect();
        let sep = if w.lang == "zh-CN" { "：" } else { ": " };
        assert_eq!(lines[0], format!("{TITLE}{sep}{}", w.check_head), "{}", w.lang);
        assert_eq!(cells(lines[1]), w.check_columns, "{}:\n{out}", w.lang);
        let rows: Vec<&str> = lines.iter().skip(3).copied().filter(|l| l.starts_with('|')).collect();
        assert_eq!(rows.len(), 4, "{out}");
        for r in &rows {
            assert_eq!(cells(r)[2], w.ok, "{}: {r}", w.lang);
        }
        let widths: Vec<usize> = lines[1..].iter().map(|l| columns(l)).collect();
        assert!(widths.iter().all(|&x| x == widths[0]), "{}: the table does not line up:\n{out}", w.lang);

        let subs = dir.join("subs");
        std::fs::create_dir_all(&subs).unwrap();
        std::fs::copy(dir.join("reference.il"), subs.join("good.il")).unwrap();
        std::fs::copy(dir.join("starter.il"), subs.join("bad.il")).unwrap();
        let (good, bad) = (subs.join("good.il"), subs.join("bad.il"));
        let (code, out, err) =
            run(&["--lang", w.lang, "lab", "grade", d, good.to_str().unwrap(), bad.to_str().unwrap()], &[]);
        assert_eq!(code, Some(0), "{}: {out}{err}", w.lang);
        let lines: Vec<&str> = out.lines().collect();
        assert_eq!(lines[0], format!("{TITLE}{sep}{}", w.grade_head), "{}", w.lang);
        assert_eq!(cells(lines[1]), w.grade_columns, "{}:\n{out}", w.lang);
        let good_row = cells(lines.iter().find(|l| l.starts_with("| good")).unwrap());
        let bad_row = cells(lines.iter().find(|l| l.starts_with("| bad")).unwrap());
        assert_eq!((good_row[4].as_str(), bad_row[4].as_str()), (w.verdicts[0], w.verdicts[1]), "{out}");
        assert!(lines.contains(&w.why), "{}: no line `{}` in:\n{out}", w.lang, w.why);
        let widths: Vec<usize> = lines[1..5].iter().map(|l| columns(l)).collect();
        assert!(widths.iter().all(|&x| x == widths[0]), "{}: the table does not line up:\n{out}", w.lang);
    }
    // The lab's `language` decides, whatever the grader's own: a Russian lab grades in Russian
    // under a Chinese --lang and a Chinese locale.
    let dir = root.join("en");
    let toml = dir.join("lab.toml");
    let text = std::fs::read_to_string(&toml).unwrap();
    std::fs::write(&toml, format!("language = \"ru\"\n{text}")).unwrap();
    let (code, out, err) = run(&["--lang", "zh-CN", "lab", "check", dir.to_str().unwrap()], &[("LANG", "zh_CN.UTF-8")]);
    assert_eq!(code, Some(0), "{out}{err}");
    assert!(out.starts_with(&format!("{TITLE}: {}", wants[1].check_head)), "{out}");
    let _ = std::fs::remove_dir_all(&root);
}

/// A lab grades in its `language` (lab.toml), and the bytes of its grades do not depend on
/// the grader's locale: the same Russian lab and submissions graded under a Chinese locale and
/// under `C` give identical output, with the verdicts that are not `passed`/`failed` (a
/// runtime error, a file that is not a submission) in Russian and their `code` in `--json`.
#[test]
fn a_russian_lab_grades_in_russian_whatever_the_graders_locale() {
    let root = std::env::temp_dir().join(format!("plcsh-lang-ru-lab-{}", std::process::id()));
    let _ = std::fs::remove_dir_all(&root);
    std::fs::create_dir_all(&root).unwrap();
    let dir = root.join("lab");
    let d = dir.to_str().unwrap();
    let (code, out, err) = run(&["lab", "new", d], &[]);
    assert_eq!(code, Some(0), "{out}{err}");
    let toml = dir.join("lab.toml");
    let text = std::fs::read_to_string(&toml).unwrap();
    std::fs::write(&toml, format!("language = \"ru\"\n{text}")).unwrap();
    let subs = root.join("subs");
    std::fs::create_dir_all(&subs).unwrap();
    std::fs::copy(dir.join("reference.il"), subs.join("good.il")).unwrap();
    std::fs::copy(dir.join("starter.il"), subs.join("bad.il")).unwrap();
    // An instruction the PLC does not have: the program does not load (a runtime error).
    std::fs::write(subs.join("broken.il"), "LD      %I0.0\nFROB    %Q0.0\n").unwrap();
    std::fs::write(subs.join("notes.txt"), "not a program").unwrap();
    let files: Vec<String> =
        ["good.il", "bad.il", "broken.il", "notes.txt"].iter().map(|f| subs.join(f).display().to_string()).collect();
    let grade = |json: bool, env: &[(&str, &str)]| {
        let mut args = vec!["lab", "grade", d];
        if json {
            args.insert(0, "--json");
        }
        args.extend(files.iter().map(|f| f.as_str()));
        let (_, out, err) = run(&args, env);
        (out, err)
    };
    let zh = grade(false, &[("PLCSH_LANG", ""), ("LANG", "zh_CN.UTF-8")]);
    let c = grade(false, &[("PLCSH_LANG", ""), ("LANG", "C")]);
    let en = grade(false, &[("PLCSH_LANG", "en")]);
    assert_eq!(zh, c, "the grades differ with the grader's locale");
    assert_eq!(en, c, "the grades differ with PLCSH_LANG");
    let out = &c.0;
    let row = |student: &str| {
        let line = out.lines().find(|l| l.starts_with(&format!("| {student} "))).unwrap_or_else(|| panic!("{out}"));
        cells(line)[4].clone()
    };
    assert_eq!(row("good"), "зачтено", "{out}");
    assert_eq!(row("bad"), "не зачтено", "{out}");
    assert!(row("broken").starts_with("ошибка выполнения: "), "{out}");
    assert_eq!(row("notes"), "не сданная работа: нужен сценарий .lua или программа .il", "{out}");
    // --json: `verdict` in the lab's language, `code` the same in every language.
    let (json, _) = grade(true, &[("PLCSH_LANG", ""), ("LANG", "zh_CN.UTF-8")]);
    let reports: Vec<serde_json::Value> = json
        .lines()
        .filter_map(|l| serde_json::from_str(l).ok())
        .filter(|v: &serde_json::Value| v.get("student").is_some())
        .collect();
    let by = |s: &str| reports.iter().find(|r| r["student"] == s).unwrap_or_else(|| panic!("{json}")).clone();
    assert_eq!(by("broken")["code"], "lab-runtime-error", "{json}");
    assert_eq!(by("notes")["code"], "lab-not-submission-kind", "{json}");
    assert!(by("good").get("code").is_none(), "{json}");
    assert_eq!(by("good")["verdict"], "passed", "{json}");
    let _ = std::fs::remove_dir_all(&root);
}

/// The README's first session, typed into the shell in each language: values read the same,
/// the error is the language's (the values and operands themselves never change).
#[test]
fn the_first_session_in_three_languages() {
    let session = "set SMB67=16#85, SMW68=500, SMD72=1000\nget SMB67 SMW68 SMD72\nset VB2=300\nfrobnicate\nquit\n";
    let values = "SMB67  133 (16#85)\nSMW68  500 (16#01F4)\nSMD72  1000 (16#000003E8)\n";
    let errors = [
        (
            "en",
            "error[value]: plc: VB2: 300 is out of range for BYTE (0…255)",
            "error[usage]: unknown command `frobnicate`",
        ),
        (
            "ru",
            "error[value]: plc: VB2: 300 вне диапазона BYTE (0…255)",
            "error[usage]: неизвестная команда `frobnicate`",
        ),
        ("zh-CN", "error[value]: plc: VB2: 300 超出 BYTE 的范围 (0…255)", "error[usage]: 未知的命令 `frobnicate`"),
    ];
    for (lang, value_error, usage_error) in errors {
        let mut c = plcsh();
        c.args(["--lang", lang, "--state", "none"])
            .stdin(std::process::Stdio::piped())
            .stdout(std::process::Stdio::piped())
            .stderr(std::process::Stdio::piped());
        let o = output_with_input(c.spawn().unwrap(), session.as_bytes());
        let (out, err) = (stdout(&o), stderr(&o));
        assert_eq!(out, values, "{lang}: {err}");
        assert!(err.contains(value_error) && err.contains(usage_error), "{lang}:\n{err}");
    }
}

/// The REPL in Chinese in a real terminal (tmux, 80×24): `help`'s command lists line up under
/// Chinese group names, and the completion menu's Chinese summaries are cut to the terminal's
/// columns (two a character), so no line wraps. Skipped without tmux.
#[cfg(unix)]
#[test]
fn the_repl_lines_up_chinese_text_in_a_terminal() {
    use std::process::Command;
    use std::time::{Duration, Instant};
    if Command::new("tmux").arg("-V").output().map(|o| !o.status.success()).unwrap_or(true) {
        skipped("tmux (apt-get install tmux)");
        return;
    }
    let home = std::env::temp_dir().join(format!("plcsh-lang-tmux-{}", std::process::id()));
    let _ = std::fs::remove_dir_all(&home);
    std::fs::create_dir_all(&home).unwrap();
    let socket = format!("plcsh-lang-{}", std::process::id());
    fn on(socket: &str, args: &[&str]) -> std::process::Output {
        Command::new("tmux").args(["-u", "-L", socket]).args(args).env("LANG", "C.UTF-8").output().expect("tmux")
    }
    let tmux = |args: &[&str]| on(&socket, args);
    let cmd = format!(
        "env HOME={h} XDG_DATA_HOME={h}/data XDG_CONFIG_HOME={h}/config LANG=zh_CN.UTF-8 PLCSH_LANG= PLCSH_STATE=none TERM=xterm-256color {bin} --lang zh-CN",
        h = home.display(),
        bin = bin()
    );
    assert!(tmux(&["-f", "/dev/null", "new-session", "-d", "-x", "80", "-y", "24", "-s", "t", &cmd]).status.success());
    struct Kill(String);
    impl Drop for Kill {
        fn drop(&mut self) {
            on(&self.0, &["kill-server"]);
        }
    }
    let _kill = Kill(socket.clone());
    let screen = |joined: bool| {
        let mut a = vec!["capture-pane", "-p", "-t", "t"];
        if joined {
            a.push("-J");
        }
        String::from_utf8_lossy(&tmux(&a).stdout).into_owned()
    };
    let wait_for = |what: &str, ok: &dyn Fn(&str) -> bool| {
        let deadline = Instant::now() + Duration::from_secs(30);
        loop {
            let s = screen(true);
            if ok(&s) {
                return s;
            }
            assert!(Instant::now() < deadline, "waited for {what}; screen:\n{s}");
            std::thread::sleep(Duration::from_millis(50));
        }
    };
    // The banner in Chinese, the devices wrapped within the terminal.
    let s = wait_for("the prompt", &|s| s.contains("plc(sim)>"));
    assert!(s.contains("`help` 列出命令，`quit` 退出。") && s.contains("设备：plc（K205-16DT 仿真）"), "{s}");
    tmux(&["send-keys", "-t", "t", "-l", "help"]);
    tmux(&["send-keys", "-t", "t", "Enter"]);
    let s = wait_for("help in Chinese", &|s| s.contains("本 shell") && s.contains("freq="));
    let groups: Vec<&str> =
        s.lines().skip_while(|l| !l.contains("按用途分组")).skip(1).take_while(|l| !l.trim().is_empty()).collect();
    assert_eq!(groups.len(), 10, "{s}");
    let starts: Vec<usize> = groups.iter().map(|l| columns(&l[..l.rfind("  ").unwrap() + 2])).collect();
    assert!(starts.iter().all(|&x| x == starts[0]), "the command lists do not line up on the screen:\n{s}");
    // The completion menu on an empty line: every command with its Chinese summary, each line
    // cut to fit (a line that wrapped would come back longer than the terminal from -J).
    tmux(&["send-keys", "-t", "t", "C-l"]);
    tmux(&["send-keys", "-t", "t", "Tab"]);
    tmux(&["send-keys", "-t", "t", "Tab"]);
    let s = wait_for("the command menu", &|s| s.contains("connect") && s.contains("eeprom") && s.contains("关闭设备"));
    for l in s.lines() {
        assert!(columns(l) < 80, "a line of the menu wraps ({} columns): {l}\n{s}", columns(l));
    }
    assert!(s.lines().any(|l| l.trim_end().ends_with('…')), "long summaries are cut:\n{s}");
    tmux(&["send-keys", "-t", "t", "C-u"]);
    tmux(&["send-keys", "-t", "t", "-l", "quit"]);
    tmux(&["send-keys", "-t", "t", "Enter"]);
}

/// The first-connection page's probe (docs/reference/first-connection.md), against a simulated
/// K204ET-16DT served on Modbus TCP, in each language: the head line, the table's headings and
/// results, the verdicts and what to do are the language's; the Modbus tables, areas,
/// addresses and models stay as they are; the table's columns line up by display width.
#[test]
fn the_first_connection_probe_in_three_languages() {
    let served = serve(&["--tcp", "127.0.0.1:0", "--model", "K204ET-16DT"]);
    let addr = served.ready["tcp"].as_str().expect("tcp address").to_string();
    let url = format!("tcp://{addr}?model=K204ET-16DT");
    let wants = [
        (
            "en",
            "probe of ",
            "read requests, no writes",
            "table",
            "answers",
            "ok: area sizes fit models K205EA-18DT, K204ET-16DT",
            "  what to do: these models have the same Modbus areas",
        ),
        (
            "ru",
            "опрос ",
            "запросов на чтение, без записи",
            "таблица",
            "отвечает",
            "в порядке: размеры областей подходят моделям K205EA-18DT, K204ET-16DT",
            "  что делать: у этих моделей одинаковые области Modbus",
        ),
        (
            "zh-CN",
            "探测 ",
            "次读请求，无写入",
            "表",
            "有应答",
            "正常：存储区大小与 2 个型号相符：K205EA-18DT, K204ET-16DT",
            "  处理方法：这些型号的 Modbus 存储区相同",
        ),
    ];
    for (lang, head, requests, first_heading, answers, fit, todo) in wants {
        let (code, out, err) = run(&["--lang", lang, "probe", &url], &[]);
        assert_eq!(code, Some(0), "{lang}: {out}{err}");
        let lines: Vec<&str> = out.lines().collect();
        assert!(lines[0].starts_with(&format!("{head}{url}")) && lines[0].ends_with(requests), "{lang}: {}", lines[0]);
        assert!(lines[1].starts_with(first_heading), "{lang}: {}", lines[1]);
        let table: Vec<&str> = lines[1..].iter().copied().take_while(|l| l.contains("  ")).collect();
        assert_eq!(table.len(), 9, "{lang}:\n{out}");
        assert!(table[1].starts_with("coils") && table[1].ends_with(answers), "{lang}: {}", table[1]);
        // The second column (FC) starts at the same terminal column on every line.
        let second = |l: &str| {
            let gap = l.find("  ").expect("two columns");
            columns(&l[..gap]) + l[gap..].chars().take_while(|c| *c == ' ').count()
        };
        let at: Vec<usize> = table.iter().map(|l| second(l)).collect();
        assert!(at.iter().all(|&c| c == at[0]), "{lang}: the columns do not line up:\n{out}");
        assert!(lines.contains(&fit), "{lang}: no `{fit}` in:\n{out}");
        assert!(lines.iter().any(|l| l.starts_with(todo)), "{lang}: no `{todo}…` in:\n{out}");
    }
}

/// With neither `--lang` nor `PLCSH_LANG`, plcsh speaks the system's language as
/// `core::platform::ui_language` reads it — the locale variables on Unix, the user's UI
/// language (GetUserDefaultUILanguage) on Windows — or English when that is none of its three.
#[test]
fn without_a_choice_plcsh_speaks_the_systems_ui_language() {
    use plcsh::core::msg::Lang;
    let system = plcsh::core::platform::ui_language();
    let want = system.as_deref().and_then(Lang::from_tag).unwrap_or(Lang::En);
    // The child gets this process's own locale (own_world sets only PLCSH_LANG, removed here).
    let mut c = plcsh();
    c.env_remove("PLCSH_LANG").args(["-c", "set VB2=300"]);
    let o = c.output().unwrap();
    let err = String::from_utf8_lossy(&o.stderr);
    let said = if err.contains("вне диапазона") {
        Lang::Ru
    } else if err.contains("超出") {
        Lang::ZhCn
    } else {
        assert!(err.contains("is out of range"), "{err}");
        Lang::En
    };
    assert_eq!(said, want, "the system's language is {system:?}: {err}");
}
