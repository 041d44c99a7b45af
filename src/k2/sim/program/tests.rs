//! The simulated K2 running programs: scan cycle, system bits, scan-time registers,
//! modes, watchdog, the manual's IL snippets, and K2 instructions from a program.

use super::{family, Mode};
use crate::core::{Clock, Device, OperandSpace, Value};
use crate::engine::FaultKind;
use crate::k2::sim::{self, K2Sim};
use std::time::Duration;

fn sim() -> (K2Sim, Clock) {
    let clock = Clock::stepped();
    (sim::open("K205-16DT", clock.clone()).unwrap(), clock)
}

fn get(s: &mut K2Sim, text: &str) -> Value {
    let op = s.space().parse(text).unwrap()[0];
    s.read(&[op]).unwrap()[0]
}

fn set(s: &mut K2Sim, text: &str, v: Value) {
    let op = s.space().parse(text).unwrap()[0];
    s.write(&[(op, v)]).unwrap();
}

fn on(s: &mut K2Sim, t: &str) -> bool {
    get(s, t) == Value::Bool(true)
}

#[test]
fn sm0_1_is_on_in_the_first_scan_only_and_scans_follow_the_cost_table() {
    let (mut s, clock) = sim();
    // Q0.0 := SM0.1 latched; count scans in VW0.
    s.load_program("LD %SM0.1\nS %Q0.0, 1\nLD %SM0.0\nINC %VW0\nLD %SM0.6\nST %Q0.1", "t.il").unwrap();
    assert!(on(&mut s, "Q0.0"), "SM0.1 was on in the first scan");
    assert_eq!(get(&mut s, "VW0"), Value::Int(1));
    clock.step(Duration::from_millis(10));
    // 10 ms of 1 ms scans (the program costs far less than the 1 ms minimum) → 11 scans.
    assert_eq!(get(&mut s, "VW0"), Value::Int(11));
    assert_eq!(get(&mut s, "SMW22"), Value::Int(1), "last scan time 1 ms (SMW22)");
    let p = s.plc().unwrap();
    assert_eq!(p.stats.scans, 11);
    assert_eq!(p.stats.last_instructions, 7, "six and the implicit end");
}

#[test]
fn a_long_program_has_a_long_scan() {
    let (mut s, clock) = sim();
    // 2000 word moves at 2 µs each + 0.3 ms overhead = 4.3 ms scans.
    let text = "LD %SM0.0\n".to_string() + &"MOVE %VW2, %VW4\n".repeat(2000) + "INC %VW0\n";
    s.load_program(&text, "long.il").unwrap();
    clock.step(Duration::from_millis(43));
    assert_eq!(get(&mut s, "VW0"), Value::Int(10), "scans at 0, 4.3042, … 38.74 ms");
    let st = s.plc().unwrap().stats;
    assert_eq!(st.last_ns, 300_000 + 200 + 2000 * 2_000 + 3_000 + 1_000, "overhead + LD + moves + INC + end");
    assert_eq!(get(&mut s, "SMW26"), Value::Int(4), "max scan time in ms (SMW26)");
}

#[test]
fn a_ton_times_in_virtual_time() {
    // T37 is a 100 ms timer (T20–T255), T2 a 1 ms timer (T0–T3).
    let (mut s, clock) = sim();
    s.load_program("LD %I0.0\nTON T37, 30\nST %Q0.0\nLD %I0.0\nTON T2, 5\nST %Q0.1", "ton.il").unwrap();
    set(&mut s, "I0.0", Value::Bool(true));
    // The next scan (1 ms later) sees the input and starts the timers.
    clock.step(Duration::from_millis(5));
    assert!(!on(&mut s, "Q0.1"));
    clock.step(Duration::from_millis(1));
    assert!(on(&mut s, "Q0.1"), "T2: 5 × 1 ms");
    clock.step(Duration::from_millis(2994));
    assert!(!on(&mut s, "Q0.0"));
    assert_eq!(get(&mut s, "T37"), Value::Int(29), "T37's value readable as T37");
    clock.step(Duration::from_millis(2));
    assert!(on(&mut s, "Q0.0"), "T37: 30 × 100 ms");
    assert_eq!(s.mem.tq[37], 1, "the timer bit (T37 in a bit context)");
    assert!(on(&mut s, "T37/BOOL"), "…read from outside as T37/BOOL");
}

#[test]
fn the_manuals_snippet_moves_a_new_current_value() {
    // K2 §3.4.3.1 method 2: LD %M0.4 / R_TRIG / MOVE DI#100, %SMD208 / ST %SM201.4 — on
    // DONE's rising edge SMD208 = 100 and SM201.4 = 1 load the current value SMD212 = 100.
    let (mut s, clock) = sim();
    s.load_program("(* Network 1 *)\nLD %M0.4\nR_TRIG\nMOVE DI # 100, %SMD208\nST %SM201.4", "manual.il").unwrap();
    assert_eq!(get(&mut s, "SMD212/DINT"), Value::Int(0));
    set(&mut s, "M0.4", Value::Bool(true));
    clock.step(Duration::from_millis(1));
    assert_eq!(get(&mut s, "SMD208"), Value::Int(100));
    assert_eq!(get(&mut s, "SMD212/DINT"), Value::Int(100), "SM201.4 loaded SMD208 into SMD212");
    clock.step(Duration::from_millis(1));
    assert!(!on(&mut s, "SM201.4"), "R_TRIG: one scan");
}

#[test]
fn a_program_starts_a_pulse_train_with_pls() {
    // K2 §3.4.2: SMB67 = 16#85, SMW68 = cycle, SMD72 = count, then PLS 0 on a rising edge.
    let (mut s, clock) = sim();
    s.load_program(
        "LD %SM0.1\nMOVE B#16#85, %SMB67\nMOVE 500, %SMW68\nMOVE DI#1000, %SMD72\nLD %I0.0\nPLS 0\nST %M0.0",
        "pto.il",
    )
    .unwrap();
    set(&mut s, "I0.0", Value::Bool(true));
    clock.step(Duration::from_millis(1));
    assert!(on(&mut s, "M0.0"), "ENO of PLS");
    assert!(!on(&mut s, "SM66.7"), "PTO0 busy");
    clock.step(Duration::from_millis(501));
    assert!(on(&mut s, "SM66.7"), "idle after 1000 × 500 µs");
    assert_eq!(get(&mut s, "SMD212/DINT"), Value::Int(1000));
}

/// K2 §3.4.2 (PLS, IL): «Если CR = 1, то PLS выполняется. Это не повлияет на значение CR.»
/// A refused PLS (pulse count below 2, §3.4.2.2: «Время цикла и количество импульсов должны
/// быть больше 1») leaves the CR on as an accepted one does; only the channel's status bit
/// SM66.4 tells them apart.
#[test]
fn pls_leaves_the_cr_as_it_was_and_a_refusal_shows_only_in_status_bit_4() {
    for (count, refused) in [("DI#1", true), ("DI#10", false)] {
        let (mut s, clock) = sim();
        let text = format!(
            "LD %SM0.0\nMOVE B#16#85, %SMB67\nMOVE W#16#03E8, %SMW68\nMOVE {count}, %SMD72\nLD %SM0.1\nPLS 0\nS %V0.0, 1"
        );
        s.load_program(&text, "repro.il").unwrap();
        clock.step(Duration::from_millis(1));
        assert!(on(&mut s, "V0.0"), "{count}: the CR after PLS is the CR before it (§3.4.2)");
        assert_eq!(
            on(&mut s, "SM66.4"),
            refused,
            "{count}: status bit 4, cycle time or pulse count invalid (§3.4.2.2)"
        );
        clock.step(Duration::from_millis(20));
        let pulses = if refused { 0 } else { 10 };
        assert_eq!(get(&mut s, "SMD212/DINT"), Value::Int(pulses), "{count}: a refused PLS starts no train");
    }
}

#[test]
fn an_endless_loop_trips_the_watchdog_and_stops_the_cpu() {
    // K80S: a scan past the watchdog stops the CPU and turns outputs off; a fault is recorded.
    let (mut s, clock) = sim();
    s.load_program("LD %SM0.0\nS %Q0.0, 2\nLD %I0.0\nJMPC LOOP\nJMP END\nLOOP: LD %SM0.0\nJMP LOOP\nEND:", "wd.il")
        .unwrap();
    clock.step(Duration::from_millis(5));
    assert!(on(&mut s, "Q0.0") && on(&mut s, "Q0.1"));
    set(&mut s, "I0.0", Value::Bool(true));
    clock.step(Duration::from_millis(2));
    s.advance();
    let p = s.plc().unwrap();
    assert_eq!(p.mode, Mode::Stop);
    let f = &p.faults[0];
    assert_eq!(f.kind, FaultKind::Watchdog);
    assert!(f.line == 6 || f.line == 7, "where the loop was: {f}");
    assert!(!on(&mut s, "Q0.0") && !on(&mut s, "Q0.1"), "outputs at their STOP values");
    let scans = s.plc().unwrap().stats.scans;
    clock.step(Duration::from_millis(100));
    s.advance();
    assert_eq!(s.plc().unwrap().stats.scans, scans, "no scans in STOP");
    // Modbus is still served in STOP: memory reads and writes work.
    set(&mut s, "VW0", Value::Int(5));
    assert_eq!(get(&mut s, "VW0"), Value::Int(5));
    // STOP → RUN restarts (first scan again) — the input still loops, so clear it first.
    set(&mut s, "I0.0", Value::Bool(false));
    s.set_mode(Mode::Run).unwrap();
    assert!(on(&mut s, "Q0.0"));
}

#[test]
fn pause_freezes_and_run_resumes_without_reinitialising() {
    let (mut s, clock) = sim();
    s.load_program("LD %SM0.1\nMOVE 100, %VW0\nLD %SM0.0\nINC %VW2\nLD %I0.0\nTON T37, 10\nST %Q0.0", "p.il").unwrap();
    set(&mut s, "I0.0", Value::Bool(true));
    clock.step(Duration::from_millis(500));
    let t = get(&mut s, "T37");
    s.set_mode(Mode::Pause).unwrap();
    set(&mut s, "VW0", Value::Int(7));
    clock.step(Duration::from_millis(700));
    assert_eq!(get(&mut s, "T37"), t, "frozen");
    let n = get(&mut s, "VW2");
    s.set_mode(Mode::Run).unwrap();
    clock.step(Duration::from_millis(3));
    assert_eq!(get(&mut s, "VW0"), Value::Int(7), "no first scan again: SM0.1 stayed off");
    assert!(get(&mut s, "VW2").as_i64() > n.as_i64(), "scanning again");
    assert_eq!((t, get(&mut s, "T37")), (Value::Int(4), Value::Int(5)), "499 ms before the pause + 3 ms after");
    assert!(!on(&mut s, "Q0.0"));
    clock.step(Duration::from_millis(500));
    assert!(on(&mut s, "Q0.0"), "1 s of RUN in all");
}

