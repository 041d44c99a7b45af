//! The PTO/PWM pulse generators (manual §3.4.2; k2.md §5) and the position counter of each
//! pulse channel (§3.4.3.1; k2.md §6), computed analytically from virtual time.
//!
//! A running pulse train is a start time plus a list of segments (cycle, count); the
//! pulses output by any instant are found by arithmetic, never by stepping pulse by pulse.
//! Registers come from [`crate::k2::sm_map::PTO_REGS`]; channel existence and frequency
//! limits from the model catalogue.
//!
//! Behaviour where the manual is silent (stated assumptions):
//! - `PLS` while a PTO is running replaces the running train from that instant (pulses
//!   already out stay counted); the manual's "after this a new PTO with the updated cycle
//!   starts being generated" (§3.4.2.3) is read this way. S7-200 would queue it instead.
//! - `PLS` with the enable bit clear stops the channel; stopping a running PTO this way (or
//!   by PSTOP) sets status bit 5 "aborted by user command" and raises no completion event.
//! - At power-up both idle bits (SM66.7 PTO idle, SM66.3 PWM idle) are 1: nothing runs.
//! - The generator keeps the last loaded cycle/width/count; a `PLS` loads only the fields
//!   whose update bit is set, so `16#84` after power-up (cycle never loaded = 0) is refused
//!   as an invalid cycle.
//! - A PWM cycle below 2, or any cycle faster than the channel's limit, is refused with
//!   status bit 4 too (the only error bit the status byte has).
//! - Position counting (SMD212 …) counts PTO pulses, up moving forward and down moving
//!   backward (§3.4.3.1: "increases counting forward, decreases counting backward"). A
//!   position instruction (PREL, PABS, PHOME, PJOG, PFLO_F) knows its direction and counts
//!   by it whatever SM201.3 says: SM201.3 = 1 only frees the direction pin as a plain output,
//!   it does not change which way the axis moves. A train started by `PLS` has no direction
//!   of its own: it counts by the direction output's level (Q0.2 …: 0 forward = +,
//!   1 reverse = −) while SM201.3 = 0, and forward while SM201.3 = 1 (the pin then says
//!   nothing about the axis). PWM pulses are not counted.
//! - SM201.6 (clear) and SM201.4 (load SMD208) act on every scan while set, as the manual
//!   warns ("avoid keeping this bit at 1"); SM201.7 is latched by PSTOP and only the user
//!   clears it. It blocks position instructions (PREL/PABS/PHOME/PJOG, not simulated); PLS
//!   is not one of them and still runs.

use super::inputs::ns;
use crate::core::{Error, ErrorKind, Result};
use crate::k2::catalog::PtoSpec;
use crate::k2::instr::EventKind;
use crate::k2::memory::Memory;
use crate::k2::sm_map::PtoRegs;
use crate::msg;
use serde::{Deserialize, Serialize};
use std::time::Duration;

/// Control byte bits (§3.4.2.2).
pub mod ctl {
    pub const UPDATE_CYCLE: u8 = 1 << 0;
    pub const UPDATE_WIDTH: u8 = 1 << 1;
    pub const UPDATE_COUNT: u8 = 1 << 2;
    pub const BASE_MS: u8 = 1 << 3;
    pub const PWM_SYNC: u8 = 1 << 4;
    pub const MULTI: u8 = 1 << 5;
    pub const PWM: u8 = 1 << 6;
    pub const ENABLE: u8 = 1 << 7;
}

/// Status byte bits (§3.4.2.2).
pub mod st {
    pub const PWM_IDLE: u8 = 3;
    pub const INVALID: u8 = 4;
    pub const ABORTED: u8 = 5;
    pub const PTO_IDLE: u8 = 7;
}

/// Position control byte bits (§3.4.3.1).
pub mod pos {
    pub const DIR_DISABLE: u8 = 3;
    pub const LOAD: u8 = 4;
    pub const CLEAR: u8 = 6;
    pub const ESTOP: u8 = 7;
}

/// Most segments in a profile table (§3.4.2.1).
pub const MAX_SEGMENTS: u8 = 64;

/// One segment of a running train.
#[derive(Clone, Debug, PartialEq, Eq, Serialize, Deserialize)]
pub struct Seg {
    pub cycle_ns: u64,
    pub count: u64,
    /// Offset of the segment's start from the train's start, ns.
    start_ns: u128,
    /// Pulses of the train before this segment.
    first: u64,
    /// ⌊(2⁶⁴ − 1) / cycle_ns⌋: divides by the cycle with a multiplication ([`Seg::cycles_in`]).
    inv: u64,
}

