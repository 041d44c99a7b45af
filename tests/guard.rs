//! The write guard holds for every command and every Lua method: the whole command
//! registry and the Lua bridge are walked, and every command or method that can change a
//! device runs against a `read_only` profile and against an `allow` list that permits
//! exactly one operand — on a simulated K2, a simulated drive, a K2 over Modbus TCP with
//! the PLC-side helper (`plcsh sim serve --agent`) and a drive on a pseudo-terminal. Each
//! must be refused naming the rule, the profile and its file:line, and leave the device's
//! state as it was.
//!
//! A new command (or bridge row) must be listed below as changing a device — with lines
//! that exercise it — or as not changing one, with the reason; until then
//! `every_command_and_bridge_row_is_classified` fails.

mod common;
use common::*;

use plcsh::core::Clock;
use plcsh::output::Style;
use plcsh::profile::Profiles;
use plcsh::session::Session;
use plcsh::shell::commands::COMMANDS;
use plcsh::shell::Shell;
use std::path::{Path, PathBuf};

/// Commands that change a K2, with lines that make them change it (device `plc`).
const K2_WRITES: &[(&str, &[&str])] = &[
    ("set", &["set VW102=5", "set VW100=1, VW102=5", "set SMB67=16#85"]),
    ("pls", &["pls 0"]),
    ("pstop", &["pstop 0"]),
    ("pto", &["pto 0 freq=2kHz count=100"]),
    ("pwm", &["pwm 0 cycle=1ms width=250us"]),
    ("profile", &["profile 0 at VB3001 [(cycle=500us, count=100)]"]),
    ("hdef", &["hdef 0 0"]),
    ("hsc", &["hsc 0", "hsc 0 mode=0 cv=5"]),
    ("rtc", &["rtc set 2001-01-01T00:00:00", "rtc sync"]),
    ("eeprom", &["eeprom restore {backup}"]),
    ("data", &["data load {dataset}"]),
    ("lua", &["lua plc.VW102 = 5", "lua plc:set(\"VW102=5\")", "lua plc:cmd(\"pls 0\")"]),
];

/// Commands that change a servo drive (device `servo`).
const SERVO_WRITES: &[(&str, &[&str])] = &[
    ("set", &["set controlword=6"]),
    (
        "servo",
        &[
            "servo enable",
            "servo disable",
            "servo fault-reset",
            "servo quickstop",
            "servo mode velocity",
            "servo move abs 1000",
            "servo move rel 10 speed=100rpm",
            "servo jog 100rpm",
            "servo home method=35",
            "servo halt",
            "servo save",
            "servo params load {params}",
            "servo raw 01 2B 40 60 00 0F 00 00 00",
            "servo raw 01 2F 60 60 00 03 00 00 00",
        ],
    ),
    ("lua", &["lua servo.controlword = 6"]),
];

/// Commands that change no device, and why.
const NOT_WRITES: &[(&str, &str)] = &[
    ("get", "reads"),
    ("read", "reads"),
    ("use", "session: picks the current device"),
    ("devices", "session: lists devices"),
    ("ports", "lists this computer's serial ports; touches no device"),
    ("paths", "prints where plcsh keeps its files; touches no device"),
    ("connect", "session: opens a device"),
    ("close", "session: closes a device"),
    ("sim", "simulation controls: the simulated world around a device (clock, input signals, retention)"),
    ("watch", "reads"),
    ("trace", "reads"),
    ("plot", "renders a recorded trace"),
    ("events", "reads plcsh's own interrupt event log"),
    ("wait", "reads plcsh's own interrupt event log"),
    ("agent", "reads the helper's status"),
    ("lab", "builds its own simulators from a lab folder in worker processes; touches no device of the session"),
    ("help", "text"),
    ("quit", "session"),
    ("models", "text: the model catalogue"),
    ("umpk", "a UMPK command: its changes (reset, echo, program, errors clear, send) are walked in umpk_commands_that_change_the_controller_are_refused"),
];

