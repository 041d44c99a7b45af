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
            common::skipped("tshark (apt-get install tshark)");
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
    // The JSON contract: `ok` and `cmd` on every line.
    assert!(l.iter().all(|v| v["ok"] == true && v["cmd"] == "record" && v["sub"] == "show"), "{l:?}");
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
    assert!(
        l.iter().all(|v| v["cmd"] == "replay" && v["ok"] == false),
        "the JSON contract, and a difference is a failure: {l:?}"
    );
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

/// A capture started by a test: stopped (SIGINT, then waited for, so it writes its file out)
/// when dropped, on every path.
struct Capturing(std::process::Child);

impl Drop for Capturing {
    fn drop(&mut self) {
        let _ =
            nix::sys::signal::kill(nix::unistd::Pid::from_raw(self.0.id() as i32), nix::sys::signal::Signal::SIGINT);
        let _ = self.0.wait();
    }
}

/// A capture of a plcsh session taken by tshark on the loopback interface — plcsh did not
/// write it: Ethernet framing from the kernel, the server on a port that is not 502, frames
/// as the sockets sent them. `record show` tells requests from replies by the ports and the
/// handshake, decodes every frame, and `replay` replays it without difference.
#[test]
fn a_tshark_capture_on_loopback_reads_like_a_recording() {
    let Some(tshark) = tshark() else { return };
    let served = serve(&["--tcp", "127.0.0.1:0"]);
    let addr = tcp_addr(&served);
    let port = addr.rsplit(':').next().unwrap().to_string();
    for iface in ["lo", "any"] {
        let file = tmp(&format!("field-{iface}.pcapng"));
        // `-w -`: written to standard output, packet by packet (a file is written in blocks).
        let mut cap = Capturing(
            Command::new(tshark)
                .args(["-i", iface, "-f", &format!("tcp port {port}"), "-w", "-"])
                .stdin(Stdio::null())
                .stdout(std::fs::File::create(&file).unwrap())
                .stderr(Stdio::piped())
                .spawn()
                .unwrap(),
        );
        // Ready when tshark says it is capturing.
        let mut err = std::io::BufReader::new(cap.0.stderr.take().unwrap());
        let mut said = String::new();
        loop {
            let mut line = String::new();
            use std::io::BufRead;
            if err.read_line(&mut line).unwrap() == 0 {
                // No permission to capture (not root, dumpcap without capabilities).
                assert!(std::env::var_os("CI").is_none(), "tshark cannot capture on {iface}: {said}");
                common::skipped(&format!(
                    "permission for tshark to capture on {iface}: root, or dumpcap with cap_net_raw ({})",
                    said.trim()
                ));
                return;
            }
            said.push_str(&line);
            if line.contains("Capturing on") {
                break;
            }
        }
        std::thread::spawn(move || std::io::copy(&mut err, &mut std::io::sink()));
        // The filter may start a moment later: connect (no payload) until a packet is in the file.
        let deadline = std::time::Instant::now() + std::time::Duration::from_secs(20);
        while !has_packet(&std::fs::read(&file).unwrap()) {
            assert!(std::time::Instant::now() < deadline, "tshark captured nothing on {iface}");
            drop(std::net::TcpStream::connect(&addr).unwrap());
            std::thread::sleep(std::time::Duration::from_millis(20));
        }
        let url = format!("plc=tcp://{addr}?model=K205-16DT");
        let o = plcsh()
            .args(["--device", &url, "-c", "set VW100=1234; get VW100; set Q0.1=1; get Q0.0..Q0.7; get VW200..VW204"])
            .stdin(Stdio::null())
            .output()
            .unwrap();
        assert!(o.status.success(), "{}", stderr(&o));
        // Wait until the last reply is in the file.
        let deadline = std::time::Instant::now() + std::time::Duration::from_secs(20);
        let shown = loop {
            let o = plcsh().args(["--json", "record", "show", file.to_str().unwrap()]).output().unwrap();
            let l = json_lines(&o);
            if l.iter().filter(|v| v["dir"] == "received").count() >= 5 || std::time::Instant::now() > deadline {
                break o;
            }
            std::thread::sleep(std::time::Duration::from_millis(50));
        };
        drop(cap);
        assert!(shown.status.success(), "{}", stderr(&shown));
        let l = json_lines(&shown);
        let sent: Vec<(u64, String)> = l
            .iter()
            .filter(|v| v["dir"] == "sent")
            .map(|v| (v["function"].as_u64().unwrap(), v["address"].as_str().unwrap_or("").to_string()))
            .collect();
        let want: Vec<(u64, String)> =
            [(6, "150"), (3, "150"), (5, "1"), (1, "0"), (3, "200")].iter().map(|(f, a)| (*f, a.to_string())).collect();
        assert_eq!(sent, want, "{iface}: {l:?}");
        assert!(l.iter().all(|v| v.get("error").is_none()), "{iface}: nothing malformed: {l:?}");
        assert!(l.iter().all(|v| v["device"] == addr.as_str()), "{iface}: the server endpoint names the link: {l:?}");
        let read = l.iter().find(|v| v["dir"] == "received" && v["function"] == 3).unwrap();
        assert_eq!((read["operands"].as_str(), &read["values"]), (Some("VW100"), &serde_json::json!([1234])));
        let o = plcsh().args(["record", "show", file.to_str().unwrap()]).output().unwrap();
        let text = stdout(&o);
        assert_eq!(text.lines().filter(|l| l.contains(" → ")).count(), 5, "{text}");
        assert_eq!(text.lines().filter(|l| l.contains(" ← ")).count(), 5, "{text}");
        // The capture replays like a recording.
        let o = plcsh().args(["replay", file.to_str().unwrap(), "--sim-model", "K205-16DT"]).output().unwrap();
        assert_eq!(stdout(&o).trim_end(), "5 request(s) replayed, 0 difference(s)", "{iface}: {}", stderr(&o));
        // The same capture as a classic pcap file (editcap, of the Wireshark suite).
        let pcap = tmp(&format!("field-{iface}.pcap"));
        let e = Command::new("editcap").args(["-F", "pcap"]).arg(&file).arg(&pcap).output().unwrap();
        assert!(e.status.success(), "{}", stderr(&e));
        let o = plcsh().args(["--json", "record", "show", pcap.to_str().unwrap()]).output().unwrap();
        assert!(o.status.success(), "{}", stderr(&o));
        let p = json_lines(&o);
        let strip = |v: &Vec<serde_json::Value>| -> Vec<String> { v.iter().map(|x| x["text"].to_string()).collect() };
        assert_eq!(strip(&p), strip(&l), "{iface}: pcap and pcapng read the same");
    }
    drop(served);
}

