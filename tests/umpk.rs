//! UMPK teaching PLCs end to end: the simulator served by the real binary on a REAL
//! pseudo-terminal (`plcsh sim serve --umpk-pty`, readiness line awaited, never a sleep
//! before talking), reached by a raw byte client that types what a terminal program would,
//! by plcsh's `umpk:` driver, by the shell, and by socat as a person's terminal.
// Unix only: real pseudo-terminals (Windows has none; its COM ports are tested under Wine
// in tests/windows_serial.rs).
#![cfg(unix)]

mod common;
use common::*;
use plcsh::core::{Clock, Device, ErrorKind};
use plcsh::session::open_url;
use plcsh::umpk::codec::{Monitor, Reply, MONITOR_LEN};
use plcsh::umpk::driver::Driver;
use plcsh::umpk::hex::Record;
use std::fs::File;
use std::io::{Read, Write};
use std::os::fd::AsFd;
use std::path::PathBuf;
use std::time::{Duration, Instant};

/// A served UMPK on a pty symlinked in a private directory.
struct Server {
    served: Served,
    link: PathBuf,
    dir: PathBuf,
}

impl Server {
    fn start(tag: &str, extra: &[&str]) -> Server {
        let dir = std::env::temp_dir().join(format!("plcsh-umpk-{}-{tag}", std::process::id()));
        std::fs::create_dir_all(&dir).unwrap();
        let link = dir.join("ttyUMPK");
        let mut args = vec!["--umpk-pty", link.to_str().unwrap()];
        args.extend_from_slice(extra);
        let served = serve(&args);
        assert!(served.ready["umpk_pty"]["path"].as_str().unwrap().starts_with("/dev/pts/"), "{}", served.ready);
        Server { served, link, dir }
    }
}

/// A raw serial client: what a terminal program or a lab's own software does.
struct Raw(File);

impl Raw {
    fn open(link: &PathBuf) -> Raw {
        Raw(std::fs::OpenOptions::new().read(true).write(true).open(link).unwrap())
    }

    fn send(&mut self, b: &[u8]) {
        self.0.write_all(b).unwrap();
    }

    /// Reads until `done(bytes)` or `limit` passes.
    fn read_until(&mut self, limit: Duration, done: impl Fn(&[u8]) -> bool) -> Vec<u8> {
        use nix::poll::{poll, PollFd, PollFlags, PollTimeout};
        let end = Instant::now() + limit;
        let mut got = Vec::new();
        let mut buf = [0u8; 4096];
        while !done(&got) {
            let left = end.saturating_duration_since(Instant::now());
            if left.is_zero() {
                break;
            }
            let mut fds = [PollFd::new(self.0.as_fd(), PollFlags::POLLIN)];
            let ms = PollTimeout::try_from(left.as_millis().min(1000) as i32).unwrap();
            if poll(&mut fds, ms).unwrap_or(0) > 0 {
                let n = self.0.read(&mut buf).unwrap();
                got.extend_from_slice(&buf[..n]);
            }
        }
        got
    }

    /// Sends a command and reads up to the reply's end (CR LF with echo, else `ends`).
    fn ask(&mut self, cmd: &str, ends: usize) -> String {
        self.send(cmd.as_bytes());
        let got = self.read_until(Duration::from_secs(20), |g| g.ends_with(b"\r\n") || g.len() >= ends);
        String::from_utf8_lossy(&got).into_owned()
    }

    /// Waits for `ms` of silence and returns what came meanwhile.
    fn quiet(&mut self, ms: u64) -> Vec<u8> {
        let mut all = Vec::new();
        loop {
            let got = self.read_until(Duration::from_millis(ms), |g| !g.is_empty());
            if got.is_empty() {
                return all;
            }
            all.extend(got);
        }
    }
}

fn open(url: &str) -> Box<dyn Device> {
    open_url(url, &Clock::following()).unwrap_or_else(|e| panic!("{url}: {e}"))
}

fn drv(d: &mut Box<dyn Device>) -> &mut Driver {
    plcsh::umpk::ops(d.as_mut(), &[]).unwrap().unwrap()
}

