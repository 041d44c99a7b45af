//! Simulated signals on the PLC's inputs, for the high-speed counters to count: a square
//! wave of a given frequency on one input (`sim input I0.1 freq=1kHz`), or an A/B
//! quadrature pair (`sim quad I0.1 I0.0 freq=1kHz`, the first input leading by a quarter
//! period = counting up).
//!
//! A wave is described analytically — its frequency and its time origin — so the number
//! of edges between any two instants is one multiplication and one division, and an hour
//! at 200 kHz costs the same as a millisecond. Waves start low; the k-th rising edge is at
//! `origin + k / f` (k ≥ 1) and each high phase lasts half a period.
//!
//! Wires add two more shapes, each as exact as the signal it carries: a pulse train's
//! pulses ([`Train`]: whole-ns cycles, a given count, as the K2's PTO puts them out) and an
//! encoder's A/B outputs following a planned position ([`Track`]: the A/B state is a
//! function of the position, so the edges between two instants follow from the position at
//! those instants). Both are family-neutral signal shapes, defined in [`crate::core::signal`]
//! beside the wiring model that carries them.

use std::sync::atomic::{AtomicU64, Ordering};
use std::time::Duration;

/// An input bit in the I area: (byte, bit).
pub type Pin = (u32, u8);

pub fn pin_name(p: Pin) -> String {
    format!("I{}.{}", p.0, p.1)
}

/// A square wave, 50 % duty.
#[derive(Clone, Copy, Debug, PartialEq, Eq, serde::Serialize, serde::Deserialize)]
pub struct Wave {
    /// Frequency in Hz (> 0).
    pub hz: u64,
    /// Time origin in ns of virtual time (64 bits: 584 years).
    pub origin_ns: u64,
}

/// Nanoseconds of `t`, saturating at 584 years (virtual time never gets there).
pub(crate) fn ns(t: Duration) -> u64 {
    u64::try_from(t.as_nanos()).unwrap_or(u64::MAX)
}

impl Wave {
    pub fn new(hz: u64, origin: Duration) -> Wave {
        Wave { hz, origin_ns: ns(origin) }
    }

    /// The same wave shifted later by `ns`.
    pub fn shifted(self, ns: u64) -> Wave {
        Wave { hz: self.hz, origin_ns: self.origin_ns.saturating_add(ns) }
    }

    /// Half a period, in ns.
    pub fn half_ns(&self) -> u64 {
        500_000_000 / self.hz
    }

    /// Rising edges in (origin, t].
    pub fn rises(&self, t: Duration) -> u64 {
        self.rises_ns(ns(t))
    }

    /// Rising edges in (origin, t], `t` in ns.
    #[inline]
    pub fn rises_ns(&self, t: u64) -> u64 {
        if t <= self.origin_ns {
            return 0;
        }
        let e = t - self.origin_ns;
        // 64-bit arithmetic while it cannot overflow (a day at 200 kHz), 128-bit beyond.
        match e.checked_mul(self.hz) {
            Some(p) => p / 1_000_000_000,
            None => (e as u128 * self.hz as u128 / 1_000_000_000) as u64,
        }
    }

    /// Falling edges in (origin, t].
    pub fn falls(&self, t: Duration) -> u64 {
        self.shifted(self.half_ns()).rises(t)
    }

    /// The level at `t`.
    pub fn level(&self, t: Duration) -> bool {
        self.level_ns(ns(t))
    }

    /// The level at `t` ns.
    #[inline]
    pub fn level_ns(&self, t: u64) -> bool {
        self.rises_ns(t) > self.shifted(self.half_ns()).rises_ns(t)
    }

    /// The time of the n-th rising edge (n ≥ 1).
    pub fn rise_time(&self, n: u64) -> Duration {
        let after = match n.checked_mul(1_000_000_000) {
            Some(p) => p.div_ceil(self.hz),
            None => u64::try_from((n as u128 * 1_000_000_000).div_ceil(self.hz as u128)).unwrap_or(u64::MAX),
        };
        Duration::from_nanos(self.origin_ns.saturating_add(after))
    }
}

pub use crate::core::signal::{floor_div, Track, Train};

/// The edges one pin's source makes, for a counter counting that pin alone.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum PinEdges {
    Train(Train),
    /// An encoder output: A (`of_b` false) or B.
    Track {
        track: Track,
        of_b: bool,
    },
}

impl PinEdges {
    /// Rising edges up to `t` ns (non-decreasing; differences count).
    #[inline]
    pub fn rises_ns(&self, t: u64) -> i64 {
        match *self {
            PinEdges::Train(tr) => tr.rises_ns(t) as i64,
            PinEdges::Track { track, of_b } => track.rises(t, of_b),
        }
    }
}

