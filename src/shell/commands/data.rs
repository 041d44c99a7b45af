//! `data save FILE OPERAND…`, `data diff FILE [FILE2]`, `data load FILE`: data sets of the
//! current device (or `data DEVICE …`), the typed values of its operands in a TOML file
//! ([`crate::dataset`]; docs/data-sets.md). Operands are `get`'s (ranges, views, names);
//! `eeprom` and `retained` name the K2's areas that survive a power cut.

use super::CommandSpec;
use crate::core::{Error, Result};
use crate::dataset::{self, device, DataSet};
use crate::msg;
use crate::output::Outcome;
use crate::shell::{lex, Args, Shell};

pub const DATA: CommandSpec = CommandSpec {
    name: "data",
    aliases: &[],
    usage: "data save FILE OPERAND… | data diff FILE [FILE2] | data load FILE   e.g. data save recipe.toml VB0..VB99 VD200/REAL eeprom",
    summary: || crate::msg!("summary-data"),
    subcommands: &["save", "diff", "load"],
    run: data,
};

fn data(sh: &mut Shell, args: Args) -> Result<Outcome> {
    let usage = || Error::usage(msg!("data-usage")).column(args.offset);
    let words = lex::words_in(&args)?;
    let Some((&(_, verb), rest)) = words.split_first() else { return Err(usage()) };
    let dev = sh.session.current_index()?;
    let name = sh.session.entries()[dev].name.clone();
    let simulated = sh.session.simulated(dev);
    let read_file = |sh: &Shell, (c, f): (usize, &str)| -> Result<(String, DataSet)> {
        let f = lex::unquote(f).into_owned();
        sh.session.check_read(&f).map_err(|e| e.column(c))?;
        let text = std::fs::read_to_string(&f)
            .map_err(|e| Error::io(msg!("data-cannot-read", file = f.as_str())).cause(e).column(c))?;
        let set = DataSet::parse(&text, &f).map_err(|e| e.column(c))?;
        Ok((f, set))
    };
    let mut o = match (verb, rest) {
        ("save", [(c, file), operands @ ..]) if !operands.is_empty() => {
            let file = lex::unquote(file).into_owned();
            crate::shell::files::check_write(&sh.write_rule, &file).map_err(|e| e.column(*c))?;
            let mut ops = Vec::new();
            for &(oc, w) in operands {
                ops.extend(device::operands(&mut sh.session, dev, w).map_err(|e| match e.column {
                    Some(col) => e.column(oc + col),
                    None => e.column(oc),
                })?);
            }
            let asked = operands.iter().map(|w| w.1.to_string()).collect();
            let set = device::read(&mut sh.session, dev, asked, &ops)?;
            crate::core::durable::write_atomic(std::path::Path::new(&file), set.to_toml().as_bytes())?;
            Outcome::new("data")
                .text(msg!(
                    "data-saved",
                    count = set.set.values.len() as u64,
                    device = name.as_str(),
                    file = file.as_str()
                ))
                .with("file", &file)
                .with("identity", &set.device)
                .with("values", &set.set.values)
        }
        ("diff", [a]) | ("diff", [a, _]) => {
            let (left_name, left) = read_file(sh, *a)?;
            let (right_name, right) = match rest {
                [_, b] => {
                    let (n, s) = read_file(sh, *b)?;
                    if s.device.family != left.device.family {
                        return Err(Error::usage(msg!(
                            "data-families-differ",
                            left = left_name.as_str(),
                            lfamily = left.device.family.as_str(),
                            right = n.as_str(),
                            rfamily = s.device.family.as_str()
                        ))
                        .column(b.0));
                    }
                    (n, s)
                }
                _ => {
                    let info = sh.session.entries()[dev].device.info().clone();
                    left.check_device(&left_name, &name, info.family, &info.model).map_err(|e| e.column(a.0))?;
                    (name.clone(), device::current(&mut sh.session, dev, &left, &left_name)?)
                }
            };
            let d = dataset::diff(&left, &right);
            let rows: Vec<Vec<String>> = d
                .iter()
                .map(|x| {
                    // A tag's name and its operand, as every reading shows them (docs/tags.md).
                    let operand = match &x.name {
                        Some(n) => format!("{n} ({})", x.operand),
                        None => x.operand.clone(),
                    };
                    vec![
                        operand,
                        x.dtype.clone(),
                        dataset::Difference::shown(x.left),
                        dataset::Difference::shown(x.right),
                    ]
                })
                .collect();
            let o = Outcome::new("data");
            let o = if rows.is_empty() {
                o.text(msg!("data-same"))
            } else {
                o.table(&["operand", "type", left_name.as_str(), right_name.as_str()], rows)
            };
            o.with("left", &left_name).with("right", &right_name).with("count", d.len()).with("differences", &d)
        }
        ("load", [f]) => {
            let (file, set) = read_file(sh, *f)?;
            let done = device::load(&mut sh.session, dev, &set, &file).map_err(|e| match e.column {
                None if e.code == "data-other-device" => e.column(f.0),
                _ => e,
            })?;
            let mut text: String =
                msg!("data-loaded", written = done.written.len() as u64, unchanged = done.unchanged as u64).into();
            for w in &done.written {
                text.push_str(&format!("\n  {} {} → {}", w.operand, w.old.text(), w.new.text()));
            }
            Outcome::new("data")
                .text(text)
                .with("file", &file)
                .with("written", &done.written)
                .with("unchanged", done.unchanged)
                .acted_on(&name, simulated)
        }
        _ => return Err(usage()),
    };
    o.device = Some(name);
    Ok(o)
}
