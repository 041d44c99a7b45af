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
        let rows = COMMANDS
            .iter()
            .map(|c| {
                // The short form; `help COMMAND` gives the whole usage.
                let mut name = c.name.to_string();
                let mut subs = String::new();
                for sub in c.subcommands {
                    if subs.len() + sub.len() > 32 {
                        subs.push('…');
                        break;
                    }
                    if !subs.is_empty() {
                        subs.push('|');
                    }
                    subs.push_str(sub);
                }
                if !subs.is_empty() {
                    name.push_str(&format!(" {subs}"));
                }
                vec![name, c.summary.to_string()]
            })
            .collect();
        let names: Vec<&str> = COMMANDS.iter().map(|c| c.name).collect();
        return Ok(Outcome::new("help").table(&["command", "what it does"], rows).with("commands", names));
    }
    if let Some(c) = super::find(&topic.to_ascii_lowercase()) {
        return Ok(Outcome::new("help").text(format!("{}\n  {}", c.usage, c.summary)).with("command", c.name));
    }
    let target = sh.session.resolve(topic)?;
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
