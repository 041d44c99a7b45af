//! The simulator's interrupt event log: every event the simulated hardware raises (PTO
//! complete, CV = PV, external reset, E2PROM wear), with its virtual timestamp, in time
//! order. Bounded: it keeps the newest [`LOG_CAP`] events and counts the ones it dropped,
//! so a counter firing 200 000 times a second for an hour costs memory for 10 000 events.
//! Event numbers and names are defined in [`crate::k2::instr`].

use crate::k2::instr::{Event, EventKind, EventMatch};
use std::collections::VecDeque;
use std::time::Duration;

/// Events kept in the log.
pub const LOG_CAP: usize = 10_000;

#[derive(Clone, Debug, Default)]
pub struct EventLog {
    events: VecDeque<Event>,
    /// Sequence number of the next event.
    next_seq: u64,
    /// Events dropped because the log was full (or skipped in bulk by a counter).
    pub dropped: u64,
}

impl EventLog {
    /// Appends events raised during one advance; sorts them by time first (several
    /// channels may raise events in one step).
    pub fn extend(&mut self, mut raised: Vec<(Duration, EventKind)>) {
        raised.sort_by_key(|e| e.0);
        for (time, kind) in raised {
            self.push(time, kind);
        }
    }

    /// Appends the events raised during one advance, in the order [`Self::extend`] gives
    /// them (a stable sort by time), without sorting: `raised` is the concatenation of
    /// one run per channel, run `k` ending before `ends[k]`, each already in time order,
    /// so merging the runs is enough (a sort is the fallback if one is not). Events that
    /// would only be pushed out again by later ones in the same batch are counted as
    /// dropped without being stored.
    pub fn extend_runs(&mut self, raised: &[(Duration, EventKind)], ends: &[usize]) {
        const MAX_RUNS: usize = 16;
        let mut head = [0usize; MAX_RUNS];
        let mut end = [0usize; MAX_RUNS];
        let (mut k, mut start, mut ordered) = (0, 0, ends.len() <= MAX_RUNS);
        for &e in ends.iter().take(MAX_RUNS) {
            if e > start {
                ordered &= raised[start..e].windows(2).all(|w| w[0].0 <= w[1].0);
                (head[k], end[k]) = (start, e);
                k += 1;
            }
            start = e;
        }
        if !ordered || start != raised.len() {
            return self.extend(raised.to_vec());
        }
        let skip = raised.len().saturating_sub(LOG_CAP);
        for i in 0..raised.len() {
            // The run whose next event is earliest; the first such run on a tie (stable).
            let mut best = usize::MAX;
            for r in 0..k {
                if head[r] < end[r] && (best == usize::MAX || raised[head[r]].0 < raised[head[best]].0) {
                    best = r;
                }
            }
            let (time, kind) = raised[head[best]];
            head[best] += 1;
            if i < skip {
                self.next_seq += 1;
                self.dropped += 1;
            } else {
                self.push(time, kind);
            }
        }
    }

    pub fn push(&mut self, time: Duration, kind: EventKind) {
        if self.events.len() == LOG_CAP {
            self.events.pop_front();
            self.dropped += 1;
        }
        self.events.push_back(Event { seq: self.next_seq, time, kind });
        self.next_seq += 1;
    }

    /// Counts `n` events that happened but were not materialised (bulk skipping).
    pub fn skip(&mut self, n: u64) {
        self.next_seq += n;
        self.dropped += n;
    }

    /// Every event raised since power-up (including dropped ones).
    pub fn total(&self) -> u64 {
        self.next_seq
    }

    pub fn list(&self) -> Vec<Event> {
        self.events.iter().copied().collect()
    }

    pub fn clear(&mut self) {
        self.events.clear();
        self.dropped = 0;
    }

    pub fn len(&self) -> usize {
        self.events.len()
    }

    pub fn is_empty(&self) -> bool {
        self.events.is_empty()
    }

