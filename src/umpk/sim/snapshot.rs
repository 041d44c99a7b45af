//! The simulated UMPK's state in a snapshot (`sim snapshot save NAME`, [`crate::snapshot`]):
//! mode, echo and monitor switches, the error history, the flash and program info, the
//! process image (inputs, outputs, markers, timer and counter bits), the timers and dividers,
//! hand-set inputs and square waves, the cycle count, and the program: an IL program's text
//! (compiled again on restore) with the scan engine's state. What a snapshot cannot hold it
//! refuses by name ([`Umpk::snapshot_state`]) — a program given as code (the built-in
//! reference solutions), a programming sequence or a monitor stream half-way, bytes on the
//! line — rather than leave it out.

use super::logic::{IlState, Image, Logic, Runner};
use super::{Mode, Program, Programming, Umpk, Wave};
use crate::engine::Cpu;
use crate::msg;
use serde::{Deserialize, Serialize};
use std::time::Duration;

/// What the flash holds, as a snapshot keeps it.
#[derive(Clone, Debug, Serialize, Deserialize)]
#[serde(tag = "kind", rename_all = "lowercase")]
pub enum ProgramState {
    None,
    Binary,
    Il(Box<IlState>),
}

/// Everything a simulated UMPK holds.
#[derive(Clone, Debug, Serialize, Deserialize)]
pub struct UmpkState {
    pub model: String,
    /// `Work`, `Wait`, `Programming` or `restarting`.
    pub mode: String,
    /// The end of a restart, nanoseconds (mode `restarting`).
    pub restart_until_ns: u64,
    pub echo: bool,
    pub echo_off_by_command: bool,
    pub errors: Vec<u8>,
    /// The flash as hex, two digits a byte.
    pub flash: String,
    pub info: String,
    pub program: ProgramState,
    pub inputs: u32,
    pub outputs: u32,
    /// The 128 markers as 32 hex digits (JSON numbers stop at 64 bits).
    pub markers: String,
    pub timer_bits: u16,
    pub counter_bits: u8,
    pub logic: Logic,
    pub forced_inputs: u32,
    pub waves: Vec<Wave>,
    pub cycle: u64,
    pub program_cycles: u64,
    pub max_program_counts: u16,
    /// The flash page whose writes fail (`flash-fail PAGE`), if one does.
    #[serde(default)]
    pub flash_fail: Option<usize>,
    /// Injected faults (`fault no-reply`, `fault stuck I1=1`) with their windows and log.
    #[serde(default)]
    pub faults: crate::core::sim_faults::Faults,
}

impl Umpk {
    /// The state to save, brought to the present; refuses naming what it cannot keep.
    ///
    /// Every field of [`Umpk`] is named below (no `..`): a field added to the simulator does
    /// not compile until it is saved here or named as not the machine's state, with why.
    pub fn snapshot_state(&mut self) -> Result<UmpkState, String> {
        self.advance(self.clock.now());
        let Umpk {
            model,
            // From the device URL (`status_bits=`), like a drive line's echo mode: the link's
            // setting, not the controller's state; a restore keeps the URL's.
            layout: _,
            // The session's clock: the snapshot's `clock_us`.
            clock: _,
            mode,
            echo,
            echo_off_by_command,
            monitor,
            errors,
            flash,
            info,
            program,
            prog,
            image,
            logic,
            forced_inputs,
            waves,
            flash_fail,
            faults,
            // Where the flash is kept (`state=`), from the device URL; a restore writes the
            // restored flash there.
            state_path: _,
            rx,
            out,
            // When the line is next free: at or before now once `out` is empty (checked).
            line_free: _,
            lose_reply,
            cycle,
            program_cycles,
            max_program_counts,
            // Counts of bytes, commands and binaries the line carried: the link's traffic
            // (tests and a server's note read them), not the controller's state.
            received: _,
            commands: _,
            binaries: _,
        } = &*self;
        if *monitor {
            return Err(msg!("umpk-snap-monitor").text);
        }
        if *prog != Programming::default() || *mode == Mode::Programming {
            return Err(msg!("umpk-snap-programming").text);
        }
        if !rx.is_empty() || !out.is_empty() || *lose_reply {
            return Err(msg!("umpk-snap-line-busy").text);
        }
        let program = match program {
            Program::None => ProgramState::None,
            Program::Binary => ProgramState::Binary,
            Program::Logic(r) => ProgramState::Il(Box::new(
                r.save().ok_or_else(|| msg!("umpk-snap-builtin-program", program = r.name()).text)?,
            )),
        };
        let (mode, until) = match *mode {
            Mode::Resetting(t) => ("restarting".to_string(), t.as_nanos() as u64),
            m => (m.name().to_string(), 0),
        };
        let Image { inputs, outputs, markers, timers, counters } = *image;
        Ok(UmpkState {
            model: model.name.into(),
            mode,
            restart_until_ns: until,
            echo: *echo,
            echo_off_by_command: *echo_off_by_command,
            errors: errors.to_vec(),
            flash: flash.iter().map(|b| format!("{b:02X}")).collect(),
            info: String::from_utf8_lossy(info).into_owned(),
            program,
            inputs,
            outputs,
            markers: format!("{markers:032X}"),
            timer_bits: timers,
            counter_bits: counters,
            logic: logic.clone(),
            forced_inputs: *forced_inputs,
            waves: waves.clone(),
            cycle: *cycle,
            program_cycles: *program_cycles,
            max_program_counts: *max_program_counts,
            flash_fail: *flash_fail,
            faults: faults.clone(),
        })
    }

