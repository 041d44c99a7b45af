//! The Unix corner of the transport layer (Linux, and macOS kept possible: POSIX calls only,
//! `/dev/cu.*` port names): pseudo-terminals for served simulators, descriptors waited on
//! with `poll`, Unix sockets for the served drive line's control channel, and the words a
//! message uses for ports here. [`super::windows`] has the same items for Windows.

pub mod async_pty;
pub mod fd_stream;
pub mod poll_port;
pub mod pty;

pub use poll_port::{serial_port, tcp_port};

use std::io;
use std::path::Path;

/// Port names as a user of this system writes them (for hints).
pub const PORT_EXAMPLES: &str =
    "/dev/ttyUSB0, /dev/ttyACM0, /dev/ttyS0, /dev/serial/by-id/…, /dev/cu.usbserial-… on macOS";
/// Why a port may refuse to open besides a wrong name.
pub const PERMISSION_HINT: &str =
    ", and that you may open it (the dialout group: sudo usermod -aG dialout $USER, then log in again)";
/// What to check when listing ports fails.
pub const PORT_LIST_HINT: &str = "ls /dev/ttyUSB* /dev/ttyACM* /dev/serial/by-id shows the ports the kernel has";

/// Whether `ports` lists a port the OS reports: Linux reports every `ttyS` slot the kernel
/// reserved, present or not, so those without a device behind them are left out.
pub fn listed_port(name: &str) -> bool {
    let Some(n) = name.strip_prefix("/dev/ttyS") else { return true };
    // A legacy UART slot with no hardware reports type 0 (PORT_UNKNOWN) in sysfs.
    let typ = std::fs::read_to_string(format!("/sys/class/tty/ttyS{n}/type")).unwrap_or_default();
    typ.trim() != "0"
}

/// Errors that mean the port itself is gone (not a slow or silent device): EIO is what a
/// hung-up tty or an unplugged adapter gives. The serialport crate passes some on as text only.
pub fn port_gone(e: &io::Error) -> bool {
    matches!(e.raw_os_error(), Some(libc::EIO | libc::ENXIO | libc::ENODEV | libc::EBADF | libc::EPIPE))
        || matches!(e.kind(), io::ErrorKind::BrokenPipe | io::ErrorKind::UnexpectedEof)
        || ["I/O error", "Input/output error", "No such device"].iter().any(|t| e.to_string().contains(t))
}

/// The system's serial port type.
pub type NativePort = serialport::TTYPort;

/// Clears TIOCEXCL before the port closes, as a precaution: on a pty whose server keeps the
/// slave open (the simulator) the tty is never fully closed, and the flag must not outlive
/// this client and refuse the next one.
pub fn release_port(p: &mut NativePort) {
    let _ = p.set_exclusive(false);
}

/// A local control channel's listening end (a Unix socket at a path).
pub struct LocalListener(std::os::unix::net::UnixListener);
/// One connection on a local control channel.
pub type LocalStream = std::os::unix::net::UnixStream;

impl LocalListener {
    /// Listens at `path` (an old socket there is replaced).
    pub fn bind(path: &Path) -> io::Result<LocalListener> {
        let _ = std::fs::remove_file(path);
        let l = std::os::unix::net::UnixListener::bind(path)?;
        l.set_nonblocking(true)?;
        Ok(LocalListener(l))
    }
    /// The next connection, if one waits (never blocks).
    pub fn accept(&self) -> io::Result<LocalStream> {
        let (s, _) = self.0.accept()?;
        s.set_nonblocking(false)?;
        Ok(s)
    }
}

/// Connects to the control channel at `path`.
pub fn local_connect(path: &Path) -> io::Result<LocalStream> {
    std::os::unix::net::UnixStream::connect(path)
}
