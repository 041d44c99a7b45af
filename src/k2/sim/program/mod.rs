//! The simulated K2's CPU: programs loaded into the scan engine ([`crate::engine`]), the
//! scan cycle in virtual time, CPU modes and faults.
//!
//! **Scan cycle.** While in RUN, scan k starts at virtual time t_k: the hardware (pulse
//! outputs, counters, input signals) is brought up to t_k and the input image refreshed;
//! SM0.1 (first scan) and SM0.6 (scan toggle) are set; the user program runs, then the
//! helper program (if installed, as a subroutine called at the end of the main program
//! would); the scan time is the fixed overhead plus the cost-table time of the
//! instructions executed, at least the minimum scan (K80S: scan = program + interrupts +
//! internal processing). t_{k+1} = t_k + scan time. Communication is served between
//! scans: a Modbus request arriving at time t sees the image after every scan that
//! started before t. Outputs are the Q image itself (written as the program runs, read by
//! the pulse hardware at the next step) — a simplification of "written at the end of the
//! scan" that no client can observe, because clients are served only between scans.
//!
//! **Scan-time registers.** SMW22 last, SMW24 minimum, SMW26 maximum scan time in ms
//! (S7-200 convention; the K80S keeps the same three figures in F52/F51/F50).
//!
//! **Modes** (K2 §2.2.1; K80S modes). RUN scans; STOP does not scan, sets the outputs to
//! their STOP values (all off unless configured) and still serves Modbus; PAUSE freezes
//! without touching data or outputs and RUN continues where it stopped. The mode is the
//! switch × command table of §2.2.1: RUN only when the switch is at RUN and the last command
//! was RUN, STOP otherwise; the simulator's switch is a setting (`sim switch run|stop`),
//! and the last command is kept while the switch is at STOP, so turning the switch back to
//! RUN after a RUN command runs. A serious error (watchdog, bad indirect address, call
//! depth) stops the CPU with a fault record; a normal error (division by zero) is recorded
//! and the CPU continues (K2 §2.2.1, K80S 5.3.4).
//!
//! **Frozen time.** PAUSE and a DEBUG halt freeze the program's time: on RUN the timers,
//! the timed interrupts' schedule, a halted scan's clock and the program's clock bits
//! (SM0.4, SM0.5) are moved on by the time spent frozen ([`Plc::thaw`]), so nothing is
//! credited for it. The pulse and counter hardware keeps running in virtual time (it is
//! hardware, outside the CPU); its events wait (irq).

pub mod debug;
pub mod family;
pub mod irq;
pub mod motion;

#[cfg(test)]
mod tests;

use super::K2Sim;
use crate::core::{Error, Result};
use crate::engine::exec::Exit;
use crate::engine::{self, CostTable, Cpu, Fault, Program};
use family::{K2Family, K2Machine};
use serde::Serialize;
use std::time::Duration;

/// CPU modes.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Serialize, serde::Deserialize)]
#[serde(rename_all = "lowercase")]
pub enum Mode {
    Run,
    Stop,
    Pause,
    /// Halted at a breakpoint or stepping (K80S DEBUG).
    Debug,
}

impl Mode {
    pub fn name(self) -> &'static str {
        match self {
            Mode::Run => "RUN",
            Mode::Stop => "STOP",
            Mode::Pause => "PAUSE",
            Mode::Debug => "DEBUG",
        }
    }
}

/// A program in the CPU with its state.
pub struct Loaded {
    pub prog: Program,
    pub cpu: Cpu,
    /// Where it came from (file name, or "helper").
    pub source: String,
    /// The IL text it was compiled from (a snapshot stores this and the CPU state; the
    /// compiled program is rebuilt from it).
    pub text: String,
    /// Per-occurrence state of the K2 instructions.
    pub inst: Vec<motion::Inst>,
}

impl Loaded {
    pub(crate) fn new(prog: Program, source: String, text: &str) -> Loaded {
        Loaded { cpu: Cpu::new(&prog), prog, source, text: text.to_string(), inst: Vec::new() }
    }
    fn reset(&mut self) {
        self.cpu = Cpu::new(&self.prog);
        self.inst.clear();
    }
}

