//! Kinco servo end to end: the driver over a REAL pseudo-terminal against the
//! simulator served by the real binary (`plcsh sim serve --servo-pty`, readiness line
//! awaited, never a sleep), and one-shot commands against the in-process simulator.
// Unix only: real pseudo-terminals (Windows has none; its COM ports are tested under Wine
// in tests/windows_serial.rs).
#![cfg(unix)]

mod common;
use common::*;
use plcsh::core::{Clock, Device, ErrorKind, Value};
use plcsh::servo::ds402::{self, Profile, Waiter};
use plcsh::servo::frame::Frame;
use plcsh::servo::objects::{self, ObjRef};
use plcsh::servo::ServoOps;
use plcsh::session::open_url;
use std::path::PathBuf;
use std::sync::atomic::AtomicBool;
use std::time::Duration;

/// A served drive simulator on a pty symlinked in a private directory.
struct Server {
    _served: Served,
    link: PathBuf,
    ready: serde_json::Value,
}

impl Server {
    fn start(tag: &str, extra: &[&str]) -> Server {
        let dir = std::env::temp_dir().join(format!("plcsh-servo-{}-{tag}", std::process::id()));
        std::fs::create_dir_all(&dir).unwrap();
        let link = dir.join("ttyKINCO");
        let mut args = vec!["--servo-pty", link.to_str().unwrap()];
        args.extend_from_slice(extra);
        let served = serve(&args);
        let ready = served.ready.clone();
        Server { _served: served, link, ready }
    }

    fn url(&self, params: &str) -> String {
        format!("kinco:{}?{params}", self.link.display())
    }
}

fn open(url: &str) -> Box<dyn Device> {
    open_url(url, &Clock::following()).unwrap_or_else(|e| panic!("{url}: {e}"))
}

#[test]
fn enable_move_wait_and_read_back_over_a_real_pty() {
    let srv = Server::start("move", &["--servo-id", "1,2"]);
    assert_eq!(srv.ready["ids"], serde_json::json!([1, 2]));
    assert!(srv.ready["servo_pty"]["path"].as_str().unwrap().starts_with("/dev/pts/"));
    let mut d = open(&srv.url("id=2&baud=38400"));
    let never = AtomicBool::new(false);
    let w = Waiter { clock: Clock::following(), interrupt: &never };
    let ops: &mut dyn plcsh::servo::ServoOps = &mut plcsh::servo::ops(d.as_mut()).unwrap();
    assert_eq!(ds402::enable(ops, &w).unwrap().len(), 3);
    assert_eq!(ds402::status(ops).unwrap().state, "operation enabled");
    // 300 rpm at R = 10000 is 819200 DEC.
    let speed = Profile { speed: Some(819_200), ..Profile::default() };
    ds402::move_to(ops, &w, false, 10_000, speed).unwrap();
    let sw = ds402::wait_target(ops, &w, Duration::from_secs(5)).unwrap();
    assert_ne!(sw & (1 << 10), 0);
    let pos = d.operands().parse("position_actual").unwrap()[0];
    assert_eq!(d.read(&[pos]).unwrap(), vec![Value::Int(10_000)]);
    // Drive 1 on the same line was not touched. (Both devices share one open port: a second
    // open of the exclusive port would fail, so this also shows the line registry at work.)
    let mut d1 = open(&srv.url("id=1"));
    assert_eq!(d1.read(&[pos]).unwrap(), vec![Value::Int(0)]);
}

