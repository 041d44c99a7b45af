//! Serving a simulated UMPK on a pseudo-terminal (`plcsh sim serve --umpk-pty LINK
//! --umpk-model UMPK16`), so a terminal program (picocom, screen, socat), a lab's own
//! software or plcsh's `umpk:` driver talks to it exactly as to the real controller's RS-232
//! port (57600 8N1; a pty has no baud rate, the simulator paces its output at 57600 baud
//! in virtual time itself).
//!
//! The loop wakes when bytes arrive or when the next queued byte or cycle is due, so the
//! monitor stream leaves once per 10 ms cycle. A line nobody reads loses bytes, as a real
//! one does: when the pty's buffer is full, what the client has not read is flushed.

use super::Umpk;
use crate::core::link::pty::Pty;
use crate::core::{Clock, Error, Result};
use crate::umpk::model::Model;
use nix::poll::{poll, PollFd, PollFlags, PollTimeout};
use std::fs::File;
use std::io::{self, Read, Write};
use std::os::fd::AsFd;
use std::path::{Path, PathBuf};
use std::sync::atomic::{AtomicBool, Ordering};
use std::sync::{Arc, Mutex};
use std::time::Duration;

/// Longest sleep of the loop (the stop flag is checked at least this often).
const MAX_WAIT: Duration = Duration::from_millis(10);

/// What `serve_pty` announces once clients may connect.
#[derive(Clone, Debug, serde::Serialize)]
pub struct Ready {
    /// The pty slave device (`/dev/pts/N`).
    pub umpk_pty: PathBuf,
    /// The symlink pointing at it.
    pub umpk_link: Option<PathBuf>,
    pub umpk_model: &'static str,
    /// Work or Wait at start (Work when the state file holds a program).
    pub umpk_mode: &'static str,
    /// The state file keeping the flash, if any.
    pub umpk_state: Option<PathBuf>,
}

fn lock(sim: &Mutex<Umpk>) -> std::sync::MutexGuard<'_, Umpk> {
    sim.lock().unwrap_or_else(|p| p.into_inner())
}

/// Serves `sim` on the pty `master` until `stop` is raised; `slave` is the server's own
/// handle on the other side (flushed when nobody reads).
pub fn serve_fd(master: &mut File, slave: &File, sim: &Arc<Mutex<Umpk>>, stop: &AtomicBool) -> Result<()> {
    nix::fcntl::fcntl(master.as_fd(), nix::fcntl::FcntlArg::F_SETFL(nix::fcntl::OFlag::O_NONBLOCK))
        .map_err(|e| Error::io("cannot make the pty non-blocking").cause(e))?;
    let mut buf = [0u8; 512];
    while !stop.load(Ordering::Relaxed) {
        let wait = {
            let s = lock(sim);
            s.next_event().saturating_sub(s.clock.now()).clamp(Duration::from_micros(200), MAX_WAIT)
        };
        let ms = PollTimeout::try_from(wait.as_millis().max(1) as i32).unwrap_or(PollTimeout::MAX);
        let mut fds = [PollFd::new(master.as_fd(), PollFlags::POLLIN)];
        let n = match poll(&mut fds, ms) {
            Ok(0) | Err(nix::errno::Errno::EINTR) => 0,
            Ok(_) => match master.read(&mut buf) {
                Ok(n) => n,
                Err(e) if e.kind() == io::ErrorKind::WouldBlock => 0,
                // EIO: no client has the slave open right now (we hold it, so rarely).
                Err(e) if e.raw_os_error() == Some(nix::libc::EIO) => 0,
                Err(e) => return Err(Error::io("reading the pty failed").cause(e)),
            },
            Err(e) => return Err(Error::io("poll on the pty failed").cause(e)),
        };
        let out = {
            let mut s = lock(sim);
            if n > 0 {
                s.receive(&buf[..n]);
            }
            s.take_due()
        };
        write_or_drop(master, slave, &out)?;
    }
    Ok(())
}

fn write_or_drop(master: &mut File, slave: &File, mut out: &[u8]) -> Result<()> {
    while !out.is_empty() {
        match master.write(out) {
            Ok(n) => out = &out[n..],
            Err(e) if e.kind() == io::ErrorKind::WouldBlock => {
                // Nobody reads: drop what waits on the client's side, as a line would.
                let _ = nix::sys::termios::tcflush(slave.as_fd(), nix::sys::termios::FlushArg::TCIFLUSH);
                if master.write(out).is_err() {
                    return Ok(());
                }
            }
            Err(e) if e.kind() == io::ErrorKind::Interrupted => {}
            Err(e) => return Err(Error::io("writing the pty failed").cause(e)),
        }
    }
    Ok(())
}

