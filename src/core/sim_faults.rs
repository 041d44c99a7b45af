//! Faults a served simulator's control channel injects for the families that have no fault
//! model of their own richer than this (the UMPK teaching PLC, FX PLCs): a silent line and
//! stuck inputs, each in a window of virtual time, logged when it starts acting. One grammar
//! with the K2's `sim fault` words (`no-reply`, `stuck IN=1`, `for=`, `fault clear`,
//! `faults`, `events`), so a teacher or a test steers every family the same way.
//!
//! The family parses its own input names (`I3` on a UMPK, octal `X17` on an FX) and applies
//! [`Faults::mute`] to its line and [`Faults::stuck`] to its input image.

use crate::core::literal::parse_option_duration_us;
use crate::core::{Error, Result};
use crate::msg;
use serde_json::{json, Value as Json};
use std::time::Duration;

/// The fault words, for messages.
pub const WORDS: &str = "fault no-reply [for=D] | fault stuck IN=1 [for=D] | fault clear [ID] | faults | events";

/// What an injected fault does.
#[derive(Clone, Debug, PartialEq, Eq, serde::Serialize, serde::Deserialize)]
#[serde(tag = "kind", rename_all = "snake_case")]
pub enum FaultKind {
    /// Received bytes are ignored: no echo, no reply (a dead line or a hung controller).
    NoReply,
    /// Input number `input` (named `name`) reads `on` whatever drives it.
    Stuck { input: u16, name: String, on: bool },
}

impl FaultKind {
    fn name(&self) -> &'static str {
        match self {
            FaultKind::NoReply => "no-reply",
            FaultKind::Stuck { .. } => "stuck",
        }
    }
}

/// One injected fault, its window in virtual time.
#[derive(Clone, Debug, PartialEq, serde::Serialize, serde::Deserialize)]
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
        let what = match &self.kind {
            FaultKind::NoReply => "no-reply".to_string(),
            FaultKind::Stuck { name, on, .. } => format!("stuck {name}={}", *on as u8),
        };
        let from = format!("{:.3}", self.from_us as f64 / 1e6);
        match self.until_us {
            None => msg!("sim-fault-describe", id = self.id, what = what, from = from).into(),
            Some(u) => msg!(
                "sim-fault-describe-until",
                id = self.id,
                what = what,
                from = from,
                until = format!("{:.3}", u as f64 / 1e6)
            )
            .into(),
        }
    }
}

/// The faults set on one simulator, and when each started acting. A snapshot keeps all of
/// it (the UMPK's and the FX PLC's sections), so a restored simulator holds the same inputs
/// stuck, stays silent for the rest of a window and numbers its next fault alike.
#[derive(Clone, Debug, Default, PartialEq, serde::Serialize, serde::Deserialize)]
pub struct Faults {
    pub list: Vec<Fault>,
    /// The id of the last fault set.
    next: u32,
    /// `(virtual time µs, fault id, what)` of every fault that started acting.
    pub log: Vec<(u64, u32, String)>,
}

fn usage(msg: impl Into<crate::core::error::Text>, words: &str) -> Error {
    Error::usage(msg).hint(msg!("sim-control-words-hint", words = words))
}

/// `1`, `on`, `true` / `0`, `off`, `false`.
pub fn level(text: &str, words: &str) -> Result<bool> {
    match text.to_ascii_lowercase().as_str() {
        "1" | "on" | "true" => Ok(true),
        "0" | "off" | "false" => Ok(false),
        v => Err(usage(msg!("sim-not-level", value = v), words)),
    }
}

fn for_window(words: &[&str], all: &str) -> Result<Option<Duration>> {
    let mut d = None;
    for w in words {
        match w.split_once('=') {
            Some(("for", v)) => {
                let us = parse_option_duration_us(v).map_err(|m| usage(format!("for={v}: {m}"), all))?;
                let us =
                    u64::try_from(us).map_err(|_| usage(msg!("k2-fault-negative", key = "for", value = v), all))?;
                d = Some(Duration::from_micros(us));
            }
            _ => return Err(usage(msg!("sim-not-option-here", word = *w), all)),
        }
    }
    Ok(d)
}

impl Faults {
    /// True while a no-reply fault holds at `now`.
    pub fn mute(&self, now: Duration) -> bool {
        self.list.iter().any(|f| f.kind == FaultKind::NoReply && f.active(now))
    }

