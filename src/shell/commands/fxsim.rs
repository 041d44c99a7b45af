//! `sim program load FILE.il | unload`, `sim program`, `sim cpu run|stop` (`sim stop`) on the
//! current simulated FX PLC (`sim-fx:`): an FX instruction list run by the simulator's CPU
//! ([`crate::fx::plc`], [`crate::fx::program`]). The same words as the K2's CPU commands; an FX
//! has no PAUSE mode, so `sim cpu pause` is refused.

use crate::core::{Error, Result};
use crate::fx::memory::Memory;
use crate::fx::plc::Mode;
use crate::output::Outcome;
use crate::shell::{lex, Args, Shell};

pub const USAGE: &str =
    "sim program load FILE.il [tags=FILE.csv] | sim program unload | sim program | sim cpu run|stop | sim stop";

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
    lines.push(format!(
        "{name}: {} {}; {}",
        m.model.name,
        c.mode.name(),
        match &program {
            Some(p) => format!("program {p} ({} instructions)", c.program.as_ref().map_or(0, |p| p.instructions)),
            None => "no program (sim program load FILE.il)".into(),
        }
    ));
    lines.push(format!(
        "scans {}; scan time last {} ms, min {} ms, max {} ms (D8010/D8011/D8012); time {:.3} s",
        c.stats.scans,
        ms(c.stats.last_ns),
        ms(c.stats.min_ns),
        ms(c.stats.max_ns),
        m.time().as_secs_f64()
    ));
    if let Some(f) = &c.fault {
        lines.push(format!("stopped by a fault: {f}"));
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
    let d = ops.ok_or_else(|| Error::usage("not an FX simulator"))?;
    let plc = d.sim.clone().ok_or_else(|| Error::unsupported("a real FX runs its own program").device(&name))?;
    let mut m = plc.lock().unwrap_or_else(|p| p.into_inner());
    m.advance();
    let arg = |k: usize| words.get(k).map(|w| (w.0, w.1));
    let msg = match sub {
        "program" => match arg(1) {
            None | Some((_, "status")) => None,
            Some((c, "load")) => {
                // The tag file of the list's symbols after it (`tags=press1.csv`, docs/tags.md).
                let (args, tag_file) = super::simprogram::tags_option(args)?;
                let (c2, path) = lex::one_path(&args, 2, "sim program load")?
                    .ok_or_else(|| Error::usage("sim program load needs a file, e.g. scripts/fx_blink.il").column(c))?;
                sh.session.check_read(&path).map_err(|e| e.device(&name).column(c2))?;
                let text = crate::core::encoding::read_source(&path)
                    .map_err(|e| Error::io(format!("cannot read {path}: {e}")).device(&name).column(c2))?;
                let tags = match &tag_file {
                    Some((tc, t)) => {
                        sh.session.check_read(t).map_err(|e| e.device(&name).column(*tc))?;
                        let space = crate::fx::space::FxSpace::new(m.model, crate::fx::space::Proto::Port);
                        Some(
                            crate::profile::tags::load(std::path::Path::new(t), None, &space)
                                .map_err(|p| p.into_error().device(&name).column(*tc))?,
                        )
                    }
                    None => None,
                };
                let loaded = crate::fx::program::Loaded::load_with_tags(&text, &path, m.model, tags.as_ref())
                    .map_err(|e| e.device(&name))?;
                let n = loaded.instructions;
                m.load_program(loaded);
                Some(format!("{path}: {n} instructions loaded; the PLC restarts in RUN"))
            }
            Some((_, "unload")) => {
                m.unload_program();
                Some("program removed: the PLC scans an empty program".to_string())
            }
            Some((c, other)) => {
                return Err(Error::usage(format!("unknown `sim program {other}` on an FX PLC"))
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
                    return Err(Error::usage("an FX PLC has RUN and STOP, no PAUSE")
                        .hint("sim cpu run | sim cpu stop")
                        .device(&name)
                        .column(c))
                }
                _ => return Err(Error::usage("sim cpu needs run or stop").hint(USAGE).column(c)),
            };
            m.set_mode(mode);
            Some(format!("{} in {}", m.model.name, mode.name()))
        }
        other => {
            return Err(Error::usage(format!("`sim {other}` is not available on an FX PLC"))
                .hint(USAGE)
                .device(&name)
                .column(col))
        }
    };
    let mut o = status(&m, &name, msg);
    o.device = Some(name);
    Ok(o)
}
