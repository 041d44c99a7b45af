//! `plcsh lab`: the test lab in tests/lab/conveyor (a K2 and a drive, wired; a start snapshot;
//! a grader whose reference runs 10 simulated minutes) graded against tests/lab/submissions —
//! correct solutions in several styles and planted mistakes — with every verdict as expected,
//! the teacher's files unchanged, and two runs giving the same bytes. Then `lab new` / `lab
//! check`, and the sandbox's rules one by one (an attempt that must fail, one that must work).

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

/// Every file under `dir` with its bytes.
fn files(dir: &Path) -> BTreeMap<PathBuf, Vec<u8>> {
    let mut out = BTreeMap::new();
    for e in std::fs::read_dir(dir).unwrap() {
        let p = e.unwrap().path();
        if p.is_dir() {
            out.extend(files(&p));
        } else {
            out.insert(p.clone(), std::fs::read(&p).unwrap());
        }
    }
    out
}

fn temp(name: &str) -> PathBuf {
    let d = std::env::temp_dir().join(format!("plcsh-labtest-{}-{name}", std::process::id()));
    let _ = std::fs::remove_dir_all(&d);
    std::fs::create_dir_all(&d).unwrap();
    d
}

/// What each submission must get: (student, points, what the verdict says).
const EXPECTED: &[(&str, f64, &str)] = &[
    // Correct, in several styles.
    ("ref_copy", 11.0, "passed"),
    ("set_reset", 11.0, "passed"),
    ("markers", 11.0, "passed"),
    ("time_literal", 11.0, "passed"),
    ("kim", 11.0, "passed"),
    ("lua_writes_il", 11.0, "passed"),
    ("lua_load_env", 11.0, "passed"),
    ("uses_lab_module", 11.0, "passed"),
    ("replace_plcsh", 11.0, "passed"),
    // Wrong logic: graded, with the criterion that caught it.
    ("starter_as_is", 6.0, "failed"),
    ("wrong_timer", 9.0, "failed"),
    ("silent_wrong", 9.0, "failed"),
    ("no_interlock", 9.0, "failed"),
    // Broken programs: the student's file and line.
    ("il_syntax_error", 0.0, "runtime error: tests/lab/submissions/il_syntax_error.il:3:1: unknown instruction FROB"),
    ("lua_syntax_error", 0.0, "runtime error: tests/lab/submissions/lua_syntax_error.lua:1:"),
    (
        "lua_runtime_error",
        0.0,
        "runtime error: tests/lab/submissions/lua_runtime_error.lua:3: attempt to index a nil value (local 'settings')",
    ),
    // Limits, named.
    ("infinite_loop", 0.0, "exceeded 20 M Lua instructions"),
    ("pcall_loop", 0.0, "exceeded 20 M Lua instructions"),
    ("never_returns", 0.0, "exceeded 11 simulated minutes"),
    ("sim_step_far", 0.0, "exceeded 11 simulated minutes"),
    ("memory_bomb", 0.0, "exceeded 64 MiB of Lua memory"),
    // The sandbox.
    ("os_execute", 0.0, "os_execute.lua:1: os.execute is not available in a sandboxed run"),
    ("io_popen", 0.0, "io_popen.lua:1: io.popen is not available in a sandboxed run"),
    ("read_outside", 0.0, "read_outside.lua:1: reading Cargo.toml is outside the sandbox's folders"),
    ("write_grader", 0.0, "write_grader.lua:2: attempt to concatenate a nil value"),
    ("named_snapshot", 0.0, "the named snapshot `lab1` lives in the user's data directory"),
    ("tcp_device", 0.0, "tcp://127.0.0.1:502 is a real device: a sandboxed run opens simulated devices only"),
    ("replace_criterion", 0.0, "replace_criterion.lua:1: attempt to index a nil value (global 'lab')"),
    ("require_outside", 0.0, "require_outside.lua:1: module 'socket' not found"),
    ("loadlib", 0.0, "loadlib.lua:1: attempt to index a nil value (global 'package')"),
    ("debug_library", 0.0, "debug_library.lua:1: attempt to call a nil value (field 'getinfo')"),
    ("string_metatable", 0.0, "string_metatable.lua:1: attempt to index a boolean value"),
    ("binary_chunk", 0.0, "binary_chunk.lua:1: attempt to load a binary chunk"),
];

