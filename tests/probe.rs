//! `plcsh probe` and `plcsh agent check` against `plcsh sim serve` in another process, over
//! Modbus TCP and an RTU pty, with and without the helper (`--agent`), on three models, and
//! with faults (no reply, exception replies, late replies). Every verdict names what failed
//! and what to do, and neither command changes anything on the PLC: the served simulator's
//! whole state (its control channel's `state`, what a snapshot holds) is the same before and
//! after, apart from time and the words the helper itself keeps moving. The frames plcsh sent
//! are recorded (`--record`) and read back: a probe sends only read function codes, and the
//! check writes only the mailbox's request words.

#![cfg(unix)]

mod common;
use common::*;
use serde_json::Value;
use std::path::{Path, PathBuf};

const BASE: usize = 3400;
/// Bytes of the helper's mailbox and scratch words (docs/agent.md).
const MAILBOX: usize = plcsh::k2::agent::protocol::TOTAL_SIZE as usize;

fn dir(name: &str) -> PathBuf {
    let d = std::env::temp_dir().join(format!("plcsh-probe-{}-{name}", std::process::id()));
    let _ = std::fs::remove_dir_all(&d);
    std::fs::create_dir_all(&d).unwrap();
    d
}

struct Plc {
    served: Served,
    ctl: PathBuf,
    agent: bool,
}

impl Plc {
    fn start(d: &Path, model: &str, agent: bool, extra: &[&str]) -> Plc {
        let ctl = d.join("k2.ctl");
        let mut args = vec!["--tcp", "127.0.0.1:0", "--model", model, "--k2-control", ctl.to_str().unwrap()];
        if agent {
            args.push("--agent");
        }
        args.extend_from_slice(extra);
        let served = serve(&args);
        Plc { served, ctl, agent }
    }

    fn tcp(&self, model: &str) -> String {
        format!("tcp://{}?model={model}", self.served.ready["tcp"].as_str().unwrap())
    }

    /// The simulator's whole state, without what moves by itself: the virtual time, SMB0 (the
    /// clock bits SM0.5 and SM0.4 and the scan toggle SM0.6), the helper's mailbox (its
    /// heartbeat counts scans), and the CPU's scan count, statistics and schedule and the helper's own
    /// execution state. The CPU's mode, errors and faults stay in: a command that stopped the
    /// CPU or raised an error would show.
    fn state(&self, faults: bool) -> Value {
        let mut args = vec!["--json", "sim", "control", self.ctl.to_str().unwrap(), "state"];
        args.retain(|a| !a.is_empty());
        let o = run(&args, "");
        assert!(o.status.success(), "{}", both(&o));
        let mut s = json_lines(&o).remove(0)["state"].take();
        for k in ["start_ns", "last_ns"] {
            s.as_object_mut().unwrap().remove(k);
        }
        if let Some(p) = s["program"].as_object_mut() {
            for k in ["run_scans", "next_scan_ns", "timed_next_ns", "helper_cpu", "stats"] {
                p.remove(k);
            }
        }
        if faults {
            // The fault's own log and hit count move with every request it acts on.
            s.as_object_mut().unwrap().remove("faults");
            s.as_object_mut().unwrap().remove("events");
        }
        let sm = s["mem"]["sm"].as_str().unwrap().to_string();
        // SMW22/24/26 (last, shortest and longest scan time: the simulator keeps them as the S7-200 does, docs/il.md) move
        // with the scans themselves: a scan that served a helper command is a longer one.
        s["mem"]["sm"] = format!("..{}<scan times>{}", &sm[2..44], &sm[56..]).into();
        if self.agent {
            let v = s["mem"]["v"].as_str().unwrap().to_string();
            let (a, b) = (2 * BASE, 2 * (BASE + MAILBOX));
            s["mem"]["v"] = format!("{}<mailbox>{}", &v[..a], &v[b..]).into();
        }
        s
    }
}

