//! The command line (clap): `plcsh` opens the REPL on a simulated K2; `-c` runs commands
//! one-shot; subcommands are thin calls into the session and the shell.
//! Exit status: 0 when every command succeeded, 1 when any failed, 2 for a usage error.
//! One file per subcommand (`models.rs` …), each a thin call into the library.

mod agent;
mod clap_error;
pub mod completions;
mod fleet;
mod lab;
mod localise;
mod man;
mod probe;
mod publish;
mod record;
pub mod reference;
mod run;
pub(crate) mod serve;
pub mod tags;

use crate::core::{exit, Clock};
use crate::k2::catalog;
use crate::output::{self, Style};
use crate::session::Session;
use crate::shell::{repl, Shell};
use clap::{Parser, Subcommand, ValueEnum};
use std::io::{IsTerminal, Write};

#[derive(Clone, Copy, Debug, PartialEq, Eq, ValueEnum)]
pub enum TimeMode {
    /// Simulator time follows the wall clock.
    Wall,
    /// Simulator time moves only when stepped (`sim step`, waits in scripts).
    Stepped,
}

#[derive(Parser, Debug)]
#[command(name = "plcsh", version, about = "A shell for commissioning and debugging Kinco K2 PLCs and servo drives", long_about = None)]
pub struct Cli {
    #[command(flatten)]
    pub options: Options,
    #[command(subcommand)]
    pub sub: Option<Sub>,
}

/// The heading of the options every subcommand takes, apart from a subcommand's own
/// (`plcsh sim serve --help` lists its serve options first, then these).
const GLOBAL: &str = "Global options";

/// The top-level options (`cli.json`, `cli.devices` … read through `Deref`): one table for
/// the full parser and for [`parse_one_shot`]'s light one.
#[derive(clap::Args, Debug)]
pub struct Options {
    /// Run these commands (separated by `;`) and exit.
    #[arg(short = 'c', long = "command", value_name = "COMMANDS")]
    pub command: Option<String>,
    /// Print one JSON object per command result.
    #[arg(long, global = true, help_heading = GLOBAL)]
    pub json: bool,
    /// Show more: each frame sent and received in hex with timing, request counts, sample rates.
    #[arg(short, long, action = clap::ArgAction::Count, global = true, help_heading = GLOBAL)]
    pub verbose: u8,
    /// Model of the default simulated PLC.
    #[arg(long, default_value = catalog::DEFAULT_MODEL, global = true, help_heading = GLOBAL)]
    pub model: String,
    /// Add a device: NAME=URL, NAME=PROFILE, a bare PROFILE (opened under its name and made
    /// current) or a bare URL (which replaces `plc`). Repeatable.
    #[arg(long = "device", short = 'd', value_name = "NAME=URL", global = true, help_heading = GLOBAL)]
    pub devices: Vec<String>,
    /// A tag file (CSV, TOML or IEC VAR_GLOBAL) whose names work wherever an operand does:
    /// FILE for the current device, DEVICE=FILE for another (docs/tags.md). Repeatable.
    #[arg(long = "tags", value_name = "[DEVICE=]FILE", global = true, help_heading = GLOBAL)]
    pub tags: Vec<String>,
    /// Simulator time: follow the wall clock, or move only when stepped.
    #[arg(long, value_enum, default_value = "wall", global = true, help_heading = GLOBAL)]
    pub time: TimeMode,
    #[arg(long, value_name = "FILE", global = true, help_heading = GLOBAL,
        help = concat!("Device profile file (default: PLCSH_CONFIG, else ", crate::core::platform::words::profile_file!(), ")."))]
    pub config: Option<std::path::PathBuf>,
    /// Simulator state file (backup area, retained ranges, clock); default PLCSH_STATE, else in the
    /// user's data directory; `none` reads and writes nothing (labs, tests). `sim serve` keeps state only with --state FILE.
    #[arg(long, value_name = "FILE|none", global = true, help_heading = GLOBAL)]
    pub state: Option<std::path::PathBuf>,
    /// Record every frame on every device link to FILE (pcapng; `plcsh record show FILE`).
    #[arg(long, value_name = "FILE", global = true, help_heading = GLOBAL)]
    pub record: Option<std::path::PathBuf>,
    /// Open a simulated machine described by a bench file (devices, wiring, initial values).
    #[arg(long, value_name = "FILE", global = true, help_heading = GLOBAL)]
    pub bench: Option<std::path::PathBuf>,
    /// Refuse every change to every device (writes, instructions, servo commands): inspect a live machine.
    #[arg(long = "read-only", global = true, help_heading = GLOBAL)]
    pub read_only: bool,
    /// Run -c's commands (or `run`'s script) on every device of this fleet from the profile file, at once (docs/fleets.md).
    #[arg(short = 'f', long = "fleet", value_name = "NAME")]
    pub fleet: Option<String>,
    /// With --fleet: how many devices are worked on at once.
    #[arg(short = 'j', long = "jobs", value_name = "N", default_value_t = 8, global = true, help_heading = GLOBAL)]
    pub jobs: usize,
    /// The language of messages: en, ru, zh-CN (default: PLCSH_LANG, else the system's; English when neither names one of these).
    #[arg(long, value_name = "LANG", value_parser = parse_lang, global = true, help_heading = GLOBAL)]
    pub lang: Option<crate::core::msg::Lang>,
    /// With --fleet: a device still busy after this long is reported as a timeout (`30s`, `2m`; 0 for no limit).
    #[arg(long = "device-timeout", value_name = "DURATION", default_value = "60s", global = true, help_heading = GLOBAL)]
    pub device_timeout: String,
}

