//! Many plcsh at once, and devices that are not there yet.
//!
//! One plcsh that uses the simulated PLC holds its state file ("one plcsh per state file",
//! docs/state.md). Every other plcsh must still run whatever does not need that simulator:
//! every command-line subcommand and every shell command is gone over here while another
//! process holds the file, and the ones that do need it say who holds it and what to do.
//! A shell opened before its device answers stays open and connects at a later command.

mod common;
use common::*;
use std::io::{BufRead, BufReader, Write};
use std::path::{Path, PathBuf};
use std::process::{Child, ChildStdin, Stdio};

fn dir(name: &str) -> PathBuf {
    let d = std::env::temp_dir().join(format!("plcsh-many-{}-{name}", std::process::id()));
    let _ = std::fs::remove_dir_all(&d);
    std::fs::create_dir_all(&d).unwrap();
    d
}

/// A plcsh batch session that has used the simulated PLC with `state` (so it holds the file),
/// kept alive until dropped.
struct Holder {
    child: Child,
    stdin: Option<ChildStdin>,
}

impl Holder {
    fn start(state: &Path) -> Holder {
        let mut cmd = plcsh();
        cmd.env_remove("PLCSH_STATE").args(["--json", "--state"]).arg(state);
        let mut child = cmd.stdin(Stdio::piped()).stdout(Stdio::piped()).stderr(Stdio::inherit()).spawn().unwrap();
        let mut stdin = child.stdin.take().unwrap();
        writeln!(stdin, "set VW3700=77").unwrap();
        stdin.flush().unwrap();
        let mut line = String::new();
        BufReader::new(child.stdout.take().unwrap()).read_line(&mut line).unwrap();
        assert!(line.contains("\"ok\":true"), "the holder wrote VW3700: {line}");
        Holder { child, stdin: Some(stdin) }
    }
}

impl Drop for Holder {
    fn drop(&mut self) {
        drop(self.stdin.take());
        let _ = self.child.wait();
    }
}

/// plcsh with the held state file (the default file of a user, as `PLCSH_STATE` names it).
fn with_state(state: &Path, args: &[&str], dir: &Path) -> std::process::Output {
    let mut c = plcsh();
    c.env("PLCSH_STATE", state).current_dir(dir).args(args).stdin(Stdio::null());
    c.output().unwrap()
}

fn held_message(o: &std::process::Output, pid: u32) -> bool {
    let text = both(o);
    text.contains(&format!("is in use by process {pid}")) && text.contains("--state")
}

/// Every subcommand of the command line, and whether it needs the default simulated PLC.
/// A new subcommand fails `the_command_line_is_classified` until it is listed here.
const SUBCOMMANDS: &[(&str, &[&str], bool)] = &[
    ("models", &["models"], false),
    ("devices", &["devices"], false),
    ("ports", &["ports"], false),
    ("paths", &["paths"], false),
    ("completions", &["completions", "bash"], false),
    ("man", &["man"], false),
    ("sim", &["sim", "control", "--help"], false),
    ("agent", &["agent", "il"], false),
    ("probe", &["probe", "--help"], false),
    ("run", &["run", "drive_only.lua"], false),
    ("record", &["record", "show", "missing.pcapng"], false),
    ("replay", &["replay", "missing.pcapng"], false),
    ("lab", &["lab", "check", "no-such-lab"], false),
    ("publish", &["publish", "--help"], false),
    ("tags", &["tags", "check", "missing.csv"], false),
];

/// Lines of every shell command, and whether each needs the simulated PLC (the current device).
const SHELL_LINES: &[(&str, bool)] = &[
    ("get VW0", true),
    ("get servo:statusword", false),
    ("set VW0=1", true),
    ("set servo:controlword=6", false),
    ("read VW0..VW2", true),
    ("use servo; get statusword", false),
    ("devices", false),
    ("connect press sim:K209EA-50DX; get press:VW0", false),
    ("close plc; devices", false),
    ("sim step 1ms", true),
    ("watch VW0", true),
    ("trace VW0", true),
    ("plot", true),
    ("servo status", false),
    ("umpk", false),
    ("pls 0", true),
    ("pstop 0", true),
    ("pto 0 status", true),
    ("pwm 0", true),
    ("profile 0", true),
    ("hdef 0 0", true),
    ("hsc 0 status", true),
    ("events", true),
    ("wait 1ms", true),
    ("rtc", true),
    ("eeprom status", true),
    ("lua print(1)", false),
    ("lua print(plc.VW0)", true),
    ("agent", true),
    ("lab", false),
    ("models", false),
    ("ports", false),
    ("paths", false),
    ("help", false),
    ("help SMB67", false),
    ("quit", false),
];

