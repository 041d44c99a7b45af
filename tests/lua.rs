//! Lua through the real binary: `plcsh run`, exit status, file:line on errors, Ctrl-C
//! running the abort handlers, the REPL's `lua`, `:` and block forms.

mod common;
use common::*;
use std::io::{BufRead, BufReader};
use std::path::PathBuf;
use std::process::Stdio;

/// Writes a script into a fresh directory and returns its path.
fn script(name: &str, code: &str) -> PathBuf {
    let dir = std::env::temp_dir().join(format!("plcsh-lua-test-{}-{name}", std::process::id()));
    std::fs::create_dir_all(&dir).unwrap();
    let p = dir.join(name);
    std::fs::write(&p, code).unwrap();
    p
}

#[test]
fn run_passes_arguments_and_exits_zero() {
    let p = script("args.lua", "print(arg[0]:match('args.lua$') ~= nil, arg[1], arg[2], select('#', ...))\n");
    let o = run(&["run", p.to_str().unwrap(), "one", "--two"], "");
    assert!(o.status.success(), "{}", stdout(&o));
    assert_eq!(stdout(&o), "true\tone\t--two\t2\n");
}

/// Everything after the script is the script's, even words that are plcsh flags; plcsh's
/// flags go before the script (`--time stepped` there sets the clock).
#[test]
fn run_gives_every_argument_after_the_script_to_the_script() {
    let p = script("args2.lua", "print(plcsh.stepped() and 'stepped' or 'wall', table.concat({...}, ' '))\n");
    let o = run(&["run", p.to_str().unwrap(), "--time", "stepped", "-v", "--json", "x"], "");
    assert!(o.status.success(), "{}", both(&o));
    assert_eq!(stdout(&o), "wall\t--time stepped -v --json x\n");
    let o = run(&["--time", "stepped", "run", p.to_str().unwrap(), "--model", "K209M"], "");
    assert!(o.status.success(), "{}", both(&o));
    assert_eq!(stdout(&o), "stepped\t--model K209M\n");
}

#[test]
fn a_runtime_error_reports_file_and_line_and_exits_1() {
    let p = script("boom.lua", "local plc = plcsh.device('plc')\nplc.VW0 = 1\nlocal t = nil\nprint(t.x)\n");
    let o = run(&["run", p.to_str().unwrap()], "");
    assert_eq!(o.status.code(), Some(1));
    let s = common::stderr(&o);
    let loc = format!("{}:4:", p.display());
    assert!(s.contains(&format!("error[script]: {loc} attempt to index a nil value")), "{s}");
    assert!(s.contains("stack traceback:") && s.contains("in main chunk"), "{s}");
}

#[test]
fn a_device_error_keeps_kind_device_operand_and_line_in_json() {
    let p = script("range.lua", "plc.VW0 = 1\n\nplc.VB2 = 300\n");
    let o = run(&["--json", "run", p.to_str().unwrap()], "");
    assert_eq!(o.status.code(), Some(1));
    let l = json_lines(&o);
    let e = &l[0]["error"];
    assert_eq!(l[0]["cmd"], "run");
    assert_eq!(e["kind"], "value");
    assert_eq!(e["device"], "plc");
    assert_eq!(e["operand"], "VB2");
    assert_eq!(e["where"], format!("{}:3", p.display()));
    assert!(e["traceback"].as_str().unwrap().contains("main chunk"));
}

#[test]
fn a_syntax_error_names_the_line() {
    let p = script("syntax.lua", "x = 1\ny = = 2\n");
    let o = run(&["run", p.to_str().unwrap()], "");
    assert_eq!(o.status.code(), Some(1));
    assert!(common::stderr(&o).contains(&format!("error[syntax]: {}:2:", p.display())), "{}", common::stderr(&o));
}

