//! The instruction table: every mnemonic the engine accepts, what it does, its cost class
//! and the source it follows — one data table, from which the compiler, the "did you mean"
//! suggestions and `docs/il.md` are derived.
//!
//! Sources: the K2 manual (`../shared/seeds/000_…`, "K2"), the MASTER-K/K80S CPU chapter
//! (`../shared/seeds/001_…`, "K80S"), and where neither defines an instruction IEC
//! 61131-3 IL ("IEC") or the S7-200 convention the K2 follows for its memory map and
//! KincoBuilder for its IL ("S7-200").

use crate::core::msg::{Lang, Msg};
use crate::msg;

/// Bit-logic operations on the current result (CR).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Logic {
    And,
    Or,
    Xor,
}

/// Comparison operators.
#[derive(Clone, Copy, Debug, PartialEq, Eq, serde::Serialize, serde::Deserialize)]
pub enum Cmp {
    Eq,
    Ne,
    Lt,
    Gt,
    Le,
    Ge,
}

/// How a comparison's result combines with the CR: load (push), AND, OR.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Comb {
    Ld,
    And,
    Or,
}

/// The type a typed mnemonic fixes (`LDW=` INT, `LDD=` DINT, `LDR=` REAL, `LDB=` BYTE).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum TyHint {
    Byte,
    Int,
    DInt,
    Real,
    /// From the operands (IEC overloading).
    Auto,
}

#[derive(Clone, Copy, Debug, PartialEq, Eq, serde::Serialize, serde::Deserialize)]
pub enum Arith {
    Add,
    Sub,
    Mul,
    Div,
    Mod,
}

/// One-operand numeric functions: OUT := f(IN).
#[derive(Clone, Copy, Debug, PartialEq, Eq, serde::Serialize, serde::Deserialize)]
pub enum Unary {
    /// Square root (REAL).
    Sqrt,
    /// Absolute value (INT, DINT, REAL).
    Abs,
}

#[derive(Clone, Copy, Debug, PartialEq, Eq, serde::Serialize, serde::Deserialize)]
pub enum Shift {
    Shl,
    Shr,
    Rol,
    Ror,
}

#[derive(Clone, Copy, Debug, PartialEq, Eq, serde::Serialize, serde::Deserialize)]
pub enum Conv {
    /// INT → DINT (sign-extends).
    IDi,
    /// DINT → INT (fault-free: ENO = 0 when out of range, destination unchanged).
    DiI,
    /// BYTE → INT.
    BI,
    /// INT → BYTE (ENO = 0 when out of range).
    IB,
    /// DINT → REAL.
    DiR,
    /// REAL → DINT, rounded to nearest.
    Round,
    /// REAL → DINT, truncated.
    Trunc,
    /// INT → BCD (0…9999).
    IBcd,
    /// BCD → INT.
    BcdI,
}

/// Timer kinds: K2/IEC TON, TOF, TP; MASTER-K TON, TOFF, TMR, TMON, TRTG (K80S).
#[derive(Clone, Copy, Debug, PartialEq, Eq, serde::Serialize, serde::Deserialize)]
pub enum TimerKind {
    /// On-delay (K2, IEC; K80S TON).
    Ton,
    /// Off-delay (K2 TOF, IEC; K80S TOFF).
    Tof,
    /// Pulse (IEC TP).
    Tp,
    /// Accumulating on-delay (K80S TMR; S7-200 TONR).
    Tmr,
    /// Monostable (K80S TMON).
    Tmon,
    /// Retriggerable monostable (K80S TRTG).
    Trtg,
}

#[derive(Clone, Copy, Debug, PartialEq, Eq, serde::Serialize, serde::Deserialize)]
pub enum CounterKind {
    Ctu,
    Ctd,
    Ctud,
    Ctr,
}