/// Function codes and first addresses of every frame plcsh sent, from its recording.
fn sent(recording: &Path) -> Vec<(u64, u64, u64)> {
    let o = run(&["--json", "record", "show", recording.to_str().unwrap()], "");
    assert!(o.status.success(), "{}", both(&o));
    json_lines(&o)
        .into_iter()
        .filter(|f| f["dir"] == "sent")
        .map(|f| {
            let addr = f["address"].as_str().and_then(|a| a.parse().ok()).unwrap_or(u64::MAX);
            (f["function"].as_u64().unwrap(), addr, f["count"].as_u64().unwrap_or(0))
        })
        .collect()
}

fn plcsh_json(args: &[&str]) -> (Value, std::process::Output) {
    let mut a = vec!["--json"];
    a.extend_from_slice(args);
    let o = run(&a, "");
    let lines = json_lines(&o);
    assert_eq!(lines.len(), 1, "{}", both(&o));
    (lines.into_iter().next().unwrap(), o)
}

/// Every failed verdict or step names what failed and what to do.
fn every_failure_says_what_to_do(v: &Value, list: &str, what: &str) {
    for x in v[list].as_array().unwrap() {
        let failed = x.get("ok").map(|o| o == false).unwrap_or(false) || x["outcome"] == "failed";
        if failed {
            assert!(!x[what].as_str().unwrap_or("").is_empty(), "{x}");
            assert!(x["todo"].as_str().is_some_and(|t| t.len() > 10), "no what-to-do: {x}");
        }
    }
}

#[test]
fn a_probe_finds_each_models_areas_with_reads_only_and_changes_nothing() {
    for (model, agent) in [("K205-16DT", false), ("K204ET-16DT", true), ("K209M-56DT", false)] {
        let d = dir(&format!("probe-{model}"));
        let plc = Plc::start(&d, model, agent, &[]);
        let before = plc.state(false);
        let rec = d.join("probe.pcapng");
        let (v, o) = plcsh_json(&["--record", rec.to_str().unwrap(), "probe", &plc.tcp(model)]);
        assert_eq!(o.status.code(), Some(0), "{model}: {}", both(&o));
        assert_eq!(v["passed"], true, "{v}");
        assert!(v["models"].as_array().unwrap().iter().any(|m| m == model), "{model}: {v}");
        assert!(v["timing"]["p50_ms"].as_f64().is_some() && v["timing"]["reads"] == 100, "{v}");
        assert_eq!(plc.state(false), before, "{model}: the probe changed the PLC");
        let frames = sent(&rec);
        assert_eq!(frames.len() as u64, v["requests"].as_u64().unwrap(), "every request is recorded");
        assert!(frames.iter().all(|(fc, _, n)| (1..=4).contains(fc) && *n == 1), "{model}: not only one-unit reads");
        let _ = std::fs::remove_dir_all(&d);
    }
}

#[test]
fn the_check_passes_on_a_served_helper_and_writes_only_the_mailbox() {
    for model in ["K205-16DT", "K204ET-16DT", "K209M-56DT", "K205-16DR"] {
        let d = dir(&format!("check-{model}"));
        let plc = Plc::start(&d, model, true, &[]);
        let before = plc.state(false);
        let rec = d.join("check.pcapng");
        let (v, o) = plcsh_json(&["--record", rec.to_str().unwrap(), "agent", "check", &plc.tcp(model)]);
        assert_eq!(o.status.code(), Some(0), "{model}: {}", both(&o));
        assert_eq!(v["passed"], true, "{v}");
        let steps = v["steps"].as_array().unwrap();
        assert_eq!(steps.len(), 6, "{v}");
        if model == "K205-16DR" {
            assert_eq!(steps[5]["outcome"], "not-applicable", "a relay model has no pulse channel: {v}");
        } else {
            assert_eq!(steps[5]["outcome"], "passed", "{v}");
            assert!(steps[5]["seen"].as_str().unwrap().contains("bit 4 set"), "{v}");
        }
        assert!(v["scan_ms"].as_f64().unwrap() > 0.0, "{v}");
        assert_eq!(plc.state(false), before, "{model}: the check changed the PLC");
        // Writes: FC 16 to the request words (holding registers from 100 + (BASE + 96) / 2) only.
        let first = (100 + (BASE + 96) / 2) as u64;
        for (fc, addr, n) in sent(&rec) {
            if !(1..=4).contains(&fc) {
                assert_eq!(fc, 16, "{model}: only FC 16 writes");
                assert!(addr == first && n == 38, "{model}: a write outside the request words: {addr} ×{n}");
            }
        }
        let _ = std::fs::remove_dir_all(&d);
    }
}

