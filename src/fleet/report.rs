//! How a fleet's results are shown: one row per device in a table for people, one JSON object
//! per device and a summary object for programs (docs/json.md's contract: `ok`, `cmd`, and
//! `device` on every line; the summary's `cmd` is `fleet`). Rows come in the fleet's order,
//! whatever order the devices finished in.

use crate::core::Error;
use crate::output::{self, Outcome, Style, View};
use serde_json::{json, Value as Json};
use std::io::Write;
use std::time::Duration;

/// One device's part of the report.
pub struct Row {
    pub device: String,
    pub ok: bool,
    /// The object `--json` prints for this device (without `device`, `fleet`, `ms`).
    pub json: Json,
    /// Per-operand values when the device answered a plain read, else `None`.
    pub values: Option<Vec<(String, String)>>,
    /// One line for the table's result column.
    pub text: String,
    pub elapsed: Duration,
}

impl Row {
    /// A device that could not be opened or did not finish.
    pub fn failed(device: &str, cmd: &str, e: &Error, elapsed: Duration) -> Row {
        Row {
            device: device.into(),
            ok: false,
            json: output::error_json(cmd, e),
            values: None,
            text: error_text(e),
            elapsed,
        }
    }

    /// A device that ran a command line: its results in order (the line stops at the first failure).
    pub fn commands(device: &str, results: &[crate::shell::CmdResult], elapsed: Duration) -> Row {
        let ok = !results.is_empty() && results.iter().all(|r| r.is_ok());
        let one = |r: &crate::shell::CmdResult| match r {
            Ok(o) => o.to_json(),
            Err((cmd, e)) => output::error_json(cmd, e),
        };
        let json = match results {
            [r] => one(r),
            // Several commands: one line for the device, `cmd` "fleet" (docs/json.md: `cmd` is
            // a command's word, never a list), each command's own line in `results`.
            _ => {
                json!({"ok": ok, "cmd": "fleet", "sub": "device", "results": results.iter().map(one).collect::<Vec<_>>()})
            }
        };
        let values = match results {
            [Ok(o)] if matches!(o.view, View::Values) && !o.values.is_empty() => {
                Some(o.values.iter().map(|r| (r.operand.clone(), output::show_value(&r.value, r.dtype))).collect())
            }
            _ => None,
        };
        let text = results
            .iter()
            .map(|r| match r {
                Ok(o) => outcome_text(o),
                Err((_, e)) => error_text(e),
            })
            .filter(|t| !t.is_empty())
            .collect::<Vec<_>>()
            .join("; ");
        Row { device: device.into(), ok, json, values, text, elapsed }
    }
}

fn error_text(e: &Error) -> String {
    format!("error[{}]: {}", e.kind.name(), e.message)
}

/// A result in one line: `VW100=5 SMB66=0`, the command's message, or `N rows`.
fn outcome_text(o: &Outcome) -> String {
    match &o.view {
        View::Values | View::Quiet if !o.values.is_empty() || !o.writes.is_empty() => {
            let list = if o.values.is_empty() { &o.writes } else { &o.values };
            list.iter()
                .map(|r| format!("{}={}", r.operand, output::show_value(&r.value, r.dtype)))
                .collect::<Vec<_>>()
                .join(" ")
        }
        View::Text(t) => t.lines().next().unwrap_or("").to_string(),
        View::Table { rows, .. } => format!("{} rows", rows.len()),
        _ => o.message.clone().unwrap_or_else(|| "ok".into()),
    }
}

/// The whole fleet's report. Returns whether every device succeeded.
pub struct Summary<'a> {
    pub fleet: &'a str,
    pub cmd: &'a str,
    pub jobs: usize,
    pub elapsed: Duration,
}

fn ms(d: Duration) -> f64 {
    (d.as_secs_f64() * 1e6).round() / 1e3
}

/// Writes the rows (table or JSON lines) and the summary; true when every device succeeded.
pub fn write(out: &mut dyn Write, style: Style, rows: &[Row], s: &Summary) -> std::io::Result<bool> {
    let failed: Vec<&str> = rows.iter().filter(|r| !r.ok).map(|r| r.device.as_str()).collect();
    let all_ok = failed.is_empty();
    if style.json {
        for r in rows {
            let mut j = r.json.clone();
            j["ok"] = r.ok.into();
            j["device"] = r.device.clone().into();
            j["fleet"] = s.fleet.into();
            j["ms"] = ms(r.elapsed).into();
            writeln!(out, "{j}")?;
        }
        let summary = json!({"ok": all_ok, "cmd": "fleet", "sub": "summary", "fleet": s.fleet, "ran": s.cmd, "devices": rows.len(),
            "succeeded": rows.len() - failed.len(), "failed": failed.len(), "failed_devices": failed,
            "jobs": s.jobs, "duration_ms": ms(s.elapsed)});
        writeln!(out, "{summary}")?;
        return Ok(all_ok);
    }
    // Operand columns when every device that answered read the same operands.
    let shared: Option<Vec<String>> = {
        let mut names =
            rows.iter().filter_map(|r| r.values.as_ref().map(|v| v.iter().map(|(o, _)| o.clone()).collect::<Vec<_>>()));
        let first = names.next();
        first.filter(|f| names.all(|n| n == *f) && rows.iter().all(|r| r.values.is_some() || !r.ok))
    };
    let mut headers = vec!["device".to_string(), "ok".to_string()];
    match &shared {
        Some(ops) => headers.extend(ops.iter().cloned()),
        None => headers.push("result".into()),
    }
    headers.push("ms".into());
    let mut table_rows = Vec::new();
    for r in rows {
        let mut row = vec![r.device.clone(), if r.ok { "ok" } else { "FAILED" }.to_string()];
        match (&shared, &r.values) {
            (Some(_), Some(v)) => row.extend(v.iter().map(|(_, x)| x.clone())),
            (Some(ops), None) => {
                row.push(r.text.clone());
                row.extend(std::iter::repeat_n(String::new(), ops.len().saturating_sub(1)));
            }
            (None, _) => row.push(r.text.clone()),
        }
        row.push(format!("{:.0}", ms(r.elapsed)));
        table_rows.push(row);
    }
    let h: Vec<&str> = headers.iter().map(String::as_str).collect();
    output::write_outcome(out, style, &Outcome::new("fleet").table(&h, table_rows))?;
    let line = if all_ok {
        crate::msg!(
            "fleet-all-ok",
            fleet = s.fleet,
            count = rows.len(),
            ms = format!("{:.0}", ms(s.elapsed)),
            jobs = s.jobs
        )
    } else {
        crate::msg!(
            "fleet-failed",
            fleet = s.fleet,
            failed = failed.len(),
            count = rows.len(),
            devices = failed.join(", "),
            ms = format!("{:.0}", ms(s.elapsed)),
            jobs = s.jobs
        )
    };
    writeln!(out, "{line}")?;
    Ok(all_ok)
}
