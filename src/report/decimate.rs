//! Decimation of long curves for a report: a plot `columns` pixels wide shows at most one
//! vertical stroke per column, so a curve keeps, per column, the sample with the smallest and
//! the one with the largest value, in time order. Every peak and dip survives (a 10-minute
//! trace sampled every 10 ms keeps its one-sample spike), the length is at most
//! `2 × columns` points whatever the trace's, and the curve still spans the whole trace —
//! decimated, not truncated. This is the usual min/max ("envelope") decimation of
//! oscilloscopes and of plotting libraries' large-data modes; one pass, linear in the samples.

/// At most two points per column of `columns` across the time span of `points` (in time
/// order); `points` unchanged when they already fit. Samples that are not finite are left out.
pub fn min_max(points: &[(f64, f64)], columns: usize) -> Vec<(f64, f64)> {
    let finite: Vec<(f64, f64)> = points.iter().copied().filter(|(t, v)| t.is_finite() && v.is_finite()).collect();
    let columns = columns.max(1);
    if finite.len() <= 2 * columns {
        return finite;
    }
    let (t0, t1) = (finite[0].0, finite[finite.len() - 1].0);
    let span = t1 - t0;
    let column = |t: f64| -> usize {
        if span <= 0.0 {
            return 0;
        }
        (((t - t0) / span) * columns as f64).floor().clamp(0.0, (columns - 1) as f64) as usize
    };
    let mut out = Vec::with_capacity(2 * columns);
    let mut i = 0;
    while i < finite.len() {
        let c = column(finite[i].0);
        let (mut lo, mut hi) = (i, i);
        let mut j = i + 1;
        while j < finite.len() && column(finite[j].0) == c {
            if finite[j].1 < finite[lo].1 {
                lo = j;
            }
            if finite[j].1 > finite[hi].1 {
                hi = j;
            }
            j += 1;
        }
        let (a, b) = (lo.min(hi), lo.max(hi));
        out.push(finite[a]);
        if b != a {
            out.push(finite[b]);
        }
        i = j;
    }
    out
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn short_curves_pass_unchanged() {
        let p = vec![(0.0, 1.0), (1.0, 2.0), (2.0, 0.0)];
        assert_eq!(min_max(&p, 10), p);
    }

    #[test]
    fn a_long_curve_keeps_its_span_its_extremes_and_two_points_per_column() {
        // 60 000 samples (10 minutes every 10 ms) with one spike and one dip.
        let mut p: Vec<(f64, f64)> = (0..60_000).map(|i| (i as f64 * 0.01, (i % 100) as f64)).collect();
        p[31_234].1 = 1e6;
        p[45_678].1 = -1e6;
        let d = min_max(&p, 800);
        assert!(d.len() <= 1600, "{}", d.len());
        assert!(d.len() >= 800, "every column has a point: {}", d.len());
        assert_eq!(d.first().unwrap().0, 0.0, "starts where the trace starts");
        assert_eq!(d.last().unwrap().0, p.last().unwrap().0, "ends where the trace ends (not truncated)");
        assert!(d.contains(&p[31_234]) && d.contains(&p[45_678]), "the spike and the dip survive");
        assert!(d.windows(2).all(|w| w[0].0 < w[1].0), "time order");
        let hi = d.iter().map(|x| x.1).fold(f64::MIN, f64::max);
        assert_eq!(hi, 1e6);
    }

    #[test]
    fn samples_that_are_not_numbers_are_left_out() {
        let mut p: Vec<(f64, f64)> = (0..100).map(|i| (i as f64, i as f64)).collect();
        p[5].1 = f64::NAN;
        let d = min_max(&p, 10);
        assert!(d.iter().all(|x| x.1.is_finite()));
        assert!(d.len() <= 20);
    }
}
