//! The project's attack class: every submission in tests/lab/attacks/submissions — hostile
//! ones (forged reports, borrowed modules, the reference read, limits dodged, outputs broken,
//! verdicts made to differ between runs) and the correct solutions they are compared with —
//! graded twice with two workers by `plcsh --json lab grade`, byte-identical, each with the
//! points and verdict tests/lab/attacks/expected.txt gives it. The outputs stay sound (the
//! JUnit file parses as XML, the text table has one line per submission and no control
//! character), and the teacher's mistakes are the teacher's: a bug in the grader is a grader
//! error, `lab check` refuses `[points]` and devices that name nothing, and a time in words
//! is quoted back with what to write.

mod common;
use common::*;
use std::collections::BTreeMap;
use std::path::{Path, PathBuf};

fn root() -> &'static Path {
    Path::new(env!("CARGO_MANIFEST_DIR"))
}

fn in_root(args: &[&str]) -> std::process::Output {
    plcsh().current_dir(root()).args(args).output_retrying().expect("start plcsh")
}

fn temp(name: &str) -> PathBuf {
    let d = std::env::temp_dir().join(format!("plcsh-attacks-{}-{name}", std::process::id()));
    let _ = std::fs::remove_dir_all(&d);
    std::fs::create_dir_all(&d).unwrap();
    d
}

/// One row of expected.txt: the student, the points, and the verdict's expected parts (any).
struct Expected {
    student: String,
    points: f64,
    verdict: Vec<String>,
}

fn expected() -> Vec<Expected> {
    let text = std::fs::read_to_string(root().join("tests/lab/attacks/expected.txt")).unwrap();
    text.lines()
        .filter(|l| !l.starts_with('#') && !l.trim().is_empty())
        .map(|l| {
            let cols: Vec<&str> = l.split('\t').collect();
            assert_eq!(cols.len(), 3, "expected.txt: three columns separated by tabs: {l}");
            Expected {
                student: cols[0].to_string(),
                points: cols[1].parse().unwrap_or_else(|_| panic!("expected.txt: points: {l}")),
                verdict: cols[2].split("||").map(str::to_string).collect(),
            }
        })
        .collect()
}

/// A memory address as Lua prints one (`table: 0x55d0c3a2b4c0`): six or more hex digits
/// after `0x`.
fn has_address(s: &str) -> bool {
    s.match_indices("0x").any(|(i, _)| s[i + 2..].chars().take_while(|c| c.is_ascii_hexdigit()).count() >= 6)
}

/// A character a terminal or an XML 1.0 parser must not receive.
fn is_control(c: char) -> bool {
    c.is_control() && c != '\n'
}

