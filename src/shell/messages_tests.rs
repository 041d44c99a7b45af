//! The shell's messages as a new user meets them: every "did you mean" names something, the
//! input is quoted as typed, and the K2 manual's own spelling is accepted with a note.

use super::Shell;
use crate::core::{Clock, Error};
use crate::output::Style;
use crate::session::Session;

fn shell() -> Shell {
    let mut s = Session::new(Clock::stepped());
    s.open("plc", "sim:K205-16DT").unwrap();
    s.open("servo", "sim-servo:?id=1").unwrap();
    Shell::new(s, Style { json: true, color: false })
}

fn error(sh: &mut Shell, line: &str) -> Error {
    let r = sh.exec(line);
    r.into_iter().find_map(|r| r.err()).unwrap_or_else(|| panic!("`{line}` should fail")).1
}

#[test]
fn suggestions_are_never_empty() {
    let mut sh = shell();
    for line in ["get DB1.DBW0", "get -v VW0", "get xw0", "get 5", "help gte", "servo stauts"] {
        let e = error(&mut sh, line);
        let hint = e.hint.clone().unwrap_or_default();
        assert!(!hint.is_empty(), "{line}: no hint in {e}");
        assert!(!hint.contains("mean ?") && !hint.contains("``") && !e.message.contains("``"), "{line}: {e} / {hint}");
    }
}

#[test]
fn errors_quote_the_input_as_typed() {
    let mut sh = shell();
    let e = error(&mut sh, "get -v VW0");
    assert!(e.message.contains("`-v`"), "{e}");
    let e = error(&mut sh, "get xw0");
    assert!(e.message.contains("`xw0`") && e.message.contains("`xw`"), "{e}");
    let e = error(&mut sh, "set VW0=0x10");
    assert!(e.message.contains("`0x10`"), "{e}");
    let e = error(&mut sh, "set VW0=x#5");
    assert!(e.message.contains("`x#`"), "{e}");
    let e = error(&mut sh, "set VW0=16#fg");
    assert!(e.message.contains("`g`"), "{e}");
}

#[test]
fn sub_command_typos_name_the_nearest_sub_command() {
    let mut sh = shell();
    let e = error(&mut sh, "servo stauts");
    assert!(e.hint.as_deref().unwrap_or("").contains("`servo status`"), "{e:?}");
    let e = error(&mut sh, "help gte");
    assert!(e.hint.as_deref().unwrap_or("").contains("`get`"), "{e:?}");
}

#[test]
fn the_manuals_cyrillic_spelling_is_accepted_with_a_note() {
    let mut sh = shell();
    // The K2 manual prints `В#16#85` with a Cyrillic В and `% VW2` with a space.
    let r = sh.exec("set SMB67=В#16#85; get SMB67");
    let o = r[0].as_ref().unwrap();
    assert!(o.notes.iter().any(|n| n.contains("`SMB67=В#16#85` as `SMB67=B#16#85`")), "{:?}", o.notes);
    assert_eq!(r[1].as_ref().unwrap().values[0].value, crate::core::Value::Int(0x85));
    let r = sh.exec("get % VW2 ВW0");
    let o = r[0].as_ref().unwrap();
    assert_eq!(o.values.iter().map(|v| v.operand.as_str()).collect::<Vec<_>>(), ["VW2", "VW0"]);
    assert!(!o.notes.is_empty());
    // A trailing comment, as a checklist writes one, is not an operand.
    assert!(sh.exec("get VW0   # speed set-point")[0].is_ok());
    // … but the manual's spaced literal is a value, not a comment.
    assert_eq!(value_of(&mut sh, "set SMB67=B # 16 # 86; get SMB67"), crate::core::Value::Int(0x86));
}

#[test]
fn c_hex_and_negative_words_suggest_the_iec_form() {
    let mut sh = shell();
    let e = error(&mut sh, "set VW0=0x10");
    assert!(e.message.contains("16#10"), "{e}");
    let e = error(&mut sh, "set VW0=-5");
    assert!(e.message.contains("INT#-5") && !e.message.contains("DI#"), "{e}");
    let e = error(&mut sh, "set VB0=-5");
    assert!(e.message.contains("SINT#-5"), "{e}");
    assert!(sh.exec("set VW0=INT#-5")[0].is_ok());
}

fn value_of(sh: &mut Shell, line: &str) -> crate::core::Value {
    let r = sh.exec(line);
    r.last().unwrap().as_ref().unwrap_or_else(|e| panic!("{line}: {}", e.1)).values[0].value
}

