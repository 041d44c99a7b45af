//! Recording, `record show` and `replay` end to end: a second plcsh records its session with
//! `plcsh sim serve` (Modbus TCP, RTU on a pty) and the in-process servo simulator; tshark
//! (a decoder we did not write) reads the Modbus TCP capture.
// Unix only: real pseudo-terminals (Windows has none; its COM ports are tested under Wine
// in tests/windows_serial.rs).
#![cfg(unix)]

mod common;
use common::*;
use std::path::{Path, PathBuf};
use std::process::{Command, Stdio};

fn tmp(name: &str) -> PathBuf {
    let d = std::env::temp_dir().join(format!("plcsh-record-{}", std::process::id()));
    std::fs::create_dir_all(&d).unwrap();
    d.join(name)
}

fn tcp_addr(served: &Served) -> String {
    served.ready["tcp"].as_str().expect("tcp address in the readiness line").to_string()
}

/// Runs one-shot commands on `url` with `--record file`.
fn record(file: &Path, url: &str, cmds: &str) -> std::process::Output {
    let o = plcsh()
        .args(["--record", file.to_str().unwrap(), "--device", url, "-c", cmds])
        .stdin(Stdio::null())
        .output()
        .unwrap();
    assert!(o.status.success(), "{}{}", stdout(&o), String::from_utf8_lossy(&o.stderr));
    o
}

/// tshark, or `None` (outside CI, where .ci/run installs it) with a note.
fn tshark() -> Option<&'static str> {
    let ok = Command::new("tshark").arg("--version").stdout(Stdio::null()).stderr(Stdio::null()).status();
    match ok {
        Ok(s) if s.success() => Some("tshark"),
        _ if std::env::var_os("CI").is_some() => panic!("tshark is missing (.ci/run installs it)"),
        _ => {
            eprintln!("tshark is not installed: skipping the tshark check (apt-get install tshark)");
            None
        }
    }
}

#[test]
fn tshark_decodes_a_recorded_modbus_tcp_session() {
    let served = serve(&["--tcp", "127.0.0.1:0"]);
    let url = format!("plc=tcp://{}?model=K205-16DT", tcp_addr(&served));
    let file = tmp("tcp.pcapng");
    record(&file, &url, "set VW100=1234; get VW100; set Q0.1=1; get Q0.0..Q0.7; get VW200..VW204");
    let Some(tshark) = tshark() else { return };
    let o = Command::new(tshark)
        .args(["-r", file.to_str().unwrap(), "-Y", "modbus", "-T", "fields"])
        .args(["-e", "frame.packet_flags_direction", "-e", "modbus.func_code", "-e", "modbus.reference_num"])
        .args(["-e", "modbus.word_cnt", "-e", "modbus.bit_cnt", "-e", "modbus.regval_uint16"])
        .output()
        .unwrap();
    assert!(o.status.success(), "{}", String::from_utf8_lossy(&o.stderr));
    let text = stdout(&o);
    // Requests (outbound, flags 0x2) with their function codes and Modbus addresses.
    let requests: Vec<Vec<&str>> = text
        .lines()
        .map(|l| l.split('\t').collect::<Vec<_>>())
        .filter(|f| f[0].ends_with('2'))
        .map(|f| f[1..5].to_vec())
        .collect();
    assert_eq!(
        requests,
        vec![
            vec!["6", "150", "", ""],  // set VW100: register 100 + 100/2
            vec!["3", "150", "1", ""], // get VW100
            vec!["5", "1", "", ""],    // set Q0.1: coil 1
            vec!["1", "0", "", "8"],   // get Q0.0..Q0.7: coils 0…7
            vec!["3", "200", "3", ""], // VW200..VW204: registers 200…202
        ],
        "{text}"
    );
    assert!(text.lines().any(|l| l.ends_with("1234")), "the register value is decoded: {text}");
    // No TCP analysis complaints (sequence numbers, checksums).
    let o = Command::new(tshark).args(["-r", file.to_str().unwrap(), "-q", "-z", "expert,warn"]).output().unwrap();
    let expert = stdout(&o);
    assert!(!expert.contains("Warning") && !expert.contains("Error"), "{expert}");
}

