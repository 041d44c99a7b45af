//! The simulator's control language — faults, switches, pulses, strictness — as ONE
//! grammar with two ways in: `servo sim …` in the shell (and Lua's `servo:sim_fault(…)`)
//! applies it to an in-process line directly, and a served line (`plcsh sim serve
//! --servo-pty LINK`) takes the same text on its control socket `LINK.ctl`, one request
//! per line, one JSON reply per line:
//!
//! ```text
//! → id=1 fault no-reply count=2
//! ← {"ok":true,"text":"drive id 1: no reply for the next 2 requests", …}
//! ```
//!
//! Words (`id=N` may appear anywhere; without it the drive is the one the shell's device
//! talks to, or every drive for line faults sent to the socket):
//! `fault [drive] [CODE] [at=POS]` · `fault no-reply|bad-checksum|drop-echo [count=N|all]` ·
//! `fault delay DURATION [count=…]` · `fault abort OBJECT CODE [count=…]` · `fault clear` ·
//! `switch [home|neg|pos] POS|off` · `pulses freq=HZ count=N [dir=fwd|rev]` ·
//! `strict on|off` · `events`.
//!
//! `fault drive CODE at=POS` arms a drive fault at a position: it acts when the drive's
//! motion crosses POS (increments), at that moment of virtual time, and is logged with it
//! (`events` lists the armed faults that acted).

use super::drive::DEFAULT_FAULT;
use super::faults::{FaultKind, LineFault};
use super::SimLine;
use crate::core::literal::parse_option_duration_us;
use crate::core::{Error, ErrorKind, Result};
use crate::msg;
use crate::servo::objects;
use serde_json::{json, Value as Json};
use std::path::Path;
use std::time::Duration;

/// Which switch `switch` moves.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Which {
    Home,
    NegLimit,
    PosLimit,
}

/// One control request.
#[derive(Clone, Debug, PartialEq)]
pub enum Control {
    /// Drive fault: Fault state, the code in 603F.00, 2601.00 bit 0.
    DriveFault(u16),
    /// A drive fault armed at a position (increments): acts when the motion crosses it.
    DriveFaultAt(u16, f64),
    /// The armed faults that acted, with their virtual times.
    Events,
    /// A line fault; `count` `None` = until cleared.
    Line(FaultKind, Option<u32>),
    ClearFaults,
    Switch(Which, Option<f64>),
    Pulses {
        freq: f64,
        count: u64,
        dir: i8,
    },
    Strict(bool),
}

/// A parsed request: what, and for which drive id (`None`: not given).
#[derive(Clone, Debug, PartialEq)]
pub struct Request {
    pub control: Control,
    pub id: Option<u8>,
}

pub const USAGE: &str = "servo sim fault [drive] [CODE] | fault no-reply|bad-checksum|drop-echo [all|count=N] | fault delay|late 50ms [count=N|all] | fault abort OBJECT CODE | fault clear | switch [home|neg|pos] POS|off | pulses freq=HZ count=N [dir=fwd|rev] | strict on|off";

fn usage(msg: impl Into<crate::core::error::Text>, col: usize) -> Error {
    Error::usage(msg).column(col).hint(USAGE)
}

/// A number: decimal, `16#…` or `0x…`.
fn number(text: &str, col: usize) -> Result<i64> {
    let t = text.replace('_', "");
    let r = if let Some(h) = t.strip_prefix("16#").or_else(|| t.strip_prefix("0x")).or_else(|| t.strip_prefix("0X")) {
        i64::from_str_radix(h, 16).ok()
    } else {
        t.parse::<i64>().ok().or_else(|| t.parse::<f64>().ok().filter(|f| f.fract() == 0.0).map(|f| f as i64))
    };
    r.ok_or_else(|| usage(msg!("servo-sim-not-number", text = text), col))
}

