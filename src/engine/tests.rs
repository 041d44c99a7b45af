//! Engine tests on a toy family (areas I, Q, M, V; 16 timers in three classes; 16
//! counters) — the engine is exercised without any K2 code, which is also the proof that
//! a second family plugs in through [`Family`] and [`Machine`] alone. Golden cases cite
//! the source of each instruction's behaviour.

use super::*;
use crate::core::DataType;

const AREAS: [(&str, u8, usize); 4] = [("I", 0, 4), ("Q", 1, 4), ("M", 2, 64), ("V", 3, 256)];
const T_CV: u8 = 4;
const T_Q: u8 = 5;
const C_CV: u8 = 6;
const C_Q: u8 = 7;

struct Toy;

fn parse_num(s: &str) -> Option<u32> {
    if s.is_empty() || s.len() > 6 {
        return None;
    }
    s.parse().ok()
}

impl Family for Toy {
    fn operand(&self, text: &str) -> Result<Resolved, OperandError> {
        let t = text.trim_start_matches('%').to_ascii_uppercase();
        if let Some(rest) = t.strip_prefix('T').filter(|r| parse_num(r).is_some()) {
            let n = parse_num(rest).unwrap();
            return Ok(Resolved {
                loc: Loc { area: T_Q, width: Width::Bit(0), index: n },
                ty: DataType::Bool,
                canonical: t,
            });
        }
        if let Some(rest) = t.strip_prefix('C').filter(|r| parse_num(r).is_some()) {
            let n = parse_num(rest).unwrap();
            return Ok(Resolved {
                loc: Loc { area: C_Q, width: Width::Bit(0), index: n },
                ty: DataType::Bool,
                canonical: t,
            });
        }
        for (name, area, len) in AREAS {
            let Some(rest) = t.strip_prefix(name) else { continue };
            let (w, ty, rest) = match rest.chars().next() {
                Some('B') => (Width::Byte, DataType::Byte, &rest[1..]),
                Some('W') => (Width::Word, DataType::Int, &rest[1..]),
                Some('D') => (Width::DWord, DataType::DInt, &rest[1..]),
                _ => (Width::Bit(0), DataType::Bool, rest),
            };
            let (rest, ty) = match rest.strip_suffix("/REAL") {
                Some(r) => (r, DataType::Real),
                None => (rest, ty),
            };
            let (idx, w) = if w == Width::Bit(0) {
                let (b, bit) = rest.split_once('.').ok_or_else(|| OperandError::new("bits are BYTE.BIT"))?;
                let bit: u8 = bit.parse().ok().filter(|b| *b < 8).ok_or_else(|| OperandError::new("bit 0…7"))?;
                (parse_num(b).ok_or_else(|| OperandError::new("bad byte"))?, Width::Bit(bit))
            } else {
                (parse_num(rest).ok_or_else(|| OperandError::new("bad address"))?, w)
            };
            if idx as usize + w.bytes() as usize > len {
                return Err(OperandError::new(format!("past the end of {name}")));
            }
            return Ok(Resolved { loc: Loc { area, width: w, index: idx }, ty, canonical: t });
        }
        Err(OperandError::new("no such operand").hint("toy operands: I, Q, M, V, T, C"))
    }

    fn element(&self, text: &str, timer: bool) -> Result<Element, OperandError> {
        let t = text.trim_start_matches('%').to_ascii_uppercase();
        let (p, cv, q) = if timer { ('T', T_CV, T_Q) } else { ('C', C_CV, C_Q) };
        let n = t
            .strip_prefix(p)
            .and_then(parse_num)
            .filter(|n| *n < 16)
            .ok_or_else(|| OperandError::new("T0…T15 / C0…C15"))?;
        // Classes like the K2's: 1 ms, 10 ms, 100 ms.
        let base_ns = if !timer {
            0
        } else if n < 2 {
            1_000_000
        } else if n < 6 {
            10_000_000
        } else {
            100_000_000
        };
        Ok(Element {
            number: n,
            cv: Loc { area: cv, width: Width::Element, index: n },
            q: Loc { area: q, width: Width::Bit(0), index: n },
            base_ns,
        })
    }

    fn pointer(&self, loc: Loc) -> Option<u32> {
        (loc.area <= 3).then_some((loc.area as u32) << 24 | loc.index)
    }

    fn specials(&self) -> &'static [SpecialDef] {
        static S: [SpecialDef; 1] = [SpecialDef {
            name: "BEEP",
            id: 7,
            args: &[ArgKind::Const, ArgKind::Out(Some(DataType::Int))],
            optional: 0,
            edge: true,
            doc: |_| crate::core::msg::Msg { id: "toy", text: "toy: writes its constant to OUT".into() },
            source: "test",
        }];
        &S
    }

    fn costs(&self) -> CostTable {
        CostTable {
            class_ns: [100, 200, 200, 300, 1000, 500, 100, 200, 1000],
            per_element_ns: 10,
            overhead_ns: 50_000,
            min_scan_ns: 0,
            watchdog_ns: 100_000_000,
        }
    }
}

#[derive(Default)]
struct Mem {
    a: [Vec<u8>; 4],
    t: Vec<i16>,
    tq: Vec<bool>,
    c: Vec<i16>,
    cq: Vec<bool>,
    flags: Flags,
    beeps: u32,
    /// Family instructions reached with the enable off.
    offs: u32,
}

