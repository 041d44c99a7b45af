//! FX instruction-list programs for the simulated FX PLC, run on the family-neutral scan
//! engine ([`crate::engine`]). The engine reads IEC/S7-200-style IL; an FX list (`LD X0`,
//! `OUT T0 K50`, `MOV K10 D0`) is a dialect of its own, so this module is its front end:
//!
//! 1. [`translate`] turns each FX instruction of the subset ([`INSTRUCTIONS`], one data table
//!    with a public source per instruction) into one or more engine instructions — `LDI` is
//!    `LDN`, `ANB` is `ALD`, `PLS M0` is `LPS / R_TRIG / ST M0 / LPP`, `K50` is `50`, `H1F` is
//!    `16#1F`, an applied instruction is wrapped in `LPS … LPP` because FX applied instructions
//!    leave the operation result alone (`LD X0 / MOV K1 D0 / OUT Y0` is one rung). Every
//!    emitted line remembers the FX line and column it came from, so load errors name the FX
//!    source (`blink.il:3:5`).
//! 2. [`FxFamily`] resolves the operands through the FX grammar ([`super::operand`]) bounded by
//!    the model; timers and counters are the family instructions `FXTIM`, `FXCNT`, `FXCNT32`
//!    and `FXRST` (not written by users: `OUT T0 K50`, `RST C0` become them).
//! 3. [`super::machine::FxMachine`] executes against the PLC's memory: FX timer and counter
//!    rules live in [`super::plc`].
//!
//! The subset and its sources are listed in `docs/il.md` ("The FX family"), checked against
//! [`INSTRUCTIONS`] by a test.

use super::elements::{C32_FIRST, C32_LAST};
use super::model::Model;
use super::operand::{self, Area, FxOperand, Width as FxWidth};
use super::space::{FxSpace, Proto};
use crate::core::{DataType, Error, ErrorKind, Result};
use crate::engine::source::{self, Pos, Stmt};
use crate::engine::{
    self, ArgKind, CostTable, Cpu, Element, Family, Loc, OperandError, Program, Resolved, SpecialDef, Width,
};

