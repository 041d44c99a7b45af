//! Grades one submission in this process: a fresh session from the lab's devices (never the
//! user's state file or profiles), the start snapshot, the sandbox's rules and the run's
//! limits, then the grader script with its `lab` table (`lab.lua`). The result is a
//! [`Report`] with no wall-clock figure in it, so two runs give the same bytes.

use super::config::Lab;
use crate::confine::Confinement;
use crate::core::budget::Budget;
use crate::core::{Clock, Error, ErrorKind};
use crate::output::Style;
use crate::script::{sandbox, Engine};
use crate::session::Session;
use crate::shell::Shell;
use mlua::{Lua, MultiValue, Table, Value};
use serde::{Deserialize, Serialize};
use std::path::{Path, PathBuf};
use std::sync::atomic::Ordering;
use std::sync::Arc;

/// One criterion's result.
#[derive(Clone, Debug, Serialize, Deserialize, PartialEq)]
pub struct Criterion {
    pub name: String,
    pub points: f64,
    pub max: f64,
    pub passed: bool,
    /// Not run (the run ended before the grader reached it).
    #[serde(default, skip_serializing_if = "std::ops::Not::not")]
    pub skipped: bool,
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub what: Option<String>,
    /// What the criterion expected and what it got: a number as a JSON number, anything
    /// else as the grader's text of it (`"on"` with its quotes for a string, `true`, `{…}`).
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub expected: Option<serde_json::Value>,
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub got: Option<serde_json::Value>,
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub error: Option<String>,
    /// Simulated time of the failure, seconds.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub at_s: Option<f64>,
}

impl Criterion {
    /// `expected 1, got 0 at 2.5 s`, in the language of messages (the lab's `language`).
    pub fn why(&self) -> String {
        use crate::msg;
        if self.skipped {
            return msg!("lab-not-reached").text;
        }
        let at = self.at_s.map(trim);
        let text = match (&self.error, &self.expected, &self.got, &self.what, at) {
            (Some(e), _, _, _, Some(at)) => msg!("lab-error-at", error = e, at = at),
            (Some(e), _, _, _, None) => return e.clone(),
            (None, Some(x), Some(g), Some(w), Some(at)) => {
                msg!("lab-expected-what-at", what = w, expected = shown(x), got = shown(g), at = at)
            }
            (None, Some(x), Some(g), Some(w), None) => {
                msg!("lab-expected-what", what = w, expected = shown(x), got = shown(g))
            }
            (None, Some(x), Some(g), None, Some(at)) => {
                msg!("lab-expected-at", expected = shown(x), got = shown(g), at = at)
            }
            (None, Some(x), Some(g), None, None) => msg!("lab-expected", expected = shown(x), got = shown(g)),
            _ => return String::new(),
        };
        text.text
    }
}

/// A recorded value as the grader showed it: a string is its text, a number its digits.
fn shown(v: &serde_json::Value) -> String {
    match v {
        serde_json::Value::String(s) => s.clone(),
        other => other.to_string(),
    }
}

fn trim(x: f64) -> String {
    let s = format!("{x:.3}");
    s.trim_end_matches('0').trim_end_matches('.').to_string()
}

/// One submission's grade.
#[derive(Clone, Debug, Serialize, Deserialize, PartialEq)]
pub struct Report {
    pub student: String,
    pub file: String,
    pub points: f64,
    pub max_points: f64,
    pub criteria: Vec<Criterion>,
    /// `passed`, `failed`, `runtime error: …`, `exceeded …`, `grader error: …` (the last three
    /// in the lab's language).
    pub verdict: String,
    /// The message id of a verdict other than `passed` and `failed` (`lab-runtime-error`,
    /// `lab-grader-error`, `budget-exceeded-minutes`, …): what a script matches, whatever the
    /// language.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub code: Option<String>,
    pub sim_time_s: f64,
    /// What the run wrote to its stdout and stderr (`print`, `io.write`), bounded: kept for
    /// the teacher, never read for a grade.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub stdout: Option<String>,
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub stderr: Option<String>,
}

impl Report {
    pub fn passed(&self) -> Vec<&str> {
        self.criteria.iter().filter(|c| c.passed).map(|c| c.name.as_str()).collect()
    }
    pub fn failed(&self) -> Vec<&str> {
        self.criteria.iter().filter(|c| !c.passed).map(|c| c.name.as_str()).collect()
    }
    /// A report for a submission that could not be run at all.
    pub fn broken(lab: &Lab, file: &str, verdict: crate::core::msg::Msg) -> Report {
        let criteria: Vec<Criterion> = lab.points.iter().map(|(n, p)| skipped(n, *p)).collect();
        Report {
            student: student_name(Path::new(file)),
            file: file.to_string(),
            points: 0.0,
            max_points: criteria.iter().map(|c| c.max).sum(),
            criteria,
            verdict: verdict.text,
            code: Some(verdict.id.to_string()),
            sim_time_s: 0.0,
            stdout: None,
            stderr: None,
        }
    }
}

