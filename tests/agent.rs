//! The PLC-side helper end to end: `plcsh sim serve --agent` in one process runs
//! the helper's mailbox protocol once per simulated scan; plcsh in another process reaches
//! SM registers and instructions through Modbus TCP → mailbox → SM → PTO, and gets the same
//! results as the in-process simulator.

mod common;
use common::*;

use plcsh::core::{Clock, ErrorKind, Value};
use plcsh::session::{Session, SetItem};
use serde_json::Value as Json;
use std::time::{Duration, Instant};

struct Server {
    _served: Served,
    tcp: String,
}

impl Server {
    fn start(extra: &[&str]) -> Server {
        let mut args = vec!["--tcp", "0"];
        args.extend_from_slice(extra);
        let served = serve(&args);
        let tcp = served.ready["tcp"].as_str().unwrap().to_string();
        Server { _served: served, tcp }
    }
    fn url(&self) -> String {
        format!("tcp://{}?model=K205-16DT&agent=VB3400", self.tcp)
    }
}

/// Runs plcsh `-c LINE --json` on `device` (or the in-process simulator in stepped time).
fn json(device: Option<&str>, line: &str) -> Vec<Json> {
    let mut args = vec!["--json", "-c", line];
    match device {
        Some(d) => args.extend(["--device", d]),
        None => args.extend(["--time", "stepped"]),
    }
    let o = run(&args, "");
    let l = json_lines(&o);
    for v in &l {
        assert_eq!(v["ok"], true, "{line}: {v}");
    }
    l
}

fn values(v: &Json) -> Vec<Json> {
    v["values"].as_array().unwrap().iter().map(|x| x["value"].clone()).collect()
}

fn session(url: &str) -> Session {
    let mut s = Session::new(Clock::following());
    s.open("plc", url).unwrap_or_else(|e| panic!("open {url}: {e}"));
    s
}

/// Polls `operand` until it reads `want` (bounded; the PTO runs in wall-clock time).
fn poll_until(s: &mut Session, operand: &str, want: Value) {
    let start = Instant::now();
    loop {
        if s.get(&[operand]).unwrap()[0].1.value == want {
            return;
        }
        assert!(start.elapsed() < Duration::from_secs(10), "{operand} never became {want}");
        std::thread::sleep(Duration::from_millis(20));
    }
}

#[test]
fn pulse_train_through_the_mailbox_matches_the_simulator() {
    let srv = Server::start(&["--agent"]);
    let url = srv.url();
    let line = "set SMB67=16#85, SMW68=500, SMD72=1000; pls 0";
    json(Some(&url), line);
    let mut s = session(&url);
    poll_until(&mut s, "SM66.7", Value::Bool(true));
    let wire: Vec<Value> = s
        .get(&["SM66.7", "SMD212", "SMB66", "SMB67", "SMW68", "SMD72"])
        .unwrap()
        .into_iter()
        .map(|r| r.1.value)
        .collect();
    let local = json(None, &format!("{line}; sim step 501ms; get SM66.7 SMD212 SMB66 SMB67 SMW68 SMD72"));
    let local: Vec<Json> = values(local.last().unwrap());
    let wire: Vec<Json> = wire.iter().map(|v| serde_json::to_value(v).unwrap()).collect();
    assert_eq!(wire, local, "SM66.7 SMD212 SMB66 SMB67 SMW68 SMD72 over the wire and in-process");
    assert_eq!(wire[1], 1000);
}

#[test]
fn hsc_setup_with_a_multi_pv_table_matches_the_simulator() {
    let srv = Server::start(&["--agent"]);
    let setup = "hsc 0 mode=9 rate=4x pv=[100,200,300] relative cyclic at VB3009";
    let read = "get SMB37 SMD38 SMB141 SMW142 SMB36 SMB140 VB3009 VD3010 VD3014 VD3018";
    let wire = json(Some(&srv.url()), &format!("{setup}; {read}"));
    let local = json(None, &format!("{setup}; {read}"));
    assert_eq!(values(wire.last().unwrap()), values(local.last().unwrap()));
    assert_eq!(wire[0]["writes"], local[0]["writes"], "the helper wrote the same registers");
    assert_eq!(values(wire.last().unwrap())[6], 3, "three PVs in the table");
}

