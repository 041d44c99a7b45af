//! `sim input I0.1 freq=1kHz [dir=up|down]`, `sim input I0.1 off`, `sim quad A B freq=…
//! [dir=down]`, `sim inputs`, `sim retain RANGES|none` — simulator-only controls, reached
//! through `k2::simulator`.

use super::k2cmd::{self, check_options, opt, value_err};
use crate::core::{Error, Result, Value};
use crate::k2::helpers::parse_freq_hz;
use crate::k2::sim::inputs::{pin_name, Pin, Source, Wave};
use crate::k2::sm_map::{HscKind, HSC_MODE_INPUTS};
use crate::output::Outcome;
use crate::shell::lex::{self, Word};
use crate::shell::{Args, Shell};
use std::time::Duration;

const USAGE: &str = "sim input I0.1 freq=1kHz [dir=up|down] | sim input I0.1 off | sim quad A B freq=1kHz [dir=down] | sim inputs | sim retain VB0..VB99 MB0[8] | sim retain none";

fn pin(w: Word) -> Result<Pin> {
    let t = w.1.to_ascii_uppercase();
    let body = t.trim_start_matches('%').strip_prefix('I');
    body.and_then(|b| b.split_once('.'))
        .and_then(|(b, bit)| Some((b.parse().ok()?, bit.parse().ok().filter(|x: &u8| *x < 8)?)))
        .ok_or_else(|| value_err(w.0, crate::msg!("shell-not-an-input-bit", text = w.1)))
}

fn hz(opts: &[lex::Opt]) -> Result<u64> {
    let (c, f) = opt(opts, "freq").ok_or_else(|| Error::usage(crate::msg!("shell-signal-needs-freq")).hint(USAGE))?;
    let hz = parse_freq_hz(f).map_err(|m| value_err(c, m))?;
    if hz.fract() != 0.0 || hz > 10_000_000.0 {
        return Err(value_err(c, crate::msg!("shell-signal-freq", value = f)));
    }
    Ok(hz as u64)
}