/// Does this (little-endian) pcapng stream hold an Enhanced Packet Block yet?
fn has_packet(b: &[u8]) -> bool {
    let mut at = 0;
    while at + 8 <= b.len() {
        let word = |i: usize| u32::from_le_bytes([b[i], b[i + 1], b[i + 2], b[i + 3]]);
        if word(at) == 6 {
            return true;
        }
        let len = word(at + 4) as usize;
        if len < 12 {
            return false;
        }
        at += len;
    }
    false
}

/// Capture bytes built by hand: classic pcap and pcapng writers for the tests below.
mod capture {
    /// An IPv4 (or IPv6) / TCP packet from `src` to `dst` with sequence number `seq`.
    pub fn ip_tcp(v6: bool, src: u16, dst: u16, seq: u32, flags: u8, payload: &[u8]) -> Vec<u8> {
        let mut tcp = Vec::new();
        tcp.extend_from_slice(&src.to_be_bytes());
        tcp.extend_from_slice(&dst.to_be_bytes());
        tcp.extend_from_slice(&seq.to_be_bytes());
        tcp.extend_from_slice(&[0, 0, 0, 0, 0x50, flags, 0xFF, 0xFF, 0, 0, 0, 0]);
        tcp.extend_from_slice(payload);
        let mut p = Vec::new();
        if v6 {
            p.extend_from_slice(&[0x60, 0, 0, 0]);
            p.extend_from_slice(&(tcp.len() as u16).to_be_bytes());
            p.extend_from_slice(&[6, 64]);
            for _ in 0..2 {
                p.extend_from_slice(&[0; 15]);
                p.push(1);
            }
        } else {
            p.extend_from_slice(&[0x45, 0]);
            p.extend_from_slice(&((20 + tcp.len()) as u16).to_be_bytes());
            // The server (port 1502) is 192.168.1.20, the client 192.168.1.10.
            let (a, b) = if src == 1502 { (20, 10) } else { (10, 20) };
            p.extend_from_slice(&[0, 0, 0x40, 0, 64, 6, 0, 0, 192, 168, 1, a, 192, 168, 1, b]);
        }
        p.extend_from_slice(&tcp);
        p
    }

