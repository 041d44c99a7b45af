//! Teaching labs (`plcsh lab new | check | grade`): a lab is a folder with a `lab.toml`
//! ([`config`]) naming its machine, start snapshot, starter files, reference solution, grader
//! and limits. Every submission is graded from the same fresh state in a sandbox
//! ([`crate::confine`], `script::sandbox`) under deterministic limits
//! ([`crate::core::budget`]), in a worker process of its own ([`runner`]); the grader's `lab`
//! API is [`grader`].

pub mod config;
pub mod example;
pub mod grader;
pub mod runner;

use crate::core::{Error, Result};
use crate::output::Outcome;
use config::Lab;
use grader::Report;
use std::path::Path;

/// `lab new NAME`: writes the example lab into a new folder.
pub fn new_lab(dir: &Path) -> Result<Outcome> {
    if dir.exists() {
        return Err(Error::usage(format!("{} already exists", dir.display()))
            .hint("give a new folder name: plcsh lab new NAME"));
    }
    std::fs::create_dir_all(dir).map_err(|e| Error::io(format!("cannot create {}", dir.display())).cause(e))?;
    for (name, text) in example::FILES {
        let p = dir.join(name);
        std::fs::write(&p, text).map_err(|e| Error::io(format!("cannot write {}", p.display())).cause(e))?;
    }
    let names: Vec<&str> = example::FILES.iter().map(|(n, _)| *n).collect();
    Ok(Outcome::new("lab")
        .with("sub", "new")
        .text(format!(
            "wrote {} ({}); check it with: plcsh lab check {}",
            dir.display(),
            names.join(", "),
            dir.display()
        ))
        .with("dir", dir.display().to_string())
        .with("files", names))
}

/// `lab check LAB`: the lab is valid and its reference solution gets every point.
pub fn check(path: &Path) -> Result<(Outcome, String, bool)> {
    let lab = Lab::load(path)?;
    let reference = lab.reference.display().to_string();
    let r = grader::grade(&lab, &reference);
    let ok = r.verdict == "passed" && r.points == r.max_points && r.max_points > 0.0;
    let rows: Vec<Vec<String>> = r
        .criteria
        .iter()
        .map(|c| vec![c.name.clone(), format!("{}/{}", c.points, c.max), if c.passed { "ok".into() } else { c.why() }])
        .collect();
    let head = if ok {
        format!(
            "{}: the reference solution gets {}/{} points in {} simulated s",
            lab.title, r.points, r.max_points, r.sim_time_s
        )
    } else {
        format!(
            "{}: the reference solution gets {}/{} points ({}): the grader or the reference needs fixing",
            lab.title, r.points, r.max_points, r.verdict
        )
    };
    let o = Outcome::new("lab")
        .with("sub", "check")
        .table(&["criterion", "points", "result"], rows)
        .with("lab", lab.title.as_str())
        .with("passed", ok)
        .with("reference", r);
    Ok((o, head, ok))
}

/// One submission's JSON object (the JSON contract: `ok`, `cmd`, then the report).
pub fn report_json(r: &Report) -> serde_json::Value {
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
    let broken = reports.iter().filter(|r| r.verdict.starts_with("grader error")).count();
    let rows: Vec<Vec<String>> = reports
        .iter()
        .map(|r| {
            vec![
                r.student.clone(),
                format!("{}/{}", r.points, r.max_points),
                r.passed().len().to_string(),
                r.failed().iter().map(|n| n.to_string()).collect::<Vec<_>>().join(", "),
                r.verdict.clone(),
                format!("{} s", r.sim_time_s),
            ]
        })
        .collect();
    let head = format!("{}: {} submission(s), {passed} passed every criterion", lab.title, reports.len());
    let o = Outcome::new("lab")
        .with("sub", "grade")
        .table(&["student", "points", "passed", "failed", "verdict", "simulated time"], rows)
        .with(
            "summary",
            serde_json::json!({
                "lab": lab.title,
                "submissions": reports.len(),
                "passed": passed,
                "grader_errors": broken,
                "points": reports.iter().map(|r| r.points).sum::<f64>(),
            }),
        );
    (head, o)
}

/// Grades `subs` (files or folders) with `jobs` workers.
pub fn grade(path: &Path, subs: &[std::path::PathBuf], jobs: usize) -> Result<(Lab, Vec<Report>)> {
    let lab = Lab::load(path)?;
    let files = runner::submissions(subs)?;
    let reports = runner::grade_all(path, &lab, &files, jobs)?;
    Ok((lab, reports))
}

/// The worker: grades one file, prints its report as one JSON line.
pub fn worker(path: &Path, file: &str) -> i32 {
    let report = match Lab::load(path) {
        Ok(lab) => grader::grade(&lab, file),
        Err(e) => {
            eprintln!("plcsh lab worker: {e}");
            return 1;
        }
    };
    match serde_json::to_string(&report) {
        Ok(s) => {
            println!("{s}");
            0
        }
        Err(_) => 1,
    }
}