/// Scan statistics (kept in snapshots: a program reads them in SMW22–SMW26).
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, Serialize, serde::Deserialize)]
pub struct ScanStats {
    pub scans: u64,
    pub last_ns: u64,
    pub min_ns: u64,
    pub max_ns: u64,
    /// Instructions executed in the last scan.
    pub last_instructions: u64,
    pub total_instructions: u64,
    /// Interrupt routines run.
    pub interrupts: u64,
}

/// The CPU of a simulated K2.
pub struct Plc {
    pub user: Option<Loaded>,
    pub helper: Option<Loaded>,
    pub mode: Mode,
    /// The RUN/STOP switch (a setting in the simulator; STOP wins over a RUN command).
    pub switch_run: bool,
    /// The last mode command (`sim cpu run|stop|pause`), kept while the switch is at STOP
    /// (K2 §2.2.1 table).
    pub command: Mode,
    /// Virtual time spent frozen (PAUSE, DEBUG) since the program started: the program's
    /// clock bits run on `now − frozen_ns`.
    pub frozen_ns: u64,
    /// Interrupt events waiting while interrupts are disabled (DISI), or the CPU is paused
    /// or halted: run in order once they may (S7-200 interrupt queues).
    pub pending: Vec<u32>,
    /// Normal errors (division by zero …), newest last, at most
    /// [`crate::engine::exec::MAX_NORMAL_ERRORS`]; `error_count` counts all since loading. The
    /// CPU keeps running (K2 §2.2.1 "normal error": Err LED on, code saved; K80S 5.3.4).
    pub errors: Vec<Fault>,
    pub error_count: u64,
    /// The last STOP came from the program's STOP instruction.
    pub stopped_by_program: bool,
    /// AQ words in STOP (K2 §2.2.1: "all outputs, including DO and AO").
    pub stop_analog: Vec<u8>,
    pub faults: Vec<Fault>,
    pub stats: ScanStats,
    /// Scans since the last STOP→RUN (SM0.1 is on in scan 0).
    pub run_scans: u64,
    /// Start time of the next scan.
    pub next_scan: Duration,
    pub costs: CostTable,
    /// When the CPU entered PAUSE (timers resume from where they froze).
    pub paused_at: Option<Duration>,
    /// Next firing of timed interrupts 0 and 1 (irq).
    pub timed_next: [Option<Duration>; 2],
    /// Interrupt-routine time to add to the next scan.
    pub irq_ns: u64,
    /// Breakpoints: one flag per instruction of the user program.
    pub breaks: Vec<bool>,
    /// Whether any of `breaks` is set (the scan checks this, not the vector).
    pub has_breaks: bool,
    /// Where a DEBUG halt stopped (the next instruction).
    pub halted: Option<u32>,
    /// Q bytes in STOP (K2 §2.2.1: values from the hardware configuration; all off here).
    pub stop_outputs: Vec<u8>,
}

impl Plc {
    pub fn new(now: Duration, q_bytes: usize) -> Plc {
        Plc {
            user: None,
            helper: None,
            mode: Mode::Run,
            switch_run: true,
            command: Mode::Run,
            frozen_ns: 0,
            pending: Vec::new(),
            stop_analog: Vec::new(),
            stopped_by_program: false,
            errors: Vec::new(),
            error_count: 0,
            faults: Vec::new(),
            stats: ScanStats::default(),
            run_scans: 0,
            next_scan: now,
            costs: family::default_costs(),
            stop_outputs: vec![0; q_bytes],
            paused_at: None,
            timed_next: [None; 2],
            breaks: Vec::new(),
            has_breaks: false,
            halted: None,
            irq_ns: 0,
        }
    }

    pub fn has_program(&self) -> bool {
        self.user.is_some() || self.helper.is_some()
    }

    /// Power-up at `now` after a power cut: the programs stay in the CPU and start afresh
    /// (first-scan bit, timers and edges reset, no pending interrupt), in RUN if the switch
    /// says RUN, else in STOP; statistics, breakpoints and the stop values stay.
    pub fn restart(&mut self, now: Duration) {
        for l in [&mut self.user, &mut self.helper].into_iter().flatten() {
            l.reset();
        }
        self.mode = if self.switch_run && self.command == Mode::Run { Mode::Run } else { Mode::Stop };
        self.run_scans = 0;
        self.next_scan = now;
        self.paused_at = None;
        self.pending.clear();
        self.timed_next = [None; 2];
        self.irq_ns = 0;
        self.halted = None;
        self.faults.clear();
    }
}