    /// A classic pcap file (microseconds, little-endian) of `packets` on `linktype`.
    pub fn pcap(linktype: u32, packets: &[Vec<u8>]) -> Vec<u8> {
        let mut f = vec![0xD4, 0xC3, 0xB2, 0xA1, 2, 0, 4, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 4, 0];
        f.extend_from_slice(&linktype.to_le_bytes());
        for (i, p) in packets.iter().enumerate() {
            f.extend_from_slice(&1_700_000_000u32.to_le_bytes());
            f.extend_from_slice(&(i as u32 * 1000).to_le_bytes());
            f.extend_from_slice(&(p.len() as u32).to_le_bytes());
            f.extend_from_slice(&(p.len() as u32).to_le_bytes());
            f.extend_from_slice(p);
        }
        f
    }

    fn block(t: u32, body: &[u8]) -> Vec<u8> {
        let mut body = body.to_vec();
        body.resize(body.len().div_ceil(4) * 4, 0);
        let total = (body.len() + 12) as u32;
        let mut b = t.to_le_bytes().to_vec();
        b.extend_from_slice(&total.to_le_bytes());
        b.extend_from_slice(&body);
        b.extend_from_slice(&total.to_le_bytes());
        b
    }

    /// A pcapng section with one interface of `linktype` and `packets` as EPBs.
    pub fn pcapng(linktype: u16, packets: &[Vec<u8>]) -> Vec<u8> {
        let mut f =
            block(0x0A0D0D0A, &[0x4D, 0x3C, 0x2B, 0x1A, 1, 0, 0, 0, 0xFF, 0xFF, 0xFF, 0xFF, 0xFF, 0xFF, 0xFF, 0xFF]);
        let mut idb = linktype.to_le_bytes().to_vec();
        idb.extend_from_slice(&[0, 0, 0, 0, 4, 0]);
        f.extend_from_slice(&block(1, &idb));
        for (i, p) in packets.iter().enumerate() {
            let mut epb = vec![0, 0, 0, 0];
            let ts = 1_700_000_000_000_000u64 + i as u64 * 1000;
            epb.extend_from_slice(&((ts >> 32) as u32).to_le_bytes());
            epb.extend_from_slice(&(ts as u32).to_le_bytes());
            epb.extend_from_slice(&(p.len() as u32).to_le_bytes());
            epb.extend_from_slice(&(p.len() as u32).to_le_bytes());
            epb.extend_from_slice(p);
            f.extend_from_slice(&block(6, &epb));
        }
        f
    }
}

/// Modbus TCP exchanges on port 1502 the way a network stack sends them: a request split
/// across two segments, two replies in one segment, a retransmitted segment, one segment
/// out of order. With `prefix` the link layer in front of each IP packet.
fn field_packets(v6: bool, prefix: &[u8], syn: bool) -> Vec<Vec<u8>> {
    use capture::ip_tcp;
    let q1 = [0, 1, 0, 0, 0, 6, 1, 3, 0, 100, 0, 1];
    let q2 = [0, 2, 0, 0, 0, 6, 1, 6, 0, 101, 0, 9];
    let r1 = [0, 1, 0, 0, 0, 5, 1, 3, 2, 0x04, 0xD2];
    let r2 = [0, 2, 0, 0, 0, 6, 1, 6, 0, 101, 0, 9];
    let (c, s) = (40001u16, 1502u16);
    let mut v = Vec::new();
    if syn {
        v.push(ip_tcp(v6, c, s, 999, 0x02, &[]));
        v.push(ip_tcp(v6, s, c, 4999, 0x12, &[]));
    }
    v.push(ip_tcp(v6, c, s, 1000, 0x18, &q1[..5]));
    v.push(ip_tcp(v6, c, s, 1005, 0x18, &q1[5..]));
    v.push(ip_tcp(v6, c, s, 1005, 0x18, &q1[5..])); // retransmitted
    v.push(ip_tcp(v6, c, s, 1012 + 6, 0x18, &q2[6..])); // ahead of its first half
    v.push(ip_tcp(v6, c, s, 1012, 0x18, &q2[..6]));
    v.push(ip_tcp(v6, s, c, 5000, 0x18, &[r1.as_slice(), r2.as_slice()].concat()));
    v.into_iter().map(|p| [prefix, p.as_slice()].concat()).collect()
}

