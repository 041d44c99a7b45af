//! Stopping signals end a Lua script the way Ctrl-C does: SIGTERM (what `timeout`, CI and
//! systemd send) and SIGHUP (a dropped SSH session) run the script's `plcsh.on_abort`
//! handlers — here they write to a K2 served over Modbus TCP, an effect seen from another
//! process — and plcsh exits with 128 + the signal. `os.exit` runs the handlers too.

// Unix only: POSIX signals and process groups (Windows' console events are tested in
// core::platform::windows).
#![cfg(unix)]

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

/// Starts plcsh on `device` with `args`, in a process group of its own (as `timeout` and
/// systemd run it), and returns it with its stdout lines once the first line arrived.
fn start_in_group(args: &[&str]) -> (std::process::Child, std::io::Lines<BufReader<std::process::ChildStdout>>) {
    use std::os::unix::process::CommandExt;
    let mut child = plcsh().args(args).stdout(Stdio::piped()).stderr(Stdio::null()).process_group(0).spawn().unwrap();
    let mut lines = BufReader::new(child.stdout.take().unwrap()).lines();
    let first = lines.next().expect("a first line").unwrap();
    assert!(!first.is_empty());
    (child, lines)
}

fn kill(sig: &str, target: &str) {
    assert!(std::process::Command::new("kill").args([sig, "--", target]).status().unwrap().success());
}

/// A stop ends the whole command line: the command after the interrupted `watch` never
/// runs (it would write VW10 on a PLC another process serves), and the status is the
/// signal's: 143 for SIGTERM, 129 for SIGHUP, 130 for Ctrl-C (SIGINT).
#[test]
fn a_stop_ends_the_rest_of_the_command_line_with_the_signals_status() {
    let served = serve(&["--tcp", "0", "--state", "none"]);
    let device = format!("plc=tcp://{}?model=K205-16DT", served.ready["tcp"].as_str().unwrap());
    for (sig, status) in [("-TERM", 143), ("-HUP", 129), ("-INT", 130)] {
        // The reader stays open: a reading the watch prints before the signal arrives (the
        // `kill` may take longer than a period on a loaded machine) must not fail on a closed pipe.
        let (mut child, _lines) = start_in_group(&[
            "--json",
            "--state",
            "none",
            "--device",
            &device,
            "-c",
            "watch VW0 every=20ms; set VW10=7; set VW12=7",
        ]);
        kill(sig, &child.id().to_string());
        assert_eq!(child.wait().unwrap().code(), Some(status), "{sig}");
        assert_eq!(read_back(&device, "VW10"), 0, "{sig}: the rest of the line did not run");
    }
    // Input piped ahead is dropped too.
    let mut child = plcsh()
        .args(["--json", "--state", "none", "--device", &device])
        .stdin(Stdio::piped())
        .stdout(Stdio::piped())
        .stderr(Stdio::null())
        .spawn()
        .unwrap();
    {
        use std::io::Write;
        let mut stdin = child.stdin.take().unwrap();
        writeln!(stdin, "watch VW0 every=20ms\nset VW10=9\nset VW12=9").unwrap();
        let mut lines = BufReader::new(child.stdout.take().unwrap()).lines();
        assert!(lines.next().unwrap().unwrap().contains("watch"));
        kill("-TERM", &child.id().to_string());
        assert_eq!(child.wait().unwrap().code(), Some(143));
    }
    assert_eq!(read_back(&device, "VW10"), 0, "queued input did not run");
}

const SLOW_HANDLERS: &str = r#"
local plc = plcsh.device("plc")
local mark = tonumber(arg[1])
plcsh.on_abort(function(why) plc.VW20 = mark end)
plcsh.on_abort(function(why) plcsh.sleep(tonumber(arg[2])); plc.VW22 = mark end)
print("ready")
plcsh.wait_until(function() return false end, {timeout = 60000, every = 20})
"#;