impl Plc {
    /// Ends a freeze (PAUSE or DEBUG) at `now`: nothing the program sees is credited with the
    /// time spent frozen — running timers, the timed interrupts' next firings, the clock of a
    /// scan halted at a breakpoint, and the clock bits' phase all move on by it.
    pub fn thaw(&mut self, now: Duration) {
        let Some(at) = self.paused_at.take() else { return };
        let dt = u64::try_from(now.saturating_sub(at).as_nanos()).unwrap_or(0);
        if dt == 0 {
            return;
        }
        self.frozen_ns = self.frozen_ns.saturating_add(dt);
        for l in [&mut self.user, &mut self.helper].into_iter().flatten() {
            for t in l.cpu.timers.iter_mut().filter(|t| t.running) {
                t.mark_ns = t.mark_ns.saturating_add(dt);
            }
            if l.cpu.pc.is_some() {
                l.cpu.now_ns = l.cpu.now_ns.saturating_add(dt);
            }
        }
        let d = Duration::from_nanos(dt);
        for t in self.timed_next.iter_mut().flatten() {
            *t += d;
        }
        self.next_scan = self.next_scan.max(now);
    }

    /// Starts a freeze at `at` (no-op when already frozen).
    pub fn freeze(&mut self, at: Duration) {
        self.paused_at = self.paused_at.or(Some(at));
    }

    /// The program's clock at virtual `now_ns`: time spent frozen does not count.
    pub fn program_ns(&self, now_ns: u64) -> u64 {
        let now = self.paused_at.map_or(now_ns, |at| now_ns.min(u64::try_from(at.as_nanos()).unwrap_or(u64::MAX)));
        now.saturating_sub(self.frozen_ns)
    }
}

const COST_KEYS: &str = "keys: bit compare move arith real timer jump call special element overhead min_scan watchdog";

/// `200ns`, `1.5us`, `2µs`, `0.3ms`, `1s` → ns.
fn parse_ns(v: &str) -> Option<u64> {
    let v = v.trim();
    let split = v.find(|c: char| !(c.is_ascii_digit() || c == '.'))?;
    let (num, unit) = v.split_at(split);
    let n: f64 = num.parse().ok()?;
    let f = match unit {
        "ns" => 1.0,
        "us" | "µs" => 1e3,
        "ms" => 1e6,
        "s" => 1e9,
        _ => return None,
    };
    let ns = n * f;
    (ns.is_finite() && (0.0..=3.6e12).contains(&ns)).then_some(ns.round() as u64)
}

/// Scan times in ms for the SM registers (saturating).
fn ms16(ns: u64) -> u16 {
    (ns / 1_000_000).min(u16::MAX as u64) as u16
}

impl K2Sim {
    fn family(&self) -> K2Family {
        K2Family { space: *self.space(), costs: self.plc.as_ref().map(|p| p.costs.clone()) }
    }

    /// Changes the cost table (`sim program costs bit=150ns overhead=0.5ms min_scan=2ms
    /// watchdog=500ms …`); loaded programs are re-costed. Returns the table.
    pub fn set_costs(&mut self, spec: &str) -> Result<CostTable> {
        self.advance();
        let mut t = self.plc.as_ref().map_or_else(family::default_costs, |p| p.costs.clone());
        for item in spec.split_whitespace() {
            let (k, v) = item
                .split_once('=')
                .ok_or_else(|| Error::usage(format!("`{item}` is not KEY=DURATION")).hint(COST_KEYS))?;
            let ns = parse_ns(v).ok_or_else(|| {
                Error::usage(format!("{k}={v}: a duration with a unit, e.g. 200ns, 1.5us, 0.3ms")).hint(COST_KEYS)
            })?;
            let k = k.to_ascii_lowercase();
            match k.as_str() {
                "overhead" => t.overhead_ns = ns,
                "min_scan" => t.min_scan_ns = ns,
                "watchdog" if ns > 0 => t.watchdog_ns = ns,
                "element" => t.per_element_ns = ns.min(u32::MAX as u64) as u32,
                _ => {
                    let c = crate::engine::CostClass::ALL
                        .iter()
                        .find(|c| c.name() == k)
                        .ok_or_else(|| Error::usage(format!("no cost `{k}`")).hint(COST_KEYS))?;
                    t.class_ns[*c as usize] = ns.min(u32::MAX as u64) as u32;
                }
            }
        }
        let p = self.plc_mut();
        p.costs = t.clone();
        for l in [&mut p.user, &mut p.helper].into_iter().flatten() {
            l.prog.set_costs(t.clone());
        }
        Ok(t)
    }

