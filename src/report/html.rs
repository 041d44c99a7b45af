//! The HTML rendering of a [`Report`]: one self-contained file — styles in a `<style>`
//! element, plots as inline SVG drawn by [`crate::plot::svg`] (the renderer `plot` uses), no
//! script, no font, image or link fetched from anywhere — readable on a phone (the layout
//! narrows to the screen, wide tables scroll inside their section) and printable on A4 (a
//! page break before each section, tables and plots kept whole where they fit).
//!
//! Every heading and label comes from the message catalogue (`lib/locales/*/report.ftl`) in
//! the report's language; the recorded texts (titles, notes, operands) are escaped, never
//! interpreted. Sections carry fixed ids (`summary`, `devices`, `checklist`, `params`,
//! `curves`, `writes`, `notes`) so a reader or a test can find them.

use super::{Report, Step, Trace};
use crate::core::msg::Lang;
use crate::msg;
use serde_json::Value as Json;
use std::fmt::Write;

/// Text for HTML: `&`, `<`, `>`, `"` and `'` escaped.
pub fn escape(s: &str) -> String {
    let mut out = String::with_capacity(s.len());
    for c in s.chars() {
        match c {
            '&' => out.push_str("&amp;"),
            '<' => out.push_str("&lt;"),
            '>' => out.push_str("&gt;"),
            '"' => out.push_str("&quot;"),
            '\'' => out.push_str("&#39;"),
            c => out.push(c),
        }
    }
    out
}

/// A recorded value as text: a string as it is, anything else as compact JSON.
fn value_text(v: &Json) -> String {
    match v {
        Json::String(s) => s.clone(),
        Json::Null => "—".to_string(),
        other => other.to_string(),
    }
}

/// Milliseconds as seconds with three decimals (`12.345 s`).
fn seconds(ms: f64) -> String {
    format!("{:.3} s", ms / 1000.0)
}