impl Seg {
    /// Whole cycles in `ns` (`ns / cycle_ns`). Runs once per channel per step, so the
    /// division is a multiplication by the reciprocal kept with the segment plus at most
    /// two corrections (the estimate is low by less than 2 for any 64-bit dividend).
    #[inline]
    fn cycles_in(&self, ns: u128) -> u64 {
        match u64::try_from(ns) {
            Ok(x) => self.cycles_in64(x),
            Err(_) => div(ns, self.cycle_ns),
        }
    }

    /// [`Self::cycles_in`] of a 64-bit interval.
    #[inline]
    fn cycles_in64(&self, x: u64) -> u64 {
        let mut q = ((x as u128 * self.inv as u128) >> 64) as u64;
        let mut r = x - q * self.cycle_ns;
        while r >= self.cycle_ns {
            q += 1;
            r -= self.cycle_ns;
        }
        q
    }
}

/// A running PTO train.
#[derive(Clone, Debug, Serialize, Deserialize)]
pub struct PtoRun {
    pub start: Duration,
    /// `start` in ns.
    start_ns: u64,
    pub segs: Vec<Seg>,
    pub total: u64,
    pub end: Duration,
}

impl PtoRun {
    pub fn new(start: Duration, segs: &[(u64, u64)]) -> PtoRun {
        let mut out = Vec::with_capacity(segs.len());
        let (mut t, mut first) = (0u128, 0u64);
        for &(cycle_ns, count) in segs {
            out.push(Seg { cycle_ns, count, start_ns: t, first, inv: u64::MAX / cycle_ns.max(1) });
            t += cycle_ns as u128 * count as u128;
            first += count;
        }
        PtoRun { start, start_ns: ns(start), segs: out, total: first, end: start + dur(t) }
    }

    pub fn duration(&self) -> Duration {
        self.end - self.start
    }

    #[inline]
    fn seg_at(&self, elapsed: u128) -> &Seg {
        let i = self.segs.partition_point(|s| s.start_ns <= elapsed);
        &self.segs[i.saturating_sub(1)]
    }

    /// Pulses completed by `t` and the output level at `t`: [`Self::pulses_at`] and
    /// [`Self::level_at`] with one segment search and one division.
    #[inline]
    pub fn at(&self, t: Duration) -> (u64, bool) {
        self.at_ns(t, ns(t))
    }

    /// [`Self::at`] with `t` also in ns (the simulator's step works it out once).
    #[inline]
    pub fn at_ns(&self, t: Duration, t_ns: u64) -> (u64, bool) {
        if t >= self.end {
            return (self.total, false);
        }
        let e = t_ns.saturating_sub(self.start_ns);
        // One segment (every PLS train without a profile table) needs no search.
        let s = match self.segs.as_slice() {
            [one] => one,
            _ => self.seg_at(e as u128),
        };
        // Inside a train shorter than 584 years every offset fits 64 bits.
        let Ok(start) = u64::try_from(s.start_ns) else { return self.at_wide(s, t_ns) };
        let into = e - start;
        let q = s.cycles_in(into as u128);
        let phase = into - q * s.cycle_ns;
        (s.first + q.min(s.count), t_ns >= self.start_ns && phase < s.cycle_ns / 2)
    }

    /// [`Self::at_ns`] in 128-bit arithmetic.
    #[cold]
    fn at_wide(&self, s: &Seg, t_ns: u64) -> (u64, bool) {
        let e = t_ns.saturating_sub(self.start_ns) as u128;
        let into = e - s.start_ns;
        let q = s.cycles_in(into);
        let phase = into - q as u128 * s.cycle_ns as u128;
        (s.first + q.min(s.count), t_ns >= self.start_ns && phase < (s.cycle_ns as u128 / 2))
    }

    /// Pulses completed by `t`.
    pub fn pulses_at(&self, t: Duration) -> u64 {
        if t >= self.end {
            return self.total;
        }
        let e = t.saturating_sub(self.start).as_nanos();
        let s = self.seg_at(e);
        s.first + (div(e - s.start_ns, s.cycle_ns)).min(s.count)
    }

    /// The output level at `t` (50 % duty: high in the first half of each cycle).
    pub fn level_at(&self, t: Duration) -> bool {
        if t >= self.end || t < self.start {
            return false;
        }
        let e = (t - self.start).as_nanos();
        let s = self.seg_at(e);
        let into = e - s.start_ns;
        let phase = into - div(into, s.cycle_ns) as u128 * s.cycle_ns as u128;
        phase < (s.cycle_ns as u128 / 2)
    }
}

