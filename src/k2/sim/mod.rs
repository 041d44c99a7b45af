//! The in-process K2 simulator: a memory image of any catalogued model, behaving as the
//! manual says, driven by the session's virtual clock.
//!
//! Everything time-dependent is computed from elapsed virtual time when the simulator is
//! touched ([`K2Sim::advance`]), never by ticking: the system bits (SM0.0 always on, SM0.1
//! first scan, SM0.5 1-second clock, SM0.6 scan toggle), and — as their modules land — the
//! pulse outputs and counters. The Modbus server (`plcsh sim serve`) serves this same type.

pub mod modbus_server;
pub mod rtu_frame;

use crate::core::{Clock, Device, DeviceInfo, Error, ErrorKind, Operand, OperandSpace, Result, Value};
use crate::k2::catalog::{self, Model};
use crate::k2::memory::Memory;
use crate::k2::operand::{Area, K2Operand, Width};
use crate::k2::space::K2Space;
use std::time::Duration;

/// Scan time the simulator assumes (the manual gives no figure; 1 ms is typical of a
/// small K2 program). SM0.1 is on for the first scan, SM0.6 toggles every scan.
pub const SCAN_TIME: Duration = Duration::from_millis(1);

/// A simulated K2.
pub struct K2Sim {
    info: DeviceInfo,
    space: K2Space,
    pub mem: Memory,
    pub clock: Clock,
    /// Virtual time the simulator was powered up.
    start: Duration,
    /// Virtual time of the last `advance`.
    pub last: Duration,
}

impl K2Sim {
    pub fn new(model: &'static Model, clock: Clock) -> K2Sim {
        let start = clock.now();
        let mut sim = K2Sim {
            info: DeviceInfo { family: "k2", model: model.name.to_string(), link: "sim".into(), simulated: true },
            space: K2Space::new(model),
            mem: Memory::new(model),
            clock,
            start,
            last: start,
        };
        sim.refresh_system_bits(start);
        sim
    }

    pub fn model(&self) -> &'static Model {
        self.space.model
    }

    pub fn space(&self) -> &K2Space {
        &self.space
    }

    /// Time since power-up.
    pub fn uptime(&self) -> Duration {
        self.last - self.start
    }

    /// Brings the simulation up to the clock's current time.
    pub fn advance(&mut self) {
        let now = self.clock.now().max(self.last);
        self.advance_to(now);
    }

    /// Brings the simulation up to virtual time `now`.
    pub fn advance_to(&mut self, now: Duration) {
        self.last = now;
        self.refresh_system_bits(now);
    }

    fn refresh_system_bits(&mut self, now: Duration) {
        let up = now.saturating_sub(self.start);
        let scans = up.as_micros() / SCAN_TIME.as_micros();
        let ms = up.as_millis();
        let mut b = 0u8;
        b |= 1; // SM0.0 always on (§8)
        if scans == 0 {
            b |= 1 << 1; // SM0.1 first scan (§8)
        }
        if (ms / 30_000).is_multiple_of(2) {
            b |= 1 << 4; // SM0.4 1-minute clock (S7-200 convention)
        }
        if (ms / 500).is_multiple_of(2) {
            b |= 1 << 5; // SM0.5 1-second clock: 0.5 s on, 0.5 s off
        }
        if scans % 2 == 1 {
            b |= 1 << 6; // SM0.6 toggles every scan
        }
        self.mem.sm[0] = b;
    }

    /// Reads one operand's raw pattern at the current time.
    pub fn read_raw(&mut self, op: &K2Operand) -> u32 {
        self.mem.read(op)
    }

    /// Refuses writes the PLC would not accept.
    fn check_writable(&self, op: &K2Operand) -> Result<()> {
        if op.area == Area::SM && op.byte == 0 {
            return Err(Error::new(
                ErrorKind::Refused,
                format!("{} holds the system status bits and is read-only", op.canonical()),
            )
            .operand(op.canonical())
            .hint("SM0.0 is always on, SM0.1 marks the first scan, SM0.5 is the 1-second clock"));
        }
        if op.area == Area::I && matches!(op.width, Width::Group { .. }) {
            return Ok(());
        }
        Ok(())
    }
}

