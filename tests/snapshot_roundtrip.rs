//! Everything a snapshot saves restores: random simulated machines (a K2 running an IL program,
//! with injected faults, wires — PTO → drive, encoder → counter, drive outputs and switches,
//! loopbacks — counters with queued events, pulse trains; drives moving, jogging, homing,
//! following pulses, faulting at a position; a UMPK with a program, flash, injected faults
//! and a failing flash page; an FX PLC with a program and injected faults) run for random
//! virtual times, are saved, and restored into a fresh
//! session that first did unrelated things of its own. Then:
//!
//! - the restored session saves the same bytes (save → restore → save is the identity);
//! - the original and the restored session, continued with the same commands for the same
//!   virtual time, give the same results — every statistic a program or a client reads
//!   among them (the K2's scan count and SMW22/24/26, the FX PLC's D8010–D8012, the UMPK's
//!   program time) — and end in the same state, byte for byte;
//! - a new `plcsh` process restoring the file and continuing ends in that state too.
//!
//! Cases come from a seeded generator (`core::test_rng`); a failure prints the seed and the
//! machine's command lines. In process (the shell on a stepped session) for the bulk.

mod common;

use plcsh::core::Clock;
use plcsh::output::Style;
use plcsh::session::Session;
use plcsh::shell::Shell;
use plcsh::snapshot::Snapshot;
use serde_json::Value;

/// The seeded generator the property tests share (`core::test_rng`).
#[path = "../src/core/test_rng.rs"]
#[allow(dead_code)]
mod test_rng;
use test_rng::Rng;

const ROOT: &str = env!("CARGO_MANIFEST_DIR");

/// A generated machine: its devices, the lines that build and run it up to the save, the
/// lines a fresh session runs before the restore, and the lines both run after it.
struct Case {
    seed: u64,
    devices: Vec<(&'static str, &'static str)>,
    /// Each must succeed, but those marked `? ` (an action between steps, which a fault or
    /// a busy output may refuse).
    setup: Vec<String>,
    noise: Vec<String>,
    after: Vec<String>,
}

impl Case {
    fn describe(&self) -> String {
        let devices: Vec<String> = self.devices.iter().map(|(n, u)| format!("--device {n}={u}")).collect();
        format!(
            "seed {:#x}\n  devices: {}\n  setup: {}\n  fresh session first: {}\n  after: {}",
            self.seed,
            devices.join(" "),
            self.setup.join("; "),
            self.noise.join("; "),
            self.after.join("; ")
        )
    }

    fn has(&self, name: &str) -> bool {
        self.devices.iter().any(|(n, _)| *n == name)
    }

    fn shell(&self) -> Shell {
        let mut s = Session::new(Clock::stepped());
        for (name, url) in &self.devices {
            s.open(name, url).unwrap_or_else(|e| panic!("{}\nopening {name}: {e}", self.describe()));
        }
        Shell::new(s, Style { json: true, color: false })
    }
}

fn path(rel: &str) -> String {
    format!("{ROOT}/{rel}")
}

/// Applies a line of the simulated FX PLC's control language (`fx-control fault stuck X1=1`:
/// what `plcsh sim serve --fx-…` takes on its control channel) to the in-process one.
fn fx_control(sh: &mut Shell, line: &str) -> Option<Value> {
    let words = line.strip_prefix("fx-control ")?;
    let i = sh.session.index("fx").expect("an FX device");
    let plc = plcsh::fx::driver::simulator(sh.session.entry(i).device.as_mut()).expect("a simulated FX PLC");
    let mut m = plc.lock().unwrap();
    Some(match plcsh::fx::control::answer(&mut m, words) {
        Ok((text, data)) => serde_json::json!({ "text": text, "data": data }),
        Err(e) => serde_json::json!({ "error": e.to_string() }),
    })
}

