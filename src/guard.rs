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
//!
//! The write log ([`WriteLog`]): because every write passes here, this is also where a
//! commissioning report learns what plcsh changed on the machine. While the session's log is
//! on (a run recording a report), the guard reads each operand it is about to let change
//! (the old value), and the value after: a plain write's new value is the one written (or
//! the device's refusal); a family operation (a servo object write, a K2 instruction) is
//! handed out before its value is known, so its operands are read back at the device's next
//! use (or when the log is taken), which is right after the operation in every helper that
//! reads back. An action whose change has no operand (`clock`) is logged without values.
//! Nothing of this runs while the log is off: the usual case costs one flag load.

use crate::core::device::Change;
use crate::core::Clock;
use crate::core::{Device, DeviceInfo, Error, ErrorKind, Operand, OperandSpace, Result, Value};
use crate::profile::Guard;
use serde::Serialize;
use std::any::Any;
use std::sync::atomic::{AtomicBool, Ordering};
use std::sync::{Arc, Mutex};

/// The pseudo-operand SET_RTC changes (a profile's allow list may name it).
pub use crate::core::device::CLOCK;

/// How many writes one log keeps; later ones are counted, not kept (a loop that writes a
/// register every scan for an hour must not grow a report without bound).
pub const LOG_LIMIT: usize = 10_000;

/// One write plcsh made to a device, as the guard saw it.
#[derive(Clone, Debug, PartialEq, Serialize)]
pub struct Written {
    /// Virtual time of the write, in ms since the session's clock started.
    pub t_ms: f64,
    /// The device's session name.
    pub device: String,
    /// The operand or object, named as the device names it.
    pub operand: String,
    /// The instruction or operation that made the change (`PLS 0`), for a family operation.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub action: Option<String>,
    /// The value before (none when the device would not say).
    pub old: Option<Value>,
    /// The value after: the one written, or read back after a family operation.
    pub new: Option<Value>,
    /// The operand's tag name: never set here (the guard sees operands only, design guide
    /// "Names are a layer over operands"); the report fills it from the device's names.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub name: Option<String>,
    /// The device's or the rules' refusal, when the write did not happen.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub refused: Option<String>,
}

/// The session's log of writes (module doc): off until a run records a report.
#[derive(Debug)]
pub struct WriteLog {
    on: AtomicBool,
    clock: Clock,
    entries: Mutex<(Vec<Written>, u64)>,
    /// Devices with family operations whose new values are still to be read back.
    waiting: Mutex<Vec<String>>,
}

impl WriteLog {
    pub fn new(clock: Clock) -> WriteLog {
        WriteLog {
            on: AtomicBool::new(false),
            clock,
            entries: Mutex::new((Vec::new(), 0)),
            waiting: Mutex::new(Vec::new()),
        }
    }

    /// Empties the log and starts logging.
    pub fn start(&self) {
        *self.entries.lock().unwrap_or_else(|e| e.into_inner()) = (Vec::new(), 0);
        self.on.store(true, Ordering::Relaxed);
    }

    /// Stops logging (the entries stay until the next start).
    pub fn stop(&self) {
        self.on.store(false, Ordering::Relaxed);
    }

    pub fn is_on(&self) -> bool {
        self.on.load(Ordering::Relaxed)
    }

    /// The writes logged so far, and how many more were made beyond [`LOG_LIMIT`].
    pub fn entries(&self) -> (Vec<Written>, u64) {
        self.entries.lock().unwrap_or_else(|e| e.into_inner()).clone()
    }

    /// The devices whose last family operation is still to be read back.
    pub fn waiting(&self) -> Vec<String> {
        self.waiting.lock().unwrap_or_else(|e| e.into_inner()).clone()
    }

    fn wait_for(&self, device: &str, waits: bool) {
        let mut w = self.waiting.lock().unwrap_or_else(|e| e.into_inner());
        w.retain(|d| d != device);
        if waits {
            w.push(device.to_string());
        }
    }

    fn now_ms(&self) -> f64 {
        (self.clock.now().as_secs_f64() * 1e6).round() / 1e3
    }

    fn push(&self, w: Written) {
        let mut e = self.entries.lock().unwrap_or_else(|e| e.into_inner());
        if e.0.len() < LOG_LIMIT {
            e.0.push(w);
        } else {
            e.1 += 1;
        }
    }
}

