//! The MQTT side of `plcsh publish`: one thread with a small tokio runtime that owns the
//! broker connection (rumqttc; MQTT 3.1.1 or 5). Readings arrive on a channel; they wait in
//! one bounded queue and leave it, oldest first, only while the broker is connected, so
//! readings taken while it is away are delivered in order when it returns. Beyond the bound
//! the oldest are dropped and counted. The connection is retried with backoff (0.1 s doubling
//! to 5 s); the publisher's own last will marks it offline.
//!
//! rumqttc's event loop runs in a task of its own and reports to the queue's owner over a
//! channel, so nothing waits on an event loop that is not being polled (its `poll` is not
//! cancelled by a `select!`). A message handed to rumqttc stays in our `unconfirmed` list
//! until it is written (QoS 0) or acknowledged (QoS 1), in order; when the broker comes back
//! without the old session, rumqttc forgets what it held, and those messages go back to the
//! front of the queue — so nothing taken while the broker was away is lost to a reconnect
//! (at QoS 1 a message may then arrive twice, as MQTT's "at least once" allows).

use std::collections::VecDeque;
use std::time::Duration;
use tokio::sync::mpsc::{unbounded_channel, UnboundedReceiver, UnboundedSender};

/// One message for the broker.
#[derive(Clone, Debug)]
pub struct Msg {
    pub topic: String,
    pub payload: Vec<u8>,
    pub retain: bool,
}

/// What the pollers send.
pub enum ToBroker {
    Msg(Msg),
    /// Deliver what is queued (for a few seconds at most), then disconnect.
    Stop,
}

/// What the broker side tells the front end.
#[derive(Clone, Debug, PartialEq)]
pub enum Note {
    Connected,
    /// The broker went away (why), with the readings queued so far.
    Away(String),
    /// A message on a command topic (`--accept-writes`): topic and payload.
    Command(String, Vec<u8>),
}

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
    /// Readings kept while the broker is away.
    pub bound: usize,
    /// The publisher's own status topic (its last will says `offline`).
    pub will_topic: String,
    /// The command topic filter subscribed to (`--accept-writes`), if any.
    pub commands: Option<String>,
}

/// What happened, for the summary.
#[derive(Clone, Debug, Default)]
pub struct Stats {
    pub published: u64,
    pub dropped: u64,
    pub reconnects: u64,
    /// Still queued at the end (the broker was away when plcsh stopped).
    pub undelivered: u64,
}

enum Loop {
    /// Connected; whether the broker kept the last session (rumqttc then resends what it holds).
    ConnAck(bool),
    /// One more message left for good: written (QoS 0) or acknowledged (QoS 1).
    Confirmed,
    Disconnected,
    Error(String),
    Command(String, Vec<u8>),
}

const BACKOFF_MIN: Duration = Duration::from_millis(100);
const BACKOFF_MAX: Duration = Duration::from_secs(5);

/// Starts the broker thread; returns the channel for readings and the thread (its stats).
pub fn spawn(
    cfg: Config,
    notes: std::sync::mpsc::Sender<Note>,
) -> std::io::Result<(UnboundedSender<ToBroker>, std::thread::JoinHandle<Stats>)> {
    let (tx, rx) = unbounded_channel();
    let h = std::thread::Builder::new().name("mqtt".into()).spawn(move || {
        let rt = match tokio::runtime::Builder::new_current_thread().enable_all().build() {
            Ok(rt) => rt,
            Err(e) => {
                let _ = notes.send(Note::Away(format!("cannot start a runtime: {e}")));
                return Stats::default();
            }
        };
        if cfg.v5 {
            rt.block_on(v5::run(cfg, rx, notes))
        } else {
            rt.block_on(v4::run(cfg, rx, notes))
        }
    })?;
    Ok((tx, h))
}

fn transport(cfg: &Config) -> rumqttc::Transport {
    match (&cfg.ca, cfg.tls) {
        (Some(ca), _) => rumqttc::Transport::tls(ca.clone(), None, None),
        (None, true) => rumqttc::Transport::tls_with_default_config(),
        (None, false) => rumqttc::Transport::Tcp,
    }
}

/// The queue: bounded, oldest dropped first.
struct Queue {
    items: VecDeque<Msg>,
    bound: usize,
    dropped: u64,
}

impl Queue {
    fn push(&mut self, m: Msg) {
        self.items.push_back(m);
        while self.items.len() > self.bound.max(1) {
            self.items.pop_front();
            self.dropped += 1;
        }
    }
}

