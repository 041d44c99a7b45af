//! The simulated FX PLC's CPU: RUN/STOP, the scan cycle in virtual time, the special devices
//! a program or a client observes, and the FX timer and counter rules. The device image is
//! [`Memory`] and the CPU's state beside it [`super::cpu`]; this module is what makes them
//! behave like a PLC rather than plain memory.
//!
//! Sources: the FX Series Programming Manual (Mitsubishi JY992D48301, public; e.g.
//! <https://marine.manualsonline.com/manuals/mfg/mitsubishi/fx2c.html?p=92>), chapter "Devices
//! in Detail" (timers, counters, special devices) — cited as "FX PM"; the FX2N timer table is
//! also given by the public note
//! <https://industrialmonitordirect.com/blogs/knowledgebase/mitsubishi-fx-timer-programming-t0-t255-configuration-guide>.
//!
//! - **Scans.** In RUN the CPU scans back to back: scan k starts when scan k−1 ends; a scan
//!   lasts the fixed END processing ([`super::program::costs`]) plus its program's time from the engine's cost
//!   table. A scan's program runs at its start time and its results are visible from then on.
//!   [`Memory::advance_to`] runs every scan that starts at or before a time — whoever asks and
//!   however often, so an outcome never depends on who polls. Without a program the scans are
//!   counted analytically (no loop).
//! - **Special devices** are computed, not stored (FX PM, special device list): M8000 on in
//!   RUN, M8001 its inverse, M8002 on during the first scan after RUN, M8003 its inverse
//!   (off in STOP); M8011/M8012/M8013/M8014 are the 10 ms / 100 ms / 1 s / 1 min clocks, 50 %
//!   duty, on for the first half of each period counted from the simulator's time 0 (power
//!   on), running in RUN and STOP; D8010/D8011/D8012 the current (last), shortest and longest
//!   scan time in 0.1 ms. Writes to them change nothing (the PLC rewrites them every scan), so
//!   a port's write is acknowledged and ignored; the driver refuses them with a message
//!   ([`super::operand::system_driven`]).
//! - **RUN/STOP.** STOP: no scans, all outputs Y off (M8033 "keep memory in STOP" is not
//!   modelled), other devices kept. STOP → RUN: scans start again, M8002 pulses, timers
//!   start from their current values, edge memories are cleared.
//! - **Timers** ([`super::elements::TIMERS`], FX2N table): `OUT Tn K` counts while its coil is on, in units of
//!   the timer's base, up to the preset, and then holds; the contact is on at the preset.
//!   Coil off: T0–T245 clear (value 0, contact off); T246–T255 are retentive and hold until
//!   `RST`. Time between two executions of the coil is credited to the coil state seen at the
//!   earlier one, so the contact turns on in the first scan that starts at least preset ×
//!   base after the scan in which the coil came on.
//! - **Counters:** C0–C199 16-bit up counters count rising edges of their coil up to the
//!   preset and hold; C200–C234 are 32-bit up/down counters whose direction is M8200–M8234
//!   (on: down), counting past the preset and wrapping at ±2³¹; the contact is on while the
//!   value is at or above the preset. High-speed counters C235–C255 are not simulated (a
//!   program naming them is refused at load).
//! - **Driven by writes.** A client drives timers and counters the way an FX operator does:
//!   by writing the devices a program's coils depend on (an input X, an M), a timer's preset
//!   register (`OUT T0 D10`) or its current value `TN0` (the timer continues from the value
//!   written). Coils (TC/CC) are the program's: without a program nothing counts, as on a
//!   real PLC.

use super::cpu::{Stats, TimerRun};
use super::elements::{timer_class, C32_FIRST, DIRECTION_RELAY};
use super::memory::Memory;
use super::program::Loaded;
use std::time::Duration;

/// RUN or STOP: the switch [`Memory::set_mode`] turns (`sim cpu run|stop`).
pub use super::cpu::Mode;

fn ns(d: Duration) -> u64 {
    d.as_nanos().min(u64::MAX as u128) as u64
}

impl Memory {
    /// Brings the PLC to the clock's present time.
    pub fn advance(&mut self) {
        let now = self.cpu.clock.now();
        self.advance_to(now);
    }

    /// Runs every scan that starts at or before `t`; afterwards the image shows time `t`.
    pub fn advance_to(&mut self, t: Duration) {
        if t < self.at {
            return;
        }
        if self.cpu.mode == Mode::Run && self.cpu.next_scan <= t {
            if self.cpu.program.is_none() {
                // An empty program: every scan is END processing alone.
                let d = (self.cpu.costs.overhead_ns).max(self.cpu.costs.min_scan_ns).max(1);
                let n = ns(t - self.cpu.next_scan) / d + 1;
                self.cpu.record(d, n);
                self.cpu.next_scan += Duration::from_nanos(d.saturating_mul(n));
            } else {
                while self.cpu.mode == Mode::Run && self.cpu.next_scan <= t {
                    self.scan_once();
                }
            }
        }
        self.at = t;
    }

    /// One scan at `next_scan`.
    fn scan_once(&mut self) {
        let start = self.cpu.next_scan;
        self.at = start;
        // Input refresh: a stuck input (control channel fault) reads its level.
        let stuck: Vec<(u16, bool)> = self.faults.stuck(start).collect();
        for (i, on) in stuck {
            if let Some(b) = self.bits[0].get_mut(i as usize) {
                *b = on;
            }
        }
        // The special relays of this scan: M8002 is on while `scans` is 1.
        self.cpu.stats.scans += 1;
        let Some(mut loaded) = self.cpu.program.take() else { return };
        let out = loaded.scan(self, ns(start));
        self.cpu.stats.scans -= 1;
        let costs = &self.cpu.costs;
        let d = (costs.overhead_ns + out.0).max(costs.min_scan_ns).max(1);
        self.cpu.record(d, 1);
        self.cpu.next_scan = start + Duration::from_nanos(d);
        self.cpu.program = Some(loaded);
        if let Some(f) = out.1 {
            // A fault (the watchdog) stops the PLC, outputs off.
            self.cpu.fault = Some(f);
            self.stop_outputs();
            self.cpu.mode = Mode::Stop;
        }
    }