impl Mem {
    fn new() -> Mem {
        Mem {
            a: [vec![0; 4], vec![0; 4], vec![0; 64], vec![0; 256]],
            t: vec![0; 16],
            tq: vec![false; 16],
            c: vec![0; 16],
            cq: vec![false; 16],
            ..Mem::default()
        }
    }
}

impl Machine for Mem {
    fn get(&self, l: Loc) -> u32 {
        let i = l.index as usize;
        match l.area {
            T_CV => self.t[i] as u16 as u32,
            T_Q => self.tq[i] as u32,
            C_CV => self.c[i] as u16 as u32,
            C_Q => self.cq[i] as u32,
            a => {
                let m = &self.a[a as usize];
                match l.width {
                    Width::Bit(b) => (m[i] >> b & 1) as u32,
                    Width::Byte => m[i] as u32,
                    Width::Word => u16::from_be_bytes([m[i], m[i + 1]]) as u32,
                    Width::DWord => u32::from_be_bytes([m[i], m[i + 1], m[i + 2], m[i + 3]]),
                    Width::Element => 0,
                }
            }
        }
    }
    fn set(&mut self, l: Loc, v: u32) {
        let i = l.index as usize;
        match l.area {
            T_CV => self.t[i] = v as u16 as i16,
            T_Q => self.tq[i] = v & 1 != 0,
            C_CV => self.c[i] = v as u16 as i16,
            C_Q => self.cq[i] = v & 1 != 0,
            a => {
                let m = &mut self.a[a as usize];
                match l.width {
                    Width::Bit(b) => m[i] = (m[i] & !(1 << b)) | ((v as u8 & 1) << b),
                    Width::Byte => m[i] = v as u8,
                    Width::Word => m[i..i + 2].copy_from_slice(&(v as u16).to_be_bytes()),
                    Width::DWord => m[i..i + 4].copy_from_slice(&v.to_be_bytes()),
                    Width::Element => {}
                }
            }
        }
    }
    fn deref(&self, ptr: u32, w: Width) -> Option<Loc> {
        let area = (ptr >> 24) as u8;
        let index = ptr & 0xFF_FFFF;
        let len = AREAS.get(area as usize)?.2;
        (index as usize + w.bytes() as usize <= len).then_some(Loc { area, width: w, index })
    }
    fn special(&mut self, id: u16, _inst: u32, args: &[Opd], types: &[DataType]) -> Result<bool, Fault> {
        assert_eq!(id, 7);
        self.beeps += 1;
        let v = read(self, &args[0], types[0])?;
        write(self, &args[1], types[1], v)?;
        Ok(true)
    }
    fn special_off(&mut self, id: u16, _inst: u32, _args: &[Opd], _types: &[DataType]) -> Result<bool, Fault> {
        assert_eq!(id, 7);
        self.offs += 1;
        Ok(false)
    }
    fn flags(&mut self, f: Flags) {
        self.flags = f;
    }
}

struct Run {
    prog: Program,
    cpu: Cpu,
    mem: Mem,
    now: u64,
}

fn load(src: &str) -> Run {
    let prog = compile(src, "t.il", &Toy).unwrap_or_else(|e| panic!("{e} ({:?})", e.hint));
    let cpu = Cpu::new(&prog);
    Run { prog, cpu, mem: Mem::new(), now: 0 }
}

fn load_err(src: &str) -> crate::core::Error {
    compile(src, "t.il", &Toy).unwrap_err()
}

impl Run {
    fn scan(&mut self) -> ScanOutcome {
        let o = self.cpu.scan(&self.prog, &mut self.mem, self.now, u64::MAX, None);
        assert!(!matches!(o.exit, exec::Exit::Fault(_)), "{:?}", o.exit);
        o
    }
    fn scan_at_ms(&mut self, ms: u64) {
        self.now = ms * 1_000_000;
        self.scan();
    }
    fn bit(&self, t: &str) -> bool {
        let r = Toy.operand(t).unwrap();
        self.mem.get(r.loc) != 0
    }
    fn set_bit(&mut self, t: &str, on: bool) {
        let r = Toy.operand(t).unwrap();
        self.mem.set(r.loc, on as u32);
    }
    fn val(&self, t: &str) -> i64 {
        let r = Toy.operand(t).unwrap();
        exec_i64(r.ty, self.mem.get(r.loc))
    }
    fn set_val(&mut self, t: &str, v: i64) {
        let r = Toy.operand(t).unwrap();
        self.mem.set(r.loc, v as u32);
    }
}

fn exec_i64(ty: DataType, raw: u32) -> i64 {
    match ty {
        DataType::Bool | DataType::Byte => raw as i64,
        DataType::Int => raw as u16 as i16 as i64,
        _ => raw as i32 as i64,
    }
}

// ---- bit logic (IEC 61131-3 IL; S7-200 stack operations) ------------------------------

