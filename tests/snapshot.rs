//! Snapshots: save, run a script, restore, run it again — identical values and event logs,
//! for the K2 (a counter fed by a quadrature signal, a pulse train, memory) and a servo
//! drive mid-move, in stepped time.

mod common;
use common::*;
use std::process::Stdio;

const SCRIPT: &str = "sim step 250ms; get SMD38 SMB66 VW10 Q0.0; get servo:position_actual servo:statusword; \
    sim step 2s; get SMD38 SMB66 VW10; get servo:position_actual servo:statusword; events keep";

fn results(lines: &[serde_json::Value]) -> Vec<serde_json::Value> {
    lines.iter().filter(|v| v["cmd"] == "get" || v["cmd"] == "events").cloned().collect()
}

#[test]
fn the_same_script_from_the_same_snapshot_gives_identical_results() {
    let dir = std::env::temp_dir().join(format!("plcsh-snapshots-{}", std::process::id()));
    let setup = "set VW10=42; hsc 0 mode=9 rate=4x pv=[100,200,300] relative at VB3009 cv=0; \
        sim quad I0.1 I0.0 freq=1kHz; pto 0 freq=2kHz count=1000; \
        servo enable; servo move rel 10rev speed=300rpm; sim step 100ms";
    let cmds = format!("{setup}; sim snapshot save lab1; {SCRIPT}; sim snapshot restore lab1; {SCRIPT}; sim snapshots");
    let o = plcsh()
        .env("PLCSH_SNAPSHOTS", &dir)
        .args(["--time", "stepped", "--json", "-c", &cmds])
        .stdin(Stdio::null())
        .output()
        .unwrap();
    assert!(o.status.success(), "{}", stdout(&o));
    let l = json_lines(&o);
    let r = results(&l);
    assert_eq!(r.len(), 10, "{}", stdout(&o));
    let (first, second) = r.split_at(5);
    assert_eq!(first, second, "same snapshot, same script, same results");
    // The state is not trivial: counts, pulses, motion and events happened after the save.
    let text = serde_json::to_string(first).unwrap();
    assert!(text.contains("pto0-done") && text.contains("hsc0-pv3"), "{text}");
    let pos = |v: &serde_json::Value| v["values"][0]["value"].as_i64().unwrap_or_else(|| panic!("{v}"));
    assert!(pos(&first[3]) > pos(&first[1]), "the drive was moving after the save: {text}");
    assert!(l.iter().any(|v| v["snapshots"] == serde_json::json!(["lab1"])), "{}", stdout(&o));
    let _ = std::fs::remove_dir_all(&dir);
}

#[test]
fn a_snapshot_from_a_newer_plcsh_or_of_another_model_is_refused() {
    let dir = std::env::temp_dir().join(format!("plcsh-snapshots-bad-{}", std::process::id()));
    let run = |args: &[&str], cmds: &str| {
        plcsh().env("PLCSH_SNAPSHOTS", &dir).args(args).args(["-c", cmds]).stdin(Stdio::null()).output().unwrap()
    };
    let o = run(&["--time", "stepped"], "set VW0=1; sim snapshot save a");
    assert!(o.status.success(), "{}", stdout(&o));
    let o = run(&["--time", "stepped", "--model", "K209M-56DT"], "sim snapshot restore a");
    assert!(!o.status.success());
    assert!(stderr(&o).contains("the snapshot is of a K205-16DT, this simulator is a K209M-56DT"), "{}", stderr(&o));
    assert!(stderr(&o).contains("plc=sim:K205-16DT"), "the hint says how to open it: {}", stderr(&o));
    let file = dir.join("a.json");
    let text = std::fs::read_to_string(&file).unwrap();
    let mut v: serde_json::Value = serde_json::from_str(&text).unwrap();
    v["devices"]["plc"]["sections"]["program"] = serde_json::json!({});
    std::fs::write(dir.join("b.json"), v.to_string()).unwrap();
    let o = run(&["--time", "stepped"], "sim snapshot restore b");
    assert!(stderr(&o).contains("has a `program` section this plcsh cannot restore"), "{}", stderr(&o));
    let _ = std::fs::remove_dir_all(&dir);
}

/// Human-readable errors go to stderr.
fn stderr(o: &std::process::Output) -> String {
    String::from_utf8_lossy(&o.stderr).into_owned()
}

