//! Trapezoidal motion computed analytically: a move is a few segments of constant
//! acceleration, and the position and velocity at any virtual time come from the segment
//! formulas (`p = p0 + v0·t + a·t²/2`), never from ticking. An hour-long jog costs the same
//! as a millisecond one.
//!
//! Units are increments and seconds. The drive's DEC units convert without the encoder
//! resolution: `DEC_speed = rpm·512·R/1875` and `inc/s = rpm·R/60` give
//! `inc/s = DEC / 16.384`; likewise `inc/s² = DEC_acc · 4 000 000 / 65536`
//! (`../shared/spec/kinco-servo.md` §4).

/// Speed DEC → increments per second.
pub fn speed_from_dec(dec: f64) -> f64 {
    dec / 16.384
}

/// Increments per second → speed DEC (rounded).
pub fn speed_to_dec(v: f64) -> i64 {
    (v * 16.384).round() as i64
}

/// Acceleration DEC → increments per second².
pub fn accel_from_dec(dec: f64) -> f64 {
    dec * 4_000_000.0 / 65536.0
}

#[derive(Clone, Copy, Debug, PartialEq, serde::Serialize, serde::Deserialize)]
struct Seg {
    #[serde(with = "crate::core::float_serde")]
    t0: f64,
    #[serde(with = "crate::core::float_serde::duration")]
    dur: f64,
    #[serde(with = "crate::core::float_serde")]
    p0: f64,
    #[serde(with = "crate::core::float_serde")]
    v0: f64,
    #[serde(with = "crate::core::float_serde")]
    a: f64,
}

impl Seg {
    fn at(&self, t: f64) -> (f64, f64) {
        let dt = (t - self.t0).clamp(0.0, self.dur);
        (self.p0 + self.v0 * dt + 0.5 * self.a * dt * dt, self.v0 + self.a * dt)
    }
    fn end(&self) -> (f64, f64, f64) {
        let (p, v) = self.at(self.t0 + self.dur);
        (self.t0 + self.dur, p, v)
    }
}

/// A planned motion: segments, then constant velocity `v_end` from `(t_end, p_end)` on.
#[derive(Clone, Debug, PartialEq, serde::Serialize, serde::Deserialize)]
pub struct Motion {
    segs: Vec<Seg>,
    #[serde(with = "crate::core::float_serde")]
    t_end: f64,
    #[serde(with = "crate::core::float_serde")]
    p_end: f64,
    #[serde(with = "crate::core::float_serde")]
    v_end: f64,
}

impl Motion {
    /// Standing at `p` from time `t`.
    pub fn still(t: f64, p: f64) -> Motion {
        Motion { segs: Vec::new(), t_end: t, p_end: p, v_end: 0.0 }
    }

    /// Position and velocity at time `t`.
    pub fn at(&self, t: f64) -> (f64, f64) {
        if t >= self.t_end {
            return (self.p_end + self.v_end * (t - self.t_end), self.v_end);
        }
        match self.segs.iter().find(|s| t < s.t0 + s.dur) {
            Some(s) => s.at(t),
            None => (self.p_end, self.v_end),
        }
    }

    /// True once the planned segments are over (at rest, or cruising at the target speed).
    pub fn settled(&self, t: f64) -> bool {
        t >= self.t_end
    }

    pub fn end_time(&self) -> f64 {
        self.t_end
    }

    /// Identifies the plan (changes whenever it is replaced by a different one).
    pub fn fingerprint(&self) -> u64 {
        let mut h = (self.segs.len() as u64).wrapping_mul(0x9E37_79B9_7F4A_7C15);
        for x in [self.t_end, self.p_end, self.v_end] {
            h = (h ^ x.to_bits()).wrapping_mul(0x1000_0000_01B3);
        }
        if let Some(s) = self.segs.first() {
            h = (h ^ s.t0.to_bits()).wrapping_mul(0x1000_0000_01B3);
        }
        h
    }

    fn push(&mut self, dur: f64, a: f64) {
        if dur <= 0.0 {
            return;
        }
        let s = Seg { t0: self.t_end, dur, p0: self.p_end, v0: self.v_end, a };
        (self.t_end, self.p_end, self.v_end) = s.end();
        self.segs.push(s);
    }

    /// From `(t, p, v)`, ramp to velocity `target` (accelerating with `acc` when speeding
    /// up, `dec` when slowing down, through zero when the sign changes) and keep it.
    pub fn velocity(t: f64, p: f64, v: f64, target: f64, acc: f64, dec: f64) -> Motion {
        let mut m = Motion { segs: Vec::new(), t_end: t, p_end: p, v_end: v };
        let (acc, dec) = (acc.max(1e-9), dec.max(1e-9));
        if v != 0.0 && target.signum() != v.signum() {
            m.push(v.abs() / dec, -v.signum() * dec);
            m.v_end = 0.0;
        }
        let dv = target - m.v_end;
        if dv != 0.0 {
            let speeding_up = target.abs() > m.v_end.abs();
            let a = if speeding_up { acc } else { dec };
            m.push(dv.abs() / a, dv.signum() * a);
        }
        m.v_end = target;
        m
    }

