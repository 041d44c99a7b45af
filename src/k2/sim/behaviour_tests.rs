//! Behaviour of the simulated special-function hardware against the manual: every control
//! and status bit of each channel's register set (§3.4.2.2, §3.4.3.1, §3.3.2), the
//! manual's worked control values and its worked HSC example (§3.3.3).

use super::*;
use crate::core::ErrorKind;
use crate::k2::sm_map::{HscRegs, PtoRegs};
use crate::k2::K2Ops;

fn sim(model: &str) -> (K2Sim, Clock) {
    let clock = Clock::stepped();
    (open(model, clock.clone()).unwrap(), clock)
}

/// `set` with the shell's syntax: `SMB67=16#85, SMW68=500`.
fn set(s: &mut K2Sim, items: &str) {
    let mut batch = Vec::new();
    for it in items.split(',') {
        let (op, v) = it.split_once('=').unwrap();
        let op = s.space().parse(op.trim()).unwrap()[0];
        let v = s.space().value(&op, v.trim()).unwrap();
        batch.push((op, v));
    }
    s.write(&batch).unwrap();
}

fn get(s: &mut K2Sim, op: &str) -> i64 {
    let op = s.space().parse(op).unwrap()[0];
    s.read(&[op]).unwrap()[0].as_i64()
}

fn bit(s: &mut K2Sim, byte: u32, b: u8) -> bool {
    get(s, &format!("SM{byte}.{b}")) != 0
}

fn ms(clock: &Clock, n: u64) {
    clock.step(Duration::from_millis(n));
}

fn us(clock: &Clock, n: u64) {
    clock.step(Duration::from_micros(n));
}

fn taken(s: &mut K2Sim) -> Vec<EventKind> {
    s.events(true).unwrap().into_iter().map(|e| e.kind).collect()
}

// ---- pulse outputs ------------------------------------------------------------------------

#[test]
fn pto0_on_a_k205_runs_its_train_and_raises_its_event() {
    let (mut s, clock) = sim("K205-16DT");
    set(&mut s, "SMB67=16#85, SMW68=500, SMD72=1000");
    s.pls(0).unwrap();
    ms(&clock, 499);
    assert!(!bit(&mut s, 66, 7), "still busy after 499 ms");
    assert!(s.events(false).unwrap().is_empty());
    ms(&clock, 2);
    assert!(bit(&mut s, 66, 7), "SM66.7 PTO idle after 501 ms");
    let ev = s.events(false).unwrap();
    assert_eq!(ev.len(), 1);
    assert_eq!(ev[0].kind.number(), Some(28));
    assert_eq!(ev[0].time, Duration::from_millis(500), "timestamped when the last pulse ended");
    assert_eq!(get(&mut s, "SMD212"), 1000, "position counter counted the pulses");
}

/// Every channel of the K209M (PTO0/1/2 and Q0.5), the manual's worked control values.
#[test]
fn worked_control_values_on_every_channel() {
    let (mut s, clock) = sim("K209M-56DT");
    for r in PTO_REGS {
        let (c, st, cy, wd, cn, n) = (r.control, r.status, r.cycle, r.width, r.count, r.channel);
        assert!(bit(&mut s, st, 7) && bit(&mut s, st, 3), "PTO{n}: both idle at power-up");
        // 16#85: PTO, 1 µs, update count and cycle.
        set(&mut s, &format!("SMB{c}=16#85, SMW{cy}=500, SMD{cn}=1000"));
        s.pls(n).unwrap();
        assert!(!bit(&mut s, st, 7), "PTO{n} busy");
        ms(&clock, 500);
        assert!(bit(&mut s, st, 7), "PTO{n} idle after 1000 × 500 µs");
        assert_eq!(taken(&mut s), vec![EventKind::PtoComplete { channel: n }]);
        // 16#84: update the count only; the cycle stays 500 µs.
        set(&mut s, &format!("SMB{c}=16#84, SMW{cy}=9999, SMD{cn}=10"));
        s.pls(n).unwrap();
        us(&clock, 4999);
        assert!(!bit(&mut s, st, 7), "PTO{n}: 10 × 500 µs not over at 4.999 ms (SMW{cy}=9999 was not loaded)");
        us(&clock, 1);
        assert!(bit(&mut s, st, 7));
        // 16#81: update the cycle only; the count stays 10.
        set(&mut s, &format!("SMB{c}=16#81, SMW{cy}=1000, SMD{cn}=5000"));
        s.pls(n).unwrap();
        ms(&clock, 9);
        assert!(!bit(&mut s, st, 7), "PTO{n}: 10 × 1000 µs");
        ms(&clock, 1);
        assert!(bit(&mut s, st, 7));
        assert_eq!(get(&mut s, &format!("SMD{}", r.pos_cv)), 1020, "PTO{n}: 1000 + 10 + 10 pulses");
        // 16#D3: PWM, update width and cycle (synchronous update).
        set(&mut s, &format!("SMB{c}=16#D3, SMW{cy}=1000, SMW{wd}=250"));
        s.pls(n).unwrap();
        assert!(!bit(&mut s, st, 3), "PWM{n} running: SM{st}.3 = 0");
        let out = s.pto.iter().find(|p| p.regs.channel == n).unwrap().spec.output;
        us(&clock, 100);
        assert_eq!(get(&mut s, out), 1, "{out} high in the first 250 µs");
        us(&clock, 200);
        assert_eq!(get(&mut s, out), 0, "{out} low after the width");
        // 16#D2: update the width only (sync: from the next cycle boundary at 1000 µs).
        set(&mut s, &format!("SMB{c}=16#D2, SMW{cy}=3, SMW{wd}=800"));
        s.pls(n).unwrap();
        us(&clock, 200);
        assert_eq!(get(&mut s, out), 0, "{out}: the old width holds until the cycle ends");
        us(&clock, 1000);
        assert_eq!(get(&mut s, out), 1, "{out}: 700 µs into the next cycle, the new 800 µs width holds");
        // Stop: enable bit clear.
        set(&mut s, &format!("SMB{c}=16#40"));
        s.pls(n).unwrap();
        assert!(bit(&mut s, st, 3), "PWM{n} idle again");
        // 16#A0: multi-segment PTO from the profile table.
        set(&mut s, &format!("SMW{}=3001, VB3001=2, VW3002=500, VD3006=1000, VW3010=250, VD3014=4000", r.profile));
        set(&mut s, &format!("SMB{c}=16#A0"));
        s.pls(n).unwrap();
        ms(&clock, 1499);
        assert!(!bit(&mut s, st, 7), "PTO{n}: 0.5 s + 1 s profile");
        ms(&clock, 1);
        assert!(bit(&mut s, st, 7));
        assert_eq!(get(&mut s, &format!("SMD{}", r.pos_cv)), 1020 + 5000);
        assert_eq!(taken(&mut s).len(), 3, "three PTO completions (PWM has none)");
    }
}

