//! The areas of a data set named by a word instead of operands: `eeprom`, the K2's E2PROM
//! backup area as configured (VB3648–VB3902, or to VB4095 after `eeprom area 4095`; K2 manual
//! §2.2.8, k2.md §7), and `retained`, the battery-retained ranges (§2.2.8 "V, C", at most the
//! model's retention size, §2.1.2). Each word becomes operand ranges in the device's own
//! grammar (`VB3648..VB3902`), which then go the way every operand goes.
//!
//! Where the retained ranges come from: a real K2 keeps them in the hardware configuration
//! KincoBuilder downloads, which no Modbus register shows, so on a real K2 `retained` is
//! refused with the advice to name the ranges; the simulator knows the ranges `sim retain`
//! set. Other families have neither area by these names (the FX manual digest names no
//! latched range): the word is refused there, naming the device.

use crate::core::{Error, ErrorKind, Result};
use crate::k2::operand::Area;
use crate::k2::K2Ops;
use crate::msg;
use crate::session::Session;

/// The E2PROM backup area.
pub const EEPROM: &str = "eeprom";
/// The battery-retained ranges.
pub const RETAINED: &str = "retained";

/// The operand ranges `word` stands for on device `dev`, or `None` when it names no area.
pub fn expand(session: &mut Session, dev: usize, word: &str) -> Option<Result<Vec<String>>> {
    let which = [EEPROM, RETAINED].into_iter().find(|k| k.eq_ignore_ascii_case(word))?;
    let name = session.entries()[dev].name.clone();
    let not_here = |name: &str| Error::unsupported(msg!("data-no-area", device = name, area = which)).device(name);
    let device = session.entry(dev).device.as_mut();
    if which == EEPROM {
        return Some(match crate::k2::ops(device) {
            Some(k) => {
                let (first, last) = k.backup_area();
                Ok(vec![format!("VB{first}..VB{last}")])
            }
            None => Err(not_here(&name)),
        });
    }
    if crate::k2::ops(device).is_none() {
        return Some(Err(not_here(&name)));
    }
    let Some(sim) = crate::k2::simulator(session.entry(dev).device.as_mut()) else {
        return Some(Err(Error::unsupported(msg!("data-retained-unknown", device = name.as_str())).device(name)));
    };
    let ranges: Vec<String> = sim
        .backup
        .retain
        .iter()
        .filter(|r| r.len > 0)
        .map(|r| {
            let last = r.first + r.len - 1;
            match r.area {
                Area::C => format!("C{}..C{last}", r.first),
                a => format!("{}B{}..{}B{last}", a.name(), r.first, a.name()),
            }
        })
        .collect();
    if ranges.is_empty() {
        return Some(
            Err(Error::new(ErrorKind::State, msg!("data-retained-none", device = name.as_str())).device(name)),
        );
    }
    Some(Ok(ranges))
}