/// `a / b`, in 64-bit arithmetic when `a` fits (the usual case: 584 years of ns).
fn div(a: u128, b: u64) -> u64 {
    match u64::try_from(a) {
        Ok(a) => a / b,
        Err(_) => (a / b as u128) as u64,
    }
}

fn dur(ns: u128) -> Duration {
    Duration::from_nanos(ns.min(u64::MAX as u128) as u64)
}

/// A running PWM.
#[derive(Clone, Copy, Debug, Serialize, Deserialize)]
struct PwmRun {
    start: Duration,
    cycle_ns: u64,
    width_ns: u64,
}

impl PwmRun {
    fn level_at(&self, t: Duration) -> bool {
        let e = t.saturating_sub(self.start).as_nanos();
        (e % self.cycle_ns as u128) < self.width_ns as u128
    }
    /// The first cycle boundary at or after `t` (a synchronous update takes effect there).
    fn next_boundary(&self, t: Duration) -> Duration {
        let e = t.saturating_sub(self.start).as_nanos();
        let c = self.cycle_ns as u128;
        self.start + dur(e.div_ceil(c) * c)
    }
}

#[derive(Clone, Debug, Serialize, Deserialize)]
enum Run {
    Idle,
    Pto(PtoRun),
    Pwm { now: PwmRun, next: Option<PwmRun> },
}

/// One pulse output channel.
#[derive(Clone, Debug)]
pub struct PtoChannel {
    pub regs: PtoRegs,
    pub spec: PtoSpec,
    out: (u32, u8),
    dir: (u32, u8),
    /// The generator's loaded registers.
    cycle: u16,
    width: u16,
    count: u32,
    run: Run,
    /// Pulses of the current train already added to the position counter.
    counted: u64,
    /// The direction of a train started by a position instruction (true = backward); `None`
    /// for a `PLS` train, which counts by the direction pin.
    reverse: Option<bool>,
}

fn q_bit(mem: &Memory, p: (u32, u8)) -> bool {
    mem.q.get(p.0 as usize).is_some_and(|b| b >> p.1 & 1 != 0)
}

fn set_q(mem: &mut Memory, p: (u32, u8), on: bool) {
    if let Some(b) = mem.q.get_mut(p.0 as usize) {
        if on {
            *b |= 1 << p.1
        } else {
            *b &= !(1 << p.1)
        }
    }
}

/// `Q0.2` → (0, 2).
fn q_pin(text: &str) -> (u32, u8) {
    let (b, bit) = text.trim_start_matches('Q').split_once('.').unwrap_or(("0", "0"));
    (b.parse().unwrap_or(0), bit.parse().unwrap_or(0))
}

/// Why PLS refused: what, the operand to look at, and what to try.
#[derive(Clone, Debug, PartialEq)]
pub struct Invalid {
    pub msg: String,
    pub operand: String,
    pub hint: String,
}

impl Invalid {
    /// The refusal as the user reads it, in process and through the helper alike.
    pub fn error(self, r: &PtoRegs) -> Error {
        Error::new(ErrorKind::Refused, msg!("k2-pls-refused", channel = r.channel, reason = self.msg, byte = r.status))
            .operand(self.operand)
            .hint(self.hint)
    }
}

/// The first rule a single-segment PTO or a PWM breaks with control byte `c` and the cycle
/// and count PLS uses (§3.4.2.2: «Время цикла и количество импульсов должны быть больше 1»;
/// §3.4: the output's frequency limit), or `None`. A multi-segment PTO's profile table is
/// checked apart. A function of values the PLC shows in its SM registers only, so a refusal
/// the helper reads back (status bit 4, then the registers: `k2::driver`) is worded as in
/// process.
pub fn invalid(r: &PtoRegs, spec: &PtoSpec, c: u8, cycle: u16, count: u32) -> Option<Invalid> {
    let base_ns: u64 = if c & ctl::BASE_MS != 0 { 1_000_000 } else { 1_000 };
    let unit = if c & ctl::BASE_MS != 0 { "ms" } else { "µs" };
    if c & ctl::PWM != 0 {
        if cycle < 2 {
            return Some(Invalid {
                msg: msg!("k2-pls-pwm-cycle-below-two", cycle = cycle).into(),
                operand: format!("SMW{}", r.cycle),
                hint: msg!("k2-pls-pwm-cycle-below-two-hint", register = r.cycle, control = r.control).into(),
            });
        }
    } else if cycle < 2 || count < 2 {
        // The rule as the manual states it (§3.4.2.2; `sm_map::PTO_INVALID_RULE` in English).
        let (m, operand, h) = if cycle < 2 {
            (
                msg!("k2-pls-cycle-below-two", cycle = cycle),
                format!("SMW{}", r.cycle),
                msg!("k2-pls-cycle-below-two-hint", register = r.cycle, control = r.control),
            )
        } else {
            (
                msg!("k2-pls-count-below-two", count = count),
                format!("SMD{}", r.count),
                msg!("k2-pls-count-below-two-hint", register = r.count, control = r.control),
            )
        };
        return Some(Invalid { msg: m.into(), operand, hint: h.into() });
    }
    too_fast(r, spec, cycle as u64 * base_ns, msg!("k2-pls-what-cycle", cycle = cycle, unit = unit).into())
}

