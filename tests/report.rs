//! Commissioning reports (docs/commissioning.md) made by the real binary: the wired bench's
//! axis commissioned by scripts/commission_axis.lua gives the HTML page and its JSON twin,
//! byte-identical when the rehearsal runs twice in stepped time; the twin validates against
//! docs/report.schema.json; a report with Cyrillic and Chinese text, a failed step, a refused
//! parameter and a 10-minute trace stays correct and under the documented sizes; and headless
//! Chromium renders the page without console errors, prints it on A4 and takes a screenshot
//! that is not blank (the page's picture in docs/ is made here with PLCSH_BLESS=1).
//!
//! The schema check is hand-written: a validator of the JSON Schema keywords the schema uses
//! (`type`, `const`, `enum`, `required`, `properties`, `additionalProperties`, `items`,
//! `minItems`, `maxItems`, `minimum`, `$ref` into `$defs`), which refuses a schema that uses
//! any other keyword, so no rule of the schema is silently ignored.

mod common;
use common::*;
use serde_json::Value;
use std::path::{Path, PathBuf};
use std::process::Command;

/// The date every rehearsal's report carries (SOURCE_DATE_EPOCH, the reproducible-builds rule).
const EPOCH: &str = "1796684646";

/// Sizes docs/commissioning.md promises for a report (HTML page, JSON twin).
const MAX_HTML: usize = 1_000_000;
const MAX_JSON: usize = 1_000_000;

fn root() -> &'static Path {
    Path::new(env!("CARGO_MANIFEST_DIR"))
}

fn dir(name: &str) -> PathBuf {
    let d = std::env::temp_dir().join(format!("plcsh-report-{}-{name}", std::process::id()));
    let _ = std::fs::remove_dir_all(&d);
    std::fs::create_dir_all(&d).unwrap();
    d
}

fn plcsh_in(d: &Path, args: &[&str]) -> std::process::Output {
    let o = plcsh().current_dir(d).env("SOURCE_DATE_EPOCH", EPOCH).args(args).output().expect("start plcsh");
    o
}

/// Commissions the bench's axis into `d`/axis-x.html; returns (html, json).
fn commission_bench(d: &Path, lang: &str) -> (String, String) {
    let bench = root().join("machines/pto_servo_encoder.toml");
    let script = root().join("scripts/commission_axis.lua");
    let o = plcsh_in(
        d,
        &[
            "--lang",
            lang,
            "--time",
            "stepped",
            "--bench",
            bench.to_str().unwrap(),
            "run",
            "--report",
            "axis-x.html",
            script.to_str().unwrap(),
            d.to_str().unwrap(),
        ],
    );
    assert!(o.status.success(), "{}", both(&o));
    assert!(stdout(&o).contains("report: axis-x.html (axis-x.json)"), "{}", both(&o));
    (std::fs::read_to_string(d.join("axis-x.html")).unwrap(), std::fs::read_to_string(d.join("axis-x.json")).unwrap())
}

// ---- A validator for the JSON Schema subset docs/report.schema.json uses -------------------

const KEYWORDS: &[&str] = &[
    "$schema",
    "$id",
    "$defs",
    "$ref",
    "title",
    "description",
    "type",
    "const",
    "enum",
    "required",
    "properties",
    "additionalProperties",
    "items",
    "minItems",
    "maxItems",
    "minimum",
];

fn schema() -> Value {
    serde_json::from_str(&std::fs::read_to_string(root().join("docs/report.schema.json")).unwrap()).unwrap()
}

/// Every keyword of every schema node is one the validator knows.
fn known_keywords(s: &Value, at: &str, bad: &mut Vec<String>) {
    let Some(o) = s.as_object() else { return };
    for (k, v) in o {
        if !KEYWORDS.contains(&k.as_str()) {
            bad.push(format!("{at}/{k}"));
        }
        match k.as_str() {
            "properties" | "$defs" => {
                for (name, sub) in v.as_object().unwrap() {
                    known_keywords(sub, &format!("{at}/{k}/{name}"), bad);
                }
            }
            "items" => known_keywords(v, &format!("{at}/items"), bad),
            _ => {}
        }
    }
}