    /// From `(t, p)`, constant-velocity pieces `(duration, velocity)` back to back (a pulse
    /// train followed through a gear), then rest.
    pub fn cruise(t: f64, p: f64, pieces: &[(f64, f64)]) -> Motion {
        let mut m = Motion::still(t, p);
        for &(dur, v) in pieces {
            if dur > 0.0 {
                m.v_end = v;
                m.push(dur, 0.0);
            }
        }
        m.v_end = 0.0;
        m
    }

    /// The pieces of the plan from `t` on: `(t0, dur, p0, v0, a)`, the last one open-ended
    /// (`dur` infinite) at the final velocity.
    pub fn pieces_from(&self, t: f64) -> Vec<(f64, f64, f64, f64, f64)> {
        let mut out = Vec::new();
        for s in &self.segs {
            let end = s.t0 + s.dur;
            if end <= t {
                continue;
            }
            let t0 = s.t0.max(t);
            let (p0, v0) = s.at(t0);
            out.push((t0, end - t0, p0, v0, s.a));
        }
        let t0 = self.t_end.max(t);
        let (p0, v0) = self.at(t0);
        out.push((t0, f64::INFINITY, p0, v0, 0.0));
        out
    }

    /// The first time at or after `t` the position reaches `x` (`None` if it never does).
    pub fn first_reach(&self, x: f64, t: f64) -> Option<f64> {
        for (t0, dur, p0, v0, a) in self.pieces_from(t) {
            // p0 + v0·τ + a·τ²/2 = x, smallest τ in [0, dur].
            let c = p0 - x;
            if c == 0.0 {
                return Some(t0);
            }
            let roots: Vec<f64> = if a == 0.0 {
                if v0 == 0.0 {
                    vec![]
                } else {
                    vec![-c / v0]
                }
            } else {
                let disc = v0 * v0 - 2.0 * a * c;
                if disc < 0.0 {
                    vec![]
                } else {
                    let r = disc.sqrt();
                    vec![(-v0 - r) / a, (-v0 + r) / a]
                }
            };
            if let Some(tau) = roots.into_iter().filter(|&r| r >= 0.0 && r <= dur).reduce(f64::min) {
                return Some(t0 + tau);
            }
        }
        None
    }

    /// The first time at or after `t` the speed `|v|` reaches `limit` (> 0).
    pub fn first_speed(&self, limit: f64, t: f64) -> Option<f64> {
        for (t0, dur, _, v0, a) in self.pieces_from(t) {
            if v0.abs() >= limit {
                return Some(t0);
            }
            if a != 0.0 {
                let tau = (limit * a.signum() - v0) / a;
                if tau >= 0.0 && tau <= dur {
                    return Some(t0 + tau);
                }
            }
        }
        None
    }

    /// From `(t, p, v)`, decelerate with `dec` to rest.
    pub fn stop(t: f64, p: f64, v: f64, dec: f64) -> Motion {
        Motion::velocity(t, p, v, 0.0, dec, dec)
    }

