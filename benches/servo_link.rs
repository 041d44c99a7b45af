//! Servo link benchmark (not part of `cargo test`): request/reply turnaround of the Kinco
//! driver over a pseudo-terminal against the simulator served by the real binary
//! (`plcsh sim serve --servo-pty`), next to the wire-time floor of a real RS232 line.
//!
//! Run: `cargo bench --bench servo_link`. A pty has no baud-rate pacing of its own: bytes
//! cross it at memory speed whatever baud rate the client sets. So the simulator paces its
//! replies like a line (`--servo-baud`, `--servo-latency`, the served default) — the paced
//! rows show what a client sees from a realistic drive — and `--servo-instant` turns pacing
//! off, so those rows measure the software path (driver + kernel pty + simulator process).

use plcsh::core::{Clock, Device};
use plcsh::session::open_url;
use std::io::{BufRead, BufReader};
use std::process::{Command, Stdio};
use std::time::{Duration, Instant};

const N: usize = 5000;
/// Paced requests take ≥ 5.2 ms each at 38400 baud: fewer of them.
const N_PACED: usize = 300;

fn floor(baud: u32) -> Duration {
    // 10 bytes × 10 bits (start + 8 data + stop) each way.
    Duration::from_secs_f64(2.0 * 10.0 * 10.0 / baud as f64)
}

fn percentile(sorted: &[Duration], p: f64) -> Duration {
    sorted[((sorted.len() as f64 - 1.0) * p).round() as usize]
}

fn run(label: &str, d: &mut dyn Device, op_name: &str) {
    run_n(label, d, op_name, N)
}

fn run_n(label: &str, d: &mut dyn Device, op_name: &str, n: usize) {
    let op = d.operands().parse(op_name).unwrap()[0];
    for _ in 0..n.min(200) / 10 {
        d.read(&[op]).unwrap();
    }
    let mut each = Vec::with_capacity(n);
    let start = Instant::now();
    for _ in 0..n {
        let t = Instant::now();
        d.read(&[op]).unwrap();
        each.push(t.elapsed());
    }
    let total = start.elapsed();
    each.sort();
    let tx = n as f64 / total.as_secs_f64();
    println!(
        "{label:<34} {tx:>9.0} req/s {:>9.0} frames/s   turnaround mean {:>7.1} µs  p50 {:>7.1} µs  p99 {:>7.1} µs  max {:>8.1} µs",
        2.0 * tx,
        total.as_secs_f64() * 1e6 / n as f64,
        percentile(&each, 0.5).as_secs_f64() * 1e6,
        percentile(&each, 0.99).as_secs_f64() * 1e6,
        each[each.len() - 1].as_secs_f64() * 1e6,
    );
}

/// Starts `plcsh sim serve` with the servo line at `link`, plus `extra` flags.
fn serve(link: &std::path::Path, extra: &[&str]) -> std::process::Child {
    let mut child = Command::new(env!("CARGO_BIN_EXE_plcsh"))
        .args(["sim", "serve", "--servo-pty", link.to_str().unwrap(), "--servo-id", "1"])
        .args(extra)
        .stdout(Stdio::piped())
        .spawn()
        .expect("start plcsh sim serve");
    let mut ready = String::new();
    BufReader::new(child.stdout.take().unwrap()).read_line(&mut ready).unwrap();
    println!("served simulator: {}", ready.trim());
    child
}

fn stop(mut child: std::process::Child) {
    plcsh::core::platform::terminate_child(&child);
    let _ = child.wait();
}

/// The pattern of a public C++ driver: send, then clear the input buffer at once, then read.
/// Returns how many of `n` replies were lost to the clear.
fn clear_after_send_losses(link: &std::path::Path, n: usize) -> usize {
    use std::io::{Read, Write};
    let mut p = serialport::new(link.to_str().unwrap(), 38_400).timeout(Duration::from_millis(100)).open().unwrap();
    let req = [0x01, 0x40, 0x41, 0x60, 0x00, 0x00, 0x00, 0x00, 0x00, 0x1E];
    let mut lost = 0;
    for _ in 0..n {
        p.write_all(&req).unwrap();
        p.clear(serialport::ClearBuffer::Input).unwrap();
        let mut got = [0u8; 10];
        let mut k = 0;
        while k < 10 {
            match p.read(&mut got[k..]) {
                Ok(m) => k += m,
                Err(_) => break,
            }
        }
        if k < 10 {
            lost += 1;
            let _ = p.clear(serialport::ClearBuffer::Input);
        }
    }
    lost
}

fn main() {
    let dir = std::env::temp_dir().join(format!("plcsh-servo-bench-{}", std::process::id()));
    std::fs::create_dir_all(&dir).unwrap();
    // Paced, as served drives answer by default: 38400 baud, 1 ms think-time; and with no
    // think-time (the wire alone).
    for (tag, extra) in
        [("paced", &["--servo-baud", "38400", "--servo-latency", "1ms"][..]), ("wire", &["--servo-latency", "0"][..])]
    {
        let link = dir.join(format!("ttyKINCO-{tag}"));
        let child = serve(&link, extra);
        let mut d = open_url(&format!("kinco:{}?id=1", link.display()), &Clock::following()).unwrap();
        run_n(&format!("pty + served sim, {tag} 38400"), d.as_mut(), "statusword", N_PACED);
        drop(d);
        stop(child);
    }
    let mut d = open_url("sim-servo:?id=1&baud=38400&latency=0", &Clock::following()).unwrap();
    run_n("in-process sim-servo, paced 38400", d.as_mut(), "statusword", N_PACED);
    drop(d);
    // Replies lost by a client that clears its input right after sending.
    for (tag, extra) in [("paced 38400", &["--servo-latency", "0"][..]), ("instant", &["--servo-instant"][..])] {
        let link = dir.join(format!("ttyKINCO-clear-{}", tag.replace(' ', "-")));
        let child = serve(&link, extra);
        let n = 1000;
        let lost = clear_after_send_losses(&link, n);
        println!(
            "clear-after-send client, {tag:<12} lost {lost} of {n} replies ({:.1} %)",
            lost as f64 * 100.0 / n as f64
        );
        stop(child);
    }
    let link = dir.join("ttyKINCO");
    let mut child = serve(&link, &["--servo-instant"]);
    println!("{N} statusword reads (one 10-byte request + one 10-byte reply each)\n");
    for baud in [38_400u32, 115_200] {
        let f = floor(baud);
        println!(
            "{:<34} {:>9.0} req/s {:>9.0} frames/s   turnaround floor {:>7.1} µs (wire time only)",
            format!("RS232 wire floor @ {baud}"),
            1.0 / f.as_secs_f64(),
            2.0 / f.as_secs_f64(),
            f.as_secs_f64() * 1e6
        );
    }
    for baud in [38_400u32, 115_200] {
        let url = format!("kinco:{}?id=1&baud={baud}", link.display());
        let mut d = open_url(&url, &Clock::following()).unwrap();
        run(&format!("pty + served sim (baud={baud} set)"), d.as_mut(), "statusword");
        run(&format!("  same, 32-bit object (baud={baud})"), d.as_mut(), "position_actual");
    }
    let mut d = open_url("sim-servo:?id=1", &Clock::following()).unwrap();
    run("in-process sim-servo (no pty)", d.as_mut(), "statusword");
    println!("\nnote: instant rows are software cost; paced rows include the simulated wire and think-time.");
    let _ = &mut child;
    stop(child);
    let _ = std::fs::remove_dir_all(&dir);
}
