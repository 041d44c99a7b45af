//! Serving simulated drives on a byte stream — in practice a pseudo-terminal, so any serial
//! client (plcsh's `kinco:` driver, a terminal program, a PLC emulator) can open the slave
//! device like a real RS232 port (`plcsh sim serve --servo-pty LINK --servo-id 1,2`).
//!
//! Frames carry no delimiter; like a drive, the server aligns on gaps: bytes that sit
//! incomplete for [`GAP`] are dropped (a real drive's inter-frame timeout), so one garbled
//! frame does not shift every later one. Requests the drives would not answer get no reply.

use super::SimLine;
use crate::core::link::pty::Pty;
use crate::core::{Clock, Result};
use crate::servo::frame::FrameBuffer;
use crate::servo::link::{FdPort, Transport};
use std::path::{Path, PathBuf};
use std::sync::atomic::{AtomicBool, Ordering};
use std::sync::{Arc, Mutex};
use std::time::Duration;

/// Silence after which a partial frame is dropped (a frame takes 2.6 ms at 38400 baud).
pub const GAP: Duration = Duration::from_millis(20);

/// Answers requests on `t` until `stop` is raised (checked at least every [`GAP`]).
pub fn serve_line(mut t: Box<dyn Transport>, line: &Arc<Mutex<SimLine>>, stop: &AtomicBool) -> Result<()> {
    let mut fb = FrameBuffer::new();
    let mut buf = [0u8; 256];
    while !stop.load(Ordering::Relaxed) {
        let n = t.recv(&mut buf, GAP)?;
        if n == 0 {
            fb.clear();
            continue;
        }
        fb.push(&buf[..n]);
        while let Some(req) = fb.next_raw() {
            let (echo, reply) = {
                let mut l = line.lock().unwrap_or_else(|p| p.into_inner());
                (l.echo, l.answer(&req))
            };
            if echo {
                t.send(&req)?;
            }
            if let Some(r) = reply {
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
}

/// Opens a pty, points `link` at it, calls `ready`, then serves drives `ids` on it until
/// `stop` is raised. The symlink is removed on the way out.
pub fn serve_pty(
    link: Option<&Path>,
    ids: &[u8],
    echo: bool,
    clock: Clock,
    stop: &AtomicBool,
    ready: impl FnOnce(&Ready),
) -> Result<()> {
    let pty = Pty::open()?;
    if let Some(l) = link {
        pty.link(l)?;
    }
    let Pty { master, slave, path } = pty;
    let mut sim = SimLine::new(ids, clock);
    sim.echo = echo;
    let line = Arc::new(Mutex::new(sim));
    ready(&Ready { servo_pty: path, link: link.map(Path::to_path_buf), ids: ids.to_vec(), echo });
    let r = serve_line(Box::new(FdPort(master)), &line, stop);
    drop(slave);
    if let Some(l) = link {
        let _ = std::fs::remove_file(l);
    }
    r
}
