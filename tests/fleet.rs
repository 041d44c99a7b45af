//! Fleets through the real binary, against `plcsh sim serve --fleet N` (N simulated K2s on N
//! loopback ports, bound to port 0; readiness read from the server's first line) and an
//! independent silent responder written here: the same commands and scripts on every member
//! at once, one row per device, failures kept to their device, write rules per device, the
//! JSON contract and the exit status.

mod common;
use common::*;
use std::path::PathBuf;

fn config(name: &str, text: &str) -> PathBuf {
    let dir = std::env::temp_dir().join(format!("plcsh-fleet-{}-{name}", std::process::id()));
    std::fs::create_dir_all(&dir).unwrap();
    let f = dir.join("devices.toml");
    std::fs::write(&f, text).unwrap();
    f
}

/// The served members' URLs.
fn urls(s: &Served) -> Vec<String> {
    s.ready["fleet"].as_array().unwrap().iter().map(|a| format!("tcp://{}", a.as_str().unwrap())).collect()
}

/// A profile file: fleet `line` of the served members, the second read-only through its profile.
fn line_config(name: &str, urls: &[String], extra: &str) -> PathBuf {
    let mut text = format!("[devices.guarded]\nurl = \"{}\"\nread_only = true\n\n", urls[1]);
    let mut list: Vec<String> = urls.iter().map(|u| format!("\"{u}\"")).collect();
    list[1] = "\"guarded\"".into();
    text.push_str(&format!("[fleets.line]\ndevices = [{}]\n{extra}", list.join(", ")));
    config(name, &text)
}

fn plcsh_with(cfg: &std::path::Path, args: &[&str]) -> std::process::Output {
    let mut all = vec!["--config", cfg.to_str().unwrap()];
    all.extend_from_slice(args);
    run(&all, "")
}

#[test]
fn served_fleet_lists_every_address() {
    let s = serve(&["--fleet", "5", "--tcp", "127.0.0.1:0"]);
    let addrs = s.ready["fleet"].as_array().unwrap();
    assert_eq!(addrs.len(), 5, "{}", s.ready);
    let mut distinct: Vec<&str> = addrs.iter().map(|a| a.as_str().unwrap()).collect();
    distinct.sort();
    distinct.dedup();
    assert_eq!(distinct.len(), 5, "each member has its own port: {}", s.ready);
    assert_eq!(s.ready["tcp"], addrs[0]);
}

#[test]
fn the_same_write_and_read_on_every_member_with_the_guard_per_device() {
    let s = serve(&["--fleet", "3", "--tcp", "0"]);
    let u = urls(&s);
    let cfg = line_config("guard", &u, "");
    let o = plcsh_with(&cfg, &["--json", "-f", "line", "-c", "set VW10=42; get VW10"]);
    assert_eq!(o.status.code(), Some(1), "one device refused: {}", both(&o));
    let l = json_lines(&o);
    assert_eq!(l.len(), 4, "three devices and a summary: {l:?}");
    for line in &l {
        assert!(line["ok"].is_boolean() && line["cmd"].is_string(), "the JSON contract: {line}");
    }
    assert_eq!(l[0]["device"], "line-1");
    assert_eq!(l[0]["ok"], true);
    assert_eq!(l[0]["results"][1]["values"][0]["value"], 42);
    assert_eq!(l[1]["device"], "guarded");
    assert_eq!(l[1]["ok"], false);
    assert_eq!(l[1]["cmd"], "set");
    assert!(l[1]["error"]["message"].as_str().unwrap().contains("read_only"), "{}", l[1]);
    assert_eq!(l[2]["device"], "line-3");
    assert_eq!(l[2]["ok"], true, "a refusal on one device stops no other");
    assert_eq!(l[3]["cmd"], "fleet");
    assert_eq!(l[3]["failed_devices"], serde_json::json!(["guarded"]));
    // Each member has its own memory: the refused device still reads 0, the others 42.
    let o = plcsh_with(&cfg, &["--json", "-f", "line", "-c", "get VW10"]);
    assert_eq!(o.status.code(), Some(0), "{}", both(&o));
    let v: Vec<i64> = json_lines(&o)[..3].iter().map(|l| l["values"][0]["value"].as_i64().unwrap()).collect();
    assert_eq!(v, vec![42, 0, 42]);
    // --read-only holds for every member.
    let o = plcsh_with(&cfg, &["--read-only", "--json", "-f", "line", "-c", "set VW10=1"]);
    let l = json_lines(&o);
    assert!(l[..3].iter().all(|l| l["ok"] == false), "{l:?}");
    assert_eq!(l[3]["failed"], 3);
}