impl std::ops::Deref for Cli {
    type Target = Options;
    fn deref(&self) -> &Options {
        &self.options
    }
}

#[derive(Subcommand, Debug)]
// Parsed once per process: the size of the largest variant (`sim serve`'s flags) costs nothing.
#[allow(clippy::large_enum_variant)]
pub enum Sub {
    /// List the K2 model catalogue; `models MODEL` shows one in full (areas, counters, manual notes).
    Models {
        /// One model (a unique prefix is enough: K209EA).
        #[arg(value_name = "MODEL")]
        name: Option<String>,
    },
    /// List open devices and the device profiles (devices.toml), with problems in that file.
    Devices,
    /// List the serial ports present, with USB adapter (VID:PID, product, serial number).
    Ports,
    /// Print where every file lives: profiles, Lua modules, state, history, snapshots, UMPK flash, recordings.
    Paths,
    /// Print the manual page (roff) made from these flags and the shell's commands: plcsh man > plcsh.1
    Man,
    /// Print a shell completion script (bash, zsh, fish, powershell), or write them all.
    Completions {
        /// The shell to print the script for.
        #[arg(value_enum)]
        shell: Option<clap_complete::Shell>,
        /// Write every script into DIR (plcsh.bash, _plcsh, plcsh.fish, _plcsh.ps1).
        #[arg(long, value_name = "DIR")]
        write: Option<std::path::PathBuf>,
    },
    // Serve simulators to other programs (the words for this system: core::platform::words).
    #[command(about = concat!("Serve simulators to other programs: `sim serve` puts the simulated K2 on Modbus TCP / RTU and drives ",
        crate::core::platform::words::served_line!(), "."))]
    Sim {
        #[command(subcommand)]
        cmd: serve::SimCmd,
    },
    /// The PLC-side helper program that gives plcsh SM registers and instructions on a real K2.
    Agent(agent::AgentArgs),
    /// What a K2 answers over Modbus before the helper is in it: areas and their last addresses,
    /// the models that fit, response time; reads only (docs/reference/first-connection.md).
    Probe(probe::ProbeArgs),
    /// Run a Lua script: plcsh [--time stepped] [--device NAME=URL] run SCRIPT.lua [ARGS…]
    Run(run::RunArgs),
    /// Recordings made with --record: `record show FILE` prints the decoded timeline.
    Record {
        #[command(subcommand)]
        cmd: record::RecordCmd,
    },
    /// Replay a recording's requests against a simulator and report every reply that differs.
    Replay(record::ReplayArgs),
    /// Teaching labs: `lab new NAME`, `lab check LAB`, `lab grade LAB SUBMISSIONS…` (sandboxed, in parallel).
    Lab {
        #[command(subcommand)]
        cmd: lab::LabCmd,
    },
    /// Poll operands on a device or a fleet and publish them to an MQTT broker (docs/fleets.md).
    Publish(publish::PublishArgs),
    /// Tag tables (docs/tags.md): `tags FILE` lists the names, `tags check FILE` checks them,
    /// `tags export FILE --to csv|iec` writes them in another form.
    Tags(tags::TagsArgs),
}

