//! `--help` and the man page in the language of messages: the command line's texts (what plcsh
//! and each subcommand do, the top-level options, the headings and the help flag) from the
//! message catalogue, put into clap's definition at run time (clap takes any string for
//! `about`, `help`, a heading and the help template).
//!
//! The English texts stay where clap's derive reads them (the doc comments of `Cli`,
//! `Options` and `Sub`); the catalogue's English of every id here is the same text (a test
//! below holds them together), so an English `--help` is clap's own, built without the
//! catalogue. Only a Russian or Chinese `--help` (and only when help or an error is shown:
//! [`super::run_cli`]) reads the catalogue: a command line that parses costs nothing more.
//!
//! Not translated, by clap's design: its own error sentences (`unexpected argument …`), the
//! `[default: …]` and `Possible values:` labels, and the texts of the subcommands' own options.

use crate::core::msg::{language, Lang, Msg};
use crate::msg;
use clap::{Arg, ArgAction, Command};

type Text = fn() -> Msg;

/// The top-level options, by clap's id (the field of `Options`).
const OPTIONS: &[(&str, Text)] = &[
    ("command", || msg!("cli-opt-command")),
    ("json", || msg!("cli-opt-json")),
    ("verbose", || msg!("cli-opt-verbose")),
    ("model", || msg!("cli-opt-model")),
    ("devices", || msg!("cli-opt-device")),
    ("time", || msg!("cli-opt-time")),
    ("config", || msg!("cli-opt-config", file = crate::core::platform::words::profile_file!())),
    ("state", || msg!("cli-opt-state")),
    ("record", || msg!("cli-opt-record")),
    ("bench", || msg!("cli-opt-bench")),
    ("read_only", || msg!("cli-opt-read-only")),
    ("fleet", || msg!("cli-opt-fleet")),
    ("jobs", || msg!("cli-opt-jobs")),
    ("lang", || msg!("cli-opt-lang")),
    ("device_timeout", || msg!("cli-opt-device-timeout")),
    ("tags", || msg!("cli-opt-tags")),
];

/// The subcommands, by name: what each does.
const SUBCOMMANDS: &[(&str, Text)] = &[
    ("models", || msg!("cli-sub-models")),
    ("devices", || msg!("cli-sub-devices")),
    ("ports", || msg!("cli-sub-ports")),
    ("paths", || msg!("cli-sub-paths")),
    ("man", || msg!("cli-sub-man")),
    ("completions", || msg!("cli-sub-completions")),
    ("sim", || msg!("cli-sub-sim", served = crate::core::platform::words::SERVED)),
    ("agent", || msg!("cli-sub-agent")),
    ("probe", || msg!("cli-sub-probe")),
    ("run", || msg!("cli-sub-run")),
    ("record", || msg!("cli-sub-record")),
    ("replay", || msg!("cli-sub-replay")),
    ("lab", || msg!("cli-sub-lab")),
    ("publish", || msg!("cli-sub-publish")),
    ("tags", || msg!("cli-sub-tags")),
];

/// Texts of the subcommands' own subcommands and options: (subcommand, its subcommand, the
/// option's clap id or none for what the subcommand does, the text).
const NESTED: &[(&str, &str, Option<&str>, Text)] = &[
    ("lab", "new", None, || msg!("cli-lab-new")),
    ("lab", "new", Some("name"), || msg!("cli-lab-new-name")),
    ("lab", "check", None, || msg!("cli-lab-check")),
    ("lab", "check", Some("lab"), || msg!("cli-lab-arg-lab")),
    ("lab", "grade", None, || msg!("cli-lab-grade")),
    ("lab", "grade", Some("lab"), || msg!("cli-lab-arg-lab")),
    ("lab", "grade", Some("submissions"), || msg!("cli-lab-grade-submissions")),
    ("lab", "grade", Some("jobs"), || msg!("cli-lab-grade-jobs")),
    ("lab", "grade", Some("junit"), || msg!("cli-lab-grade-junit")),
    ("lab", "grade", Some("show_output"), || msg!("cli-lab-grade-show-output")),
];

/// An option's help (and its long help, when clap made one from a longer doc comment).
fn arg_text(a: Arg, text: String) -> Arg {
    let long = a.get_long_help().is_some();
    let a = a.help(text.clone());
    if long {
        a.long_help(text)
    } else {
        a
    }
}

/// `cmd` (the whole command line's definition) in the current language: unchanged in English.
pub fn command(cmd: Command) -> Command {
    if language() == Lang::En {
        return cmd;
    }
    apply(cmd)
}

