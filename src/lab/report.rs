//! What `lab grade` and `lab check` show: the text table, the JSON objects and the JUnit file.
//! Every string in a report may come from a student (a verdict is often the student's own
//! `error(...)` message, a file name is the student's), so nothing reaches an output as it
//! is: [`bound`] caps each verdict, `got`, `expected` and error at [`CAP`] bytes with
//! "(… N bytes more)" and makes control characters visible (`\u{1b}`), so a JUnit file stays
//! well-formed XML 1.0 and a terminal never receives an escape sequence; the text table adds
//! [`cell`], one line per cell with newlines and `|` written out, so no verdict can draw rows
//! of its own.

use super::config::Lab;
use super::grader::{Criterion, Report};
use crate::output::Outcome;

/// The most bytes of one verdict, `got`, `expected` or error a report keeps.
pub const CAP: usize = 2048;

/// `s` cut to at most [`CAP`] bytes (at a character boundary), with what was left out.
pub fn cap(s: &str) -> String {
    if s.len() <= CAP {
        return s.to_string();
    }
    let mut end = CAP;
    while !s.is_char_boundary(end) {
        end -= 1;
    }
    format!("{} ({})", &s[..end], crate::msg!("lab-bytes-more", n = s.len() - end))
}

/// A character no output may carry as it is: C0 controls (but newline and tab, which JSON
/// and XML write escaped), DEL, C1 controls, and the characters XML 1.0 cannot hold.
fn hidden(c: char) -> bool {
    (c.is_control() && c != '\n' && c != '\t') || matches!(c, '\u{FFFE}' | '\u{FFFF}')
}

/// `s` with control characters written as `\u{1b}` (newline and tab kept).
pub fn visible(s: &str) -> String {
    if !s.chars().any(hidden) {
        return s.to_string();
    }
    let mut out = String::with_capacity(s.len() + 8);
    for c in s.chars() {
        if hidden(c) {
            out.push_str(&format!("\\u{{{:x}}}", c as u32));
        } else {
            out.push(c);
        }
    }
    out
}

/// [`visible`] and at most about [`CAP`] bytes, in one pass: what is left out of `s` is
/// counted in `s`'s own bytes.
fn clean(s: &str) -> String {
    let mut out = String::with_capacity(s.len().min(CAP + 64));
    for (i, c) in s.char_indices() {
        if out.len() >= CAP {
            out.push_str(&format!(" ({})", crate::msg!("lab-bytes-more", n = s.len() - i)));
            return out;
        }
        if hidden(c) {
            out.push_str(&format!("\\u{{{:x}}}", c as u32));
        } else {
            out.push(c);
        }
    }
    out
}

fn clean_opt(s: &mut Option<String>) {
    if let Some(t) = s {
        *t = clean(t);
    }
}

fn clean_value(v: &mut Option<serde_json::Value>) {
    if let Some(serde_json::Value::String(t)) = v {
        *t = clean(t);
    }
}

/// Bounds every string of a report ([`cap`] and [`visible`]): done once, where the reports
/// come back from the workers, so the JSON, the table and the JUnit file show the same text.
pub fn bound(r: &mut Report) {
    r.student = clean(&r.student);
    r.file = clean(&r.file);
    r.verdict = clean(&r.verdict);
    for c in &mut r.criteria {
        bound_criterion(c);
    }
}

fn bound_criterion(c: &mut Criterion) {
    c.name = clean(&c.name);
    clean_opt(&mut c.what);
    clean_opt(&mut c.error);
    clean_value(&mut c.expected);
    clean_value(&mut c.got);
}

/// One line of the text table: newline, carriage return and tab written as `\n`, `\r`,
/// `\t`, and `|` (the table's own separator) as `\|`; other controls as [`visible`] does.
pub fn cell(s: &str) -> String {
    let mut out = String::with_capacity(s.len());
    for c in s.chars() {
        match c {
            '\n' => out.push_str("\\n"),
            '\r' => out.push_str("\\r"),
            '\t' => out.push_str("\\t"),
            '|' => out.push_str("\\|"),
            c if hidden(c) => out.push_str(&format!("\\u{{{:x}}}", c as u32)),
            c => out.push(c),
        }
    }
    out
}

/// One submission's JSON object (the JSON contract: `ok`, `cmd`, then the report).
pub fn json(r: &Report) -> serde_json::Value {
    let mut v = serde_json::json!({"ok": true, "cmd": "lab", "sub": "grade"});
    if let (Some(m), serde_json::Value::Object(rep)) = (v.as_object_mut(), serde_json::to_value(r).unwrap_or_default())
    {
        m.extend(rep);
    }
    v
}

