//! `watch OPERAND… [every=200ms] [count=N]`: a live table refreshed in place until Ctrl-C or
//! `count=N`, with the values that changed since the last sample highlighted. On a terminal
//! the table redraws over itself (highlight in colour only without NO_COLOR, else a `*`); on a
//! pipe it prints one plain line per sample; with `--json` one JSON object per sample:
//! `{"ok":true,"cmd":"watch","sample":3,"t_us":600000,"ts_ms":…,"values":[…],"changed":["VW0"]}`
//! and a closing summary `{"ok":true,"cmd":"watch","samples":N,…}`.
//! The live lines go to stdout directly (they are the command's output while it runs).

use super::CommandSpec;
use crate::core::clock::format_time;
use crate::core::{Error, Result, Value};
use crate::output::{show_value, Outcome};
use crate::session::Session;
use crate::shell::sample::{self, Plan, Sample, Stats};
use crate::shell::{Args, Shell};
use std::io::Write;
use std::time::Duration;

pub const WATCH: CommandSpec = CommandSpec {
    name: "watch",
    aliases: &[],
    usage: "watch OPERAND… [every=200ms] [count=N]   e.g. watch VW0 SMD72 SM0.5 every=100ms",
    summary: || crate::msg!("summary-watch"),
    subcommands: &[],
    run: watch,
};

/// How samples are shown.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum Mode {
    /// A table redrawn in place (a terminal); `color` highlights changes with ANSI colour.
    Live { color: bool },
    /// One plain line per sample (a pipe).
    Lines,
    /// One JSON object per sample.
    Json,
}

/// Draws samples in a [`Mode`], remembering the previous values to mark changes.
pub struct Render {
    mode: Mode,
    labels: Vec<String>,
    every: Duration,
    prev: Option<Vec<Value>>,
    drawn: usize,
    /// The terminal's (columns, rows): a table that would not fit is laid out in columns,
    /// then shown a page at a time, so the redraw stays on the screen.
    pub size: Option<(usize, usize)>,
    page: usize,
}

impl Render {
    pub fn new(mode: Mode, labels: Vec<String>, every: Duration) -> Render {
        Render { mode, labels, every, prev: None, drawn: 0, size: None, page: 0 }
    }

    /// Writes one sample.
    pub fn sample(&mut self, s: &Sample, w: &mut dyn Write) -> std::io::Result<()> {
        let values: Vec<Value> = s.readings.iter().map(|r| r.value).collect();
        let changed: Vec<bool> = match &self.prev {
            Some(p) => values.iter().zip(p).map(|(a, b)| a != b).collect(),
            None => vec![false; values.len()],
        };
        match self.mode {
            Mode::Json => {
                let names: Vec<&str> =
                    self.labels.iter().zip(&changed).filter(|(_, c)| **c).map(|(l, _)| l.as_str()).collect();
                let ts_ms = std::time::SystemTime::now()
                    .duration_since(std::time::UNIX_EPOCH)
                    .map(|d| d.as_millis() as u64)
                    .unwrap_or(0);
                let line = serde_json::json!({"ok": true, "cmd": "watch", "sample": s.index,
                    "t_us": s.t.as_micros() as u64, "ts_ms": ts_ms, "values": s.readings, "changed": names});
                writeln!(w, "{line}")?;
            }
            Mode::Lines => {
                let mut line = format_time(s.t);
                for (l, r) in self.labels.iter().zip(&s.readings) {
                    line.push_str(&format!("  {l}={}", r.value));
                }
                writeln!(w, "{line}")?;
            }
            Mode::Live { color } => {
                if self.drawn > 0 {
                    write!(w, "\x1b[{}A", self.drawn)?;
                }
                // A tag's reading shows its operand beside its name (`Tank2_Level (VD200/REAL)`).
                let shown: Vec<String> = self
                    .labels
                    .iter()
                    .zip(&s.readings)
                    .map(|(l, r)| if r.name.is_some() { format!("{l} ({})", r.operand) } else { l.clone() })
                    .collect();
                let width = shown.iter().map(|l| l.chars().count()).max().unwrap_or(0);
                let mut header = format!(
                    "every {} · t={} · sample {} · Ctrl-C stops",
                    crate::plot::time(self.every.as_secs_f64()),
                    format_time(s.t),
                    s.index + 1
                );
                // Cells: the text, and its width on screen (without colour codes).
                let cells: Vec<(String, usize)> = shown
                    .iter()
                    .zip(&s.readings)
                    .zip(&changed)
                    .map(|((l, r), c)| {
                        let v = show_value(&r.value, r.dtype);
                        let v = match &r.comment {
                            Some(text) => format!("{v}  {text}"),
                            None => v,
                        };
                        let shown = format!("{l:<width$}  {v}{}", if *c && !color { " *" } else { "" });
                        let n = shown.chars().count();
                        let text = match (c, color) {
                            (true, true) => format!("{l:<width$}  \x1b[1;33m{v}\x1b[0m"),
                            _ => shown,
                        };
                        (text, n)
                    })
                    .collect();
                let (body, paged) = self.layout(&cells);
                if let Some(p) = paged {
                    header.push_str(&format!(" · page {p}"));
                }
                let mut lines = vec![header];
                lines.extend(body);
                for l in &lines {
                    write!(w, "\r\x1b[2K{l}\n")?;
                }
                self.drawn = lines.len();
            }
        }
        self.prev = Some(values);
        w.flush()
    }
}