impl Device for K2Sim {
    fn info(&self) -> &DeviceInfo {
        &self.info
    }

    fn operands(&self) -> &dyn OperandSpace {
        &self.space
    }

    fn read(&mut self, ops: &[Operand]) -> Result<Vec<Value>> {
        self.advance();
        Ok(ops
            .iter()
            .map(|o| {
                let k = K2Operand::from_key(o.key);
                o.dtype.decode(self.mem.read(&k))
            })
            .collect())
    }

    fn write(&mut self, items: &[(Operand, Value)]) -> Result<()> {
        for (o, _) in items {
            self.check_writable(&K2Operand::from_key(o.key))?;
        }
        self.advance();
        for (o, v) in items {
            let k = K2Operand::from_key(o.key);
            let raw = o.dtype.encode(v);
            self.mem.write(&k, raw);
        }
        Ok(())
    }

    fn as_k2(&mut self) -> Option<&mut dyn crate::k2::K2Ops> {
        Some(self)
    }
}

impl crate::k2::K2Ops for K2Sim {
    fn model(&self) -> &'static Model {
        self.space.model
    }
    fn as_sim(&mut self) -> Option<&mut K2Sim> {
        Some(self)
    }
}

/// Opens `sim:MODEL` (or `sim:` for the default model).
pub fn open(model: &str, clock: Clock) -> Result<K2Sim> {
    let name = if model.is_empty() { catalog::DEFAULT_MODEL } else { model };
    Ok(K2Sim::new(catalog::lookup(name)?, clock))
}

#[cfg(test)]
mod tests {
    use super::*;
    use std::sync::atomic::AtomicBool;

    fn sim() -> (K2Sim, Clock) {
        let clock = Clock::stepped();
        (open("K205-16DT", clock.clone()).unwrap(), clock)
    }

    fn get(s: &mut K2Sim, text: &str) -> Value {
        let op = s.space().parse(text).unwrap()[0];
        s.read(&[op]).unwrap()[0]
    }

    #[test]
    fn system_bits_follow_virtual_time() {
        let (mut s, clock) = sim();
        assert_eq!(get(&mut s, "SM0.0"), Value::Bool(true));
        assert_eq!(get(&mut s, "SM0.1"), Value::Bool(true), "first scan");
        assert_eq!(get(&mut s, "SM0.5"), Value::Bool(true));
        clock.step(Duration::from_millis(1));
        assert_eq!(get(&mut s, "SM0.1"), Value::Bool(false), "after the first scan");
        assert_eq!(get(&mut s, "SM0.6"), Value::Bool(true));
        clock.sleep(Duration::from_millis(499), &AtomicBool::new(false));
        assert_eq!(get(&mut s, "SM0.5"), Value::Bool(false), "SM0.5 off after 0.5 s");
        clock.step(Duration::from_millis(500));
        assert_eq!(get(&mut s, "SM0.5"), Value::Bool(true), "SM0.5 on again after 1 s");
        assert_eq!(get(&mut s, "SM0.0"), Value::Bool(true));
    }

    #[test]
    fn smb0_is_read_only() {
        let (mut s, _) = sim();
        let op = s.space().parse("SM0.1").unwrap()[0];
        let e = s.write(&[(op, Value::Bool(false))]).unwrap_err();
        assert_eq!(e.kind, ErrorKind::Refused);
    }

    #[test]
    fn a_refused_batch_writes_nothing() {
        let (mut s, _) = sim();
        let vw = s.space().parse("VW0").unwrap()[0];
        let sm = s.space().parse("SMB0").unwrap()[0];
        assert!(s.write(&[(vw, Value::Int(7)), (sm, Value::Int(0))]).is_err());
        assert_eq!(get(&mut s, "VW0"), Value::Int(0));
    }
}
