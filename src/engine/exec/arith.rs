//! Executing arithmetic, shifts and conversions with the S7-200 status a family sees
//! ([`crate::engine::Flags`]: zero, overflow, negative, division by zero; S7-200 System
//! Manual "Integer Math", "Floating-Point Math", "Shift and Rotate", "Conversion"): results
//! wrap to the type's width with overflow flagged, division by zero leaves the output
//! unchanged and returns ENO = 0, conversions that do not fit return ENO = 0.

use super::operands::{bad, put, val};
use super::Fault;
use crate::core::DataType;
use crate::engine::isa::{Arith, Conv, Logic, Shift, Unary};
use crate::engine::{read, write, Flags, Machine, Opd};

/// Sign-extends or interprets a raw pattern of type `ty` as i64.
#[inline]
pub(super) fn as_i64(ty: DataType, raw: u32) -> i64 {
    match ty {
        DataType::Bool => (raw & 1) as i64,
        DataType::Byte => (raw & 0xFF) as i64,
        DataType::SInt => raw as u8 as i8 as i64,
        DataType::Word => (raw & 0xFFFF) as i64,
        DataType::Int => raw as u16 as i16 as i64,
        DataType::DWord => raw as i64,
        DataType::DInt => raw as i32 as i64,
        DataType::Real => f32::from_bits(raw) as i64,
    }
}

#[inline]
pub(super) fn fits(ty: DataType, v: i64) -> bool {
    let (lo, hi) = ty.int_range();
    v >= lo && v <= hi
}

#[inline]
pub(super) fn mask(ty: DataType, v: i64) -> u32 {
    match ty.bits() {
        8 => v as u32 & 0xFF,
        16 => v as u32 & 0xFFFF,
        _ => v as u32,
    }
}

/// SQRT and ABS: OUT := f(IN); ENO = 0 when the result is not a number or does not fit
/// (S7-200 status bits: SM1.1 overflow / illegal value, SM1.0 zero, SM1.2 negative).
pub(super) fn unary<M: Machine>(m: &mut M, op: Unary, ty: DataType, a: &Opd, out: &Opd) -> Result<bool, Fault> {
    let Some(x) = val(m, a, ty) else {
        return Err(bad(m, &[a], ty));
    };
    if ty == DataType::Real {
        let x = f32::from_bits(x);
        if op == Unary::Sqrt && (x.is_nan() || x < 0.0) {
            m.flags(Flags { overflow: true, ..Flags::default() });
            return Ok(false);
        }
        let r = match op {
            Unary::Sqrt => x.sqrt(),
            Unary::Abs => x.abs(),
        };
        m.flags(Flags { zero: r == 0.0, overflow: !r.is_finite(), negative: false, div_zero: false });
        write(m, out, ty, r.to_bits())?;
        return Ok(r.is_finite());
    }
    let r = as_i64(ty, x).abs();
    let overflow = !fits(ty, r);
    let raw = mask(ty, r);
    m.flags(Flags { zero: raw == 0, overflow, negative: as_i64(ty, raw) < 0, div_zero: false });
    if !put(m, out, ty, raw) {
        return Err(bad(m, &[out], ty));
    }
    Ok(!overflow)
}

/// Whether a divisor reads as zero (cold: after a failed division only).
#[cold]
pub(super) fn is_zero<M: Machine>(m: &M, b: &Opd, ty: DataType) -> bool {
    match val(m, b, ty) {
        Some(v) if ty == DataType::Real => f32::from_bits(v) == 0.0,
        Some(v) => as_i64(ty, v) == 0,
        None => false,
    }
}

/// [`arith`]'s integer add, subtract and multiply, on the hot path: the same result, status
/// and ENO, without a `Result` that could carry a fault. `None` — and nothing written, status
/// included — for everything else (REAL, division, a pointer outside memory), which
/// [`arith`] then does as it always has.
#[inline(always)]
pub(super) fn arith_int<M: Machine>(m: &mut M, op: Arith, ty: DataType, a: &Opd, b: &Opd, out: &Opd) -> Option<bool> {
    if ty == DataType::Real {
        return None;
    }
    let out_loc = match *out {
        Opd::Loc(l) => l,
        _ => return None,
    };
    let (x, y) = (as_i64(ty, val(m, a, ty)?), as_i64(ty, val(m, b, ty)?));
    let r = match op {
        Arith::Add => x + y,
        Arith::Sub => x - y,
        Arith::Mul => x.wrapping_mul(y),
        Arith::Div | Arith::Mod => return None,
    };
    let overflow = !fits(ty, r);
    let raw = mask(ty, r);
    m.flags(Flags { zero: raw == 0, overflow, negative: as_i64(ty, raw) < 0, div_zero: false });
    m.set(out_loc, raw);
    Some(!overflow)
}

