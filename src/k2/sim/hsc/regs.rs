//! The high-speed counter's register map (manual §3.3.2, §3.3.3, §3.3.5; k2.md §4): the
//! bits of its control byte, multi-PV control byte and status byte, the PV table in V, the
//! `HDEF` and `HSC` instructions that read them, and what the counter publishes back (SMD38
//! …, the status bits it owns, the current segment). What a mode counts and when events fall
//! are in [`super::modes`] and [`super::events`].

use super::modes::level;
use super::HscChannel;
use crate::core::{Error, ErrorKind, Result};
use crate::k2::memory::Memory;
use crate::k2::sm_map::{self, HscKind, HscRegs};
use crate::msg;
use serde::{Deserialize, Serialize};

/// Control byte bits (§3.3.2).
pub mod ctl {
    pub const RESET_LOW: u8 = 1 << 0;
    pub const START_LOW: u8 = 1 << 1;
    pub const RATE_4X: u8 = 1 << 2;
    pub const DIR_UP: u8 = 1 << 3;
    pub const WRITE_DIR: u8 = 1 << 4;
    pub const WRITE_PV: u8 = 1 << 5;
    pub const WRITE_CV: u8 = 1 << 6;
    pub const ENABLE: u8 = 1 << 7;
}

/// Multi-PV control byte bits (§3.3.2).
pub mod mpv {
    pub const MULTI: u8 = 1 << 0;
    pub const RELATIVE: u8 = 1 << 1;
    pub const CYCLIC: u8 = 1 << 2;
    pub const LOAD: u8 = 1 << 4;
    pub const KEEP_SEGMENT: u8 = 1 << 5;
}

/// Status byte bits (§3.3.2).
pub mod st {
    pub const TABLE_FAULT: u8 = 3;
    pub const DIR_UP: u8 = 5;
    pub const EQUAL: u8 = 6;
    pub const GREATER: u8 = 7;
}

/// The status byte's bits a counter owns; the others keep what was written to them.
pub(super) const STATUS_BITS: u8 = 1 << st::TABLE_FAULT | 1 << st::DIR_UP | 1 << st::EQUAL | 1 << st::GREATER;

/// Most PVs in a table (§3.3.3).
pub const MAX_PVS: u8 = 32;

/// A loaded PV table.
#[derive(Clone, Debug, PartialEq, Eq, Serialize, Deserialize)]
pub struct PvTable {
    pub pvs: Vec<i64>,
    pub relative: bool,
    pub cyclic: bool,
}

/// Reads a PV table at V offset `start` (§3.3.3): count byte, then DINTs. Relative PVs with
/// |PV| ≤ 1, or absolute PVs within 1 of the previous one, end the table there.
pub fn read_table(v: &[u8], start: u32, relative: bool, cyclic: bool) -> std::result::Result<PvTable, String> {
    if start.is_multiple_of(2) {
        return Err(msg!("k2-hsc-table-even", start = start).into());
    }
    let s = start as usize;
    if s >= v.len() {
        return Err(msg!("k2-hsc-table-past-v", start = start).into());
    }
    let n = v[s];
    if n == 0 || n > MAX_PVS {
        return Err(msg!("k2-hsc-table-count", start = start, n = n, max = MAX_PVS).into());
    }
    if s + 1 + 4 * n as usize > v.len() {
        return Err(msg!("k2-hsc-table-runs-past", start = start).into());
    }
    let mut pvs: Vec<i64> = Vec::new();
    for k in 0..n as usize {
        let o = s + 1 + 4 * k;
        let pv = i32::from_be_bytes([v[o], v[o + 1], v[o + 2], v[o + 3]]) as i64;
        let ends = if relative { pv.abs() <= 1 } else { pvs.last().is_some_and(|p| (pv - p).abs() <= 1) };
        if ends {
            break;
        }
        pvs.push(pv);
    }
    if pvs.is_empty() {
        return Err(msg!("k2-hsc-table-empty", start = start).into());
    }
    Ok(PvTable { pvs, relative, cyclic: cyclic && relative })
}

/// The note HSC adds when the multi-PV table it read breaks a rule (`why`, from
/// [`read_table`]): status bit 3, «Неисправность в нескольких табличных значениях PV»
/// (§3.3.2). The counter runs all the same. In process and through the helper (`k2::driver`,
/// reading the registers and the table back after the helper saw the bit) alike.
pub fn table_fault_note(r: &HscRegs, why: &str) -> String {
    msg!("k2-hsc-table-fault", status = r.status, reason = why).text
}

