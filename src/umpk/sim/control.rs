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
use crate::core::literal::parse_option_duration_us;
use crate::core::{Error, Result};
use serde_json::{json, Value as Json};
use std::time::Duration;

/// The control words, for messages.
pub const WORDS: &str = "input I3=1|I3=0|I3 freq=2Hz | inputs | flash-fail PAGE|off | fault no-reply [for=D] | fault stuck I3=1 [for=D] | fault clear | faults | events";

/// What an injected UMPK fault does.
#[derive(Clone, Copy, Debug, PartialEq, Eq, serde::Serialize)]
#[serde(tag = "kind", rename_all = "snake_case")]
pub enum FaultKind {
    /// Received bytes are ignored: no echo, no reply (a dead line or a hung controller).
    NoReply,
    /// Input `input` reads `on` whatever drives it.
    Stuck { input: u8, on: bool },
}

/// One injected fault, its window in virtual time.
#[derive(Clone, Debug, PartialEq, serde::Serialize)]
pub struct Fault {
    pub id: u32,
    #[serde(flatten)]
    pub kind: FaultKind,
    pub from_us: u64,
    pub until_us: Option<u64>,
}

impl Fault {
    pub fn active(&self, now: Duration) -> bool {
        let t = now.as_micros() as u64;
        t >= self.from_us && self.until_us.is_none_or(|u| t < u)
    }

    fn describe(&self) -> String {
        let what = match self.kind {
            FaultKind::NoReply => "no-reply".to_string(),
            FaultKind::Stuck { input, on } => format!("stuck I{input}={}", on as u8),
        };
        let until = self.until_us.map_or(" until cleared".to_string(), |u| format!(" until {:.3} s", u as f64 / 1e6));
        format!("fault {}: {what} from {:.3} s{until}", self.id, self.from_us as f64 / 1e6)
    }
}

/// The faults set on one simulated UMPK, and when each started acting.
#[derive(Clone, Debug, Default)]
pub struct Faults {
    pub list: Vec<Fault>,
    next: u32,
    /// `(virtual time µs, fault id, what)` of every fault that started acting.
    pub log: Vec<(u64, u32, &'static str)>,
}

impl Faults {
    /// True while a no-reply fault holds at `now`.
    pub fn mute(&self, now: Duration) -> bool {
        self.list.iter().any(|f| f.kind == FaultKind::NoReply && f.active(now))
    }

