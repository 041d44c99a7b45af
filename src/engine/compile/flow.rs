//! Compiling the program-flow and interrupt instructions (S7-200 System Manual "Program
//! Control", "Interrupt Instructions"): `FOR` (its `NEXT` is bound by the POU loop in
//! [`super::compile`]), jumps and calls (their labels and POUs are bound after the POU, or
//! the file, is read: here they are only remembered), `ATCH` and `DTCH`.

use super::arith::signed;
use super::{Ctx, Ins};
use crate::core::{DataType, Result};
use crate::engine::isa::{Kind, TyHint};
use crate::engine::source::{OperandText, Pos};
use crate::engine::{Family, Opd};
use crate::msg;

impl<F: Family + ?Sized> Ctx<'_, F> {
    /// `FOR INDX, INIT, FINAL`: INT or DINT; its end is filled in at the matching `NEXT`.
    pub(super) fn for_loop(&self, m: &str, ops: &[OperandText], pos: Pos) -> Result<Ins> {
        let indx = self.raw(&ops[0])?;
        self.out_loc(&ops[0], &indx)?;
        let (init, fin) = (self.raw(&ops[1])?, self.raw(&ops[2])?);
        let t = signed(self.value_ty(m, TyHint::Auto, &[(&ops[0], &indx), (&ops[1], &init), (&ops[2], &fin)])?);
        if !matches!(t, DataType::Int | DataType::DInt) {
            return Err(self.e(pos, format!("{m}: INDX, INIT and FINAL are INT or DINT")));
        }
        Ok(Ins::For {
            ty: t,
            indx: self.typed(&ops[0], &indx, t)?,
            init: self.typed(&ops[1], &init, t)?,
            fin: self.typed(&ops[2], &fin, t)?,
            end: 0,
        })
    }

    /// `JMP n` / `JMPC n`: the label is bound when the POU is read.
    pub(super) fn jump(kind: Kind, ops: &[OperandText], here: usize, jumps: &mut Vec<(usize, String, Pos)>) -> Ins {
        jumps.push((here, Self::name(&ops[0]), ops[0].pos));
        match kind {
            Kind::Jmpc { neg } => Ins::Jmpc { to: 0, neg },
            _ => Ins::Jmp { to: 0 },
        }
    }

    /// `CALL name` / `CALLC name`: the POU is bound when the file is read.
    pub(super) fn call(kind: Kind, ops: &[OperandText], here: usize, calls: &mut Vec<(usize, String, Pos)>) -> Ins {
        calls.push((here, Self::name(&ops[0]), ops[0].pos));
        let cond = match kind {
            Kind::Calc { neg } => Some(!neg),
            // KincoBuilder runs a subroutine box when its EN (the CR) is on.
            _ => Some(true),
        };
        Ins::Cal { pou: 0, cond }
    }

    /// `ATCH INT, EVENT`: a constant event must be one the family has.
    pub(super) fn atch(&self, ops: &[OperandText], here: usize, calls: &mut Vec<(usize, String, Pos)>) -> Result<Ins> {
        calls.push((here, Self::name(&ops[0]), ops[0].pos));
        let r = self.raw(&ops[1])?;
        let event = self.typed(&ops[1], &r, DataType::Int)?;
        if let Opd::Imm(v) = event {
            if (v as i16) < 0 || !self.fam.event_exists(v as i16 as u32) {
                return Err(self.e_m(
                    ops[1].pos,
                    msg!("engine-no-event", event = (v as i16).to_string(), events = self.fam.event_list()),
                ));
            }
        }
        Ok(Ins::Atch { pou: 0, event })
    }

    /// `DTCH EVENT`.
    pub(super) fn dtch(&self, ops: &[OperandText]) -> Result<Ins> {
        let r = self.raw(&ops[0])?;
        Ok(Ins::Dtch { event: self.typed(&ops[0], &r, DataType::Int)? })
    }
}