/// Runs a line; each command's result as JSON (an error as `{"error": message}`).
fn run(sh: &mut Shell, line: &str) -> Vec<Value> {
    if let Some(v) = fx_control(sh, line) {
        return vec![v];
    }
    sh.exec(line)
        .into_iter()
        .map(|r| match r {
            Ok(o) => serde_json::to_value(&o).unwrap(),
            Err((cmd, e)) => serde_json::json!({ "cmd": cmd, "error": e.to_string() }),
        })
        .collect()
}

/// Runs a line whose every command must succeed.
fn must(sh: &mut Shell, line: &str, case: &Case) {
    if let Some(v) = fx_control(sh, line) {
        assert!(v.get("error").is_none(), "{}\n`{line}`: {v}", case.describe());
        return;
    }
    for r in sh.exec(line) {
        if let Err((cmd, e)) = r {
            panic!("{}\n`{line}`: {cmd} failed: {e}", case.describe());
        }
    }
}

fn snapshot_text(sh: &mut Shell, case: &Case) -> String {
    Snapshot::capture(&mut sh.session)
        .and_then(|s| s.encode())
        .unwrap_or_else(|e| panic!("{}\nsaving: {e}", case.describe()))
}

/// The first path where two JSON texts differ, for a failure message.
fn difference(a: &str, b: &str) -> String {
    fn walk(a: &Value, b: &Value, at: String) -> Option<String> {
        match (a, b) {
            (Value::Object(x), Value::Object(y)) => x.keys().chain(y.keys()).find_map(|k| match (x.get(k), y.get(k)) {
                (Some(va), Some(vb)) => walk(va, vb, format!("{at}.{k}")),
                _ => Some(format!("{at}.{k} (only on one side)")),
            }),
            (Value::Array(x), Value::Array(y)) if x.len() == y.len() => {
                x.iter().zip(y).enumerate().find_map(|(i, (va, vb))| walk(va, vb, format!("{at}[{i}]")))
            }
            _ => (a != b).then(|| format!("{at}: {a} vs {b}")),
        }
    }
    let (a, b): (Value, Value) = (serde_json::from_str(a).unwrap(), serde_json::from_str(b).unwrap());
    walk(&a, &b, String::new()).unwrap_or_else(|| "(same JSON, different text)".into())
}