#[test]
fn the_test_lab_grades_every_submission_as_expected_twice_alike() {
    let lab = root().join("tests/lab/conveyor");
    let before = files(&lab);
    let junit = temp("junit").join("results.xml");
    let args =
        ["--json", "lab", "grade", "tests/lab/conveyor", "tests/lab/submissions", "--junit", junit.to_str().unwrap()];
    let first = in_root(&args);
    assert_eq!(first.status.code(), Some(0), "{}", both(&first));
    let lines = json_lines(&first);
    assert_eq!(lines.len(), EXPECTED.len() + 1, "one object per submission and a summary");
    for l in &lines {
        assert_eq!(l["ok"], true, "{l}");
        assert_eq!((&l["cmd"], &l["sub"]), (&serde_json::json!("lab"), &serde_json::json!("grade")), "{l}");
    }
    let by_student: BTreeMap<&str, &serde_json::Value> =
        lines[..EXPECTED.len()].iter().map(|l| (l["student"].as_str().unwrap(), l)).collect();
    for (student, points, verdict) in EXPECTED {
        let r = by_student.get(student).unwrap_or_else(|| panic!("{student} was graded"));
        // A path in a verdict has the platform's separator after the folder given (`submissions\x.il` on Windows).
        let v = r["verdict"].as_str().unwrap().replace('\\', "/");
        assert!(v.contains(verdict), "{student}: verdict `{v}`, expected `{verdict}`");
        assert_eq!(r["points"].as_f64(), Some(*points), "{student}: {r}");
        assert_eq!(r["max_points"].as_f64(), Some(11.0), "{student}");
    }
    // A failed criterion says what it expected, what it got and when (simulated time).
    let why = |student: &str, criterion: &str| -> serde_json::Value {
        by_student[student]["criteria"].as_array().unwrap().iter().find(|c| c["name"] == criterion).unwrap().clone()
    };
    let c = why("wrong_timer", "ready lamp after 2 s");
    assert_eq!(
        (c["what"].as_str(), c["expected"].as_str(), c["got"].as_str()),
        (Some("Q0.1 after 2 s"), Some("true"), Some("false"))
    );
    assert_eq!(c["at_s"].as_f64(), Some(2.2));
    let c = why("silent_wrong", "ready lamp after 2 s");
    assert_eq!(
        (c["what"].as_str(), c["got"].as_str(), c["at_s"].as_f64()),
        (Some("Q0.1 before 2 s"), Some("true"), Some(1.9))
    );
    let c = why("no_interlock", "no start while the drive is disabled");
    assert_eq!(c["what"].as_str(), Some("Q0.0 after start with the drive disabled"));
    // Limits in simulated time: the budget, whatever the machine's load.
    assert_eq!(by_student["never_returns"]["sim_time_s"].as_f64(), Some(660.0));
    assert_eq!(by_student["ref_copy"]["sim_time_s"].as_f64(), Some(596.54));
    let summary = &lines[EXPECTED.len()]["summary"];
    assert_eq!(summary["submissions"], EXPECTED.len());
    assert_eq!(summary["passed"], 9);
    assert_eq!(summary["grader_errors"], 0);

    // The teacher's files are as they were; nothing was written in the user's data directory.
    assert!(before == files(&lab), "the lab folder changed");
    let home = std::env::temp_dir().join(format!("plcsh-test-home-{}", std::process::id()));
    assert!(!home.join("data/plcsh/snapshots/lab1.json").exists());
    assert!(!Path::new("/tmp/plcsh-lab-escaped").exists());

    // JUnit: a suite per student, a failure per failed criterion.
    let xml = std::fs::read_to_string(&junit).unwrap();
    assert!(xml.starts_with("<?xml"), "{xml}");
    assert_eq!(xml.matches("<testsuite ").count(), EXPECTED.len());
    assert!(xml.contains("<testcase classname=\"wrong_timer\" name=\"ready lamp after 2 s\"><failure message=\"Q0.1 after 2 s: expected true, got false at 2.2 s (failed)\"/>"), "{xml}");

    // The same bytes again, with one worker this time.
    let second = in_root(&["--json", "lab", "grade", "tests/lab/conveyor", "tests/lab/submissions", "--jobs", "1"]);
    assert_eq!(stdout(&first), stdout(&second), "two runs differ");
}

