//! The real binary on the K2's special functions: pulse outputs in stepped time,
//! helpers returning their register writes, events, waits, and state that survives a restart.

mod common;
use common::*;

fn tmp(name: &str) -> std::path::PathBuf {
    let d = std::env::temp_dir().join(format!("plcsh-motion-{name}-{}", std::process::id()));
    let _ = std::fs::remove_dir_all(&d);
    std::fs::create_dir_all(&d).unwrap();
    d
}

#[test]
fn pls_in_stepped_time_finishes_after_500ms_with_event_28() {
    let o = run(
        &[
            "--time",
            "stepped",
            "--json",
            "-c",
            "set SMB67=16#85, SMW68=500, SMD72=1000; pls 0; sim step 499ms; get SM66.7; sim step 2ms; get SM66.7 SMD212; events",
        ],
        "",
    );
    assert!(o.status.success(), "{}", stdout(&o));
    let l = json_lines(&o);
    assert_eq!(l[1]["cmd"], "pls");
    assert_eq!(l[3]["values"][0]["value"], false, "busy after 499 ms");
    assert_eq!(l[5]["values"][0]["value"], true, "SM66.7 = 1 after 501 ms");
    assert_eq!(l[5]["values"][1]["value"], 1000);
    let ev = &l[6]["events"];
    assert_eq!(ev.as_array().unwrap().len(), 1);
    assert_eq!(ev[0]["number"], 28);
    assert_eq!(ev[0]["time_us"], 500_000);
    assert_eq!(ev[0]["name"], "pto0-done");
}

#[test]
fn helpers_return_the_register_writes() {
    let o = run(
        &["--time", "stepped", "--json", "-c", "pto 0 freq=2kHz count=1000; wait event 28 timeout=2s; sim time"],
        "",
    );
    assert!(o.status.success(), "{}", stdout(&o));
    let l = json_lines(&o);
    let w: Vec<(String, i64)> = l[0]["writes"]
        .as_array()
        .unwrap()
        .iter()
        .map(|w| (w["operand"].as_str().unwrap().to_string(), w["value"].as_i64().unwrap()))
        .collect();
    assert_eq!(w, vec![("SMB67".into(), 0x85), ("SMW68".into(), 500), ("SMD72".into(), 1000)]);
    assert_eq!(l[1]["event"]["number"], 28);
    assert_eq!(l[1]["waited_us"], 500_000, "the stepped clock jumped straight to the event");
    assert_eq!(l[2]["time_us"], 500_000);
    let o = run(&["--json", "-c", "hsc 0 mode=9 rate=4x pv=[100,200,300] relative cyclic at VB3009"], "");
    let l = json_lines(&o);
    let ops: Vec<&str> = l[0]["writes"].as_array().unwrap().iter().map(|w| w["operand"].as_str().unwrap()).collect();
    assert_eq!(ops, vec!["SMB37", "VB3009", "VD3010/DINT", "VD3014/DINT", "VD3018/DINT", "SMW142", "SMB141"]);
}

#[test]
fn wait_times_out_in_virtual_time_and_errors_name_what_to_try() {
    let o = run(&["--time", "stepped", "--json", "-c", "wait event 28 timeout=2s; sim time"], "");
    let l = json_lines(&o);
    assert_eq!(l[0]["error"]["kind"], "timeout");
    assert_eq!(l.len(), 1, "the line stops at the failed command");
    let o = run(&["--json", "-c", "set SMB77=16#85, SMW78=500, SMD82=1000; pls 0"], "");
    let l = json_lines(&o);
    assert_eq!(l[1]["error"]["kind"], "state");
    assert!(l[1]["error"]["hint"].as_str().unwrap().contains("PLS 1"), "{}", l[1]);
    let o = run(&["--json", "--model", "K205-16DR", "-c", "pto 0 freq=1kHz count=10"], "");
    let l = json_lines(&o);
    assert_eq!(l[0]["error"]["kind"], "unsupported");
    let o = run(&["-c", "profile 0 at VB3000 [(cycle=500us, count=1000)]"], "");
    assert!(common::stderr(&o).contains("even"), "{}", both(&o));
}

#[test]
fn backup_area_and_clock_survive_a_restart_with_state() {
    let d = tmp("state");
    let state = d.join("state.json");
    let s = state.to_str().unwrap();
    let o = run(&["--state", s, "-c", "set VB3700=42, VB3903=1, VB100=7; rtc set 2030-01-01T00:00:00"], "");
    assert!(o.status.success(), "{}", stdout(&o));
    assert!(state.exists());
    let o = run(&["--state", s, "--json", "-c", "get VB3700 VB3903 VB100; rtc"], "");
    let l = json_lines(&o);
    let v: Vec<i64> = l[0]["values"].as_array().unwrap().iter().map(|v| v["value"].as_i64().unwrap()).collect();
    assert_eq!(v, vec![42, 0, 0], "the backup area is restored; VB3903 (outside by default) and VB100 are not");
    assert!(l[1]["rtc"].as_str().unwrap() >= "2030-01-01T00:00:00", "{}", l[1]);
    assert!(l[1]["rtc"].as_str().unwrap() < "2030-01-02T00:00:00");
}

#[test]
fn eeprom_dump_and_restore_through_a_file() {
    let d = tmp("eeprom");
    let (a, b) = (d.join("a.json"), d.join("b.json"));
    let dump = d.join("backup.bin");
    let o = run(
        &["--state", a.to_str().unwrap(), "-c", &format!("set VB3648=1, VB3902=2; eeprom dump {}", dump.display())],
        "",
    );
    assert!(o.status.success(), "{}", stdout(&o));
    let bytes = std::fs::read(&dump).unwrap();
    assert_eq!(bytes.len(), 255);
    assert_eq!((bytes[0], bytes[254]), (1, 2));
    let o = run(
        &[
            "--state",
            b.to_str().unwrap(),
            "--json",
            "-c",
            &format!("eeprom restore {}; get VB3648 VB3902; eeprom status", dump.display()),
        ],
        "",
    );
    let l = json_lines(&o);
    assert_eq!(l[1]["values"][0]["value"], 1);
    assert_eq!(l[1]["values"][1]["value"], 2);
    assert_eq!(l[2]["hottest"]["writes"], 1, "restoring wrote each byte once");
}

#[test]
fn profile_plan_draws_the_ramp_and_writes_nothing() {
    let svg = std::env::temp_dir().join(format!("plcsh-plan-{}.svg", std::process::id()));
    let cmd = format!(
        "profile 0 at VB3001 [(freq=1kHz, count=100), (freq=5kHz, count=2000)] plan to={}; get SMW168 VB3001",
        svg.display()
    );
    let o = run(&["--time", "stepped", "-c", &cmd], "");
    let text = stdout(&o);
    assert!(
        text.contains("PTO0 frequency (Hz)") && text.contains('┤') && text.contains('⠉'),
        "a terminal chart: {text}"
    );
    assert!(text.contains("2100 pulses"), "{text}");
    let pic = std::fs::read_to_string(&svg).expect("the SVG was written");
    assert!(pic.starts_with("<svg") && pic.contains("PTO0 frequency"));
    let _ = std::fs::remove_file(&svg);
    let o = run(&["--time", "stepped", "--json", "-c", &cmd], "");
    let l = json_lines(&o);
    assert_eq!(l[0]["timeline"]["total_pulses"], 2100);
    assert_eq!(l[1]["values"][0]["value"], 0, "plan wrote nothing: SMW168 still 0");
    assert_eq!(l[1]["values"][1]["value"], 0, "nor the table");
}
