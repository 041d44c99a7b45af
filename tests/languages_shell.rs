//! The command line's and the shell's own texts in Russian and Simplified Chinese: clap's
//! errors (an unknown option, a missing value, an invalid value, an unknown subcommand) written
//! from the catalogue with clap's facts and exit status, a subcommand's `--help`, and the
//! progress lines of `-v` with their plural forms. English stays clap's text, byte for byte.

mod common;
use common::*;

/// Runs `plcsh ARGS` with `env` on top of the test's own world (English unless told);
/// returns the exit status, stdout and stderr.
fn run(args: &[&str], env: &[(&str, &str)]) -> (Option<i32>, String, String) {
    let mut c = plcsh();
    c.env_remove("LC_ALL").env_remove("LC_MESSAGES").env_remove("LANG");
    for (k, v) in env {
        c.env(k, v);
    }
    let o = c.args(args).output().unwrap();
    (o.status.code(), String::from_utf8_lossy(&o.stdout).into_owned(), String::from_utf8_lossy(&o.stderr).into_owned())
}

/// Variables set for one run.
type Env = &'static [(&'static str, &'static str)];

#[test]
fn an_unknown_option_reads_in_the_chosen_language() {
    let cases: [(&[&str], Env, &str); 4] = [
        (
            &["--jsn"],
            &[],
            "error: unexpected argument '--jsn' found\n\n  tip: a similar argument exists: '--json'\n\n\
             Usage: plcsh --json\n\nFor more information, try '--help'.\n",
        ),
        (
            &["--lang", "ru", "--jsn"],
            &[],
            "ошибка: неизвестный аргумент '--jsn'\n\n  совет: есть похожий аргумент: '--json'\n\n\
             Использование: plcsh --lang <LANG> --json\n\nПодробнее: '--help'.\n",
        ),
        (
            &["--jsn"],
            &[("PLCSH_LANG", "zh-CN")],
            "错误：未知的参数 '--jsn'\n\n  提示：存在相似的参数：'--json'\n\n用法: plcsh --json\n\n更多信息请尝试 '--help'。\n",
        ),
        (
            &["--jsn"],
            &[("PLCSH_LANG", ""), ("LANG", "ru_RU.UTF-8")],
            "ошибка: неизвестный аргумент '--jsn'\n\n  совет: есть похожий аргумент: '--json'\n\n\
             Использование: plcsh --json\n\nПодробнее: '--help'.\n",
        ),
    ];
    for (args, env, want) in cases {
        let (code, out, err) = run(args, env);
        assert_eq!(code, Some(2), "{args:?} {env:?}: {out}{err}");
        assert_eq!(err, want, "{args:?} {env:?}");
        assert_eq!(out, "");
    }
}

#[test]
fn missing_and_invalid_values_name_the_option_and_what_it_takes() {
    let cases: [(&[&str], &str); 5] = [
        (
            &["--lang", "ru", "--time", "sometimes"],
            "ошибка: недопустимое значение 'sometimes' для '--time <TIME>'\n  [допустимые значения: wall, stepped]\n\n\
             Подробнее: '--help'.\n",
        ),
        (
            &["--lang", "zh-CN", "--time", "sometimes"],
            "错误：'--time <TIME>' 的值 'sometimes' 无效\n  [可选值：wall, stepped]\n\n更多信息请尝试 '--help'。\n",
        ),
        (
            &["--lang", "ru", "sim", "serve", "--tcp"],
            "ошибка: для '--tcp <ADDR>' нужно значение, но оно не задано\n\nПодробнее: '--help'.\n",
        ),
        (
            &["--lang", "ru", "tags", "export"],
            "ошибка: не заданы обязательные аргументы:\n  --to <TO>\n  <FILE>\n\n\
             Использование: plcsh tags export --to <TO> <FILE>\n\nПодробнее: '--help'.\n",
        ),
        (
            &["--lang", "zh-CN", "publish", "--deadband", "1", "VW0"],
            "错误：未提供以下 1 个必需的参数：\n  --on-change\n\n\
             用法: plcsh publish --on-change --deadband <X> <OPERAND>...\n\n更多信息请尝试 '--help'。\n",
        ),
    ];
    for (args, want) in cases {
        let (code, out, err) = run(args, &[]);
        assert_eq!(code, Some(2), "{args:?}: {out}{err}");
        assert_eq!(err, want, "{args:?}");
    }
    // The English stays clap's own.
    let (code, _, err) = run(&["--time", "sometimes"], &[]);
    assert_eq!(code, Some(2));
    assert!(
        err.starts_with("error: invalid value 'sometimes' for '--time <TIME>'\n  [possible values: wall, stepped]"),
        "{err}"
    );
}

