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
/// Whether a port may refuse to open because the user is not in its group (dialout): the
/// open hint then says how to join it (`link-hint-open-port-group`).
pub const PORT_GROUP: bool = true;
/// What to check when listing ports fails.
pub fn port_list_hint() -> String {
    crate::msg!("link-hint-list-ports-dev").into()
}

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
        let (short, _dir) = socket_path(path)?;
        let l = std::os::unix::net::UnixListener::bind(short)?;
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
    let (short, _dir) = socket_path(path)?;
    std::os::unix::net::UnixStream::connect(short)
}

/// The path to give a Unix socket call for `path`. A socket's path is limited to about 100
/// bytes (`SUN_LEN`), which a control channel beside a pty in a deep folder — a Cyrillic name
/// takes two bytes a letter — passes quickly. On Linux a longer path is reached through its
/// folder's descriptor (`/proc/self/fd/N/NAME`, the same file), which is short; the folder
/// stays open (the second value) until the call is made. Elsewhere the path is used as it is.
fn socket_path(path: &Path) -> io::Result<(std::path::PathBuf, Option<std::fs::File>)> {
    const ROOM: usize = 100;
    if path.as_os_str().len() < ROOM {
        return Ok((path.to_path_buf(), None));
    }
    #[cfg(target_os = "linux")]
    if let (Some(dir), Some(name)) = (path.parent(), path.file_name()) {
        use std::os::fd::AsRawFd;
        let dir = if dir.as_os_str().is_empty() { Path::new(".") } else { dir };
        let folder = std::fs::File::open(dir)?;
        let short = std::path::PathBuf::from(format!("/proc/self/fd/{}", folder.as_raw_fd())).join(name);
        if short.as_os_str().len() < ROOM {
            return Ok((short, Some(folder)));
        }
    }
    Ok((path.to_path_buf(), None))
}

#[cfg(test)]
mod socket_path_tests {
    use super::*;

    #[test]
    fn a_control_socket_in_a_deep_folder_with_a_cyrillic_name_listens_and_connects() {
        let mut dir = std::env::temp_dir().join(format!("plcsh-sock-{}", std::process::id()));
        for _ in 0..4 {
            dir = dir.join("Проверка лабораторной работы");
        }
        std::fs::create_dir_all(&dir).unwrap();
        let path = dir.join("пресс rtu.ctl");
        assert!(path.as_os_str().len() > 200, "past SUN_LEN: {}", path.as_os_str().len());
        let l = LocalListener::bind(&path);
        if cfg!(target_os = "linux") {
            let l = l.expect("bound through the folder's descriptor");
            assert!(path.exists(), "the socket is at the long path itself");
            let _c = local_connect(&path).expect("connects through the folder's descriptor");
            let mut tries = 0;
            while l.accept().is_err() {
                tries += 1;
                assert!(tries < 1000, "the connection never arrived");
                std::thread::yield_now();
            }
        }
        let _ = std::fs::remove_dir_all(std::env::temp_dir().join(format!("plcsh-sock-{}", std::process::id())));
    }
}