#[test]
fn bit_logic_with_the_current_result() {
    // IEC 61131-3 §3.2 (IL): LD/AND/OR/XOR/NOT/ST/STN with the current result.
    let mut r = load(
        "LD %I0.0\nAND %I0.1\nST %Q0.0\nLD %I0.0\nOR %I0.1\nST %Q0.1\nLD %I0.0\nXOR %I0.1\nST %Q0.2\nLDN %I0.0\nSTN %Q0.3\nLD %I0.0\nNOT\nANDN %I0.1\nST %Q0.4",
    );
    for (a, b) in [(false, false), (false, true), (true, false), (true, true)] {
        r.set_bit("I0.0", a);
        r.set_bit("I0.1", b);
        r.scan();
        assert_eq!(r.bit("Q0.0"), a && b, "AND {a} {b}");
        assert_eq!(r.bit("Q0.1"), a || b, "OR");
        assert_eq!(r.bit("Q0.2"), a ^ b, "XOR");
        assert_eq!(r.bit("Q0.3"), a, "STN of LDN");
        assert_eq!(r.bit("Q0.4"), !a && !b, "NOT, ANDN");
    }
}

#[test]
fn parentheses_and_the_logic_stack() {
    // IEC: Q0.0 := I0.0 AND (I0.1 OR I0.2); S7-200: Q0.1 := (I0.0 OR I0.1) AND (I0.2 OR I0.3) by ALD.
    let mut r = load(
        "LD %I0.0\nAND( %I0.1\nOR %I0.2\n)\nST %Q0.0\nLD %I0.0\nO %I0.1\nLD %I0.2\nO %I0.3\nALD\n= %Q0.1\nLD %I0.0\nANDN(\nLD %I0.1\n)\nST %Q0.2",
    );
    for bits in 0..16u8 {
        let b: Vec<bool> = (0..4).map(|k| bits >> k & 1 != 0).collect();
        for (k, v) in b.iter().enumerate() {
            r.set_bit(&format!("I0.{k}"), *v);
        }
        r.scan();
        assert_eq!(r.bit("Q0.0"), b[0] && (b[1] || b[2]), "{bits:04b}");
        assert_eq!(r.bit("Q0.1"), (b[0] || b[1]) && (b[2] || b[3]), "{bits:04b}");
        assert_eq!(r.bit("Q0.2"), b[0] && !b[1], "{bits:04b}");
    }
}

#[test]
fn set_reset_and_edges() {
    // IEC S/R; R_TRIG/F_TRIG (K2 §3.4.3.1 uses R_TRIG to make a one-scan pulse).
    let mut r = load("LD %I0.0\nS %M0.0, 3\nLD %I0.1\nR %M0.1\nLD %I0.2\nR_TRIG\nST %Q0.0\nLD %I0.2\nF_TRIG\nST %Q0.1");
    r.set_bit("I0.0", true);
    r.scan();
    assert_eq!(r.val("MB0"), 0b111, "S M0.0, 3 sets three bits");
    r.set_bit("I0.1", true);
    r.scan();
    assert_eq!(r.val("MB0"), 0b101);
    r.set_bit("I0.2", true);
    r.scan();
    assert!(r.bit("Q0.0"), "rising edge on the first scan the input is on");
    r.scan();
    assert!(!r.bit("Q0.0"), "one scan only");
    r.set_bit("I0.2", false);
    r.scan();
    assert!(r.bit("Q0.1"), "falling edge");
    r.scan();
    assert!(!r.bit("Q0.1"));
}

// ---- comparisons, moves, arithmetic (S7-200 / IEC) -----------------------------------

#[test]
fn comparisons_int_dint_real() {
    let mut r = load(
        "LDW> %VW0, 100\nST %Q0.0\nLDD< %VD4, -70000\nST %Q0.1\nLDR>= %VD8/REAL, 1.5\nST %Q0.2\nLD %I0.0\nAW= %VW0, 101\nST %Q0.3\nLDB<> %VB20, 16#FF\nOW= %VW0, 0\nST %Q1.0",
    );
    r.set_val("VW0", 101);
    r.set_val("VD4", -70001);
    r.mem.set(Toy.operand("VD8").unwrap().loc, 1.5f32.to_bits());
    r.set_val("VB20", 0xFF);
    r.set_bit("I0.0", true);
    r.scan();
    assert!(r.bit("Q0.0"), "101 > 100 (INT)");
    assert!(r.bit("Q0.1"), "-70001 < -70000 (DINT)");
    assert!(r.bit("Q0.2"), "1.5 >= 1.5 (REAL)");
    assert!(r.bit("Q0.3"), "AW=");
    assert!(!r.bit("Q1.0"), "16#FF <> 16#FF is false, VW0 = 0 is false");
    r.set_val("VW0", -1);
    r.scan();
    assert!(!r.bit("Q0.0"), "INT compares are signed: -1 < 100");
    assert!(r.bit("Q1.0") == (r.val("VW0") == 0), "OW=");
}

#[test]
fn moves_run_only_when_the_cr_is_on() {
    // K2 §3.4.3.1: LD %M0.4 / R_TRIG / MOVE DI#100, %SMD208 / ST %SM201.4 — MOVE has EN = CR
    // and passes the CR on as ENO.
    let mut r = load("LD %M0.4\nR_TRIG\nMOVE DI#100, %VD8\nST %M1.4");
    r.scan();
    assert_eq!(r.val("VD8"), 0, "CR off: no move");
    r.set_bit("M0.4", true);
    r.scan();
    assert_eq!(r.val("VD8"), 100);
    assert!(r.bit("M1.4"), "ENO carried to ST");
    r.scan();
    assert!(!r.bit("M1.4"), "one scan after the edge");
}

