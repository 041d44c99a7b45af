//! Stopping signals end a Lua script the way Ctrl-C does: SIGTERM (what `timeout`, CI and
//! systemd send) and SIGHUP (a dropped SSH session) run the script's `plcsh.on_abort`
//! handlers — here they write to a K2 served over Modbus TCP, an effect seen from another
//! process — and plcsh exits with 128 + the signal. `os.exit` runs the handlers too.

mod common;
use common::*;

use std::io::{BufRead, BufReader};
use std::process::Stdio;

const SCRIPT: &str = r#"
local plc = plcsh.device("plc")
local mark = tonumber(arg[1])
plcsh.on_abort(function(why) plc.VW0 = mark; plc.VW2 = (why == "interrupted") and 1 or 2 end)
print("ready")
if arg[2] == "exit" then os.exit(3) end
plcsh.wait_until(function() return false end, {timeout = 60000, every = 20})
"#;

fn script() -> std::path::PathBuf {
    let dir = std::env::temp_dir().join(format!("plcsh-signals-{}", std::process::id()));
    std::fs::create_dir_all(&dir).unwrap();
    let f = dir.join("wait.lua");
    std::fs::write(&f, SCRIPT).unwrap();
    f
}

fn read_back(device: &str, op: &str) -> i64 {
    let o = run(&["--json", "--state", "none", "--device", device, "-c", &format!("get {op}")], "");
    json_lines(&o)[0]["values"][0]["value"].as_i64().unwrap()
}

/// Runs the script on `device`; once it says "ready", sends `signal` (if any); returns
/// the exit status.
fn run_and_signal(device: &str, mark: &str, mode: &str, signal: Option<&str>) -> i32 {
    let mut child = plcsh()
        .args(["--state", "none", "--device", device, "run", script().to_str().unwrap(), mark, mode])
        .stdout(Stdio::piped())
        .stderr(Stdio::inherit())
        .spawn()
        .unwrap();
    let mut lines = BufReader::new(child.stdout.take().unwrap()).lines();
    let first = lines.next().expect("a line").unwrap();
    assert!(first.contains("ready"), "{first}");
    if let Some(sig) = signal {
        let ok = std::process::Command::new("kill").args([sig, &child.id().to_string()]).status().unwrap();
        assert!(ok.success());
    }
    let rest: Vec<String> = lines.map_while(Result::ok).collect();
    let status = child.wait().unwrap();
    assert!(rest.iter().any(|l| l.contains("on_abort")), "the handlers ran: {rest:?}");
    status.code().expect("plcsh exits by itself, not killed by the signal")
}

#[test]
fn sigterm_and_sighup_run_the_abort_handlers_and_exit_128_plus_the_signal() {
    let served = serve(&["--tcp", "0", "--state", "none"]);
    let device = format!("plc=tcp://{}?model=K205-16DT", served.ready["tcp"].as_str().unwrap());
    assert_eq!(run_and_signal(&device, "143", "wait", Some("-TERM")), 143);
    assert_eq!(read_back(&device, "VW0"), 143, "the on_abort handler wrote the PLC");
    assert_eq!(read_back(&device, "VW2"), 1, "as an interruption");
    assert_eq!(run_and_signal(&device, "129", "wait", Some("-HUP")), 129);
    assert_eq!(read_back(&device, "VW0"), 129);
}

#[test]
fn os_exit_runs_the_abort_handlers_and_exits_with_its_code() {
    let served = serve(&["--tcp", "0", "--state", "none"]);
    let device = format!("plc=tcp://{}?model=K205-16DT", served.ready["tcp"].as_str().unwrap());
    assert_eq!(run_and_signal(&device, "33", "exit", None), 3);
    assert_eq!(read_back(&device, "VW0"), 33);
    assert_eq!(read_back(&device, "VW2"), 2, "as an exit");
}

#[test]
fn sigterm_at_an_idle_prompt_ends_plcsh_with_143() {
    use std::io::Write;
    let mut child = plcsh()
        .args(["--state", "none", "--time", "stepped"])
        .stdin(Stdio::piped())
        .stdout(Stdio::piped())
        .stderr(Stdio::inherit())
        .spawn()
        .unwrap();
    let mut stdin = child.stdin.take().unwrap();
    writeln!(stdin, "get VW0").unwrap();
    let mut lines = BufReader::new(child.stdout.take().unwrap()).lines();
    assert!(lines.next().unwrap().unwrap().contains("VW0"));
    // plcsh now waits for the next line, with stdin still open.
    std::process::Command::new("kill").args(["-TERM", &child.id().to_string()]).status().unwrap();
    let status = child.wait().unwrap();
    drop(stdin);
    assert_eq!(status.code(), Some(143));
}
