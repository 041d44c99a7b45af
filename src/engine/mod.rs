//! The family-neutral PLC scan engine: instruction-list (IL) text → a compact compiled
//! program → scans executed against a device's memory image, in virtual time.
//!
//! It exists apart from any family because several simulated PLCs run programs (the K2
//! today, the UMPK teaching PLC next): the engine knows bit logic, comparisons, moves,
//! arithmetic, jumps, calls, timers, counters and interrupts; a family supplies what is its
//! own through two traits:
//!
//! * [`Family`] — used while **loading**: resolves operand text to a [`Loc`] and a type,
//!   names its timers and counters (number → value/bit locations and time base), encodes
//!   `&` pointers, lists its own instructions ([`SpecialDef`]) and its cost table.
//! * [`Machine`] — used while **running**: reads and writes raw bit patterns at a `Loc`,
//!   dereferences pointers, and executes the family's own instructions.
//!
//! Two families plug in by implementing both over their memory images: the K2
//! (`k2::sim::program::family`) and the UMPK teaching PLC (`umpk::sim::program`: its 10 ms
//! cycle as the minimum scan, its bit operands as `Loc`s, its on-delay timers and
//! divide-by-N counters as family instructions whose input is the CR, hence
//! [`Machine::special_off`]). The FX PLC (`fx::program`) is a third: its instruction lists
//! are translated to this dialect first, its timers and counters are family instructions.
//! Nothing here names a K2, UMPK or FX device.
//!
//! Pipeline: [`source::parse`] (linear, never panics) → [`compile::compile`] (operands
//! resolved, labels and calls bound, errors with `file:line:column` and a suggestion) →
//! [`Program`] (a flat `Vec<Ins>` with resolved locations) → [`exec::Cpu::scan`].
//! The accepted dialect is documented in `docs/il.md`.

pub mod compile;
pub mod exec;
pub mod isa;
pub mod source;
pub mod symbols;
pub mod timers;

#[cfg(test)]
mod tests;

pub use compile::Program;
pub use exec::{Cpu, Fault, FaultKind, ScanOutcome};
pub use isa::{CostClass, CounterKind, TimerKind};
pub use symbols::{compile, compile_with_tags};

use crate::core::DataType;
use serde::{Deserialize, Serialize};

/// Width of a location.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash, Serialize, Deserialize)]
pub enum Width {
    /// One bit: `bit` of byte `index`.
    Bit(u8),
    Byte,
    Word,
    DWord,
    /// A 16-bit element addressed by number (a timer's or counter's value).
    Element,
}

impl Width {
    /// Bytes one such location spans (block moves step by it).
    pub fn bytes(self) -> u32 {
        match self {
            Width::Bit(_) | Width::Byte => 1,
            Width::Word => 2,
            Width::DWord => 4,
            Width::Element => 1,
        }
    }
}

/// A resolved location in a family's memory image: area (family-defined number), width
/// and byte index (element number for [`Width::Element`]).
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash, Serialize, Deserialize)]
pub struct Loc {
    pub area: u8,
    pub width: Width,
    pub index: u32,
}

impl Loc {
    /// The `k`-th location of the same width after this one (block moves, `S bit, N`).
    pub fn nth(self, k: u32) -> Loc {
        match self.width {
            Width::Bit(b) => {
                let abs = b as u32 + k;
                Loc { width: Width::Bit((abs % 8) as u8), index: self.index + abs / 8, ..self }
            }
            w => Loc { index: self.index + k * w.bytes(), ..self },
        }
    }
}

/// An operand resolved by the family.
#[derive(Clone, Debug, PartialEq)]
pub struct Resolved {
    pub loc: Loc,
    pub ty: DataType,
    /// Canonical spelling (for listings and the debugger).
    pub canonical: String,
}

/// Why an operand was refused: message and what to try.
#[derive(Clone, Debug, PartialEq)]
pub struct OperandError {
    pub message: String,
    pub hint: Option<String>,
}

impl OperandError {
    pub fn new(message: impl Into<String>) -> OperandError {
        OperandError { message: message.into(), hint: None }
    }
    pub fn hint(mut self, h: impl Into<String>) -> OperandError {
        self.hint = Some(h.into());
        self
    }
}

