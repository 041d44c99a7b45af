//! The K2's side of the scan engine: its operand space, timer classes, pointers, cost
//! table and special instructions ([`K2Family`]), and its memory image at run time
//! ([`K2Machine`], a view of the simulator during one scan).
//!
//! Timer resolution classes (K2 manual §2.1.2: 256 timers, 4 with a 1 ms base, 16 with
//! 10 ms, 236 with 100 ms; the manual does not say which numbers, so we choose contiguous
//! blocks): **T0–T3 1 ms, T4–T19 10 ms, T20–T255 100 ms**.
//!
//! Locations: areas are numbered as [`Area::ALL`] (I, Q, M, V, SM, AI, AQ, T values, C
//! values), plus 9 = timer bits and 10 = counter bits. Pointers (`&VB100`) are
//! `(area + 1) << 24 | byte`, so a pointer cannot be mistaken for a plain number below
//! 16#01000000 and `*VDn` of a bad pointer is a fault rather than a stray write.

use super::super::K2Sim;
use crate::core::DataType;
use crate::engine::{
    self, ArgKind, CostTable, Element, Family, Fault, FaultKind, Flags, Loc, Machine, Opd, OperandError, Resolved,
    SpecialDef, Width,
};
use crate::k2::catalog;
use crate::k2::instr::RtcTime;
use crate::k2::operand::{Area, K2Operand, Width as KW};
use crate::k2::space::K2Space;
use crate::msg;
use std::time::Duration;

pub const AREA_TQ: u8 = 9;
pub const AREA_CQ: u8 = 10;

/// Time base of timer `n` (K2 §2.1.2 classes, numbering chosen here).
pub fn timer_base_ns(n: u32) -> u64 {
    match n {
        0..=3 => 1_000_000,
        4..=19 => 10_000_000,
        _ => 100_000_000,
    }
}

/// Special instruction ids.
pub mod id {
    pub const PLS: u16 = 1;
    pub const HDEF: u16 = 2;
    pub const HSC: u16 = 3;
    pub const PSTOP: u16 = 4;
    pub const READ_RTC: u16 = 5;
    pub const SET_RTC: u16 = 6;
    pub const STOP: u16 = 7;
    /// Position control (`super::motion`).
    pub const PREL: u16 = 10;
    pub const PABS: u16 = 11;
    pub const PHOME: u16 = 12;
    pub const PJOG: u16 = 13;
    pub const PFLO_F: u16 = 14;
}

/// Per-occurrence state of a K2 instruction in a program.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, serde::Serialize, serde::Deserialize)]
pub struct Inst {
    pub exec_prev: bool,
    pub busy: bool,
    pub done: bool,
    pub err: u8,
    /// Frequency of the running constant-speed train (PJOG, PHOME, PFLO_F), Hz.
    pub freq: u64,
    /// PFLO_F: pulses still to output; PHOME: slowed down by NHOME.
    pub remaining: u64,
    pub slow: bool,
}

use ArgKind as A;

const W: ArgKind = A::Value(Some(DataType::Word));
const D: ArgKind = A::Value(Some(DataType::DWord));
const DI: ArgKind = A::Value(Some(DataType::DInt));
const B: ArgKind = A::Out(Some(DataType::Byte));

/// Most operands a K2 instruction takes (PHOME's 12; `SPECIALS`).
pub(super) const MAX_ARGS: usize = 12;

