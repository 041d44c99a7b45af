//! Compiling the arithmetic and word instructions (S7-200 System Manual "Integer Math",
//! "Floating-Point Math", "Logical Operations", "Shift and Rotate", "Conversion"): `+I` … `/R`,
//! `MOD`, `INC`/`DEC`, `SHL`/`SHR`/`ROL`/`ROR`, `WAND`/`WOR`/`WXOR`, `INV`, `SQRT`/`ABS` and
//! the conversions. Arithmetic on WORD/DWORD operands is INT/DINT arithmetic ([`signed`]).

use super::operands::Raw;
use super::{Ctx, Ins};
use crate::core::{DataType, Result};
use crate::engine::isa::{Arith, Conv, Logic, Shift, TyHint, Unary};
use crate::engine::source::{OperandText, Pos};
use crate::engine::{Family, Opd};
use crate::msg;

impl<F: Family + ?Sized> Ctx<'_, F> {
    /// `+I IN1, IN2, OUT` (or `IN, OUT`: OUT := OUT op IN).
    pub(super) fn arith(&self, m: &str, op: Arith, ty: TyHint, ops: &[OperandText], pos: Pos) -> Result<Ins> {
        let (t, a, b, out) = self.binary(ops, |all| {
            let t = signed(self.value_ty(m, ty, all)?);
            if t == DataType::Bool {
                return Err(self.e_m(pos, msg!("engine-numbers-not-bits", mnemonic = m)));
            }
            Ok(t)
        })?;
        Ok(Ins::Arith { op, ty: t, a, b, out })
    }

    /// `INC…` / `DEC… OUT`.
    pub(super) fn inc_dec(&self, m: &str, inc: bool, ty: TyHint, ops: &[OperandText]) -> Result<Ins> {
        let out = self.raw(&ops[0])?;
        self.out_loc(&ops[0], &out)?;
        let t = signed(self.value_ty(m, ty, &[(&ops[0], &out)])?);
        Ok(Ins::IncDec { inc, ty: t, out: self.typed(&ops[0], &out, t)? })
    }

    /// `SHL… OUT, N` and the rotations.
    pub(super) fn shift(&self, m: &str, op: Shift, ops: &[OperandText]) -> Result<Ins> {
        let out = self.raw(&ops[0])?;
        self.out_loc(&ops[0], &out)?;
        let t = self.value_ty(m, TyHint::Auto, &[(&ops[0], &out)])?;
        let n = self.raw(&ops[1])?;
        Ok(Ins::Shift { op, ty: t, out: self.typed(&ops[0], &out, t)?, n: self.typed(&ops[1], &n, DataType::Byte)? })
    }

    /// `WAND IN1, IN2, OUT` (or `IN, OUT`).
    pub(super) fn word_logic(&self, m: &str, op: Logic, ops: &[OperandText]) -> Result<Ins> {
        let (t, a, b, out) = self.binary(ops, |all| self.value_ty(m, TyHint::Auto, all))?;
        Ok(Ins::WordLogic { op, ty: t, a, b, out })
    }

    /// The operands of `OP IN1, IN2, OUT` or `OP IN, OUT` (OUT := OUT op IN): the output
    /// checked first, then the inputs, all typed as `ty_of` decides from them (the output
    /// first): the type and the operands `a`, `b`, `out`.
    fn binary(
        &self,
        ops: &[OperandText],
        ty_of: impl FnOnce(&[(&OperandText, &Raw)]) -> Result<DataType>,
    ) -> Result<(DataType, Opd, Opd, Opd)> {
        let out_o = ops.last().unwrap();
        let out = self.raw(out_o)?;
        self.out_loc(out_o, &out)?;
        let ins: Vec<Raw> = ops[..ops.len() - 1].iter().map(|o| self.raw(o)).collect::<Result<_>>()?;
        let mut all: Vec<(&OperandText, &Raw)> = vec![(out_o, &out)];
        all.extend(ops.iter().zip(ins.iter()));
        let t = ty_of(&all)?;
        let outd = self.typed(out_o, &out, t)?;
        let (a, b) = if ins.len() == 1 {
            (outd, self.typed(&ops[0], &ins[0], t)?)
        } else {
            (self.typed(&ops[0], &ins[0], t)?, self.typed(&ops[1], &ins[1], t)?)
        };
        Ok((t, a, b, outd))
    }

    /// `INV… OUT`.
    pub(super) fn inv(&self, m: &str, ops: &[OperandText]) -> Result<Ins> {
        let out = self.raw(&ops[0])?;
        self.out_loc(&ops[0], &out)?;
        let t = self.value_ty(m, TyHint::Auto, &[(&ops[0], &out)])?;
        Ok(Ins::Inv { ty: t, out: self.typed(&ops[0], &out, t)? })
    }

    /// `SQRT IN, OUT` (REAL) and `ABS IN, OUT`.
    pub(super) fn unary(&self, m: &str, op: Unary, ops: &[OperandText], pos: Pos) -> Result<Ins> {
        let (a, out) = (self.raw(&ops[0])?, self.raw(&ops[1])?);
        self.out_loc(&ops[1], &out)?;
        let t = match op {
            Unary::Sqrt => DataType::Real,
            Unary::Abs => signed(self.value_ty(m, TyHint::Auto, &[(&ops[1], &out), (&ops[0], &a)])?),
        };
        if t == DataType::Bool || t == DataType::Byte {
            return Err(self.e_m(pos, msg!("engine-int-dint-real", mnemonic = m)));
        }
        Ok(Ins::Unary { op, ty: t, a: self.typed(&ops[0], &a, t)?, out: self.typed(&ops[1], &out, t)? })
    }

    /// A conversion `I_DI IN, OUT` …: each has its input and output types.
    pub(super) fn conv(&self, c: Conv, ops: &[OperandText]) -> Result<Ins> {
        let (ti, to) = conv_types(c);
        let (a, out) = (self.raw(&ops[0])?, self.raw(&ops[1])?);
        self.out_loc(&ops[1], &out)?;
        Ok(Ins::Conv { c, a: self.typed(&ops[0], &a, ti)?, out: self.typed(&ops[1], &out, to)? })
    }
}

/// Arithmetic on a WORD or DWORD operand is INT or DINT arithmetic (S7-200 `+I`, `+D`:
/// VW and VD hold signed numbers for the arithmetic instructions).
pub(super) fn signed(t: DataType) -> DataType {
    match t {
        DataType::Word => DataType::Int,
        DataType::DWord => DataType::DInt,
        t => t,
    }
}

fn conv_types(c: Conv) -> (DataType, DataType) {
    use DataType as T;
    match c {
        Conv::IDi => (T::Int, T::DInt),
        Conv::DiI => (T::DInt, T::Int),
        Conv::BI => (T::Byte, T::Int),
        Conv::IB => (T::Int, T::Byte),
        Conv::DiR => (T::DInt, T::Real),
        Conv::Round | Conv::Trunc => (T::Real, T::DInt),
        Conv::IBcd | Conv::BcdI => (T::Int, T::Int),
    }
}
