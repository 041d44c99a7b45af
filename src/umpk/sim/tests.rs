//! The simulator byte for byte: what a terminal sees for each command in each mode, the
//! programming replies, error 255 and the monitor's rate in virtual time.

use super::logic::{FnRunner, Group};
use super::*;
use crate::umpk::codec::{syserr, Monitor, MONITOR_LEN};
use crate::umpk::hex::Record;
use crate::umpk::model;

fn sim(name: &str) -> (Umpk, Clock) {
    let clock = Clock::stepped();
    (Umpk::new(model::find(name).unwrap(), clock.clone()), clock)
}

/// Sends `text` and returns everything the PLC sent back.
fn talk(u: &mut Umpk, text: &[u8]) -> Vec<u8> {
    u.receive(text);
    u.take_all()
}

fn s(b: &[u8]) -> String {
    String::from_utf8_lossy(b).into_owned()
}

#[test]
fn echo_on_and_off_as_a_terminal_sees_them() {
    let (mut u, _) = sim("UMPK16");
    // Echo on (power-up default): echo, packet, CR LF. Status 00 in Wait.
    assert_eq!(s(&talk(&mut u, b"?03FD")), "?03FD#06102910080001A8\r\n");
    assert_eq!(s(&talk(&mut u, b"?02FE")), "?02FER", "echoed (echo was on), R without CR LF");
    // Echo off: no echo, no CR LF; the E bit (bit 2) is set.
    assert_eq!(s(&talk(&mut u, b"?03FD")), "#06102910080401A4");
    assert_eq!(s(&talk(&mut u, b"?01FF")), "R\r\n", "not echoed (echo was off), CR LF (now on)");
    assert_eq!(s(&talk(&mut u, b"?03FD")), "?03FD#06102910080001A8\r\n");
}

#[test]
fn wait_mode_commands_and_errors() {
    let (mut u, _) = sim("UMPK8");
    talk(&mut u, b"?02FE");
    assert_eq!(s(&talk(&mut u, b"?04FC")), format!("#{}", " ".repeat(22)), "22 spaces in Wait");
    assert_eq!(s(&talk(&mut u, b"?05FB")), "#0400000000FC");
    u.forced_inputs = 0b1001;
    u.clock.step(Duration::from_millis(10));
    assert_eq!(s(&talk(&mut u, b"?05FB")), "#0409000000F3");
    assert_eq!(s(&talk(&mut u, b"?06FA")), "#0400000000FC", "outputs are off outside Work");
    assert_eq!(s(&talk(&mut u, b"?07F9")), "#080000000000000000F8");
    assert_eq!(s(&talk(&mut u, b"?08F8")), "R");
    assert_eq!(s(&talk(&mut u, b"?0CF4")), "#0403E803E826", "firmware 1000 counts, no program");
    assert_eq!(s(&talk(&mut u, b"?03FE")), "E");
    assert_eq!(s(&talk(&mut u, b"?0DF3")), "U");
    assert_eq!(s(&talk(&mut u, b"?0ZFD")), "C");
    assert_eq!(s(&talk(&mut u, b"x")), "C", "a stray character");
    assert_eq!(s(&talk(&mut u, b"\r\n")), "", "line ends between commands are ignored");
    assert_eq!(s(&talk(&mut u, b"?03?03FD")), "C#06082908040401B8", "an abandoned command, then the next");
}

#[test]
fn programming_mode_availability_and_reset() {
    let (mut u, clock) = sim("UMPK16");
    talk(&mut u, b"?02FE");
    assert_eq!(s(&talk(&mut u, b"?09F7")), "R");
    assert_eq!(u.mode(), Mode::Programming);
    // Only reset, echo on/off and controller info answer in Programming mode (Table 6).
    for c in [
        Command::ProgramInfo,
        Command::Inputs,
        Command::Outputs,
        Command::Errors,
        Command::ClearErrors,
        Command::Programming,
        Command::MonitorStart,
        Command::MonitorStop,
        Command::Timing,
    ] {
        assert_eq!(s(&talk(&mut u, &c.encode())), "U", "{}", c.name());
    }
    let info = talk(&mut u, b"?03FD");
    assert_eq!(s(&info), "#06102910080601A2", "P (bit 1) and E set");
    // Reset: silent 0.6 s, then R CR LF with echo on; nothing was erased, nothing programmed: Wait.
    assert_eq!(s(&talk(&mut u, b"?0000")), "");
    clock.step(Duration::from_millis(590));
    assert_eq!(s(&talk(&mut u, b"?03FD")), "", "bytes during the restart are lost");
    clock.step(Duration::from_millis(10));
    assert_eq!(s(&u.take_all()), "R\r\n");
    assert_eq!(u.mode(), Mode::Wait);
    assert!(u.echo());
}

