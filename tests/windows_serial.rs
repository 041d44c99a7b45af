//! plcsh for Windows on COM ports, end to end under Wine (run by `.ci/windows`): the Windows
//! build opens `COM5`/`COM6`, which Wine maps onto the pseudo-terminals a Linux `plcsh sim
//! serve` serves a K2 (Modbus RTU) and a Kinco drive line on (`.ci/wine/serve-com`). Reads,
//! writes and a servo move go through the Windows serial code (`serialport`'s COMPort, the
//! transport layer's Windows corner) against the real simulators.
//!
//! Elsewhere (a native build, or no mapping) the tests say why and pass without running:
//! they need `PLCSH_WINE_COM_K2` and `PLCSH_WINE_COM_SERVO` (the COM names), set by the stage.

#[path = "support/words.rs"]
mod words;
use plcsh::core::{Clock, Device, Value};
use plcsh::session::open_url;

/// The tests share COM5/COM6 and one served pair of simulators (and one stops them): one at a time.
static ONE_AT_A_TIME: std::sync::Mutex<()> = std::sync::Mutex::new(());

fn serial_guard() -> std::sync::MutexGuard<'static, ()> {
    ONE_AT_A_TIME.lock().unwrap_or_else(|p| p.into_inner())
}

/// One `skipped: needs …` line on the terminal even when cargo test captures output.
fn skipped(var: &str) {
    use std::io::Write;
    let _ = writeln!(
        std::io::stderr().lock(),
        "skipped: needs {var}, set by .ci/windows when it maps COM ports under Wine"
    );
}

fn com(var: &str) -> Option<String> {
    let v = std::env::var(var).ok().filter(|v| !v.is_empty());
    if v.is_none() {
        assert!(
            std::env::var_os("PLCSH_WINE").is_none() || std::env::var_os("CI").is_none(),
            "{var} must be set by .ci/windows when the tests run under Wine in CI"
        );
        skipped(var);
    }
    v
}

fn open(url: &str) -> Box<dyn Device> {
    open_url(url, &Clock::following()).unwrap_or_else(|e| panic!("{url}: {e}"))
}

fn ops(d: &dyn Device, names: &[&str]) -> Vec<plcsh::core::Operand> {
    names.iter().flat_map(|n| d.operands().parse(n).unwrap()).collect()
}

#[test]
fn k2_over_modbus_rtu_on_a_com_port() {
    let _one = serial_guard();
    let Some(port) = com("PLCSH_WINE_COM_K2") else { return };
    let mut d = open(&format!("rtu:{port}?baud=19200&unit=1&timeout=2s"));
    assert!(d.info().link.contains(&port), "{}", d.info().link);
    let o = ops(d.as_ref(), &["VW200", "VD204", "Q0.0"]);
    d.write(&[(o[0], Value::Int(1234)), (o[1], Value::Int(4_000_000_000)), (o[2], Value::Bool(true))]).unwrap();
    assert_eq!(d.read(&o).unwrap(), vec![Value::Int(1234), Value::Int(4_000_000_000), Value::Bool(true)]);
}

#[test]
fn servo_move_on_a_com_port() {
    let _one = serial_guard();
    let Some(port) = com("PLCSH_WINE_COM_SERVO") else { return };
    let mut d = open(&format!("kinco:{port}?id=1&baud=38400&timeout=2s"));
    let o = ops(d.as_ref(), &["statusword", "target_velocity"]);
    assert_eq!(d.read(&o[..1]).unwrap(), vec![Value::Int(0x4231)]);
    d.write(&[(o[1], Value::Int(-5))]).unwrap();
    assert_eq!(d.read(&o[1..]).unwrap(), vec![Value::Int(-5)]);
    let never = std::sync::atomic::AtomicBool::new(false);
    let w = plcsh::servo::ds402::Waiter { clock: Clock::following(), interrupt: &never };
    let ops: &mut dyn plcsh::servo::ServoOps = &mut plcsh::servo::ops(d.as_mut()).unwrap();
    plcsh::servo::ds402::enable(ops, &w).unwrap();
    let speed = plcsh::servo::ds402::Profile { speed: Some(819_200), ..Default::default() };
    plcsh::servo::ds402::move_to(ops, &w, false, 10_000, speed).unwrap();
    assert_eq!(plcsh::servo::ds402::status(ops).unwrap().state, "operation enabled");
}