#[test]
fn the_clock_is_set_and_read_through_the_helper() {
    let srv = Server::start(&["--agent"]);
    let l = json(Some(&srv.url()), "rtc set 2026-11-22T10:00:00; rtc");
    let t = l[1]["rtc"].as_str().unwrap_or_else(|| panic!("{}", l[1]));
    assert!(t.starts_with("2026-11-22T10:00:0"), "{t}");
}

#[test]
fn a_missing_helper_is_one_clear_message() {
    let srv = Server::start(&[]);
    // A 10 s timeout: waiting one out cannot pass for a slow start on a loaded machine.
    let url = format!("{}&timeout=10s", srv.url());
    let started = Instant::now();
    let o = run(&["--json", "--device", &url, "-c", "set SMB67=16#85, SMW68=500, SMD72=1000; pls 0"], "");
    let l = json_lines(&o);
    assert_eq!(l.len(), 1, "one message, not one per register: {l:?}");
    assert_eq!(l[0]["error"]["kind"], "unsupported");
    assert!(l[0]["error"]["hint"].as_str().unwrap().contains("k2_agent.il"), "{}", l[0]);
    assert!(started.elapsed() < Duration::from_secs(10), "no timeout was waited out");
    // Without agent= the SM area is refused before anything is sent, naming the helper.
    let o = run(&["--json", "--device", &format!("tcp://{}", srv.tcp), "-c", "get SMB66"], "");
    let l = json_lines(&o);
    assert!(l[0]["error"]["hint"].as_str().unwrap().contains("agent=VB3400"), "{}", l[0]);
}

/// As reported: a plain Modbus client leaves an SM write with start 40000 in the
/// mailbox. The helper refuses it (result 2, bad range) and keeps running: the heartbeat
/// moves and the next helper command is served, not "mailbox busy … is the PLC in RUN?".
#[test]
fn a_request_with_a_huge_start_is_refused_and_the_helper_keeps_running() {
    let srv = Server::start(&["--agent", "VB3400"]);
    let plain = format!("tcp://{}?model=K205-16DT", srv.tcp);
    json(Some(&plain), "set VW3502=40000, VW3504=1, VW3500=1; set VW3496=1");
    let mut s = session(&plain);
    let read = |s: &mut Session, op: &str| match s.get(&[op]).unwrap()[0].1.value {
        Value::Int(v) => v,
        ref v => panic!("{op}: {v:?}"),
    };
    let start = Instant::now();
    while read(&mut s, "VW3408") != 1 {
        assert!(start.elapsed() < Duration::from_secs(20), "the request was never acknowledged");
        std::thread::sleep(Duration::from_millis(5));
    }
    // The result word: the code in the low byte, the cause (the row of the checks) above.
    let word = read(&mut s, "VW3412");
    assert_eq!(word & 0xFF, 2, "result 2: bad range");
    let row =
        &plcsh::k2::agent::protocol::checks(plcsh::k2::catalog::lookup("K205-16DT").unwrap())[(word >> 8) as usize - 1];
    assert!(row.why.contains("SMB0..SMB265"), "cause {}: {}", word >> 8, row.why);
    // The heartbeat moves: the PLC still scans (waited for, however late a loaded machine
    // schedules the server).
    let beat = read(&mut s, "VW3404");
    let start = Instant::now();
    while read(&mut s, "VW3404") == beat {
        assert!(start.elapsed() < Duration::from_secs(20), "the heartbeat stopped at {beat}: the PLC no longer scans");
        std::thread::sleep(Duration::from_millis(10));
    }
    let l = json(Some(&srv.url()), "get SMB66");
    assert_eq!(values(&l[0]).len(), 1, "the helper still answers: {l:?}");
}