/// Lua methods that change a device, with a call that makes them.
const BRIDGE_WRITES: &[(&str, &str)] = &[
    ("cmd", "plc:cmd(\"pstop 0\")"),
    ("pls", "plc:pls(0)"),
    ("pstop", "plc:pstop(0)"),
    ("pto", "plc:pto(0, {freq=2000, count=100})"),
    ("pwm", "plc:pwm(0, {cycle=1000, width=250})"),
    ("profile", "plc:profile(0, \"VB3001\", {{cycle=500, count=100}})"),
    ("hdef", "plc:hdef(0, 0)"),
    ("hsc", "plc:hsc(0, {mode=0, cv=5})"),
    ("rtc_set", "plc:rtc_set(\"2001-01-01T00:00:00\")"),
    ("rtc_sync", "plc:rtc_sync()"),
    ("eeprom_restore", "plc:eeprom_restore(\"{backup}\")"),
    ("data_load", "plc:data_load(\"{dataset}\")"),
    ("enable", "servo:enable()"),
    ("disable", "servo:disable()"),
    ("fault_reset", "servo:fault_reset()"),
    ("quickstop", "servo:quickstop()"),
    ("mode", "servo:mode(\"velocity\")"),
    ("move_abs", "servo:move_abs(1000, {rpm=100})"),
    ("move_rel", "servo:move_rel(10)"),
    ("jog", "servo:jog{rpm=100}"),
    ("home", "servo:home()"),
    ("save", "servo:save()"),
    ("params_load", "servo:params_load(\"{params}\")"),
    ("halt", "servo:halt()"),
    ("umpk_reset", "lab:umpk_reset()"),
    ("umpk_echo", "lab:umpk_echo(\"off\")"),
    ("umpk_clear_errors", "lab:umpk_clear_errors()"),
    ("umpk_program", "lab:umpk_program(\"{hex}\")"),
    ("umpk_send", "lab:umpk_send(\"?03FD\")"),
];

/// Lua methods that change no device, and why.
const BRIDGE_NOT_WRITES: &[(&str, &str)] = &[
    ("read", "reads"),
    ("help", "text"),
    ("pto_status", "reads"),
    ("hsc_status", "reads"),
    ("events", "plcsh's own event log"),
    ("wait_event", "plcsh's own event log"),
    ("rtc", "reads"),
    ("agent_status", "reads"),
    ("eeprom_dump", "reads the device, writes a host file"),
    ("data_save", "reads the device, writes a host file"),
    ("data_diff", "reads"),
    ("eeprom_status", "reads the simulator's wear counters"),
    ("eeprom_area", "where plcsh takes the backup area to end (client-side; simulator configuration)"),
    ("sim_input", "simulation control"),
    ("sim_quad", "simulation control"),
    ("sim_off", "simulation control"),
    ("sim_inputs", "simulation control"),
    ("status", "reads"),
    ("params_save", "reads the drive, writes a host file"),
    ("params_diff", "reads"),
    ("wait_target", "reads"),
    ("encoder", "client-side unit conversion"),
    ("sim_fault", "simulation control"),
    ("sim_switch", "simulation control"),
    ("sim_pulses", "simulation control"),
    ("inject_fault", "simulation control"),
    ("injected_faults", "simulation control"),
    ("program_load", "simulation control: the simulated CPU"),
    ("program", "simulation control: the simulated CPU"),
    ("cpu", "simulation control: the simulated CPU"),
    ("scan", "simulation control: the simulated CPU"),
    ("breakpoint", "simulation control: the simulated CPU"),
    ("step_instruction", "simulation control: the simulated CPU"),
    ("step_network", "simulation control: the simulated CPU"),
    ("trace", "reads (samples returned to the script)"),
    ("umpk_info", "reads"),
    ("umpk_program_info", "reads"),
    ("umpk_errors", "reads"),
    ("umpk_timing", "reads"),
    ("umpk_monitor", "reads"),
    ("umpk_sim_input", "simulation control"),
    ("umpk_sim_reference", "simulation control"),
];

#[test]
fn every_command_and_bridge_row_is_classified() {
    for c in COMMANDS {
        let writes = K2_WRITES.iter().chain(SERVO_WRITES).any(|(n, _)| *n == c.name);
        let not = NOT_WRITES.iter().any(|(n, _)| *n == c.name);
        assert!(
            writes != not,
            "command `{}`: list it in K2_WRITES/SERVO_WRITES (with lines that change the device) or in NOT_WRITES (with why)",
            c.name
        );
    }
    for b in plcsh::script::bridge::BRIDGE {
        let writes = BRIDGE_WRITES.iter().any(|(n, _)| *n == b.method);
        let not = BRIDGE_NOT_WRITES.iter().any(|(n, _)| *n == b.method);
        assert!(writes != not, "Lua method `{}`: list it in BRIDGE_WRITES or BRIDGE_NOT_WRITES", b.method);
    }
}

/// A scratch directory for one test.
fn scratch(tag: &str) -> PathBuf {
    let d = std::env::temp_dir().join(format!("plcsh-guard-{}-{tag}", std::process::id()));
    std::fs::create_dir_all(&d).unwrap();
    d
}

