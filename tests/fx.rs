//! FX-protocol PLCs end to end: the served simulator (`plcsh sim serve --fx-pty --fx-link-pty`,
//! readiness line awaited) over REAL pseudo-terminal pairs, driven by the real binary's
//! commands and by the drivers; the simulator fed byte sequences re-created by hand from the
//! public protocol descriptions (seed 004; the computer-link format as public drivers write
//! it), including a bad sum check, an address out of range and a parity-damaged byte; retries
//! through a proxy pty that spoils replies; batch reads coalesced within the frame limits.
// Unix only: real pseudo-terminals (Windows has none; its COM ports are tested under Wine
// in tests/windows_serial.rs).
#![cfg(unix)]

mod common;
use common::*;
use plcsh::core::link::pty::Pty;
use plcsh::core::{Clock, Device, ErrorKind, Operand, Value};
use plcsh::session::open_url;
use std::fs::File;
use std::io::{Read, Write};
use std::os::fd::AsFd;
use std::path::PathBuf;
use std::sync::atomic::{AtomicU32, Ordering};
use std::sync::Arc;
use std::time::{Duration, Instant};

/// A served FX simulator with both ports on ptys symlinked in a private directory.
struct Server {
    _served: Served,
    port: PathBuf,
    link: PathBuf,
    ready: serde_json::Value,
}

impl Server {
    fn start(tag: &str, extra: &[&str]) -> Server {
        let dir = std::env::temp_dir().join(format!("plcsh-fx-{}-{tag}", std::process::id()));
        std::fs::create_dir_all(&dir).unwrap();
        let (port, link) = (dir.join("ttyFX"), dir.join("ttyFXLINK"));
        let mut args = vec!["--fx-pty", port.to_str().unwrap(), "--fx-link-pty", link.to_str().unwrap()];
        args.extend_from_slice(extra);
        let served = serve(&args);
        let ready = served.ready.clone();
        Server { _served: served, port, link, ready }
    }
}

fn open(url: &str) -> Box<dyn Device> {
    open_url(url, &Clock::following()).unwrap_or_else(|e| panic!("{url}: {e}"))
}

fn ops(d: &dyn Device, names: &[&str]) -> Vec<Operand> {
    names.iter().flat_map(|n| d.operands().parse(n).unwrap_or_else(|e| panic!("{n}: {e}"))).collect()
}

/// A raw client on a served pty: writes bytes, reads what comes back within `wait`.
struct Raw(File);

impl Raw {
    fn open(path: &PathBuf) -> Raw {
        let f = std::fs::OpenOptions::new().read(true).write(true).open(path).unwrap();
        Raw(f)
    }
    fn ask(&mut self, bytes: &[u8], want: usize) -> Vec<u8> {
        self.ask_within(bytes, want, Duration::from_secs(5))
    }
    fn ask_within(&mut self, bytes: &[u8], want: usize, wait: Duration) -> Vec<u8> {
        self.0.write_all(bytes).unwrap();
        let mut got = Vec::new();
        let deadline = Instant::now() + wait;
        while got.len() < want && Instant::now() < deadline {
            let mut fds = [nix::poll::PollFd::new(self.0.as_fd(), nix::poll::PollFlags::POLLIN)];
            if nix::poll::poll(&mut fds, nix::poll::PollTimeout::from(100u16)).unwrap_or(0) > 0 {
                let mut buf = [0u8; 256];
                let n = self.0.read(&mut buf).unwrap();
                got.extend_from_slice(&buf[..n]);
            }
        }
        got
    }
}

fn hex(s: &str) -> Vec<u8> {
    s.split_whitespace().map(|b| u8::from_str_radix(b, 16).unwrap()).collect()
}

