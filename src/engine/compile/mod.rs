//! Statements → a compiled [`Program`]: mnemonics looked up in [`super::isa`] or the
//! family's table, operands resolved through [`Family`], types checked, labels and calls
//! bound to instruction indices. Every refusal is a load error naming `file:line:column`
//! and, where one is close, the instruction or label meant — nothing unknown survives to
//! run time.
//!
//! This file holds the compiled program's shape ([`Ins`], [`Program`]), the walk over the
//! file's POUs, networks, labels and calls, and the dispatch of each mnemonic. Operands are
//! resolved and typed in `operands`; each instruction group is compiled in its own file:
//! bit logic and comparisons (`logic`), moves (`moves`), arithmetic, word logic and
//! conversions (`arith`), program flow and interrupts (`flow`), timers and counters
//! (`elements`).

mod arith;
mod elements;
mod flow;
mod logic;
mod moves;
mod operands;

use super::isa::{
    self, Arith, Cmp, Comb, Conv, CostClass, CounterKind, Def, Kind, Logic, Shift, TimerKind, TyHint, Unary,
};
use super::source::{self, OperandText, Pos, PouKind, Stmt};
use super::{ArgKind, CostTable, Element, Family, Loc, Opd, SpecialDef};
use crate::core::msg::Msg;
use crate::core::text::edit_distance;
use crate::core::{DataType, Error, ErrorKind, Result};
use crate::msg;
use operands::Raw;
use std::collections::HashMap;

/// FOR loops nest at most this deep (S7-200 System Manual, For-Next Loop: eight levels).
pub const MAX_FOR_NESTING: usize = 8;

/// One compiled instruction: resolved locations, no names.
#[derive(Clone, Debug, PartialEq)]
pub enum Ins {
    Ld {
        loc: Loc,
        neg: bool,
    },
    Logic {
        op: Logic,
        loc: Loc,
        neg: bool,
    },
    ParOpen {
        op: Logic,
        neg: bool,
        load: Option<Loc>,
    },
    ParClose,
    Not,
    St {
        loc: Loc,
        neg: bool,
    },
    Set {
        loc: Loc,
        n: u32,
        on: bool,
    },
    ResetElem {
        timer: bool,
        slot: u32,
        cv: Loc,
        q: Loc,
    },
    Ald,
    Old,
    Lps,
    Lrd,
    Lpp,
    Edge {
        slot: u32,
        rising: bool,
    },
    Compare {
        comb: Comb,
        op: Cmp,
        ty: DataType,
        a: Opd,
        b: Opd,
    },
    Move {
        ty: DataType,
        a: Opd,
        out: Opd,
    },
    Block {
        ty: DataType,
        a: Opd,
        out: Opd,
        n: Opd,
        fill: bool,
    },
    Arith {
        op: Arith,
        ty: DataType,
        a: Opd,
        b: Opd,
        out: Opd,
    },
    IncDec {
        inc: bool,
        ty: DataType,
        out: Opd,
    },
    Shift {
        op: Shift,
        ty: DataType,
        out: Opd,
        n: Opd,
    },
    WordLogic {
        op: Logic,
        ty: DataType,
        a: Opd,
        b: Opd,
        out: Opd,
    },
    Inv {
        ty: DataType,
        out: Opd,
    },
    Conv {
        c: Conv,
        a: Opd,
        out: Opd,
    },
    Unary {
        op: Unary,
        ty: DataType,
        a: Opd,
        out: Opd,
    },
    Swap {
        out: Opd,
    },
    /// FOR INDX, INIT, FINAL; `end` is the instruction after the matching NEXT.
    For {
        ty: DataType,
        indx: Opd,
        init: Opd,
        fin: Opd,
        end: u32,
    },
    /// NEXT of the FOR at `start`.
    Next {
        start: u32,
    },
    Jmp {
        to: u32,
    },
    Jmpc {
        to: u32,
        neg: bool,
    },
    Cal {
        pou: u32,
        cond: Option<bool>,
    },
    Ret {
        cond: Option<bool>,
    },
    /// The element's locations are boxed (here and in `Counter`): they are read once per
    /// timer, and an unboxed `Element` made every instruction of the program about 80 bytes long.
    Timer {
        kind: TimerKind,
        slot: u32,
        el: Box<Element>,
        pt: Opd,
        reset: Option<Loc>,
    },
    Counter {
        kind: CounterKind,
        slot: u32,
        el: Box<Element>,
        pv: Opd,
        second: Option<Loc>,
        reset: Option<Loc>,
    },
    Atch {
        pou: u32,
        event: Opd,
    },
    Dtch {
        event: Opd,
    },
    Eni,
    Disi,
    Wdt,
    Nop,
    Special {
        id: u16,
        inst: u32,
        edge: bool,
        args: Box<[Opd]>,
        types: Box<[DataType]>,
    },
    /// End of a POU (implicit return).
    End,
}

