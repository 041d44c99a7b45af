//! The high-speed counters HSC0–HSC3 (manual §3.3; k2.md §4): every mode of §3.3.1
//! (inputs from [`crate::k2::sm_map::HSC_MODE_INPUTS`]), counting from simulated input
//! signals ([`super::inputs`]) and from edges written to I0.x; single-PV and multi-PV
//! compare (absolute / relative / cyclic), the "CV = PV" events with the manual's numbers,
//! the status byte and the current-segment byte.
//!
//! Counting over an interval is arithmetic: the edges each input wave makes between two
//! instants. A "CV = PV" crossing inside the interval is timed exactly by inverting the
//! wave (one division for a single input, a binary search for 4x quadrature). Two-pulse
//! mode (6/7) with both inputs driven is treated as moving monotonically at the net rate
//! within one interval — crossings are timed approximately there (stated assumption).
//! The edge streams a counter counts (its "drive") are kept between intervals while the
//! sources, its settings and the input levels they were worked out from are unchanged, so
//! an interval without a crossing costs a few multiplications.
//!
//! Behaviour where the manual is silent (stated assumptions):
//! - SMD38 … shows the live count. A value the user writes there is the new current value
//!   (§3.3.2, "write new current value into HSC": SM37.6 …): it is kept there (not
//!   overwritten by the count) until the next `HSC`, which loads it when SM37.6 is set and
//!   drops it otherwise (SMD38 then shows the count again). The count itself goes on
//!   meanwhile ([`HscChannel::cv`]); `hsc N status` reports it, and the value waiting.
//!   docs/pulse-hsc-rtc-eeprom.md states the rule.
//! - SM141.5 "reset interrupt variable": 0 → `HSC` restarts the table at PV1 with the
//!   current value as the relative reference; 1 → it continues from the current segment.
//! - External reset (modes 1, 2, 4, 7, 10) acts on the edge into the active level (SM37.0:
//!   0 = active high) and clears CV; start (mode 2) gates counting while inactive.
//! - External direction input (modes 3, 4): level 1 counts up.
//! - A/B mode with two independent square waves (not a `sim quad` pair) counts nothing: a
//!   real decoder would count noise.
//! - A/B rate (SM37.2, §3.3.2: "0 = 1x; 1 = 4x"; the manual says no more): 4x counts every
//!   change of A or B; 1x counts one edge per A/B period, A's edge while B is low — A rising
//!   (A leads B) counts up, A falling (B leads A) counts down (the usual X1 decoding). So 1x is
//!   always a quarter of 4x rounded down, and a reversal inside a period neither adds nor
//!   loses a count. A wired encoder's phase at power-up and its edges: `inputs::Track`.
//! - CV is a DINT in SMD38 (wraps); the simulator keeps a 64-bit value internally.
//! - In relative cyclic mode a step that would raise more events than the log keeps skips
//!   whole cycles arithmetically (they are counted as dropped), so an hour costs no more
//!   than a second.

use super::events::LOG_CAP;
use super::inputs::{ns, Inputs, Pin, PinEdges, Track, Wave};
use crate::core::{Error, ErrorKind, Result};
use crate::k2::catalog::HscSpec;
use crate::k2::instr::EventKind;
use crate::k2::memory::Memory;
use crate::k2::sm_map::{self, HscKind, HscModeInputs, HscRegs};
use serde::{Deserialize, Serialize};
use std::time::Duration;

/// Control byte bits (§3.3.2).
pub mod ctl {
    pub const RESET_LOW: u8 = 1 << 0;
    pub const START_LOW: u8 = 1 << 1;
    pub const RATE_4X: u8 = 1 << 2;
    pub const DIR_UP: u8 = 1 << 3;
    pub const WRITE_DIR: u8 = 1 << 4;
    pub const WRITE_PV: u8 = 1 << 5;
    pub const WRITE_CV: u8 = 1 << 6;
    pub const ENABLE: u8 = 1 << 7;
}

/// Multi-PV control byte bits (§3.3.2).
pub mod mpv {
    pub const MULTI: u8 = 1 << 0;
    pub const RELATIVE: u8 = 1 << 1;
    pub const CYCLIC: u8 = 1 << 2;
    pub const LOAD: u8 = 1 << 4;
    pub const KEEP_SEGMENT: u8 = 1 << 5;
}

/// Status byte bits (§3.3.2).
pub mod st {
    pub const TABLE_FAULT: u8 = 3;
    pub const DIR_UP: u8 = 5;
    pub const EQUAL: u8 = 6;
    pub const GREATER: u8 = 7;
}

/// The status byte's bits a counter owns; the others keep what was written to them.
const STATUS_BITS: u8 = 1 << st::TABLE_FAULT | 1 << st::DIR_UP | 1 << st::EQUAL | 1 << st::GREATER;

/// Most PVs in a table (§3.3.3).
pub const MAX_PVS: u8 = 32;

/// A loaded PV table.
#[derive(Clone, Debug, PartialEq, Eq, Serialize, Deserialize)]
pub struct PvTable {
    pub pvs: Vec<i64>,
    pub relative: bool,
    pub cyclic: bool,
}

