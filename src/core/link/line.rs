//! The byte line the serial families' drivers talk over (servo, UMPK, FX): "send these
//! bytes" and "give me what arrives within this time", whatever carries them — a serial port
//! ([`super::serial`]: a tty or a COM port), a raw TCP connection to a serial device server
//! ([`super::tcp`]), RFC 2217 ([`super::rfc2217`]), a served pty's master, an in-process pipe
//! ([`super::pipe`]) or a simulator in the same process.
//!
//! Several devices share one RS232/RS485 line (multi-drop / loop wiring), so a line is opened
//! once per process and shared: [`shared`] keeps a registry keyed by port path, and every
//! device on the same path gets the same [`Line`] (one request at a time, under its mutex).
//! The registry holds weak references: the port closes with its last device.

use crate::core::{Error, Result};
use crate::msg;
use std::collections::HashMap;
use std::sync::{Arc, Mutex, OnceLock, Weak};

pub use super::transport::Transport;

/// Opens a line's transport again after its port disappeared.
pub type Reopen = Box<dyn Fn() -> Result<Box<dyn Transport>> + Send + Sync>;

/// One shared line: the transport, plus what it was opened with (to refuse a second open
/// with other settings).
pub struct Line {
    pub transport: Mutex<Box<dyn Transport>>,
    pub settings: String,
    /// Name for traces and messages (`/dev/ttyUSB0`).
    pub name: String,
    /// How to open the port again (serial ports), and whether it is gone: a port that
    /// disappears (USB adapter unplugged, a served pty restarted) is reopened by the next
    /// request once it is back.
    pub reopen: Option<Reopen>,
    pub gone: std::sync::atomic::AtomicBool,
}

pub type SharedLine = Arc<Line>;

fn registry() -> &'static Mutex<HashMap<String, Weak<Line>>> {
    static R: OnceLock<Mutex<HashMap<String, Weak<Line>>>> = OnceLock::new();
    R.get_or_init(|| Mutex::new(HashMap::new()))
}

/// The line at `key`, opened by `open` if no device holds it yet. `settings` must match
/// those of a line already open.
pub fn shared(key: &str, settings: &str, open: impl FnOnce() -> Result<Box<dyn Transport>>) -> Result<SharedLine> {
    shared_with(key, settings, open, None)
}

/// A shared serial line (a port, or a device server), reopened after it disappears
/// ([`Line::reopen`]).
pub fn shared_serial(carrier: &super::serial::Carrier, line: super::serial::LineSettings) -> Result<SharedLine> {
    let c = carrier.clone();
    let settings = line.to_string();
    shared_with(
        &carrier.key(),
        &settings,
        || super::serial::open(carrier, line),
        Some(Box::new(move || super::serial::open(&c, line))),
    )
}

fn shared_with(
    key: &str,
    settings: &str,
    open: impl FnOnce() -> Result<Box<dyn Transport>>,
    reopen: Option<Reopen>,
) -> Result<SharedLine> {
    let mut reg = registry().lock().unwrap_or_else(|p| p.into_inner());
    reg.retain(|_, w| w.strong_count() > 0);
    if let Some(line) = reg.get(key).and_then(Weak::upgrade) {
        if line.settings != settings {
            return Err(Error::usage(msg!(
                "link-line-settings",
                line = key,
                open = &line.settings,
                settings = settings
            ))
            .hint(msg!("link-hint-line-settings")));
        }
        return Ok(line);
    }
    let line = Arc::new(Line {
        transport: Mutex::new(open()?),
        settings: settings.to_string(),
        name: key.to_string(),
        reopen,
        gone: Default::default(),
    });
    reg.insert(key.to_string(), Arc::downgrade(&line));
    Ok(line)
}

/// A private (unshared) line.
pub fn private(name: &str, t: Box<dyn Transport>) -> SharedLine {
    Arc::new(Line {
        transport: Mutex::new(t),
        settings: String::new(),
        name: name.to_string(),
        reopen: None,
        gone: Default::default(),
    })
}