#[test]
fn echo_on_and_off_and_every_command_in_each_mode() {
    let srv = Server::start("modes", &["--umpk-model", "UMPK8"]);
    let mut t = Raw::open(&srv.link);
    // Echo on: every byte back, the reply, CR LF. UMPK8 in Wait: status 00.
    assert_eq!(t.ask("?03FD", 99), "?03FD#06082908040001BC\r\n");
    // Wait mode (Table 6, «Раб»/«Ожид» column): every command answers.
    assert_eq!(t.ask("?04FC", 99), format!("?04FC#{}\r\n", " ".repeat(22)));
    assert_eq!(t.ask("?05FB", 99), "?05FB#0400000000FC\r\n");
    assert_eq!(t.ask("?06FA", 99), "?06FA#0400000000FC\r\n");
    assert_eq!(t.ask("?07F9", 99), "?07F9#080000000000000000F8\r\n");
    assert_eq!(t.ask("?08F8", 99), "?08F8R\r\n");
    assert_eq!(t.ask("?0CF4", 99), "?0CF4#0403E803E826\r\n");
    t.send(b"?0AF6");
    let got = t.read_until(Duration::from_secs(20), |g| g.len() >= 8);
    assert!(got.starts_with(b"?0AF6R\r\n"), "{got:?}");
    t.send(b"?0BF5");
    let got = t.read_until(Duration::from_secs(20), |g| g.ends_with(b"?0BF5R\r\n"));
    assert!(got.ends_with(b"?0BF5R\r\n"), "{got:?}");
    assert_eq!(t.ask("?0DF3", 99), "?0DF3U\r\n");
    assert_eq!(t.ask("?03FC", 99), "?03FCE\r\n");
    assert_eq!(t.ask("?0X00", 99), "?0X00C\r\n");
    // Echo off: neither echo nor CR LF; the E bit shows in the status word.
    assert_eq!(t.ask("?02FE", 6), "?02FER");
    assert_eq!(t.ask("?03FD", 17), "#06082908040401B8");
    assert_eq!(t.ask("?05FB", 13), "#0400000000FC");
    // Programming mode: reset, echo and info answer; the rest gets U.
    assert_eq!(t.ask("?09F7", 1), "R");
    for c in ["?04FC", "?05FB", "?06FA", "?07F9", "?08F8", "?09F7", "?0AF6", "?0BF5", "?0CF4"] {
        assert_eq!(t.ask(c, 1), "U", "{c} in Programming mode");
    }
    assert_eq!(t.ask("?03FD", 17), "#06082908040601B6", "P and E bits");
    // Reset: silent while restarting, then R CR LF with echo on, back to Wait.
    t.send(b"?0000");
    let got = t.read_until(Duration::from_secs(20), |g| g.ends_with(b"R\r\n"));
    assert_eq!(got, b"R\r\n");
    assert_eq!(t.ask("?03FD", 99), "?03FD#06082908040001BC\r\n");
    // Work mode: program a page by hand (as a terminal would), reset, and ask again.
    assert_eq!(t.ask("?09F7", 99), "?09F7R\r\n");
    for r in [Record::start(), Record::info(b"BY HAND"), Record::data(0, &[0x55; 64]), Record::end()] {
        let text = String::from_utf8(r.encode()).unwrap();
        assert_eq!(t.ask(&text, 999), format!("{text}R\r\n"));
    }
    t.send(b"?0000");
    let got = t.read_until(Duration::from_secs(20), |g| g.ends_with(b"R\r\n"));
    assert_eq!(got, b"?0000R\r\n", "echoed, then R after the restart");
    // W (bit 5) set; every command answers in Work mode.
    assert_eq!(t.ask("?03FD", 99), "?03FD#06082908042001 9C\r\n".replace(' ', ""));
    assert_eq!(t.ask("?04FC", 99), format!("?04FC#BY HAND{}\r\n", " ".repeat(15)));
    assert_eq!(t.ask("?05FB", 99), "?05FB#0400000000FC\r\n");
    assert_eq!(t.ask("?06FA", 99), "?06FA#0400000000FC\r\n", "the stored binary is not executed: outputs off");
    assert_eq!(t.ask("?07F9", 99), "?07F9#080000000000000000F8\r\n");
    assert_eq!(t.ask("?08F8", 99), "?08F8R\r\n");
    assert_eq!(t.ask("?0CF4", 99), "?0CF4#0403E803E826\r\n");
    t.send(b"?0AF6");
    let got = t.read_until(Duration::from_secs(20), |g| g.len() >= 8);
    assert!(got.starts_with(b"?0AF6R\r\n"), "{got:?}");
    let more = t.read_until(Duration::from_secs(20), |g| g.len() + got.len() >= 8 + MONITOR_LEN);
    let first = [&got[8..], &more[..]].concat();
    t.send(b"?0BF5");
    let got = t.read_until(Duration::from_secs(20), |g| g.ends_with(b"?0BF5R\r\n"));
    assert!(got.ends_with(b"?0BF5R\r\n"));
    let packet = Monitor::decode(&first[..MONITOR_LEN]).expect("a monitor packet");
    assert_ne!(packet.status & (1 << 5), 0, "W in the monitor's status word");
    assert_eq!(t.ask("?01FF", 99), "?01FFR\r\n");
    let _ = std::fs::remove_dir_all(&srv.dir);
}

#[test]
fn monitor_stream_rate_and_any_command_stops_it() {
    let srv = Server::start("monitor", &[]);
    let mut t = Raw::open(&srv.link);
    assert_eq!(t.ask("?02FE", 6), "?02FER");
    // `R`, then the stream; on a loaded machine the first packet may come in the same read.
    t.send(b"?0AF6");
    let first = t.read_until(Duration::from_secs(20), |g| !g.is_empty());
    assert_eq!(first.first(), Some(&b'R'), "{first:02X?}");
    // One second of wall time (the served simulator follows it): 100 packets, one per cycle.
    let start = Instant::now();
    let got = [&first[1..], &t.read_until(Duration::from_millis(1000), |_| false)[..]].concat();
    let secs = start.elapsed().as_secs_f64();
    let packets = got.len() / MONITOR_LEN;
    let rate = packets as f64 / secs;
    assert!((85.0..=110.0).contains(&rate), "{packets} packets in {secs:.3} s");
    let mut decoded = 0;
    for p in got.chunks_exact(MONITOR_LEN) {
        let m = Monitor::decode(p).unwrap_or_else(|| panic!("bad packet {p:02X?}"));
        assert_ne!(m.status & (1 << 3), 0, "R (monitor on) bit");
        decoded += 1;
    }
    assert_eq!(decoded, packets);
    // Any command stops it: after `?03FD` only whole packets already sent, then the reply.
    t.send(b"?03FD");
    // Waits for the reply itself (a loaded machine may deliver the packets sent before it
    // slowly), never for a pause in the stream.
    let reply = b"#06102910080401A4";
    let after = t.read_until(Duration::from_secs(20), |g| g.ends_with(reply));
    let all = [got, after].concat();
    assert!(all.ends_with(reply), "no reply to ?03FD: {:02X?}", &all[all.len().saturating_sub(64)..]);
    let pos = all.len() - 17;
    assert_eq!(&all[pos..], b"#06102910080401A4", "monitor off again, echo off");
    assert_eq!(pos % MONITOR_LEN, 0, "whole packets before the reply");
    assert!(all[..pos].chunks_exact(MONITOR_LEN).all(|p| Monitor::decode(p).is_some()));
    assert!(t.quiet(100).is_empty(), "nothing more: the stream stopped");
    let _ = std::fs::remove_dir_all(&srv.dir);
}

