//! Where a serial family's simulator is served: on a new pseudo-terminal (Unix; clients open
//! its slave device, or the symlink given) or on a TCP port (every system; clients connect
//! with `…+tcp://HOST:PORT`, as to a serial device server). Either way the serve loop gets
//! one [`Transport`] that behaves like the device's end of a line.

use super::pty::Pty;
use super::tcp::ServedTcp;
use super::transport::Transport;
use crate::core::Result;
use std::net::SocketAddr;
use std::path::{Path, PathBuf};

/// Where to serve.
#[derive(Clone, Debug)]
pub enum ServeOn {
    /// A new pseudo-terminal, with a symlink to its slave at the path if one is given.
    Pty(Option<PathBuf>),
    /// A TCP port (port 0 picks a free one).
    Tcp(SocketAddr),
}

impl ServeOn {
    /// The name traces and state files use for this endpoint.
    pub fn name(&self) -> String {
        match self {
            ServeOn::Pty(Some(l)) => l.display().to_string(),
            ServeOn::Pty(None) => "pty".to_string(),
            ServeOn::Tcp(a) => format!("tcp://{a}"),
        }
    }
}

/// A pty endpoint as every family's readiness line names it (`rtu_pty`, `servo_pty`, `fx_pty`,
/// `fx_link_pty`, `umpk_pty`: one shape): the slave device and the symlink to it, if any.
#[derive(Clone, Debug, serde::Serialize)]
pub struct PtyReady {
    pub path: PathBuf,
    pub link: Option<PathBuf>,
}

/// An open endpoint: the line, and what clients need to reach it.
pub struct Served {
    pub line: Box<dyn Transport>,
    /// The pty's slave device (`/dev/pts/N`), when served on a pty.
    pub pty: Option<PathBuf>,
    /// The symlink to it, when one was asked for (removed when this is dropped).
    pub link: Option<PathBuf>,
    /// The bound address, when served on TCP.
    pub tcp: Option<SocketAddr>,
}

impl Served {
    /// The readiness line's field for a pty endpoint (`None` on TCP).
    pub fn pty_ready(&self) -> Option<PtyReady> {
        self.pty.clone().map(|path| PtyReady { path, link: self.link.clone() })
    }

    /// Opens the endpoint.
    pub fn open(on: &ServeOn) -> Result<Served> {
        match on {
            ServeOn::Pty(link) => {
                let pty = Pty::open()?;
                if let Some(l) = link {
                    pty.link(l)?;
                }
                let path = pty.path().to_path_buf();
                Ok(Served { line: Box::new(pty.served()?), pty: Some(path), link: link.clone(), tcp: None })
            }
            ServeOn::Tcp(addr) => {
                let t = ServedTcp::bind(*addr)?;
                let local = t.local_addr();
                Ok(Served { line: Box::new(t), pty: None, link: None, tcp: Some(local) })
            }
        }
    }

    /// The name clients use: the link, the pty device, or `tcp://ADDR`.
    pub fn name(&self) -> String {
        match (&self.link, &self.pty, &self.tcp) {
            (Some(l), _, _) => l.display().to_string(),
            (None, Some(p), _) => p.display().to_string(),
            (_, _, Some(a)) => format!("tcp://{a}"),
            _ => String::new(),
        }
    }

    /// The symlink, if any.
    pub fn link_path(&self) -> Option<&Path> {
        self.link.as_deref()
    }
}

impl Drop for Served {
    fn drop(&mut self) {
        if let Some(l) = &self.link {
            let _ = std::fs::remove_file(l);
        }
    }
}