/// Reads a PV table at V offset `start` (§3.3.3): count byte, then DINTs. Relative PVs with
/// |PV| ≤ 1, or absolute PVs within 1 of the previous one, end the table there.
pub fn read_table(v: &[u8], start: u32, relative: bool, cyclic: bool) -> std::result::Result<PvTable, String> {
    if start.is_multiple_of(2) {
        return Err(format!("the PV table start {start} is even (it must be an odd V offset, §3.3.2)"));
    }
    let s = start as usize;
    if s >= v.len() {
        return Err(format!("the PV table start VB{start} is past the V area"));
    }
    let n = v[s];
    if n == 0 || n > MAX_PVS {
        return Err(format!("the PV table at VB{start} holds {n} PVs (1–{MAX_PVS} allowed)"));
    }
    if s + 1 + 4 * n as usize > v.len() {
        return Err(format!("the PV table at VB{start} runs past the V area"));
    }
    let mut pvs: Vec<i64> = Vec::new();
    for k in 0..n as usize {
        let o = s + 1 + 4 * k;
        let pv = i32::from_be_bytes([v[o], v[o + 1], v[o + 2], v[o + 3]]) as i64;
        let ends = if relative { pv.abs() <= 1 } else { pvs.last().is_some_and(|p| (pv - p).abs() <= 1) };
        if ends {
            break;
        }
        pvs.push(pv);
    }
    if pvs.is_empty() {
        return Err(format!("the PV table at VB{start} ends before its first PV (|PV| must be > 1)"));
    }
    Ok(PvTable { pvs, relative, cyclic: cyclic && relative })
}

/// Up to four edge streams (each the rising edges of a wave; falling edges are the wave
/// shifted by half a period). Inline, so computing a drive allocates nothing.
#[derive(Clone, Copy, Debug)]
struct Streams {
    w: [Wave; 4],
    n: u8,
}

impl Default for Streams {
    fn default() -> Streams {
        Streams { w: [Wave { hz: 1, origin_ns: 0 }; 4], n: 0 }
    }
}

impl Streams {
    fn of(ws: &[Wave]) -> Streams {
        let mut s = Streams::default();
        for w in ws {
            s.push(*w);
        }
        s
    }
    fn push(&mut self, w: Wave) {
        if let Some(slot) = self.w.get_mut(self.n as usize) {
            *slot = w;
            self.n += 1;
        }
    }
    fn waves(&self) -> &[Wave] {
        &self.w[..self.n as usize]
    }
    /// Rising edges of every stream in (origin, t], `t` in ns.
    #[inline]
    fn at(&self, t: u64) -> i64 {
        self.waves().iter().map(|w| w.rises_ns(t) as i64).sum()
    }
    fn single(&self) -> Option<&Wave> {
        match self.waves() {
            [w] => Some(w),
            _ => None,
        }
    }
    fn is_empty(&self) -> bool {
        self.n == 0
    }
}

/// A count that is not a square wave's edges: a wired pulse train's or encoder's.
#[derive(Clone, Copy, Debug)]
enum Term {
    /// Rising edges of one pin.
    Pin(PinEdges),
    /// An A/B decoder on an encoder's outputs (`Track::quad`).
    Quad { track: Track, swapped: bool, x4: bool },
}

impl Term {
    #[inline]
    fn at(&self, t: u64) -> i64 {
        match *self {
            Term::Pin(e) => e.rises_ns(t),
            Term::Quad { track, swapped, x4 } => track.quad(t, swapped, x4),
        }
    }
}

/// Edge streams counting up and down during one interval, and up to two other counts
/// with their signs.
#[derive(Clone, Copy, Debug, Default)]
struct Drive {
    up: Streams,
    down: Streams,
    terms: [Option<(Term, i64)>; 2],
}

impl Drive {
    /// The net count at `t` ns.
    #[inline]
    fn at(&self, t: u64) -> i64 {
        let mut n = self.up.at(t) - self.down.at(t);
        for (term, sign) in self.terms.iter().flatten() {
            n += sign * term.at(t);
        }
        n
    }

    fn has_terms(&self) -> bool {
        self.terms[0].is_some()
    }

    fn add_term(&mut self, term: Term, sign: i64) {
        let slot = if self.terms[0].is_none() { 0 } else { 1 };
        self.terms[slot] = Some((term, sign));
    }

    /// The one edge stream of a drive counting in one direction only, with its sign.
    fn single(&self) -> Option<(Wave, i64)> {
        if self.has_terms() {
            return None;
        }
        match (self.up.single(), self.down.single()) {
            (Some(w), None) if self.down.is_empty() => Some((*w, 1)),
            (None, Some(w)) if self.up.is_empty() => Some((*w, -1)),
            _ => None,
        }
    }

    /// Times the counts of the interval (a, b] that move in direction `sign`.
    fn timer(&self, a: Duration, b: Duration, sign: i64) -> Timer<'_> {
        let single = match (sign > 0, self.up.single(), self.down.is_empty(), self.down.single(), self.up.is_empty()) {
            _ if self.has_terms() => None,
            (true, Some(w), true, _, _) => Some(*w),
            (false, _, _, Some(w), true) => Some(*w),
            _ => None,
        };
        let (a, b) = (ns(a), ns(b));
        match single {
            Some(w) => Timer { drive: self, a, b, sign, base: 0, single: Some((w, w.rises_ns(a))) },
            None => Timer { drive: self, a, b, sign, base: self.at(a), single: None },
        }
    }
}

/// Finds the time of the k-th count of an interval; what does not depend on k is worked
/// out once per interval.
struct Timer<'a> {
    drive: &'a Drive,
    a: u64,
    b: u64,
    sign: i64,
    /// The net count at `a` (search path).
    base: i64,
    /// One wave counting alone, with its rising edges up to `a`: the time is one division.
    single: Option<(Wave, u64)>,
}

impl Timer<'_> {
    /// The earliest time in (a, b] at which the count since `a` reaches `k`.
    fn time_of(&self, k: u64) -> Duration {
        if let Some((w, before)) = self.single {
            return w.rise_time(before + k).min(Duration::from_nanos(self.b));
        }
        let (mut lo, mut hi) = (self.a, self.b);
        while lo < hi {
            let mid = lo + (hi - lo) / 2;
            if (self.drive.at(mid) - self.base) * self.sign >= k as i64 {
                hi = mid;
            } else {
                lo = mid + 1;
            }
        }
        Duration::from_nanos(hi)
    }
}