fn show_json(bytes: &[u8], name: &str) -> (std::process::Output, Vec<serde_json::Value>) {
    let f = tmp(name);
    std::fs::write(&f, bytes).unwrap();
    let o = plcsh().args(["--json", "record", "show", f.to_str().unwrap()]).output().unwrap();
    let l = json_lines(&o);
    (o, l)
}

#[test]
fn hand_built_captures_of_every_link_type_reassemble_into_frames() {
    let sll2 = [0x08, 0x00, 0, 0, 0, 0, 0, 1, 3, 4, 0, 6, 0, 0, 0, 0, 0, 0, 0, 0];
    let sll2_v6 = [0x86, 0xDD, 0, 0, 0, 0, 0, 1, 3, 4, 0, 6, 0, 0, 0, 0, 0, 0, 0, 0];
    let sll = [0, 0, 3, 4, 0, 6, 0, 0, 0, 0, 0, 0, 0, 0, 0x08, 0x00];
    let mut eth = vec![0; 12];
    eth.extend_from_slice(&[0x08, 0x00]);
    let cases: Vec<(&str, Vec<u8>)> = vec![
        ("null.pcap", capture::pcap(0, &field_packets(false, &[2, 0, 0, 0], true))),
        ("loop-v6.pcap", capture::pcap(108, &field_packets(true, &[0, 0, 0, 30], true))),
        ("raw.pcap", capture::pcap(101, &field_packets(false, &[], false))),
        ("ipv6.pcapng", capture::pcapng(229, &field_packets(true, &[], true))),
        ("sll.pcapng", capture::pcapng(113, &field_packets(false, &sll, true))),
        ("sll2.pcapng", capture::pcapng(276, &field_packets(false, &sll2, false))),
        ("sll2-v6.pcapng", capture::pcapng(276, &field_packets(true, &sll2_v6, true))),
        ("eth.pcapng", capture::pcapng(1, &field_packets(false, &eth, true))),
    ];
    for (name, bytes) in cases {
        let (o, l) = show_json(&bytes, name);
        assert!(o.status.success(), "{name}: {}", stderr(&o));
        let got: Vec<(String, String)> = l
            .iter()
            .map(|v| (v["dir"].as_str().unwrap().to_string(), v["text"].as_str().unwrap().to_string()))
            .collect();
        let want = [
            // A link to a port that is not 502 is a K204ET (the tcp:// default), VW0 = 100.
            ("sent", "FC3 read holding registers 100 ×1 (VW0)"),
            ("sent", "FC6 write single register 101 (VW2): 9"),
            ("received", "FC3 reply, 2 bytes (VW0): 1234"),
            ("received", "FC6 written 101 (VW2): 9"),
        ];
        let want: Vec<(String, String)> = want.iter().map(|(d, t)| (d.to_string(), t.to_string())).collect();
        assert_eq!(got, want, "{name}");
        assert!(l[0]["device"].as_str().unwrap().ends_with(":1502"), "{name}: {:?}", l[0]);
    }
}

#[test]
fn a_capture_plcsh_cannot_read_is_refused_naming_the_packet_and_what_to_try() {
    // IEEE 802.11 (link type 105): not a link plcsh reads.
    let f = tmp("wifi.pcapng");
    std::fs::write(&f, capture::pcapng(105, &[vec![0; 40]])).unwrap();
    let o = plcsh().args(["record", "show", f.to_str().unwrap()]).output().unwrap();
    assert_eq!(o.status.code(), Some(2));
    let e = stderr(&o);
    assert!(
        e.contains("wifi.pcapng") && e.contains("packet 1 (block at offset 48)") && e.contains("link type 105"),
        "{e}"
    );
    assert!(e.contains("tshark -i lo"), "what to try: {e}");
    // UDP only: nothing to show.
    let mut udp = capture::ip_tcp(false, 1, 2, 0, 0, b"x");
    udp[9] = 17;
    let f = tmp("udp.pcap");
    std::fs::write(&f, capture::pcap(101, &[udp])).unwrap();
    let o = plcsh().args(["record", "show", f.to_str().unwrap()]).output().unwrap();
    assert_eq!(o.status.code(), Some(2));
    assert!(stderr(&o).contains("no TCP payload"), "{}", stderr(&o));
}

/// The directory holding the plcsh binary the tests run.
fn bin_dir() -> PathBuf {
    Path::new(env!("CARGO_BIN_EXE_plcsh")).parent().unwrap().to_path_buf()
}

