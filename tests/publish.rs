//! `plcsh publish` against a real broker: mosquitto, started here on a free loopback port with a
//! generated configuration and waited for by connecting; a subscriber written here (rumqttc)
//! checks topics, payloads, retained values, device and publisher status, and — across a broker
//! restart — that readings taken while the broker was away arrive, all of them, in order.
//! Without mosquitto the tests are skipped (CI installs it: .ci/run).
#![cfg(unix)]

mod common;
use common::*;
use std::io::BufRead;
use std::path::{Path, PathBuf};
use std::process::{Child, Command, Stdio};
use std::sync::{Arc, Mutex};
use std::time::{Duration, Instant};

/// The broker's program: on PATH, or where Debian puts it (/usr/sbin is not on every user's PATH).
fn mosquitto() -> &'static str {
    let runs = |p: &str| Command::new(p).arg("-h").stdout(Stdio::null()).stderr(Stdio::null()).status().is_ok();
    if runs("mosquitto") {
        "mosquitto"
    } else {
        "/usr/sbin/mosquitto"
    }
}

fn mosquitto_present() -> bool {
    let found = Command::new(mosquitto()).arg("-h").stdout(Stdio::null()).stderr(Stdio::null()).status().is_ok();
    if !found {
        assert!(std::env::var_os("CI").is_none(), "mosquitto is required when CI is set (.ci/run installs it)");
        common::skipped("mosquitto (apt-get install mosquitto)");
    }
    found
}

fn dir(name: &str) -> PathBuf {
    use std::os::unix::fs::PermissionsExt;
    let d = std::env::temp_dir().join(format!("plcsh-publish-{}-{name}", std::process::id()));
    let _ = std::fs::remove_dir_all(&d);
    std::fs::create_dir_all(&d).unwrap();
    // Started as root, mosquitto runs as its own user: it must be able to write its database here.
    std::fs::set_permissions(&d, std::fs::Permissions::from_mode(0o777)).unwrap();
    d
}

/// The broker's `user` line: run as root, mosquitto drops to the `mosquitto` user, which cannot
/// read files in a private temporary folder (a TMPDIR of mode 0700, as CI's own); it keeps
/// the test's user instead. Run as anyone else, mosquitto stays that user anyway.
fn broker_user() -> &'static str {
    if unsafe { libc::geteuid() } == 0 {
        "user root\n"
    } else {
        ""
    }
}

/// A mosquitto on `port` with its database in `dir` (sessions and queued messages survive a
/// restart), ready once it accepts a connection.
struct Broker {
    child: Child,
}

impl Broker {
    fn start(dir: &Path, port: u16) -> Broker {
        Broker::start_with(dir, port, "")
    }

    /// The same, with more lines of configuration.
    fn start_with(dir: &Path, port: u16, more: &str) -> Broker {
        let conf = dir.join("mosquitto.conf");
        std::fs::write(
            &conf,
            format!(
                "{}listener {port} 127.0.0.1\nallow_anonymous true\nmax_queued_messages 0\npersistence true\npersistence_location {}/\nautosave_interval 0\n{more}",
                broker_user(),
                dir.display()
            ),
        )
        .unwrap();
        let child =
            Command::new(mosquitto()).arg("-c").arg(&conf).stdout(Stdio::null()).stderr(Stdio::null()).spawn().unwrap();
        let deadline = Instant::now() + Duration::from_secs(10);
        while std::net::TcpStream::connect(("127.0.0.1", port)).is_err() {
            assert!(Instant::now() < deadline, "mosquitto did not start on port {port}");
            std::thread::sleep(Duration::from_millis(10));
        }
        Broker { child }
    }

    /// SIGTERM (mosquitto saves its database), then waits for it to exit.
    fn stop(mut self) {
        plcsh::core::platform::terminate_child(&self.child);
        let _ = self.child.wait();
    }
}

impl Drop for Broker {
    fn drop(&mut self) {
        let _ = self.child.kill();
        let _ = self.child.wait();
    }
}

/// A free loopback port: bound to 0, then released for the broker.
fn free_port() -> u16 {
    std::net::TcpListener::bind("127.0.0.1:0").unwrap().local_addr().unwrap().port()
}

type Got = Arc<Mutex<Vec<(String, Vec<u8>, bool)>>>;

/// A subscriber to `plcsh/#` (QoS 1, a persistent session), collecting what arrives; it
/// reconnects by itself while the broker is away.
fn subscribe(port: u16, id: &str) -> Got {
    let got: Got = Arc::default();
    let mut opts = rumqttc::MqttOptions::new(id, "127.0.0.1", port);
    opts.set_clean_session(false);
    opts.set_keep_alive(Duration::from_secs(5));
    let (client, mut conn) = rumqttc::Client::new(opts, 100);
    client.subscribe("plcsh/#", rumqttc::QoS::AtLeastOnce).unwrap();
    let g = got.clone();
    let (ready_tx, ready) = std::sync::mpsc::channel();
    std::thread::spawn(move || {
        let _keep = client;
        for ev in conn.iter() {
            match ev {
                Ok(rumqttc::Event::Incoming(rumqttc::Packet::SubAck(_))) => {
                    let _ = ready_tx.send(());
                }
                Ok(rumqttc::Event::Incoming(rumqttc::Packet::Publish(p))) => {
                    g.lock().unwrap().push((p.topic.clone(), p.payload.to_vec(), p.retain))
                }
                Ok(_) => {}
                Err(_) => std::thread::sleep(Duration::from_millis(50)),
            }
        }
    });
    ready.recv_timeout(Duration::from_secs(10)).expect("subscribed");
    got
}

/// Publishes a marker on `plcsh/marker` from a client of the test's own and waits until the
/// subscriber `got` has it: whatever reached the broker before (from a plcsh that has ended)
/// has been delivered by then, so "nothing else arrived" is decided by an arrival, not by a
/// quiet window.
fn mark(port: u16, got: &Got) {
    let opts = rumqttc::MqttOptions::new("marker", "127.0.0.1", port);
    let (client, mut conn) = rumqttc::Client::new(opts, 10);
    client.publish("plcsh/marker", rumqttc::QoS::AtLeastOnce, false, b"marker".to_vec()).unwrap();
    let deadline = Instant::now() + Duration::from_secs(20);
    for ev in conn.iter() {
        assert!(Instant::now() < deadline, "the marker was never acknowledged");
        if let Ok(rumqttc::Event::Incoming(rumqttc::Packet::PubAck(_))) = ev {
            break;
        }
    }
    wait_for(got, "the marker", |g| g.iter().any(|(t, _, _)| t == "plcsh/marker"));
}

fn wait_for(got: &Got, what: &str, f: impl Fn(&[(String, Vec<u8>, bool)]) -> bool) {
    let deadline = Instant::now() + Duration::from_secs(20);
    while !f(&got.lock().unwrap()) {
        assert!(
            Instant::now() < deadline,
            "timed out waiting for {what}: {:?}",
            got.lock()
                .unwrap()
                .iter()
                .map(|(t, p, _)| format!("{t} {}", String::from_utf8_lossy(p)))
                .collect::<Vec<_>>()
        );
        std::thread::sleep(Duration::from_millis(10));
    }
}

fn json(b: &[u8]) -> serde_json::Value {
    serde_json::from_slice(b).unwrap_or_else(|e| panic!("not JSON: {}: {e}", String::from_utf8_lossy(b)))
}

#[test]
fn a_fleets_values_and_status_are_published_and_retained() {
    if !mosquitto_present() {
        return;
    }
    let d = dir("retained");
    let port = free_port();
    let _broker = Broker::start(&d, port);
    let dead = free_port();
    let cfg = d.join("devices.toml");
    std::fs::write(
        &cfg,
        format!("[devices.a]\nurl = \"sim:K205-16DT\"\n[devices.b]\nurl = \"sim:K209EA-50DX\"\n[fleets.line]\ndevices = [\"a\", \"b\", \"tcp://127.0.0.1:{dead}\"]\n"),
    )
    .unwrap();
    let o = run(
        &[
            "--config",
            cfg.to_str().unwrap(),
            "--json",
            "publish",
            "-f",
            "line",
            "--broker",
            &format!("mqtt://127.0.0.1:{port}"),
            "--every",
            "20ms",
            "--count",
            "3",
            "--qos",
            "1",
            "--mqtt-version",
            "5",
            "VW100",
            "VD200/REAL",
        ],
        "",
    );
    let l = json_lines(&o);
    let summary = l.last().unwrap();
    assert_eq!(o.status.code(), Some(1), "a member is offline: {}", both(&o));
    assert_eq!(summary["cmd"], "publish");
    assert_eq!(summary["offline"], serde_json::json!(["line-3"]));
    assert_eq!(summary["dropped"], 0);
    assert!(l.iter().any(|x| x["event"] == "device" && x["device"] == "line-3" && x["state"] == "offline"), "{l:?}");
    // A subscriber that connects afterwards gets the last values: retained.
    let got = subscribe(port, "late-reader");
    wait_for(&got, "the retained values", |g| g.len() >= 8);
    let g = got.lock().unwrap().clone();
    let find = |t: &str| g.iter().find(|(topic, _, _)| topic == t).unwrap_or_else(|| panic!("{t}: {g:?}")).clone();
    for dev in ["a", "b"] {
        let (_, p, retained) = find(&format!("plcsh/line/{dev}/VW100"));
        assert!(retained);
        let v = json(&p);
        assert_eq!(
            (v["value"].as_i64(), v["type"].as_str(), v["seq"].as_u64()),
            (Some(0), Some("WORD"), Some(3)),
            "{v}"
        );
        assert_eq!(v["device"], dev);
        assert!(v["ts"].as_u64().unwrap() > 1_600_000_000_000, "a source timestamp in ms: {v}");
        assert_eq!(json(&find(&format!("plcsh/line/{dev}/VD200_REAL")).1)["type"], "REAL");
        assert_eq!(json(&find(&format!("plcsh/line/{dev}/status")).1), serde_json::json!({"state": "online"}));
    }
    // A port that refuses connections: offline, and why.
    assert_eq!(
        json(&find("plcsh/line/line-3/status").1),
        serde_json::json!({"state": "offline", "reason": "unreachable"})
    );
    assert!(!g.iter().any(|(t, _, _)| t == "plcsh/line/line-3/VW100"), "an offline device publishes no values");
    assert_eq!(find("plcsh/line/_publisher/status").1, b"offline", "the publisher said goodbye");
}

