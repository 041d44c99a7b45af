//! `sim serve --rfc2217`: the served serial lines speak RFC 2217 on their TCP ports, so
//! `rtu+rfc2217://` and `kinco+rfc2217://` reach plcsh's own simulators, and so does a client
//! that is not plcsh: pyserial's `serial_for_url("rfc2217://…")`, which negotiates
//! COM-PORT-OPTION, sets 19200 8E1 and waits for each setting to be confirmed, then sends a
//! Modbus RTU request and a Kinco read frame built here (CRC and checksum computed, not
//! copied), with 0xFF bytes that must cross the Telnet stream escaped both ways.
//!
//! The pyserial test (Unix only) needs /usr/bin/python3 with pyserial (Debian's python3-serial, installed
//! by .ci/run); outside CI it says so and passes without running when it is missing.

mod common;
use common::{open_device as open, operands as ops, serve, Start};
use plcsh::core::Value;
#[cfg(unix)]
use std::process::{Command, Stdio};

fn addr(ready: &serde_json::Value, field: &str) -> String {
    ready[field].as_str().unwrap_or_else(|| panic!("no {field} in {ready}")).to_string()
}

#[test]
fn plcsh_reaches_its_own_served_lines_over_rfc2217() {
    let srv = serve(&["--rtu-tcp", "0", "--servo-tcp", "0", "--servo-instant", "--rfc2217"]);
    assert_eq!(srv.ready["rfc2217"], true, "{}", srv.ready);
    let rtu = addr(&srv.ready, "rtu_tcp");
    let mut d = open(&format!("rtu+rfc2217://{rtu}?baud=19200&parity=even&unit=1"));
    let o = ops(d.as_ref(), &["VW100", "VW102"]);
    d.write(&[(o[0], Value::Int(4242)), (o[1], Value::Int(0xFF01))]).unwrap();
    assert_eq!(d.read(&o).unwrap(), vec![Value::Int(4242), Value::Int(0xFF01)]);
    d.write(&[(o[0], Value::Int(0x00FF))]).unwrap();
    assert_eq!(d.read(&o[..1]).unwrap(), vec![Value::Int(0xFF)], "0xFF crosses escaped both ways");

    let servo = addr(&srv.ready, "servo_tcp");
    let mut k = open(&format!("kinco+rfc2217://{servo}?id=1&baud=38400"));
    let sw = ops(k.as_ref(), &["statusword", "target_velocity"]);
    assert_eq!(k.read(&sw[..1]).unwrap(), vec![Value::Int(0x4231)]);
    k.write(&[(sw[1], Value::Int(-1))]).unwrap();
    assert_eq!(k.read(&sw[1..]).unwrap(), vec![Value::Int(-1)], "0xFF bytes cross");
}

#[test]
fn without_the_flag_the_ports_stay_raw_and_the_flag_alone_is_refused() {
    let out = common::plcsh().args(["sim", "serve", "--rfc2217"]).output_retrying().unwrap();
    let err = String::from_utf8_lossy(&out.stderr);
    assert_eq!(out.status.code(), Some(2), "{err}");
    assert!(err.contains("--rfc2217") && err.contains("--rtu-tcp"), "{err}");
    let srv = serve(&["--rtu-tcp", "0"]);
    assert!(srv.ready.get("rfc2217").is_none(), "{}", srv.ready);
    let mut d = open(&format!("rtu+tcp://{}?unit=1", addr(&srv.ready, "rtu_tcp")));
    let o = ops(d.as_ref(), &["VW0"]);
    d.write(&[(o[0], Value::Int(7))]).unwrap();
    assert_eq!(d.read(&o).unwrap(), vec![Value::Int(7)]);
}

/// pyserial as the client (on Unix: Python is a Linux program where the Windows stage runs): the line set to 19200 8E1 (each setting confirmed, or pyserial
/// refuses to open), a Modbus RTU write and read of holding registers with 0xFF bytes, and
/// a Kinco read of the statusword.
#[cfg(unix)]
const CLIENT: &str = r#"
import sys, json, serial
def crc(b):
    c = 0xFFFF
    for x in b:
        c ^= x
        for _ in range(8):
            c = (c >> 1) ^ 0xA001 if c & 1 else c >> 1
    return bytes([c & 0xFF, c >> 8])
