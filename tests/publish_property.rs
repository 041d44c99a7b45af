//! The publisher's invariant against a real broker, over generated runs: every value a
//! subscriber receives on `plcsh/GROUP/DEVICE/OPERAND` is that device's value of that operand
//! at the poll that read it, and nothing is counted as published that the broker never got
//! (docs/fleets.md, "What is published is true").
//!
//! The world: served K2s (`plcsh sim serve`, one process each, with a control channel), one
//! mosquitto on a free loopback port, a writer that keeps changing every register of every
//! device to a value derived from (device, operand, epoch) and notes when each epoch was
//! written, and a subscriber (rumqttc, QoS 1) that receives everything. Each generated case
//! publishes a random part of the served fleet, in a random order, with a random operand list
//! (word and bit ranges, single words and bits, repeated operands), `--buffer`, `--every`,
//! `--qos` 0 or 1 and MQTT 3.1.1 or 5, while the broker is paused (SIGSTOP/SIGCONT), devices
//! stop answering or answer with a Modbus exception (the control channel) and are restarted on
//! their port. Some cases end by `--count`, some by a stop (SIGINT) under overload, at QoS 0 and 1.
//! The consumer then checks every message of the case: its topic against its payload, the value
//! against the epochs the device can have held when it was read (the payload's `ts`), statuses
//! and their reasons, and that it received at least as many messages as the summary counts as
//! published, with the summary's counters adding up.
//!
//! The in-process property test (src/publish/property.rs, 1 000 cases) covers the queue and the
//! poller without a broker; this one the whole path. PLCSH_BENCH_PUBLISH_BROKER_CASES (default
//! 10) and PLCSH_BENCH_PUBLISH_BROKER_FLEET (more devices, served by one `sim serve --fleet N`
//! and written too, but never faulted; default 0) set its size; bench/fleet.sh runs it at plant
//! size. A failure names its case: PLCSH_BENCH_PUBLISH_BROKER_SEED=N PLCSH_BENCH_PUBLISH_BROKER_CASES=1
//! runs case N again.
#![cfg(unix)]

mod common;
use common::*;
use std::io::BufRead;
use std::path::{Path, PathBuf};
use std::process::{Child, Command, Stdio};
use std::sync::atomic::{AtomicBool, Ordering};
use std::sync::{Arc, Mutex};
use std::time::{Duration, Instant};

fn mosquitto() -> &'static str {
    let runs = |p: &str| Command::new(p).arg("-h").stdout(Stdio::null()).stderr(Stdio::null()).status().is_ok();
    if runs("mosquitto") {
        "mosquitto"
    } else {
        "/usr/sbin/mosquitto"
    }
}

/// The test's own mosquitto on a free port: no limit on what it queues for the subscriber
/// (what it was handed, it passes on), paused and resumed by signals.
struct Broker {
    child: Child,
    port: u16,
}

impl Broker {
    fn start(dir: &Path) -> Option<Broker> {
        use std::os::unix::fs::PermissionsExt;
        if Command::new(mosquitto()).arg("-h").stdout(Stdio::null()).stderr(Stdio::null()).status().is_err() {
            assert!(std::env::var_os("CI").is_none(), "mosquitto is required when CI is set (.ci/run installs it)");
            common::skipped("mosquitto (apt-get install mosquitto)");
            return None;
        }
        std::fs::set_permissions(dir, std::fs::Permissions::from_mode(0o777)).unwrap();
        let port = std::net::TcpListener::bind("127.0.0.1:0").unwrap().local_addr().unwrap().port();
        let conf = dir.join("mosquitto.conf");
        // Started as root, mosquitto would drop to its own user; it keeps the test's instead.
        let user = if unsafe { libc::geteuid() } == 0 { "user root\n" } else { "" };
        std::fs::write(
            &conf,
            format!(
                "{user}listener {port} 127.0.0.1\nallow_anonymous true\nmax_queued_messages 0\npersistence false\n"
            ),
        )
        .unwrap();
        let child =
            Command::new(mosquitto()).arg("-c").arg(&conf).stdout(Stdio::null()).stderr(Stdio::null()).spawn().unwrap();
        let deadline = Instant::now() + Duration::from_secs(10);
        while std::net::TcpStream::connect(("127.0.0.1", port)).is_err() {
            assert!(Instant::now() < deadline, "mosquitto did not start on port {port}");
            std::thread::sleep(Duration::from_millis(10));
        }
        Some(Broker { child, port })
    }

