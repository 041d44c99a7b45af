//! The one bounded queue between the pollers and the broker connection ([`super::broker`]),
//! and the counters that say why a reading did not reach the broker.
//!
//! Readings wait here, oldest first, until the broker thread hands them to the MQTT client.
//! The queue never holds more than its bound (`--buffer`). When it is full, what gives way
//! depends on why it is full:
//!
//! - **The broker is away** (not connected): the oldest reading is dropped and counted as
//!   `broker_away` for its device. What is kept is the newest `--buffer` readings, in order,
//!   delivered when the broker returns — the count is exact.
//! - **The broker is connected** and plcsh cannot hand readings over as fast as the pollers
//!   take them: a new reading replaces the queued one of the same topic (newest value wins,
//!   the older one is counted as `behind` for its device); a reading with no queued twin
//!   pushes out the oldest, counted `behind` too. Memory stays bounded and the counters name
//!   the real cause.
//!
//! The publisher's stats message has a slot of its own beside the queue (the newest wins).
//!
//! A message's `key` names its topic for merging (one per device and operand, and per
//! status topic); replies to writes have none and are never merged.

use std::collections::{HashMap, VecDeque};
use std::sync::atomic::{AtomicU64, Ordering};
use std::sync::Mutex;

/// A message's identity: its device's index and the topic's index among that device's.
pub type Key = (u32, u32);

/// One message for the broker.
#[derive(Clone, Debug)]
pub struct Msg {
    pub topic: String,
    pub payload: Vec<u8>,
    pub retain: bool,
    /// The message's identity for merging: (device, topic of that device), carried with the
    /// value from the poll that read it (`None`: never merged).
    pub key: Option<Key>,
    /// The device it is about ([`Outbox::PUBLISHER`] for the publisher's own).
    pub dev: u32,
}

/// Why readings of one device did not reach the broker, and polls it missed.
#[derive(Debug, Default)]
pub struct Counters {
    /// Schedule slots skipped because the previous poll ran past them (the device or plcsh
    /// could not keep up); the next poll gives the newest value.
    pub skipped: AtomicU64,
    /// Readings replaced by a newer one of the same topic, or pushed out, while the broker was
    /// connected (plcsh could not hand them over fast enough).
    pub behind: AtomicU64,
    /// Readings dropped from a full queue while the broker was away.
    pub broker_away: AtomicU64,
}

struct Inner {
    items: VecDeque<Msg>,
    /// The position of `items[0]` in the sequence of every message ever queued.
    base: u64,
    /// Each key's newest queued message, by position.
    latest: HashMap<Key, u64>,
    connected: bool,
    closed: bool,
    /// The publisher's latest stats message: one slot, newest wins, outside the bound.
    stats: Option<Msg>,
}

/// The queue, its bound, and the per-device counters (one more slot for the publisher).
pub struct Outbox {
    inner: Mutex<Inner>,
    bound: usize,
    pub counters: Vec<Counters>,
    /// Messages ever queued (put back ones aside): each is delivered, or counted in one of
    /// the counters, or still queued.
    pub accepted: AtomicU64,
    /// Wakes the broker thread when the queue stops being empty or is closed.
    pub wake: tokio::sync::Notify,
}

impl Outbox {
    /// The `dev` of the publisher's own messages (status, stats, replies to unknown devices).
    pub const PUBLISHER: u32 = u32::MAX;

    pub fn new(bound: usize, devices: usize) -> Outbox {
        Outbox {
            // Positions start high so that messages put back at the front never go below 0.
            inner: Mutex::new(Inner {
                items: VecDeque::new(),
                base: 1 << 40,
                latest: HashMap::new(),
                connected: false,
                closed: false,
                stats: None,
            }),
            bound: bound.max(1),
            counters: (0..=devices).map(|_| Counters::default()).collect(),
            accepted: AtomicU64::new(0),
            wake: tokio::sync::Notify::new(),
        }
    }