/// Why PLS refused with control byte `c`, in words made only of what the PLC's registers
/// show: `cycle` and `count` are SMW68 and SMD72 … as they read. A value whose update bit is
/// set is the one PLS loaded and is named with the rule it breaks ([`invalid`]'s words and
/// order); one whose update bit is clear is the value PLS kept from an earlier PLS (§3.4.2.2:
/// SM67.0 «Следует ли обновлять время цикла: 0 = нет», SM67.2 likewise for the pulse count),
/// which no register shows, so it is named as kept. The rules on loaded values come first. In
/// process ([`PtoChannel::pls`], once [`invalid`] refused the values it used) and through the
/// helper (`k2::driver`, reading the registers back after status bit 4) alike.
pub fn explain(r: &PtoRegs, spec: &PtoSpec, c: u8, cycle: u16, count: u32) -> Invalid {
    let pwm = c & ctl::PWM != 0;
    let cycle_kept = c & ctl::UPDATE_CYCLE == 0;
    let count_kept = !pwm && c & ctl::UPDATE_COUNT == 0;
    // A kept value stands in as one that breaks no rule: what fails then is a loaded value.
    let loaded =
        invalid(r, spec, c, if cycle_kept { u16::MAX } else { cycle }, if count_kept { u32::MAX } else { count });
    if let Some(why) = loaded {
        return why;
    }
    let (control, cyc, cnt) = (r.control, r.cycle, r.count);
    match (cycle_kept, count_kept) {
        (true, false) => Invalid {
            msg: msg!("agent-pls-kept-cycle", control = control, cycle = cyc).text,
            operand: format!("SMW{cyc}"),
            hint: msg!("agent-pls-kept-cycle-hint", control = control, cycle = cyc).text,
        },
        (false, true) => Invalid {
            msg: msg!("agent-pls-kept-count", control = control, count = cnt).text,
            operand: format!("SMD{cnt}"),
            hint: msg!("agent-pls-kept-count-hint", control = control, count = cnt).text,
        },
        _ => Invalid {
            msg: msg!("agent-pls-kept-both", control = control, cycle = cyc, count = cnt).text,
            operand: format!("SMB{control}"),
            hint: msg!("agent-pls-kept-both-hint", control = control, cycle = cyc, count = cnt).text,
        },
    }
}

/// PLS on a channel whose control byte `c` has the enable bit clear while it is idle: nothing
/// to stop, nothing started (§3.4.2.2, bit 7). The helper reads the same byte back.
pub fn did_nothing(r: &PtoRegs, spec: &PtoSpec, c: u8) -> Error {
    Error::state(msg!(
        "k2-pls-did-nothing",
        channel = r.channel,
        control = r.control,
        value = format!("{c:02X}"),
        output = spec.output
    ))
    .operand(format!("SMB{}", r.control))
}

/// A cycle of `cycle_ns` above the output's frequency limit (manual §3.4), or `None`.
fn too_fast(r: &PtoRegs, spec: &PtoSpec, cycle_ns: u64, what: String) -> Option<Invalid> {
    let max = spec.max_hz as u64;
    if cycle_ns * max < 1_000_000_000 {
        let min_us = 1_000_000u64.div_ceil(max);
        return Some(Invalid {
            msg: msg!("k2-pls-too-fast", what = what, hz = 1_000_000_000 / cycle_ns, output = spec.output, max = max)
                .into(),
            operand: format!("SMW{}", r.cycle),
            hint: msg!("k2-pto-freq-too-high-hint", output = spec.output, shortest = min_us).into(),
        });
    }
    None
}

