//! Units that cannot surprise (docs/lua.md, "Scripting reference: units"): for every command that
//! takes a quantity, each spelling of the same amount — the bare number in the table's unit,
//! and the number with each unit — gives the same result, the value the table says; and a
//! trailing extra word is refused, never ignored. One table, one test.

mod common;
use common::*;
use serde_json::Value;

/// One quantity: a command template (`{}` is the quantity), the spellings that all mean the
/// same amount, what the result must show for it, and how to read that from the JSON lines.
struct Case {
    what: &'static str,
    template: &'static str,
    spellings: &'static [&'static str],
    expect: Value,
    read: fn(&[Value]) -> Value,
}

fn last_with(lines: &[Value], cmd: &str) -> Value {
    lines.iter().rev().find(|l| l["cmd"] == cmd).cloned().unwrap_or(Value::Null)
}

fn write_of(lines: &[Value], operand: &str) -> Value {
    lines
        .iter()
        .flat_map(|l| l["writes"].as_array().cloned().unwrap_or_default())
        .chain(lines.iter().flat_map(|l| {
            l["results"]
                .as_array()
                .cloned()
                .unwrap_or_default()
                .into_iter()
                .flat_map(|r| r["writes"].as_array().cloned().unwrap_or_default())
        }))
        .find(|w| w["operand"] == operand)
        .map(|w| w["value"].clone())
        .unwrap_or(Value::Null)
}

fn cases() -> Vec<Case> {
    vec![
        Case {
            what: "pulse cycle (bare: µs)",
            template: "pto 0 cycle={} count=10",
            spellings: &["500", "500us", "500µs", "0.5ms"],
            expect: 500.into(),
            read: |l| write_of(l, "SMW68"),
        },
        Case {
            what: "a 2 µs cycle is 2 µs, never 2 s",
            template: "pto 0 cycle={} count=10",
            spellings: &["2", "2us"],
            expect: "value".into(),
            read: |l| last_with(l, "pto")["error"]["kind"].clone(),
        },
        Case {
            what: "PWM cycle (bare: µs)",
            template: "pwm 0 cycle={} width=50us",
            spellings: &["100", "100us", "0.1ms"],
            expect: 100.into(),
            read: |l| write_of(l, "SMW68"),
        },
        Case {
            what: "PWM width (bare: µs)",
            template: "pwm 0 cycle=100us width={}",
            spellings: &["50", "50us", "0.05ms"],
            expect: 50.into(),
            read: |l| write_of(l, "SMW70"),
        },
        Case {
            what: "Lua pulse cycle (bare: µs)",
            template: "lua plc:pto(0, {cycle={}, count=10})",
            spellings: &["500", "'500us'", "'0.5ms'"],
            expect: 500.into(),
            read: |l| write_of(l, "SMW68"),
        },
        Case {
            what: "frequency (bare: Hz)",
            template: "pto 0 freq={} count=10",
            spellings: &["2000", "2kHz", "2khz", "2k"],
            expect: 500.into(),
            read: |l| write_of(l, "SMW68"),
        },
        Case {
            what: "sim step (bare: ms)",
            template: "sim step {}",
            spellings: &["1500", "1500ms", "1.5s", "1s500ms", "1500000us"],
            expect: 1_500_000.into(),
            read: |l| last_with(l, "sim")["time_us"].clone(),
        },
        Case {
            what: "watch every= (bare: ms)",
            template: "watch VW0 every={} count=2",
            spellings: &["500", "500ms", "0.5s"],
            expect: 500_000.into(),
            read: |l| l.iter().find(|x| x["sample"] == 1).map(|x| x["t_us"].clone()).unwrap_or(Value::Null),
        },
        Case {
            what: "trace every= (bare: ms)",
            template: "trace VW0 every={} for=40ms",
            spellings: &["10", "10ms", "10000us", "0.01s"],
            expect: 10_000.into(),
            read: |l| last_with(l, "trace")["every_us"].clone(),
        },
        Case {
            what: "trace for= (bare: ms)",
            template: "trace VW0 every=10ms for={}",
            spellings: &["40", "40ms", "0.04s"],
            expect: 5.into(),
            read: |l| last_with(l, "trace")["samples"].clone(),
        },
        Case {
            what: "wait timeout= (bare: ms)",
            template: "wait event 28 timeout={}",
            spellings: &["1500", "1500ms", "1.5s"],
            expect: "no event 28 within 1.500000s".into(),
            read: |l| last_with(l, "wait")["error"]["message"].clone(),
        },
        Case {
            what: "fault windows after=/for= (bare: ms)",
            template: "sim fault no-reply after={} for=1s",
            spellings: &["500", "500ms", "0.5s"],
            expect: 500_000_000u64.into(),
            read: |l| last_with(l, "sim")["fault"]["from_ns"].clone(),
        },
        Case {
            what: "wire delay= (bare: ms)",
            template: "sim wire plc:Q0.0 -> plc:I0.3 delay={}",
            spellings: &["2", "2ms", "2000us"],
            expect: true.into(),
            read: |l| Value::from(last_with(l, "sim")["message"].as_str().unwrap_or("").contains("delay 2000 µs")),
        },
        Case {
            what: "servo speed (bare: rpm)",
            template: "servo enable; servo move rel 10000 speed={} acc=100",
            spellings: &["300", "300rpm"],
            expect: 819_200.into(),
            read: |l| last_with(l, "servo")["profile_velocity"].clone(),
        },
        Case {
            what: "servo acceleration (bare: rps/s)",
            template: "servo enable; servo move rel 10000 speed=300 acc={}",
            spellings: &["100", "100rps/s"],
            expect: 16_384.into(),
            read: |l| last_with(l, "servo")["profile_acceleration"].clone(),
        },
        Case {
            what: "servo position (bare: increments)",
            template: "servo enable; servo move rel {} speed=300 acc=100",
            spellings: &["10000", "10000inc", "1rev"],
            expect: 10_000.into(),
            read: |l| last_with(l, "servo")["target_position"].clone(),
        },
    ]
}

