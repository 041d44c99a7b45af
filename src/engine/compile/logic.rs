//! Compiling the bit-logic instructions that take more than a bit operand: parentheses,
//! set and reset (of bits, and `R` of a timer or counter, S7-200 `R T37, 1`), edge
//! detection and comparisons (`LDW=`, `AD<`, `OR>` …, S7-200 System Manual "Compare
//! Instructions"). The one-line ones (LD, A, O, =, NOT, the logic stack) are in
//! [`super::Ctx::core`].

use super::operands::hint_ty;
use super::{Ctx, Ins};
use crate::core::{DataType, Result};
use crate::engine::isa::{Cmp, Comb, Logic, TyHint};
use crate::engine::source::OperandText;
use crate::engine::Family;

impl<F: Family + ?Sized> Ctx<'_, F> {
    /// `A(`, `O(`, `X(` …: a parenthesis, optionally loading its first bit.
    pub(super) fn par_open(&self, op: Logic, neg: bool, ops: &[OperandText]) -> Result<Ins> {
        let load = match ops.first() {
            Some(o) => Some(self.bit(o)?),
            None => None,
        };
        Ok(Ins::ParOpen { op, neg, load })
    }

    /// `S bit, n` / `R bit, n`; `R` of a timer or counter clears it.
    pub(super) fn set_reset(&mut self, on: bool, ops: &[OperandText]) -> Result<Ins> {
        // A timer or counter operand: R clears it (S7-200 `R T37, 1`).
        let up = ops[0].text.trim_start_matches('%').to_ascii_uppercase();
        if !on && (up.starts_with('T') || up.starts_with('C')) && up[1..].chars().all(|c| c.is_ascii_digit()) {
            let timer = up.starts_with('T');
            let (el, slot) = self.element(&ops[0], timer)?;
            return Ok(Ins::ResetElem { timer, slot, cv: el.cv, q: el.q });
        }
        let n = match ops.get(1) {
            Some(o) => self.count(o)?,
            None => 1,
        };
        Ok(Ins::Set { loc: self.bit(&ops[0])?, n, on })
    }

    /// `EU` / `ED` (R_TRIG / F_TRIG): each gets its own edge memory.
    pub(super) fn edge(&mut self, rising: bool) -> Ins {
        let slot = self.prog.edges;
        self.prog.edges += 1;
        Ins::Edge { slot, rising }
    }

    /// A comparison contact: the mnemonic's type, else the operands'.
    pub(super) fn compare(&self, comb: Comb, ty: TyHint, op: Cmp, ops: &[OperandText]) -> Result<Ins> {
        let (a, b) = (self.raw(&ops[0])?, self.raw(&ops[1])?);
        let t = match hint_ty(ty) {
            Some(t) => t,
            None => Self::own_ty(&a).or(Self::own_ty(&b)).unwrap_or(DataType::Int),
        };
        // `LDW` compares INT; a WORD operand compares as its bits (same width).
        Ok(Ins::Compare { comb, op, ty: t, a: self.typed(&ops[0], &a, t)?, b: self.typed(&ops[1], &b, t)? })
    }
}
