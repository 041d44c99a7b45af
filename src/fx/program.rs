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
use crate::core::msg::{Lang, Msg};
use crate::core::{DataType, Error, ErrorKind, Result};
use crate::engine::source::{self, Pos, Stmt};
use crate::engine::{
    self, ArgKind, CostTable, Cpu, Element, Family, Loc, OperandError, Program, Resolved, SpecialDef, Width,
};
use crate::msg;

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
    /// What it does (catalogue `tables.ftl`, ids `tbl-fx-…`; `docs/il.md` takes the English).
    pub doc: fn(Lang) -> Msg,
    pub source: &'static str,
}

const fn fx(name: &'static str, operands: (u8, u8), kind: FxKind, doc: fn(Lang) -> Msg, source: &'static str) -> FxDef {
    FxDef { name, operands, kind, doc, source }
}

use FxKind as K;

/// The FX instruction subset plcsh runs. Sources: FX PM chapter 2 (basic instructions, by
/// section title) and chapter 5 (applied instructions, by FNC number).
pub static INSTRUCTIONS: &[FxDef] = &[
    fx("LD", (1, 1), K::Contact("LD"), |l| msg!(lang: l, "tbl-fx-ld"), "FX PM 2, Load"),
    fx("LDI", (1, 1), K::Contact("LDN"), |l| msg!(lang: l, "tbl-fx-ldi"), "FX PM 2, Load Inverse"),
    fx(
        "LDP",
        (1, 1),
        K::EdgeContact { rising: true, combine: None },
        |l| msg!(lang: l, "tbl-fx-ldp"),
        "FX PM 2, Load Pulse",
    ),
    fx(
        "LDF",
        (1, 1),
        K::EdgeContact { rising: false, combine: None },
        |l| msg!(lang: l, "tbl-fx-ldf"),
        "FX PM 2, Load Trailing Pulse",
    ),
    fx("AND", (1, 1), K::Contact("AND"), |l| msg!(lang: l, "tbl-fx-and"), "FX PM 2, And"),
    fx("ANI", (1, 1), K::Contact("ANDN"), |l| msg!(lang: l, "tbl-fx-ani"), "FX PM 2, And Inverse"),
    fx(
        "ANDP",
        (1, 1),
        K::EdgeContact { rising: true, combine: Some("ALD") },
        |l| msg!(lang: l, "tbl-fx-andp"),
        "FX PM 2, And Pulse",
    ),
    fx(
        "ANDF",
        (1, 1),
        K::EdgeContact { rising: false, combine: Some("ALD") },
        |l| msg!(lang: l, "tbl-fx-andf"),
        "FX PM 2, And Trailing Pulse",
    ),
    fx("OR", (1, 1), K::Contact("OR"), |l| msg!(lang: l, "tbl-fx-or"), "FX PM 2, Or"),
    fx("ORI", (1, 1), K::Contact("ORN"), |l| msg!(lang: l, "tbl-fx-ori"), "FX PM 2, Or Inverse"),
    fx(
        "ORP",
        (1, 1),
        K::EdgeContact { rising: true, combine: Some("OLD") },
        |l| msg!(lang: l, "tbl-fx-orp"),
        "FX PM 2, Or Pulse",
    ),
    fx(
        "ORF",
        (1, 1),
        K::EdgeContact { rising: false, combine: Some("OLD") },
        |l| msg!(lang: l, "tbl-fx-orf"),
        "FX PM 2, Or Trailing Pulse",
    ),
    fx("ANB", (0, 0), K::Plain("ALD"), |l| msg!(lang: l, "tbl-fx-anb"), "FX PM 2, And Block"),
    fx("ORB", (0, 0), K::Plain("OLD"), |l| msg!(lang: l, "tbl-fx-orb"), "FX PM 2, Or Block"),
    fx("MPS", (0, 0), K::Plain("LPS"), |l| msg!(lang: l, "tbl-fx-mps"), "FX PM 2, MPS, MRD and MPP"),
    fx("MRD", (0, 0), K::Plain("LRD"), |l| msg!(lang: l, "tbl-fx-mrd"), "FX PM 2, MPS, MRD and MPP"),
    fx("MPP", (0, 0), K::Plain("LPP"), |l| msg!(lang: l, "tbl-fx-mpp"), "FX PM 2, MPS, MRD and MPP"),
    fx("INV", (0, 0), K::Plain("NOT"), |l| msg!(lang: l, "tbl-fx-inv"), "FX PM 2, Inverse"),
    fx("OUT", (1, 2), K::Out, |l| msg!(lang: l, "tbl-fx-out"), "FX PM 2, Out; Timer, Counter (Out & Reset)"),
    fx("SET", (1, 1), K::Set, |l| msg!(lang: l, "tbl-fx-set"), "FX PM 2, Set and Reset"),
    fx("RST", (1, 1), K::Rst, |l| msg!(lang: l, "tbl-fx-rst"), "FX PM 2, Set and Reset; Timer, Counter (Out & Reset)"),
    fx("PLS", (1, 1), K::Pulse { rising: true }, |l| msg!(lang: l, "tbl-fx-pls"), "FX PM 2, Pulse (PLS, PLF)"),
    fx("PLF", (1, 1), K::Pulse { rising: false }, |l| msg!(lang: l, "tbl-fx-plf"), "FX PM 2, Pulse (PLS, PLF)"),
    fx(
        "MOV",
        (2, 2),
        K::Applied { engine: "MOVE", wide: false, pulse: false },
        |l| msg!(lang: l, "tbl-fx-mov"),
        "FX PM 5, FNC 12 MOV",
    ),
    fx(
        "MOVP",
        (2, 2),
        K::Applied { engine: "MOVE", wide: false, pulse: true },
        |l| msg!(lang: l, "tbl-fx-movp"),
        "FX PM 5, FNC 12 MOV",
    ),
    fx(
        "DMOV",
        (2, 2),
        K::Applied { engine: "MOVD", wide: true, pulse: false },
        |l| msg!(lang: l, "tbl-fx-dmov"),
        "FX PM 5, FNC 12 MOV",
    ),
    fx(
        "DMOVP",
        (2, 2),
        K::Applied { engine: "MOVD", wide: true, pulse: true },
        |l| msg!(lang: l, "tbl-fx-dmovp"),
        "FX PM 5, FNC 12 MOV",
    ),
    fx(
        "ADD",
        (3, 3),
        K::Applied { engine: "ADD", wide: false, pulse: false },
        |l| msg!(lang: l, "tbl-fx-add"),
        "FX PM 5, FNC 20 ADD",
    ),
    fx(
        "ADDP",
        (3, 3),
        K::Applied { engine: "ADD", wide: false, pulse: true },
        |l| msg!(lang: l, "tbl-fx-addp"),
        "FX PM 5, FNC 20 ADD",
    ),
    fx(
        "DADD",
        (3, 3),
        K::Applied { engine: "ADD", wide: true, pulse: false },
        |l| msg!(lang: l, "tbl-fx-dadd"),
        "FX PM 5, FNC 20 ADD",
    ),
    fx(
        "SUB",
        (3, 3),
        K::Applied { engine: "SUB", wide: false, pulse: false },
        |l| msg!(lang: l, "tbl-fx-sub"),
        "FX PM 5, FNC 21 SUB",
    ),
    fx(
        "SUBP",
        (3, 3),
        K::Applied { engine: "SUB", wide: false, pulse: true },
        |l| msg!(lang: l, "tbl-fx-subp"),
        "FX PM 5, FNC 21 SUB",
    ),
    fx(
        "DSUB",
        (3, 3),
        K::Applied { engine: "SUB", wide: true, pulse: false },
        |l| msg!(lang: l, "tbl-fx-dsub"),
        "FX PM 5, FNC 21 SUB",
    ),
    fx(
        "INC",
        (1, 1),
        K::Applied { engine: "INC", wide: false, pulse: false },
        |l| msg!(lang: l, "tbl-fx-inc"),
        "FX PM 5, FNC 24 INC",
    ),
    fx(
        "INCP",
        (1, 1),
        K::Applied { engine: "INC", wide: false, pulse: true },
        |l| msg!(lang: l, "tbl-fx-incp"),
        "FX PM 5, FNC 24 INC",
    ),
    fx(
        "DEC",
        (1, 1),
        K::Applied { engine: "DEC", wide: false, pulse: false },
        |l| msg!(lang: l, "tbl-fx-dec"),
        "FX PM 5, FNC 25 DEC",
    ),
    fx(
        "DECP",
        (1, 1),
        K::Applied { engine: "DEC", wide: false, pulse: true },
        |l| msg!(lang: l, "tbl-fx-decp"),
        "FX PM 5, FNC 25 DEC",
    ),
    fx(
        "LD=",
        (2, 2),
        K::Compare { engine: "LDW=", wide: false },
        |l| msg!(lang: l, "tbl-fx-ld-eq"),
        "FX PM 5, FNC 224–230 LD□",
    ),
    fx(
        "LD>",
        (2, 2),
        K::Compare { engine: "LDW>", wide: false },
        |l| msg!(lang: l, "tbl-fx-ld-gt"),
        "FX PM 5, FNC 224–230 LD□",
    ),
    fx(
        "LD<",
        (2, 2),
        K::Compare { engine: "LDW<", wide: false },
        |l| msg!(lang: l, "tbl-fx-ld-lt"),
        "FX PM 5, FNC 224–230 LD□",
    ),
    fx(
        "LD<>",
        (2, 2),
        K::Compare { engine: "LDW<>", wide: false },
        |l| msg!(lang: l, "tbl-fx-ld-ne"),
        "FX PM 5, FNC 224–230 LD□",
    ),
    fx(
        "LD<=",
        (2, 2),
        K::Compare { engine: "LDW<=", wide: false },
        |l| msg!(lang: l, "tbl-fx-ld-le"),
        "FX PM 5, FNC 224–230 LD□",
    ),
    fx(
        "LD>=",
        (2, 2),
        K::Compare { engine: "LDW>=", wide: false },
        |l| msg!(lang: l, "tbl-fx-ld-ge"),
        "FX PM 5, FNC 224–230 LD□",
    ),
    fx(
        "AND=",
        (2, 2),
        K::Compare { engine: "AW=", wide: false },
        |l| msg!(lang: l, "tbl-fx-and-eq"),
        "FX PM 5, FNC 232–238 AND□",
    ),
    fx(
        "AND>",
        (2, 2),
        K::Compare { engine: "AW>", wide: false },
        |l| msg!(lang: l, "tbl-fx-and-gt"),
        "FX PM 5, FNC 232–238 AND□",
    ),
    fx(
        "AND<",
        (2, 2),
        K::Compare { engine: "AW<", wide: false },
        |l| msg!(lang: l, "tbl-fx-and-lt"),
        "FX PM 5, FNC 232–238 AND□",
    ),
    fx(
        "AND<>",
        (2, 2),
        K::Compare { engine: "AW<>", wide: false },
        |l| msg!(lang: l, "tbl-fx-and-ne"),
        "FX PM 5, FNC 232–238 AND□",
    ),
    fx(
        "AND<=",
        (2, 2),
        K::Compare { engine: "AW<=", wide: false },
        |l| msg!(lang: l, "tbl-fx-and-le"),
        "FX PM 5, FNC 232–238 AND□",
    ),
    fx(
        "AND>=",
        (2, 2),
        K::Compare { engine: "AW>=", wide: false },
        |l| msg!(lang: l, "tbl-fx-and-ge"),
        "FX PM 5, FNC 232–238 AND□",
    ),
    fx(
        "OR=",
        (2, 2),
        K::Compare { engine: "OW=", wide: false },
        |l| msg!(lang: l, "tbl-fx-or-eq"),
        "FX PM 5, FNC 240–246 OR□",
    ),
    fx(
        "OR>",
        (2, 2),
        K::Compare { engine: "OW>", wide: false },
        |l| msg!(lang: l, "tbl-fx-or-gt"),
        "FX PM 5, FNC 240–246 OR□",
    ),
    fx(
        "OR<",
        (2, 2),
        K::Compare { engine: "OW<", wide: false },
        |l| msg!(lang: l, "tbl-fx-or-lt"),
        "FX PM 5, FNC 240–246 OR□",
    ),
    fx(
        "OR<>",
        (2, 2),
        K::Compare { engine: "OW<>", wide: false },
        |l| msg!(lang: l, "tbl-fx-or-ne"),
        "FX PM 5, FNC 240–246 OR□",
    ),
    fx(
        "OR<=",
        (2, 2),
        K::Compare { engine: "OW<=", wide: false },
        |l| msg!(lang: l, "tbl-fx-or-le"),
        "FX PM 5, FNC 240–246 OR□",
    ),
    fx(
        "OR>=",
        (2, 2),
        K::Compare { engine: "OW>=", wide: false },
        |l| msg!(lang: l, "tbl-fx-or-ge"),
        "FX PM 5, FNC 240–246 OR□",
    ),
    fx(
        "LDD=",
        (2, 2),
        K::Compare { engine: "LDD=", wide: true },
        |l| msg!(lang: l, "tbl-fx-ldd-eq"),
        "FX PM 5, FNC 224 LD=",
    ),
    fx(
        "LDD>",
        (2, 2),
        K::Compare { engine: "LDD>", wide: true },
        |l| msg!(lang: l, "tbl-fx-ldd-gt"),
        "FX PM 5, FNC 225 LD>",
    ),
    fx(
        "LDD<",
        (2, 2),
        K::Compare { engine: "LDD<", wide: true },
        |l| msg!(lang: l, "tbl-fx-ldd-lt"),
        "FX PM 5, FNC 226 LD<",
    ),
    fx(
        "ANDD=",
        (2, 2),
        K::Compare { engine: "AD=", wide: true },
        |l| msg!(lang: l, "tbl-fx-andd-eq"),
        "FX PM 5, FNC 232 AND=",
    ),
    fx(
        "ORD=",
        (2, 2),
        K::Compare { engine: "OD=", wide: true },
        |l| msg!(lang: l, "tbl-fx-ord-eq"),
        "FX PM 5, FNC 240 OR=",
    ),
    fx("NOP", (0, 0), K::Plain("NOP"), |l| msg!(lang: l, "tbl-fx-nop"), "FX PM 2, No Operation"),
    fx("END", (0, 0), K::End, |l| msg!(lang: l, "tbl-fx-end"), "FX PM 2, End"),
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
        s.push_str(&format!("| `{}` (FX) | {ops} | {} | {} |\n", d.name, (d.doc)(Lang::En), d.source));
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
        doc: |l| msg!(lang: l, "engine-doc-fx-fxtim"),
        source: "FX PM 2, Out; 4, Timers",
    },
    SpecialDef {
        name: "FXCNT",
        id: id::COUNTER,
        args: &[ArgKind::Bit, ArgKind::Value(Some(DataType::Int))],
        optional: 0,
        edge: false,
        doc: |l| msg!(lang: l, "engine-doc-fx-fxcnt"),
        source: "FX PM 2, Out; 4, Counters",
    },
    SpecialDef {
        name: "FXCNT32",
        id: id::COUNTER32,
        args: &[ArgKind::Bit, ArgKind::Value(Some(DataType::DInt))],
        optional: 0,
        edge: false,
        doc: |l| msg!(lang: l, "engine-doc-fx-fxcnt32"),
        source: "FX PM 2, Out; 4, Counters",
    },
    SpecialDef {
        name: "FXRST",
        id: id::RESET,
        args: &[ArgKind::Value(None)],
        optional: 0,
        edge: false,
        doc: |l| msg!(lang: l, "engine-doc-fx-fxrst"),
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

/// A load error at `file:line:col:` whose text another part already wrote (an operand's or
/// the IL reader's refusal).
fn load_err_text(file: &str, p: Pos, text: String) -> Error {
    Error::new(ErrorKind::Syntax, format!("{file}:{}:{}: {text}", p.line, p.col))
}

/// A load error at `file:line:col:`, keeping the message's id as the error's code.
fn load_err(file: &str, p: Pos, m: Msg) -> Error {
    let text = format!("{file}:{}:{}: {}", p.line, p.col, m.text);
    Error::new(ErrorKind::Syntax, Msg { text, ..m })
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
            let mut x = load_err_text(self.file, p, format!("{t}: {}", e.message));
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
                return Err(load_err(self.file, at, msg!("tbl-fx-unknown", m = m)).hint(msg!(
                    "tbl-fx-foreign-hint",
                    m = m,
                    how = how().text
                )));
            }
            let near = suggest(m);
            let mut e = load_err(self.file, at, msg!("tbl-fx-unknown", m = m));
            e = e.hint(match near {
                Some(n) => msg!("tbl-fx-unknown-near", near = n),
                None => msg!("tbl-fx-unknown-hint"),
            });
            return Err(e);
        };
        let (lo, hi) = def.operands;
        if ops.len() < lo as usize || ops.len() > hi as usize {
            let found = ops.len();
            return Err(load_err(
                self.file,
                at,
                if lo == hi {
                    msg!("tbl-fx-operand-count", m = m, want = lo, found = found)
                } else {
                    msg!("tbl-fx-operand-range", m = m, lo = lo, hi = hi, found = found)
                },
            ));
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
                            return Err(load_err(self.file, at, msg!("tbl-fx-needs-preset", t = t.as_str())));
                        };
                        if constant(k).is_none() && !k.to_ascii_uppercase().starts_with('D') {
                            return Err(load_err(self.file, *kp, msg!("tbl-fx-bad-preset", k = k.as_str())));
                        }
                        let n = o.index;
                        let special = if timer {
                            "FXTIM"
                        } else if n < C32_FIRST {
                            "FXCNT"
                        } else if n <= C32_LAST {
                            "FXCNT32"
                        } else {
                            return Err(load_err(self.file, *p, msg!("tbl-fx-hsc-not-simulated", t = t.as_str()))
                                .hint(msg!("tbl-fx-hsc-not-simulated-hint")));
                        };
                        let wide = special == "FXCNT32";
                        self.emit(at, special, &[(o.canonical(), *p), (value_text(k, wide), *kp)]);
                    }
                    _ => {
                        if ops.len() > 1 {
                            return Err(load_err(self.file, ops[1].1, msg!("tbl-fx-out-one-operand", t = t.as_str())));
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
                    _ => return Err(load_err(self.file, *p, msg!("tbl-fx-rst-target", t = t.as_str()))),
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
                        return Err(load_err(self.file, *p, msg!("tbl-fx-input-written", m = m, t = t.as_str()))
                            .hint(msg!("tbl-fx-input-written-hint")));
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
            return Err(
                load_err(self.file, p, msg!("tbl-fx-coil-target", m = m, t = t)).hint(msg!("tbl-fx-coil-target-hint"))
            );
        }
        if operand::system_driven(o.area, o.index) {
            return Err(load_err(self.file, p, msg!("tbl-fx-system-driven", m = m, t = t, operand = o.canonical())));
        }
        if !FxSpace::new(self.model, Proto::Port).exists(o.area, o.index) {
            return Err(load_err(self.file, p, msg!("tbl-fx-not-on-model", t = t, model = self.model.name)));
        }
        Ok(())
    }
}

