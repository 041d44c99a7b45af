//! What the K2's special instructions exchange, independent of how a device runs them:
//! interrupt events (with the manual's event numbers), the real-time-clock value, and the
//! event filter `wait event` uses. The simulator produces these; a wire driver that runs the
//! instructions through a PLC-side helper will produce the same types, so [`super::K2Ops`]
//! stays about instructions and results, not about simulator internals.
//!
//! Event numbers (one table, [`EventKind::number`]):
//! - PTO0 complete = 28: manual §3.4.2.3 ("событие 28"), k2.md §5.
//! - Multi-PV "CV = PV": HSC0 64–95, HSC1 96–127, HSC2 128–159, HSC3 160–191, PV k → base +
//!   k − 1: manual §3.3.4 (bases in `sm_map::HSC_REGS`).
//! - Everything else has **no number**: the manual says single-PV mode keeps the K5 event
//!   numbers but does not list them, and the K5 numbering is not S7-200's (S7-200's event 28
//!   is "HSC0 external reset", the K2's is "PTO0 complete", kinco-public-notes). Guessing
//!   would make a user ATCH the wrong event, so these events carry only a name
//!   (`pto1-done`, `hsc0-cv=pv`, `hsc1-reset`, `hsc1-dir`, `eeprom-wear`) and `wait event` accepts names.

use crate::core::civil::civil_from_days;
use crate::msg;
use serde::Serialize;
use std::fmt;
use std::time::Duration;

/// What happened.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Serialize, serde::Deserialize)]
#[serde(tag = "kind", rename_all = "snake_case")]
pub enum EventKind {
    /// A PTO finished its pulses (single or multi-segment).
    PtoComplete { channel: u8 },
    /// A counter reached a preset: `pv` is the 1-based PV number in multi-PV mode, `None`
    /// in single-PV mode.
    HscCvEqPv { channel: u8, pv: Option<u8> },
    /// A counter's external reset input became active.
    HscReset { channel: u8 },
    /// A counter's counting direction changed (the status bit SM36.5 …: `up` is the new
    /// direction) while it runs: the HSC instruction's direction bit, the external direction
    /// input, or the signals counted (two-pulse and A/B modes).
    HscDirection { channel: u8, up: bool },
    /// An E2PROM backup byte crossed a wear threshold (`writes` so far, manual §2.2.8).
    EepromWear { byte: u32, writes: u64 },
    /// An injected fault acted (`fault` is its kind's code, `crate::k2::sim::fault`).
    Fault { id: u32, fault: u8 },
}

/// PTO0's completion event (manual §3.4.2.3).
pub const PTO0_COMPLETE: u16 = 28;

impl EventKind {
    /// The interrupt event number the manual gives, if it gives one (see the module doc).
    pub fn number(&self) -> Option<u16> {
        match *self {
            EventKind::PtoComplete { channel: 0 } => Some(PTO0_COMPLETE),
            EventKind::HscCvEqPv { channel, pv: Some(k) } => {
                let base = crate::k2::sm_map::HSC_REGS.get(channel as usize)?.event_base as u16;
                Some(base + k as u16 - 1)
            }
            _ => None,
        }
    }

    /// A stable short name, usable in `wait event NAME`.
    pub fn name(&self) -> String {
        match *self {
            EventKind::PtoComplete { channel } => format!("pto{channel}-done"),
            EventKind::HscCvEqPv { channel, pv: Some(k) } => format!("hsc{channel}-pv{k}"),
            EventKind::HscCvEqPv { channel, pv: None } => format!("hsc{channel}-cv=pv"),
            EventKind::HscReset { channel } => format!("hsc{channel}-reset"),
            EventKind::HscDirection { channel, .. } => format!("hsc{channel}-dir"),
            EventKind::EepromWear { .. } => "eeprom-wear".to_string(),
            EventKind::Fault { id, .. } => format!("fault{id}"),
        }
    }

