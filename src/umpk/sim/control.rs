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
use serde_json::{json, Value as Json};

/// The control words, for messages.
pub const WORDS: &str = "input I3=1|I3=0|I3 freq=2Hz | inputs | flash-fail PAGE|off | fault no-reply [for=D] | fault stuck I3=1 [for=D] | fault clear | faults | events";

fn usage(msg: impl Into<crate::core::error::Text>) -> Error {
    Error::usage(msg).hint(format!("control words: {WORDS}"))
}

fn input_of(u: &Umpk, text: &str) -> Result<u8> {
    parse_input(u.model, u.model.inputs, text)
}

fn parse_input(model: &crate::umpk::model::Model, inputs: u8, text: &str) -> Result<u8> {
    let t = text.trim();
    let n = t
        .strip_prefix(['I', 'i'])
        .and_then(|d| d.parse::<u8>().ok())
        .ok_or_else(|| usage(format!("`{t}` is not an input (I0…I{})", inputs - 1)))?;
    if n >= inputs {
        return Err(usage(format!("I{n} is not an input of the {} (I0…I{})", model.name, inputs - 1)));
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
            let first = words.get(1).ok_or_else(|| usage("input needs an input and a level: input I3=1"))?;
            let (op, value) = match first.split_once('=') {
                Some((o, v)) => (o, Some(v).filter(|v| !v.is_empty())),
                None => (*first, words.get(2).copied().filter(|w| !w.contains('='))),
            };
            let i = input_of(u, op)?;
            let opts: Vec<&str> = words[2..].iter().copied().filter(|w| w.contains('=')).collect();
            let extra: Vec<&str> =
                words[2..].iter().copied().filter(|w| !w.contains('=') && Some(*w) != value).collect();
            if let Some(w) = extra.first() {
                return Err(usage(format!("`{w}` after input I{i} is not understood")));
            }
            if let Some(f) = opts.iter().find_map(|o| o.strip_prefix("freq=")) {
                if value.is_some() {
                    return Err(usage("give a level or freq=, not both"));
                }
                let hz = crate::core::literal::parse_freq_hz(f).map_err(usage)?;
                let period = (1000.0 / hz / CYCLE_MS as f64).round();
                if !(2.0..=1_000_000.0).contains(&period) {
                    return Err(usage(format!("freq={f}: the 10 ms cycle sees square waves of 0.0001–50 Hz")));
                }
                u.set_wave(i, period as u64);
                return Ok((
                    format!("I{i}: square wave, period {} ms", period as u64 * CYCLE_MS),
                    json!({"input": i, "period_ms": period as u64 * CYCLE_MS, "time_us": now_us}),
                ));
            }
            if let Some(o) = opts.first() {
                return Err(usage(format!("`{o}` is not an input option (freq=)")));
            }
            let on = level(value.ok_or_else(|| usage(format!("I{i}: give =1, =0 or freq=…")))?)?;
            u.set_input(i, on);
            Ok((format!("I{i} = {}", on as u8), json!({"input": i, "value": on, "time_us": now_us})))
        }
        Some("inputs") => {
            if let Some(w) = words.get(1) {
                return Err(usage(format!("`inputs` takes nothing after it (got `{w}`)")));
            }
            let waves: Vec<Json> =
                u.waves.iter().map(|w| json!({"input": w.input, "period_ms": w.period * CYCLE_MS})).collect();
            let text = format!(
                "inputs {:0width$b} (I{}…I0); square waves on {}",
                u.image.inputs,
                u.model.inputs - 1,
                if waves.is_empty() {
                    "none".to_string()
                } else {
                    u.waves.iter().map(|w| format!("I{}", w.input)).collect::<Vec<_>>().join(", ")
                },
                width = u.model.inputs as usize
            );
            Ok((text, json!({"inputs": u.image.inputs, "waves": waves, "time_us": now_us})))
        }
        Some("flash-fail") => {
            let page = match words.get(1).copied() {
                Some("off") => None,
                Some(p) => Some(p.parse::<usize>().map_err(|_| usage(format!("`{p}` is not a page number")))?),
                None => return Err(usage("flash-fail PAGE|off")),
            };
            u.fail_flash_page(page)?;
            let text = match page {
                Some(p) => {
                    format!("flash writes to page {p} (16#{:04X}) will fail with W", p * crate::umpk::model::PAGE)
                }
                None => "flash writes succeed".into(),
            };
            Ok((text, json!({"flash_fail": page, "time_us": now_us})))
        }
        Some(other) => Err(usage(format!("`{other}` is not a control word of a simulated UMPK"))),
        None => Err(usage("an empty control line")),
    }
}