/// A family operation's change whose new value is read at the device's next use.
struct Unsettled {
    entry: Written,
    op: Option<Operand>,
}

/// A device behind the session's write rules.
pub struct Guarded {
    inner: Box<dyn Device>,
    rules: Option<Guard>,
    /// The session-wide read-only switch (`--read-only`), shared by every device.
    session_read_only: Arc<AtomicBool>,
    /// The session's write log and this device's name in it.
    log: Option<(Arc<WriteLog>, String)>,
    unsettled: Vec<Unsettled>,
}

impl Guarded {
    pub fn new(inner: Box<dyn Device>, rules: Option<Guard>, session_read_only: Arc<AtomicBool>) -> Guarded {
        Guarded { inner, rules, session_read_only, log: None, unsettled: Vec::new() }
    }

    /// The same guard, logging this device's writes as `name` in `log` while it is on.
    pub fn logging(mut self, log: Arc<WriteLog>, name: &str) -> Guarded {
        self.log = Some((log, name.to_string()));
        self
    }

    /// The log, when it is on.
    fn active_log(&self) -> Option<Arc<WriteLog>> {
        self.log.as_ref().filter(|(l, _)| l.is_on()).map(|(l, _)| l.clone())
    }

    /// One operand's value, or none when the device will not say.
    fn peek(&mut self, op: Operand) -> Option<Value> {
        self.inner.read(&[op]).ok().and_then(|v| v.into_iter().next())
    }

    /// Reads back the operands of the family operations logged since the last use.
    fn settle(&mut self) {
        if self.unsettled.is_empty() {
            return;
        }
        let list = std::mem::take(&mut self.unsettled);
        let Some((log, name)) = self.log.clone() else { return };
        log.wait_for(&name, false);
        for mut u in list {
            u.entry.new = u.op.and_then(|op| self.peek(op));
            log.push(u.entry);
        }
    }

    /// Logs a family operation's changes before it is handed out: old values now, new ones
    /// at the next use ([`Self::settle`]).
    fn log_changes(&mut self, changes: &[Change]) {
        let Some((log, name)) = self.log.clone().filter(|(l, _)| l.is_on()) else { return };
        let t_ms = log.now_ms();
        for c in changes {
            let (action, touched): (Option<String>, Vec<(String, Option<Operand>)>) = match c {
                Change::Write(op) => (None, vec![(self.inner.operands().name(op), Some(*op))]),
                Change::Action { what, touches } => {
                    let ops = touches
                        .iter()
                        .map(|t| {
                            let op = self.inner.operands().parse(t).ok().filter(|v| v.len() == 1).map(|v| v[0]);
                            (t.clone(), op)
                        })
                        .collect();
                    (Some(what.clone()), ops)
                }
            };
            for (operand, op) in touched {
                let old = op.and_then(|op| self.peek(op));
                let entry = Written {
                    t_ms,
                    device: name.clone(),
                    operand,
                    action: action.clone(),
                    old,
                    new: None,
                    name: None,
                    refused: None,
                };
                self.unsettled.push(Unsettled { entry, op });
            }
        }
        log.wait_for(&name, !self.unsettled.is_empty());
    }

