//! Helpers shared by the integration tests: run the real `plcsh` binary.

#![allow(dead_code)]

#[cfg(unix)]
pub mod pty_responder;

use std::io::Write;
use std::process::{Command, Output, Stdio};

/// Says that the calling test did not run its check, on the terminal even when cargo test
/// captures output (a passing test's `eprintln!` is hidden, so a skip would read as `ok`):
/// one line `skipped: needs WHAT (HOW TO GET IT)`. The test then returns.
pub fn skipped(needs: &str) {
    use std::io::Write;
    let test = std::thread::current().name().unwrap_or("a test").to_string();
    let _ = writeln!(std::io::stderr().lock(), "skipped: needs {needs} ({test})");
}

/// Path of the built binary.
pub fn bin() -> &'static str {
    env!("CARGO_BIN_EXE_plcsh")
}

/// A `plcsh` command with a private HOME (history and state files stay out of the user's).
pub fn plcsh() -> Command {
    let mut c = Command::new(bin());
    own_world(&mut c);
    c
}

/// Gives a command (plcsh, or a shell that runs plcsh) this test process's private HOME and
/// data/config folders and no state file, so nothing depends on the user's files or on
/// another plcsh running on the machine, nor on the machine's language.
pub fn own_world(c: &mut Command) -> &mut Command {
    let home = std::env::temp_dir().join(format!("plcsh-test-home-{}", std::process::id()));
    let _ = std::fs::create_dir_all(&home);
    c.env("HOME", &home).env("XDG_DATA_HOME", home.join("data")).env("XDG_CONFIG_HOME", home.join("config"));
    c.env_remove("NO_COLOR").env_remove("PLCSH_CONFIG");
    // Messages in English whatever the machine's locale (LC_ALL, LANG) or PLCSH_LANG: tests
    // that check other languages say so with --lang.
    c.env("PLCSH_LANG", "en");
    // No test touches a default state file; tests about state name theirs with --state.
    c.env("PLCSH_STATE", "none")
}

/// Starting a process, tried again when Wine fails a start with ERROR_INTERNAL_ERROR (1359),
/// which it now and then does under load for no reason of the program's (seen only in the
/// Windows stage; no other system has that code). Any other failure is returned at once.
pub trait Start {
    fn output_retrying(&mut self) -> std::io::Result<Output>;
    fn spawn_retrying(&mut self) -> std::io::Result<std::process::Child>;
}

const WINE_TRANSIENT: i32 = 1359;

impl Start for Command {
    fn output_retrying(&mut self) -> std::io::Result<Output> {
        let mut tries = Retries::new();
        loop {
            match self.output() {
                Err(e) if tries.again(&e) => continue,
                r => return r,
            }
        }
    }
    fn spawn_retrying(&mut self) -> std::io::Result<std::process::Child> {
        let mut tries = Retries::new();
        loop {
            match self.spawn() {
                Err(e) if tries.again(&e) => continue,
                r => return r,
            }
        }
    }
}

/// When a start that failed for a passing reason is tried again: Wine's transient error (four
/// times), and "text file busy" — a program the test has just copied is still open for writing
/// in a child that another test's thread forked at that instant and that has not yet exec'd;
/// it closes as soon as that child execs, so the start is tried again for up to 10 s.
struct Retries {
    wine: u32,
    until: std::time::Instant,
}

impl Retries {
    fn new() -> Retries {
        Retries { wine: 0, until: std::time::Instant::now() + std::time::Duration::from_secs(10) }
    }
    fn again(&mut self, e: &std::io::Error) -> bool {
        if e.raw_os_error() == Some(WINE_TRANSIENT) && self.wine < 4 {
            self.wine += 1;
            return true;
        }
        if e.kind() == std::io::ErrorKind::ExecutableFileBusy && std::time::Instant::now() < self.until {
            std::thread::sleep(std::time::Duration::from_millis(10));
            return true;
        }
        false
    }
}

/// Runs plcsh with `args`, feeding `stdin`.
pub fn run(args: &[&str], stdin: &str) -> Output {
    let child = plcsh()
        .args(args)
        .stdin(Stdio::piped())
        .stdout(Stdio::piped())
        .stderr(Stdio::piped())
        .spawn_retrying()
        .expect("start plcsh");
    output_with_input(child, stdin.as_bytes())
}

