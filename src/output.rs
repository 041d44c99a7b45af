//! Rendering command results: tables (comfy-table) for people, one JSON object per line
//! (serde) for programs. Everything writes to `impl Write`, so it is testable without a
//! terminal. Depends on core value types only.
//!
//! JSON schema (stable; documented in README.md):
//! success `{"ok":true,"cmd":…,"device":…,"values":[{"operand","value","type"}],…}`;
//! failure `{"ok":false,"cmd":…,"error":{"kind","message","device"?,"operand"?,"hint"?,"column"?}}`.

use crate::core::{DataType, Error, Value};
use comfy_table::{presets, ContentArrangement, Table};
use serde::Serialize;
use std::io::{self, Write};

/// One value read or written, as reported to users and scripts (`values`, `writes`).
#[derive(Clone, Debug, PartialEq, Serialize)]
pub struct Reading {
    pub operand: String,
    pub value: Value,
    #[serde(rename = "type")]
    pub dtype: DataType,
    /// Set when a command touches several devices.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub device: Option<String>,
    /// The operand's tag name, when the device has a tag that is exactly this operand
    /// (`crate::names`): shown as `Tank2_Level (VD200/REAL)`, `name` beside `operand` in JSON.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub name: Option<String>,
    /// The tag's comment, when it has one (a column of its own in text).
    #[serde(skip_serializing_if = "Option::is_none")]
    pub comment: Option<String>,
}

impl Reading {
    /// A reading of an operand that has no name.
    pub fn plain(operand: String, value: Value, dtype: DataType) -> Reading {
        Reading { operand, value, dtype, device: None, name: None, comment: None }
    }
}

/// How a result is shown to a person.
#[derive(Clone, Debug, Default)]
pub enum View {
    /// `operand = value` lines (the `values` field).
    #[default]
    Values,
    /// A table.
    Table { headers: Vec<String>, rows: Vec<Vec<String>> },
    /// Free text.
    Text(String),
    /// Nothing (the command succeeded silently).
    Quiet,
}

/// The result of one command.
#[derive(Clone, Debug, Default, Serialize)]
pub struct Outcome {
    pub cmd: String,
    #[serde(skip_serializing_if = "Option::is_none")]
    pub device: Option<String>,
    #[serde(skip_serializing_if = "Vec::is_empty")]
    pub values: Vec<Reading>,
    #[serde(skip_serializing_if = "Vec::is_empty")]
    pub writes: Vec<Reading>,
    #[serde(skip_serializing_if = "Option::is_none")]
    pub message: Option<String>,
    /// Things the user should know about how the command was read or what it did (a warning,
    /// a spelling accepted); printed as `note: …` before the result, `notes` in JSON.
    #[serde(skip_serializing_if = "Vec::is_empty")]
    pub notes: Vec<String>,
    /// Command-specific fields (flattened into the JSON object).
    #[serde(flatten)]
    pub data: serde_json::Map<String, serde_json::Value>,
    #[serde(skip)]
    pub view: View,
}

impl Outcome {
    pub fn new(cmd: &str) -> Outcome {
        Outcome { cmd: cmd.to_string(), ..Default::default() }
    }
    pub fn note(mut self, n: impl Into<String>) -> Outcome {
        self.notes.push(n.into());
        self
    }
    pub fn quiet(mut self) -> Outcome {
        self.view = View::Quiet;
        self
    }
    /// Marks an outcome that moved or changed something on device `name` with whether
    /// the device is simulated: the text starts `plc(sim): ` or `press1(real): ` and the
    /// JSON carries `simulated`, so a line never leaves doubt about where it acted.
    pub fn acted_on(mut self, name: &str, simulated: bool) -> Outcome {
        let mark = format!("{name}({}): ", if simulated { "sim" } else { "real" });
        if let View::Text(t) = &mut self.view {
            t.insert_str(0, &mark);
        }
        if let Some(m) = &mut self.message {
            m.insert_str(0, &mark);
        }
        self.device = Some(name.to_string());
        self.data.insert("simulated".into(), serde_json::json!(simulated));
        self
    }
    pub fn text(mut self, t: impl Into<String>) -> Outcome {
        let t = t.into();
        self.message = Some(t.clone());
        self.view = View::Text(t);
        self
    }
    pub fn with(mut self, key: &str, v: impl Serialize) -> Outcome {
        self.data.insert(key.to_string(), serde_json::to_value(v).unwrap_or(serde_json::Value::Null));
        self
    }
    pub fn table<S: AsRef<str>>(mut self, headers: &[S], rows: Vec<Vec<String>>) -> Outcome {
        self.view = View::Table { headers: headers.iter().map(|s| s.as_ref().to_string()).collect(), rows };
        self
    }
    /// The same data as `--json` prints, as a JSON value (for Lua and tests).
    pub fn to_json(&self) -> serde_json::Value {
        serde_json::to_value(JsonOk { ok: true, outcome: self }).unwrap_or_default()
    }
}

/// A table's column headings from one catalogue message (`|` between them), so a language
/// has them side by side (`lab-grade-columns`, `probe-columns`).
pub fn headings(m: crate::core::msg::Msg) -> Vec<String> {
    m.text.split('|').map(|h| h.trim().to_string()).collect()
}

