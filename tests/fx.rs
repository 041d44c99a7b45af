//! FX-protocol PLCs end to end: the served simulator (`plcsh sim serve --fx-pty --fx-link-pty`,
//! readiness line awaited) over REAL pseudo-terminal pairs, driven by the real binary's
//! commands and by the drivers; the simulator fed byte sequences re-created by hand from the
//! public protocol descriptions (seed 004; the computer-link format as public drivers write
//! it), including a bad sum check, an address out of range and a parity-damaged byte; retries
//! through a proxy pty that spoils replies; batch reads coalesced within the frame limits.
//! Transaction integrity against an independent responder (test code with its own reading of
//! the frames, on a pty of its own) that answers late, as another station, with NAK, behind
//! 00H noise, or at 4800/9600/19200 baud pace. The programming port's reach per
//! model: a served FX2N and FX3U fed the public drivers' frames (D1000, D7999, M1535, the
//! E-commands), the npm package node-fxplc run against them, and the driver against an
//! independent responder per model, with and without ENQ.
// Unix only: real pseudo-terminals (Windows has none; its COM ports are tested under Wine
// in tests/windows_serial.rs).
#![cfg(unix)]

mod common;
#[path = "support/words.rs"]
mod words;
use common::pty_responder::{self, Act};
use common::*;
use plcsh::core::link::pty::Pty;
use plcsh::core::{Clock, Device, ErrorKind, Operand, Value};
use plcsh::session::open_url;
use std::fs::File;
use std::io::{Read, Write};
use std::os::fd::AsFd;
use std::path::PathBuf;
use std::sync::atomic::{AtomicBool, AtomicU32, Ordering};
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

/// The tests whose responder paces replies at line speed run one at a time: each measures
/// times a thread keeps, and the others' threads on two cores would stretch them.
fn line_timing() -> std::sync::MutexGuard<'static, ()> {
    static ALONE: std::sync::Mutex<()> = std::sync::Mutex::new(());
    ALONE.lock().unwrap_or_else(|p| p.into_inner())
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
             use fx; get Y17; get D600; get M1536",
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
    assert_eq!(vals(&find("get", 4)), vec![7], "the programming port reaches D600 too (1000H + 2n)");
    // M1536 is past an FX2N's programming-port table: refused before sending, saying why and
    // what reaches it.
    let errs: Vec<_> = lines.iter().filter(|l| l["ok"] == false).collect();
    assert_eq!(errs.len(), 1, "{lines:?}");
    assert_eq!(errs[0]["error"]["kind"], "range");
    assert!(errs[0]["error"]["message"].as_str().unwrap().contains("M0–M1535"), "{:?}", errs[0]);
    assert!(errs[0]["error"]["hint"].as_str().unwrap().contains("model=FX3U"), "{:?}", errs[0]);
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
    // An address with no device: 0x4E80 (D8000 by 1000H + 2n, past D7999): '0' '4E80' '02' ETX
    // = 0x176.
    assert_eq!(c.ask(&hex("02 30 34 45 38 30 30 32 03 37 36"), 1), vec![0x15]);
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
    // Another station's request: silence. Then our own is answered, and its reply is the
    // first thing on the line: an answer to the other station's, however late, would have
    // come before it (the line is one stream), so no quiet window decides this.
    assert!(c.ask_within(b"\x0500FFWR0D0000022B", 1, Duration::from_millis(300)).is_empty());
    assert_eq!(c.ask(b"\x0505FFWR0D00000230", 16), b"\x0205FF1234ABCD\x03C8".to_vec());
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

// ---------------------------------------------------------------------------------------------
// An independent responder: test code that plays the PLC on a pty of its own, reading the
// requests with its own reading of seed 004's frames (not plcsh's codecs, not its simulator)
// and answering late, as another station, with NAK, behind noise, or at a baud rate's pace.
// A reader thread stamps each request as it arrives; a writer thread answers them in order.

const STX: u8 = 0x02;
const ETX: u8 = 0x03;
const ENQ: u8 = 0x05;
const ACK: u8 = 0x06;
const NAK: u8 = 0x15;

/// One request as the responder read it.
#[derive(Clone, Debug)]
struct Req {
    /// When its last character arrived.
    at: Instant,
    /// Link: the station number; the port: 0.
    station: u8,
    /// Link: `WR`, `WW`, `BR`, `BW`; the port: `ENQ`, `0` read, `1` write, `7`/`8` force.
    cmd: String,
    /// Link: the device number (`D0100` → 100); the port: the byte address.
    dev: u32,
    count: usize,
    /// Link: the message wait digit (×10 ms).
    wait: u8,
    /// The request's sum check is right.
    sum_ok: bool,
}

/// The sum check: the low byte of the sum of the characters, two upper-case hex digits.
fn sum2(bytes: &[u8]) -> Vec<u8> {
    format!("{:02X}", bytes.iter().fold(0u8, |a, b| a.wrapping_add(*b))).into_bytes()
}

fn hexnum(s: &[u8]) -> Option<u32> {
    u32::from_str_radix(std::str::from_utf8(s).ok()?, 16).ok()
}

/// A computer-link request at the start of `buf` (which starts with ENQ): `ENQ station(2) pc(2)
/// cmd(2) wait(1) device(5) count(2) [data] sum(2)`; its length and what it asks, `Some((n,
/// None))` for bytes that are not a request.
fn parse_link(buf: &[u8]) -> Option<(usize, Option<Req>)> {
    if buf.len() < 15 {
        return None;
    }
    let junk = Some((1, None));
    let (Some(station), Some(count)) = (hexnum(&buf[1..3]), hexnum(&buf[13..15])) else { return junk };
    let Some(dev) = std::str::from_utf8(&buf[9..13]).ok().and_then(|d| d.parse::<u32>().ok()) else { return junk };
    let count = if count == 0 { 256 } else { count as usize };
    let cmd = String::from_utf8_lossy(&buf[5..7]).to_string();
    let data = match cmd.as_str() {
        "WR" | "BR" => 0,
        "WW" => 4 * count,
        "BW" => count,
        _ => return junk,
    };
    let len = 15 + data + 2;
    if buf.len() < len {
        return None;
    }
    let wait = (buf[7] as char).to_digit(16).unwrap_or(0) as u8;
    let sum_ok = sum2(&buf[1..len - 2]) == buf[len - 2..len];
    let at = Instant::now();
    Some((len, Some(Req { at, station: station as u8, cmd, dev, count, wait, sum_ok })))
}

