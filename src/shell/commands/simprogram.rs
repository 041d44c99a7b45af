//! `sim program load FILE.il | unload`, `sim program` (status), `sim cpu run|stop|pause`
//! (`sim stop`, `sim pause` for short), `sim switch run|stop`, `sim scan [N]`: the
//! simulated K2's CPU running an IL program (k2::sim::program). The CPU's RUN is
//! `sim cpu run`; the clock's mode is `sim clock real|stepped` (`sim run` is refused as
//! ambiguous).

use super::k2cmd;
use crate::core::{Error, Result};
use crate::k2::sim::program::Mode;
use crate::k2::sim::K2Sim;
use crate::output::Outcome;
use crate::shell::{Args, Shell};

pub const USAGE: &str = "sim program load FILE.il [tags=FILE.csv] | sim program unload | sim program | sim program costs [bit=200ns … overhead=0.3ms min_scan=1ms watchdog=300ms] | sim program stop-outputs QB0=16#05 AQW0=16000 … | sim cpu run|stop|pause | sim stop | sim pause | sim switch run|stop | sim scan [N] | sim break LINE|FILE:LINE|network N|clear | sim stepi [N] | sim stepn";

fn ms(ns: u64) -> f64 {
    (ns as f64 / 1e6 * 1000.0).round() / 1000.0
}

/// The status outcome (`sim program`).
pub fn status(s: &K2Sim, name: &str) -> Outcome {
    let Some(p) = s.plc() else {
        return Outcome::new("sim").text(crate::msg!("shell-sim-no-program", name = name).text).with("mode", "RUN");
    };
    let st = p.stats;
    let switch = if p.switch_run { "run" } else { "stop" };
    let mut lines = vec![crate::msg!("shell-sim-cpu", name = name, mode = p.mode.name(), switch = switch).text];
    for (what, l) in [("program", &p.user), ("helper", &p.helper)] {
        if let Some(l) = l {
            let source = l.source.to_string();
            let n = l.prog.source_instructions;
            lines.push(crate::msg!("shell-sim-loaded", what = what, source = source, instructions = n).text);
        }
    }
    lines.push(
        crate::msg!(
            "shell-sim-scans",
            scans = st.scans,
            last = ms(st.last_ns).to_string(),
            min = ms(st.min_ns).to_string(),
            max = ms(st.max_ns).to_string(),
            instructions = st.last_instructions,
            interrupts = st.interrupts
        )
        .text,
    );
    lines.push(
        crate::msg!(
            "shell-sim-costs",
            watchdog = ms(p.costs.watchdog_ns).to_string(),
            min_scan = ms(p.costs.min_scan_ns).to_string(),
            overhead = ms(p.costs.overhead_ns).to_string()
        )
        .text,
    );
    if p.mode == Mode::Stop && p.stopped_by_program {
        lines.push(crate::msg!("shell-sim-stopped-by-program").text);
    }
    for f in &p.faults {
        lines.push(
            crate::msg!("shell-sim-fault", at = format!("{:.3}", f.at_ns as f64 / 1e9), fault = f.to_string()).text,
        );
    }
    if let Some(last) = p.errors.last() {
        lines.push(
            crate::msg!(
                "shell-sim-err-led",
                count = p.error_count,
                at = format!("{:.3}", last.at_ns as f64 / 1e9),
                error = last.to_string()
            )
            .text,
        );
    }
    let record = |f: &crate::engine::Fault| {
        serde_json::json!({"code": f.kind.code(), "kind": f.kind.name(), "message": f.message,
            "line": f.line, "instruction": f.instruction, "at_s": f.at_ns as f64 / 1e9})
    };
    let errors: Vec<serde_json::Value> = p.errors.iter().map(record).collect();
    let faults: Vec<serde_json::Value> = p.faults.iter().map(record).collect();
    Outcome::new("sim")
        .text(lines.join("\n"))
        .with("mode", p.mode.name())
        .with("program", p.user.as_ref().map(|l| l.source.clone()))
        .with("helper", p.helper.is_some())
        .with("scans", st.scans)
        .with("scan_ms", ms(st.last_ns))
        .with("scan_min_ms", ms(st.min_ns))
        .with("scan_max_ms", ms(st.max_ns))
        .with("instructions", st.last_instructions)
        .with("interrupts", st.interrupts)
        .with("watchdog_ms", ms(p.costs.watchdog_ns))
        .with("faults", faults)
        .with("errors", errors)
        .with("error_count", p.error_count)
        .with("err_led", !p.faults.is_empty() || p.error_count > 0)
}