#[test]
fn a_command_before_the_reply_is_complete_is_error_255() {
    let srv = Server::start("overflow", &[]);
    let mut t = Raw::open(&srv.link);
    t.quiet(50);
    // Two commands in one write: the second arrives while the first reply is being sent.
    t.send(b"?03FD?07F9");
    let want = "?03FD#06102910080001A8\r\n?07F9";
    // Everything expected (however slowly a loaded machine delivers it), then nothing more.
    let mut got = t.read_until(Duration::from_secs(20), |g| g.len() >= want.len());
    got.extend(t.quiet(100));
    assert_eq!(String::from_utf8_lossy(&got), want, "the second reply was lost");
    assert_eq!(t.ask("?07F9", 99), "?07F9#08FF00000000000000F9\r\n");
    // plcsh's driver reads the history and explains 255; it never causes one itself.
    drop(t);
    let mut d = open(&format!("umpk:{}", srv.link.display()));
    let u = drv(&mut d);
    for _ in 0..20 {
        u.controller_info().unwrap();
    }
    let e = u.errors().unwrap();
    assert_eq!(e[0], 255, "{e:?}");
    assert_eq!(e[1], 0, "no new overflow from twenty back-to-back driver commands");
    assert!(plcsh::umpk::codec::error_code_text(e[0]).contains("before the previous reply was complete"));
    u.clear_errors().unwrap();
    assert_eq!(u.errors().unwrap(), [0; 8]);
    let _ = std::fs::remove_dir_all(&srv.dir);
}

fn hex_file(dir: &std::path::Path, name: &str, records: &[Record]) -> PathBuf {
    let mut text = String::new();
    for r in records {
        text.push_str(&String::from_utf8(r.encode()).unwrap());
        text.push_str("\r\n");
    }
    let p = dir.join(name);
    std::fs::write(&p, text).unwrap();
    p
}

#[test]
fn hex_programming_end_to_end_through_the_shell_and_each_error_letter() {
    let srv = Server::start("program", &["--umpk-flash-fail", "40"]);
    // A 200-byte program in 16-byte lines, with program info in the file.
    let mut recs = vec![Record::info(b"file info")];
    for a in (0..200u16).step_by(16) {
        let n = (200 - a).min(16) as usize;
        recs.push(Record::data(a, &vec![a as u8; n]));
    }
    recs.push(Record::end());
    let file = hex_file(&srv.dir, "lab.hex", &recs);
    let url = format!("lab=umpk:{}", srv.link.display());
    let script = format!("use lab\numpk program {} info=\"LAB 1\" run\numpk program-info\numpk info\n", file.display());
    let o = run(&["--json", "--device", &url], &script);
    let lines = json_lines(&o);
    assert!(o.status.success(), "{}\n{}", stdout(&o), String::from_utf8_lossy(&o.stderr));
    assert_eq!(lines[1]["pages"], 4, "{}", lines[1]);
    assert_eq!(lines[1]["records"], 7, "start, info, 4 pages, end");
    assert_eq!(lines[1]["bytes"], 200);
    assert_eq!(lines[2]["program_info"], format!("LAB 1{}", " ".repeat(17)));
    assert_eq!(lines[3]["mode"], "Work");
    // A file that does not fit is refused before anything is sent.
    let big = hex_file(&srv.dir, "big.hex", &[Record::data(0x0C00, &[1]), Record::end()]);
    let o = run(&["--json", "--device", &url], &format!("use lab\numpk program {}\n", big.display()));
    let err = &json_lines(&o)[1];
    assert_eq!(err["ok"], false);
    assert!(err["error"]["message"].as_str().unwrap().contains("outside the program memory"), "{err}");

    // Each letter, provoked over the pty and reported in words.
    let mut d = open(&format!("umpk:{}", srv.link.display()));
    let u = drv(&mut d);
    let letter = |u: &mut Driver, raw: &str| -> u8 {
        match u.send_raw(raw).unwrap().reply {
            Reply::Letter(l) => l,
            Reply::Ok => b'R',
            r => panic!("{raw}: {r:?}"),
        }
    };
    assert_eq!(letter(u, ":00000002FE"), b'X', "not in Programming mode");
    u.send_raw("?09F7").unwrap();
    assert_eq!(letter(u, ":0100000000FF"), b'X', "no start record yet");
    for (raw, want) in [(":00000002FD", b'E'), (":020000040000FA", b'U'), (":0100000Z00FF", b'C')] {
        assert_eq!(letter(u, ":00000002FE"), b'R');
        assert_eq!(letter(u, raw), want, "{raw}");
    }
    assert_eq!(letter(u, ":00000002FE"), b'R');
    assert_eq!(letter(u, &String::from_utf8(Record::data(0, &[0; 65]).encode()).unwrap()), b'L');
    assert_eq!(letter(u, ":00000002FE"), b'R');
    assert_eq!(letter(u, &String::from_utf8(Record::data(0x40, &[0; 64]).encode()).unwrap()), b'R');
    assert_eq!(letter(u, &String::from_utf8(Record::data(0x00, &[0; 64]).encode()).unwrap()), b'A');
    // W: page 40 is made to fail by the server (--umpk-flash-fail 40): a file reaching it.
    let p = plcsh::umpk::hex::parse_file(
        &std::fs::read_to_string(hex_file(&srv.dir, "w.hex", &[Record::data(0x0A00, &[7; 64]), Record::end()]))
            .unwrap(),
        3072,
    )
    .unwrap();
    let e = u.program(&p, None, &mut |_, _| {}).unwrap_err();
    assert_eq!(e.kind, ErrorKind::Refused);
    assert!(e.message.contains("W: the flash (IAP) write failed") && e.message.contains("16#0A00..16#0A3F"), "{e}");
    assert!(e.hint.as_deref().unwrap().contains("again from the start"), "{e:?}");
    assert_eq!(letter(u, ":00000001FF"), b'X', "the aborted sequence allows nothing until a new start");
    // The failed sequence erased the program: reset leaves Programming mode to Wait.
    u.reset().unwrap();
    let word = u.controller_info().unwrap().status;
    let st = u.layout.decode(word);
    assert!(!st.work && !st.programming, "{st:?}");
    let _ = std::fs::remove_dir_all(&srv.dir);
}

