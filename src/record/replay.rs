//! `plcsh replay FILE`: the recorded requests sent again, to a simulator, and every reply
//! compared with the recorded one — so a session recorded at a machine becomes a regression
//! test at a desk.
//!
//! Each recorded link gets its own fresh simulator: a K2 simulator of the model the link's
//! URL names (`model=`, else the scheme's default; `--sim-model` overrides) for Modbus links,
//! a servo line with the recorded drive ids for servo links; a snapshot (`--snapshot`) sets
//! the K2's starting state. The simulator's clock is stepped to each request's recorded
//! virtual time (relative to the link's first request), so time-dependent values (pulse
//! counts, counters, motion) replay as they were. Modbus requests go through the
//! simulator's own server code (the same request handling `plcsh sim serve` answers with),
//! so a replay answers exactly as a served simulator would.
//!
//! With a bench (`--bench FILE`, [`crate::wiring::bench`]) the recorded requests go to the
//! machine the bench describes instead — its PLC for the Modbus links, its drive line for
//! the servo links, wired to each other, in the recorded order of all links, on one clock
//! stepped to each request's virtual time
//! relative to the recording's first request — so a session recorded at a served bench
//! replays without difference against the same bench, and against a bench with one
//! initial value changed reports exactly that value.
//!
//! A difference is a reply whose bytes differ (values, exception, or a reply where none was
//! recorded and back); for reads it names every differing operand.

use super::decode::{self, Asked};
use super::file::{Frame, LinkInfo, Recording};
use super::helper::Helper;
use crate::core::trace::{hex_bytes, Dir, Proto};
use crate::core::{Clock, Error, Result};
use crate::k2::modbus_map;
use crate::k2::sim::modbus_server::K2Service;
use crate::k2::sim::rtu_frame;
use crate::k2::sim::K2Sim;
use crate::k2::space::K2Space;
use serde::Serialize;
use std::sync::{Arc, Mutex};
use std::time::Duration;

/// How to build the simulators a replay runs against.
#[derive(Clone, Debug, Default)]
pub struct Target {
    /// K2 model for every Modbus link (default: the recorded one).
    pub model: Option<String>,
    /// A K2 simulator state to start from (see [`crate::snapshot`]).
    pub snapshot: Option<std::path::PathBuf>,
    /// A bench file whose machine answers instead of fresh simulators.
    pub bench: Option<std::path::PathBuf>,
    /// The helper program's mailbox base (a V byte), when the recording does not show it.
    pub agent: Option<u32>,
}

/// The simulators a link is replayed against, and the clock they run on.
struct Sims {
    clock: Clock,
    /// The clock's reading that the link's first request time maps to.
    base: Duration,
    /// The recorded virtual time that `base` stands for (`None`: the link's first request).
    vt0: Option<Duration>,
    k2: Option<Arc<Mutex<K2Sim>>>,
    line: Option<Arc<Mutex<crate::servo::sim::SimLine>>>,
}

/// A bench's machine: its PLC and drive line, wired, on one stepped clock.
fn bench_sims(rec: &Recording, path: &std::path::Path) -> Result<Sims> {
    let clock = Clock::stepped();
    let (k2, line, _notes) = crate::wiring::bench::serve_parts(path, &clock)?;
    Ok(Sims {
        base: clock.now(),
        vt0: rec.frames.iter().filter(|f| f.dir == Dir::Sent).find_map(|f| f.vt),
        clock,
        k2: k2.map(|k| Arc::new(Mutex::new(k))),
        line,
    })
}

/// One reply that differs.
#[derive(Clone, Debug, PartialEq, Serialize)]
pub struct Difference {
    /// The request's frame number in the recording (1-based, as `record show` counts).
    pub frame: usize,
    pub device: String,
    /// Virtual time of the request, when recorded.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub vt: Option<f64>,
    /// The request, decoded.
    pub request: String,
    /// The recorded and the replayed reply (hex; empty: no reply).
    pub recorded: String,
    pub replayed: String,
    /// What differs, in operand terms where the request names operands.
    pub detail: String,
}

/// What a replay found.
#[derive(Clone, Debug, Default, Serialize)]
pub struct Report {
    pub requests: usize,
    pub differences: Vec<Difference>,
    /// Links not replayed, and why.
    pub skipped: Vec<String>,
    /// The file had damaged regions skipped: frames in them were not replayed.
    pub damaged: bool,
}

/// A request and its reply: indices into the recording's frames.
type Exchange = (usize, Option<usize>);

