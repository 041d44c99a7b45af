//! `get`, `set` and `read`: operand access through the session.

use super::CommandSpec;
use crate::core::{DataType, Error, Result, Value};
use crate::output::{binary, hex, Outcome};
use crate::session::SetItem;
use crate::shell::{lex, Args, Shell};

pub const GET: CommandSpec = CommandSpec {
    name: "get",
    aliases: &["g"],
    usage: "get OPERAND…   e.g. get VW100 SMD72 plc:M0.0 VW0..VW8",
    summary: || crate::msg!("summary-get"),
    subcommands: &[],
    run: get,
};

pub const SET: CommandSpec = CommandSpec {
    name: "set",
    aliases: &["s"],
    usage: "set OPERAND=VALUE[, OPERAND=VALUE…]   e.g. set SMB67=16#85, SMW68=500, SMD72=1000",
    summary: || crate::msg!("summary-set"),
    subcommands: &[],
    run: set,
};

pub const READ: CommandSpec = CommandSpec {
    name: "read",
    aliases: &["r"],
    usage: "read RANGE…   e.g. read VW0..VW20, read VB0[16]",
    summary: || crate::msg!("summary-read"),
    subcommands: &[],
    run: read,
};

fn operand_words<'a>(args: &Args<'a>, what: &str) -> Result<Vec<(usize, &'a str)>> {
    let w = lex::words(args.text).map_err(|e| e.shift(args.offset))?;
    if w.is_empty() {
        return Err(Error::usage(crate::msg!("shell-needs-operand", command = what)).column(args.offset));
    }
    Ok(w)
}

fn read_values(sh: &mut Shell, args: &Args) -> Result<(Option<String>, Vec<crate::session::Reading>)> {
    let words = operand_words(args, "get")?;
    let mut targets = Vec::new();
    for &(col, w) in &words {
        targets.push(sh.session.resolve(w).map_err(|e| e.shift(args.offset + col))?);
    }
    let texts: Vec<&str> = words.iter().map(|w| w.1).collect();
    let readings = sh.session.get(&texts)?;
    let first = targets.first().map(|t| t.device);
    let many = targets.iter().any(|t| Some(t.device) != first);
    let name = |i: usize| sh.session.entries()[i].name.clone();
    let device = first.map(name);
    let values = readings
        .into_iter()
        .map(|(dev, mut r)| {
            if many {
                r.device = Some(sh.session.entries()[dev].name.clone());
            }
            r
        })
        .collect();
    Ok((device, values))
}

/// Requests sent on the wire so far, over every open device.
fn requests_total(sh: &Shell) -> u64 {
    sh.session.entries().iter().map(|e| e.device.requests()).sum()
}

/// With `--verbose`: how many requests the command sent (stderr, and `requests` in JSON).
fn count_requests(sh: &Shell, before: u64, o: Outcome) -> Outcome {
    if !sh.verbose {
        return o;
    }
    let n = requests_total(sh).saturating_sub(before);
    if !sh.style.json {
        eprintln!("{}", crate::msg!("shell-requests-on-wire", command = o.cmd.as_str(), count = n));
    }
    o.with("requests", n)
}

fn get(sh: &mut Shell, args: Args) -> Result<Outcome> {
    let before = requests_total(sh);
    let (device, values) = read_values(sh, &args)?;
    let mut o = Outcome::new("get");
    o.device = device;
    o.values = values;
    Ok(count_requests(sh, before, o))
}

fn set(sh: &mut Shell, args: Args) -> Result<Outcome> {
    if args.text.is_empty() {
        return Err(Error::usage(crate::msg!("shell-set-needs-items")).hint(SET.usage).column(args.offset));
    }
    let mut items = Vec::new();
    for (col, piece) in lex::split_top(args.text, ',').map_err(|e| e.shift(args.offset))? {
        let lead = piece.len() - piece.trim_start().len();
        let p = piece.trim();
        let column = args.offset + col + lead;
        let Some(eq) = p.find('=') else {
            return Err(Error::syntax(crate::msg!("shell-set-not-item", item = p)).column(column).hint(SET.usage));
        };
        if p[..eq].ends_with(':') {
            return Err(Error::syntax(crate::msg!(
                "shell-set-st-assignment",
                operand = p[..eq - 1].trim(),
                value = p[eq + 1..].trim()
            ))
            .column(column + eq - 1)
            .hint(SET.usage));
        }
        let vtext = &p[eq + 1..];
        let vlead = vtext.len() - vtext.trim_start().len();
        let v = vtext.trim();
        // `set VW0=5 VW2=6`: a second write after a space, not a value with a space in it.
        if let Some(sp) = v.find(char::is_whitespace) {
            let after = v[sp..].trim_start();
            if after.split_whitespace().next().is_some_and(|w| w.contains('=') && !w.starts_with('=')) {
                let at = column + eq + 1 + vlead + (v.len() - after.len());
                return Err(Error::syntax(crate::msg!("shell-set-commas", line = comma_line(args.text)))
                    .column(at)
                    .hint(SET.usage));
            }
        }
        items.push(SetItem {
            operand: p[..eq].to_string(),
            value: vtext.trim().to_string(),
            column,
            value_column: column + eq + 1 + vlead,
        });
    }
    let before = requests_total(sh);
    let writes = sh.session.set(&items)?;
    let mut o = Outcome::new("set");
    o.device = writes.first().map(|(d, _)| sh.session.entries()[*d].name.clone());
    o.writes = writes.into_iter().map(|(_, r)| r).collect();
    Ok(count_requests(sh, before, o.quiet()))
}

/// `VW0=5 VW2=6` as the writes it means, `VW0=5, VW2=6`: every word with a `=` starts a
/// write, other words stay with the value before them (`B # 16 # 85`).
fn comma_line(text: &str) -> String {
    let mut out = String::new();
    for w in text.split([' ', '\t', ',']).filter(|w| !w.is_empty()) {
        if !out.is_empty() {
            out.push_str(if w.contains('=') && !w.starts_with('=') { ", " } else { " " });
        }
        out.push_str(w);
    }
    out
}

fn read(sh: &mut Shell, args: Args) -> Result<Outcome> {
    let before = requests_total(sh);
    let (device, values) = read_values(sh, &args)?;
    let rows = values
        .iter()
        .map(|r| {
            let raw = match r.value {
                Value::Real(f) => (f as f32).to_bits() as u64,
                v => v.as_i64() as u64,
            };
            let bits = if r.dtype == DataType::Bool { 1 } else { r.dtype.bits() };
            let label = match &r.device {
                Some(d) => format!("{d}:{}", r.operand),
                None => r.operand.clone(),
            };
            vec![label, r.value.to_string(), r.dtype.name().to_string(), hex(raw, bits), binary(raw, bits)]
        })
        .collect();
    let mut o = Outcome::new("read").table(&["operand", "value", "type", "hex", "binary"], rows);
    o.device = device;
    o.values = values;
    Ok(count_requests(sh, before, o))
}
