//! The data tables' descriptions in Russian and Simplified Chinese, as a person sees them: one
//! row of each table a command shows — the K2's SM registers (`help SMB67`, K2 manual
//! §3.4.2.2), its counter modes (`hdef`, §3.3.1), the model catalogue's manual discrepancies
//! (`models`), the servo object dictionary (`help servo:…`) with its refusals and units, and
//! the FX timer classes (`help fx:T250`, FX PM "Timers"). Each text comes from
//! lib/locales/*/tables.ftl; English is checked by the tests of each command.

mod common;
use common::*;

/// Runs one command of a one-shot in `lang`; returns stdout and stderr together.
fn run(lang: &str, commands: &str) -> String {
    let o = plcsh().args(["--lang", lang, "-c", commands]).output().unwrap();
    String::from_utf8_lossy(&o.stdout).into_owned() + &String::from_utf8_lossy(&o.stderr)
}

/// Asserts that `out` has a line equal to `want` (after trimming the table's indentation).
fn has_line(out: &str, want: &str) {
    assert!(out.lines().any(|l| l.trim() == want), "no line `{want}` in:\n{out}");
}

#[test]
fn sm_registers_and_counter_modes_read_in_the_users_language() {
    let out = run("ru", "help SMB67; help SM37.3; hdef 0, 9");
    has_line(&out, "SMB67 — контрольный байт PTO0/PWM0 (Q0.0)");
    has_line(&out, "SM37.3 — управление HSC0: направление счета (0 вниз, 1 вверх)");
    assert!(out.contains("фаза AB, A = I0.1, B = I0.0"), "{out}");
    let out = run("zh-CN", "help SMB67; help SM37.3; hdef 0, 9");
    has_line(&out, "SMB67 — PTO0/PWM0（Q0.0）控制字节");
    has_line(&out, "SM37.3 — HSC0 控制：计数方向（0 减计数，1 增计数）");
    assert!(out.contains("AB相正交，A = I0.1，B = I0.0"), "{out}");
}

#[test]
fn servo_objects_their_refusals_and_units_read_in_the_users_language() {
    let out = run("ru", "help servo:target_position");
    has_line(&out, "target_position (607A.00) — заданное положение для режима профильного позиционирования");
    let out = run("ru", "set servo:statusword=1");
    assert!(out.contains("error[unsupported]: servo: statusword (6041.00) только для чтения"), "{out}");
    let out = run("ru", "set servo:target_velocity=300rps");
    assert!(
        out.contains("единица `rps` здесь неизвестна; для скорости пишите rpm или dec (единица привода): 300rpm"),
        "{out}"
    );

    let out = run("zh-CN", "help servo:target_position");
    has_line(&out, "target_position (607A.00) — 位置模式的目标位置");
    let out = run("zh-CN", "set servo:statusword=1");
    assert!(out.contains("error[unsupported]: servo: statusword（6041.00）为只读"), "{out}");
    let out = run("zh-CN", "set servo:target_velocity=300rps");
    assert!(out.contains("此处不识别单位 `rps`；速度请写 rpm 或 dec（驱动器单位）：300rpm"), "{out}");
}

#[test]
fn the_model_catalogues_manual_notes_read_in_the_users_language() {
    // The note wraps at the table's width (a Chinese line may break between two characters):
    // compare without any white space.
    let bare = |s: &str| s.split_whitespace().collect::<String>();
    for (lang, what, other) in [
        ("ru", "частоты HSC и импульсных выходов", "в §2.2.6 и §3.4 нет CPU205EA"),
        ("zh-CN", "HSC 和脉冲输出频率", "§2.2.6 和 §3.4 未列出 CPU205EA"),
    ] {
        let o = plcsh().args(["--lang", lang, "models", "K205EA-18DT"]).output().unwrap();
        let out = String::from_utf8_lossy(&o.stdout);
        assert!(bare(&out).contains(&bare(what)) && bare(&out).contains(&bare(other)), "{lang}:\n{out}");
    }
}

#[test]
fn fx_timer_classes_read_in_the_users_language() {
    let out = run("ru", "connect fx sim-fx:FX2N; help fx:T250");
    has_line(
        &out,
        "T250: таймер 100 ms с сохранением (RST сбрасывает его) (T250–T255); контакт T250 = TS250, катушка TC250, текущее значение TN250; в программе `OUT T250 K50`",
    );
    let out = run("zh-CN", "connect fx sim-fx:FX2N; help fx:C200");
    has_line(&out, "C200：32 位增/减计数器（C200–C234），M8200 为 ON 时减计数；触点 C200 = CS200，当前值 CN200");
}
