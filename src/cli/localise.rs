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
//! Every subcommand's own options are here too (`plcsh --lang ru sim serve --help`); clap's
//! own error sentences are written from the catalogue by `super::clap_error`; an option's
//! `[default: …]` and `[possible values: …]` labels too (clap's own are hidden then).

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

/// Texts of the subcommands' own subcommands and options: (the path of subcommands below
/// `plcsh`, the option's clap id or none for what the subcommand does, the text). Every
/// subcommand and option with a help text is here (a test walks the definition).
const NESTED: &[(&[&str], Option<&str>, Text)] = &[
    (&["models"], Some("name"), || msg!("cli-models-name")),
    (&["completions"], Some("shell"), || msg!("cli-completions-shell")),
    (&["completions"], Some("write"), || msg!("cli-completions-write")),
    (&["sim", "serve"], None, || msg!("cli-sim-serve")),
    (&["sim", "serve"], Some("tcp"), || msg!("cli-sim-serve-tcp")),
    (&["sim", "serve"], Some("rtu_pty"), || msg!("cli-sim-serve-rtu-pty")),
    (&["sim", "serve"], Some("rtu_tcp"), || msg!("cli-sim-serve-rtu-tcp")),
    (&["sim", "serve"], Some("unit"), || msg!("cli-sim-serve-unit")),
    (&["sim", "serve"], Some("agent"), || msg!("cli-sim-serve-agent")),
    (&["sim", "serve"], Some("program"), || msg!("cli-sim-serve-program")),
    (&["sim", "serve"], Some("servo_pty"), || msg!("cli-sim-serve-servo-pty")),
    (&["sim", "serve"], Some("servo_tcp"), || msg!("cli-sim-serve-servo-tcp")),
    (&["sim", "serve"], Some("servo_control"), || msg!("cli-sim-serve-servo-control")),
    (&["sim", "serve"], Some("servo_id"), || msg!("cli-sim-serve-servo-id")),
    (&["sim", "serve"], Some("servo_loop"), || msg!("cli-sim-serve-servo-loop")),
    (&["sim", "serve"], Some("servo_baud"), || msg!("cli-sim-serve-servo-baud")),
    (&["sim", "serve"], Some("servo_latency"), || msg!("cli-sim-serve-servo-latency")),
    (&["sim", "serve"], Some("servo_instant"), || msg!("cli-sim-serve-servo-instant")),
    (&["sim", "serve"], Some("servo_strict"), || msg!("cli-sim-serve-servo-strict")),
    (&["sim", "serve"], Some("fx_pty"), || msg!("cli-sim-serve-fx-pty")),
    (&["sim", "serve"], Some("fx_tcp"), || msg!("cli-sim-serve-fx-tcp")),
    (&["sim", "serve"], Some("fx_link_pty"), || msg!("cli-sim-serve-fx-link-pty")),
    (&["sim", "serve"], Some("fx_link_tcp"), || msg!("cli-sim-serve-fx-link-tcp")),
    (&["sim", "serve"], Some("fx_model"), || msg!("cli-sim-serve-fx-model")),
    (&["sim", "serve"], Some("fx_station"), || msg!("cli-sim-serve-fx-station")),
    (&["sim", "serve"], Some("fx_program"), || msg!("cli-sim-serve-fx-program")),
    (&["sim", "serve"], Some("umpk_pty"), || msg!("cli-sim-serve-umpk-pty")),
    (&["sim", "serve"], Some("umpk_tcp"), || msg!("cli-sim-serve-umpk-tcp")),
    (&["sim", "serve"], Some("umpk_model"), || msg!("cli-sim-serve-umpk-model")),
    (&["sim", "serve"], Some("umpk_status_bits"), || msg!("cli-sim-serve-umpk-status-bits")),
    (&["sim", "serve"], Some("umpk_flash_fail"), || msg!("cli-sim-serve-umpk-flash-fail")),
    (&["sim", "serve"], Some("umpk_state"), || msg!("cli-sim-serve-umpk-state")),
    (&["sim", "serve"], Some("umpk_program"), || msg!("cli-sim-serve-umpk-program")),
    (&["sim", "serve"], Some("fx_control"), || msg!("cli-sim-serve-fx-control")),
    (&["sim", "serve"], Some("umpk_control"), || msg!("cli-sim-serve-umpk-control")),
    (&["sim", "serve"], Some("k2_control"), || msg!("cli-sim-serve-k2-control")),
    (&["sim", "serve"], Some("faults"), || msg!("cli-sim-serve-fault")),
    (&["sim", "serve"], Some("max_connections"), || msg!("cli-sim-serve-max-connections")),
    (&["sim", "serve"], Some("idle_timeout"), || msg!("cli-sim-serve-idle-timeout")),
    (&["sim", "serve"], Some("strict_unit"), || msg!("cli-sim-serve-strict-unit")),
    (&["sim", "serve"], Some("fleet"), || msg!("cli-sim-serve-fleet")),
    (&["sim", "serve"], Some("rfc2217"), || msg!("cli-sim-serve-rfc2217")),
    (&["sim", "control"], None, || msg!("cli-sim-control")),
    (&["sim", "control"], Some("path"), || msg!("cli-sim-control-path")),
    (&["sim", "control"], Some("words"), || msg!("cli-sim-control-words")),
    (&["agent", "il"], None, || msg!("cli-agent-il")),
    (&["agent", "il"], Some("model"), || msg!("cli-agent-il-model")),
    (&["agent", "il"], Some("base"), || msg!("cli-agent-il-base")),
    (&["agent", "check"], None, || msg!("cli-agent-check")),
    (&["agent", "check"], Some("url"), || msg!("cli-agent-check-url")),
    (&["probe"], Some("url"), || msg!("cli-probe-url")),
    (&["probe"], Some("report"), || msg!("cli-probe-report")),
    (&["probe"], Some("reads"), || msg!("cli-probe-reads")),
    (&["probe"], Some("scan_serial"), || msg!("cli-probe-scan-serial")),
    (&["run"], Some("sandbox"), || msg!("cli-run-sandbox")),
    (&["run"], Some("write_dir"), || msg!("cli-run-write-dir")),
    (&["run"], Some("fleet"), || msg!("cli-run-fleet")),
    (&["run"], Some("report"), || msg!("cli-run-report")),
    (&["run"], Some("script"), || msg!("cli-run-script")),
    (&["run"], Some("args"), || msg!("cli-run-args")),
    (&["record", "show"], None, || msg!("cli-record-show")),
    (&["record", "show"], Some("file"), || msg!("cli-record-file")),
    (&["replay"], Some("file"), || msg!("cli-record-file")),
    (&["replay"], Some("sim_model"), || msg!("cli-replay-sim-model")),
    (&["replay"], Some("snapshot"), || msg!("cli-replay-snapshot")),
    (&["replay"], Some("agent"), || msg!("cli-replay-agent")),
    (&["lab", "new"], None, || msg!("cli-lab-new")),
    (&["lab", "new"], Some("name"), || msg!("cli-lab-new-name")),
    (&["lab", "check"], None, || msg!("cli-lab-check")),
    (&["lab", "check"], Some("lab"), || msg!("cli-lab-arg-lab")),
    (&["lab", "grade"], None, || msg!("cli-lab-grade")),
    (&["lab", "grade"], Some("lab"), || msg!("cli-lab-arg-lab")),
    (&["lab", "grade"], Some("submissions"), || msg!("cli-lab-grade-submissions")),
    (&["lab", "grade"], Some("jobs"), || msg!("cli-lab-grade-jobs")),
    (&["lab", "grade"], Some("junit"), || msg!("cli-lab-grade-junit")),
    (&["lab", "grade"], Some("show_output"), || msg!("cli-lab-grade-show-output")),
    (&["publish"], Some("broker"), || msg!("cli-publish-broker")),
    (&["publish"], Some("fleet"), || msg!("cli-publish-fleet")),
    (&["publish"], Some("every"), || msg!("cli-publish-every")),
    (&["publish"], Some("qos"), || msg!("cli-publish-qos")),
    (&["publish"], Some("on_change"), || msg!("cli-publish-on-change")),
    (&["publish"], Some("deadband"), || msg!("cli-publish-deadband")),
    (&["publish"], Some("buffer"), || msg!("cli-publish-buffer")),
    (&["publish"], Some("mqtt_version"), || msg!("cli-publish-mqtt-version")),
    (&["publish"], Some("count"), || msg!("cli-publish-count")),
    (&["publish"], Some("client_id"), || msg!("cli-publish-client-id")),
    (&["publish"], Some("accept_writes"), || msg!("cli-publish-accept-writes")),
    (&["publish"], Some("shard"), || msg!("cli-publish-shard")),
    (&["publish"], Some("operands"), || msg!("cli-publish-operands")),
    (&["tags"], Some("file"), || msg!("cli-tags-file")),
    (&["tags"], Some("model"), || msg!("cli-tags-model")),
    (&["tags"], Some("format"), || msg!("cli-tags-format")),
    (&["tags", "check"], None, || msg!("cli-tags-check")),
    (&["tags", "check"], Some("model"), || msg!("cli-tags-model")),
    (&["tags", "check"], Some("format"), || msg!("cli-tags-format")),
    (&["tags", "export"], None, || msg!("cli-tags-export")),
    (&["tags", "export"], Some("to"), || msg!("cli-tags-export-to")),
    (&["tags", "export"], Some("output"), || msg!("cli-tags-export-output")),
    (&["tags", "export"], Some("model"), || msg!("cli-tags-model")),
    (&["tags", "export"], Some("format"), || msg!("cli-tags-format")),
];