/// Splits `NAME=URL` (or a bare URL, named `plc`; or a bare profile name, named after itself).
pub fn split_device_arg(arg: &str) -> (String, String) {
    if !arg.contains(['=', ':']) {
        return (arg.to_string(), arg.to_string());
    }
    if let Some((name, url)) = arg.split_once('=') {
        if !name.is_empty()
            && !name.contains(':')
            && name.chars().all(|c| c.is_ascii_alphanumeric() || c == '_' || c == '-')
        {
            return (name.to_string(), url.to_string());
        }
    }
    ("plc".to_string(), arg.to_string())
}

/// Builds the session the flags describe: `plc` on the simulator, a simulated drive
/// `servo`, then every `--device`.
pub fn build_session(cli: &Cli) -> crate::core::Result<Session> {
    let clock = match cli.time {
        TimeMode::Wall => Clock::following(),
        TimeMode::Stepped => Clock::stepped(),
    };
    let mut s = Session::new(clock);
    // A sandboxed run's rules hold from the first device on: a real device given with
    // --device is refused where the session opens it, before any connection.
    if let Some(Sub::Run(r)) = &cli.sub {
        if r.sandbox {
            s.confine = Some(std::sync::Arc::new(r.confinement()));
        }
    }
    crate::paths::set_in_effect(crate::paths::InEffect {
        config: cli.config.clone().or_else(crate::paths::config_file),
        state: state_file(cli),
        record: cli.record.clone(),
    });
    if let Some(path) = &cli.config {
        // A file named on the command line must exist (a typo would silently load nothing).
        if !path.exists() {
            return Err(crate::core::Error::usage(crate::msg!(
                "cli-config-missing",
                file = path.display().to_string()
            ))
            .hint(crate::msg!("cli-hint-config-missing")));
        }
    }
    if let Some(path) = &cli.record {
        // Before any device opens, so connections are recorded from their first frame.
        crate::record::start(path, s.clock.clone())?;
    }
    if let Some(path) = cli.config.clone().or_else(crate::profile::default_path) {
        s.profiles = crate::profile::Profiles::load(&path);
        s.profiles.validate(&s.clock);
    }
    s.set_read_only(cli.read_only);
    let mut current = "plc".to_string();
    let named: Vec<(String, String)> = cli.devices.iter().map(|d| split_device_arg(d)).collect();
    let real = |family: &str| named.iter().any(|(_, url)| real_family(&s, url) == Some(family));
    let (real_k2, real_servo) = (real("k2"), real("servo"));
    // The default simulators, unless a --device takes their name (a real `plc` then opens
    // without first loading the simulator's state) or names a real device of their family
    // (a real K2 or drive is never shadowed by a simulated one the user did not ask for).
    if !named.iter().any(|(n, _)| n == "plc") && !real_k2 {
        let url = format!("sim:{}", cli.model);
        // The simulated PLC keeps its backup area, retained ranges and clock (k2.md §7);
        // `sim serve` keeps its own (`--state`), so the shell's default file stays untouched.
        // A sandboxed run keeps no state: every run starts clean (`--state FILE` is not read).
        let keeps_state = !matches!(&cli.sub, Some(Sub::Sim { .. })) && s.confine.is_none();
        match state_file(cli).filter(|_| keeps_state) {
            // Taken when a command first uses `plc`, not now: a plcsh that never does (ports,
            // models, help, a fleet, a second shell for the drive) leaves it to the shell that
            // has it (docs/state.md, "One plcsh per state file").
            Some(state) => s.open_with_option_on_first_use("plc", &url, "state", &state.to_string_lossy())?,
            None => s.open("plc", &url)?,
        }
        if interactive_shell(cli) {
            // A second interactive shell: say now that the state file is taken, and go on with a
            // plc that keeps nothing rather than refusing every command on it.
            let i = s.index("plc")?;
            if let Err(e) = s.ready(i) {
                if !matches!(e.code, "k2-state-in-use" | "k2-state-in-use-by") {
                    return Err(e);
                }
                s.open("plc", &url)?;
                eprintln!("{}", crate::msg!("shell-state-taken", reason = e.message.trim_end_matches('.')));
            }
        }
    }
    if !named.iter().any(|(n, _)| n == "servo") && !real_servo {
        s.open("servo", "sim-servo:?id=1")?;
    }
    for d in &cli.devices {
        let (name, url) = split_device_arg(d);
        if line_by_line(cli) {
            // A shell opened before the cabinet is powered stays open: the device is marked not
            // connected and every command tries again. A one-shot still fails with the link error.
            if let Some(e) = s.open_or_later(&name, &url)? {
                eprintln!(
                    "{}",
                    crate::msg!("shell-not-connected-yet", device = name.as_str(), reason = e.message.as_str())
                );
            }
        } else if matches!(&cli.sub, Some(Sub::Publish(p)) if p.fleet.is_none()) {
            // A publisher waits for its device like a fleet's member: offline (the reason on its
            // status topic) and tried again with backoff until it answers (docs/fleets.md).
            s.open_or_later(&name, &url)?;
        } else {
            s.open(&name, &url)?;
        }
        if name == url {
            current = name;
        }
    }
    if s.index(&current).is_err() {
        // No `plc`: the first device named on the command line is current.
        current = named.first().map(|(n, _)| n.clone()).unwrap_or_default();
    }
    s.use_device(&current)?;
    for t in &cli.tags {
        // `DEVICE=FILE` when DEVICE is an open device, else a file for the current device.
        let (i, file) = match t.split_once('=').map(|(d, f)| (s.index(d), f)) {
            Some((Ok(i), f)) => (i, f),
            _ => (s.current_index()?, t.as_str()),
        };
        s.load_tags(i, std::path::Path::new(file))?;
        for w in &s.names(i).warnings {
            eprintln!("plcsh: warning: {w}");
        }
    }
    // `sim serve --bench` opens the bench in the served simulators instead.
    if let (Some(path), false) = (&cli.bench, matches!(cli.sub, Some(Sub::Sim { .. }))) {
        let bench = crate::wiring::bench::Bench::load(path)?;
        for note in crate::wiring::bench::open(&mut s, &bench)? {
            eprintln!("plcsh: {note}");
        }
    }
    Ok(s)
}

