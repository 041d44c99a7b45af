//! `help [COMMAND|OPERAND]` and `quit`.

use super::{CommandSpec, COMMANDS};
use crate::core::Result;
use crate::output::Outcome;
use crate::shell::{Args, Shell};

pub const HELP: CommandSpec = CommandSpec {
    name: "help",
    aliases: &["?"],
    usage: "help [COMMAND|OPERAND]",
    summary: "list commands, or explain one command (its full usage) or operand",
    subcommands: &[],
    run: help,
};

pub const QUIT: CommandSpec = CommandSpec {
    name: "quit",
    aliases: &["exit", "q"],
    usage: "quit",
    summary: "leave the shell",
    subcommands: &[],
    run: quit,
};

fn help(sh: &mut Shell, args: Args) -> Result<Outcome> {
    let topic = args.text.trim();
    if topic.is_empty() {
        // Name and summary, wrapped to 80 columns; `help COMMAND` gives the whole usage.
        let names: Vec<&str> = COMMANDS.iter().map(|c| c.name).collect();
        return Ok(Outcome::new("help").text(command_list()).with("commands", names));
    }
    if let Some(c) = super::find(&topic.to_ascii_lowercase()) {
        let mut text = crate::core::text::wrap(c.usage, 78).join("\n    ");
        for line in crate::core::text::wrap(c.summary, 76) {
            text.push_str(&format!("\n  {line}"));
        }
        if !c.subcommands.is_empty() {
            for line in crate::core::text::wrap(&format!("sub-commands: {}", c.subcommands.join(", ")), 76) {
                text.push_str(&format!("\n  {line}"));
            }
        }
        return Ok(Outcome::new("help").text(text).with("command", c.name));
    }
    let target = sh.session.resolve(topic).map_err(|e| {
        // A word that is neither a command nor an operand: most likely a mistyped command.
        if topic.chars().all(|c| c.is_ascii_alphabetic() || c == '-') {
            crate::core::Error::usage(format!("no command or operand `{topic}`"))
                .hint(super::suggest(&topic.to_ascii_lowercase()))
                .column(args.offset)
        } else {
            e
        }
    })?;
    let entry = &sh.session.entries()[target.device];
    let body = topic.rsplit(':').next().unwrap_or(topic);
    let text = entry.device.operands().help(body)?;
    let mut o = Outcome::new("help").text(text.trim_end().to_string());
    o.device = Some(entry.name.clone());
    Ok(o)
}

fn quit(sh: &mut Shell, _args: Args) -> Result<Outcome> {
    sh.quit = true;
    Ok(Outcome::new("quit").quiet())
}

/// The command list as `help` prints it: one command a line, summaries wrapped to fit 80
/// columns under their own column.
pub fn command_list() -> String {
    const WIDTH: usize = 80;
    let name_w = COMMANDS.iter().map(|c| c.name.len()).max().unwrap_or(4) + 2;
    let mut text = String::from("commands (`help COMMAND` shows its full usage and sub-commands):\n");
    for c in COMMANDS {
        for (i, line) in crate::core::text::wrap(c.summary, WIDTH - 2 - name_w - 1).iter().enumerate() {
            let name = if i == 0 { c.name } else { "" };
            text.push_str(&format!("  {name:<name_w$}{line}\n"));
        }
    }
    text.push_str("operands: `help VW100`, `help SMB67` explain one; Tab completes them");
    text
}