/// Asks `.ci/windows`'s watcher for `what` (`stop` or `start`) and waits for it to be done.
fn ask_serve(dir: &str, what: &str, done: &str) {
    let dir = std::path::Path::new(dir);
    let _ = std::fs::remove_file(dir.join(done));
    std::fs::write(dir.join(format!("{what}.request")), b"").unwrap();
    let until = std::time::Instant::now() + std::time::Duration::from_secs(30);
    while !dir.join(done).exists() {
        assert!(std::time::Instant::now() < until, "the CI watcher did not {what} the served simulators");
        std::thread::sleep(std::time::Duration::from_millis(20));
    }
}

/// The link disappears (the served simulators stop, their ptys vanish: what an unplugged
/// USB adapter is to COM5) and comes back on new ptys: the failure names the port and says the
/// next command reopens it; once back, the same device works without being opened again.
#[test]
fn a_com_link_that_disappears_is_reported_and_reopened_when_back() {
    let _one = serial_guard();
    let (Some(k2), Some(servo)) = (com("PLCSH_WINE_COM_K2"), com("PLCSH_WINE_COM_SERVO")) else { return };
    let Ok(dir) = std::env::var("PLCSH_WINE_SERVE_DIR") else { return };
    let mut plc = open(&format!("rtu:{k2}?baud=19200&unit=1&timeout=500ms&retries=1"));
    let mut drive = open(&format!("kinco:{servo}?id=1&baud=38400&timeout=500ms"));
    let o = ops(plc.as_ref(), &["VW300"]);
    let sw = ops(drive.as_ref(), &["statusword"]);
    plc.write(&[(o[0], Value::Int(77))]).unwrap();
    assert_eq!(drive.read(&sw).unwrap(), vec![Value::Int(0x4231)]);
    ask_serve(&dir, "stop", "stopped");
    let e = plc.read(&o).unwrap_err();
    let text = format!("{} {}", e.message, e.hint.clone().unwrap_or_default());
    assert!(text.contains(&k2) && text.contains("opens it again"), "{text}");
    let e = drive.read(&sw).unwrap_err();
    assert_eq!(e.kind, plcsh::core::ErrorKind::Link, "{e}");
    ask_serve(&dir, "start", "started");
    // A new simulator: its memory starts empty; writing and reading back proves the link.
    plc.write(&[(o[0], Value::Int(78))]).unwrap();
    assert_eq!(plc.read(&o).unwrap(), vec![Value::Int(78)]);
    assert_eq!(drive.read(&sw).unwrap(), vec![Value::Int(0x4231)]);
}

/// The README's Windows first session, run as written with this machine's ports in place of
/// the README's (COM3 → the served K2, COM10 → the served drive line): every `PS> plcsh …`
/// line of that section succeeds with the Windows build.
#[test]
fn the_readme_windows_session_runs() {
    let _one = serial_guard();
    let (Some(k2), Some(servo)) = (com("PLCSH_WINE_COM_K2"), com("PLCSH_WINE_COM_SERVO")) else { return };
    let readme = std::fs::read_to_string(concat!(env!("CARGO_MANIFEST_DIR"), "/docs/install.md")).unwrap();
    let section = readme.split("## Windows: a first session at the machine").nth(1).unwrap();
    let section = section.split("\n## ").next().unwrap();
    let lines: Vec<&str> = section.lines().filter_map(|l| l.strip_prefix("PS> plcsh ")).collect();
    assert!(lines.len() >= 3, "the section shows a session: {lines:?}");
    for line in lines {
        let line = line.replace("COM10", &servo).replace("COM3", &k2);
        let args = words::split(&line);
        let o = std::process::Command::new(env!("CARGO_BIN_EXE_plcsh"))
            .args(&args)
            .env("PLCSH_STATE", "none")
            .env("PLCSH_LANG", "en")
            .output()
            .unwrap();
        let text = format!("{}{}", String::from_utf8_lossy(&o.stdout), String::from_utf8_lossy(&o.stderr));
        assert!(o.status.success(), "plcsh {line}: {text}");
    }
}
