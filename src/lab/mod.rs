//! Teaching labs (`plcsh lab new | check | grade`): a lab is a folder with a `lab.toml`
//! ([`config`]) naming its machine, start snapshot, starter files, reference solution, grader
//! and limits. Every submission is graded from the same fresh state in a sandbox
//! ([`crate::confine`], `script::sandbox`) under deterministic limits
//! ([`crate::core::budget`]), in a worker process of its own ([`runner`]); the grader's `lab`
//! API is [`grader`].

pub mod config;
pub mod example;
pub mod grader;
pub mod hook;
pub mod report;
pub mod runner;

use crate::core::{Error, Result};
use crate::output::Outcome;
use config::Lab;
use grader::Report;
use std::path::Path;

/// `lab new NAME`: writes the example lab into a new folder.
pub fn new_lab(dir: &Path) -> Result<Outcome> {
    if dir.exists() {
        return Err(Error::usage(crate::msg!("lab-new-exists", dir = dir.display().to_string()))
            .hint(crate::msg!("lab-hint-new-name")));
    }
    std::fs::create_dir_all(dir)
        .map_err(|e| Error::io(crate::msg!("lab-cannot-create", dir = dir.display().to_string())).cause(e))?;
    for (name, text) in example::FILES {
        let p = dir.join(name);
        std::fs::write(&p, text)
            .map_err(|e| Error::io(crate::msg!("lab-cannot-write", file = p.display().to_string())).cause(e))?;
    }
    let names: Vec<&str> = example::FILES.iter().map(|(n, _)| *n).collect();
    // The command to type next, with the folder quoted as the shell reads it (`'my lab'`).
    let shown = dir.display().to_string();
    let word = crate::shell::lex::quote(&shown);
    Ok(Outcome::new("lab")
        .with("sub", "new")
        .text(crate::msg!("lab-new-wrote", dir = word.to_string(), files = names.join(", ")).text)
        .with("dir", dir.display().to_string())
        .with("files", names))
}

/// Every `[points]` key names a criterion the grader defines (the reference's run shows
/// which): a misspelt key would otherwise cost every student its points. Only a run that
/// reached the grader's end tells; one that stopped early is reported by its verdict.
fn points_name_criteria(lab: &Lab, r: &Report) -> Result<()> {
    if r.verdict != "passed" && r.verdict != "failed" {
        return Ok(());
    }
    let defined: Vec<&str> = r.criteria.iter().filter(|c| !c.skipped).map(|c| c.name.as_str()).collect();
    for key in lab.points.keys() {
        if defined.contains(&key.as_str()) {
            continue;
        }
        let near = defined.iter().map(|n| (crate::core::text::edit_distance(key, n), *n)).min();
        let hint = match near {
            Some((d, n)) if d <= key.chars().count().max(3) / 3 + 1 => {
                crate::msg!("lab-hint-did-you-mean-criterion", near = n, criteria = quoted(&defined))
            }
            _ if defined.is_empty() => crate::msg!("lab-hint-no-criteria"),
            _ => crate::msg!("lab-hint-criteria", criteria = quoted(&defined)),
        };
        return Err(
            Error::usage(crate::msg!("lab-points-no-criterion", file = config::FILE, key = key.as_str())).hint(hint)
        );
    }
    Ok(())
}

fn quoted(names: &[&str]) -> String {
    names.iter().map(|n| format!("\"{n}\"")).collect::<Vec<_>>().join(", ")
}

/// Points as a message argument: a whole number as a number (plural forms read it), any
/// other as its digits.
fn number(x: f64) -> crate::core::msg::Arg {
    if x.fract() == 0.0 && x.abs() < 1e15 {
        crate::core::msg::Arg::Int(x as i64)
    } else {
        crate::core::msg::Arg::Text(x.to_string())
    }
}

/// `lab check LAB`: the lab is valid and its reference solution gets every point.
pub fn check(path: &Path) -> Result<(Outcome, String, bool)> {
    let lab = Lab::load(path)?;
    let reference = lab.reference.display().to_string();
    let mut r = runner::grade_one(path, &lab, &reference)?;
    report::bound(&mut r);
    points_name_criteria(&lab, &r)?;
    let ok = r.verdict == "passed" && r.points == r.max_points && r.max_points > 0.0;
    let rows = report::check_rows(&r);
    let warnings = if ok { free_points(path, &lab)? } else { Vec::new() };
    let (points, max) = (number(r.points), number(r.max_points));
    let head = if ok {
        crate::msg!(
            "lab-check-passed",
            lab = lab.title.as_str(),
            points = points,
            max = max,
            time = r.sim_time_s.to_string()
        )
    } else {
        crate::msg!(
            "lab-check-failed",
            lab = lab.title.as_str(),
            points = points,
            max = max,
            verdict = r.verdict.as_str()
        )
    }
    .text;
    let o = Outcome::new("lab")
        .with("sub", "check")
        .table(&report::headings(crate::msg!("lab-check-columns")), rows)
        .with("lab", lab.title.as_str())
        .with("passed", ok)
        .with("warnings", warnings)
        .with("reference", r);
    Ok((o, head, ok))
}

/// Points a program earns without doing the task: each starter file the lab accepts, and an
/// empty program of the lab's first kind, graded as a student's would be. A criterion such a
/// program passes checks nothing the task asks for; each one that earns points is named.
fn free_points(path: &Path, lab: &Lab) -> Result<Vec<String>> {
    let dir = runner::PrivateDir::new().map_err(|e| Error::io(crate::msg!("lab-cannot-create-empty-dir")).cause(e))?;
    // (the starter's name, or none for the empty program; the file graded)
    let mut tries: Vec<(Option<String>, String)> = Vec::new();
    for s in &lab.starter {
        if lab.kind_of(s).is_some_and(|k| lab.accepts.contains(&k)) {
            let name = s.strip_prefix(&lab.dir).unwrap_or(s).display().to_string();
            tries.push((Some(name), s.display().to_string()));
        }
    }
    let ext = if lab.accepts.iter().any(|k| k == "lua") { "lua" } else { "il" };
    let empty = dir.path().join(format!("empty.{ext}"));
    std::fs::write(&empty, "").map_err(|e| Error::io(crate::msg!("lab-cannot-write-empty")).cause(e))?;
    tries.push((None, empty.display().to_string()));
    let mut out = Vec::new();
    for (starter, file) in tries {
        let mut r = runner::grade_one(path, lab, &file)?;
        report::bound(&mut r);
        if r.points > 0.0 {
            let (points, max, criteria) = (number(r.points), number(r.max_points), quoted(&r.passed()));
            out.push(
                match starter {
                    Some(file) => crate::msg!(
                        "lab-free-points-starter",
                        file = file,
                        points = points,
                        max = max,
                        criteria = criteria
                    ),
                    None => crate::msg!("lab-free-points-empty", points = points, max = max, criteria = criteria),
                }
                .text,
            );
        }
    }
    Ok(out)
}

pub use report::{json as report_json, summary};

/// Grades `subs` (files or folders) with `jobs` workers.
pub fn grade(path: &Path, subs: &[std::path::PathBuf], jobs: usize) -> Result<(Lab, Vec<Report>)> {
    let lab = Lab::load(path)?;
    let files = runner::submissions(subs)?;
    let mut reports = runner::grade_all(path, &lab, &files, jobs)?;
    reports.iter_mut().for_each(report::bound);
    Ok((lab, reports))
}
