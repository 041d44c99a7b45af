//! Position control from a program: PREL, PABS, PHOME, PJOG and PFLO_F (K2 manual §3.4.3;
//! parameters as the KincoBuilder help gives them, `../shared/spec/kinco-public-notes.md`),
//! driving the same simulated pulse channels as PLS.
//!
//! Ramps are trapezoidal in frequency from MINF to MAXF over TIME ms and back, computed
//! when the move starts as ten constant-frequency steps each way (a [`super::super::pto`]
//! train: analytic in virtual time, no per-pulse stepping); a move too short to reach MAXF
//! turns round where half its pulses are spent. PREL and PABS latch MINF, MAXF and TIME at
//! the start (§3.4.3.2); PJOG re-reads MAXF every scan; PHOME re-reads MAXF while it runs at
//! full speed before the home signal. Output frequencies below 125 Hz (30 Hz for PFLO_F)
//! are refused (§3.4.3). While the channel's emergency-stop bit (SM201.7 …) is set no
//! position instruction starts.
//!
//! Every execution writes DONE, ERR and ERRID. ERRID values (the manual lists none; ours):
//! 1 stopped or blocked by the emergency-stop bit, 2 frequency below the minimum, 3 MAXF
//! below MINF or above the channel's maximum, 4 the channel is busy, 5 no such pulse channel.

pub use super::family::Inst;
use super::family::{id, K2Machine};
use crate::core::DataType;
use crate::engine::{self, Fault, Opd};
use crate::k2::sim::pto::pos;

/// Minimum output frequency of position control (§3.4.3), and of PFLO_F.
pub const MIN_HZ: u64 = 125;
pub const MIN_HZ_FOLLOW: u64 = 30;
/// Steps per ramp.
pub const RAMP_STEPS: u64 = 10;
/// A "run until told" train: pulses enough for days at any frequency.
const ENDLESS: u64 = 1 << 40;

fn cycle_ns(hz: u64) -> u64 {
    (1_000_000_000 / hz.max(1)).max(1)
}

/// The trapezoid for `n` pulses: (cycle ns, pulses) segments.
pub fn ramp(minf: u64, maxf: u64, time_ms: u64, n: u64) -> Vec<(u64, u64)> {
    if n == 0 {
        return Vec::new();
    }
    if time_ms == 0 || maxf <= minf {
        return vec![(cycle_ns(maxf), n)];
    }
    let dt_us = time_ms * 1000 / RAMP_STEPS;
    let steps: Vec<(u64, u64)> = (0..RAMP_STEPS)
        .map(|i| {
            let f = minf + (maxf - minf) * (2 * i + 1) / (2 * RAMP_STEPS);
            (f, (f * dt_us / 1_000_000).max(1))
        })
        .collect();
    let mut up = Vec::new();
    let mut cum = 0;
    for &(f, k) in &steps {
        if 2 * (cum + k) > n {
            break;
        }
        cum += k;
        up.push((f, k));
    }
    let top = if up.len() == steps.len() { maxf } else { up.last().map_or(minf, |s| s.0) };
    let mut segs: Vec<(u64, u64)> = up.iter().map(|&(f, k)| (cycle_ns(f), k)).collect();
    let cruise = n - 2 * cum;
    if cruise > 0 {
        segs.push((cycle_ns(top), cruise));
    }
    segs.extend(up.iter().rev().map(|&(f, k)| (cycle_ns(f), k)));
    segs
}