/// The two rule sets, as profiles `ro` and `one` for `url`; `one` allows only `allowed`.
fn profiles(dir: &Path, url: &str, allowed: &str) -> (PathBuf, Profiles) {
    let text = format!(
        "[devices.ro]\nurl = \"{url}\"\nread_only = true\n\n[devices.one]\nurl = \"{url}\"\nallow = [\"{allowed}\"]\n"
    );
    let f = dir.join("devices.toml");
    std::fs::write(&f, &text).unwrap();
    let p = Profiles::parse(&text, &f);
    assert!(p.problems.is_empty(), "{:?}", p.problems);
    (f, p)
}

fn shell(clock: Clock, p: &Profiles, name: &str, profile: &str) -> Shell {
    let mut s = Session::new(clock);
    s.profiles = p.clone();
    s.open(name, profile).unwrap_or_else(|e| panic!("open {profile}: {e}"));
    let mut sh = Shell::new(s, Style::detect(true));
    plcsh::script::install(&mut sh);
    sh
}

/// Runs a line; returns the error text of its first failing command.
fn refusal(sh: &mut Shell, line: &str) -> Option<String> {
    sh.exec(line).into_iter().find_map(|r| r.err()).map(|(_, e)| {
        format!("{} | {} | {}", e.message, e.operand.clone().unwrap_or_default(), e.hint.clone().unwrap_or_default())
    })
}

fn ok(sh: &mut Shell, line: &str) {
    if let Some(e) = refusal(sh, line) {
        panic!("{line}: {e}");
    }
}

/// Everything a K2 command could change, read through the guarded device: V (without
/// the helper's mailbox and scratch bytes VB3400…VB3587, which the helper program itself
/// writes as it runs), SM (the registers the manual gives the model — what the helper
/// reaches — without SMB0's clock bits), Q, M, the clock's year.
fn k2_state(sh: &mut Shell) -> Vec<String> {
    let mut lines = Vec::new();
    let model = plcsh::k2::catalog::lookup("K205-16DT").unwrap();
    let sm: Vec<String> =
        plcsh::k2::agent::protocol::sm_rows(model).into_iter().filter(|b| *b != 0).map(|b| format!("SMB{b}")).collect();
    let sm: Vec<&str> = sm.iter().map(String::as_str).collect();
    let got = sh.session.get(&sm).unwrap_or_else(|e| panic!("get SM rows: {e}"));
    lines.extend(got.iter().map(|(_, r)| format!("{}={}", r.operand, r.value)));
    for r in ["VB0..VB3399", "VB3588..VB4095", "QB0..QB1", "MB0..MB31"] {
        let got = sh.session.get(&[r]).unwrap_or_else(|e| panic!("get {r}: {e}"));
        lines.extend(got.iter().map(|(_, r)| format!("{}={}", r.operand, r.value)));
    }
    let rtc = sh.exec("rtc").remove(0).expect("rtc reads");
    lines.push(format!("rtc year {}", &rtc.data["rtc"].as_str().unwrap()[..4]));
    lines
}

/// Every readable object of the drive.
fn servo_state(sh: &mut Shell) -> Vec<String> {
    let names: Vec<&str> = plcsh::servo::objects::OBJECTS.iter().filter(|o| o.readable()).map(|o| o.name).collect();
    let got = sh.session.get(&names).unwrap_or_else(|e| panic!("get {names:?}: {e}"));
    got.iter().map(|(_, r)| format!("{}={}", r.operand, r.value)).collect()
}

/// The entries that differ (at most 8), for a readable failure.
fn diff(a: &[String], b: &[String]) -> Vec<String> {
    a.iter().zip(b).filter(|(x, y)| x != y).take(8).map(|(x, y)| format!("{x} → {y}")).collect()
}

