//! A shell in the test's own process on a stepped clock, with JSON results: what the
//! in-process tests (data sets, servo parameter sets, wired counts) share, so each test file
//! says only what it checks.

use plcsh::core::Clock;
use plcsh::output::Style;
use plcsh::session::Session;
use plcsh::shell::Shell;
use serde_json::Value;

/// A JSON shell on a stepped session with `devices` (name, URL) open.
pub fn shell_with(devices: &[(&str, &str)]) -> Shell {
    let mut s = Session::new(Clock::stepped());
    for (name, url) in devices {
        s.open(name, url).unwrap_or_else(|e| panic!("cannot open {name} ({url}): {e}"));
    }
    Shell::new(s, Style { json: true, color: false })
}

/// Runs a line; every command must succeed. The JSON of each result.
pub fn run(sh: &mut Shell, line: &str) -> Vec<Value> {
    sh.exec(line)
        .into_iter()
        .map(|r| match r {
            Ok(o) => serde_json::to_value(&o).unwrap(),
            Err((cmd, e)) => panic!("`{line}`: {cmd} failed: {e}"),
        })
        .collect()
}

/// The error of the last command of `line` (which must fail).
#[allow(dead_code)]
pub fn error(sh: &mut Shell, line: &str) -> plcsh::core::Error {
    match sh.exec(line).pop().expect("a result") {
        Ok(o) => panic!("`{line}` succeeded: {}", serde_json::to_value(&o).unwrap()),
        Err((_, e)) => e,
    }
}