/// Opens a pty, points `link` at it, calls `ready`, then serves a simulated `model` on it
/// until `stop` is raised. The symlink is removed on the way out. `setup` adjusts the
/// simulator first (status layout, injected faults).
pub fn serve_pty(
    link: Option<&Path>,
    model: &'static Model,
    clock: Clock,
    setup: impl FnOnce(&mut Umpk) -> Result<()>,
    stop: &AtomicBool,
    ready: impl FnOnce(&Ready),
) -> Result<()> {
    let pty = Pty::open()?;
    if let Some(l) = link {
        pty.link(l)?;
    }
    let Pty { mut master, slave, path } = pty;
    let mut u = Umpk::new(model, clock);
    setup(&mut u)?;
    let sim = Arc::new(Mutex::new(u));
    let (umpk_mode, umpk_state) = {
        let u = lock(&sim);
        (u.mode().name(), u.state_path.clone())
    };
    ready(&Ready {
        umpk_pty: path,
        umpk_link: link.map(Path::to_path_buf),
        umpk_model: model.name,
        umpk_mode,
        umpk_state,
    });
    let r = serve_fd(&mut master, &slave, &sim, stop);
    if let Some(l) = link {
        let _ = std::fs::remove_file(l);
    }
    r
}

/// Where a served UMPK keeps its flash unless `--umpk-state` says otherwise: one file per
/// model and link in the user's data directory, so the controller served at the same link
/// powers up with the program it was given last time (as a real one does).
pub fn default_state(link: &Path, model: &Model) -> Option<PathBuf> {
    let abs = std::path::absolute(link).unwrap_or_else(|_| link.to_path_buf());
    let key: String =
        abs.to_string_lossy().chars().map(|c| if c.is_ascii_alphanumeric() || c == '-' { c } else { '_' }).collect();
    directories::ProjectDirs::from("", "", "plcsh")
        .map(|d| d.data_dir().join("umpk").join(format!("{}{key}.json", model.name)))
}

/// `--umpk-model`: a model name from the table.
pub fn parse_model(text: &str) -> std::result::Result<&'static Model, String> {
    crate::umpk::model::find(text)
        .ok_or_else(|| format!("`{text}` is not a UMPK model ({})", crate::umpk::model::names()))
}

/// What `plcsh sim serve --umpk-pty …` asks for.
#[derive(Clone, Debug)]
pub struct Options {
    pub link: PathBuf,
    pub model: &'static Model,
    pub layout: crate::umpk::codec::StatusLayout,
    pub flash_fail: Option<usize>,
    /// The state file keeping the flash through restarts ([`super::state`]).
    pub state: Option<PathBuf>,
    /// An IL lab program the served controller runs ([`super::program`]).
    pub program: Option<PathBuf>,
}

/// Serves a simulated UMPK from a thread of its own (the pty loop is blocking); returns
/// once the pty is open, with its fields for the readiness line. `stop` ends it.
pub async fn spawn(o: Options, stop: Arc<AtomicBool>) -> Result<serde_json::Map<String, serde_json::Value>> {
    let (model, layout) = (o.model, o.layout);
    let state = match o.state {
        Some(p) if p.as_os_str() == "none" => None,
        Some(p) => Some(p),
        None => default_state(&o.link, model),
    };
    // A program that does not load stops the server before it is ready.
    let runner = match &o.program {
        Some(p) => {
            let text = std::fs::read_to_string(p)
                .map_err(|e| Error::io(format!("cannot read the UMPK program {}: {e}", p.display())))?;
            Some(super::program::IlRunner::load(&text, &p.to_string_lossy(), model)?)
        }
        None => None,
    };
    let (tx, rx) = tokio::sync::oneshot::channel::<Result<serde_json::Value>>();
    std::thread::spawn(move || {
        let mut tx = Some(tx);
        let setup = |u: &mut Umpk| {
            u.layout = layout;
            u.flash_fail = o.flash_fail;
            if let Some(p) = &state {
                u.open_state(p)?;
            }
            if let Some(r) = runner {
                u.load_logic(Box::new(r));
            }
            Ok(())
        };
        let r = serve_pty(Some(&o.link), model, Clock::following(), setup, &stop, |r| {
            if let Some(tx) = tx.take() {
                let _ = tx.send(Ok(serde_json::json!(r)));
            }
        });
        if let (Err(e), Some(tx)) = (r, tx.take()) {
            let _ = tx.send(Err(e));
        }
    });
    match rx.await {
        Ok(Ok(serde_json::Value::Object(m))) => Ok(m),
        Ok(Ok(_)) => Ok(Default::default()),
        Ok(Err(e)) => Err(e),
        Err(_) => Err(Error::io("the UMPK line stopped before it was ready")),
    }
}
