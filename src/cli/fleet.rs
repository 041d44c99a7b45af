//! `plcsh -f FLEET -c 'COMMANDS'` and `plcsh run --fleet FLEET SCRIPT.lua`: the same command
//! line or script on every member of a fleet, concurrently ([`crate::fleet::run`]), one row
//! per device back ([`crate::fleet::report`]).
//!
//! Exit status: 0 when every device succeeded, 1 when any device failed (its row says why;
//! the others still ran), 2 for a usage error before any device was touched (no such fleet,
//! `--fleet` without `-c` or `run`) and for a command line that every member refused the same
//! way before doing anything (an operand typo, an unknown command: one error, not one row per
//! device), 130 when Ctrl-C stopped the run.

use crate::core::{Error, ErrorKind};
use crate::fleet::report::{self, Row};
use crate::fleet::run::{self, Base, Settings, Work};
use crate::output::{self, Style};
use crate::shell::Shell;
use std::io::Write;
use std::sync::{Arc, Mutex};
use std::time::{Duration, Instant};

/// `--jobs` and `--device-timeout` as the runner takes them.
pub fn settings(cli: &super::Cli) -> crate::core::Result<Settings> {
    let timeout = match cli.device_timeout.trim() {
        "0" | "none" => None,
        t => {
            let us = crate::core::literal::parse_option_duration_us(t).ok().filter(|us| *us > 0).ok_or_else(|| {
                Error::usage(crate::msg!("cli-device-timeout-bad", value = t))
                    .hint(crate::msg!("cli-hint-device-timeout"))
            })?;
            Some(Duration::from_micros(us as u64))
        }
    };
    if cli.jobs == 0 {
        return Err(Error::usage(crate::msg!("cli-jobs-at-least-one")));
    }
    Ok(Settings { jobs: cli.jobs, timeout })
}

fn usage(out: &mut dyn Write, style: Style, cmd: &str, e: &Error) -> i32 {
    let _ = output::report_error(out, style, cmd, e, None);
    if e.kind == ErrorKind::Usage {
        2
    } else {
        1
    }
}

/// What the fleet run needs from the main shell.
fn prepare(cli: &super::Cli, shell: &Shell, name: &str) -> crate::core::Result<(crate::fleet::Fleet, Settings, Base)> {
    let fleet = shell.session.profiles.fleet(name)?.clone();
    let settings = settings(cli)?;
    Ok((fleet, settings, Base::of(&shell.session, Style { json: false, color: false })))
}

fn finish(out: &mut dyn Write, style: Style, rows: &[Row], summary: &report::Summary, shell: &Shell) -> i32 {
    match report::write(out, style, rows, summary) {
        Ok(_) if shell.session.interrupted() => 130,
        Ok(true) => 0,
        _ => 1,
    }
}

/// `plcsh -f FLEET -c LINE`.
pub fn commands(cli: &super::Cli, shell: &Shell, name: &str, line: &str, style: Style, out: &mut dyn Write) -> i32 {
    let (fleet, settings, base) = match prepare(cli, shell, name) {
        Ok(p) => p,
        Err(e) => return usage(out, style, "fleet", &e),
    };
    let members = Arc::new(fleet.clone());
    let ran = line.trim().to_string();
    let line = line.to_string();
    let work: Work<Vec<crate::shell::CmdResult>> = Arc::new(move |i, stop| {
        let mut sh = base.open(&members, &members.members[i], stop)?;
        Ok(sh.exec(&line))
    });
    let start = Instant::now();
    let done = run::each(&fleet, settings, &shell.session.interrupt, work);
    if let Some((cmd, e)) = same_usage_error(&done, name) {
        let _ = output::report_error(out, style, &cmd, &e, None);
        return 2;
    }
    let rows: Vec<Row> = done
        .iter()
        .map(|d| match &d.result {
            Ok(results) => Row::commands(&d.device, results, d.elapsed),
            Err(e) => Row::failed(&d.device, "open", e, d.elapsed),
        })
        .collect();
    finish(
        out,
        style,
        &rows,
        &report::Summary { fleet: name, cmd: &ran, jobs: settings.jobs, elapsed: start.elapsed() },
        shell,
    )
}

/// The one error to show when every member refused the line's first command with the same
/// usage error (a syntax or operand error, an unknown command) before anything ran: the line
/// is wrong, not the devices.
fn same_usage_error(done: &[run::Done<Vec<crate::shell::CmdResult>>], fleet: &str) -> Option<(String, Error)> {
    let mut first: Option<(&String, &Error)> = None;
    for d in done {
        let Ok(results) = &d.result else { return None };
        let [Err((cmd, e))] = results.as_slice() else { return None };
        // A refused write (a usage error about an operand of a device) is the device's answer.
        let line_error = match e.kind {
            ErrorKind::Syntax | ErrorKind::Operand => true,
            ErrorKind::Usage => e.operand.is_none() && e.device.is_none(),
            _ => false,
        };
        if !line_error {
            return None;
        }
        match first {
            None => first = Some((cmd, e)),
            Some((c, f)) if c == cmd && f.kind == e.kind && f.message == e.message => {}
            Some(_) => return None,
        }
    }
    let (cmd, e) = first?;
    let mut e = e.clone();
    e.device = None;
    e.message = crate::msg!("cli-fleet-all-refused", message = e.message.as_str(), fleet = fleet).text;
    Some((cmd.clone(), e))
}