fn level(mem: &Memory, p: Pin) -> bool {
    mem.i.get(p.0 as usize).is_some_and(|b| b >> p.1 & 1 != 0)
}

fn put_level(i: &mut [u8], p: Pin, on: bool) {
    if let Some(b) = i.get_mut(p.0 as usize) {
        if on {
            *b |= 1 << p.1;
        } else {
            *b &= !(1 << p.1);
        }
    }
}

fn level_in(i: &[u8], p: Pin) -> bool {
    i.get(p.0 as usize).is_some_and(|b| b >> p.1 & 1 != 0)
}

/// Compare state in multi-PV mode.
#[derive(Clone, Copy, Debug, Default, Serialize, Deserialize)]
struct Compare {
    seg: usize,
    target: i64,
    done: bool,
}

/// One high-speed counter.
#[derive(Clone, Debug)]
pub struct HscChannel {
    pub regs: HscRegs,
    pub spec: HscSpec,
    pub mode: Option<&'static HscModeInputs>,
    pub running: bool,
    cv: i64,
    dir_up: bool,
    rate4x: bool,
    reset_low: bool,
    start_low: bool,
    pv: i64,
    multi: bool,
    table: Option<PvTable>,
    fault: bool,
    cmp: Compare,
    last_up: bool,
    /// The user wrote SMD38 …: keep it until the next `HSC`.
    pub user_cv: bool,
    /// The drive of the last interval and what it was computed from.
    cache: Option<DriveCache>,
    /// The count as one formula while only time passes ([`Quiet`]).
    quiet: Option<Quiet>,
    /// Changes whenever a setting the drive depends on may have changed (HDEF, HSC, a
    /// snapshot): the quiet formula's cheap validity test, with the sources' generation.
    settings: u64,
    /// The direction the status bit last showed while running, and a change of it not yet
    /// raised as an event (the simulator raises it at its next step).
    shown_up: Option<bool>,
    pub(crate) dir_event: Option<bool>,
    /// When the counted signals turned the direction (the first count the other way), for
    /// the direction event; `None`: at the step's start (a written input, a setting).
    pub(crate) dir_at: Option<Duration>,
    /// Tests turn the quiet path off to compare it with the general one.
    #[cfg(test)]
    pub(crate) general_only: bool,
}

/// The count as one formula while only time passes: one edge stream counting in one
/// direction, from a drive that is still the same. A step then costs one edge count instead
/// of the drive's general sum; whether it reaches the PV is still tested every step, and any
/// change to the CV by other means (HSC, a written input, a snapshot) ends it.
#[derive(Clone, Copy, Debug)]
struct Quiet {
    /// The counter's settings and the input sources the formula was made from.
    settings: u64,
    sources: u64,
    wave: Wave,
    /// +1 counting up, −1 down.
    sign: i64,
    /// The interval's start (ns), the wave's rising edges and the CV then:
    /// CV(t) = cv0 + sign · (rises(t) − rises0) for t ≥ t0.
    t0: u64,
    rises0: u64,
    cv0: i64,
    /// The CV the formula last produced.
    cv: i64,
    /// The counter's status bits and segment number, which only a CV = PV step changes.
    status: u8,
    segment: u8,
    /// The PV a count would reach next ([`HscChannel::target`]) and the PV the status bits
    /// compare with ([`HscChannel::current_pv`]): both change only with the settings or at
    /// a CV = PV, and neither happens while the formula holds.
    target: Option<i64>,
    pv: Option<i64>,
}

/// What a drive depends on besides input levels: when none of it changed and the inputs
/// it read have the same levels, the drive is the same.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
struct DriveFrom {
    sources: u64,
    mode: Option<u8>,
    running: bool,
    dir_up: bool,
    rate4x: bool,
    start_low: bool,
}

/// A drive kept between intervals.
#[derive(Clone, Copy, Debug)]
struct DriveCache {
    from: DriveFrom,
    /// The input levels the drive was computed from.
    levels: [(Pin, bool); 3],
    n: u8,
    drive: Option<Drive>,
    /// The drive's net count at a time (ns), from the previous interval.
    at: Option<(u64, i64)>,
}

impl DriveCache {
    fn read(&self) -> &[(Pin, bool)] {
        &self.levels[..(self.n as usize).min(self.levels.len())]
    }
}

impl HscChannel {
    pub fn new(regs: HscRegs, spec: HscSpec) -> HscChannel {
        HscChannel {
            regs,
            spec,
            mode: None,
            running: false,
            cv: 0,
            dir_up: false,
            rate4x: false,
            reset_low: false,
            start_low: false,
            pv: 0,
            multi: false,
            table: None,
            fault: false,
            cmp: Compare::default(),
            last_up: true,
            user_cv: false,
            cache: None,
            quiet: None,
            settings: 0,
            shown_up: None,
            dir_event: None,
            dir_at: None,
            #[cfg(test)]
            general_only: false,
        }
    }

    pub fn cv(&self) -> i64 {
        self.cv
    }

    pub fn table(&self) -> Option<&PvTable> {
        self.table.as_ref()
    }

    /// The value compared against now (the current PV), if any.
    pub fn current_pv(&self) -> Option<i64> {
        if self.multi {
            self.table.as_ref().map(|_| self.cmp.target)
        } else {
            Some(self.pv)
        }
    }

