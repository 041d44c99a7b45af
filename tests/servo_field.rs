//! The served Kinco drive simulator as field client code finds it: over a REAL pseudo-terminal
//! pair (`plcsh sim serve --servo-pty`), byte sequences re-created in this file from the
//! documented behaviour of public clients — a Python RS232 driver that picks the write code
//! from the value's magnitude, a C# library that writes each object at its own size and uses
//! controlword 0x103F, a C++ driver that clears its input buffer right after sending — plus
//! line timing measured on the pty, faults injected through the control socket, and the
//! diagnosis a user sees.
// Unix only: real pseudo-terminals (Windows has none; its COM ports are tested under Wine
// in tests/windows_serial.rs).
#![cfg(unix)]

mod common;
use common::*;
use plcsh::core::{Clock, ErrorKind, Value};
use plcsh::servo::objects::{self, ObjRef};
use plcsh::servo::sim::control;
use plcsh::session::open_url;
use serialport::SerialPort;
use std::io::{BufRead, Read, Write};
use std::path::PathBuf;
use std::time::{Duration, Instant};

/// A served simulator on a pty symlinked in a private directory.
struct Server {
    served: Served,
    link: PathBuf,
}

impl Server {
    fn start(tag: &str, extra: &[&str]) -> Server {
        let dir = std::env::temp_dir().join(format!("plcsh-field-{}-{tag}", std::process::id()));
        std::fs::create_dir_all(&dir).unwrap();
        let link = dir.join("ttyKINCO");
        let mut args = vec!["--servo-pty", link.to_str().unwrap()];
        args.extend_from_slice(extra);
        Server { served: serve(&args), link }
    }
    fn url(&self, params: &str) -> String {
        format!("kinco:{}?{params}", self.link.display())
    }
    fn control(&self, line: &str) -> serde_json::Value {
        let path = PathBuf::from(self.served.ready["servo_control"].as_str().expect("a control socket"));
        control::send(&path, line).unwrap_or_else(|e| panic!("{line}: {e}")).1
    }
}

/// A bare serial client: what the field code does with the port, byte for byte.
struct Client(serialport::TTYPort);

impl Client {
    fn open(srv: &Server) -> Client {
        let p = serialport::new(srv.link.to_str().unwrap(), 38_400).timeout(Duration::from_millis(500)).open_native();
        let mut p = p.expect("open the served pty");
        let _ = p.set_exclusive(false);
        Client(p)
    }
    fn send(&mut self, b: &[u8; 10]) {
        self.0.write_all(b).unwrap();
        self.0.flush().unwrap();
    }
    /// Ten bytes, waited for with a generous deadline (a loaded machine may deliver a reply
    /// late); `None` when they never come.
    fn recv(&mut self) -> Option<[u8; 10]> {
        self.recv_within(Duration::from_secs(10))
    }
    /// Ten bytes, or `None` when they do not come within `limit` (for a reply that must not
    /// come at all).
    fn recv_within(&mut self, limit: Duration) -> Option<[u8; 10]> {
        let mut got = [0u8; 10];
        let mut n = 0;
        let deadline = Instant::now() + limit;
        while n < 10 && Instant::now() < deadline {
            match self.0.read(&mut got[n..]) {
                Ok(k) => n += k,
                Err(e) if e.kind() == std::io::ErrorKind::TimedOut => {}
                Err(e) => panic!("{e}"),
            }
        }
        (n == 10).then_some(got)
    }
    fn xfer(&mut self, b: [u8; 10]) -> Option<[u8; 10]> {
        self.send(&b);
        self.recv()
    }
}

fn frame(id: u8, func: u8, index: u16, sub: u8, data: [u8; 4]) -> [u8; 10] {
    let i = index.to_le_bytes();
    let mut b = [id, func, i[0], i[1], sub, data[0], data[1], data[2], data[3], 0];
    b[9] = b[..9].iter().fold(0u8, |s, x| s.wrapping_add(*x)).wrapping_neg();
    b
}

fn read_req(id: u8, index: u16, sub: u8) -> [u8; 10] {
    frame(id, 0x40, index, sub, [0; 4])
}

