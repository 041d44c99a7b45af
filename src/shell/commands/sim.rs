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
    summary: "the simulator's clock (show, step and keep stepped, follow the wall clock), input signals for the counters, retained ranges, the CPU running an IL program, wiring between simulated devices, snapshots of the simulated state, injected faults",
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
        let form = if sub == "step" { "sim step DURATION (e.g. sim step 1s, sim step 500ms)" } else { SIM.usage };
        return Err(Error::usage(format!("unexpected `{w}` after `sim {sub}`"))
            .hint(form.to_string())
            .column(args.offset + args.text.find(w).unwrap_or(0)));
    }
    match sub {
        "time" => {}
        "step" => {
            let d = it
                .next()
                .ok_or_else(|| Error::usage("sim step needs a duration, e.g. sim step 500ms").column(args.offset))?;
            let us = parse_option_duration_us(d).map_err(|m| Error::usage(m).column(args.offset + 5))?;
            if us < 0 {
                return Err(Error::usage("time only moves forward"));
            }
            let step = Duration::from_micros(us as u64);
            if clock.now().checked_add(step).is_none_or(|t| t > Clock::LATEST) {
                return Err(Error::usage(format!(
                    "sim step {d} would take the simulated clock past {:.0} s (about 584 years), the latest time it counts",
                    Clock::LATEST.as_secs_f64()
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
                return Err(Error::unsupported(
                    "`sim clock real` is not available in a graded run: its clock is simulated",
                )
                .hint("wait with sim step DURATION or plcsh.sleep(ms)"))
            }
            Some("real") => clock.run(),
            Some("stepped") => clock.step(Duration::ZERO),
            Some(w) => {
                return Err(Error::usage(format!("`{w}` is not a clock mode"))
                    .hint("sim clock real (follow the wall clock) | sim clock stepped (move only with sim step)")
                    .column(args.offset + args.text.find(w).unwrap_or(0)))
            }
        },
        "run" => {
            return Err(Error::usage("`sim run` is ambiguous: say which runs")
                // Within 80 columns after `  hint: `.
                .hint("sim clock real: time follows the clock; sim cpu run: the program runs")
                .column(args.offset));
        }
        "serve" | "control" => {
            return Err(Error::usage(format!("`sim {sub}` is a command-line command, not a shell command"))
                .hint(format!("in another terminal: plcsh sim {sub} … (plcsh sim {sub} --help lists its options)"))
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
                const HINT: &str =
                    "sim fault clear (every fault) | sim fault clear 2 (fault 2; `sim faults` lists the ids)";
                if let Some(&(col, extra)) = words.get(3) {
                    let typed: Vec<&str> = words[..3].iter().map(|w| w.1).collect();
                    return Err(Error::usage(format!(
                        "unexpected `{extra}` after `sim {}`: the form is {FORM}",
                        typed.join(" ")
                    ))
                    .hint(HINT)
                    .column(col));
                }
                if let Some(&(col, id)) = words.get(2) {
                    if !id.eq_ignore_ascii_case("all") && id.parse::<u32>().is_err() {
                        return Err(Error::usage(format!("`{id}` is not a fault id: the form is {FORM}"))
                            .hint(HINT)
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
                    .and_then(|d| super::k2cmd::sim(sh, d, "sim scan").ok())
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
        other => return Err(Error::usage(format!("unknown `sim {other}`")).hint(SIM.usage).column(args.offset)),
    }
    let now = clock.now();
    let mode = if clock.is_stepped() { "stepped" } else { "following the wall clock" };
    Ok(Outcome::new("sim")
        .text(format!("simulator time {} ({mode})", format_time(now)))
        .with("time_us", now.as_micros() as u64)
        .with("stepped", clock.is_stepped()))
}