/// GNU `timeout` sends SIGTERM to plcsh and then to its process group: the second signal
/// must not cut the abort handlers short — every handler runs and the `--json` summary is
/// printed, 20 times out of 20.
#[test]
fn sigterm_to_the_process_and_then_its_group_runs_every_handler_20_of_20() {
    let served = serve(&["--tcp", "0", "--state", "none"]);
    let device = format!("plc=tcp://{}?model=K205-16DT", served.ready["tcp"].as_str().unwrap());
    let dir = std::env::temp_dir().join(format!("plcsh-signals-slow-{}", std::process::id()));
    std::fs::create_dir_all(&dir).unwrap();
    let script = dir.join("slow.lua");
    std::fs::write(&script, SLOW_HANDLERS).unwrap();
    for i in 1..=20 {
        let mark = (1000 + i).to_string();
        let (mut child, lines) = start_in_group(&[
            "--json",
            "--state",
            "none",
            "--device",
            &device,
            "run",
            script.to_str().unwrap(),
            &mark,
            "100",
        ]);
        let pid = child.id().to_string();
        kill("-TERM", &pid);
        kill("-TERM", &format!("-{pid}"));
        let rest: Vec<String> = lines.map_while(Result::ok).collect();
        assert_eq!(child.wait().unwrap().code(), Some(143), "run {i}: {rest:?}");
        let summary: serde_json::Value = serde_json::from_str(rest.last().expect("a summary")).unwrap();
        assert_eq!((summary["cmd"].as_str(), summary["error"]["kind"].as_str()), (Some("run"), Some("interrupted")));
        assert!(summary["error"]["message"].as_str().unwrap().contains("SIGTERM"), "{summary}");
        assert_eq!(read_back(&device, "VW20"), 1000 + i as i64, "run {i}: the first handler ran");
        assert_eq!(read_back(&device, "VW22"), 1000 + i as i64, "run {i}: the slow handler ran to its end");
    }
}

/// The handlers have a grace period (5 s): a handler that never ends does not keep the
/// process alive; it ends with the first signal's status.
#[test]
fn a_handler_that_never_ends_is_cut_after_the_grace_period() {
    let dir = std::env::temp_dir().join(format!("plcsh-signals-grace-{}", std::process::id()));
    std::fs::create_dir_all(&dir).unwrap();
    let script = dir.join("stuck.lua");
    std::fs::write(
        &script,
        "plcsh.on_abort(function() while true do end end)\nprint('ready')\nplcsh.wait_until(function() return false end, {timeout = 60000})\n",
    )
    .unwrap();
    let (mut child, _) = start_in_group(&["--state", "none", "run", script.to_str().unwrap()]);
    let t = std::time::Instant::now();
    kill("-TERM", &child.id().to_string());
    assert_eq!(child.wait().unwrap().code(), Some(143));
    let took = t.elapsed();
    assert!(took >= std::time::Duration::from_secs(5) && took < std::time::Duration::from_secs(20), "{took:?}");
}

/// `sim serve` stopped by SIGINT or SIGTERM removes what it made, for every family alike:
/// the served UMPK's link and control channel go with the K2's, the drives' and the FX's.
#[test]
fn sim_serve_removes_every_link_on_sigint_and_sigterm() {
    let dir = std::env::temp_dir().join(format!("plcsh-serve-links-{}", std::process::id()));
    std::fs::create_dir_all(&dir).unwrap();
    for sig in ["-INT", "-TERM"] {
        let links: Vec<(&str, std::path::PathBuf)> =
            ["umpk", "servo", "fx", "rtu"].iter().map(|f| (*f, dir.join(format!("tty-{f}{sig}")))).collect();
        let mut args = vec!["sim".to_string(), "serve".into(), "--state".into(), "none".into()];
        args.extend(["--umpk-state".into(), "none".into()]);
        for (family, link) in &links {
            args.push(format!("--{family}-pty"));
            args.push(link.display().to_string());
        }
        let refs: Vec<&str> = args.iter().map(String::as_str).collect();
        let (mut child, _) = start_in_group(&refs);
        let made = |p: &std::path::Path| std::fs::symlink_metadata(p).is_ok();
        for (family, link) in &links {
            assert!(made(link), "{sig}: the {family} link is made");
        }
        let umpk_ctl = dir.join(format!("tty-umpk{sig}.ctl"));
        assert!(made(&umpk_ctl), "{sig}: the UMPK's control channel is made");
        kill(sig, &child.id().to_string());
        let _ = child.wait().unwrap();
        for (family, link) in &links {
            assert!(!made(link), "{sig}: the {family} link {} is removed", link.display());
        }
        assert!(!made(&umpk_ctl), "{sig}: the UMPK's control channel is removed");
    }
    let _ = std::fs::remove_dir_all(&dir);
}
