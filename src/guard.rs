//! The write guard: a device wrapper every opened device sits in, so the session's write
//! rules hold for every path to a device — `set`, Lua, the typed helpers, the K2
//! instructions and the servo's DS402 helpers alike. A command written next year reaches
//! the device through the same wrapper and cannot forget the rules.
//!
//! The rules are the device profile's `read_only` and `allow` ([`crate::profile::Guard`])
//! and the session-wide read-only switch (`--read-only`). What counts as a change:
//!
//! - `Device::write`: the operands written; the whole batch is checked before anything
//!   is sent.
//! - K2 instructions ([`K2Ops`]): PLS and PSTOP change the channel's output and status
//!   byte (PSTOP also latches the position control byte), HDEF the counter's control byte,
//!   HSC its current value and status byte, SET_RTC the clock (`clock`, which no allow
//!   list names). Reads (READ_RTC, the helper status, the backup-area bounds) pass.
//! - Servo objects ([`ServoOps`]): `write_raw` writes its object; `raw_frame` with a write
//!   function code writes the frame's object, with a read code it reads, and with any other
//!   code it is refused under a rule (the guard cannot tell what it does).
//! - [`Device::family_ops`]: the generic hook hands out an object the guard cannot see
//!   into. With a rule in force it answers `None`; family commands use
//!   [`Device::family_ops_for`] and state their changes (`&[]` for a command that only
//!   reads), which the guard checks first (see `core::device`).
//!
//! Batches: a typed helper computes everything it will change first and asks
//! [`Device::permits`]; the guard refuses the whole command before anything is sent,
//! naming the profile, the rule, the register and the profile's file:line. The per-call
//! checks stay as the backstop for code that does not ask first.
//!
//! Deliberately passed through: reading; the interrupt event log (`events`, `wait event`
//! consume plcsh's own log, not machine state); client-side options (`set_option`:
//! word order, timeouts, a simulator's backup-area end); and simulation controls
//! (`K2Ops::as_sim`, `ServoOps::simulator`), which act on the simulated world around a
//! device (input signals, injected faults) and exist only on simulators, never on a real
//! machine.

use crate::core::device::Change;
use crate::core::{Device, DeviceInfo, Error, Operand, OperandSpace, Result, Value};
use crate::k2::catalog::Model;
use crate::k2::changes;
use crate::k2::{Event, EventMatch, K2Ops, RtcTime};
use crate::profile::Guard;
use crate::servo::frame::FRAME_LEN;
use crate::servo::objects::ObjRef;
use crate::servo::{units, ServoOps};
use std::sync::atomic::{AtomicBool, Ordering};
use std::sync::{Arc, Mutex};

/// The pseudo-operand SET_RTC changes (a profile's allow list may name it).
pub use crate::core::device::CLOCK;

/// A device behind the session's write rules.
pub struct Guarded {
    inner: Box<dyn Device>,
    rules: Option<Guard>,
    /// The session-wide read-only switch (`--read-only`), shared by every device.
    session_read_only: Arc<AtomicBool>,
    /// Answers of `&self` capability methods, cached when the hook is taken.
    k2_model: Option<&'static Model>,
    backup: (u32, u32),
    servo: Option<(u8, units::Resolution)>,
    /// A served simulated drive's control socket (`servo sim …`: simulation control, which
    /// the guard passes as it passes the in-process simulator's).
    servo_control: Option<std::path::PathBuf>,
}

impl Guarded {
    pub fn new(mut inner: Box<dyn Device>, rules: Option<Guard>, session_read_only: Arc<AtomicBool>) -> Guarded {
        let (k2_model, backup) = match inner.as_k2() {
            Some(k) => (Some(k.model()), k.backup_area()),
            None => (None, (0, 0)),
        };
        let servo = inner.as_servo().map(|s| (s.drive_id(), s.resolution()));
        let servo_control = inner.as_servo().and_then(|s| s.sim_control());
        Guarded { inner, rules, session_read_only, k2_model, backup, servo, servo_control }
    }

    /// The profile rules, for `devices`.
    pub fn rules(&self) -> Option<&Guard> {
        self.rules.as_ref()
    }

