//! The interpreter: one [`Cpu`] (current result, logic stack, edge memories, timer and
//! counter state, call stack, interrupt attachments) executing a compiled [`Program`]
//! against a [`Machine`]. A scan runs the main program from the top; the time it costs is
//! the sum of the cost table over the instructions executed, checked against the watchdog
//! as it goes. Execution can stop at breakpoints or after N instructions and resume later
//! (the debugger), so the program counter and call stack are part of the state.
//!
//! All state types are plain data (serde) so a snapshot can store a running CPU.

use super::compile::{Ins, Program};
use super::isa::{Arith, Cmp, Comb, Conv, Logic, Shift, Unary};
use super::timers::{self, CounterState, TimerState};
use super::{read, write, Flags, Machine, Opd};
use crate::core::DataType;
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
    pub fn name(self) -> &'static str {
        match self {
            FaultKind::Watchdog => "watchdog",
            FaultKind::BadAddress => "bad indirect address",
            FaultKind::CallDepth => "call depth",
            FaultKind::Instruction => "instruction",
            FaultKind::DivZero => "division by zero",
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
        write!(f, "fault {} ({}): {}", self.kind.code(), self.kind.name(), self.message)?;
        if self.line > 0 {
            write!(f, " at line {} `{}`", self.line, self.instruction)?;
        }
        Ok(())
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

fn logic(op: u8, a: bool, b: bool) -> bool {
    match op {
        0 => a & b,
        1 => a | b,
        _ => a ^ b,
    }
}

fn lcode(l: Logic) -> u8 {
    match l {
        Logic::And => 0,
        Logic::Or => 1,
        Logic::Xor => 2,
    }
}

/// Sign-extends or interprets a raw pattern of type `ty` as i64.
#[inline]
fn as_i64(ty: DataType, raw: u32) -> i64 {
    match ty {
        DataType::Bool => (raw & 1) as i64,
        DataType::Byte => (raw & 0xFF) as i64,
        DataType::SInt => raw as u8 as i8 as i64,
        DataType::Word => (raw & 0xFFFF) as i64,
        DataType::Int => raw as u16 as i16 as i64,
        DataType::DWord => raw as i64,
        DataType::DInt => raw as i32 as i64,
        DataType::Real => f32::from_bits(raw) as i64,
    }
}

fn fits(ty: DataType, v: i64) -> bool {
    let (lo, hi) = ty.int_range();
    v >= lo && v <= hi
}

fn mask(ty: DataType, v: i64) -> u32 {
    match ty.bits() {
        8 => v as u32 & 0xFF,
        16 => v as u32 & 0xFFFF,
        _ => v as u32,
    }
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
        let cost = &prog.cost[..];
        let wd = prog.costs.watchdog_ns;
        let mut pc = start as usize;
        let mut left = limit;
        let mut first = true;
        let base_depth = self.calls.len();
        loop {
            if STEP {
                if left == 0 {
                    self.pc = Some(pc as u32);
                    return Exit::Paused(pc as u32);
                }
                if let Some(b) = brk {
                    if !first && b.get(pc).copied().unwrap_or(false) {
                        self.pc = Some(pc as u32);
                        return Exit::Paused(pc as u32);
                    }
                }
                first = false;
                left -= 1;
            }
            let Some(ins) = code.get(pc) else {
                return self.fault(prog, pc as u32, Fault::new(FaultKind::Instruction, "ran off the program"));
            };
            self.spent_ns += cost.get(pc).copied().unwrap_or(0) as u64;
            self.executed += 1;
            pc += 1;
            // Only a jump or call can make a scan run long (straight-line code ends), so
            // the watchdog is checked there and at the end of a POU.
            macro_rules! watchdog {
                () => {
                    if self.spent_ns - self.wdt_mark_ns > wd {
                        return self.fault(prog, (pc - 1) as u32, watchdog_fault(wd));
                    }
                };
            }
            match ins {
                Ins::Ld { loc, neg } => {
                    self.stack = (self.stack << 1) | self.cr as u32;
                    self.cr = (m.get(*loc) & 1 != 0) ^ neg;
                }
                Ins::Logic { op, loc, neg } => {
                    let v = (m.get(*loc) & 1 != 0) ^ neg;
                    self.cr = logic(lcode(*op), self.cr, v);
                }
                Ins::St { loc, neg } => m.set(*loc, (self.cr ^ neg) as u32),
                Ins::Not => self.cr = !self.cr,
                Ins::ParOpen { op, neg, load } => {
                    if self.parens.len() >= MAX_PARENS {
                        let f = Fault::new(FaultKind::Instruction, "parentheses nested deeper than 8");
                        return self.fault(prog, (pc - 1) as u32, f);
                    }
                    self.parens.push((lcode(*op), *neg, self.cr));
                    if let Some(l) = load {
                        self.cr = m.get(*l) & 1 != 0;
                    }
                }
                Ins::ParClose => {
                    if let Some((op, neg, saved)) = self.parens.pop() {
                        self.cr = logic(op, saved, self.cr ^ neg);
                    }
                }
                Ins::Set { loc, n, on } => {
                    if self.cr {
                        for k in 0..*n {
                            m.set(loc.nth(k), *on as u32);
                        }
                    }
                }
                Ins::ResetElem { timer, slot, cv, q } => {
                    if self.cr {
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
                    self.cr &= self.stack & 1 != 0;
                    self.stack >>= 1;
                }
                Ins::Old => {
                    self.cr |= self.stack & 1 != 0;
                    self.stack >>= 1;
                }
                Ins::Lps => self.stack = (self.stack << 1) | self.cr as u32,
                Ins::Lrd => self.cr = self.stack & 1 != 0,
                Ins::Lpp => {
                    self.cr = self.stack & 1 != 0;
                    self.stack >>= 1;
                }
                Ins::Edge { slot, rising } => {
                    let e = &mut self.edges[*slot as usize];
                    let prev = *e;
                    *e = self.cr;
                    self.cr = if *rising { self.cr && !prev } else { !self.cr && prev };
                }
                Ins::Compare { comb, op, ty, a, b } => {
                    let (x, y) = match (val(m, a, *ty), val(m, b, *ty)) {
                        (Some(x), Some(y)) => (x, y),
                        _ => return self.fault(prog, (pc - 1) as u32, bad(m, &[a, b], *ty)),
                    };
                    let r = compare(*ty, *op, x, y);
                    match comb {
                        Comb::Ld => {
                            self.stack = (self.stack << 1) | self.cr as u32;
                            self.cr = r;
                        }
                        Comb::And => self.cr &= r,
                        Comb::Or => self.cr |= r,
                    }
                }
                Ins::Move { ty, a, out } => {
                    if self.cr {
                        let ok = match val(m, a, *ty) {
                            Some(v) => put(m, out, *ty, v),
                            None => false,
                        };
                        if !ok {
                            return self.fault(prog, (pc - 1) as u32, bad(m, &[a, out], *ty));
                        }
                    }
                }
                Ins::Block { ty, a, out, n, fill } => {
                    if self.cr {
                        if let Err(f) = self.block(prog, m, *ty, a, out, n, *fill, pc - 1) {
                            return self.fault(prog, (pc - 1) as u32, f);
                        }
                    }
                }
                Ins::Arith { op, ty, a, b, out } => {
                    if self.cr {
                        match arith(m, *op, *ty, a, b, out) {
                            Ok(eno) => {
                                self.cr = eno;
                                if !eno && matches!(op, Arith::Div | Arith::Mod) && is_zero(m, b, *ty) {
                                    self.normal_error(prog, (pc - 1) as u32, FaultKind::DivZero, "division by zero");
                                }
                            }
                            Err(f) => return self.fault(prog, (pc - 1) as u32, f),
                        }
                    }
                }
                Ins::IncDec { inc, ty, out } => {
                    if self.cr {
                        let one = if *ty == DataType::Real { 1f32.to_bits() } else { 1 };
                        let op = if *inc { Arith::Add } else { Arith::Sub };
                        match arith(m, op, *ty, out, &Opd::Imm(one), out) {
                            Ok(eno) => self.cr = eno,
                            Err(f) => return self.fault(prog, (pc - 1) as u32, f),
                        }
                    }
                }
                Ins::Shift { op, ty, out, n } => {
                    if self.cr {
                        let r = read(m, out, *ty).and_then(|v| {
                            let k = read(m, n, DataType::Byte)?;
                            let v = shift(*op, ty.bits(), v, k);
                            m.flags(Flags { zero: v == 0, ..Flags::default() });
                            write(m, out, *ty, v)
                        });
                        if let Err(f) = r {
                            return self.fault(prog, (pc - 1) as u32, f);
                        }
                    }
                }
                Ins::WordLogic { op, ty, a, b, out } => {
                    if self.cr {
                        let r = read(m, a, *ty).and_then(|x| {
                            let y = read(m, b, *ty)?;
                            let v = mask(
                                *ty,
                                match op {
                                    Logic::And => x & y,
                                    Logic::Or => x | y,
                                    Logic::Xor => x ^ y,
                                } as i64,
                            );
                            m.flags(Flags { zero: v == 0, ..Flags::default() });
                            write(m, out, *ty, v)
                        });
                        if let Err(f) = r {
                            return self.fault(prog, (pc - 1) as u32, f);
                        }
                    }
                }
                Ins::Inv { ty, out } => {
                    if self.cr {
                        let r = read(m, out, *ty).and_then(|x| write(m, out, *ty, mask(*ty, !x as i64)));
                        if let Err(f) = r {
                            return self.fault(prog, (pc - 1) as u32, f);
                        }
                    }
                }
                Ins::Unary { op, ty, a, out } => {
                    if self.cr {
                        match unary(m, *op, *ty, a, out) {
                            Ok(eno) => self.cr = eno,
                            Err(f) => return self.fault(prog, (pc - 1) as u32, f),
                        }
                    }
                }
                Ins::Swap { out } => {
                    if self.cr {
                        let r = read(m, out, DataType::Word)
                            .and_then(|x| write(m, out, DataType::Word, (x as u16).swap_bytes() as u32));
                        if let Err(f) = r {
                            return self.fault(prog, (pc - 1) as u32, f);
                        }
                    }
                }
                Ins::For { ty, indx, init, fin, end } => {
                    if !self.cr {
                        pc = *end as usize;
                    } else {
                        let r = read(m, init, *ty).and_then(|i| {
                            let f = read(m, fin, *ty)?;
                            write(m, indx, *ty, i)?;
                            Ok(as_i64(*ty, i) > as_i64(*ty, f))
                        });
                        match r {
                            Ok(true) => pc = *end as usize,
                            Ok(false) => {}
                            Err(f) => return self.fault(prog, (pc - 1) as u32, f),
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
                                pc = *start as usize + 1;
                                // The body runs with the FOR's enable on (S7-200).
                                self.cr = true;
                            }
                            Ok(false) => {}
                            Err(f) => return self.fault(prog, (pc - 1) as u32, f),
                        }
                    }
                }
                Ins::Conv { c, a, out } => {
                    if self.cr {
                        match convert(m, *c, a, out) {
                            Ok(eno) => self.cr = eno,
                            Err(f) => return self.fault(prog, (pc - 1) as u32, f),
                        }
                    }
                }
                Ins::Jmp { to } => {
                    watchdog!();
                    pc = *to as usize
                }
                Ins::Jmpc { to, neg } => {
                    watchdog!();
                    if self.cr ^ neg {
                        pc = *to as usize;
                    }
                }
                Ins::Cal { pou, cond } => {
                    watchdog!();
                    if cond.is_none_or(|c| self.cr == c) {
                        if self.calls.len() >= MAX_CALL_DEPTH {
                            let f = Fault::new(
                                FaultKind::CallDepth,
                                format!("subroutines nested deeper than {MAX_CALL_DEPTH}"),
                            );
                            return self.fault(prog, (pc - 1) as u32, f);
                        }
                        self.calls.push(pc as u32);
                        pc = prog.pous[*pou as usize].entry as usize;
                    }
                }
                Ins::Ret { cond } => {
                    watchdog!();
                    if cond.is_none_or(|c| self.cr == c) {
                        if self.calls.len() <= base_depth {
                            self.pc = None;
                            return Exit::Done;
                        }
                        pc = self.calls.pop().unwrap_or(0) as usize;
                    }
                }
                Ins::End => {
                    watchdog!();
                    if self.calls.len() <= base_depth {
                        self.pc = None;
                        return Exit::Done;
                    }
                    pc = self.calls.pop().unwrap_or(0) as usize;
                }
                Ins::Timer { kind, slot, el, pt, reset } => {
                    let pt = match read(m, pt, DataType::Int) {
                        Ok(v) => v as u16 as i16 as i32,
                        Err(f) => return self.fault(prog, (pc - 1) as u32, f),
                    };
                    let rs = reset.is_some_and(|r| m.get(r) & 1 != 0);
                    let cv = m.get(el.cv) as u16 as i16 as i32;
                    let st = &mut self.timers[*slot as usize];
                    let (cv, q) = timers::timer(*kind, st, self.cr, cv, pt, rs, self.now_ns, el.base_ns);
                    m.set(el.cv, cv as u16 as u32);
                    m.set(el.q, q as u32);
                    self.cr = q;
                }
                Ins::Counter { kind, slot, el, pv, second, reset } => {
                    let pv = match read(m, pv, DataType::Int) {
                        Ok(v) => v as u16 as i16 as i32,
                        Err(f) => return self.fault(prog, (pc - 1) as u32, f),
                    };
                    let rs = reset.is_some_and(|r| m.get(r) & 1 != 0);
                    let down = second.is_some_and(|r| m.get(r) & 1 != 0);
                    let cv = m.get(el.cv) as u16 as i16 as i32;
                    let st = &mut self.counters[*slot as usize];
                    let (cv, q) = timers::counter(*kind, st, self.cr, down, cv, pv, rs);
                    m.set(el.cv, cv as u16 as u32);
                    m.set(el.q, q as u32);
                    self.cr = q;
                }
                Ins::Atch { pou, event } => {
                    if self.cr {
                        let ev = read(m, event, DataType::Int).unwrap_or(0) as u16 as usize;
                        if self.attached.len() <= ev {
                            self.attached.resize(ev + 1, None);
                        }
                        self.attached[ev] = Some(*pou);
                    }
                }
                Ins::Dtch { event } => {
                    if self.cr {
                        let ev = read(m, event, DataType::Int).unwrap_or(0) as u16 as usize;
                        if let Some(a) = self.attached.get_mut(ev) {
                            *a = None;
                        }
                    }
                }
                Ins::Eni => {
                    if self.cr {
                        self.interrupts_enabled = true;
                    }
                }
                Ins::Disi => {
                    if self.cr {
                        self.interrupts_enabled = false;
                    }
                }
                Ins::Wdt => {
                    if self.cr {
                        self.wdt_mark_ns = self.spent_ns;
                    }
                }
                Ins::Nop => {}
                Ins::Special { id, inst, edge, args, types } => {
                    let en = self.cr;
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
                        Some(Ok(eno)) => self.cr = eno,
                        Some(Err(f)) => return self.fault(prog, (pc - 1) as u32, f),
                        None => {}
                    }
                }
            }
        }
    }

    #[allow(clippy::too_many_arguments)]
    fn block<M: Machine>(
        &mut self,
        prog: &Program,
        m: &mut M,
        ty: DataType,
        a: &Opd,
        out: &Opd,
        n: &Opd,
        fill: bool,
        _pc: usize,
    ) -> Result<(), Fault> {
        let n = read(m, n, DataType::Int)? as u16 as i16;
        if !(1..=255).contains(&n) {
            return Err(Fault::new(FaultKind::Instruction, format!("block length {n} is not 1…255")));
        }
        self.spent_ns += prog.costs.per_element_ns as u64 * n as u64;
        let w = super::width_of(ty);
        let src = super::loc_of(m, a, ty)?;
        let dst = super::loc_of(m, out, ty)?.ok_or_else(|| Fault::new(FaultKind::BadAddress, "no destination"))?;
        let _ = w;
        // Read all first: overlapping blocks copy as if through a buffer.
        let vals: Vec<u32> = match (fill, src) {
            (true, _) | (false, None) => vec![read(m, a, ty)?; n as usize],
            (false, Some(s)) => (0..n as u32).map(|k| m.get(s.nth(k))).collect(),
        };
        for (k, v) in vals.into_iter().enumerate() {
            m.set(dst.nth(k as u32), v);
        }
        Ok(())
    }
}

