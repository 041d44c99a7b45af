//! Device profiles through the real binary: `--config`, `PLCSH_CONFIG`, the
//! user's config directory, `connect PROFILE`, `--device PROFILE`, `plcsh devices`, write
//! rules enforced before anything reaches the device, and a bad file that does not stop the shell.

mod common;
use common::*;
use std::path::PathBuf;

fn config(name: &str, text: &str) -> PathBuf {
    let dir = std::env::temp_dir().join(format!("plcsh-profiles-{}-{name}", std::process::id()));
    std::fs::create_dir_all(&dir).unwrap();
    let f = dir.join("devices.toml");
    std::fs::write(&f, text).unwrap();
    f
}

const PROFILES: &str = r#"
[devices.press1]
url = "sim:K205-16DT"
model = "K209EA-50DX"
allow = ["VW100..VW104", "M0.0"]

[devices.viewer]
url = "sim:K205-16DT"
read_only = true
"#;

#[test]
fn connect_a_profile_and_its_allow_list_is_enforced() {
    let f = config("allow", PROFILES);
    let o = run(
        &["--config", f.to_str().unwrap(), "--json"],
        "connect press1\nuse press1\nset VW102=7\nset VW100=1, VW200=5\nget VW100 VW200 VW102 AIW10\n",
    );
    let l = json_lines(&o);
    assert_eq!(l[0]["ok"], true, "{l:?}");
    assert_eq!(l[2]["ok"], true, "VW102 is allowed");
    assert_eq!(l[3]["ok"], false);
    let err = &l[3]["error"];
    assert_eq!(err["operand"], "VW200");
    assert_eq!(err["device"], "press1");
    let msg = err["message"].as_str().unwrap();
    assert!(msg.contains("profile `press1`") && msg.contains("allow list") && msg.contains("devices.toml:2"), "{msg}");
    let v: Vec<i64> = l[4]["values"].as_array().unwrap().iter().map(|v| v["value"].as_i64().unwrap()).collect();
    assert_eq!(&v[..3], &[0, 0, 7], "the refused line wrote nothing, VW100 included");
    // `model` from the profile reached the URL: the K209EA has AIW10, the K205 has no AI.
    assert_eq!(l[4]["ok"], true);
}

#[test]
fn a_read_only_profile_given_as_device_is_current_and_refuses_writes() {
    let f = config("ro", PROFILES);
    let o =
        plcsh_env(&["--device", "viewer", "--json", "-c", "get VW0; set VW0=1"], "PLCSH_CONFIG", f.to_str().unwrap());
    let l = json_lines(&o);
    assert_eq!(l[0]["device"], "viewer", "a bare profile becomes the current device");
    assert_eq!(l[1]["ok"], false);
    assert!(l[1]["error"]["message"].as_str().unwrap().contains("read_only"));
    assert_eq!(o.status.code(), Some(1));
}

fn plcsh_env(args: &[&str], key: &str, value: &str) -> std::process::Output {
    plcsh().args(args).env(key, value).stdin(std::process::Stdio::null()).output().unwrap()
}

#[test]
fn devices_lists_profiles_and_open_devices() {
    let f = config("list", PROFILES);
    let o = run(&["devices", "--json", "--config", f.to_str().unwrap()], "");
    let l = json_lines(&o);
    let profiles: Vec<&str> =
        l[0]["profiles"].as_array().unwrap().iter().map(|p| p["name"].as_str().unwrap()).collect();
    assert_eq!(profiles, vec!["press1", "viewer"]);
    assert_eq!(l[0]["devices"][0]["name"], "plc");
    let human = stdout(&run(&["devices", "--config", f.to_str().unwrap()], ""));
    assert!(
        human.contains("viewer") && human.contains("read only") && human.contains("allow VW100..VW104, M0.0"),
        "{human}"
    );
}

