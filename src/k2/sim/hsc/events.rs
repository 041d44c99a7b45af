//! A high-speed counter over an interval of virtual time, and the events it raises (manual
//! §3.3; k2.md §4): the count the mode's drive makes ([`super::modes`]), the "CV = PV"
//! crossings timed exactly inside the interval with the manual's event numbers, single-PV and
//! multi-PV compare (absolute / relative / cyclic, whole cycles skipped arithmetically when
//! the log could not keep them), counting edge by edge while a fault acts on an input, and
//! when the next crossing will be. While one edge stream counts alone a step is one formula
//! ([`Quiet`]).

use super::modes::{level, put_level};
use super::regs::{st, STATUS_BITS};
use super::HscChannel;
use crate::k2::instr::EventKind;
use crate::k2::memory::Memory;
use crate::k2::sim::events::LOG_CAP;
use crate::k2::sim::inputs::{ns, Inputs, Pin, Wave};
use crate::k2::sm_map::HscKind;
use std::time::Duration;

/// The count as one formula while only time passes: one edge stream counting in one
/// direction, from a drive that is still the same. A step then costs one edge count instead
/// of the drive's general sum; whether it reaches the PV is still tested every step, and any
/// change to the CV by other means (HSC, a written input, a snapshot) ends it.
#[derive(Clone, Copy, Debug)]
pub(super) struct Quiet {
    /// The counter's settings and the input sources the formula was made from.
    pub(super) settings: u64,
    pub(super) sources: u64,
    pub(super) wave: Wave,
    /// +1 counting up, −1 down.
    pub(super) sign: i64,
    /// The interval's start (ns), the wave's rising edges and the CV then:
    /// CV(t) = cv0 + sign · (rises(t) − rises0) for t ≥ t0.
    pub(super) t0: u64,
    pub(super) rises0: u64,
    pub(super) cv0: i64,
    /// The CV the formula last produced.
    pub(super) cv: i64,
    /// The counter's status bits and segment number, which only a CV = PV step changes.
    pub(super) status: u8,
    pub(super) segment: u8,
    /// The PV a count would reach next ([`HscChannel::target`]) and the PV the status bits
    /// compare with ([`HscChannel::current_pv`]): both change only with the settings or at
    /// a CV = PV, and neither happens while the formula holds.
    pub(super) target: Option<i64>,
    pub(super) pv: Option<i64>,
}

impl HscChannel {
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
    pub(super) fn count(
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

    /// Counts the interval `(a, b]` ns edge by edge ([`crate::k2::sim::edges`]): a stuck or noisy
    /// fault acts on one of the counter's inputs then. Each edge is counted as a written
    /// input's is, at its own time (CV = PV and direction events at that time).
    pub fn advance_edges(
        &mut self,
        mem: &mut Memory,
        inputs: &Inputs,
        faults: &crate::k2::sim::fault::Faults,
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
            let (start, ch) = crate::k2::sim::edges::changes(inputs, faults, p, a, b, written(p));
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
