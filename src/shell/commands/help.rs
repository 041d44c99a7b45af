//! `help [COMMAND|OPERAND]` and `quit`.

use super::{CommandSpec, COMMANDS};
use crate::core::Result;
use crate::output::Outcome;
use crate::shell::{Args, Shell};

pub const HELP: CommandSpec = CommandSpec {
    name: "help",
    aliases: &["?"],
    usage: "help [COMMAND [SUB]|OPERAND|all]",
    summary: || crate::msg!("summary-help"),
    subcommands: &[],
    run: help,
};

pub const QUIT: CommandSpec = CommandSpec {
    name: "quit",
    aliases: &["exit", "q"],
    usage: "quit",
    summary: || crate::msg!("summary-quit"),
    subcommands: &[],
    run: quit,
};

fn help(sh: &mut Shell, args: Args) -> Result<Outcome> {
    let topic = args.text.trim();
    if topic.is_empty() || topic.eq_ignore_ascii_case("all") {
        // `help`: the commands by group, on one 80×24 screen; `help all`: each with its summary.
        let names: Vec<&str> = COMMANDS.iter().map(|c| c.name).collect();
        let text = if topic.is_empty() { grouped() } else { command_list() };
        return Ok(Outcome::new("help").text(text).with("commands", names));
    }
    let mut words = topic.split_whitespace();
    let first = words.next().unwrap_or("").to_ascii_lowercase();
    if let (Some(c), Some(sub)) = (super::find(&first), words.next()) {
        return sub_help(c, sub, words.next(), args);
    }
    if let Some(c) = super::find(&topic.to_ascii_lowercase()) {
        return Ok(Outcome::new("help").text(command_help(c)).with("command", c.name));
    }
    let target = sh.session.resolve(topic).map_err(|e| {
        // A word that is neither a command nor an operand: most likely a mistyped command.
        if topic.chars().all(|c| c.is_ascii_alphabetic() || c == '-') {
            crate::core::Error::usage(crate::msg!("help-no-topic", topic = topic))
                .hint(super::suggest(&topic.to_ascii_lowercase()))
                .column(args.offset)
        } else {
            e
        }
    })?;
    let entry = &sh.session.entries()[target.device];
    let body = topic.rsplit(':').next().unwrap_or(topic);
    // A tag's name (`crate::names`): what it stands for and its comment, then its operand's help.
    if let Some(n) = entry.names.get(body) {
        let mut text: String = crate::msg!(
            "names-help-tag",
            name = n.name.as_str(),
            operand = n.operand.as_str(),
            file = entry.names.file.as_str()
        )
        .into();
        if !n.comment.is_empty() {
            text.push_str(&format!("\n  {}", crate::msg!("names-help-comment", comment = n.comment.as_str()).text));
        }
        let operand = entry.device.operands().help(&n.operand).unwrap_or_default();
        text.push_str(&format!("\n{}", operand.trim_end()));
        let mut o = Outcome::new("help")
            .text(text)
            .with("name", &n.name)
            .with("operand", &n.operand)
            .with("comment", &n.comment);
        o.device = Some(entry.name.clone());
        return Ok(o);
    }
    let text = entry.device.operands().help(body)?;
    let mut o = Outcome::new("help").text(text.trim_end().to_string());
    o.device = Some(entry.name.clone());
    Ok(o)
}

/// `help COMMAND`: its forms, as the command card shows them ([`super::forms`]), one a line,
/// then what it does and its sub-commands. Continuation lines are indented by 4: 75 columns
/// of text keep every line within 79 (a line of 80 leaves some terminals at the edge).
pub fn command_help(c: &CommandSpec) -> String {
    let mut text = super::forms::of(c)
        .iter()
        .map(|f| crate::core::text::wrap(&f.text, 75).join("\n    "))
        .collect::<Vec<_>>()
        .join("\n");
    for line in crate::core::text::wrap(&c.summary(), 76) {
        text.push_str(&format!("\n  {line}"));
    }
    if !c.subcommands.is_empty() {
        for line in crate::core::text::wrap(&crate::msg!("help-sub-commands", list = c.subcommands.join(", ")), 76) {
            text.push_str(&format!("\n  {line}"));
        }
    }
    text
}