#[test]
fn readings_taken_while_the_broker_is_away_arrive_in_order() {
    if !mosquitto_present() {
        return;
    }
    let d = dir("restart");
    let port = free_port();
    let broker = Broker::start(&d, port);
    let got = subscribe(port, "steady-reader");
    let mut child = plcsh()
        .args([
            "--json",
            "publish",
            "--broker",
            &format!("mqtt://127.0.0.1:{port}"),
            "--every",
            "20ms",
            "--count",
            "120",
            "--qos",
            "1",
            "VW100",
        ])
        .stdout(Stdio::piped())
        .stderr(Stdio::piped())
        .spawn()
        .unwrap();
    let mut lines = std::io::BufReader::new(child.stdout.take().unwrap()).lines();
    let next_event = |lines: &mut std::io::Lines<_>, what: &str| loop {
        let l: String = lines.next().unwrap_or_else(|| panic!("publish ended before {what}")).unwrap();
        let v: serde_json::Value = serde_json::from_str(&l).unwrap();
        if v["event"] == "broker" && v["state"] == what {
            return;
        }
    };
    next_event(&mut lines, "connected");
    let seqs = |g: &[(String, Vec<u8>, bool)]| -> Vec<u64> {
        g.iter()
            .filter(|(t, _, _)| t == "plcsh/single/plc/VW100")
            .map(|(_, p, _)| json(p)["seq"].as_u64().unwrap())
            .collect()
    };
    wait_for(&got, "the first readings", |g| seqs(g).len() >= 5);
    broker.stop();
    next_event(&mut lines, "away");
    let broker = Broker::start(&d, port);
    let rest: Vec<String> = lines.map(|l| l.unwrap()).collect();
    let out = child.wait_with_output().unwrap();
    let summary: serde_json::Value = serde_json::from_str(rest.last().expect("a summary")).unwrap();
    assert_eq!(summary["ok"], true, "{rest:?} {}", String::from_utf8_lossy(&out.stderr));
    assert!(summary["reconnects"].as_u64().unwrap() >= 1, "{summary}");
    assert_eq!(summary["dropped"], 0);
    wait_for(&got, "every reading", |g| seqs(g).contains(&120));
    // At least once: a reading may come twice around the restart, but never out of order and none is missing.
    let s = seqs(&got.lock().unwrap());
    let (mut highest, mut seen) = (0, std::collections::HashSet::new());
    for &x in &s {
        // A repeat is a redelivery; a reading not seen before must come after every earlier one.
        if seen.insert(x) {
            assert!(x > highest, "out of order at {x}: {s:?}");
            highest = x;
        }
    }
    let mut unique = s.clone();
    unique.sort();
    unique.dedup();
    // Every poll taken arrived; a slot the poller had to skip (a loaded machine) is counted as
    // such in the summary, and is the only kind of gap.
    let skipped = summary["skipped"].as_u64().unwrap();
    assert_eq!(unique.len() as u64 + skipped, 120, "every reading arrived: {unique:?} {summary}");
    assert!(skipped <= 10, "{summary}");
    drop(broker);
}

#[test]
fn credentials_never_come_from_the_command_line() {
    let o = run(&["publish", "--broker", "mqtt://user:secret@127.0.0.1:1883", "VW0"], "");
    assert_eq!(o.status.code(), Some(2), "{}", both(&o));
    assert!(stderr(&o).contains("PLCSH_MQTT_PASSWORD"), "{}", both(&o));
    let o = run(&["publish", "VW0"], "");
    assert_eq!(o.status.code(), Some(2));
    assert!(stderr(&o).contains("needs a broker"), "{}", both(&o));
}