fn type_ok(t: &str, v: &Value) -> bool {
    match t {
        "object" => v.is_object(),
        "array" => v.is_array(),
        "string" => v.is_string(),
        "number" => v.is_number(),
        "integer" => v.is_i64() || v.is_u64(),
        "boolean" => v.is_boolean(),
        "null" => v.is_null(),
        other => panic!("the schema names type {other}"),
    }
}

fn validate(root_schema: &Value, s: &Value, v: &Value, at: &str, errors: &mut Vec<String>) {
    if let Some(r) = s.get("$ref").and_then(Value::as_str) {
        let name = r.strip_prefix("#/$defs/").expect("refs point into $defs");
        return validate(root_schema, &root_schema["$defs"][name], v, at, errors);
    }
    if let Some(t) = s.get("type") {
        let ok = match t {
            Value::String(t) => type_ok(t, v),
            Value::Array(ts) => ts.iter().any(|t| type_ok(t.as_str().unwrap(), v)),
            _ => panic!("type at {at}"),
        };
        if !ok {
            errors.push(format!("{at}: {v} is not {t}"));
            return;
        }
    }
    if let Some(c) = s.get("const") {
        if c != v {
            errors.push(format!("{at}: {v} is not {c}"));
        }
    }
    if let Some(e) = s.get("enum").and_then(Value::as_array) {
        if !e.contains(v) {
            errors.push(format!("{at}: {v} is not one of {e:?}"));
        }
    }
    if let (Some(m), Some(n)) = (s.get("minimum").and_then(Value::as_f64), v.as_f64()) {
        if n < m {
            errors.push(format!("{at}: {n} < {m}"));
        }
    }
    if let Some(o) = v.as_object() {
        for r in s.get("required").and_then(Value::as_array).into_iter().flatten() {
            if !o.contains_key(r.as_str().unwrap()) {
                errors.push(format!("{at}: `{}` missing", r.as_str().unwrap()));
            }
        }
        let props = s.get("properties").and_then(Value::as_object);
        for (k, x) in o {
            match props.and_then(|p| p.get(k)) {
                Some(ps) => validate(root_schema, ps, x, &format!("{at}/{k}"), errors),
                None if s.get("additionalProperties") == Some(&Value::Bool(false)) => {
                    errors.push(format!("{at}: `{k}` is not in the schema"))
                }
                None => {}
            }
        }
    }
    if let Some(a) = v.as_array() {
        if let Some(n) = s.get("minItems").and_then(Value::as_u64) {
            if (a.len() as u64) < n {
                errors.push(format!("{at}: {} items < {n}", a.len()));
            }
        }
        if let Some(n) = s.get("maxItems").and_then(Value::as_u64) {
            if a.len() as u64 > n {
                errors.push(format!("{at}: {} items > {n}", a.len()));
            }
        }
        if let Some(items) = s.get("items") {
            for (i, x) in a.iter().enumerate() {
                validate(root_schema, items, x, &format!("{at}/{i}"), errors);
            }
        }
    }
}

fn schema_errors(json: &Value) -> Vec<String> {
    let s = schema();
    let mut errors = Vec::new();
    validate(&s, &s, json, "", &mut errors);
    errors
}

#[test]
fn the_schema_uses_only_what_the_validator_checks_and_the_validator_refuses_bad_twins() {
    let s = schema();
    let mut bad = Vec::new();
    known_keywords(&s, "", &mut bad);
    assert!(bad.is_empty(), "keywords the test's validator does not check: {bad:?}");
    // The validator can fail: a twin with a wrong format, a missing part, an unknown key and a
    // step result the schema does not list.
    let wrong = serde_json::json!({"format": "plcsh-report/2", "title": 1, "extra": true,
        "steps": [{"n": 0, "result": "maybe"}]});
    let e = schema_errors(&wrong);
    for expect in ["/format", "/title", "`extra`", "`time` missing", "/steps/0/result", "/steps/0/n"] {
        assert!(e.iter().any(|x| x.contains(expect)), "{expect} in {e:#?}");
    }
}

// ---- The wired bench's axis --------------------------------------------------------------