/// A programming-port request at the start of `buf`: ENQ, or `STX cmd addr(4) [count(2) data]
/// ETX sum(2)`; `cmd` is `0`, `1`, `7`, `8` or, for the extended commands, `E00`, `E10`, `E7`,
/// `E8` (`dev`: the byte address; for a force, the force address, sent low byte first).
fn parse_port(buf: &[u8]) -> Option<(usize, Option<Req>)> {
    let at = Instant::now();
    let req = |cmd: &str, dev, count, sum_ok| Req { at, station: 0, cmd: cmd.into(), dev, count, wait: 0, sum_ok };
    if buf[0] == ENQ {
        return Some((1, Some(req("ENQ", 0, 0, true))));
    }
    let etx = buf.iter().position(|b| *b == ETX)?;
    if buf.len() < etx + 3 {
        return None;
    }
    let sum_ok = sum2(&buf[1..=etx]) == buf[etx + 1..etx + 3];
    let code_len = match (buf.get(1), buf.get(2)) {
        (Some(b'E'), Some(b'7' | b'8')) => 2,
        (Some(b'E'), _) => 3,
        _ => 1,
    };
    let cmd = String::from_utf8_lossy(&buf[1..(1 + code_len).min(etx)]).to_string();
    let at_addr = 1 + code_len;
    let mut dev = buf.get(at_addr..at_addr + 4).and_then(hexnum).unwrap_or(0);
    if cmd.ends_with('7') || cmd.ends_with('8') {
        dev = (dev >> 8) | (dev & 0xFF) << 8;
    }
    let count = buf.get(at_addr + 4..at_addr + 6).and_then(hexnum).unwrap_or(0) as usize;
    Some((etx + 3, Some(req(&cmd, dev, count, sum_ok))))
}

type Responder = pty_responder::Responder<Req>;

/// Starts a responder on a new pty: `answer(request, k)` (k counts the requests from 0) says
/// what to do for each. `port`: programming-port requests, else computer-link ones.
fn responder(port: bool, answer: impl FnMut(&Req, usize) -> Vec<Act> + Send + 'static) -> Responder {
    let frame = move |buf: &mut Vec<u8>, _| {
        // What cannot start a request is ignored, as a PLC ignores it.
        let start = buf.iter().position(|b| *b == ENQ || (port && *b == STX)).unwrap_or(buf.len());
        buf.drain(..start);
        if buf.is_empty() {
            return None;
        }
        let (len, req) = if port { parse_port(buf) } else { parse_link(buf) }?;
        buf.drain(..len);
        Some(req)
    };
    pty_responder::start(frame, answer)
}

/// Link replies, built by hand: `STX station "FF" data ETX sum`, `ACK station "FF"`, `NAK
/// station "FF" code` (seed 004, "FX系列PLC专用协议通信指令格式详解").
fn link_data(station: u8, data: &str) -> Vec<u8> {
    let body = format!("{station:02X}FF{data}\x03").into_bytes();
    [vec![STX], body.clone(), sum2(&body)].concat()
}
fn link_ack(station: u8) -> Vec<u8> {
    format!("\x06{station:02X}FF").into_bytes()
}
fn link_nak(station: u8, code: u8) -> Vec<u8> {
    format!("\x15{station:02X}FF{code:02X}").into_bytes()
}

/// The responder's PLC: every D register holds its own number, so a value read shows which
/// register it came from.
fn words(from: u32, count: usize) -> String {
    (0..count as u32).map(|i| format!("{:04X}", from + i)).collect()
}

/// A programming-port read reply (`STX data ETX sum`, the sum over data and ETX) from the
/// same PLC: D n at 1000H + 2n, low byte first (seed 004's D123 example).
fn port_data(addr: u32, count: usize) -> Vec<u8> {
    let hex: String = (addr..addr + count as u32)
        .map(|a| {
            let n = (a - 0x1000) / 2;
            format!("{:02X}", if a % 2 == 0 { n & 0xFF } else { n >> 8 })
        })
        .collect();
    let body = [hex.into_bytes(), vec![ETX]].concat();
    [vec![STX], body.clone(), sum2(&body)].concat()
}

fn read_one(d: &mut dyn Device, name: &str) -> plcsh::core::Result<i64> {
    let o = ops(d, &[name]);
    d.read(&o).map(|v| v[0].as_i64())
}

/// The `N` of "within N ms" in a message.
fn within_ms(msg: &str) -> u64 {
    let at = msg.find("within ").unwrap_or_else(|| panic!("{msg}")) + 7;
    msg[at..].split(' ').next().unwrap().parse().unwrap_or_else(|_| panic!("{msg}"))
}