fn compare(ty: DataType, op: Cmp, x: u32, y: u32) -> bool {
    use std::cmp::Ordering;
    let ord = if ty == DataType::Real {
        match f32::from_bits(x).partial_cmp(&f32::from_bits(y)) {
            Some(o) => o,
            None => return op == Cmp::Ne,
        }
    } else {
        as_i64(ty, x).cmp(&as_i64(ty, y))
    };
    match op {
        Cmp::Eq => ord == Ordering::Equal,
        Cmp::Ne => ord != Ordering::Equal,
        Cmp::Lt => ord == Ordering::Less,
        Cmp::Gt => ord == Ordering::Greater,
        Cmp::Le => ord != Ordering::Greater,
        Cmp::Ge => ord != Ordering::Less,
    }
}

/// Arithmetic with S7-200 status: result wraps to the type's width, overflow is flagged;
/// division by zero leaves the output unchanged and returns ENO = 0 (SM1.3 on the K2).
#[cold]
fn watchdog_fault(wd: u64) -> Fault {
    Fault::new(
        FaultKind::Watchdog,
        format!("the scan ran past the watchdog limit of {} ms (an endless loop?)", wd as f64 / 1e6),
    )
}

/// An operand's raw value without building a fault (the hot path); `None` only for a
/// pointer outside memory.
#[inline(always)]
fn val<M: Machine>(m: &M, o: &Opd, ty: DataType) -> Option<u32> {
    match *o {
        Opd::Imm(v) => Some(v),
        Opd::Loc(l) => Some(m.get(l)),
        Opd::Ind(p) => m.deref(m.get(p), super::width_of(ty)).map(|l| m.get(l)),
    }
}