fn program_records(u: &mut Umpk, records: &[Record]) -> String {
    records.iter().map(|r| s(&talk(u, &r.encode()))).collect::<Vec<_>>().join(" ")
}

#[test]
fn hex_programming_end_to_end_and_reset_runs_it() {
    let (mut u, clock) = sim("UMPK16");
    talk(&mut u, b"?02FE");
    assert_eq!(s(&talk(&mut u, &Record::start().encode())), "X", "not in Programming mode");
    talk(&mut u, b"?09F7");
    assert_eq!(s(&talk(&mut u, &Record::data(0, &[1]).encode())), "X", "no start record yet");
    let recs = [
        Record::start(),
        Record::info(b"LAB 1 latch"),
        Record::data(0x00, &[0x11; 64]),
        Record::data(0x40, &[0x22; 64]),
        Record::data(0xBC0, &[0x33; 64]),
        Record::end(),
    ];
    assert_eq!(program_records(&mut u, &recs), "R R R R R R");
    assert_eq!(u.flash[0x3F], 0x11);
    assert_eq!(u.flash[0xBFF], 0x33);
    assert_eq!(s(&talk(&mut u, &Record::data(0xC00, &[1]).encode())), "X", "after the end record");
    talk(&mut u, b"?0000");
    clock.step(RESET_TIME);
    assert_eq!(s(&u.take_all()), "R\r\n");
    assert_eq!(u.mode(), Mode::Work, "programming completed: Work");
    assert_eq!(s(&talk(&mut u, b"?04FC")), "?04FC#LAB 1 latch           \r\n");
}

#[test]
fn every_programming_error_letter() {
    let (mut u, clock) = sim("UMPK8");
    talk(&mut u, b"?02FE");
    talk(&mut u, b"?09F7");
    let start = s(&Record::start().encode());
    let fresh = |u: &mut Umpk| assert_eq!(s(&talk(u, start.as_bytes())), "R");
    fresh(&mut u);
    assert_eq!(s(&talk(&mut u, b":00000001FE")), "E", "checksum");
    assert_eq!(s(&talk(&mut u, &Record::data(0, &[0]).encode())), "X", "aborted: restart from the beginning");
    fresh(&mut u);
    assert_eq!(s(&talk(&mut u, b":020000040000FA")), "U", "record type 04");
    fresh(&mut u);
    assert_eq!(s(&talk(&mut u, b":0100000G00FF")), "C", "illegal character");
    assert_eq!(s(&talk(&mut u, b":ZZ")), "C", "RECLEN not hex");
    fresh(&mut u);
    assert_eq!(s(&talk(&mut u, &Record::data(0, &[0; 65]).encode())), "L", "more than a page");
    fresh(&mut u);
    assert_eq!(s(&talk(&mut u, &Record::info(&[b'x'; 23]).encode())), "L", "info longer than 22");
    fresh(&mut u);
    assert_eq!(
        program_records(&mut u, &[Record::data(0x40, &[1; 64]), Record::data(0, &[1; 64])]),
        "R A",
        "out of sequence"
    );
    fresh(&mut u);
    assert_eq!(s(&talk(&mut u, &Record::data(0x800, &[1; 64]).encode())), "A", "beyond the UMPK8's 2 KB");
    fresh(&mut u);
    assert_eq!(s(&talk(&mut u, &Record::data(0x30, &[1; 32]).encode())), "A", "crosses a page boundary");
    fresh(&mut u);
    u.fail_flash_page(Some(1)).unwrap();
    assert_eq!(
        program_records(&mut u, &[Record::data(0, &[1; 64]), Record::data(0x40, &[1; 64])]),
        "R W",
        "flash write failed"
    );
    // The failed sequence erased the program: after reset the PLC waits.
    talk(&mut u, b"?0000");
    clock.step(RESET_TIME);
    u.take_all();
    assert_eq!(u.mode(), Mode::Wait);
}