/// Draws a machine. Setup lines are valid by construction (each must succeed); the lines
/// after a save may fail (a fault, a busy output), and then fail alike on both sides.
fn generate(seed: u64) -> Case {
    let mut r = Rng(seed);
    let mut devices = Vec::new();
    let (k2, servo, umpk, fx) = loop {
        let k2 = r.below(6) != 0;
        let servo = r.below(3) != 0;
        let umpk = r.below(3) == 0;
        let fx = r.below(3) == 0;
        if k2 || servo || umpk || fx {
            break (k2, servo, umpk, fx);
        }
    };
    if k2 {
        devices.push(("plc", *["sim:K205-16DT", "sim:K205-16DT", "sim:K209M-56DT"].get(r.below(3) as usize).unwrap()));
    }
    if servo {
        devices.push(("servo", "sim-servo:?id=1"));
    }
    let umpk_program = umpk && r.below(3) != 0;
    if umpk {
        devices.push(("umpk", if umpk_program { "sim-umpk:UMPK16" } else { "sim-umpk:UMPK8" }));
    }
    if fx {
        devices.push(("fx", "sim-fx:FX3U"));
    }
    let mut setup: Vec<String> = Vec::new();
    let mut actions: Vec<String> = Vec::new();
    let mut gets: Vec<String> = Vec::new();
    let ms = |r: &mut Rng, lo: i64, hi: i64| format!("{}ms", r.in_range(lo, hi));

    // The K2 and what is wired to it.
    let wired = k2 && servo && r.below(2) == 0;
    if k2 {
        setup.push("use plc".into());
        setup.push(format!("set VW10={}, VW12={}", r.below(65536), r.below(65536)));
        // 0 none, 1 traffic light (timers), 2 conveyor (counter, edge interrupt), 3 PABS (PTO0).
        let program = r.below(4);
        match program {
            1 => {
                setup.push(format!("sim program load {}", path("scripts/traffic_light.il")));
                // Its enable input, unless the encoder drives I0.0.
                if !wired {
                    setup.push("set I0.0=1".into());
                    actions.push("use plc; set I0.0=0".into());
                    actions.push("use plc; set I0.0=1".into());
                }
                gets.push("plc:T37 plc:T38 plc:T39 plc:M10.0 plc:M10.1".into());
            }
            2 => {
                setup.push(format!("sim program load {}", path("scripts/conveyor.il")));
                if !wired {
                    setup.push(format!("sim input I0.0 freq={}Hz", r.in_range(1, 40)));
                }
                actions.push("use plc; set I0.2=1".into());
                actions.push("use plc; set I0.2=0".into());
                gets.push("plc:C1 plc:VW20".into());
            }
            3 => {
                setup.push(format!("sim program load {}", path("scripts/pabs_ramp.il")));
                setup.push(format!("set VD8={}", r.in_range(100, 20_000)));
                actions.push("use plc; set M0.0=1".into());
                actions.push("use plc; set M0.0=0".into());
                gets.push("plc:M0.1 plc:M0.2 plc:MB1".into());
            }
            _ => {}
        }
        if r.below(3) == 0 {
            setup.push("sim retain VB0[64]".into());
        }
        if wired {
            let lines = r.pick(&[250, 500, 1000, 1250]);
            let gear = r.in_range(1, 8);
            setup.push(format!(
                "set servo:gear_factor={gear}, servo:gear_divider=1; servo mode pulse; servo enable; \
                 sim wire plc:Q0.0 -> servo:pulse; sim wire servo:encoder -> plc:I0.1,I0.0 lines={lines}"
            ));
            if r.below(2) == 0 {
                setup.push("sim wire servo:target_reached -> plc:I0.5".into());
            }
            if r.below(2) == 0 {
                setup.push(format!("sim wire servo:home@{} -> plc:I0.4", r.in_range(-5_000, 40_000)));
            }
            let rate = r.pick(&["1x", "4x"]);
            let pv: Vec<String> = (0..r.in_range(1, 4)).map(|_| r.in_range(1, 3_000).to_string()).collect();
            setup.push(format!("hsc 0 mode=9 rate={rate} pv=[{}] relative at VB3009 cv=0", pv.join(",")));
            if program != 3 {
                setup.push(format!("pto 0 freq={}Hz count={}", r.in_range(200, 50_000), r.in_range(1, 20_000)));
                actions.push(format!(
                    "use plc; pto 0 freq={}Hz count={}",
                    r.in_range(200, 50_000),
                    r.in_range(1, 5_000)
                ));
            }
            gets.push("plc:SMD38 plc:SMB36 plc:I0.4 plc:I0.5 servo:position_actual servo:statusword".into());
        } else if program == 0 || program == 3 && r.below(2) == 0 {
            setup.push(format!(
                "hsc 0 mode=9 rate=4x pv=[100,200,300] relative at VB3009 cv=0; sim quad I0.1 I0.0 freq={}Hz",
                r.in_range(50, 5_000)
            ));
            actions.push(format!("use plc; sim quad I0.1 I0.0 freq={}Hz", r.in_range(50, 5_000)));
            gets.push("plc:SMD38".into());
        }
        if r.below(2) == 0 {
            setup.push(format!("set Q0.3=1; sim wire plc:Q0.3 -> plc:I0.6 delay={}", ms(&mut r, 1, 50)));
            actions.push("use plc; set Q0.3=0".into());
            actions.push("use plc; set Q0.3=1".into());
            gets.push("plc:I0.6".into());
        }
        if program != 1 && r.below(2) == 0 {
            setup.push(format!(
                "sim wire plc:Q0.1 -> plc:I0.3 delay={}; pto 1 freq={}Hz count={}",
                ms(&mut r, 0, 20),
                r.in_range(20, 2_000),
                r.in_range(1, 500)
            ));
            actions.push(format!("use plc; pto 1 freq={}Hz count={}", r.in_range(20, 2_000), r.in_range(1, 200)));
            gets.push("plc:I0.3 plc:SMB66".into());
        }
        for _ in 0..r.below(3) {
            setup.push(match r.below(6) {
                0 => format!("sim fault stuck I0.7=1 after={} for={}", ms(&mut r, 0, 800), ms(&mut r, 1, 800)),
                1 => format!("sim fault noisy I1.0 freq={}Hz for={}", r.in_range(10, 5_000), ms(&mut r, 1, 900)),
                2 => format!("sim fault power-loss after={} for={}", ms(&mut r, 0, 1_500), ms(&mut r, 1, 400)),
                3 => format!("sim fault exception 4 on VW200 times={}", r.in_range(1, 3)),
                4 => format!("sim fault no-reply on VW202 after={} times=1", ms(&mut r, 0, 1_500)),
                _ => format!("sim fault late 5ms on VW204 times={}", r.in_range(1, 3)),
            });
        }
        gets.push(
            "plc:VW10 plc:VW12 plc:VW200 plc:VW202 plc:VW204 plc:Q0.0 plc:Q0.1 plc:Q0.2 plc:I0.7 plc:I1.0 plc:SMB66"
                .into(),
        );
    }

    // The drive on its own: a move, a jog, homing, pulses at its input; switches and an
    // armed fault on its axis.
    if servo && !wired {
        if r.below(2) == 0 {
            setup.push(format!("servo sim switch home {}", r.in_range(-20_000, 20_000)));
        }
        if r.below(3) == 0 {
            setup.push(format!("servo sim switch pos {}", r.in_range(30_000, 200_000)));
        }
        if r.below(3) == 0 {
            setup.push(format!("servo sim fault drive 16#7500 at={}", r.in_range(-50_000, 50_000)));
        }
        let speed = r.in_range(10, 1_500);
        setup.push(match r.below(5) {
            0 => format!("servo enable; servo move rel {} speed={speed}rpm", r.in_range(-200_000, 200_000)),
            1 => format!("servo enable; servo jog {}rpm", r.in_range(-speed, speed)),
            2 => format!("servo enable; servo home method={}", r.pick(&[19, 34, 35])),
            3 => format!(
                "servo mode pulse; servo enable; servo sim pulses freq={} count={}",
                r.in_range(100, 20_000),
                r.in_range(1, 10_000)
            ),
            _ => "servo enable".to_string(),
        });
        actions.push("servo halt".into());
        actions.push("servo halt off".into());
        actions.push(format!("servo move abs {} speed={}rpm", r.in_range(-100_000, 100_000), r.in_range(10, 1_000)));
        actions.push("servo fault-reset".into());
        gets.push("servo:position_actual servo:velocity_actual servo:statusword servo:error_code".into());
    }

    // A UMPK: its flash programmed (and the controller reset to Work mode), an IL program.
    if umpk {
        setup.push("use umpk".into());
        if r.below(2) == 0 {
            setup.push(format!("umpk program {}; umpk reset", path("docs/umpk-demo.hex")));
        }
        if umpk_program {
            setup.push(format!("sim program load {}", path("scripts/umpk_lab1.il")));
            setup.push(format!("sim input I0=1; sim input I2 freq={}Hz", r.in_range(1, 20)));
            actions.push("use umpk; sim input I1=1".into());
            actions.push("use umpk; sim input I1=0".into());
            gets.push("umpk:Q0 umpk:Q1 umpk:Q2".into());
        }
        // Injected faults: an input stuck (for a while or until cleared), a failing flash
        // page. A line kept silent shows in the state compared, not by asking the silent line.
        for _ in 0..r.below(3) {
            setup.push(match r.below(4) {
                0 => format!("umpk sim fault stuck I{}={}", r.below(4), r.below(2)),
                1 => format!("umpk sim fault stuck I1=1 for={}", ms(&mut r, 1, 2_000)),
                2 => format!("umpk sim flash-fail {}", r.below(8)),
                _ => format!("umpk sim fault no-reply for={}", ms(&mut r, 1, 600)),
            });
        }
        actions.push("use umpk; umpk sim fault stuck I3=1 for=300ms".into());
        // Statistics a client reads: the longest program time (`umpk timing`).
        gets.push("umpk:I0 umpk:I1 umpk:I3".into());
    }

    // An FX PLC running its program.
    if fx {
        setup.push("use fx".into());
        setup.push(format!("sim program load {}", path("scripts/fx_blink.il")));
        if r.below(2) == 0 {
            setup.push("set X0=1".into());
        }
        actions.push("set fx:X1=1".into());
        actions.push("set fx:X1=0".into());
        actions.push("set fx:X0=1".into());
        // Injected faults (the control channel's words, applied in process): inputs stuck.
        for _ in 0..r.below(3) {
            setup.push(match r.below(2) {
                0 => format!("fx-control fault stuck X{}={}", r.below(2), r.below(2)),
                _ => format!("fx-control fault stuck X1=1 for={}", ms(&mut r, 1, 2_000)),
            });
        }
        // Statistics a program reads: the scan times D8010–D8012.
        gets.push("fx:Y0 fx:Y1 fx:Y2 fx:CS0 fx:D0 fx:TN0 fx:X0 fx:X1 fx:D8010 fx:D8011 fx:D8012".into());
    }

    // Run to the save: steps of random length with actions between them.
    for _ in 0..r.in_range(1, 3) {
        setup.push(format!("sim step {}", ms(&mut r, 0, 900)));
        if !actions.is_empty() && r.below(2) == 0 {
            setup.push(format!("? {}", actions[r.below(actions.len() as u64) as usize]));
        }
    }
    // A fresh session busy with something else before it restores.
    let mut noise = vec![format!("sim step {}", ms(&mut r, 0, 3_000))];
    if k2 && r.below(2) == 0 {
        noise.push(format!(
            "use plc; set VW10=7; sim program load {}; sim wire plc:Q0.3 -> plc:I0.6; set Q0.3=1; sim fault stuck I0.7=1",
            path("scripts/traffic_light.il")
        ));
    }
    if servo && r.below(2) == 0 {
        noise.push("servo enable; servo jog 100rpm; servo sim switch home 1234".into());
    }
    if umpk && r.below(2) == 0 {
        noise.push("use umpk; sim input I3=1".into());
    }
    if fx && r.below(2) == 0 {
        noise.push("use fx; set D100=5".into());
    }
    // After: the same actions and steps on both sides, then everything read.
    let mut after = Vec::new();
    for _ in 0..r.in_range(1, 4) {
        if !actions.is_empty() && r.below(2) == 0 {
            after.push(actions[r.below(actions.len() as u64) as usize].clone());
        }
        after.push(format!("sim step {}", ms(&mut r, 1, 1_500)));
    }
    after.push(format!("get {}", gets.join(" ")));
    if k2 {
        // `sim program` shows the scan count and SMW22/24/26's times.
        after.push("use plc; events keep; sim faults; sim wires; sim program".into());
        after.push("get plc:SMW22 plc:SMW24 plc:SMW26".into());
    }
    if umpk {
        after.push("use umpk; umpk sim faults; umpk sim events; umpk timing".into());
    }
    if fx {
        after.push("fx-control faults".into());
        after.push("fx-control events".into());
        after.push("use fx; sim program".into());
    }
    Case { seed, devices, setup, noise, after }
}

