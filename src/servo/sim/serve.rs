//! Serving simulated drives on a byte stream — in practice a pseudo-terminal, so any serial
//! client (plcsh's `kinco:` driver, a terminal program, a PLC emulator) can open the slave
//! device like a real RS232 port (`plcsh sim serve --servo-pty LINK --servo-id 1,2`).
//!
//! Frames carry no delimiter; like a drive, the server aligns on gaps: bytes that sit
//! incomplete for [`GAP`] are dropped (a real drive's inter-frame timeout), so one garbled
//! frame does not shift every later one. Requests the drives would not answer get no reply.
//!
//! **Line timing.** A pty moves bytes at memory speed, so a reply would come back within
//! ~0.1 ms — faster than any RS232 line, and a client that clears its input buffer right
//! after sending (as a public C++ driver does) then loses replies it would never lose on a
//! wire. With a [`Pace`] (the default for served drives: 38400 baud, 1 ms think-time) the echo
//! goes out one frame time after the request arrived and the reply one frame time + the
//! think-time + one frame time after it, as a real line would deliver them.
//!
//! **Control socket.** With a link, a Unix socket `LINK.ctl` takes the simulator's control
//! language ([`super::control`]): faults, switches, pulses, strictness — one line in, one
//! JSON line out. `servo sim …` on a `kinco:LINK` device uses it.
//!
//! With tracing on (`plcsh -v sim serve`), every frame is reported to [`crate::core::trace`]
//! as the Modbus servers' frames are.

use super::{control, Pace, SimLine};
use crate::core::link::pty::Pty;
use crate::core::trace::{self, Dir};
use crate::core::{Clock, Error, Result};
use crate::servo::frame::FrameBuffer;
use crate::servo::link::{FdPort, Transport};
use std::io::{BufRead, BufReader, Read, Write};
use std::os::unix::net::UnixListener;
use std::path::{Path, PathBuf};
use std::sync::atomic::{AtomicBool, Ordering};
use std::sync::{Arc, Mutex};
use std::time::{Duration, Instant};

/// Longest control-socket line accepted.
const MAX_LINE: usize = 4096;

/// Silence after which a partial frame is dropped (a frame takes 2.6 ms at 38400 baud).
pub const GAP: Duration = Duration::from_millis(20);

fn sleep_until(at: Instant) {
    let now = Instant::now();
    if at > now {
        std::thread::sleep(at - now);
    }
}

/// Answers requests on `t` until `stop` is raised (checked at least every [`GAP`]).
/// `name` names the line in traces.
pub fn serve_line(mut t: Box<dyn Transport>, line: &Arc<Mutex<SimLine>>, stop: &AtomicBool, name: &str) -> Result<()> {
    let mut fb = FrameBuffer::new();
    let mut buf = [0u8; 256];
    while !stop.load(Ordering::Relaxed) {
        let n = t.recv(&mut buf, GAP)?;
        if n == 0 {
            fb.clear();
            continue;
        }
        let arrived = Instant::now();
        fb.push(&buf[..n]);
        while let Some(req) = fb.next_raw() {
            trace::frame(name, Dir::Received, &req);
            let a = line.lock().unwrap_or_else(|p| p.into_inner()).exchange(&req);
            if let Some(e) = a.echo {
                sleep_until(arrived + a.echo_after);
                trace::frame(name, Dir::Sent, &e);
                t.send(&e)?;
            }
            if let Some(r) = a.reply {
                sleep_until(arrived + a.reply_after);
                trace::frame(name, Dir::Sent, &r);
                t.send(&r)?;
            }
        }
    }
    Ok(())
}

/// What `serve_pty` announces once clients may connect.
#[derive(Clone, Debug, serde::Serialize)]
pub struct Ready {
    /// The pty slave device (`/dev/pts/N`).
    pub servo_pty: PathBuf,
    /// The symlink pointing at it, if one was asked for.
    pub link: Option<PathBuf>,
    pub ids: Vec<u8>,
    pub echo: bool,
    /// The control socket (`LINK.ctl`), when there is a link.
    pub servo_control: Option<PathBuf>,
    /// Line timing: baud rate and think-time in µs; absent for instant replies.
    pub servo_baud: Option<u32>,
    pub servo_latency_us: Option<u64>,
    pub strict: bool,
}

/// How to serve a line.
#[derive(Clone, Debug)]
pub struct Options {
    pub ids: Vec<u8>,
    pub echo: bool,
    pub pace: Option<Pace>,
    pub strict: bool,
}

