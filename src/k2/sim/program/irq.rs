//! Interrupts of the simulated K2: which events exist, their numbers, and when an attached
//! routine runs.
//!
//! Event numbers:
//! - **0–7 edge interrupts**: I0.0 rising 0, falling 1; I0.1 2/3; I0.2 4/5; I0.3 6/7. The
//!   K2 manual (§2.2.7) gives the four edge inputs but no numbers; these are the S7-200
//!   (= K5, which the manual says single-PV numbering follows) numbers.
//! - **10, 11 timed interrupts 0 and 1**: interval in SMB34 / SMB35 in units of 0.1 ms
//!   (K2 §2.1.2: "2 timed interrupts with a 0.1 ms base"; the registers are S7-200's;
//!   0 = off). The period starts when the routine is attached.
//! - **28 PTO0 complete** (K2 §3.4.2.3) and **64–191 multi-PV CV = PV** (K2 §3.3.4), from
//!   [`crate::k2::instr::EventKind::number`]; events the manual does not number cannot be
//!   attached.
//!
//! Waiting events: an event whose routine is attached while interrupts are disabled
//! (`DISI`), or while the CPU is in PAUSE or halted in DEBUG, is queued and its routine runs
//! once interrupts may run again — before the next scan's program after `ENI` or RUN — in
//! arrival order (S7-200 System Manual, "Understanding the Interrupt Priority and Queuing",
//! Table 9-22: an I/O queue of 16 and a timed queue of 8 entries; an event arriving at a
//! full queue is lost and sets SM4.1 (I/O) or SM4.2 (timed), Table 9-23). STOP empties the
//! queue. Timed interrupts do not fire while the CPU is frozen (PAUSE, DEBUG): their
//! schedule moves on by the frozen time (program::Plc::thaw).
//!
//! When: a routine runs at its event's virtual time. Events between two scans (an input
//! written by a client, a timed interrupt, a PTO finishing) run after the earlier scan's
//! program and before the next scan's program, in time order; the routine's cost-table
//! time is added to the next scan. Edges on I0.0–I0.3 come from writes to the input image
//! (shell, Lua, Modbus: at the write's time) and from `sim input` signals (at each edge's
//! time, computed from the wave; a routine between two hardware steps sees the memory as of
//! the step's end).

use super::super::K2Sim;
use super::family::K2Machine;
use super::Mode;
use crate::engine::exec::Exit;
use std::time::Duration;

/// Most edge interrupts a signal source raises in one step (a 200 kHz signal on an
/// attached input would otherwise run 400 000 routines per simulated second).
pub const MAX_SOURCE_EDGES: u64 = 100_000;

/// Timed interrupt events and their interval registers (SMB34, SMB35).
pub const TIMED: [(u32, u32); 2] = [(10, 34), (11, 35)];
/// Timed-interrupt time base (K2 §2.1.2).
pub const TIMED_BASE: Duration = Duration::from_micros(100);

/// Interrupt queue depths (S7-200 System Manual Table 9-22): I/O events, timed events.
pub const QUEUE_IO: usize = 16;
pub const QUEUE_TIMED: usize = 8;

fn is_timed(event: u32) -> bool {
    TIMED.iter().any(|t| t.0 == event)
}

/// Edge event for input bit `bit` (0–3) of I0.
pub fn edge_event(bit: u8, rising: bool) -> u32 {
    2 * bit as u32 + (!rising) as u32
}

impl K2Sim {
    /// Whether events reach routines now or later: a user program and a mode other than STOP.
    fn interrupts_live(&self) -> bool {
        self.plc.as_ref().is_some_and(|p| p.mode != Mode::Stop && p.user.is_some())
    }