#[test]
fn control_bits_time_base_enable_and_async_pwm() {
    let (mut s, clock) = sim("K205-16DT");
    // Bit 3: 1 ms time base.
    set(&mut s, "SMB67=16#8D, SMW68=5, SMD72=2");
    s.pls(0).unwrap();
    ms(&clock, 9);
    assert!(!bit(&mut s, 66, 7));
    ms(&clock, 1);
    assert!(bit(&mut s, 66, 7), "2 × 5 ms");
    assert_eq!(taken(&mut s), vec![EventKind::PtoComplete { channel: 0 }]);
    // Bit 4 = 0: asynchronous PWM update takes effect at once.
    set(&mut s, "SMB67=16#C3, SMW68=1000, SMW70=250");
    s.pls(0).unwrap();
    us(&clock, 100);
    set(&mut s, "SMB67=16#C2, SMW70=800");
    s.pls(0).unwrap();
    us(&clock, 300);
    assert_eq!(get(&mut s, "Q0.0"), 1, "300 µs into the new cycle, below the 800 µs width");
    // Width ≥ cycle is 100 %; width 0 is 0 %.
    set(&mut s, "SMB67=16#C2, SMW70=5000");
    s.pls(0).unwrap();
    us(&clock, 990);
    assert_eq!(get(&mut s, "Q0.0"), 1);
    set(&mut s, "SMB67=16#C2, SMW70=0");
    s.pls(0).unwrap();
    us(&clock, 1);
    assert_eq!(get(&mut s, "Q0.0"), 0);
    // Bit 7 = 0 on a running PTO: stopped by user command, status bit 5.
    set(&mut s, "SMB67=16#85, SMW68=500, SMD72=1000");
    s.pls(0).unwrap();
    ms(&clock, 100);
    set(&mut s, "SMB67=16#05");
    let m = s.pls(0).unwrap();
    assert!(m.contains("stopped"), "{m}");
    assert!(bit(&mut s, 66, 5), "SM66.5 aborted by user command");
    assert!(bit(&mut s, 66, 7));
    assert_eq!(get(&mut s, "SMD212"), 2 + 200, "2 pulses of the 5 ms train, then 200 of 500 µs");
    ms(&clock, 1000);
    assert!(taken(&mut s).is_empty(), "an aborted PTO raises no completion event");
    // The next good PLS clears bits 4 and 5.
    set(&mut s, "SMB67=16#85");
    s.pls(0).unwrap();
    assert!(!bit(&mut s, 66, 5) && !bit(&mut s, 66, 4));
}

#[test]
fn invalid_cycle_or_count_sets_bit_4_and_refuses() {
    let (mut s, _clock) = sim("K205-16DT");
    set(&mut s, "SMB77=16#85, SMW78=500, SMD82=1");
    let e = s.pls(1).unwrap_err();
    assert_eq!(e.kind, ErrorKind::Refused);
    assert_eq!(e.operand.as_deref(), Some("SMD82"));
    assert!(bit(&mut s, 76, 4), "SM76.4 invalid");
    assert!(bit(&mut s, 76, 7), "nothing started");
    set(&mut s, "SMW78=1, SMD82=100");
    let e = s.pls(1).unwrap_err();
    assert_eq!(e.operand.as_deref(), Some("SMW78"));
    // 16#84 after power-up: the cycle was never loaded (0, §3.4.2.2: «Все значения по
    // умолчанию … = 0»); named as the kept value, as the helper's route can name it.
    set(&mut s, "SMB97=16#84, SMD102=100");
    let e = s.pls(2).unwrap_err();
    assert!(e.message.contains("cycle time kept from before") && e.message.contains("SM97.0"), "{}", e.message);
    assert!(bit(&mut s, 96, 4));
}

