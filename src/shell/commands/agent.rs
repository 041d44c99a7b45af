//! `agent status`: is the PLC-side helper program there, current and running?

use super::k2cmd;
use super::CommandSpec;
use crate::core::Result;
use crate::output::Outcome;
use crate::shell::{Args, Shell};

pub const AGENT: CommandSpec = CommandSpec {
    name: "agent",
    aliases: &[],
    usage: "agent status [DEVICE]",
    summary: "check the PLC-side helper that reaches SM registers and instructions over Modbus (docs/agent.md)",
    subcommands: &["status"],
    run: agent,
};

fn agent(sh: &mut Shell, args: Args) -> Result<Outcome> {
    let mut words = args.text.split_whitespace();
    let sub = words.next().unwrap_or("status");
    if sub == "il" {
        return Err(crate::core::Error::usage(
            "`agent il` is a command-line command: it prints the helper program for KincoBuilder",
        )
        .hint("plcsh agent il > k2_agent.il (see plcsh agent il --help)")
        .column(args.offset));
    }
    if sub != "status" {
        return Err(crate::core::Error::usage(format!("unknown `agent {sub}`")).hint(AGENT.usage).column(args.offset));
    }
    let dev = match words.next() {
        Some(d) => sh.session.index(d)?,
        None => sh.session.current_index()?,
    };
    let name = k2cmd::name(sh, dev);
    let k2 = k2cmd::k2(sh, dev)?;
    let text = if k2.as_sim().is_some() {
        "simulator: SM registers and instructions are reached directly (no helper needed)".to_string()
    } else {
        k2.helper_status().map_err(|e| e.device(&name))?
    };
    let mut o = Outcome::new("agent").text(text);
    o.device = Some(name);
    Ok(o)
}