/// A program organisation unit in the compiled program.
#[derive(Clone, Debug, PartialEq)]
pub struct Pou {
    pub name: String,
    pub kind: PouKind,
    pub entry: u32,
}

/// A compiled program.
#[derive(Clone, Debug)]
pub struct Program {
    /// File name shown in messages.
    pub file: String,
    pub code: Vec<Ins>,
    /// Cost of each instruction in ns (parallel to `code`).
    pub cost: Vec<u32>,
    /// Prefix sums of `cost` (one longer than `code`): the instructions `a..b` cost
    /// `cost_prefix[b] - cost_prefix[a]`. The interpreter adds a straight run's cost at once.
    /// Built with `cost` ([`compile`], [`Program::set_costs`]).
    pub cost_prefix: Vec<u64>,
    /// Cost class of each instruction (to re-cost it with another table).
    pub class: Vec<CostClass>,
    /// Source position of each instruction (parallel to `code`).
    pub pos: Vec<Pos>,
    /// Network number of each instruction (0 before the first marker).
    pub network: Vec<u32>,
    /// Mnemonic and operand text of each instruction (listings, the debugger).
    pub text: Vec<String>,
    pub pous: Vec<Pou>,
    /// Edge-memory slots, timer and counter numbers used (engine state sizes).
    pub edges: u32,
    pub timers: u32,
    pub counters: u32,
    pub costs: CostTable,
    /// Instructions in the source (what the user wrote, not counting implicit ends).
    pub source_instructions: usize,
    /// Load warnings (`file:line:column: …`): the program loads, but the user should know.
    pub warnings: Vec<String>,
}

impl Program {
    /// Index of the main program's POU.
    pub fn main(&self) -> &Pou {
        &self.pous[0]
    }
    /// Re-costs the program with another table (`sim program costs`).
    pub fn set_costs(&mut self, t: CostTable) {
        self.cost = self.class.iter().map(|c| t.ns(*c)).collect();
        self.cost_prefix = prefix_sums(&self.cost);
        self.costs = t;
    }

    pub fn pou(&self, name: &str) -> Option<u32> {
        self.pous.iter().position(|p| p.name.eq_ignore_ascii_case(name)).map(|i| i as u32)
    }
}

struct Ctx<'a, F: Family + ?Sized> {
    fam: &'a F,
    file: &'a str,
    prog: Program,
    specials: &'static [SpecialDef],
    timer_slots: HashMap<u32, u32>,
    counter_slots: HashMap<u32, u32>,
    special_inst: u32,
}

fn err(file: &str, pos: Pos, msg: impl std::fmt::Display) -> Error {
    Error::new(ErrorKind::Syntax, format!("{file}:{}:{}: {msg}", pos.line, pos.col))
}

/// A load error at `file:line:col:` from the catalogue, keeping the message's id as the
/// error's code.
fn err_m(file: &str, pos: Pos, m: Msg) -> Error {
    let text = format!("{file}:{}:{}: {}", pos.line, pos.col, m.text);
    Error::new(ErrorKind::Syntax, Msg { text, ..m })
}

/// Compiles IL `text` (named `file` in messages) for `fam`. Statements before any POU
/// header form the main program. A refusal quoting the text writes its control characters
/// out ([`crate::core::encoding::printable`]).
pub fn compile<F: Family + ?Sized>(text: &str, file: &str, fam: &F) -> Result<Program> {
    compile_text(text, file, fam).map_err(crate::core::encoding::printable_error)
}