/// The forms of a command's sub-commands ([`super::forms::of`]), with the sub-command each
/// belongs to.
pub fn sub_forms(c: &CommandSpec) -> Vec<(&'static str, String)> {
    super::forms::of(c).into_iter().filter_map(|f| Some((f.sub?, f.text))).collect()
}

/// `help COMMAND SUB`: the forms of one sub-command, with the details of those that have
/// a grammar of their own, or an error naming the sub-commands there are.
fn sub_help(c: &CommandSpec, sub: &str, extra: Option<&str>, args: Args) -> Result<Outcome> {
    let sub_l = sub.to_ascii_lowercase();
    if let Some(w) = extra {
        return Err(crate::core::Error::usage(crate::msg!("help-extra-word", word = w))
            .hint(format!("help {} {sub_l}", c.name))
            .column(args.offset));
    }
    let forms: Vec<String> = sub_forms(c).into_iter().filter(|(s, _)| *s == sub_l).map(|(_, f)| f).collect();
    if forms.is_empty() {
        return Err(crate::core::Error::usage(crate::msg!("help-no-sub-command", command = c.name, sub = sub))
            .hint(if c.subcommands.is_empty() {
                format!("help {}", c.name)
            } else {
                crate::msg!("help-sub-commands", list = c.subcommands.join(", ")).text
            })
            .column(args.offset));
    }
    let mut lines: Vec<String> = forms
        .iter()
        .flat_map(|f| {
            let wrapped = crate::core::text::wrap(f, 75);
            wrapped.into_iter().enumerate().map(|(i, l)| if i == 0 { l } else { format!("    {l}") })
        })
        .collect();
    if let Some(detail) = SUB_DETAILS.iter().find(|d| d.0 == c.name && d.1 == sub_l).map(|d| d.2) {
        lines.extend(crate::core::text::wrap(detail, 76).into_iter().map(|l| format!("  {l}")));
    }
    Ok(Outcome::new("help").text(lines.join("\n")).with("command", c.name).with("subcommand", sub_l))
}

/// Sub-commands with a grammar of their own, shown by `help COMMAND SUB` (each from the
/// one place that grammar is defined).
const SUB_DETAILS: &[(&str, &str, &str)] = &[
    ("sim", "fault", crate::k2::sim::fault::USAGE),
    ("sim", "faults", crate::k2::sim::fault::USAGE),
    ("servo", "sim", crate::servo::sim::control::USAGE),
    ("umpk", "sim", crate::umpk::sim::control::WORDS),
];

fn quit(sh: &mut Shell, args: Args) -> Result<Outcome> {
    super::no_arguments("quit", args)?;
    sh.quit = true;
    Ok(Outcome::new("quit").quiet())
}

/// The commands by what they are for, as `help` lists them (every command in one group), each
/// group by its key of `help-group` in the catalogue.
pub const GROUPS: &[(&str, &[&str])] = &[
    ("io", &["get", "set", "read", "watch", "trace", "plot"]),
    ("devices", &["use", "devices", "connect", "close", "ports", "paths", "models"]),
    ("simulator", &["sim"]),
    ("pulse", &["pls", "pstop", "pto", "pwm", "profile"]),
    ("counters", &["hdef", "hsc"]),
    ("interrupts", &["events", "wait"]),
    ("plc", &["rtc", "eeprom", "data", "agent"]),
    ("servo", &["servo", "umpk"]),
    ("scripts", &["lua", "lab"]),
    ("shell", &["help", "quit"]),
];

/// `text` padded with spaces to `width` terminal columns (a Chinese character takes two).
fn pad(text: &str, width: usize) -> String {
    let w = crate::shell::term::width(text);
    format!("{text}{}", " ".repeat(width.saturating_sub(w)))
}

/// `help`: the commands by group, fitting an 80×24 terminal with room for the prompt.
pub fn grouped() -> String {
    let names: Vec<String> = GROUPS.iter().map(|g| crate::msg!("help-group", group = g.0).text).collect();
    let w = names.iter().map(|n| crate::shell::term::width(n)).max().unwrap_or(8) + 2;
    let mut lines = vec![crate::msg!("help-groups-heading").text];
    for ((_, cmds), name) in GROUPS.iter().zip(&names) {
        lines.push(format!("  {}{}", pad(name, w), cmds.join(", ")));
    }
    lines.push(String::new());
    // Whole sentences within 80 columns (the test below holds them to it).
    lines.extend(crate::core::text::wrap(&crate::msg!("help-footer"), 79));
    lines.join("\n")
}

