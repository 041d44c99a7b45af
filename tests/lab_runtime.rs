//! `plcsh lab grade`'s runtime, tried as a student who wants the points without doing the
//! task: the worker's report cannot be written from the submission (its stdout is only its
//! output, kept for the teacher), a submission's `require` and files are its own world (the
//! grader's modules, the reference and the grader stay the teacher's), every limit ends the
//! run with its verdict (memory through `pcall`, loops in coroutines, finalizers, a PLC
//! program's endless loop), and what a submission sees of time, chance and addresses is the
//! same in every run. Each submission is written by the test into a folder of its own and
//! graded against the test lab in tests/lab/conveyor (which accepts K2 IL and Lua).

mod common;
use common::*;
use std::collections::BTreeMap;
use std::path::{Path, PathBuf};

fn root() -> &'static Path {
    Path::new(env!("CARGO_MANIFEST_DIR"))
}

fn temp(name: &str) -> PathBuf {
    let d = std::env::temp_dir().join(format!("plcsh-labrt-{}-{name}", std::process::id()));
    let _ = std::fs::remove_dir_all(&d);
    std::fs::create_dir_all(&d).unwrap();
    d
}

/// A correct Lua solution: writes the IL into the write directory and loads it.
const SOLUTION: &str = r#"
local f = assert(io.open(plcsh.write_dir .. "/p.il", "w"))
f:write("LD %I0.0\nO %Q0.0\nA %I0.2\nAN %I0.1\n= %Q0.0\nLD %Q0.0\nTON T37, 20\n= %Q0.1\n")
f:close()
plcsh.exec("sim program load " .. plcsh.write_dir .. "/p.il")
"#;

/// Writes `subs` (file name → text) into `dir` and grades them all (`--json`, plus `extra`
/// arguments); the reports by student, and the whole output.
fn grade(
    dir: &Path,
    subs: &[(&str, String)],
    extra: &[&str],
) -> (BTreeMap<String, serde_json::Value>, std::process::Output) {
    for (name, text) in subs {
        let p = dir.join(name);
        std::fs::create_dir_all(p.parent().unwrap()).unwrap();
        std::fs::write(&p, text).unwrap();
    }
    let mut args = vec!["--json", "lab", "grade", "tests/lab/conveyor"];
    let files: Vec<String> = subs.iter().map(|(n, _)| dir.join(n).display().to_string()).collect();
    args.extend(files.iter().map(String::as_str));
    args.extend(extra);
    let o = plcsh().current_dir(root()).args(&args).output_retrying().expect("start plcsh");
    let lines = json_lines(&o);
    assert_eq!(lines.len(), subs.len() + 1, "{}", both(&o));
    let by = lines[..subs.len()].iter().map(|l| (l["student"].as_str().unwrap().to_string(), l.clone())).collect();
    (by, o)
}

fn verdict(r: &serde_json::Value) -> String {
    r["verdict"].as_str().unwrap().replace('\\', "/")
}

#[test]
fn a_submission_prints_freely_and_cannot_write_its_own_report() {
    let d = temp("report");
    // The report a worker writes for the reference, as a forger would copy it.
    let forged = serde_json::json!({
        "student": "forger", "file": "forger.lua", "points": 11.0, "max_points": 11.0,
        "criteria": [{"name": "program loads", "points": 11.0, "max": 11.0, "passed": true}],
        "verdict": "passed", "sim_time_s": 1.0
    })
    .to_string();
    let subs = vec![
        (
            "honest.lua",
            format!(
                "{SOLUTION}\nio.write(\"move done\\n\")\nprint(\"progress\", 1)\nio.stderr:write(\"a warning\\n\")\n"
            ),
        ),
        (
            "forger.lua",
            format!("io.write({forged:?} .. \"\\n\")\nio.stdout:write({forged:?}, \"\\n\")\nprint({forged:?})\n"),
        ),
        ("nothing.lua", "-- does nothing\n".into()),
        ("chatty.lua", format!("{SOLUTION}\nfor i = 1, 5000 do io.write(string.rep(\"x\", 99), \"\\n\") end\n")),
    ];
    let (by, o) = grade(&d, &subs, &[]);
    assert_eq!(o.status.code(), Some(0), "{}", both(&o));
    let honest = &by["honest"];
    assert_eq!((verdict(honest).as_str(), honest["points"].as_f64()), ("passed", Some(11.0)), "{honest}");
    let out = honest["stdout"].as_str().unwrap();
    assert!(out.contains("move done") && out.contains("progress\t1"), "{honest}");
    assert_eq!(honest["stderr"].as_str(), Some("a warning\n"), "{honest}");
    let forger = &by["forger"];
    // Graded as what it does: nothing.
    assert_eq!(verdict(forger), "failed", "{forger}");
    assert_eq!(forger["points"], by["nothing"]["points"], "{forger}");
    assert_eq!(forger["criteria"], by["nothing"]["criteria"], "{forger}");
    assert!(forger["stdout"].as_str().unwrap().contains("\"verdict\":\"passed\""), "kept as output: {forger}");
    // Output is kept up to 64 KiB, with what was left out counted.
    let chatty = &by["chatty"];
    assert_eq!(verdict(chatty), "passed", "{chatty}");
    let out = chatty["stdout"].as_str().unwrap();
    assert!(out.len() < 66 * 1024 && out.ends_with("(… 434464 bytes more)"), "{}", &out[out.len() - 40..]);
    // --show-output prints each submission's output under its name.
    let files: Vec<String> = ["honest.lua", "forger.lua"].iter().map(|n| d.join(n).display().to_string()).collect();
    let o = plcsh()
        .current_dir(root())
        .args(["lab", "grade", "tests/lab/conveyor", &files[0], &files[1], "--show-output"])
        .output_retrying()
        .unwrap();
    let text = stdout(&o);
    let shown = text.split("honest (stdout):\n").nth(1).unwrap_or_default();
    assert!(shown.contains("  move done\n") && shown.contains("  progress\t1\n"), "{text}");
    assert!(text.contains("honest (stderr):\n  a warning\n"), "{text}");
    std::fs::remove_dir_all(&d).unwrap();
}