/// The public Python driver's write: the controlword always as two bytes; otherwise
/// 0…255 as one byte (`2F`), -32768…32767 as a signed short (`2B`), else four bytes (`23`),
/// unused bytes zero — whatever the object's size.
fn python_write(id: u8, index: u16, sub: u8, value: i64) -> [u8; 10] {
    let v = value as i32 as u32;
    let b = v.to_le_bytes();
    if index == 0x6040 {
        frame(id, 0x2B, index, sub, [b[0], b[1], 0, 0])
    } else if (0..=0xFF).contains(&value) {
        frame(id, 0x2F, index, sub, [b[0], 0, 0, 0])
    } else if (-0x8000..=0x7FFF).contains(&value) {
        frame(id, 0x2B, index, sub, [b[0], b[1], 0, 0])
    } else {
        frame(id, 0x23, index, sub, b)
    }
}

/// The public C# library's write: the code from the object's bit length in its register table.
fn csharp_write(id: u8, index: u16, sub: u8, bits: u8, value: u32) -> [u8; 10] {
    let b = value.to_le_bytes();
    match bits {
        8 => frame(id, 0x2F, index, sub, [b[0], 0, 0, 0]),
        16 => frame(id, 0x2B, index, sub, [b[0], b[1], 0, 0]),
        _ => frame(id, 0x23, index, sub, b),
    }
}

/// A read reply decoded the way the Python driver does: by its own length code.
fn python_value(reply: [u8; 10]) -> Option<i64> {
    match reply[1] {
        0x4F => Some(reply[5] as i64),
        0x4B => Some(u16::from_le_bytes([reply[5], reply[6]]) as i64),
        0x43 => Some(u32::from_le_bytes([reply[5], reply[6], reply[7], reply[8]]) as i32 as i64),
        _ => None,
    }
}

fn abort_code(reply: [u8; 10]) -> Option<u32> {
    (reply[1] == 0x80).then(|| u32::from_le_bytes([reply[5], reply[6], reply[7], reply[8]]))
}

#[test]
fn magnitude_sized_writes_are_applied_when_lenient_and_refused_when_strict() {
    let srv = Server::start("lenient", &[]);
    let mut c = Client::open(&srv);
    // (object, value, the write code the Python driver picks, what reads back)
    let cases: &[(u16, u8, i64, u8, i64)] = &[
        (0x6060, 0, 1, 0x2F, 1),             // mode 1: one byte, the object's size
        (0x607A, 0, 200, 0x2F, 200),         // 32-bit target position as one byte
        (0x607A, 0, 1000, 0x2B, 1000),       // … as a short
        (0x607A, 0, -5, 0x2B, -5),           // … negative short, sign-extended
        (0x6081, 0, 100_000, 0x23, 100_000), // 32-bit profile velocity, four bytes
        (0x6083, 0, 255, 0x2F, 255),         // acceleration as one byte
        (0x60FF, 0, -100, 0x2B, -100),       // signed 32-bit target velocity as a short
        (0x6060, 0, -3, 0x2B, -3),           // mode -3 as a signed short into an 8-bit object
        (0x605A, 0, 6, 0x2F, 6),             // 16-bit quick-stop option as one byte
    ];
    for &(index, sub, v, code, back) in cases {
        let req = python_write(1, index, sub, v);
        assert_eq!(req[1], code, "{index:04X} = {v}: the client's code");
        let r = c.xfer(req).expect("a reply");
        assert_eq!(r[1], 0x60, "{index:04X}.{sub:02X} = {v} ({code:02X}) accepted: {r:02X?}");
        assert_eq!(r[5..9], req[5..9], "the acknowledgement echoes the data");
        let got = python_value(c.xfer(read_req(1, index, sub)).unwrap()).unwrap();
        let o = objects::lookup(index, sub).unwrap();
        let got = o.dtype.decode(got as u32 & (u32::MAX >> (32 - o.dtype.bits()))).as_i64();
        assert_eq!(got, back, "{index:04X}.{sub:02X} applied");
    }
    // Too big for the object: 300 into the 8-bit mode is "length too high".
    let r = c.xfer(python_write(1, 0x6060, 0, 300)).unwrap();
    assert_eq!(abort_code(r), Some(0x0607_0012));

    // plcsh's own driver sends exact sizes, so strict drives accept it (its own server: this
    // process does not open a port its raw client holds).
    let own = Server::start("strict-own", &["--servo-strict", "--servo-instant"]);
    let mut d = open_url(&own.url("id=1"), &Clock::following()).unwrap();
    let tp = d.operands().parse("target_position").unwrap()[0];
    let mode = d.operands().parse("operating_mode").unwrap()[0];
    d.write(&[(tp, Value::Int(1234)), (mode, Value::Int(-3))]).unwrap();
    assert_eq!(d.read(&[tp, mode]).unwrap(), vec![Value::Int(1234), Value::Int(-3)]);

    let strict = Server::start("strict", &["--servo-strict", "--servo-instant"]);
    assert_eq!(strict.served.ready["strict"], true);
    let mut c = Client::open(&strict);
    for &(index, sub, v, code, _) in cases {
        let r = c.xfer(python_write(1, index, sub, v)).unwrap();
        let exact = objects::lookup(index, sub).unwrap().dtype.bits()
            == [8, 16, 32][[0x2F, 0x2B, 0x23].iter().position(|x| *x == code).unwrap()];
        if exact {
            assert_eq!(r[1], 0x60, "{index:04X} = {v}: the right size is accepted when strict");
        } else {
            assert_eq!(abort_code(r), Some(0x0607_0010), "{index:04X} = {v} ({code:02X}) refused when strict");
        }
    }
    // The switch also works at run time through the control socket.
    strict.control("strict off");
    assert_eq!(c.xfer(python_write(1, 0x607A, 0, 7)).unwrap()[1], 0x60);
}