impl Render {
    /// The operand lines for one frame: one a line when they fit the terminal; else in
    /// columns (down, then across); else a page at a time, the page turning every two seconds
    /// of samples. Returns the lines and, when paged, "N/M".
    fn layout(&mut self, cells: &[(String, usize)]) -> (Vec<String>, Option<String>) {
        let indent = |c: &(String, usize)| format!("  {}", c.0);
        let Some((cols, rows)) = self.size else { return (cells.iter().map(indent).collect(), None) };
        // The header and the line the cursor rests on take two rows.
        let room = rows.saturating_sub(2).max(1);
        if cells.len() <= room {
            return (cells.iter().map(indent).collect(), None);
        }
        let cell_w = cells.iter().map(|c| c.1).max().unwrap_or(1) + 4;
        let per_row = (cols.saturating_sub(2) / cell_w).max(1);
        let per_page = per_row * room;
        let pages = cells.len().div_ceil(per_page);
        let turn = (Duration::from_secs(2).as_micros() / self.every.as_micros().max(1)).max(1) as usize;
        let page = if pages > 1 { (self.page / turn) % pages } else { 0 };
        self.page += 1;
        let shown = &cells[page * per_page..cells.len().min((page + 1) * per_page)];
        let height = shown.len().div_ceil(per_row);
        let mut lines = vec![String::from(" "); height];
        for (k, c) in shown.iter().enumerate() {
            let line = &mut lines[k % height];
            line.push(' ');
            line.push_str(&c.0);
            line.push_str(&" ".repeat(cell_w - 1 - c.1));
        }
        let lines = lines.into_iter().map(|l| l.trim_end().to_string()).collect();
        (lines, (pages > 1).then(|| format!("{}/{pages}", page + 1)))
    }
}

/// Samples and draws until the plan or Ctrl-C stops it.
pub fn watch_into(
    session: &mut Session,
    texts: &[&str],
    plan: &Plan,
    render: &mut Render,
    w: &mut dyn Write,
) -> Result<Stats> {
    sample::run(session, texts, plan, |s| {
        render.sample(s, w).map_err(|e| Error::io(crate::msg!("shell-watch-cannot-write", reason = e.to_string())))
    })
}

