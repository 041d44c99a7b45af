//! Homing methods by number (CiA 402 numbering, which Kinco drives use: the public notes'
//! examples are 33 and 19): where each method's home point lies, given the simulated
//! switches. The drive then moves there on a trapezoidal profile at the switch-search speed
//! (6099.01) and homing acceleration (609A.00) and assigns the home offset (607C.00) there.
//!
//! Simplification, stated: a real drive searches the switch fast, then creeps back at the
//! zero-search speed (6099.02) to the edge or index pulse; the simulator makes one pass at
//! the switch speed to the same end point, so homing takes slightly less time than on a drive.

use crate::msg;

/// The simulated switches, in position coordinates (increments).
#[derive(Clone, Copy, Debug, PartialEq, serde::Serialize, serde::Deserialize)]
pub struct Switches {
    /// The home switch's edge: the switch is active at and above it.
    #[serde(with = "crate::core::float_serde")]
    pub home: f64,
    /// Negative limit switch: active at and below it (`None`: not wired).
    #[serde(with = "crate::core::float_serde::option")]
    pub neg_limit: Option<f64>,
    /// Positive limit switch: active at and above it.
    #[serde(with = "crate::core::float_serde::option")]
    pub pos_limit: Option<f64>,
}

impl Default for Switches {
    fn default() -> Switches {
        Switches { home: 5_000.0, neg_limit: None, pos_limit: None }
    }
}

impl Switches {
    /// 60FD.00 bits 0 (negative limit), 1 (positive limit), 2 (home) at position `p`.
    pub fn inputs(&self, p: f64) -> u32 {
        u32::from(self.neg_limit.is_some_and(|l| p <= l))
            | u32::from(self.pos_limit.is_some_and(|l| p >= l)) << 1
            | u32::from(p >= self.home) << 2
    }

    /// Moves every switch by `d` (the position coordinates shift when homing assigns the offset).
    pub fn shift(&mut self, d: f64) {
        self.home += d;
        self.neg_limit = self.neg_limit.map(|l| l + d);
        self.pos_limit = self.pos_limit.map(|l| l + d);
    }
}

/// Which limit switch a method homes onto (so reaching it is the goal, not an error).
#[derive(Clone, Copy, Debug, PartialEq, Eq, serde::Serialize, serde::Deserialize)]
pub enum Onto {
    Nothing,
    NegLimit,
    PosLimit,
}

/// Where homing ends, or why it cannot.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Plan {
    pub target: f64,
    pub onto: Onto,
}

/// The methods the simulator implements.
pub const METHODS: &[i8] = &[17, 18, 19, 20, 21, 22, 33, 34, 35, 37];

/// The home point of `method` from position `p`; `resolution` places the index pulses
/// (one per revolution, at multiples of it). `Err` names why homing fails at once.
pub fn plan(method: i8, p: f64, sw: &Switches, resolution: f64) -> Result<Plan, String> {
    let r = resolution.max(1.0);
    Ok(match method {
        // 17/18: the negative/positive limit switch's edge.
        17 => Plan { target: sw.neg_limit.ok_or_else(|| msg!("servo-sim-homing-neg").text)?, onto: Onto::NegLimit },
        18 => Plan { target: sw.pos_limit.ok_or_else(|| msg!("servo-sim-homing-pos").text)?, onto: Onto::PosLimit },
        // 19-22: the home switch's edge (19/20 approach it from below, 21/22 from above;
        // the end point is the same edge).
        19..=22 => Plan { target: sw.home, onto: Onto::Nothing },
        // 33/34: the next index pulse in the negative/positive direction.
        33 => Plan { target: ((p / r).ceil() - 1.0) * r, onto: Onto::Nothing },
        34 => Plan { target: ((p / r).floor() + 1.0) * r, onto: Onto::Nothing },
        // 35 (37 in newer CiA 402 editions): the current position is home.
        35 | 37 => Plan { target: p, onto: Onto::Nothing },
        m => {
            return Err(msg!(
                "servo-sim-homing-method",
                method = m,
                methods = METHODS.iter().map(|m| m.to_string()).collect::<Vec<_>>().join(", ")
            )
            .text)
        }
    })
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn each_method_finds_its_home_point() {
        let sw = Switches { home: 2000.0, neg_limit: Some(-30_000.0), pos_limit: Some(40_000.0) };
        assert_eq!(plan(17, 0.0, &sw, 10_000.0).unwrap(), Plan { target: -30_000.0, onto: Onto::NegLimit });
        assert_eq!(plan(18, 0.0, &sw, 10_000.0).unwrap(), Plan { target: 40_000.0, onto: Onto::PosLimit });
        for m in 19..=22 {
            assert_eq!(plan(m, 100.0, &sw, 10_000.0).unwrap().target, 2000.0);
        }
        assert_eq!(plan(33, 2500.0, &sw, 10_000.0).unwrap().target, 0.0);
        assert_eq!(plan(33, 0.0, &sw, 10_000.0).unwrap().target, -10_000.0, "the next pulse, not this one");
        assert_eq!(plan(34, 2500.0, &sw, 10_000.0).unwrap().target, 10_000.0);
        assert_eq!(plan(35, 1234.0, &sw, 10_000.0).unwrap().target, 1234.0);
        assert!(plan(17, 0.0, &Switches::default(), 10_000.0).unwrap_err().contains("negative limit"));
        assert!(plan(1, 0.0, &sw, 10_000.0).unwrap_err().contains("not simulated"));
        assert_eq!(sw.inputs(-30_000.0), 0b001);
        assert_eq!(sw.inputs(45_000.0), 0b110);
        assert_eq!(sw.inputs(0.0), 0);
    }
}