fn compile_text<F: Family + ?Sized>(text: &str, file: &str, fam: &F) -> Result<Program> {
    let stmts = source::parse(text).map_err(|e| err(file, e.pos, e.message))?;
    let mut cx = Ctx {
        fam,
        file,
        prog: Program {
            file: file.to_string(),
            code: Vec::new(),
            cost: Vec::new(),
            cost_prefix: Vec::new(),
            class: Vec::new(),
            pos: Vec::new(),
            network: Vec::new(),
            text: Vec::new(),
            pous: Vec::new(),
            edges: 0,
            timers: 0,
            counters: 0,
            costs: fam.costs(),
            source_instructions: 0,
            warnings: Vec::new(),
        },
        specials: fam.specials(),
        timer_slots: HashMap::new(),
        counter_slots: HashMap::new(),
        special_inst: 0,
    };
    // Split into POUs: (kind, name, pos, statements).
    let mut pous: Vec<(PouKind, String, Pos, Vec<Stmt>)> = Vec::new();
    let mut cur: (PouKind, String, Pos, Vec<Stmt>) = (PouKind::Program, "MAIN".into(), Pos::default(), Vec::new());
    let mut explicit = false;
    for s in stmts {
        match s {
            Stmt::Pou { kind, name, pos } => {
                if !cur.3.is_empty() || explicit {
                    pous.push(std::mem::replace(&mut cur, (kind, name, pos, Vec::new())));
                } else {
                    cur = (kind, name, pos, Vec::new());
                }
                explicit = true;
            }
            Stmt::EndPou { .. } => {}
            s => cur.3.push(s),
        }
    }
    pous.push(cur);
    // A program POU first: it is the main program.
    if let Some(i) = pous.iter().position(|p| p.0 == PouKind::Program) {
        let p = pous.remove(i);
        pous.insert(0, p);
    } else {
        let p = &pous[0];
        if p.0 != PouKind::Program && pous.iter().all(|q| q.0 != PouKind::Program) && pous.len() > 1 {
            return Err(err_m(file, p.2, msg!("engine-no-program")).hint(msg!("engine-no-program-hint")));
        }
    }
    for (i, p) in pous.iter().enumerate() {
        if pous[..i].iter().any(|q| q.1 == p.1) {
            return Err(err_m(file, p.2, msg!("engine-pou-twice", name = &p.1)));
        }
        cx.prog.pous.push(Pou { name: p.1.clone(), kind: p.0, entry: 0 });
    }
    // Calls are bound after all POUs are placed: remember (instruction, name, pos).
    let mut calls: Vec<(usize, String, Pos)> = Vec::new();
    for (pi, (_, _, _, stmts)) in pous.iter().enumerate() {
        cx.prog.pous[pi].entry = cx.prog.code.len() as u32;
        let mut labels: HashMap<String, u32> = HashMap::new();
        let mut jumps: Vec<(usize, String, Pos)> = Vec::new();
        let mut fors: Vec<(usize, Pos)> = Vec::new();
        let mut network = 0;
        for s in stmts {
            match s {
                Stmt::Network { n, .. } => network = *n,
                Stmt::Label { name, pos } if labels.insert(name.clone(), cx.prog.code.len() as u32).is_some() => {
                    return Err(err_m(
                        file,
                        *pos,
                        msg!("engine-label-twice", name = name, pou = &cx.prog.pous[pi].name),
                    ));
                }
                Stmt::Instr { mnemonic, operands, pos } => {
                    let (mut ins, class) = cx.instr(mnemonic, operands, *pos, &mut jumps, &mut calls)?;
                    let here = cx.prog.code.len();
                    match &mut ins {
                        Ins::For { .. } => {
                            if fors.len() >= MAX_FOR_NESTING {
                                return Err(err_m(file, *pos, msg!("engine-for-too-deep", max = MAX_FOR_NESTING)));
                            }
                            fors.push((here, *pos));
                        }
                        Ins::Next { start } => {
                            let Some((f, _)) = fors.pop() else {
                                return Err(err_m(file, *pos, msg!("engine-next-without-for"))
                                    .hint(msg!("engine-next-without-for-hint")));
                            };
                            *start = f as u32;
                            if let Ins::For { end, .. } = &mut cx.prog.code[f] {
                                *end = here as u32 + 1;
                            }
                        }
                        _ => {}
                    }
                    cx.push(ins, class, *pos, network, mnemonic, operands);
                    cx.prog.source_instructions += 1;
                }
                _ => {}
            }
        }
        if let Some((_, pos)) = fors.last() {
            return Err(err_m(file, *pos, msg!("engine-for-without-next", pou = &cx.prog.pous[pi].name)));
        }
        cx.push(Ins::End, CostClass::Jump, Pos::default(), network, "(end)", &[]);
        for (at, name, pos) in jumps {
            let Some(&to) = labels.get(&name) else {
                let near = suggest(&name, labels.keys().map(|s| s.as_str()));
                let mut e = err_m(file, pos, msg!("engine-no-label", name = &name, pou = &cx.prog.pous[pi].name));
                if let Some(n) = near {
                    e = e.hint(msg!("engine-did-you-mean", name = n));
                }
                return Err(e);
            };
            match &mut cx.prog.code[at] {
                Ins::Jmp { to: t } | Ins::Jmpc { to: t, .. } => *t = to,
                _ => {}
            }
        }
    }
    for (at, name, pos) in calls {
        let Some(p) = cx.prog.pou(&name) else {
            let near = suggest(&name, cx.prog.pous.iter().map(|p| p.name.as_str()));
            let mut e = err_m(file, pos, msg!("engine-no-routine", name = &name, file = file));
            e = e.hint(match near {
                Some(n) => msg!("engine-did-you-mean", name = n),
                None => msg!("engine-no-routine-hint"),
            });
            return Err(e);
        };
        match &mut cx.prog.code[at] {
            Ins::Cal { pou, .. } | Ins::Atch { pou, .. } => *pou = p,
            _ => {}
        }
    }
    cx.prog.cost_prefix = prefix_sums(&cx.prog.cost);
    Ok(cx.prog)
}

