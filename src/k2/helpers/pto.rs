//! Pulse output helpers (manual §3.4.2; k2.md §5): `pto`, `pwm`, `profile` plans, the
//! plan-only profile timeline (what a trend plot draws), and the PTO status decoder.
//! Registers from [`crate::k2::sm_map::PTO_REGS`]; limits from the model catalogue.

use super::{bad, overlaps_backup, read_ops, Instr, Plan, Written};
use crate::core::{Device, Error, Result};
use crate::k2::catalog::{Model, PtoSpec};
use crate::k2::operand::{Area, K2Operand};
use crate::k2::sim::pto::{ctl, MAX_SEGMENTS};
use crate::k2::sm_map::{PtoRegs, PTO_REGS};
use crate::msg;
use serde::Serialize;

/// How fast: a frequency or a cycle time.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum Rate {
    Hz(f64),
    CycleUs(u64),
}

impl Rate {
    /// The cycle in µs, rounded to whole µs; plus a note when a frequency was rounded.
    fn cycle_us(self) -> (u64, Option<String>) {
        match self {
            Rate::CycleUs(us) => (us, None),
            Rate::Hz(f) => {
                let us = (1e6 / f).round().max(1.0) as u64;
                let actual = 1e6 / us as f64;
                let note = ((actual - f).abs() > 1e-9 * f).then(|| {
                    msg!("k2-pto-rounded", hz = f.to_string(), us = us, actual = format!("{actual:.3}")).into()
                });
                (us, note)
            }
        }
    }
}

/// The channel's spec and registers, or an error naming what the model has.
pub fn channel(model: &Model, ch: u8) -> Result<(&'static PtoSpec, PtoRegs)> {
    if model.relay {
        return Err(
            Error::unsupported(msg!("k2-pto-relay-model", model = model.name)).hint(msg!("k2-pto-relay-model-hint"))
        );
    }
    let all: &'static [PtoSpec] = model.pto;
    let spec = all.iter().find(|p| p.channel == ch).ok_or_else(|| {
        let list: Vec<String> = all.iter().map(|p| format!("{} ({})", p.channel, p.output)).collect();
        Error::unsupported(msg!("k2-pto-no-channel", model = model.name, channel = ch))
            .hint(msg!("k2-pto-no-channel-hint", list = list.join(", ")))
    })?;
    Ok((spec, PTO_REGS[ch as usize]))
}

/// A cycle in the channel's units: (value, ms base?).
fn to_base(us: u64, what: &str) -> Result<(u64, bool)> {
    if us <= 65_535 {
        Ok((us, false))
    } else if us.is_multiple_of(1000) && us / 1000 <= 65_535 {
        Ok((us / 1000, true))
    } else {
        Err(bad(what, msg!("k2-pto-cycle-register", us = us)))
    }
}

fn check_freq(spec: &PtoSpec, us: u64, what: &str) -> Result<()> {
    if us < 2 {
        return Err(bad(what, msg!("k2-pto-cycle-below-minimum", us = us)));
    }
    // Saturating: a product past u64 is far above 1 000 000, and a cycle that long is
    // refused by the register's limit (to_base), not wrapped into "too fast".
    let shortest = 1_000_000u64.div_ceil(spec.max_hz as u64);
    if us.saturating_mul(spec.max_hz as u64) < 1_000_000 && what.starts_with("cycle") {
        // The cycle as typed: `cycle=2` is 2 µs, too short, not "500000 Hz".
        return Err(bad(
            what,
            msg!("k2-pto-cycle-too-short", us = us, output = spec.output, shortest = shortest, max = spec.max_hz),
        )
        .hint(msg!("k2-pto-cycle-too-short-hint", shortest = shortest)));
    }
    if us.saturating_mul(spec.max_hz as u64) < 1_000_000 {
        return Err(bad(
            what,
            msg!("k2-pto-freq-too-high", hz = 1_000_000 / us, output = spec.output, max = spec.max_hz),
        )
        .hint(msg!("k2-pto-freq-too-high-hint", output = spec.output, shortest = shortest)));
    }
    Ok(())
}