#[test]
fn the_attack_class_gets_its_expected_verdicts_twice_alike() {
    let want = expected();
    assert!(want.len() >= 60, "the class has {} submissions", want.len());
    let d = temp("class");
    let junit = d.join("results.xml");
    let grade = |junit: Option<&Path>| {
        let mut args = vec!["--json", "lab", "grade", "tests/lab/attacks/lab", "tests/lab/attacks/submissions"];
        args.extend(["--jobs", "2"]);
        if let Some(j) = junit {
            args.extend(["--junit", j.to_str().unwrap()]);
        }
        in_root(&args)
    };
    let first = grade(Some(&junit));
    // The second run on a loaded machine: a busy thread per core beside the two workers.
    let stop = std::sync::Arc::new(std::sync::atomic::AtomicBool::new(false));
    let cores = std::thread::available_parallelism().map(|n| n.get()).unwrap_or(2);
    let load: Vec<_> = (0..cores)
        .map(|_| {
            let stop = stop.clone();
            std::thread::spawn(move || {
                let mut x = 0u64;
                while !stop.load(std::sync::atomic::Ordering::Relaxed) {
                    x = std::hint::black_box(x.wrapping_mul(6364136223846793005).wrapping_add(1));
                }
            })
        })
        .collect();
    let second = grade(None);
    stop.store(true, std::sync::atomic::Ordering::Relaxed);
    load.into_iter().for_each(|t| t.join().unwrap());
    assert_eq!(first.status.code(), Some(0), "no grader error: {}", stderr(&first));
    let lines = json_lines(&first);
    assert_eq!(lines.len(), want.len() + 1, "one object per submission and a summary");
    let by_student: BTreeMap<&str, &serde_json::Value> =
        lines[..want.len()].iter().map(|l| (l["student"].as_str().unwrap(), l)).collect();

    // Every submission as expected; all the differences at once.
    let root_text = root().display().to_string();
    let mut wrong = Vec::new();
    for w in &want {
        let Some(r) = by_student.get(w.student.as_str()) else {
            wrong.push(format!("{}: not graded", w.student));
            continue;
        };
        // A path in a verdict has the platform's separator (`submissions\x.lua` on Windows).
        let raw = r["verdict"].as_str().unwrap();
        let v = raw.replace('\\', "/");
        let short: String = v.chars().take(200).collect();
        if !w.verdict.iter().any(|part| v.contains(part.as_str()) || raw.contains(part.as_str())) {
            wrong.push(format!("{}: verdict `{short}`, expected `{}`", w.student, w.verdict.join("` or `")));
        }
        if r["points"].as_f64() != Some(w.points) {
            wrong.push(format!("{}: {} points, expected {} (`{short}`)", w.student, r["points"], w.points));
        }
        // Nothing in a report names the machine's folders or a memory address, or is large.
        let text = r.to_string();
        if text.contains(&root_text) {
            wrong.push(format!("{}: the report names {root_text}", w.student));
        }
        if has_address(&text) {
            wrong.push(format!("{}: a memory address in `{short}`", w.student));
        }
        if r["verdict"].as_str().unwrap().chars().any(is_control) {
            wrong.push(format!("{}: a control character in the verdict", w.student));
        }
        if text.len() > 200_000 {
            wrong.push(format!("{}: a report of {} bytes", w.student, text.len()));
        }
    }
    assert!(wrong.is_empty(), "{} of {} submissions differ:\n{}", wrong.len(), want.len(), wrong.join("\n"));

    // Byte-identical, run after run, idle or loaded.
    assert_eq!(stdout(&first), stdout(&second), "two runs differ");
    let third = grade(None);
    assert_eq!(stdout(&first), stdout(&third), "a third run differs");

    // What the submissions printed: in the order written, the write directory as `write`, and
    // never the reference (an abort handler runs as the submission, or not at all).
    let out = |s: &str| by_student[s]["stdout"].as_str().unwrap_or_default().to_string();
    // (On Windows the C library's text-mode stdout writes io.write's "\n" as "\r\n": the
    // order is what this checks.)
    assert_eq!(out("io_order").replace("\r\n", "\n"), "one\ntwo\nthree\nfour\n");
    assert_eq!(out("write_dir_path"), "write\n");
    let tmp = std::env::temp_dir().display().to_string();
    for l in &lines[..want.len()] {
        let text = l.to_string();
        assert!(!text.contains("servo.controlword = 15"), "the reference reached a report: {text}");
        assert!(!text.contains(&tmp) && !text.contains("plcsh-report-"), "a folder of the grader's: {text}");
    }

    // A number the grader expected or got is a JSON number.
    let answer = by_student["math_random"]["criteria"]
        .as_array()
        .unwrap()
        .iter()
        .find(|c| c["name"] == "answer in VW0")
        .unwrap()
        .clone();
    assert_eq!(answer["expected"], serde_json::json!(1234), "{answer}");
    assert!(answer["got"].is_number(), "{answer}");

    // The JUnit file is XML a real parser reads, with a suite per submission.
    let xml = std::fs::read_to_string(&junit).unwrap();
    assert!(!xml.chars().any(|c| c.is_control() && c != '\n'), "a control character in the JUnit file");
    assert_eq!(xml.matches("<testsuite ").count(), want.len());
    // Python's own XML parser, where there is one to run (not under Wine: it is a Linux program).
    let python = Path::new("/usr/bin/python3");
    if cfg!(unix) && python.exists() {
        let o = std::process::Command::new(python)
            .args([
                "-c",
                "import sys, xml.etree.ElementTree as E\nr = E.parse(sys.argv[1]).getroot()\nprint(len(r.findall('testsuite')), sum(1 for _ in r.iter('failure')))",
            ])
            .arg(&junit)
            .output()
            .unwrap();
        assert!(o.status.success(), "the JUnit file does not parse: {}", String::from_utf8_lossy(&o.stderr));
        let counts = String::from_utf8_lossy(&o.stdout).to_string();
        let failures: usize = lines[..want.len()]
            .iter()
            .map(|l| l["criteria"].as_array().unwrap().iter().filter(|c| c["passed"] != true).count())
            .sum();
        assert_eq!(counts.split_whitespace().collect::<Vec<_>>(), [want.len().to_string(), failures.to_string()]);
    } else {
        skipped("/usr/bin/python3 on a Unix system (to parse the JUnit file with an XML parser of its own)");
    }
    std::fs::remove_dir_all(&d).unwrap();
}

