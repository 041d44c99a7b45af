//! In-process tests of the Lua layer against the simulator (stepped clock).

use super::*;
use crate::core::Clock;
use crate::output::Style;
use std::sync::Mutex;

/// A writer the test can read back.
#[derive(Clone, Default)]
struct Buf(Arc<Mutex<Vec<u8>>>);

impl Write for Buf {
    fn write(&mut self, b: &[u8]) -> std::io::Result<usize> {
        self.0.lock().unwrap().extend_from_slice(b);
        Ok(b.len())
    }
    fn flush(&mut self) -> std::io::Result<()> {
        Ok(())
    }
}

impl Buf {
    fn text(&self) -> String {
        String::from_utf8(self.0.lock().unwrap().clone()).unwrap()
    }
}

fn setup() -> (Shell, Engine, Buf) {
    let mut s = Session::new(Clock::stepped());
    s.open("plc", "sim:K205-16DT").unwrap();
    s.open("big", "sim:K209M-56DT").unwrap();
    s.use_device("plc").unwrap();
    let shell = Shell::new(s, Style::default());
    let buf = Buf::default();
    let engine = Engine::new(shell.session.interrupt.clone(), Box::new(buf.clone())).unwrap();
    (shell, engine, buf)
}

fn run(shell: &mut Shell, engine: &Engine, code: &str) -> Result<Outcome, Failure> {
    engine.run_chunk(shell, code)
}

fn get(shell: &mut Shell, op: &str) -> i64 {
    shell.session.get(&[op]).unwrap()[0].1.value.as_i64()
}

#[test]
fn field_access_reads_and_writes_the_device() {
    let (mut sh, e, _) = setup();
    run(&mut sh, &e, "plc.SMB67 = 0x85; plc.VW100 = 500; big.VW16000 = 9").unwrap();
    assert_eq!(get(&mut sh, "SMB67"), 0x85);
    assert_eq!(get(&mut sh, "VW100"), 500);
    assert_eq!(get(&mut sh, "big:VW16000"), 9);
    sh.session
        .set(&[crate::session::SetItem { operand: "VD104".into(), value: "-7".into(), column: 0, value_column: 0 }])
        .unwrap_err();
    sh.session
        .set(&[crate::session::SetItem {
            operand: "VD104/DINT".into(),
            value: "-7".into(),
            column: 0,
            value_column: 0,
        }])
        .unwrap();
    let o = run(&mut sh, &e, "plc.VW100, plc['VD104/DINT'], plc['M0.0'], plc.vw100").unwrap();
    assert_eq!(o.data["results"], serde_json::json!([500, -7, false, 500]));
    run(&mut sh, &e, "plc['M0.1'] = true; plc['VD200/REAL'] = 1.5").unwrap();
    let o = run(&mut sh, &e, "plc['M0.1'], plc['VD200/REAL'], plc:get('VB0..VB2')").unwrap();
    assert_eq!(o.data["results"], serde_json::json!([true, 1.5, 0, 0, 0]));
}

#[test]
fn batch_set_forms_write_in_their_order() {
    let (mut sh, e, _) = setup();
    // Later items overwrite earlier ones on the same operand: the order is observable.
    run(&mut sh, &e, "plc:set({'VW0', 1}, {'VW0', 2})").unwrap();
    assert_eq!(get(&mut sh, "VW0"), 2);
    run(&mut sh, &e, "plc:set{{'VW0', 3}, {'VW0', 4}}").unwrap();
    assert_eq!(get(&mut sh, "VW0"), 4);
    run(&mut sh, &e, "plc:set('VW0', 6, 'VW0', 5)").unwrap();
    assert_eq!(get(&mut sh, "VW0"), 5);
    run(&mut sh, &e, "plc:set('VW0=16#85, VW0=9')").unwrap();
    assert_eq!(get(&mut sh, "VW0"), 9);
    // Keyed items go in name order: VB1 before VW0, so VW0 (0x0102) wins over VB1.
    run(&mut sh, &e, "plc:set{VW0=0x0102, VB1=0xFF}").unwrap();
    assert_eq!(get(&mut sh, "VW0"), 0x0102);
    run(&mut sh, &e, "plc:set{SMB67=0x85, SMW68=500, SMD72=1000}").unwrap();
    assert_eq!((get(&mut sh, "SMB67"), get(&mut sh, "SMW68"), get(&mut sh, "SMD72")), (133, 500, 1000));
}

