//! `plcsh sim serve` holds up against hostile or careless clients, over real loopback
//! sockets and a real pseudo-terminal: malformed requests get the exception the Modbus
//! specification requires on every transport, unit 0xFF is answered on TCP, a damaged RTU
//! frame costs only itself, idle and surplus connections are closed, running out of file
//! descriptors does not end the server, and the servo pty's link is removed on a signal.
// Unix only: real pseudo-terminals (Windows has none; its COM ports are tested under Wine
// in tests/windows_serial.rs).
#![cfg(unix)]

mod common;
use common::*;

use std::io::{Read, Write};
use std::net::TcpStream;
use std::path::PathBuf;
use std::process::Stdio;
use std::time::{Duration, Instant};

fn crc16(data: &[u8]) -> [u8; 2] {
    let mut crc = 0xFFFFu16;
    for b in data {
        crc ^= *b as u16;
        for _ in 0..8 {
            crc = if crc & 1 != 0 { (crc >> 1) ^ 0xA001 } else { crc >> 1 };
        }
    }
    crc.to_le_bytes()
}

fn rtu(unit: u8, pdu: &[u8]) -> Vec<u8> {
    let mut f = vec![unit];
    f.extend_from_slice(pdu);
    let c = crc16(&f);
    f.extend(c);
    f
}

fn mbap(tid: u16, unit: u8, pdu: &[u8]) -> Vec<u8> {
    let mut f = tid.to_be_bytes().to_vec();
    f.extend([0, 0]);
    f.extend((pdu.len() as u16 + 1).to_be_bytes());
    f.push(unit);
    f.extend_from_slice(pdu);
    f
}

/// Reads one Modbus TCP reply: (transaction id, PDU).
fn tcp_reply(s: &mut TcpStream) -> (u16, Vec<u8>) {
    let mut head = [0u8; 7];
    s.read_exact(&mut head).expect("a reply header");
    let len = u16::from_be_bytes([head[4], head[5]]) as usize;
    let mut pdu = vec![0u8; len - 1];
    s.read_exact(&mut pdu).expect("a reply PDU");
    (u16::from_be_bytes([head[0], head[1]]), pdu)
}

/// Reads an RTU reply of `n` bytes from any byte stream and checks its CRC.
fn rtu_reply(r: &mut dyn Read, n: usize) -> Vec<u8> {
    let mut f = vec![0u8; n];
    r.read_exact(&mut f).expect("an RTU reply");
    assert_eq!(crc16(&f[..n - 2]), [f[n - 2], f[n - 1]], "reply CRC: {f:02X?}");
    f
}

fn connect(addr: &str) -> TcpStream {
    let s = TcpStream::connect(addr).unwrap();
    s.set_read_timeout(Some(Duration::from_secs(5))).unwrap();
    s
}

/// A raw pty client: the served link opened and put in raw mode.
fn open_pty(link: &std::path::Path) -> std::fs::File {
    use nix::sys::termios;
    let f = std::fs::OpenOptions::new().read(true).write(true).open(link).unwrap();
    let mut t = termios::tcgetattr(&f).unwrap();
    termios::cfmakeraw(&mut t);
    termios::tcsetattr(&f, termios::SetArg::TCSANOW, &t).unwrap();
    f
}

fn link(tag: &str) -> PathBuf {
    let d = std::env::temp_dir().join(format!("plcsh-servers-{}-{tag}", std::process::id()));
    std::fs::create_dir_all(&d).unwrap();
    d.join("link")
}