/// Runs every write line and Lua call for `family` against both rule sets.
fn walk(url: &str, family: &str, clock: impl Fn() -> Clock) {
    let tag = url.replace(|c: char| !c.is_ascii_alphanumeric(), "_");
    let dir = scratch(&tag);
    let (name, allowed, allowed_write, lines, state): (_, _, _, _, fn(&mut Shell) -> Vec<String>) = if family == "k2" {
        ("plc", "VW100", "set VW100=7", K2_WRITES, k2_state)
    } else {
        ("servo", "target_position", "set target_position=7", SERVO_WRITES, servo_state)
    };
    let (file, p) = profiles(&dir, url, allowed);
    let backup = dir.join("backup.bin");
    std::fs::write(&backup, [1u8, 2, 3, 4]).unwrap();
    // A parameter set that differs from the drive's (profile_velocity), for `servo params load`.
    let params = dir.join("params.toml");
    std::fs::write(
        &params,
        "[drive]\ntype = \"Kinco servo\"\nmodel = \"m\"\nid = 1\nurl = \"u\"\nsaved = \"t\"\nplcsh = \"v\"\nencoder_resolution = 10000\n\n[[parameter]]\nname = \"profile_velocity\"\nobject = \"6081.00\"\ntype = \"u32\"\nunit = \"DEC\"\nvalue = 1234\n",
    )
    .unwrap();
    // A data set that differs from the PLC's (VW102), for `data load`.
    let dataset = dir.join("data.toml");
    std::fs::write(
        &dataset,
        "[device]\nfamily = \"k2\"\nmodel = \"K205-16DT\"\nname = \"plc\"\nurl = \"u\"\nsaved = \"t\"\nplcsh = \"v\"\n\n[set]\nvalues = [{ operand = \"VW102\", type = \"WORD\", value = 4321 }]\n",
    )
    .unwrap();
    let subst = |l: &str| {
        l.replace("{backup}", backup.to_str().unwrap())
            .replace("{params}", params.to_str().unwrap())
            .replace("{dataset}", dataset.to_str().unwrap())
    };
    let mut calls: Vec<String> = lines.iter().flat_map(|(_, ls)| ls.iter().map(|l| subst(l))).collect();
    let prefix = format!("{name}:");
    calls
        .extend(BRIDGE_WRITES.iter().filter(|(_, c)| c.starts_with(&prefix)).map(|(_, c)| format!("lua {}", subst(c))));
    assert!(calls.len() > 8, "{calls:?}");
    for (profile, rule) in [("ro", "read_only"), ("one", "allow list")] {
        let mut sh = shell(clock(), &p, name, profile);
        let before = state(&mut sh);
        for line in &calls {
            let e = refusal(&mut sh, line).unwrap_or_else(|| panic!("{family} {profile}: `{line}` was not refused"));
            assert!(
                e.contains(rule)
                    && e.contains(&format!("profile `{profile}`"))
                    && e.contains(&format!("{}:", file.display())),
                "{family} {profile}: `{line}`: the refusal names the rule, profile and file:line: {e}"
            );
            let now = state(&mut sh);
            assert!(now == before, "{family} {profile}: `{line}` changed the device: {:?}", diff(&before, &now));
        }
        if profile == "one" {
            ok(&mut sh, allowed_write);
            assert_ne!(state(&mut sh), before, "the one allowed operand is written");
        }
    }
    if family == "k2" {
        // The clock is allowed by name.
        let text = format!("[devices.clock]\nurl = \"{url}\"\nallow = [\"clock\"]\n");
        let p = Profiles::parse(&text, &dir.join("clock.toml"));
        let mut sh = shell(clock(), &p, name, "clock");
        ok(&mut sh, "rtc set 2001-01-01T00:00:00");
        assert!(refusal(&mut sh, "set VW0=1").unwrap().contains("allow list"));
    }
}

#[test]
fn every_write_is_refused_on_a_simulated_k2() {
    walk("sim:K205-16DT", "k2", Clock::stepped);
}

#[test]
fn every_write_is_refused_on_a_simulated_drive() {
    walk("sim-servo:?id=1", "servo", Clock::stepped);
}

#[test]
fn every_write_is_refused_on_a_k2_over_modbus_tcp_with_the_helper() {
    let served = serve(&["--tcp", "0", "--agent", "--state", "none"]);
    let url = format!("tcp://{}?model=K205-16DT&agent=VB3400", served.ready["tcp"].as_str().unwrap());
    walk(&url, "k2", Clock::following);
}

#[test]
fn every_write_is_refused_on_a_drive_over_a_pty() {
    let dir = scratch("pty");
    let link = dir.join("ttyKINCO");
    let _served = serve(&["--servo-pty", link.to_str().unwrap()]);
    // A generous timeout: the served line is paced like RS232, and a loaded CI machine can
    // delay a reply past the default 200 ms; this test is about refusals, not timing.
    walk(&format!("kinco:{}?id=1&timeout=2s", link.display()), "servo", Clock::following);
}

