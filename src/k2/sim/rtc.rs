//! The simulated real-time clock (manual §2.2.9; k2.md §7): calendar time that runs with
//! the session's virtual clock (so stepped time moves it too), settable by SET_RTC, and
//! kept across restarts by the state file (the battery keeps it running while the
//! simulator is off: on restore it has moved on by the host time that passed).

use crate::k2::instr::RtcTime;
use std::time::Duration;

#[derive(Clone, Copy, Debug, serde::Serialize, serde::Deserialize)]
pub struct Rtc {
    /// Civil seconds (see [`RtcTime::to_secs`]) at `at`.
    base: i64,
    /// Virtual time at which `base` held.
    at: Duration,
}

impl Rtc {
    /// A clock reading `t` at virtual time `at`.
    pub fn new(t: RtcTime, at: Duration) -> Rtc {
        Rtc { base: t.to_secs(), at }
    }

    /// The calendar time at virtual time `now`.
    pub fn read(&self, now: Duration) -> RtcTime {
        RtcTime::from_secs(self.base + now.saturating_sub(self.at).as_secs() as i64)
    }

    /// SET_RTC at virtual time `now`.
    pub fn set(&mut self, t: RtcTime, now: Duration) {
        self.base = t.to_secs();
        self.at = now;
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_clock_runs_with_virtual_time() {
        let t = RtcTime::parse("2026-11-22T10:00:00").unwrap();
        let mut r = Rtc::new(t, Duration::from_secs(5));
        assert_eq!(r.read(Duration::from_secs(5)), t);
        assert_eq!(r.read(Duration::from_millis(65_999)).to_string(), "2026-11-22T10:01:00");
        r.set(RtcTime::parse("2027-01-01T00:00:00").unwrap(), Duration::from_secs(100));
        assert_eq!(r.read(Duration::from_secs(3700)).to_string(), "2027-01-01T01:00:00");
    }
}
