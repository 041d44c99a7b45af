//! `sim wire FROM -> TO [lines=N] [delay=D]`, `sim wires`, `sim unwire TERMINAL|all`:
//! virtual wiring between simulated devices (`crate::wiring`).

use crate::core::{Error, Result};
use crate::output::Outcome;
use crate::shell::{Args, Shell};

pub const USAGE: &str = "sim wire FROM -> TO [lines=N] [delay=D] | sim wires | sim unwire TERMINAL|all — e.g. sim wire plc:Q0.0 -> servo:pulse; sim wire servo:encoder -> plc:I0.1,I0.0 lines=1250";

pub fn run(sh: &mut Shell, sub: &str, args: Args) -> Result<Outcome> {
    let rest = args.text.trim_start().strip_prefix(sub).unwrap_or("").trim();
    match sub {
        "wire" => {
            if rest.is_empty() {
                return Err(Error::usage(crate::msg!("shell-wire-needs-ends")).hint(USAGE).column(args.offset));
            }
            let msg = crate::wiring::setup::wire(&mut sh.session, rest)?;
            let wires = crate::wiring::setup::list(&mut sh.session);
            Ok(Outcome::new("sim").text(msg).with("wires", &wires))
        }
        "wires" => {
            let wires = crate::wiring::setup::list(&mut sh.session);
            let text = if wires.is_empty() { crate::msg!("shell-nothing-wired").text } else { wires.join("\n") };
            Ok(Outcome::new("sim").text(text).with("wires", &wires))
        }
        _ => {
            if rest.is_empty() {
                return Err(Error::usage(crate::msg!("shell-unwire-needs-terminal")).hint(USAGE).column(args.offset));
            }
            let gone = crate::wiring::setup::unwire(&mut sh.session, rest)?;
            Ok(Outcome::new("sim").text(format!("unwired {}", gone.join("; "))).with("removed", &gone))
        }
    }
}
