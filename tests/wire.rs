//! The K2 over the wire: the real `plcsh sim serve` process, talked to by plcsh's
//! wire driver over Modbus TCP, Modbus RTU on the server's pseudo-terminal, and RTU over
//! TCP; raw tokio-modbus requests for the server's exception codes.
// Unix only: real pseudo-terminals (Windows has none; its COM ports are tested under Wine
// in tests/windows_serial.rs).
#![cfg(unix)]

mod common;
use common::*;

use plcsh::core::{Clock, ErrorKind, Value};
use plcsh::session::{Session, SetItem};
use serde_json::Value as Json;
use std::path::PathBuf;
use tokio_modbus::prelude::*;

/// A running `plcsh sim serve` on every transport, stopped on drop.
struct Server {
    served: Served,
    ready: Json,
    link: PathBuf,
}

static NEXT: std::sync::atomic::AtomicUsize = std::sync::atomic::AtomicUsize::new(0);

impl Server {
    /// Starts the server on every transport (ports chosen by the system) and waits for
    /// its readiness line.
    fn start(model: &str, tcp: &str) -> Server {
        let n = NEXT.fetch_add(1, std::sync::atomic::Ordering::Relaxed);
        let link = std::env::temp_dir().join(format!("plcsh-wire-{}-{n}", std::process::id()));
        let served = serve(&["--tcp", tcp, "--rtu-tcp", "0", "--rtu-pty", link.to_str().unwrap(), "--model", model]);
        let ready = served.ready.clone();
        Server { served, ready, link }
    }

    fn tcp(&self) -> String {
        self.ready["tcp"].as_str().unwrap().to_string()
    }

    fn urls(&self, params: &str) -> Vec<String> {
        vec![
            format!("tcp://{}?{params}", self.tcp()),
            format!("rtu:{}?baud=115200&{params}", self.link.display()),
            format!("rtu+tcp://{}?{params}", self.ready["rtu_tcp"].as_str().unwrap()),
        ]
    }
}

fn session(urls: &[(&str, &str)]) -> Session {
    let mut s = Session::new(Clock::stepped());
    for (name, url) in urls {
        s.open(name, url).unwrap_or_else(|e| panic!("open {url}: {e}"));
    }
    s
}

fn set(s: &mut Session, items: &[(&str, &str)]) {
    let items: Vec<SetItem> = items
        .iter()
        .map(|(o, v)| SetItem { operand: o.to_string(), value: v.to_string(), column: 0, value_column: 0 })
        .collect();
    s.set(&items).unwrap_or_else(|e| panic!("set: {e}"));
}

fn get(s: &mut Session, ops: &[&str]) -> Vec<Value> {
    s.get(ops).unwrap_or_else(|e| panic!("get {ops:?}: {e}")).into_iter().map(|(_, r)| r.value).collect()
}

fn int(v: i64) -> Value {
    Value::Int(v)
}

