//! Pulse output commands (manual §3.4): the instructions `pls N` and `pstop N`, and the
//! typed helpers `pto`, `pwm`, `profile` that write the registers for the user, validate
//! first, and print the raw writes they made.

use super::k2cmd::{self, check_options, done_outcome, opt, value_err};
use super::CommandSpec;
use crate::core::{Error, Result};
use crate::k2::helpers::{self, pto as hp};
use crate::k2::K2Ops;
use crate::output::Outcome;
use crate::shell::lex::{self, Word};
use crate::shell::{Args, Shell};

pub const PLS: CommandSpec = CommandSpec {
    name: "pls",
    aliases: &[],
    usage: "pls N [strict]   e.g. set SMB67=16#85, SMW68=500, SMD72=1000; pls 0",
    summary: || crate::msg!("summary-pls"),
    subcommands: &[],
    run: pls,
};

pub const PSTOP: CommandSpec = CommandSpec {
    name: "pstop",
    aliases: &[],
    usage: "pstop N",
    summary: || crate::msg!("summary-pstop"),
    subcommands: &[],
    run: pstop,
};

pub const PTO: CommandSpec = CommandSpec {
    name: "pto",
    aliases: &[],
    usage: "pto N freq=2kHz count=1000 [strict] | pto N cycle=500us count=1000 [strict] | pto N status | pto status N",
    summary: || crate::msg!("summary-pto"),
    subcommands: &["status"],
    run: pto,
};

pub const PWM: CommandSpec = CommandSpec {
    name: "pwm",
    aliases: &[],
    usage: "pwm N cycle=1ms width=250us [sync|async] [strict]",
    summary: || crate::msg!("summary-pwm"),
    subcommands: &[],
    run: pwm,
};

pub const PROFILE: CommandSpec = CommandSpec {
    name: "profile",
    aliases: &[],
    usage: "profile N at VB3001 [(cycle=500us, count=1000), (freq=4kHz, count=4000), …] [force] [strict] [plan [to=FILE.png|FILE.svg] [size=900x340]]",
    summary: || crate::msg!("summary-profile"),
    subcommands: &[],
    run: profile,
};

fn instruction(sh: &mut Shell, args: Args, cmd: &str, usage: &str) -> Result<Outcome> {
    let mut w = lex::words_in(&args)?;
    let strict = cmd == "pls" && w.iter().any(|(_, t)| t.eq_ignore_ascii_case("strict"));
    w.retain(|(_, t)| cmd != "pls" || !t.eq_ignore_ascii_case("strict"));
    let Some(&word) = w.first() else {
        return Err(Error::usage(crate::msg!("shell-pulse-channel-missing", usage = usage)).column(args.offset));
    };
    if w.len() > 1 {
        return Err(Error::usage(crate::msg!("shell-pulse-one-channel", command = cmd))
            .column(w[1].0)
            .hint(usage.to_string()));
    }
    let (dev, ch) = k2cmd::channel(sh, word, "pulse", 3)?;
    let name = k2cmd::name(sh, dev);
    let warning = if cmd == "pls" { busy_check(sh, dev, ch, strict, "PLS")? } else { None };
    let mut k2 = k2cmd::k2(sh, dev)?;
    let report = if cmd == "pls" { k2.pls(ch) } else { k2.pstop(ch) }.map_err(|e| e.device(&name))?;
    let sim = sh.session.simulated(dev);
    let mut o = Outcome::new(cmd).text(report.clone()).with("report", report).with("channel", ch).acted_on(&name, sim);
    o.notes.extend(warning);
    Ok(o)
}