/// `pto N freq=… | cycle=… count=…`: single-segment PTO (§3.4.2.3): control byte 16#85
/// (16#8D with a 1 ms time base), SMW68, SMD72, then PLS.
pub fn plan_pto(model: &Model, ch: u8, rate: Rate, count: u64) -> Result<Plan> {
    let (spec, r) = channel(model, ch)?;
    let (us, note) = rate.cycle_us();
    check_freq(spec, us, if matches!(rate, Rate::CycleUs(_)) { "cycle" } else { "freq" })?;
    if !(2..=u32::MAX as u64).contains(&count) {
        return Err(bad("count", msg!("k2-pto-count-range", count = count)));
    }
    let (cycle, ms) = to_base(us, "cycle")?;
    let mut p = Plan::default();
    p.notes.extend(note);
    if ms {
        p.notes.push(msg!("k2-pto-ms-base", us = us, control = r.control).into());
    }
    let control = ctl::ENABLE | ctl::UPDATE_CYCLE | ctl::UPDATE_COUNT | if ms { ctl::BASE_MS } else { 0 };
    p.byte(Area::SM, r.control, control as i64);
    p.word(Area::SM, r.cycle, cycle as i64);
    p.dword(Area::SM, r.count, count as i64);
    p.then.push(Instr::Pls(ch));
    Ok(p)
}

/// `pwm N cycle=… width=… [async]` (§3.4.2.4): control byte 16#D3 (synchronous update, as
/// the manual's example) or 16#C3 (asynchronous), SMW68, SMW70, then PLS.
pub fn plan_pwm(model: &Model, ch: u8, cycle_us: u64, width_us: u64, sync: bool) -> Result<Plan> {
    let (spec, r) = channel(model, ch)?;
    check_freq(spec, cycle_us, "cycle")?;
    let (cycle, ms) = to_base(cycle_us, "cycle")?;
    let width = if ms {
        if !width_us.is_multiple_of(1000) {
            return Err(bad("width", msg!("k2-pwm-width-whole-ms", width = width_us, cycle = cycle_us)));
        }
        width_us / 1000
    } else {
        width_us
    };
    let mut p = Plan::default();
    if width >= cycle {
        p.notes.push(msg!("k2-pwm-always-on").into());
    } else if width == 0 {
        p.notes.push(msg!("k2-pwm-always-off").into());
    }
    let width = width.min(65_535);
    let control = ctl::ENABLE
        | ctl::PWM
        | ctl::UPDATE_CYCLE
        | ctl::UPDATE_WIDTH
        | if sync { ctl::PWM_SYNC } else { 0 }
        | if ms { ctl::BASE_MS } else { 0 };
    p.byte(Area::SM, r.control, control as i64);
    p.word(Area::SM, r.cycle, cycle as i64);
    p.word(Area::SM, r.width, width as i64);
    p.then.push(Instr::Pls(ch));
    Ok(p)
}

/// One segment of a profile request.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Segment {
    pub rate: Rate,
    pub count: u64,
}

/// One segment as the table holds it: cycle in the profile's time base, pulse count.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Serialize)]
pub struct TableSegment {
    pub cycle: u16,
    pub count: u32,
}

/// A point of the planned frequency-over-time curve (one per segment).
#[derive(Clone, Copy, Debug, PartialEq, Serialize)]
pub struct TimelinePoint {
    pub start_us: u64,
    pub end_us: u64,
    pub freq_hz: f64,
    pub pulses: u64,
}

/// What a profile does over time, without running it — for plots and previews.
#[derive(Clone, Debug, PartialEq, Serialize)]
pub struct Timeline {
    pub points: Vec<TimelinePoint>,
    pub total_pulses: u64,
    pub duration_us: u64,
}

/// The frequency over time of a profile table (plan only: pure arithmetic, §3.4.2.1).
pub fn timeline(segments: &[TableSegment], base_ms: bool) -> Timeline {
    let unit = if base_ms { 1000 } else { 1 };
    let mut t = 0u64;
    let mut points = Vec::with_capacity(segments.len());
    for s in segments {
        // Saturating: a planned table (64 segments at most) cannot reach u64::MAX µs, but
        // this takes any table.
        let cycle_us = s.cycle as u64 * unit;
        let d = cycle_us.saturating_mul(s.count as u64);
        points.push(TimelinePoint {
            start_us: t,
            end_us: t.saturating_add(d),
            freq_hz: 1e6 / cycle_us as f64,
            pulses: s.count as u64,
        });
        t = t.saturating_add(d);
    }
    Timeline { total_pulses: points.iter().map(|p| p.pulses).sum(), duration_us: t, points }
}

