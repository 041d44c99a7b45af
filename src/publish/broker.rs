//! The MQTT side of `plcsh publish`: one thread with a small tokio runtime that owns the
//! broker connection (rumqttc; MQTT 3.1.1 or 5). Readings wait in the one bounded queue
//! ([`super::outbox`]) and leave it, oldest first, only while the broker is connected, so
//! readings taken while it is away are delivered in order when it returns; what a full queue
//! drops is counted by cause there. The connection is retried with backoff (0.1 s doubling
//! to 5 s); the publisher's own last will marks it offline.
//!
//! Failures that no retry mends end the run instead of being retried for ever: the broker
//! refusing the credentials (CONNACK "not authorized" or "bad user name or password"), a TLS
//! certificate it presents that does not verify, and a broker never reached at all within
//! [`FIRST_CONTACT`] of the start ([`Fatal`]; exit statuses in docs/fleets.md). A broker that
//! answered once and then went away is an outage: readings are kept and it is retried.
//!
//! rumqttc's event loop runs in a task of its own and reports to the queue's owner over a
//! channel, so nothing waits on an event loop that is not being polled (its `poll` is not
//! cancelled by a `select!`). A message handed to rumqttc stays in our `unconfirmed` list
//! until it is written (QoS 0) or acknowledged (QoS 1), in order; when the broker comes back
//! without the old session, rumqttc forgets what it held, and those messages go back to the
//! front of the queue — so nothing taken while the broker was away is lost to a reconnect
//! (at QoS 1 a message may then arrive twice, as MQTT's "at least once" allows). At QoS 0 a
//! message written on a connection that is then lost before a proof that the broker read it
//! ([`Proofs`]) is counted as dropped with the broker away, for its device ([`Written`]):
//! `published` counts only what is known to have reached the broker.

use super::outbox::{Msg, Outbox};
use std::collections::VecDeque;
use std::sync::Arc;
use std::time::Duration;
use tokio::sync::mpsc::unbounded_channel;

/// What the broker side tells the front end.
#[derive(Clone, Debug, PartialEq)]
pub enum Note {
    Connected,
    /// The broker went away (why); readings are kept.
    Away(String),
    /// A message on a command topic (`--accept-writes`): topic and payload.
    Command(String, Vec<u8>),
    /// A failure no retry mends: the run ends with its status.
    Fatal(Fatal),
}

/// Why the broker connection cannot be used at all.
#[derive(Clone, Debug, PartialEq)]
pub enum Fatal {
    /// The broker refused the credentials (or their absence).
    Auth(String),
    /// The broker's TLS certificate did not verify (or TLS could not start).
    Tls(String),
    /// No broker answered within [`FIRST_CONTACT`] of the start.
    NeverReached(String),
}

/// How long a broker may take to answer the first time before the run gives up on it.
pub const FIRST_CONTACT: Duration = Duration::from_secs(10);

/// How to reach the broker.
#[derive(Clone, Debug)]
pub struct Config {
    pub host: String,
    pub port: u16,
    pub tls: bool,
    /// A CA certificate file (PEM) for TLS; the system's roots otherwise.
    pub ca: Option<Vec<u8>>,
    pub credentials: Option<(String, String)>,
    pub client_id: String,
    pub v5: bool,
    pub qos1: bool,
    /// The publisher's own status topic (its last will says `offline`).
    pub will_topic: String,
    /// The command topic filter subscribed to (`--accept-writes`), if any.
    pub commands: Option<String>,
}

/// What happened, for the summary.
#[derive(Clone, Debug, Default)]
pub struct Stats {
    pub published: u64,
    pub reconnects: u64,
    /// Not known to have reached the broker at the end (still queued, not acknowledged, or at
    /// QoS 0 written without a proof of arrival): dropped at the stop.
    pub undelivered: u64,
    /// Set when the run ended on a failure no retry mends.
    pub fatal: Option<Fatal>,
}

enum Loop {
    /// Connected; whether the broker kept the last session (rumqttc then resends what it holds).
    ConnAck(bool),
    /// Messages left for good: written (QoS 0) or acknowledged (QoS 1); their number is in
    /// [`Confirmations`] (one wake-up for however many came meanwhile).
    Confirmed,
    /// plcsh's DISCONNECT was written; the connection closes next.
    Disconnected,
    /// The broker closed the connection after the DISCONNECT.
    Closed,
    Error(String),
    Command(String, Vec<u8>),
}

