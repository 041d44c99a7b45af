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

/// Parses `VB3400` (or `3400`).
pub fn parse_base(text: &str) -> Result<u32, String> {
    let t = text.trim().to_ascii_uppercase();
    let n: u32 = t
        .trim_start_matches('%')
        .trim_start_matches("VB")
        .parse()
        .map_err(|_| format!("`{text}` is not a V byte address (e.g. VB{})", protocol::DEFAULT_BASE))?;
    if !n.is_multiple_of(2) || n + il::TOTAL_SIZE > crate::k2::catalog::EEPROM_FIRST {
        return Err(format!(
            "the mailbox needs an even address with {} bytes free below the E2PROM area VB{} (got VB{n})",
            il::TOTAL_SIZE,
            crate::k2::catalog::EEPROM_FIRST
        ));
    }
    Ok(n)
}

pub fn run(args: &AgentArgs, out: &mut dyn Write) -> i32 {
    match &args.cmd {
        AgentCmd::Il { base } => match parse_base(base) {
            Ok(b) => i32::from(out.write_all(il::program(b).as_bytes()).is_err()),
            Err(m) => {
                eprintln!("error: {m}");
                2
            }
        },
    }
}