#[test]
fn two_clients_using_the_mailbox_do_not_corrupt_each_other() {
    let srv = Server::start(&["--agent"]);
    // The helper's acknowledgement may take long on a busy machine (two clients, one scan at a
    // time): a generous timeout, as a user on a slow line sets it (`timeout=` in the URL). What
    // is checked is that neither client corrupts the other, not how fast they are.
    let url = format!("{}&timeout=10s", srv.url());
    let worker = |operand: &'static str, url: String| {
        std::thread::spawn(move || {
            let mut s = session(&url);
            let (mut ok, mut busy) = (0, 0);
            for i in 1..=25i64 {
                let item = SetItem { operand: operand.into(), value: (i * 7).to_string(), column: 0, value_column: 0 };
                match s.set(&[item]) {
                    Ok(_) => {}
                    Err(e) if e.kind == ErrorKind::State => {
                        busy += 1;
                        continue;
                    }
                    Err(e) => panic!("{operand}: {e}"),
                }
                match s.get(&[operand]) {
                    Ok(r) => {
                        assert_eq!(r[0].1.value, Value::Int(i * 7), "{operand} read back what this client wrote");
                        ok += 1;
                    }
                    Err(e) if e.kind == ErrorKind::State => busy += 1,
                    Err(e) => panic!("{operand}: {e}"),
                }
            }
            (ok, busy)
        })
    };
    let a = worker("SMW68", url.clone());
    let b = worker("SMW78", url.clone());
    let (a, b) = (a.join().unwrap(), b.join().unwrap());
    eprintln!("client A: {} round trips, {} busy; client B: {} round trips, {} busy", a.0, a.1, b.0, b.1);
    assert!(a.0 > 0 && b.0 > 0, "both clients got through");
    let mut s = session(&url);
    let last: Vec<Value> = s.get(&["SMW68", "SMW78"]).unwrap().into_iter().map(|r| r.1.value).collect();
    assert!(matches!(last[0], Value::Int(v) if v % 7 == 0 && v > 0), "{last:?}");
    assert!(matches!(last[1], Value::Int(v) if v % 7 == 0 && v > 0), "{last:?}");
}

#[test]
fn lua_reaches_the_helper_on_a_wire_plc() {
    let srv = Server::start(&["--agent"]);
    let dir = std::env::temp_dir().join(format!("plcsh-agent-lua-{}", std::process::id()));
    std::fs::create_dir_all(&dir).unwrap();
    let script = dir.join("wire_pto.lua");
    std::fs::write(
        &script,
        r#"
local plc = plcsh.device("plc")
assert(plc:agent_status().message:find("helper protocol 3"))
plc:set({"SMB67", 0x85}, {"SMW68", 500}, {"SMD72", 200})
plc:pls(0)
plcsh.wait_until(function() return plc["SM66.7"] end, {timeout = 5000, every = 10})
plcsh.assert_eq(plc.SMD212, 200, "pulses counted by the PLC")
print("ok")
"#,
    )
    .unwrap();
    let o = run(&["--device", &srv.url(), "run", script.to_str().unwrap()], "");
    assert!(o.status.success(), "{}{}", stdout(&o), String::from_utf8_lossy(&o.stderr));
    assert!(stdout(&o).contains("ok"));
    let _ = std::fs::remove_dir_all(&dir);
}

/// The readiness line says which helper runs (the copy built into plcsh, not the file) and
/// how to run an edited one: `--program FILE` without `--agent`, which then serves the
/// mailbox from the file (docs/simulator.md).
#[test]
fn the_ready_line_names_the_built_in_helper_and_an_edited_one_runs_as_the_program() {
    let served = serve(&["--tcp", "0", "--agent"]);
    let note = served.ready["agent_program"].as_str().unwrap_or_else(|| panic!("{}", served.ready));
    assert!(note.contains("built-in copy of lib/k2_agent.il") && note.contains("--program FILE"), "{note}");
    drop(served);
    let file = concat!(env!("CARGO_MANIFEST_DIR"), "/lib/k2_agent.il");
    let served = serve(&["--tcp", "0", "--program", file]);
    assert!(served.ready.get("agent_program").is_none(), "no built-in helper: {}", served.ready);
    let url = format!("tcp://{}?model=K205-16DT&agent=VB3400", served.ready["tcp"].as_str().unwrap());
    let l = json(Some(&url), "rtc set 2026-11-22T10:00:00; rtc");
    assert!(l[1]["rtc"].as_str().unwrap_or("").starts_with("2026-11-22T10:00:0"), "{}", l[1]);
}

