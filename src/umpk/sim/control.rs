//! The simulated UMPK's control language: what a lab bench's switches, signal generator and
//! broken cables do to the controller, in one grammar with two ways in — `umpk sim …` /
//! `sim input …` in the shell on an in-process simulator (`sim-umpk:`), and the control
//! channel of a served one (`plcsh sim serve --umpk-pty LINK` → `LINK.ctl`, or
//! `--umpk-control PATH`; [`crate::core::link::control`]), so the lab's own PC software on
//! the served line sees inputs change while a teacher or a test steers them.
//!
//! ```text
//! input I3=1 | input I3=0 | input I3 freq=2Hz      a switch, or a square wave (10 ms cycle)
//! inputs                                           levels, waves and stuck inputs
//! flash-fail PAGE | flash-fail off                 a flash page whose write fails (W)
//! fault no-reply [for=DURATION]                    the controller ignores its line
//! fault stuck I3=1 [for=DURATION]                  an input held at a level
//! fault clear | faults | events
//! ```
//!
//! Faults use the K2's words (`sim fault`): a window from now, `for=` long (until cleared
//! without it), logged with its virtual time when it starts acting.

use super::{Umpk, CYCLE_MS};
use crate::core::sim_faults;
use crate::core::{Error, Result};
use crate::msg;
use serde_json::{json, Value as Json};

/// The control words, for messages.
pub const WORDS: &str = "input I3=1|I3=0|I3 freq=2Hz | inputs | flash-fail PAGE|off | fault no-reply [for=D] | fault stuck I3=1 [for=D] | fault clear | faults | events";

fn usage(msg: impl Into<crate::core::error::Text>) -> Error {
    Error::usage(msg).hint(msg!("umpk-sim-hint-words", words = WORDS))
}

fn input_of(u: &Umpk, text: &str) -> Result<u8> {
    parse_input(u.model, u.model.inputs, text)
}

fn parse_input(model: &crate::umpk::model::Model, inputs: u8, text: &str) -> Result<u8> {
    let t = text.trim();
    let n = t
        .strip_prefix(['I', 'i'])
        .and_then(|d| d.parse::<u8>().ok())
        .ok_or_else(|| usage(msg!("umpk-sim-not-input", text = t, last = inputs - 1)))?;
    if n >= inputs {
        return Err(usage(msg!("umpk-sim-no-such-input", n = n, model = model.name, last = inputs - 1)));
    }
    Ok(n)
}

fn level(text: &str) -> Result<bool> {
    sim_faults::level(text, WORDS)
}

/// Applies one control line to `u` at its clock's time: the text for people, the data for JSON.
pub fn answer(u: &mut Umpk, text: &str) -> Result<(String, Json)> {
    let now = u.clock.now();
    u.advance(now);
    let words: Vec<&str> = text.split_whitespace().collect();
    let now_us = now.as_micros() as u64;
    let (model, inputs) = (u.model, u.model.inputs);
    let input = |t: &str| -> Result<(u16, String)> {
        let n = parse_input(model, inputs, t)?;
        Ok((u16::from(n), format!("I{n}")))
    };
    if let Some(r) = u.faults.control(&words, now, input, WORDS) {
        u.refresh_inputs();
        return r;
    }
    match words.first().map(|w| w.to_ascii_lowercase()).as_deref() {
        Some("input") => {
            let first = words.get(1).ok_or_else(|| usage(msg!("umpk-sim-input-usage")))?;
            let (op, value) = match first.split_once('=') {
                Some((o, v)) => (o, Some(v).filter(|v| !v.is_empty())),
                None => (*first, words.get(2).copied().filter(|w| !w.contains('='))),
            };
            let i = input_of(u, op)?;
            let opts: Vec<&str> = words[2..].iter().copied().filter(|w| w.contains('=')).collect();
            let extra: Vec<&str> =
                words[2..].iter().copied().filter(|w| !w.contains('=') && Some(*w) != value).collect();
            if let Some(w) = extra.first() {
                return Err(usage(msg!("umpk-sim-input-extra", word = *w, n = i)));
            }
            if let Some(f) = opts.iter().find_map(|o| o.strip_prefix("freq=")) {
                if value.is_some() {
                    return Err(usage(msg!("umpk-sim-level-and-freq")));
                }
                let hz = crate::core::literal::parse_freq_hz(f).map_err(usage)?;
                let period = (1000.0 / hz / CYCLE_MS as f64).round();
                if !(2.0..=1_000_000.0).contains(&period) {
                    return Err(usage(msg!("umpk-sim-freq-range", freq = f)));
                }
                u.set_wave(i, period as u64);
                return Ok((
                    msg!("umpk-sim-wave-set", n = i, period = period as u64 * CYCLE_MS).text,
                    json!({"input": i, "period_ms": period as u64 * CYCLE_MS, "time_us": now_us}),
                ));
            }
            if let Some(o) = opts.first() {
                return Err(usage(msg!("umpk-sim-not-input-option", option = *o)));
            }
            let on = level(value.ok_or_else(|| usage(msg!("umpk-sim-level-missing", n = i)))?)?;
            u.set_input(i, on);
            Ok((format!("I{i} = {}", on as u8), json!({"input": i, "value": on, "time_us": now_us})))
        }
        Some("inputs") => {
            if let Some(w) = words.get(1) {
                return Err(usage(msg!("umpk-sim-inputs-extra", word = *w)));
            }
            let waves: Vec<Json> =
                u.waves.iter().map(|w| json!({"input": w.input, "period_ms": w.period * CYCLE_MS})).collect();
            let bits = format!("{:0width$b}", u.image.inputs, width = u.model.inputs as usize);
            let last = u.model.inputs - 1;
            let text = if waves.is_empty() {
                msg!("umpk-sim-inputs-no-waves", bits = bits, last = last)
            } else {
                let on = u.waves.iter().map(|w| format!("I{}", w.input)).collect::<Vec<_>>().join(", ");
                msg!("umpk-sim-inputs", bits = bits, last = last, waves = on)
            }
            .text;
            Ok((text, json!({"inputs": u.image.inputs, "waves": waves, "time_us": now_us})))
        }
        Some("flash-fail") => {
            let page = match words.get(1).copied() {
                Some("off") => None,
                Some(p) => Some(p.parse::<usize>().map_err(|_| usage(msg!("umpk-sim-not-page", page = p)))?),
                None => return Err(usage("flash-fail PAGE|off")),
            };
            u.fail_flash_page(page)?;
            let text = match page {
                Some(p) => {
                    msg!("umpk-sim-flash-fail", page = p, address = format!("{:04X}", p * crate::umpk::model::PAGE))
                        .text
                }
                None => msg!("umpk-sim-flash-ok").text,
            };
            Ok((text, json!({"flash_fail": page, "time_us": now_us})))
        }
        Some(other) => Err(usage(msg!("umpk-sim-not-word", word = other))),
        None => Err(usage(msg!("umpk-sim-empty-line"))),
    }
}
