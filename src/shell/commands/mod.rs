//! The command registry: every shell command in one list, one file per command family.
//! Completion, `help` and the README's command table all read this list.

mod agent;
mod counter;
mod data;
mod device;
mod eeprom;
mod events;
mod fault;
pub mod forms;
mod fxsim;
pub mod help;
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
    /// What it does, in the current language (`summary-NAME` in the catalogue).
    pub summary: fn() -> crate::core::msg::Msg,
    /// Sub-commands, for completion.
    pub subcommands: &'static [&'static str],
    pub run: fn(&mut Shell, Args) -> Result<Outcome>,
}

impl CommandSpec {
    /// What the command does, in the current language.
    pub fn summary(&self) -> String {
        (self.summary)().text
    }
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
    data::DATA,
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
pub const DEVICE_FIRST: &[&str] = &["eeprom", "rtc", "events", "wait", "data"];

/// Commands that do not act on the current device, or find their device themselves (and make
/// it ready there): the shell does not make the current device ready before them, so `help`,
/// `ports` or `servo status` never take the simulated PLC's state file (`crate::pending`).
pub const NO_CURRENT_DEVICE: &[&str] = &[
    "help", "quit", "models", "ports", "paths", "devices", "use", "connect", "close", "lua", "lab", "get", "set",
    "read", "servo", "umpk", "agent",
];

/// Which words of a command are text — a file path, a name, a message — and never operands.
/// The shell reads the K2 manual's look-alike letters (`ВW0` as `VW0`,
/// [`crate::core::text::fold_manual_spelling`]) in every other word, and never in these:
/// `sim program load Проверка/светофор.il` loads that file. Quoted words are text wherever they
/// are. Every usage form with a file in it (`FILE…`, `LAB`, `SUBMISSIONS…`) has its entry
/// here (a test reads the registry's forms to keep it so).
pub struct TextArg {
    pub cmd: &'static str,
    /// The sub-command words before the text (any case); a device word may come first
    /// for the commands that read it themselves (`umpk lab program FILE.hex`).
    pub after: &'static [&'static str],
    pub what: Text,
    /// The placeholder in the usage form (`FILE.il`, `to=FILE.csv`, `LAB`).
    pub placeholder: &'static str,
}

/// Where the text is, after a [`TextArg`]'s sub-command words.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Text {
    /// Every word after them (a command that takes one file refuses more words, and names
    /// them as typed).
    Rest,
    /// The value of this `key=` option, anywhere after them.
    Option(&'static str),
    /// The one word right after them (`data save FILE OPERAND…`: the file is text, the
    /// operands after it are operands).
    Word,
}