/// A timer or counter the family has: its number, where its value and bit live, and (for
/// timers) the time base of its resolution class.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Element {
    pub number: u32,
    pub cv: Loc,
    pub q: Loc,
    /// Time base in ns (timers; 0 for counters).
    pub base_ns: u64,
}

/// Operand kinds a family instruction takes (checked at load time).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum ArgKind {
    /// A constant number (channel, mode …) known at load time.
    Const,
    /// A bit location (read or written).
    Bit,
    /// Any value operand: a location, a pointer target or a literal, of the given type
    /// (`None`: the operand's own type).
    Value(Option<DataType>),
    /// A location only (an output or a buffer start), of the given type.
    Out(Option<DataType>),
}

/// A family instruction (PLS, HDEF, PHOME …): name, operands, cost, documentation.
#[derive(Clone, Copy, Debug)]
pub struct SpecialDef {
    pub name: &'static str,
    pub id: u16,
    pub args: &'static [ArgKind],
    /// Trailing operands that may be left out.
    pub optional: u8,
    /// Whether it acts on the rising edge of its enable input (K2 PLS, §3.4.2) rather
    /// than whenever the CR is on.
    pub edge: bool,
    /// What it does (docs/il.md shows it in English; catalogue `engine.ftl`, ids
    /// `engine-doc-FAMILY-…`, one row per family instruction).
    pub doc: fn(crate::core::msg::Lang) -> crate::core::msg::Msg,
    pub source: &'static str,
}

/// Time per instruction cost class, a fixed per-scan overhead (self-diagnosis, I/O
/// refresh, communication — K80S "internal processing"), the minimum scan time and the
/// watchdog limit. All configurable; the family gives defaults.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
pub struct CostTable {
    /// ns per instruction of each [`CostClass`] (indexed by `CostClass as usize`).
    pub class_ns: [u32; 9],
    /// Extra ns per element moved by block moves and fills.
    pub per_element_ns: u32,
    /// Fixed ns per scan.
    pub overhead_ns: u64,
    /// Minimum scan time in ns (0: as fast as the program allows).
    pub min_scan_ns: u64,
    /// Watchdog limit in ns: a scan whose program time passes it stops the CPU.
    pub watchdog_ns: u64,
}

impl CostTable {
    pub fn ns(&self, c: CostClass) -> u32 {
        self.class_ns[c as usize]
    }
}

/// A compiled operand.
#[derive(Clone, Copy, Debug, PartialEq, Serialize, Deserialize)]
pub enum Opd {
    /// A literal's raw bit pattern in the instruction's type.
    Imm(u32),
    Loc(Loc),
    /// `*VDn`: the location whose pointer is stored in this double word.
    Ind(Loc),
}

/// The family's side of loading a program.
pub trait Family {
    /// Resolves a plain operand (no literal, `&` or `*`: the engine handles those) where
    /// a bit is expected (`LD`, `ST`, …): a timer or counter name means its bit.
    fn operand(&self, text: &str) -> Result<Resolved, OperandError>;
    /// The same where a value is expected (`MOVE T5, …`: a timer's current value).
    fn value_operand(&self, text: &str) -> Result<Resolved, OperandError> {
        self.operand(text)
    }
    /// Resolves a timer (`want_timer`) or counter operand (`T37`, `C5`).
    fn element(&self, text: &str, want_timer: bool) -> Result<Element, OperandError>;
    /// The pointer value `&operand` stores, or `None` if the family has no pointer to it.
    fn pointer(&self, loc: Loc) -> Option<u32>;
    /// The family's own instructions.
    fn specials(&self) -> &'static [SpecialDef];
    /// Default costs.
    fn costs(&self) -> CostTable;
    /// Highest interrupt event number + 1.
    fn events(&self) -> u32 {
        256
    }
    /// Whether interrupt event `n` exists (an `ATCH` to any other is a load error), and
    /// the list to name in that error.
    fn event_exists(&self, n: u32) -> bool {
        n < self.events()
    }
    fn event_list(&self) -> String {
        match self.events() {
            0 => "none: this PLC has no interrupts".to_string(),
            n => format!("0–{}", n - 1),
        }
    }
}