fn skipped(name: &str, max: f64) -> Criterion {
    Criterion {
        name: name.into(),
        points: 0.0,
        max,
        passed: false,
        skipped: true,
        what: None,
        expected: None,
        got: None,
        error: None,
        at_s: None,
    }
}

/// The student's name: the submission's file name without its extension (or the folder's
/// name for `NAME/main.lua`).
pub fn student_name(file: &Path) -> String {
    let stem = file.file_stem().map(|s| s.to_string_lossy().into_owned()).unwrap_or_default();
    if stem == "main" {
        if let Some(p) = file.parent().and_then(|p| p.file_name()) {
            return p.to_string_lossy().into_owned();
        }
    }
    stem
}

/// A folder for one run's files: made fresh and private (0700 where the system has modes; a
/// path that exists, a link included, is passed over, never used), removed when dropped. A
/// worker of `lab grade` is given one its parent made ([`WriteDir::given`]), which the parent
/// removes however the worker ends.
pub struct WriteDir(PathBuf, bool);

impl WriteDir {
    pub fn new() -> crate::core::Result<WriteDir> {
        use std::sync::atomic::AtomicU64;
        static N: AtomicU64 = AtomicU64::new(0);
        loop {
            let d = std::env::temp_dir().join(format!(
                "plcsh-lab-{}-{}",
                std::process::id(),
                N.fetch_add(1, Ordering::Relaxed)
            ));
            match crate::core::platform::create_private_dir(&d) {
                Ok(()) => return Ok(WriteDir(d, true)),
                Err(e) if e.kind() == std::io::ErrorKind::AlreadyExists => continue,
                Err(e) => return Err(Error::io(crate::msg!("lab-cannot-create-write-dir")).cause(e)),
            }
        }
    }

    /// A folder the caller made and removes (it must be a folder, not a link to one).
    pub fn given(dir: &Path) -> crate::core::Result<WriteDir> {
        if crate::core::platform::is_link(dir) || !dir.is_dir() {
            return Err(Error::io(crate::msg!("lab-write-dir-not-own")));
        }
        Ok(WriteDir(dir.to_path_buf(), false))
    }

    pub fn path(&self) -> &Path {
        &self.0
    }
}

impl Drop for WriteDir {
    fn drop(&mut self) {
        if self.1 {
            let _ = std::fs::remove_dir_all(&self.0);
        }
    }
}

/// What a submission left in its write directory, in bytes (links counted as themselves,
/// never followed); stops counting past `cap`.
pub fn written(dir: &Path, cap: u64) -> u64 {
    let mut total = 0u64;
    let mut todo = vec![dir.to_path_buf()];
    while let Some(d) = todo.pop() {
        let Ok(entries) = std::fs::read_dir(&d) else { continue };
        for e in entries.flatten() {
            let Ok(m) = std::fs::symlink_metadata(e.path()) else { continue };
            if m.is_dir() {
                todo.push(e.path());
            }
            total = total.saturating_add(m.len().max(1));
            if total > cap {
                return total;
            }
        }
    }
    total
}

/// The verdict of a run that left more than `cap` bytes in its write directory.
pub fn write_verdict(cap: u64) -> crate::core::msg::Msg {
    crate::msg!(
        "lab-exceeded-write",
        size = crate::core::budget::describe_bytes(usize::try_from(cap).unwrap_or(usize::MAX))
    )
}

/// `grader error: …`: a verdict that is the grader's (or the machine's) fault, not the
/// submission's.
pub fn grader_error(why: impl std::fmt::Display) -> crate::core::msg::Msg {
    crate::msg!("lab-grader-error", error = why.to_string())
}