/// What an FX mnemonic becomes.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum FxKind {
    /// A contact instruction with one bit operand: the engine mnemonic.
    Contact(&'static str),
    /// `LDP`/`ANDF` …: load the bit, take its edge, combine (`None`: a new block).
    EdgeContact {
        rising: bool,
        combine: Option<&'static str>,
    },
    /// No operand: the engine mnemonic (`ANB` → `ALD`).
    Plain(&'static str),
    /// `OUT`: a bit, or a timer/counter with its preset.
    Out,
    Set,
    Rst,
    /// `PLS`/`PLF`: a one-scan pulse on the CR's edge.
    Pulse {
        rising: bool,
    },
    /// An applied instruction: engine mnemonic, 32-bit (`D…`), pulse-executed (`…P`).
    Applied {
        engine: &'static str,
        wide: bool,
        pulse: bool,
    },
    /// A contact comparison: engine mnemonic, 32-bit.
    Compare {
        engine: &'static str,
        wide: bool,
    },
    /// `END`: the rest of the file is not scanned.
    End,
}

/// One instruction of the FX subset.
#[derive(Clone, Copy, Debug)]
pub struct FxDef {
    pub name: &'static str,
    /// Operand count accepted (min, max).
    pub operands: (u8, u8),
    pub kind: FxKind,
    pub doc: &'static str,
    pub source: &'static str,
}

const fn fx(name: &'static str, operands: (u8, u8), kind: FxKind, doc: &'static str, source: &'static str) -> FxDef {
    FxDef { name, operands, kind, doc, source }
}

use FxKind as K;

/// The FX instruction subset plcsh runs. Sources: FX PM chapter 2 (basic instructions, by
/// section title) and chapter 5 (applied instructions, by FNC number).
pub static INSTRUCTIONS: &[FxDef] = &[
    fx("LD", (1, 1), K::Contact("LD"), "start a block with a normally open contact", "FX PM 2, Load"),
    fx("LDI", (1, 1), K::Contact("LDN"), "start a block with a normally closed contact", "FX PM 2, Load Inverse"),
    fx(
        "LDP",
        (1, 1),
        K::EdgeContact { rising: true, combine: None },
        "start a block: on for one scan when the bit rises",
        "FX PM 2, Load Pulse",
    ),
    fx(
        "LDF",
        (1, 1),
        K::EdgeContact { rising: false, combine: None },
        "start a block: on for one scan when the bit falls",
        "FX PM 2, Load Trailing Pulse",
    ),
    fx("AND", (1, 1), K::Contact("AND"), "series normally open contact", "FX PM 2, And"),
    fx("ANI", (1, 1), K::Contact("ANDN"), "series normally closed contact", "FX PM 2, And Inverse"),
    fx(
        "ANDP",
        (1, 1),
        K::EdgeContact { rising: true, combine: Some("ALD") },
        "series rising-edge contact",
        "FX PM 2, And Pulse",
    ),
    fx(
        "ANDF",
        (1, 1),
        K::EdgeContact { rising: false, combine: Some("ALD") },
        "series falling-edge contact",
        "FX PM 2, And Trailing Pulse",
    ),
    fx("OR", (1, 1), K::Contact("OR"), "parallel normally open contact", "FX PM 2, Or"),
    fx("ORI", (1, 1), K::Contact("ORN"), "parallel normally closed contact", "FX PM 2, Or Inverse"),
    fx(
        "ORP",
        (1, 1),
        K::EdgeContact { rising: true, combine: Some("OLD") },
        "parallel rising-edge contact",
        "FX PM 2, Or Pulse",
    ),
    fx(
        "ORF",
        (1, 1),
        K::EdgeContact { rising: false, combine: Some("OLD") },
        "parallel falling-edge contact",
        "FX PM 2, Or Trailing Pulse",
    ),
    fx("ANB", (0, 0), K::Plain("ALD"), "AND the last two blocks", "FX PM 2, And Block"),
    fx("ORB", (0, 0), K::Plain("OLD"), "OR the last two blocks", "FX PM 2, Or Block"),
    fx("MPS", (0, 0), K::Plain("LPS"), "push the operation result", "FX PM 2, MPS, MRD and MPP"),
    fx("MRD", (0, 0), K::Plain("LRD"), "read the pushed result", "FX PM 2, MPS, MRD and MPP"),
    fx("MPP", (0, 0), K::Plain("LPP"), "pop the pushed result", "FX PM 2, MPS, MRD and MPP"),
    fx("INV", (0, 0), K::Plain("NOT"), "invert the operation result", "FX PM 2, Inverse"),
    fx(
        "OUT",
        (1, 2),
        K::Out,
        "OUT Y/M/S: coil := result; OUT Tn K|D: timer coil with preset; OUT Cn K|D: counter coil",
        "FX PM 2, Out; Timer, Counter (Out & Reset)",
    ),
    fx("SET", (1, 1), K::Set, "if the result is on: set Y/M/S (stays on)", "FX PM 2, Set and Reset"),
    fx(
        "RST",
        (1, 1),
        K::Rst,
        "if the result is on: reset Y/M/S, clear D, clear a timer or counter (value 0, contact off)",
        "FX PM 2, Set and Reset; Timer, Counter (Out & Reset)",
    ),
    fx(
        "PLS",
        (1, 1),
        K::Pulse { rising: true },
        "Y/M on for one scan after the result rises",
        "FX PM 2, Pulse (PLS, PLF)",
    ),
    fx(
        "PLF",
        (1, 1),
        K::Pulse { rising: false },
        "Y/M on for one scan after the result falls",
        "FX PM 2, Pulse (PLS, PLF)",
    ),
    fx(
        "MOV",
        (2, 2),
        K::Applied { engine: "MOVE", wide: false, pulse: false },
        "MOV S D: D := S (16-bit)",
        "FX PM 5, FNC 12 MOV",
    ),
    fx(
        "MOVP",
        (2, 2),
        K::Applied { engine: "MOVE", wide: false, pulse: true },
        "MOV on the result's rising edge",
        "FX PM 5, FNC 12 MOV",
    ),
    fx(
        "DMOV",
        (2, 2),
        K::Applied { engine: "MOVD", wide: true, pulse: false },
        "32-bit MOV (D0 = D0 low, D1 high)",
        "FX PM 5, FNC 12 MOV",
    ),
    fx(
        "DMOVP",
        (2, 2),
        K::Applied { engine: "MOVD", wide: true, pulse: true },
        "32-bit MOV on the rising edge",
        "FX PM 5, FNC 12 MOV",
    ),
    fx(
        "ADD",
        (3, 3),
        K::Applied { engine: "ADD", wide: false, pulse: false },
        "ADD S1 S2 D: D := S1 + S2 (16-bit, wraps)",
        "FX PM 5, FNC 20 ADD",
    ),
    fx(
        "ADDP",
        (3, 3),
        K::Applied { engine: "ADD", wide: false, pulse: true },
        "ADD on the rising edge",
        "FX PM 5, FNC 20 ADD",
    ),
    fx("DADD", (3, 3), K::Applied { engine: "ADD", wide: true, pulse: false }, "32-bit ADD", "FX PM 5, FNC 20 ADD"),
    fx(
        "SUB",
        (3, 3),
        K::Applied { engine: "SUB", wide: false, pulse: false },
        "SUB S1 S2 D: D := S1 − S2 (16-bit, wraps)",
        "FX PM 5, FNC 21 SUB",
    ),
    fx(
        "SUBP",
        (3, 3),
        K::Applied { engine: "SUB", wide: false, pulse: true },
        "SUB on the rising edge",
        "FX PM 5, FNC 21 SUB",
    ),
    fx("DSUB", (3, 3), K::Applied { engine: "SUB", wide: true, pulse: false }, "32-bit SUB", "FX PM 5, FNC 21 SUB"),
    fx(
        "INC",
        (1, 1),
        K::Applied { engine: "INC", wide: false, pulse: false },
        "D := D + 1 every scan the result is on",
        "FX PM 5, FNC 24 INC",
    ),
    fx(
        "INCP",
        (1, 1),
        K::Applied { engine: "INC", wide: false, pulse: true },
        "D := D + 1 on the rising edge",
        "FX PM 5, FNC 24 INC",
    ),
    fx(
        "DEC",
        (1, 1),
        K::Applied { engine: "DEC", wide: false, pulse: false },
        "D := D − 1 every scan the result is on",
        "FX PM 5, FNC 25 DEC",
    ),
    fx(
        "DECP",
        (1, 1),
        K::Applied { engine: "DEC", wide: false, pulse: true },
        "D := D − 1 on the rising edge",
        "FX PM 5, FNC 25 DEC",
    ),
    fx(
        "LD=",
        (2, 2),
        K::Compare { engine: "LDW=", wide: false },
        "start a block: S1 = S2 (16-bit)",
        "FX PM 5, FNC 224–230 LD□",
    ),
    fx("LD>", (2, 2), K::Compare { engine: "LDW>", wide: false }, "start a block: S1 > S2", "FX PM 5, FNC 224–230 LD□"),
    fx("LD<", (2, 2), K::Compare { engine: "LDW<", wide: false }, "start a block: S1 < S2", "FX PM 5, FNC 224–230 LD□"),
    fx(
        "LD<>",
        (2, 2),
        K::Compare { engine: "LDW<>", wide: false },
        "start a block: S1 ≠ S2",
        "FX PM 5, FNC 224–230 LD□",
    ),
    fx(
        "LD<=",
        (2, 2),
        K::Compare { engine: "LDW<=", wide: false },
        "start a block: S1 ≤ S2",
        "FX PM 5, FNC 224–230 LD□",
    ),
    fx(
        "LD>=",
        (2, 2),
        K::Compare { engine: "LDW>=", wide: false },
        "start a block: S1 ≥ S2",
        "FX PM 5, FNC 224–230 LD□",
    ),
    fx(
        "AND=",
        (2, 2),
        K::Compare { engine: "AW=", wide: false },
        "series contact: S1 = S2",
        "FX PM 5, FNC 232–238 AND□",
    ),
    fx(
        "AND>",
        (2, 2),
        K::Compare { engine: "AW>", wide: false },
        "series contact: S1 > S2",
        "FX PM 5, FNC 232–238 AND□",
    ),
    fx(
        "AND<",
        (2, 2),
        K::Compare { engine: "AW<", wide: false },
        "series contact: S1 < S2",
        "FX PM 5, FNC 232–238 AND□",
    ),
    fx(
        "AND<>",
        (2, 2),
        K::Compare { engine: "AW<>", wide: false },
        "series contact: S1 ≠ S2",
        "FX PM 5, FNC 232–238 AND□",
    ),
    fx(
        "AND<=",
        (2, 2),
        K::Compare { engine: "AW<=", wide: false },
        "series contact: S1 ≤ S2",
        "FX PM 5, FNC 232–238 AND□",
    ),
    fx(
        "AND>=",
        (2, 2),
        K::Compare { engine: "AW>=", wide: false },
        "series contact: S1 ≥ S2",
        "FX PM 5, FNC 232–238 AND□",
    ),
    fx(
        "OR=",
        (2, 2),
        K::Compare { engine: "OW=", wide: false },
        "parallel contact: S1 = S2",
        "FX PM 5, FNC 240–246 OR□",
    ),
    fx(
        "OR>",
        (2, 2),
        K::Compare { engine: "OW>", wide: false },
        "parallel contact: S1 > S2",
        "FX PM 5, FNC 240–246 OR□",
    ),
    fx(
        "OR<",
        (2, 2),
        K::Compare { engine: "OW<", wide: false },
        "parallel contact: S1 < S2",
        "FX PM 5, FNC 240–246 OR□",
    ),
    fx(
        "OR<>",
        (2, 2),
        K::Compare { engine: "OW<>", wide: false },
        "parallel contact: S1 ≠ S2",
        "FX PM 5, FNC 240–246 OR□",
    ),
    fx(
        "OR<=",
        (2, 2),
        K::Compare { engine: "OW<=", wide: false },
        "parallel contact: S1 ≤ S2",
        "FX PM 5, FNC 240–246 OR□",
    ),
    fx(
        "OR>=",
        (2, 2),
        K::Compare { engine: "OW>=", wide: false },
        "parallel contact: S1 ≥ S2",
        "FX PM 5, FNC 240–246 OR□",
    ),
    fx(
        "LDD=",
        (2, 2),
        K::Compare { engine: "LDD=", wide: true },
        "32-bit: start a block: S1 = S2",
        "FX PM 5, FNC 224 LD=",
    ),
    fx(
        "LDD>",
        (2, 2),
        K::Compare { engine: "LDD>", wide: true },
        "32-bit: start a block: S1 > S2",
        "FX PM 5, FNC 225 LD>",
    ),
    fx(
        "LDD<",
        (2, 2),
        K::Compare { engine: "LDD<", wide: true },
        "32-bit: start a block: S1 < S2",
        "FX PM 5, FNC 226 LD<",
    ),
    fx(
        "ANDD=",
        (2, 2),
        K::Compare { engine: "AD=", wide: true },
        "32-bit series contact: S1 = S2",
        "FX PM 5, FNC 232 AND=",
    ),
    fx(
        "ORD=",
        (2, 2),
        K::Compare { engine: "OD=", wide: true },
        "32-bit parallel contact: S1 = S2",
        "FX PM 5, FNC 240 OR=",
    ),
    fx("NOP", (0, 0), K::Plain("NOP"), "nothing", "FX PM 2, No Operation"),
    fx("END", (0, 0), K::End, "end of the program: what follows is not scanned", "FX PM 2, End"),
];

/// Looks an FX mnemonic up.
pub fn lookup(m: &str) -> Option<&'static FxDef> {
    INSTRUCTIONS.iter().find(|d| d.name == m)
}