#[test]
fn a_bad_batch_writes_nothing_and_names_device_and_operand() {
    let (mut sh, e, _) = setup();
    let f = run(&mut sh, &e, "plc:set({'VW0', 1}, {'VB2', 300}, {'VW4', 2})").unwrap_err();
    assert_eq!(f.error.kind, ErrorKind::Value);
    assert_eq!(f.error.device.as_deref(), Some("plc"));
    assert_eq!(f.error.operand.as_deref(), Some("VB2"));
    assert_eq!((get(&mut sh, "VW0"), get(&mut sh, "VW4")), (0, 0));
    let f = run(&mut sh, &e, "plc.VW5000 = 1").unwrap_err();
    assert_eq!(f.error.kind, ErrorKind::Range);
    assert!(f.error.to_string().contains("VW4094"), "{}", f.error);
    let f = run(&mut sh, &e, "plc.SMB0 = 1").unwrap_err();
    assert_eq!(f.error.kind, ErrorKind::Refused);
}

#[test]
fn errors_reach_scripts_as_fields() {
    let (mut sh, e, _) = setup();
    let o = run(
        &mut sh,
        &e,
        "local ok, err = pcall(function() plc.VB2 = 300 end); local i = plcsh.errinfo(err); \
         return ok, i.kind, i.device, i.operand, tostring(err):match('out of range') ~= nil",
    )
    .unwrap();
    assert_eq!(o.data["results"], serde_json::json!([false, "value", "plc", "VB2", true]));
    let o = run(
        &mut sh,
        &e,
        "local ok, err = pcall(plcsh.exec, 'set VW0=1, VB2=300'); local i = plcsh.errinfo(err); \
         return i.cmd, i.kind, i.operand, i.column, tostring(err)",
    )
    .unwrap();
    let r = &o.data["results"];
    assert_eq!(
        (r[0].as_str(), r[1].as_str(), r[2].as_str(), r[3].as_u64()),
        (Some("set"), Some("value"), Some("VB2"), Some(15))
    );
    let msg = r[4].as_str().unwrap();
    assert!(msg.contains("error[value]: `set`: plc: VB2: 300 is out of range for BYTE"), "{msg}");
}

#[test]
fn exec_returns_one_table_per_command() {
    let (mut sh, e, _) = setup();
    let o = run(
        &mut sh,
        &e,
        "local s, g = plcsh.exec('set SMB67=16#85, SMW68=500, SMD72=1000; get SMB67 SMW68'); return s, g",
    )
    .unwrap();
    let r = &o.data["results"];
    assert_eq!(r[0]["cmd"], "set");
    assert_eq!(r[0]["writes"][2]["operand"], "SMD72");
    assert_eq!(
        r[1],
        serde_json::json!({"ok": true, "cmd": "get", "device": "plc", "values": [
        {"operand": "SMB67", "value": 133, "type": "BYTE"}, {"operand": "SMW68", "value": 500, "type": "WORD"}]})
    );
}

#[test]
fn the_bridge_runs_commands_on_the_handles_device() {
    let (mut sh, e, _) = setup();
    run(&mut sh, &e, "big.VW16000 = 42").unwrap();
    let o = run(&mut sh, &e, "return big:read('VW16000'), plc:help('SMB67'), big:cmd('get VW16000; get VW0')").unwrap();
    let r = &o.data["results"];
    assert_eq!(r[0]["device"], "big");
    assert_eq!(r[0]["values"][0]["value"], 42);
    assert!(r[1]["message"].as_str().unwrap().contains("PTO0"), "{}", r[1]);
    assert_eq!(r[2]["values"][0]["value"], 42);
    assert_eq!(r[3]["cmd"], "get");
    assert_eq!(sh.session.current_name(), Some("plc"), "the current device is restored");
    // A helper's own refusal comes back as the Lua error, with the device.
    let f = run(&mut sh, &e, "plc:pls(0)").unwrap_err();
    assert!(f.error.message.contains("SMB67"), "{}", f.error);
    assert_eq!(f.error.device.as_deref(), Some("plc"));
    let f = run(&mut sh, &e, "plc:enable()").unwrap_err();
    assert_eq!(f.error.kind, ErrorKind::Unsupported);
    assert!(f.error.message.contains("servo method"), "{}", f.error);
}