/// The summary after the submissions: its first line, and the table.
pub fn summary(lab: &Lab, reports: &[Report]) -> (String, Outcome) {
    let passed = reports.iter().filter(|r| r.verdict == "passed").count();
    let broken = reports.iter().filter(|r| r.code.as_deref() == Some("lab-grader-error")).count();
    let rows: Vec<Vec<String>> = reports
        .iter()
        .map(|r| {
            vec![
                cell(&r.student),
                format!("{}/{}", r.points, r.max_points),
                r.passed().len().to_string(),
                cell(&r.failed().iter().map(|n| n.to_string()).collect::<Vec<_>>().join(", ")),
                cell(&shown_verdict(&r.verdict)),
                format!("{} s", r.sim_time_s),
            ]
        })
        .collect();
    // Two submissions with one student name (`ivanov.lua` and `ivanov/main.lua`) are flagged:
    // their rows would otherwise read as one student graded twice.
    let mut names: std::collections::BTreeMap<&str, Vec<&str>> = std::collections::BTreeMap::new();
    for r in reports {
        names.entry(r.student.as_str()).or_default().push(r.file.as_str());
    }
    let twice: Vec<(&str, Vec<&str>)> = names.into_iter().filter(|(_, f)| f.len() > 1).collect();
    let mut head = crate::msg!("lab-grade-head", lab = cell(&lab.title), count = reports.len(), passed = passed).text;
    for (name, files) in &twice {
        let listed = files.iter().map(|f| cell(f)).collect::<Vec<_>>().join(", ");
        head.push('\n');
        head.push_str(&crate::msg!("lab-duplicate-student", count = files.len(), student = cell(name), files = listed));
    }
    let duplicates: Vec<serde_json::Value> =
        twice.iter().map(|(n, f)| serde_json::json!({"student": n, "files": f})).collect();
    let o = Outcome::new("lab").with("sub", "grade").table(&headings(crate::msg!("lab-grade-columns")), rows).with(
        "summary",
        serde_json::json!({
            "lab": lab.title,
            "submissions": reports.len(),
            "passed": passed,
            "grader_errors": broken,
            "points": reports.iter().map(|r| r.points).sum::<f64>(),
            "duplicate_students": duplicates,
        }),
    );
    (head, o)
}

/// A verdict as a person reads it: `passed` and `failed` in the language of messages, any
/// other (an error, a limit) as the grader wrote it.
fn shown_verdict(v: &str) -> String {
    match v {
        "passed" | "failed" => crate::msg!("lab-verdict", verdict = v).text,
        _ => v.to_string(),
    }
}

pub use crate::output::headings;

/// The lines under the table: why each criterion failed (expected, got, and when), one line
/// each.
pub fn why_lines(reports: &[Report]) -> Vec<String> {
    let mut out = Vec::new();
    for r in reports {
        for c in r.criteria.iter().filter(|c| !c.passed && !c.skipped) {
            out.push(format!("{}: {}: {}", cell(&r.student), cell(&c.name), cell(&c.why())));
        }
    }
    out
}

/// The table rows of `lab check`: each criterion, its points and why it failed.
pub fn check_rows(r: &Report) -> Vec<Vec<String>> {
    r.criteria
        .iter()
        .map(|c| {
            let result = if c.passed { crate::msg!("lab-criterion-ok").text } else { cell(&c.why()) };
            vec![cell(&c.name), format!("{}/{}", c.points, c.max), result]
        })
        .collect()
}

/// Text for an XML attribute: the five markup characters as entities, newline, carriage
/// return and tab as character references (a parser keeps them), and any character XML 1.0
/// cannot hold written visibly.
fn xml(s: &str) -> String {
    let s = visible(s);
    let mut out = String::with_capacity(s.len());
    for c in s.chars() {
        match c {
            '&' => out.push_str("&amp;"),
            '<' => out.push_str("&lt;"),
            '>' => out.push_str("&gt;"),
            '"' => out.push_str("&quot;"),
            '\'' => out.push_str("&apos;"),
            '\n' => out.push_str("&#10;"),
            '\r' => out.push_str("&#13;"),
            '\t' => out.push_str("&#9;"),
            c => out.push(c),
        }
    }
    out
}