/// Builds and runs the case's machine, saves it, restores it into a fresh session and
/// continues both. Returns the saved file's text and the continued state's.
fn check(case: &Case, file: &std::path::Path) -> (String, String) {
    let mut a = case.shell();
    for line in &case.setup {
        match line.strip_prefix("? ") {
            Some(may_fail) => drop(run(&mut a, may_fail)),
            None => must(&mut a, line, case),
        }
    }
    let snap = Snapshot::capture(&mut a.session).unwrap_or_else(|e| panic!("{}\ncapture: {e}", case.describe()));
    snap.save(file).unwrap_or_else(|e| panic!("{}\nsave: {e}", case.describe()));
    let saved = std::fs::read_to_string(file).unwrap();

    let mut b = case.shell();
    for line in &case.noise {
        must(&mut b, line, case);
    }
    let loaded = Snapshot::load(file).unwrap_or_else(|e| panic!("{}\nload: {e}", case.describe()));
    loaded.restore(&mut b.session).unwrap_or_else(|e| panic!("{}\nrestore: {e}", case.describe()));
    let again = snapshot_text(&mut b, case);
    assert!(again == saved, "{}\nsave → restore → save differs at {}", case.describe(), difference(&saved, &again));

    for line in &case.after {
        let (ra, rb) = (run(&mut a, line), run(&mut b, line));
        assert_eq!(ra, rb, "{}\n`{line}` gives other results after the restore", case.describe());
    }
    let (sa, sb) = (snapshot_text(&mut a, case), snapshot_text(&mut b, case));
    assert!(sa == sb, "{}\nthe continued states differ at {}", case.describe(), difference(&sa, &sb));
    (saved, sa)
}

