//! The Modbus benchmark: plcsh's wire driver and simulator server side by
//! side with libmodbus (C), pymodbus and mbpoll, over loopback TCP and RTU on a pty, with the
//! 12-byte echo round trip as the floor. Run it through `bench/run.sh`, which installs the
//! peers (Debian `libmodbus-dev`, `mbpoll`; PyPI `pymodbus`) and builds the C programs in
//! `bench/c`; it is not part of `cargo test` or CI (slow, installs packages).
//!
//! Every loop is bounded (a count and a time), one request is in flight, and every address is
//! on 127.0.0.1 or a pseudo-terminal. Servers are waited for through their readiness lines.
//!
//! Usage: `bench_modbus [--seconds S] [--count N] [--runs R] [--peers DIR] [--py DIR] [--plcsh EXE]
//! [--plcsh-dynamic EXE]` (`--peers`: the built C programs, default `target/bench`; `--py`:
//! `bench/py`; `--plcsh`: the plcsh measured as a server and one-shot, default the one beside
//! this program; `--plcsh-dynamic`: the default dynamically linked build, shown beside it in the
//! one-shot table, default also the one beside this program. `bench/run.sh` gives copies of the
//! static build, `cargo build-static`, and of the default build).
//!
//! `bench_modbus transactions URL REGS N` reads REGS words from VW0 N times after one warm-up
//! read, with no timing: `bench/callgrind.sh` runs it under callgrind to count the driver's
//! instructions per transaction.

use plcsh::core::Clock;
use serde_json::Value as Json;
use std::io::{BufRead, BufReader, Read};
use std::path::{Path, PathBuf};
use std::process::{Child, Command, Stdio};
use std::time::{Duration, Instant};

/// One measured series.
#[derive(Clone, Debug, Default)]
struct Fig {
    n: f64,
    secs: f64,
    p50: Option<f64>,
    p99: Option<f64>,
}

impl Fig {
    fn rate(&self) -> f64 {
        if self.secs > 0.0 {
            self.n / self.secs
        } else {
            0.0
        }
    }
    fn from_json(j: &Json) -> Option<Fig> {
        Some(Fig {
            n: j["n"].as_f64()?,
            secs: j["secs"].as_f64()?,
            p50: j["p50_us"].as_f64(),
            p99: j["p99_us"].as_f64(),
        })
    }
    fn from_latencies(mut lat: Vec<f64>, secs: f64) -> Fig {
        lat.sort_by(f64::total_cmp);
        let n = lat.len();
        Fig { n: n as f64, secs, p50: lat.get(n / 2).map(|s| s * 1e6), p99: lat.get(n * 99 / 100).map(|s| s * 1e6) }
    }
}

struct Opts {
    /// Each throughput figure is the best of this many interleaved runs ([`group`]).
    rounds: usize,
    seconds: f64,
    count: u64,
    runs: usize,
    peers: PathBuf,
    py: PathBuf,
    plcsh: PathBuf,
    /// The default, dynamically linked build, shown beside `plcsh` in the one-shot table.
    plcsh_dynamic: PathBuf,
}

/// A server process, killed on drop.
struct Server {
    child: Child,
    ready: Json,
}

impl Server {
    /// Starts `cmd` and waits for its first stdout line (a JSON readiness line).
    fn start(name: &'static str, mut cmd: Command) -> Option<Server> {
        let mut child = cmd.stdout(Stdio::piped()).stderr(Stdio::null()).spawn().ok()?;
        let mut line = String::new();
        BufReader::new(child.stdout.take()?).read_line(&mut line).ok()?;
        match serde_json::from_str(&line) {
            Ok(ready) => Some(Server { child, ready }),
            Err(_) => {
                eprintln!("{name}: no readiness line (got {line:?}); left out of the tables");
                let _ = child.kill();
                None
            }
        }
    }
    fn field(&self, k: &str) -> String {
        self.ready[k].as_str().unwrap_or_default().to_string()
    }
}

impl Drop for Server {
    fn drop(&mut self) {
        let _ = self.child.kill();
        let _ = self.child.wait();
    }
}

/// One thing to measure: a peer program printing a JSON figure, plcsh's driver in
/// process, or mbpoll (which only polls, so it is run once and its polls counted).
#[derive(Clone)]
enum Job {
    Peer(PathBuf, Vec<String>),
    Driver(String, usize),
    Mbpoll(Vec<String>, usize),
    Missing,
}