/// Messages confirmed by the event loop and not yet taken off the `unconfirmed` list. The
/// event loop counts each one here and sends [`Loop::Confirmed`] only when the last one sent
/// was taken, so a burst of confirmations costs the queue's owner one turn, not one per message.
#[derive(Default)]
struct Confirmations {
    count: std::sync::atomic::AtomicU64,
    signalled: std::sync::atomic::AtomicBool,
}

impl Confirmations {
    /// One more (event loop side); whether the owner must be told.
    fn add(&self) -> bool {
        use std::sync::atomic::Ordering::SeqCst;
        self.count.fetch_add(1, SeqCst);
        !self.signalled.swap(true, SeqCst)
    }

    /// All counted so far (owner side).
    fn take(&self) -> u64 {
        use std::sync::atomic::Ordering::SeqCst;
        self.signalled.store(false, SeqCst);
        self.count.swap(0, SeqCst)
    }
}

/// At QoS 0 a message "written" is in the kernel's send buffer, not yet known to be at the
/// broker. A PUBACK of a later QoS 1 message (the publisher's own status and stats are sent at
/// QoS 1) proves that the broker read everything before it, in order: `written` counts the
/// messages handed to the socket, `proven` how many of them are known to have arrived.
#[derive(Default)]
struct Proofs {
    written: std::sync::atomic::AtomicU64,
    proven: std::sync::atomic::AtomicU64,
}

impl Proofs {
    fn unproven(&self) -> u64 {
        use std::sync::atomic::Ordering::SeqCst;
        self.written.load(SeqCst).saturating_sub(self.proven.load(SeqCst))
    }
}

/// At QoS 0, the devices of the messages written and not yet proven to have arrived
/// ([`Proofs`]), oldest first: when the connection is lost they are counted as dropped with the
/// broker away (for their devices), never as published.
#[derive(Default)]
struct Written {
    devs: VecDeque<u32>,
    /// Messages written before `devs[0]` (proven, or lost and counted; set again after a loss).
    before: u64,
}

impl Written {
    /// Forgets the proven ones: the first `proven` messages ever written.
    fn trim(&mut self, proven: u64) {
        while self.before < proven && self.devs.pop_front().is_some() {
            self.before += 1;
        }
    }

    /// Counts every unproven message as dropped with the broker away; returns how many.
    fn lose(&mut self, outbox: &Outbox) -> u64 {
        let n = self.devs.len() as u64;
        for dev in self.devs.drain(..) {
            outbox.of(dev).broker_away.fetch_add(1, std::sync::atomic::Ordering::Relaxed);
        }
        n
    }
}

/// How long a stop may take to hand what is queued to the broker and close the connection;
/// what is not delivered by then is counted as dropped at the stop.
pub const STOP_GRACE: Duration = Duration::from_secs(5);
/// How long the broker has to close the connection after plcsh's DISCONNECT.
const CLOSE_GRACE: Duration = Duration::from_secs(1);

const BACKOFF_MIN: Duration = Duration::from_millis(100);
const BACKOFF_MAX: Duration = Duration::from_secs(5);
/// How long the broker thread lets readings gather after it handed some to the client. A
/// poller that queues a reading while the thread is awake (or lingering) does not wake it, so
/// at 1 000 devices at 10 Hz the thread wakes a few hundred times a second instead of once per
/// poll; a reading waits at most this much longer.
const LINGER: Duration = Duration::from_millis(2);
/// Messages taken from the queue at once (one lock for many).
const BATCH: usize = 256;

/// Starts the broker thread, which takes its messages from `outbox` until it is closed and
/// empty; returns the thread (its stats).
pub fn spawn(
    cfg: Config,
    outbox: Arc<Outbox>,
    notes: std::sync::mpsc::Sender<Note>,
) -> std::io::Result<std::thread::JoinHandle<Stats>> {
    std::thread::Builder::new().name("mqtt".into()).spawn(move || {
        let rt = match tokio::runtime::Builder::new_current_thread().enable_all().build() {
            Ok(rt) => rt,
            Err(e) => {
                let _ = notes.send(Note::Away(crate::msg!("publish-no-runtime", error = e.to_string()).text));
                return Stats::default();
            }
        };
        if cfg.v5 {
            rt.block_on(v5::run(cfg, outbox, notes))
        } else {
            rt.block_on(v4::run(cfg, outbox, notes))
        }
    })
}