/// Why `file` is not a submission of its own bytes, or too big to grade: a symbolic link
/// (the file itself, its folder for `NAME/main.lua`, or any entry in that folder), or more
/// bytes than the lab's `[budget] submission`. Git checkouts and zip or tar archives keep
/// links, and a link to the lab's reference would be graded as the reference.
fn refused(lab: &Lab, file: &Path) -> Option<crate::core::msg::Msg> {
    use crate::core::platform::is_link;
    let name = |p: &Path| crate::core::encoding::printable(&p.display().to_string()).into_owned();
    let link = |p: &Path| Some(crate::msg!("lab-refused-link", file = name(p)));
    if is_link(file) {
        return link(file);
    }
    let cap = lab.limits.submission;
    let too_big = |n: u64| {
        Some(crate::msg!(
            "lab-refused-size",
            n = n,
            cap = crate::core::budget::describe_bytes(usize::try_from(cap).unwrap_or(usize::MAX))
        ))
    };
    if file.file_stem().is_some_and(|s| s == "main") {
        let dir = file.parent().filter(|p| !p.as_os_str().is_empty()).unwrap_or(Path::new("."));
        if is_link(dir) {
            return link(dir);
        }
        // The folder's entries, to a bounded depth and number: a link anywhere is refused.
        let (mut total, mut seen) = (0u64, 0usize);
        let mut todo = vec![(dir.to_path_buf(), 0usize)];
        while let Some((d, depth)) = todo.pop() {
            let Ok(entries) = std::fs::read_dir(&d) else { continue };
            for e in entries.flatten() {
                let p = e.path();
                seen += 1;
                let Ok(m) = std::fs::symlink_metadata(&p) else { continue };
                if m.file_type().is_symlink() {
                    let shown = p.strip_prefix(dir).map(|r| Path::new(dir.file_name().unwrap_or_default()).join(r));
                    return link(shown.as_deref().unwrap_or(&p));
                }
                if m.is_dir() && depth < 16 && seen < 10_000 {
                    todo.push((p, depth + 1));
                } else if m.is_file() {
                    total = total.saturating_add(m.len());
                }
            }
            if total > cap {
                return too_big(total);
            }
        }
        return None;
    }
    match std::fs::symlink_metadata(file) {
        Ok(m) if m.len() > cap => too_big(m.len()),
        _ => None,
    }
}

/// The lab's devices in a fresh session under `rules`, at the start snapshot.
pub fn session(lab: &Lab, rules: Option<Arc<Confinement>>) -> crate::core::Result<Session> {
    let mut s = Session::new(Clock::stepped());
    s.confine = rules;
    match &lab.bench {
        Some(b) => {
            let bench = crate::wiring::bench::Bench::load(b)?;
            crate::wiring::bench::open(&mut s, &bench)?;
        }
        None => {
            for (n, url) in &lab.devices {
                s.open(n, url)?;
            }
        }
    }
    if s.index(&lab.device).is_ok() {
        s.use_device(&lab.device)?;
    }
    if let Some(snap) = &lab.snapshot {
        crate::snapshot::Snapshot::load(snap)?.restore(&mut s)?;
    }
    Ok(s)
}

/// Grades `file` (as given on the command line) against `lab`; what the Lua code prints is
/// dropped (`lab check`).
pub fn grade(lab: &Lab, file: &str) -> Report {
    grade_to(lab, file, Box::new(std::io::sink()))
}

/// Grades `file`, with what the grader and the submission `print` written to `out` (a
/// worker's stdout, which `lab grade` keeps as the submission's output and never reads a
/// grade from).
pub fn grade_to(lab: &Lab, file: &str, out: Box<dyn std::io::Write + Send>) -> Report {
    grade_in(lab, file, out, None)
}

/// [`grade_to`] with the write directory `write` (a worker's, made by its parent), or a new one.
pub fn grade_in(lab: &Lab, file: &str, out: Box<dyn std::io::Write + Send>, write: Option<&Path>) -> Report {
    let path = Path::new(file);
    let Some(kind) = lab.kind_of(path) else {
        return Report::broken(lab, file, crate::msg!("lab-not-submission-kind"));
    };
    if let Some(why) = refused(lab, path) {
        return Report::broken(lab, file, why);
    }
    if !path.is_file() {
        return Report::broken(lab, file, crate::msg!("lab-not-submission-missing"));
    }
    if !lab.accepts.contains(&kind) {
        return Report::broken(
            lab,
            file,
            crate::msg!("lab-not-accepted", kinds = super::config::describe_kinds(&lab.accepts)),
        );
    }
    let kind = if kind == "lua" { "lua" } else { "il" };
    let write = match write.map(WriteDir::given).unwrap_or_else(WriteDir::new) {
        Ok(w) => w,
        Err(e) => return Report::broken(lab, file, grader_error(e)),
    };
    match run(lab, file, kind, out, &write) {
        Ok(_) if written(write.path(), lab.limits.write) > lab.limits.write => {
            Report::broken(lab, file, write_verdict(lab.limits.write))
        }
        Ok(r) => r,
        Err(e) => Report::broken(lab, file, grader_error(e)),
    }
}

