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

/// What runs before a real sleep (the signal watcher's start, which lives above `core`:
/// `signals::install` sets it, so a process that never sleeps starts no watcher thread).
static BEFORE_SLEEP: std::sync::OnceLock<fn()> = std::sync::OnceLock::new();

/// Sets what runs before every real sleep (once per process; later calls are ignored).
pub fn before_sleep(f: fn()) {
    let _ = BEFORE_SLEEP.set(f);
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

    /// Waits `d` of wall time whatever the mode; false when `interrupt` was raised. The wait
    /// is one timed wait on a process-wide condition variable that [`Clock::wake_sleepers`]
    /// wakes (the signal watcher calls it when a stop signal raised the flag; code that raises
    /// a flag itself calls it too), not a loop of short sleeps: a sleeping poller costs no
    /// wake-ups until its time is up.
    pub fn sleep_real(d: Duration, interrupt: &AtomicBool) -> bool {
        // Whoever sleeps may be woken by a stop signal: the watcher that wakes sleepers runs
        // from the first sleep on (a one-shot that never sleeps does without it).
        if let Some(start) = BEFORE_SLEEP.get() {
            start();
        }
        let end = Instant::now() + d;
        let (lock, cv) = &SLEEPERS;
        let mut gen = lock.lock().unwrap_or_else(|p| p.into_inner());
        loop {
            if interrupt.load(Ordering::SeqCst) {
                return false;
            }
            let now = Instant::now();
            if now >= end {
                return true;
            }
            gen = cv.wait_timeout(gen, end - now).unwrap_or_else(|p| p.into_inner()).0;
        }
    }

    /// Wakes every [`Clock::sleep_real`] so it looks at its interrupt flag again (after a
    /// flag was raised).
    pub fn wake_sleepers() {
        let (lock, cv) = &SLEEPERS;
        *lock.lock().unwrap_or_else(|p| p.into_inner()) += 1;
        cv.notify_all();
    }
}

/// The sleepers' condition variable and a count of wake-ups (the mutex guards nothing else).
static SLEEPERS: (Mutex<u64>, std::sync::Condvar) = (Mutex::new(0), std::sync::Condvar::new());

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

    #[test]
    fn a_raised_flag_ends_a_long_sleep_when_the_sleepers_are_woken() {
        let stop = Arc::new(AtomicBool::new(false));
        let s = stop.clone();
        let t = std::thread::spawn(move || {
            let started = Instant::now();
            (Clock::sleep_real(Duration::from_secs(30), &s), started.elapsed())
        });
        // Raise the flag and wake until the sleeper has gone (it may not be asleep yet).
        stop.store(true, Ordering::SeqCst);
        while !t.is_finished() {
            Clock::wake_sleepers();
            std::thread::yield_now();
        }
        let (slept, took) = t.join().unwrap();
        assert!(!slept);
        assert!(took < Duration::from_secs(5), "{took:?}");
    }

    #[test]
    fn a_real_sleep_lasts_its_time_and_no_more_than_a_little() {
        let never = AtomicBool::new(false);
        let started = Instant::now();
        assert!(Clock::sleep_real(Duration::from_millis(30), &never));
        let took = started.elapsed();
        assert!(took >= Duration::from_millis(30) && took < Duration::from_millis(500), "{took:?}");
    }
}