// Seed 004, computer link ("FX系列PLC专用协议通信指令格式详解"): a reply carries the station and
// PC number but no device address, so only time tells a late reply from the next one. The
// driver waits for quiet before every request and, after a timeout, for one more timeout.
#[test]
fn a_late_reply_is_never_taken_for_the_next_read() {
    let _alone = line_timing();
    // timeout=400ms. The responder's delays are chosen with room on the side a loaded machine
    // moves them (later: a reader, writer or driver thread woken late only adds to a delay):
    // the answers in time come by 0.3 T, the late ones between 1.2 T and 1.5 T — past the
    // timeout, and half a timeout before the one more timeout the driver waits ends.
    const T: u64 = 400;
    // Per read of D100, D101, …: the responder's delay in units of T/10, and whether the read
    // is answered in time. The late ones come inside the one more timeout the driver waits;
    // the one at 3T comes after it, while the driver is idle.
    let plan: [(u64, bool); 10] = [
        (15, false),
        (0, true),
        (13, false),
        (3, true),
        (14, false),
        (0, true),
        (12, false),
        (2, true),
        (30, false),
        (0, true),
    ];
    let r = responder(false, move |q, k| {
        let mut acts = vec![Act::Sleep(Duration::from_millis(plan.get(k).map_or(0, |p| p.0) * T / 10))];
        if q.cmd == "WR" && q.sum_ok {
            acts.push(Act::Send(link_data(q.station, &words(q.dev, q.count))));
        }
        acts
    });
    let mut d = open(&r.url("fxlink", &format!("?timeout={T}ms")));
    for (k, (delay, in_time)) in plan.iter().enumerate() {
        let name = format!("D{}", 100 + k);
        match read_one(d.as_mut(), &name) {
            Ok(v) => {
                assert_eq!(v, 100 + k as i64, "{name} read as another register's value");
                assert!(in_time, "{name}: answered after {delay}/10 T, yet taken");
            }
            Err(e) => {
                assert!(!in_time, "{name}: {e}");
                assert_eq!(e.kind, ErrorKind::Link, "{e}");
                assert!(e.message.contains(&format!("no reply to WR of 1 point(s) from D0{}", 100 + k)), "{e}");
                if *delay < 20 {
                    assert!(e.message.contains("came later and were dropped"), "{e}");
                    assert!(e.hint.as_deref().unwrap().contains(&format!("timeout={}ms", 2 * T)), "{e:?}");
                } else {
                    // The reply arrives while the driver is idle; the next read starts once it
                    // is on the line (the responder says when it wrote it).
                    let deadline = Instant::now() + Duration::from_secs(10);
                    while r.ends().len() <= k {
                        assert!(Instant::now() < deadline, "the responder never answered {name}");
                        std::thread::sleep(Duration::from_millis(5));
                    }
                }
            }
        }
    }
    let seen = r.seen();
    assert_eq!(seen.len(), plan.len(), "a timeout is not resent: {seen:?}");
    assert!(seen.iter().all(|q| q.sum_ok && q.cmd == "WR" && q.count == 1));
}

// Seed 004, computer link: the reply repeats the request's station number ("站号"); a reply
// from another station is not this station's answer.
#[test]
fn a_reply_from_another_station_is_never_taken() {
    let _alone = line_timing();
    // Station 5 is asked; station 3 answers the first request of each read (with its own D100,
    // 9999), station 5 the resend. Then station 3 answers everything.
    let only_3 = Arc::new(AtomicBool::new(false));
    let flag = only_3.clone();
    let r = responder(false, move |q, k| {
        let from = if flag.load(Ordering::SeqCst) || k % 2 == 0 { 3 } else { q.station };
        let reply = match q.cmd.as_str() {
            "WR" if from == 3 => link_data(3, &"270F".repeat(q.count)),
            "WR" => link_data(from, &words(q.dev, q.count)),
            _ => link_ack(from),
        };
        vec![Act::Send(reply)]
    });
    let mut d = open(&r.url("fxlink", "?station=5"));
    for k in 0..3 {
        assert_eq!(read_one(d.as_mut(), &format!("D{}", 100 + k)).unwrap(), 100 + k as i64);
    }
    assert_eq!(r.seen().len(), 6, "each read resent once");
    assert!(r.seen().iter().all(|q| q.station == 5 && q.sum_ok));
    only_3.store(true, Ordering::SeqCst);
    let e = read_one(d.as_mut(), "D100").unwrap_err();
    assert_eq!(e.kind, ErrorKind::Link, "{e}");
    assert!(e.message.contains("a reply from station 3") && e.message.contains("station 5"), "{e}");
    assert!(e.message.contains("WR of 1 point(s) from D0100") && e.message.contains("4 attempts"), "{e}");
    assert!(e.hint.as_deref().unwrap().contains("D8121"), "{e:?}");
    // Station 3's ACK does not confirm station 5's write.
    let o = ops(d.as_ref(), &["D100"]);
    let e = d.write(&[(o[0], Value::Int(1))]).unwrap_err();
    assert_eq!(e.kind, ErrorKind::Link, "{e}");
    assert!(e.message.contains("WW of 1 value(s) at D0100"), "{e}");
    assert_eq!(r.seen().len(), 6 + 4 + 4);
}

// Seed 004, computer link: a write is acknowledged with ACK; an error is answered NAK with its
// code ("若发送码有误，则有以下回应"). A write is done only on ACK from the addressed station.
#[test]
fn a_refused_or_unconfirmed_write_never_reports_success() {
    let _alone = line_timing();
    // By request: NAK 06, then a stale read reply to every write, then NAK 02 (sum) to all.
    let r = responder(false, |q, k| {
        let reply = match k {
            0 => link_nak(q.station, 0x06),
            1..=4 => link_data(q.station, &words(100, 1)),
            _ => link_nak(q.station, 0x02),
        };
        vec![Act::Send(reply)]
    });
    let mut d = open(&r.url("fxlink", ""));
    let o = ops(d.as_ref(), &["D100", "M500"]);
    let e = d.write(&[(o[0], Value::Int(5))]).unwrap_err();
    assert_eq!(e.kind, ErrorKind::Refused, "{e}");
    assert!(e.message.contains("NAK 06H to WW of 1 value(s) at D0100"), "{e}");
    assert_eq!(r.seen().len(), 1, "a device-number error is not resent");
    let e = d.write(&[(o[1], Value::Bool(true))]).unwrap_err();
    assert_eq!(e.kind, ErrorKind::Link, "{e}");
    assert!(e.message.contains("BW of 1 point(s) at M0500") && e.message.contains("where ACK should be"), "{e}");
    assert_eq!(r.seen().len(), 5);
    let e = d.write(&[(o[0], Value::Int(5))]).unwrap_err();
    assert_eq!(e.kind, ErrorKind::Refused, "{e}");
    assert!(e.message.contains("NAK 02H") && e.message.contains("sum check"), "{e}");
    assert_eq!(r.seen().len(), 9, "a sum-check NAK is resent three times");
    assert!(r.seen().iter().all(|q| q.sum_ok), "the frames were right: the refusals are the responder's");
    drop(d);
    // The shell says so too: no `ok` for a refused or unconfirmed write.
    let r = responder(false, |q, k| {
        vec![Act::Send(if k == 0 { link_nak(q.station, 6) } else { link_data(q.station, "0064") })]
    });
    for kind in ["refused", "link"] {
        let out = run(&["--json", "-d", &format!("l={}", r.url("fxlink", "")), "-c", "use l; set D100=5"], "");
        let lines = json_lines(&out);
        let set = lines.iter().find(|l| l["cmd"] == "set").unwrap_or_else(|| panic!("{lines:?}"));
        assert_eq!(set["ok"], false, "{lines:?}");
        assert_eq!(set["error"]["kind"], kind, "{lines:?}");
        assert!(!out.status.success());
    }
}

