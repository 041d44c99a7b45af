//! High-speed counter helper (manual §3.3; k2.md §4): `hsc N mode=9 rate=4x
//! pv=[100,200,300] relative cyclic at VB3009` plans the control byte, CV, the single PV or
//! the PV table with its multi-PV control byte, then HDEF and HSC; and the status decoder.
//! Registers from [`crate::k2::sm_map::HSC_REGS`], modes from `HSC_MODE_INPUTS`.

use super::{bad, overlaps_backup, read_ops, Instr, Plan, Written};
use crate::core::{DataType, Device, Error, Result};
use crate::k2::catalog::Model;
use crate::k2::operand::{Area, K2Operand};
use crate::k2::sim::hsc::{ctl, mpv, MAX_PVS};
use crate::k2::sm_map::{self, HscKind, HscRegs, HSC_REGS};
use crate::msg;

/// What the user asked for.
#[derive(Clone, Debug, Default, PartialEq)]
pub struct HscRequest {
    pub counter: u8,
    pub mode: u8,
    /// 4x quadrature (modes 9/10).
    pub rate4x: bool,
    /// Count direction for modes 0–2 (`dir=up|down`); `None` = up.
    pub up: Option<bool>,
    /// Load this current value (bit 6).
    pub cv: Option<i32>,
    /// Preset values: one without `at` = single PV; a table with `at`.
    pub pv: Vec<i32>,
    pub relative: bool,
    pub cyclic: bool,
    /// PV table start (odd V offset).
    pub at: Option<u32>,
    pub reset_low: bool,
    pub start_low: bool,
    /// Allow a table in the E2PROM backup area.
    pub force: bool,
}

/// The counter's registers, or an error naming the model's counters.
pub fn counter(model: &Model, n: u8) -> Result<HscRegs> {
    if model.hsc(n).is_none() {
        let list: Vec<String> = model.hsc.iter().map(|h| format!("HSC{}", h.channel)).collect();
        return Err(Error::unsupported(msg!("k2-hsc-no-counter", model = model.name, n = n)).hint(msg!(
            "k2-hsc-no-counter-hint",
            model = model.name,
            list = list.join(", ")
        )));
    }
    Ok(HSC_REGS[n as usize])
}

