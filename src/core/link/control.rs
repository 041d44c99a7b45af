//! The control channel of a served simulator, family-neutral: a served device (a K2 on
//! Modbus, a drive line, a UMPK, an FX PLC) is steered while it runs — faults added, listed
//! and cleared, inputs switched, the fault event log read — through one local channel beside
//! its link, in the same words as the in-process `sim …` commands.
//!
//! The channel is a Unix socket at `PATH` (on Windows a loopback TCP port whose number is
//! written to the file `PATH`; see [`super::LocalListener`]). One request per line, at most
//! [`MAX_LINE`] bytes; one JSON reply per line: `{"ok":true,"text":"…",…}` or
//! `{"ok":false,"error":"…","hint":"…"}`. Any client can use it (`socat - UNIX:PATH`,
//! `plcsh sim control PATH …`, a test harness); what each family accepts is its own
//! `sim::control` module's grammar.
//!
//! It lives in the transport layer because it is platform code (sockets, the Windows port
//! file) that every served family shares, and because a front end must never reach into a
//! served simulator any other way.

use super::{local_connect, LocalListener, LocalStream};
use crate::core::{Error, Result};
use crate::msg;
use serde_json::{json, Value as Json};
use std::io::{BufRead, BufReader, Read, Write};
use std::path::{Path, PathBuf};
use std::sync::atomic::{AtomicBool, Ordering};
use std::sync::Arc;
use std::time::Duration;

/// Longest control line accepted.
pub const MAX_LINE: usize = 4096;

/// How long the accept loop sleeps between polls of the stop flag.
const POLL: Duration = Duration::from_millis(20);

/// Answers one control line with a JSON reply (`ok`, `text` | `error`, `hint`, data).
pub type Answer = Arc<dyn Fn(&str) -> Json + Send + Sync>;

/// The control channel's default path for a link: `LINK.ctl`.
pub fn default_path(link: &Path) -> PathBuf {
    let mut s = link.as_os_str().to_os_string();
    s.push(".ctl");
    PathBuf::from(s)
}

/// The JSON reply for a result: `{"ok":true,"text":…, …data}` or the error with its hint.
pub fn reply(r: Result<(String, Json)>) -> Json {
    match r {
        Ok((text, data)) => {
            let mut m = serde_json::Map::new();
            m.insert("ok".into(), json!(true));
            m.insert("text".into(), json!(text));
            if let Json::Object(d) = data {
                for (k, v) in d {
                    if k != "ok" && k != "text" {
                        m.insert(k, v);
                    }
                }
            }
            Json::Object(m)
        }
        Err(e) => {
            let mut j = json!({"ok": false, "error": e.message});
            if let Some(h) = &e.hint {
                j["hint"] = json!(h);
            }
            j
        }
    }
}

/// A bound control channel: answers requests on its own thread until the stop flag is
/// raised; the socket (or port file) is removed when it is dropped.
pub struct Channel {
    path: PathBuf,
}

impl Channel {
    /// Binds `path` and serves `answer` on it. `what` names the device in the error
    /// ("the served K2's control channel").
    pub fn open(path: &Path, what: &str, answer: Answer, stop: Arc<AtomicBool>) -> Result<Channel> {
        let listener = LocalListener::bind(path).map_err(|e| {
            Error::io(msg!("link-cannot-open-channel", what = what, path = path.display().to_string()))
                .cause(e)
                .hint(msg!("link-hint-channel-path"))
        })?;
        std::thread::spawn(move || serve(listener, answer, stop));
        Ok(Channel { path: path.to_path_buf() })
    }

    pub fn path(&self) -> &Path {
        &self.path
    }
}

impl Drop for Channel {
    fn drop(&mut self) {
        let _ = std::fs::remove_file(&self.path);
    }
}

