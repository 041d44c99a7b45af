//! A served simulator is steered while it runs, through its control channel: faults are
//! added, observed and cleared while a client that is not plcsh (pymodbus) polls the served
//! K2 over Modbus TCP, and the same words work from `plcsh sim control PATH …`, from a
//! `tcp://…?control=PATH` device's `sim fault`, and in-process (`sim:`).
//!
//! Needs /usr/bin/python3 with pymodbus (Debian's python3-pymodbus, installed by .ci/run);
//! without it the pymodbus test is skipped, except under CI where that is a failure.

#![cfg(unix)]

mod common;

use common::{json_lines, pymodbus, run, serve, stdout};
use serde_json::Value;
use std::io::{BufRead, BufReader};
use std::process::{Child, Stdio};
use std::sync::mpsc::{channel, Receiver};
use std::time::{Duration, Instant};

fn tmp(name: &str) -> std::path::PathBuf {
    let d = std::env::temp_dir().join(format!("plcsh-sim-control-{}-{name}", std::process::id()));
    let _ = std::fs::remove_dir_all(&d);
    std::fs::create_dir_all(&d).unwrap();
    d
}

/// The pymodbus poller: one JSON line per poll of VW0–VW2 (holding registers 100–101).
struct Poller {
    child: Child,
    lines: Receiver<Value>,
}

impl Poller {
    fn start(python: &str, addr: &str) -> Poller {
        let (host, port) = addr.rsplit_once(':').unwrap();
        let script = concat!(env!("CARGO_MANIFEST_DIR"), "/tests/support/modbus_poller.py");
        let mut child = std::process::Command::new(python)
            .args([script, host, port, "100", "2", "0.02"])
            .stdin(Stdio::piped())
            .stdout(Stdio::piped())
            .stderr(Stdio::null())
            .spawn()
            .expect("start the pymodbus poller");
        let out = child.stdout.take().unwrap();
        let (tx, lines) = channel();
        std::thread::spawn(move || {
            for l in BufReader::new(out).lines().map_while(Result::ok) {
                if let Ok(v) = serde_json::from_str::<Value>(&l) {
                    if tx.send(v).is_err() {
                        break;
                    }
                }
            }
        });
        Poller { child, lines }
    }

    /// Reads polls until `want` holds for `n` of them in a row; returns them. Fails after a
    /// generous bound (the poller answers every 20 ms; the bound covers a loaded machine).
    fn until(&self, what: &str, n: usize, want: impl Fn(&Value) -> bool) -> Vec<Value> {
        let end = Instant::now() + Duration::from_secs(30);
        let mut run = Vec::new();
        while run.len() < n {
            let left = end.saturating_duration_since(Instant::now());
            let v = self.lines.recv_timeout(left).unwrap_or_else(|_| panic!("the poller never saw {what}"));
            if want(&v) {
                run.push(v);
            } else {
                run.clear();
            }
        }
        run
    }
}

impl Drop for Poller {
    fn drop(&mut self) {
        drop(self.child.stdin.take());
        let _ = self.child.kill();
        let _ = self.child.wait();
    }
}

fn control(path: &std::path::Path, words: &str) -> Value {
    let mut args = vec!["--json", "sim", "control", path.to_str().unwrap()];
    args.extend(words.split_whitespace());
    let o = run(&args, "");
    assert!(o.status.success(), "sim control {words}: {}", common::both(&o));
    json_lines(&o).remove(0)
}

#[test]
fn a_fault_is_added_observed_and_cleared_while_pymodbus_polls() {
    let Some(python) = pymodbus() else { return };
    let dir = tmp("pymodbus");
    let ctl = dir.join("k2.ctl");
    let s = serve(&["--tcp", "0", "--k2-control", ctl.to_str().unwrap()]);
    assert_eq!(s.ready["k2_control"], ctl.to_str().unwrap());
    let addr = s.ready["tcp"].as_str().unwrap().to_string();
    let w = run(&["-d", &format!("plc=tcp://{addr}"), "-c", "set VW0=1234"], "");
    assert!(w.status.success(), "{}", common::both(&w));
    let poller = Poller::start(python, &addr);
    poller.until("answers", 3, |v| v["result"] == "ok" && v["values"][0] == 1234);

    // Exception 04 for exactly three requests, then answers again.
    let added = control(&ctl, "fault exception 4 times=3");
    assert_eq!(added["id"], 1);
    poller.until("three exceptions 04", 3, |v| v["result"] == "exception" && v["code"] == 4);
    poller.until("answers after the fault", 3, |v| v["result"] == "ok");
    let ev = control(&ctl, "events");
    let acted: Vec<&Value> = ev["events"].as_array().unwrap().iter().filter(|e| e["id"] == 1).collect();
    assert_eq!(acted.len(), 3, "{ev}");
    assert!(acted.iter().all(|e| e["fault"] == "exception"), "{ev}");
    let listed = control(&ctl, "faults");
    assert_eq!(listed["faults"][0]["hits"], 3, "{listed}");

    // Silence until cleared: the client times out, and answers return after `fault clear`.
    control(&ctl, "fault no-reply");
    poller.until("silence", 2, |v| v["result"] == "timeout");
    let cleared = control(&ctl, "fault clear");
    assert_eq!(cleared["cleared"], 2, "{cleared}");
    poller.until("answers after fault clear", 3, |v| v["result"] == "ok" && v["values"][0] == 1234);
    assert_eq!(control(&ctl, "faults")["faults"], serde_json::json!([]));

    // A power cut: silence for its window, then the PLC is back without VW0 (not retained).
    control(&ctl, "fault power-loss for=1s");
    poller.until("no power", 1, |v| v["result"] == "timeout");
    poller.until("power back, VW0 lost", 3, |v| v["result"] == "ok" && v["values"][0] == 0);
    let ev = control(&ctl, "events");
    assert!(ev["events"].as_array().unwrap().iter().any(|e| e["fault"] == "power-loss"), "{ev}");
}

