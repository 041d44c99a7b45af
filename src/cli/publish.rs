//! `plcsh publish OPERANDS… --broker mqtt://HOST:PORT [-f FLEET]`: polls the operands on the
//! current device or on every member of a fleet and publishes them to an MQTT broker
//! ([`crate::publish`] has the topic layout and payloads; docs/fleets.md the guide).
//!
//! Exit status: 0 when the run ended (its `--count` polls, or a stop by Ctrl-C or SIGTERM)
//! with every reading delivered and every device answering; 1 when readings were dropped (the
//! stop's `dropped_at_stop` included) or a device was offline at the end; 2 for a usage error found before
//! anything connects (no broker, a password on the command line, a bad option, an operand
//! that one of the devices does not have); 3 when the broker refused the credentials; 4 when
//! the broker's TLS certificate did not verify or no broker answered at the start.

use crate::core::{Error, ErrorKind, Result};
use crate::output::{self, Style};
use crate::publish::broker::{self, Fatal, Note};
use crate::publish::outbox::{Msg, Outbox};
use crate::publish::poller::{Member, Pool};
use crate::publish::{self as publish, Poll, Seen, Shard};
use crate::shell::Shell;
use clap::Args;
use serde_json::json;
use std::io::Write;
use std::sync::atomic::Ordering;
use std::sync::mpsc::RecvTimeoutError;
use std::sync::Arc;
use std::time::{Duration, Instant};

/// Exit statuses of a broker failure (the table is `core::exit`).
pub use crate::core::exit::{BROKER_AUTH as EXIT_AUTH, BROKER_UNREACHABLE as EXIT_BROKER};
/// How long polling waits for the broker's first answer before it starts anyway.
const START_GRACE: Duration = Duration::from_secs(2);
/// How often `plcsh/GROUP/_publisher/stats` is published.
const STATS_EVERY: Duration = Duration::from_secs(5);

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
    /// Readings queued for the broker at most: while it is away the oldest beyond it are dropped;
    /// while it is connected but plcsh falls behind, the newest value of a topic replaces the queued one
    /// (both counted).
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
    /// Publish this part of the fleet only (K of N publishers; default: `shard` in the profile file's [mqtt]).
    #[arg(long, value_name = "K/N", requires = "fleet")]
    pub shard: Option<String>,
    /// The operands to publish (ranges allowed: VW100..VW110).
    #[arg(value_name = "OPERAND", required = true)]
    pub operands: Vec<String>,
}

/// Where the publisher's own topics go: `plcsh/GROUP/_publisher/` (`…/_publisher/shardK/` for
/// a shard, so each shard has its own status and last will).
fn publisher_prefix(group: &str, shard: Option<Shard>) -> String {
    match shard {
        Some(s) => format!("plcsh/{}/_publisher/shard{}/", publish::level(group), s.k),
        None => format!("plcsh/{}/_publisher/", publish::level(group)),
    }
}