rtu, servo = sys.argv[1], sys.argv[2]
out = {}
s = serial.serial_for_url("rfc2217://" + rtu, baudrate=19200, bytesize=8, parity="E", stopbits=1, timeout=3)
req = bytes([1, 6, 0, 151, 0xFF, 0x00]); req += crc(req)
s.write(req); out["write"] = s.read(8).hex()
req = bytes([1, 3, 0, 150, 0, 2]); req += crc(req)
s.write(req); out["read"] = s.read(9).hex()
out["read_crc_ok"] = crc(bytes.fromhex(out["read"])[:7]) == bytes.fromhex(out["read"])[7:]
out["write_req"] = (bytes([1, 6, 0, 151, 0xFF, 0x00]) + crc(bytes([1, 6, 0, 151, 0xFF, 0x00]))).hex()
s.close()
k = serial.serial_for_url("rfc2217://" + servo, baudrate=38400, timeout=3)
f = bytes([1, 0x40, 0x41, 0x60, 0, 0, 0, 0, 0]); f += bytes([(-sum(f)) & 0xFF])
k.write(f); out["servo"] = k.read(10).hex()
k.close()
print(json.dumps(out))
"#;

#[cfg(unix)]
fn python() -> Option<&'static str> {
    let ok = |p: &str| {
        Command::new(p).args(["-c", "import serial.rfc2217"]).stderr(Stdio::null()).status().is_ok_and(|s| s.success())
    };
    ["/usr/bin/python3", "python3"].into_iter().find(|p| ok(p))
}

#[cfg(unix)]
fn bytes(hex: &serde_json::Value) -> Vec<u8> {
    let h = hex.as_str().unwrap_or("");
    (0..h.len() / 2).map(|i| u8::from_str_radix(&h[2 * i..2 * i + 2], 16).unwrap()).collect()
}

#[cfg(unix)]
#[test]
fn pyserial_sets_the_line_and_reads_a_k2_and_a_drive() {
    let Some(py) = python() else {
        assert!(std::env::var_os("CI").is_none(), "CI must install python3-serial (pyserial)");
        common::skipped("python3 with pyserial (apt-get install python3-serial)");
        return;
    };
    let srv = serve(&["--rtu-tcp", "0", "--servo-tcp", "0", "--servo-instant", "--rfc2217"]);
    let (rtu, servo) = (addr(&srv.ready, "rtu_tcp"), addr(&srv.ready, "servo_tcp"));
    // VW100 (holding register 150, docs/modbus.md) set through plcsh's own client first.
    let mut d = open(&format!("rtu+rfc2217://{rtu}?baud=19200&parity=even&unit=1"));
    let o = ops(d.as_ref(), &["VW100", "VW102"]);
    d.write(&[(o[0], Value::Int(0x12FF))]).unwrap();
    drop(d);

    let out = Command::new(py).args(["-c", CLIENT, &rtu, &servo]).output().expect("python3 runs");
    let stdout = String::from_utf8_lossy(&out.stdout);
    assert!(out.status.success(), "{stdout}{}", String::from_utf8_lossy(&out.stderr));
    let r: serde_json::Value = serde_json::from_str(stdout.trim()).unwrap_or_else(|e| panic!("{stdout}: {e}"));
    // Function 06 echoes its request (Modbus application protocol §6.6).
    assert_eq!(r["write"], r["write_req"], "{r}");
    // Function 03: unit, function, byte count 4, then the two registers high byte first.
    let read = bytes(&r["read"]);
    assert_eq!(read.get(..7), Some(&[1u8, 3, 4, 0x12, 0xFF, 0xFF, 0x00][..]), "{r}");
    assert_eq!(r["read_crc_ok"], true, "{r}");
    // Kinco read reply (kinco-servo §2): 0x4B = two data bytes, index 0x6041 low byte first,
    // the statusword low byte first, and a checksum that makes the ten bytes sum to 0.
    let sv = bytes(&r["servo"]);
    assert_eq!(sv.len(), 10, "{r}");
    assert_eq!(sv[..5], [1, 0x4B, 0x41, 0x60, 0]);
    assert_eq!(u16::from_le_bytes([sv[5], sv[6]]), 0x4231, "{r}");
    assert_eq!(sv.iter().fold(0u8, |a, b| a.wrapping_add(*b)), 0, "{r}");

    // What pyserial wrote is what plcsh reads.
    let mut d = open(&format!("rtu+rfc2217://{rtu}?baud=19200&parity=even&unit=1"));
    assert_eq!(d.read(&o).unwrap(), vec![Value::Int(0x12FF), Value::Int(0xFF00)]);
}