#[test]
fn the_bench_axis_gives_a_report_byte_identical_on_a_second_rehearsal() {
    let d = dir("bench");
    let (html, json) = commission_bench(&d, "en");
    let (html2, json2) = commission_bench(&d, "en");
    assert!(html == html2, "the HTML page differs between two rehearsals");
    assert!(json == json2, "the JSON twin differs between two rehearsals");

    let j: Value = serde_json::from_str(&json).unwrap();
    let errors = schema_errors(&j);
    assert!(errors.is_empty(), "the twin against docs/report.schema.json:\n{}", errors.join("\n"));
    assert_eq!(j["time"]["date"], "2026-12-07T23:04:06Z", "SOURCE_DATE_EPOCH gives the date");
    assert_eq!(j["time"]["clock"], "stepped");
    assert_eq!(j["summary"]["result"], "passed");
    assert_eq!(j["summary"]["ok"], 8);
    // Devices with what they report about themselves.
    let devices = j["devices"].as_array().unwrap();
    assert_eq!(devices.len(), 2);
    let servo = devices.iter().find(|d| d["family"] == "servo").unwrap();
    assert_eq!(servo["reports"]["state"], "operation enabled");
    assert_eq!(servo["reports"]["cmd"], "servo", "the command's own --json result");
    // The move's measured values, a recorded command result, the parameter sets.
    let mv = &j["steps"][5];
    let value =
        |name: &str| mv["values"].as_array().unwrap().iter().find(|v| v["name"] == name).unwrap()["value"].clone();
    assert_eq!(value("pulses out (SMD212)"), 8000);
    assert_eq!(value("drive moved"), 32000);
    assert_eq!(j["steps"][1]["results"][0]["state"], "operation enabled");
    let params = j["params"].as_array().unwrap();
    assert_eq!(params[0]["action"], "compared");
    assert_eq!(params[0]["differences"].as_array().unwrap().len(), 0);
    assert_eq!(params[1]["action"], "saved");
    assert!(params[1]["result"]["parameters"].as_array().unwrap().len() > 20);
    // The curve: the whole move, HSC0's count rising to 16000.
    let t = &j["traces"][0];
    assert_eq!(t["samples"], 141, "700 ms every 5 ms");
    assert_eq!(t["series"][0]["name"], "SMD38");
    assert_eq!(t["series"][0]["max"], 16000.0);
    // The write log: the guard saw the script's plain writes and the helpers' operations.
    let writes = j["writes"].as_array().unwrap();
    let smb201: Vec<&Value> = writes.iter().filter(|w| w["operand"] == "SMB201").collect();
    assert_eq!(smb201.len(), 2, "{smb201:?}");
    assert_eq!(
        (smb201[0]["new"].clone(), smb201[1]["old"].clone(), smb201[1]["new"].clone()),
        (64.into(), 64.into(), 0.into())
    );
    assert!(writes.iter().all(|w| w["t_ms"].as_f64().unwrap() <= j["time"]["end_ms"].as_f64().unwrap()));
    assert!(
        writes.iter().any(|w| w["device"] == "plc" && w["action"].is_string()),
        "a K2 instruction's changes are logged"
    );

    for id in ["summary", "devices", "checklist", "params", "curves", "writes", "notes"] {
        assert!(html.contains(&format!("<section id=\"{id}\">")), "section {id}");
    }
    assert_eq!(html.matches("<svg").count(), 1, "one plot");
    assert!(html.contains("HSC0 count and PTO0 pulses during the move"));
    for fetch in ["src=", "href=", "url(", "@import", "<script"] {
        assert!(!html.contains(fetch), "a self-contained page fetches nothing: {fetch}");
    }
    assert!(html.len() < MAX_HTML && json.len() < MAX_JSON);
}