    /// Compiles IL text for this model (load errors name `file:line:column`).
    pub fn compile(&self, text: &str, file: &str) -> Result<Program> {
        engine::compile(text, file, &self.family()).map_err(|e| e.device(self.model().name))
    }

    /// [`Self::compile`] with the tags of a tag file beside the program (and those the
    /// program declares in `VAR_GLOBAL`: engine::symbols).
    pub fn compile_with_tags(&self, text: &str, file: &str, tags: Option<&crate::tags::TagTable>) -> Result<Program> {
        engine::compile_with_tags(text, file, &self.family(), tags).map_err(|e| e.device(self.model().name))
    }

    /// Compiles IL text for this model with the cost table `costs` (a snapshot's).
    pub(crate) fn compile_costed(&self, text: &str, file: &str, costs: CostTable) -> Result<Program> {
        let family = K2Family { space: *self.space(), costs: Some(costs) };
        engine::compile(text, file, &family).map_err(|e| e.device(self.model().name))
    }

    fn plc_mut(&mut self) -> &mut Plc {
        let (now, q) = (self.last, self.mem.q.len());
        self.plc.get_or_insert_with(|| Box::new(Plc::new(now, q)))
    }

    /// Loads a user program (replacing any); the CPU restarts it from its first scan.
    /// Loading is allowed in any mode (the real K2 wants STOP for a download; the
    /// simulator loads as if it switched to STOP, downloaded and returned).
    pub fn load_program(&mut self, text: &str, file: &str) -> Result<String> {
        self.load_program_with_tags(text, file, None)
    }

    /// [`Self::load_program`] with the tags of a tag file beside the program. The program is
    /// kept (for snapshots and `sim serve` restarts) with those tags appended as a
    /// `VAR_GLOBAL` block after its last line, so it loads again without the file and its
    /// line numbers stay.
    pub fn load_program_with_tags(
        &mut self,
        text: &str,
        file: &str,
        tags: Option<&crate::tags::TagTable>,
    ) -> Result<String> {
        let prog = self.compile_with_tags(text, file, tags)?;
        let kept = match tags {
            Some(t) if !t.is_empty() => {
                let block = crate::tags::export::to_iec(t, self.space()).map_err(|e| e.device(self.model().name))?;
                std::borrow::Cow::Owned(format!("{text}\n{block}"))
            }
            _ => std::borrow::Cow::Borrowed(text),
        };
        let text: &str = &kept;
        self.advance();
        let now = self.last;
        let n = prog.source_instructions;
        let warnings: String = prog.warnings.iter().map(|w| format!("\nwarning: {w}")).collect();
        let p = self.plc_mut();
        p.breaks = vec![false; prog.code.len()];
        p.has_breaks = false;
        p.halted = None;
        if p.mode == Mode::Debug {
            p.mode = Mode::Run;
        }
        p.user = Some(Loaded::new(prog, file.to_string(), text));
        if let Some(h) = &mut p.helper {
            h.reset();
        }
        p.run_scans = 0;
        p.next_scan = now;
        p.faults.clear();
        p.pending.clear();
        p.errors.clear();
        p.error_count = 0;
        if p.mode == Mode::Run {
            self.advance_to(now);
        }
        Ok(format!(
            "{file}: {n} instructions loaded; CPU {}{warnings}",
            self.plc.as_ref().map_or("RUN", |p| p.mode.name())
        ))
    }

    /// Installs the helper program (`lib/k2_agent.il` for this mailbox base) as text.
    pub fn load_helper(&mut self, text: &str, source: &str) -> Result<()> {
        let prog = self.compile(text, source)?;
        let now = self.last;
        let p = self.plc_mut();
        p.helper = Some(Loaded::new(prog, source.to_string(), text));
        if p.user.is_none() {
            p.run_scans = 0;
            p.next_scan = now;
        }
        // A PLC in RUN has been scanning before any client looks: run the first scan now.
        self.advance_to(now);
        Ok(())
    }

