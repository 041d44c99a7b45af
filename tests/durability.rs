//! Acknowledged means kept: a served K2 with a state file takes a burst of Modbus writes
//! into its E2PROM backup area and a battery-retained range and is killed with SIGKILL at
//! random moments, 50 times; after every restart each write the client saw acknowledged is
//! there (a write in flight at the kill may or may not be), the file is valid and no
//! temporary file is left. The same for the shell killed during `set` into the backup area.
//! Also: two processes on one state file, and a served K2's state kept in its own file.

mod common;
use common::*;

use plcsh::core::{Clock, Device, Value};
use std::collections::HashMap;
use std::io::{BufRead, BufReader, Write};
use std::path::{Path, PathBuf};
use std::process::Stdio;
use std::time::Duration;

/// A small deterministic generator (xorshift), seeded per run and printed on failure.
struct Rng(u64);

impl Rng {
    fn new() -> Rng {
        let t = std::time::SystemTime::now().duration_since(std::time::UNIX_EPOCH).unwrap().as_nanos() as u64;
        Rng(t | 1)
    }
    fn next(&mut self) -> u64 {
        self.0 ^= self.0 << 13;
        self.0 ^= self.0 >> 7;
        self.0 ^= self.0 << 17;
        self.0
    }
    fn below(&mut self, n: u64) -> u64 {
        self.next() % n
    }
}

fn scratch(tag: &str) -> PathBuf {
    let d = std::env::temp_dir().join(format!("plcsh-durability-{}-{tag}", std::process::id()));
    let _ = std::fs::remove_dir_all(&d);
    std::fs::create_dir_all(&d).unwrap();
    d
}

/// The state file parses as JSON, and nothing but it and its lock is in the directory.
fn valid_and_alone(dir: &Path, state: &Path) {
    let text = std::fs::read_to_string(state).unwrap();
    let _: serde_json::Value =
        serde_json::from_str(&text).unwrap_or_else(|e| panic!("the state file is not valid: {e}"));
    let name = state.file_name().unwrap().to_string_lossy().into_owned();
    for e in std::fs::read_dir(dir).unwrap() {
        let f = e.unwrap().file_name().to_string_lossy().into_owned();
        assert!(f == name || f == format!(".{name}.lock"), "left behind: {f}");
    }
}

fn open(url: &str) -> Box<dyn Device> {
    plcsh::session::open_url(url, &Clock::following()).unwrap_or_else(|e| panic!("{url}: {e}"))
}

/// Addresses the burst writes: the backup area and the retained range VB0..VB99.
const WORDS: [&str; 6] = ["VW3648", "VW3700", "VW3900", "VW0", "VW50", "VW98"];

#[test]
fn served_k2_killed_during_a_modbus_write_burst_keeps_every_acknowledged_write() {
    let dir = scratch("serve");
    let state = dir.join("state.json");
    let s = state.to_str().unwrap();
    let o = run(&["--state", s, "-c", "sim retain VB0..VB99"], "");
    assert!(o.status.success(), "{}", stdout(&o));
    let mut rng = Rng::new();
    let seed = rng.0;
    // Last acknowledged value per word, and the value in flight when the server died.
    let mut acked: HashMap<&str, i64> = HashMap::new();
    let mut total = 0;
    for round in 0..50u64 {
        let mut served = serve(&["--tcp", "0", "--state", s]);
        let url = format!("tcp://{}?model=K205-16DT&timeout=300ms&retries=0", served.ready["tcp"].as_str().unwrap());
        let mut dev = open(&url);
        // Everything acknowledged before is there.
        for (w, v) in &acked {
            let op = dev.operands().parse(w).unwrap()[0];
            let got = dev.read(&[op]).unwrap()[0].as_i64();
            assert_eq!(got, *v, "seed {seed}, round {round}: {w} lost its acknowledged value");
        }
        valid_and_alone(&dir, &state);
        // Kill at a random moment while writing.
        let pid = served.child.id();
        let delay = Duration::from_millis(5 + rng.below(120));
        let killer = std::thread::spawn(move || {
            std::thread::sleep(delay);
            let _ = std::process::Command::new("kill").args(["-KILL", &pid.to_string()]).status();
        });
        let mut k = 0u64;
        loop {
            let w = WORDS[rng.below(WORDS.len() as u64) as usize];
            let v = ((round * 1000 + k) % 30000) as i64;
            k += 1;
            let op = dev.operands().parse(w).unwrap()[0];
            match dev.write(&[(op, Value::Int(v))]) {
                Ok(()) => {
                    acked.insert(w, v);
                    total += 1;
                }
                Err(_) => {
                    // In flight at the kill: either value may be kept; take what is there.
                    killer.join().unwrap();
                    let _ = served.child.wait();
                    drop(dev);
                    let mut again = serve(&["--tcp", "0", "--state", s]);
                    let url = format!("tcp://{}?model=K205-16DT", again.ready["tcp"].as_str().unwrap());
                    let mut d = open(&url);
                    let got = d.read(&[op]).unwrap()[0].as_i64();
                    assert!(
                        got == v || Some(&got) == acked.get(w) || (!acked.contains_key(w) && got == 0),
                        "seed {seed}, round {round}: {w} = {got}, neither the write in flight ({v}) nor the last acknowledged"
                    );
                    acked.insert(w, got);
                    drop(d);
                    let _ = again.child.kill();
                    let _ = again.child.wait();
                    break;
                }
            }
        }
    }
    assert!(total >= 50, "seed {seed}: only {total} writes were acknowledged over 50 rounds");
    eprintln!("seed {seed}: {total} acknowledged writes over 50 kills");
}

