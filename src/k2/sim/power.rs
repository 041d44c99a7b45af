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
//! SM0.1 in the first scan, uptime from zero. A loss shorter than 20 ms is a dip, not a cut
//! ([`POWER_DIP`], K80S §5.2.2): the program pauses with its outputs held and carries on
//! afterwards with nothing lost and no restart. Both moments are exact in virtual time, so a
//! client that polls through the cut and one that never polls see the same PLC afterwards.

use super::K2Sim;
use crate::k2::catalog;
use crate::k2::memory::Memory;
use crate::k2::operand::Area;
use crate::k2::sim::hsc::HscChannel;
use crate::k2::sim::pto::PtoChannel;
use crate::k2::sm_map::{HSC_REGS, PTO_REGS};
use std::time::Duration;

/// A power loss shorter than this is a dip, not a cut (K80S CPU chapter §5.2.2, "instantaneous
/// power failure": under 20 ms the CPU pauses, holds its outputs, keeps its timers and timed
/// interrupt sources running and continues; from 20 ms it restarts as at power-up).
pub const POWER_DIP: Duration = Duration::from_millis(20);

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
            if on - off < POWER_DIP {
                if self.last < off {
                    self.advance_powered(off);
                    self.dip(id, off, on);
                }
                if now < on {
                    self.advance_powered(now);
                    return;
                }
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

    /// A dip shorter than [`POWER_DIP`] from `off` to `on` (K80S §5.2.2): the program pauses
    /// with the outputs held; memory, timers and the hardware carry on; a timed interrupt
    /// due during the dip runs once when it ends, repeats are dropped; no restart.
    fn dip(&mut self, id: u32, off: Duration, on: Duration) {
        self.events.extend(vec![(off, crate::k2::instr::EventKind::Fault { id, fault: 8 })]);
        if let Some(f) = self.faults.list.iter_mut().find(|f| f.id == id) {
            f.hits = 1;
        }
        if let Some(p) = self.plc.as_mut() {
            p.next_scan = p.next_scan.max(on);
            for t in p.timed_next.iter_mut().flatten() {
                *t = (*t).max(on);
            }
        }
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

    /// K80S §5.2.2: under 20 ms the CPU pauses with outputs held, timers and timed interrupt
    /// sources keep running (one interrupt due in the dip runs after it), no restart; from
    /// 20 ms it restarts as at power-up (SM0.1, memory lost).
    #[test]
    fn a_dip_under_20_ms_pauses_and_continues_a_longer_loss_restarts() {
        let run = |ms: u64| {
            let clock = Clock::stepped();
            let mut sim = crate::k2::sim::open("K205-16DT", clock.clone()).unwrap();
            sim.load_program(
                "PROGRAM MAIN\nLD %SM0.1\nINC %VW0\nMOVE B#50, %SMB34\nATCH TICK, 10\nENI\n\
                 LD %SM0.0\nTON T37, 2\nST %Q0.5\nLD %SM0.0\nINC %VW2\nEND_PROGRAM\n\
                 INTERRUPT TICK\nLD %SM0.0\nINC %VW4\nEND_INTERRUPT",
                "dip.il",
            )
            .unwrap();
            sim.mem.m[3] = 0x5A;
            clock.step(Duration::from_millis(300));
            let ops = sim.operands().parse("VW2").unwrap();
            let scans = sim.read(&ops).unwrap()[0].as_i64();
            crate::k2::sim::control::answer(&mut sim, &format!("fault power-loss after=1ms for={ms}ms"), true).unwrap();
            clock.step(Duration::from_millis(1 + ms / 2));
            sim.advance();
            let held = sim.mem.q[0] & 0x20 != 0;
            clock.step(Duration::from_millis(ms / 2 + 1));
            let v: Vec<i64> =
                ["VW0", "VW2", "VW4", "T37", "MB3"].iter().map(|n| read(&mut sim, n).unwrap().as_i64()).collect();
            (v, scans, held)
        };
        let (v, scans, held) = run(15);
        assert_eq!(v[0], 1, "a dip: no second first scan");
        assert!(held, "outputs held during the dip");
        assert!(v[1] - scans <= 3, "no scans in the dip: {} then {}", scans, v[1]);
        assert!(v[3] >= 3, "the 100 ms timer kept running: {}", v[3]);
        assert_eq!(v[4], 0x5A, "memory kept");
        // 5 ms ticks: 60 in 300 ms, then one for the 15 ms dip, not three.
        assert!((60..=62).contains(&v[2]), "one tick after the dip: {}", v[2]);
        let (v, _, held) = run(20);
        assert!(!held, "a 20 ms loss turns the outputs off");
        assert_eq!(v[0], 1, "restarted: SM0.1 counted again from a cleared VW0");
        assert_eq!(v[4], 0, "memory lost");
    }
}
