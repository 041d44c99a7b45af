//! `plcsh publish OPERANDS… --broker mqtt://HOST:PORT [-f FLEET]`: polls the operands on the
//! current device or on every member of a fleet and publishes them to an MQTT broker
//! ([`crate::publish`] has the topic layout and payloads; docs/fleets.md the guide).
//!
//! Exit status: 0 when the run ended (its `--count` polls, or Ctrl-C) with every reading
//! delivered and every device answering; 1 when readings were dropped or left undelivered or a
//! device was offline at the end; 2 for a usage error (no broker, a password on the command
//! line, a bad option).

use crate::core::{Error, ErrorKind, Result};
use crate::output::{self, Style};
use crate::publish::broker::{self, Note, ToBroker};
use crate::publish::{self as publish, Poll, Seen};
use crate::shell::Shell;
use clap::Args;
use serde_json::json;
use std::io::Write;
use std::sync::mpsc::RecvTimeoutError;
use std::sync::Arc;
use std::time::Duration;

#[derive(Args, Debug)]
pub struct PublishArgs {
    /// The broker: mqtt://HOST:PORT, or mqtts://HOST:PORT for TLS (default: `url` in the profile file's [mqtt]).
    #[arg(long, value_name = "URL")]
    pub broker: Option<String>,
    /// Publish every member of this fleet (default: the current device).
    #[arg(short = 'f', long = "fleet", value_name = "NAME")]
    pub fleet: Option<String>,
    /// How often each device is read.
    #[arg(long, value_name = "DURATION", default_value = "1s")]
    pub every: String,
    /// MQTT quality of service for values: 0 (at most once) or 1 (at least once).
    #[arg(long, default_value_t = 0, value_parser = clap::value_parser!(u8).range(0..=1))]
    pub qos: u8,
    /// Publish a value only when it changed (by more than --deadband); otherwise every poll.
    #[arg(long = "on-change")]
    pub on_change: bool,
    /// With --on-change: the smallest change published (in the operand's units).
    #[arg(long, value_name = "X", requires = "on_change")]
    pub deadband: Option<f64>,
    /// Readings kept while the broker is away (the oldest beyond it are dropped and counted).
    #[arg(long, value_name = "N", default_value_t = 10_000)]
    pub buffer: usize,
    /// MQTT protocol version.
    #[arg(long = "mqtt-version", value_name = "VERSION", default_value = "3.1.1", value_parser = ["3.1.1", "5"])]
    pub mqtt_version: String,
    /// Stop after this many polls of each device (default: until Ctrl-C).
    #[arg(long, value_name = "N")]
    pub count: Option<u64>,
    /// The MQTT client id (default: plcsh-GROUP-PID).
    #[arg(long = "client-id", value_name = "ID")]
    pub client_id: Option<String>,
    /// Take writes from the broker on plcsh/GROUP/DEVICE/set, only to operands on the device profile's
    /// allow list (replies on plcsh/GROUP/DEVICE/reply); read-only profiles never accept one.
    #[arg(long = "accept-writes")]
    pub accept_writes: bool,
    /// The operands to publish (ranges allowed: VW100..VW110).
    #[arg(value_name = "OPERAND", required = true)]
    pub operands: Vec<String>,
}

fn config(cli: &super::Cli, args: &PublishArgs, group: &str) -> Result<broker::Config> {
    let path = cli.config.clone().or_else(crate::profile::default_path);
    let file = publish::file_settings(path.as_deref())?;
    let url = args.broker.clone().or(file.url.clone()).ok_or_else(|| {
        Error::usage("publish needs a broker")
            .hint("--broker mqtt://HOST:1883, or url = \"mqtt://HOST:1883\" under [mqtt] in the profile file")
    })?;
    let (host, port, tls) = publish::parse_broker(&url)?;
    let env = |k: &str| std::env::var(k).ok().filter(|v| !v.is_empty());
    let username = env("PLCSH_MQTT_USERNAME").or(file.username);
    let password = env("PLCSH_MQTT_PASSWORD").or(file.password);
    let credentials = match (username, password) {
        (Some(u), p) => Some((u, p.unwrap_or_default())),
        (None, Some(_)) => {
            return Err(Error::usage("a broker password without a username")
                .hint("set username under [mqtt] in the profile file or PLCSH_MQTT_USERNAME"))
        }
        (None, None) => None,
    };
    let ca = match &file.ca_file {
        Some(f) => {
            Some(std::fs::read(f).map_err(|e| Error::io(format!("cannot read [mqtt] ca_file {}: {e}", f.display())))?)
        }
        None => None,
    };
    Ok(broker::Config {
        host,
        port,
        tls: tls || ca.is_some(),
        ca,
        credentials,
        client_id: args
            .client_id
            .clone()
            .or(file.client_id)
            .unwrap_or_else(|| format!("plcsh-{group}-{}", std::process::id())),
        v5: args.mqtt_version == "5",
        qos1: args.qos == 1,
        bound: args.buffer.max(1),
        will_topic: publish::topic(group, "_publisher", "status"),
        commands: args.accept_writes.then(|| format!("plcsh/{}/+/set", publish::level(group))),
    })
}