    fn stop_outputs(&mut self) {
        for i in 0..self.model.y {
            self.set_plain_bit(super::operand::Area::Y, i, false);
        }
    }

    /// RUN or STOP (the simulator's RUN/STOP switch).
    pub fn set_mode(&mut self, mode: Mode) {
        self.advance();
        match (self.cpu.mode, mode) {
            (Mode::Run, Mode::Stop) => {
                self.cpu.mode = Mode::Stop;
                self.stop_outputs();
            }
            (Mode::Stop, Mode::Run) => self.restart(),
            _ => {}
        }
    }

    /// STOP → RUN: the first scan starts now.
    pub fn restart(&mut self) {
        let now = self.at.max(self.cpu.clock.now());
        self.at = now;
        self.cpu.mode = Mode::Run;
        self.cpu.fault = None;
        self.cpu.next_scan = now;
        self.cpu.stats = Stats::default();
        for t in &mut self.cpu.timers {
            *t = TimerRun::default();
        }
        for c in &mut self.cpu.counter_prev {
            *c = false;
        }
        if let Some(p) = &mut self.cpu.program {
            p.reset();
        }
        // The first scan starts at once.
        self.advance_to(now);
    }

    /// Loads a program (replacing any) and restarts RUN with it.
    pub fn load_program(&mut self, p: Loaded) {
        self.advance();
        self.cpu.program = Some(Box::new(p));
        self.restart();
    }

    /// Removes the program: the PLC runs an empty one.
    pub fn unload_program(&mut self) {
        self.advance();
        self.cpu.program = None;
        if self.cpu.mode == Mode::Run {
            self.restart();
        }
    }

    /// One execution of `OUT Tn K`: coil `input`, preset `preset` (FX PM "Timers").
    pub fn timer_coil(&mut self, n: u16, input: bool, preset: i32, now_ns: u64) {
        use super::operand::Area;
        let class = timer_class(n);
        let Some(run) = self.cpu.timers.get(n as usize).copied() else { return };
        self.set_plain_bit(Area::TC, n, input);
        let mut cv = self.word(Area::TN, n).unwrap_or(0) as u16 as i16 as i32;
        let mut st = run;
        if input {
            if st.on {
                let el = now_ns.saturating_sub(st.mark_ns) + st.frac_ns;
                st.frac_ns = el % class.base_ns;
                let units = (el / class.base_ns).min(i32::MAX as u64) as i64;
                cv = ((cv.max(0) as i64 + units).min(preset.max(cv) as i64)).min(32767) as i32;
                if cv >= preset {
                    st.frac_ns = 0;
                }
            } else {
                st.frac_ns = 0;
            }
            st.mark_ns = now_ns;
            st.on = true;
        } else {
            st.on = false;
            st.frac_ns = 0;
            if !class.retentive {
                cv = 0;
            }
        }
        self.cpu.timers[n as usize] = st;
        self.set_plain_word(Area::TN, n, cv as u16 as u32);
        // A retentive timer keeps its contact with its value; others are off with the coil.
        let contact = (input || class.retentive) && cv >= preset && (input || cv > 0);
        self.set_plain_bit(Area::TS, n, contact);
    }

    /// One execution of `OUT Cn K` (FX PM "Counters").
    pub fn counter_coil(&mut self, n: u16, input: bool, preset: i64) {
        use super::operand::Area;
        let Some(prev) = self.cpu.counter_prev.get(n as usize).copied() else { return };
        self.cpu.counter_prev[n as usize] = input;
        self.set_plain_bit(Area::CC, n, input);
        let rising = input && !prev;
        if n < C32_FIRST {
            let mut cv = self.word(Area::CN, n).unwrap_or(0) as u16 as i16 as i64;
            if rising && cv < preset {
                cv += 1;
            }
            self.set_plain_word(Area::CN, n, cv as u16 as u32);
            self.set_plain_bit(Area::CS, n, cv >= preset);
        } else {
            let mut cv = self.word(Area::CN, n).unwrap_or(0) as i32;
            if rising {
                let down = self.bit(Area::M, DIRECTION_RELAY + n - C32_FIRST).unwrap_or(false);
                cv = if down { cv.wrapping_sub(1) } else { cv.wrapping_add(1) };
            }
            self.set_plain_word(Area::CN, n, cv as u32);
            self.set_plain_bit(Area::CS, n, cv as i64 >= preset);
        }
    }

    /// `RST Tn` / `RST Cn`: value 0, contact off, timing forgotten.
    pub fn reset_element(&mut self, timer: bool, n: u16) {
        use super::operand::Area;
        if timer {
            if let Some(t) = self.cpu.timers.get_mut(n as usize) {
                t.frac_ns = 0;
            }
            self.set_plain_word(Area::TN, n, 0);
            self.set_plain_bit(Area::TS, n, false);
        } else {
            self.set_plain_word(Area::CN, n, 0);
            self.set_plain_bit(Area::CS, n, false);
        }
    }
}

#[cfg(test)]
#[path = "plc_tests.rs"]
mod tests;
