//! Commissioning reports: what a technician hands over after commissioning a machine — the
//! checklist with the values each step measured, the parameter sets with their differences
//! from a reference, the curves recorded during steps and the log of every write plcsh made
//! to a device — as one self-contained HTML file and its JSON twin.
//!
//! Records first, renderings second (design guide, "Added after the fourth wave"): the
//! commission runner (`lib/commission.lua`) records a [`Run`]; [`Report::build`] adds what
//! only the session knows (the devices and what they report, the clock, the guard's write
//! log, [`crate::guard::WriteLog`]); [`Report::json`] and [`html::render`] are two renderings
//! of that one record. Both are deterministic: no wall-clock reading except the report's
//! date, which `SOURCE_DATE_EPOCH` fixes (the reproducible-builds convention), keys in a
//! fixed order, numbers as Rust prints them — so a simulated rehearsal run twice in stepped
//! time gives byte-identical files.
//!
//! Size: a curve is drawn and kept as at most two points (the minimum and the maximum) per
//! pixel column of its plot ([`decimate`], [`PLOT_COLUMNS`] columns), never cut off, and the
//! write log keeps [`crate::guard::LOG_LIMIT`] writes (the rest are counted), so a report
//! stays small whatever the length of the run (docs/commissioning.md gives the figures).

pub mod decimate;
pub mod html;

use crate::core::msg::Lang;
use crate::guard::Written;
use serde::{Deserialize, Serialize};
use serde_json::Value as Json;
use std::collections::BTreeMap;

/// The format name and version in every JSON twin (docs/report.schema.json).
pub const FORMAT: &str = "plcsh-report/1";

/// Width of a plot in pixels; a curve keeps at most two points per column.
pub const PLOT_COLUMNS: usize = 800;

/// What the commission runner recorded (the Lua side, `lib/commission.lua`).
#[derive(Clone, Debug, Default, Deserialize)]
#[serde(default)]
pub struct Run {
    pub title: String,
    pub site: Option<String>,
    pub operator: Option<String>,
    pub steps: Vec<Step>,
    pub notes: Vec<String>,
    pub params: Vec<Params>,
    pub traces: Vec<TraceIn>,
    /// What each device reports about itself, by device name (a command's result).
    pub reports: BTreeMap<String, Json>,
}

/// One step of the checklist.
#[derive(Clone, Debug, Default, Serialize, Deserialize)]
#[serde(default)]
pub struct Step {
    pub n: u32,
    pub name: String,
    /// `ok`, `failed`, `failed-optional` or `skipped`.
    pub result: String,
    pub optional: bool,
    pub note: Option<String>,
    pub notes: Vec<String>,
    /// Start and length in the session's time (ms).
    pub started_ms: Option<f64>,
    pub duration_ms: Option<f64>,
    /// Values the step measured (`c:measure`, or the table a step returns).
    pub values: Vec<Measured>,
    /// For a failed check: what was expected and what was measured.
    pub expected: Option<String>,
    pub measured: Option<String>,
    pub error: Option<String>,
    /// Command results the step recorded (`c:record`): the objects `--json` shows.
    pub results: Vec<Json>,
}

/// A measured value.
#[derive(Clone, Debug, Default, Serialize, Deserialize)]
#[serde(default)]
pub struct Measured {
    pub name: String,
    pub value: Json,
    #[serde(skip_serializing_if = "Option::is_none")]
    pub unit: Option<String>,
}

/// A parameter set saved, loaded or compared during the run.
#[derive(Clone, Debug, Default, Serialize, Deserialize)]
#[serde(default)]
pub struct Params {
    pub step: Option<u32>,
    pub device: String,
    /// `compared`, `saved` or `loaded`.
    pub action: String,
    pub file: Option<String>,
    /// The reference file the differences are taken against.
    pub reference: Option<String>,
    /// The differences against the reference (`servo params diff`'s `differences`).
    pub differences: Vec<Json>,
    /// The command's own result (`servo params save/load/diff` as `--json` shows it).
    pub result: Json,
}

/// A trace as the runner hands it over: `trace`'s result (`t_s`, `series`).
#[derive(Clone, Debug, Default, Deserialize)]
#[serde(default)]
pub struct TraceIn {
    pub step: Option<u32>,
    pub title: String,
    pub t_s: Vec<f64>,
    pub series: Vec<SeriesIn>,
    /// Units by series name.
    pub units: BTreeMap<String, String>,
}

