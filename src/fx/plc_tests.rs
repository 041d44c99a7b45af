//! The simulated FX PLC in stepped virtual time: clocks, initial pulse, scan times, timers
//! and counters driven by a program and by writes, RUN/STOP, and the property that an
//! outcome does not depend on who polls.

use crate::core::test_rng::Rng;
use crate::core::Clock;
use crate::fx::cpu::Mode;
use crate::fx::memory::Memory;
use crate::fx::model::Model;
use crate::fx::operand::Area;
use crate::fx::program::{self, Loaded};
use std::time::Duration;

fn fx2n() -> &'static Model {
    Model::find("FX2N").unwrap()
}

fn plc(program: Option<&str>) -> (Memory, Clock) {
    let clock = Clock::stepped();
    let mut m = Memory::with_clock(fx2n(), clock.clone());
    if let Some(p) = program {
        m.load_program(Loaded::load(p, "t.il", fx2n()).unwrap_or_else(|e| panic!("{e}")));
    }
    (m, clock)
}

fn ms(n: u64) -> Duration {
    Duration::from_millis(n)
}

/// Steps the clock and brings the PLC to it (what a client's request does).
fn step(m: &mut Memory, c: &Clock, d: Duration) {
    c.step(d);
    m.advance();
}

#[test]
fn m8013_toggles_every_half_second_for_ten_seconds_as_clients_and_programs_see_it() {
    // Y0 follows M8013 through a program; a client reads M8013 itself.
    let (mut m, c) = plc(Some("LD M8013\nOUT Y0\n"));
    let (mut seen, mut y0) = (Vec::new(), Vec::new());
    let (mut last, mut last_y) = (m.bit(Area::M, 8013).unwrap(), m.bit(Area::Y, 0).unwrap());
    assert!(last && last_y, "on for the first half of each second, from time 0");
    // Ten seconds, and one more millisecond for the scan after the last change.
    for k in 1..=10_001u64 {
        step(&mut m, &c, ms(1));
        let (b, y) = (m.bit(Area::M, 8013).unwrap(), m.bit(Area::Y, 0).unwrap());
        if b != last {
            seen.push(k);
        }
        if y != last_y {
            y0.push(k);
        }
        (last, last_y) = (b, y);
    }
    let want: Vec<u64> = (1..=20).map(|i| i * 500).collect();
    assert_eq!(seen, want, "a change every 0.5 s, at 0.5 s, 1.0 s … 10 s");
    // The program sees the clock at each scan's start: Y0 changes in the first scan that
    // starts at or after the change (within one scan, here about 0.5 ms).
    let d = m.cpu.stats.last_ns;
    assert!(d > 500_000 && d < 510_000, "{d}");
    assert_eq!(y0.len(), 20);
    for (y, w) in y0.iter().zip(&want) {
        assert!(*y == w + 1 || *y == *w, "Y0 changed at {y} ms, M8013 at {w} ms");
    }
    // The other clocks, read at chosen instants.
    let (mut m, c) = plc(None);
    let at = |m: &mut Memory, t: u64| {
        c.set(Duration::from_micros(t));
        m.advance();
        [8011, 8012, 8013, 8014].map(|i| m.bit(Area::M, i).unwrap() as u8)
    };
    assert_eq!(at(&mut m, 4_999), [1, 1, 1, 1]);
    assert_eq!(at(&mut m, 5_000), [0, 1, 1, 1], "10 ms clock: 5 ms on, 5 ms off");
    assert_eq!(at(&mut m, 50_000), [1, 0, 1, 1], "100 ms clock: 50 ms on");
    assert_eq!(at(&mut m, 29_999_999), [0, 0, 0, 1]);
    assert_eq!(at(&mut m, 30_000_000), [1, 1, 1, 0], "1 min clock: 30 s on, 30 s off");
}

