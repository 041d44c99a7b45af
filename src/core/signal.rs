//! Pulse trains described analytically in virtual time — the signal model a pulse output
//! (a K2 PTO channel) and a pulse input (a servo drive in pulse-train mode) both speak, so
//! wiring one to the other is handing over a value, not stepping pulse by pulse.
//!
//! A [`PulseTrain`] is a list of segments back to back: from `start` (virtual seconds), `count`
//! pulses at `freq` Hz in a direction (+1 / -1, the direction line or the CW/CCW channel).
//! This is the shape of a K2 PTO profile (k2.md §5: segments of constant frequency and pulse
//! count), so a PTO output converts by mapping its segments; an A/B encoder output is the
//! same description with the direction as the phase order. The pulse count at any time
//! comes from the segment formulas, so an hour at 200 kHz costs what a millisecond does.
//!
//! What a wire puts on an input is described as exactly: a pulse train's pulses as they
//! arrive ([`Train`]: whole-ns cycles, a given count) and an encoder's A/B outputs following a
//! planned position ([`Track`]: the A/B state is a function of the position, so the edges
//! between two instants follow from the position at those instants). They live here, below
//! the families, because the wiring model ([`crate::core::wiring`]) carries them between a
//! host and its peers.

/// One stretch of constant frequency.
#[derive(Clone, Copy, Debug, PartialEq, serde::Serialize, serde::Deserialize)]
pub struct PulseSegment {
    /// Virtual time of the first pulse's rising edge, seconds.
    #[serde(with = "crate::core::float_serde")]
    pub start: f64,
    /// Pulses per second (> 0).
    #[serde(with = "crate::core::float_serde")]
    pub freq: f64,
    /// Number of pulses.
    pub count: u64,
    /// +1 forward (direction line high / CW channel), -1 reverse.
    pub dir: i8,
}

impl PulseSegment {
    pub fn duration(&self) -> f64 {
        self.count as f64 / self.freq
    }
    pub fn end(&self) -> f64 {
        self.start + self.duration()
    }
    /// Pulses started by time `t` (a pulse counts at its rising edge, so the first at `start`).
    pub fn pulses_at(&self, t: f64) -> u64 {
        if t < self.start {
            return 0;
        }
        (((t - self.start) * self.freq).floor() as u64 + 1).min(self.count)
    }
}

/// A pulse signal: segments in time order, never overlapping.
#[derive(Clone, Debug, Default, PartialEq, serde::Serialize, serde::Deserialize)]
pub struct PulseTrain {
    segments: Vec<PulseSegment>,
}

impl PulseTrain {
    pub fn new() -> PulseTrain {
        PulseTrain::default()
    }

    pub fn segments(&self) -> &[PulseSegment] {
        &self.segments
    }

    /// When the train falls silent (the end of its last segment), or `None` when empty.
    pub fn end(&self) -> Option<f64> {
        self.segments.last().map(PulseSegment::end)
    }

    /// Appends `count` pulses at `freq` in `dir`, starting at `at` or when the previous
    /// segment ends, whichever is later. Returns the segment as queued.
    pub fn push(&mut self, at: f64, freq: f64, count: u64, dir: i8) -> Result<PulseSegment, String> {
        if !(freq.is_finite() && freq > 0.0) {
            return Err(crate::msg!("signal-freq-positive", freq = freq.to_string()).into());
        }
        let start = self.end().map_or(at, |e| e.max(at));
        let s = PulseSegment { start, freq, count, dir: if dir < 0 { -1 } else { 1 } };
        if count > 0 {
            self.segments.push(s);
        }
        Ok(s)
    }

    /// Net signed pulse count at time `t` (forward minus reverse).
    pub fn net_at(&self, t: f64) -> i64 {
        self.segments.iter().map(|s| s.dir as i64 * s.pulses_at(t) as i64).sum()
    }

    /// The frequency at time `t` (signed by direction; 0 between or after segments).
    pub fn rate_at(&self, t: f64) -> f64 {
        self.segments.iter().find(|s| t >= s.start && t < s.end()).map_or(0.0, |s| s.dir as f64 * s.freq)
    }

    /// The signal from `t` on as `(duration, signed rate)` pieces, gaps as rate 0 — what a
    /// follower integrates (the average rate; a pulse's own edge is below its resolution).
    pub fn pieces_from(&self, t: f64) -> Vec<(f64, f64)> {
        let mut out = Vec::new();
        let mut now = t;
        for s in &self.segments {
            if s.end() <= now {
                continue;
            }
            if s.start > now {
                out.push((s.start - now, 0.0));
                now = s.start;
            }
            out.push((s.end() - now, s.dir as f64 * s.freq));
            now = s.end();
        }
        out
    }