    /// Restores a saved state (same model); the IL program is compiled again from its text.
    pub fn restore_snapshot(&mut self, s: &UmpkState) -> Result<(), String> {
        if s.model != self.model.name {
            return Err(msg!("umpk-snap-other-model", saved = &s.model, model = self.model.name).text);
        }
        let flash: Option<Vec<u8>> =
            s.flash.as_bytes().chunks(2).map(crate::umpk::codec::hex_pair).collect::<Option<_>>();
        let flash = flash.filter(|f| f.len() == self.flash.len()).ok_or_else(|| msg!("umpk-snap-flash-size").text)?;
        if s.info.len() != self.info.len() || s.errors.len() != self.errors.len() {
            return Err(msg!("umpk-snap-info-size").text);
        }
        let markers = u128::from_str_radix(&s.markers, 16).map_err(|_| msg!("umpk-snap-markers").text)?;
        if s.logic.timers.len() != self.logic.timers.len() || s.logic.counters.len() != self.logic.counters.len() {
            return Err(msg!("umpk-snap-timers").text);
        }
        if let Some(w) = s.waves.iter().find(|w| w.input >= self.model.inputs || w.period < 2) {
            return Err(msg!("umpk-snap-wave", input = w.input, period = w.period).text);
        }
        if let Some(p) = s.flash_fail.filter(|&p| p >= self.model.program_bytes / crate::umpk::model::PAGE) {
            return Err(msg!("umpk-snap-flash-fail-page", page = p).text);
        }
        if let Some(f) = s.faults.list.iter().find(|f| match f.kind {
            crate::core::sim_faults::FaultKind::Stuck { input, .. } => input >= u16::from(self.model.inputs),
            crate::core::sim_faults::FaultKind::NoReply => false,
        }) {
            return Err(msg!("umpk-snap-fault-input", fault = f.id.to_string()).text);
        }
        if s.cycle > self.clock.now().as_millis() as u64 / super::logic::CYCLE_MS + 1 {
            return Err(msg!("umpk-snap-cycle-ahead").text);
        }
        let mode = match s.mode.as_str() {
            "Work" => Mode::Work,
            "Wait" => Mode::Wait,
            "restarting" => Mode::Resetting(Duration::from_nanos(s.restart_until_ns)),
            other => return Err(msg!("umpk-snap-mode", mode = other).text),
        };
        let program = match &s.program {
            ProgramState::None => Program::None,
            ProgramState::Binary => Program::Binary,
            ProgramState::Il(il) => {
                let mut r = super::program::IlRunner::load(&il.text, &il.source, self.model)
                    .map_err(|e| msg!("umpk-snap-il-compile", source = &il.source, reason = e.to_string()).text)?;
                check_cpu(&r.cpu, &il.cpu)?;
                r.cpu = il.cpu.clone();
                r.fault = il.fault.clone();
                r.set_last_ns(il.last_ns);
                Program::Logic(Box::new(r) as Box<dyn Runner>)
            }
        };
        self.flash = flash;
        self.info.copy_from_slice(s.info.as_bytes());
        self.errors.copy_from_slice(&s.errors);
        self.program = program;
        self.mode = mode;
        self.echo = s.echo;
        self.echo_off_by_command = s.echo_off_by_command;
        self.monitor = false;
        self.prog = Programming::default();
        self.image =
            Image { inputs: s.inputs, outputs: s.outputs, markers, timers: s.timer_bits, counters: s.counter_bits };
        self.logic = s.logic.clone();
        self.forced_inputs = s.forced_inputs;
        self.waves = s.waves.clone();
        self.cycle = s.cycle;
        self.program_cycles = s.program_cycles;
        self.max_program_counts = s.max_program_counts;
        self.flash_fail = s.flash_fail;
        self.faults = s.faults.clone();
        self.lose_reply = false;
        self.rx.clear();
        self.out.clear();
        let now = self.clock.now();
        self.line_free = now;
        self.persist();
        Ok(())
    }
}