#[test]
fn controlword_103f_then_a_target_write_alone_starts_a_move() {
    let srv = Server::start("103f", &[]);
    let mut c = Client::open(&srv);
    // The C# library's sequence: mode, speed, power on, then 0x103F "absolute positioning
    // with target position"; every later target write is a move.
    for req in [
        csharp_write(1, 0x6060, 0, 8, 1),
        csharp_write(1, 0x6081, 0, 32, 819_200),
        csharp_write(1, 0x6040, 0, 16, 0x06),
        csharp_write(1, 0x6040, 0, 16, 0x0F),
        csharp_write(1, 0x6040, 0, 16, 0x103F),
    ] {
        assert_eq!(c.xfer(req).unwrap()[1], 0x60, "{req:02X?}");
    }
    for target in [3000i32, -2000] {
        assert_eq!(c.xfer(csharp_write(1, 0x607A, 0, 32, target as u32)).unwrap()[1], 0x60);
        let sw = python_value(c.xfer(read_req(1, 0x6041, 0)).unwrap()).unwrap();
        assert_eq!(sw & (1 << 10), 0, "moving after the target write alone (statusword {sw:04X})");
        let deadline = Instant::now() + Duration::from_secs(5);
        loop {
            let sw = python_value(c.xfer(read_req(1, 0x6041, 0)).unwrap()).unwrap();
            if sw & (1 << 10) != 0 {
                break;
            }
            assert!(Instant::now() < deadline, "target {target} not reached");
        }
        assert_eq!(python_value(c.xfer(read_req(1, 0x6063, 0)).unwrap()), Some(target as i64));
    }
}

#[test]
fn every_object_in_the_table_is_answered_with_its_size_code() {
    let srv = Server::start("objects", &["--servo-instant"]);
    let mut c = Client::open(&srv);
    for o in objects::OBJECTS.iter().filter(|o| o.readable()) {
        let r =
            c.xfer(read_req(1, o.index, o.sub)).unwrap_or_else(|| panic!("{} ({}) unanswered", o.name, o.address()));
        let want = match o.dtype.bits() {
            8 => 0x4F,
            16 => 0x4B,
            _ => 0x43,
        };
        assert_eq!(r[1], want, "{} ({}): reply code", o.name, o.address());
        assert_eq!(r[2..5], [o.index.to_le_bytes()[0], o.index.to_le_bytes()[1], o.sub]);
    }
    // The public FD5P manual's RS232 example object 2FF0.09 and a public client's first
    // frame, the quick-stop option 605A.00, are answered; an object outside the table is not.
    assert!(c.xfer(read_req(1, 0x2FF0, 9)).is_some());
    assert!(c.xfer(read_req(1, 0x605A, 0)).is_some());
    c.send(&read_req(1, 0x3FFF, 1));
    assert!(c.recv_within(Duration::from_millis(500)).is_none(), "an object outside the table is not answered");
    // Nor later: the next reply on the line is the next request's (a late answer to 3FFF.01,
    // however late, would come first), so no quiet window decides it.
    let r = c.xfer(read_req(1, 0x605A, 0)).expect("605A.00 answered");
    assert_eq!(r[2..5], [0x5A, 0x60, 0x00], "the reply after the unanswered request is 605A.00's: {r:02X?}");
}

