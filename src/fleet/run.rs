//! Running one piece of work on every member of a fleet at once: one worker thread per
//! device, at most `jobs` of them at a time, each device owned by its thread for the whole
//! work (the design's "Concurrency for fleets": the `Device` trait is synchronous; async
//! stays inside the transports).
//!
//! Why threads and not one async loop: a member is a whole [`Shell`] with its own
//! [`Session`] — command lines, Lua (an `mlua` state per thread; the "send" feature makes it
//! movable, but one state must not be entered from two threads at once), guards, the virtual
//! clock shared by all. A thread per device reuses every command and every driver unchanged,
//! and costs a stack (2 MiB reserved, a few pages touched) per concurrent member; with
//! `--jobs 8` that is nothing next to a device's round trip. Measured in BENCHMARKS.md
//! ("Fleets").
//!
//! Failures stay with their device: an error, a panic or a per-device timeout is that
//! member's result, and the others go on. A member that overruns its timeout is reported as
//! `timeout`, its interrupt flag is raised (waits and Lua stop at their next check) and its
//! slot is given to the next member; its thread is left to end on its own (a blocked read
//! ends with the link's own timeout).

use super::{Fleet, Member};
use crate::core::{Error, ErrorKind, Result};
use crate::output::Style;
use crate::session::Session;
use crate::shell::Shell;
use std::collections::HashMap;
use std::sync::atomic::{AtomicBool, Ordering};
use std::sync::{mpsc, Arc};
use std::time::{Duration, Instant};

/// How a fleet runs.
#[derive(Clone, Copy, Debug)]
pub struct Settings {
    /// Members worked on at once (at least 1).
    pub jobs: usize,
    /// A member still busy after this long is reported as `timeout` (`None`: no limit).
    pub timeout: Option<Duration>,
}

/// What every member's session starts from: the main session's clock, profiles and
/// `--read-only` switch.
#[derive(Clone)]
pub struct Base {
    pub clock: crate::core::Clock,
    pub profiles: crate::profile::Profiles,
    pub read_only: bool,
    pub style: Style,
}

impl Base {
    pub fn of(s: &Session, style: Style) -> Base {
        Base { clock: s.clock.clone(), profiles: s.profiles.clone(), read_only: s.read_only(), style }
    }

    /// A shell with one device, `m`, open and current: opened through the profile path
    /// ([`crate::session::Session::open_profile`]), so its write rules and `--read-only` hold.
    pub fn open(&self, fleet: &Fleet, m: &Member, interrupt: Arc<AtomicBool>) -> Result<Shell> {
        let mut s = self.open_session(fleet, m, interrupt)?;
        s.profiles = self.profiles.clone();
        let mut shell = Shell::new(s, self.style);
        crate::script::install(&mut shell);
        Ok(shell)
    }

    /// Only the session of [`Base::open`], with the member's device open and current: no Lua
    /// state and no copy of the profile file (a publisher holds thousands of these at once;
    /// a copy of the profiles each would hold the whole member list once per member).
    pub fn open_session(&self, fleet: &Fleet, m: &Member, interrupt: Arc<AtomicBool>) -> Result<Session> {
        let mut s = Session::new(self.clock.clone());
        s.set_read_only(self.read_only);
        s.interrupt = interrupt;
        let p = fleet.profile_of(m, &self.profiles)?.clone();
        s.open_profile(&m.name, &p)?;
        s.use_device(&m.name)?;
        Ok(s)
    }
}

/// One member's result.
#[derive(Debug)]
pub struct Done<T> {
    pub device: String,
    pub result: Result<T>,
    pub elapsed: Duration,
}

/// The work done on one member: its index in the fleet and its stop flag.
pub type Work<T> = Arc<dyn Fn(usize, Arc<AtomicBool>) -> Result<T> + Send + Sync>;

/// Runs `work` on every member of `fleet` (at most `settings.jobs` at once); the results
/// come back in the fleet's order. `stop` (Ctrl-C) stops the running members and starts no
/// more; the members not started are reported as interrupted.
pub fn each<T: Send + 'static>(fleet: &Fleet, settings: Settings, stop: &AtomicBool, work: Work<T>) -> Vec<Done<T>> {
    let n = fleet.members.len();
    let jobs = settings.jobs.max(1);
    let (tx, rx) = mpsc::channel::<(usize, Result<T>)>();
    let mut results: Vec<Option<Done<T>>> = (0..n).map(|_| None).collect();
    let mut running: HashMap<usize, (Instant, Arc<AtomicBool>)> = HashMap::new();
    let mut next = 0;
    let name = |i: usize| fleet.members[i].name.clone();
    loop {
        while running.len() < jobs && next < n && !stop.load(Ordering::Relaxed) {
            let i = next;
            next += 1;
            let flag = Arc::new(AtomicBool::new(false));
            let (tx, work, f) = (tx.clone(), work.clone(), flag.clone());
            let spawned = std::thread::Builder::new().name(format!("fleet-{}", name(i))).spawn(move || {
                let r = std::panic::catch_unwind(std::panic::AssertUnwindSafe(|| work(i, f)))
                    .unwrap_or_else(|_| Err(Error::state(crate::msg!("fleet-internal-error"))));
                let _ = tx.send((i, r));
            });
            match spawned {
                Ok(_) => {
                    running.insert(i, (Instant::now(), flag));
                }
                Err(e) => {
                    let e = Error::io(crate::msg!("fleet-no-thread")).cause(e).device(name(i));
                    results[i] = Some(Done { device: name(i), result: Err(e), elapsed: Duration::ZERO });
                }
            }
        }
        if running.is_empty() {
            break;
        }
        // Wake for the first result, the nearest deadline, or a look at the stop flag.
        let mut wait = Duration::from_millis(50);
        if let Some(t) = settings.timeout {
            for (start, _) in running.values() {
                wait = wait.min(t.saturating_sub(start.elapsed()));
            }
        }
        if let Ok((i, r)) = rx.recv_timeout(wait) {
            if let Some((start, _)) = running.remove(&i) {
                results[i] =
                    Some(Done { device: name(i), result: r.map_err(|e| named(e, &name(i))), elapsed: start.elapsed() });
            }
        }
        if let Some(t) = settings.timeout {
            let late: Vec<usize> = running.iter().filter(|(_, (s, _))| s.elapsed() >= t).map(|(i, _)| *i).collect();
            for i in late {
                if let Some((start, flag)) = running.remove(&i) {
                    flag.store(true, Ordering::Relaxed);
                    crate::core::Clock::wake_sleepers();
                    let e = Error::new(
                        ErrorKind::Timeout,
                        crate::msg!("fleet-timeout", seconds = t.as_secs_f64().to_string()),
                    )
                    .device(name(i))
                    .hint(crate::msg!("fleet-hint-timeout"));
                    results[i] = Some(Done { device: name(i), result: Err(e), elapsed: start.elapsed() });
                }
            }
        }
        if stop.load(Ordering::Relaxed) {
            for (_, flag) in running.values() {
                flag.store(true, Ordering::Relaxed);
            }
            crate::core::Clock::wake_sleepers();
        }
    }
    results
        .into_iter()
        .enumerate()
        .map(|(i, r)| {
            r.unwrap_or_else(|| Done {
                device: name(i),
                result: Err(Error::new(ErrorKind::Interrupted, crate::msg!("fleet-not-started")).device(name(i))),
                elapsed: Duration::ZERO,
            })
        })
        .collect()
}

/// An error that names its device (a member's own errors usually do already).
fn named(e: Error, device: &str) -> Error {
    if e.device.is_some() {
        e
    } else {
        e.device(device)
    }
}