/// The malformed requests and the exception each must get.
const MALFORMED: &[(&[u8], u8)] = &[
    (&[0x2B, 0x0E, 0x01, 0x00], 0x01),       // MEI read device id: not a K2 function
    (&[0x03, 0x00, 0x32, 0x00, 0x01], 0x02), // register 50: no area there
    (&[0x05, 0x00, 0x00, 0x12, 0x34], 0x03), // FC 05 with an illegal coil value
    (&[0x0F, 0x00, 0x01, 0x00, 0x10, 0x01, 0xFF], 0x03), // 16 coils need 2 bytes, 1 carried
    // Quantity 0 with byte count 0, as pymodbus encodes `write_coils(1, [])` and
    // `write_registers(100, [])`: the application protocol V1.1b3 §6.11/§6.12 allows
    // 1…0x7B0 coils and 1…123 registers, anything else is exception 03.
    (&[0x0F, 0x00, 0x01, 0x00, 0x00, 0x00], 0x03),
    (&[0x10, 0x00, 0x64, 0x00, 0x00, 0x00], 0x03),
    // The same with data after a byte count of 0 (on RTU the CRC is valid over the whole
    // frame, so its end is the silence after it, not where the byte count says).
    (&[0x10, 0x00, 0x64, 0x00, 0x00, 0x00, 0x12, 0x34], 0x03),
    (&[0x0F, 0x00, 0x01, 0x00, 0x00, 0x00, 0xFF], 0x03),
];

/// A valid read of VW0 (register 100) and its reply's data.
const READ_VW0: &[u8] = &[0x03, 0x00, 0x64, 0x00, 0x01];

#[test]
fn malformed_requests_get_exceptions_01_02_03_on_every_transport() {
    let pty = link("exc");
    let served = serve(&["--tcp", "0", "--rtu-tcp", "0", "--rtu-pty", pty.to_str().unwrap(), "--state", "none"]);
    // Modbus TCP.
    let mut t = connect(served.ready["tcp"].as_str().unwrap());
    for (i, (pdu, code)) in MALFORMED.iter().enumerate() {
        t.write_all(&mbap(i as u16, 1, pdu)).unwrap();
        let (tid, reply) = tcp_reply(&mut t);
        assert_eq!((tid, reply), (i as u16, vec![pdu[0] | 0x80, *code]), "TCP {pdu:02X?}");
    }
    t.write_all(&mbap(9, 1, READ_VW0)).unwrap();
    assert_eq!(tcp_reply(&mut t), (9, vec![0x03, 0x02, 0x00, 0x00]), "the connection still serves");
    // RTU over TCP, then RTU on the pty.
    let mut g = connect(served.ready["rtu_tcp"].as_str().unwrap());
    let mut p = open_pty(&pty);
    for (name, s) in [("RTU over TCP", &mut g as &mut dyn ReadWrite), ("RTU", &mut p as &mut dyn ReadWrite)] {
        for (pdu, code) in MALFORMED {
            s.write_all(&rtu(1, pdu)).unwrap();
            let f = rtu_reply(s, 5);
            assert_eq!(&f[..3], &[1, pdu[0] | 0x80, *code], "{name} {pdu:02X?}");
        }
        s.write_all(&rtu(1, READ_VW0)).unwrap();
        assert_eq!(&rtu_reply(s, 7)[..5], &[1, 3, 2, 0, 0], "{name}: still serving");
    }
}

trait ReadWrite: Read + Write {}
impl<T: Read + Write> ReadWrite for T {}

#[test]
fn unit_ff_is_this_device_on_tcp_unless_strict() {
    let served = serve(&["--tcp", "0", "--state", "none"]);
    let mut t = connect(served.ready["tcp"].as_str().unwrap());
    t.write_all(&mbap(1, 0xFF, READ_VW0)).unwrap();
    assert_eq!(tcp_reply(&mut t), (1, vec![0x03, 0x02, 0x00, 0x00]));
    let strict = serve(&["--tcp", "0", "--strict-unit", "--state", "none"]);
    let mut t = connect(strict.ready["tcp"].as_str().unwrap());
    t.write_all(&mbap(1, 0xFF, READ_VW0)).unwrap();
    t.write_all(&mbap(2, 1, READ_VW0)).unwrap();
    assert_eq!(tcp_reply(&mut t).0, 2, "unit 0xFF got no reply; unit 1 did");
}