#[test]
fn the_switch_at_stop_wins_over_a_run_command() {
    // K2 §2.2.1 table: switch STOP + command RUN = STOP.
    let (mut s, _) = sim();
    s.load_program("LD %SM0.0\nS %Q0.0, 1", "s.il").unwrap();
    assert!(on(&mut s, "Q0.0"));
    s.set_switch(false).unwrap();
    assert_eq!(s.plc().unwrap().mode, Mode::Stop);
    assert!(!on(&mut s, "Q0.0"));
    assert!(s.set_mode(Mode::Run).is_err());
    assert_eq!(s.plc().unwrap().mode, Mode::Stop);
    s.set_switch(true).unwrap();
    s.set_mode(Mode::Run).unwrap();
    assert!(on(&mut s, "Q0.0"));
}

#[test]
fn load_errors_name_the_file_line_and_a_suggestion() {
    let (mut s, _) = sim();
    let e = s.load_program("LD %SM0.0\nMOVE 1, %VX0", "bad.il").unwrap_err();
    assert!(e.message.starts_with("bad.il:2:9:"), "{}", e.message);
    let e = s.load_program("LD %SM0.0\nMOVEE 1, %VW0", "bad.il").unwrap_err();
    assert!(e.hint.as_deref().unwrap_or("").contains("MOVE"), "{:?}", e.hint);
    // A typo is never pointed at an instruction that starts pulses (engine::isa::NEVER_SUGGESTED).
    let e = s.load_program("LD %SM0.0\nPLSS 0", "bad.il").unwrap_err();
    assert!(!e.hint.as_deref().unwrap_or("").contains("PLS"), "{:?}", e.hint);
    let e = s.load_program("LD %I7.0", "bad.il").unwrap_err();
    assert!(e.message.contains("I7.0") && e.message.contains("K205-16DT"), "{}", e.message);
    assert!(s.plc().is_none(), "nothing was loaded");
}

/// `ATCH` takes only the event numbers the manual gives (docs/il.md "Interrupts"): 12 is
/// S7-200's HSC0 CV = PV, which the K2 manual does not number, so it is a load error that
/// lists the numbers there are.
#[test]
fn atch_refuses_event_numbers_the_manual_does_not_give() {
    let (mut s, _) = sim();
    let prog =
        |ev: u32| format!("PROGRAM MAIN\nLD %SM0.1\nATCH R, {ev}\nEND_PROGRAM\nINTERRUPT R\nLD %SM0.0\nEND_INTERRUPT");
    for ev in [8, 9, 12, 27, 29, 63, 192] {
        let e = s.load_program(&prog(ev), "x.il").unwrap_err();
        assert!(
            e.message.contains(&format!("no interrupt event {ev}")) && e.message.contains("28 PTO0 complete"),
            "{}",
            e.message
        );
    }
    for ev in [0, 7, 10, 11, 28, 64, 191] {
        s.load_program(&prog(ev), "x.il").unwrap_or_else(|e| panic!("{ev}: {e}"));
    }
}

#[test]
fn a_bad_indirect_address_stops_the_cpu() {
    let (mut s, _) = sim();
    s.load_program("LD %SM0.0\nMOVE 16#7F000000, %VD0\nMOVE 1, *%VD0", "ind.il").unwrap();
    let p = s.plc().unwrap();
    assert_eq!(p.mode, Mode::Stop);
    assert_eq!(p.faults[0].kind, FaultKind::BadAddress);
}

// ---- interrupts (K2 §2.2.7 edge inputs, §2.1.2 timed interrupts, §3.4.2.3 event 28) ----

#[test]
fn an_edge_on_i0_0_runs_its_routine_at_the_edge_before_the_next_scan() {
    let (mut s, clock) = sim();
    s.load_program(
        "PROGRAM MAIN\nLD %SM0.1\nATCH ON_EDGE, 0\nENI\nLD %SM0.0\nMOVE %VW10, %VW12\nEND_PROGRAM\n\
         INTERRUPT ON_EDGE\nLD %SM0.0\nINC %VW10\nMOVE %SMW22, %VW14\nEND_INTERRUPT",
        "edge.il",
    )
    .unwrap();
    clock.step(Duration::from_micros(2500));
    s.advance();
    // Between the scans at 2 ms and 3 ms: the edge at 2.5 ms.
    set(&mut s, "I0.0", Value::Bool(true));
    assert_eq!(s.mem.v[11], 1, "the routine ran at the edge's time, at once");
    assert_eq!(s.mem.v[13], 0, "the next scan's program has not run yet");
    assert_eq!(s.plc().unwrap().stats.interrupts, 1);
    clock.step(Duration::from_micros(500));
    assert_eq!(get(&mut s, "VW12"), Value::Int(1), "the 3 ms scan saw the routine's result");
    set(&mut s, "I0.0", Value::Bool(false));
    assert_eq!(s.plc().unwrap().stats.interrupts, 1, "falling edge (event 1) not attached");
    set(&mut s, "I0.1", Value::Bool(true));
    assert_eq!(s.plc().unwrap().stats.interrupts, 1, "I0.1 (event 2) not attached");
}

#[test]
fn a_timed_interrupt_fires_at_its_0_1_ms_interval() {
    // SMB34 = 5 → every 0.5 ms: 2000 times in a simulated second.
    let (mut s, clock) = sim();
    s.load_program(
        "PROGRAM MAIN\nLD %SM0.1\nMOVE B#5, %SMB34\nATCH TICK, 10\nENI\nEND_PROGRAM\n\
         INTERRUPT TICK\nLD %SM0.0\nINC %VW20\nEND_INTERRUPT",
        "tick.il",
    )
    .unwrap();
    clock.step(Duration::from_secs(1));
    assert_eq!(get(&mut s, "VW20"), Value::Int(2000));
    // Timed interrupt 1 at the 0.1 ms base itself: 10 000 a second.
    s.load_program(
        "PROGRAM MAIN\nLD %SM0.1\nMOVE B#1, %SMB35\nATCH FAST, 11\nENI\nEND_PROGRAM\n\
         INTERRUPT FAST\nLD %SM0.0\nINC %VW24\nEND_INTERRUPT",
        "fast.il",
    )
    .unwrap();
    clock.step(Duration::from_secs(1));
    assert_eq!(get(&mut s, "VW24"), Value::Int(10_000));
    s.load_program(
        "PROGRAM MAIN\nLD %SM0.1\nMOVE B#3, %SMB34\nATCH TICK, 10\nEND_PROGRAM\nINTERRUPT TICK\nLD %SM0.0\nINC %VW22",
        "off.il",
    )
    .unwrap();
    clock.step(Duration::from_millis(10));
    assert_eq!(get(&mut s, "VW22"), Value::Int(0), "attached but never enabled with ENI");
}

#[test]
fn pto_complete_event_28_runs_its_routine() {
    let (mut s, clock) = sim();
    s.load_program(
        "PROGRAM MAIN\nLD %SM0.1\nATCH PTO_DONE, 28\nENI\nMOVE B#16#85, %SMB67\nMOVE 500, %SMW68\nMOVE DI#100, %SMD72\nPLS 0\nEND_PROGRAM\n\
         INTERRUPT PTO_DONE\nLD %SM0.0\nS %Q0.2, 1\nMOVE %SMD212, %VD30\nEND_INTERRUPT",
        "pto.il",
    )
    .unwrap();
    clock.step(Duration::from_millis(49));
    assert!(!on(&mut s, "Q0.2"));
    clock.step(Duration::from_millis(2));
    assert!(on(&mut s, "Q0.2"), "100 × 500 µs = 50 ms");
    assert_eq!(get(&mut s, "VD30"), Value::Int(100), "the routine saw all pulses counted");
}

#[test]
fn the_instruction_table_in_docs_is_current() {
    let path = concat!(env!("CARGO_MANIFEST_DIR"), "/docs/il.md");
    let table = crate::engine::isa::markdown(super::family::SPECIALS, "K2");
    let doc = std::fs::read_to_string(path).unwrap_or_default();
    let (begin, end) = ("<!-- instruction table: generated -->\n", "<!-- end of table -->");
    let (a, b) = (doc.find(begin).map(|i| i + begin.len()), doc.find(end));
    if std::env::var_os("PLCSH_BLESS").is_some() {
        if let (Some(a), Some(b)) = (a, b) {
            std::fs::write(path, format!("{}{table}{}", &doc[..a], &doc[b..])).unwrap();
            return;
        }
    }
    let have = match (a, b) {
        (Some(a), Some(b)) => &doc[a..b],
        _ => "",
    };
    assert!(have == table, "docs/il.md's instruction table is stale: PLCSH_BLESS=1 cargo test the_instruction_table");
}

// ---- position control (K2 §3.4.3) --------------------------------------------------

const PHOME: &str =
    "(* Network 0 *)\nLD %SM0.0\nPHOME 0, %M0.0, %M0.1, %M0.2, %VW0, %VW2, %VW4, %VD6, %VW10, %M0.4, %M0.5, %MB1\n";

fn home_setup(s: &mut K2Sim) {
    // MODE 1 (HOME only), DIRC 1 (backward), MINF 200 Hz, MAXF 5 kHz, TIME 100 ms.
    for (op, v) in [("VW0", 1), ("VW2", 1), ("VW4", 200), ("VD6", 5000), ("VW10", 100)] {
        set(s, op, Value::Int(v));
    }
}

#[test]
fn the_manuals_phome_snippet_clears_the_current_value_on_done() {
    // K2 §3.4.3.1 method 1: after PHOME, DONE's rising edge sets SM201.6 for one scan.
    let (mut s, clock) = sim();
    s.load_program(&format!("{PHOME}(* Network 1 *)\nLD %M0.4\nR_TRIG\nST %SM201.6"), "home.il").unwrap();
    home_setup(&mut s);
    set(&mut s, "M0.0", Value::Bool(true));
    clock.step(Duration::from_millis(1000));
    let pos = get(&mut s, "SMD212/DINT").as_i64();
    // 0.1 s ramp (≈ 260 pulses) then 5 kHz backward: about −(260 + 4500).
    assert!((-4900..=-4600).contains(&pos), "moving backward toward home: {pos}");
    assert!(on(&mut s, "Q0.2"), "direction output Q0.2 = reverse");
    assert!(!on(&mut s, "M0.4"));
    set(&mut s, "M0.1", Value::Bool(true));
    clock.step(Duration::from_millis(2));
    assert!(on(&mut s, "M0.4"), "DONE");
    assert_eq!(get(&mut s, "SMD212/DINT"), Value::Int(0), "SM201.6 cleared the current value");
    clock.step(Duration::from_millis(2));
    assert!(!on(&mut s, "SM201.6"), "one scan only");
    assert!(on(&mut s, "SM66.7"), "PTO0 idle");
}