/// Arithmetic with S7-200 status: result wraps to the type's width, overflow is flagged;
/// division by zero leaves the output unchanged and returns ENO = 0 (SM1.3 on the K2).
pub(super) fn arith<M: Machine>(
    m: &mut M,
    op: Arith,
    ty: DataType,
    a: &Opd,
    b: &Opd,
    out: &Opd,
) -> Result<bool, Fault> {
    let (Some(x), Some(y)) = (val(m, a, ty), val(m, b, ty)) else {
        return Err(bad(m, &[a, b], ty));
    };
    if ty == DataType::Real {
        let (x, y) = (f32::from_bits(x), f32::from_bits(y));
        if matches!(op, Arith::Div | Arith::Mod) && y == 0.0 {
            m.flags(Flags { div_zero: true, ..Flags::default() });
            return Ok(false);
        }
        let r = match op {
            Arith::Add => x + y,
            Arith::Sub => x - y,
            Arith::Mul => x * y,
            Arith::Div => x / y,
            Arith::Mod => x % y,
        };
        m.flags(Flags { zero: r == 0.0, overflow: !r.is_finite(), negative: r < 0.0, div_zero: false });
        write(m, out, ty, r.to_bits())?;
        return Ok(r.is_finite());
    }
    let (x, y) = (as_i64(ty, x), as_i64(ty, y));
    if matches!(op, Arith::Div | Arith::Mod) && y == 0 {
        m.flags(Flags { div_zero: true, ..Flags::default() });
        return Ok(false);
    }
    let r = match op {
        Arith::Add => x + y,
        Arith::Sub => x - y,
        Arith::Mul => x.wrapping_mul(y),
        Arith::Div => x / y,
        Arith::Mod => x % y,
    };
    let overflow = !fits(ty, r);
    let raw = mask(ty, r);
    let shown = as_i64(ty, raw);
    m.flags(Flags { zero: raw == 0, overflow, negative: shown < 0, div_zero: false });
    if !put(m, out, ty, raw) {
        return Err(bad(m, &[out], ty));
    }
    Ok(!overflow)
}

/// `SHL`/`SHR`/`ROL`/`ROR OUT, N`: OUT shifted or rotated by N bits (SM1.0 zero).
#[inline]
pub(super) fn shift_out<M: Machine>(m: &mut M, op: Shift, ty: DataType, out: &Opd, n: &Opd) -> Result<(), Fault> {
    read(m, out, ty).and_then(|v| {
        let k = read(m, n, DataType::Byte)?;
        let v = shift(op, ty.bits(), v, k);
        m.flags(Flags { zero: v == 0, ..Flags::default() });
        write(m, out, ty, v)
    })
}

/// `WAND`/`WOR`/`WXOR IN1, IN2, OUT` (SM1.0 zero).
#[inline]
pub(super) fn word_logic<M: Machine>(
    m: &mut M,
    op: Logic,
    ty: DataType,
    a: &Opd,
    b: &Opd,
    out: &Opd,
) -> Result<(), Fault> {
    read(m, a, ty).and_then(|x| {
        let y = read(m, b, ty)?;
        let v = mask(
            ty,
            match op {
                Logic::And => x & y,
                Logic::Or => x | y,
                Logic::Xor => x ^ y,
            } as i64,
        );
        m.flags(Flags { zero: v == 0, ..Flags::default() });
        write(m, out, ty, v)
    })
}

/// `INV… OUT`: the ones' complement within the type's width.
#[inline]
pub(super) fn invert<M: Machine>(m: &mut M, ty: DataType, out: &Opd) -> Result<(), Fault> {
    read(m, out, ty).and_then(|x| write(m, out, ty, mask(ty, !x as i64)))
}

#[inline]
fn shift(op: Shift, bits: u32, v: u32, k: u32) -> u32 {
    let mask = if bits == 32 { u32::MAX } else { (1u32 << bits) - 1 };
    let v = v & mask;
    match op {
        Shift::Shl => {
            if k >= bits {
                0
            } else {
                (v << k) & mask
            }
        }
        Shift::Shr => {
            if k >= bits {
                0
            } else {
                v >> k
            }
        }
        Shift::Rol => {
            let k = k % bits;
            if k == 0 {
                v
            } else {
                ((v << k) | (v >> (bits - k))) & mask
            }
        }
        Shift::Ror => {
            let k = k % bits;
            if k == 0 {
                v
            } else {
                ((v >> k) | (v << (bits - k))) & mask
            }
        }
    }
}

pub(super) fn convert<M: Machine>(m: &mut M, c: Conv, a: &Opd, out: &Opd) -> Result<bool, Fault> {
    use DataType as T;
    let r: Option<(DataType, u32)> = match c {
        Conv::IDi => Some((T::DInt, as_i64(T::Int, read(m, a, T::Int)?) as i32 as u32)),
        Conv::DiI => {
            let v = as_i64(T::DInt, read(m, a, T::DInt)?);
            fits(T::Int, v).then_some((T::Int, v as u16 as u32))
        }
        Conv::BI => Some((T::Int, read(m, a, T::Byte)? & 0xFF)),
        Conv::IB => {
            let v = as_i64(T::Int, read(m, a, T::Int)?);
            (0..=255).contains(&v).then_some((T::Byte, v as u32))
        }
        Conv::DiR => Some((T::Real, (as_i64(T::DInt, read(m, a, T::DInt)?) as f32).to_bits())),
        Conv::Round | Conv::Trunc => {
            let f = f32::from_bits(read(m, a, T::Real)?) as f64;
            let v = if c == Conv::Round { f.round() } else { f.trunc() };
            (v.is_finite() && v >= i32::MIN as f64 && v <= i32::MAX as f64).then_some((T::DInt, v as i32 as u32))
        }
        Conv::IBcd => {
            let v = as_i64(T::Int, read(m, a, T::Int)?);
            (0..=9999).contains(&v).then(|| {
                let d = |k: i64| ((v / 10i64.pow(k as u32)) % 10) as u32;
                (T::Int, d(0) | d(1) << 4 | d(2) << 8 | d(3) << 12)
            })
        }
        Conv::BcdI => {
            let v = read(m, a, T::Int)? & 0xFFFF;
            let digits = [v & 0xF, v >> 4 & 0xF, v >> 8 & 0xF, v >> 12 & 0xF];
            digits
                .iter()
                .all(|d| *d <= 9)
                .then(|| (T::Int, digits[0] + digits[1] * 10 + digits[2] * 100 + digits[3] * 1000))
        }
    };
    match r {
        Some((ty, v)) => {
            write(m, out, ty, v)?;
            Ok(true)
        }
        None => Ok(false),
    }
}