/// The K2's own instructions (K2 manual §3.3, §3.4; PSTOP parameters from the KincoBuilder
/// help as quoted in `../shared/spec/kinco-public-notes.md`).
pub static SPECIALS: &[SpecialDef] = &[
    SpecialDef {
        name: "PLS",
        id: id::PLS,
        args: &[A::Const],
        optional: 0,
        edge: true,
        doc: |l| msg!(lang: l, "engine-doc-k2-pls"),
        source: "K2 §3.4.2",
    },
    SpecialDef {
        name: "HDEF",
        id: id::HDEF,
        args: &[A::Const, A::Const],
        optional: 0,
        edge: false,
        doc: |l| msg!(lang: l, "engine-doc-k2-hdef"),
        source: "K2 §3.3.1, §3.3.5",
    },
    SpecialDef {
        name: "HSC",
        id: id::HSC,
        args: &[A::Const],
        optional: 0,
        edge: false,
        doc: |l| msg!(lang: l, "engine-doc-k2-hsc"),
        source: "K2 §3.3.5",
    },
    SpecialDef {
        name: "PSTOP",
        id: id::PSTOP,
        args: &[A::Const, A::Bit, A::Bit, A::Out(Some(DataType::Word))],
        optional: 3,
        edge: false,
        doc: |l| msg!(lang: l, "engine-doc-k2-pstop"),
        source: "K2 §3.4.3; KincoBuilder help (kinco-public-notes)",
    },
    SpecialDef {
        name: "PREL",
        id: id::PREL,
        args: &[A::Const, A::Bit, W, D, W, DI, A::Bit, A::Bit, B],
        optional: 0,
        edge: false,
        doc: |l| msg!(lang: l, "engine-doc-k2-prel"),
        source: "K2 §3.4.3; KincoBuilder help (kinco-public-notes)",
    },
    SpecialDef {
        name: "PABS",
        id: id::PABS,
        args: &[A::Const, A::Bit, W, D, W, DI, A::Bit, A::Bit, B],
        optional: 0,
        edge: false,
        doc: |l| msg!(lang: l, "engine-doc-k2-pabs"),
        source: "K2 §3.4.3; KincoBuilder help (kinco-public-notes)",
    },
    SpecialDef {
        name: "PHOME",
        id: id::PHOME,
        args: &[A::Const, A::Bit, A::Bit, A::Bit, W, W, W, D, W, A::Bit, A::Bit, B],
        optional: 0,
        edge: false,
        doc: |l| msg!(lang: l, "engine-doc-k2-phome"),
        source: "K2 §3.4.3.1; KincoBuilder help (kinco-public-notes)",
    },
    SpecialDef {
        name: "PJOG",
        id: id::PJOG,
        args: &[A::Const, A::Bit, D, W, A::Bit, A::Bit, B],
        optional: 0,
        edge: false,
        doc: |l| msg!(lang: l, "engine-doc-k2-pjog"),
        source: "K2 §3.4.3.2; KincoBuilder help (kinco-public-notes)",
    },
    SpecialDef {
        name: "PFLO_F",
        id: id::PFLO_F,
        args: &[A::Const, A::Bit, D, W, W, DI, A::Bit, A::Bit, B],
        optional: 0,
        edge: false,
        doc: |l| msg!(lang: l, "engine-doc-k2-pflo-f"),
        source: "K2 §3.4.3 (parameters named there; order ours)",
    },
    SpecialDef {
        name: "READ_RTC",
        id: id::READ_RTC,
        args: &[A::Out(Some(DataType::Byte))],
        optional: 0,
        edge: false,
        doc: |l| msg!(lang: l, "engine-doc-k2-read-rtc"),
        source: "K2 §2.2.10; S7-200 buffer layout",
    },
    SpecialDef {
        name: "SET_RTC",
        id: id::SET_RTC,
        args: &[A::Out(Some(DataType::Byte))],
        optional: 0,
        edge: false,
        doc: |l| msg!(lang: l, "engine-doc-k2-set-rtc"),
        source: "K2 §2.2.10; S7-200 buffer layout",
    },
    SpecialDef {
        name: "STOP",
        id: id::STOP,
        args: &[],
        optional: 0,
        edge: false,
        doc: |l| msg!(lang: l, "engine-doc-k2-stop"),
        source: "K80S 5.4.5 (the program's STOP changes the mode); timing: S7-200 System Manual, STOP instruction",
    },
];

/// Default cost table: estimates (the K2 manual gives no execution times), configurable
/// with `sim program costs`. Minimum scan 1 ms (the simulator's scan time without a
/// program), watchdog 300 ms.
pub fn default_costs() -> CostTable {
    CostTable {
        // bit, compare, move, arith, real, timer, jump, call, special (ns)
        class_ns: [200, 1_500, 2_000, 3_000, 10_000, 5_000, 1_000, 5_000, 20_000],
        per_element_ns: 200,
        overhead_ns: 300_000,
        min_scan_ns: 1_000_000,
        watchdog_ns: 300_000_000,
    }
}