#[test]
fn the_manuals_phome_snippet_loads_a_new_current_value_on_done() {
    // K2 §3.4.3.1 method 2: MOVE DI#100, %SMD208 / ST %SM201.4 → SMD212 = 100.
    let (mut s, clock) = sim();
    s.load_program(
        &format!("{PHOME}(* Network 1 *)\nLD %M0.4\nR_TRIG\nMOVE DI # 100, %SMD208\nST %SM201.4"),
        "home2.il",
    )
    .unwrap();
    home_setup(&mut s);
    set(&mut s, "M0.0", Value::Bool(true));
    clock.step(Duration::from_millis(300));
    set(&mut s, "M0.1", Value::Bool(true));
    clock.step(Duration::from_millis(3));
    assert_eq!(get(&mut s, "SMD212/DINT"), Value::Int(100));
}

#[test]
fn pabs_ramps_and_latches_its_parameters() {
    // PABS 0 to 10 000 pulses: 125 Hz → 10 kHz over 100 ms; MAXF changed mid-move is ignored (§3.4.3.2).
    let (mut s, clock) = sim();
    s.load_program("LD %SM0.0\nPABS 0, %M0.0, %VW0, %VD2, %VW6, %VD8, %M0.1, %M0.2, %MB1", "abs.il").unwrap();
    for (op, v) in [("VW0", 125), ("VD2", 10_000), ("VW6", 100), ("VD8", 10_000)] {
        set(&mut s, op, Value::Int(v));
    }
    set(&mut s, "M0.0", Value::Bool(true));
    clock.step(Duration::from_millis(50));
    let early = get(&mut s, "SMD212/DINT").as_i64();
    set(&mut s, "VD2", Value::Int(1000));
    clock.step(Duration::from_millis(50));
    let ramp_end = get(&mut s, "SMD212/DINT").as_i64();
    clock.step(Duration::from_millis(100));
    let cruise = get(&mut s, "SMD212/DINT").as_i64() - ramp_end;
    assert!(early < ramp_end - early, "accelerating: {early} in the first 50 ms, {} in the next", ramp_end - early);
    assert!((990..=1010).contains(&cruise), "10 kHz cruise despite MAXF = 1000 written: {cruise} in 100 ms");
    clock.step(Duration::from_millis(900));
    assert!(on(&mut s, "M0.1"), "DONE");
    assert_eq!(get(&mut s, "SMD212/DINT"), Value::Int(10_000));
    assert!(!on(&mut s, "Q0.2"), "forward");
}

#[test]
fn position_instructions_check_frequencies_and_the_emergency_stop_bit() {
    let (mut s, clock) = sim();
    s.load_program("LD %SM0.0\nPREL 0, %M0.0, %VW0, %VD2, %VW6, %VD8, %M0.1, %M0.2, %MB1", "rel.il").unwrap();
    for (op, v) in [("VW0", 100), ("VD2", 1000), ("VW6", 0), ("VD8", -50)] {
        set(&mut s, op, Value::Int(v));
    }
    set(&mut s, "M0.0", Value::Bool(true));
    clock.step(Duration::from_millis(2));
    assert!(on(&mut s, "M0.2"), "ERR: MINF 100 Hz is below 125 Hz");
    assert_eq!(get(&mut s, "MB1"), Value::Int(2));
    set(&mut s, "VW0", Value::Int(125));
    set(&mut s, "SM201.7", Value::Bool(true));
    set(&mut s, "M0.0", Value::Bool(false));
    clock.step(Duration::from_millis(2));
    set(&mut s, "M0.0", Value::Bool(true));
    clock.step(Duration::from_millis(2));
    assert_eq!(get(&mut s, "MB1"), Value::Int(1), "SM201.7 blocks position instructions");
    set(&mut s, "SM201.7", Value::Bool(false));
    set(&mut s, "M0.0", Value::Bool(false));
    clock.step(Duration::from_millis(2));
    set(&mut s, "M0.0", Value::Bool(true));
    clock.step(Duration::from_millis(100));
    assert!(on(&mut s, "M0.1"), "DONE: 50 pulses back at 1 kHz");
    assert_eq!(get(&mut s, "SMD212/DINT"), Value::Int(-50));
    assert!(on(&mut s, "Q0.2"), "reverse");
}

/// Pulses `exec` (M0.0) off and on and lets the move finish.
fn restart(s: &mut K2Sim, clock: &Clock, ms: u64) {
    set(s, "M0.0", Value::Bool(false));
    clock.step(Duration::from_millis(2));
    set(s, "M0.0", Value::Bool(true));
    clock.step(Duration::from_millis(ms));
}

#[test]
fn backward_moves_count_down_whether_the_direction_pin_is_freed_or_not() {
    // K2 §3.4.3.1: SMD212 "increases counting forward and decreases counting backward";
    // SM201.3 = 1 frees the direction pin as a plain output, the axis still moves backward.
    // PABS is absolute (§3.4.1): PABS 0 after PABS −1000 returns to 0, and again stays there.
    for freed in [false, true] {
        let (mut s, clock) = sim();
        s.load_program(
            "LD %SM0.0\nPREL 0, %M0.0, %VW0, %VD2, %VW6, %VD8, %M0.1, %M0.2, %MB1\n\
             LD %SM0.0\nPABS 0, %M2.0, %VW0, %VD2, %VW6, %VD12, %M2.1, %M2.2, %MB3",
            "rev.il",
        )
        .unwrap();
        for (op, v) in [("VW0", 125), ("VD2", 10_000), ("VW6", 0), ("VD8", -1000)] {
            set(&mut s, op, Value::Int(v));
        }
        set(&mut s, "SM201.3", Value::Bool(freed));
        set(&mut s, "Q0.2", Value::Bool(false));
        restart(&mut s, &clock, 200);
        assert!(on(&mut s, "M0.1") && !on(&mut s, "M0.2"), "PREL −1000 DONE, no ERR (freed {freed})");
        assert_eq!(get(&mut s, "SMD212/DINT"), Value::Int(-1000), "PREL −1000 (freed {freed})");
        assert_eq!(on(&mut s, "Q0.2"), !freed, "the direction output is driven only while SM201.3 = 0");
        set(&mut s, "SM201.6", Value::Bool(true));
        clock.step(Duration::from_millis(2));
        set(&mut s, "SM201.6", Value::Bool(false));
        let mut seen = Vec::new();
        for target in [-1000, 0, 0, 500, -250] {
            set(&mut s, "VD12", Value::Int(target));
            set(&mut s, "M2.0", Value::Bool(false));
            clock.step(Duration::from_millis(2));
            set(&mut s, "M2.0", Value::Bool(true));
            clock.step(Duration::from_millis(300));
            assert!(
                on(&mut s, "M2.1") && !on(&mut s, "M2.2"),
                "PABS {target} DONE (freed {freed}): ERRID {:?} at {:?}",
                get(&mut s, "MB3"),
                get(&mut s, "SMD212/DINT")
            );
            seen.push(get(&mut s, "SMD212/DINT").as_i64());
        }
        assert_eq!(seen, [-1000, 0, 0, 500, -250], "PABS is absolute in both directions (freed {freed})");
    }
}

#[test]
fn jog_and_homing_backward_count_down_with_the_direction_pin_freed() {
    // K2 §3.4.3.1 (SMD212 decreases backward), §3.4.3.2 (PJOG DIRC), with SM201.3 = 1.
    let (mut s, clock) = sim();
    s.load_program(
        "LD %SM0.0\nPJOG 0, %M0.0, %VD0, %VW4, %M0.1, %M0.2, %MB1\n\
         LD %SM0.0\nPFLO_F 1, %M2.0, %VD10, %VW14, %VW16, %VD18, %M2.1, %M2.2, %MB3",
        "jogrev.il",
    )
    .unwrap();
    set(&mut s, "SM201.3", Value::Bool(true));
    set(&mut s, "SM231.3", Value::Bool(true));
    set(&mut s, "VD0", Value::Int(1000));
    set(&mut s, "VW4", Value::Int(1));
    set(&mut s, "M0.0", Value::Bool(true));
    clock.step(Duration::from_millis(1000));
    let a = get(&mut s, "SMD212/DINT").as_i64();
    assert!((-1010..=-990).contains(&a), "1 s backward at 1 kHz: {a}");
    assert!(!on(&mut s, "Q0.2"), "the freed pin is left alone");
    // PFLO_F with a negative COUNT moves backward on channel 1.
    for (op, v) in [("VD10", 1000), ("VW14", 1), ("VW16", 1), ("VD18", -300)] {
        set(&mut s, op, Value::Int(v));
    }
    set(&mut s, "M2.0", Value::Bool(true));
    clock.step(Duration::from_millis(400));
    assert!(on(&mut s, "M2.1"), "DONE");
    assert_eq!(get(&mut s, "SMD242/DINT"), Value::Int(-300));
}

#[test]
fn pjog_follows_maxf_and_pflo_f_counts() {
    let (mut s, clock) = sim();
    s.load_program(
        "LD %SM0.0\nPJOG 0, %M0.0, %VD0, %VW4, %M0.1, %M0.2, %MB1\nLD %SM0.0\nPFLO_F 1, %M2.0, %VD10, %VW14, %VW16, %VD18, %M2.1, %M2.2, %MB3",
        "jog.il",
    )
    .unwrap();
    set(&mut s, "VD0", Value::Int(1000));
    set(&mut s, "M0.0", Value::Bool(true));
    clock.step(Duration::from_millis(1000));
    let a = get(&mut s, "SMD212/DINT").as_i64();
    set(&mut s, "VD0", Value::Int(2000));
    clock.step(Duration::from_millis(1000));
    let b = get(&mut s, "SMD212/DINT").as_i64() - a;
    assert!((990..=1010).contains(&a) && (1990..=2010).contains(&b), "1 kHz then 2 kHz: {a}, {b}");
    set(&mut s, "M0.0", Value::Bool(false));
    clock.step(Duration::from_millis(5));
    assert!(on(&mut s, "M0.1") && on(&mut s, "SM66.7"), "stopped, DONE");
    // PFLO_F on channel 1: F = 1000 Hz × 3 / 2 = 1500 Hz for 300 pulses.
    for (op, v) in [("VD10", 1000), ("VW14", 3), ("VW16", 2), ("VD18", 300)] {
        set(&mut s, op, Value::Int(v));
    }
    set(&mut s, "M2.0", Value::Bool(true));
    clock.step(Duration::from_millis(150));
    assert!(!on(&mut s, "M2.1"));
    clock.step(Duration::from_millis(60));
    assert!(on(&mut s, "M2.1"), "300 pulses at 1500 Hz = 200 ms");
    assert_eq!(get(&mut s, "SMD242/DINT"), Value::Int(300));
    // Below 30 Hz: refused.
    set(&mut s, "VD10", Value::Int(10));
    set(&mut s, "M2.0", Value::Bool(false));
    clock.step(Duration::from_millis(2));
    set(&mut s, "M2.0", Value::Bool(true));
    clock.step(Duration::from_millis(2));
    assert_eq!(get(&mut s, "MB3"), Value::Int(2), "15 Hz is below PFLO_F's 30 Hz");
}