pub fn run(sh: &mut Shell, sub: &str, args: Args) -> Result<Outcome> {
    let all: Vec<Word> = lex::words(args.text)?.into_iter().map(|(c, w)| (c + args.offset, w)).collect();
    let w = &all[1..];
    let (pos, opts) = lex::options(w);
    let dev = sh.session.current_index()?;
    let name = k2cmd::name(sh, dev);
    // The command as typed (`sim input`), for the simulator-only error.
    let command = format!("sim {sub}");
    let mut o = match sub {
        "inputs" => {
            if let Some(w) = args.text.split_whitespace().nth(1) {
                return Err(Error::usage(crate::msg!("shell-sim-inputs-alone", extra = w)).hint(USAGE));
            }
            let s = k2cmd::sim(sh, dev, &command)?;
            let list: Vec<String> = s.inputs.sources().iter().map(|s| s.describe()).collect();
            Outcome::new("sim")
                .text(if list.is_empty() { crate::msg!("shell-no-input-signals").text } else { list.join("\n") })
                .with("sources", &list)
        }
        "retain" => {
            let text: Vec<&str> = w.iter().map(|w| w.1).collect();
            // `none` is the whole list: a word beside it is refused at its own column, never
            // read as an operand named `none`.
            if let Some(at) = w.iter().position(|x| x.1.eq_ignore_ascii_case("none")).filter(|_| w.len() > 1) {
                let other = if at == 0 { w[1] } else { w[0] };
                return Err(Error::usage(crate::msg!("shell-retain-none-alone", extra = other.1))
                    .hint(crate::msg!("shell-hint-retain-forms"))
                    .column(other.0));
            }
            let s = k2cmd::sim(sh, dev, &command)?;
            if !text.is_empty() {
                // A range that is not an operand is named at its column.
                for x in w {
                    if !x.1.eq_ignore_ascii_case("none") {
                        s.space().parse_k2(x.1.trim_matches(',')).map_err(|e| e.column(x.0).device(&name))?;
                    }
                }
                s.set_retain(&text.join(" ")).map_err(|e| e.device(&name))?;
            }
            let list: Vec<String> = s
                .backup
                .retain
                .iter()
                .map(|r| format!("{}B{}..{}B{}", r.area.name(), r.first, r.area.name(), r.first + r.len - 1))
                .collect();
            Outcome::new("sim")
                .text(if list.is_empty() {
                    crate::msg!("shell-no-retained").text
                } else {
                    crate::msg!("shell-retained", ranges = list.join(" ")).text
                })
                .with("retain", &list)
        }
        "input" => {
            check_options(&opts, &["freq", "dir"], USAGE)?;
            let p = pin(*pos.first().ok_or_else(|| Error::usage(USAGE).column(args.offset))?)?;
            if pos.get(1).is_some_and(|w| w.1.eq_ignore_ascii_case("off")) {
                let s = k2cmd::sim(sh, dev, &command)?;
                let old = s.remove_source(p).map_err(|e| e.device(&name))?;
                Outcome::new("sim").text(crate::msg!("shell-signal-stopped", signal = old.describe()).text)
            } else {
                if let Some(x) = pos.get(1) {
                    return Err(Error::usage(crate::msg!("shell-unexpected", extra = x.1)).column(x.0).hint(USAGE));
                }
                let f = hz(&opts)?;
                let mut msg = String::new();
                if let Some((c, d)) = opt(&opts, "dir") {
                    let up = match d.to_ascii_lowercase().as_str() {
                        "up" => true,
                        "down" => false,
                        _ => return Err(value_err(c, crate::msg!("shell-hsc-dir", value = d))),
                    };
                    // The direction input paired with this count input (modes 3/4, §3.3.1).
                    let dir = HSC_MODE_INPUTS
                        .iter()
                        .find(|m| m.kind == HscKind::ExternalDir && m.count == p)
                        .and_then(|m| m.dir)
                        .ok_or_else(|| value_err(c, crate::msg!("shell-no-direction-input", input = pin_name(p))))?;
                    let op = crate::k2::operand::K2Operand::bit(crate::k2::operand::Area::I, dir.0, dir.1).to_core();
                    sh.session.write_values(dev, &[(op, Value::Bool(up))])?;
                    msg = crate::msg!("shell-direction-input", input = pin_name(dir), value = u8::from(up)).text;
                }
                let s = k2cmd::sim(sh, dev, &command)?;
                let d = s
                    .add_source(Source::Freq { pin: p, wave: Wave::new(f, Duration::ZERO) })
                    .map_err(|e| e.device(&name))?;
                Outcome::new("sim").text(format!("{d}{msg}"))
            }
        }
        "quad" => {
            check_options(&opts, &["freq", "dir"], USAGE)?;
            if pos.len() != 2 {
                return Err(Error::usage(crate::msg!("shell-quad-needs-two")).column(args.offset).hint(USAGE));
            }
            let (mut a, mut b) = (pin(pos[0])?, pin(pos[1])?);
            if a == b {
                return Err(value_err(pos[1].0, crate::msg!("shell-quad-same-input")));
            }
            if let Some((c, d)) = opt(&opts, "dir") {
                match d.to_ascii_lowercase().as_str() {
                    "up" => {}
                    "down" => std::mem::swap(&mut a, &mut b),
                    _ => return Err(value_err(c, crate::msg!("shell-quad-dir", value = d))),
                }
            }
            let f = hz(&opts)?;
            let s = k2cmd::sim(sh, dev, &command)?;
            let d = s
                .add_source(Source::Quad { lead: a, lag: b, wave: Wave::new(f, Duration::ZERO) })
                .map_err(|e| e.device(&name))?;
            Outcome::new("sim").text(d)
        }
        _ => unreachable!("dispatched by sim.rs"),
    };
    o.device = Some(name);
    Ok(o)
}