/// The K2 operand space as the engine sees it.
pub struct K2Family {
    pub space: K2Space,
    /// A cost table set by the user (`sim program costs`), else the defaults.
    pub costs: Option<CostTable>,
}

fn op_err(e: crate::core::Error) -> OperandError {
    let mut o = OperandError::new(e.message.clone());
    o.hint = e.hint.clone();
    o
}

fn to_loc(o: &K2Operand) -> Option<Loc> {
    let area = Area::ALL.iter().position(|a| *a == o.area)? as u8;
    let width = match o.width {
        KW::Bit(b) => Width::Bit(b),
        KW::Byte => Width::Byte,
        KW::Word => Width::Word,
        KW::DWord => Width::DWord,
        KW::Element => Width::Element,
        KW::Group { .. } => return None,
    };
    Some(Loc { area, width, index: o.byte })
}

impl K2Family {
    fn one(&self, text: &str) -> Result<K2Operand, OperandError> {
        let ops = self.space.parse_k2(text).map_err(op_err)?;
        if ops.len() != 1 {
            return Err(OperandError::new(msg!("k2-program-one-location")));
        }
        Ok(ops[0])
    }
}

impl Family for K2Family {
    fn operand(&self, text: &str) -> Result<Resolved, OperandError> {
        let o = self.one(text)?;
        if let KW::Element = o.width {
            // T5 / C5 in a bit context is the timer's or counter's bit (S7-200 convention);
            // as a value it is the current value.
            let area = if o.area == Area::T { AREA_TQ } else { AREA_CQ };
            return Ok(Resolved {
                loc: Loc { area, width: Width::Bit(0), index: o.byte },
                ty: DataType::Bool,
                canonical: o.canonical(),
            });
        }
        let loc = to_loc(&o).ok_or_else(|| {
            OperandError::new(msg!("k2-program-bit-group", operand = o.canonical()))
                .hint(msg!("k2-program-bit-group-hint"))
        })?;
        Ok(Resolved { loc, ty: o.view, canonical: o.canonical() })
    }

    fn value_operand(&self, text: &str) -> Result<Resolved, OperandError> {
        let o = self.one(text)?;
        if let KW::Element = o.width {
            return Ok(Resolved { loc: to_loc(&o).unwrap(), ty: DataType::Int, canonical: o.canonical() });
        }
        self.operand(text)
    }

    fn element(&self, text: &str, want_timer: bool) -> Result<Element, OperandError> {
        let o = self.one(text)?;
        let (area, q, what) = if want_timer { (Area::T, AREA_TQ, "timer") } else { (Area::C, AREA_CQ, "counter") };
        if o.area != area || o.width != KW::Element {
            return Err(OperandError::new(msg!("k2-program-not-element", operand = o.canonical(), what = what))
                .hint(if want_timer { msg!("k2-program-timers-hint") } else { msg!("k2-program-counters-hint") }));
        }
        Ok(Element {
            number: o.byte,
            cv: to_loc(&o).unwrap(),
            q: Loc { area: q, width: Width::Bit(0), index: o.byte },
            base_ns: if want_timer { timer_base_ns(o.byte) } else { 0 },
        })
    }

    fn pointer(&self, loc: Loc) -> Option<u32> {
        let a = Area::ALL.get(loc.area as usize)?;
        a.is_bit_area().then_some(((loc.area as u32 + 1) << 24) | loc.index)
    }

    fn specials(&self) -> &'static [SpecialDef] {
        SPECIALS
    }

    fn costs(&self) -> CostTable {
        self.costs.clone().unwrap_or_else(default_costs)
    }

    fn events(&self) -> u32 {
        // K2 event numbers go up to 191 (HSC3 PV 32, §3.3.3).
        192
    }
    /// The numbers docs/il.md lists ([`super::irq`]): a number the manual does not give
    /// would attach a routine to nothing here and to something else on a real K2.
    fn event_exists(&self, n: u32) -> bool {
        matches!(n, 0..=7 | 10 | 11 | 64..=191) || n == crate::k2::instr::PTO0_COMPLETE as u32
    }
    fn event_list(&self) -> String {
        "0–7 input edges, 10–11 timed, 28 PTO0 complete, 64–191 multi-PV CV = PV; the other \
         counter and PTO events have no number in the manual (docs/il.md, \"Interrupts\")"
            .to_string()
    }
}

