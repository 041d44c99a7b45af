//! `trace OPERAND… every=10ms for=2s [to=FILE.csv]` records samples (on a simulator in its
//! virtual time: a stepped clock traces two seconds instantly) and keeps them as the shell's
//! last trace; `plot [OPERAND…] [to=FILE.svg]` draws that trace in the terminal (a braille line
//! chart per operand, time on the x axis) and optionally as an SVG picture (`crate::plot`).

use super::CommandSpec;
use crate::core::{Error, Result};
use crate::output::Outcome;
use crate::shell::progress::Progress;
use crate::shell::sample::{self, Recording};
use crate::shell::{lex, Args, Shell};
use std::time::Duration;

pub const TRACE: CommandSpec = CommandSpec {
    name: "trace",
    aliases: &[],
    usage: "trace OPERAND… every=10ms for=2s [to=FILE.csv]   e.g. trace SMD72 Q0.0 every=10ms for=2s",
    summary: "record operands over time (for `plot`), optionally into a CSV file",
    subcommands: &[],
    run: trace,
};

pub const PLOT: CommandSpec = CommandSpec {
    name: "plot",
    aliases: &[],
    usage: "plot [OPERAND…] [to=FILE.svg] [width=60] [height=8]   e.g. plot SMD72 to=ramp.svg",
    summary: "draw the last trace in the terminal, and as an SVG picture with to=",
    subcommands: &[],
    run: plot,
};

fn write_file(path: &str, text: &str, col: usize) -> Result<()> {
    std::fs::write(path, text).map_err(|e| Error::io(format!("cannot write {path}: {e}")).column(col))
}

fn trace(sh: &mut Shell, args: Args) -> Result<Outcome> {
    let req = sample::parse(&args, Duration::from_millis(10), &["to"], TRACE.usage)?;
    let mut plan = req.plan;
    if plan.span.is_none() && plan.count.is_none() {
        plan.span = Some(Duration::from_secs(2));
    }
    let labels = sample::labels(&sh.session, &req.operands)?;
    let texts: Vec<&str> = req.operands.iter().map(|(_, t)| *t).collect();
    let mut rec = Recording::new(labels, plan.every);
    let total = plan.span.or(plan.count.map(|n| plan.every * n.saturating_sub(1) as u32));
    let mut progress = Progress::new("trace", total.filter(|_| !sh.session.clock.is_stepped()));
    let stats = sample::run(&mut sh.session, &texts, &plan, |s| {
        rec.push(s);
        progress.update(s.t, &format!("{} samples", s.index + 1));
        Ok(())
    })?;
    progress.finish();
    if sh.verbose {
        eprintln!("{}", stats.report("trace", &plan));
    }
    let mut o = Outcome::new("trace");
    if let Some(&(col, _, path)) = req.options.iter().find(|(_, k, _)| *k == "to") {
        write_file(path, &rec.csv(), col)?;
        o = o.with("file", path);
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

fn plot(sh: &mut Shell, args: Args) -> Result<Outcome> {
    let words = lex::words(args.text).map_err(|e| e.shift(args.offset))?;
    let (names, opts) = lex::options(&words);
    let (mut width, mut height, mut to) = (60usize, 8usize, None);
    for (c, k, v) in opts {
        let col = args.offset + c;
        let num = |v: &str| -> Result<usize> {
            v.parse()
                .ok()
                .filter(|n| (2..=1000).contains(n))
                .ok_or_else(|| Error::usage(format!("{k}={v} is not a size (2…1000 characters)")).column(col))
        };
        match k {
            "to" => to = Some((col, v)),
            "width" => width = num(v)?,
            "height" => height = num(v)?,
            _ => return Err(Error::usage(format!("unknown option `{k}`")).column(col).hint(PLOT.usage)),
        }
    }
    let rec = sh.last_trace.as_ref().ok_or_else(|| {
        Error::usage("nothing to plot yet").hint("record first, e.g. trace SMD72 every=10ms for=2s").column(args.offset)
    })?;
    let names: Vec<&str> = names.iter().map(|(_, n)| *n).collect();
    let series = rec.series(&names).map_err(|e| e.column(args.offset))?;
    let mut text = crate::plot::terminal(&series, width, height);
    let mut o = Outcome::new("plot").with("operands", series.iter().map(|s| s.name.clone()).collect::<Vec<_>>());
    if let Some((col, path)) = to {
        write_file(path, &crate::plot::svg(&series, 800, 200), col)?;
        text.push_str(&format!("wrote {path}\n"));
        o = o.with("file", path);
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

    #[test]
    fn plot_before_trace_says_what_to_do() {
        let mut sh = shell();
        let e = sh.exec("plot").remove(0).unwrap_err().1;
        assert!(e.hint.clone().unwrap().contains("trace"));
    }
}