/// Mnemonics of the K2's and IEC 61131-3 instruction lists that an FX writes otherwise, with
/// the FX form (FX PM 2 and 4: timers and counters are coils with a preset).
#[allow(clippy::type_complexity)] // one row: mnemonic, the FX way to write it
const FOREIGN: &[(&str, fn() -> Msg)] = &[
    ("TON", || msg!("tbl-fx-foreign-ton")),
    ("TOF", || msg!("tbl-fx-foreign-tof")),
    ("TONR", || msg!("tbl-fx-foreign-tonr")),
    ("TP", || msg!("tbl-fx-foreign-tp")),
    ("CTU", || msg!("tbl-fx-foreign-ctu")),
    ("CTD", || msg!("tbl-fx-foreign-ctd")),
    ("=", || msg!("tbl-fx-foreign-code", code = "OUT Y0")),
    ("ST", || msg!("tbl-fx-foreign-code", code = "OUT Y0")),
    ("LDN", || msg!("tbl-fx-foreign-code", code = "LDI X0")),
    ("AN", || msg!("tbl-fx-foreign-code", code = "ANI X0")),
    ("ANDN", || msg!("tbl-fx-foreign-code", code = "ANI X0")),
    ("A", || msg!("tbl-fx-foreign-code", code = "AND X0")),
    ("O", || msg!("tbl-fx-foreign-code", code = "OR X0")),
    ("ON", || msg!("tbl-fx-foreign-code", code = "ORI X0")),
    ("ORN", || msg!("tbl-fx-foreign-code", code = "ORI X0")),
    ("ALD", || msg!("tbl-fx-foreign-code", code = "ANB")),
    ("OLD", || msg!("tbl-fx-foreign-code", code = "ORB")),
    ("LPS", || msg!("tbl-fx-foreign-code", code = "MPS")),
    ("LRD", || msg!("tbl-fx-foreign-code", code = "MRD")),
    ("LPP", || msg!("tbl-fx-foreign-code", code = "MPP")),
    ("NOT", || msg!("tbl-fx-foreign-code", code = "INV")),
    ("S", || msg!("tbl-fx-foreign-code", code = "SET Y0")),
    ("R", || msg!("tbl-fx-foreign-code", code = "RST Y0")),
    ("MOVW", || msg!("tbl-fx-foreign-code", code = "MOV K5 D0")),
    ("MOVB", || msg!("tbl-fx-foreign-code", code = "MOV K5 D0")),
    ("MOVD", || msg!("tbl-fx-foreign-code", code = "DMOV K5 D0")),
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
            let mut x = load_err_text(file, *p, e.message);
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
    let stmts = source::parse(text).map_err(|e| load_err_text(file, e.pos, e.message))?;
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
            return Err(load_err(file, p, msg!("tbl-fx-no-blocks")).hint(msg!("tbl-fx-no-blocks-hint")));
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
            return Err(OperandError::new(
                msg!("tbl-fx-not-on-model", t = o.canonical(), model = self.model.name).text,
            )
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
        Err(OperandError::new(msg!("tbl-fx-element-by-out", text = text).text)
            .hint(msg!("tbl-fx-element-by-out-hint").text))
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

#[cfg(test)]
mod table_tests {
    use super::*;

    /// Every instruction's description and every foreign mnemonic's FX form is in every
    /// language, and every `tbl-fx-…` id of the catalogue belongs to a row or is one of the
    /// load errors above.
    #[test]
    fn every_row_has_its_text_in_every_language() {
        let mut used: Vec<&str> = INSTRUCTIONS.iter().map(|d| (d.doc)(Lang::En).id).collect();
        used.extend(FOREIGN.iter().map(|(_, how)| how().id));
        for lang in Lang::ALL {
            let ids = crate::core::msg::ids(*lang);
            for id in &used {
                assert!(ids.iter().any(|i| i == id), "{id} has no text in {}", lang.tag());
            }
        }
        let errors = [
            "tbl-fx-unknown",
            "tbl-fx-foreign-hint",
            "tbl-fx-unknown-near",
            "tbl-fx-unknown-hint",
            "tbl-fx-operand-count",
            "tbl-fx-operand-range",
            "tbl-fx-needs-preset",
            "tbl-fx-bad-preset",
            "tbl-fx-hsc-not-simulated",
            "tbl-fx-hsc-not-simulated-hint",
            "tbl-fx-out-one-operand",
            "tbl-fx-rst-target",
            "tbl-fx-input-written",
            "tbl-fx-input-written-hint",
            "tbl-fx-coil-target",
            "tbl-fx-coil-target-hint",
            "tbl-fx-system-driven",
            "tbl-fx-not-on-model",
            "tbl-fx-no-blocks",
            "tbl-fx-no-blocks-hint",
            "tbl-fx-element-by-out",
            "tbl-fx-element-by-out-hint",
        ];
        for id in crate::core::msg::ids(Lang::En) {
            if id.starts_with("tbl-fx-") {
                assert!(used.contains(&id.as_str()) || errors.contains(&id.as_str()), "{id} belongs to no row");
            }
        }
        assert_eq!((lookup("LDI").unwrap().doc)(Lang::Ru).text, "начать блок нормально закрытым контактом");
    }
}