/// The subset as Markdown rows (`docs/il.md` is checked against it).
pub fn markdown() -> String {
    let mut s = String::from("| instruction | operands | does | source |\n|---|---|---|---|\n");
    for d in INSTRUCTIONS {
        let ops = if d.operands.0 == d.operands.1 {
            d.operands.0.to_string()
        } else {
            format!("{}–{}", d.operands.0, d.operands.1)
        };
        s.push_str(&format!("| `{}` (FX) | {ops} | {} | {} |\n", d.name, d.doc, d.source));
    }
    s
}

/// Family instruction ids.
pub mod id {
    pub const TIMER: u16 = 1;
    pub const COUNTER: u16 = 2;
    pub const COUNTER32: u16 = 3;
    pub const RESET: u16 = 4;
}

/// The family instructions the translation emits (users write `OUT T0 K50`, `RST C0`).
pub static SPECIALS: &[SpecialDef] = &[
    SpecialDef {
        name: "FXTIM",
        id: id::TIMER,
        args: &[ArgKind::Bit, ArgKind::Value(Some(DataType::Int))],
        optional: 0,
        edge: false,
        doc: "OUT Tn K|D: FX timer coil (input = CR, CR unchanged)",
        source: "FX PM 2, Out; 4, Timers",
    },
    SpecialDef {
        name: "FXCNT",
        id: id::COUNTER,
        args: &[ArgKind::Bit, ArgKind::Value(Some(DataType::Int))],
        optional: 0,
        edge: false,
        doc: "OUT Cn K|D: FX 16-bit counter coil",
        source: "FX PM 2, Out; 4, Counters",
    },
    SpecialDef {
        name: "FXCNT32",
        id: id::COUNTER32,
        args: &[ArgKind::Bit, ArgKind::Value(Some(DataType::DInt))],
        optional: 0,
        edge: false,
        doc: "OUT Cn K|D: FX 32-bit up/down counter coil",
        source: "FX PM 2, Out; 4, Counters",
    },
    SpecialDef {
        name: "FXRST",
        id: id::RESET,
        args: &[ArgKind::Value(None)],
        optional: 0,
        edge: false,
        doc: "RST D/T/C: clear a register, timer or counter",
        source: "FX PM 2, Set and Reset",
    },
];

