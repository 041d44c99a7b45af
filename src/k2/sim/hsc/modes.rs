//! What each high-speed counter mode counts (manual §3.3.1; inputs from
//! [`crate::k2::sm_map::HSC_MODE_INPUTS`]): from the simulated input signals
//! ([`crate::k2::sim::inputs`]) a mode's "drive" — the edge streams that count up and down
//! during an interval, with wired pulse trains and encoders as other terms — and the time of
//! the k-th count of an interval; and the count of edges written to I0.x. The drive is kept
//! between intervals while the sources, the counter's settings and the input levels it read
//! are unchanged ([`DriveCache`]).

use super::HscChannel;
use crate::k2::instr::EventKind;
use crate::k2::memory::Memory;
use crate::k2::sim::inputs::{ns, Inputs, Pin, PinEdges, Track, Wave};
use crate::k2::sm_map::HscKind;
use std::time::Duration;

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
pub(super) struct Drive {
    up: Streams,
    down: Streams,
    terms: [Option<(Term, i64)>; 2],
}

impl Drive {
    /// The net count at `t` ns.
    #[inline]
    pub(super) fn at(&self, t: u64) -> i64 {
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
    pub(super) fn single(&self) -> Option<(Wave, i64)> {
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
    pub(super) fn timer(&self, a: Duration, b: Duration, sign: i64) -> Timer<'_> {
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
pub(super) struct Timer<'a> {
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
    pub(super) fn time_of(&self, k: u64) -> Duration {
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

pub(super) fn level(mem: &Memory, p: Pin) -> bool {
    mem.i.get(p.0 as usize).is_some_and(|b| b >> p.1 & 1 != 0)
}

pub(super) fn put_level(i: &mut [u8], p: Pin, on: bool) {
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

/// What a drive depends on besides input levels: when none of it changed and the inputs
/// it read have the same levels, the drive is the same.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub(super) struct DriveFrom {
    pub(super) sources: u64,
    pub(super) mode: Option<u8>,
    pub(super) running: bool,
    pub(super) dir_up: bool,
    rate4x: bool,
    pub(super) start_low: bool,
}

/// A drive kept between intervals.
#[derive(Clone, Copy, Debug)]
pub(super) struct DriveCache {
    pub(super) from: DriveFrom,
    /// The input levels the drive was computed from.
    pub(super) levels: [(Pin, bool); 3],
    pub(super) n: u8,
    pub(super) drive: Option<Drive>,
    /// The drive's net count at a time (ns), from the previous interval.
    pub(super) at: Option<(u64, i64)>,
}

impl DriveCache {
    fn read(&self) -> &[(Pin, bool)] {
        &self.levels[..(self.n as usize).min(self.levels.len())]
    }
}

impl HscChannel {
    fn active(level: bool, low: bool) -> bool {
        level != low
    }

    /// The edge streams that count during an interval starting now.
    pub(super) fn drive(&self, inputs: &Inputs, mem: &Memory) -> Option<Drive> {
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
    pub(super) fn cached_drive(&mut self, inputs: &Inputs, mem: &Memory) -> &mut DriveCache {
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

    /// The inputs the current mode reads.
    pub fn pins(&self) -> Vec<Pin> {
        let Some(m) = self.mode else { return Vec::new() };
        let mut v: Vec<Pin> = [Some(m.count), m.second, m.dir, m.reset, m.start].into_iter().flatten().collect();
        v.dedup();
        v
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
}
