//! High-speed counter commands (manual §3.3): the instructions `hdef N MODE` and `hsc N`,
//! the typed helper `hsc N mode=… pv=[…] …` and `hsc N status`.

use super::k2cmd::{self, check_options, done_outcome, opt, value_err};
use super::CommandSpec;
use crate::core::{Error, Result};
use crate::k2::helpers::{self, hsc as hh};
use crate::k2::K2Ops;
use crate::output::Outcome;
use crate::shell::lex::{self, Word};
use crate::shell::{Args, Shell};

pub const HDEF: CommandSpec = CommandSpec {
    name: "hdef",
    aliases: &[],
    usage: "hdef N MODE   e.g. hdef 0 9",
    summary: || crate::msg!("summary-hdef"),
    subcommands: &[],
    run: hdef,
};

pub const HSC: CommandSpec = CommandSpec {
    name: "hsc",
    aliases: &[],
    usage: "hsc N | hsc N mode=9 [rate=4x] [pv=[100,200,300]] [relative] [cyclic] [at VB3009] [cv=0] [dir=up|down] [reset=low] [start=low] [force] | hsc N status | hsc status N",
    summary: || crate::msg!("summary-hsc"),
    subcommands: &["status"],
    run: hsc,
};

/// `what`: `mode` (a counter mode), `cv` (a current value) or `pv` (a preset value).
fn number<T: std::str::FromStr>(w: Word, what: &str) -> Result<T> {
    w.1.parse().map_err(|_| value_err(w.0, crate::msg!("shell-hsc-not-a-number", text = w.1, what = what)))
}

fn hdef(sh: &mut Shell, args: Args) -> Result<Outcome> {
    let w = lex::words_in(&args)?;
    if w.len() != 2 {
        return Err(Error::usage(crate::msg!("shell-hdef-needs-two")).column(args.offset).hint(HDEF.usage));
    }
    let (dev, n) = k2cmd::channel(sh, w[0], "counter", 3)?;
    let mode: u8 = number(w[1], "mode")?;
    let name = k2cmd::name(sh, dev);
    let r = k2cmd::k2(sh, dev)?.hdef(n, mode).map_err(|e| e.device(&name).column(w[1].0))?;
    let mut o = Outcome::new("hdef").text(r.clone()).with("report", r);
    o.device = Some(name);
    Ok(o)
}

fn hsc(sh: &mut Shell, args: Args) -> Result<Outcome> {
    let w = lex::words_in(&args)?;
    let (pos, opts) = lex::options(&w);
    if let Some(word) = k2cmd::status_channel(&pos, args.offset, "counter", "hsc 0 status") {
        let word = word?;
        let (dev, n) = k2cmd::channel(sh, word, "counter", 3)?;
        let name = k2cmd::name(sh, dev);
        let model = k2cmd::k2(sh, dev)?.model();
        let st = hh::status(sh.session.entry(dev).device.as_mut(), model, n).map_err(|e| e.device(&name))?;
        let mut o = Outcome::new("hsc")
            .text(format!("HSC{n}: {}", st.words.join("; ")))
            .with("status", &st.words)
            .with("cv", st.cv);
        o.device = Some(name);
        o.values = k2cmd::readings(&st.registers);
        return Ok(o);
    }
    let word = *pos
        .first()
        .ok_or_else(|| Error::usage(crate::msg!("shell-hsc-needs-counter")).column(args.offset).hint(HSC.usage))?;
    let (dev, n) = k2cmd::channel(sh, word, "counter", 3)?;
    let name = k2cmd::name(sh, dev);
    if pos.len() == 1 && opts.is_empty() {
        let r = k2cmd::k2(sh, dev)?.hsc(n).map_err(|e| e.device(&name))?;
        let mut o = Outcome::new("hsc").text(r.clone()).with("report", r);
        o.device = Some(name);
        return Ok(o);
    }
    check_options(&opts, &["mode", "rate", "pv", "cv", "dir", "reset", "start"], HSC.usage)?;
    let mut q = hh::HscRequest { counter: n, ..Default::default() };
    let (mc, mt) =
        opt(&opts, "mode").ok_or_else(|| Error::usage(crate::msg!("shell-hsc-needs-mode")).hint(HSC.usage))?;
    q.mode = number((mc, mt), "mode")?;
    if let Some((c, r)) = opt(&opts, "rate") {
        q.rate4x = match r.to_ascii_lowercase().as_str() {
            "4x" | "4" => true,
            "1x" | "1" => false,
            _ => return Err(value_err(c, format!("rate={r}: use 1x or 4x"))),
        };
    }
    if let Some((c, d)) = opt(&opts, "dir") {
        q.up = Some(match d.to_ascii_lowercase().as_str() {
            "up" => true,
            "down" => false,
            _ => return Err(value_err(c, crate::msg!("shell-hsc-dir", value = d))),
        });
    }
    for (key, slot) in [("reset", &mut q.reset_low), ("start", &mut q.start_low)] {
        if let Some((c, v)) = opt(&opts, key) {
            *slot = match v.to_ascii_lowercase().as_str() {
                "low" => true,
                "high" => false,
                _ => return Err(value_err(c, crate::msg!("shell-hsc-level", key = key, value = v))),
            };
        }
    }
    if let Some((c, v)) = opt(&opts, "cv") {
        q.cv = Some(number((c, v), "cv")?);
    }
    if let Some((c, v)) = opt(&opts, "pv") {
        let inner = v.strip_prefix('[').and_then(|t| t.strip_suffix(']')).unwrap_or(v);
        for (k, p) in lex::split_top(inner, ',')? {
            let p = p.trim();
            if !p.is_empty() {
                q.pv.push(number((c + 4 + k, p), "pv")?);
            }
        }
    }
    let mut i = 1;
    while i < pos.len() {
        let (c, t) = pos[i];
        match t.to_ascii_lowercase().as_str() {
            "relative" => q.relative = true,
            "absolute" => q.relative = false,
            "cyclic" => q.cyclic = true,
            "force" => q.force = true,
            "at" => {
                let (c2, a) =
                    *pos.get(i + 1).ok_or_else(|| Error::usage(crate::msg!("shell-at-needs-v-address")).column(c))?;
                q.at = Some(
                    a.to_ascii_uppercase()
                        .trim_start_matches('%')
                        .strip_prefix("VB")
                        .and_then(|n| n.parse().ok())
                        .ok_or_else(|| {
                            value_err(c2, crate::msg!("shell-not-a-v-byte", text = a, example = "VB3009"))
                        })?,
                );
                i += 1;
            }
            _ => return Err(Error::usage(crate::msg!("shell-unexpected", extra = t)).column(c).hint(HSC.usage)),
        }
        i += 1;
    }
    let (model, backup) = {
        let k2 = k2cmd::k2(sh, dev)?;
        (k2.model(), k2.backup_area())
    };
    let plan = hh::plan(model, &q, backup).map_err(|e| e.device(&name))?;
    let d = helpers::execute(sh.session.entry(dev).device.as_mut(), &plan).map_err(|e| e.device(&name))?;
    Ok(done_outcome("hsc", name, d))
}