fn job(program: &Path, args: &[&str]) -> Job {
    Job::Peer(program.to_path_buf(), args.iter().map(|a| a.to_string()).collect())
}

fn py_job(o: &Opts, script: &str, args: &[&str]) -> Job {
    let mut a = vec![o.py.join(script).to_string_lossy().to_string()];
    a.extend(args.iter().map(|s| s.to_string()));
    Job::Peer(PathBuf::from("python3"), a)
}

fn run_once(o: &Opts, j: &Job) -> Option<Fig> {
    match j {
        Job::Peer(p, a) => {
            let mut c = Command::new(p);
            c.args(a);
            peer_once(c)
        }
        Job::Driver(url, regs) => plcsh_driver_once(o, url, *regs),
        Job::Mbpoll(a, regs) => mbpoll_rate(o, a, *regs),
        Job::Missing => None,
    }
}

/// Measures a group of contenders round-robin, `rounds` times, keeping each one's best run:
/// load from elsewhere on the machine only ever slows a run down, and interleaving gives
/// every contender the same chance at a quiet moment.
fn group(o: &Opts, jobs: &[Job]) -> Vec<Option<Fig>> {
    let mut best: Vec<Option<Fig>> = vec![None; jobs.len()];
    for round in 0..o.rounds.max(1) {
        for (k, j) in jobs.iter().enumerate() {
            if round > 0 && matches!(j, Job::Mbpoll(..)) {
                continue;
            }
            if let Some(f) = run_once(o, j) {
                if best[k].as_ref().is_none_or(|b| f.rate() > b.rate()) {
                    best[k] = Some(f);
                }
            }
        }
    }
    best
}

/// Runs a measuring peer and parses its last JSON line.
fn peer_once(mut cmd: Command) -> Option<Fig> {
    let out = cmd.stderr(Stdio::null()).output().ok()?;
    let text = String::from_utf8_lossy(&out.stdout);
    let line = text.lines().rev().find(|l| l.starts_with('{'))?;
    Fig::from_json(&serde_json::from_str(line).ok()?)
}

fn cmd(program: &Path, args: &[&str]) -> Command {
    let mut c = Command::new(program);
    c.args(args);
    c
}

fn py(o: &Opts, script: &str, args: &[&str]) -> Command {
    let mut c = Command::new("python3");
    c.arg(o.py.join(script)).args(args);
    c
}

fn print_table(first: &str, names: &[&str], figs: &[Option<Fig>], refs: &[(&str, &Option<Fig>)]) {
    let h = header(first, refs);
    let h = if first == "program" { h.replace("| tx/s | p50 |", "| runs/s | median |") } else { h };
    println!("{h}");
    for (n, f) in names.iter().zip(figs) {
        println!("{}", row(n, f, refs));
    }
    println!();
}

/// plcsh's driver, in process: `regs` words from VW0 (holding registers 100…).
fn plcsh_driver_once(o: &Opts, url: &str, regs: usize) -> Option<Fig> {
    let mut dev = match plcsh::session::open_url(url, &Clock::following()) {
        Ok(d) => d,
        Err(e) => {
            eprintln!("plcsh driver: {e}");
            return None;
        }
    };
    let ops = dev.operands().parse(&format!("VW0[{regs}]")).ok()?;
    dev.read(&ops).ok()?; // connect and warm up
    let before = dev.requests();
    let mut lat = Vec::with_capacity(o.count as usize);
    let start = Instant::now();
    while (lat.len() as u64) < o.count && start.elapsed().as_secs_f64() < o.seconds {
        let t0 = Instant::now();
        if let Err(e) = dev.read(&ops) {
            eprintln!("plcsh driver: {e}");
            return None;
        }
        lat.push(t0.elapsed().as_secs_f64());
    }
    assert_eq!(dev.requests() - before, lat.len() as u64, "one request per read");
    Some(Fig::from_latencies(lat, start.elapsed().as_secs_f64()))
}

