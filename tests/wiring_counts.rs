//! A wired machine counts exactly, and what it counts does not depend on who reads it or
//! when: a wired encoder at 1× gives one count per encoder period (from power-up, on ramps,
//! however often a client polls), the CV = PV event comes where the plan says, and a pulse
//! output wired back to an input carries its whole train, delayed, ending low.
//!
//! In process (the shell on a stepped session), so a scenario can be run polled at random
//! instants and never polled, and the two compared.

use plcsh::shell::Shell;

#[path = "common/in_process.rs"]
mod in_process;
use in_process::run;

/// The seeded generator the property tests share (`core::test_rng`).
#[path = "../src/core/test_rng.rs"]
#[allow(dead_code)]
mod test_rng;
use test_rng::Rng;

fn shell() -> Shell {
    in_process::shell_with(&[("plc", "sim:K205-16DT"), ("servo", "sim-servo:?id=1")])
}

fn get(sh: &mut Shell, op: &str) -> i64 {
    let v = &run(sh, &format!("get {op}"))[0]["values"][0]["value"];
    v.as_i64().unwrap_or_else(|| i64::from(v.as_bool().unwrap()))
}

/// The PLC's event log: (name, time µs).
fn events(sh: &mut Shell) -> Vec<(String, i64)> {
    let l = run(sh, "events keep");
    l[0]["events"]
        .as_array()
        .map(|a| a.iter().map(|e| (e["name"].as_str().unwrap().to_string(), e["time_us"].as_i64().unwrap())).collect())
        .unwrap_or_default()
}

/// The drive follows PTO0 through gear 10: one pulse = 10 increments = one encoder period
/// at 1000 lines per revolution (10000 increments), so N pulses move N periods.
const PULSE_AXIS: &str = "set servo:gear_factor=10, servo:gear_divider=1; servo mode pulse; servo enable; \
     sim wire plc:Q0.0 -> servo:pulse; sim wire servo:encoder -> plc:I0.1,I0.0 lines=1000";

#[test]
fn one_x_counts_one_per_period_from_power_up() {
    for (count, x4) in [(750, false), (300, false), (750, true)] {
        let mut sh = shell();
        run(&mut sh, PULSE_AXIS);
        let rate = if x4 { "4x" } else { "1x" };
        run(&mut sh, &format!("hsc 0 mode=9 rate={rate} pv=500; pto 0 freq=1kHz count={count}; sim step 2s"));
        let want = if x4 { 4 * count } else { count };
        assert_eq!(get(&mut sh, "SMD38"), want, "{count} periods at {rate}");
        assert_eq!(get(&mut sh, "servo:position_actual"), 10 * count);
        let hit: Vec<_> = events(&mut sh).into_iter().filter(|e| e.0 == "hsc0-cv=pv").collect();
        if x4 {
            // 4 counts a period: the 500th count ends the 125th period.
            assert_eq!(hit, vec![("hsc0-cv=pv".to_string(), 125_000)]);
        } else if count >= 500 {
            // The 500th period runs from 499 ms to 500 ms; its count comes as it ends.
            assert_eq!(hit, vec![("hsc0-cv=pv".to_string(), 500_000)]);
        }
    }
}

#[test]
fn a_trapezoid_at_one_x_counts_the_periods_it_moves() {
    for (rate, want) in [("1x", 1000), ("4x", 4000)] {
        let mut sh = shell();
        run(
            &mut sh,
            &format!(
                "sim step 100ms; sim wire servo:encoder -> plc:I0.1,I0.0 lines=1000; hsc 0 mode=9 rate={rate}; \
                 servo enable; servo move abs 10000 speed=300rpm acc=100rps/s; servo wait target"
            ),
        );
        assert_eq!(get(&mut sh, "SMD38"), want, "10000 increments = 1000 periods at {rate}");
        // Back to 0 and out again: the count follows the position, reversals included.
        run(&mut sh, "servo move abs 0 speed=300rpm acc=100rps/s; servo wait target");
        assert_eq!(get(&mut sh, "SMD38"), 0);
        run(&mut sh, "servo move abs 2345 speed=100rpm acc=7rps/s; servo wait target");
        // 2345 increments = 234.5 periods: 234 whole periods at 1×, 938 quarter periods at 4×.
        assert_eq!(get(&mut sh, "SMD38"), if rate == "1x" { 234 } else { 938 });
    }
}

