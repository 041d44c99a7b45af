//! UMPK8 / UMPK16 teaching PLCs, everything in one room: the model table (`model`), the
//! terminal-protocol codec (`codec`), Intel HEX records (`hex`), the operand space
//! (`space`), the driver (`driver`) and the simulator (`sim`).
//! Manual: `../shared/seeds/003_…` (Russian); digest `../shared/spec/umpk.md`.

pub mod codec;
pub mod driver;
pub mod hex;
pub mod model;
pub mod sim;
pub mod space;

use crate::core::device::{lookup, Change};
use crate::core::{Device, Result};

/// The UMPK behind a device (the serial driver or the in-process simulator alike), for a
/// command about to make `changes` (`&[]` to read or to drive the simulator's inputs),
/// through the one generic lookup (`core::device::lookup`): the device's write rules check
/// `changes` first and refuse the whole command. `None` for a device that is not a UMPK.
pub fn ops<'a>(dev: &'a mut dyn Device, changes: &[Change]) -> Result<Option<&'a mut driver::Driver>> {
    Ok(lookup(dev, "umpk", changes)?.and_then(|a| a.downcast_mut::<driver::Driver>()))
}