// Seed 004: the programming port answers ENQ with ACK when ready and NAK on error ("通过ENQ、
// ACK和NAK上位机协调与PLC的通信应答"), at 9600 baud 7E1 ("传输速率固定为9600bps，奇偶校验位采用
// 偶校验 … 七位有效数据"). 00H is what a serial port delivers for a character with a parity
// error: noise, not NAK.
#[test]
fn noise_is_never_called_a_nak() {
    let _alone = line_timing();
    let burst = Duration::from_millis(31);
    // A 31 ms burst of 00H before the ACK: the handshake and the read go through, nothing resent.
    let r = responder(true, move |q, _| match q.cmd.as_str() {
        "ENQ" => vec![Act::Noise(burst, 9600), Act::Send(vec![ACK])],
        "0" => vec![Act::Send(port_data(q.dev, q.count))],
        _ => vec![Act::Send(vec![NAK])],
    });
    let mut d = open(&r.url("fx", ""));
    assert_eq!(read_one(d.as_mut(), "D123").unwrap(), 123);
    let cmds: Vec<String> = r.seen().iter().map(|q| q.cmd.clone()).collect();
    assert_eq!(cmds, ["ENQ", "0"]);
    drop(d);
    // Nothing but the burst: reported as noise after four paced ENQs, never as NAK.
    let r = responder(true, move |_, _| vec![Act::Noise(burst, 9600)]);
    let mut d = open(&r.url("fx", ""));
    let e = read_one(d.as_mut(), "D123").unwrap_err();
    assert_eq!(e.kind, ErrorKind::Link, "{e}");
    assert!(e.message.contains("noise on the line") && e.message.contains("× 00H") && e.message.contains("ENQ"), "{e}");
    assert!(!e.message.contains("NAK"), "{e}");
    let seen = r.seen();
    assert_eq!(seen.len(), 4, "{seen:?}");
    for w in seen.windows(2) {
        let pause = w[1].at - w[0].at;
        assert!(pause > burst + Duration::from_millis(20), "ENQ resent {pause:?} after the last into the noise");
    }
    drop(d);
    // A real NAK stays a NAK.
    let r = responder(true, |_, _| vec![Act::Send(vec![NAK])]);
    let mut d = open(&r.url("fx", ""));
    let e = read_one(d.as_mut(), "D123").unwrap_err();
    assert!(e.message.contains("answered ENQ with NAK 4 times"), "{e}");
    drop(d);
    // The computer link: noise before a reply is set aside; noise alone is noise.
    let noise_only = Arc::new(AtomicBool::new(false));
    let flag = noise_only.clone();
    let r = responder(false, move |q, _| {
        let mut acts = vec![Act::Noise(burst, 9600)];
        if !flag.load(Ordering::SeqCst) {
            acts.push(Act::Send(link_data(q.station, &words(q.dev, q.count))));
        }
        acts
    });
    let mut d = open(&r.url("fxlink", ""));
    assert_eq!(read_one(d.as_mut(), "D7").unwrap(), 7);
    assert_eq!(r.seen().len(), 1);
    noise_only.store(true, Ordering::SeqCst);
    let e = read_one(d.as_mut(), "D7").unwrap_err();
    assert!(e.message.contains("noise on the line") && !e.message.contains("NAK"), "{e}");
    assert_eq!(r.seen().len(), 5);
}

/// Characters of a computer-link WR of `count` words: the request (`ENQ`, station 2, PC 2,
/// `WR`, wait 1, device 5, count 2, sum 2) and the reply (`STX`, station 2, PC 2, 4 per word,
/// `ETX`, sum 2).
fn wr_chars(count: usize) -> (usize, usize) {
    (17, 8 + 4 * count)
}

// Seed 004, computer link: the message wait is 0–150 ms as one hex digit ("等待延时为0-150毫秒，
// 以十六进制0H-FH表示"); a WR reads up to 64 words. The timeout follows the baud rate, the
// frames' sizes and the wait: a 64-word WR at 4800 baud is ~550 ms of reply alone.
#[test]
fn timeouts_scale_with_the_baud_rate_and_the_frame_size() {
    let _alone = line_timing();
    // A responder that honours the wait digit and sends its reply at the line's pace.
    for baud in [4800u32, 9600, 19200] {
        let r = responder(false, move |q, _| {
            vec![
                Act::Sleep(Duration::from_millis(10 * q.wait as u64)),
                Act::Paced(link_data(q.station, &words(q.dev, q.count)), baud),
            ]
        });
        let mut d = open(&r.url("fxlink", &format!("?baud={baud}&wait=2")));
        let o = ops(d.as_ref(), &["D0..D63"]);
        let start = Instant::now();
        let v = d.read(&o).unwrap_or_else(|e| panic!("{baud} baud: {e}"));
        let took = start.elapsed();
        assert_eq!(v, (0..64).map(Value::Int).collect::<Vec<_>>(), "{baud} baud");
        let reply = Duration::from_secs_f64(wr_chars(64).1 as f64 * 10.0 / baud as f64);
        assert!(took >= reply, "{baud} baud: the reply was paced ({took:?} < {reply:?})");
        assert_eq!(r.seen().len(), 1, "{baud} baud: answered in time, not resent");
    }
    // A responder that never answers: the timeout each read waited, from the messages.
    let cases: Vec<(u32, usize, u8, &str)> = vec![
        (4800, 64, 0, ""),
        (9600, 64, 0, ""),
        (19200, 64, 0, ""),
        (9600, 1, 0, ""),
        (9600, 1, 5, ""),
        (4800, 64, 0, "&timeout=150ms"),
    ];
    let handles: Vec<_> = cases
        .iter()
        .map(|&(baud, count, wait, extra)| {
            let extra = extra.to_string();
            std::thread::spawn(move || {
                let r = responder(false, |_, _| Vec::new());
                let mut d = open(&r.url("fxlink", &format!("?baud={baud}&wait={wait}{extra}")));
                let o = ops(d.as_ref(), &[&format!("D0..D{}", count - 1)]);
                let start = Instant::now();
                let e = d.read(&o).unwrap_err();
                let took = start.elapsed();
                assert_eq!(e.kind, ErrorKind::Link, "{e}");
                let ms = within_ms(&e.message);
                assert!(took >= Duration::from_millis(ms), "waited {took:?}, said {ms} ms");
                (ms, e.message.clone())
            })
        })
        .collect();
    let got: Vec<(u64, String)> = handles.into_iter().map(|h| h.join().unwrap()).collect();
    let ms = |i: usize| got[i].0 as f64;
    let wire = |chars: usize, baud: u32| chars as f64 * 10_000.0 / baud as f64;
    let (q64, r64) = wr_chars(64);
    let (q1, r1) = wr_chars(1);
    let near = |a: f64, b: f64, what: &str| assert!((a - b).abs() <= 2.0, "{what}: {a} vs {b} ms ({got:?})");
    assert!(ms(0) > ms(1) && ms(1) > ms(2), "{got:?}");
    assert!(ms(0) >= wire(q64 + r64, 4800), "a 64-word WR at 4800 baud has time to arrive: {got:?}");
    near(ms(1) - ms(2), wire(q64 + r64, 9600) - wire(q64 + r64, 19200), "9600 → 19200 baud");
    near(ms(0) - ms(1), wire(q64 + r64, 4800) - wire(q64 + r64, 9600), "4800 → 9600 baud");
    near(ms(1) - ms(3), wire(r64 - r1, 9600), "64 words → 1 word");
    let _ = q1;
    near(ms(4) - ms(3), 50.0, "wait digit 5");
    assert_eq!(got[5].0, 150, "timeout= overrides: {}", got[5].1);
    assert!(got[0].1.contains("281 characters at 4800 7E1"), "{}", got[0].1);
}