#[test]
fn m8002_is_on_in_the_first_scan_only_and_again_after_stop_run() {
    // D0 counts scans in which M8002 was on; D1 counts scans; M10 latches M8003's first value.
    let (mut m, c) = plc(Some("LD M8002\nINC D0\nLD M8000\nINC D1\nLD M8002\nAND M8003\nSET M10\n"));
    assert_eq!(m.word(Area::D, 0), Some(1), "the first scan runs when the program is loaded");
    assert_eq!(m.bit(Area::M, 8002), Some(true), "during the first scan");
    assert_eq!(m.bit(Area::M, 8003), Some(false));
    let d = period(&m);
    step(&mut m, &c, d - Duration::from_nanos(1));
    assert_eq!(m.bit(Area::M, 8002), Some(true), "until the second scan starts");
    step(&mut m, &c, Duration::from_nanos(1));
    assert_eq!((m.bit(Area::M, 8002), m.bit(Area::M, 8003)), (Some(false), Some(true)));
    step(&mut m, &c, ms(1000));
    assert_eq!(m.word(Area::D, 0), Some(1));
    let scans = (c.now().as_nanos() / d.as_nanos()) as u32 + 1;
    assert_eq!(m.word(Area::D, 1), Some(scans), "one scan every {d:?}");
    assert_eq!(m.bit(Area::M, 10), Some(false), "M8002 and M8003 are never on together");
    m.set_mode(Mode::Stop);
    assert_eq!(
        (m.bit(Area::M, 8000), m.bit(Area::M, 8001), m.bit(Area::M, 8002)),
        (Some(false), Some(true), Some(false))
    );
    step(&mut m, &c, ms(1000));
    assert_eq!(m.word(Area::D, 1), Some(scans), "no scans in STOP");
    m.set_mode(Mode::Run);
    assert_eq!(m.word(Area::D, 0), Some(2), "M8002 pulses again after STOP → RUN");
    assert_eq!(m.bit(Area::M, 8000), Some(true));
}

#[test]
fn scan_times_come_from_the_cost_table_and_cannot_be_written() {
    let (mut m, c) = plc(None);
    step(&mut m, &c, ms(10));
    let t = crate::fx::program::costs();
    let units = (t.overhead_ns / 100_000) as u32;
    assert_eq!([8010, 8011, 8012].map(|i| m.word(Area::D, i)), [Some(units); 3], "an empty program: END only");
    assert_eq!(m.cpu.stats.scans, 10_000_000 / t.overhead_ns + 1, "scans at 0, 0.5 ms … 10 ms");
    // A longer program takes longer: 400 bit instructions and 100 moves.
    let text = "LD X0\nOUT Y0\n".repeat(200) + &"MOV K1 D0\n".repeat(100);
    let (mut m, c) = plc(Some(&text));
    step(&mut m, &c, ms(10));
    let prog_ns = 400 * t.ns(crate::engine::CostClass::Bit) as u64
        + 100 * (2 * t.ns(crate::engine::CostClass::Bit) + t.ns(crate::engine::CostClass::Move)) as u64
        + t.ns(crate::engine::CostClass::Jump) as u64;
    assert_eq!(m.word(Area::D, 8010), Some(((t.overhead_ns + prog_ns) / 100_000) as u32));
    // Writes to the CPU's own devices are accepted and change nothing (the PLC rewrites them).
    m.set_word(Area::D, 8012, 0).unwrap();
    m.set_bit(Area::M, 8000, false).unwrap();
    assert_eq!(m.word(Area::D, 8012), Some(((t.overhead_ns + prog_ns) / 100_000) as u32));
    assert_eq!(m.bit(Area::M, 8000), Some(true));
}

/// The scan period of a program without branches (every scan costs the same).
fn period(m: &Memory) -> Duration {
    Duration::from_nanos(m.cpu.stats.last_ns)
}

/// The start of the first scan at or after `t` (scans every `d` from time 0).
fn scan_at(t: Duration, d: Duration) -> Duration {
    let (t, d) = (t.as_nanos(), d.as_nanos());
    Duration::from_nanos((t.div_ceil(d) * d) as u64)
}

/// Steps from scan start to scan start until `bit` is on; returns that scan's start.
fn when_on(m: &mut Memory, c: &Clock, area: Area, n: u16, limit: Duration) -> Duration {
    let d = period(m);
    while m.bit(area, n) != Some(true) {
        assert!(c.now() < limit, "{area:?}{n} never came on");
        let next = scan_at(c.now() + Duration::from_nanos(1), d);
        c.set(next);
        m.advance();
    }
    c.now()
}