/// Pairs each request with the reply that followed it on its link (if any before the next
/// request): `(request index, reply index)` into `frames`; `of_link` are the indices of
/// the link's frames, in order.
fn exchanges(frames: &[Frame], of_link: &[usize]) -> Vec<(usize, Option<usize>)> {
    let mut out: Vec<(usize, Option<usize>)> = Vec::new();
    for (i, f) in of_link.iter().map(|&i| (i, &frames[i])) {
        match f.dir {
            Dir::Sent => out.push((i, None)),
            Dir::Received => {
                if let Some(last) = out.last_mut() {
                    // The first reply belongs to the request; a second one (a late reply) is
                    // not compared.
                    last.1.get_or_insert(i);
                }
            }
        }
    }
    out
}

/// Replays every link of `rec`.
pub fn run(rec: &Recording, target: &Target) -> Result<Report> {
    let mut report = Report { damaged: !rec.damaged.is_empty(), ..Default::default() };
    // Each link's frames, in one pass (a capture may hold many links).
    let mut of_link: Vec<Vec<usize>> = vec![Vec::new(); rec.links.len()];
    for (i, f) in rec.frames.iter().enumerate() {
        if let Some(v) = of_link.get_mut(f.link) {
            v.push(i);
        }
    }
    match &target.bench {
        Some(path) => {
            // One machine on one clock: every link's exchanges in recorded order.
            let bench = bench_sims(rec, path)?;
            let mut all: Vec<(usize, Exchange)> = (0..rec.links.len())
                .flat_map(|li| exchanges(&rec.frames, &of_link[li]).into_iter().map(move |e| (li, e)))
                .collect();
            all.sort_by_key(|(_, (q, _))| *q);
            let mut warned = vec![false; rec.links.len()];
            for run in all.chunk_by(|a, b| a.0 == b.0) {
                let li = run[0].0;
                let ex: Vec<Exchange> = run.iter().map(|(_, e)| *e).collect();
                replay_link(rec, li, &ex, Some(&bench), target, &mut report, &mut warned[li])?;
            }
        }
        None => {
            for (li, frames) in of_link.iter().enumerate() {
                let ex = exchanges(&rec.frames, frames);
                replay_link(rec, li, &ex, None, target, &mut report, &mut false)?;
            }
        }
    }
    report.differences.sort_by_key(|d| d.frame);
    Ok(report)
}

/// Replays exchanges `ex` of link `li`, against the bench's machine or fresh simulators.
fn replay_link(
    rec: &Recording,
    li: usize,
    ex: &[Exchange],
    bench: Option<&Sims>,
    target: &Target,
    report: &mut Report,
    skipped: &mut bool,
) -> Result<()> {
    let link = &rec.links[li];
    let mut skip = |report: &mut Report, why: String| {
        if !std::mem::replace(skipped, true) {
            report.skipped.push(why);
        }
    };
    match link.proto {
        Proto::ModbusTcp | Proto::ModbusRtu | Proto::RtuOverTcp => {
            let sims = match bench {
                Some(b) => match b.k2.clone() {
                    Some(k2) => Sims { clock: b.clock.clone(), base: b.base, vt0: b.vt0, k2: Some(k2), line: None },
                    None => {
                        skip(report, crate::msg!("replay-no-sim-plc", link = link.name.as_str()).text);
                        return Ok(());
                    }
                },
                None => fresh_k2(link, target)?,
            };
            modbus_link(rec, ex, link, &sims, target, bench.is_none(), report);
        }
        Proto::KincoServo => {
            let sims = match bench {
                Some(b) => match b.line.clone() {
                    Some(line) => Sims { clock: b.clock.clone(), base: b.base, vt0: b.vt0, k2: None, line: Some(line) },
                    None => {
                        skip(report, crate::msg!("replay-no-sim-drive", link = link.name.as_str()).text);
                        return Ok(());
                    }
                },
                None => fresh_line(rec, ex),
            };
            servo_link(rec, ex, link, &sims, report);
        }
        Proto::Umpk | Proto::FxPort | Proto::FxLink => skip(
            report,
            crate::msg!(
                "replay-other-protocol",
                link = link.name.as_str(),
                protocol = super::packet::proto_name(link.proto)
            )
            .text,
        ),
        Proto::Unknown => skip(report, crate::msg!("replay-undeclared-protocol", link = link.name.as_str()).text),
    }
    Ok(())
}

/// Steps `clock` forward to `want` (never back).
fn step_to(clock: &Clock, want: Duration) {
    let now = clock.now();
    if want > now {
        clock.step(want - now);
    }
}