/// A snapshot holds the simulated CPU: its program (recompiled from the saved text), the
/// program's timers and mode, so a lab started from it runs on from where it was saved.
#[test]
fn a_snapshot_carries_the_running_program_and_its_timers() {
    let dir = std::env::temp_dir().join(format!("plcsh-snapshots-prog-{}", std::process::id()));
    let il = concat!(env!("CARGO_MANIFEST_DIR"), "/scripts/traffic_light.il");
    let script = "sim step 3s; get Q0.0 Q0.1 Q0.2 T37 T38; sim step 4s; get Q0.0 Q0.1 Q0.2 T37 T38 T39";
    let cmds = format!(
        "sim program load {il}; set I0.0=1; sim step 2s; sim snapshot save prog; {script}; \
         sim program unload; sim step 1s; sim snapshot restore prog; {script}"
    );
    let o = plcsh()
        .env("PLCSH_SNAPSHOTS", &dir)
        .args(["--time", "stepped", "--json", "-c", &cmds])
        .stdin(Stdio::null())
        .output()
        .unwrap();
    assert!(o.status.success(), "{}{}", stdout(&o), String::from_utf8_lossy(&o.stderr));
    let l = json_lines(&o);
    let r = results(&l);
    assert_eq!(r.len(), 4, "{}", stdout(&o));
    let (first, second) = r.split_at(2);
    assert_eq!(first, second, "the restored program runs on exactly as it did");
    // Not trivial: the light changed between the two reads (red for 5 s, then green).
    assert_ne!(first[0]["values"][0], first[1]["values"][0], "{}", stdout(&o));
    let _ = std::fs::remove_dir_all(&dir);
}

/// The wired machine (PTO0 → drive → encoder → HSC0, a drive output, a home switch, a
/// delayed loopback) saved mid-move: the same script after a restore gives identical
/// results, in the same process and in a fresh one whose wires were all removed first —
/// the wires and what they carry come back from the snapshot.
#[test]
fn a_wired_machine_restored_mid_move_continues_identically() {
    let dir = std::env::temp_dir().join(format!("plcsh-snapshots-wired-{}", std::process::id()));
    let bench = concat!(env!("CARGO_MANIFEST_DIR"), "/machines/pto_servo_encoder.toml");
    let script = "sim step 50ms; get SMD38 servo:position_actual I0.3 I0.4 I0.5 SMD212; \
        sim step 1s; get SMD38 servo:position_actual I0.3 I0.4 I0.5 SMD212; events keep";
    let run = |cmds: &str| {
        let o = plcsh()
            .env("PLCSH_SNAPSHOTS", &dir)
            .args(["--time", "stepped", "--json", "--bench", bench, "-c", cmds])
            .stdin(Stdio::null())
            .output()
            .unwrap();
        assert!(o.status.success(), "{}{}", stdout(&o), stderr(&o));
        json_lines(&o)
    };
    let setup = "sim wire plc:Q0.1 -> plc:I0.3 delay=2ms; hsc 0 mode=9 rate=4x; \
        pto 0 freq=20kHz count=8000; pto 1 freq=100Hz count=50; sim step 100ms";
    let l = run(&format!("{setup}; sim snapshot save wired; {script}; sim snapshot restore wired; {script}"));
    let r = results(&l);
    assert_eq!(r.len(), 6, "{l:?}");
    let (first, second) = r.split_at(3);
    assert_eq!(first, second, "same snapshot, same script, same results");
    let val = |v: &serde_json::Value, i: usize| v["values"][i]["value"].as_i64().unwrap_or_else(|| panic!("{v}"));
    // Mid-move after the save (0.15 s of 0.4 s), then done: 8000 pulses × gear 4, 1250 lines.
    assert!(val(&first[0], 1) > 8_000 && val(&first[0], 1) < 32_000, "{:?}", first[0]);
    assert_eq!(val(&first[0], 0), val(&first[0], 1) / 2, "encoder counts follow the drive");
    assert_eq!((val(&first[1], 0), val(&first[1], 1)), (16_000, 32_000));
    assert_eq!(first[1]["values"][3]["value"], true, "past the home switch: {:?}", first[1]);
    // A fresh process, its wires removed: the restore brings them (and their state) back.
    let l = run(&format!("sim unwire all; sim snapshot restore wired; sim wires; {script}"));
    let wires = |l: &[serde_json::Value]| l.iter().rev().find_map(|v| v.get("wires").cloned()).unwrap_or_default();
    assert_eq!(wires(&l).as_array().map(Vec::len), Some(5), "{l:?}");
    assert_eq!(results(&l), first, "a fresh process continues identically");
    // A snapshot saved with no wires removes the PLC's wires when restored.
    let l = run("sim unwire all; sim snapshot save bare; sim wire plc:Q0.0 -> servo:pulse; sim snapshot restore bare; sim wires");
    assert_eq!(wires(&l), serde_json::json!([]), "{l:?}");
}