    fn signal(&self, sig: libc::c_int) {
        // SAFETY: kill(2) on the test's own child.
        unsafe {
            libc::kill(self.child.id() as libc::pid_t, sig);
        }
    }
}

impl Drop for Broker {
    fn drop(&mut self) {
        self.signal(libc::SIGCONT);
        let _ = self.child.kill();
        let _ = self.child.wait();
    }
}

/// Every message the subscriber received: topic, payload.
type Got = Arc<Mutex<Vec<(String, Vec<u8>)>>>;

fn subscribe(port: u16) -> Got {
    let got: Got = Arc::default();
    let mut opts = rumqttc::MqttOptions::new("property-watch", "127.0.0.1", port);
    opts.set_clean_session(false);
    // Longer than any pause of the broker: the subscriber stays connected through them.
    opts.set_keep_alive(Duration::from_secs(30));
    opts.set_max_packet_size(1 << 20, 1 << 20);
    let (client, mut conn) = rumqttc::Client::new(opts, 100);
    client.subscribe("plcsh/#", rumqttc::QoS::AtLeastOnce).unwrap();
    let g = got.clone();
    let (ready_tx, ready) = std::sync::mpsc::channel();
    std::thread::spawn(move || {
        let _keep = client;
        for ev in conn.iter() {
            match ev {
                Ok(rumqttc::Event::Incoming(rumqttc::Packet::SubAck(_))) => {
                    let _ = ready_tx.send(());
                }
                Ok(rumqttc::Event::Incoming(rumqttc::Packet::Publish(p))) => {
                    g.lock().unwrap().push((p.topic.clone(), p.payload.to_vec()))
                }
                Ok(_) => {}
                Err(_) => std::thread::sleep(Duration::from_millis(50)),
            }
        }
    });
    ready.recv_timeout(Duration::from_secs(10)).expect("subscribed");
    got
}

/// xorshift64* (as src/core/test_rng.rs, which only the library's own tests see): a case is
/// reproducible from its number.
struct Rng(u64);

impl Rng {
    fn below(&mut self, n: u64) -> u64 {
        self.0 ^= self.0 >> 12;
        self.0 ^= self.0 << 25;
        self.0 ^= self.0 >> 27;
        self.0.wrapping_mul(0x2545_F491_4F6C_DD1D) % n
    }
    fn in_range(&mut self, lo: i64, hi: i64) -> i64 {
        lo + self.below((hi - lo) as u64 + 1) as i64
    }
    fn pick<T: Copy>(&mut self, v: &[T]) -> T {
        v[self.below(v.len() as u64) as usize]
    }
}

fn now_ms() -> u64 {
    std::time::SystemTime::now().duration_since(std::time::UNIX_EPOCH).unwrap().as_millis() as u64
}

/// Words VW0..VW30 and bits M0.0..M1.7 of every device hold values derived from (device,
/// operand, epoch): a word is `epoch | device | word index` in its bits, so a word under
/// another device's or operand's name never matches; a bit is a function of all three.
#[derive(Clone, Copy)]
struct Layout {
    /// Bits of a word that name the device (the device's index modulo 2^dev_bits).
    dev_bits: u32,
}

const WORDS: u64 = 16;
const BITS: u64 = 16;

impl Layout {
    fn for_devices(n: usize) -> Layout {
        Layout { dev_bits: (usize::BITS - (n.max(2) - 1).leading_zeros()).min(8) }
    }
    fn epoch_bits(&self) -> u32 {
        16 - 4 - self.dev_bits
    }
    /// Epoch 0: the device's memory as a fresh start leaves it (zeros).
    fn word(&self, epoch: u64, dev: usize, idx: u64) -> i64 {
        if epoch == 0 {
            return 0;
        }
        let code = (epoch - 1) % ((1 << self.epoch_bits()) - 1) + 1;
        let dev = dev as u64 & ((1 << self.dev_bits) - 1);
        ((code << (self.dev_bits + 4)) | (dev << 4) | idx) as i64
    }
    fn bit(&self, epoch: u64, dev: usize, idx: u64) -> bool {
        epoch != 0 && (epoch * 5 + dev as u64 * 3 + idx) % 4 < 2
    }
}