    /// Drops segments that ended before `t` (they no longer change anything ahead).
    pub fn forget_before(&mut self, t: f64) {
        self.segments.retain(|s| s.end() > t);
    }
}

/// `⌊n / d⌋` rounding toward minus infinity (`d` > 0).
#[inline]
pub fn floor_div(n: i64, d: i64) -> i64 {
    n.div_euclid(d)
}

/// The pulses of one stretch of a pulse train on an input: `count` cycles of `cycle_ns`,
/// the first rising at `first_ns`; each pulse is high for the first half of its cycle (as
/// a pulse output puts it out, e.g. the K2's `k2::sim::pto::PtoRun::level_at`), so the input
/// is low when the train ends.
#[derive(Clone, Copy, Debug, PartialEq, Eq, serde::Serialize, serde::Deserialize)]
pub struct Train {
    pub first_ns: u64,
    pub cycle_ns: u64,
    pub count: u64,
}

impl Train {
    /// Rising edges at or before `t` ns.
    #[inline]
    pub fn rises_ns(&self, t: u64) -> u64 {
        if t < self.first_ns || self.count == 0 {
            return 0;
        }
        ((t - self.first_ns) / self.cycle_ns.max(1) + 1).min(self.count)
    }

    /// The level at `t` ns.
    pub fn level_ns(&self, t: u64) -> bool {
        if t < self.first_ns {
            return false;
        }
        let c = self.cycle_ns.max(1);
        let e = t - self.first_ns;
        e / c < self.count && e % c < c / 2
    }

    /// When the last pulse has fallen (the input is low from then on).
    pub fn low_from_ns(&self) -> u64 {
        let c = self.cycle_ns.max(1);
        self.first_ns.saturating_add(c.saturating_mul(self.count.saturating_sub(1))).saturating_add(c / 2)
    }
}

/// An incremental encoder's A/B outputs while its position moves one way with constant
/// acceleration: `x(τ) = x0 + v·τ + a·τ²/2` in 4× counts, `τ` seconds after `t0_ns`, held
/// at its value `dur` seconds on.
///
/// The A/B state is a function of the position (`n = ⌊x⌋`): `n mod 4` = 0 → A high, B low;
/// 1 → both high; 2 → A low, B high; 3 → both low. So A rises wherever the position
/// crosses a whole encoder period (`x = 4k`, one line) moving up, B a quarter period later,
/// and at position 0 (a drive's position at power-up) A is high and B low. A 1× decoder
/// (the K2's `SM37.2 = 0`) then counts once per period, at that edge of A ([`Track::quad`]).
#[derive(Clone, Copy, Debug, PartialEq, serde::Serialize, serde::Deserialize)]
pub struct Track {
    pub t0_ns: u64,
    /// Seconds the stretch lasts; `+∞` for the last one (saved as `"inf"`).
    #[serde(with = "crate::core::float_serde::duration")]
    pub dur: f64,
    #[serde(with = "crate::core::float_serde")]
    pub x0: f64,
    #[serde(with = "crate::core::float_serde")]
    pub v: f64,
    #[serde(with = "crate::core::float_serde")]
    pub a: f64,
}

impl Track {
    /// The position (4× counts) at `t` ns.
    #[inline]
    pub fn x(&self, t: u64) -> f64 {
        let tau = (t.saturating_sub(self.t0_ns) as f64 / 1e9).min(self.dur);
        self.x0 + self.v * tau + 0.5 * self.a * tau * tau
    }

    /// The position its formula gives at `t` ns, also past `dur` (where the next stretch of
    /// the same motion starts).
    pub fn x_unheld(&self, t: u64) -> f64 {
        let tau = t.saturating_sub(self.t0_ns) as f64 / 1e9;
        self.x0 + self.v * tau + 0.5 * self.a * tau * tau
    }

    /// The 4× state count `⌊x⌋` at `t` ns (a position within float noise of a whole count
    /// is on it).
    #[inline]
    pub fn n(&self, t: u64) -> i64 {
        let x = self.x(t);
        let r = x.round();
        if (x - r).abs() < 1e-6 {
            r as i64
        } else {
            x.floor() as i64
        }
    }

    /// Moving up (the track moves one way; at rest counts as up).
    pub fn up(&self) -> bool {
        self.v > 0.0 || (self.v == 0.0 && self.a >= 0.0)
    }

    /// A's and B's levels in state `n`.
    pub fn levels(n: i64) -> (bool, bool) {
        match n.rem_euclid(4) {
            0 => (true, false),
            1 => (true, true),
            2 => (false, true),
            _ => (false, false),
        }
    }

