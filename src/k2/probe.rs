//! `plcsh probe`: what a K2 answers over Modbus before anything is installed in it, found with
//! reads only. For each area of the K2 Modbus map (manual §3.2.1, [`REGIONS`]) it finds whether
//! the area answers and its highest valid address, with few requests: one read of the area's
//! first address, then reads at first + 1, + 2, + 4 … until one is refused with exception 02
//! (illegal data address, Modbus Application Protocol V1.1b3 §7), then a binary search between
//! the last address that answered and the first refused — about 2·log₂(size) reads an area.
//! The sizes found are compared with every catalogue model's ([`catalog::MODELS`]), and 100
//! reads of one register give the response time (p50, p99).
//!
//! Pure: the reads come through [`Reader`] (the wire driver's, or a fake in tests); every
//! request is a read of one unit (FC 01, 02, 03 or 04), so a probe writes nothing by
//! construction: [`Reader::read`] has no way to ask for anything else.
//!
//! What the manual is silent on, and whose convention is followed: the manual gives the map's
//! bases and the models' area sizes but not what the PLC answers past an area's end. A probe
//! takes exception 02 as "past the end" (the Modbus specification's meaning of it); another
//! exception stops the area's search and is reported as such, and an area that answers up to
//! the next area's base is reported as "no end found".

use super::catalog::{self, Model};
use super::modbus_map::{exception_name, Region, Table, REGIONS};
use super::operand::Area;
use super::space::K2Space;
use serde::Serialize;
use std::time::Duration;

/// What one read of one unit got.
#[derive(Clone, Debug, PartialEq)]
pub enum Answer {
    /// Data came back, after this long.
    Data(Duration),
    /// A Modbus exception reply with this code.
    Exception(u8),
    /// No valid reply (timeout, garbled reply, closed connection): the link's message and hint.
    Failed { message: String, hint: String },
}

/// One-unit reads on some link. Nothing else can be asked: a probe never writes.
pub trait Reader {
    /// Reads one bit (coils, discrete inputs) or one register at `addr` of `table`.
    fn read(&mut self, table: Table, addr: u16) -> Answer;
}

/// How far an area answered.
#[derive(Clone, Debug, PartialEq, Serialize)]
#[serde(tag = "state", rename_all = "kebab-case")]
pub enum Extent {
    /// Addresses `first` … `last` answer; `last + 1` was refused with exception 02.
    Answers { last: u16 },
    /// Every address up to the next area's base (or 65535) answered: no end found.
    NoEnd { last: u16 },
    /// The area's first address is refused with exception 02: this PLC has no such area.
    Absent,
    /// A read was refused with another exception; `last` is the highest address that
    /// answered before it (none when the first read was refused).
    Refused { code: u8, name: &'static str, at: u16, last: Option<u16> },
    /// A read got no valid reply; `last` as for `Refused`.
    NoReply { at: u16, last: Option<u16>, message: String },
}

/// One area of the map as the PLC answered it.
#[derive(Clone, Debug, Serialize)]
pub struct AreaFound {
    pub table: &'static str,
    pub area: &'static str,
    pub fc: u8,
    /// The area's first Modbus address (manual §3.2.1).
    pub first: u16,
    pub extent: Extent,
    /// Units that answered (bits or registers), when the end was found.
    pub units: Option<u32>,
    /// Reads this area took.
    pub requests: u32,
}

/// Response times of repeated reads of one register.
#[derive(Clone, Debug, Serialize)]
pub struct Timing {
    pub what: String,
    pub reads: u32,
    pub failed: u32,
    pub p50_ms: Option<f64>,
    pub p99_ms: Option<f64>,
    pub max_ms: Option<f64>,
}

/// One finding: what holds or failed, and what to do.
#[derive(Clone, Debug, Serialize)]
pub struct Verdict {
    pub ok: bool,
    pub what: String,
    #[serde(skip_serializing_if = "Option::is_none")]
    pub todo: Option<String>,
}

/// A whole probe.
#[derive(Clone, Debug, Serialize)]
pub struct Probe {
    pub areas: Vec<AreaFound>,
    /// Catalogue models whose every area size matches what answered.
    pub models: Vec<&'static str>,
    pub timing: Option<Timing>,
    pub requests: u32,
    pub verdicts: Vec<Verdict>,
}

impl Probe {
    /// True when nothing failed.
    pub fn ok(&self) -> bool {
        self.verdicts.iter().all(|v| v.ok)
    }
}

/// The highest address an area's search may reach: one below the next area's base in the same
/// table, or the top of the address space.
fn cap(r: &Region) -> u16 {
    REGIONS.iter().filter(|o| o.table == r.table && o.base > r.base).map(|o| o.base - 1).min().unwrap_or(u16::MAX)
}

/// Finds how far one area answers.
pub fn search(reader: &mut dyn Reader, r: &Region) -> AreaFound {
    let mut requests = 0u32;
    let mut ask = |a: u16| {
        requests += 1;
        reader.read(r.table, a)
    };
    let first = r.base;
    let top = cap(r);
    let stop = |a: Answer, at: u16, last: Option<u16>| match a {
        Answer::Exception(2) if last.is_none() => Extent::Absent,
        Answer::Exception(code) => Extent::Refused { code, name: exception_name(code), at, last },
        Answer::Failed { message, .. } => Extent::NoReply { at, last, message },
        Answer::Data(_) => unreachable!("data is not a stop"),
    };
    let extent = 'search: {
        match ask(first) {
            Answer::Data(_) => {}
            a => break 'search stop(a, first, None),
        }
        // Exponential: lo answers, hi (once known) is refused with 02.
        let mut lo = first;
        let mut step: u32 = 1;
        let hi = loop {
            let a = (first as u32 + step).min(top as u32) as u16;
            if a == lo {
                break 'search Extent::NoEnd { last: lo };
            }
            match ask(a) {
                Answer::Data(_) => lo = a,
                Answer::Exception(2) => break a,
                other => break 'search stop(other, a, Some(lo)),
            }
            step *= 2;
        };
        // Binary search between lo (answers) and hi (refused).
        let mut hi = hi;
        while hi - lo > 1 {
            let mid = lo + (hi - lo) / 2;
            match ask(mid) {
                Answer::Data(_) => lo = mid,
                Answer::Exception(2) => hi = mid,
                other => break 'search stop(other, mid, Some(lo)),
            }
        }
        Extent::Answers { last: lo }
    };
    let units = match extent {
        Extent::Answers { last } => Some((last - first) as u32 + 1),
        Extent::Absent => Some(0),
        _ => None,
    };
    AreaFound { table: r.table.name(), area: r.area.name(), fc: r.table.read_fc(), first, extent, units, requests }
}

