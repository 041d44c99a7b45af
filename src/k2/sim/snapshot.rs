//! The K2 simulator's section of a snapshot ([`crate::snapshot`]): its complete state —
//! every memory area, the pulse outputs and counters mid-run, the input signals, the event
//! log, the real-time clock, the backup-area bookkeeping, the helper program — as plain data
//! (serde). Restoring onto a simulator of the same model makes it continue exactly as the
//! saved one would have.
//!
//! Not captured: the registers and limits (they come from the model) and caches that are
//! worked out again from the state. A program engine adds its own section beside this one.

use super::events::EventLogState;
use super::hsc::HscState;
use super::inputs::{Inputs, Source};
use super::pto::PtoState;
use super::rtc::Rtc;
use super::state::{hex, unhex, Retain};
use super::K2Sim;
use crate::k2::operand::Area;
use crate::msg;
use serde::{Deserialize, Serialize};
use std::time::Duration;

/// Memory areas as hex strings (compact, diffable).
#[derive(Clone, Debug, Serialize, Deserialize)]
pub struct MemImage {
    pub i: String,
    pub q: String,
    pub m: String,
    pub v: String,
    pub sm: String,
    pub ai: String,
    pub aq: String,
    pub t: Vec<i16>,
    pub c: Vec<i16>,
    /// Timer and counter bits (one byte each, 0/1); empty in a file older than them (all off).
    #[serde(default)]
    pub tq: String,
    #[serde(default)]
    pub cq: String,
}

#[derive(Clone, Debug, Serialize, Deserialize)]
pub struct BackupState {
    pub last: u32,
    pub writes: Vec<u64>,
    pub session: Vec<u64>,
    /// `(area, first byte, length)`.
    pub retain: Vec<(String, u32, u32)>,
    pub since_ns: u64,
}

#[derive(Clone, Debug, Serialize, Deserialize)]
pub struct K2State {
    pub model: String,
    /// Virtual times (ns) of power-up and of the last step.
    pub start_ns: u64,
    pub last_ns: u64,
    pub mem: MemImage,
    pub pto: Vec<PtoState>,
    pub hsc: Vec<HscState>,
    pub inputs: Vec<Source>,
    pub events: EventLogState,
    pub rtc: Rtc,
    pub backup: BackupState,
    /// The helper program's mailbox base when it runs (`--agent`).
    #[serde(default)]
    pub agent_base: Option<u32>,
    /// The CPU and its programs (text and execution state), when one was loaded.
    #[serde(default)]
    pub program: Option<ProgramState>,
    /// Injected faults and their schedule.
    #[serde(default)]
    pub faults: super::fault::Faults,
}

fn ns(d: Duration) -> u64 {
    u64::try_from(d.as_nanos()).unwrap_or(u64::MAX)
}

fn area_named(name: &str) -> Option<Area> {
    [Area::V, Area::M, Area::I, Area::Q, Area::AI, Area::AQ, Area::SM].into_iter().find(|a| a.name() == name)
}

impl K2Sim {
    /// The simulator's complete state.
    ///
    /// Every field of [`K2Sim`], its memory and its backup bookkeeping is named below (no
    /// `..`; the pulse outputs, counters, event log and CPU do the same in their own `save`):
    /// a field added to the simulator does not compile until it is saved here or named as
    /// not the machine's state, with why.
    pub fn snapshot_state(&self) -> K2State {
        let K2Sim {
            // The device's name card and operand space: from the model.
            info: _,
            space: _,
            mem,
            // The session's clock: the snapshot's `clock_us`.
            clock: _,
            start,
            // `start` in ns (restored from it).
            start_ns: _,
            last,
            pto,
            hsc,
            inputs,
            events,
            rtc,
            backup,
            faults,
            // The wires: the snapshot's `wiring` section ([`crate::snapshot`]).
            wiring: _,
            plc,
            agent_base,
            // Scratch space of one step, empty between steps.
            raised: _,
            run_ends: _,
            // Events for interrupt routines, queued and run within one step.
            irq_queue,
            // A STOP instruction's request, acted on at the end of the scan that ran it.
            stop_requested,
        } = self;
        debug_assert!(irq_queue.is_empty() && !*stop_requested, "a K2 simulator saved in the middle of a step");
        let crate::k2::memory::Memory { i, q, m, v, sm, ai, aq, t, c, tq, cq } = mem;
        let super::state::Backup {
            last: backup_last,
            writes,
            session,
            retain,
            // The state file and its lock: where this simulator persists, from its URL.
            path: _,
            lock: _,
            since,
        } = backup;
        K2State {
            model: self.model().name.to_string(),
            start_ns: ns(*start),
            last_ns: ns(*last),
            mem: MemImage {
                i: hex(i),
                q: hex(q),
                m: hex(m),
                v: hex(v),
                sm: hex(sm),
                ai: hex(ai),
                aq: hex(aq),
                t: t.clone(),
                c: c.clone(),
                tq: hex(tq),
                cq: hex(cq),
            },
            pto: pto.iter().map(|p| p.save()).collect(),
            hsc: hsc.iter().map(|h| h.save()).collect(),
            inputs: inputs.sources().to_vec(),
            events: events.save(),
            rtc: *rtc,
            backup: BackupState {
                last: *backup_last,
                writes: writes.clone(),
                session: session.clone(),
                retain: retain.iter().map(|r| (r.area.name().to_string(), r.first, r.len)).collect(),
                since_ns: ns(*since),
            },
            agent_base: *agent_base,
            program: plc.as_ref().map(|p| ProgramState::save(p)),
            faults: faults.clone(),
        }
    }

