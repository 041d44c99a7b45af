//! How commands reach a K2's instructions: [`ops`] finds the K2 operations behind any device
//! through the one generic lookup (`core::device::lookup`) and hands out a [`K2Access`],
//! whose every instruction first states what it changes ([`super::changes`]) and goes past
//! the device's write rules before it runs. There is no other way from a device to
//! [`K2Ops`], so the rules hold for the shell, Lua, the typed helpers and whatever command
//! comes next, and the write guard needs to know nothing about K2 PLCs.
//!
//! Simulation controls (input signals, retention, faults, the IL program: [`simulator`],
//! [`K2Ops::as_sim`]) change the simulated world around a PLC, not the PLC's own state a
//! rule protects, and exist only on simulators; they go past the rules with no changes.

use super::catalog::Model;
use super::driver::K2Wire;
use super::sim::K2Sim;
use super::{changes, Event, EventMatch, K2Ops, RtcTime};
use crate::core::device::{lookup, Change};
use crate::core::{Device, Error, Result};
use crate::msg;
use std::any::Any;

/// A K2 PLC's operations behind a device's write rules (module doc).
pub struct K2Access<'a> {
    dev: &'a mut dyn Device,
    /// Answers of the `&self` methods, read when the access was taken.
    model: &'static Model,
    backup: (u32, u32),
}

/// The K2 operations of a device, if it is a K2 PLC (simulated or reached over Modbus).
pub fn ops(dev: &mut dyn Device) -> Option<K2Access<'_>> {
    let k = raw(lookup(dev, "k2", &[]).ok()??)?;
    let (model, backup) = (k.model(), k.backup_area());
    Some(K2Access { dev, model, backup })
}

/// The simulator behind a device, if it is a simulated K2 (simulation controls).
pub fn simulator(dev: &mut dyn Device) -> Option<&mut K2Sim> {
    lookup(dev, "k2", &[]).ok()??.downcast_mut::<K2Sim>()
}

/// The K2 operations behind a family hook's answer: the simulator's or the wire driver's.
fn raw(ops: &mut dyn Any) -> Option<&mut dyn K2Ops> {
    if ops.is::<K2Sim>() {
        return ops.downcast_mut::<K2Sim>().map(|s| s as &mut dyn K2Ops);
    }
    ops.downcast_mut::<K2Wire>().map(|w| w as &mut dyn K2Ops)
}

impl K2Access<'_> {
    /// The PLC's operations, once `changes` are permitted.
    fn after(&mut self, changes: &[Change]) -> Result<&mut dyn K2Ops> {
        let answer = self.dev.family(changes)?;
        answer.and_then(raw).ok_or_else(|| Error::state(msg!("k2-no-longer-k2")))
    }

    /// The PLC's operations for instruction `name` on `channel`, once what it changes is
    /// permitted.
    fn running(&mut self, name: &str, channel: u8) -> Result<&mut dyn K2Ops> {
        let change = changes::instruction(self.model, name, channel);
        self.after(std::slice::from_ref(&change))
    }
}

impl K2Ops for K2Access<'_> {
    fn model(&self) -> &'static Model {
        self.model
    }
    fn pls(&mut self, channel: u8) -> Result<String> {
        self.running("PLS", channel)?.pls(channel)
    }
    fn hdef(&mut self, counter: u8, mode: u8) -> Result<String> {
        self.running("HDEF", counter)?.hdef(counter, mode)
    }
    fn hsc(&mut self, counter: u8) -> Result<String> {
        self.running("HSC", counter)?.hsc(counter)
    }
    fn pstop(&mut self, channel: u8) -> Result<String> {
        self.running("PSTOP", channel)?.pstop(channel)
    }
    fn read_rtc(&mut self) -> Result<RtcTime> {
        self.after(&[])?.read_rtc()
    }
    fn set_rtc(&mut self, t: RtcTime) -> Result<()> {
        self.running("SET_RTC", 0)?.set_rtc(t)
    }
    /// The interrupt event log is plcsh's own record, not machine state: reading and
    /// emptying it change nothing a rule protects.
    fn events(&mut self, clear: bool) -> Result<Vec<Event>> {
        self.after(&[])?.events(clear)
    }
    fn take_event(&mut self, m: &EventMatch) -> Result<Option<Event>> {
        self.after(&[])?.take_event(m)
    }
    fn backup_area(&self) -> (u32, u32) {
        self.backup
    }
    fn helper_status(&mut self) -> Result<String> {
        self.after(&[])?.helper_status()
    }
    fn as_sim(&mut self) -> Option<&mut K2Sim> {
        self.dev.family(&[]).ok()??.downcast_mut::<K2Sim>()
    }
}