/// `flash-fail PAGE` (the control channel, `umpk sim flash-fail`, `--umpk-flash-fail`) takes
/// the pages of the model's program memory (Table 1 row 10: 2 KB = pages 0–31 on the UMPK8,
/// 3 KB = 0–47 on the UMPK16) and refuses the rest naming the range; a page number near
/// `usize::MAX` overflowed its address (`p * 64`) in the fuzz campaign with overflow checks.
#[test]
fn a_failing_flash_page_is_one_of_the_models_pages() {
    for (name, last) in [("UMPK8", 31), ("UMPK16", 47)] {
        let (mut u, _) = sim(name);
        let (text, j) = super::control::answer(&mut u, &format!("flash-fail {last}")).unwrap();
        assert!(text.contains(&format!("page {last} (16#{:04X})", last * 64)), "{text}");
        assert_eq!(j["flash_fail"], last);
        for (page, want) in [
            (format!("{}", last + 1), format!("pages 0–{last}")),
            (usize::MAX.to_string(), format!("pages 0–{last}")),
            ("3444444444444444444444".into(), "is not a page number".into()),
        ] {
            let e = super::control::answer(&mut u, &format!("flash-fail {page}")).unwrap_err();
            assert!(e.to_string().contains(&want), "{page}: {e}");
            let (_, j) = super::control::answer(&mut u, "inputs").unwrap();
            assert!(j.is_object(), "the simulator still answers");
        }
        // A refusal keeps the page set before it.
        assert_eq!(u.flash_fail, Some(last));
        assert!(u.fail_flash_page(Some(last + 1)).unwrap_err().to_string().contains(name));
        super::control::answer(&mut u, "flash-fail off").unwrap();
        assert_eq!(u.flash_fail, None);
    }
}

#[test]
fn a_command_before_the_reply_is_complete_is_error_255() {
    // Served at 57600 baud: take only what has been transmitted.
    let (mut u, clock) = sim("UMPK16");
    u.receive(b"?03FD?07F9");
    clock.step(Duration::from_millis(20));
    let got = s(&u.take_due());
    assert_eq!(got, "?03FD#06102910080001A8\r\n?07F9", "the second reply is lost");
    u.receive(b"?07F9");
    clock.step(Duration::from_millis(20));
    let got = s(&u.take_due());
    assert!(got.starts_with("?07F9#08FF"), "{got}");
    assert_eq!(u.errors()[0], 255);
    // Waiting for the whole reply first: no error.
    u.receive(b"?08F8");
    clock.step(Duration::from_millis(20));
    u.take_due();
    u.receive(b"?03FD");
    clock.step(Duration::from_millis(5));
    assert_eq!(u.take_due().len(), 24, "24 bytes take 4.2 ms at 57600 baud");
    u.receive(b"?07F9");
    clock.step(Duration::from_millis(20));
    assert!(s(&u.take_due()).starts_with("?07F9#0800"));
}

#[test]
fn monitor_streams_once_per_cycle_and_any_command_stops_it() {
    let (mut u, clock) = sim("UMPK16");
    talk(&mut u, b"?02FE");
    assert_eq!(s(&talk(&mut u, b"?0AF6")), "R");
    clock.step(Duration::from_secs(1));
    let out = u.take_all();
    assert_eq!(out.len(), 100 * MONITOR_LEN, "100 packets in one second of virtual time");
    let m = Monitor::decode(&out[..MONITOR_LEN]).unwrap();
    assert_eq!(m.status & (1 << 3), 1 << 3, "R bit");
    talk(&mut u, b"?");
    clock.step(Duration::from_millis(100));
    assert!(u.take_all().is_empty(), "the first byte of any command stops it");
    assert_eq!(s(&talk(&mut u, b"03FD")), "#06102910080401A4");
    // Stop is acknowledged with R.
    talk(&mut u, b"?0AF6");
    clock.step(Duration::from_millis(30));
    let out = talk(&mut u, b"?0BF5");
    assert_eq!(out.len(), 3 * MONITOR_LEN + 1);
    assert_eq!(out[out.len() - 1], b'R');
}

