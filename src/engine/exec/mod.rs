//! The interpreter: one [`Cpu`] (current result, logic stack, edge memories, timer and
//! counter state, call stack, interrupt attachments) executing a compiled [`Program`]
//! against a [`Machine`]. A scan runs the main program from the top; the time it costs is
//! the sum of the cost table over the instructions executed, checked against the watchdog
//! as it goes. Execution can stop at breakpoints or after N instructions and resume later
//! (the debugger), so the program counter and call stack are part of the state.
//!
//! All state types are plain data (serde) so a snapshot can store a running CPU.
//!
//! This file holds the CPU's state and the interpreter loop, which dispatches each
//! instruction (the one-line ones, jumps and calls, which move the program counter, run in
//! the loop itself). What an instruction group computes is in its own file: bit logic and
//! comparisons (`logic`), arithmetic, shifts and conversions (`arith`), block moves
//! (`moves`); timers and counters are [`super::timers`]. Operand access through pointers
//! is `operands`.

mod arith;
mod logic;
mod moves;
mod operands;

use super::compile::{Ins, Program};
use super::isa::{Arith, Comb};
use super::timers::{self, CounterState, TimerState};
use super::{read, write, Machine, Opd};
use crate::core::msg::Msg;
use crate::core::DataType;
use crate::msg;
use arith::{arith, arith_int, as_i64, convert, fits, invert, is_zero, mask, shift_out, unary, word_logic};
use logic::{compare, lcode, logic};
use moves::swap;
use operands::{bad, put, val};
use serde::{Deserialize, Serialize};

/// What stopped a CPU.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Serialize, Deserialize)]
pub enum FaultKind {
    /// A scan ran past the watchdog limit.
    Watchdog,
    /// An indirect address pointed outside memory.
    BadAddress,
    /// Subroutines nested deeper than the CPU allows.
    CallDepth,
    /// A family instruction refused.
    Instruction,
    /// Division by zero: a normal error (K2 §2.2.1 "normal error": code saved, Err LED;
    /// K80S 5.3.4: an operation error is recorded and the CPU continues).
    DivZero,
}

impl FaultKind {
    /// Fault codes (recorded with the fault; K80S records a code per fault).
    pub fn code(self) -> u16 {
        match self {
            FaultKind::Watchdog => 1,
            FaultKind::BadAddress => 2,
            FaultKind::CallDepth => 3,
            FaultKind::Instruction => 4,
            FaultKind::DivZero => 5,
        }
    }
    /// The fault's name in JSON (`"kind"`): a fixed English word, the same in every language.
    pub fn name(self) -> &'static str {
        match self {
            FaultKind::Watchdog => "watchdog",
            FaultKind::BadAddress => "bad indirect address",
            FaultKind::CallDepth => "call depth",
            FaultKind::Instruction => "instruction",
            FaultKind::DivZero => "division by zero",
        }
    }
    /// What the fault is called in its report (`fault 2 (bad indirect address): …`), in the
    /// user's language.
    pub fn label(self) -> Msg {
        match self {
            FaultKind::Watchdog => msg!("engine-fault-watchdog"),
            FaultKind::BadAddress => msg!("engine-fault-bad-address"),
            FaultKind::CallDepth => msg!("engine-fault-call-depth"),
            FaultKind::Instruction => msg!("engine-fault-instruction"),
            FaultKind::DivZero => msg!("engine-fault-div-zero"),
        }
    }
    /// Serious errors stop the CPU; normal ones are recorded and it continues (K2 §2.2.1).
    pub fn serious(self) -> bool {
        self != FaultKind::DivZero
    }
}

/// A serious error: what, where (filled in by the CPU) and when.
#[derive(Clone, Debug, PartialEq, Eq, Serialize, Deserialize)]
pub struct Fault {
    pub kind: FaultKind,
    pub message: String,
    /// Source line and instruction text where it happened.
    pub line: u32,
    pub instruction: String,
    /// Virtual time (ns) of the scan.
    pub at_ns: u64,
}

impl Fault {
    pub fn new(kind: FaultKind, message: impl Into<String>) -> Fault {
        Fault { kind, message: message.into(), line: 0, instruction: String::new(), at_ns: 0 }
    }
}