    /// A sentence for people.
    pub fn describe(&self) -> String {
        match *self {
            EventKind::PtoComplete { channel } => msg!("k2-event-pto-complete", channel = channel).into(),
            EventKind::HscCvEqPv { channel, pv: Some(k) } => {
                msg!("k2-event-cv-eq-pv-multi", channel = channel, k = k).into()
            }
            EventKind::HscCvEqPv { channel, pv: None } => msg!("k2-event-cv-eq-pv", channel = channel).into(),
            EventKind::HscReset { channel } => msg!("k2-event-hsc-reset", channel = channel).into(),
            EventKind::HscDirection { channel, up } => {
                msg!("k2-event-hsc-direction", channel = channel, dir = if up { "up" } else { "down" }).into()
            }
            EventKind::EepromWear { byte, writes } => msg!("k2-event-eeprom-wear", byte = byte, writes = writes).into(),
            EventKind::Fault { id, fault } => {
                msg!("k2-event-fault", id = id, name = crate::k2::sim::fault::FaultKind::name_of_code(fault)).into()
            }
        }
    }
}

/// One event with its virtual time.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Serialize)]
pub struct Event {
    /// Sequence number, counting every event the device raised (including dropped ones).
    pub seq: u64,
    /// Virtual time since the session's clock started.
    #[serde(serialize_with = "ser_us", rename = "time_us")]
    pub time: Duration,
    #[serde(flatten)]
    pub kind: EventKind,
}

fn ser_us<S: serde::Serializer>(d: &Duration, s: S) -> Result<S::Ok, S::Error> {
    s.serialize_u64(d.as_micros() as u64)
}

/// Which events a `wait` accepts: an event number (`28`) or a name (`pto1-done`).
#[derive(Clone, Debug, PartialEq, Eq)]
pub enum EventMatch {
    Number(u16),
    Name(String),
}

impl EventMatch {
    pub fn parse(text: &str) -> EventMatch {
        match text.parse::<u16>() {
            Ok(n) => EventMatch::Number(n),
            Err(_) => EventMatch::Name(text.to_ascii_lowercase()),
        }
    }
    pub fn matches(&self, k: &EventKind) -> bool {
        match self {
            EventMatch::Number(n) => k.number() == Some(*n),
            EventMatch::Name(s) => k.name() == *s,
        }
    }
}

impl fmt::Display for EventMatch {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            EventMatch::Number(n) => write!(f, "event {n}"),
            EventMatch::Name(s) => write!(f, "event {s}"),
        }
    }
}

/// A calendar time as the PLC's real-time clock holds it (local civil time, no zone).
#[derive(Clone, Copy, Debug, PartialEq, Eq, PartialOrd, Ord, Serialize)]
pub struct RtcTime {
    pub year: u16,
    pub month: u8,
    pub day: u8,
    pub hour: u8,
    pub minute: u8,
    pub second: u8,
}

impl RtcTime {
    /// Parses `2026-11-22T10:00:00` (also with a space, or without seconds).
    pub fn parse(text: &str) -> Result<RtcTime, String> {
        let bad = || msg!("k2-rtc-not-datetime", text = text).text;
        let t = text.trim();
        let (date, time) = t.split_once(['T', 't', ' ']).ok_or_else(bad)?;
        let d: Vec<&str> = date.split('-').collect();
        let h: Vec<&str> = time.split(':').collect();
        if d.len() != 3 || !(2..=3).contains(&h.len()) {
            return Err(bad());
        }
        let num = |s: &str| s.parse::<u32>().map_err(|_| bad());
        let r = RtcTime {
            year: num(d[0])? as u16,
            month: num(d[1])? as u8,
            day: num(d[2])? as u8,
            hour: num(h[0])? as u8,
            minute: num(h[1])? as u8,
            second: if h.len() == 3 { num(h[2])? as u8 } else { 0 },
        };
        r.validate()?;
        Ok(r)
    }