/// Records one session per protocol in `dir` under the names docs/recording.md uses.
fn record_each_protocol(dir: &Path) {
    let run = |file: &str, args: &[&str]| {
        let o = plcsh()
            .current_dir(dir)
            .args(["--time", "stepped", "--record", file])
            .args(args)
            .stdin(Stdio::null())
            .output()
            .unwrap();
        assert!(o.status.success(), "{file}: {}{}", stdout(&o), stderr(&o));
    };
    run("servo.pcapng", &["-c", "get servo:statusword; set servo:target_velocity=-100; get servo:target_velocity"]);
    run("umpk.pcapng", &["-d", "lab=sim-umpk:UMPK16", "-c", "umpk info; get lab:I0"]);
    run("fx.pcapng", &["-d", "fx=sim-fx:FX2N", "-c", "use fx; set D100=1234, M500=1; get D100"]);
    run("fxlink.pcapng", &["-d", "fx=sim-fx:FX2N?protocol=link", "-c", "use fx; set D100=7; get D100 M1"]);
}

/// tshark (not our code) with the Lua dissector `lua`: the fields of every packet.
fn dissect(tshark: &str, dir: &Path, lua: &str, file: &str, fields: &[&str]) -> Vec<Vec<String>> {
    let script = Path::new(env!("CARGO_MANIFEST_DIR")).join("lib/wireshark").join(lua);
    let mut c = Command::new(tshark);
    c.current_dir(dir).arg("-X").arg(format!("lua_script:{}", script.display())).args(["-r", file, "-T", "fields"]);
    for f in fields {
        c.args(["-e", f]);
    }
    let o = c.output().unwrap();
    assert!(o.status.success(), "{}", stderr(&o));
    assert!(!stderr(&o).contains("Lua Error") && !stdout(&o).contains("Lua Error"), "{}{}", stderr(&o), stdout(&o));
    stdout(&o).lines().map(|l| l.split('\t').map(str::to_string).collect()).collect()
}

/// Each protocol has its own link type, and the Lua dissectors in lib/wireshark decode what
/// plcsh recorded: tshark shows the servo's object and value, UMPK's command and packet
/// length, the FX frames' command, address and sum check.
#[test]
fn tshark_decodes_servo_umpk_and_fx_recordings_with_the_lua_dissectors() {
    let Some(tshark) = tshark() else { return };
    let dir = tmp("dissectors");
    std::fs::create_dir_all(&dir).unwrap();
    record_each_protocol(&dir);
    // Link types, as tshark reads them from the interface descriptions.
    for (file, want) in
        [("servo.pcapng", "149"), ("umpk.pcapng", "150"), ("fx.pcapng", "151"), ("fxlink.pcapng", "152")]
    {
        let o = Command::new(tshark)
            .current_dir(&dir)
            .args(["-r", file, "-T", "fields", "-e", "frame.encap_type"])
            .output()
            .unwrap();
        let wtap = stdout(&o);
        // Wireshark numbers its encapsulations itself: USER0 is 45, so USERn is 45 + n.
        let n: u32 = want.parse::<u32>().unwrap() - 147;
        assert!(wtap.lines().all(|l| l.trim() == (45 + n).to_string()), "{file}: {wtap}");
    }
    let servo = dissect(
        tshark,
        &dir,
        "kinco_servo.lua",
        "servo.pcapng",
        &[
            "kinco_servo.direction",
            "kinco_servo.func",
            "kinco_servo.object",
            "kinco_servo.value",
            "kinco_servo.checksum.status",
        ],
    );
    let row = |v: &[&str]| v.iter().map(|s| s.to_string()).collect::<Vec<String>>();
    assert_eq!(servo[0], row(&["0", "0x40", "6041.00", "", "good"]), "{servo:?}");
    assert!(servo.contains(&row(&["0", "0x23", "60FF.00", "4294967196", "good"])), "-100 as 32 bits: {servo:?}");
    assert!(servo.contains(&row(&["1", "0x43", "60FF.00", "4294967196", "good"])), "{servo:?}");
    assert_eq!(servo.len(), 6);
    let umpk = dissect(
        tshark,
        &dir,
        "umpk.lua",
        "umpk.pcapng",
        &["umpk.direction", "umpk.command", "umpk.length", "umpk.checksum.status"],
    );
    // ?03FD (controller info), then its echo and the 6-byte #06… packet.
    assert_eq!(umpk[0], row(&["0", "0x03", "", "good"]), "{umpk:?}");
    assert_eq!(umpk[1], row(&["1", "0x03", "6", "good,good"]), "{umpk:?}");
    assert!(umpk.contains(&row(&["0", "0x05", "", "good"])), "input states: {umpk:?}");
    let fx = dissect(
        tshark,
        &dir,
        "fx.lua",
        "fx.pcapng",
        &["fx_port.command", "fx_port.address", "fx_port.count", "fx_port.sum.status"],
    );
    // D100 is byte address 0x1000 + 2·100 (seed 004); M500 is forced at 0x09F4, sent F409.
    assert!(fx.contains(&row(&["1 (write)", "0x10c8", "2", "good"])), "{fx:?}");
    assert!(fx.contains(&row(&["7 (force on)", "0x09f4", "", "good"])), "{fx:?}");
    assert!(fx.contains(&row(&["0 (read)", "0x10c8", "2", "good"])), "{fx:?}");
    let link = dissect(
        tshark,
        &dir,
        "fx.lua",
        "fxlink.pcapng",
        &["fx_link.command", "fx_link.device", "fx_link.count", "fx_link.data", "fx_link.sum.status"],
    );
    assert!(link.contains(&row(&["WW (write words)", "D0100", "1", "0007", "good"])), "{link:?}");
    assert!(link.contains(&row(&["BR (read bits)", "M0001", "1", "", "good"])), "{link:?}");
    assert!(link.contains(&row(&["", "", "", "0007", "good"])), "the WR reply: {link:?}");
    // A damaged servo checksum is reported bad.
    let mut bytes = std::fs::read(dir.join("servo.pcapng")).unwrap();
    let at = bytes.windows(4).position(|w| w == [0x40, 0x41, 0x60, 0x00]).unwrap() + 7;
    bytes[at] ^= 0xFF;
    std::fs::write(dir.join("bad.pcapng"), &bytes).unwrap();
    let bad = dissect(tshark, &dir, "kinco_servo.lua", "bad.pcapng", &["kinco_servo.checksum.status"]);
    assert_eq!(bad[0], row(&["bad"]), "{bad:?}");
}