/// The simulator during one scan, as the engine's memory image.
pub struct K2Machine<'a> {
    pub sim: &'a mut K2Sim,
    pub now: Duration,
    /// Per-occurrence state of the K2 instructions (EXEC edges, running moves).
    pub inst: &'a mut Vec<Inst>,
    pub raised: Vec<(Duration, crate::k2::instr::EventKind)>,
}

/// Reads a raw pattern from a byte area (S7 byte order); 0 outside it.
#[inline(always)]
fn take(b: &[u8], w: Width, i: usize) -> u32 {
    match w {
        Width::Bit(k) => b.get(i).map_or(0, |v| (v >> k & 1) as u32),
        Width::Byte => b.get(i).map_or(0, |v| *v as u32),
        Width::Word => b.get(i..i + 2).map_or(0, |w| u16::from_be_bytes([w[0], w[1]]) as u32),
        Width::DWord => b.get(i..i + 4).map_or(0, |w| u32::from_be_bytes([w[0], w[1], w[2], w[3]])),
        Width::Element => 0,
    }
}

/// Writes a raw pattern into a byte area (S7 byte order), ignoring out-of-range locations.
#[inline(always)]
fn put(b: &mut [u8], w: Width, i: usize, v: u32) {
    match w {
        Width::Bit(k) => {
            if let Some(x) = b.get_mut(i) {
                *x = (*x & !(1 << k)) | (((v & 1) as u8) << k);
            }
        }
        Width::Byte => {
            if let Some(x) = b.get_mut(i) {
                *x = v as u8
            }
        }
        Width::Word => {
            if let Some(x) = b.get_mut(i..i + 2) {
                x.copy_from_slice(&(v as u16).to_be_bytes())
            }
        }
        Width::DWord => {
            if let Some(x) = b.get_mut(i..i + 4) {
                x.copy_from_slice(&v.to_be_bytes())
            }
        }
        Width::Element => {}
    }
}

impl K2Machine<'_> {
    /// The same bookkeeping as a client's write: HSC CV holds, position bits, E2PROM wear.
    #[cold]
    #[inline(never)]
    fn hook(&mut self, area: Area, l: Loc) {
        let kw = match l.width {
            Width::Bit(k) => KW::Bit(k),
            Width::Byte => KW::Byte,
            Width::Word => KW::Word,
            _ => KW::DWord,
        };
        let op = K2Operand::new(area, kw, l.index);
        let mut raised = std::mem::take(&mut self.raised);
        self.sim.after_write(&op, &mut raised);
        self.raised = raised;
    }

    fn area(&self, a: u8) -> &[u8] {
        match a {
            0 => &self.sim.mem.i,
            1 => &self.sim.mem.q,
            2 => &self.sim.mem.m,
            3 => &self.sim.mem.v,
            4 => &self.sim.mem.sm,
            5 => &self.sim.mem.ai,
            6 => &self.sim.mem.aq,
            _ => &[],
        }
    }

    /// Registers the CPU owns: SMB0 (system bits) and the position current values.
    #[inline(never)]
    fn read_only(&self, l: Loc) -> bool {
        if l.area != 4 {
            return false;
        }
        let (lo, hi) = (l.index, l.index + l.width.bytes());
        lo == 0 || self.sim.pto.iter().any(|p| lo < p.regs.pos_cv + 4 && p.regs.pos_cv < hi)
    }

    fn buf(&self, o: &Opd) -> Result<Loc, Fault> {
        engine::loc_of(self, o, DataType::Byte)?
            .filter(|l| matches!(l.width, Width::Byte) && (l.index as usize + 8) <= self.area(l.area).len())
            .ok_or_else(|| Fault::new(FaultKind::BadAddress, msg!("k2-program-clock-buffer")))
    }
}