#[test]
fn frequency_limits_per_model_and_channel() {
    // K205: Q0.0 50 kHz (20 µs), Q0.4 10 kHz (100 µs).
    let (mut s, _c) = sim("K205-16DT");
    set(&mut s, "SMB67=16#85, SMW68=19, SMD72=10");
    let e = s.pls(0).unwrap_err();
    assert!(e.message.contains("50000 Hz"), "{e}");
    assert!(e.hint.as_deref().unwrap().contains("20 µs"));
    set(&mut s, "SMW68=20");
    s.pls(0).unwrap();
    set(&mut s, "SMB97=16#85, SMW98=99, SMD102=10");
    assert!(s.pls(2).is_err());
    // K209M: Q0.4 200 kHz (5 µs), Q0.5 10 kHz.
    let (mut s, _c) = sim("K209M-56DT");
    set(&mut s, "SMB97=16#85, SMW98=5, SMD102=10");
    s.pls(2).unwrap();
    set(&mut s, "SMB107=16#85, SMW108=50, SMD112=10");
    assert!(s.pls(3).unwrap_err().message.contains("10000 Hz"));
    assert!(bit(&mut s, 106, 4));
}

#[test]
fn channels_that_do_not_exist() {
    let (mut s, _c) = sim("K205-16DR");
    let e = s.pls(0).unwrap_err();
    assert_eq!(e.kind, ErrorKind::Unsupported);
    assert!(e.message.contains("relay"), "{e}");
    let (mut s, _c) = sim("K205-16DT");
    let e = s.pls(3).unwrap_err();
    assert!(e.message.contains("K209M"), "{e}");
    let (mut s, _c) = sim("K209M-56DT");
    assert!(s.hdef(2, 0).unwrap_err().hint.as_deref().unwrap().contains("HSC0, HSC1"));
}

#[test]
fn pls_on_an_unset_channel_names_the_channel_whose_registers_were_set() {
    let (mut s, _c) = sim("K205-16DT");
    set(&mut s, "SMB77=16#85, SMW78=500, SMD82=1000");
    let e = s.pls(0).unwrap_err();
    assert_eq!(e.kind, ErrorKind::State);
    let h = e.hint.clone().unwrap();
    assert!(h.contains("SMB77") && h.contains("PTO1") && h.contains("PLS 1"), "{h}");
}

#[test]
fn profile_table_errors_set_bit_4() {
    let (mut s, _c) = sim("K205-16DT");
    set(&mut s, "SMB67=16#A0, SMW168=3000");
    assert!(s.pls(0).unwrap_err().message.contains("even"));
    set(&mut s, "SMW168=3001, VB3001=65");
    assert!(s.pls(0).unwrap_err().message.contains("65 segments"));
    set(&mut s, "VB3001=1, VW3002=1, VD3006=5");
    assert!(s.pls(0).unwrap_err().message.contains("below 2"));
    set(&mut s, "VW3002=100, VD3006=0");
    assert!(s.pls(0).unwrap_err().message.contains("is 0"));
    assert!(bit(&mut s, 66, 4));
    set(&mut s, "VD3006=1");
    s.pls(0).unwrap();
    assert!(!bit(&mut s, 66, 4), "one pulse is a valid segment (§3.4.2.1: 1 … 4 294 967 295)");
}

#[test]
fn multi_segment_duration_and_pulses_are_the_sums_of_the_segments() {
    let (mut s, clock) = sim("K204ET-16DT");
    let segs = [(500u64, 1000u64), (250, 4000), (100, 123), (5, 77)];
    set(&mut s, &format!("SMW168=3001, VB3001={}", segs.len()));
    for (k, (c, n)) in segs.iter().enumerate() {
        let o = 3002 + 8 * k;
        set(&mut s, &format!("VW{o}={c}, VW{}=0, VD{}={n}", o + 2, o + 4));
    }
    set(&mut s, "SMB67=16#A0");
    s.pls(0).unwrap();
    let total_us: u64 = segs.iter().map(|(c, n)| c * n).sum();
    let total_pulses: u64 = segs.iter().map(|s| s.1).sum();
    let train = s.pto[0].train().unwrap().clone();
    assert_eq!(train.duration(), Duration::from_micros(total_us));
    assert_eq!(train.total, total_pulses);
    us(&clock, total_us - 1);
    assert!(!bit(&mut s, 66, 7));
    us(&clock, 1);
    assert!(bit(&mut s, 66, 7));
    assert_eq!(get(&mut s, "SMD212") as u64, total_pulses);
}

// ---- position control registers ---------------------------------------------------------