    /// `HDEF n, mode`.
    pub fn hdef(&mut self, mode: u8) -> Result<String> {
        let ch = self.regs.channel;
        let Some(m) = sm_map::hsc_mode(ch, mode) else {
            let modes: Vec<String> = sm_map::hsc_modes_of(ch).iter().map(|m| m.to_string()).collect();
            return Err(Error::new(ErrorKind::Value, format!("HSC{ch} has no mode {mode} (manual §3.3.1)"))
                .hint(format!("HSC{ch}'s modes: {}", modes.join(", "))));
        };
        self.mode = Some(m);
        self.running = false;
        self.settings += 1;
        let text = sm_map::HSC_MODES.iter().find(|t| t.0 == ch && t.1 == mode).map(|t| t.2).unwrap_or("");
        Ok(format!("HSC{ch} mode {mode}: {text}"))
    }

    /// `HSC n` (§3.3.5): applies the control byte and (multi-)PV settings, starts or stops.
    pub fn hsc(&mut self, mem: &mut Memory) -> Result<String> {
        let r = self.regs;
        let ch = r.channel;
        let Some(m) = self.mode else {
            return Err(Error::state(format!("HSC{ch} has no mode yet")).hint(format!(
                "run `hdef {ch} MODE` first (HDEF, manual §3.3.5); modes: {}",
                sm_map::hsc_modes_of(ch).iter().map(|m| m.to_string()).collect::<Vec<_>>().join(", ")
            )));
        };
        let c = mem.sm_byte(r.control);
        self.user_cv = false;
        self.settings += 1;
        if c & ctl::ENABLE == 0 {
            self.running = false;
            return Ok(format!("HSC{ch} stopped (enable bit SM{}.7 is 0); CV {}", r.control, self.cv));
        }
        self.reset_low = c & ctl::RESET_LOW != 0;
        self.start_low = c & ctl::START_LOW != 0;
        self.rate4x = c & ctl::RATE_4X != 0;
        if c & ctl::WRITE_DIR != 0 && m.kind == HscKind::InternalDir {
            self.dir_up = c & ctl::DIR_UP != 0;
        }
        if c & ctl::WRITE_CV != 0 {
            self.cv = mem.sm_dword(r.cv) as i32 as i64;
        }
        let b = mem.sm_byte(r.mpv_control);
        self.multi = b & mpv::MULTI != 0;
        let mut notes = Vec::new();
        if !self.multi {
            if c & ctl::WRITE_PV != 0 {
                self.pv = mem.sm_dword(r.pv) as i32 as i64;
            }
            self.fault = false;
        } else if b & mpv::LOAD != 0 {
            let start = mem.sm_word(r.table) as u32;
            match read_table(&mem.v, start, b & mpv::RELATIVE != 0, b & mpv::CYCLIC != 0) {
                Ok(t) => {
                    self.table = Some(t);
                    self.fault = false;
                }
                Err(e) => {
                    self.table = None;
                    self.fault = true;
                    notes.push(format!("PV table fault (SM{}.3 = 1): {e}", r.status));
                }
            }
        } else if self.table.is_none() {
            self.fault = true;
            notes.push(format!(
                "PV table fault (SM{}.3 = 1): no table loaded; set SM{}.4 to load the table at SMW{}",
                r.status, r.mpv_control, r.table
            ));
        }
        if let Some(t) = &mut self.table {
            // The PV type and cyclic bits apply at every HSC, also to a table kept from before.
            t.relative = b & mpv::RELATIVE != 0;
            t.cyclic = t.relative && b & mpv::CYCLIC != 0;
        }
        if let Some(t) = &self.table {
            if self.multi {
                if b & mpv::KEEP_SEGMENT == 0 || self.cmp.seg >= t.pvs.len() {
                    self.cmp.seg = 0;
                }
                self.cmp.done = false;
                self.cmp.target = if t.relative { self.cv + t.pvs[self.cmp.seg] } else { t.pvs[self.cmp.seg] };
            }
        }
        self.running = true;
        self.publish(mem);
        let cmp = match (&self.table, self.multi) {
            (Some(t), true) => format!(
                "{} {} PVs{}, next CV = PV at {}",
                t.pvs.len(),
                if t.relative { "relative" } else { "absolute" },
                if t.cyclic { " (cyclic)" } else { "" },
                self.cmp.target
            ),
            (None, true) => "no PV table".to_string(),
            _ => format!("single PV {}", self.pv),
        };
        let mut msg = format!("HSC{ch} counting in mode {} from CV {}; {cmp}", m.mode, self.cv);
        for n in notes {
            msg.push_str("; ");
            msg.push_str(&n);
        }
        Ok(msg)
    }

    fn target(&self) -> Option<i64> {
        if self.multi {
            if self.table.is_some() && !self.cmp.done {
                Some(self.cmp.target)
            } else {
                None
            }
        } else {
            Some(self.pv)
        }
    }

    fn hit_kind(&self) -> EventKind {
        let channel = self.regs.channel;
        if self.multi {
            EventKind::HscCvEqPv { channel, pv: Some(self.cmp.seg as u8 + 1) }
        } else {
            EventKind::HscCvEqPv { channel, pv: None }
        }
    }

    fn on_hit(&mut self, cv: i64) {
        if !self.multi {
            return;
        }
        let Some(t) = &self.table else { return };
        self.cmp.seg += 1;
        if self.cmp.seg == t.pvs.len() {
            if t.relative && t.cyclic {
                self.cmp.seg = 0;
                self.cmp.target = cv + t.pvs[0];
            } else {
                self.cmp.done = true;
                self.cmp.seg = t.pvs.len() - 1;
            }
        } else {
            self.cmp.target = if t.relative { cv + t.pvs[self.cmp.seg] } else { t.pvs[self.cmp.seg] };
        }
    }

    /// Whether `total` counts from the current value reach the current PV (the first
    /// test of [`Self::count`]).
    #[inline]
    fn hits(&self, total: i64) -> bool {
        let n = total.unsigned_abs();
        self.target().is_some_and(|target| {
            let dist = (target - self.cv) * total.signum();
            dist > 0 && dist as u64 <= n
        })
    }

