use super::*;

fn sample_run() -> Run {
    let run = serde_json::json!({
        "title": "Ось X, шкаф 3 — 调试",
        "site": "Цех 2",
        "operator": "Иванов 李",
        "steps": [
            {"n": 1, "name": "PTO0 <configured>", "result": "ok", "duration_ms": 12.5, "started_ms": 0.0,
             "values": [{"name": "SMB67", "value": 133}], "results": [{"b": 1, "a": 2}]},
            {"n": 2, "name": "Position", "result": "failed", "expected": "20000", "measured": "19990",
             "error": "assert_eq failed"},
            {"n": 3, "name": "Later", "result": "skipped"}
        ],
        "notes": ["<script>alert(1)</script>"],
        "traces": [{"title": "long", "t_s": (0..60_000).map(|i| i as f64 * 0.01).collect::<Vec<_>>(),
                    "series": [{"operand": "SMD38", "values": (0..60_000).map(|i| (i % 977) as f64).collect::<Vec<_>>()}]}]
    });
    serde_json::from_value(run).unwrap()
}

fn ctx(lang: Lang) -> Context {
    Context {
        devices: vec![
            serde_json::json!({"name": "plc", "family": "k2", "model": "K205-16DT", "url": "sim:K205-16DT", "simulated": true}),
        ],
        date: rfc3339(1_796_684_646),
        stepped: true,
        start_ms: 0.0,
        end_ms: 1500.0,
        writes: Vec::new(),
        writes_not_kept: 0,
        lang,
    }
}

#[test]
fn the_record_counts_steps_and_decimates_curves() {
    let r = Report::build(sample_run(), ctx(Lang::En));
    assert_eq!(r.summary.result, "failed");
    assert_eq!((r.summary.ok, r.summary.failed, r.summary.skipped), (1, 1, 1));
    let t = &r.traces[0];
    assert_eq!(t.samples, 60_000);
    assert!(t.decimated && t.series[0].points.len() <= 2 * PLOT_COLUMNS);
    assert_eq!(t.series[0].max, 976.0);
    assert_eq!(t.t_end_s, 599.99);
}

#[test]
fn two_renderings_of_one_record_are_identical_and_escape_recorded_text() {
    let a = Report::build(sample_run(), ctx(Lang::Ru));
    let b = Report::build(sample_run(), ctx(Lang::Ru));
    assert_eq!(a.json(), b.json());
    let h = html::render(&a);
    assert_eq!(h, html::render(&b));
    assert!(!h.contains("<script>"), "recorded text is escaped");
    assert!(h.contains("&lt;script&gt;"));
    assert!(h.contains("Ось X, шкаф 3 — 调试"));
    assert!(h.contains("Перечень проверок"), "headings in the report's language");
    for id in ["summary", "devices", "checklist", "params", "curves", "writes", "notes"] {
        assert!(h.contains(&format!("<section id=\"{id}\">")), "{id}");
    }
    assert_eq!(h.matches("<svg").count(), 1);
    assert!(!h.contains("http://") || !h.contains("src=\"http"), "nothing fetched");
    // Keys of recorded objects are sorted, whatever order they came in.
    let j: serde_json::Value = serde_json::from_str(&a.json()).unwrap();
    let keys: Vec<&String> = j["steps"][0]["results"][0].as_object().unwrap().keys().collect();
    assert_eq!(keys, ["a", "b"]);
    assert!(h.len() < 400_000, "{}", h.len());
}

#[test]
fn the_twin_sits_beside_the_page() {
    use std::path::Path;
    assert_eq!(json_path(Path::new("r/axis-x.html")), Path::new("r/axis-x.json"));
    assert_eq!(json_path(Path::new("axis.HTM")), Path::new("axis.json"));
    assert_eq!(json_path(Path::new("axis")), Path::new("axis.json"));
    assert_eq!(rfc3339(0), "1970-01-01T00:00:00Z");
    assert_eq!(rfc3339(951_782_400), "2000-02-29T00:00:00Z", "a leap day");
    assert_eq!(rfc3339(1_796_684_646), "2026-12-07T23:04:06Z");
}