#[test]
fn record_show_decodes_rtu_and_servo_frames_by_name() {
    let link = tmp("rtu-link");
    let served = serve(&["--rtu-pty", link.to_str().unwrap()]);
    let file = tmp("rtu.pcapng");
    let url = format!("plc=rtu:{}?baud=115200&model=K205-16DT", link.display());
    // The default session also has the in-process servo simulator `servo`.
    record(&file, &url, "set VW10=7; get VW10 M2.1; get servo:statusword; set servo:target_velocity=100");
    drop(served);
    let o = plcsh().args(["record", "show", file.to_str().unwrap()]).output().unwrap();
    assert!(o.status.success());
    let text = stdout(&o);
    // Device names are padded to one width: compare with single spaces.
    let lines: Vec<String> = text.lines().map(|l| l.split_whitespace().collect::<Vec<_>>().join(" ")).collect();
    assert!(lines.iter().any(|l| l.contains("plc →") && l.contains("FC6 write single register 105 (VW10)")), "{text}");
    assert!(lines.iter().any(|l| l.contains("plc ←") && l.contains("FC3 reply") && l.contains("(VW10): 7")), "{text}");
    assert!(lines.iter().any(|l| l.contains("plc →") && l.contains("(M2.1)")), "{text}");
    assert!(lines.iter().any(|l| l.contains("servo →") && l.contains("read statusword (6041.00)")), "{text}");
    assert!(lines.iter().any(|l| l.contains("servo ←") && l.contains("statusword (6041.00) =")), "{text}");
    assert!(lines.iter().any(|l| l.contains("write target_velocity (60FF.00)")), "{text}");
    let o = plcsh().args(["--json", "record", "show", file.to_str().unwrap()]).output().unwrap();
    let l = json_lines(&o);
    let rtu: Vec<&serde_json::Value> = l.iter().filter(|v| v["proto"] == "modbus-rtu").collect();
    assert_eq!(rtu[0]["dir"], "sent");
    assert_eq!(rtu[0]["function"], 6);
    assert_eq!(rtu[0]["operands"], "VW10");
    assert_eq!(rtu[0]["values"], serde_json::json!([7]));
    assert!(l.iter().any(|v| v["proto"] == "kinco-servo" && v["operands"] == "statusword"));
}

#[test]
fn replay_reports_no_difference_then_exactly_the_changed_register() {
    let served = serve(&["--tcp", "127.0.0.1:0"]);
    let url = format!("plc=tcp://{}?model=K205-16DT", tcp_addr(&served));
    let script = "set VW100=5; set VD300=70000; get VW100 VD300 VW200 Q0.0..Q0.7; set M1.0=1; get M1.0";
    // Against the same state (a fresh simulator both times): no difference.
    let same = tmp("same.pcapng");
    record(&same, &url, script);
    let o = plcsh().args(["replay", same.to_str().unwrap()]).output().unwrap();
    let text = stdout(&o);
    assert!(o.status.success(), "{text}");
    assert!(text.trim_end().ends_with("0 difference(s)"), "{text}");
    // Another client changes one register the session then reads; the replay (on a fresh
    // simulator) differs in exactly that one.
    let o = plcsh().args(["--device", &url, "-c", "set VW200=9"]).stdin(Stdio::null()).output().unwrap();
    assert!(o.status.success());
    let changed = tmp("changed.pcapng");
    record(&changed, &url, script);
    let o = plcsh().args(["--json", "replay", changed.to_str().unwrap()]).output().unwrap();
    assert_eq!(o.status.code(), Some(1), "a difference exits 1");
    let l = json_lines(&o);
    let diffs: Vec<&serde_json::Value> = l.iter().filter_map(|v| v.get("difference")).collect();
    assert_eq!(diffs.len(), 1, "{}", stdout(&o));
    let detail = diffs[0]["detail"].as_str().unwrap();
    assert!(detail.contains("VW200 (address 200) recorded 9, replayed 0"), "{detail}");
    assert!(!detail.contains(';'), "only that register differs: {detail}");
    assert_eq!(l.last().unwrap()["differences"], 1);
}