#[test]
fn without_the_helper_the_check_fails_at_its_first_step_and_writes_nothing() {
    let d = dir("no-helper");
    let plc = Plc::start(&d, "K205-16DT", false, &[]);
    let before = plc.state(false);
    let rec = d.join("check.pcapng");
    let (v, o) = plcsh_json(&["--record", rec.to_str().unwrap(), "agent", "check", &plc.tcp("K205-16DT")]);
    assert_eq!(o.status.code(), Some(1), "{}", both(&o));
    assert_eq!(v["passed"], false);
    assert_eq!(v["steps"][0]["outcome"], "failed");
    assert!(v["steps"][0]["todo"].as_str().unwrap().contains("plcsh agent il"), "{v}");
    every_failure_says_what_to_do(&v, "steps", "seen");
    assert!(sent(&rec).iter().all(|(fc, _, _)| (1..=4).contains(fc)), "nothing was written");
    assert_eq!(plc.state(false), before);
    // The comparison sees a change when there is one.
    let o = run(&["-d", &plc.tcp("K205-16DT"), "-c", "set VW10=1"], "");
    assert!(o.status.success(), "{}", both(&o));
    assert_ne!(plc.state(false), before, "a write shows in the state");
    // The text form says the same.
    let o = run(&["agent", "check", &plc.tcp("K205-16DT")], "");
    assert_eq!(o.status.code(), Some(1));
    assert!(stdout(&o).contains("1. FAIL signature") && stdout(&o).contains("what to do:"), "{}", both(&o));
    let _ = std::fs::remove_dir_all(&d);
}

#[test]
fn both_commands_work_over_an_rtu_pty() {
    let d = dir("rtu");
    let link = d.join("k2");
    let served = serve(&["--rtu-pty", link.to_str().unwrap(), "--agent", "--model", "K209EA-50DX"]);
    let url = format!("rtu:{}?baud=19200&parity=even&model=K209EA-50DX", link.display());
    let (v, o) = plcsh_json(&["probe", &url, "--reads", "20"]);
    assert_eq!(o.status.code(), Some(0), "{}", both(&o));
    assert!(v["models"].as_array().unwrap().iter().any(|m| m == "K209EA-50DX"), "{v}");
    assert_eq!(v["serial"], "19200 8E1, unit 1", "the settings that answered: {v}");
    let (v, o) = plcsh_json(&["agent", "check", &url]);
    assert_eq!(o.status.code(), Some(0), "{}", both(&o));
    assert_eq!(v["passed"], true, "{v}");
    drop(served);
    let _ = std::fs::remove_dir_all(&d);
}

