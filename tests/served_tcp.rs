//! Every serial family's simulator served on a TCP port (`sim serve --rtu-tcp --servo-tcp
//! --fx-tcp --fx-link-tcp --umpk-tcp`), reached with `FAMILY+tcp://` as through a serial device
//! server's raw channel: how simulators are served on Windows, which has no pseudo-terminals.
//! Portable: it runs on Linux and, in `.ci/windows`, under Wine (the Windows build serving
//! and the Windows build connecting).

mod common;
use common::*;
use plcsh::core::Value;

use common::{open_device as open, operands as ops};

#[test]
fn every_serial_family_is_served_on_tcp_and_reached_with_plus_tcp() {
    let dir = std::env::temp_dir().join(format!("plcsh-served-tcp-{}", std::process::id()));
    std::fs::create_dir_all(&dir).unwrap();
    let ctl = dir.join("drive.ctl");
    let umpk_state = dir.join("umpk.json");
    let srv = serve(&[
        "--rtu-tcp",
        "0",
        "--servo-tcp",
        "0",
        "--servo-instant",
        "--servo-control",
        ctl.to_str().unwrap(),
        "--fx-tcp",
        "0",
        "--fx-link-tcp",
        "0",
        "--umpk-tcp",
        "0",
        "--umpk-state",
        umpk_state.to_str().unwrap(),
    ]);
    let r = &srv.ready;
    let addr = |k: &str| r[k].as_str().unwrap_or_else(|| panic!("{k} in {r}")).to_string();

    let mut k2 = open(&format!("rtu+tcp://{}?unit=1", addr("rtu_tcp")));
    let o = ops(k2.as_ref(), &["VW10"]);
    k2.write(&[(o[0], Value::Int(321))]).unwrap();
    assert_eq!(k2.read(&o).unwrap(), vec![Value::Int(321)]);

    let mut drive = open(&format!("kinco+tcp://{}?id=1&control={}", addr("servo_tcp"), ctl.display()));
    let sw = ops(drive.as_ref(), &["statusword"]);
    assert_eq!(drive.read(&sw).unwrap(), vec![Value::Int(0x4231)]);

    let mut fx = open(&format!("fx+tcp://{}?model=FX2N", addr("fx_tcp")));
    let d = ops(fx.as_ref(), &["D100"]);
    fx.write(&[(d[0], Value::Int(-12))]).unwrap();
    let mut link = open(&format!("fxlink+tcp://{}?station=0&model=FX2N", addr("fx_link_tcp")));
    assert_eq!(link.read(&d).unwrap(), vec![Value::Int(-12)], "one PLC behind both ports");

    let umpk = open(&format!("umpk+tcp://{}", addr("umpk_tcp")));
    assert!(umpk.info().model.starts_with("UMPK"), "{}", umpk.info().model);
    drop(umpk);

    // The drive line has one client at a time: this process lets it go for the next one.
    drop(drive);

    // The drive line's control channel works for a TCP-served line too (`servo sim`).
    let o = run(
        &[
            "--json",
            "-d",
            // A generous reply timeout: the served line is paced like RS232, and a loaded machine
            // can delay a reply past the default; this is about the control channel, not timing.
            &format!("axis=kinco+tcp://{}?id=1&timeout=2s&control={}", addr("servo_tcp"), ctl.display()),
            "-c",
            "servo sim fault 16#2310; get axis:error_code",
        ],
        "",
    );
    let l = json_lines(&o);
    assert_eq!(l[0]["ok"], true, "{l:?} {}", stderr(&o));
    assert_eq!(l[1]["values"][0]["value"], 0x2310, "{l:?}");
}

/// Another program (here a second plcsh) cannot take a line a client holds, as with a COM port
/// another program has open; it gets the line once the first lets go. (Devices in one process
/// on one line share it: several drives on one RS232 line.)
#[test]
fn a_tcp_served_line_has_one_client_at_a_time() {
    let srv = serve(&["--servo-tcp", "0", "--servo-instant"]);
    let addr = srv.ready["servo_tcp"].as_str().unwrap().to_string();
    let mut first = open(&format!("kinco+tcp://{addr}?id=1"));
    let sw = ops(first.as_ref(), &["statusword"]);
    assert_eq!(first.read(&sw).unwrap(), vec![Value::Int(0x4231)]);
    let url = format!("axis=kinco+tcp://{addr}?id=1&timeout=300ms");
    let o = run(&["--json", "-d", &url, "-c", "get axis:statusword"], "");
    assert_eq!(json_lines(&o)[0]["error"]["kind"], "link", "{}", both(&o));
    assert_eq!(first.read(&sw).unwrap(), vec![Value::Int(0x4231)], "the first client is undisturbed");
    drop(first);
    let o = run(&["--json", "-d", &url, "-c", "get axis:statusword"], "");
    assert_eq!(json_lines(&o)[0]["values"][0]["value"], 0x4231, "the line is free again: {}", both(&o));
}

/// docs/reference/first-connection.md and docs/safety.md say what the prompt shows for a real
/// device opened by a profile's name: its name alone, `press1>` (a simulator's says `(sim)`).
#[test]
fn the_prompt_of_a_real_device_is_as_the_first_connection_page_says() {
    let served = serve(&["--tcp", "0", "--state", "none"]);
    let mut s = plcsh::session::Session::new(plcsh::core::Clock::following());
    s.open("press1", &format!("tcp://{}?model=K205-16DT", served.ready["tcp"].as_str().unwrap())).unwrap();
    let prompt = plcsh::shell::repl::prompt(&s);
    assert_eq!(prompt, "press1> ");
    let page =
        std::fs::read_to_string(concat!(env!("CARGO_MANIFEST_DIR"), "/docs/reference/first-connection.md")).unwrap();
    assert!(page.contains(&format!("the prompt says `{}`", prompt.trim_end())), "the page names another prompt");
    assert!(!page.contains("(real)`"), "no `(real)` prompt on the page");
}
