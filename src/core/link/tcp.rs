//! TCP as a byte line, both ways: the client side of a serial device server's raw TCP port
//! ([`TcpLine`], `kinco+tcp://HOST:PORT`), and the server side a simulator is served on
//! ([`ServedTcp`], `sim serve --servo-tcp ADDR`: how simulators are served on Windows, which
//! has no pseudo-terminals, and how a lab PC reaches a simulator on another).
//!
//! A served line has one client at a time, as a serial port has one program holding it: a
//! second connection is closed at once while the first is open (ser2net's default), and the
//! line is free again as soon as the first client disconnects. A client that stops reading
//! loses what the server sends meanwhile, as a line nobody listens to does; the server never
//! waits for it.

use super::transport::Transport;
use crate::core::url::DeviceUrl;
use crate::core::{Error, Result};
use crate::msg;
use std::io::{self, Read, Write};
use std::net::{SocketAddr, TcpListener, TcpStream, ToSocketAddrs};
use std::sync::mpsc;
use std::time::{Duration, Instant};

/// How long connecting to a device server may take.
pub const CONNECT_TIMEOUT: Duration = Duration::from_secs(3);

/// How long a served line's reply may wait for room in a client's receive window.
const SEND_STALL: Duration = Duration::from_millis(200);

/// `HOST:PORT` from a URL's target (a device server has no well-known port: one is required).
pub fn with_port(target: &str, u: &DeviceUrl) -> Result<String> {
    let t = target.trim_end_matches('/');
    match t.rsplit_once(':') {
        Some((host, p)) if !host.is_empty() && p.parse::<u16>().is_ok_and(|p| p > 0) => Ok(t.to_string()),
        _ => Err(Error::usage(msg!("link-not-host-port", target = target, url = u.text.as_str()))
            .hint(msg!("link-hint-host-port"))),
    }
}

/// Connects to `addr` (`HOST:PORT`; every address it resolves to is tried) within `timeout`.
/// A host name is looked up on a thread of its own, so a name server that does not answer
/// costs the timeout, not a hang. `hint` says what to check when nothing answers; it is
/// written only then (a message costs a catalogue lookup, which a connection that works must
/// not pay: one-shot start-up).
pub fn connect(addr: &str, timeout: Duration, hint: fn() -> String) -> Result<TcpStream> {
    let refused = |e: io::Error| Error::link(msg!("link-cannot-connect", addr = addr)).cause(e).hint(hint());
    let start = Instant::now();
    let addrs: Vec<SocketAddr> = match addr.parse::<SocketAddr>() {
        Ok(a) => vec![a],
        Err(_) => {
            let (tx, rx) = mpsc::channel();
            let name = addr.to_string();
            std::thread::spawn(move || {
                let _ = tx.send(name.to_socket_addrs().map(|a| a.collect::<Vec<_>>()));
            });
            match rx.recv_timeout(timeout) {
                Ok(r) => r.map_err(refused)?,
                Err(_) => {
                    return Err(Error::link(msg!(
                        "link-name-not-looked-up",
                        addr = addr,
                        ms = timeout.as_millis() as u64
                    ))
                    .hint(msg!("link-hint-name-server")))
                }
            }
        }
    };
    let mut last = None;
    for a in addrs {
        let left = timeout.saturating_sub(start.elapsed()).max(Duration::from_millis(1));
        match TcpStream::connect_timeout(&a, left) {
            Ok(s) => {
                let _ = s.set_nodelay(true);
                return Ok(s);
            }
            Err(e) => last = Some(e),
        }
    }
    Err(match last {
        Some(e) if e.kind() == io::ErrorKind::TimedOut => {
            Error::link(msg!("link-connect-timeout", addr = addr, ms = timeout.as_millis() as u64)).hint(hint())
        }
        Some(e) => refused(e),
        None => refused(io::Error::new(io::ErrorKind::NotFound, String::from(msg!("link-no-address")))),
    })
}

/// What to check when a serial device server does not answer.
pub fn server_hint() -> String {
    msg!("link-hint-server").into()
}