#[test]
fn block_moves_fill_and_pointers() {
    let mut r = load(
        "LD %I0.0\nBLKMOVE %VB0, %VB10, 4\nFILL 7, %VW20, 3\nMOVE &VB40, %VD100\nMOVE &VB50, %VD104\nMOVE *%VD100, *%VD104\nADD 1, %VD100",
    );
    r.set_bit("I0.0", true);
    for (k, b) in [1u8, 2, 3, 4].iter().enumerate() {
        r.mem.a[3][k] = *b;
    }
    r.mem.a[3][40] = 0xAB;
    r.scan();
    assert_eq!(&r.mem.a[3][10..14], &[1, 2, 3, 4]);
    assert_eq!((r.val("VW20"), r.val("VW22"), r.val("VW24")), (7, 7, 7));
    assert_eq!(r.val("VB50"), 0xAB, "MOVE *VD100, *VD104 copies one byte");
    assert_eq!(r.val("VD100"), (3 << 24 | 41) as i64, "pointer arithmetic");
}

#[test]
fn arithmetic_with_flags() {
    // S7-200: OUT := OUT op IN; overflow wraps and sets SM1.1; ÷0 sets SM1.3, ENO = 0.
    let mut r = load(
        "LD %I0.0\nADD 1, %VW0\nSUB %VW0, 3, %VW2\nMUL 1000, %VD20\nDIV 0, %VW6\nST %Q0.0\nLD %I0.0\nMOD 3, %VW8\nINC %VB10\nDEC %VW12\nADD 1, %VW14\nLD %I0.0\n+R 0.25, %VD16/REAL",
    );
    r.set_bit("I0.0", true);
    r.set_val("VD20", 5);
    r.set_val("VW6", 9);
    r.set_val("VW8", 11);
    r.set_val("VW14", 32767);
    r.mem.set(Toy.operand("VD16").unwrap().loc, 1.0f32.to_bits());
    r.scan();
    assert_eq!(r.val("VW0"), 1);
    assert_eq!(r.val("VW2"), -2, "IN1 − IN2");
    assert_eq!(r.val("VD20"), 5000, "DINT multiply");
    assert_eq!(r.val("VW6"), 9, "÷0 leaves the output");
    assert!(!r.bit("Q0.0"), "÷0: ENO = 0");
    assert_eq!(r.val("VW8"), 2);
    assert_eq!(r.val("VB10"), 1);
    assert_eq!(r.val("VW12"), -1);
    assert_eq!(r.val("VW14"), -32768, "INT overflow wraps");
    let mut o = load("LD %I0.0\nADD 1, %VW14\nST %Q0.1");
    o.set_bit("I0.0", true);
    o.set_val("VW14", 32767);
    o.scan();
    assert!(o.mem.flags.overflow && o.mem.flags.negative, "…and is flagged (S7-200 SM1.1, SM1.2)");
    assert!(!o.bit("Q0.1"), "overflow: ENO = 0");
    assert_eq!(f32::from_bits(r.mem.get(Toy.operand("VD16").unwrap().loc)), 1.25);
}

#[test]
fn shifts_word_logic_conversions_bcd() {
    let mut r = load(
        "LD %I0.0\nSHL %VW0, 4\nSHR %VB2, 1\nROL %VW4, 4\nROR %VB6, 1\nWAND 16#0F0F, %VW8\nWOR 16#00F0, %VW8\nWXOR 16#FFFF, %VW10\nINV %VB12\nI_DI %VW14, %VD16\nDI_I %VD20, %VW24\nST %Q0.0\nLD %I0.0\nI_BCD %VW26, %VW28\nBCD_I %VW30, %VW32\nDI_R %VD16, %VD36/REAL\nROUND %VD40/REAL, %VD44\nTRUNC %VD40/REAL, %VD48",
    );
    r.set_bit("I0.0", true);
    r.set_val("VW0", 0x0123);
    r.set_val("VB2", 0x81);
    r.set_val("VW4", 0x1234);
    r.set_val("VB6", 0x01);
    r.set_val("VW8", 0xFFFF);
    r.set_val("VW10", 0x00FF);
    r.set_val("VB12", 0x0F);
    r.set_val("VW14", -5i64 as u16 as i64);
    r.set_val("VD20", 40000);
    r.set_val("VW26", 1234);
    r.set_val("VW30", 0x9876);
    r.mem.set(Toy.operand("VD40").unwrap().loc, (-2.5f32).to_bits());
    r.scan();
    assert_eq!(r.val("VW0"), 0x1230);
    assert_eq!(r.val("VB2"), 0x40);
    assert_eq!(r.val("VW4"), 0x2341);
    assert_eq!(r.val("VB6"), 0x80);
    assert_eq!(r.val("VW8"), 0x0FFF);
    assert_eq!(r.val("VW10") as u16, 0xFF00);
    assert_eq!(r.val("VB12"), 0xF0);
    assert_eq!(r.val("VD16"), -5, "I_DI sign-extends");
    assert_eq!(r.val("VW24"), 0, "DI_I out of range leaves the output");
    assert!(!r.bit("Q0.0"), "…with ENO = 0");
    assert_eq!(r.val("VW28"), 0x1234, "I_BCD");
    assert_eq!(r.val("VW32"), 9876, "BCD_I");
    assert_eq!(f32::from_bits(r.mem.get(Toy.operand("VD36").unwrap().loc)), -5.0);
    assert_eq!(r.val("VD44"), -3, "ROUND half away from zero");
    assert_eq!(r.val("VD48"), -2, "TRUNC");
}

