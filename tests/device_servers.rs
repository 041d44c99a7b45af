//! Serial device servers (Moxa NPort, ser2net, USR …) as plcsh meets them: every serial family
//! reaches a served simulator through a TCP port, raw (`FAMILY+tcp://`) or with RFC 2217
//! (`FAMILY+rfc2217://`, the line's baud rate and format set from plcsh). The server is
//! pyserial's RFC 2217 implementation (tests/support/device_server.py), not plcsh's: an
//! independent peer, sitting on the real pseudo-terminal a `plcsh sim serve` serves.
//!
//! Needs /usr/bin/python3 with pyserial (Debian's python3-serial, installed by .ci/run); the
//! tests say so and pass without running when it is missing outside CI.

// Unix only: the device server sits on a real pseudo-terminal.
#![cfg(unix)]

mod common;
use common::*;
use plcsh::core::{Clock, Value};
use plcsh::session::open_url;
use std::io::{BufRead, BufReader};
use std::process::{Child, Command, Stdio};

/// A running device_server.py and the lines it prints.
struct DeviceServer {
    child: Child,
    lines: std::io::Lines<BufReader<std::process::ChildStdout>>,
    port: u16,
}

impl Drop for DeviceServer {
    fn drop(&mut self) {
        let _ = self.child.kill();
        let _ = self.child.wait();
    }
}

fn python() -> Option<&'static str> {
    let ok = |p: &str| {
        Command::new(p).args(["-c", "import serial.rfc2217"]).stderr(Stdio::null()).status().is_ok_and(|s| s.success())
    };
    ["/usr/bin/python3", "python3"].into_iter().find(|p| ok(p))
}

/// Starts the server on `serial` in `mode`; None (with a note) when pyserial is missing
/// outside CI — in CI it must be there.
fn device_server(mode: &str, serial: &str) -> Option<DeviceServer> {
    let Some(py) = python() else {
        assert!(std::env::var_os("CI").is_none(), "CI must install python3-serial (pyserial)");
        common::skipped("python3 with pyserial (apt-get install python3-serial)");
        return None;
    };
    let script = concat!(env!("CARGO_MANIFEST_DIR"), "/tests/support/device_server.py");
    let mut child = Command::new(py)
        .args([script, mode, serial])
        .stdout(Stdio::piped())
        .stderr(Stdio::inherit())
        .spawn()
        .expect("start device_server.py");
    let mut lines = BufReader::new(child.stdout.take().unwrap()).lines();
    let ready: serde_json::Value = serde_json::from_str(&lines.next().unwrap().unwrap()).unwrap();
    let port = ready["port"].as_u64().unwrap() as u16;
    Some(DeviceServer { child, lines, port })
}

use common::{open_device as open, operands as ops};

#[test]
fn k2_over_rfc2217_sets_the_line_and_reads_and_writes() {
    let dir = tempdir("rfc2217-k2");
    let link = dir.join("ttyK2");
    let _srv = serve(&["--rtu-pty", link.to_str().unwrap()]);
    let Some(mut ds) = device_server("rfc2217", link.to_str().unwrap()) else { return };
    let mut d = open(&format!("rtu+rfc2217://127.0.0.1:{}?baud=19200&parity=even&unit=1", ds.port));
    // RFC 2217 §3: the server applied what plcsh sent (SET-BAUDRATE, -DATASIZE, -PARITY, -STOPSIZE).
    let settings: serde_json::Value = loop {
        let l: serde_json::Value = serde_json::from_str(&ds.lines.next().unwrap().unwrap()).unwrap();
        if l["baud"] == 19200 && l["parity"] == "E" {
            break l;
        }
    };
    assert_eq!((settings["bits"].as_u64(), settings["stop"].as_f64()), (Some(8), Some(1.0)), "{settings}");
    let o = ops(d.as_ref(), &["VW100", "VW102"]);
    d.write(&[(o[0], Value::Int(4242)), (o[1], Value::Int(0xFF01))]).unwrap();
    assert_eq!(d.read(&o).unwrap(), vec![Value::Int(4242), Value::Int(0xFF01)]);
    // A value with a 0xFF byte crosses the Telnet stream escaped (IAC IAC) both ways.
    d.write(&[(o[0], Value::Int(0x00FF))]).unwrap();
    assert_eq!(d.read(&o[..1]).unwrap(), vec![Value::Int(0xFF)]);
}

#[test]
fn servo_over_rfc2217_and_raw_tcp() {
    let dir = tempdir("rfc2217-servo");
    let link = dir.join("ttyKINCO");
    let _srv = serve(&["--servo-pty", link.to_str().unwrap(), "--servo-instant"]);
    for mode in ["rfc2217", "raw"] {
        let Some(ds) = device_server(mode, link.to_str().unwrap()) else { return };
        let scheme = if mode == "raw" { "kinco+tcp" } else { "kinco+rfc2217" };
        let url = format!("{scheme}://127.0.0.1:{}?id=1&baud=38400", ds.port);
        let mut d = open(&url);
        let sw = ops(d.as_ref(), &["statusword", "target_velocity"]);
        assert_eq!(d.read(&sw[..1]).unwrap(), vec![Value::Int(0x4231)], "{url}");
        d.write(&[(sw[1], Value::Int(-1))]).unwrap();
        assert_eq!(d.read(&sw[1..]).unwrap(), vec![Value::Int(-1)], "{url}: 0xFF bytes cross");
        assert!(d.info().link.contains(&format!("127.0.0.1:{}", ds.port)), "{}", d.info().link);
        drop(d);
        drop(ds);
    }
}

#[test]
fn a_server_that_does_not_speak_rfc2217_is_named() {
    // A raw channel never agrees to COM-PORT-OPTION: the error says what to try.
    let dir = tempdir("rfc2217-raw");
    let link = dir.join("ttyK2");
    let _srv = serve(&["--rtu-pty", link.to_str().unwrap()]);
    let Some(ds) = device_server("raw", link.to_str().unwrap()) else { return };
    let url = format!("rtu+rfc2217://127.0.0.1:{}?baud=9600&timeout=300ms&retries=0", ds.port);
    let e = match open_url(&url, &Clock::following()) {
        Ok(mut d) => {
            let o = ops(d.as_ref(), &["VW0"]);
            d.read(&o).unwrap_err()
        }
        Err(e) => e,
    };
    assert!(e.message.contains("RFC 2217") || e.to_string().contains("RFC 2217"), "{e}");
    assert!(e.hint.as_deref().unwrap_or("").contains("+tcp://"), "{:?}", e.hint);
}

fn tempdir(name: &str) -> std::path::PathBuf {
    let d = std::env::temp_dir().join(format!("plcsh-{name}-{}", std::process::id()));
    std::fs::create_dir_all(&d).unwrap();
    d
}