fn config(
    args: &PublishArgs,
    file: &publish::FileSettings,
    group: &str,
    shard: Option<Shard>,
) -> Result<broker::Config> {
    let url =
        args.broker.clone().or(file.url.clone()).ok_or_else(|| {
            Error::usage(crate::msg!("publish-needs-broker")).hint(crate::msg!("publish-hint-broker"))
        })?;
    let (host, port, tls) = publish::parse_broker(&url)?;
    let env = |k: &str| std::env::var(k).ok().filter(|v| !v.is_empty());
    let username = env("PLCSH_MQTT_USERNAME").or(file.username.clone());
    let password = env("PLCSH_MQTT_PASSWORD").or(file.password.clone());
    let credentials = match (username, password) {
        (Some(u), p) => Some((u, p.unwrap_or_default())),
        (None, Some(_)) => {
            return Err(
                Error::usage(crate::msg!("publish-password-without-user")).hint(crate::msg!("publish-hint-username"))
            )
        }
        (None, None) => None,
    };
    let ca = match &file.ca_file {
        Some(f) => Some(std::fs::read(f).map_err(|e| {
            Error::io(crate::msg!("publish-cannot-read-ca", file = f.display().to_string(), error = e.to_string()))
        })?),
        None => None,
    };
    let default_id = match shard {
        Some(s) => format!("plcsh-{group}-shard{}-{}", s.k, std::process::id()),
        None => format!("plcsh-{group}-{}", std::process::id()),
    };
    Ok(broker::Config {
        host,
        port,
        tls: tls || ca.is_some(),
        ca,
        credentials,
        client_id: match (args.client_id.clone().or(file.client_id.clone()), shard) {
            // One id given for every shard (the profile file is shared): each shard still needs its own.
            (Some(id), Some(s)) if args.client_id.is_none() => format!("{id}-shard{}", s.k),
            (Some(id), _) => id,
            (None, _) => default_id,
        },
        v5: args.mqtt_version == "5",
        qos1: args.qos == 1,
        will_topic: format!("{}status", publisher_prefix(group, shard)),
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

/// The error and exit status of a broker failure no retry mends.
fn fatal(f: &Fatal, broker: &str) -> (Error, i32) {
    match f {
        Fatal::Auth(why) => (
            Error::new(ErrorKind::Refused, crate::msg!("publish-auth-refused", broker = broker, why = why.as_str()))
                .hint(crate::msg!("publish-hint-auth")),
            EXIT_AUTH,
        ),
        Fatal::Tls(why) => (
            Error::new(ErrorKind::Link, crate::msg!("publish-tls-failed", broker = broker, why = why.as_str()))
                .hint(crate::msg!("publish-hint-tls")),
            EXIT_BROKER,
        ),
        Fatal::NeverReached(why) => (
            Error::new(
                ErrorKind::Link,
                crate::msg!(
                    "publish-no-broker",
                    broker = broker,
                    seconds = broker::FIRST_CONTACT.as_secs(),
                    why = why.as_str()
                ),
            )
            .hint(crate::msg!("publish-hint-no-broker")),
            EXIT_BROKER,
        ),
    }
}

/// The members this publisher polls, each with its session opened (no connection yet), and
/// every operand checked against every member's model: one usage error for all that are
/// wrong, before anything connects.
fn members(
    shell: &mut Shell,
    fleet: Option<&crate::fleet::Fleet>,
    shard: Option<Shard>,
    operands: &[String],
) -> Result<Vec<Member>> {
    let texts: Vec<&str> = operands.iter().map(String::as_str).collect();
    let Some(f) = fleet else {
        // A device that could not be connected yet (its grammar comes with its model, known
        // once it answers) is checked at its first answer; any other is checked now.
        let waiting = shell
            .session
            .current_index()
            .ok()
            .and_then(|i| shell.session.entries().get(i))
            .is_some_and(|e| crate::pending::is_not_connected(e.device.info()));
        if !waiting {
            for t in &texts {
                if let Err(e) = shell.session.resolve(t) {
                    let mut err = Error::usage(crate::msg!(
                        "publish-not-an-operand",
                        operand = *t,
                        error = e.message.to_string()
                    ))
                    .hint(crate::msg!("publish-hint-fix-operand"));
                    if let Some(h) = e.hint.clone() {
                        err = err.hint(h);
                    }
                    return Err(err);
                }
            }
        }
        let name = shell.current_device().unwrap_or_else(|_| "plc".into());
        let mut stand_in = crate::session::Session::new(shell.session.clock.clone());
        stand_in.interrupt = shell.session.interrupt.clone();
        let session = std::mem::replace(&mut shell.session, stand_in);
        return Ok(vec![Member { name, session: Ok(session), reopen: None }]);
    };
    let base = crate::fleet::run::Base::of(&shell.session, Style::default());
    let stop = shell.session.interrupt.clone();
    // One copy of the fleet and the profiles for every member's reopening.
    let shared = Arc::new((base.clone(), f.clone()));
    let mut list = Vec::new();
    // (operand, devices that do not have it, the first error)
    let mut wrong: Vec<(String, Vec<String>, Error)> = Vec::new();
    for m in f.members.iter().filter(|m| shard.is_none_or(|s| s.takes(&m.name))) {
        let session = base.open_session(f, m, stop.clone());
        if let Ok(s) = &session {
            for t in &texts {
                if let Err(e) = s.resolve(t) {
                    match wrong.iter_mut().find(|(op, ..)| op == t) {
                        Some((_, devices, _)) => devices.push(m.name.clone()),
                        None => wrong.push((t.to_string(), vec![m.name.clone()], e)),
                    }
                }
            }
        }
        // A member that cannot be opened now is tried again by its poller (with backoff).
        let (shared, member, stop) = (shared.clone(), m.clone(), stop.clone());
        let reopen: crate::publish::poller::Reopen =
            Box::new(move || shared.0.open_session(&shared.1, &member, stop.clone()));
        list.push(Member { name: m.name.clone(), session, reopen: Some(reopen) });
    }
    if let Some((op, devices, e)) = wrong.into_iter().next() {
        let shown = devices.iter().take(5).cloned().collect::<Vec<_>>().join(", ");
        let message = if devices.len() == list.len() {
            crate::msg!(
                "publish-not-an-operand-fleet",
                operand = op.as_str(),
                fleet = f.name.as_str(),
                error = e.message.to_string()
            )
        } else {
            crate::msg!(
                "publish-not-an-operand-members",
                operand = op.as_str(),
                members = shown,
                more = devices.len().saturating_sub(5),
                error = e.message.to_string()
            )
        };
        let mut err = Error::usage(message).hint(crate::msg!("publish-hint-fix-operand-fleet"));
        if let Some(h) = e.hint.clone() {
            err = err.hint(h);
        }
        return Err(err);
    }
    Ok(list)
}

fn start(cli: &super::Cli, shell: &mut Shell, args: &PublishArgs, style: Style, out: &mut dyn Write) -> Result<i32> {
    let every = crate::core::literal::parse_option_duration_us(&args.every)
        .ok()
        .filter(|us| *us > 0)
        .map(|us| Duration::from_micros(us as u64))
        .ok_or_else(|| {
            Error::usage(crate::msg!("publish-bad-every", every = args.every.as_str()))
                .hint(crate::msg!("publish-hint-every"))
        })?;
    let fleet = match &args.fleet {
        Some(name) => Some(shell.session.profiles.fleet(name)?.clone()),
        None => None,
    };
    let group = fleet.as_ref().map_or("single".to_string(), |f| f.name.clone());
    let path = cli.config.clone().or_else(crate::profile::default_path);
    let file = publish::file_settings(path.as_deref())?;
    let shard = match (args.shard.as_deref(), fleet.is_some()) {
        (Some(t), _) => Some(Shard::parse(t)?),
        (None, true) => file.shard.as_deref().map(Shard::parse).transpose()?,
        (None, false) => None,
    };
    let cfg = config(args, &file, &group, shard)?;
    let members = members(shell, fleet.as_ref(), shard, &args.operands)?;
    let single = fleet.is_none();
    let broker_name = format!("{}:{}", cfg.host, cfg.port);
    let prefix = publisher_prefix(&group, shard);
    let poll = Poll {
        group: group.clone(),
        operands: args.operands.clone(),
        every,
        deadband: args.on_change.then(|| args.deadband.unwrap_or(0.0)),
        count: args.count,
    };
    let names: Vec<String> = members.iter().map(|m| m.name.clone()).collect();
    // `--accept-writes`: the members by their topic level; every member of the fleet, for
    // telling "another shard's" from "no such device".
    let routes: std::collections::HashMap<String, usize> =
        names.iter().enumerate().map(|(i, n)| (publish::level(n), i)).collect();
    let everyone: Vec<String> = match &fleet {
        Some(f) => f.members.iter().map(|m| m.name.clone()).collect(),
        None => names.clone(),
    };
    let outbox = Arc::new(Outbox::new(args.buffer.max(1), members.len()));
    let (notes_tx, notes) = std::sync::mpsc::channel();
    let broker_thread = broker::spawn(cfg, outbox.clone(), notes_tx)
        .map_err(|e| Error::io(crate::msg!("publish-no-mqtt-thread")).cause(e))?;
    let (seen_tx, seen) = std::sync::mpsc::channel::<Seen>();
    let stop = shell.session.interrupt.clone();
    // Polling starts once the broker has answered (or after START_GRACE without it, the
    // readings then wait for it): readings dropped while a connection is still being made
    // would be blamed on a broker that is there.
    let grace = Instant::now() + START_GRACE;
    let mut early = Vec::new();
    while let Ok(n) = notes.recv_timeout(grace.saturating_duration_since(Instant::now())) {
        let done = matches!(n, Note::Connected | Note::Fatal(_));
        early.push(n);
        if done || stop.load(Ordering::SeqCst) {
            break;
        }
    }
    if let Some(Note::Fatal(f)) = early.last() {
        outbox.close();
        let _ = broker_thread.join();
        let (e, code) = fatal(f, &broker_name);
        output::report_error(out, style, "publish", &e, None)?;
        return Ok(code);
    }
    let (early_tx, notes_early) = std::sync::mpsc::channel();
    for n in early {
        let _ = early_tx.send(n);
    }
    drop(early_tx);
    let pool = Pool::start(members, poll, outbox.clone(), seen_tx)
        .map_err(|e| Error::io(crate::msg!("publish-no-poll-threads")).cause(e))?;
    let mut offline: std::collections::BTreeSet<String> = Default::default();
    let mut failed: Option<Fatal> = None;
    let mut stopped_by_signal = false;
    let started = Instant::now();
    let mut next_stats = started + STATS_EVERY;
    let stats_msg = |outbox: &Outbox, offline: usize, workers: usize| {
        let (skipped, behind, away) = outbox.totals();
        let j = json!({"ts": publish::now_ms(), "devices": names.len(), "workers": workers, "queued": outbox.len(),
            "skipped": skipped, "dropped_behind": behind, "dropped_broker_away": away, "offline": offline,
            "shard": shard.map(|s| format!("{}/{}", s.k, s.n)), "uptime_s": started.elapsed().as_secs()});
        Msg {
            topic: format!("{prefix}stats"),
            payload: j.to_string().into_bytes(),
            retain: true,
            key: None,
            dev: Outbox::PUBLISHER,
        }
    };
    // Report what happens while the devices are polled.
    loop {
        while let Ok(n) = notes_early.try_recv().or_else(|_| notes.try_recv()) {
            match n {
                Note::Connected => event(
                    out,
                    style,
                    json!({"ok": true, "cmd": "publish", "event": "broker", "state": "connected", "broker": broker_name}),
                    crate::msg!("publish-connected", broker = broker_name.as_str()).text,
                ),
                Note::Away(why) => event(
                    out,
                    style,
                    json!({"ok": true, "cmd": "publish", "event": "broker", "state": "away", "broker": broker_name, "reason": why}),
                    crate::msg!("publish-broker-away", broker = broker_name.as_str(), why = why.as_str()).text,
                ),
                Note::Fatal(f) => failed = Some(f),
                Note::Command(topic, payload) => {
                    // plcsh/GROUP/DEVICE/set: to that device's poller; another shard's device is
                    // that shard's; a device of no shard gets its answer from this publisher
                    // (from shard 1 only, so it is answered once).
                    let device = topic.split('/').nth(2).unwrap_or("");
                    if let Some(&i) = routes.get(device) {
                        pool.command(i, payload);
                    } else if shard.is_none_or(|s| s.k == 1) && !everyone.iter().any(|n| publish::level(n) == device) {
                        let reply = publish::writes::unknown_device(device, &group, &everyone, &payload);
                        outbox.push(Msg {
                            topic: publish::topic(&group, device, "reply"),
                            payload: reply.to_string().into_bytes(),
                            retain: false,
                            key: None,
                            dev: Outbox::PUBLISHER,
                        });
                    }
                }
            }
        }
        if failed.is_some() {
            break;
        }
        if stop.load(Ordering::SeqCst) {
            stopped_by_signal = true;
            break;
        }
        match seen.recv_timeout(Duration::from_millis(50)) {
            Ok(Seen::Offline(d, e)) => {
                offline.insert(d.clone());
                event(
                    out,
                    style,
                    json!({"ok": true, "cmd": "publish", "event": "device", "device": d, "state": "offline",
                        "reason": crate::publish::poller::reason(&e), "error": e}),
                    format!("{d} offline ({}): {e}", crate::publish::poller::reason(&e)),
                );
            }
            Ok(Seen::Online(d)) => {
                offline.remove(&d);
                event(
                    out,
                    style,
                    json!({"ok": true, "cmd": "publish", "event": "device", "device": d, "state": "online"}),
                    crate::msg!("publish-device-back", device = d.as_str()).text,
                );
            }
            Err(RecvTimeoutError::Timeout) => {}
            Err(RecvTimeoutError::Disconnected) => {}
        }
        if pool.finished() {
            break;
        }
        if Instant::now() >= next_stats {
            next_stats += STATS_EVERY;
            outbox.set_stats(stats_msg(&outbox, offline.len(), pool.workers()));
        }
    }
    pool.stop();
    pool.join();
    if stopped_by_signal {
        // A stop is this command's normal end: the exit status says how the delivery went
        // (a second signal during the delivery counts again).
        crate::signals::handled();
        stop.store(false, Ordering::SeqCst);
    }
    let mut offline: Vec<String> = pool.offline();
    offline.sort();
    if let Some(f) = &failed {
        outbox.close();
        let _ = broker_thread.join();
        let (e, code) = fatal(f, &broker_name);
        output::report_error(out, style, "publish", &e, None)?;
        return Ok(code);
    }
    event(
        out,
        style,
        json!({"ok": true, "cmd": "publish", "event": "polling", "state": "stopped"}),
        crate::msg!("publish-polling-stopped").text,
    );
    outbox.set_stats(stats_msg(&outbox, offline.len(), 0));
    outbox.close();
    let stats = broker_thread.join().unwrap_or_default();
    let mut late_fatal = None;
    while let Ok(n) = notes.try_recv() {
        match n {
            Note::Away(why) => event(
                out,
                style,
                json!({"ok": true, "cmd": "publish", "event": "broker", "state": "away", "broker": broker_name, "reason": why}),
                format!("broker {broker_name} away ({why})"),
            ),
            Note::Fatal(f) => late_fatal = Some(f),
            _ => {}
        }
    }
    if let Some(f) = late_fatal.or(stats.fatal.clone()) {
        let (e, code) = fatal(&f, &broker_name);
        output::report_error(out, style, "publish", &e, None)?;
        return Ok(code);
    }
    if single {
        // The session goes back to the shell (its device stays open for what follows).
        if let Some(s) = pool.take_session(0) {
            shell.session = s;
        }
    }
    let (skipped, behind, away) = outbox.totals();
    // What the stop could not hand to the broker (or, at QoS 0, not prove it arrived) is
    // dropped at the stop, never published.
    let at_stop = stats.undelivered;
    let dropped = behind + away + at_stop;
    // Per device, those that missed anything: {"press7": {"skipped": 3, "dropped_behind": 0, …}}.
    let mut per_device = serde_json::Map::new();
    for (i, c) in outbox.counters.iter().enumerate() {
        let (s, b, a) = (
            c.skipped.load(Ordering::Relaxed),
            c.behind.load(Ordering::Relaxed),
            c.broker_away.load(Ordering::Relaxed),
        );
        if s + b + a > 0 {
            let name = names.get(i).cloned().unwrap_or_else(|| "_publisher".into());
            per_device.insert(name, json!({"skipped": s, "dropped_behind": b, "dropped_broker_away": a}));
        }
    }
    let ok = dropped == 0 && stats.undelivered == 0 && offline.is_empty();
    let summary = json!({"ok": ok, "cmd": "publish", "group": group, "broker": broker_name, "published": stats.published,
        "dropped": dropped, "dropped_broker_away": away, "dropped_behind": behind, "dropped_at_stop": at_stop, "skipped": skipped,
        "undelivered": stats.undelivered, "reconnects": stats.reconnects, "offline": offline,
        "devices": names.len(), "behind": per_device, "shard": shard.map(|s| format!("{}/{}", s.k, s.n))});
    if style.json {
        writeln!(out, "{summary}")?;
    } else {
        let worst: Vec<String> = {
            let mut v: Vec<(&String, u64)> = per_device
                .iter()
                .map(|(k, v)| {
                    (
                        k,
                        ["skipped", "dropped_behind", "dropped_broker_away"]
                            .iter()
                            .map(|f| v[*f].as_u64().unwrap_or(0))
                            .sum(),
                    )
                })
                .collect();
            v.sort_by_key(|b| std::cmp::Reverse(b.1));
            v.iter().take(5).map(|(k, n)| format!("{k} {n}")).collect()
        };
        let some = |b: bool| if b { "some" } else { "none" };
        let summary = crate::msg!(
            "publish-summary",
            published = stats.published,
            broker = broker_name.as_str(),
            group = group.as_str(),
            shard = some(shard.is_some()),
            shard_of = shard.map(|s| format!("{}/{}", s.k, s.n)).unwrap_or_default(),
            away = away,
            behind = behind,
            skipped = skipped,
            undelivered = stats.undelivered,
            reconnects = stats.reconnects,
            worst = some(!worst.is_empty()),
            worst_list = worst.join(", "),
            offline = some(!offline.is_empty()),
            offline_list = offline.join(", "),
        );
        writeln!(out, "{summary}")?;
    }
    Ok(if ok { 0 } else { 1 })
}