/// Every `plcsh` and `tshark -r` line in docs/recording.md's sh blocks runs as written, on
/// recordings made under the names it uses (the live capture line is run by
/// `a_tshark_capture_on_loopback_reads_like_a_recording`, on a port of its own).
#[test]
fn the_recording_docs_examples_run() {
    let Some(_) = tshark() else { return };
    let dir = tmp("docs");
    std::fs::create_dir_all(&dir).unwrap();
    record_each_protocol(&dir);
    let _ = std::os::unix::fs::symlink(Path::new(env!("CARGO_MANIFEST_DIR")).join("lib"), dir.join("lib"));
    // rtu.pcapng: an RTU session; field.pcapng: a capture of Modbus TCP (a recording reads the same).
    let link = dir.join("rtu-link");
    let served = serve(&["--rtu-pty", link.to_str().unwrap()]);
    record(&dir.join("rtu.pcapng"), &format!("plc=rtu:{}?model=K205-16DT", link.display()), "get VW0");
    drop(served);
    let served = serve(&["--tcp", "127.0.0.1:0"]);
    record(&dir.join("field.pcapng"), &format!("plc=tcp://{}?model=K205-16DT", tcp_addr(&served)), "get VW0");
    drop(served);
    let served = serve(&["--agent", "--tcp", "127.0.0.1:0"]);
    let url = format!("plc=tcp://{}?model=K205-16DT&agent=VB3400", tcp_addr(&served));
    record(&dir.join("helper.pcapng"), &url, "set SMB67=16#85, SMW68=500; get SMB67 SMW68");
    drop(served);
    let doc = std::fs::read_to_string(Path::new(env!("CARGO_MANIFEST_DIR")).join("docs/recording.md")).unwrap();
    let mut in_sh = false;
    let mut ran = 0;
    let path = format!("{}:{}", bin_dir().display(), std::env::var("PATH").unwrap_or_default());
    for line in doc.lines() {
        if line.starts_with("```") {
            in_sh = line == "```sh";
            continue;
        }
        let cmd = line.split("  #").next().unwrap().trim();
        if !in_sh || cmd.is_empty() || cmd.contains(" -i ") {
            continue;
        }
        let o =
            own_world(&mut Command::new("sh")).current_dir(&dir).env("PATH", &path).args(["-c", cmd]).output().unwrap();
        assert!(o.status.success(), "{cmd}: {}{}", stdout(&o), stderr(&o));
        assert!(!stdout(&o).trim().is_empty(), "{cmd} printed nothing");
        assert!(!stdout(&o).contains("Lua Error"), "{cmd}: {}", stdout(&o));
        ran += 1;
    }
    assert!(ran >= 6, "{ran} examples");
}