#[test]
fn position_and_counter_values_read_signed() {
    use crate::core::Value;
    let mut sh = shell();
    // §3.4.3.1: the position current value SMD212 is a DINT (+forward / −reverse); load a
    // negative new current value (SMD208, control bit 4 of SMB201) and read it back.
    assert_eq!(value_of(&mut sh, "set SMD208=-50, SMB201=16#10; sim step 10ms; get SMD212"), Value::Int(-50));
    // §3.3.2: a counter counting down goes below zero, as `hsc status` says.
    let v = value_of(&mut sh, "hsc 0 mode=0 dir=down; sim input I0.1 freq=1kHz; sim step 100ms; get SMD38");
    assert_eq!(v, Value::Int(-100));
    // A pulse count stays unsigned.
    assert_eq!(crate::k2::operand::parse_one("SMD72").unwrap().view, crate::core::DataType::DWord);
}

#[test]
// 3.14 is the value a user types (`VD8/REAL=3.14`), not an approximation of π.
#[allow(clippy::approx_constant)]
fn reals_show_the_shortest_text_that_reads_back() {
    let mut sh = shell();
    let v = value_of(&mut sh, "set VD8/REAL=3.14; get VD8/REAL");
    assert_eq!(v.to_string(), "3.14");
    assert_eq!(crate::output::show_value(&v, crate::core::DataType::Real), "3.14");
    // Writing the value shown stores the same bits.
    let raw = value_of(&mut sh, "get VD8");
    assert_eq!(raw, crate::core::Value::Int(3.14f32.to_bits() as i64));
}

/// A second PLS (or `pto`, `profile`) on a channel still sending warns (SM66.7 PTO idle = 0,
/// §3.4.1); with `strict` it is refused and nothing is written. An idle channel is quiet.
#[test]
fn pls_on_a_busy_channel_warns_and_strict_refuses() {
    let mut sh = shell();
    let r = sh.exec("pto 0 freq=1kHz count=1000; sim step 100ms; pls 0");
    let o = r[2].as_ref().unwrap();
    assert!(o.notes.iter().any(|n| n.contains("PTO0 is still sending") && n.contains("SM66.7")), "{:?}", o.notes);
    let e = error(&mut sh, "pto 0 freq=2kHz count=10 strict");
    assert!(e.message.contains("would replace it; nothing was written"), "{e}");
    let count = value_of(&mut sh, "get SMD72");
    assert_eq!(count, crate::core::Value::Int(1000), "strict wrote nothing");
    assert!(error(&mut sh, "pls 0 strict").message.contains("still sending"));
    // Once the train is done the channel is idle: no warning.
    let r = sh.exec("sim step 2s; pls 0 strict");
    assert!(r[1].as_ref().unwrap().notes.is_empty());
}

/// A step past what the simulated clock counts is refused naming the limit, not saturated.
#[test]
fn a_step_past_the_clocks_range_is_refused() {
    let mut sh = shell();
    for step in ["106751991d", "365000d"] {
        let e = error(&mut sh, &format!("sim step {step}"));
        assert!(e.message.contains("about 584 years"), "{step}: {e}");
    }
    assert!(sh.exec("sim step 36500d").into_iter().all(|r| r.is_ok()), "a century is fine");
}

/// One line per fact: a profile run states its pulses and duration once.
#[test]
fn a_profile_run_reports_each_fact_once() {
    let mut sh = shell();
    let r = sh.exec("profile 0 at VB3001 [(freq=1kHz, count=1000), (freq=2kHz, count=4000)]");
    let text = r[0].as_ref().unwrap().message.clone().unwrap();
    assert_eq!(text.matches("5000 pulses").count(), 1, "{text}");
}