#[test]
fn position_bits_on_every_channel() {
    let (mut s, clock) = sim("K209M-56DT");
    for r in PTO_REGS {
        let PtoRegs { channel: n, control: c, cycle: cy, count: cn, pos_cv, pos_new_cv, pos_control: pc, .. } = r;
        let dir = s.pto.iter().find(|p| p.regs.channel == n).unwrap().spec.direction;
        // Direction output 1 = reverse: the count goes down.
        set(&mut s, &format!("{dir}=1, SMB{c}=16#85, SMW{cy}=100, SMD{cn}=50"));
        s.pls(n).unwrap();
        ms(&clock, 10);
        assert_eq!(get(&mut s, &format!("SMD{pos_cv}/DINT")), -50, "channel {n} reverse via {dir}");
        // Bit 3: direction output disabled → the pin is a plain output, pulses count forward.
        set(&mut s, &format!("SM{pc}.3=1"));
        s.pls(n).unwrap();
        ms(&clock, 10);
        assert_eq!(get(&mut s, &format!("SMD{pos_cv}/DINT")), 0);
        // Bit 4: load the new current value.
        set(&mut s, &format!("SMD{pos_new_cv}=DI#100, SM{pc}.4=1"));
        assert_eq!(get(&mut s, &format!("SMD{pos_cv}/DINT")), 100);
        set(&mut s, &format!("SM{pc}.4=0"));
        // Bit 6: clear.
        set(&mut s, &format!("SM{pc}.6=1"));
        assert_eq!(get(&mut s, &format!("SMD{pos_cv}/DINT")), 0);
        set(&mut s, &format!("SM{pc}.6=0"));
        // The current value is read-only.
        let op = s.space().parse(&format!("SMD{pos_cv}")).unwrap()[0];
        let e = s.write(&[(op, Value::Int(5))]).unwrap_err();
        assert!(e.hint.as_deref().unwrap().contains(&format!("SMD{pos_new_cv}")), "{e}");
        // Bit 7: PSTOP stops and latches; the user clears it.
        set(&mut s, &format!("SMD{cn}=100000"));
        s.pls(n).unwrap();
        ms(&clock, 1);
        assert!(s.pstop(n).unwrap().contains("PTO stopped"));
        assert!(bit(&mut s, pc, 7), "SM{pc}.7 latched");
        assert!(bit(&mut s, r.status, 5), "aborted by user command");
        ms(&clock, 100);
        assert!(bit(&mut s, pc, 7), "stays latched");
        assert_eq!(get(&mut s, &format!("SMD{pos_cv}/DINT")), 10, "stopped after 10 pulses");
        set(&mut s, &format!("SM{pc}.7=0, SM{pc}.3=0, {dir}=0"));
        assert!(!bit(&mut s, pc, 7));
        s.events(true).unwrap();
    }
}

// ---- high-speed counters -------------------------------------------------------------------

fn start_counter(s: &mut K2Sim, n: u8, mode: u8, control: u8) {
    let r = HSC_REGS[n as usize];
    set(s, &format!("SMB{}=16#{control:02X}", r.control));
    s.hdef(n, mode).unwrap();
    s.hsc(n).unwrap();
}

fn freq(s: &mut K2Sim, pin: &str, hz: u64) {
    let (b, bit) = pin.trim_start_matches('I').split_once('.').unwrap();
    let p = (b.parse().unwrap(), bit.parse().unwrap());
    s.add_source(Source::Freq { pin: p, wave: inputs::Wave::new(hz, Duration::ZERO) }).unwrap();
}

fn quad(s: &mut K2Sim, lead: Pin, lag: Pin, hz: u64) {
    s.add_source(Source::Quad { lead, lag, wave: inputs::Wave::new(hz, Duration::ZERO) }).unwrap();
}

/// The manual's worked example (§3.3.3): relative, cyclic, PVs 10/1000/1000 from CV 100.
#[test]
fn worked_example_relative_cyclic_from_100() {
    let (mut s, clock) = sim("K205-16DT");
    set(&mut s, "VB3009=3, VD3010=10, VD3014=1000, VD3018=1000, SMW142=3009, SMB141=16#17, SMD38=100");
    start_counter(&mut s, 0, 0, 0xD8); // enable, write CV, write dir, up
    freq(&mut s, "I0.1", 1000);
    let t0 = clock.now();
    ms(&clock, 6030);
    let ev = s.events(true).unwrap();
    let got: Vec<(u16, Duration)> = ev.iter().map(|e| (e.kind.number().unwrap(), e.time - t0)).collect();
    let want_cv = [110i64, 1110, 2110, 2120, 3120, 4120, 4130, 5130, 6130];
    let want: Vec<(u16, Duration)> = want_cv
        .iter()
        .enumerate()
        .map(|(i, cv)| (64 + (i % 3) as u16, Duration::from_millis((cv - 100) as u64)))
        .collect();
    assert_eq!(got, want, "interrupts at CV 110, 1110, 2110, 2120, 3120, 4120, …");
    // CV at each interrupt, read back by stepping to it.
    let (mut s, clock) = sim("K205-16DT");
    set(&mut s, "VB3009=3, VD3010=10, VD3014=1000, VD3018=1000, SMW142=3009, SMB141=16#17, SMD38=100");
    start_counter(&mut s, 0, 0, 0xD8);
    freq(&mut s, "I0.1", 1000);
    let mut at = 0;
    for (k, cv) in want_cv.iter().enumerate() {
        let dt = (*cv - 100) as u64 - at;
        ms(&clock, dt);
        at += dt;
        assert_eq!(get(&mut s, "SMD38"), *cv);
        assert!(!bit(&mut s, 36, 7), "SM36.7: CV is below the next PV");
        assert_eq!(get(&mut s, "SMB140"), ((k + 1) % 3) as i64, "segment after PV{}", k % 3 + 1);
        let e = s.take_event(&EventMatch::Number(64 + (k % 3) as u16)).unwrap().unwrap();
        assert_eq!(e.time - Duration::ZERO, Duration::from_millis(at));
    }
}