#[test]
fn lab_new_writes_a_lab_that_passes_check_and_check_catches_a_wrong_reference() {
    let d = temp("new");
    let lab = d.join("conveyor");
    let o = plcsh().args(["lab", "new", lab.to_str().unwrap()]).output_retrying().unwrap();
    assert!(o.status.success(), "{}", both(&o));
    let o = plcsh().args(["lab", "check", lab.to_str().unwrap()]).output_retrying().unwrap();
    assert!(o.status.success(), "{}", both(&o));
    assert!(stdout(&o).contains("the reference solution gets 10/10 points"), "{}", stdout(&o));
    // The starter is not a solution: grading it gives some criteria, not all.
    let o = plcsh()
        .args(["--json", "lab", "grade", lab.to_str().unwrap(), lab.join("starter.il").to_str().unwrap()])
        .output_retrying()
        .unwrap();
    let r = &json_lines(&o)[0];
    assert_eq!(r["verdict"], "failed", "{r}");
    // `lab new` refuses an existing folder.
    let o = plcsh().args(["lab", "new", lab.to_str().unwrap()]).output_retrying().unwrap();
    assert!(!o.status.success() && both(&o).contains("already exists"), "{}", both(&o));
    // A wrong reference fails the check, naming the criterion.
    let text = std::fs::read_to_string(lab.join("reference.il")).unwrap().replace("T37, 20", "T37, 25");
    std::fs::write(lab.join("reference.il"), text).unwrap();
    let o = plcsh().args(["lab", "check", lab.to_str().unwrap()]).output_retrying().unwrap();
    assert_eq!(o.status.code(), Some(1), "{}", both(&o));
    assert!(stdout(&o).contains("Q0.1 after 2 s: expected true, got false at 2.2 s"), "{}", stdout(&o));
    let o = plcsh().args(["--json", "lab", "check", lab.to_str().unwrap()]).output_retrying().unwrap();
    let j = &json_lines(&o)[0];
    assert_eq!((j["ok"].as_bool(), j["cmd"].as_str()), (Some(false), Some("lab")), "{j}");
    std::fs::remove_dir_all(&d).unwrap();
}

#[test]
fn a_bad_lab_toml_is_refused_naming_the_key() {
    let d = temp("bad");
    std::fs::write(d.join("g.lua"), "").unwrap();
    std::fs::write(d.join("r.il"), "").unwrap();
    std::fs::write(
        d.join("lab.toml"),
        "title = \"x\"\nreference = \"r.il\"\ngrader = \"g.lua\"\n[devices]\nplc = \"tcp://192.0.2.1:502\"\n",
    )
    .unwrap();
    let o = plcsh().args(["lab", "check", d.to_str().unwrap()]).output_retrying().unwrap();
    assert_eq!(o.status.code(), Some(2), "{}", both(&o));
    assert!(both(&o).contains("[devices] plc") && both(&o).contains("real device"), "{}", both(&o));
    std::fs::remove_dir_all(&d).unwrap();
}

/// One rule of the sandbox: a script that must fail with `refusal`, and one that must work.
struct Rule {
    name: &'static str,
    denied: &'static str,
    refusal: &'static str,
    allowed: &'static str,
}

