//! The device trait: the small surface every device family implements, real or simulated.
//!
//! Batched reads and writes are the primitive (a single read is a batch of one) because
//! coalescing is where a fieldbus tool wins or loses. Optional capabilities are hooks that
//! default to `None` (the probe-rs `DebugProbe` pattern): a K2 answers `as_k2`, a servo
//! drive `as_servo`, and a simulator additionally exposes its simulation controls.
//!
//! Design note: the trait is synchronous. The design guide sketches `async fn`; we chose
//! blocking calls because every front end (rustyline, Lua, one-shot) is sequential, the
//! in-process simulator then costs a function call per register (Lua's ≥ 1 M writes/s
//! target), and wire drivers own a small current-thread tokio runtime internally, so
//! tokio stays an implementation detail of the transports.

use super::error::Result;
use super::operand::{Operand, OperandSpace};
use super::value::Value;
use serde::Serialize;

/// What a device is, for `devices` and messages.
#[derive(Clone, Debug, Serialize)]
pub struct DeviceInfo {
    /// Family (`k2`, `servo`).
    pub family: &'static str,
    /// Model name (`K205-16DT`).
    pub model: String,
    /// How it is reached (`sim`, `tcp://127.0.0.1:502?unit=1`).
    pub link: String,
    /// True for simulators.
    pub simulated: bool,
}

/// A device the session can talk to.
pub trait Device: Send {
    fn info(&self) -> &DeviceInfo;
    fn operands(&self) -> &dyn OperandSpace;
    /// Reads a batch; values come back in the order asked.
    fn read(&mut self, ops: &[Operand]) -> Result<Vec<Value>>;
    /// Writes a batch in the given order. Values were already checked against the operands.
    fn write(&mut self, items: &[(Operand, Value)]) -> Result<()>;
    /// Number of requests sent on the wire since the device was opened (0 in-process).
    fn requests(&self) -> u64 {
        0
    }
    fn as_k2(&mut self) -> Option<&mut dyn crate::k2::K2Ops> {
        None
    }
    fn as_servo(&mut self) -> Option<&mut dyn crate::servo::ServoOps> {
        None
    }
    /// Capabilities of families that have no hook of their own (UMPK, FX and later ones):
    /// their shell commands and Lua methods downcast through this one generic hook instead
    /// of each family adding an `as_<family>` method here (design guide, "New families").
    /// A wrapper (the write guard) must decide what it lets through this door.
    fn family_ops(&mut self) -> Option<&mut dyn std::any::Any> {
        None
    }
    /// Sets a device option given in its URL or profile (`word_order`, `encoder` …).
    fn set_option(&mut self, key: &str, _value: &str) -> Result<()> {
        Err(crate::core::Error::usage(format!("{} devices have no option `{key}`", self.info().family)))
    }
}