/// One unit rule (README "Units"): a bare number in a command is the quantity's engineering
/// unit — ms for times, rpm and rps/s for servo speeds and accelerations; raw drive values
/// carry their suffix (`dec`).
#[test]
fn bare_numbers_follow_one_unit_rule() {
    let mut sh = shell();
    // every=100 is 100 ms: one second gives 11 samples.
    let r = sh.exec("trace VW0 every=100 for=1000");
    assert_eq!(r[0].as_ref().unwrap().data["samples"], 11);
    // speed=300 is 300 rpm and acc=100 is 100 rps/s, not the drive's raw DEC.
    let r = sh.exec("servo enable; servo mode position; servo move abs 10000 speed=300 acc=100");
    let o = r[2].as_ref().unwrap_or_else(|e| panic!("{}", e.1));
    assert!(o.message.as_deref().unwrap_or("").contains("300 rpm"), "{o:?}");
    let acc = value_of(&mut sh, "get servo:profile_acceleration");
    let r = crate::servo::units::DEFAULT_RESOLUTION;
    let want = crate::servo::units::rps2_to_dec(crate::servo::units::parse_decimal("100").unwrap(), r);
    assert_eq!(acc.as_i64() as i128, want);
    // The raw value is still reachable, with its suffix.
    let r = sh.exec("servo move abs 0 speed=2731dec");
    assert!(r[0].as_ref().unwrap().message.as_deref().unwrap_or("").contains("(2731 DEC)"));
}