#[test]
fn verdicts_that_would_break_the_text_table_stay_one_line_each() {
    let subs = [
        "error_escape.lua",
        "error_newlines.lua",
        "error_pipes.lua",
        "error_nul.lua",
        "error_c1.lua",
        "error_huge.lua",
    ];
    let mut args = vec!["lab".to_string(), "grade".into(), "tests/lab/attacks/lab".into()];
    args.extend(subs.iter().map(|s| format!("tests/lab/attacks/submissions/{s}")));
    let started = std::time::Instant::now();
    let o = plcsh().current_dir(root()).args(&args).output_retrying().unwrap();
    let took = started.elapsed();
    assert_eq!(o.status.code(), Some(0), "{}", both(&o));
    let text = stdout(&o);
    assert!(!text.chars().any(is_control), "a control character reached the terminal: {text:?}");
    assert!(text.len() < 40_000, "{} bytes for six submissions", text.len());
    // The table: a header, a rule, then one row per submission, each with seven unescaped |.
    let rows: Vec<&str> = text.lines().filter(|l| l.starts_with('|')).collect();
    assert_eq!(rows.len(), subs.len() + 2, "{text}");
    for r in &rows {
        let bars = r.char_indices().filter(|(i, c)| *c == '|' && (*i == 0 || &r[i - 1..*i] != "\\")).count();
        assert_eq!(bars, 7, "one row, six cells: {r}");
    }
    assert!(text.contains("\\u{1b}[2J"), "{text}");
    assert!(text.contains("a \\| b \\| c \\|"), "{text}");
    assert!(text.contains("bytes more)"), "{text}");
    // A 20 MiB error is graded and shown in seconds (it took minutes when the table held it whole).
    assert!(took < std::time::Duration::from_secs(30), "{took:?}");
}

/// A lab folder `lab/` in a temporary folder of its own: the attack lab's files, with `edit`
/// applied to one. Returns the lab folder.
fn lab_copy(name: &str, file: &str, edit: impl Fn(&str) -> String) -> PathBuf {
    let d = temp(name).join("lab");
    std::fs::create_dir_all(&d).unwrap();
    for f in ["lab.toml", "grade.lua", "helpers.lua", "reference.lua"] {
        let text = std::fs::read_to_string(root().join("tests/lab/attacks/lab").join(f)).unwrap();
        std::fs::write(d.join(f), if f == file { edit(&text) } else { text }).unwrap();
    }
    d
}

fn remove(lab: &Path) {
    std::fs::remove_dir_all(lab.parent().unwrap()).unwrap();
}

/// The rows of docs/teaching.md's "What a submission sees": (what, try, yes).
fn doc_rows() -> Vec<(String, String, bool)> {
    let doc = std::fs::read_to_string(root().join("docs/teaching.md")).unwrap();
    let start = doc.find("| what | try | a submission |").expect("the table in docs/teaching.md");
    let mut rows = Vec::new();
    for line in doc[start..].lines().skip(2) {
        if !line.starts_with('|') {
            break;
        }
        let cells: Vec<&str> = line.trim_matches('|').split(" | ").map(str::trim).collect();
        assert_eq!(cells.len(), 3, "three cells: {line}");
        let code = cells[1]
            .strip_prefix('`')
            .and_then(|c| c.strip_suffix('`'))
            .unwrap_or_else(|| panic!("a code span: {line}"));
        let yes = match cells[2] {
            "yes" => true,
            "no" => false,
            other => panic!("yes or no, not `{other}`: {line}"),
        };
        rows.push((cells[0].to_string(), code.to_string(), yes));
    }
    rows
}