impl K2Machine<'_> {
    fn out(&mut self, args: &[Opd], at: usize, st: Inst) -> Result<(), Fault> {
        engine::write(self, &args[at], DataType::Bool, st.done as u32)?;
        engine::write(self, &args[at + 1], DataType::Bool, (st.err != 0) as u32)?;
        engine::write(self, &args[at + 2], DataType::Byte, st.err as u32)
    }

    /// One execution of a position instruction (`vals` are the operands' values).
    pub(super) fn position(&mut self, sid: u16, inst: u32, args: &[Opd], vals: &[u32]) -> Result<bool, Fault> {
        let i = inst as usize;
        if self.inst.len() <= i {
            self.inst.resize(i + 1, Inst::default());
        }
        let mut st = self.inst[i];
        let exec = vals[1] != 0;
        let rising = exec && !st.exec_prev;
        st.exec_prev = exec;
        let outs = match sid {
            id::PHOME => 9,
            id::PJOG => 4,
            _ => 6,
        };
        let now = self.now;
        let Ok(ch) = self.sim.pto_index(vals[0] as u8) else {
            st.err = 5;
            st.done = false;
            self.inst[i] = st;
            self.out(args, outs, st)?;
            return Ok(false);
        };
        let regs = self.sim.pto[ch].regs;
        let max_hz = self.sim.pto[ch].spec.max_hz as u64;
        let estop = self.sim.mem.sm_bit(regs.pos_control, pos::ESTOP);
        if rising {
            st.done = false;
            st.err = 0;
            if estop {
                st.err = 1;
            } else if st.busy || self.sim.pto[ch].is_pto_busy() {
                st.err = 4;
            } else {
                let cur = self.sim.mem.sm_dword(regs.pos_cv) as i32 as i64;
                let plan: Result<Plan, u8> = match sid {
                    id::PREL | id::PABS => {
                        let (minf, maxf, time) = (vals[2] as u16 as u64, vals[3] as u64, vals[4] as u16 as u64);
                        let target = vals[5] as i32 as i64;
                        let dist = if sid == id::PREL { target } else { target - cur };
                        check(minf, maxf, max_hz, MIN_HZ)
                            .map(|_| (ramp(minf, maxf, time, dist.unsigned_abs()), dist < 0, 0))
                    }
                    id::PHOME => {
                        let (dirc, minf, maxf, time) =
                            (vals[5], vals[6] as u16 as u64, vals[7] as u64, vals[8] as u16 as u64);
                        check(minf, maxf, max_hz, MIN_HZ).map(|_| {
                            let mut segs = ramp(minf, maxf, time, ENDLESS);
                            // Up to speed, then run until the home signal.
                            segs.truncate(RAMP_STEPS as usize);
                            segs.push((cycle_ns(maxf), ENDLESS));
                            (segs, dirc & 1 != 0, maxf)
                        })
                    }
                    id::PJOG => {
                        let (maxf, dirc) = (vals[2] as u64, vals[3]);
                        check(MIN_HZ, maxf, max_hz, MIN_HZ)
                            .map(|_| (vec![(cycle_ns(maxf), ENDLESS)], dirc & 1 != 0, maxf))
                    }
                    _ => {
                        let f = follow_hz(vals);
                        let count = vals[5] as i32 as i64;
                        st.remaining = count.unsigned_abs();
                        check(f.min(MIN_HZ_FOLLOW), f, max_hz, MIN_HZ_FOLLOW)
                            .map(|_| (vec![(cycle_ns(f), count.unsigned_abs())], count < 0, f))
                    }
                };
                match plan {
                    Err(e) => st.err = e,
                    Ok((segs, _, _)) if segs.is_empty() => st.done = true,
                    Ok((segs, reverse, f)) => {
                        let sim = &mut *self.sim;
                        sim.pto[ch].start_train(&mut sim.mem, now, &segs, reverse);
                        st.busy = true;
                        st.freq = f;
                        st.slow = false;
                    }
                }
            }
        } else if st.busy {
            let sim = &mut *self.sim;
            let p = &mut sim.pto[ch];
            match sid {
                id::PJOG => {
                    let maxf = vals[2] as u64;
                    if !exec {
                        p.halt(&mut sim.mem);
                    } else if maxf != st.freq && maxf >= MIN_HZ && maxf <= max_hz {
                        // PJOG follows MAXF all the time (§3.4.3.2).
                        p.start_train(&mut sim.mem, now, &[(cycle_ns(maxf), ENDLESS)], vals[3] & 1 != 0);
                        st.freq = maxf;
                    }
                }
                id::PHOME => {
                    let (home, nhome, mode) = (vals[2] != 0, vals[3] != 0, vals[4]);
                    let (dirc, minf, maxf) = (vals[5] & 1 != 0, vals[6] as u16 as u64, vals[7] as u64);
                    if home {
                        p.halt(&mut sim.mem);
                    } else if mode == 0 && nhome && !st.slow {
                        // Near home: creep at MINF to the home signal.
                        p.start_train(&mut sim.mem, now, &[(cycle_ns(minf.max(MIN_HZ)), ENDLESS)], dirc);
                        st.slow = true;
                        st.freq = minf;
                    } else if !st.slow && maxf != st.freq && maxf >= MIN_HZ && maxf <= max_hz && p.is_pto_busy() {
                        // At full speed PHOME re-reads MAXF (§3.4.3.2).
                        p.start_train(&mut sim.mem, now, &[(cycle_ns(maxf), ENDLESS)], dirc);
                        st.freq = maxf;
                    }
                }
                id::PFLO_F => {
                    let f = follow_hz(vals);
                    if f != st.freq {
                        let done = p.train().map_or(0, |t| t.pulses_at(now));
                        st.remaining = st.remaining.saturating_sub(done);
                        if f < MIN_HZ_FOLLOW {
                            p.halt(&mut sim.mem);
                            st.err = 2;
                        } else if st.remaining > 0 {
                            let reverse = (vals[5] as i32) < 0;
                            p.start_train(&mut sim.mem, now, &[(cycle_ns(f.min(max_hz)), st.remaining)], reverse);
                            st.freq = f;
                        }
                    }
                }
                _ => {}
            }
            if !sim.pto[ch].is_pto_busy() {
                st.busy = false;
                if sim.mem.sm_bit(regs.pos_control, pos::ESTOP) {
                    st.err = 1;
                } else if st.err == 0 {
                    st.done = true;
                }
            }
        }
        self.inst[i] = st;
        self.out(args, outs, st)?;
        Ok(true)
    }
}