impl PtoChannel {
    pub fn new(regs: PtoRegs, spec: PtoSpec, mem: &mut Memory) -> PtoChannel {
        mem.set_sm_bit(regs.status, st::PTO_IDLE, true);
        mem.set_sm_bit(regs.status, st::PWM_IDLE, true);
        PtoChannel {
            regs,
            spec,
            out: q_pin(spec.output),
            dir: q_pin(spec.direction),
            cycle: 0,
            width: 0,
            count: 0,
            run: Run::Idle,
            counted: 0,
            reverse: None,
        }
    }

    pub fn is_pto_busy(&self) -> bool {
        matches!(self.run, Run::Pto(_))
    }

    pub fn is_pwm_running(&self) -> bool {
        matches!(self.run, Run::Pwm { .. })
    }

    /// The running train, if any.
    pub fn train(&self) -> Option<&PtoRun> {
        match &self.run {
            Run::Pto(r) => Some(r),
            _ => None,
        }
    }

    /// The pulse output and the direction output (`Q0.0`, `Q0.2` for PTO0).
    pub fn pins(&self) -> ((u32, u8), (u32, u8)) {
        (self.out, self.dir)
    }

    /// When this channel next raises an event (PTO completion), if it will.
    pub fn next_due(&self) -> Option<Duration> {
        self.train().map(|r| r.end)
    }

    fn name(&self) -> String {
        format!("PTO{} ({})", self.regs.channel, self.spec.output)
    }

    /// Brings the channel to `now`: counts pulses into the position counter, finishes
    /// trains (raising their completion events), drives the output pin, and applies the
    /// position control bits.
    #[inline]
    pub fn advance(&mut self, mem: &mut Memory, to: (Duration, u64), raised: &mut Vec<(Duration, EventKind)>) {
        let (now, now_ns) = to;
        // Inside a one-segment train that has not ended (every PLS without a profile
        // table): [`PtoRun::at_ns`] reduced to that case, without the general path's call.
        if let Run::Pto(train) = &self.run {
            if let [s] = train.segs.as_slice() {
                if now < train.end && now_ns >= train.start_ns {
                    let into = now_ns - train.start_ns;
                    let q = s.cycles_in64(into);
                    let level = into - q * s.cycle_ns < s.cycle_ns / 2;
                    let p = q.min(s.count);
                    let new = p - self.counted;
                    self.counted = p;
                    set_q(mem, self.out, level);
                    self.count_pulses(mem, new);
                    self.apply_position_bits(mem);
                    return;
                }
            }
        }
        self.advance_general(mem, to, raised);
    }

    /// [`Self::advance`] for everything but the inside of a one-segment train.
    #[inline(never)]
    fn advance_general(
        &mut self,
        mem: &mut Memory,
        (now, now_ns): (Duration, u64),
        raised: &mut Vec<(Duration, EventKind)>,
    ) {
        let r = self.regs;
        let mut drive = None;
        match &mut self.run {
            Run::Idle => {}
            Run::Pto(train) => {
                let (p, level) = train.at_ns(now, now_ns);
                let new = p - self.counted;
                self.counted = p;
                drive = Some(level);
                if now >= train.end {
                    raised.push((train.end, EventKind::PtoComplete { channel: r.channel }));
                    self.run = Run::Idle;
                    mem.set_sm_bit(r.status, st::PTO_IDLE, true);
                }
                self.count_pulses(mem, new);
            }
            Run::Pwm { now: cur, next } => {
                if let Some(n) = *next {
                    if now >= n.start {
                        *cur = n;
                        *next = None;
                    }
                }
                drive = Some(cur.level_at(now));
            }
        }
        if let Some(level) = drive {
            set_q(mem, self.out, level);
        }
        self.apply_position_bits(mem);
    }

    #[inline]
    fn count_pulses(&self, mem: &mut Memory, n: u64) {
        if n == 0 {
            return;
        }
        let r = self.regs;
        let reverse = match self.reverse {
            Some(rev) => rev,
            None => !mem.sm_bit(r.pos_control, pos::DIR_DISABLE) && q_bit(mem, self.dir),
        };
        let cv = mem.sm_dword(r.pos_cv) as i32;
        let d = n as i64 as i32;
        let cv = if reverse { cv.wrapping_sub(d) } else { cv.wrapping_add(d) };
        mem.set_sm_dword(r.pos_cv, cv as u32);
    }

    /// SM201.6 clears SMD212; SM201.4 loads SMD208 into it (§3.4.3.1).
    #[inline(always)]
    pub fn apply_position_bits(&self, mem: &mut Memory) {
        let r = self.regs;
        if mem.sm_bit(r.pos_control, pos::CLEAR) {
            mem.set_sm_dword(r.pos_cv, 0);
        }
        if mem.sm_bit(r.pos_control, pos::LOAD) {
            let v = mem.sm_dword(r.pos_new_cv);
            mem.set_sm_dword(r.pos_cv, v);
        }
    }

