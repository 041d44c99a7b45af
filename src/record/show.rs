//! `plcsh record show FILE`: a recording as a decoded timeline, one line per frame (time,
//! device, direction, what the frame says, its bytes), or one JSON object per frame.

use super::decode::{self, Decoded};
use super::file::Recording;
use super::packet::proto_name;
use crate::core::trace::{hex_bytes, Dir};
use serde::Serialize;
use std::io::Write;

/// One timeline entry as `--json` writes it (the JSON contract's `ok`, `cmd` and `sub` first).
#[derive(Serialize)]
struct JsonFrame<'a> {
    ok: bool,
    cmd: &'static str,
    sub: &'static str,
    n: usize,
    /// Virtual time in seconds (the session's clock), when recorded.
    #[serde(skip_serializing_if = "Option::is_none")]
    vt: Option<f64>,
    /// Wall time, seconds since the Unix epoch.
    wall: f64,
    device: &'a str,
    proto: &'static str,
    dir: &'static str,
    #[serde(flatten)]
    decoded: &'a Decoded,
    hex: String,
}

/// Writes the timeline of `rec`.
pub fn write(rec: &Recording, json: bool, out: &mut dyn Write) -> std::io::Result<()> {
    let decoded = decode::all(&rec.links, &rec.frames);
    let t0 = rec.frames.first().map(|f| f.wall).unwrap_or_default();
    let width = rec.links.iter().map(|l| l.name.chars().count()).max().unwrap_or(0);
    for (n, (f, d)) in rec.frames.iter().zip(&decoded).enumerate() {
        let link = &rec.links[f.link];
        if json {
            let j = JsonFrame {
                ok: true,
                cmd: "record",
                sub: "show",
                n: n + 1,
                vt: f.vt.map(|v| v.as_secs_f64()),
                wall: f.wall.as_secs_f64(),
                device: &link.name,
                proto: proto_name(link.proto),
                dir: if f.dir == Dir::Sent { "sent" } else { "received" },
                decoded: d,
                hex: hex_bytes(&f.bytes),
            };
            writeln!(out, "{}", serde_json::to_string(&j).map_err(std::io::Error::other)?)?;
        } else {
            let time = match f.vt {
                Some(v) => format!("{:>12.6}", v.as_secs_f64()),
                None => format!("{:>12.6}", f.wall.saturating_sub(t0).as_secs_f64()),
            };
            let arrow = if f.dir == Dir::Sent { "→" } else { "←" };
            writeln!(out, "{time}  {:<width$} {arrow} {}  [{}]", link.name, d.text, hex_bytes(&f.bytes))?;
        }
    }
    Ok(())
}
