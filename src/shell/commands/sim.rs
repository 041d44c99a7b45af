//! `sim time`, `sim step DURATION`, `sim clock [real|stepped]`: the session's virtual clock
//! (`sim run` is refused: the clock's word is `sim clock real`, the CPU's `sim cpu run`); `sim input`,
//! `sim quad`, `sim inputs`: simulated signals on the PLC's inputs for the high-speed
//! counters; `sim retain`: battery-retained ranges; `sim snapshot`, `sim snapshots`: saved
//! simulator states.

use super::CommandSpec;
use crate::core::clock::format_time;
use crate::core::literal::parse_option_duration_us;
use crate::core::{Clock, Error, Result};
use crate::output::Outcome;
use crate::shell::{Args, Shell};
use std::time::Duration;

pub const SIM: CommandSpec = CommandSpec {
    name: "sim",
    aliases: &[],
    usage: "sim time | sim step DURATION | sim clock [real|stepped] | sim input I0.1 freq=1kHz [dir=up|down] | sim input I0.1 off | sim quad A B freq=1kHz [dir=up|down] | sim inputs | sim retain RANGE…|none | sim program load FILE.il [tags=FILE.csv] | sim program unload | sim program [status] | sim program costs [bit=200ns] … | sim program stop-outputs QB0=16#05 … | sim cpu run|stop|pause | sim stop | sim pause | sim switch run|stop | sim scan [N] | sim break [LINE|FILE:LINE|network N|clear] | sim stepi [N] | sim stepn | sim wire FROM -> TO[,TO…] [lines=N] [delay=D] | sim wires | sim unwire TERMINAL|all | sim snapshot save|restore NAME | sim snapshots | sim fault KIND … [at=TIME] [after=D] [for=D] [times=N] | sim fault clear [ID] | sim faults",
    summary: || crate::msg!("summary-sim"),
    subcommands: &[
        "time", "step", "clock", "input", "quad", "inputs", "retain", "program", "cpu", "stop", "pause", "switch", "scan", "break", "stepi",
        "stepn", "wire", "wires", "unwire", "snapshot", "snapshots", "fault", "faults",
    ],
    run: sim,
};