#[test]
fn timers_reach_their_preset_at_the_right_virtual_time() {
    // T0 100 ms ×30, T200 10 ms ×50, T246 1 ms ×250 (retentive), T1 with its preset in D10.
    let text = "LD X0\nOUT T0 K30\nLD T0\nOUT Y0\nLD X0\nOUT T200 K50\nLD X1\nOUT T246 K250\nLD X0\nOUT T1 D10\nLD X2\nRST T246\n";
    let (mut m, c) = plc(Some(text));
    m.set_word(Area::D, 10, 20).unwrap();
    step(&mut m, &c, ms(1000));
    // A client turns X0 on at 1.000 s; the first scan after it sees X0 and starts the timers.
    m.set_bit(Area::X, 0, true).unwrap();
    let d = period(&m);
    let on = scan_at(ms(1000) + Duration::from_nanos(1), d);
    assert_eq!(when_on(&mut m, &c, Area::TS, 200, ms(10_000)), scan_at(on + ms(500), d), "T200: 50 × 10 ms");
    assert_eq!(m.bit(Area::TS, 0), Some(false));
    assert_eq!(when_on(&mut m, &c, Area::TS, 1, ms(10_000)), scan_at(on + ms(2000), d), "T1: D10 = 20 × 100 ms");
    assert_eq!(when_on(&mut m, &c, Area::TS, 0, ms(10_000)), scan_at(on + ms(3000), d), "T0: 30 × 100 ms");
    assert_eq!(m.bit(Area::Y, 0), Some(true), "LD T0 / OUT Y0 in the same scan");
    assert_eq!(m.word(Area::TN, 0), Some(30), "an FX timer holds at its preset");
    step(&mut m, &c, ms(5000));
    assert_eq!(m.word(Area::TN, 0), Some(30));
    assert_eq!(m.bit(Area::TC, 0), Some(true), "the coil follows its input");
    // Coil off: T0 clears at once.
    m.set_bit(Area::X, 0, false).unwrap();
    step(&mut m, &c, Duration::from_micros(500));
    assert_eq!((m.word(Area::TN, 0), m.bit(Area::TS, 0), m.bit(Area::Y, 0)), (Some(0), Some(false), Some(false)));
    // T246 (1 ms, retentive) accumulates 100 ms + 150 ms of X1 and holds between.
    m.set_bit(Area::X, 1, true).unwrap();
    let start = scan_at(c.now() + Duration::from_nanos(1), d);
    c.set(scan_at(start + ms(100), d));
    m.advance();
    m.set_bit(Area::X, 1, false).unwrap();
    step(&mut m, &c, ms(1000));
    assert_eq!(m.word(Area::TN, 246), Some(100), "held while the coil is off");
    m.set_bit(Area::X, 1, true).unwrap();
    let t1 = scan_at(c.now() + Duration::from_nanos(1), d);
    assert_eq!(when_on(&mut m, &c, Area::TS, 246, c.now() + ms(1000)), scan_at(t1 + ms(150), d), "100 + 150 ms");
    m.set_bit(Area::X, 1, false).unwrap();
    step(&mut m, &c, ms(10));
    assert_eq!(m.bit(Area::TS, 246), Some(true), "a retentive timer keeps its contact");
    m.set_bit(Area::X, 2, true).unwrap();
    step(&mut m, &c, ms(1));
    assert_eq!((m.word(Area::TN, 246), m.bit(Area::TS, 246)), (Some(0), Some(false)), "RST T246");
}

#[test]
fn a_timer_continues_from_a_value_a_client_writes() {
    let (mut m, c) = plc(Some("LD X0\nOUT T5 K100\n"));
    m.set_bit(Area::X, 0, true).unwrap();
    step(&mut m, &c, ms(2000));
    assert_eq!(m.word(Area::TN, 5), Some(19), "2 s less the first scan");
    m.set_word(Area::TN, 5, 90).unwrap();
    let written = c.now();
    let on = when_on(&mut m, &c, Area::TS, 5, ms(10_000));
    // Ten more units; the part of a unit already under way counts (at most 100 ms).
    assert!(on > written + ms(900) && on <= written + ms(1000) + period(&m), "{on:?} after {written:?}");
}