    /// Restores a saved state. Refuses (changing nothing) a state of another model or one
    /// whose sizes do not fit this model.
    pub fn restore_snapshot(&mut self, s: &K2State) -> Result<(), String> {
        if s.model != self.model().name {
            return Err(msg!("k2-snapshot-model", saved = s.model.as_str(), model = self.model().name).into());
        }
        // Programs are recompiled from their text before anything changes.
        let plc = match &s.program {
            Some(ps) => Some(Box::new(ps.build(self, s.agent_base)?)),
            None => None,
        };
        let area = |name: &str, text: &str, want: usize| -> Result<Vec<u8>, String> {
            let b = unhex(text).ok_or_else(|| msg!("k2-snapshot-area-hex", area = name).text)?;
            if b.len() != want {
                return Err(msg!(
                    "k2-snapshot-area-size",
                    area = name,
                    n = b.len(),
                    model = s.model.as_str(),
                    want = want
                )
                .into());
            }
            Ok(b)
        };
        let m = &self.mem;
        let mem = (
            area("I", &s.mem.i, m.i.len())?,
            area("Q", &s.mem.q, m.q.len())?,
            area("M", &s.mem.m, m.m.len())?,
            area("V", &s.mem.v, m.v.len())?,
            area("SM", &s.mem.sm, m.sm.len())?,
            area("AI", &s.mem.ai, m.ai.len())?,
            area("AQ", &s.mem.aq, m.aq.len())?,
        );
        if s.mem.t.len() != m.t.len() || s.mem.c.len() != m.c.len() {
            return Err(msg!("k2-snapshot-element-counts").into());
        }
        // Timer and counter bits: all off in a file older than them.
        let bits = |name: &str, text: &str, want: usize| {
            if text.is_empty() {
                Ok(vec![0; want])
            } else {
                area(name, text, want)
            }
        };
        let (tq, cq) = (bits("T bits", &s.mem.tq, m.tq.len())?, bits("C bits", &s.mem.cq, m.cq.len())?);
        if s.pto.len() != self.pto.len() || s.hsc.len() != self.hsc.len() {
            return Err(msg!("k2-snapshot-channel-counts").into());
        }
        let retain = s
            .backup
            .retain
            .iter()
            .map(|(a, first, len)| {
                area_named(a)
                    .map(|area| Retain { area, first: *first, len: *len })
                    .ok_or_else(|| msg!("k2-snapshot-no-area", area = a.as_str()).text)
            })
            .collect::<Result<Vec<_>, String>>()?;
        // Everything checked that can be: now apply. A counter mode is checked as it loads;
        // on that (corrupt file) error the counters are reset first.
        let mut hsc = self.hsc.clone();
        for (h, st) in hsc.iter_mut().zip(&s.hsc) {
            h.load(st.clone())?;
        }
        self.hsc = hsc;
        (self.mem.i, self.mem.q, self.mem.m, self.mem.v, self.mem.sm, self.mem.ai, self.mem.aq) = mem;
        self.mem.t = s.mem.t.clone();
        self.mem.c = s.mem.c.clone();
        (self.mem.tq, self.mem.cq) = (tq, cq);
        for (p, st) in self.pto.iter_mut().zip(&s.pto) {
            p.load(st.clone());
        }
        let mut inputs = Inputs::default();
        for src in &s.inputs {
            inputs.add(*src);
        }
        self.inputs = inputs;
        self.events.load(s.events.clone());
        self.rtc = s.rtc;
        self.backup.last = s.backup.last;
        self.backup.writes = s.backup.writes.clone();
        self.backup.session = s.backup.session.clone();
        self.backup.retain = retain;
        self.backup.since = Duration::from_nanos(s.backup.since_ns);
        self.faults = s.faults.clone();
        self.start = Duration::from_nanos(s.start_ns);
        self.start_ns = s.start_ns;
        self.last = Duration::from_nanos(s.last_ns);
        self.plc = plc;
        self.agent_base = s.agent_base;
        Ok(())
    }
}

