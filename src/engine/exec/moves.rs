//! Executing the block moves and fills (S7-200 System Manual "Move Instructions": `BMB`,
//! `BMW`, `BMD`, `FILL`): N from 1 to 255, each element costing the family's per-element
//! time, overlapping blocks copied as if through a buffer. Single moves are one line of the
//! interpreter loop ([`super::Cpu`]); `SWAP` exchanges a word's bytes.

use super::{Cpu, Fault, FaultKind};
use crate::core::DataType;
use crate::engine::compile::Program;
use crate::engine::{read, write, Machine, Opd};
use crate::msg;

impl Cpu {
    #[allow(clippy::too_many_arguments)]
    pub(super) fn block<M: Machine>(
        &mut self,
        prog: &Program,
        m: &mut M,
        ty: DataType,
        a: &Opd,
        out: &Opd,
        n: &Opd,
        fill: bool,
        _pc: usize,
    ) -> Result<(), Fault> {
        let n = read(m, n, DataType::Int)? as u16 as i16;
        if !(1..=255).contains(&n) {
            return Err(Fault::new(FaultKind::Instruction, msg!("engine-block-length", n = n.to_string())));
        }
        self.spent_ns += prog.costs.per_element_ns as u64 * n as u64;
        let w = crate::engine::width_of(ty);
        let src = crate::engine::loc_of(m, a, ty)?;
        let dst = crate::engine::loc_of(m, out, ty)?
            .ok_or_else(|| Fault::new(FaultKind::BadAddress, msg!("engine-no-destination")))?;

        let _ = w;
        // Read all first: overlapping blocks copy as if through a buffer.
        let vals: Vec<u32> = match (fill, src) {
            (true, _) | (false, None) => vec![read(m, a, ty)?; n as usize],
            (false, Some(s)) => (0..n as u32).map(|k| m.get(s.nth(k))).collect(),
        };
        for (k, v) in vals.into_iter().enumerate() {
            m.set(dst.nth(k as u32), v);
        }
        Ok(())
    }
}

/// `SWAP OUT`: the two bytes of a word exchanged.
#[inline]
pub(super) fn swap<M: Machine>(m: &mut M, out: &Opd) -> Result<(), Fault> {
    read(m, out, DataType::Word).and_then(|x| write(m, out, DataType::Word, (x as u16).swap_bytes() as u32))
}
