//! A lean async byte stream over a file descriptor (a serial port, a pty), for request/reply
//! protocols with one request in flight.
//!
//! Why not `tokio_serial::SerialStream`: it registers the descriptor for both readable and
//! writable events, so on a tty every reply the other side reads wakes this side up once
//! more for nothing (an EPOLLOUT edge), and its `flush` is `tcdrain`, one more system call
//! per frame. Here the descriptor is registered for reading only, a write goes straight to
//! the descriptor, and `flush` is a no-op (the reply is what tells a master its request went
//! out). A write that finds the tty's output buffer full (kilobytes; a Modbus frame is at
//! most 256 bytes) yields and tries again. The owner value (e.g. a `serialport::TTYPort`)
//! is kept inside, so its `Drop` (release of exclusive access) still runs.

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
}

impl<T: AsRawFd> FdStream<T> {
    /// Puts the descriptor in non-blocking mode and registers it with the current tokio
    /// runtime (call inside one).
    pub fn new(owner: T) -> io::Result<FdStream<T>> {
        set_nonblocking(&owner)?;
        // SAFETY: `owner` owns a valid descriptor and keeps it open, unreplaced, for as long
        // as the AsyncFd holds it.
        Ok(FdStream { fd: unsafe { AsyncFd::register_with_interest(owner, Interest::READABLE)? } })
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
    fn poll_write(self: Pin<&mut Self>, cx: &mut Context<'_>, buf: &[u8]) -> Poll<io::Result<usize>> {
        // SAFETY: writing from a valid buffer of the given length.
        let n = unsafe { nix::libc::write(self.fd.get_ref().as_raw_fd(), buf.as_ptr().cast(), buf.len()) };
        if n >= 0 {
            return Poll::Ready(Ok(n as usize));
        }
        let e = io::Error::last_os_error();
        if e.kind() == io::ErrorKind::WouldBlock || e.kind() == io::ErrorKind::Interrupted {
            // Output buffer full: rare with one small frame in flight; try again shortly.
            cx.waker().wake_by_ref();
            return Poll::Pending;
        }
        Poll::Ready(Err(e))
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
    use super::*;
    use crate::core::link::pty::Pty;
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