/// The rules of docs/teaching.md's table, row by row (its "the grader" row is the test lab's
/// `replace_criterion` and `replace_plcsh` submissions above).
const RULES: &[Rule] = &[
    Rule {
        name: "processes",
        denied: "os.execute('true')",
        refusal: "os.execute is not available in a sandboxed run",
        allowed: "assert(os.time() > 0)",
    },
    Rule {
        name: "pipes",
        denied: "io.popen('ls')",
        refusal: "io.popen is not available in a sandboxed run",
        allowed: "io.write('')",
    },
    Rule {
        name: "deleting files",
        denied: "os.remove('x')",
        refusal: "os.remove is not available",
        allowed: "assert(string.rep('a', 3) == 'aaa')",
    },
    Rule {
        name: "C modules",
        denied: "require('lfs')",
        refusal: "module 'lfs' not found",
        allowed: "local c = require('commission'); assert(c)",
    },
    Rule {
        name: "lab modules",
        denied: "require('nowhere')",
        refusal: "module 'nowhere' not found",
        allowed: "assert(require('helper').answer == 42)",
    },
    Rule {
        name: "debug library",
        denied: "debug.getinfo(1)",
        refusal: "field 'getinfo'",
        allowed: "assert(debug.traceback('here'):find('here') and type(utf8.char(65)) == 'string')",
    },
    Rule {
        name: "reading outside",
        denied: "io.open('/etc/hostname')",
        refusal: "outside the sandbox's folders",
        allowed: "assert(io.open(arg[0]):read('l'))",
    },
    Rule {
        name: "writing outside",
        denied: "io.open('elsewhere.txt', 'w')",
        refusal: "outside",
        allowed: "assert(io.open(plcsh.write_dir .. '/out.txt', 'w')):write('x')",
    },
    Rule {
        name: "real devices",
        denied: "plcsh.connect('tcp://127.0.0.1:PORT', 'real')",
        refusal: "is a real device: a sandboxed run opens simulated devices only",
        allowed: "local d = plcsh.connect('sim:K205-16DT', 'k2'); d.VW0 = 4242; assert(d.VW0 == 4242)",
    },
    Rule {
        name: "real devices by command",
        denied: "plcsh.exec('connect r umpk:/dev/ttyS0')",
        refusal: "is a real device",
        allowed: "plcsh.exec('connect u sim-umpk:UMPK16')",
    },
    Rule {
        name: "named snapshots",
        denied: "plcsh.snapshot_save('lab1')",
        refusal: "named snapshot `lab1`",
        allowed:
            "plcsh.snapshot_save(plcsh.write_dir .. '/s.json'); plcsh.snapshot_restore(plcsh.write_dir .. '/s.json')",
    },
    Rule {
        name: "snapshot paths",
        denied: "plcsh.exec('sim snapshot save ./grade.json')",
        refusal: "outside",
        allowed: "plcsh.exec('sim snapshot save ' .. plcsh.write_dir .. '/t.json')",
    },
    Rule {
        name: "command files",
        denied: "plcsh.exec('sim program load /etc/hostname')",
        refusal: "outside the sandbox's folders",
        allowed: "plcsh.exec('sim program load ' .. plcsh.write_dir .. '/../prog.il')",
    },
    Rule {
        name: "load",
        denied: "load(string.dump(function() end))()",
        refusal: "attempt to",
        allowed: "assert(load('return plcsh ~= nil and string.format(\"%d\", 1)')() == '1')",
    },
    Rule {
        name: "loadfile",
        denied: "loadfile('/etc/hostname')",
        refusal: "outside the sandbox's folders",
        allowed: "assert(loadfile(arg[0]))",
    },
    Rule {
        name: "commands",
        denied: "plcsh.exec('lab new elsewhere')",
        refusal: "`lab` is not available in a sandboxed run",
        allowed: "plcsh.exec('set VW0=7'); assert(plcsh.exec('get VW0').values[1].value == 7)",
    },
];