/// The catalogue models every known area size of `areas` fits.
pub fn fitting(areas: &[AreaFound]) -> Vec<&'static str> {
    catalog::MODELS.iter().filter(|m| fits(m, areas)).map(|m| m.name).collect()
}

fn fits(m: &'static Model, areas: &[AreaFound]) -> bool {
    let space = K2Space::new(m);
    REGIONS.iter().zip(areas).all(|(r, a)| match a.units {
        Some(n) => n == r.len(&space),
        None => true,
    })
}

/// Nearest-rank percentile of sorted durations.
fn percentile(sorted: &[Duration], p: f64) -> Option<f64> {
    if sorted.is_empty() {
        return None;
    }
    let rank = ((p * sorted.len() as f64).ceil() as usize).clamp(1, sorted.len());
    Some(sorted[rank - 1].as_secs_f64() * 1000.0)
}

/// `n` reads of one unit at (`table`, `addr`), timed.
pub fn time_reads(reader: &mut dyn Reader, table: Table, addr: u16, what: String, n: u32) -> Timing {
    let mut times = Vec::new();
    let mut failed = 0;
    for _ in 0..n {
        match reader.read(table, addr) {
            Answer::Data(d) => times.push(d),
            _ => failed += 1,
        }
    }
    times.sort();
    Timing {
        what,
        reads: n,
        failed,
        p50_ms: percentile(&times, 0.50),
        p99_ms: percentile(&times, 0.99),
        max_ms: times.last().map(|d| d.as_secs_f64() * 1000.0),
    }
}

/// The area a timing run reads: V through holding register 100 (VW0) when it answers, else the
/// first area that answered.
fn timing_target(areas: &[AreaFound]) -> Option<(Table, u16, String)> {
    let answered = |a: &AreaFound| matches!(a.extent, Extent::Answers { .. } | Extent::NoEnd { .. });
    let pick = REGIONS
        .iter()
        .zip(areas)
        .find(|(r, a)| r.table == Table::HoldingRegisters && r.area == Area::V && answered(a))
        .or_else(|| REGIONS.iter().zip(areas).find(|(_, a)| answered(a)))?;
    let (r, a) = pick;
    Some((r.table, r.base, format!("{} {} ({} FC {:02})", a.table, r.base, a.area, r.table.read_fc())))
}