impl Machine for K2Machine<'_> {
    /// One match on the area (one dispatch per read; the byte areas' width match is
    /// inlined into each arm).
    #[inline(always)]
    fn get(&self, l: Loc) -> u32 {
        let i = l.index as usize;
        let m = &self.sim.mem;
        match l.area {
            0 => take(&m.i, l.width, i),
            1 => take(&m.q, l.width, i),
            2 => take(&m.m, l.width, i),
            3 => take(&m.v, l.width, i),
            4 => take(&m.sm, l.width, i),
            5 => take(&m.ai, l.width, i),
            6 => take(&m.aq, l.width, i),
            7 => m.t.get(i).map_or(0, |v| *v as u16 as u32),
            8 => m.c.get(i).map_or(0, |v| *v as u16 as u32),
            AREA_TQ => m.tq.get(i).map_or(0, |v| *v as u32),
            AREA_CQ => m.cq.get(i).map_or(0, |v| *v as u32),
            _ => 0,
        }
    }

    /// A bit of I, Q, M, V or SM read straight from its byte (no width dispatch); anything else
    /// through [`Machine::get`]. The same bit either way.
    #[inline(always)]
    fn get_bit(&self, l: Loc) -> bool {
        if let Width::Bit(k) = l.width {
            let m = &self.sim.mem;
            let b: &[u8] = match l.area {
                0 => &m.i,
                1 => &m.q,
                2 => &m.m,
                3 => &m.v,
                4 => &m.sm,
                _ => return self.get(l) & 1 != 0,
            };
            return b.get(l.index as usize).is_some_and(|v| v >> k & 1 != 0);
        }
        self.get(l) & 1 != 0
    }

    /// A bit of I, Q or M written straight into its byte (plain memory: no bookkeeping, as in
    /// [`Machine::set`]); anything else through [`Machine::set`].
    #[inline(always)]
    fn set_bit(&mut self, l: Loc, v: bool) {
        if let Width::Bit(k) = l.width {
            let m = &mut self.sim.mem;
            let b: &mut [u8] = match l.area {
                0 => &mut m.i,
                1 => &mut m.q,
                2 => &mut m.m,
                _ => return self.set(l, v as u32),
            };
            if let Some(x) = b.get_mut(l.index as usize) {
                *x = (*x & !(1 << k)) | ((v as u8) << k);
            }
            return;
        }
        self.set(l, v as u32)
    }

    #[inline(always)]
    fn set(&mut self, l: Loc, v: u32) {
        let i = l.index as usize;
        let m = &mut self.sim.mem;
        match l.area {
            // I, Q, M, AI, AQ: plain memory.
            0 => put(&mut m.i, l.width, i, v),
            1 => put(&mut m.q, l.width, i, v),
            2 => put(&mut m.m, l.width, i, v),
            5 => put(&mut m.ai, l.width, i, v),
            6 => put(&mut m.aq, l.width, i, v),
            // V: E2PROM wear is counted for the backup area.
            3 => {
                put(&mut m.v, l.width, i, v);
                if l.index + l.width.bytes() > catalog::EEPROM_FIRST {
                    self.hook(Area::V, l);
                }
            }
            // SM: the CPU owns SMB0 and the position values; writes act like a client's.
            4 => {
                if self.read_only(l) {
                    return;
                }
                put(&mut self.sim.mem.sm, l.width, i, v);
                self.hook(Area::SM, l);
            }
            7 => {
                if let Some(x) = m.t.get_mut(i) {
                    *x = v as u16 as i16
                }
            }
            8 => {
                if let Some(x) = m.c.get_mut(i) {
                    *x = v as u16 as i16
                }
            }
            AREA_TQ => {
                if let Some(x) = m.tq.get_mut(i) {
                    *x = (v & 1) as u8
                }
            }
            AREA_CQ => {
                if let Some(x) = m.cq.get_mut(i) {
                    *x = (v & 1) as u8
                }
            }
            _ => {}
        }
    }

    fn deref(&self, ptr: u32, w: Width) -> Option<Loc> {
        let area = (ptr >> 24).checked_sub(1)? as u8;
        if area > 4 {
            return None;
        }
        let index = ptr & 0x00FF_FFFF;
        let len = self.area(area).len();
        (index as usize + w.bytes() as usize <= len).then_some(Loc { area, width: w, index })
    }

    fn special(&mut self, sid: u16, inst: u32, args: &[Opd], types: &[DataType]) -> Result<bool, Fault> {
        // The operands' values on the stack (no allocation: PSTOP runs every scan of the
        // helper); a K2 instruction has at most 12 operands (PHOME), and `SPECIALS` is the list.
        let mut buf = [0u32; MAX_ARGS];
        for (slot, (a, t)) in buf.iter_mut().zip(args.iter().zip(types)) {
            *slot = engine::read(&*self, a, *t)?;
        }
        let vals = &buf[..args.len().min(MAX_ARGS)];
        let c = |k: usize| -> Result<u32, Fault> { Ok(vals[k]) };
        let now = self.now;
        let sim = &mut *self.sim;
        Ok(match sid {
            id::PLS => {
                // K2 §3.4.2 (IL): «Если CR = 1, то PLS выполняется. Это не повлияет на
                // значение CR.» — PLS runs only with the CR on and leaves it on, refused or
                // not. A refusal shows in the channel's status byte alone: bit 4, "cycle time
                // or pulse count invalid" (§3.4.2.2, SM66.4 …), which `pls` sets.
                let ch = c(0)? as u8;
                if let Ok(i) = sim.pto_index(ch) {
                    let _ = sim.pto[i].pls(&mut sim.mem, now);
                }
                true
            }
            id::HDEF => {
                let (h, mode) = (c(0)? as u8, c(1)? as u8);
                match sim.hsc_index(h) {
                    Ok(i) => sim.hsc[i].hdef(mode).is_ok(),
                    Err(_) => false,
                }
            }
            id::HSC => {
                let h = c(0)? as u8;
                match sim.hsc_index(h) {
                    Ok(i) => sim.hsc[i].hsc(&mut sim.mem).is_ok(),
                    Err(_) => false,
                }
            }
            id::PSTOP => {
                let ch = c(0)? as u8;
                // EXEC's rising edge (or EN's, when EXEC is left out).
                let exec = if args.len() > 1 { c(1)? != 0 } else { true };
                let i = inst as usize;
                if self.inst.len() <= i {
                    self.inst.resize(i + 1, Default::default());
                }
                let rising = exec && !self.inst[i].exec_prev;
                self.inst[i].exec_prev = exec;
                let sim = &mut *self.sim;
                let ok = match sim.pto_index(ch) {
                    Ok(i) => {
                        if rising {
                            sim.pto[i].pstop(&mut sim.mem);
                        }
                        true
                    }
                    Err(_) => false,
                };
                if args.len() > 2 {
                    engine::write(self, &args[2], DataType::Bool, (rising && ok) as u32)?;
                }
                if args.len() > 3 {
                    engine::write(self, &args[3], DataType::Word, if ok { 0 } else { 1 })?;
                }
                ok
            }
            id::READ_RTC => {
                let l = self.buf(&args[0])?;
                let b = self.sim.rtc.read(now).to_bcd8();
                for (k, v) in b.iter().enumerate() {
                    self.set(l.nth(k as u32), *v as u32);
                }
                true
            }
            id::STOP => {
                // Takes effect when the scan (or interrupt routine) ends: program::scan_part.
                sim.stop_requested = true;
                true
            }
            id::SET_RTC => {
                let l = self.buf(&args[0])?;
                let mut b = [0u8; 8];
                for (k, v) in b.iter_mut().enumerate() {
                    *v = self.get(l.nth(k as u32)) as u8;
                }
                match RtcTime::from_bcd8(&b) {
                    Ok(t) if t.validate().is_ok() => {
                        self.sim.rtc.set(t, now);
                        true
                    }
                    _ => false,
                }
            }
            id::PREL..=id::PFLO_F => return self.position(sid, inst, args, vals),
            _ => return Err(Fault::new(FaultKind::Instruction, msg!("k2-program-unknown-instruction", id = sid))),
        })
    }

    /// S7-200 arithmetic status bits SM1.0 zero, SM1.1 overflow, SM1.2 negative, SM1.3
    /// division by zero (the S7-200 convention the K2 SM map follows; not in the K2 manual).
    fn flags(&mut self, f: Flags) {
        let b = &mut self.sim.mem.sm[1];
        *b = (*b & 0xF0) | f.zero as u8 | (f.overflow as u8) << 1 | (f.negative as u8) << 2 | (f.div_zero as u8) << 3;
    }
}