#[test]
fn what_a_submission_sees_is_as_the_teaching_guide_says_row_by_row() {
    let rows = doc_rows();
    assert!(rows.len() >= 30, "{} rows", rows.len());
    let lab = lab_copy("doc", "", |t| t.to_string());
    let top = lab.parent().unwrap().to_path_buf();
    std::fs::write(top.join("outside.txt"), "not the submission's\n").unwrap();
    for (i, (_, code, _)) in rows.iter().enumerate() {
        let name = format!("row{i:02}");
        let sub = top.join("subs").join(&name);
        std::fs::create_dir_all(&sub).unwrap();
        std::fs::write(sub.join("mine.lua"), "return { ok = true }\n").unwrap();
        let code = code.replace("NAME", &name);
        std::fs::write(
            sub.join("main.lua"),
            format!("local ok, v = pcall(function() return {code} end)\nprint(\"ROW \" .. ((ok and v) and \"yes\" or \"no\"))\n"),
        )
        .unwrap();
    }
    let o = plcsh()
        .current_dir(&top)
        .args(["--json", "lab", "grade", "lab", "subs", "--jobs", "2"])
        .output_retrying()
        .unwrap();
    let lines = json_lines(&o);
    assert_eq!(lines.len(), rows.len() + 1, "{}", both(&o));
    let mut wrong = Vec::new();
    for (i, (what, code, yes)) in rows.iter().enumerate() {
        let r = lines.iter().find(|l| l["student"] == format!("row{i:02}")).unwrap();
        let out = r["stdout"].as_str().unwrap_or_default();
        let got = out.contains("ROW yes");
        if got != *yes {
            wrong.push(format!(
                "{what}: `{code}` gives {}, the guide says {} (verdict `{}`, output `{out}`)",
                if got { "yes" } else { "no" },
                if *yes { "yes" } else { "no" },
                r["verdict"].as_str().unwrap_or_default().chars().take(200).collect::<String>()
            ));
        }
        // A "no" that ended the run ends it on its limit or refusal, never on the wall-clock net.
        assert!(!r["verdict"].as_str().unwrap_or_default().contains("wall-clock"), "{what}: {r}");
    }
    assert!(wrong.is_empty(), "{} of {} rows differ:\n{}", wrong.len(), rows.len(), wrong.join("\n"));
    remove(&lab);
}

#[test]
fn lab_check_refuses_points_devices_and_times_that_name_nothing() {
    // A [points] key no criterion has would cost every student its points.
    let d = lab_copy("points", "lab.toml", |t| t.replace("\"lamp on\" = 3", "\"lamp onn\" = 3"));
    let o = plcsh().args(["lab", "check"]).arg(&d).output_retrying().unwrap();
    assert_eq!(o.status.code(), Some(2), "{}", both(&o));
    let text = both(&o);
    assert!(text.contains("[points] \"lamp onn\" names no criterion the grader defines"), "{text}");
    assert!(text.contains("did you mean \"lamp on\"?"), "{text}");
    remove(&d);
    // The device IL is loaded into is one of the lab's.
    let d = lab_copy("device", "lab.toml", |t| t.replace("device = \"plc\"", "device = \"plc2\""));
    let o = plcsh().args(["lab", "check"]).arg(&d).output_retrying().unwrap();
    assert_eq!(o.status.code(), Some(2), "{}", both(&o));
    assert!(both(&o).contains("device = \"plc2\" is not a device of the lab"), "{}", both(&o));
    assert!(both(&o).contains("did you mean device = \"plc\"?"), "{}", both(&o));
    remove(&d);
    // A time in words is quoted as written, with what to write.
    let d = lab_copy("time", "lab.toml", |t| t.replace("sim_time = \"1min\"", "sim_time = \"10 minutes\""));
    let o = plcsh().args(["lab", "check"]).arg(&d).output_retrying().unwrap();
    assert_eq!(o.status.code(), Some(2), "{}", both(&o));
    let text = both(&o);
    assert!(text.contains("sim_time = \"10 minutes\"") && text.contains("\"10min\" or \"600s\""), "{text}");
    assert!(!text.contains("mutes"), "{text}");
    remove(&d);
}