/// Plans the writes and HDEF + HSC for a request (§3.3.5 method 1).
pub fn plan(model: &Model, q: &HscRequest, backup: (u32, u32)) -> Result<Plan> {
    let r = counter(model, q.counter)?;
    let n = q.counter;
    let m = sm_map::hsc_mode(n, q.mode).ok_or_else(|| {
        let modes: Vec<String> = sm_map::hsc_modes_of(n).iter().map(|m| m.to_string()).collect();
        bad("mode", msg!("k2-hsc-no-mode", n = n, mode = q.mode)).hint(msg!(
            "k2-hsc-no-mode-hint",
            n = n,
            list = modes.join(", ")
        ))
    })?;
    if q.rate4x && m.kind != HscKind::Quadrature {
        return Err(bad("rate", msg!("k2-hsc-rate-4x", mode = q.mode)));
    }
    if q.up.is_some() && m.kind != HscKind::InternalDir {
        return Err(bad("dir", msg!("k2-hsc-dir", mode = q.mode)));
    }
    if q.reset_low && m.reset.is_none() {
        return Err(bad("reset", msg!("k2-hsc-no-reset", mode = q.mode)));
    }
    if q.start_low && m.start.is_none() {
        return Err(bad("start", msg!("k2-hsc-no-start", mode = q.mode)));
    }
    let mut p = Plan::default();
    let mut c = ctl::ENABLE;
    if q.rate4x {
        c |= ctl::RATE_4X;
    }
    if q.reset_low {
        c |= ctl::RESET_LOW;
    }
    if q.start_low {
        c |= ctl::START_LOW;
    }
    if m.kind == HscKind::InternalDir {
        c |= ctl::WRITE_DIR;
        if q.up.unwrap_or(true) {
            c |= ctl::DIR_UP;
        }
    }
    if let Some(cv) = q.cv {
        c |= ctl::WRITE_CV;
        p.dint(Area::SM, r.cv, cv as i64);
    }
    if q.cyclic && !q.relative {
        return Err(bad("cyclic", msg!("k2-hsc-cyclic-relative")));
    }
    match (q.pv.len(), q.at) {
        (0, None) => {
            p.byte(Area::SM, r.mpv_control, 0);
        }
        (1, None) if !q.relative => {
            c |= ctl::WRITE_PV;
            p.dint(Area::SM, r.pv, q.pv[0] as i64);
            p.byte(Area::SM, r.mpv_control, 0);
        }
        (_, None) => return Err(bad("pv", msg!("k2-hsc-table-needs-at"))),
        (0, Some(_)) => return Err(bad("pv", msg!("k2-hsc-at-needs-pv"))),
        (k, Some(at)) => {
            if at % 2 == 0 {
                return Err(bad("at", msg!("k2-hsc-even", at = at)).hint(msg!("k2-table-odd-hint", at = at as u64 + 1)));
            }
            if k > MAX_PVS as usize {
                return Err(bad("pv", msg!("k2-hsc-too-many-pvs", n = k, max = MAX_PVS)));
            }
            // In u64: an address near the top of u32 must be refused, not wrap past the check.
            let last = at as u64 + 4 * k as u64;
            if last >= model.v_bytes as u64 {
                return Err(bad(
                    "at",
                    msg!("k2-hsc-past-v", at = at, last = last, model = model.name, top = model.v_bytes - 1),
                ));
            }
            let last = last as u32;
            if overlaps_backup(at, last, backup) && !q.force {
                return Err(bad("at", msg!("k2-hsc-backup", at = at, last = last, first = backup.0, end = backup.1))
                    .hint(msg!("k2-table-backup-hint")));
            }
            for (i, pv) in q.pv.iter().enumerate() {
                let ends = if q.relative {
                    (*pv as i64).abs() <= 1
                } else {
                    i > 0 && (*pv as i64 - q.pv[i - 1] as i64).abs() <= 1
                };
                if ends {
                    return Err(bad("pv", msg!("k2-hsc-pv-ends-table", index = i + 1, pv = *pv)));
                }
            }
            p.byte(Area::V, at, k as i64);
            for (i, pv) in q.pv.iter().enumerate() {
                p.dint(Area::V, at + 1 + 4 * i as u32, *pv as i64);
            }
            p.word(Area::SM, r.table, at as i64);
            let mut b = mpv::MULTI | mpv::LOAD;
            if q.relative {
                b |= mpv::RELATIVE;
            }
            if q.cyclic {
                b |= mpv::CYCLIC;
            }
            p.byte(Area::SM, r.mpv_control, b as i64);
            let first = r.event_base as u32;
            p.notes.push(msg!("k2-hsc-events", first = first, last = first + k as u32 - 1).into());
        }
    }
    p.writes.insert(0, (K2Operand::byte(Area::SM, r.control), crate::core::Value::Int(c as i64)));
    p.then.push(Instr::Hdef(n, q.mode));
    p.then.push(Instr::Hsc(n));
    Ok(p)
}

/// Meanings of an HSC status byte (§3.3.2).
pub fn decode_status(s: u8) -> Vec<String> {
    let bit = |b: &str| msg!("k2-hsc-status-bit", bit = b).text;
    let mut w = vec![bit(if s & 0x20 != 0 { "up" } else { "down" })];
    if s & 0x40 != 0 {
        w.push(bit("equal"));
    }
    if s & 0x80 != 0 {
        w.push(bit("greater"));
    }
    if s & 0x08 != 0 {
        w.push(bit("fault"));
    }
    w
}

