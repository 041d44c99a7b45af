//! Lab programs in IL for the simulated UMPK, run on the family-neutral scan engine
//! ([`crate::engine`]) with the UMPK's variables and semantics. The UMPK's own language is
//! not published (so a vendor binary is stored, not executed); this is what the simulator
//! executes instead, once per 10 ms cycle in Work mode (manual §1, Table 1 row 11).
//!
//! * Operands are the UMPK's bits, resolved through [`UmpkSpace`] (model-bounded): `I0…`,
//!   `Q0…`, `M0…`, `T0…` (a timer's output), `C0…C3` (a counter's output pulse). A program
//!   assigns only outputs and markers; `ST I3`, `S T0` … are refused at load time.
//! * `TIMER Tn, GROUP, STEPS` — the on-delay timer (§3.5, Table 5): its input is the CR, its
//!   delay STEPS (1–255) of GROUP (0: 10 ms, 1: 0.1 s, 2: 1 s); afterwards the CR is Tn.
//!   It runs through [`Logic::set_timer`] and [`Scan::timer`], so it counts cycles exactly
//!   as the reference programs' timers do.
//! * `DIVIDE Cn, RATIO[, RESET]` — the divide-by-N counter (§3.5): counts rising edges of
//!   the CR; the RATIO-th (1–255) passes as an output pulse exactly as long as that input
//!   pulse; the RESET bit, while on, is the program reset (count and output cleared).
//!
//! Both act whenever they are reached, with the CR on or off (an on-delay timer must see
//! its input go off), through [`Machine::special_off`]. The cost of a cycle comes from the
//! engine's cost table ([`costs`]: estimates, the manual gives no instruction times) and
//! is reported in the timing figures (§4.1.13) through [`Runner::cost_counts`].

use super::logic::{Group, Runner, Scan, CYCLE_MS};
use crate::core::{DataType, Error, ErrorKind, OperandSpace, Result};
use crate::engine::compile::Ins;
use crate::engine::{
    self, ArgKind, CostTable, Cpu, Element, Family, Fault, Loc, Machine, Opd, OperandError, Program, Resolved,
    SpecialDef, Width,
};
use crate::msg;
use crate::umpk::codec::syserr;
use crate::umpk::model::Model;
use crate::umpk::space::{UmpkOperand, UmpkSpace, AREAS};

/// Family instruction ids.
pub mod id {
    pub const TIMER: u16 = 1;
    pub const DIVIDE: u16 = 2;
    pub const ERROR: u16 = 3;
}

/// The UMPK's own instructions (manual §3.5, Table 5).
pub static SPECIALS: &[SpecialDef] = &[
    SpecialDef {
        name: "TIMER",
        id: id::TIMER,
        args: &[ArgKind::Bit, ArgKind::Const, ArgKind::Const],
        optional: 0,
        edge: false,
        doc: |l| msg!(lang: l, "engine-doc-umpk-timer"),
        source: "UMPK §3.5, Table 5",
    },
    SpecialDef {
        name: "DIVIDE",
        id: id::DIVIDE,
        args: &[ArgKind::Bit, ArgKind::Const, ArgKind::Bit],
        optional: 1,
        edge: false,
        doc: |l| msg!(lang: l, "engine-doc-umpk-divide"),
        source: "UMPK §3.5",
    },
    SpecialDef {
        name: "ERROR",
        id: id::ERROR,
        args: &[ArgKind::Const],
        optional: 0,
        edge: true,
        doc: |l| msg!(lang: l, "engine-doc-umpk-error"),
        source: "UMPK §4.1.8 (codes 1–127 are the user's); the instruction is plcsh's",
    },
];

/// Area numbers of [`Loc`]s: the index into [`AREAS`] (I, Q, T, C, M).
fn area_of(letter: char) -> u8 {
    AREAS.iter().position(|a| a.letter == letter).unwrap_or(0) as u8
}

fn loc(op: UmpkOperand) -> Loc {
    let n = op.index as u32;
    Loc { area: op.area as u8, width: Width::Bit((n % 8) as u8), index: n / 8 }
}

fn operand_of(l: Loc) -> Option<UmpkOperand> {
    let Width::Bit(b) = l.width else { return None };
    let n = l.index * 8 + b as u32;
    (n < 256 && (l.area as usize) < AREAS.len()).then_some(UmpkOperand { area: l.area as usize, index: n as u8 })
}