/// As reported: through the helper, `pto N freq=2kHz count=…` twice (two plcsh runs) counted
/// only the first train, though both said "done by the helper", and a second `pstop` with
/// only SM writes in between did not latch SM201.7. PLS and PSTOP act on the rising edge of
/// their enable (K2 manual §3.4.2); the helper now lets it fall between requests. On every
/// pulse channel: two trains count twice, PLS right after PLS runs twice, and PSTOP latches
/// again after the latch was cleared.
#[test]
fn pls_and_pstop_act_every_time_they_are_asked_on_every_channel() {
    use plcsh::k2::sm_map::PTO_REGS;
    let srv = Server::start(&["--agent"]);
    let url = srv.url();
    let mut s = session(&url);
    let model = plcsh::k2::catalog::lookup("K205-16DT").unwrap();
    for r in PTO_REGS.iter().filter(|r| model.pto.iter().any(|c| c.channel == r.channel)) {
        let (ch, idle, pos) = (r.channel, format!("SM{}.7", r.status), format!("SMD{}", r.pos_cv));
        for train in 1..=2 {
            let l = json(Some(&url), &format!("pto {ch} freq=2kHz count=100"));
            assert!(l[0].to_string().contains("done by the helper"), "{l:?}");
            poll_until(&mut s, &idle, Value::Bool(true));
            assert_eq!(s.get(&[pos.as_str()]).unwrap()[0].1.value, Value::Int(100 * train), "PTO{ch}, train {train}");
        }
        // Back to back in one session: the second PLS restarts the running train (pulses
        // already out stay counted), so more than one train's worth is added.
        json(Some(&url), &format!("pls {ch}; pls {ch}"));
        poll_until(&mut s, &idle, Value::Bool(true));
        match s.get(&[pos.as_str()]).unwrap()[0].1.value {
            Value::Int(v) => assert!(v > 300 && v <= 400, "PTO{ch}: {pos} = {v} after PLS twice"),
            ref v => panic!("{pos}: {v:?}"),
        }
        let latch = format!("SM{}.7", r.pos_control);
        for round in 1..=2 {
            json(Some(&url), &format!("pstop {ch}"));
            assert_eq!(s.get(&[latch.as_str()]).unwrap()[0].1.value, Value::Bool(true), "{latch}, PSTOP {round}");
            json(Some(&url), &format!("set SMW{}=500; set {latch}=0", r.cycle));
            assert_eq!(s.get(&[latch.as_str()]).unwrap()[0].1.value, Value::Bool(false), "{latch} cleared");
        }
    }
}