    /// Applies `total` counts along a monotone path, raising CV = PV events timed by
    /// `time_of(k)` (the time of the k-th count).
    fn count(
        &mut self,
        total: i64,
        time_of: &dyn Fn(u64) -> Duration,
        raised: &mut Vec<(Duration, EventKind)>,
        skipped: &mut u64,
    ) {
        if total == 0 {
            return;
        }
        let sign = total.signum();
        let n = total.unsigned_abs();
        self.last_up = sign > 0;
        let mut used = 0u64;
        let mut cv = self.cv;
        while let Some(target) = self.target() {
            let dist = (target - cv) * sign;
            if dist <= 0 || dist as u64 > n - used {
                break;
            }
            used += dist as u64;
            cv = target;
            raised.push((time_of(used), self.hit_kind()));
            self.on_hit(cv);
            self.skip_cycles(sign, n - used, &mut used, &mut cv, skipped);
        }
        self.cv += total;
    }

    /// In relative cyclic mode, at the start of a cycle, jumps over whole cycles that
    /// would only be dropped from the log.
    fn skip_cycles(&mut self, sign: i64, remaining: u64, used: &mut u64, cv: &mut i64, skipped: &mut u64) {
        let Some(t) = &self.table else { return };
        if !(self.multi && t.cyclic && self.cmp.seg == 0 && t.pvs.iter().all(|p| p.signum() == sign)) {
            return;
        }
        let l: i64 = t.pvs.iter().sum();
        let cycle = l.unsigned_abs();
        let per = t.pvs.len() as u64;
        let keep = LOG_CAP as u64 / per + 1;
        let cycles = remaining / cycle;
        if cycles > keep {
            let skip = cycles - keep;
            *used += skip * cycle;
            *cv += l * skip as i64;
            self.cmp.target += l * skip as i64;
            *skipped += skip * per;
        }
    }

    fn active(level: bool, low: bool) -> bool {
        level != low
    }

    /// The edge streams that count during an interval starting now.
    fn drive(&self, inputs: &Inputs, mem: &Memory) -> Option<Drive> {
        self.drive_with(inputs, &mut |p| level(mem, p))
    }

    /// What [`Self::drive`] depends on besides input levels.
    fn drive_from(&self, inputs: &Inputs) -> DriveFrom {
        DriveFrom {
            sources: inputs.generation(),
            mode: self.mode.map(|m| m.mode),
            running: self.running,
            dir_up: self.dir_up,
            rate4x: self.rate4x,
            start_low: self.start_low,
        }
    }

    /// [`Self::drive`], kept from the last interval while nothing it depends on changed
    /// (the same sources, settings and levels of the inputs it read).
    #[inline]
    fn cached_drive(&mut self, inputs: &Inputs, mem: &Memory) -> &mut DriveCache {
        let from = self.drive_from(inputs);
        let fresh = self.cache.as_ref().is_some_and(|c| {
            c.from == from && c.n as usize <= c.levels.len() && c.read().iter().all(|&(p, l)| level(mem, p) == l)
        });
        if !fresh {
            let mut c = DriveCache { from, levels: [((0, 0), false); 3], n: 0, drive: None, at: None };
            c.drive = self.drive_with(inputs, &mut |p| {
                let l = level(mem, p);
                match c.levels.get_mut(c.n as usize) {
                    Some(slot) => {
                        *slot = (p, l);
                        c.n += 1;
                    }
                    None => c.n = u8::MAX, // more than it can keep: never reused
                }
                l
            });
            self.cache = Some(c);
        }
        self.cache.as_mut().expect("just filled")
    }

    /// [`Self::drive`] with the input levels from `level`.
    fn drive_with(&self, inputs: &Inputs, level: &mut dyn FnMut(Pin) -> bool) -> Option<Drive> {
        let m = self.mode?;
        if !self.running {
            return None;
        }
        if let Some(s) = m.start {
            if !Self::active(level(s), self.start_low) {
                return None;
            }
        }
        let mut d = Drive::default();
        match m.kind {
            HscKind::InternalDir | HscKind::ExternalDir => {
                let w = inputs.wave(m.count);
                let e = inputs.pin_edges(m.count);
                if w.is_none() && e.is_none() {
                    return None;
                }
                let up = match m.kind {
                    HscKind::InternalDir => self.dir_up,
                    _ => m.dir.is_some_and(&mut *level),
                };
                match (w, e, up) {
                    (Some(w), _, true) => d.up.push(w),
                    (Some(w), _, false) => d.down.push(w),
                    (None, Some(e), up) => d.add_term(Term::Pin(e), if up { 1 } else { -1 }),
                    (None, None, _) => {}
                }
            }
            HscKind::TwoPulse => {
                if let Some(w) = inputs.wave(m.count) {
                    d.up.push(w);
                } else if let Some(e) = inputs.pin_edges(m.count) {
                    d.add_term(Term::Pin(e), 1);
                }
                if let Some(w) = m.second.and_then(|p| inputs.wave(p)) {
                    d.down.push(w);
                } else if let Some(e) = m.second.and_then(|p| inputs.pin_edges(p)) {
                    d.add_term(Term::Pin(e), -1);
                }
            }
            HscKind::Quadrature => {
                let (a, b) = (m.count, m.second?);
                if let Some((track, swapped)) = inputs.track(a, b) {
                    d.add_term(Term::Quad { track, swapped, x4: self.rate4x }, 1);
                } else if let Some((w, a_leads)) = inputs.quad(a, b) {
                    let half = w.half_ns();
                    let (wa, wb) = if a_leads { (w, w.shifted(half / 2)) } else { (w.shifted(half / 2), w) };
                    // 1×: A's edge while B is low — rising when A leads (up), falling when
                    // B leads (down), as `Track::quad` and written edges count.
                    let edges = if self.rate4x {
                        Streams::of(&[wa, wa.shifted(half), wb, wb.shifted(half)])
                    } else if a_leads {
                        Streams::of(&[wa])
                    } else {
                        Streams::of(&[wa.shifted(half)])
                    };
                    if a_leads {
                        d.up = edges
                    } else {
                        d.down = edges
                    }
                } else {
                    match (inputs.wave(a), inputs.wave(b)) {
                        (Some(wa), None) => {
                            let b_high = level(b);
                            let fall = wa.shifted(wa.half_ns());
                            match (self.rate4x, b_high) {
                                // 1×: A's edges while B is low, rising up and falling down
                                // (a square wave on A alone comes and goes); none while B is high.
                                (false, false) => (d.up, d.down) = (Streams::of(&[wa]), Streams::of(&[fall])),
                                (false, true) => {}
                                (true, false) => (d.up, d.down) = (Streams::of(&[wa]), Streams::of(&[fall])),
                                (true, true) => (d.up, d.down) = (Streams::of(&[fall]), Streams::of(&[wa])),
                            }
                        }
                        (None, Some(wb)) if self.rate4x => {
                            let fall = wb.shifted(wb.half_ns());
                            if level(a) {
                                (d.up, d.down) = (Streams::of(&[wb]), Streams::of(&[fall]))
                            } else {
                                (d.up, d.down) = (Streams::of(&[fall]), Streams::of(&[wb]))
                            }
                        }
                        _ => return None,
                    }
                }
            }
        }
        Some(d)
    }