/// Default costs (estimates for an 8-bit controller; the manual gives none): bit 2 µs,
/// compare 5 µs, move 5 µs, arithmetic 8 µs, REAL 50 µs, timer/counter 10 µs, jump 2 µs,
/// call 5 µs, family instruction 10 µs. The firmware's own share is separate (the timing
/// reply's first figure). Minimum scan: the 10 ms cycle; watchdog: a program that does not
/// fit in the cycle stops.
pub fn costs() -> CostTable {
    CostTable {
        class_ns: [2_000, 5_000, 5_000, 8_000, 50_000, 10_000, 2_000, 5_000, 10_000],
        per_element_ns: 1_000,
        overhead_ns: 0,
        min_scan_ns: CYCLE_MS * 1_000_000,
        watchdog_ns: CYCLE_MS * 1_000_000,
    }
}

/// The UMPK operand space as the engine sees it.
pub struct UmpkFamily {
    pub space: UmpkSpace,
}

impl UmpkFamily {
    pub fn new(model: &'static Model) -> UmpkFamily {
        UmpkFamily { space: UmpkSpace { model } }
    }
}

impl Family for UmpkFamily {
    fn operand(&self, text: &str) -> Result<Resolved, OperandError> {
        let ops = self.space.parse(text).map_err(|e| {
            let mut o = OperandError::new(e.message.clone());
            o.hint = e.hint.clone();
            o
        })?;
        let [one] = ops.as_slice() else {
            return Err(OperandError::new(msg!("umpk-il-range", text = text).text));
        };
        let op = UmpkOperand::from_core(one);
        Ok(Resolved { loc: loc(op), ty: DataType::Bool, canonical: op.name() })
    }

    fn element(&self, text: &str, _want_timer: bool) -> Result<Element, OperandError> {
        Err(OperandError::new(msg!("umpk-il-elements", text = text).text).hint(msg!("umpk-il-hint-elements").text))
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
        // The UMPK has no interrupts.
        0
    }
}

/// One cycle of the simulator as the engine's memory image.
struct UmpkMachine<'s, 'a> {
    scan: &'s mut Scan<'a>,
}

impl Machine for UmpkMachine<'_, '_> {
    fn get(&self, l: Loc) -> u32 {
        operand_of(l).is_some_and(|op| self.scan.bit(op)) as u32
    }

    fn set(&mut self, l: Loc, v: u32) {
        // Inputs, timers and counters are refused at load time; nothing else is writable.
        if let Some(op) = operand_of(l) {
            let _ = self.scan.set_bit(op, v & 1 != 0);
        }
    }

    fn deref(&self, _ptr: u32, _w: Width) -> Option<Loc> {
        None
    }

    fn special(&mut self, id: u16, inst: u32, args: &[Opd], types: &[DataType]) -> Result<bool, Fault> {
        self.element(id, inst, args, types, true)
    }

    fn special_off(&mut self, id: u16, inst: u32, args: &[Opd], types: &[DataType]) -> Result<bool, Fault> {
        self.element(id, inst, args, types, false)
    }
}

impl UmpkMachine<'_, '_> {
    fn element(&mut self, id: u16, _inst: u32, args: &[Opd], _types: &[DataType], input: bool) -> Result<bool, Fault> {
        // Operands were checked at load time ([`check`]): element, constant, constant/bit.
        let n = match args.first() {
            Some(Opd::Loc(l)) => operand_of(*l).map_or(0, |o| o.index),
            _ => 0,
        };
        let konst = |k: usize| match args.get(k) {
            Some(Opd::Imm(v)) => *v,
            _ => 0,
        };
        Ok(match id {
            id::ERROR => {
                if input {
                    self.scan.raise(konst(0) as u8);
                }
                input
            }
            id::TIMER => {
                let group = Group::from_number(konst(1) as u8).unwrap_or(Group::Ms10);
                if let Some(t) = self.scan.logic.timers.get_mut(n as usize) {
                    t.group = group;
                    t.steps = (konst(2) as u8).max(1);
                }
                self.scan.timer(n, input)
            }
            _ => {
                if let Some(c) = self.scan.logic.counters.get_mut(n as usize) {
                    c.ratio = (konst(1) as u8).max(1);
                }
                let reset = matches!(args.get(2), Some(Opd::Loc(l)) if engine::Machine::get(self, *l) != 0);
                self.scan.counter(n, input, reset)
            }
        })
    }
}