#[test]
fn a_refused_control_line_names_the_words_and_exits_2() {
    let dir = tmp("refused");
    let ctl = dir.join("k2.ctl");
    let _s = serve(&["--tcp", "0", "--k2-control", ctl.to_str().unwrap()]);
    let o = run(&["sim", "control", ctl.to_str().unwrap(), "reboot", "now"], "");
    assert_eq!(o.status.code(), Some(2), "{}", common::both(&o));
    let err = common::stderr(&o);
    assert!(err.contains("`reboot` is not a control word") && err.contains("fault clear"), "{err}");
    let o = run(&["sim", "control", dir.join("nothing.ctl").to_str().unwrap(), "faults"], "");
    assert_eq!(o.status.code(), Some(1));
    assert!(common::stderr(&o).contains("is `plcsh sim serve` still running?"), "{}", common::stderr(&o));
}

#[test]
fn a_served_k2_on_a_pty_has_its_channel_beside_the_link_and_a_url_forwards_sim_fault() {
    let dir = tmp("pty");
    let link = dir.join("k2");
    let s = serve(&["--rtu-pty", link.to_str().unwrap()]);
    let ctl = format!("{}.ctl", link.display());
    assert_eq!(s.ready["k2_control"], ctl.as_str());
    let url = format!("plc=rtu:{}?control={ctl}&timeout=200ms&retries=0", link.display());
    let o = run(&["-d", &url, "--json", "-c", "sim fault no-reply on VW10 times=1; sim faults"], "");
    assert!(o.status.success(), "{}", common::both(&o));
    let j = json_lines(&o);
    assert_eq!(j[0]["id"], 1, "{j:?}");
    assert!(j[1]["faults"][0]["range"].is_array(), "{j:?}");
    // The fault acts on the next request that touches VW10, once.
    let o = run(&["-d", &url, "-c", "get VW10"], "");
    assert!(!o.status.success());
    assert!(common::stderr(&o).contains("did not answer"), "{}", common::stderr(&o));
    let o = run(&["-d", &url, "-c", "get VW10"], "");
    assert!(o.status.success(), "{}", common::both(&o));
    let ev = control(std::path::Path::new(&ctl), "events");
    assert_eq!(ev["events"][0]["fault"], "no-reply", "{ev}");
}

#[test]
fn in_process_sim_fault_speaks_the_same_words() {
    let o = run(
        &[
            "--time",
            "stepped",
            "--json",
            "-d",
            "plc=sim:K205-16DT",
            "-c",
            "sim fault stuck I0.2=1 after=1s; sim step 2s; get I0.2; sim faults",
        ],
        "",
    );
    assert!(o.status.success(), "{}", common::both(&o));
    let j = json_lines(&o);
    assert_eq!(j[0]["id"], 1);
    assert_eq!(j[2]["values"][0]["value"], true, "{}", stdout(&o));
    assert_eq!(j.last().unwrap()["faults"][0]["kind"]["kind"], "stuck", "{j:?}");
}

/// A served FX PLC's control channel: X inputs switched, stuck and a silent line, seen by a
/// client on its programming port (`fx+tcp://`), in the same words as the other families.
#[test]
fn a_served_fx_plc_takes_inputs_and_faults_on_its_control_channel() {
    let dir = tmp("fx");
    let ctl = dir.join("fx.ctl");
    let s = serve(&["--fx-tcp", "0", "--fx-control", ctl.to_str().unwrap()]);
    assert_eq!(s.ready["fx_control"], ctl.to_str().unwrap());
    let url = format!("fx=fx+tcp://{}?timeout=300ms", s.ready["fx_tcp"].as_str().unwrap());
    let get = |op: &str| {
        let o = run(&["--json", "-d", &url, "-c", &format!("use fx; get {op}")], "");
        (o.status.success(), json_lines(&o).last().cloned().unwrap_or_default())
    };
    assert_eq!(get("X17").1["values"][0]["value"], false);
    assert_eq!(control(&ctl, "input X17=1")["input"], "X17");
    assert_eq!(get("X17").1["values"][0]["value"], true);
    control(&ctl, "fault stuck X17=0");
    assert_eq!(get("X17").1["values"][0]["value"], false, "a stuck input reads its level");
    control(&ctl, "fault no-reply for=1s");
    let (ok, line) = get("X17");
    assert!(!ok, "a silent line: {line}");
    assert_eq!(control(&ctl, "fault clear")["cleared"], 2);
    assert_eq!(get("X17").1["values"][0]["value"], true, "cleared: the switch's level again");
    assert_eq!(control(&ctl, "events")["events"].as_array().unwrap().len(), 2);
    let o = run(&["sim", "control", ctl.to_str().unwrap(), "input", "X18=1"], "");
    assert_eq!(o.status.code(), Some(2), "X18 is not octal: {}", common::both(&o));
}