#[test]
fn device_flags_and_stepped_time_apply_to_scripts() {
    let p = script(
        "flags.lua",
        "big.VW16000 = 3\nplcsh.sleep(600000)\nprint(plcsh.stepped(), plcsh.now(), big.VW16000, big:info().model)\n",
    );
    let o = run(&["--time", "stepped", "--device", "big=sim:K209M-56DT", "run", p.to_str().unwrap()], "");
    assert!(o.status.success(), "{}", stdout(&o));
    assert_eq!(stdout(&o), "true\t600000.0\t3\tK209M-56DT\n");
}

#[test]
fn ctrl_c_during_wait_until_runs_the_abort_handlers_and_exits_non_zero() {
    let marker = std::env::temp_dir().join(format!("plcsh-abort-marker-{}", std::process::id()));
    let _ = std::fs::remove_file(&marker);
    let p = script(
        "forever.lua",
        &format!(
            "plcsh.on_abort(function(why)\n  plc.VW0 = 99\n  local f = io.open({:?}, 'w'); f:write(why, ' ', plc.VW0); f:close()\n  print('ABORT HANDLER ' .. why)\nend)\nprint('READY')\nplcsh.wait_until(function() return false end)\nprint('NOT REACHED')\n",
            marker.to_str().unwrap()
        ),
    );
    let mut child = plcsh()
        .args(["run", p.to_str().unwrap()])
        .stdin(Stdio::null())
        .stdout(Stdio::piped())
        .stderr(Stdio::piped())
        .spawn_retrying()
        .unwrap();
    let mut lines = BufReader::new(child.stdout.take().unwrap()).lines();
    // Readiness: the script is about to wait.
    let first = lines.next().unwrap().unwrap();
    assert_eq!(first, "READY");
    plcsh::core::platform::interrupt_child(&child);
    let mut rest: Vec<String> = lines.map(|l| l.unwrap()).collect();
    let mut err = String::new();
    std::io::Read::read_to_string(&mut child.stderr.take().unwrap(), &mut err).unwrap();
    rest.push(err);
    let status = child.wait().unwrap();
    assert_eq!(status.code(), Some(130), "{rest:?}");
    let text = rest.join("\n");
    assert!(text.contains("ABORT HANDLER interrupted"), "{text}");
    assert!(text.contains("error[interrupted]"), "{text}");
    assert!(!text.contains("NOT REACHED"), "{text}");
    assert_eq!(std::fs::read_to_string(&marker).unwrap(), "interrupted 99");
    let _ = std::fs::remove_file(&marker);
}

/// A line that is not UTF-8 (CP1251, as a Russian CSV file holds it) prints as its bytes, as
/// stock Lua prints it, from `plcsh run` and from the REPL's `lua`, and the run succeeds.
#[test]
fn print_of_cp1251_text_writes_its_bytes() {
    let cp1251 = b"\xCF\xF0\xE8\xE2\xE5\xF2;1\n"; // "Привет;1"
    let dir = script("cp1251.lua", "").parent().unwrap().to_path_buf();
    let csv = dir.join("line.csv");
    std::fs::write(&csv, cp1251).unwrap();
    let p = script(
        "cp1251.lua",
        "local f = assert(io.open(arg[1], 'rb'))\nlocal line = f:read('l')\nf:close()\nprint(line)\nplcsh.log(line)\n",
    );
    let o = run(&["run", p.to_str().unwrap(), csv.to_str().unwrap()], "");
    assert!(o.status.success(), "{}", both(&o));
    assert!(o.stdout.starts_with(b"\xCF\xF0\xE8\xE2\xE5\xF2;1\n"), "{:?}", o.stdout);
    assert!(o.stdout.ends_with(b"s \xCF\xF0\xE8\xE2\xE5\xF2;1\n"), "plcsh.log too: {:?}", o.stdout);
    let o = run(&[], "lua print('\\207\\240\\232')\n");
    assert!(o.status.success(), "{}", both(&o));
    assert_eq!(o.stdout, b"\xCF\xF0\xE8\n");
}