/// One write of an epoch to one area of a device: when it was asked, and when the device
/// confirmed it (`None`: it failed, and may or may not have been applied).
#[derive(Clone, Copy, Debug)]
struct Entry {
    asked: u64,
    done: Option<u64>,
    epoch: u64,
}

/// What each device's words and bits held when: per device, [words, bits].
type Timeline = Arc<Vec<Mutex<[Vec<Entry>; 2]>>>;

/// The epochs area `area` of a device may have held at some instant in `[from, to]` (ms): an
/// epoch is possible from when its write was asked until a later write was confirmed.
fn possible(entries: &[Entry], from: u64, to: u64) -> Vec<u64> {
    let mut out = Vec::new();
    let mut end = u64::MAX;
    for e in entries.iter().rev() {
        if e.asked <= to && end >= from {
            out.push(e.epoch);
        }
        if let Some(d) = e.done {
            end = end.min(d);
        }
    }
    out
}

/// A served K2: its port (kept across restarts) and control channel.
struct Plc {
    served: Option<Served>,
    port: u16,
    ctl: PathBuf,
}

impl Plc {
    fn start(dir: &Path, i: usize) -> Plc {
        let ctl = dir.join(format!("k{i}.ctl"));
        let served = serve(&["--tcp", "127.0.0.1:0", "--k2-control", ctl.to_str().unwrap()]);
        let port = served.ready["tcp"].as_str().unwrap().rsplit(':').next().unwrap().parse().unwrap();
        Plc { served: Some(served), port, ctl }
    }

    fn control(&self, words: &str) {
        let mut args = vec!["sim", "control", self.ctl.to_str().unwrap()];
        args.extend(words.split_whitespace());
        let o = run(&args, "");
        assert!(o.status.success(), "sim control {words}: {}", both(&o));
    }
}

/// The writer: sweeps over every device, each sweep a new epoch, words first, then bits, each
/// area in one write; notes each write in the timeline. A device that does not answer is
/// opened again on the next sweep.
fn writer(
    addrs: Vec<String>,
    layout: Layout,
    timeline: Timeline,
    stop: Arc<AtomicBool>,
) -> std::thread::JoinHandle<()> {
    std::thread::spawn(move || {
        let mut devices: Vec<Option<Box<dyn plcsh::core::Device>>> = addrs.iter().map(|_| None).collect();
        let mut epoch = 0u64;
        while !stop.load(Ordering::Relaxed) {
            epoch += 1;
            let sweep = Instant::now();
            for (i, addr) in addrs.iter().enumerate() {
                if devices[i].is_none() {
                    let url = format!("tcp://{addr}?timeout=300ms&retries=0");
                    devices[i] = plcsh::session::open_url(&url, &plcsh::core::Clock::following()).ok();
                }
                let Some(d) = devices[i].as_mut() else { continue };
                for area in 0..2 {
                    let (names, n) = if area == 0 { ("VW0..VW30", WORDS) } else { ("M0.0..M1.7", BITS) };
                    let ops = d.operands().parse(names).unwrap();
                    let items: Vec<_> = ops
                        .into_iter()
                        .zip(0..n)
                        .map(|(op, k)| {
                            let v = if area == 0 {
                                plcsh::core::Value::Int(layout.word(epoch, i, k))
                            } else {
                                plcsh::core::Value::Bool(layout.bit(epoch, i, k))
                            };
                            (op, v)
                        })
                        .collect();
                    let asked = now_ms();
                    let r = d.write(&items);
                    let done = r.is_ok().then(now_ms);
                    timeline[i].lock().unwrap()[area].push(Entry { asked, done, epoch });
                    if r.is_err() {
                        devices[i] = None;
                        break;
                    }
                }
            }
            // At least 40 ms per epoch: a few polls see each one.
            if let Some(rest) = Duration::from_millis(40).checked_sub(sweep.elapsed()) {
                std::thread::sleep(rest);
            }
        }
    })
}

/// One generated case's parameters.
struct Case {
    members: Vec<usize>,
    operands: Vec<String>,
    buffer: usize,
    every_ms: u64,
    qos: u8,
    v5: bool,
    /// `Some(n)`: ends by `--count n`; `None`: stopped by SIGINT under overload.
    count: Option<u64>,
}

