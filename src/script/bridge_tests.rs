//! One test per family of bridged helpers: each method is called from Lua, and the table it returns is checked against
//! the simulator's state as Rust reads it (session reads, not the Lua side).

use super::*;
use serde_json::{json, Value as J};

fn setup_with_servo() -> (Shell, Engine, Buf) {
    let (mut sh, e, buf) = setup();
    sh.session.open("servo", "sim-servo:?id=1").unwrap();
    sh.session.use_device("plc").unwrap();
    (sh, e, buf)
}

/// The values a chunk returns, as JSON.
fn lua(sh: &mut Shell, e: &Engine, code: &str) -> J {
    match run(sh, e, code) {
        Ok(o) => o.data.get("results").cloned().unwrap_or(J::Null),
        Err(f) => panic!("{code}: {}", f.human()),
    }
}

/// Every write a helper reports is what the device now holds.
fn writes_hold(sh: &mut Shell, r: &J) -> Vec<(String, i64)> {
    let mut out = Vec::new();
    for w in r["writes"].as_array().expect("writes") {
        let op = w["operand"].as_str().unwrap();
        let v = w["value"].as_i64().unwrap();
        assert_eq!(get(sh, op), v, "{op} holds what the helper reported");
        out.push((op.to_string(), v));
    }
    out
}

/// Every value a status helper reports is what the device holds.
fn values_hold(sh: &mut Shell, r: &J) {
    for v in r["values"].as_array().expect("values") {
        let op = v["operand"].as_str().unwrap();
        assert_eq!(get(sh, op), v["value"].as_i64().unwrap(), "{op}");
    }
}

fn ops(list: &[(String, i64)]) -> Vec<(&str, i64)> {
    list.iter().map(|(o, v)| (o.as_str(), *v)).collect()
}

#[test]
fn pulse_output_methods_write_and_report_the_registers() {
    let (mut sh, e, _) = setup();
    let r = lua(&mut sh, &e, "return plc:pto(0, {freq=2000, count=1000})");
    let w = writes_hold(&mut sh, &r[0]);
    assert_eq!(ops(&w), [("SMB67", 0x85), ("SMW68", 500), ("SMD72", 1000)]);
    let r = lua(&mut sh, &e, "return plc:pto_status(0)");
    values_hold(&mut sh, &r[0]);
    assert_eq!(r[0]["status"][0], "PTO busy");
    assert_eq!(get(&mut sh, "SM66.7"), 0);

    // 250 ms in, PSTOP: half the pulses out, the latch and the abort bit set.
    let r = lua(&mut sh, &e, "plcsh.sleep(250); return plc:pstop(0), plc:pto_status(0)");
    assert_eq!(r[0]["channel"], 0);
    assert!(r[0]["report"].as_str().unwrap().contains("PTO stopped"), "{}", r[0]);
    values_hold(&mut sh, &r[1]);
    assert_eq!((get(&mut sh, "SMD212"), get(&mut sh, "SM201.7"), get(&mut sh, "SM66.5")), (500, 1, 1));
    assert!(r[1]["status"].as_array().unwrap().contains(&json!("aborted by user command")));

    // pls runs the registers as they are; the cycle given as a number is µs.
    let r =
        lua(&mut sh, &e, "plc['SM201.7'] = false; plc.SMD72 = 10; return plc:pls(0), plc:pto(0, {cycle=250, count=4})");
    assert_eq!(r[0]["cmd"], "pls");
    assert_eq!(ops(&writes_hold(&mut sh, &r[1])), [("SMB67", 0x85), ("SMW68", 250), ("SMD72", 4)]);

    // PWM on channel 1, asynchronous update: 16#C3.
    let r = lua(&mut sh, &e, "return plc:pwm(1, {cycle=1000, width=250}, 'async')");
    assert_eq!(ops(&writes_hold(&mut sh, &r[0])), [("SMB77", 0xC3), ("SMW78", 1000), ("SMW80", 250)]);
    let r = lua(&mut sh, &e, "return plc:pto_status(1)");
    values_hold(&mut sh, &r[0]);
    assert!(r[0]["status"].as_array().unwrap().contains(&json!("PWM running")), "{}", r[0]);

    // A profile from a Lua list of segments (a number cycle is µs, freq is Hz).
    let r = lua(
        &mut sh,
        &e,
        "plcsh.sleep(10); plc.SMB201 = 0x40; plc.SMB201 = 0
         return plc:profile(0, 'VB3001', {{cycle=500, count=4}, {freq=4000, count=8}})",
    );
    let w = writes_hold(&mut sh, &r[0]);
    assert_eq!(
        ops(&w),
        [
            ("VB3001", 2),
            ("VW3002", 500),
            ("VW3004", 0),
            ("VD3006", 4),
            ("VW3010", 250),
            ("VW3012", 0),
            ("VD3014", 8),
            ("SMW168", 3001),
            ("SMB67", 0xA0)
        ]
    );
    assert_eq!(r[0]["timeline"]["total_pulses"], 12);
    assert_eq!(r[0]["timeline"]["duration_us"], 4000);
    lua(&mut sh, &e, "plcsh.sleep(4)");
    assert_eq!((get(&mut sh, "SMD212"), get(&mut sh, "SM66.7")), (12, 1));
    // A bad segment is refused before anything is written.
    let f = run(&mut sh, &e, "plc:profile(0, 'VB3002', {{cycle=500, count=4}})").unwrap_err();
    assert!(f.error.message.contains("odd"), "{}", f.error);
}