/// A validated profile: the table, its time base, and the plan writing it.
#[derive(Clone, Debug)]
pub struct Profile {
    pub table: Vec<TableSegment>,
    pub base_ms: bool,
    pub plan: Plan,
}

/// `profile N at VBx [(cycle=…, count=…), …] [force]` (§3.4.2.1, §3.4.2.3): checks the
/// table, then writes it (count byte, 8 bytes per segment), SMW168, control byte 16#A0
/// (16#A8 with a 1 ms time base), then PLS. Refuses even addresses, more than 64 segments,
/// counts < 1, cycles < 2 or above the channel's limit, mixed time bases, tables past the V
/// area, and tables that overlap the E2PROM backup area `backup` unless `force`.
pub fn plan_profile(
    model: &Model,
    ch: u8,
    at: u32,
    segments: &[Segment],
    force: bool,
    backup: (u32, u32),
) -> Result<Profile> {
    let (spec, r) = channel(model, ch)?;
    if at.is_multiple_of(2) {
        return Err(bad("at", msg!("k2-profile-even", at = at)).hint(msg!("k2-table-odd-hint", at = at as u64 + 1)));
    }
    if segments.is_empty() || segments.len() > MAX_SEGMENTS as usize {
        return Err(bad("segments", msg!("k2-profile-segments", n = segments.len(), max = MAX_SEGMENTS)));
    }
    // In u64: an address near the top of u32 must be refused, not wrap past the check.
    let last = at as u64 + 8 * segments.len() as u64;
    if last >= model.v_bytes as u64 {
        return Err(Error::new(
            crate::core::ErrorKind::Range,
            msg!("k2-profile-past-v", at = at, last = last, model = model.name, top = model.v_bytes - 1),
        )
        .operand(format!("VB{at}")));
    }
    let last = last as u32;
    if overlaps_backup(at, last, backup) && !force {
        return Err(bad("at", msg!("k2-profile-backup", at = at, last = last, first = backup.0, end = backup.1))
            .hint(msg!("k2-table-backup-hint")));
    }
    let mut us = Vec::with_capacity(segments.len());
    let mut plan = Plan::default();
    for (k, s) in segments.iter().enumerate() {
        let what = msg!("k2-profile-segment", n = k + 1).to_string();
        if s.count < 1 || s.count > u32::MAX as u64 {
            return Err(bad(&what, msg!("k2-profile-segment-count", n = k + 1, count = s.count)));
        }
        let (c, note) = s.rate.cycle_us();
        check_freq(spec, c, &what).map_err(|e| {
            let m = msg!("k2-profile-segment-error", n = k + 1, message = e.message.as_str());
            Error::new(e.kind, m).operand(what.clone()).hint(e.hint.clone().unwrap_or_default())
        })?;
        plan.notes.extend(note.map(|n| msg!("k2-profile-segment-error", n = k + 1, message = n).into()));
        us.push(c);
    }
    let base_ms = if us.iter().all(|&c| c <= 65_535) {
        false
    } else if us.iter().all(|&c| c % 1000 == 0 && c / 1000 <= 65_535) {
        plan.notes.push(msg!("k2-profile-ms-base", control = r.control).into());
        true
    } else {
        return Err(bad("segments", msg!("k2-profile-mixed-base")));
    };
    let div = if base_ms { 1000 } else { 1 };
    let table: Vec<TableSegment> = segments
        .iter()
        .zip(&us)
        .map(|(s, c)| TableSegment { cycle: (c / div) as u16, count: s.count as u32 })
        .collect();
    plan.byte(Area::V, at, table.len() as i64);
    for (k, s) in table.iter().enumerate() {
        let o = at + 1 + 8 * k as u32;
        plan.word(Area::V, o, s.cycle as i64);
        plan.word(Area::V, o + 2, 0);
        plan.dword(Area::V, o + 4, s.count as i64);
    }
    plan.word(Area::SM, r.profile, at as i64);
    let control = ctl::ENABLE | ctl::MULTI | if base_ms { ctl::BASE_MS } else { 0 };
    plan.byte(Area::SM, r.control, control as i64);
    plan.then.push(Instr::Pls(ch));
    Ok(Profile { table, base_ms, plan })
}