#[derive(Serialize)]
struct JsonOk<'a> {
    ok: bool,
    #[serde(flatten)]
    outcome: &'a Outcome,
}

#[derive(Serialize)]
struct JsonErr<'a> {
    ok: bool,
    cmd: &'a str,
    error: &'a Error,
}

/// Output settings.
#[derive(Clone, Copy, Debug, Default)]
pub struct Style {
    pub json: bool,
    pub color: bool,
}

impl Style {
    /// Colour only where standard output takes escape codes (a terminal; on Windows a
    /// console switched to them) and `NO_COLOR` is unset: `core::platform::colour` decides.
    pub fn detect(json: bool) -> Style {
        Style { json, color: !json && crate::core::platform::colour(crate::core::platform::Stream::Stdout) }
    }
}

/// The JSON text of an error line, for callers that need it outside a writer.
pub fn error_json(cmd: &str, e: &Error) -> serde_json::Value {
    serde_json::to_value(JsonErr { ok: false, cmd, error: e }).unwrap_or_default()
}

/// Writes one successful result. Its notes (`note: …`) go to standard error, so a pipeline
/// reading the results gets only results; in JSON they are the line's `notes`.
pub fn write_outcome(w: &mut dyn Write, style: Style, o: &Outcome) -> io::Result<()> {
    if !style.json {
        for n in &o.notes {
            eprintln!("note: {n}");
        }
    }
    // One write per result: standard output flushes at every line, and a result of ten lines
    // would otherwise be ten system calls (a pipeline still gets each result as it comes).
    let mut text = Vec::new();
    render_outcome(&mut text, style, o)?;
    w.write_all(&text)
}

/// The text (or JSON line) of one result.
fn render_outcome(w: &mut dyn Write, style: Style, o: &Outcome) -> io::Result<()> {
    if style.json {
        serde_json::to_writer(&mut *w, &JsonOk { ok: true, outcome: o })?;
        return writeln!(w);
    }
    match &o.view {
        View::Quiet => Ok(()),
        View::Text(t) => writeln!(w, "{t}"),
        View::Values => {
            let width = o.values.iter().map(|r| label(r).chars().count()).max().unwrap_or(0);
            let commented = o.values.iter().any(|r| r.comment.is_some());
            let shown: Vec<String> = o.values.iter().map(|r| show_value(&r.value, r.dtype)).collect();
            let vwidth = if commented { shown.iter().map(|v| v.chars().count()).max().unwrap_or(0) } else { 0 };
            for (r, v) in o.values.iter().zip(&shown) {
                let l = label(r);
                let pad = width - l.chars().count();
                match &r.comment {
                    Some(c) => writeln!(w, "{l}{}  {v:<vwidth$}  {c}", " ".repeat(pad))?,
                    None => writeln!(w, "{l}{}  {v}", " ".repeat(pad))?,
                }
            }
            Ok(())
        }
        View::Table { headers, rows } => {
            let mut t = Table::new();
            t.load_preset(if style.color { presets::UTF8_FULL_CONDENSED } else { presets::ASCII_MARKDOWN });
            t.set_content_arrangement(ContentArrangement::Disabled);
            if !style.color {
                t.force_no_tty();
            }
            t.set_header(headers);
            for r in rows {
                t.add_row(r);
            }
            writeln!(w, "{t}")
        }
    }
}

/// `VW100`, `press:VW100`, `Tank2_Level (VD200/REAL)`, `press:Tank2_Level (VD200/REAL)`.
pub fn label(r: &Reading) -> String {
    let dev = r.device.as_deref().map(|d| format!("{d}:")).unwrap_or_default();
    match &r.name {
        Some(n) => format!("{dev}{n} ({})", r.operand),
        None => format!("{dev}{}", r.operand),
    }
}

/// A value as a person reads it: decimal, with the hex pattern for bytes and words.
pub fn show_value(v: &Value, t: DataType) -> String {
    match (v, t) {
        (Value::Int(i), DataType::Byte | DataType::Word | DataType::DWord) if *i > 9 => {
            format!("{i} ({})", hex(*i as u64, t.bits()))
        }
        (v, _) => v.to_string(),
    }
}

/// `16#85`, `16#01F4`: IEC hex with the operand's width.
pub fn hex(raw: u64, bits: u32) -> String {
    format!("16#{:0w$X}", raw & crate::core::value::mask(bits.clamp(1, 32)), w = (bits.div_ceil(4)) as usize)
}

/// `2#1000_0101`: IEC binary grouped in nibbles.
pub fn binary(raw: u64, bits: u32) -> String {
    let s = format!("{:0w$b}", raw & crate::core::value::mask(bits.clamp(1, 32)), w = bits as usize);
    let chunks: Vec<String> = s.as_bytes().rchunks(4).rev().map(|c| String::from_utf8_lossy(c).into_owned()).collect();
    format!("2#{}", chunks.join("_"))
}