/// 10 bytes × 10 bits each way.
fn wire(baud: f64) -> Duration {
    Duration::from_secs_f64(2.0 * 100.0 / baud)
}

fn turnarounds(c: &mut Client, n: usize) -> Vec<Duration> {
    let mut v: Vec<Duration> = (0..n)
        .map(|_| {
            let t = Instant::now();
            c.xfer(read_req(1, 0x6041, 0)).expect("a reply");
            t.elapsed()
        })
        .collect();
    v.sort();
    v
}

#[test]
fn line_timing_paces_replies_at_the_baud_rate_on_the_pty() {
    let paced = Server::start("paced", &["--servo-baud", "38400", "--servo-latency", "0"]);
    assert_eq!(paced.served.ready["servo_baud"], 38400);
    let mut c = Client::open(&paced);
    let p = turnarounds(&mut c, 30);
    assert!(p[0] >= wire(38_400.0), "fastest request/reply {:?} beats the wire time {:?}", p[0], wire(38_400.0));
    // The C++ driver's pattern: clear the input buffer right after sending. On a paced line
    // the reply is still on the wire then, so none is lost. (At 9600 baud: a 20 ms window,
    // so a test process preempted between its two calls on a loaded machine does not flake.)
    let slow_line = Server::start("clear", &["--servo-baud", "9600", "--servo-latency", "0"]);
    let mut c = Client::open(&slow_line);
    let mut lost = 0;
    for _ in 0..50 {
        c.send(&read_req(1, 0x6041, 0));
        c.0.clear(serialport::ClearBuffer::Input).unwrap();
        if c.recv().is_none() {
            lost += 1;
        }
    }
    assert_eq!(lost, 0, "replies lost to a clear right after sending");
    // Think-time adds to the wire time.
    let slow = Server::start("latency", &["--servo-baud", "115200", "--servo-latency", "4ms"]);
    let s = turnarounds(&mut Client::open(&slow), 10);
    assert!(s[0] >= wire(115_200.0) + Duration::from_millis(4), "{:?}", s[0]);
    // Instant replies: the software path only.
    let instant = Server::start("instant", &["--servo-instant"]);
    assert!(instant.served.ready["servo_baud"].is_null());
    let i = turnarounds(&mut Client::open(&instant), 30);
    println!(
        "pty request/reply, µs: paced 38400 min {:.0} median {:.0}; 115200 + 4 ms min {:.0}; instant min {:.0} median {:.0}",
        p[0].as_secs_f64() * 1e6,
        p[15].as_secs_f64() * 1e6,
        s[0].as_secs_f64() * 1e6,
        i[0].as_secs_f64() * 1e6,
        i[15].as_secs_f64() * 1e6
    );
    assert!(i[15] < p[15], "instant is faster than paced");
}