#[test]
fn hsc_control_and_status_bits_on_every_counter() {
    let (mut s, clock) = sim("K204ET-16DT");
    for r in HSC_REGS {
        let HscRegs { channel: n, control: c, status: st, cv, pv, .. } = r;
        let count_pin = crate::k2::sm_map::hsc_mode(n, 0).unwrap().count;
        let pin = inputs::pin_name(count_pin);
        // bit 7 enable, bit 4 write direction, bit 3 up, bit 6 write CV, bit 5 write PV.
        set(&mut s, &format!("SMD{cv}=DI#5, SMD{pv}=DI#105"));
        start_counter(&mut s, n, 0, 0xF8);
        freq(&mut s, &pin, 1000);
        ms(&clock, 99);
        assert_eq!(get(&mut s, &format!("SMD{cv}")), 104, "HSC{n} counts up from 5");
        assert!(bit(&mut s, st, 5), "SM{st}.5 up");
        assert!(!bit(&mut s, st, 6) && !bit(&mut s, st, 7));
        ms(&clock, 1);
        assert!(bit(&mut s, st, 6), "SM{st}.6 CV = PV");
        assert_eq!(taken(&mut s), vec![EventKind::HscCvEqPv { channel: n, pv: None }]);
        ms(&clock, 1);
        assert!(bit(&mut s, st, 7) && !bit(&mut s, st, 6), "SM{st}.7 CV > PV");
        // bit 3 = 0 down (with bit 4), without touching CV (bit 6 = 0).
        set(&mut s, &format!("SMB{c}=16#90"));
        s.hsc(n).unwrap();
        ms(&clock, 10);
        assert_eq!(get(&mut s, &format!("SMD{cv}")), 96);
        assert!(!bit(&mut s, st, 5), "SM{st}.5 down");
        // bit 4 = 0: the direction bit is ignored.
        set(&mut s, &format!("SMB{c}=16#88"));
        s.hsc(n).unwrap();
        ms(&clock, 10);
        assert_eq!(get(&mut s, &format!("SMD{cv}")), 86, "still down");
        // bit 7 = 0 stops counting.
        set(&mut s, &format!("SMB{c}=16#00"));
        s.hsc(n).unwrap();
        ms(&clock, 10);
        assert_eq!(get(&mut s, &format!("SMD{cv}")), 86);
        s.remove_source(count_pin).unwrap();
        s.events(true).unwrap();
    }
}

#[test]
fn multi_pv_bits_absolute_relative_fault_and_segment_on_every_counter() {
    let (mut s, clock) = sim("K204ET-16DT");
    for r in HSC_REGS {
        let HscRegs { channel: n, status: st, cv, mpv_control: b, table, segment, event_base, .. } = r;
        let pin = inputs::pin_name(crate::k2::sm_map::hsc_mode(n, 0).unwrap().count);
        // Absolute (bit 1 = 0), load (bit 4), multi (bit 0): PVs 100, 200, 300 at VB3009.
        set(&mut s, "VB3009=3, VD3010=100, VD3014=200, VD3018=300");
        set(&mut s, &format!("SMW{table}=3009, SMB{b}=16#11, SMD{cv}=0"));
        start_counter(&mut s, n, 0, 0xD8);
        freq(&mut s, &pin, 1000);
        ms(&clock, 150);
        assert_eq!(get(&mut s, &format!("SMB{segment}")), 1, "HSC{n} comparing PV2");
        ms(&clock, 1000);
        let nums: Vec<u16> = s.events(true).unwrap().iter().map(|e| e.kind.number().unwrap()).collect();
        let b0 = event_base as u16;
        assert_eq!(nums, vec![b0, b0 + 1, b0 + 2], "HSC{n}: absolute PVs fire once each, events {b0}…");
        // Relative non-cyclic (bit 1, no bit 2) from the current value: fires 3 times then stops.
        set(&mut s, &format!("SMB{b}=16#13"));
        s.hsc(n).unwrap();
        ms(&clock, 2000);
        assert_eq!(s.events(true).unwrap().len(), 3, "HSC{n} relative, not cyclic");
        // Bit 5 = 1 keeps the segment; without bit 4 the last table stays in use.
        set(&mut s, &format!("VB3009=0, SMB{b}=16#27"));
        s.hsc(n).unwrap();
        assert!(!bit(&mut s, st, 3), "no fault: the loaded table is reused");
        ms(&clock, 400);
        let ev = s.events(true).unwrap();
        assert_eq!(ev[0].kind, EventKind::HscCvEqPv { channel: n, pv: Some(3) }, "HSC{n} continued at PV3");
        // Bit 3 of the status byte: a table fault (even start).
        set(&mut s, &format!("SMW{table}=3008, SMB{b}=16#13"));
        let m = s.hsc(n).unwrap();
        assert!(m.contains("fault"), "{m}");
        assert!(bit(&mut s, st, 3), "SM{st}.3 table fault");
        set(&mut s, &format!("SMW{table}=3009, VB3009=3"));
        s.hsc(n).unwrap();
        assert!(!bit(&mut s, st, 3));
        set(&mut s, &format!("SMB{}=16#00", r.control));
        s.hsc(n).unwrap();
        s.remove_source(crate::k2::sm_map::hsc_mode(n, 0).unwrap().count).unwrap();
        s.events(true).unwrap();
    }
}

#[test]
fn relative_pvs_of_the_wrong_sign_never_fire() {
    let (mut s, clock) = sim("K205-16DT");
    set(&mut s, "VB3009=1, VD3010=DI#-50, SMW142=3009, SMB141=16#13");
    start_counter(&mut s, 0, 0, 0x98);
    freq(&mut s, "I0.1", 1000);
    ms(&clock, 1000);
    assert!(s.events(false).unwrap().is_empty());
}