#[test]
fn a_runner_drives_outputs_timers_and_counters_in_work_mode() {
    let (mut u, clock) = sim("UMPK16");
    // Start/stop latch on I0/I1 → Q0; T0 (group 1, 0.5 s) after Q0 → Q1; C0 divides I2 by 4 → Q2.
    u.logic.set_timer(0, Group::Ms100, 5).unwrap();
    u.logic.set_ratio(0, 4).unwrap();
    u.load_logic(Box::new(FnRunner {
        name: "lab1".into(),
        f: |sc: &mut Scan<'_>| {
            let run = (sc.io.input(0) || sc.io.output(0)) && !sc.io.input(1);
            sc.io.set_output(0, run);
            sc.io.set_marker(5, run);
            let t = sc.timer(0, run);
            sc.io.set_output(1, t);
            let c = sc.counter(0, sc.io.input(2), sc.io.input(1));
            sc.io.set_output(2, c);
        },
    }));
    assert_eq!(u.mode(), Mode::Work);
    u.forced_inputs = 1;
    clock.step(Duration::from_millis(20));
    u.take_all();
    u.forced_inputs = 0;
    clock.step(Duration::from_millis(100));
    u.take_all();
    assert_eq!(u.image.outputs & 3, 1, "latched, timer running");
    clock.step(Duration::from_millis(500));
    u.take_all();
    assert_eq!(u.image.outputs & 3, 3, "T0 done after 0.5 s");
    assert!(u.image.marker(5));
    // Divide a 10 Hz square wave on I2 by 4: one output pulse of 50 ms per 400 ms.
    u.set_wave(2, 10);
    let mut high = 0;
    for _ in 0..40 {
        clock.step(Duration::from_millis(10));
        u.take_all();
        high += u.image.outputs >> 2 & 1;
    }
    assert_eq!(high, 5, "one 5-cycle pulse in 40 cycles");
    // Programming mode forces outputs off.
    talk(&mut u, b"?09F7");
    clock.step(Duration::from_millis(10));
    u.take_all();
    assert_eq!(u.image.outputs, 0);
}

#[test]
fn hostile_bytes_never_panic_and_cost_linear_time() {
    let (mut u, clock) = sim("UMPK16");
    let mut seed = 0x2545_F491u32;
    let mut junk = Vec::with_capacity(200_000);
    for _ in 0..200_000 {
        seed ^= seed << 13;
        seed ^= seed >> 17;
        seed ^= seed << 5;
        // Mostly protocol characters, so commands and records start and break often.
        junk.push(b"?:0123456789ABCDEFZ\r\n\xAA"[(seed % 22) as usize]);
    }
    let t = std::time::Instant::now();
    for chunk in junk.chunks(97) {
        u.receive(chunk);
        clock.step(Duration::from_millis(3));
        u.take_all();
    }
    assert!(t.elapsed() < Duration::from_secs(20), "{:?}", t.elapsed());
    // Still a working controller afterwards (after a reset, if the junk asked for one).
    talk(&mut u, b"\r");
    clock.step(RESET_TIME);
    u.take_all();
    talk(&mut u, b"?01FF");
    assert!(s(&talk(&mut u, b"?03FD")).starts_with("?03FD#0610"));
}

#[test]
fn a_year_of_idle_time_costs_one_cycle() {
    let (mut u, clock) = sim("UMPK8");
    u.set_input(1, true);
    clock.step(Duration::from_secs(365 * 24 * 3600));
    let t = std::time::Instant::now();
    assert_eq!(s(&talk(&mut u, b"?05FB")), "?05FB#0402000000FA\r\n");
    assert!(t.elapsed() < Duration::from_secs(10), "{:?}", t.elapsed());
}

#[test]
fn state_file_keeps_what_was_acknowledged() {
    let dir = std::env::temp_dir().join(format!("plcsh-umpk-state-{}", std::process::id()));
    let path = dir.join("u.json");
    let _ = std::fs::remove_file(&path);
    let (mut u, _) = sim("UMPK8");
    u.open_state(&path).unwrap();
    talk(&mut u, b"?02FE");
    talk(&mut u, b"?09F7");
    let recs = [Record::start(), Record::info(b"KEPT"), Record::data(0x40, &[9; 64]), Record::end()];
    assert_eq!(program_records(&mut u, &recs), "R R R R");
    u.push_error(7);
    // A new controller on the same file powers up with the program, its info and history.
    let (mut v, _) = sim("UMPK8");
    v.open_state(&path).unwrap();
    assert_eq!(v.mode(), Mode::Work);
    assert_eq!(&v.program_info()[..4], b"KEPT");
    assert_eq!(v.flash[0x40..0x80], [9; 64]);
    assert_eq!(v.errors()[0], 7);
    // Another model's file is refused; a damaged one too.
    let (mut w, _) = sim("UMPK16");
    assert!(w.open_state(&path).unwrap_err().message.contains("UMPK8"));
    std::fs::write(&path, "{").unwrap();
    assert!(v.open_state(&path).is_err());
    let _ = std::fs::remove_dir_all(&dir);
}