/// Writes an operand; `false` for a pointer outside memory.
#[inline(always)]
fn put<M: Machine>(m: &mut M, o: &Opd, ty: DataType, v: u32) -> bool {
    match *o {
        Opd::Imm(_) => true,
        Opd::Loc(l) => {
            m.set(l, v);
            true
        }
        Opd::Ind(p) => match m.deref(m.get(p), super::width_of(ty)) {
            Some(l) => {
                m.set(l, v);
                true
            }
            None => false,
        },
    }
}

/// The fault for the first of `ops` whose pointer is bad (cold path).
#[cold]
fn bad<M: Machine>(m: &M, ops: &[&Opd], ty: DataType) -> Fault {
    ops.iter()
        .find_map(|o| read(m, o, ty).err())
        .unwrap_or_else(|| Fault::new(FaultKind::BadAddress, "bad indirect address"))
}

/// SQRT and ABS: OUT := f(IN); ENO = 0 when the result is not a number or does not fit
/// (S7-200 status bits: SM1.1 overflow / illegal value, SM1.0 zero, SM1.2 negative).
fn unary<M: Machine>(m: &mut M, op: Unary, ty: DataType, a: &Opd, out: &Opd) -> Result<bool, Fault> {
    let Some(x) = val(m, a, ty) else {
        return Err(bad(m, &[a], ty));
    };
    if ty == DataType::Real {
        let x = f32::from_bits(x);
        if op == Unary::Sqrt && (x.is_nan() || x < 0.0) {
            m.flags(Flags { overflow: true, ..Flags::default() });
            return Ok(false);
        }
        let r = match op {
            Unary::Sqrt => x.sqrt(),
            Unary::Abs => x.abs(),
        };
        m.flags(Flags { zero: r == 0.0, overflow: !r.is_finite(), negative: false, div_zero: false });
        write(m, out, ty, r.to_bits())?;
        return Ok(r.is_finite());
    }
    let r = as_i64(ty, x).abs();
    let overflow = !fits(ty, r);
    let raw = mask(ty, r);
    m.flags(Flags { zero: raw == 0, overflow, negative: as_i64(ty, raw) < 0, div_zero: false });
    if !put(m, out, ty, raw) {
        return Err(bad(m, &[out], ty));
    }
    Ok(!overflow)
}