/// What a mnemonic does.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Kind {
    /// LD/LDN: push the CR and load a bit.
    Ld {
        neg: bool,
    },
    /// AND/ANDN, OR/ORN, XOR/XORN with a bit operand; with a trailing `(` a parenthesis.
    Logic {
        op: Logic,
        neg: bool,
    },
    ParOpen {
        op: Logic,
        neg: bool,
    },
    ParClose,
    Not,
    St {
        neg: bool,
    },
    Set,
    Reset,
    /// S7-200 logic-stack operations.
    Ald,
    Old,
    Lps,
    Lrd,
    Lpp,
    RTrig,
    FTrig,
    Compare {
        comb: Comb,
        ty: TyHint,
        op: Cmp,
    },
    Move {
        ty: TyHint,
    },
    BlkMove {
        ty: TyHint,
    },
    Fill,
    Arith {
        op: Arith,
        ty: TyHint,
    },
    IncDec {
        inc: bool,
        ty: TyHint,
    },
    Shift {
        op: Shift,
    },
    WordLogic {
        op: Logic,
    },
    Inv,
    Unary(Unary),
    Swap,
    For,
    Next,
    Conv(Conv),
    Jmp,
    Jmpc {
        neg: bool,
    },
    Cal,
    Calc {
        neg: bool,
    },
    Ret,
    Retc {
        neg: bool,
    },
    Timer(TimerKind),
    Counter(CounterKind),
    Atch,
    Dtch,
    Eni,
    Disi,
    Wdt,
    Nop,
}

/// Cost classes: each compiled instruction costs its class's time in the family's table.
#[derive(Clone, Copy, Debug, PartialEq, Eq, serde::Serialize, serde::Deserialize)]
pub enum CostClass {
    Bit,
    Compare,
    Move,
    Arith,
    Real,
    Timer,
    Jump,
    Call,
    Special,
}

impl CostClass {
    pub const ALL: [CostClass; 9] = [
        CostClass::Bit,
        CostClass::Compare,
        CostClass::Move,
        CostClass::Arith,
        CostClass::Real,
        CostClass::Timer,
        CostClass::Jump,
        CostClass::Call,
        CostClass::Special,
    ];
    pub fn name(self) -> &'static str {
        match self {
            CostClass::Bit => "bit",
            CostClass::Compare => "compare",
            CostClass::Move => "move",
            CostClass::Arith => "arith",
            CostClass::Real => "real",
            CostClass::Timer => "timer",
            CostClass::Jump => "jump",
            CostClass::Call => "call",
            CostClass::Special => "special",
        }
    }
}

/// One table row.
#[derive(Clone, Copy, Debug)]
pub struct Def {
    pub name: &'static str,
    pub kind: Kind,
    /// Operand count accepted (min, max).
    pub operands: (u8, u8),
    pub cost: CostClass,
    /// What it does, for `docs/il.md` (in English) and help (catalogue `tables.ftl`, ids `tbl-il-…`).
    pub doc: fn(Lang) -> Msg,
    pub source: &'static str,
}

const fn d(
    name: &'static str,
    kind: Kind,
    operands: (u8, u8),
    cost: CostClass,
    doc: fn(Lang) -> Msg,
    source: &'static str,
) -> Def {
    Def { name, kind, operands, cost, doc, source }
}

use CostClass as C;
use Kind as K;