    /// Checks the fields. The K2 (like the S7-200 READ_RTC buffer) keeps a two-digit year,
    /// so 2000–2099.
    pub fn validate(&self) -> Result<(), String> {
        if !(2000..=2099).contains(&self.year) {
            return Err(msg!("k2-rtc-year", year = self.year).into());
        }
        if !(1..=12).contains(&self.month) {
            return Err(msg!("k2-rtc-month", month = self.month).into());
        }
        let dim = days_in_month(self.year as i64, self.month as u32);
        if self.day < 1 || self.day as u32 > dim {
            return Err(msg!(
                "k2-rtc-day",
                day = self.day,
                days = dim,
                month = format!("{}-{:02}", self.year, self.month)
            )
            .into());
        }
        if self.hour > 23 || self.minute > 59 || self.second > 59 {
            return Err(
                msg!("k2-rtc-time", time = format!("{:02}:{:02}:{:02}", self.hour, self.minute, self.second)).into()
            );
        }
        Ok(())
    }

    /// Seconds since 1970-01-01T00:00:00 of this civil time (no zone).
    pub fn to_secs(&self) -> i64 {
        days_from_civil(self.year as i64, self.month as u32, self.day as u32) * 86_400
            + self.hour as i64 * 3600
            + self.minute as i64 * 60
            + self.second as i64
    }

    pub fn from_secs(s: i64) -> RtcTime {
        let days = s.div_euclid(86_400);
        let rem = s.rem_euclid(86_400);
        let (y, m, d) = civil_from_days(days);
        RtcTime {
            year: y as u16,
            month: m as u8,
            day: d as u8,
            hour: (rem / 3600) as u8,
            minute: (rem / 60 % 60) as u8,
            second: (rem % 60) as u8,
        }
    }

    /// Day of week, 1 = Sunday … 7 = Saturday (S7-200 READ_RTC convention).
    pub fn weekday(&self) -> u8 {
        let days = days_from_civil(self.year as i64, self.month as u32, self.day as u32);
        // 1970-01-01 was a Thursday (5 in this numbering).
        ((days + 4).rem_euclid(7) + 1) as u8
    }

    /// The 8-byte BCD buffer READ_RTC fills (S7-200 layout: year, month, day, hour, minute,
    /// second, 0, weekday). Kinco's own layout is not in the manual (kinco-public-notes):
    /// this is the S7-200 one, stated as an assumption.
    pub fn to_bcd8(&self) -> [u8; 8] {
        let b = |v: u8| ((v / 10) << 4) | (v % 10);
        [
            b((self.year % 100) as u8),
            b(self.month),
            b(self.day),
            b(self.hour),
            b(self.minute),
            b(self.second),
            0,
            self.weekday(),
        ]
    }

    /// Reads the 8-byte BCD buffer of [`RtcTime::to_bcd8`] (years 00–99 are 2000–2099),
    /// checking every digit and the date.
    pub fn from_bcd8(b: &[u8; 8]) -> Result<RtcTime, String> {
        let d = |v: u8| -> Result<u8, String> {
            if v >> 4 > 9 || v & 0xF > 9 {
                Err(msg!("k2-rtc-not-bcd", value = format!("{v:02X}")).into())
            } else {
                Ok((v >> 4) * 10 + (v & 0xF))
            }
        };
        let t = RtcTime {
            year: 2000 + d(b[0])? as u16,
            month: d(b[1])?,
            day: d(b[2])?,
            hour: d(b[3])?,
            minute: d(b[4])?,
            second: d(b[5])?,
        };
        t.validate()?;
        Ok(t)
    }
}

impl fmt::Display for RtcTime {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        write!(
            f,
            "{:04}-{:02}-{:02}T{:02}:{:02}:{:02}",
            self.year, self.month, self.day, self.hour, self.minute, self.second
        )
    }
}

fn is_leap(y: i64) -> bool {
    (y % 4 == 0 && y % 100 != 0) || y % 400 == 0
}