/// A session recorded at a served bench replays against the same bench without difference —
/// including an input the bench wires to the drive's "target reached" output — and against
/// a bench with one initial value changed reports exactly that value.
#[test]
fn replay_against_a_bench_reports_exactly_the_changed_initial_value() {
    let bench = |vw2: u16, name: &str| {
        let p = tmp(name);
        std::fs::write(
            &p,
            format!(
                "wires = [\"servo:target_reached -> plc:I0.5\", \"plc:Q0.0 -> servo:pulse\"]\n\
                 init = [\"plc:VW0=7\", \"plc:VW2={vw2}\", \"servo:operating_mode=-4\", \"servo:controlword=6\", \"servo:controlword=7\", \"servo:controlword=15\"]\n\
                 [devices]\nplc = \"sim:K205-16DT\"\nservo = \"sim-servo:?id=1\"\n"
            ),
        )
        .unwrap();
        p
    };
    let (same, changed) = (bench(3, "bench-same.toml"), bench(4, "bench-changed.toml"));
    let served = serve(&["--bench", same.to_str().unwrap(), "--tcp", "127.0.0.1:0"]);
    let url = format!("plc=tcp://{}?model=K205-16DT", tcp_addr(&served));
    let file = tmp("at-bench.pcapng");
    let o = record(&file, &url, "get VW0 VW2 VW4 I0.5 I0.4; set VW10=5; get VW10");
    assert!(stdout(&o).contains("I0.5  1"), "the served bench's wire: {}", stdout(&o));
    drop(served);
    let o = plcsh().args(["replay", file.to_str().unwrap(), "--bench"]).arg(&same).output().unwrap();
    assert_eq!(stdout(&o).trim_end(), "4 request(s) replayed, 0 difference(s)", "{}", stderr(&o));
    assert!(o.status.success());
    let o = plcsh().args(["--json", "replay", file.to_str().unwrap(), "--bench"]).arg(&changed).output().unwrap();
    assert_eq!(o.status.code(), Some(1), "{}", stdout(&o));
    let l = json_lines(&o);
    let diffs: Vec<&serde_json::Value> = l.iter().filter_map(|v| v.get("difference")).collect();
    assert_eq!(diffs.len(), 1, "{}", stdout(&o));
    assert_eq!(diffs[0]["detail"], "VW2 (address 101) recorded 3, replayed 4");
    // Without the bench (a fresh simulator) the initial values and the wired input all differ.
    let o = plcsh().args(["--json", "replay", file.to_str().unwrap()]).output().unwrap();
    let l = json_lines(&o);
    let detail: Vec<String> =
        l.iter().filter_map(|v| v.get("difference")).map(|d| d["detail"].as_str().unwrap().to_string()).collect();
    assert!(detail.iter().any(|d| d.contains("I0.5")) && detail.iter().any(|d| d.contains("VW0")), "{detail:?}");
    // The bench is the starting state: --snapshot with it is refused.
    let o = plcsh()
        .args(["replay", file.to_str().unwrap(), "--snapshot", "x.json", "--bench"])
        .arg(&same)
        .output()
        .unwrap();
    assert_eq!(o.status.code(), Some(2));
}

