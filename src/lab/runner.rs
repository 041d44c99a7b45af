//! `plcsh lab grade`: every submission in a worker process of its own (`plcsh lab worker LAB
//! FILE`, one per core by default, `--jobs N`), so one submission's crash, memory or endless
//! loop cannot touch another's grade, and the wall-clock limit is a safety net the parent
//! holds (it ends a worker that passes it; every other limit is counted inside the worker in
//! simulated time and Lua instructions). Results are shown in the order the submissions were
//! given.
//!
//! A worker's report comes back in a file the parent names (`--report FILE`, in a folder of
//! the parent's own, 0700, removed afterwards), never through the worker's stdout: a
//! submission reads and writes only its own files and the write directory, so it cannot
//! reach that file, and what it prints (`print`, `io.write`, `io.stderr:write`) is only its
//! output — kept, bounded, for the teacher (`--show-output`, `stdout`/`stderr` in `--json`).

use super::config::Lab;
use super::grader::{grader_error, Report};
use crate::core::{Error, Result};
use crate::msg;
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
            let entries = std::fs::read_dir(a)
                .map_err(|e| Error::io(msg!("lab-cannot-list", dir = a.display().to_string())).cause(e))?;
            for e in entries.flatten() {
                let p = e.path();
                // A link is listed as what it names (a file, a folder's main.lua) and graded
                // as a link: refused, with a verdict saying so (`grader::refused`).
                let link = crate::core::platform::is_link(&p);
                if p.is_dir() {
                    let mains = ["main.lua", "main.il"].iter().map(|m| p.join(m));
                    found.extend(mains.filter(|m| std::fs::symlink_metadata(m).is_ok()));
                } else if matches!(p.extension().and_then(|x| x.to_str()), Some("lua" | "il")) || link {
                    found.push(p);
                }
            }
            found.sort();
            out.extend(found.into_iter().map(|p| p.display().to_string()));
        } else if a.is_file() || crate::core::platform::is_link(a) {
            out.push(a.display().to_string());
        } else {
            return Err(Error::usage(msg!("lab-no-such-submission", file = a.display().to_string()))
                .hint(msg!("lab-hint-submissions")));
        }
    }
    if out.is_empty() {
        return Err(Error::usage(msg!("lab-no-submissions")));
    }
    Ok(out)
}

/// How much of a worker's stdout and of its stderr is kept.
pub const OUTPUT_CAP: usize = 64 << 10;

/// Reads `r` to its end, keeping the first [`OUTPUT_CAP`] bytes: the text (cut at a character)
/// and `(… N bytes more)` for the rest.
fn capture(mut r: impl Read) -> String {
    let mut kept = Vec::new();
    let mut more: u64 = 0;
    let mut buf = [0u8; 8192];
    loop {
        match r.read(&mut buf) {
            Ok(0) | Err(_) => break,
            Ok(n) => {
                let room = OUTPUT_CAP.saturating_sub(kept.len()).min(n);
                kept.extend_from_slice(&buf[..room]);
                more += (n - room) as u64;
            }
        }
    }
    let mut text = String::from_utf8_lossy(&kept).into_owned();
    if more > 0 {
        text.push_str(&format!("({})", msg!("lab-bytes-more", n = more)));
    }
    text
}

/// A folder of the parent's own for one worker's report (0700 where the system has modes),
/// removed when dropped.
struct ReportDir(PathBuf);

/// A private folder of this process's own (0700), removed when dropped: where `lab check`
/// writes the empty program it grades.
pub struct PrivateDir(ReportDir);

impl PrivateDir {
    pub fn new() -> std::io::Result<PrivateDir> {
        ReportDir::new().map(PrivateDir)
    }

    pub fn path(&self) -> &Path {
        &self.0 .0
    }
}