    /// Stops whatever runs (PLS with enable clear, PSTOP). Returns what was stopped.
    fn stop(&mut self, mem: &mut Memory) -> &'static str {
        let r = self.regs;
        let what = match self.run {
            Run::Pto(_) => {
                mem.set_sm_bit(r.status, st::ABORTED, true);
                "PTO"
            }
            Run::Pwm { .. } => "PWM",
            Run::Idle => "",
        };
        self.run = Run::Idle;
        self.counted = 0;
        mem.set_sm_bit(r.status, st::PTO_IDLE, true);
        mem.set_sm_bit(r.status, st::PWM_IDLE, true);
        set_q(mem, self.out, false);
        what
    }

    /// Starts a pulse train from `segs` ((cycle ns, pulses) each) at `now`, with the
    /// direction output set for `reverse` (unless SM201.3 frees it): the position-control
    /// instructions' way into the channel (program::motion).
    pub fn start_train(&mut self, mem: &mut Memory, now: Duration, segs: &[(u64, u64)], reverse: bool) {
        if !mem.sm_bit(self.regs.pos_control, pos::DIR_DISABLE) {
            set_q(mem, self.dir, reverse);
        }
        self.run = Run::Pto(PtoRun::new(now, segs));
        self.counted = 0;
        self.reverse = Some(reverse);
        let r = self.regs;
        for (b, v) in [(st::PTO_IDLE, false), (st::PWM_IDLE, true), (st::INVALID, false), (st::ABORTED, false)] {
            mem.set_sm_bit(r.status, b, v);
        }
    }

    /// Stops the channel's output now (a position instruction ending a jog or homing run).
    pub fn halt(&mut self, mem: &mut Memory) {
        self.stop(mem);
        mem.set_sm_bit(self.regs.status, st::ABORTED, false);
    }

    /// PSTOP: stops the output and latches SM201.7 (§3.4.3.1).
    pub fn pstop(&mut self, mem: &mut Memory) -> &'static str {
        let what = self.stop(mem);
        mem.set_sm_bit(self.regs.pos_control, pos::ESTOP, true);
        what
    }

    /// Sets the invalid bit and builds the refusal.
    fn refuse(&self, mem: &mut Memory, why: Invalid) -> Error {
        mem.set_sm_bit(self.regs.status, st::INVALID, true);
        why.error(&self.regs)
    }

    /// Executes `PLS` for this channel at `now` (the caller advanced to `now` first).
    /// `v` is the V area (profile tables).
    pub fn pls(&mut self, mem: &mut Memory, now: Duration) -> Result<String> {
        let r = self.regs;
        let c = mem.sm_byte(r.control);
        if c & ctl::ENABLE == 0 {
            let what = self.stop(mem);
            if what.is_empty() {
                return Err(did_nothing(&r, &self.spec, c));
            }
            return Ok(msg!("k2-pls-stopped", name = self.name(), what = what, control = r.control).into());
        }
        let base_ns: u64 = if c & ctl::BASE_MS != 0 { 1_000_000 } else { 1_000 };
        let unit = if c & ctl::BASE_MS != 0 { "ms" } else { "µs" };
        if c & ctl::UPDATE_CYCLE != 0 {
            self.cycle = mem.sm_word(r.cycle);
        }
        if c & ctl::UPDATE_WIDTH != 0 {
            self.width = mem.sm_word(r.width);
        }
        if c & ctl::UPDATE_COUNT != 0 {
            self.count = mem.sm_dword(r.count);
        }
        if c & ctl::PWM != 0 {
            if invalid(&r, &self.spec, c, self.cycle, self.count).is_some() {
                let why = explain(&r, &self.spec, c, mem.sm_word(r.cycle), mem.sm_dword(r.count));
                return Err(self.refuse(mem, why));
            }
            let cycle_ns = self.cycle as u64 * base_ns;
            let width_ns = (self.width.min(self.cycle)) as u64 * base_ns;
            let new = PwmRun { start: now, cycle_ns, width_ns };
            let sync = c & ctl::PWM_SYNC != 0;
            self.run = match &self.run {
                Run::Pwm { now: cur, .. } if sync => {
                    let at = cur.next_boundary(now);
                    Run::Pwm { now: *cur, next: Some(PwmRun { start: at, ..new }) }
                }
                _ => Run::Pwm { now: new, next: None },
            };
            self.counted = 0;
            for (b, v) in [(st::PWM_IDLE, false), (st::PTO_IDLE, true), (st::INVALID, false), (st::ABORTED, false)] {
                mem.set_sm_bit(r.status, b, v);
            }
            let duty = new.width_ns as f64 * 100.0 / cycle_ns as f64;
            return Ok(msg!(
                "k2-pls-pwm-started",
                name = self.name(),
                cycle = self.cycle,
                width = self.width.min(self.cycle),
                unit = unit,
                duty = format!("{duty:.1}"),
                update = if sync { "sync" } else { "async" }
            )
            .into());
        }
        let segs: Vec<(u64, u64)> = if c & ctl::MULTI != 0 {
            self.profile_segments(mem)?
        } else {
            if invalid(&r, &self.spec, c, self.cycle, self.count).is_some() {
                let why = explain(&r, &self.spec, c, mem.sm_word(r.cycle), mem.sm_dword(r.count));
                return Err(self.refuse(mem, why));
            }
            vec![(self.cycle as u64 * base_ns, self.count as u64)]
        };
        let train = PtoRun::new(now, &segs);
        let msg: String = msg!(
            "k2-pls-pto-started",
            name = self.name(),
            pulses = train.total,
            segments = segs.len(),
            seconds = format!("{:.6}", train.duration().as_secs_f64())
        )
        .into();
        self.run = Run::Pto(train);
        self.counted = 0;
        self.reverse = None;
        for (b, v) in [(st::PTO_IDLE, false), (st::PWM_IDLE, true), (st::INVALID, false), (st::ABORTED, false)] {
            mem.set_sm_bit(r.status, b, v);
        }
        Ok(msg)
    }

    /// Reads and checks the multi-segment profile table at SMW168 … (§3.4.2.1).
    fn profile_segments(&self, mem: &mut Memory) -> Result<Vec<(u64, u64)>> {
        let r = self.regs;
        let c = mem.sm_byte(r.control);
        profile(&r, &self.spec, c, mem.sm_word(r.profile), &mem.v).map_err(|why| self.refuse(mem, why))
    }
}