// Seed 004: a resend after a bad exchange ("如接收的信息有误，则重新读取"). A reply still coming
// in when the timeout runs out is not a reply, nor is its tail: the resend waits until the line
// has been quiet for at least the frame time.
#[test]
fn resends_wait_for_a_quiet_line() {
    let _alone = line_timing();
    // The first reply stalls half way, past the timeout, and its tail comes later; the resend
    // waits until the tail is over and the line has been quiet for the frame time, and its
    // reply is used. A 64-word WR at 4800 baud: a 835 ms timeout, a 264-character reply of
    // 550 ms, so 550 ms of quiet before a resend. The head's 132 characters take 275 ms; after
    // an 835 ms stall the tail starts 1110 ms after the request, in the middle of the 835–1385 ms
    // the driver waits for quiet after its timeout: a thread woken up to 275 ms late on either
    // side (the responder's, or the driver's before it starts its timeout) keeps the order.
    let baud = 4800;
    let r = responder(false, move |q, k| {
        let reply = link_data(q.station, &words(q.dev, q.count));
        if k > 0 {
            return vec![Act::Paced(reply, baud)];
        }
        let (head, tail) = reply.split_at(reply.len() / 2);
        vec![Act::Paced(head.to_vec(), baud), Act::Sleep(Duration::from_millis(835)), Act::Paced(tail.to_vec(), baud)]
    });
    let mut d = open(&r.url("fxlink", &format!("?baud={baud}")));
    let o = ops(d.as_ref(), &["D0..D63"]);
    assert_eq!(d.read(&o).unwrap(), (0..64).map(Value::Int).collect::<Vec<_>>());
    let (seen, ends) = (r.seen(), r.ends());
    assert_eq!(seen.len(), 2, "{seen:?}");
    let quiet = seen[1].at.saturating_duration_since(ends[0]);
    assert!(quiet >= Duration::from_millis(400), "the resend went out {quiet:?} after the tail ended");
    drop(d);
    // A timeout shorter than the reply's wire time cuts every reply short: reported as an
    // incomplete reply, each resend after the line fell quiet.
    let baud = 4800;
    let r = responder(false, move |q, _| vec![Act::Paced(link_data(q.station, &words(q.dev, q.count)), baud)]);
    // 264 characters at 4800 baud take 550 ms; a 275 ms timeout cuts every reply short. The
    // reply's last character cannot reach the line sooner, however the threads are scheduled,
    // and its first one is due at once: a thread woken up to 275 ms late (the responder's, or
    // the driver's between its deadline check and its read) keeps the outcome.
    let mut d = open(&r.url("fxlink", &format!("?baud={baud}&timeout=275ms")));
    let o = ops(d.as_ref(), &["D0..D63"]);
    let e = d.read(&o).unwrap_err();
    assert_eq!(e.kind, ErrorKind::Link, "{e}");
    assert!(e.message.contains("incomplete reply") && e.message.contains("4 attempts"), "{e}");
    let (seen, ends) = (r.seen(), r.ends());
    assert_eq!(seen.len(), 4, "{seen:?}");
    for k in 1..4 {
        let quiet = seen[k].at.saturating_duration_since(ends[k - 1]);
        // The resend waits for the frame's time on the wire (550 ms) after the last character.
        assert!(quiet >= Duration::from_millis(400), "resend {k} went out {quiet:?} after the line fell quiet");
    }
}

// ----- the programming port's reach per model, the E-commands, ENQ optional -----

/// A programming-port frame built by hand: STX, the body's characters, ETX, then the sum check
/// over the body and ETX (seed 004; the E-commands as the public write-up and drivers send
/// them: `E00`/`E10` with address, count and data, `E7`/`E8` with the force address low byte
/// first).
fn port_frame(body: &str) -> Vec<u8> {
    let b = [body.as_bytes(), &[ETX]].concat();
    [vec![STX], b.clone(), sum2(&b)].concat()
}

/// The data bytes of a read reply `STX hex ETX sum`, its sum check verified.
fn reply_bytes(r: &[u8]) -> Vec<u8> {
    let n = r.len();
    assert!(n >= 4 && r[0] == STX && r[n - 3] == ETX, "not a data frame: {r:02X?}");
    assert_eq!(sum2(&r[1..n - 2]), r[n - 2..].to_vec(), "sum check of {r:02X?}");
    r[1..n - 3].chunks(2).map(|c| hexnum(c).unwrap() as u8).collect()
}