    /// Applies stuck inputs to an input word at `now`.
    pub fn inputs(&self, mut word: u32, now: Duration) -> u32 {
        for f in self.list.iter().filter(|f| f.active(now)) {
            if let FaultKind::Stuck { input, on } = f.kind {
                word = word & !(1 << input) | (on as u32) << input;
            }
        }
        word
    }
}

fn usage(msg: impl Into<String>) -> Error {
    Error::usage(msg).hint(format!("control words: {WORDS}"))
}

fn input_of(u: &Umpk, text: &str) -> Result<u8> {
    let t = text.trim();
    let n = t
        .strip_prefix(['I', 'i'])
        .and_then(|d| d.parse::<u8>().ok())
        .ok_or_else(|| usage(format!("`{t}` is not an input (I0…I{})", u.model.inputs - 1)))?;
    if n >= u.model.inputs {
        return Err(usage(format!("I{n} is not an input of the {} (I0…I{})", u.model.name, u.model.inputs - 1)));
    }
    Ok(n)
}

fn level(text: &str) -> Result<bool> {
    match text.to_ascii_lowercase().as_str() {
        "1" | "on" | "true" => Ok(true),
        "0" | "off" | "false" => Ok(false),
        v => Err(usage(format!("`{v}` is not a level (1, 0, on, off)"))),
    }
}

fn for_window(words: &[&str]) -> Result<Option<Duration>> {
    let mut d = None;
    for w in words {
        match w.split_once('=') {
            Some(("for", v)) => {
                let us = parse_option_duration_us(v).map_err(|m| usage(format!("for={v}: {m}")))?;
                let us = u64::try_from(us).map_err(|_| usage(format!("for={v}: must not be negative")))?;
                d = Some(Duration::from_micros(us));
            }
            _ => return Err(usage(format!("`{w}` is not an option here (for=DURATION)"))),
        }
    }
    Ok(d)
}

/// Applies one control line to `u` at its clock's time: the text for people, the data for JSON.
pub fn answer(u: &mut Umpk, text: &str) -> Result<(String, Json)> {
    let now = u.clock.now();
    u.advance(now);
    let words: Vec<&str> = text.split_whitespace().collect();
    let now_us = now.as_micros() as u64;
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
                let hz = crate::k2::helpers::parse_freq_hz(f).map_err(usage)?;
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
            u.flash_fail = page;
            let text = match page {
                Some(p) => format!("flash writes to page {p} (16#{:04X}) will fail with W", p * 64),
                None => "flash writes succeed".into(),
            };
            Ok((text, json!({"flash_fail": page, "time_us": now_us})))
        }
        Some("faults") => {
            let list: Vec<String> = u.faults.list.iter().map(Fault::describe).collect();
            let text = if list.is_empty() { "no injected faults".into() } else { list.join("\n") };
            Ok((text, json!({"faults": u.faults.list, "time_us": now_us})))
        }
        Some("events") => {
            let ev: Vec<Json> =
                u.faults.log.iter().map(|(t, id, what)| json!({"id": id, "fault": what, "time_us": t})).collect();
            let text = if ev.is_empty() {
                "no injected fault has acted".to_string()
            } else {
                u.faults
                    .log
                    .iter()
                    .map(|(t, id, what)| format!("{:.6} s: fault {id} ({what}) acted", *t as f64 / 1e6))
                    .collect::<Vec<_>>()
                    .join("\n")
            };
            Ok((text, json!({"events": ev, "time_us": now_us})))
        }
        Some("fault") => {
            let kind = words.get(1).map(|w| w.to_ascii_lowercase());
            match kind.as_deref() {
                Some("clear") => {
                    let n = match words.get(2).copied() {
                        None | Some("all") => {
                            let n = u.faults.list.len();
                            u.faults.list.clear();
                            n
                        }
                        Some(id) => {
                            let id: u32 = id.parse().map_err(|_| usage(format!("`{id}` is not a fault id")))?;
                            let before = u.faults.list.len();
                            u.faults.list.retain(|f| f.id != id);
                            if before == u.faults.list.len() {
                                return Err(Error::usage(format!("there is no fault {id}")).hint("`faults` lists them"));
                            }
                            1
                        }
                    };
                    u.refresh_inputs();
                    Ok((format!("cleared {n} fault(s)"), json!({"cleared": n, "time_us": now_us})))
                }
                Some("no-reply") => add(u, FaultKind::NoReply, for_window(&words[2..])?, now),
                Some("stuck") => {
                    let spec =
                        words.get(2).ok_or_else(|| usage("fault stuck needs an input and a level: stuck I3=1"))?;
                    let (op, v) = spec
                        .split_once('=')
                        .ok_or_else(|| usage(format!("`{spec}`: write stuck I3=1 or stuck I3=0")))?;
                    let kind = FaultKind::Stuck { input: input_of(u, op)?, on: level(v)? };
                    add(u, kind, for_window(&words[3..])?, now)
                }
                Some(other) => Err(usage(format!("`{other}` is not a fault of a simulated UMPK (no-reply, stuck)"))),
                None => Err(usage("which fault? fault no-reply | fault stuck I3=1")),
            }
        }
        Some(other) => Err(usage(format!("`{other}` is not a control word of a simulated UMPK"))),
        None => Err(usage("an empty control line")),
    }
}

fn add(u: &mut Umpk, kind: FaultKind, window: Option<Duration>, now: Duration) -> Result<(String, Json)> {
    u.faults.next += 1;
    let from = now.as_micros() as u64;
    let f = Fault { id: u.faults.next, kind, from_us: from, until_us: window.map(|d| from + d.as_micros() as u64) };
    let name = match kind {
        FaultKind::NoReply => "no-reply",
        FaultKind::Stuck { .. } => "stuck",
    };
    u.faults.log.push((from, f.id, name));
    let text = f.describe();
    let data = json!({"id": f.id, "fault": f, "time_us": from});
    u.faults.list.push(f);
    u.refresh_inputs();
    Ok((text, data))
}
