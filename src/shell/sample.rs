//! Periodic sampling for `watch` and `trace`: read a set of operands every `every` of the
//! session clock until a count, a time span or Ctrl-C. Sample k is due at start + k·every,
//! so read time does not accumulate into drift; on a stepped simulator clock the waits
//! advance virtual time instantly (an hour of trace costs only its reads), on the wall clock
//! they are real. Works with any device the session can read.

use super::lex;
use super::Args;
use crate::core::literal::parse_option_duration_us;
use crate::core::{Error, Result};
use crate::session::{Reading, Session};
use std::time::{Duration, Instant};

/// When to sample and when to stop.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Plan {
    pub every: Duration,
    /// Stop after this many samples.
    pub count: Option<u64>,
    /// Stop after this span of clock time (samples at 0, every, …, ≤ span).
    pub span: Option<Duration>,
}

/// One sample: its index, clock time since the first sample, and the readings.
pub struct Sample {
    pub index: u64,
    pub t: Duration,
    pub readings: Vec<Reading>,
}

/// What a sampling run achieved (for `--verbose`).
#[derive(Clone, Copy, Debug, Default)]
pub struct Stats {
    pub samples: u64,
    /// Wall-clock time from the first sample to the last.
    pub wall: Duration,
    /// Session-clock time from the first sample to the last.
    pub clock: Duration,
    /// Wire requests the devices sent meanwhile.
    pub requests: u64,
    pub interrupted: bool,
}

impl Stats {
    /// Samples per second of wall time (what a user watching sees).
    pub fn wall_rate(&self) -> f64 {
        rate(self.samples, self.wall)
    }
    /// Samples per second of session time (virtual on a stepped simulator).
    pub fn clock_rate(&self) -> f64 {
        rate(self.samples, self.clock)
    }
    /// `25 samples in 4.801 s wall (5.2 Hz) …` for `--verbose`.
    pub fn report(&self, cmd: &str, plan: &Plan) -> String {
        crate::msg!(
            "shell-sample-report",
            command = cmd,
            samples = self.samples,
            clock = format!("{:.3}", self.clock.as_secs_f64()),
            clock_rate = format!("{:.1}", self.clock_rate()),
            asked_rate = format!("{:.1}", 1.0 / plan.every.as_secs_f64()),
            wall = format!("{:.3}", self.wall.as_secs_f64()),
            wall_rate = format!("{:.1}", self.wall_rate()),
            requests = self.requests,
            interrupted = if self.interrupted { "yes" } else { "no" }
        )
        .text
    }
}

/// Rate of n samples spanning `d` (n samples have n-1 intervals).
fn rate(n: u64, d: Duration) -> f64 {
    if n < 2 || d.is_zero() {
        0.0
    } else {
        (n - 1) as f64 / d.as_secs_f64()
    }
}

/// Parsed `OPERAND… key=value…` arguments.
#[derive(Debug)]
pub struct Request<'a> {
    pub operands: Vec<(usize, &'a str)>,
    pub plan: Plan,
    /// Other options (`to=`), with their columns.
    pub options: Vec<(usize, &'a str, &'a str)>,
}

fn duration(col: usize, key: &str, v: &str) -> Result<Duration> {
    let us = parse_option_duration_us(v).map_err(|m| Error::usage(format!("{key}={v}: {m}")).column(col))?;
    if us <= 0 {
        return Err(Error::usage(crate::msg!("shell-option-positive", key = key)).column(col));
    }
    Ok(Duration::from_micros(us as u64))
}

/// Splits operands from `every=`, `count=`, `for=` and the `extra` option keys.
pub fn parse<'a>(args: &Args<'a>, default_every: Duration, extra: &[&str], usage: &str) -> Result<Request<'a>> {
    let words = lex::words(args.text).map_err(|e| e.shift(args.offset))?;
    let (pos, opts) = lex::options(&words);
    if pos.is_empty() {
        return Err(Error::usage(crate::msg!("shell-name-an-operand")).hint(usage.to_string()).column(args.offset));
    }
    let mut plan = Plan { every: default_every, count: None, span: None };
    let mut options = Vec::new();
    for (c, k, v) in opts {
        let col = args.offset + c;
        match k {
            "every" => plan.every = duration(col, k, v)?,
            "for" => plan.span = Some(duration(col, k, v)?),
            "count" => {
                let n: u64 = v
                    .parse()
                    .map_err(|_| Error::usage(crate::msg!("shell-count-not-number", value = v)).column(col))?;
                if n == 0 {
                    return Err(Error::usage(crate::msg!("shell-count-at-least-one")).column(col));
                }
                plan.count = Some(n);
            }
            k if extra.contains(&k) => options.push((col, k, v)),
            _ => {
                let mut known = vec!["every", "count", "for"];
                known.extend_from_slice(extra);
                return Err(Error::usage(crate::msg!("shell-unknown-option", key = k)).column(col).hint(crate::msg!(
                    "shell-hint-options",
                    options = known.join(", "),
                    usage = usage
                )));
            }
        }
    }
    let operands = pos.into_iter().map(|(c, w)| (args.offset + c, w)).collect();
    Ok(Request { operands, plan, options })
}

