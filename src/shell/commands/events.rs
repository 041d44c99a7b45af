//! `events` (show the interrupt event log and clear it) and `wait event N timeout=2s`
//! (block until an event arrives, in virtual time: a stepped clock jumps straight to the
//! simulator's next due event; a following clock waits for real; Ctrl-C interrupts).

use super::k2cmd::{self, opt, value_err};
use super::CommandSpec;
use crate::core::clock::format_time;
use crate::core::{Error, ErrorKind, Result};
use crate::k2::K2Ops;
use crate::k2::{Event, EventMatch};
use crate::output::Outcome;
use crate::shell::lex;
use crate::shell::{Args, Shell};
use std::time::Duration;

pub const EVENTS: CommandSpec = CommandSpec {
    name: "events",
    aliases: &[],
    usage: "events [keep]",
    summary: || crate::msg!("summary-events"),
    subcommands: &["keep"],
    run: events,
};

pub const WAIT: CommandSpec = CommandSpec {
    name: "wait",
    aliases: &[],
    usage: "wait event N|NAME [timeout=2s]   e.g. wait event 28 timeout=2s, wait event pto1-done",
    summary: || crate::msg!("summary-wait"),
    subcommands: &["event"],
    run: wait,
};

fn row(e: &Event) -> Vec<String> {
    vec![
        e.seq.to_string(),
        format_time(e.time),
        e.kind.number().map(|n| n.to_string()).unwrap_or_else(|| "–".into()),
        e.kind.name(),
        e.kind.describe(),
    ]
}

/// An event as JSON: its number (null when the manual gives none), name, text and fields.
fn event_json(e: &Event) -> serde_json::Value {
    let mut v = serde_json::to_value(e).unwrap_or_default();
    if let Some(m) = v.as_object_mut() {
        m.insert("number".into(), serde_json::json!(e.kind.number()));
        m.insert("name".into(), serde_json::json!(e.kind.name()));
        m.insert("what".into(), serde_json::json!(e.kind.describe()));
    }
    v
}

fn events(sh: &mut Shell, args: Args) -> Result<Outcome> {
    let keep = match args.text.trim().to_ascii_lowercase().as_str() {
        "" | "clear" => false,
        "keep" => true,
        other => return Err(Error::usage(format!("unknown `events {other}`")).column(args.offset).hint(EVENTS.usage)),
    };
    let dev = sh.session.current_index()?;
    let name = k2cmd::name(sh, dev);
    let dropped = k2cmd::sim(sh, dev, "events").map(|s| s.events.dropped).unwrap_or(0);
    let list = k2cmd::k2(sh, dev)?.events(!keep).map_err(|e| e.device(&name))?;
    let mut o = if list.is_empty() {
        Outcome::new("events").text(crate::msg!("shell-no-events").text)
    } else {
        Outcome::new("events").table(&["seq", "time", "event", "name", "what"], list.iter().map(row).collect())
    };
    let json: Vec<serde_json::Value> = list.iter().map(event_json).collect();
    o = o.with("events", json).with("dropped", dropped);
    o.device = Some(name);
    Ok(o)
}

fn wait(sh: &mut Shell, args: Args) -> Result<Outcome> {
    let w: Vec<lex::Word> = lex::words(args.text)?.into_iter().map(|(c, t)| (c + args.offset, t)).collect();
    let (pos, opts) = lex::options(&w);
    k2cmd::check_options(&opts, &["timeout"], WAIT.usage)?;
    if pos.first().map(|p| p.1.to_ascii_lowercase()) != Some("event".into()) || pos.len() != 2 {
        return Err(Error::usage(crate::msg!("shell-wait-needs-event")).column(args.offset).hint(WAIT.usage));
    }
    let m = EventMatch::parse(pos[1].1);
    let timeout = match opt(&opts, "timeout") {
        Some((c, t)) => {
            let us = crate::core::literal::parse_option_duration_us(t).map_err(|e| value_err(c, e))?;
            Duration::from_micros(us.max(0) as u64)
        }
        None => Duration::from_secs(10),
    };
    let dev = sh.session.current_index()?;
    let name = k2cmd::name(sh, dev);
    let clock = sh.session.clock.clone();
    let start = clock.now();
    let deadline = start + timeout;
    loop {
        if let Some(e) = k2cmd::k2(sh, dev)?.take_event(&m).map_err(|e| e.device(&name))? {
            let waited = clock.now().saturating_sub(start);
            let (event, what, at, after) = (e.kind.name(), e.kind.describe(), format_time(e.time), format_time(waited));
            let text = match e.kind.number() {
                Some(n) => {
                    crate::msg!(
                        "shell-wait-event-number",
                        number = n,
                        name = event,
                        what = what,
                        at = at,
                        waited = after
                    )
                }
                None => crate::msg!("shell-wait-event", name = event, what = what, at = at, waited = after),
            };
            let mut o = Outcome::new("wait")
                .text(text.text)
                .with("event", event_json(&e))
                .with("waited_us", waited.as_micros() as u64);
            o.device = Some(name);
            return Ok(o);
        }
        if sh.session.interrupted() {
            return Err(Error::new(
                ErrorKind::Interrupted,
                crate::msg!("shell-wait-interrupted", event = m.to_string()),
            )
            .device(name));
        }
        let now = clock.now();
        if now >= deadline {
            return Err(Error::new(
                ErrorKind::Timeout,
                crate::msg!("shell-wait-timeout", event = m.to_string(), timeout = format_time(timeout)),
            )
            .device(name)
            .hint(crate::msg!("shell-hint-wait-timeout")));
        }
        // Jumping the clock to the next event is for simulators; with a device on a wire
        // open the wait is real (Session::sleep), never a timeout that expires in no time.
        if clock.is_stepped() && !sh.session.has_wire_device() {
            let due = k2cmd::sim(sh, dev, "").ok().map(|s| s.next_event_due());
            let target = match due {
                // The simulator knows when its next event is due; nothing due → jump to the end.
                Some(Some(d)) if d > now => d.min(deadline),
                Some(None) => deadline,
                _ => (now + Duration::from_millis(1)).min(deadline),
            };
            let step = target.saturating_sub(now).max(Duration::from_nanos(1)).min(deadline - now);
            clock.step(sh.session.budget_step(step)?);
        } else {
            sh.session.sleep((deadline - now).min(Duration::from_millis(5)));
        }
    }
}
