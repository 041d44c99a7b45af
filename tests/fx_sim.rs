//! The simulated FX PLC as a PLC in RUN, driven through the real binary: the user guide's example (docs/fx.md)
//! (run exactly as printed), the clock relay M8013 and the initial pulse in stepped time,
//! timers reaching their preset, RUN/STOP, refused writes and names; and a served FX PLC
//! running a program whose timer value both ports read (loopback TCP, port 0, readiness line).

mod common;
use common::*;
use plcsh::core::Value;

/// The `-c` argument of the README's FX example that loads `scripts/fx_blink.il`.
fn readme_example() -> String {
    let readme = std::fs::read_to_string(concat!(env!("CARGO_MANIFEST_DIR"), "/docs/fx.md")).unwrap();
    let line = readme
        .lines()
        .find(|l| l.starts_with("plcsh --time stepped -d fx=sim-fx:FX2N -c \"use fx; sim program load"))
        .expect("the FX program example of docs/fx.md");
    line.split('"').nth(1).unwrap().to_string()
}

#[test]
fn the_readme_example_blinks_y0_and_times_t0() {
    let cmd = readme_example();
    let o = run(&["--time", "stepped", "--json", "-d", "fx=sim-fx:FX2N", "-c", &cmd], "");
    assert!(o.status.success(), "{}", both(&o));
    let l = json_lines(&o);
    let gets: Vec<&serde_json::Value> = l.iter().filter(|v| v["cmd"] == "get").collect();
    let vals = |k: usize| -> serde_json::Value {
        gets[k]["values"].as_array().unwrap().iter().map(|v| v["value"].clone()).collect()
    };
    // At 0.6 s: M8013 is in its off half, Y0 follows it, the first scan is over, a scan takes 0.5 ms.
    assert_eq!(vals(0), serde_json::json!([false, false, false, 5]), "{}", stdout(&o));
    // X0 on at 0.6 s; 3.1 s later T0 (K30 × 100 ms) has reached its preset and Y1 follows it.
    assert_eq!(vals(1), serde_json::json!([30, true, true]), "{}", stdout(&o));
}

#[test]
fn m8013_toggles_every_half_second_and_m8002_is_the_first_scan_only() {
    // 10 s in 250 ms steps, starting a quarter period in.
    let mut cmd = String::from("use fx; get M8002 M8013; sim step 250ms");
    for _ in 0..40 {
        cmd.push_str("; get M8013 M8002; sim step 250ms");
    }
    let o = run(&["--time", "stepped", "--json", "-d", "fx=sim-fx:FX2N", "-c", &cmd], "");
    assert!(o.status.success(), "{}", both(&o));
    let gets: Vec<serde_json::Value> = json_lines(&o).into_iter().filter(|v| v["cmd"] == "get").collect();
    assert_eq!(gets[0]["values"][0]["value"], true, "M8002 in the first scan");
    let m8013: Vec<bool> = gets[1..].iter().map(|g| g["values"][0]["value"].as_bool().unwrap()).collect();
    assert_eq!(m8013.len(), 40);
    for (k, v) in m8013.iter().enumerate() {
        // At 250 ms + k·250 ms: on in the first half of each second.
        let t = 250 + 250 * k as u64;
        assert_eq!(*v, t % 1000 < 500, "M8013 at {t} ms");
        assert_eq!(gets[1 + k]["values"][1]["value"], false, "M8002 after the first scan ({t} ms)");
    }
}

#[test]
fn run_stop_refused_writes_and_fx_names() {
    let o = run(
        &[
            "--time",
            "stepped",
            "-d",
            "fx=sim-fx:FX2N",
            "-c",
            "use fx; sim cpu stop; get M8000 M8001; sim cpu run; get M8000 T0 K4Y0/DINT; sim step 1s; get D8010",
        ],
        "",
    );
    let out = both(&o);
    assert!(o.status.success(), "{out}");
    assert!(out.contains("FX2N in STOP") && out.contains("FX2N in RUN"), "{out}");
    assert!(out.contains("TS0 ") && out.contains("K4Y0/DINT"), "T0 reads the contact: {out}");
    for (cmd, want) in [
        ("use fx; set M8000=0", "M8000 — RUN monitor (on while the PLC runs) — is driven by the PLC"),
        ("use fx; set D8012=0", "is driven by the PLC"),
        ("use fx; set Y8=1", "Y numbers are octal (Y0–Y7, Y10–Y17"),
        ("use fx; sim cpu pause", "no PAUSE"),
        ("use fx; sim scan 3", "`sim scan` is not available on an FX PLC"),
        ("use fx; set K4Y0/DINT=70000", "out of range"),
        ("use fx; help T250", "100 ms timer, retentive"),
    ] {
        let o = run(&["--time", "stepped", "-d", "fx=sim-fx:FX2N", "-c", cmd], "");
        assert!(both(&o).contains(want), "{cmd}: {}", both(&o));
    }
    // After a refused write M8000 is still on (the REPL goes on after an error).
    let o = run(&["--time", "stepped", "--json", "-d", "fx=sim-fx:FX2N"], "use fx\nset M8000=0\nget M8000\n");
    let l = json_lines(&o);
    assert_eq!(l.last().unwrap()["values"][0]["value"], true, "{}", both(&o));
}

