//! The command registry: every shell command in one list, one file per command family.
//! Completion, `help` and the README's command table all read this list.

mod agent;
mod counter;
mod device;
mod eeprom;
mod events;
mod fault;
mod fxsim;
mod help;
mod io;
mod k2cmd;
mod lab;
pub mod lua;
pub mod models;
pub mod paths;
pub mod ports;
pub mod profiles;
pub(crate) mod pulse;
mod rtc;
mod servo;
mod sim;
mod siminputs;
mod simprogram;
mod simwire;
mod snapshot;
mod trend;
mod umpk;
mod watch;

use super::{Args, Shell};
use crate::core::{Error, Result};
use crate::output::Outcome;

/// One shell command.
pub struct CommandSpec {
    pub name: &'static str,
    pub aliases: &'static [&'static str],
    pub usage: &'static str,
    pub summary: &'static str,
    /// Sub-commands, for completion.
    pub subcommands: &'static [&'static str],
    pub run: fn(&mut Shell, Args) -> Result<Outcome>,
}

/// Every command, in the order `help` lists them.
pub static COMMANDS: &[CommandSpec] = &[
    io::GET,
    io::SET,
    io::READ,
    device::USE,
    device::DEVICES,
    device::CONNECT,
    device::CLOSE,
    sim::SIM,
    watch::WATCH,
    trend::TRACE,
    trend::PLOT,
    servo::SERVO,
    umpk::UMPK,
    pulse::PLS,
    pulse::PSTOP,
    pulse::PTO,
    pulse::PWM,
    pulse::PROFILE,
    counter::HDEF,
    counter::HSC,
    events::EVENTS,
    events::WAIT,
    rtc::RTC,
    eeprom::EEPROM,
    lua::LUA,
    agent::AGENT,
    lab::LAB,
    models::MODELS,
    ports::PORTS,
    paths::PATHS,
    help::HELP,
    help::QUIT,
];

/// Commands that take a device right after the command word (docs/commands.md, "Where the
/// device goes"): `eeprom press status`, `rtc press sync`, `events press`, `wait press event 1`.
/// `servo`, `umpk` and `agent` read their device word themselves; K2 instructions take it as
/// the prefix of their channel (`pto press:0`), operands as theirs (`get press:VW0`).
pub const DEVICE_FIRST: &[&str] = &["eeprom", "rtc", "events", "wait"];

pub fn find(name: &str) -> Option<&'static CommandSpec> {
    COMMANDS.iter().find(|c| c.name == name || c.aliases.contains(&name))
}

/// "did you mean" for an unknown command.
/// Refuses words after a command that takes none (`devices x`, `quit now`): extra words are
/// never ignored.
pub fn no_arguments(name: &str, args: Args) -> Result<()> {
    match args.text.split_whitespace().next() {
        None => Ok(()),
        Some(w) => Err(Error::usage(format!("{name} takes nothing after it (got `{w}`)"))
            .hint(name.to_string())
            .column(args.offset)),
    }
}

/// Commands of the command line that the shell does not have, with where they belong and
/// what the shell offers instead.
const COMMAND_LINE_ONLY: &[(&str, &str)] = &[
    ("run", "`run` is a command-line command: plcsh run SCRIPT.lua [ARGS…]; in the shell, lua dofile(\"SCRIPT.lua\")"),
    ("replay", "`replay` is a command-line command: plcsh replay FILE.pcapng (it builds its own simulators)"),
    ("record", "`record` is a command-line command: plcsh record show FILE.pcapng; to record this session start plcsh with --record FILE"),
    ("completions", "`completions` is a command-line command: plcsh completions bash|zsh|fish|powershell"),
    ("serve", "serving is a command-line command: plcsh sim serve --tcp 5020 …"),
];

pub fn suggest(name: &str) -> String {
    if let Some((_, where_)) = COMMAND_LINE_ONLY.iter().find(|(n, _)| *n == name) {
        return where_.to_string();
    }
    let mut best: Vec<(usize, &str)> =
        COMMANDS.iter().map(|c| (crate::core::text::edit_distance(name, c.name), c.name)).collect();
    best.sort();
    match best.first() {
        Some((d, n)) if *d <= 2 => format!("did you mean `{n}`? `help` lists the commands"),
        _ => "`help` lists the commands".to_string(),
    }
}
