//! Executing bit logic and comparisons: the logic operations the CR and parentheses
//! combine with, and the comparison contacts (S7-200 System Manual "Compare Instructions":
//! REAL compares as IEEE values, a NaN is only unequal; integers by their type's sign).

use super::arith::as_i64;
use crate::core::DataType;
use crate::engine::isa::{Cmp, Logic};

#[inline]
pub(super) fn logic(op: u8, a: bool, b: bool) -> bool {
    match op {
        0 => a & b,
        1 => a | b,
        _ => a ^ b,
    }
}

#[inline]
pub(super) fn lcode(l: Logic) -> u8 {
    match l {
        Logic::And => 0,
        Logic::Or => 1,
        Logic::Xor => 2,
    }
}

#[inline]
pub(super) fn compare(ty: DataType, op: Cmp, x: u32, y: u32) -> bool {
    use std::cmp::Ordering;
    let ord = if ty == DataType::Real {
        match f32::from_bits(x).partial_cmp(&f32::from_bits(y)) {
            Some(o) => o,
            None => return op == Cmp::Ne,
        }
    } else {
        as_i64(ty, x).cmp(&as_i64(ty, y))
    };
    match op {
        Cmp::Eq => ord == Ordering::Equal,
        Cmp::Ne => ord != Ordering::Equal,
        Cmp::Lt => ord == Ordering::Less,
        Cmp::Gt => ord == Ordering::Greater,
        Cmp::Le => ord != Ordering::Greater,
        Cmp::Ge => ord != Ordering::Less,
    }
}
