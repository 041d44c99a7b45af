//! A simulated drive as a wiring peer ([`crate::wiring::Peer`]): its pulse input, its
//! encoder output (the planned motion), its digital outputs and the switches on its axis,
//! reached through the shared line so the same drive answers its serial link and its wires.

use super::SimLine;
use crate::core::signal::PulseTrain;
use crate::servo::ds402::State;
use crate::wiring::{DriveOut, Peer, Piece, Switch};
use std::sync::{Arc, Mutex};

/// Drive `id` on a simulated line.
pub struct DrivePeer {
    pub line: Arc<Mutex<SimLine>>,
    pub id: u8,
}

impl DrivePeer {
    fn with<R>(&mut self, f: impl FnOnce(&mut super::drive::Drive) -> R) -> Option<R> {
        let mut l = self.line.lock().unwrap_or_else(|p| p.into_inner());
        l.drive(self.id).map(f)
    }
}

impl Peer for DrivePeer {
    fn pulses(&mut self, train: PulseTrain, t: f64) {
        self.with(|d| d.connect_pulses(train, t));
    }

    fn motion(&mut self, t: f64) -> Vec<Piece> {
        self.with(|d| {
            d.advance(t);
            d.plan()
                .pieces_from(t)
                .into_iter()
                .map(|(t0, dur, p0, v0, a)| Piece { t0, dur, p0, v0, a })
                .collect()
        })
        .unwrap_or_default()
    }

    fn plan_id(&mut self, t: f64) -> u64 {
        self.with(|d| {
            d.advance(t);
            d.plan().fingerprint()
        })
        .unwrap_or(0)
    }

    fn next_event(&mut self, t: f64) -> Option<f64> {
        self.with(|d| {
            d.advance(t);
            d.next_event_time()
        })
        .flatten()
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
            None => Err(format!("no drive id {} on the simulated line", self.id)),
            Some(2 | 12) => Err("the drive's pulse input is set to A/B (2508.03 = 2); a PLC pulse output is pulse + direction: set 2508.03 to 1 first".into()),
            Some(_) => Ok(()),
        }
    }
}
