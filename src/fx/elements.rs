//! The FX timer and counter numbering: which numbers are 100 ms, 10 ms or 1 ms timers, which
//! keep their value, which counters are 16-bit up counters and which 32-bit up/down counters
//! with their direction relays (FX PM "Timers", "Counters"; the FX2N/FX1N table). One table
//! that the CPU's rules ([`super::plc`]), the program front end ([`super::program`]) and
//! `help T5` ([`super::space`]) all read.
//!
//! Source: the FX Series Programming Manual (Mitsubishi JY992D48301), chapter "Devices in
//! Detail" — cited as "FX PM".

use crate::msg;

/// One FX2N timer class: numbers, time base, whether it keeps its value when its coil goes
/// off (FX PM "Timers"; the FX2N/FX1N table).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct TimerClass {
    pub first: u16,
    pub last: u16,
    pub base_ns: u64,
    pub retentive: bool,
}

/// The timer table (FX2N): T0–T199 100 ms, T200–T245 10 ms, T246–T249 1 ms retentive,
/// T250–T255 100 ms retentive. Other models use the same numbers within their range.
pub static TIMERS: &[TimerClass] = &[
    TimerClass { first: 0, last: 199, base_ns: 100_000_000, retentive: false },
    TimerClass { first: 200, last: 245, base_ns: 10_000_000, retentive: false },
    TimerClass { first: 246, last: 249, base_ns: 1_000_000, retentive: true },
    TimerClass { first: 250, last: 255, base_ns: 100_000_000, retentive: true },
];

/// The class of timer `n` (numbers past the table count as 100 ms).
pub fn timer_class(n: u16) -> TimerClass {
    TIMERS.iter().find(|c| (c.first..=c.last).contains(&n)).copied().unwrap_or(TIMERS[0])
}

/// First 32-bit up/down counter and the direction relay of C200 (FX PM "Counters").
pub const C32_FIRST: u16 = 200;
pub const C32_LAST: u16 = 234;
pub const DIRECTION_RELAY: u16 = 8200;

/// A line for `help T5` / `help C5`: which class the timer or counter is in.
pub fn element_note(timer: bool, n: u16) -> String {
    if timer {
        let c = timer_class(n);
        let base = match c.base_ns {
            1_000_000 => "1 ms",
            10_000_000 => "10 ms",
            _ => "100 ms",
        };
        let (first, last) = (c.first, c.last);
        if c.retentive {
            msg!("tbl-element-timer-retentive", n = n, base = base, first = first, last = last).text
        } else {
            msg!("tbl-element-timer", n = n, base = base, first = first, last = last).text
        }
    } else if n < C32_FIRST {
        msg!("tbl-element-counter", n = n).text
    } else if n <= C32_LAST {
        msg!("tbl-element-counter32", n = n, relay = DIRECTION_RELAY + n - C32_FIRST).text
    } else {
        msg!("tbl-element-hsc", n = n).text
    }
}