/// A loaded program in a snapshot: its text (recompiled on restore) and its execution state.
#[derive(Clone, Debug, serde::Serialize, serde::Deserialize)]
pub struct LoadedState {
    pub source: String,
    pub text: String,
    pub cpu: crate::engine::Cpu,
    pub inst: Vec<super::program::motion::Inst>,
}

/// The simulated CPU in a snapshot: mode, switch, scan count and schedule, and its programs.
#[derive(Clone, Debug, serde::Serialize, serde::Deserialize)]
pub struct ProgramState {
    pub mode: super::program::Mode,
    pub switch_run: bool,
    pub run_scans: u64,
    pub next_scan_ns: u64,
    pub timed_next_ns: [Option<u64>; 2],
    pub stop_outputs: Vec<u8>,
    /// AQ words in STOP.
    #[serde(default)]
    pub stop_analog: Vec<u8>,
    /// The last mode command (K2 §2.2.1 table).
    #[serde(default = "run_mode")]
    pub command: super::program::Mode,
    /// Frozen time so far and, while frozen, since when (PAUSE, DEBUG).
    #[serde(default)]
    pub frozen_ns: u64,
    #[serde(default)]
    pub paused_at_ns: Option<u64>,
    /// Interrupt events waiting.
    #[serde(default)]
    pub pending: Vec<u32>,
    /// Normal errors kept (division by zero …; the Err LED is on while any is) and how many
    /// there were since loading (K2 §2.2.1 "normal error": the code is saved).
    #[serde(default)]
    pub errors: Vec<crate::engine::exec::Fault>,
    #[serde(default)]
    pub error_count: u64,
    /// The serious error that stopped the CPU, if one did.
    #[serde(default)]
    pub faults: Vec<crate::engine::exec::Fault>,
    /// The last STOP came from the program's STOP instruction.
    #[serde(default)]
    pub stopped_by_program: bool,
    /// Where a DEBUG halt stopped (the next instruction of the user program) and the
    /// instructions with breakpoints.
    #[serde(default)]
    pub halted: Option<u32>,
    #[serde(default)]
    pub breaks: Vec<u32>,
    /// Interrupt-routine time still to add to the next scan.
    #[serde(default)]
    pub irq_ns: u64,
    pub user: Option<LoadedState>,
    /// The helper's execution state (its text is regenerated from `agent_base`).
    pub helper_cpu: Option<crate::engine::Cpu>,
    /// Scan statistics: the scan count and the last, shortest and longest scan times a
    /// program reads in SMW22/SMW24/SMW26. A file older than them starts them afresh.
    #[serde(default)]
    pub stats: super::program::ScanStats,
    /// The cost table (`sim program costs …`); `None` in a file older than it (the defaults).
    #[serde(default)]
    pub costs: Option<crate::engine::CostTable>,
}

fn run_mode() -> super::program::Mode {
    super::program::Mode::Run
}