fn days_in_month(y: i64, m: u32) -> u32 {
    match m {
        2 if is_leap(y) => 29,
        2 => 28,
        4 | 6 | 9 | 11 => 30,
        _ => 31,
    }
}

/// Days since 1970-01-01 (H. Hinnant's `days_from_civil`).
fn days_from_civil(y: i64, m: u32, d: u32) -> i64 {
    let y = if m <= 2 { y - 1 } else { y };
    let era = y.div_euclid(400);
    let yoe = y - era * 400;
    let mp = (m as i64 + 9) % 12;
    let doy = (153 * mp + 2) / 5 + d as i64 - 1;
    let doe = yoe * 365 + yoe / 4 - yoe / 100 + doy;
    era * 146_097 + doe - 719_468
}

/// The host's local civil time now (for `rtc sync` and a fresh simulator's clock).
pub fn host_local_now() -> RtcTime {
    let now = std::time::SystemTime::now().duration_since(std::time::UNIX_EPOCH).unwrap_or_default().as_secs() as i64;
    RtcTime::from_secs(now + host_utc_offset(now))
}

/// Seconds east of UTC of the host's zone at Unix time `t` (0 if unknown).
pub fn host_utc_offset(t: i64) -> i64 {
    crate::core::platform::utc_offset(t)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn event_numbers_from_the_manual() {
        assert_eq!(EventKind::PtoComplete { channel: 0 }.number(), Some(28));
        assert_eq!(EventKind::PtoComplete { channel: 1 }.number(), None, "not in the manual");
        assert_eq!(EventKind::HscCvEqPv { channel: 0, pv: Some(1) }.number(), Some(64));
        assert_eq!(EventKind::HscCvEqPv { channel: 0, pv: Some(32) }.number(), Some(95));
        assert_eq!(EventKind::HscCvEqPv { channel: 1, pv: Some(1) }.number(), Some(96));
        assert_eq!(EventKind::HscCvEqPv { channel: 2, pv: Some(1) }.number(), Some(128));
        assert_eq!(EventKind::HscCvEqPv { channel: 3, pv: Some(32) }.number(), Some(191));
        assert_eq!(EventKind::HscCvEqPv { channel: 3, pv: None }.number(), None);
    }

    #[test]
    fn matching_by_number_and_name() {
        let k = EventKind::PtoComplete { channel: 0 };
        assert!(EventMatch::parse("28").matches(&k));
        assert!(EventMatch::parse("PTO0-done").matches(&k));
        assert!(!EventMatch::parse("29").matches(&k));
    }

    #[test]
    fn civil_time_round_trips() {
        let t = RtcTime::parse("2026-11-22T10:00:00").unwrap();
        assert_eq!(t.to_string(), "2026-11-22T10:00:00");
        assert_eq!(RtcTime::from_secs(t.to_secs()), t);
        assert_eq!(RtcTime::from_secs(t.to_secs() + 14 * 3600).to_string(), "2026-11-23T00:00:00");
        assert_eq!(RtcTime::parse("2024-02-29 23:59").unwrap().second, 0);
        assert!(RtcTime::parse("2025-02-29T00:00:00").is_err(), "not a leap year");
        assert!(RtcTime::parse("2026-13-01T00:00:00").is_err());
        assert!(RtcTime::parse("1999-01-01T00:00:00").is_err());
        assert!(RtcTime::parse("yesterday").is_err());
    }

    #[test]
    fn weekday_and_bcd() {
        // 2026-11-22 is a Sunday.
        let t = RtcTime::parse("2026-11-22T10:05:59").unwrap();
        assert_eq!(t.weekday(), 1);
        assert_eq!(t.to_bcd8(), [0x26, 0x11, 0x22, 0x10, 0x05, 0x59, 0, 1]);
        assert!(RtcTime::parse("1970-01-01T00:00:00").map(|_| ()).unwrap_err().contains("2000"));
        assert_eq!(RtcTime::from_secs(0).weekday(), 5, "1970-01-01 was a Thursday");
    }
}