#[test]
fn every_shell_command_is_classified() {
    for spec in plcsh::shell::commands::COMMANDS {
        assert!(
            SHELL_LINES.iter().any(|(l, _)| l.split_whitespace().next() == Some(spec.name)),
            "shell command `{}`: add a line to SHELL_LINES saying whether it needs the simulated PLC",
            spec.name
        );
    }
}

#[test]
fn the_command_line_is_classified() {
    use clap::CommandFactory;
    for sub in plcsh::cli::Cli::command().get_subcommands() {
        let name = sub.get_name();
        if name == "help" {
            continue;
        }
        assert!(
            SUBCOMMANDS.iter().any(|(n, _, _)| *n == name),
            "subcommand `{name}`: say in SUBCOMMANDS whether it needs the simulated PLC"
        );
    }
}

#[test]
fn one_shell_holding_the_state_file_locks_out_nothing_that_does_not_need_it() {
    let d = dir("held");
    let state = d.join("state.json");
    std::fs::write(d.join("drive_only.lua"), "local s = plcsh.device(\"servo\")\nprint(s:status() ~= nil)\n").unwrap();
    let holder = Holder::start(&state);
    let pid = holder.child.id();

    // Every subcommand of the command line.
    for (name, args, needs_plc) in SUBCOMMANDS {
        let o = with_state(&state, args, &d);
        assert_eq!(held_message(&o, pid), *needs_plc, "plcsh {args:?} ({name}): {}", both(&o));
        assert!(!both(&o).contains("is in use"), "plcsh {args:?}: {}", both(&o));
    }
    // `sim serve` serves simulators of its own.
    let mut serve = plcsh();
    serve.env("PLCSH_STATE", &state).args(["sim", "serve", "--tcp", "127.0.0.1:0"]).stdout(Stdio::piped());
    let mut served = serve.stderr(Stdio::piped()).spawn().unwrap();
    let mut line = String::new();
    BufReader::new(served.stdout.take().unwrap()).read_line(&mut line).unwrap();
    assert!(line.contains("\"ready\":true"), "sim serve while the state file is held: {line}");
    let _ = served.kill();
    let _ = served.wait();

    // Every command of the shell: a line that needs the simulated PLC names the holder; a line
    // that does not never mentions it.
    for (line, needs_plc) in SHELL_LINES {
        let o = with_state(&state, &["--json", "-c", line], &d);
        assert_eq!(held_message(&o, pid), *needs_plc, "`{line}`: {}", both(&o));
        if !needs_plc {
            assert!(!both(&o).contains("is in use"), "`{line}` does not need plc: {}", both(&o));
        } else {
            assert_eq!(o.status.code(), Some(1), "`{line}`: the command failed");
        }
    }
    // The drive and help work in the same invocation style a second terminal uses.
    let o = with_state(&state, &["-c", "help; servo status; ports"], &d);
    assert!(o.status.success(), "{}", both(&o));
    // Reading the PLC names the holder and what to do instead.
    let o = with_state(&state, &["-c", "get VW3700"], &d);
    assert!(held_message(&o, pid), "{}", both(&o));
    assert_eq!(o.status.code(), Some(1));
    drop(holder);
    // The holder has gone: the next plcsh takes the file and sees what the first kept.
    let o = with_state(&state, &["-c", "get VW3700"], &d);
    assert!(o.status.success() && stdout(&o).contains("77"), "{}", both(&o));
    let _ = std::fs::remove_dir_all(&d);
}

#[test]
fn fleets_and_publishers_never_take_the_state_file() {
    let d = dir("fleet");
    let state = d.join("state.json");
    let config = d.join("devices.toml");
    std::fs::write(
        &config,
        "[devices.a]\nurl = \"sim:K205-16DT\"\n[devices.b]\nurl = \"sim:K205-16DT\"\n[fleets.two]\ndevices = [\"a\", \"b\"]\n",
    )
    .unwrap();
    let holder = Holder::start(&state);
    let o = with_state(&state, &["--config", config.to_str().unwrap(), "-f", "two", "-c", "get VW0"], &d);
    assert!(!both(&o).contains("is in use"), "{}", both(&o));
    assert!(o.status.success(), "{}", both(&o));
    drop(holder);
    let _ = std::fs::remove_dir_all(&d);
}

