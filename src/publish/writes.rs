//! `plcsh publish --accept-writes`: writes that arrive from the broker. Off by default. A
//! message on `plcsh/GROUP/DEVICE/set` — `{"operand":"VW100","value":5,"id":"any"}` — is
//! applied only when the device's profile has an `allow` list and the operand is on it; a
//! read-only profile (or `--read-only`) never accepts one, and a device without a profile or
//! without an allow list refuses them all. Every outcome, applied or refused with the reason,
//! is published on `plcsh/GROUP/DEVICE/reply` (not retained), with the request's `id`.
//!
//! The write itself goes through the session like `set`, so the profile's guard checks it
//! again at the device boundary; the rule here only adds "the broker may write nothing the
//! profile does not list".

use crate::core::{Error, ErrorKind};
use crate::session::Session;
use crate::session::SetItem;
use serde_json::{json, Value as Json};

/// The longest command payload read (a write is a few dozen bytes).
pub const MAX_PAYLOAD: usize = 4096;

/// A write request.
#[derive(Debug, PartialEq)]
pub struct Command {
    pub operand: String,
    /// The value as `set` reads it (`5`, `16#85`, `true`, `1.5`).
    pub value: String,
    pub id: Json,
}

/// Parses a command payload; refuses anything but a small JSON object with `operand` and `value`.
pub fn parse(payload: &[u8]) -> Result<Command, String> {
    if payload.len() > MAX_PAYLOAD {
        return Err(crate::msg!("publish-command-too-big", max = MAX_PAYLOAD).text);
    }
    let v: Json = serde_json::from_slice(payload)
        .map_err(|e| crate::msg!("publish-command-not-json", error = e.to_string()).text)?;
    let o = v.as_object().ok_or_else(|| crate::msg!("publish-command-not-object").text)?;
    let operand =
        o.get("operand").and_then(Json::as_str).ok_or_else(|| crate::msg!("publish-command-no-operand").text)?;
    let value = match o.get("value") {
        Some(Json::Number(n)) => n.to_string(),
        Some(Json::Bool(b)) => b.to_string(),
        Some(Json::String(s)) => s.clone(),
        _ => return Err(crate::msg!("publish-command-no-value").text),
    };
    if operand.contains(['=', ',', ';']) || value.contains([',', ';']) {
        return Err(crate::msg!("publish-command-one-write").text);
    }
    Ok(Command { operand: operand.to_string(), value, id: o.get("id").cloned().unwrap_or(Json::Null) })
}

/// Applies (or refuses) one command on `device`, the session's current device; returns the reply.
pub fn apply(session: &mut Session, device: &str, payload: &[u8]) -> Json {
    let cmd = match parse(payload) {
        Ok(c) => c,
        Err(m) => return json!({"ok": false, "device": device, "error": {"kind": "syntax", "message": m}}),
    };
    // The same error object as the same write through `set` (`plcsh -c 'set …' --json`).
    let refuse = |e: Error| {
        json!({"ok": false, "device": device, "operand": cmd.operand, "value": cmd.value, "id": cmd.id,
            "error": serde_json::to_value(&e).unwrap_or_else(|_| json!({"kind": e.kind.name(), "message": e.message}))})
    };
    // `--read-only` and a read_only profile: refused by the device's guard, as `set` is. A
    // device without an allow list: refused here (`set` would write, the broker may not).
    let rules = session.entries().iter().find(|e| e.name == device).and_then(|e| e.guard.clone());
    let guarded = session.read_only() || rules.as_ref().is_some_and(|g| g.read_only());
    if !guarded {
        let refusal = match &rules {
            None => Some(crate::msg!("publish-write-no-allow-list", device = device)),
            Some(g) if !g.has_allow() => Some(crate::msg!("publish-write-profile-no-allow-list", device = device)),
            Some(_) => None,
        };
        if let Some(m) = refusal {
            return refuse(Error::new(ErrorKind::Refused, m).operand(cmd.operand.clone()).device(device.to_string()));
        }
    }
    let item = SetItem { operand: cmd.operand.clone(), value: cmd.value.clone(), column: 0, value_column: 0 };
    match session.set(&[item]) {
        Ok(w) => {
            // A tag's name beside its operand, as every reading carries it (docs/tags.md).
            let written: Vec<Json> = w
                .iter()
                .map(|(_, r)| {
                    let mut x = json!({"operand": r.operand, "value": r.value, "type": r.dtype});
                    if let Some(n) = &r.name {
                        x["name"] = Json::from(n.as_str());
                    }
                    x
                })
                .collect();
            json!({"ok": true, "device": device, "operand": cmd.operand, "id": cmd.id, "writes": written})
        }
        Err(e) => refuse(e),
    }
}

