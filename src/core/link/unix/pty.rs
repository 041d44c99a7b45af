//! Pseudo-terminal pairs: a simulator keeps the master side and serves a serial protocol
//! on it; any serial client (plcsh's drivers, mbpoll, a terminal program) opens the slave
//! device like a real port. The slave is put in raw mode (no echo, no line editing) and kept
//! open by the server, so the master does not see EIO between client sessions.
//!
//! The server's end is a [`Transport`] ([`Pty::served`]) that behaves like a line: a client
//! that stops reading (or closes the port) loses what the server sends meanwhile — what
//! it has not read is flushed — and the server never waits or spins on a full buffer.

use crate::core::link::line::Transport;
use crate::core::{Error, Result};
use crate::msg;
use nix::poll::{poll, PollFd, PollFlags, PollTimeout};
use nix::pty::{openpty, OpenptyResult};
use nix::sys::termios::{self, SetArg};
use std::fs::File;
use std::io::{self, Read, Write};
use std::os::fd::AsFd;
use std::path::{Path, PathBuf};
use std::time::Duration;

/// An open pseudo-terminal pair.
pub struct Pty {
    /// The server's side.
    pub(crate) master: File,
    /// Held open so the master stays readable while no client is attached.
    pub(crate) slave: File,
    /// The slave device path clients open (`/dev/pts/N`).
    pub(crate) path: PathBuf,
}

impl Pty {
    /// Opens a new pair with the slave in raw mode.
    pub fn open() -> Result<Pty> {
        let OpenptyResult { master, slave } =
            openpty(None, None).map_err(|e| Error::io(msg!("link-pty-open")).cause(e))?;
        let mut t = termios::tcgetattr(slave.as_fd())
            .map_err(|e| Error::io(msg!("link-pty-call", call = "tcgetattr")).cause(e))?;
        termios::cfmakeraw(&mut t);
        termios::tcsetattr(slave.as_fd(), SetArg::TCSANOW, &t)
            .map_err(|e| Error::io(msg!("link-pty-call", call = "tcsetattr")).cause(e))?;
        let path = nix::unistd::ttyname(slave.as_fd())
            .map_err(|e| Error::io(msg!("link-pty-call", call = "ttyname")).cause(e))?;
        Ok(Pty { master: File::from(master), slave: File::from(slave), path })
    }

    /// The slave device clients open (`/dev/pts/N`).
    pub fn path(&self) -> &Path {
        &self.path
    }

    /// The master, the slave and the slave's path, for a caller that drives the pair itself
    /// (a test's relay between two ptys).
    pub fn into_parts(self) -> (File, File, PathBuf) {
        (self.master, self.slave, self.path)
    }

    /// The server's end as a line ([`ServedPty`]).
    pub fn served(self) -> Result<ServedPty> {
        super::fd_stream::set_nonblocking(&self.master)
            .map_err(|e| Error::io(msg!("link-pty-nonblocking")).cause(e))?;
        Ok(ServedPty { pty: self })
    }

    /// Points a symlink at the slave device (replacing an old symlink at `link`; refusing
    /// to replace anything that is not a symlink).
    pub fn link(&self, link: &Path) -> Result<()> {
        if let Ok(meta) = std::fs::symlink_metadata(link) {
            if !meta.file_type().is_symlink() {
                return Err(Error::usage(msg!("link-not-symlink", path = link.display().to_string())));
            }
            std::fs::remove_file(link)?;
        }
        std::os::unix::fs::symlink(&self.path, link)
            .map_err(|e| Error::io(msg!("link-cannot-symlink", path = link.display().to_string())).cause(e))
    }
}

/// The server's end of a pty, as a line.
pub struct ServedPty {
    pty: Pty,
}

impl ServedPty {
    /// Drops what the client has not read (what a line does with bytes nobody listens to).
    fn drop_unread(&self) {
        let _ = termios::tcflush(self.pty.slave.as_fd(), termios::FlushArg::TCIFLUSH);
    }
}

