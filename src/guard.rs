//! The write guard: a device wrapper every opened device sits in, so the session's write
//! rules hold for every path to a device — `set`, Lua, the typed helpers, the K2
//! instructions and the servo's DS402 helpers alike. A command written next year reaches
//! the device through the same wrapper and cannot forget the rules.
//!
//! The rules are the device profile's `read_only` and `allow` ([`crate::profile::Guard`])
//! and the session-wide read-only switch (`--read-only`). The guard checks lists of
//! [`Change`]s — operands written, and actions with the names they change — and knows no
//! device family. What counts as a change:
//!
//! - `Device::write`: the operands written; the whole batch is checked before anything
//!   is sent.
//! - [`Device::family`], the one capability hook: a family's operations are handed out only
//!   for the changes the caller states, which the guard checks first. Each family's
//!   accessor states them for every call it makes, computed by the family itself: a K2
//!   instruction (`k2::ops`, `k2::changes`: PLS, PSTOP, HDEF, HSC change their channel's
//!   registers and output, SET_RTC the clock), a servo object write or hand-made frame
//!   (`servo::ops`, `servo::changes`), a UMPK command's action (`umpk:reset` …). A call
//!   that changes nothing states nothing and passes.
//!
//! Batches: a typed helper computes everything it will change first and asks
//! [`Device::permits`]; the guard refuses the whole command before anything is sent,
//! naming the profile, the rule, the register and the profile's file:line. The per-call
//! checks of the families' accessors stay as the backstop for code that does not ask first.
//!
//! Deliberately passed through: reading; the interrupt event log (`events`, `wait event`
//! consume plcsh's own log, not machine state); client-side options (`set_option`:
//! word order, timeouts, a simulator's backup-area end); and simulation controls
//! (`k2::simulator`, `servo::simulator`), which act on the simulated world around a
//! device (input signals, injected faults) and exist only on simulators, never on a real
//! machine: they are reached through the same hook, stating no changes.

use crate::core::device::Change;
use crate::core::{Device, DeviceInfo, Error, ErrorKind, Operand, OperandSpace, Result, Value};
use crate::profile::Guard;
use std::any::Any;
use std::sync::atomic::{AtomicBool, Ordering};
use std::sync::Arc;

/// The pseudo-operand SET_RTC changes (a profile's allow list may name it).
pub use crate::core::device::CLOCK;

/// A device behind the session's write rules.
pub struct Guarded {
    inner: Box<dyn Device>,
    rules: Option<Guard>,
    /// The session-wide read-only switch (`--read-only`), shared by every device.
    session_read_only: Arc<AtomicBool>,
}

impl Guarded {
    pub fn new(inner: Box<dyn Device>, rules: Option<Guard>, session_read_only: Arc<AtomicBool>) -> Guarded {
        Guarded { inner, rules, session_read_only }
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
            return Err(Error::new(ErrorKind::Refused, format!("{doing}: the session is read-only (--read-only)"))
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
    fn family(&mut self, changes: &[Change]) -> Result<Option<&mut dyn Any>> {
        self.check_changes(changes)?;
        self.inner.family(changes)
    }
    fn permits(&self, changes: &[Change]) -> Result<()> {
        self.check_changes(changes)
    }
    fn set_option(&mut self, key: &str, value: &str) -> Result<()> {
        self.inner.set_option(key, value)
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::k2::K2Ops;

    #[test]
    fn an_unrestricted_guard_passes_everything_and_the_session_switch_stops_it() {
        let flag = Arc::new(AtomicBool::new(false));
        let sim = crate::k2::sim::open("K205-16DT", crate::core::Clock::stepped()).unwrap();
        let mut g = Guarded::new(Box::new(sim), None, flag.clone());
        let op = g.operands().parse("VW0").unwrap()[0];
        g.write(&[(op, Value::Int(5))]).unwrap();
        assert!(g.family(&[]).unwrap().is_some(), "an unrestricted guard hands out the family's operations");
        let pls = Change::Action { what: "PLS 0".into(), touches: vec!["Q0.0".into(), "SMB66".into()] };
        assert!(g.family(std::slice::from_ref(&pls)).unwrap().is_some());
        flag.store(true, Ordering::Relaxed);
        let e = g.write(&[(op, Value::Int(6))]).unwrap_err();
        assert!(e.message.contains("--read-only"), "{e}");
        assert!(g.family(&[]).unwrap().is_some(), "a use that changes nothing is let through");
        let e = g.family(&[pls]).expect_err("a stated change is checked");
        assert!(e.message.contains("PLS 0") && e.message.contains("--read-only"), "{e}");
        assert!(crate::k2::ops(&mut g).unwrap().pls(0).unwrap_err().message.contains("PLS 0"));
        assert_eq!(g.read(&[op]).unwrap(), vec![Value::Int(5)]);
    }
}