#[test]
fn a_bad_crc_on_the_pty_costs_only_that_request() {
    let pty = link("crc");
    let served = serve(&["--rtu-pty", pty.to_str().unwrap(), "--state", "none"]);
    let mut p = open_pty(&pty);
    let mut write = rtu(1, &[0x06, 0x00, 0x64, 0x12, 0x34]); // VW0 = 16#1234
    let _ = served;
    for round in 0..5 {
        let mut bad = rtu(1, &[0x06, 0x00, 0x64, 0x00, 0x07]);
        bad[7] ^= 0x55; // damaged CRC: the slave stays silent
        p.write_all(&bad).unwrap();
        // A truncated FC 16 whose byte count promises more than comes, in the same burst.
        p.write_all(&[0x01, 0x10, 0x00, 0x64, 0x00, 0x7B, 0xF6, 0x11]).unwrap();
        std::thread::sleep(Duration::from_millis(60)); // the line falls silent (framing, §2.5.1.1)
        write[5] = round;
        let c = crc16(&write[..6]);
        write[6..].copy_from_slice(&c);
        p.write_all(&write).unwrap();
        assert_eq!(rtu_reply(&mut p, 8), write, "round {round}: the good request is answered (echo)");
        p.write_all(&rtu(1, READ_VW0)).unwrap();
        assert_eq!(&rtu_reply(&mut p, 7)[3..5], &[0x12, round], "round {round}: and nothing else was written");
    }
}

#[test]
fn idle_and_surplus_connections_are_closed() {
    let served = serve(&["--tcp", "0", "--idle-timeout", "300ms", "--max-connections", "2", "--state", "none"]);
    let addr = served.ready["tcp"].as_str().unwrap();
    let mut a = connect(addr);
    let mut b = connect(addr);
    for s in [&mut a, &mut b] {
        s.write_all(&mbap(1, 1, READ_VW0)).unwrap();
        assert_eq!(tcp_reply(s).0, 1);
    }
    // A third is closed at once.
    let mut c = connect(addr);
    let _ = c.write_all(&mbap(1, 1, READ_VW0));
    let mut buf = [0u8; 16];
    assert!(matches!(c.read(&mut buf), Ok(0) | Err(_)), "the surplus connection is closed");
    // Both served connections fall idle and are closed within the timeout (bounded wait).
    let start = Instant::now();
    assert!(matches!(a.read(&mut buf), Ok(0) | Err(_)));
    assert!(start.elapsed() < Duration::from_secs(4), "closed after {:?}", start.elapsed());
    // Then a new client is served.
    let start = Instant::now();
    loop {
        let mut d = connect(addr);
        let _ = d.write_all(&mbap(5, 1, READ_VW0));
        let mut head = [0u8; 7];
        if d.read_exact(&mut head).is_ok() {
            break;
        }
        assert!(start.elapsed() < Duration::from_secs(10), "never served again");
    }
}

#[test]
fn eleven_hundred_connections_against_a_1024_descriptor_limit_do_not_end_the_server() {
    // Room for our own 1100 sockets.
    let mut lim = libc::rlimit { rlim_cur: 0, rlim_max: 0 };
    unsafe {
        libc::getrlimit(libc::RLIMIT_NOFILE, &mut lim);
    }
    if lim.rlim_max < 2048 {
        common::skipped(&format!("a hard descriptor limit of 2048 or more (it is {}; ulimit -Hn)", lim.rlim_max));
        return;
    }
    lim.rlim_cur = lim.rlim_max.min(4096);
    unsafe {
        libc::setrlimit(libc::RLIMIT_NOFILE, &lim);
    }
    let script = format!("ulimit -n 1024 && exec '{}' sim serve --tcp 0 --max-connections 5000 --state none", bin());
    let mut child = std::process::Command::new("sh")
        .args(["-c", &script])
        .env("PLCSH_STATE", "none")
        .env("PLCSH_LANG", "en")
        .stdout(Stdio::piped())
        .stderr(Stdio::piped())
        .spawn()
        .unwrap();
    let mut line = String::new();
    std::io::BufRead::read_line(&mut std::io::BufReader::new(child.stdout.as_mut().unwrap()), &mut line).unwrap();
    let ready: serde_json::Value = serde_json::from_str(&line).unwrap();
    let addr: std::net::SocketAddr = ready["tcp"].as_str().unwrap().parse().unwrap();
    let mut held = Vec::new();
    for _ in 0..1100 {
        if let Ok(s) = TcpStream::connect_timeout(&addr, Duration::from_secs(2)) {
            held.push(s);
        }
    }
    assert!(held.len() >= 1024, "only {} connections were made", held.len());
    assert!(child.try_wait().unwrap().is_none(), "the server lives with {} connections", held.len());
    drop(held);
    let start = Instant::now();
    loop {
        if let Ok(mut s) = TcpStream::connect_timeout(&addr, Duration::from_secs(2)) {
            s.set_read_timeout(Some(Duration::from_secs(2))).unwrap();
            if s.write_all(&mbap(7, 1, READ_VW0)).is_ok() {
                let mut head = [0u8; 7];
                if s.read_exact(&mut head).is_ok() {
                    break;
                }
            }
        }
        assert!(child.try_wait().unwrap().is_none(), "the server ended");
        assert!(start.elapsed() < Duration::from_secs(30), "a new client was never served");
    }
    let _ = child.kill();
    let out = child.wait_with_output().unwrap();
    let err = String::from_utf8_lossy(&out.stderr);
    assert!(err.contains("cannot accept a connection now"), "the descriptor limit was reached: {err}");
}