/// Applies `f` to the subcommand at `path` (`["sim", "serve"]`) below `cmd`.
fn at_path(cmd: Command, path: &[&str], f: &dyn Fn(Command) -> Command) -> Command {
    match path {
        [] => f(cmd),
        [first, rest @ ..] => cmd.mut_subcommand(first, |s| at_path(s, rest, f)),
    }
}

/// The subcommand at `path` below `cmd`.
#[cfg(test)]
fn find_path<'a>(cmd: &'a Command, path: &[&str]) -> Option<&'a Command> {
    path.iter().try_fold(cmd, |c, name| c.find_subcommand(name))
}

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
    let mut cmd = apply(cmd);
    // clap makes the `help` subcommand when it builds the definition: built here, so its text
    // can be the catalogue's too (the parse then uses the built definition as it is).
    cmd.build();
    help_subcommands(cmd)
}

/// The `help` subcommands clap made, at every level, with the catalogue's text.
fn help_subcommands(cmd: Command) -> Command {
    cmd.mut_subcommands(|s| {
        if s.get_name() == "help" {
            s.about(msg!("cli-help-subcommand").text)
        } else {
            help_subcommands(s)
        }
    })
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
    for (path, arg, text) in NESTED {
        cmd = at_path(cmd, path, &|t: Command| match arg {
            None => t.about(text().text),
            Some(a) => t.mut_arg(a, |x| arg_text(x, text().text)),
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
        .mut_args(|a| {
            labels(match a.get_help_heading() {
                Some(super::GLOBAL) => a.help_heading(global),
                None if a.is_positional() => a.help_heading(arguments),
                None => a.help_heading(options),
                _ => a,
            })
        });
    cmd.mut_subcommands(|s| frame(s, false))
}

/// An option's `[default: …]` and `[possible values: …]` in the catalogue's words: clap's own
/// labels hidden, the same facts written after the option's text.
fn labels(mut a: Arg) -> Arg {
    if !a.get_action().takes_values() {
        return a;
    }
    let mut extra = Vec::new();
    let defaults: Vec<String> = a.get_default_values().iter().map(|v| v.to_string_lossy().into_owned()).collect();
    if !defaults.is_empty() && !a.is_hide_default_value_set() {
        extra.push(msg!("cli-default", value = defaults.join(", ")).text);
        a = a.hide_default_value(true);
    }
    let values: Vec<String> =
        a.get_possible_values().iter().filter(|v| !v.is_hide_set()).map(|v| v.get_name().to_string()).collect();
    if !values.is_empty() && !a.is_hide_possible_values_set() {
        extra.push(msg!("cli-possible-values", values = values.join(", ")).text);
        a = a.hide_possible_values(true);
    }
    if extra.is_empty() {
        return a;
    }
    let tail = extra.join(" ");
    let long = a.get_long_help().map(|h| format!("{h}\n\n{tail}"));
    let short = match a.get_help() {
        Some(h) => format!("{h} {tail}"),
        None => tail,
    };
    let a = a.help(short);
    match long {
        Some(l) => a.long_help(l),
        None => a,
    }
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
        for (path, arg, text) in NESTED {
            let c = find_path(&cmd, path).unwrap_or_else(|| panic!("no subcommand {path:?}"));
            let shown = match arg {
                None => c.get_about(),
                Some(a) => c.get_arguments().find(|x| x.get_id() == a).and_then(|x| x.get_help()),
            };
            assert_eq!(shown.map(|s| s.to_string()), Some(text().text), "{path:?} {arg:?}");
        }
        // Below the top level: every shown subcommand and every option with a help text.
        fn walk(c: &Command, path: &[&str], out: &mut Vec<String>) {
            for sub in c.get_subcommands().filter(|s| !s.is_hide_set()) {
                let p: Vec<&str> = path.iter().copied().chain([sub.get_name()]).collect();
                let here = |q: &[&str]| q == p.as_slice();
                if !path.is_empty()
                    && sub.get_about().is_some()
                    && !NESTED.iter().any(|(q, a, _)| here(q) && a.is_none())
                {
                    out.push(p.join(" "));
                }
                for a in sub.get_arguments().filter(|a| a.get_help().is_some()) {
                    if !NESTED.iter().any(|(q, id, _)| here(q) && *id == Some(a.get_id().as_str())) {
                        out.push(format!("{} {}", p.join(" "), a.get_id()));
                    }
                }
                walk(sub, &p, out);
            }
        }
        let mut missing = Vec::new();
        walk(&cmd, &[], &mut missing);
        assert!(missing.is_empty(), "no text here for: {missing:?}");
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
