//! What recording costs (`--record`): Modbus client transactions per second against the
//! simulator served over loopback TCP, with and without a recording running, measured in
//! one process in interleaved rounds so machine load affects both alike; prints the ratio.
//!
//! Usage: `bench_record [--rounds R] [--count N]` (default 10 rounds of 2000 reads each way).

use plcsh::core::url::DeviceUrl;
use plcsh::core::{Clock, Device};
use plcsh::k2::sim::modbus_server::{serve_tcp, K2Service};
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
            serve_tcp(l, service).await.unwrap();
        })
    });
    let addr = rx.recv().unwrap();
    let url = DeviceUrl::parse(&format!("tcp://{addr}?model=K205-16DT")).unwrap();
    let mut dev = plcsh::k2::open_wire(&url).unwrap();
    let ops = dev.operands().parse("VW100").unwrap();
    let file = std::env::temp_dir().join(format!("plcsh-bench-record-{}.pcapng", std::process::id()));
    let (mut plain, mut recorded) = (0.0f64, 0.0f64);
    let run = |dev: &mut Box<dyn Device>| {
        let t = Instant::now();
        for _ in 0..count {
            dev.read(&ops).unwrap();
        }
        t.elapsed().as_secs_f64()
    };
    run(&mut dev); // warm up
    for _ in 0..rounds {
        plain += run(&mut dev);
        plcsh::record::start(&file, Clock::following()).unwrap();
        recorded += run(&mut dev);
        plcsh::record::stop().unwrap();
    }
    let n = (rounds * count) as f64;
    let (a, b) = (n / plain, n / recorded);
    println!("transactions/s without recording: {a:.0}");
    println!("transactions/s while recording:   {b:.0}");
    println!(
        "recording costs {:.1} % ({} rounds × {count} reads of VW100, interleaved)",
        (a / b - 1.0) * 100.0,
        rounds
    );
    let _ = std::fs::remove_file(&file);
}