#[test]
fn the_servo_pty_link_is_removed_on_sigint_and_sigterm() {
    for sig in ["-INT", "-TERM"] {
        let l = link(&format!("servo{sig}"));
        let mut served = serve(&["--servo-pty", l.to_str().unwrap()]);
        assert!(l.exists());
        std::process::Command::new("kill").args([sig, &served.child.id().to_string()]).status().unwrap();
        let _ = served.child.wait();
        assert!(!l.exists(), "{sig}: the link is removed");
    }
}

#[test]
fn noise_on_the_pty_does_not_hold_up_tcp() {
    let pty = link("noise");
    let served = serve(&["--tcp", "0", "--rtu-pty", pty.to_str().unwrap(), "--state", "none"]);
    let mut p = open_pty(&pty);
    let mut t = connect(served.ready["tcp"].as_str().unwrap());
    t.write_all(&mbap(1, 1, READ_VW0)).unwrap();
    let before = Instant::now();
    tcp_reply(&mut t);
    let quiet = before.elapsed();
    // 16 KB of bytes that never form a frame, then a TCP request while the server chews on them.
    let noise: Vec<u8> = (0..16_384u32).map(|i| (i.wrapping_mul(2_654_435_761) >> 13) as u8 | 0x80).collect();
    p.write_all(&noise).unwrap();
    let start = Instant::now();
    t.write_all(&mbap(2, 1, READ_VW0)).unwrap();
    assert_eq!(tcp_reply(&mut t).0, 2);
    let took = start.elapsed();
    eprintln!("TCP request during pty noise: {took:?} ({quiet:?} without)");
    assert!(took < Duration::from_millis(300), "a TCP request took {took:?} during pty noise ({quiet:?} without)");
    // And the pty serves again after its silence.
    std::thread::sleep(Duration::from_millis(60));
    p.write_all(&rtu(1, READ_VW0)).unwrap();
    assert_eq!(&rtu_reply(&mut p, 7)[..5], &[1, 3, 2, 0, 0]);
}

/// A port another program holds is refused with the words docs/reference/errors.md quotes.
#[cfg(unix)]
#[test]
fn a_port_another_program_holds_is_refused_as_the_error_page_says() {
    let dir = std::env::temp_dir().join(format!("plcsh-held-{}", std::process::id()));
    let _ = std::fs::remove_dir_all(&dir);
    std::fs::create_dir_all(&dir).unwrap();
    let link = dir.join("held");
    let _served = serve(&["--rtu-pty", link.to_str().unwrap(), "--state", "none"]);
    // Another program holds it, as a terminal program would (opened exclusively).
    let _held = serialport::new(link.to_str().unwrap(), 9600).open_native().expect("the first open");
    let o = run(&["--state", "none", "-d", &format!("rtu:{}", link.display()), "-c", "get VW0"], "");
    let err = stderr(&o);
    let shown = "Unable to acquire exclusive lock on serial port";
    assert!(err.contains(&format!("cannot open the serial port {}: {shown}", link.display())), "{err}");
    let page = std::fs::read_to_string(concat!(env!("CARGO_MANIFEST_DIR"), "/docs/reference/errors.md")).unwrap();
    assert!(
        page.contains(&format!("### `cannot open the serial port …: {shown}`")),
        "errors.md quotes another message"
    );
    let _ = std::fs::remove_dir_all(&dir);
}