#[test]
fn reading_every_7ms_during_a_3khz_move_changes_nothing() {
    let mut sh = shell();
    run(&mut sh, PULSE_AXIS);
    run(&mut sh, "hsc 0 mode=9 rate=1x; pto 0 freq=3kHz count=300");
    let mut last = 0;
    for _ in 0..20 {
        run(&mut sh, "sim step 7ms");
        let cv = get(&mut sh, "SMD38");
        assert!(cv >= last && cv <= 300, "{cv} after {last}");
        last = cv;
    }
    assert_eq!(get(&mut sh, "SMD38"), 300);
}

/// A scenario: setup, then commands at fixed instants; `polled` reads the PLC at the
/// instants `rng` picks in between. Returns the final counts, status and the event log.
fn scenario(setup: &str, steps: &[(u64, &str)], rng: Option<&mut Rng>) -> (Vec<i64>, Vec<(String, i64)>) {
    let mut sh = shell();
    run(&mut sh, setup);
    let mut rng = rng;
    for &(us, then) in steps {
        match rng.as_deref_mut() {
            Some(r) => {
                let mut left = us;
                while left > 0 {
                    let d = (r.below(9_000) + 1).min(left);
                    run(&mut sh, &format!("sim step {d}us"));
                    left -= d;
                    match r.below(4) {
                        0 => run(&mut sh, "get SMD38 I0.0 I0.1 SMB36"),
                        1 => run(&mut sh, "get plc:SMD38; get servo:position_actual"),
                        2 => run(&mut sh, "events keep"),
                        _ => run(&mut sh, "get SMD48 I0.3"),
                    };
                }
            }
            None => {
                run(&mut sh, &format!("sim step {us}us"));
            }
        }
        if !then.is_empty() {
            run(&mut sh, then);
        }
    }
    let ops = ["SMD38", "SMB36", "SMD48", "I0.0", "I0.1", "I0.3"];
    let vals = ops.iter().map(|o| get(&mut sh, o)).collect();
    (vals, events(&mut sh))
}

