//! A graded run's limits, counted in things that do not depend on the machine: simulated time
//! (waits stop at the limit, [`Budget::cap_wait`]), Lua instructions (counted by the
//! interpreter's instruction hook) and Lua memory (the interpreter's allocator limit), with a
//! wall-clock limit only as a safety net (the parent process ends a worker that passes it).
//! The verdicts name the limit ("exceeded 10 simulated minutes", from the message catalogue), so a submission gets the
//! same verdict on an idle machine and on a loaded one.
//!
//! The limits are set by `plcsh lab` (`crate::lab`) and kept by the session (its waits stop at
//! the simulated-time limit) and the Lua engine (its instruction hook): it lives in the core so
//! that the session below the lab can hold it.

use crate::core::msg::{Arg, Msg};
use crate::core::Clock;
use std::sync::atomic::{AtomicU64, Ordering};
use std::sync::Mutex;
use std::time::Duration;

/// The limits of one run, and which one it passed first.
#[derive(Debug, Default)]
pub struct Budget {
    /// Simulated time from `start`.
    pub sim_time: Option<Duration>,
    pub start: Duration,
    pub instructions: Option<u64>,
    pub memory: Option<usize>,
    executed: AtomicU64,
    exceeded: Mutex<Option<Msg>>,
    /// An allocation the memory limit refused, not yet known to be final ([`Budget::refused`]).
    suspect: Mutex<Option<Allocation>>,
}

/// One request to Lua's allocator: the block, its old size, its new size.
pub type Allocation = (usize, usize, usize);

/// `600 s` → `exceeded 10 simulated minutes`; `90 s` → `exceeded 90 simulated seconds` (in
/// the language of messages: a lab's `language`).
pub fn exceeded_time(d: Duration) -> Msg {
    let s = d.as_secs_f64();
    if s >= 60.0 && (s / 60.0).fract() == 0.0 {
        crate::msg!("budget-exceeded-minutes", n = whole(s / 60.0))
    } else {
        crate::msg!("budget-exceeded-seconds", n = whole(s))
    }
}

/// A figure as a plural selector reads it: a whole number as a number, any other as its
/// digits (which take a language's "other" form: `0.5 simulated seconds`).
fn whole(x: f64) -> Arg {
    if x.fract() == 0.0 && x.abs() < 1e15 {
        Arg::Int(x as i64)
    } else {
        Arg::Text(trim(x))
    }
}

/// `50_000_000` → `50 M`.
pub fn describe_count(n: u64) -> String {
    if n >= 1_000_000 && n.is_multiple_of(100_000) {
        format!("{} M", trim(n as f64 / 1e6))
    } else {
        n.to_string()
    }
}

/// `268435456` → `256 MiB`; `1000` → `1000 bytes` (in the language of messages).
pub fn describe_bytes(n: usize) -> String {
    if n >= 1 << 20 {
        crate::msg!("budget-size-mib", n = trim(n as f64 / (1u64 << 20) as f64)).text
    } else {
        crate::msg!("budget-size-bytes", n = n).text
    }
}

fn trim(x: f64) -> String {
    let s = format!("{x:.3}");
    s.trim_end_matches('0').trim_end_matches('.').to_string()
}

impl Budget {
    pub fn new(sim_time: Option<Duration>, instructions: Option<u64>, memory: Option<usize>, clock: &Clock) -> Budget {
        Budget { sim_time, start: clock.now(), instructions, memory, ..Default::default() }
    }

    /// Notes the first limit passed (later ones do not replace it).
    pub fn exceed(&self, why: Msg) {
        let mut e = self.exceeded.lock().unwrap_or_else(|p| p.into_inner());
        if e.is_none() {
            *e = Some(why);
        }
    }

    /// The limit the run passed, as its verdict. A refused allocation still waiting for its
    /// retry is final by now (the retry comes at once, before any instruction): it is the
    /// memory limit.
    pub fn exceeded(&self) -> Option<String> {
        self.exceeded_msg().map(|m| m.text)
    }

