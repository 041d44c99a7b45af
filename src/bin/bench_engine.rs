//! Scan-engine benchmark (not a test). Run with `cargo run --release --bin bench_engine`.
//!
//! 1. Raw interpreter speed: a 1000-instruction program of simple bit and word
//!    instructions (LD/AND/OR/ST, MOVE, compare, ADD) executed scan after scan against the
//!    K2's memory image, without the scan cycle around it: IL instructions per second.
//! 2. One simulated hour of a K205-16DT running the helper program (`lib/k2_agent.il`) plus
//!    a 1000-instruction user program at its modelled scan time, the clock stepped in 10 ms
//!    steps with a status read per step (as a polling client would): wall time, scans,
//!    instructions, memory.
//! 3. The helper's own cost per catalogue model (`plcsh agent il --model`): the
//!    instructions of an idle scan, the modelled scan time (cost table), and the wall time
//!    per simulated scan, the helper alone.

use plcsh::core::{Clock, Device, OperandSpace};
use plcsh::engine::Cpu;
use plcsh::k2::agent::protocol::DEFAULT_BASE;
use plcsh::k2::sim::{self, program::family::K2Machine};
use std::time::{Duration, Instant};

/// 1000 instructions: 100 blocks of 10 simple bit/word instructions.
fn user_program() -> String {
    let mut s = String::new();
    for k in 0..100 {
        let (b, w) = (k % 50, 2 * (k % 100));
        s.push_str(&format!(
            "LD %I0.{i}\nAND %M{b}.1\nOR %M{b}.2\nST %Q0.{q}\nLD %SM0.0\nMOVE %VW{w}, %VW{w2}\nLDW> %VW{w}, 100\nAN %M{b}.3\nST %M{b}.4\nADD 1, %VW{w3}\n",
            i = k % 8,
            q = k % 6,
            w2 = w + 400,
            w3 = w + 800
        ));
    }
    s
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

fn raw_speed() {
    let clock = Clock::stepped();
    let mut s = sim::open("K205-16DT", clock).unwrap();
    let prog = s.compile(&user_program(), "bench.il").unwrap();
    let mut cpu = Cpu::new(&prog);
    let mut inst = Vec::new();
    let scans = std::env::var("BENCH_SCANS").ok().and_then(|v| v.parse().ok()).unwrap_or(200_000u64);
    let t = Instant::now();
    let mut n = 0u64;
    for k in 0..scans {
        let mut m = K2Machine { sim: &mut s, now: Duration::ZERO, inst: &mut inst, raised: Vec::new() };
        n += cpu.scan(&prog, &mut m, k * 1_000_000, u64::MAX, None).instructions;
    }
    let wall = t.elapsed();
    println!(
        "raw interpreter: {n} instructions in {wall:.3?} → {:.1} million IL instructions/s ({} per scan)",
        n as f64 / wall.as_secs_f64() / 1e6,
        n / scans
    );
}

fn hour() {
    let clock = Clock::stepped();
    let mut s = sim::open("K205-16DT", clock.clone()).unwrap();
    s.enable_agent(DEFAULT_BASE).unwrap();
    // BENCH_HELPER=FILE runs another helper text (an older one, to compare on one machine).
    if let Ok(path) = std::env::var("BENCH_HELPER") {
        let text = std::fs::read_to_string(&path).unwrap();
        s.load_helper(&text, &path).unwrap();
    }
    s.load_program(&user_program(), "user.il").unwrap();
    let polls = s.space().parse("SMB66").unwrap();
    // BENCH_SECONDS shortens the run (for callgrind).
    let secs = std::env::var("BENCH_SECONDS").ok().and_then(|v| v.parse().ok()).unwrap_or(3600);
    let hour = Duration::from_secs(secs);
    let step = Duration::from_millis(10);
    let t = Instant::now();
    for _ in 0..(hour.as_millis() / step.as_millis()) {
        clock.step(step);
        std::hint::black_box(s.read(&polls).unwrap());
    }
    let wall = t.elapsed();
    let p = s.plc().unwrap();
    println!(
        "{secs} simulated s, helper + 1000-instruction program: wall {wall:.2?} ({:.0}× real time); {} scans of {:.3} ms; {} instructions ({:.1} M/s)",
        hour.as_secs_f64() / wall.as_secs_f64(),
        p.stats.scans,
        p.stats.last_ns as f64 / 1e6,
        p.stats.total_instructions,
        p.stats.total_instructions as f64 / wall.as_secs_f64() / 1e6
    );
    s.backup.path = None;
}

/// The helper alone on every model: idle scans (no request), then one SM read per scan.
fn helper_cost() {
    for model in plcsh::k2::catalog::MODELS {
        let clock = Clock::stepped();
        let mut s = sim::open(model.name, clock.clone()).unwrap();
        s.enable_agent(DEFAULT_BASE).unwrap();
        clock.step(Duration::from_millis(10));
        s.advance();
        let (scans0, n0) = s.plc().map(|p| (p.stats.scans, p.stats.total_instructions)).unwrap();
        let t = Instant::now();
        clock.step(Duration::from_secs(60));
        s.advance();
        let wall = t.elapsed();
        let p = s.plc().unwrap();
        let scans = p.stats.scans - scans0;
        println!(
            "helper alone on {}: {} instructions per idle scan, modelled scan {:.3} ms (cost table), {:.2} µs wall per scan",
            model.name,
            (p.stats.total_instructions - n0) / scans.max(1),
            p.stats.last_ns as f64 / 1e6,
            wall.as_secs_f64() * 1e6 / scans.max(1) as f64
        );
        s.backup.path = None;
    }
}

fn main() {
    raw_speed();
    hour();
    helper_cost();
    println!("memory: VmRSS {} kB, VmHWM {} kB", mem_kb("VmRSS:"), mem_kb("VmHWM:"));
}