#[test]
fn repl_lua_forms_share_one_state() {
    let input = "lua x = 20; y = 22\n:x + y\nlua\nfor i = 1, 2 do\n  print('line ' .. i)\nend\nend\n:function twice(v)\n  return v * 2\nend\n:twice(plc.VW0 + 4)\nset VW0=1; get VW0\n";
    let o = run(&[], input);
    assert!(o.status.success(), "{}", stdout(&o));
    assert_eq!(stdout(&o), "42\nline 1\nline 2\n8\nVW0  1\n");
}

#[test]
fn repl_lua_in_json_mode() {
    let o =
        run(&["--json", "-c", ":plc.VW0 = 7; print('hi'); return plc.VW0, plcsh.exec('get VW0').values[1].value"], "");
    assert!(o.status.success(), "{}", stdout(&o));
    let l = json_lines(&o);
    assert_eq!(l[0], serde_json::json!({"ok": true, "cmd": "print", "message": "hi"}));
    assert_eq!(l[1]["results"], serde_json::json!([7, 7]));
    let o = run(&["--json", "-c", "lua plc.VB0 = 300"], "");
    assert_eq!(o.status.code(), Some(1));
    let l = json_lines(&o);
    assert_eq!(l[0]["error"]["operand"], "VB0");
}

#[test]
fn require_finds_the_project_lib() {
    let p = script("req.lua", "local c = require('commission')\nprint(type(c.new))\n");
    let o = run(&["run", p.to_str().unwrap()], "");
    assert!(o.status.success(), "{}", stdout(&o));
    assert_eq!(stdout(&o), "function\n");
    // PLCSH_LIB comes first.
    let dir = p.parent().unwrap().join("mylib");
    std::fs::create_dir_all(&dir).unwrap();
    std::fs::write(dir.join("commission.lua"), "return {new = 'mine'}\n").unwrap();
    let mut cmd = plcsh();
    cmd.env("PLCSH_LIB", &dir).args(["run", p.to_str().unwrap()]);
    let o = cmd.output_retrying().unwrap();
    assert_eq!(stdout(&o), "string\n");
}

#[test]
fn a_failed_checklist_step_fails_the_script() {
    let p = script(
        "check.lua",
        "local c = require('commission').new('demo')\nc:step('ok', function() end)\nc:step('bad', function() plcsh.assert_eq(plc.VW0, 5, 'VW0') end)\nc:step('later', function() end)\nc:run()\n",
    );
    let o = run(&["run", p.to_str().unwrap()], "");
    assert_eq!(o.status.code(), Some(1));
    let s = common::both(&o);
    assert!(s.contains("[x] 1. ok"), "{s}");
    assert!(s.contains("[ ] 2. bad — FAILED") && s.contains("actual:   0"), "{s}");
    assert!(s.contains("[-] 3. later (skipped)"), "{s}");
    assert!(s.contains(&format!("{}:5: demo: 1 step(s) failed", p.display())), "{s}");
}

/// A checklist's table keeps a failed check's actual and expected values, and its numbers
/// are numbers in JSON.
#[test]
fn a_checklist_table_keeps_the_values_of_a_failed_check_and_its_numbers() {
    let p = script(
        "check_values.lua",
        "local c = require('commission').new('demo', {keep_going = true})\nc:step('bad', function() plcsh.assert_eq(plc.VW0, 5) end)\nc:step('ok', function() end)\nc:run()\n",
    );
    let o = run(&["--json", "run", p.to_str().unwrap()], "");
    let table = common::json_lines(&o).into_iter().find(|l| l["cmd"] == "table").expect("the table line");
    let rows = table["rows"].as_array().unwrap();
    assert_eq!(rows[0][0], 1, "the step number is a number: {table}");
    assert!(rows[0][3].is_number() && rows[1][3].is_number(), "ms are numbers: {table}");
    let note = rows[0][4].as_str().unwrap();
    assert!(note.contains("actual:   0") && note.contains("expected: 5"), "{note}");
}