/// A report in Russian with Chinese text, a failed step, a refused parameter and a 10-minute
/// trace: correct, and under the documented sizes (the trace decimated, not truncated).
#[test]
fn cyrillic_chinese_a_failed_step_a_refused_parameter_and_ten_minutes_of_trace() {
    let d = dir("stress");
    let reference = root().join("machines/pto_servo_encoder.servo.toml");
    let script = format!(
        r#"
local commission = require("commission")
local plc, servo = plcsh.device("plc"), plcsh.device("servo")
local c = commission.new("Ось X — 调试轴 <1>", {{report = "отчёт.html", operator = "Иванов И. И.", site = "车间 2, линия 3", keep_going = true}})
c:note("Запуск после замены привода; 更换驱动器后调试")
c:step("Параметры привода", function()
  servo.gear_factor = 3
  servo:cmd("servo sim fault abort profile_velocity 16#08000020")
  local d = c:attach_params(servo, {reference:?})
  c:measure("отличий", d.count)
end)
c:step("Позиция 位置", function()
  plcsh.assert_eq(plc.VW0, 5, "VW0 после наладки")
end)
c:step("Десять минут счёта", function()
  plc:pto(0, {{cycle = 1000, count = 1000000}})
  c:trace{{plc, "SMD212", "VW0", every = 10, ["for"] = 600000, title = "10 минут, 十分钟"}}
  return "готово"
end)
c:run()
"#
    );
    std::fs::write(d.join("stress.lua"), script).unwrap();
    let o = plcsh_in(&d, &["--lang", "ru", "--time", "stepped", "run", "stress.lua"]);
    assert_eq!(o.status.code(), Some(1), "a failed required step fails the run:\n{}", both(&o));
    let html = std::fs::read_to_string(d.join("отчёт.html")).expect("the report is written even when a step failed");
    let json = std::fs::read_to_string(d.join("отчёт.json")).unwrap();
    eprintln!("report sizes: HTML {} bytes, JSON {} bytes", html.len(), json.len());
    assert!(html.len() < MAX_HTML, "HTML {} bytes", html.len());
    assert!(json.len() < MAX_JSON, "JSON {} bytes", json.len());
    let j: Value = serde_json::from_str(&json).unwrap();
    let errors = schema_errors(&j);
    assert!(errors.is_empty(), "{}", errors.join("\n"));
    assert_eq!(j["language"], "ru");
    assert_eq!(j["summary"]["result"], "failed");
    // The failed step: expected and measured.
    let failed = &j["steps"][1];
    assert_eq!(failed["result"], "failed");
    assert_eq!((failed["expected"].as_str(), failed["measured"].as_str()), (Some("5"), Some("0")));
    assert!(html.contains("Ожидалось") && html.contains("Измерено"), "labels in Russian");
    assert!(html.contains("Перечень проверок") && html.contains("Запись в устройства"));
    // Text kept as written, markup escaped.
    assert!(html.contains("Ось X — 调试轴 &lt;1&gt;") && html.contains("车间 2, линия 3"));
    assert!(j["title"] == "Ось X — 调试轴 <1>");
    // The refused parameter: listed as refused, never with a guessed value.
    let diffs = j["params"][0]["differences"].as_array().unwrap();
    let pv = diffs.iter().find(|x| x["name"] == "profile_velocity").expect("the refused parameter is listed");
    assert_eq!(pv["right"]["status"], "refused");
    assert!(pv["right"].get("value").is_none());
    assert!(diffs.iter().any(|x| x["name"] == "gear_factor"), "the changed gear differs from the reference");
    // Ten minutes every 10 ms: 60 001 samples, kept as at most 2 × 800 points, start to end.
    let t = &j["traces"][0];
    assert_eq!(t["samples"], 60_001);
    assert_eq!(t["decimated"], true);
    assert_eq!(t["t_end_s"].as_f64().unwrap() - t["t_start_s"].as_f64().unwrap(), 600.0);
    let pts = t["series"][0]["points"].as_array().unwrap();
    assert!(pts.len() <= 1600 && pts.len() >= 800, "{}", pts.len());
    assert_eq!(pts.last().unwrap()[0], t["t_end_s"], "not truncated: the last point is the last sample");
    assert_eq!(t["series"][0]["max"], t["series"][0]["last"], "the pulse count only rises");
    assert!(t["series"][0]["last"].as_f64().unwrap() > 590_000.0, "1 kHz for 600 s");
}