    /// Runs the routine attached to `event` at virtual time `at` when the CPU is in RUN
    /// with interrupts enabled; queues it while they are disabled or the CPU is frozen.
    pub(crate) fn run_interrupt(&mut self, event: u32, at: Duration) {
        let Some(mut p) = self.plc.take() else { return };
        let waits = p.mode != Mode::Stop
            && p.user.as_ref().is_some_and(|l| l.cpu.attached_to(event).is_some())
            && (p.mode != Mode::Run || !p.user.as_ref().is_some_and(|l| l.cpu.interrupts_enabled));
        if waits {
            let (cap, bit) = if is_timed(event) { (QUEUE_TIMED, 2) } else { (QUEUE_IO, 1) };
            if p.pending.iter().filter(|e| is_timed(**e) == is_timed(event)).count() < cap {
                p.pending.push(event);
            } else {
                self.mem.sm[4] |= 1 << bit;
            }
            self.plc = Some(p);
            return;
        }
        if p.mode == Mode::Run {
            if let Some(l) = p.user.as_mut() {
                if let Some(pou) = l.cpu.handler(event) {
                    let at_ns = u64::try_from(at.as_nanos()).unwrap_or(u64::MAX);
                    let mut m = K2Machine { sim: self, now: at, inst: &mut l.inst, raised: Vec::new() };
                    let o = l.cpu.interrupt(&l.prog, &mut m, pou, at_ns);
                    let raised = std::mem::take(&mut m.raised);
                    p.irq_ns += o.cost_ns;
                    p.stats.interrupts += 1;
                    if !raised.is_empty() {
                        self.events.extend(raised);
                    }
                    if let Exit::Fault(f) = o.exit {
                        p.faults.push(f);
                        p.mode = Mode::Stop;
                        self.plc = Some(p);
                        self.apply_stop_outputs();
                        return;
                    }
                }
            }
        }
        self.plc = Some(p);
        self.take_stop_request();
    }

    /// Runs the events that waited, at `at`, while interrupts are enabled in RUN (a routine
    /// that disables them leaves the rest waiting). The overflow bits clear when the queue
    /// empties (S7-200 Table 9-23).
    pub(crate) fn run_pending(&mut self, at: Duration) {
        let mut ran = false;
        loop {
            let Some(p) = self.plc.as_mut() else { return };
            let ready = p.mode == Mode::Run && p.user.as_ref().is_some_and(|l| l.cpu.interrupts_enabled);
            if !ready || p.pending.is_empty() {
                if ran && p.pending.is_empty() {
                    self.mem.sm[4] &= !0b110;
                }
                return;
            }
            let ev = p.pending.remove(0);
            self.run_interrupt(ev, at);
            ran = true;
        }
    }

    /// Edge interrupts after the input image changed from `old` (a client's write).
    pub(crate) fn input_edge_interrupts(&mut self, old: &[u8]) {
        if !self.interrupts_live() {
            return;
        }
        let (a, b) = (old.first().copied().unwrap_or(0), self.mem.i.first().copied().unwrap_or(0));
        let at = self.last;
        for bit in 0..4u8 {
            let (was, is) = (a >> bit & 1 != 0, b >> bit & 1 != 0);
            if was != is {
                self.run_interrupt(edge_event(bit, is), at);
            }
        }
    }

    /// Numbered hardware events raised by the last hardware step, for their routines.
    pub(crate) fn queue_hw_events(&mut self, raised: &[(Duration, crate::k2::instr::EventKind)]) {
        if !self.interrupts_live() {
            return;
        }
        for (t, k) in raised {
            if let Some(n) = k.number() {
                self.irq_queue.push((*t, n as u32));
            }
        }
    }

    /// Runs queued hardware-event routines in time order.
    pub(crate) fn dispatch_queued(&mut self) {
        if self.irq_queue.is_empty() {
            return;
        }
        let mut q = std::mem::take(&mut self.irq_queue);
        q.sort_by_key(|e| e.0);
        for (t, ev) in q.drain(..) {
            self.run_interrupt(ev, t);
        }
        self.irq_queue = q;
    }

