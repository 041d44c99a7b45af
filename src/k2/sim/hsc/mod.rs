//! The high-speed counters HSC0–HSC3 (manual §3.3; k2.md §4): every mode of §3.3.1
//! (inputs from [`crate::k2::sm_map::HSC_MODE_INPUTS`]), counting from simulated input
//! signals ([`super::inputs`]) and from edges written to I0.x; single-PV and multi-PV
//! compare (absolute / relative / cyclic), the "CV = PV" events with the manual's numbers,
//! the status byte and the current-segment byte.
//!
//! Counting over an interval is arithmetic: the edges each input wave makes between two
//! instants. A "CV = PV" crossing inside the interval is timed exactly by inverting the
//! wave (one division for a single input, a binary search for 4x quadrature). Two-pulse
//! mode (6/7) with both inputs driven is treated as moving monotonically at the net rate
//! within one interval — crossings are timed approximately there (stated assumption).
//! The edge streams a counter counts (its "drive") are kept between intervals while the
//! sources, its settings and the input levels they were worked out from are unchanged, so
//! an interval without a crossing costs a few multiplications.
//!
//! Behaviour where the manual is silent (stated assumptions):
//! - SMD38 … shows the live count. A value the user writes there is the new current value
//!   (§3.3.2, "write new current value into HSC": SM37.6 …): it is kept there (not
//!   overwritten by the count) until the next `HSC`, which loads it when SM37.6 is set and
//!   drops it otherwise (SMD38 then shows the count again). The count itself goes on
//!   meanwhile ([`HscChannel::cv`]); `hsc N status` reports it, and the value waiting.
//!   docs/pulse-hsc-rtc-eeprom.md states the rule.
//! - SM141.5 "reset interrupt variable": 0 → `HSC` restarts the table at PV1 with the
//!   current value as the relative reference; 1 → it continues from the current segment.
//! - External reset (modes 1, 2, 4, 7, 10) acts on the edge into the active level (SM37.0:
//!   0 = active high) and clears CV; start (mode 2) gates counting while inactive.
//! - External direction input (modes 3, 4): level 1 counts up.
//! - A/B mode with two independent square waves (not a `sim quad` pair) counts nothing: a
//!   real decoder would count noise.
//! - A/B rate (SM37.2, §3.3.2: "0 = 1x; 1 = 4x"; the manual says no more): 4x counts every
//!   change of A or B; 1x counts one edge per A/B period, A's edge while B is low — A rising
//!   (A leads B) counts up, A falling (B leads A) counts down (the usual X1 decoding). So 1x is
//!   always a quarter of 4x rounded down, and a reversal inside a period neither adds nor
//!   loses a count. A wired encoder's phase at power-up and its edges: `inputs::Track`.
//! - CV is a DINT in SMD38 (wraps); the simulator keeps a 64-bit value internally.
//! - In relative cyclic mode a step that would raise more events than the log keeps skips
//!   whole cycles arithmetically (they are counted as dropped), so an hour costs no more
//!   than a second.
//!
//! The counter is one [`HscChannel`] in four files: this one holds its state and snapshot;
//! `regs` its register map (the control, multi-PV and status bytes of §3.3.2, the PV
//! table of §3.3.3, `HDEF`/`HSC` and what the counter publishes to its SM registers);
//! `modes` what each mode of §3.3.1 counts (the edge streams of its inputs, written
//! edges); `events` counting over an interval of virtual time and the "CV = PV", direction
//! and reset events it raises.

mod events;
mod modes;
mod regs;

pub use regs::{ctl, mpv, no_mode, no_table_note, read_table, st, table_fault_note, PvTable, MAX_PVS};

use crate::k2::catalog::HscSpec;
use crate::k2::sm_map::{self, HscModeInputs, HscRegs};
use events::Quiet;
use modes::DriveCache;
use serde::{Deserialize, Serialize};
use std::time::Duration;

/// Compare state in multi-PV mode.
#[derive(Clone, Copy, Debug, Default, Serialize, Deserialize)]
struct Compare {
    seg: usize,
    target: i64,
    done: bool,
}

/// One high-speed counter.
#[derive(Clone, Debug)]
pub struct HscChannel {
    pub regs: HscRegs,
    pub spec: HscSpec,
    pub mode: Option<&'static HscModeInputs>,
    pub running: bool,
    cv: i64,
    dir_up: bool,
    rate4x: bool,
    reset_low: bool,
    start_low: bool,
    pv: i64,
    multi: bool,
    table: Option<PvTable>,
    fault: bool,
    cmp: Compare,
    last_up: bool,
    /// The user wrote SMD38 …: keep it until the next `HSC`.
    pub user_cv: bool,
    /// The drive of the last interval and what it was computed from.
    cache: Option<DriveCache>,
    /// The count as one formula while only time passes ([`Quiet`]).
    quiet: Option<Quiet>,
    /// Changes whenever a setting the drive depends on may have changed (HDEF, HSC, a
    /// snapshot): the quiet formula's cheap validity test, with the sources' generation.
    settings: u64,
    /// The direction the status bit last showed while running, and a change of it not yet
    /// raised as an event (the simulator raises it at its next step).
    shown_up: Option<bool>,
    pub(crate) dir_event: Option<bool>,
    /// When the counted signals turned the direction (the first count the other way), for
    /// the direction event; `None`: at the step's start (a written input, a setting).
    pub(crate) dir_at: Option<Duration>,
    /// Tests turn the quiet path off to compare it with the general one.
    #[cfg(test)]
    pub(crate) general_only: bool,
}

