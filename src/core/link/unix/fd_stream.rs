//! A lean async byte stream over a file descriptor (a serial port, a pty), for request/reply
//! protocols with one request in flight.
//!
//! Why not `tokio_serial::SerialStream`: it registers the descriptor for both readable and
//! writable events, so on a tty every reply the other side reads wakes this side up once
//! more for nothing (an EPOLLOUT edge), and its `flush` is `tcdrain`, one more system call
//! per frame. Here the descriptor is registered for reading only, a write goes straight to
//! the descriptor, and `flush` is a no-op (the reply is what tells a master its request went
//! out). The owner value is kept inside, so its `Drop` still runs.
//!
//! A write that finds the output buffer full means nobody reads the other side (a pty client
//! that stopped reading, or closed the port while the server holds the slave): a line would
//! carry the bytes away regardless, so the stream drops what the client has not read (a
//! flush of the slave's input, [`FdStream::dropping_unread`]) and writes again; if it is
//! still full, the frame is lost, as on a line. It never waits for the client and never
//! spins. A stream without a slave to flush waits for room by timer (1 ms steps).

use std::future::Future;
use std::io;
use std::os::fd::AsRawFd;
use std::pin::Pin;
use std::task::{Context, Poll};
use tokio::io::unix::AsyncFd;
use tokio::io::{AsyncRead, AsyncWrite, Interest, ReadBuf};

/// Puts the descriptor `owner` holds in non-blocking mode.
pub(crate) fn set_nonblocking<T: AsRawFd>(owner: &T) -> io::Result<()> {
    let raw = owner.as_raw_fd();
    // SAFETY: fcntl on a descriptor `owner` keeps open for as long as it lives.
    let ok = unsafe {
        let flags = nix::libc::fcntl(raw, nix::libc::F_GETFL);
        flags >= 0 && nix::libc::fcntl(raw, nix::libc::F_SETFL, flags | nix::libc::O_NONBLOCK) >= 0
    };
    if ok {
        Ok(())
    } else {
        Err(io::Error::last_os_error())
    }
}

/// An async stream over the descriptor of `T`.
pub struct FdStream<T: AsRawFd> {
    fd: AsyncFd<T>,
    /// The pty's slave, flushed when the client does not read.
    unread: Option<std::fs::File>,
    /// The timer a full buffer waits on when there is no slave to flush.
    retry: Option<std::pin::Pin<Box<tokio::time::Sleep>>>,
}

impl<T: AsRawFd> FdStream<T> {
    /// Puts the descriptor in non-blocking mode and registers it with the current tokio
    /// runtime (call inside one).
    pub fn new(owner: T) -> io::Result<FdStream<T>> {
        set_nonblocking(&owner)?;
        // SAFETY: `owner` owns a valid descriptor and keeps it open, unreplaced, for as long
        // as the AsyncFd holds it.
        Ok(FdStream {
            fd: unsafe { AsyncFd::register_with_interest(owner, Interest::READABLE)? },
            unread: None,
            retry: None,
        })
    }

    /// On a full output buffer, flushes what the client has not read from `slave` (the
    /// pty's other side) instead of waiting for it.
    pub fn dropping_unread(mut self, slave: std::fs::File) -> FdStream<T> {
        self.unread = Some(slave);
        self
    }

    pub fn get_ref(&self) -> &T {
        self.fd.get_ref()
    }
}

impl<T: AsRawFd> std::fmt::Debug for FdStream<T> {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        write!(f, "FdStream(fd {})", self.fd.get_ref().as_raw_fd())
    }
}

impl<T: AsRawFd + Unpin> AsyncRead for FdStream<T> {
    fn poll_read(self: Pin<&mut Self>, cx: &mut Context<'_>, buf: &mut ReadBuf<'_>) -> Poll<io::Result<()>> {
        loop {
            let mut guard = std::task::ready!(self.fd.poll_read_ready(cx))?;
            let unfilled = buf.initialize_unfilled();
            let r = guard.try_io(|inner| {
                // SAFETY: reading into an initialised buffer of the given length.
                let n = unsafe {
                    nix::libc::read(inner.get_ref().as_raw_fd(), unfilled.as_mut_ptr().cast(), unfilled.len())
                };
                if n < 0 {
                    Err(io::Error::last_os_error())
                } else {
                    Ok(n as usize)
                }
            });
            match r {
                Ok(Ok(n)) => {
                    buf.advance(n);
                    return Poll::Ready(Ok(()));
                }
                Ok(Err(e)) => return Poll::Ready(Err(e)),
                Err(_would_block) => continue,
            }
        }
    }
}

impl<T: AsRawFd + Unpin> AsyncWrite for FdStream<T> {
    fn poll_write(mut self: Pin<&mut Self>, cx: &mut Context<'_>, buf: &[u8]) -> Poll<io::Result<usize>> {
        let mut flushed = false;
        loop {
            // SAFETY: writing from a valid buffer of the given length.
            let n = unsafe { nix::libc::write(self.fd.get_ref().as_raw_fd(), buf.as_ptr().cast(), buf.len()) };
            if n >= 0 {
                self.retry = None;
                return Poll::Ready(Ok(n as usize));
            }
            let e = io::Error::last_os_error();
            match e.kind() {
                io::ErrorKind::Interrupted => continue,
                io::ErrorKind::WouldBlock => {}
                _ => return Poll::Ready(Err(e)),
            }
            if let Some(slave) = &self.unread {
                if flushed {
                    // Still full right after a flush: nobody reads; the frame is lost.
                    return Poll::Ready(Ok(buf.len()));
                }
                let _ = nix::sys::termios::tcflush(slave, nix::sys::termios::FlushArg::TCIFLUSH);
                flushed = true;
                continue;
            }
            let retry =
                self.retry.get_or_insert_with(|| Box::pin(tokio::time::sleep(std::time::Duration::from_millis(1))));
            std::task::ready!(retry.as_mut().poll(cx));
            self.retry = None;
        }
    }
    fn poll_flush(self: Pin<&mut Self>, _cx: &mut Context<'_>) -> Poll<io::Result<()>> {
        Poll::Ready(Ok(()))
    }
    fn poll_shutdown(self: Pin<&mut Self>, _cx: &mut Context<'_>) -> Poll<io::Result<()>> {
        Poll::Ready(Ok(()))
    }
}

#[cfg(test)]
mod tests {
    use super::super::pty::Pty;
    use super::*;
    use std::io::{Read, Write};
    use tokio::io::{AsyncReadExt, AsyncWriteExt};

    #[test]
    fn frames_cross_a_pty_both_ways() {
        let rt = tokio::runtime::Builder::new_current_thread().enable_all().build().unwrap();
        let mut p = Pty::open().unwrap();
        let client = std::fs::OpenOptions::new().read(true).write(true).open(&p.path).unwrap();
        rt.block_on(async {
            let mut s = FdStream::new(client).unwrap();
            AsyncWriteExt::write_all(&mut s, &[1, 3, 0, 100, 0, 1, 0xC5, 0xD5]).await.unwrap();
            let mut got = [0u8; 8];
            p.master.read_exact(&mut got).unwrap();
            assert_eq!(got, [1, 3, 0, 100, 0, 1, 0xC5, 0xD5]);
            p.master.write_all(&[1, 3, 2, 0, 7, 0xF9, 0x86]).unwrap();
            let mut back = [0u8; 7];
            AsyncReadExt::read_exact(&mut s, &mut back).await.unwrap();
            assert_eq!(back, [1, 3, 2, 0, 7, 0xF9, 0x86]);
        });
    }
}