    fn lock(&self) -> std::sync::MutexGuard<'_, Inner> {
        self.inner.lock().unwrap_or_else(|p| p.into_inner())
    }

    /// The counters of device `dev` (the last slot for the publisher).
    pub fn of(&self, dev: u32) -> &Counters {
        let last = self.counters.len() - 1;
        &self.counters[(dev as usize).min(last)]
    }

    /// Queues a message (see the module's rules for a full queue).
    pub fn push(&self, m: Msg) {
        self.push_all(std::iter::once(m));
    }

    /// Queues a poll's messages, in order, under one lock and with at most one wake-up.
    pub fn push_all(&self, msgs: impl IntoIterator<Item = Msg>) {
        let mut g = self.lock();
        let was_empty = g.items.is_empty();
        for m in msgs {
            self.push_locked(&mut g, m);
        }
        drop(g);
        if was_empty {
            self.wake.notify_one();
        }
    }

    fn push_locked(&self, g: &mut Inner, m: Msg) {
        self.accepted.fetch_add(1, Ordering::Relaxed);
        if g.items.len() >= self.bound {
            if g.connected {
                if let Some(&pos) = m.key.and_then(|k| g.latest.get(&k)) {
                    let i = pos.wrapping_sub(g.base) as usize;
                    // Only into a queued message of the same identity (a position may have
                    // been taken and another message put back there since).
                    if pos >= g.base && g.items.get(i).is_some_and(|old| old.key == m.key) {
                        let old = &mut g.items[i];
                        self.of(old.dev).behind.fetch_add(1, Ordering::Relaxed);
                        old.payload = m.payload;
                        return;
                    }
                }
            }
            if let Some(old) = g.items.pop_front() {
                g.base += 1;
                let c = self.of(old.dev);
                if g.connected { &c.behind } else { &c.broker_away }.fetch_add(1, Ordering::Relaxed);
            }
        }
        let pos = g.base + g.items.len() as u64;
        if let Some(k) = m.key {
            g.latest.insert(k, pos);
        }
        g.items.push_back(m);
    }

    /// Takes up to `max` messages from the front.
    pub fn take(&self, max: usize, into: &mut Vec<Msg>) {
        let mut g = self.lock();
        let n = max.min(g.items.len());
        into.extend(g.items.drain(..n));
        g.base += n as u64;
    }

    /// Puts messages back at the front, in their order (not sent after all, or to be sent again).
    pub fn put_back(&self, msgs: impl DoubleEndedIterator<Item = Msg>) {
        let mut g = self.lock();
        for m in msgs.rev() {
            g.base -= 1;
            g.items.push_front(m);
        }
    }

    /// Puts a message first in the queue (the publisher's `online`, beyond the bound).
    pub fn push_front(&self, m: Msg) {
        self.put_back(std::iter::once(m));
        self.wake.notify_one();
    }

    /// Replaces the publisher's stats message waiting to be sent (it takes no place in the
    /// queue, so it never pushes a reading out).
    pub fn set_stats(&self, m: Msg) {
        self.lock().stats = Some(m);
        self.wake.notify_one();
    }

    /// Puts a stats message that could not be sent back (unless a newer one came), without
    /// waking the broker thread.
    pub fn restore_stats(&self, m: Msg) {
        self.lock().stats.get_or_insert(m);
    }

    pub fn take_stats(&self) -> Option<Msg> {
        self.lock().stats.take()
    }

    pub fn has_stats(&self) -> bool {
        self.lock().stats.is_some()
    }

    pub fn len(&self) -> usize {
        self.lock().items.len()
    }

    pub fn is_empty(&self) -> bool {
        self.len() == 0
    }

    /// Whether the broker is connected (decides what a full queue drops).
    pub fn set_connected(&self, connected: bool) {
        self.lock().connected = connected;
    }

    /// No more messages will come: the broker thread delivers what is queued and stops.
    pub fn close(&self) {
        self.lock().closed = true;
        self.wake.notify_one();
    }

    pub fn is_closed(&self) -> bool {
        self.lock().closed
    }

    /// Sums of the counters over every device: (skipped, behind, broker_away).
    pub fn totals(&self) -> (u64, u64, u64) {
        self.counters.iter().fold((0, 0, 0), |(s, b, a), c| {
            (
                s + c.skipped.load(Ordering::Relaxed),
                b + c.behind.load(Ordering::Relaxed),
                a + c.broker_away.load(Ordering::Relaxed),
            )
        })
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn msg(topic: &str, key: u32, dev: u32, payload: &str) -> Msg {
        Msg { topic: topic.into(), payload: payload.into(), retain: true, key: Some((dev, key)), dev }
    }

    fn topics(o: &Outbox) -> Vec<(String, String)> {
        let mut v = Vec::new();
        o.take(usize::MAX, &mut v);
        v.into_iter().map(|m| (m.topic, String::from_utf8(m.payload).unwrap())).collect()
    }

    #[test]
    fn with_the_broker_away_the_oldest_are_dropped_and_counted_exactly() {
        let o = Outbox::new(3, 1);
        for i in 0..5 {
            o.push(msg(&format!("t{i}"), i, 0, "x"));
        }
        assert_eq!(o.of(0).broker_away.load(Ordering::Relaxed), 2);
        assert_eq!(o.of(0).behind.load(Ordering::Relaxed), 0);
        let kept: Vec<String> = topics(&o).into_iter().map(|(t, _)| t).collect();
        assert_eq!(kept, ["t2", "t3", "t4"]);
    }

    #[test]
    fn with_the_broker_connected_the_newest_value_of_a_topic_wins_and_counts_as_behind() {
        let o = Outbox::new(2, 2);
        o.set_connected(true);
        o.push(msg("a", 1, 0, "1"));
        o.push(msg("b", 2, 1, "1"));
        o.push(msg("a", 1, 0, "2"));
        o.push(msg("a", 1, 0, "3"));
        assert_eq!(o.len(), 2, "bounded");
        assert_eq!(o.of(0).behind.load(Ordering::Relaxed), 2);
        assert_eq!(o.of(1).behind.load(Ordering::Relaxed), 0);
        // A topic with nothing queued pushes out the oldest, counted for that one's device.
        o.push(msg("c", 3, 1, "1"));
        assert_eq!(o.of(0).behind.load(Ordering::Relaxed), 3);
        assert_eq!(topics(&o), [("b".to_string(), "1".to_string()), ("c".to_string(), "1".to_string())]);
        assert_eq!(o.totals(), (0, 3, 0));
    }

    #[test]
    fn a_poll_queued_at_once_keeps_its_order_and_the_bound() {
        let o = Outbox::new(3, 2);
        o.set_connected(true);
        o.push_all((0..3).map(|i| msg(&format!("t{i}"), i, 0, "1")));
        o.push_all((0..3).map(|i| msg(&format!("t{i}"), i, 0, "2")));
        assert_eq!(o.len(), 3, "bounded");
        assert_eq!(o.of(0).behind.load(Ordering::Relaxed), 3, "each newer value took its topic's place");
        // A topic with nothing queued pushes out the oldest.
        o.push_all([msg("u", 9, 1, "1")]);
        assert_eq!(o.of(0).behind.load(Ordering::Relaxed), 4);
        let want = [("t1", "2"), ("t2", "2"), ("u", "1")];
        assert_eq!(topics(&o), want.map(|(t, p)| (t.to_string(), p.to_string())));
    }

    #[test]
    fn messages_put_back_come_first_in_their_order_and_a_stale_key_is_not_merged_into() {
        let o = Outbox::new(3, 1);
        o.set_connected(true);
        for (i, t) in ["a", "b", "c"].iter().enumerate() {
            o.push(msg(t, i as u32, 0, "old"));
        }
        let mut sent = Vec::new();
        o.take(2, &mut sent);
        o.push(msg("a", 0, 0, "new"));
        o.put_back(sent.into_iter());
        let got: Vec<(String, String)> = topics(&o);
        let want = [("a", "old"), ("b", "old"), ("c", "old"), ("a", "new")];
        assert_eq!(got, want.map(|(t, p)| (t.to_string(), p.to_string())));
    }
}