/// What to do about exception `code` on a read.
fn exception_todo(code: u8) -> String {
    match code {
        1 => crate::msg!("probe-todo-exception-01").text,
        4 => crate::msg!("probe-todo-exception-04").text,
        6 => crate::msg!("probe-todo-exception-06").text,
        0x0A | 0x0B => crate::msg!("probe-todo-gateway").text,
        _ => crate::msg!("probe-todo-attach").text,
    }
}

/// Probes every area, fits the models, times `reads` reads.
pub fn run(reader: &mut dyn Reader, reads: u32, link_hint: &str) -> Probe {
    let mut areas: Vec<AreaFound> = Vec::new();
    for r in REGIONS {
        let a = search(reader, r);
        let silent = matches!(a.extent, Extent::NoReply { last: None, .. });
        areas.push(a);
        if silent && areas.iter().all(|a| matches!(a.extent, Extent::NoReply { last: None, .. })) {
            // Nothing has answered yet: one area's silence is the link's, not the area's.
            break;
        }
    }
    let mut probe = Probe { models: Vec::new(), timing: None, requests: 0, verdicts: Vec::new(), areas };
    probe.requests = probe.areas.iter().map(|a| a.requests).sum();
    if probe.areas.iter().all(|a| matches!(a.extent, Extent::NoReply { last: None, .. })) {
        let msg = match &probe.areas[0].extent {
            Extent::NoReply { message, .. } => message.clone(),
            _ => String::new(),
        };
        probe.verdicts.push(Verdict {
            ok: false,
            what: crate::msg!(
                "probe-no-answer",
                table = probe.areas[0].table.to_string(),
                address = probe.areas[0].first,
                message = msg
            )
            .text,
            todo: Some(link_hint.to_string()),
        });
        return probe;
    }
    for a in &probe.areas {
        match &a.extent {
            Extent::Refused { code, name, at, .. } => probe.verdicts.push(Verdict {
                ok: false,
                what: crate::msg!(
                    "probe-refused",
                    table = a.table.to_string(),
                    address = *at,
                    area = a.area.to_string(),
                    fc = format!("{:02}", a.fc),
                    code = format!("{code:02}"),
                    name = name.to_string()
                )
                .text,
                todo: Some(exception_todo(*code)),
            }),
            Extent::NoReply { at, message, .. } => probe.verdicts.push(Verdict {
                ok: false,
                what: crate::msg!(
                    "probe-no-reply",
                    table = a.table.to_string(),
                    address = *at,
                    area = a.area.to_string(),
                    fc = format!("{:02}", a.fc),
                    message = message.as_str()
                )
                .text,
                todo: Some(crate::msg!("probe-todo-link-again", hint = link_hint).text),
            }),
            _ => {}
        }
    }
    probe.models = fitting(&probe.areas);
    let shown = |a: &AreaFound| format!("{} {}: {}", a.area, a.table, a.units.map_or("?".into(), |n| n.to_string()));
    if probe.models.is_empty() {
        let found: Vec<String> = probe.areas.iter().map(shown).collect();
        probe.verdicts.push(Verdict {
            ok: false,
            what: crate::msg!("probe-no-model", sizes = found.join(", ")).text,
            todo: Some(crate::msg!("probe-todo-no-model").text),
        });
    } else {
        probe.verdicts.push(Verdict {
            ok: true,
            what: crate::msg!("probe-models-fit", count = probe.models.len(), models = probe.models.join(", ")).text,
            todo: (probe.models.len() > 1).then(|| crate::msg!("probe-todo-same-areas").text),
        });
    }
    let v_holding = REGIONS.iter().position(|r| r.table == Table::HoldingRegisters && r.area == Area::V);
    if let Some(a) = v_holding.and_then(|i| probe.areas.get(i)) {
        let end = match a.extent {
            Extent::Answers { last } | Extent::NoEnd { last } => Some(last),
            _ => None,
        };
        let helper_last = (super::agent::protocol::DEFAULT_BASE + super::agent::protocol::TOTAL_SIZE) / 2 + 100;
        if end.is_none_or(|l| (l as u32) < helper_last) {
            probe.verdicts.push(Verdict {
                ok: false,
                what: crate::msg!(
                    "probe-no-mailbox",
                    register = helper_last,
                    first = super::agent::protocol::DEFAULT_BASE,
                    last = super::agent::protocol::DEFAULT_BASE + super::agent::protocol::TOTAL_SIZE - 1
                )
                .text,
                todo: Some(crate::msg!("probe-todo-mailbox").text),
            });
        }
    }
    if let Some((table, addr, what)) = timing_target(&probe.areas) {
        let t = time_reads(reader, table, addr, what, reads);
        probe.requests += reads;
        if t.failed > 0 {
            probe.verdicts.push(Verdict {
                ok: false,
                what: crate::msg!("probe-timed-failed", failed = t.failed, reads = t.reads, what = t.what.as_str())
                    .text,
                todo: Some(crate::msg!("probe-todo-link-slow", hint = link_hint).text),
            });
        } else {
            probe.verdicts.push(Verdict {
                ok: true,
                what: crate::msg!(
                    "probe-timed",
                    reads = t.reads,
                    what = t.what.as_str(),
                    p50 = format!("{:.2}", t.p50_ms.unwrap_or(0.0)),
                    p99 = format!("{:.2}", t.p99_ms.unwrap_or(0.0))
                )
                .text,
                todo: None,
            });
        }
        probe.timing = Some(t);
    }
    probe
}

