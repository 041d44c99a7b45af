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
//! `plcsh/<GROUP>/<DEVICE>/status` is `online`/`offline` (retained): a device that stops
//! answering is marked offline and none of its values are published until it answers again
//! (so nothing stale is published as fresh). `plcsh/<GROUP>/_publisher/status` is the
//! publisher's own state, `offline` also as its last will. With `--accept-writes`,
//! `plcsh/<GROUP>/<DEVICE>/set` takes writes and `…/reply` answers them ([`writes`]).
//!
//! Each device is polled on a thread of its own with the same reader as `get` (one batch per
//! poll, coalesced by the driver); the broker connection is one thread ([`broker`]).

pub mod broker;
pub mod writes;

use crate::core::{Error, Result, Value};
use crate::shell::Shell;
use broker::{Msg, ToBroker};
use std::collections::HashMap;
use std::sync::atomic::{AtomicBool, Ordering};
use std::time::Duration;
use tokio::sync::mpsc::UnboundedSender;

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
fn now_ms() -> u64 {
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

/// Polls one device (the shell's current one) until `stop` or the count; sends its messages.
pub fn poll_device(
    shell: &mut Shell,
    device: &str,
    p: &Poll,
    tx: &UnboundedSender<ToBroker>,
    seen: &std::sync::mpsc::Sender<Seen>,
    stop: &AtomicBool,
    commands: Option<&std::sync::mpsc::Receiver<Vec<u8>>>,
) {
    let texts: Vec<&str> = p.operands.iter().map(String::as_str).collect();
    let mut last: HashMap<String, Value> = HashMap::new();
    let mut online: Option<bool> = None;
    let send = |topic: String, payload: Vec<u8>| {
        let _ = tx.send(ToBroker::Msg(Msg { topic, payload, retain: true }));
    };
    let mut seq = 0u64;
    loop {
        if stop.load(Ordering::Relaxed) || p.count.is_some_and(|c| seq >= c) {
            break;
        }
        seq += 1;
        let started = std::time::Instant::now();
        // Writes from the broker (`--accept-writes`) first, so this poll shows them.
        while let Some(payload) = commands.and_then(|c| c.try_recv().ok()) {
            let reply = writes::apply(shell, device, &payload);
            let _ = tx.send(ToBroker::Msg(Msg {
                topic: topic(&p.group, device, "reply"),
                payload: reply.to_string().into_bytes(),
                retain: false,
            }));
        }
        match shell.session.get(&texts) {
            Ok(readings) => {
                let ts = now_ms();
                if online != Some(true) {
                    // Back (or first): every value is published fresh.
                    last.clear();
                    send(topic(&p.group, device, "status"), b"online".to_vec());
                    if online.is_some() {
                        let _ = seen.send(Seen::Online(device.to_string()));
                    }
                    online = Some(true);
                }
                for (_, r) in readings {
                    if let Some(db) = p.deadband {
                        if !changed(last.get(&r.operand), &r.value, db) {
                            continue;
                        }
                    }
                    let payload = serde_json::json!({"value": r.value, "type": r.dtype, "ts": ts, "seq": seq,
                        "device": device, "operand": r.operand});
                    send(topic(&p.group, device, &r.operand), payload.to_string().into_bytes());
                    last.insert(r.operand.clone(), r.value);
                }
            }
            Err(e) => {
                if online != Some(false) {
                    send(topic(&p.group, device, "status"), b"offline".to_vec());
                    let _ = seen.send(Seen::Offline(device.to_string(), e));
                    online = Some(false);
                }
            }
        }
        if p.count.is_some_and(|c| seq >= c) {
            break;
        }
        let rest = p.every.saturating_sub(started.elapsed());
        if !crate::core::Clock::sleep_real(rest, &shell.session.interrupt) {
            break;
        }
    }
}

/// The `[mqtt]` section of the profile file: `url`, `username`, `password`, `ca_file`,
/// `client_id`. PLCSH_MQTT_USERNAME and PLCSH_MQTT_PASSWORD override the file's.
#[derive(Clone, Debug, Default, serde::Deserialize)]
#[serde(deny_unknown_fields)]
pub struct FileSettings {
    pub url: Option<String>,
    pub username: Option<String>,
    pub password: Option<String>,
    pub ca_file: Option<std::path::PathBuf>,
    pub client_id: Option<String>,
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