#[test]
fn every_area_and_size_round_trips_over_tcp_rtu_pty_and_rtu_over_tcp() {
    let srv = Server::start("K209EA-50DX", "0");
    for (k, url) in srv.urls("model=K209EA-50DX").iter().enumerate() {
        let mut s = session(&[("plc", url)]);
        // A different value set per transport, so each transport proves its own writes.
        let b = 16 * k as i64;
        let items: Vec<(String, String)> = [
            ("QB0", format!("{}", 0x58 + b)),
            ("Q0.1", "1".to_string()),
            ("QW1", "16#0102".to_string()),
            ("M100.7", "1".to_string()),
            ("MB200", format!("{}", 0xA5 - b)),
            ("MW300", "16#BEEF".to_string()),
            ("MD400", "16#12345678".to_string()),
            ("K4M500.4", "16#F00D".to_string()),
            ("V1000.3", "1".to_string()),
            ("VB1100", format!("{}", 200 + k as i64)),
            ("VB1201", format!("{}", 100 + k as i64)),
            ("VW1300", format!("{}", 40000 + k as i64)),
            ("VW1401", "16#ABCD".to_string()),
            ("VD1500", format!("{}", 3_000_000_000u64 + k as u64)),
            ("VD1601", "16#CAFEBABE".to_string()),
            ("VD1700/DINT", format!("DI#{}", -123_456 - k as i64)),
            ("VD1800/REAL", "REAL#-2.5".to_string()),
            ("VW1900/INT", "INT#-300".to_string()),
            ("VB2001/SINT", "-7".to_string()),
            ("AQW0", format!("{}", -1000 - k as i64)),
            ("AQW2", "INT#32767".to_string()),
        ]
        .into_iter()
        .map(|(o, v)| (o.to_string(), v))
        .collect();
        let pairs: Vec<(&str, &str)> = items.iter().map(|(o, v)| (o.as_str(), v.as_str())).collect();
        set(&mut s, &pairs);
        let ops: Vec<&str> = items.iter().map(|(o, _)| o.as_str()).collect();
        let got = get(&mut s, &ops);
        let want = vec![
            int(0x5A + b),
            Value::Bool(true),
            int(0x0102),
            Value::Bool(true),
            int(0xA5 - b),
            int(0xBEEF),
            int(0x12345678),
            int(0xF00D),
            Value::Bool(true),
            int(200 + k as i64),
            int(100 + k as i64),
            int(40000 + k as i64),
            int(0xABCD),
            int(3_000_000_000 + k as i64),
            int(0xCAFEBABE),
            int(-123_456 - k as i64),
            Value::Real(-2.5),
            int(-300),
            int(-7),
            int(-1000 - k as i64),
            int(32767),
        ];
        assert_eq!(got, want, "{url}");
        // The bytes land where the S7 layout puts them.
        assert_eq!(
            get(&mut s, &["QB2", "VB1401", "VB1402", "VW1600", "VB1604"]),
            vec![int(0x02), int(0xAB), int(0xCD), int(0x00CA), int(0xBE)]
        );
        assert_eq!(get(&mut s, &["MB501", "MB500"]), vec![int(0x00), int(0xD0)], "K4M500.4 starts at bit 4");
        // Inputs are read over FC 02 and FC 04 (all zero on an idle simulator).
        assert_eq!(get(&mut s, &["I0.0", "IB2", "AIW0", "AIW10"]), vec![Value::Bool(false), int(0), int(0), int(0)]);
    }
}

#[test]
fn thirty_two_bit_values_in_both_word_orders() {
    let srv = Server::start("K205-16DT", "0");
    let tcp = srv.tcp();
    let hi = format!("tcp://{tcp}?model=K205-16DT");
    let lo = format!("rtu:{}?baud=115200&model=K205-16DT&word_order=low-first", srv.link.display());
    let mut s = session(&[("hi", &hi), ("lo", &lo)]);
    // High word first (the default, S7 order): VD200's high word is register 200 = VW200.
    set(&mut s, &[("hi:VD200", "16#11223344")]);
    assert_eq!(get(&mut s, &["hi:VW200", "hi:VW202", "lo:VD200"]), vec![int(0x1122), int(0x3344), int(0x33441122)]);
    // Low word first: the low word goes in the lower register.
    set(&mut s, &[("lo:VD300", "16#11223344"), ("lo:VD401", "16#A1B2C3D4"), ("lo:VD500/REAL", "REAL#1.5")]);
    assert_eq!(get(&mut s, &["hi:VW300", "hi:VW302"]), vec![int(0x3344), int(0x1122)]);
    assert_eq!(
        get(&mut s, &["lo:VD300", "lo:VD401", "lo:VD500/REAL"]),
        vec![int(0x11223344), int(0xA1B2C3D4), Value::Real(1.5)]
    );
    assert_eq!(get(&mut s, &["hi:VW401", "hi:VW403"]), vec![int(0xC3D4), int(0xA1B2)]);
    // Raw registers agree (a third-party client's view).
    let rt = tokio::runtime::Builder::new_current_thread().enable_all().build().unwrap();
    let regs = rt.block_on(async {
        let mut c = tcp::connect_slave(tcp.parse().unwrap(), Slave(1)).await.unwrap();
        c.read_holding_registers(100 + 150, 2).await.unwrap().unwrap()
    });
    assert_eq!(regs, vec![0x3344, 0x1122]);
}

