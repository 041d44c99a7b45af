//! The simulated FX PLC's control language: the switches wired to its X inputs and the
//! faults of its line, while clients use its programming port and computer link. One grammar
//! with the other families' (`input …`, `fault no-reply|stuck …`, `faults`, `events`), through
//! the served PLC's control channel (`plcsh sim serve --fx-pty LINK` → `LINK.ctl`, or
//! `--fx-control PATH`; [`crate::core::link::control`]).
//!
//! ```text
//! input X0=1 | input X17=0        an input switched (octal numbers, as FX inputs are)
//! inputs                          the X inputs that are on
//! fault no-reply [for=DURATION]   both ports silent (a pulled cable, a hung PLC)
//! fault stuck X3=1 [for=DURATION] an input held at a level, whatever drives it
//! fault clear [ID] | faults | events
//! ```
//!
//! A program sees a switched or stuck input from its next scan (input refresh).

use super::memory::Memory;
use super::model::Model;
use super::operand::{parse_one, Area, FxOperand, Width};
use crate::core::sim_faults;
use crate::core::{Error, Result};
use serde_json::{json, Value as Json};

/// The control words, for messages.
pub const WORDS: &str =
    "input X0=1|X0=0 | inputs | fault no-reply [for=D] | fault stuck X0=1 [for=D] | fault clear [ID] | faults | events";

fn usage(msg: impl Into<crate::core::error::Text>) -> Error {
    Error::usage(msg).hint(format!("control words: {WORDS}"))
}

/// An X input of the PLC's model: its number and canonical name.
fn input(model: &Model, text: &str) -> Result<(u16, String)> {
    let o = parse_one(text.trim()).map_err(|e| usage(e.message.clone()))?;
    if o.area != Area::X || !matches!(o.width, Width::Bit) {
        return Err(usage(format!("`{}` is not an X input (X0, X17 …)", text.trim())));
    }
    if o.index >= model.x {
        let last = FxOperand::number_text(Area::X, model.x - 1);
        return Err(usage(format!("{} is not an input of the {} (X0–X{last})", o.canonical(), model.name)));
    }
    Ok((o.index, o.canonical()))
}

/// Applies one control line to the PLC at its clock's time.
pub fn answer(mem: &mut Memory, text: &str) -> Result<(String, Json)> {
    mem.advance();
    let now = mem.cpu.clock.now();
    let now_us = now.as_micros() as u64;
    let words: Vec<&str> = text.split_whitespace().collect();
    let model = mem.model;
    if let Some(r) = mem.faults.control(&words, now, |t| input(model, t), WORDS) {
        return r;
    }
    match words.first().map(|w| w.to_ascii_lowercase()).as_deref() {
        Some("input") => {
            let spec = words.get(1).ok_or_else(|| usage("input needs an input and a level: input X0=1"))?;
            if let Some(w) = words.get(2) {
                return Err(usage(format!("`{w}` after input {spec} is not understood")));
            }
            let (op, v) = spec.split_once('=').ok_or_else(|| usage(format!("`{spec}`: write input {spec}=1 or =0")))?;
            let (i, name) = input(mem.model, op)?;
            let on = sim_faults::level(v, WORDS)?;
            mem.set_input(i, on);
            Ok((format!("{name} = {}", on as u8), json!({"input": name, "value": on, "time_us": now_us})))
        }
        Some("inputs") => {
            if let Some(w) = words.get(1) {
                return Err(usage(format!("`inputs` takes nothing after it (got `{w}`)")));
            }
            let on: Vec<String> = (0..mem.model.x)
                .filter(|i| mem.bit(Area::X, *i) == Some(true))
                .map(|i| format!("X{}", FxOperand::number_text(Area::X, i)))
                .collect();
            let text = if on.is_empty() { "no X input is on".to_string() } else { format!("on: {}", on.join(" ")) };
            Ok((text, json!({"on": on, "time_us": now_us})))
        }
        Some(other) => Err(usage(format!("`{other}` is not a control word of a simulated FX PLC"))),
        None => Err(usage("an empty control line")),
    }
}