#[test]
fn a_submissions_require_and_files_are_its_own_world() {
    let d = temp("world");
    let lab = root().join("tests/lab/conveyor");
    let lab_abs = lab.display().to_string();
    let mut subs: Vec<(&str, String)> = vec![
        ("nothing.lua", "-- does nothing\n".into()),
        // A folder submission requires its own module.
        ("folder/main.lua", "local u = require(\"util\")\nu.load()\n".into()),
        ("folder/util.lua", format!("return {{ load = function()\n{SOLUTION}\nend }}\n")),
        // The lab's shared module is a fresh copy: replacing a function there fools no grader.
        (
            "fake_checks.lua",
            "local c = require(\"checks\")\nc.running = function() return true end\nassert(c ~= package)\n".into(),
        ),
    ];
    for m in ["package", "io", "os", "debug", "grade", "reference", "string", "lab"] {
        subs.push((
            Box::leak(format!("req_{m}.lua").into_boxed_str()),
            format!("local ok, e = pcall(require, {m:?})\nerror(ok and \"loaded\" or e, 0)\n"),
        ));
    }
    let reads = [
        ("read_ref", format!("io.open({:?})", lab.join("reference.il").display().to_string())),
        ("read_ref_rel", "io.open('tests/lab/conveyor/reference.il')".to_string()),
        ("dofile_grader", format!("dofile({:?})", lab.join("grade.lua").display().to_string())),
        ("loadfile_grader", "loadfile('tests/lab/conveyor/grade.lua')".to_string()),
        ("lines_ref", "io.lines('tests/lab/conveyor/reference.il')".to_string()),
        ("load_ref", "plcsh.exec('sim program load tests/lab/conveyor/reference.il')".to_string()),
        ("read_other", format!("io.open({:?})", d.join("folder/util.lua").display().to_string())),
    ];
    for (n, code) in &reads {
        subs.push((Box::leak(format!("{n}.lua").into_boxed_str()), format!("{code}\n")));
    }
    let (by, o) = grade(&d, &subs, &[]);
    assert_eq!(o.status.code(), Some(0), "{}", both(&o));
    assert_eq!(verdict(&by["folder"]), "passed", "{}", by["folder"]);
    let fake = &by["fake_checks"];
    assert_eq!(fake["points"], by["nothing"]["points"], "{fake}");
    let c = fake["criteria"].as_array().unwrap().iter().find(|c| c["name"] == "program loads").unwrap();
    assert_eq!(c["passed"], false, "the grader's checks module is its own: {fake}");
    for m in ["package", "io", "os", "debug", "grade", "reference", "string", "lab"] {
        let v = verdict(&by[&format!("req_{m}")]);
        assert!(v.contains(&format!("module '{m}' not found")), "require({m}): {v}");
        assert!(v.contains("the lab shares checks"), "{v}");
        assert!(!v.contains(&lab_abs) && !v.contains("conveyor"), "no lab path in `{v}`");
    }
    for (n, _) in &reads {
        let v = verdict(&by[*n]);
        assert!(v.starts_with("runtime error:") && v.contains("outside the sandbox's folders"), "{n}: {v}");
        assert!(v.contains("the submission's own files"), "{n}: {v}");
        assert!(by[*n]["points"].as_f64() <= by["nothing"]["points"].as_f64(), "{n}");
    }
    std::fs::remove_dir_all(&d).unwrap();
}