/// `args` without a last word `tags=FILE` (any case; the file may be quoted), and that file
/// with its column. `tags=` elsewhere than last is refused: it follows the program's file.
pub fn tags_option(args: Args) -> Result<(Args, Option<(usize, String)>)> {
    let words = crate::shell::lex::words_in(&args)?;
    let is_tags = |w: &str| w.get(..5).is_some_and(|k| k.eq_ignore_ascii_case("tags="));
    let Some(i) = words.iter().position(|(_, w)| is_tags(w)) else { return Ok((args, None)) };
    let (col, word) = words[i];
    if i + 1 != words.len() {
        return Err(Error::usage(crate::msg!("tags-option-last")).column(col));
    }
    let path = crate::shell::lex::unquote(&word[5..]).into_owned();
    if path.is_empty() {
        return Err(Error::usage(crate::msg!("tags-option-last")).column(col));
    }
    let cut = col - args.offset;
    Ok((Args { text: &args.text[..cut], offset: args.offset }, Some((col + 5, path))))
}

pub fn run(sh: &mut Shell, sub: &str, args: Args) -> Result<Outcome> {
    let words: Vec<&str> = args.text.split_whitespace().collect();
    let dev = sh.session.current_index()?;
    let name = k2cmd::name(sh, dev);
    // The file, as text: `sim program load "Проверка 1/светофор.il"` (docs/commands.md, "Quoting"),
    // and the tag file of its symbols after it (`tags=press1.csv`, docs/tags.md).
    let (file, tag_file) = match (sub, words.get(1)) {
        ("program", Some(&"load")) => {
            let (args, tags) = tags_option(args)?;
            (crate::shell::lex::one_path(&args, 2, "sim program load")?, tags)
        }
        _ => (None, None),
    };
    if let Some((c, path)) = &tag_file {
        sh.session.check_read(path).map_err(|e| e.column(*c))?;
    }
    if let Some((c, path)) = &file {
        sh.session.check_read(path).map_err(|e| e.column(*c))?;
    }
    let s = k2cmd::sim(sh, dev, &format!("sim {sub}"))?;
    s.advance();
    let mode = |w: Option<&&str>| -> Result<Mode> {
        match w.map(|w| w.to_ascii_lowercase()).as_deref() {
            Some("run") => Ok(Mode::Run),
            Some("stop") => Ok(Mode::Stop),
            Some("pause") => Ok(Mode::Pause),
            _ => Err(Error::usage(crate::msg!("shell-sim-cpu-needs-mode")).hint(USAGE)),
        }
    };
    match sub {
        "program" => match words.get(1).copied() {
            None | Some("status") => Ok(status(s, &name)),
            Some("load") => {
                let (c, path) =
                    file.ok_or_else(|| Error::usage(crate::msg!("shell-sim-load-needs-file", example = "prog.il")))?;
                let text = crate::core::encoding::read_source(&path).map_err(|e| {
                    Error::io(crate::msg!("shell-cannot-read-because", file = path.as_str(), reason = e.to_string()))
                        .device(name.clone())
                        .column(c)
                })?;
                let tags = match &tag_file {
                    Some((c, t)) => Some(
                        crate::profile::tags::load(std::path::Path::new(t), None, s.space())
                            .map_err(|p| p.into_error().device(name.clone()).column(*c))?,
                    ),
                    None => None,
                };
                let msg = s.load_program_with_tags(&text, &path, tags.as_ref()).map_err(|e| e.device(name.clone()))?;
                let mut o = status(s, &name).text(msg);
                o.notes.extend(tags.iter().flat_map(|t| t.warnings()).map(|w| w.to_string()));
                Ok(o)
            }
            Some("costs") => {
                let t = s.set_costs(&words[2..].join(" ")).map_err(|e| e.device(name.clone()))?;
                let classes: Vec<String> =
                    crate::engine::CostClass::ALL.iter().map(|c| format!("{}={}ns", c.name(), t.ns(*c))).collect();
                let text = format!(
                    "{}; element={}ns overhead={} ms min_scan={} ms watchdog={} ms",
                    classes.join(" "),
                    t.per_element_ns,
                    ms(t.overhead_ns),
                    ms(t.min_scan_ns),
                    ms(t.watchdog_ns)
                );
                Ok(Outcome::new("sim").text(text).with("costs", t))
            }
            Some("stop-outputs") => {
                let b = s.set_stop_outputs(&words[2..].join(" ")).map_err(|e| e.device(name.clone()))?;
                let text: Vec<String> = b.iter().enumerate().map(|(i, v)| format!("QB{i}=16#{v:02X}")).collect();
                let text = crate::msg!("shell-sim-stop-values", values = text.join(" ")).text;
                Ok(Outcome::new("sim").text(text).with("stop_outputs", b))
            }
            Some("unload") => {
                s.unload_program();
                Ok(status(s, &name))
            }
            Some(o) => Err(Error::usage(crate::msg!("shell-sim-program-unknown", sub = o)).hint(USAGE)),
        },
        "cpu" | "stop" | "pause" => {
            let m = if sub == "cpu" { mode(words.get(1))? } else { mode(Some(&sub))? };
            s.set_mode(m).map_err(|e| e.device(name.clone()))?;
            Ok(status(s, &name))
        }
        "switch" => {
            let run = match words.get(1).map(|w| w.to_ascii_lowercase()).as_deref() {
                Some("run") => true,
                Some("stop") => false,
                _ => return Err(Error::usage(crate::msg!("shell-sim-switch-form"))),
            };
            s.set_switch(run).map_err(|e| e.device(name.clone()))?;
            Ok(status(s, &name))
        }
        "scan" => {
            let n: u64 = match words.get(1) {
                Some(w) => w
                    .parse()
                    .ok()
                    .filter(|n| (1..=10_000_000).contains(n))
                    .ok_or_else(|| Error::usage(crate::msg!("shell-sim-scan-count", text = *w)))?,
                None => 1,
            };
            let before = s.plc().map_or(0, |p| p.stats.scans);
            s.scan_n(n).map_err(|e| e.device(name.clone()))?;
            // The clock stays where it is; the scans ran at their modelled times.
            let done = s.plc().map_or(0, |p| p.stats.scans) - before;
            let o = status(s, &name);
            Ok(o.with("ran", done))
        }
        "break" => {
            // `sim break "Проверка 1/светофор.il:5"`: the words as text.
            let spec = crate::shell::lex::unquoted_words(args.text)?[1..].join(" ");
            let msg = match spec.as_str() {
                "" => {
                    let b = s.breakpoints();
                    if b.is_empty() {
                        crate::msg!("shell-sim-no-breakpoints").text
                    } else {
                        let lines = b.iter().map(|l| l.to_string()).collect::<Vec<_>>().join(", ");
                        crate::msg!("shell-sim-breakpoints", count = b.len(), lines = lines).text
                    }
                }
                "clear" => {
                    s.clear_breakpoints();
                    crate::msg!("shell-sim-breakpoints-cleared").text
                }
                spec => s.set_breakpoint(spec).map_err(|e| e.device(name.clone()))?,
            };
            let lines = s.breakpoints();
            Ok(Outcome::new("sim").text(msg).with("breakpoints", lines))
        }
        "stepi" | "stepn" => {
            let n: u64 = match words.get(1) {
                Some(w) if sub == "stepi" => w
                    .parse()
                    .ok()
                    .filter(|n| (1..=100_000).contains(n))
                    .ok_or_else(|| Error::usage(crate::msg!("shell-sim-stepi-count", text = *w)))?,
                _ => 1,
            };
            let steps = s.debug_step(n, sub == "stepn").map_err(|e| e.device(name.clone()))?;
            let text: Vec<String> = steps
                .iter()
                .map(|st| {
                    format!(
                        "line {:>4} (network {}): {:<36} CR={} {}",
                        st.line,
                        st.network,
                        st.instruction,
                        st.cr as u8,
                        st.operands.join(" ")
                    )
                })
                .collect();
            let mode = s.plc().map_or("RUN", |p| p.mode.name());
            Ok(Outcome::new("sim").text(text.join("\n")).with("steps", steps).with("mode", mode))
        }
        _ => Err(Error::usage(format!("unknown `sim {sub}`")).hint(USAGE)),
    }
}
