//! Links that come back: a `kinco:` or `rtu:` device whose serial port disappears (here: the
//! served pty's server stops, as when a USB adapter is unplugged) reports it in words, and
//! the next command after the port is back reopens it, as the TCP driver reconnects.

mod common;
use common::*;

use plcsh::core::Clock;
use plcsh::session::{Session, SetItem};

fn link(tag: &str) -> std::path::PathBuf {
    let d = std::env::temp_dir().join(format!("plcsh-links-{}-{tag}", std::process::id()));
    std::fs::create_dir_all(&d).unwrap();
    d.join("tty")
}

fn set(s: &mut Session, op: &str, v: &str) -> plcsh::core::Result<()> {
    s.set(&[SetItem { operand: op.into(), value: v.into(), column: 0, value_column: 0 }]).map(|_| ())
}

fn get(s: &mut Session, op: &str) -> plcsh::core::Result<i64> {
    Ok(s.get(&[op])?[0].1.value.as_i64())
}

#[test]
fn an_rtu_port_that_disappears_is_reported_and_reopened_when_back() {
    let l = link("rtu");
    let served = serve(&["--rtu-pty", l.to_str().unwrap(), "--state", "none"]);
    let mut s = Session::new(Clock::following());
    s.open("plc", &format!("rtu:{}?baud=115200&model=K205-16DT&timeout=300ms&retries=1", l.display())).unwrap();
    set(&mut s, "VW0", "7").unwrap();
    assert_eq!(get(&mut s, "VW0").unwrap(), 7);
    drop(served);
    let e = get(&mut s, "VW0").unwrap_err();
    let text = format!("{} {}", e.message, e.hint.clone().unwrap_or_default());
    assert!(
        text.contains(&l.display().to_string()) && text.contains("opens it again"),
        "the message names the port: {text}"
    );
    let _back = serve(&["--rtu-pty", l.to_str().unwrap(), "--state", "none"]);
    assert_eq!(get(&mut s, "VW0").unwrap(), 0, "the port is reopened: a fresh simulator answers");
}

#[test]
fn a_kinco_port_that_disappears_is_reported_and_reopened_when_back() {
    let l = link("kinco");
    let served = serve(&["--servo-pty", l.to_str().unwrap()]);
    let mut s = Session::new(Clock::following());
    s.open("ax", &format!("kinco:{}?id=1&timeout=300ms", l.display())).unwrap();
    set(&mut s, "target_position", "1234").unwrap();
    assert_eq!(get(&mut s, "target_position").unwrap(), 1234);
    drop(served);
    let e = get(&mut s, "target_position").unwrap_err();
    let text = format!("{} {}", e.message, e.hint.clone().unwrap_or_default());
    assert!(text.contains("gone") && text.contains(&l.display().to_string()), "{text} {e:?}");
    let _back = serve(&["--servo-pty", l.to_str().unwrap()]);
    assert_eq!(get(&mut s, "target_position").unwrap(), 0, "the port is reopened: a fresh drive answers");
}