impl std::fmt::Display for Fault {
    fn fmt(&self, f: &mut std::fmt::Formatter) -> std::fmt::Result {
        let (code, name, message) = (self.kind.code(), self.kind.label().text, self.message.as_str());
        let m = if self.line > 0 {
            msg!(
                "engine-fault-at",
                code = code,
                name = &name,
                message = message,
                line = self.line,
                instruction = &self.instruction
            )
        } else {
            msg!("engine-fault", code = code, name = &name, message = message)
        };
        f.write_str(&m)
    }
}

/// How a run of instructions ended.
#[derive(Clone, Debug, PartialEq, Eq)]
pub enum Exit {
    /// The main program (or interrupt routine) reached its end.
    Done,
    /// Stopped before instruction `pc` (breakpoint or step limit).
    Paused(u32),
    Fault(Fault),
}

/// The result of one scan's program part.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct ScanOutcome {
    pub instructions: u64,
    /// Program time in ns from the cost table (without the fixed overhead).
    pub cost_ns: u64,
    pub exit: Exit,
}

/// Normal errors a CPU keeps between two looks by its family.
pub const MAX_NORMAL_ERRORS: usize = 16;

/// Nesting limit of subroutine calls (S7-200 allows 8 levels from the main program).
pub const MAX_CALL_DEPTH: usize = 8;
/// Depth of the logic stack and of parentheses.
pub const MAX_PARENS: usize = 8;

/// The CPU state of one program.
#[derive(Clone, Debug, Default, Serialize, Deserialize)]
pub struct Cpu {
    /// Current result.
    pub cr: bool,
    /// The S7-200 logic stack below the CR (bit 0 = top).
    pub stack: u32,
    parens: Vec<(u8, bool, bool)>,
    pub edges: Vec<bool>,
    pub timers: Vec<TimerState>,
    pub counters: Vec<CounterState>,
    /// Previous enable of edge-triggered family instructions, by instance.
    special_en: Vec<bool>,
    calls: Vec<u32>,
    /// Interrupt routine (POU index) attached to each event.
    pub attached: Vec<Option<u32>>,
    pub interrupts_enabled: bool,
    /// Where execution resumes (`None`: at the top of the next scan).
    pub pc: Option<u32>,
    /// Virtual time of the scan being executed (timers read it).
    pub now_ns: u64,
    /// Program time spent in the current scan (ns), for the watchdog.
    pub spent_ns: u64,
    /// Instructions executed in the current scan.
    pub executed: u64,
    /// Watchdog restart point (WDT): the scan time counts from here.
    wdt_mark_ns: u64,
    /// Normal errors since the family last took them ([`Cpu::take_errors`]), at most
    /// [`MAX_NORMAL_ERRORS`] (the newest kept).
    #[serde(default)]
    errors: Vec<Fault>,
}

impl Cpu {
    /// A CPU sized for `prog`, as at power-up (interrupts disabled until ENI).
    pub fn new(prog: &Program) -> Cpu {
        let specials = prog
            .code
            .iter()
            .filter_map(|i| if let Ins::Special { inst, .. } = i { Some(*inst as usize + 1) } else { None })
            .max()
            .unwrap_or(0);
        Cpu {
            edges: vec![false; prog.edges as usize],
            timers: vec![TimerState::default(); prog.timers as usize],
            counters: vec![CounterState::default(); prog.counters as usize],
            special_en: vec![false; specials],
            attached: Vec::new(),
            ..Cpu::default()
        }
    }

    /// The normal errors recorded since the last call (division by zero), oldest first.
    pub fn take_errors(&mut self) -> Vec<Fault> {
        std::mem::take(&mut self.errors)
    }

    /// Records a normal error at instruction `pc` (cold: only on the error path).
    #[cold]
    fn normal_error(&mut self, prog: &Program, pc: u32, kind: FaultKind, message: &str) {
        let mut f = Fault::new(kind, message);
        f.line = prog.pos.get(pc as usize).map_or(0, |p| p.line);
        f.instruction = prog.text.get(pc as usize).cloned().unwrap_or_default();
        f.at_ns = self.now_ns;
        if self.errors.len() >= MAX_NORMAL_ERRORS {
            self.errors.remove(0);
        }
        self.errors.push(f);
    }