#[test]
fn every_command_over_both_ports() {
    let srv = Server::start("cmds", &[]);
    assert_eq!(srv.ready["fx_model"], "FX2N");
    assert!(srv.ready["fx_pty"]["path"].as_str().unwrap().starts_with("/dev/pts/"));
    let port = format!("fx={}", format_args!("fx:{}", srv.port.display()));
    let link = format!("l=fxlink:{}?station=0&pc=FF&wait=1", srv.link.display());
    let out = run(
        &[
            "--json",
            "-d",
            &port,
            "-d",
            &link,
            "-c",
            "use fx; set D100=1234, M500=1, K4Y0=16#A5, D10/DINT=-100000; get D100 M500 K4Y0 Y2 D10/DINT; \
             read D100[2]; watch D100 every=10ms count=2; trace D100 every=20ms for=60ms; \
             use l; get D100 M500 K4Y0 D10/DINT; set D600=7, Y17=1; get D600; read D600[2]; \
             use fx; get Y17; get D600",
        ],
        "",
    );
    let lines = json_lines(&out);
    let find = |cmd: &str, k: usize| lines.iter().filter(|l| l["cmd"] == cmd).nth(k).cloned().unwrap();
    let vals = |l: &serde_json::Value| -> Vec<i64> {
        l["values"]
            .as_array()
            .unwrap()
            .iter()
            .map(|v| v["value"].as_i64().unwrap_or(v["value"].as_bool().map(i64::from).unwrap_or(-999)))
            .collect()
    };
    assert_eq!(vals(&find("get", 0)), vec![1234, 1, 0xA5, 1, -100000], "{lines:?}");
    assert_eq!(find("read", 0)["values"].as_array().unwrap().len(), 2);
    assert_eq!(find("read", 1)["values"][0]["value"], 7, "read over the computer link");
    assert!(lines.iter().any(|l| l["cmd"] == "watch"), "{lines:?}");
    assert!(lines.iter().any(|l| l["cmd"] == "trace"), "{lines:?}");
    // The computer link sees the programming port's writes: one PLC memory.
    assert_eq!(vals(&find("get", 1)), vec![1234, 1, 0xA5, -100000]);
    assert_eq!(vals(&find("get", 2)), vec![7], "the link reaches D600");
    assert_eq!(vals(&find("get", 3)), vec![1], "Y17 written over the link, read on the port");
    // D600 is past the programming port's table: refused before sending, saying why.
    let errs: Vec<_> = lines.iter().filter(|l| l["ok"] == false).collect();
    assert_eq!(errs.len(), 1, "{lines:?}");
    assert_eq!(errs[0]["error"]["kind"], "range");
    assert!(errs[0]["error"]["message"].as_str().unwrap().contains("D0–D511"), "{:?}", errs[0]);
    let out = run(&["--json", "-d", &port, "-c", "use fx; set TC0=1"], "");
    let e = json_lines(&out).into_iter().find(|l| l["ok"] == false).unwrap();
    assert_eq!(e["error"]["kind"], "unsupported", "a coil follows the program: {e}");
}

#[test]
fn the_programming_port_answers_hand_made_frames() {
    let srv = Server::start("port-raw", &[]);
    let mut c = Raw::open(&srv.port);
    assert_eq!(c.ask(&[0x05], 1), vec![0x06], "ENQ → ACK");
    // Seed 004: write 1234 and ABCD to D123/D124, then read 4 bytes from D123.
    assert_eq!(c.ask(&hex("02 31 31 30 46 36 30 34 33 34 31 32 43 44 41 42 03 34 39"), 1), vec![0x06]);
    assert_eq!(
        c.ask(&hex("02 30 31 30 46 36 30 34 03 37 34"), 12),
        hex("02 33 34 31 32 43 44 41 42 03 44 37"),
        "STX 3412CDAB ETX D7"
    );
    // Force M500 on; read M496–M503 (byte 0x013E): bit 4.
    assert_eq!(c.ask(&hex("02 37 46 34 30 39 03 31 44"), 1), vec![0x06]);
    // '0' '013E' '01' ETX: 0x30+0x30+0x31+0x33+0x45+0x30+0x31+0x03 = 0x16D → "6D".
    assert_eq!(c.ask(&hex("02 30 30 31 33 45 30 31 03 36 44"), 6), hex("02 31 30 03 36 34"));
    // A bad sum check: NAK.
    assert_eq!(c.ask(&hex("02 30 31 30 46 36 30 34 03 37 35"), 1), vec![0x15]);
    // An address with no device: 0x1400 (D512, past the table): '0' '1400' '02' ETX = 0x15A.
    assert_eq!(c.ask(&hex("02 30 31 34 30 30 30 32 03 35 41"), 1), vec![0x15]);
    // A byte with bit 7 set (a parity error on a real 7E1 line): NAK, and the next frame works.
    assert_eq!(c.ask(&[0x02, 0x30, 0xB1], 1), vec![0x15]);
    assert_eq!(c.ask(&hex("02 30 31 30 46 36 30 34 03 37 34"), 12).len(), 12);
}