#[test]
fn an_unknown_subcommand_lists_the_subcommands_in_the_chosen_language() {
    let (code, _, err) = run(&["--lang", "ru", "agent", "status"], &[]);
    assert_eq!(code, Some(2), "{err}");
    assert_eq!(
        err,
        "plcsh: у `plcsh agent` нет подкоманды `status`; её подкоманды: il, check\n  \
         подсказка: `agent status` — команда оболочки: plcsh -c 'agent status'\n  `plcsh agent --help` описывает каждую\n"
    );
    let (code, _, err) = run(&["--lang", "zh-CN", "sim", "srve"], &[]);
    assert_eq!(code, Some(2), "{err}");
    assert_eq!(
        err,
        "plcsh：`plcsh sim` 没有子命令 `srve`；它的子命令：serve, control\n  `plcsh sim --help` 说明每一个子命令\n"
    );
}

#[test]
fn a_subcommands_help_is_in_the_chosen_language() {
    let (code, out, err) = run(&["--lang", "ru", "sim", "serve", "-h"], &[]);
    assert_eq!(code, Some(0), "{err}");
    for line in [
        "Предоставить симулятор по Modbus TCP, по Modbus RTU на псевдотерминале и/или по RTU поверх TCP\n\nИспользование: plcsh sim serve [OPTIONS]\n\nПараметры:\n",
        "      --servo-baud <BAUD>               Время на линии: ответ занимает время передачи кадра на этой скорости передачи данных (10 бит на байт) [по умолчанию: 38400]\n",
        "  -h, --help                            Показать справку\n",
        "\nОбщие параметры:\n",
        "      --time <TIME>                Время симулятора: идёт по реальным часам или движется только шагами [по умолчанию: wall] [допустимые значения: wall, stepped]\n",
    ] {
        assert!(out.contains(line), "missing:\n{line}\nin:\n{out}");
    }
    let (code, out, err) = run(&["sim", "serve", "--help"], &[("PLCSH_LANG", "zh-CN")]);
    assert_eq!(code, Some(0), "{err}");
    for line in [
        "通过 Modbus TCP、伪终端上的 Modbus RTU 和/或 TCP 上的 RTU 提供仿真器\n\n用法: plcsh sim serve [OPTIONS]\n\n选项:\n",
        "      --servo-baud <BAUD>               线路时序：回复按此波特率下的帧传输时间发送（每字节 10 位） [默认：38400]\n",
    ] {
        assert!(out.contains(line), "missing:\n{line}\nin:\n{out}");
    }
    // Nothing of the English help is left (clap's labels included).
    let (_, en, _) = run(&["sim", "serve", "--help"], &[]);
    for text in ["Modbus RTU on a new pseudo-terminal", "[default: ", "Print help", "Options:", "Usage:"] {
        assert!(en.contains(text), "{text}");
        assert!(!out.contains(text), "`{text}` left in:\n{out}");
    }
}

#[test]
fn progress_lines_take_the_languages_plural_forms() {
    // Stepped time: the sample clock is exact; the wall time and its rate vary.
    let cases = [
        ("ru", "21", "watch: 21 выборка за 2.000 с по часам сессии (10.0 Гц; запрошено 10.0 Гц), ", "0 запросов\n"),
        ("ru", "3", "watch: 3 выборки за 0.200 с по часам сессии (10.0 Гц; запрошено 10.0 Гц), ", "0 запросов\n"),
        ("zh-CN", "5", "watch：时钟时间 0.400 秒内 5 个采样（10.0 Hz；要求 10.0 Hz），实际时间 ", "0 个请求\n"),
        ("en", "3", "watch: 3 samples over 0.200 s of clock time (10.0 Hz; asked 10.0 Hz), ", "0 requests\n"),
    ];
    for (lang, count, head, tail) in cases {
        let line = format!("watch VW0 every=100ms count={count}");
        let (code, _, err) = run(&["--lang", lang, "--time", "stepped", "--state", "none", "-v", "-c", &line], &[]);
        assert_eq!(code, Some(0), "{err}");
        let report = err.lines().last().unwrap_or("").to_string() + "\n";
        assert!(report.starts_with(head) && report.ends_with(tail), "{lang} {count}:\n{err}");
    }
    for (lang, want) in [
        ("ru", "get: 0 запросов по линии связи\n"),
        ("zh-CN", "get：线路上发送了 0 个请求\n"),
        ("en", "get: 0 request(s) on the wire\n"),
    ] {
        let (code, _, err) = run(&["--lang", lang, "--state", "none", "-v", "-c", "get VW0"], &[]);
        assert_eq!(code, Some(0), "{err}");
        assert!(err.ends_with(want), "{lang}:\n{err}");
    }
}