#[test]
fn a_persons_terminal_typing_by_hand() {
    if std::process::Command::new("socat").arg("-V").output().map(|o| !o.status.success()).unwrap_or(true) {
        common::skipped("socat (apt-get install socat)");
        return;
    }
    let srv = Server::start("socat", &[]);
    // socat joins its stdin/stdout to the serial device like a terminal program does
    // (raw, no local echo: the PLC echoes); keys arrive one at a time, as typed.
    let mut child = std::process::Command::new("socat")
        .args(["-", &format!("FILE:{},raw,echo=0", srv.link.display())])
        .stdin(std::process::Stdio::piped())
        .stdout(std::process::Stdio::piped())
        .spawn()
        .unwrap();
    let mut keys = child.stdin.take().unwrap();
    let mut out = child.stdout.take().unwrap();
    let (tx, rx) = std::sync::mpsc::channel();
    std::thread::spawn(move || {
        let mut b = [0u8; 64];
        while let Ok(n) = out.read(&mut b) {
            if n == 0 || tx.send(b[..n].to_vec()).is_err() {
                break;
            }
        }
    });
    for k in "?03FD".bytes() {
        keys.write_all(&[k]).unwrap();
        keys.flush().unwrap();
        std::thread::sleep(Duration::from_millis(40)); // a person's typing pace
    }
    let mut seen = Vec::new();
    let end = Instant::now() + Duration::from_secs(20);
    while !seen.ends_with(b"\r\n") && Instant::now() < end {
        if let Ok(b) = rx.recv_timeout(Duration::from_millis(100)) {
            seen.extend(b);
        }
    }
    let _ = child.kill();
    let _ = child.wait();
    assert_eq!(String::from_utf8_lossy(&seen), "?03FD#06102910080001A8\r\n");
    let _ = std::fs::remove_dir_all(&srv.dir);
}

#[test]
fn shell_monitor_as_json_lines_and_as_a_trace_for_plot() {
    let dir = std::env::temp_dir().join(format!("plcsh-umpk-{}-plot", std::process::id()));
    std::fs::create_dir_all(&dir).unwrap();
    let svg = dir.join("i2.svg");
    let script = format!(
        "use lab\nsim input I2 freq=25Hz\numpk monitor I2 Q0 count=4\nplot I2 to={}\nsim input I2 off\numpk errors\n",
        svg.display()
    );
    let o = run(&["--json", "--time", "stepped", "--device", "lab=sim-umpk:UMPK16"], &script);
    assert!(o.status.success(), "{}", stdout(&o));
    let lines = json_lines(&o);
    let samples: Vec<&serde_json::Value> = lines.iter().filter(|l| l.get("sample").is_some()).collect();
    assert_eq!(samples.len(), 4, "{lines:?}");
    // 25 Hz: 20 ms on, 20 ms off, one packet per 10 ms cycle.
    let i2: Vec<bool> = samples.iter().map(|s| s["values"][0]["value"].as_bool().unwrap()).collect();
    assert_eq!(i2, [true, true, false, false]);
    assert_eq!(samples[3]["t_us"], 30_000);
    let done = lines.iter().find(|l| l.get("packets").is_some()).unwrap();
    assert_eq!(done["packets"], 4);
    assert!(std::fs::read_to_string(&svg).unwrap().contains("<svg"), "plot drew the monitor trace");
    let _ = std::fs::remove_dir_all(&dir);
}

#[test]
fn an_acknowledged_program_survives_kill_9() {
    let dir = std::env::temp_dir().join(format!("plcsh-umpk-{}-durable", std::process::id()));
    std::fs::create_dir_all(&dir).unwrap();
    let state = dir.join("umpk16.json");
    let _ = std::fs::remove_file(&state);
    let file = hex_file(&dir, "p.hex", &[Record::info(b"kept"), Record::data(0, &[0x42; 64]), Record::end()]);
    let p = plcsh::umpk::hex::parse_file(&std::fs::read_to_string(&file).unwrap(), 3072).unwrap();
    let srv = Server::start("durable", &["--umpk-state", state.to_str().unwrap()]);
    {
        let mut d = open(&format!("umpk:{}", srv.link.display()));
        drv(&mut d).program(&p, None, &mut |_, _| {}).unwrap();
    }
    // Power loss right after the last acknowledgement: SIGKILL, no chance to save on exit.
    let pid = nix::unistd::Pid::from_raw(srv.served.child.id() as i32);
    nix::sys::signal::kill(pid, nix::sys::signal::Signal::SIGKILL).unwrap();
    drop(srv);
    let srv = Server::start("durable2", &["--umpk-state", state.to_str().unwrap()]);
    let mut d = open(&format!("umpk:{}", srv.link.display()));
    let u = drv(&mut d);
    let word = u.controller_info().unwrap().status;
    assert!(u.layout.decode(word).work, "powered up in Work: the program was kept");
    assert_eq!(&u.program_info().unwrap()[..4], b"kept");
    let _ = std::fs::remove_dir_all(&dir);
}

#[test]
fn the_driver_opens_a_controller_whose_monitor_someone_else_left_running() {
    let srv = Server::start("stream", &[]);
    {
        let mut t = Raw::open(&srv.link);
        t.send(b"?0AF6");
        let got = t.read_until(Duration::from_secs(20), |g| g.len() >= 8 + 3 * MONITOR_LEN);
        assert!(got.starts_with(b"?0AF6R\r\n"), "{got:?}");
        // The lab program exits with the stream still running.
    }
    std::thread::sleep(Duration::from_millis(30)); // the stream goes on into the port meanwhile
    let mut d = open(&format!("umpk:{}", srv.link.display()));
    let u = drv(&mut d);
    let word = u.controller_info().unwrap().status;
    assert!(!u.layout.decode(word).monitor, "opening stopped the stream");
    assert_eq!(u.errors().unwrap(), [0; 8], "without an overflow");
    let _ = std::fs::remove_dir_all(&srv.dir);
}