#[test]
fn counter_event_and_input_methods_match_the_simulator() {
    let (mut sh, e, _) = setup();
    let r = lua(
        &mut sh,
        &e,
        "plc:events()
         return plc:hsc(0, {mode=9, rate='4x', pv={10, 1000, 1000}, relative=true, cyclic=true, at='VB3009', cv=100})",
    );
    let w = writes_hold(&mut sh, &r[0]);
    assert_eq!(w.iter().find(|(o, _)| o == "SMW142").map(|x| x.1), Some(3009));
    assert_eq!(w.iter().find(|(o, _)| o == "SMB141").map(|x| x.1), Some(0x17), "multi, relative, cyclic, load");
    assert_eq!(get(&mut sh, "VB3009"), 3);

    let r = lua(&mut sh, &e, "return plc:sim_quad('I0.1', 'I0.0', {freq=1000, dir='up'}), plc:sim_inputs()");
    assert_eq!(r[1]["sources"].as_array().unwrap().len(), 1);
    assert!(r[0]["message"].as_str().unwrap().starts_with(r[1]["sources"][0].as_str().unwrap()), "{r}");

    // CV 100 → 110 is 10 counts: the first count one A period after the start, then 250 µs each.
    let r = lua(&mut sh, &e, "return plc:wait_event(64, 1000)");
    assert_eq!(r[0]["event"]["number"], 64);
    assert_eq!(r[0]["event"]["time_us"], 1000 + 9 * 250);
    assert_eq!(get(&mut sh, "SMD38"), 110, "CV = PV1 when the event is raised");
    let r = lua(&mut sh, &e, "return plc:wait_event(65), plc:hsc_status(0)");
    assert_eq!((r[0]["event"]["number"].as_i64(), r[0]["event"]["pv"].as_i64()), (Some(65), Some(2)));
    assert_eq!(get(&mut sh, "SMD38"), 1110);
    values_hold(&mut sh, &r[1]);
    assert_eq!(get(&mut sh, "SMB140"), 2, "next PV is PV3");

    let r = lua(&mut sh, &e, "plcsh.sleep(300); return plc:sim_off('I0.1'), plc:sim_inputs(), plc:events({keep=true})");
    assert_eq!(r[1]["sources"], json!([]));
    let cv = get(&mut sh, "SMD38");
    lua(&mut sh, &e, "plcsh.sleep(100)");
    assert_eq!(get(&mut sh, "SMD38"), cv, "the source is off");
    let log: Vec<i64> = r[2]["events"].as_array().unwrap().iter().map(|e| e["number"].as_i64().unwrap()).collect();
    assert_eq!(log, [66, 64], "PV3 at 2110, then PV1 again at 2120 (cyclic)");
    let r = lua(&mut sh, &e, "return plc:events()");
    assert_eq!(r[0]["events"].as_array().unwrap().len(), 2, "keep left them in the log");
    assert_eq!(lua(&mut sh, &e, "return #plc:events().events"), json!([0]), "events clears");

    // A single input with a frequency; hdef gives counter 1 mode 0.
    let r = lua(&mut sh, &e, "return plc:hdef(1, 0), plc:sim_input('I0.3', {freq=500})");
    assert!(r[0]["report"].as_str().unwrap().starts_with("HSC1 mode 0"), "{}", r[0]);
    let f = run(&mut sh, &e, "plc:hdef(1, 99)").unwrap_err();
    assert_eq!(f.error.device.as_deref(), Some("plc"));
}

