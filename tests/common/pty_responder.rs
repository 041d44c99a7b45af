//! An independent device on a pseudo-terminal of its own, for tests of the drivers' framing
//! and timing against something plcsh did not write: the test frames requests with its own
//! reading of the protocol (`frame`) and says what to answer (`answer`). A reader thread
//! stamps each request as its last byte arrives; a writer thread answers them in order, at
//! once or paced at a baud rate, on the line's schedule (never sooner than the line allows).

use plcsh::core::link::pty::Pty;
use std::fs::File;
use std::io::{Read, Write};
use std::os::fd::AsFd;
use std::path::PathBuf;
use std::sync::atomic::{AtomicBool, Ordering};
use std::sync::{Arc, Mutex};
use std::time::{Duration, Instant};

/// What the responder does for one request, in order.
pub enum Act {
    Sleep(Duration),
    /// Bytes at once.
    Send(Vec<u8>),
    /// Bytes one character at a time at the pace of `baud` (10-bit characters, e.g. 7E1).
    Paced(Vec<u8>, u32),
    /// 00H characters back to back at `baud` for this long: what a serial port delivers for
    /// characters with parity or framing errors.
    Noise(Duration, u32),
}

/// The time of one 10-bit character at `baud`.
pub fn char_time(baud: u32) -> Duration {
    Duration::from_nanos(10_000_000_000 / baud as u64)
}

/// A running responder; it stops when dropped.
pub struct Responder<R> {
    pub path: PathBuf,
    seen: Arc<Mutex<Vec<R>>>,
    /// When the last character of each answer went to the line (stamped just before its write).
    ends: Arc<Mutex<Vec<Instant>>>,
    stop: Arc<AtomicBool>,
}

impl<R: Clone> Responder<R> {
    /// The requests framed so far.
    pub fn seen(&self) -> Vec<R> {
        self.seen.lock().unwrap().clone()
    }
    /// When the last character of each answer went to the line (stamped just before its write,
    /// so a quiet measured from it is never shorter than the line's); for an answer that
    /// wrote nothing, when it was over.
    pub fn ends(&self) -> Vec<Instant> {
        self.ends.lock().unwrap().clone()
    }
    /// A device URL for the responder's port: `scheme:PATH` followed by `params`.
    pub fn url(&self, scheme: &str, params: &str) -> String {
        format!("{scheme}:{}{params}", self.path.display())
    }
}

impl<R> Drop for Responder<R> {
    fn drop(&mut self) {
        self.stop.store(true, Ordering::SeqCst);
    }
}

/// Starts a responder on a new pty. `frame(buffer, arrived)` takes what it can from the
/// front of the buffer: `None` when it needs more bytes, `Some(None)` when it dropped bytes
/// that start no request, `Some(Some(request))` for a request (`arrived`: when its last byte
/// came). `answer(request, k)` says what to do for the k-th request (k counts from 0).
pub fn start<R: Clone + Send + 'static>(
    mut frame: impl FnMut(&mut Vec<u8>, Instant) -> Option<Option<R>> + Send + 'static,
    mut answer: impl FnMut(&R, usize) -> Vec<Act> + Send + 'static,
) -> Responder<R> {
    let (master, slave, path) = Pty::open().unwrap().into_parts();
    let seen = Arc::new(Mutex::new(Vec::new()));
    let ends = Arc::new(Mutex::new(Vec::new()));
    let stop = Arc::new(AtomicBool::new(false));
    let (tx, rx) = std::sync::mpsc::channel::<R>();
    let mut reader = master.try_clone().unwrap();
    let (seen2, stop2) = (seen.clone(), stop.clone());
    std::thread::spawn(move || {
        // Our slave handle stays open: with no slave open, the master reads EIO.
        let _slave = slave;
        let mut buf: Vec<u8> = Vec::new();
        while !stop2.load(Ordering::SeqCst) {
            let mut fds = [nix::poll::PollFd::new(reader.as_fd(), nix::poll::PollFlags::POLLIN)];
            if nix::poll::poll(&mut fds, nix::poll::PollTimeout::from(10u16)).unwrap_or(0) == 0 {
                continue;
            }
            let mut b = [0u8; 512];
            match reader.read(&mut b) {
                Ok(n) if n > 0 => buf.extend_from_slice(&b[..n]),
                _ => {
                    std::thread::sleep(Duration::from_millis(5));
                    continue;
                }
            }
            let arrived = Instant::now();
            while let Some(got) = frame(&mut buf, arrived) {
                if let Some(req) = got {
                    seen2.lock().unwrap().push(req.clone());
                    let _ = tx.send(req);
                }
            }
        }
    });
    let (ends2, stop3) = (ends.clone(), stop.clone());
    std::thread::spawn(move || {
        let mut w: File = master;
        let mut k = 0;
        while !stop3.load(Ordering::SeqCst) {
            let req = match rx.recv_timeout(Duration::from_millis(10)) {
                Ok(r) => r,
                Err(std::sync::mpsc::RecvTimeoutError::Timeout) => continue,
                Err(_) => break,
            };
            // When the last character of this answer was handed to the line.
            let mut end = None;
            for act in answer(&req, k) {
                // On the line's schedule: character i goes out no earlier than i character times
                // after the first, so a paced frame never arrives sooner than the line allows.
                // A thread woken late (a loaded machine) writes the characters already due at
                // once, as a USB serial adapter delivers a line's characters in bursts, so the
                // frame keeps the line's pace on average instead of being stretched by every
                // late wake-up. The end is stamped before the last write: a thread preempted
                // after it cannot make the quiet that follows look shorter than it was.
                let paced = |w: &mut File, bytes: &[u8], baud: u32, end: &mut Option<Instant>| {
                    let start = Instant::now();
                    let mut sent = 0;
                    while sent < bytes.len() {
                        let due = start + char_time(baud) * sent as u32;
                        std::thread::sleep(due.saturating_duration_since(Instant::now()));
                        let now = Instant::now();
                        let ready =
                            (now.saturating_duration_since(start).as_nanos() / char_time(baud).as_nanos()) as usize + 1;
                        let upto = ready.clamp(sent + 1, bytes.len());
                        if upto == bytes.len() {
                            *end = Some(now);
                        }
                        let _ = w.write_all(&bytes[sent..upto]);
                        sent = upto;
                    }
                    let done = start + char_time(baud) * bytes.len() as u32;
                    std::thread::sleep(done.saturating_duration_since(Instant::now()));
                };
                match act {
                    Act::Sleep(d) => std::thread::sleep(d),
                    Act::Send(b) => {
                        end = Some(Instant::now());
                        let _ = w.write_all(&b);
                    }
                    Act::Paced(b, baud) => paced(&mut w, &b, baud, &mut end),
                    Act::Noise(d, baud) => {
                        let n = (d.as_nanos() / char_time(baud).as_nanos()) as usize;
                        paced(&mut w, &vec![0u8; n], baud, &mut end)
                    }
                }
            }
            ends2.lock().unwrap().push(end.unwrap_or_else(Instant::now));
            k += 1;
        }
    });
    Responder { path, seen, ends, stop }
}