#[test]
fn silence_over_a_pty_is_diagnosed_and_the_link_recovers() {
    let srv = Server::start("silence", &[]);
    // Both devices are open at once and share the port (this process never reopens a port
    // it closed: a child forked meanwhile by a parallel test could still hold its lock).
    let mut wrong = open(&srv.url("id=7&timeout=150ms"));
    let mut d = open(&srv.url("id=1&timeout=150ms"));
    // Wrong id: nothing answers id 7.
    let sw = wrong.operands().parse("statusword").unwrap()[0];
    let e = wrong.read(&[sw]).unwrap_err();
    assert_eq!(e.kind, ErrorKind::Link);
    assert!(e.message.contains("likely cause: wrong id"), "{e}");
    assert!(e.hint.as_deref().unwrap().contains("(3) a bad checksum"), "{e:?}");
    // Bad checksum: the served drive ignores the frame.
    let mut bad = Frame::read(1, 0x6041, 0).to_bytes();
    bad[9] ^= 0x55;
    let e = plcsh::servo::ops(d.as_mut()).unwrap().raw_frame(bad).unwrap_err();
    assert_eq!(e.kind, ErrorKind::Link);
    assert!(e.message.contains("likely cause: bad checksum"), "{e}");
    // Unknown object: the id answers its statusword, so the object is the likely cause.
    let unknown = d.operands().parse("3FFF.01/u16").unwrap()[0];
    let e = d.read(&[unknown]).unwrap_err();
    assert!(e.message.contains("likely cause: unknown object"), "{e}");
    // The link is still in step: the same frame with its right checksum is answered.
    let good = plcsh::servo::ops(d.as_mut()).unwrap().raw_frame(Frame::read(1, 0x6041, 0).to_bytes()).unwrap();
    assert_eq!(good, [0x01, 0x4B, 0x41, 0x60, 0x00, 0x31, 0x42, 0x00, 0x00, 0xA0], "the manual's reply");
}

#[test]
fn read_only_write_gets_the_abort_code_in_words_over_a_pty() {
    let srv = Server::start("abort", &[]);
    // Through the binary's `servo raw`, as JSON (first: the port is exclusive, and this
    // process opens it below).
    let o =
        run(&["-d", &format!("ax={}", srv.url("id=1")), "--json", "-c", "servo ax raw 01 2B 41 60 00 01 00 00 00"], "");
    let l = json_lines(&o);
    assert_eq!(l[0]["abort_code"], 0x0601_0002, "{l:?}");
    assert_eq!(l[0]["abort"], "attempt to write a read-only object");
    let mut d = open(&srv.url("id=1"));
    // The table refuses it before sending …
    let sw = d.operands().parse("statusword").unwrap()[0];
    assert_eq!(d.write(&[(sw, Value::Int(1))]).unwrap_err().kind, ErrorKind::Unsupported);
    assert_eq!(d.requests(), 0);
    // … and the drive itself answers 0x80 with 0x06010002 when asked anyway.
    let e = plcsh::servo::ops(d.as_mut()).unwrap().write_raw(ObjRef::of(objects::named("statusword")), 1).unwrap_err();
    assert_eq!(e.kind, ErrorKind::Refused);
    assert!(e.message.contains("16#06010002 — attempt to write a read-only object"), "{e}");
}

#[test]
fn the_binary_drives_a_served_drive_in_loop_mode() {
    let srv = Server::start("loop", &["--servo-loop", "--servo-id", "3"]);
    assert_eq!(srv.ready["echo"], true);
    let dev = format!("ax={}", srv.url("id=3&echo=1"));
    let o = run(
        &[
            "-d",
            &dev,
            "--json",
            "-c",
            "servo ax enable; servo ax move rel -2500 speed=600rpm acc=1000rps/s dec=1000rps/s; servo ax wait target timeout=5s; get ax:position_actual ax:profile_velocity",
        ],
        "",
    );
    assert!(o.status.success(), "{}", stdout(&o));
    let l = json_lines(&o);
    assert_eq!(l[3]["values"][0]["value"], -2500);
    assert_eq!(l[3]["values"][1]["value"], 1_638_400, "600 rpm at R = 10000");
    // Without echo=1 the echo is taken for the reply, and that is a link error.
    let o = run(&["-d", &format!("ax={}", srv.url("id=3")), "--json", "-c", "get ax:statusword"], "");
    let l = json_lines(&o);
    assert_eq!(l[0]["error"]["kind"], "link", "{l:?}");
}