/// Before a PLS (or `pto`/`profile`, which end in one): a channel still busy would have its
/// running train replaced. A warning by default; an error with `strict`.
fn busy_check(sh: &mut Shell, dev: usize, ch: u8, strict: bool, by: &str) -> Result<Option<String>> {
    let (model, _) = model_of(sh, dev)?;
    let name = k2cmd::name(sh, dev);
    let Some(what) = hp::busy(sh.session.entry(dev).device.as_mut(), model, ch).map_err(|e| e.device(&name))? else {
        return Ok(None);
    };
    // A new cycle/width for a running PWM is how its duty is changed, not a conflict.
    if by == "PWM" && what.starts_with("PWM") {
        return Ok(None);
    }
    if strict {
        return Err(Error::state(crate::msg!("shell-pulse-busy-strict", busy = what.as_str(), by = by, channel = ch))
            .device(&name)
            .hint(crate::msg!("shell-hint-pulse-busy", channel = ch)));
    }
    Ok(Some(crate::msg!("shell-pulse-busy-replaced", busy = what.as_str(), by = by, channel = ch).text))
}

fn pls(sh: &mut Shell, args: Args) -> Result<Outcome> {
    instruction(sh, args, "pls", PLS.usage)
}

fn pstop(sh: &mut Shell, args: Args) -> Result<Outcome> {
    instruction(sh, args, "pstop", PSTOP.usage)
}

/// `freq=` or `cycle=` → a rate.
fn rate(opts: &[lex::Opt]) -> Result<Option<hp::Rate>> {
    match (opt(opts, "freq"), opt(opts, "cycle")) {
        (Some(_), Some((c, _))) => Err(Error::usage(crate::msg!("shell-freq-or-cycle")).column(c)),
        (Some((c, f)), None) => Ok(Some(hp::Rate::Hz(helpers::parse_freq_hz(f).map_err(|m| value_err(c, m))?))),
        (None, Some((c, t))) => Ok(Some(hp::Rate::CycleUs(helpers::parse_us(t).map_err(|m| value_err(c, m))?))),
        (None, None) => Ok(None),
    }
}

/// A pulse count: a whole number; past u32 it is refused naming the limit (a PTO counts
/// to 4 294 967 295, §3.4.2.1).
fn count(opts: &[lex::Opt], key: &str) -> Result<Option<u64>> {
    opt(opts, key)
        .map(|(c, v)| {
            let t = v.replace('_', "");
            t.parse::<u64>().map_err(|_| {
                if !t.is_empty() && t.bytes().all(|b| b.is_ascii_digit()) {
                    value_err(c, crate::msg!("shell-too-many-pulses", key = key, value = v))
                } else {
                    value_err(c, crate::msg!("shell-pulses-not-whole", key = key, value = v))
                }
            })
        })
        .transpose()
}

/// The device's model and its configured backup area.
fn model_of(sh: &mut Shell, dev: usize) -> Result<(&'static crate::k2::catalog::Model, (u32, u32))> {
    let k2 = k2cmd::k2(sh, dev)?;
    Ok((k2.model(), k2.backup_area()))
}

fn run_plan(sh: &mut Shell, dev: usize, cmd: &str, plan: &helpers::Plan) -> Result<Outcome> {
    let name = k2cmd::name(sh, dev);
    let d = helpers::execute(sh.session.entry(dev).device.as_mut(), plan).map_err(|e| e.device(&name))?;
    let sim = sh.session.simulated(dev);
    Ok(done_outcome(cmd, name.clone(), d).acted_on(&name, sim))
}

