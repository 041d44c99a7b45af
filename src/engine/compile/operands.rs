//! Operands while compiling: text resolved through the family ([`Family::operand`],
//! [`Family::value_operand`], pointers `*VD4` and `&VB0`), literals fitted to the type the
//! instruction works on, bit operands, and the type a value instruction takes from its
//! mnemonic or its operands. Every instruction group's compiler uses these.

use super::Ctx;
use crate::core::literal::parse_literal;
use crate::core::msg::Msg;
use crate::core::{DataType, Result};
use crate::engine::isa::TyHint;
use crate::engine::source::OperandText;
use crate::engine::{Family, Loc, Opd, Width};
use crate::msg;

fn bits_of(ty: DataType) -> u32 {
    ty.bits()
}

/// The type a typed mnemonic fixes.
pub(super) fn hint_ty(h: TyHint) -> Option<DataType> {
    match h {
        TyHint::Byte => Some(DataType::Byte),
        TyHint::Int => Some(DataType::Int),
        TyHint::DInt => Some(DataType::DInt),
        TyHint::Real => Some(DataType::Real),
        TyHint::Auto => None,
    }
}

/// An operand before typing: a location (with its own type), a pointer deref, or literal text.
#[derive(Clone, Debug)]
pub(super) enum Raw {
    Loc(Loc, DataType, String),
    Ind(Loc),
    Lit(String),
    Ptr(u32),
}