// ---- DEBUG mode (K80S: breakpoints, step execution) -----------------------------------

#[test]
fn a_breakpoint_halts_and_steps_show_the_current_result_and_operands() {
    let (mut s, clock) = sim();
    s.load_program("(* Network 1 *)\nLD %I0.0\nAND %M0.1\nST %Q0.0\n(* Network 2 *)\nLD %SM0.0\nINC %VW0", "dbg.il")
        .unwrap();
    set(&mut s, "M0.1", Value::Bool(true));
    assert!(s.set_breakpoint("dbg.il:7").unwrap().contains("INC %VW0"));
    clock.step(Duration::from_millis(5));
    s.advance();
    let p = s.plc().unwrap();
    assert_eq!(p.mode, Mode::Debug, "halted at the breakpoint");
    let vw0 = s.mem.v[1];
    clock.step(Duration::from_millis(50));
    s.advance();
    assert_eq!(s.mem.v[1], vw0, "no scans while halted");
    let st = s.debug_step(1, false).unwrap();
    assert_eq!((st[0].line, st[0].cr), (7, true));
    assert_eq!(st[0].operands, vec![format!("VW0={}", vw0 + 1)], "the operand after the step");
    // Step a whole network of the next scan: to the end of network 1 … then network 2.
    s.debug_step(1, false).unwrap(); // the implicit end: the scan completes
    let net = s.debug_step(0, true).unwrap();
    assert_eq!(net.iter().map(|x| x.line).collect::<Vec<_>>(), vec![2, 3, 4], "network 1");
    assert_eq!(net[1].operands, vec!["M0.1=1".to_string()]);
    assert!(!net[2].cr, "I0.0 is off");
    s.clear_breakpoints();
    s.set_mode(Mode::Run).unwrap();
    clock.step(Duration::from_millis(10));
    s.advance();
    assert_eq!(s.plc().unwrap().mode, Mode::Run);
    assert!(s.mem.v[1] > vw0 + 5, "running again");
}

#[test]
fn random_il_never_panics_the_loader() {
    // Hostile input: token soup from the dialect's own pieces, 3000 programs.
    let pieces = [
        "LD",
        "ST",
        "MOVE",
        "ADD",
        "JMP",
        "L:",
        "(*",
        "*)",
        "%",
        "VW",
        "VD",
        "V",
        "M0.",
        "SM",
        "T",
        "C",
        "#",
        "16#",
        "DI#",
        "*%VD",
        "&VB",
        ",",
        " ",
        "\n",
        "-",
        "9",
        "0",
        "4095",
        "65536",
        "(",
        ")",
        "PHOME",
        "ATCH",
        "PROGRAM",
        "INTERRUPT",
        "END_PROGRAM",
        "TON",
        "CTUD",
        ".",
        "/REAL",
        "T#",
        "ms",
        "ä",
        "\t",
        "R_TRIG",
        "LDW>",
        "BLKMOVE",
    ];
    let (mut s, _) = sim();
    let mut seed = 0x2545_F491_4F6C_DD1Du64;
    for _ in 0..3000 {
        let mut text = String::new();
        for _ in 0..40 {
            seed ^= seed << 13;
            seed ^= seed >> 7;
            seed ^= seed << 17;
            text.push_str(pieces[(seed % pieces.len() as u64) as usize]);
        }
        if s.compile(&text, "fuzz.il").is_ok() {
            // Whatever loads must also run without panicking.
            let _ = s.load_program(&text, "fuzz.il");
            let _ = s.scan_n(3);
        }
    }
}

#[test]
fn the_cost_table_is_configurable() {
    let (mut s, clock) = sim();
    s.load_program("LD %SM0.0\nINC %VW0", "c.il").unwrap();
    let t = s.set_costs("min_scan=5ms arith=1ms").unwrap();
    assert_eq!((t.min_scan_ns, t.class_ns[crate::engine::CostClass::Arith as usize]), (5_000_000, 1_000_000));
    let before = get(&mut s, "VW0").as_i64();
    clock.step(Duration::from_millis(50));
    assert_eq!(get(&mut s, "VW0").as_i64() - before, 10, "a 5 ms minimum scan: 10 scans in 50 ms");
    s.set_costs("min_scan=0ms").unwrap();
    clock.step(Duration::from_millis(10));
    s.advance();
    // 1 ms INC + 0.2 µs LD + 1 µs end + 0.3 ms overhead.
    assert_eq!(s.plc().unwrap().stats.last_ns, 1_000_000 + 200 + 1_000 + 300_000);
    assert!(s.set_costs("bogus=1ms").unwrap_err().hint.as_deref().unwrap().contains("watchdog"));
    assert!(s.set_costs("bit=fast").is_err());
}

#[test]
fn a_signal_on_i0_1_runs_its_edge_routine_at_every_edge() {
    // 100 Hz on I0.1 from t = 0: rising edges (event 2) at 10, 20 … 1000 ms, falling edges
    // (event 3) half a period later, at 15 … 995 ms.
    let (mut s, clock) = sim();
    s.load_program(
        "PROGRAM MAIN\nLD %SM0.1\nATCH UP, 2\nATCH DOWN, 3\nENI\nEND_PROGRAM\n\
         INTERRUPT UP\nLD %SM0.0\nINC %VW0\nEND_INTERRUPT\nINTERRUPT DOWN\nLD %SM0.0\nINC %VW2\nEND_INTERRUPT",
        "sig.il",
    )
    .unwrap();
    let pin = (0, 1);
    s.add_source(crate::k2::sim::inputs::Source::Freq {
        pin,
        wave: crate::k2::sim::inputs::Wave::new(100, Duration::ZERO),
    })
    .unwrap();
    clock.step(Duration::from_secs(1));
    assert_eq!((get(&mut s, "VW0"), get(&mut s, "VW2")), (Value::Int(100), Value::Int(99)));
}

#[test]
fn stop_values_of_the_outputs_are_a_setting() {
    // K2 §2.2.1: in STOP the outputs take the values of the hardware configuration.
    let (mut s, _) = sim();
    s.load_program("LD %SM0.0\nS %Q0.0, 3", "q.il").unwrap();
    assert_eq!(get(&mut s, "QB0"), Value::Int(7));
    s.set_stop_outputs("QB0=16#04").unwrap();
    s.set_mode(Mode::Stop).unwrap();
    assert_eq!(get(&mut s, "QB0"), Value::Int(4), "Q0.2 stays on in STOP, the others go off");
    assert!(s.set_stop_outputs("VB0=1").is_err());
    assert!(s.set_stop_outputs("QB0=300").is_err());
}

// ---- Frozen time, waiting events, the mode table ------------------------------------

const FROZEN: &str = "PROGRAM MAIN\nLD %SM0.1\nMOVE B#10, %SMB34\nATCH TICK, 10\nENI\n(* Network 2 *)\n\
LD %I0.0\nTON T37, 20\nST %Q0.0\n(* Network 3 *)\nLD %SM0.0\nINC %VW0\nEND_PROGRAM\n\
INTERRUPT TICK\nLD %SM0.0\nINC %VW20\nEND_INTERRUPT";

#[test]
fn a_breakpoint_halt_is_not_credited_to_timers_timed_interrupts_or_sm0_5() {
    // docs/il.md "Debugging": DEBUG freezes the program's time as PAUSE does (K80S DEBUG mode;
    // K2 §2.1.2 timers and timed interrupts count program time). A 2 s TON halted for 10 s.
    let (mut s, clock) = sim();
    s.load_program(FROZEN, "frozen.il").unwrap();
    set(&mut s, "I0.0", Value::Bool(true));
    clock.step(Duration::from_millis(500));
    s.advance();
    s.set_breakpoint("12").unwrap();
    clock.step(Duration::from_millis(2));
    s.advance();
    assert_eq!(s.plc().unwrap().mode, Mode::Debug);
    let (t37, ticks, sm05) = (get(&mut s, "T37").as_i64(), get(&mut s, "VW20").as_i64(), get(&mut s, "SM0.5"));
    assert!((4..=5).contains(&t37), "0.5 s of TON: {t37}");
    clock.step(Duration::from_millis(10_250));
    s.advance();
    assert_eq!(get(&mut s, "T37").as_i64(), t37, "frozen while halted");
    assert_eq!(get(&mut s, "VW20").as_i64(), ticks, "no timed interrupt while halted");
    assert_eq!(get(&mut s, "SM0.5"), sm05, "the 1 s clock is frozen too");
    s.clear_breakpoints();
    s.set_mode(Mode::Run).unwrap();
    assert_eq!(get(&mut s, "SM0.5"), sm05, "and continues from its phase");
    clock.step(Duration::from_millis(100));
    let t = get(&mut s, "T37").as_i64();
    assert!(t - t37 <= 2, "100 ms after RUN the timer moved by 1, not by the halt: {t37} → {t}");
    let n = get(&mut s, "VW20").as_i64() - ticks;
    assert!((95..=105).contains(&n), "1 ms timed interrupt: about 100 in 100 ms, no burst: {n}");
    clock.step(Duration::from_millis(1_300));
    assert!(!on(&mut s, "Q0.0"), "1.9 s of program time: not yet");
    clock.step(Duration::from_millis(200));
    assert!(on(&mut s, "Q0.0"), "2.1 s of program time: done");
}

#[test]
fn stepping_in_debug_credits_no_time_between_steps() {
    let (mut s, clock) = sim();
    s.load_program(FROZEN, "frozen.il").unwrap();
    set(&mut s, "I0.0", Value::Bool(true));
    clock.step(Duration::from_millis(300));
    s.advance();
    s.set_breakpoint("12").unwrap();
    clock.step(Duration::from_millis(2));
    s.advance();
    let t37 = get(&mut s, "T37").as_i64();
    for _ in 0..5 {
        clock.step(Duration::from_secs(5));
        s.debug_step(20, false).unwrap();
    }
    let t = get(&mut s, "T37").as_i64();
    assert!(t - t37 <= 1, "25 s of stepping is not timer time: {t37} → {t}");
}

const DISI: &str = "PROGRAM MAIN\nLD %SM0.1\nATCH ON_EDGE, 0\nLD %M0.0\nDISI\nLD %M0.1\nENI\nEND_PROGRAM\n\
INTERRUPT ON_EDGE\nLD %SM0.0\nINC %VW10\nLD %SM4.1\nS %M1.0, 1\nEND_INTERRUPT";