/// Offsets of the Enhanced Packet Blocks of a little-endian pcapng file.
fn epb_offsets(b: &[u8]) -> Vec<usize> {
    let mut out = Vec::new();
    let mut at = 0;
    while at + 8 <= b.len() {
        let word = |i: usize| u32::from_le_bytes([b[i], b[i + 1], b[i + 2], b[i + 3]]);
        if word(at) == 6 {
            out.push(at);
        }
        at += (word(at + 4) as usize).max(12);
    }
    out
}

/// A recording damaged in the middle (a block's length overwritten) is read around the
/// damage: the warning names the byte offsets, every frame after it is shown, and the exit
/// status is 1 — for `record show` and for `replay`, which replays the rest.
#[test]
fn damage_in_the_middle_of_a_recording_is_named_and_the_frames_after_it_are_kept() {
    let file = tmp("damaged.pcapng");
    let o = plcsh()
        .args(["--time", "stepped", "--record", file.to_str().unwrap(), "-c"])
        .arg("get servo:statusword; get servo:position_actual; get servo:target_velocity; get servo:statusword")
        .stdin(Stdio::null())
        .output()
        .unwrap();
    assert!(o.status.success(), "{}", stderr(&o));
    let mut bytes = std::fs::read(&file).unwrap();
    let epbs = epb_offsets(&bytes);
    assert_eq!(epbs.len(), 8);
    let whole = json_lines(&plcsh().args(["--json", "record", "show", file.to_str().unwrap()]).output().unwrap());
    // The third packet's block length: 0xFFFF (past the end of the file).
    let at = epbs[2];
    bytes[at + 4..at + 8].copy_from_slice(&0xFFFFu32.to_le_bytes());
    std::fs::write(&file, &bytes).unwrap();
    let o = plcsh().args(["--json", "record", "show", file.to_str().unwrap()]).output().unwrap();
    assert_eq!(o.status.code(), Some(1), "{}", stderr(&o));
    let e = stderr(&o);
    assert!(
        e.contains(&format!("bytes {at}…{} ", epbs[3] - 1)) && e.contains(&format!("block at offset {}", epbs[3])),
        "{e}"
    );
    assert!(e.contains("block length 65535"), "{e}");
    let l = json_lines(&o);
    let hex = |v: &[serde_json::Value]| v.iter().map(|x| x["hex"].as_str().unwrap().to_string()).collect::<Vec<_>>();
    let mut want = hex(&whole);
    want.remove(2);
    assert_eq!(hex(&l), want, "every frame but the damaged one");
    let o = plcsh().args(["--json", "replay", file.to_str().unwrap()]).output().unwrap();
    assert_eq!(o.status.code(), Some(1), "{}", stderr(&o));
    let last = json_lines(&o).pop().unwrap();
    assert_eq!((last["damaged"].as_bool(), last["ok"].as_bool()), (Some(true), Some(false)), "{last}");
    assert!(stderr(&o).contains(&format!("bytes {at}…")), "{}", stderr(&o));
}

/// A session through the PLC-side helper (SM registers, PLS) replays clean: the replay runs
/// the helper program in the simulated K2, at the mailbox base the recording shows, scan for
/// scan as the recorded heartbeat counts them.
#[test]
fn a_session_through_the_plc_side_helper_replays_without_difference() {
    for base in ["VB3400", "VB2000"] {
        let served = serve(&["--agent", base, "--tcp", "127.0.0.1:0"]);
        let url = format!("plc=tcp://{}?model=K205-16DT&agent={base}", tcp_addr(&served));
        let file = tmp(&format!("helper-{base}.pcapng"));
        let o = record(&file, &url, "set SMB67=16#85, SMW68=500, SMD72=1000; pls 0; get SMB67 SMW68 SMD72 VW0; rtc set 2026-11-22T10:00:00; rtc");
        assert!(stdout(&o).contains("SMB67"), "{}", stdout(&o));
        drop(served);
        let o = plcsh().args(["--json", "replay", file.to_str().unwrap()]).output().unwrap();
        let l = json_lines(&o);
        let summary = l.last().unwrap();
        assert_eq!(summary["differences"], 0, "{base}: {}", stdout(&o));
        assert!(summary["requests"].as_u64().unwrap() > 10, "{summary}");
        assert!(o.status.success());
        // The helper is what answers: without it (another base named) the mailbox reads differ.
        let o = plcsh().args(["--json", "replay", file.to_str().unwrap(), "--agent", "VB1000"]).output().unwrap();
        assert_eq!(o.status.code(), Some(1), "{}", stdout(&o));
        let diffs: Vec<serde_json::Value> =
            json_lines(&o).into_iter().filter_map(|v| v.get("difference").cloned()).collect();
        assert!(
            diffs.iter().any(|d| d["detail"].as_str().unwrap().contains("recorded 19265, replayed 0")),
            "{diffs:?}"
        );
    }
}