/// `hsc N status`: the registers as read, and in words. The current value is the
/// counter's own: in a simulator the count itself, even while SMD38 … holds a value the user
/// wrote there (a new current value, §3.3.2: loaded by the next HSC with SM37.6 … set — the
/// words say so); on a PLC the SMD38 … it shows.
pub fn status(dev: &mut dyn Device, model: &Model, n: u8) -> Result<Status> {
    let r = counter(model, n)?;
    let mut cv = K2Operand::dword(Area::SM, r.cv);
    cv.view = DataType::DInt;
    let mut pv = K2Operand::dword(Area::SM, r.pv);
    pv.view = DataType::DInt;
    let ops = [
        K2Operand::byte(Area::SM, r.status),
        K2Operand::byte(Area::SM, r.control),
        cv,
        pv,
        K2Operand::byte(Area::SM, r.mpv_control),
        K2Operand::byte(Area::SM, r.segment),
    ];
    let vals = read_ops(dev, &ops)?;
    let st = vals[0].value.as_i64() as u8;
    let c = vals[1].value.as_i64() as u8;
    let b = vals[4].value.as_i64() as u8;
    let mut words: Vec<String> = decode_status(st);
    words.insert(0, msg!("k2-hsc-status-bit", bit = if c & ctl::ENABLE != 0 { "enabled" } else { "disabled" }).into());
    let smd = vals[2].value.as_i64();
    // The count wraps as a DINT, as SMD38 … shows it.
    let live = crate::k2::simulator(dev)
        .and_then(|s| s.hsc.iter().find(|h| h.regs.channel == n).map(|h| (h.cv() as i32 as i64, h.user_cv)));
    let cv = live.map_or(smd, |(cv, _)| cv);
    words.push(msg!("k2-hsc-status-cv", cv = cv).into());
    if live.is_some_and(|(cv, written)| written && cv != smd) {
        words.push(msg!("k2-hsc-status-written-cv", smd = r.cv, value = smd, n = n, control = r.control).into());
    }
    if b & mpv::MULTI != 0 {
        let kind = match (b & mpv::RELATIVE != 0, b & mpv::CYCLIC != 0) {
            (true, false) => "relative",
            (true, true) => "relative-cyclic",
            (false, true) => "absolute-cyclic",
            (false, false) => "absolute",
        };
        words.push(msg!("k2-hsc-status-multi-pv", kind = kind, segment = vals[5].value.as_i64()).into());
    } else {
        words.push(msg!("k2-hsc-status-single-pv", pv = vals[3].value.as_i64()).into());
    }

    Ok(Status { registers: vals, words, cv })
}

/// What `hsc N status` found.
#[derive(Clone, Debug)]
pub struct Status {
    /// The registers as read (SMB36, SMB37, SMD38, SMD42, SMB141, SMB140 for HSC0).
    pub registers: Vec<Written>,
    /// Enabled, direction, compare, CV, a written SMD38 waiting for HSC, the PV(s).
    pub words: Vec<String>,
    /// The counter's current value (see [`status`]).
    pub cv: i64,
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::k2::catalog::find;

    #[test]
    fn the_worked_example_plans_table_and_control_bytes() {
        let q = HscRequest {
            counter: 0,
            mode: 9,
            rate4x: true,
            pv: vec![100, 200, 300],
            relative: true,
            cyclic: true,
            at: Some(3009),
            ..Default::default()
        };
        let p = plan(find("K205-16DT").unwrap(), &q, (3648, 3902)).unwrap();
        assert_eq!(p.value_of("SMB37"), Some(0x84), "enable + 4x");
        assert_eq!(p.value_of("VB3009"), Some(3));
        assert_eq!(p.value_of("VD3010/DINT"), Some(100));
        assert_eq!(p.value_of("VD3018/DINT"), Some(300));
        assert_eq!(p.value_of("SMW142"), Some(3009));
        assert_eq!(p.value_of("SMB141"), Some(0x17));
        assert_eq!(p.then, vec![Instr::Hdef(0, 9), Instr::Hsc(0)]);
        assert!(p.notes[0].contains("64…66"));
    }

    /// A PV table address near the top of u32 is refused, not wrapped past the V check.
    #[test]
    fn a_table_address_past_v_is_refused_not_wrapped() {
        for at in [4_294_967_295, 4_294_967_291, 4095] {
            let q =
                HscRequest { counter: 0, mode: 9, pv: vec![100, 200], at: Some(at), force: true, ..Default::default() };
            let e = plan(find("K205-16DT").unwrap(), &q, (3648, 3902)).unwrap_err();
            assert!(e.message.contains("runs past the V area") && e.message.contains("VB4095"), "{at}: {e}");
        }
    }

    #[test]
    fn single_pv_and_direction() {
        let q = HscRequest { counter: 1, mode: 0, up: Some(false), cv: Some(-5), pv: vec![-100], ..Default::default() };
        let p = plan(find("K205-16DT").unwrap(), &q, (3648, 3902)).unwrap();
        assert_eq!(p.value_of("SMB47"), Some(0xF0), "enable, write CV, write PV, write dir, down");
        assert_eq!(p.value_of("SMD52"), Some(-100));
        assert_eq!(p.value_of("SMD48"), Some(-5));
        assert_eq!(p.value_of("SMB151"), Some(0));
    }