// ---- jumps, calls, returns -----------------------------------------------------------

#[test]
fn jumps_loops_calls_and_returns() {
    let mut r = load(
        "PROGRAM MAIN\nLD %I0.0\nMOVE 10, %VW0\nLOOP:\nLD %I0.0\nADD 1, %VW2\nSUB 1, %VW0\nLDW> %VW0, 0\nJMPC LOOP\nLD %I0.0\nCAL SUB1\nLD %I0.0\nJMPCN SKIP\nMOVE 1, %VW4\nSKIP:\nEND_PROGRAM\nSUBROUTINE SUB1\nLD %I0.0\nADD 100, %VW6\nRETC\nMOVE 99, %VW8\nEND_SUBROUTINE",
    );
    r.set_bit("I0.0", true);
    r.scan();
    assert_eq!(r.val("VW2"), 10, "ten times round the loop");
    assert_eq!(r.val("VW6"), 100, "the subroutine ran");
    assert_eq!(r.val("VW8"), 0, "RETC returned before the MOVE");
    assert_eq!(r.val("VW4"), 1, "JMPCN did not jump with the CR on");
}

#[test]
fn a_family_instruction_runs_on_its_enable_edge() {
    let mut r = load("LD %I0.0\nBEEP 42, %VW0");
    r.scan();
    r.set_bit("I0.0", true);
    r.scan();
    r.scan();
    assert_eq!((r.mem.beeps, r.val("VW0")), (1, 42), "edge-triggered: once while the enable stays on");
}

#[test]
fn a_family_instruction_hears_of_its_enable_off() {
    // An instruction whose input is the CR (the UMPK's timers) must see the input go off.
    let mut r = load("LD %I0.0\nBEEP 42, %VW0\nST %Q0.0");
    r.scan();
    assert_eq!((r.mem.beeps, r.mem.offs, r.bit("Q0.0")), (0, 1, false), "enable off: special_off, ENO off");
    r.set_bit("I0.0", true);
    r.scan();
    r.scan();
    assert_eq!((r.mem.beeps, r.mem.offs), (1, 1), "enable on: special on its edge, special_off not called");
    r.set_bit("I0.0", false);
    r.scan();
    assert_eq!(r.mem.offs, 2);
}

// ---- timers (K80S; K2 §2.1.2 classes) ------------------------------------------------

/// Runs `src` with I0.0 following `input(ms)` in scans every `scan_ms`, returning (ms, T.Q, T.CV) samples.
fn trace(src: &str, scan_ms: u64, until: u64, input: impl Fn(u64) -> bool) -> Vec<(u64, bool, i64)> {
    let mut r = load(src);
    let mut out = Vec::new();
    let mut t = 0;
    while t <= until {
        r.set_bit("I0.0", input(t));
        r.scan_at_ms(t);
        out.push((
            t,
            r.bit("Q0.0"),
            r.mem.t[r
                .prog
                .code
                .iter()
                .find_map(|i| if let compile::Ins::Timer { el, .. } = i { Some(el.number as usize) } else { None })
                .unwrap()] as i64,
        ));
        t += scan_ms;
    }
    out
}

fn q_at(tr: &[(u64, bool, i64)], ms: u64) -> bool {
    tr.iter().find(|s| s.0 == ms).unwrap().1
}

#[test]
fn ton_at_each_resolution_class() {
    // K80S TON: on-delay; output when the elapsed time reaches the preset; input off resets.
    for (timer, pt, base_ms) in [("T0", 50, 1), ("T2", 5, 10), ("T6", 2, 100)] {
        let src = format!("LD %I0.0\nTON {timer}, {pt}\nST %Q0.0");
        let tr = trace(&src, 1, 400, |t| (10..=300).contains(&t));
        let delay = pt * base_ms;
        assert!(!q_at(&tr, 10 + delay - 1), "{timer}: not before {delay} ms");
        assert!(q_at(&tr, 10 + delay), "{timer}: on at {delay} ms");
        assert!(q_at(&tr, 300));
        assert!(!q_at(&tr, 301), "{timer}: off with the input");
        assert_eq!(tr.last().unwrap().2, 0, "value reset");
    }
}

#[test]
fn ton_preset_as_a_time_literal() {
    let tr = trace("LD %I0.0\nTON T2, T#200ms\nST %Q0.0", 10, 300, |t| t >= 10);
    assert!(!q_at(&tr, 200) && q_at(&tr, 210), "T#200ms on a 10 ms timer = 20 units");
}

#[test]
fn tof_and_toff_off_delay() {
    // K80S TOFF / K2 TOF: on with the input, off the preset after the input goes off.
    for m in ["TOF", "TOFF"] {
        let tr = trace(&format!("LD %I0.0\n{m} T2, 10\nST %Q0.0"), 10, 400, |t| (20..=100).contains(&t));
        assert!(!q_at(&tr, 10));
        assert!(q_at(&tr, 20) && q_at(&tr, 100));
        assert!(q_at(&tr, 200), "{m}: still on 90 ms after the input dropped");
        assert!(!q_at(&tr, 210), "{m}: off 100 ms after");
    }
}