    /// Removes and returns the oldest matching event.
    pub fn take(&mut self, m: &EventMatch) -> Option<Event> {
        let i = self.events.iter().position(|e| m.matches(&e.kind))?;
        self.events.remove(i)
    }
}

/// The log's state for snapshots (`crate::snapshot`).
#[derive(Clone, Debug, serde::Serialize, serde::Deserialize)]
pub struct EventLogState {
    /// `(sequence number, virtual time in ns, what)`, oldest first.
    events: Vec<(u64, u64, EventKind)>,
    next_seq: u64,
    dropped: u64,
}

impl EventLog {
    /// Every field is named (no `..`): a field added to the log does not compile until it is
    /// saved here.
    pub fn save(&self) -> EventLogState {
        let EventLog { events, next_seq, dropped } = self;
        EventLogState {
            events: events.iter().map(|e| (e.seq, e.time.as_nanos() as u64, e.kind)).collect(),
            next_seq: *next_seq,
            dropped: *dropped,
        }
    }

    pub fn load(&mut self, s: EventLogState) {
        self.events =
            s.events.into_iter().map(|(seq, ns, kind)| Event { seq, time: Duration::from_nanos(ns), kind }).collect();
        self.next_seq = s.next_seq;
        self.dropped = s.dropped;
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn events_are_sorted_capped_and_taken() {
        let mut log = EventLog::default();
        log.extend(vec![
            (Duration::from_millis(5), EventKind::PtoComplete { channel: 1 }),
            (Duration::from_millis(2), EventKind::PtoComplete { channel: 0 }),
        ]);
        let l = log.list();
        assert_eq!(l[0].kind, EventKind::PtoComplete { channel: 0 });
        assert_eq!(l[0].seq, 0);
        assert_eq!(log.take(&EventMatch::Number(28)).unwrap().time, Duration::from_millis(2));
        assert!(log.take(&EventMatch::Number(28)).is_none(), "taken once");
        for i in 0..LOG_CAP as u64 + 5 {
            log.push(Duration::from_micros(i), EventKind::HscReset { channel: 0 });
        }
        assert_eq!(log.len(), LOG_CAP);
        assert_eq!(log.dropped, 6);
        assert_eq!(log.total(), 2 + LOG_CAP as u64 + 5);
    }

    /// `extend_runs` leaves the log exactly as `extend` (stable sort, then push) does.
    #[test]
    fn merging_runs_is_sorting() {
        let ev = |us: u64, channel: u8| (Duration::from_micros(us), EventKind::HscReset { channel });
        type Batch = Vec<(Duration, EventKind)>;
        let cases: Vec<(Batch, Vec<usize>)> = vec![
            (vec![], vec![0, 0]),
            (vec![ev(5, 0), ev(2, 1), ev(2, 2), ev(9, 2)], vec![1, 1, 4]),
            (vec![ev(3, 0), ev(3, 0), ev(1, 1), ev(3, 1), ev(0, 2)], vec![2, 4, 5]),
            (vec![ev(4, 0), ev(1, 0), ev(2, 1)], vec![2, 3]), // a run out of order: the fallback
            (
                (0..2 * LOG_CAP as u64 + 3).map(|i| ev(i / 2, (i % 2) as u8)).collect(),
                vec![LOG_CAP + 1, 2 * LOG_CAP + 3],
            ),
        ];
        for (raised, ends) in cases {
            let mut a = EventLog::default();
            let mut b = EventLog::default();
            for i in 0..7 {
                a.push(Duration::ZERO, EventKind::PtoComplete { channel: i });
                b.push(Duration::ZERO, EventKind::PtoComplete { channel: i });
            }
            a.extend(raised.clone());
            b.extend_runs(&raised, &ends);
            assert_eq!(a.list(), b.list());
            assert_eq!((a.total(), a.dropped), (b.total(), b.dropped));
        }
    }
}