#[test]
fn what_a_wired_machine_counts_does_not_depend_on_who_reads_it() {
    let trapezoid =
        "sim wire servo:encoder -> plc:I0.1,I0.0 lines=1000; hsc 0 mode=9 rate=1x pv=[250,700,400] at VB3009; \
                     servo enable";
    let cruise = format!("{PULSE_AXIS}; hsc 0 mode=9 rate=1x pv=[100,200] relative cyclic at VB3009");
    let looped = "sim wire plc:Q0.1 -> plc:I0.3 delay=7ms; hsc 1 mode=0 pv=60";
    // Noise on A and B stuck for a while: miscounts, the same ones whoever reads.
    let noisy = format!(
        "{PULSE_AXIS}; hsc 0 mode=9 rate=1x pv=150; sim fault noisy I0.1 freq=20kHz at=20ms for=30ms; \
         sim fault stuck I0.0=1 at=70ms for=9ms"
    );
    type Scenario<'a> = (String, Vec<(u64, &'a str)>, Option<i64>);
    let cases: Vec<Scenario> = vec![
        // 8000 increments out (800 periods), back to 4000 (400) while still moving.
        (
            trapezoid.to_string(),
            vec![
                (1_300, "servo move abs 8000 speed=200rpm acc=30rps/s"),
                (170_000, "servo move abs 4000 speed=150rpm acc=50rps/s"),
                (600_000, ""),
            ],
            Some(400),
        ),
        // 1234 pulses at 2.5 kHz, then 321 more at 700 Hz, each one encoder period.
        (
            cruise,
            vec![(900, "pto 0 freq=2.5kHz count=1234"), (600_000, "pto 0 freq=700Hz count=321"), (600_000, "")],
            Some(1555),
        ),
        // 100 pulses at 10 kHz and 50 at 1 kHz, looped back 7 ms later.
        (
            looped.to_string(),
            vec![(500, "pto 1 freq=10kHz count=100"), (30_000, "pto 1 freq=1kHz count=50"), (80_000, "")],
            Some(150),
        ),
        (noisy, vec![(0, "pto 0 freq=3kHz count=300"), (200_000, "")], None),
    ];
    let mut rng = Rng(0x5EED_F1CE);
    for (setup, steps, want) in &cases {
        let quiet = scenario(setup, steps, None);
        let counted = if setup.contains("I0.3") { quiet.0[2] } else { quiet.0[0] };
        match want {
            Some(n) => assert_eq!(counted, *n, "{setup}: the exact count"),
            None => assert_ne!(counted, 300, "{setup}: the noise miscounts"),
        }
        assert!(!quiet.1.is_empty(), "{setup}: some events");
        assert_eq!(scenario(setup, steps, None), quiet, "{setup}: the same again");
        for i in 0..100 {
            let seed = rng.next_u64() | 1;
            let polled = scenario(setup, steps, Some(&mut Rng(seed)));
            assert_eq!(polled, quiet, "{setup}: polled with seed {seed:#x} (schedule {i})");
        }
    }
}

#[test]
fn a_looped_train_ends_low_and_arrives_whole_after_its_delay() {
    for delay in ["0ms", "3ms", "10ms", "11ms", "25ms"] {
        let mut sh = shell();
        run(&mut sh, &format!("sim wire plc:Q0.1 -> plc:I0.3 delay={delay}; hsc 1 mode=0"));
        run(&mut sh, "pto 1 freq=10kHz count=100; sim step 60ms");
        assert_eq!(get(&mut sh, "SMD48"), 100, "delay {delay}");
        assert_eq!((get(&mut sh, "Q0.1"), get(&mut sh, "I0.3")), (0, 0), "delay {delay}: low after the train");
    }
    // Read while the delayed train arrives: every count on its cycle, low between trains.
    let mut sh = shell();
    run(&mut sh, "sim wire plc:Q0.1 -> plc:I0.3 delay=11ms; hsc 1 mode=0; pto 1 freq=10kHz count=100");
    run(&mut sh, "sim step 10ms");
    assert_eq!((get(&mut sh, "SMD48"), get(&mut sh, "I0.3")), (0, 0), "the train is out, none arrived");
    run(&mut sh, "sim step 1ms");
    assert_eq!((get(&mut sh, "SMD48"), get(&mut sh, "I0.3")), (1, 1), "the first pulse rises 11 ms after PLS");
    run(&mut sh, "sim step 4920us");
    assert_eq!((get(&mut sh, "SMD48"), get(&mut sh, "I0.3")), (50, 1), "50 pulses by 15.92 ms, the 50th high");
    run(&mut sh, "sim step 5080us");
    assert_eq!((get(&mut sh, "SMD48"), get(&mut sh, "I0.3")), (100, 0), "all 100, low again");
    // A stopped train: what was out arrives, the rest never does.
    let mut sh = shell();
    run(&mut sh, "sim wire plc:Q0.1 -> plc:I0.3 delay=5ms; hsc 1 mode=0; pto 1 freq=1kHz count=100; sim step 20500us");
    run(&mut sh, "pstop 1; sim step 50ms");
    assert_eq!(get(&mut sh, "SMD48"), 21, "pulses 1..21 rose before PSTOP at 20.5 ms");
}

