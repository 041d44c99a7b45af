//! Polling many devices on a fixed-rate schedule with a small pool of threads.
//!
//! **The model.** Every device has a schedule: poll k is due at `start + phase + k·every`
//! (the phase spreads the devices over one period so they do not all fire at once). The due
//! instants of all devices sit in one binary heap; a pool of worker threads takes the
//! earliest due device, waits (a timed wait on a condition variable, no sleep slicing) until
//! its time — or takes it at once when it is due within [`SLACK`], so a busy pool polls one
//! device after the next without a sleep and a wake-up per poll — polls it with the same
//! reader as `get` (the operand texts resolved once into a plan), queues the poll's values at
//! once ([`super::outbox`]) and puts the device back with its next due instant. A device is
//! held by one worker at a time, so its polls never overlap and stay in order.
//!
//! **Where the CPU goes.** Measured with `perf` at 1 000 devices at 10 Hz (BENCHMARKS.md,
//! "Fleet publishing at scale"): mostly in wake-ups and the kernel's TCP — each poll's
//! request and answer, each message rumqttc writes (one write per message) — not in building
//! payloads. So a worker does not sleep between polls that are due within [`SLACK`], and the
//! broker thread lets readings gather for a moment instead of waking for every poll.
//!
//! **Late polls.** The next poll is always the next slot of the schedule, never "every after
//! the last poll started", so the rate does not drift. When a poll (or the pool) ran so late
//! that whole slots have passed, those slots are skipped — the next poll reads the newest
//! values — and counted per device as `skipped`; `seq` in the payload is the slot number, so
//! a historian sees the gap.
//!
//! **Why a pool and not a thread per device.** The `Device` interface is synchronous; a
//! thread per device (the first design) costs a stack and a wake-up per poll per device and,
//! past about 800 devices at 10 Hz on two cores, spent more time switching than polling. The
//! pool starts with two threads per core (at least 4); a device that is slow to answer
//! holds only the worker polling it, and when a due poll finds no idle worker and is already
//! half a period late, the pool grows by one (up to [`MAX_WORKERS`]), so a few silent
//! devices waiting out their timeouts do not hold the others. Async transports would avoid
//! even that but would mean a second implementation of every driver; measured in
//! BENCHMARKS.md ("Fleet publishing at scale").
//!
//! **What a device costs.** A device is a [`Session`] with one open device, no Lua state and
//! no copy of the profile file (the fleet's member list is not copied into every member),
//! and the topics and JSON pieces of its operands, built once.

use super::outbox::{Msg, Outbox};
use super::{changed, now_ms, Poll, Seen};
use crate::core::{Error, Value};
use crate::session::Session;
use std::cmp::Reverse;
use std::collections::{BinaryHeap, HashMap};
use std::io::Write as _;
use std::sync::atomic::Ordering;
use std::sync::{Arc, Condvar, Mutex};
use std::time::{Duration, Instant};

/// A worker that finds the next poll due within this much (and at most a hundredth of the
/// period) takes it at once instead of sleeping for it: at 1 000 devices at 10 Hz a poll is
/// due every 0.1 ms, and a sleep and wake-up per poll cost more than the poll's own work.
pub const SLACK: Duration = Duration::from_millis(1);

/// The most worker threads one publisher grows to.
pub const MAX_WORKERS: usize = 64;

/// Opens a member's session again (a device that could not be opened, tried again later).
pub type Reopen = Box<dyn FnMut() -> std::result::Result<Session, Error> + Send>;

/// One device to poll: its name, its session (or why it could not be opened) and how to
/// open it again when it could not.
pub struct Member {
    pub name: String,
    pub session: std::result::Result<Session, Error>,
    pub reopen: Option<Reopen>,
}

/// The longest wait between two tries of a device that is offline (the backoff starts at
/// one period and doubles up to this; a device is tried again for as long as the run lasts).
pub const RETRY_MAX: Duration = Duration::from_secs(5);