#[test]
fn tp_and_tmon_ignore_the_input_during_the_pulse() {
    // IEC TP / K80S TMON: a rising input starts a pulse of the preset; input ignored meanwhile.
    for m in ["TP", "TMON"] {
        let input = |t: u64| (10..=20).contains(&t) || (50..=60).contains(&t) || (200..=400).contains(&t);
        let tr = trace(&format!("LD %I0.0\n{m} T2, 10\nST %Q0.0"), 10, 400, input);
        assert!(q_at(&tr, 10) && q_at(&tr, 100), "{m}: on for 100 ms from the first edge");
        assert!(!q_at(&tr, 110), "{m}: the second edge inside the pulse did not extend it");
        assert!(q_at(&tr, 200) && !q_at(&tr, 300), "{m}: a long input still gives one pulse");
    }
}

#[test]
fn trtg_retriggers() {
    // K80S TRTG: each rising input reloads the timer.
    let input = |t: u64| t == 10 || t == 80 || t == 150;
    let tr = trace("LD %I0.0\nTRTG T2, 10\nST %Q0.0", 10, 400, input);
    assert!(q_at(&tr, 10) && q_at(&tr, 100) && q_at(&tr, 240), "re-triggered at 80 and 150 ms");
    assert!(!q_at(&tr, 250), "off 100 ms after the last trigger");
}

#[test]
fn tmr_accumulates_and_resets() {
    // K80S TMR: accumulates while on, keeps the value while off, reset clears.
    let input = |t: u64| (0..50).contains(&t) || (100..160).contains(&t);
    let src = "LD %I0.0\nTMR T2, 10, %I0.1\nST %Q0.0";
    let tr = trace(src, 10, 300, input);
    assert!(!q_at(&tr, 140), "50 + 40 ms accumulated");
    assert!(q_at(&tr, 150), "on after 50 + 50 ms of input");
    assert!(q_at(&tr, 300), "stays on with the input off");
    let mut r = load(src);
    r.set_bit("I0.0", true);
    r.scan_at_ms(0);
    r.scan_at_ms(50);
    assert_eq!(r.mem.t[2], 5);
    r.set_bit("I0.1", true);
    r.scan_at_ms(60);
    assert_eq!(r.mem.t[2], 0, "reset input");
}

#[test]
fn a_written_timer_value_continues_and_r_clears() {
    let mut r = load("LD %I0.0\nTON T6, 100\nST %Q0.0\nLD %I0.1\nR T6");
    r.set_bit("I0.0", true);
    r.scan_at_ms(0);
    r.mem.t[6] = 99;
    r.scan_at_ms(100);
    assert!(r.bit("Q0.0"), "continued from the written value");
    r.set_bit("I0.1", true);
    r.scan_at_ms(110);
    assert_eq!((r.mem.t[6], r.mem.tq[6]), (0, false));
}

// ---- counters (K80S) -----------------------------------------------------------------

fn pulses(r: &mut Run, bit: &str, n: usize) {
    for _ in 0..n {
        r.set_bit(bit, true);
        r.scan();
        r.set_bit(bit, false);
        r.scan();
    }
}

#[test]
fn ctu_ctd_ctud_ctr() {
    // K80S CTU: on at the preset; reset clears.
    let mut r = load("LD %I0.0\nCTU C1, 3, %I0.7\nST %Q0.0");
    pulses(&mut r, "I0.0", 2);
    assert!(!r.bit("Q0.0"));
    pulses(&mut r, "I0.0", 1);
    assert!(r.bit("Q0.0") && r.mem.c[1] == 3);
    r.set_bit("I0.7", true);
    r.scan();
    assert!(!r.bit("Q0.0") && r.mem.c[1] == 0);
    // K80S CTD: the load input loads the preset; on when the count reaches 0.
    let mut r = load("LD %I0.0\nCTD C2, 2, %I0.7\nST %Q0.0");
    r.set_bit("I0.7", true);
    r.scan();
    r.set_bit("I0.7", false);
    assert_eq!(r.mem.c[2], 2);
    pulses(&mut r, "I0.0", 1);
    assert!(!r.bit("Q0.0"));
    pulses(&mut r, "I0.0", 2);
    assert!(r.bit("Q0.0") && r.mem.c[2] == 0, "stops at 0");
    // K80S CTUD: two inputs, on while count ≥ preset.
    let mut r = load("LD %I0.0\nCTUD C3, 2, %I0.1\nST %Q0.0");
    pulses(&mut r, "I0.0", 3);
    assert!(r.bit("Q0.0") && r.mem.c[3] == 3);
    pulses(&mut r, "I0.1", 2);
    assert!(!r.bit("Q0.0") && r.mem.c[3] == 1);
    // K80S CTR: ring — on at the preset, the next edge clears to 0.
    let mut r = load("LD %I0.0\nCTR C4, 3\nST %Q0.0");
    pulses(&mut r, "I0.0", 3);
    assert!(r.bit("Q0.0") && r.mem.c[4] == 3);
    pulses(&mut r, "I0.0", 1);
    assert!(!r.bit("Q0.0") && r.mem.c[4] == 0);
    pulses(&mut r, "I0.0", 3);
    assert!(r.bit("Q0.0"));
}