#[derive(Clone, Debug, Default, Deserialize)]
#[serde(default)]
pub struct SeriesIn {
    pub operand: String,
    pub values: Vec<f64>,
}

/// A curve as the report keeps it: decimated points and the whole trace's figures.
#[derive(Clone, Debug, Serialize)]
pub struct Trace {
    pub step: Option<u32>,
    pub title: String,
    /// Samples recorded, and the time they span (s).
    pub samples: usize,
    pub t_start_s: f64,
    pub t_end_s: f64,
    /// True when the points are fewer than the samples (min/max per pixel column).
    pub decimated: bool,
    pub series: Vec<Curve>,
}

#[derive(Clone, Debug, Serialize)]
pub struct Curve {
    pub name: String,
    pub unit: String,
    pub min: f64,
    pub max: f64,
    pub last: f64,
    /// `[t_s, value]` pairs, at most two per pixel column.
    pub points: Vec<(f64, f64)>,
}

/// The date and times of the run.
#[derive(Clone, Debug, Serialize)]
pub struct Times {
    /// The machine's date and time when the report was begun, RFC 3339 UTC.
    pub date: String,
    /// `stepped` (simulated time, advanced by the run) or `real` (follows the machine's clock).
    pub clock: String,
    /// The session's time at the start and the end of the run (ms).
    pub start_ms: f64,
    pub end_ms: f64,
}

#[derive(Clone, Debug, Serialize)]
pub struct Summary {
    /// `passed` when no required step failed.
    pub result: String,
    pub steps: usize,
    pub ok: usize,
    pub failed: usize,
    pub skipped: usize,
}

/// The whole record, as the JSON twin holds it.
#[derive(Clone, Debug, Serialize)]
pub struct Report {
    pub format: String,
    pub title: String,
    pub site: Option<String>,
    pub operator: Option<String>,
    pub language: String,
    pub plcsh: String,
    pub time: Times,
    pub summary: Summary,
    pub devices: Vec<Json>,
    pub steps: Vec<Step>,
    pub notes: Vec<String>,
    pub params: Vec<Params>,
    pub traces: Vec<Trace>,
    pub writes: Vec<Written>,
    /// Writes made beyond the log's limit, counted only.
    pub writes_not_kept: u64,
}

/// What the session contributes: its devices, clock readings and the write log.
pub struct Context {
    pub devices: Vec<Json>,
    pub date: String,
    pub stepped: bool,
    pub start_ms: f64,
    pub end_ms: f64,
    pub writes: Vec<Written>,
    pub writes_not_kept: u64,
    pub lang: Lang,
}

/// A number of milliseconds as the report keeps it: to the microsecond.
fn ms(v: f64) -> f64 {
    (v * 1e3).round() / 1e3
}

/// JSON with every object's keys in sorted order, whatever order a Lua table gave them in.
pub fn canonical(v: Json) -> Json {
    match v {
        Json::Object(m) => {
            let sorted: BTreeMap<String, Json> = m.into_iter().map(|(k, v)| (k, canonical(v))).collect();
            Json::Object(sorted.into_iter().collect())
        }
        Json::Array(a) => Json::Array(a.into_iter().map(canonical).collect()),
        other => other,
    }
}