/// `printf 'get VW0\nget VW0\n' | plcsh -d rtu:LINK` where LINK appears between the lines:
/// the first line says not connected, the shell stays open, the second reads the PLC.
#[cfg(unix)]
#[test]
fn a_shell_opened_before_the_cabinet_is_powered_connects_at_a_later_command() {
    let d = dir("later");
    let link = d.join("k2-line");
    let url = format!("rtu:{}?baud=19200", link.display());
    let mut child = plcsh()
        .args(["--json", "-d", &url])
        .stdin(Stdio::piped())
        .stdout(Stdio::piped())
        .stderr(Stdio::piped())
        .spawn()
        .unwrap();
    let mut stdin = child.stdin.take().unwrap();
    let mut out = BufReader::new(child.stdout.take().unwrap());
    writeln!(stdin, "get VW0").unwrap();
    stdin.flush().unwrap();
    let mut line = String::new();
    out.read_line(&mut line).unwrap();
    let first: serde_json::Value = serde_json::from_str(&line).unwrap();
    assert_eq!(first["ok"], false, "{line}");
    assert_eq!(first["error"]["kind"], "link", "{line}");
    assert!(first["error"]["hint"].as_str().unwrap_or("").contains("next command"), "{line}");
    // The cabinet is powered: a simulated K2 answers on that line now.
    let served = serve(&["--rtu-pty", link.to_str().unwrap()]);
    writeln!(stdin, "set VW0=5\nget VW0").unwrap();
    drop(stdin);
    let rest: Vec<serde_json::Value> =
        out.lines().map(|l| serde_json::from_str(&l.unwrap()).unwrap()).collect::<Vec<_>>();
    let o = child.wait_with_output().unwrap();
    assert_eq!(rest.len(), 2, "{rest:?} {}", stderr(&o));
    assert!(rest.iter().all(|r| r["ok"] == true), "{rest:?}");
    assert_eq!(rest[1]["values"][0]["value"], 5, "{rest:?}");
    assert!(stderr(&o).contains("not connected"), "{}", stderr(&o));
    assert_eq!(o.status.code(), Some(1), "one line failed");
    drop(served);
    let _ = std::fs::remove_dir_all(&d);
}

#[test]
fn a_device_not_there_yet_shows_in_the_prompt_and_in_devices() {
    let mut s = plcsh::session::Session::new(plcsh::core::Clock::stepped());
    let e = s.open_or_later("plc", "rtu:./no-such-port?baud=19200&model=K205-16DT").unwrap();
    assert!(e.is_some(), "the port is missing: opened later");
    assert_eq!(plcsh::shell::repl::prompt(&s), "plc(not connected)> ");
    // Its model is known from the URL: the listing still says it is not connected, in the
    // table and in JSON.
    let url = "rtu:./no-such-port?baud=19200&model=K205-16DT";
    let o = run(&["-d", url], "devices\n");
    let row = stdout(&o).lines().find(|l| l.contains("no-such-port")).map(str::to_string);
    assert!(row.as_deref().is_some_and(|r| r.contains("(not connected)") && r.contains("K205-16DT")), "{}", both(&o));
    let o = run(&["--json", "-d", url], "devices\n");
    let j = json_lines(&o);
    let named = |j: &serde_json::Value, name: &str| {
        j["devices"].as_array().and_then(|d| d.iter().find(|d| d["name"] == name)).cloned().unwrap_or_default()
    };
    assert_eq!(named(&j[0], "plc")["connected"], false, "{j:?}");
    assert_eq!(named(&j[0], "plc")["model"], "K205-16DT", "{j:?}");
    // The simulated drive beside it is connected, and says so.
    assert_eq!(named(&j[0], "servo")["connected"], true, "{j:?}");
}

#[test]
fn a_one_shot_still_fails_with_the_link_error() {
    let o = run(&["--json", "-d", "rtu:./no-such-port?baud=19200", "-c", "get VW0"], "");
    assert_eq!(o.status.code(), Some(1), "{}", both(&o));
    let j = json_lines(&o);
    assert_eq!(j[0]["error"]["kind"], "link", "{j:?}");
}

#[test]
fn a_batch_on_a_missing_port_reports_each_line_and_stays_open() {
    let o = run(&["--json", "-d", "rtu:./no-such-port?baud=19200"], "get VW0\nget VW0\n");
    let j = json_lines(&o);
    assert_eq!(j.len(), 2, "each line has its answer: {}", both(&o));
    assert!(j.iter().all(|r| r["error"]["kind"] == "link"), "{j:?}");
    assert_eq!(o.status.code(), Some(1));
    assert!(stderr(&o).contains("not connected"), "{}", stderr(&o));
}
