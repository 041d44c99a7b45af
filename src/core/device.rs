//! The device trait: the small surface every device family implements, real or simulated.
//!
//! Batched reads and writes are the primitive (a single read is a batch of one) because
//! coalescing is where a fieldbus tool wins or loses. What a device can do beyond that is
//! its family's, reached through one optional hook (below).
//!
//! Design note, capabilities: one mechanism for every family. A device's family operations
//! (a K2's instructions and event log, a drive's raw objects and frames, a UMPK's terminal
//! commands, a simulated FX's CPU) are reached through one hook, [`Device::family`], found
//! by one generic lookup, [`lookup`] (`lookup(dev, "k2", changes)`), which answers the
//! family's own object as `dyn Any`. Only that family downcasts it, in its typed accessor
//! (`k2::ops`, `servo::ops`, `umpk::ops`, `fx::driver::ops`; for simulation controls
//! `k2::simulator`, `servo::simulator`, `fx::driver::simulator`). So this module names no
//! family, and a new family adds its operations by answering the hook and writing its
//! accessor, without touching `core` or the write guard.
//!
//! Every call that changes a device states its changes first: the hook takes the
//! [`Change`]s the caller is about to make and hands the object out only once they are
//! permitted (the write guard checks its rules; a plain device permits everything). The
//! families' accessors state them per call, computed by the family (`k2::changes`,
//! `servo::changes`), so every instruction and object write made through them is checked;
//! the simulator reached for simulation controls (`k2::simulator`) is the deliberate
//! exception the guard's doc names. Why the hook takes the changes instead of handing out the object beside a
//! separate rule checker: checking a write names the operand in the device's own operand
//! space, which a wrapper can read only while it holds the whole device, not while the
//! object is lent out. Why the lookup compares the family name before asking the hook: a
//! device whose readiness is deferred (`crate::pending`) must not be made ready by a
//! lookup for another family. Capability traits per function (pulse outputs, counters, the
//! clock: the embedded-hal shape) can sit on the same lookup when a second family shares
//! one; today each operation belongs to one family, so the accessors are per family.
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
use std::any::Any;

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

/// The pseudo-operand a change of a device's real-time clock names (`SET_RTC`): a profile's
/// allow list may name it like a register.
pub const CLOCK: &str = "clock";

/// A change a command is about to make to a device, as the write guard sees it.
#[derive(Clone, Debug, PartialEq)]
pub enum Change {
    /// A write of one operand.
    Write(Operand),
    /// An instruction or action (`PLS 0`, `SET_RTC`, a servo object write) and the
    /// operand names it changes (`Q0.0`, `SMB66`; `clock` for the real-time clock).
    Action { what: String, touches: Vec<String> },
}

/// A device the session can talk to.
pub trait Device: Send {
    fn info(&self) -> &DeviceInfo;
    fn operands(&self) -> &dyn OperandSpace;
    /// Makes the device usable before a command: sets what was deferred to its first use
    /// (the simulator's state file) and tries again a link that could not be made when the
    /// session opened it (`crate::pending`). Devices that are always ready answer `Ok`.
    fn ready(&mut self) -> Result<()> {
        Ok(())
    }
    /// Reads a batch; values come back in the order asked.
    fn read(&mut self, ops: &[Operand]) -> Result<Vec<Value>>;
    /// Reads a batch into `out` (cleared first), reusing its allocation: for a loop that
    /// polls the same operands again and again. The K2 simulator reads straight into it;
    /// other devices go through [`Device::read`].
    fn read_into(&mut self, ops: &[Operand], out: &mut Vec<Value>) -> Result<()> {
        *out = self.read(ops)?;
        Ok(())
    }
    /// Writes a batch in the given order. Values were already checked against the operands.
    fn write(&mut self, items: &[(Operand, Value)]) -> Result<()>;
    /// Number of requests sent on the wire since the device was opened (0 in-process).
    fn requests(&self) -> u64 {
        0
    }
    /// The one capability hook: the device's family operations — the family's own object,
    /// which only that family's typed accessor downcasts ([`lookup`]) — handed out once
    /// `changes`, what the caller is about to make through it (`&[]` to read or to reach
    /// simulation controls), are permitted. A wrapper that holds write rules checks
    /// `changes` first and refuses the whole command, naming the rule; a plain device just
    /// answers. Devices without family operations answer `None`.
    fn family(&mut self, changes: &[Change]) -> Result<Option<&mut dyn Any>> {
        let _ = changes;
        Ok(None)
    }
    /// Asks whether `changes` may be made, before a command makes any of them, so a
    /// command is refused whole (nothing sent) rather than half-way. Unguarded devices
    /// permit everything; the write guard checks its rules.
    fn permits(&self, changes: &[Change]) -> Result<()> {
        let _ = changes;
        Ok(())
    }
    /// Sets a device option given in its URL or profile (`word_order`, `encoder` …).
    fn set_option(&mut self, key: &str, _value: &str) -> Result<()> {
        Err(crate::core::Error::usage(crate::msg!("device-no-option", family = self.info().family, key = key)))
    }
}

/// The one generic lookup: the family operations of `dev` when it is a device of `family`
/// (its [`DeviceInfo::family`]), for a caller about to make `changes` (see
/// [`Device::family`]). A device of another family answers `Ok(None)` without being asked,
/// so looking for a drive among the open devices never makes a PLC take its deferred state
/// file (`crate::pending`).
pub fn lookup<'a>(dev: &'a mut dyn Device, family: &str, changes: &[Change]) -> Result<Option<&'a mut dyn Any>> {
    if dev.info().family != family {
        return Ok(None);
    }
    dev.family(changes)
}
