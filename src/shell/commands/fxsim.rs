//! `sim program load FILE.il | unload`, `sim program`, `sim cpu run|stop` (`sim stop`) on the
//! current simulated FX PLC (`sim-fx:`): an FX instruction list run by the simulator's CPU
//! ([`crate::fx::plc`], [`crate::fx::program`]). The same words as the K2's CPU commands; an FX
//! has no PAUSE mode, so `sim cpu pause` is refused.

use crate::core::{Error, Result};
use crate::fx::memory::Memory;
use crate::fx::plc::Mode;
use crate::output::Outcome;
use crate::shell::{lex, Args, Shell};

pub const USAGE: &str = "sim program load FILE.il | sim program unload | sim program | sim cpu run|stop | sim stop";

/// True when the current device is a simulated FX PLC.
pub fn current_is_fx_sim(sh: &mut Shell) -> bool {
    let Ok(i) = sh.session.current_index() else { return false };
    crate::fx::driver::ops(sh.session.entry(i).device.as_mut(), &[]).ok().flatten().is_some()
}

fn ms(ns: u64) -> f64 {
    (ns as f64 / 1e4).round() / 100.0
}

/// The status outcome (`sim program`).
fn status(m: &Memory, name: &str, msg: Option<String>) -> Outcome {
    let c = &m.cpu;
    let program = c.program.as_ref().map(|p| p.source.clone());
    let mut lines: Vec<String> = msg.into_iter().collect();
    let (model, mode) = (m.model.name, c.mode.name());
    lines.push(match &program {
        Some(p) => {
            let n = c.program.as_ref().map_or(0, |p| p.instructions);
            crate::msg!(
                "shell-fx-program",
                name = name,
                model = model,
                mode = mode,
                program = p.as_str(),
                instructions = n
            )
            .text
        }
        None => crate::msg!("shell-fx-no-program", name = name, model = model, mode = mode).text,
    });
    lines.push(
        crate::msg!(
            "shell-fx-scans",
            scans = c.stats.scans,
            last = ms(c.stats.last_ns).to_string(),
            min = ms(c.stats.min_ns).to_string(),
            max = ms(c.stats.max_ns).to_string(),
            time = format!("{:.3}", m.time().as_secs_f64())
        )
        .text,
    );
    if let Some(f) = &c.fault {
        lines.push(crate::msg!("shell-fx-fault", fault = f.to_string()).text);
    }
    Outcome::new("sim")
        .text(lines.join("\n"))
        .with("mode", c.mode.name())
        .with("program", program)
        .with("scans", c.stats.scans)
        .with("scan_ms", ms(c.stats.last_ns))
        .with("scan_min_ms", ms(c.stats.min_ns))
        .with("scan_max_ms", ms(c.stats.max_ns))
        .with("fault", c.fault.clone())
}

/// `sim program …`, `sim cpu …`, `sim stop` on the current FX simulator.
pub fn run(sh: &mut Shell, sub: &str, args: Args) -> Result<Outcome> {
    let words = lex::words_in(&args)?;
    let dev = sh.session.current_index()?;
    let name = sh.session.entries()[dev].name.clone();
    let col = words.first().map_or(args.offset, |w| w.0);
    let ops = crate::fx::driver::ops(sh.session.entry(dev).device.as_mut(), &[])?;
    let d = ops.ok_or_else(|| Error::usage(crate::msg!("shell-fx-not-simulator")))?;
    let plc = d.sim.clone().ok_or_else(|| Error::unsupported(crate::msg!("shell-fx-real")).device(&name))?;
    let mut m = plc.lock().unwrap_or_else(|p| p.into_inner());
    m.advance();
    let arg = |k: usize| words.get(k).map(|w| (w.0, w.1));
    let msg = match sub {
        "program" => match arg(1) {
            None | Some((_, "status")) => None,
            Some((c, "load")) => {
                let (c2, path) = lex::one_path(&args, 2, "sim program load")?.ok_or_else(|| {
                    Error::usage(crate::msg!("shell-sim-load-needs-file", example = "scripts/fx_blink.il")).column(c)
                })?;
                sh.session.check_read(&path).map_err(|e| e.device(&name).column(c2))?;
                let text = crate::core::encoding::read_source(&path).map_err(|e| {
                    Error::io(crate::msg!("shell-cannot-read-because", file = path.as_str(), reason = e.to_string()))
                        .device(&name)
                        .column(c2)
                })?;
                let loaded = crate::fx::program::Loaded::load(&text, &path, m.model).map_err(|e| e.device(&name))?;
                let n = loaded.instructions;
                m.load_program(loaded);
                Some(crate::msg!("shell-fx-loaded", file = path.as_str(), instructions = n).text)
            }
            Some((_, "unload")) => {
                m.unload_program();
                Some(crate::msg!("shell-fx-unloaded").text)
            }
            Some((c, other)) => {
                return Err(Error::usage(crate::msg!("shell-fx-program-unknown", sub = other))
                    .hint(USAGE)
                    .device(&name)
                    .column(c))
            }
        },
        "cpu" | "stop" | "pause" => {
            let (c, w) = if sub == "cpu" { arg(1).unwrap_or((col, "")) } else { (col, sub) };
            let mode = match w.to_ascii_lowercase().as_str() {
                "run" => Mode::Run,
                "stop" => Mode::Stop,
                "pause" => {
                    return Err(Error::usage(crate::msg!("shell-fx-no-pause"))
                        .hint("sim cpu run | sim cpu stop")
                        .device(&name)
                        .column(c))
                }
                _ => return Err(Error::usage(crate::msg!("shell-fx-cpu-needs-mode")).hint(USAGE).column(c)),
            };
            m.set_mode(mode);
            Some(crate::msg!("shell-fx-mode", model = m.model.name, mode = mode.name()).text)
        }
        other => {
            return Err(Error::usage(crate::msg!("shell-fx-sim-unavailable", sub = other))
                .hint(USAGE)
                .device(&name)
                .column(col))
        }
    };
    let mut o = status(&m, &name, msg);
    o.device = Some(name);
    Ok(o)
}