/// The reply to a write for a device that is offline (not opened yet): the device's error.
pub fn offline(device: &str, e: &Error, payload: &[u8]) -> Json {
    let (operand, value, id) = match parse(payload) {
        Ok(c) => (Json::from(c.operand), Json::from(c.value), c.id),
        Err(m) => return json!({"ok": false, "device": device, "error": {"kind": "syntax", "message": m}}),
    };
    json!({"ok": false, "device": device, "operand": operand, "value": value, "id": id,
        "error": serde_json::to_value(e).unwrap_or_else(|_| json!({"kind": e.kind.name(), "message": e.message}))})
}

/// The reply to a write for a device that is no member of the fleet (`plcsh/GROUP/pressX/set`):
/// an error naming the members, the closest names first.
pub fn unknown_device(device: &str, group: &str, members: &[String], payload: &[u8]) -> Json {
    let mut near: Vec<(usize, &String)> = members.iter().map(|m| (distance(device, m), m)).collect();
    near.sort();
    let close: Vec<&str> =
        near.iter().filter(|(d, _)| *d <= 2.max(device.len() / 3)).take(3).map(|(_, m)| m.as_str()).collect();
    let mut listed: Vec<&str> = members.iter().take(10).map(String::as_str).collect();
    if members.len() > 10 {
        listed.push("…");
    }
    let message = if close.is_empty() {
        crate::msg!("publish-no-such-member", device = device, group = group, members = listed.join(", "))
    } else {
        crate::msg!(
            "publish-no-such-member-near",
            device = device,
            group = group,
            members = listed.join(", "),
            near = close.join(", ")
        )
    }
    .text;
    let id = parse(payload).map(|c| c.id).unwrap_or(Json::Null);
    json!({"ok": false, "device": device, "id": id, "error": {"kind": "usage", "message": message}})
}

/// Levenshtein distance (names are short).
fn distance(a: &str, b: &str) -> usize {
    let b: Vec<char> = b.chars().collect();
    let mut row: Vec<usize> = (0..=b.len()).collect();
    for (i, ca) in a.chars().enumerate() {
        let mut prev = row[0];
        row[0] = i + 1;
        for (j, cb) in b.iter().enumerate() {
            let cur = row[j + 1];
            row[j + 1] = (prev + usize::from(ca != *cb)).min(row[j] + 1).min(cur + 1);
            prev = cur;
        }
    }
    row[b.len()]
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn commands_are_small_json_objects() {
        let c = parse(br#"{"operand":"VW100","value":5,"id":7}"#).unwrap();
        assert_eq!(c, Command { operand: "VW100".into(), value: "5".into(), id: json!(7) });
        assert_eq!(parse(br#"{"operand":"M0.0","value":true}"#).unwrap().value, "true");
        assert_eq!(parse(br#"{"operand":"SMB67","value":"16#85"}"#).unwrap().value, "16#85");
        for bad in
            [&b"5"[..], b"{", br#"{"value":1}"#, br#"{"operand":"VW0"}"#, br#"{"operand":"VW0=1, VW2","value":1}"#]
        {
            assert!(parse(bad).is_err(), "{}", String::from_utf8_lossy(bad));
        }
        assert!(parse(&vec![b' '; MAX_PAYLOAD + 1]).is_err());
    }

    #[test]
    fn a_write_for_no_member_names_the_members_and_the_closest() {
        let members: Vec<String> = ["press1", "press2", "oven"].iter().map(|s| s.to_string()).collect();
        let r = unknown_device("presX", "line", &members, br#"{"operand":"VW0","value":1,"id":9}"#);
        assert_eq!(r["ok"], false);
        assert_eq!(r["id"], 9);
        let m = r["error"]["message"].as_str().unwrap();
        assert!(m.contains("press1, press2, oven") && m.contains("did you mean press1, press2?"), "{m}");
        let far = unknown_device("zzzzzzzz", "line", &members, b"{}");
        assert!(!far["error"]["message"].as_str().unwrap().contains("did you mean"));
    }
}