/// A saved scan-engine state fits the program compiled again: the same number of edges,
/// timers, counters and instruction instances, and saved between scans (no open parentheses,
/// calls or resume point) — a damaged or foreign snapshot is refused, never run.
fn check_cpu(fresh: &Cpu, saved: &Cpu) -> Result<(), String> {
    let (a, b) = (serde_json::to_value(fresh).unwrap_or_default(), serde_json::to_value(saved).unwrap_or_default());
    let len = |v: &serde_json::Value, k: &str| v[k].as_array().map(Vec::len);
    for k in ["edges", "timers", "counters", "special_en", "attached"] {
        if len(&a, k) != len(&b, k) {
            return Err(msg!("umpk-snap-il-state", part = k).text);
        }
    }
    for k in ["parens", "calls"] {
        if len(&b, k) != Some(0) {
            return Err(msg!("umpk-snap-il-mid-scan-part", part = k).text);
        }
    }
    if !b["pc"].is_null() {
        return Err(msg!("umpk-snap-il-mid-scan").text);
    }
    Ok(())
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::core::Clock;
    use std::time::Duration;

    const LAB: &str = "LD I0\nOR Q0\nANDN I1\nST Q0\nLD Q0\nTIMER T0, 1, 20\nST Q1\n";

    fn umpk(clock: &Clock) -> Umpk {
        let m = &crate::umpk::model::MODELS[1];
        let mut u = Umpk::new(m, clock.clone());
        u.load_logic(Box::new(super::super::program::IlRunner::load(LAB, "lab.il", m).unwrap()));
        u
    }

    #[test]
    fn a_running_il_program_continues_exactly_after_a_restore() {
        let clock = Clock::stepped();
        let mut a = umpk(&clock);
        a.set_input(0, true);
        clock.step(Duration::from_millis(1000));
        a.advance(clock.now());
        let saved = a.snapshot_state().unwrap();
        let text = serde_json::to_string(&saved).unwrap();
        clock.step(Duration::from_millis(1500));
        a.advance(clock.now());
        assert!(a.image.output(1), "Q1 on 2 s after the start");
        // Back to 1 s, on a controller that never ran the program.
        clock.set(Duration::from_millis(1000));
        let mut b = Umpk::new(&crate::umpk::model::MODELS[1], clock.clone());
        b.restore_snapshot(&serde_json::from_str(&text).unwrap()).unwrap();
        assert!(b.image.output(0) && !b.image.output(1));
        clock.step(Duration::from_millis(1500));
        b.advance(clock.now());
        assert!(b.image.output(1));
        assert_eq!(b.errors, a.errors);
    }

    /// An injected fault is the controller's state: a UMPK saved while `fault stuck I1=1`
    /// holds its input keeps it held after a restore, numbers its next fault alike and keeps
    /// its failing flash page.
    #[test]
    fn injected_faults_are_saved_and_restored() {
        let clock = Clock::stepped();
        let mut a = umpk(&clock);
        a.set_input(0, true);
        clock.step(Duration::from_millis(1000));
        super::super::control::answer(&mut a, "fault stuck I1=1 for=500ms").unwrap();
        super::super::control::answer(&mut a, "flash-fail 3").unwrap();
        let text = serde_json::to_string(&a.snapshot_state().unwrap()).unwrap();
        clock.step(Duration::from_millis(1500));
        a.advance(clock.now());
        assert!(a.image.output(0) && !a.image.output(1), "I1 held Q0 off until 1.5 s: Q1's delay starts again");
        clock.set(Duration::from_millis(1000));
        let mut b = Umpk::new(&crate::umpk::model::MODELS[1], clock.clone());
        b.restore_snapshot(&serde_json::from_str(&text).unwrap()).unwrap();
        clock.step(Duration::from_millis(1500));
        b.advance(clock.now());
        assert_eq!((b.image.outputs, b.image.inputs), (a.image.outputs, a.image.inputs), "as the uninterrupted run");
        assert_eq!(b.faults, a.faults);
        assert_eq!(b.flash_fail, Some(3));
        let (next_a, next_b) = (
            super::super::control::answer(&mut a, "fault no-reply").unwrap().1,
            super::super::control::answer(&mut b, "fault no-reply").unwrap().1,
        );
        assert_eq!(next_a["id"], next_b["id"], "the next fault is numbered alike");
    }

    #[test]
    fn what_a_snapshot_cannot_hold_is_refused_by_name() {
        let clock = Clock::stepped();
        let mut u = umpk(&clock);
        u.monitor = true;
        assert!(u.snapshot_state().unwrap_err().contains("monitor"));
        u.monitor = false;
        u.rx.push(b'I');
        assert!(u.snapshot_state().unwrap_err().contains("serial line"));
        let mut other = Umpk::new(&crate::umpk::model::MODELS[0], clock.clone());
        u.rx.clear();
        let st = u.snapshot_state().unwrap();
        assert!(other.restore_snapshot(&st).unwrap_err().contains("UMPK16"));
    }
}