fn run_json(line: &str) -> (std::process::Output, Vec<Value>) {
    let o = run(&["--json", "--time", "stepped", "--state", "none", "-c", line], "");
    let lines = stdout(&o).lines().filter_map(|l| serde_json::from_str(l).ok()).collect();
    (o, lines)
}

#[test]
fn every_spelling_of_a_quantity_means_what_the_units_table_says() {
    let mut checked = 0;
    for c in cases() {
        for s in c.spellings {
            let line = c.template.replace("{}", s);
            let (o, lines) = run_json(&line);
            assert_eq!((c.read)(&lines), c.expect, "{}: `{line}`\n{}", c.what, both(&o));
            checked += 1;
        }
    }
    assert!(checked >= 50, "{checked}");
}

#[test]
fn a_trailing_extra_word_is_refused_never_ignored() {
    let mut lines: Vec<String> = cases()
        .iter()
        .filter(|c| c.expect != "value" && !c.template.starts_with("lua"))
        .map(|c| format!("{} extra", c.template.replace("{}", c.spellings[0])))
        .collect();
    lines.extend(
        [
            "sim step 1 s",
            "sim step 500ms extra",
            "sim time now",
            "sim run x",
            "servo status foo",
            "devices x",
            "quit now",
            "sim inputs x",
        ]
        .map(String::from),
    );
    for line in lines {
        let (o, json) = run_json(&line);
        assert!(!o.status.success(), "`{line}` was accepted:\n{}", both(&o));
        let err =
            json.iter().find(|l| l["ok"] == false).unwrap_or_else(|| panic!("`{line}`: no error line\n{}", both(&o)));
        assert!(matches!(err["error"]["kind"].as_str(), Some("usage" | "operand" | "value")), "`{line}`: {err}");
        // Nothing of the refused command ran: no write, no step of the clock.
        assert!(json.iter().all(|l| l["writes"].is_null() || l["cmd"] != err["cmd"]), "`{line}`: {json:?}");
    }
}

/// Notes and warnings are for the person, not the pipeline: on stderr in text mode, in the
/// line's `notes` in JSON, never among the results on stdout.
#[test]
fn notes_go_to_stderr_and_into_json_never_to_stdout_text() {
    let o = run(&["--time", "stepped", "--state", "none", "-c", "pto 0 cycle=70ms count=3"], "");
    assert!(o.status.success(), "{}", both(&o));
    assert!(!stdout(&o).contains("note:"), "{}", stdout(&o));
    assert!(stderr(&o).contains("note: cycle 70000 µs uses the 1 ms time base"), "{}", stderr(&o));
    let (_, lines) = run_json("pto 0 cycle=70ms count=3");
    assert!(lines[0]["notes"][0].as_str().unwrap_or("").contains("1 ms time base"), "{lines:?}");
}

/// One vocabulary: the clock has its own word (`sim clock real|stepped`), `sim run` is
/// refused as ambiguous (the clock, or the CPU's `sim cpu run`).
#[test]
fn the_clock_has_its_own_word_and_sim_run_is_refused() {
    let (o, lines) = run_json("sim step 1s; sim clock real; sim clock stepped; sim step 1s; sim clock");
    assert!(o.status.success(), "{}", both(&o));
    let last = lines.last().unwrap();
    assert_eq!(last["stepped"], true);
    assert!(last["time_us"].as_u64().unwrap() >= 2_000_000, "{last}");
    let (o, lines) = run_json("sim run");
    assert!(!o.status.success());
    assert!(lines[0]["error"]["hint"].as_str().unwrap().contains("sim clock real"), "{lines:?}");
}