#[test]
fn faults_injected_through_the_control_socket_and_the_shell() {
    let srv = Server::start("faults", &["--servo-instant", "--servo-id", "1,2"]);
    assert!(srv.served.ready["servo_control"].as_str().unwrap().ends_with("ttyKINCO.ctl"));
    // From the shell: `servo sim fault …` on a kinco: device goes to LINK.ctl.
    let o = run(&["-d", &format!("ax={}", srv.url("id=2")), "--json", "-c", "servo ax sim fault no-reply count=2"], "");
    let l = json_lines(&o);
    assert_eq!(l[0]["ok"], true, "{l:?}");
    assert_eq!(l[0]["id"], 2);
    let mut d1 = open_url(&srv.url("id=1&timeout=100ms"), &Clock::following()).unwrap();
    let mut d2 = open_url(&srv.url("id=2&timeout=100ms"), &Clock::following()).unwrap();
    let sw = d1.operands().parse("statusword").unwrap()[0];
    assert!(d1.read(&[sw]).is_ok(), "drive 1 is not affected");
    for _ in 0..2 {
        let e = d2.read(&[sw]).unwrap_err();
        assert_eq!(e.kind, ErrorKind::Link);
        assert!(e.message.contains("no reply"), "{e}");
    }
    assert!(d2.read(&[sw]).is_ok(), "two requests, then the line is back");
    // Abort for one object.
    srv.control("id=2 fault abort target_position 16#06090030");
    let tp = d2.operands().parse("target_position").unwrap()[0];
    let e = d2.write(&[(tp, Value::Int(5))]).unwrap_err();
    assert_eq!(e.kind, ErrorKind::Refused);
    assert!(e.message.contains("16#06090030 — value range of parameter exceeded"), "{e}");
    d2.write(&[(tp, Value::Int(5))]).unwrap();
    // Bad checksum in the reply.
    srv.control("fault bad-checksum id=1");
    let e = d1.read(&[sw]).unwrap_err();
    assert_eq!(e.kind, ErrorKind::Link);
    assert!(e.message.contains("checksum"), "{e}");
    // A delayed reply within the timeout arrives late but arrives.
    srv.control("fault delay 60ms id=1");
    let t = Instant::now();
    d1.read(&[sw]).unwrap();
    assert!(t.elapsed() >= Duration::from_millis(60));
    // Drive fault: statusword fault bit and the code in the error objects.
    srv.control("fault drive 16#2310 id=1");
    let s: &mut dyn plcsh::servo::ServoOps = &mut plcsh::servo::ops(d1.as_mut()).unwrap();
    let status = plcsh::servo::ds402::status(s).unwrap();
    assert!(status.fault, "{status:?}");
    assert_eq!(s.read_raw(ObjRef::of(objects::named("error_code"))).unwrap(), 0x2310);
    assert_eq!(s.read_raw(ObjRef::of(objects::named("error_state"))).unwrap() & 1, 1);
    // Clear, and the line is healthy.
    srv.control("fault no-reply count=all");
    assert!(d1.read(&[sw]).is_err());
    srv.control("fault clear");
    assert!(d1.read(&[sw]).is_ok());
    // Refusals name what was wrong.
    let path = PathBuf::from(srv.served.ready["servo_control"].as_str().unwrap());
    let e = control::send(&path, "id=9 fault drive").unwrap_err();
    assert!(e.message.contains("no simulated drive has id 9"), "{e}");
    let e = control::send(&path, &"x".repeat(5000)).unwrap_err();
    assert!(e.message.contains("at most 4096 bytes"), "{e}");
    // A reply delayed beyond the timeout is silence (last: the served drive is busy meanwhile).
    srv.control("fault delay 300ms id=1");
    assert_eq!(d1.read(&[sw]).unwrap_err().kind, ErrorKind::Link);
}

#[test]
fn a_dropped_echo_and_a_wrong_echo_setting_are_diagnosed() {
    let looped = Server::start("loop", &["--servo-loop", "--servo-instant"]);
    // Looped line, client without echo=1: the "reply" is the request itself (the binary
    // first: this process opens the port below and keeps it).
    let o = run(&["-d", &format!("ax={}", looped.url("id=1")), "-c", "get ax:statusword"], "");
    let err = String::from_utf8_lossy(&o.stdout).to_string() + &String::from_utf8_lossy(&o.stderr);
    assert!(err.contains("the request itself") && err.contains("echo=1"), "{err}");
    let mut with_echo = open_url(&looped.url("id=1&echo=1&timeout=100ms"), &Clock::following()).unwrap();
    let sw = with_echo.operands().parse("statusword").unwrap()[0];
    assert!(with_echo.read(&[sw]).is_ok());
    looped.control("fault drop-echo");
    let e = with_echo.read(&[sw]).unwrap_err();
    assert!(e.message.contains("expected the echo") || e.message.contains("no echo"), "{e}");
    // Plain line, client with echo=1: the reply comes where the echo should.
    let plain = Server::start("noloop", &["--servo-instant"]);
    let o = run(&["-d", &format!("ax={}", plain.url("id=1&echo=1")), "-c", "get ax:statusword"], "");
    let err = String::from_utf8_lossy(&o.stdout).to_string() + &String::from_utf8_lossy(&o.stderr);
    assert!(err.contains("not in loop mode") && err.contains("echo=0"), "{err}");
    // An unknown function code is named as such.
    let o = run(&["-d", &format!("ax={}", plain.url("id=1")), "-c", "servo ax raw 01 99 41 60 00 00 00 00 00"], "");
    let err = String::from_utf8_lossy(&o.stdout).to_string() + &String::from_utf8_lossy(&o.stderr);
    assert!(err.contains("unknown function code 99"), "{err}");
}