// ---- interrupts, watchdog, debugging --------------------------------------------------

#[test]
fn attached_routines_run_when_enabled() {
    let mut r = load("PROGRAM MAIN\nLD %I0.0\nATCH ON_EDGE, 3\nENI\nEND_PROGRAM\nINTERRUPT ON_EDGE\nLD %I0.0\nINC %VW0\nEND_INTERRUPT");
    assert_eq!(r.cpu.handler(3), None);
    r.set_bit("I0.0", true);
    r.scan();
    let pou = r.cpu.handler(3).expect("attached and enabled");
    let o = r.cpu.interrupt(&r.prog, &mut r.mem, pou, 5);
    assert_eq!(o.exit, exec::Exit::Done);
    assert_eq!(r.val("VW0"), 1);
}

#[test]
fn an_endless_loop_trips_the_watchdog() {
    let mut r = load("L: LD %I0.0\nJMP L");
    let o = r.cpu.scan(&r.prog, &mut r.mem, 0, u64::MAX, None);
    match o.exit {
        exec::Exit::Fault(f) => {
            assert_eq!(f.kind, FaultKind::Watchdog);
            assert_eq!((f.line, f.instruction.as_str()), (2, "JMP L"), "checked at the jump");
        }
        e => panic!("{e:?}"),
    }
    assert!(o.cost_ns > 100_000_000);
}

#[test]
fn wdt_restarts_the_watchdog_count() {
    // K80S: WDT restarts the watchdog; a long but finite loop with WDT completes.
    let mut r = load("LDN %I0.0\nMOVE 100000, %VD0\nL: LD %I0.0\nNOT\nSUB 1, %VD0\nWDT\nLDD> %VD0, 0\nJMPC L");
    let o = r.cpu.scan(&r.prog, &mut r.mem, 0, u64::MAX, None);
    assert_eq!(o.exit, exec::Exit::Done, "{:?}", o.exit);
    assert!(o.cost_ns > 100_000_000, "longer than the watchdog in all");
}

#[test]
fn stepping_stops_and_resumes() {
    let mut r = load("LD %I0.0\nST %Q0.0\nLD %I0.1\nST %Q0.1");
    r.set_bit("I0.0", true);
    let o = r.cpu.scan(&r.prog, &mut r.mem, 0, 2, None);
    assert_eq!(o.exit, exec::Exit::Paused(2));
    assert!(r.bit("Q0.0") && r.cpu.cr);
    let mut brk = vec![false; r.prog.code.len()];
    brk[3] = true;
    let o = r.cpu.scan(&r.prog, &mut r.mem, 0, u64::MAX, Some(&brk));
    assert_eq!(o.exit, exec::Exit::Paused(3), "breakpoint on the fourth instruction");
    let o = r.cpu.scan(&r.prog, &mut r.mem, 0, u64::MAX, Some(&brk));
    assert_eq!(o.exit, exec::Exit::Done, "resumed past the breakpoint");
}

/// The interpreter adds the cost table per straight run of instructions (prefix sums), not
/// instruction by instruction. The scan's program time and instruction count must be the
/// sums over the instructions executed, through jumps taken and not taken, calls, a
/// conditional return, a WDT and the end: stepping one instruction at a time (each pause
/// names the next instruction) adds the table entry by entry, and the free-running scan
/// must reach the same totals. Costs differ per class, so a run counted wrong shows. A
/// scan resumed inside the subroutine returns into the main program and runs it to its end.
#[test]
fn a_scans_time_and_count_are_the_sums_over_the_instructions_executed() {
    let src = "PROGRAM MAIN\nLD %I0.0\nMOVE 3, %VW0\nLOOP:\nLD %I0.0\nADD 1, %VW2\nSUB 1, %VW0\nLDW> %VW0, 0\nJMPC LOOP\nLD %I0.0\nCAL SUB1\nWDT\nLD %I0.0\nJMPCN SKIP\nMOVE 1, %VW4\nSKIP:\nEND_PROGRAM\nSUBROUTINE SUB1\nLD %I0.0\nADD 100, %VW6\nRETC\nMOVE 99, %VW8\nEND_SUBROUTINE";
    for on in [false, true] {
        let mut free = load(src);
        free.set_bit("I0.0", on);
        let whole = free.scan();
        let mut step = load(src);
        step.set_bit("I0.0", on);
        let (mut n, mut ns, mut table) = (0, 0, 0u64);
        let mut pc = step.prog.main().entry as usize;
        loop {
            let o = step.cpu.scan(&step.prog, &mut step.mem, 0, 1, None);
            assert_eq!(o.instructions, 1, "one instruction per step");
            n += o.instructions;
            ns += o.cost_ns;
            table += step.prog.cost[pc] as u64;
            match o.exit {
                exec::Exit::Paused(next) => pc = next as usize,
                exec::Exit::Done => break,
                exec::Exit::Fault(f) => panic!("{f}"),
            }
        }
        assert!(n > 10, "{n} instructions");
        assert_eq!(whole.instructions, n, "I0.0 = {on}: instructions");
        assert_eq!(ns, table, "I0.0 = {on}: stepped time is the table's sum");
        assert_eq!(whole.cost_ns, table, "I0.0 = {on}: program time");
        assert_eq!(free.cpu.spent_ns, table);
        assert_eq!(free.cpu.executed, n);
    }
}

