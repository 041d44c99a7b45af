//! Typed helpers for the K2's special functions: `pto`, `pwm`, `profile`, `hsc` and the
//! status decoders. Each is split in two:
//!
//! - **planning** is pure: from a typed request and the model it validates everything and
//!   returns a [`Plan`] — the exact register writes (SMB67, SMW68, the profile table …) and
//!   the instructions to run after them (PLS, HDEF, HSC). Nothing is written when planning
//!   fails, so bad input changes nothing.
//! - **execution** ([`execute`]) goes only through [`Device`] and [`K2Ops`], so the same
//!   helpers will drive a real PLC once its wire driver implements `K2Ops`.
//!
//! Every execution returns the writes it made ([`Written`]) so the user learns the raw
//! registers behind the helper.

pub mod hsc;
pub mod pto;

use super::operand::{Area, K2Operand};
use super::K2Ops;
use crate::core::device::Change;
use crate::core::{DataType, Device, Error, ErrorKind, Result, Value};
use crate::msg;

/// An instruction a plan runs after its writes.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Instr {
    Pls(u8),
    Hdef(u8, u8),
    Hsc(u8),
}

impl Instr {
    /// What the instruction changes, for the write rules ([`super::changes`]).
    pub fn change(&self, model: &super::catalog::Model) -> Change {
        match *self {
            Instr::Pls(q) => super::changes::instruction(model, "PLS", q),
            Instr::Hdef(n, _) => super::changes::instruction(model, "HDEF", n),
            Instr::Hsc(n) => super::changes::instruction(model, "HSC", n),
        }
    }
}

impl std::fmt::Display for Instr {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        match self {
            Instr::Pls(q) => write!(f, "PLS {q}"),
            Instr::Hdef(n, m) => write!(f, "HDEF {n}, {m}"),
            Instr::Hsc(n) => write!(f, "HSC {n}"),
        }
    }
}

/// What a helper will do: writes in order, then instructions.
#[derive(Clone, Debug, Default, PartialEq)]
pub struct Plan {
    pub writes: Vec<(K2Operand, Value)>,
    pub then: Vec<Instr>,
    /// Facts worth telling the user (rounding, chosen time base …).
    pub notes: Vec<String>,
}

impl Plan {
    pub fn byte(&mut self, area: Area, at: u32, v: i64) {
        self.writes.push((K2Operand::byte(area, at), Value::Int(v)));
    }
    pub fn word(&mut self, area: Area, at: u32, v: i64) {
        self.writes.push((K2Operand::word(area, at), Value::Int(v)));
    }
    pub fn dword(&mut self, area: Area, at: u32, v: i64) {
        self.writes.push((K2Operand::dword(area, at), Value::Int(v)));
    }
    /// A signed double word (`SMD38/DINT`).
    pub fn dint(&mut self, area: Area, at: u32, v: i64) {
        let mut op = K2Operand::dword(area, at);
        op.view = DataType::DInt;
        self.writes.push((op, Value::Int(v)));
    }
    /// The value planned for `op`, if any (for tests and previews).
    pub fn value_of(&self, text: &str) -> Option<i64> {
        self.writes.iter().rev().find(|(o, _)| o.canonical() == text).map(|(_, v)| v.as_i64())
    }
}

/// One write a helper made, for output.
#[derive(Clone, Debug, PartialEq)]
pub struct Written {
    pub operand: String,
    pub value: Value,
    pub dtype: DataType,
}

/// What an executed plan did.
#[derive(Clone, Debug, Default)]
pub struct Done {
    pub writes: Vec<Written>,
    /// One line per instruction run (the device's report).
    pub reports: Vec<String>,
    pub notes: Vec<String>,
}

/// Runs a plan on a device: checks every value, writes in one batch, then runs the
/// instructions through [`K2Ops`].
pub fn execute(dev: &mut dyn Device, plan: &Plan) -> Result<Done> {
    let space = dev.operands();
    let mut items = Vec::with_capacity(plan.writes.len());
    for (op, v) in &plan.writes {
        let core = op.to_core();
        let v = space.check(&core, *v).map_err(|e| e.operand(op.canonical()))?;
        items.push((core, v));
    }
    if !plan.then.is_empty() && super::ops(dev).is_none() {
        return Err(Error::unsupported(msg!("k2-not-a-k2")));
    }
    // The whole plan goes past the write rules first: refused whole, nothing sent.
    let mut changes: Vec<Change> = items.iter().map(|(op, _)| Change::Write(*op)).collect();
    if let Some(model) = super::ops(dev).map(|k| k.model()) {
        changes.extend(plan.then.iter().map(|i| i.change(model)));
    }
    dev.permits(&changes)?;
    dev.write(&items)?;
    let mut done = Done { notes: plan.notes.clone(), ..Default::default() };
    for ((op, v), (core, _)) in plan.writes.iter().zip(&items) {
        done.writes.push(Written { operand: op.canonical(), value: *v, dtype: core.dtype });
    }
    let mut access = super::ops(dev).expect("checked above");
    let k2: &mut dyn K2Ops = &mut access;
    for i in &plan.then {
        let r = match *i {
            Instr::Pls(q) => k2.pls(q),
            Instr::Hdef(n, m) => k2.hdef(n, m),
            Instr::Hsc(n) => k2.hsc(n),
        };
        done.reports.push(r?);
    }
    Ok(done)
}