// ----- translation -----

/// One emitted engine line and where its parts came from.
struct Emitted {
    text: String,
    /// The FX statement's position.
    at: Pos,
    /// (column in `text`, 1-based; FX position) of each operand.
    operands: Vec<(u32, Pos)>,
}

/// An FX program translated to the engine's IL.
pub struct Translation {
    pub text: String,
    lines: Vec<Emitted>,
}

impl Translation {
    /// The FX position of engine line `line`, column `col`.
    fn origin(&self, line: u32, col: u32) -> Pos {
        let Some(e) = line.checked_sub(1).and_then(|l| self.lines.get(l as usize)) else { return Pos::default() };
        e.operands.iter().find(|(c, _)| *c == col).map_or(e.at, |(_, p)| *p)
    }

    /// Rewrites `file:L:C:` at the start of an engine message to the FX source position.
    fn remap(&self, file: &str, mut e: Error) -> Error {
        let prefix = format!("{file}:");
        if let Some(rest) = e.message.strip_prefix(&prefix) {
            let mut it = rest.splitn(3, ':');
            if let (Some(l), Some(c), Some(msg)) = (it.next(), it.next(), it.next()) {
                if let (Ok(l), Ok(c)) = (l.parse::<u32>(), c.parse::<u32>()) {
                    let p = self.origin(l, c);
                    let m = format!("{file}:{}:{}:{msg}", p.line, p.col);
                    e.message = m;
                }
            }
        }
        e
    }
}

fn load_err(file: &str, p: Pos, msg: impl std::fmt::Display) -> Error {
    Error::new(ErrorKind::Syntax, format!("{file}:{}:{}: {msg}", p.line, p.col))
}

/// `K123` → `123`, `K-5` → `-5`, `H1F` → `16#1F`; anything else is not a constant.
fn constant(t: &str) -> Option<String> {
    let up = t.to_ascii_uppercase();
    if let Some(d) = up.strip_prefix('K') {
        let digits = d.strip_prefix(['-', '+']).unwrap_or(d);
        if !digits.is_empty() && digits.bytes().all(|b| b.is_ascii_digit()) {
            return Some(d.trim_start_matches('+').to_string());
        }
        return None;
    }
    if let Some(h) = up.strip_prefix('H') {
        if !h.is_empty() && h.len() <= 8 && h.bytes().all(|b| b.is_ascii_hexdigit()) {
            return Some(format!("16#{h}"));
        }
    }
    None
}

