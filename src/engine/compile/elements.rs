//! Compiling the timer and counter instructions (S7-200 System Manual "Timer
//! Instructions", "Counter Instructions"; the family names its elements, [`Family::element`]):
//! `TON`/`TOF`/`TONR`, `CTU`/`CTD`/`CTUD`, each element numbered into the CPU's state slots,
//! and their presets — a `T#…` duration converted to the timer's units, rounded up with a
//! load warning, never shorter than asked.

use super::operands::Raw;
use super::{Ctx, Ins};
use crate::core::literal::parse_literal;
use crate::core::{DataType, Result};
use crate::engine::isa::{CounterKind, TimerKind};
use crate::engine::source::OperandText;
use crate::engine::{Element, Family, Opd};
use crate::msg;

impl<F: Family + ?Sized> Ctx<'_, F> {
    /// `TON T37, PT[, R]`.
    pub(super) fn timer(&mut self, kind: TimerKind, ops: &[OperandText]) -> Result<Ins> {
        let (el, slot) = self.element(&ops[0], true)?;
        let pt = self.preset(&ops[1], Some(el.base_ns))?;
        let reset = match ops.get(2) {
            Some(o) => Some(self.bit(o)?),
            None => None,
        };
        Ok(Ins::Timer { kind, slot, el: Box::new(el), pt, reset })
    }

    /// `CTU C0, PV[, R]`, `CTUD C0, PV, CD[, R]`.
    pub(super) fn counter(&mut self, kind: CounterKind, ops: &[OperandText]) -> Result<Ins> {
        let (el, slot) = self.element(&ops[0], false)?;
        let pv = self.preset(&ops[1], None)?;
        let (second, reset) = match kind {
            CounterKind::Ctud => (Some(self.bit(&ops[2])?), ops.get(3).map(|o| self.bit(o)).transpose()?),
            _ => (None, ops.get(2).map(|o| self.bit(o)).transpose()?),
        };
        Ok(Ins::Counter { kind, slot, el: Box::new(el), pv, second, reset })
    }

    pub(super) fn element(&mut self, o: &OperandText, timer: bool) -> Result<(Element, u32)> {
        let el = self.fam.element(&o.text, timer).map_err(|e| {
            let mut x = self.e(o.pos, format!("{}: {}", o.text, e.message));
            if let Some(h) = e.hint {
                x = x.hint(h);
            }
            x
        })?;
        let slots = if timer { &mut self.timer_slots } else { &mut self.counter_slots };
        let next = slots.len() as u32;
        let slot = *slots.entry(el.number).or_insert(next);
        if timer {
            self.prog.timers = self.timer_slots.len() as u32;
        } else {
            self.prog.counters = self.counter_slots.len() as u32;
        }
        Ok((el, slot))
    }

    /// A timer preset or counter preset: INT operand or literal; `T#…` literals are
    /// converted to the timer's units.
    fn preset(&mut self, o: &OperandText, base_ns: Option<u64>) -> Result<Opd> {
        let r = self.raw(o)?;
        if let (Raw::Lit(t), Some(base)) = (&r, base_ns) {
            if t.to_ascii_uppercase().starts_with("T#") {
                let lit = parse_literal(t).map_err(|e| self.e(o.pos, format!("{t}: {}", e.message)))?;
                let ms = lit.value.as_i64();
                // In i128 to the end: a long T# on a fine time base must be refused, not
                // truncated back into 0…32767.
                // A delay is never shorter than asked: a duration between two units rounds up
                // (T#250ms on a 100 ms timer is 3 units, 300 ms), with a load warning.
                let base = base.max(1) as i128;
                let ns = ms as i128 * 1_000_000;
                let units = (ns + base - 1).div_euclid(base);
                if !(0..=32767).contains(&units) {
                    let longest = 32767 * base / 1_000_000;
                    return Err(self.e_m(
                        o.pos,
                        msg!(
                            "engine-timer-preset-range",
                            time = t,
                            units = units as i64,
                            base = (base / 1_000_000).to_string(),
                            longest = format!("{}.{:03}", longest / 1000, longest % 1000)
                        ),
                    ));
                }
                if units * base != ns {
                    let got = units * base / 1_000_000;
                    let m = msg!(
                        "engine-timer-rounded",
                        time = t,
                        base = (base / 1_000_000).to_string(),
                        got = got.to_string(),
                        units = units as i64
                    );
                    self.prog.warnings.push(format!("{}:{}:{}: {m}", self.prog.file, o.pos.line, o.pos.col));
                }
                return Ok(Opd::Imm(units as u16 as u32));
            }
        }
        self.typed(o, &r, DataType::Int)
    }
}