/// The teacher's side of a class: a submission larger than the lab's cap is a verdict, not
/// gigabytes of memory; two submissions with one student name are flagged; a file name with a
/// newline stays one line under `--show-output`; a write directory past the cap is a verdict,
/// and no folder of a run is left behind, whether the worker ended or was ended.
#[test]
fn big_twin_and_odd_submissions_are_told_apart_and_leave_nothing_behind() {
    let d = lab_copy("teacher", "lab.toml", |t| t.replace("wall = \"60s\"", "wall = \"60s\"\nwrite = \"1MiB\""));
    let top = d.parent().unwrap().to_path_buf();
    let subs = top.join("subs");
    std::fs::create_dir_all(subs.join("twin")).unwrap();
    let task = std::fs::read_to_string(root().join("tests/lab/attacks/lab/reference.lua")).unwrap();
    std::fs::write(subs.join("twin.lua"), &task).unwrap();
    std::fs::write(subs.join("twin/main.lua"), &task).unwrap();
    std::fs::write(subs.join("huge.il"), "LD SM0.0\n".repeat(300_000)).unwrap();
    // More than the cap, and far more (the parent may end this one while it writes).
    let flood = |mib: u32| {
        format!("local f = assert(io.open(plcsh.write_dir .. \"/w.bin\", \"wb\"))\nlocal s = string.rep(\"z\", 1 << 20)\nfor _ = 1, {mib} do f:write(s) f:flush() end\nf:close()\n{task}")
    };
    std::fs::write(subs.join("flood.lua"), flood(2)).unwrap();
    std::fs::write(subs.join("deluge.lua"), flood(40)).unwrap();
    let odd = if cfg!(unix) { "odd\nrow" } else { "odd_row" };
    std::fs::write(subs.join(format!("{odd}.lua")), format!("print(\"hi\")\n{task}")).unwrap();
    let tmp = top.join("tmp");
    std::fs::create_dir_all(&tmp).unwrap();
    let o = plcsh()
        .current_dir(&top)
        .env("TMPDIR", &tmp)
        .env("TMP", &tmp)
        .env("TEMP", &tmp)
        .args(["lab", "grade", "lab", "subs", "--jobs", "2", "--show-output"])
        .output_retrying()
        .unwrap();
    assert_eq!(o.status.code(), Some(0), "{}", both(&o));
    let text = stdout(&o);
    assert!(text.contains("warning: 2 submissions have the student name twin"), "{text}");
    assert!(text.contains("refused: the submission is 2700000 bytes, more than the lab's 1 MiB"), "{text}");
    assert_eq!(text.matches("exceeded 1 MiB in the write directory").count(), 2, "{text}");
    if cfg!(unix) {
        assert!(text.contains("odd\\nrow (stdout):"), "{text}");
    }
    let left: Vec<_> = std::fs::read_dir(&tmp).unwrap().flatten().map(|e| e.file_name()).collect();
    assert!(left.is_empty(), "left in the temporary folder: {left:?}");
    remove(&d);
}

/// `lab check` names the criteria a program earns without doing the task: here the attack
/// lab's "runs", which an empty program passes, and a starter that is the reference copied.
#[test]
fn lab_check_warns_of_points_a_program_earns_without_the_task() {
    let d = lab_copy("free", "lab.toml", |t| t.replace("shared = [", "starter = [\"given.lua\"]\nshared = ["));
    std::fs::copy(d.join("reference.lua"), d.join("given.lua")).unwrap();
    let o = plcsh().args(["lab", "check"]).arg(&d).output_retrying().unwrap();
    assert_eq!(o.status.code(), Some(0), "{}", both(&o));
    let text = stdout(&o);
    assert!(text.contains("warning: an empty program earns 1/10 points (\"runs\")"), "{text}");
    assert!(text.contains("warning: the starter given.lua earns 10/10 points"), "{text}");
    let o = plcsh().args(["--json", "lab", "check"]).arg(&d).output_retrying().unwrap();
    assert_eq!(json_lines(&o)[0]["warnings"].as_array().map(Vec::len), Some(2), "{}", both(&o));
    remove(&d);
}