fn transport(cfg: &Config) -> rumqttc::Transport {
    match (&cfg.ca, cfg.tls) {
        (Some(ca), _) => rumqttc::Transport::tls(ca.clone(), None, None),
        (None, true) => rumqttc::Transport::tls_with_default_config(),
        (None, false) => rumqttc::Transport::Tcp,
    }
}

/// A connection error that no retry mends, by rumqttc's words for it (the same for MQTT
/// 3.1.1 and 5): a refused CONNACK for the credentials, or a TLS failure.
pub fn classify(error: &str) -> Option<Fatal> {
    if error.contains("NotAuthorized") || error.contains("BadUserNamePassword") {
        return Some(Fatal::Auth(error.to_string()));
    }
    let e = error.to_ascii_lowercase();
    if e.starts_with("tls") || e.contains("certificate") || e.contains("handshake") {
        return Some(Fatal::Tls(error.to_string()));
    }
    None
}

/// The same loop for MQTT 3.1.1 and 5: the two client APIs differ only in their types.
macro_rules! broker_loop {
    ($m:ident, $client:path, $opts:path, $event:path, $packet:path, $qos:path, $will:expr) => {
        pub(super) mod $m {
            use super::*;
            use $event as Event;
            use $packet as Packet;
            use $qos as QoS;

            pub async fn run(cfg: Config, outbox: Arc<Outbox>, notes: std::sync::mpsc::Sender<Note>) -> Stats {
                let mut opts = <$opts>::new(cfg.client_id.clone(), cfg.host.clone(), cfg.port);
                opts.set_keep_alive(Duration::from_secs(5));
                opts.set_transport(transport(&cfg));
                if let Some((u, p)) = &cfg.credentials {
                    opts.set_credentials(u.clone(), p.clone());
                }
                opts.set_last_will($will(cfg.will_topic.clone(), b"offline".to_vec(), QoS::AtLeastOnce, true));
                let (client, mut eventloop) = <$client>::new(opts, 1000);
                let (etx, mut erx) = unbounded_channel::<Loop>();
                // The owner's word that it took an error in: it hands nothing more to the
                // client until the next CONNACK (see the event loop's error arm).
                let (atx, mut arx) = unbounded_channel::<()>();
                let qos1 = cfg.qos1;
                let confirmations = Arc::new(Confirmations::default());
                let counted = confirmations.clone();
                let proofs = Arc::new(Proofs::default());
                let proved = proofs.clone();
                let confirmed = move |etx: &tokio::sync::mpsc::UnboundedSender<Loop>| {
                    if counted.add() {
                        etx.send(Loop::Confirmed).map_err(|_| ())
                    } else {
                        Ok(())
                    }
                };
                tokio::spawn(async move {
                    use std::sync::atomic::Ordering::SeqCst;
                    let mut backoff = BACKOFF_MIN;
                    // QoS 0: each QoS 1 message written, and how many were written up to it.
                    let mut proof_points: VecDeque<(u16, u64)> = VecDeque::new();
                    let mut closing = false;
                    loop {
                        let sent = match eventloop.poll().await {
                            Ok(Event::Incoming(Packet::ConnAck(c))) => {
                                backoff = BACKOFF_MIN;
                                etx.send(Loop::ConnAck(c.session_present)).map_err(|_| ())
                            }
                            Ok(Event::Incoming(Packet::PubAck(_))) if qos1 => confirmed(&etx),
                            Ok(Event::Incoming(Packet::PubAck(a))) => {
                                while let Some((pkid, upto)) = proof_points.pop_front() {
                                    if pkid == a.pkid {
                                        proved.proven.fetch_max(upto, SeqCst);
                                        break;
                                    }
                                }
                                etx.send(Loop::Confirmed).map_err(|_| ())
                            }
                            Ok(Event::Incoming(Packet::Publish(p))) => {
                                let topic = String::from_utf8_lossy(AsRef::<[u8]>::as_ref(&p.topic)).into_owned();
                                etx.send(Loop::Command(topic, p.payload.to_vec())).map_err(|_| ())
                            }
                            Ok(Event::Outgoing(rumqttc::Outgoing::Publish(pkid))) if !qos1 => {
                                let upto = proved.written.fetch_add(1, SeqCst) + 1;
                                if pkid != 0 {
                                    proof_points.push_back((pkid, upto));
                                }
                                confirmed(&etx)
                            }
                            Ok(Event::Outgoing(rumqttc::Outgoing::Disconnect)) => {
                                // Then read until the broker closes: dropping a socket with
                                // unread bytes resets it, and a reset discards what the
                                // kernel has not sent yet.
                                closing = true;
                                etx.send(Loop::Disconnected).map_err(|_| ())
                            }
                            Ok(_) => Ok(()),
                            Err(_) if closing => {
                                let _ = etx.send(Loop::Closed);
                                break;
                            }
                            Err(e) => {
                                // What was written on the lost connection without a proof is
                                // not known to have arrived: the owner counts it as dropped
                                // ([`Written`]); the proofs of the old connection are void.
                                proof_points.clear();
                                let r = etx.send(Loop::Error(e.to_string())).map_err(|_| ());
                                // rumqttc moved what it held (in flight, and what waited in the
                                // client's channel) to its `pending` when the connection broke,
                                // and drops that on a CONNACK without the old session; the owner
                                // then puts all of it back at the front of the queue. But the
                                // owner may have handed more to the client between the break
                                // and taking the error in: those would wait in the channel and
                                // go out first after the reconnect, ahead of the older readings
                                // put back — out of order. So the reconnect waits until the
                                // owner has taken the error in (from then on it hands nothing
                                // over until the CONNACK), and what reached the channel
                                // meanwhile joins `pending` behind the rest, in order.
                                let (acked, _) = tokio::join!(arx.recv(), tokio::time::sleep(backoff));
                                eventloop.clean();
                                backoff = (backoff * 2).min(BACKOFF_MAX);
                                r.and(acked.ok_or(()))
                            }
                        };
                        if sent.is_err() {
                            break;
                        }
                    }
                });
                let qos = if cfg.qos1 { QoS::AtLeastOnce } else { QoS::AtMostOnce };
                let mut unconfirmed: VecDeque<Msg> = VecDeque::new();
                let status = |text: &[u8]| Msg {
                    topic: cfg.will_topic.clone(),
                    payload: text.to_vec(),
                    retain: true,
                    key: None,
                    dev: Outbox::PUBLISHER,
                };
                let mut stats = Stats::default();
                let (mut connected, mut was_connected, mut said_offline) = (false, false, false);
                let mut away_told = false;
                // The stop: by when it must be done, and by when the broker must have closed.
                let (mut stop_by, mut close_by) = (None, None);
                let mut disconnecting = false;
                // The publisher's own messages go at QoS 1: their PUBACK proves that the broker
                // read everything before them, at QoS 0 too ([`Proofs`]).
                let qos_of = |m: &Msg| {
                    if m.dev == Outbox::PUBLISHER && m.retain {
                        QoS::AtLeastOnce
                    } else {
                        qos
                    }
                };
                let first_contact = tokio::time::Instant::now() + FIRST_CONTACT;
                let mut last_error = String::from("no answer");
                let mut batch = Vec::with_capacity(BATCH);
                let mut pending: VecDeque<Msg> = VecDeque::with_capacity(BATCH);
                let mut handed = false;
                let mut written = Written::default();
                loop {
                    if std::mem::take(&mut handed) && !outbox.is_closed() {
                        // Readings keep coming: let them gather for a moment, so the pollers'
                        // pushes meanwhile cost no wake-up of this thread (see [`LINGER`]).
                        tokio::time::sleep(LINGER).await;
                    }
                    let stopping = outbox.is_closed();
                    if stopping && stop_by.is_none() {
                        stop_by = Some(tokio::time::Instant::now() + STOP_GRACE);
                    }
                    // Nothing is handed to the client while the event loop has news waiting: after
                    // a connection loss rumqttc has already emptied its channel, and a message
                    // handed now would go out after the reconnect ahead of the older ones put
                    // back at ConnAck (out of order). The event loop runs only while this task
                    // waits, so the check holds until the handing is done.
                    if connected && !disconnecting && erx.is_empty() {
                        // The stats first: they say how the readings fare, and must not wait
                        // behind them when plcsh falls behind (a full client channel keeps them
                        // in their slot, first for the next room).
                        if let Some(m) = outbox.take_stats() {
                            match client.try_publish(m.topic.clone(), qos_of(&m), m.retain, m.payload.clone()) {
                                Ok(()) => unconfirmed.push_back(m),
                                // Back in its slot without a wake-up: the client's room comes with
                                // its next event (a wake-up here would spin and starve the client).
                                Err(_) => outbox.restore_stats(m),
                            }
                        }
                        // Oldest first; a full client channel leaves the rest queued for the next turn.
                        // Taken in batches (one lock for many) into `pending`, which the
                        // client's channel empties as it has room: a full channel leaves them
                        // there for the next turn instead of going back into the queue.
                        loop {
                            if pending.is_empty() {
                                outbox.take(BATCH, &mut batch);
                                pending.extend(batch.drain(..));
                                if pending.is_empty() {
                                    break;
                                }
                            }
                            let Some(m) = pending.pop_front() else { break };
                            if client.try_publish(m.topic.clone(), qos_of(&m), m.retain, m.payload.clone()).is_err() {
                                pending.push_front(m);
                                break;
                            }
                            unconfirmed.push_back(m);
                            handed = true;
                        }
                        if stopping && pending.is_empty() && outbox.is_empty() && !outbox.has_stats() {
                            if !said_offline {
                                said_offline = true;
                                outbox.push_front(status(b"offline"));
                                continue;
                            }
                            // Everything acknowledged (QoS 1) or proven to have arrived (QoS 0):
                            // DISCONNECT, then the broker closes the connection.
                            if unconfirmed.is_empty() && (qos1 || proofs.unproven() == 0) {
                                let _ = client.try_disconnect();
                                disconnecting = true;
                                close_by = Some(tokio::time::Instant::now() + CLOSE_GRACE);
                            }
                        }
                    }
                    let never = !was_connected && stats.fatal.is_none();
                    let deadline = match (stop_by, close_by) {
                        (Some(a), Some(b)) => Some(a.min(b)),
                        (a, b) => a.or(b),
                    };
                    let until = match deadline {
                        Some(d) if never => d.min(first_contact),
                        Some(d) => d,
                        None if never => first_contact,
                        None => tokio::time::Instant::now() + Duration::from_secs(3600),
                    };
                    let e = tokio::select! {
                        e = erx.recv() => e,
                        _ = outbox.wake.notified() => continue,
                        _ = tokio::time::sleep_until(until) => {
                            if !was_connected {
                                let f = Fatal::NeverReached(last_error.clone());
                                let _ = notes.send(Note::Fatal(f.clone()));
                                stats.fatal = Some(f);
                            }
                            if stats.fatal.is_some() {
                                break;
                            }
                            let now = tokio::time::Instant::now();
                            if close_by.is_some_and(|c| now >= c) {
                                break;
                            }
                            if stop_by.is_some_and(|c| now >= c) {
                                if !connected || disconnecting {
                                    break;
                                }
                                // Out of time: what is not delivered now is dropped at the
                                // stop; the connection is still closed cleanly.
                                let _ = client.try_disconnect();
                                disconnecting = true;
                                close_by = Some(now + CLOSE_GRACE);
                            }
                            continue;
                        }
                    };
                    // Confirmations first: the event loop counted them before it sent `e`
                    // (an error puts back only what was not confirmed).
                    for _ in 0..confirmations.take() {
                        if let Some(m) = unconfirmed.pop_front() {
                            stats.published += 1;
                            if !qos1 {
                                written.devs.push_back(m.dev);
                            }
                        }
                    }
                    written.trim(proofs.proven.load(std::sync::atomic::Ordering::SeqCst));
                    match e {
                        Some(Loop::ConnAck(kept)) => {
                            connected = true;
                            outbox.set_connected(true);
                            away_told = false;
                            if was_connected {
                                stats.reconnects += 1;
                            }
                            was_connected = true;
                            if !kept {
                                // A new session: rumqttc dropped what it held; send it again, first.
                                outbox.put_back(pending.drain(..));
                                outbox.put_back(unconfirmed.drain(..));
                            }
                            if !said_offline {
                                // Straight to the client, ahead of the queue (a full queue
                                // could push it out).
                                let m = status(b"online");
                                match client.try_publish(m.topic.clone(), QoS::AtLeastOnce, true, m.payload.clone()) {
                                    Ok(()) => unconfirmed.push_back(m),
                                    Err(_) => outbox.push_front(m),
                                }
                            }
                            if let Some(filter) = &cfg.commands {
                                let _ = client.try_subscribe(filter.clone(), QoS::AtLeastOnce);
                            }
                            let _ = notes.send(Note::Connected);
                        }
                        Some(Loop::Confirmed) => {}
                        Some(Loop::Disconnected) => {}
                        Some(Loop::Closed) => break,
                        Some(Loop::Command(topic, payload)) => {
                            let _ = notes.send(Note::Command(topic, payload));
                        }
                        Some(Loop::Error(why)) => {
                            connected = false;
                            outbox.set_connected(false);
                            if !qos1 {
                                // Written at QoS 0 on the lost connection and never proven to
                                // have arrived: not published, dropped with the broker away.
                                let lost = written.lose(&outbox);
                                stats.published = stats.published.saturating_sub(lost);
                                use std::sync::atomic::Ordering::SeqCst;
                                let all = proofs.written.load(SeqCst);
                                proofs.proven.store(all, SeqCst);
                                written.before = all;
                            }
                            // Nothing more goes to the client until the next CONNACK: the event
                            // loop may reconnect now (see its error arm).
                            let _ = atx.send(());
                            // Not handed over: back into the queue, where the bound applies.
                            outbox.put_back(pending.drain(..));
                            if let Some(f) = classify(&why) {
                                let _ = notes.send(Note::Fatal(f.clone()));
                                stats.fatal = Some(f);
                                break;
                            }
                            last_error = why.clone();
                            if !away_told {
                                away_told = true;
                                let _ = notes.send(Note::Away(why));
                            }
                        }
                        None => break,
                    }
                }
                for _ in 0..confirmations.take() {
                    if unconfirmed.pop_front().is_some() {
                        stats.published += 1;
                    }
                }
                // At QoS 0, what was written without a proof of arrival is not counted as
                // published: dropped at the stop.
                let unproven = if qos1 { 0 } else { proofs.unproven() };
                stats.published = stats.published.saturating_sub(unproven);
                stats.undelivered = (outbox.len() + pending.len() + unconfirmed.len()) as u64 + unproven;
                stats
            }
        }
    };
}