#[test]
fn bit_and_byte_writes_leave_their_neighbours_alone() {
    let srv = Server::start("K205-16DT", "0");
    for url in srv.urls("model=K205-16DT") {
        let mut s = session(&[("plc", &url)]);
        set(&mut s, &[("VW10", "16#FFFF"), ("MB5", "16#FF"), ("QB1", "16#FF"), ("VW20", "16#1234")]);
        set(&mut s, &[("V10.0", "0")]);
        assert_eq!(get(&mut s, &["VW10"]), vec![int(0xFEFF)], "{url}: V10.0 is bit 8 of VW10");
        set(&mut s, &[("V11.7", "0"), ("M5.3", "0"), ("Q1.0", "0")]);
        assert_eq!(get(&mut s, &["VW10", "MB5", "QB1"]), vec![int(0xFE7F), int(0xF7), int(0xFE)], "{url}");
        set(&mut s, &[("VB21", "16#AA")]);
        assert_eq!(get(&mut s, &["VW20"]), vec![int(0x12AA)], "{url}");
        // Several partial writes to one register in one batch, in order.
        set(&mut s, &[("VB20", "1"), ("VB21", "2"), ("V20.7", "1")]);
        assert_eq!(get(&mut s, &["VW20"]), vec![int(0x8102)], "{url}");
        set(&mut s, &[("K1M5.2", "0")]);
        assert_eq!(get(&mut s, &["MB5"]), vec![int(0xC3)], "{url}");
    }
}

#[test]
fn limits_and_bounds_answer_with_the_right_exception_codes() {
    let srv = Server::start("K205-16DT", "0");
    let rt = tokio::runtime::Builder::new_current_thread().enable_all().build().unwrap();
    let tcp_addr = srv.tcp().parse().unwrap();
    let link = srv.link.clone();
    rt.block_on(async {
        let tcp_ctx = tcp::connect_slave(tcp_addr, Slave(1)).await.unwrap();
        let port = tokio_serial::SerialStream::open(&tokio_serial::new(link.to_string_lossy(), 115200)).unwrap();
        let rtu_ctx = rtu::attach_slave(port, Slave(1));
        for mut c in [tcp_ctx, rtu_ctx] {
            use ExceptionCode::*;
            // Limits (§3.2.1): read words 100, read bits 1600, write bits 800, write words 100.
            assert!(c.read_holding_registers(100, 100).await.unwrap().is_ok());
            assert_eq!(c.read_holding_registers(100, 101).await.unwrap(), Err(IllegalDataValue));
            assert_eq!(c.read_input_registers(100, 101).await.unwrap(), Err(IllegalDataValue));
            assert!(c.read_coils(320, 1600).await.unwrap().is_ok());
            assert_eq!(c.read_coils(320, 1601).await.unwrap(), Err(IllegalDataValue));
            assert_eq!(c.read_discrete_inputs(320, 1601).await.unwrap(), Err(IllegalDataValue));
            assert_eq!(c.write_multiple_coils(320, &[true; 801]).await.unwrap(), Err(IllegalDataValue));
            assert!(c.write_multiple_coils(320, &[false; 800]).await.unwrap().is_ok());
            assert_eq!(c.write_multiple_registers(100, &[0; 101]).await.unwrap(), Err(IllegalDataValue));
            // Bounds: V ends at register 2147 on the K205; nothing between 16 and 319 in coils.
            assert!(c.read_holding_registers(2147, 1).await.unwrap().is_ok());
            assert_eq!(c.read_holding_registers(2140, 10).await.unwrap(), Err(IllegalDataAddress));
            assert_eq!(c.write_single_register(2148, 1).await.unwrap(), Err(IllegalDataAddress));
            assert_eq!(c.read_coils(100, 1).await.unwrap(), Err(IllegalDataAddress));
            assert_eq!(c.write_single_coil(8512, true).await.unwrap(), Err(IllegalDataAddress));
            assert_eq!(c.read_input_registers(0, 1).await.unwrap(), Err(IllegalDataAddress), "no AI on K205");
            // Function codes the K2 does not list (§3.2.1): 22 and 23.
            assert_eq!(c.masked_write_register(100, 0xFF, 0).await.unwrap(), Err(IllegalFunction));
            assert_eq!(c.read_write_multiple_registers(100, 1, 100, &[1]).await.unwrap(), Err(IllegalFunction));
            // A user-defined function code (65), which a K2 does not implement.
            let diag = Request::Custom(0x41, std::borrow::Cow::Borrowed(&[0x00, 0x00, 0xA5, 0x37]));
            assert_eq!(c.call(diag).await.unwrap(), Err(IllegalFunction));
            // The connection still serves after all these refusals.
            assert!(c.read_holding_registers(100, 1).await.unwrap().is_ok());
        }
    });
    // The driver names the exception and the operand: a K209M's V area is larger than the K205's.
    let mut s = session(&[("plc", &format!("tcp://{}?model=K209M-56DT", srv.tcp()))]);
    let e = s.get(&["VW8000"]).unwrap_err();
    assert_eq!(e.kind, ErrorKind::Refused, "{e}");
    assert_eq!(e.operand.as_deref(), Some("VW8000"));
    assert!(e.message.contains("illegal data address") && e.message.contains("exception 02"), "{e}");
    assert!(e.hint.as_deref().unwrap().contains("model="), "{e}");
}

