//! Simulator benchmark (not a test): one simulated hour of every pulse channel at its
//! maximum frequency with every high-speed counter counting a signal at its maximum
//! single-phase frequency, on each transistor model. Prints simulated seconds per wall
//! second for several step sizes (each step also reads the status registers, as a polling
//! client would) and the process's memory use. Run with
//! `cargo run --release --bin bench_sim`.

use plcsh::core::{Clock, Device, OperandSpace};
use plcsh::k2::helpers::{self, hsc as hh, pto as hp};
use plcsh::k2::sim::inputs::{Source, Wave};
use plcsh::k2::sim::{self, K2Sim};
use plcsh::k2::sm_map::{self, PTO_REGS};
use plcsh::k2::{catalog, K2Ops};
use std::time::{Duration, Instant};

const HOUR: Duration = Duration::from_secs(3600);

/// Sets every channel running: PTOs at full speed for longer than an hour, counters
/// counting (multi-PV relative cyclic tables with `pv` counts between events).
fn setup(model: &str, pv: i32) -> (K2Sim, Clock) {
    let clock = Clock::stepped();
    let mut s = sim::open(model, clock.clone()).unwrap();
    let m = s.model();
    for p in m.pto {
        let cycle = 1_000_000u64.div_ceil(p.max_hz as u64);
        let count = HOUR.as_secs() * 1_000_000 / cycle + 1000;
        let plan = hp::plan_pto(m, p.channel, hp::Rate::CycleUs(cycle), count).unwrap();
        helpers::execute(&mut s, &plan).unwrap();
    }
    for (k, h) in m.hsc.iter().enumerate() {
        let q = hh::HscRequest {
            counter: h.channel,
            mode: 0,
            pv: vec![pv; 3],
            relative: true,
            cyclic: true,
            at: Some(1 + 16 * k as u32),
            ..Default::default()
        };
        let plan = hh::plan(m, &q, s.backup_area()).unwrap();
        helpers::execute(&mut s, &plan).unwrap();
        let pin = sm_map::hsc_mode(h.channel, 0).unwrap().count;
        s.add_source(Source::Freq { pin, wave: Wave::new(h.max_hz_single as u64, Duration::ZERO) }).unwrap();
    }
    (s, clock)
}

fn mem_kb(field: &str) -> u64 {
    std::fs::read_to_string("/proc/self/status")
        .ok()
        .and_then(|t| {
            t.lines()
                .find(|l| l.starts_with(field))
                .and_then(|l| l.split_whitespace().nth(1).and_then(|n| n.parse().ok()))
        })
        .unwrap_or(0)
}

fn run(model: &str, pv: i32, step: Duration) {
    let (mut s, clock) = setup(model, pv);
    let polls: Vec<_> = PTO_REGS
        .iter()
        .take(s.model().pto.len())
        .map(|r| s.space().parse(&format!("SMB{}", r.status)).unwrap()[0])
        .chain(
            s.model()
                .hsc
                .iter()
                .map(|h| s.space().parse(&format!("SMD{}", sm_map::HSC_REGS[h.channel as usize].cv)).unwrap()[0]),
        )
        .collect();
    let steps = (HOUR.as_nanos() / step.as_nanos()) as u64;
    // A poll reads into one buffer, as `sim serve` answers a Modbus client's poll: a copy into
    // the reply it reuses, no allocation per poll.
    let mut values = Vec::with_capacity(polls.len());
    let t = Instant::now();
    for _ in 0..steps {
        clock.step(step);
        s.read_into(&polls, &mut values).unwrap();
        std::hint::black_box(&values);
    }
    let wall = t.elapsed();
    let ratio = HOUR.as_secs_f64() / wall.as_secs_f64();
    let pulses: u64 = s.pto.iter().map(|p| p.train().map_or(0, |t| t.pulses_at(s.last))).sum();
    let counts: i64 = s.hsc.iter().map(|h| h.cv()).sum();
    println!(
        "{model:<12} pv={pv:<9} step={:>9?} steps={steps:>8} wall={:>10.3?} → {ratio:>14.0}× real time  pulses={pulses} counts={counts} events={} (kept {})",
        step,
        wall,
        s.events.total(),
        s.events.len()
    );
    s.backup.path = None;
}

fn main() {
    // BENCH_ONLY=K204ET-16DT,10 runs one scenario (model, step in ms) — for callgrind.
    if let Some((m, ms)) = std::env::var("BENCH_ONLY").ok().as_deref().and_then(|v| v.split_once(',')) {
        run(m, 1_000_000, Duration::from_millis(ms.parse().unwrap_or(10)));
        return;
    }
    println!(
        "one simulated hour, every pulse channel at maximum frequency, every counter counting at maximum frequency"
    );
    for m in catalog::MODELS.iter().filter(|m| !m.relay) {
        for step in [HOUR, Duration::from_secs(1), Duration::from_millis(100), Duration::from_millis(10)] {
            run(m.name, 1_000_000, step);
        }
    }
    println!("\nevent-heavy: PVs 1000 apart (200 CV = PV events per second per counter at 200 kHz)");
    for step in [HOUR, Duration::from_secs(1), Duration::from_millis(100), Duration::from_millis(10)] {
        run("K204ET-16DT", 1000, step);
    }
    println!("\nmemory: VmRSS {} kB, VmHWM {} kB", mem_kb("VmRSS:"), mem_kb("VmHWM:"));
}