/// The segments ((cycle ns, pulses) each) of the multi-segment profile table PLS reads with
/// control byte `c`, table start `start` (SMW168 …) and the V area `v`, or the first rule the
/// table breaks (§3.4.2.1: 1 to 64 segments, each a cycle time of 2 to 65535 in the channel's
/// time base and a pulse count of at least 1; «начальная позиция в таблице профилей должна
/// быть нечетным адрес в V области»; §3.4: the output's frequency limit). A function of what
/// the PLC shows (SMW168 and V), so a refusal the helper reads back (status bit 4, then SMW168
/// through the helper and the table over Modbus: `k2::driver`) is worded as in process.
pub fn profile(
    r: &PtoRegs,
    spec: &PtoSpec,
    c: u8,
    start: u16,
    v: &[u8],
) -> std::result::Result<Vec<(u64, u64)>, Invalid> {
    let base_ns: u64 = if c & ctl::BASE_MS != 0 { 1_000_000 } else { 1_000 };
    let unit = if c & ctl::BASE_MS != 0 { "ms" } else { "µs" };
    let start = start as u32;
    let tab = format!("SMW{}", r.profile);
    let v_len = v.len() as u32;
    let refuse = |msg: String, operand: String, hint: String| Err(Invalid { msg, operand, hint });
    if start.is_multiple_of(2) {
        return refuse(
            msg!("k2-pls-table-even", register = r.profile, start = start).into(),
            tab,
            msg!("k2-pls-table-even-hint", register = r.profile).into(),
        );
    }
    if start >= v_len {
        return refuse(
            msg!("k2-pls-table-past-v", start = start, top = v_len.saturating_sub(1)).into(),
            tab,
            msg!("k2-pls-table-past-v-hint").into(),
        );
    }
    let n = v[start as usize];
    if n == 0 || n > MAX_SEGMENTS {
        return refuse(
            msg!("k2-pls-table-segments", start = start, n = n, max = MAX_SEGMENTS).into(),
            format!("VB{start}"),
            msg!("k2-pls-table-segments-hint").into(),
        );
    }
    let end = start + 1 + 8 * n as u32;
    if end > v_len {
        return refuse(
            msg!("k2-pls-table-runs-past", start = start, last = end - 1).into(),
            format!("VB{start}"),
            msg!("k2-pls-table-runs-past-hint").into(),
        );
    }
    let mut segs = Vec::with_capacity(n as usize);
    for k in 0..n as u32 {
        let off = (start + 1 + 8 * k) as usize;
        let cycle = u16::from_be_bytes([v[off], v[off + 1]]);
        let count = u32::from_be_bytes([v[off + 4], v[off + 5], v[off + 6], v[off + 7]]);
        if cycle < 2 {
            return refuse(
                msg!("k2-pls-segment-cycle", n = k + 1, word = off, cycle = cycle).into(),
                format!("VW{off}"),
                msg!("k2-pls-segment-cycle-hint").into(),
            );
        }
        if count < 1 {
            return refuse(
                msg!("k2-pls-segment-count", n = k + 1, dword = off + 4).into(),
                format!("VD{}", off + 4),
                msg!("k2-pls-segment-count-hint").into(),
            );
        }
        let cycle_ns = cycle as u64 * base_ns;
        if let Some(why) =
            too_fast(r, spec, cycle_ns, msg!("k2-pls-what-segment-cycle", n = k + 1, cycle = cycle, unit = unit).into())
        {
            return Err(why);
        }
        segs.push((cycle_ns, count as u64));
    }
    Ok(segs)
}