#[test]
fn counters_count_rising_edges_of_their_coil() {
    let text = "LD X0\nOUT C0 K3\nLD X0\nOUT C200 K2\nLD X1\nRST C0\nRST C200\n";
    let (mut m, c) = plc(Some(text));
    let pulse = |m: &mut Memory| {
        m.set_bit(Area::X, 0, true).unwrap();
        step(m, &c, ms(1));
        m.set_bit(Area::X, 0, false).unwrap();
        step(m, &c, ms(1));
    };
    for _ in 0..5 {
        pulse(&mut m);
    }
    assert_eq!((m.word(Area::CN, 0), m.bit(Area::CS, 0)), (Some(3), Some(true)), "16-bit: stops at the preset");
    assert_eq!((m.word(Area::CN, 200), m.bit(Area::CS, 200)), (Some(5), Some(true)), "32-bit: counts on");
    // M8200 on: C200 counts down; its contact goes off below the preset.
    m.set_bit(Area::M, 8200, true).unwrap();
    for _ in 0..7 {
        pulse(&mut m);
    }
    assert_eq!(m.word(Area::CN, 200).map(|v| v as i32), Some(-2));
    assert_eq!(m.bit(Area::CS, 200), Some(false));
    // Holding the input on counts once.
    m.set_bit(Area::X, 0, true).unwrap();
    step(&mut m, &c, ms(100));
    assert_eq!(m.word(Area::CN, 200).map(|v| v as i32), Some(-3));
    m.set_bit(Area::X, 1, true).unwrap();
    step(&mut m, &c, ms(1));
    assert_eq!((m.word(Area::CN, 0), m.bit(Area::CS, 0), m.word(Area::CN, 200)), (Some(0), Some(false), Some(0)));
}

#[test]
fn stop_turns_outputs_off_and_freezes_timers() {
    let (mut m, c) = plc(Some("LD X0\nOUT T0 K50\nLD X0\nOUT Y3\n"));
    m.set_bit(Area::X, 0, true).unwrap();
    step(&mut m, &c, ms(2000));
    m.set_mode(Mode::Stop);
    assert_eq!(m.bit(Area::Y, 3), Some(false), "outputs off in STOP");
    let tn = m.word(Area::TN, 0);
    step(&mut m, &c, ms(5000));
    assert_eq!(m.word(Area::TN, 0), tn, "no scans: the timer does not count");
    m.set_mode(Mode::Run);
    assert_eq!(m.bit(Area::Y, 3), Some(true));
    step(&mut m, &c, ms(1000));
    assert_eq!(m.word(Area::TN, 0), tn.map(|v| v + 9), "it continues after RUN (1 s less its first scan)");
}

#[test]
fn an_outcome_does_not_depend_on_who_polls() {
    // One scenario: writes at fixed times, 20 s; polled at random instants, or never.
    let text = std::fs::read_to_string(concat!(env!("CARGO_MANIFEST_DIR"), "/scripts/fx_blink.il")).unwrap();
    let writes: &[(u64, Area, u16, bool)] =
        &[(1_234, Area::X, 0, true), (7_777, Area::X, 0, false), (9_001, Area::X, 0, true), (15_000, Area::X, 1, true)];
    let run = |polls: &mut dyn FnMut(u64) -> bool| {
        let (mut m, c) = plc(Some(&text));
        for t in 0..20_000u64 {
            if polls(t) {
                c.set(ms(t));
                m.advance();
                let _ = (m.bit(Area::Y, 0), m.word(Area::TN, 0), m.port_byte(0x00A0));
            }
            for (at, a, n, v) in writes {
                if *at == t {
                    c.set(ms(t));
                    m.advance();
                    m.set_bit(*a, *n, *v).unwrap();
                }
            }
        }
        c.set(ms(20_000));
        m.advance();
        let bits = |a: Area, n: u16| (0..n).map(|i| m.bit(a, i).unwrap()).collect::<Vec<_>>();
        let words = |a: Area, n: u16| (0..n).map(|i| m.word(a, i).unwrap()).collect::<Vec<_>>();
        (
            bits(Area::Y, 8),
            words(Area::TN, 8),
            words(Area::CN, 8),
            words(Area::D, 4),
            [8010, 8011, 8012].map(|i| m.word(Area::D, i)),
            m.cpu.stats,
        )
    };
    let never = run(&mut |_| false);
    for seed in 1..=3 {
        let mut rng = Rng(seed);
        let polled = run(&mut |_| rng.below(50) == 0);
        assert_eq!(polled, never, "seed {seed}");
    }
    assert!(never.0[1] && never.1[0] == 30 && never.3[0] == 1234 && never.5.scans > 30_000, "{never:?}");
}

