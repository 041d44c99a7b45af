//! Statements → a compiled [`Program`]: mnemonics looked up in [`super::isa`] or the
//! family's table, operands resolved through [`Family`], types checked, labels and calls
//! bound to instruction indices. Every refusal is a load error naming `file:line:column`
//! and, where one is close, the instruction or label meant — nothing unknown survives to
//! run time.

use super::isa::{
    self, Arith, Cmp, Comb, Conv, CostClass, CounterKind, Def, Kind, Logic, Shift, TimerKind, TyHint, Unary,
};
use super::source::{self, OperandText, Pos, PouKind, Stmt};
use super::{ArgKind, CostTable, Element, Family, Loc, Opd, SpecialDef, Width};
use crate::core::literal::parse_literal;
use crate::core::text::edit_distance;
use crate::core::{DataType, Error, ErrorKind, Result};
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
    Timer {
        kind: TimerKind,
        slot: u32,
        el: Element,
        pt: Opd,
        reset: Option<Loc>,
    },
    Counter {
        kind: CounterKind,
        slot: u32,
        el: Element,
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
            return Err(err(file, p.2, "no PROGRAM in the file: the main program runs every scan")
                .hint("start the main program with `PROGRAM MAIN` (or put it before the first SUBROUTINE)"));
        }
    }
    for (i, p) in pous.iter().enumerate() {
        if pous[..i].iter().any(|q| q.1 == p.1) {
            return Err(err(file, p.2, format!("{} is defined twice", p.1)));
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
                    return Err(err(file, *pos, format!("label {name} is defined twice in {}", cx.prog.pous[pi].name)));
                }
                Stmt::Instr { mnemonic, operands, pos } => {
                    let (mut ins, class) = cx.instr(mnemonic, operands, *pos, &mut jumps, &mut calls)?;
                    let here = cx.prog.code.len();
                    match &mut ins {
                        Ins::For { .. } => {
                            if fors.len() >= MAX_FOR_NESTING {
                                return Err(err(file, *pos, format!("FOR loops nested deeper than {MAX_FOR_NESTING}")));
                            }
                            fors.push((here, *pos));
                        }
                        Ins::Next { start } => {
                            let Some((f, _)) = fors.pop() else {
                                return Err(err(file, *pos, "NEXT without a FOR".to_string())
                                    .hint("a loop is FOR INDX, INIT, FINAL … NEXT in the same POU"));
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
            return Err(err(file, *pos, format!("FOR without a NEXT in {}", cx.prog.pous[pi].name)));
        }
        cx.push(Ins::End, CostClass::Jump, Pos::default(), network, "(end)", &[]);
        for (at, name, pos) in jumps {
            let Some(&to) = labels.get(&name) else {
                let near = suggest(&name, labels.keys().map(|s| s.as_str()));
                let mut e = err(file, pos, format!("no label {name} in {}", cx.prog.pous[pi].name));
                if let Some(n) = near {
                    e = e.hint(format!("did you mean {n}?"));
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
            let mut e = err(file, pos, format!("no subroutine or interrupt routine {name} in {file}"));
            e = e.hint(match near {
                Some(n) => format!("did you mean {n}?"),
                None => "define it with `SUBROUTINE NAME` (or `INTERRUPT NAME`) … `END_SUBROUTINE`".into(),
            });
            return Err(e);
        };
        match &mut cx.prog.code[at] {
            Ins::Cal { pou, .. } | Ins::Atch { pou, .. } => *pou = p,
            _ => {}
        }
    }
    Ok(cx.prog)
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

fn bits_of(ty: DataType) -> u32 {
    ty.bits()
}

/// The type a typed mnemonic fixes.
fn hint_ty(h: TyHint) -> Option<DataType> {
    match h {
        TyHint::Byte => Some(DataType::Byte),
        TyHint::Int => Some(DataType::Int),
        TyHint::DInt => Some(DataType::DInt),
        TyHint::Real => Some(DataType::Real),
        TyHint::Auto => None,
    }
}

/// An operand before typing: a location (with its own type), a pointer deref, or literal text.
#[derive(Clone, Debug)]
enum Raw {
    Loc(Loc, DataType, String),
    Ind(Loc),
    Lit(String),
    Ptr(u32),
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

    fn raw(&self, o: &OperandText) -> Result<Raw> {
        let t = o.text.as_str();
        let fail = |e: super::OperandError| {
            let mut x = self.e(o.pos, format!("{t}: {}", e.message)).operand(t);
            if let Some(h) = e.hint {
                x = x.hint(h);
            }
            x
        };
        if let Some(rest) = t.strip_prefix('*') {
            let r = self.fam.operand(rest).map_err(fail)?;
            if r.loc.width != Width::DWord {
                return Err(self
                    .e(o.pos, format!("{t}: a pointer is a double word, {rest} is not"))
                    .hint(format!("keep pointers in double words, e.g. *%VD{}", r.loc.index)));
            }
            return Ok(Raw::Ind(r.loc));
        }
        if let Some(rest) = t.strip_prefix('&') {
            let r = self.fam.operand(rest).map_err(fail)?;
            let p = self.fam.pointer(r.loc).ok_or_else(|| {
                self.e(o.pos, format!("{t}: {} cannot be pointed to", r.canonical))
                    .hint("point to V, M, I, Q or SM bytes")
            })?;
            return Ok(Raw::Ptr(p));
        }
        let first = t.chars().next().unwrap_or(' ');
        let upper = t.to_ascii_uppercase();
        if first.is_ascii_digit()
            || first == '-'
            || first == '+'
            || t.contains('#')
            || matches!(upper.as_str(), "TRUE" | "FALSE" | "ON" | "OFF")
        {
            return Ok(Raw::Lit(t.to_string()));
        }
        let r = self.fam.value_operand(t).map_err(fail)?;
        Ok(Raw::Loc(r.loc, r.ty, r.canonical))
    }

    /// Types a raw operand as `ty`: locations must have the same width; literals must fit.
    fn typed(&self, o: &OperandText, r: &Raw, ty: DataType) -> Result<Opd> {
        match r {
            Raw::Loc(l, t, name) => {
                if bits_of(*t) != bits_of(ty) {
                    return Err(self
                        .e(o.pos, format!("{name} is a {} but this operation works on {}", t.name(), ty.name()))
                        .operand(name.clone())
                        .hint(conversion_hint(*t, ty)));
                }
                Ok(Opd::Loc(*l))
            }
            Raw::Ind(l) => Ok(Opd::Ind(*l)),
            Raw::Ptr(p) => {
                if bits_of(ty) != 32 {
                    return Err(self.e(o.pos, format!("{}: a pointer needs a double word", o.text)));
                }
                Ok(Opd::Imm(*p))
            }
            Raw::Lit(text) => Ok(Opd::Imm(self.literal(o, text, ty)?)),
        }
    }

    fn literal(&self, o: &OperandText, text: &str, ty: DataType) -> Result<u32> {
        let lit = parse_literal(text).map_err(|e| self.e(o.pos, format!("{text}: {}", e.message)))?;
        let v = lit.fit(ty, ty.bits()).map_err(|m| self.e(o.pos, m))?;
        Ok(ty.encode(&v))
    }

    /// The type of an operand as written (locations only).
    fn own_ty(r: &Raw) -> Option<DataType> {
        match r {
            Raw::Loc(_, t, _) => Some(*t),
            Raw::Ptr(_) => Some(DataType::DWord),
            _ => None,
        }
    }

    fn out_loc(&self, o: &OperandText, r: &Raw) -> Result<()> {
        match r {
            Raw::Lit(_) | Raw::Ptr(_) => {
                Err(self.e(o.pos, format!("{} cannot be written: the output must be a memory location", o.text)))
            }
            _ => Ok(()),
        }
    }

    fn bit(&self, o: &OperandText) -> Result<Loc> {
        let first = o.text.chars().next().unwrap_or(' ');
        let raw = if matches!(first, '*' | '&') || first.is_ascii_digit() || o.text.contains('#') {
            self.raw(o)?
        } else {
            let r = self.fam.operand(&o.text).map_err(|e| {
                let mut x = self.e(o.pos, format!("{}: {}", o.text, e.message)).operand(o.text.clone());
                if let Some(h) = e.hint {
                    x = x.hint(h);
                }
                x
            })?;
            Raw::Loc(r.loc, r.ty, r.canonical)
        };
        match raw {
            Raw::Loc(l, DataType::Bool, _) => Ok(l),
            Raw::Loc(_, t, name) => Err(self
                .e(o.pos, format!("{name} is a {}, not a bit", t.name()))
                .operand(name.clone())
                .hint("bit operands look like %M0.0, %I0.1, %SM0.0 (or T5/C5 for a timer's or counter's bit)")),
            _ => Err(self.e(o.pos, format!("{}: a bit location is needed here", o.text))),
        }
    }

    fn count(&self, o: &OperandText) -> Result<u32> {
        let v = self.literal(o, &o.text, DataType::DInt)? as i32;
        if !(1..=255).contains(&v) {
            return Err(self.e(o.pos, format!("{}: expected a count 1…255", o.text)));
        }
        Ok(v as u32)
    }

    fn name(o: &OperandText) -> String {
        o.text.trim_start_matches('%').to_ascii_uppercase()
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
                            return Err(self.e(o.pos, format!("{m}: {} must be a constant", o.text)));
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
        let mut e = self.e(pos, format!("unknown instruction {m}"));
        let names = names.filter(|n| !isa::NEVER_SUGGESTED.contains(n));
        e = e.hint(match suggest(m, names) {
            Some(n) => format!("did you mean {n}? (docs/il.md lists the instructions)"),
            None => "docs/il.md lists the instructions this simulator runs".into(),
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

    fn element(&mut self, o: &OperandText, timer: bool) -> Result<(Element, u32)> {
        let el = self.fam.element(&o.text, timer).map_err(|e| {
            let mut x = self.e(o.pos, format!("{}: {}", o.text, e.message));
            if let Some(h) = e.hint {
                x = x.hint(h);
            }
            x
        })?;
        let slots = if timer { &mut self.timer_slots } else { &mut self.counter_slots };
        let next = slots.len() as u32;
        let slot = *slots.entry(el.number).or_insert(next);
        if timer {
            self.prog.timers = self.timer_slots.len() as u32;
        } else {
            self.prog.counters = self.counter_slots.len() as u32;
        }
        Ok((el, slot))
    }

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
            Kind::ParOpen { op, neg } => {
                let load = match ops.first() {
                    Some(o) => Some(self.bit(o)?),
                    None => None,
                };
                Ins::ParOpen { op, neg, load }
            }
            Kind::ParClose => Ins::ParClose,
            Kind::Not => Ins::Not,
            Kind::St { neg } => Ins::St { loc: self.bit(&ops[0])?, neg },
            Kind::Set | Kind::Reset => {
                let on = def.kind == Kind::Set;
                // A timer or counter operand: R clears it (S7-200 `R T37, 1`).
                let up = ops[0].text.trim_start_matches('%').to_ascii_uppercase();
                if !on && (up.starts_with('T') || up.starts_with('C')) && up[1..].chars().all(|c| c.is_ascii_digit()) {
                    let timer = up.starts_with('T');
                    let (el, slot) = self.element(&ops[0], timer)?;
                    return Ok(Ins::ResetElem { timer, slot, cv: el.cv, q: el.q });
                }
                let n = match ops.get(1) {
                    Some(o) => self.count(o)?,
                    None => 1,
                };
                Ins::Set { loc: self.bit(&ops[0])?, n, on }
            }
            Kind::Ald => Ins::Ald,
            Kind::Old => Ins::Old,
            Kind::Lps => Ins::Lps,
            Kind::Lrd => Ins::Lrd,
            Kind::Lpp => Ins::Lpp,
            Kind::RTrig | Kind::FTrig => {
                let slot = self.prog.edges;
                self.prog.edges += 1;
                Ins::Edge { slot, rising: def.kind == Kind::RTrig }
            }
            Kind::Compare { comb, ty, op } => {
                let (a, b) = (self.raw(&ops[0])?, self.raw(&ops[1])?);
                let t = match hint_ty(ty) {
                    Some(t) => t,
                    None => Self::own_ty(&a).or(Self::own_ty(&b)).unwrap_or(DataType::Int),
                };
                // `LDW` compares INT; a WORD operand compares as its bits (same width).
                Ins::Compare { comb, op, ty: t, a: self.typed(&ops[0], &a, t)?, b: self.typed(&ops[1], &b, t)? }
            }
            Kind::Move { ty } => {
                let (a, out) = (self.raw(&ops[0])?, self.raw(&ops[1])?);
                self.out_loc(&ops[1], &out)?;
                let t = self.value_ty(m, ty, &[(&ops[1], &out), (&ops[0], &a)])?;
                Ins::Move { ty: t, a: self.typed(&ops[0], &a, t)?, out: self.typed(&ops[1], &out, t)? }
            }
            Kind::BlkMove { .. } | Kind::Fill => {
                let fill = def.kind == Kind::Fill;
                let hint = if let Kind::BlkMove { ty } = def.kind { ty } else { TyHint::Int };
                let (a, out) = (self.raw(&ops[0])?, self.raw(&ops[1])?);
                self.out_loc(&ops[1], &out)?;
                let t = self.value_ty(m, hint, &[(&ops[1], &out), (&ops[0], &a)])?;
                let n_raw = self.raw(&ops[2])?;
                let n = self.typed(&ops[2], &n_raw, DataType::Int)?;
                if let Opd::Imm(v) = n {
                    if !(1..=255).contains(&(v as u16 as i16)) {
                        return Err(self.e(ops[2].pos, format!("{m}: N must be 1…255, found {}", v as i16)));
                    }
                }
                Ins::Block { ty: t, a: self.typed(&ops[0], &a, t)?, out: self.typed(&ops[1], &out, t)?, n, fill }
            }
            Kind::Arith { op, ty } => {
                let out_o = ops.last().unwrap();
                let out = self.raw(out_o)?;
                self.out_loc(out_o, &out)?;
                let ins: Vec<Raw> = ops[..ops.len() - 1].iter().map(|o| self.raw(o)).collect::<Result<_>>()?;
                let mut all: Vec<(&OperandText, &Raw)> = vec![(out_o, &out)];
                all.extend(ops.iter().zip(ins.iter()));
                let t = signed(self.value_ty(m, ty, &all)?);
                if t == DataType::Bool {
                    return Err(self.e(pos, format!("{m} works on numbers, not bits")));
                }
                let outd = self.typed(out_o, &out, t)?;
                let (a, b) = if ins.len() == 1 {
                    (outd, self.typed(&ops[0], &ins[0], t)?)
                } else {
                    (self.typed(&ops[0], &ins[0], t)?, self.typed(&ops[1], &ins[1], t)?)
                };
                Ins::Arith { op, ty: t, a, b, out: outd }
            }
            Kind::IncDec { inc, ty } => {
                let out = self.raw(&ops[0])?;
                self.out_loc(&ops[0], &out)?;
                let t = signed(self.value_ty(m, ty, &[(&ops[0], &out)])?);
                Ins::IncDec { inc, ty: t, out: self.typed(&ops[0], &out, t)? }
            }
            Kind::Shift { op } => {
                let out = self.raw(&ops[0])?;
                self.out_loc(&ops[0], &out)?;
                let t = self.value_ty(m, TyHint::Auto, &[(&ops[0], &out)])?;
                let n = self.raw(&ops[1])?;
                Ins::Shift {
                    op,
                    ty: t,
                    out: self.typed(&ops[0], &out, t)?,
                    n: self.typed(&ops[1], &n, DataType::Byte)?,
                }
            }
            Kind::WordLogic { op } => {
                let out_o = ops.last().unwrap();
                let out = self.raw(out_o)?;
                self.out_loc(out_o, &out)?;
                let ins: Vec<Raw> = ops[..ops.len() - 1].iter().map(|o| self.raw(o)).collect::<Result<_>>()?;
                let mut all: Vec<(&OperandText, &Raw)> = vec![(out_o, &out)];
                all.extend(ops.iter().zip(ins.iter()));
                let t = self.value_ty(m, TyHint::Auto, &all)?;
                let outd = self.typed(out_o, &out, t)?;
                let (a, b) = if ins.len() == 1 {
                    (outd, self.typed(&ops[0], &ins[0], t)?)
                } else {
                    (self.typed(&ops[0], &ins[0], t)?, self.typed(&ops[1], &ins[1], t)?)
                };
                Ins::WordLogic { op, ty: t, a, b, out: outd }
            }
            Kind::Inv => {
                let out = self.raw(&ops[0])?;
                self.out_loc(&ops[0], &out)?;
                let t = self.value_ty(m, TyHint::Auto, &[(&ops[0], &out)])?;
                Ins::Inv { ty: t, out: self.typed(&ops[0], &out, t)? }
            }
            Kind::Unary(op) => {
                let (a, out) = (self.raw(&ops[0])?, self.raw(&ops[1])?);
                self.out_loc(&ops[1], &out)?;
                let t = match op {
                    Unary::Sqrt => DataType::Real,
                    Unary::Abs => signed(self.value_ty(m, TyHint::Auto, &[(&ops[1], &out), (&ops[0], &a)])?),
                };
                if t == DataType::Bool || t == DataType::Byte {
                    return Err(self.e(pos, format!("{m} works on INT, DINT or REAL values")));
                }
                Ins::Unary { op, ty: t, a: self.typed(&ops[0], &a, t)?, out: self.typed(&ops[1], &out, t)? }
            }
            Kind::Swap => {
                let out = self.raw(&ops[0])?;
                self.out_loc(&ops[0], &out)?;
                Ins::Swap { out: self.typed(&ops[0], &out, DataType::Word)? }
            }
            Kind::For => {
                let indx = self.raw(&ops[0])?;
                self.out_loc(&ops[0], &indx)?;
                let (init, fin) = (self.raw(&ops[1])?, self.raw(&ops[2])?);
                let t =
                    signed(self.value_ty(m, TyHint::Auto, &[(&ops[0], &indx), (&ops[1], &init), (&ops[2], &fin)])?);
                if !matches!(t, DataType::Int | DataType::DInt) {
                    return Err(self.e(pos, format!("{m}: INDX, INIT and FINAL are INT or DINT")));
                }
                Ins::For {
                    ty: t,
                    indx: self.typed(&ops[0], &indx, t)?,
                    init: self.typed(&ops[1], &init, t)?,
                    fin: self.typed(&ops[2], &fin, t)?,
                    end: 0,
                }
            }
            Kind::Next => Ins::Next { start: 0 },
            Kind::Conv(c) => {
                let (ti, to) = conv_types(c);
                let (a, out) = (self.raw(&ops[0])?, self.raw(&ops[1])?);
                self.out_loc(&ops[1], &out)?;
                Ins::Conv { c, a: self.typed(&ops[0], &a, ti)?, out: self.typed(&ops[1], &out, to)? }
            }
            Kind::Jmp | Kind::Jmpc { .. } => {
                jumps.push((here, Self::name(&ops[0]), ops[0].pos));
                match def.kind {
                    Kind::Jmpc { neg } => Ins::Jmpc { to: 0, neg },
                    _ => Ins::Jmp { to: 0 },
                }
            }
            Kind::Cal | Kind::Calc { .. } => {
                calls.push((here, Self::name(&ops[0]), ops[0].pos));
                let cond = match def.kind {
                    Kind::Calc { neg } => Some(!neg),
                    // KincoBuilder runs a subroutine box when its EN (the CR) is on.
                    _ => Some(true),
                };
                Ins::Cal { pou: 0, cond }
            }
            Kind::Ret => Ins::Ret { cond: None },
            Kind::Retc { neg } => Ins::Ret { cond: Some(!neg) },
            Kind::Timer(kind) => {
                let (el, slot) = self.element(&ops[0], true)?;
                let pt = self.preset(&ops[1], Some(el.base_ns))?;
                let reset = match ops.get(2) {
                    Some(o) => Some(self.bit(o)?),
                    None => None,
                };
                Ins::Timer { kind, slot, el, pt, reset }
            }
            Kind::Counter(kind) => {
                let (el, slot) = self.element(&ops[0], false)?;
                let pv = self.preset(&ops[1], None)?;
                let (second, reset) = match kind {
                    CounterKind::Ctud => (Some(self.bit(&ops[2])?), ops.get(3).map(|o| self.bit(o)).transpose()?),
                    _ => (None, ops.get(2).map(|o| self.bit(o)).transpose()?),
                };
                Ins::Counter { kind, slot, el, pv, second, reset }
            }
            Kind::Atch => {
                calls.push((here, Self::name(&ops[0]), ops[0].pos));
                let r = self.raw(&ops[1])?;
                let event = self.typed(&ops[1], &r, DataType::Int)?;
                if let Opd::Imm(v) = event {
                    if (v as i16) < 0 || !self.fam.event_exists(v as i16 as u32) {
                        return Err(self.e(
                            ops[1].pos,
                            format!("ATCH: no interrupt event {} (events: {})", v as i16, self.fam.event_list()),
                        ));
                    }
                }
                Ins::Atch { pou: 0, event }
            }
            Kind::Dtch => {
                let r = self.raw(&ops[0])?;
                Ins::Dtch { event: self.typed(&ops[0], &r, DataType::Int)? }
            }
            Kind::Eni => Ins::Eni,
            Kind::Disi => Ins::Disi,
            Kind::Wdt => Ins::Wdt,
            Kind::Nop => Ins::Nop,
        })
    }

    /// A timer preset or counter preset: INT operand or literal; `T#…` literals are
    /// converted to the timer's units.
    fn preset(&mut self, o: &OperandText, base_ns: Option<u64>) -> Result<Opd> {
        let r = self.raw(o)?;
        if let (Raw::Lit(t), Some(base)) = (&r, base_ns) {
            if t.to_ascii_uppercase().starts_with("T#") {
                let lit = parse_literal(t).map_err(|e| self.e(o.pos, format!("{t}: {}", e.message)))?;
                let ms = lit.value.as_i64();
                // In i128 to the end: a long T# on a fine time base must be refused, not
                // truncated back into 0…32767.
                // A delay is never shorter than asked: a duration between two units rounds up
                // (T#250ms on a 100 ms timer is 3 units, 300 ms), with a load warning.
                let base = base.max(1) as i128;
                let ns = ms as i128 * 1_000_000;
                let units = (ns + base - 1).div_euclid(base);
                if !(0..=32767).contains(&units) {
                    let longest = 32767 * base / 1_000_000;
                    return Err(self.e(
                        o.pos,
                        format!(
                            "{t} is {units} units of this {} ms timer; the preset must be 0…32767 (at most {}.{:03} s)",
                            base / 1_000_000,
                            longest / 1000,
                            longest % 1000
                        ),
                    ));
                }
                if units * base != ns {
                    let got = units * base / 1_000_000;
                    self.prog.warnings.push(format!(
                        "{}:{}:{}: {t} is not a whole number of this timer's {} ms units: rounded up to {got} ms ({units} units), never shorter than asked",
                        self.prog.file,
                        o.pos.line,
                        o.pos.col,
                        base / 1_000_000
                    ));
                }
                return Ok(Opd::Imm(units as u16 as u32));
            }
        }
        self.typed(o, &r, DataType::Int)
    }

    /// The type of a value instruction: the mnemonic's, else the first located operand's
    /// (the output first), else INT for literals only and BYTE behind pointers.
    fn value_ty(&self, m: &str, hint: TyHint, ops: &[(&OperandText, &Raw)]) -> Result<DataType> {
        if let Some(t) = hint_ty(hint) {
            return Ok(t);
        }
        for (_, r) in ops {
            if let Raw::Loc(_, t, _) = r {
                return Ok(*t);
            }
        }
        if ops.iter().any(|(_, r)| matches!(r, Raw::Ptr(_))) {
            return Ok(DataType::DWord);
        }
        if ops.iter().any(|(_, r)| matches!(r, Raw::Ind(_))) {
            // `MOVE *VD4, *VD8`: pointers made with `&VB…` address bytes.
            return Ok(DataType::Byte);
        }
        let _ = m;
        Ok(DataType::Int)
    }
}

/// Arithmetic on a WORD or DWORD operand is INT or DINT arithmetic (S7-200 `+I`, `+D`:
/// VW and VD hold signed numbers for the arithmetic instructions).
fn signed(t: DataType) -> DataType {
    match t {
        DataType::Word => DataType::Int,
        DataType::DWord => DataType::DInt,
        t => t,
    }
}

fn conv_types(c: Conv) -> (DataType, DataType) {
    use DataType as T;
    match c {
        Conv::IDi => (T::Int, T::DInt),
        Conv::DiI => (T::DInt, T::Int),
        Conv::BI => (T::Byte, T::Int),
        Conv::IB => (T::Int, T::Byte),
        Conv::DiR => (T::DInt, T::Real),
        Conv::Round | Conv::Trunc => (T::Real, T::DInt),
        Conv::IBcd | Conv::BcdI => (T::Int, T::Int),
    }
}

fn conversion_hint(from: DataType, to: DataType) -> String {
    match (from.bits(), to.bits()) {
        (16, 32) => "convert first: I_DI IN, %VDn (INT → DINT)".into(),
        (32, 16) => "convert first: DI_I IN, %VWn (DINT → INT)".into(),
        (8, 16) => "convert first: B_I IN, %VWn (BYTE → INT)".into(),
        (16, 8) => "convert first: I_B IN, %VBn (INT → BYTE)".into(),
        _ => "use operands of the same size (B, W, D)".into(),
    }
}

/// For docs and tests: every core and family mnemonic.
pub fn mnemonics(specials: &[SpecialDef]) -> Vec<&'static str> {
    isa::CORE.iter().map(|d| d.name).chain(specials.iter().map(|s| s.name)).collect()
}