/// What a submission may read: its own file (a folder submission, `NAME/main.lua`: its
/// folder), the lab's shared modules and starter files, and the write directory. The grader,
/// the reference and every other file of the lab are the teacher's.
fn submission_view(lab: &Lab, file: &Path, write: &Path) -> (Arc<Confinement>, sandbox::World) {
    let folder = file.file_stem().is_some_and(|s| s == "main");
    let dir = file.parent().filter(|p| !p.as_os_str().is_empty()).unwrap_or(Path::new("."));
    let mut read = vec![if folder { dir.to_path_buf() } else { file.to_path_buf() }];
    read.extend(lab.shared.iter().map(|(_, f, _)| f.clone()));
    read.extend(lab.starter.iter().cloned());
    let mut rules = Confinement::new(read, Some(write.to_path_buf()));
    rules.view = Some(crate::msg!("lab-view").text);
    // The machine is the lab's: the submission drives it, and changes the bench only as granted.
    rules.machine = Some(lab.grants.clone());
    let own = folder.then(|| {
        let real = crate::core::fspath::canonical(dir).unwrap_or_else(|_| dir.to_path_buf());
        (real, dir.display().to_string())
    });
    (Arc::new(rules), sandbox::World { own, shared: lab.shared.clone() })
}

/// `math.random`'s seed for `student` in `lab`: the same in every run, another per student.
fn seed(lab: &Lab, student: &str) -> i64 {
    let mut h: u64 = 0xcbf2_9ce4_8422_2325;
    for b in lab.title.bytes().chain([0u8]).chain(student.bytes()) {
        h = (h ^ u64::from(b)).wrapping_mul(0x0100_0000_01b3);
    }
    h as i64
}