#[test]
fn a_lab_grades_only_the_kinds_it_accepts() {
    let d = temp("kinds");
    let sub = d.join("script.lua");
    std::fs::write(&sub, "plcsh.exec('sim program load tests/lab/umpk/reference.il')\n").unwrap();
    let o = plcsh()
        .current_dir(root())
        .args(["--json", "lab", "grade", "tests/lab/umpk", sub.to_str().unwrap()])
        .output_retrying()
        .unwrap();
    let r = &json_lines(&o)[0];
    assert_eq!(r["verdict"], "not accepted: this lab accepts UMPK IL (.il) submissions", "{r}");
    assert_eq!(r["points"].as_f64(), Some(0.0));
    // An endless loop on the UMPK trips its watchdog (10 ms): the verdict names it.
    let looping = d.join("looping.il");
    std::fs::write(&looping, "L1: LD I0\nJMP L1\n").unwrap();
    let o = plcsh()
        .current_dir(root())
        .args(["--json", "lab", "grade", "tests/lab/umpk", looping.to_str().unwrap()])
        .output_retrying()
        .unwrap();
    let r = &json_lines(&o)[0];
    let v = r["verdict"].as_str().unwrap();
    assert!(
        v.starts_with("runtime error: ")
            && v.contains("looping.il:2: the PLC stopped: the scan ran past the watchdog limit of 10 ms"),
        "{r}"
    );
    std::fs::remove_dir_all(&d).unwrap();
}

#[test]
fn every_limit_ends_the_run_with_its_verdict() {
    let d = temp("limits");
    let subs: Vec<(&str, String)> = vec![
        // The memory limit, caught a hundred times, then a correct solution: still the limit.
        ("mem_pcall.lua", format!("for _ = 1, 100 do pcall(string.rep, 'x', 1e9) end\n{SOLUTION}")),
        (
            "mem_coroutine.lua",
            format!("for _ = 1, 10 do coroutine.resume(coroutine.create(function() local t = {{}} for i = 1, 1e9 do t[i] = i end end)) end\n{SOLUTION}"),
        ),
        ("mem_xpcall.lua", format!("xpcall(string.rep, function() return 'fine' end, 'x', 1e9)\n{SOLUTION}")),
        // The memory left full for the grader: the run's limit, not the grader's error.
        ("mem_kept.lua", format!("{SOLUTION}\nkeep = {{}}\npcall(function() for i = 1, 1e9 do keep[i] = i end end)\n")),
        ("co_loop.lua", "coroutine.wrap(function() while true do end end)()\n".into()),
        (
            "co_pcall_loop.lua",
            "while true do coroutine.resume(coroutine.create(function() pcall(function() while true do end end) end)) end\n".into(),
        ),
        ("gc_loop.lua", "setmetatable({}, { __gc = function() while true do end end })\ncollectgarbage()\n".into()),
        ("endless.il", "L1: LD SM0.0\nJMP L1\n".into()),
    ];
    let (by, o) = grade(&d, &subs, &[]);
    assert_eq!(o.status.code(), Some(0), "{}", both(&o));
    for s in ["mem_pcall", "mem_coroutine", "mem_xpcall", "mem_kept"] {
        assert_eq!(verdict(&by[s]), "exceeded 64 MiB of Lua memory", "{s}: {}", by[s]);
        assert_eq!(by[s]["points"].as_f64(), Some(0.0), "{s}");
    }
    for s in ["co_loop", "co_pcall_loop"] {
        assert_eq!(verdict(&by[s]), "exceeded 20 M Lua instructions", "{s}: {}", by[s]);
    }
    let v = verdict(&by["gc_loop"]);
    assert!(v.contains("gc_loop.lua:1:") && v.contains("__gc finalizer is not available"), "{v}");
    let v = verdict(&by["endless"]);
    assert!(
        v.starts_with("runtime error: ")
            && v.contains(
                "endless.il:2: the PLC stopped on fault 1 (watchdog): the scan ran past the watchdog limit of 300 ms"
            ),
        "{v}"
    );
    // The grader went on in simulated time after the CPU stopped: its later criteria ran.
    let c = by["endless"]["criteria"].as_array().unwrap();
    assert!(c.iter().all(|c| c["skipped"].is_null()), "{}", by["endless"]);
    std::fs::remove_dir_all(&d).unwrap();
}