/// A move to start: segments, reverse, constant frequency (0 for ramps).
type Plan = (Vec<(u64, u64)>, bool, u64);

/// PFLO_F's output frequency F × NUM / DENOM.
fn follow_hz(vals: &[u32]) -> u64 {
    let (f, num, den) = (vals[2] as u64, vals[3] as u16 as u64, (vals[4] as u16 as u64).max(1));
    f * num / den
}

fn check(minf: u64, maxf: u64, max_hz: u64, floor: u64) -> Result<(), u8> {
    if minf < floor || maxf < floor {
        Err(2)
    } else if maxf < minf || maxf > max_hz {
        Err(3)
    } else {
        Ok(())
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_long_move_is_a_trapezoid_and_a_short_one_a_triangle() {
        // 125 Hz → 10 kHz over 100 ms, 10 000 pulses.
        let segs = ramp(125, 10_000, 100, 10_000);
        let total: u64 = segs.iter().map(|s| s.1).sum();
        assert_eq!(total, 10_000);
        assert_eq!(segs.len(), 21, "10 up, cruise, 10 down");
        assert_eq!(segs[10].0, 100_000, "cruise at 10 kHz");
        assert!(segs[0].0 > segs[9].0, "accelerating");
        let accel: u64 = segs[..10].iter().map(|s| s.1).sum();
        // Mean frequency (125 + 10 000) / 2 over 0.1 s ≈ 506 pulses.
        assert!((495..=515).contains(&accel), "{accel}");
        let short = ramp(125, 10_000, 100, 300);
        assert_eq!(short.iter().map(|s| s.1).sum::<u64>(), 300);
        assert!(short.iter().all(|s| s.0 > 100_000), "never reaches 10 kHz");
        assert_eq!(ramp(200, 200, 50, 7), vec![(5_000_000, 7)]);
        assert!(ramp(125, 1000, 10, 0).is_empty());
    }
}