fn edge(s: &mut K2Sim) {
    set(s, "I0.0", Value::Bool(false));
    set(s, "I0.0", Value::Bool(true));
}

#[test]
fn an_edge_during_disi_waits_and_runs_once_after_eni() {
    // docs/il.md "Interrupts": events wait while interrupts are disabled (S7-200 System Manual,
    // interrupt queues: I/O queue of 16, overflow bit SM4.1).
    let (mut s, clock) = sim();
    s.load_program(DISI, "disi.il").unwrap();
    set(&mut s, "M0.1", Value::Bool(true));
    clock.step(Duration::from_millis(2));
    edge(&mut s);
    assert_eq!(get(&mut s, "VW10"), Value::Int(1), "enabled: runs at once");
    set(&mut s, "M0.1", Value::Bool(false));
    set(&mut s, "M0.0", Value::Bool(true));
    clock.step(Duration::from_millis(2));
    edge(&mut s);
    clock.step(Duration::from_millis(5));
    assert_eq!(get(&mut s, "VW10"), Value::Int(1), "disabled: waits");
    set(&mut s, "M0.0", Value::Bool(false));
    set(&mut s, "M0.1", Value::Bool(true));
    clock.step(Duration::from_millis(5));
    assert_eq!(get(&mut s, "VW10"), Value::Int(2), "ran once after ENI");
    clock.step(Duration::from_millis(5));
    assert_eq!(get(&mut s, "VW10"), Value::Int(2), "and only once");
    assert!(!on(&mut s, "M1.0"), "no overflow");
    // 20 edges while disabled: the queue keeps 16, the overflow bit says some were lost.
    set(&mut s, "M0.1", Value::Bool(false));
    set(&mut s, "M0.0", Value::Bool(true));
    clock.step(Duration::from_millis(2));
    for _ in 0..20 {
        edge(&mut s);
    }
    set(&mut s, "M0.0", Value::Bool(false));
    set(&mut s, "M0.1", Value::Bool(true));
    clock.step(Duration::from_millis(5));
    assert_eq!(get(&mut s, "VW10"), Value::Int(18), "16 queued edges ran");
    assert!(on(&mut s, "M1.0"), "SM4.1 was on inside the routines");
    assert!(!on(&mut s, "SM4.1"), "cleared once the queue emptied");
}

#[test]
fn an_edge_during_pause_waits_for_run() {
    let (mut s, clock) = sim();
    s.load_program(DISI, "disi.il").unwrap();
    set(&mut s, "M0.1", Value::Bool(true));
    clock.step(Duration::from_millis(2));
    s.set_mode(Mode::Pause).unwrap();
    edge(&mut s);
    clock.step(Duration::from_millis(5));
    assert_eq!(get(&mut s, "VW10"), Value::Int(0), "paused: waits");
    s.set_mode(Mode::Run).unwrap();
    clock.step(Duration::from_millis(2));
    assert_eq!(get(&mut s, "VW10"), Value::Int(1), "ran after RUN");
    s.set_mode(Mode::Stop).unwrap();
    edge(&mut s);
    s.set_mode(Mode::Run).unwrap();
    clock.step(Duration::from_millis(5));
    assert_eq!(get(&mut s, "VW10"), Value::Int(1), "STOP drops events (a fresh start)");
}

#[test]
fn the_switch_and_the_command_combine_as_the_manuals_table() {
    // K2 §2.2.1: switch RUN + command RUN = RUN; every other pair = STOP; the last command is
    // kept while the switch is at STOP.
    let (mut s, clock) = sim();
    s.load_program("LD %SM0.1\nINC %VW0\nLD %SM0.0\nINC %VW2", "sw.il").unwrap();
    let mode = |s: &K2Sim| s.plc().unwrap().mode;
    for (switch_run, command, want) in [
        (true, Mode::Run, Mode::Run),
        (true, Mode::Stop, Mode::Stop),
        (false, Mode::Run, Mode::Stop),
        (false, Mode::Stop, Mode::Stop),
    ] {
        s.set_switch(true).unwrap();
        let _ = s.set_mode(command);
        s.set_switch(switch_run).unwrap();
        let r = s.set_mode(command);
        assert_eq!(r.is_err(), !switch_run && command == Mode::Run, "refusal says the switch wins");
        assert_eq!(mode(&s), want, "switch {switch_run} command {command:?}");
    }
    // Switch STOP then RUN with the last command RUN: RUN again, from a first scan.
    s.set_switch(true).unwrap();
    s.set_mode(Mode::Run).unwrap();
    let first = get(&mut s, "VW0").as_i64();
    s.set_switch(false).unwrap();
    assert_eq!(mode(&s), Mode::Stop);
    s.set_switch(true).unwrap();
    assert_eq!(mode(&s), Mode::Run, "the kept RUN command runs");
    assert_eq!(get(&mut s, "VW0").as_i64(), first + 1, "STOP → RUN starts with a first scan");
    // A RUN command given while the switch is at STOP takes effect when it returns to RUN.
    s.set_mode(Mode::Stop).unwrap();
    s.set_switch(false).unwrap();
    assert!(s.set_mode(Mode::Run).is_err());
    s.set_switch(true).unwrap();
    assert_eq!(mode(&s), Mode::Run);
    // The last command STOP: the switch alone does not start it.
    s.set_mode(Mode::Stop).unwrap();
    s.set_switch(false).unwrap();
    s.set_switch(true).unwrap();
    assert_eq!(mode(&s), Mode::Stop);
    let n = get(&mut s, "VW2");
    clock.step(Duration::from_millis(10));
    assert_eq!(get(&mut s, "VW2"), n, "no scans");
}

#[test]
fn the_stop_instruction_stops_the_cpu_at_the_end_of_the_scan() {
    // K80S 5.4.5: the program's STOP changes the mode to STOP; the rest of the scan runs
    // (S7-200 System Manual, STOP instruction). Outputs take their STOP values (K2 §2.2.1).
    let (mut s, clock) = sim();
    s.load_program("LD %SM0.0\nS %Q0.0, 1\nLD %I0.0\nSTOP\nLD %SM0.0\nINC %VW0", "stop.il").unwrap();
    clock.step(Duration::from_millis(5));
    s.advance();
    assert_eq!(s.plc().unwrap().mode, Mode::Run);
    let n = get(&mut s, "VW0").as_i64();
    set(&mut s, "I0.0", Value::Bool(true));
    clock.step(Duration::from_millis(5));
    s.advance();
    assert_eq!(s.plc().unwrap().mode, Mode::Stop);
    assert!(s.plc().unwrap().stopped_by_program);
    assert_eq!(get(&mut s, "VW0").as_i64(), n + 1, "the scan that ran STOP finished");
    assert!(!on(&mut s, "Q0.0"), "outputs at their STOP values");
    set(&mut s, "I0.0", Value::Bool(false));
    s.set_mode(Mode::Run).unwrap();
    clock.step(Duration::from_millis(5));
    s.advance();
    assert_eq!(s.plc().unwrap().mode, Mode::Run, "sim cpu run restarts it");
}

#[test]
fn no_unknown_instruction_is_ever_pointed_at_a_dangerous_one() {
    // A typo must not be answered "did you mean PSTOP?" (an axis emergency stop), STOP, a
    // move, PLS … (engine::isa::NEVER_SUGGESTED). Every name one edit away from each of them
    // (deletions, substitutions, insertions, transpositions), and the S7-200 names the
    // dialect lacks, either load or get a hint naming none of them.
    let (s, _) = sim();
    let letters: Vec<char> = ('A'..='Z').chain('0'..='9').chain(['_']).collect();
    let mut names: Vec<String> =
        ["STOPP", "STP", "PSTP", "ESTOP", "END", "MEND", "HALT", "SCRE", "LSCR", "SCRT", "PID", "XMT", "RCV", "NETR"]
            .iter()
            .map(|x| x.to_string())
            .collect();
    for d in crate::engine::isa::NEVER_SUGGESTED {
        let c: Vec<char> = d.chars().collect();
        for i in 0..=c.len() {
            if i < c.len() {
                let mut v = c.clone();
                v.remove(i);
                names.push(v.iter().collect());
                for l in &letters {
                    let mut v = c.clone();
                    v[i] = *l;
                    names.push(v.iter().collect());
                }
            }
            if i + 1 < c.len() {
                let mut v = c.clone();
                v.swap(i, i + 1);
                names.push(v.iter().collect());
            }
            for l in &letters {
                let mut v = c.clone();
                v.insert(i, *l);
                names.push(v.iter().collect());
            }
        }
    }
    let mut checked = 0;
    for n in &names {
        let Err(e) = s.compile(&format!("LD %SM0.0\n{n} 0"), "t.il") else { continue };
        if !e.message.contains("unknown instruction") {
            continue;
        }
        checked += 1;
        let hint = e.hint.clone().unwrap_or_default();
        for d in crate::engine::isa::NEVER_SUGGESTED {
            let named = hint.split(|c: char| !(c.is_ascii_alphanumeric() || c == '_')).any(|w| w == *d);
            assert!(!named, "`{n}` is answered with {d}: {hint}");
        }
    }
    assert!(checked > 1000, "the variants were unknown instructions: {checked}");
}

#[test]
fn breakpoint_specs_are_accepted_as_lua_passes_them() {
    // plc:breakpoint("network 2") reaches `sim break "network 2"` (docs/il.md "Debugging").
    let (mut s, _) = sim();
    s.load_program("(* Network 1 *)\nLD %SM0.0\nINC %VW0\n(* Network 2 *)\nLD %SM0.0\nINC %VW2", "n.il").unwrap();
    for spec in ["network 2", "\"network 2\"", "'network 2'", "Network 2", "n2", "5", "\"n.il:5\""] {
        let at = s.set_breakpoint(spec).unwrap_or_else(|e| panic!("{spec}: {e}"));
        assert!(at.contains("n.il:5"), "{spec}: {at}");
    }
}

