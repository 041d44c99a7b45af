//! An in-process byte pipe: two [`Transport`] ends joined in memory. Tests put a driver on
//! one end and a simulator's serve loop (or a scripted responder) on the other, on every
//! operating system (a socket pair or a pty exists only on some).

use super::transport::Transport;
use crate::msg;
use std::collections::VecDeque;
use std::io;
use std::sync::{Arc, Condvar, Mutex};
use std::time::{Duration, Instant};

/// One direction of the pipe.
#[derive(Default)]
struct Queue {
    bytes: Mutex<(VecDeque<u8>, bool)>,
    ready: Condvar,
}

/// One end of a pipe made by [`pair`].
pub struct PipeEnd {
    rx: Arc<Queue>,
    tx: Arc<Queue>,
}

/// Two ends: what one sends, the other receives.
pub fn pair() -> (PipeEnd, PipeEnd) {
    let (a, b) = (Arc::new(Queue::default()), Arc::new(Queue::default()));
    (PipeEnd { rx: a.clone(), tx: b.clone() }, PipeEnd { rx: b, tx: a })
}

impl Drop for PipeEnd {
    /// The other end then reads end of file once it has read what was sent.
    fn drop(&mut self) {
        let mut q = self.tx.bytes.lock().unwrap_or_else(|p| p.into_inner());
        q.1 = true;
        self.tx.ready.notify_all();
    }
}

impl Transport for PipeEnd {
    fn send(&mut self, bytes: &[u8]) -> io::Result<()> {
        let mut q = self.tx.bytes.lock().unwrap_or_else(|p| p.into_inner());
        q.0.extend(bytes);
        self.tx.ready.notify_all();
        Ok(())
    }

    fn recv(&mut self, buf: &mut [u8], timeout: Duration) -> io::Result<usize> {
        let end = Instant::now() + timeout;
        let mut q = self.rx.bytes.lock().unwrap_or_else(|p| p.into_inner());
        loop {
            if !q.0.is_empty() {
                let n = buf.len().min(q.0.len());
                for (slot, b) in buf.iter_mut().zip(q.0.drain(..n)) {
                    *slot = b;
                }
                return Ok(n);
            }
            if q.1 {
                return Err(io::Error::new(io::ErrorKind::UnexpectedEof, msg!("link-pipe-closed").text));
            }
            let left = end.saturating_duration_since(Instant::now());
            if left.is_zero() {
                return Ok(0);
            }
            q = self.rx.ready.wait_timeout(q, left).unwrap_or_else(|p| p.into_inner()).0;
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn bytes_cross_both_ways_and_a_closed_end_reads_eof() {
        let (mut a, mut b) = pair();
        a.send(&[1, 2, 3]).unwrap();
        let mut buf = [0u8; 8];
        assert_eq!(b.recv(&mut buf, Duration::from_secs(1)).unwrap(), 3);
        assert_eq!(&buf[..3], &[1, 2, 3]);
        assert_eq!(a.recv(&mut buf, Duration::from_millis(5)).unwrap(), 0, "nothing sent: a timeout");
        let t = std::thread::spawn(move || {
            b.send(&[9]).unwrap();
        });
        assert_eq!(a.recv(&mut buf, Duration::from_secs(5)).unwrap(), 1);
        t.join().unwrap();
        assert_eq!(a.recv(&mut buf, Duration::from_secs(1)).unwrap_err().kind(), io::ErrorKind::UnexpectedEof);
    }
}