/// An operand where a value is read or written: bare `T5`/`C5` are the current values (FX
/// applied instructions read a timer's value), 32-bit instructions read D pairs and groups
/// as DINT.
fn value_text(t: &str, wide: bool) -> String {
    if let Some(k) = constant(t) {
        return k;
    }
    let up = t.trim_start_matches('%').to_ascii_uppercase();
    let b = up.as_bytes();
    let mut s = match b.first() {
        Some(b'T' | b'C') if b.get(1).is_some_and(u8::is_ascii_digit) => format!("{}N{}", &up[..1], &up[1..]),
        _ => up.clone(),
    };
    if wide && !s.contains('/') {
        let word = s.starts_with('D') || (s.starts_with('K') && s.as_bytes().get(1).is_some_and(u8::is_ascii_digit));
        if word {
            s.push_str("/DINT");
        }
    }
    s
}

/// The operands of an FX statement: the lexer splits on commas; FX lists separate them with
/// spaces (`OUT T0 K50`). Each operand keeps its position.
fn split_operands(ops: &[source::OperandText]) -> Vec<(String, Pos)> {
    let mut out = Vec::new();
    for o in ops {
        let mut col = o.pos.col;
        for part in o.text.split(' ') {
            if !part.is_empty() {
                out.push((part.to_string(), Pos { line: o.pos.line, col }));
            }
            col += part.chars().count() as u32 + 1;
        }
    }
    out
}

struct Builder<'a> {
    file: &'a str,
    model: &'static Model,
    lines: Vec<Emitted>,
}

impl Builder<'_> {
    /// Emits `mnemonic op, op …` for the FX statement at `at`.
    fn emit(&mut self, at: Pos, mnemonic: &str, ops: &[(String, Pos)]) {
        let mut text = mnemonic.to_string();
        let mut cols = Vec::new();
        for (i, (t, p)) in ops.iter().enumerate() {
            text.push_str(if i == 0 { " " } else { ", " });
            cols.push((text.chars().count() as u32 + 1, *p));
            text.push_str(t);
        }
        self.lines.push(Emitted { text, at, operands: cols });
    }

    /// A parsed FX operand (for checks the translation makes itself).
    fn parse(&self, t: &str, p: Pos) -> Result<FxOperand> {
        operand::parse_one(t).map_err(|e| {
            let mut x = load_err(self.file, p, format!("{t}: {}", e.message));
            if let Some(h) = &e.hint {
                x = x.hint(h.clone());
            }
            x
        })
    }

    fn statement(&mut self, m: &str, ops: &[(String, Pos)], at: Pos) -> Result<bool> {
        let Some(def) = lookup(m) else {
            // Another family's mnemonic (a K2's or IEC's `TON`): the FX way to write it, not
            // the FX mnemonic nearest in spelling (`TON` is two letters from `MOV`).
            if let Some((_, how)) = FOREIGN.iter().find(|(f, _)| f.eq_ignore_ascii_case(m)) {
                return Err(load_err(self.file, at, format!("unknown FX instruction {m}"))
                    .hint(format!("{m} is not an FX mnemonic: on an FX write {how} (docs/il.md, The FX family)")));
            }
            let near = suggest(m);
            let mut e = load_err(self.file, at, format!("unknown FX instruction {m}"));
            e = e.hint(match near {
                Some(n) => format!("did you mean {n}? (docs/il.md lists the FX subset)"),
                None => "docs/il.md lists the FX instructions the simulator runs".into(),
            });
            return Err(e);
        };
        let (lo, hi) = def.operands;
        if ops.len() < lo as usize || ops.len() > hi as usize {
            let want = if lo == hi { lo.to_string() } else { format!("{lo} to {hi}") };
            return Err(load_err(self.file, at, format!("{m} takes {want} operand(s), found {}", ops.len())));
        }
        let one = |s: String, p: Pos| vec![(s, p)];
        match def.kind {
            K::Contact(e) => self.emit(at, e, &ops[..1]),
            K::EdgeContact { rising, combine } => {
                self.emit(at, "LD", &ops[..1]);
                self.emit(at, if rising { "R_TRIG" } else { "F_TRIG" }, &[]);
                if let Some(c) = combine {
                    self.emit(at, c, &[]);
                }
            }
            K::Plain(e) => self.emit(at, e, &[]),
            K::End => return Ok(false),
            K::Out => {
                let (t, p) = &ops[0];
                let o = self.parse(t, *p)?;
                match o.area {
                    Area::TS | Area::CS => {
                        let timer = o.area == Area::TS;
                        let Some((k, kp)) = ops.get(1) else {
                            return Err(load_err(
                                self.file,
                                at,
                                format!("OUT {t} needs a preset: OUT {t} K10 (a constant) or OUT {t} D10 (a register)"),
                            ));
                        };
                        if constant(k).is_none() && !k.to_ascii_uppercase().starts_with('D') {
                            return Err(load_err(
                                self.file,
                                *kp,
                                format!("{k}: a preset is a constant K… or a data register D…"),
                            ));
                        }
                        let n = o.index;
                        let special = if timer {
                            "FXTIM"
                        } else if n < C32_FIRST {
                            "FXCNT"
                        } else if n <= C32_LAST {
                            "FXCNT32"
                        } else {
                            return Err(load_err(
                                self.file,
                                *p,
                                format!("{t}: high-speed counters (C235–C255) are not simulated"),
                            )
                            .hint("use C0–C199 (16-bit) or C200–C234 (32-bit up/down)"));
                        };
                        let wide = special == "FXCNT32";
                        self.emit(at, special, &[(o.canonical(), *p), (value_text(k, wide), *kp)]);
                    }
                    _ => {
                        if ops.len() > 1 {
                            return Err(load_err(
                                self.file,
                                ops[1].1,
                                format!("OUT {t} takes one operand (a preset is for timers and counters)"),
                            ));
                        }
                        self.coil_target(&o, t, *p, m)?;
                        self.emit(at, "ST", &ops[..1]);
                    }
                }
            }
            K::Set => {
                let (t, p) = &ops[0];
                let o = self.parse(t, *p)?;
                self.coil_target(&o, t, *p, m)?;
                self.emit(at, "S", &ops[..1]);
            }
            K::Rst => {
                let (t, p) = &ops[0];
                let o = self.parse(t, *p)?;
                match o.area {
                    Area::Y | Area::M | Area::S if o.width == FxWidth::Bit => {
                        self.coil_target(&o, t, *p, m)?;
                        self.emit(at, "R", &ops[..1]);
                    }
                    Area::TS | Area::TN | Area::CS | Area::CN | Area::D if !matches!(o.width, FxWidth::Group(_)) => {
                        self.emit(at, "FXRST", &one(o.canonical(), *p));
                    }
                    _ => {
                        return Err(load_err(
                            self.file,
                            *p,
                            format!("RST {t}: resets Y, M, S, D, a timer T or a counter C"),
                        ))
                    }
                }
            }
            K::Pulse { rising } => {
                let (t, p) = &ops[0];
                let o = self.parse(t, *p)?;
                self.coil_target(&o, t, *p, m)?;
                self.emit(at, "LPS", &[]);
                self.emit(at, if rising { "R_TRIG" } else { "F_TRIG" }, &[]);
                self.emit(at, "ST", &ops[..1]);
                self.emit(at, "LPP", &[]);
            }
            K::Applied { engine, wide, pulse } => {
                // The destination (the last operand) is written: never an input.
                let (t, p) = &ops[ops.len() - 1];
                if constant(t).is_none() {
                    let o = self.parse(&value_text(t, false), *p)?;
                    if o.area == Area::X {
                        return Err(load_err(
                            self.file,
                            *p,
                            format!("{m} {t}: inputs X cannot be written by a program"),
                        )
                        .hint("write Y, M, S (as KnY0 …), D, or a timer's or counter's value"));
                    }
                }
                let vals: Vec<(String, Pos)> = ops.iter().map(|(t, p)| (value_text(t, wide), *p)).collect();
                self.emit(at, "LPS", &[]);
                if pulse {
                    self.emit(at, "R_TRIG", &[]);
                }
                self.emit(at, engine, &vals);
                self.emit(at, "LPP", &[]);
            }
            K::Compare { engine, wide } => {
                let vals: Vec<(String, Pos)> = ops.iter().map(|(t, p)| (value_text(t, wide), *p)).collect();
                self.emit(at, engine, &vals);
            }
        }
        Ok(true)
    }

    /// A coil a program may drive: Y, M, S (not an input, not a special relay the CPU drives).
    fn coil_target(&self, o: &FxOperand, t: &str, p: Pos, m: &str) -> Result<()> {
        if !matches!(o.area, Area::Y | Area::M | Area::S) || o.width != FxWidth::Bit {
            return Err(load_err(self.file, p, format!("{m} {t}: a program drives Y, M and S bits here"))
                .hint("inputs X come from the field; OUT T0 K10 / OUT C0 K5 drive timers and counters"));
        }
        if operand::system_driven(o.area, o.index) {
            return Err(load_err(self.file, p, format!("{m} {t}: {} is driven by the PLC", o.canonical())));
        }
        if !FxSpace::new(self.model, Proto::Port).exists(o.area, o.index) {
            return Err(load_err(self.file, p, format!("{t} is not on an {}", self.model.name)));
        }
        Ok(())
    }
}