/// Load-time rules the engine leaves to the family: element kinds and ranges of the
/// UMPK's own instructions, and which bits a program may assign.
fn check(p: &Program) -> Result<()> {
    let (t, c) = (area_of('T'), area_of('C'));
    for (k, ins) in p.code.iter().enumerate() {
        let here = |m: crate::core::msg::Msg| {
            let pos = p.pos.get(k).copied().unwrap_or_default();
            let text = format!("{}:{}:{}: {}", p.file, pos.line, pos.col, m.text);
            Error::new(ErrorKind::Syntax, crate::core::msg::Msg { id: m.id, text })
        };
        let text = p.text.get(k).cloned().unwrap_or_default();
        let written = match ins {
            Ins::St { loc, .. } | Ins::Set { loc, .. } => Some(*loc),
            _ => None,
        };
        if let Some(op) = written.and_then(operand_of) {
            if !matches!(op.area().letter, 'Q' | 'M') {
                return Err(here(msg!(
                    "umpk-il-cannot-assign",
                    text = &text,
                    operand = op.name(),
                    meaning = op.area().meaning().text
                ))
                .hint(msg!("umpk-il-hint-assign")));
            }
        }
        let Ins::Special { id, args, .. } = ins else { continue };
        if *id == id::ERROR {
            match args.first() {
                Some(Opd::Imm(v)) if (1..=127).contains(v) => continue,
                _ => return Err(here(msg!("umpk-il-user-error", text = &text)).hint(msg!("umpk-il-hint-user-error"))),
            }
        }
        let el = match args.first() {
            Some(Opd::Loc(l)) => operand_of(*l),
            _ => None,
        };
        let konst = |i: usize| match args.get(i) {
            Some(Opd::Imm(v)) => *v as i32,
            _ => -1,
        };
        let (want, what) = if *id == id::TIMER { (t, "timer") } else { (c, "counter") };
        if el.is_none_or(|o| o.area as u8 != want) {
            return Err(here(msg!("umpk-il-first-operand", text = &text, what = what)));
        }
        if *id == id::TIMER {
            if !(0..=2).contains(&konst(1)) {
                return Err(here(msg!("umpk-il-delay-group", text = &text)));
            }
            if !(1..=255).contains(&konst(2)) {
                return Err(here(msg!("umpk-il-delay-steps", text = &text)));
            }
        } else if !(1..=255).contains(&konst(1)) {
            return Err(here(msg!("umpk-il-ratio", text = &text)));
        }
    }
    Ok(())
}

/// An IL program loaded into the simulated UMPK.
pub struct IlRunner {
    prog: Program,
    pub(crate) cpu: Cpu,
    pub(crate) file: String,
    /// The source, kept for snapshots (compiled again on restore).
    text: String,
    /// The name given at load (a path), for messages on restore.
    source: String,
    /// Program time of the last cycle (ns, from the cost table).
    last_ns: u64,
    /// Why the program stopped (a fault: the watchdog), if it did.
    pub fault: Option<String>,
}

impl IlRunner {
    /// Compiles `text` (named `file` in messages) for `model`.
    pub fn load(text: &str, file: &str, model: &'static Model) -> Result<IlRunner> {
        IlRunner::load_with_tags(text, file, model, None)
    }

    /// [`IlRunner::load`] with the tags of a tag file beside the program (docs/tags.md). The
    /// program is kept with those tags appended as a `VAR_GLOBAL` block after its last line,
    /// so a snapshot loads it again without the file.
    pub fn load_with_tags(
        text: &str,
        file: &str,
        model: &'static Model,
        tags: Option<&crate::tags::TagTable>,
    ) -> Result<IlRunner> {
        let fam = UmpkFamily::new(model);
        let prog = engine::compile_with_tags(text, file, &fam, tags)?;
        let kept = match tags {
            Some(t) if !t.is_empty() => {
                let space = crate::umpk::space::UmpkSpace { model };
                std::borrow::Cow::Owned(format!("{text}\n{}", crate::tags::export::to_iec(t, &space)?))
            }
            _ => std::borrow::Cow::Borrowed(text),
        };
        let text: &str = &kept;
        check(&prog).map_err(crate::core::encoding::printable_error)?;
        let cpu = Cpu::new(&prog);
        let name = std::path::Path::new(file).file_name().map_or(file.into(), |n| n.to_string_lossy().into_owned());
        Ok(IlRunner { prog, cpu, file: name, text: text.into(), source: file.into(), last_ns: 0, fault: None })
    }

    pub(crate) fn set_last_ns(&mut self, ns: u64) {
        self.last_ns = ns;
    }

    /// Instructions in the source.
    pub fn instructions(&self) -> usize {
        self.prog.source_instructions
    }
}