/// Loads IL `text` as the program (Work mode).
fn load_il(u: &mut Umpk, text: &str) {
    let r = super::program::IlRunner::load(text, "p.il", u.model).unwrap();
    u.load_logic(Box::new(r));
}

fn status(u: &Umpk) -> Status {
    u.layout.decode(u.controller_info().status)
}

#[test]
fn a_program_that_overruns_the_cycle_shows_through_the_protocol() {
    let (mut u, clock) = sim("UMPK16");
    load_il(&mut u, "LD I0\nST Q0\nTOP:\nJMP TOP\n");
    assert_eq!(u.mode(), Mode::Work);
    u.set_input(0, true);
    clock.step(Duration::from_millis(30));
    u.take_all();
    // System error 254 in the history, Wait mode (W off, H on), outputs off.
    let mut want = b"?07F9".to_vec();
    want.extend(packet(&[syserr::CYCLE_OVERRUN, 0, 0, 0, 0, 0, 0, 0]));
    want.extend(b"\r\n");
    assert_eq!(s(&talk(&mut u, b"?07F9")), s(&want));
    assert_eq!(u.mode(), Mode::Wait);
    let st = status(&u);
    assert!(!st.work && st.errors, "{st:?}");
    assert_eq!(u.image.outputs, 0);
    assert!(u.program_kind().contains("stopped"), "{}", u.program_kind());
    // The same after more cycles: stopped once, recorded once.
    clock.step(Duration::from_millis(100));
    u.take_all();
    assert_eq!(&u.errors()[..2], &[syserr::CYCLE_OVERRUN, 0]);
    // A reset starts the program again (in Work mode, in its first cycle), and it overruns
    // again.
    talk(&mut u, b"?0000");
    clock.step(RESET_TIME + Duration::from_millis(20));
    u.take_all();
    assert_eq!(&u.errors()[..3], &[syserr::CYCLE_OVERRUN, syserr::CYCLE_OVERRUN, 0]);
    assert_eq!(u.mode(), Mode::Wait);
    // A program that fits runs after a reset as before.
    load_il(&mut u, "LD I0\nST Q0\n");
    clock.step(Duration::from_millis(20));
    u.take_all();
    assert_eq!((u.mode(), u.image.outputs & 1), (Mode::Work, 1));
}

#[test]
fn an_il_program_raises_user_error_codes_into_the_history() {
    let (mut u, clock) = sim("UMPK16");
    load_il(&mut u, "LD I7\nERROR 12\nLD I6\nERROR 127\nLD I0\nST Q0\n");
    let step = |u: &mut Umpk| {
        clock.step(Duration::from_millis(10));
        u.take_all();
    };
    step(&mut u);
    assert_eq!(u.errors(), [0; 8]);
    u.set_input(7, true);
    u.set_input(0, true);
    for _ in 0..5 {
        step(&mut u);
    }
    assert_eq!(&u.errors()[..2], &[12, 0], "once, on the rising edge");
    u.set_input(7, false);
    step(&mut u);
    u.set_input(7, true);
    u.set_input(6, true);
    step(&mut u);
    assert_eq!(&u.errors()[..4], &[127, 12, 12, 0], "newest first");
    // The program keeps running; the history is what ?07F9 sends, H is set.
    assert_eq!(u.mode(), Mode::Work);
    assert_eq!(u.image.outputs & 1, 1);
    let mut want = b"?07F9".to_vec();
    want.extend(packet(&[127, 12, 12, 0, 0, 0, 0, 0]));
    want.extend(b"\r\n");
    assert_eq!(s(&talk(&mut u, b"?07F9")), s(&want));
    assert!(status(&u).errors && status(&u).work);
    // Codes outside 1–127 are refused at load time.
    for bad in ["LD I0\nERROR 0\n", "LD I0\nERROR 128\n"] {
        let e = super::program::IlRunner::load(bad, "p.il", u.model).err().expect(bad).to_string();
        assert!(e.contains("p.il:2:1") && e.contains("1–127"), "{bad}: {e}");
    }
    let e = super::program::IlRunner::load("LD I0\nERROR Q0\n", "p.il", u.model).err().unwrap().to_string();
    assert!(e.contains("constant"), "{e}");
}