/// Whether a divisor reads as zero (cold: after a failed division only).
#[cold]
fn is_zero<M: Machine>(m: &M, b: &Opd, ty: DataType) -> bool {
    match val(m, b, ty) {
        Some(v) if ty == DataType::Real => f32::from_bits(v) == 0.0,
        Some(v) => as_i64(ty, v) == 0,
        None => false,
    }
}

fn arith<M: Machine>(m: &mut M, op: Arith, ty: DataType, a: &Opd, b: &Opd, out: &Opd) -> Result<bool, Fault> {
    let (Some(x), Some(y)) = (val(m, a, ty), val(m, b, ty)) else {
        return Err(bad(m, &[a, b], ty));
    };
    if ty == DataType::Real {
        let (x, y) = (f32::from_bits(x), f32::from_bits(y));
        if matches!(op, Arith::Div | Arith::Mod) && y == 0.0 {
            m.flags(Flags { div_zero: true, ..Flags::default() });
            return Ok(false);
        }
        let r = match op {
            Arith::Add => x + y,
            Arith::Sub => x - y,
            Arith::Mul => x * y,
            Arith::Div => x / y,
            Arith::Mod => x % y,
        };
        m.flags(Flags { zero: r == 0.0, overflow: !r.is_finite(), negative: r < 0.0, div_zero: false });
        write(m, out, ty, r.to_bits())?;
        return Ok(r.is_finite());
    }
    let (x, y) = (as_i64(ty, x), as_i64(ty, y));
    if matches!(op, Arith::Div | Arith::Mod) && y == 0 {
        m.flags(Flags { div_zero: true, ..Flags::default() });
        return Ok(false);
    }
    let r = match op {
        Arith::Add => x + y,
        Arith::Sub => x - y,
        Arith::Mul => x.wrapping_mul(y),
        Arith::Div => x / y,
        Arith::Mod => x % y,
    };
    let overflow = !fits(ty, r);
    let raw = mask(ty, r);
    let shown = as_i64(ty, raw);
    m.flags(Flags { zero: raw == 0, overflow, negative: shown < 0, div_zero: false });
    if !put(m, out, ty, raw) {
        return Err(bad(m, &[out], ty));
    }
    Ok(!overflow)
}

