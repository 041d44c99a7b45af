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
    }
}