#[test]
fn a_wrong_unit_id_gets_no_answer_and_the_message_says_what_to_check() {
    let srv = Server::start("K205-16DT", "0");
    for url in srv.urls("model=K205-16DT&unit=7&timeout=150&retries=1") {
        let mut s = session(&[("plc", &url)]);
        let e = s.get(&["VW0"]).unwrap_err();
        assert_eq!(e.kind, ErrorKind::Link, "{url}: {e}");
        assert!(e.message.contains("did not answer") && e.message.contains("unit 7"), "{url}: {e}");
        assert!(e.message.contains("2 attempts"), "{url}: {e}");
        assert!(e.hint.as_deref().unwrap().contains("unit id"), "{url}: {e}");
        assert_eq!(e.operand.as_deref(), Some("VW0"));
        assert_eq!(e.device.as_deref(), Some("plc"));
    }
}

/// The no-reply message keeps the timeout the user gave, to the microsecond: `timeout=150.5`
/// is `150.5 ms`, not `150 ms`.
#[test]
fn a_no_reply_message_keeps_the_timeout_the_user_gave() {
    let srv = Server::start("K205-16DT", "0");
    for url in srv.urls("model=K205-16DT&unit=7&timeout=150.5&retries=0") {
        let mut s = session(&[("plc", &url)]);
        let e = s.get(&["VW0"]).unwrap_err();
        assert!(e.message.contains("no reply from unit 7 within 150.5 ms"), "{url}: {e}");
    }
}

#[test]
fn sm_t_and_c_are_refused_before_anything_is_sent() {
    let srv = Server::start("K205-16DT", "0");
    let url = format!("tcp://{}?model=K205-16DT", srv.tcp());
    let o = run(&["--json", "-v", "-d", &url, "-c", "get VW0 SMB67"], "");
    let lines = json_lines(&o);
    assert_eq!(lines[0]["ok"], false);
    assert_eq!(lines[0]["error"]["kind"], "unsupported");
    assert_eq!(lines[0]["error"]["operand"], "SMB67");
    assert!(lines[0]["error"]["message"].as_str().unwrap().contains("not in the K2 Modbus map"));
    assert!(lines[0]["error"]["hint"].as_str().unwrap().contains("helper program"));
    // A batch write with one bad item sends nothing: VW0 stays 0.
    let o = run(&["--json", "-d", &url, "-c", "set VW0=5, T3=1"], "");
    assert_eq!(json_lines(&o)[0]["error"]["operand"], "T3");
    let o = run(&["--json", "-v", "-d", &url, "-c", "get VW0"], "");
    let lines = json_lines(&o);
    assert_eq!(lines[0]["values"][0]["value"], 0);
    assert_eq!(lines[0]["requests"], 1);
}

