//! What a UMPK program runs on: the I/O image of one 10 ms cycle, the on-delay timers with
//! their three delay groups (manual §3.5, Table 5), the divide-by-N counters (§3.5), and
//! the [`Runner`] hook where a program plugs in.
//!
//! The UMPK's own language is not published, so the simulator cannot execute the binary a
//! vendor tool produces (it stores and reports it). A [`Runner`] is the program the
//! simulator does execute: once per cycle in Work mode, after the inputs are read and
//! before the outputs are written (§1: read inputs, evaluate, write outputs). It reads and
//! writes the [`Image`] and drives the timers and counters through [`Logic`], whose
//! semantics are the UMPK's, so any front end (an IL program on the scan engine, a test's
//! closure) gets the same timing:
//! - on-delay timer: its output turns on once its input has been on for the preset, and
//!   off as soon as the input is off. Presets are counted in 10 ms cycles: group 0 is
//!   1–255 × 10 ms, group 1 1–255 × 0.1 s, group 2 1–255 × 1 s;
//! - counter: counts rising edges of its input; the N-th (N = division ratio 1–255) starts
//!   an output pulse that lasts exactly as long as that input pulse, and counting starts
//!   over; a program reset clears the count and the output.

use crate::msg;
use std::fmt;

/// The cycle time (§1, Table 1 row 11).
pub const CYCLE_MS: u64 = 10;

/// The I/O image the program and the monitor see (Table 7's areas).
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct Image {
    pub inputs: u32,
    pub outputs: u32,
    pub markers: u128,
    pub timers: u16,
    pub counters: u8,
}

fn bit<T: Into<u128>>(word: T, i: u8) -> bool {
    word.into() >> i & 1 != 0
}

impl Image {
    pub fn input(&self, i: u8) -> bool {
        bit(self.inputs, i)
    }
    pub fn output(&self, i: u8) -> bool {
        bit(self.outputs, i)
    }
    pub fn marker(&self, i: u8) -> bool {
        bit(self.markers, i)
    }
    pub fn set_output(&mut self, i: u8, on: bool) {
        self.outputs = self.outputs & !(1 << i) | (on as u32) << i;
    }
    pub fn set_marker(&mut self, i: u8, on: bool) {
        self.markers = self.markers & !(1 << i) | (on as u128) << i;
    }
}

/// A timer's delay group (Table 5).
#[derive(Clone, Copy, Debug, PartialEq, Eq, serde::Serialize, serde::Deserialize)]
pub enum Group {
    /// 10 ms – 2.55 s in 10 ms steps.
    Ms10 = 0,
    /// 0.1 s – 25.5 s in 0.1 s steps.
    Ms100 = 1,
    /// 1 s – 255 s in 1 s steps.
    S1 = 2,
}

impl Group {
    pub fn from_number(n: u8) -> Option<Group> {
        [Group::Ms10, Group::Ms100, Group::S1].get(n as usize).copied()
    }
    /// Cycles per step.
    pub fn cycles(self) -> u32 {
        match self {
            Group::Ms10 => 1,
            Group::Ms100 => 10,
            Group::S1 => 100,
        }
    }
}

/// An on-delay timer.
#[derive(Clone, Copy, Debug, PartialEq, Eq, serde::Serialize, serde::Deserialize)]
pub struct OnDelay {
    pub group: Group,
    /// 1–255 steps of the group.
    pub steps: u8,
    /// Cycles since the input turned on (0 in the cycle it turned on).
    pub elapsed: u32,
    /// The input was on in the previous cycle.
    pub input: bool,
    pub q: bool,
}

impl Default for OnDelay {
    fn default() -> Self {
        OnDelay { group: Group::Ms10, steps: 1, elapsed: 0, input: false, q: false }
    }
}

impl OnDelay {
    pub fn preset_cycles(&self) -> u32 {
        self.steps.max(1) as u32 * self.group.cycles()
    }
    /// One cycle with `input`; returns the output. The output turns on `preset` after the
    /// cycle in which the input turned on (a 2.0 s timer: 200 cycles later).
    pub fn update(&mut self, input: bool) -> bool {
        if input && self.input {
            self.elapsed = (self.elapsed + 1).min(self.preset_cycles());
        } else {
            self.elapsed = 0;
        }
        self.input = input;
        self.q = input && self.elapsed >= self.preset_cycles();
        self.q
    }
}

/// A divide-by-N counter.
#[derive(Clone, Copy, Debug, PartialEq, Eq, serde::Serialize, serde::Deserialize)]
pub struct Divider {
    /// Division ratio 1–255.
    pub ratio: u8,
    pub count: u8,
    pub q: bool,
    prev: bool,
}

impl Default for Divider {
    fn default() -> Self {
        Divider { ratio: 1, count: 0, q: false, prev: false }
    }
}