/// The command list as `help all` prints it: one command a line, summaries wrapped to fit 80
/// columns under their own column.
pub fn command_list() -> String {
    const WIDTH: usize = 80;
    let name_w = COMMANDS.iter().map(|c| c.name.len()).max().unwrap_or(4) + 2;
    let mut text = crate::msg!("help-all-heading").text + "\n";
    for c in COMMANDS {
        for (i, line) in crate::core::text::wrap(&c.summary(), WIDTH - 2 - name_w - 1).iter().enumerate() {
            let name = if i == 0 { c.name } else { "" };
            text.push_str(&format!("  {name:<name_w$}{line}\n"));
        }
    }
    text.push_str(&crate::msg!("help-all-footer"));
    text
}

/// The command card of the user guide (`docs/commands.md`, between its card markers): every
/// command of the registry with its forms, one table made from [`COMMANDS`] so the guide and
/// the shell cannot drift apart.
#[cfg(test)]
pub fn card_markdown() -> String {
    let mut t = String::from("| command | forms | what it does |\n|---|---|---|\n");
    for c in COMMANDS {
        let forms: Vec<String> = super::forms::of(c).into_iter().map(|f| f.text).collect();
        let cell = |s: &str| s.replace('|', "\\|");
        let forms: Vec<String> = forms.iter().map(|f| format!("`{}`", cell(f))).collect();
        t.push_str(&format!("| `{}` | {} | {} |\n", c.name, forms.join("<br>"), cell(&c.summary())));
    }
    t
}

#[cfg(test)]
mod screen_tests {
    use super::*;

    /// `help` fits an 80×24 terminal (22 lines leave the command and the next prompt), and
    /// names every command once; `help all` lists every command with its summary.
    #[test]
    fn help_fits_one_screen_and_names_every_command() {
        let text = grouped();
        let lines: Vec<&str> = text.lines().collect();
        assert!(lines.len() <= 22, "{} lines:\n{text}", lines.len());
        for l in &lines {
            assert!(l.chars().count() <= 80, "wider than 80 columns: {l}");
        }
        // The footer is whole sentences: each ends with a full stop, none is cut off.
        let footer = text.split("\n\n").last().unwrap_or("").replace('\n', " ");
        assert!(footer.contains("a sub-command's forms.") && footer.ends_with('.'), "{footer}");
        for c in COMMANDS {
            let n = GROUPS.iter().filter(|g| g.1.contains(&c.name)).count();
            assert_eq!(n, 1, "`{}` is in {n} groups of `help`", c.name);
        }
        for (_, names) in GROUPS {
            for n in *names {
                assert!(super::super::find(n).is_some(), "`{n}` in a group is no command");
            }
        }
        let all = command_list();
        for c in COMMANDS {
            assert!(all.lines().any(|l| l.trim_start().starts_with(c.name)), "`help all` lacks {}", c.name);
        }
        for l in all.lines() {
            assert!(l.chars().count() <= 80, "wider than 80 columns: {l}");
        }
    }
}

#[cfg(test)]
mod card_tests {
    /// The guide's command card is the registry's (`PLCSH_BLESS=1 cargo test card` rewrites it).
    #[test]
    fn the_guides_command_card_is_the_registrys() {
        const START: &str = "<!-- command card: made from the command registry; PLCSH_BLESS=1 cargo test card -->\n";
        const END: &str = "<!-- end of command card -->";
        let path = concat!(env!("CARGO_MANIFEST_DIR"), "/docs/commands.md");
        let doc = std::fs::read_to_string(path).unwrap();
        let (a, b) =
            (doc.find(START).expect("card start marker") + START.len(), doc.find(END).expect("card end marker"));
        let card = super::card_markdown();
        if std::env::var_os("PLCSH_BLESS").is_some() {
            std::fs::write(path, format!("{}{card}{}", &doc[..a], &doc[b..])).unwrap();
            return;
        }
        assert!(doc[a..b] == card, "docs/commands.md's command card is stale: PLCSH_BLESS=1 cargo test card");
        for c in super::COMMANDS {
            let row = card.lines().find(|l| l.starts_with(&format!("| `{}` |", c.name))).expect(c.name);
            for s in c.subcommands {
                assert!(row.contains(s), "{} {s} is missing from the card", c.name);
            }
        }
    }
}