    /// The inputs held at a level at `now`: `(input number, level)`.
    pub fn stuck(&self, now: Duration) -> impl Iterator<Item = (u16, bool)> + '_ {
        self.list.iter().filter(move |f| f.active(now)).filter_map(|f| match f.kind {
            FaultKind::Stuck { input, on, .. } => Some((input, on)),
            FaultKind::NoReply => None,
        })
    }

    /// Answers `fault …`, `faults` and `events` (`words` split, the first one of them);
    /// `None` for any other word. `input` turns an input's name into its number and its
    /// canonical name; `all` names every control word of the family, for messages.
    pub fn control(
        &mut self,
        words: &[&str],
        now: Duration,
        input: impl Fn(&str) -> Result<(u16, String)>,
        all: &str,
    ) -> Option<Result<(String, Json)>> {
        let now_us = now.as_micros() as u64;
        let r = match words.first().map(|w| w.to_ascii_lowercase()).as_deref() {
            Some("faults") => match words.get(1) {
                Some(w) => Err(usage(msg!("sim-word-takes-nothing", word = "faults", rest = *w), all)),
                None => {
                    let list: Vec<String> = self.list.iter().map(Fault::describe).collect();
                    let text = if list.is_empty() { msg!("sim-no-faults").into() } else { list.join("\n") };
                    Ok((text, json!({"faults": self.list, "time_us": now_us})))
                }
            },
            Some("events") => match words.get(1) {
                Some(w) => Err(usage(msg!("sim-word-takes-nothing", word = "events", rest = *w), all)),
                None => {
                    let ev: Vec<Json> =
                        self.log.iter().map(|(t, id, what)| json!({"id": id, "fault": what, "time_us": t})).collect();
                    let text = if ev.is_empty() {
                        msg!("sim-no-fault-acted").into()
                    } else {
                        self.log
                            .iter()
                            .map(|(t, id, what)| {
                                msg!(
                                    "sim-fault-acted",
                                    seconds = format!("{:.6}", *t as f64 / 1e6),
                                    id = id.to_string(),
                                    name = what
                                )
                                .into()
                            })
                            .collect::<Vec<String>>()
                            .join("\n")
                    };
                    Ok((text, json!({"events": ev, "time_us": now_us})))
                }
            },
            Some("fault") => self.fault(&words[1..], now, input, all),
            _ => return None,
        };
        Some(r)
    }

    fn fault(
        &mut self,
        words: &[&str],
        now: Duration,
        input: impl Fn(&str) -> Result<(u16, String)>,
        all: &str,
    ) -> Result<(String, Json)> {
        let now_us = now.as_micros() as u64;
        match words.first().map(|w| w.to_ascii_lowercase()).as_deref() {
            Some("clear") => {
                let n = match words.get(1).copied() {
                    None | Some("all") => std::mem::take(&mut self.list).len(),
                    Some(id) => {
                        let id: u32 = id.parse().map_err(|_| usage(msg!("sim-not-fault-id", text = id), all))?;
                        let before = self.list.len();
                        self.list.retain(|f| f.id != id);
                        if before == self.list.len() {
                            return Err(
                                Error::usage(msg!("sim-no-such-fault", id = id)).hint(msg!("sim-no-such-fault-hint"))
                            );
                        }
                        1
                    }
                };
                Ok((msg!("sim-faults-cleared", n = n).into(), json!({"cleared": n, "time_us": now_us})))
            }
            Some("no-reply") => self.add(FaultKind::NoReply, for_window(&words[1..], all)?, now),
            Some("stuck") => {
                let spec = words.get(1).ok_or_else(|| usage(msg!("sim-stuck-needs-input"), all))?;
                let (op, v) = spec.split_once('=').ok_or_else(|| usage(msg!("sim-stuck-shape", spec = *spec), all))?;
                let (n, name) = input(op)?;
                let kind = FaultKind::Stuck { input: n, name, on: level(v, all)? };
                self.add(kind, for_window(&words[2..], all)?, now)
            }
            Some(other) => Err(usage(msg!("sim-not-fault-here", kind = other), all)),
            None => Err(usage(msg!("sim-which-fault"), all)),
        }
    }

    fn add(&mut self, kind: FaultKind, window: Option<Duration>, now: Duration) -> Result<(String, Json)> {
        self.next += 1;
        let from = now.as_micros() as u64;
        let f = Fault { id: self.next, kind, from_us: from, until_us: window.map(|d| from + d.as_micros() as u64) };
        self.log.push((from, f.id, f.kind.name().to_string()));
        let text = f.describe();
        let data = json!({"id": f.id, "fault": f, "time_us": from});
        self.list.push(f);
        Ok((text, data))
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn input(t: &str) -> Result<(u16, String)> {
        t.strip_prefix('I').and_then(|d| d.parse().ok()).map(|n| (n, format!("I{n}"))).ok_or_else(|| Error::usage("no"))
    }

    fn w(t: &str) -> Vec<&str> {
        t.split_whitespace().collect()
    }

    #[test]
    fn windows_mute_and_stuck_inputs_in_virtual_time() {
        let mut f = Faults::default();
        let s = Duration::from_secs;
        f.control(&w("fault no-reply for=2s"), s(1), input, WORDS).unwrap().unwrap();
        f.control(&w("fault stuck I3=1"), s(1), input, WORDS).unwrap().unwrap();
        assert!(!f.mute(s(0)) && f.mute(s(2)) && !f.mute(s(3)));
        assert_eq!(f.stuck(s(5)).collect::<Vec<_>>(), vec![(3, true)]);
        let (_, ev) = f.control(&w("events"), s(5), input, WORDS).unwrap().unwrap();
        assert_eq!(ev["events"].as_array().unwrap().len(), 2);
        assert!(f.control(&w("fault stuck I3"), s(5), input, WORDS).unwrap().is_err());
        assert!(f.control(&w("fault clear 9"), s(5), input, WORDS).unwrap().is_err());
        assert_eq!(f.control(&w("fault clear"), s(5), input, WORDS).unwrap().unwrap().1["cleared"], 2);
        assert!(f.control(&w("input I3=1"), s(5), input, WORDS).is_none());
    }
}