/// Meanings of a PTO control byte's set bits (§3.4.2.2).
pub fn decode_control(c: u8) -> Vec<String> {
    let bit = |b: &str| msg!("k2-pto-control-bit", bit = b).text;
    let mut w = vec![bit(if c & ctl::ENABLE != 0 { "enabled" } else { "disabled" })];
    if c & ctl::PWM != 0 {
        w.push("PWM".into());
        w.push(bit(if c & ctl::PWM_SYNC != 0 { "sync" } else { "async" }));
    } else {
        w.push("PTO".into());
        w.push(bit(if c & ctl::MULTI != 0 { "multi" } else { "single" }));
    }
    w.push(bit(if c & ctl::BASE_MS != 0 { "base-ms" } else { "base-us" }));
    if c & ctl::UPDATE_CYCLE != 0 {
        w.push(bit("cycle"));
    }
    if c & ctl::UPDATE_WIDTH != 0 {
        w.push(bit("width"));
    }
    if c & ctl::UPDATE_COUNT != 0 {
        w.push(bit("count"));
    }
    w
}

/// Meanings of a PTO status byte (§3.4.2.2).
pub fn decode_status(s: u8) -> Vec<String> {
    let bit = |b: &str| msg!("k2-pto-status-bit", bit = b).text;
    let mut w = vec![bit(if s & 0x80 != 0 { "pto-idle" } else { "pto-busy" })];
    w.push(bit(if s & 0x08 != 0 { "pwm-idle" } else { "pwm-running" }));
    if s & 0x10 != 0 {
        w.push(bit("invalid"));
    }
    if s & 0x20 != 0 {
        w.push(bit("aborted"));
    }
    w
}

/// `pto N status`: reads the channel's registers and decodes them.
pub fn status(dev: &mut dyn Device, model: &Model, ch: u8) -> Result<(Vec<Written>, Vec<String>)> {
    let (_, r) = channel(model, ch)?;
    let mut pos = K2Operand::dword(Area::SM, r.pos_cv);
    pos.view = crate::core::DataType::DInt;
    let ops = [
        K2Operand::byte(Area::SM, r.status),
        K2Operand::byte(Area::SM, r.control),
        K2Operand::word(Area::SM, r.cycle),
        K2Operand::word(Area::SM, r.width),
        K2Operand::dword(Area::SM, r.count),
        pos,
        K2Operand::byte(Area::SM, r.pos_control),
    ];
    let vals = read_ops(dev, &ops)?;
    let st = vals[0].value.as_i64() as u8;
    let c = vals[1].value.as_i64() as u8;
    let pc = vals[6].value.as_i64() as u8;
    let mut words: Vec<String> = decode_status(st);
    words.push(msg!("k2-pto-status-control", words = decode_control(c).join(", ")).into());
    words.push(msg!("k2-pto-status-position", pulses = vals[5].value.as_i64()).into());
    if pc & 0x80 != 0 {
        words.push(msg!("k2-pto-status-estop", byte = r.pos_control).into());
    }
    if pc & 0x08 != 0 {
        words.push(msg!("k2-pto-status-dir-off", byte = r.pos_control).into());
    }
    Ok((vals, words))
}