    /// From `(t, p, v)`, a trapezoidal (or triangular) move to `target` with top speed
    /// `vmax`, acceleration `acc` and deceleration `dec`, ending at rest exactly on target.
    /// If the current velocity points away from the target or cannot stop in time, the
    /// drive first decelerates to rest and moves back.
    pub fn position(t: f64, p: f64, v: f64, target: f64, vmax: f64, acc: f64, dec: f64) -> Motion {
        let (vmax, acc, dec) = (vmax.abs().max(1e-9), acc.max(1e-9), dec.max(1e-9));
        let mut m = Motion { segs: Vec::new(), t_end: t, p_end: p, v_end: v };
        let d = target - p;
        let stopping = v * v / (2.0 * dec);
        if v != 0.0 && (d.signum() != v.signum() || stopping > d.abs()) {
            m.push(v.abs() / dec, -v.signum() * dec);
            m.v_end = 0.0;
            let rest = Motion::position(m.t_end, m.p_end, 0.0, target, vmax, acc, dec);
            m.segs.extend(rest.segs);
            (m.t_end, m.p_end, m.v_end) = (rest.t_end, target, 0.0);
            return m;
        }
        let s = d.signum();
        let dist = d.abs();
        let u = v.abs();
        if dist == 0.0 {
            return m;
        }
        // Phase 1: reach vmax (accelerate, or decelerate if faster), then cruise, then stop.
        let a1 = if vmax > u { acc } else { dec };
        let d1 = (vmax * vmax - u * u).abs() / (2.0 * a1);
        let d3 = vmax * vmax / (2.0 * dec);
        if d1 + d3 <= dist {
            m.push((vmax - u).abs() / a1, s * (vmax - u).signum() * a1);
            m.push((dist - d1 - d3) / vmax, 0.0);
            m.push(vmax / dec, -s * dec);
        } else {
            // Triangle: the peak speed where accelerating from u and braking meet.
            let peak = ((dist + u * u / (2.0 * acc)) / (1.0 / (2.0 * acc) + 1.0 / (2.0 * dec))).sqrt().max(u);
            m.push((peak - u) / acc, s * acc);
            m.push(peak / dec, -s * dec);
        }
        m.p_end = target;
        m.v_end = 0.0;
        m
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn close(a: f64, b: f64) -> bool {
        (a - b).abs() < 1e-6 * (1.0 + b.abs())
    }

    #[test]
    fn trapezoid_reaches_the_target_at_rest() {
        // 10000 inc at 50000 inc/s (300 rpm at R = 10000) with 1e6 inc/s² (100 rps/s):
        // accelerate 0.05 s over 1250 inc, cruise 7500 inc in 0.15 s, brake 0.05 s.
        let m = Motion::position(0.0, 0.0, 0.0, 10_000.0, 50_000.0, 1e6, 1e6);
        assert!(close(m.end_time(), 0.25), "{}", m.end_time());
        let (p, v) = m.at(0.05);
        assert!(close(p, 1250.0) && close(v, 50_000.0), "{p} {v}");
        let (p, v) = m.at(0.125);
        assert!(close(p, 5000.0) && close(v, 50_000.0));
        assert_eq!(m.at(0.25), (10_000.0, 0.0));
        assert_eq!(m.at(100.0), (10_000.0, 0.0));
        assert!(!m.settled(0.2499) && m.settled(0.25));
    }

    #[test]
    fn short_moves_are_triangles_and_negative_moves_mirror() {
        let m = Motion::position(1.0, 0.0, 0.0, -100.0, 50_000.0, 1e6, 1e6);
        // Peak 10000 inc/s at 0.01 s, 0.02 s in total.
        assert!(close(m.end_time(), 1.02));
        let (p, v) = m.at(1.01);
        assert!(close(p, -50.0) && close(v, -10_000.0), "{p} {v}");
        assert_eq!(m.at(2.0).0, -100.0);
    }

    #[test]
    fn moving_away_first_stops_then_returns() {
        let m = Motion::position(0.0, 0.0, 1000.0, -10.0, 1000.0, 1e4, 1e4);
        let (p, _) = m.at(0.1);
        assert!(close(p, 50.0), "stops 50 inc past the start: {p}");
        assert_eq!(m.at(10.0), (-10.0, 0.0));
    }

    #[test]
    fn velocity_ramps_and_cruises() {
        let m = Motion::velocity(0.0, 0.0, 0.0, 1000.0, 1e4, 2e4);
        assert!(close(m.end_time(), 0.1));
        let (p, v) = m.at(1.1);
        assert!(close(v, 1000.0) && close(p, 50.0 + 1000.0), "{p} {v}");
        let back = Motion::velocity(1.1, p, v, -1000.0, 1e4, 2e4);
        // Brake at 2e4 for 0.05 s, then accelerate at 1e4 for 0.1 s.
        assert!(close(back.end_time(), 1.25));
        let s = Motion::stop(0.0, 0.0, -1000.0, 1e4);
        assert!(close(s.at(1.0).0, -50.0) && s.at(1.0).1 == 0.0);
    }

    #[test]
    fn crossings_and_cruises_are_solved_not_stepped() {
        let m = Motion::position(0.0, 0.0, 0.0, 10_000.0, 50_000.0, 1e6, 1e6);
        assert!(close(m.first_reach(1250.0, 0.0).unwrap(), 0.05));
        assert!(close(m.first_reach(5000.0, 0.0).unwrap(), 0.125));
        assert_eq!(m.first_reach(10_001.0, 0.0), None, "never passes the target");
        assert_eq!(m.first_reach(-1.0, 0.0), None);
        assert!(close(m.first_speed(25_000.0, 0.0).unwrap(), 0.025));
        assert_eq!(m.first_speed(60_000.0, 0.0), None);
        let v = Motion::velocity(0.0, 0.0, 0.0, -1000.0, 1e4, 1e4);
        // 0.1 s ramp covers -50; then -1000 inc/s: -1050 at 1.1 s.
        assert!(close(v.first_reach(-1050.0, 0.0).unwrap(), 1.1));
        let c = Motion::cruise(1.0, 10.0, &[(0.5, 100.0), (0.25, -40.0)]);
        assert!(close(c.at(1.4).0, 50.0) && c.at(1.4).1 == 100.0);
        assert!(close(c.at(10.0).0, 50.0) && c.at(10.0).1 == 0.0);
        assert!(close(c.end_time(), 1.75));
    }

    #[test]
    fn units_convert_without_the_resolution() {
        assert!(close(speed_from_dec(819_200.0), 50_000.0));
        assert_eq!(speed_to_dec(50_000.0), 819_200);
        assert!(close(accel_from_dec(16_384.0), 1e6));
    }
}