#[test]
fn the_shell_killed_during_set_keeps_every_acknowledged_write() {
    let dir = scratch("repl");
    let state = dir.join("state.json");
    let s = state.to_str().unwrap();
    let mut rng = Rng::new();
    let seed = rng.0;
    let mut acked: HashMap<String, i64> = HashMap::new();
    for round in 0..10u64 {
        let mut child = plcsh()
            .args(["--json", "--state", s, "--time", "stepped"])
            .stdin(Stdio::piped())
            .stdout(Stdio::piped())
            .stderr(Stdio::null())
            .spawn()
            .unwrap();
        let mut stdin = child.stdin.take().unwrap();
        let mut out = BufReader::new(child.stdout.take().unwrap()).lines();
        let n = 3 + rng.below(20);
        for k in 0..n {
            let op = format!("VB{}", 3648 + rng.below(255));
            let v = ((round * 31 + k) % 256) as i64;
            writeln!(stdin, "set {op}={v}").unwrap();
            let line = out.next().unwrap().unwrap();
            assert!(line.contains("\"ok\":true"), "{line}");
            acked.insert(op, v);
        }
        // Killed with more sets on the way.
        writeln!(stdin, "set VB3648=1").unwrap();
        child.kill().unwrap();
        let _ = child.wait();
        let ops: Vec<&String> = acked.keys().collect();
        let line = ops.iter().map(|o| o.as_str()).collect::<Vec<_>>().join(" ");
        let o = run(&["--json", "--state", s, "-c", &format!("get {line}")], "");
        let l = json_lines(&o);
        for v in l[0]["values"].as_array().unwrap() {
            let op = v["operand"].as_str().unwrap();
            if op == "VB3648" {
                continue; // the unacknowledged set may or may not have landed
            }
            assert_eq!(v["value"].as_i64(), acked.get(op).copied(), "seed {seed}, round {round}: {op}");
        }
        acked.remove("VB3648");
        valid_and_alone(&dir, &state);
    }
}

#[test]
fn a_second_process_on_a_state_file_is_refused_naming_the_first() {
    let dir = scratch("lock");
    let state = dir.join("state.json");
    let s = state.to_str().unwrap();
    let served = serve(&["--tcp", "0", "--state", s]);
    assert_eq!(served.ready["state"].as_str(), Some(s));
    let o = run(&["--state", s, "-c", "get VB3648"], "");
    assert!(!o.status.success());
    let text = String::from_utf8_lossy(&o.stderr).into_owned(); // errors go to stderr
    assert!(text.contains("in use by process") && text.contains(&served.child.id().to_string()), "{text}");
    // A served K2 keeps its state in its own file.
    let url = format!("plc=tcp://{}?model=K205-16DT", served.ready["tcp"].as_str().unwrap());
    let o = run(&["--device", &url, "-c", "set VW3648=4321"], "");
    assert!(o.status.success(), "{}", stdout(&o));
    drop(served);
    let o = run(&["--json", "--state", s, "-c", "get VW3648"], "");
    assert_eq!(json_lines(&o)[0]["values"][0]["value"], 4321);
}

#[test]
fn retention_is_limited_to_the_models_size_and_counters_can_be_retained() {
    let dir = scratch("retain");
    let state = dir.join("state.json");
    let s = state.to_str().unwrap();
    let o = run(&["--model", "K204ET-16DT", "--state", s, "-c", "sim retain VB0..VB3000"], "");
    let err = String::from_utf8_lossy(&o.stderr).into_owned(); // errors go to stderr
    assert!(err.contains("retains at most"), "{err}");
    let o = run(&["--state", s, "-c", "sim retain VB0..VB9 C0..C3; set C2=77, VB1=5"], "");
    assert!(o.status.success(), "{}", stdout(&o));
    let o = run(&["--json", "--state", s, "-c", "get C2 VB1"], "");
    let v: Vec<i64> =
        json_lines(&o)[0]["values"].as_array().unwrap().iter().map(|x| x["value"].as_i64().unwrap()).collect();
    assert_eq!(v, vec![77, 5]);
}

#[test]
fn a_temporary_file_left_by_a_killed_writer_is_never_read_and_is_removed_at_start() {
    let dir = scratch("stale");
    let state = dir.join("state.json");
    let s = state.to_str().unwrap();
    let o = run(&["--state", s, "-c", "set VW3648=11"], "");
    assert!(o.status.success(), "{}", stdout(&o));
    // What a writer killed between writing and renaming leaves: a whole, valid state file
    // under the temporary name, holding a value that was never acknowledged.
    let other = dir.join("other.json");
    let o = run(&["--state", other.to_str().unwrap(), "-c", "set VW3648=22"], "");
    assert!(o.status.success(), "{}", stdout(&o));
    let tmp = dir.join(".state.json.tmp");
    std::fs::rename(&other, &tmp).unwrap();
    let _ = std::fs::remove_file(dir.join(".other.json.lock"));
    // The served K2 starts from the state file, and the leftover is gone once it is ready.
    let served = serve(&["--tcp", "0", "--state", s]);
    assert!(!tmp.exists(), "the leftover was removed at start");
    let mut dev = open(&format!("tcp://{}?model=K205-16DT", served.ready["tcp"].as_str().unwrap()));
    let op = dev.operands().parse("VW3648").unwrap()[0];
    assert_eq!(dev.read(&[op]).unwrap(), vec![Value::Int(11)], "the leftover was not read as state");
    drop(dev);
    drop(served);
    valid_and_alone(&dir, &state);
    // A simulated UMPK's state file: the same.
    let umpk = dir.join("umpk.json");
    let tmp = dir.join(".umpk.json.tmp");
    std::fs::write(&tmp, "{ half a file").unwrap();
    let d = open(&format!("sim-umpk:UMPK16?state={}", umpk.display()));
    assert!(!tmp.exists(), "the UMPK's leftover was removed when it opened");
    drop(d);
}