/// A session on both links of a served bench — the PLC over Modbus TCP, the drive on its
/// pty — replays against the bench in recorded order, without difference; with one initial
/// value changed, exactly that value differs.
#[test]
fn a_two_link_session_replays_against_its_bench_in_recorded_order() {
    let bench = |vw2: u16, name: &str| {
        let p = tmp(name);
        std::fs::write(
            &p,
            format!(
                "wires = [\"servo:target_reached -> plc:I0.5\"]\n\
                 init = [\"plc:VW2={vw2}\", \"servo:controlword=6\", \"servo:controlword=7\", \"servo:controlword=15\"]\n\
                 [devices]\nplc = \"sim:K205-16DT\"\nservo = \"sim-servo:?id=1\"\n"
            ),
        )
        .unwrap();
        p
    };
    let (same, changed) = (bench(3, "two-same.toml"), bench(4, "two-changed.toml"));
    let pty = tmp("two-kinco");
    let served = serve(&[
        "--bench",
        same.to_str().unwrap(),
        "--tcp",
        "127.0.0.1:0",
        "--servo-pty",
        pty.to_str().unwrap(),
        "--servo-instant",
    ]);
    let file = tmp("two-links.pcapng");
    let o = plcsh()
        .args(["--record", file.to_str().unwrap()])
        .args(["-d", &format!("plc=tcp://{}?model=K205-16DT", tcp_addr(&served))])
        .args(["-d", &format!("servo=kinco:{}?id=1", pty.display())])
        .args(["-c", "use plc; get VW2 I0.5 servo:gear_factor; set servo:gear_factor=3; get servo:gear_factor VW2"])
        .stdin(Stdio::null())
        .output()
        .unwrap();
    assert!(o.status.success(), "{}{}", stdout(&o), stderr(&o));
    assert!(stdout(&o).contains("servo:gear_factor  3"), "{}", stdout(&o));
    drop(served);
    let o = plcsh().args(["replay", file.to_str().unwrap(), "--bench"]).arg(&same).output().unwrap();
    let text = stdout(&o);
    assert!(o.status.success() && text.trim_end().ends_with(" 0 difference(s)"), "{text}{}", stderr(&o));
    let o = plcsh().args(["--json", "replay", file.to_str().unwrap(), "--bench"]).arg(&changed).output().unwrap();
    let l = json_lines(&o);
    let diffs: Vec<&serde_json::Value> = l.iter().filter_map(|v| v.get("difference")).collect();
    assert_eq!(diffs.len(), 2, "both reads of VW2: {}", stdout(&o));
    assert!(diffs.iter().all(|d| d["detail"] == "VW2 (address 101) recorded 3, replayed 4"), "{diffs:?}");
}

#[test]
fn a_file_that_is_not_a_recording_is_refused_with_a_hint() {
    let f = tmp("junk.pcapng");
    std::fs::write(&f, b"not a capture at all").unwrap();
    let o = plcsh().args(["record", "show", f.to_str().unwrap()]).output().unwrap();
    assert_eq!(o.status.code(), Some(2));
    assert!(stderr(&o).contains("not a readable pcapng recording"), "{}", stderr(&o));
    let o = plcsh().args(["replay", f.to_str().unwrap()]).output().unwrap();
    assert_eq!(o.status.code(), Some(2));
    // Replayed writes never go to a device: refused before anything connects.
    let o = plcsh().args(["replay", f.to_str().unwrap(), "--device", "plc=tcp://127.0.0.1:1"]).output().unwrap();
    assert_eq!(o.status.code(), Some(2));
    assert!(stderr(&o).contains("never to --device"), "{}", stderr(&o));
}

#[test]
fn a_recorded_servo_session_replays_in_virtual_time_without_difference() {
    // The in-process servo simulator runs the real driver: its frames are recorded, with
    // virtual time, and a replay steps a fresh simulated drive through the same motion.
    let file = tmp("servo.pcapng");
    let o = plcsh()
        .args(["--time", "stepped", "--record", file.to_str().unwrap(), "-c"])
        .arg("servo enable; servo move rel 2rev; sim step 100ms; get servo:position_actual; sim step 2s; get servo:position_actual")
        .stdin(Stdio::null())
        .output()
        .unwrap();
    assert!(o.status.success(), "{}", stdout(&o));
    let o = plcsh().args(["replay", file.to_str().unwrap()]).output().unwrap();
    let text = stdout(&o);
    assert!(o.status.success(), "{text}");
    assert!(text.trim_end().ends_with(" 0 difference(s)") && !text.starts_with("0 request"), "{text}");
    // The timeline shows the move mid-way (virtual time 0.1 s) and done (2.1 s).
    let o = plcsh().args(["--json", "record", "show", file.to_str().unwrap()]).output().unwrap();
    let l = json_lines(&o);
    let pos: Vec<(f64, i64)> = l
        .iter()
        .filter(|v| v["dir"] == "received" && v["operands"] == "position_actual")
        .map(|v| (v["vt"].as_f64().unwrap(), v["values"][0].as_i64().unwrap()))
        .collect();
    assert_eq!(pos.len(), 2, "{l:?}");
    assert!((pos[0].0 - 0.1).abs() < 1e-9 && pos[0].1 > 0 && pos[0].1 < 20_000, "{pos:?}");
    assert_eq!(pos[1], (2.1, 20_000), "2 rev at 10000 inc/rev");
}