    /// Makes the logged writes complete (the log's reader calls it before taking the log).
    pub fn settle_log(&mut self) {
        self.settle();
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
            let message = match what {
                Some(w) => crate::msg!("guard-read-only-action", action = w, name = name),
                None => crate::msg!("guard-read-only-write"),
            };
            return Err(Error::new(ErrorKind::Refused, message)
                .operand(name.to_string())
                .hint(crate::msg!("guard-hint-read-only")));
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

impl Guarded {
    /// Logs a plain write's items: old values as read before, new ones as written.
    fn log_writes(&self, log: &WriteLog, items: &[(Operand, Value)], old: Option<Vec<Value>>, refused: Option<&Error>) {
        let Some((_, name)) = &self.log else { return };
        let t_ms = log.now_ms();
        for (i, (op, v)) in items.iter().enumerate() {
            log.push(Written {
                t_ms,
                device: name.clone(),
                operand: self.inner.operands().name(op),
                action: None,
                old: old.as_ref().and_then(|o| o.get(i).copied()),
                new: refused.is_none().then_some(*v),
                name: None,
                refused: refused.map(|e| e.message.to_string()),
            });
        }
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
        self.settle();
        if ops.is_empty() {
            return Ok(Vec::new());
        }
        self.inner.read(ops)
    }
    fn read_into(&mut self, ops: &[Operand], out: &mut Vec<Value>) -> Result<()> {
        self.settle();
        self.inner.read_into(ops, out)
    }
    fn write(&mut self, items: &[(Operand, Value)]) -> Result<()> {
        self.settle();
        let log = self.active_log();
        // Unrestricted (the usual case) costs one flag load: no allocation per write.
        if self.restricted() {
            let changes: Vec<Change> = items.iter().map(|(op, _)| Change::Write(*op)).collect();
            if let Err(e) = self.check_changes(&changes) {
                if let Some(log) = &log {
                    self.log_writes(log, items, None, Some(&e));
                }
                return Err(e);
            }
        }
        let Some(log) = log else { return self.inner.write(items) };
        let ops: Vec<Operand> = items.iter().map(|(op, _)| *op).collect();
        let old = self.inner.read(&ops).ok();
        let r = self.inner.write(items);
        self.log_writes(&log, items, old, r.as_ref().err());
        r
    }
    fn requests(&self) -> u64 {
        self.inner.requests()
    }
    fn family(&mut self, changes: &[Change]) -> Result<Option<&mut dyn Any>> {
        self.settle();
        self.check_changes(changes)?;
        if !changes.is_empty() {
            self.log_changes(changes);
        }
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

    #[test]
    fn the_write_log_sees_plain_writes_family_operations_and_refusals_only_while_on() {
        let clock = crate::core::Clock::stepped();
        let log = Arc::new(WriteLog::new(clock.clone()));
        let flag = Arc::new(AtomicBool::new(false));
        let sim = crate::k2::sim::open("K205-16DT", clock.clone()).unwrap();
        let mut g = Guarded::new(Box::new(sim), None, flag.clone()).logging(log.clone(), "plc");
        let vw0 = g.operands().parse("VW0").unwrap()[0];
        g.write(&[(vw0, Value::Int(5))]).unwrap();
        assert!(log.entries().0.is_empty(), "nothing is logged while the log is off");
        log.start();
        clock.step(std::time::Duration::from_millis(250));
        g.write(&[(vw0, Value::Int(6))]).unwrap();
        let (e, more) = log.entries();
        assert_eq!(more, 0);
        assert_eq!(e.len(), 1);
        assert_eq!((e[0].device.as_str(), e[0].operand.as_str()), ("plc", "VW0"));
        assert_eq!((e[0].old, e[0].new, e[0].t_ms), (Some(Value::Int(5)), Some(Value::Int(6)), 250.0));
        // A family operation: its old values now, its new ones read back at the next use.
        let set = Change::Action { what: "test".into(), touches: vec!["VW0".into(), "clock".into()] };
        g.family(std::slice::from_ref(&set)).unwrap();
        assert_eq!(log.waiting(), vec!["plc".to_string()]);
        g.inner.write(&[(vw0, Value::Int(7))]).unwrap(); // what the operation did, behind the guard
        g.read(&[]).unwrap();
        assert!(log.waiting().is_empty());
        let e = log.entries().0;
        assert_eq!(e.len(), 3, "{e:?}");
        assert_eq!(
            (e[1].action.as_deref(), e[1].old, e[1].new),
            (Some("test"), Some(Value::Int(6)), Some(Value::Int(7)))
        );
        assert_eq!((e[2].operand.as_str(), e[2].old, e[2].new), ("clock", None, None), "no operand, no values");
        // A refused write is logged with the refusal and no new value.
        flag.store(true, Ordering::Relaxed);
        assert!(g.write(&[(vw0, Value::Int(8))]).is_err());
        let e = log.entries().0;
        assert!(e[3].refused.as_deref().is_some_and(|r| r.contains("--read-only")), "{e:?}");
        assert_eq!(e[3].new, None);
        log.stop();
        flag.store(false, Ordering::Relaxed);
        g.write(&[(vw0, Value::Int(9))]).unwrap();
        assert_eq!(log.entries().0.len(), 4);
    }
}