/// The same loop for MQTT 3.1.1 and 5: the two client APIs differ only in their types.
macro_rules! broker_loop {
    ($m:ident, $client:path, $opts:path, $event:path, $packet:path, $qos:path, $will:expr) => {
        pub(super) mod $m {
            use super::*;
            use $event as Event;
            use $packet as Packet;
            use $qos as QoS;

            pub async fn run(
                cfg: Config,
                mut rx: UnboundedReceiver<ToBroker>,
                notes: std::sync::mpsc::Sender<Note>,
            ) -> Stats {
                let mut opts = <$opts>::new(cfg.client_id.clone(), cfg.host.clone(), cfg.port);
                opts.set_keep_alive(Duration::from_secs(5));
                opts.set_transport(transport(&cfg));
                if let Some((u, p)) = &cfg.credentials {
                    opts.set_credentials(u.clone(), p.clone());
                }
                opts.set_last_will($will(cfg.will_topic.clone(), b"offline".to_vec(), QoS::AtLeastOnce, true));
                let (client, mut eventloop) = <$client>::new(opts, 100);
                let (etx, mut erx) = unbounded_channel::<Loop>();
                let qos1 = cfg.qos1;
                tokio::spawn(async move {
                    let mut backoff = BACKOFF_MIN;
                    loop {
                        let sent = match eventloop.poll().await {
                            Ok(Event::Incoming(Packet::ConnAck(c))) => {
                                backoff = BACKOFF_MIN;
                                etx.send(Loop::ConnAck(c.session_present))
                            }
                            Ok(Event::Incoming(Packet::PubAck(_))) if qos1 => etx.send(Loop::Confirmed),
                            Ok(Event::Incoming(Packet::Publish(p))) => {
                                let topic = String::from_utf8_lossy(AsRef::<[u8]>::as_ref(&p.topic)).into_owned();
                                etx.send(Loop::Command(topic, p.payload.to_vec()))
                            }
                            Ok(Event::Outgoing(rumqttc::Outgoing::Publish(_))) if !qos1 => etx.send(Loop::Confirmed),
                            Ok(Event::Outgoing(rumqttc::Outgoing::Disconnect)) => etx.send(Loop::Disconnected),
                            Ok(_) => Ok(()),
                            Err(e) => {
                                let r = etx.send(Loop::Error(e.to_string()));
                                tokio::time::sleep(backoff).await;
                                backoff = (backoff * 2).min(BACKOFF_MAX);
                                r
                            }
                        };
                        if sent.is_err() {
                            break;
                        }
                    }
                });
                let qos = if cfg.qos1 { QoS::AtLeastOnce } else { QoS::AtMostOnce };
                let mut queue = Queue { items: VecDeque::new(), bound: cfg.bound, dropped: 0 };
                let mut unconfirmed: VecDeque<Msg> = VecDeque::new();
                let status = |text: &[u8]| Msg { topic: cfg.will_topic.clone(), payload: text.to_vec(), retain: true };
                let mut stats = Stats::default();
                let (mut connected, mut was_connected, mut stopping, mut said_offline) = (false, false, false, false);
                let mut away_told = false;
                let mut deadline = None;
                loop {
                    if connected {
                        // Oldest first; a full client channel leaves the rest queued for the next turn.
                        while let Some(m) = queue.items.front() {
                            if client.try_publish(m.topic.clone(), qos, m.retain, m.payload.clone()).is_err() {
                                break;
                            }
                            unconfirmed.extend(queue.items.pop_front());
                        }
                        if stopping && queue.items.is_empty() && unconfirmed.is_empty() && deadline.is_none() {
                            if !said_offline {
                                said_offline = true;
                                queue.items.push_back(status(b"offline"));
                                continue;
                            }
                            let _ = client.try_disconnect();
                            deadline = Some(tokio::time::Instant::now() + Duration::from_secs(5));
                        }
                    }
                    let until = deadline.unwrap_or_else(|| tokio::time::Instant::now() + Duration::from_secs(3600));
                    tokio::select! {
                        e = erx.recv() => match e {
                            Some(Loop::ConnAck(kept)) => {
                                connected = true;
                                away_told = false;
                                if was_connected {
                                    stats.reconnects += 1;
                                }
                                was_connected = true;
                                if !kept {
                                    // A new session: rumqttc dropped what it held; send it again, first.
                                    while let Some(m) = unconfirmed.pop_back() {
                                        queue.items.push_front(m);
                                    }
                                }
                                if !said_offline {
                                    queue.items.push_front(status(b"online"));
                                }
                                if let Some(filter) = &cfg.commands {
                                    let _ = client.try_subscribe(filter.clone(), QoS::AtLeastOnce);
                                }
                                let _ = notes.send(Note::Connected);
                            }
                            Some(Loop::Confirmed) => {
                                if unconfirmed.pop_front().is_some() {
                                    stats.published += 1;
                                }
                            }
                            Some(Loop::Disconnected) => break,
                            Some(Loop::Command(topic, payload)) => {
                                let _ = notes.send(Note::Command(topic, payload));
                            }
                            Some(Loop::Error(why)) => {
                                if !away_told {
                                    away_told = true;
                                    let _ = notes.send(Note::Away(why));
                                }
                                connected = false;
                                if stopping && deadline.is_none() {
                                    // Stopping with the broker away: give it a few seconds to return.
                                    deadline = Some(tokio::time::Instant::now() + Duration::from_secs(5));
                                }
                            }
                            None => break,
                        },
                        m = rx.recv(), if !stopping => match m {
                            Some(ToBroker::Msg(m)) => queue.push(m),
                            Some(ToBroker::Stop) | None => stopping = true,
                        },
                        _ = tokio::time::sleep_until(until), if deadline.is_some() => break,
                    }
                }
                stats.dropped = queue.dropped;
                stats.undelivered = (queue.items.len() + unconfirmed.len()) as u64;
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
    fn the_queue_keeps_the_newest_in_order_and_counts_the_dropped() {
        let mut q = Queue { items: VecDeque::new(), bound: 3, dropped: 0 };
        for i in 0..5 {
            q.push(Msg { topic: format!("t{i}"), payload: Vec::new(), retain: false });
        }
        let kept: Vec<&str> = q.items.iter().map(|m| m.topic.as_str()).collect();
        assert_eq!(kept, ["t2", "t3", "t4"]);
        assert_eq!(q.dropped, 2);
    }
}
