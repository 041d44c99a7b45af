//! The master side of a [`Pty`] as a tokio stream, for servers that answer a serial
//! protocol on a pseudo-terminal (the K2 simulator's Modbus RTU server, a servo simulator).
//!
//! The stream is an [`FdStream`] (`AsyncRead + AsyncWrite`, registered for reading only:
//! see its module for why). Each call to [`AsyncPty::stream`] wraps a fresh duplicate of the
//! master descriptor, so a server whose stream ended on an error can start again on the same
//! pty without the clients noticing. The slave stays open for as long as the `AsyncPty` lives, so the
//! master never reads EIO between client sessions. A client that stops reading loses replies
//! instead of making the server wait or spin ([`FdStream::dropping_unread`]).

use super::fd_stream::FdStream;
use super::pty::Pty;
use crate::core::{Error, Result};
use crate::msg;
use std::fs::File;
use std::path::Path;

/// The master side as an async stream.
pub type PtyStream = FdStream<File>;

/// A pseudo-terminal whose master side is served asynchronously.
pub struct AsyncPty {
    pty: Pty,
}

impl AsyncPty {
    /// Opens a new pair (slave in raw mode).
    pub fn open() -> Result<AsyncPty> {
        Ok(AsyncPty { pty: Pty::open()? })
    }

    pub fn from_pty(pty: Pty) -> AsyncPty {
        AsyncPty { pty }
    }

    /// The slave device clients open (`/dev/pts/N`).
    pub fn path(&self) -> &Path {
        self.pty.path()
    }

    /// Points a symlink at the slave device (see [`Pty::link`]).
    pub fn link(&self, link: &Path) -> Result<()> {
        self.pty.link(link)
    }

    /// A new async stream on the master side. Must be called inside a tokio runtime.
    pub fn stream(&self) -> Result<PtyStream> {
        let fd = self.pty.master.try_clone().map_err(|e| Error::io(msg!("link-pty-dup-master")).cause(e))?;
        let slave = self.pty.slave.try_clone().map_err(|e| Error::io(msg!("link-pty-dup-slave")).cause(e))?;
        FdStream::new(fd).map(|s| s.dropping_unread(slave)).map_err(|e| Error::io(msg!("link-pty-register")).cause(e))
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use std::io::{Read, Write};
    use tokio::io::{AsyncReadExt, AsyncWriteExt};

    #[test]
    fn bytes_cross_the_async_master() {
        let rt = tokio::runtime::Builder::new_current_thread().enable_all().build().unwrap();
        let p = AsyncPty::open().unwrap();
        let mut client = std::fs::OpenOptions::new().read(true).write(true).open(p.path()).unwrap();
        rt.block_on(async {
            let mut m = p.stream().unwrap();
            client.write_all(&[1, 3, 0, 100, 0, 1, 0xC5, 0xD5]).unwrap();
            let mut got = [0u8; 8];
            AsyncReadExt::read_exact(&mut m, &mut got).await.unwrap();
            assert_eq!(got, [1, 3, 0, 100, 0, 1, 0xC5, 0xD5]);
            AsyncWriteExt::write_all(&mut m, &[0x0D, 0x0A, 0x03]).await.unwrap();
            drop(m);
            // A second stream on the same pty works after the first is gone.
            let mut m2 = p.stream().unwrap();
            AsyncWriteExt::write_all(&mut m2, &[7]).await.unwrap();
        });
        let mut back = [0u8; 4];
        client.read_exact(&mut back).unwrap();
        assert_eq!(back, [0x0D, 0x0A, 0x03, 7]);
    }
}
