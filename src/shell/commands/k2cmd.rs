//! Plumbing shared by the K2 special-function commands (`pls`, `pto`, `hsc`, `events`,
//! `rtc`, `eeprom`, `sim input`): finding the device and channel a command names, reaching
//! its [`crate::k2::K2Ops`] (a [`K2Access`]), and turning helper results into an [`Outcome`].

use crate::core::{Error, ErrorKind, Result};
use crate::k2::helpers::{Done, Written};
use crate::k2::sim::K2Sim;
use crate::k2::K2Access;
use crate::output::Outcome;
use crate::session::Reading;
use crate::shell::lex::{Opt, Word};
use crate::shell::Shell;

/// `0` or `press:0` → (device index, channel number). `what` is `pulse` (a pulse output's
/// channel) or `counter`.
pub fn channel(sh: &Shell, word: Word, what: &str, max: u8) -> Result<(usize, u8)> {
    let (col, text) = word;
    let (dev, num, off) = match text.rsplit_once(':') {
        Some((d, n)) => (sh.session.index(d).map_err(|e| e.column(col))?, n, d.len() + 1),
        None => (sh.session.current_index()?, text, 0),
    };
    let n: u8 = num.parse().ok().filter(|n| *n <= max).ok_or_else(|| {
        Error::usage(crate::msg!("shell-not-a-channel", num = num, what = what, max = max)).column(col + off)
    })?;
    Ok((dev, n))
}

/// The channel of a status form: `CMD N status` (the channel first, as in every `CMD N …`
/// form) or `CMD status N`; `None` when the words are not a status form. `example` is the
/// form to show (`pto 0 status`); `what` as for [`channel`].
pub fn status_channel<'a>(pos: &[Word<'a>], col: usize, what: &str, example: &str) -> Option<Result<Word<'a>>> {
    let at = pos.iter().take(2).position(|p| p.1.eq_ignore_ascii_case("status"))?;
    let Some(word) = pos.get(1 - at) else {
        return Some(Err(
            Error::usage(crate::msg!("shell-status-needs-channel", what = what, example = example)).column(col)
        ));
    };
    if let Some(extra) = pos.get(2) {
        return Some(Err(Error::usage(crate::msg!("shell-unexpected", extra = extra.1))
            .column(extra.0)
            .hint(example.to_string())));
    }
    Some(Ok(*word))
}

/// The device's name.
pub fn name(sh: &Shell, dev: usize) -> String {
    sh.session.entries()[dev].name.clone()
}

/// The K2 instructions of device `dev`, each checked against the device's write rules.
pub fn k2(sh: &mut Shell, dev: usize) -> Result<K2Access<'_>> {
    let name = name(sh, dev);
    crate::k2::ops(sh.session.entry(dev).device.as_mut())
        .ok_or_else(|| Error::unsupported(crate::msg!("shell-not-a-k2", name = name.as_str())).device(name))
}

/// The simulator behind device `dev`, or an error saying the control is simulator-only.
pub fn sim<'a>(sh: &'a mut Shell, dev: usize, what: &str) -> Result<&'a mut K2Sim> {
    let name = name(sh, dev);
    k2(sh, dev)?;
    crate::k2::simulator(sh.session.entry(dev).device.as_mut()).ok_or_else(|| {
        Error::unsupported(crate::msg!("shell-simulator-only", command = what, name = name.as_str())).device(name)
    })
}

/// Helper writes as the output's readings.
pub fn readings(w: &[Written]) -> Vec<Reading> {
    w.iter().map(|w| Reading::plain(w.operand.clone(), w.value, w.dtype)).collect()
}

/// The outcome of an executed helper: the raw writes first, then what the device did.
pub fn done_outcome(cmd: &str, device: String, d: Done) -> Outcome {
    let mut lines = Vec::new();
    if !d.writes.is_empty() {
        let w: Vec<String> = d
            .writes
            .iter()
            .map(|w| match (w.dtype, w.value) {
                (crate::core::DataType::Byte, v) if v.as_i64() > 9 => {
                    format!("{}={}", w.operand, crate::output::hex(v.as_i64() as u64, 8))
                }
                (_, v) => format!("{}={v}", w.operand),
            })
            .collect();
        lines.push(format!("set {}", w.join(", ")));
    }
    for r in &d.reports {
        lines.push(r.clone());
    }
    // Notes go to stderr with the other notes (`output`), and to `notes` in JSON.
    let mut o = Outcome::new(cmd).text(lines.join("\n")).with("reports", &d.reports);
    o.notes = d.notes.clone();
    o.device = Some(device);
    o.writes = readings(&d.writes);
    o
}

/// Looks up an option, with the error for an unknown one.
pub fn check_options(opts: &[Opt], known: &[&str], usage: &str) -> Result<()> {
    for &(col, k, _) in opts {
        if !known.contains(&k) {
            let near = known.iter().map(|c| (crate::core::text::edit_distance(k, c), *c)).min();
            let options = known.join(", ");
            let hint = match near {
                Some((d, c)) if d <= 2 => {
                    crate::msg!("shell-hint-option-near", near = c, options = options, usage = usage)
                }
                _ => crate::msg!("shell-hint-option-usage", options = options, usage = usage),
            };
            return Err(Error::usage(crate::msg!("shell-unknown-key", key = k)).column(col).hint(hint));
        }
    }
    Ok(())
}

pub fn opt<'a>(opts: &[Opt<'a>], key: &str) -> Option<(usize, &'a str)> {
    opts.iter().find(|o| o.1 == key).map(|o| (o.0, o.2))
}

/// A value error at a column.
pub fn value_err(col: usize, msg: impl Into<crate::core::error::Text>) -> Error {
    Error::new(ErrorKind::Value, msg).column(col)
}
