//! A teacher's lab on a wired machine, end to end: the start state is saved with plcsh from
//! the bench `machines/pto_servo_encoder.toml` (a K2 whose PTO0 drives a servo in
//! pulse-train mode, the servo's encoder counted by HSC0, its "target reached" output and a
//! home switch on PLC inputs), with the counter set up and the axis at rest. `plcsh lab check`
//! and `plcsh lab grade` then restore that snapshot for every submission: the reference and
//! a student's correct solution in another style get full marks, planted mistakes lose the
//! criteria that catch them. The grader also saves and restores a snapshot of its own in Lua
//! (`plcsh.snapshot_save` / `plcsh.snapshot_restore`) to run a second scenario from the same
//! start.

mod common;
use common::*;
use std::path::{Path, PathBuf};

fn temp(name: &str) -> PathBuf {
    let d = std::env::temp_dir().join(format!("plcsh-labsnap-{}-{name}", std::process::id()));
    let _ = std::fs::remove_dir_all(&d);
    std::fs::create_dir_all(&d).unwrap();
    d
}

const LAB_TOML: &str = r#"# The axis lab: a PABS move on the wired bench, started from a saved state.
title = "Axis move with encoder feedback"
bench = "bench.toml"
reference = "reference.il"
grader = "grade.lua"
snapshot = "start.json"
device = "plc"

[budget]
sim_time = "1min"

[points]
"program loads" = 1
"at rest before the button" = 1
"lamp off while moving" = 2
"moves 8000 pulses" = 3
"lamp when done" = 2
"no move without the button" = 1
"#;

/// A press of I0.2 moves axis 0 to 8000 pulses with PABS (K2 manual §3.4.3); Q0.1 lights
/// once the move is done and the drive reports the target reached on I0.5.
const REFERENCE: &str = r#"(* Axis lab, reference solution. *)