impl Report {
    /// The report of `run` in `ctx`.
    pub fn build(run: Run, ctx: Context) -> Report {
        let mut steps = run.steps;
        for s in &mut steps {
            s.results = std::mem::take(&mut s.results).into_iter().map(canonical).collect();
            for v in &mut s.values {
                v.value = canonical(std::mem::take(&mut v.value));
            }
            s.started_ms = s.started_ms.map(ms);
            s.duration_ms = s.duration_ms.map(ms);
        }
        let count = |r: &str| steps.iter().filter(|s| s.result == r).count();
        let failed = count("failed");
        let summary = Summary {
            result: if failed == 0 { "passed" } else { "failed" }.to_string(),
            steps: steps.len(),
            ok: count("ok"),
            failed: failed + count("failed-optional"),
            skipped: count("skipped"),
        };
        let params = run
            .params
            .into_iter()
            .map(|mut p| {
                p.result = canonical(std::mem::take(&mut p.result));
                p.differences = std::mem::take(&mut p.differences).into_iter().map(canonical).collect();
                p
            })
            .collect();
        let mut devices = ctx.devices;
        for d in &mut devices {
            let name = d.get("name").and_then(Json::as_str).unwrap_or_default().to_string();
            if let Some(r) = run.reports.get(&name) {
                d["reports"] = canonical(r.clone());
            }
            *d = canonical(std::mem::take(d));
        }
        Report {
            format: FORMAT.to_string(),
            title: run.title,
            site: run.site.filter(|s| !s.is_empty()),
            operator: run.operator.filter(|s| !s.is_empty()),
            language: ctx.lang.tag().to_string(),
            plcsh: env!("CARGO_PKG_VERSION").to_string(),
            time: Times {
                date: ctx.date,
                clock: if ctx.stepped { "stepped" } else { "real" }.to_string(),
                start_ms: ms(ctx.start_ms),
                end_ms: ms(ctx.end_ms),
            },
            summary,
            devices,
            steps,
            notes: run.notes,
            params,
            traces: run.traces.into_iter().map(trace).collect(),
            writes: ctx.writes,
            writes_not_kept: ctx.writes_not_kept,
        }
    }

    /// The JSON twin: pretty-printed, keys in a fixed order, a final newline.
    pub fn json(&self) -> String {
        let mut s = serde_json::to_string_pretty(self).unwrap_or_else(|_| "{}".to_string());
        s.push('\n');
        s
    }

    /// The report's language.
    pub fn lang(&self) -> Lang {
        Lang::from_tag(&self.language).unwrap_or(Lang::En)
    }
}

/// A trace as the report keeps it: each series decimated to the plot's columns.
fn trace(t: TraceIn) -> Trace {
    let t_start_s = t.t_s.first().copied().unwrap_or(0.0);
    let t_end_s = t.t_s.last().copied().unwrap_or(0.0);
    let mut decimated = false;
    let series = t
        .series
        .iter()
        .map(|s| {
            let pts: Vec<(f64, f64)> = t.t_s.iter().copied().zip(s.values.iter().copied()).collect();
            let points = decimate::min_max(&pts, PLOT_COLUMNS);
            decimated |= points.len() < pts.len();
            let finite = || s.values.iter().copied().filter(|v| v.is_finite());
            Curve {
                name: s.operand.clone(),
                unit: t.units.get(&s.operand).cloned().unwrap_or_default(),
                min: finite().fold(f64::INFINITY, f64::min).min(f64::MAX),
                max: finite().fold(f64::NEG_INFINITY, f64::max).max(f64::MIN),
                last: s.values.last().copied().filter(|v| v.is_finite()).unwrap_or(0.0),
                points,
            }
        })
        .collect();
    Trace { step: t.step, title: t.title, samples: t.t_s.len(), t_start_s, t_end_s, decimated, series }
}

/// The JSON twin's path beside the HTML file: `axis-x.html` → `axis-x.json`.
pub fn json_path(html: &std::path::Path) -> std::path::PathBuf {
    match html.extension().and_then(|e| e.to_str()).map(str::to_ascii_lowercase).as_deref() {
        Some("html") | Some("htm") => html.with_extension("json"),
        _ => {
            let mut s = html.as_os_str().to_owned();
            s.push(".json");
            s.into()
        }
    }
}

/// The report's date: `SOURCE_DATE_EPOCH` (seconds, the reproducible-builds convention) when
/// set, else now; RFC 3339 UTC.
pub fn date_now() -> String {
    crate::core::civil::utc_now()
}

pub use crate::core::civil::rfc3339;

/// Writes the HTML report to `path` and its JSON twin beside it (atomically each); returns
/// the twin's path.
pub fn write(report: &Report, path: &std::path::Path) -> crate::core::Result<std::path::PathBuf> {
    use crate::core::durable::write_atomic;
    let twin = json_path(path);
    write_atomic(path, html::render(report).as_bytes())?;
    write_atomic(&twin, report.json().as_bytes())?;
    Ok(twin)
}

#[cfg(test)]
mod tests;