#[test]
fn a_bug_in_the_grader_inside_a_criterion_is_a_grader_error() {
    let reference = "tests/lab/attacks/submissions/honest_reference.lua";
    let grade = |d: &Path| {
        plcsh().current_dir(root()).args(["--json", "lab", "grade"]).arg(d).arg(reference).output_retrying().unwrap()
    };
    // Calling a nil in the grader's own function: the teacher's bug, `lab grade` exits 1.
    let d = lab_copy("bug", "grade.lua", |t| {
        t.replace(
            "lab.expect(plc.VW0, helpers.ANSWER, \"VW0\")",
            "lab.expect(plc.VW0, helpers.answer_of(plc), \"VW0\")",
        )
    });
    let o = grade(&d);
    assert_eq!(o.status.code(), Some(1), "{}", both(&o));
    let r = &json_lines(&o)[0];
    let v = r["verdict"].as_str().unwrap();
    assert!(v.starts_with("grader error: criterion \"answer in VW0\": "), "{v}");
    assert!(v.contains("grade.lua:") && v.contains("attempt to call a nil value (field 'answer_of')"), "{v}");
    // Indexing a nil in a lab module the grader calls: the teacher's too.
    std::fs::write(d.join("helpers.lua"), "local M = { ANSWER = 1234 }\nfunction M.enabled(servo) return servo.statusword & M.mask.enabled == 0x27 end\nreturn M\n").unwrap();
    std::fs::write(
        d.join("grade.lua"),
        std::fs::read_to_string(root().join("tests/lab/attacks/lab/grade.lua")).unwrap(),
    )
    .unwrap();
    let o = grade(&d);
    assert_eq!(o.status.code(), Some(1), "{}", both(&o));
    let v = json_lines(&o)[0]["verdict"].as_str().unwrap().to_string();
    assert!(v.starts_with("grader error: criterion \"drive enabled\": ") && v.contains("helpers.lua:2:"), "{v}");
    remove(&d);

    // A check the grader makes with assert or error, and a device refusing, are the student's.
    let d = lab_copy("checks", "grade.lua", |t| {
        t.replace("lab.expect(plc[\"Q0.0\"], true, \"Q0.0\")", "assert(plc[\"Q0.1\"], \"the second lamp is off\")")
            .replace(
                "lab.expect(plc.VW0, helpers.ANSWER, \"VW0\")",
                "if plc.VW0 ~= 4321 then error(\"VW0 is not 4321\") end",
            )
            .replace(
                "lab.expect(helpers.enabled(servo), true, \"the drive's operation enabled\")",
                "servo.nosuchobject = 1",
            )
    });
    let o = grade(&d);
    assert_eq!(o.status.code(), Some(0), "{}", both(&o));
    let r = &json_lines(&o)[0];
    assert_eq!((r["verdict"].as_str(), r["points"].as_f64()), (Some("failed"), Some(1.0)), "{r}");
    let errors: Vec<&str> = r["criteria"].as_array().unwrap().iter().filter_map(|c| c["error"].as_str()).collect();
    assert_eq!(errors.len(), 3, "{r}");
    assert!(errors.iter().all(|e| !e.contains("grader error")), "{errors:?}");
    assert!(errors.iter().any(|e| e.contains("the second lamp is off")), "{errors:?}");
    remove(&d);
}