    /// Counts the interval (last, now] from the input sources.
    #[inline]
    pub fn advance(
        &mut self,
        mem: &mut Memory,
        inputs: &Inputs,
        from: (Duration, u64),
        to: (Duration, u64),
        raised: &mut Vec<(Duration, EventKind)>,
        skipped: &mut u64,
    ) {
        if !self.quiet_step(mem, inputs, to.1) {
            self.advance_general(mem, inputs, from, to, raised, skipped);
        }
    }

    /// [`Self::advance`] when the quiet formula does not apply.
    #[inline(never)]
    fn advance_general(
        &mut self,
        mem: &mut Memory,
        inputs: &Inputs,
        (last, a): (Duration, u64),
        (now, b): (Duration, u64),
        raised: &mut Vec<(Duration, EventKind)>,
        skipped: &mut u64,
    ) {
        // A counter without a mode or not running counts nothing (`drive` is None).
        if self.running && self.mode.is_some() && b > a {
            let was_up = self.last_up;
            let counted_dir = self.mode.is_some_and(|m| matches!(m.kind, HscKind::Quadrature | HscKind::TwoPulse));
            let mut dir_at = None;
            let c = self.cached_drive(inputs, mem);
            if let Some(d) = &c.drive {
                // The count at `a` ns was worked out by the previous interval.
                let at_a = match c.at {
                    Some((t, n)) if t == a => n,
                    _ => d.at(a),
                };
                let at_b = d.at(b);
                c.at = Some((b, at_b));
                let total = at_b - at_a;
                if total != 0 && (total > 0) != was_up && counted_dir {
                    // The counted direction (A/B, two-pulse) turns with the first count of the
                    // interval: that is when the status bit changes, however long the interval.
                    dir_at = Some(d.timer(last, now, total.signum()).time_of(1));
                }
                if dir_at.is_some() {
                    self.dir_at = dir_at;
                }
                if total != 0 {
                    if self.hits(total) {
                        self.count_timed(last, now, total, raised, skipped);
                    } else {
                        // What `count` does when no PV is reached.
                        self.last_up = total > 0;
                        self.cv += total;
                    }
                }
            }
            self.quiet = self.cache.as_ref().filter(|c| c.n == 0).and_then(|c| {
                let (wave, sign) = c.drive?.single()?;
                Some(Quiet {
                    settings: self.settings,
                    sources: c.from.sources,
                    wave,
                    sign,
                    t0: b,
                    rises0: wave.rises_ns(b),
                    cv0: self.cv,
                    cv: self.cv,
                    status: 0,
                    segment: 0,
                    target: self.target(),
                    pv: self.current_pv(),
                })
            });
        }
        self.publish(mem);
    }

    /// A step by the [`Quiet`] formula, when it holds and no PV is reached; false leaves
    /// the step to the general path.
    #[inline]
    fn quiet_step(&mut self, mem: &mut Memory, inputs: &Inputs, b: u64) -> bool {
        #[cfg(test)]
        if self.general_only {
            return false;
        }
        let Some(q) = &self.quiet else { return false };
        if b < q.t0 || q.cv != self.cv || q.settings != self.settings || q.sources != inputs.generation() {
            return false;
        }
        let cv = q.cv0 + q.sign * (q.wave.rises_ns(b) - q.rises0) as i64;
        let total = cv - self.cv;
        // A step reaching the PV, or turning the direction bit, goes the general way; in the
        // others only CV = PV and CV > PV can change (moving off a PV, or past the last PV
        // of a finished table), and the segment cannot.
        let reaches = q.target.is_some_and(|target| {
            let dist = (target - self.cv) * total.signum();
            dist > 0 && dist as u64 <= total.unsigned_abs()
        });
        if reaches || (total != 0 && self.last_up != (total > 0)) {
            return false;
        }
        let (eq, gt) = match q.pv {
            Some(pv) => (cv == pv, cv > pv),
            None => (false, false),
        };
        const CMP: u8 = 1 << st::EQUAL | 1 << st::GREATER;
        let status = q.status & !CMP | (eq as u8) << st::EQUAL | (gt as u8) << st::GREATER;
        let segment = q.segment;
        if total != 0 {
            self.last_up = total > 0;
            self.cv = cv;
        }
        if let Some(q) = &mut self.quiet {
            (q.cv, q.status) = (cv, status);
        }
        let r = self.regs;
        if !self.user_cv {
            mem.set_sm_dword(r.cv, cv as i32 as u32);
        }
        mem.set_sm_byte(r.status, mem.sm_byte(r.status) & !STATUS_BITS | status);
        mem.set_sm_byte(r.segment, segment);
        true
    }