#[test]
fn a_program_that_does_not_load_names_the_fx_line() {
    let dir = std::env::temp_dir().join(format!("plcsh-fxsim-{}", std::process::id()));
    std::fs::create_dir_all(&dir).unwrap();
    let p = dir.join("bad.il");
    std::fs::write(&p, "LD X0\nOUT T0 K10\nLD T0\nOUTT Y0\n").unwrap();
    let cmd = format!("use fx; sim program load {}", p.display());
    let o = run(&["--time", "stepped", "-d", "fx=sim-fx:FX2N", "-c", &cmd], "");
    let out = both(&o);
    assert!(!o.status.success(), "{out}");
    assert!(out.contains("bad.il:4:1: unknown FX instruction OUTT") && out.contains("did you mean OUT"), "{out}");
}

/// A served FX PLC running a program: the timer's current value, read over the programming
/// port and the computer link, is one value that grows with time.
#[test]
fn both_served_ports_read_the_running_timer() {
    let dir = std::env::temp_dir().join(format!("plcsh-fxsim-serve-{}", std::process::id()));
    std::fs::create_dir_all(&dir).unwrap();
    let p = dir.join("count.il");
    std::fs::write(&p, "LD M8000\nOUT T0 K32000\nLD M8002\nMOV K77 D0\n").unwrap();
    let served =
        serve(&["--fx-tcp", "127.0.0.1:0", "--fx-link-tcp", "127.0.0.1:0", "--fx-program", p.to_str().unwrap()]);
    let addr = |k: &str| served.ready[k].as_str().unwrap_or_else(|| panic!("{k} in {}", served.ready)).to_string();
    assert!(served.ready["fx_program"].as_str().is_some_and(|s| s.ends_with("count.il")));
    let mut port = open_device(&format!("fx+tcp://{}?model=FX2N", addr("fx_tcp")));
    let mut link = open_device(&format!("fxlink+tcp://{}?model=FX2N", addr("fx_link_tcp")));
    let tn = |d: &mut Box<dyn plcsh::core::Device>| {
        let ops = operands(d.as_ref(), &["TN0", "D0", "M8000"]);
        let v = d.read(&ops).unwrap();
        (v[0].as_i64(), v[1].as_i64(), v[2])
    };
    let (a, d0, run) = tn(&mut port);
    assert_eq!((d0, run), (77, Value::Bool(true)), "the program ran its first scan; the PLC is in RUN");
    // The timer counts in 100 ms units: wait (polling, with a deadline) until it has moved.
    let deadline = std::time::Instant::now() + std::time::Duration::from_secs(10);
    let mut b = a;
    while b < a + 2 {
        assert!(std::time::Instant::now() < deadline, "TN0 stays at {b}");
        b = tn(&mut link).0;
    }
    let c = tn(&mut port).0;
    assert!(c >= b, "the port reads the same timer the link read: {b} then {c}");
}

/// A snapshot holds the FX PLC's image, CPU and program: the same script after a restore
/// (the program unloaded and the inputs changed in between) gives the same results.
#[test]
fn a_snapshot_carries_the_fx_program_its_timers_and_counters() {
    let dir = std::env::temp_dir().join(format!("plcsh-fxsim-snap-{}", std::process::id()));
    let script = "sim step 2s; get Y0 Y1 TN0 CN0 D8010; sim step 1.7s; get Y0 Y1 TN0 CN0 Y2";
    let cmds = format!(
        "use fx; sim program load scripts/fx_blink.il; sim step 1.3s; set X0=1; sim snapshot save fxs; {script}; \
         sim program unload; set X0=0, TN0=0; sim step 1s; sim snapshot restore fxs; {script}; sim program"
    );
    let o = plcsh()
        .env("PLCSH_SNAPSHOTS", &dir)
        .args(["--time", "stepped", "--json", "-d", "fx=sim-fx:FX2N", "-c", &cmds])
        .stdin(std::process::Stdio::null())
        .output()
        .unwrap();
    assert!(o.status.success(), "{}", both(&o));
    let l = json_lines(&o);
    let gets: Vec<&serde_json::Value> = l.iter().filter(|v| v["cmd"] == "get").collect();
    assert_eq!(gets.len(), 4, "{}", stdout(&o));
    assert_eq!(gets[0]["values"], gets[2]["values"], "{}", stdout(&o));
    assert_eq!(gets[1]["values"], gets[3]["values"], "{}", stdout(&o));
    // Not trivial: T0 reached its preset (Y1) and C0 counted between the reads.
    assert_eq!(gets[0]["values"][1]["value"], false);
    assert_eq!(gets[1]["values"][1]["value"], true, "{}", stdout(&o));
    assert_ne!(gets[0]["values"][3], gets[1]["values"][3]);
    assert_eq!(l.last().unwrap()["program"], "fx_blink.il", "the program came back");
    let _ = std::fs::remove_dir_all(&dir);
}