(* Network 1: the move's parameters: 200 Hz to 20 kHz in 100 ms, to 8000 pulses *)
LD      %SM0.1
MOVE    200, %VW0
MOVE    DI#20000, %VD2
MOVE    100, %VW6
MOVE    DI#8000, %VD8

(* Network 2: the move, started by the button's rising edge *)
LD      %SM0.0
PABS    0, %I0.2, %VW0, %VD2, %VW6, %VD8, %M0.1, %M0.2, %MB1

(* Network 3: the done lamp *)
LD      %M0.1
A       %I0.5
=       %Q0.1
"#;

const GRADER: &str = r#"-- Grader of the axis lab. The start snapshot holds the bench at rest with HSC0 counting
-- the encoder (mode 9, 4x): 8000 pulses × gear 4 = 32000 increments = 16000 counts
-- (1250 lines per 10000 increments, 4 counts a line).
local plc, servo = plcsh.device("plc"), plcsh.device("servo")
local loaded, why = lab.run()
lab.criterion("program loads", 1, function()
  if not loaded then return false, why, "a program that loads" end
end)
if not loaded then return end
-- The program loaded, at rest: a second scenario starts from here.
local start = plcsh.snapshot_save(plcsh.write_dir .. "/loaded.json")

plcsh.sleep(100)
lab.criterion("at rest before the button", 1, function()
  lab.expect(servo.position_actual, 0, "drive position before the button")
  lab.expect(plc.SMD38, 0, "encoder count before the button")
  lab.expect(plc["Q0.1"], false, "Q0.1 before the button")
end)

plc["I0.2"] = true
plcsh.sleep(50)
plc["I0.2"] = false
lab.criterion("lamp off while moving", 2, function()
  lab.expect(plc["Q0.1"], false, "Q0.1 50 ms into the move")
end)

plcsh.sleep(2000)
lab.criterion("moves 8000 pulses", 3, function()
  lab.expect(servo.position_actual, 32000, "drive position after the move")
  lab.expect(plc.SMD38, 16000, "encoder count after the move")
  lab.expect(plc["I0.4"], true, "home switch (at 20000) passed")
end)
lab.criterion("lamp when done", 2, function()
  lab.expect(plc["Q0.1"], true, "Q0.1 after the move")
end)

plcsh.snapshot_restore(start)
plcsh.sleep(1000)
lab.criterion("no move without the button", 1, function()
  lab.expect(servo.position_actual, 0, "drive position 1 s after the restart, no button")
  lab.expect(plc["Q0.1"], false, "Q0.1 1 s after the restart, no button")
end)
"#;

/// A correct solution in another style: the lamp latched with S/R, the position in VD100.
const STUDENT_OK: &str = r#"LD      %SM0.1
MOVE    500, %VW0
MOVE    DI#15000, %VD2
MOVE    50, %VW6
MOVE    DI#8000, %VD100
R       %Q0.1, 1

LD      %SM0.0
PABS    0, %I0.2, %VW0, %VD2, %VW6, %VD100, %M1.0, %M1.1, %MB2

LD      %M1.0
A       %I0.5
S       %Q0.1, 1
"#;

fn write(dir: &Path, name: &str, text: &str) {
    std::fs::write(dir.join(name), text).unwrap();
}

#[test]
fn a_lab_started_from_a_wired_bench_snapshot_grades_a_correct_submission_full_marks() {
    let d = temp("axis");
    let lab = d.join("axis");
    std::fs::create_dir_all(&lab).unwrap();
    std::fs::copy(
        Path::new(env!("CARGO_MANIFEST_DIR")).join("machines/pto_servo_encoder.toml"),
        lab.join("bench.toml"),
    )
    .unwrap();
    write(&lab, "lab.toml", LAB_TOML);
    write(&lab, "reference.il", REFERENCE);
    write(&lab, "grade.lua", GRADER);

    // The teacher saves the start state from the bench: HSC0 set up, the axis at rest.
    let start = lab.join("start.json");
    let o = plcsh()
        .args(["--time", "stepped", "--bench", lab.join("bench.toml").to_str().unwrap()])
        .args(["-c", &format!("hsc 0 mode=9 rate=4x; sim step 10ms; sim snapshot save {}", start.display())])
        .output()
        .unwrap();
    assert!(o.status.success(), "{}", both(&o));
    let text = std::fs::read_to_string(&start).unwrap();
    // A wired machine at rest: its encoder's signal is a stretch without end.
    assert!(text.contains(r#""wiring""#) && text.contains(r#""dur":"inf""#), "{text}");

    // The reference gets every point.
    let o = plcsh().args(["lab", "check", lab.to_str().unwrap()]).output().unwrap();
    assert!(o.status.success(), "{}", both(&o));
    assert!(stdout(&o).contains("the reference solution gets 10/10 points"), "{}", stdout(&o));

    // Students: a correct solution in another style, and two planted mistakes.
    let subs = d.join("submissions");
    std::fs::create_dir_all(&subs).unwrap();
    write(&subs, "ok_latched.il", STUDENT_OK);
    write(&subs, "short_move.il", &REFERENCE.replace("DI#8000", "DI#4000"));
    write(&subs, "lamp_early.il", &REFERENCE.replace("LD      %M0.1\nA       %I0.5", "LD      %SM0.0"));
    let o = plcsh().args(["--json", "lab", "grade", lab.to_str().unwrap(), subs.to_str().unwrap()]).output().unwrap();
    assert!(o.status.success(), "{}", both(&o));
    let lines = json_lines(&o);
    let report = |student: &str| {
        lines.iter().find(|l| l["student"] == student).unwrap_or_else(|| panic!("{student}: {}", stdout(&o))).clone()
    };
    let failed = |r: &serde_json::Value| -> Vec<String> {
        r["criteria"]
            .as_array()
            .unwrap()
            .iter()
            .filter(|c| c["passed"] != true)
            .map(|c| c["name"].as_str().unwrap().to_string())
            .collect()
    };
    let ok = report("ok_latched");
    assert_eq!((ok["verdict"].as_str(), ok["points"].as_f64()), (Some("passed"), Some(10.0)), "{ok}");
    let short = report("short_move");
    assert_eq!(failed(&short), ["moves 8000 pulses"], "{short}");
    assert_eq!(short["points"].as_f64(), Some(7.0), "{short}");
    let early = report("lamp_early");
    assert_eq!(
        failed(&early),
        ["at rest before the button", "lamp off while moving", "no move without the button"],
        "{early}"
    );
    std::fs::remove_dir_all(&d).unwrap();
}