/// Why a device is offline, in a word a consumer can switch on (the `reason` of the
/// device's status and of the `--json` device event): `unreachable` (no connection could be
/// made), `no reply` (connected, but it did not answer in time), `exception N` (it answered
/// with Modbus exception N), `refused` (it refused otherwise, or its profile cannot be used).
pub fn reason(e: &Error) -> String {
    use crate::core::ErrorKind as K;
    let m = e.message.to_ascii_lowercase();
    match e.kind {
        K::Refused => match m.find("exception ") {
            Some(at) => {
                let digits: String = m[at + 10..].chars().take_while(char::is_ascii_digit).collect();
                match digits.parse::<u32>() {
                    Ok(n) => format!("exception {n}"),
                    Err(_) => "refused".into(),
                }
            }
            None => "refused".into(),
        },
        K::Timeout => "no reply".into(),
        K::Link | K::Io
            if m.contains("no reply") || m.contains("did not answer") || m.contains("instead of replying") =>
        {
            "no reply".into()
        }
        K::Link | K::Io | K::Interrupted => "unreachable".into(),
        _ => "refused".into(),
    }
}

/// The retained payload of a device's status topic: `{"state":"online"}` or
/// `{"state":"offline","reason":"no reply"}` (docs/fleets.md, "Topics").
pub fn status_payload(online: bool, why: Option<&str>) -> Vec<u8> {
    match (online, why) {
        (true, _) => br#"{"state":"online"}"#.to_vec(),
        (false, Some(r)) => format!(r#"{{"state":"offline","reason":{}}}"#, serde_json::Value::from(r)).into_bytes(),
        (false, None) => br#"{"state":"offline"}"#.to_vec(),
    }
}

/// One operand's topic and the pieces of its payload, built once.
struct Leaf {
    topic: String,
    /// `,"type":"WORD","ts":` — the payload's middle.
    mid: String,
    /// `,"device":"NAME","operand":"OP"}` — the payload's tail.
    tail: String,
    /// The message's identity: (device, leaf + 1); a device's status is leaf 0.
    key: (u32, u32),
}

/// What a device's poll reads, resolved once from the operand texts after its first good
/// read (the model is known then): the operands and the leaf of each. A poll then reads
/// them straight from the device, without parsing the texts or naming each value again.
struct Plan {
    /// The device's index in its session.
    device: usize,
    ops: Vec<crate::core::Operand>,
    leaves: Vec<usize>,
}

struct Dev {
    name: String,
    /// The device's index in the pool (the first half of its messages' keys).
    index: u32,
    session: std::result::Result<Session, Error>,
    reopen: Option<Reopen>,
    /// The wait before the next try while offline (doubles up to [`RETRY_MAX`]).
    backoff: Duration,
    /// Why it went offline (while it is).
    reason: Option<String>,
    /// The operands' leaves, in the order they were first read.
    leaves: Vec<Leaf>,
    /// A leaf's index by the operand's name as read.
    leaf_of: HashMap<String, usize>,
    /// The resolved reads (dropped when the device goes offline: it may come back another model).
    plan: Option<Plan>,
    status_topic: String,
    /// The last published value of each leaf (`--deadband`).
    last: Vec<Option<Value>>,
    online: Option<bool>,
    /// The next slot of the schedule (0-based).
    slot: u64,
    phase: Duration,
}

impl Dev {
    /// The leaf of operand `name` (made on its first reading). A tag's name (`crate::names`)
    /// is the topic's last level and rides in the payload as `name` beside `operand`.
    fn leaf(&mut self, group: &str, name: &str, tag: Option<&str>, dtype: crate::core::DataType) -> usize {
        if let Some(&i) = self.leaf_of.get(name) {
            return i;
        }
        let i = self.leaves.len();
        let dtype = serde_json::to_string(&dtype).unwrap_or_else(|_| "null".into());
        let tag_field = tag.map(|t| format!(",\"name\":{}", serde_json::Value::from(t))).unwrap_or_default();
        self.leaves.push(Leaf {
            topic: super::topic(group, &self.name, tag.unwrap_or(name)),
            mid: format!(",\"type\":{dtype},\"ts\":"),
            tail: format!(
                ",\"device\":{},\"operand\":{}{tag_field}}}",
                serde_json::Value::from(self.name.as_str()),
                serde_json::Value::from(name)
            ),
            key: (self.index, 1 + i as u32),
        });
        self.last.push(None);
        self.leaf_of.insert(name.to_string(), i);
        i
    }

    /// Resolves the operand texts once into a [`Plan`] (`None`: they name more than one
    /// device, or do not resolve; the poll then goes through [`Session::get`] each time).
    fn plan(&mut self, group: &str, texts: &[String]) -> Option<()> {
        let session = self.session.as_ref().ok()?;
        let mut device = None;
        let mut named = Vec::new();
        for t in texts {
            let target = session.resolve(t).ok()?;
            if *device.get_or_insert(target.device) != target.device {
                return None;
            }
            for op in target.ops {
                let tag = session.tag_of(target.device, &op).map(|t| t.name.clone());
                named.push((op, session.name_of(target.device, &op), tag));
            }
        }
        let device = device?;
        let leaves = named.iter().map(|(op, name, tag)| self.leaf(group, name, tag.as_deref(), op.dtype)).collect();
        self.plan = Some(Plan { device, ops: named.into_iter().map(|(op, ..)| op).collect(), leaves });
        Some(())
    }
}

struct Sched {
    heap: BinaryHeap<Reverse<(Instant, u32)>>,
    stop: bool,
    idle: usize,
    workers: usize,
    /// Devices still on the schedule (not finished their `--count`).
    live: usize,
}

/// The pool, its devices and their schedule.
pub struct Pool {
    devs: Vec<Mutex<Dev>>,
    /// Writes from the broker waiting for their device's next poll (`--accept-writes`).
    commands: Vec<Mutex<Vec<Vec<u8>>>>,
    sched: Mutex<Sched>,
    cv: Condvar,
    outbox: Arc<Outbox>,
    seen: Mutex<std::sync::mpsc::Sender<Seen>>,
    poll: Poll,
    texts: Vec<String>,
    start: Instant,
    threads: Mutex<Vec<std::thread::JoinHandle<()>>>,
}

impl Pool {
    /// Starts polling `members` (their order is the fleet's); values go to `outbox`, device
    /// state changes to `seen`.
    pub fn start(
        members: Vec<Member>,
        poll: Poll,
        outbox: Arc<Outbox>,
        seen: std::sync::mpsc::Sender<Seen>,
    ) -> std::io::Result<Arc<Pool>> {
        let n = members.len().max(1);
        let start = Instant::now();
        let every = poll.every;
        let mut heap = BinaryHeap::new();
        let devs: Vec<Mutex<Dev>> = members
            .into_iter()
            .enumerate()
            .map(|(i, m)| {
                let phase = every.mul_f64(i as f64 / n as f64);
                heap.push(Reverse((start + phase, i as u32)));
                Mutex::new(Dev {
                    status_topic: super::topic(&poll.group, &m.name, "status"),
                    name: m.name,
                    index: i as u32,
                    session: m.session,
                    reopen: m.reopen,
                    backoff: every,
                    reason: None,
                    leaves: Vec::new(),
                    leaf_of: HashMap::new(),
                    plan: None,
                    last: Vec::new(),
                    online: None,
                    slot: 0,
                    phase,
                })
            })
            .collect();
        let count = devs.len();
        let workers = count.min((2 * std::thread::available_parallelism().map_or(2, |n| n.get())).max(4));
        let pool = Arc::new(Pool {
            commands: (0..count).map(|_| Mutex::new(Vec::new())).collect(),
            devs,
            sched: Mutex::new(Sched { heap, stop: false, idle: 0, workers: 0, live: count }),
            cv: Condvar::new(),
            outbox,
            seen: Mutex::new(seen),
            texts: poll.operands.clone(),
            poll,
            start,
            threads: Mutex::new(Vec::new()),
        });
        for _ in 0..workers {
            pool.spawn_worker()?;
        }
        Ok(pool)
    }

    fn lock(&self) -> std::sync::MutexGuard<'_, Sched> {
        self.sched.lock().unwrap_or_else(|p| p.into_inner())
    }

    fn spawn_worker(self: &Arc<Self>) -> std::io::Result<()> {
        let me = self.clone();
        self.lock().workers += 1;
        let h = std::thread::Builder::new().name("publish".into()).spawn(move || me.work());
        match h {
            Ok(h) => {
                self.threads.lock().unwrap_or_else(|p| p.into_inner()).push(h);
                Ok(())
            }
            Err(e) => {
                self.lock().workers -= 1;
                Err(e)
            }
        }
    }

    /// Queues a write for device `i`, applied before its next poll.
    pub fn command(&self, i: usize, payload: Vec<u8>) {
        if let Some(c) = self.commands.get(i) {
            c.lock().unwrap_or_else(|p| p.into_inner()).push(payload);
        }
    }

    /// Stops the schedule: workers finish the poll they are in and end.
    pub fn stop(&self) {
        self.lock().stop = true;
        self.cv.notify_all();
    }

    /// True when every device finished its `--count` (or the pool was stopped and its
    /// workers are gone).
    pub fn finished(&self) -> bool {
        let g = self.lock();
        g.live == 0 || (g.stop && g.workers == 0)
    }

    /// Waits for the workers to end (after [`Pool::stop`] or the last `--count`).
    pub fn join(&self) {
        loop {
            let Some(h) = self.threads.lock().unwrap_or_else(|p| p.into_inner()).pop() else { return };
            let _ = h.join();
        }
    }

    /// Devices that are offline (or never opened) now.
    pub fn offline(&self) -> Vec<String> {
        self.devs
            .iter()
            .filter_map(|d| {
                let d = d.lock().unwrap_or_else(|p| p.into_inner());
                (d.online == Some(false)).then(|| d.name.clone())
            })
            .collect()
    }

    /// Device `i`'s session back (after the pool has stopped), for the single device's shell.
    pub fn take_session(&self, i: usize) -> Option<Session> {
        let mut d = self.devs.get(i)?.lock().unwrap_or_else(|p| p.into_inner());
        let gone = Err(Error::state("the session was handed back"));
        std::mem::replace(&mut d.session, gone).ok()
    }

    /// Worker threads running now.
    pub fn workers(&self) -> usize {
        self.lock().workers
    }

    fn work(self: Arc<Self>) {
        let every = self.poll.every;
        let slack = (every / 100).min(SLACK);
        loop {
            let mut g = self.lock();
            let i = loop {
                if g.stop || g.live == 0 {
                    g.workers -= 1;
                    drop(g);
                    self.cv.notify_all();
                    return;
                }
                let now = Instant::now();
                match g.heap.peek() {
                    Some(&Reverse((due, i))) if due <= now + slack => {
                        g.heap.pop();
                        // Late, and nobody idle to take the next one: a worker is held by a
                        // slow device; one more worker keeps the others on time.
                        if now.saturating_duration_since(due) > every / 2
                            && g.idle == 0
                            && g.workers < MAX_WORKERS
                            && g.workers < g.live
                        {
                            drop(g);
                            let _ = self.spawn_worker();
                            g = self.lock();
                        }
                        break i as usize;
                    }
                    Some(&Reverse((due, _))) => {
                        g.idle += 1;
                        g = self.cv.wait_timeout(g, due - now).unwrap_or_else(|p| p.into_inner()).0;
                        g.idle -= 1;
                    }
                    None => {
                        g.idle += 1;
                        g = self.cv.wait(g).unwrap_or_else(|p| p.into_inner());
                        g.idle -= 1;
                    }
                }
            };
            drop(g);
            let next = self.poll_one(i);
            let mut g = self.lock();
            match next {
                Some(due) => {
                    let earliest = g.heap.peek().is_none_or(|Reverse((d, _))| due < *d);
                    g.heap.push(Reverse((due, i as u32)));
                    if earliest && g.idle > 0 {
                        self.cv.notify_one();
                    }
                }
                None => {
                    g.live -= 1;
                    if g.live == 0 {
                        self.cv.notify_all();
                    }
                }
            }
        }
    }

    fn send(&self, m: Msg) {
        self.outbox.push(m);
    }

    fn tell(&self, s: Seen) {
        let _ = self.seen.lock().unwrap_or_else(|p| p.into_inner()).send(s);
    }

    /// Marks a device offline: its retained status with the reason, and the front end told
    /// why — once per change of state (the reason is the one it went offline with).
    fn mark_offline(&self, d: &mut Dev, e: Error) {
        if d.online == Some(false) {
            return;
        }
        let why = reason(&e);
        self.send(Msg {
            topic: d.status_topic.clone(),
            payload: status_payload(false, Some(&why)),
            retain: true,
            key: Some((d.index, 0)),
            dev: d.index,
        });
        d.online = Some(false);
        d.reason = Some(why);
        self.tell(Seen::Offline(d.name.clone(), e));
    }

    /// Polls device `i` once (writes first; a device not opened yet is opened first);
    /// returns its next due instant, `None` when done.
    fn poll_one(&self, i: usize) -> Option<Instant> {
        let mut guard = self.devs[i].lock().unwrap_or_else(|p| p.into_inner());
        let d = &mut *guard;
        let p = &self.poll;
        let dev = i as u32;
        if d.session.is_err() {
            match d.reopen.as_mut() {
                // Never opened (or lost): tried again, on the backoff below.
                Some(open) => d.session = open(),
                None => {
                    // Nothing to open it with: offline once, and off the schedule.
                    let e = d.session.as_ref().err().cloned().unwrap_or_else(|| Error::state("not open"));
                    self.mark_offline(d, e);
                    return None;
                }
            }
        }
        d.slot += 1;
        let seq = d.slot;
        // Writes from the broker (`--accept-writes`) first, so this poll shows them.
        let cmds = std::mem::take(&mut *self.commands[i].lock().unwrap_or_else(|p| p.into_inner()));
        let read: crate::core::Result<Vec<(usize, Value)>> = match &mut d.session {
            Err(e) => {
                for payload in cmds {
                    let reply = super::writes::offline(&d.name, e, &payload);
                    self.send(Msg {
                        topic: super::topic(&p.group, &d.name, "reply"),
                        payload: reply.to_string().into_bytes(),
                        retain: false,
                        key: None,
                        dev,
                    });
                }
                Err(e.clone())
            }
            Ok(session) => {
                for payload in cmds {
                    let reply = super::writes::apply(session, &d.name, &payload);
                    self.send(Msg {
                        topic: super::topic(&p.group, &d.name, "reply"),
                        payload: reply.to_string().into_bytes(),
                        retain: false,
                        key: None,
                        dev,
                    });
                }
                // The resolved plan when there is one (one read, no parsing); the general
                // reader the first time and whenever the texts do not make a plan.
                match &d.plan {
                    Some(plan) => session
                        .ready(plan.device)
                        .and_then(|()| session.read_values(plan.device, &plan.ops))
                        .map(|values| plan.leaves.iter().copied().zip(values).collect()),
                    None => {
                        let texts: Vec<&str> = self.texts.iter().map(String::as_str).collect();
                        match session.get(&texts) {
                            Ok(readings) => Ok(readings
                                .into_iter()
                                .map(|(_, r)| (d.leaf(&p.group, &r.operand, r.name.as_deref(), r.dtype), r.value))
                                .collect()),
                            Err(e) => Err(e),
                        }
                    }
                }
            }
        };
        let mut wait = None;
        match read {
            Ok(values) => {
                let ts = now_ms();
                if d.plan.is_none() {
                    d.plan(&p.group, &self.texts);
                }
                d.backoff = p.every;
                let mut batch = Vec::with_capacity(values.len() + 1);
                if d.online != Some(true) {
                    // Back (or first): every value is published fresh.
                    d.last.iter_mut().for_each(|l| *l = None);
                    batch.push(Msg {
                        topic: d.status_topic.clone(),
                        payload: status_payload(true, None),
                        retain: true,
                        key: Some((d.index, 0)),
                        dev,
                    });
                    if d.online.is_some() {
                        self.tell(Seen::Online(d.name.clone()));
                    }
                    d.online = Some(true);
                    d.reason = None;
                }
                for (l, value) in values {
                    if let Some(db) = p.deadband {
                        if !changed(d.last[l].as_ref(), &value, db) {
                            continue;
                        }
                        d.last[l] = Some(value);
                    }
                    let leaf = &d.leaves[l];
                    // `{"value":V,"type":"T","ts":TS,"seq":SEQ,"device":"D","operand":"O"}`,
                    // written straight into the message's own buffer.
                    let mut payload = Vec::with_capacity(48 + leaf.mid.len() + leaf.tail.len());
                    payload.extend_from_slice(b"{\"value\":");
                    if serde_json::to_writer(&mut payload, &value).is_err() {
                        payload.extend_from_slice(b"null");
                    }
                    payload.extend_from_slice(leaf.mid.as_bytes());
                    let _ = write!(payload, "{ts},\"seq\":{seq}");
                    payload.extend_from_slice(leaf.tail.as_bytes());
                    batch.push(Msg { topic: leaf.topic.clone(), payload, retain: true, key: Some(leaf.key), dev });
                }
                self.outbox.push_all(batch);
            }
            // A stop (Ctrl-C) that cut a read short says nothing about the device.
            Err(e) if e.kind == crate::core::ErrorKind::Interrupted => {}
            Err(e) => {
                d.plan = None;
                self.mark_offline(d, e);
                // Tried again after the backoff (one period, doubling up to RETRY_MAX).
                wait = Some(d.backoff);
                d.backoff = (d.backoff * 2).min(RETRY_MAX.max(p.every));
            }
        }
        if p.count.is_some_and(|c| d.slot >= c) {
            return None;
        }
        // The next slot; slots already a whole period past are skipped (the next poll reads
        // the newest values) and counted. An offline device's next try is the first slot
        // after its backoff (those slots are not counted as skipped: nothing could be read).
        let every = p.every;
        let due = |slot: u64| self.start + d.phase + every.saturating_mul(slot.min(u32::MAX as u64) as u32);
        let now = Instant::now();
        let mut next = due(d.slot);
        let clamp = |behind: u64, slot: u64| p.count.map_or(behind, |c| behind.min(c.saturating_sub(slot + 1)));
        if let Some(wait) = wait {
            let at = now + wait;
            if next < at {
                let behind = clamp((at - next).as_nanos().div_ceil(every.as_nanos().max(1)) as u64, d.slot);
                d.slot += behind;
                next = due(d.slot);
            }
        } else if next + every <= now {
            let behind = ((now - next).as_nanos() / every.as_nanos().max(1)) as u64;
            // With --count the last slot is always polled (the run ends on a fresh reading).
            let behind = clamp(behind, d.slot);
            d.slot += behind;
            self.outbox.of(dev).skipped.fetch_add(behind, Ordering::Relaxed);
            next = due(d.slot);
        }
        Some(next)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn members(n: usize) -> Vec<Member> {
        (0..n)
            .map(|i| {
                let mut s = Session::new(crate::core::Clock::following());
                s.open(&format!("d{i}"), "sim:K205-16DT").unwrap();
                Member { name: format!("d{i}"), session: Ok(s), reopen: None }
            })
            .collect()
    }

    fn poll(every_ms: u64, count: u64) -> Poll {
        Poll {
            group: "g".into(),
            operands: vec!["VW0".into(), "VW2".into()],
            every: Duration::from_millis(every_ms),
            deadband: None,
            count: Some(count),
        }
    }

    fn seqs(outbox: &Outbox, device: &str) -> Vec<u64> {
        let mut all = Vec::new();
        outbox.take(usize::MAX, &mut all);
        all.iter()
            .filter(|m| m.topic == format!("plcsh/g/{device}/VW0"))
            .map(|m| serde_json::from_slice::<serde_json::Value>(&m.payload).unwrap()["seq"].as_u64().unwrap())
            .collect()
    }

    #[test]
    fn every_device_is_polled_on_its_slots_in_order_by_a_few_threads() {
        let outbox = Arc::new(Outbox::new(100_000, 40));
        let (tx, _rx) = std::sync::mpsc::channel();
        let started = Instant::now();
        let pool = Pool::start(members(40), poll(20, 5), outbox.clone(), tx).unwrap();
        pool.join();
        let took = started.elapsed();
        assert!(pool.finished());
        assert!(pool.workers() == 0, "the workers end when every device is done");
        // 5 slots 20 ms apart: 80 ms of schedule at least (less a worker's slack), and not
        // much more.
        assert!(
            took >= Duration::from_millis(80) - Duration::from_millis(20) / 100 && took < Duration::from_secs(5),
            "{took:?}"
        );
        assert_eq!(outbox.totals().0, 0, "nothing skipped");
        let mut all = Vec::new();
        outbox.take(usize::MAX, &mut all);
        for d in 0..40 {
            let topic = format!("plcsh/g/d{d}/VW0");
            let s: Vec<u64> = all
                .iter()
                .filter(|m| m.topic == topic)
                .map(|m| serde_json::from_slice::<serde_json::Value>(&m.payload).unwrap()["seq"].as_u64().unwrap())
                .collect();
            assert_eq!(s, [1, 2, 3, 4, 5], "d{d}");
            let status: Vec<&Msg> = all.iter().filter(|m| m.topic == format!("plcsh/g/d{d}/status")).collect();
            assert_eq!(status.len(), 1);
            assert_eq!(status[0].payload, br#"{"state":"online"}"#);
        }
        let first = all.iter().find(|m| m.topic == "plcsh/g/d3/VW2").unwrap();
        let j: serde_json::Value = serde_json::from_slice(&first.payload).unwrap();
        assert_eq!(j["device"], "d3");
        assert_eq!(j["operand"], "VW2");
        assert_eq!(j["type"], "WORD");
        assert_eq!(j["value"], 0);
    }

    /// A tag's name is the topic's last level on every poll (the first through the session's
    /// reader, the later ones through the resolved plan), and the payload carries `name` beside
    /// `operand` (docs/tags.md, "How names appear"); an operand without a tag keeps its topic.
    #[test]
    fn a_named_operand_is_published_under_its_name_with_name_and_operand_in_the_payload() {
        let mut s = Session::new(crate::core::Clock::following());
        s.open("press", "sim:K205-16DT").unwrap();
        let table = crate::tags::TagTable::parse_text(
            "name,address,type,comment\nTank2_Level,VD200,REAL,\nМотор_1_Пуск,M0.3,BOOL,\n",
            "t.csv",
            None,
        )
        .unwrap();
        s.attach_tags(0, table).unwrap();
        let outbox = Arc::new(Outbox::new(1000, 1));
        let (tx, _rx) = std::sync::mpsc::channel();
        let poll = Poll {
            group: "g".into(),
            operands: vec!["Tank2_Level".into(), "Мотор_1_Пуск".into(), "VW0".into()],
            every: Duration::from_millis(5),
            deadband: None,
            count: Some(3),
        };
        let pool =
            Pool::start(vec![Member { name: "press".into(), session: Ok(s), reopen: None }], poll, outbox.clone(), tx)
                .unwrap();
        pool.join();
        let mut all = Vec::new();
        outbox.take(usize::MAX, &mut all);
        for (topic, operand, name) in [
            ("plcsh/g/press/Tank2_Level", "VD200/REAL", Some("Tank2_Level")),
            ("plcsh/g/press/Мотор_1_Пуск", "M0.3", Some("Мотор_1_Пуск")),
            ("plcsh/g/press/VW0", "VW0", None),
        ] {
            let got: Vec<serde_json::Value> =
                all.iter().filter(|m| m.topic == topic).map(|m| serde_json::from_slice(&m.payload).unwrap()).collect();
            assert_eq!(got.len(), 3, "{topic}: every poll");
            for j in got {
                assert_eq!(j["operand"], operand, "{j}");
                assert_eq!(j["device"], "press", "{j}");
                assert_eq!(j.get("name").and_then(|n| n.as_str()), name, "{j}");
            }
        }
    }

    #[test]
    fn a_poll_that_overruns_its_slots_skips_them_and_counts_them() {
        // A device whose poll takes longer than the period: a write queued for it runs first
        // in a poll; instead, hold its lock from outside for a few periods.
        let outbox = Arc::new(Outbox::new(100_000, 1));
        let (tx, _rx) = std::sync::mpsc::channel();
        let pool = Pool::start(members(1), poll(10, 30), outbox.clone(), tx).unwrap();
        std::thread::sleep(Duration::from_millis(25));
        {
            let _held = pool.devs[0].lock().unwrap();
            std::thread::sleep(Duration::from_millis(100));
        }
        pool.join();
        let skipped = outbox.totals().0;
        let s = seqs(&outbox, "d0");
        assert!(skipped >= 5, "skipped {skipped}, seqs {s:?}");
        assert_eq!(s.len() as u64 + skipped, 30, "every slot is a poll or a skip: {s:?}");
        assert!(s.windows(2).all(|w| w[0] < w[1]), "in order: {s:?}");
        assert_eq!(*s.last().unwrap(), 30);
    }

    #[test]
    fn stop_ends_the_workers_at_once() {
        let outbox = Arc::new(Outbox::new(1000, 3));
        let (tx, _rx) = std::sync::mpsc::channel();
        let pool = Pool::start(members(3), poll(60_000, 1000), outbox, tx).unwrap();
        std::thread::sleep(Duration::from_millis(50));
        let t = Instant::now();
        pool.stop();
        pool.join();
        assert!(t.elapsed() < Duration::from_secs(2), "{:?}", t.elapsed());
        assert!(pool.finished());
    }
}
