//! `paths`: where plcsh keeps every file (the table is `crate::paths`), for the technician
//! who asks "where is my devices.toml, my history, the simulator's state?". Shared by the
//! REPL's `paths` and `plcsh paths`.

use super::CommandSpec;
use crate::core::Result;
use crate::output::Outcome;
use crate::shell::{Args, Shell};

pub const PATHS: CommandSpec = CommandSpec {
    name: "paths",
    aliases: &[],
    usage: "paths",
    summary: || crate::msg!("summary-paths"),
    subcommands: &[],
    run: paths,
};

/// `paths`: the table of [`crate::paths::places`] (`paths` in JSON: name → path).
fn paths(_sh: &mut Shell, args: Args) -> Result<Outcome> {
    super::no_arguments("paths", args)?;
    let places = crate::paths::places();
    let json: serde_json::Map<String, serde_json::Value> =
        places.iter().map(|p| (p.name.to_string(), p.path.clone().into())).collect();
    let rows = places.iter().map(|p| vec![p.name.to_string(), p.path.clone(), p.set_by.to_string()]).collect();
    Ok(Outcome::new("paths")
        .with("paths", json)
        .table(&crate::output::headings(crate::msg!("shell-paths-columns")), rows))
}
