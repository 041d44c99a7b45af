//! Pseudo-terminal pairs: a simulator keeps the master side and serves a serial protocol
//! on it; any serial client (plcsh's drivers, mbpoll, a terminal program) opens the slave
//! device like a real port. The slave is put in raw mode (no echo, no line editing) and kept
//! open by the server, so the master does not see EIO between client sessions.

use crate::core::{Error, Result};
use nix::pty::{openpty, OpenptyResult};
use nix::sys::termios::{self, SetArg};
use std::fs::File;
use std::os::fd::AsFd;
use std::path::{Path, PathBuf};

/// An open pseudo-terminal pair.
pub struct Pty {
    /// The server's side.
    pub master: File,
    /// Held open so the master stays readable while no client is attached.
    pub slave: File,
    /// The slave device path clients open (`/dev/pts/N`).
    pub path: PathBuf,
}

impl Pty {
    /// Opens a new pair with the slave in raw mode.
    pub fn open() -> Result<Pty> {
        let OpenptyResult { master, slave } =
            openpty(None, None).map_err(|e| Error::io("cannot open a pseudo-terminal").cause(e))?;
        let mut t = termios::tcgetattr(slave.as_fd()).map_err(|e| Error::io("tcgetattr on pty").cause(e))?;
        termios::cfmakeraw(&mut t);
        termios::tcsetattr(slave.as_fd(), SetArg::TCSANOW, &t).map_err(|e| Error::io("tcsetattr on pty").cause(e))?;
        let path = nix::unistd::ttyname(slave.as_fd()).map_err(|e| Error::io("ttyname on pty").cause(e))?;
        Ok(Pty { master: File::from(master), slave: File::from(slave), path })
    }

    /// Points a symlink at the slave device (replacing an old symlink at `link`; refusing
    /// to replace anything that is not a symlink).
    pub fn link(&self, link: &Path) -> Result<()> {
        if let Ok(meta) = std::fs::symlink_metadata(link) {
            if !meta.file_type().is_symlink() {
                return Err(Error::usage(format!(
                    "{} exists and is not a symlink; choose another path",
                    link.display()
                )));
            }
            std::fs::remove_file(link)?;
        }
        std::os::unix::fs::symlink(&self.path, link)
            .map_err(|e| Error::io(format!("cannot create the symlink {}", link.display())).cause(e))
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use std::io::{Read, Write};

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