/// The note HSC adds in multi-PV mode with no table to use: SM141.4 clear («HSC будет
/// игнорировать данные в таблице PV», §3.3.3) and none loaded before. In process and through
/// the helper alike.
pub fn no_table_note(r: &HscRegs) -> String {
    msg!("k2-hsc-table-fault-none", status = r.status, mpv = r.mpv_control, table = r.table).text
}

/// HDEF with a mode counter `ch` does not have (§3.3.1). In process and through the helper
/// (`k2::driver`) alike.
pub fn no_mode(ch: u8, mode: u8) -> Error {
    let modes: Vec<String> = sm_map::hsc_modes_of(ch).iter().map(|m| m.to_string()).collect();
    Error::new(ErrorKind::Value, msg!("k2-hsc-no-mode", n = ch, mode = mode)).hint(msg!(
        "k2-hsc-no-mode-hint",
        n = ch,
        list = modes.join(", ")
    ))
}

impl HscChannel {
    /// `HDEF n, mode`.
    pub fn hdef(&mut self, mode: u8) -> Result<String> {
        let ch = self.regs.channel;
        let Some(m) = sm_map::hsc_mode(ch, mode) else {
            return Err(no_mode(ch, mode));
        };
        self.mode = Some(m);
        self.running = false;
        self.settings += 1;
        let text = sm_map::HSC_MODES
            .iter()
            .find(|t| t.0 == ch && t.1 == mode)
            .map(|t| t.2(crate::core::msg::language()).text)
            .unwrap_or_default();
        Ok(format!("HSC{ch} mode {mode}: {text}"))
    }

    /// `HSC n` (§3.3.5): applies the control byte and (multi-)PV settings, starts or stops.
    pub fn hsc(&mut self, mem: &mut Memory) -> Result<String> {
        let r = self.regs;
        let ch = r.channel;
        let Some(m) = self.mode else {
            return Err(Error::state(msg!("k2-hsc-no-mode-yet", n = ch)).hint(msg!(
                "k2-hsc-no-mode-yet-hint",
                n = ch,
                list = sm_map::hsc_modes_of(ch).iter().map(|m| m.to_string()).collect::<Vec<_>>().join(", ")
            )));
        };
        let c = mem.sm_byte(r.control);
        self.user_cv = false;
        self.settings += 1;
        if c & ctl::ENABLE == 0 {
            self.running = false;
            return Ok(msg!("k2-hsc-stopped", n = ch, control = r.control, cv = self.cv).into());
        }
        self.reset_low = c & ctl::RESET_LOW != 0;
        self.start_low = c & ctl::START_LOW != 0;
        self.rate4x = c & ctl::RATE_4X != 0;
        if c & ctl::WRITE_DIR != 0 && m.kind == HscKind::InternalDir {
            self.dir_up = c & ctl::DIR_UP != 0;
        }
        if c & ctl::WRITE_CV != 0 {
            self.cv = mem.sm_dword(r.cv) as i32 as i64;
        }
        let b = mem.sm_byte(r.mpv_control);
        self.multi = b & mpv::MULTI != 0;
        let mut notes = Vec::new();
        if !self.multi {
            if c & ctl::WRITE_PV != 0 {
                self.pv = mem.sm_dword(r.pv) as i32 as i64;
            }
            self.fault = false;
        } else if b & mpv::LOAD != 0 {
            let start = mem.sm_word(r.table) as u32;
            match read_table(&mem.v, start, b & mpv::RELATIVE != 0, b & mpv::CYCLIC != 0) {
                Ok(t) => {
                    self.table = Some(t);
                    self.fault = false;
                }
                Err(e) => {
                    self.table = None;
                    self.fault = true;
                    notes.push(table_fault_note(&r, &e));
                }
            }
        } else if self.table.is_none() {
            self.fault = true;
            notes.push(no_table_note(&r));
        }
        if let Some(t) = &mut self.table {
            // The PV type and cyclic bits apply at every HSC, also to a table kept from before.
            t.relative = b & mpv::RELATIVE != 0;
            t.cyclic = t.relative && b & mpv::CYCLIC != 0;
        }
        if let Some(t) = &self.table {
            if self.multi {
                if b & mpv::KEEP_SEGMENT == 0 || self.cmp.seg >= t.pvs.len() {
                    self.cmp.seg = 0;
                }
                self.cmp.done = false;
                self.cmp.target = if t.relative { self.cv + t.pvs[self.cmp.seg] } else { t.pvs[self.cmp.seg] };
            }
        }
        self.running = true;
        self.publish(mem);
        let cmp = match (&self.table, self.multi) {
            (Some(t), true) => msg!(
                "k2-hsc-counting-table",
                n = t.pvs.len(),
                kind = match (t.relative, t.cyclic) {
                    (true, true) => "relative-cyclic",
                    (true, false) => "relative",
                    (false, true) => "absolute-cyclic",
                    (false, false) => "absolute",
                },
                target = self.cmp.target
            ),
            (None, true) => msg!("k2-hsc-counting-no-table"),
            _ => msg!("k2-hsc-status-single-pv", pv = self.pv),
        };
        let mut msg: String = msg!("k2-hsc-counting", n = ch, mode = m.mode, cv = self.cv, compare = cmp.text).into();

        for n in notes {
            msg.push_str("; ");
            msg.push_str(&n);
        }
        Ok(msg)
    }