    /// True when any rule restricts writes.
    pub fn restricted(&self) -> bool {
        self.rules.is_some() || self.session_read_only.load(Ordering::Relaxed)
    }

    /// Checks that the named thing may change. `what` is the action (`PLS 0`) for a
    /// change that is not a plain write.
    fn check_name(&self, name: &str, what: Option<&str>) -> Result<()> {
        if self.session_read_only.load(Ordering::Relaxed) {
            let doing = match what {
                Some(w) => format!("{w} refused (it changes {name})"),
                None => "write refused".to_string(),
            };
            return Err(Error::usage(format!("{doing}: the session is read-only (--read-only)"))
                .operand(name.to_string())
                .hint("reading works; start plcsh without --read-only to write"));
        }
        match &self.rules {
            Some(g) => g.check_name(name, what),
            None => Ok(()),
        }
    }

    fn check_changes(&self, changes: &[Change]) -> Result<()> {
        if !self.restricted() {
            return Ok(());
        }
        let space = self.inner.operands();
        for c in changes {
            match c {
                Change::Write(op) => self.check_name(&space.name(op), None)?,
                Change::Action { what, touches } => {
                    for t in touches {
                        self.check_name(t, Some(what))?;
                    }
                    if touches.is_empty() {
                        self.check_name(what, Some(what))?;
                    }
                }
            }
        }
        Ok(())
    }

    fn k2(&mut self) -> &mut dyn K2Ops {
        self.inner.as_k2().expect("as_k2 answered for this device")
    }

    fn servo_ops(&mut self) -> &mut dyn ServoOps {
        self.inner.as_servo().expect("as_servo answered for this device")
    }
}

impl Device for Guarded {
    fn info(&self) -> &DeviceInfo {
        self.inner.info()
    }
    fn operands(&self) -> &dyn OperandSpace {
        self.inner.operands()
    }
    fn read(&mut self, ops: &[Operand]) -> Result<Vec<Value>> {
        self.inner.read(ops)
    }
    fn read_into(&mut self, ops: &[Operand], out: &mut Vec<Value>) -> Result<()> {
        self.inner.read_into(ops, out)
    }
    fn write(&mut self, items: &[(Operand, Value)]) -> Result<()> {
        // Unrestricted (the usual case) costs one flag load: no allocation per write.
        if self.restricted() {
            let changes: Vec<Change> = items.iter().map(|(op, _)| Change::Write(*op)).collect();
            self.check_changes(&changes)?;
        }
        self.inner.write(items)
    }
    fn requests(&self) -> u64 {
        self.inner.requests()
    }
    fn as_k2(&mut self) -> Option<&mut dyn K2Ops> {
        let k = self.inner.as_k2()?;
        self.backup = k.backup_area();
        Some(self)
    }
    fn as_servo(&mut self) -> Option<&mut dyn ServoOps> {
        self.inner.as_servo()?;
        Some(self)
    }
    fn family_ops(&mut self) -> Option<&mut dyn std::any::Any> {
        if self.restricted() {
            return None;
        }
        self.inner.family_ops()
    }
    fn family_ops_for(&mut self, changes: &[Change]) -> Result<Option<&mut dyn std::any::Any>> {
        self.check_changes(changes)?;
        Ok(self.inner.family_ops())
    }
    fn family(&mut self, changes: &[Change]) -> Result<Option<&mut dyn std::any::Any>> {
        self.check_changes(changes)?;
        self.inner.family(changes)
    }
    fn permits(&self, changes: &[Change]) -> Result<()> {
        self.check_changes(changes)
    }
    fn set_option(&mut self, key: &str, value: &str) -> Result<()> {
        self.inner.set_option(key, value)?;
        if let Some(k) = self.inner.as_k2() {
            self.backup = k.backup_area();
        }
        Ok(())
    }
}

impl Guarded {
    fn instruction(&self, name: &str, channel: u8) -> Result<()> {
        match self.k2_model {
            Some(m) => self.check_changes(&[changes::instruction(m, name, channel)]),
            None => Ok(()),
        }
    }
}