    /// Runs the main program once from the top at virtual time `now_ns` (or resumes a
    /// paused scan), up to `limit` instructions or a breakpoint (`brk[pc]`).
    pub fn scan<M: Machine>(
        &mut self,
        prog: &Program,
        m: &mut M,
        now_ns: u64,
        limit: u64,
        brk: Option<&[bool]>,
    ) -> ScanOutcome {
        let start = match self.pc {
            Some(pc) => pc,
            None => {
                self.begin(now_ns);
                prog.main().entry
            }
        };
        let before = self.executed;
        let cost_before = self.spent_ns;
        let exit = if limit == u64::MAX && brk.is_none() {
            self.exec::<M, false>(prog, m, start, limit, None)
        } else {
            self.exec::<M, true>(prog, m, start, limit, brk)
        };
        ScanOutcome { instructions: self.executed - before, cost_ns: self.spent_ns - cost_before, exit }
    }

    fn begin(&mut self, now_ns: u64) {
        self.now_ns = now_ns;
        self.cr = false;
        self.stack = 0;
        self.parens.clear();
        self.calls.clear();
        self.spent_ns = 0;
        self.wdt_mark_ns = 0;
        self.executed = 0;
    }

    /// Runs interrupt routine `pou` to its end (interrupt routines are not stepped).
    /// Its time counts towards the scan it interrupts.
    pub fn interrupt<M: Machine>(&mut self, prog: &Program, m: &mut M, pou: u32, now_ns: u64) -> ScanOutcome {
        let saved = (self.cr, self.stack, std::mem::take(&mut self.parens), std::mem::take(&mut self.calls), self.pc);
        let saved_now = self.now_ns;
        self.now_ns = now_ns;
        self.cr = false;
        self.stack = 0;
        let (before, cost_before) = (self.executed, self.spent_ns);
        let entry = prog.pous.get(pou as usize).map_or(0, |p| p.entry);
        let exit = self.exec::<M, false>(prog, m, entry, u64::MAX, None);
        (self.cr, self.stack, self.parens, self.calls, self.pc) = saved;
        self.now_ns = saved_now;
        ScanOutcome { instructions: self.executed - before, cost_ns: self.spent_ns - cost_before, exit }
    }

    /// The POU attached to `event`, whether interrupts are enabled or not.
    pub fn attached_to(&self, event: u32) -> Option<u32> {
        self.attached.get(event as usize).copied().flatten()
    }

    /// The POU attached to `event`, if interrupts are enabled.
    pub fn handler(&self, event: u32) -> Option<u32> {
        if !self.interrupts_enabled {
            return None;
        }
        self.attached.get(event as usize).copied().flatten()
    }

    fn fault(&mut self, prog: &Program, pc: u32, mut f: Fault) -> Exit {
        f.line = prog.pos.get(pc as usize).map_or(0, |p| p.line);
        f.instruction = prog.text.get(pc as usize).cloned().unwrap_or_default();
        f.at_ns = self.now_ns;
        self.pc = None;
        self.calls.clear();
        Exit::Fault(f)
    }