/// A PLS the PLC refuses (pulse count 1; K2 §3.4.2.2: «Время цикла и количество импульсов
/// должны быть больше 1») leaves the CR as it was (§3.4.2, «Это не повлияет на значение CR»),
/// so the helper reads the channel's status bit 4: through `sim serve --agent` the refusal is
/// reported with that bit and the manual's rule, the words the simulator uses in process —
/// never "done by the helper". A write to SMD212 is refused with the read-only rule and the
/// way to set it (SMD208 + SM201.4), as in process.
#[test]
fn a_refused_pls_and_a_read_only_write_are_reported_with_their_reasons() {
    let srv = Server::start(&["--agent"]);
    let line = "set SMB67=16#85, SMW68=1000, SMD72=1; pls 0";
    let o = run(&["--json", "--device", &srv.url(), "-c", line], "");
    let l = json_lines(&o);
    let last = l.last().unwrap();
    assert_ne!(last["ok"], true, "refused, not done: {l:?}");
    let msg = last["error"]["message"].as_str().unwrap_or_else(|| panic!("{last}"));
    assert!(msg.contains("SM66.4") && msg.contains("cycle and count must both be > 1, §3.4.2.2"), "{msg}");
    assert!(!stdout(&o).contains("done by the helper"), "{}", stdout(&o));
    let local = run(&["--json", "--time", "stepped", "-c", line], "");
    let local = json_lines(&local);
    let local_msg = local.last().unwrap()["error"]["message"].as_str().unwrap().to_string();
    assert!(
        local_msg.contains("SM66.4") && local_msg.contains("cycle and count must both be > 1, §3.4.2.2"),
        "{local_msg}"
    );

    for (device, what) in [(Some(srv.url()), "helper"), (None, "in process")] {
        let mut args = vec!["--json", "-c", "set SMD212=5"];
        let d;
        match &device {
            Some(u) => {
                d = u.clone();
                args.extend(["--device", &d]);
            }
            None => args.extend(["--time", "stepped"]),
        }
        let l = json_lines(&run(&args, ""));
        let e = &l.last().unwrap()["error"];
        let m = e["message"].as_str().unwrap_or_else(|| panic!("{what}: {l:?}"));
        assert!(
            m.contains("SMD212 is the read-only current value of position channel 0 (manual §3.4.3.1)"),
            "{what}: {m}"
        );
        let h = e["hint"].as_str().unwrap_or_else(|| panic!("{what}: {e}"));
        assert!(h.contains("SMD208") && h.contains("SM201.4"), "{what}: {h}");
    }
}

/// `plcsh agent il --model MODEL` prints the helper for that model only: the K209M's fourth
/// pulse output (`PLS 3`, manual §3.4) and no HSC2 (§3.3), no PLS on the relay K205-16DR
/// (§2.2.6), the default model's program is `lib/k2_agent.il`, and an unknown model is
/// refused with the catalogue.
#[test]
fn the_helper_is_printed_for_the_model_it_goes_into() {
    let il = |model: &str| {
        let o = run(&["agent", "il", "--model", model], "");
        assert!(o.status.success(), "{model}: {}", String::from_utf8_lossy(&o.stderr));
        stdout(&o)
    };
    let k209m = il("K209M-56DT");
    assert!(k209m.contains("\nPLS     3") && k209m.contains("\nPSTOP   3,"), "the K209M's Q0.5");
    assert!(!k209m.contains("\nHDEF    2,") && k209m.contains("\nHDEF    1, 10"), "HSC0, HSC1 only");
    let relay = il("K205-16DR");
    assert!(!relay.contains("\nPLS ") && !relay.contains("\nPSTOP "), "no pulse outputs on relays");
    let k205 = il("K205-16DT");
    assert!(!k205.contains("\nPLS     3"), "PLS 0, 1, 2 only (§3.4.2: «Константа (0,1 или 2)»)");
    let lib = std::fs::read_to_string(concat!(env!("CARGO_MANIFEST_DIR"), "/lib/k2_agent.il")).unwrap();
    assert_eq!(stdout(&run(&["agent", "il"], "")), lib, "the default model's helper is lib/k2_agent.il");
    assert_eq!(k205, lib);
    let o = run(&["agent", "il", "--model", "K999"], "");
    assert_eq!(o.status.code(), Some(2));
    assert!(String::from_utf8_lossy(&o.stderr).contains("K209M-56DT"), "the catalogue is named");
}

/// The error (message, hint) of the last command of `line` on `device` (or in process). A
/// line stops at its first error, so lines that run on past one (an earlier refusal that
/// leaves a value behind) come in on standard input, one after the other.
fn refusal(device: Option<&str>, line: &str) -> (String, String) {
    let mut args = vec!["--json"];
    let stdin = if line.contains('\n') {
        format!("{line}\n")
    } else {
        args.extend(["-c", line]);
        String::new()
    };
    match device {
        Some(d) => args.extend(["--device", d]),
        None => args.extend(["--time", "stepped", "--model", "K205-16DT"]),
    }
    let l = json_lines(&run(&args, &stdin));
    let last = l.last().unwrap_or_else(|| panic!("{line}: no output"));
    assert_ne!(last["ok"], true, "{line}: refused, not done: {l:?}");
    let e = &last["error"];
    let text = |k: &str| e[k].as_str().unwrap_or("").to_string();
    (text("message"), text("hint"))
}