    #[test]
    fn refusals() {
        let m = find("K205-16DT").unwrap();
        let b = (3648, 3902);
        let base = HscRequest { counter: 0, mode: 0, ..Default::default() };
        assert!(plan(m, &HscRequest { mode: 5, ..base.clone() }, b)
            .unwrap_err()
            .hint
            .clone()
            .unwrap()
            .contains("0, 1, 2, 3, 4, 6, 9"));
        assert!(plan(m, &HscRequest { rate4x: true, ..base.clone() }, b).is_err());
        assert!(plan(m, &HscRequest { pv: vec![1, 2], ..base.clone() }, b).unwrap_err().message.contains("at VB"));
        assert!(plan(m, &HscRequest { pv: vec![10], at: Some(3008), ..base.clone() }, b).is_err());
        let e = plan(m, &HscRequest { pv: vec![10, 1], relative: true, at: Some(1), ..base.clone() }, b).unwrap_err();
        assert!(e.message.contains("PV2 = 1"), "{e}");
        assert!(plan(m, &HscRequest { pv: vec![10], cyclic: true, at: Some(1), ..base.clone() }, b).is_err());
        assert!(plan(m, &HscRequest { pv: vec![10], at: Some(3649), ..base.clone() }, b).is_err());
        assert!(plan(m, &HscRequest { counter: 2, mode: 3, ..base.clone() }, b).is_err());
        assert!(plan(find("K209M-56DT").unwrap(), &HscRequest { counter: 3, ..base.clone() }, b).is_err());
        assert!(plan(m, &HscRequest { mode: 3, up: Some(true), ..base }, b).is_err(), "dir= with external direction");
    }

    /// §3.3.2: SMD38 is the new current value an HSC with SM37.6 set loads. Written while
    /// the counter counts, it waits there; `hsc 0 status` still reports the count (and the
    /// value waiting), the next HSC with SM37.6 loads it, one without drops it.
    #[test]
    fn status_reports_the_count_while_smd38_holds_a_written_value() {
        use crate::core::Clock;
        use crate::output::Style;
        use crate::session::Session;
        use crate::shell::Shell;
        let mut s = Session::new(Clock::stepped());
        s.open("plc", "sim:K205-16DT").unwrap();
        let mut sh = Shell::new(s, Style { json: true, color: false });
        let mut last = |line: &str| {
            let r = sh.exec(line);
            r.last().unwrap().as_ref().unwrap_or_else(|e| panic!("{line}: {}", e.1)).clone()
        };
        let cv = |o: &crate::output::Outcome| o.data["cv"].as_i64().unwrap();
        let words = |o: &crate::output::Outcome| o.message.clone().unwrap_or_default();
        last("hsc 0 mode=0 dir=up; sim input I0.1 freq=1kHz; sim step 1s");
        let o = last("set SMD38=5; sim step 10ms; hsc status 0");
        assert_eq!(cv(&o), 1010, "{}", words(&o));
        assert!(words(&o).contains("CV 1010; SMD38 holds 5, written: a new CV"), "{}", words(&o));
        assert_eq!(o.values[2].operand, "SMD38");
        assert_eq!(o.values[2].value.as_i64(), 5, "the register as read");
        // An HSC without SM37.6 (16#98: enable, write direction, up) keeps counting from the
        // count; SMD38 shows the count again.
        let o = last("hsc 0; sim step 10ms; hsc 0 status");
        assert_eq!((cv(&o), o.values[2].value.as_i64()), (1020, 1020), "{}", words(&o));
        assert!(!words(&o).contains("holds"), "{}", words(&o));
        // With SM37.6 set (16#C8: enable, write CV, up) the next HSC loads it.
        let o = last("set SMD38=7, SMB37=16#C8; hsc 0 status");
        assert_eq!(cv(&o), 1020, "not before the HSC: {}", words(&o));
        let o = last("hsc 0; sim step 10ms; hsc 0 status");
        assert_eq!((cv(&o), o.values[2].value.as_i64()), (17, 17), "{}", words(&o));
    }

    #[test]
    fn status_words() {
        assert_eq!(decode_status(0x60), vec!["counting up", "CV = PV"]);
        assert_eq!(decode_status(0x88), vec!["counting down", "CV > PV", "PV table fault"]);
    }
}