/// The REPL or a batch of lines on stdin (no subcommand, no `-c`, no fleet): commands come
/// one at a time, so a device that is not there yet can be there for the next one.
fn line_by_line(cli: &Cli) -> bool {
    cli.sub.is_none() && cli.command.is_none() && cli.fleet.is_none()
}

/// The REPL at a terminal (not a batch on stdin).
fn interactive_shell(cli: &Cli) -> bool {
    line_by_line(cli) && std::io::stdin().is_terminal()
}

/// Options of plcsh that take a value (`--time stepped`): their value is not a positional.
const VALUE_OPTIONS: &[&str] = &[
    "-c",
    "--command",
    "--model",
    "-d",
    "--device",
    "--tags",
    "--time",
    "--config",
    "--state",
    "--write-dir",
    "--report",
    "--record",
    "--bench",
    "-f",
    "--fleet",
    "-j",
    "--jobs",
    "--device-timeout",
    "--lang",
];

/// `--lang`: a language plcsh speaks, by tag (`ru`, `zh-CN`) or locale name (`ru_RU.UTF-8`).
fn parse_lang(text: &str) -> Result<crate::core::msg::Lang, String> {
    crate::core::msg::Lang::from_tag(text).ok_or_else(|| crate::msg!("lang-unknown", lang = text).into())
}

/// The language `--lang X` (or `--lang=X`) names on a command line clap refused or answered
/// with help, for that answer.
fn lang_in(argv: &[std::ffi::OsString]) -> Option<crate::core::msg::Lang> {
    let words: Vec<&str> = argv.iter().filter_map(|a| a.to_str()).collect();
    words.iter().enumerate().rev().find_map(|(i, w)| match w.strip_prefix("--lang") {
        Some(v) if v.starts_with('=') => crate::core::msg::Lang::from_tag(&v[1..]),
        Some("") => words.get(i + 1).and_then(|v| crate::core::msg::Lang::from_tag(v)),
        _ => None,
    })
}

/// What a word of the command line is, before clap sees it.
#[derive(Clone, Copy, PartialEq, Eq, Debug)]
enum Word {
    /// An option (`-v`, `--json`, `--time`; the value of one in [`VALUE_OPTIONS`] is skipped).
    Flag,
    /// `--`.
    Separator,
    /// Anything else: a subcommand, a script, an argument.
    Positional,
}

/// The words of `argv` after the program name, each with its index.
fn words(argv: &[std::ffi::OsString]) -> Vec<(usize, Word)> {
    let mut out = Vec::new();
    let mut i = 1;
    while i < argv.len() {
        let a = argv[i].to_string_lossy();
        let word = match a.as_ref() {
            "--" => Word::Separator,
            _ if a.starts_with('-') && a.len() > 1 => Word::Flag,
            _ => Word::Positional,
        };
        out.push((i, word));
        i += if word == Word::Flag && VALUE_OPTIONS.contains(&a.as_ref()) { 2 } else { 1 };
    }
    out
}

