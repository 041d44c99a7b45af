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
            return Err(format!("pulse frequency {freq} Hz must be positive"));
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
}