fn watch(sh: &mut Shell, args: Args) -> Result<Outcome> {
    let req = sample::parse(&args, Duration::from_millis(200), &[], WATCH.usage)?;
    let labels = sample::labels(&sh.session, &req.operands)?;
    let texts: Vec<&str> = req.operands.iter().map(|(_, t)| *t).collect();
    let mode = if sh.style.json {
        Mode::Json
    } else if crate::core::platform::escapes(crate::core::platform::Stream::Stdout) {
        Mode::Live { color: sh.style.color }
    } else {
        Mode::Lines
    };
    let mut render = Render::new(mode, labels, req.plan.every);
    render.size = crate::shell::term::size();
    let mut out = std::io::stdout();
    let stats = watch_into(&mut sh.session, &texts, &req.plan, &mut render, &mut out)?;
    if sh.verbose {
        eprintln!("{}", stats.report("watch", &req.plan));
    }
    Ok(Outcome::new("watch")
        .with("samples", stats.samples)
        .with("interrupted", stats.interrupted)
        .with("clock_rate_hz", stats.clock_rate())
        .with("wall_rate_hz", stats.wall_rate())
        .quiet())
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::core::Clock;
    use crate::session::SetItem;

    fn session() -> Session {
        let mut s = Session::new(Clock::stepped());
        s.open("plc", "sim:K205-16DT").unwrap();
        s
    }

    fn run(mode: Mode, count: u64) -> String {
        let mut s = session();
        let plan = Plan { every: Duration::from_millis(300), count: Some(count), span: None };
        let mut r = Render::new(mode, vec!["SM0.5".into(), "VW0".into()], plan.every);
        let mut buf = Vec::new();
        watch_into(&mut s, &["SM0.5", "VW0"], &plan, &mut r, &mut buf).unwrap();
        String::from_utf8(buf).unwrap()
    }

    #[test]
    fn live_mode_redraws_in_place_and_highlights_changes() {
        // SM0.5 is on for 0–500 ms: samples at 0 and 300 ms see TRUE, at 600 ms FALSE.
        let out = run(Mode::Live { color: true }, 3);
        let frames: Vec<&str> = out.split("\x1b[3A").collect();
        assert_eq!(frames.len(), 3, "drawn three times, moving up over the 3-line table: {out:?}");
        assert!(!frames[1].contains("\x1b[1;33m"), "nothing changed between 0 and 300 ms");
        assert!(frames[2].contains("\x1b[1;33m0\x1b[0m"), "{:?}", frames[2]);
        assert!(frames[2].contains("t=0.600000s"));
        let plain = run(Mode::Live { color: false }, 3);
        assert!(!plain.contains("\x1b[1;33m") && plain.contains(" *"), "NO_COLOR marks changes with *");
    }

    /// A table taller than the terminal stays on the screen: columns, then pages; every frame
    /// moves the cursor up by no more than the rows the terminal has.
    #[test]
    fn a_table_taller_than_the_terminal_stays_in_place() {
        let mut s = session();
        let texts: Vec<String> = (0..60).map(|k| format!("VW{}", 2 * k)).collect();
        let texts: Vec<&str> = texts.iter().map(String::as_str).collect();
        let labels: Vec<String> = texts.iter().map(|t| t.to_string()).collect();
        for (size, paged) in [((80, 12), false), ((30, 8), true)] {
            let mut r = Render::new(Mode::Live { color: false }, labels.clone(), Duration::from_millis(500));
            r.size = Some(size);
            let plan = Plan { every: Duration::from_millis(500), count: Some(20), span: None };
            let mut out = Vec::new();
            watch_into(&mut s, &texts, &plan, &mut r, &mut out).unwrap();
            let out = String::from_utf8(out).unwrap();
            for frame in
                out.split("\x1b[").filter_map(|f| f.split_once('A')).filter_map(|(n, _)| n.parse::<usize>().ok())
            {
                assert!(frame < size.1, "a frame of {frame} lines in a {}-row terminal", size.1);
            }
            assert!(out.lines().all(|l| l.replace("\r\x1b[2K", "").chars().count() <= size.0 || l.contains("Ctrl-C")));
            assert_eq!(out.contains("page 1/"), paged, "{out}");
            // Paged: every operand is shown at some point (the page turns every 2 s of samples).
            assert!(out.contains("VW118"), "{out}");
        }
    }

    #[test]
    fn lines_mode_is_plain_text() {
        let out = run(Mode::Lines, 2);
        assert!(!out.contains('\x1b'));
        let lines: Vec<&str> = out.lines().collect();
        assert_eq!(lines.len(), 2);
        assert!(lines[1].starts_with("0.300000s  SM0.5="), "{out}");
    }

    #[test]
    fn json_mode_is_one_object_per_sample() {
        let out = run(Mode::Json, 3);
        let v: Vec<serde_json::Value> = out.lines().map(|l| serde_json::from_str(l).unwrap()).collect();
        assert_eq!(v.len(), 3);
        assert_eq!(v[2]["t_us"], 600_000);
        assert_eq!(v[2]["changed"], serde_json::json!(["SM0.5"]));
        assert_eq!(v[1]["changed"], serde_json::json!([]));
        assert_eq!(v[0]["values"][1]["operand"], "VW0");
        assert!(v[0]["ts_ms"].as_u64().unwrap() > 1_600_000_000_000);
    }

    #[test]
    fn a_write_between_samples_shows_as_a_change() {
        let mut s = session();
        let plan = Plan { every: Duration::from_millis(100), count: Some(1), span: None };
        let mut r = Render::new(Mode::Json, vec!["VW0".into()], plan.every);
        let mut buf = Vec::new();
        watch_into(&mut s, &["VW0"], &plan, &mut r, &mut buf).unwrap();
        s.set(&[SetItem { operand: "VW0".into(), value: "5".into(), column: 0, value_column: 0 }]).unwrap();
        buf.clear();
        watch_into(&mut s, &["VW0"], &plan, &mut r, &mut buf).unwrap();
        let v: serde_json::Value = serde_json::from_slice(&buf).unwrap();
        assert_eq!(v["changed"], serde_json::json!(["VW0"]));
        assert_eq!(v["values"][0]["value"], 5);
    }
}