#[test]
fn sim_serve_v_traces_servo_frames() {
    use std::process::Stdio;
    let dir = std::env::temp_dir().join(format!("plcsh-field-{}-trace", std::process::id()));
    std::fs::create_dir_all(&dir).unwrap();
    let link = dir.join("ttyKINCO");
    let mut child = plcsh()
        .args(["-v", "sim", "serve", "--servo-instant", "--servo-pty", link.to_str().unwrap()])
        .stdout(Stdio::piped())
        .stderr(Stdio::piped())
        .spawn()
        .unwrap();
    let mut ready = String::new();
    std::io::BufReader::new(child.stdout.take().unwrap()).read_line(&mut ready).unwrap();
    let (tx, rx) = std::sync::mpsc::channel();
    let err = child.stderr.take().unwrap();
    std::thread::spawn(move || {
        for l in std::io::BufReader::new(err).lines().map_while(Result::ok) {
            if tx.send(l).is_err() {
                break;
            }
        }
    });
    let srv_link = Server { served: Served { child, ready: serde_json::from_str(&ready).unwrap() }, link };
    let mut c = Client::open(&srv_link);
    c.xfer(read_req(1, 0x6041, 0)).unwrap();
    let mut lines = Vec::new();
    while let Ok(l) = rx.recv_timeout(Duration::from_secs(20)) {
        lines.push(l);
        if lines.iter().any(|l| l.contains("→ 01 4B 41 60 00 31 42 00 00 A0")) {
            break;
        }
    }
    assert!(lines.iter().any(|l| l.contains("← 01 40 41 60 00 00 00 00 00 1E")), "{lines:?}");
    assert!(lines.iter().any(|l| l.contains("→ 01 4B 41 60 00 31 42 00 00 A0")), "{lines:?}");
}

#[test]
fn the_fault_script_handles_a_served_drive_and_on_abort_runs_when_unhandled() {
    let srv = Server::start("lua", &[]);
    let script = concat!(env!("CARGO_MANIFEST_DIR"), "/scripts/servo_faults.lua");
    let dev = format!("servo={}", srv.url("id=1"));
    let o = run(&["-d", &dev, "run", script], "");
    assert!(o.status.success(), "{}\n{}", stdout(&o), String::from_utf8_lossy(&o.stderr));
    assert!(stdout(&o).contains("attempt 1 failed (link), retrying"), "{}", stdout(&o));
    let o = run(&["-d", &dev, "run", script, "unhandled"], "");
    let out = stdout(&o) + &String::from_utf8_lossy(&o.stderr);
    assert_eq!(o.status.code(), Some(1), "{out}");
    assert!(out.contains("on_abort: axis disabled"), "{out}");
    assert!(out.contains("16#06090030"), "{out}");
    // on_abort left the drive disabled and the line clear.
    let mut d = open_url(&srv.url("id=1"), &Clock::following()).unwrap();
    let st = plcsh::servo::ds402::status(&mut plcsh::servo::ops(d.as_mut()).unwrap()).unwrap();
    assert_eq!(st.state, "ready to switch on");
}

#[test]
fn pulses_raw_width_and_status_wording_from_the_shell() {
    // N pulses with gear 2/1 move the drive 2N increments (in-process command input).
    let o = run(
        &[
            "--time",
            "stepped",
            "--json",
            "-c",
            "servo mode pulse; set servo:gear_factor=2, servo:gear_divider=1; servo enable; servo sim pulses freq=1000 count=500; sim step 1s; get servo:position_actual",
        ],
        "",
    );
    let l = json_lines(&o);
    assert_eq!(l.last().unwrap()["values"][0]["value"], 1000, "{l:?}");
    // `servo raw` shows a sign-extended statusword at its 16 bits; `servo status` says
    // "quick stop: off" for bit 5 on an enabled drive.
    let o = run(
        &[
            "--time",
            "stepped",
            "-c",
            "servo enable; servo home method=35; sim step 1s; servo raw 01 40 41 60 00 00 00 00 00; servo status",
        ],
        "",
    );
    let out = stdout(&o);
    assert!(out.contains("6041.00 statusword = 5") && out.contains(", u16)"), "{out}");
    assert!(!out.contains("4294"), "{out}");
    assert!(out.contains("quick stop: off"), "{out}");
    assert!(!out.contains("active low"), "{out}");
    // A homing method the drive does not have ends in a homing error, which the wait reports.
    let o = run(&["--time", "stepped", "-c", "servo enable; servo home method=1; servo wait target"], "");
    assert!(!o.status.success());
    assert!(stdout(&o).contains("homing error") || String::from_utf8_lossy(&o.stderr).contains("homing error"));
}