/// HSC with a fault in its multi-PV table: the PLC reports it in the counter's status bit 3
/// (K2 §3.3.2: «Неисправность в нескольких табличных значениях PV: 0 = нет, 1 = да») and the
/// manual does not say HSC is refused, so the counter runs and the command succeeds with the
/// fault named — in process and through the helper (which reads SMB141, SMW142 and the V
/// table back), with the same note: no table loaded (SM141.4 clear, §3.3.3), an even start, a
/// start past V, no PVs, a table that ends before its first PV.
#[test]
fn an_hsc_table_fault_is_noted_alike_through_the_helper_and_in_process() {
    let srv = Server::start(&["--agent"]);
    let url = srv.url();
    let note = |device: Option<&str>, line: &str| -> String {
        let mut args = vec!["--json", "-c", line];
        match device {
            Some(d) => args.extend(["--device", d]),
            None => args.extend(["--time", "stepped", "--model", "K205-16DT"]),
        }
        let l = json_lines(&run(&args, ""));
        let last = l.last().unwrap_or_else(|| panic!("{line}: no output"));
        assert_eq!(last["ok"], true, "{line}: HSC runs, the fault is a note: {l:?}");
        let text = last.to_string();
        let at = text.find("PV table fault").unwrap_or_else(|| panic!("{line}: no note in {text}"));
        text[at..].split('"').next().unwrap().to_string()
    };
    // The first case runs first on the served PLC: no table was ever loaded on HSC1.
    let cases = [
        "hdef 1 0; set SMB151=16#01, SMB47=16#80; hsc 1",
        "hdef 0 0; set SMB141=16#11, SMW142=3000, SMB37=16#80; hsc 0",
        "hdef 0 0; set SMB141=16#11, SMW142=9001, SMB37=16#80; hsc 0",
        "hdef 0 0; set VB3101=0, SMB141=16#11, SMW142=3101, SMB37=16#80; hsc 0",
        "hdef 0 0; set VB3101=2, VD3102=1, VD3106=50, SMB141=16#13, SMW142=3101, SMB37=16#80; hsc 0",
    ];
    for line in cases {
        let helper = note(Some(&url), line);
        let local = note(None, line);
        assert_eq!(helper, local, "`{line}`: the routes word the fault differently");
        assert!(helper.contains("SM36.3 = 1") || helper.contains("SM46.3 = 1"), "{helper}");
    }
    // And the counter counts through the helper as in process: its status bit 3 is set, its
    // enable bit on.
    let l = json_lines(&run(&["--json", "--device", &url, "-c", "get SM36.3, SMB37"], ""));
    assert!(l.last().unwrap().to_string().contains("true"), "{l:?}");
}