#[test]
fn a_closed_device_gives_a_clear_error() {
    let (mut sh, e, _) = setup();
    run(&mut sh, &e, "h = plcsh.device('big'); h.VW0 = 1; plcsh.exec('close big')").unwrap();
    let f = run(&mut sh, &e, "h.VW0 = 2").unwrap_err();
    assert_eq!(f.error.kind, ErrorKind::State);
    assert!(f.error.message.contains("`big` is not open"), "{}", f.error);
    // Reopened under the same name as another model: the operand cache is not reused.
    run(&mut sh, &e, "plcsh.connect('sim:K209M-56DT', 'big'); h.VW16000 = 5").unwrap();
    assert_eq!(get(&mut sh, "big:VW16000"), 5);
    // Without a name, a K2 is `plc` or the next free `plcN`.
    let o = run(&mut sh, &e, "local d = plcsh.connect('sim:K205-16DT'); d.VW0 = 4; return d:name()").unwrap();
    assert_eq!(o.data["results"][0], "plc2");
    assert_eq!(get(&mut sh, "plc2:VW0"), 4);
    let f = run(&mut sh, &e, "plcsh.device('nope')").unwrap_err();
    assert!(f.error.hint.clone().unwrap().contains("plc"), "{:?}", f.error);
}

#[test]
fn stepped_waits_advance_virtual_time() {
    let (mut sh, e, _) = setup();
    let o = run(&mut sh, &e, "plcsh.sleep(600000); return plcsh.now()").unwrap();
    assert_eq!(o.data["results"][0], 600000.0);
    let o = run(
        &mut sh,
        &e,
        "local t0 = plcsh.now(); plcsh.wait_until(function() return plcsh.now() - t0 >= 1500 end, {every=100}); return plcsh.now() - t0",
    )
    .unwrap();
    assert_eq!(o.data["results"][0], 1500.0);
    let f =
        run(&mut sh, &e, "plcsh.wait_until(function() return false end, {timeout=2000, what='never'})").unwrap_err();
    assert_eq!(f.error.kind, ErrorKind::Timeout);
    assert!(f.error.message.contains("(never) still false after 2s"), "{}", f.error);
    assert_eq!(sh.session.clock.now().as_millis(), 600000 + 1500 + 2000);
}

#[test]
fn abort_handlers_run_last_first_on_failure_only() {
    let (mut sh, e, buf) = setup();
    run(&mut sh, &e, "plcsh.on_abort(function() print('never') end)").unwrap();
    let f = run(
        &mut sh,
        &e,
        "plcsh.on_abort(function(why) print('first ' .. why) end); plcsh.on_abort(function() plc.VW0 = 7; print('second') end); error('boom')",
    )
    .unwrap_err();
    assert!(f.error.message.contains("boom"));
    let out = buf.text();
    assert!(!out.contains("never"), "handlers of a finished chunk are dropped: {out}");
    let second = out.find("second").unwrap();
    let first = out.find("first failed").unwrap();
    assert!(second < first, "{out}");
    assert_eq!(get(&mut sh, "VW0"), 7);
}