fn run(
    lab: &Lab,
    file: &str,
    kind: &str,
    out: Box<dyn std::io::Write + Send>,
    write: &WriteDir,
) -> crate::core::Result<Report> {
    let sub_dir = Path::new(file).parent().filter(|p| !p.as_os_str().is_empty()).unwrap_or(Path::new("."));
    let rules = Arc::new(Confinement::new(vec![lab.dir.clone(), sub_dir.to_path_buf()], Some(write.0.clone())));
    let (student_rules, world) = submission_view(lab, Path::new(file), write.path());
    let session = session(lab, Some(rules.clone())).map_err(|e| e.cause(crate::msg!("lab-opening-devices").text))?;
    let clock = session.clock.clone();
    let mut shell = Shell::new(session, Style { json: false, color: false });
    shell.confine(rules.clone());
    // One clock per lab: every simulated PLC's real-time clock starts at the lab's epoch
    // (2026-01-01 00:00:00, what `os.time` reads at simulated time zero), not the host's.
    set_rtc_epoch(&mut shell);
    let budget = Arc::new(Budget::new(
        Some(lab.limits.sim_time),
        Some(lab.limits.instructions),
        Some(lab.limits.memory),
        &clock,
    ));
    shell.session.budget = Some(budget.clone());
    let interrupt = shell.session.interrupt.clone();
    let script_err =
        |e: mlua::Error| Error::new(ErrorKind::Script, crate::msg!("lab-cannot-start-lua", error = e.to_string()));
    let engine = Engine::new(interrupt.clone(), out).map_err(script_err)?;
    let lua = engine.lua();
    sandbox::apply(lua, rules.clone()).map_err(script_err)?;
    crate::script::paths::confine(lua, Some(&lab.dir)).map_err(script_err)?;
    sandbox::deterministic(lua, clock.clone(), budget.clone(), seed(lab, &student_name(Path::new(file))))
        .map_err(script_err)?;
    // A limit is over for good: a caught "not enough memory" is the memory limit, and a
    // `pcall` in the submission gives back no limit (the verdict is raised again).
    let (b, stop_flag) = (budget.clone(), interrupt.clone());
    let stop = lua
        .create_function(move |_, v: Value| {
            let memory = match &v {
                Value::String(s) => s.to_string_lossy().contains("not enough memory"),
                Value::Error(e) => {
                    matches!(**e, mlua::Error::MemoryError(_)) || e.to_string().contains("not enough memory")
                }
                _ => false,
            };
            if memory {
                b.exceed_memory();
                stop_flag.store(true, Ordering::Relaxed);
            }
            Ok(b.exceeded())
        })
        .map_err(script_err)?;
    // The grader's own protected calls too: a submission that keeps the memory full makes the
    // run's verdict the memory limit, not a grader error.
    sandbox::hold_limits(lua, &lua.globals(), &stop).map_err(script_err)?;
    let student_env = sandbox::submission_env(lua, student_rules.clone(), world, stop).map_err(script_err)?;
    install_lab(lua, lab, file, kind, student_env, budget.clone(), [rules.clone(), student_rules])
        .map_err(script_err)?;
    let watch = engine.limit(budget.clone(), clock.clone(), interrupt.clone()).map_err(script_err)?;

    let outcome = engine.run_file(&mut shell, &lab.grader, &[]);
    let lua = engine.lua();
    lua.remove_hook();
    lua.remove_global_hook();
    if let Some(w) = &watch {
        w.remove(lua).ok();
    }
    lua.set_memory_limit(0).ok();
    let plc_fault = if kind == "il" { plc_fault(&mut shell, lab, file) } else { None };
    let mut grader_errors = Vec::new();
    let mut criteria = collect(lua, &mut grader_errors).map_err(script_err)?;
    for (name, p) in &lab.points {
        if !criteria.iter().any(|c| &c.name == name) {
            criteria.push(skipped(name, *p));
        }
    }
    let student_error: Option<String> =
        lua.globals().get::<Table>("lab").and_then(|l| l.get::<Option<String>>("_student_error")).ok().flatten();
    let runtime = |e: &str| crate::msg!("lab-runtime-error", error = e);
    let verdict: Result<crate::core::msg::Msg, &str> = if let Some(v) = budget.exceeded_msg() {
        Ok(v)
    } else if let Some(v) = outcome
        .as_ref()
        .is_err_and(|f| f.error.message.contains("not enough memory"))
        .then(|| budget.memory_verdict())
        .flatten()
    {
        Ok(v)
    } else if let Some(e) = grader_errors.first() {
        // A mistake in the grader's own code is the teacher's, whatever the submission did.
        Ok(grader_error(e))
    } else if let Some(e) = student_error {
        Ok(runtime(e.lines().next().unwrap_or_default()))
    } else if let Some(fault) = plc_fault {
        Ok(runtime(&fault))
    } else if let Err(f) = &outcome {
        Ok(grader_error(f.headline()))
    } else if criteria.iter().all(|c| c.passed) {
        Err("passed")
    } else {
        Err("failed")
    };
    let (verdict, code) = match verdict {
        Ok(m) => (m.text, Some(m.id.to_string())),
        Err(word) => (word.to_string(), None),
    };
    // The write directory's name changes from run to run: reports name it by its role.
    let wd = crate::core::fspath::canonical(&write.0).unwrap_or_else(|_| write.0.clone()).display().to_string();
    // `got` holds values as JSON text, where a Windows path's `\` is written `\\`.
    let wd_json = wd.replace('\\', "\\\\");
    let role = crate::msg!("lab-write-dir-role").text;
    let hide = |s: &mut Option<String>| {
        if let Some(t) = s {
            *t = t.replace(&wd, &role).replace(&wd_json, &role);
        }
    };
    for c in &mut criteria {
        hide(&mut c.error);
        if let Some(serde_json::Value::String(g)) = &c.got {
            let mut g = Some(g.clone());
            hide(&mut g);
            c.got = g.map(serde_json::Value::String);
        }
    }
    let verdict = no_addresses(&verdict.replace(&wd, &role));
    Ok(Report {
        student: student_name(Path::new(file)),
        file: file.to_string(),
        points: criteria.iter().map(|c| c.points).sum(),
        max_points: criteria.iter().map(|c| c.max).sum(),
        criteria,
        verdict,
        code,
        sim_time_s: budget.used(&clock).as_secs_f64(),
        stdout: None,
        stderr: None,
    })
}

/// The date and time every simulated K2's real-time clock starts at in a graded run: the
/// sandbox's epoch ([`sandbox::EPOCH`], 2026-01-01 00:00:00), so a program that reads the
/// clock gets the same answer on every machine and at every hour.
pub const RTC_EPOCH: &str = "2026-01-01T00:00:00";

/// Sets every simulated K2's clock to [`RTC_EPOCH`] (`rtc NAME set …`, the manual's SET_RTC,
/// §2.2.9). The UMPK, FX and drive simulators keep no calendar clock: their time is the
/// session's simulated clock, which starts at zero.
fn set_rtc_epoch(shell: &mut Shell) {
    let k2s: Vec<String> = shell
        .session
        .entries()
        .iter()
        .filter(|e| e.url.split(':').next().is_some_and(|s| s.eq_ignore_ascii_case("sim")))
        .map(|e| e.name.clone())
        .collect();
    let back = shell.session.current_index().ok();
    for name in k2s {
        let _ = shell.exec(&format!("rtc {name} set {RTC_EPOCH}"));
    }
    if let Some(b) = back {
        shell.session.use_index(b);
    }
}