/// The core instruction set (family instructions come from the family's own table).
#[rustfmt::skip] // one row per line: an edit to a row changes one line
pub static CORE: &[Def] = &[
    d("LD", K::Ld { neg: false }, (1, 1), C::Bit, |l| msg!(lang: l, "tbl-il-ld"), "K2 §3.4.3.1; IEC"),
    d("LDN", K::Ld { neg: true }, (1, 1), C::Bit, |l| msg!(lang: l, "tbl-il-ldn"), "IEC"),
    d("AND", K::Logic { op: Logic::And, neg: false }, (1, 1), C::Bit, |l| msg!(lang: l, "tbl-il-and"), "IEC"),
    d("A", K::Logic { op: Logic::And, neg: false }, (1, 1), C::Bit, |l| msg!(lang: l, "tbl-il-a"), "S7-200"),
    d("ANDN", K::Logic { op: Logic::And, neg: true }, (1, 1), C::Bit, |l| msg!(lang: l, "tbl-il-andn"), "IEC"),
    d("AN", K::Logic { op: Logic::And, neg: true }, (1, 1), C::Bit, |l| msg!(lang: l, "tbl-il-an"), "S7-200"),
    d("OR", K::Logic { op: Logic::Or, neg: false }, (1, 1), C::Bit, |l| msg!(lang: l, "tbl-il-or"), "IEC"),
    d("O", K::Logic { op: Logic::Or, neg: false }, (1, 1), C::Bit, |l| msg!(lang: l, "tbl-il-o"), "S7-200"),
    d("ORN", K::Logic { op: Logic::Or, neg: true }, (1, 1), C::Bit, |l| msg!(lang: l, "tbl-il-orn"), "IEC"),
    d("ON", K::Logic { op: Logic::Or, neg: true }, (1, 1), C::Bit, |l| msg!(lang: l, "tbl-il-on"), "S7-200"),
    d("XOR", K::Logic { op: Logic::Xor, neg: false }, (1, 1), C::Bit, |l| msg!(lang: l, "tbl-il-xor"), "IEC"),
    d("XORN", K::Logic { op: Logic::Xor, neg: true }, (1, 1), C::Bit, |l| msg!(lang: l, "tbl-il-xorn"), "IEC"),
    d("AND(", K::ParOpen { op: Logic::And, neg: false }, (0, 1), C::Bit, |l| msg!(lang: l, "tbl-il-and-paren"), "IEC"),
    d("ANDN(", K::ParOpen { op: Logic::And, neg: true }, (0, 1), C::Bit, |l| msg!(lang: l, "tbl-il-andn-paren"), "IEC"),
    d("OR(", K::ParOpen { op: Logic::Or, neg: false }, (0, 1), C::Bit, |l| msg!(lang: l, "tbl-il-or-paren"), "IEC"),
    d("ORN(", K::ParOpen { op: Logic::Or, neg: true }, (0, 1), C::Bit, |l| msg!(lang: l, "tbl-il-orn-paren"), "IEC"),
    d("XOR(", K::ParOpen { op: Logic::Xor, neg: false }, (0, 1), C::Bit, |l| msg!(lang: l, "tbl-il-xor-paren"), "IEC"),
    d("XORN(", K::ParOpen { op: Logic::Xor, neg: true }, (0, 1), C::Bit, |l| msg!(lang: l, "tbl-il-xorn-paren"), "IEC"),
    d(")", K::ParClose, (0, 0), C::Bit, |l| msg!(lang: l, "tbl-il-close"), "IEC"),
    d("NOT", K::Not, (0, 0), C::Bit, |l| msg!(lang: l, "tbl-il-not"), "IEC"),
    d("ST", K::St { neg: false }, (1, 1), C::Bit, |l| msg!(lang: l, "tbl-il-st"), "K2 §3.4.3.1; IEC"),
    d("=", K::St { neg: false }, (1, 1), C::Bit, |l| msg!(lang: l, "tbl-il-assign"), "S7-200"),
    d("STN", K::St { neg: true }, (1, 1), C::Bit, |l| msg!(lang: l, "tbl-il-stn"), "IEC"),
    d("S", K::Set, (1, 2), C::Bit, |l| msg!(lang: l, "tbl-il-s"), "IEC; S7-200"),
    d(
        "R",
        K::Reset,
        (1, 2),
        C::Bit,
        |l| msg!(lang: l, "tbl-il-r"),
        "IEC; S7-200",
    ),
    d("ALD", K::Ald, (0, 0), C::Bit, |l| msg!(lang: l, "tbl-il-ald"), "S7-200"),
    d("OLD", K::Old, (0, 0), C::Bit, |l| msg!(lang: l, "tbl-il-old"), "S7-200"),
    d("LPS", K::Lps, (0, 0), C::Bit, |l| msg!(lang: l, "tbl-il-lps"), "S7-200"),
    d("LRD", K::Lrd, (0, 0), C::Bit, |l| msg!(lang: l, "tbl-il-lrd"), "S7-200"),
    d("LPP", K::Lpp, (0, 0), C::Bit, |l| msg!(lang: l, "tbl-il-lpp"), "S7-200"),
    d("R_TRIG", K::RTrig, (0, 0), C::Bit, |l| msg!(lang: l, "tbl-il-r-trig"), "K2 §3.4.3.1; IEC"),
    d("EU", K::RTrig, (0, 0), C::Bit, |l| msg!(lang: l, "tbl-il-eu"), "S7-200"),
    d("F_TRIG", K::FTrig, (0, 0), C::Bit, |l| msg!(lang: l, "tbl-il-f-trig"), "IEC"),
    d("ED", K::FTrig, (0, 0), C::Bit, |l| msg!(lang: l, "tbl-il-ed"), "S7-200"),
    d("MOVE", K::Move { ty: TyHint::Auto }, (2, 2), C::Move, |l| msg!(lang: l, "tbl-il-move"), "K2 §3.4.3.1"),
    d("MOVB", K::Move { ty: TyHint::Byte }, (2, 2), C::Move, |l| msg!(lang: l, "tbl-il-movb"), "S7-200"),
    d("MOVW", K::Move { ty: TyHint::Int }, (2, 2), C::Move, |l| msg!(lang: l, "tbl-il-movw"), "S7-200"),
    d("MOVD", K::Move { ty: TyHint::DInt }, (2, 2), C::Move, |l| msg!(lang: l, "tbl-il-movd"), "S7-200"),
    d("MOVR", K::Move { ty: TyHint::Real }, (2, 2), C::Move, |l| msg!(lang: l, "tbl-il-movr"), "S7-200"),
    d(
        "BLKMOVE",
        K::BlkMove { ty: TyHint::Auto },
        (3, 3),
        C::Move,
        |l| msg!(lang: l, "tbl-il-blkmove"),
        "IEC (KincoBuilder name)",
    ),
    d("BMB", K::BlkMove { ty: TyHint::Byte }, (3, 3), C::Move, |l| msg!(lang: l, "tbl-il-bmb"), "S7-200"),
    d("BMW", K::BlkMove { ty: TyHint::Int }, (3, 3), C::Move, |l| msg!(lang: l, "tbl-il-bmw"), "S7-200"),
    d("BMD", K::BlkMove { ty: TyHint::DInt }, (3, 3), C::Move, |l| msg!(lang: l, "tbl-il-bmd"), "S7-200"),
    d("FILL", K::Fill, (3, 3), C::Move, |l| msg!(lang: l, "tbl-il-fill"), "S7-200"),
    d(
        "ADD",
        K::Arith { op: Arith::Add, ty: TyHint::Auto },
        (2, 3),
        C::Arith,
        |l| msg!(lang: l, "tbl-il-add"),
        "IEC; S7-200",
    ),
    d(
        "SUB",
        K::Arith { op: Arith::Sub, ty: TyHint::Auto },
        (2, 3),
        C::Arith,
        |l| msg!(lang: l, "tbl-il-sub"),
        "IEC; S7-200",
    ),
    d(
        "MUL",
        K::Arith { op: Arith::Mul, ty: TyHint::Auto },
        (2, 3),
        C::Arith,
        |l| msg!(lang: l, "tbl-il-mul"),
        "IEC; S7-200",
    ),
    d(
        "DIV",
        K::Arith { op: Arith::Div, ty: TyHint::Auto },
        (2, 3),
        C::Arith,
        |l| msg!(lang: l, "tbl-il-div"),
        "IEC; S7-200",
    ),
    d("MOD", K::Arith { op: Arith::Mod, ty: TyHint::Auto }, (2, 3), C::Arith, |l| msg!(lang: l, "tbl-il-mod"), "IEC"),
    d("+I", K::Arith { op: Arith::Add, ty: TyHint::Int }, (2, 2), C::Arith, |l| msg!(lang: l, "tbl-il-add-i"), "S7-200"),
    d("-I", K::Arith { op: Arith::Sub, ty: TyHint::Int }, (2, 2), C::Arith, |l| msg!(lang: l, "tbl-il-sub-i"), "S7-200"),
    d("*I", K::Arith { op: Arith::Mul, ty: TyHint::Int }, (2, 2), C::Arith, |l| msg!(lang: l, "tbl-il-mul-i"), "S7-200"),
    d("/I", K::Arith { op: Arith::Div, ty: TyHint::Int }, (2, 2), C::Arith, |l| msg!(lang: l, "tbl-il-div-i"), "S7-200"),
    d("+D", K::Arith { op: Arith::Add, ty: TyHint::DInt }, (2, 2), C::Arith, |l| msg!(lang: l, "tbl-il-add-d"), "S7-200"),
    d("-D", K::Arith { op: Arith::Sub, ty: TyHint::DInt }, (2, 2), C::Arith, |l| msg!(lang: l, "tbl-il-sub-d"), "S7-200"),
    d("*D", K::Arith { op: Arith::Mul, ty: TyHint::DInt }, (2, 2), C::Arith, |l| msg!(lang: l, "tbl-il-mul-d"), "S7-200"),
    d("/D", K::Arith { op: Arith::Div, ty: TyHint::DInt }, (2, 2), C::Arith, |l| msg!(lang: l, "tbl-il-div-d"), "S7-200"),
    d("+R", K::Arith { op: Arith::Add, ty: TyHint::Real }, (2, 2), C::Real, |l| msg!(lang: l, "tbl-il-add-r"), "S7-200"),
    d("-R", K::Arith { op: Arith::Sub, ty: TyHint::Real }, (2, 2), C::Real, |l| msg!(lang: l, "tbl-il-sub-r"), "S7-200"),
    d("*R", K::Arith { op: Arith::Mul, ty: TyHint::Real }, (2, 2), C::Real, |l| msg!(lang: l, "tbl-il-mul-r"), "S7-200"),
    d("/R", K::Arith { op: Arith::Div, ty: TyHint::Real }, (2, 2), C::Real, |l| msg!(lang: l, "tbl-il-div-r"), "S7-200"),
    d("INC", K::IncDec { inc: true, ty: TyHint::Auto }, (1, 1), C::Arith, |l| msg!(lang: l, "tbl-il-inc"), "IEC; S7-200"),
    d("DEC", K::IncDec { inc: false, ty: TyHint::Auto }, (1, 1), C::Arith, |l| msg!(lang: l, "tbl-il-dec"), "IEC; S7-200"),
    d("SHL", K::Shift { op: Shift::Shl }, (2, 2), C::Arith, |l| msg!(lang: l, "tbl-il-shl"), "IEC"),
    d("SHR", K::Shift { op: Shift::Shr }, (2, 2), C::Arith, |l| msg!(lang: l, "tbl-il-shr"), "IEC"),
    d("ROL", K::Shift { op: Shift::Rol }, (2, 2), C::Arith, |l| msg!(lang: l, "tbl-il-rol"), "IEC"),
    d("ROR", K::Shift { op: Shift::Ror }, (2, 2), C::Arith, |l| msg!(lang: l, "tbl-il-ror"), "IEC"),
    d("WAND", K::WordLogic { op: Logic::And }, (2, 3), C::Arith, |l| msg!(lang: l, "tbl-il-wand"), "S7-200 (ANDW)"),
    d("ANDW", K::WordLogic { op: Logic::And }, (2, 3), C::Arith, |l| msg!(lang: l, "tbl-il-andw"), "S7-200"),
    d("WOR", K::WordLogic { op: Logic::Or }, (2, 3), C::Arith, |l| msg!(lang: l, "tbl-il-wor"), "S7-200 (ORW)"),
    d("ORW", K::WordLogic { op: Logic::Or }, (2, 3), C::Arith, |l| msg!(lang: l, "tbl-il-orw"), "S7-200"),
    d("WXOR", K::WordLogic { op: Logic::Xor }, (2, 3), C::Arith, |l| msg!(lang: l, "tbl-il-wxor"), "S7-200 (XORW)"),
    d("XORW", K::WordLogic { op: Logic::Xor }, (2, 3), C::Arith, |l| msg!(lang: l, "tbl-il-xorw"), "S7-200"),
    d("INV", K::Inv, (1, 1), C::Arith, |l| msg!(lang: l, "tbl-il-inv"), "S7-200 (INVW)"),
    d(
        "SQRT",
        K::Unary(Unary::Sqrt),
        (2, 2),
        C::Real,
        |l| msg!(lang: l, "tbl-il-sqrt"),
        "S7-200 System Manual, Square Root (SQRT)",
    ),
    d(
        "ABS",
        K::Unary(Unary::Abs),
        (2, 2),
        C::Arith,
        |l| msg!(lang: l, "tbl-il-abs"),
        "IEC 61131-3 ABS (KincoBuilder IL)",
    ),
    d(
        "SWAP",
        K::Swap,
        (1, 1),
        C::Move,
        |l| msg!(lang: l, "tbl-il-swap"),
        "S7-200 System Manual, Swap Bytes (SWAP)",
    ),
    d(
        "FOR",
        K::For,
        (3, 3),
        C::Jump,
        |l| msg!(lang: l, "tbl-il-for"),
        "S7-200 System Manual, For-Next Loop (FOR, NEXT)",
    ),
    d(
        "NEXT",
        K::Next,
        (0, 0),
        C::Jump,
        |l| msg!(lang: l, "tbl-il-next"),
        "S7-200 System Manual, For-Next Loop (FOR, NEXT)",
    ),
    d("I_DI", K::Conv(Conv::IDi), (2, 2), C::Move, |l| msg!(lang: l, "tbl-il-i-di"), "S7-200"),
    d("INT_TO_DINT", K::Conv(Conv::IDi), (2, 2), C::Move, |l| msg!(lang: l, "tbl-il-int-to-dint"), "IEC"),
    d("DI_I", K::Conv(Conv::DiI), (2, 2), C::Move, |l| msg!(lang: l, "tbl-il-di-i"), "S7-200"),
    d("DINT_TO_INT", K::Conv(Conv::DiI), (2, 2), C::Move, |l| msg!(lang: l, "tbl-il-dint-to-int"), "IEC"),
    d("B_I", K::Conv(Conv::BI), (2, 2), C::Move, |l| msg!(lang: l, "tbl-il-b-i"), "S7-200"),
    d("I_B", K::Conv(Conv::IB), (2, 2), C::Move, |l| msg!(lang: l, "tbl-il-i-b"), "S7-200"),
    d("DI_R", K::Conv(Conv::DiR), (2, 2), C::Real, |l| msg!(lang: l, "tbl-il-di-r"), "S7-200"),
    d("ROUND", K::Conv(Conv::Round), (2, 2), C::Real, |l| msg!(lang: l, "tbl-il-round"), "S7-200"),
    d("TRUNC", K::Conv(Conv::Trunc), (2, 2), C::Real, |l| msg!(lang: l, "tbl-il-trunc"), "S7-200; IEC"),
    d("I_BCD", K::Conv(Conv::IBcd), (2, 2), C::Move, |l| msg!(lang: l, "tbl-il-i-bcd"), "S7-200"),
    d("BCD_I", K::Conv(Conv::BcdI), (2, 2), C::Move, |l| msg!(lang: l, "tbl-il-bcd-i"), "S7-200"),
    d("JMP", K::Jmp, (1, 1), C::Jump, |l| msg!(lang: l, "tbl-il-jmp"), "IEC"),
    d("JMPC", K::Jmpc { neg: false }, (1, 1), C::Jump, |l| msg!(lang: l, "tbl-il-jmpc"), "IEC"),
    d("JMPCN", K::Jmpc { neg: true }, (1, 1), C::Jump, |l| msg!(lang: l, "tbl-il-jmpcn"), "IEC"),
    d("CAL", K::Cal, (1, 1), C::Call, |l| msg!(lang: l, "tbl-il-cal"), "IEC; K2 helper"),
    d("CALC", K::Calc { neg: false }, (1, 1), C::Call, |l| msg!(lang: l, "tbl-il-calc"), "IEC"),
    d("CALCN", K::Calc { neg: true }, (1, 1), C::Call, |l| msg!(lang: l, "tbl-il-calcn"), "IEC"),
    d("RET", K::Ret, (0, 0), C::Jump, |l| msg!(lang: l, "tbl-il-ret"), "IEC"),
    d("RETC", K::Retc { neg: false }, (0, 0), C::Jump, |l| msg!(lang: l, "tbl-il-retc"), "IEC"),
    d("RETCN", K::Retc { neg: true }, (0, 0), C::Jump, |l| msg!(lang: l, "tbl-il-retcn"), "IEC"),
    d("CRET", K::Retc { neg: false }, (0, 0), C::Jump, |l| msg!(lang: l, "tbl-il-cret"), "S7-200"),
    d("TON", K::Timer(TimerKind::Ton), (2, 2), C::Timer, |l| msg!(lang: l, "tbl-il-ton"), "K2 §2.1.2; K80S"),
    d("TOF", K::Timer(TimerKind::Tof), (2, 2), C::Timer, |l| msg!(lang: l, "tbl-il-tof"), "K2; IEC"),
    d("TOFF", K::Timer(TimerKind::Tof), (2, 2), C::Timer, |l| msg!(lang: l, "tbl-il-toff"), "K80S"),
    d("TP", K::Timer(TimerKind::Tp), (2, 2), C::Timer, |l| msg!(lang: l, "tbl-il-tp"), "IEC"),
    d("TMR", K::Timer(TimerKind::Tmr), (2, 3), C::Timer, |l| msg!(lang: l, "tbl-il-tmr"), "K80S"),
    d("TONR", K::Timer(TimerKind::Tmr), (2, 3), C::Timer, |l| msg!(lang: l, "tbl-il-tonr"), "S7-200"),
    d("TMON", K::Timer(TimerKind::Tmon), (2, 2), C::Timer, |l| msg!(lang: l, "tbl-il-tmon"), "K80S"),
    d("TRTG", K::Timer(TimerKind::Trtg), (2, 2), C::Timer, |l| msg!(lang: l, "tbl-il-trtg"), "K80S"),
    d("CTU", K::Counter(CounterKind::Ctu), (2, 3), C::Timer, |l| msg!(lang: l, "tbl-il-ctu"), "K80S; IEC"),
    d("CTD", K::Counter(CounterKind::Ctd), (2, 3), C::Timer, |l| msg!(lang: l, "tbl-il-ctd"), "K80S; IEC"),
    d(
        "CTUD",
        K::Counter(CounterKind::Ctud),
        (3, 4),
        C::Timer,
        |l| msg!(lang: l, "tbl-il-ctud"),
        "K80S; IEC",
    ),
    d("CTR", K::Counter(CounterKind::Ctr), (2, 3), C::Timer, |l| msg!(lang: l, "tbl-il-ctr"), "K80S"),
    d("ATCH", K::Atch, (2, 2), C::Special, |l| msg!(lang: l, "tbl-il-atch"), "K2 §3.3, §3.4"),
    d("DTCH", K::Dtch, (1, 1), C::Special, |l| msg!(lang: l, "tbl-il-dtch"), "K2; S7-200"),
    d("ENI", K::Eni, (0, 0), C::Special, |l| msg!(lang: l, "tbl-il-eni"), "K2; S7-200"),
    d("DISI", K::Disi, (0, 0), C::Special, |l| msg!(lang: l, "tbl-il-disi"), "K2; S7-200"),
    d("WDT", K::Wdt, (0, 0), C::Special, |l| msg!(lang: l, "tbl-il-wdt"), "K80S"),
    d("WDR", K::Wdt, (0, 0), C::Special, |l| msg!(lang: l, "tbl-il-wdr"), "S7-200"),
    d("NOP", K::Nop, (0, 1), C::Bit, |l| msg!(lang: l, "tbl-il-nop"), "IEC"),
];

