//! Timer and counter behaviour, one pure function per kind, separate from the interpreter
//! so each kind's rules read as the manual states them and test without a program.
//!
//! Timers (K80S CPU chapter, `../shared/seeds/001_…`; K2 TON/TOF; IEC TP) count up in
//! units of their time base (K2 §2.1.2 resolution classes, chosen by the family). Time is
//! sampled: a timer is updated when its instruction runs, from the virtual time of the
//! scan, and time between two executions is credited to the input state seen at the
//! earlier one. The current value saturates at 32767 (S7-200 convention, which the K2's
//! INT timer values follow). The value lives in the family's image, so a client that writes
//! `T5` changes what the timer continues from.

use super::isa::{CounterKind, TimerKind};
use serde::{Deserialize, Serialize};

/// Per-timer engine state (the value and bit live in the image).
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, Serialize, Deserialize)]
pub struct TimerState {
    pub running: bool,
    /// The input at the last execution (edge detection).
    pub prev: bool,
    /// Virtual time (ns) up to which time has been credited.
    pub mark_ns: u64,
    /// Time credited but not yet a whole unit.
    pub frac_ns: u64,
}

/// Per-counter engine state.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, Serialize, Deserialize)]
pub struct CounterState {
    pub prev_up: bool,
    pub prev_down: bool,
}

const MAX: i32 = 32767;

fn start(st: &mut TimerState, now: u64) {
    st.running = true;
    st.mark_ns = now;
    st.frac_ns = 0;
}

/// Credits the time since the last update to `cv`.
fn credit(st: &mut TimerState, cv: i32, now: u64, base: u64) -> i32 {
    let el = now.saturating_sub(st.mark_ns) + st.frac_ns;
    let base = base.max(1);
    st.frac_ns = el % base;
    st.mark_ns = now;
    (cv as i64 + (el / base) as i64).min(MAX as i64) as i32
}

/// One execution of a timer: input `inp`, current value `cv`, preset `pt` (units of
/// `base` ns), optional reset. Returns the new value and output bit.
#[allow(clippy::too_many_arguments)]
pub fn timer(
    kind: TimerKind,
    st: &mut TimerState,
    inp: bool,
    cv: i32,
    pt: i32,
    reset: bool,
    now: u64,
    base: u64,
) -> (i32, bool) {
    let rising = inp && !st.prev;
    let falling = !inp && st.prev;
    st.prev = inp;
    if reset {
        st.running = false;
        st.frac_ns = 0;
        return (0, false);
    }
    match kind {
        // On-delay: input on → count from 0; Q when the value reaches the preset; input
        // off → value 0, Q off (K80S TON; K2 TON).
        TimerKind::Ton => {
            if !inp {
                st.running = false;
                return (0, false);
            }
            let cv = if st.running {
                credit(st, cv, now, base)
            } else {
                start(st, now);
                0
            };
            (cv, cv >= pt)
        }
        // Off-delay: Q on while the input is on; counting starts when it goes off; Q off
        // when the preset is reached (K80S TOFF; K2 TOF).
        TimerKind::Tof => {
            if inp {
                st.running = false;
                return (0, true);
            }
            if falling {
                start(st, now);
                return (0, pt > 0);
            }
            if !st.running {
                return (cv, false);
            }
            let cv = credit(st, cv, now, base);
            if cv >= pt {
                st.running = false;
                return (pt, false);
            }
            (cv, true)
        }
        // Accumulating: counts while the input is on and keeps the value while it is off;
        // Q at the preset; only a reset clears it (K80S TMR).
        TimerKind::Tmr => {
            let mut cv = cv;
            if st.running {
                cv = credit(st, cv, now, base);
            }
            if inp && !st.running {
                st.running = true;
                st.mark_ns = now;
            } else if !inp {
                st.running = false;
            }
            (cv, cv >= pt)
        }
        // Pulse / monostable: a rising input starts a pulse of the preset length; the
        // input is ignored meanwhile (IEC TP; K80S TMON).
        TimerKind::Tp | TimerKind::Tmon => {
            if rising && !st.running {
                start(st, now);
                return (0, pt > 0);
            }
            if st.running {
                let cv = credit(st, cv, now, base);
                if cv >= pt {
                    st.running = false;
                    return (pt, false);
                }
                return (cv, true);
            }
            // IEC TP clears its value once the input is off after the pulse.
            if kind == TimerKind::Tp && !inp {
                return (0, false);
            }
            (cv, false)
        }
        // Retriggerable: each rising input (re)starts the pulse from 0 (K80S TRTG).
        TimerKind::Trtg => {
            if rising {
                start(st, now);
                return (0, pt > 0);
            }
            if st.running {
                let cv = credit(st, cv, now, base);
                if cv >= pt {
                    st.running = false;
                    return (pt, false);
                }
                return (cv, true);
            }
            (cv, false)
        }
    }
}

/// One execution of a counter: up input `up` (the CR; for CTD the down input), second
/// input `down` (CTUD), reset (CTD: load the preset). Counts rising edges (K80S).
pub fn counter(
    kind: CounterKind,
    st: &mut CounterState,
    up: bool,
    down: bool,
    cv: i32,
    pv: i32,
    reset: bool,
) -> (i32, bool) {
    let up_edge = up && !st.prev_up;
    let down_edge = down && !st.prev_down;
    st.prev_up = up;
    st.prev_down = down;
    match kind {
        // Up: Q when the count reaches the preset; reset clears (K80S CTU).
        CounterKind::Ctu => {
            let cv = if reset {
                0
            } else if up_edge {
                (cv + 1).min(MAX)
            } else {
                cv
            };
            (cv, cv >= pv)
        }
        // Down: Q when the count reaches 0; "reset" loads the preset (K80S CTD).
        CounterKind::Ctd => {
            let cv = if reset {
                pv
            } else if up_edge && cv > 0 {
                cv - 1
            } else {
                cv
            };
            (cv, cv <= 0)
        }
        // Up/down: two inputs; Q while count ≥ preset (K80S CTUD).
        CounterKind::Ctud => {
            let mut cv = cv;
            if reset {
                cv = 0;
            } else {
                if up_edge {
                    cv = (cv + 1).min(MAX);
                }
                if down_edge {
                    cv = (cv - 1).max(-32768);
                }
            }
            (cv, cv >= pv)
        }
        // Ring: counts up, Q on at the preset, the next rising edge clears to 0 (K80S CTR).
        CounterKind::Ctr => {
            let cv = if reset {
                0
            } else if up_edge {
                if cv >= pv {
                    0
                } else {
                    cv + 1
                }
            } else {
                cv
            };
            (cv, cv >= pv)
        }
    }
}