/// Parses the words after `servo sim` (each with its column).
pub fn parse(words: &[(usize, &str)]) -> Result<Request> {
    let mut id = None;
    let mut opts: Vec<(usize, &str, &str)> = Vec::new();
    let mut pos: Vec<(usize, &str)> = Vec::new();
    for &(c, w) in words {
        match w.split_once('=') {
            Some(("id", v)) => {
                id = Some(u8::try_from(number(v, c + 3)?).map_err(|_| usage(msg!("servo-sim-id-range"), c + 3))?)
            }
            Some((k, v)) => opts.push((c, k, v)),
            None => pos.push((c, w)),
        }
    }
    let opt = |k: &str| opts.iter().find(|o| o.1 == k).map(|o| (o.0 + k.len() + 1, o.2));
    let known = |allowed: &[&str]| -> Result<()> {
        match opts.iter().find(|o| !allowed.contains(&o.1)) {
            Some(&(c, k, _)) => Err(usage(msg!("servo-sim-unknown-option", key = k), c)),
            None => Ok(()),
        }
    };
    // `times=` (the K2's word) is `count=`; `late` is `delay`: one vocabulary for faults.
    let count = || -> Result<Option<u32>> {
        match opt("count").or_else(|| opt("times")) {
            None => Ok(Some(1)),
            Some((_, "all")) => Ok(None),
            Some((c, v)) => u32::try_from(number(v, c)?)
                .ok()
                .filter(|n| *n > 0)
                .map(Some)
                .ok_or_else(|| usage(msg!("servo-sim-count"), c)),
        }
    };
    let first = pos.first().copied().unwrap_or((0, ""));
    let control = match (first.1, &pos[1.min(pos.len())..]) {
        ("fault", rest) => {
            let kind = rest.first().map(|w| w.1).unwrap_or("drive");
            let args = if rest.is_empty() { rest } else { &rest[1..] };
            match kind {
                "no-reply" | "bad-checksum" | "drop-echo" => {
                    known(&["count", "times"])?;
                    let k = match kind {
                        "no-reply" => FaultKind::NoReply,
                        "bad-checksum" => FaultKind::BadChecksum,
                        _ => FaultKind::DropEcho,
                    };
                    // `all` (the command card's form) is `count=all`: every request from now on.
                    // Any other word is refused, never dropped (a rehearsed outage must not
                    // pass on the retry).
                    match args {
                        [] => Control::Line(k, count()?),
                        [(_, w)] if w.eq_ignore_ascii_case("all") => {
                            if let Some((oc, _)) = opt("count").or_else(|| opt("times")) {
                                return Err(usage(msg!("servo-sim-all-and-count"), oc));
                            }
                            Control::Line(k, None)
                        }
                        [(c, w), ..] => return Err(usage(msg!("servo-sim-fault-extra", word = *w, kind = kind), *c)),
                    }
                }
                "delay" | "late" => {
                    known(&["count", "times"])?;
                    let &[(c, d)] = args else {
                        return Err(usage(msg!("servo-sim-fault-duration", kind = kind), first.0));
                    };
                    let us = parse_option_duration_us(d).map_err(|m| usage(m, c))?;
                    Control::Line(FaultKind::Delay(Duration::from_micros(us.max(0) as u64)), count()?)
                }
                "abort" => {
                    known(&["count", "times"])?;
                    let &[(oc, o), (cc, code)] = args else {
                        return Err(usage(msg!("servo-sim-fault-abort"), first.0));
                    };
                    let r = objects::parse(o).map_err(|e| e.column(oc))?;
                    let code = u32::try_from(number(code, cc)?).map_err(|_| usage(msg!("servo-sim-abort-bits"), cc))?;
                    Control::Line(FaultKind::Abort { index: r.index, sub: r.sub, code }, count()?)
                }
                "clear" => Control::ClearFaults,
                "drive" => {
                    known(&["at"])?;
                    at_position(drive_fault(args.first().copied())?, opt("at"))?
                }
                _ => {
                    known(&["at"])?;
                    at_position(drive_fault(rest.first().copied())?, opt("at"))?
                }
            }
        }
        ("switch", rest) => {
            known(&[])?;
            let (which, at) = match rest {
                [(_, "home"), p] => (Which::Home, *p),
                [(_, "neg"), p] => (Which::NegLimit, *p),
                [(_, "pos"), p] => (Which::PosLimit, *p),
                [p] => (Which::Home, *p),
                _ => return Err(usage("usage: servo sim switch [home|neg|pos] POS|off", first.0)),
            };
            let pos = match at.1 {
                "off" if which != Which::Home => None,
                p => Some(number(p, at.0)? as f64),
            };
            Control::Switch(which, pos)
        }
        ("pulses", []) => {
            known(&["freq", "count", "dir"])?;
            let (fc, f) = opt("freq").ok_or_else(|| usage(msg!("servo-sim-pulses-freq"), first.0))?;
            let (cc, n) = opt("count").ok_or_else(|| usage(msg!("servo-sim-pulses-count"), first.0))?;
            let freq = f.trim_end_matches("Hz").trim_end_matches("hz").parse::<f64>().ok().filter(|f| *f > 0.0);
            let freq = freq.ok_or_else(|| usage(msg!("servo-sim-not-freq", text = f), fc))?;
            let count = u64::try_from(number(n, cc)?).map_err(|_| usage(msg!("servo-sim-pulse-count"), cc))?;
            let dir = match opt("dir") {
                None | Some((_, "fwd" | "+" | "cw" | "1")) => 1,
                Some((_, "rev" | "-" | "ccw" | "-1")) => -1,
                Some((c, d)) => return Err(usage(msg!("servo-sim-not-dir", dir = d), c)),
            };
            Control::Pulses { freq, count, dir }
        }
        ("events", []) => Control::Events,
        ("strict", [(_, "on")]) => Control::Strict(true),
        ("strict", [(_, "off")]) => Control::Strict(false),
        (w, _) => return Err(usage(msg!("servo-sim-unknown-word", word = w), first.0)),
    };
    Ok(Request { control, id })
}