fn temp(name: &str) -> std::path::PathBuf {
    std::env::temp_dir().join(format!("plcsh-roundtrip-{}-{name}", std::process::id()))
}

#[test]
fn every_saved_machine_restores_and_continues_identically() {
    let base = 0x5A9E_0000_0000_0001u64;
    let file = temp("inproc.json");
    let mut devices = std::collections::BTreeSet::new();
    let mut wired = 0;
    for i in 0..100u64 {
        let case = generate(base.wrapping_add(i.wrapping_mul(0x9E37_79B9_7F4A_7C15)));
        let (saved, _) = check(&case, &file);
        devices.extend(case.devices.iter().map(|d| d.0));
        wired += usize::from(saved.contains("\"wiring\""));
    }
    let _ = std::fs::remove_file(&file);
    // The generator reaches every family and wired machines.
    assert_eq!(devices.len(), 4, "{devices:?}");
    assert!(wired >= 5, "only {wired} wired machines");
}

/// A machine saved in this process and restored by a new `plcsh` process, continued the
/// same way: the new process ends in the same state, byte for byte.
#[test]
fn a_new_plcsh_process_restores_and_continues_identically() {
    let mut done = 0;
    let mut seed = 0xC0FF_EE00_0000_0001u64;
    while done < 3 {
        seed = seed.wrapping_add(0x9E37_79B9_7F4A_7C15);
        let case = generate(seed);
        // A wired K2 and a drive at least (the richest state), and more when drawn.
        if !(case.has("plc") && case.has("servo") && case.setup.iter().any(|l| l.contains("sim wire plc:Q0.0"))) {
            continue;
        }
        done += 1;
        let (file, out) = (temp(&format!("{done}.json")), temp(&format!("{done}-after.json")));
        let (_, continued) = check(&case, &file);
        // Line by line on standard input, as in process: a failing command (an injected
        // fault) ends its line only.
        let mut lines = vec![format!("sim snapshot restore {}", file.display())];
        // The FX control words go to the in-process simulator only (they only read here).
        lines.extend(case.after.iter().filter(|l| !l.starts_with("fx-control ")).cloned());
        lines.push(format!("sim snapshot save {}", out.display()));
        let mut args = vec!["--time".to_string(), "stepped".into(), "--json".into()];
        for (n, u) in &case.devices {
            args.extend(["--device".to_string(), format!("{n}={u}")]);
        }
        let args: Vec<&str> = args.iter().map(String::as_str).collect();
        let o = common::run(&args, &(lines.join("\n") + "\n"));
        let text = std::fs::read_to_string(&out)
            .unwrap_or_else(|e| panic!("{}\n{e}: {}{}", case.describe(), common::stdout(&o), common::stderr(&o)));
        assert!(
            text == continued,
            "{}\nthe new process's state differs at {}",
            case.describe(),
            difference(&continued, &text)
        );
        let _ = std::fs::remove_file(&file);
        let _ = std::fs::remove_file(&out);
    }
}