/// `plcsh run --fleet FLEET SCRIPT.lua ARGS…`: the script runs once per member in a Lua state
/// of its own, on the member's thread, with the member as its current device (commands and
/// `plcsh.exec` act on it; `plcsh.fleet_member` names it for `plcsh.device`). What the
/// script prints is kept per device and shown before the table (`output` in JSON), so the
/// devices' lines never interleave.
pub fn script(
    cli: &super::Cli,
    shell: &Shell,
    name: &str,
    args: &super::run::RunArgs,
    style: Style,
    out: &mut dyn Write,
) -> i32 {
    if args.sandbox {
        // The sandbox is for simulated devices only (docs/teaching.md); a fleet is machines.
        let e = Error::usage(crate::msg!("cli-fleet-no-sandbox")).hint(crate::msg!("cli-hint-fleet-no-sandbox"));
        return usage(out, style, "run", &e);
    }
    let (fleet, settings, base) = match prepare(cli, shell, name) {
        Ok(p) => p,
        Err(e) => return usage(out, style, "run", &e),
    };
    let members = Arc::new(fleet.clone());
    let (script, script_args) = (args.script.clone(), args.args.clone());
    let work: Work<ScriptResult> = Arc::new(move |i, stop| {
        let mut sh = base.open(&members, &members.members[i], stop.clone())?;
        let printed = Arc::new(Mutex::new(Vec::new()));
        let engine = crate::script::Engine::new(stop, Box::new(Shared(printed.clone())))
            .map_err(|e| Error::new(ErrorKind::Script, crate::msg!("cli-run-no-lua", reason = e.to_string())))?;
        // The member's name, so one script serves a fleet and a single device:
        // `plcsh.device(plcsh.fleet_member or "plc")`.
        let member = members.members[i].name.clone();
        let set = engine.lua().globals().get::<mlua::Table>("plcsh").and_then(|p| p.set("fleet_member", member));
        set.map_err(|e| Error::new(ErrorKind::Script, crate::msg!("cli-run-no-lua", reason = e.to_string())))?;
        let r = engine.run_file(&mut sh, &script, &script_args);
        let (checks, failed) = super::run::checks(&engine);
        let output = String::from_utf8_lossy(&printed.lock().unwrap_or_else(|p| p.into_inner())).into_owned();
        Ok(ScriptResult { failure: r.err().map(|f| (f.json("run"), f.human())), checks, failed, output })
    });
    let start = Instant::now();
    let done = run::each(&fleet, settings, &shell.session.interrupt, work);
    let mut rows = Vec::new();
    let mut printed = Vec::new();
    for d in &done {
        rows.push(match &d.result {
            Ok(r) => {
                let ok = r.failure.is_none() && r.failed == 0;
                let mut json = match &r.failure {
                    None => serde_json::json!({"ok": ok, "cmd": "run"}),
                    Some((j, _)) => j.clone(),
                };
                json["checks"] = serde_json::json!({"passed": r.checks.saturating_sub(r.failed), "failed": r.failed});
                json["output"] = r.output.clone().into();
                let text = match &r.failure {
                    Some((j, _)) => format!(
                        "error[{}]: {}",
                        j["error"]["kind"].as_str().unwrap_or("script"),
                        j["error"]["message"].as_str().unwrap_or("")
                    ),
                    None => {
                        let passed = r.checks.saturating_sub(r.failed);
                        crate::msg!("cli-fleet-checks", passed = passed, failed = r.failed).text
                    }
                };
                if !r.output.is_empty() || r.failure.is_some() {
                    let human = r.failure.as_ref().map(|(_, h)| h.clone()).unwrap_or_default();
                    printed.push(format!("--- {}\n{}{}", d.device, r.output, human));
                }
                Row { device: d.device.clone(), ok, json, values: None, text, elapsed: d.elapsed }
            }
            Err(e) => Row::failed(&d.device, "run", e, d.elapsed),
        });
    }
    if !style.json {
        for p in &printed {
            let _ = write!(out, "{p}");
            if !p.ends_with('\n') {
                let _ = writeln!(out);
            }
        }
    }
    let what = args.script.display().to_string();
    finish(
        out,
        style,
        &rows,
        &report::Summary { fleet: name, cmd: &what, jobs: settings.jobs, elapsed: start.elapsed() },
        shell,
    )
}

/// One member's script run.
pub struct ScriptResult {
    /// The failure's JSON and text, when the script failed.
    failure: Option<(serde_json::Value, String)>,
    checks: u64,
    failed: u64,
    output: String,
}

/// A writer into a buffer shared with the thread that shows it.
struct Shared(Arc<Mutex<Vec<u8>>>);

impl Write for Shared {
    fn write(&mut self, b: &[u8]) -> std::io::Result<usize> {
        self.0.lock().unwrap_or_else(|p| p.into_inner()).extend_from_slice(b);
        Ok(b.len())
    }
    fn flush(&mut self) -> std::io::Result<()> {
        Ok(())
    }
}
