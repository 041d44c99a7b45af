//! What a K2 instruction changes, stated before it runs so the session's write rules (a
//! profile's `read_only`/`allow`, `--read-only`) can refuse it whole: the K2 family computes
//! its own change lists from its SM register tables and model catalogue, and the write guard
//! only checks the names (`core::device::Change`), knowing no family.
//!
//! - PLS and PSTOP change the channel's output and its status byte (K2 manual §3.4: SMB66 for
//!   channel 0, SMB76 for channel 1); PSTOP also latches the position control byte's
//!   emergency-stop bit (§3.4.3: SMB201, SMB231, SMB251, SMB221).
//! - HDEF changes the counter's control byte (§3.3.5 step 2: SMB37 for HSC0).
//! - HSC changes the counter's current value and status byte (§3.3.5 step 4: SMD38, SMB36).
//! - SET_RTC changes the real-time clock (§2.2.10; [`CLOCK`], a name, not a register).
//!
//! Reads (READ_RTC, the helper status, the backup-area bounds, the event log) change nothing.

use super::catalog::Model;
use super::sm_map::{HSC_REGS, PTO_REGS};
use crate::core::device::Change;
pub use crate::core::device::CLOCK;

/// The change a K2 instruction makes: `name` is `PLS`, `PSTOP`, `HDEF`, `HSC` or `SET_RTC`;
/// `channel` the pulse channel or counter (ignored for `SET_RTC`).
pub fn instruction(model: &Model, name: &str, channel: u8) -> Change {
    let pto = PTO_REGS.iter().find(|r| r.channel == channel);
    let out = model.pto(channel).map(|p| p.output.to_string());
    let hsc = HSC_REGS.iter().find(|r| r.channel == channel);
    let mut touches = Vec::new();
    match name {
        "PLS" | "PSTOP" => {
            touches.extend(out);
            if let Some(r) = pto {
                touches.push(format!("SMB{}", r.status));
                if name == "PSTOP" {
                    touches.push(format!("SMB{}", r.pos_control));
                }
            }
        }
        "HDEF" => touches.extend(hsc.map(|r| format!("SMB{}", r.control))),
        "HSC" => {
            if let Some(r) = hsc {
                touches.push(format!("SMD{}", r.cv));
                touches.push(format!("SMB{}", r.status));
            }
        }
        _ => touches.push(CLOCK.to_string()),
    }
    let what = if name == "SET_RTC" { name.to_string() } else { format!("{name} {channel}") };
    Change::Action { what, touches }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::k2::catalog;

    fn touches(c: Change) -> Vec<String> {
        match c {
            Change::Action { touches, .. } => touches,
            Change::Write(_) => Vec::new(),
        }
    }

    #[test]
    fn instructions_change_their_channels_registers_and_outputs() {
        let m = catalog::find("K205-16DT").unwrap();
        assert_eq!(touches(instruction(m, "PLS", 0)), ["Q0.0", "SMB66"]);
        assert_eq!(touches(instruction(m, "PSTOP", 1)), ["Q0.1", "SMB76", "SMB231"]);
        assert_eq!(touches(instruction(m, "HDEF", 0)), ["SMB37"]);
        assert_eq!(touches(instruction(m, "HSC", 0)), ["SMD38", "SMB36"]);
        assert_eq!(touches(instruction(m, "SET_RTC", 0)), [CLOCK]);
    }
}