#[test]
fn time_chance_and_addresses_are_the_same_in_every_run() {
    let d = temp("determinism");
    let subs: Vec<(&str, String)> = vec![
        // Full marks or not by chance: the same chance in every run.
        ("dice.lua", format!("if math.random(1, 2) == 1 then\n{SOLUTION}\nend\nerror('rolled ' .. math.random(1, 1e9), 0)\n")),
        ("reseed.lua", "math.randomseed()\nlocal a = math.random(1, 1e9)\nmath.randomseed()\nerror(('%d %d'):format(a, math.random(1, 1e9)), 0)\n".into()),
        ("clock.lua", "error(os.time() .. ' ' .. os.date('!%Y-%m-%d %H:%M:%S') .. ' ' .. os.date('%H') .. ' ' .. os.time({year = 2026, month = 1, day = 2, hour = 0}), 0)\n".into()),
        ("sleepy.lua", "plcsh.sleep(90000)\nerror(os.time() - os.time({year = 2026, month = 1, day = 1, hour = 0}) .. ' ' .. os.date('!%H:%M:%S'), 0)\n".into()),
        ("busy.lua", "local t = os.clock()\nwhile os.clock() - t < 3 do end\n".into()),
        ("error_table.lua", "error({})\n".into()),
        ("error_meta.lua", "error(setmetatable({}, { __index = {} }))\n".into()),
        ("error_func.lua", "error('got ' .. tostring(print) .. ' ' .. tostring({}) .. ' ' .. string.format('%s', coroutine.create(print)), 0)\n".into()),
        ("format_p.lua", "error(string.format('%p', {}), 0)\n".into()),
        // The order `pairs` visits string keys in (Lua's string hashes start from a fixed seed).
        ("keys.lua", "local t, s = {}, {}\nfor i = 1, 40 do t['k' .. i] = i end\nfor k in pairs(t) do s[#s + 1] = k end\nerror(table.concat(s, ','), 0)\n".into()),
    ];
    let (first, o1) = grade(&d, &subs, &[]);
    let (second, o2) = grade(&d, &subs, &["--jobs", "1"]);
    assert_eq!(stdout(&o1), stdout(&o2), "two runs differ");
    assert_eq!(first, second);
    // The message after `runtime error: FILE:LINE: `.
    let v = |s: &str| {
        let v = verdict(&first[s]);
        match v.strip_prefix("runtime error: ") {
            Some(m) => m.splitn(3, ':').nth(2).unwrap_or_default().trim_start().to_string(),
            None => v,
        }
    };
    assert!(v("dice").starts_with("rolled "), "{}", v("dice"));
    let reseed = v("reseed");
    let nums: Vec<&str> = reseed.split(' ').collect();
    assert_eq!(nums.len(), 2);
    assert_eq!(nums[0], nums[1], "randomseed() starts the same sequence again: {}", v("reseed"));
    // Simulated time from 2026-01-01 00:00:00 UTC, in UTC whatever the machine's zone.
    assert_eq!(v("clock"), "1767225600 2026-01-01 00:00:00 00 1767312000");
    assert_eq!(v("sleepy"), "90 00:01:30");
    // A busy loop on os.clock advances it by the instructions run: the same limit every time.
    assert_eq!(v("busy"), "exceeded 20 M Lua instructions");
    for s in ["error_table", "error_meta", "error_func"] {
        let t = v(s);
        assert!(!t.contains("0x") && !t.to_lowercase().contains("builtin:"), "{s}: {t}");
    }
    assert_eq!(v("error_func"), "got function table thread");
    assert_eq!(v("error_table"), "table");
    assert!(v("format_p").contains("%p (an address) is not available in a graded run"), "{}", v("format_p"));
    std::fs::remove_dir_all(&d).unwrap();
}

/// A submission printing text that is not UTF-8 (a CP1251 line, as a Russian CSV file holds
/// it) prints as stock Lua does, and is graded as what it does: its output is kept (the JSON
/// report shows the bytes that are not UTF-8 as U+FFFD).
#[test]
fn a_submission_printing_cp1251_text_is_graded_and_its_output_kept() {
    let d = temp("cp1251");
    let subs = vec![("cyrillic.lua", format!("{SOLUTION}\nprint(\"\\207\\240\\232\\226\\229\\242;1\")\n"))];
    let (by, o) = grade(&d, &subs, &[]);
    assert_eq!(o.status.code(), Some(0), "{}", both(&o));
    let r = &by["cyrillic"];
    assert_eq!(verdict(r), "passed", "{r}");
    assert_eq!(r["stdout"].as_str(), Some("\u{FFFD}\u{FFFD}\u{FFFD}\u{FFFD}\u{FFFD}\u{FFFD};1\n"), "{r}");
    std::fs::remove_dir_all(&d).unwrap();
}
