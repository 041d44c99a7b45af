//! `trace OPERAND… every=10ms for=2s [to=FILE.csv]` records samples (on a simulator in its
//! virtual time: a stepped clock traces two seconds instantly) and keeps them as the shell's
//! last trace; `plot [OPERAND…] [to=FILE.png|.svg]` draws that trace in the terminal (a braille
//! line chart per operand, time on the x axis) and optionally as a picture (`crate::plot`). A
//! pulse output is traced with its channel's pulse count and drawn as its frequency.

use super::CommandSpec;
use crate::core::{Error, Result};
use crate::k2::K2Ops;
use crate::output::Outcome;
use crate::shell::progress::Progress;
use crate::shell::sample::{self, Recording};
use crate::shell::{lex, Args, Shell};
use std::time::Duration;

pub const TRACE: CommandSpec = CommandSpec {
    name: "trace",
    aliases: &[],
    usage: "trace OPERAND… every=10ms for=2s [to=FILE.csv]   e.g. trace SMD72 Q0.0 every=10ms for=2s",
    summary: || crate::msg!("summary-trace"),
    subcommands: &[],
    run: trace,
};

pub const PLOT: CommandSpec = CommandSpec {
    name: "plot",
    aliases: &[],
    usage: "plot [OPERAND…] [to=FILE.png|FILE.svg] [size=900x340] [width=60] [height=8]   e.g. plot Q0.0 to=ramp.png",
    summary: || crate::msg!("summary-plot"),
    subcommands: &[],
    run: plot,
};

fn write_file(sh: &Shell, path: &str, text: &str, col: usize) -> Result<()> {
    crate::shell::files::check_write(&sh.write_rule, path).map_err(|e| e.column(col))?;
    std::fs::write(path, text)
        .map_err(|e| Error::io(crate::msg!("shell-cannot-write", file = path, reason = e.to_string())).column(col))
}

fn trace(sh: &mut Shell, args: Args) -> Result<Outcome> {
    let req = sample::parse(&args, Duration::from_millis(10), &["to"], TRACE.usage)?;
    let mut plan = req.plan;
    if plan.span.is_none() && plan.count.is_none() {
        plan.span = Some(Duration::from_secs(2));
    }
    let mut labels = sample::labels(&sh.session, &req.operands)?;
    let mut texts: Vec<String> = req.operands.iter().map(|(_, t)| t.to_string()).collect();
    // A pulse output (Q0.0 of PTO0 …) sampled every few ms of a kHz train reads as a constant
    // 1: also sample its channel's pulse count (SMD212 …, §3.4.3.1) so `plot` can draw the
    // output as its frequency over time.
    let mut rates = Vec::new();
    for (bit, count) in pulse_counts(sh, &req.operands) {
        let Some(b) = labels.iter().position(|l| *l == bit) else { continue };
        let c = match labels.iter().position(|l| *l == count) {
            Some(c) => c,
            None => {
                labels.push(count.clone());
                texts.push(count);
                labels.len() - 1
            }
        };
        rates.push((b, c));
    }
    let texts: Vec<&str> = texts.iter().map(String::as_str).collect();
    let mut rec = Recording::new(labels, plan.every);
    rec.rates = rates;
    let total = plan.span.or(plan.count.map(|n| plan.every * n.saturating_sub(1) as u32));
    let mut progress = Progress::new("trace", total.filter(|_| !sh.session.clock.is_stepped()));
    let stats = sample::run(&mut sh.session, &texts, &plan, |s| {
        rec.push(s);
        progress.update(s.t, &crate::msg!("shell-samples", count = s.index + 1));
        Ok(())
    })?;
    progress.finish();
    if sh.verbose {
        eprintln!("{}", stats.report("trace", &plan));
    }
    let mut o = Outcome::new("trace");
    if let Some(&(col, _, path)) = req.options.iter().find(|(_, k, _)| *k == "to") {
        // The file as text: `to="журнал 1.csv"` (docs/commands.md, "Quoting").
        let path = lex::unquote(path);
        write_file(sh, &path, &rec.csv(), col)?;
        o = o.with("file", path.as_ref());
    }
    let rows = rec
        .labels
        .iter()
        .zip(&rec.columns)
        .map(|(l, c)| {
            let min = c.iter().copied().fold(f64::INFINITY, f64::min);
            let max = c.iter().copied().fold(f64::NEG_INFINITY, f64::max);
            let last = c.last().copied().unwrap_or(0.0);
            vec![
                l.clone(),
                c.len().to_string(),
                crate::plot::number(min),
                crate::plot::number(max),
                crate::plot::number(last),
            ]
        })
        .collect();
    let series: Vec<serde_json::Value> =
        rec.labels.iter().zip(&rec.columns).map(|(l, c)| serde_json::json!({"operand": l, "values": c})).collect();
    o = o
        .table(&["operand", "samples", "min", "max", "last"], rows)
        .with("samples", stats.samples)
        .with("every_us", plan.every.as_micros() as u64)
        .with("interrupted", stats.interrupted)
        .with("t_s", &rec.t)
        .with("series", series);
    sh.last_trace = Some(rec);
    Ok(o)
}

