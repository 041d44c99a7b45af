//! Serving a simulated UMPK on a pseudo-terminal (`plcsh sim serve --umpk-pty LINK
//! --umpk-model UMPK16`) or a TCP port (`--umpk-tcp ADDR`, `umpk+tcp://ADDR`; also how it is
//! served on Windows), so a terminal program (picocom, screen, socat), a lab's own
//! software or plcsh's `umpk:` driver talks to it exactly as to the real controller's RS-232
//! port (57600 8N1; a pty has no baud rate, the simulator paces its output at 57600 baud
//! in virtual time itself).
//!
//! The loop wakes when bytes arrive or when the next queued byte or cycle is due, so the
//! monitor stream leaves once per 10 ms cycle. A line nobody reads loses bytes, as a real
//! one does: when the pty's buffer is full, what the client has not read is flushed.

use super::Umpk;
use crate::core::link::control as channel;
use crate::core::link::line::Transport;
use crate::core::link::served::{ServeOn, Served};
use crate::core::{Clock, Error, Result};
use crate::msg;
use crate::umpk::model::Model;
use std::path::{Path, PathBuf};
use std::sync::atomic::{AtomicBool, Ordering};
use std::sync::{Arc, Mutex};
use std::time::Duration;

/// Longest sleep of the loop (the stop flag is checked at least this often).
const MAX_WAIT: Duration = Duration::from_millis(10);

/// What `serve` announces once clients may connect.
#[derive(Clone, Debug, serde::Serialize)]
pub struct Ready {
    /// The pty slave device (`/dev/pts/N`) and the symlink to it, when served on a pty.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub umpk_pty: Option<crate::core::link::served::PtyReady>,
    /// The TCP address, when served on TCP (`umpk+tcp://ADDR`).
    #[serde(skip_serializing_if = "Option::is_none")]
    pub umpk_tcp: Option<String>,
    pub umpk_model: &'static str,
    /// Work or Wait at start (Work when the state file holds a program).
    pub umpk_mode: &'static str,
    /// The state file keeping the flash, if any.
    pub umpk_state: Option<PathBuf>,
    /// The control channel (inputs, square waves, faults; [`super::control`]).
    #[serde(skip_serializing_if = "Option::is_none")]
    pub umpk_control: Option<PathBuf>,
}

fn lock(sim: &Mutex<Umpk>) -> std::sync::MutexGuard<'_, Umpk> {
    sim.lock().unwrap_or_else(|p| p.into_inner())
}

/// Serves `sim` on `line` until `stop` is raised. The line drops what a client does not
/// read, as a real one does ([`crate::core::link::served`]).
pub fn serve_line(line: &mut dyn Transport, sim: &Arc<Mutex<Umpk>>, stop: &AtomicBool) -> Result<()> {
    let mut buf = [0u8; 512];
    let mut binaries = lock(sim).binaries;
    while !stop.load(Ordering::Relaxed) {
        let wait = {
            let s = lock(sim);
            s.next_event().saturating_sub(s.clock.now()).clamp(Duration::from_micros(200), MAX_WAIT)
        };
        let n = line.recv(&mut buf, wait).map_err(|e| Error::io(msg!("umpk-serve-read-failed")).cause(e))?;
        let out = {
            let mut s = lock(sim);
            if n > 0 {
                s.receive(&buf[..n]);
            }
            if s.binaries != binaries {
                binaries = s.binaries;
                eprintln!("{}", msg!("umpk-serve-binary", note = super::binary_not_executed().text));
            }
            s.take_due()
        };
        if !out.is_empty() {
            line.send(&out).map_err(|e| Error::io(msg!("umpk-serve-write-failed")).cause(e))?;
        }
    }
    Ok(())
}