#[test]
fn division_by_zero_is_a_recorded_normal_error_and_the_cpu_continues() {
    // K2 §2.2.1: a normal error lights Err and saves the code; K80S 5.3.4: an operation
    // error is recorded and the CPU keeps running. SM1.3 is S7-200's divide-by-zero bit.
    let (mut s, clock) = sim();
    s.load_program("LD %M0.0\nDIV %VW0, %VW2\nST %Q0.0\nLD %SM1.3\nS %M1.0, 1\nLD %SM0.0\nINC %VW4", "div.il").unwrap();
    set(&mut s, "VW2", Value::Int(10));
    clock.step(Duration::from_millis(3));
    s.advance();
    assert!(s.plc().unwrap().errors.is_empty(), "no division yet");
    set(&mut s, "M0.0", Value::Bool(true));
    clock.step(Duration::from_millis(3));
    s.advance();
    // VW0 is 0: 10 / 0.
    let p = s.plc().unwrap();
    assert_eq!(p.mode, Mode::Run, "the CPU continues");
    let e = p.errors.last().expect("a record");
    assert_eq!((e.kind, e.kind.code(), e.line), (FaultKind::DivZero, 5, 2), "{e}");
    assert!(!e.kind.serious());
    assert!(p.error_count >= 1 && p.faults.is_empty());
    assert!(on(&mut s, "M1.0"), "SM1.3, the divide-by-zero bit, was on after DIV");
    assert!(!on(&mut s, "Q0.0"), "ENO = 0");
    assert_eq!(get(&mut s, "VW2"), Value::Int(10), "the output is unchanged");
    let n = get(&mut s, "VW4").as_i64();
    clock.step(Duration::from_millis(10));
    assert!(get(&mut s, "VW4").as_i64() > n, "still scanning");
    let p = s.plc().unwrap();
    assert!(p.errors.len() <= crate::engine::exec::MAX_NORMAL_ERRORS, "the record is bounded");
    assert!(p.error_count > 10, "every occurrence counted: {}", p.error_count);
    // REAL too.
    s.load_program("LD %SM0.0\nMOVR 1.5, %VD8\nMOVR 0.0, %VD12\n/R %VD12, %VD8", "divr.il").unwrap();
    assert_eq!(s.plc().unwrap().errors.last().map(|e| e.kind), Some(FaultKind::DivZero));
}

#[test]
fn analog_outputs_take_their_stop_values_too() {
    // K2 §2.2.1: in STOP all outputs, "including DO and AO", take the configured values.
    // The K205EA-18DT has one analog output (AQW0).
    let mut s = sim::open("K205EA-18DT", Clock::stepped()).unwrap();
    s.load_program("LD %SM0.0\nMOVE 5000, %AQW0\nMOVE 16#FF, %QB0", "ao.il").unwrap();
    assert_eq!(get(&mut s, "AQW0"), Value::Int(5000));
    s.set_stop_outputs("QB0=16#04 AQW0=16000").unwrap();
    s.set_mode(Mode::Stop).unwrap();
    assert_eq!(get(&mut s, "AQW0"), Value::Int(16000), "the configured AO value");
    assert_eq!(get(&mut s, "QB0"), Value::Int(4));
    let e = s.set_stop_outputs("VW0=1").unwrap_err();
    assert!(e.message.contains("AQW0"), "{}", e.message);
    s.set_stop_outputs("QB0=0").unwrap();
    assert_eq!(get(&mut s, "AQW0"), Value::Int(0), "not named: 0");
}

// ---- Added instructions: golden values at the edges (docs/il.md names each source) -------

/// Runs `body` once (first scan) and returns the simulator.
fn once(body: &str) -> K2Sim {
    let (mut s, _) = sim();
    s.load_program(&format!("LD %SM0.1\n{body}"), "golden.il").unwrap();
    s
}

fn real(s: &mut K2Sim, op: &str) -> f32 {
    match get(s, &format!("{op}/REAL")) {
        Value::Real(r) => r as f32,
        v => panic!("{op}: {v:?}"),
    }
}

#[test]
fn sqrt_golden_values() {
    // S7-200 System Manual, Square Root (SQRT): REAL in, REAL out; SM1.1 on an illegal value.
    for (x, want, eno) in [
        (16.0f32, Some(4.0f32), true),
        (2.0, Some(std::f32::consts::SQRT_2), true),
        (0.0, Some(0.0), true),
        (-4.0, None, false),
        (f32::NAN, None, false),
        (f32::INFINITY, Some(f32::INFINITY), false),
    ] {
        let (mut s, _) = sim();
        set(&mut s, "VD0/REAL", Value::Real(x as f64));
        set(&mut s, "VD4/REAL", Value::Real(-1.0));
        s.load_program("LD %SM0.0\nSQRT %VD0, %VD4\nST %M0.0\nLD %SM1.1\nST %M0.1", "sqrt.il").unwrap();
        let r = real(&mut s, "VD4");
        match want {
            Some(w) => assert_eq!(r, w, "√{x}"),
            None => assert_eq!(r, -1.0, "√{x}: OUT unchanged"),
        }
        assert_eq!(on(&mut s, "M0.0"), eno, "ENO for √{x}");
        assert_eq!(on(&mut s, "M0.1"), !eno, "SM1.1 for √{x}");
    }
}

#[test]
fn abs_golden_values() {
    // IEC 61131-3 ABS; the S7-200 status bits (SM1.1 overflow) as the other arithmetic.
    for (out, x, want, eno) in [
        ("VW4", -5i64, 5, true),
        ("VW4", 32767, 32767, true),
        ("VW4", -32768, -32768, false),
        ("VD8", -2_000_000, 2_000_000, true),
        ("VD8", i32::MIN as i64, i32::MIN as i64, false),
    ] {
        let (src, lit) = if out == "VW4" { ("VW0", format!("INT#{x}")) } else { ("VD12", format!("DI#{x}")) };
        let mut s = once(&format!("MOVE {lit}, %{src}\nABS %{src}, %{out}\nST %M0.0"));
        let view = if out == "VW4" { "VW4/INT" } else { "VD8/DINT" };
        assert_eq!(get(&mut s, view).as_i64(), want, "|{x}|");
        assert_eq!(on(&mut s, "M0.0"), eno, "ENO for |{x}|");
    }
    for (x, want, eno) in [(-1.5f32, 1.5f32, true), (f32::NEG_INFINITY, f32::INFINITY, false)] {
        let (mut s, _) = sim();
        set(&mut s, "VD0/REAL", Value::Real(x as f64));
        s.load_program("LD %SM0.0\nABS %VD0/REAL, %VD4/REAL\nST %M0.0", "absr.il").unwrap();
        assert_eq!(real(&mut s, "VD4"), want);
        assert_eq!(on(&mut s, "M0.0"), eno);
    }
    let (mut s, _) = sim();
    set(&mut s, "VD0/REAL", Value::Real(f64::NAN));
    s.load_program("LD %SM0.0\nABS %VD0/REAL, %VD4/REAL\nST %M0.0", "absn.il").unwrap();
    assert!(real(&mut s, "VD4").is_nan() && !on(&mut s, "M0.0"), "|NaN| is NaN with ENO = 0");
    let (s, _) = sim();
    assert!(s.compile("LD %SM0.0\nABS %VB0, %VB1", "b.il").is_err(), "not on bytes");
}

#[test]
fn swap_golden_values() {
    // S7-200 System Manual, Swap Bytes (SWAP): the high and low byte of a word.
    let mut s = once("MOVE W#16#1234, %VW0\nSWAP %VW0\nMOVE INT#-2, %VW2\nSWAP %VW2\nMOVE 16#0080, %VW4\nSWAP %VW4");
    assert_eq!(get(&mut s, "VW0/WORD").as_i64(), 0x3412);
    assert_eq!(get(&mut s, "VW2/WORD").as_i64(), 0xFEFF, "−2 = FFFE → FEFF");
    assert_eq!(get(&mut s, "VW4/INT").as_i64(), -32768, "0080 → 8000 = −32768");
    let (s, _) = sim();
    assert!(s.compile("LD %SM0.0\nSWAP %VD0", "d.il").is_err(), "a word only");
}

#[test]
fn for_next_golden_values() {
    // S7-200 System Manual, For-Next Loop: INDX from INIT to FINAL, the body once per value;
    // INIT > FINAL runs it not at all; loops nest (up to 8).
    let mut s = once("FOR %VW0, 1, 10\nLD %SM0.0\nINC %VW2\nNEXT");
    assert_eq!(get(&mut s, "VW2").as_i64(), 10, "ten passes");
    assert_eq!(get(&mut s, "VW0").as_i64(), 11, "INDX ends at FINAL + 1");
    let mut s = once("FOR %VW0, 5, 4\nLD %SM0.0\nINC %VW2\nNEXT");
    assert_eq!(get(&mut s, "VW2").as_i64(), 0, "INIT > FINAL: none");
    let mut s = once("FOR %VW0, -3, -1\nLD %SM0.0\nINC %VW2\nNEXT");
    assert_eq!(get(&mut s, "VW2").as_i64(), 3, "negative bounds");
    let mut s = once("FOR %VW0, 32765, 32767\nLD %SM0.0\nINC %VW2\nNEXT");
    assert_eq!(get(&mut s, "VW2").as_i64(), 3, "FINAL = 32767 ends (no wrap to −32768)");
    assert_eq!(get(&mut s, "VW0").as_i64(), 32767);
    let mut s = once("FOR %VW0, 1, 3\nFOR %VW4, 1, 4\nLD %SM0.0\nINC %VW2\nNEXT\nNEXT");
    assert_eq!(get(&mut s, "VW2").as_i64(), 12, "3 × 4 nested");
    let mut s = once("FOR %VD0, DI#40000, DI#50000\nLD %SM0.0\nINC %VD4\nNEXT");
    assert_eq!(get(&mut s, "VD4").as_i64(), 10_001, "DINT index past 32767");
    // Not enabled: skipped.
    let (mut s, _) = sim();
    s.load_program("LD %M0.0\nFOR %VW0, 1, 10\nLD %SM0.0\nINC %VW2\nNEXT", "off.il").unwrap();
    assert_eq!(get(&mut s, "VW2").as_i64(), 0);
    // Load errors: unpaired, too deep.
    let (s, _) = sim();
    assert!(s.compile("LD %SM0.0\nNEXT", "n.il").unwrap_err().message.contains("NEXT without a FOR"));
    assert!(s.compile("LD %SM0.0\nFOR %VW0, 1, 2", "f.il").unwrap_err().message.contains("FOR without a NEXT"));
    let deep = "LD %SM0.0\n".to_string() + &"FOR %VW0, 1, 1\n".repeat(9) + &"NEXT\n".repeat(9);
    assert!(s.compile(&deep, "d.il").unwrap_err().message.contains("deeper than 8"));
    // An endless loop (FINAL re-read, the body keeps lowering INDX) meets the watchdog.
    let (mut s, clock) = sim();
    s.load_program("LD %SM0.0\nFOR %VW0, 1, 2\nLD %SM0.0\nMOVE 0, %VW0\nNEXT", "w.il").unwrap();
    clock.step(Duration::from_millis(1));
    s.advance();
    assert_eq!(s.plc().unwrap().faults.first().map(|f| f.kind), Some(FaultKind::Watchdog));
}

