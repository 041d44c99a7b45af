//! The real binary: piped stdin, `-c`, `--json`, exit codes.

mod common;
use common::*;

#[test]
fn piped_set_then_get_prints_the_three_values_as_json() {
    let o = run(&["--json"], "set SMB67=16#85, SMW68=500, SMD72=1000\nget SMB67 SMW68 SMD72\n");
    assert!(o.status.success(), "{}", stdout(&o));
    let lines = json_lines(&o);
    assert_eq!(lines.len(), 2, "one JSON object per command");
    let values: Vec<i64> =
        lines[1]["values"].as_array().unwrap().iter().map(|v| v["value"].as_i64().unwrap()).collect();
    assert_eq!(values, vec![133, 500, 1000]);
    assert_eq!(lines[1]["values"][0]["type"], "BYTE");
    assert_eq!(lines[1]["device"], "plc");
}

#[test]
fn one_shot_with_semicolons() {
    let o = run(&["-c", "set VW100=5; get VW100", "--json"], "");
    assert!(o.status.success());
    let lines = json_lines(&o);
    assert_eq!(
        lines[1],
        serde_json::json!({"ok":true,"cmd":"get","device":"plc","values":[{"operand":"VW100","value":5,"type":"WORD"}]})
    );
}

#[test]
fn a_bad_item_writes_nothing_and_the_repl_continues() {
    let o = run(&["--json"], "set VW0=1, VB2=300, VW4=2\nget VW0 VB2 VW4\n");
    assert_eq!(o.status.code(), Some(1), "a failed command makes the exit status 1");
    let lines = json_lines(&o);
    assert_eq!(lines[0]["ok"], false);
    assert_eq!(lines[0]["error"]["kind"], "value");
    assert_eq!(lines[0]["error"]["operand"], "VB2");
    assert!(lines[0]["error"]["message"].as_str().unwrap().contains("300"));
    let zeros: Vec<i64> = lines[1]["values"].as_array().unwrap().iter().map(|v| v["value"].as_i64().unwrap()).collect();
    assert_eq!(zeros, vec![0, 0, 0], "nothing was written");
}

#[test]
fn human_errors_point_at_the_column() {
    // Human-readable errors go to stderr (as mbpoll's do); stdout keeps only results.
    let o = run(&["-c", "get VW0; set VW0=1, VB2=300"], "");
    assert_eq!(o.status.code(), Some(1));
    assert_eq!(stdout(&o), "VW0  0\n", "no error text on stdout");
    let s = String::from_utf8_lossy(&o.stderr).into_owned();
    assert!(s.contains("  get VW0; set VW0=1, VB2=300\n                          ^\n"), "{s}");
    assert!(s.contains("out of range for BYTE"), "{s}");
}

#[test]
fn usage_errors_exit_2() {
    let o = run(&["--no-such-flag"], "");
    assert_eq!(o.status.code(), Some(2));
    let o = run(&["--device", "x=bogus:1"], "");
    assert_eq!(o.status.code(), Some(2));
}

#[test]
fn model_flag_and_device_prefix() {
    let o = run(
        &[
            "--model",
            "K209M-56DT",
            "--device",
            "small=sim:K205-16DT",
            "--json",
            "-c",
            "set VW16000=7, small:VW0=3; get VW16000 small:VW0",
        ],
        "",
    );
    assert!(o.status.success(), "{}", stdout(&o));
    let lines = json_lines(&o);
    assert_eq!(lines[1]["values"][0]["value"], 7);
    assert_eq!(lines[1]["values"][1]["device"], "small");
    let o = run(&["--json", "-c", "get VW16000"], "");
    let lines = json_lines(&o);
    assert_eq!(lines[0]["error"]["kind"], "range");
    assert!(lines[0]["error"]["message"].as_str().unwrap().contains("VW4094"));
}

#[test]
fn read_prints_a_table_with_hex_and_binary() {
    let o = run(&["-c", "set VB0=16#85; read VB0..VB1"], "");
    let s = stdout(&o);
    assert!(s.contains("16#85") && s.contains("2#1000_0101"), "{s}");
}

#[test]
fn stepped_time_from_the_command_line() {
    let o = run(
        &["--time", "stepped", "--json", "-c", "get SM0.1; sim step 499ms; get SM0.5; sim step 2ms; get SM0.5 SM0.1"],
        "",
    );
    let l = json_lines(&o);
    assert_eq!(l[0]["values"][0]["value"], true, "first scan");
    assert_eq!(l[2]["values"][0]["value"], true, "SM0.5 still on at 499 ms");
    assert_eq!(l[4]["values"][0]["value"], false, "SM0.5 off at 501 ms");
    assert_eq!(l[4]["values"][1]["value"], false, "first scan over");
}