#[test]
fn quadrature_rate_and_direction_on_every_counter() {
    let (mut s, clock) = sim("K204ET-16DT");
    for n in 0..4u8 {
        let m = crate::k2::sm_map::hsc_mode(n, 9).unwrap();
        let (a, b) = (m.count, m.second.unwrap());
        let cv = format!("SMD{}/DINT", HSC_REGS[n as usize].cv);
        // 1x, A leads: up, one count per cycle.
        start_counter(&mut s, n, 9, 0x80);
        quad(&mut s, a, b, 1000);
        ms(&clock, 1000);
        assert_eq!(get(&mut s, &cv), 1000, "HSC{n} 1x");
        // 4x (bit 2): four counts per cycle.
        start_counter(&mut s, n, 9, 0x84);
        ms(&clock, 1000);
        assert_eq!(get(&mut s, &cv), 5000, "HSC{n} 4x");
        // B leads: down, four counts per cycle once the new signal runs.
        quad(&mut s, b, a, 1000);
        ms(&clock, 1000);
        let v1 = get(&mut s, &cv);
        ms(&clock, 1000);
        assert_eq!(get(&mut s, &cv), v1 - 4000, "HSC{n} 4x down");
        assert!(!bit(&mut s, HSC_REGS[n as usize].status, 5));
        s.remove_source(a).unwrap();
        start_counter(&mut s, n, 9, 0x00);
    }
}

#[test]
fn reset_and_start_inputs_with_their_active_levels() {
    let (mut s, clock) = sim("K205-16DT");
    for (n, reset, start) in [(0u8, "I0.0", "I0.5"), (1, "I0.4", "I0.6")] {
        let r = HSC_REGS[n as usize];
        let count = inputs::pin_name(crate::k2::sm_map::hsc_mode(n, 2).unwrap().count);
        let cv = format!("SMD{}", r.cv);
        // Mode 2, start active high (bit 1 = 0): no counting until the start input is on.
        start_counter(&mut s, n, 2, 0x98);
        freq(&mut s, &count, 1000);
        ms(&clock, 10);
        assert_eq!(get(&mut s, &cv), 0, "HSC{n} waits for start {start}");
        set(&mut s, &format!("{start}=1"));
        ms(&clock, 10);
        assert_eq!(get(&mut s, &cv), 10);
        // Reset active high (bit 0 = 0): clears CV on the edge, with a named event.
        set(&mut s, &format!("{reset}=1"));
        assert_eq!(get(&mut s, &cv), 0);
        assert_eq!(taken(&mut s), vec![EventKind::HscReset { channel: n }]);
        set(&mut s, &format!("{reset}=0"));
        ms(&clock, 5);
        // Active low (bits 0 and 1 set): the start input at 1 now stops counting.
        start_counter(&mut s, n, 2, 0x9B);
        ms(&clock, 5);
        assert_eq!(get(&mut s, &cv), 5, "HSC{n}: start active low, input high → no counting");
        set(&mut s, &format!("{start}=0, {reset}=1"));
        assert_eq!(get(&mut s, &cv), 5, "reset active low: going high is not the active edge");
        set(&mut s, &format!("{reset}=0"));
        assert_eq!(get(&mut s, &cv), 0, "reset active low: going low clears");
        s.remove_source(crate::k2::sm_map::hsc_mode(n, 2).unwrap().count).unwrap();
        set(&mut s, &format!("SMB{}=0", r.control));
        s.hsc(n).unwrap();
        s.events(true).unwrap();
    }
}

#[test]
fn edges_written_with_set_count() {
    let (mut s, _clock) = sim("K205-16DT");
    // Mode 3: count I0.1, direction input I0.5 (1 = up).
    start_counter(&mut s, 0, 3, 0x80);
    set(&mut s, "I0.5=1");
    for _ in 0..3 {
        set(&mut s, "I0.1=1");
        set(&mut s, "I0.1=0");
    }
    assert_eq!(get(&mut s, "SMD38"), 3);
    set(&mut s, "I0.5=0, I0.1=1");
    assert_eq!(get(&mut s, "SMD38"), 2, "direction input low counts down");
    // Mode 6: up I0.0, down I0.1, from CV 0 loaded through bit 6.
    set(&mut s, "I0.1=0, SMD38=0");
    start_counter(&mut s, 0, 6, 0xC0);
    set(&mut s, "I0.0=1");
    set(&mut s, "I0.0=0");
    set(&mut s, "I0.0=1");
    set(&mut s, "I0.1=1");
    assert_eq!(get(&mut s, "SMD38"), 1, "two up, one down");
    // Mode 9 at 4x: a full A/B cycle with A leading counts 4.
    set(&mut s, "I0.0=0, I0.1=0, SMD38=0");
    start_counter(&mut s, 0, 9, 0xC4);
    for (a, b) in [(1, 0), (1, 1), (0, 1), (0, 0)] {
        set(&mut s, &format!("I0.1={a}, I0.0={b}"));
    }
    assert_eq!(get(&mut s, "SMD38"), 4);
}