/// `at=POS` makes a drive fault one armed at a position.
fn at_position(c: Control, at: Option<(usize, &str)>) -> Result<Control> {
    match (c, at) {
        (Control::DriveFault(code), Some((col, p))) => Ok(Control::DriveFaultAt(code, number(p, col)? as f64)),
        (c, _) => Ok(c),
    }
}

fn drive_fault(code: Option<(usize, &str)>) -> Result<Control> {
    Ok(Control::DriveFault(match code {
        None => DEFAULT_FAULT,
        Some((c, s)) => u16::try_from(number(s, c)?)
            .map_err(|_| Error::new(ErrorKind::Value, msg!("servo-sim-fault-bits")).column(c))?,
    }))
}

/// Splits a control line into words with their columns.
pub fn words(line: &str) -> Vec<(usize, &str)> {
    let mut out = Vec::new();
    let mut start = None;
    for (i, ch) in line.char_indices().chain(std::iter::once((line.len(), ' '))) {
        match (ch.is_whitespace(), start) {
            (false, None) => start = Some(i),
            (true, Some(s)) => {
                out.push((s, &line[s..i]));
                start = None;
            }
            _ => {}
        }
    }
    out
}

/// Applies a request to `line`; `default_id` is the drive when the request names none
/// (`None`: line faults apply to every id, drive controls need an id or a single drive).
pub fn apply(line: &mut SimLine, req: &Request, default_id: Option<u8>) -> Result<(String, Json)> {
    let id = req.id.or(default_id);
    let drive_id = || -> Result<u8> {
        match id {
            Some(i) if line.ids().contains(&i) => Ok(i),
            Some(i) => Err(Error::usage(msg!("servo-sim-no-drive", id = i, ids = format!("{:?}", line.ids())))),
            None => match line.ids().as_slice() {
                [one] => Ok(*one),
                ids => Err(Error::usage(msg!("servo-sim-several-drives", ids = format!("{ids:?}")))),
            },
        }
    };
    Ok(match &req.control {
        Control::DriveFault(code) => {
            let i = drive_id()?;
            line.inject_fault(i, *code);
            (
                msg!("servo-sim-fault-injected", id = i, code = format!("{code:04X}")).text,
                json!({"fault": code, "id": i}),
            )
        }
        Control::DriveFaultAt(code, pos) => {
            let i = drive_id()?;
            let t = line.now();
            let d = line.drive(i).expect("checked id");
            d.advance(t);
            d.faults_at.push((*pos, *code));
            (
                msg!("servo-sim-fault-armed", id = i, code = format!("{code:04X}"), position = pos.to_string()).text,
                json!({"fault": code, "at": *pos as i64, "id": i}),
            )
        }
        Control::Events => {
            let t = line.now();
            let mut rows = Vec::new();
            let mut list = Vec::new();
            for i in line.ids() {
                let d = line.drive(i).expect("listed id");
                d.advance(t);
                for &(te, x, code) in &d.fault_events {
                    rows.push(
                        msg!(
                            "servo-sim-fault-acted",
                            time = format!("{te:.6}"),
                            id = i,
                            code = format!("{code:04X}"),
                            position = x.to_string()
                        )
                        .text,
                    );
                    list.push(json!({"time_s": te, "id": i, "fault": code, "at": x as i64}));
                }
            }
            let text = if rows.is_empty() { msg!("servo-sim-no-fault-acted").text } else { rows.join("\n") };
            (text, json!({"events": list}))
        }
        Control::Line(kind, count) => {
            if id.is_some() {
                drive_id()?; // an id must name a drive on the line
            }
            line.faults.add(LineFault { kind: *kind, id, remaining: *count });
            let (scope, n) = match count {
                Some(1) => ("one", 1),
                Some(n) => ("many", *n),
                None => ("every", 0),
            };
            let text = msg!(
                "servo-sim-line-fault",
                scope = if id.is_some() { "one" } else { "all" },
                id = id.unwrap_or(0),
                fault = kind.describe(),
                count = scope,
                n = n
            );
            let english = kind.describe_in(crate::core::msg::Lang::En);
            (text.text, json!({"line_fault": english, "count": count, "id": id}))
        }
        Control::ClearFaults => {
            line.faults.clear();
            (msg!("servo-sim-faults-cleared").text, json!({"cleared": true}))
        }
        Control::Switch(which, pos) => {
            let i = drive_id()?;
            let d = line.drive(i).expect("checked id");
            let (name, key) = match which {
                Which::Home => {
                    d.switches.home = pos.unwrap_or(d.switches.home);
                    ("home", "home_switch")
                }
                Which::NegLimit => {
                    d.switches.neg_limit = *pos;
                    ("neg", "neg_limit")
                }
                Which::PosLimit => {
                    d.switches.pos_limit = *pos;
                    ("pos", "pos_limit")
                }
            };
            let mut data = json!({"id": i});
            data[key] = json!(pos.map(|p| p as i64));
            let text = msg!(
                "servo-sim-switch",
                id = i,
                switch = name,
                position = if pos.is_some() { "at" } else { "off" },
                at = pos.map(|p| p.to_string()).unwrap_or_default()
            );
            (text.text, data)
        }
        Control::Pulses { freq, count, dir } => {
            let i = drive_id()?;
            let (start, end) = line.add_pulses(i, *freq, *count, *dir).map_err(Error::usage)?;
            (
                msg!(
                    "servo-sim-pulses",
                    id = i,
                    count = *count,
                    freq = freq.to_string(),
                    dir = if *dir < 0 { "reverse" } else { "forward" },
                    start = format!("{start:.6}"),
                    end = format!("{end:.6}")
                )
                .text,
                json!({"pulses": count, "freq": freq, "dir": dir, "start_s": start, "end_s": end, "id": i}),
            )
        }
        Control::Strict(on) => {
            line.set_strict(*on);
            (msg!("servo-sim-strict", strict = if *on { "on" } else { "off" }).text, json!({"strict": on}))
        }
    })
}

