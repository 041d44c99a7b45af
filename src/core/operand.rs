//! Family-neutral operands: what the session, the shell and Lua pass around.
//!
//! Each device family has its own grammar (`k2::operand`, `servo::objects` …) and packs
//! its parsed address into an [`Operand`]: a `Copy` key the family alone interprets, the
//! data type, and the significant width. This keeps the session and the front ends free
//! of family types (a new family is a new folder, not a change here) and keeps batch
//! reads cheap: an operand is 16 bytes, parsed once.

use super::error::{Error, ErrorKind, Result};
use super::literal::parse_literal;
use super::value::{DataType, Value};

/// A parsed, validated operand of some device family.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub struct Operand {
    /// Family-specific packed address.
    pub key: u64,
    /// The type values are shown and written as.
    pub dtype: DataType,
    /// Significant bits (equal to `dtype.bits()` except for bit groups like `K1M0`).
    pub bits: u8,
}

/// The longest range or count form a family accepts in one operand expression.
pub const MAX_RANGE: usize = 4096;

/// The count form `A[n]` every family's operand grammar shares: `t` holds it (its `[` at
/// `open`), `lead` is the column of `t` in the line, `example` a count form of the family
/// (`VW0[10]`) for messages. `parse_one` parses the first operand, `next` steps to the
/// following one. Linear in `n`, which is bounded by [`MAX_RANGE`].
pub fn count_form<T: Copy>(
    t: &str,
    open: usize,
    lead: usize,
    example: &str,
    parse_one: impl Fn(&str) -> Result<T>,
    next: impl Fn(&T) -> T,
) -> Result<Vec<T>> {
    let err = |col: usize, m: super::msg::Msg| Error::new(ErrorKind::Operand, m).column(col);
    let a = parse_one(&t[..open]).map_err(|e| e.shift(lead))?;
    let inner = t[open + 1..]
        .strip_suffix(']')
        .ok_or_else(|| err(lead + t.len(), crate::msg!("count-missing-bracket", example = example)))?;
    let n: usize = inner
        .trim()
        .parse()
        .map_err(|_| err(lead + open + 1, crate::msg!("count-not-a-count", count = inner, example = example)))?;
    if n == 0 || n > MAX_RANGE {
        return Err(err(lead + open + 1, crate::msg!("count-out-of-range", max = MAX_RANGE)));
    }
    let mut out = Vec::with_capacity(n);
    let mut cur = a;
    for _ in 0..n {
        out.push(cur);
        cur = next(&cur);
    }
    Ok(out)
}

/// One completion candidate with its meaning (for hints and `help`).
#[derive(Clone, Debug, PartialEq)]
pub struct Candidate {
    pub text: String,
    pub meaning: String,
}

/// The memory an operand occupies, in its family's own numbering: `area` (any number the
/// family chooses, one per independent memory), the first bit and the number of bits. Two
/// operands overlap when their areas are equal and their bit ranges meet (tag tables use it
/// to find two names on overlapping addresses).
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash, PartialOrd, Ord)]
pub struct Span {
    pub area: u32,
    pub first_bit: u64,
    pub bits: u64,
}

/// A device family's operand grammar, bound to one model (so bounds are known).
pub trait OperandSpace: Send + Sync {
    /// Family name, e.g. `k2`, `servo`.
    fn family(&self) -> &'static str;
    /// Parses one operand expression; a range (`VW0..VW20`) yields several operands.
    /// Errors carry a 0-based column within `text`.
    fn parse(&self, text: &str) -> Result<Vec<Operand>>;
    /// The canonical name (`VW100`, `SMB67`, `controlword`).
    fn name(&self, op: &Operand) -> String;
    /// A one-line meaning for an operand name, if the data tables know it.
    fn describe(&self, op: &Operand) -> Option<String>;
    /// A longer help text for `help OPERAND` (what it is, range, manual section).
    fn help(&self, text: &str) -> Result<String>;
    /// Candidates that start with `prefix` (case-insensitive), for completion.
    fn complete(&self, prefix: &str) -> Vec<Candidate>;
    /// The memory `op` occupies ([`Span`]); `None` (the default) when the family does not
    /// say, and then no overlap is looked for.
    fn span(&self, _op: &Operand) -> Option<Span> {
        None
    }
    /// Parses the value text of `set OP=VALUE` for this operand and checks that it fits.
    /// The default reads an IEC literal; a family overrides it to accept its own value
    /// syntax (e.g. a servo's `300rpm`). Errors carry a column within `text`.
    fn value(&self, op: &Operand, text: &str) -> Result<Value> {
        let lit = parse_literal(text).map_err(|e| Error::new(ErrorKind::Value, e.message).column(e.column))?;
        lit.fit(op.dtype, op.bits as u32).map_err(|m| Error::new(ErrorKind::Value, m))
    }
    /// Checks a numeric value (from Lua or a typed helper) against the operand.
    fn check(&self, op: &Operand, v: Value) -> Result<Value> {
        let lit = super::literal::Literal { value: v, declared: None, pattern: false, text: v.to_string() };
        lit.fit(op.dtype, op.bits as u32).map_err(|m| Error::new(ErrorKind::Value, m))
    }
}