fn pto(sh: &mut Shell, args: Args) -> Result<Outcome> {
    let w = lex::words_in(&args)?;
    let (pos, opts) = lex::options(&w);
    if let Some(word) = k2cmd::status_channel(&pos, args.offset, "pulse", "pto 0 status") {
        let word = word?;
        let (dev, ch) = k2cmd::channel(sh, word, "pulse", 3)?;
        let name = k2cmd::name(sh, dev);
        let (model, _) = model_of(sh, dev)?;
        let (vals, words) =
            hp::status(sh.session.entry(dev).device.as_mut(), model, ch).map_err(|e| e.device(&name))?;
        let mut o = Outcome::new("pto").text(format!("PTO{ch}: {}", words.join("; "))).with("status", &words);
        o.device = Some(name);
        o.values = k2cmd::readings(&vals);
        return Ok(o);
    }
    check_options(&opts, &["freq", "cycle", "count"], PTO.usage)?;
    let strict = pos.iter().any(|(_, t)| t.eq_ignore_ascii_case("strict"));
    let pos: Vec<_> = pos.into_iter().filter(|(_, t)| !t.eq_ignore_ascii_case("strict")).collect();
    let word = *pos.first().ok_or_else(|| Error::usage(PTO.usage).column(args.offset))?;
    if let Some(extra) = pos.get(1) {
        return Err(Error::usage(crate::msg!("shell-unexpected", extra = extra.1)).column(extra.0).hint(PTO.usage));
    }
    let (dev, ch) = k2cmd::channel(sh, word, "pulse", 3)?;
    let rate = rate(&opts)?
        .ok_or_else(|| Error::usage(crate::msg!("shell-pto-needs-rate")).column(args.offset).hint(PTO.usage))?;
    let n = count(&opts, "count")?
        .ok_or_else(|| Error::usage(crate::msg!("shell-pto-needs-count")).column(args.offset).hint(PTO.usage))?;
    let (model, _) = model_of(sh, dev)?;
    let name = k2cmd::name(sh, dev);
    // A refused rate points at the option as typed (`cycle=2`).
    let at_option = |e: Error| match e.operand.as_deref().and_then(|o| opt(&opts, o)) {
        Some((c, _)) if e.column.is_none() => e.column(c),
        _ => e,
    };
    let plan = hp::plan_pto(model, ch, rate, n).map_err(|e| at_option(e).device(&name))?;
    let warning = busy_check(sh, dev, ch, strict, "PLS")?;
    let mut o = run_plan(sh, dev, "pto", &plan)?;
    o.notes.extend(warning);
    Ok(o)
}

fn pwm(sh: &mut Shell, args: Args) -> Result<Outcome> {
    let w = lex::words_in(&args)?;
    let (pos, opts) = lex::options(&w);
    check_options(&opts, &["cycle", "width", "freq"], PWM.usage)?;
    let word = *pos.first().ok_or_else(|| Error::usage(PWM.usage).column(args.offset))?;
    let (mut sync, mut strict) = (true, false);
    for p in &pos[1..] {
        match p.1.to_ascii_lowercase().as_str() {
            "async" => sync = false,
            "sync" => sync = true,
            "strict" => strict = true,
            _ => return Err(Error::usage(format!("unexpected `{}`", p.1)).column(p.0).hint(PWM.usage)),
        }
    }
    let (dev, ch) = k2cmd::channel(sh, word, "pulse", 3)?;
    let (model, _) = model_of(sh, dev)?;
    let name = k2cmd::name(sh, dev);
    let plan = pwm_plan(model, ch, &opts, sync, args.offset).map_err(|e| e.device(&name))?;
    // As pls/pto/profile: a running train on the channel is replaced with a note, or
    // refused with `strict`.
    let warning = busy_check(sh, dev, ch, strict, "PWM")?;
    let mut o = run_plan(sh, dev, "pwm", &plan)?;
    o.notes.extend(warning);
    Ok(o)
}

/// `pwm`'s options, from the typed text to the plan (the fuzz target `pulse` runs this too).
fn pwm_plan(
    model: &crate::k2::catalog::Model,
    ch: u8,
    opts: &[lex::Opt],
    sync: bool,
    col: usize,
) -> Result<helpers::Plan> {
    let cycle = match rate(opts)? {
        Some(hp::Rate::CycleUs(us)) => us,
        // A float past u64 saturates; the cycle register's limit refuses it in plan_pwm.
        Some(hp::Rate::Hz(f)) => (1e6 / f).round() as u64,
        None => return Err(Error::usage(crate::msg!("shell-pwm-needs-cycle")).column(col).hint(PWM.usage)),
    };
    let (wc, wt) =
        opt(opts, "width").ok_or_else(|| Error::usage(crate::msg!("shell-pwm-needs-width")).hint(PWM.usage))?;
    let width = crate::core::literal::parse_pulse_time_us(wt).map_err(|m| value_err(wc, m))?;
    if width < 0 {
        return Err(value_err(wc, crate::msg!("shell-pwm-negative-width")));
    }
    hp::plan_pwm(model, ch, cycle, width as u64, sync)
}