#[test]
fn clock_and_backup_methods_match_the_simulator() {
    let (mut sh, e, _) = setup();
    let r = lua(&mut sh, &e, "return plc:rtc_set('2026-01-02T03:04:05'), plc:rtc()");
    assert_eq!(r[0]["rtc"], "2026-01-02T03:04:05");
    assert_eq!(r[1]["bcd"], json!([0x26, 0x01, 0x02, 0x03, 0x04, 0x05, 0, 6]), "Friday = 6");
    lua(&mut sh, &e, "plcsh.sleep(61000)");
    let o = sh.exec("rtc").remove(0).unwrap().to_json();
    assert_eq!(o["rtc"], "2026-01-02T03:05:06", "the clock Rust reads ran with virtual time");
    let r = lua(&mut sh, &e, "return plc:rtc_sync()");
    assert!(r[0]["rtc"].as_str().unwrap().len() == 19, "{}", r[0]);

    let dir = std::env::temp_dir().join(format!("plcsh-bridge-eeprom-{}", std::process::id()));
    std::fs::create_dir_all(&dir).unwrap();
    let file = dir.join("backup.bin");
    let path = file.to_str().unwrap().replace('\\', "/");
    let r = lua(
        &mut sh,
        &e,
        &format!("plc.VB3648 = 7; plc.VB3902 = 9; return plc:eeprom_status(), plc:eeprom_dump('{path}')"),
    );
    assert_eq!((r[0]["first"].as_i64(), r[0]["last"].as_i64()), (Some(3648), Some(3902)));
    assert_eq!(r[1]["bytes"], 255);
    let bytes = std::fs::read(&file).unwrap();
    assert_eq!((bytes.len(), bytes[0], bytes[254]), (255, 7, 9), "the file holds the area");
    lua(&mut sh, &e, "plc.VB3648 = 0; plc.VB3902 = 0");
    let r = lua(&mut sh, &e, &format!("return plc:eeprom_restore('{path}')"));
    assert_eq!(r[0]["bytes"], 255);
    assert_eq!((get(&mut sh, "VB3648"), get(&mut sh, "VB3902")), (7, 9));
    let r = lua(&mut sh, &e, "return plc:eeprom_area(4095), plc:eeprom_status()");
    assert_eq!((r[0]["last"].as_i64(), r[1]["last"].as_i64()), (Some(4095), Some(4095)));
    std::fs::remove_dir_all(&dir).unwrap();
}

#[test]
fn servo_methods_drive_the_simulated_drive() {
    let (mut sh, e, _) = setup_with_servo();
    let sget = |sh: &mut Shell, op: &str| get(sh, &format!("servo:{op}"));
    let r = lua(&mut sh, &e, "return servo:fault_reset(), servo:mode('position'), servo:enable(), servo:status()");
    assert_eq!(r[1]["mode_name"], "position");
    assert_eq!(sget(&mut sh, "operating_mode"), 1);
    assert_eq!(r[2]["state"], "operation enabled");
    assert_eq!(r[3]["state"], "operation enabled");
    assert_eq!(r[3]["statusword"].as_i64().unwrap(), sget(&mut sh, "statusword"));

    let r = lua(&mut sh, &e, "return servo:move_abs(10000, {rpm=300}), servo:wait_target(5000)");
    assert_eq!((r[0]["move"].as_str(), r[0]["target_position"].as_i64()), (Some("abs"), Some(10000)));
    assert_eq!(r[0]["profile_velocity"].as_i64().unwrap(), sget(&mut sh, "profile_velocity"));
    assert_eq!(r[1]["position_actual"], 10000);
    assert_eq!(sget(&mut sh, "position_actual"), 10000);
    let r = lua(&mut sh, &e, "return servo:move_rel(-2500, {rpm=300}), servo:wait_target()");
    assert_eq!(r[1]["position_actual"], 7500);
    assert_eq!(sget(&mut sh, "position_actual"), 7500);

    // Jog 60 rpm: velocity mode, the target velocity in DEC as the drive holds it.
    let r = lua(&mut sh, &e, "return servo:jog{rpm=60}, servo:encoder()");
    assert_eq!(r[0]["target_velocity"].as_i64().unwrap(), sget(&mut sh, "target_velocity"));
    assert_eq!(sget(&mut sh, "operating_mode"), 3);
    assert_eq!(r[1]["encoder_resolution"], 10000);
    let r = lua(&mut sh, &e, "plcsh.sleep(1000); return servo:status(), servo:quickstop()");
    assert_eq!(r[0]["velocity_rpm"], 60.0, "at speed after a second");
    // About one revolution (10000 inc) in the second, less the acceleration ramp.
    let moved = r[0]["position_actual"].as_i64().unwrap() - 7500;
    assert!((9000..=10000).contains(&moved), "{moved}");
    assert_eq!(r[1]["state"], "quick stop active");
    let r = lua(&mut sh, &e, "return servo:disable()");
    assert_eq!(r[0]["state"], "switch on disabled", "disable from quick stop");

    // Homing onto the simulated switch; then a fault and its reset.
    let r = lua(
        &mut sh,
        &e,
        "servo:enable(); return servo:sim_switch(2000), servo:home(), servo:wait_target(5000), servo:status(), servo:save()",
    );
    assert_eq!(r[0]["home_switch"], 2000);
    assert_eq!(r[3]["mode_name"], "homing");
    assert_eq!(sget(&mut sh, "position_actual"), r[2]["position_actual"].as_i64().unwrap());
    assert_eq!(r[4]["cmd"], "servo");
    let r = lua(&mut sh, &e, "return servo:sim_fault(), servo:status(), servo:fault_reset()");
    assert_eq!(r[0]["fault"], 0x5000);
    assert_eq!((r[1]["state"].as_str(), r[1]["fault"].as_bool()), (Some("fault"), Some(true)));
    assert_eq!(r[2]["state"], "switch on disabled");
    // A servo method on the PLC, and a K2 method on the servo, are refused by family.
    assert_eq!(run(&mut sh, &e, "plc:move_abs(1)").unwrap_err().error.kind, ErrorKind::Unsupported);
    assert_eq!(run(&mut sh, &e, "servo:pls(0)").unwrap_err().error.kind, ErrorKind::Unsupported);
}