#[test]
fn writes_from_the_broker_only_to_allowed_operands() {
    if !mosquitto_present() {
        return;
    }
    let d = dir("writes");
    let port = free_port();
    let _broker = Broker::start(&d, port);
    let cfg = d.join("devices.toml");
    std::fs::write(
        &cfg,
        "[devices.a]\nurl = \"sim:K205-16DT\"\nallow = [\"VW100\"]\n[devices.v]\nurl = \"sim:K205-16DT\"\nread_only = true\n[devices.n]\nurl = \"sim:K205-16DT\"\n[fleets.pair]\ndevices = [\"a\", \"v\", \"n\"]\n",
    )
    .unwrap();
    let got = subscribe(port, "writer-watch");
    let mut child = plcsh()
        .args([
            "--config",
            cfg.to_str().unwrap(),
            "--json",
            "publish",
            "-f",
            "pair",
            "--accept-writes",
            "--broker",
            &format!("mqtt://127.0.0.1:{port}"),
            "--every",
            "20ms",
            "--count",
            "400",
            "VW100",
            "VW102",
        ])
        .stdout(Stdio::piped())
        .stderr(Stdio::null())
        .spawn()
        .unwrap();
    let topic_seen = |t: &str| {
        let t = t.to_string();
        move |g: &[(String, Vec<u8>, bool)]| g.iter().any(|(x, _, _)| *x == t)
    };
    // A value published after the publisher connected: its command subscription is in place.
    wait_for(&got, "the first values", topic_seen("plcsh/pair/v/VW100"));
    let mut opts = rumqttc::MqttOptions::new("writer", "127.0.0.1", port);
    opts.set_keep_alive(Duration::from_secs(5));
    let (client, mut conn) = rumqttc::Client::new(opts, 10);
    std::thread::spawn(move || for _ in conn.iter() {});
    let send = |topic: &str, body: &str| {
        client.publish(topic, rumqttc::QoS::AtLeastOnce, false, body.as_bytes().to_vec()).unwrap()
    };
    send("plcsh/pair/a/set", r#"{"operand":"VW100","value":1234,"id":"allowed"}"#);
    send("plcsh/pair/a/set", r#"{"operand":"VW102","value":1,"id":"not-listed"}"#);
    send("plcsh/pair/v/set", r#"{"operand":"VW100","value":1,"id":"read-only"}"#);
    send("plcsh/pair/a/set", r#"{"operand":"VW100""#);
    send("plcsh/pair/n/set", r#"{"operand":"VW100","value":1,"id":"no-allow-list"}"#);
    send("plcsh/pair/b/set", r#"{"operand":"VW100","value":1,"id":"no-such-device"}"#);
    let replies = |g: &[(String, Vec<u8>, bool)]| -> Vec<serde_json::Value> {
        g.iter().filter(|(t, _, _)| t.ends_with("/reply")).map(|(_, p, _)| json(p)).collect()
    };
    wait_for(&got, "six replies", |g| replies(g).len() >= 6);
    let value_of = |g: &[(String, Vec<u8>, bool)]| {
        g.iter().filter(|(t, _, _)| t == "plcsh/pair/a/VW100").any(|(_, p, _)| json(p)["value"] == 1234)
    };
    wait_for(&got, "the written value published", value_of);
    plcsh::core::platform::interrupt_child(&child);
    let _ = child.wait();
    let r = replies(&got.lock().unwrap());
    let by = |id: &str| r.iter().find(|x| x["id"] == id).unwrap_or_else(|| panic!("{id}: {r:?}")).clone();
    assert_eq!(by("allowed")["ok"], true, "{r:?}");
    let not_listed = by("not-listed");
    assert_eq!(not_listed["ok"], false);
    assert!(not_listed["error"]["message"].as_str().unwrap().contains("allow list"), "{not_listed}");
    assert_eq!(not_listed["error"]["kind"], "refused", "{not_listed}");
    let ro = by("read-only");
    assert_eq!(ro["ok"], false);
    assert!(ro["error"]["message"].as_str().unwrap().contains("read_only"), "{ro}");
    // The same refusal, in the same words, as the same write through `set`.
    let o = run(&["--config", cfg.to_str().unwrap(), "--json", "-f", "pair", "-c", "set VW100=1"], "");
    let by_set = json_lines(&o).into_iter().find(|l| l["device"] == "v").unwrap_or_else(|| panic!("{}", both(&o)));
    assert_eq!(
        (&ro["error"]["kind"], &ro["error"]["message"]),
        (&by_set["error"]["kind"], &by_set["error"]["message"]),
        "{ro} {by_set}"
    );
    assert_eq!(ro["error"]["kind"], "refused");
    let no_allow = by("no-allow-list");
    assert_eq!(no_allow["error"]["kind"], "refused", "{no_allow}");
    assert!(
        r.iter().any(|x| x["ok"] == false && x["error"]["kind"] == "syntax"),
        "a broken command is answered: {r:?}"
    );
    // A device that is no member is answered on its own reply topic, with the members.
    let unknown = by("no-such-device");
    assert_eq!((unknown["ok"].as_bool(), unknown["device"].as_str()), (Some(false), Some("b")), "{unknown}");
    let m = unknown["error"]["message"].as_str().unwrap();
    assert!(m.contains("no device of `pair`") && m.contains("members: a, v, n") && m.contains("did you mean"), "{m}");
    assert!(got.lock().unwrap().iter().any(|(t, _, _)| t == "plcsh/pair/b/reply"));
    assert!(
        !got.lock().unwrap().iter().any(|(t, p, _)| t == "plcsh/pair/v/VW100" && json(p)["value"] != 0),
        "the read-only device was not written"
    );
}

/// Names end to end (docs/tags.md, "How names appear"): a device with a tag file publishes an
/// operand that has a tag on the tag's topic, with `name` beside `operand` in the payload (an
/// operand without a tag keeps its own), and a write from the broker that names a tag reaches
/// its address — through the profile's allow list of addresses, refused when the address is
/// not on it — and is published on the name's topic.
#[test]
fn tag_names_are_topics_payloads_and_write_targets() {
    if !mosquitto_present() {
        return;
    }
    let d = dir("names");
    let port = free_port();
    let _broker = Broker::start(&d, port);
    std::fs::write(
        d.join("a.csv"),
        "name;address;type;comment\nTank2_Level;VD200;REAL;\nУровень_2;VW100;INT;уровень\n电机速度;VW102;INT;\n",
    )
    .unwrap();
    let cfg = d.join("devices.toml");
    std::fs::write(
        &cfg,
        "[devices.a]\nurl = \"sim:K205-16DT\"\ntags = \"a.csv\"\nallow = [\"VW100\", \"VD200\"]\n[fleets.line]\ndevices = [\"a\"]\n",
    )
    .unwrap();
    let got = subscribe(port, "names-watch");
    let mut child = plcsh()
        .args(["--config", cfg.to_str().unwrap(), "--json", "publish", "-f", "line", "--accept-writes"])
        .args(["--broker", &format!("mqtt://127.0.0.1:{port}"), "--every", "20ms", "--count", "1000"])
        .args(["Tank2_Level", "Уровень_2", "电机速度", "VW104"])
        .stdout(Stdio::piped())
        .stderr(Stdio::null())
        .spawn()
        .unwrap();
    let on = |t: &str| {
        let t = t.to_string();
        move |g: &[(String, Vec<u8>, bool)]| g.iter().any(|(x, _, _)| *x == t)
    };
    for t in ["plcsh/line/a/Tank2_Level", "plcsh/line/a/Уровень_2", "plcsh/line/a/电机速度", "plcsh/line/a/VW104"]
    {
        wait_for(&got, t, on(t));
    }
    let payload = |t: &str| {
        let g = got.lock().unwrap();
        json(&g.iter().find(|(x, _, _)| x == t).unwrap_or_else(|| panic!("{t}")).1)
    };
    let p = payload("plcsh/line/a/Tank2_Level");
    assert_eq!(
        (p["name"].as_str(), p["operand"].as_str(), p["type"].as_str()),
        (Some("Tank2_Level"), Some("VD200/REAL"), Some("REAL")),
        "{p}"
    );
    let p = payload("plcsh/line/a/电机速度");
    assert_eq!((p["name"].as_str(), p["operand"].as_str()), (Some("电机速度"), Some("VW102/INT")), "{p}");
    let p = payload("plcsh/line/a/VW104");
    assert_eq!((p.get("name"), p["operand"].as_str()), (None, Some("VW104")), "{p}");
    assert!(!got.lock().unwrap().iter().any(|(t, _, _)| t == "plcsh/line/a/VW100"), "a named operand has one topic");
    // Writes by name.
    let mut opts = rumqttc::MqttOptions::new("names-writer", "127.0.0.1", port);
    opts.set_keep_alive(Duration::from_secs(5));
    let (client, mut conn) = rumqttc::Client::new(opts, 10);
    std::thread::spawn(move || for _ in conn.iter() {});
    let send = |body: &str| {
        client.publish("plcsh/line/a/set", rumqttc::QoS::AtLeastOnce, false, body.as_bytes().to_vec()).unwrap()
    };
    send(r#"{"operand":"Уровень_2","value":-77,"id":"cyrillic"}"#);
    send(r#"{"operand":"tank2_level","value":12.5,"id":"any-case"}"#);
    send(r#"{"operand":"电机速度","value":5,"id":"not-allowed"}"#);
    send(r#"{"operand":"Уровен_2","value":1,"id":"misspelt"}"#);
    let replies = |g: &[(String, Vec<u8>, bool)]| -> Vec<serde_json::Value> {
        g.iter().filter(|(t, _, _)| t == "plcsh/line/a/reply").map(|(_, p, _)| json(p)).collect()
    };
    wait_for(&got, "four replies", |g| replies(g).len() >= 4);
    let published = |t: &'static str, want: serde_json::Value| {
        move |g: &[(String, Vec<u8>, bool)]| g.iter().any(|(x, p, _)| x == t && json(p)["value"] == want)
    };
    wait_for(&got, "the level written by name", published("plcsh/line/a/Уровень_2", serde_json::json!(-77)));
    wait_for(&got, "the REAL written by name", published("plcsh/line/a/Tank2_Level", serde_json::json!(12.5)));
    plcsh::core::platform::interrupt_child(&child);
    let _ = child.wait();
    let r = replies(&got.lock().unwrap());
    let by = |id: &str| r.iter().find(|x| x["id"] == id).unwrap_or_else(|| panic!("{id}: {r:?}")).clone();
    let c = by("cyrillic");
    assert_eq!(c["ok"], true, "{c}");
    assert_eq!(
        (c["writes"][0]["operand"].as_str(), c["writes"][0]["name"].as_str()),
        (Some("VW100/INT"), Some("Уровень_2")),
        "{c}"
    );
    assert_eq!(by("any-case")["ok"], true);
    let n = by("not-allowed");
    assert_eq!((n["ok"].as_bool(), n["error"]["kind"].as_str()), (Some(false), Some("refused")), "{n}");
    let m = by("misspelt");
    assert_eq!(m["ok"], false);
    assert!(m["error"]["hint"].as_str().unwrap_or("").contains("Уровень_2"), "did you mean: {m}");
    assert!(
        !got.lock().unwrap().iter().any(|(t, p, _)| t == "plcsh/line/a/电机速度" && json(p)["value"] != 0),
        "the address off the allow list was not written"
    );
}

#[test]
fn without_accept_writes_the_broker_writes_nothing() {
    if !mosquitto_present() {
        return;
    }
    let d = dir("no-writes");
    let port = free_port();
    let _broker = Broker::start(&d, port);
    let cfg = d.join("devices.toml");
    std::fs::write(&cfg, "[devices.a]\nurl = \"sim:K205-16DT\"\nallow = [\"VW100\"]\n").unwrap();
    let got = subscribe(port, "no-writes-watch");
    let mut child = plcsh()
        .args([
            "--config",
            cfg.to_str().unwrap(),
            "-d",
            "a",
            "publish",
            "--broker",
            &format!("mqtt://127.0.0.1:{port}"),
            "--every",
            "20ms",
            "--count",
            "400",
            "VW100",
        ])
        .stdout(Stdio::null())
        .stderr(Stdio::null())
        .spawn()
        .unwrap();
    let seqs = |g: &[(String, Vec<u8>, bool)]| -> u64 {
        g.iter()
            .filter(|(t, _, _)| t == "plcsh/single/a/VW100")
            .filter_map(|(_, p, _)| json(p)["seq"].as_u64())
            .max()
            .unwrap_or(0)
    };
    wait_for(&got, "the first values", |g| seqs(g) >= 1);
    let mut opts = rumqttc::MqttOptions::new("uninvited", "127.0.0.1", port);
    opts.set_keep_alive(Duration::from_secs(5));
    let (client, mut conn) = rumqttc::Client::new(opts, 10);
    let (acked_tx, acked) = std::sync::mpsc::channel();
    std::thread::spawn(move || {
        for ev in conn.iter() {
            if let Ok(rumqttc::Event::Incoming(rumqttc::Packet::PubAck(_))) = ev {
                let _ = acked_tx.send(());
            }
        }
    });
    client
        .publish("plcsh/single/a/set", rumqttc::QoS::AtLeastOnce, false, br#"{"operand":"VW100","value":77}"#.to_vec())
        .unwrap();
    acked.recv_timeout(Duration::from_secs(10)).expect("the broker took the command");
    // Ten more polls after the broker had the command: none shows it, no reply came.
    let after = seqs(&got.lock().unwrap());
    wait_for(&got, "ten more polls", |g| seqs(g) >= after + 10);
    plcsh::core::platform::interrupt_child(&child);
    let _ = child.wait();
    let g = got.lock().unwrap();
    assert!(!g.iter().any(|(t, _, _)| t.ends_with("/reply")), "no reply without --accept-writes");
    assert!(g.iter().filter(|(t, _, _)| t == "plcsh/single/a/VW100").all(|(_, p, _)| json(p)["value"] == 0));
}

#[test]
fn the_username_comes_from_the_profile_file_and_the_password_from_the_environment() {
    if !mosquitto_present() {
        return;
    }
    let d = dir("auth");
    let port = free_port();
    let passwords = d.join("passwords");
    // mosquitto_passwd hashes the password into the broker's password file.
    let made = Command::new("mosquitto_passwd").args(["-b", "-c"]).arg(&passwords).args(["plcsh", "s3cret"]).status();
    if !made.is_ok_and(|s| s.success()) {
        common::skipped("mosquitto_passwd (apt-get install mosquitto)");
        return;
    }
    use std::os::unix::fs::PermissionsExt;
    std::fs::set_permissions(&passwords, std::fs::Permissions::from_mode(0o644)).unwrap();
    let conf = d.join("mosquitto.conf");
    std::fs::write(
        &conf,
        format!(
            "{}listener {port} 127.0.0.1\nallow_anonymous false\npassword_file {}\n",
            broker_user(),
            passwords.display()
        ),
    )
    .unwrap();
    let mut broker =
        Command::new(mosquitto()).arg("-c").arg(&conf).stdout(Stdio::null()).stderr(Stdio::null()).spawn().unwrap();
    let deadline = Instant::now() + Duration::from_secs(10);
    while std::net::TcpStream::connect(("127.0.0.1", port)).is_err() {
        assert!(Instant::now() < deadline, "mosquitto did not start");
        std::thread::sleep(Duration::from_millis(10));
    }
    let cfg = d.join("devices.toml");
    std::fs::write(&cfg, format!("[mqtt]\nurl = \"mqtt://127.0.0.1:{port}\"\nusername = \"plcsh\"\n")).unwrap();
    let publish = |password: &str| {
        plcsh()
            .args(["--config", cfg.to_str().unwrap(), "--json", "publish", "--every", "10ms", "--count", "3", "VW100"])
            .env("PLCSH_MQTT_PASSWORD", password)
            .output()
            .unwrap()
    };
    let o = publish("s3cret");
    assert_eq!(o.status.code(), Some(0), "{}", both(&o));
    let last: serde_json::Value = serde_json::from_str(stdout(&o).lines().last().unwrap()).unwrap();
    assert!(last["published"].as_u64().unwrap() >= 4, "{last}");
    // Refused credentials are no outage: the run ends at once with its own status and says so.
    let o = publish("wrong");
    assert_eq!(o.status.code(), Some(3), "refused by the broker: {}", both(&o));
    let lines = json_lines(&o);
    let last = lines.last().unwrap();
    assert_eq!(last["ok"], false, "{lines:?}");
    let message = last["error"]["message"].as_str().unwrap();
    assert!(message.contains("refused the credentials") && message.contains("NotAuthorized"), "{message}");
    assert!(last["error"]["hint"].as_str().unwrap().contains("PLCSH_MQTT_PASSWORD"), "{last}");
    assert!(!lines.iter().any(|l| l["state"] == "away"), "not reported as an outage: {lines:?}");
    // Without the username at all: the same.
    std::fs::write(&cfg, format!("[mqtt]\nurl = \"mqtt://127.0.0.1:{port}\"\n")).unwrap();
    let o = publish("");
    assert_eq!(o.status.code(), Some(3), "{}", both(&o));
    let _ = broker.kill();
    let _ = broker.wait();
}

/// Runs openssl with `args` in `dir`; false when it is missing or fails.
fn openssl(dir: &Path, args: &[&str]) -> bool {
    Command::new("openssl")
        .args(args)
        .current_dir(dir)
        .stdout(Stdio::null())
        .stderr(Stdio::null())
        .status()
        .is_ok_and(|s| s.success())
}

#[test]
fn tls_with_the_ca_from_the_profile_file() {
    if !mosquitto_present() {
        return;
    }
    let d = dir("tls");
    // A CA of our own and a server certificate for 127.0.0.1 signed by it.
    std::fs::write(d.join("server.ext"), "basicConstraints=CA:FALSE\nsubjectAltName=IP:127.0.0.1\n").unwrap();
    let made = openssl(
        &d,
        &[
            "req",
            "-x509",
            "-newkey",
            "rsa:2048",
            "-nodes",
            "-keyout",
            "ca.key",
            "-out",
            "ca.pem",
            "-days",
            "2",
            "-subj",
            "/CN=plcsh test CA",
        ],
    ) && openssl(
        &d,
        &[
            "req",
            "-newkey",
            "rsa:2048",
            "-nodes",
            "-keyout",
            "server.key",
            "-out",
            "server.csr",
            "-subj",
            "/CN=127.0.0.1",
        ],
    ) && openssl(
        &d,
        &[
            "x509",
            "-req",
            "-in",
            "server.csr",
            "-CA",
            "ca.pem",
            "-CAkey",
            "ca.key",
            "-CAcreateserial",
            "-out",
            "server.pem",
            "-days",
            "2",
            "-extfile",
            "server.ext",
        ],
    );
    if !made {
        common::skipped("openssl to make test certificates (apt-get install openssl)");
        return;
    }
    use std::os::unix::fs::PermissionsExt;
    for f in ["server.key", "server.pem", "ca.pem"] {
        std::fs::set_permissions(d.join(f), std::fs::Permissions::from_mode(0o644)).unwrap();
    }
    let port = free_port();
    let conf = d.join("mosquitto.conf");
    std::fs::write(
        &conf,
        format!(
            "{1}listener {port} 127.0.0.1\nallow_anonymous true\ncertfile {0}/server.pem\nkeyfile {0}/server.key\ncafile {0}/ca.pem\n",
            d.display(),
            broker_user()
        ),
    )
    .unwrap();
    let mut broker =
        Command::new(mosquitto()).arg("-c").arg(&conf).stdout(Stdio::null()).stderr(Stdio::null()).spawn().unwrap();
    let deadline = Instant::now() + Duration::from_secs(10);
    while std::net::TcpStream::connect(("127.0.0.1", port)).is_err() {
        assert!(Instant::now() < deadline, "mosquitto did not start");
        std::thread::sleep(Duration::from_millis(10));
    }
    let cfg = d.join("devices.toml");
    let publish = |ca: &str| {
        std::fs::write(
            &cfg,
            format!("[mqtt]\nurl = \"mqtts://127.0.0.1:{port}\"\nca_file = \"{}\"\n", d.join(ca).display()),
        )
        .unwrap();
        plcsh()
            .args(["--config", cfg.to_str().unwrap(), "--json", "publish", "--every", "10ms", "--count", "3", "VW100"])
            .output()
            .unwrap()
    };
    let o = publish("ca.pem");
    assert_eq!(o.status.code(), Some(0), "over TLS: {}", both(&o));
    assert!(json_lines(&o).last().unwrap()["published"].as_u64().unwrap() >= 4, "{}", both(&o));
    // A certificate the given CA did not sign is refused: the publisher never connects.
    assert!(openssl(
        &d,
        &[
            "req",
            "-x509",
            "-newkey",
            "rsa:2048",
            "-nodes",
            "-keyout",
            "other.key",
            "-out",
            "other.pem",
            "-days",
            "2",
            "-subj",
            "/CN=other CA"
        ]
    ));
    let o = publish("other.pem");
    assert_eq!(o.status.code(), Some(4), "a certificate error has its own status: {}", both(&o));
    let lines = json_lines(&o);
    assert!(!lines.iter().any(|l| l["state"] == "connected" || l["state"] == "away"), "{}", both(&o));
    let message = lines.last().unwrap()["error"]["message"].as_str().unwrap().to_string();
    assert!(message.contains("TLS") && message.contains("certificate"), "{message}");
    let _ = broker.kill();
    let _ = broker.wait();
}

#[test]
fn on_change_publishes_once_and_a_device_that_stops_answering_goes_offline() {
    if !mosquitto_present() {
        return;
    }
    let d = dir("offline");
    let port = free_port();
    let _broker = Broker::start(&d, port);
    let got = subscribe(port, "offline-watch");
    let k2 = serve(&["--tcp", "0"]);
    let url = format!("tcp://{}?timeout=200ms&retries=0", k2.ready["tcp"].as_str().unwrap());
    let mut child = plcsh()
        .args([
            "-d",
            &format!("press={url}"),
            "--json",
            "publish",
            "--broker",
            &format!("mqtt://127.0.0.1:{port}"),
            "--every",
            "20ms",
            "--count",
            "100",
            "--on-change",
            "VW100",
        ])
        .stdout(Stdio::piped())
        .stderr(Stdio::null())
        .spawn()
        .unwrap();
    let mut lines = std::io::BufReader::new(child.stdout.take().unwrap()).lines();
    let values = |g: &[(String, Vec<u8>, bool)]| g.iter().filter(|(t, _, _)| t == "plcsh/single/press/VW100").count();
    wait_for(&got, "the first value", |g| values(g) >= 1);
    // Polls go on (every 20 ms) with VW100 unchanged; then it changes, and is published again.
    std::thread::sleep(Duration::from_millis(300));
    let o = run(&["-d", &url, "-c", "set VW100=5"], "");
    assert!(o.status.success(), "{}", both(&o));
    wait_for(&got, "the changed value", |g| values(g) >= 2);
    drop(k2);
    let offline = loop {
        let l: serde_json::Value = serde_json::from_str(&lines.next().expect("a device event").unwrap()).unwrap();
        if l["event"] == "device" {
            break l;
        }
    };
    assert_eq!((offline["device"].as_str(), offline["state"].as_str()), (Some("press"), Some("offline")), "{offline}");
    wait_for(&got, "the offline status", |g| {
        g.iter().any(|(t, p, _)| t == "plcsh/single/press/status" && json(p)["state"] == "offline")
    });
    plcsh::core::platform::interrupt_child(&child);
    let rest: Vec<String> = lines.map(|l| l.unwrap()).collect();
    let _ = child.wait();
    let summary: serde_json::Value = serde_json::from_str(rest.last().expect("a summary")).unwrap();
    assert_eq!(summary["offline"], serde_json::json!(["press"]), "{summary}");
    let g = got.lock().unwrap();
    let published: Vec<serde_json::Value> =
        g.iter().filter(|(t, _, _)| t == "plcsh/single/press/VW100").map(|(_, p, _)| json(p)).collect();
    assert_eq!(published.len(), 2, "--on-change: an unchanged value is published once: {published:?}");
    assert_eq!((published[0]["value"].as_i64(), published[1]["value"].as_i64()), (Some(0), Some(5)));
    assert!(published[1]["seq"].as_u64().unwrap() >= 3, "polls in between published nothing: {published:?}");
    let status: Vec<serde_json::Value> =
        g.iter().filter(|(t, _, _)| t == "plcsh/single/press/status").map(|(_, p, _)| json(p)).collect();
    assert_eq!(status.len(), 2, "{status:?}");
    assert_eq!(status[0], serde_json::json!({"state": "online"}));
    assert_eq!(status[1]["state"], "offline", "{status:?}");
    assert!(["unreachable", "no reply"].contains(&status[1]["reason"].as_str().unwrap()), "{status:?}");
}

#[test]
fn beyond_the_buffer_the_oldest_readings_are_dropped_and_counted() {
    if !mosquitto_present() {
        return;
    }
    let d = dir("bound");
    let port = free_port();
    // No broker yet: every reading waits in a queue of 5.
    let mut child = plcsh()
        .args([
            "--json",
            "publish",
            "--broker",
            &format!("mqtt://127.0.0.1:{port}"),
            "--every",
            "10ms",
            "--count",
            "30",
            "--buffer",
            "5",
            "--qos",
            "1",
            "VW100",
        ])
        .stdout(Stdio::piped())
        .stderr(Stdio::null())
        .spawn()
        .unwrap();
    let mut lines = std::io::BufReader::new(child.stdout.take().unwrap()).lines();
    let mut until = |event: &str, state: &str| loop {
        let l: serde_json::Value = serde_json::from_str(&lines.next().expect("an event").unwrap()).unwrap();
        if l["event"] == event && l["state"] == state {
            return;
        }
    };
    until("broker", "away");
    until("polling", "stopped");
    // All 30 polls are queued (or dropped); now the broker comes, with a subscriber waiting.
    let _broker = Broker::start(&d, port);
    let got = subscribe(port, "bound-watch");
    let rest: Vec<String> = lines.map(|l| l.unwrap()).collect();
    let _ = child.wait();
    let summary: serde_json::Value = serde_json::from_str(rest.last().expect("a summary")).unwrap();
    // The device's `online` and a value per poll (30, less the slots a loaded machine made
    // it skip, counted apart): of these messages the newest 5 are kept.
    let polls = 30 - summary["skipped"].as_u64().unwrap();
    assert_eq!(summary["dropped"].as_u64(), Some(1 + polls - 5), "{summary}");
    assert_eq!(summary["dropped_broker_away"], summary["dropped"], "{summary}");
    assert_eq!(summary["undelivered"], 0, "{summary}");
    assert_eq!(summary["ok"], false, "readings were dropped: {summary}");
    wait_for(&got, "the kept readings", |g| g.iter().filter(|(t, _, _)| t == "plcsh/single/plc/VW100").count() >= 1);
    let g = got.lock().unwrap();
    // The subscriber came after them: it sees the retained last value, the newest reading.
    let last = g.iter().rev().find(|(t, _, _)| t == "plcsh/single/plc/VW100").map(|(_, p, _)| json(p)).unwrap();
    assert_eq!(last["seq"], 30, "{last}");
}

/// A profile file with fleet `line` of `n` in-process simulated K2s (`line-1` … `line-N`).
fn sim_fleet(d: &Path, n: usize) -> PathBuf {
    let cfg = d.join("devices.toml");
    let list = vec!["\"sim:K205-16DT\""; n].join(", ");
    std::fs::write(&cfg, format!("[fleets.line]\ndevices = [{list}]\n")).unwrap();
    cfg
}

/// Reads `lines` until a JSON event with `event` and `state`.
/// Bytes received and not yet read by the listener on `port` of this machine (the sum of the
/// receive queues of its established connections in /proc/net/tcp and tcp6): what a paused
/// broker has been sent.
fn bytes_waiting_at(port: u16) -> u64 {
    let mut total = 0;
    for table in ["/proc/net/tcp", "/proc/net/tcp6"] {
        let Ok(text) = std::fs::read_to_string(table) else { continue };
        for line in text.lines().skip(1) {
            let f: Vec<&str> = line.split_whitespace().collect();
            let (Some(local), Some(state), Some(queues)) = (f.get(1), f.get(3), f.get(4)) else { continue };
            let local_port = local.rsplit(':').next().and_then(|p| u16::from_str_radix(p, 16).ok());
            if local_port == Some(port) && *state == "01" {
                let rx = queues.split(':').nth(1).and_then(|q| u64::from_str_radix(q, 16).ok());
                total += rx.unwrap_or(0);
            }
        }
    }
    total
}

fn until_event(lines: &mut impl Iterator<Item = std::io::Result<String>>, event: &str, state: &str) {
    loop {
        let l = lines.next().unwrap_or_else(|| panic!("publish ended before {event} {state}")).unwrap();
        let v: serde_json::Value = serde_json::from_str(&l).unwrap();
        if v["event"] == event && v["state"] == state {
            return;
        }
    }
}

#[test]
fn an_operand_no_member_has_is_one_usage_error_before_anything_connects() {
    if !mosquitto_present() {
        return;
    }
    let d = dir("typo");
    let port = free_port();
    let _broker = Broker::start(&d, port);
    let got = subscribe(port, "typo-watch");
    let cfg = sim_fleet(&d, 3);
    let broker = format!("mqtt://127.0.0.1:{port}");
    let args = ["--config", cfg.to_str().unwrap(), "--json", "publish", "-f", "line", "--broker", &broker];
    let o = run(&[&args[..], &["VW100", "VX0"]].concat(), "");
    assert_eq!(o.status.code(), Some(2), "{}", both(&o));
    let l = json_lines(&o);
    assert_eq!(l.len(), 1, "one error, not one per device: {l:?}");
    let m = l[0]["error"]["message"].as_str().unwrap();
    assert!(m.contains("VX0") && m.contains("any member of fleet `line`"), "{m}");
    // A model that lacks an operand the others have: the member is named.
    std::fs::write(&cfg, "[fleets.line]\ndevices = [\"sim:K205-16DT\", \"sim:K204ET-16DT\"]\n").unwrap();
    let o = run(&[&args[..], &["AIW0"]].concat(), "");
    assert_eq!(o.status.code(), Some(2), "{}", both(&o));
    let m = json_lines(&o)[0]["error"]["message"].as_str().unwrap().to_string();
    assert!(m.contains("AIW0") && m.contains("line-1") && !m.contains("line-2"), "{m}");
    // Nothing reached the broker: no device marked offline, no publisher status.
    mark(port, &got);
    let g = got.lock().unwrap();
    assert!(g.iter().all(|(t, _, _)| t == "plcsh/marker"), "nothing published: {g:?}");
}

/// A dropped SSH session: SIGHUP to the child.
fn hang_up(c: &Child) {
    assert!(Command::new("kill").args(["-HUP", &c.id().to_string()]).status().unwrap().success());
}

/// Every stop signal the docs list (docs/reference/exit-status.md) ends `publish` normally once
/// everything was delivered.
#[test]
fn a_stop_by_signal_after_everything_was_delivered_exits_0() {
    if !mosquitto_present() {
        return;
    }
    let d = dir("stop");
    let port = free_port();
    let _broker = Broker::start(&d, port);
    let got = subscribe(port, "stop-watch");
    for (signal, name) in [
        (plcsh::core::platform::interrupt_child as fn(&Child), "SIGINT"),
        (plcsh::core::platform::terminate_child, "SIGTERM"),
        (hang_up, "SIGHUP"),
    ] {
        got.lock().unwrap().clear();
        let mut child = plcsh()
            .args([
                "--json",
                "publish",
                "--broker",
                &format!("mqtt://127.0.0.1:{port}"),
                "--every",
                "20ms",
                "--qos",
                "1",
                "VW100",
            ])
            .stdout(Stdio::piped())
            .stderr(Stdio::piped())
            .spawn()
            .unwrap();
        let mut lines = std::io::BufReader::new(child.stdout.take().unwrap()).lines();
        until_event(&mut lines, "broker", "connected");
        wait_for(&got, "values", |g| g.iter().filter(|(t, _, _)| t == "plcsh/single/plc/VW100").count() >= 3);
        signal(&child);
        let rest: Vec<String> = lines.map(|l| l.unwrap()).collect();
        let status = child.wait().unwrap();
        let summary: serde_json::Value = serde_json::from_str(rest.last().expect("a summary")).unwrap();
        assert_eq!(summary["ok"], true, "{name}: {rest:?}");
        assert_eq!(summary["undelivered"], 0, "{name}: {summary}");
        assert_eq!(status.code(), Some(0), "{name}: a normal stop with everything delivered: {rest:?}");
        wait_for(&got, "the goodbye", |g| {
            g.iter().any(|(t, p, _)| t == "plcsh/single/_publisher/status" && p == b"offline")
        });
    }
}

#[test]
fn a_broker_never_reached_is_named_as_such() {
    let port = free_port();
    let started = Instant::now();
    let o = run(
        &[
            "--json",
            "publish",
            "--broker",
            &format!("mqtt://127.0.0.1:{port}"),
            "--every",
            "50ms",
            "--count",
            "2",
            "VW100",
        ],
        "",
    );
    assert_eq!(o.status.code(), Some(4), "{}", both(&o));
    let l = json_lines(&o);
    let m = l.last().unwrap()["error"]["message"].as_str().unwrap().to_string();
    assert!(m.contains("no MQTT broker answered at 127.0.0.1:") && m.contains("refused"), "{m}");
    assert!(started.elapsed() < Duration::from_secs(15), "{:?}", started.elapsed());
}

#[test]
fn falling_behind_with_the_broker_up_keeps_the_queue_bounded_and_says_so() {
    if !mosquitto_present() {
        return;
    }
    let d = dir("behind");
    let port = free_port();
    let _broker = Broker::start(&d, port);
    let cfg = sim_fleet(&d, 20);
    // 20 devices every millisecond at QoS 1 into a queue of 3: more than plcsh hands over.
    let o = run(
        &[
            "--config",
            cfg.to_str().unwrap(),
            "--json",
            "publish",
            "-f",
            "line",
            "--broker",
            &format!("mqtt://127.0.0.1:{port}"),
            "--every",
            "1ms",
            "--count",
            "300",
            "--buffer",
            "3",
            "--qos",
            "1",
            "VW100",
            "VW102",
        ],
        "",
    );
    let l = json_lines(&o);
    let summary = l.last().unwrap();
    assert!(l.iter().any(|x| x["state"] == "connected"), "{l:?}");
    assert!(!l.iter().any(|x| x["state"] == "away"), "the broker never left: {l:?}");
    assert_eq!(summary["dropped_broker_away"], 0, "not blamed on the broker: {summary}");
    let behind = summary["dropped_behind"].as_u64().unwrap() + summary["skipped"].as_u64().unwrap();
    assert!(behind > 0, "{summary}");
    assert_eq!(summary["dropped"], summary["dropped_behind"], "{summary}");
    // Per device: who missed what.
    let per = summary["behind"].as_object().unwrap();
    let total: u64 = per.values().map(|v| v["dropped_behind"].as_u64().unwrap() + v["skipped"].as_u64().unwrap()).sum();
    assert_eq!(total, behind, "{summary}");
    assert!(per.keys().all(|k| k.starts_with("line-")), "{summary}");
    assert_eq!(o.status.code(), Some(1), "readings were dropped: {}", both(&o));
}

#[test]
fn three_shards_publish_the_whole_fleet_once_and_a_killed_shard_shows_its_will() {
    if !mosquitto_present() {
        return;
    }
    let d = dir("shards");
    let port = free_port();
    let _broker = Broker::start(&d, port);
    let got = subscribe(port, "shard-watch");
    let cfg = sim_fleet(&d, 12);
    let shard = |k: u32| {
        let mut c = plcsh()
            .args([
                "--config",
                cfg.to_str().unwrap(),
                "--json",
                "publish",
                "-f",
                "line",
                "--shard",
                &format!("{k}/3"),
                "--broker",
                &format!("mqtt://127.0.0.1:{port}"),
                "--every",
                "50ms",
                "VW100",
            ])
            .stdout(Stdio::piped())
            .stderr(Stdio::piped())
            .spawn()
            .unwrap();
        let lines = std::io::BufReader::new(c.stdout.take().unwrap()).lines();
        (c, lines)
    };
    let mut shards: Vec<_> = (1..=3).map(shard).collect();
    for (_, lines) in shards.iter_mut() {
        until_event(lines, "broker", "connected");
    }
    let status_of = |g: &[(String, Vec<u8>, bool)], k: u32| {
        g.iter()
            .rev()
            .find(|(t, _, _)| *t == format!("plcsh/line/_publisher/shard{k}/status"))
            .map(|(_, p, _)| p.clone())
    };
    wait_for(&got, "every shard online", |g| (1..=3).all(|k| status_of(g, k).as_deref() == Some(&b"online"[..])));
    let devices = |g: &[(String, Vec<u8>, bool)]| -> std::collections::BTreeSet<String> {
        g.iter()
            .filter(|(t, _, _)| t.ends_with("/VW100"))
            .map(|(_, p, _)| json(p)["device"].as_str().unwrap().to_string())
            .collect()
    };
    wait_for(&got, "every device", |g| devices(g).len() == 12);
    // kill -9 the third shard: the broker publishes its will; the others stay online.
    let (mut third, _) = shards.pop().unwrap();
    third.kill().unwrap();
    let _ = third.wait();
    wait_for(&got, "the killed shard's will", |g| status_of(g, 3).as_deref() == Some(&b"offline"[..]));
    let g = got.lock().unwrap().clone();
    assert_eq!(status_of(&g, 1).as_deref(), Some(&b"online"[..]));
    assert_eq!(status_of(&g, 2).as_deref(), Some(&b"online"[..]));
    let mut summaries = Vec::new();
    for (c, lines) in shards {
        plcsh::core::platform::interrupt_child(&c);
        let rest: Vec<String> = lines.map(|l| l.unwrap()).collect();
        let _ = c.wait_with_output();
        summaries.push(serde_json::from_str::<serde_json::Value>(rest.last().unwrap()).unwrap());
    }
    // Exactly the fleet, each device from one shard only: one `online` per device, and no
    // poll number twice for a device.
    let all: std::collections::BTreeSet<String> = (1..=12).map(|i| format!("line-{i}")).collect();
    assert_eq!(devices(&g), all);
    for dev in &all {
        let onlines = g
            .iter()
            .filter(|(t, p, _)| *t == format!("plcsh/line/{dev}/status") && json(p)["state"] == "online")
            .count();
        assert_eq!(onlines, 1, "{dev} is polled by one shard");
        let mut seqs: Vec<u64> = g
            .iter()
            .filter(|(t, _, _)| *t == format!("plcsh/line/{dev}/VW100"))
            .map(|(_, p, _)| json(p)["seq"].as_u64().unwrap())
            .collect();
        let n = seqs.len();
        seqs.dedup();
        assert_eq!(seqs.len(), n, "{dev}: one publisher's polls");
    }
    let held: u64 = summaries.iter().map(|s| s["devices"].as_u64().unwrap()).sum::<u64>();
    assert!(held < 12 && held > 0, "the two left hold their parts only: {summaries:?}");
    assert!(summaries.iter().all(|s| s["shard"].is_string() && s["ok"] == true), "{summaries:?}");
}

/// Checks every value message of `got` against its topic and the device's known values:
/// `plcsh/GROUP/DEV/OP` carries `"device":"DEV","operand":"OP"` and the value `want(DEV, OP)`;
/// a status topic carries a status. Returns the number of value messages checked.
fn check_attribution(got: &[(String, Vec<u8>, bool)], want: impl Fn(&str, &str) -> i64) -> usize {
    let mut values = 0;
    for (topic, payload, _) in got {
        let parts: Vec<&str> = topic.split('/').collect();
        if parts.len() != 4 || parts[2] == "_publisher" || parts[3] == "reply" {
            continue;
        }
        let (dev, leaf) = (parts[2], parts[3]);
        let v = json(payload);
        if leaf == "status" {
            assert!(v["state"] == "online" || v["state"] == "offline", "{topic}: {v}");
            continue;
        }
        values += 1;
        assert_eq!((v["device"].as_str(), v["operand"].as_str()), (Some(dev), Some(leaf)), "{topic}: {v}");
        assert_eq!(v["value"].as_i64(), Some(want(dev, leaf)), "{topic}: {v}");
    }
    values
}

#[test]
fn a_range_published_under_overload_is_never_attributed_to_another_device() {
    if !mosquitto_present() {
        return;
    }
    let d = dir("attribution");
    let port = free_port();
    let _broker = Broker::start(&d, port);
    let got = subscribe(port, "attribution-watch");
    let (a, b) = (serve(&["--tcp", "0"]), serve(&["--tcp", "0"]));
    let url = |s: &Served| format!("tcp://{}", s.ready["tcp"].as_str().unwrap());
    // Every register of each device holds a value naming the device and the register.
    let want = |dev: &str, op: &str| -> i64 {
        let n: i64 = op.trim_start_matches("VW").parse().unwrap();
        if dev == "a" {
            1000 + n
        } else {
            2000 + n
        }
    };
    for (s, dev) in [(&a, "a"), (&b, "b")] {
        let sets: Vec<String> = (0..=6).step_by(2).map(|n| format!("VW{n}={}", want(dev, &format!("VW{n}")))).collect();
        let o = run(&["-d", &url(s), "-c", &format!("set {}", sets.join(", "))], "");
        assert!(o.status.success(), "{}", both(&o));
    }
    let cfg = d.join("devices.toml");
    std::fs::write(
        &cfg,
        format!(
            "[devices.a]\nurl = \"{}\"\n[devices.b]\nurl = \"{}\"\n[fleets.pair]\ndevices = [\"a\", \"b\"]\n",
            url(&a),
            url(&b)
        ),
    )
    .unwrap();
    let o = run(
        &[
            "--config",
            cfg.to_str().unwrap(),
            "--json",
            "publish",
            "-f",
            "pair",
            "--broker",
            &format!("mqtt://127.0.0.1:{port}"),
            "--buffer",
            "4",
            "--every",
            "5ms",
            "--count",
            "400",
            "VW0..VW6",
        ],
        "",
    );
    let summary = json_lines(&o).pop().unwrap();
    let published = summary["published"].as_u64().unwrap() as usize;
    assert!(published > 100, "{summary}");
    wait_for(&got, "every published message", |g| {
        g.iter().filter(|(t, _, _)| t.starts_with("plcsh/pair/")).count() >= published
    });
    let checked = check_attribution(&got.lock().unwrap(), want);
    assert!(checked > 50, "{checked} values checked: {summary}");
}

/// Reads `lines` (JSON events) until one satisfies `want`; returns it.
fn until_line(
    lines: &mut impl Iterator<Item = std::io::Result<String>>,
    what: &str,
    want: impl Fn(&serde_json::Value) -> bool,
) -> serde_json::Value {
    loop {
        let l = lines.next().unwrap_or_else(|| panic!("publish ended before {what}")).unwrap();
        let v: serde_json::Value = serde_json::from_str(&l).unwrap();
        if want(&v) {
            return v;
        }
    }
}

#[test]
fn a_member_off_at_the_start_is_published_once_it_answers_and_reasons_are_told_apart() {
    if !mosquitto_present() {
        return;
    }
    let d = dir("comeback");
    let port = free_port();
    let _broker = Broker::start(&d, port);
    let got = subscribe(port, "comeback-watch");
    let late = free_port();
    let ctl = d.join("k2.ctl");
    let other = serve(&["--tcp", "0", "--k2-control", ctl.to_str().unwrap()]);
    let cfg = d.join("devices.toml");
    std::fs::write(
        &cfg,
        format!(
            "[devices.late]\nurl = \"tcp://127.0.0.1:{late}?timeout=300ms&retries=0\"\n[devices.hung]\nurl = \"tcp://{}?timeout=300ms&retries=0\"\n[fleets.pair]\ndevices = [\"late\", \"hung\"]\n",
            other.ready["tcp"].as_str().unwrap()
        ),
    )
    .unwrap();
    let mut child = plcsh()
        .args(["--config", cfg.to_str().unwrap(), "--json", "publish", "-f", "pair"])
        .args(["--broker", &format!("mqtt://127.0.0.1:{port}"), "--every", "50ms", "VW100"])
        .stdout(Stdio::piped())
        .stderr(Stdio::null())
        .spawn()
        .unwrap();
    let mut lines = std::io::BufReader::new(child.stdout.take().unwrap()).lines();
    let off = until_line(&mut lines, "late offline", |v| v["event"] == "device" && v["device"] == "late");
    assert_eq!((off["state"].as_str(), off["reason"].as_str()), (Some("offline"), Some("unreachable")), "{off}");
    let status = |g: &[(String, Vec<u8>, bool)], dev: &str| {
        g.iter().rev().find(|(t, _, _)| *t == format!("plcsh/pair/{dev}/status")).map(|(_, p, _)| json(p))
    };
    wait_for(&got, "late's status with its reason", |g| {
        status(g, "late") == Some(serde_json::json!({"state": "offline", "reason": "unreachable"}))
    });
    // Served a while later: polled again, published from its first good poll.
    std::thread::sleep(Duration::from_millis(500));
    let _served = serve(&["--tcp", &format!("127.0.0.1:{late}")]);
    let back = until_line(&mut lines, "late back", |v| v["event"] == "device" && v["device"] == "late");
    assert_eq!(back["state"], "online", "{back}");
    wait_for(&got, "late's values", |g| g.iter().any(|(t, _, _)| t == "plcsh/pair/late/VW100"));
    wait_for(&got, "late online", |g| status(g, "late") == Some(serde_json::json!({"state": "online"})));
    // Exceptions and silence are told apart, on the status topic as in the events.
    let control = |words: &str| {
        let mut args = vec!["sim", "control", ctl.to_str().unwrap()];
        args.extend(words.split_whitespace());
        let o = run(&args, "");
        assert!(o.status.success(), "{}", both(&o));
    };
    control("fault exception 2");
    let ev = until_line(&mut lines, "an exception", |v| v["event"] == "device" && v["device"] == "hung");
    assert_eq!((ev["state"].as_str(), ev["reason"].as_str()), (Some("offline"), Some("exception 2")), "{ev}");
    wait_for(&got, "the exception's status", |g| status(g, "hung").is_some_and(|s| s["reason"] == "exception 2"));
    control("fault clear");
    until_line(&mut lines, "hung back", |v| v["event"] == "device" && v["device"] == "hung" && v["state"] == "online");
    control("fault no-reply");
    let ev = until_line(&mut lines, "silence", |v| v["event"] == "device" && v["device"] == "hung");
    assert_eq!((ev["state"].as_str(), ev["reason"].as_str()), (Some("offline"), Some("no reply")), "{ev}");
    wait_for(&got, "the silence's status", |g| status(g, "hung").is_some_and(|s| s["reason"] == "no reply"));
    control("fault clear");
    until_line(&mut lines, "hung back again", |v| {
        v["event"] == "device" && v["device"] == "hung" && v["state"] == "online"
    });
    plcsh::core::platform::interrupt_child(&child);
    let rest: Vec<String> = lines.map(|l| l.unwrap()).collect();
    let _ = child.wait();
    let summary: serde_json::Value = serde_json::from_str(rest.last().expect("a summary")).unwrap();
    assert_eq!(summary["offline"], serde_json::json!([]), "{summary}");
}

#[test]
fn one_device_down_at_the_start_is_waited_for_and_a_typo_is_a_usage_error() {
    if !mosquitto_present() {
        return;
    }
    let d = dir("single-late");
    let port = free_port();
    let _broker = Broker::start(&d, port);
    let got = subscribe(port, "single-late-watch");
    let broker = format!("mqtt://127.0.0.1:{port}");
    // An operand the device does not have: a usage error before anything connects.
    let k2 = serve(&["--tcp", "0"]);
    let o = run(
        &["-d", &format!("press=tcp://{}", k2.ready["tcp"].as_str().unwrap()), "publish", "--broker", &broker, "VX0"],
        "",
    );
    assert_eq!(o.status.code(), Some(2), "{}", both(&o));
    assert!(stderr(&o).contains("VX0"), "{}", both(&o));
    drop(k2);
    let late = free_port();
    let mut child = plcsh()
        .args(["-d", &format!("press=tcp://127.0.0.1:{late}?timeout=300ms&retries=0"), "--json", "publish"])
        .args(["--broker", &broker, "--every", "50ms", "VW100"])
        .stdout(Stdio::piped())
        .stderr(Stdio::null())
        .spawn()
        .unwrap();
    let mut lines = std::io::BufReader::new(child.stdout.take().unwrap()).lines();
    let off = until_line(&mut lines, "offline", |v| v["event"] == "device");
    assert_eq!((off["state"].as_str(), off["reason"].as_str()), (Some("offline"), Some("unreachable")), "{off}");
    let _served = serve(&["--tcp", &format!("127.0.0.1:{late}")]);
    until_line(&mut lines, "online", |v| v["event"] == "device" && v["state"] == "online");
    wait_for(&got, "its values", |g| g.iter().any(|(t, _, _)| t == "plcsh/single/press/VW100"));
    plcsh::core::platform::interrupt_child(&child);
    let rest: Vec<String> = lines.map(|l| l.unwrap()).collect();
    let status = child.wait().unwrap();
    let summary: serde_json::Value = serde_json::from_str(rest.last().expect("a summary")).unwrap();
    assert_eq!(summary["offline"], serde_json::json!([]), "{summary}");
    assert_eq!(status.code(), Some(0), "{rest:?}");
}

#[test]
fn a_stop_under_overload_delivers_what_it_counts_and_counts_the_rest_as_dropped() {
    if !mosquitto_present() {
        return;
    }
    let d = dir("overload-stop");
    let port = free_port();
    let _broker = Broker::start(&d, port);
    // No limit on what the broker queues for the subscriber: what it was handed, it passes on.
    let got = subscribe(port, "overload-watch");
    let cfg = sim_fleet(&d, 10);
    for qos in ["0", "1"] {
        got.lock().unwrap().clear();
        let mut child = plcsh()
            .args(["--config", cfg.to_str().unwrap(), "--json", "publish", "-f", "line"])
            .args(["--broker", &format!("mqtt://127.0.0.1:{port}"), "--every", "1ms", "--buffer", "100000"])
            .args(["--qos", qos, "VW0..VW18"])
            .stdout(Stdio::piped())
            .stderr(Stdio::null())
            .spawn()
            .unwrap();
        let mut lines = std::io::BufReader::new(child.stdout.take().unwrap()).lines();
        until_event(&mut lines, "broker", "connected");
        wait_for(&got, "readings flowing", |g| g.len() >= 2000);
        // The stats come on time (every 5 s) while plcsh is behind, not only at the end.
        wait_for(&got, "the stats during the run", |g| g.iter().any(|(t, _, _)| t == "plcsh/line/_publisher/stats"));
        plcsh::core::platform::interrupt_child(&child);
        let stopped = Instant::now();
        let rest: Vec<String> = lines.map(|l| l.unwrap()).collect();
        let _ = child.wait();
        let took = stopped.elapsed();
        let summary: serde_json::Value = serde_json::from_str(rest.last().expect("a summary")).unwrap();
        // Bounded: the stop's grace (5 s) and the close (1 s), and a loaded machine's slack.
        assert!(took < Duration::from_secs(20), "QoS {qos}: the stop took {took:?}: {summary}");
        let published = summary["published"].as_u64().unwrap() as usize;
        let at_stop = summary["dropped_at_stop"].as_u64().unwrap();
        assert_eq!(summary["undelivered"].as_u64(), Some(at_stop), "{summary}");
        // Everything counted as published reached the broker: the subscriber gets it all.
        wait_for(&got, "every message counted as published", |g| g.len() >= published);
        let g = got.lock().unwrap();
        let received = g.len();
        assert!(received >= published, "QoS {qos}: {received} received, {published} counted: {summary}");
        if at_stop == 0 {
            // A clean end: the publisher's goodbye, after everything else.
            assert!(
                g.iter().any(|(t, p, _)| t == "plcsh/line/_publisher/status" && p == b"offline"),
                "QoS {qos}: {summary}"
            );
        }
        check_attribution(&g, |_, _| 0);
    }
}

/// At QoS 0 a message written to a connection that is then lost is not known to have arrived:
/// it is counted as dropped with the broker away, never as published (docs/fleets.md,
/// "Publishing to MQTT"). The broker is paused, so what plcsh writes meanwhile waits unread in
/// its socket, and then killed, which loses it for certain.
#[test]
fn at_qos_0_what_a_lost_connection_took_is_dropped_not_published() {
    if !mosquitto_present() {
        return;
    }
    let (d1, d2) = (dir("qos0-lost-1"), dir("qos0-lost-2"));
    // The second broker knows the second subscriber from the start (its saved session, QoS 0
    // messages queued for it while it is away): it gets everything published to that broker,
    // whenever plcsh reconnects.
    let queue = "queue_qos0_messages true\n";
    let early_port = free_port();
    let early = Broker::start_with(&d2, early_port, queue);
    {
        let mut opts = rumqttc::MqttOptions::new("qos0-lost-after", "127.0.0.1", early_port);
        opts.set_clean_session(false);
        let (client, mut conn) = rumqttc::Client::new(opts, 10);
        client.subscribe("plcsh/#", rumqttc::QoS::AtLeastOnce).unwrap();
        for ev in conn.iter() {
            if let Ok(rumqttc::Event::Incoming(rumqttc::Packet::SubAck(_))) = ev {
                break;
            }
        }
        client.disconnect().unwrap();
        for ev in conn.iter() {
            if ev.is_err() {
                break;
            }
        }
    }
    early.stop();
    let port = free_port();
    let first = Broker::start(&d1, port);
    let before = subscribe(port, "qos0-lost-before");
    let mut child = plcsh()
        .args(["--json", "publish", "--broker", &format!("mqtt://127.0.0.1:{port}")])
        .args(["--every", "20ms", "--count", "150", "--qos", "0", "VW100"])
        .stdout(Stdio::piped())
        .stderr(Stdio::null())
        .spawn()
        .unwrap();
    let mut lines = std::io::BufReader::new(child.stdout.take().unwrap()).lines();
    until_event(&mut lines, "broker", "connected");
    wait_for(&before, "the first readings", |g| g.iter().filter(|(t, _, _)| t.ends_with("/VW100")).count() >= 5);
    // SAFETY: kill(2) on the test's own child.
    unsafe {
        libc::kill(first.child.id() as libc::pid_t, libc::SIGSTOP);
    }
    // Wait until the paused broker's socket holds several readings plcsh wrote into it (its
    // receive queue, as the kernel reports it), not for a time: on a busy machine 400 ms may see
    // no poll at all.
    let deadline = Instant::now() + Duration::from_secs(30);
    while bytes_waiting_at(port) < 500 {
        assert!(Instant::now() < deadline, "plcsh wrote nothing to the paused broker in 30 s");
        std::thread::sleep(Duration::from_millis(20));
    }
    drop(first);
    let _second = Broker::start_with(&d2, port, queue);
    let after = subscribe(port, "qos0-lost-after");
    let rest: Vec<String> = lines.map(|l| l.unwrap()).collect();
    let status = child.wait().unwrap();
    let summary: serde_json::Value = serde_json::from_str(rest.last().expect("a summary")).unwrap();
    assert!(summary["reconnects"].as_u64().unwrap() >= 1, "{summary}");
    let lost = summary["dropped_broker_away"].as_u64().unwrap();
    assert!(lost > 0, "the readings written while the broker was paused were lost with it: {summary}");
    assert_eq!(summary["dropped"].as_u64(), Some(lost + summary["dropped_behind"].as_u64().unwrap()), "{summary}");
    assert_eq!(status.code(), Some(1), "readings were dropped: {summary}");
    // Nothing counted as published went missing: the two brokers' subscribers got at least as many.
    let published = summary["published"].as_u64().unwrap() as usize;
    wait_for(&after, "the goodbye", |g| {
        g.iter().any(|(t, p, _)| t == "plcsh/single/_publisher/status" && p == b"offline")
    });
    let received = before.lock().unwrap().len() + after.lock().unwrap().len();
    assert!(received >= published, "{received} received, {published} counted as published: {summary}");
}

/// `--read-only` refuses a write from the broker exactly as it refuses the same `set`: kind
/// `refused`, the same message (docs/fleets.md, "Writes from the broker") — even for an
/// operand on the profile's allow list.
#[test]
fn a_write_from_the_broker_to_a_read_only_session_is_refused_as_set_is() {
    if !mosquitto_present() {
        return;
    }
    let d = dir("read-only");
    let port = free_port();
    let _broker = Broker::start(&d, port);
    let cfg = d.join("devices.toml");
    std::fs::write(
        &cfg,
        "[devices.a]\nurl = \"sim:K205-16DT\"\nallow = [\"VW100\"]\n[fleets.one]\ndevices = [\"a\"]\n",
    )
    .unwrap();
    let got = subscribe(port, "read-only-watch");
    let mut child = plcsh()
        .args(["--config", cfg.to_str().unwrap(), "--read-only", "--json", "publish", "-f", "one"])
        .args(["--accept-writes", "--broker", &format!("mqtt://127.0.0.1:{port}"), "--every", "20ms", "VW100"])
        .stdout(Stdio::null())
        .stderr(Stdio::null())
        .spawn()
        .unwrap();
    wait_for(&got, "the first value", |g| g.iter().any(|(t, _, _)| t == "plcsh/one/a/VW100"));
    let mut opts = rumqttc::MqttOptions::new("read-only-writer", "127.0.0.1", port);
    opts.set_keep_alive(Duration::from_secs(5));
    let (client, mut conn) = rumqttc::Client::new(opts, 10);
    std::thread::spawn(move || for _ in conn.iter() {});
    let body = r#"{"operand":"VW100","value":5,"id":"ro"}"#;
    client.publish("plcsh/one/a/set", rumqttc::QoS::AtLeastOnce, false, body.as_bytes().to_vec()).unwrap();
    wait_for(&got, "the reply", |g| g.iter().any(|(t, _, _)| t == "plcsh/one/a/reply"));
    plcsh::core::platform::interrupt_child(&child);
    let _ = child.wait();
    let reply = got.lock().unwrap().iter().find(|(t, _, _)| t == "plcsh/one/a/reply").map(|(_, p, _)| json(p)).unwrap();
    let o = run(&["--config", cfg.to_str().unwrap(), "--read-only", "--json", "-d", "a", "-c", "set VW100=5"], "");
    let by_set = json_lines(&o).pop().unwrap_or_else(|| panic!("{}", both(&o)));
    assert_eq!((reply["ok"].as_bool(), reply["id"].as_str()), (Some(false), Some("ro")), "{reply}");
    assert_eq!(reply["error"]["kind"], "refused", "{reply}");
    assert_eq!(
        (&reply["error"]["kind"], &reply["error"]["message"]),
        (&by_set["error"]["kind"], &by_set["error"]["message"]),
        "the same refusal as `set`: {reply} / {by_set}"
    );
    assert!(
        !got.lock().unwrap().iter().any(|(t, p, _)| t == "plcsh/one/a/VW100" && json(p)["value"] != 0),
        "nothing was written"
    );
}

// ---------------------------------------------------------------------------------------------
// A broker that breaks the connection again and again while readings flow: a minimal MQTT
// 3.1.1 server written here (CONNECT → CONNACK without a session, PUBLISH QoS 1 → PUBACK,
// SUBSCRIBE → SUBACK, PINGREQ → PINGRESP; MQTT 3.1.1, §3), which records every reading in the
// order it arrived and closes the connection after a few readings. A reading taken after a
// break must never arrive before one taken earlier (a reconnect puts what the broker did not
// acknowledge back at the front of the queue), whatever the break interrupted.

/// One MQTT control packet from `s`: its first byte and its body; `None` at the end.
fn mqtt_packet(s: &mut std::net::TcpStream) -> Option<(u8, Vec<u8>)> {
    use std::io::Read;
    let mut b = [0u8; 1];
    s.read_exact(&mut b).ok()?;
    let (mut len, mut shift) = (0usize, 0);
    loop {
        let mut d = [0u8; 1];
        s.read_exact(&mut d).ok()?;
        len |= ((d[0] & 0x7F) as usize) << shift;
        if d[0] & 0x80 == 0 {
            break;
        }
        shift += 7;
        if shift > 21 {
            return None;
        }
    }
    let mut body = vec![0u8; len];
    s.read_exact(&mut body).ok()?;
    Some((b[0], body))
}

/// What the breaking broker saw: the readings' `seq` in arrival order.
type Seqs = Arc<Mutex<Vec<u64>>>;

/// The breaking broker on a free port: the readings' `seq` in arrival order, and how many
/// connections it broke. It closes each connection after `every` readings, `breaks` times.
fn breaking_broker(every: usize, breaks: usize) -> (u16, Seqs, Arc<Mutex<usize>>) {
    use std::io::Write;
    let listener = std::net::TcpListener::bind("127.0.0.1:0").unwrap();
    let port = listener.local_addr().unwrap().port();
    let seqs: Seqs = Arc::default();
    let broken: Arc<Mutex<usize>> = Arc::default();
    let (seqs2, broken2) = (seqs.clone(), broken.clone());
    std::thread::spawn(move || {
        for conn in listener.incoming() {
            let Ok(mut s) = conn else { continue };
            let mut taken = 0;
            while let Some((first, body)) = mqtt_packet(&mut s) {
                let reply: Vec<u8> = match first >> 4 {
                    1 => vec![0x20, 2, 0, 0],
                    3 => {
                        let qos = (first >> 1) & 3;
                        let tlen = u16::from_be_bytes([body[0], body[1]]) as usize;
                        let topic = String::from_utf8_lossy(&body[2..2 + tlen]).to_string();
                        let at = 2 + tlen + if qos > 0 { 2 } else { 0 };
                        if topic.ends_with("/VW100") {
                            let v: serde_json::Value = serde_json::from_slice(&body[at..]).unwrap();
                            seqs2.lock().unwrap().push(v["seq"].as_u64().unwrap());
                            taken += 1;
                        }
                        if *broken2.lock().unwrap() < breaks && taken >= every {
                            // Gone without a word, the last reading unacknowledged.
                            *broken2.lock().unwrap() += 1;
                            break;
                        }
                        if qos > 0 {
                            vec![0x40, 2, body[2 + tlen], body[3 + tlen]]
                        } else {
                            Vec::new()
                        }
                    }
                    8 => vec![0x90, 3, body[0], body[1], 0],
                    12 => vec![0xD0, 0],
                    14 => break,
                    _ => Vec::new(),
                };
                if !reply.is_empty() && s.write_all(&reply).is_err() {
                    break;
                }
            }
            let _ = s.shutdown(std::net::Shutdown::Both);
        }
    });
    (port, seqs, broken)
}

#[test]
fn readings_keep_their_order_across_many_broken_connections() {
    let (port, seqs, broken) = breaking_broker(15, 10);
    let o = run(
        &[
            "--json",
            "publish",
            "--broker",
            &format!("mqtt://127.0.0.1:{port}"),
            "--every",
            "5ms",
            "--count",
            "300",
            "--qos",
            "1",
            "VW100",
            "VW102",
            "VW104",
            "VW106",
        ],
        "",
    );
    let l = json_lines(&o);
    let summary = l.last().unwrap_or_else(|| panic!("{}", both(&o)));
    assert_eq!(summary["ok"], true, "{}", both(&o));
    assert_eq!(*broken.lock().unwrap(), 10, "{summary}");
    assert!(summary["reconnects"].as_u64().unwrap() >= 10, "{summary}");
    assert_eq!(summary["dropped"], 0, "{summary}");
    let s = seqs.lock().unwrap().clone();
    let (mut highest, mut seen) = (0, std::collections::HashSet::new());
    for &x in &s {
        // A repeat is a resend of what the broker did not acknowledge; a reading not seen before
        // comes after every earlier one.
        if seen.insert(x) {
            assert!(x > highest, "out of order at {x}: {s:?}");
            highest = x;
        }
    }
    let skipped = summary["skipped"].as_u64().unwrap();
    assert_eq!(seen.len() as u64 + skipped, 300, "every reading arrived: {s:?} {summary}");
}