/// One signal source.
#[derive(Clone, Copy, Debug, PartialEq, serde::Serialize, serde::Deserialize)]
pub enum Source {
    /// A square wave on one input.
    Freq { pin: Pin, wave: Wave },
    /// A quadrature pair: `lead`'s wave leads `lag`'s by a quarter period.
    Quad { lead: Pin, lag: Pin, wave: Wave },
    /// A pulse train's pulses on one input (a wired pulse output).
    Train { pin: Pin, train: Train },
    /// An encoder's A and B outputs (a wired encoder).
    Encoder { a: Pin, b: Pin, track: Track },
}

/// The one or two pins a source drives (inline: listing them allocates nothing).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct Pins {
    pins: [Pin; 2],
    n: usize,
}

impl std::ops::Deref for Pins {
    type Target = [Pin];
    fn deref(&self) -> &[Pin] {
        &self.pins[..self.n]
    }
}

impl IntoIterator for Pins {
    type Item = Pin;
    type IntoIter = std::iter::Take<std::array::IntoIter<Pin, 2>>;
    fn into_iter(self) -> Self::IntoIter {
        self.pins.into_iter().take(self.n)
    }
}

impl Source {
    pub fn pins(&self) -> Pins {
        match *self {
            Source::Freq { pin, .. } => Pins { pins: [pin, pin], n: 1 },
            Source::Quad { lead, lag, .. } => Pins { pins: [lead, lag], n: 2 },
            Source::Train { pin, .. } => Pins { pins: [pin, pin], n: 1 },
            Source::Encoder { a, b, .. } => Pins { pins: [a, b], n: 2 },
        }
    }

    pub fn hz(&self) -> u64 {
        match *self {
            Source::Freq { wave, .. } | Source::Quad { wave, .. } => wave.hz,
            Source::Train { train, .. } => 1_000_000_000 / train.cycle_ns.max(1),
            Source::Encoder { track, .. } => (track.v.abs() / 4.0).round() as u64,
        }
    }

    /// The levels of a train or encoder source at `t` ns (square waves are in [`Inputs::edges`]).
    pub fn shaped_levels(&self, t: u64) -> Option<[(Pin, bool); 2]> {
        match *self {
            Source::Train { pin, train } => {
                let l = train.level_ns(t);
                Some([(pin, l), (pin, l)])
            }
            Source::Encoder { a, b, track } => {
                let (la, lb) = Track::levels(track.n(t));
                Some([(a, la), (b, lb)])
            }
            _ => None,
        }
    }

    pub fn describe(&self) -> String {
        match *self {
            Source::Freq { pin, wave } => {
                crate::msg!("k2-source-square", pin = pin_name(pin), freq = show_hz(wave.hz)).into()
            }
            Source::Quad { lead, lag, wave } => {
                crate::msg!("k2-source-quadrature", lead = pin_name(lead), lag = pin_name(lag), freq = show_hz(wave.hz))
                    .into()
            }
            Source::Train { pin, train } => {
                crate::msg!("k2-source-train", pin = pin_name(pin), pulses = train.count, cycle = train.cycle_ns).into()
            }
            Source::Encoder { a, b, .. } => crate::msg!("k2-source-encoder", a = pin_name(a), b = pin_name(b)).into(),
        }
    }
}

pub fn show_hz(hz: u64) -> String {
    if hz >= 1000 && hz.is_multiple_of(1000) {
        format!("{} kHz", hz / 1000)
    } else {
        format!("{hz} Hz")
    }
}

/// Every active source.
#[derive(Clone, Debug, Default)]
pub struct Inputs {
    sources: Vec<Source>,
    /// Each driven pin with its rising-edge wave and falling-edge wave (the rising one
    /// shifted by half a period), worked out when the sources change.
    edges: Vec<(Pin, Wave, Wave)>,
    /// Changes whenever the sources change (unique across all `Inputs`; 0 = none ever
    /// added), so a counter can keep what it worked out from them until then.
    generation: u64,
    /// A train or encoder source is among them.
    shaped: bool,
}

/// The next `Inputs::generation`.
static GENERATION: AtomicU64 = AtomicU64::new(1);

impl Inputs {
    /// The active sources, oldest first.
    pub fn sources(&self) -> &[Source] {
        &self.sources
    }

    /// Identifies the current set of sources (see the field).
    pub fn generation(&self) -> u64 {
        self.generation
    }

    /// Every driven pin with its rising-edge and falling-edge waves: its level at `t` ns
    /// is `rise.rises_ns(t) > fall.rises_ns(t)` ([`Wave::level_ns`] without the division).
    pub fn edges(&self) -> &[(Pin, Wave, Wave)] {
        &self.edges
    }

    /// A train or encoder source is among the sources.
    #[inline]
    pub fn has_shaped(&self) -> bool {
        self.shaped
    }