/// `--scan-serial`: the URL's settings get no answer (the served K2 is silent for exactly the
/// requests they take), so the probe tries the common settings in order and names the first
/// that answered. A pty carries bytes at any baud rate, so this proves the scan, not that the
/// simulator checks the line's settings.
#[test]
fn a_serial_scan_names_the_settings_that_answered() {
    let d = dir("scan");
    let link = d.join("k2");
    let served = serve(&["--rtu-pty", link.to_str().unwrap(), "--fault", "no-reply times=2"]);
    let url = format!("rtu:{}?baud=19200&parity=even&timeout=200ms&retries=1", link.display());
    let (v, o) = plcsh_json(&["probe", &url, "--scan-serial", "--reads", "5"]);
    assert_eq!(o.status.code(), Some(0), "{}", both(&o));
    assert_eq!(v["serial_tried"][0], "19200 8E1, unit 1", "{v}");
    assert_eq!(v["serial"], "9600 8N1, unit 1", "the first common setting answered: {v}");
    assert!(v["models"].as_array().unwrap().iter().any(|m| m == "K205-16DT"), "{v}");
    // Without --scan-serial the same silence is one verdict naming the serial settings to check.
    let o =
        run(&["sim", "control", &link.with_extension("ctl").display().to_string(), "fault", "no-reply", "times=2"], "");
    assert!(o.status.success(), "{}", both(&o));
    let (v, o) = plcsh_json(&["probe", &url]);
    assert_eq!(o.status.code(), Some(1), "{}", both(&o));
    assert!(v["verdicts"][0]["todo"].as_str().unwrap().contains("baud="), "{v}");
    drop(served);
    let _ = std::fs::remove_dir_all(&d);
}

#[test]
fn a_silent_plc_is_one_verdict_with_what_to_check() {
    let d = dir("silent");
    let plc = Plc::start(&d, "K205-16DT", true, &["--fault", "no-reply"]);
    let before = plc.state(true);
    let url = format!("{}&timeout=200ms&retries=0", plc.tcp("K205-16DT"));
    let (v, o) = plcsh_json(&["probe", &url]);
    assert_eq!(o.status.code(), Some(1), "{}", both(&o));
    let verdicts = v["verdicts"].as_array().unwrap();
    assert_eq!(verdicts.len(), 1, "{v}");
    assert!(verdicts[0]["what"].as_str().unwrap().contains("did not answer"), "{v}");
    assert!(verdicts[0]["todo"].as_str().unwrap().contains("unit id"), "{v}");
    assert_eq!(v["requests"], 1, "one unanswered read, not a search of every area: {v}");
    let (v, o) = plcsh_json(&["agent", "check", &url]);
    assert_eq!(o.status.code(), Some(1), "{}", both(&o));
    assert!(v["steps"][0]["seen"].as_str().unwrap().contains("did not answer"), "{v}");
    every_failure_says_what_to_do(&v, "steps", "seen");
    assert_eq!(plc.state(true), before);
    let _ = std::fs::remove_dir_all(&d);
}

#[test]
fn exception_replies_are_named_with_what_to_do() {
    let d = dir("exception");
    let plc = Plc::start(&d, "K205-16DT", true, &["--fault", "exception 4"]);
    let before = plc.state(true);
    let (v, o) = plcsh_json(&["probe", &plc.tcp("K205-16DT")]);
    assert_eq!(o.status.code(), Some(1), "{}", both(&o));
    let text = v["verdicts"].to_string();
    assert!(text.contains("exception 04 (server device failure)") && text.contains("diagnostics"), "{v}");
    every_failure_says_what_to_do(&v, "verdicts", "what");
    let (v, o) = plcsh_json(&["agent", "check", &plc.tcp("K205-16DT")]);
    assert_eq!(o.status.code(), Some(1), "{}", both(&o));
    assert!(v["steps"][0]["seen"].as_str().unwrap().contains("exception 04"), "{v}");
    every_failure_says_what_to_do(&v, "steps", "seen");
    assert_eq!(plc.state(true), before);
    let _ = std::fs::remove_dir_all(&d);
}

