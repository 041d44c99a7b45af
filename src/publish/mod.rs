//! `plcsh publish`: watched values flow into an MQTT broker (Node-RED, Telegraf, a SCADA),
//! from one device or every member of a fleet.
//!
//! Topics: `plcsh/<GROUP>/<DEVICE>/<OPERAND>` where GROUP is the fleet's name or `single`;
//! an operand's type view keeps its name with `/` written `_` (`VD100/REAL` →
//! `VD100_REAL`), since `/` separates topic levels. Payload (JSON):
//! `{"value":5,"type":"WORD","ts":1764115200123,"seq":7,"device":"press1","operand":"VW100"}`
//! — `ts` is the source timestamp (ms since the Unix epoch, UTC: when the device's answer
//! arrived), `seq` counts this device's polls, `unit` is added where the operand has one.
//! Values are retained (a subscriber that connects later gets the last ones).
//! `plcsh/<GROUP>/<DEVICE>/status` is `{"state":"online"}` or
//! `{"state":"offline","reason":"no reply"}` (retained; [`poller::reason`]): a device that
//! stops answering, or cannot be opened, is marked offline and none of its values are
//! published until it answers again (so nothing stale is published as fresh); it is tried
//! again with backoff for as long as the run lasts. `plcsh/<GROUP>/_publisher/status` is the
//! publisher's own state, `offline` also as its last will. With `--accept-writes`,
//! `plcsh/<GROUP>/<DEVICE>/set` takes writes and `…/reply` answers them ([`writes`]).
//!
//! `plcsh/<GROUP>/_publisher/stats` (retained, every few seconds and at the end) sums up
//! what the publisher did and why readings went missing ([`outbox`]'s counters).
//!
//! The devices are polled on a fixed-rate schedule by a small pool of threads ([`poller`])
//! with the same reader as `get` (one batch per poll, coalesced by the driver); values wait
//! in one bounded queue ([`outbox`]); the broker connection is one thread ([`broker`]).
//! With `--shard K/N` a publisher takes its part of a fleet ([`Shard`]).

pub mod broker;
pub mod outbox;
pub mod poller;
#[cfg(test)]
mod property;
pub mod writes;

use crate::core::{Error, Result, Value};
use std::time::Duration;

/// How a device is polled.
#[derive(Clone, Debug)]
pub struct Poll {
    pub group: String,
    pub operands: Vec<String>,
    pub every: Duration,
    /// Publish only changes bigger than this (`None`: every poll).
    pub deadband: Option<f64>,
    /// Stop after this many polls (`None`: until stopped).
    pub count: Option<u64>,
}

/// A topic level from a name: `/`, `+` and `#` are not allowed inside one.
pub fn level(name: &str) -> String {
    name.chars().map(|c| if matches!(c, '/' | '+' | '#') { '_' } else { c }).collect()
}

pub fn topic(group: &str, device: &str, leaf: &str) -> String {
    format!("plcsh/{}/{}/{}", level(group), level(device), level(leaf))
}

/// Milliseconds since the Unix epoch (UTC), now.
pub(crate) fn now_ms() -> u64 {
    std::time::SystemTime::now().duration_since(std::time::UNIX_EPOCH).map(|d| d.as_millis() as u64).unwrap_or(0)
}

fn number(v: &Value) -> Option<f64> {
    serde_json::to_value(v).ok()?.as_f64()
}

/// Whether a new reading differs from the last published one by more than the deadband.
pub fn changed(last: Option<&Value>, new: &Value, deadband: f64) -> bool {
    match (last, number(new)) {
        (None, _) => true,
        (Some(l), Some(n)) => match number(l) {
            Some(o) => (n - o).abs() > deadband || (deadband == 0.0 && n != o),
            None => true,
        },
        (Some(l), None) => l != new,
    }
}

/// What a device's poller reports to the front end.
#[derive(Clone, Debug)]
pub enum Seen {
    Offline(String, Error),
    Online(String),
}

/// `--shard K/N`: this publisher's part of a fleet split over N publishers. A member belongs
/// to shard `FNV-1a(name) mod N + 1`: the parts are disjoint, together they are the fleet,
/// and a member stays in its part whatever the order of the list and whatever members are
/// added or removed (only the new ones find a part). Each shard has its own client id
/// (`plcsh-GROUP-shardK-PID` by default) and last will (`plcsh/GROUP/_publisher/shardK/status`),
/// and all publish one topic tree.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Shard {
    pub k: u32,
    pub n: u32,
}

impl Shard {
    pub fn parse(text: &str) -> Result<Shard> {
        let bad = || {
            Error::usage(format!("--shard {text} is not K/N"))
                .hint("e.g. --shard 1/3, --shard 2/3 and --shard 3/3 on three publishers (1 <= K <= N)")
        };
        let (k, n) = text.split_once('/').ok_or_else(bad)?;
        let (k, n) = (k.trim().parse::<u32>().map_err(|_| bad())?, n.trim().parse::<u32>().map_err(|_| bad())?);
        if n == 0 || k == 0 || k > n {
            return Err(bad());
        }
        Ok(Shard { k, n })
    }

    /// Whether member `name` is this shard's.
    pub fn takes(&self, name: &str) -> bool {
        let mut h: u64 = 0xcbf2_9ce4_8422_2325;
        for b in name.bytes() {
            h ^= u64::from(b);
            h = h.wrapping_mul(0x0100_0000_01b3);
        }
        (h % u64::from(self.n)) as u32 + 1 == self.k
    }
}

