//! `plcsh lab grade`: every submission in a worker process of its own (`plcsh lab worker LAB
//! FILE`, one per core by default, `--jobs N`), so one submission's crash, memory or endless
//! loop cannot touch another's grade, and the wall-clock limit is a safety net the parent
//! holds (it ends a worker that passes it; every other limit is counted inside the worker in
//! simulated time and Lua instructions). Results come back as one JSON line each and are
//! shown in the order the submissions were given.

use super::config::Lab;
use super::grader::Report;
use crate::core::{Error, Result};
use std::io::Read;
use std::path::{Path, PathBuf};
use std::process::{Command, Stdio};
use std::sync::{Arc, Mutex};
use std::time::{Duration, Instant};

/// The submissions named: files as they are; a folder's `.lua` and `.il` files (and its
/// sub-folders' `main.lua` / `main.il`), sorted by name.
pub fn submissions(args: &[PathBuf]) -> Result<Vec<String>> {
    let mut out = Vec::new();
    for a in args {
        if a.is_dir() {
            let mut found: Vec<PathBuf> = Vec::new();
            let entries =
                std::fs::read_dir(a).map_err(|e| Error::io(format!("cannot list {}", a.display())).cause(e))?;
            for e in entries.flatten() {
                let p = e.path();
                if p.is_dir() {
                    found.extend(["main.lua", "main.il"].iter().map(|m| p.join(m)).filter(|m| m.is_file()));
                } else if matches!(p.extension().and_then(|x| x.to_str()), Some("lua" | "il")) {
                    found.push(p);
                }
            }
            found.sort();
            out.extend(found.into_iter().map(|p| p.display().to_string()));
        } else if a.is_file() {
            out.push(a.display().to_string());
        } else {
            return Err(Error::usage(format!("{}: no such file or folder", a.display()))
                .hint("give submission files (.lua, .il) or folders of them"));
        }
    }
    if out.is_empty() {
        return Err(Error::usage("no submissions found (.lua or .il files)"));
    }
    Ok(out)
}

/// Runs one worker for `file` and reads its report; ends it at the wall-clock limit.
fn one(exe: &Path, lab_path: &Path, lab: &Lab, file: &str) -> Report {
    let child = Command::new(exe)
        .args(["lab", "worker"])
        .arg(lab_path)
        .arg(file)
        .stdin(Stdio::null())
        .stdout(Stdio::piped())
        .stderr(Stdio::null())
        .spawn();
    let mut child = match child {
        Ok(c) => c,
        Err(e) => return Report::broken(lab, file, format!("grader error: cannot start a worker: {e}")),
    };
    let mut stdout = child.stdout.take().expect("piped");
    let reader = std::thread::spawn(move || {
        let mut s = String::new();
        let _ = stdout.read_to_string(&mut s);
        s
    });
    let deadline = Instant::now() + lab.limits.wall;
    let status = loop {
        match child.try_wait() {
            Ok(Some(st)) => break Some(st),
            Ok(None) if Instant::now() >= deadline => {
                let _ = child.kill();
                let _ = child.wait();
                break None;
            }
            Ok(None) => std::thread::sleep(Duration::from_millis(5)),
            Err(_) => break None,
        }
    };
    let text = reader.join().unwrap_or_default();
    let Some(status) = status else {
        return Report::broken(
            lab,
            file,
            format!("exceeded the wall-clock safety net of {} s", lab.limits.wall.as_secs_f64()),
        );
    };
    match text.lines().last().and_then(|l| serde_json::from_str::<Report>(l).ok()) {
        Some(r) => r,
        None => Report::broken(lab, file, format!("grader error: the worker ended ({status}) without a report")),
    }
}

/// Grades `files` with `jobs` workers at a time; reports in the order of `files`.
pub fn grade_all(lab_path: &Path, lab: &Lab, files: &[String], jobs: usize) -> Result<Vec<Report>> {
    let exe = std::env::current_exe().map_err(|e| Error::io("cannot find the plcsh executable").cause(e))?;
    let next = Arc::new(Mutex::new(0usize));
    let results: Arc<Mutex<Vec<Option<Report>>>> = Arc::new(Mutex::new(vec![None; files.len()]));
    std::thread::scope(|scope| {
        for _ in 0..jobs.max(1).min(files.len()) {
            let (next, results, exe) = (next.clone(), results.clone(), exe.clone());
            scope.spawn(move || loop {
                let i = {
                    let mut n = next.lock().unwrap_or_else(|p| p.into_inner());
                    let i = *n;
                    *n += 1;
                    i
                };
                let Some(file) = files.get(i) else { break };
                let r = one(&exe, lab_path, lab, file);
                results.lock().unwrap_or_else(|p| p.into_inner())[i] = Some(r);
            });
        }
    });
    let results = Arc::try_unwrap(results).map_err(|_| Error::state("workers still running"))?;
    Ok(results.into_inner().unwrap_or_else(|p| p.into_inner()).into_iter().flatten().collect())
}

/// The default number of workers: one per core.
pub fn default_jobs() -> usize {
    std::thread::available_parallelism().map(|n| n.get()).unwrap_or(1)
}