fn operands(r: &mut Rng) -> Vec<String> {
    let mut list: Vec<String> = Vec::new();
    for _ in 0..r.in_range(1, 5) {
        let t = match r.below(6) {
            0 => format!("VW{}", 2 * r.below(WORDS)),
            1 | 2 => {
                let a = r.below(WORDS);
                format!("VW{}..VW{}", 2 * a, 2 * (a + r.below(WORDS - a)))
            }
            3 => format!("M{}.{}", r.below(2), r.below(8)),
            4 => {
                let (b, a) = (r.below(2), r.below(8));
                format!("M{b}.{a}..M{b}.{}", a + r.below(8 - a))
            }
            _ => list.last().cloned().unwrap_or_else(|| "VW0".into()),
        };
        list.push(t);
    }
    list
}

fn generate(r: &mut Rng, case: u64, faulty: usize, devices: usize) -> Case {
    // One case in four is a stop under overload; they alternate QoS 0 and 1.
    let stop = case % 4 == 1;
    let mut members: Vec<usize> = (0..devices).collect();
    // A random part of the fleet (every faulty device when stopping), in a random order.
    for i in (1..members.len()).rev() {
        members.swap(i, r.below(i as u64 + 1) as usize);
    }
    let n = if stop { devices } else { r.in_range(1, devices as i64) as usize };
    members.truncate(n);
    if faulty > 0 && !members.iter().any(|&m| m < faulty) {
        members.push(r.below(faulty as u64) as usize);
    }
    let every_ms = if stop { 1 } else { r.pick(&[2, 3, 5, 10, 20, 40, 100, 200]) };
    Case {
        members,
        operands: operands(r),
        buffer: if stop { 100_000 } else { r.pick(&[1, 2, 4, 16, 100, 10_000]) },
        every_ms,
        qos: if stop { ((case / 4) % 2) as u8 } else { r.below(2) as u8 },
        v5: r.below(3) == 0,
        count: (!stop).then(|| (r.in_range(300, 2500) as u64 / every_ms).max(3)),
    }
}

/// The (area, index) of a published operand: words VW0..VW30, bits M0.0..M1.7.
fn operand(leaf: &str) -> Option<(usize, u64)> {
    if let Some(n) = leaf.strip_prefix("VW") {
        let n: u64 = n.parse().ok()?;
        return (n.is_multiple_of(2) && n / 2 < WORDS).then_some((0, n / 2));
    }
    let (b, i) = leaf.strip_prefix('M')?.split_once('.')?;
    let (b, i): (u64, u64) = (b.parse().ok()?, i.parse().ok()?);
    (i < 8 && b * 8 + i < BITS).then_some((1, b * 8 + i))
}

/// How long before its answer arrived (`ts`) a device may have read a value: the poll's
/// requests (300 ms timeout each) on a loaded machine.
const READ_WINDOW_MS: u64 = 3000;

/// Checks every message of the case; returns the number of values checked.
fn check(case: &str, group: &str, got: &[(String, Vec<u8>)], layout: Layout, timeline: &Timeline) -> usize {
    let mut values = 0;
    for (topic, payload) in got {
        let text = String::from_utf8_lossy(payload);
        let parts: Vec<&str> = topic.split('/').collect();
        assert!(parts.len() >= 4 && parts[0] == "plcsh" && parts[1] == group, "{case}: {topic} {text}");
        if parts[2] == "_publisher" {
            match parts[3] {
                "status" => assert!(text == "online" || text == "offline", "{case}: {topic} {text}"),
                "stats" => {
                    let j: serde_json::Value = serde_json::from_slice(payload).unwrap();
                    assert!(j["dropped_behind"].is_u64() && j["queued"].is_u64(), "{case}: {topic} {text}");
                }
                _ => panic!("{case}: {topic} {text}"),
            }
            continue;
        }
        assert_eq!(parts.len(), 4, "{case}: {topic} {text}");
        let dev: usize = parts[2].strip_prefix('k').and_then(|d| d.parse().ok()).unwrap_or(usize::MAX);
        assert!(dev < timeline.len(), "{case}: a device that is no member: {topic} {text}");
        let j: serde_json::Value =
            serde_json::from_slice(payload).unwrap_or_else(|e| panic!("{case}: {topic}: not JSON: {text}: {e}"));
        if parts[3] == "status" {
            match (j["state"].as_str(), j["reason"].as_str()) {
                (Some("online"), None) => {}
                (Some("offline"), Some("unreachable" | "no reply" | "exception 2")) => {}
                _ => panic!("{case}: {topic} {text}"),
            }
            continue;
        }
        values += 1;
        assert_eq!(
            (j["device"].as_str(), j["operand"].as_str()),
            (Some(parts[2]), Some(parts[3])),
            "{case}: {topic} {text}"
        );
        let (area, idx) =
            operand(parts[3]).unwrap_or_else(|| panic!("{case}: an operand not asked for: {topic} {text}"));
        let ts = j["ts"].as_u64().unwrap_or_else(|| panic!("{case}: {topic} {text}"));
        assert!(j["seq"].as_u64().is_some_and(|s| s > 0), "{case}: {topic} {text}");
        let epochs = possible(&timeline[dev].lock().unwrap()[area], ts.saturating_sub(READ_WINDOW_MS), ts + 5);
        let ok = if area == 0 {
            assert_eq!(j["type"], "WORD", "{case}: {topic} {text}");
            epochs.iter().any(|&e| j["value"].as_i64() == Some(layout.word(e, dev, idx)))
        } else {
            assert_eq!(j["type"], "BOOL", "{case}: {topic} {text}");
            epochs.iter().any(|&e| j["value"].as_bool() == Some(layout.bit(e, dev, idx)))
        };
        assert!(ok, "{case}: {topic} {text}: not the device's value at that poll (epochs then: {epochs:?})");
    }
    values
}