/// Reads SM/V registers for a status decoder.
pub(crate) fn read_ops(dev: &mut dyn Device, ops: &[K2Operand]) -> Result<Vec<Written>> {
    let core: Vec<_> = ops.iter().map(|o| o.to_core()).collect();
    let vals = dev.read(&core)?;
    Ok(ops
        .iter()
        .zip(core.iter().zip(vals))
        .map(|(o, (c, v))| Written { operand: o.canonical(), value: v, dtype: c.dtype })
        .collect())
}

pub use crate::core::literal::parse_freq_hz;

/// A pulse cycle or width: a bare number is µs (the units table), else `500us`, `1ms`, `2s`.
pub fn parse_us(text: &str) -> std::result::Result<u64, String> {
    let us = crate::core::literal::parse_pulse_time_us(text)?;
    if us <= 0 {
        return Err(msg!("k2-duration-not-positive", text = text).into());
    }
    Ok(us as u64)
}

/// A value error naming the option.
pub(crate) fn bad(option: &str, msg: impl Into<crate::core::error::Text>) -> Error {
    Error::new(ErrorKind::Value, msg).operand(option.to_string())
}

/// Does V range `first..=last` overlap the E2PROM backup area (§2.2.8)?
pub fn overlaps_backup(first: u32, last: u32, backup: (u32, u32)) -> bool {
    first <= backup.1 && backup.0 <= last
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::core::Clock;
    use std::time::Duration;

    fn read(sim: &mut dyn Device, text: &str) -> i64 {
        let op = sim.operands().parse(text).unwrap()[0];
        sim.read(&[op]).unwrap()[0].as_i64()
    }

    #[test]
    fn a_profile_plan_runs_on_the_simulator_for_exactly_its_timeline() {
        let clock = Clock::stepped();
        let mut sim = crate::k2::sim::open("K205-16DT", clock.clone()).unwrap();
        let segs = [(500, 1000), (250, 4000), (40, 7), (1000, 2)]
            .map(|(c, n)| pto::Segment { rate: pto::Rate::CycleUs(c), count: n });
        let pr = pto::plan_profile(sim.model(), 0, 3001, &segs, false, (3648, 3902)).unwrap();
        let t = pto::timeline(&pr.table, pr.base_ms);
        assert_eq!(t.total_pulses, segs.iter().map(|s| s.count).sum::<u64>());
        let done = execute(&mut sim, &pr.plan).unwrap();
        assert_eq!(done.writes.len(), pr.plan.writes.len());
        assert_eq!(done.writes[0].operand, "VB3001");
        assert_eq!(done.writes.last().unwrap().operand, "SMB67");
        assert!(done.reports[0].contains("4 segments"), "{:?}", done.reports);
        clock.step(Duration::from_micros(t.duration_us - 1));
        assert_eq!(read(&mut sim, "SM66.7"), 0);
        clock.step(Duration::from_micros(1));
        assert_eq!(read(&mut sim, "SM66.7"), 1);
        assert_eq!(read(&mut sim, "SMD212") as u64, t.total_pulses);
    }

    #[test]
    fn a_refused_instruction_reports_after_the_writes() {
        let clock = Clock::stepped();
        let mut sim = crate::k2::sim::open("K205-16DT", clock).unwrap();
        let mut p = Plan::default();
        p.byte(Area::SM, 67, 0x85);
        p.then.push(Instr::Pls(0));
        let e = execute(&mut sim, &p).unwrap_err();
        assert!(e.message.contains("below 2"), "{e}");
        let mut bad_plan = Plan::default();
        bad_plan.byte(Area::V, 0, 300);
        assert!(execute(&mut sim, &bad_plan).is_err(), "a value that does not fit is refused before writing");
        assert_eq!(read(&mut sim, "VB0"), 0);
    }

    #[test]
    fn durations() {
        assert_eq!(parse_us("500us").unwrap(), 500);
        assert_eq!(parse_us("1ms").unwrap(), 1000);
        assert!(parse_us("0ms").is_err());
    }
}