    /// [`Self::count`] for an interval in which a CV = PV event falls: the events are timed
    /// from the drive (kept out of line: most steps reach no PV).
    #[cold]
    #[inline(never)]
    fn count_timed(
        &mut self,
        last: Duration,
        now: Duration,
        total: i64,
        raised: &mut Vec<(Duration, EventKind)>,
        skipped: &mut u64,
    ) {
        let d = self.cache.as_ref().and_then(|c| c.drive).expect("counting needs a drive");
        let timer = std::cell::OnceCell::new();
        let time_of = |k| timer.get_or_init(|| d.timer(last, now, total.signum())).time_of(k);
        self.count(total, &time_of, raised, skipped);
    }

    /// The inputs the current mode reads.
    pub fn pins(&self) -> Vec<Pin> {
        let Some(m) = self.mode else { return Vec::new() };
        let mut v: Vec<Pin> = [Some(m.count), m.second, m.dir, m.reset, m.start].into_iter().flatten().collect();
        v.dedup();
        v
    }

    /// Counts the interval `(a, b]` ns edge by edge ([`super::edges`]): a stuck or noisy
    /// fault acts on one of the counter's inputs then. Each edge is counted as a written
    /// input's is, at its own time (CV = PV and direction events at that time).
    pub fn advance_edges(
        &mut self,
        mem: &mut Memory,
        inputs: &Inputs,
        faults: &super::fault::Faults,
        (a, b): (u64, u64),
        raised: &mut Vec<(Duration, EventKind)>,
    ) {
        let pins = self.pins();
        if !self.running || pins.is_empty() || b <= a {
            return;
        }
        // The level each input had (as written) before a fault took it.
        let written = |p: Pin| {
            faults.list.iter().filter(|f| f.kind.pin() == Some(p)).find_map(|f| f.held).unwrap_or(level(mem, p))
        };
        let mut img = mem.i.clone();
        let mut all: Vec<(u64, Pin, bool)> = Vec::new();
        for &p in &pins {
            let (start, ch) = super::edges::changes(inputs, faults, p, a, b, written(p));
            put_level(&mut img, p, start);
            all.extend(ch.into_iter().map(|(t, l)| (t, p, l)));
        }
        all.sort_by_key(|e| e.0);
        // The counter works on the levels it sees; the image is the simulator's to set.
        let shown = std::mem::replace(&mut mem.i, img);
        for (t, p, l) in all {
            let old = mem.i.clone();
            put_level(&mut mem.i, p, l);
            let at = Duration::from_nanos(t);
            self.input_edges(mem, &old, at, raised);
            if let Some(up) = self.dir_event.take() {
                raised.push((at, EventKind::HscDirection { channel: self.regs.channel, up }));
            }
        }
        mem.i = shown;
        // The drive is worked out again from the sources after the interval.
        self.cache = None;
        self.quiet = None;
        self.publish(mem);
    }

    /// Counts edges the user wrote to the inputs (`set I0.1=1`), at `now`.
    pub fn input_edges(
        &mut self,
        mem: &mut Memory,
        old: &[u8],
        now: Duration,
        raised: &mut Vec<(Duration, EventKind)>,
    ) {
        let Some(m) = self.mode else { return };
        if !self.running {
            return;
        }
        // Written edges may move the CV and the PV compared next: no quiet formula across.
        self.settings += 1;
        let new = mem.i.clone();
        let (o, n) = (|p: Pin| level_in(old, p), |p: Pin| level_in(&new, p));
        if let Some(p) = m.reset {
            if !Self::active(o(p), self.reset_low) && Self::active(n(p), self.reset_low) {
                self.cv = 0;
                raised.push((now, EventKind::HscReset { channel: self.regs.channel }));
            }
        }
        if let Some(p) = m.start {
            if !Self::active(n(p), self.start_low) {
                self.publish(mem);
                return;
            }
        }
        let rise = |p: Pin| !o(p) && n(p);
        let delta: i64 = match m.kind {
            HscKind::InternalDir | HscKind::ExternalDir => {
                let up = match m.kind {
                    HscKind::InternalDir => self.dir_up,
                    _ => m.dir.is_some_and(n),
                };
                if rise(m.count) {
                    if up {
                        1
                    } else {
                        -1
                    }
                } else {
                    0
                }
            }
            HscKind::TwoPulse => i64::from(rise(m.count)) - m.second.map_or(0, |p| i64::from(rise(p))),
            HscKind::Quadrature => {
                let Some(b) = m.second else { return };
                let a = m.count;
                let (da, db) = (o(a) != n(a), o(b) != n(b));
                let s = |up: bool| if up { 1 } else { -1 };
                match (da, db) {
                    // 1×: A's edge while B is low, up when A rises, down when it falls.
                    (true, false) if !self.rate4x => {
                        if n(b) {
                            0
                        } else {
                            s(n(a))
                        }
                    }
                    (true, false) => s(n(a) != n(b)),
                    (false, true) if self.rate4x => s(n(a) == n(b)),
                    _ => 0,
                }
            }
        };
        let mut skipped = 0;
        self.count(delta, &|_| now, raised, &mut skipped);
        self.publish(mem);
    }