    /// [`Budget::exceeded`] with its message id (a lab report's `code`).
    pub fn exceeded_msg(&self) -> Option<Msg> {
        if self.suspect.lock().unwrap_or_else(|p| p.into_inner()).take().is_some() {
            self.exceed_memory();
        }
        self.exceeded.lock().unwrap_or_else(|p| p.into_inner()).clone()
    }

    /// The allocator refused `a` at the memory limit. Lua retries a refused allocation once,
    /// at once, after an emergency collection (Lua 5.4's lmem.c, `tryagain`), and raises "not
    /// enough memory" only when the retry fails too; some refusals it does not retry (a
    /// string buffer's, lauxlib's `resizebox`). So a refusal is held as a suspect: the same
    /// request granted next was the retry, and the program goes on as stock Lua would; anything
    /// else next — another request, a failed retry, an instruction count, a protected call's
    /// check — makes it final, and the run has passed the memory limit for good. Noted here,
    /// where the allocation fails, it does not depend on the error reaching any handler: a
    /// `__close` that raises in its place, however it was installed, hides nothing.
    pub fn refused(&self, a: Allocation) {
        let mut s = self.suspect.lock().unwrap_or_else(|p| p.into_inner());
        if s.take().is_some() {
            drop(s);
            self.exceed_memory();
        } else {
            *s = Some(a);
        }
    }

    /// The allocator granted `a`, a request that grows what Lua holds: a suspect refusal of
    /// the same request was retried and rescued; a suspect refusal of another was final.
    pub fn granted(&self, a: Allocation) {
        let mut s = self.suspect.lock().unwrap_or_else(|p| p.into_inner());
        match s.take() {
            Some(r) if r == a => {}
            Some(_) => {
                drop(s);
                self.exceed_memory();
            }
            None => {}
        }
    }

    /// Whether a refused allocation waits for its retry (the allocator's fast path asks).
    pub fn has_suspect(&self) -> bool {
        self.suspect.lock().unwrap_or_else(|p| p.into_inner()).is_some()
    }

    fn deadline(&self) -> Option<Duration> {
        self.sim_time.map(|t| self.start + t)
    }

    /// A wait of `d` from now: `Some(d)` within the limit; otherwise the clock moves to the
    /// limit (stepped time), the limit is noted and the wait ends the run (`None`).
    pub fn cap_wait(&self, clock: &Clock, d: Duration) -> Option<Duration> {
        let Some(deadline) = self.deadline() else { return Some(d) };
        let now = clock.now();
        if now + d <= deadline {
            return Some(d);
        }
        if clock.is_stepped() && deadline > now {
            clock.step(deadline - now);
        }
        self.exceed(exceeded_time(self.sim_time.unwrap_or_default()));
        None
    }

    /// Counts `n` more Lua instructions and checks the limits; the verdict when one is passed.
    pub fn tick(&self, n: u64, clock: &Clock) -> Option<String> {
        let done = self.executed.fetch_add(n, Ordering::Relaxed) + n;
        if let Some(max) = self.instructions {
            if done > max {
                self.exceed(crate::msg!("budget-exceeded-instructions", count = describe_count(max)));
            }
        }
        if let Some(deadline) = self.deadline() {
            if clock.now() > deadline {
                self.exceed(exceeded_time(self.sim_time.unwrap_or_default()));
            }
        }
        self.exceeded()
    }

    /// Simulated time used since the start (at most the limit).
    pub fn used(&self, clock: &Clock) -> Duration {
        let used = clock.now().saturating_sub(self.start);
        self.sim_time.map_or(used, |t| used.min(t))
    }

    /// The memory verdict.
    pub fn memory_verdict(&self) -> Option<Msg> {
        self.memory.map(|m| crate::msg!("budget-exceeded-memory", size = describe_bytes(m)))
    }

    /// Notes that the memory limit was hit: from then on the run is over, whatever the Lua
    /// code does (the interpreter's "not enough memory" error alone could be caught by a
    /// `pcall`; the instruction hook and the sandbox's `pcall` raise the verdict again).
    pub fn exceed_memory(&self) {
        if let Some(v) = self.memory_verdict() {
            self.exceed(v);
        }
    }

