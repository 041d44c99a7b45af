//! `plcsh agent il [--base VB3400]`: prints the PLC-side helper program for a mailbox base.

use crate::k2::agent::{il, protocol};
use std::io::Write;

#[derive(clap::Args, Debug)]
pub struct AgentArgs {
    #[command(subcommand)]
    pub cmd: AgentCmd,
}

#[derive(clap::Subcommand, Debug)]
pub enum AgentCmd {
    /// Print the helper program (K2 instruction list) for KincoBuilder.
    Il {
        /// Mailbox base: an even V byte address below the E2PROM area (VB3648).
        #[arg(long, default_value = "VB3400")]
        base: String,
    },
    /// Self-test of the helper in a PLC: signature, version, scan rate, system bits, clock and
    /// a refused PLS; writes only the mailbox and puts back the SM bytes it used (docs/agent.md).
    Check(super::probe::CheckArgs),
}

pub fn run(args: &AgentArgs, out: &mut dyn Write) -> i32 {
    match &args.cmd {
        AgentCmd::Il { base } => match protocol::parse_base(base) {
            Ok(b) => i32::from(out.write_all(il::program(b).as_bytes()).is_err()),
            Err(m) => {
                eprintln!("error: {m}");
                2
            }
        },
        AgentCmd::Check(_) => unreachable!("`agent check` is run by cli::probe with the session's profiles"),
    }
}