/// Receives into `buf` within `timeout` on a blocking stream: 0 when nothing came, an
/// `UnexpectedEof` error when the peer closed.
fn recv_within(s: &mut TcpStream, buf: &mut [u8], timeout: Duration) -> io::Result<usize> {
    // A zero read timeout means "block forever" to the socket API: ask for 1 µs instead.
    s.set_read_timeout(Some(timeout.max(Duration::from_micros(1))))?;
    match s.read(buf) {
        Ok(0) => Err(io::Error::new(io::ErrorKind::UnexpectedEof, String::from(msg!("link-connection-closed")))),
        Ok(n) => Ok(n),
        Err(e) if matches!(e.kind(), io::ErrorKind::WouldBlock | io::ErrorKind::TimedOut) => Ok(0),
        Err(e) if e.kind() == io::ErrorKind::Interrupted => Ok(0),
        Err(e) => Err(e),
    }
}

/// Whether a peer is still connected (it has not closed its end), without reading data.
fn still_open(s: &TcpStream) -> bool {
    if s.set_nonblocking(true).is_err() {
        return false;
    }
    let r = s.peek(&mut [0u8; 1]);
    let _ = s.set_nonblocking(false);
    match r {
        Ok(0) => false,
        Ok(_) => true,
        Err(e) => e.kind() == io::ErrorKind::WouldBlock,
    }
}

/// The client side of a raw TCP serial channel.
pub struct TcpLine {
    stream: TcpStream,
}

impl TcpLine {
    pub fn connect(addr: &str, timeout: Duration) -> Result<TcpLine> {
        Ok(TcpLine { stream: connect(addr, timeout, server_hint)? })
    }

    pub fn from_stream(stream: TcpStream) -> TcpLine {
        let _ = stream.set_nodelay(true);
        TcpLine { stream }
    }
}

impl Transport for TcpLine {
    fn send(&mut self, bytes: &[u8]) -> io::Result<()> {
        self.stream.write_all(bytes)
    }
    fn recv(&mut self, buf: &mut [u8], timeout: Duration) -> io::Result<usize> {
        recv_within(&mut self.stream, buf, timeout)
    }
}

/// The server side of a line served on a TCP port: one client at a time.
pub struct ServedTcp {
    local: SocketAddr,
    incoming: mpsc::Receiver<TcpStream>,
    client: Option<TcpStream>,
}

impl ServedTcp {
    /// Listens on `addr` (port 0 picks a free port, see [`ServedTcp::local_addr`]).
    pub fn bind(addr: SocketAddr) -> Result<ServedTcp> {
        let listener = TcpListener::bind(addr).map_err(|e| {
            Error::io(msg!("link-cannot-listen", addr = addr.to_string())).cause(e).hint(msg!("link-hint-listen"))
        })?;
        let local = listener.local_addr()?;
        let (tx, incoming) = mpsc::channel();
        std::thread::Builder::new()
            .name(format!("accept {local}"))
            .spawn(move || {
                for conn in listener.incoming().flatten() {
                    if tx.send(conn).is_err() {
                        break; // the line was dropped
                    }
                }
            })
            .map_err(|e| Error::io(msg!("link-cannot-start-thread")).cause(e))?;
        Ok(ServedTcp { local, incoming, client: None })
    }

    /// The address clients connect to.
    pub fn local_addr(&self) -> SocketAddr {
        self.local
    }

    /// Closes connections that arrive while a client holds the line; takes the next one
    /// (waiting up to `wait`) when none does.
    fn admit(&mut self, wait: Duration) {
        while let Ok(next) = self.incoming.try_recv() {
            if self.client.as_ref().is_some_and(still_open) {
                let _ = next.shutdown(std::net::Shutdown::Both);
            } else {
                let _ = next.set_nodelay(true);
                let _ = next.set_write_timeout(Some(SEND_STALL));
                self.client = Some(next);
            }
        }
        if self.client.is_some() {
            return;
        }
        if let Ok(c) = self.incoming.recv_timeout(wait) {
            let _ = c.set_nodelay(true);
            let _ = c.set_write_timeout(Some(SEND_STALL));
            self.client = Some(c);
        }
    }
}

