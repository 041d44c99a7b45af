//! `agent [DEVICE] status`: is the PLC-side helper program there, current and running? The
//! device goes right after the command word, as in `servo [DEVICE] status`; `agent status
//! DEVICE` reads the same.

use super::k2cmd;
use super::CommandSpec;
use crate::core::Result;
use crate::k2::K2Ops;
use crate::output::Outcome;
use crate::shell::{Args, Shell};

pub const AGENT: CommandSpec = CommandSpec {
    name: "agent",
    aliases: &[],
    usage: "agent [DEVICE] [status] | agent status DEVICE",
    summary: || crate::msg!("summary-agent"),
    subcommands: &["status"],
    run: agent,
};

fn agent(sh: &mut Shell, args: Args) -> Result<Outcome> {
    let words: Vec<&str> = args.text.split_whitespace().collect();
    if words.first() == Some(&"il") {
        return Err(crate::core::Error::usage(crate::msg!("shell-agent-il-cli"))
            .hint(crate::msg!("shell-hint-agent-il-cli"))
            .column(args.offset));
    }
    // `agent`, `agent status`, `agent DEVICE`, `agent DEVICE status`, `agent status DEVICE`.
    let (device, rest): (Option<&str>, Vec<&str>) = match words.as_slice() {
        [] | ["status"] => (None, vec![]),
        ["status", d, more @ ..] => (Some(d), more.to_vec()),
        [d, "status", more @ ..] => (Some(d), more.to_vec()),
        [d] if sh.session.index(d).is_ok() => (Some(d), vec![]),
        [w, ..] => {
            return Err(crate::core::Error::usage(format!("unknown `agent {w}`")).hint(AGENT.usage).column(args.offset))
        }
    };
    if let Some(extra) = rest.first() {
        return Err(crate::core::Error::usage(format!("unexpected `{extra}`")).hint(AGENT.usage).column(args.offset));
    }
    let dev = match device {
        Some(d) => sh.session.index(d)?,
        None => sh.session.current_index()?,
    };
    sh.session.ready(dev)?;
    let name = k2cmd::name(sh, dev);
    let mut k2 = k2cmd::k2(sh, dev)?;
    let text = if k2.as_sim().is_some() {
        crate::msg!("shell-agent-simulator").text
    } else {
        k2.helper_status().map_err(|e| e.device(&name))?
    };
    let mut o = Outcome::new("agent").text(text);
    o.device = Some(name);
    Ok(o)
}