#[test]
fn the_interrupt_flag_stops_a_busy_loop_and_runs_handlers() {
    let (mut sh, e, buf) = setup();
    // Stands in for the SIGINT handler (tests/lua.rs sends a real SIGINT to the binary).
    let flag = sh.session.interrupt.clone();
    let ctrl_c = e
        .lua()
        .create_function(move |_, ()| {
            flag.store(true, Ordering::Relaxed);
            Ok(())
        })
        .unwrap();
    e.lua().globals().set("ctrl_c", ctrl_c).unwrap();
    let f = run(
        &mut sh,
        &e,
        "plcsh.on_abort(function(why) plc.VW0 = 1; print('cleanup ' .. why) end)\n\
         ctrl_c()\n\
         while true do pcall(function() while true do end end) end",
    )
    .unwrap_err();
    assert!(f.interrupted(), "{:?}", f.error);
    assert!(buf.text().contains("cleanup interrupted"), "{}", buf.text());
    assert_eq!(get(&mut sh, "VW0"), 1, "the handler ran with the flag cleared");
    assert!(sh.session.interrupted(), "the flag stays up for the caller (the next command clears it)");
    sh.session.clear_interrupt();
    // Waits are interrupted too.
    let f = run(&mut sh, &e, "ctrl_c(); plcsh.sleep(10)").unwrap_err();
    assert!(f.interrupted());
}

#[test]
fn print_and_table_go_through_the_shell_output() {
    let (mut sh, e, buf) = setup();
    run(&mut sh, &e, "print('a', 1, true, nil); plcsh.table({{op='VW0', v=1}, {op='VW2', v=2}})").unwrap();
    let out = buf.text();
    assert!(out.starts_with("a\t1\ttrue\tnil\n"), "{out}");
    assert!(out.contains("| op  | v |") && out.contains("| VW2 | 2 |"), "{out}");
    sh.style.json = true;
    run(&mut sh, &e, "print('x')").unwrap();
    assert!(buf.text().ends_with("{\"ok\":true,\"cmd\":\"print\",\"message\":\"x\"}\n"), "{}", buf.text());
}

/// Text that is not UTF-8 (a CP1251 line read from a CSV file) prints as its bytes, as
/// stock Lua prints it; under `--json` as a JSON string, its bytes that are not UTF-8 shown
/// as U+FFFD. `plcsh.log` prints the same way.
#[test]
fn print_writes_bytes_that_are_not_utf8_as_they_are() {
    let (mut sh, e, buf) = setup();
    // "Привет" in CP1251.
    run(&mut sh, &e, r"print('\207\240\232\226\229\242', 1)").unwrap();
    assert_eq!(buf.0.lock().unwrap().as_slice(), b"\xCF\xF0\xE8\xE2\xE5\xF2\t1\n");
    run(&mut sh, &e, r"plcsh.log('\207')").unwrap();
    assert!(buf.0.lock().unwrap().ends_with(b" \xCF\n"), "{:?}", buf.0.lock().unwrap());
    buf.0.lock().unwrap().clear();
    sh.style.json = true;
    run(&mut sh, &e, r"print('\207\240 ok')").unwrap();
    assert_eq!(buf.text(), "{\"ok\":true,\"cmd\":\"print\",\"message\":\"\u{FFFD}\u{FFFD} ok\"}\n");
}

#[test]
fn json_round_trips_and_checks_report_both_values() {
    let (mut sh, e, _) = setup();
    let o = run(&mut sh, &e, "return plcsh.json.encode(plcsh.json.decode('{\"a\":[1,2,{\"b\":true}]}'))").unwrap();
    assert_eq!(o.data["results"][0], "{\"a\":[1,2,{\"b\":true}]}");
    let f = run(&mut sh, &e, "plcsh.assert_eq(plc.VW0 + 1, 2, 'VW0 plus one')").unwrap_err();
    assert!(f.error.message.contains("assert_eq failed: VW0 plus one"), "{}", f.error.message);
    assert!(f.error.message.contains("actual:   1") && f.error.message.contains("expected: 2"), "{}", f.error.message);
    run(&mut sh, &e, "plcsh.assert_eq({a={1,2}}, {a={1,2}}); plcsh.assert_near(1.0001, 1, 0.001); plcsh.check(true)")
        .unwrap();
}

#[test]
fn incomplete_chunks_are_detected() {
    let (_, e, _) = setup();
    assert!(e.incomplete("for i=1,2 do"));
    assert!(e.incomplete("function f()"));
    assert!(e.incomplete("x = {"));
    assert!(!e.incomplete("x = 1"));
    assert!(!e.incomplete("1 +"), "a syntax error is reported, not continued");
    assert!(!e.incomplete("plc.VW0"));
}

#[path = "bridge_tests.rs"]
mod bridge_tests;