fn hex(s: &str) -> [u8; 10] {
    let v: Vec<u8> = s.split_whitespace().map(|b| u8::from_str_radix(b, 16).unwrap()).collect();
    v.try_into().unwrap()
}

/// Sends a frame and checks the reply byte for byte.
fn expect(c: &mut Client, send: &str, reply: &str) {
    assert_eq!(c.xfer(hex(send)), Some(hex(reply)), "→ {send}");
}

fn poll_statusword(c: &mut Client, bit: u8) -> [u8; 10] {
    let deadline = Instant::now() + Duration::from_secs(5);
    loop {
        let r = c.xfer(hex("01 40 41 60 00 00 00 00 00 1E")).unwrap();
        if u16::from_le_bytes([r[5], r[6]]) & (1 << bit) != 0 {
            return r;
        }
        assert!(Instant::now() < deadline, "statusword bit {bit} never set: {r:02X?}");
    }
}

#[test]
fn the_fd5p_manuals_rs232_examples_replay_byte_for_byte() {
    // The public FD5P manual's RS232 chapter (§10): its 2FF0.09 example and table 10-1
    // (homing, position and velocity by RS232), frames and acknowledgements as printed.
    let srv = Server::start("fd5p", &[]);
    let mut c = Client::open(&srv);
    // 600 rpm into 2FF0.09 with a 4-byte write, as the manual describes it (its checksum computed
    // here); read back with the manual's printed frames: the drive answers with 2 bytes.
    // (The manual's read request carries stale data bytes; the drive ignores them.)
    expect(&mut c, "01 23 F0 2F 09 58 02 00 00 5A", "01 60 F0 2F 09 58 02 00 00 1D");
    expect(&mut c, "01 40 F0 2F 09 58 02 00 00 3D", "01 4B F0 2F 09 58 02 00 00 32");
    // Homing: enable, mode 6, method 33 (index pulse), the two homing speeds, then 0x1F.
    for (send, reply) in [
        ("01 2B 40 60 00 0F 00 00 00 25", "01 60 40 60 00 0F 00 00 00 F0"),
        ("01 2F 60 60 00 06 00 00 00 0A", "01 60 60 60 00 06 00 00 00 D9"),
        ("01 2F 98 60 00 21 00 00 00 B7", "01 60 98 60 00 21 00 00 00 86"),
        ("01 23 99 60 01 03 9D 36 00 0C", "01 60 99 60 01 03 9D 36 00 CF"),
        ("01 23 99 60 02 82 4E 1B 00 F6", "01 60 99 60 02 82 4E 1B 00 B9"),
        ("01 2B 40 60 00 1F 00 00 00 15", "01 60 40 60 00 1F 00 00 00 E0"),
    ] {
        expect(&mut c, send, reply);
    }
    // "bit15=1 indicates home is found"; 16-bit replies come sign-extended (FF FF), as printed.
    let r = poll_statusword(&mut c, 15);
    assert_eq!(r[7..9], [0xFF, 0xFF]);
    // Position: 0x2F, 0x4F, mode 1, target 50000, speed, acceleration, deceleration, 0x3F, 0x5F.
    for (send, reply) in [
        ("01 2B 40 60 00 2F 00 00 00 05", "01 60 40 60 00 2F 00 00 00 D0"),
        ("01 2B 40 60 00 4F 00 00 00 E5", "01 60 40 60 00 4F 00 00 00 B0"),
        ("01 2F 60 60 00 01 00 00 00 0F", "01 60 60 60 00 01 00 00 00 DE"),
        ("01 23 7A 60 00 50 C3 00 00 EF", "01 60 7A 60 00 50 C3 00 00 B2"),
        ("01 23 81 60 00 03 9D 36 00 25", "01 60 81 60 00 03 9D 36 00 E8"),
        ("01 23 83 60 00 6E A3 01 00 E7", "01 60 83 60 00 6E A3 01 00 AA"),
        ("01 23 84 60 00 6E A3 01 00 E6", "01 60 84 60 00 6E A3 01 00 A9"),
        ("01 2B 40 60 00 3F 00 00 00 F5", "01 60 40 60 00 3F 00 00 00 C0"),
        ("01 2B 40 60 00 5F 00 00 00 D5", "01 60 40 60 00 5F 00 00 00 A0"),
    ] {
        expect(&mut c, send, reply);
    }
    // "bit10 indicates target position reached" (the manual prints 01 4B 41 60 00 37 C4 FF FF 1A:
    // operation enabled, target reached, home found).
    let r = poll_statusword(&mut c, 10);
    assert_eq!((r[5] & 0x6F, r[6] & 0xC4), (0x27, 0xC4), "{r:02X?}");
    assert_eq!(python_value(c.xfer(read_req(1, 0x6063, 0)).unwrap()), Some(50_000));
    // Velocity: mode 3, target speed -1789570 DEC, 0x2F, acceleration, deceleration.
    for (send, reply) in [
        ("01 2F 60 60 00 03 00 00 00 0D", "01 60 60 60 00 03 00 00 00 DC"),
        ("01 23 FF 60 00 7E B1 E4 FF 6B", "01 60 FF 60 00 7E B1 E4 FF 2E"),
        ("01 2B 40 60 00 2F 00 00 00 05", "01 60 40 60 00 2F 00 00 00 D0"),
        ("01 23 83 60 00 6E A3 01 00 E7", "01 60 83 60 00 6E A3 01 00 AA"),
        ("01 23 84 60 00 6E A3 01 00 E6", "01 60 84 60 00 6E A3 01 00 A9"),
    ] {
        expect(&mut c, send, reply);
    }
    poll_statusword(&mut c, 10); // at speed
    assert_eq!(python_value(c.xfer(read_req(1, 0x606C, 0)).unwrap()), Some(-1_789_570));
}