const fn text(cmd: &'static str, after: &'static [&'static str], what: Text, placeholder: &'static str) -> TextArg {
    TextArg { cmd, after, what, placeholder }
}

/// Every command word that is text (see [`TextArg`]).
pub static TEXT_ARGS: &[TextArg] = &[
    text("sim", &["program", "load"], Text::Rest, "FILE.il"),
    text("sim", &["snapshot", "save"], Text::Rest, "NAME"),
    text("sim", &["snapshot", "restore"], Text::Rest, "NAME"),
    text("sim", &["break"], Text::Rest, "FILE:LINE"),
    text("eeprom", &["dump"], Text::Rest, "FILE"),
    text("eeprom", &["restore"], Text::Rest, "FILE"),
    text("data", &["save"], Text::Word, "FILE"),
    text("data", &["diff"], Text::Rest, "FILE"),
    text("data", &["load"], Text::Rest, "FILE"),
    text("servo", &["params", "save"], Text::Rest, "FILE"),
    text("servo", &["params", "diff"], Text::Rest, "FILE"),
    text("servo", &["params", "load"], Text::Rest, "FILE"),
    text("trace", &[], Text::Option("to"), "to=FILE.csv"),
    text("plot", &[], Text::Option("to"), "to=FILE.png"),
    text("profile", &[], Text::Option("to"), "to=FILE.png"),
    text("umpk", &["program"], Text::Rest, "FILE.hex"),
    text("umpk", &["send"], Text::Rest, "TEXT"),
    text("lab", &["new"], Text::Rest, "NAME"),
    text("lab", &["check"], Text::Rest, "LAB"),
    text("lab", &["grade"], Text::Rest, "SUBMISSIONS…"),
    text("connect", &[], Text::Rest, "URL"),
    text("use", &[], Text::Rest, "DEVICE"),
    text("close", &[], Text::Rest, "NAME"),
];

/// Commands that read a device word before their sub-command themselves.
const OWN_DEVICE_WORD: &[&str] = &["umpk", "servo", "agent"];

/// For each of `words` (a command's arguments as the lexer splits them, quotes kept): true
/// when it is text by [`TEXT_ARGS`] or quoted, false when it may be an operand or a value.
pub fn text_words(cmd: &str, words: &[&str]) -> Vec<bool> {
    let mut mask: Vec<bool> = words.iter().map(|w| w.contains(['"', '\''])).collect();
    for t in TEXT_ARGS.iter().filter(|t| t.cmd == cmd) {
        let starts: &[usize] = if OWN_DEVICE_WORD.contains(&cmd) { &[0, 1] } else { &[0] };
        for &s in starts {
            let n = t.after.len();
            let matches =
                words.len() >= s + n && t.after.iter().zip(&words[s..s + n]).all(|(a, w)| a.eq_ignore_ascii_case(w));
            if !matches {
                continue;
            }
            let from = s + n;
            match t.what {
                Text::Rest => mask[from..].iter_mut().for_each(|m| *m = true),
                Text::Word => mask.iter_mut().skip(from).take(1).for_each(|m| *m = true),
                Text::Option(key) => {
                    for (m, w) in mask[from..].iter_mut().zip(&words[from..]) {
                        if w.split_once('=').is_some_and(|(k, _)| k.eq_ignore_ascii_case(key)) {
                            *m = true;
                        }
                    }
                }
            }
            break;
        }
    }
    mask
}

pub fn find(name: &str) -> Option<&'static CommandSpec> {
    COMMANDS.iter().find(|c| c.name == name || c.aliases.contains(&name))
}

/// "did you mean" for an unknown command.
/// Refuses words after a command that takes none (`devices x`, `quit now`): extra words are
/// never ignored.
pub fn no_arguments(name: &str, args: Args) -> Result<()> {
    match args.text.split_whitespace().next() {
        None => Ok(()),
        Some(w) => Err(Error::usage(crate::msg!("shell-takes-nothing", command = name, word = w))
            .hint(name.to_string())
            .column(args.offset)),
    }
}

/// Commands of the command line that the shell does not have, with where they belong and
/// what the shell offers instead.
/// A message of the catalogue, made when it is shown (in the language of that moment).
type Where = fn() -> crate::core::msg::Msg;

const COMMAND_LINE_ONLY: &[(&str, Where)] = &[
    ("run", || crate::msg!("shell-cli-only-run")),
    ("replay", || crate::msg!("shell-cli-only-replay")),
    ("record", || crate::msg!("shell-cli-only-record")),
    ("completions", || crate::msg!("shell-cli-only-completions")),
    ("serve", || crate::msg!("shell-cli-only-serve")),
];

pub fn suggest(name: &str) -> String {
    if let Some((_, where_)) = COMMAND_LINE_ONLY.iter().find(|(n, _)| *n == name) {
        return where_().text;
    }
    let mut best: Vec<(usize, &str)> =
        COMMANDS.iter().map(|c| (crate::core::text::edit_distance(name, c.name), c.name)).collect();
    best.sort();
    match best.first() {
        Some((d, n)) if *d <= 2 => crate::msg!("shell-hint-did-you-mean", name = *n).into(),
        _ => crate::msg!("shell-hint-help").into(),
    }
}