    /// Removes the user program.
    pub fn unload_program(&mut self) {
        self.advance();
        if let Some(p) = &mut self.plc {
            p.user = None;
            p.breaks.clear();
            p.has_breaks = false;
            p.halted = None;
            if p.mode == Mode::Debug {
                p.mode = Mode::Run;
                p.next_scan = self.last;
            }
        }
    }

    /// The CPU, when a program is loaded.
    pub fn plc(&self) -> Option<&Plc> {
        self.plc.as_deref()
    }

    /// Sets the mode by command (`sim cpu run|stop|pause`). The command is kept; the mode
    /// follows the switch × command table (K2 §2.2.1): with the switch at STOP the CPU stays
    /// in STOP (an error saying so; the RUN command takes effect when the switch returns to RUN).
    pub fn set_mode(&mut self, want: Mode) -> Result<Mode> {
        self.advance();
        let p = self.plc_mut();
        if want != Mode::Debug {
            p.command = want;
        }
        let switch_run = p.switch_run;
        let refused = want != Mode::Stop && !switch_run;
        let new = self.enter_mode(if switch_run { want } else { Mode::Stop });
        if refused {
            return Err(Error::state(format!(
                "the RUN/STOP switch is at STOP: the CPU stays in STOP (manual §2.2.1); the {} command takes effect when the switch is at RUN",
                want.name()
            ))
            .hint("sim switch run"));
        }
        Ok(new)
    }

    /// Puts the CPU into mode `new` now (the transitions: STOP → RUN restarts, PAUSE/DEBUG →
    /// RUN continues with the frozen time not credited, STOP sets the STOP outputs).
    fn enter_mode(&mut self, new: Mode) -> Mode {
        let now = self.last;
        let p = self.plc_mut();
        let old = p.mode;
        if new == old {
            return new;
        }
        if new != Mode::Stop {
            p.stopped_by_program = false;
        }
        match new {
            Mode::Stop => {
                p.paused_at = None;
                p.pending.clear();
            }
            Mode::Pause | Mode::Debug => p.freeze(now),
            Mode::Run => {
                p.halted = None;
                p.thaw(now);
                if old == Mode::Stop {
                    // STOP → RUN: a fresh start (first-scan bit, timers and edges reset);
                    // memory keeps its values.
                    p.run_scans = 0;
                    for l in [&mut p.user, &mut p.helper].into_iter().flatten() {
                        l.reset();
                    }
                    p.timed_next = [None; 2];
                }
                p.next_scan = now;
            }
        }
        p.mode = new;
        if new == Mode::Stop {
            self.apply_stop_outputs();
        }
        if new == Mode::Run {
            self.advance_to(now);
        }
        new
    }

    /// The outputs' STOP values (K2 §2.2.1: "all outputs, including DO and AO", set in
    /// KincoBuilder's hardware configuration): `QB0=16#05 QB1=0 AQW0=16000` (bytes and
    /// words not named are off / 0). Returns the Q bytes.
    pub fn set_stop_outputs(&mut self, spec: &str) -> Result<Vec<u8>> {
        use crate::k2::operand::{Area, Width};
        let mut bytes = vec![0u8; self.mem.q.len()];
        let mut analog = vec![0u8; self.mem.aq.len()];
        for item in spec.split_whitespace() {
            let (k, v) = item.split_once('=').ok_or_else(|| {
                Error::usage(format!("`{item}` is not QBn=VALUE or AQWn=VALUE")).hint("e.g. QB0=16#05 AQW0=16000")
            })?;
            let ops = self.space().parse_k2(k)?;
            let op = ops[0];
            let lit =
                crate::core::literal::parse_literal(v).map_err(|e| Error::usage(format!("{v}: {}", e.message)))?;
            match (op.area, op.width) {
                (Area::Q, Width::Byte) if ops.len() == 1 => {
                    let val = lit.fit(crate::core::DataType::Byte, 8).map_err(Error::usage)?;
                    bytes[op.byte as usize] = val.as_i64() as u8;
                }
                (Area::AQ, Width::Word) if ops.len() == 1 => {
                    let val = lit.fit(crate::core::DataType::Int, 16).map_err(Error::usage)?;
                    // The AQ image holds words as the memory does (scratch write, then copy).
                    let keep = self.mem.aq.clone();
                    self.mem.write(&op, val.as_i64() as u16 as u32);
                    let b = op.byte as usize;
                    analog[b..b + 2].copy_from_slice(&self.mem.aq[b..b + 2]);
                    self.mem.aq = keep;
                }
                _ => {
                    return Err(Error::usage(format!(
                        "{k}: STOP values are set per output byte (QB0, QB1 …) or analog output word (AQW0 …)"
                    )))
                }
            }
        }
        let p = self.plc_mut();
        p.stop_outputs = bytes.clone();
        p.stop_analog = analog;
        if p.mode == Mode::Stop {
            self.apply_stop_outputs();
        }
        Ok(bytes)
    }