/// Quoted text is text: a `#` or `;` in quotes neither comments nor splits, and neither quoted
/// words nor file paths are read in the manual's spelling, while the operands beside them are.
#[test]
fn quotes_and_paths_are_read_as_typed() {
    assert_eq!(super::strip_comment(r#"eeprom dump "a #1.bin" # note"#), r#"eeprom dump "a #1.bin" "#);
    assert_eq!(super::strip_comment("trace VW0 to='#1 .csv'"), "trace VW0 to='#1 .csv'");
    // The manual's spaced literal with a Cyrillic В is still a value, not a comment.
    assert_eq!(super::strip_comment("set SMB67=В # 16 # 85"), "set SMB67=В # 16 # 85");
    let mut sh = shell();
    let e = error(&mut sh, "sim program load Проверка/светофор.il");
    assert!(e.message.contains("Проверка/светофор.il"), "the path as typed: {e}");
    let e = error(&mut sh, "sim program load 'Лаб 1/светофор.il'; get VW0");
    assert!(e.message.contains("Лаб 1/светофор.il"), "{e}");
    let r = sh.exec("set VW0=7; get 'VW0'");
    assert!(r[1].is_err(), "a quoted word is text, never an operand: {:?}", r[1]);
}

/// The shell's reading of a line is linear in its length, whatever it holds.
#[test]
fn long_lines_are_read_in_linear_time() {
    for unit in ["# ", "В # ", "% ", "'a' ", "ВW0 ", "\"\\\"\" ", "to=x "] {
        let line = format!("trace {}", unit.repeat(100_000));
        let t = std::time::Instant::now();
        let _ = super::strip_comment(&line);
        let _ = super::fold_operands("trace", &line);
        let _ = super::fold_operands("sim", &format!("program load {line}"));
        assert!(t.elapsed() < std::time::Duration::from_secs(10), "{unit:?}: {:?}", t.elapsed());
    }
}

/// Messages that name the mistake and the form that works, at the word they are about.
#[test]
fn messages_name_the_mistake_and_the_correct_form() {
    let mut sh = shell();
    // Two writes after a space: the comma that separates them.
    let e = error(&mut sh, "set VW0=5 VW2=6");
    assert!(e.message.contains("separated by commas") && e.message.contains("set VW0=5, VW2=6"), "{e}");
    assert_eq!(e.column, Some(10), "at the second write");
    // A negative count: what a count is.
    let e = error(&mut sh, "pto 0 freq=1kHz count=-5");
    assert!(e.message.contains("count must be a positive whole number"), "{e}");
    // A cycle too short is told as the cycle typed (2 µs), with the shortest there is (§3.4).
    let e = error(&mut sh, "pto 0 cycle=2 count=10");
    assert!(e.message.contains("cycle of 2 µs is too short") && e.message.contains("shortest cycle is"), "{e}");
    assert!(!e.message.contains("500000 Hz"), "{e}");
    assert_eq!(e.column, Some(6), "at cycle=");
    // A unit the drive's speeds do not take.
    for line in ["servo move abs 100 speed=300rps", "servo jog 300rps"] {
        let e = error(&mut sh, line);
        assert!(e.message.contains("unit `rps` is not known here") && e.message.contains("rpm"), "{line}: {e}");
    }
}

/// A write the session's rules refuse is `kind: "refused"` (docs/json.md), not a usage error.
#[test]
fn write_rule_refusals_are_kind_refused() {
    let mut sh = shell();
    sh.session.set_read_only(true);
    let e = error(&mut sh, "set VW0=1");
    assert_eq!(e.kind, crate::core::ErrorKind::Refused, "{e}");
    assert_eq!(e.kind.name(), "refused");
}

/// A jog or move above the drive's configured maximum speed (6080.00) is refused with that
/// maximum; the simulated drive's is 3000 rpm.
#[test]
fn speeds_above_the_drives_maximum_are_refused_with_it() {
    let mut sh = shell();
    for line in ["servo jog 99999rpm", "servo move abs 1000 speed=3001rpm", "servo jog -4000"] {
        let e = error(&mut sh, line);
        assert!(e.message.contains("maximum speed of 3000 rpm"), "{line}: {e}");
        assert_eq!(e.kind, crate::core::ErrorKind::Range, "{line}");
    }
    // The limit is the drive's setting, read each time.
    let r = sh.exec("set servo:max_speed=5000; servo enable; servo jog 4000rpm");
    assert!(r.iter().all(|r| r.is_ok()), "{r:?}");
}

/// `connect`, `use` and `close` read quoted words by the shell's one quoting rule: the
/// quotes are not part of the name or the URL.
#[test]
fn connect_use_and_close_take_quoted_words_as_their_text() {
    let mut sh = shell();
    for r in sh.exec("connect k2 'sim:K209EA-50DX'; use \"k2\"; get VW0; close 'k2'") {
        r.unwrap_or_else(|(_, e)| panic!("{e}"));
    }
    assert!(sh.session.entries().iter().all(|e| e.name != "k2"), "closed");
    let e = error(&mut sh, "use 'nosuch'");
    assert!(e.message.contains("nosuch") && !e.message.contains("'nosuch'"), "{e}");
}

/// Each refusal names its own word at its own column, with the form it breaks, in a hint a
/// person reads at a glance.
#[test]
fn extra_words_are_refused_at_their_column_with_a_short_hint() {
    let mut sh = shell();
    let e = error(&mut sh, "sim fault clear 1 x");
    assert_eq!(e.column, Some(18), "{e}");
    assert!(e.message.contains("unexpected `x`") && e.message.contains("sim fault clear [ID|all]"), "{e}");
    assert!(e.hint.as_deref().unwrap_or("").len() <= 100, "{e:?}");
    let e = error(&mut sh, "sim fault clear x");
    assert_eq!(e.column, Some(16), "{e}");
    let e = error(&mut sh, "sim retain none x");
    assert_eq!(e.column, Some(16), "{e}");
    assert!(!e.message.contains("operand"), "`none` is no operand: {e}");
    let e = error(&mut sh, "sim program load 'my prog.il' extra");
    assert_eq!(e.column, Some(30), "{e}");
    let hint = e.hint.clone().unwrap_or_default();
    assert!(!hint.contains("extra"), "the extra word is not folded into the file name: {hint}");
    let e = error(&mut sh, "sim step 1 s");
    assert!(e.hint.as_deref().unwrap_or("").contains("sim step 1s"), "{e:?}");
}

/// `servo sim fault no-reply all` (a form on the command card) silences every request, not
/// one; `late D` is `delay D`; a stray word is refused.
#[test]
fn servo_sim_no_reply_all_is_every_request() {
    let mut sh = shell();
    let r = sh.exec("servo servo sim fault no-reply all");
    let o = r[0].as_ref().unwrap_or_else(|(_, e)| panic!("{e}"));
    assert!(o.message.as_deref().unwrap_or("").contains("every request"), "{:?}", o.message);
    for _ in 0..3 {
        assert!(sh.exec("servo servo status")[0].is_err(), "each request goes unanswered");
    }
    assert!(sh.exec("servo servo sim fault clear")[0].is_ok());
    assert!(sh.exec("servo servo status")[0].is_ok());
    let r = sh.exec("servo servo sim fault late 50ms");
    assert!(r[0].is_ok(), "{:?}", r[0].as_ref().err());
    assert!(sh.exec("servo servo sim fault clear")[0].is_ok());
    assert!(sh.exec("servo servo sim fault no-reply zz")[0].is_err());
}

/// Device and profile names are Latin letters, digits, `_` and `-`, and the refusal says so
/// (never just "letters", which a Cyrillic name is too).
#[test]
fn a_cyrillic_device_name_is_refused_saying_latin_letters() {
    let mut sh = shell();
    let e = error(&mut sh, "connect пресс sim:K205-16DT");
    assert!(e.message.contains("Latin letters"), "{e}");
}