/// The fuzz target `pulse`: `text` as the options of `pto`, `pwm` and `profile` (a segment
/// list in brackets, `at=VB…`), read as those commands read them and planned on channel 0
/// of every model with pulse outputs. Outside input never panics or wraps on this path.
pub fn fuzz_options(text: &str) {
    let Ok(w) = lex::words(text) else { return };
    let (pos, opts) = lex::options(&w);
    let list = pos.iter().find(|(_, t)| t.starts_with('[')).and_then(|&(c, t)| segments(t, c).ok());
    let at = opt(&opts, "at").and_then(|(_, v)| v.trim_start_matches("VB").parse::<u32>().ok());
    for model in crate::k2::catalog::MODELS.iter().filter(|m| !m.relay) {
        let _ = pwm_plan(model, 0, &opts, true, 0);
        if let (Ok(Some(rate)), Ok(Some(n))) = (rate(&opts), count(&opts, "count")) {
            let _ = hp::plan_pto(model, 0, rate, n);
        }
        if let (Some(list), Some(at)) = (&list, at) {
            if let Ok(p) = hp::plan_profile(model, 0, at, list, true, (3648, 3902)) {
                let _ = hp::timeline(&p.table, p.base_ms);
            }
        }
    }
}

/// `[(cycle=500us, count=1000), …]` → segments.
fn segments(text: &str, col: usize) -> Result<Vec<hp::Segment>> {
    let inner = text
        .strip_prefix('[')
        .and_then(|t| t.strip_suffix(']'))
        .ok_or_else(|| Error::syntax(crate::msg!("shell-segments-in-brackets")).column(col))?;
    let mut out = Vec::new();
    for (c, item) in lex::split_top(inner, ',').map_err(|e| e.shift(col + 1))? {
        let t = item.trim();
        if t.is_empty() {
            continue;
        }
        let at = col + 1 + c + (item.len() - item.trim_start().len());
        let body = t
            .strip_prefix('(')
            .and_then(|t| t.strip_suffix(')'))
            .ok_or_else(|| Error::syntax(crate::msg!("shell-not-a-segment", text = t)).column(at))?;
        let ws: Vec<Word> = lex::words(body)?.into_iter().map(|(c2, w)| (at + 1 + c2, w)).collect();
        let (pos, opts) = lex::options(&ws);
        if let Some(p) = pos.first() {
            return Err(Error::syntax(crate::msg!("shell-unexpected-in-segment", extra = p.1)).column(p.0));
        }
        check_options(&opts, &["cycle", "freq", "count"], PROFILE.usage)?;
        let rate = rate(&opts)?.ok_or_else(|| Error::usage(crate::msg!("shell-segment-needs-rate")).column(at))?;
        let count =
            count(&opts, "count")?.ok_or_else(|| Error::usage(crate::msg!("shell-segment-needs-count")).column(at))?;
        out.push(hp::Segment { rate, count });
    }
    Ok(out)
}