/// A fresh K2 simulator for one Modbus link.
fn fresh_k2(link: &LinkInfo, target: &Target) -> Result<Sims> {
    let model = match &target.model {
        Some(m) => crate::k2::catalog::lookup(m)?,
        None => decode::model_of(link),
    };
    let clock = Clock::stepped();
    let mut sim = K2Sim::new(model, clock.clone());
    if let Some(path) = &target.snapshot {
        crate::snapshot::Snapshot::load(path)?.restore_k2(&mut sim)?;
    }
    // The snapshot may have set the clock; replay times are relative to it.
    Ok(Sims { base: clock.now(), vt0: None, clock, k2: Some(Arc::new(Mutex::new(sim))), line: None })
}

/// A fresh servo line with the drive ids a servo link addressed.
fn fresh_line(rec: &Recording, ex: &[Exchange]) -> Sims {
    let mut ids: Vec<u8> = ex.iter().filter_map(|(q, _)| rec.frames[*q].bytes.first().copied()).collect();
    ids.sort_unstable();
    ids.dedup();
    let clock = Clock::stepped();
    let line = crate::servo::sim::SimLine::new(&ids, clock.clone());
    Sims { base: clock.now(), vt0: None, clock, k2: None, line: Some(Arc::new(Mutex::new(line))) }
}

fn modbus_link(
    rec: &Recording,
    ex: &[Exchange],
    link: &LinkInfo,
    sims: &Sims,
    target: &Target,
    heartbeat_clock: bool,
    report: &mut Report,
) {
    let sim = sims.k2.clone().expect("a K2 for a Modbus link");
    let model = sim.lock().unwrap_or_else(|p| p.into_inner()).model();
    let (clock, base) = (&sims.clock, sims.base);
    let space = K2Space::new(model);
    let vt0 = sims.vt0.or_else(|| ex.first().and_then(|(q, _)| rec.frames[*q].vt));
    let pdu_of = |i: usize| decode::modbus_pdu(link.proto, &rec.frames[i].bytes).ok().map(|(_, p)| p.to_vec());
    let pairs: Vec<(Vec<u8>, Option<Vec<u8>>)> =
        ex.iter().filter_map(|&(q, r)| Some((pdu_of(q)?, r.and_then(pdu_of)))).collect();
    let mut helper = Helper::detect(&space, &pairs, target.agent);
    if let Some(h) = &helper {
        let mut s = sim.lock().unwrap_or_else(|p| p.into_inner());
        if s.agent_base.is_none() {
            if let Err(e) = s.enable_agent(h.vbyte) {
                report.skipped.push(
                    crate::msg!("replay-helper-cannot-run", link = link.name.as_str(), error = e.to_string()).text,
                );
                helper = None;
            }
        }
    }
    let mut service: Option<K2Service> = None;
    for &(q, r) in ex {
        let req = &rec.frames[q];
        report.requests += 1;
        let Ok((unit, pdu)) = decode::modbus_pdu(link.proto, &req.bytes) else { continue };
        let service = service.get_or_insert_with(|| K2Service::new(sim.clone(), unit));
        let recorded_pdu = r.and_then(pdu_of);
        match helper.as_mut() {
            // With the helper the clock follows the PLC's scans (see `super::helper`).
            Some(h) if heartbeat_clock => {
                if let Some(n) = h.scans_before(&space, pdu, recorded_pdu.as_deref()) {
                    h.catch_up(&mut sim.lock().unwrap_or_else(|p| p.into_inner()), clock, n);
                }
            }
            _ => {
                if let (Some(t0), Some(t)) = (vt0, req.vt) {
                    step_to(clock, base + t.saturating_sub(t0));
                }
            }
        }
        // The simulator's RTU framing decodes the request, whatever transport carried it.
        let mut adu = Vec::with_capacity(pdu.len() + 3);
        adu.push(unit);
        adu.extend_from_slice(pdu);
        adu.extend_from_slice(&rtu_frame::crc16(&adu).to_le_bytes());
        let replayed: Option<Vec<u8>> = match rtu_frame::next_frame(&mut adu) {
            Some(rtu_frame::Frame::Request { unit, request }) => service
                .handle(unit, &request)
                .map(|reply| rtu_frame::encode(unit, request.function_code().value(), &reply)),
            Some(rtu_frame::Frame::Refuse { unit, function, exception }) => {
                (unit == service.unit()).then(|| rtu_frame::encode(unit, function, &Err(exception)))
            }
            None => None,
        };
        // Compare PDUs (unit … CRC and MBAP framing are transport matters).
        let mut replayed_pdu = replayed.as_ref().map(|b| b[1..b.len() - 2].to_vec());
        if let (Some(h), Some(p)) = (helper.as_mut(), replayed_pdu.as_mut()) {
            h.match_heartbeat(&space, pdu, recorded_pdu.as_deref(), p);
        }
        if replayed_pdu == recorded_pdu {
            continue;
        }
        let (dq, asked) = decode::modbus(&space, unit, pdu, Dir::Sent, None);
        let detail = modbus_detail(&space, asked, recorded_pdu.as_deref(), replayed_pdu.as_deref());
        report.differences.push(Difference {
            frame: q + 1,
            device: link.name.clone(),
            vt: req.vt.map(|v| v.as_secs_f64()),
            request: dq.text,
            recorded: r.map(|r| hex_bytes(&rec.frames[r].bytes)).unwrap_or_default(),
            replayed: replayed.map(|b| hex_bytes(&b)).unwrap_or_default(),
            detail,
        });
    }
}