// node-fxplc (`lib/FXPLCClient.js`, `lib/registers.js`) and KrystianD/fxplc (`FXPLCClient.py`)
// send no ENQ and compute D n at 1000H + 2n, M n's byte at 0100H + n/8 and its force address
// at 0800H + n (low byte first); HslCommunication's FX3U-era client (`MelsecFxSerial`,
// `isNewVersion`) reads D n with E00 at 4000H + 2n and writes it with E10; fx-fiddle
// (`cli/fx-fiddle/lib/protocol.py`) forces with E7/E8. Their frames, re-created here, go to a
// served FX2N and a served FX3U: each answers what the model answers, NAK to the rest.
#[test]
fn served_fx2n_and_fx3u_answer_the_public_drivers_frames() {
    // The frame builder against a literal: STX "E00" "47D0" "02" ETX "E9" (D1000 by E00).
    assert_eq!(port_frame("E0047D002"), hex("02 45 30 30 34 37 44 30 30 32 03 45 39"));
    for model in ["FX2N", "FX3U"] {
        let srv = Server::start(&format!("public-{model}"), &["--fx-model", model]);
        assert_eq!(srv.ready["fx_model"], model);
        let mut c = Raw::open(&srv.port);
        // No ENQ first: writeNumber('D1000', -1234) = "1" "17D0" "02" "2EFB" (FB2EH, low byte first).
        assert_eq!(c.ask(&port_frame("117D0022EFB"), 1), vec![ACK], "{model}");
        assert_eq!(reply_bytes(&c.ask(&port_frame("017D002"), 8)), vec![0x2E, 0xFB], "{model} D1000");
        // D7999: 1000H + 2·7999 = 4E7EH; 7999 = 1F3FH.
        assert_eq!(c.ask(&port_frame("14E7E023F1F"), 1), vec![ACK], "{model}");
        assert_eq!(reply_bytes(&c.ask(&port_frame("04E7E02"), 8)), vec![0x3F, 0x1F], "{model} D7999");
        // writeBit('M1535', true): "7" and 0800H + 1535 = 0DFFH as "FF0D"; readBit: byte 01BFH, bit 7.
        assert_eq!(c.ask(&port_frame("7FF0D"), 1), vec![ACK], "{model}");
        assert_eq!(reply_bytes(&c.ask(&port_frame("001BF01"), 6)), vec![0x80], "{model} M1535");
        // And with ENQ first, as the seed's host program does: the same answers.
        assert_eq!(c.ask(&[ENQ], 1), vec![ACK]);
        assert_eq!(reply_bytes(&c.ask(&port_frame("017D002"), 8)), vec![0x2E, 0xFB]);
        let e00_d1000 = c.ask(&port_frame("E0047D002"), 8);
        if model == "FX2N" {
            assert_eq!(e00_d1000, vec![NAK], "an FX2N answers no E-commands");
            assert_eq!(c.ask(&port_frame("E70040"), 1), vec![NAK]);
            continue;
        }
        // FX3U: E00 sees what the classic write wrote (one memory behind both tables).
        assert_eq!(reply_bytes(&e00_d1000), vec![0x2E, 0xFB], "E00 D1000 at 47D0H");
        // E10 D7999 (7E7EH) = 1234H, read back by both commands.
        assert_eq!(c.ask(&port_frame("E107E7E023412"), 1), vec![ACK]);
        assert_eq!(reply_bytes(&c.ask(&port_frame("E007E7E02"), 8)), vec![0x34, 0x12]);
        assert_eq!(reply_bytes(&c.ask(&port_frame("04E7E02"), 8)), vec![0x34, 0x12]);
        // M1535 in the E00 table: 8800H + 191 = 88BFH, bit 7 (forced on above); E8 at
        // 4000H + 1535 = 45FFH ("FF45") turns it off for both tables.
        assert_eq!(reply_bytes(&c.ask(&port_frame("E0088BF01"), 6)), vec![0x80]);
        assert_eq!(c.ask(&port_frame("E8FF45"), 1), vec![ACK]);
        assert_eq!(reply_bytes(&c.ask(&port_frame("001BF01"), 6)), vec![0x00]);
        // Past the classic table, the FX3U's own ranges: M7679 (E7 5DFFH, byte 8BBFH bit 7),
        // S4095 (E7 6700H + 4095 = 76FFH, byte 8EDFH bit 7), TN511 (1000H + 2·511 = 13FEH),
        // D8000 (8000H: the watchdog, 200 ms = C8H).
        assert_eq!(c.ask(&port_frame("E7FF5D"), 1), vec![ACK]);
        assert_eq!(reply_bytes(&c.ask(&port_frame("E008BBF01"), 6)), vec![0x80]);
        assert_eq!(c.ask(&port_frame("E7FF76"), 1), vec![ACK]);
        assert_eq!(reply_bytes(&c.ask(&port_frame("E008EDF01"), 6)), vec![0x80]);
        assert_eq!(c.ask(&port_frame("E1013FE020700"), 1), vec![ACK]);
        assert_eq!(reply_bytes(&c.ask(&port_frame("E0013FE02"), 8)), vec![0x07, 0x00]);
        assert_eq!(reply_bytes(&c.ask(&port_frame("E00800002"), 8)), vec![0xC8, 0x00]);
        // Refused: past D7999 by 4000H + 2n (7E80H), program memory (E01, not simulated), a
        // bad sum check; then the line still works.
        assert_eq!(c.ask(&port_frame("E007E8002"), 1), vec![NAK]);
        assert_eq!(c.ask(&port_frame("E01805C06"), 1), vec![NAK]);
        let mut bad = port_frame("E0047D002");
        let n = bad.len();
        bad[n - 1] ^= 1;
        assert_eq!(c.ask(&bad, 1), vec![NAK]);
        assert_eq!(reply_bytes(&c.ask(&port_frame("E0047D002"), 8)), vec![0x2E, 0xFB]);
    }
}

/// node-fxplc as installed from npm (.ci/run puts it in target/node-fxplc), or `None` with a
/// note outside CI; in CI it must be there.
fn node_fxplc() -> Option<PathBuf> {
    let dir = std::env::var_os("PLCSH_NODE_FXPLC").map(PathBuf::from).unwrap_or_else(|| {
        PathBuf::from(concat!(env!("CARGO_MANIFEST_DIR"), "/target/node-fxplc/node_modules/node-fxplc"))
    });
    let node = std::process::Command::new("node").arg("--version").output().is_ok_and(|o| o.status.success());
    if node && dir.join("dist/esm/index.js").exists() {
        return Some(dir);
    }
    assert!(std::env::var_os("CI").is_none(), "CI must install node-fxplc (npm) into {}", dir.display());
    common::skipped(&format!(
        "node and node-fxplc in {} (npm install --prefix target/node-fxplc node-fxplc@0.1.6)",
        dir.display()
    ));
    None
}