#[cfg(test)]
mod text_args_tests {
    use super::*;

    /// Every form of every command, as `help` and the command card show them.
    fn forms() -> Vec<(&'static str, String)> {
        COMMANDS
            .iter()
            .flat_map(|c| {
                if c.subcommands.is_empty() {
                    vec![(c.name, c.usage.split("   e.g.").next().unwrap_or(c.usage).trim().to_string())]
                } else {
                    help::sub_forms(c).into_iter().map(|(_, f)| (c.name, f)).collect()
                }
            })
            .collect()
    }

    /// A placeholder that stands for a file or folder: `FILE…`, `LAB`, `SUBMISSIONS…`, and the
    /// NAME of `lab new NAME` and `sim snapshot save NAME` (a name or a path).
    fn is_file(cmd: &str, token: &str) -> bool {
        token.contains("FILE")
            || token == "LAB"
            || token.starts_with("SUBMISSIONS")
            || token == "NAME" && ["lab", "sim"].contains(&cmd)
    }

    /// Every file a usage form takes is text: a line made from the form (files a Cyrillic
    /// path, other placeholders a number) keeps the path as typed while the shell reads the
    /// manual's spelling in the rest. A new command that takes a file and is missing from
    /// [`TEXT_ARGS`] fails here.
    #[test]
    fn every_file_in_a_usage_form_is_text_never_an_operand() {
        const PATH: &str = "Проверка/светофор";
        let mut seen = Vec::new();
        for (cmd, form) in forms() {
            let (mut words, mut files) = (Vec::<String>::new(), Vec::new());
            for token in form.split_whitespace().skip(1) {
                let t = token.trim_matches(['[', ']']);
                if t.contains(['(', ')']) || t == "…" || t.is_empty() {
                    continue; // the profile's segment list
                }
                let alt = t.split('|').find(|a| is_file(cmd, a)).unwrap_or_else(|| t.split('|').next().unwrap_or(t));
                if is_file(cmd, alt) {
                    let (key, value) = alt.split_once('=').map_or(("", alt), |(k, v)| (k, v));
                    let ext = value.split_once('.').map_or(String::new(), |(_, e)| format!(".{e}"));
                    let eq = if key.is_empty() { "" } else { "=" };
                    files.push(words.len());
                    words.push(format!("{key}{eq}{PATH}{ext}"));
                } else if alt.chars().any(|c| c.is_ascii_uppercase()) && !alt.chars().any(|c| c.is_ascii_lowercase()) {
                    words.push("0".into());
                } else {
                    words.push(alt.to_string());
                }
            }
            if files.is_empty() {
                continue;
            }
            let text = words.join(" ");
            assert!(crate::shell::lex::words(&text).is_ok(), "{form}: `{text}` does not split");
            let after = crate::shell::fold_operands(cmd, &text).map_or(text.clone(), |f| f.0);
            let after: Vec<&str> = after.split(' ').collect();
            for &i in &files {
                assert_eq!(after.get(i).copied(), Some(words[i].as_str()), "{form}: the file was read as an operand");
            }
            seen.push(form);
        }
        for want in ["sim program load", "eeprom dump", "eeprom restore", "trace", "plot", "profile", "umpk program"] {
            assert!(seen.iter().any(|f| f.starts_with(want)), "no form `{want} … FILE` in the registry: {seen:?}");
        }
        // … and an operand next to them is still read in the manual's spelling.
        let f = crate::shell::fold_operands("trace", "ВW0 every=10ms to=Проверка.csv").unwrap();
        assert_eq!(f.0, "VW0 every=10ms to=Проверка.csv");
        let f = crate::shell::fold_operands("umpk", "lab program Проверка.hex info=\"Тест\" run").unwrap_or_default();
        assert_eq!(f.0, "", "nothing in `umpk program` is an operand");
    }
}