/// A script without the runner, `plcsh run --report`: the devices and the writes it made, in
/// the language chosen (Chinese here).
#[test]
fn any_script_run_with_report_gets_its_devices_and_writes() {
    let d = dir("plain");
    std::fs::write(d.join("plain.lua"), "plc.VW10 = 7\nplc.VW10 = 8\nservo:enable()\n").unwrap();
    let o = plcsh_in(&d, &["--lang", "zh-CN", "--time", "stepped", "run", "--report", "r.html", "plain.lua"]);
    assert!(o.status.success(), "{}", both(&o));
    let j: Value = serde_json::from_str(&std::fs::read_to_string(d.join("r.json")).unwrap()).unwrap();
    assert!(schema_errors(&j).is_empty(), "{:?}", schema_errors(&j));
    let w: Vec<(Value, Value, Value)> = j["writes"]
        .as_array()
        .unwrap()
        .iter()
        .map(|w| (w["operand"].clone(), w["old"].clone(), w["new"].clone()))
        .collect();
    let e = |op: &str, old: i64, new: i64| (Value::from(op), Value::from(old), Value::from(new));
    // Plain writes, then the drive's enable sequence (DS402 shutdown, switch on, enable
    // operation): object writes the guard sees as operations, read back after each.
    assert_eq!(
        w,
        vec![e("VW10", 0, 7), e("VW10", 7, 8), e("controlword", 0, 6), e("controlword", 6, 7), e("controlword", 7, 15)]
    );
    assert_eq!(j["title"], "plain.lua");
    let html = std::fs::read_to_string(d.join("r.html")).unwrap();
    assert!(html.contains("对设备的写入") && html.contains("lang=\"zh-CN\""), "headings in Chinese");
}

// ---- Headless Chromium ---------------------------------------------------------------------

fn chromium() -> Option<&'static str> {
    for c in ["chromium", "chromium-browser"] {
        if Command::new(c).arg("--version").output().is_ok_and(|o| o.status.success()) {
            return Some(c);
        }
    }
    assert!(std::env::var_os("CI").is_none(), "chromium is required when CI is set (.ci/run installs it)");
    skipped("chromium (apt-get install chromium)");
    None
}

/// Runs headless Chromium on `page` with `args`; returns (stdout, stderr).
fn headless(browser: &str, d: &Path, page: &Path, args: &[&str]) -> (String, String) {
    let profile = d.join("chromium-profile");
    let o = Command::new(browser)
        .args(["--headless", "--no-sandbox", "--disable-gpu", "--no-first-run", "--hide-scrollbars"])
        .arg(format!("--user-data-dir={}", profile.display()))
        .args(["--enable-logging=stderr", "--v=0", "--virtual-time-budget=2000"])
        .args(args)
        .arg(format!("file://{}", page.display()))
        .env("HOME", d)
        .output()
        .expect("start chromium");
    (String::from_utf8_lossy(&o.stdout).into_owned(), String::from_utf8_lossy(&o.stderr).into_owned())
}

/// Console messages Chromium logged for the page (`CONSOLE` lines) and script errors.
fn console_errors(stderr: &str) -> Vec<&str> {
    stderr.lines().filter(|l| l.contains("CONSOLE") || l.contains("Uncaught")).collect()
}

/// Width, height and the share of pixels that are not near-white.
fn png_figures(path: &Path) -> (u32, u32, f64) {
    let decoder = png::Decoder::new(std::fs::File::open(path).unwrap());
    let mut reader = decoder.read_info().unwrap();
    let mut buf = vec![0; reader.output_buffer_size()];
    let info = reader.next_frame(&mut buf).unwrap();
    let bytes = &buf[..info.buffer_size()];
    let step = info.color_type.samples();
    let pixels = bytes.chunks(step);
    let total = (info.width * info.height) as f64;
    let inked = pixels.filter(|p| p.iter().take(3).any(|&c| c < 230)).count() as f64;
    (info.width, info.height, inked / total)
}

/// Where the page's picture in docs/commissioning.md lives, and its size.
const SCREENSHOT: &str = "docs/images/commissioning-report.png";
const SHOT_SIZE: (u32, u32) = (900, 1400);

