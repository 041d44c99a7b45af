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

/// The script's file, written once per test process: tests run side by side, and a rewrite
/// (truncate, then write) while another test's plcsh reads it would hand that plcsh an empty
/// script, which ends before its first line.
fn script() -> std::path::PathBuf {
    static FILE: std::sync::OnceLock<std::path::PathBuf> = std::sync::OnceLock::new();
    FILE.get_or_init(|| {
        let dir = std::env::temp_dir().join(format!("plcsh-signals-{}", std::process::id()));
        // Fresh: nothing a previous run left is read.
        let _ = std::fs::remove_dir_all(&dir);
        std::fs::create_dir_all(&dir).unwrap();
        let f = dir.join("wait.lua");
        std::fs::write(&f, SCRIPT).unwrap();
        f
    })
    .clone()
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

/// How a command says it is running, so the signal is sent to the work and not to a process
/// still starting up.
enum Ready {
    /// Its first line on standard output.
    FirstLine,
    /// A child process (a lab's worker) exists: Linux's /proc names it.
    AChild,
}

/// One long-running command of the table below.
struct Case {
    what: &'static str,
    args: Vec<String>,
    stdin: Option<&'static str>,
    ready: Ready,
    /// The statuses for SIGINT, SIGTERM and SIGHUP (docs/reference/exit-status.md).
    statuses: [i32; 3],
}

/// A lab whose one submission spins until it is stopped (its budgets are far away).
fn spinning_lab(dir: &std::path::Path) -> (String, String) {
    let lab = dir.join("lab");
    let _ = std::fs::remove_dir_all(&lab);
    let o = plcsh().args(["lab", "new"]).arg(&lab).output().unwrap();
    assert!(o.status.success(), "{}", both(&o));
    let toml = std::fs::read_to_string(lab.join("lab.toml")).unwrap();
    let toml = toml
        .replace("instructions = 50_000_000", "instructions = 100_000_000_000")
        .replace("wall = \"60s\"", "wall = \"600s\"")
        .replace("\ndevice = \"plc\"", "\naccepts = [\"lua\", \"k2-il\"]\ndevice = \"plc\"");
    assert!(toml.contains("100_000_000_000") && toml.contains("600s") && toml.contains("accepts"), "{toml}");
    std::fs::write(lab.join("lab.toml"), toml).unwrap();
    let spin = dir.join("spin.lua");
    std::fs::write(&spin, "while true do end\n").unwrap();
    (lab.display().to_string(), spin.display().to_string())
}

/// The children of process `pid`, started by any of its threads (Linux), `None` where /proc
/// does not say.
fn children(pid: u32) -> Option<Vec<u32>> {
    std::fs::metadata(format!("/proc/{pid}/task/{pid}/children")).ok()?;
    let mut out = Vec::new();
    for task in std::fs::read_dir(format!("/proc/{pid}/task")).ok()?.flatten() {
        let text = std::fs::read_to_string(task.path().join("children")).unwrap_or_default();
        out.extend(text.split_whitespace().filter_map(|w| w.parse::<u32>().ok()));
    }
    Some(out)
}

/// Every stop signal the docs list, for every long-running command: `sim serve` in each of its
/// modes exits 0 (a stop is its normal end, links removed); `watch`, `trace`, `run`, the REPL
/// reading piped input and `lab grade` exit 128 + the signal (130, 143, 129) — each within the
/// abort grace, never by the signal's default action (which `code()` would show as `None`).
/// (`publish`, which needs a broker, is in tests/publish.rs; the interactive REPL's Ctrl-C,
/// which returns to the prompt, in tests/terminal.rs.)
#[test]
fn every_long_running_command_stops_on_every_listed_signal_with_the_documented_status() {
    let dir = std::env::temp_dir().join(format!("plcsh-signals-table-{}", std::process::id()));
    let _ = std::fs::remove_dir_all(&dir);
    std::fs::create_dir_all(&dir).unwrap();
    let served = serve(&["--tcp", "0", "--state", "none"]);
    let device = format!("plc=tcp://{}?model=K205-16DT", served.ready["tcp"].as_str().unwrap());
    let (lab, spin) = spinning_lab(&dir);
    let bench =
        std::path::Path::new(env!("CARGO_MANIFEST_DIR")).join("machines/pto_servo_encoder.toml").display().to_string();
    let link = |name: &str| dir.join(name).display().to_string();
    let s = |v: &[&str]| v.iter().map(|x| x.to_string()).collect::<Vec<String>>();
    let serve_case = |what: &'static str, mode: Vec<String>| {
        let mut args = s(&["sim", "serve", "--state", "none", "--umpk-state", "none"]);
        args.extend(mode);
        Case { what, args, stdin: None, ready: Ready::FirstLine, statuses: [0, 0, 0] }
    };
    let one_shot = |what: &'static str, line: &str| Case {
        what,
        args: s(&["--json", "--state", "none", "--device", &device, "-c", line]),
        stdin: None,
        ready: Ready::FirstLine,
        statuses: [130, 143, 129],
    };
    let cases = vec![
        serve_case("sim serve --tcp", s(&["--tcp", "0"])),
        serve_case("sim serve --rtu-tcp", s(&["--rtu-tcp", "0"])),
        serve_case("sim serve --rtu-pty", vec!["--rtu-pty".into(), link("rtu")]),
        serve_case("sim serve --servo-tcp", s(&["--servo-tcp", "0"])),
        serve_case("sim serve --servo-pty", vec!["--servo-pty".into(), link("servo")]),
        serve_case("sim serve --fx-tcp", s(&["--fx-tcp", "0"])),
        serve_case("sim serve --fx-pty", vec!["--fx-pty".into(), link("fx")]),
        serve_case("sim serve --fx-link-tcp", s(&["--fx-link-tcp", "0"])),
        serve_case("sim serve --umpk-tcp", s(&["--umpk-tcp", "0"])),
        serve_case("sim serve --umpk-pty", vec!["--umpk-pty".into(), link("umpk")]),
        serve_case("sim serve --fleet", s(&["--fleet", "2", "--tcp", "0"])),
        serve_case("sim serve --rtu-tcp --rfc2217", s(&["--rtu-tcp", "0", "--rfc2217"])),
        serve_case("sim serve --bench", vec!["--bench".into(), bench, "--tcp".into(), "0".into()]),
        one_shot("watch", "watch VW0 every=20ms"),
        // `get` says the line runs; the trace after it would take two minutes.
        one_shot("trace", "get VW0; trace VW0 every=10ms for=120s"),
        Case {
            what: "run",
            args: vec![
                "--state".into(),
                "none".into(),
                "--device".into(),
                device.clone(),
                "run".into(),
                script().display().to_string(),
                "1".into(),
                "wait".into(),
            ],
            stdin: None,
            ready: Ready::FirstLine,
            statuses: [130, 143, 129],
        },
        Case {
            what: "the REPL on piped input, at its prompt",
            args: s(&["--state", "none", "--time", "stepped"]),
            stdin: Some("get VW0\n"),
            ready: Ready::FirstLine,
            statuses: [130, 143, 129],
        },
        Case {
            what: "lab grade",
            args: vec!["--json".into(), "lab".into(), "grade".into(), lab.clone(), spin.clone()],
            stdin: None,
            ready: Ready::AChild,
            statuses: [130, 143, 129],
        },
    ];
    if children(std::process::id()).is_none() {
        skipped("/proc/PID/task/PID/children (Linux) for the lab grade row");
    }
    for case in &cases {
        if matches!(case.ready, Ready::AChild) && children(std::process::id()).is_none() {
            continue;
        }
        for (sig, want) in ["-INT", "-TERM", "-HUP"].iter().zip(case.statuses) {
            let refs: Vec<&str> = case.args.iter().map(String::as_str).collect();
            let mut cmd = plcsh();
            cmd.args(&refs).stdout(Stdio::piped()).stderr(Stdio::piped());
            cmd.stdin(if case.stdin.is_some() { Stdio::piped() } else { Stdio::null() });
            let mut child = cmd.spawn().unwrap();
            // The input stays open (an idle prompt, not an end of input).
            let mut input = child.stdin.take();
            if let (Some(i), Some(text)) = (input.as_mut(), case.stdin) {
                use std::io::Write;
                // A plcsh that already ended fails the readiness wait below with its output;
                // a broken pipe here says nothing more.
                let _ = i.write_all(text.as_bytes());
            }
            let mut lines = BufReader::new(child.stdout.take().unwrap()).lines();
            let deadline = std::time::Instant::now() + std::time::Duration::from_secs(30);
            match case.ready {
                Ready::FirstLine => {
                    let first = lines.next().unwrap_or_else(|| {
                        // Ended before its first line: what it said on its error output is the why.
                        let mut err = String::new();
                        if let Some(mut e) = child.stderr.take() {
                            use std::io::Read;
                            let _ = e.read_to_string(&mut err);
                        }
                        panic!("{} ({sig}): no first line; status {:?}; error output: {err}", case.what, child.wait())
                    });
                    let first = first.unwrap();
                    assert!(!first.is_empty(), "{}", case.what);
                }
                Ready::AChild => {
                    while children(child.id()).unwrap_or_default().is_empty() {
                        assert!(std::time::Instant::now() < deadline, "{}: no worker started", case.what);
                        std::thread::sleep(std::time::Duration::from_millis(20));
                    }
                }
            }
            // The output is read to its end meanwhile (a full pipe must not hold the stop up).
            let reader = std::thread::spawn(move || lines.map_while(Result::ok).collect::<Vec<String>>());
            let sent = std::time::Instant::now();
            kill(sig, &child.id().to_string());
            // A command that ignores the signal fails the test, not hangs it.
            let status = loop {
                if let Some(st) = child.try_wait().unwrap() {
                    break st;
                }
                if sent.elapsed() > std::time::Duration::from_secs(30) {
                    let _ = child.kill();
                    panic!("{} still runs 30 s after {sig}", case.what);
                }
                std::thread::sleep(std::time::Duration::from_millis(20));
            };
            drop(input);
            let took = sent.elapsed();
            let rest = reader.join().unwrap();
            let mut err = String::new();
            {
                use std::io::Read;
                let _ = child.stderr.take().unwrap().read_to_string(&mut err);
            }
            assert_eq!(
                status.code(),
                Some(want),
                "{} stopped by {sig}: {status:?} after {took:?}\nstdout: {rest:?}\nstderr: {err}",
                case.what
            );
            assert!(took < std::time::Duration::from_secs(20), "{} took {took:?} to stop on {sig}", case.what);
        }
    }
    for l in ["rtu", "servo", "fx", "umpk"] {
        assert!(std::fs::symlink_metadata(dir.join(l)).is_err(), "the {l} link was removed at every stop");
    }
    let _ = std::fs::remove_dir_all(&dir);
}