/// Instructions never offered as a "did you mean" for an unknown name, in any family: each
/// stops the CPU or an axis, moves an axis, starts pulses or counters, sets the clock,
/// silences interrupts or ends the program — a typo must not become one of them (a user who
/// meant one types it).
pub const NEVER_SUGGESTED: &[&str] = &[
    "STOP", "PSTOP", "PLS", "PREL", "PABS", "PHOME", "PJOG", "PFLO_F", "HSC", "HDEF", "SET_RTC", "DISI", "DTCH", "END",
    "MEND", "FEND",
];

/// Comparison mnemonics, S7-200 style: `LD`/`A`/`O` + `B`/`W`/`D`/`R` + operator.
pub fn compare(m: &str) -> Option<Def> {
    let (comb, rest) = if let Some(r) = m.strip_prefix("LD") {
        (Comb::Ld, r)
    } else if let Some(r) = m.strip_prefix('A') {
        (Comb::And, r)
    } else if let Some(r) = m.strip_prefix('O') {
        (Comb::Or, r)
    } else {
        return None;
    };
    let (ty, op) = match rest.get(..1)? {
        "B" => (TyHint::Byte, &rest[1..]),
        "W" => (TyHint::Int, &rest[1..]),
        "D" => (TyHint::DInt, &rest[1..]),
        "R" => (TyHint::Real, &rest[1..]),
        _ => return None,
    };
    let op = match op {
        "=" | "==" => Cmp::Eq,
        "<>" => Cmp::Ne,
        "<" => Cmp::Lt,
        ">" => Cmp::Gt,
        "<=" => Cmp::Le,
        ">=" => Cmp::Ge,
        _ => return None,
    };
    Some(Def {
        name: "compare",
        kind: Kind::Compare { comb, ty, op },
        operands: (2, 2),
        cost: CostClass::Compare,
        doc: |l| msg!(lang: l, "tbl-il-compare"),
        source: "S7-200 (KincoBuilder IL)",
    })
}