/// Mnemonics of the K2's and IEC 61131-3 instruction lists that an FX writes otherwise, with
/// the FX form (FX PM 2 and 4: timers and counters are coils with a preset).
const FOREIGN: &[(&str, &str)] = &[
    ("TON", "the timer as a coil with its preset: LD X0 / OUT T0 K20 (T0–T199 count 100 ms)"),
    ("TOF", "an off-delay with a timer coil and LDI: LDI X0 / OUT T0 K20 (T0–T199 count 100 ms)"),
    ("TONR", "a retentive timer coil: OUT T250 K20 (T250–T255 keep their value; RST T250 clears it)"),
    ("TP", "a pulse from a timer coil: OUT T0 K20 with its contact (T0–T199 count 100 ms)"),
    ("CTU", "the counter as a coil with its preset: LD X0 / OUT C0 K10 (RST C0 clears it)"),
    ("CTD", "a down count with a 32-bit counter: OUT C200 K10 with M8200 on"),
    ("=", "OUT Y0"),
    ("ST", "OUT Y0"),
    ("LDN", "LDI X0"),
    ("AN", "ANI X0"),
    ("ANDN", "ANI X0"),
    ("A", "AND X0"),
    ("O", "OR X0"),
    ("ON", "ORI X0"),
    ("ORN", "ORI X0"),
    ("ALD", "ANB"),
    ("OLD", "ORB"),
    ("LPS", "MPS"),
    ("LRD", "MRD"),
    ("LPP", "MPP"),
    ("NOT", "INV"),
    ("S", "SET Y0"),
    ("R", "RST Y0"),
    ("MOVW", "MOV K5 D0"),
    ("MOVB", "MOV K5 D0"),
    ("MOVD", "DMOV K5 D0"),
];