/// The fault that stopped the PLC an IL submission runs on (its watchdog: an endless loop),
/// as `file:line: …`, read from `sim program` once the grader is done.
fn plc_fault(shell: &mut Shell, lab: &Lab, file: &str) -> Option<String> {
    shell.session.interrupt.store(false, Ordering::Relaxed);
    shell.session.use_device(&lab.device).ok()?;
    let o = shell.exec("sim program").into_iter().next()?.ok()?.to_json();
    // A UMPK says it in its program line: `IL p.il stopped: line 2: … (JMP L1) (executed …)`.
    if let Some(why) = o.get("program").and_then(|p| p.as_str()).and_then(|p| p.split_once(" stopped: line ")) {
        let (line, msg) = why.1.split_once(": ")?;
        let msg = msg.split(" (executed").next().unwrap_or(msg);
        return Some(crate::msg!("lab-plc-stopped", file = file, line = line, error = msg).text);
    }
    let f = o.get("faults")?.as_array()?.first()?;
    let line = f.get("line").and_then(|l| l.as_u64()).map(|l| format!(":{l}")).unwrap_or_default();
    let kind = f.get("kind").and_then(|k| k.as_str()).unwrap_or("fault");
    let msg = f.get("message").and_then(|m| m.as_str()).unwrap_or_default();
    let place = format!("{file}{line}");
    let at = f.get("instruction").and_then(|i| i.as_str());
    let fault = match (f.get("code").and_then(|c| c.as_u64()), at) {
        (Some(c), Some(i)) => {
            crate::msg!("lab-plc-fault-code-at", place = place, code = c, kind = kind, error = msg, at = i)
        }
        (Some(c), None) => crate::msg!("lab-plc-fault-code", place = place, code = c, kind = kind, error = msg),
        (None, Some(i)) => crate::msg!("lab-plc-fault-at", place = place, kind = kind, error = msg, at = i),
        (None, None) => crate::msg!("lab-plc-fault", place = place, kind = kind, error = msg),
    };
    Some(fault.text)
}

/// The message of a student's error: `file:line: message`, without the traceback.
fn student_message(e: &mlua::Error, file: &str) -> String {
    let f = crate::script::error::failure(e).with_full_chunk_name(file);
    let msg = f.headline().split("\nstack traceback:").next().unwrap_or_default().trim_end().to_string();
    no_addresses(&with_hint(msg, f.error.hint.as_deref()))
}

/// `s` without the memory addresses Lua shows for a table, function, thread or userdata
/// (`table: 0x55d…` → `table`): they differ from run to run, and a verdict must not.
pub fn no_addresses(s: &str) -> String {
    let mut out = String::with_capacity(s.len());
    let mut rest = s;
    while let Some(i) = rest.find(": ") {
        let (head, tail) = rest.split_at(i);
        let after = &tail[2..];
        let hex = after.strip_prefix("0x").unwrap_or(after);
        let named = ["table", "function", "thread", "userdata", "builtin"].iter().any(|w| head.ends_with(w));
        // An address has at most 16 hex digits: no need to look further into a long text.
        let n = if named { hex.bytes().take(17).take_while(u8::is_ascii_hexdigit).count() } else { 0 };
        out.push_str(head);
        if (8..=16).contains(&n) || (hex.len() < after.len() && (1..=16).contains(&n)) {
            rest = &hex[n..];
        } else {
            out.push_str(": ");
            rest = after;
        }
    }
    out.push_str(rest);
    out
}

/// A verdict with the shell's hint for it (`— did you mean TON?`), as the shell shows it.
fn with_hint(msg: String, hint: Option<&str>) -> String {
    match hint {
        Some(h) if !h.is_empty() && !msg.contains(h) => format!("{msg} — {h}"),
        _ => msg,
    }
}

/// The session's devices by name and identity (where each device lives): a device closed and
/// opened again under its name is another.
fn machine(sh: &Shell) -> Vec<(String, usize)> {
    sh.session.entries().iter().map(|e| (e.name.clone(), &*e.device as *const _ as *const u8 as usize)).collect()
}