/// The style sheet: screen first, then print (A4, a page per section).
const STYLE: &str = "\
:root{--fg:#1b1f24;--muted:#5b6470;--line:#d0d7de;--ok:#1a7f37;--bad:#cf222e;--skip:#7d8590}
*{box-sizing:border-box}
body{font-family:system-ui,-apple-system,'Segoe UI',Roboto,'Noto Sans','Noto Sans CJK SC','PingFang SC','Microsoft YaHei',sans-serif;color:var(--fg);margin:0 auto;padding:1rem;max-width:60rem;line-height:1.4}
h1{font-size:1.6rem;margin:.2rem 0 .6rem}
h2{font-size:1.25rem;border-bottom:2px solid var(--line);padding-bottom:.2rem;margin-top:2rem}
h3{font-size:1.05rem;margin:1.2rem 0 .4rem}
dl.facts{display:grid;grid-template-columns:max-content 1fr;gap:.2rem 1rem;margin:0}
dl.facts dt{color:var(--muted)}
dl.facts dd{margin:0;overflow-wrap:anywhere}
.scroll{overflow-x:auto;-webkit-overflow-scrolling:touch}
table{border-collapse:collapse;width:100%;font-size:.92rem}
th,td{border:1px solid var(--line);padding:.3rem .45rem;text-align:left;vertical-align:top;overflow-wrap:anywhere}
th{background:#f6f8fa;overflow-wrap:normal}
td.word{white-space:nowrap}
td.num{text-align:right;white-space:nowrap;font-variant-numeric:tabular-nums}
.ok{color:var(--ok);font-weight:600}
.failed,.failed-optional{color:var(--bad);font-weight:600}
.skipped{color:var(--skip)}
.verdict{display:inline-block;padding:.15rem .6rem;border-radius:.3rem;color:#fff;font-weight:700}
.verdict.passed{background:var(--ok)}
.verdict.failed{background:var(--bad)}
.detail{font-size:.88rem;color:var(--muted);margin:.2rem 0 0}
.mismatch{background:#fff1f0}
figure{margin:1rem 0}
figure svg{width:100%;height:auto;display:block}
figcaption{font-size:.88rem;color:var(--muted)}
code{font-family:ui-monospace,SFMono-Regular,Menlo,Consolas,monospace;font-size:.9em}
footer{margin-top:2rem;font-size:.8rem;color:var(--muted)}
@media (max-width:40rem){body{padding:.6rem}dl.facts{grid-template-columns:1fr}dl.facts dt{margin-top:.3rem}table{font-size:.85rem}}
@page{size:A4;margin:14mm}
@media print{body{max-width:none;padding:0}section{break-before:page}section:first-of-type{break-before:auto}table,figure,tr{break-inside:avoid}.scroll{overflow:visible}h2{break-after:avoid}}
";

/// The report as one HTML document.
pub fn render(r: &Report) -> String {
    let lang = r.lang();
    let mut h = String::with_capacity(64 * 1024);
    let _ = write!(
        h,
        "<!DOCTYPE html>\n<html lang=\"{}\">\n<head>\n<meta charset=\"utf-8\">\n\
         <meta name=\"viewport\" content=\"width=device-width, initial-scale=1\">\n\
         <meta name=\"generator\" content=\"plcsh {}\">\n<title>{}</title>\n<style>\n{STYLE}</style>\n</head>\n<body>\n",
        escape(&r.language),
        escape(&r.plcsh),
        escape(&r.title)
    );
    summary(&mut h, r, lang);
    devices(&mut h, r, lang);
    checklist(&mut h, r, lang);
    params(&mut h, r, lang);
    curves(&mut h, r, lang);
    writes(&mut h, r, lang);
    notes(&mut h, r, lang);
    let _ = write!(
        h,
        "<footer>{}</footer>\n</body>\n</html>\n",
        escape(&msg!(
            lang: lang,
            "report-footer",
            version = r.plcsh.as_str(),
            columns = super::PLOT_COLUMNS,
            writes = crate::guard::LOG_LIMIT
        ))
    );
    h
}

fn section_start(h: &mut String, id: &str, heading: &str) {
    let _ = write!(h, "<section id=\"{id}\">\n<h2>{}</h2>\n", escape(heading));
}

fn fact(h: &mut String, label: &str, value: &str) {
    let _ = writeln!(h, "<dt>{}</dt><dd>{}</dd>", escape(label), escape(value));
}

fn summary(h: &mut String, r: &Report, lang: Lang) {
    let _ = write!(h, "<section id=\"summary\">\n<h1>{}</h1>\n", escape(&r.title));
    let verdict = if r.summary.result == "passed" {
        msg!(lang: lang, "report-result-passed")
    } else {
        msg!(lang: lang, "report-result-failed")
    };
    let _ =
        writeln!(h, "<p><span class=\"verdict {}\">{}</span> {}</p>", escape(&r.summary.result), escape(&verdict), {
            escape(&msg!(
                lang: lang,
                "report-summary",
                ok = r.summary.ok,
                total = r.summary.steps,
                failed = r.summary.failed,
                skipped = r.summary.skipped
            ))
        });
    h.push_str("<dl class=\"facts\">\n");
    if let Some(s) = &r.site {
        fact(h, &msg!(lang: lang, "report-site"), s);
    }
    if let Some(o) = &r.operator {
        fact(h, &msg!(lang: lang, "report-operator"), o);
    }
    fact(h, &msg!(lang: lang, "report-date"), &r.time.date);
    let (start, end) = (seconds(r.time.start_ms), seconds(r.time.end_ms));
    let clock = if r.time.clock == "stepped" {
        msg!(lang: lang, "report-clock-stepped", start = start, end = end)
    } else {
        msg!(lang: lang, "report-clock-real", start = start, end = end)
    };
    fact(h, &msg!(lang: lang, "report-time"), &clock);
    fact(h, &msg!(lang: lang, "report-version"), &format!("plcsh {}", r.plcsh));
    h.push_str("</dl>\n</section>\n");
}

fn devices(h: &mut String, r: &Report, lang: Lang) {
    section_start(h, "devices", &msg!(lang: lang, "report-devices"));
    if r.devices.is_empty() {
        let _ = writeln!(h, "<p>{}</p>", escape(&msg!(lang: lang, "report-no-devices")));
    }
    for d in &r.devices {
        let s = |k: &str| d.get(k).map(value_text).unwrap_or_default();
        let _ = writeln!(h, "<h3>{}</h3>\n<dl class=\"facts\">", escape(&s("name")));
        fact(h, &msg!(lang: lang, "report-device-family"), &s("family"));
        fact(h, &msg!(lang: lang, "report-device-model"), &s("model"));
        fact(h, &msg!(lang: lang, "report-device-link"), &s("url"));
        let sim = if d.get("simulated").and_then(Json::as_bool) == Some(true) {
            msg!(lang: lang, "report-device-simulated")
        } else {
            msg!(lang: lang, "report-device-real")
        };
        fact(h, &msg!(lang: lang, "report-device-kind"), &sim);
        if let Some(Json::Object(rep)) = d.get("reports") {
            // Scalars only: lists and tables stay in the JSON twin.
            for (k, v) in rep {
                if matches!(k.as_str(), "ok" | "cmd" | "sub" | "text" | "device" | "message")
                    || v.is_object()
                    || v.is_array()
                {
                    continue;
                }
                let _ = writeln!(h, "<dt><code>{}</code></dt><dd>{}</dd>", escape(k), escape(&value_text(v)));
            }
        }
        h.push_str("</dl>\n");
    }
    h.push_str("</section>\n");
}

fn result_word(lang: Lang, result: &str) -> String {
    match result {
        "ok" => msg!(lang: lang, "report-step-ok").text,
        "failed" => msg!(lang: lang, "report-step-failed").text,
        "failed-optional" => msg!(lang: lang, "report-step-failed-optional").text,
        _ => msg!(lang: lang, "report-step-skipped").text,
    }
}

fn checklist(h: &mut String, r: &Report, lang: Lang) {
    section_start(h, "checklist", &msg!(lang: lang, "report-checklist"));
    if r.steps.is_empty() {
        let _ = writeln!(h, "<p>{}</p>\n</section>", escape(&msg!(lang: lang, "report-no-steps")));
        return;
    }
    let _ = writeln!(
        h,
        "<div class=\"scroll\"><table class=\"checklist\">\n<tr><th>#</th><th>{}</th><th>{}</th><th>{}</th><th>{}</th></tr>",
        escape(&msg!(lang: lang, "report-step")),
        escape(&msg!(lang: lang, "report-result")),
        escape(&msg!(lang: lang, "report-duration")),
        escape(&msg!(lang: lang, "report-note")),
    );
    for s in &r.steps {
        step_row(h, s, lang);
    }
    h.push_str("</table></div>\n</section>\n");
}

fn step_row(h: &mut String, s: &Step, lang: Lang) {
    let class = escape(&s.result);
    let _ = write!(
        h,
        "<tr id=\"step-{}\" class=\"step step-{class}\"><td class=\"num\">{}</td><td>{}</td><td class=\"{class} word\">{}</td><td class=\"num\">{}</td><td>",
        s.n,
        s.n,
        escape(&s.name),
        escape(&result_word(lang, &s.result)),
        s.duration_ms.map(seconds).unwrap_or_default(),
    );
    if let Some(n) = &s.note {
        h.push_str(&escape(n));
    }
    for n in &s.notes {
        let _ = write!(h, "<p class=\"detail\">{}</p>", escape(n));
    }
    if s.expected.is_some() || s.measured.is_some() {
        let _ = write!(
            h,
            "<table class=\"mismatch\"><tr><th>{}</th><td>{}</td></tr><tr><th>{}</th><td>{}</td></tr></table>",
            escape(&msg!(lang: lang, "report-expected")),
            escape(s.expected.as_deref().unwrap_or("—")),
            escape(&msg!(lang: lang, "report-measured")),
            escape(s.measured.as_deref().unwrap_or("—")),
        );
    }
    if !s.values.is_empty() {
        let _ = write!(
            h,
            "<table class=\"values\"><tr><th colspan=\"2\">{}</th></tr>",
            escape(&msg!(lang: lang, "report-values"))
        );
        for v in &s.values {
            let unit = v.unit.as_deref().map(|u| format!(" {u}")).unwrap_or_default();
            let _ = write!(
                h,
                "<tr><td>{}</td><td class=\"num\">{}{}</td></tr>",
                escape(&v.name),
                escape(&value_text(&v.value)),
                escape(&unit)
            );
        }
        h.push_str("</table>");
    }
    if !s.results.is_empty() {
        let _ = write!(
            h,
            "<p class=\"detail\">{}</p>",
            escape(&msg!(lang: lang, "report-results", count = s.results.len()))
        );
    }
    h.push_str("</td></tr>\n");
}

fn params(h: &mut String, r: &Report, lang: Lang) {
    section_start(h, "params", &msg!(lang: lang, "report-params"));
    if r.params.is_empty() {
        let _ = writeln!(h, "<p>{}</p>", escape(&msg!(lang: lang, "report-no-params")));
    }
    for p in &r.params {
        let file = p.file.as_deref().unwrap_or("—");
        let heading = match p.action.as_str() {
            "saved" => msg!(lang: lang, "report-params-saved", device = p.device.as_str(), file = file),
            "loaded" => msg!(lang: lang, "report-params-loaded", device = p.device.as_str(), file = file),
            _ => msg!(lang: lang, "report-params-compared", device = p.device.as_str()),
        };
        let _ = writeln!(h, "<h3>{}</h3>", escape(&heading));
        if let Some(reference) = &p.reference {
            let _ = writeln!(
                h,
                "<p class=\"detail\">{}</p>",
                escape(&msg!(lang: lang, "report-params-reference", file = reference.as_str()))
            );
        }
        if p.reference.is_none() {
            continue;
        }
        if p.differences.is_empty() {
            let _ = writeln!(h, "<p>{}</p>", escape(&msg!(lang: lang, "report-params-same")));
            continue;
        }
        let _ = writeln!(
            h,
            "<div class=\"scroll\"><table class=\"params\">\n<tr><th>{}</th><th>{}</th><th>{}</th><th>{}</th></tr>",
            escape(&msg!(lang: lang, "report-parameter")),
            escape(&msg!(lang: lang, "report-object")),
            escape(&msg!(lang: lang, "report-reference")),
            escape(&msg!(lang: lang, "report-drive")),
        );
        for d in &p.differences {
            let s = |k: &str| d.get(k).map(value_text).unwrap_or_default();
            let side = |k: &str| d.get(k).and_then(|x| x.get("shown")).map(value_text).unwrap_or_default();
            let _ = writeln!(
                h,
                "<tr><td>{}</td><td><code>{}</code></td><td>{}</td><td>{}</td></tr>",
                escape(&s("name")),
                escape(&s("object")),
                escape(&side("left")),
                escape(&side("right"))
            );
        }
        h.push_str("</table></div>\n");
    }
    h.push_str("</section>\n");
}

/// The plot's SVG made to scale with the page: its fixed size becomes a view box.
fn scalable_svg(svg: &str, w: u32, height: u32) -> String {
    let fixed = format!("width=\"{w}\" height=\"{height}\"");
    let open = svg.find("<svg").unwrap_or(0);
    let head_end = svg[open..].find('>').map(|e| open + e).unwrap_or(open);
    let head = &svg[open..head_end];
    let mut new_head = head.replacen(&fixed, "", 1);
    if !new_head.contains("viewBox") {
        new_head.push_str(&format!(" viewBox=\"0 0 {w} {height}\""));
    }
    new_head.push_str(" role=\"img\" preserveAspectRatio=\"xMidYMid meet\"");
    let rest = &svg[head_end..];
    // The XML declaration plotters may write is not allowed inside HTML.
    format!("{}{}", new_head, rest)
}

fn curves(h: &mut String, r: &Report, lang: Lang) {
    section_start(h, "curves", &msg!(lang: lang, "report-curves"));
    if r.traces.is_empty() {
        let _ = writeln!(h, "<p>{}</p>", escape(&msg!(lang: lang, "report-no-curves")));
    }
    for (i, t) in r.traces.iter().enumerate() {
        curve(h, i, t, lang);
    }
    h.push_str("</section>\n");
}

fn curve(h: &mut String, i: usize, t: &Trace, lang: Lang) {
    let series: Vec<crate::plot::Series> =
        t.series.iter().map(|c| crate::plot::Series::new(c.name.clone(), c.unit.clone(), c.points.clone())).collect();
    let (w, height) = crate::plot::default_size(&series);
    let w = w.min(super::PLOT_COLUMNS as u32 + 100);
    let _ = writeln!(h, "<figure class=\"plot\" id=\"curve-{}\">", i + 1);
    match crate::plot::svg(&series, &t.title, w, height) {
        Ok(svg) => h.push_str(&scalable_svg(&svg, w, height)),
        Err(e) => {
            let _ = write!(h, "<p>{}</p>", escape(&e));
        }
    }
    let span = seconds((t.t_end_s - t.t_start_s) * 1000.0);
    let mut caption = msg!(lang: lang, "report-trace-caption", samples = t.samples, span = span).text;
    if t.decimated {
        caption.push(' ');
        caption.push_str(&msg!(lang: lang, "report-trace-decimated", columns = super::PLOT_COLUMNS));
    }
    if let Some(n) = t.step {
        caption.push(' ');
        caption.push_str(&msg!(lang: lang, "report-trace-step", step = n));
    }
    let _ = write!(h, "\n<figcaption>{}", escape(&caption));
    for c in &t.series {
        let with_unit = |v: f64| {
            if c.unit.is_empty() {
                crate::plot::number(v)
            } else {
                format!("{} {}", crate::plot::number(v), c.unit)
            }
        };
        let figures = msg!(
            lang: lang,
            "report-curve-figures",
            name = c.name.as_str(),
            min = with_unit(c.min),
            max = with_unit(c.max),
            last = with_unit(c.last)
        );
        let _ = write!(h, "<br>{}", escape(&figures));
    }
    h.push_str("</figcaption>\n</figure>\n");
}

fn writes(h: &mut String, r: &Report, lang: Lang) {
    section_start(h, "writes", &msg!(lang: lang, "report-writes"));
    if r.writes.is_empty() {
        let _ = writeln!(h, "<p>{}</p>", escape(&msg!(lang: lang, "report-writes-none")));
    } else {
        let _ = writeln!(
            h,
            "<div class=\"scroll\"><table class=\"writes\">\n<tr><th>{}</th><th>{}</th><th>{}</th><th>{}</th><th>{}</th></tr>",
            escape(&msg!(lang: lang, "report-time")),
            escape(&msg!(lang: lang, "report-device")),
            escape(&msg!(lang: lang, "report-operand")),
            escape(&msg!(lang: lang, "report-old")),
            escape(&msg!(lang: lang, "report-new")),
        );
        let v = |x: &Option<crate::core::Value>| x.map(|v| v.to_string()).unwrap_or_else(|| "—".to_string());
        for w in &r.writes {
            let operand = match &w.action {
                Some(a) => format!("<code>{}</code> ({})", escape(&w.operand), escape(a)),
                None => format!("<code>{}</code>", escape(&w.operand)),
            };
            // A tag's name and its operand, as every reading shows them (docs/tags.md).
            let operand = match &w.name {
                Some(n) => format!("{} ({operand})", escape(n)),
                None => operand,
            };
            let new = match &w.refused {
                Some(why) => format!(
                    "<span class=\"failed\">{}</span>",
                    escape(&msg!(lang: lang, "report-refused", reason = why.as_str()))
                ),
                None => escape(&v(&w.new)),
            };
            let _ = writeln!(
                h,
                "<tr><td class=\"num\">{}</td><td>{}</td><td>{operand}</td><td class=\"num\">{}</td><td class=\"num\">{new}</td></tr>",
                seconds(w.t_ms),
                escape(&w.device),
                escape(&v(&w.old)),
            );
        }
        h.push_str("</table></div>\n");
    }
    if r.writes_not_kept > 0 {
        let _ =
            writeln!(h, "<p>{}</p>", escape(&msg!(lang: lang, "report-writes-not-kept", count = r.writes_not_kept)));
    }
    h.push_str("</section>\n");
}

fn notes(h: &mut String, r: &Report, lang: Lang) {
    section_start(h, "notes", &msg!(lang: lang, "report-notes"));
    if r.notes.is_empty() {
        let _ = writeln!(h, "<p>{}</p>", escape(&msg!(lang: lang, "report-no-notes")));
    } else {
        h.push_str("<ul>\n");
        for n in &r.notes {
            let _ = writeln!(h, "<li>{}</li>", escape(n));
        }
        h.push_str("</ul>\n");
    }
    h.push_str("</section>\n");
}