fn suggest(m: &str) -> Option<&'static str> {
    fn dist(a: &str, b: &str) -> usize {
        let (a, b): (Vec<char>, Vec<char>) = (a.chars().collect(), b.chars().collect());
        let mut prev: Vec<usize> = (0..=b.len()).collect();
        for (i, ca) in a.iter().enumerate() {
            let mut cur = vec![i + 1; b.len() + 1];
            for (j, cb) in b.iter().enumerate() {
                cur[j + 1] = (prev[j] + (ca != cb) as usize).min(prev[j + 1] + 1).min(cur[j] + 1);
            }
            prev = cur;
        }
        prev[b.len()]
    }
    if m.chars().count() > 16 {
        return None;
    }
    INSTRUCTIONS
        .iter()
        .filter(|d| !crate::engine::isa::NEVER_SUGGESTED.contains(&d.name))
        .map(|d| (dist(m, d.name), d.name))
        .filter(|(d, _)| *d <= 2)
        .min()
        .map(|(_, n)| n)
}

/// Translates an FX list (named `file` in messages) into engine IL.
pub fn translate(text: &str, file: &str, model: &'static Model) -> Result<Translation> {
    translate_with(text, file, model, None)
}

/// An operand of a list with symbols as the FX grammar reads it: a tag's address (the tag's
/// position kept, so errors name the symbol's place); a word that is neither a tag, a
/// constant nor an FX operand, and reads as a name, is an unknown symbol naming the nearest
/// tags ([`engine::symbols::unknown_symbol`]).
fn symbol(file: &str, tags: &crate::tags::TagTable, (t, p): &mut (String, Pos)) -> Result<()> {
    if let Some(tag) = tags.get(t) {
        *t = tag.address.clone();
    } else if constant(t).is_none() {
        if let Err(e) = operand::parse_one(t) {
            let e = engine::symbols::unknown_symbol(
                tags,
                t,
                OperandError { message: e.message.clone(), hint: e.hint.clone() },
            );
            let mut x = load_err(file, *p, e.message);
            if let Some(h) = e.hint {
                x = x.hint(h);
            }
            return Err(x);
        }
    }
    Ok(())
}

/// [`translate`] for a list with symbols: `tags` (the program's `VAR_GLOBAL` block and a tag
/// file beside it, [`engine::symbols::declarations`]) name its operands.
pub fn translate_with(
    text: &str,
    file: &str,
    model: &'static Model,
    tags: Option<&crate::tags::TagTable>,
) -> Result<Translation> {
    let stmts = source::parse(text).map_err(|e| load_err(file, e.pos, e.message))?;
    let mut b = Builder { file, model, lines: Vec::new() };
    for s in stmts {
        let Stmt::Instr { mnemonic, operands, pos } = s else {
            let p = match s {
                Stmt::Pou { pos, .. } | Stmt::EndPou { pos } | Stmt::Label { pos, .. } | Stmt::Network { pos, .. } => {
                    pos
                }
                Stmt::Instr { pos, .. } => pos,
            };
            if matches!(s, Stmt::Network { .. }) {
                continue;
            }
            return Err(load_err(file, p, "FX lists have no labels or program blocks here")
                .hint("write one instruction per line: LD X0 / OUT Y0 … END"));
        };
        let mut ops = split_operands(&operands);
        // A step number in front (`0 LD X000`, as list exports print it) is skipped.
        let (m, at) = if mnemonic.bytes().all(|c| c.is_ascii_digit()) && !ops.is_empty() {
            let (m, p) = ops.remove(0);
            (m.to_ascii_uppercase(), p)
        } else {
            (mnemonic, pos)
        };
        if let Some(tags) = tags {
            for op in ops.iter_mut() {
                symbol(file, tags, op)?;
            }
        }
        if !b.statement(&m, &ops, at)? {
            break;
        }
    }
    let text = b.lines.iter().map(|e| e.text.as_str()).collect::<Vec<_>>().join("\n");
    Ok(Translation { text, lines: b.lines })
}

// ----- the engine family -----

/// Loc area byte: the FX area code, with a group's digit count in the high nibble.
fn loc_of(o: &FxOperand) -> Loc {
    let n = o.index as u32;
    match o.width {
        FxWidth::Bit => Loc { area: o.area as u8, width: Width::Bit((n % 8) as u8), index: n / 8 },
        FxWidth::Group(k) => Loc {
            area: o.area as u8 | k << 4,
            width: if o.view.bits() == 32 { Width::DWord } else { Width::Word },
            index: n,
        },
        FxWidth::Word => Loc { area: o.area as u8, width: Width::Word, index: 2 * n },
        FxWidth::Pair => Loc { area: o.area as u8, width: Width::DWord, index: 2 * n },
    }
}

/// The area and device number of a location (groups: the digit count too).
pub(super) fn decode(l: Loc) -> Option<(Area, u16, u8)> {
    let area = *operand::AREAS.get((l.area & 0x0F) as usize).map(|s| &s.area)?;
    let groups = l.area >> 4;
    let n = match l.width {
        Width::Bit(b) => l.index * 8 + b as u32,
        _ if groups > 0 => l.index,
        _ => l.index / 2,
    };
    u16::try_from(n).ok().map(|n| (area, n, groups))
}