/// The grader's `lab` table, in the globals (a submission's environment has none).
/// `rules`: the grader's and the submission's; the session holds the submission's while it runs
/// (so `plcsh.exec("sim program load …")` in a submission reads only what it may).
fn install_lab(
    lua: &Lua,
    lab: &Lab,
    file: &str,
    kind: &str,
    env: Table,
    budget: Arc<Budget>,
    rules: [Arc<Confinement>; 2],
) -> mlua::Result<()> {
    let t = lua.create_table()?;
    t.set("title", lab.title.as_str())?;
    t.set("submission", file)?;
    t.set("student", student_name(Path::new(file)))?;
    t.set("kind", kind)?;
    t.set("device", lab.device.as_str())?;
    t.set("dir", lab.dir.display().to_string())?;
    let b = budget.clone();
    let cap = lab.limits.submission;
    t.set(
        "_run_lua",
        lua.create_function(move |lua, path: String| {
            // Never through a link (the submission was checked for links before the run).
            let code = crate::core::platform::read_no_follow(Path::new(&path), cap).map_err(|e| {
                mlua::Error::runtime(crate::msg!("lab-cannot-read", file = path.as_str(), error = e.to_string()))
            })?;
            let code = match sandbox::lua_text(code) {
                Ok(c) => c,
                Err(why) => {
                    let msg = format!("{path}: {why}");
                    let lab: Table = lua.globals().get("lab")?;
                    lab.raw_set("_student_error", msg.clone())?;
                    return Ok((false, Some(msg)));
                }
            };
            let f = lua
                .load(code)
                .set_name(format!("@{path}"))
                .set_mode(mlua::chunk::ChunkMode::Text)
                .set_environment(env.clone())
                .into_function();
            let confine = |lua: &Lua, r: &Arc<Confinement>| {
                if let Some(mut sh) = lua.app_data_mut::<Shell>() {
                    sh.confine(r.clone());
                }
            };
            let current = lua.app_data_ref::<Shell>().and_then(|sh| sh.session.current_index().ok());
            let before = lua.app_data_ref::<Shell>().map(|sh| machine(&sh)).unwrap_or_default();
            // The submission's abort handlers are its own: kept apart from the grader's and
            // run here, as the submission (its file rules, the run's limits), never by the
            // grader's end of the run.
            let grader_handlers: Table = lua.named_registry_value(crate::script::ABORT_KEY)?;
            lua.set_named_registry_value(crate::script::ABORT_KEY, lua.create_table()?)?;
            confine(lua, &rules[1]);
            let mut r = f.and_then(|f| f.call::<()>(()));
            let own: Table = lua.named_registry_value(crate::script::ABORT_KEY)?;
            lua.set_named_registry_value(crate::script::ABORT_KEY, grader_handlers)?;
            if r.is_err() && b.exceeded().is_none() {
                // Once a limit ended the run, no submission code runs again.
                let list: Vec<mlua::Function> = own.sequence_values().filter_map(|f| f.ok()).collect();
                for h in list.iter().rev() {
                    if let Err(e) = h.call::<()>("failed") {
                        if b.exceeded().is_some() {
                            r = Err(e);
                            break;
                        }
                    }
                }
            }
            confine(lua, &rules[0]);
            // What the submission made current (`use servo`) is not the grader's.
            if let (Some(i), Some(mut sh)) = (current, lua.app_data_mut::<Shell>()) {
                sh.session.use_index(i);
            }
            // The grader grades the lab's devices, never others under their names: a device
            // the submission closed or replaced (where the lab grants it) ends every criterion
            // still to run, and the verdict is the submission's.
            let after = lua.app_data_ref::<Shell>().map(|sh| machine(&sh)).unwrap_or_default();
            if let Some((name, _)) = before.iter().find(|d| !after.contains(d)) {
                let msg = crate::msg!("lab-device-replaced", file = path.as_str(), device = name.as_str()).text;
                let lab: Table = lua.globals().get("lab")?;
                lab.raw_set("_machine_changed", msg.clone())?;
                if r.is_ok() {
                    lab.raw_set("_student_error", msg.clone())?;
                    return Ok((false, Some(msg)));
                }
            }
            match r {
                Ok(()) => Ok((true, None)),
                Err(e) => {
                    if matches!(e, mlua::Error::MemoryError(_)) {
                        if let Some(v) = b.memory_verdict() {
                            b.exceed(v);
                        }
                    }
                    let stopped = b.exceeded().is_some()
                        || lua
                            .globals()
                            .get::<Table>("plcsh")
                            .and_then(|p| p.get::<mlua::Function>("_interrupted"))
                            .and_then(|f| f.call::<bool>(()))
                            .unwrap_or(false);
                    if stopped {
                        return Err(e);
                    }
                    let msg = student_message(&e, &path);
                    let lab: Table = lua.globals().get("lab")?;
                    lab.raw_set("_student_error", msg.clone())?;
                    Ok((false, Some(msg)))
                }
            }
        })?,
    )?;
    t.set(
        "_load_il",
        lua.create_function(|lua, (path, device): (String, String)| {
            let plcsh: Table = lua.globals().get("plcsh")?;
            let exec: mlua::Function = plcsh.get("exec")?;
            // The path as one quoted word: a lab under `C:\Users\Иванов\лаб 1` loads as it is.
            use crate::shell::lex::quote;
            exec.call::<MultiValue>(format!("use {}", quote(&device)))?;
            match exec.call::<MultiValue>(format!("sim program load {}", quote(&path))) {
                Ok(_) => Ok((true, None)),
                Err(e) => {
                    // The program's own error names its file:line (not the grader's line).
                    let f = crate::script::error::failure(&e);
                    let msg = f.error.message.split('\n').next().unwrap_or_default().to_string();
                    let msg = with_hint(msg, f.error.hint.as_deref());
                    let lab: Table = lua.globals().get("lab")?;
                    lab.raw_set("_student_error", msg.clone())?;
                    Ok((false, Some(msg)))
                }
            }
        })?,
    )?;
    let points = lua.create_table()?;
    for (n, p) in &lab.points {
        points.set(n.as_str(), *p)?;
    }
    lua.load(include_str!("lab.lua")).set_name("=plcsh:lab").call::<()>((t.clone(), points))?;
    lua.globals().set("lab", t)?;
    Ok(())
}

