//! `plcsh record show FILE` and `plcsh replay FILE`: thin calls into [`crate::record`].

use crate::output::{self, Style};
use crate::record::{file, replay, show};
use clap::{Args, Subcommand};
use std::io::Write;
use std::path::PathBuf;

#[derive(Subcommand, Debug)]
pub enum RecordCmd {
    /// Print a recording as a decoded timeline (K2 operand names, servo object names);
    /// with --json one object per frame.
    Show {
        /// The file written by --record.
        file: PathBuf,
    },
}

#[derive(Args, Debug)]
pub struct ReplayArgs {
    /// The file written by --record.
    pub file: PathBuf,
    /// Simulate this K2 model instead of the one each recorded link names.
    #[arg(long, value_name = "MODEL")]
    pub sim_model: Option<String>,
    /// Start the simulated K2 from this snapshot (a file, or a name saved with `sim snapshot save`).
    #[arg(long, value_name = "NAME|FILE")]
    pub snapshot: Option<String>,
    /// Run the PLC-side helper (lib/k2_agent.il) with its mailbox at this V address. Without it,
    /// the helper runs when the recording shows its status block being read.
    #[arg(long, value_name = "VBn")]
    pub agent: Option<String>,
}

fn fail(out: &mut dyn Write, style: Style, cmd: &str, e: &crate::core::Error) -> i32 {
    let _ = output::report_error(out, style, cmd, e, None);
    if e.kind == crate::core::ErrorKind::Usage {
        2
    } else {
        1
    }
}

pub fn show(cmd: &RecordCmd, style: Style, out: &mut dyn Write) -> i32 {
    let RecordCmd::Show { file: path } = cmd;
    let rec = match file::read(path) {
        Ok(r) => r,
        Err(e) => return fail(out, style, "record", &e),
    };
    warn(&rec, path, "showing");
    match show::write(&rec, style.json, out) {
        // A damaged file is shown whole but exits 1: frames were lost.
        Ok(()) => i32::from(!rec.damaged.is_empty()),
        Err(e) => {
            eprintln!("plcsh: {e}");
            1
        }
    }
}

/// Exit status: 0 when every reply matches, 1 when any differs (or on error). `bench`
/// (the global `--bench FILE`): replay against the machine it describes — its PLC answers
/// the Modbus links, its drive line the servo links, wired as the bench wires them.
pub fn replay(
    args: &ReplayArgs,
    bench: Option<&std::path::Path>,
    devices_given: bool,
    style: Style,
    out: &mut dyn Write,
) -> i32 {
    let run = || -> crate::core::Result<replay::Report> {
        if bench.is_some() && (args.sim_model.is_some() || args.snapshot.is_some()) {
            return Err(crate::core::Error::usage(crate::msg!("cli-replay-bench-options"))
                .hint(crate::msg!("cli-hint-replay-bench-options")));
        }
        if devices_given {
            // Replaying recorded writes at a machine could move it: only simulators built here.
            return Err(crate::core::Error::usage(crate::msg!("cli-replay-no-device"))
                .hint(crate::msg!("cli-hint-replay-no-device")));
        }
        let rec = file::read(&args.file)?;
        warn(&rec, &args.file, "replaying");
        replay::check_not_empty(&rec, &args.file)?;
        let snapshot = args.snapshot.as_deref().map(crate::snapshot::locate).transpose()?;
        let agent = args
            .agent
            .as_deref()
            .map(crate::k2::agent::protocol::parse_base)
            .transpose()
            .map_err(crate::core::Error::usage)?;
        replay::run(
            &rec,
            &replay::Target { model: args.sim_model.clone(), snapshot, bench: bench.map(Into::into), agent },
        )
    };
    let report = match run() {
        Ok(r) => r,
        Err(e) => return fail(out, style, "replay", &e),
    };
    let r = if style.json {
        report
            .differences
            .iter()
            .try_for_each(|d| writeln!(out, "{}", serde_json::json!({ "ok": false, "cmd": "replay", "difference": d })))
            .and_then(|_| {
                writeln!(
                    out,
                    "{}",
                    serde_json::json!({ "ok": report.differences.is_empty() && !report.damaged, "cmd": "replay", "damaged": report.damaged, "requests": report.requests,
                    "differences": report.differences.len(), "skipped": report.skipped })
                )
            })
    } else {
        (|| {
            for d in &report.differences {
                let vt = d.vt.map(|v| format!(" at {v:.6} s")).unwrap_or_default();
                writeln!(out, "frame {} ({}{vt}): {}", d.frame, d.device, d.request)?;
                writeln!(out, "  {}", d.detail)?;
                let no_reply = || crate::msg!("cli-replay-no-reply").text;
                let recorded = if d.recorded.is_empty() { no_reply() } else { d.recorded.clone() };
                let replayed = if d.replayed.is_empty() { no_reply() } else { d.replayed.clone() };
                writeln!(out, "  {}", crate::msg!("cli-replay-recorded", reply = recorded))?;
                writeln!(out, "  {}", crate::msg!("cli-replay-replayed", reply = replayed))?;
            }
            for s in &report.skipped {
                writeln!(out, "{}", crate::msg!("cli-replay-skipped", what = s.as_str()))?;
            }
            let (requests, differences) = (report.requests, report.differences.len());
            writeln!(out, "{}", crate::msg!("cli-replay-summary", requests = requests, differences = differences))
        })()
    };
    if let Err(e) = r {
        eprintln!("plcsh: {e}");
        return 1;
    }
    i32::from(!report.differences.is_empty() || report.damaged)
}

/// Says on stderr what of a file could not be read (damage skipped, an early end) and what
/// a capture missed.
fn warn(rec: &file::Recording, path: &std::path::Path, doing: &str) {
    for d in &rec.damaged {
        eprintln!("plcsh: warning: {}: {d}", path.display());
    }
    if !rec.damaged.is_empty() {
        let (file, frames) = (path.display().to_string(), rec.frames.len());
        eprintln!("{}", crate::msg!("cli-record-damaged", file = file, doing = doing, frames = frames));
    }
    if let Some(why) = &rec.truncated {
        let (file, frames) = (path.display().to_string(), rec.frames.len());
        eprintln!(
            "{}",
            crate::msg!("cli-record-truncated", file = file, why = why.as_str(), doing = doing, frames = frames)
        );
    }
    for n in &rec.notes {
        eprintln!("plcsh: note: {}: {n}", path.display());
    }
}