impl ReportDir {
    fn new() -> std::io::Result<ReportDir> {
        use std::sync::atomic::{AtomicU64, Ordering};
        static N: AtomicU64 = AtomicU64::new(0);
        // A new folder every time: one left by an earlier process with the same id (a crash,
        // a reused process id) is passed over, never reused, since another user may own it.
        loop {
            let d = std::env::temp_dir().join(format!(
                "plcsh-report-{}-{}",
                std::process::id(),
                N.fetch_add(1, Ordering::Relaxed)
            ));
            match crate::core::platform::create_private_dir(&d) {
                Ok(()) => return Ok(ReportDir(d)),
                Err(e) if e.kind() == std::io::ErrorKind::AlreadyExists => continue,
                Err(e) => return Err(e),
            }
        }
    }
}

impl Drop for ReportDir {
    fn drop(&mut self) {
        let _ = std::fs::remove_dir_all(&self.0);
    }
}

/// `text` with the write directory's path (as made, and as the system resolves it) shown as
/// `write`: the folder's name changes from run to run and is the grader's, never the output's.
fn hide_write_dir(text: String, dir: &Path) -> String {
    let mut names = vec![dir.display().to_string()];
    if let Ok(real) = crate::core::fspath::canonical(dir) {
        names.push(real.display().to_string());
    }
    names.sort_by_key(|n| std::cmp::Reverse(n.len()));
    let mut text = text;
    for n in names.iter().filter(|n| !n.is_empty()) {
        text = text.replace(n.as_str(), "write");
    }
    text
}

/// Runs one worker for `file` and reads its report; ends it at the wall-clock limit.
fn one(exe: &Path, lab_path: &Path, lab: &Lab, file: &str) -> Report {
    let dir = match ReportDir::new() {
        Ok(d) => d,
        Err(e) => {
            return Report::broken(lab, file, grader_error(msg!("lab-cannot-create-report-dir", error = e.to_string())))
        }
    };
    let report = dir.0.join("report.json");
    // The submission's write directory: made here, private, inside this run's own folder and
    // removed with it however the worker ends (killed at the wall-clock limit included).
    let write = dir.0.join("write");
    if let Err(e) = crate::core::platform::create_private_dir(&write) {
        return Report::broken(
            lab,
            file,
            grader_error(msg!("lab-cannot-create-write-dir-error", error = e.to_string())),
        );
    }
    let child = Command::new(exe)
        .args(["lab", "worker"])
        .arg(lab_path)
        .arg(file)
        .arg("--report")
        .arg(&report)
        .arg("--write-dir")
        .arg(&write)
        // The worker writes in this run's language (the lab's `language`, else `--lang` or the
        // user's): it is not given `--lang` or the lab's choice otherwise.
        .env("PLCSH_LANG", crate::core::msg::language().tag())
        .stdin(Stdio::null())
        .stdout(Stdio::piped())
        .stderr(Stdio::piped())
        .spawn();
    let mut child = match child {
        Ok(c) => c,
        Err(e) => {
            return Report::broken(lab, file, grader_error(msg!("lab-cannot-start-worker", error = e.to_string())))
        }
    };
    let stdout = child.stdout.take().expect("piped");
    let stderr = child.stderr.take().expect("piped");
    let out_reader = std::thread::spawn(move || capture(stdout));
    let err_reader = std::thread::spawn(move || capture(stderr));
    let deadline = Instant::now() + lab.limits.wall;
    // The disk's safety net: a worker whose write directory grows far past the lab's cap is
    // ended (the worker itself gives the verdict for any size past the cap at its end).
    let mut next_look = Instant::now();
    let mut flooded = false;
    let status = loop {
        match child.try_wait() {
            Ok(Some(st)) => break Some(st),
            Ok(None) if Instant::now() >= deadline => {
                let _ = child.kill();
                let _ = child.wait();
                break None;
            }
            // A stop (Ctrl-C, SIGTERM, SIGHUP) ends the worker at once: no orphan grades on.
            Ok(None) if crate::signals::exit_status().is_some() => {
                let _ = child.kill();
                let _ = child.wait();
                return Report::broken(lab, file, msg!("lab-not-graded", cause = crate::signals::cause().to_string()));
            }
            Ok(None) => {
                if Instant::now() >= next_look {
                    next_look = Instant::now() + Duration::from_millis(200);
                    let far = lab.limits.write.saturating_mul(4);
                    if super::grader::written(&write, far) > far {
                        flooded = true;
                        let _ = child.kill();
                        let _ = child.wait();
                        break None;
                    }
                }
                std::thread::sleep(Duration::from_millis(5))
            }
            Err(_) => break None,
        }
    };
    let out = out_reader.join().unwrap_or_default();
    let err = err_reader.join().unwrap_or_default();
    let (out, err) = (hide_write_dir(out, &write), hide_write_dir(err, &write));
    let mut r = match status {
        None if flooded => Report::broken(lab, file, super::grader::write_verdict(lab.limits.write)),
        None => {
            Report::broken(lab, file, msg!("lab-exceeded-wall", seconds = lab.limits.wall.as_secs_f64().to_string()))
        }
        Some(status) => match std::fs::read(&report).ok().and_then(|b| serde_json::from_slice::<Report>(&b).ok()) {
            Some(r) => r,
            None => Report::broken(lab, file, grader_error(msg!("lab-worker-no-report", status = status.to_string()))),
        },
    };
    r.stdout = Some(out).filter(|s| !s.is_empty());
    r.stderr = Some(err).filter(|s| !s.is_empty());
    r
}