/// Every saved field is restored or refused, mechanically: where a simulator's state is
/// saved, its state structs are taken apart whole — `let Struct { a, b, c: _ } = …` without
/// `..` — so a field added to a simulator does not compile until its snapshot code saves it
/// or names it as not the machine's state (with a comment saying why). This test keeps
/// those patterns in place: each exists and none has `..`. A drive is saved whole by serde
/// (every field, none skipped), as are the fault lists.
#[test]
fn each_simulator_state_struct_is_taken_apart_whole_where_it_is_saved() {
    let whole: &[(&str, &[&str])] = &[
        ("src/k2/sim/snapshot.rs", &["K2Sim", "Memory", "Backup", "Plc", "Loaded"]),
        ("src/k2/sim/pto.rs", &["PtoChannel"]),
        ("src/k2/sim/hsc/mod.rs", &["HscChannel"]),
        ("src/k2/sim/events.rs", &["EventLog"]),
        ("src/umpk/sim/snapshot.rs", &["Umpk", "Image"]),
        ("src/fx/snapshot.rs", &["Memory", "Cpu"]),
        ("src/servo/sim/mod.rs", &["SimLine"]),
        ("src/snapshot.rs", &["Harness", "Wire"]),
    ];
    for (file, structs) in whole {
        let text = std::fs::read_to_string(path(file)).unwrap();
        // Comments out: a `..` in one is not a rest pattern.
        let code: String = text.lines().map(|l| l.split("//").next().unwrap_or("").to_string() + "\n").collect();
        for name in *structs {
            let start = code
                .match_indices("let ")
                .map(|(i, _)| i + 4)
                .find(|&i| {
                    let head = code[i..].split('{').next().unwrap_or("");
                    head.trim().rsplit("::").next() == Some(*name) && !head.contains(['=', ';', '('])
                })
                .unwrap_or_else(|| {
                    panic!("{file}: no `let {name} {{ … }} = …` taking the state apart where it is saved")
                });
            let open = start + code[start..].find('{').unwrap();
            let mut depth = 0;
            let end = code[open..]
                .char_indices()
                .find_map(|(i, c)| {
                    depth += match c {
                        '{' => 1,
                        '}' => -1,
                        _ => 0,
                    };
                    (depth == 0).then_some(open + i)
                })
                .unwrap();
            let pattern = &code[open..=end];
            assert!(!pattern.contains(".."), "{file}: `let {name} {pattern} = …` must name every field, without `..`");
        }
    }
    for (file, ty) in [
        ("src/servo/sim/drive.rs", "pub struct Drive {"),
        ("src/core/sim_faults.rs", "pub struct Faults {"),
        ("src/k2/sim/fault.rs", "pub struct Faults {"),
        ("src/core/wiring.rs", "pub struct WireState {"),
    ] {
        let text = std::fs::read_to_string(path(file)).unwrap();
        let at = text.find(ty).unwrap_or_else(|| panic!("{file}: no `{ty}`"));
        let derive = text[..at].rsplit("#[derive(").next().unwrap();
        assert!(derive.contains("Serialize") && derive.contains("Deserialize"), "{file}: {ty} is saved by serde");
        let body = &text[at..at + text[at..].find("\n}").unwrap()];
        assert!(!body.contains("serde(skip"), "{file}: {ty} skips a field a snapshot would then leave out");
    }
}
