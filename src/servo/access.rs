//! How commands reach a servo drive's objects: [`ops`] finds the drive behind any device
//! through the one generic lookup (`core::device::lookup`) and hands out a [`ServoAccess`],
//! whose every object write and hand-made frame first states what it changes
//! ([`super::changes`]) and goes past the device's write rules before it is sent. There is no
//! other way from a device to [`ServoOps`], so the rules hold for the `servo` commands, the
//! DS402 helpers and Lua alike, and the write guard needs to know nothing about drives.
//!
//! Simulation controls (the simulated line: [`simulator`], [`ServoOps::simulator`]; a served
//! simulator's control socket) act on the simulated world around a drive and exist only on
//! simulators; they go past the rules with no changes.

use super::driver::Driver;
use super::frame::FRAME_LEN;
use super::objects::ObjRef;
use super::sim::SimLine;
use super::{changes, units, ServoOps};
use crate::core::device::{lookup, Change};
use crate::core::{Device, Error, Result};
use crate::msg;
use std::path::PathBuf;
use std::sync::{Arc, Mutex};

/// A servo drive's operations behind a device's write rules (module doc).
pub struct ServoAccess<'a> {
    dev: &'a mut dyn Device,
    /// Answers of the `&self` methods, read when the access was taken.
    id: u8,
    resolution: units::Resolution,
    control: Option<PathBuf>,
}

/// The drive operations of a device, if it is a Kinco servo drive (on a line or simulated).
pub fn ops(dev: &mut dyn Device) -> Option<ServoAccess<'_>> {
    let d = lookup(dev, "servo", &[]).ok()??.downcast_mut::<Driver>()?;
    let (id, resolution, control) = (ServoOps::drive_id(d), ServoOps::resolution(d), ServoOps::sim_control(d));
    Some(ServoAccess { dev, id, resolution, control })
}

/// The simulated line behind a device, if it is a simulated drive (simulation controls).
pub fn simulator(dev: &mut dyn Device) -> Option<Arc<Mutex<SimLine>>> {
    lookup(dev, "servo", &[]).ok()??.downcast_mut::<Driver>()?.simulator()
}

impl ServoAccess<'_> {
    /// The drive's operations, once `changes` are permitted.
    fn after(&mut self, changes: &[Change]) -> Result<&mut Driver> {
        let answer = self.dev.family(changes)?;
        answer.and_then(|a| a.downcast_mut::<Driver>()).ok_or_else(|| Error::state(msg!("servo-not-servo-any-more")))
    }
}

impl ServoOps for ServoAccess<'_> {
    fn drive_id(&self) -> u8 {
        self.id
    }
    fn resolution(&self) -> units::Resolution {
        self.resolution.clone()
    }
    fn read_raw(&mut self, obj: ObjRef) -> Result<u32> {
        self.after(&[])?.read_raw(obj)
    }
    fn write_raw(&mut self, obj: ObjRef, raw: u32) -> Result<()> {
        self.after(&[changes::write(obj)])?.write_raw(obj, raw)
    }
    fn raw_frame(&mut self, bytes: [u8; FRAME_LEN]) -> Result<[u8; FRAME_LEN]> {
        self.after(&changes::frame(&bytes))?.raw_frame(bytes)
    }
    /// Reading 6410.03 changes only how plcsh converts units, not the drive.
    fn read_resolution(&mut self) -> Result<u32> {
        self.after(&[])?.read_resolution()
    }
    fn simulator(&mut self) -> Option<Arc<Mutex<SimLine>>> {
        self.after(&[]).ok()?.simulator()
    }
    fn sim_control(&self) -> Option<PathBuf> {
        self.control.clone()
    }
    fn permits(&self, changes: &[Change]) -> Result<()> {
        self.dev.permits(changes)
    }
}
