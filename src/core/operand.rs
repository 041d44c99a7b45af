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

/// One completion candidate with its meaning (for hints and `help`).
#[derive(Clone, Debug, PartialEq)]
pub struct Candidate {
    pub text: String,
    pub meaning: String,
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