/// The areas as table rows: table, FC, area, first, last, units, reads, result.
pub fn rows(p: &Probe) -> Vec<Vec<String>> {
    p.areas
        .iter()
        .map(|a| {
            let (last, note) = match &a.extent {
                Extent::Answers { last } => (last.to_string(), crate::msg!("probe-result-answers").text),
                Extent::NoEnd { last } => (last.to_string(), crate::msg!("probe-result-no-end").text),
                Extent::Absent => ("-".into(), crate::msg!("probe-result-absent").text),
                Extent::Refused { code, name, at, last } => (
                    last.map_or("-".into(), |l| l.to_string()),
                    crate::msg!(
                        "probe-result-refused",
                        code = format!("{code:02}"),
                        name = name.to_string(),
                        address = *at
                    )
                    .text,
                ),
                Extent::NoReply { at, last, .. } => (
                    last.map_or("-".into(), |l| l.to_string()),
                    crate::msg!("probe-result-no-reply", address = *at).text,
                ),
            };
            vec![
                a.table.to_string(),
                format!("{:02}", a.fc),
                a.area.to_string(),
                a.first.to_string(),
                last,
                a.units.map_or("?".into(), |n| n.to_string()),
                a.requests.to_string(),
                note,
            ]
        })
        .collect()
}

/// Column headers of [`rows`].
pub const HEADERS: &[&str] = &["table", "FC", "area", "first", "last", "units", "reads", "result"];

/// The probe as a Markdown report a user can attach: the link, the areas, the models, the
/// timing, the verdicts.
pub fn markdown(p: &Probe, url: &str, serial: Option<&str>, version: &str) -> String {
    let mut s = format!(
        "# {}\n\n- plcsh {version}\n- {}\n",
        crate::msg!("agent-probe-report-title"),
        crate::msg!("agent-probe-report-device", url = url)
    );
    if let Some(line) = serial {
        s.push_str(&format!("- {}\n", crate::msg!("probe-serial-answered", settings = line)));
    }
    s.push_str(&format!("- {}\n\n", crate::msg!("agent-probe-report-requests", requests = p.requests)));
    s.push_str(&format!("## {}\n\n", crate::msg!("agent-probe-report-areas")));
    s.push_str(&format!("| {} |\n|{}\n", HEADERS.join(" | "), "---|".repeat(HEADERS.len())));
    for r in rows(p) {
        s.push_str(&format!("| {} |\n", r.join(" | ")));
    }
    s.push_str(&format!("\n## {}\n\n", crate::msg!("agent-probe-report-models")));
    if p.models.is_empty() {
        s.push_str(&format!("{}\n", crate::msg!("agent-probe-report-no-models")));
    } else {
        for m in &p.models {
            s.push_str(&format!("- {m}\n"));
        }
    }
    if let Some(t) = &p.timing {
        s.push_str(&format!(
            "\n## {}\n\n{}\n",
            crate::msg!("agent-probe-report-timing"),
            crate::msg!(
                "agent-probe-report-timed",
                reads = t.reads,
                what = t.what.as_str(),
                failed = t.failed,
                p50 = ms(t.p50_ms),
                p99 = ms(t.p99_ms),
                max = ms(t.max_ms)
            )
        ));
    }
    s.push_str(&format!("\n## {}\n\n", crate::msg!("agent-probe-report-verdicts")));
    for v in &p.verdicts {
        s.push_str(&format!("- {} {}\n", if v.ok { "ok:" } else { "FAILED:" }, v.what));
        if let Some(t) = &v.todo {
            s.push_str(&format!("  - {}\n", crate::msg!("probe-what-to-do", todo = t.as_str())));
        }
    }
    s
}

fn ms(v: Option<f64>) -> String {
    v.map_or("-".into(), |v| format!("{v:.2} ms"))
}

#[cfg(test)]
mod tests {
    use super::*;