#[test]
fn each_refusal_letter_in_words_through_the_shell() {
    let srv = Server::start("words", &["--umpk-flash-fail", "0"]);
    let page = |a: u16, n: usize| String::from_utf8(Record::data(a, &vec![1; n]).encode()).unwrap();
    let cases: Vec<(String, &str)> = vec![
        (":00000002FE".into(), "X: programming is not allowed"),
        ("?09F7".into(), "ok"),
        (":00000002FD".into(), "E: checksum error"),
        (":00000002FE".into(), "ok"),
        (":020000040000FA".into(), "U: unknown command"),
        (":00000002FE".into(), "ok"),
        (":0100000Z00FF".into(), "C: the command contains an illegal character"),
        (":00000002FE".into(), "ok"),
        (page(0x40, 65), "L: the record's data is longer than allowed"),
        (":00000002FE".into(), "ok"),
        (page(0x0C00, 64), "A: address out of sequence or out of range"),
        (":00000002FE".into(), "ok"),
        (page(0, 64), "W: the flash (IAP) write failed"),
        (":00000001FF".into(), "X: programming is not allowed"),
        ("?05FB".into(), "U"),
    ];
    let script: String =
        std::iter::once("use lab\n".to_string()).chain(cases.iter().map(|(c, _)| format!("umpk send {c}\n"))).collect();
    let o = run(&["--json", "--device", &format!("lab=umpk:{}", srv.link.display())], &script);
    let lines = json_lines(&o);
    for (k, (c, want)) in cases.iter().enumerate().take(cases.len() - 1) {
        let m = lines[k + 1]["meaning"].as_str().unwrap_or_else(|| panic!("{c}: {}", lines[k + 1]));
        assert!(m.starts_with(want), "{c}: {m}");
    }
    // In Programming mode a terminal command other than the four gets U, in words too.
    assert!(lines[cases.len()]["meaning"].as_str().unwrap().starts_with("U: unknown command"));
    let _ = std::fs::remove_dir_all(&srv.dir);
}

#[test]
fn the_lab_grading_script_fails_a_program_that_misses_a_criterion() {
    let src = std::path::Path::new(env!("CARGO_MANIFEST_DIR")).join("scripts/umpk_lab1_grade.lua");
    let code = std::fs::read_to_string(&src).unwrap();
    let dir = std::env::temp_dir().join(format!("plcsh-umpk-{}-grade", std::process::id()));
    std::fs::create_dir_all(&dir).unwrap();
    // The same script expecting a 1.5 s delay: the 2.0 s reference must fail that criterion.
    let changed = dir.join("grade.lua");
    std::fs::write(&changed, code.replace("delay == 2000", "delay == 1500")).unwrap();
    let o = run(&["--time", "stepped", "run", changed.to_str().unwrap()], "");
    let out = stdout(&o);
    assert_eq!(o.status.code(), Some(1), "{out}");
    assert!(out.contains("FAIL  Q1 follows Q0 after 2.0 s (T0)  (2000 ms)"), "{out}");
    assert!(out.contains("lab 1: 11 of 12 criteria"), "{out}");
    let _ = std::fs::remove_dir_all(&dir);
}

/// A student's IL program with one mistake each: the grading script fails exactly the
/// criterion the mistake breaks; the built-in reference passes it.
#[test]
fn the_lab_grading_script_grades_il_programs_and_fails_a_wrong_one() {
    let root = std::path::Path::new(env!("CARGO_MANIFEST_DIR"));
    let good = std::fs::read_to_string(root.join("scripts/umpk_lab1.il")).unwrap();
    let dir = std::env::temp_dir().join(format!("plcsh-umpk-{}-grade-il", std::process::id()));
    std::fs::create_dir_all(&dir).unwrap();
    let grade = |arg: &str| run(&["--time", "stepped", "run", "scripts/umpk_lab1_grade.lua", arg], "");
    for (name, from, to, fails) in [
        ("noreset.il", "DIVIDE  C0, 4, I1", "DIVIDE  C0, 4", "FAIL  stop reset the counter  (5)"),
        ("short.il", "TIMER   T0, 1, 20", "TIMER   T0, 1, 15", "FAIL  Q1 follows Q0 after 2.0 s (T0)  (1500 ms)"),
        (
            "ratio3.il",
            "DIVIDE  C0, 4, I1",
            "DIVIDE  C0, 3, I1",
            "FAIL  Q2 passes the 4th and the 8th input pulse  (3, 6)",
        ),
        ("nolatch.il", "OR      Q0\n", "", "FAIL  Q0 latches after the button is released"),
    ] {
        assert!(good.contains(from), "{from}");
        let f = dir.join(name);
        std::fs::write(&f, good.replacen(from, to, 1)).unwrap();
        let o = grade(f.to_str().unwrap());
        let out = stdout(&o);
        assert_eq!(o.status.code(), Some(1), "{name}:\n{out}");
        assert!(out.contains(fails), "{name}:\n{out}");
        assert!(out.contains(&format!("grading IL {name}")), "{out}");
    }
    // The same delay in group 0 (200 × 10 ms) is a correct solution.
    let f = dir.join("group0.il");
    std::fs::write(&f, good.replacen("TIMER   T0, 1, 20", "TIMER   T0, 0, 200", 1)).unwrap();
    let o = grade(f.to_str().unwrap());
    assert!(o.status.success() && stdout(&o).contains("lab 1: 12 of 12 criteria"), "{}", stdout(&o));
    let o = grade("reference");
    assert!(o.status.success() && stdout(&o).contains("grading lab1 (reference)"), "{}", stdout(&o));
    let _ = std::fs::remove_dir_all(&dir);
}