#[test]
fn every_sandbox_rule_refuses_one_attempt_and_allows_another() {
    // A loopback server that must never see a connection.
    let listener = std::net::TcpListener::bind("127.0.0.1:0").unwrap();
    listener.set_nonblocking(true).unwrap();
    let port = listener.local_addr().unwrap().port().to_string();
    let d = temp("rules");
    let out = d.join("out");
    std::fs::create_dir_all(&out).unwrap();
    std::fs::write(d.join("helper.lua"), "return { answer = 42 }\n").unwrap();
    std::fs::write(d.join("prog.il"), "LD %I0.0\n= %Q0.0\n").unwrap();
    // The program lies beside the write directory, in the script's folder (readable).
    for r in RULES {
        for (code, must_fail) in [(r.denied.replace("PORT", &port), true), (r.allowed.to_string(), false)] {
            let script = d.join(format!("{}.lua", r.name.replace(' ', "_")));
            std::fs::write(&script, format!("{code}\nprint('reached the end')\n")).unwrap();
            let o = plcsh()
                .current_dir(&d)
                .args(["--time", "stepped", "run", "--sandbox", "--write-dir", "out"])
                .arg(&script)
                .output_retrying()
                .unwrap();
            let text = both(&o);
            if must_fail {
                assert_eq!(o.status.code(), Some(1), "{}: `{code}` must fail: {text}", r.name);
                assert!(text.contains(r.refusal), "{}: `{code}`: {text}", r.name);
                assert!(!text.contains("reached the end"), "{}", r.name);
            } else {
                assert!(o.status.success(), "{}: `{code}` must work: {text}", r.name);
                assert!(text.contains("reached the end"), "{}: {text}", r.name);
            }
        }
    }
    // A real device given on the command line is refused before the script starts.
    let script = d.join("plain.lua");
    std::fs::write(&script, "print('reached the end')\n").unwrap();
    let o = plcsh()
        .current_dir(&d)
        .args(["--device", &format!("real=tcp://127.0.0.1:{port}"), "run", "--sandbox"])
        .arg(&script)
        .output_retrying()
        .unwrap();
    assert_eq!(o.status.code(), Some(1), "{}", both(&o));
    assert!(both(&o).contains("is a real device: a sandboxed run opens simulated devices only"), "{}", both(&o));
    assert!(!both(&o).contains("reached the end"));
    assert!(listener.accept().is_err(), "nothing connected to the loopback server");
    std::fs::remove_dir_all(&d).unwrap();
}

#[test]
fn a_umpk_il_submission_is_graded_and_its_snapshot_kept() {
    let o =
        in_root(&["--json", "lab", "grade", "tests/lab/umpk", "scripts/umpk_lab1.il", "tests/lab/umpk/wrong_delay.il"]);
    assert!(o.status.success(), "{}", both(&o));
    let lines = json_lines(&o);
    assert_eq!(lines[0]["verdict"], "passed", "{}", lines[0]);
    assert_eq!(lines[1]["verdict"], "failed", "{}", lines[1]);
    // The snapshot: a UMPK mid-timer continues exactly after a restore.
    let d = temp("umpk");
    let snap = d.join("u.json");
    let snap = snap.to_str().unwrap();
    let o = in_root(&[
        "--time",
        "stepped",
        "--device",
        "lab=sim-umpk:UMPK16",
        "-c",
        &format!("use lab; sim program load scripts/umpk_lab1.il; sim input I0=1; sim step 1s; sim snapshot save {snap}; sim step 1.5s; get Q1; sim snapshot restore {snap}; get Q1; sim step 1.5s; get Q1"),
    ]);
    assert!(o.status.success(), "{}", both(&o));
    let text = stdout(&o);
    let q1: Vec<&str> =
        text.lines().filter(|l| l.starts_with("Q1")).map(|l| l.split_whitespace().last().unwrap()).collect();
    assert_eq!(q1, ["1", "0", "1"], "{}", stdout(&o));
    // A built-in program is refused by name, never left out.
    let o = in_root(&[
        "--device",
        "lab=sim-umpk:UMPK16",
        "-c",
        &format!("use lab; umpk sim reference lab1; sim snapshot save {snap}"),
    ]);
    assert!(!o.status.success());
    assert!(
        both(&o).contains("cannot snapshot `lab`: its program `lab1 (reference)` is built into plcsh"),
        "{}",
        both(&o)
    );
    std::fs::remove_dir_all(&d).unwrap();
}
