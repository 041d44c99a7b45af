//! The simulated FX PLC's CPU state beside its device image ([`super::memory`]): RUN or
//! STOP, when the next scan starts, the scan-time statistics, each timer's and counter's
//! run, the loaded program and a fault that stopped it — and the special devices computed
//! from that state (M8000–M8003, the clock relays M8011–M8014, the scan times D8010–D8012;
//! FX PM, special device list). The image holds this state, so it lives below both the image
//! and the scan cycle that changes it ([`super::plc`]).

use super::model::Model;
use super::program::{costs, Loaded};
use crate::core::Clock;
use crate::engine::CostTable;
use std::time::Duration;

/// RUN or STOP.
#[derive(Clone, Copy, Debug, PartialEq, Eq, serde::Serialize, serde::Deserialize)]
pub enum Mode {
    Run,
    Stop,
}

impl Mode {
    pub fn name(self) -> &'static str {
        match self {
            Mode::Run => "RUN",
            Mode::Stop => "STOP",
        }
    }
}

/// Per-timer state the image does not hold: the coil at the last execution and the time
/// credited so far.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, serde::Serialize, serde::Deserialize)]
pub struct TimerRun {
    pub on: bool,
    pub mark_ns: u64,
    pub frac_ns: u64,
}

/// Scan-time statistics (D8010–D8012).
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, serde::Serialize, serde::Deserialize)]
pub struct Stats {
    /// Scans since the last STOP → RUN.
    pub scans: u64,
    pub last_ns: u64,
    pub min_ns: u64,
    pub max_ns: u64,
}

/// The CPU part of a simulated PLC.
#[derive(Clone, Debug)]
pub struct Cpu {
    pub clock: Clock,
    pub mode: Mode,
    /// Start of the next scan.
    pub next_scan: Duration,
    pub stats: Stats,
    pub costs: CostTable,
    /// Why the CPU stopped on its own (the watchdog), if it did.
    pub fault: Option<String>,
    pub program: Option<Box<Loaded>>,
    pub timers: Vec<TimerRun>,
    /// Each counter's coil at its last execution (rising edges count).
    pub counter_prev: Vec<bool>,
}

impl Cpu {
    /// A CPU in RUN from the clock's present time.
    pub fn new(clock: Clock, model: &Model) -> Cpu {
        let now = clock.now();
        Cpu {
            clock,
            mode: Mode::Run,
            next_scan: now,
            stats: Stats::default(),
            costs: costs(),
            fault: None,
            program: None,
            timers: vec![TimerRun::default(); model.t as usize],
            counter_prev: vec![false; model.c as usize],
        }
    }

    /// A special relay the CPU drives, at image time `at` (`None`: an ordinary relay).
    pub fn system_bit(&self, index: u16, at: Duration) -> Option<bool> {
        let run = self.mode == Mode::Run;
        let clock = |period_ns: u64| (at.as_nanos() as u64 % period_ns) < period_ns / 2;
        Some(match index {
            8000 => run,
            8001 => !run,
            8002 => run && self.stats.scans == 1,
            8003 => run && self.stats.scans > 1,
            8011 => clock(10_000_000),
            8012 => clock(100_000_000),
            8013 => clock(1_000_000_000),
            8014 => clock(60_000_000_000),
            _ => return None,
        })
    }

    /// A special register the CPU drives (D8010–D8012, 0.1 ms units).
    pub fn system_word(&self, index: u16) -> Option<u16> {
        let units = |ns: u64| (ns / 100_000).min(u16::MAX as u64) as u16;
        Some(match index {
            8010 => units(self.stats.last_ns),
            8011 => units(self.stats.min_ns),
            8012 => units(self.stats.max_ns),
            _ => return None,
        })
    }

    pub(super) fn record(&mut self, d_ns: u64, n: u64) {
        let s = &mut self.stats;
        s.min_ns = if s.scans == 0 { d_ns } else { s.min_ns.min(d_ns) };
        s.max_ns = s.max_ns.max(d_ns);
        s.last_ns = d_ns;
        s.scans += n;
    }
}
