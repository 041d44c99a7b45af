//! What recording costs (`--record`): Modbus client transactions per second against the
//! simulator served over loopback TCP, with and without a recording running, measured in
//! one process in interleaved rounds so machine load affects both alike; prints the ratio.
//!
//! Usage: `bench_record [--rounds R] [--count N]` (default 10 rounds of 2000 reads each way).
//! Also times the recorder alone (frames handed to it directly), which load disturbs less.

use plcsh::core::trace::{self, Dir, Proto};
use plcsh::core::url::DeviceUrl;
use plcsh::core::{Clock, Device};
use plcsh::k2::sim::modbus_net::serve_tcp;
use plcsh::k2::sim::modbus_server::K2Service;
use std::sync::{Arc, Mutex};
use std::time::Instant;

fn arg(name: &str, default: usize) -> usize {
    let a: Vec<String> = std::env::args().collect();
    a.iter().position(|x| x == name).and_then(|i| a.get(i + 1)).and_then(|v| v.parse().ok()).unwrap_or(default)
}

fn main() {
    let rounds = arg("--rounds", 10);
    let count = arg("--count", 2000);
    let sim = plcsh::k2::sim::open("K205-16DT", Clock::following()).expect("model");
    let service = K2Service::new(Arc::new(Mutex::new(sim)), 1);
    let (tx, rx) = std::sync::mpsc::channel();
    std::thread::spawn(move || {
        let rt = tokio::runtime::Builder::new_current_thread().enable_all().build().unwrap();
        rt.block_on(async move {
            let l = tokio::net::TcpListener::bind("127.0.0.1:0").await.unwrap();
            tx.send(l.local_addr().unwrap()).unwrap();
            serve_tcp(l, service, Default::default()).await.unwrap();
        })
    });
    let addr = rx.recv().unwrap();
    let url = DeviceUrl::parse(&format!("tcp://{addr}?model=K205-16DT")).unwrap();
    let mut dev = plcsh::k2::open_wire(&url).unwrap();
    let ops = dev.operands().parse("VW100").unwrap();
    let file = std::env::temp_dir().join(format!("plcsh-bench-record-{}.pcapng", std::process::id()));
    let (mut plain, mut recorded) = (0.0f64, 0.0f64);
    let mut ratios = Vec::new();
    let run = |dev: &mut Box<dyn Device>| {
        let t = Instant::now();
        for _ in 0..count {
            dev.read(&ops).unwrap();
        }
        t.elapsed().as_secs_f64()
    };
    run(&mut dev); // warm up
    for _ in 0..rounds {
        let a = run(&mut dev);
        plcsh::record::start(&file, Clock::following()).unwrap();
        let b = run(&mut dev);
        plcsh::record::stop().unwrap();
        plain += a;
        recorded += b;
        ratios.push(b / a);
    }
    ratios.sort_by(f64::total_cmp);
    let median = ratios[ratios.len() / 2];
    let n = (rounds * count) as f64;
    let (a, b) = (n / plain, n / recorded);
    println!("transactions/s without recording: {a:.0}");
    println!("transactions/s while recording:   {b:.0}");
    println!(
        "recording costs {:.1} % overall, {:.1} % in the median round ({rounds} rounds × {count} reads of VW100, interleaved)",
        (a / b - 1.0) * 100.0,
        (median - 1.0) * 100.0,
    );
    // The recorder alone: one request and one reply frame per iteration, no I/O but the file.
    plcsh::record::start(&file, Clock::following()).unwrap();
    let req = [0u8, 1, 0, 0, 0, 6, 1, 3, 0, 150, 0, 1];
    let rep = [0u8, 1, 0, 0, 0, 5, 1, 3, 2, 0, 7];
    let n = 200_000;
    let t = Instant::now();
    for _ in 0..n {
        trace::frame_proto("tcp://127.0.0.1:502?unit=1&model=K205-16DT", Proto::ModbusTcp, Dir::Sent, &req);
        trace::frame_proto("tcp://127.0.0.1:502?unit=1&model=K205-16DT", Proto::ModbusTcp, Dir::Received, &rep);
    }
    let per = t.elapsed().as_secs_f64() / n as f64 * 1e6;
    plcsh::record::stop().unwrap();
    println!(
        "recorder alone: {per:.2} µs per request/reply pair = {:.1} % of a {:.1} µs transaction",
        per / (1e6 / a) * 100.0,
        1e6 / a
    );
    let _ = std::fs::remove_file(&file);
}