#[test]
fn a_silent_device_times_out_alone_and_the_table_has_one_row_per_device() {
    let s = serve(&["--fleet", "2", "--tcp", "0"]);
    let mut u = urls(&s);
    // An independent responder that accepts and never answers: a device that hangs.
    let silent = std::net::TcpListener::bind("127.0.0.1:0").unwrap();
    u.insert(1, format!("tcp://{}", silent.local_addr().unwrap()));
    // It holds the connection until the test is over (however long a loaded machine makes it).
    let (done, over) = std::sync::mpsc::channel::<()>();
    let held = std::thread::spawn(move || {
        let c = silent.accept();
        let _ = over.recv();
        drop(c);
    });
    let list: Vec<String> = u.iter().map(|x| format!("\"{x}\"")).collect();
    let cfg = config("silent", &format!("[fleets.line]\ndevices = [{}]\n", list.join(", ")));
    let start = std::time::Instant::now();
    let o = plcsh_with(&cfg, &["--device-timeout", "1500ms", "-f", "line", "-c", "get VW0 VW2"]);
    assert!(start.elapsed() < std::time::Duration::from_secs(7), "the timeout ends the run: {:?}", start.elapsed());
    assert_eq!(o.status.code(), Some(1), "{}", both(&o));
    let out = stdout(&o);
    let rows: Vec<&str> = out.lines().filter(|l| l.starts_with("| line-")).collect();
    assert_eq!(rows.len(), 3, "{out}");
    assert!(rows[0].contains("| ok ") && rows[2].contains("| ok "), "{out}");
    assert!(rows[1].contains("FAILED") && (rows[1].contains("timeout") || rows[1].contains("error[")), "{out}");
    assert!(out.contains("| VW0 ") && out.contains("| VW2 "), "operands are columns: {out}");
    assert!(out.contains("1 of 3 devices failed: line-2"), "{out}");
    drop(done);
    held.join().unwrap();
}

#[test]
fn a_script_runs_on_every_member_and_checks_decide_the_status() {
    let s = serve(&["--fleet", "3", "--tcp", "0"]);
    let u = urls(&s);
    let cfg = line_config("script", &u, "");
    // Members 1 and 3 get VW20=1 first; the check fails on the guarded member, which reads 0.
    let o = plcsh_with(&cfg, &["-f", "line", "-c", "set VW20=1"]);
    assert_eq!(o.status.code(), Some(1));
    let script = cfg.with_file_name("check.lua");
    std::fs::write(&script, "local v = plcsh.exec('get VW20')\nprint('VW20 is', v)\nplcsh.check(plcsh.exec('get VW20') ~= nil)\nlocal r = plcsh.exec('get VW20')\nassert(r.values[1].value == 1, 'VW20 is not 1')\n").unwrap();
    let o = plcsh_with(&cfg, &["--json", "run", "--fleet", "line", script.to_str().unwrap()]);
    let l = json_lines(&o);
    assert_eq!(o.status.code(), Some(1), "{}", both(&o));
    assert_eq!(l.len(), 4, "{l:?}");
    assert_eq!(
        (l[0]["ok"].clone(), l[1]["ok"].clone(), l[2]["ok"].clone()),
        (true.into(), false.into(), true.into()),
        "{l:?}"
    );
    assert!(l[1]["error"]["message"].as_str().unwrap().contains("VW20 is not 1"), "{}", l[1]);
    assert!(l[0]["output"].as_str().unwrap().contains("VW20 is"), "what a member prints is kept: {}", l[0]);
    assert_eq!(l[3]["cmd"], "fleet");
}

