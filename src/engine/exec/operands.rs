//! Operands while executing: an operand's raw value and its write, through a pointer where
//! the operand is one, without building a fault on the hot path; the fault for a pointer
//! outside memory when one is needed. Every instruction group's execution uses these.

use super::{Fault, FaultKind};
use crate::core::DataType;
use crate::engine::{read, Machine, Opd};
use crate::msg;

/// An operand's raw value without building a fault (the hot path); `None` only for a
/// pointer outside memory.
#[inline(always)]
pub(super) fn val<M: Machine>(m: &M, o: &Opd, ty: DataType) -> Option<u32> {
    match *o {
        Opd::Imm(v) => Some(v),
        Opd::Loc(l) => Some(m.get(l)),
        Opd::Ind(p) => m.deref(m.get(p), crate::engine::width_of(ty)).map(|l| m.get(l)),
    }
}

/// Writes an operand; `false` for a pointer outside memory.
#[inline(always)]
pub(super) fn put<M: Machine>(m: &mut M, o: &Opd, ty: DataType, v: u32) -> bool {
    match *o {
        Opd::Imm(_) => true,
        Opd::Loc(l) => {
            m.set(l, v);
            true
        }
        Opd::Ind(p) => match m.deref(m.get(p), crate::engine::width_of(ty)) {
            Some(l) => {
                m.set(l, v);
                true
            }
            None => false,
        },
    }
}

/// The fault for the first of `ops` whose pointer is bad (cold path).
#[cold]
pub(super) fn bad<M: Machine>(m: &M, ops: &[&Opd], ty: DataType) -> Fault {
    ops.iter()
        .find_map(|o| read(m, o, ty).err())
        .unwrap_or_else(|| Fault::new(FaultKind::BadAddress, msg!("engine-bad-address")))
}