#[test]
fn sim_program_load_runs_il_on_a_simulated_umpk_and_refuses_bad_programs() {
    let dir = std::env::temp_dir().join(format!("plcsh-umpk-{}-simprog", std::process::id()));
    std::fs::create_dir_all(&dir).unwrap();
    let bad = dir.join("bad.il");
    std::fs::write(&bad, "LD I0\nTIMER T0, 3, 20\nST Q1\n").unwrap();
    let script = format!(
        "use lab\nsim program\nsim program load {}\nsim program load scripts/umpk_lab1.il\nsim input I0=1\nsim step 1990ms\nget Q1\nsim step 10ms\nget Q0 Q1 M0\numpk timing\n",
        bad.display()
    );
    let o = run(&["--json", "--time", "stepped", "--device", "lab=sim-umpk:UMPK16"], &script);
    let l = json_lines(&o);
    assert_eq!(l[1]["program"], "none", "{}", l[1]);
    assert_eq!(l[1]["mode"], "Wait");
    let err = l[2]["error"]["message"].as_str().unwrap_or_else(|| panic!("{}", l[2]));
    assert!(err.contains("bad.il:2:1") && err.contains("delay group is 0 (10 ms), 1 (0.1 s) or 2 (1 s)"), "{err}");
    assert_eq!(l[2]["error"]["device"], "lab");
    let loaded = l.iter().find(|v| v["program"].as_str().is_some_and(|p| p.starts_with("IL umpk_lab1.il"))).unwrap();
    assert_eq!(loaded["mode"], "Work");
    let gets: Vec<&serde_json::Value> = l.iter().filter(|v| v["cmd"] == "get").collect();
    assert_eq!(gets[0]["values"][0]["value"], false, "T0 is still running at 1.99 s: {}", gets[0]);
    let vals: Vec<bool> = gets[1]["values"].as_array().unwrap().iter().map(|v| v["value"] == true).collect();
    assert_eq!(vals, vec![true, true, true], "at 2.0 s: {}", gets[1]);
    // The program's time (from the cost table) is in the timing figures: 10 bit
    // instructions × 2 µs + 2 UMPK instructions × 10 µs = 40 µs = 147 counts of 0.271 µs.
    let t = l.iter().find(|v| v["cmd"] == "umpk" && v.get("program_us").is_some()).expect("timing");
    assert_eq!(t["total_counts"].as_u64().unwrap() - t["firmware_counts"].as_u64().unwrap(), 147, "{t}");
    // The URL form loads the same program at open.
    let o = run(
        &["--json", "--time", "stepped", "--device", "lab=sim-umpk:UMPK16?program=scripts/umpk_lab1.il"],
        "use lab\nsim program\n",
    );
    assert!(json_lines(&o)[1]["program"].as_str().unwrap().starts_with("IL umpk_lab1.il"), "{}", stdout(&o));
    let _ = std::fs::remove_dir_all(&dir);
}

#[test]
fn a_served_umpk_runs_an_il_program_given_at_start_and_refuses_a_bad_one() {
    let lab1 = std::path::Path::new(env!("CARGO_MANIFEST_DIR")).join("scripts/umpk_lab1.il");
    let srv = Server::start("il", &["--umpk-state", "none", "--umpk-program", lab1.to_str().unwrap()]);
    assert_eq!(srv.served.ready["umpk_mode"], "Work", "{}", srv.served.ready);
    {
        let mut d = open(&format!("umpk:{}", srv.link.display()));
        let info = drv(&mut d).program_info().unwrap();
        assert!(String::from_utf8_lossy(&info).starts_with("IL umpk_lab1.il"), "{:?}", String::from_utf8_lossy(&info));
    }
    let bad = srv.dir.join("bad.il");
    std::fs::write(&bad, "LD I0\nDIVIDE C0, 0\nST Q2\n").unwrap();
    let link = srv.dir.join("ttyBad");
    let o = run(
        &[
            "sim",
            "serve",
            "--umpk-pty",
            link.to_str().unwrap(),
            "--umpk-state",
            "none",
            "--umpk-program",
            bad.to_str().unwrap(),
        ],
        "",
    );
    assert!(!o.status.success());
    let out = common::both(&o);
    assert!(out.contains("bad.il:2:1") && out.contains("the division ratio is 1–255"), "{out}");
    let _ = std::fs::remove_dir_all(&srv.dir);
}

#[test]
fn a_served_umpk_keeps_its_program_by_default_unless_told_none() {
    let p = plcsh::umpk::hex::parse_file(":0100000042BD\n:00000001FF\n", 3072).unwrap();
    let srv = Server::start("default-state", &[]);
    let state = std::path::PathBuf::from(srv.served.ready["umpk_state"].as_str().unwrap());
    assert!(state.starts_with(std::env::temp_dir()), "inside the test's private HOME: {}", state.display());
    {
        let mut d = open(&format!("umpk:{}", srv.link.display()));
        drv(&mut d).program(&p, Some(b"again"), &mut |_, _| {}).unwrap();
    }
    drop(srv);
    let srv = Server::start("default-state", &[]);
    assert_eq!(srv.served.ready["umpk_mode"], "Work", "the same link powers up with its program");
    drop(srv);
    let srv = Server::start("default-state", &["--umpk-state", "none"]);
    assert_eq!(srv.served.ready["umpk_mode"], "Wait");
    assert!(srv.served.ready["umpk_state"].is_null());
    let _ = std::fs::remove_file(&state);
    let _ = std::fs::remove_dir_all(&srv.dir);
}

