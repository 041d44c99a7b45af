//! A byte stream that reports what crosses it to [`crate::core::trace`], so `-vv` shows the
//! frames of drivers built on protocol stacks that do not expose their frames (tokio-modbus).
//!
//! Each write a driver makes is one frame (the stacks write a whole frame at once); reads
//! are reported as they arrive, so a reply the operating system delivers in two pieces
//! shows as two lines. When tracing is off a report costs one atomic load.
//!
//! A stream made with [`Traced::with_proto`] also tells the recorder its protocol and when
//! the connection opens and closes (dropping the stream closes it).

use crate::core::trace::{self, Dir, Proto};
use std::fmt;
use std::io;
use std::pin::Pin;
use std::sync::atomic::{AtomicBool, Ordering};
use std::sync::Arc;
use std::task::{Context, Poll};
use tokio::io::{AsyncRead, AsyncWrite, ReadBuf};

/// A stream whose traffic is traced under the name `link`.
pub struct Traced<T> {
    inner: T,
    link: Arc<str>,
    proto: Proto,
    /// Set when the peer closes the stream (a read returns end of file): protocol stacks
    /// that report that badly (tokio-modbus's TCP client) can then be diagnosed by the driver.
    eof: Option<Arc<AtomicBool>>,
}

impl<T> Traced<T> {
    pub fn new(inner: T, link: impl Into<Arc<str>>) -> Traced<T> {
        Traced { inner, link: link.into(), proto: Proto::Unknown, eof: None }
    }

    /// A stream carrying `proto` to `peer`; reports the connection as opened.
    pub fn with_proto(inner: T, link: impl Into<Arc<str>>, proto: Proto, peer: &str) -> Traced<T> {
        let link = link.into();
        trace::opened(&link, proto, peer);
        Traced { inner, link, proto, eof: None }
    }

    /// Raises `flag` when the peer closes the stream.
    pub fn watch_eof(mut self, flag: Arc<AtomicBool>) -> Traced<T> {
        self.eof = Some(flag);
        self
    }
}

impl<T> Drop for Traced<T> {
    fn drop(&mut self) {
        if self.proto != Proto::Unknown {
            trace::closed(&self.link);
        }
    }
}

impl<T> fmt::Debug for Traced<T> {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        write!(f, "Traced({})", self.link)
    }
}

impl<T: AsyncRead + Unpin> AsyncRead for Traced<T> {
    fn poll_read(mut self: Pin<&mut Self>, cx: &mut Context<'_>, buf: &mut ReadBuf<'_>) -> Poll<io::Result<()>> {
        let before = buf.filled().len();
        let room = buf.remaining() > 0;
        let r = Pin::new(&mut self.inner).poll_read(cx, buf);
        if let Poll::Ready(Ok(())) = r {
            let new = &buf.filled()[before..];
            if !new.is_empty() {
                trace::frame_proto(&self.link, self.proto, Dir::Received, new);
            } else if room {
                if let Some(f) = &self.eof {
                    f.store(true, Ordering::Relaxed);
                }
            }
        }
        r
    }
}

impl<T: AsyncWrite + Unpin> AsyncWrite for Traced<T> {
    fn poll_write(mut self: Pin<&mut Self>, cx: &mut Context<'_>, buf: &[u8]) -> Poll<io::Result<usize>> {
        let r = Pin::new(&mut self.inner).poll_write(cx, buf);
        if let Poll::Ready(Ok(n)) = r {
            trace::frame_proto(&self.link, self.proto, Dir::Sent, &buf[..n]);
        }
        r
    }
    fn poll_flush(mut self: Pin<&mut Self>, cx: &mut Context<'_>) -> Poll<io::Result<()>> {
        Pin::new(&mut self.inner).poll_flush(cx)
    }
    fn poll_shutdown(mut self: Pin<&mut Self>, cx: &mut Context<'_>) -> Poll<io::Result<()>> {
        Pin::new(&mut self.inner).poll_shutdown(cx)
    }
}
