//! Compiling the move instructions (S7-200 System Manual "Move Instructions"): `MOVB`,
//! `MOVW`, `MOVD`, `MOVR`, the block moves `BMB`/`BMW`/`BMD` and fills `FILL`, and `SWAP`.
//! The type is the mnemonic's, else the operands' ([`super::Ctx::value_ty`]).

use super::{Ctx, Ins};
use crate::core::{DataType, Result};
use crate::engine::isa::TyHint;
use crate::engine::source::OperandText;
use crate::engine::{Family, Opd};
use crate::msg;

impl<F: Family + ?Sized> Ctx<'_, F> {
    /// `MOV… IN, OUT`.
    pub(super) fn move_value(&self, m: &str, ty: TyHint, ops: &[OperandText]) -> Result<Ins> {
        let (a, out) = (self.raw(&ops[0])?, self.raw(&ops[1])?);
        self.out_loc(&ops[1], &out)?;
        let t = self.value_ty(m, ty, &[(&ops[1], &out), (&ops[0], &a)])?;
        Ok(Ins::Move { ty: t, a: self.typed(&ops[0], &a, t)?, out: self.typed(&ops[1], &out, t)? })
    }

    /// `BM… IN, OUT, N` (`hint`: the mnemonic's type) and `FILL IN, OUT, N` (`fill`).
    pub(super) fn block(&self, m: &str, hint: TyHint, fill: bool, ops: &[OperandText]) -> Result<Ins> {
        let (a, out) = (self.raw(&ops[0])?, self.raw(&ops[1])?);
        self.out_loc(&ops[1], &out)?;
        let t = self.value_ty(m, hint, &[(&ops[1], &out), (&ops[0], &a)])?;
        let n_raw = self.raw(&ops[2])?;
        let n = self.typed(&ops[2], &n_raw, DataType::Int)?;
        if let Opd::Imm(v) = n {
            if !(1..=255).contains(&(v as u16 as i16)) {
                return Err(self.e_m(ops[2].pos, msg!("engine-block-n", mnemonic = m, n = (v as i16).to_string())));
            }
        }
        Ok(Ins::Block { ty: t, a: self.typed(&ops[0], &a, t)?, out: self.typed(&ops[1], &out, t)?, n, fill })
    }

    /// `SWAP IN`: the bytes of a word.
    pub(super) fn swap(&self, ops: &[OperandText]) -> Result<Ins> {
        let out = self.raw(&ops[0])?;
        self.out_loc(&ops[0], &out)?;
        Ok(Ins::Swap { out: self.typed(&ops[0], &out, DataType::Word)? })
    }
}