#[test]
fn models_lists_the_catalogue() {
    let o = run(&["models", "--json"], "");
    let l = json_lines(&o);
    let names: Vec<&str> = l[0]["models"].as_array().unwrap().iter().map(|m| m["name"].as_str().unwrap()).collect();
    assert!(names.contains(&"K205-16DR") && names.contains(&"K209M-56DT"));
}

/// `plcsh ports` (docs/install.md, "Windows: a first session"): the serial ports present, as a table or
/// as JSON with the fields a script needs; extra words are refused.
#[test]
fn ports_lists_serial_ports_as_table_or_json() {
    let o = run(&["--json", "ports"], "");
    assert!(o.status.success(), "{}", both(&o));
    let j = &json_lines(&o)[0];
    assert_eq!((j["ok"].as_bool(), j["cmd"].as_str()), (Some(true), Some("ports")), "{j}");
    for p in j["ports"].as_array().unwrap() {
        assert!(p["name"].as_str().is_some_and(|n| !n.is_empty()), "{p}");
        assert!(["usb", "pci", "bluetooth", "other"].contains(&p["kind"].as_str().unwrap()), "{p}");
    }
    let o = run(&["ports"], "");
    assert!(o.status.success());
    let text = stdout(&o);
    assert!(text.contains("port") || text.contains("no serial ports found"), "{text}");
    let o = run(&["-c", "ports now"], "");
    assert!(!o.status.success());
    assert!(both(&o).contains("takes no arguments"), "{}", both(&o));
}

/// The device-server URLs the user guide shows (docs/install.md) name the carrier plcsh uses (parsed, not
/// connected: those addresses are not on this machine).
#[test]
fn readme_device_server_urls_parse() {
    use plcsh::core::link::serial::Carrier;
    use plcsh::core::url::DeviceUrl;
    for (url, want) in [
        (
            "rtu+rfc2217://192.168.127.254:4001?baud=19200&parity=even&unit=1",
            Carrier::Rfc2217("192.168.127.254:4001".into()),
        ),
        ("kinco+tcp://192.168.127.254:4002?id=1", Carrier::Tcp("192.168.127.254:4002".into())),
        ("fxlink+rfc2217://moxa:4003?station=0", Carrier::Rfc2217("moxa:4003".into())),
        ("rtu:COM3?baud=19200&unit=1", Carrier::Port("COM3".into())),
        ("kinco:COM10?id=1", Carrier::Port("COM10".into())),
    ] {
        let u = DeviceUrl::parse(url).unwrap();
        assert_eq!(Carrier::from_url(&u, "x").unwrap(), want, "{url}");
    }
}

/// Cyrillic in a script's file name, its folder and its output: the K2 manual's spelling and
/// Russian file names on a Windows lab PC (this test also runs under Wine).
#[test]
fn cyrillic_file_names_and_output() {
    let dir = std::env::temp_dir().join(format!("plcsh-кириллица-{}", std::process::id()));
    std::fs::create_dir_all(&dir).unwrap();
    let p = dir.join("проверка.lua");
    std::fs::write(&p, "-- пуск насоса\nprint('Привет, ПЛК: ' .. plc.VW0)\nlocal x = plc['Q0.9']\n").unwrap();
    let o = run(&["run", p.to_str().unwrap()], "");
    assert_eq!(stdout(&o), "Привет, ПЛК: 0\n", "{}", both(&o));
    assert!(stderr(&o).contains(&format!("{}:3:", p.display())), "the location names the file: {}", stderr(&o));
}

/// `plcsh paths` (and `paths` in the shell) prints where every file lives, following the
/// user's directories, the environment and the flags of this run.
#[test]
fn paths_prints_where_every_file_lives() {
    let home = std::env::temp_dir().join(format!("plcsh-test-home-{}", std::process::id()));
    std::fs::create_dir_all(&home).unwrap();
    let cfg = home.join("paths-devices.toml");
    std::fs::write(&cfg, "").unwrap();
    let o = run(&["paths", "--json", "--config", cfg.to_str().unwrap(), "--state", "/tmp/k2-state.json"], "");
    assert!(o.status.success(), "{}", both(&o));
    let l = json_lines(&o);
    let p = &l[0]["paths"];
    assert_eq!(p["config"], cfg.display().to_string());
    assert_eq!(p["state"], "/tmp/k2-state.json");
    // The per-user directories follow XDG_DATA_HOME / XDG_CONFIG_HOME on Unix (the test's
    // private home); on Windows they are under %APPDATA%.
    if cfg!(unix) {
        let data = home.join("data/plcsh");
        assert_eq!(p["history"], data.join("history.txt").display().to_string());
        assert_eq!(p["snapshots"], data.join("snapshots").display().to_string());
        assert_eq!(p["umpk_flash"], data.join("umpk").display().to_string());
        assert_eq!(p["user_lib"], home.join("config/plcsh/lib").display().to_string());
    } else {
        // Configuration roams with the user; state, history, snapshots and flash stay on the PC.
        for k in ["history", "snapshots", "umpk_flash"] {
            assert!(p[k].as_str().is_some_and(|s| s.contains(r"\AppData\Local\plcsh\data")), "{k}: {p}");
        }
        assert!(p["user_lib"].as_str().is_some_and(|s| s.contains(r"\AppData\Roaming\plcsh\config")), "{p}");
    }
    assert!(p["lib"].as_str().unwrap().ends_with("built in"), "{p}");
    assert!(p["recordings"].as_str().unwrap().starts_with("none"), "{p}");
    // The defaults and the environment, from the shell's `paths`.
    let snaps = home.join("snaps").display().to_string();
    let o = plcsh().env("PLCSH_SNAPSHOTS", &snaps).args(["-c", "paths"]).output_retrying().unwrap();
    let text = stdout(&o);
    if cfg!(unix) {
        assert!(text.contains(&home.join("config/plcsh/devices.toml").display().to_string()), "{text}");
    }
    assert!(text.contains(&snaps) && text.contains("none"), "state none under PLCSH_STATE=none:\n{text}");
}