    /// The simulated mode switch: the mode becomes the §2.2.1 table's (switch RUN and last
    /// command RUN → RUN; otherwise STOP). Returns the mode.
    pub fn set_switch(&mut self, run: bool) -> Result<Mode> {
        self.advance();
        let p = self.plc_mut();
        let was = p.switch_run;
        p.switch_run = run;
        let command = p.command;
        let mode = p.mode;
        Ok(match (was, run) {
            (_, false) => self.enter_mode(Mode::Stop),
            // STOP → RUN on the switch: the kept command decides.
            (false, true) => self.enter_mode(command),
            (true, true) => mode,
        })
    }

    pub(super) fn apply_stop_outputs(&mut self) {
        let Some(p) = &self.plc else { return };
        let n = self.mem.q.len().min(p.stop_outputs.len());
        self.mem.q[..n].copy_from_slice(&p.stop_outputs[..n]);
        for (i, a) in self.mem.aq.iter_mut().enumerate() {
            *a = p.stop_analog.get(i).copied().unwrap_or(0);
        }
    }

    /// True when scans are due before `now` (the scan loop runs them).
    pub(super) fn scan_due(&self, now: Duration) -> bool {
        self.plc.as_ref().is_some_and(|p| p.mode == Mode::Run && p.has_program() && p.next_scan <= now)
    }

    /// Runs every scan that starts at or before `now`, bringing the hardware to each
    /// scan's start first. Called from `advance_to`.
    pub(super) fn run_scans(&mut self, now: Duration) {
        while self.scan_due(now) {
            let t = self.plc.as_ref().map_or(now, |p| p.next_scan);
            self.advance_with_interrupts(t);
            self.one_scan(t);
        }
    }

    /// Runs `n` scans now in stepped time (`sim scan N`): each at its modelled start.
    pub fn scan_n(&mut self, n: u64) -> Result<ScanStats> {
        self.advance();
        if !self.plc.as_ref().is_some_and(|p| p.has_program()) {
            return Err(Error::state("no program is loaded: no scan runs").hint("sim program load FILE.il"));
        }
        for _ in 0..n {
            let Some(p) = &self.plc else { break };
            if p.mode != Mode::Run || !p.has_program() {
                return Err(Error::state(format!("the CPU is in {}: no scan runs", p.mode.name())).hint("sim cpu run"));
            }
            let t = p.next_scan.max(self.last);
            self.advance_with_interrupts(t);
            self.one_scan(t);
        }
        Ok(self.plc.as_ref().map(|p| p.stats).unwrap_or_default())
    }

    fn one_scan(&mut self, t: Duration) {
        if let Some(pc) = self.scan_part(t, u64::MAX, true) {
            // A breakpoint: the CPU halts in DEBUG before instruction `pc`; the program's
            // time freezes at the halted scan's time.
            if let Some(p) = self.plc.as_mut() {
                p.mode = Mode::Debug;
                p.halted = Some(pc);
                let at = p.user.as_ref().map_or(t, |l| Duration::from_nanos(l.cpu.now_ns));
                p.freeze(at);
            }
        }
    }

