//! Kinco servo drives, everything in one room: the 10-byte RS232 frame codec
//! (`frame`), the object dictionary table and operand space (`objects`), engineering
//! units (`units`), the driver (`driver`), the DS402 state machine
//! and helpers (`ds402`) and the drive simulator (`sim`).
//! Specs: `../shared/spec/kinco-servo.md`, `../shared/spec/kinco-public-notes.md`.

pub mod access;
pub mod changes;
pub mod driver;
pub mod ds402;
pub mod frame;
pub mod objects;
pub mod params;
pub mod sim;
pub mod units;

use crate::core::Result;
pub use access::{ops, simulator, ServoAccess};
use objects::ObjRef;
use std::sync::{Arc, Mutex};

/// Servo-specific capabilities: raw object access, hand-made frames, units and the
/// simulator's controls. The DS402 helpers ([`ds402`]) and the `servo` shell commands
/// run on this, for the serial driver and the simulator alike.
pub trait ServoOps {
    /// The drive id requests go to.
    fn drive_id(&self) -> u8;
    /// The encoder resolution used for `rpm`/`rps/s` conversion (shared with the operands).
    fn resolution(&self) -> units::Resolution;
    /// Reads an object's raw value (masked to its size).
    fn read_raw(&mut self, obj: ObjRef) -> Result<u32>;
    /// Writes an object's raw value. Unlike `Device::write` this does not consult the
    /// table's access column, so the drive's own refusal (0x80) can be seen.
    fn write_raw(&mut self, obj: ObjRef, raw: u32) -> Result<()>;
    /// Sends 10 hand-made bytes as they are and returns the reply; silence is diagnosed.
    fn raw_frame(&mut self, bytes: [u8; frame::FRAME_LEN]) -> Result<[u8; frame::FRAME_LEN]>;
    /// Reads the encoder resolution from 6410.03 and uses it from then on.
    fn read_resolution(&mut self) -> Result<u32>;
    /// The simulated line, when the drive is simulated in-process.
    fn simulator(&mut self) -> Option<Arc<Mutex<sim::SimLine>>> {
        None
    }
    /// The control socket of a simulator served on this drive's port (`plcsh sim serve
    /// --servo-pty LINK` opens `LINK.ctl`), for `servo sim …` on a served drive.
    fn sim_control(&self) -> Option<std::path::PathBuf> {
        None
    }

    /// Asks the device's write rules whether `changes` may be made, before a helper makes
    /// any of them ([`ServoAccess`] asks the device; a bare driver permits everything).
    fn permits(&self, changes: &[crate::core::device::Change]) -> Result<()> {
        let _ = changes;
        Ok(())
    }
}
