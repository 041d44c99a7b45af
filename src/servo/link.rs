//! Byte transports for the servo driver, apart from the codec: a real serial port
//! (`serialport`), any file descriptor waited on with `poll` (a pty master, a pipe), a Unix
//! socket pair (tests), and the in-process simulator ([`super::sim::SimLink`]). The driver
//! only needs "send these bytes" and "give me what arrives within this time".
//!
//! Several drives share one RS232 line (multi-drop / loop wiring), so a line is opened once
//! per process and shared: [`shared`] keeps a registry keyed by port path, and every
//! `kinco:` device on the same path gets the same [`Line`] (one request at a time, under
//! its mutex). The registry holds weak references: the port closes with its last device.

use crate::core::{Error, Result};
use std::collections::HashMap;
use std::fs::File;
use std::io::{self, Read, Write};
use std::os::fd::AsFd;
use std::sync::{Arc, Mutex, OnceLock, Weak};
use std::time::Duration;

/// A byte stream with receive timeouts.
pub trait Transport: Send {
    /// Sends all of `bytes`.
    fn send(&mut self, bytes: &[u8]) -> io::Result<()>;
    /// Receives what arrives within `timeout` (at least one byte), or `Ok(0)` when nothing did.
    fn recv(&mut self, buf: &mut [u8], timeout: Duration) -> io::Result<usize>;
    /// Drops bytes already received but not read (a late reply after a timeout).
    fn discard_input(&mut self) -> io::Result<()> {
        let mut scratch = [0u8; 64];
        while self.recv(&mut scratch, Duration::ZERO)? > 0 {}
        Ok(())
    }
    /// The simulated line behind this transport, when it is the in-process simulator.
    fn sim_line(&self) -> Option<Arc<Mutex<super::sim::SimLine>>> {
        None
    }
}

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

/// A shared serial port, reopened after it disappears ([`Line::reopen`]).
pub fn shared_serial(path: &str, baud: u32, settings: &str) -> Result<SharedLine> {
    let p = path.to_string();
    shared_with(path, settings, || open_serial(path, baud), Some(Box::new(move || open_serial(&p, baud))))
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
            return Err(Error::usage(format!("{key} is already open with {}, not {settings}", line.settings))
                .hint("every drive on one line uses the same baud rate and loop setting"));
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

/// Opens a serial port 8N1 at `baud` (the drive's factory framing, seed §1).
pub fn open_serial(path: &str, baud: u32) -> Result<Box<dyn Transport>> {
    let port = serialport::new(path, baud)
        .data_bits(serialport::DataBits::Eight)
        .parity(serialport::Parity::None)
        .stop_bits(serialport::StopBits::One)
        .flow_control(serialport::FlowControl::None)
        .timeout(Duration::from_millis(100))
        .open_native()
        .map_err(|e| {
            Error::link(format!("cannot open serial port {path}"))
                .cause(e)
                .hint("check the path (ls /dev/ttyUSB* /dev/ttyS*), that your user may open it (group dialout) and that no other program holds it")
        })?;
    Ok(Box::new(Serial(port)))
}

/// A serial port.
pub struct Serial(pub serialport::TTYPort);

impl Drop for Serial {
    /// Clears TIOCEXCL before closing, as a precaution: on a pty whose server keeps the
    /// slave open (the simulator) the tty is never fully closed, and the flag must not
    /// outlive this client and refuse the next one.
    fn drop(&mut self) {
        let _ = self.0.set_exclusive(false);
    }
}

fn timed_out(e: &io::Error) -> bool {
    matches!(e.kind(), io::ErrorKind::TimedOut | io::ErrorKind::WouldBlock)
}

impl Transport for Serial {
    fn send(&mut self, bytes: &[u8]) -> io::Result<()> {
        self.0.write_all(bytes)?;
        self.0.flush()
    }
    fn recv(&mut self, buf: &mut [u8], timeout: Duration) -> io::Result<usize> {
        use serialport::SerialPort;
        self.0.set_timeout(timeout).map_err(io::Error::from)?;
        match self.0.read(buf) {
            Err(e) if timed_out(&e) => Ok(0),
            r => r,
        }
    }
    fn discard_input(&mut self) -> io::Result<()> {
        use serialport::SerialPort;
        self.0.clear(serialport::ClearBuffer::Input).map_err(io::Error::from)
    }
}

/// Any file descriptor, waited on with `poll` (the pty master in the simulator server).
pub struct FdPort(pub File);

impl Transport for FdPort {
    fn send(&mut self, bytes: &[u8]) -> io::Result<()> {
        self.0.write_all(bytes)?;
        self.0.flush()
    }
    fn recv(&mut self, buf: &mut [u8], timeout: Duration) -> io::Result<usize> {
        use nix::poll::{poll, PollFd, PollFlags, PollTimeout};
        let ms = PollTimeout::try_from(timeout).unwrap_or(PollTimeout::MAX);
        let mut fds = [PollFd::new(self.0.as_fd(), PollFlags::POLLIN)];
        match poll(&mut fds, ms) {
            Ok(0) => return Ok(0),
            Ok(_) => {}
            Err(nix::errno::Errno::EINTR) => return Ok(0),
            Err(e) => return Err(io::Error::from(e)),
        }
        self.0.read(buf)
    }
}

/// A Unix socket (one end of `UnixStream::pair()` in tests).
impl Transport for std::os::unix::net::UnixStream {
    fn send(&mut self, bytes: &[u8]) -> io::Result<()> {
        self.write_all(bytes)
    }
    fn recv(&mut self, buf: &mut [u8], timeout: Duration) -> io::Result<usize> {
        if timeout.is_zero() {
            self.set_nonblocking(true)?;
            let r = self.read(buf);
            self.set_nonblocking(false)?;
            return match r {
                Err(e) if timed_out(&e) => Ok(0),
                r => r,
            };
        }
        self.set_read_timeout(Some(timeout))?;
        match self.read(buf) {
            Err(e) if timed_out(&e) => Ok(0),
            r => r,
        }
    }
}