/// `plcsh [FLAGS] run [RUN FLAGS] SCRIPT ARGS…`: everything after the script belongs to the
/// script, even words that look like plcsh's own flags (`run a.lua --time stepped` gives
/// `--time` to the script). Returns the arguments for clap (up to the script) and the
/// script's arguments, or `None` when the command line is not `run`.
pub fn split_script_args(argv: Vec<std::ffi::OsString>) -> (Vec<std::ffi::OsString>, Option<Vec<String>>) {
    let mut in_run = false;
    for (i, word) in words(&argv) {
        let script = match word {
            Word::Flag => continue,
            Word::Separator if in_run => i + 1,
            Word::Separator => continue,
            Word::Positional if !in_run => {
                if argv[i] != "run" {
                    break;
                }
                in_run = true;
                continue;
            }
            Word::Positional => i,
        };
        if script >= argv.len() {
            break;
        }
        // The script: what follows is its own.
        let rest = argv[script + 1..].iter().map(|s| s.to_string_lossy().into_owned()).collect();
        let mut head = argv;
        head.truncate(script + 1);
        return (head, Some(rest));
    }
    (argv, None)
}

/// The parse of a command line without a subcommand (`plcsh -c '…' -d URL`, `plcsh --json`):
/// the top-level options alone, without building the subcommands' parsers (most of clap's
/// start-up: their arguments, the global options copied into each, and their stack frames;
/// BENCHMARKS.md, "One-shot start-up, second round"). `None` sends the line to the full
/// parser: a word that may be a subcommand, help or version, or anything this parser refuses,
/// so that help and every error message come from one place.
fn parse_one_shot(argv: &[std::ffi::OsString]) -> Option<Cli> {
    use clap::{Args, FromArgMatches};
    let help = ["-h", "--help", "-V", "--version"];
    if words(argv).iter().any(|&(i, w)| w != Word::Flag || help.iter().any(|h| argv[i] == *h)) {
        return None;
    }
    let matches = Options::augment_args(clap::Command::new("plcsh")).try_get_matches_from(argv).ok()?;
    let options = Options::from_arg_matches(&matches).ok()?;
    Some(Cli { options, sub: None })
}

/// The simulator state file the flags name: `--state FILE` (or `PLCSH_STATE`), none for
/// `none`, else the user's default file.
pub fn state_file(cli: &Cli) -> Option<std::path::PathBuf> {
    let given = cli.state.clone().or_else(|| std::env::var_os("PLCSH_STATE").filter(|s| !s.is_empty()).map(Into::into));
    match given {
        Some(p) if p.as_os_str() == "none" => None,
        Some(p) => Some(p),
        None => crate::k2::sim::state::default_path(),
    }
}

/// The family of a device URL (or profile) when it is a real device: `k2` for Modbus
/// URLs, `servo` for `kinco:`; `None` for simulators and unknown schemes.
fn real_family(s: &Session, url: &str) -> Option<&'static str> {
    let url = if url.contains(':') { url } else { s.profiles.get(url).map(|p| p.url.as_str())? };
    crate::session::url_family(url).filter(|(_, simulated)| !simulated).map(|(family, _)| family)
}

/// Entry point; returns the process exit status.
pub fn main() -> i32 {
    let code = run_cli();
    // A recording is complete only once written out (the REPL and one-shot paths both end here).
    match crate::record::stop() {
        Ok(()) => code,
        Err(e) => {
            eprintln!("plcsh: {e}");
            code.max(1)
        }
    }
}