    /// The interpreter loop; `STEP` compiles in the step limit and breakpoint checks.
    fn exec<M: Machine, const STEP: bool>(
        &mut self,
        prog: &Program,
        m: &mut M,
        start: u32,
        limit: u64,
        brk: Option<&[bool]>,
    ) -> Exit {
        let code = &prog.code[..];
        // Cost and count are kept per straight run of instructions, not per instruction:
        // `run` is where the current run started, and `flush!` adds the run's cost (from
        // the program's prefix sums) and length to the CPU's totals. Every place that
        // reads the totals or leaves the loop flushes first, and every jump starts a new
        // run, so the totals are the same as adding instruction by instruction.
        let prefix = &prog.cost_prefix[..];
        let wd = prog.costs.watchdog_ns;
        let mut pc = start as usize;
        let mut run = pc;
        let mut left = limit;
        let mut first = true;
        // A return with no call open ends the POU the loop started in: the main program or
        // an interrupt routine (which runs with the interrupted calls set aside). Not the
        // depth at entry: a scan resumed inside a subroutine (stepping) returns from it.
        // The current result and the logic stack live in locals while the loop runs (in
        // registers, not written back instruction by instruction); `count!` writes them
        // back with the totals before anything leaves the loop.
        let (mut cr, mut stack) = (self.cr, self.stack);
        // Adds the run so far and writes the CR and stack back (before leaving the loop).
        macro_rules! count {
            () => {
                self.cr = cr;
                self.stack = stack;
                if pc > run {
                    let (a, b) = (run.min(prefix.len() - 1), pc.min(prefix.len() - 1));
                    self.spent_ns += prefix[b] - prefix[a];
                    self.executed += (pc - run) as u64;
                }
            };
        }
        // Adds the run so far and starts a new one here (before reading the totals).
        macro_rules! flush {
            () => {
                count!();
                run = pc;
            };
        }
        // A jump: the run so far is counted, a new one starts at the target.
        macro_rules! goto {
            ($to:expr) => {
                count!();
                pc = $to;
                run = pc;
            };
        }
        macro_rules! fail {
            ($f:expr) => {{
                let f = $f;
                count!();
                return self.fault(prog, (pc - 1) as u32, f);
            }};
        }
        loop {
            if STEP {
                if left == 0 {
                    count!();
                    self.pc = Some(pc as u32);
                    return Exit::Paused(pc as u32);
                }
                if let Some(b) = brk {
                    if !first && b.get(pc).copied().unwrap_or(false) {
                        count!();
                        self.pc = Some(pc as u32);
                        return Exit::Paused(pc as u32);
                    }
                }
                first = false;
                left -= 1;
            }
            let Some(ins) = code.get(pc) else {
                count!();
                return self.fault(prog, pc as u32, Fault::new(FaultKind::Instruction, msg!("engine-ran-off")));
            };
            pc += 1;
            // Only a jump or call can make a scan run long (straight-line code ends), so
            // the watchdog is checked there and at the end of a POU.
            macro_rules! watchdog {
                () => {
                    flush!();
                    if self.spent_ns - self.wdt_mark_ns > wd {
                        return self.fault(prog, (pc - 1) as u32, watchdog_fault(wd));
                    }
                };
            }
            match ins {
                Ins::Ld { loc, neg } => {
                    stack = (stack << 1) | cr as u32;
                    cr = m.get_bit(*loc) ^ neg;
                }
                Ins::Logic { op, loc, neg } => {
                    let v = m.get_bit(*loc) ^ neg;
                    cr = logic(lcode(*op), cr, v);
                }
                Ins::St { loc, neg } => m.set_bit(*loc, cr ^ neg),
                Ins::Not => cr = !cr,
                Ins::ParOpen { op, neg, load } => {
                    if self.parens.len() >= MAX_PARENS {
                        let f = Fault::new(FaultKind::Instruction, msg!("engine-parens-too-deep", max = MAX_PARENS));
                        fail!(f);
                    }
                    self.parens.push((lcode(*op), *neg, cr));
                    if let Some(l) = load {
                        cr = m.get_bit(*l);
                    }
                }
                Ins::ParClose => {
                    if let Some((op, neg, saved)) = self.parens.pop() {
                        cr = logic(op, saved, cr ^ neg);
                    }
                }
                Ins::Set { loc, n, on } => {
                    if cr {
                        for k in 0..*n {
                            m.set(loc.nth(k), *on as u32);
                        }
                    }
                }
                Ins::ResetElem { timer, slot, cv, q } => {
                    if cr {
                        m.set(*cv, 0);
                        m.set(*q, 0);
                        if *timer {
                            self.timers[*slot as usize] = TimerState::default();
                        } else {
                            self.counters[*slot as usize] = CounterState::default();
                        }
                    }
                }
                Ins::Ald => {
                    cr &= stack & 1 != 0;
                    stack >>= 1;
                }
                Ins::Old => {
                    cr |= stack & 1 != 0;
                    stack >>= 1;
                }
                Ins::Lps => stack = (stack << 1) | cr as u32,
                Ins::Lrd => cr = stack & 1 != 0,
                Ins::Lpp => {
                    cr = stack & 1 != 0;
                    stack >>= 1;
                }
                Ins::Edge { slot, rising } => {
                    let e = &mut self.edges[*slot as usize];
                    let prev = *e;
                    *e = cr;
                    cr = if *rising { cr && !prev } else { !cr && prev };
                }
                Ins::Compare { comb, op, ty, a, b } => {
                    let (x, y) = match (val(m, a, *ty), val(m, b, *ty)) {
                        (Some(x), Some(y)) => (x, y),
                        _ => fail!(bad(m, &[a, b], *ty)),
                    };
                    let r = compare(*ty, *op, x, y);
                    match comb {
                        Comb::Ld => {
                            stack = (stack << 1) | cr as u32;
                            cr = r;
                        }
                        Comb::And => cr &= r,
                        Comb::Or => cr |= r,
                    }
                }
                Ins::Move { ty, a, out } => {
                    if cr {
                        let ok = match val(m, a, *ty) {
                            Some(v) => put(m, out, *ty, v),
                            None => false,
                        };
                        if !ok {
                            fail!(bad(m, &[a, out], *ty));
                        }
                    }
                }
                Ins::Block { ty, a, out, n, fill } => {
                    if cr {
                        if let Err(f) = self.block(prog, m, *ty, a, out, n, *fill, pc - 1) {
                            fail!(f);
                        }
                    }
                }
                Ins::Arith { op, ty, a, b, out } => {
                    if cr {
                        if let Some(eno) = arith_int(m, *op, *ty, a, b, out) {
                            cr = eno;
                            continue;
                        }
                        match arith(m, *op, *ty, a, b, out) {
                            Ok(eno) => {
                                cr = eno;
                                if !eno && matches!(op, Arith::Div | Arith::Mod) && is_zero(m, b, *ty) {
                                    let what = msg!("engine-division-by-zero");
                                    self.normal_error(prog, (pc - 1) as u32, FaultKind::DivZero, &what);
                                }
                            }
                            Err(f) => fail!(f),
                        }
                    }
                }
                Ins::IncDec { inc, ty, out } => {
                    if cr {
                        let one = if *ty == DataType::Real { 1f32.to_bits() } else { 1 };
                        let op = if *inc { Arith::Add } else { Arith::Sub };
                        if let Some(eno) = arith_int(m, op, *ty, out, &Opd::Imm(one), out) {
                            cr = eno;
                            continue;
                        }
                        match arith(m, op, *ty, out, &Opd::Imm(one), out) {
                            Ok(eno) => cr = eno,
                            Err(f) => fail!(f),
                        }
                    }
                }
                Ins::Shift { op, ty, out, n } => {
                    if cr {
                        if let Err(f) = shift_out(m, *op, *ty, out, n) {
                            fail!(f);
                        }
                    }
                }
                Ins::WordLogic { op, ty, a, b, out } => {
                    if cr {
                        if let Err(f) = word_logic(m, *op, *ty, a, b, out) {
                            fail!(f);
                        }
                    }
                }
                Ins::Inv { ty, out } => {
                    if cr {
                        if let Err(f) = invert(m, *ty, out) {
                            fail!(f);
                        }
                    }
                }
                Ins::Unary { op, ty, a, out } => {
                    if cr {
                        match unary(m, *op, *ty, a, out) {
                            Ok(eno) => cr = eno,
                            Err(f) => fail!(f),
                        }
                    }
                }
                Ins::Swap { out } => {
                    if cr {
                        if let Err(f) = swap(m, out) {
                            fail!(f);
                        }
                    }
                }
                Ins::For { ty, indx, init, fin, end } => {
                    if !cr {
                        goto!(*end as usize);
                    } else {
                        let r = read(m, init, *ty).and_then(|i| {
                            let f = read(m, fin, *ty)?;
                            write(m, indx, *ty, i)?;
                            Ok(as_i64(*ty, i) > as_i64(*ty, f))
                        });
                        match r {
                            Ok(true) => {
                                goto!(*end as usize);
                            }
                            Ok(false) => {}
                            Err(f) => fail!(f),
                        }
                    }
                }
                Ins::Next { start } => {
                    if let Some(Ins::For { ty, indx, fin, .. }) = code.get(*start as usize) {
                        let r = read(m, indx, *ty).and_then(|i| {
                            let (i, f) = (as_i64(*ty, i), as_i64(*ty, read(m, fin, *ty)?));
                            // INDX + 1; at the type's maximum the loop ends without wrapping.
                            if fits(*ty, i + 1) {
                                write(m, indx, *ty, mask(*ty, i + 1))?;
                            }
                            Ok(i < f)
                        });
                        match r {
                            Ok(true) => {
                                watchdog!();
                                goto!(*start as usize + 1);
                                // The body runs with the FOR's enable on (S7-200).
                                cr = true;
                            }
                            Ok(false) => {}
                            Err(f) => fail!(f),
                        }
                    }
                }
                Ins::Conv { c, a, out } => {
                    if cr {
                        match convert(m, *c, a, out) {
                            Ok(eno) => cr = eno,
                            Err(f) => fail!(f),
                        }
                    }
                }
                Ins::Jmp { to } => {
                    watchdog!();
                    goto!(*to as usize);
                }
                Ins::Jmpc { to, neg } => {
                    watchdog!();
                    if cr ^ neg {
                        goto!(*to as usize);
                    }
                }
                Ins::Cal { pou, cond } => {
                    watchdog!();
                    if cond.is_none_or(|c| cr == c) {
                        if self.calls.len() >= MAX_CALL_DEPTH {
                            let f =
                                Fault::new(FaultKind::CallDepth, msg!("engine-calls-too-deep", max = MAX_CALL_DEPTH));
                            fail!(f);
                        }
                        self.calls.push(pc as u32);
                        goto!(prog.pous[*pou as usize].entry as usize);
                    }
                }
                Ins::Ret { cond } => {
                    watchdog!();
                    if cond.is_none_or(|c| cr == c) {
                        if self.calls.is_empty() {
                            self.pc = None;
                            return Exit::Done;
                        }
                        let back = self.calls.pop().unwrap_or(0) as usize;
                        goto!(back);
                    }
                }
                Ins::End => {
                    watchdog!();
                    if self.calls.is_empty() {
                        self.pc = None;
                        return Exit::Done;
                    }
                    let back = self.calls.pop().unwrap_or(0) as usize;
                    goto!(back);
                }
                Ins::Timer { kind, slot, el, pt, reset } => {
                    let pt = match read(m, pt, DataType::Int) {
                        Ok(v) => v as u16 as i16 as i32,
                        Err(f) => fail!(f),
                    };
                    let rs = reset.is_some_and(|r| m.get(r) & 1 != 0);
                    let cv = m.get(el.cv) as u16 as i16 as i32;
                    let st = &mut self.timers[*slot as usize];
                    let (cv, q) = timers::timer(*kind, st, cr, cv, pt, rs, self.now_ns, el.base_ns);
                    m.set(el.cv, cv as u16 as u32);
                    m.set(el.q, q as u32);
                    cr = q;
                }
                Ins::Counter { kind, slot, el, pv, second, reset } => {
                    let pv = match read(m, pv, DataType::Int) {
                        Ok(v) => v as u16 as i16 as i32,
                        Err(f) => fail!(f),
                    };
                    let rs = reset.is_some_and(|r| m.get(r) & 1 != 0);
                    let down = second.is_some_and(|r| m.get(r) & 1 != 0);
                    let cv = m.get(el.cv) as u16 as i16 as i32;
                    let st = &mut self.counters[*slot as usize];
                    let (cv, q) = timers::counter(*kind, st, cr, down, cv, pv, rs);
                    m.set(el.cv, cv as u16 as u32);
                    m.set(el.q, q as u32);
                    cr = q;
                }
                Ins::Atch { pou, event } => {
                    if cr {
                        let ev = read(m, event, DataType::Int).unwrap_or(0) as u16 as usize;
                        if self.attached.len() <= ev {
                            self.attached.resize(ev + 1, None);
                        }
                        self.attached[ev] = Some(*pou);
                    }
                }
                Ins::Dtch { event } => {
                    if cr {
                        let ev = read(m, event, DataType::Int).unwrap_or(0) as u16 as usize;
                        if let Some(a) = self.attached.get_mut(ev) {
                            *a = None;
                        }
                    }
                }
                Ins::Eni => {
                    if cr {
                        self.interrupts_enabled = true;
                    }
                }
                Ins::Disi => {
                    if cr {
                        self.interrupts_enabled = false;
                    }
                }
                Ins::Wdt => {
                    if cr {
                        flush!();
                        self.wdt_mark_ns = self.spent_ns;
                    }
                }
                Ins::Nop => {}
                Ins::Special { id, inst, edge, args, types } => {
                    let en = cr;
                    let run = if *edge {
                        let p = &mut self.special_en[*inst as usize];
                        let r = en && !*p;
                        *p = en;
                        r
                    } else {
                        en
                    };
                    let done = if run {
                        Some(m.special(*id, *inst, args, types))
                    } else if !en {
                        Some(m.special_off(*id, *inst, args, types))
                    } else {
                        None
                    };
                    match done {
                        Some(Ok(eno)) => cr = eno,
                        Some(Err(f)) => fail!(f),
                        None => {}
                    }
                }
            }
        }
    }
}

/// The watchdog fault: the scan's program time passed the limit.
#[cold]
fn watchdog_fault(wd: u64) -> Fault {
    Fault::new(FaultKind::Watchdog, msg!("engine-watchdog", ms = (wd as f64 / 1e6).to_string()))
}