/// The pulse outputs among `operands` (as labelled) with their channel's pulse-count register.
fn pulse_counts(sh: &mut Shell, operands: &[(usize, &str)]) -> Vec<(String, String)> {
    let mut out = Vec::new();
    for &(_, text) in operands {
        let Ok(target) = sh.session.resolve(text) else { continue };
        let dev = target.device;
        // The operand (to find the pulse output) and its series label (a tag's name, if any).
        let names: Vec<(String, String)> =
            target.ops.iter().map(|o| (sh.session.name_of(dev, o), sh.session.label_of(dev, o))).collect();
        let prefix = text.trim().find(':').map(|c| text.trim()[..=c].to_string()).unwrap_or_default();
        let Some(k2) = crate::k2::ops(sh.session.entry(dev).device.as_mut()) else { continue };
        let model = k2.model();
        for (name, shown) in names {
            let Some(p) = model.pto.iter().find(|p| p.output == name) else { continue };
            let Some(r) = crate::k2::sm_map::PTO_REGS.iter().find(|r| r.channel == p.channel) else { continue };
            let label = |n: &str| if prefix.is_empty() { n.to_string() } else { format!("{prefix}{n}") };
            out.push((label(&shown), label(&format!("SMD{}", r.pos_cv))));
        }
    }
    out
}