/// Default costs (estimates: FX2N basic instructions 0.08 µs each, applied instructions from
/// 1.52 µs — FX2N hardware specification; END processing 0.5 ms is plcsh's estimate). The
/// watchdog is D8000's default, 200 ms (FX PM, D8000).
pub fn costs() -> CostTable {
    CostTable {
        // bit, compare, move, arith, real, timer, jump, call, special (OUT T/C, RST)
        class_ns: [80, 1_520, 1_520, 1_520, 10_000, 160, 80, 1_000, 160],
        per_element_ns: 100,
        overhead_ns: 500_000,
        min_scan_ns: 0,
        watchdog_ns: 200_000_000,
    }
}

/// The FX operand space as the engine sees it.
pub struct FxFamily {
    pub model: &'static Model,
}

impl FxFamily {
    fn resolve(&self, text: &str) -> std::result::Result<FxOperand, OperandError> {
        let o = operand::parse_one(text).map_err(|e| {
            let mut x = OperandError::new(e.message.clone());
            x.hint = e.hint.clone();
            x
        })?;
        let space = FxSpace::new(self.model, Proto::Port);
        let last = o.index as u32 + o.span() as u32 - 1;
        if last > u16::MAX as u32 || !space.exists(o.area, o.index) || !space.exists(o.area, last as u16) {
            return Err(OperandError::new(format!("{} is not on an {}", o.canonical(), self.model.name))
                .hint(self.model.summary));
        }
        Ok(o)
    }
}

impl Family for FxFamily {
    fn operand(&self, text: &str) -> std::result::Result<Resolved, OperandError> {
        let o = self.resolve(text)?;
        Ok(Resolved { loc: loc_of(&o), ty: o.view, canonical: o.canonical() })
    }

    fn element(&self, text: &str, _want_timer: bool) -> std::result::Result<Element, OperandError> {
        Err(OperandError::new(format!("{text}: FX timers and counters are driven by OUT"))
            .hint("OUT T0 K50 (timer), OUT C0 K10 (counter), RST T0 / RST C0"))
    }

    fn pointer(&self, _loc: Loc) -> Option<u32> {
        None
    }

    fn specials(&self) -> &'static [SpecialDef] {
        SPECIALS
    }

    fn costs(&self) -> CostTable {
        costs()
    }

    fn events(&self) -> u32 {
        0
    }
}

/// A program loaded into the simulated PLC.
#[derive(Clone, Debug)]
pub struct Loaded {
    pub prog: Program,
    pub cpu: Cpu,
    /// The file it came from, and the FX instructions it has.
    pub source: String,
    pub instructions: usize,
    /// The FX list as loaded (a snapshot stores it and compiles it again).
    pub text: String,
}

impl Loaded {
    /// Translates and compiles FX list `text` (named `file` in messages) for `model`.
    pub fn load(text: &str, file: &str, model: &'static Model) -> Result<Loaded> {
        Loaded::load_with_tags(text, file, model, None)
    }

    /// [`Loaded::load`] for a list with symbols: the names of its `VAR_GLOBAL` block and of
    /// `tags` (a tag file beside it) stand for their addresses, as the K2's and the UMPK's
    /// loaders read them ([`engine::symbols`]). The list is kept with the tag file's tags
    /// appended as a `VAR_GLOBAL` block after its last line, so a snapshot loads it without
    /// the file and its line numbers stay.
    pub fn load_with_tags(
        text: &str,
        file: &str,
        model: &'static Model,
        tags: Option<&crate::tags::TagTable>,
    ) -> Result<Loaded> {
        let fam = FxFamily { model };
        let address = |a: &str| fam.resolve(a).map(|_| ()).map_err(|e| e.message);
        let declared = engine::symbols::declarations(text, file, tags, &address)?;
        let (list, symbols) = match &declared {
            Some((list, table)) => (list.as_ref(), Some(table).filter(|t| !t.is_empty())),
            None => (text, None),
        };
        let kept = match tags {
            Some(t) if !t.is_empty() => {
                format!("{text}\n{}", crate::tags::export::to_iec(t, &FxSpace::new(model, Proto::Port))?)
            }
            _ => text.to_string(),
        };
        // Refusals quote the list's text: its control characters are written out.
        let tr = translate_with(list, file, model, symbols).map_err(crate::core::encoding::printable_error)?;
        let mut prog = engine::compile(&tr.text, file, &fam).map_err(|e| tr.remap(file, e))?;
        // Listings and faults name the FX source line.
        for p in prog.pos.iter_mut() {
            if p.line > 0 {
                *p = tr.origin(p.line, 0);
            }
        }
        let instructions = {
            let mut seen: Vec<Pos> = tr.lines.iter().map(|e| e.at).collect();
            seen.dedup();
            seen.len()
        };
        let cpu = Cpu::new(&prog);
        let name = std::path::Path::new(file).file_name().map_or(file.into(), |n| n.to_string_lossy().into_owned());
        Ok(Loaded { prog, cpu, source: name, instructions, text: kept })
    }

    /// STOP → RUN: edge memories and the engine's state start afresh.
    pub fn reset(&mut self) {
        self.cpu = Cpu::new(&self.prog);
    }
}