#[test]
fn a_bad_file_is_reported_with_its_line_and_the_shell_still_works() {
    let f = config("bad", "[devices.ok]\nurl = \"sim:K205-16DT\"\n\n[devices.broken]\nread_only = true\n");
    let o = run(&["--config", f.to_str().unwrap(), "--json", "-c", "connect ok; set VW0=3; get VW0"], "");
    let err = String::from_utf8_lossy(&o.stderr);
    assert!(err.contains(&format!("{}:4: profile `broken` skipped: `url` is missing", f.display())), "{err}");
    let l = json_lines(&o);
    assert_eq!(l[2]["values"][0]["value"], 3, "the good profile still works");
    let f = config("syntax", "[devices.a\nurl = 1\n");
    let o = run(&["--config", f.to_str().unwrap(), "--json", "-c", "get VW0; connect a"], "");
    let err = String::from_utf8_lossy(&o.stderr);
    assert!(err.contains(&format!("{}:1: ", f.display())), "{err}");
    let l = json_lines(&o);
    assert_eq!(l[0]["ok"], true, "defaults still work");
    assert_eq!(l[1]["ok"], false);
    assert!(l[1]["error"]["message"].as_str().unwrap().contains("neither a device URL nor a profile"));
}

#[test]
fn the_default_file_is_in_the_users_config_directory() {
    // common::plcsh sets XDG_CONFIG_HOME to <private home>/config.
    let home = std::env::temp_dir().join(format!("plcsh-profiles-home-{}", std::process::id()));
    let dir = home.join("config/plcsh");
    std::fs::create_dir_all(&dir).unwrap();
    std::fs::write(dir.join("devices.toml"), PROFILES).unwrap();
    let o = plcsh()
        .env("XDG_CONFIG_HOME", home.join("config"))
        .args(["--json", "-c", "connect viewer; devices"])
        .stdin(std::process::Stdio::null())
        .output()
        .unwrap();
    let l = json_lines(&o);
    assert_eq!(l[0]["ok"], true, "{l:?}");
    assert!(l[1]["profile_file"].as_str().unwrap().ends_with("config/plcsh/devices.toml"));
}

/// Profiles are checked when loaded, against the simulator of their family and model (no
/// wire traffic): a bad allow item, an unknown scheme and an unknown model are reported at
/// start-up and in `devices` with file:line; the good profile still loads.
#[test]
fn profiles_are_checked_at_load_with_file_and_line() {
    let f = config(
        "validate",
        "[devices.good]\nurl = \"sim:K205-16DT\"\n\n[devices.badallow]\nurl = \"tcp://127.0.0.1:1\"\nallow = [\"VW100\", \"Q0.9\"]\n\n[devices.badscheme]\nurl = \"modbus://127.0.0.1:502\"\n\n[devices.badmodel]\nurl = \"rtu:/dev/null\"\nmodel = \"K999\"\n",
    );
    let o = run(&["--config", f.to_str().unwrap(), "devices"], "");
    let err = common::stderr(&o);
    let file = f.display().to_string();
    assert!(err.contains(&format!("{file}:4: profile `badallow` skipped")) && err.contains("Q0.9"), "{err}");
    assert!(err.contains(&format!("{file}:8: profile `badscheme` skipped")) && err.contains("modbus"), "{err}");
    assert!(err.contains(&format!("{file}:11: profile `badmodel` skipped")) && err.contains("K999"), "{err}");
    let out = stdout(&o);
    // The listing names the good profile; the problems are lines of their own (notes).
    assert!(out.contains("good") && !out.contains(&format!("{file}:4")), "{out}");
    assert_eq!(err.matches(&format!("{file}:4: profile `badallow` skipped")).count(), 1, "once: {err}");
}

#[test]
fn a_missing_config_file_is_an_error() {
    let o = run(&["--config", "/nonexistent/devices.toml", "-c", "get VW0"], "");
    assert_eq!(o.status.code(), Some(2));
    assert!(common::stderr(&o).contains("/nonexistent/devices.toml: no such file"), "{}", common::stderr(&o));
    assert!(stdout(&o).is_empty());
}

/// The README's own `devices.toml` loads without a problem (checked against the offline
/// twins, so the serial ports it names need not exist).
#[test]
fn the_readme_profile_example_loads_cleanly() {
    // The user guide's profile example (docs/at-the-machine.md, linked from the README).
    let readme = std::fs::read_to_string(concat!(env!("CARGO_MANIFEST_DIR"), "/docs/at-the-machine.md")).unwrap();
    let at = readme.find("**Device profiles**").expect("the profiles section");
    let block = &readme[at..];
    let start = block.find("```toml\n").expect("a toml example") + "```toml\n".len();
    let example = &block[start..start + block[start..].find("```").unwrap()];
    assert!(example.contains("[devices.axis1.options]"), "{example}");
    let f = config("readme", example);
    let o = run(&["--config", f.to_str().unwrap(), "devices", "--json"], "");
    assert!(common::stderr(&o).is_empty(), "{}", common::stderr(&o));
    let l = json_lines(&o);
    assert!(l[0].get("problems").is_none(), "{l:?}");
    let names: Vec<&str> = l[0]["profiles"].as_array().unwrap().iter().map(|p| p["name"].as_str().unwrap()).collect();
    assert_eq!(names, vec!["axis1", "press1"]);
}