impl Runner for IlRunner {
    fn scan(&mut self, scan: &mut Scan<'_>) {
        if self.fault.is_some() {
            return;
        }
        let now = scan.cycle * CYCLE_MS * 1_000_000;
        let out = self.cpu.scan(&self.prog, &mut UmpkMachine { scan }, now, u64::MAX, None);
        self.last_ns = out.cost_ns;
        if let engine::exec::Exit::Fault(f) = out.exit {
            // The program stops with a system error in the history; the controller leaves
            // Work mode and its outputs go off, as outside Work mode (§3.4).
            let code = match f.kind {
                engine::exec::FaultKind::Watchdog => syserr::CYCLE_OVERRUN,
                _ => syserr::PROGRAM_FAULT,
            };
            scan.stop(code);
            self.fault = Some(format!("line {}: {} ({})", f.line, f.message, f.instruction));
        }
    }

    fn save(&self) -> Option<super::logic::IlState> {
        Some(super::logic::IlState {
            source: self.source.clone(),
            text: self.text.clone(),
            cpu: self.cpu.clone(),
            last_ns: self.last_ns,
            fault: self.fault.clone(),
        })
    }

    fn restart(&mut self) {
        self.cpu = Cpu::new(&self.prog);
        self.fault = None;
        self.last_ns = 0;
    }

    fn name(&self) -> String {
        match &self.fault {
            None => format!("IL {}", self.file),
            Some(f) => format!("IL {} stopped: {f}", self.file),
        }
    }

    fn cost_counts(&self) -> u16 {
        // 0.271 µs counts (§4.1.13).
        (self.last_ns / 271).min(u16::MAX as u64) as u16
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::umpk::model::MODELS;
    use crate::umpk::sim::logic::{Image, Logic};
    use crate::umpk::sim::reference;

    const LAB1: &str = include_str!("../../../scripts/umpk_lab1.il");

    fn umpk16() -> &'static Model {
        &MODELS[1]
    }

    /// Runs `r` for the input sequence, returning (outputs, markers, timers, counters) per cycle.
    fn run(r: &mut dyn Runner, logic: &mut Logic, inputs: &[u32]) -> Vec<(u32, u128, u16, u8)> {
        let mut io = Image::default();
        let mut out = Vec::new();
        for (cycle, &i) in inputs.iter().enumerate() {
            io.inputs = i;
            r.scan(&mut Scan { io: &mut io, logic, cycle: cycle as u64 });
            out.push((io.outputs, io.markers, io.timers, io.counters));
        }
        out
    }

    /// A test bench for lab 1: start, hold past the delay, pulses of several lengths on I2,
    /// stop in the middle of a count, more pulses, start again.
    fn bench() -> Vec<u32> {
        let mut v = vec![0u32; 5];
        v.extend([1; 3]); // start
        v.extend([0; 250]); // T0 runs out at 200 cycles
        for (on, off) in [(3, 2), (5, 5), (1, 1), (7, 3), (2, 2), (4, 1), (3, 3)] {
            v.extend(std::iter::repeat_n(4, on));
            v.extend(std::iter::repeat_n(0, off));
        }
        v.extend([2; 2]); // stop: resets C0
        for _ in 0..5 {
            v.extend([4, 4, 0]);
        }
        v.extend([1, 0, 0]);
        v.extend([0; 30]);
        v.extend([2, 0]);
        v.extend([1; 250]);
        v
    }

    #[test]
    fn lab1_in_il_matches_the_reference_cycle_by_cycle() {
        let inputs = bench();
        let mut il_logic = Logic::new(16, 4);
        let mut il = IlRunner::load(LAB1, "umpk_lab1.il", umpk16()).unwrap();
        let got = run(&mut il, &mut il_logic, &inputs);
        let mut ref_logic = Logic::new(16, 4);
        let mut r = (reference::find("lab1").unwrap().build)(&mut ref_logic);
        let want = run(r.as_mut(), &mut ref_logic, &inputs);
        for (k, (g, w)) in got.iter().zip(&want).enumerate() {
            assert_eq!(g, w, "cycle {k} (inputs {:03b})", inputs[k]);
        }
        // The bench exercised what it should: the delay, the counter and its reset.
        assert!(want.iter().any(|s| s.0 & 2 != 0) && want.iter().any(|s| s.0 & 4 != 0));
        assert_eq!(il_logic, ref_logic);
        assert!(il.fault.is_none());
    }

