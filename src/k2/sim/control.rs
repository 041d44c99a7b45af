//! The simulated K2's control language — one grammar, two ways in. The shell's `sim fault …`,
//! `sim faults` and `sim events` apply it to an in-process simulator (`sim:MODEL`); a served
//! K2 (`plcsh sim serve --tcp … --k2-control PATH`, or `LINK.ctl` beside `--rtu-pty LINK`)
//! takes the same words on its control channel ([`crate::core::link::control`]) while
//! clients poll it, and a `tcp://…?control=PATH` device forwards `sim fault …` there.
//!
//! ```text
//! fault KIND … [on OPERANDS] [at=TIME|after=DURATION] [for=DURATION] [times=N]
//! fault clear [ID|all]
//! faults                      the faults set, with how often each acted
//! events                      the fault event log: which fault acted, when (virtual time)
//! ```
//!
//! `KIND` is the grammar of [`super::fault`] (no-reply, exception, late, bad-crc, drop,
//! stuck, noisy, power-loss). Every reply carries the simulator's virtual time (`time_us`).

use super::fault::{self, USAGE};
use super::K2Sim;
use crate::core::{Error, Result};
use crate::k2::instr::EventKind;
use crate::msg;
use serde_json::{json, Value as Json};

/// The control words, for messages.
pub const WORDS: &str = "fault KIND … | fault clear [ID|all] | faults | events | state";

fn usage(msg: impl Into<crate::core::error::Text>) -> Error {
    Error::usage(msg).hint(msg!("k2-control-words-hint", words = WORDS, usage = USAGE))
}

/// Applies one control line to `sim` at its current virtual time: the text for people and
/// the data for JSON. `served`: the simulator is behind a transport (faults that act on the
/// wire — late, bad-crc, drop — then act; in-process the text says they wait for serving).
pub fn answer(sim: &mut K2Sim, text: &str, served: bool) -> Result<(String, Json)> {
    sim.advance();
    let text = text.trim();
    let (word, rest) = text.split_once(char::is_whitespace).unwrap_or((text, ""));
    let rest = rest.trim();
    let now_us = sim.last.as_micros() as u64;
    match word.to_ascii_lowercase().as_str() {
        "faults" => {
            if !rest.is_empty() {
                return Err(usage(msg!("sim-word-takes-nothing", word = "faults", rest = rest)));
            }
            let list: Vec<String> = sim.faults.list.iter().map(|f| f.describe()).collect();
            let text = if list.is_empty() { msg!("sim-no-faults").into() } else { list.join("\n") };
            Ok((text, json!({"faults": sim.faults.list, "time_us": now_us})))
        }
        "events" => {
            if !rest.is_empty() {
                return Err(usage(msg!("sim-word-takes-nothing", word = "events", rest = rest)));
            }
            let acted: Vec<Json> = sim
                .events
                .list()
                .iter()
                .filter_map(|e| match e.kind {
                    EventKind::Fault { id, fault } => Some(json!({
                        "id": id,
                        "fault": fault::FaultKind::name_of_code(fault),
                        "time_us": e.time.as_micros() as u64,
                    })),
                    _ => None,
                })
                .collect();
            let text = if acted.is_empty() {
                msg!("sim-no-fault-acted").into()
            } else {
                acted
                    .iter()
                    .map(|a| {
                        msg!(
                            "sim-fault-acted",
                            seconds = format!("{:.6}", a["time_us"].as_u64().unwrap_or(0) as f64 / 1e6),
                            id = a["id"].to_string(),
                            name = a["fault"].as_str().unwrap_or("")
                        )
                        .into()
                    })
                    .collect::<Vec<String>>()
                    .join("\n")
            };
            Ok((text, json!({"events": acted, "time_us": now_us})))
        }
        "fault" => {
            if let Some(arg) = rest.strip_prefix("clear").filter(|a| a.is_empty() || a.starts_with(' ')) {
                let id = match arg.trim() {
                    "" | "all" => None,
                    n => Some(n.parse::<u32>().map_err(|_| usage(msg!("sim-not-fault-id", text = n)))?),
                };
                let n = sim.clear_faults(id);
                if let (Some(id), 0) = (id, n) {
                    return Err(Error::usage(msg!("sim-no-such-fault", id = id)).hint(msg!("sim-no-such-fault-hint")));
                }
                return Ok((msg!("sim-faults-cleared", n = n).into(), json!({"cleared": n, "time_us": now_us})));
            }
            let spec = fault::parse(rest).map_err(usage)?;
            let now = sim.last;
            let id = sim.faults.add(&spec, now);
            let f = sim.faults.list.last().expect("just added");
            let mut text = f.describe();
            if !served && !f.kind.in_process() {
                text.push(' ');
                text.push_str(&msg!("k2-control-acts-when-served"));
            }
            Ok((text, json!({"id": id, "fault": f, "time_us": now_us})))
        }
        "state" => {
            // The whole simulated state, as a snapshot holds it: a client's tests compare it
            // before and after a command that must change nothing (`plcsh probe`, `agent check`).
            if !rest.is_empty() {
                return Err(usage(msg!("sim-word-takes-nothing", word = "state", rest = rest)));
            }
            let state = serde_json::to_value(sim.snapshot_state()).unwrap_or_default();
            Ok((state.to_string(), json!({"state": state, "time_us": now_us})))
        }
        "" => Err(usage(msg!("k2-control-empty"))),
        other => Err(usage(msg!("k2-control-unknown-word", word = other))),
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::core::Clock;

    #[test]
    fn faults_are_added_listed_logged_and_cleared_in_one_grammar() {
        let clock = Clock::stepped();
        let mut sim = crate::k2::sim::open("K205-16DT", clock.clone()).unwrap();
        let (text, j) = answer(&mut sim, "fault stuck I0.1=1 after=1s", true).unwrap();
        assert!(text.starts_with("fault 1: stuck I0.1=1"), "{text}");
        assert_eq!(j["id"], 1);
        assert!(answer(&mut sim, "events", true).unwrap().0.contains("no injected fault"));
        clock.step(std::time::Duration::from_millis(1500));
        let (_, j) = answer(&mut sim, "events", true).unwrap();
        assert_eq!(j["events"][0]["fault"], "stuck");
        assert_eq!(j["events"][0]["time_us"], 1_000_000);
        let (_, j) = answer(&mut sim, "faults", true).unwrap();
        assert_eq!(j["faults"].as_array().unwrap().len(), 1);
        assert_eq!(answer(&mut sim, "fault clear", true).unwrap().1["cleared"], 1);
        assert!(answer(&mut sim, "fault clear 7", true).is_err());
        for bad in ["", "fault", "fault bogus", "faults now", "events x", "reboot"] {
            let e = answer(&mut sim, bad, true).unwrap_err();
            assert!(e.hint.as_deref().unwrap_or("").contains("control words"), "{bad}: {e}");
        }
    }
}