/// The `[mqtt]` section of the profile file: `url`, `username`, `password`, `ca_file`,
/// `client_id`, `shard`. PLCSH_MQTT_USERNAME and PLCSH_MQTT_PASSWORD override the file's.
#[derive(Clone, Debug, Default, serde::Deserialize)]
#[serde(deny_unknown_fields)]
pub struct FileSettings {
    pub url: Option<String>,
    pub username: Option<String>,
    pub password: Option<String>,
    pub ca_file: Option<std::path::PathBuf>,
    pub client_id: Option<String>,
    /// This host's part of a fleet (`"2/3"`), as `--shard`.
    pub shard: Option<String>,
}

#[derive(serde::Deserialize)]
struct RawFile {
    #[serde(default)]
    mqtt: Option<FileSettings>,
}

/// Reads `[mqtt]` from the profile file (none when the file or the section is missing).
pub fn file_settings(path: Option<&std::path::Path>) -> Result<FileSettings> {
    let Some(path) = path else { return Ok(FileSettings::default()) };
    let text = match std::fs::read_to_string(path) {
        Ok(t) => t,
        Err(_) => return Ok(FileSettings::default()),
    };
    let raw: RawFile = toml::from_str(&text)
        .map_err(|e| Error::usage(format!("{}: [mqtt]: {}", path.display(), e.message().trim_end())))?;
    Ok(raw.mqtt.unwrap_or_default())
}

/// `mqtt://HOST[:PORT]` or `mqtts://HOST[:PORT]` (1883, 8883 by default). A password in the
/// URL is refused: it would show in the process list and the shell's history.
pub fn parse_broker(url: &str) -> Result<(String, u16, bool)> {
    let bad = || {
        Error::usage(format!("`{url}` is not a broker URL"))
            .hint("mqtt://HOST:1883 or mqtts://HOST:8883 (TLS); credentials go in the profile file's [mqtt] or PLCSH_MQTT_PASSWORD")
    };
    let (tls, rest) = if let Some(r) = url.strip_prefix("mqtts://") {
        (true, r)
    } else if let Some(r) = url.strip_prefix("mqtt://") {
        (false, r)
    } else {
        return Err(bad());
    };
    if rest.contains('@') {
        return Err(Error::usage("a broker URL must not carry credentials")
            .hint("put username in the profile file's [mqtt] and the password in PLCSH_MQTT_PASSWORD"));
    }
    let rest = rest.trim_end_matches('/');
    let (host, port) = match rest.rsplit_once(':') {
        Some((h, p)) if !h.ends_with(']') || h.starts_with('[') => (h, p.parse::<u16>().map_err(|_| bad())?),
        _ => (rest, if tls { 8883 } else { 1883 }),
    };
    let host = host.trim_start_matches('[').trim_end_matches(']');
    if host.is_empty() {
        return Err(bad());
    }
    Ok((host.to_string(), port, tls))
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn topics_keep_one_level_per_name() {
        assert_eq!(topic("single", "plc", "VD100/REAL"), "plcsh/single/plc/VD100_REAL");
        assert_eq!(topic("presses", "press1", "status"), "plcsh/presses/press1/status");
        assert_eq!(level("a+b#c"), "a_b_c");
    }

    #[test]
    fn a_deadband_publishes_only_real_changes() {
        let (a, b) = (Value::Int(100), Value::Int(102));
        assert!(changed(None, &a, 5.0));
        assert!(!changed(Some(&a), &b, 5.0));
        assert!(changed(Some(&a), &Value::Int(106), 5.0));
        assert!(changed(Some(&a), &b, 0.0), "deadband 0: any change");
        assert!(!changed(Some(&a), &a, 0.0));
        assert!(changed(Some(&Value::Bool(false)), &Value::Bool(true), 0.0));
    }

    #[test]
    fn shards_split_a_fleet_into_disjoint_parts_whatever_its_order() {
        let names: Vec<String> = (1..=500).map(|i| format!("press{i}")).collect();
        let shards: Vec<Shard> = (1..=3).map(|k| Shard::parse(&format!("{k}/3")).unwrap()).collect();
        let mut sizes = [0; 3];
        for n in &names {
            let owners: Vec<usize> = (0..3).filter(|&k| shards[k].takes(n)).collect();
            assert_eq!(owners.len(), 1, "{n} belongs to exactly one shard: {owners:?}");
            sizes[owners[0]] += 1;
        }
        assert!(sizes.iter().all(|&s| s > 120), "roughly even: {sizes:?}");
        // The part depends on the name alone: the same in any order, with any other members.
        assert!(names.iter().filter(|n| shards[0].takes(n)).all(|n| Shard { k: 1, n: 3 }.takes(n)));
        assert!(Shard::parse("1/1").unwrap().takes("anything"));
        for bad in ["0/3", "4/3", "1/0", "3", "a/b", "1/3/4"] {
            assert!(Shard::parse(bad).is_err(), "{bad}");
        }
    }

    #[test]
    fn broker_urls() {
        assert_eq!(parse_broker("mqtt://127.0.0.1:1884").unwrap(), ("127.0.0.1".into(), 1884, false));
        assert_eq!(parse_broker("mqtts://broker.local").unwrap(), ("broker.local".into(), 8883, true));
        assert_eq!(parse_broker("mqtt://[::1]:1883").unwrap(), ("::1".into(), 1883, false));
        assert!(parse_broker("mqtt://u:secret@h").unwrap_err().message.contains("credentials"));
        assert!(parse_broker("http://h").is_err());
        assert!(parse_broker("mqtt://h:port").is_err());
        assert!(parse_broker("mqtt://").is_err());
    }
}