    #[test]
    fn timer_groups_and_divider_follow_the_manual() {
        // T1: group 0, 3 × 10 ms; T2: group 2, 1 s; C1 divides by 2.
        let text = "LD I0\nTIMER T1, 0, 3\nST Q0\nLD I0\nTIMER T2, 2, 1\nST Q1\nLD I1\nDIVIDE C1, 2\nST Q2\n";
        let mut il = IlRunner::load(text, "t.il", umpk16()).unwrap();
        let mut logic = Logic::new(16, 4);
        let mut inputs = vec![1u32; 120];
        for (k, v) in inputs.iter_mut().enumerate() {
            *v |= ((k % 4 < 2) as u32) << 1;
        }
        let out = run(&mut il, &mut logic, &inputs);
        let first = |bit: u32| out.iter().position(|s| s.0 & bit != 0);
        assert_eq!(first(1), Some(3), "3 × 10 ms after the cycle the input came on");
        assert_eq!(first(2), Some(100), "1 × 1 s");
        let q2: Vec<usize> = (0..12).filter(|&k| out[k].0 & 4 != 0).collect();
        assert_eq!(q2, vec![4, 5], "every 2nd pulse, as long as it (2 cycles)");
        assert_eq!((logic.timers[1].group, logic.timers[1].steps), (Group::Ms10, 3));
        assert_eq!((logic.timers[2].group, logic.timers[2].steps, logic.counters[1].ratio), (Group::S1, 1, 2));
    }

    #[test]
    fn load_errors_name_the_line_and_what_to_do() {
        let m = umpk16();
        let e = |t: &str| IlRunner::load(t, "p.il", m).err().expect(t).to_string();
        assert!(e("LD I0\nST I3\n").contains("p.il:2:1") && e("LD I0\nST I3\n").contains("cannot assign I3"));
        assert!(e("LD I0\nS T0\n").contains("cannot assign T0"));
        assert!(e("LD I0\nTIMER T0, 3, 20\n").contains("delay group"));
        assert!(e("LD I0\nTIMER T0, 1, 256\n").contains("1–255"));
        assert!(e("LD I0\nTIMER T0, 1, 0\n").contains("1–255"));
        assert!(e("LD I0\nTIMER C0, 1, 2\n").contains("timer"));
        assert!(e("LD I0\nDIVIDE T0, 4\n").contains("counter"));
        assert!(e("LD I0\nDIVIDE C0, 0\n").contains("ratio"));
        assert!(e("LD I0\nTON T0, 20\n").contains("TIMER T0"), "{}", e("LD I0\nTON T0, 20\n"));
        assert!(e("LD I16\nST Q0\n").contains("I16"), "the UMPK16 has I0…I15");
        assert!(IlRunner::load("LD I8\nST Q0\n", "p.il", &MODELS[0]).is_err(), "the UMPK8 has I0…I7");
        assert!(e("LD I0\nST Q0\nST X1\n").contains("p.il:3"));
        // The UMPK has no interrupts: an ATCH is refused saying so (it once underflowed).
        let atch = e("LD I0\nATCH INT_0, 0\n");
        assert!(atch.contains("no interrupts"), "{atch}");
    }

    #[test]
    fn cost_counts_come_from_the_cost_table() {
        let mut il = IlRunner::load(LAB1, "umpk_lab1.il", umpk16()).unwrap();
        let mut logic = Logic::new(16, 4);
        run(&mut il, &mut logic, &[0]);
        // 10 bit instructions (LD/OR/ANDN/ST…) and 2 family instructions.
        let t = costs();
        let ns = 10 * t.ns(engine::CostClass::Bit) as u64 + 2 * t.ns(engine::CostClass::Special) as u64;
        assert_eq!(il.cost_counts() as u64, ns / 271);
    }

    #[test]
    fn docs_list_every_umpk_instruction_with_its_source() {
        let doc = std::fs::read_to_string(concat!(env!("CARGO_MANIFEST_DIR"), "/docs/il.md")).unwrap();
        for sp in SPECIALS {
            let row = doc.lines().find(|l| l.starts_with(&format!("| `{}` (UMPK) |", sp.name)));
            assert!(row.is_some_and(|r| r.ends_with(&format!("| {} |", sp.source))), "docs/il.md: {}", sp.name);
        }
    }

    #[test]
    fn an_endless_loop_stops_the_program_with_its_outputs_off() {
        let mut il = IlRunner::load("LD I0\nST Q0\nTOP:\nJMP TOP\n", "loop.il", umpk16()).unwrap();
        let mut logic = Logic::new(16, 4);
        let out = run(&mut il, &mut logic, &[1, 1]);
        assert_eq!(out[0].0, 0);
        assert!(il.name().contains("stopped"), "{}", il.name());
    }
}