/// What a script author needs in the first hour: tables print their contents, JSON refuses
/// tables it would mangle, exec takes several lines, trace returns its samples (and writes
/// CSV), log writes timestamped lines to a file and to the output.
#[test]
fn first_hour_conveniences() {
    let (mut sh, e, buf) = setup();
    run(&mut sh, &e, "print({1, 2, a=3, [10]=4, {x=1}})").unwrap();
    assert_eq!(buf.text(), "{1, 2, {x=1}, [10]=4, a=3}\n");
    for bad in ["{1, nil, 3}", "{a={1, 2, x=3}}"] {
        let f = run(&mut sh, &e, &format!("return plcsh.json.encode({bad})")).unwrap_err();
        assert!(
            f.error.message.contains("sparse list") || f.error.message.contains("mixes list items"),
            "{bad}: {f:?}"
        );
    }
    let o = run(&mut sh, &e, "return plcsh.json.encode({1, 2, {x=3}})").unwrap();
    assert_eq!(o.message.as_deref(), Some("[1,2,{\"x\":3}]"));
    run(&mut sh, &e, "plcsh.exec('set VW0=7\\nset VW2=8\\n# a comment\\n')").unwrap();
    assert_eq!((get(&mut sh, "VW0"), get(&mut sh, "VW2")), (7, 8));
    let dir = std::env::temp_dir().join(format!("plcsh-lua-first-{}", std::process::id()));
    std::fs::create_dir_all(&dir).unwrap();
    let csv = dir.join("t.csv");
    let o = run(
        &mut sh,
        &e,
        &format!(
            "local tr = plc:trace('SM0.5', 'VW0', {{every=100, ['for']=1000, to={:?}}}) return #tr.t_s, tr.series[2].values[1]",
            csv.display().to_string()
        ),
    )
    .unwrap();
    assert_eq!(o.message.as_deref(), Some("11\t7.0"));
    assert!(std::fs::read_to_string(&csv).unwrap().starts_with("t_s,SM0.5,VW0\n0.000000,"));
    let log = dir.join("run.log");
    run(&mut sh, &e, &format!("plcsh.log_to({:?}); plcsh.log('homed', {{pos=0}})", log.display().to_string())).unwrap();
    let line = std::fs::read_to_string(&log).unwrap();
    assert!(line.ends_with(" t=1.000s homed\t{pos=0}\n"), "{line}");
    assert!(buf.text().contains(" t=1.000s homed"));
}

/// A Lua file is read as the stock `lua` reads it: a UTF-8 byte-order mark (Notepad) is
/// skipped, a first `#` line is left empty and the line numbers stay the file's.
#[test]
fn a_files_byte_order_mark_and_first_hash_line_are_skipped() {
    assert_eq!(file_chunk(b"\xEF\xBB\xBFprint(1)"), b"print(1)");
    assert_eq!(file_chunk(b"#!/usr/bin/env plcsh run\nprint(1)"), b"\nprint(1)");
    assert_eq!(file_chunk(b"\xEF\xBB\xBF# shebang\n\nerror('x')"), b"\n\nerror('x')");
    assert_eq!(file_chunk(b"# only a comment"), b"");
    assert_eq!(file_chunk(b"print(1) # not the first line"), b"print(1) # not the first line");
    assert_eq!(file_chunk(b"\xEF\xBB"), b"\xEF\xBB", "a partial mark is text (Lua reports it)");
    let dir = std::env::temp_dir().join(format!("plcsh-bom-{}", std::process::id()));
    std::fs::create_dir_all(&dir).unwrap();
    let p = dir.join("bom.lua");
    std::fs::write(&p, b"\xEF\xBB\xBF#!/usr/bin/env plcsh run\nprint('ok')\nerror('line 3')\n").unwrap();
    let (mut sh, engine, out) = setup();
    let f = engine.run_file(&mut sh, &p, &[]).unwrap_err();
    assert_eq!(out.text(), "ok\n");
    assert!(f.headline().contains("bom.lua:3:"), "the error keeps the file's line: {}", f.headline());
    let _ = std::fs::remove_dir_all(&dir);
}