impl HscChannel {
    pub fn new(regs: HscRegs, spec: HscSpec) -> HscChannel {
        HscChannel {
            regs,
            spec,
            mode: None,
            running: false,
            cv: 0,
            dir_up: false,
            rate4x: false,
            reset_low: false,
            start_low: false,
            pv: 0,
            multi: false,
            table: None,
            fault: false,
            cmp: Compare::default(),
            last_up: true,
            user_cv: false,
            cache: None,
            quiet: None,
            settings: 0,
            shown_up: None,
            dir_event: None,
            dir_at: None,
            #[cfg(test)]
            general_only: false,
        }
    }

    pub fn cv(&self) -> i64 {
        self.cv
    }

    pub fn table(&self) -> Option<&PvTable> {
        self.table.as_ref()
    }

    /// The value compared against now (the current PV), if any.
    pub fn current_pv(&self) -> Option<i64> {
        if self.multi {
            self.table.as_ref().map(|_| self.cmp.target)
        } else {
            Some(self.pv)
        }
    }
}

/// A counter's state for snapshots (`crate::snapshot`): everything but the registers, the
/// model's limits and the cache (worked out again on the next step).
#[derive(Clone, Debug, Serialize, Deserialize)]
pub struct HscState {
    /// The `HDEF` mode number.
    mode: Option<u8>,
    running: bool,
    cv: i64,
    dir_up: bool,
    rate4x: bool,
    reset_low: bool,
    start_low: bool,
    pv: i64,
    multi: bool,
    table: Option<PvTable>,
    fault: bool,
    cmp: Compare,
    last_up: bool,
    user_cv: bool,
    /// The direction the status bit last showed, a change not yet raised as an event and
    /// when it happened (a file older than them: none).
    #[serde(default)]
    shown_up: Option<bool>,
    #[serde(default)]
    dir_event: Option<bool>,
    #[serde(default)]
    dir_at_ns: Option<u64>,
}

impl HscChannel {
    /// Every field is named (no `..`): a field added to the counter does not compile until
    /// it is saved here or named as not the machine's state.
    pub fn save(&self) -> HscState {
        let HscChannel {
            // The registers and limits: from the model.
            regs: _,
            spec: _,
            mode,
            running,
            cv,
            dir_up,
            rate4x,
            reset_low,
            start_low,
            pv,
            multi,
            table,
            fault,
            cmp,
            last_up,
            user_cv,
            // Worked out again on the next step.
            cache: _,
            quiet: _,
            settings: _,
            shown_up,
            dir_event,
            dir_at,
            #[cfg(test)]
                general_only: _,
        } = self;
        HscState {
            mode: mode.map(|m| m.mode),
            running: *running,
            cv: *cv,
            dir_up: *dir_up,
            rate4x: *rate4x,
            reset_low: *reset_low,
            start_low: *start_low,
            pv: *pv,
            multi: *multi,
            table: table.clone(),
            fault: *fault,
            cmp: *cmp,
            last_up: *last_up,
            user_cv: *user_cv,
            shown_up: *shown_up,
            dir_event: *dir_event,
            dir_at_ns: dir_at.map(|t| u64::try_from(t.as_nanos()).unwrap_or(u64::MAX)),
        }
    }

    /// Restores a saved state; refuses a mode this channel does not have.
    pub fn load(&mut self, s: HscState) -> std::result::Result<(), String> {
        self.mode = match s.mode {
            Some(m) => Some(
                sm_map::hsc_mode(self.regs.channel, m)
                    .ok_or_else(|| crate::msg!("k2-hsc-snapshot-mode", n = self.regs.channel, mode = m).text)?,
            ),
            None => None,
        };
        self.running = s.running;
        self.cv = s.cv;
        self.dir_up = s.dir_up;
        self.rate4x = s.rate4x;
        self.reset_low = s.reset_low;
        self.start_low = s.start_low;
        self.pv = s.pv;
        self.multi = s.multi;
        self.table = s.table;
        self.fault = s.fault;
        self.cmp = s.cmp;
        self.last_up = s.last_up;
        self.user_cv = s.user_cv;
        self.cache = None;
        self.quiet = None;
        self.settings += 1;
        (self.shown_up, self.dir_event, self.dir_at) =
            (s.shown_up, s.dir_event, s.dir_at_ns.map(std::time::Duration::from_nanos));
        Ok(())
    }
}