/// Operand labels as shown (`VW0`, a tag's name `Tank2_Level`, or `press:VW0` when several
/// devices are involved), checked
/// before the first read.
pub fn labels(session: &Session, operands: &[(usize, &str)]) -> Result<Vec<String>> {
    let mut targets = Vec::new();
    for &(col, w) in operands {
        targets.push(session.resolve(w).map_err(|e| e.shift(col))?);
    }
    let many = targets.iter().any(|t| t.device != targets[0].device);
    let mut out = Vec::new();
    for t in &targets {
        for op in &t.ops {
            // A tag's name labels its series (`crate::names`); else the operand.
            let name = session.label_of(t.device, op);
            out.push(if many { format!("{}:{name}", session.entries()[t.device].name) } else { name });
        }
    }
    Ok(out)
}

fn requests(session: &Session) -> u64 {
    session.entries().iter().map(|e| e.device.requests()).sum()
}

/// Samples `texts` by `plan`, calling `on` with each sample; stops at the count, the span or
/// Ctrl-C (the session's interrupt flag).
pub fn run(
    session: &mut Session,
    texts: &[&str],
    plan: &Plan,
    mut on: impl FnMut(&Sample) -> Result<()>,
) -> Result<Stats> {
    let clock = session.clock.clone();
    let start = clock.now();
    let wall = Instant::now();
    let req0 = requests(session);
    let mut stats = Stats::default();
    let mut k: u64 = 0;
    loop {
        // The first sample defines time zero; later ones carry their measured clock time.
        let t = if k == 0 { Duration::ZERO } else { clock.now().saturating_sub(start) };
        let readings = session.get(texts)?.into_iter().map(|(_, r)| r).collect();
        on(&Sample { index: k, t, readings })?;
        k += 1;
        stats.samples = k;
        stats.clock = t;
        stats.wall = wall.elapsed();
        let due = plan.every * k as u32;
        if plan.count.is_some_and(|n| k >= n) || plan.span.is_some_and(|s| due > s) {
            break;
        }
        let now = clock.now().saturating_sub(start);
        let ok = if due > now { session.sleep(due - now) } else { !session.interrupted() };
        if !ok {
            stats.interrupted = true;
            break;
        }
    }
    stats.requests = requests(session) - req0;
    Ok(stats)
}

/// A finished trace: one column of values per operand over common sample times. Kept by the
/// shell as the last trace for `plot`.
#[derive(Clone, Debug, Default, PartialEq)]
pub struct Recording {
    pub labels: Vec<String>,
    /// Sample times in seconds of session clock since the first sample.
    pub t: Vec<f64>,
    /// `columns[i][k]` is operand i at sample k (bits as 0/1).
    pub columns: Vec<Vec<f64>>,
    pub every: Duration,
    /// Pulse outputs drawn as frequency: (output bit column, pulse count column).
    pub rates: Vec<(usize, usize)>,
}

impl Recording {
    pub fn new(labels: Vec<String>, every: Duration) -> Recording {
        let columns = vec![Vec::new(); labels.len()];
        Recording { labels, t: Vec::new(), columns, every, rates: Vec::new() }
    }

    pub fn push(&mut self, s: &Sample) {
        self.t.push(s.t.as_secs_f64());
        for (col, r) in self.columns.iter_mut().zip(&s.readings) {
            col.push(r.value.as_f64());
        }
    }

    /// CSV: a header `t_s,VW0,SMD72` and one row per sample.
    pub fn csv(&self) -> String {
        let mut out = format!("t_s,{}\n", self.labels.join(","));
        for (k, t) in self.t.iter().enumerate() {
            out.push_str(&format!("{t:.6}"));
            for c in &self.columns {
                out.push_str(&format!(",{}", crate::plot::number(c[k])));
            }
            out.push('\n');
        }
        out
    }