fn run_cli() -> i32 {
    // Messages follow PLCSH_LANG and the system's language (read on the first message only).
    crate::core::msg::follow_system();
    let (argv, script_args) = split_script_args(std::env::args_os().collect());
    let parsed = match parse_one_shot(&argv) {
        Some(cli) => Ok(cli),
        None => Cli::try_parse_from(argv.iter()),
    };
    let cli = match parsed {
        Ok(mut c) => {
            if let (Some(Sub::Run(r)), Some(rest)) = (c.sub.as_mut(), script_args) {
                r.args = rest;
            }
            c
        }
        Err(e) => {
            // The answer (help, an error) in the language `--lang` names, if it names one.
            if let Some(lang) = lang_in(&argv) {
                crate::core::msg::set_choice(lang);
            }
            if let Some(msg) = unknown_subcommand(&argv, &e) {
                eprintln!("{msg}");
                return exit::USAGE;
            }
            // Help in the language of messages: the parser again, with the catalogue's texts
            // (only here, so a line that parses costs nothing). An error is clap's in English,
            // else written from the catalogue with clap's facts (cli::clap_error).
            use clap::error::ErrorKind;
            if let Some(text) = clap_error::render(&e) {
                eprint!("{text}");
                return exit::USAGE;
            }
            let e = if matches!(e.kind(), ErrorKind::DisplayHelp | ErrorKind::DisplayHelpOnMissingArgumentOrSubcommand)
            {
                localise::command(<Cli as clap::CommandFactory>::command())
                    .try_get_matches_from(argv.iter())
                    .err()
                    .filter(|l| l.kind() == e.kind())
                    .unwrap_or(e)
            } else {
                e
            };
            let _ = e.print();
            return if e.use_stderr() { exit::USAGE } else { exit::OK };
        }
    };
    if let Some(lang) = cli.lang {
        crate::core::msg::set_choice(lang);
    }
    crate::core::platform::enable_escapes();
    let style = Style::detect(cli.json);
    let mut out = std::io::stdout().lock();
    if let Some(Sub::Replay(args)) = &cli.sub {
        // Before any device is opened: replay builds its own simulators (and refuses --device).
        return record::replay(args, cli.bench.as_deref(), !cli.devices.is_empty(), style, &mut out);
    }
    if let Some(Sub::Man) = &cli.sub {
        // Made from the flags and the command registry: no device is opened.
        return man::run(&mut out);
    }
    if let Some(Sub::Tags(args)) = &cli.sub {
        // A tag file alone: no device is opened.
        return tags::run(args, style, &mut out);
    }
    if let Some(Sub::Lab { cmd }) = &cli.sub {
        // A lab builds its own simulators from its lab.toml (never the user's state file).
        // The stopping signals end the workers and the run with the signal's status (a worker
        // keeps the default handling: its parent ends it).
        if matches!(cmd, lab::LabCmd::Worker { .. }) {
            return lab::run(cmd, style, &mut out);
        }
        crate::signals::install(&std::sync::Arc::new(std::sync::atomic::AtomicBool::new(false)));
        let code = lab::run(cmd, style, &mut out);
        return crate::signals::exit_status().unwrap_or(code);
    }
    let session = match build_session(&cli) {
        Ok(s) => s,
        Err(e) => {
            let _ = output::report_error(&mut out, style, "open", &e, None);
            return exit::for_error(e.kind);
        }
    };
    crate::signals::install(&session.interrupt);
    // Once per run: `plcsh devices` shows the problems itself, as notes of its listing (in
    // JSON they are its `problems` and `notes`, and the warnings stay on standard error).
    if !matches!(cli.sub, Some(Sub::Devices)) || style.json {
        for p in &session.profiles.problems {
            eprintln!("plcsh: warning: {p}");
        }
    }
    let mut shell = Shell::new(session, style);
    shell.verbose = cli.verbose > 0;
    if cli.verbose > 0 {
        // Every driver reports its frames to core::trace; -v shows them on stderr in hex with timing.
        crate::core::trace::set_sink(Some(std::sync::Arc::new(crate::core::trace::StderrSink)));
    }
    if !matches!(cli.sub, Some(Sub::Run(_))) {
        crate::script::install(&mut shell);
    }
    crate::lab::hook::install(&mut shell);

    let serving = matches!(cli.sub, Some(Sub::Sim { .. }));
    let code = run(&cli, shell, style, out);
    // A SIGTERM or SIGHUP that stopped the work decides the status (143, 129); for
    // `sim serve` they are the normal way to stop it (status 0 after a clean stop).
    match crate::signals::exit_status() {
        Some(s) if !serving => s,
        _ => code,
    }
}