#[test]
fn a_driven_input_refuses_set_and_an_hour_at_200khz_is_exact() {
    let (mut s, clock) = sim("K204ET-16DT");
    start_counter(&mut s, 0, 0, 0x98);
    freq(&mut s, "I0.1", 200_000);
    let op = s.space().parse("I0.1").unwrap()[0];
    let e = s.write(&[(op, Value::Bool(true))]).unwrap_err();
    assert!(e.hint.as_deref().unwrap().contains("sim input I0.1 off"), "{e}");
    clock.step(Duration::from_secs(3600));
    assert_eq!(get(&mut s, "SMD38"), 720_000_000);
}

#[test]
fn next_event_due_for_pto_and_counter() {
    let (mut s, _clock) = sim("K205-16DT");
    set(&mut s, "SMB67=16#85, SMW68=500, SMD72=1000");
    s.pls(0).unwrap();
    assert_eq!(s.next_event_due(), Some(Duration::from_millis(500)));
    set(&mut s, "SMB67=16#05");
    s.pls(0).unwrap();
    set(&mut s, "SMD42=DI#250");
    start_counter(&mut s, 0, 0, 0xB8);
    freq(&mut s, "I0.1", 1000);
    assert_eq!(s.next_event_due(), Some(Duration::from_millis(250)));
}

// ---- clock, backup, persistence -------------------------------------------------------------

#[test]
fn rtc_reads_what_was_set_plus_virtual_time() {
    let (mut s, clock) = sim("K205-16DT");
    s.set_rtc(RtcTime::parse("2026-11-22T10:00:00").unwrap()).unwrap();
    clock.step(Duration::from_secs(90));
    assert_eq!(s.read_rtc().unwrap().to_string(), "2026-11-22T10:01:30");
}

#[test]
fn backup_area_and_retained_ranges_persist_and_wear_is_counted() {
    let dir = std::env::temp_dir().join(format!("plcsh-sim-state-{}", std::process::id()));
    let path = dir.join("state.json");
    let _ = std::fs::remove_file(&path);
    {
        let (mut s, clock) = sim("K205-16DT");
        s.attach_state(path.clone()).unwrap();
        s.set_retain("VB0..VB3, MB10").unwrap();
        set(&mut s, "VB3648=7, VW3901=16#ABCD, VB3903=9, VB0=1, MB10=2, VB4=3");
        s.set_rtc(RtcTime::parse("2030-01-01T00:00:00").unwrap()).unwrap();
        clock.step(Duration::from_secs(5));
        // Wear counting needs no file per store (each durable store is an fsync'd rewrite):
        // count detached, then keep the counts.
        let kept = s.backup.path.take();
        for _ in 0..10_000 {
            set(&mut s, "VB3700=1");
        }
        s.backup.path = kept;
        let wear: Vec<_> = taken(&mut s);
        assert_eq!(wear, vec![EventKind::EepromWear { byte: 3700, writes: 10_000 }]);
    }
    let (mut s, _clock) = sim("K205-16DT");
    s.attach_state(path.clone()).unwrap();
    assert_eq!(get(&mut s, "VB3648"), 7);
    assert_eq!(get(&mut s, "VB3901"), 0xAB);
    assert_eq!(get(&mut s, "VB3902"), 0xCD, "VB3902 is the last default backup byte");
    assert_eq!(get(&mut s, "VB3903"), 0, "VB3903 is outside the default area");
    assert_eq!((get(&mut s, "VB0"), get(&mut s, "MB10"), get(&mut s, "VB4")), (1, 2, 0), "retained ranges");
    assert_eq!(s.backup.writes[(3700 - catalog::EEPROM_FIRST) as usize], 10_000, "write counts persist");
    assert!(s.read_rtc().unwrap() >= RtcTime::parse("2030-01-01T00:00:05").unwrap());
    // Extending the area to VB4095 keeps VB3903 from now on.
    s.set_option("backup_last", "4095").unwrap();
    set(&mut s, "VB4095=5");
    drop(s);
    let (mut s, _clock) = sim("K205-16DT");
    s.attach_state(path.clone()).unwrap();
    assert_eq!(get(&mut s, "VB4095"), 5);
    assert_eq!(s.backup.last, 4095);
    s.backup.path = None;
    let _ = std::fs::remove_dir_all(&dir);
}