impl<F: Family + ?Sized> Ctx<'_, F> {
    pub(super) fn raw(&self, o: &OperandText) -> Result<Raw> {
        let t = o.text.as_str();
        let fail = |e: crate::engine::OperandError| {
            let mut x = self.e(o.pos, format!("{t}: {}", e.message)).operand(t);
            if let Some(h) = e.hint {
                x = x.hint(h);
            }
            x
        };
        if let Some(rest) = t.strip_prefix('*') {
            let r = self.fam.operand(rest).map_err(fail)?;
            if r.loc.width != Width::DWord {
                return Err(self
                    .e_m(o.pos, msg!("engine-pointer-not-dword", operand = t, target = rest))
                    .hint(msg!("engine-pointer-not-dword-hint", index = r.loc.index)));
            }
            return Ok(Raw::Ind(r.loc));
        }
        if let Some(rest) = t.strip_prefix('&') {
            let r = self.fam.operand(rest).map_err(fail)?;
            let p = self.fam.pointer(r.loc).ok_or_else(|| {
                self.e_m(o.pos, msg!("engine-not-pointable", operand = t, target = &r.canonical))
                    .hint(msg!("engine-not-pointable-hint"))
            })?;
            return Ok(Raw::Ptr(p));
        }
        let first = t.chars().next().unwrap_or(' ');
        let upper = t.to_ascii_uppercase();
        if first.is_ascii_digit()
            || first == '-'
            || first == '+'
            || t.contains('#')
            || matches!(upper.as_str(), "TRUE" | "FALSE" | "ON" | "OFF")
        {
            return Ok(Raw::Lit(t.to_string()));
        }
        let r = self.fam.value_operand(t).map_err(fail)?;
        Ok(Raw::Loc(r.loc, r.ty, r.canonical))
    }

    /// Types a raw operand as `ty`: locations must have the same width; literals must fit.
    pub(super) fn typed(&self, o: &OperandText, r: &Raw, ty: DataType) -> Result<Opd> {
        match r {
            Raw::Loc(l, t, name) => {
                if bits_of(*t) != bits_of(ty) {
                    return Err(self
                        .e_m(o.pos, msg!("engine-operand-type", name = name, have = t.name(), want = ty.name()))
                        .operand(name.clone())
                        .hint(conversion_hint(*t, ty)));
                }
                Ok(Opd::Loc(*l))
            }
            Raw::Ind(l) => Ok(Opd::Ind(*l)),
            Raw::Ptr(p) => {
                if bits_of(ty) != 32 {
                    return Err(self.e_m(o.pos, msg!("engine-pointer-needs-dword", operand = &o.text)));
                }
                Ok(Opd::Imm(*p))
            }
            Raw::Lit(text) => Ok(Opd::Imm(self.literal(o, text, ty)?)),
        }
    }

    pub(super) fn literal(&self, o: &OperandText, text: &str, ty: DataType) -> Result<u32> {
        let lit = parse_literal(text).map_err(|e| self.e(o.pos, format!("{text}: {}", e.message)))?;
        let v = lit.fit(ty, ty.bits()).map_err(|m| self.e(o.pos, m))?;
        Ok(ty.encode(&v))
    }

    /// The type of an operand as written (locations only).
    pub(super) fn own_ty(r: &Raw) -> Option<DataType> {
        match r {
            Raw::Loc(_, t, _) => Some(*t),
            Raw::Ptr(_) => Some(DataType::DWord),
            _ => None,
        }
    }

    pub(super) fn out_loc(&self, o: &OperandText, r: &Raw) -> Result<()> {
        match r {
            Raw::Lit(_) | Raw::Ptr(_) => Err(self.e_m(o.pos, msg!("engine-output-not-location", operand = &o.text))),
            _ => Ok(()),
        }
    }

    pub(super) fn bit(&self, o: &OperandText) -> Result<Loc> {
        let first = o.text.chars().next().unwrap_or(' ');
        let raw = if matches!(first, '*' | '&') || first.is_ascii_digit() || o.text.contains('#') {
            self.raw(o)?
        } else {
            let r = self.fam.operand(&o.text).map_err(|e| {
                let mut x = self.e(o.pos, format!("{}: {}", o.text, e.message)).operand(o.text.clone());
                if let Some(h) = e.hint {
                    x = x.hint(h);
                }
                x
            })?;
            Raw::Loc(r.loc, r.ty, r.canonical)
        };
        match raw {
            Raw::Loc(l, DataType::Bool, _) => Ok(l),
            Raw::Loc(_, t, name) => Err(self
                .e_m(o.pos, msg!("engine-not-a-bit", name = &name, have = t.name()))
                .operand(name.clone())
                .hint(msg!("engine-not-a-bit-hint"))),
            _ => Err(self.e_m(o.pos, msg!("engine-bit-needed", operand = &o.text))),
        }
    }

    pub(super) fn count(&self, o: &OperandText) -> Result<u32> {
        let v = self.literal(o, &o.text, DataType::DInt)? as i32;
        if !(1..=255).contains(&v) {
            return Err(self.e_m(o.pos, msg!("engine-count-range", operand = &o.text)));
        }
        Ok(v as u32)
    }

    pub(super) fn name(o: &OperandText) -> String {
        o.text.trim_start_matches('%').to_ascii_uppercase()
    }

    /// The type of a value instruction: the mnemonic's, else the first located operand's
    /// (the output first), else INT for literals only and BYTE behind pointers.
    pub(super) fn value_ty(&self, m: &str, hint: TyHint, ops: &[(&OperandText, &Raw)]) -> Result<DataType> {
        if let Some(t) = hint_ty(hint) {
            return Ok(t);
        }
        for (_, r) in ops {
            if let Raw::Loc(_, t, _) = r {
                return Ok(*t);
            }
        }
        if ops.iter().any(|(_, r)| matches!(r, Raw::Ptr(_))) {
            return Ok(DataType::DWord);
        }
        if ops.iter().any(|(_, r)| matches!(r, Raw::Ind(_))) {
            // `MOVE *VD4, *VD8`: pointers made with `&VB…` address bytes.
            return Ok(DataType::Byte);
        }
        let _ = m;
        Ok(DataType::Int)
    }
}

fn conversion_hint(from: DataType, to: DataType) -> Msg {
    let convert = |how: &str| msg!("engine-convert-first", how = how);
    match (from.bits(), to.bits()) {
        (16, 32) => convert("I_DI IN, %VDn (INT → DINT)"),
        (32, 16) => convert("DI_I IN, %VWn (DINT → INT)"),
        (8, 16) => convert("B_I IN, %VWn (BYTE → INT)"),
        (16, 8) => convert("I_B IN, %VBn (INT → BYTE)"),
        _ => msg!("engine-same-size"),
    }
}