fn event(out: &mut dyn Write, style: Style, j: serde_json::Value, text: String) {
    if style.json {
        let _ = writeln!(out, "{j}");
        let _ = out.flush();
    } else {
        eprintln!("publish: {text}");
    }
}

/// Runs `plcsh publish`; returns the exit status.
pub fn run(cli: &super::Cli, shell: &mut Shell, args: &PublishArgs, style: Style, out: &mut dyn Write) -> i32 {
    match start(cli, shell, args, style, out) {
        Ok(code) => code,
        Err(e) => {
            let _ = output::report_error(out, style, "publish", &e, None);
            if e.kind == ErrorKind::Usage {
                2
            } else {
                1
            }
        }
    }
}

fn start(cli: &super::Cli, shell: &mut Shell, args: &PublishArgs, style: Style, out: &mut dyn Write) -> Result<i32> {
    let every = crate::core::literal::parse_option_duration_us(&args.every)
        .ok()
        .filter(|us| *us > 0)
        .map(|us| Duration::from_micros(us as u64))
        .ok_or_else(|| Error::usage(format!("--every {} is not a duration", args.every)).hint("e.g. 1s, 250ms"))?;
    let fleet = match &args.fleet {
        Some(name) => Some(shell.session.profiles.fleet(name)?.clone()),
        None => None,
    };
    let group = fleet.as_ref().map_or("single".to_string(), |f| f.name.clone());
    if fleet.is_none() {
        let texts: Vec<&str> = args.operands.iter().map(String::as_str).collect();
        for t in &texts {
            shell.session.resolve(t)?;
        }
    }
    let cfg = config(cli, args, &group)?;
    let broker_name = format!("{}:{}", cfg.host, cfg.port);
    let poll = Poll {
        group: group.clone(),
        operands: args.operands.clone(),
        every,
        deadband: args.on_change.then(|| args.deadband.unwrap_or(0.0)),
        count: args.count,
    };
    let (notes_tx, notes) = std::sync::mpsc::channel();
    let (tx, broker_thread) =
        broker::spawn(cfg, notes_tx).map_err(|e| Error::io("cannot start the MQTT thread").cause(e))?;
    let (seen_tx, seen) = std::sync::mpsc::channel::<Seen>();
    let stop = shell.session.interrupt.clone();
    let mut offline: std::collections::BTreeSet<String> = Default::default();
    let base = crate::fleet::run::Base::of(&shell.session, Style::default());
    // `--accept-writes`: each device's command channel, by its topic level.
    let mut routes: std::collections::HashMap<String, std::sync::mpsc::Sender<Vec<u8>>> = Default::default();
    let mut route = |name: &str| {
        let (t, r) = std::sync::mpsc::channel::<Vec<u8>>();
        routes.insert(publish::level(name), t);
        args.accept_writes.then_some(r)
    };
    let single = shell.current_device().unwrap_or_else(|_| "plc".into());
    let single_rx = route(&single);
    let member_rx: Vec<_> = fleet.iter().flat_map(|f| f.members.iter()).map(|m| route(&m.name)).collect();
    std::thread::scope(|scope| {
        let mut pollers = Vec::new();
        match &fleet {
            Some(f) => {
                let f = Arc::new(f.clone());
                for ((i, m), rx) in f.members.iter().enumerate().zip(member_rx) {
                    let (f, base, poll, tx, seen_tx, stop) =
                        (f.clone(), base.clone(), poll.clone(), tx.clone(), seen_tx.clone(), stop.clone());
                    let name = m.name.clone();
                    pollers.push(scope.spawn(move || match base.open(&f, &f.members[i], stop.clone()) {
                        Ok(mut sh) => publish::poll_device(&mut sh, &name, &poll, &tx, &seen_tx, &stop, rx.as_ref()),
                        Err(e) => {
                            let _ = tx.send(ToBroker::Msg(broker::Msg {
                                topic: publish::topic(&poll.group, &name, "status"),
                                payload: b"offline".to_vec(),
                                retain: true,
                            }));
                            let _ = seen_tx.send(Seen::Offline(name, e));
                        }
                    }));
                }
            }
            None => {
                let name = single.clone();
                let (poll, tx, seen_tx, stop) = (poll.clone(), tx.clone(), seen_tx.clone(), stop.clone());
                let sh = &mut *shell;
                pollers.push(
                    scope.spawn(move || {
                        publish::poll_device(sh, &name, &poll, &tx, &seen_tx, &stop, single_rx.as_ref())
                    }),
                );
            }
        }
        drop(seen_tx);
        // Report what happens while the devices are polled.
        loop {
            while let Ok(n) = notes.try_recv() {
                match n {
                    Note::Connected => event(out, style, json!({"ok": true, "cmd": "publish", "event": "broker", "state": "connected", "broker": broker_name}), format!("connected to {broker_name}")),
                    Note::Away(why) => event(out, style, json!({"ok": true, "cmd": "publish", "event": "broker", "state": "away", "broker": broker_name, "reason": why}), format!("broker {broker_name} away ({why}); readings are kept up to --buffer and sent when it returns")),
                    Note::Command(topic, payload) => {
                        // plcsh/GROUP/DEVICE/set: to that device's poller (others are not ours).
                        let device = topic.split('/').nth(2).unwrap_or("");
                        if let Some(t) = routes.get(device) {
                            let _ = t.send(payload);
                        }
                    }
                }
            }
            match seen.recv_timeout(Duration::from_millis(50)) {
                Ok(Seen::Offline(d, e)) => {
                    offline.insert(d.clone());
                    event(
                        out,
                        style,
                        json!({"ok": true, "cmd": "publish", "event": "device", "device": d, "state": "offline", "error": e}),
                        format!("{d} offline: {e}"),
                    );
                }
                Ok(Seen::Online(d)) => {
                    offline.remove(&d);
                    event(
                        out,
                        style,
                        json!({"ok": true, "cmd": "publish", "event": "device", "device": d, "state": "online"}),
                        format!("{d} answers again"),
                    );
                }
                Err(RecvTimeoutError::Timeout) => {}
                Err(RecvTimeoutError::Disconnected) => break,
            }
        }
        for p in pollers {
            let _ = p.join();
        }
    });
    event(
        out,
        style,
        json!({"ok": true, "cmd": "publish", "event": "polling", "state": "stopped"}),
        "polling stopped; delivering what is queued (the broker has a few seconds to take it)".into(),
    );
    let _ = tx.send(ToBroker::Stop);
    drop(tx);
    let stats = broker_thread.join().unwrap_or_default();
    while let Ok(n) = notes.try_recv() {
        let Note::Away(why) = n else { continue };
        event(
            out,
            style,
            json!({"ok": true, "cmd": "publish", "event": "broker", "state": "away", "broker": broker_name, "reason": why}),
            format!("broker {broker_name} away ({why})"),
        );
    }
    let ok = stats.dropped == 0 && stats.undelivered == 0 && offline.is_empty();
    let offline: Vec<String> = offline.into_iter().collect();
    let summary = json!({"ok": ok, "cmd": "publish", "group": group, "broker": broker_name, "published": stats.published,
        "dropped": stats.dropped, "undelivered": stats.undelivered, "reconnects": stats.reconnects, "offline": offline});
    if style.json {
        writeln!(out, "{summary}")?;
    } else {
        writeln!(
            out,
            "published {} messages to {broker_name} (group {group}); {} dropped while the broker was away, {} undelivered, {} reconnects{}",
            stats.published,
            stats.dropped,
            stats.undelivered,
            stats.reconnects,
            if offline.is_empty() { String::new() } else { format!("; offline: {}", offline.join(", ")) }
        )?;
    }
    Ok(if ok { 0 } else { 1 })
}