#[test]
fn stdin_closes_cleanly_after_an_unfinished_block() {
    let child = plcsh().stdin(Stdio::piped()).stdout(Stdio::piped()).spawn_retrying().unwrap();
    let o = output_with_input(child, b"lua\nprint(1)\n");
    assert_eq!(String::from_utf8_lossy(&o.stdout), "1\n");
}

/// Errors point at the script: a bad operand read names the script's line (not mlua's glue),
/// in text and in `--json`'s `where`; an error caught with pcall carries file:line.
#[test]
fn read_errors_and_pcalled_errors_name_the_script_line() {
    let p = script("badread.lua", "local a = 1\nlocal x = plc['Q0.8']\n");
    let o = run(&["run", p.to_str().unwrap()], "");
    assert_eq!(o.status.code(), Some(1));
    let e = common::stderr(&o);
    assert!(e.contains(&format!("{}:2: plc: bit 8", p.display())) && !e.contains("error[operand]: __mlua"), "{e}");
    let o = run(&["--json", "run", p.to_str().unwrap()], "");
    assert_eq!(json_lines(&o)[0]["error"]["where"], format!("{}:2", p.display()));

    let p = script(
        "pcalled.lua",
        "local ok, e = pcall(function()\n  return plc.XYZ\nend)\nprint(ok, tostring(e):match('^[^\\n]*'))\n",
    );
    let o = run(&["run", p.to_str().unwrap()], "");
    assert!(o.status.success(), "{}", both(&o));
    assert!(stdout(&o).starts_with(&format!("false\t{}:2: error[operand]:", p.display())), "{}", stdout(&o));
}

/// A method typo says there is no such method and names the near ones; a dot instead of a
/// colon says so.
#[test]
fn method_typos_and_dots_for_colons_are_explained() {
    let p = script("typo.lua", "servo:stauts()\n");
    let e = common::stderr(&run(&["run", p.to_str().unwrap()], ""));
    assert!(e.contains("has no method or operand `stauts`") && e.contains("servo:status()"), "{e}");
    assert!(!e.contains("needs a number"), "{e}");
    let p = script("dot.lua", "local v = plc.get('VW0')\n");
    let e = common::stderr(&run(&["run", p.to_str().unwrap()], ""));
    assert!(e.contains(&format!("{}:1:", p.display())) && e.contains("call it with a colon, `dev:get(…)`"), "{e}");
    // Caught with pcall (called through a function or directly) or xpcall: the same explanation,
    // with the script line, and plcsh.errinfo reads it.
    let p = script(
        "dotpcall.lua",
        "local ok, e = pcall(function() return plc.get('VW0') end)\nprint(ok, e)\n\
         print(select(2, pcall(plc.get, 'VW0')))\n\
         print(select(2, xpcall(function() return plc.get('VW0') end, function(m) return 'handled: ' .. tostring(m) end)))\n\
         print(plcsh.errinfo(e).kind)\n",
    );
    let o = run(&["run", p.to_str().unwrap()], "");
    assert!(o.status.success(), "{}", both(&o));
    let out: Vec<String> = stdout(&o).lines().map(str::to_string).collect();
    let friendly = "`get` is a method: call it with a colon, `dev:get(…)`, not a dot `dev.get(…)`";
    // Lua shortens a long script path inside a caught message (`...\\Temp\\…` on Windows):
    // the line and the explanation are what count.
    assert!(out[0].starts_with("false\t"), "{out:?}");
    assert!(out[0].ends_with(&format!("dotpcall.lua:1: error[script]: {friendly}")), "{out:?}");
    assert!(out[1].ends_with(friendly), "{out:?}");
    assert!(out[2].starts_with("handled: "), "{out:?}");
    assert!(out[2].ends_with(&format!("dotpcall.lua:4: error[script]: {friendly}")), "{out:?}");
    assert_eq!(out[3], "script");
}