/// A channel's state for snapshots (`crate::snapshot`); the registers and the model's
/// limits come from the model the snapshot is restored on.
#[derive(Clone, Debug, Serialize, Deserialize)]
pub struct PtoState {
    cycle: u16,
    width: u16,
    count: u32,
    run: Run,
    counted: u64,
    #[serde(default)]
    reverse: Option<bool>,
}

impl PtoChannel {
    /// Every field is named (no `..`): a field added to the channel does not compile until
    /// it is saved here or named as not the machine's state.
    pub fn save(&self) -> PtoState {
        let PtoChannel {
            // The registers, limits and output pins: from the model.
            regs: _,
            spec: _,
            out: _,
            dir: _,
            cycle,
            width,
            count,
            run,
            counted,
            reverse,
        } = self;
        PtoState { cycle: *cycle, width: *width, count: *count, run: run.clone(), counted: *counted, reverse: *reverse }
    }

    pub fn load(&mut self, s: PtoState) {
        (self.cycle, self.width, self.count, self.run, self.counted, self.reverse) =
            (s.cycle, s.width, s.count, s.run, s.counted, s.reverse);
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn trains_are_arithmetic() {
        let t = PtoRun::new(Duration::from_millis(10), &[(500_000, 1000), (250_000, 4000)]);
        assert_eq!(t.total, 5000);
        assert_eq!(t.duration(), Duration::from_millis(500 + 1000));
        assert_eq!(t.pulses_at(Duration::from_millis(10)), 0);
        assert_eq!(t.pulses_at(Duration::from_micros(10_499)), 0);
        assert_eq!(t.pulses_at(Duration::from_micros(10_500)), 1);
        assert_eq!(t.pulses_at(Duration::from_millis(510)), 1000);
        assert_eq!(t.pulses_at(Duration::from_micros(510_250)), 1001);
        assert_eq!(t.pulses_at(Duration::from_secs(100)), 5000);
        assert!(t.level_at(Duration::from_micros(10_100)));
        assert!(!t.level_at(Duration::from_micros(10_300)));
    }

    #[test]
    fn division_by_the_kept_reciprocal_is_exact() {
        for cycle in [1u64, 2, 3, 5, 7, 1000, 4_999, 5_000, 65_535_000_000, u32::MAX as u64 + 7, u64::MAX / 3, u64::MAX]
        {
            let s = &PtoRun::new(Duration::ZERO, &[(cycle, 1)]).segs[0];
            let mut xs = vec![0u64, 1, cycle - 1, cycle, cycle.saturating_add(1), u64::MAX, u64::MAX - 1, u64::MAX / 2];
            xs.extend((1..64u64).map(|k| k.wrapping_mul(0x9E37_79B9_7F4A_7C15) >> (k % 64)));
            for x in xs {
                assert_eq!(s.cycles_in(x as u128), x / cycle, "{x} / {cycle}");
            }
            assert_eq!(s.cycles_in(u64::MAX as u128 * 3), (u64::MAX as u128 * 3 / cycle as u128) as u64);
        }
    }

    #[test]
    fn at_is_pulses_and_level_together() {
        let t = PtoRun::new(Duration::from_millis(10), &[(500_000, 1000), (250_000, 4000), (3, 7)]);
        let ends = t.end.as_micros() as u64;
        for us in (0..ends + 20).step_by(37).chain([10_000, 10_250, 10_499, 10_500, 510_000, ends - 1, ends]) {
            let at = Duration::from_micros(us);
            assert_eq!(t.at(at), (t.pulses_at(at), t.level_at(at)), "at {us} µs");
        }
    }
}