    /// Runs the scan starting at `t`, or continues the user program's halted scan, for at
    /// most `limit` user-program instructions, stopping at breakpoints when `brk`.
    /// Returns the instruction it halted before, or `None` when the scan completed.
    pub(super) fn scan_part(&mut self, t: Duration, limit: u64, brk: bool) -> Option<u32> {
        if self.plc.as_ref()?.user.as_ref().is_none_or(|l| l.cpu.pc.is_none()) {
            // Events that waited (DISI, PAUSE, DEBUG) run before the scan's program.
            self.run_pending(t);
        }
        let mut p = self.plc.take()?;
        let resuming = p.user.as_ref().is_some_and(|l| l.cpu.pc.is_some());
        let t = if resuming { Duration::from_nanos(p.user.as_ref().map_or(0, |l| l.cpu.now_ns)) } else { t };
        if !resuming {
            // System bits from the program's point of view.
            let first = p.run_scans == 0;
            let b = &mut self.mem.sm[0];
            *b = (*b & !(1 << 1 | 1 << 6)) | (first as u8) << 1 | ((p.run_scans % 2 == 1) as u8) << 6;
        }
        let now_ns = u64::try_from(t.as_nanos()).unwrap_or(u64::MAX);
        let mut fault = None;
        let mut raised = Vec::new();
        let mask = if brk && p.has_breaks { Some(&p.breaks[..]) } else { None };
        if let Some(l) = p.user.as_mut() {
            let mut m = K2Machine { sim: self, now: t, inst: &mut l.inst, raised: Vec::new() };
            let o = l.cpu.scan(&l.prog, &mut m, now_ns, limit, mask);
            raised.append(&mut m.raised);
            match o.exit {
                Exit::Fault(f) => fault = Some(f),
                Exit::Paused(pc) => {
                    if !raised.is_empty() {
                        self.events.extend(raised);
                    }
                    self.plc = Some(p);
                    return Some(pc);
                }
                Exit::Done => {}
            }
        }
        if fault.is_none() {
            if let Some(l) = p.helper.as_mut() {
                let mut m = K2Machine { sim: self, now: t, inst: &mut l.inst, raised: Vec::new() };
                let o = l.cpu.scan(&l.prog, &mut m, now_ns, u64::MAX, None);
                raised.append(&mut m.raised);
                if let Exit::Fault(f) = o.exit {
                    fault = Some(f);
                }
            }
        }
        if !raised.is_empty() {
            self.events.extend(raised);
        }
        let (mut cost, mut instrs) = (0, 0);
        for l in [&mut p.user, &mut p.helper].into_iter().flatten() {
            cost += l.cpu.spent_ns;
            instrs += l.cpu.executed;
            let errs = l.cpu.take_errors();
            if !errs.is_empty() {
                p.error_count += errs.len() as u64;
                p.errors.extend(errs);
                let over = p.errors.len().saturating_sub(crate::engine::exec::MAX_NORMAL_ERRORS);
                p.errors.drain(..over);
            }
        }
        let scan_ns = (p.costs.overhead_ns + cost + std::mem::take(&mut p.irq_ns)).max(p.costs.min_scan_ns).max(1);
        let s = &mut p.stats;
        s.scans += 1;
        s.last_ns = scan_ns;
        s.min_ns = if s.scans == 1 { scan_ns } else { s.min_ns.min(scan_ns) };
        s.max_ns = s.max_ns.max(scan_ns);
        s.last_instructions = instrs;
        s.total_instructions += instrs;
        self.mem.set_sm_word(22, ms16(s.last_ns));
        self.mem.set_sm_word(24, ms16(s.min_ns));
        self.mem.set_sm_word(26, ms16(s.max_ns));
        p.run_scans += 1;
        // After a halt the scan ends later than it started: never schedule into the past.
        p.next_scan = (t + Duration::from_nanos(scan_ns)).max(self.last);
        if let Some(f) = fault {
            p.faults.push(f);
            p.mode = Mode::Stop;
            self.plc = Some(p);
            self.apply_stop_outputs();
            return None;
        }
        self.plc = Some(p);
        self.take_stop_request();
        None
    }

    /// A STOP instruction ran (K80S 5.4.5): the CPU goes to STOP now that the scan or the
    /// routine is over (S7-200: "the transition to STOP is made at the end of the current
    /// scan").
    pub(super) fn take_stop_request(&mut self) {
        if std::mem::take(&mut self.stop_requested) {
            if let Some(p) = self.plc.as_mut() {
                p.stopped_by_program = true;
            }
            self.enter_mode(Mode::Stop);
        }
    }
}