/// Answers control requests on `listener` until `stop` (one thread per connection).
pub fn serve(listener: LocalListener, answer: Answer, stop: Arc<AtomicBool>) {
    while !stop.load(Ordering::Relaxed) {
        match listener.accept() {
            Ok(conn) => {
                let answer = answer.clone();
                std::thread::spawn(move || connection(conn, &*answer));
            }
            Err(_) => std::thread::sleep(POLL),
        }
    }
}

fn connection(conn: LocalStream, answer: &(dyn Fn(&str) -> Json + Send + Sync)) {
    let Ok(mut w) = conn.try_clone() else { return };
    let mut r = BufReader::new(conn);
    loop {
        // One request per line, at most MAX_LINE bytes (outside input).
        let mut raw = Vec::new();
        match (&mut r).take(MAX_LINE as u64 + 1).read_until(b'\n', &mut raw) {
            Ok(0) | Err(_) => break,
            Ok(_) => {}
        }
        let too_long = raw.len() > MAX_LINE;
        let reply = if too_long {
            json!({"ok": false, "error": msg!("link-control-line-long", max = MAX_LINE).text})
        } else {
            match std::str::from_utf8(&raw) {
                Ok(text) => answer(text.trim()),
                Err(_) => json!({"ok": false, "error": msg!("link-control-line-utf8").text}),
            }
        };
        if writeln!(w, "{reply}").is_err() || too_long {
            break;
        }
    }
}

/// Sends one control line to the channel at `path` and returns the reply's text and the
/// whole reply; a refusal comes back as a usage error with the channel's hint.
pub fn send(path: &Path, text: &str) -> Result<(String, Json)> {
    let io = |e: std::io::Error| {
        Error::link(msg!("link-cannot-reach-channel", path = path.display().to_string()))
            .cause(e)
            .hint(msg!("link-hint-reach-channel"))
    };
    let mut s = local_connect(path).map_err(io)?;
    s.set_read_timeout(Some(Duration::from_secs(5))).map_err(io)?;
    writeln!(s, "{}", text.replace(['\n', '\r'], " ")).map_err(io)?;
    let mut reply = String::new();
    BufReader::new(&s).read_line(&mut reply).map_err(io)?;
    let j: Json = serde_json::from_str(&reply)
        .map_err(|e| Error::link(msg!("link-channel-answered", reply = reply.trim())).cause(e))?;
    if j["ok"] == json!(true) {
        Ok((j["text"].as_str().unwrap_or_default().to_string(), j))
    } else {
        let mut e = match j["error"].as_str() {
            Some(m) => Error::usage(m.to_string()),
            None => Error::usage(msg!("link-simulator-refused")),
        };
        if let Some(h) = j["hint"].as_str() {
            e = e.hint(h.to_string());
        }
        Err(e)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_channel_answers_line_by_line_and_refuses_long_lines() {
        let dir = std::env::temp_dir().join(format!("plcsh-control-{}", std::process::id()));
        std::fs::create_dir_all(&dir).unwrap();
        let path = dir.join("dev.ctl");
        let stop = Arc::new(AtomicBool::new(false));
        let answer: Answer = Arc::new(|t: &str| {
            if t == "bad" {
                reply(Err(Error::usage("no such control").hint("try ping")))
            } else {
                reply(Ok((format!("echo {t}"), json!({"n": t.len()}))))
            }
        });
        let ch = Channel::open(&path, "the test channel", answer, stop.clone()).unwrap();
        let (text, j) = send(&path, "ping").unwrap();
        assert_eq!((text.as_str(), j["n"].as_u64()), ("echo ping", Some(4)));
        let e = send(&path, "bad").unwrap_err();
        assert_eq!((e.message.as_str(), e.hint.as_deref()), ("no such control", Some("try ping")));
        let e = send(&path, &"x".repeat(MAX_LINE + 10)).unwrap_err();
        assert!(e.message.contains("at most"), "{e}");
        stop.store(true, Ordering::Relaxed);
        drop(ch);
        assert!(!path.exists());
        let _ = std::fs::remove_dir(&dir);
    }
}