/// The counters' quiet path (one formula while only time passes) publishes exactly what the
/// general path does: two simulators given the same operations, one with the quiet path
/// off, compared byte for byte (SM, events) after every step of irregular size — through
/// CV = PV hits, moving off a PV, a direction change, a CV written by HSC, a user
/// overwriting a status byte, a multi-PV table finishing and being passed, and inputs
/// written by the user.
#[test]
fn quiet_counting_matches_the_general_path() {
    let (mut a, ca) = sim("K204ET-16DT");
    let (mut b, cb) = sim("K204ET-16DT");
    for h in &mut b.hsc {
        h.general_only = true;
    }
    let both = |a: &mut K2Sim, b: &mut K2Sim, f: &dyn Fn(&mut K2Sim)| {
        f(a);
        f(b);
    };
    let hz = [1000, 7000, 20_000, 333];
    both(&mut a, &mut b, &|s| {
        for r in HSC_REGS {
            let n = r.channel;
            set(s, &format!("SMD{}=DI#0, SMD{}=DI#{}", r.cv, r.pv, 40 + 30 * n as i32));
            start_counter(s, n, 0, 0xF8);
            let pin = inputs::pin_name(crate::k2::sm_map::hsc_mode(n, 0).unwrap().count);
            freq(s, &pin, hz[n as usize]);
        }
    });
    let mut seed = 0x2545_F491_4F6C_DD1Du64;
    for k in 0..2000 {
        seed ^= seed << 13;
        seed ^= seed >> 7;
        seed ^= seed << 17;
        // Steps around the counting period, so that many end exactly on a PV.
        let step = Duration::from_micros(1 + seed % 3_000);
        ca.step(step);
        cb.step(step);
        match k {
            400 => both(&mut a, &mut b, &|s| {
                set(s, "SMB47=16#90");
                s.hsc(1).unwrap();
            }),
            800 => both(&mut a, &mut b, &|s| {
                set(s, "SMD58=DI#12345, SMB57=16#C8");
                s.hsc(2).unwrap();
            }),
            1200 => both(&mut a, &mut b, &|s| set(s, "SMB36=16#0F")),
            1600 => both(&mut a, &mut b, &|s| set(s, "I0.0=1")),
            1601 => both(&mut a, &mut b, &|s| set(s, "I0.0=0")),
            1400 => both(&mut a, &mut b, &|s| {
                let r = HSC_REGS[3];
                set(s, "VB3009=3, VD3010=100, VD3014=200, VD3018=300");
                set(s, &format!("SMW{}=3009, SMB{}=16#11, SMD{}=DI#0", r.table, r.mpv_control, r.cv));
                set(s, &format!("SMB{}=16#D8", r.control));
                s.hsc(3).unwrap();
            }),
            _ => {}
        }
        a.advance();
        b.advance();
        assert_eq!(a.mem.sm, b.mem.sm, "SM after step {k}");
        assert_eq!(taken(&mut a), taken(&mut b), "events after step {k}");
    }
    let cvs: Vec<i64> = a.hsc.iter().map(|h| h.cv()).collect();
    assert!(cvs.iter().all(|&c| c != 0), "every counter counted: {cvs:?}");
}

/// A running counter's direction change is an event (`hsc0-dir`) at the time it shows in
/// the status bit (SM36.5 …): by the HSC instruction's direction bits (SMB37 bits 3 and 4,
/// k2.md §4), by the external direction input (mode 3: I0.5 for HSC0), and by the signals
/// counted (mode 9, A/B: B leading counts down, from its first count). Starting a counter raises none, nor does an
/// HSC that leaves the direction as it was. The manual gives no event number for it, so it
/// has only its name (see `instr`).
#[test]
fn direction_changes_are_events_when_they_show() {
    let dir = |s: &mut K2Sim| -> Vec<(Duration, EventKind)> {
        s.events(true)
            .unwrap()
            .into_iter()
            .filter(|e| matches!(e.kind, EventKind::HscDirection { .. }))
            .map(|e| (e.time, e.kind))
            .collect()
    };
    let (mut s, clock) = sim("K204ET-16DT");
    // Mode 0, counting up, then down by the direction bits, then HSC again unchanged.
    start_counter(&mut s, 0, 0, 0xF8);
    freq(&mut s, "I0.1", 1000);
    ms(&clock, 10);
    assert_eq!(dir(&mut s), vec![], "starting raises nothing");
    set(&mut s, "SMB37=16#90");
    s.hsc(0).unwrap();
    let at = clock.now();
    ms(&clock, 10);
    assert_eq!(dir(&mut s), vec![(at, EventKind::HscDirection { channel: 0, up: false })]);
    assert_eq!(EventKind::HscDirection { channel: 0, up: false }.name(), "hsc0-dir");
    assert_eq!(EventKind::HscDirection { channel: 0, up: false }.number(), None);
    s.hsc(0).unwrap();
    ms(&clock, 10);
    assert_eq!(dir(&mut s), vec![], "the same direction again");
    s.remove_source((0, 1)).unwrap();
    start_counter(&mut s, 0, 0, 0x00);

    // Mode 3: the direction input I0.5 (1 = up).
    set(&mut s, "I0.5=1");
    start_counter(&mut s, 0, 3, 0x80);
    freq(&mut s, "I0.1", 1000);
    ms(&clock, 10);
    assert_eq!(dir(&mut s), vec![]);
    set(&mut s, "I0.5=0");
    let at = clock.now();
    ms(&clock, 10);
    assert_eq!(dir(&mut s), vec![(at, EventKind::HscDirection { channel: 0, up: false })]);
    s.remove_source((0, 1)).unwrap();
    start_counter(&mut s, 0, 3, 0x00);

    // Mode 9 on HSC1: A leads (up), then B leads (down) from the new signal's start.
    let m = crate::k2::sm_map::hsc_mode(1, 9).unwrap();
    let (a, b) = (m.count, m.second.unwrap());
    start_counter(&mut s, 1, 9, 0x80);
    quad(&mut s, a, b, 1000);
    ms(&clock, 10);
    assert_eq!(dir(&mut s), vec![]);
    quad(&mut s, b, a, 1000);
    // At 1x the first count down is A falling while B is low, 1.75 periods into the new
    // signal (B rises at 1 ms, A at 1.25, B falls at 1.5, A at 1.75): the direction bit turns
    // then, however the time is stepped.
    let at = clock.now() + Duration::from_micros(1750);
    ms(&clock, 10);
    assert_eq!(dir(&mut s), vec![(at, EventKind::HscDirection { channel: 1, up: false })]);
}