#[test]
fn one_shot_move_against_the_in_process_simulator_returns_the_target() {
    let o = run(
        &[
            "-c",
            "servo enable; servo move abs 10000 speed=300rpm; servo wait target timeout=5s; get servo:position_actual",
            "--json",
        ],
        "",
    );
    assert!(o.status.success(), "{}", stdout(&o));
    let l = json_lines(&o);
    assert_eq!(l.len(), 4);
    assert_eq!(l[3]["values"][0], serde_json::json!({"operand": "position_actual", "value": 10000, "type": "DINT"}));
}

#[test]
fn stepped_time_makes_the_wait_virtual() {
    // 10000 inc at 300 rpm with the default 100 rps/s ramps takes 0.25 s of virtual time;
    // on a stepped clock the wait advances it instead of sleeping.
    let o = run(
        &[
            "--time",
            "stepped",
            "--json",
            "-c",
            "servo enable; servo move abs 10000 speed=300rpm; servo wait target timeout=5s; sim time",
        ],
        "",
    );
    let l = json_lines(&o);
    let waited = l[2]["waited_s"].as_f64().unwrap();
    assert!((0.25..=0.26).contains(&waited), "{waited}");
    assert_eq!(l[2]["position_actual"], 10000);
    // A wait that cannot succeed times out in virtual time too.
    let o = run(
        &[
            "--time",
            "stepped",
            "--json",
            "-c",
            "servo enable; servo jog 0; servo sim fault; servo wait target timeout=1s",
        ],
        "",
    );
    let l = json_lines(&o);
    assert_eq!(l[3]["error"]["kind"], "state", "{l:?}");
}

#[test]
fn units_and_refusals_from_the_command_line() {
    let o = run(
        &[
            "--json",
            "-c",
            "set servo:target_velocity=300rpm, servo:profile_acceleration=100rps/s; servo read target_velocity profile_acceleration",
        ],
        "",
    );
    let l = json_lines(&o);
    assert_eq!(l[1]["objects"][0]["value"], 819_200);
    assert_eq!(l[1]["objects"][0]["eng"], 300.0);
    assert_eq!(l[1]["objects"][0]["eng_unit"], "rpm");
    assert_eq!(l[1]["objects"][1]["value"], 16_384);
    let o = run(
        &[
            "--json",
            "-d",
            "servo=sim-servo:?id=1&encoder=65536",
            "-c",
            "set servo:target_velocity=1rpm; get servo:target_velocity",
        ],
        "",
    );
    assert_eq!(json_lines(&o)[1]["values"][0]["value"], 17_896);
    let o = run(&["--json", "-c", "set servo:statusword=1"], "");
    let l = json_lines(&o);
    assert_eq!(l[0]["error"]["kind"], "unsupported");
    assert!(l[0]["error"]["message"].as_str().unwrap().contains("read-only"));
}

#[test]
fn state_machine_commands_from_the_shell() {
    let o = run(
        &[
            "--time",
            "stepped",
            "--json",
            "-c",
            "servo status; servo enable; servo jog 60rpm; sim step 1s; servo quickstop; servo disable; servo enable; servo sim fault 16#2310; servo status; servo fault-reset; servo fault-reset; servo mode homing; get servo:error_code",
        ],
        "",
    );
    let l = json_lines(&o);
    assert!(o.status.success(), "{l:?}");
    assert_eq!(l[0]["state"], "ready to switch on");
    assert_eq!(l[0]["statusword"], 0x4231);
    assert_eq!(l[4]["state"], "quick stop active");
    assert_eq!(l[5]["state"], "switch on disabled", "disable from quick stop is disable voltage");
    assert_eq!(l[8]["state"], "fault");
    assert_eq!(l[8]["fault"], true);
    assert_eq!(l[8]["bits"][0], serde_json::json!({"bit": 3, "name": "fault"}));
    assert_eq!(l[9]["state"], "switch on disabled");
    assert_eq!(l[10]["state"], "switch on disabled", "no fault: left alone");
    assert_eq!(l[11]["mode"], 6);
    assert_eq!(l[12]["values"][0]["value"], 0, "error code cleared by the reset");
}
