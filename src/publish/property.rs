//! The publisher's invariant, checked over generated runs: every message it hands to the
//! broker is true — a value on `plcsh/GROUP/DEVICE/OPERAND` is that device's value of that
//! operand (the payload names the same device and operand), a status says what the device's
//! state was, and every message queued is delivered or counted as dropped, never lost
//! unnoticed.
//!
//! Each case serves a fleet of in-process simulated K2s whose every register holds a value
//! derived from (device, operand), behind a wrapper that fails on command (no reply, a
//! Modbus exception, a link down; members that cannot be opened at the start and come back),
//! and publishes a random operand list (words, bits, ranges, repeated operands) with a random
//! `--buffer` and `--every` into the real queue ([`super::outbox`]). A consumer in the place of
//! the broker thread takes messages at a random pace, goes away and comes back (putting back
//! what it held, as a reconnect without the old session does), and checks each message.
//! The MQTT side (QoS 0 and 1, a real broker) is covered by tests/publish.rs with the same
//! check; bench/fleet.sh runs it at plant size.

use super::outbox::{Msg, Outbox};
use super::poller::{Member, Pool, Reopen};
use super::Poll;
use crate::core::test_rng::Rng;
use crate::core::{Device, DeviceInfo, Error, ErrorKind, Operand, OperandSpace, Result, Value};
use crate::session::Session;
use std::sync::atomic::{AtomicU64, AtomicU8, Ordering};
use std::sync::Arc;
use std::time::Duration;

/// How a wrapped device behaves now.
const OK: u8 = 0;
const NO_REPLY: u8 = 1;
const EXCEPTION: u8 = 2;
const DOWN: u8 = 3;

/// A simulated K2 that fails while its mode says so, and whose words read `POLL` ×
/// [`POLL`] more than they hold (POLL counts its good reads): a value names its poll too.
struct Flaky {
    inner: Box<dyn Device>,
    mode: Arc<AtomicU8>,
    reads: i64,
}

/// A word's value is `expected + POLL × k` at the device's k-th good read.
const POLL: i64 = 100_000;

impl Flaky {
    fn check(&self) -> Result<()> {
        match self.mode.load(Ordering::Relaxed) {
            NO_REPLY => Err(Error::link("the device did not answer: no reply from unit 1 within 300 ms")),
            EXCEPTION => Err(Error::new(ErrorKind::Refused, "the PLC refused the read: busy (Modbus exception 06)")),
            DOWN => Err(Error::link("cannot connect to 127.0.0.1:502")),
            _ => Ok(()),
        }
    }
}

impl Device for Flaky {
    fn info(&self) -> &DeviceInfo {
        self.inner.info()
    }
    fn operands(&self) -> &dyn OperandSpace {
        self.inner.operands()
    }
    fn read(&mut self, ops: &[Operand]) -> Result<Vec<Value>> {
        self.check()?;
        self.reads += 1;
        let k = self.reads;
        Ok(self
            .inner
            .read(ops)?
            .into_iter()
            .map(|v| if let Value::Int(n) = v { Value::Int(n + POLL * k) } else { v })
            .collect())
    }
    fn write(&mut self, items: &[(Operand, Value)]) -> Result<()> {
        self.check()?;
        self.inner.write(items)
    }
}

/// The value every device holds in VW0..VW40 and M0.0..M2.7: derived from the device and the operand.
fn expected(dev: u32, operand: &str) -> Option<serde_json::Value> {
    if let Some(n) = operand.strip_prefix("VW") {
        return Some(serde_json::json!(1000 * (dev as u64 + 1) + n.parse::<u64>().ok()?));
    }
    let (byte, bit) = operand.strip_prefix('M')?.split_once('.')?;
    let i = byte.parse::<u32>().ok()? * 8 + bit.parse::<u32>().ok()?;
    Some(serde_json::json!((dev + i).is_multiple_of(3)))
}

/// Device `dev`'s session: a simulated K2 named `d{dev}`, its registers set, behind [`Flaky`].
fn session(dev: u32, mode: Arc<AtomicU8>) -> Session {
    let mut device = crate::session::open_url("sim:K205-16DT", &crate::core::Clock::following()).unwrap();
    let mut items = Vec::new();
    let mut names: Vec<String> = (0..=40).step_by(2).map(|n| format!("VW{n}")).collect();
    names.extend((0..3).flat_map(|b| (0..8).map(move |i| format!("M{b}.{i}"))));
    for name in &names {
        let op = device.operands().parse(name).unwrap()[0];
        let v = match expected(dev, name).unwrap() {
            serde_json::Value::Bool(b) => Value::Bool(b),
            n => device.operands().value(&op, &n.to_string()).unwrap(),
        };
        items.push((op, v));
    }
    device.write(&items).unwrap();
    let mut s = Session::new(crate::core::Clock::following());
    let name = format!("d{dev}");
    s.add(&name, "sim:K205-16DT", Box::new(Flaky { inner: device, mode, reads: 0 }));
    s.use_device(&name).unwrap();
    s
}

