//! The byte stream every transport offers: "send these bytes" and "give me what arrives within
//! this time". Serial ports, raw TCP, RFC 2217, a served pty's master and in-process pipes all
//! implement it, and the shared line ([`super::line`]) holds one; it sits in a file of its own,
//! below all of them, so the transports and the line that shares them never name each other.

use std::io;
use std::sync::Arc;
use std::time::Duration;

/// A byte stream with receive timeouts.
pub trait Transport: Send {
    /// Sends all of `bytes`.
    fn send(&mut self, bytes: &[u8]) -> io::Result<()>;
    /// Receives what arrives within `timeout` (at least one byte), or `Ok(0)` when nothing did.
    fn recv(&mut self, buf: &mut [u8], timeout: Duration) -> io::Result<usize>;
    /// Drops bytes already received but not read (a late reply after a timeout).
    fn discard_input(&mut self) -> io::Result<()> {
        let mut scratch = [0u8; 64];
        while self.recv(&mut scratch, Duration::ZERO)? > 0 {}
        Ok(())
    }
    /// Waits until the line has been quiet for `gap` (at most `limit` in all), dropping what
    /// arrives meanwhile: a late reply to an earlier request, or a tail of noise, must not be
    /// read as the reply to the next one. Returns the number of bytes dropped.
    fn settle(&mut self, gap: Duration, limit: Duration) -> io::Result<usize> {
        let end = std::time::Instant::now() + limit;
        let mut scratch = [0u8; 256];
        let mut dropped = 0;
        loop {
            let left = end.saturating_duration_since(std::time::Instant::now());
            if left.is_zero() {
                return Ok(dropped);
            }
            match self.recv(&mut scratch, gap.min(left))? {
                0 => return Ok(dropped),
                n => dropped += n,
            }
        }
    }
    /// The in-process simulator behind this transport, when there is one (the servo
    /// simulator's line, reached by downcasting).
    fn sim_line(&self) -> Option<Arc<dyn std::any::Any + Send + Sync>> {
        None
    }
}