/// A lab that grants opening and closing devices (`grants` in lab.toml) still grades its own
/// machine: a submission that closes a lab device, or rebuilds the machine under the same
/// names and presets what the grader reads, gets a runtime error and no point — never 10/10,
/// and never a grader error (`lab grade` exits 0). A name that is no bench action is refused.
#[test]
fn a_granted_bench_action_never_makes_another_machine_the_graded_one() {
    let d =
        lab_copy("grants", "lab.toml", |t| t.replace("shared = [", "grants = [\"close\", \"connect\"]\nshared = ["));
    let o = plcsh()
        .current_dir(root())
        .args(["--json", "lab", "grade"])
        .arg(&d)
        .args([
            "tests/lab/attacks/submissions/machine_rebuilt.lua",
            "tests/lab/attacks/submissions/machine_close_device.lua",
            "tests/lab/attacks/submissions/machine_connect_same_name.lua",
            "tests/lab/attacks/submissions/honest_reference.lua",
        ])
        .output_retrying()
        .unwrap();
    assert_eq!(o.status.code(), Some(0), "{}", both(&o));
    let lines = json_lines(&o);
    for r in &lines[..3] {
        assert_eq!(r["points"].as_f64(), Some(0.0), "{r}");
        let v = r["verdict"].as_str().unwrap();
        assert!(v.starts_with("runtime error: ") && v.contains("closed or replaced the lab's device"), "{r}");
    }
    assert_eq!((lines[3]["verdict"].as_str(), lines[3]["points"].as_f64()), (Some("passed"), Some(10.0)));
    remove(&d);
    let d = lab_copy("grants_bad", "lab.toml", |t| t.replace("shared = [", "grants = [\"sim faultz\"]\nshared = ["));
    let o = plcsh().args(["lab", "check"]).arg(&d).output_retrying().unwrap();
    assert_eq!(o.status.code(), Some(2), "{}", both(&o));
    assert!(
        both(&o).contains("grants = [\"sim faultz\"]") && both(&o).contains("did you mean \"sim fault"),
        "{}",
        both(&o)
    );
    remove(&d);
}

/// Symlinks a submission brings along (made here: a checkout on Windows has none): a link to
/// the reference as the submission (relative and absolute), a folder whose `main.lua` links
/// there, a folder with a link to the lab folder or a module that links to the reference, and
/// an IL program that is a link. Each is refused with a verdict saying so; none is graded.
#[cfg(unix)]
#[test]
fn symlinks_in_a_submission_lead_nowhere() {
    let lab = lab_copy("links", "", |t| t.to_string());
    let top = lab.parent().unwrap().to_path_buf();
    let subs = top.join("subs");
    std::fs::create_dir_all(&subs).unwrap();
    let link = |to: &Path, at: &Path| std::os::unix::fs::symlink(to, at).unwrap();
    link(Path::new("../lab/reference.lua"), &subs.join("relative.lua"));
    link(&lab.join("reference.lua"), &subs.join("absolute.lua"));
    std::fs::write(lab.join("reference.il"), "LD SM0.0\n= Q0.0\nMOVW 1234, VW0\n").unwrap();
    link(&lab.join("reference.il"), &subs.join("program.il"));
    std::fs::create_dir_all(subs.join("main_link")).unwrap();
    link(&lab.join("reference.lua"), &subs.join("main_link/main.lua"));
    link(&lab.join("reference.lua"), &top.join("elsewhere.lua"));
    std::fs::create_dir_all(top.join("folder_target")).unwrap();
    link(&lab.join("reference.lua"), &top.join("folder_target/main.lua"));
    link(&top.join("folder_target"), &subs.join("folder_link"));
    let tries =
        [("module", "require(\"ref\")"), ("lab_folder", "dofile(\"subs/linked_lab_folder/lab/reference.lua\")")];
    for (name, code) in tries {
        let sub = subs.join(format!("linked_{name}"));
        std::fs::create_dir_all(&sub).unwrap();
        link(&lab, &sub.join("lab"));
        link(&lab.join("reference.lua"), &sub.join("ref.lua"));
        std::fs::write(sub.join("main.lua"), format!("{code}\n")).unwrap();
    }
    let o = plcsh()
        .current_dir(&top)
        .args(["--json", "lab", "grade", "lab", "subs", "--jobs", "2"])
        .output_retrying()
        .unwrap();
    let lines = json_lines(&o);
    let want = ["absolute", "folder_link", "linked_lab_folder", "linked_module", "main_link", "program", "relative"];
    assert_eq!(lines.len(), want.len() + 1, "{}", both(&o));
    let got: Vec<&str> = lines[..want.len()].iter().map(|r| r["student"].as_str().unwrap()).collect();
    assert_eq!(got, want, "{}", both(&o));
    for r in &lines[..want.len()] {
        assert_eq!(r["points"].as_f64(), Some(0.0), "{r}");
        let v = r["verdict"].as_str().unwrap();
        assert!(v.starts_with("refused: ") && v.contains("is a symbolic link"), "{r}");
    }
    remove(&lab);
}