fn sim(sh: &mut Shell, args: Args) -> Result<Outcome> {
    let mut it = args.text.split_whitespace();
    let sub = it.next().unwrap_or("time");
    let clock = sh.session.clock.clone();
    // `sim time`, `sim step D`, `sim run` take nothing more: a trailing word (`sim step 1 s`,
    // `sim time now`) is refused, never ignored.
    let takes = match sub {
        "time" | "run" => 0,
        "step" | "clock" => 1,
        _ => usize::MAX,
    };
    if let Some(w) = args.text.split_whitespace().nth(1 + takes.min(8)).filter(|_| takes != usize::MAX) {
        let form = if sub == "step" { crate::msg!("shell-sim-step-form").text } else { SIM.usage.to_string() };
        return Err(Error::usage(crate::msg!("shell-unexpected-after-sim", extra = w, sub = sub))
            .hint(form)
            .column(args.offset + args.text.find(w).unwrap_or(0)));
    }
    match sub {
        "time" => {}
        "step" => {
            let d = it
                .next()
                .ok_or_else(|| Error::usage(crate::msg!("shell-sim-step-needs-duration")).column(args.offset))?;
            let us = parse_option_duration_us(d).map_err(|m| Error::usage(m).column(args.offset + 5))?;
            if us < 0 {
                return Err(Error::usage(crate::msg!("shell-sim-time-forward")));
            }
            let step = Duration::from_micros(us as u64);
            if clock.now().checked_add(step).is_none_or(|t| t > Clock::LATEST) {
                return Err(Error::usage(crate::msg!(
                    "shell-sim-step-too-far",
                    step = d,
                    latest = format!("{:.0}", Clock::LATEST.as_secs_f64())
                ))
                .column(args.offset + 5));
            }
            let step = sh.session.budget_step(step)?;
            clock.step(step);
        }
        "clock" => match args.text.split_whitespace().nth(1).map(str::to_ascii_lowercase).as_deref() {
            None => {}
            // Under a simulated-time limit (a graded run) the clock stays simulated: the
            // wall clock would make the run's results depend on the machine's speed.
            Some("real") if sh.session.budget.is_some() => {
                return Err(Error::unsupported(crate::msg!("shell-sim-clock-graded"))
                    .hint(crate::msg!("shell-hint-sim-clock-graded")))
            }
            Some("real") => clock.run(),
            Some("stepped") => clock.step(Duration::ZERO),
            Some(w) => {
                return Err(Error::usage(crate::msg!("shell-sim-not-clock-mode", mode = w))
                    .hint(crate::msg!("shell-hint-sim-clock-modes"))
                    .column(args.offset + args.text.find(w).unwrap_or(0)))
            }
        },
        "run" => {
            return Err(Error::usage(crate::msg!("shell-sim-run-ambiguous"))
                // Within 80 columns after `  hint: `.
                .hint(crate::msg!("shell-hint-sim-run-ambiguous"))
                .column(args.offset));
        }
        "serve" | "control" => {
            return Err(Error::usage(crate::msg!("shell-sim-cli-only", sub = sub))
                .hint(crate::msg!("shell-hint-sim-cli-only", sub = sub))
                .column(args.offset))
        }
        "input" if super::umpk::current_is_umpk(sh) => return super::umpk::sim_input(sh, args),
        "program" if super::umpk::current_is_umpk(sh) => return super::umpk::sim_program(sh, args),
        "program" | "cpu" | "stop" | "pause" | "switch" | "scan" | "break" | "stepi" | "stepn"
            if super::fxsim::current_is_fx_sim(sh) =>
        {
            return super::fxsim::run(sh, sub, args)
        }
        "input" | "quad" | "inputs" | "retain" => return super::siminputs::run(sh, sub, args),
        "snapshot" | "snapshots" => {
            // The name or path as text: `sim snapshot save "снимки/до пуска.json"`.
            let words = crate::shell::lex::unquoted_words(args.text).map_err(|e| e.shift(args.offset))?;
            let rest = words.iter().skip(1).map(|w| w.as_ref()).collect();
            return super::snapshot::run(sh, sub, rest, args.offset);
        }
        "fault" | "faults" => {
            // `sim fault clear [ID|all]`: one word at most, a number or `all`, each refused at
            // its column with the form (the control language's whole grammar is no hint here).
            let words = crate::shell::lex::words_in(&args)?;
            if sub == "fault" && words.get(1).is_some_and(|w| w.1.eq_ignore_ascii_case("clear")) {
                const FORM: &str = "sim fault clear [ID|all]";
                let hint = || crate::msg!("shell-hint-fault-clear");
                if let Some(&(col, extra)) = words.get(3) {
                    let typed: Vec<&str> = words[..3].iter().map(|w| w.1).collect();
                    return Err(Error::usage(crate::msg!(
                        "shell-unexpected-after",
                        extra = extra,
                        typed = format!("sim {}", typed.join(" ")),
                        forms = FORM
                    ))
                    .hint(hint())
                    .column(col));
                }
                if let Some(&(col, id)) = words.get(2) {
                    if !id.eq_ignore_ascii_case("all") && id.parse::<u32>().is_err() {
                        return Err(Error::usage(crate::msg!("shell-not-a-fault-id", id = id, form = FORM))
                            .hint(hint())
                            .column(col));
                    }
                }
            }
            let rest = args.text.trim_start().get(sub.len()..).unwrap_or("").trim();
            return super::fault::run(sh, sub, rest);
        }
        "wire" | "wires" | "unwire" => return super::simwire::run(sh, sub, args),
        "program" | "cpu" | "stop" | "pause" | "switch" | "scan" | "break" | "stepi" | "stepn" => {
            let o = super::simprogram::run(sh, sub, args)?;
            if sub == "scan" {
                // Scans run at their modelled times: the clock follows to the last one.
                if let Some(t) = sh
                    .session
                    .current_index()
                    .ok()
                    .and_then(|d| super::k2cmd::sim(sh, d, &format!("sim {sub}")).ok())
                    .map(|s| s.last)
                {
                    let now = clock.now();
                    if t > now {
                        clock.step(t - now);
                    }
                }
            }
            return Ok(o);
        }
        other => {
            return Err(Error::usage(crate::msg!("shell-sim-unknown", sub = other)).hint(SIM.usage).column(args.offset))
        }
    }
    let now = clock.now();
    let mode = if clock.is_stepped() { "stepped" } else { "wall" };
    Ok(Outcome::new("sim")
        .text(crate::msg!("shell-sim-time", time = format_time(now), mode = mode).text)
        .with("time_us", now.as_micros() as u64)
        .with("stepped", clock.is_stepped()))
}
