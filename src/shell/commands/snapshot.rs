//! `sim snapshot save NAME`, `sim snapshot restore NAME`, `sim snapshots`: the session's
//! simulated state to and from files ([`crate::snapshot`]).

use crate::core::clock::format_time;
use crate::core::{Error, Result};
use crate::output::Outcome;
use crate::shell::Shell;
use crate::snapshot::{self, Snapshot};
use std::time::Duration;

pub fn run(sh: &mut Shell, sub: &str, rest: Vec<&str>, offset: usize) -> Result<Outcome> {
    let usage = "sim snapshot save NAME | sim snapshot restore NAME | sim snapshots";
    if sub == "snapshots" {
        if sh.session.confine.is_some() {
            return Err(Error::unsupported("`sim snapshots` lists the user's data directory: not in a sandboxed run")
                .hint("a sandboxed run keeps snapshots as files under its write directory"));
        }
        let rows: Vec<Vec<String>> =
            snapshot::list().into_iter().map(|(n, p)| vec![n, p.display().to_string()]).collect();
        let names: Vec<String> = rows.iter().map(|r| r[0].clone()).collect();
        let mut o = Outcome::new("sim").with("snapshots", names);
        if rows.is_empty() {
            o = o.text("no saved snapshots (sim snapshot save NAME)");
        } else {
            o = o.table(&["snapshot", "file"], rows);
        }
        return Ok(o);
    }
    let (verb, name) = match rest.as_slice() {
        [v, n] => (*v, *n),
        [v, more @ ..] if more.len() > 1 => {
            return Err(Error::usage(format!("`sim snapshot {v}` takes one name or file, not {} words", more.len()))
                .hint(format!(
                    "a path with spaces goes in quotes: sim snapshot {v} {}",
                    crate::shell::lex::quote(&more.join(" "))
                ))
                .column(offset))
        }
        _ => {
            return Err(Error::usage(format!("`sim snapshot` needs save or restore and a name: {usage}")).column(offset))
        }
    };
    let path = sh.session.snapshot_file(name, verb == "save")?;
    match verb {
        "save" => {
            let snap = Snapshot::capture(&mut sh.session)?;
            snap.save(&path)?;
            let devices: Vec<String> = snap.devices.keys().cloned().collect();
            Ok(Outcome::new("sim")
                .text(format!(
                    "saved {} at {} to {}",
                    devices.join(", "),
                    format_time(Duration::from_micros(snap.clock_us)),
                    path.display()
                ))
                .with("saved", name)
                .with("file", path.display().to_string())
                .with("devices", devices)
                .with("time_us", snap.clock_us))
        }
        "restore" => {
            let snap = Snapshot::load(&path)?;
            snap.restore(&mut sh.session)?;
            let devices: Vec<String> = snap.devices.keys().cloned().collect();
            Ok(Outcome::new("sim")
                .text(format!(
                    "restored {} to {}",
                    devices.join(", "),
                    format_time(Duration::from_micros(snap.clock_us))
                ))
                .with("restored", name)
                .with("devices", devices)
                .with("time_us", snap.clock_us))
        }
        other => Err(Error::usage(format!("unknown `sim snapshot {other}`")).hint(usage).column(offset)),
    }
}