#[test]
fn late_replies_show_in_the_response_time_or_as_no_reply() {
    let d = dir("late");
    let plc = Plc::start(&d, "K205-16DT", true, &["--fault", "late 40ms on VW0"]);
    let before = plc.state(true);
    // Late but within the timeout: every area is found, and the timed reads of VW0 show it.
    let (v, o) = plcsh_json(&["probe", &plc.tcp("K205-16DT"), "--reads", "10"]);
    assert_eq!(o.status.code(), Some(0), "{}", both(&o));
    assert!(v["timing"]["p50_ms"].as_f64().unwrap() >= 40.0, "{v}");
    // Later than the timeout: the check's reads of the mailbox go unanswered, and it says so.
    let ctl = plc.ctl.to_str().unwrap().to_string();
    let o = run(&["sim", "control", &ctl, "fault", "late", "1s"], "");
    assert!(o.status.success(), "{}", both(&o));
    let url = format!("{}&timeout=300ms&retries=0", plc.tcp("K205-16DT"));
    let (v, o) = plcsh_json(&["agent", "check", &url]);
    assert_eq!(o.status.code(), Some(1), "{}", both(&o));
    assert_eq!(v["steps"][0]["outcome"], "failed", "{v}");
    assert!(v["steps"][0]["seen"].as_str().unwrap().contains("did not answer"), "{v}");
    every_failure_says_what_to_do(&v, "steps", "seen");
    let o = run(&["sim", "control", &ctl, "fault", "clear"], "");
    assert!(o.status.success());
    assert_eq!(plc.state(true), before);
    let _ = std::fs::remove_dir_all(&d);
}

#[test]
fn the_report_is_markdown_a_user_can_attach() {
    let d = dir("report");
    let plc = Plc::start(&d, "K205-16DT", false, &[]);
    let report = d.join("probe report.md");
    let o = run(&["probe", &plc.tcp("K205-16DT"), "--reads", "5", "--report", report.to_str().unwrap()], "");
    assert_eq!(o.status.code(), Some(0), "{}", both(&o));
    let md = std::fs::read_to_string(&report).unwrap();
    assert!(md.starts_with("# plcsh probe report"), "{md}");
    assert!(md.contains("| holding registers | 03 | V | 100 | 2147 | 2048 |"), "{md}");
    assert!(md.contains("K205-16DT") && md.contains("## Verdicts"), "{md}");
    assert!(stdout(&o).contains("models that fit: K205-16DT"), "{}", both(&o));
    let _ = std::fs::remove_dir_all(&d);
}

#[test]
fn the_in_process_simulator_is_refused_with_how_to_serve_it() {
    for cmd in [&["probe", "sim:K205-16DT"][..], &["agent", "check", "sim:K205-16DT"]] {
        let o = run(cmd, "");
        assert_eq!(o.status.code(), Some(2), "{}", both(&o));
        assert!(both(&o).contains("sim serve"), "{}", both(&o));
    }
}

/// The check writes (the mailbox, one channel's SM bytes): `--read-only` and a profile that
/// limits writes refuse it before anything is sent; the probe, which only reads, runs.
#[test]
fn a_read_only_session_or_profile_refuses_the_check_but_not_the_probe() {
    let d = dir("read-only");
    let plc = Plc::start(&d, "K205-16DT", true, &[]);
    let rec = d.join("r.pcapng");
    let o = run(&["--read-only", "--record", rec.to_str().unwrap(), "agent", "check", &plc.tcp("K205-16DT")], "");
    assert_eq!(o.status.code(), Some(1), "{}", both(&o));
    assert!(both(&o).contains("--read-only refuses every change"), "{}", both(&o));
    assert!(sent(&rec).is_empty(), "nothing was sent");
    let config = d.join("devices.toml");
    std::fs::write(&config, format!("[devices.press]\nurl = \"{}\"\nread_only = true\n", plc.tcp("K205-16DT")))
        .unwrap();
    let o = run(&["--config", config.to_str().unwrap(), "agent", "check", "press"], "");
    assert_eq!(o.status.code(), Some(1), "{}", both(&o));
    assert!(both(&o).contains("profile `press`"), "{}", both(&o));
    let o = run(&["--read-only", "--config", config.to_str().unwrap(), "probe", "press", "--reads", "3"], "");
    assert_eq!(o.status.code(), Some(0), "{}", both(&o));
    assert!(stdout(&o).contains("models that fit: K205-16DT"), "{}", both(&o));
    let _ = std::fs::remove_dir_all(&d);
}