#[test]
fn fifty_words_over_vw0_to_vw400_take_three_requests_through_the_binary() {
    let srv = Server::start("K205-16DT", "0");
    let url = format!("tcp://{}?model=K205-16DT", srv.tcp());
    // VW0, VW8 … VW384 and VW400: registers 100…300; one request reads at most 100
    // registers, and no 100-register window holds both register 200 and register 300.
    let words: Vec<String> = (0..49).map(|k| format!("VW{}", 8 * k)).chain(["VW400".to_string()]).collect();
    let cmd = format!("set VW8=8, VW400=400; get {}", words.join(" "));
    let o = run(&["--json", "-v", "-d", &url, "-c", &cmd], "");
    let lines = json_lines(&o);
    assert!(o.status.success(), "{}", stdout(&o));
    assert_eq!(lines[0]["requests"], 2, "two writes that are not neighbours");
    assert_eq!(lines[1]["values"].as_array().unwrap().len(), 50);
    assert_eq!(lines[1]["values"][1]["value"], 8);
    assert_eq!(lines[1]["values"][49]["value"], 400);
    assert_eq!(lines[1]["requests"], 3);
    let o = run(&["--json", "-v", "-d", &url, "-c", "get VW0..VW198 M0.0..M199.7"], "");
    assert_eq!(json_lines(&o)[0]["requests"], 2, "100 registers and 1600 coils: one request each");
}

#[test]
fn a_dropped_tcp_connection_is_reopened() {
    let srv = Server::start("K205-16DT", "0");
    let tcp = srv.tcp();
    let mut s = session(&[("plc", &format!("tcp://{tcp}?model=K205-16DT&timeout=500"))]);
    set(&mut s, &[("VW0", "42")]);
    drop(srv);
    // A new server on the same port: the driver's connection to the old one is dead.
    let srv2 = Server::start("K205-16DT", &tcp);
    assert_eq!(srv2.tcp(), tcp);
    assert_eq!(get(&mut s, &["VW0"]), vec![int(0)], "a fresh simulator answers after the reconnect");
}

#[test]
fn sigterm_stops_the_server_cleanly_and_removes_the_link() {
    let mut srv = Server::start("K205-16DT", "0");
    let pid = nix::unistd::Pid::from_raw(srv.served.child.id() as i32);
    assert!(srv.link.exists());
    nix::sys::signal::kill(pid, nix::sys::signal::Signal::SIGTERM).unwrap();
    let status = srv.served.child.wait().unwrap();
    assert!(status.success(), "{status:?}");
    assert!(!srv.link.exists(), "the pty symlink is removed");
}

/// With `--time stepped` and a device on a wire, `plcsh.sleep` and `wait_until`'s timeout
/// wait in real time (a timeout at a real machine must not expire in no time); the virtual
/// clock moves by the same amount. Checked as a lower bound on the wall time taken.
#[test]
fn stepped_waits_with_a_wire_device_wait_in_real_time() {
    let srv = Server::start("K205-16DT", "0");
    let dir = std::env::temp_dir().join(format!("plcsh-wire-wait-{}", std::process::id()));
    std::fs::create_dir_all(&dir).unwrap();
    let script = dir.join("wait.lua");
    std::fs::write(
        &script,
        "local t0 = plcsh.now()\nplcsh.sleep(400)\nlocal ok, e = pcall(plcsh.wait_until, function() return plc.VW0 == 12345 end, {timeout=400})\nassert(not ok and tostring(e):match('still false'), tostring(e))\nprint(plcsh.now() - t0 >= 800)\n",
    )
    .unwrap();
    let url = format!("plc=tcp://{}", srv.tcp());
    let start = std::time::Instant::now();
    let o = run(&["--time", "stepped", "--device", &url, "run", script.to_str().unwrap()], "");
    let took = start.elapsed();
    assert!(o.status.success(), "{}", both(&o));
    assert_eq!(stdout(&o), "true\n", "the virtual clock moved with the waits");
    assert!(took >= std::time::Duration::from_millis(800), "the waits took {took:?} of real time");
}