impl Transport for ServedPty {
    fn send(&mut self, mut bytes: &[u8]) -> io::Result<()> {
        let mut flushed = false;
        while !bytes.is_empty() {
            match self.pty.master.write(bytes) {
                Ok(n) => bytes = &bytes[n..],
                Err(e) if e.kind() == io::ErrorKind::Interrupted => {}
                Err(e) if e.kind() == io::ErrorKind::WouldBlock && !flushed => {
                    self.drop_unread();
                    flushed = true;
                }
                // Still full right after a flush: nobody reads; the rest is lost, as on a line.
                Err(e) if e.kind() == io::ErrorKind::WouldBlock => return Ok(()),
                Err(e) => return Err(e),
            }
        }
        Ok(())
    }

    fn recv(&mut self, buf: &mut [u8], timeout: Duration) -> io::Result<usize> {
        let ms = PollTimeout::try_from(timeout.as_micros().div_ceil(1000).min(i32::MAX as u128) as i32)
            .unwrap_or(PollTimeout::MAX);
        let mut fds = [PollFd::new(self.pty.master.as_fd(), PollFlags::POLLIN)];
        match poll(&mut fds, ms) {
            Ok(0) | Err(nix::errno::Errno::EINTR) => return Ok(0),
            Ok(_) => {}
            Err(e) => return Err(io::Error::from(e)),
        }
        match self.pty.master.read(buf) {
            Ok(n) => Ok(n),
            Err(e) if matches!(e.kind(), io::ErrorKind::WouldBlock | io::ErrorKind::Interrupted) => Ok(0),
            // EIO: no client has the slave open right now (the server holds it, so rarely).
            Err(e) if e.raw_os_error() == Some(libc::EIO) => {
                std::thread::sleep(timeout.min(Duration::from_millis(10)));
                Ok(0)
            }
            Err(e) => Err(e),
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn bytes_cross_the_pair_unchanged() {
        let mut p = Pty::open().unwrap();
        let mut client = std::fs::OpenOptions::new().read(true).write(true).open(&p.path).unwrap();
        // Raw mode: binary bytes, including CR, LF and 0x03 (^C), pass untouched.
        let frame = [0x01u8, 0x2B, 0x40, 0x60, 0x00, 0x0F, 0x0D, 0x0A, 0x03, 0x25];
        client.write_all(&frame).unwrap();
        let mut got = [0u8; 10];
        p.master.read_exact(&mut got).unwrap();
        assert_eq!(got, frame);
        p.master.write_all(&frame).unwrap();
        let mut back = [0u8; 10];
        client.read_exact(&mut back).unwrap();
        assert_eq!(back, frame);
    }

    #[test]
    fn link_points_at_the_device_and_refuses_regular_files() {
        let p = Pty::open().unwrap();
        let dir = std::env::temp_dir().join(format!("plcsh-pty-test-{}", std::process::id()));
        std::fs::create_dir_all(&dir).unwrap();
        let link = dir.join("port");
        p.link(&link).unwrap();
        p.link(&link).unwrap();
        assert_eq!(std::fs::read_link(&link).unwrap(), p.path);
        let file = dir.join("plain");
        std::fs::write(&file, b"x").unwrap();
        assert!(p.link(&file).is_err());
        let _ = std::fs::remove_dir_all(&dir);
    }
}

#[cfg(test)]
mod served_tests {
    use super::*;
    use std::time::Instant;

    /// A client that sends requests and never reads costs the server no waiting and no
    /// spinning: every send returns at once, the unread replies are dropped.
    #[test]
    fn a_client_that_never_reads_costs_the_server_nothing() {
        let pty = Pty::open().unwrap();
        let mut client = std::fs::OpenOptions::new().read(true).write(true).open(pty.path()).unwrap();
        let mut served = pty.served().unwrap();
        let start = Instant::now();
        let reply = [0x55u8; 256];
        let mut buf = [0u8; 64];
        for i in 0..1000 {
            client.write_all(&[i as u8; 8]).unwrap();
            assert!(served.recv(&mut buf, Duration::from_secs(5)).unwrap() > 0);
            served.send(&reply).unwrap();
        }
        assert!(start.elapsed() < Duration::from_secs(5), "1000 unread replies took {:?}", start.elapsed());
        drop(client);
        // After the client closed: sending still returns at once.
        let t = Instant::now();
        for _ in 0..100 {
            served.send(&reply).unwrap();
        }
        assert!(t.elapsed() < Duration::from_secs(1), "{:?}", t.elapsed());
    }
}