/// Unknown keys in an options table are errors (a misspelt timeout would wait for ever).
#[test]
fn unknown_option_keys_are_refused() {
    let p = script("opts.lua", "plcsh.wait_until(function() return false end, {timout=50})\n");
    let o = run(&["--time", "stepped", "run", p.to_str().unwrap()], "");
    assert_eq!(o.status.code(), Some(1));
    let e = common::stderr(&o);
    assert!(e.contains("unknown option `timout`") && e.contains("did you mean `timeout`?"), "{e}");
    let p = script("opts2.lua", "print(plcsh.json.encode({1}, {prety=true}))\n");
    let e = common::stderr(&run(&["run", p.to_str().unwrap()], ""));
    assert!(e.contains("unknown option `prety`"), "{e}");
    let p = script("opts3.lua", "local c = require('commission').new('x', {keep_goin=true})\n");
    let e = common::stderr(&run(&["run", p.to_str().unwrap()], ""));
    assert!(e.contains(&format!("{}:1: commission.new: unknown option `keep_goin`", p.display())), "{e}");
}

/// A lab grades a folder of submissions: `--json run --sandbox` refuses os.execute with a
/// clear error naming the line, and the run ends with one summary object.
#[test]
fn a_sandboxed_run_refuses_os_execute_and_ends_with_a_summary() {
    let marker = std::env::temp_dir().join(format!("plcsh-sandbox-marker-{}", std::process::id()));
    let _ = std::fs::remove_file(&marker);
    let p = script(
        "student.lua",
        &format!(
            "plcsh.check(plc.VW0 == 0, 'VW0 starts at 0')\nplcsh.assert_eq(1 + 1, 2)\nos.execute({:?})\n",
            format!("touch {}", marker.display())
        ),
    );
    let o = run(&["--json", "run", "--sandbox", p.to_str().unwrap()], "");
    assert_eq!(o.status.code(), Some(1));
    assert!(!marker.exists(), "os.execute did not run");
    let l = json_lines(&o);
    assert_eq!(l.len(), 1, "one summary object: {l:?}");
    let s = &l[0];
    assert_eq!(s["ok"], false);
    assert_eq!(s["error"]["where"], format!("{}:3", p.display()));
    assert!(s["error"]["message"].as_str().unwrap().contains("os.execute is not available in a sandboxed run"));
    assert_eq!(s["checks"], serde_json::json!({"passed": 2, "failed": 0}));
    assert!(s["duration_ms"].as_f64().unwrap() >= 0.0);

    // A passing run ends with the summary too; a failed check is counted.
    let p = script("graded.lua", "print('hello')\nplcsh.check(true)\nlocal ok = pcall(plcsh.check, false, 'wrong')\n");
    let l = json_lines(&run(&["--json", "run", "--sandbox", p.to_str().unwrap()], ""));
    let s = l.last().unwrap();
    assert_eq!(s["ok"], true, "{l:?}");
    assert_eq!(s["checks"], serde_json::json!({"passed": 1, "failed": 1}));

    // Writing: refused without --write-dir, allowed under it, refused outside it.
    let dir = std::env::temp_dir().join(format!("plcsh-sandbox-dir-{}", std::process::id()));
    std::fs::create_dir_all(&dir).unwrap();
    let inside = dir.join("out.txt");
    let w = script(
        "writer.lua",
        &format!("local f = assert(io.open({:?}, 'w'))\nf:write('x')\nf:close()\n", inside.to_str().unwrap()),
    );
    let o = run(&["run", "--sandbox", w.to_str().unwrap()], "");
    assert!(common::stderr(&o).contains("not allowed in a sandboxed run"), "{}", common::stderr(&o));
    let o = run(&["run", "--sandbox", "--write-dir", dir.to_str().unwrap(), w.to_str().unwrap()], "");
    assert!(o.status.success(), "{}", both(&o));
    assert_eq!(std::fs::read_to_string(&inside).unwrap(), "x");
    let o = run(&["run", "--sandbox", "--write-dir", dir.join("sub").to_str().unwrap(), w.to_str().unwrap()], "");
    assert!(common::stderr(&o).contains("is outside"), "{}", common::stderr(&o));
    // Commands that write files follow the same rule.
    let outside = std::env::temp_dir().join(format!("plcsh-sandbox-trace-{}.csv", std::process::id()));
    let t = script(
        "tracer.lua",
        &format!("plc:trace('VW0', {{every=10, ['for']=50, to={:?}}})\n", outside.to_str().unwrap()),
    );
    let o =
        run(&["--time", "stepped", "run", "--sandbox", "--write-dir", dir.to_str().unwrap(), t.to_str().unwrap()], "");
    assert!(common::stderr(&o).contains("is outside") && !outside.exists(), "{}", both(&o));
}

