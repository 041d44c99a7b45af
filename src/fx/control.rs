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
use crate::msg;
use serde_json::{json, Value as Json};

/// The control words, for messages.
pub const WORDS: &str =
    "input X0=1|X0=0 | inputs | fault no-reply [for=D] | fault stuck X0=1 [for=D] | fault clear [ID] | faults | events";

fn usage(msg: impl Into<crate::core::error::Text>) -> Error {
    Error::usage(msg).hint(msg!("umpk-sim-hint-words", words = WORDS))
}

/// An X input of the PLC's model: its number and canonical name.
fn input(model: &Model, text: &str) -> Result<(u16, String)> {
    let o = parse_one(text.trim()).map_err(|e| usage(e.message.clone()))?;
    if o.area != Area::X || !matches!(o.width, Width::Bit) {
        return Err(usage(msg!("fx-sim-not-x", text = text.trim())));
    }
    if o.index >= model.x {
        let last = FxOperand::number_text(Area::X, model.x - 1);
        return Err(usage(msg!("fx-sim-no-such-input", operand = o.canonical(), model = model.name, last = last)));
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
            let spec = words.get(1).ok_or_else(|| usage(msg!("fx-sim-input-usage")))?;
            if let Some(w) = words.get(2) {
                return Err(usage(msg!("fx-sim-input-extra", word = *w, input = *spec)));
            }
            let (op, v) = spec.split_once('=').ok_or_else(|| usage(msg!("fx-sim-input-level", input = *spec)))?;
            let (i, name) = input(mem.model, op)?;
            let on = sim_faults::level(v, WORDS)?;
            mem.set_input(i, on);
            Ok((format!("{name} = {}", on as u8), json!({"input": name, "value": on, "time_us": now_us})))
        }
        Some("inputs") => {
            if let Some(w) = words.get(1) {
                return Err(usage(msg!("umpk-sim-inputs-extra", word = *w)));
            }
            let on: Vec<String> = (0..mem.model.x)
                .filter(|i| mem.bit(Area::X, *i) == Some(true))
                .map(|i| format!("X{}", FxOperand::number_text(Area::X, i)))
                .collect();
            let text = if on.is_empty() {
                msg!("fx-sim-inputs-none").text
            } else {
                msg!("fx-sim-inputs-on", inputs = on.join(" ")).text
            };
            Ok((text, json!({"on": on, "time_us": now_us})))
        }
        Some(other) => Err(usage(msg!("fx-sim-not-word", word = other))),
        None => Err(usage(msg!("umpk-sim-empty-line"))),
    }
}