    /// Rising edges of A (`of_b` false) or B since any earlier instant of the track, as a
    /// non-decreasing function of time (differences count the edges between two instants).
    /// Moving up, A rises entering state 0 (mod 4) and B entering 1; moving down, A rises
    /// leaving state 2 and B leaving state 3.
    #[inline]
    pub fn rises(&self, t: u64, of_b: bool) -> i64 {
        let n = self.n(t);
        match (self.up(), of_b) {
            (true, false) => floor_div(n, 4),
            (true, true) => floor_div(n - 1, 4),
            (false, false) => -floor_div(n - 2, 4),
            (false, true) => -floor_div(n - 3, 4),
        }
    }

    /// What an A/B decoder counts (up to a constant) at `t`: at 4× every state change (`n`),
    /// at 1× one count per period, on A's edge while B is low — A rising counts up, A
    /// falling counts down (the usual X1 decoding), so the count is `⌊n / 4⌋` and never
    /// drifts when the motion reverses. `swapped`: the decoder's A is the encoder's B.
    #[inline]
    pub fn quad(&self, t: u64, swapped: bool, x4: bool) -> i64 {
        let n = self.n(t);
        match (swapped, x4) {
            (false, true) => n,
            (false, false) => floor_div(n, 4),
            (true, true) => -n,
            // The decoder's A (the encoder's B) changes while its B (the encoder's A) is
            // low between states 2 and 3: entering 3 moving up is its A falling.
            (true, false) => -floor_div(n - 3, 4),
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn counts_come_from_the_formula() {
        let mut p = PulseTrain::new();
        let a = p.push(1.0, 1000.0, 500, 1).unwrap();
        assert_eq!((a.start, a.end()), (1.0, 1.5));
        let b = p.push(0.0, 2000.0, 100, -1).unwrap();
        assert_eq!(b.start, 1.5, "queued after the first");
        assert_eq!(p.net_at(0.999), 0);
        assert_eq!(p.net_at(1.0), 1, "the first rising edge at start");
        assert_eq!(p.net_at(1.25), 251);
        assert_eq!(p.net_at(1.5), 500 - 1);
        assert_eq!(p.net_at(100.0), 400);
        assert_eq!(p.rate_at(1.2), 1000.0);
        assert_eq!(p.rate_at(1.52), -2000.0);
        let pieces = p.pieces_from(0.5);
        assert_eq!(pieces.len(), 3);
        assert_eq!((pieces[0], pieces[1]), ((0.5, 0.0), (0.5, 1000.0)));
        assert!((pieces[2].0 - 0.05).abs() < 1e-12 && pieces[2].1 == -2000.0);
        assert!(p.push(0.0, 0.0, 1, 1).is_err());
        // An hour at 200 kHz costs one multiplication.
        let mut h = PulseTrain::new();
        h.push(0.0, 200_000.0, 720_000_000, 1).unwrap();
        assert_eq!(h.net_at(3600.0), 720_000_000);
        p.forget_before(1.6);
        assert!(p.segments().is_empty());
    }

    /// The encoder's A/B state and what a decoder counts: at power-up (position 0) A is
    /// high and B low; walking the states one by one, up and down at random, an X1 decoder
    /// (A's edge while B is low: rising up, falling down) and an X4 decoder counting edge by
    /// edge agree with `Track::quad` at every state, with A and B either way round.
    #[test]
    fn the_encoder_state_is_a_function_of_position_and_decoders_agree() {
        assert_eq!(Track::levels(0), (true, false), "power-up phase");
        let track = |n: i64| Track { t0_ns: 0, dur: 0.0, x0: n as f64, v: 0.0, a: 0.0 };
        let mut rng = crate::core::test_rng::Rng(0xA5B_0001);
        for swapped in [false, true] {
            let (mut n, mut x1, mut x4) = (0i64, 0i64, 0i64);
            let (base1, base4) = (track(0).quad(0, swapped, false), track(0).quad(0, swapped, true));
            for _ in 0..5000 {
                let (oa, ob) = Track::levels(n);
                n += if rng.below(2) == 0 { 1 } else { -1 };
                let (na, nb) = Track::levels(n);
                // What the decoder's A and B are.
                let ((da0, db0), (da1, db1)) = if swapped { ((ob, oa), (nb, na)) } else { ((oa, ob), (na, nb)) };
                if da0 != da1 {
                    x4 += if da1 != db1 { 1 } else { -1 };
                    if !db1 {
                        x1 += if da1 { 1 } else { -1 };
                    }
                } else if db0 != db1 {
                    x4 += if da1 == db1 { 1 } else { -1 };
                }
                let t = track(n);
                assert_eq!(t.quad(0, swapped, true) - base4, x4, "4x at {n} (swapped {swapped})");
                assert_eq!(t.quad(0, swapped, false) - base1, x1, "1x at {n} (swapped {swapped})");
            }
        }
    }
}
