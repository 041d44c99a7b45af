//! Serving simulated drives on a byte stream — a pseudo-terminal, so any serial client
//! (plcsh's `kinco:` driver, a terminal program, a PLC emulator) can open the slave device
//! like a real RS232 port (`plcsh sim serve --servo-pty LINK --servo-id 1,2`), or a TCP port
//! reached as a serial device server's (`--servo-tcp ADDR`, `kinco+tcp://ADDR`; also how
//! drives are served on Windows).
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
use crate::core::link::control as control_channel;
use crate::core::link::line::Transport;
use crate::core::link::served::{ServeOn, Served};
use crate::core::trace::{self, Dir};
use crate::core::{Clock, Result};
use crate::msg;
use crate::servo::frame::FrameBuffer;
use std::path::{Path, PathBuf};
use std::sync::atomic::{AtomicBool, Ordering};
use std::sync::{Arc, Mutex};
use std::time::{Duration, Instant};

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
pub fn serve_line(t: &mut dyn Transport, line: &Arc<Mutex<SimLine>>, stop: &AtomicBool, name: &str) -> Result<()> {
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

/// What `serve` announces once clients may connect.
#[derive(Clone, Debug, serde::Serialize)]
pub struct Ready {
    /// The pty slave device (`/dev/pts/N`) and the symlink to it, when served on a pty.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub servo_pty: Option<crate::core::link::served::PtyReady>,
    /// The TCP address, when served on TCP (`kinco+tcp://ADDR`).
    #[serde(skip_serializing_if = "Option::is_none")]
    pub servo_tcp: Option<String>,
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
    /// Where the control channel listens; by default `LINK.ctl` beside a pty's link (a line
    /// served on TCP has none unless one is given).
    pub control: Option<PathBuf>,
    pub ids: Vec<u8>,
    pub echo: bool,
    pub pace: Option<Pace>,
    pub strict: bool,
}

/// The control socket's path for a pty link: `LINK.ctl`.
pub fn control_path(link: &Path) -> PathBuf {
    crate::core::link::control::default_path(link)
}

/// Opens the endpoint (a pty with `LINK` and its control socket `LINK.ctl`, or a TCP port),
/// calls `ready`, then serves the drives on it until `stop` is raised. The symlink and the
/// socket are removed on the way out.
pub fn serve(
    on: &ServeOn,
    opts: &Options,
    clock: Clock,
    stop: &Arc<AtomicBool>,
    ready: impl FnOnce(&Ready),
) -> Result<()> {
    serve_on_line(on, opts, Arc::new(Mutex::new(SimLine::new(&opts.ids, clock))), stop, ready)
}

/// [`serve`] for a line that already exists (a bench's drives, wired to its PLC); the
/// line takes `opts`' echo, timing and strictness, and its own drive ids.
pub fn serve_on_line(
    on: &ServeOn,
    opts: &Options,
    line: Arc<Mutex<SimLine>>,
    stop: &Arc<AtomicBool>,
    ready: impl FnOnce(&Ready),
) -> Result<()> {
    let served = Served::open(on)?;
    let ids = {
        let mut sim = line.lock().unwrap_or_else(|p| p.into_inner());
        sim.echo = opts.echo;
        sim.pace = opts.pace;
        sim.set_strict(opts.strict);
        sim.ids()
    };
    let ctl = match opts.control.clone().or_else(|| served.link_path().map(control_path)) {
        Some(p) => {
            let line = line.clone();
            let answer: control_channel::Answer = Arc::new(move |text: &str| {
                control::answer_line(&mut line.lock().unwrap_or_else(|p| p.into_inner()), text)
            });
            Some(control_channel::Channel::open(
                &p,
                &msg!("link-channel-name", device = "servo"),
                answer,
                stop.clone(),
            )?)
        }
        None => None,
    };
    ready(&Ready {
        servo_pty: served.pty_ready(),
        servo_tcp: served.tcp.map(|a| a.to_string()),
        ids,
        echo: opts.echo,
        servo_control: ctl.as_ref().map(|c| c.path().to_path_buf()),
        servo_baud: opts.pace.map(|p| p.baud),
        servo_latency_us: opts.pace.map(|p| p.latency.as_micros() as u64),
        strict: opts.strict,
    });
    let name = served.name();
    let mut served = served;
    let r = serve_line(served.line.as_mut(), &line, stop, &name);
    drop(ctl);
    r
}
