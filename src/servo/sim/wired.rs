//! A simulated drive as a wiring peer ([`crate::core::wiring::Peer`]): its pulse input, its
//! encoder output (the planned motion), its digital outputs and the switches on its axis,
//! reached through the shared line so the same drive answers its serial link and its wires.

use super::SimLine;
use crate::core::signal::PulseTrain;
use crate::core::wiring::{DriveOut, Peer, Piece, Switch};
use crate::msg;
use crate::servo::ds402::State;
use std::sync::{Arc, Mutex};

/// Drive `id` on a simulated line.
pub struct DrivePeer {
    pub line: Arc<Mutex<SimLine>>,
    pub id: u8,
    /// What the drive's next own event was, worked out for a state key (its plan, the
    /// requests the line has answered, its switches): while the key holds and time is
    /// before that event, bringing the drive forward changes nothing and is skipped.
    quiet: Option<(u64, f64)>,
}

impl DrivePeer {
    pub fn new(line: Arc<Mutex<SimLine>>, id: u8) -> DrivePeer {
        if let Some(d) = line.lock().unwrap_or_else(|p| p.into_inner()).drive(id) {
            d.followers += 1;
        }
        DrivePeer { line, id, quiet: None }
    }

    /// Brings the drive to `t` unless nothing can happen before then; returns the plan's id.
    fn bring(&mut self, t: f64) -> u64 {
        let quiet = self.quiet;
        let id = self.id;
        let mut l = self.line.lock().unwrap_or_else(|p| p.into_inner());
        let received = l.received;
        let Some(d) = l.drive(id) else { return 0 };
        let key = |d: &super::drive::Drive| {
            let s = &d.switches;
            let mut h = d.plan().fingerprint() ^ received.wrapping_mul(0x9E37_79B9_7F4A_7C15);
            // A fault armed at a position is an event to come.
            h = (h ^ d.faults_at.len() as u64).wrapping_mul(0x1000_0000_01B3);
            for x in [s.home, s.neg_limit.unwrap_or(f64::NAN), s.pos_limit.unwrap_or(f64::NAN)] {
                h = (h ^ x.to_bits()).wrapping_mul(0x1000_0000_01B3);
            }
            h
        };
        if let Some((k, next)) = quiet {
            if k == key(d) && t < next {
                return d.plan().fingerprint();
            }
        }
        d.advance(t);
        let next = d.next_event_time().unwrap_or(f64::INFINITY);
        let fp = d.plan().fingerprint();
        self.quiet = Some((key(d), next));
        fp
    }

    fn with<R>(&mut self, f: impl FnOnce(&mut super::drive::Drive) -> R) -> Option<R> {
        let mut l = self.line.lock().unwrap_or_else(|p| p.into_inner());
        l.drive(self.id).map(f)
    }
}

impl Drop for DrivePeer {
    /// One wire host fewer follows the drive; with none, it keeps no history.
    fn drop(&mut self) {
        let mut l = self.line.lock().unwrap_or_else(|p| p.into_inner());
        if let Some(d) = l.drive(self.id) {
            d.followers = d.followers.saturating_sub(1);
            if d.followers == 0 {
                d.history.clear();
            }
        }
    }
}

impl Peer for DrivePeer {
    fn pulses(&mut self, train: PulseTrain, t: f64) {
        self.with(|d| d.connect_pulses(train, t));
    }

    fn motion(&mut self, t: f64) -> Vec<Piece> {
        self.bring(t);
        self.with(|d| {
            let pieces =
                d.pieces_from(t).into_iter().map(|(t0, dur, p0, v0, a)| Piece { t0, dur, p0, v0, a }).collect();
            d.forget_before(t);
            pieces
        })
        .unwrap_or_default()
    }

    fn plan_id(&mut self, t: f64) -> u64 {
        self.bring(t)
    }

    fn next_event(&mut self, t: f64) -> Option<f64> {
        self.bring(t);
        self.quiet.map(|q| q.1).filter(|n| n.is_finite())
    }

    fn output(&mut self, what: DriveOut, t: f64) -> bool {
        self.with(|d| {
            d.advance(t);
            let sw = d.statusword(t);
            match what {
                DriveOut::TargetReached => sw & (1 << 10) != 0,
                DriveOut::Fault => d.state() == State::Fault,
                DriveOut::Enabled => d.state() == State::OperationEnabled,
            }
        })
        .unwrap_or(false)
    }

    fn resolution(&mut self) -> f64 {
        self.with(|d| d.resolution()).unwrap_or(10_000.0)
    }

    fn set_switch(&mut self, s: Switch, on: bool) {
        self.with(|d| match s {
            Switch::Home(x) => d.switches.home = if on { x } else { super::homing::Switches::default().home },
            Switch::PosLimit(x) => d.switches.pos_limit = on.then_some(x),
            Switch::NegLimit(x) => d.switches.neg_limit = on.then_some(x),
        });
    }

    fn check_pulse_input(&mut self) -> Result<(), String> {
        match self.with(|d| d.pulse_mode()) {
            None => Err(msg!("servo-sim-no-drive-id", id = self.id).text),
            Some(2 | 12) => Err(msg!("servo-sim-pulse-ab").text),
            Some(_) => Ok(()),
        }
    }
}