    /// The next timed interrupt at or before `until`: (time, index).
    fn next_timed(&mut self, until: Duration) -> Option<(Duration, usize)> {
        let live = self.interrupts_live();
        let last = self.last;
        let sm = [self.mem.sm[TIMED[0].1 as usize], self.mem.sm[TIMED[1].1 as usize]];
        let p = self.plc.as_mut()?;
        if matches!(p.mode, Mode::Pause | Mode::Debug) {
            return None; // frozen: the schedule moves on at RUN (Plc::thaw)
        }
        let cpu = &p.user.as_ref()?.cpu;
        let mut best: Option<(Duration, usize)> = None;
        for (i, &(ev, _)) in TIMED.iter().enumerate() {
            let period = TIMED_BASE * sm[i] as u32;
            if !live || cpu.attached_to(ev).is_none() || period.is_zero() {
                p.timed_next[i] = None;
                continue;
            }
            let next = *p.timed_next[i].get_or_insert(last + period);
            if next <= until && best.is_none_or(|b| next < b.0) {
                best = Some((next, i));
            }
        }
        best
    }

    /// Edges of `sim input` signals on I0.0–I0.3 in (from, to] whose events have routines
    /// attached, queued at their times (at most [`MAX_SOURCE_EDGES`] per step).
    fn queue_source_edges(&mut self, from: Duration, to: Duration) {
        if to <= from || (self.inputs.edges().is_empty() && !self.inputs.has_shaped()) || !self.interrupts_live() {
            return;
        }
        let Some(cpu) = self.plc.as_ref().and_then(|p| p.user.as_ref()).map(|u| &u.cpu) else { return };
        let mut q = Vec::new();
        for &(pin, rise, fall) in self.inputs.edges() {
            if pin.0 != 0 || pin.1 > 3 {
                continue;
            }
            for (wave, rising) in [(rise, true), (fall, false)] {
                let ev = edge_event(pin.1, rising);
                if cpu.attached_to(ev).is_none() {
                    continue;
                }
                let (a, b) = (wave.rises(from), wave.rises(to));
                for k in a + 1..=b.min(a + MAX_SOURCE_EDGES) {
                    q.push((wave.rise_time(k), ev));
                }
            }
        }
        // Wired pulse trains and encoders: their level changes, listed edge by edge.
        if self.inputs.has_shaped() {
            let none = crate::k2::sim::fault::Faults::default();
            let (a, b) = (crate::k2::sim::inputs::ns(from), crate::k2::sim::inputs::ns(to));
            for bit in 0..4u8 {
                let pin = (0, bit);
                let attached = [true, false].iter().any(|r| cpu.attached_to(edge_event(bit, *r)).is_some());
                if !attached || self.inputs.pin_edges(pin).is_none() {
                    continue;
                }
                let (_, ch) = crate::k2::sim::edges::changes(&self.inputs, &none, pin, a, b, false);
                for (t, rising) in ch.into_iter().take(MAX_SOURCE_EDGES as usize) {
                    let ev = edge_event(bit, rising);
                    if cpu.attached_to(ev).is_some() {
                        q.push((Duration::from_nanos(t), ev));
                    }
                }
            }
        }
        self.irq_queue.extend(q);
    }

    /// Brings the hardware to `until`, running timed and hardware-event routines at their
    /// times on the way.
    pub(crate) fn advance_with_interrupts(&mut self, until: Duration) {
        let from = self.last;
        self.queue_source_edges(from, until);
        while let Some((t, i)) = self.next_timed(until) {
            self.advance_hw(t);
            self.dispatch_queued();
            let period = TIMED_BASE * self.mem.sm[TIMED[i].1 as usize] as u32;
            if let Some(p) = self.plc.as_mut() {
                p.timed_next[i] = Some(t + period.max(TIMED_BASE));
            }
            self.run_interrupt(TIMED[i].0, t);
        }
        self.advance_hw(until);
        self.dispatch_queued();
    }
}