fn plot(sh: &mut Shell, args: Args) -> Result<Outcome> {
    let words = lex::words(args.text).map_err(|e| e.shift(args.offset))?;
    let (names, opts) = lex::options(&words);
    let (mut width, mut height, mut to, mut size) = (60usize, 8usize, None, None);
    for (c, k, v) in opts {
        let col = args.offset + c;
        let num = |v: &str| -> Result<usize> {
            v.parse()
                .ok()
                .filter(|n| (2..=1000).contains(n))
                .ok_or_else(|| Error::usage(crate::msg!("shell-plot-not-a-size", key = k, value = v)).column(col))
        };
        match k {
            "to" => to = Some((col, lex::unquote(v))),
            "width" => width = num(v)?,
            "height" => height = num(v)?,
            "size" => size = Some(crate::plot::parse_size(v).map_err(|m| Error::usage(m).column(col))?),
            _ => return Err(Error::usage(crate::msg!("shell-unknown-option", key = k)).column(col).hint(PLOT.usage)),
        }
    }
    let rec = sh.last_trace.as_ref().ok_or_else(|| {
        Error::usage(crate::msg!("shell-plot-nothing")).hint(crate::msg!("shell-hint-plot-nothing")).column(args.offset)
    })?;
    let names: Vec<&str> = names.iter().map(|(_, n)| *n).collect();
    let series = rec.series(&names).map_err(|e| e.column(args.offset))?;
    let mut text = crate::plot::terminal(&series, width, height);
    let mut o = Outcome::new("plot").with("operands", series.iter().map(|s| s.name.clone()).collect::<Vec<_>>());
    if let Some((col, path)) = to {
        let size = size.unwrap_or_else(|| crate::plot::default_size(&series));
        let title = format!("trace, every {}", crate::plot::time(rec.every.as_secs_f64()));
        crate::shell::files::check_write(&sh.write_rule, &path).map_err(|e| e.column(col))?;
        crate::plot::write_picture(&path, &series, &title, size).map_err(|e| e.column(col))?;
        text.push_str(&format!("wrote {path}\n"));
        o = o.with("file", path.as_ref());
    }
    Ok(o.text(text.trim_end().to_string()))
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::core::Clock;
    use crate::output::Style;
    use crate::session::Session;

    fn shell() -> Shell {
        let mut s = Session::new(Clock::stepped());
        s.open("plc", "sim:K205-16DT").unwrap();
        Shell::new(s, Style { json: true, color: false })
    }

    #[test]
    fn trace_records_in_virtual_time_writes_csv_and_plot_draws_it() {
        let dir = std::env::temp_dir().join(format!("plcsh-trend-{}", std::process::id()));
        std::fs::create_dir_all(&dir).unwrap();
        let csv = dir.join("t.csv");
        let svg = dir.join("t.svg");
        let mut sh = shell();
        let r = sh.exec(&format!("trace SM0.5 VW0 every=100ms for=2s to={}", csv.display()));
        let o = r[0].as_ref().unwrap();
        assert_eq!(o.data["samples"], 21);
        assert_eq!(sh.session.clock.now(), Duration::from_secs(2), "virtual time, stepped instantly");
        let text = std::fs::read_to_string(&csv).unwrap();
        let lines: Vec<&str> = text.lines().collect();
        assert_eq!(lines[0], "t_s,SM0.5,VW0");
        assert_eq!(lines[1], "0.000000,1,0");
        assert_eq!(lines[7], "0.600000,0,0", "SM0.5 off from 500 ms");
        assert_eq!(lines.len(), 22);
        let r = sh.exec(&format!("plot SM0.5 to={} width=20 height=2", svg.display()));
        let chart = r[0].as_ref().unwrap().message.clone().unwrap();
        assert!(chart.starts_with("SM0.5\n1 ┤"), "{chart}");
        assert!(chart.contains("0s") && chart.contains("2s"));
        assert!(std::fs::read_to_string(&svg).unwrap().starts_with("<svg"));
        let e = sh.exec("plot VW2").remove(0).unwrap_err().1;
        assert!(e.hint.clone().unwrap().contains("SM0.5, VW0"));
        std::fs::remove_dir_all(&dir).unwrap();
    }

    /// A multi-segment PTO ramp traced on its output Q0.0 is drawn as frequency over time
    /// (from the channel's pulse count SMD212), into a PNG of the requested size; the plan of
    /// the same profile draws the same way before anything is sent.
    #[test]
    fn a_pto_ramp_plots_as_frequency_into_a_png_of_the_requested_size() {
        let dir = std::env::temp_dir().join(format!("plcsh-ramp-{}", std::process::id()));
        std::fs::create_dir_all(&dir).unwrap();
        let (ramp, plan) = (dir.join("ramp.png"), dir.join("plan.png"));
        let mut sh = shell();
        let profile = "profile 0 at VB3001 [(freq=500Hz, count=250), (freq=1kHz, count=500), (freq=2kHz, count=2000), (freq=1kHz, count=500), (freq=500Hz, count=250)]";
        let r = sh.exec(&format!("{profile} plan to={} size=800x300", plan.display()));
        assert!(r[0].is_ok(), "{:?}", r[0].as_ref().err());
        let r =
            sh.exec(&format!("{profile}; trace Q0.0 every=20ms for=3s; plot Q0.0 to={} size=900x400", ramp.display()));
        let o = r[2].as_ref().unwrap_or_else(|e| panic!("{}", e.1));
        assert_eq!(o.data["operands"], serde_json::json!(["Q0.0 frequency"]));
        let size = |p: &std::path::Path| {
            let b = std::fs::read(p).unwrap();
            assert_eq!(&b[..8], b"\x89PNG\r\n\x1a\n", "{} is a PNG", p.display());
            (u32::from_be_bytes(b[16..20].try_into().unwrap()), u32::from_be_bytes(b[20..24].try_into().unwrap()))
        };
        assert_eq!(size(&ramp), (900, 400));
        assert_eq!(size(&plan), (800, 300));
        // The frequency series: 500 Hz, then 1 kHz, 2 kHz, 1 kHz, 500 Hz (from the pulse count).
        let series = sh.last_trace.as_ref().unwrap().series(&["Q0.0"]).unwrap();
        let at = |t: f64| series[0].points.iter().rev().find(|p| p.0 <= t).unwrap().1.round();
        assert_eq!((at(0.2), at(0.7), at(1.5), at(2.2), at(2.7)), (500.0, 1000.0, 2000.0, 1000.0, 500.0));
    }

    #[test]
    fn plot_before_trace_says_what_to_do() {
        let mut sh = shell();
        let e = sh.exec("plot").remove(0).unwrap_err().1;
        assert!(e.hint.clone().unwrap().contains("trace"));
    }
}