/// A random operand list: words, word ranges, bits, bit ranges, and repeats.
fn operands(r: &mut Rng) -> Vec<String> {
    let mut list: Vec<String> = Vec::new();
    for _ in 0..r.in_range(1, 5) {
        let t = match r.below(5) {
            0 => format!("VW{}", 2 * r.below(21)),
            1 => {
                let a = 2 * r.below(15);
                format!("VW{a}..VW{}", a + 2 * r.below(6))
            }
            2 => format!("M{}.{}", r.below(3), r.below(8)),
            3 => {
                let a = r.below(6);
                format!("M1.{a}..M1.{}", a + r.below(8 - a))
            }
            _ => match list.last() {
                Some(t) => t.clone(),
                None => "VW0".into(),
            },
        };
        list.push(t);
    }
    list
}

/// Checks one message; returns whether it was a value. `polls` keeps, per (device, seq), the
/// read its words came from: every value of one poll must come from the same read, and a
/// later poll from a later read.
fn check(m: &Msg, devices: u32, case: u64, polls: &mut std::collections::HashMap<(u32, u64), i64>) -> bool {
    let text = String::from_utf8_lossy(&m.payload);
    let parts: Vec<&str> = m.topic.split('/').collect();
    assert_eq!(parts.len(), 4, "case {case}: {} {text}", m.topic);
    let dev: u32 = parts[2].strip_prefix('d').and_then(|d| d.parse().ok()).unwrap_or(u32::MAX);
    assert!(dev < devices, "case {case}: {} {text}", m.topic);
    assert_eq!(m.dev, dev, "case {case}: counted for the device it names: {} {text}", m.topic);
    let j: serde_json::Value = serde_json::from_slice(&m.payload).unwrap();
    if parts[3] == "status" {
        match j["state"].as_str() {
            Some("online") => assert!(j.get("reason").is_none(), "case {case}: {text}"),
            Some("offline") => assert!(
                ["no reply", "exception 6", "unreachable"].contains(&j["reason"].as_str().unwrap_or("")),
                "case {case}: {text}"
            ),
            _ => panic!("case {case}: {} {text}", m.topic),
        }
        return false;
    }
    assert_eq!(j["device"], parts[2], "case {case}: {} {text}", m.topic);
    assert_eq!(j["operand"], parts[3], "case {case}: {} {text}", m.topic);
    let want = expected(dev, parts[3]);
    match (j["value"].as_i64(), want.as_ref().and_then(|w| w.as_i64())) {
        (Some(got), Some(base)) => {
            let k = got - base;
            assert!(k > 0 && k % POLL == 0, "case {case}: {} {text}: not {base} + {POLL} × k", m.topic);
            let seq = j["seq"].as_u64().unwrap();
            let read = *polls.entry((dev, seq)).or_insert(k / POLL);
            assert_eq!(read, k / POLL, "case {case}: one poll, one read: {} {text}", m.topic);
            let earlier = polls.iter().filter(|((d, s), _)| *d == dev && *s < seq).map(|(_, r)| *r).max();
            assert!(earlier.is_none_or(|e| e < read), "case {case}: a later poll, a later read: {} {text}", m.topic);
        }
        _ => assert_eq!(Some(&j["value"]), want.as_ref(), "case {case}: {} {text}", m.topic),
    }
    true
}