/// Every instruction of a program is one element of a flat vector: keep it small (the
/// timer's and counter's locations are boxed; an unboxed element made each one about 80 bytes).
#[test]
fn an_instruction_is_at_most_48_bytes() {
    assert!(
        std::mem::size_of::<crate::engine::compile::Ins>() <= 48,
        "{}",
        std::mem::size_of::<crate::engine::compile::Ins>()
    );
}

// ---- load errors ----------------------------------------------------------------------

#[test]
fn load_errors_name_file_line_column_and_a_suggestion() {
    let e = load_err("LD %I0.0\n  LDD %I0.1");
    assert!(e.message.starts_with("t.il:2:3: unknown instruction LDD"), "{}", e.message);
    assert!(e.hint.as_deref().unwrap().contains("did you mean"), "{:?}", e.hint);
    let e = load_err("LD %I0.0\nST %X0.0");
    assert!(e.message.starts_with("t.il:2:4:"), "{}", e.message);
    assert!(e.hint.as_deref().unwrap().contains("toy operands"));
    let e = load_err("JMP LOPP\nLOOP:");
    assert!(e.message.contains("no label LOPP"), "{}", e.message);
    assert_eq!(e.hint.as_deref(), Some("did you mean LOOP?"));
    let e = load_err("ADD %VW0, %VD4");
    assert!(
        e.message.contains("is a INT") || e.message.contains("is an INT") || e.message.contains("INT but"),
        "{}",
        e.message
    );
    assert!(e.hint.as_deref().unwrap().contains("I_DI"), "{:?}", e.hint);
    let e = load_err("MOVE 300, %VB0");
    assert!(e.message.starts_with("t.il:1:6:"), "{}", e.message);
    let e = load_err("CAL NOPE");
    assert!(e.message.contains("no subroutine"), "{}", e.message);
    assert!(load_err("LD %VW0").message.contains("not a bit"));
    assert!(load_err("TON T99, 5").message.contains("T99"));
    assert!(load_err("MOVE 1").message.contains("takes 2"));
    assert!(load_err("MOVE 1, 2").message.contains("cannot be written"));
    assert!(load_err("ST").message.contains("takes 1"));
}

#[test]
fn hostile_text_never_panics() {
    let samples = [
        "",
        "\n\n",
        "LD",
        "LD %",
        "LD %I",
        "LD %I9.9",
        "MOVE *%VW0, %VB0",
        "MOVE &T0, %VD0",
        "TON",
        "S %M0.0, 0",
        "S %M0.0, 999",
        "BLKMOVE %VB0, %VB1, 0",
        "ATCH X, 99999",
        "LDW= 1",
        ")",
        "AND(",
        "X:\nX:",
        "PROGRAM\n",
        "SUBROUTINE A\nSUBROUTINE A",
        "MOVE T#5s, %VW0",
        "MOVE 1e99, %VD0/REAL",
        "MOVE REAL#nan, %VW0",
        "LD %I0.0 %I0.1",
        "ADD 1, 2, 3, 4",
        "\u{feff}LD %I0.0",
        "LD %Ι0.0",
        "CTUD C1, 2",
    ];
    for s in samples {
        let _ = compile(s, "x.il", &Toy);
    }
}

#[test]
fn every_timer_kind_at_every_resolution_class() {
    // K80S kinds (TON, TOFF, TMR, TMON, TRTG) and K2/IEC TON, TOF, TP, each on a 1 ms, a
    // 10 ms and a 100 ms timer (the toy family's classes mirror the K2's), preset 5 units.
    for (timer, base) in [("T0", 1u64), ("T2", 10), ("T6", 100)] {
        let d = 5 * base;
        for kind in ["TON", "TOF", "TOFF", "TP", "TMR", "TMON", "TRTG"] {
            let src = format!("LD %I0.0\n{kind} {timer}, 5\nST %Q0.0");
            let off_delay = kind == "TOF" || kind == "TOFF";
            // Input on for 3·d from t = 10 (off-delay timers: on for d, then off).
            let on_until = if off_delay { 10 + d } else { 10 + 3 * d };
            let tr = trace(&src, 1, 10 + 6 * d, |t| (10..=on_until).contains(&t));
            let what = format!("{kind} {timer} ({base} ms)");
            match kind {
                "TON" | "TMR" => {
                    assert!(!q_at(&tr, 10 + d - 1) && q_at(&tr, 10 + d), "{what}: on after {d} ms");
                    assert!(q_at(&tr, on_until), "{what}");
                }
                "TOF" | "TOFF" => {
                    assert!(q_at(&tr, 10) && q_at(&tr, on_until), "{what}: on with the input");
                    let fall = on_until + 1;
                    assert!(q_at(&tr, fall + d - 1) && !q_at(&tr, fall + d), "{what}: off {d} ms after the input");
                }
                _ => {
                    assert!(q_at(&tr, 10) && q_at(&tr, 10 + d - 1), "{what}: on at the edge for {d} ms");
                    assert!(!q_at(&tr, 10 + d), "{what}: off after {d} ms although the input stays on");
                }
            }
        }
    }
}