#[test]
fn lua_visits_every_member_and_keeps_each_failure() {
    let s = serve(&["--fleet", "2", "--tcp", "0"]);
    let u = urls(&s);
    let cfg = line_config("lua", &u, "");
    let script = cfg.with_file_name("each.lua");
    std::fs::write(
        &script,
        r#"local f = plcsh.fleet("line")
assert(#f.devices == 2 and f.devices[2] == "guarded")
local r = f:each(function(plc) plc:set("VW30", 9); return plc:get("VW30") end)
print(r[1].device, r[1].ok, r[1].value)
print(r[2].device, r[2].ok, r[2].kind)
print("failed", r.failed)
"#,
    )
    .unwrap();
    let o = plcsh_with(&cfg, &["run", script.to_str().unwrap()]);
    assert!(o.status.success(), "{}", both(&o));
    let out = stdout(&o);
    assert!(out.contains("line-1\ttrue\t9"), "{out}");
    assert!(out.contains("guarded\tfalse\trefused"), "{out}");
    assert!(out.contains("failed\t1"), "{out}");
}

#[test]
fn usage_errors_touch_no_device() {
    let cfg = config("usage", "[devices.a]\nurl = \"sim:K205-16DT\"\n[fleets.line]\ndevices = [\"a\"]\n");
    let o = plcsh_with(&cfg, &["-f", "nope", "-c", "get VW0"]);
    assert_eq!(o.status.code(), Some(2), "{}", both(&o));
    assert!(stderr(&o).contains("fleets in") && stderr(&o).contains("line"), "{}", both(&o));
    let o = plcsh_with(&cfg, &["-f", "line", "devices"]);
    assert_eq!(o.status.code(), Some(2), "{}", both(&o));
    let o = plcsh_with(&cfg, &["-f", "line", "-c", "get VW0"]);
    assert_eq!(o.status.code(), Some(0), "{}", both(&o));
    let o = plcsh_with(&cfg, &["--jobs", "0", "-f", "line", "-c", "get VW0"]);
    assert_eq!(o.status.code(), Some(2), "{}", both(&o));
}

#[test]
fn devices_shows_fleets_and_bad_ones_with_their_line() {
    let cfg = config(
        "show",
        "[fleets.presses]\nurl = \"tcp://10.0.0.{11..13}:502?unit=1\"\nread_only = true\n[fleets.bad]\nurl = \"tcp://10.0.0.{9..1}\"\n",
    );
    let o = plcsh_with(&cfg, &["--json", "devices"]);
    let l = json_lines(&o);
    let fleets = l[0]["fleets"].as_array().unwrap();
    assert_eq!(fleets.len(), 1, "{l:?}");
    assert_eq!(fleets[0]["members"], serde_json::json!(["presses-11", "presses-12", "presses-13"]));
    let o = plcsh_with(&cfg, &["devices"]);
    let words = stdout(&o).split_whitespace().collect::<Vec<_>>().join(" ");
    assert!(
        words.contains("| presses | (fleet) | 3 devices | tcp://10.0.0.{11..13}:502?unit=1 | read only |"),
        "{words}"
    );
    let problems = l[0]["problems"].as_array().unwrap();
    assert!(
        problems
            .iter()
            .any(|p| p.as_str().unwrap().contains(":5: fleet `bad` skipped: the range {9..1} runs backwards")),
        "{problems:?}"
    );
}

#[test]
fn a_line_every_member_refuses_alike_is_one_usage_error() {
    let s = serve(&["--fleet", "3", "--tcp", "0"]);
    let u = urls(&s);
    let cfg = line_config("typo", &u, "");
    for json in [false, true] {
        let mut args = vec!["-f", "line", "-c", "get VX0"];
        if json {
            args.insert(0, "--json");
        }
        let o = plcsh_with(&cfg, &args);
        assert_eq!(o.status.code(), Some(2), "one usage error: {}", both(&o));
        let text = both(&o);
        assert_eq!(text.matches("V needs a bit").count(), 1, "said once, not once per device: {text}");
        assert!(text.contains("every member of fleet `line`"), "{text}");
        if json {
            let l = json_lines(&o);
            assert_eq!(l.len(), 1, "{l:?}");
            assert_eq!((l[0]["ok"].as_bool(), l[0]["cmd"].as_str()), (Some(false), Some("get")), "{l:?}");
            assert_eq!(l[0]["error"]["kind"], "operand");
        }
    }
    // A command that ran first (the devices were touched), or a failure of one device only,
    // stays a row per device.
    let o = plcsh_with(&cfg, &["-f", "line", "-c", "get VW0; get VX0"]);
    assert_eq!(o.status.code(), Some(1), "{}", both(&o));
    let o = plcsh_with(&cfg, &["-f", "line", "-c", "set VW0=1"]);
    assert_eq!(o.status.code(), Some(1), "the read-only member refuses alone: {}", both(&o));
}

#[test]
fn thousands_of_members_in_one_served_fleet_and_one_fleet() {
    // Past the old cap of 1024, in one process: every member its own port, each one answers.
    let s = serve(&["--fleet", "2500", "--tcp", "127.0.0.1:0"]);
    let addrs: Vec<String> = urls(&s);
    assert_eq!(addrs.len(), 2500);
    let mut distinct = addrs.clone();
    distinct.sort();
    distinct.dedup();
    assert_eq!(distinct.len(), 2500);
    for (i, a) in [(0, &addrs[0]), (1000, &addrs[1000]), (2499, &addrs[2499])] {
        let set = run(&["-d", a, "-c", &format!("set VW0={i}; get VW0")], "");
        assert!(set.status.success(), "{}", both(&set));
        assert!(stdout(&set).contains(&format!("{i}")), "{}", both(&set));
    }
    let o = run(&["sim", "serve", "--fleet", "10001", "--tcp", "0"], "");
    assert_eq!(o.status.code(), Some(2), "{}", both(&o));
    // A URL fleet of 10 000 members is accepted; one more is refused with its line.
    let cfg = config(
        "many",
        "[fleets.plant]\nurl = \"tcp://127.0.0.1:{1..10000}\"\n[fleets.more]\nurl = \"tcp://127.0.0.1:{1..10001}\"\n",
    );
    let o = plcsh_with(&cfg, &["--json", "devices"]);
    let l = json_lines(&o);
    let fleets = l[0]["fleets"].as_array().unwrap();
    assert_eq!(fleets.len(), 1, "{l:?}");
    assert_eq!(fleets[0]["members"].as_array().unwrap().len(), 10_000);
    assert!(stderr(&o).contains("a fleet has at most 10000"), "{}", stderr(&o));
}