#[test]
fn load_errors_name_the_fx_line_and_what_to_do() {
    let e = |t: &str| Loaded::load(t, "p.il", fx2n()).expect_err(t).to_string();
    assert!(e("LD X0\nOUTT Y0\n").contains("p.il:2:1: unknown FX instruction OUTT"), "{}", e("LD X0\nOUTT Y0\n"));
    assert!(e("LD X0\nOUTT Y0\n").contains("did you mean OUT"));
    // Another family's mnemonic gets the FX way to write it (FX PM 2 and 4), not MOV for TON.
    let ton = e("LD X0\nTON T0 K20\n");
    assert!(ton.contains("OUT T0 K20") && !ton.contains("did you mean MOV"), "{ton}");
    assert!(e("LDN X0\n").contains("LDI X0"), "{}", e("LDN X0\n"));
    assert!(e("LD X0\nOUT X1\n").contains("p.il:2:5") && e("LD X0\nOUT X1\n").contains("drives Y, M and S"));
    assert!(e("LD X0\nOUT T0\n").contains("needs a preset"));
    assert!(e("LD X0\nOUT C240 K5\n").contains("high-speed counters"));
    assert!(e("LD X0\nOUT M8000\n").contains("driven by the PLC"));
    assert!(e("LD X0\nMOV K1 D9000\n").contains("p.il:2:8"), "{}", e("LD X0\nMOV K1 D9000\n"));
    assert!(e("LD Y8\n").contains("Y numbers are octal"));
    assert!(e("LD X0\nOUT Y0 K5\n").contains("one operand"));
    assert!(e("LD X0\nMOV K1\n").contains("MOV takes 2 operand(s)"));
    assert!(e("LD X0\nMOV K5 K4X0\n").contains("p.il:2:8: MOV K4X0: inputs X cannot be written"));
    assert!(e("LD X0\nINC X0\n").contains("inputs X"));
    // After END nothing is read; a step-number column is accepted.
    assert!(Loaded::load("0 LD X000\n1 OUT Y000\nEND\nthis is not FX\n", "p.il", fx2n()).is_ok());
}

#[test]
fn fx_lists_translate_to_the_engine_dialect() {
    let t =
        program::translate("LDI X0\nANB\nPLS M0\nMOV K-5 D0\nDMOV K4Y0 D2\nMOV T3 D4\nLD> C5 H1F\n", "p.il", fx2n())
            .unwrap();
    assert_eq!(
        t.text,
        "LDN X0\nALD\nLPS\nR_TRIG\nST M0\nLPP\nLPS\nMOVE -5, D0\nLPP\nLPS\nMOVD K4Y0/DINT, D2/DINT\nLPP\nLPS\nMOVE TN3, D4\nLPP\nLDW> CN5, 16#1F"
    );
}

#[test]
fn k4y0_in_a_32_bit_move_has_its_high_bits_zero() {
    let (mut m, c) = plc(Some("LD M8000\nMOV K-1 K4Y0\nDMOV K4Y0 D0\nMOV K4Y0 D2\nDMOV K8Y0 D4\n"));
    step(&mut m, &c, ms(1));
    let d = |i| m.word(Area::D, i).unwrap();
    assert_eq!((d(0), d(1)), (0xFFFF, 0), "K4Y0 in 32 bits: 65535");
    assert_eq!(d(2), 0xFFFF, "in 16 bits: −1");
    assert_eq!((d(4), d(5)), (0xFFFF, 0), "K8Y0: Y20–Y37 are off");
}

#[test]
fn docs_list_every_fx_instruction_with_its_source() {
    let doc = std::fs::read_to_string(concat!(env!("CARGO_MANIFEST_DIR"), "/docs/il.md")).unwrap();
    assert!(doc.contains(&program::markdown()), "docs/il.md: the FX table is generated by fx::program::markdown()");
}