#[test]
fn a_counter_sees_injected_noise_and_a_stuck_input() {
    // HSC0 in mode 0 counts I0.1: 1000 rising edges of a 1 kHz wave in a second.
    let base = "hsc 0 mode=0; sim input I0.1 freq=1kHz";
    let count = |extra: &str| {
        let mut sh = shell();
        run(&mut sh, &format!("{base}; {extra}; sim step 1s"));
        get(&mut sh, "SMD38")
    };
    assert_eq!(count("get SMD38"), 1000);
    // Stuck low for 200 ms: the 200 edges in that window are not seen.
    assert_eq!(count("sim fault stuck I0.1=0 at=300ms for=200ms"), 800);
    // Noise at 20 kHz for 100 ms: random levels in 2000 slots instead of 100 clean edges.
    let noisy = count("sim fault noisy I0.1 freq=20kHz at=100ms for=100ms");
    assert!(noisy > 1000 + 300, "noise adds edges: {noisy}");
    assert_eq!(count("sim fault noisy I0.1 freq=20kHz at=100ms for=100ms"), noisy, "seeded: the same noise");
    // Read at every millisecond: the same.
    let mut sh = shell();
    run(&mut sh, &format!("{base}; sim fault noisy I0.1 freq=20kHz at=100ms for=100ms"));
    for _ in 0..1000 {
        run(&mut sh, "sim step 1ms; get I0.1");
    }
    assert_eq!(get(&mut sh, "SMD38"), noisy, "polled every millisecond");
    // A stepped wait stops at an event the noise brings forward, at its time.
    let at = |line: &str| {
        let mut sh = shell();
        let l = run(
            &mut sh,
            &format!("{base}; hsc 0 mode=0 pv=300; sim fault noisy I0.1 freq=20kHz at=100ms for=100ms; {line}"),
        );
        // The event as the wait took it, or as the log has it.
        let waited = l.iter().find(|r| r["cmd"] == "wait").map(|r| r["event"].clone());
        let ev = run(&mut sh, "events keep");
        let logged = ev[0]["events"].as_array().and_then(|a| a.iter().find(|e| e["name"] == "hsc0-cv=pv").cloned());
        let hit = waited.or(logged);
        (hit.map(|e| e["time_us"].as_i64().unwrap()), l.last().unwrap()["time_us"].as_i64())
    };
    let (quiet, _) = at("sim step 2s");
    let quiet = quiet.expect("the PV is reached");
    assert!(quiet < 300_000, "the noise brought it forward: {quiet}");
    let (waited, clock) = at("wait event hsc0-cv=pv timeout=2s; sim time");
    assert_eq!((waited, clock), (Some(quiet), Some(quiet)), "the wait stops at the event");
}

#[test]
fn a_looped_train_runs_the_edge_interrupt_of_each_pulse() {
    // Event 6: I0.3 rising (K2 §2.2.7); the routine counts the pulses it sees.
    let dir = std::env::temp_dir().join(format!("plcsh-wiring-counts-{}", std::process::id()));
    std::fs::create_dir_all(&dir).unwrap();
    let il = dir.join("edges.il");
    std::fs::write(
        &il,
        "PROGRAM MAIN\nLD %SM0.1\nATCH ON_EDGE, 6\nENI\nEND_PROGRAM\nINTERRUPT ON_EDGE\nLD %SM0.0\nINC %VW10\nEND_INTERRUPT\n",
    )
    .unwrap();
    let mut sh = shell();
    run(&mut sh, &format!("sim program load {}; sim wire plc:Q0.1 -> plc:I0.3 delay=2ms", il.display()));
    run(&mut sh, "sim step 5ms; pto 1 freq=1kHz count=50; sim step 100ms");
    assert_eq!(get(&mut sh, "VW10"), 50, "one routine per looped pulse");
    let _ = std::fs::remove_dir_all(&dir);
}