#[test]
fn the_session_wide_read_only_switch_refuses_every_change_and_shows_in_the_prompt() {
    let mut s = Session::new(Clock::stepped());
    s.open("plc", "sim:K205-16DT").unwrap();
    s.open("servo", "sim-servo:?id=1").unwrap();
    assert_eq!(plcsh::shell::repl::prompt(&s), "plc(sim)> ");
    s.set_read_only(true);
    assert_eq!(plcsh::shell::repl::prompt(&s), "plc(sim, read-only)> ");
    let mut sh = Shell::new(s, Style::detect(true));
    for line in ["set VW0=1", "pls 0", "rtc sync", "servo enable", "hsc 0 mode=0"] {
        let e = refusal(&mut sh, line).unwrap_or_else(|| panic!("`{line}` was not refused"));
        assert!(e.contains("--read-only"), "{line}: {e}");
    }
    ok(&mut sh, "get VW0; servo status; rtc");
    let o = run(&["--read-only", "--state", "none", "-c", "set VW0=1"], "");
    assert!(!o.status.success());
    let text = stdout(&o) + &String::from_utf8_lossy(&o.stderr);
    assert!(text.contains("read-only"), "{text}");
}

/// Simulated and real are never confused: a real K2 named on the command line opens no
/// simulated `plc` beside it, and every line that moves something says which it was.
#[test]
fn a_real_device_opens_no_default_simulator_and_moving_lines_say_sim_or_real() {
    let served = serve(&["--tcp", "0", "--agent", "--state", "none"]);
    let url = format!("tcp://{}?model=K205-16DT&agent=VB3400", served.ready["tcp"].as_str().unwrap());
    let press = format!("press={url}");
    let o = run(&["--json", "--state", "none", "--device", &press, "-c", "devices"], "");
    let l = json_lines(&o);
    let names: Vec<&str> = l[0]["devices"].as_array().unwrap().iter().map(|d| d["name"].as_str().unwrap()).collect();
    assert!(!names.contains(&"plc"), "no simulated plc beside the real K2: {names:?}");
    assert!(names.contains(&"press") && names.contains(&"servo"), "{names:?}");
    let o = run(&["--state", "none", "--device", &press, "-c", "set SMB67=16#85, SMW68=500, SMD72=10; pls 0"], "");
    let text = stdout(&o);
    assert!(o.status.success() && text.contains("press(real): "), "{text}");
    let o = run(&["--state", "none", "--time", "stepped", "-c", "set SMB67=16#85, SMW68=500, SMD72=10; pls 0"], "");
    assert!(stdout(&o).contains("plc(sim): PTO0"), "{}", stdout(&o));
    let o = run(&["--json", "--state", "none", "--time", "stepped", "-c", "servo enable; servo move abs 100"], "");
    for v in json_lines(&o) {
        assert_eq!(v["simulated"], true, "{v}");
        assert!(v["message"].as_str().unwrap().starts_with("servo(sim): "), "{v}");
    }
}

/// The UMPK's commands that change the controller (reset, echo, programming, clearing the
/// error history, a hand-typed command) are refused whole under `read_only` and under an
/// allow list (which names operands: none of these is one), naming the rule.
#[test]
fn umpk_commands_that_change_the_controller_are_refused() {
    let dir = scratch("umpk");
    let hex = dir.join("p.hex");
    std::fs::write(&hex, ":0400000001020304F2\n:00000001FF\n").unwrap();
    let (file, p) = profiles(&dir, "sim-umpk:UMPK16", "M0");
    let hexs = hex.to_str().unwrap();
    let lines: Vec<String> = ["umpk reset", "umpk echo off", "umpk errors clear", "umpk send ?03FD"]
        .iter()
        .map(|l| l.to_string())
        .chain([format!("umpk program {hexs}")])
        .chain(
            BRIDGE_WRITES
                .iter()
                .filter(|(_, c)| c.starts_with("lab:"))
                .map(|(_, c)| format!("lua {}", c.replace("{hex}", hexs))),
        )
        .collect();
    for (profile, rule) in [("ro", "read_only"), ("one", "allow list")] {
        let mut sh = shell(Clock::stepped(), &p, "lab", profile);
        let before = refusal(&mut sh, "umpk info");
        assert!(before.is_none(), "reads pass: {before:?}");
        for line in &lines {
            let e = refusal(&mut sh, line).unwrap_or_else(|| panic!("umpk {profile}: `{line}` was not refused"));
            assert!(
                e.contains(rule) && e.contains(&format!("{}:", file.display())),
                "umpk {profile}: `{line}`: the refusal names the rule and the file: {e}"
            );
        }
        let info = sh.exec("umpk program-info").remove(0).expect("reads pass");
        assert_eq!(info.data["program_info"].as_str().map(str::trim), Some(""), "nothing was programmed");
    }
}