/// The control socket's path for a pty link: `LINK.ctl`.
pub fn control_path(link: &Path) -> PathBuf {
    let mut s = link.as_os_str().to_os_string();
    s.push(".ctl");
    PathBuf::from(s)
}

/// Answers control requests on `listener` until `stop` (one thread per connection).
fn serve_control(listener: UnixListener, line: Arc<Mutex<SimLine>>, stop: Arc<AtomicBool>) {
    let _ = listener.set_nonblocking(true);
    while !stop.load(Ordering::Relaxed) {
        match listener.accept() {
            Ok((conn, _)) => {
                let line = line.clone();
                std::thread::spawn(move || {
                    let _ = conn.set_nonblocking(false);
                    let mut w = match conn.try_clone() {
                        Ok(w) => w,
                        Err(_) => return,
                    };
                    let mut r = BufReader::new(conn);
                    loop {
                        // One request per line, at most MAX_LINE bytes (outside input).
                        let mut text = String::new();
                        match (&mut r).take(MAX_LINE as u64 + 1).read_line(&mut text) {
                            Ok(0) | Err(_) => break,
                            Ok(_) => {}
                        }
                        let reply = if text.len() > MAX_LINE {
                            serde_json::json!({"ok": false, "error": format!("a control line is at most {MAX_LINE} bytes")})
                        } else {
                            control::answer_line(&mut line.lock().unwrap_or_else(|p| p.into_inner()), text.trim())
                        };
                        if writeln!(w, "{reply}").is_err() || text.len() > MAX_LINE {
                            break;
                        }
                    }
                });
            }
            Err(e) if e.kind() == std::io::ErrorKind::WouldBlock => std::thread::sleep(GAP),
            Err(_) => std::thread::sleep(GAP),
        }
    }
}

/// Opens a pty, points `link` at it (and opens `LINK.ctl`), calls `ready`, then serves the
/// drives on it until `stop` is raised. The symlink and the socket are removed on the way out.
pub fn serve_pty(
    link: Option<&Path>,
    opts: &Options,
    clock: Clock,
    stop: &Arc<AtomicBool>,
    ready: impl FnOnce(&Ready),
) -> Result<()> {
    serve_pty_line(link, opts, Arc::new(Mutex::new(SimLine::new(&opts.ids, clock))), stop, ready)
}

/// [`serve_pty`] for a line that already exists (a bench's drives, wired to its PLC); the
/// line takes `opts`' echo, timing and strictness, and its own drive ids.
pub fn serve_pty_line(
    link: Option<&Path>,
    opts: &Options,
    line: Arc<Mutex<SimLine>>,
    stop: &Arc<AtomicBool>,
    ready: impl FnOnce(&Ready),
) -> Result<()> {
    let pty = Pty::open()?;
    if let Some(l) = link {
        pty.link(l)?;
    }
    let Pty { master, slave, path } = pty;
    let ids = {
        let mut sim = line.lock().unwrap_or_else(|p| p.into_inner());
        sim.echo = opts.echo;
        sim.pace = opts.pace;
        sim.set_strict(opts.strict);
        sim.ids()
    };
    let ctl = match link {
        Some(l) => {
            let p = control_path(l);
            let _ = std::fs::remove_file(&p);
            let listener = UnixListener::bind(&p)
                .map_err(|e| Error::io(format!("cannot open the servo control socket {}", p.display())).cause(e))?;
            let (line, stop) = (line.clone(), stop.clone());
            std::thread::spawn(move || serve_control(listener, line, stop));
            Some(p)
        }
        None => None,
    };
    ready(&Ready {
        servo_pty: path.clone(),
        link: link.map(Path::to_path_buf),
        ids,
        echo: opts.echo,
        servo_control: ctl.clone(),
        servo_baud: opts.pace.map(|p| p.baud),
        servo_latency_us: opts.pace.map(|p| p.latency.as_micros() as u64),
        strict: opts.strict,
    });
    let name = link.map(|l| l.display().to_string()).unwrap_or_else(|| path.display().to_string());
    let r = serve_line(Box::new(FdPort(master)), &line, stop, &name);
    drop(slave);
    if let Some(l) = link {
        let _ = std::fs::remove_file(l);
    }
    if let Some(c) = ctl {
        let _ = std::fs::remove_file(c);
    }
    r
}
