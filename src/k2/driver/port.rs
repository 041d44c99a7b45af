//! The byte transport under the driver's Modbus client: a descriptor (a TCP socket, a serial
//! port) driven with plain system calls, or an async stream handed over by the caller.
//!
//! Why plain system calls: the driver has one request in flight and nothing else to do while
//! it waits, so an async runtime only adds work per request (entering the runtime, a timer
//! in its wheel, an `epoll_wait` and the bookkeeping around it). Here a request is a
//! `write`, and each piece of the reply a `poll` with the time left and a `read` — what
//! libmodbus does with `select` and `recv`. And a one-shot command does not build a runtime.
//!
//! Every frame written and every piece read is reported to [`crate::core::trace`] as the
//! traced async streams report theirs (`core::link::traced`), and a peer closing the
//! connection raises the driver's flag.

use super::client::Stream;
use crate::core::link::traced::Traced;
use crate::core::trace::{self, Dir, Proto};
use std::io;
use std::os::fd::{AsRawFd, BorrowedFd};
use std::sync::atomic::{AtomicBool, Ordering};
use std::sync::Arc;
use std::time::Instant;
use tokio::io::{AsyncReadExt, AsyncWriteExt};

/// How much a read may take at once (a Modbus frame is at most 260 bytes).
const CHUNK: usize = 512;

/// One connection's bytes, both ways, within deadlines.
pub trait Port: Send {
    /// Writes the whole frame.
    fn send(&mut self, frame: &[u8], deadline: Instant) -> io::Result<()>;
    /// Appends at least one received byte to `buf`: `TimedOut` at the deadline,
    /// `UnexpectedEof` when the peer closed the connection.
    fn recv(&mut self, buf: &mut Vec<u8>, deadline: Instant) -> io::Result<()>;
}

fn timed_out() -> io::Error {
    io::Error::new(io::ErrorKind::TimedOut, "no reply within the timeout")
}

/// A descriptor owned by `T` (a `TcpStream`, a `serialport::TTYPort`, whose `Drop` releases
/// the port), in non-blocking mode.
pub struct FdPort<T: AsRawFd + Send> {
    owner: T,
    link: Arc<str>,
    proto: Proto,
    eof: Option<Arc<AtomicBool>>,
}

impl<T: AsRawFd + Send> FdPort<T> {
    /// Takes the descriptor over and reports the connection to `peer` as opened.
    pub fn new(owner: T, link: &str, proto: Proto, peer: &str) -> io::Result<FdPort<T>> {
        crate::core::link::fd_stream::set_nonblocking(&owner)?;
        trace::opened(link, proto, peer);
        Ok(FdPort { owner, link: link.into(), proto, eof: None })
    }

    /// Raises `flag` when the peer closes the connection.
    pub fn watch_eof(mut self, flag: Arc<AtomicBool>) -> FdPort<T> {
        self.eof = Some(flag);
        self
    }

    fn fd(&self) -> BorrowedFd<'_> {
        // SAFETY: `owner` keeps the descriptor open for as long as it (and so `self`) lives.
        unsafe { BorrowedFd::borrow_raw(self.owner.as_raw_fd()) }
    }

    /// Waits until the descriptor is ready for `events` or the deadline passes.
    fn wait(&self, events: nix::poll::PollFlags, deadline: Instant) -> io::Result<()> {
        loop {
            let left = deadline.saturating_duration_since(Instant::now());
            if left.is_zero() {
                return Err(timed_out());
            }
            // Round up, so a wait never ends before the deadline.
            let ms = u16::try_from(left.as_micros().div_ceil(1000)).unwrap_or(u16::MAX);
            let mut fds = [nix::poll::PollFd::new(self.fd(), events)];
            match nix::poll::poll(&mut fds, nix::poll::PollTimeout::from(ms)) {
                Ok(0) => continue, // the deadline is checked above
                Ok(_) => return Ok(()),
                Err(nix::errno::Errno::EINTR) => continue,
                Err(e) => return Err(e.into()),
            }
        }
    }
}

impl<T: AsRawFd + Send> Drop for FdPort<T> {
    fn drop(&mut self) {
        trace::closed(&self.link);
    }
}

impl<T: AsRawFd + Send> Port for FdPort<T> {
    fn send(&mut self, frame: &[u8], deadline: Instant) -> io::Result<()> {
        let mut at = 0;
        while at < frame.len() {
            match nix::unistd::write(self.fd(), &frame[at..]) {
                Ok(n) => at += n,
                Err(nix::errno::Errno::EAGAIN) => self.wait(nix::poll::PollFlags::POLLOUT, deadline)?,
                Err(nix::errno::Errno::EINTR) => {}
                Err(e) => return Err(e.into()),
            }
        }
        trace::frame_proto(&self.link, self.proto, Dir::Sent, frame);
        Ok(())
    }

    fn recv(&mut self, buf: &mut Vec<u8>, deadline: Instant) -> io::Result<()> {
        let old = buf.len();
        buf.resize(old + CHUNK, 0);
        let r = loop {
            if let Err(e) = self.wait(nix::poll::PollFlags::POLLIN, deadline) {
                break Err(e);
            }
            match nix::unistd::read(self.fd(), &mut buf[old..]) {
                Ok(0) => {
                    if let Some(f) = &self.eof {
                        f.store(true, Ordering::Relaxed);
                    }
                    break Err(io::Error::new(io::ErrorKind::UnexpectedEof, "the connection closed"));
                }
                Ok(n) => break Ok(n),
                Err(nix::errno::Errno::EAGAIN | nix::errno::Errno::EINTR) => {}
                Err(e) => break Err(e.into()),
            }
        };
        buf.truncate(old + *r.as_ref().unwrap_or(&0));
        let n = r?;
        trace::frame_proto(&self.link, self.proto, Dir::Received, &buf[old..old + n]);
        Ok(())
    }
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
                Ok(Ok(0)) => Err(io::Error::new(io::ErrorKind::UnexpectedEof, "the connection closed")),
                Ok(r) => r.map(|_| ()),
            }
        })
    }
}