/// Puts the catalogue's texts into `cmd`, whatever the language.
fn apply(mut cmd: Command) -> Command {
    cmd = cmd.about(msg!("cli-about").text);
    for (id, text) in OPTIONS {
        cmd = cmd.mut_arg(id, |a| arg_text(a, text().text));
    }
    for (name, text) in SUBCOMMANDS {
        cmd = cmd.mut_subcommand(name, |s| s.about(text().text));
    }
    for (sub, inner, arg, text) in NESTED {
        cmd = cmd.mut_subcommand(sub, |s| {
            s.mut_subcommand(inner, |t| match arg {
                None => t.about(text().text),
                Some(a) => t.mut_arg(a, |x| arg_text(x, text().text)),
            })
        });
    }
    frame(cmd, true)
}

/// The parts of a help screen every command has: the `Usage:` heading, the option headings,
/// the help flag; for `cmd` and each of its subcommands.
fn frame(mut cmd: Command, top: bool) -> Command {
    // clap takes headings as `&'static str` (without its `string` feature): made once, for the
    // one help screen or error this process prints.
    static HEADINGS: std::sync::OnceLock<[&'static str; 4]> = std::sync::OnceLock::new();
    let [global, options, commands, arguments] = *HEADINGS.get_or_init(|| {
        let leak = |m: Msg| -> &'static str { Box::leak(m.text.into_boxed_str()) };
        [
            leak(msg!("cli-heading-global")),
            leak(msg!("cli-heading-options")),
            leak(msg!("cli-heading-commands")),
            leak(msg!("cli-heading-arguments")),
        ]
    });
    let template = format!(
        "{{before-help}}{{about-with-newline}}\n{} {{usage}}\n\n{{all-args}}{{after-help}}",
        msg!("cli-heading-usage")
    );
    if top {
        cmd = cmd.disable_version_flag(true).arg(
            Arg::new("version")
                .short('V')
                .long("version")
                .action(ArgAction::Version)
                .help(msg!("cli-version-flag").text),
        );
    }
    cmd = cmd
        .help_template(template)
        .subcommand_help_heading(commands)
        .disable_help_flag(true)
        .arg(Arg::new("help").short('h').long("help").action(ArgAction::Help).help(msg!("cli-help-flag").text))
        .mut_args(|a| match a.get_help_heading() {
            Some(super::GLOBAL) => a.help_heading(global),
            None if a.is_positional() => a.help_heading(arguments),
            None => a.help_heading(options),
            _ => a,
        });
    cmd.mut_subcommands(|s| frame(s, false))
}

#[cfg(test)]
mod tests {
    use super::*;
    use clap::CommandFactory;

    /// The catalogue's English of each text here is clap's text from the doc comments: an
    /// English `--help` (clap's own) and a Russian one say the same things. (The library
    /// speaks English unless told: these are the English texts.)
    #[test]
    fn the_catalogues_english_is_clap_s_text() {
        assert_eq!(language(), Lang::En);
        let cmd = super::super::Cli::command();
        assert_eq!(cmd.get_about().map(|s| s.to_string()), Some(msg!("cli-about").text));
        for (id, text) in OPTIONS {
            let arg = cmd.get_arguments().find(|a| a.get_id() == id).unwrap_or_else(|| panic!("no option {id}"));
            assert_eq!(arg.get_help().map(|s| s.to_string()), Some(text().text), "--{id}");
        }
        for (name, text) in SUBCOMMANDS {
            let sub = cmd.find_subcommand(name).unwrap_or_else(|| panic!("no subcommand {name}"));
            assert_eq!(sub.get_about().map(|s| s.to_string()), Some(text().text), "{name}");
        }
        for (sub, inner, arg, text) in NESTED {
            let c = cmd.find_subcommand(sub).and_then(|s| s.find_subcommand(inner)).expect("a nested subcommand");
            let shown = match arg {
                None => c.get_about(),
                Some(a) => c.get_arguments().find(|x| x.get_id() == a).and_then(|x| x.get_help()),
            };
            assert_eq!(shown.map(|s| s.to_string()), Some(text().text), "{sub} {inner} {arg:?}");
        }
        // Every subcommand and every top-level option with a help text has its text here.
        for sub in cmd.get_subcommands() {
            assert!(SUBCOMMANDS.iter().any(|(n, _)| *n == sub.get_name()), "{} has no text here", sub.get_name());
        }
        for a in cmd.get_arguments().filter(|a| a.get_help().is_some()) {
            assert!(OPTIONS.iter().any(|(id, _)| *id == a.get_id()), "--{} has no text here", a.get_id());
        }
    }

    /// The catalogue's texts keep every option, subcommand and flag of the help screen.
    #[test]
    fn the_catalogues_help_keeps_every_option() {
        let mut cmd = apply(super::super::Cli::command());
        let help = cmd.render_long_help().to_string();
        for opt in
            ["--json", "--lang", "--device-timeout", "--help", "--version", "models", "publish", "Global options:"]
        {
            assert!(help.contains(opt), "{opt} missing:\n{help}");
        }
    }
}