/// Habits from other tools get messages that name the mistake; `pwm` takes `strict` like
/// `pls`, `pto` and `profile`.
#[test]
fn habits_from_other_tools_are_named_and_pwm_takes_strict() {
    let (_, l) = run_json("set VW100:=5");
    assert!(l[0]["error"]["message"].as_str().unwrap().contains("`:=` is the ST assignment"), "{l:?}");
    let (_, l) = run_json("get VW0..VW20..");
    assert!(l[0]["error"]["message"].as_str().unwrap().contains("a range has one `..`"), "{l:?}");
    let (o, l) = run_json("pto 0 freq=10Hz count=100; pwm 0 cycle=100 width=50 strict");
    assert!(!o.status.success());
    assert_eq!(l.last().unwrap()["error"]["kind"], "state", "{l:?}");
    let (o, _) = run_json("pwm 0 cycle=100 width=50; pwm 0 cycle=100 width=20 strict");
    assert!(o.status.success(), "changing a running PWM's duty is no conflict: {}", both(&o));
}

/// Commands of the command line typed in the shell say where they belong.
#[test]
fn command_line_commands_in_the_shell_say_where_they_belong() {
    for (line, want) in [
        ("run x.lua", "plcsh run SCRIPT.lua"),
        ("replay x.pcapng", "plcsh replay FILE.pcapng"),
        ("record show x.pcapng", "plcsh record show"),
        ("agent il", "plcsh agent il"),
    ] {
        let (o, l) = run_json(line);
        assert!(!o.status.success(), "{line}");
        let e = &l[0]["error"];
        let text = format!("{} {}", e["message"].as_str().unwrap_or(""), e["hint"].as_str().unwrap_or(""));
        assert!(text.contains(want), "{line}: {text}");
    }
}

/// One placement (docs/commands.md, "Where the device goes"): the device right after the
/// command word, a K2 channel first and prefixed like an operand; the older order reads the same.
#[test]
fn device_and_channel_go_in_the_same_place_in_every_family() {
    let (o, l) = run_json(
        "pto 0 freq=10Hz count=5; pto 0 status; pto status 0; pto plc:0 status; \
         hsc 0 status; hsc status 0; agent plc status; agent status plc; agent; servo servo status",
    );
    assert!(o.status.success(), "{}", both(&o));
    assert_eq!(l.len(), 10, "{l:?}");
    assert_eq!(l[1]["status"], l[2]["status"], "{l:?}");
    assert_eq!(l[1]["status"], l[3]["status"], "{l:?}");
    assert_eq!(l[4]["status"], l[5]["status"], "{l:?}");
    assert!(l[1]["status"].as_array().is_some_and(|s| !s.is_empty()), "{l:?}");
    assert_eq!(l[6]["message"], l[7]["message"], "{l:?}");
    assert_eq!(l[6]["message"], l[8]["message"], "{l:?}");
    assert_eq!(l[9]["device"], "servo", "{l:?}");
    // The device after the command word for the K2's eeprom, rtc, events and wait, too.
    let (o, l) =
        run_json("eeprom plc status; eeprom status; rtc plc; events plc; use servo; rtc plc sync; servo status");
    assert!(o.status.success(), "{}", both(&o));
    assert_eq!(l[0]["message"], l[1]["message"], "{l:?}");
    assert_eq!(l[2]["device"], "plc", "{l:?}");
    // ... for that command only: afterwards the current device is the one `use` chose.
    let (o, l) = run_json("use servo; rtc plc; get VW0");
    assert!(!o.status.success(), "VW0 went to plc although `use servo` chose the drive: {l:?}");
    let (_, l) = run_json("wait plc event 1 timeout=1ms");
    assert_eq!(l[0]["error"]["kind"], "timeout", "{l:?}");
    for bad in ["pto 0 status extra", "agent plc status extra", "agent nosuchdevice", "eeprom nosuchdevice status"] {
        let (o, l) = run_json(bad);
        assert!(!o.status.success(), "`{bad}` was accepted: {l:?}");
    }
}

/// `cmd` is the command's word, the same for all its forms, and `sub` names the sub-command
/// (docs/json.md): `sim wires` and `sim faults` read alike.
#[test]
fn cmd_is_the_command_word_and_sub_names_the_sub_command() {
    let (o, l) = run_json("sim wires; sim faults; sim inputs; sim time; servo status; pto 0 status; get VW0");
    assert!(o.status.success(), "{}", both(&o));
    let pairs: Vec<(String, String)> =
        l.iter().map(|v| (v["cmd"].as_str().unwrap_or("?").into(), v["sub"].as_str().unwrap_or("").into())).collect();
    let want = [
        ("sim", "wires"),
        ("sim", "faults"),
        ("sim", "inputs"),
        ("sim", "time"),
        ("servo", "status"),
        ("pto", "status"),
        ("get", ""),
    ];
    assert_eq!(pairs, want.map(|(a, b)| (a.to_string(), b.to_string())), "{l:?}");
}