/// Answers one control-socket line (the served simulator's side).
pub fn answer_line(line: &mut SimLine, text: &str) -> Json {
    let ws = words(text);
    crate::core::link::control::reply(parse(&ws).and_then(|r| apply(line, &r, None)))
}

/// Sends one control line to a served line's control channel and returns its reply.
pub fn send(path: &Path, text: &str) -> Result<(String, Json)> {
    crate::core::link::control::send(path, text)
}

#[cfg(test)]
mod tests {
    use super::*;

    fn p(s: &str) -> Result<Request> {
        parse(&words(s))
    }

    #[test]
    fn the_grammar() {
        // One vocabulary with the K2's faults: `late` is `delay`, `times=` is `count=`.
        assert_eq!(p("fault late 50ms times=2").unwrap().control, p("fault delay 50ms count=2").unwrap().control);
        assert_eq!(p("fault no-reply times=3").unwrap().control, Control::Line(FaultKind::NoReply, Some(3)));
        assert_eq!(p("fault").unwrap().control, Control::DriveFault(DEFAULT_FAULT));
        assert_eq!(p("fault 16#2310").unwrap().control, Control::DriveFault(0x2310));
        assert_eq!(
            p("fault drive 0x7500 id=2").unwrap(),
            Request { control: Control::DriveFault(0x7500), id: Some(2) }
        );
        assert_eq!(p("fault no-reply").unwrap().control, Control::Line(FaultKind::NoReply, Some(1)));
        assert_eq!(p("fault bad-checksum count=all").unwrap().control, Control::Line(FaultKind::BadChecksum, None));
        // The command card's `all` is every request, like count=all; any other word is refused.
        assert_eq!(p("fault no-reply all").unwrap().control, Control::Line(FaultKind::NoReply, None));
        assert_eq!(p("fault drop-echo all").unwrap().control, Control::Line(FaultKind::DropEcho, None));
        assert_eq!(p("fault no-reply x").unwrap_err().column, Some(15));
        assert!(p("fault no-reply all count=2").is_err());
        assert_eq!(
            p("fault late 50ms").unwrap().control,
            Control::Line(FaultKind::Delay(Duration::from_millis(50)), Some(1))
        );
        assert!(p("fault late").unwrap_err().message.contains("fault late needs one duration"));
        assert_eq!(
            p("fault delay 50ms count=3").unwrap().control,
            Control::Line(FaultKind::Delay(Duration::from_millis(50)), Some(3))
        );
        assert_eq!(
            p("fault abort target_position 16#06090030").unwrap().control,
            Control::Line(FaultKind::Abort { index: 0x607A, sub: 0, code: 0x0609_0030 }, Some(1))
        );
        assert_eq!(p("switch neg -3000").unwrap().control, Control::Switch(Which::NegLimit, Some(-3000.0)));
        assert_eq!(p("switch pos off").unwrap().control, Control::Switch(Which::PosLimit, None));
        assert_eq!(p("switch 250").unwrap().control, Control::Switch(Which::Home, Some(250.0)));
        assert_eq!(
            p("pulses freq=1000 count=500 dir=rev").unwrap().control,
            Control::Pulses { freq: 1000.0, count: 500, dir: -1 }
        );
        assert_eq!(p("strict on").unwrap().control, Control::Strict(true));
        assert_eq!(p("fault drive 16#7500 at=-1200").unwrap().control, Control::DriveFaultAt(0x7500, -1200.0));
        assert_eq!(p("fault at=300").unwrap().control, Control::DriveFaultAt(DEFAULT_FAULT, 300.0));
        assert_eq!(p("events").unwrap().control, Control::Events);
        for bad in [
            "fault no-reply at=3",
            "fault drive 1 at=x",
            "fault abort target_position",
            "fault delay",
            "pulses freq=0 count=1",
            "juggle",
            "switch home off",
            "fault no-reply count=0",
            "fault no-reply speed=3",
        ] {
            let e = p(bad).unwrap_err();
            assert_eq!(e.kind, ErrorKind::Usage, "{bad}: {e}");
        }
        assert_eq!(p("fault abort nosuch 1").unwrap_err().column, Some(12));
    }
}