/// Looks a core mnemonic up.
pub fn lookup(m: &str) -> Option<Def> {
    CORE.iter().find(|d| d.name == m).copied().or_else(|| compare(m))
}

/// The instruction table as Markdown rows (`docs/il.md` is checked against it).
pub fn markdown(specials: &[super::SpecialDef], family: &str) -> String {
    let mut s = String::from("| instruction | operands | does | source |\n|---|---|---|---|\n");
    for d in CORE {
        let ops = if d.operands.0 == d.operands.1 {
            d.operands.0.to_string()
        } else {
            format!("{}–{}", d.operands.0, d.operands.1)
        };
        let name = d.name.replace('|', "\\|");
        s.push_str(&format!("| `{name}` | {ops} | {} | {} |\n", (d.doc)(Lang::En), d.source));
    }
    s.push_str("| `LDB=` … `LDR>=`, `AB=` … `OR<>` | 2 | compare: `LD`/`A`/`O` × `B`(BYTE) `W`(INT) `D`(DINT) `R`(REAL) × `=` `<>` `<` `>` `<=` `>=` | S7-200 (KincoBuilder IL) |\n");
    for sp in specials {
        let n = sp.args.len();
        let ops = if sp.optional > 0 { format!("{}–{n}", n - sp.optional as usize) } else { n.to_string() };
        s.push_str(&format!("| `{}` ({family}) | {ops} | {} | {} |\n", sp.name, (sp.doc)(Lang::En), sp.source));
    }
    s
}

#[cfg(test)]
mod table_tests {
    use super::*;

    /// Every instruction's description is in every language, and every `tbl-il-…` id of the
    /// catalogue belongs to a row.
    #[test]
    fn every_instruction_has_its_description_in_every_language() {
        let mut used: Vec<&str> = CORE.iter().map(|d| (d.doc)(Lang::En).id).collect();
        used.push((lookup("LDW>=").unwrap().doc)(Lang::En).id);
        for lang in Lang::ALL {
            let ids = crate::core::msg::ids(*lang);
            for id in &used {
                assert!(ids.iter().any(|i| i == id), "{id} has no text in {}", lang.tag());
            }
        }
        for id in crate::core::msg::ids(Lang::En) {
            if id.starts_with("tbl-il-") {
                assert!(used.contains(&id.as_str()), "{id} belongs to no instruction");
            }
        }
        assert_eq!((lookup("LD").unwrap().doc)(Lang::En).text, "CR := bit (the old CR is pushed)");
    }
}