#[test]
fn the_computer_link_answers_hand_made_frames() {
    let srv = Server::start("link-raw", &["--fx-station", "5"]);
    assert_eq!(srv.ready["fx_station"], 5);
    let mut c = Raw::open(&srv.link);
    // WW D0000, 2 words 1234 ABCD, station 05: sum over "05FFWW0D0000021234ABCD" = 0x509 → "09".
    assert_eq!(c.ask(b"\x0505FFWW0D0000021234ABCD09", 5), b"\x0605FF".to_vec());
    // WR D0000, 2 words: sum over "05FFWR0D000002" = 0x330 → "30"; reply sum over
    // "05FF1234ABCD" ETX = 0x3C8 → "C8".
    assert_eq!(c.ask(b"\x0505FFWR0D00000230", 16), b"\x0205FF1234ABCD\x03C8".to_vec());
    // BW Y0000 3 points "101" then BR Y0000 4 points.
    // "05FFBW0Y000003101" = 0x3C8 → "C8"; "05FFBR0Y000004" = 0x332 → "32"; reply "05FF1010" ETX = 0x1B6.
    assert_eq!(c.ask(b"\x0505FFBW0Y000003101C8", 5), b"\x0605FF".to_vec());
    assert_eq!(c.ask(b"\x0505FFBR0Y00000432", 12), b"\x0205FF1010\x03B6".to_vec());
    // WT: D0005 = 0007 and D0100 = 00FF: "05FFWT002D00050007D010000FF" = 0x5EF → "EF".
    assert_eq!(c.ask(b"\x0505FFWT002D00050007D010000FFEF", 5), b"\x0605FF".to_vec());
    // Bad sum: NAK with error 02.
    assert_eq!(c.ask(b"\x0505FFWR0D00000231", 7), b"\x1505FF02".to_vec());
    // D8256 does not exist: error 06. "05FFWR0D825601" = 0x344 → "44".
    assert_eq!(c.ask(b"\x0505FFWR0D82560144", 7), b"\x1505FF06".to_vec());
    // Another station's request: silence (then our own still works).
    assert!(c.ask_within(b"\x0500FFWR0D0000022B", 1, Duration::from_millis(300)).is_empty());
    assert_eq!(c.ask(b"\x0505FFWR0D00000230", 16).len(), 16);
    // The driver reports the link's error code in words.
    let mut d = open(&format!("fxlink:{}?station=5&model=FX2N", srv.link.display()));
    let o = ops(d.as_ref(), &["D100", "D5"]);
    assert_eq!(d.read(&o).unwrap(), vec![Value::Int(255), Value::Int(7)]);
    let mut wrong = open(&format!("fxlink:{}?station=5&pc=01&timeout=300ms", srv.link.display()));
    let e = wrong.read(&o).unwrap_err();
    assert_eq!(e.kind, ErrorKind::Refused, "{e}");
    assert!(e.message.contains("0AH") && e.message.contains("PC number"), "{e}");
}

/// A proxy between the driver and the served port: a pty pair of its own whose master relays
/// to the simulator, spoiling the sum check of the next `bad` read replies (the test sets it).
fn proxy(sim: &PathBuf) -> (PathBuf, Arc<AtomicU32>, Arc<AtomicU32>) {
    let (master, slave, path) = Pty::open().unwrap().into_parts();
    let frames = Arc::new(AtomicU32::new(0));
    let mut to_sim = std::fs::OpenOptions::new().read(true).write(true).open(sim).unwrap();
    let mut from_sim = to_sim.try_clone().unwrap();
    let mut from_drv = master.try_clone().unwrap();
    let mut to_drv = master;
    let f = frames.clone();
    let bad = Arc::new(AtomicU32::new(0));
    let spoil = bad.clone();
    std::thread::spawn(move || {
        // Our slave handle stays open while the proxy runs: with no slave open, a read on
        // the master fails (EIO) and would end the proxy before the driver opened the path.
        let _slave = slave;
        let mut buf = [0u8; 256];
        while let Ok(n) = from_drv.read(&mut buf) {
            if n == 0 {
                break;
            }
            f.fetch_add(buf[..n].iter().filter(|b| **b == 0x02).count() as u32, Ordering::Relaxed);
            if to_sim.write_all(&buf[..n]).is_err() {
                break;
            }
        }
    });
    std::thread::spawn(move || {
        let mut since_etx: Option<u8> = None;
        let mut buf = [0u8; 256];
        while let Ok(n) = from_sim.read(&mut buf) {
            if n == 0 {
                break;
            }
            for b in &mut buf[..n] {
                match since_etx {
                    Some(1) => {
                        if spoil.load(Ordering::SeqCst) > 0 {
                            spoil.fetch_sub(1, Ordering::SeqCst);
                            *b = if *b == b'0' { b'1' } else { b'0' };
                        }
                        since_etx = None;
                    }
                    Some(k) => since_etx = Some(k + 1),
                    None if *b == 0x03 => since_etx = Some(0),
                    None => {}
                }
            }
            if to_drv.write_all(&buf[..n]).is_err() {
                break;
            }
        }
    });
    (path, frames, bad)
}