    fn changed(&mut self) {
        self.generation = GENERATION.fetch_add(1, Ordering::Relaxed);
        self.shaped = self.sources.iter().any(|s| matches!(s, Source::Train { .. } | Source::Encoder { .. }));
        self.edges.clear();
        for s in &self.sources {
            for p in s.pins() {
                // `wave` is what drives the pin (the lead's wave on a pair given one pin twice).
                if let Some(w) = self.wave(p) {
                    if !self.edges.iter().any(|e| e.0 == p) {
                        self.edges.push((p, w, w.shifted(w.half_ns())));
                    }
                }
            }
        }
    }

    /// The wave on `pin`, if a source drives it.
    pub fn wave(&self, pin: Pin) -> Option<Wave> {
        self.sources.iter().find_map(|s| match *s {
            Source::Freq { pin: p, wave } if p == pin => Some(wave),
            Source::Quad { lead, wave, .. } if lead == pin => Some(wave),
            Source::Quad { lag, wave, .. } if lag == pin => Some(wave.shifted(wave.half_ns() / 2)),
            _ => None,
        })
    }

    /// The quadrature source on exactly this pair, with `true` when `a` leads (counting up).
    pub fn quad(&self, a: Pin, b: Pin) -> Option<(Wave, bool)> {
        self.sources.iter().find_map(|s| match *s {
            Source::Quad { lead, lag, wave } if lead == a && lag == b => Some((wave, true)),
            Source::Quad { lead, lag, wave } if lead == b && lag == a => Some((wave, false)),
            _ => None,
        })
    }

    /// The edges of a train or encoder source on `pin`.
    pub fn pin_edges(&self, pin: Pin) -> Option<PinEdges> {
        self.sources.iter().find_map(|s| match *s {
            Source::Train { pin: p, train } if p == pin => Some(PinEdges::Train(train)),
            Source::Encoder { a, track, .. } if a == pin => Some(PinEdges::Track { track, of_b: false }),
            Source::Encoder { b, track, .. } if b == pin => Some(PinEdges::Track { track, of_b: true }),
            _ => None,
        })
    }

    /// The encoder source on exactly this pair, with `true` when the decoder's A is the
    /// encoder's B.
    pub fn track(&self, a: Pin, b: Pin) -> Option<(Track, bool)> {
        self.sources.iter().find_map(|s| match *s {
            Source::Encoder { a: ea, b: eb, track } if ea == a && eb == b => Some((track, false)),
            Source::Encoder { a: ea, b: eb, track } if ea == b && eb == a => Some((track, true)),
            _ => None,
        })
    }

    pub fn drives(&self, pin: Pin) -> Option<&Source> {
        self.sources.iter().find(|s| s.pins().contains(&pin))
    }

    /// Adds a source, replacing any that drives one of its pins.
    pub fn add(&mut self, s: Source) {
        let pins = s.pins();
        self.sources.retain(|o| !o.pins().iter().any(|p| pins.contains(p)));
        self.sources.push(s);
        self.changed();
    }

    /// Removes the source driving `pin`; returns it.
    pub fn remove(&mut self, pin: Pin) -> Option<Source> {
        let i = self.sources.iter().position(|s| s.pins().contains(&pin))?;
        let s = self.sources.remove(i);
        self.changed();
        Some(s)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_wave_counts_edges_analytically() {
        let w = Wave::new(1000, Duration::from_millis(10));
        assert_eq!(w.rises(Duration::from_millis(10)), 0);
        assert!(!w.level(Duration::from_micros(10_500)), "starts low");
        assert_eq!(w.rises(Duration::from_millis(11)), 1, "first rising edge one period after the origin");
        assert!(w.level(Duration::from_micros(11_200)));
        assert!(!w.level(Duration::from_micros(11_600)));
        assert_eq!(w.rises(Duration::from_secs(3600) + Duration::from_millis(10)), 3_600_000);
        assert_eq!(w.rise_time(1), Duration::from_millis(11));
        assert_eq!(w.falls(Duration::from_micros(11_499)), 0);
        assert_eq!(w.falls(Duration::from_micros(11_500)), 1);
    }

    #[test]
    fn quadrature_lag_is_a_quarter_period_late() {
        let mut i = Inputs::default();
        i.add(Source::Quad { lead: (0, 1), lag: (0, 0), wave: Wave::new(1000, Duration::ZERO) });
        let a = i.wave((0, 1)).unwrap();
        let b = i.wave((0, 0)).unwrap();
        assert_eq!(b.origin_ns - a.origin_ns, 250_000);
        assert!(i.quad((0, 1), (0, 0)).unwrap().1);
        assert!(!i.quad((0, 0), (0, 1)).unwrap().1);
        i.add(Source::Freq { pin: (0, 0), wave: Wave::new(5, Duration::ZERO) });
        assert!(i.quad((0, 1), (0, 0)).is_none(), "a new source on one pin replaces the pair");
        assert!(i.remove((0, 0)).is_some());
        assert!(i.sources().is_empty());
    }
}
