//! The device families in Russian and Simplified Chinese: one error of each family — the
//! UMPK teaching PLC, the FX PLC, the Kinco servo drive — read the same in the three
//! languages, with the words of the manual the family comes from (the UMPK manual's Russian,
//! the FX notes' and the Kinco servo notes' Chinese; ../shared/spec/glossary.md), and the
//! same JSON `code` whatever the language. The devices are the simulators, in the process.

mod common;
use common::*;

/// Runs a session on one simulated device named `dev` (`use dev`, then `lines`) in `lang`;
/// returns stderr.
fn session(lang: &str, url: &str, lines: &str) -> String {
    let script = format!("use dev\n{lines}");
    let o = run(&["--lang", lang, "--device", &format!("dev={url}")], &script);
    stderr(&o)
}

/// The error lines of `err` and their hints, in each language's words (the echo of the
/// line and the caret under it are left out).
fn errors(err: &str) -> String {
    err.lines()
        .filter(|l| {
            l.starts_with("error[") || ["  hint: ", "  подсказка: ", "  提示："].iter().any(|h| l.starts_with(h))
        })
        .map(|l| format!("{l}\n"))
        .collect()
}

#[test]
fn a_umpk_refusal_reads_as_the_umpk_manual_writes_it() {
    // UMPK manual §4.1, Table 6: the terminal protocol has no write command.
    let cases = [
        (
            "en",
            "error[unsupported]: dev: the UMPK terminal protocol has no write commands (manual §4.1, Table 6), so Q0 cannot be set\n  hint: inputs are wired, outputs, timers, counters and markers belong to the program; on the simulator use `umpk sim input I3=1`\n",
        ),
        (
            "ru",
            "error[unsupported]: dev: в терминальном протоколе УМПК нет команд записи (§4.1 руководства, таблица 6), поэтому Q0 установить нельзя\n  подсказка: входы задаются подключением, а выходы, таймеры, счетчики и маркеры принадлежат программе; на симуляторе используйте `umpk sim input I3=1`\n",
        ),
        (
            "zh-CN",
            "error[unsupported]: dev: UMPK 终端协议没有写命令（手册 §4.1，表 6），因此无法设置 Q0\n  提示：输入由接线决定，输出、定时器、计数器和标志位属于程序；在仿真器上请用 `umpk sim input I3=1`\n",
        ),
    ];
    for (lang, want) in cases {
        let err = session(lang, "sim-umpk:UMPK16", "set Q0=1\n");
        assert_eq!(errors(&err), want, "{lang}:\n{err}");
    }
}

#[test]
fn an_fx_operand_error_reads_as_the_fx_notes_write_it() {
    // X and Y are numbered in octal (FX notes, seed 004: "八进制").
    let cases = [
        ("en", "error[operand]: dev: Y numbers are octal (Y0–Y7, Y10–Y17 …): `8` is not an octal digit in `Y8`\n"),
        ("ru", "error[operand]: dev: номера Y восьмеричные (Y0–Y7, Y10–Y17 …): `8` в `Y8` — не восьмеричная цифра\n"),
        ("zh-CN", "error[operand]: dev: Y 的编号是八进制（Y0–Y7，Y10–Y17 …）：`Y8` 中的 `8` 不是八进制数字\n"),
    ];
    for (lang, want) in cases {
        let err = session(lang, "sim-fx:FX2N", "get Y8\n");
        assert_eq!(errors(&err), want, "{lang}:\n{err}");
    }
}

#[test]
fn a_servo_refusal_reads_as_the_kinco_servo_notes_write_it() {
    // The drive answers function code 80 with a CANopen abort code (Kinco servo notes §2.2.2);
    // the simulator is told to refuse the next write of 607A.00 with 0609 0030.
    let lines = "servo sim fault abort target_position 16#06090030\nset target_position=5\n";
    let cases = [
        (
            "en",
            "drive id 1: abort 16#06090030 (value range of parameter exceeded) for 607A.00 for the next request\n",
            "error[refused]: dev: drive id 1 refused the write of target_position: abort code 16#06090030 — value range of parameter exceeded\n",
        ),
        (
            "ru",
            "привод с ID 1: прерывание 16#06090030 (значение параметра вне диапазона) для 607A.00; действует на следующий запрос\n",
            "error[refused]: dev: привод с ID 1 отказал в записи target_position: код прерывания 16#06090030 — значение параметра вне диапазона\n",
        ),
        (
            "zh-CN",
            "驱动器 ID 1：下一个请求对 607A.00 回复中止代码 16#06090030（超出参数的数值范围）\n",
            "error[refused]: dev: 驱动器 ID 1 拒绝了对 target_position 的写入：中止代码 16#06090030 — 超出参数的数值范围\n",
        ),
    ];
    for (lang, armed, refused) in cases {
        let o = run(&["--lang", lang, "--device", "dev=sim-servo:"], &format!("use dev\n{lines}"));
        assert_eq!(stdout(&o), armed, "{lang}:\n{}", both(&o));
        assert_eq!(errors(&stderr(&o)), refused, "{lang}:\n{}", both(&o));
    }
}

#[test]
fn the_json_code_of_a_device_error_does_not_follow_the_language() {
    let mut seen = Vec::new();
    for lang in ["en", "ru", "zh-CN"] {
        let o = run(&["--json", "--lang", lang, "--device", "dev=sim-umpk:UMPK16"], "use dev\nget I99\n");
        let lines = json_lines(&o);
        let e = lines.iter().find_map(|l| l.get("error")).unwrap_or_else(|| panic!("{lang}: {}", both(&o)));
        assert_eq!(e["kind"], "range", "{e}");
        seen.push(e["code"].as_str().unwrap_or_default().to_string());
    }
    assert_eq!(seen, ["umpk-past-end"; 3]);
}