#[test]
fn replay_from_a_snapshot_reports_the_register_the_snapshot_changed() {
    let served = serve(&["--tcp", "127.0.0.1:0"]);
    let url = format!("plc=tcp://{}?model=K205-16DT", tcp_addr(&served));
    let file = tmp("for-snapshot.pcapng");
    record(&file, &url, "set VW100=5; get VW100 VW200 VW300");
    // A desk simulator state where VW200 differs from the machine's.
    let snap = tmp("desk.json");
    let o = plcsh()
        .args(["--time", "stepped", "-c", &format!("set VW200=9; sim snapshot save {}", snap.display())])
        .stdin(Stdio::null())
        .output()
        .unwrap();
    assert!(o.status.success(), "{}", stdout(&o));
    let o = plcsh().args(["--json", "replay", file.to_str().unwrap(), "--snapshot"]).arg(&snap).output().unwrap();
    assert_eq!(o.status.code(), Some(1), "{}", stdout(&o));
    let l = json_lines(&o);
    let diffs: Vec<&serde_json::Value> = l.iter().filter_map(|v| v.get("difference")).collect();
    assert_eq!(diffs.len(), 1, "{}", stdout(&o));
    let detail = diffs[0]["detail"].as_str().unwrap();
    assert_eq!(detail, "VW200 (address 200) recorded 0, replayed 9", "{detail}");
}

#[test]
fn an_idle_session_s_frames_reach_the_file_before_it_is_killed() {
    use std::io::Write;
    let served = serve(&["--tcp", "127.0.0.1:0"]);
    let url = format!("plc=tcp://{}?model=K205-16DT", tcp_addr(&served));
    let file = tmp("killed.pcapng");
    let mut child = plcsh()
        .args(["--record", file.to_str().unwrap(), "--device", &url])
        .stdin(Stdio::piped())
        .stdout(Stdio::null())
        .stderr(Stdio::null())
        .spawn()
        .unwrap();
    let mut stdin = child.stdin.take().unwrap();
    stdin.write_all(b"get VW100\n").unwrap();
    stdin.flush().unwrap();
    // The session stays open and idle (stdin not closed): the frames must still reach the file.
    let deadline = std::time::Instant::now() + std::time::Duration::from_secs(10);
    let shown = loop {
        let o = plcsh().args(["record", "show", file.to_str().unwrap()]).output().unwrap();
        let text = stdout(&o);
        if text.contains("FC3 reply") || std::time::Instant::now() > deadline {
            break text;
        }
        std::thread::sleep(std::time::Duration::from_millis(50));
    };
    let _ = nix::sys::signal::kill(nix::unistd::Pid::from_raw(child.id() as i32), nix::sys::signal::Signal::SIGKILL);
    let _ = child.wait();
    drop(stdin);
    assert!(shown.contains("FC3 read holding registers 150") && shown.contains("FC3 reply"), "{shown}");
    let o = plcsh().args(["record", "show", file.to_str().unwrap()]).output().unwrap();
    assert!(o.status.success(), "the file is readable after kill -9: {}", stdout(&o));
}

/// Human-readable errors go to stderr.
fn stderr(o: &std::process::Output) -> String {
    String::from_utf8_lossy(&o.stderr).into_owned()
}