#[test]
fn the_subset_behaves_as_the_fx_manual_says() {
    let text = "\
LD X0
ANI X1
LD X2
OR X3
ANB
OUT Y0
LD X0
MPS
AND X2
OUT Y1
MRD
INV
OUT Y2
MPP
PLS M0
LDF X0
OUT M1
LD M0
SET M2
LD X4
RST M2
LDP X0
ADDP D0 K5 D0
LD X0
INC D1
SUB K0 K7 D2
MOV K4X0 D3
LD X0
DADD D10 K100000 D10
LD= D0 K10
OUT Y3
LD X0
ORB
LD> D1 K1
AND< D1 K3
OUT Y4
LD X5
RST D0
END
";
    let (mut m, c) = plc(Some(text));
    let (y, mm, d) = (
        |m: &Memory, i| m.bit(Area::Y, i).unwrap(),
        |m: &Memory, i| m.bit(Area::M, i).unwrap(),
        |m: &Memory, i| m.word(Area::D, i).unwrap() as u16 as i16,
    );
    // Runs exactly `n` more scans.
    let scans = |m: &mut Memory, n: u32| {
        let d = period(m);
        for _ in 0..n {
            c.set(scan_at(c.now() + Duration::from_nanos(1), d));
            m.advance();
        }
    };
    m.set_bit(Area::X, 0, true).unwrap();
    m.set_bit(Area::X, 3, true).unwrap();
    scans(&mut m, 1);
    assert!(mm(&m, 0), "PLS: on in the scan X0 rose");
    scans(&mut m, 1);
    assert!(y(&m, 0), "X0·¬X1·(X2+X3)");
    assert!(!y(&m, 1) && !y(&m, 2), "MPS/MRD/INV: Y1 = X0·X2, Y2 = ¬X0");
    assert!(!mm(&m, 0), "PLS: on for one scan only");
    assert!(mm(&m, 2), "SET from the pulse stays on");
    assert_eq!(d(&m, 0), 5, "ADDP ran once, on the rising edge");
    assert_eq!(d(&m, 1), 2, "INC runs every scan");
    assert_eq!(d(&m, 2), -7, "16-bit results are signed");
    assert_eq!(d(&m, 3), 0b1001, "K4X0: X0 and X3");
    assert_eq!(m.word(Area::D, 10).unwrap() | m.word(Area::D, 11).unwrap() << 16, 200_000, "DADD: a 32-bit pair");
    assert!(y(&m, 4), "LD> D1 K1 / AND< D1 K3 with D1 = 2");
    m.set_bit(Area::X, 0, false).unwrap();
    scans(&mut m, 1);
    assert!(mm(&m, 1), "LDF: the scan X0 fell");
    scans(&mut m, 1);
    assert!(!mm(&m, 1), "… for one scan");
    m.set_bit(Area::X, 4, true).unwrap();
    m.set_word(Area::D, 0, 10).unwrap();
    scans(&mut m, 1);
    assert!(!mm(&m, 2) && y(&m, 3), "RST M2; LD= D0 K10");
    m.set_bit(Area::X, 5, true).unwrap();
    scans(&mut m, 1);
    assert_eq!(d(&m, 0), 0, "RST D0");
}

#[test]
fn an_unknown_fx_instruction_is_never_pointed_at_end() {
    // END stops what follows from being scanned (FX PM 2, End): a typo is not answered with
    // it (engine::isa::NEVER_SUGGESTED), while a harmless near name still is.
    for typo in ["EN", "ENDD", "EMD", "XEND"] {
        let Err(e) = Loaded::load(&format!("LD X0\n{typo}\n"), "t.il", fx2n()) else { panic!("{typo} loaded") };
        assert!(!e.hint.as_deref().unwrap_or("").contains("END"), "{typo}: {:?}", e.hint);
    }
    let Err(e) = Loaded::load("LD X0\nOUTT Y0\n", "t.il", fx2n()) else { panic!("OUTT loaded") };
    assert!(e.hint.as_deref().unwrap_or("").contains("OUT"), "{:?}", e.hint);
}
