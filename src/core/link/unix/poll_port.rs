//! The Unix deadline port: a descriptor in non-blocking mode, each wait a `poll` with the
//! time left (see [`crate::core::link::port`] for why not an async runtime).

use crate::core::link::port::{received, timed_out, Port, CHUNK};
use crate::core::link::serial::LineSettings;
use crate::core::trace::{self, Dir, Proto};
use crate::core::{Error, Result};
use crate::msg;
use std::io;
use std::os::fd::{AsRawFd, BorrowedFd};
use std::sync::atomic::{AtomicBool, Ordering};
use std::sync::Arc;
use std::time::Instant;

/// A TCP connection as a deadline port.
pub fn tcp_port(stream: std::net::TcpStream, link: &str, proto: Proto, peer: &str) -> io::Result<Box<dyn Port>> {
    Ok(Box::new(PollPort::new(stream, link, proto, peer)?))
}

/// Opens a serial port (exclusively) as a deadline port.
pub fn serial_port(path: &str, settings: LineSettings, link: &str, proto: Proto) -> Result<Box<dyn Port>> {
    let port = crate::core::link::serial::builder(path, settings).open_native().map_err(|e| {
        Error::link(crate::msg!("link-cannot-open-port", port = path))
            .cause(e)
            .hint(crate::core::link::serial::open_hint())
    })?;
    PollPort::new(port, link, proto, path)
        .map(|p| Box::new(p) as Box<dyn Port>)
        .map_err(|e| Error::link(crate::msg!("link-cannot-use-port", port = path)).cause(e))
}

/// A descriptor owned by `T` (a `TcpStream`, a `serialport::TTYPort`, whose `Drop` releases
/// the port), in non-blocking mode.
pub struct PollPort<T: AsRawFd + Send> {
    owner: T,
    link: Arc<str>,
    proto: Proto,
    eof: Option<Arc<AtomicBool>>,
}

impl<T: AsRawFd + Send> PollPort<T> {
    /// Takes the descriptor over and reports the connection to `peer` as opened.
    pub fn new(owner: T, link: &str, proto: Proto, peer: &str) -> io::Result<PollPort<T>> {
        super::fd_stream::set_nonblocking(&owner)?;
        trace::opened(link, proto, peer);
        Ok(PollPort { owner, link: link.into(), proto, eof: None })
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

impl<T: AsRawFd + Send> Drop for PollPort<T> {
    fn drop(&mut self) {
        trace::closed(&self.link);
    }
}

impl<T: AsRawFd + Send> Port for PollPort<T> {
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
                    break Err(io::Error::new(io::ErrorKind::UnexpectedEof, msg!("link-connection-closed").text));
                }
                Ok(n) => break Ok(n),
                Err(nix::errno::Errno::EAGAIN | nix::errno::Errno::EINTR) => {}
                Err(e) => break Err(e.into()),
            }
        };
        received(buf, old, r, &self.link, self.proto)
    }

    fn watch_eof(&mut self, flag: Arc<AtomicBool>) {
        self.eof = Some(flag);
    }
}