/// plcsh's own message for a subcommand the command line does not have (`plcsh agent status`):
/// the subcommands there are, and the shell command of that name when there is one (`agent
/// status` is a shell command: `plcsh -c 'agent status'`).
fn unknown_subcommand(argv: &[std::ffi::OsString], e: &clap::Error) -> Option<String> {
    use clap::error::{ContextKind, ContextValue};
    if e.kind() != clap::error::ErrorKind::InvalidSubcommand {
        return None;
    }
    let Some(ContextValue::String(bad)) = e.get(ContextKind::InvalidSubcommand) else { return None };
    // The subcommands typed before the unknown word (`agent`), walked through the definition.
    let mut cmd = <Cli as clap::CommandFactory>::command();
    let mut path = vec!["plcsh".to_string()];
    for a in argv.iter().skip(1).filter_map(|a| a.to_str()) {
        if a == bad {
            break;
        }
        if let Some(sub) = cmd.find_subcommand(a).cloned() {
            path.push(a.to_string());
            cmd = sub;
        }
    }
    let subs: Vec<String> = cmd
        .get_subcommands()
        .filter(|s| !s.is_hide_set())
        .map(|s| s.get_name().to_string())
        .filter(|n| n != "help")
        .collect();
    let mut msg = crate::msg!(
        "cli-no-such-subcommand",
        command = path.join(" "),
        subcommand = bad.as_str(),
        subcommands = subs.join(", ")
    )
    .text;
    let shell_line = format!("{} {bad}", path[1..].join(" "));
    let shell_line = shell_line.trim();
    if let Some(c) = crate::shell::commands::find(shell_line.split(' ').next().unwrap_or("")) {
        if !crate::shell::commands::forms::fitting(c, shell_line[c.name.len()..].trim()).is_empty() {
            let hint = crate::msg!("cli-hint-shell-command", line = shell_line);
            msg.push_str(&format!("\n  {}", crate::msg!("label-hint", hint = hint.text)));
        }
    }
    msg.push_str(&format!("\n  {}", crate::msg!("cli-help-describes-each", command = path.join(" "))));
    Some(msg)
}