#[test]
fn chromium_renders_prints_on_a4_and_shows_the_report() {
    let Some(browser) = chromium() else { return };
    let d = dir("chromium");
    let (html, _) = commission_bench(&d, "en");
    let page = d.join("axis-x.html");

    // The detector of console errors can fail: a page that logs one is caught.
    let control = d.join("control.html");
    std::fs::write(&control, "<!DOCTYPE html><title>x</title><script>console.error('broken page')</script>").unwrap();
    let (_, err) = headless(browser, &d, &control, &["--dump-dom"]);
    assert!(console_errors(&err).iter().any(|l| l.contains("broken page")), "the console is seen:\n{err}");

    // The report: no console message, every section and the plot in the rendered DOM.
    let (dom, err) = headless(browser, &d, &page, &["--dump-dom"]);
    assert!(console_errors(&err).is_empty(), "console errors:\n{err}");
    for id in ["summary", "devices", "checklist", "params", "curves", "writes", "notes"] {
        assert!(dom.contains(&format!("<section id=\"{id}\">")), "section {id} rendered");
    }
    assert_eq!(dom.matches("<svg").count(), html.matches("<svg").count(), "every plot rendered");
    assert!(dom.contains("<polyline") || dom.contains("<path"), "the plot has its curve");

    // Printing: A4 pages (595 × 842 pt), one section per page at least.
    let pdf = d.join("axis-x.pdf");
    let (_, err) =
        headless(browser, &d, &page, &[&format!("--print-to-pdf={}", pdf.display()), "--no-pdf-header-footer"]);
    let bytes = std::fs::read(&pdf).unwrap_or_else(|e| panic!("no PDF ({e}):\n{err}"));
    let text = String::from_utf8_lossy(&bytes);
    let boxes: Vec<&str> = text.match_indices("/MediaBox").map(|(i, _)| &text[i..(i + 60).min(text.len())]).collect();
    assert!(!boxes.is_empty(), "the PDF has pages");
    for b in &boxes {
        let nums: Vec<f64> =
            b[b.find('[').unwrap() + 1..b.find(']').unwrap()].split_whitespace().map(|n| n.parse().unwrap()).collect();
        assert_eq!((nums[2].round(), nums[3].round()), (595.0, 842.0), "A4 in points: {b}");
    }
    let pages = text.matches("/Type /Page\n").count()
        + text.matches("/Type /Page ").count()
        + text.matches("/Type /Page/").count();
    assert!(
        pages >= 7 || boxes.len() >= 7,
        "a page break before each of the 7 sections: {pages} pages, {} boxes",
        boxes.len()
    );

    // A screenshot: its size and a fair share of ink (text, tables, the plot).
    let shot = d.join("shot.png");
    let size = format!("--window-size={},{}", SHOT_SIZE.0, SHOT_SIZE.1);
    headless(browser, &d, &page, &[&format!("--screenshot={}", shot.display()), &size]);
    let (w, h, ink) = png_figures(&shot);
    assert_eq!((w, h), SHOT_SIZE);
    assert!(ink > 0.03 && ink < 0.6, "the screenshot shows a page, not a blank or a black one: {ink}");
    // A phone's width: the page narrows (no sideways scrolling of the whole page) and shows.
    let phone = d.join("phone.png");
    headless(browser, &d, &page, &[&format!("--screenshot={}", phone.display()), "--window-size=390,844"]);
    let (pw, _, pink) = png_figures(&phone);
    assert_eq!(pw, 390);
    assert!(pink > 0.03, "{pink}");

    // The page's picture in docs/commissioning.md: made here with PLCSH_BLESS=1, checked loosely.
    let doc_shot = root().join(SCREENSHOT);
    if std::env::var_os("PLCSH_BLESS").is_some() {
        std::fs::create_dir_all(doc_shot.parent().unwrap()).unwrap();
        std::fs::copy(&shot, &doc_shot).unwrap();
    }
    let (dw, dh, dink) = png_figures(&doc_shot);
    assert_eq!((dw, dh), SHOT_SIZE, "{SCREENSHOT}: remake it with PLCSH_BLESS=1 cargo test --test report");
    assert!((dink - ink).abs() < 0.05, "{SCREENSHOT} no longer looks like the report ({dink} vs {ink}): PLCSH_BLESS=1");
}