    /// A PLC of `model` as a set of answering addresses, counting reads, with optional faults.
    struct Fake {
        space: K2Space,
        reads: u32,
        refuse_all: Option<u8>,
        silent_from: Option<u32>,
    }

    impl Reader for Fake {
        fn read(&mut self, table: Table, addr: u16) -> Answer {
            self.reads += 1;
            if self.silent_from.is_some_and(|n| self.reads >= n) {
                return Answer::Failed { message: "no reply".into(), hint: String::new() };
            }
            if let Some(c) = self.refuse_all {
                return Answer::Exception(c);
            }
            let inside = REGIONS
                .iter()
                .any(|r| r.table == table && (addr as u32) >= r.base as u32 && (addr as u32) < r.end(&self.space));
            if inside {
                Answer::Data(Duration::from_micros(500 + addr as u64 % 7))
            } else {
                Answer::Exception(2)
            }
        }
    }

    fn fake(model: &str) -> Fake {
        Fake { space: K2Space::new(catalog::find(model).unwrap()), reads: 0, refuse_all: None, silent_from: None }
    }

    #[test]
    fn every_model_is_found_by_its_own_sizes_with_few_reads() {
        for m in catalog::MODELS {
            let mut f = fake(m.name);
            let p = run(&mut f, 100, "check the link");
            assert!(p.models.contains(&m.name), "{}: {:?}", m.name, p.verdicts);
            for (r, a) in REGIONS.iter().zip(&p.areas) {
                assert_eq!(a.units, Some(r.len(&f.space)), "{} {:?}", m.name, r);
                // 2·log2(size) + 2 reads at most.
                let size = r.len(&f.space).max(1) as f64;
                assert!(a.requests as f64 <= 2.0 * size.log2() + 3.0, "{} {:?}: {} reads", m.name, r, a.requests);
            }
            assert_eq!(f.reads, p.requests, "every read is counted");
            assert!(p.ok(), "{}: {:?}", m.name, p.verdicts);
        }
    }

    #[test]
    fn models_with_the_same_areas_are_all_named() {
        let p = run(&mut fake("K205-16DT"), 10, "");
        assert!(p.models.contains(&"K205-16DR") && p.models.contains(&"K205EX-22DT"), "{:?}", p.models);
        assert!(!p.models.contains(&"K209M-56DT"));
        assert!(p.verdicts.iter().any(|v| v.todo.as_deref().unwrap_or("").contains("label")));
    }

    #[test]
    fn a_silent_plc_is_one_verdict_naming_the_link() {
        let mut f = fake("K205-16DT");
        f.silent_from = Some(1);
        let p = run(&mut f, 100, "check the wiring");
        assert_eq!(f.reads, 1, "one unanswered read, not a search of every area");
        assert!(!p.ok());
        assert_eq!(p.verdicts.len(), 1);
        assert!(p.verdicts[0].what.contains("did not answer"));
        assert_eq!(p.verdicts[0].todo.as_deref(), Some("check the wiring"));
    }

    #[test]
    fn exceptions_other_than_02_stop_the_area_and_say_what_to_do() {
        let mut f = fake("K205-16DT");
        f.refuse_all = Some(4);
        let p = run(&mut f, 100, "");
        assert!(!p.ok());
        let v = p.verdicts.iter().find(|v| v.what.contains("exception 04")).unwrap();
        assert!(v.todo.as_deref().unwrap().contains("device failure"), "{v:?}");
        assert!(p.timing.is_none(), "nothing answered to time");
    }

    #[test]
    fn a_line_that_fails_midway_keeps_what_was_found() {
        let mut f = fake("K209M-56DT");
        f.silent_from = Some(4);
        let p = run(&mut f, 10, "check");
        match &p.areas[0].extent {
            Extent::NoReply { last: Some(l), .. } => assert!(*l >= 1),
            e => panic!("{e:?}"),
        }
        assert!(!p.ok());
    }

    #[test]
    fn percentiles_are_nearest_rank() {
        let d: Vec<Duration> = (1..=100).map(Duration::from_millis).collect();
        assert_eq!(percentile(&d, 0.5), Some(50.0));
        assert_eq!(percentile(&d, 0.99), Some(99.0));
        assert_eq!(percentile(&[], 0.5), None);
    }

    #[test]
    fn the_report_has_the_table_the_models_and_the_verdicts() {
        let p = run(&mut fake("K204ET-16DT"), 10, "");
        let md = markdown(&p, "tcp://10.0.0.5", None, "0.1.0");
        assert!(md.contains("| holding registers | 03 | V | 100 | 2147 | 2048 |"), "{md}");
        assert!(md.contains("K204ET-16DT") && md.contains("## Verdicts"), "{md}");
    }
}
