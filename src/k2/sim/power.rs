//! A power cut on the simulated K2 (`sim fault power-loss for=5s`): the PLC is gone for the
//! fault's window and comes back as a real one does after a power cycle (manual §2.2.8–
//! §2.2.10, k2.md §7) — with only what survives a power cut:
//!
//! - kept: the E2PROM backup area (VB3648 up to the configured end), the battery-retained
//!   ranges (`sim retain`), the real-time clock (it keeps running through the cut), the
//!   E2PROM write counts, the program in the CPU and the RUN/STOP switch;
//! - lost: every other byte of I, Q, M, V, SM, AI, AQ, T and C, running pulse trains, the
//!   high-speed counters' counts, pending interrupts and the program's timers and edges.
//!
//! While the power is off the PLC answers nothing (a `no-reply` to every request, on every
//! transport), runs no scan and drives no output. At power-up it starts as at first power-on:
//! SM0.1 in the first scan, uptime from zero. Both moments are exact in virtual time, so a
//! client that polls through the cut and one that never polls see the same PLC afterwards.

use super::K2Sim;
use crate::k2::catalog;
use crate::k2::memory::Memory;
use crate::k2::operand::Area;
use crate::k2::sim::hsc::HscChannel;
use crate::k2::sim::pto::PtoChannel;
use crate::k2::sm_map::{HSC_REGS, PTO_REGS};
use std::time::Duration;

impl K2Sim {
    /// [`Self::advance_to`] when a power loss is set: up to the cut as usual, nothing while
    /// the power is off, a power-up at the window's end, then as usual again.
    pub(crate) fn advance_through_power_loss(&mut self, now: Duration) {
        let mut windows: Vec<(u32, Duration, Duration)> = self.faults.power_windows().collect();
        windows.sort_by_key(|w| w.1);
        for (id, off, on) in windows {
            if on <= self.last || now < off {
                continue;
            }
            if self.last < off {
                self.advance_powered(off);
                self.power_off(id, off);
            }
            if now < on {
                self.last = now;
                return;
            }
            self.power_on(on);
        }
        self.advance_powered(now);
    }

    /// The cut at `at`: outputs go dark at once (what a client reads after the power returns
    /// is decided at power-up).
    fn power_off(&mut self, id: u32, at: Duration) {
        self.events.extend(vec![(at, crate::k2::instr::EventKind::Fault { id, fault: 8 })]);
        if let Some(f) = self.faults.list.iter_mut().find(|f| f.id == id) {
            f.hits = 1;
        }
        self.mem.q.iter_mut().for_each(|b| *b = 0);
        self.mem.aq.iter_mut().for_each(|b| *b = 0);
        self.last = at;
    }

    /// Power returns at `at`: memory from what a cut keeps, hardware channels and the CPU
    /// as at power-on.
    fn power_on(&mut self, at: Duration) {
        let model = self.model();
        let mut mem = Memory::new(model);
        let lo = catalog::EEPROM_FIRST as usize;
        let hi = (self.backup.last as usize + 1).min(self.mem.v.len());
        mem.v[lo..hi].copy_from_slice(&self.mem.v[lo..hi]);
        for r in &self.backup.retain {
            let range = r.first as usize..(r.first + r.len) as usize;
            match r.area {
                Area::C => mem.c[range.clone()].copy_from_slice(&self.mem.c[range]),
                a => mem.area_mut(a)[range.clone()].copy_from_slice(&self.mem.area(a)[range]),
            }
        }
        self.pto = model.pto.iter().map(|p| PtoChannel::new(PTO_REGS[p.channel as usize], *p, &mut mem)).collect();
        self.hsc = model.hsc.iter().map(|h| HscChannel::new(HSC_REGS[h.channel as usize], *h)).collect();
        self.mem = mem;
        self.irq_queue.clear();
        self.start = at;
        self.start_ns = super::inputs::ns(at);
        self.last = at;
        if let Some(p) = self.plc.as_mut() {
            p.restart(at);
        }
        self.refresh_system_bits(at);
    }
}

#[cfg(test)]
mod tests {
    use crate::core::{Clock, Device, Value};
    use std::time::Duration;

    fn read(sim: &mut super::K2Sim, name: &str) -> crate::core::Result<Value> {
        let ops = sim.operands().parse(name).unwrap();
        sim.read(&ops).map(|v| v[0])
    }

    /// One scenario, read at the instants `polls` (ms) or never: the PLC after the cut.
    fn scenario(polls: &[u64]) -> (Vec<i64>, u64) {
        let clock = Clock::stepped();
        let mut sim = crate::k2::sim::open("K205-16DT", clock.clone()).unwrap();
        let rtc_before = sim.rtc.read(sim.last).to_secs();
        sim.set_retain("VB100..VB101").unwrap();
        let ops = sim.operands().parse("VW100").unwrap();
        sim.write(&[(ops[0], Value::Int(1111))]).unwrap();
        for (name, v) in [("VW0", 2222), ("VW3700", 3333), ("MB0", 5), ("QB0", 255)] {
            let ops = sim.operands().parse(name).unwrap();
            sim.write(&[(ops[0], Value::Int(v))]).unwrap();
        }
        crate::k2::sim::control::answer(&mut sim, "fault power-loss after=1s for=2s", true).unwrap();
        let mut at = 0;
        for &p in polls {
            clock.step(Duration::from_millis(p - at));
            at = p;
            let r = read(&mut sim, "VW0");
            let off = (1000..3000).contains(&p);
            assert_eq!(r.is_err(), off, "a read at {p} ms");
        }
        clock.step(Duration::from_millis(4000 - at));
        let mut vals: Vec<i64> =
            ["VW100", "VW0", "VW3700", "MB0", "QB0"].iter().map(|n| read(&mut sim, n).unwrap().as_i64()).collect();
        // The clock ran through the cut: 4 s after the start.
        vals.push(sim.rtc.read(sim.last).to_secs() - rtc_before);
        (vals, sim.uptime().as_millis() as u64)
    }

    #[test]
    fn a_power_cut_keeps_the_backup_area_and_retained_ranges_only_whoever_polls() {
        let never = scenario(&[]);
        // VW100 retained, VW0 lost, VW3700 in the backup area, MB0 lost, outputs off;
        // uptime counts from the power-up at 3 s.
        assert_eq!(never, (vec![1111, 0, 3333, 0, 0, 4], 1000));
        let mut rng = crate::core::test_rng::Rng(29);
        for _ in 0..20 {
            let mut polls: Vec<u64> = (0..8).map(|_| rng.below(4000)).collect();
            polls.sort_unstable();
            polls.dedup();
            assert_eq!(scenario(&polls), never, "polled at {polls:?}");
        }
    }

    #[test]
    fn a_power_loss_needs_its_length() {
        let e = crate::k2::sim::fault::parse("power-loss").unwrap_err();
        assert!(e.contains("for=5s"), "{e}");
        assert!(crate::k2::sim::fault::parse("power-loss for=1s on VW0").is_err());
    }
}
