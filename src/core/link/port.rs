//! Deadline ports: the byte transport under a request/reply client with one request in
//! flight and a deadline per step (the K2 driver's Modbus client). Three kinds:
//!
//! - a descriptor (a TCP socket, a serial port) driven with plain system calls, on Unix
//!   (`sys::PollPort`): the driver has one request in flight and nothing else to do while it
//!   waits, so an async runtime only adds work per request. A request is a `write`, and each
//!   piece of the reply a `poll` with the time left and a `read` — what libmodbus does with
//!   `select` and `recv`; a one-shot command does not build a runtime;
//! - any [`Transport`] ([`TransportPort`]): COM ports, TCP sockets on Windows, RFC 2217 and
//!   raw TCP device servers;
//! - an async stream handed over by the caller ([`AsyncPort`]; an in-memory pipe in tests).
//!
//! [`tcp_port`] and [`serial_port`] pick the best kind for the platform. Every frame written
//! and every piece read is reported to [`crate::core::trace`] as the traced async streams
//! report theirs ([`super::traced`]), and a peer closing the connection raises a flag.

use super::traced::Traced;
use super::transport::Transport;
use crate::core::trace::{self, Dir, Proto};
use crate::msg;
use std::io;
use std::sync::atomic::{AtomicBool, Ordering};
use std::sync::Arc;
use std::time::Instant;
use tokio::io::{AsyncRead, AsyncReadExt, AsyncWrite, AsyncWriteExt};

pub use super::sys::{serial_port, tcp_port};

/// An async byte stream a port can carry ([`AsyncPort`]).
pub trait Stream: AsyncRead + AsyncWrite + Send + Unpin {}
impl<T: AsyncRead + AsyncWrite + Send + Unpin> Stream for T {}

/// How much a read may take at once (a Modbus frame is at most 260 bytes).
pub(crate) const CHUNK: usize = 512;

/// One connection's bytes, both ways, within deadlines.
pub trait Port: Send {
    /// Writes the whole frame.
    fn send(&mut self, frame: &[u8], deadline: Instant) -> io::Result<()>;
    /// Appends at least one received byte to `buf`: `TimedOut` at the deadline,
    /// `UnexpectedEof` when the peer closed the connection.
    fn recv(&mut self, buf: &mut Vec<u8>, deadline: Instant) -> io::Result<()>;
    /// Raises `flag` when the peer closes the connection.
    fn watch_eof(&mut self, _flag: Arc<AtomicBool>) {}
}

pub(crate) fn timed_out() -> io::Error {
    io::Error::new(io::ErrorKind::TimedOut, msg!("link-no-reply-timeout").text)
}

/// An async stream the caller opened (any transport, an in-memory pipe in tests), polled on
/// a runtime of its own; traced as [`Traced`] traces.
pub struct AsyncPort {
    stream: Traced<Box<dyn Stream>>,
    rt: tokio::runtime::Runtime,
}

impl AsyncPort {
    pub fn new(stream: Box<dyn Stream>, link: &str, proto: Proto, peer: &str) -> io::Result<AsyncPort> {
        let rt = tokio::runtime::Builder::new_current_thread().enable_all().build()?;
        Ok(AsyncPort { stream: Traced::with_proto(stream, link, proto, peer), rt })
    }
}

impl Port for AsyncPort {
    fn send(&mut self, frame: &[u8], deadline: Instant) -> io::Result<()> {
        let s = &mut self.stream;
        self.rt.block_on(async {
            let io = async {
                s.write_all(frame).await?;
                s.flush().await
            };
            tokio::time::timeout_at(deadline.into(), io).await.unwrap_or_else(|_| Err(timed_out()))
        })
    }

    fn recv(&mut self, buf: &mut Vec<u8>, deadline: Instant) -> io::Result<()> {
        let s = &mut self.stream;
        buf.reserve(CHUNK);
        self.rt.block_on(async {
            match tokio::time::timeout_at(deadline.into(), s.read_buf(buf)).await {
                Err(_) => Err(timed_out()),
                Ok(Ok(0)) => Err(io::Error::new(io::ErrorKind::UnexpectedEof, msg!("link-connection-closed").text)),
                Ok(r) => r.map(|_| ()),
            }
        })
    }
}

/// Ends a port's `recv`: `buf` keeps what the read `r` put after `old` (nothing on an error),
/// and what came is traced.
pub(crate) fn received(
    buf: &mut Vec<u8>,
    old: usize,
    r: io::Result<usize>,
    link: &str,
    proto: Proto,
) -> io::Result<()> {
    buf.truncate(old + *r.as_ref().unwrap_or(&0));
    let n = r?;
    trace::frame_proto(link, proto, Dir::Received, &buf[old..old + n]);
    Ok(())
}

/// Any [`Transport`] as a deadline port, traced and watched for the peer closing.
pub struct TransportPort {
    t: Box<dyn Transport>,
    link: Arc<str>,
    proto: Proto,
    eof: Option<Arc<AtomicBool>>,
}

impl TransportPort {
    /// Takes the transport over and reports the connection to `peer` as opened.
    pub fn new(t: Box<dyn Transport>, link: &str, proto: Proto, peer: &str) -> TransportPort {
        trace::opened(link, proto, peer);
        TransportPort { t, link: link.into(), proto, eof: None }
    }
}

impl Drop for TransportPort {
    fn drop(&mut self) {
        trace::closed(&self.link);
    }
}

impl Port for TransportPort {
    fn send(&mut self, frame: &[u8], _deadline: Instant) -> io::Result<()> {
        self.t.send(frame)?;
        trace::frame_proto(&self.link, self.proto, Dir::Sent, frame);
        Ok(())
    }

    fn recv(&mut self, buf: &mut Vec<u8>, deadline: Instant) -> io::Result<()> {
        let old = buf.len();
        buf.resize(old + CHUNK, 0);
        let r = loop {
            let left = deadline.saturating_duration_since(Instant::now());
            if left.is_zero() {
                break Err(timed_out());
            }
            match self.t.recv(&mut buf[old..], left) {
                Ok(0) => continue, // the deadline is checked above
                Ok(n) => break Ok(n),
                Err(e) if e.kind() == io::ErrorKind::UnexpectedEof => {
                    if let Some(f) = &self.eof {
                        f.store(true, Ordering::Relaxed);
                    }
                    break Err(e);
                }
                Err(e) => break Err(e),
            }
        };
        received(buf, old, r, &self.link, self.proto)
    }

    fn watch_eof(&mut self, flag: Arc<AtomicBool>) {
        self.eof = Some(flag);
    }
}