/// What differs between two reply PDUs, by operand for reads.
fn modbus_detail(space: &K2Space, asked: Option<Asked>, recorded: Option<&[u8]>, replayed: Option<&[u8]>) -> String {
    let (Some(a), Some(b)) = (recorded, replayed) else {
        return match recorded {
            None => crate::msg!("replay-no-reply-recorded").text,
            Some(_) => crate::msg!("replay-no-reply-replayed").text,
        };
    };
    let describe = |p: &[u8]| decode::modbus(space, 0, p, Dir::Received, asked).0;
    let (da, db) = (describe(a), describe(b));
    if da.exception.is_some() || db.exception.is_some() || da.values.len() != db.values.len() {
        return format!("recorded {}, replayed {}", da.text, db.text);
    }
    let Some(q) = asked else { return format!("recorded {}, replayed {}", da.text, db.text) };
    let table = modbus_map::Table::of_fc(q.fc).map(|(t, _)| t);
    let mut parts = Vec::new();
    for (i, (x, y)) in da.values.iter().zip(&db.values).enumerate() {
        if x != y {
            let addr = q.addr.wrapping_add(i as u16);
            let name =
                table.and_then(|t| modbus_map::operand_at(space, t, addr)).unwrap_or_else(|| format!("address {addr}"));
            parts.push(format!("{name} (address {addr}) recorded {x}, replayed {y}"));
        }
    }
    if parts.is_empty() {
        format!("recorded {}, replayed {}", da.text, db.text)
    } else {
        parts.join("; ")
    }
}

fn servo_link(rec: &Recording, ex: &[Exchange], link: &LinkInfo, sims: &Sims, report: &mut Report) {
    use crate::servo::frame::FRAME_LEN;
    let line = sims.line.clone().expect("a drive line for a servo link");
    let vt0 = sims.vt0.or_else(|| ex.first().and_then(|(q, _)| rec.frames[*q].vt));
    for &(q, r) in ex {
        let req = &rec.frames[q];
        report.requests += 1;
        if let (Some(t0), Some(t)) = (vt0, req.vt) {
            step_to(&sims.clock, sims.base + t.saturating_sub(t0));
        }
        let Ok(bytes) = <[u8; FRAME_LEN]>::try_from(req.bytes.as_slice()) else { continue };
        let replayed = line.lock().unwrap_or_else(|p| p.into_inner()).answer(&bytes).map(|b| b.to_vec());
        let recorded = r.map(|r| rec.frames[r].bytes.clone());
        if replayed == recorded {
            continue;
        }
        let show = |b: &Option<Vec<u8>>| b.as_ref().map(|b| decode::servo(b).text).unwrap_or_else(|| "no reply".into());
        report.differences.push(Difference {
            frame: q + 1,
            device: link.name.clone(),
            vt: req.vt.map(|v| v.as_secs_f64()),
            request: decode::servo(&req.bytes).text,
            recorded: recorded.as_ref().map(|b| hex_bytes(b)).unwrap_or_default(),
            replayed: replayed.as_ref().map(|b| hex_bytes(b)).unwrap_or_default(),
            detail: format!("recorded {}, replayed {}", show(&recorded), show(&replayed)),
        });
    }
}

/// Refuses a recording with nothing to replay.
pub fn check_not_empty(rec: &Recording, path: &std::path::Path) -> Result<()> {
    if rec.frames.iter().any(|f| f.dir == Dir::Sent) {
        Ok(())
    } else {
        Err(Error::usage(crate::msg!("replay-no-requests", file = path.display().to_string()))
            .hint(crate::msg!("replay-hint-record")))
    }
}