/// A capture taken with a small snap length keeps what it kept, and says so.
#[test]
fn packets_cut_by_the_snap_length_are_noted() {
    let mut packets = field_packets(false, &[], true);
    let last = packets.last_mut().unwrap();
    last.truncate(last.len() - 3);
    let f = tmp("snaplen.pcap");
    std::fs::write(&f, capture::pcap(101, &packets)).unwrap();
    let o = plcsh().args(["record", "show", f.to_str().unwrap()]).output().unwrap();
    assert!(o.status.success(), "{}", stderr(&o));
    assert!(stderr(&o).contains("1 packets were cut short by the capture's snap length"), "{}", stderr(&o));
    assert!(stdout(&o).contains("FC3 reply, 2 bytes (VW0): 1234"), "the whole first reply: {}", stdout(&o));
    assert!(stdout(&o).contains("malformed"), "the cut second reply: {}", stdout(&o));
}

/// A file holding no complete block (an empty file, a pcapng section header cut short, in
/// either byte order) is no capture: refused with exit status 2, saying so. A file whose
/// section header is whole but whose next block is cut short is what a killed writer
/// leaves: read up to the cut, which the warning names (pcapng draft §3.1: a block's total
/// length counts its whole body).
#[test]
fn a_file_with_no_complete_block_is_refused_and_a_cut_after_the_header_is_named() {
    let whole = capture::pcapng(1, &field_packets(false, &[0; 14], true));
    let mut be_shb = vec![0x0A, 0x0D, 0x0D, 0x0A, 0, 0, 0, 28, 0x1A, 0x2B, 0x3C, 0x4D, 0, 1, 0, 0];
    be_shb.extend_from_slice(&[0xFF; 8]);
    for (name, bytes, says) in [
        ("shb-cut-le.pcapng", whole[..20].to_vec(), "block length 28 but 20 bytes left"),
        ("shb-cut-8.pcapng", whole[..8].to_vec(), "8 bytes left, less than a section header"),
        ("shb-cut-be.pcapng", be_shb, "block length 28 but 24 bytes left"),
        ("empty.pcapng", Vec::new(), "it is empty (0 bytes)"),
    ] {
        let (o, _) = show_json(&bytes, name);
        let e = stderr(&o) + &stdout(&o);
        assert_eq!(o.status.code(), Some(2), "{name}: {e}");
        assert!(e.contains(says), "{name}: {e}");
        assert!(
            bytes.is_empty() || (e.contains("holds no complete block") && e.contains("section header at offset 0")),
            "{name}: {e}"
        );
        let f = tmp(name);
        let o = plcsh().args(["replay", f.to_str().unwrap()]).output().unwrap();
        assert_eq!(o.status.code(), Some(2), "replay {name}: {}", stderr(&o));
    }
    // The header and the interface whole, the first packet cut: no frames, the cut named.
    let idb_end = 28 + 20;
    let (o, l) = show_json(&whole[..idb_end + 10], "first-epb-cut.pcapng");
    assert_eq!(o.status.code(), Some(0), "{}", stderr(&o));
    assert!(l.is_empty(), "{l:?}");
    let e = stderr(&o);
    let first = u32::from_le_bytes(whole[idb_end + 4..idb_end + 8].try_into().unwrap());
    assert!(
        e.contains(&format!(
            "ends early (the block at offset {idb_end} is cut short: block length {first} but 10 bytes left)"
        )),
        "{e}"
    );
    assert!(e.contains("showing the 0 frames before"), "{e}");
}