/// One generated run; returns the number of values checked.
fn run_case(case: u64) -> u64 {
    let mut r = Rng(case.wrapping_mul(0x9E37_79B9_7F4A_7C15) | 1);
    let devices = r.in_range(1, 4) as u32;
    let texts = operands(&mut r);
    let buffer = r.pick(&[1, 2, 4, 7, 16, 10_000]);
    let every = Duration::from_micros(r.in_range(500, 3000) as u64);
    let count = r.in_range(2, 10) as u64;
    let modes: Vec<Arc<AtomicU8>> = (0..devices).map(|_| Arc::new(AtomicU8::new(OK))).collect();
    let members: Vec<Member> = (0..devices)
        .map(|d| {
            let mode = modes[d as usize].clone();
            let name = format!("d{d}");
            if r.below(4) == 0 {
                // Cannot be opened at the start; opens after a few tries.
                let tries = Arc::new(AtomicU64::new(r.below(3)));
                let reopen: Reopen = Box::new(move || {
                    if tries.fetch_sub(1, Ordering::Relaxed) > 0 {
                        Err(Error::link("cannot connect to 127.0.0.1:502"))
                    } else {
                        Ok(session(d, mode.clone()))
                    }
                });
                Member { name, session: Err(Error::link("cannot connect to 127.0.0.1:502")), reopen: Some(reopen) }
            } else {
                Member { name, session: Ok(session(d, mode)), reopen: None }
            }
        })
        .collect();
    let outbox = Arc::new(Outbox::new(buffer, devices as usize));
    let mut connected = r.below(3) > 0;
    outbox.set_connected(connected);
    let poll = Poll { group: "g".into(), operands: texts.clone(), every, deadband: None, count: Some(count) };
    let (tx, _seen) = std::sync::mpsc::channel();
    let pool = Pool::start(members, poll, outbox.clone(), tx).unwrap();
    let (mut delivered, mut values) = (0u64, 0u64);
    let mut held = Vec::new();
    let mut polls = std::collections::HashMap::new();
    let faulty = r.below(2) == 0;
    loop {
        let done = pool.finished();
        if faulty && r.below(8) == 0 {
            let d = r.below(devices as u64) as usize;
            modes[d].store(r.pick(&[OK, OK, NO_REPLY, EXCEPTION, DOWN]), Ordering::Relaxed);
        }
        if connected {
            outbox.take(r.in_range(1, 6) as usize, &mut held);
            if r.below(10) == 0 && !done {
                // The broker went away before these left: back to the front, in order.
                outbox.put_back(held.drain(..));
                connected = false;
                outbox.set_connected(false);
            } else {
                for m in held.drain(..) {
                    values += u64::from(check(&m, devices, case, &mut polls));
                    delivered += 1;
                }
            }
        } else if r.below(3) == 0 || done {
            connected = true;
            outbox.set_connected(true);
        }
        if done && connected && outbox.is_empty() {
            break;
        }
        if r.below(3) == 0 {
            std::thread::sleep(Duration::from_micros(r.in_range(50, 800) as u64));
        }
    }
    pool.join();
    let (_, behind, away) = outbox.totals();
    assert_eq!(
        delivered + behind + away,
        outbox.accepted.load(Ordering::Relaxed),
        "case {case}: every message queued is delivered or counted ({texts:?}, buffer {buffer})"
    );
    values
}

#[test]
fn every_published_message_is_true_over_generated_runs() {
    // PLCSH_BENCH_PUBLISH_CASES raises the number of cases (bench/fleet.sh: plant size).
    let cases: u64 = std::env::var("PLCSH_BENCH_PUBLISH_CASES").ok().and_then(|n| n.parse().ok()).unwrap_or(1000);
    let first: u64 = std::env::var("PLCSH_BENCH_PUBLISH_SEED").ok().and_then(|n| n.parse().ok()).unwrap_or(1);
    let started = std::time::Instant::now();
    let values: u64 = (first..first + cases).map(run_case).sum();
    assert!(values > cases, "values were checked: {values} in {cases} cases");
    eprintln!("{cases} cases, {values} values checked in {:?}", started.elapsed());
}

#[test]
fn a_device_that_cannot_be_opened_is_tried_with_backoff_and_published_once_it_opens() {
    let tries = Arc::new(AtomicU64::new(0));
    let opens_at = std::time::Instant::now() + Duration::from_millis(600);
    let counted = tries.clone();
    let reopen: Reopen = Box::new(move || {
        counted.fetch_add(1, Ordering::Relaxed);
        if std::time::Instant::now() < opens_at {
            Err(Error::link("cannot connect to 127.0.0.1:502"))
        } else {
            Ok(session(0, Arc::new(AtomicU8::new(OK))))
        }
    });
    let member = Member { name: "d0".into(), session: Err(Error::link("cannot connect")), reopen: Some(reopen) };
    let outbox = Arc::new(Outbox::new(10_000, 1));
    let poll = Poll {
        group: "g".into(),
        operands: vec!["VW0..VW2".into()],
        every: Duration::from_millis(5),
        deadband: None,
        count: None,
    };
    let (tx, seen) = std::sync::mpsc::channel();
    let pool = Pool::start(vec![member], poll, outbox.clone(), tx).unwrap();
    let deadline = std::time::Instant::now() + Duration::from_secs(20);
    let mut got = Vec::new();
    while !got.iter().any(|m: &Msg| m.topic == "plcsh/g/d0/VW2") {
        assert!(std::time::Instant::now() < deadline, "never published: {got:?}");
        outbox.take(usize::MAX, &mut got);
        std::thread::sleep(Duration::from_millis(5));
    }
    pool.stop();
    pool.join();
    // Every 5 ms for 600 ms would be 120 tries; the backoff (5, 10, 20 … ms) makes it about 8.
    let n = tries.load(Ordering::Relaxed);
    assert!((3..=14).contains(&n), "{n} tries");
    let status: Vec<String> = got
        .iter()
        .filter(|m| m.topic == "plcsh/g/d0/status")
        .map(|m| String::from_utf8_lossy(&m.payload).into_owned())
        .collect();
    assert_eq!(status, [r#"{"state":"offline","reason":"unreachable"}"#, r#"{"state":"online"}"#], "once each");
    let told: Vec<String> = seen.try_iter().map(|s| format!("{s:?}")).collect();
    assert_eq!(told.len(), 2, "one report per change: {told:?}");
    let mut polls = std::collections::HashMap::new();
    let values = got.iter().filter(|m| check(m, 1, 0, &mut polls)).count();
    assert!(values >= 2, "{got:?}");
}