impl ProgramState {
    /// Every field of the CPU and its programs is named (no `..`): a field added to them
    /// does not compile until it is saved here or named as not the machine's state.
    fn save(p: &super::program::Plc) -> ProgramState {
        let super::program::Plc {
            user,
            helper,
            mode,
            switch_run,
            command,
            frozen_ns,
            pending,
            errors,
            error_count,
            stopped_by_program,
            stop_analog,
            faults,
            stats,
            run_scans,
            next_scan,
            costs,
            paused_at,
            timed_next,
            irq_ns,
            breaks,
            // Whether any of `breaks` is set (restored from them).
            has_breaks: _,
            halted,
            stop_outputs,
        } = p;
        let loaded = |l: &super::program::Loaded| {
            let super::program::Loaded {
                // Compiled again from `text` on restore.
                prog: _,
                cpu,
                source,
                text,
                inst,
            } = l;
            LoadedState { source: source.clone(), text: text.clone(), cpu: cpu.clone(), inst: inst.clone() }
        };
        ProgramState {
            mode: *mode,
            switch_run: *switch_run,
            run_scans: *run_scans,
            next_scan_ns: ns(*next_scan),
            timed_next_ns: timed_next.map(|t| t.map(ns)),
            stop_outputs: stop_outputs.clone(),
            stop_analog: stop_analog.clone(),
            command: *command,
            frozen_ns: *frozen_ns,
            paused_at_ns: paused_at.map(ns),
            pending: pending.clone(),
            errors: errors.clone(),
            error_count: *error_count,
            faults: faults.clone(),
            stopped_by_program: *stopped_by_program,
            halted: *halted,
            breaks: breaks.iter().enumerate().filter(|(_, b)| **b).map(|(i, _)| i as u32).collect(),
            irq_ns: *irq_ns,
            user: user.as_ref().map(loaded),
            // The helper's text is regenerated from `agent_base`.
            helper_cpu: helper.as_ref().map(|l| loaded(l).cpu),
            stats: *stats,
            costs: (*costs != super::program::family::default_costs()).then(|| costs.clone()),
        }
    }

    /// Rebuilds the CPU: programs recompiled from their text (the helper's regenerated for
    /// its mailbox base), execution state put back. Changes nothing in `sim`.
    fn build(&self, sim: &K2Sim, agent_base: Option<u32>) -> Result<super::program::Plc, String> {
        use super::program::{Loaded, Plc};
        let mut p = Plc::new(Duration::from_nanos(self.next_scan_ns), sim.mem.q.len());
        if let Some(c) = &self.costs {
            p.costs = c.clone();
        }
        p.stats = self.stats;
        // Compiled with the saved costs, not the ones this simulator had before the restore.
        let compile = |text: &str, file: &str| sim.compile_costed(text, file, p.costs.clone());
        if let Some(base) = agent_base {
            let text = crate::k2::agent::il::program(sim.model(), base);
            let prog = compile(&text, "k2_agent.il")
                .map_err(|e| msg!("k2-snapshot-helper-program", error = e.to_string()).text)?;
            let mut l = Loaded::new(prog, "k2_agent.il".to_string(), &text);
            if let Some(cpu) = &self.helper_cpu {
                l.cpu = cpu.clone();
            }
            p.helper = Some(l);
        }
        if let Some(u) = &self.user {
            let prog = compile(&u.text, &u.source)
                .map_err(|e| msg!("k2-snapshot-program", source = u.source.as_str(), error = e.to_string()).text)?;
            p.breaks = vec![false; prog.code.len()];
            let mut l = Loaded::new(prog, u.source.clone(), &u.text);
            l.cpu = u.cpu.clone();
            l.inst = u.inst.clone();
            p.user = Some(l);
        }
        p.mode = self.mode;
        p.switch_run = self.switch_run;
        p.run_scans = self.run_scans;
        p.timed_next = self.timed_next_ns.map(|t| t.map(Duration::from_nanos));
        p.stop_outputs = self.stop_outputs.clone();
        p.stop_analog = self.stop_analog.clone();
        p.command = self.command;
        p.frozen_ns = self.frozen_ns;
        p.paused_at = self.paused_at_ns.map(Duration::from_nanos);
        p.pending = self.pending.clone();
        p.errors = self.errors.clone();
        p.error_count = self.error_count;
        p.faults = self.faults.clone();
        p.stopped_by_program = self.stopped_by_program;
        p.irq_ns = self.irq_ns;
        let code_len = p.user.as_ref().map_or(0, |l| l.prog.code.len());
        if let Some(h) = self.halted {
            if h as usize >= code_len {
                return Err(msg!("k2-snapshot-halt", at = h, n = code_len).into());
            }
            p.halted = Some(h);
        }
        for &b in &self.breaks {
            let slot = p
                .breaks
                .get_mut(b as usize)
                .ok_or_else(|| msg!("k2-snapshot-breakpoint", at = b, n = code_len).text)?;
            *slot = true;
            p.has_breaks = true;
        }
        Ok(p)
    }
}
