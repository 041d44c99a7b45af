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
            return Err(
                Error::unsupported(crate::msg!("snapshot-list-sandboxed")).hint(crate::msg!("snapshot-hint-sandboxed"))
            );
        }
        let rows: Vec<Vec<String>> =
            snapshot::list().into_iter().map(|(n, p)| vec![n, p.display().to_string()]).collect();
        let names: Vec<String> = rows.iter().map(|r| r[0].clone()).collect();
        let mut o = Outcome::new("sim").with("snapshots", names);
        if rows.is_empty() {
            o = o.text(crate::msg!("snapshot-none").text);
        } else {
            o = o.table(&crate::output::headings(crate::msg!("snapshot-columns")), rows);
        }
        return Ok(o);
    }
    let (verb, name) = match rest.as_slice() {
        [v, n] => (*v, *n),
        [v, more @ ..] if more.len() > 1 => {
            return Err(Error::usage(crate::msg!("snapshot-one-name", verb = *v, count = more.len()))
                .hint(crate::msg!(
                    "snapshot-hint-quotes",
                    verb = *v,
                    path = crate::shell::lex::quote(&more.join(" ")).into_owned()
                ))
                .column(offset))
        }
        _ => return Err(Error::usage(crate::msg!("snapshot-needs-verb", usage = usage)).column(offset)),
    };
    let path = sh.session.snapshot_file(name, verb == "save")?;
    match verb {
        "save" => {
            let snap = Snapshot::capture(&mut sh.session)?;
            snap.save(&path)?;
            let devices: Vec<String> = snap.devices.keys().cloned().collect();
            Ok(Outcome::new("sim")
                .text(
                    crate::msg!(
                        "snapshot-saved",
                        devices = devices.join(", "),
                        time = format_time(Duration::from_micros(snap.clock_us)),
                        file = path.display().to_string()
                    )
                    .text,
                )
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
                .text(
                    crate::msg!(
                        "snapshot-restored",
                        devices = devices.join(", "),
                        time = format_time(Duration::from_micros(snap.clock_us))
                    )
                    .text,
                )
                .with("restored", name)
                .with("devices", devices)
                .with("time_us", snap.clock_us))
        }
        other => Err(Error::usage(crate::msg!("snapshot-unknown", verb = other)).hint(usage).column(offset)),
    }
}