/// Reports one error where its reader looks: with `--json` as an error object on `out` (the
/// stream a pipeline parses), otherwise as text on standard error, as mbpoll and most
/// command-line tools do (`out` is flushed first so the two streams stay in order).
pub fn report_error(out: &mut dyn Write, style: Style, cmd: &str, e: &Error, line: Option<&str>) -> io::Result<()> {
    if style.json {
        return write_error(out, style, cmd, e, line);
    }
    out.flush()?;
    let mut err = io::stderr().lock();
    write_error(&mut err, style, cmd, e, line)?;
    err.flush()
}

/// Writes one error, with a caret under the column when the error came from `line`.
pub fn write_error(w: &mut dyn Write, style: Style, cmd: &str, e: &Error, line: Option<&str>) -> io::Result<()> {
    if style.json {
        serde_json::to_writer(&mut *w, &JsonErr { ok: false, cmd, error: e })?;
        return writeln!(w);
    }
    // The column is a byte offset in the line; the caret goes under it on a terminal, where a
    // Chinese character takes two columns (UAX #11) and a Cyrillic letter one.
    if let (Some(line), Some(col)) = (line, e.column) {
        if let Some(before) = line.get(..col) {
            writeln!(w, "  {line}")?;
            writeln!(w, "  {}^", " ".repeat(unicode_width::UnicodeWidthStr::width(before)))?;
        }
    }
    let (red, reset) = if style.color { ("\x1b[31m", "\x1b[0m") } else { ("", "") };
    let mut msg = e.clone();
    let hint = msg.hint.take();
    writeln!(w, "{red}error[{}]{reset}: {msg}", e.kind.name())?;
    if let Some(h) = hint {
        writeln!(w, "  {}", crate::msg!("label-hint", hint = h))?;
    }
    Ok(())
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::core::ErrorKind;

    fn reading(op: &str, v: i64, t: DataType) -> Reading {
        Reading::plain(op.into(), Value::Int(v), t)
    }

    #[test]
    fn json_line_matches_the_documented_shape() {
        let mut o = Outcome::new("get");
        o.device = Some("plc".into());
        o.values.push(reading("VW100", 5, DataType::Word));
        let mut buf = Vec::new();
        write_outcome(&mut buf, Style { json: true, color: false }, &o).unwrap();
        assert_eq!(
            String::from_utf8(buf).unwrap(),
            "{\"ok\":true,\"cmd\":\"get\",\"device\":\"plc\",\"values\":[{\"operand\":\"VW100\",\"value\":5,\"type\":\"WORD\"}]}\n"
        );
    }

    #[test]
    fn error_json_and_caret() {
        let e = Error::new(ErrorKind::Value, "300 does not fit").operand("VB2").column(11);
        let mut buf = Vec::new();
        write_error(&mut buf, Style { json: true, color: false }, "set", &e, None).unwrap();
        let v: serde_json::Value = serde_json::from_slice(&buf).unwrap();
        assert_eq!(v["ok"], false);
        assert_eq!(v["error"]["kind"], "value");
        assert_eq!(v["error"]["operand"], "VB2");
        let mut human = Vec::new();
        write_error(&mut human, Style::default(), "set", &e, Some("set VB2=300")).unwrap();
        let text = String::from_utf8(human).unwrap();
        assert!(text.contains("  set VB2=300\n             ^\n"), "{text}");
        assert!(text.contains("error[value]"));
    }

    #[test]
    fn tables_align_chinese_text_by_display_width() {
        // A Chinese character takes two columns of a terminal (UAX #11 East Asian Wide): the
        // table's borders line up only if comfy-table counts display columns, not chars.
        let o = Outcome::new("read").table(
            &["operand", "value"],
            vec![vec!["VW0".into(), "温度传感器".into()], vec!["VW2".into(), "1".into()]],
        );
        let mut buf = Vec::new();
        write_outcome(&mut buf, Style::default(), &o).unwrap();
        let s = String::from_utf8(buf).unwrap();
        let width =
            |l: &str| l.chars().map(|c| if ('\u{4e00}'..='\u{9fff}').contains(&c) { 2 } else { 1 }).sum::<usize>();
        let lines: Vec<&str> = s.lines().filter(|l| !l.is_empty()).collect();
        assert!(lines.len() >= 4 && s.contains("温度传感器"), "{s}");
        assert!(lines.iter().all(|l| width(l) == width(lines[0])), "{s}");
    }

    #[test]
    fn hex_and_binary_use_the_operand_width() {
        assert_eq!(hex(0x85, 8), "16#85");
        assert_eq!(hex(500, 16), "16#01F4");
        assert_eq!(binary(0x85, 8), "2#1000_0101");
        assert_eq!(binary(1, 1), "2#1");
        assert_eq!(binary(0xFFFF_FFFF, 32).len(), 2 + 32 + 7);
    }

    #[test]
    fn table_renders_without_colour_as_ascii() {
        let o = Outcome::new("read").table(&["operand", "value"], vec![vec!["VW0".into(), "1".into()]]);
        let mut buf = Vec::new();
        write_outcome(&mut buf, Style::default(), &o).unwrap();
        let s = String::from_utf8(buf).unwrap();
        assert!(s.contains("| VW0") && !s.contains('\x1b'), "{s}");
    }
}