/// Feeds `input` to a started child (its stdin piped) and waits for its output. The input is
/// written from a thread while the output is read: the program may refuse and exit before it
/// reads its input (a broken pipe is then no failure of the test, which judges the exit status
/// and the output), and a large input must not block against a full output pipe.
pub fn output_with_input(mut child: std::process::Child, input: &[u8]) -> Output {
    let mut pipe = child.stdin.take().expect("stdin piped");
    let text = input.to_vec();
    let writer = std::thread::spawn(move || match pipe.write_all(&text) {
        Err(e) if e.kind() == std::io::ErrorKind::BrokenPipe => {}
        r => r.expect("write the program's input"),
    });
    let out = child.wait_with_output().expect("the program's output");
    writer.join().expect("the input writer");
    out
}

pub fn stdout(o: &Output) -> String {
    String::from_utf8_lossy(&o.stdout).into_owned()
}

pub fn stderr(o: &Output) -> String {
    String::from_utf8_lossy(&o.stderr).into_owned()
}

/// What a person at the terminal sees: results (stdout) then errors (stderr).
pub fn both(o: &Output) -> String {
    format!("{}{}", stdout(o), stderr(o))
}

/// Parses every stdout line as JSON.
pub fn json_lines(o: &Output) -> Vec<serde_json::Value> {
    stdout(o).lines().map(|l| serde_json::from_str(l).unwrap_or_else(|e| panic!("not JSON: {l}: {e}"))).collect()
}

/// A running `plcsh sim serve`: started with `args`, its readiness line parsed; stopped with
/// SIGTERM on drop (it then removes its symlinks). Never a fixed port or a sleep: callers
/// pass port 0 and read the bound addresses from `ready`.
pub struct Served {
    pub child: std::process::Child,
    pub ready: serde_json::Value,
}

pub fn serve(args: &[&str]) -> Served {
    use std::io::BufRead;
    let mut child = plcsh()
        .args(["sim", "serve"])
        .args(args)
        .stdout(Stdio::piped())
        .stderr(Stdio::inherit())
        .spawn_retrying()
        .expect("start plcsh sim serve");
    let mut line = String::new();
    std::io::BufReader::new(child.stdout.take().unwrap()).read_line(&mut line).expect("readiness line");
    let ready: serde_json::Value = serde_json::from_str(&line).unwrap_or_else(|e| panic!("not JSON: {line:?}: {e}"));
    assert_eq!(ready["ok"], true, "{line}");
    assert_eq!(ready["ready"], true, "{line}");
    Served { child, ready }
}

impl Drop for Served {
    fn drop(&mut self) {
        plcsh::core::platform::terminate_child(&self.child);
        let _ = self.child.wait();
    }
}

/// Opens a device URL on the wall clock, or fails the test naming the URL.
pub fn open_device(url: &str) -> Box<dyn plcsh::core::Device> {
    plcsh::session::open_url(url, &plcsh::core::Clock::following()).unwrap_or_else(|e| panic!("{url}: {e}"))
}

/// The operands `names` name on device `d`.
pub fn operands(d: &dyn plcsh::core::Device, names: &[&str]) -> Vec<plcsh::core::Operand> {
    names.iter().flat_map(|n| d.operands().parse(n).unwrap()).collect()
}

/// A python3 that has pymodbus (Debian's python3-pymodbus, installed by .ci/run), for the
/// tests that check the simulator with another client; `None` skips the test, except under CI.
pub fn pymodbus() -> Option<&'static str> {
    let ok = |p: &str| {
        Command::new(p)
            .args(["-c", "import pymodbus.client"])
            .stdout(Stdio::null())
            .stderr(Stdio::null())
            .status()
            .is_ok_and(|s| s.success())
    };
    let found = ["/usr/bin/python3", "python3"].into_iter().find(|p| ok(p));
    if found.is_none() {
        assert!(std::env::var_os("CI").is_none(), "CI must install python3-pymodbus");
        skipped("python3 with pymodbus (apt-get install python3-pymodbus)");
    }
    found
}