/// `[0, c0, c0 + c1, …]`: one more entry than `cost`.
fn prefix_sums(cost: &[u32]) -> Vec<u64> {
    let mut sum = 0u64;
    std::iter::once(0)
        .chain(cost.iter().map(|c| {
            sum += *c as u64;
            sum
        }))
        .collect()
}

/// The closest name within edit distance 2 (names longer than 32 characters are not compared).
fn suggest<'a>(name: &str, cands: impl Iterator<Item = &'a str>) -> Option<String> {
    if name.len() > 32 {
        return None;
    }
    cands
        .filter(|c| c.len() <= 34)
        .map(|c| (edit_distance(name, c), c))
        .filter(|(d, _)| *d <= 2)
        .min_by_key(|(d, _)| *d)
        .map(|(_, c)| c.to_string())
}

impl<F: Family + ?Sized> Ctx<'_, F> {
    fn push(&mut self, ins: Ins, class: CostClass, pos: Pos, network: u32, m: &str, ops: &[OperandText]) {
        self.prog.code.push(ins);
        self.prog.cost.push(self.prog.costs.ns(class));
        self.prog.class.push(class);
        self.prog.pos.push(pos);
        self.prog.network.push(network);
        let ops: Vec<&str> = ops.iter().map(|o| o.text.as_str()).collect();
        self.prog.text.push(if ops.is_empty() { m.to_string() } else { format!("{m} {}", ops.join(", ")) });
    }

    fn e(&self, pos: Pos, msg: impl std::fmt::Display) -> Error {
        err(self.file, pos, msg)
    }

    /// [`err_m`] at `pos` of this file.
    fn e_m(&self, pos: Pos, m: Msg) -> Error {
        err_m(self.file, pos, m)
    }

    #[allow(clippy::type_complexity)]
    fn instr(
        &mut self,
        m: &str,
        ops: &[OperandText],
        pos: Pos,
        jumps: &mut Vec<(usize, String, Pos)>,
        calls: &mut Vec<(usize, String, Pos)>,
    ) -> Result<(Ins, CostClass)> {
        let here = self.prog.code.len();
        if let Some(def) = isa::lookup(m) {
            self.arity(m, def.operands, ops, pos)?;
            return Ok((self.core(def, ops, pos, here, jumps, calls)?, def.cost));
        }
        if let Some(sp) = self.specials.iter().find(|s| s.name == m) {
            let n = sp.args.len() as u8;
            self.arity(m, (n - sp.optional, n), ops, pos)?;
            let mut args = Vec::new();
            let mut types = Vec::new();
            for (o, k) in ops.iter().zip(sp.args) {
                let r = self.raw(o)?;
                let (opd, ty) = match k {
                    ArgKind::Const => {
                        let Raw::Lit(t) = &r else {
                            return Err(self.e_m(o.pos, msg!("engine-needs-constant", mnemonic = m, operand = &o.text)));
                        };
                        (Opd::Imm(self.literal(o, t, DataType::DInt)?), DataType::DInt)
                    }
                    ArgKind::Bit => (Opd::Loc(self.bit(o)?), DataType::Bool),
                    ArgKind::Value(t) | ArgKind::Out(t) => {
                        if matches!(k, ArgKind::Out(_)) {
                            self.out_loc(o, &r)?;
                        }
                        let ty = t.or(Self::own_ty(&r)).unwrap_or(DataType::Byte);
                        (self.typed(o, &r, ty)?, ty)
                    }
                };
                args.push(opd);
                types.push(ty);
            }
            let inst = self.special_inst;
            self.special_inst += 1;
            let ins = Ins::Special { id: sp.id, inst, edge: sp.edge, args: args.into(), types: types.into() };
            return Ok((ins, CostClass::Special));
        }
        // Unknown: suggest from the core table, the comparisons and the family's own.
        let names = isa::CORE
            .iter()
            .map(|d| d.name)
            .chain(self.specials.iter().map(|s| s.name))
            .chain(["LDW=", "LDW<>", "LDW>", "LDW<", "LDD=", "LDR>", "AW=", "OW="].iter().copied());
        let mut e = self.e_m(pos, msg!("engine-unknown-instruction", mnemonic = m));
        let names = names.filter(|n| !isa::NEVER_SUGGESTED.contains(n));
        e = e.hint(match suggest(m, names) {
            Some(n) => msg!("engine-unknown-instruction-near", name = n),
            None => msg!("engine-unknown-instruction-hint"),
        });
        Err(e)
    }

    fn arity(&self, m: &str, (lo, hi): (u8, u8), ops: &[OperandText], pos: Pos) -> Result<()> {
        let n = ops.len();
        if n < lo as usize || n > hi as usize {
            let want = if lo == hi { format!("{lo}") } else { format!("{lo} to {hi}") };
            return Err(self.e(pos, format!("{m} takes {want} operand(s), found {n}")));
        }
        Ok(())
    }

    /// A core instruction: the one-line ones here, the others by their group — bit logic
    /// ([`logic`]), moves ([`moves`]), arithmetic and conversions ([`arith`]), program flow
    /// and interrupts ([`flow`]), timers and counters ([`elements`]).
    #[allow(clippy::too_many_arguments)]
    fn core(
        &mut self,
        def: Def,
        ops: &[OperandText],
        pos: Pos,
        here: usize,
        jumps: &mut Vec<(usize, String, Pos)>,
        calls: &mut Vec<(usize, String, Pos)>,
    ) -> Result<Ins> {
        let m = def.name;
        Ok(match def.kind {
            Kind::Ld { neg } => Ins::Ld { loc: self.bit(&ops[0])?, neg },
            Kind::Logic { op, neg } => Ins::Logic { op, loc: self.bit(&ops[0])?, neg },
            Kind::ParOpen { op, neg } => self.par_open(op, neg, ops)?,
            Kind::ParClose => Ins::ParClose,
            Kind::Not => Ins::Not,
            Kind::St { neg } => Ins::St { loc: self.bit(&ops[0])?, neg },
            Kind::Set | Kind::Reset => self.set_reset(def.kind == Kind::Set, ops)?,
            Kind::Ald => Ins::Ald,
            Kind::Old => Ins::Old,
            Kind::Lps => Ins::Lps,
            Kind::Lrd => Ins::Lrd,
            Kind::Lpp => Ins::Lpp,
            Kind::RTrig | Kind::FTrig => self.edge(def.kind == Kind::RTrig),
            Kind::Compare { comb, ty, op } => self.compare(comb, ty, op, ops)?,
            Kind::Move { ty } => self.move_value(m, ty, ops)?,
            Kind::BlkMove { ty } => self.block(m, ty, false, ops)?,
            Kind::Fill => self.block(m, TyHint::Int, true, ops)?,
            Kind::Arith { op, ty } => self.arith(m, op, ty, ops, pos)?,
            Kind::IncDec { inc, ty } => self.inc_dec(m, inc, ty, ops)?,
            Kind::Shift { op } => self.shift(m, op, ops)?,
            Kind::WordLogic { op } => self.word_logic(m, op, ops)?,
            Kind::Inv => self.inv(m, ops)?,
            Kind::Unary(op) => self.unary(m, op, ops, pos)?,
            Kind::Swap => self.swap(ops)?,
            Kind::For => self.for_loop(m, ops, pos)?,
            Kind::Next => Ins::Next { start: 0 },
            Kind::Conv(c) => self.conv(c, ops)?,
            Kind::Jmp | Kind::Jmpc { .. } => Self::jump(def.kind, ops, here, jumps),
            Kind::Cal | Kind::Calc { .. } => Self::call(def.kind, ops, here, calls),
            Kind::Ret => Ins::Ret { cond: None },
            Kind::Retc { neg } => Ins::Ret { cond: Some(!neg) },
            Kind::Timer(kind) => self.timer(kind, ops)?,
            Kind::Counter(kind) => self.counter(kind, ops)?,
            Kind::Atch => self.atch(ops, here, calls)?,
            Kind::Dtch => self.dtch(ops)?,
            Kind::Eni => Ins::Eni,
            Kind::Disi => Ins::Disi,
            Kind::Wdt => Ins::Wdt,
            Kind::Nop => Ins::Nop,
        })
    }
}

/// For docs and tests: every core and family mnemonic.
pub fn mnemonics(specials: &[SpecialDef]) -> Vec<&'static str> {
    isa::CORE.iter().map(|d| d.name).chain(specials.iter().map(|s| s.name)).collect()
}
