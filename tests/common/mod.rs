//! Helpers shared by the integration tests: run the real `plcsh` binary.

#![allow(dead_code)]

use std::io::Write;
use std::process::{Command, Output, Stdio};

/// Path of the built binary.
pub fn bin() -> &'static str {
    env!("CARGO_BIN_EXE_plcsh")
}

/// A `plcsh` command with a private HOME (history and state files stay out of the user's).
pub fn plcsh() -> Command {
    let mut c = Command::new(bin());
    let home = std::env::temp_dir().join(format!("plcsh-test-home-{}", std::process::id()));
    let _ = std::fs::create_dir_all(&home);
    c.env("HOME", &home).env("XDG_DATA_HOME", home.join("data")).env("XDG_CONFIG_HOME", home.join("config"));
    c.env_remove("NO_COLOR").env_remove("PLCSH_CONFIG");
    c
}

/// Runs plcsh with `args`, feeding `stdin`.
pub fn run(args: &[&str], stdin: &str) -> Output {
    let mut child = plcsh()
        .args(args)
        .stdin(Stdio::piped())
        .stdout(Stdio::piped())
        .stderr(Stdio::piped())
        .spawn()
        .expect("start plcsh");
    child.stdin.take().unwrap().write_all(stdin.as_bytes()).unwrap();
    child.wait_with_output().expect("plcsh output")
}

pub fn stdout(o: &Output) -> String {
    String::from_utf8_lossy(&o.stdout).into_owned()
}

/// Parses every stdout line as JSON.
pub fn json_lines(o: &Output) -> Vec<serde_json::Value> {
    stdout(o).lines().map(|l| serde_json::from_str(l).unwrap_or_else(|e| panic!("not JSON: {l}: {e}"))).collect()
}