#[test]
fn a_duration_between_timer_units_rounds_up_with_a_warning() {
    // docs/il.md "Timers": a delay is never shorter than asked. T37 is a 100 ms timer.
    let (mut s, clock) = sim();
    let msg =
        s.load_program("LD %I0.0\nTON T37, T#250ms\nST %Q0.0\nLD %I0.0\nTON T38, T#300ms\nST %Q0.1", "r.il").unwrap();
    assert!(msg.contains("warning: r.il:2:10: T#250ms") && msg.contains("300 ms (3 units)"), "{msg}");
    assert!(!msg.contains("r.il:5"), "T#300ms is exact: no warning: {msg}");
    set(&mut s, "I0.0", Value::Bool(true));
    clock.step(Duration::from_millis(260));
    assert!(!on(&mut s, "Q0.0"), "not after 250 ms");
    clock.step(Duration::from_millis(60));
    assert!(on(&mut s, "Q0.0") && on(&mut s, "Q0.1"), "at 300 ms");
    // The 100 ms class holds 32767 units: 3276.7 s; longer is refused naming the limit.
    let e = s.compile("LD %I0.0\nTON T37, T#3277s", "l.il").unwrap_err();
    assert!(e.message.contains("3276.700 s"), "{}", e.message);
    assert!(s.compile("LD %I0.0\nTON T37, T#3276700ms", "l.il").unwrap().warnings.is_empty());
}

#[test]
fn homing_backward_counts_down_with_the_direction_pin_freed() {
    // K2 §3.4.3.1: SMD212 decreases moving backward; SM201.3 = 1 only frees Q0.2.
    let (mut s, clock) = sim();
    s.load_program(PHOME, "home.il").unwrap();
    home_setup(&mut s);
    set(&mut s, "SM201.3", Value::Bool(true));
    set(&mut s, "M0.0", Value::Bool(true));
    clock.step(Duration::from_millis(1000));
    let pos = get(&mut s, "SMD212/DINT").as_i64();
    assert!((-4900..=-4600).contains(&pos), "moving backward toward home: {pos}");
    assert!(!on(&mut s, "Q0.2"), "the freed pin is not driven");
    set(&mut s, "M0.1", Value::Bool(true));
    clock.step(Duration::from_millis(2));
    assert!(on(&mut s, "M0.4") && !on(&mut s, "M0.5"), "DONE, no ERR");
}

#[test]
fn timed_interrupts_during_disi_queue_eight_and_flag_the_rest() {
    // S7-200 System Manual Tables 9-22/9-23: the timed queue holds 8; SM4.2 marks a loss.
    let (mut s, clock) = sim();
    s.load_program(
        "PROGRAM MAIN\nLD %SM0.1\nMOVE B#10, %SMB34\nATCH TICK, 10\nLD %M0.1\nENI\nEND_PROGRAM\n\
         INTERRUPT TICK\nLD %SM0.0\nINC %VW20\nLD %SM4.2\nS %M1.0, 1\nEND_INTERRUPT",
        "tq.il",
    )
    .unwrap();
    clock.step(Duration::from_millis(20));
    assert_eq!(get(&mut s, "VW20"), Value::Int(0), "not enabled yet: the ticks wait");
    set(&mut s, "M0.1", Value::Bool(true));
    clock.step(Duration::from_millis(2));
    let n = get(&mut s, "VW20").as_i64();
    assert!((8..=10).contains(&n), "8 waited, then the ticks since ENI: {n}");
    assert!(on(&mut s, "M1.0"), "SM4.2: some were lost");
}

// ---- Snapshots keep the CPU's error list, the STOP flag, waiting events, a DEBUG halt ----

/// The simulator's state through the snapshot file's JSON, restored onto a fresh simulator
/// whose clock is set to the saved time (as `sim snapshot restore` does).
fn through_snapshot(s: &K2Sim, clock: &Clock) -> (K2Sim, Clock) {
    let text = serde_json::to_string(&s.snapshot_state()).unwrap();
    let st: crate::k2::sim::snapshot::K2State = serde_json::from_str(&text).unwrap();
    let (mut b, bclock) = sim();
    bclock.set(clock.now());
    b.restore_snapshot(&st).unwrap();
    (b, bclock)
}

#[test]
fn a_snapshot_keeps_the_normal_errors_and_the_program_stop() {
    // K2 §2.2.1: a normal error lights Err and its code is saved; it must not vanish across
    // `sim snapshot save/restore`. Nor may "stopped by the program's STOP" (K80S 5.4.5).
    let (mut s, clock) = sim();
    s.load_program("LD %SM0.0\nDIV %VW0, %VW2\nLD %I0.0\nSTOP\nLD %SM0.0\nINC %VW4", "ds.il").unwrap();
    set(&mut s, "VW2", Value::Int(7));
    clock.step(Duration::from_millis(5));
    set(&mut s, "I0.0", Value::Bool(true));
    clock.step(Duration::from_millis(3));
    s.advance();
    let (errors, count) = {
        let p = s.plc().unwrap();
        assert!(p.stopped_by_program && p.mode == Mode::Stop);
        assert!(!p.errors.is_empty());
        (p.errors.clone(), p.error_count)
    };
    let (b, _) = through_snapshot(&s, &clock);
    let p = b.plc().unwrap();
    assert_eq!(p.errors, errors, "the normal-error records (Err LED) came back");
    assert_eq!(p.error_count, count);
    assert!(p.stopped_by_program, "the program's STOP came back");
    assert_eq!(p.mode, Mode::Stop);
}

#[test]
fn a_snapshot_keeps_a_serious_fault() {
    // A bad indirect address stops the CPU with a serious error (K2 §2.2.1): restored, the CPU
    // still says why it stopped.
    let (mut s, clock) = sim();
    s.load_program("LD %SM0.0\nMOVD 16#7FFFFF00, %VD0\nMOVE *%VD0, %VW10", "bad.il").unwrap();
    clock.step(Duration::from_millis(2));
    s.advance();
    let faults = s.plc().unwrap().faults.clone();
    assert!(!faults.is_empty(), "the bad pointer stopped the CPU");
    let (b, _) = through_snapshot(&s, &clock);
    assert_eq!(b.plc().unwrap().faults, faults);
    assert_eq!(b.plc().unwrap().mode, Mode::Stop);
}

#[test]
fn an_edge_waiting_during_disi_survives_a_snapshot_and_runs_once_after_eni() {
    let (mut s, clock) = sim();
    s.load_program(DISI, "disi.il").unwrap();
    set(&mut s, "M0.0", Value::Bool(true));
    clock.step(Duration::from_millis(2));
    edge(&mut s);
    clock.step(Duration::from_millis(2));
    assert_eq!(get(&mut s, "VW10"), Value::Int(0), "disabled: waits");
    let (mut b, bclock) = through_snapshot(&s, &clock);
    assert_eq!(b.plc().unwrap().pending.len(), 1, "the waiting event came back");
    for (x, c) in [(&mut s, &clock), (&mut b, &bclock)] {
        set(x, "M0.0", Value::Bool(false));
        set(x, "M0.1", Value::Bool(true));
        c.step(Duration::from_millis(5));
        assert_eq!(get(x, "VW10"), Value::Int(1), "ran once after ENI");
    }
}

#[test]
fn a_debug_halt_survives_a_snapshot_with_its_frozen_time_and_breakpoints() {
    // docs/il.md "Debugging": a halt freezes program time; restored, it is still halted at the
    // same instruction, still frozen, and `sim cpu run` continues the halted scan.
    let (mut s, clock) = sim();
    s.load_program(FROZEN, "frozen.il").unwrap();
    set(&mut s, "I0.0", Value::Bool(true));
    clock.step(Duration::from_millis(500));
    s.advance();
    s.set_breakpoint("12").unwrap();
    clock.step(Duration::from_millis(2));
    s.advance();
    assert_eq!(s.plc().unwrap().mode, Mode::Debug);
    let halted = s.plc().unwrap().halted;
    assert!(halted.is_some());
    let (mut b, bclock) = through_snapshot(&s, &clock);
    assert_eq!(b.plc().unwrap().mode, Mode::Debug);
    assert_eq!(b.plc().unwrap().halted, halted, "halted at the same instruction");
    assert_eq!(b.breakpoints(), s.breakpoints(), "the breakpoints came back");
    let mut seen = Vec::new();
    for (x, c) in [(&mut s, &clock), (&mut b, &bclock)] {
        let t37 = get(x, "T37").as_i64();
        c.step(Duration::from_secs(10));
        x.advance();
        assert_eq!(get(x, "T37").as_i64(), t37, "still frozen");
        x.clear_breakpoints();
        x.set_mode(Mode::Run).unwrap();
        c.step(Duration::from_millis(1400));
        seen.push((get(x, "T37").as_i64(), get(x, "VW0").as_i64(), get(x, "VW20").as_i64(), on(x, "Q0.0")));
    }
    assert_eq!(seen[0], seen[1], "the restored CPU continues exactly as the saved one");
    assert!(!seen[0].3, "1.9 s of program time: the 2 s TON is not done");
}

// ---- Every position instruction in both directions, direction pin driven or freed -------

/// One move of `instr` on channel 0: exec on, run `ms`, (PHOME: the home signal, PJOG:
/// exec off), let it stop. Returns (SMD212, Q0.2, DONE, ERR, ERRID, event-28 routines run).
fn one_move(instr: &str, backward: bool, freed: bool) -> (i64, bool, bool, bool, i64, i64) {
    let (mut s, clock) = sim();
    let text = format!(
        "PROGRAM MAIN\nLD %SM0.1\nATCH PTO0_DONE, 28\nENI\nLD %SM0.0\n{instr}\nEND_PROGRAM\n\
         INTERRUPT PTO0_DONE\nLD %SM0.0\nINC %VW200\nEND_INTERRUPT"
    );
    s.load_program(&text, "dir.il").unwrap();
    let sign = if backward { -1 } else { 1 };
    for (op, v) in [
        ("VW100", 125),             // MINF
        ("VD102", 1000),            // MAXF / F
        ("VW106", 0),               // TIME (PREL, PABS)
        ("VD130", 200 * sign),      // POS / COUNT
        ("VW110", 1),               // PHOME MODE 1
        ("VW112", backward as i64), // PHOME DIRC
        ("VW114", 200),             // PHOME MINF
        ("VW120", 100),             // PHOME TIME
        ("VW122", 1),               // PFLO_F NUM, DENOM
        ("VW124", backward as i64), // PJOG DIRC
    ] {
        set(&mut s, op, Value::Int(v));
    }
    set(&mut s, "SM201.3", Value::Bool(freed));
    // A freed pin is a plain output: give it the level a driven pin would NOT have.
    set(&mut s, "Q0.2", Value::Bool(freed && !backward));
    clock.step(Duration::from_millis(2));
    set(&mut s, "M0.0", Value::Bool(true));
    clock.step(Duration::from_millis(150));
    let mid_pin = on(&mut s, "Q0.2");
    if instr.starts_with("PHOME") {
        set(&mut s, "M0.3", Value::Bool(true));
    } else if instr.starts_with("PJOG") {
        set(&mut s, "M0.0", Value::Bool(false));
    }
    clock.step(Duration::from_millis(400));
    assert_eq!(mid_pin, on(&mut s, "Q0.2"), "{instr}: the pin keeps its level after the move");
    (
        get(&mut s, "SMD212/DINT").as_i64(),
        mid_pin,
        on(&mut s, "M0.1"),
        on(&mut s, "M0.2"),
        get(&mut s, "MB1").as_i64(),
        get(&mut s, "VW200").as_i64(),
    )
}

