//! Wired-machine benchmark (not a test): a K2 whose PTO0 drives a simulated Kinco servo in
//! pulse-train mode (gear 4) for one simulated hour of continuous motion at PTO0's maximum
//! frequency, the servo's encoder output wired back to HSC0 (A/B, 4x), polled in 100 ms
//! steps as a client would: each step reads HSC0's count and PTO0's position counter, and
//! (second run) also the drive's actual position over its serial protocol. Prints simulated
//! seconds per wall second and checks the counts against the arithmetic. Run with
//! `cargo run --release --bin bench_wired` (`-- plc` or `-- drive` for one case, e.g. under callgrind).

use plcsh::core::{Clock, Operand};
use plcsh::k2::helpers::{self, hsc as hh, pto as hp};
use plcsh::k2::K2Ops;
use plcsh::session::{Session, SetItem};
use std::time::{Duration, Instant};

const HOUR: Duration = Duration::from_secs(3600);

fn set(s: &mut Session, item: &str) {
    let (op, v) = item.split_once('=').unwrap();
    s.set(&[SetItem { operand: op.into(), value: v.into(), column: 0, value_column: 0 }]).unwrap();
}

/// The machine, running: returns the session, its clock and the pulse rate.
fn machine() -> (Session, Clock, u64) {
    let clock = Clock::stepped();
    let mut s = Session::new(clock.clone());
    s.open("plc", "sim:K205-16DT").unwrap();
    s.open("servo", "sim-servo:?id=1").unwrap();
    for it in [
        "servo:gear_factor=4",
        "servo:operating_mode=-4",
        "servo:controlword=6",
        "servo:controlword=7",
        "servo:controlword=15",
    ] {
        set(&mut s, it);
    }
    plcsh::wiring::setup::wire(&mut s, "plc:Q0.0 -> servo:pulse").unwrap();
    plcsh::wiring::setup::wire(&mut s, "servo:encoder -> plc:I0.1,I0.0 lines=1250").unwrap();
    let dev = s.device("plc").unwrap().as_mut();
    let m = plcsh::k2::ops(dev).unwrap().model();
    let q = hh::HscRequest { counter: 0, mode: 9, rate4x: true, pv: vec![1_000_000_000], ..Default::default() };
    let backup = plcsh::k2::ops(dev).unwrap().backup_area();
    helpers::execute(dev, &hh::plan(m, &q, backup).unwrap()).unwrap();
    let p = &m.pto[0];
    let cycle = 1_000_000u64.div_ceil(p.max_hz as u64);
    let count = HOUR.as_secs() * 1_000_000 / cycle + 1000;
    helpers::execute(dev, &hp::plan_pto(m, 0, hp::Rate::CycleUs(cycle), count).unwrap()).unwrap();
    (s, clock, 1_000_000 / cycle)
}

fn run(with_drive: bool) {
    let (mut s, clock, hz) = machine();
    let step = Duration::from_millis(100);
    let plc: Vec<Operand> =
        ["SMD38", "SMD212"].iter().map(|t| s.resolve(&format!("plc:{t}")).unwrap().ops[0]).collect();
    let servo = s.resolve("servo:position_actual").unwrap().ops[0];
    let (pi, si) = (s.index("plc").unwrap(), s.index("servo").unwrap());
    let steps = (HOUR.as_nanos() / step.as_nanos()) as u64;
    let cpu0 = cpu_time();
    let t = Instant::now();
    for _ in 0..steps {
        clock.step(step);
        std::hint::black_box(s.entry(pi).device.read(&plc).unwrap());
        if with_drive {
            std::hint::black_box(s.entry(si).device.read(&[servo]).unwrap());
        }
    }
    let wall = t.elapsed();
    let cpu = cpu_time() - cpu0;
    let v = s.entry(pi).device.read(&plc).unwrap();
    let pos = s.entry(si).device.read(&[servo]).unwrap()[0].as_i64();
    let (cv, pulses) = (v[0].as_i64(), v[1].as_i64());
    // One hour at `hz`: pulses × gear 4 increments; × 5000/10000 counts.
    let want = hz as i64 * 3600;
    let ok = pulses == want && pos == 4 * want && cv == 2 * want;
    println!(
        "{:<42} steps={steps} wall={wall:>9.3?} → {:>7.0}× real time; thread CPU {cpu:>9.3?} → {:>7.0}×  pulses={pulses} increments={pos} counts={cv} {}",
        if with_drive { "poll PLC (2 registers) + drive (1 object)" } else { "poll PLC (2 registers)" },
        HOUR.as_secs_f64() / wall.as_secs_f64(),
        HOUR.as_secs_f64() / cpu.as_secs_f64(),
        if ok { "(exact)" } else { "(MISMATCH)" }
    );
}

/// CPU time this thread has used (the machine may be loaded by other work: CPU time is what
/// the simulation itself cost).
fn cpu_time() -> Duration {
    plcsh::core::platform::thread_cpu_time()
}

fn main() {
    println!("one simulated hour of continuous motion at PTO0's maximum frequency, polled every 100 ms");
    // `plc` or `drive` runs that case once (for callgrind); nothing runs both three times.
    match std::env::args().nth(1).as_deref() {
        Some("plc") => run(false),
        Some("drive") => run(true),
        _ => {
            for _ in 0..3 {
                run(false);
                run(true);
            }
        }
    }
}
