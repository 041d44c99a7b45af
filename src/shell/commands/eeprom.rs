//! `eeprom dump FILE [all]`, `eeprom restore FILE`, `eeprom status`, `eeprom area LAST`:
//! the E2PROM backup area VB3648… (manual §2.2.8). Dump and restore go through plain V
//! reads and writes, so they work on any K2 connection; `status` and `area` configure and
//! inspect the simulator's E2PROM.

use super::k2cmd;
use super::CommandSpec;
use crate::core::{Error, Result, Value};
use crate::k2::catalog::{EEPROM_ENDURANCE, EEPROM_FIRST, EEPROM_LAST_MAX};
use crate::k2::operand::{Area, K2Operand};
use crate::k2::K2Ops;
use crate::output::Outcome;
use crate::shell::{Args, Shell};

pub const EEPROM: CommandSpec = CommandSpec {
    name: "eeprom",
    aliases: &[],
    usage: "eeprom dump FILE [all] | eeprom restore FILE | eeprom status | eeprom area 3902|4095",
    summary: || crate::msg!("summary-eeprom"),
    subcommands: &["dump", "restore", "status", "area"],
    run: eeprom,
};

fn eeprom(sh: &mut Shell, args: Args) -> Result<Outcome> {
    // The words as text: `eeprom dump "Резерв 1/VB.bin"` (docs/commands.md, "Quoting").
    let words = crate::shell::lex::unquoted_words(args.text).map_err(|e| e.shift(args.offset))?;
    let parts: Vec<&str> = words.iter().map(|w| w.as_ref()).collect();
    let dev = sh.session.current_index()?;
    let name = k2cmd::name(sh, dev);
    let (first, last) = k2cmd::k2(sh, dev)?.backup_area();
    let ops = |last: u32| -> Vec<K2Operand> { (first..=last).map(|b| K2Operand::byte(Area::V, b)).collect() };
    let mut o = match parts.as_slice() {
        ["dump", file, rest @ ..] => {
            let end = match rest {
                [] => last,
                ["all"] => EEPROM_LAST_MAX,
                _ => {
                    return Err(Error::usage("eeprom dump FILE [all]")
                        .hint(crate::msg!(
                            "shell-hint-quote-path",
                            line = format!("eeprom dump {}", crate::shell::lex::quote(&parts[1..].join(" ")))
                        ))
                        .column(args.offset))
                }
            };
            crate::shell::files::check_write(&sh.write_rule, file)?;
            let core: Vec<_> = ops(end).iter().map(|o| o.to_core()).collect();
            let vals = sh.session.read_values(dev, &core)?;
            let bytes: Vec<u8> = vals.iter().map(|v| v.as_i64() as u8).collect();
            crate::core::durable::write_atomic(std::path::Path::new(file), &bytes)?;
            Outcome::new("eeprom")
                .text(
                    crate::msg!("shell-eeprom-saved", first = first, last = end, bytes = bytes.len(), file = *file)
                        .text,
                )
                .with("bytes", bytes.len())
                .with("file", file)
        }
        ["restore", file] => {
            sh.session.check_read(file)?;
            let bytes =
                std::fs::read(file).map_err(|e| Error::io(crate::msg!("shell-cannot-read", file = *file)).cause(e))?;
            let room = (last - first + 1) as usize;
            if bytes.len() > room {
                return Err(Error::usage(crate::msg!(
                    "shell-eeprom-too-big",
                    file = *file,
                    bytes = bytes.len(),
                    first = first,
                    last = last,
                    room = room
                ))
                .hint(crate::msg!("shell-hint-eeprom-area")));
            }
            let items: Vec<_> = ops(first + bytes.len() as u32 - 1)
                .iter()
                .zip(&bytes)
                .map(|(o, b)| (o.to_core(), Value::Int(*b as i64)))
                .collect();
            sh.session.write_values(dev, &items)?;
            Outcome::new("eeprom")
                .text(
                    crate::msg!(
                        "shell-eeprom-restored",
                        bytes = bytes.len(),
                        first = first,
                        last = first + bytes.len() as u32 - 1,
                        file = *file
                    )
                    .text,
                )
                .with("bytes", bytes.len())
        }
        ["status"] => {
            let s = k2cmd::sim(sh, dev, "eeprom status")?;
            s.advance();
            let mut lines =
                vec![crate::msg!("shell-eeprom-area-size", first = first, last = last, bytes = last - first + 1).text];
            let mut warn = None;
            let elapsed = s.last.saturating_sub(s.backup.since).as_secs_f64();
            let mut data = serde_json::Map::new();
            if let Some((byte, total, session)) = s.backup.hottest() {
                lines.push(
                    crate::msg!(
                        "shell-eeprom-hottest",
                        byte = byte,
                        writes = total,
                        share = format!("{:.3}", total as f64 * 100.0 / EEPROM_ENDURANCE as f64),
                        endurance = EEPROM_ENDURANCE
                    )
                    .text,
                );
                data.insert("hottest".into(), serde_json::json!({"byte": byte, "writes": total, "session": session}));
                if session > 0 && elapsed > 0.0 {
                    let rate = session as f64 / elapsed;
                    let left = EEPROM_ENDURANCE.saturating_sub(total) as f64 / rate;
                    lines.push(crate::msg!("shell-eeprom-wear", rate = format!("{rate:.1}"), left = human(left)).text);
                    if left < 10.0 * 365.0 * 86_400.0 {
                        warn = Some(crate::msg!("shell-eeprom-wear-warning"));
                    }
                    data.insert("wear_out_s".into(), serde_json::json!(left));
                }
            } else {
                lines.push(crate::msg!("shell-eeprom-no-writes").text);
            }
            let mut o = Outcome::new("eeprom").text(lines.join("\n")).with("first", first).with("last", last);
            if let Some(w) = warn {
                o = o.note(crate::msg!("label-warning", warning = w.text).text);
            }
            o.data.extend(data);
            o
        }
        ["area", n] => {
            let n = n.trim_start_matches(['V', 'B', 'v', 'b']);
            sh.session.entry(dev).device.set_option("backup_last", n).map_err(|e| e.device(&name))?;
            let (_, last) = k2cmd::k2(sh, dev)?.backup_area();
            Outcome::new("eeprom")
                .text(crate::msg!("shell-eeprom-area", first = EEPROM_FIRST, last = last).text)
                .with("last", last)
        }
        ["restore", more @ ..] if more.len() > 1 => {
            return Err(Error::usage(crate::msg!(
                "shell-one-file-only-plain",
                form = "eeprom restore",
                count = more.len()
            ))
            .hint(crate::msg!(
                "shell-hint-quote-path",
                line = format!("eeprom restore {}", crate::shell::lex::quote(&more.join(" ")))
            ))
            .column(args.offset))
        }
        _ => return Err(Error::usage(crate::msg!("shell-eeprom-unknown")).column(args.offset).hint(EEPROM.usage)),
    };
    o.device = Some(name);
    Ok(o)
}

fn human(secs: f64) -> String {
    if secs < 3600.0 {
        format!("{:.0} s", secs)
    } else if secs < 86_400.0 * 2.0 {
        format!("{:.1} h", secs / 3600.0)
    } else if secs < 86_400.0 * 730.0 {
        format!("{:.0} days", secs / 86_400.0)
    } else {
        format!("{:.0} years", secs / (365.0 * 86_400.0))
    }
}