impl K2Ops for Guarded {
    fn model(&self) -> &'static Model {
        self.k2_model.expect("as_k2 answered for this device")
    }
    fn pls(&mut self, channel: u8) -> Result<String> {
        self.instruction("PLS", channel)?;
        self.k2().pls(channel)
    }
    fn hdef(&mut self, counter: u8, mode: u8) -> Result<String> {
        self.instruction("HDEF", counter)?;
        self.k2().hdef(counter, mode)
    }
    fn hsc(&mut self, counter: u8) -> Result<String> {
        self.instruction("HSC", counter)?;
        self.k2().hsc(counter)
    }
    fn pstop(&mut self, channel: u8) -> Result<String> {
        self.instruction("PSTOP", channel)?;
        self.k2().pstop(channel)
    }
    fn read_rtc(&mut self) -> Result<RtcTime> {
        self.k2().read_rtc()
    }
    fn set_rtc(&mut self, t: RtcTime) -> Result<()> {
        self.instruction("SET_RTC", 0)?;
        self.k2().set_rtc(t)
    }
    fn events(&mut self, clear: bool) -> Result<Vec<Event>> {
        self.k2().events(clear)
    }
    fn take_event(&mut self, m: &EventMatch) -> Result<Option<Event>> {
        self.k2().take_event(m)
    }
    fn backup_area(&self) -> (u32, u32) {
        self.backup
    }
    fn helper_status(&mut self) -> Result<String> {
        self.k2().helper_status()
    }
    fn as_sim(&mut self) -> Option<&mut crate::k2::sim::K2Sim> {
        self.k2().as_sim()
    }
}

impl ServoOps for Guarded {
    fn drive_id(&self) -> u8 {
        self.servo.as_ref().expect("as_servo answered for this device").0
    }
    fn resolution(&self) -> units::Resolution {
        self.servo.as_ref().expect("as_servo answered for this device").1.clone()
    }
    fn read_raw(&mut self, obj: ObjRef) -> Result<u32> {
        self.servo_ops().read_raw(obj)
    }
    fn write_raw(&mut self, obj: ObjRef, raw: u32) -> Result<()> {
        self.check_changes(&[crate::servo::changes::write(obj)])?;
        self.servo_ops().write_raw(obj, raw)
    }
    fn raw_frame(&mut self, bytes: [u8; FRAME_LEN]) -> Result<[u8; FRAME_LEN]> {
        if self.restricted() {
            self.check_changes(&crate::servo::changes::frame(&bytes))?;
        }
        self.servo_ops().raw_frame(bytes)
    }
    fn read_resolution(&mut self) -> Result<u32> {
        self.servo_ops().read_resolution()
    }
    fn simulator(&mut self) -> Option<Arc<Mutex<crate::servo::sim::SimLine>>> {
        self.servo_ops().simulator()
    }
    fn sim_control(&self) -> Option<std::path::PathBuf> {
        self.servo_control.clone()
    }
    fn permits(&self, changes: &[Change]) -> Result<()> {
        self.check_changes(changes)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn an_unrestricted_guard_passes_everything_and_the_session_switch_stops_it() {
        let flag = Arc::new(AtomicBool::new(false));
        let sim = crate::k2::sim::open("K205-16DT", crate::core::Clock::stepped()).unwrap();
        let mut g = Guarded::new(Box::new(sim), None, flag.clone());
        let op = g.operands().parse("VW0").unwrap()[0];
        g.write(&[(op, Value::Int(5))]).unwrap();
        assert!(g.family_ops().is_none(), "a K2 has no generic family hook");
        flag.store(true, Ordering::Relaxed);
        let e = g.write(&[(op, Value::Int(6))]).unwrap_err();
        assert!(e.message.contains("--read-only"), "{e}");
        assert!(g.family_ops_for(&[]).unwrap().is_none(), "a read-only use is let through");
        assert!(g.as_k2().unwrap().pls(0).unwrap_err().message.contains("PLS 0"));
        assert_eq!(g.read(&[op]).unwrap(), vec![Value::Int(5)]);
    }
}