/// Opens the endpoint, calls `ready`, then serves a simulated `model` on it until `stop` is
/// raised. A symlink is removed on the way out. `setup` adjusts the simulator first (status
/// layout, injected faults).
pub fn serve(
    on: &ServeOn,
    model: &'static Model,
    clock: Clock,
    setup: impl FnOnce(&mut Umpk) -> Result<()>,
    stop: &Arc<AtomicBool>,
    control: Option<PathBuf>,
    ready: impl FnOnce(&Ready),
) -> Result<()> {
    let mut served = Served::open(on)?;
    let mut u = Umpk::new(model, clock);
    setup(&mut u)?;
    let sim = Arc::new(Mutex::new(u));
    let control = match control.or_else(|| served.link_path().map(channel::default_path)) {
        Some(path) => {
            let s = sim.clone();
            let answer: channel::Answer =
                Arc::new(move |text: &str| channel::reply(super::control::answer(&mut lock(&s), text)));
            Some(channel::Channel::open(&path, &msg!("link-channel-name", device = "umpk"), answer, stop.clone())?)
        }
        None => None,
    };
    let (umpk_mode, umpk_state) = {
        let u = lock(&sim);
        (u.mode().name(), u.state_path.clone())
    };
    ready(&Ready {
        umpk_pty: served.pty_ready(),
        umpk_tcp: served.tcp.map(|a| a.to_string()),
        umpk_model: model.name,
        umpk_mode,
        umpk_state,
        umpk_control: control.as_ref().map(|c| c.path().to_path_buf()),
    });
    serve_line(served.line.as_mut(), &sim, stop)
}

/// Where a served UMPK keeps its flash unless `--umpk-state` says otherwise: one file per
/// model and link in the user's data directory, so the controller served at the same link
/// powers up with the program it was given last time (as a real one does).
pub fn default_state(link: &Path, model: &Model) -> Option<PathBuf> {
    let abs = std::path::absolute(link).unwrap_or_else(|_| link.to_path_buf());
    let key: String =
        abs.to_string_lossy().chars().map(|c| if c.is_ascii_alphanumeric() || c == '-' { c } else { '_' }).collect();
    crate::paths::umpk_flash().map(|d| d.join(format!("{}{key}.json", model.name)))
}

/// `--umpk-model`: a model name from the table.
pub fn parse_model(text: &str) -> std::result::Result<&'static Model, String> {
    crate::umpk::model::find(text)
        .ok_or_else(|| msg!("umpk-serve-not-model", model = text, models = crate::umpk::model::names()).text)
}

/// What `plcsh sim serve --umpk-pty …` (or `--umpk-tcp …`) asks for.
#[derive(Clone, Debug)]
pub struct Options {
    pub on: ServeOn,
    pub model: &'static Model,
    pub layout: crate::umpk::codec::StatusLayout,
    pub flash_fail: Option<usize>,
    /// The state file keeping the flash through restarts ([`super::state`]).
    pub state: Option<PathBuf>,
    /// An IL lab program the served controller runs ([`super::program`]).
    pub program: Option<PathBuf>,
    /// The control channel's path (default: `LINK.ctl` beside a pty's link).
    pub control: Option<PathBuf>,
}

/// Serves a simulated UMPK from a thread of its own (the pty loop is blocking); returns
/// once the pty is open, with its fields for the readiness line. `stop` ends it.
pub async fn spawn(o: Options, stop: Arc<AtomicBool>) -> Result<serde_json::Map<String, serde_json::Value>> {
    let (model, layout) = (o.model, o.layout);
    let state = match o.state {
        Some(p) if p.as_os_str() == "none" => None,
        Some(p) => Some(p),
        None => default_state(Path::new(&o.on.name()), model),
    };
    // A program that does not load stops the server before it is ready.
    let runner = match &o.program {
        Some(p) => {
            let text = crate::core::encoding::read_source(p).map_err(|e| {
                Error::io(msg!(
                    "umpk-serve-cannot-read-program",
                    file = p.display().to_string(),
                    reason = e.to_string()
                ))
            })?;
            Some(super::program::IlRunner::load(&text, &p.to_string_lossy(), model)?)
        }
        None => None,
    };
    let (tx, rx) = tokio::sync::oneshot::channel::<Result<serde_json::Value>>();
    std::thread::spawn(move || {
        let mut tx = Some(tx);
        let setup = |u: &mut Umpk| {
            u.layout = layout;
            u.fail_flash_page(o.flash_fail)?;
            if let Some(p) = &state {
                u.open_state(p)?;
            }
            if let Some(r) = runner {
                u.load_logic(Box::new(r));
            }
            Ok(())
        };
        let r = serve(&o.on, model, Clock::following(), setup, &stop, o.control.clone(), |r| {
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
        Err(_) => Err(Error::io(msg!("umpk-serve-line-stopped"))),
    }
}
