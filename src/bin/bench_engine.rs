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
//!    per simulated scan, the helper alone; then the instructions and modelled time of the
//!    scan that serves an SM read, an SM write and a PLS (`BENCH_ONLY=helper`).

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

/// The helper's scans on `s`, `n` of them, with `request(ack 0's sequence)` written into the
/// mailbox before each (a request block; `None`: nothing): instructions per scan, those of the
/// busiest scan, wall time per scan (µs) and the busiest scan's modelled time (ns).
fn helper_scans(
    s: &mut sim::K2Sim,
    clock: &Clock,
    n: u64,
    mut request: impl FnMut(u16) -> Option<Vec<u16>>,
) -> (u64, u64, f64, u64) {
    use plcsh::k2::agent::protocol::{OFF_ACKS, OFF_REQUEST};
    use plcsh::k2::operand::{Area, K2Operand};
    let (scans0, n0) = s.plc().map(|p| (p.stats.scans, p.stats.total_instructions)).unwrap();
    let t = Instant::now();
    let mut max = (0, 0);
    for _ in 0..n {
        let ack = s.mem.read(&K2Operand::word(Area::V, DEFAULT_BASE + OFF_ACKS)) as u16;
        if let Some(words) = request(ack) {
            for (i, w) in words.iter().enumerate() {
                s.mem.write(&K2Operand::word(Area::V, DEFAULT_BASE + OFF_REQUEST + 2 * i as u32), *w as u32);
            }
        }
        let next = s.plc().unwrap().next_scan;
        clock.step(next.saturating_sub(clock.now()).max(Duration::from_nanos(1)));
        s.advance();
        let st = s.plc().unwrap().stats;
        if st.last_instructions > max.0 {
            max = (st.last_instructions, st.last_ns);
        }
    }
    let wall = t.elapsed();
    let p = s.plc().unwrap();
    let scans = (p.stats.scans - scans0).max(1);
    ((p.stats.total_instructions - n0) / scans, max.0, wall.as_secs_f64() * 1e6 / scans as f64, max.1)
}

/// The helper alone on every model: idle scans (no request); then scans serving a request,
/// one after the other (each acknowledged before the next is written): an SM read of the
/// first pulse channel's registers (command 2), an SM write of its cycle time (command 1),
/// and PLS on its channel with the enable bit clear (command 3: nothing to do, nothing
/// moves). The busiest scan is the one that executes the request.
fn helper_cost() {
    use plcsh::k2::agent::protocol::{next_seq, request_words, Command};
    for model in plcsh::k2::catalog::MODELS {
        let clock = Clock::stepped();
        let mut s = sim::open(model.name, clock.clone()).unwrap();
        s.enable_agent(DEFAULT_BASE).unwrap();
        clock.step(Duration::from_millis(10));
        s.advance();
        let (idle, _, wall, ns) = helper_scans(&mut s, &clock, 20_000, |_| None);
        let mut row = format!(
            "helper alone on {}: {idle} instructions per idle scan, modelled scan {:.3} ms (cost table), {wall:.2} µs wall per scan",
            model.name,
            ns as f64 / 1e6
        );
        let ch = model.pto.first().map(|c| c.channel);
        let cmds: Vec<(&str, Command)> = match ch {
            Some(c) => {
                let r = plcsh::k2::sm_map::PTO_REGS[c as usize];
                vec![
                    ("SM read", Command::SmRead { start: r.status as u16, len: 10 }),
                    ("SM write", Command::SmWrite { start: r.cycle as u16, data: vec![0x01, 0xF4] }),
                    ("PLS", Command::Pls(c)),
                ]
            }
            None => vec![("SM read", Command::SmRead { start: 36, len: 10 })],
        };
        for (what, cmd) in cmds {
            // A new request whenever the last one is acknowledged; the busiest scan executes it.
            let mut sent: Option<u16> = None;
            let (_, busiest, _, ns) = helper_scans(&mut s, &clock, 40, |ack| {
                sent.is_none_or(|s| s == ack).then(|| {
                    let seq = next_seq(ack);
                    sent = Some(seq);
                    request_words(seq, 0x5A5A, &cmd)
                })
            });
            row.push_str(&format!("; serving {what}: {busiest} instructions, {:.3} ms", ns as f64 / 1e6));
        }
        println!("{row}");
        s.backup.path = None;
    }
}

fn main() {
    // BENCH_ONLY=raw|hour|helper runs one part (callgrind counts one part at a time).
    let only = std::env::var("BENCH_ONLY").unwrap_or_default();
    let run = |part: &str| only.is_empty() || only == part;
    if run("raw") {
        raw_speed();
    }
    if run("hour") {
        hour();
    }
    if run("helper") {
        helper_cost();
    }
    println!("memory: VmRSS {} kB, VmHWM {} kB", mem_kb("VmRSS:"), mem_kb("VmHWM:"));
}