    /// Writes CV, status and segment into the SM registers.
    #[inline]
    pub fn publish(&mut self, mem: &mut Memory) {
        let r = self.regs;
        if !self.user_cv {
            mem.set_sm_dword(r.cv, self.cv as i32 as u32);
        }
        let (status, segment) = self.status_bits(mem);
        let up = status & 1 << st::DIR_UP != 0;
        if !self.running {
            self.shown_up = None;
        } else if self.shown_up.replace(up).is_some_and(|was| was != up) {
            self.dir_event = Some(up);
        }
        mem.set_sm_byte(r.status, mem.sm_byte(r.status) & !STATUS_BITS | status);
        mem.set_sm_byte(r.segment, segment);
        if let Some(q) = &mut self.quiet {
            (q.status, q.segment) = (status, segment);
        }
    }

    /// The status byte's bits this counter owns ([`STATUS_BITS`]) and the segment number.
    pub(super) fn status_bits(&self, mem: &Memory) -> (u8, u8) {
        let up = match self.mode {
            Some(m) if m.kind == HscKind::InternalDir => self.dir_up,
            Some(m) if m.kind == HscKind::ExternalDir => m.dir.is_some_and(|p| level(mem, p)),
            _ => self.last_up,
        };
        let (eq, gt) = match self.current_pv() {
            Some(pv) => (self.cv == pv, self.cv > pv),
            None => (false, false),
        };
        let bits = (self.fault as u8) << st::TABLE_FAULT
            | (up as u8) << st::DIR_UP
            | (eq as u8) << st::EQUAL
            | (gt as u8) << st::GREATER;
        (bits, if self.multi { self.cmp.seg as u8 } else { 0 })
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn tables_end_at_small_relative_pvs_and_close_absolute_ones() {
        let mut v = vec![0u8; 64];
        v[9] = 3;
        v[10..14].copy_from_slice(&10i32.to_be_bytes());
        v[14..18].copy_from_slice(&1i32.to_be_bytes());
        v[18..22].copy_from_slice(&1000i32.to_be_bytes());
        let t = read_table(&v, 9, true, true).unwrap();
        assert_eq!(t.pvs, vec![10], "|PV| ≤ 1 ends a relative table");
        let t = read_table(&v, 9, false, true).unwrap();
        assert_eq!(t.pvs, vec![10, 1, 1000], "absolute neighbours differ by more than 1");
        assert!(!t.cyclic, "cyclic applies to relative tables only");
        v[14..18].copy_from_slice(&11i32.to_be_bytes());
        assert_eq!(read_table(&v, 9, false, false).unwrap().pvs, vec![10], "11 is within 1 of 10: the table ends");
    }

    #[test]
    fn table_faults() {
        let v = vec![0u8; 64];
        assert!(read_table(&v, 8, true, false).unwrap_err().contains("even"));
        assert!(read_table(&v, 9, true, false).unwrap_err().contains("0 PVs"));
        let mut v = vec![0u8; 64];
        v[1] = 33;
        assert!(read_table(&v, 1, true, false).unwrap_err().contains("33 PVs"));
    }
}