fn shift(op: Shift, bits: u32, v: u32, k: u32) -> u32 {
    let mask = if bits == 32 { u32::MAX } else { (1u32 << bits) - 1 };
    let v = v & mask;
    match op {
        Shift::Shl => {
            if k >= bits {
                0
            } else {
                (v << k) & mask
            }
        }
        Shift::Shr => {
            if k >= bits {
                0
            } else {
                v >> k
            }
        }
        Shift::Rol => {
            let k = k % bits;
            if k == 0 {
                v
            } else {
                ((v << k) | (v >> (bits - k))) & mask
            }
        }
        Shift::Ror => {
            let k = k % bits;
            if k == 0 {
                v
            } else {
                ((v >> k) | (v << (bits - k))) & mask
            }
        }
    }
}

fn convert<M: Machine>(m: &mut M, c: Conv, a: &Opd, out: &Opd) -> Result<bool, Fault> {
    use DataType as T;
    let r: Option<(DataType, u32)> = match c {
        Conv::IDi => Some((T::DInt, as_i64(T::Int, read(m, a, T::Int)?) as i32 as u32)),
        Conv::DiI => {
            let v = as_i64(T::DInt, read(m, a, T::DInt)?);
            fits(T::Int, v).then_some((T::Int, v as u16 as u32))
        }
        Conv::BI => Some((T::Int, read(m, a, T::Byte)? & 0xFF)),
        Conv::IB => {
            let v = as_i64(T::Int, read(m, a, T::Int)?);
            (0..=255).contains(&v).then_some((T::Byte, v as u32))
        }
        Conv::DiR => Some((T::Real, (as_i64(T::DInt, read(m, a, T::DInt)?) as f32).to_bits())),
        Conv::Round | Conv::Trunc => {
            let f = f32::from_bits(read(m, a, T::Real)?) as f64;
            let v = if c == Conv::Round { f.round() } else { f.trunc() };
            (v.is_finite() && v >= i32::MIN as f64 && v <= i32::MAX as f64).then_some((T::DInt, v as i32 as u32))
        }
        Conv::IBcd => {
            let v = as_i64(T::Int, read(m, a, T::Int)?);
            (0..=9999).contains(&v).then(|| {
                let d = |k: i64| ((v / 10i64.pow(k as u32)) % 10) as u32;
                (T::Int, d(0) | d(1) << 4 | d(2) << 8 | d(3) << 12)
            })
        }
        Conv::BcdI => {
            let v = read(m, a, T::Int)? & 0xFFFF;
            let digits = [v & 0xF, v >> 4 & 0xF, v >> 8 & 0xF, v >> 12 & 0xF];
            digits
                .iter()
                .all(|d| *d <= 9)
                .then(|| (T::Int, digits[0] + digits[1] * 10 + digits[2] * 100 + digits[3] * 1000))
        }
    };
    match r {
        Some((ty, v)) => {
            write(m, out, ty, v)?;
            Ok(true)
        }
        None => Ok(false),
    }
}
