//! `rtc` (READ_RTC), `rtc set 2026-11-22T10:00:00` (SET_RTC), `rtc sync` (set it to the
//! host's local time). Manual §2.2.9.

use super::k2cmd;
use super::CommandSpec;
use crate::core::{Error, Result};
use crate::k2::instr::{host_local_now, RtcTime};
use crate::k2::K2Ops;
use crate::output::Outcome;
use crate::shell::{Args, Shell};

pub const RTC: CommandSpec = CommandSpec {
    name: "rtc",
    aliases: &[],
    usage: "rtc | rtc set 2026-11-22T10:00:00 | rtc sync",
    summary: || crate::msg!("summary-rtc"),
    subcommands: &["set", "sync"],
    run: rtc,
};

const DAYS: [&str; 7] = ["Sunday", "Monday", "Tuesday", "Wednesday", "Thursday", "Friday", "Saturday"];

fn rtc(sh: &mut Shell, args: Args) -> Result<Outcome> {
    let text = args.text.trim();
    let (sub, rest) = text.split_once(char::is_whitespace).unwrap_or((text, ""));
    let dev = sh.session.current_index()?;
    let name = k2cmd::name(sh, dev);
    let mut k2 = k2cmd::k2(sh, dev)?;
    let set = match sub.to_ascii_lowercase().as_str() {
        "" => None,
        "set" => Some(
            RtcTime::parse(rest)
                .map_err(|m| Error::new(crate::core::ErrorKind::Value, m).column(args.offset + sub.len() + 1))?,
        ),
        "sync" => Some(host_local_now()),
        other => return Err(Error::usage(format!("unknown `rtc {other}`")).column(args.offset).hint(RTC.usage)),
    };
    let changed = set.is_some();
    if let Some(t) = set {
        k2.set_rtc(t).map_err(|e| e.device(&name))?;
    }
    let t = k2.read_rtc().map_err(|e| e.device(&name))?;
    let day = DAYS[(t.weekday() - 1) as usize];
    let mut o = Outcome::new("rtc")
        .text(format!("{t} ({day})"))
        .with("rtc", t.to_string())
        .with("weekday", t.weekday())
        .with("bcd", t.to_bcd8());
    if changed {
        let sim = sh.session.simulated(dev);
        o = o.acted_on(&name, sim);
    }
    o.device = Some(name);
    Ok(o)
}