#[test]
fn bad_sums_are_retried_three_times_over_a_real_pty() {
    let srv = Server::start("retry", &[]);
    // Three spoiled replies: the fourth frame is answered and used.
    let (path, frames, bad) = proxy(&srv.port);
    bad.store(3, Ordering::SeqCst);
    let mut d = open(&format!("fx:{}?model=FX2N", path.display()));
    let o = ops(d.as_ref(), &["D8000"]);
    assert_eq!(d.read(&o).unwrap(), vec![Value::Int(200)], "watchdog 200 ms");
    assert_eq!(d.requests(), 4);
    assert_eq!(frames.load(Ordering::Relaxed), 4, "the proxy saw four frames");
    // Four spoiled replies: reported, kind link, after four more frames.
    bad.store(4, Ordering::SeqCst);
    let e = d.read(&o).unwrap_err();
    assert_eq!(e.kind, ErrorKind::Link, "{e}");
    assert!(e.message.contains("sum check") && e.message.contains("4 attempts"), "{e}");
    assert_eq!(frames.load(Ordering::Relaxed), 8);
    assert_eq!(d.requests(), 8);
    assert_eq!(d.read(&o).unwrap(), vec![Value::Int(200)], "the link recovers");
}

#[test]
fn batch_gets_coalesce_within_the_frame_limits() {
    let srv = Server::start("batch", &[]);
    // Through the shell first (a child process), then in this process: one get line, 4 frames
    // on the wire (-v counts them).
    let out = run(&["-v", "-d", &format!("fx=fx:{}", srv.port.display()), "-c", "use fx; get D0..D40 D100 M0..M7"], "");
    let err = String::from_utf8_lossy(&out.stderr).to_string() + &stdout(&out);
    assert!(err.contains("get: 4 request(s) on the wire"), "{err}");
    let mut d = open(&format!("fx:{}", srv.port.display()));
    // D0..D40 (82 bytes), D100, M0..M7: D0–D31 (64 bytes), D32–D40, D100, M0–M7 = 4 frames.
    let o = ops(d.as_ref(), &["D0..D40", "D100", "M0..M7"]);
    let before = d.requests();
    assert_eq!(d.read(&o).unwrap().len(), 41 + 1 + 8);
    assert_eq!(d.requests() - before, 4);
    // The computer link: WR of 64 words is its limit.
    let mut l = open(&format!("fxlink:{}", srv.link.display()));
    let o = ops(l.as_ref(), &["D0..D64", "X0..X17"]);
    let before = l.requests();
    l.read(&o).unwrap();
    assert_eq!(l.requests() - before, 3, "WR D0–D63, WR D64, BR X0–X17");
}

#[test]
fn write_guards_from_profiles_cover_forces_and_writes() {
    let dir = std::env::temp_dir().join(format!("plcsh-fx-profile-{}", std::process::id()));
    std::fs::create_dir_all(&dir).unwrap();
    let f = dir.join("devices.toml");
    std::fs::write(&f, "[devices.line]\nurl = \"sim-fx:FX1N\"\nallow = [\"D100..D109\", \"M0\"]\n").unwrap();
    let o = run(
        &["--config", f.to_str().unwrap(), "--json"],
        "connect line\nuse line\nset D100=5, M0=1\nset D100=6, M500=1\nset D200=1\nget D100 M0 M500 D200\n",
    );
    let l = json_lines(&o);
    assert_eq!(l[2]["ok"], true, "{l:?}");
    assert_eq!(l[3]["ok"], false, "forcing M500 is outside the allow list: {l:?}");
    assert_eq!(l[3]["error"]["operand"], "M500");
    assert_eq!(l[4]["ok"], false);
    let v: Vec<i64> = l[5]["values"]
        .as_array()
        .unwrap()
        .iter()
        .map(|v| v["value"].as_i64().unwrap_or(v["value"].as_bool().map(i64::from).unwrap_or(-1)))
        .collect();
    assert_eq!(v, vec![5, 1, 0, 0], "the refused lines wrote nothing");
}

#[test]
fn the_recipe_script_runs_against_a_served_fx_as_at_the_machine() {
    let srv = Server::start("recipe", &[]);
    // The "machine's" FX holds a recipe (written over its computer link) …
    let link = format!("l=fxlink:{}", srv.link.display());
    let o = run(
        &["-d", &link, "-c", "use l; set D200=11, D201=-22, D202=33, D203=44, D204=55, D205=66, D206=77, D207=88, D210/DINT=-5, K4M100=16#8001"],
        "",
    );
    assert!(o.status.success(), "{}", stdout(&o));
    // … and the same script that rehearsed on the simulator copies it over the programming port.
    let script = std::path::Path::new(env!("CARGO_MANIFEST_DIR")).join("scripts/fx_recipe_to_k2.lua");
    let fx = format!("fx=fx:{}", srv.port.display());
    let o = run(&["--time", "stepped", "-d", &fx, "run", script.to_str().unwrap()], "");
    let out = stdout(&o);
    assert!(o.status.success(), "{out}{}", String::from_utf8_lossy(&o.stderr));
    assert!(out.contains("recipe copied: 8 setpoints, batch -5, options 16#8001"), "{out}");
}