    /// Lua instructions counted so far (in steps of the hook's interval).
    pub fn instructions_used(&self) -> u64 {
        self.executed.load(Ordering::Relaxed)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn verdicts_name_the_limit() {
        assert_eq!(exceeded_time(Duration::from_secs(600)), "exceeded 10 simulated minutes");
        assert_eq!(exceeded_time(Duration::from_secs(60)), "exceeded 1 simulated minute");
        assert_eq!(exceeded_time(Duration::from_secs(90)), "exceeded 90 simulated seconds");
        assert_eq!(exceeded_time(Duration::from_millis(500)), "exceeded 0.5 simulated seconds");
        assert_eq!(describe_bytes(1000), "1000 bytes");
        assert_eq!(describe_count(50_000_000), "50 M");
        assert_eq!(describe_bytes(256 << 20), "256 MiB");
    }

    #[test]
    fn a_wait_past_the_limit_stops_at_the_limit() {
        let clock = Clock::stepped();
        let b = Budget::new(Some(Duration::from_secs(600)), None, None, &clock);
        assert_eq!(b.cap_wait(&clock, Duration::from_secs(10)), Some(Duration::from_secs(10)));
        assert_eq!(b.cap_wait(&clock, Duration::from_secs(3600)), None);
        assert_eq!(clock.now(), Duration::from_secs(600));
        assert_eq!(b.exceeded().unwrap(), "exceeded 10 simulated minutes");
    }

    #[test]
    fn a_memory_limit_hit_stays_hit_and_comes_first() {
        let clock = Clock::stepped();
        let b = Budget::new(Some(Duration::from_secs(60)), Some(5000), Some(1 << 20), &clock);
        assert!(b.tick(1000, &clock).is_none());
        b.exceed_memory();
        assert_eq!(b.tick(1000, &clock).unwrap(), "exceeded 1 MiB of Lua memory");
        assert_eq!(b.tick(9000, &clock).unwrap(), "exceeded 1 MiB of Lua memory");
        assert_eq!(b.instructions_used(), 11000);
    }

    #[test]
    fn a_refused_allocation_is_the_memory_limit_unless_its_retry_is_granted() {
        let clock = Clock::stepped();
        // Rescued: the same request granted next (Lua's retry after an emergency collection).
        let b = Budget::new(None, None, Some(1 << 20), &clock);
        b.refused((0, 4, 4096));
        assert!(b.has_suspect());
        b.granted((0, 4, 4096));
        assert!(b.exceeded().is_none());
        // Final: the retry refused too.
        let b = Budget::new(None, None, Some(1 << 20), &clock);
        b.refused((0, 4, 4096));
        b.refused((0, 4, 4096));
        assert_eq!(b.exceeded().unwrap(), "exceeded 1 MiB of Lua memory");
        // Final: something else granted next (no retry: a string buffer's refusal).
        let b = Budget::new(None, None, Some(1 << 20), &clock);
        b.refused((0, 0, 1 << 30));
        b.granted((0, 4, 32));
        assert_eq!(b.exceeded().unwrap(), "exceeded 1 MiB of Lua memory");
        // Final: asked for the verdict (an instruction count, a protected call) meanwhile.
        let b = Budget::new(None, None, Some(1 << 20), &clock);
        b.refused((0, 0, 1 << 30));
        assert_eq!(b.tick(1000, &clock).unwrap(), "exceeded 1 MiB of Lua memory");
        // Once passed, for good: a later granted retry changes nothing.
        b.refused((0, 0, 64));
        b.granted((0, 0, 64));
        assert_eq!(b.exceeded().unwrap(), "exceeded 1 MiB of Lua memory");
    }

    #[test]
    fn instructions_are_counted() {
        let clock = Clock::stepped();
        let b = Budget::new(None, Some(5000), None, &clock);
        assert!(b.tick(4000, &clock).is_none());
        assert_eq!(b.tick(2000, &clock).unwrap(), "exceeded 5000 Lua instructions");
    }
}
