//! Inputs edge by edge, for a counter whose inputs a stuck or noisy fault acts on
//! ([`super::fault`]): the counter must see the injected levels (miscounts are why noise is
//! injected), and those are not a formula a counter can evaluate at two instants. So over an
//! interval that meets such a fault, each of the counter's inputs is listed as the level
//! changes it makes — its signal's edges (a square wave's, a pulse train's, an encoder's
//! state changes) overridden inside the fault's window by the fault's levels (noise is one
//! seeded pseudo-random level per slot of virtual time) — and the counter takes them in
//! time order as it takes written inputs. The list depends only on the interval's ends,
//! and an interval cut in two gives the same changes, so what is counted does not depend on
//! who reads when. The cost is one step per edge, for intervals that meet a fault window.

use super::fault::Faults;
use super::inputs::{Inputs, Pin, PinEdges, Track};

/// Most level changes one input is listed with in one interval (beyond that, the rest of
/// the interval's edges are dropped: a real input filter would not pass them either).
pub const MAX_EDGES: usize = 1 << 20;

/// An input's own level at `t` ns (without faults): its signal's, or `fallback` (the
/// level it was written to) when nothing drives it.
pub fn own_level(inputs: &Inputs, p: Pin, t: u64, fallback: bool) -> bool {
    if let Some(w) = inputs.wave(p) {
        return w.level_ns(t);
    }
    match inputs.pin_edges(p) {
        Some(PinEdges::Train(tr)) => tr.level_ns(t),
        Some(PinEdges::Track { track, of_b }) => {
            let (a, b) = Track::levels(track.n(t));
            if of_b {
                b
            } else {
                a
            }
        }
        None => fallback,
    }
}

/// The instants in `(a, b]` ns where an input's own level may change.
fn own_changes(inputs: &Inputs, p: Pin, a: u64, b: u64, out: &mut Vec<u64>) {
    if let Some(w) = inputs.wave(p) {
        for e in [w, w.shifted(w.half_ns())] {
            for k in e.rises_ns(a) + 1..=e.rises_ns(b) {
                if out.len() >= MAX_EDGES {
                    return;
                }
                out.push(crate::k2::sim::inputs::ns(e.rise_time(k)));
            }
        }
        return;
    }
    match inputs.pin_edges(p) {
        Some(PinEdges::Train(tr)) => {
            let c = tr.cycle_ns.max(1);
            for k in 0..tr.count {
                let rise = tr.first_ns.saturating_add(k.saturating_mul(c));
                if rise > b || out.len() >= MAX_EDGES {
                    break;
                }
                for t in [rise, rise + c / 2] {
                    if t > a && t <= b {
                        out.push(t);
                    }
                }
            }
        }
        Some(PinEdges::Track { track, .. }) => {
            // Each change of the 4× state is a change of A or B: the first instant the
            // state reaches the next value (the track moves one way).
            let (na, nb) = (track.n(a), track.n(b));
            let up = nb > na;
            let mut lo = a;
            let mut m = na;
            while m != nb && out.len() < MAX_EDGES {
                m += if up { 1 } else { -1 };
                let (mut l, mut h) = (lo, b);
                while l < h {
                    let mid = l + (h - l) / 2;
                    let n = track.n(mid);
                    if (up && n >= m) || (!up && n <= m) {
                        h = mid;
                    } else {
                        l = mid + 1;
                    }
                }
                out.push(h);
                lo = h;
            }
        }
        None => {}
    }
}

/// The level changes of input `p` in `(a, b]` ns as a counter sees it, with faults, and its
/// level at `a`. `fallback`: the level written to the input (when no signal drives it).
pub fn changes(inputs: &Inputs, faults: &Faults, p: Pin, a: u64, b: u64, fallback: bool) -> (bool, Vec<(u64, bool)>) {
    let level = |t: u64| {
        faults
            .list
            .iter()
            .filter(|f| f.kind.pin() == Some(p))
            .find_map(|f| f.level_at(t))
            .unwrap_or_else(|| own_level(inputs, p, t, fallback))
    };
    let mut at = Vec::new();
    own_changes(inputs, p, a, b, &mut at);
    for f in faults.on_pin(p, a, b) {
        at.extend(f.changes(a, b));
    }
    at.sort_unstable();
    at.dedup();
    let start = level(a);
    let mut now = start;
    let mut out = Vec::new();
    for t in at {
        let l = level(t);
        if l != now {
            out.push((t, l));
            now = l;
        }
    }
    (start, out)
}

/// Does a fault window on one of `pins` meet `(a, b]`?
pub fn faulted(faults: &Faults, pins: &[Pin], a: u64, b: u64) -> bool {
    !faults.is_empty() && pins.iter().any(|p| faults.on_pin(*p, a, b).next().is_some())
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::k2::sim::inputs::{Source, Wave};
    use std::time::Duration;

    #[test]
    fn a_stuck_window_hides_the_waves_edges_and_noise_is_the_same_however_cut() {
        let mut inputs = Inputs::default();
        inputs.add(Source::Freq { pin: (0, 1), wave: Wave::new(1000, Duration::ZERO) });
        let mut faults = Faults::default();
        let spec = crate::k2::sim::fault::parse("stuck I0.1=0 at=2ms for=3ms").unwrap();
        faults.add(&spec, Duration::ZERO);
        let (start, ch) = changes(&inputs, &faults, (0, 1), 0, 10_000_000, false);
        assert!(!start);
        // Edges at 1, 1.5 ms; stuck low 2–5 ms; edges again from 5 ms (rising at 5, 6 …).
        let times: Vec<u64> = ch.iter().map(|c| c.0 / 100_000).collect();
        assert_eq!(times, vec![10, 15, 50, 55, 60, 65, 70, 75, 80, 85, 90, 95, 100]);
        let spec = crate::k2::sim::fault::parse("noisy I0.1 freq=7kHz at=1ms for=4ms").unwrap();
        let mut faults = Faults::default();
        faults.add(&spec, Duration::ZERO);
        let whole = changes(&inputs, &faults, (0, 1), 0, 9_000_000, false);
        let mut cut = Vec::new();
        let mut t = 0;
        for step in [333_333, 1_000_001, 17, 2_666_649, 5_000_000] {
            let (_, c) = changes(&inputs, &faults, (0, 1), t, t + step, false);
            cut.extend(c);
            t += step;
        }
        assert_eq!(whole.1, cut, "the same changes however the interval is cut");
        assert!(whole.1.len() > 20, "noise: {}", whole.1.len());
    }
}