// The real node-fxplc client (npm `node-fxplc`, n-car/node-fxplc) over its TCP transport:
// D1000, D7999 and M1535 of a served FX2N and FX3U, and D8000 by its formula (1000H + 2n =
// 4E80H, where there is no device) refused with NAK, which it reports as NotSupportedCommandError.
#[test]
fn node_fxplc_reads_and_writes_a_served_fx2n_and_fx3u() {
    let Some(pkg) = node_fxplc() else { return };
    let script = concat!(env!("CARGO_MANIFEST_DIR"), "/tests/support/node_fxplc.mjs");
    for model in ["FX2N", "FX3U"] {
        let served = serve(&["--fx-tcp", "127.0.0.1:0", "--fx-model", model]);
        let addr = served.ready["fx_tcp"].as_str().unwrap().to_string();
        let (host, port) = addr.rsplit_once(':').unwrap();
        let ops = serde_json::json!([
            {"op": "writeNumber", "reg": "D1000", "value": -1234},
            {"op": "readNumber", "reg": "D1000"},
            {"op": "writeNumber", "reg": "D7999", "value": 7999},
            {"op": "readNumber", "reg": "D7999"},
            {"op": "writeBit", "reg": "M1535", "value": true},
            {"op": "readBit", "reg": "M1535"},
            {"op": "readNumber", "reg": "D8000"},
        ]);
        let out = std::process::Command::new("node")
            .args([script, pkg.to_str().unwrap(), host, port, &ops.to_string()])
            .output()
            .expect("run node");
        let text = String::from_utf8_lossy(&out.stdout);
        assert!(out.status.success(), "{model}: {text} {}", String::from_utf8_lossy(&out.stderr));
        let got: serde_json::Value = serde_json::from_str(text.trim()).unwrap_or_else(|e| panic!("{text}: {e}"));
        let values: Vec<&serde_json::Value> = got.as_array().unwrap().iter().map(|r| &r["value"]).collect();
        assert_eq!(values[1], -1234, "{model}: {got}");
        assert_eq!(values[3], 7999, "{model}: {got}");
        assert_eq!(values[5], true, "{model}: {got}");
        assert_eq!(got[6]["error"], "NotSupportedCommandError", "{model}: {got}");
        // plcsh's own driver sees what node-fxplc wrote.
        let mut d = open(&format!("fx+tcp://{addr}?model={model}"));
        assert_eq!(read_one(d.as_mut(), "D1000").unwrap(), -1234);
        assert_eq!(read_one(d.as_mut(), "D7999").unwrap(), 7999);
        assert_eq!(read_one(d.as_mut(), "M1535").unwrap(), 1);
    }
}

/// An independent FX PLC for the driver: `model`'s tables read by the test's own arithmetic
/// (D n holds n; M n is on for odd n), answering ENQ as `enq` says.
#[derive(Clone, Copy, PartialEq)]
enum EnqMode {
    /// Never answers ENQ; answers frames (clones, as the public drivers use them).
    Never,
    /// Answers ENQ with ACK and no frame until it has had one.
    Required,
}

fn fx_responder(extended: bool, enq: EnqMode) -> Responder {
    let mut opened = false;
    responder(true, move |q, _| {
        let data = |bytes: Vec<u8>| {
            let body = [bytes.iter().map(|b| format!("{b:02X}")).collect::<String>().into_bytes(), vec![ETX]].concat();
            vec![Act::Send([vec![STX], body.clone(), sum2(&body)].concat())]
        };
        if q.cmd == "ENQ" {
            opened = true;
            return if enq == EnqMode::Never { vec![] } else { vec![Act::Send(vec![ACK])] };
        }
        if enq == EnqMode::Required && !opened || !q.sum_ok {
            return if q.sum_ok { vec![] } else { vec![Act::Send(vec![NAK])] };
        }
        // The word table and the bit table of the model's command set.
        let (read, write, force_on, force_off, d_base, m_base) =
            if extended { ("E00", "E10", "E7", "E8", 0x4000, 0x8800) } else { ("0", "1", "7", "8", 0x1000, 0x0100) };
        let cmd = q.cmd.as_str();
        if cmd == read && (d_base..d_base + 16000).contains(&q.dev) {
            let bytes = (q.dev..q.dev + q.count as u32).map(|a| {
                let n = (a - d_base) / 2;
                if a % 2 == 0 {
                    n as u8
                } else {
                    (n >> 8) as u8
                }
            });
            return data(bytes.collect());
        }
        if cmd == read && (m_base..m_base + 960).contains(&q.dev) {
            return data(vec![0xAA; q.count]);
        }
        if cmd == write || cmd == force_on || cmd == force_off {
            return vec![Act::Send(vec![ACK])];
        }
        vec![Act::Send(vec![NAK])]
    })
}

