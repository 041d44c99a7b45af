//! `plcsh agent il [--model MODEL] [--base VB3400]`: prints the PLC-side helper program for
//! a model (its channels, counters and modes only) and a mailbox base.

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
        /// The PLC's model: the helper runs only the pulse outputs, counters and counter
        /// modes this model has (default: the default simulated model).
        #[arg(long, default_value = crate::k2::catalog::DEFAULT_MODEL)]
        model: String,
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
        AgentCmd::Il { model, base } => {
            let model = match crate::k2::catalog::lookup(model) {
                Ok(m) => m,
                Err(e) => {
                    eprintln!("error: {e}");
                    return 2;
                }
            };
            match protocol::parse_base(base) {
                Ok(b) => match il::refuse(model, b) {
                    Some(m) => {
                        eprintln!("error: {m}");
                        2
                    }
                    None => i32::from(out.write_all(il::program(model, b).as_bytes()).is_err()),
                },
                Err(m) => {
                    eprintln!("error: {m}");
                    2
                }
            }
        }
        AgentCmd::Check(_) => unreachable!("`agent check` is run by cli::probe with the session's profiles"),
    }
}