/// `require` searches in the order docs/lua.md gives: PLCSH_LIB, the user's lib, the project's lib/,
/// then the script's own directory — and `plcsh.lib_dirs` lists every directory searched.
#[test]
fn require_searches_in_the_documented_order() {
    let base = std::env::temp_dir().join(format!("plcsh-require-{}", std::process::id()));
    let (libdir, scriptdir) = (base.join("lib"), base.join("scripts"));
    std::fs::create_dir_all(&libdir).unwrap();
    std::fs::create_dir_all(&scriptdir).unwrap();
    std::fs::write(libdir.join("shadow.lua"), "return 'from PLCSH_LIB'\n").unwrap();
    std::fs::write(scriptdir.join("shadow.lua"), "return 'from the script directory'\n").unwrap();
    std::fs::write(scriptdir.join("own.lua"), "return 'own'\n").unwrap();
    let s = scriptdir.join("main.lua");
    std::fs::write(
        &s,
        "print((require('shadow')), (require('own')))\nprint(plcsh.lib_dirs[1], plcsh.lib_dirs[#plcsh.lib_dirs])\n",
    )
    .unwrap();
    let o = plcsh().env("PLCSH_LIB", &libdir).args(["run", s.to_str().unwrap()]).output_retrying().unwrap();
    assert!(o.status.success(), "{}", both(&o));
    assert_eq!(stdout(&o), format!("from PLCSH_LIB\town\n{}\t{}\n", libdir.display(), scriptdir.display()),);
}

/// `-c`: a Lua `print` appears in order with the output of the commands around it.
#[test]
fn print_output_stays_in_order_under_dash_c() {
    let o = run(&["-c", "set VW0=5; get VW0; lua print('between'); get VW0"], "");
    assert_eq!(stdout(&o), "VW0  5\nbetween\nVW0  5\n");
}