#[test]
fn relative_moves_queue_behind_a_running_move_from_the_shell() {
    // `servo move rel` uses Kinco's 0x4F → 0x5F (bit 5 low): during a move it queues in the
    // drive's one-deep set-point buffer; a second one waits for the buffer to drain.
    let o = run(
        &[
            "--time",
            "stepped",
            "--json",
            "-c",
            "servo enable; servo move abs 100000 speed=100rpm; servo move rel 1000; servo move rel 1000; servo wait target timeout=60s; get servo:position_actual",
        ],
        "",
    );
    let l = json_lines(&o);
    assert_eq!(l.last().unwrap()["values"][0]["value"], 102_000, "{l:?}");
}

#[test]
fn halt_from_the_shell_brakes_holds_and_resumes() {
    let o = run(
        &[
            "--time",
            "stepped",
            "--json",
            "-c",
            "servo enable; servo jog 60rpm; sim step 1s; servo halt; sim step 1s; get servo:velocity_actual; servo halt off; sim step 1s; get servo:velocity_actual",
        ],
        "",
    );
    let l = json_lines(&o);
    let v: Vec<&serde_json::Value> = l.iter().filter(|j| j["cmd"] == "get").map(|j| &j["values"][0]["value"]).collect();
    assert_eq!(v, [&serde_json::json!(0), &serde_json::json!(163_840)], "{l:?}");
    let halt = l.iter().find(|j| j["halt"] == true).unwrap();
    assert_eq!(halt["controlword"], 0x10F);
}

#[test]
fn stopping_the_server_removes_the_link_and_the_control_socket() {
    let srv = Server::start("cleanup", &["--servo-instant"]);
    let ctl = PathBuf::from(srv.served.ready["servo_control"].as_str().unwrap());
    let link = srv.link.clone();
    assert!(link.exists() && ctl.exists());
    drop(srv); // SIGTERM, then wait for the process
    assert!(!link.exists() && std::fs::symlink_metadata(&link).is_err(), "link left behind");
    assert!(!ctl.exists(), "control socket left behind");
}
