//! The simulated FX PLC's state in a snapshot (`sim snapshot save NAME`, [`crate::snapshot`]):
//! its device image, its CPU (RUN/STOP, next scan, scan times, timer and counter state) and
//! its program (the FX list's text, compiled again on restore, with the engine's state), so
//! the same script from the same snapshot gives the same results.

use super::cpu::{Mode, Stats, TimerRun};
use super::memory::Memory;
use super::program::Loaded;
use crate::msg;
use serde::{Deserialize, Serialize};
use std::time::Duration;

/// A program in a snapshot.
#[derive(Clone, Debug, Serialize, Deserialize)]
pub struct ProgramState {
    pub source: String,
    pub text: String,
    pub cpu: crate::engine::Cpu,
}

/// Everything a simulated FX PLC holds.
#[derive(Clone, Debug, Serialize, Deserialize)]
pub struct FxState {
    pub model: String,
    pub bits: Vec<Vec<bool>>,
    pub tn: Vec<u16>,
    pub cn: Vec<u32>,
    pub d: Vec<u16>,
    pub at_ns: u64,
    pub mode: Mode,
    pub next_scan_ns: u64,
    pub stats: Stats,
    pub fault: Option<String>,
    pub timers: Vec<TimerRun>,
    pub counter_prev: Vec<bool>,
    pub program: Option<ProgramState>,
    /// Injected faults (`fault no-reply`, `fault stuck X0=1`) with their windows and log.
    #[serde(default)]
    pub faults: crate::core::sim_faults::Faults,
}

fn ns(d: Duration) -> u64 {
    d.as_nanos().min(u64::MAX as u128) as u64
}

impl Memory {
    /// The state to save (the PLC brought to the present first).
    ///
    /// Every field of [`Memory`] and its [`super::cpu::Cpu`] is named below (no `..`): a
    /// field added to the simulator does not compile until it is saved here or named as not
    /// the machine's state, with why.
    pub fn snapshot_state(&mut self) -> FxState {
        self.advance();
        let Memory {
            model,
            bits,
            tn,
            cn,
            d,
            // The ports' device tables, from the model.
            regions: _,
            ext_regions: _,
            // Device writes through either port: the link's traffic (`devices` shows it), not
            // the PLC's state.
            writes: _,
            cpu,
            at,
            faults,
        } = &*self;
        let super::cpu::Cpu {
            // The session's clock: the snapshot's `clock_us`.
            clock: _,
            mode,
            next_scan,
            stats,
            // The instruction cost table: fixed (`program::costs`), no command changes it.
            costs: _,
            fault,
            program,
            timers,
            counter_prev,
        } = cpu;
        FxState {
            model: model.name.to_string(),
            bits: bits.to_vec(),
            tn: tn.clone(),
            cn: cn.clone(),
            d: d.clone(),
            at_ns: ns(*at),
            mode: *mode,
            next_scan_ns: ns(*next_scan),
            stats: *stats,
            fault: fault.clone(),
            timers: timers.clone(),
            counter_prev: counter_prev.clone(),
            program: program.as_ref().map(|p| ProgramState {
                source: p.source.clone(),
                text: p.text.clone(),
                cpu: p.cpu.clone(),
            }),
            faults: faults.clone(),
        }
    }

    /// Restores a saved state; checks everything (model, sizes, the program compiles) before
    /// changing anything.
    pub fn restore_state(&mut self, st: &FxState) -> Result<(), String> {
        if st.model != self.model.name {
            return Err(msg!("fx-snap-other-model", saved = &st.model, model = self.model.name).text);
        }
        let sizes_ok = st.bits.len() == self.bits.len()
            && st.bits.iter().zip(&self.bits).all(|(a, b)| a.len() == b.len())
            && (st.tn.len(), st.cn.len(), st.d.len()) == (self.tn.len(), self.cn.len(), self.d.len())
            && st.timers.len() == self.cpu.timers.len()
            && st.counter_prev.len() == self.cpu.counter_prev.len();
        if !sizes_ok {
            return Err(msg!("fx-snap-image").text);
        }
        if let Some(f) = st.faults.list.iter().find(|f| match f.kind {
            crate::core::sim_faults::FaultKind::Stuck { input, .. } => input >= self.model.x,
            crate::core::sim_faults::FaultKind::NoReply => false,
        }) {
            return Err(msg!("umpk-snap-fault-input", fault = f.id.to_string()).text);
        }
        let program = match &st.program {
            None => None,
            Some(p) => {
                let mut l = Loaded::load(&p.text, &p.source, self.model).map_err(|e| e.to_string())?;
                l.cpu = p.cpu.clone();
                Some(Box::new(l))
            }
        };
        for (dst, src) in self.bits.iter_mut().zip(&st.bits) {
            dst.clone_from(src);
        }
        self.tn.clone_from(&st.tn);
        self.cn.clone_from(&st.cn);
        self.d.clone_from(&st.d);
        self.at = Duration::from_nanos(st.at_ns);
        let c = &mut self.cpu;
        c.mode = st.mode;
        c.next_scan = Duration::from_nanos(st.next_scan_ns);
        c.stats = st.stats;
        c.fault.clone_from(&st.fault);
        c.timers.clone_from(&st.timers);
        c.counter_prev.clone_from(&st.counter_prev);
        c.program = program;
        self.faults.clone_from(&st.faults);
        Ok(())
    }
}