impl Transport for ServedTcp {
    /// Sends to the client, if one is connected; a client that does not read in time loses
    /// the rest of the frame (what a line does), and a gone client frees the line.
    fn send(&mut self, bytes: &[u8]) -> io::Result<()> {
        if let Some(c) = &mut self.client {
            match c.write_all(bytes) {
                Ok(()) => {}
                Err(e) if matches!(e.kind(), io::ErrorKind::WouldBlock | io::ErrorKind::TimedOut) => {}
                Err(_) => self.client = None,
            }
        }
        Ok(())
    }

    /// What the client sends within `timeout`; 0 while no client is connected (the wait
    /// for one counts against the timeout).
    fn recv(&mut self, buf: &mut [u8], timeout: Duration) -> io::Result<usize> {
        let start = Instant::now();
        self.admit(timeout);
        let Some(c) = &mut self.client else { return Ok(0) };
        match recv_within(c, buf, timeout.saturating_sub(start.elapsed())) {
            Ok(n) => Ok(n),
            Err(_) => {
                self.client = None; // closed or reset: the line is free
                Ok(0)
            }
        }
    }

    fn discard_input(&mut self) -> io::Result<()> {
        let mut scratch = [0u8; 256];
        while self.recv(&mut scratch, Duration::ZERO)? > 0 {}
        Ok(())
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_served_line_has_one_client_at_a_time_and_frees_itself() {
        let mut served = ServedTcp::bind("127.0.0.1:0".parse().unwrap()).unwrap();
        let addr = served.local_addr().to_string();
        let mut a = TcpLine::connect(&addr, CONNECT_TIMEOUT).unwrap();
        a.send(b"hello").unwrap();
        let mut buf = [0u8; 16];
        let mut got = Vec::new();
        while got.len() < 5 {
            let n = served.recv(&mut buf, Duration::from_secs(5)).unwrap();
            got.extend_from_slice(&buf[..n]);
        }
        assert_eq!(got, b"hello");
        served.send(b"back").unwrap();
        let mut back = Vec::new();
        while back.len() < 4 {
            let n = a.recv(&mut buf, Duration::from_secs(5)).unwrap();
            back.extend_from_slice(&buf[..n]);
        }
        assert_eq!(back, b"back");
        // A second client is closed while the first holds the line.
        let mut b = TcpLine::connect(&addr, CONNECT_TIMEOUT).unwrap();
        let deadline = Instant::now() + Duration::from_secs(5);
        let closed = loop {
            served.recv(&mut buf, Duration::from_millis(20)).unwrap();
            match b.recv(&mut buf, Duration::from_millis(20)) {
                Err(e) => break e.kind() == io::ErrorKind::UnexpectedEof || e.kind() == io::ErrorKind::ConnectionReset,
                Ok(_) if Instant::now() > deadline => break false,
                Ok(_) => {}
            }
        };
        assert!(closed, "the second client was refused");
        // The first leaves; the next client gets the line.
        drop(a);
        let mut c = TcpLine::connect(&addr, CONNECT_TIMEOUT).unwrap();
        c.send(b"x").unwrap();
        let deadline = Instant::now() + Duration::from_secs(5);
        loop {
            let n = served.recv(&mut buf, Duration::from_millis(50)).unwrap();
            if n == 1 && buf[0] == b'x' {
                break;
            }
            assert!(Instant::now() < deadline, "the third client never got the line");
        }
    }

    #[test]
    fn device_server_addresses_need_a_port() {
        let u = DeviceUrl::parse("kinco+tcp://moxa?id=1").unwrap();
        assert!(with_port("moxa", &u).unwrap_err().hint.as_deref().unwrap().contains("4001"));
        assert_eq!(with_port("moxa:4001/", &u).unwrap(), "moxa:4001");
        assert!(with_port(":4001", &u).is_err());
    }
}