    /// Writes CV, status and segment into the SM registers.
    #[inline]
    pub fn publish(&mut self, mem: &mut Memory) {
        let r = self.regs;
        if !self.user_cv {
            mem.set_sm_dword(r.cv, self.cv as i32 as u32);
        }
        let (status, segment) = self.status_bits(mem);
        let up = status & 1 << st::DIR_UP != 0;
        if !self.running {
            self.shown_up = None;
        } else if self.shown_up.replace(up).is_some_and(|was| was != up) {
            self.dir_event = Some(up);
        }
        mem.set_sm_byte(r.status, mem.sm_byte(r.status) & !STATUS_BITS | status);
        mem.set_sm_byte(r.segment, segment);
        if let Some(q) = &mut self.quiet {
            (q.status, q.segment) = (status, segment);
        }
    }

    /// The status byte's bits this counter owns ([`STATUS_BITS`]) and the segment number.
    fn status_bits(&self, mem: &Memory) -> (u8, u8) {
        let up = match self.mode {
            Some(m) if m.kind == HscKind::InternalDir => self.dir_up,
            Some(m) if m.kind == HscKind::ExternalDir => m.dir.is_some_and(|p| level(mem, p)),
            _ => self.last_up,
        };
        let (eq, gt) = match self.current_pv() {
            Some(pv) => (self.cv == pv, self.cv > pv),
            None => (false, false),
        };
        let bits = (self.fault as u8) << st::TABLE_FAULT
            | (up as u8) << st::DIR_UP
            | (eq as u8) << st::EQUAL
            | (gt as u8) << st::GREATER;
        (bits, if self.multi { self.cmp.seg as u8 } else { 0 })
    }

    /// When the next CV = PV crossing will happen from the current sources, if it will
    /// (for `wait event` in stepped time).
    pub fn next_due(&self, inputs: &Inputs, mem: &Memory, now: Duration) -> Option<Duration> {
        let d = self.drive(inputs, mem)?;
        let target = self.target()?;
        let rate_probe = now + Duration::from_secs(1);
        let sign = (d.at(ns(rate_probe)) - d.at(ns(now))).signum();
        let dist = (target - self.cv) * sign;
        if sign == 0 || dist <= 0 {
            return None;
        }
        // Search far enough ahead: a day of virtual time bounds any wait.
        let horizon = now + Duration::from_secs(86_400);
        if (d.at(ns(horizon)) - d.at(ns(now))) * sign < dist {
            return None;
        }
        Some(d.timer(now, horizon, sign).time_of(dist as u64))
    }
}

/// A counter's state for snapshots (`crate::snapshot`): everything but the registers, the
/// model's limits and the cache (worked out again on the next step).
#[derive(Clone, Debug, Serialize, Deserialize)]
pub struct HscState {
    /// The `HDEF` mode number.
    mode: Option<u8>,
    running: bool,
    cv: i64,
    dir_up: bool,
    rate4x: bool,
    reset_low: bool,
    start_low: bool,
    pv: i64,
    multi: bool,
    table: Option<PvTable>,
    fault: bool,
    cmp: Compare,
    last_up: bool,
    user_cv: bool,
}

impl HscChannel {
    pub fn save(&self) -> HscState {
        HscState {
            mode: self.mode.map(|m| m.mode),
            running: self.running,
            cv: self.cv,
            dir_up: self.dir_up,
            rate4x: self.rate4x,
            reset_low: self.reset_low,
            start_low: self.start_low,
            pv: self.pv,
            multi: self.multi,
            table: self.table.clone(),
            fault: self.fault,
            cmp: self.cmp,
            last_up: self.last_up,
            user_cv: self.user_cv,
        }
    }

    /// Restores a saved state; refuses a mode this channel does not have.
    pub fn load(&mut self, s: HscState) -> std::result::Result<(), String> {
        self.mode = match s.mode {
            Some(m) => Some(
                sm_map::hsc_mode(self.regs.channel, m)
                    .ok_or_else(|| format!("HSC{} has no mode {m}", self.regs.channel))?,
            ),
            None => None,
        };
        self.running = s.running;
        self.cv = s.cv;
        self.dir_up = s.dir_up;
        self.rate4x = s.rate4x;
        self.reset_low = s.reset_low;
        self.start_low = s.start_low;
        self.pv = s.pv;
        self.multi = s.multi;
        self.table = s.table;
        self.fault = s.fault;
        self.cmp = s.cmp;
        self.last_up = s.last_up;
        self.user_cv = s.user_cv;
        self.cache = None;
        self.quiet = None;
        self.settings += 1;
        (self.shown_up, self.dir_event, self.dir_at) = (None, None, None);
        Ok(())
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn tables_end_at_small_relative_pvs_and_close_absolute_ones() {
        let mut v = vec![0u8; 64];
        v[9] = 3;
        v[10..14].copy_from_slice(&10i32.to_be_bytes());
        v[14..18].copy_from_slice(&1i32.to_be_bytes());
        v[18..22].copy_from_slice(&1000i32.to_be_bytes());
        let t = read_table(&v, 9, true, true).unwrap();
        assert_eq!(t.pvs, vec![10], "|PV| ≤ 1 ends a relative table");
        let t = read_table(&v, 9, false, true).unwrap();
        assert_eq!(t.pvs, vec![10, 1, 1000], "absolute neighbours differ by more than 1");
        assert!(!t.cyclic, "cyclic applies to relative tables only");
        v[14..18].copy_from_slice(&11i32.to_be_bytes());
        assert_eq!(read_table(&v, 9, false, false).unwrap().pvs, vec![10], "11 is within 1 of 10: the table ends");
    }

    #[test]
    fn table_faults() {
        let v = vec![0u8; 64];
        assert!(read_table(&v, 8, true, false).unwrap_err().contains("even"));
        assert!(read_table(&v, 9, true, false).unwrap_err().contains("0 PVs"));
        let mut v = vec![0u8; 64];
        v[1] = 33;
        assert!(read_table(&v, 1, true, false).unwrap_err().contains("33 PVs"));
    }
}