/// Every refusal a command can meet reads the same through the helper (`sim serve --agent`,
/// the refusal read where the PLC reports it: status bits, the control byte, the helper's
/// checks) and in process (the simulator's own pulse generator, counters and clock): the
/// same message and the same hint. PLS with a pulse count or cycle time below 2 (K2
/// §3.4.2.2: «Время цикла и количество импульсов должны быть больше 1», status bit 4), PLS
/// at a frequency above the output's limit (§3.4), PWM with a cycle below 2, PLS on a
/// disabled idle channel (the control byte's value in the words, §3.4.2.2 bit 7), PLS, PSTOP,
/// HDEF and HSC on channels the model lacks, HDEF with a mode the counter lacks (§3.3.1),
/// writes to SMB0 and to the read-only current positions SMD212/SMD242/SMD262 (§3.4.3.1,
/// set through SMD208 + SM201.4), a date the clock cannot hold (SET_RTC); PLS on a value an
/// earlier PLS left behind, its update bit clear (§3.4.2.2: named as kept, no register shows
/// it), and on a multi-segment profile table that breaks a rule of §3.4.2.1 (read back over
/// Modbus).
#[test]
fn every_refusal_reads_the_same_through_the_helper_and_in_process() {
    let srv = Server::start(&["--agent"]);
    let url = srv.url();
    let cases = [
        "set SMB67=16#85, SMW68=1000, SMD72=1; pls 0",
        "set SMB67=16#85, SMW68=1, SMD72=100; pls 0",
        "set SMB77=16#85, SMW78=0, SMD82=0; pls 1",
        "set SMB97=16#85, SMW98=500, SMD102=1; pls 2",
        "set SMB67=16#85, SMW68=2, SMD72=100; pls 0",
        "set SMB67=16#D3, SMW68=1, SMW70=0; pls 0",
        "set SMB67=16#00; pls 0",
        "set SMB67=16#00, SMB77=16#85; pls 0",
        "set SMB97=16#04; pls 2",
        "pls 3",
        "pstop 3",
        "hdef 0 5",
        "hdef 2 4",
        "hdef 1 11",
        "hdef 4 0",
        "hsc 4",
        "set SMB0=1",
        "set SMD212=5",
        "set SMD242=-7",
        "set SMD262=1",
        "set SMW214=3",
        "rtc set 2026-02-30T10:00:00",
        "rtc set 2026-13-01T10:00:00",
        // An update bit clear (§3.4.2.2, SM67.0 / SM67.2 «0 = нет»): PLS keeps the value an
        // earlier PLS loaded — here one a refused PLS loaded — which no register shows.
        "set SMB67=16#85, SMW68=1000, SMD72=1; pls 0\nset SMB67=16#81, SMW68=1000; pls 0",
        "set SMB77=16#85, SMW78=1, SMD82=100; pls 1\nset SMB77=16#84, SMD82=100; pls 1",
        "set SMB97=16#85, SMW98=1, SMD102=1; pls 2\nset SMB97=16#80; pls 2",
        "set SMB67=16#85, SMW68=1, SMD72=100; pls 0\nset SMB67=16#84, SMD72=1; pls 0",
        "set SMB67=16#D3, SMW68=1, SMW70=0; pls 0\nset SMB67=16#C2, SMW70=0; pls 0",
        // A multi-segment PTO (§3.4.2.1): the table PLS reads, its start in SMW168 ….
        "set SMW168=3000, SMB67=16#A0; pls 0",
        "set SMW168=9001, SMB67=16#A0; pls 0",
        "set VB3001=0, SMW168=3001, SMB67=16#A0; pls 0",
        "set VB3001=1, VW3002=1, VD3006=10, SMW168=3001, SMB67=16#A0; pls 0",
        "set VB3001=1, VW3002=100, VD3006=0, SMW168=3001, SMB67=16#A0; pls 0",
        "set VB3001=2, VW3002=100, VD3006=10, VW3010=1, VD3014=5, SMW178=3001, SMB77=16#A0; pls 1",
        "set VB3001=1, VW3002=2, VD3006=10, SMW168=3001, SMB67=16#A0; pls 0",
        "set VB3001=1, VW3002=2, VD3006=10, SMW218=3001, SMB97=16#A0; pls 2",
    ];
    let mut differ = Vec::new();
    for case in cases {
        // The served PLC keeps its state from case to case: every case starts with the pulse
        // channels' control bytes cleared, as the fresh simulator in process has them.
        let line = &format!("set SMB67=16#00, SMB77=16#00, SMB97=16#00; {case}");
        let helper = refusal(Some(&url), line);
        let local = refusal(None, line);
        assert!(!helper.0.is_empty(), "{line}: no message through the helper");
        // The second PLS of a two-line case meets the value the first one left: a kept value
        // is named as kept, a loaded one with its rule even when a kept one breaks a rule too.
        if case.contains('\n') {
            let loaded = case.ends_with("SMD72=1; pls 0");
            let want = if loaded { "pulse count 1 is below 2" } else { "kept from before" };
            assert!(helper.0.contains(want), "{line}: {}", helper.0);
        }
        if helper != local {
            differ.push(format!(
                "`{line}`\n  helper:     {} | hint: {}\n  in process: {} | hint: {}",
                helper.0, helper.1, local.0, local.1
            ));
        }
    }
    assert!(differ.is_empty(), "the routes word these refusals differently:\n{}", differ.join("\n"));
}