fn profile(sh: &mut Shell, args: Args) -> Result<Outcome> {
    let w = lex::words_in(&args)?;
    let word = *w.first().ok_or_else(|| Error::usage(PROFILE.usage).column(args.offset))?;
    let (dev, ch) = k2cmd::channel(sh, word, "pulse", 3)?;
    let (mut at, mut list, mut force, mut plan_only, mut svg_to) = (None, None, false, false, None);
    let (mut strict, mut size) = (false, None);
    let mut i = 1;
    while i < w.len() {
        let (c, t) = w[i];
        match t.to_ascii_lowercase().as_str() {
            "at" => {
                let (c2, a) =
                    *w.get(i + 1).ok_or_else(|| Error::usage(crate::msg!("shell-at-needs-address")).column(c))?;
                let n = a
                    .to_ascii_uppercase()
                    .trim_start_matches('%')
                    .strip_prefix("VB")
                    .and_then(|n| n.parse::<u32>().ok())
                    .ok_or_else(|| value_err(c2, crate::msg!("shell-not-a-v-byte", text = a, example = "VB3001")))?;
                at = Some(n);
                i += 1;
            }
            "force" => force = true,
            "strict" => strict = true,
            "plan" => plan_only = true,
            // The file as text: `plan to="графики/профиль 1.svg"`.
            _ if t.to_ascii_lowercase().starts_with("to=") => svg_to = Some(lex::unquote(&t[3..]).into_owned()),
            _ if t.to_ascii_lowercase().starts_with("size=") => {
                size = Some(crate::plot::parse_size(&t[5..]).map_err(|m| Error::usage(m).column(c))?)
            }
            _ if t.starts_with('[') => list = Some(segments(t, c)?),
            _ => return Err(Error::usage(crate::msg!("shell-unexpected", extra = t)).column(c).hint(PROFILE.usage)),
        }
        i += 1;
    }
    let at = at.ok_or_else(|| Error::usage(crate::msg!("shell-profile-needs-at")).hint(PROFILE.usage))?;
    let list = list.ok_or_else(|| Error::usage(crate::msg!("shell-profile-needs-segments")))?;
    let (model, backup) = model_of(sh, dev)?;
    let name = k2cmd::name(sh, dev);
    let pr = hp::plan_profile(model, ch, at, &list, force, backup).map_err(|e| e.device(&name))?;
    let tl = hp::timeline(&pr.table, pr.base_ms);
    if plan_only {
        // Frequency over time, drawn before anything is sent.
        let mut points: Vec<(f64, f64)> = tl.points.iter().map(|p| (p.start_us as f64 / 1e6, p.freq_hz)).collect();
        if let Some(last) = tl.points.last() {
            points.push((last.end_us as f64 / 1e6, last.freq_hz));
        }
        let series =
            crate::plot::Series::new(crate::msg!("shell-profile-series", channel = ch).text, "Hz", points).stepped();
        if let Some(path) = &svg_to {
            crate::shell::files::check_write(&sh.write_rule, path)?;
            let one = std::slice::from_ref(&series);
            let title = crate::msg!(
                "shell-profile-plan-title",
                channel = ch,
                pulses = tl.total_pulses,
                segments = tl.points.len()
            )
            .text;
            crate::plot::write_picture(path, one, &title, size.unwrap_or_else(|| crate::plot::default_size(one)))?;
        }
        let mut text = crate::plot::terminal(std::slice::from_ref(&series), 64, 8);
        for (k, p) in tl.points.iter().enumerate() {
            let line = crate::msg!(
                "shell-profile-plan-segment",
                segment = k + 1,
                from = format!("{:.6}", p.start_us as f64 / 1e6),
                to = format!("{:.6}", p.end_us as f64 / 1e6),
                hz = format!("{:.1}", p.freq_hz),
                pulses = p.pulses
            );
            text.push_str(&format!("{line}\n"));
        }
        text.push_str(&crate::msg!(
            "shell-profile-plan-total",
            pulses = tl.total_pulses,
            seconds = format!("{:.6}", tl.duration_us as f64 / 1e6)
        ));
        let mut o =
            Outcome::new("profile").text(text).with("timeline", &tl).with("planned_writes", pr.plan.writes.len());
        if let Some(path) = svg_to {
            o = o.with("file", path);
        }
        o.device = Some(name);
        return Ok(o);
    }
    // The run's report already says "PTO0 (Q0.0): N pulses in K segments, T s": one line per fact.
    let warning = busy_check(sh, dev, ch, strict, "PLS")?;
    let mut o = run_plan(sh, dev, "profile", &pr.plan)?;
    o.notes.extend(warning);
    Ok(o.with("timeline", &tl))
}