/// Arithmetic status after an operation (S7-200's SM1.0–SM1.3 on the K2).
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct Flags {
    pub zero: bool,
    pub overflow: bool,
    pub negative: bool,
    pub div_zero: bool,
}

/// The family's side of running a program.
pub trait Machine {
    /// Raw bit pattern at `l` (bits: 0/1; bytes, words, double words zero-extended).
    fn get(&self, l: Loc) -> u32;
    /// Writes a raw pattern. A family may ignore writes to locations its CPU owns
    /// (read-only system registers), as the real PLC does.
    fn set(&mut self, l: Loc, v: u32);
    /// The bit at `l` (`LD`, `A`, `O` …): bit 0 of [`Machine::get`]. A family may give a
    /// shorter way for bit locations (the scan engine's hottest read); the result is the same.
    #[inline(always)]
    fn get_bit(&self, l: Loc) -> bool {
        self.get(l) & 1 != 0
    }
    /// Writes the bit at `l` (`ST`): [`Machine::set`] of 0 or 1, or a shorter way to the same.
    #[inline(always)]
    fn set_bit(&mut self, l: Loc, v: bool) {
        self.set(l, v as u32)
    }
    /// The location a pointer designates at width `w`, or `None` (a fault: bad indirect address).
    fn deref(&self, ptr: u32, w: Width) -> Option<Loc>;
    /// Executes family instruction `id` (its operands already checked); `inst` numbers
    /// this occurrence in the program (for per-instance state such as an EXEC edge).
    /// Returns ENO.
    fn special(&mut self, id: u16, inst: u32, args: &[Opd], types: &[DataType]) -> Result<bool, Fault>;
    /// Family instruction `id` reached with its enable (the CR) off. Most do nothing then
    /// and leave ENO off (the default); an instruction whose input is the CR — the UMPK's
    /// on-delay timers and divide-by-N counters — updates with the input off. Returns ENO.
    fn special_off(&mut self, _id: u16, _inst: u32, _args: &[Opd], _types: &[DataType]) -> Result<bool, Fault> {
        Ok(false)
    }
    /// Arithmetic status after an operation.
    fn flags(&mut self, _f: Flags) {}
}

/// Reads an operand as a raw pattern of width `ty` (helper for family instructions).
#[inline]
pub fn read<M: Machine + ?Sized>(m: &M, o: &Opd, ty: DataType) -> Result<u32, Fault> {
    Ok(match *o {
        Opd::Imm(v) => v,
        Opd::Loc(l) => m.get(l),
        Opd::Ind(p) => m.get(deref(m, p, ty)?),
    })
}

/// Writes an operand (helper for family instructions).
#[inline]
pub fn write<M: Machine + ?Sized>(m: &mut M, o: &Opd, ty: DataType, v: u32) -> Result<(), Fault> {
    match *o {
        Opd::Imm(_) => {}
        Opd::Loc(l) => m.set(l, v),
        Opd::Ind(p) => {
            let l = deref(m, p, ty)?;
            m.set(l, v)
        }
    }
    Ok(())
}

/// The location an operand designates (literals have none).
pub fn loc_of<M: Machine + ?Sized>(m: &M, o: &Opd, ty: DataType) -> Result<Option<Loc>, Fault> {
    Ok(match *o {
        Opd::Imm(_) => None,
        Opd::Loc(l) => Some(l),
        Opd::Ind(p) => Some(deref(m, p, ty)?),
    })
}

fn deref<M: Machine + ?Sized>(m: &M, p: Loc, ty: DataType) -> Result<Loc, Fault> {
    let ptr = m.get(p);
    let w = width_of(ty);
    m.deref(ptr, w).ok_or_else(|| {
        Fault::new(FaultKind::BadAddress, crate::msg!("engine-bad-address-at", pointer = format!("16#{ptr:08X}")))
    })
}

/// The location width that holds a type.
pub fn width_of(ty: DataType) -> Width {
    match ty {
        DataType::Bool => Width::Bit(0),
        DataType::Byte | DataType::SInt => Width::Byte,
        DataType::Word | DataType::Int => Width::Word,
        DataType::DWord | DataType::DInt | DataType::Real => Width::DWord,
    }
}