/// JUnit XML: one test suite per student, one test case per criterion (a failure says why),
/// plus one case for the verdict when the run did not end normally.
pub fn junit(lab: &Lab, reports: &[Report]) -> String {
    let mut out = String::from("<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n");
    let failures: usize = reports.iter().map(|r| r.failed().len()).sum();
    let tests: usize = reports.iter().map(|r| r.criteria.len()).sum();
    out.push_str(&format!("<testsuites name=\"{}\" tests=\"{tests}\" failures=\"{failures}\">\n", xml(&lab.title)));
    for r in reports {
        out.push_str(&format!(
            "  <testsuite name=\"{}\" tests=\"{}\" failures=\"{}\" time=\"{}\">\n",
            xml(&r.student),
            r.criteria.len(),
            r.failed().len(),
            r.sim_time_s
        ));
        out.push_str(&format!(
            "    <properties><property name=\"verdict\" value=\"{}\"/><property name=\"points\" value=\"{}/{}\"/></properties>\n",
            xml(&r.verdict),
            r.points,
            r.max_points
        ));
        for c in &r.criteria {
            out.push_str(&format!("    <testcase classname=\"{}\" name=\"{}\"", xml(&r.student), xml(&c.name)));
            if c.passed {
                out.push_str("/>\n");
            } else {
                out.push_str(&format!(
                    "><failure message=\"{}\"/></testcase>\n",
                    xml(&format!("{} ({})", c.why(), r.verdict))
                ));
            }
        }
        out.push_str("  </testsuite>\n");
    }
    out.push_str("</testsuites>\n");
    out
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_long_text_is_capped_at_a_character_boundary_saying_how_much_is_left() {
        let s = "é".repeat(CAP); // 2 bytes each
        let c = cap(&s);
        assert!(c.len() < CAP + 40, "{}", c.len());
        assert!(c.ends_with(&format!("(… {} bytes more)", 2 * CAP - CAP)), "{}", &c[c.len() - 30..]);
        assert_eq!(cap("short"), "short");
        // Made visible and capped in one pass: the cap holds however many controls there are.
        let c = clean(&"\u{1b}".repeat(10 * CAP));
        assert!(c.len() < CAP + 40 && c.starts_with("\\u{1b}"), "{}", c.len());
        assert!(c.ends_with(&format!("(… {} bytes more)", 10 * CAP - CAP / 6 - 1)), "{}", &c[c.len() - 30..]);
    }

    #[test]
    fn control_characters_become_visible_and_cells_stay_on_one_line() {
        assert_eq!(visible("a\u{1b}[2Jb\u{7}"), "a\\u{1b}[2Jb\\u{7}");
        assert_eq!(visible("line\nnext\t"), "line\nnext\t");
        assert_eq!(visible("c1\u{85}"), "c1\\u{85}");
        assert_eq!(cell("a|b\nc\r\u{1b}"), "a\\|b\\nc\\r\\u{1b}");
        assert!(!cell("x\n| fake | row |\n").contains('\n'));
    }

    #[test]
    fn a_20_mib_verdict_gives_a_small_table_fast() {
        // A folder of this test's own, made afresh.
        let dir = std::env::temp_dir().join(format!("plcsh-report-test-{}", std::process::id()));
        let _ = std::fs::remove_dir_all(&dir);
        std::fs::create_dir_all(&dir).unwrap();
        std::fs::write(dir.join("r.lua"), "").unwrap();
        std::fs::write(dir.join("g.lua"), "").unwrap();
        let dir = crate::core::fspath::canonical(&dir).unwrap();
        let text = "title = \"t\"\nreference = \"r.lua\"\ngrader = \"g.lua\"\n[devices]\nplc = \"sim:K205-16DT\"\n[points]\na = 1\n";
        let lab = Lab::parse(text, &dir).unwrap();
        std::fs::remove_dir_all(&dir).unwrap();
        let started = std::time::Instant::now();
        let huge = format!("x.lua:1: {}\n| fake | row |", "A\u{1b}".repeat(10 << 20));
        let mut r = Report::broken(&lab, "x.lua", crate::msg!("lab-runtime-error", error = huge));
        bound(&mut r);
        let (_, o) = summary(&lab, &[r.clone()]);
        let mut text = Vec::new();
        crate::output::write_outcome(&mut text, crate::output::Style { json: false, color: false }, &o).unwrap();
        let xml = junit(&lab, &[r.clone()]);
        let took = started.elapsed();
        assert!(text.len() < 3 * CAP + 1000 && xml.len() < 3 * CAP + 1000, "{} {}", text.len(), xml.len());
        assert!(String::from_utf8(text).unwrap().contains("bytes more)"));
        assert!(took < std::time::Duration::from_secs(1), "{took:?}");
    }

    #[test]
    fn xml_attributes_hold_no_raw_control_or_markup_character() {
        let x = xml("<a href=\"x\">&'\n\u{0}\u{1b}");
        assert_eq!(x, "&lt;a href=&quot;x&quot;&gt;&amp;&apos;&#10;\\u{0}\\u{1b}");
    }
}