/// mbpoll has no count or latency output: poll with its shortest delay for the test time,
/// stop it, and count the polls it printed.
fn mbpoll_rate(o: &Opts, args: &[String], regs: usize) -> Option<Fig> {
    let out = std::env::temp_dir().join(format!("plcsh-bench-mbpoll-{}", std::process::id()));
    let file = std::fs::File::create(&out).ok()?;
    let mut child = Command::new("mbpoll")
        .args(args)
        .args(["-a", "1", "-r", "101", "-c", &regs.to_string(), "-l", "10"])
        .stdout(file)
        .stderr(Stdio::null())
        .spawn()
        .ok()?;
    let start = Instant::now();
    std::thread::sleep(Duration::from_secs_f64(o.seconds));
    let secs = start.elapsed().as_secs_f64();
    plcsh::core::platform::interrupt_child(&child);
    let _ = child.wait();
    let mut text = String::new();
    std::fs::File::open(&out).ok()?.read_to_string(&mut text).ok()?;
    let _ = std::fs::remove_file(&out);
    let polls = text.lines().filter(|l| l.starts_with("[101]:")).count();
    Some(Fig { n: polls as f64, secs, p50: None, p99: None })
}

/// Wall time of whole processes (start → read 10 registers → exit), `runs` times each,
/// the programs taking turns so they see the same machine.
fn one_shots(o: &Opts, makers: &[Box<dyn Fn() -> Command + '_>]) -> Vec<Option<Fig>> {
    let mut lat: Vec<Option<Vec<f64>>> = vec![Some(Vec::new()); makers.len()];
    let start = Instant::now();
    for _ in 0..o.runs {
        for (k, make) in makers.iter().enumerate() {
            let Some(l) = lat[k].as_mut() else { continue };
            let t0 = Instant::now();
            match make().stdout(Stdio::null()).stderr(Stdio::null()).status() {
                Ok(st) if st.success() => l.push(t0.elapsed().as_secs_f64()),
                _ => lat[k] = None,
            }
        }
    }
    let secs = start.elapsed().as_secs_f64();
    lat.into_iter()
        .map(|l| {
            l.map(|l| {
                let total: f64 = l.iter().sum();
                let mut f = Fig::from_latencies(l, secs);
                f.secs = total; // runs/s of the program itself
                f
            })
        })
        .collect()
}

fn us(v: Option<f64>) -> String {
    v.map(|v| if v >= 1000.0 { format!("{:.2} ms", v / 1000.0) } else { format!("{v:.1} µs") })
        .unwrap_or_else(|| "—".into())
}

/// One table row: name, tx/s, p50, p99, then ratios against the references.
fn row(name: &str, f: &Option<Fig>, refs: &[(&str, &Option<Fig>)]) -> String {
    let Some(f) = f else {
        return format!("| {name} | not measured | | |{}", " |".repeat(refs.len()));
    };
    let mut s = format!("| {name} | {:.0} | {} | {} |", f.rate(), us(f.p50), us(f.p99));
    for (_, r) in refs {
        match r {
            Some(r) if r.rate() > 0.0 => s.push_str(&format!(" {:.2}× |", f.rate() / r.rate())),
            _ => s.push_str(" — |"),
        }
    }
    s
}

fn header(first: &str, refs: &[(&str, &Option<Fig>)]) -> String {
    let mut h = format!("| {first} | tx/s | p50 | p99 |");
    let mut sep = "|---|---:|---:|---:|".to_string();
    for (n, _) in refs {
        h.push_str(&format!(" vs {n} |"));
        sep.push_str("---:|");
    }
    format!("{h}\n{sep}")
}

/// `transactions URL REGS N`: N reads of REGS words from VW0 after one warm-up read.
fn transactions(mut args: impl Iterator<Item = String>) {
    let usage = "usage: bench_modbus transactions URL REGS N";
    let url = args.next().expect(usage);
    let regs: usize = args.next().and_then(|v| v.parse().ok()).expect(usage);
    let n: u64 = args.next().and_then(|v| v.parse().ok()).expect(usage);
    let mut dev = plcsh::session::open_url(&url, &Clock::following()).unwrap_or_else(|e| panic!("{url}: {e}"));
    let ops = dev.operands().parse(&format!("VW0[{regs}]")).expect("VW0[n] parses");
    dev.read(&ops).expect("warm-up read");
    for _ in 0..n {
        std::hint::black_box(dev.read(&ops).expect("read"));
    }
    println!("{{\"n\":{n},\"requests\":{}}}", dev.requests());
}

fn main() {
    let mut args = std::env::args().skip(1).peekable();
    if args.peek().map(String::as_str) == Some("transactions") {
        args.next();
        return transactions(args);
    }
    let exe_dir = std::env::current_exe().ok().and_then(|p| p.parent().map(Path::to_path_buf)).unwrap_or_default();
    let mut o = Opts {
        rounds: 10,
        seconds: 0.3,
        count: 100_000,
        runs: 20,
        peers: PathBuf::from("target/bench"),
        py: PathBuf::from("bench/py"),
        plcsh: exe_dir.join("plcsh"),
        plcsh_dynamic: exe_dir.join("plcsh"),
    };
    while let Some(a) = args.next() {
        let v = args.next().unwrap_or_default();
        match a.as_str() {
            "--seconds" => o.seconds = v.parse().expect("--seconds S"),
            "--count" => o.count = v.parse().expect("--count N"),
            "--runs" => o.runs = v.parse().expect("--runs R"),
            "--rounds" => o.rounds = v.parse().expect("--rounds N"),
            "--peers" => o.peers = v.into(),
            "--py" => o.py = v.into(),
            "--plcsh" => o.plcsh = v.into(),
            "--plcsh-dynamic" => o.plcsh_dynamic = v.into(),
            _ => {
                eprintln!(
                    "usage: bench_modbus [--seconds S] [--count N] [--rounds N] [--runs R] [--peers DIR] [--py DIR] [--plcsh EXE] [--plcsh-dynamic EXE]"
                );
                std::process::exit(2);
            }
        }
    }
    let (secs, count) = (o.seconds.to_string(), o.count.to_string());
    let c_client = o.peers.join("mb_client");
    let c_server = o.peers.join("mb_server");
    let echo = o.peers.join("echo_floor");

    println!("# plcsh Modbus benchmark\n");
    let load = std::fs::read_to_string("/proc/loadavg").unwrap_or_default();
    println!("Load average when the run started: {}.\n", load.split_whitespace().take(3).collect::<Vec<_>>().join(" "));
    // bench/run.sh names the machine, the commit and what else the machine was doing.
    for (key, what) in
        [("PLCSH_BENCH_MACHINE", "Machine"), ("PLCSH_BENCH_COMMIT", "Commit"), ("PLCSH_BENCH_CONDITIONS", "Conditions")]
    {
        if let Ok(v) = std::env::var(key) {
            println!("{what}: {v}.\n");
        }
    }
    println!(
        "Each throughput figure: the best of {} interleaved runs of {} s (or {} transactions), one request in flight, loopback only; latencies are from that run.\n",
        o.rounds, o.seconds, o.count
    );

    let echo_tcp = job(&echo, &["tcp", &count, &secs]);
    let echo_pty = job(&echo, &["pty", &count, &secs]);
    let floor = "12-byte echo (the floor)";

    // Servers.
    let link = std::env::temp_dir().join(format!("plcsh-bench-k2-{}", std::process::id()));
    let plcsh_srv = Server::start(
        "plcsh sim serve",
        cmd(&o.plcsh, &["sim", "serve", "--tcp", "0", "--rtu-pty", &link.to_string_lossy(), "--model", "K205-16DT"]),
    )
    .expect("plcsh sim serve starts");
    let p_tcp = plcsh_srv.field("tcp");
    let (p_host, p_port) = p_tcp.rsplit_once(':').map(|(h, p)| (h.to_string(), p.to_string())).unwrap();
    let p_dev = link.to_string_lossy().to_string();
    let c_tcp_srv = Server::start("libmodbus server (TCP)", cmd(&c_server, &["tcp", "0"]));
    let c_rtu_srv = Server::start("libmodbus server (RTU)", cmd(&c_server, &["rtu"]));
    let py_srv = Server::start("pymodbus server", py(&o, "server.py", &["tcp"]));
    let lib_tcp = c_tcp_srv.as_ref().map(|s| s.field("tcp"));
    let lib_dev = c_rtu_srv.as_ref().map(|s| s.field("path"));
    let py_tcp = py_srv.as_ref().map(|s| s.field("tcp"));

    let mut targets: Vec<Target> = Vec::new();
    let mut floors: Vec<(String, Option<Fig>)> = Vec::new();
    let clients =
        ["plcsh driver", "libmodbus client (C)", "pymodbus sync", "pymodbus async", "mbpoll (10 ms poll delay)", floor];
    for regs in [1usize, 100] {
        let r = regs.to_string();
        let tcp_c = |addr: &str| -> Job {
            let (h, p) = addr.rsplit_once(':').unwrap_or(("127.0.0.1", "0"));
            job(&c_client, &["tcp", h, p, &r, &count, &secs])
        };
        let rtu_c = |dev: &str| job(&c_client, &["rtu", dev, "115200", &r, &count, &secs]);

        // Clients on plcsh's server, TCP.
        let figs = group(
            &o,
            &[
                Job::Driver(format!("tcp://{p_tcp}?model=K205-16DT"), regs),
                tcp_c(&p_tcp),
                py_job(&o, "client.py", &["sync", "tcp", &p_tcp, &r, &count, &secs]),
                py_job(&o, "client.py", &["async", "tcp", &p_tcp, &r, &count, &secs]),
                Job::Mbpoll(vec!["-m".into(), "tcp".into(), "-p".into(), p_port.clone(), p_host.clone()], regs),
                echo_tcp.clone(),
            ],
        );
        println!("## Clients → plcsh server, TCP, {regs} register(s)\n");
        print_table("client", &clients, &figs, &[("libmodbus client", &figs[1]), ("echo floor", &figs[5])]);
        targets.push(Target::rate(
            format!("driver, TCP, {regs} register(s), vs libmodbus client"),
            &figs[0],
            &figs[1],
            1.0,
        ));
        floors.push((format!("TCP, {regs} register(s)"), figs[5].clone()));

        // Clients on plcsh's server, RTU on the pty.
        let figs = group(
            &o,
            &[
                Job::Driver(format!("rtu:{p_dev}?baud=115200&model=K205-16DT"), regs),
                rtu_c(&p_dev),
                py_job(&o, "client.py", &["sync", "rtu", &p_dev, &r, &count, &secs]),
                py_job(&o, "client.py", &["async", "rtu", &p_dev, &r, &count, &secs]),
                Job::Mbpoll(
                    vec![
                        "-m".into(),
                        "rtu".into(),
                        "-b".into(),
                        "115200".into(),
                        "-P".into(),
                        "none".into(),
                        p_dev.clone(),
                    ],
                    regs,
                ),
                echo_pty.clone(),
            ],
        );
        println!("## Clients → plcsh server, RTU on a pty, {regs} register(s)\n");
        print_table("client", &clients, &figs, &[("libmodbus client", &figs[1]), ("echo floor", &figs[5])]);
        targets.push(Target::rate(
            format!("driver, RTU on a pty, {regs} register(s), vs libmodbus client"),
            &figs[0],
            &figs[1],
            1.0,
        ));

        // Servers under the libmodbus client, TCP.
        let figs = group(
            &o,
            &[
                tcp_c(&p_tcp),
                lib_tcp.as_deref().map(tcp_c).unwrap_or(Job::Missing),
                py_tcp.as_deref().map(tcp_c).unwrap_or(Job::Missing),
                lib_tcp
                    .as_ref()
                    .map(|t| Job::Driver(format!("tcp://{t}?model=K205-16DT"), regs))
                    .unwrap_or(Job::Missing),
                echo_tcp.clone(),
            ],
        );
        targets.push(Target::rate(
            format!("sim serve, TCP, {regs} register(s), vs libmodbus server"),
            &figs[0],
            &figs[1],
            0.9,
        ));
        println!("## Servers under the libmodbus client, TCP, {regs} register(s)\n");
        print_table(
            "server",
            &["plcsh sim serve", "libmodbus server (C)", "pymodbus server", "(plcsh driver → libmodbus server)", floor],
            &figs,
            &[("libmodbus server", &figs[1]), ("pymodbus server", &figs[2]), ("echo floor", &figs[4])],
        );

        // Servers under the libmodbus client, RTU on a pty.
        let figs = group(
            &o,
            &[
                rtu_c(&p_dev),
                lib_dev.as_deref().map(rtu_c).unwrap_or(Job::Missing),
                lib_dev
                    .as_ref()
                    .map(|d| Job::Driver(format!("rtu:{d}?baud=115200&model=K205-16DT"), regs))
                    .unwrap_or(Job::Missing),
                echo_pty.clone(),
            ],
        );
        targets.push(Target::rate(
            format!("sim serve, RTU on a pty, {regs} register(s), vs libmodbus server"),
            &figs[0],
            &figs[1],
            0.9,
        ));
        println!("## Servers under the libmodbus client, RTU on a pty, {regs} register(s)\n");
        print_table(
            "server",
            &["plcsh sim serve", "libmodbus server (C)", "(plcsh driver → libmodbus server)", floor],
            &figs,
            &[("libmodbus server", &figs[1]), ("echo floor", &figs[3])],
        );
        println!("(pymodbus's serial server opens a device path, and a pty master has none: not measured on RTU.)\n");
    }

    // One-shot: process start → read 10 registers → exit.
    let url = format!("tcp://{p_tcp}?model=K205-16DT");
    let makers: Vec<Box<dyn Fn() -> Command + '_>> = vec![
        Box::new(|| cmd(&o.plcsh, &["-c", "get VW0..VW18", "--device", &url])),
        Box::new(|| cmd(&c_client, &["tcp", &p_host, &p_port, "--once"])),
        Box::new(|| {
            cmd(Path::new("mbpoll"), &["-m", "tcp", "-p", &p_port, "-a", "1", "-r", "101", "-c", "10", "-1", &p_host])
        }),
        Box::new(|| py(&o, "client.py", &["once", "tcp", &p_tcp])),
        Box::new(|| cmd(Path::new("true"), &[])),
        Box::new(|| cmd(&o.plcsh_dynamic, &["-c", "get VW0..VW18", "--device", &url])),
    ];
    let figs = one_shots(&o, &makers);
    println!(
        "## One-shot: process start → read 10 registers (VW0..VW18) → exit, TCP, {} runs each, interleaved\n",
        o.runs
    );
    println!("plcsh: {}; the dynamically linked build: {}\n", o.plcsh.display(), o.plcsh_dynamic.display());
    print_table(
        "program",
        &[
            "plcsh -c 'get VW0..VW18' --device tcp://…",
            "libmodbus client (C)",
            "mbpoll -1",
            "pymodbus sync (python3 start included)",
            "(`true`: starting any process)",
            "(the same plcsh, default dynamically linked build)",
        ],
        &figs,
        &[("libmodbus one-shot", &figs[1])],
    );
    if let (Some(p), Some(c), Some(t)) = (&figs[0], &figs[1], &figs[4]) {
        let (p, c, t) = (p.p50.unwrap_or(0.0), c.p50.unwrap_or(0.0), t.p50.unwrap_or(0.0));
        targets.push(Target {
            what: "one-shot median vs libmodbus one-shot (≤)".into(),
            got: p / c,
            want: 1.5,
            more: false,
        });
        targets.push(Target {
            what: "one-shot start-up beyond `true`, ms (≤)".into(),
            got: (p - t) / 1000.0,
            want: 0.5,
            more: false,
        });
    }
    println!("## Targets\n");
    println!("| target | measured | wanted | |\n|---|---:|---:|---|");
    for t in &targets {
        let met = if t.more { t.got >= t.want } else { t.got <= t.want };
        println!("| {} | {:.2} | {:.2} | {} |", t.what, t.got, t.want, if met { "met" } else { "missed" });
    }
    let floor: Vec<String> =
        floors.iter().map(|(k, f)| format!("{k}: {}", f.as_ref().map(|f| us(f.p50)).unwrap_or("—".into()))).collect();
    println!("\nThe 12-byte echo floor (p50) in this run: {}.", floor.join("; "));
    // The phase: VMs like the development machine switch between a fast and a slow phase
    // whatever their load; the TCP echo floor tells which one a run saw.
    if let Some(us) = floors.first().and_then(|(_, f)| f.as_ref()).and_then(|f| f.p50) {
        let phase = if us < FAST_PHASE_US { "fast" } else { "slow" };
        println!("Phase: {phase} (the TCP echo floor's p50 is {us:.1} µs; fast means under {FAST_PHASE_US} µs).");
    }
    let load = std::fs::read_to_string("/proc/loadavg").unwrap_or_default();
    println!("Load average when the run ended: {}.", load.split_whitespace().take(3).collect::<Vec<_>>().join(" "));
    drop(plcsh_srv);
    let _ = std::fs::remove_file(&link);
}

/// A TCP echo floor (p50) under this many microseconds marks the machine's fast phase.
const FAST_PHASE_US: f64 = 25.0;

/// One target of the benchmark: a ratio (or a time) measured in this run against what is wanted.
struct Target {
    what: String,
    got: f64,
    want: f64,
    /// Met when `got ≥ want` (throughput ratios); otherwise when `got ≤ want`.
    more: bool,
}

impl Target {
    /// `ours / reference` throughput, met at `want` or more (0 when either is missing).
    fn rate(what: String, ours: &Option<Fig>, reference: &Option<Fig>, want: f64) -> Target {
        let got = match (ours, reference) {
            (Some(a), Some(b)) if b.rate() > 0.0 => a.rate() / b.rate(),
            _ => 0.0,
        };
        Target { what: format!("{what} (≥)"), got, want, more: true }
    }
}