/// Runs what the flags ask for with the built shell; returns the exit status.
fn run(cli: &Cli, mut shell: Shell, style: Style, mut out: std::io::StdoutLock<'static>) -> i32 {
    if let Some(name) = &cli.fleet {
        return match (&cli.sub, &cli.command) {
            (Some(Sub::Run(args)), _) if args.fleet.is_none() => {
                fleet::script(cli, &shell, name, args, style, &mut out)
            }
            (None, Some(cmds)) => fleet::commands(cli, &shell, name, cmds, style, &mut out),
            _ => {
                let e = crate::core::Error::usage(crate::msg!("cli-fleet-needs-work"))
                    .hint(crate::msg!("cli-hint-fleet-needs-work", fleet = name.as_str()));
                let _ = output::report_error(&mut out, style, "fleet", &e, None);
                2
            }
        };
    }
    if let Some(Sub::Run(args)) = &cli.sub {
        if let Some(name) = &args.fleet {
            return fleet::script(cli, &shell, name, args, style, &mut out);
        }
    }
    if let Some(sub) = &cli.sub {
        return match sub {
            Sub::Models { name } => match crate::shell::commands::models::outcome(name.as_deref()) {
                Ok(o) => i32::from(output::write_outcome(&mut out, style, &o).is_err()),
                Err(e) => {
                    let _ = output::report_error(&mut out, style, "models", &e, None);
                    2
                }
            },
            Sub::Man => man::run(&mut out),
            Sub::Completions { shell, write } => completions::run(*shell, write.as_deref(), &mut out),
            Sub::Devices => i32::from(!shell.run_line("devices", &mut out)),
            Sub::Ports => i32::from(!shell.run_line("ports", &mut out)),
            Sub::Paths => i32::from(!shell.run_line("paths", &mut out)),
            Sub::Sim { cmd: serve::SimCmd::Serve(args) } => serve::run(cli, args, style, &mut out),
            Sub::Sim { cmd: serve::SimCmd::Control(args) } => serve::control_run(args, style, &mut out),
            Sub::Agent(agent::AgentArgs { cmd: agent::AgentCmd::Check(a) }) => probe::check(a, &shell, style, &mut out),
            Sub::Agent(a) => agent::run(a, &mut out),
            Sub::Probe(a) => probe::probe(a, &shell, style, &mut out),
            Sub::Run(args) => run::main(&mut shell, args, style),
            Sub::Record { cmd } => record::show(cmd, style, &mut out),
            Sub::Replay(args) => record::replay(args, cli.bench.as_deref(), false, style, &mut out),
            Sub::Lab { cmd } => lab::run(cmd, style, &mut out),
            Sub::Publish(args) => publish::run(cli, &mut shell, args, style, &mut out),
            Sub::Tags(args) => tags::run(args, style, &mut out),
        };
    }
    if let Some(cmds) = &cli.command {
        return i32::from(!shell.run_line(cmds, &mut out));
    }
    drop(out);
    if std::io::stdin().is_terminal() {
        repl::interactive(&mut shell)
    } else {
        let stdin = std::io::stdin();
        let mut input = stdin.lock();
        let mut out = std::io::stdout().lock();
        let code = repl::batch(&mut shell, &mut input, &mut out);
        let _ = out.flush();
        code
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn argv(line: &[&str]) -> Vec<std::ffi::OsString> {
        std::iter::once("plcsh").chain(line.iter().copied()).map(Into::into).collect()
    }

    #[test]
    fn the_light_parse_equals_the_full_parse() {
        let lines: &[&[&str]] = &[
            &[],
            &["-c", "get VW0..VW18", "-d", "tcp://127.0.0.1:502?model=K205-16DT"],
            &["--json", "-vv", "--command=get VW0", "--time", "stepped", "--state", "none"],
            &["-d", "press=sim:K209EA-50DX", "--device", "servo=sim-servo:?id=2", "--read-only"],
            &["--model", "K204ET-16DT", "--config", "x.toml", "--record", "r.pcapng", "--bench", "b.toml"],
        ];
        for line in lines {
            let light = parse_one_shot(&argv(line)).unwrap_or_else(|| panic!("{line:?}: not taken"));
            let full = Cli::try_parse_from(argv(line)).unwrap();
            assert_eq!(format!("{light:?}"), format!("{full:?}"), "{line:?}");
        }
    }

    #[test]
    fn the_full_parser_takes_subcommands_help_and_errors() {
        let lines: &[&[&str]] = &[
            &["models"],
            &["--json", "sim", "serve", "--tcp", "0"],
            &["-vc", "get VW0"],
            &["--help"],
            &["-V"],
            &["--time", "sometimes"],
            &["--no-such-flag"],
            &["-c"],
            &["-c", "--json"],
            &["--", "-c"],
        ];
        for line in lines {
            assert!(parse_one_shot(&argv(line)).is_none(), "{line:?}");
        }
    }

    #[test]
    fn a_scripts_own_arguments_start_after_the_script() {
        let split = |line: &[&str]| {
            let (head, rest) = split_script_args(argv(line));
            (head.len() - 1, rest)
        };
        let some = |v: &[&str]| Some(v.iter().map(|s| s.to_string()).collect::<Vec<_>>());
        assert_eq!(split(&["run", "a.lua", "--time", "stepped"]), (2, some(&["--time", "stepped"])));
        assert_eq!(split(&["--time", "stepped", "run", "--sandbox", "a.lua", "x"]), (5, some(&["x"])));
        assert_eq!(split(&["run", "--time", "stepped", "a.lua"]), (4, some(&[])));
        assert_eq!(split(&["run", "--", "-odd.lua", "y"]), (3, some(&["y"])));
        assert_eq!(split(&["--", "run", "a.lua"]), (3, some(&[])));
        assert_eq!(split(&["run", "--"]), (2, None));
        assert_eq!(split(&["models", "run"]), (2, None));
        assert_eq!(split(&["-c", "run", "x"]), (3, None), "`run` is -c's value here");
    }

    #[test]
    fn every_top_level_option_with_a_value_is_known_to_the_scans() {
        // `split_script_args` and `parse_one_shot` skip an option's value by this list; an
        // option missing from it would make its value look like a subcommand or a script.
        use clap::CommandFactory;
        for arg in Cli::command().get_arguments().filter(|a| a.get_action().takes_values()) {
            let names =
                arg.get_long().map(|l| format!("--{l}")).into_iter().chain(arg.get_short().map(|s| format!("-{s}")));
            for name in names {
                assert!(VALUE_OPTIONS.contains(&name.as_str()), "{name} takes a value: add it to VALUE_OPTIONS");
            }
        }
    }

    #[test]
    fn device_args_with_and_without_names() {
        assert_eq!(split_device_arg("press=sim:K209EA-50DX"), ("press".into(), "sim:K209EA-50DX".into()));
        assert_eq!(split_device_arg("tcp://127.0.0.1:502?unit=1"), ("plc".into(), "tcp://127.0.0.1:502?unit=1".into()));
        assert_eq!(split_device_arg("press1"), ("press1".into(), "press1".into()), "a bare profile name");
        assert_eq!(split_device_arg("p=press1"), ("p".into(), "press1".into()));
    }
}
