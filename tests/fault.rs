//! Injected faults, each observed by plcsh's own wire driver through `plcsh sim serve`
//! (Modbus TCP, RTU on a pty) with the right error kind and diagnosis, and in-process with
//! the event log stamping each fault at its virtual time.

mod common;
use common::*;
use std::process::Stdio;

/// Runs batch lines (one command a line: a failing one does not stop the rest) with --json.
fn batch(args: &[&str], lines: &str) -> Vec<serde_json::Value> {
    let o = run(&[args, &["--json"]].concat(), lines);
    json_lines(&o)
}

fn error_of(v: &serde_json::Value) -> (String, String) {
    let e = &v["error"];
    (e["kind"].as_str().unwrap_or("").to_string(), e["message"].as_str().unwrap_or("").to_string())
}

#[test]
fn served_faults_reach_the_wire_driver_with_their_diagnosis() {
    let served = serve(&[
        "--tcp",
        "127.0.0.1:0",
        "--fault",
        "no-reply on VW100 times=1",
        "--fault",
        "exception 4 on VW150..VW160 times=1",
        "--fault",
        "drop on VW200 times=1",
        "--fault",
        "late 800ms on VW300 times=2",
    ]);
    let url = format!("tcp://{}?model=K205-16DT&retries=0&timeout=300ms", served.ready["tcp"].as_str().unwrap());
    let l = batch(&["-d", &url], "get VW100\nget VW100\nget VW150\nget VW200\nget VW200\nget VW300\n");
    assert_eq!(l.len(), 6, "{l:?}");
    let (kind, msg) = error_of(&l[0]);
    assert_eq!(kind, "link");
    assert!(msg.contains("did not answer: no reply from unit 1 within 300 ms"), "{msg}");
    assert_eq!(l[1]["ok"], true, "times=1: the next request is answered");
    let (kind, msg) = error_of(&l[2]);
    assert_eq!(kind, "refused");
    assert!(msg.contains("04") || msg.to_lowercase().contains("device failure"), "{msg}");
    let (kind, msg) = error_of(&l[3]);
    assert_eq!(kind, "link");
    assert!(msg.contains("the PLC closed the connection"), "{msg}");
    assert_eq!(l[4]["ok"], true, "the driver reconnects");
    let (kind, msg) = error_of(&l[5]);
    assert_eq!(kind, "link", "800 ms late with a 300 ms timeout: {msg}");
    // A late reply within the timeout is just slow.
    let url = url.replace("timeout=300ms", "timeout=2s");
    let t = std::time::Instant::now();
    let l = batch(&["-d", &url], "get VW300\n");
    assert_eq!(l[0]["ok"], true, "{l:?}");
    assert!(t.elapsed() >= std::time::Duration::from_millis(800), "the reply came late");
}

#[test]
fn a_corrupted_crc_on_rtu_is_a_link_error_then_the_line_recovers() {
    let link = std::env::temp_dir().join(format!("plcsh-fault-rtu-{}", std::process::id()));
    let _served = serve(&["--rtu-pty", link.to_str().unwrap(), "--fault", "bad-crc on VW10 times=1"]);
    let url = format!("rtu:{}?baud=115200&model=K205-16DT&retries=0&timeout=300ms", link.display());
    let l = batch(&["-d", &url], "get VW10\nget VW10\n");
    let (kind, msg) = error_of(&l[0]);
    assert_eq!(kind, "link", "{msg}");
    assert_eq!(l[1]["ok"], true, "{l:?}");
}

#[test]
fn in_process_faults_act_on_schedule_and_are_logged_with_their_time() {
    let lines = "sim fault no-reply on VW100 after=1s times=1\n\
        sim fault exception 2 on MB0..MB3 at=2s for=1s\n\
        sim fault stuck I0.1=1 after=500ms for=1s\n\
        get VW100 I0.1\n\
        sim step 1s\n\
        get VW100\nget VW100\nget I0.1\n\
        sim step 1s\n\
        get MB2\n\
        sim step 1s\n\
        get MB2 I0.1\n\
        events keep\n";
    let l = batch(&["--time", "stepped"], lines);
    let gets: Vec<&serde_json::Value> = l.iter().filter(|v| v["cmd"] == "get").collect();
    assert_eq!(gets[0]["ok"], true, "before the windows open");
    assert_eq!(gets[0]["values"][1]["value"], false, "I0.1 not yet stuck");
    let (kind, msg) = error_of(gets[1]);
    assert_eq!((kind.as_str(), msg.contains("injected fault 1")), ("link", true), "{msg}");
    assert_eq!(gets[2]["ok"], true);
    assert_eq!(gets[3]["values"][0]["value"], true, "I0.1 stuck on at 1 s");
    let (kind, msg) = error_of(gets[4]);
    assert_eq!(kind, "refused", "{msg}");
    assert!(msg.contains("exception 02 illegal data address"), "{msg}");
    assert_eq!(gets[5]["ok"], true, "the exception window ended at 3 s");
    assert_eq!(gets[5]["values"][1]["value"], false, "I0.1 has its own level back after 1.5 s");
    let events = l.iter().find(|v| v["cmd"] == "events").unwrap();
    let log: Vec<(String, u64)> = events["events"]
        .as_array()
        .unwrap()
        .iter()
        .map(|e| (e["name"].as_str().unwrap().to_string(), e["time_us"].as_u64().unwrap()))
        .collect();
    assert_eq!(
        log,
        vec![("fault3".into(), 500_000), ("fault1".into(), 1_000_000), ("fault2".into(), 2_000_000)],
        "each fault at the virtual time it acted"
    );
    let o = plcsh().args(["-c", "sim fault melt"]).stdin(Stdio::null()).output().unwrap();
    assert!(!o.status.success());
    // Human-readable errors go to stderr.
    let err = String::from_utf8_lossy(&o.stderr);
    assert!(err.contains("`melt` is not a fault kind"), "{err}");
}

#[test]
fn clearing_a_fault_gives_the_input_its_own_level_back() {
    let lines = "set I0.2=1\n\
        sim fault stuck I0.2=0\n\
        sim fault stuck I0.4=1\n\
        sim step 1ms\n\
        get I0.2 I0.4\n\
        sim fault clear\n\
        get I0.2 I0.4\n\
        sim step 1ms\n\
        get I0.2 I0.4\n";
    let l = batch(&["--time", "stepped"], lines);
    let gets: Vec<&serde_json::Value> = l.iter().filter(|v| v["cmd"] == "get").collect();
    let levels = |g: &serde_json::Value| (g["values"][0]["value"].clone(), g["values"][1]["value"].clone());
    assert_eq!(levels(gets[0]), (false.into(), true.into()), "held by the faults");
    assert_eq!(levels(gets[1]), (true.into(), false.into()), "cleared: the levels from before");
    assert_eq!(levels(gets[2]), (true.into(), false.into()), "and they stay");
}