/// An installed plcsh needs no source checkout: the binary is copied into a fresh prefix
/// (`PREFIX/bin/plcsh`, the layout `cargo install --root PREFIX` makes) with no `lib/` beside
/// it, run from another directory with a private home and no `PLCSH_LIB`, and
/// `require("commission")` is served from the copy built into the binary (its loader data
/// says so). `PLCSH_LIB` still overrides the built-in module.
#[test]
fn an_installed_binary_finds_the_lib_modules_without_the_checkout() {
    let base = std::env::temp_dir().join(format!("plcsh-installed-{}", std::process::id()));
    let (bin_dir, work, home) = (base.join("prefix/bin"), base.join("work"), base.join("home"));
    for d in [&bin_dir, &work, &home] {
        std::fs::create_dir_all(d).unwrap();
    }
    let src = std::path::Path::new(bin());
    let exe = bin_dir.join(src.file_name().unwrap());
    std::fs::copy(src, &exe).unwrap();
    for up in [base.join("prefix/lib"), base.join("lib"), bin_dir.join("lib")] {
        assert!(!up.exists(), "no lib/ beside the installed binary");
    }
    std::fs::write(
        work.join("commission_run.lua"),
        "local commission, from = require('commission')\nprint(from)\n\
         local c = commission.new('installed')\nc:step('VW0 set', function() plc:set('VW0=7') end)\nc:run()\n\
         print(#plcsh.lib_dirs)\n",
    )
    .unwrap();
    let installed = |lib: Option<&std::path::Path>| {
        let mut c = std::process::Command::new(&exe);
        c.current_dir(&work)
            .env("HOME", &home)
            .env("XDG_CONFIG_HOME", home.join("config"))
            .env("XDG_DATA_HOME", home.join("data"))
            .env("APPDATA", home.join("appdata"))
            .env("PLCSH_STATE", "none")
            .env_remove("PLCSH_LIB")
            .env_remove("PLCSH_CONFIG")
            .args(["--time", "stepped", "run", "commission_run.lua"])
            .stdin(Stdio::null());
        if let Some(l) = lib {
            c.env("PLCSH_LIB", l);
        }
        c.output_retrying().unwrap()
    };
    let o = installed(None);
    assert!(o.status.success(), "{}", both(&o));
    let out = stdout(&o);
    assert!(out.starts_with("plcsh:lib/commission.lua\n"), "served from the binary:\n{out}");
    assert!(out.contains("[x] 1. VW0 set"), "{out}");
    assert!(out.ends_with("1\n"), "only the script's directory is a lib directory:\n{out}");
    // PLCSH_LIB comes before the built-in copy.
    let mine = base.join("mylib");
    std::fs::create_dir_all(&mine).unwrap();
    std::fs::write(mine.join("commission.lua"), "return {new = function() error('mine') end}\n").unwrap();
    let o = installed(Some(&mine));
    assert!(!o.status.success() && both(&o).contains("mine"), "{}", both(&o));
    assert!(stdout(&o).starts_with(&format!("{}\n", mine.join("commission.lua").display())), "{}", both(&o));
    let _ = std::fs::remove_dir_all(&base);
}

/// A module that is found nowhere lists every place searched, the built-in modules included.
#[test]
fn a_missing_module_names_every_place_searched() {
    let p = script("missing.lua", "require('no_such_module')\n");
    let o = run(&["run", p.to_str().unwrap()], "");
    assert_eq!(o.status.code(), Some(1));
    let e = both(&o);
    assert!(e.contains("module 'no_such_module' not found"), "{e}");
    assert!(e.contains("no module 'no_such_module' built into plcsh"), "{e}");
    assert!(e.contains(&format!("no file '{}'", p.parent().unwrap().join("no_such_module.lua").display())), "{e}");
}

/// `plcsh.quote` makes any path one word of a shell line: a snapshot saved under a name with a
/// space, a quote, `;`, `#` and Cyrillic letters restores through `plcsh.exec`.
#[test]
fn quote_makes_any_path_one_word_for_exec() {
    let dir = std::env::temp_dir().join(format!("plcsh-lua-quote-{}", std::process::id()));
    // A name every system allows (Windows refuses `"` in names): a quote, `;`, `#`, a space.
    let odd = dir.join("снимок it's one; #1");
    std::fs::create_dir_all(&odd).unwrap();
    let p = script(
        "quote.lua",
        r#"
local dir = arg[1]
local file = dir .. "/s.json"
plcsh.exec("set VW0=42; sim snapshot save " .. plcsh.quote(file))
plcsh.exec("set VW0=1; sim snapshot restore " .. plcsh.quote(file))
plcsh.assert_eq(plcsh.device("plc").VW0, 42, "restored from " .. file)
print("ok")
"#,
    );
    let o = run(&["--time", "stepped", "run", p.to_str().unwrap(), odd.to_str().unwrap()], "");
    assert!(o.status.success(), "{}", both(&o));
    assert!(stdout(&o).contains("ok"));
    let _ = std::fs::remove_dir_all(&dir);
}