/// `plcsh man` prints the roff page made from the clap definition: its title, then every
/// subcommand and every shell command; `plcsh man > plcsh.1` is the file `man ./plcsh.1` reads.
#[test]
fn man_prints_the_manual_page() {
    let o = run(&["man"], "");
    assert!(o.status.success(), "{}", both(&o));
    let page = stdout(&o);
    let th = page.lines().find(|l| l.starts_with(".TH")).unwrap_or("");
    assert!(th.starts_with(".TH PLCSH 1"), "{th}");
    for sub in
        ["models", "devices", "ports", "paths", "man", "completions", "sim", "agent", "probe", "run", "record", "lab"]
    {
        assert!(page.contains(&format!("plcsh\\-{sub}")), "the page lacks the subcommand {sub}");
    }
    for cmd in ["get", "set", "pto", "hsc", "servo", "sim"] {
        assert!(page.contains(&format!("\\fB{cmd} ")), "the page lacks the shell command {cmd}");
    }
}

/// A subcommand the command line does not have gets plcsh's message: the subcommands there
/// are, and the shell command of that name (`agent status` is one).
#[test]
fn an_unknown_subcommand_names_the_ones_there_are() {
    let o = run(&["agent", "status"], "");
    assert_eq!(o.status.code(), Some(2));
    let err = stderr(&o);
    assert!(err.contains("`plcsh agent` has no subcommand `status`") && err.contains("its subcommands: il"), "{err}");
    assert!(err.contains("plcsh -c 'agent status'"), "{err}");
    assert!(!err.contains("unrecognized subcommand"), "{err}");
}

/// A subcommand's help lists its own options apart from the global ones.
#[test]
fn subcommand_help_separates_its_own_options_from_the_global_ones() {
    for args in [&["completions", "--help"][..], &["sim", "serve", "--help"]] {
        let o = run(args, "");
        let text = stdout(&o);
        let (own, global) = text.split_once("Global options:").unwrap_or_else(|| panic!("{args:?}: {text}"));
        assert!(global.contains("--json") && !own.contains("--json"), "{args:?}: {text}");
    }
    let o = run(&["completions", "--help"], "");
    let own = stdout(&o).split("Global options:").next().unwrap_or("").to_string();
    assert!(own.contains("--write") && !own.contains("--model"), "{own}");
}

/// One bad profile leaves `devices` readable: the problem is a line of its own, the table's
/// rows as narrow as the devices make them.
#[test]
fn a_bad_profile_does_not_widen_the_devices_table() {
    // A folder of this test's own, made afresh.
    let dir = std::env::temp_dir().join(format!("plcsh-bad-profile-{}", std::process::id()));
    let _ = std::fs::remove_dir_all(&dir);
    std::fs::create_dir_all(&dir).unwrap();
    let file = dir.join("devices.toml");
    std::fs::write(&file, "[devices.bad]\nurl = \"nope:/x\"\n").unwrap();
    let o = run(&["--config", file.to_str().unwrap(), "devices"], "");
    assert!(o.status.success(), "{}", both(&o));
    for l in stdout(&o).lines() {
        assert!(l.chars().count() <= 100, "a row {} wide: {l}", l.chars().count());
    }
    assert_eq!(stderr(&o).matches("profile `bad` skipped").count(), 1, "once per run: {}", stderr(&o));
    let o = run(&["--json", "--config", file.to_str().unwrap(), "devices"], "");
    let j = &json_lines(&o)[0];
    assert!(j["problems"][0].as_str().is_some_and(|p| p.contains("`bad`")), "{j}");
    std::fs::remove_dir_all(&dir).unwrap();
}