/// Runs one case; returns (values checked, messages published).
#[allow(clippy::too_many_arguments)]
fn run_case(
    case: u64,
    dir: &Path,
    broker: &Broker,
    got: &Got,
    plcs: &mut [Plc],
    addrs: &[String],
    layout: Layout,
    timeline: &Timeline,
) -> (usize, u64) {
    let r = &mut Rng(case.wrapping_mul(0x9E37_79B9_7F4A_7C15) | 1);
    let c = generate(r, case, plcs.len(), addrs.len());
    let group = format!("case{case}");
    let members = if c.members.len() <= 8 {
        format!("{:?}", c.members)
    } else {
        format!("{} ({:?} …)", c.members.len(), &c.members[..8])
    };
    let name = format!(
        "case {case}: members {members}, {:?}, --buffer {} --every {}ms --qos {}{} {}",
        c.operands,
        c.buffer,
        c.every_ms,
        c.qos,
        if c.v5 { " --mqtt-version 5" } else { "" },
        c.count.map_or("stopped under overload".to_string(), |n| format!("--count {n}"))
    );
    let cfg = dir.join(format!("{group}.toml"));
    let mut text = String::new();
    for &m in &c.members {
        text += &format!("[devices.k{m}]\nurl = \"tcp://{}?timeout=300ms&retries=0\"\n", addrs[m]);
    }
    let names: Vec<String> = c.members.iter().map(|m| format!("\"k{m}\"")).collect();
    text += &format!("[fleets.{group}]\ndevices = [{}]\n", names.join(", "));
    std::fs::write(&cfg, text).unwrap();
    let mut cmd = plcsh();
    cmd.args(["--config", cfg.to_str().unwrap(), "--json", "publish", "-f", &group])
        .args(["--broker", &format!("mqtt://127.0.0.1:{}", broker.port)])
        .args([
            "--buffer",
            &c.buffer.to_string(),
            "--every",
            &format!("{}ms", c.every_ms),
            "--qos",
            &c.qos.to_string(),
        ]);
    if c.v5 {
        cmd.args(["--mqtt-version", "5"]);
    }
    if let Some(n) = c.count {
        cmd.args(["--count", &n.to_string()]);
    }
    let mut child = cmd.args(&c.operands).stdout(Stdio::piped()).stderr(Stdio::piped()).spawn().unwrap();
    let lines = std::io::BufReader::new(child.stdout.take().unwrap()).lines();
    let (tx, events) = std::sync::mpsc::channel::<String>();
    let reader = std::thread::spawn(move || {
        for l in lines.map_while(|l| l.ok()) {
            let _ = tx.send(l);
        }
    });
    let mut out = Vec::new();
    let connected = Instant::now() + Duration::from_secs(20);
    while !out.iter().any(|l: &String| l.contains(r#""state":"connected""#)) {
        let left = connected.saturating_duration_since(Instant::now());
        match events.recv_timeout(left) {
            Ok(l) => out.push(l),
            Err(_) => panic!("{name}: never connected: {out:?}"),
        }
    }
    // The chaos, while it polls: broker pauses, device faults and restarts, in a random order.
    let faulty: Vec<usize> = c.members.iter().copied().filter(|&m| m < plcs.len()).collect();
    let runs_for = Duration::from_millis(c.count.map_or(r.in_range(800, 2000) as u64, |n| n * c.every_ms));
    let started = Instant::now();
    let mut chaos = Vec::new();
    while started.elapsed() < runs_for && chaos.len() < 3 {
        std::thread::sleep(Duration::from_millis(r.in_range(50, 400) as u64));
        let hold = Duration::from_millis(r.in_range(100, 900) as u64);
        match r.below(4) {
            0 => {
                chaos.push(format!("broker paused {hold:?}"));
                broker.signal(libc::SIGSTOP);
                std::thread::sleep(hold);
                broker.signal(libc::SIGCONT);
            }
            1 | 2 if !faulty.is_empty() => {
                let i = faulty[r.below(faulty.len() as u64) as usize];
                let fault = if r.below(2) == 0 { "fault no-reply" } else { "fault exception 2" };
                chaos.push(format!("k{i} {fault} {hold:?}"));
                let p = &plcs[i];
                p.control(fault);
                std::thread::sleep(hold);
                p.control("fault clear");
            }
            3 if !faulty.is_empty() => {
                let i = faulty[r.below(faulty.len() as u64) as usize];
                chaos.push(format!("k{i} restarted {:?}", hold / 2));
                let p = &mut plcs[i];
                // The restarted device starts from zeros (epoch 0) until the writer writes it.
                drop(p.served.take());
                let t = now_ms();
                for area in timeline[i].lock().unwrap().iter_mut() {
                    area.push(Entry { asked: t, done: Some(t), epoch: 0 });
                }
                std::thread::sleep(hold / 2);
                p.served =
                    Some(serve(&["--tcp", &format!("127.0.0.1:{}", p.port), "--k2-control", p.ctl.to_str().unwrap()]));
            }
            _ => chaos.push("nothing".into()),
        }
    }
    let mut stopped = Instant::now();
    // A stop under overload: the broker is paused, readings pile up, the stop comes, and the
    // broker comes back only later — after the stop's grace in some cases, so that what was
    // handed to the connection cannot be known to have arrived.
    let long = c.count.is_none() && (case / 4) % 3 == 2;
    if c.count.is_none() {
        if let Some(rest) = runs_for.checked_sub(started.elapsed()) {
            std::thread::sleep(rest);
        }
        broker.signal(libc::SIGSTOP);
        std::thread::sleep(Duration::from_millis(r.in_range(100, 600) as u64));
        plcsh::core::platform::interrupt_child(&child);
        stopped = Instant::now();
        let hold = Duration::from_millis(if long { 7000 } else { r.in_range(200, 1500) as u64 });
        chaos.push(format!("broker paused at the stop {hold:?}"));
        std::thread::sleep(hold);
        broker.signal(libc::SIGCONT);
    }
    let status = child.wait().unwrap();
    reader.join().unwrap();
    out.extend(events.try_iter());
    let took = stopped.elapsed();
    let summary: serde_json::Value =
        out.last().and_then(|l| serde_json::from_str(l).ok()).unwrap_or_else(|| panic!("{name}: no summary: {out:?}"));
    assert_eq!(summary["cmd"], "publish", "{name}: {summary}");
    let n = |k: &str| summary[k].as_u64().unwrap_or_else(|| panic!("{name}: no {k}: {summary}"));
    let published = n("published");
    // The counters add up, and the exit status says whether anything went missing.
    assert_eq!(
        n("dropped"),
        n("dropped_broker_away") + n("dropped_behind") + n("dropped_at_stop"),
        "{name}: {summary}"
    );
    assert_eq!(n("undelivered"), n("dropped_at_stop"), "{name}: {summary}");
    assert_eq!(status.code(), Some(if summary["ok"] == true { 0 } else { 1 }), "{name}: {summary}");
    if c.count.is_none() {
        // A stop is bounded: the grace to deliver (5 s) and to close (1 s), and a loaded machine's slack.
        assert!(took < Duration::from_secs(25), "{name}: the stop took {took:?}: {summary}");
    }
    if long {
        // The broker answered nothing for longer than the stop's grace: what waited, and what
        // was written without a proof of arrival, is dropped at the stop (or with the broker
        // away, had the connection been lost meanwhile), not published.
        assert!(n("dropped_at_stop") + n("dropped_broker_away") > 0 && summary["ok"] == false, "{name}: {summary}");
    }
    // Everything counted as published reached the broker: the subscriber gets at least as many.
    let prefix = format!("plcsh/{group}/");
    let mine = |g: &[(String, Vec<u8>)]| g.iter().filter(|(t, _)| t.starts_with(&prefix)).count() as u64;
    let deadline = Instant::now() + Duration::from_secs(30);
    while mine(&got.lock().unwrap()) < published {
        assert!(
            Instant::now() < deadline,
            "{name}: {} received, {published} counted as published: {summary}",
            mine(&got.lock().unwrap())
        );
        std::thread::sleep(Duration::from_millis(20));
    }
    // This case's messages, out of the subscriber's list.
    let case_got: Vec<(String, Vec<u8>)> = {
        let mut g = got.lock().unwrap();
        let (m, rest): (Vec<_>, Vec<_>) =
            std::mem::take(&mut *g).into_iter().partition(|(t, _)| t.starts_with(&prefix));
        *g = rest;
        m
    };
    let values = check(&name, &group, &case_got, layout, timeline);
    eprintln!(
        "{name}: {values} values checked, {} messages received; published {published}, dropped behind {}, broker away {}, at the stop {}, skipped {}, offline {}; chaos: {}",
        case_got.len(),
        n("dropped_behind"),
        n("dropped_broker_away"),
        n("dropped_at_stop"),
        n("skipped"),
        summary["offline"],
        chaos.join(", ")
    );
    if summary["ok"] == true {
        assert!(values > 0, "{name}: {summary}");
    }
    (values, published)
}

#[test]
fn every_message_a_subscriber_receives_is_true_over_generated_runs_with_a_real_broker() {
    let dir = std::env::temp_dir().join(format!("plcsh-publish-property-{}", std::process::id()));
    let _ = std::fs::remove_dir_all(&dir);
    std::fs::create_dir_all(&dir).unwrap();
    let Some(broker) = Broker::start(&dir) else { return };
    let got = subscribe(broker.port);
    let env = |k: &str, d: u64| std::env::var(k).ok().and_then(|v| v.parse().ok()).unwrap_or(d);
    let cases = env("PLCSH_BENCH_PUBLISH_BROKER_CASES", 10);
    let seed = env("PLCSH_BENCH_PUBLISH_BROKER_SEED", 1);
    let more = env("PLCSH_BENCH_PUBLISH_BROKER_FLEET", 0) as usize;
    // Three devices of their own (faults and restarts), and `more` served by one process.
    let mut plcs: Vec<Plc> = (0..3).map(|i| Plc::start(&dir, i)).collect();
    let mut addrs: Vec<String> = plcs.iter().map(|p| format!("127.0.0.1:{}", p.port)).collect();
    let _fleet = (more > 0).then(|| {
        let s = serve(&["--tcp", "127.0.0.1:0", "--fleet", &more.to_string()]);
        addrs.extend(s.ready["fleet"].as_array().unwrap().iter().map(|a| a.as_str().unwrap().to_string()));
        s
    });
    let layout = Layout::for_devices(addrs.len());
    let timeline: Timeline = Arc::new(addrs.iter().map(|_| Mutex::new([Vec::new(), Vec::new()])).collect());
    let stop = Arc::new(AtomicBool::new(false));
    let writing = writer(addrs.clone(), layout, timeline.clone(), stop.clone());
    // Every device written at least once before the first case.
    let deadline = Instant::now() + Duration::from_secs(30);
    while !timeline.iter().all(|t| t.lock().unwrap()[1].iter().any(|e| e.done.is_some())) {
        assert!(Instant::now() < deadline, "the writer never reached every device");
        std::thread::sleep(Duration::from_millis(10));
    }
    let started = Instant::now();
    let (mut values, mut published) = (0, 0);
    for case in seed..seed + cases {
        let (v, p) = run_case(case, &dir, &broker, &got, &mut plcs, &addrs, layout, &timeline);
        values += v;
        published += p;
    }
    stop.store(true, Ordering::Relaxed);
    writing.join().unwrap();
    assert!(values as u64 > cases, "{values} values in {cases} cases");
    eprintln!(
        "{cases} cases over {} devices: {values} values checked, {published} messages published, in {:?}",
        addrs.len(),
        started.elapsed()
    );
    let _ = std::fs::remove_dir_all(&dir);
}
