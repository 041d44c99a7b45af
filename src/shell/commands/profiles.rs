//! The `devices` listing: open devices (the current one marked `*`), then the profiles from
//! devices.toml that are not open, its fleets (`crate::profile::fleet`); any problem in that file (with
//! file:line) is a note of its own line. Shared by the REPL's `devices` and `plcsh devices`.

use crate::output::Outcome;
use crate::session::Session;

/// Table rows and the outcome (with `devices`, `profiles`, `problems` for JSON).
pub fn devices_and_profiles(s: &Session) -> (Vec<Vec<String>>, Outcome) {
    let current = s.current_name().map(str::to_string);
    let mut rows = Vec::new();
    let mut list = Vec::new();
    for e in s.entries() {
        let info = e.device.info();
        let is_current = Some(&e.name) == current.as_ref();
        let mark = if is_current { "*" } else { "" };
        let writes = e.guard.as_ref().map(|g| g.summary()).unwrap_or_default();
        // A device whose link could not be made yet says so, in the prompt's words, whatever
        // its URL tells of its model.
        let connected = !crate::pending::is_not_connected(info);
        let url = if connected { e.url.clone() } else { format!("{}{}", e.url, crate::pending::NOT_CONNECTED) };
        let model =
            if connected || info.model != crate::pending::UNKNOWN_MODEL { info.model.clone() } else { String::new() };
        rows.push(vec![format!("{mark}{}", e.name), info.family.to_string(), model, url, writes.clone()]);
        list.push(serde_json::json!({"name": e.name, "family": info.family, "model": info.model, "url": e.url,
            "simulated": info.simulated, "current": is_current, "connected": connected, "writes": writes}));
    }
    let mut profiles = Vec::new();
    for p in s.profiles.list() {
        let open = s.entries().iter().any(|e| e.name == p.name);
        if !open {
            let writes = match (&p.allow, p.read_only) {
                (_, true) => crate::msg!("shell-devices-read-only").text,
                (Some(a), false) => format!("allow {}", a.join(", ")),
                (None, false) => String::new(),
            };
            rows.push(vec![p.name.clone(), "(profile)".into(), String::new(), p.url.clone(), writes]);
        }
        profiles.push(serde_json::json!({"name": p.name, "url": p.url, "read_only": p.read_only,
            "allow": p.allow, "origin": p.origin, "open": open}));
    }
    let mut fleets = Vec::new();
    for f in &s.profiles.fleets {
        let n = f.members.len();
        // A URL fleet's members share its rules; a list's members have their own profiles.
        let writes = match f.members.first().map(|m| &m.source) {
            Some(crate::profile::fleet::Source::Made(p)) if p.read_only => crate::msg!("shell-devices-read-only").text,
            Some(crate::profile::fleet::Source::Made(p)) => {
                p.allow.as_ref().map(|a| format!("allow {}", a.join(", "))).unwrap_or_default()
            }
            _ => crate::msg!("shell-devices-per-profile").text,
        };
        rows.push(vec![
            f.name.clone(),
            "(fleet)".into(),
            crate::msg!("shell-devices-count", count = n).text,
            f.spec.clone(),
            writes,
        ]);
        let members: Vec<&str> = f.members.iter().map(|m| m.name.as_str()).collect();
        fleets.push(serde_json::json!({"name": f.name, "members": members, "spec": f.spec, "origin": f.origin}));
    }
    let problems: Vec<String> = s.profiles.problems.iter().map(|p| p.to_string()).collect();
    let mut o = Outcome::new("devices").with("devices", list).with("profiles", profiles);
    // A problem is a message of its own line (`note: …`), never a table cell: one bad profile
    // leaves the rows as narrow as the devices make them.
    for p in &problems {
        o.notes.push(crate::msg!("shell-devices-profile-problem", problem = p.as_str()).text);
    }
    if !fleets.is_empty() {
        o = o.with("fleets", fleets);
    }
    if !problems.is_empty() {
        o = o.with("problems", problems);
    }
    if let Some(f) = &s.profiles.file {
        o = o.with("profile_file", f.display().to_string());
    }
    (rows, o)
}