    /// The named operands (all when `names` is empty) as plot series; a name not traced is an
    /// error listing the traced ones.
    pub fn series(&self, names: &[&str]) -> Result<Vec<crate::plot::Series>> {
        let pick: Vec<usize> = if names.is_empty() {
            (0..self.labels.len()).collect()
        } else {
            names
                .iter()
                .map(|n| {
                    self.labels.iter().position(|l| l.eq_ignore_ascii_case(n)).ok_or_else(|| {
                        Error::usage(crate::msg!("shell-not-traced", name = *n))
                            .hint(crate::msg!("shell-hint-traced", names = self.labels.join(", ")))
                    })
                })
                .collect::<Result<_>>()?
        };
        Ok(pick
            .into_iter()
            .map(|i| match self.rates.iter().find(|(b, _)| *b == i) {
                Some(&(_, c)) => self.frequency(i, c),
                None => {
                    let pts = self.t.iter().copied().zip(self.columns[i].iter().copied()).collect();
                    crate::plot::Series::new(self.labels[i].clone(), "", pts)
                }
            })
            .collect())
    }

    /// Output `bit` as its frequency: the pulse count's change over each sample interval
    /// (pulses in either direction count), held over the interval.
    fn frequency(&self, bit: usize, count: usize) -> crate::plot::Series {
        let c = &self.columns[count];
        let mut pts = Vec::with_capacity(self.t.len());
        for k in 1..self.t.len() {
            let dt = self.t[k] - self.t[k - 1];
            let f = if dt > 0.0 { (c[k] - c[k - 1]).abs() / dt } else { 0.0 };
            pts.push((self.t[k - 1], f));
        }
        if let (Some(&t), Some(&(_, f))) = (self.t.last(), pts.last()) {
            pts.push((t, f));
        }
        crate::plot::Series::new(format!("{} frequency", self.labels[bit]), "Hz", pts).stepped()
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::core::Clock;

    fn args(text: &str) -> Args<'_> {
        Args { text, offset: 6 }
    }

    #[test]
    fn options_are_parsed_and_checked() {
        let r = parse(&args("VW0 SMB67 every=10ms for=2s"), Duration::from_millis(200), &[], "u").unwrap();
        assert_eq!(r.operands, vec![(6, "VW0"), (10, "SMB67")]);
        assert_eq!(r.plan, Plan { every: Duration::from_millis(10), count: None, span: Some(Duration::from_secs(2)) });
        let e = parse(&args("VW0 every=0s"), Duration::from_millis(200), &[], "u").unwrap_err();
        assert_eq!(e.column, Some(10));
        assert!(parse(&args("VW0 colour=red"), Duration::from_millis(200), &[], "u")
            .unwrap_err()
            .message
            .contains("colour"));
        let r = parse(&args("VW0 to=x.csv"), Duration::from_millis(200), &["to"], "u").unwrap();
        assert_eq!(r.options, vec![(10, "to", "x.csv")]);
        assert!(parse(&args("count=3"), Duration::from_millis(200), &[], "u").is_err());
    }

    #[test]
    fn a_stepped_clock_samples_at_exact_virtual_times() {
        let mut s = Session::new(Clock::stepped());
        s.open("plc", "sim:K205-16DT").unwrap();
        let plan = Plan { every: Duration::from_millis(10), count: None, span: Some(Duration::from_secs(2)) };
        let mut times = Vec::new();
        let mut uptime = Vec::new();
        let stats = run(&mut s, &["SM0.5"], &plan, |x| {
            times.push(x.t);
            uptime.push(x.readings[0].value.as_i64());
            Ok(())
        })
        .unwrap();
        assert_eq!(stats.samples, 201, "0, 10 ms … 2 s");
        assert_eq!(times[200], Duration::from_secs(2));
        assert!(times.windows(2).all(|w| w[1] - w[0] == Duration::from_millis(10)));
        assert_eq!(s.clock.now(), Duration::from_secs(2), "the clock moved exactly the traced span");
        assert!((stats.clock_rate() - 100.0).abs() < 1e-9);
        // SM0.5 (1 s clock) is on for the first 500 ms of virtual time: the device saw it.
        assert_eq!((uptime[49], uptime[51], uptime[101]), (1, 0, 1));
    }

    #[test]
    fn count_and_interrupt_stop_sampling() {
        let mut s = Session::new(Clock::stepped());
        s.open("plc", "sim:K205-16DT").unwrap();
        let plan = Plan { every: Duration::from_millis(200), count: Some(3), span: None };
        assert_eq!(run(&mut s, &["VW0"], &plan, |_| Ok(())).unwrap().samples, 3);
        let plan = Plan { every: Duration::from_millis(200), count: None, span: None };
        let flag = s.interrupt.clone();
        let stats = run(&mut s, &["VW0"], &plan, |x| {
            if x.index == 4 {
                flag.store(true, std::sync::atomic::Ordering::Relaxed);
            }
            Ok(())
        })
        .unwrap();
        assert_eq!(stats.samples, 5);
        assert!(stats.interrupted);
    }
}