#[test]
fn every_position_instruction_moves_both_ways_with_the_direction_pin_driven_or_freed() {
    // K2 §3.4: the direction output (Q0.2 for channel 0) is "forward = 0, reverse = 1";
    // SM201.3 = 1 disables it "and it is used as an ordinary output" (§3.4 SM table);
    // §3.4.3.1: SMD212 increases counting forward and decreases counting backward.
    let instrs = [
        "PREL 0, %M0.0, %VW100, %VD102, %VW106, %VD130, %M0.1, %M0.2, %MB1",
        "PABS 0, %M0.0, %VW100, %VD102, %VW106, %VD130, %M0.1, %M0.2, %MB1",
        "PJOG 0, %M0.0, %VD102, %VW124, %M0.1, %M0.2, %MB1",
        "PHOME 0, %M0.0, %M0.3, %M0.4, %VW110, %VW112, %VW114, %VD102, %VW120, %M0.1, %M0.2, %MB1",
        "PFLO_F 0, %M0.0, %VD102, %VW122, %VW122, %VD130, %M0.1, %M0.2, %MB1",
    ];
    for instr in instrs {
        let name = instr.split(' ').next().unwrap();
        let mut events = Vec::new();
        for freed in [false, true] {
            for backward in [false, true] {
                let (pos, pin, done, err, errid, ev) = one_move(instr, backward, freed);
                let what = format!("{name} backward={backward} SM201.3={freed}");
                assert!(done && !err && errid == 0, "{what}: DONE {done} ERR {err} ERRID {errid}");
                assert!(pos != 0 && (pos < 0) == backward, "{what}: SMD212 = {pos}");
                if !instr.starts_with("PHOME") && !instr.starts_with("PJOG") {
                    assert_eq!(pos.abs(), 200, "{what}: the whole move");
                } else if instr.starts_with("PHOME") {
                    // Method-free homing: the position counts the pulses run toward home.
                    assert!(pos.abs() > 100, "{what}: {pos}");
                }
                let want_pin = if freed { !backward } else { backward };
                assert_eq!(pin, want_pin, "{what}: direction output (freed: left as it was)");
                events.push(ev);
            }
        }
        assert!(events.iter().all(|e| *e == events[0]), "{name}: event 28 the same either way: {events:?}");
    }
}

// ---- Every timer kind halted at a breakpoint mid-timing ----------------------------------

const TIMERS: &str = "(* Network 1 *)\nLD %I0.0\nTON T37, 20\nST %M10.0\nLD %I0.1\nTOF T38, 20\nST %M10.1\n\
LD %I0.0\nTMR T39, 20\nST %M10.2\nLD %I0.0\nTMON T40, 20\nST %M10.3\nLD %I0.0\nTRTG T41, 20\nST %M10.4\n\
LD %I0.0\nTP T42, 20\nST %M10.5\n(* Network 2 *)\nLD %SM0.0\nINC %VW0";

/// The six timer outputs M10.0–M10.5.
fn timer_bits(s: &mut K2Sim) -> Vec<bool> {
    (0..6).map(|k| on(s, &format!("M10.{k}"))).collect()
}

#[test]
fn every_timer_kind_halted_ten_seconds_mid_timing_is_credited_no_time() {
    // docs/il.md "Debugging": a breakpoint halt freezes the program's time for TON, TOF, TMR,
    // TMON, TRTG and TP alike (K80S DEBUG; K2 §2.1.2: 100 ms timers T20–T255). Each is 2 s.
    // At program time 0 I0.0 rises (TON, TMR, TMON, TRTG, TP start) and I0.1 falls (TOF starts).
    let (mut s, clock) = sim();
    s.load_program(TIMERS, "timers.il").unwrap();
    set(&mut s, "I0.1", Value::Bool(true));
    clock.step(Duration::from_millis(5));
    assert_eq!(timer_bits(&mut s), [false, true, false, false, false, false], "TOF on while its input is");
    set(&mut s, "I0.0", Value::Bool(true));
    set(&mut s, "I0.1", Value::Bool(false));
    clock.step(Duration::from_millis(700));
    s.advance();
    s.set_breakpoint("network 2").unwrap();
    clock.step(Duration::from_millis(2));
    s.advance();
    assert_eq!(s.plc().unwrap().mode, Mode::Debug);
    let timing = [false, true, false, true, true, true];
    assert_eq!(timer_bits(&mut s), timing, "0.7 s in: all timing");
    let values: Vec<i64> = (37..=42).map(|t| get(&mut s, &format!("T{t}")).as_i64()).collect();
    assert!(values.iter().all(|v| (6..=7).contains(v)), "0.7 s = 7 ticks of 100 ms: {values:?}");
    clock.step(Duration::from_secs(10));
    s.advance();
    let frozen: Vec<i64> = (37..=42).map(|t| get(&mut s, &format!("T{t}")).as_i64()).collect();
    assert_eq!(frozen, values, "no timer moved during the 10 s halt");
    assert_eq!(timer_bits(&mut s), timing);
    s.clear_breakpoints();
    s.set_mode(Mode::Run).unwrap();
    clock.step(Duration::from_millis(1100));
    assert_eq!(timer_bits(&mut s), timing, "1.8 s of program time: all still timing");
    clock.step(Duration::from_millis(400));
    assert_eq!(
        timer_bits(&mut s),
        [true, false, true, false, false, false],
        "2.2 s of program time: on-delays done, off-delay and pulses over"
    );
}

// ---- PTO / PWM edge values (K2 §3.4.2) ----------------------------------------------------

/// PLS 0 once with control byte `ctrl`, cycle `cycle`, width `width`, count `count`; after
/// 20 ms returns (SM66.4 bad cycle/count, SM66.7 idle, pulses counted in SMD212… via Q0.0).
fn pls_once(ctrl: i64, cycle: i64, width: i64, count: i64) -> (K2Sim, Clock) {
    let (mut s, clock) = sim();
    s.load_program(
        "LD %M0.0\nR_TRIG\nMOVE %VB0, %SMB67\nMOVE %VW2, %SMW68\nMOVE %VW4, %SMW70\nMOVE %VD6, %SMD72\nPLS 0",
        "pls.il",
    )
    .unwrap();
    for (op, v) in [("VB0", ctrl), ("VW2", cycle), ("VW4", width), ("VD6", count)] {
        set(&mut s, op, Value::Int(v));
    }
    set(&mut s, "M0.0", Value::Bool(true));
    clock.step(Duration::from_millis(2));
    (s, clock)
}

#[test]
fn a_pto_with_fewer_than_two_pulses_or_a_cycle_below_two_is_refused_with_sm66_4() {
    // K2 §3.4.2: "the number of pulses 2 ~ 4,294,967,295. If fewer than 2, the K2 sets the
    // error bit and inhibits the output"; SM66.4 "cycle time or pulse count invalid; both
    // must be greater than 1".
    // The cycle cases use the 1 ms time base (SM67.3 = 1): 2 µs is beyond the channel anyway.
    for (ctrl, cycle, count, bad) in [
        (0x85, 500, 0, true),
        (0x85, 500, 1, true),
        (0x85, 500, 2, false),
        (0x8D, 1, 10, true),
        (0x8D, 0, 10, true),
        (0x8D, 2, 10, false),
    ] {
        let (mut s, clock) = pls_once(ctrl, cycle, 0, count);
        clock.step(Duration::from_millis(30));
        assert_eq!(on(&mut s, "SM66.4"), bad, "cycle {cycle} µs, count {count}: SM66.4");
        if bad {
            assert!(!on(&mut s, "Q0.0"), "cycle {cycle}, count {count}: no output");
        }
        assert!(on(&mut s, "SM66.7"), "cycle {cycle}, count {count}: idle again (or never started)");
    }
}

#[test]
fn a_pwm_width_above_the_cycle_is_always_on_and_zero_is_always_off() {
    // K2 §3.4.2 PWM: "if the pulse width is greater than the cycle time, the duty cycle is
    // 100% and the output is on continuously; if the width is 0, the duty cycle is 0% and the
    // output is off". Control byte 16#CB: enabled, PWM, µs, update cycle and width.
    for (width, want) in [(2000, true), (0, false)] {
        let (mut s, clock) = pls_once(0xCB, 1000, width, 0);
        let mut seen = Vec::new();
        for _ in 0..20 {
            clock.step(Duration::from_micros(137));
            seen.push(on(&mut s, "Q0.0"));
        }
        assert!(seen.iter().all(|q| *q == want), "width {width} µs of a 1000 µs cycle: {seen:?}");
    }
}

/// The scan statistics a program reads (SMW22 last, SMW24 minimum, SMW26 maximum scan time)
/// and the scan count survive a snapshot, as do the costs that made them: restored, the
/// longest scan is still the 12 ms one from before the save, not the first scan after it.
#[test]
fn scan_statistics_and_costs_survive_a_snapshot() {
    let (mut a, clock) = sim();
    a.load_program("LD %SM0.0\nINC %VW0", "t.il").unwrap();
    a.set_costs("min_scan=12ms").unwrap();
    clock.step(Duration::from_millis(100));
    a.set_costs("min_scan=2ms").unwrap();
    clock.step(Duration::from_millis(20));
    let st = a.snapshot_state();
    let mut b = sim::open("K205-16DT", clock.clone()).unwrap();
    b.restore_snapshot(&st).unwrap();
    clock.step(Duration::from_millis(30));
    for op in ["SMW22", "SMW24", "SMW26", "VW0"] {
        assert_eq!(get(&mut b, op), get(&mut a, op), "{op} as in the uninterrupted run");
    }
    assert_eq!(get(&mut b, "SMW26"), Value::Int(12), "the longest scan was before the save");
    assert_eq!(get(&mut b, "SMW22"), Value::Int(2), "scans of the saved 2 ms minimum");
    let (pa, pb) = (a.plc().unwrap(), b.plc().unwrap());
    assert_eq!(pb.stats, pa.stats, "the scan count and times");
    assert_eq!(pb.costs, pa.costs);
}

/// The operands of a K2 instruction fit the stack buffer `K2Machine::special` reads them
/// into (PHOME has the most: 12).
#[test]
fn every_k2_instruction_fits_the_operand_buffer() {
    let most = family::SPECIALS.iter().map(|s| s.args.len()).max().unwrap();
    assert_eq!(most, family::MAX_ARGS);
}