/// What channel `ch` is doing now, when it is busy: the status byte's idle bits (§3.4.1:
/// SM66.7 PTO idle, SM66.3 PWM idle, both 1 when nothing runs). A second PLS on a busy
/// channel replaces the running train, so the shell warns (or refuses with `strict`).
pub fn busy(dev: &mut dyn Device, model: &Model, ch: u8) -> Result<Option<String>> {
    let (_, r) = channel(model, ch)?;
    let ops = [K2Operand::byte(Area::SM, r.status), K2Operand::dword(Area::SM, r.count)];
    let vals = read_ops(dev, &ops)?;
    let st = vals[0].value.as_i64() as u8;
    Ok(if st & 0x80 == 0 {
        Some(msg!("k2-pto-busy", channel = ch, byte = r.status).into())
    } else if st & 0x08 == 0 {
        Some(msg!("k2-pwm-busy", channel = ch, byte = r.status).into())
    } else {
        None
    })
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::k2::catalog::find;

    fn k205() -> &'static Model {
        find("K205-16DT").unwrap()
    }

    #[test]
    fn pto_plans_the_manual_registers() {
        let p = plan_pto(k205(), 0, Rate::Hz(2000.0), 1000).unwrap();
        assert_eq!(p.value_of("SMB67"), Some(0x85));
        assert_eq!(p.value_of("SMW68"), Some(500));
        assert_eq!(p.value_of("SMD72"), Some(1000));
        assert_eq!(p.then, vec![Instr::Pls(0)]);
        let p = plan_pto(k205(), 1, Rate::CycleUs(500), 1000).unwrap();
        assert_eq!(p.value_of("SMB77"), Some(0x85));
        let p = plan_pto(k205(), 0, Rate::Hz(3000.0), 10).unwrap();
        assert_eq!(p.value_of("SMW68"), Some(333));
        assert!(p.notes[0].contains("3003.003"), "{:?}", p.notes);
        let p = plan_pto(k205(), 0, Rate::Hz(2.0), 10).unwrap();
        assert_eq!((p.value_of("SMB67"), p.value_of("SMW68")), (Some(0x8D), Some(500)), "2 Hz = 500 ms, ms base");
    }

    #[test]
    fn pto_refusals() {
        let e = plan_pto(k205(), 0, Rate::Hz(60_000.0), 10).unwrap_err();
        assert!(e.message.contains("50000 Hz"), "{e}");
        assert!(plan_pto(k205(), 0, Rate::CycleUs(500), 1).is_err());
        assert!(plan_pto(k205(), 3, Rate::CycleUs(500), 10).unwrap_err().hint.clone().unwrap().contains("2 (Q0.4)"));
        assert!(plan_pto(find("K205-16DR").unwrap(), 0, Rate::CycleUs(500), 10).unwrap_err().message.contains("relay"));
        assert!(plan_pto(k205(), 0, Rate::CycleUs(65_535_001), 10).is_err());
        assert!(plan_pto(k205(), 0, Rate::CycleUs(70_001), 10).is_err(), "not whole ms and too long for µs");
    }

    #[test]
    fn pwm_plans_16_d3() {
        let p = plan_pwm(k205(), 0, 1000, 250, true).unwrap();
        assert_eq!(
            (p.value_of("SMB67"), p.value_of("SMW68"), p.value_of("SMW70")),
            (Some(0xD3), Some(1000), Some(250))
        );
        let p = plan_pwm(k205(), 0, 1000, 250, false).unwrap();
        assert_eq!(p.value_of("SMB67"), Some(0xC3));
        let p = plan_pwm(k205(), 0, 100_000, 25_000, true).unwrap();
        assert_eq!((p.value_of("SMB67"), p.value_of("SMW68"), p.value_of("SMW70")), (Some(0xDB), Some(100), Some(25)));
        assert!(plan_pwm(k205(), 0, 100_000, 250, true).is_err(), "width not whole ms in the ms base");
        assert!(plan_pwm(k205(), 0, 1000, 2000, true).unwrap().notes[0].contains("100 %"));
    }

    /// Cycle × the channel's frequency limit wrapped in a release build
    /// (368 934 881 474 192 µs read as "0 Hz is above Q0.0's limit") and panicked with
    /// overflow checks (`cycle=122222h`); a cycle that long is refused by the register.
    #[test]
    fn a_huge_cycle_is_refused_by_the_register_not_wrapped() {
        for us in [368_934_881_474_192, 122_222 * 3_600_000_000, u64::MAX] {
            let e = plan_pwm(k205(), 0, us, 250, true).unwrap_err();
            assert!(e.message.contains("up to 65 535 µs, or whole milliseconds up to 65 535 ms"), "{us}: {e}");
            let e = plan_pto(k205(), 0, Rate::CycleUs(us), 10).unwrap_err();
            assert!(e.message.contains("65 535 ms"), "{us}: {e}");
            let slow = [Segment { rate: Rate::CycleUs(us), count: 1 }];
            let e = plan_profile(k205(), 0, 3001, &slow, false, (3648, 3902)).unwrap_err();
            assert!(e.message.contains("65 535"), "{us}: {e}");
        }
    }

    /// A table address near the top of u32 is refused, not wrapped past the V check.
    #[test]
    fn a_table_address_past_v_is_refused_not_wrapped() {
        for at in [4_294_967_295, 4_294_967_291, 4095] {
            let e = plan_profile(k205(), 0, at, &segs(), true, (3648, 3902)).unwrap_err();
            assert!(e.message.contains("runs past the V area") && e.message.contains("VB4095"), "{at}: {e}");
        }
    }

    fn segs() -> Vec<Segment> {
        vec![Segment { rate: Rate::CycleUs(500), count: 1000 }, Segment { rate: Rate::CycleUs(250), count: 4000 }]
    }

    #[test]
    fn profile_writes_the_table_and_its_timeline_sums_the_segments() {
        let pr = plan_profile(k205(), 0, 3001, &segs(), false, (3648, 3902)).unwrap();
        let p = &pr.plan;
        assert_eq!(p.value_of("VB3001"), Some(2));
        assert_eq!(p.value_of("VW3002"), Some(500));
        assert_eq!(p.value_of("VW3004"), Some(0));
        assert_eq!(p.value_of("VD3006"), Some(1000));
        assert_eq!(p.value_of("VW3010"), Some(250));
        assert_eq!(p.value_of("VD3014"), Some(4000));
        assert_eq!(p.value_of("SMW168"), Some(3001));
        assert_eq!(p.value_of("SMB67"), Some(0xA0));
        let t = timeline(&pr.table, pr.base_ms);
        assert_eq!(t.total_pulses, 5000);
        assert_eq!(t.duration_us, 500 * 1000 + 250 * 4000);
        assert_eq!(t.points[1].start_us, 500_000);
        assert_eq!(t.points[1].freq_hz, 4000.0);
    }

    #[test]
    fn profile_refusals() {
        let b = (3648, 3902);
        assert!(plan_profile(k205(), 0, 3000, &segs(), false, b).unwrap_err().message.contains("even"));
        let many = vec![Segment { rate: Rate::CycleUs(500), count: 1 }; 65];
        assert!(plan_profile(k205(), 0, 1, &many, false, b).unwrap_err().message.contains("65 segments"));
        let zero = vec![Segment { rate: Rate::CycleUs(500), count: 0 }];
        assert!(plan_profile(k205(), 0, 1, &zero, false, b).is_err());
        let fast = vec![Segment { rate: Rate::CycleUs(1), count: 5 }];
        assert!(plan_profile(k205(), 0, 1, &fast, false, b).unwrap_err().message.contains("below the minimum of 2"));
        let e = plan_profile(k205(), 0, 3641, &segs(), false, b).unwrap_err();
        assert!(e.message.contains("backup"), "{e}");
        assert!(plan_profile(k205(), 0, 3641, &segs(), true, b).is_ok(), "force");
        assert!(plan_profile(k205(), 0, 4091, &segs(), true, b).is_err(), "past the V area");
        let mixed =
            vec![Segment { rate: Rate::CycleUs(100_000), count: 1 }, Segment { rate: Rate::CycleUs(500), count: 1 }];
        assert!(plan_profile(k205(), 0, 1, &mixed, false, b).unwrap_err().message.contains("time base"));
    }

    #[test]
    fn decoders_read_the_manuals_worked_values() {
        assert_eq!(
            decode_control(0x85),
            vec!["enabled", "PTO", "single segment", "1 µs time base", "update cycle", "update count"]
        );
        assert_eq!(decode_control(0x81), vec!["enabled", "PTO", "single segment", "1 µs time base", "update cycle"]);
        assert_eq!(decode_control(0x84), vec!["enabled", "PTO", "single segment", "1 µs time base", "update count"]);
        assert_eq!(decode_control(0xA0), vec!["enabled", "PTO", "multi-segment", "1 µs time base"]);
        assert_eq!(
            decode_control(0xD3),
            vec!["enabled", "PWM", "synchronous update", "1 µs time base", "update cycle", "update width"]
        );
        assert_eq!(
            decode_control(0xD2),
            vec!["enabled", "PWM", "synchronous update", "1 µs time base", "update width"]
        );
        assert_eq!(decode_status(0x88), vec!["PTO idle", "PWM idle"]);
        assert_eq!(
            decode_status(0x38),
            vec!["PTO busy", "PWM idle", "cycle or count invalid", "aborted by user command"]
        );
    }
}