impl Divider {
    /// One cycle with `input` and the program's `reset`; returns the output.
    pub fn update(&mut self, input: bool, reset: bool) -> bool {
        if reset {
            self.count = 0;
            self.q = false;
            self.prev = input;
            return false;
        }
        if input && !self.prev {
            self.count += 1;
            if self.count >= self.ratio.max(1) {
                self.count = 0;
                self.q = true;
            }
        }
        if !input {
            self.q = false;
        }
        self.prev = input;
        self.q
    }
}

/// The timers and counters of one controller, updated by the program each cycle, and what
/// the cycle reports to the controller: error codes for the history and whether the program
/// stopped.
#[derive(Clone, Debug, Default, PartialEq, Eq, serde::Serialize, serde::Deserialize)]
pub struct Logic {
    pub timers: Vec<OnDelay>,
    pub counters: Vec<Divider>,
    /// Error codes raised in this cycle, in order ([`Scan::raise`]); the controller moves
    /// them into its error history (§4.1.8) after the cycle.
    pub raised: Vec<u8>,
    /// The program stopped in this cycle ([`Scan::stop`]).
    pub stopped: bool,
}

impl Logic {
    pub fn new(timers: u8, counters: u8) -> Logic {
        Logic {
            timers: vec![OnDelay::default(); timers as usize],
            counters: vec![Divider::default(); counters as usize],
            raised: Vec::new(),
            stopped: false,
        }
    }

    /// Sets timer `i`'s delay: `steps` (1–255) of `group`.
    pub fn set_timer(&mut self, i: usize, group: Group, steps: u8) -> Result<(), String> {
        let t = self.timers.get_mut(i).ok_or_else(|| msg!("umpk-logic-no-timer", n = i).text)?;
        if steps == 0 {
            return Err(msg!("umpk-logic-delay", n = i).text);
        }
        t.group = group;
        t.steps = steps;
        Ok(())
    }

    pub fn set_ratio(&mut self, i: usize, ratio: u8) -> Result<(), String> {
        let c = self.counters.get_mut(i).ok_or_else(|| msg!("umpk-logic-no-counter", n = i).text)?;
        if ratio == 0 {
            return Err(msg!("umpk-logic-ratio", n = i).text);
        }
        c.ratio = ratio;
        Ok(())
    }

    /// Clears every timer and counter (power-up, reset).
    pub fn clear(&mut self) {
        for t in &mut self.timers {
            t.elapsed = 0;
            t.input = false;
            t.q = false;
        }
        for c in &mut self.counters {
            *c = Divider { ratio: c.ratio, ..Divider::default() };
        }
    }
}

/// One cycle's view for a program.
pub struct Scan<'a> {
    pub io: &'a mut Image,
    pub logic: &'a mut Logic,
    /// Cycles since the program started.
    pub cycle: u64,
}

impl Scan<'_> {
    /// Any operand's bit, by its place in the operand table ([`crate::umpk::space::AREAS`]:
    /// I, Q, T, C, M) — what an engine that resolved `I3` or `T0` through the UMPK's operand
    /// space reads.
    pub fn bit(&self, op: crate::umpk::space::UmpkOperand) -> bool {
        let i = op.index;
        match op.area().letter {
            'I' => self.io.input(i),
            'Q' => self.io.output(i),
            'T' => bit(self.io.timers, i),
            'C' => bit(self.io.counters, i),
            _ => self.io.marker(i),
        }
    }

    /// Sets an output or a marker; inputs, timers and counters are not the program's to set
    /// (timers and counters change through [`Scan::timer`] and [`Scan::counter`]).
    pub fn set_bit(&mut self, op: crate::umpk::space::UmpkOperand, on: bool) -> Result<(), String> {
        match op.area().letter {
            'Q' => self.io.set_output(op.index, on),
            'M' => self.io.set_marker(op.index, on),
            l => return Err(msg!("umpk-logic-cannot-assign", operand = op.name(), area = l.to_string()).text),
        }
        Ok(())
    }

    /// Runs timer `i` with `input` for this cycle; its output goes to the image (T bit).
    pub fn timer(&mut self, i: u8, input: bool) -> bool {
        let Some(t) = self.logic.timers.get_mut(i as usize) else { return false };
        let q = t.update(input);
        self.io.timers = self.io.timers & !(1 << i) | (q as u16) << i;
        q
    }
    /// Puts `code` into the controller's error history after this cycle (§4.1.8: 1–127 are
    /// the program's own codes, 128–255 the system's).
    pub fn raise(&mut self, code: u8) {
        if self.logic.raised.len() < 8 {
            self.logic.raised.push(code);
        }
    }

    /// The program stopped with system error `code`: the code goes into the history and the
    /// controller leaves Work mode (outputs off) until it is reset.
    pub fn stop(&mut self, code: u8) {
        self.raise(code);
        self.logic.stopped = true;
        self.io.outputs = 0;
    }

    /// Runs counter `i` with `input` and `reset` for this cycle; its output goes to the image.
    pub fn counter(&mut self, i: u8, input: bool, reset: bool) -> bool {
        let Some(c) = self.logic.counters.get_mut(i as usize) else { return false };
        let q = c.update(input, reset);
        self.io.counters = self.io.counters & !(1 << i) | (q as u8) << i;
        q
    }
}

