//! The Windows corner of the transport layer: COM ports (through `serialport`'s `COMPort`,
//! `COM10` and above included: it adds the `\\.\` prefix), TCP sockets as deadline ports, a
//! loopback TCP port for the served drive line's control channel (its port number written to
//! the file a Unix socket would be), and the words a message uses for ports here.
//!
//! Windows has no pseudo-terminals: [`pty::Pty::open`] and [`async_pty::AsyncPty::open`]
//! refuse with the TCP option to use instead (`sim serve --servo-tcp …`), so no caller
//! needs to know which system it runs on.

use crate::core::link::port::{Port, TransportPort};
use crate::core::link::serial::LineSettings;
use crate::core::trace::Proto;
use crate::core::Result;
use crate::msg;
use std::io::{self, Read, Write};
use std::net::{TcpListener, TcpStream};
use std::path::Path;

/// Port names as a user of this system writes them (for hints).
pub const PORT_EXAMPLES: &str = "COM3, COM10; Device Manager → Ports (COM & LPT) shows them too";
/// Whether a port may refuse to open because the user is not in its group: not on Windows.
pub const PORT_GROUP: bool = false;
/// What to check when listing ports fails.
pub fn port_list_hint() -> String {
    crate::msg!("link-hint-list-ports-device-manager").into()
}

/// Every port Windows reports is listed.
pub fn listed_port(_name: &str) -> bool {
    true
}

/// A TCP connection as a deadline port (timeouts on the socket).
pub fn tcp_port(stream: TcpStream, link: &str, proto: Proto, peer: &str) -> io::Result<Box<dyn Port>> {
    Ok(Box::new(TransportPort::new(Box::new(crate::core::link::tcp::TcpLine::from_stream(stream)), link, proto, peer)))
}

/// Opens a COM port (exclusively: Windows lets one program hold it) as a deadline port.
pub fn serial_port(path: &str, settings: LineSettings, link: &str, proto: Proto) -> Result<Box<dyn Port>> {
    let port = crate::core::link::serial::open_port(path, settings)?;
    Ok(Box::new(TransportPort::new(Box::new(port), link, proto, path)))
}

/// Errors that mean the port itself is gone (an unplugged USB adapter), not a silent device.
pub fn port_gone(e: &io::Error) -> bool {
    // ERROR_FILE_NOT_FOUND, ERROR_ACCESS_DENIED (a vanished handle), ERROR_BAD_COMMAND,
    // ERROR_GEN_FAILURE, ERROR_OPERATION_ABORTED, ERROR_DEVICE_NOT_CONNECTED.
    matches!(e.raw_os_error(), Some(2 | 5 | 22 | 31 | 995 | 1167))
        || matches!(e.kind(), io::ErrorKind::BrokenPipe | io::ErrorKind::UnexpectedEof)
}

/// The system's serial port type.
pub type NativePort = serialport::COMPort;

/// Nothing to give back: closing the handle releases a COM port.
pub fn release_port(_p: &mut NativePort) {}

/// A local control channel's listening end: a loopback TCP port whose number is written to
/// the file at the channel's path.
pub struct LocalListener(TcpListener);
/// One connection on a local control channel.
pub type LocalStream = TcpStream;

impl LocalListener {
    /// Listens on a free loopback port and writes its number to `path`.
    pub fn bind(path: &Path) -> io::Result<LocalListener> {
        let l = TcpListener::bind("127.0.0.1:0")?;
        l.set_nonblocking(true)?;
        let mut f = std::fs::File::create(path)?;
        writeln!(f, "{}", l.local_addr()?.port())?;
        Ok(LocalListener(l))
    }
    /// The next connection, if one waits (never blocks).
    pub fn accept(&self) -> io::Result<LocalStream> {
        let (s, _) = self.0.accept()?;
        s.set_nonblocking(false)?;
        Ok(s)
    }
}

/// Connects to the control channel whose port number is in the file at `path`.
pub fn local_connect(path: &Path) -> io::Result<LocalStream> {
    let mut text = String::new();
    std::fs::File::open(path)?.read_to_string(&mut text)?;
    let port: u16 = text
        .trim()
        .parse()
        .map_err(|_| io::Error::new(io::ErrorKind::InvalidData, msg!("link-control-no-port").text))?;
    TcpStream::connect(("127.0.0.1", port))
}

/// Why a pseudo-terminal cannot be had here, and what to use instead.
fn no_pty() -> crate::core::Error {
    crate::core::Error::usage(msg!("link-windows-no-pty")).hint(msg!("link-hint-windows-tcp"))
}

/// Pseudo-terminals: none on Windows.
pub mod pty {
    use crate::core::link::line::Transport;
    use crate::core::Result;
    use std::io;
    use std::path::Path;
    use std::time::Duration;

    /// Never constructed on Windows.
    pub struct Pty {
        never: std::convert::Infallible,
    }

    impl Pty {
        pub fn open() -> Result<Pty> {
            Err(super::no_pty())
        }
        pub fn path(&self) -> &Path {
            match self.never {}
        }
        pub fn link(&self, _link: &Path) -> Result<()> {
            match self.never {}
        }
        pub fn served(self) -> Result<ServedPty> {
            match self.never {}
        }
    }

    /// Never constructed on Windows.
    pub struct ServedPty {
        never: std::convert::Infallible,
    }

    impl Transport for ServedPty {
        fn send(&mut self, _bytes: &[u8]) -> io::Result<()> {
            match self.never {}
        }
        fn recv(&mut self, _buf: &mut [u8], _timeout: Duration) -> io::Result<usize> {
            match self.never {}
        }
    }
}

/// Pseudo-terminals served asynchronously: none on Windows.
pub mod async_pty {
    use crate::core::Result;
    use std::path::Path;

    /// The master side as an async stream (never made on Windows).
    pub type PtyStream = tokio::io::DuplexStream;

    /// Never constructed on Windows.
    pub struct AsyncPty {
        never: std::convert::Infallible,
    }

    impl AsyncPty {
        pub fn open() -> Result<AsyncPty> {
            Err(super::no_pty())
        }
        pub fn path(&self) -> &Path {
            match self.never {}
        }
        pub fn link(&self, _link: &Path) -> Result<()> {
            match self.never {}
        }
        pub fn stream(&self) -> Result<PtyStream> {
            match self.never {}
        }
    }
}