// The driver against the independent responder, per model: an FX2N's D1000, D7999 and M1535
// through the classic commands (0 at 17D0H and 4E7EH, 0 at 01BFH, force 7 at 0DFFH), an
// FX3U's through the E-commands (E00 at 47D0H and 7E7EH, E00 at 88BFH, E7 at 45FFH, E10 at
// 7E7EH), and its M7679 and S4095, which no classic table reaches. The responder never answers
// ENQ: the driver probes once, then talks without it.
#[test]
fn the_driver_reaches_d1000_d7999_m1535_per_model() {
    let _alone = line_timing();
    for (model, extended) in [("FX2N", false), ("FX1N", false), ("FX3U", true)] {
        let r = fx_responder(extended, EnqMode::Never);
        let mut d = open(&r.url("fx", &format!("?model={model}")));
        assert_eq!(read_one(d.as_mut(), "D1000").unwrap(), 1000, "{model}");
        assert_eq!(read_one(d.as_mut(), "D7999").unwrap(), 7999, "{model}");
        assert_eq!(read_one(d.as_mut(), "M1535").unwrap(), 1, "{model}");
        let o = ops(d.as_ref(), &["M1535", "D7999"]);
        d.write(&[(o[0], Value::Bool(true)), (o[1], Value::Int(-1))]).unwrap();
        let seen: Vec<(String, u32)> = r.seen().iter().map(|q| (q.cmd.clone(), q.dev)).collect();
        let want: Vec<(&str, u32)> = if extended {
            vec![("ENQ", 0), ("E00", 0x47D0), ("E00", 0x7E7E), ("E00", 0x88BF), ("E7", 0x45FF), ("E10", 0x7E7E)]
        } else {
            vec![("ENQ", 0), ("0", 0x17D0), ("0", 0x4E7E), ("0", 0x01BF), ("7", 0x0DFF), ("1", 0x4E7E)]
        };
        let want: Vec<(String, u32)> = want.into_iter().map(|(c, a)| (c.to_string(), a)).collect();
        assert_eq!(seen, want, "{model}: one ENQ probe, then the model's commands");
        assert!(r.seen().iter().all(|q| q.sum_ok));
        if extended {
            // The FX3U's own ranges: M7679 (byte 8BBFH), forced as 5DFFH; S4095 forced as 76FFH.
            assert_eq!(read_one(d.as_mut(), "M7679").unwrap(), 1);
            let o = ops(d.as_ref(), &["S4095"]);
            d.write(&[(o[0], Value::Bool(false))]).unwrap();
            let tail: Vec<(String, u32)> = r.seen()[6..].iter().map(|q| (q.cmd.clone(), q.dev)).collect();
            assert_eq!(tail, vec![("E00".to_string(), 0x8BBF), ("E8".to_string(), 0x76FF)]);
        } else {
            // Past the classic table: refused before anything is sent, pointing to what reaches it.
            let before = r.seen().len();
            let e = d.operands().parse("M1536").map(|_| ()).unwrap_err();
            if model == "FX2N" {
                assert!(e.message.contains("M0–M1535") && e.hint.as_deref().unwrap().contains("model=FX3U"), "{e:?}");
            }
            assert_eq!(r.seen().len(), before);
        }
    }
    // A PLC without the E-commands opened as an FX3U: NAK, and the hint says what to open it as.
    let r = fx_responder(false, EnqMode::Never);
    let mut d = open(&r.url("fx", "?model=FX3U"));
    let e = read_one(d.as_mut(), "D1000").unwrap_err();
    assert_eq!(e.kind, ErrorKind::Refused, "{e}");
    assert!(e.message.contains("an E00 read of 2 bytes at 47D0H"), "{e}");
    assert!(e.hint.as_deref().unwrap().contains("model=FX2N"), "{e:?}");
}

// ENQ is optional: a PLC that never answers it is probed once and then talked to without it
// (above); one that requires it gets ENQ before the first frame and again after a failure; one
// that answers NAK to ENQ has answered (noise_is_never_called_a_nak: "answered ENQ with NAK").
#[test]
fn enq_is_probed_and_followed_where_the_plc_requires_it() {
    let _alone = line_timing();
    let r = fx_responder(false, EnqMode::Required);
    let mut d = open(&r.url("fx", "?model=FX2N"));
    assert_eq!(read_one(d.as_mut(), "D1000").unwrap(), 1000);
    assert_eq!(read_one(d.as_mut(), "D7999").unwrap(), 7999);
    let cmds: Vec<String> = r.seen().iter().map(|q| q.cmd.clone()).collect();
    assert_eq!(cmds, ["ENQ", "0", "0"], "ENQ once, then frames in the open conversation");
    // A NAK to a frame (this responder has no D8000 table) is resent in the open
    // conversation, then reported as the PLC refusing; a bad sum check in a reply reopens the
    // conversation with ENQ before the resend.
    let e = read_one(d.as_mut(), "D8255").unwrap_err();
    assert_eq!(e.kind, ErrorKind::Refused, "{e}");
    let cmds: Vec<String> = r.seen().iter().map(|q| q.cmd.clone()).collect();
    assert_eq!(cmds[3..], ["0", "0", "0", "0"], "NAK: resent without a new ENQ");
    drop(d);
    // The never-answering responder: exactly one ENQ however many requests follow.
    let r = fx_responder(false, EnqMode::Never);
    let mut d = open(&r.url("fx", "?model=FX2N"));
    for _ in 0..3 {
        assert_eq!(read_one(d.as_mut(), "D1000").unwrap(), 1000);
    }
    let cmds: Vec<String> = r.seen().iter().map(|q| q.cmd.clone()).collect();
    assert_eq!(cmds, ["ENQ", "0", "0", "0"]);
}

/// The user guide's FX examples (docs/fx.md), run as written (the served one against this test's own ptys in
/// place of /tmp/fx and /tmp/fxlink): every command succeeds.
#[test]
fn the_readme_fx_examples_run() {
    let section = std::fs::read_to_string(concat!(env!("CARGO_MANIFEST_DIR"), "/docs/fx.md")).unwrap();
    let lines: Vec<String> = section
        .split("```sh")
        .skip(1)
        .flat_map(|b| b.split("```").next().unwrap().lines().map(str::to_string).collect::<Vec<_>>())
        .filter(|l| l.starts_with("plcsh -d"))
        .collect();
    assert!(lines.len() >= 4, "{lines:?}");
    let srv = Server::start("readme", &[]);
    let mut outputs = String::new();
    for line in &lines {
        let line =
            line.replace("/tmp/fxlink", srv.link.to_str().unwrap()).replace("/tmp/fx", srv.port.to_str().unwrap());
        let words = words::split(&line);
        let mut args: Vec<&str> = vec!["--json"];
        args.extend(words[1..].iter().map(String::as_str));
        let out = run(&args, "");
        assert!(out.status.success(), "{line}: {}", String::from_utf8_lossy(&out.stderr));
        for l in json_lines(&out) {
            assert_eq!(l["ok"], true, "{line}: {l}");
        }
        outputs.push_str(&String::from_utf8_lossy(&out.stdout));
    }
    // The FX3U example reaches its own ranges, and `help` shows the E-command address.
    assert!(outputs.contains("47D0H") && outputs.contains("E00/E10/E7/E8"), "{outputs}");
}