broker_loop!(
    v4,
    rumqttc::AsyncClient,
    rumqttc::MqttOptions,
    rumqttc::Event,
    rumqttc::Packet,
    rumqttc::QoS,
    rumqttc::LastWill::new
);

fn will5(
    topic: String,
    payload: Vec<u8>,
    qos: rumqttc::v5::mqttbytes::QoS,
    retain: bool,
) -> rumqttc::v5::mqttbytes::v5::LastWill {
    rumqttc::v5::mqttbytes::v5::LastWill::new(topic, payload, qos, retain, None)
}

broker_loop!(
    v5,
    rumqttc::v5::AsyncClient,
    rumqttc::v5::MqttOptions,
    rumqttc::v5::Event,
    rumqttc::v5::mqttbytes::v5::Packet,
    rumqttc::v5::mqttbytes::QoS,
    will5
);

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn confirmations_wake_the_owner_once_per_burst_and_none_is_lost() {
        let c = Confirmations::default();
        assert!(c.add(), "the first one tells the owner");
        assert!(!c.add() && !c.add(), "the rest of the burst ride along");
        assert_eq!(c.take(), 3);
        assert_eq!(c.take(), 0);
        assert!(c.add(), "after a take the next one tells the owner again");
        assert_eq!(c.take(), 1);
    }

    #[test]
    fn refused_credentials_and_certificates_are_told_from_an_outage() {
        for e in [
            "Connection refused, return code: `NotAuthorized`",
            "Connection refused, return code: `BadUserNamePassword`",
        ] {
            assert!(matches!(classify(e), Some(Fatal::Auth(_))), "{e}");
        }
        for e in ["TLS: I/O: invalid peer certificate: UnknownIssuer", "TLS: Web Pki: certificate expired"] {
            assert!(matches!(classify(e), Some(Fatal::Tls(_))), "{e}");
        }
        for e in ["I/O: Connection refused (os error 111)", "Network timeout", "I/O: connection reset by peer"] {
            assert_eq!(classify(e), None, "{e}");
        }
    }
}