#[test]
fn lua_connects_to_a_served_umpk_and_calls_each_method() {
    let srv = Server::start("lua", &["--umpk-state", "none"]);
    let hex = hex_file(&srv.dir, "l.hex", &[Record::data(0, &[1; 40]), Record::end()]);
    let script = srv.dir.join("t.lua");
    std::fs::write(
        &script,
        format!(
            r#"
local lab = plcsh.connect("umpk:{link}", "lab")
plcsh.assert_eq(lab:umpk_info().mode, "Wait")
plcsh.assert_eq(lab:umpk_program_info().program_info, string.rep(" ", 22))
plcsh.assert_eq(lab:umpk_errors().codes, {{}})
lab:umpk_clear_errors()
plcsh.assert_near(lab:umpk_timing().firmware_us, 271.0, 1e-6)
plcsh.assert_eq(lab:umpk_echo("off").echo, false)
plcsh.assert_eq(lab:umpk_send("?03FD").echoed, false)
local m = lab:umpk_monitor("I0", "Q0", {{count = 5}})
plcsh.assert_eq({{m.samples, #m.columns.I0}}, {{5, 5}})
local p = lab:umpk_program("{hex}", {{info = "FROM LUA", run = true}})
plcsh.assert_eq({{p.pages, p.bytes, p.run}}, {{1, 40, true}})
plcsh.assert_eq(lab:umpk_info().mode, "Work")
plcsh.assert_eq(lab:umpk_program_info().program_info, "FROM LUA" .. string.rep(" ", 14))
lab:umpk_reset()
local ok, err = pcall(function() return lab:umpk_sim_input("I3=1") end)
plcsh.check(not ok and tostring(err):find("works on a simulated UMPK"), "a real port has no simulated inputs", tostring(err))
print("lua ok")
"#,
            link = srv.link.display(),
            hex = hex.display()
        ),
    )
    .unwrap();
    let o = run(&["run", script.to_str().unwrap()], "");
    assert!(o.status.success(), "{}\n{}", stdout(&o), String::from_utf8_lossy(&o.stderr));
    assert!(stdout(&o).contains("lua ok"));
    let _ = std::fs::remove_dir_all(&srv.dir);
}

/// The lab's own PC software on the served line sees what the control channel switches:
/// inputs, a stuck input, a silent line (`LINK.ctl`, the same words as `umpk sim …`).
#[test]
fn the_control_channel_switches_what_the_lab_software_reads_on_the_served_line() {
    let srv = Server::start("control", &["--umpk-state", "none"]);
    let ctl = format!("{}.ctl", srv.link.display());
    assert_eq!(srv.served.ready["umpk_control"], ctl.as_str());
    let control = |words: &str| {
        let mut args = vec!["--json", "sim", "control", ctl.as_str()];
        args.extend(words.split_whitespace());
        let o = run(&args, "");
        assert!(o.status.success(), "{words}: {}", both(&o));
        json_lines(&o).remove(0)
    };
    let mut t = Raw::open(&srv.link);
    assert_eq!(t.ask("?05FB", 99), "?05FB#0400000000FC\r\n");
    control("input I3=1");
    control("input I9=1");
    // Terminal command ?05FB (spec/umpk.md §3): `#04` + 4 bytes of inputs, I0–I7 first, + CC.
    assert_eq!(t.ask("?05FB", 99), "?05FB#0408020000F2\r\n");
    let f = control("fault stuck I3=0");
    assert_eq!(f["id"], 1);
    assert_eq!(t.ask("?05FB", 99), "?05FB#0400020000FA\r\n");
    // Until cleared (no `for=`): a window that could run out before the request arrives on a
    // loaded machine would let the line answer.
    control("fault no-reply");
    t.send(b"?05FB");
    assert!(t.read_until(Duration::from_millis(150), |g| !g.is_empty()).is_empty(), "a silent line answers nothing");
    let ev = control("events");
    assert_eq!(ev["events"].as_array().unwrap().len(), 2, "{ev}");
    assert_eq!(control("fault clear")["cleared"], 2);
    t.quiet(400);
    assert_eq!(t.ask("?05FB", 99), "?05FB#0408020000F2\r\n", "cleared: I3 follows its switch again");
    let o = run(&["sim", "control", ctl.as_str(), "input", "I16=1"], "");
    assert_eq!(o.status.code(), Some(2));
    assert!(stderr(&o).contains("I16 is not an input of the UMPK16 (I0…I15)"), "{}", stderr(&o));
    let _ = std::fs::remove_dir_all(&srv.dir);
}

#[test]
fn a_command_of_the_wrong_form_is_refused_before_it_is_sent_naming_the_right_one() {
    let srv = Server::start("form", &[]);
    let script = "use lab\numpk send ?3FD\numpk send hello\numpk send :0000002FE\numpk send ?03FD\n";
    let o = run(&["--json", "-v", "--device", &format!("lab=umpk:{}", srv.link.display())], script);
    let lines = json_lines(&o);
    let err = |k: usize| {
        let e = &lines[k]["error"];
        assert_eq!(e["kind"], "usage", "{}", lines[k]);
        let m = e["message"].as_str().unwrap().to_string();
        assert!(!m.contains("cable") && !m.contains("57600"), "not blamed on the line: {m}");
        m
    };
    let m = err(1);
    assert!(m.contains("`?3FD`") && m.contains("for controller info send ?03FD"), "{m}");
    let m = err(2);
    assert!(m.contains("`hello` is neither") && m.contains("?03FD"), "{m}");
    let m = err(3);
    assert!(m.contains("RECLEN 00 is 11") && m.contains(":00000002FE"), "{m}");
    assert_eq!(lines[4]["ok"], true, "the right form is answered: {}", lines[4]);
    // Nothing of the refused forms went on the line (the trace shows every frame sent).
    let trace = stderr(&o);
    assert!(trace.contains("3F 30 33 46 44"), "the trace shows ?03FD as sent:\n{trace}");
    for sent in ["3F 33 46 44", "68 65 6C 6C 6F", "3A 30 30 30 30 30 30 32 46 45"] {
        assert!(!trace.contains(sent), "{sent} was sent:\n{trace}");
    }
    let _ = std::fs::remove_dir_all(&srv.dir);
}

#[test]
fn a_served_program_that_overruns_the_cycle_shows_in_the_error_history_and_the_status() {
    let dir = std::env::temp_dir().join(format!("plcsh-umpk-{}-overrun-il", std::process::id()));
    std::fs::create_dir_all(&dir).unwrap();
    let il = dir.join("loop.il");
    std::fs::write(&il, "LD I0\nST Q0\nTOP:\nJMP TOP\n").unwrap();
    let srv = Server::start("overrun", &["--umpk-state", "none", "--umpk-program", il.to_str().unwrap()]);
    let url = format!("lab=umpk:{}", srv.link.display());
    // What a terminal sees: the history holds 254 and the status word says Wait with errors.
    let mut d = open(&format!("umpk:{}", srv.link.display()));
    let u = drv(&mut d);
    let deadline = Instant::now() + Duration::from_secs(20);
    while u.errors().unwrap()[0] != 254 {
        assert!(Instant::now() < deadline, "no error 254 in the history: {:?}", u.errors().unwrap());
        std::thread::sleep(Duration::from_millis(20));
    }
    let word = u.controller_info().unwrap().status;
    let st = u.layout.decode(word);
    assert!(!st.work && st.errors, "{st:?}");
    drop(d);
    let o = run(&["--device", &url], "use lab\numpk errors\numpk info\n");
    let out = stdout(&o);
    assert!(out.contains("254") && out.contains("overran the 10 ms cycle"), "{out}");
    assert!(out.contains("Wait"), "{out}");
    let _ = std::fs::remove_dir_all(&srv.dir);
    let _ = std::fs::remove_dir_all(&dir);
}

#[test]
fn an_il_program_raises_user_codes_that_umpk_errors_shows() {
    let dir = std::env::temp_dir().join(format!("plcsh-umpk-{}-user-error", std::process::id()));
    std::fs::create_dir_all(&dir).unwrap();
    let il = dir.join("err.il");
    std::fs::write(&il, "LD I7\nERROR 12\nLD I0\nST Q0\n").unwrap();
    let url = format!("lab=sim-umpk:UMPK16?program={}", il.display());
    let script = "use lab\nsim step 50ms\numpk errors\numpk sim input I7=1\nsim step 50ms\numpk errors\numpk info\n";
    let o = run(&["--json", "--time", "stepped", "--device", &url], script);
    let l = json_lines(&o);
    assert_eq!(l[2]["errors"], serde_json::json!([0, 0, 0, 0, 0, 0, 0, 0]), "{}", l[2]);
    assert_eq!(l[5]["errors"], serde_json::json!([12, 0, 0, 0, 0, 0, 0, 0]), "once, on the rising edge: {}", l[5]);
    assert_eq!(l[6]["mode"], "Work", "the program keeps running: {}", l[6]);
    assert_eq!(l[6]["status_bits"]["errors"], true);
    let o = run(&["--time", "stepped", "--device", &url], "use lab\numpk sim input I7=1\nsim step 50ms\numpk errors\n");
    assert!(stdout(&o).contains("user error 12"), "{}", stdout(&o));
    let _ = std::fs::remove_dir_all(&dir);
}

#[test]
fn programming_a_binary_into_the_simulator_says_it_is_stored_not_executed() {
    let dir = std::env::temp_dir().join(format!("plcsh-umpk-{}-binary-note", std::process::id()));
    std::fs::create_dir_all(&dir).unwrap();
    let file = hex_file(&dir, "p.hex", &[Record::data(0, &[0x42; 64]), Record::end()]);
    // In-process: the shell says so, in text and JSON, and names what the status shows.
    let script = format!("use lab\numpk program {} run\numpk info\n", file.display());
    let o = run(&["--json", "--device", "lab=sim-umpk:UMPK16"], &script);
    let l = json_lines(&o);
    assert_eq!(l[1]["executed"], false, "{}", l[1]);
    let note = l[1]["note"].as_str().unwrap();
    assert!(
        note.contains("does not execute") && note.contains("Work mode") && note.contains("outputs stay off"),
        "{note}"
    );
    assert_eq!(l[2]["mode"], "Work");
    let o = run(&["--device", "lab=sim-umpk:UMPK16"], &script);
    assert!(stdout(&o).contains("note: the simulator stores and verifies a programmed binary"), "{}", stdout(&o));
    // Served: the server says so on its standard error when the end record is accepted.
    let link = dir.join("ttyNote");
    let mut child = plcsh()
        .args(["sim", "serve", "--umpk-pty", link.to_str().unwrap(), "--umpk-state", "none"])
        .stdout(std::process::Stdio::piped())
        .stderr(std::process::Stdio::piped())
        .spawn()
        .unwrap();
    let mut ready = String::new();
    std::io::BufRead::read_line(&mut std::io::BufReader::new(child.stdout.take().unwrap()), &mut ready).unwrap();
    assert!(ready.contains("\"ready\":true"), "{ready}");
    let p = plcsh::umpk::hex::parse_file(&std::fs::read_to_string(&file).unwrap(), 3072).unwrap();
    {
        let mut d = open(&format!("umpk:{}", link.display()));
        drv(&mut d).program(&p, None, &mut |_, _| {}).unwrap();
    }
    let (tx, rx) = std::sync::mpsc::channel();
    let err = child.stderr.take().unwrap();
    std::thread::spawn(move || {
        for line in std::io::BufRead::lines(std::io::BufReader::new(err)).map_while(Result::ok) {
            let _ = tx.send(line);
        }
    });
    let line = rx.recv_timeout(Duration::from_secs(20)).expect("a note on the server's standard error");
    assert!(line.contains("a binary was programmed") && line.contains("does not execute"), "{line}");
    plcsh::core::platform::terminate_child(&child);
    let _ = child.wait();
    let _ = std::fs::remove_dir_all(&dir);
}

/// A failing flash page outside the model's program memory stops the server before it is
/// ready, naming the model's pages (Table 1 row 10), instead of serving a fault no write meets.
#[test]
fn a_flash_fail_page_past_the_program_memory_is_refused_before_serving() {
    let dir = std::env::temp_dir().join(format!("plcsh-umpk-{}-flashpage", std::process::id()));
    std::fs::create_dir_all(&dir).unwrap();
    let link = dir.join("ttyUMPK");
    for (model, page, pages) in [("UMPK8", "32", "pages 0–31"), ("UMPK16", "48", "pages 0–47")] {
        let o = plcsh()
            .args(["sim", "serve", "--umpk-pty", link.to_str().unwrap(), "--umpk-model", model])
            .args(["--umpk-flash-fail", page])
            .output()
            .unwrap();
        assert_eq!(o.status.code(), Some(2), "{model}: {}", both(&o));
        assert!(stderr(&o).contains(pages) && stderr(&o).contains(model), "{model}: {}", both(&o));
        assert!(!link.exists(), "nothing is served");
    }
}