/// Grades one file in a worker (`lab check` grades the reference this way too, so what it
/// prints stays out of the check's own output).
pub fn grade_one(lab_path: &Path, lab: &Lab, file: &str) -> Result<Report> {
    let exe = std::env::current_exe().map_err(|e| Error::io(msg!("lab-no-executable")).cause(e))?;
    Ok(one(&exe, lab_path, lab, file))
}

/// The worker (`plcsh lab worker LAB FILE --report REPORT`): grades one file, with what the
/// Lua code prints on this process's stdout, and writes the report as JSON to `REPORT`.
pub fn worker(path: &Path, file: &str, report: &Path, write: Option<&Path>) -> i32 {
    let r = match Lab::load(path) {
        Ok(lab) => super::grader::grade_in(&lab, file, Box::new(std::io::stdout()), write),
        Err(e) => {
            eprintln!("{}", msg!("lab-worker-error", error = e.to_string()));
            return 1;
        }
    };
    let text = match serde_json::to_vec(&r) {
        Ok(t) => t,
        Err(_) => return 1,
    };
    match std::fs::write(report, text) {
        Ok(()) => 0,
        Err(e) => {
            eprintln!(
                "{}",
                msg!("lab-worker-cannot-write", file = report.display().to_string(), error = e.to_string())
            );
            1
        }
    }
}

/// Grades `files` with `jobs` workers at a time; reports in the order of `files`.
pub fn grade_all(lab_path: &Path, lab: &Lab, files: &[String], jobs: usize) -> Result<Vec<Report>> {
    let exe = std::env::current_exe().map_err(|e| Error::io(msg!("lab-no-executable")).cause(e))?;
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
                if crate::signals::exit_status().is_some() {
                    break; // stopped: no new worker starts
                }
                let r = one(&exe, lab_path, lab, file);
                results.lock().unwrap_or_else(|p| p.into_inner())[i] = Some(r);
            });
        }
    });
    let results = Arc::try_unwrap(results).map_err(|_| Error::state(msg!("lab-workers-running")))?;
    Ok(results.into_inner().unwrap_or_else(|p| p.into_inner()).into_iter().flatten().collect())
}

/// The default number of workers: one per core.
pub fn default_jobs() -> usize {
    std::thread::available_parallelism().map(|n| n.get()).unwrap_or(1)
}