/// An IL program in a snapshot ([`Runner::save`]; the snapshot file is `super::snapshot`'s).
#[derive(Clone, Debug, serde::Serialize, serde::Deserialize)]
pub struct IlState {
    /// The name it was loaded under (a path), for messages.
    pub source: String,
    pub text: String,
    pub cpu: crate::engine::Cpu,
    pub last_ns: u64,
    pub fault: Option<String>,
}

/// A program the simulator executes, once per 10 ms cycle in Work mode.
pub trait Runner: Send {
    /// Evaluates the program for one cycle: inputs are in `scan.io`; it sets outputs and
    /// markers and runs timers and counters through `scan`.
    fn scan(&mut self, scan: &mut Scan<'_>);
    /// What it is, for `umpk info` and the program-info reply (at most 22 characters used).
    fn name(&self) -> String;
    /// Its execution time per cycle in 0.271 µs counts, for the timing figures (§4.1.13).
    fn cost_counts(&self) -> u16 {
        0
    }
    /// Starts the program afresh (a reset or power-up after it stopped).
    fn restart(&mut self) {}
    /// Its state for a snapshot; `None` for a program a snapshot cannot hold (one given as
    /// code, like the built-in reference solutions).
    fn save(&self) -> Option<IlState> {
        None
    }
}

/// A program given as a closure (tests, built-in demonstrations).
pub struct FnRunner<F: FnMut(&mut Scan<'_>) + Send> {
    pub name: String,
    pub f: F,
}

impl<F: FnMut(&mut Scan<'_>) + Send> Runner for FnRunner<F> {
    fn scan(&mut self, scan: &mut Scan<'_>) {
        (self.f)(scan)
    }
    fn name(&self) -> String {
        self.name.clone()
    }
}

impl fmt::Debug for dyn Runner {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        write!(f, "Runner({})", self.name())
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn on_delay_groups_count_cycles() {
        for (group, steps, cycles) in
            [(Group::Ms10, 1, 1), (Group::Ms10, 255, 255), (Group::Ms100, 15, 150), (Group::S1, 2, 200)]
        {
            let mut t = OnDelay { group, steps, ..OnDelay::default() };
            assert!(!t.update(true), "{group:?} {steps}: the input turns on");
            for k in 1..cycles {
                assert!(!t.update(true), "{group:?} {steps}: cycle {k}");
            }
            assert!(t.update(true), "{group:?} {steps}: on {cycles} cycles after the input");
            assert!(t.update(true));
            assert!(!t.update(false), "off at once");
            assert!(!t.update(true), "starts over");
        }
    }

    #[test]
    fn divider_pulse_lasts_as_long_as_the_input_pulse() {
        let mut c = Divider { ratio: 4, ..Divider::default() };
        let mut outs = Vec::new();
        // Five input pulses of 3 cycles on, 2 off.
        for _ in 0..5 {
            for on in [true, true, true, false, false] {
                outs.push(c.update(on, false));
            }
        }
        let high: Vec<usize> = outs.iter().enumerate().filter(|(_, q)| **q).map(|(i, _)| i).collect();
        assert_eq!(high, vec![15, 16, 17], "the 4th pulse (cycles 15–17) passes, exactly as long");
        assert_eq!(c.count, 1, "the 5th pulse counts again");
        assert!(!c.update(true, true) && c.count == 0, "program reset");
        let mut one = Divider::default();
        assert!(
            one.update(true, false) && one.update(true, false) && !one.update(false, false),
            "ratio 1 passes every pulse"
        );
    }

    #[test]
    fn scan_writes_timer_and_counter_bits() {
        let mut io = Image::default();
        let mut logic = Logic::new(16, 4);
        logic.set_timer(15, Group::Ms10, 2).unwrap();
        assert!(logic.set_timer(16, Group::Ms10, 2).is_err());
        assert!(logic.set_ratio(0, 0).is_err());
        let mut s = Scan { io: &mut io, logic: &mut logic, cycle: 0 };
        assert!(!s.timer(15, true));
        assert!(!s.timer(15, true));
        assert!(s.timer(15, true));
        assert!(s.counter(3, true, false));
        let op = |area, index| crate::umpk::space::UmpkOperand { area, index };
        assert!(s.bit(op(2, 15)) && s.bit(op(3, 3)), "T15 and C3 through the operand table");
        s.set_bit(op(4, 63), true).unwrap();
        assert!(s.bit(op(4, 63)));
        assert!(s.set_bit(op(0, 1), true).is_err(), "inputs are not assignable");
        assert_eq!((io.timers, io.counters), (0x8000, 0x08));
    }
}
