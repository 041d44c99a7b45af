//! The virtual clock every simulator reads (design: "time is a value, not a sleep").
//!
//! Two modes: *following* the wall clock (the REPL's default, so pulses go out in real
//! time), or *stepped*, where time moves only when told (`sim step 500ms`, a script's
//! `plcsh.sleep` in stepped mode). Simulators compute their state analytically from the
//! elapsed virtual time, so one step of an hour costs the same as a step of a millisecond.
//! The clock is shared (cheap `Clone`) by every simulated device in a session, so wired
//! devices see one time.

use std::sync::atomic::{AtomicBool, AtomicU64, Ordering};
use std::sync::{Arc, Mutex};
use std::time::{Duration, Instant};

/// `stepped_ns` while the clock follows the wall clock.
const FOLLOWING: u64 = u64::MAX;

/// The wall-clock anchor of a following clock.
#[derive(Debug)]
struct Follow {
    /// Virtual time at `anchor`.
    base: Duration,
    anchor: Instant,
}

#[derive(Debug)]
struct Shared {
    /// The virtual time in ns while stepped ([`FOLLOWING`] otherwise). Stepped time is read
    /// on every simulator access, so it is one atomic load, not a lock.
    stepped_ns: AtomicU64,
    /// The anchor while following; mode changes happen under this lock.
    follow: Mutex<Follow>,
}

/// A shared virtual clock. Time starts at zero when the clock is created.
#[derive(Clone, Debug)]
pub struct Clock {
    shared: Arc<Shared>,
}

impl Default for Clock {
    fn default() -> Self {
        Clock::following()
    }
}

/// `d` in ns, saturating below [`FOLLOWING`] (584 years of virtual time).
fn ns(d: Duration) -> u64 {
    d.as_secs().saturating_mul(1_000_000_000).saturating_add(d.subsec_nanos() as u64).min(FOLLOWING - 1)
}

impl Clock {
    /// The latest virtual time a stepped clock reaches (its ns count is 64 bits: about 584
    /// years); a step past it stops there. Commands refuse such a step instead.
    pub const LATEST: Duration = Duration::from_nanos(FOLLOWING - 1);

    /// A clock that follows the wall clock.
    pub fn following() -> Clock {
        Clock {
            shared: Arc::new(Shared {
                stepped_ns: AtomicU64::new(FOLLOWING),
                follow: Mutex::new(Follow { base: Duration::ZERO, anchor: Instant::now() }),
            }),
        }
    }

    /// A clock that moves only when stepped.
    pub fn stepped() -> Clock {
        let c = Clock::following();
        c.shared.stepped_ns.store(0, Ordering::Release);
        c
    }

    fn lock(&self) -> std::sync::MutexGuard<'_, Follow> {
        self.shared.follow.lock().unwrap_or_else(|p| p.into_inner())
    }

    /// Virtual time since the clock started.
    #[inline]
    pub fn now(&self) -> Duration {
        match self.shared.stepped_ns.load(Ordering::Acquire) {
            FOLLOWING => {
                let f = self.lock();
                // Re-read under the lock: a step may have switched the mode meanwhile.
                match self.shared.stepped_ns.load(Ordering::Acquire) {
                    FOLLOWING => f.base + f.anchor.elapsed(),
                    t => Duration::from_nanos(t),
                }
            }
            t => Duration::from_nanos(t),
        }
    }

    pub fn is_stepped(&self) -> bool {
        self.shared.stepped_ns.load(Ordering::Acquire) != FOLLOWING
    }

    /// Advances by exactly `d` and leaves the clock stepped from then on.
    #[inline]
    pub fn step(&self, d: Duration) {
        let s = &self.shared.stepped_ns;
        let dn = ns(d);
        let mut t = s.load(Ordering::Acquire);
        while t != FOLLOWING {
            let next = t.saturating_add(dn).min(FOLLOWING - 1);
            match s.compare_exchange_weak(t, next, Ordering::AcqRel, Ordering::Acquire) {
                Ok(_) => return,
                Err(now) => t = now,
            }
        }
        // Following: switch to stepped from the current wall-clock-based time, under the
        // lock so a concurrent `run` or `set` sees one mode.
        let f = self.lock();
        match s.load(Ordering::Acquire) {
            FOLLOWING => s.store(ns(f.base + f.anchor.elapsed() + d), Ordering::Release),
            t => s.store(ns(Duration::from_nanos(t) + d), Ordering::Release),
        }
    }

    /// Sets the virtual time to `t` (a snapshot being restored), keeping the mode.
    pub fn set(&self, t: Duration) {
        let mut f = self.lock();
        f.base = t;
        f.anchor = Instant::now();
        let s = &self.shared.stepped_ns;
        if s.load(Ordering::Acquire) != FOLLOWING {
            s.store(ns(t), Ordering::Release);
        }
    }

    /// Makes the clock follow the wall clock again, from the current virtual time.
    pub fn run(&self) {
        let mut f = self.lock();
        let t = self.shared.stepped_ns.load(Ordering::Acquire);
        if t != FOLLOWING {
            f.base = Duration::from_nanos(t);
            f.anchor = Instant::now();
            self.shared.stepped_ns.store(FOLLOWING, Ordering::Release);
        }
    }

    /// Waits `d` of virtual time: instantly in stepped mode (the clock is advanced), for
    /// real otherwise. Returns `false` if `interrupt` was raised before the time was up.
    pub fn sleep(&self, d: Duration, interrupt: &AtomicBool) -> bool {
        if self.is_stepped() {
            self.step(d);
            return !interrupt.load(Ordering::Relaxed);
        }
        Clock::sleep_real(d, interrupt)
    }

    /// Waits `d` of wall time whatever the mode, in slices that notice `interrupt`; false
    /// when interrupted.
    pub fn sleep_real(d: Duration, interrupt: &AtomicBool) -> bool {
        let end = Instant::now() + d;
        loop {
            if interrupt.load(Ordering::Relaxed) {
                return false;
            }
            let now = Instant::now();
            if now >= end {
                return true;
            }
            std::thread::sleep((end - now).min(Duration::from_millis(20)));
        }
    }
}

/// Formats a virtual time as `12.345678s`.
pub fn format_time(d: Duration) -> String {
    format!("{}.{:06}s", d.as_secs(), d.subsec_micros())
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn stepped_clock_moves_only_when_told() {
        let c = Clock::stepped();
        assert_eq!(c.now(), Duration::ZERO);
        std::thread::sleep(Duration::from_millis(2));
        assert_eq!(c.now(), Duration::ZERO);
        c.step(Duration::from_millis(500));
        assert_eq!(c.now(), Duration::from_millis(500));
        let never = AtomicBool::new(false);
        assert!(c.sleep(Duration::from_secs(600), &never));
        assert_eq!(c.now(), Duration::from_millis(600_500));
    }

    #[test]
    fn following_clock_becomes_stepped_after_a_step_and_resumes_on_run() {
        let c = Clock::following();
        c.step(Duration::from_secs(10));
        assert!(c.is_stepped());
        let t = c.now();
        assert!(t >= Duration::from_secs(10));
        c.run();
        assert!(!c.is_stepped());
        assert!(c.now() >= t);
    }

    #[test]
    fn sleep_returns_false_when_interrupted() {
        let c = Clock::following();
        let stop = AtomicBool::new(true);
        assert!(!c.sleep(Duration::from_secs(5), &stop));
    }
}
