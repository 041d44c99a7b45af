//! DEBUG mode (K80S: breakpoints and step execution): breakpoints by source line or
//! network, stepping by instruction or by network, each step reporting the instruction,
//! the current result and the values of its operands after it ran.
//!
//! A breakpoint halts the CPU before the instruction (mode DEBUG); while halted no scan
//! runs and the program's time is frozen (as in PAUSE: timers, timed interrupts, SM0.5;
//! [`super::Plc::thaw`]); events wait and run after RUN. `sim cpu run` continues the halted scan.
//! Stepping past the end of the main program finishes the scan (the helper program, if
//! any, runs whole) and the next step starts the next scan at its modelled time.

use super::super::K2Sim;
use super::Mode;
use crate::core::{Error, Result};
use crate::msg;
use serde::Serialize;

/// One executed instruction, as the debugger shows it.
#[derive(Clone, Debug, PartialEq, Serialize)]
pub struct Step {
    pub line: u32,
    pub network: u32,
    pub instruction: String,
    /// The current result after it.
    pub cr: bool,
    /// `OPERAND=value` for each operand the simulator can read.
    pub operands: Vec<String>,
}

impl K2Sim {
    /// Sets a breakpoint: `42`, `prog.il:42` (the first instruction on or after line 42)
    /// or `network 3` / `n3` (the network's first instruction). Returns where it is.
    pub fn set_breakpoint(&mut self, spec: &str) -> Result<String> {
        let p = self
            .plc
            .as_deref_mut()
            .filter(|p| p.user.is_some())
            .ok_or_else(|| Error::state(msg!("k2-no-program")).hint(msg!("k2-no-program-hint")))?;
        let l = p.user.as_ref().unwrap();
        // From Lua (`plc:breakpoint("network 2")`) the words arrive quoted, as one argument.
        let spec = spec.trim().trim_matches(['"', '\'']).trim();
        let lower = spec.to_ascii_lowercase();
        let net = lower.strip_prefix("network").or_else(|| lower.strip_prefix('n')).map(str::trim);
        let idx = if let Some(n) = net.and_then(|n| n.parse::<u32>().ok()) {
            l.prog.network.iter().position(|x| *x == n).ok_or_else(|| {
                Error::usage(msg!("k2-no-network", source = l.source.as_str(), n = n)).hint(msg!("k2-no-network-hint"))
            })?
        } else {
            let line: u32 = spec.rsplit(':').next().and_then(|x| x.parse().ok()).ok_or_else(|| {
                Error::usage(msg!("k2-not-breakpoint", spec = spec)).hint("sim break LINE | FILE:LINE | network N")
            })?;
            let last = l.prog.code.len().saturating_sub(1);
            l.prog.pos[..last]
                .iter()
                .position(|pos| pos.line >= line)
                .ok_or_else(|| Error::usage(msg!("k2-no-instruction-after", source = l.source.as_str(), line = line)))?
        };
        p.breaks[idx] = true;
        p.has_breaks = true;
        Ok(msg!(
            "k2-breakpoint-at",
            source = l.source.as_str(),
            line = l.prog.pos[idx].line,
            text = l.prog.text[idx].as_str()
        )
        .into())
    }

    pub fn clear_breakpoints(&mut self) {
        if let Some(p) = self.plc.as_deref_mut() {
            p.breaks.iter_mut().for_each(|b| *b = false);
            p.has_breaks = false;
        }
    }

    /// Lines with breakpoints.
    pub fn breakpoints(&self) -> Vec<u32> {
        let Some(p) = self.plc.as_deref() else { return Vec::new() };
        let Some(l) = &p.user else { return Vec::new() };
        p.breaks.iter().enumerate().filter(|(_, b)| **b).map(|(i, _)| l.prog.pos[i].line).collect()
    }

    /// Executes `n` instructions of the user program (or, `by_network`, up to the start of
    /// the next network), entering DEBUG. Returns what ran.
    pub fn debug_step(&mut self, n: u64, by_network: bool) -> Result<Vec<Step>> {
        self.advance();
        {
            let p = self
                .plc
                .as_deref_mut()
                .filter(|p| p.user.is_some())
                .ok_or_else(|| Error::state(msg!("k2-no-program")).hint(msg!("k2-no-program-hint")))?;
            if p.mode == Mode::Stop && !p.faults.is_empty() && p.user.as_ref().is_some_and(|l| l.cpu.pc.is_none()) {
                // Stepping after a fault starts afresh, as STOP → RUN does.
                p.run_scans = 0;
            }
            if p.mode != Mode::Debug {
                p.freeze(self.last);
                p.mode = Mode::Debug;
            }
        }
        let mut out = Vec::new();
        let start_net = self.next_pc().map(|(_, net)| net);
        let max = if by_network { 100_000 } else { n.min(100_000) };
        for _ in 0..max {
            let Some((pc, net)) = self.next_pc() else { break };
            if by_network && !out.is_empty() && Some(net) != start_net {
                break;
            }
            let t = {
                // A step runs now; the time since the last step stays uncredited.
                let p = self.plc.as_deref_mut().unwrap();
                p.thaw(self.last);
                p.next_scan.max(self.last)
            };
            let fresh = self.plc.as_deref().and_then(|p| p.user.as_ref()).is_some_and(|l| l.cpu.pc.is_none());
            if fresh {
                self.advance_with_interrupts(t);
            }
            let halted = self.scan_part(t, 1, false);
            let step = self.describe(pc);
            out.push(step);
            if let Some(p) = self.plc.as_deref_mut() {
                p.freeze(self.last);
                p.halted = halted;
                if p.mode == Mode::Stop {
                    break; // a fault
                }
            }
            if by_network && halted.is_none() {
                break; // the scan ended
            }
        }
        Ok(out)
    }

    /// The user program's next instruction (index, network).
    fn next_pc(&self) -> Option<(u32, u32)> {
        let l = self.plc.as_deref()?.user.as_ref()?;
        let pc = l.cpu.pc.unwrap_or(l.prog.main().entry);
        Some((pc, *l.prog.network.get(pc as usize)?))
    }

    fn describe(&self, pc: u32) -> Step {
        let l = self.plc.as_deref().and_then(|p| p.user.as_ref()).unwrap();
        let text = l.prog.text[pc as usize].clone();
        let operands = text
            .split_once(' ')
            .map(|(_, ops)| {
                ops.split(',')
                    .filter_map(|o| {
                        let o = o.trim().trim_start_matches('*');
                        let op = self.space().parse_k2(o).ok()?.into_iter().next()?;
                        let v = op.view.decode(self.mem.read(&op));
                        Some(format!("{}={v}", op.canonical()))
                    })
                    .collect()
            })
            .unwrap_or_default();
        Step {
            line: l.prog.pos[pc as usize].line,
            network: l.prog.network[pc as usize],
            instruction: text,
            cr: l.cpu.cr,
            operands,
        }
    }
}