/// `[options]` are checked against the family of the profile's device when the file is
/// loaded: an option the family does not have, or a value it refuses, skips the profile with
/// its file:line at start-up and in `devices`, naming the options the family has.
#[test]
fn profile_options_are_checked_against_their_family_at_load() {
    let f = config(
        "options",
        "[devices.axis1]\nurl = \"kinco:/dev/ttyUSB1?id=1\"\n[devices.axis1.options]\nword_order = \"swapped\"\n\n\
         [devices.press1]\nurl = \"tcp://127.0.0.1:1\"\n[devices.press1.options]\nword_order = \"swapped\"\n\n\
         [devices.press2]\nurl = \"rtu:/dev/null\"\n[devices.press2.options]\nword_order = \"low-first\"\nretries = 3\n\n\
         [devices.fx1]\nurl = \"fx:/dev/null\"\n[devices.fx1.options]\nretries = 99\n\n\
         [devices.trainer]\nurl = \"sim-umpk:UMPK16\"\n[devices.trainer.options]\nencoder = 4096\n\n\
         [devices.bench]\nurl = \"sim:K205-16DT\"\n[devices.bench.options]\nretain = \"VB0..VB9\"\n",
    );
    let file = f.display().to_string();
    let o = run(&["--config", &file, "devices", "--json"], "");
    let err = common::stderr(&o);
    for (line, name, says) in [
        (1, "axis1", "servo devices have no option `word_order`"),
        (6, "press1", "`word_order=swapped` is not a word order"),
        (17, "fx1", "retries `99` must be 0–10"),
        (22, "trainer", "UMPK devices have no option `encoder`"),
    ] {
        assert!(err.contains(&format!("{file}:{line}: profile `{name}` skipped: [options] ")), "{name}: {err}");
        assert!(err.contains(says), "{says}: {err}");
    }
    assert!(err.contains("options: encoder, timeout"), "the servo's options are named: {err}");
    let l = json_lines(&o);
    let names: Vec<&str> = l[0]["profiles"].as_array().unwrap().iter().map(|p| p["name"].as_str().unwrap()).collect();
    assert_eq!(names, vec!["bench", "press2"], "the good profiles load");
    let problems = l[0]["problems"].as_array().unwrap();
    assert_eq!(problems.len(), 4, "`devices` lists every problem: {problems:?}");
    assert!(problems[0].as_str().unwrap().starts_with(&format!("{file}:1: profile `axis1` skipped")), "{problems:?}");
}

/// A profile's other keys become URL parameters: one its family does not take (a typo) is
/// found at load too, naming the parameters there are; the family's own ones load.
#[test]
fn profile_url_parameters_are_checked_against_their_family_at_load() {
    let f = config(
        "params",
        "[devices.axis1]\nurl = \"kinco:/dev/ttyUSB1?id=1\"\nencodr = 65536\n\n\
         [devices.axis2]\nurl = \"kinco:/dev/ttyUSB1?id=2\"\nencoder = 65536\n\n\
         [devices.press1]\nurl = \"tcp://127.0.0.1:1\"\nbaud = 9600\n\n\
         [devices.press2]\nurl = \"rtu:/dev/null\"\nbaud = 9600\nparity = \"even\"\n",
    );
    let file = f.display().to_string();
    let o = run(&["--config", &file, "devices", "--json"], "");
    let err = common::stderr(&o);
    assert!(err.contains(&format!("{file}:1: profile `axis1` skipped: unknown parameter `encodr`")), "{err}");
    assert!(err.contains("known: id, baud, echo, loop, timeout, encoder, control"), "{err}");
    assert!(
        err.contains(&format!("{file}:9: profile `press1` skipped: unknown parameter `baud`")),
        "a TCP K2 has no baud: {err}"
    );
    let l = json_lines(&o);
    let names: Vec<&str> = l[0]["profiles"].as_array().unwrap().iter().map(|p| p["name"].as_str().unwrap()).collect();
    assert_eq!(names, vec!["axis2", "press2"]);
}