/// Lua's text of a number JSON cannot hold (`inf`, `-inf`, `nan`).
fn lua_number_text(n: f64) -> String {
    if n.is_nan() {
        "nan".into()
    } else if n > 0.0 {
        "inf".into()
    } else {
        "-inf".into()
    }
}

/// The criteria the grader ran, and the errors in the grader's own code that ended any of
/// them (lab.lua tells those from failed checks: see `lab.criterion`).
fn collect(lua: &Lua, grader_errors: &mut Vec<String>) -> mlua::Result<Vec<Criterion>> {
    let lab: Table = lua.globals().get("lab")?;
    let f: mlua::Function = lab.get("_collect")?;
    let list: Table = f.call(())?;
    let mut out = Vec::new();
    for r in list.sequence_values::<Table>() {
        let r = r?;
        let s = |k: &str| -> mlua::Result<Option<String>> {
            Ok(match r.get::<Value>(k)? {
                Value::Nil => None,
                v => Some(lua.coerce_string(v)?.map(|s| s.to_string_lossy()).unwrap_or_default()),
            })
        };
        // A number stays a number (an integer as one); anything else is the grader's text.
        let v = |k: &str| -> mlua::Result<Option<serde_json::Value>> {
            Ok(match r.get::<Value>(k)? {
                Value::Nil => None,
                Value::Integer(i) => Some(i.into()),
                Value::Number(n) => Some(
                    serde_json::Number::from_f64(n)
                        .map(serde_json::Value::Number)
                        .unwrap_or_else(|| lua_number_text(n).into()),
                ),
                other => Some(lua.coerce_string(other)?.map(|s| s.to_string_lossy()).unwrap_or_default().into()),
            })
        };
        if let Some(e) = s("grader_error")? {
            grader_errors.push(format!("criterion \"{}\": {e}", r.get::<String>("name")?));
        }
        out.push(Criterion {
            name: r.get("name")?,
            points: r.get("points")?,
            max: r.get("max")?,
            passed: r.get("passed")?,
            skipped: false,
            what: s("what")?,
            expected: v("expected")?,
            got: v("got")?,
            error: s("error")?,
            at_s: r.get::<Option<f64>>("at")?.map(|t| (t * 1e6).round() / 1e6),
        });
    }
    Ok(out)
}

#[cfg(test)]
mod runtime_tests {
    use super::*;

    #[test]
    fn addresses_leave_verdicts() {
        assert_eq!(no_addresses("x.lua:1: table: 0x55d0c8a1b2c0"), "x.lua:1: table");
        assert_eq!(
            no_addresses("got function: builtin: 0x5583e0c31ba0 and thread: 000001A2B3C4D5E6"),
            "got function: builtin and thread"
        );
        assert_eq!(no_addresses("stop: deadbeef, table: no"), "stop: deadbeef, table: no");
        assert_eq!(no_addresses("Q0.0: expected 1, got 0"), "Q0.0: expected 1, got 0");
    }
}
