//! Snapshots: the complete simulated state of a session's simulators in one file
//! (`sim snapshot save NAME`, `sim snapshot restore NAME`, `sim snapshots`), so a lab can
//! ship a starting state and the same script from the same snapshot gives the same results.
//!
//! The file is JSON, versioned and made of sections, so new kinds of state (a program and
//! its timers, wiring) are new sections, not a new format:
//!
//! ```json
//! { "format": "plcsh-snapshot", "version": 1, "clock_us": 1500000, "stepped": true,
//!   "devices": { "plc":   { "family": "k2",    "sections": { "k2": { … } } },
//!                "servo": { "family": "servo", "sections": { "servo": { … } } } } }
//! ```
//!
//! A simulated FX PLC is one `fx` section ([`crate::fx::snapshot`]): its image, its CPU and its
//! program's text (compiled again on restore) with the engine's state. A simulated UMPK is one
//! `umpk` section ([`crate::umpk::sim::snapshot`]): mode, flash, error history, image, timers,
//! counters and its IL program with the engine's state. A simulator whose state a snapshot
//! cannot hold (a UMPK running a built-in program, a family without a section) makes the save
//! fail, naming the device and what it cannot keep: a snapshot never leaves a device out.
//!
//! A simulated PLC's wires are its `wiring` section: each wire's declaration (as `sim wire`
//! takes it) and what it carries between pieces (counts given, pulses pushed, levels in
//! flight). Restoring one re-declares the wires (replacing the PLC's current ones), then
//! sets the PLC, the drives and each wire's state, so a wired machine continues exactly.
//! From version 2 a PLC without a `wiring` section had no wires, and restoring removes
//! its wires; a version-1 snapshot (older than wiring in snapshots) leaves them as they are.
//!
//! A reader refuses a newer `version` and a section it does not know (a snapshot holding
//! state this plcsh cannot restore would otherwise restore silently incomplete). Restoring
//! needs the same devices, by name, with the same models; it checks everything before
//! changing anything it can check, then sets the clock and each device.
//!
//! A save brings every simulator to the saved instant first (`settle`: the same machine
//! always writes the same file) and reads back what it encoded before writing anything
//! ([`Snapshot::encode`]): every section must decode into the state it restores and encode to
//! the same JSON, or the save is refused naming the device, the section and the value. Non-finite
//! numbers are written as words ([`crate::core::float_serde`]), never as JSON `null`.
//!
//! Named snapshots live in the user's data directory (`…/plcsh/snapshots/NAME.json`);
//! a NAME with a `/` or ending in `.json` is a file path.

use crate::core::{Error, Result};
use crate::msg;
use crate::session::Session;
use serde::{Deserialize, Serialize};
use std::collections::BTreeMap;
use std::path::{Path, PathBuf};
use std::time::Duration;

pub const FORMAT: &str = "plcsh-snapshot";
pub const VERSION: u32 = 2;

/// One device's state, by section.
#[derive(Clone, Debug, Serialize, Deserialize)]
pub struct DeviceSnap {
    pub family: String,
    pub sections: BTreeMap<String, serde_json::Value>,
}

#[derive(Clone, Debug, Serialize, Deserialize)]
pub struct Snapshot {
    pub format: String,
    pub version: u32,
    /// The session's virtual time, microseconds.
    pub clock_us: u64,
    pub stepped: bool,
    pub devices: BTreeMap<String, DeviceSnap>,
}

fn enc(v: impl Serialize) -> Result<serde_json::Value> {
    serde_json::to_value(v).map_err(|e| Error::io(msg!("snapshot-cannot-encode")).cause(e))
}

/// Decodes `device`'s `section`; a value that does not fit is named by its path.
fn dec<T: serde::de::DeserializeOwned>(v: &serde_json::Value, device: &str, section: &str) -> Result<T> {
    serde_json::from_value(v.clone()).map_err(|e| {
        let m = match failing_field::<T>(v) {
            Some(at) => msg!("snapshot-section-invalid-at", device = device, section = section, at = at),
            None => msg!("snapshot-section-invalid", device = device, section = section),
        };
        Error::usage(m).cause(e).hint(msg!("snapshot-file-damaged"))
    })
}

/// The path (`inputs[0].Encoder.track.dur`) of the value in `v` that decoding as `T` stops
/// at: `v` written out one value a line, decoded again, and the keys above the line the
/// decoder names collected by indentation.
fn failing_field<T: serde::de::DeserializeOwned>(v: &serde_json::Value) -> Option<String> {
    let text = serde_json::to_string_pretty(v).ok()?;
    let e = serde_json::from_str::<T>(&text).err()?;
    let lines: Vec<&str> = text.lines().take(e.line()).collect();
    let (last, above) = lines.split_last()?;
    let indent = |l: &str| l.len() - l.trim_start().len();
    let closing = |l: &str| l.trim_start().starts_with(['}', ']']);
    let mut parts: Vec<String> = Vec::new();
    // Counting the array elements before the one on the path, while inside an array.
    let mut element: Option<usize> = None;
    let mut level = indent(last);
    match json_key(last) {
        Some(k) => parts.push(k),
        None if closing(last) => level += 1,
        None => element = Some(0),
    }
    for l in above.iter().rev() {
        let i = indent(l);
        if i == level {
            if let Some(n) = element.as_mut().filter(|_| !closing(l)) {
                *n += 1;
            }
            continue;
        }
        if i > level {
            continue;
        }
        if let Some(n) = element.take() {
            parts.push(format!("[{n}]"));
        }
        level = i;
        match json_key(l) {
            Some(k) => parts.push(k),
            None => element = Some(0),
        }
    }
    let mut path = String::new();
    for p in parts.iter().rev() {
        if !path.is_empty() && !p.starts_with('[') {
            path.push('.');
        }
        path.push_str(p);
    }
    (!path.is_empty()).then_some(path)
}

/// The key of a pretty-printed `"key": value` line.
fn json_key(line: &str) -> Option<String> {
    let t = line.trim_start();
    let body = t.strip_prefix('"')?;
    let mut escaped = false;
    let end = body.char_indices().find_map(|(i, c)| match (escaped, c) {
        (false, '\\') => {
            escaped = true;
            None
        }
        (false, '"') => Some(i),
        _ => {
            escaped = false;
            None
        }
    })?;
    body[end + 1..].starts_with(':').then(|| serde_json::from_str(&t[..end + 2]).ok()).flatten()
}

/// The first place two JSON values differ, as a path (`""` for the top).
fn first_difference(a: &serde_json::Value, b: &serde_json::Value) -> Option<String> {
    use serde_json::Value as V;
    match (a, b) {
        (V::Object(x), V::Object(y)) => {
            for (k, va) in x {
                match y.get(k) {
                    Some(vb) => {
                        if let Some(p) = first_difference(va, vb) {
                            return Some(if p.is_empty() || p.starts_with('[') {
                                format!("{k}{p}")
                            } else {
                                format!("{k}.{p}")
                            });
                        }
                    }
                    None => return Some(k.clone()),
                }
            }
            y.keys().find(|k| !x.contains_key(*k)).cloned()
        }
        (V::Array(x), V::Array(y)) if x.len() == y.len() => x.iter().zip(y).enumerate().find_map(|(i, (va, vb))| {
            first_difference(va, vb).map(|p| {
                if p.is_empty() || p.starts_with('[') {
                    format!("[{i}]{p}")
                } else {
                    format!("[{i}].{p}")
                }
            })
        }),
        _ => (a != b).then(String::new),
    }
}

/// The sections this plcsh knows, per family.
const KNOWN: &[(&str, &str)] = &[("k2", "k2"), ("k2", "wiring"), ("servo", "servo"), ("fx", "fx"), ("umpk", "umpk")];

/// The simulated UMPK behind a device, if it is one (`sim-umpk:`).
fn umpk_sim(
    dev: &mut Box<dyn crate::core::Device>,
) -> Option<std::sync::Arc<std::sync::Mutex<crate::umpk::sim::Umpk>>> {
    crate::umpk::ops(dev.as_mut(), &[]).ok()??.simulator()
}

/// The simulated FX PLC behind a device, if it is one (`sim-fx:`).
fn fx_sim(dev: &mut Box<dyn crate::core::Device>) -> Option<crate::fx::sim::Plc> {
    crate::fx::driver::simulator(dev.as_mut())
}

/// One wire in a snapshot's `wiring` section.
#[derive(Clone, Debug, Serialize, Deserialize)]
pub struct WireSnap {
    /// The declaration, as `sim wire` takes it.
    pub decl: String,
    pub state: crate::wiring::WireState,
}

/// One device's sections, decoded into the states they restore.
#[derive(Default)]
struct Sections {
    k2: Option<crate::k2::sim::snapshot::K2State>,
    wiring: Option<Vec<WireSnap>>,
    servo: Option<Vec<crate::servo::sim::drive::Drive>>,
    fx: Option<crate::fx::snapshot::FxState>,
    umpk: Option<crate::umpk::sim::snapshot::UmpkState>,
}

impl Sections {
    /// Decodes every section of `d` ([`Snapshot::check`] refused unknown ones).
    fn decode(name: &str, d: &DeviceSnap) -> Result<Sections> {
        let mut s = Sections::default();
        for (section, v) in &d.sections {
            match section.as_str() {
                "k2" => s.k2 = Some(dec(v, name, section)?),
                "wiring" => s.wiring = Some(dec(v, name, section)?),
                "servo" => s.servo = Some(dec(v, name, section)?),
                "fx" => s.fx = Some(dec(v, name, section)?),
                "umpk" => s.umpk = Some(dec(v, name, section)?),
                _ => {}
            }
        }
        for w in s.wiring.iter().flatten() {
            crate::wiring::parse(&w.decl).map_err(|e| e.cause(msg!("snapshot-wire-of", name = name)))?;
        }
        Ok(s)
    }

    /// The sections again, as JSON.
    fn encode(&self) -> Result<BTreeMap<String, serde_json::Value>> {
        let mut out = BTreeMap::new();
        if let Some(x) = &self.k2 {
            out.insert("k2".to_string(), enc(x)?);
        }
        if let Some(x) = &self.wiring {
            out.insert("wiring".to_string(), enc(x)?);
        }
        if let Some(x) = &self.servo {
            out.insert("servo".to_string(), enc(x)?);
        }
        if let Some(x) = &self.fx {
            out.insert("fx".to_string(), enc(x)?);
        }
        if let Some(x) = &self.umpk {
            out.insert("umpk".to_string(), enc(x)?);
        }
        Ok(out)
    }
}

/// Brings every simulator to now before a capture: the drives, then the PLCs (whose wires
/// read the drives), twice. A simulator works lazily — a drive handles what happened since
/// it was last asked; a PLC's wire keeps a drive's plan while it holds and skips asking
/// while nothing can happen; a pulse output that ended reaches its drive as the PLC's step
/// ends, after its wires were read — so without this the same machine could save
/// different (equivalent) files, and a restored one, asked afresh, would not save the file
/// it came from. The second pass lets the wires read what the first one's outputs did; no
/// virtual time passes.
fn settle(s: &mut Session) {
    // The instant in seconds as a drive's line and as a PLC's wires work it out (from the
    // clock's seconds and nanoseconds, from nanoseconds): they can differ in the last bit,
    // and a drive keeps the later time it was brought to.
    let now = s.clock.now();
    let now = now.as_secs_f64().max(now.as_nanos() as f64 / 1e9);
    for _ in 0..2 {
        for i in 0..s.entries().len() {
            if let Some(line) = crate::servo::simulator(s.entry(i).device.as_mut()) {
                let mut line = line.lock().unwrap_or_else(|p| p.into_inner());
                for id in line.ids() {
                    if let Some(d) = line.drive(id) {
                        d.advance(now);
                    }
                }
            }
        }
        for i in 0..s.entries().len() {
            if let Some(sim) = crate::k2::simulator(s.entry(i).device.as_mut()) {
                sim.advance();
            }
        }
    }
}

/// The wires a simulated PLC hosts, with their state. Every field of a wire and of the
/// harness is named (no `..`): one added does not compile until it is saved or named.
fn capture_wiring(sim: &crate::k2::sim::K2Sim) -> Vec<WireSnap> {
    let Some(h) = sim.wiring.as_ref() else { return Vec::new() };
    // The peers are the session's devices, found again by name when the wires are declared.
    let crate::core::wiring::Harness { peers: _, wires } = h.as_ref();
    wires
        .iter()
        .map(|w| {
            // The kind and the peer follow from the declaration (`sim wire` makes them again).
            let crate::core::wiring::Wire { decl, kind: _, peer: _, state } = w;
            WireSnap { decl: decl.to_string(), state: state.clone() }
        })
        .collect()
}

impl Snapshot {
    /// Captures every simulator in the session (real devices have no simulated state).
    pub fn capture(s: &mut Session) -> Result<Snapshot> {
        let clock = s.clock.clone();
        settle(s);
        let mut devices = BTreeMap::new();
        for i in 0..s.entries().len() {
            let e = s.entry(i);
            let name = e.name.clone();
            let dev = &mut e.device;
            if let Some(sim) = crate::k2::simulator(dev.as_mut()) {
                let mut sections = BTreeMap::new();
                sections.insert("k2".to_string(), enc(sim.snapshot_state())?);
                let wires = capture_wiring(sim);
                if !wires.is_empty() {
                    sections.insert("wiring".to_string(), enc(wires)?);
                }
                devices.insert(name, DeviceSnap { family: "k2".into(), sections });
            } else if let Some(line) = crate::servo::simulator(dev.as_mut()) {
                let line = line.lock().unwrap_or_else(|p| p.into_inner());
                let mut sections = BTreeMap::new();
                sections.insert("servo".to_string(), enc(line.save_drives())?);
                devices.insert(name, DeviceSnap { family: "servo".into(), sections });
            } else if let Some(plc) = fx_sim(dev) {
                let st = plc.lock().unwrap_or_else(|p| p.into_inner()).snapshot_state();
                let mut sections = BTreeMap::new();
                sections.insert("fx".to_string(), enc(st)?);
                devices.insert(name, DeviceSnap { family: "fx".into(), sections });
            } else if let Some(u) = umpk_sim(dev) {
                let st = u.lock().unwrap_or_else(|p| p.into_inner()).snapshot_state().map_err(|why| {
                    Error::unsupported(msg!("snapshot-cannot-snapshot", name = name.as_str(), why = why.to_string()))
                        .hint(msg!("snapshot-all-or-none"))
                })?;
                let mut sections = BTreeMap::new();
                sections.insert("umpk".to_string(), enc(st)?);
                devices.insert(name, DeviceSnap { family: "umpk".into(), sections });
            } else if dev.info().simulated {
                let family = dev.info().family;
                return Err(Error::unsupported(msg!(
                    "snapshot-family-not-kept",
                    name = name.as_str(),
                    family = family
                ))
                .hint(msg!("snapshot-family-not-kept-hint")));
            }
        }
        if devices.is_empty() {
            return Err(Error::usage(msg!("snapshot-nothing")).hint(msg!("snapshot-nothing-hint")));
        }
        Ok(Snapshot {
            format: FORMAT.into(),
            version: VERSION,
            clock_us: clock.now().as_micros() as u64,
            stepped: clock.is_stepped(),
            devices,
        })
    }

    /// Restores onto the session's devices of the same names.
    pub fn restore(&self, s: &mut Session) -> Result<()> {
        self.check()?;
        // Check that every device is there and of its family first.
        for (name, d) in &self.devices {
            let i = s.index(name).map_err(|e| e.cause(msg!("snapshot-has-device")))?;
            let dev = &mut s.entry(i).device;
            let ok = match d.family.as_str() {
                "k2" => crate::k2::simulator(dev.as_mut()).is_some(),
                "servo" => crate::servo::simulator(dev.as_mut()).is_some(),
                "fx" => fx_sim(dev).is_some(),
                "umpk" => umpk_sim(dev).is_some(),
                _ => false,
            };
            if !ok {
                return Err(Error::usage(msg!("snapshot-not-simulated", name = name, family = d.family.as_str()))
                    .hint(msg!("snapshot-not-simulated-hint")));
            }
        }
        // Decode every section and check the models before anything changes.
        let mut k2 = Vec::new();
        let mut servo = Vec::new();
        let mut fx = Vec::new();
        let mut umpk = Vec::new();
        let mut wiring: Vec<(usize, String, Vec<WireSnap>)> = Vec::new();
        for (name, d) in &self.devices {
            let i = s.index(name)?;
            let sections = Sections::decode(name, d)?;
            if let Some(st) = sections.k2 {
                let sim = crate::k2::simulator(s.entry(i).device.as_mut()).expect("checked above");
                if st.model != sim.model().name {
                    return Err(model_differs(name, &st.model, sim.model().name, "sim"));
                }
                k2.push((i, name, st));
                let wires = sections.wiring.unwrap_or_default();
                // Version 1 did not save wires: its PLCs keep theirs.
                if self.version >= 2 {
                    wiring.push((i, name.clone(), wires));
                }
            }
            if let Some(drives) = sections.servo {
                servo.push((i, drives));
            }
            if let Some(st) = sections.fx {
                let plc = fx_sim(&mut s.entry(i).device).expect("checked above");
                let model = plc.lock().unwrap_or_else(|p| p.into_inner()).model.name;
                if st.model != model {
                    return Err(model_differs(name, &st.model, model, "sim-fx"));
                }
                fx.push((i, name, st));
            }
            if let Some(st) = sections.umpk {
                let u = umpk_sim(&mut s.entry(i).device).expect("checked above");
                let model = u.lock().unwrap_or_else(|p| p.into_inner()).model.name;
                if st.model != model {
                    return Err(model_differs(name, &st.model, model, "sim-umpk"));
                }
                umpk.push((i, name, st));
            }
        }
        // Wires first: declaring one touches the PLC and the drive, whose saved states follow.
        for (i, name, wires) in &wiring {
            let sim = crate::k2::simulator(s.entry(*i).device.as_mut()).expect("checked above");
            if sim.wiring.as_ref().is_some_and(|h| !h.wires.is_empty()) {
                sim.unwire("all")?;
            }
            for w in wires {
                crate::wiring::setup::wire(s, &w.decl).map_err(|e| {
                    e.cause(msg!("snapshot-restoring-wire", name = name.as_str(), wire = w.decl.as_str()))
                })?;
            }
        }
        s.clock.set(Duration::from_micros(self.clock_us));
        for (i, name, st) in k2 {
            let sim = crate::k2::simulator(s.entry(i).device.as_mut()).expect("checked above");
            sim.restore_snapshot(&st)
                .map_err(|m| Error::usage(msg!("snapshot-cannot-restore", name = name, why = m.to_string())))?;
        }
        for (i, drives) in servo {
            let line = crate::servo::simulator(s.entry(i).device.as_mut()).expect("checked above");
            line.lock().unwrap_or_else(|p| p.into_inner()).restore_drives(drives);
        }
        for (i, name, st) in fx {
            let plc = fx_sim(&mut s.entry(i).device).expect("checked above");
            let mut m = plc.lock().unwrap_or_else(|p| p.into_inner());
            m.restore_state(&st)
                .map_err(|e| Error::usage(msg!("snapshot-cannot-restore", name = name, why = e.to_string())))?;
        }
        for (i, name, st) in umpk {
            let u = umpk_sim(&mut s.entry(i).device).expect("checked above");
            let mut m = u.lock().unwrap_or_else(|p| p.into_inner());
            m.restore_snapshot(&st)
                .map_err(|e| Error::usage(msg!("snapshot-cannot-restore", name = name, why = e.to_string())))?;
        }
        for (i, name, wires) in wiring {
            let sim = crate::k2::simulator(s.entry(i).device.as_mut()).expect("checked above");
            let h = sim.wiring.get_or_insert_with(Default::default);
            if h.wires.len() != wires.len() {
                return Err(Error::state(msg!("snapshot-wires-not-back", name = name)));
            }
            for (w, saved) in h.wires.iter_mut().zip(wires) {
                w.state = saved.state;
            }
        }
        Ok(())
    }

    /// The format, version and sections are ones this plcsh can restore.
    fn check(&self) -> Result<()> {
        if self.format != FORMAT {
            return Err(Error::usage(msg!("snapshot-not-format", format = self.format.as_str())));
        }
        if self.version > VERSION {
            return Err(Error::usage(msg!("snapshot-newer-version", version = self.version, max = VERSION))
                .hint(msg!("snapshot-newer-version-hint")));
        }
        for (name, d) in &self.devices {
            for section in d.sections.keys() {
                if !KNOWN.iter().any(|(f, s)| *f == d.family && s == section) {
                    return Err(Error::usage(msg!("snapshot-unknown-section", name = name, section = section))
                        .hint(msg!("snapshot-unknown-section-hint")));
                }
            }
        }
        Ok(())
    }

    /// Writes the snapshot to `path` (atomically: a crash leaves the old file or the new),
    /// after checking that it reads back ([`Self::encode`]): a file is never written that
    /// could not be restored.
    pub fn save(&self, path: &Path) -> Result<()> {
        let text = self.encode()?;
        crate::core::durable::write_atomic(path, text.as_bytes())
    }

    /// The file's text, checked by reading it back as [`Self::load`] and [`Self::restore`]
    /// will: every section must decode into the state it restores, and that state must
    /// encode to the same JSON (nothing changed or lost on the way, non-finite numbers
    /// included). Otherwise the save is refused, naming the device, the section and the
    /// value.
    pub fn encode(&self) -> Result<String> {
        let text = serde_json::to_string(self).map_err(|e| Error::io(msg!("snapshot-cannot-encode")).cause(e))?;
        let refuse = |what: String| {
            Error::state(msg!("snapshot-save-refused", why = what)).hint(msg!("snapshot-save-refused-hint"))
        };
        let back: Snapshot = serde_json::from_str(&text)
            .map_err(|e| refuse(msg!("snapshot-does-not-read-back", error = e.to_string()).into()))?;
        back.check().map_err(|e| refuse(e.message.clone()))?;
        for (name, d) in &back.devices {
            let sections = Sections::decode(name, d).map_err(|e| {
                let cause = e.causes.first().map(|c| format!(" ({c})")).unwrap_or_default();
                refuse(format!("{}{cause}", e.message))
            })?;
            let again = sections.encode()?;
            for (section, v) in &d.sections {
                let Some(w) = again.get(section) else { continue };
                if let Some(at) = first_difference(v, w) {
                    return Err(refuse(
                        msg!("snapshot-section-changes", name = name, section = section, at = at).into(),
                    ));
                }
            }
        }
        Ok(text)
    }

    pub fn load(path: &Path) -> Result<Snapshot> {
        let text = std::fs::read_to_string(path).map_err(|e| {
            Error::io(msg!("snapshot-cannot-read", path = path.display().to_string()))
                .cause(e)
                .hint(msg!("snapshot-cannot-read-hint"))
        })?;
        let s: Snapshot = serde_json::from_str(&text)
            .map_err(|e| Error::usage(msg!("snapshot-not-snapshot", path = path.display().to_string())).cause(e))?;
        s.check()?;
        Ok(s)
    }

    /// Restores the K2 section of the only (or first) K2 device onto `sim` (replay).
    pub fn restore_k2(&self, sim: &mut crate::k2::sim::K2Sim) -> Result<()> {
        let v = self
            .devices
            .values()
            .find_map(|d| d.sections.get("k2"))
            .ok_or_else(|| Error::usage(msg!("snapshot-no-k2")))?;

        let st: crate::k2::sim::snapshot::K2State = dec(v, "plc", "k2")?;
        sim.clock.set(Duration::from_micros(self.clock_us));
        sim.restore_snapshot(&st).map_err(Error::usage)
    }
}

/// The directory named snapshots live in (`PLCSH_SNAPSHOTS` overrides).
pub fn dir() -> Option<PathBuf> {
    crate::paths::snapshots()
}

/// The file of snapshot `name` ([`crate::paths::snapshot_file`]: a path when it has a path
/// separator of this system, a drive letter or ends in `.json`, else a named snapshot).
pub fn locate(name: &str) -> Result<PathBuf> {
    crate::paths::snapshot_file(name)
}

/// Named snapshots: `(name, file)`, sorted.
pub fn list() -> Vec<(String, PathBuf)> {
    let Some(d) = dir() else { return Vec::new() };
    let mut out: Vec<(String, PathBuf)> = std::fs::read_dir(&d)
        .into_iter()
        .flatten()
        .flatten()
        .filter_map(|e| {
            let p = e.path();
            let name = p.file_name()?.to_str()?.strip_suffix(".json")?.to_string();
            (!name.starts_with('.')).then_some((name, p))
        })
        .collect();
    out.sort();
    out
}

/// The refusal to restore a saved `saved` into `name`, a simulator of `model` opened with
/// `scheme` (`sim`, `sim-fx`, `sim-umpk`), and how to open the right one. The English article
/// goes with how the family's name is said ("an FX3U", "a K205", "a UMPK").
fn model_differs(name: &str, saved: &str, model: &str, scheme: &str) -> Error {
    let article = if scheme == "sim-fx" { "an" } else { "a" };
    Error::usage(msg!("snapshot-model-differs", name = name, saved = saved, model = model, article = article))
        .hint(msg!("snapshot-open-as", name = name, scheme = scheme, model = saved))
}

#[cfg(test)]
mod tests {
    #[test]
    fn a_name_with_this_systems_separator_or_a_drive_is_a_path() {
        assert_eq!(locate("dir/s1").unwrap(), PathBuf::from("dir/s1"));
        let name = format!("snaps{}before", std::path::MAIN_SEPARATOR);
        assert_eq!(locate(&name).unwrap(), PathBuf::from(&name), "C:\\snaps\\before on Windows");
        assert!(locate("before").unwrap().ends_with("before.json"), "a bare name is a named snapshot");
    }

    use super::*;
    use crate::core::Clock;

    /// The wired bench (`machines/pto_servo_encoder.toml`) at rest after 10 ms: its encoder
    /// signals are stretches that never end (duration +∞).
    fn wired_bench() -> Session {
        let mut s = Session::new(Clock::stepped());
        let path = Path::new(env!("CARGO_MANIFEST_DIR")).join("machines/pto_servo_encoder.toml");
        crate::wiring::bench::open(&mut s, &crate::wiring::bench::Bench::load(&path).unwrap()).unwrap();
        s.clock.step(Duration::from_millis(10));
        s
    }

    /// A machine at rest holds endless stretches; its snapshot encodes them, reads back and
    /// restores onto a fresh bench, and that one saves the same text.
    #[test]
    fn a_wired_machine_at_rest_saves_a_file_that_restores() {
        let mut s = wired_bench();
        let snap = Snapshot::capture(&mut s).unwrap();
        let text = snap.encode().unwrap();
        assert!(text.contains(r#""dur":"inf""#), "an endless stretch is saved as a word: {text}");
        let back: Snapshot = serde_json::from_str(&text).unwrap();
        let mut fresh = wired_bench();
        fresh.clock.step(Duration::from_millis(123));
        back.restore(&mut fresh).unwrap();
        assert_eq!(Snapshot::capture(&mut fresh).unwrap().encode().unwrap(), text);
    }

    /// A value that would not read back (here: the `null` JSON has for a NaN) refuses the
    /// save, naming the device, the section and the value's path.
    #[test]
    fn a_value_that_would_not_read_back_refuses_the_save_by_name() {
        let mut snap = Snapshot::capture(&mut wired_bench()).unwrap();
        let k2 = snap.devices.get_mut("plc").unwrap().sections.get_mut("k2").unwrap();
        k2["inputs"][0]["Encoder"]["track"]["x0"] = serde_json::Value::Null;
        let e = snap.encode().unwrap_err();
        let m = e.to_string();
        assert!(m.contains("cannot save the snapshot"), "{m}");
        assert!(m.contains("`plc`'s k2 section") && m.contains("at `inputs[0].Encoder.track.x0`"), "{m}");
        assert!(m.contains("invalid type: null"), "{m}");
        assert!(e.hint.as_deref().unwrap_or("").contains("nothing was written"), "{e:?}");
        let file = std::env::temp_dir().join(format!("plcsh-unreadable-{}.json", std::process::id()));
        assert!(snap.save(&file).is_err());
        assert!(!file.exists(), "no file is written");
        // A value that decodes but changes on the way is refused too.
        let mut snap = Snapshot::capture(&mut wired_bench()).unwrap();
        let servo = snap.devices.get_mut("servo").unwrap().sections.get_mut("servo").unwrap();
        servo[0]["surplus"] = serde_json::json!(1);
        let m = snap.encode().unwrap_err().to_string();
        assert!(m.contains("`servo`'s servo section does not read back as saved: `[0].surplus` changes"), "{m}");
    }

    #[test]
    fn the_failing_value_is_found_by_its_path() {
        #[derive(Debug, serde::Deserialize)]
        #[allow(dead_code)]
        struct Inner {
            x: f64,
            tag: String,
        }
        #[derive(Debug, serde::Deserialize)]
        #[allow(dead_code)]
        struct Outer {
            name: String,
            list: Vec<Inner>,
            nums: Vec<u8>,
        }
        let path = |v: serde_json::Value| failing_field::<Outer>(&v);
        let ok = serde_json::json!({"name": "a", "list": [{"x": 1, "tag": "{\"k\": 1}"}], "nums": [1, 2]});
        assert_eq!(path(ok.clone()), None);
        let mut v = ok.clone();
        v["list"] = serde_json::json!([{"x": 1, "tag": "p"}, {"x": 2, "tag": "q"}, {"x": null, "tag": "r"}]);
        assert_eq!(path(v).as_deref(), Some("list[2].x"));
        let mut v = ok.clone();
        v["nums"] = serde_json::json!([1, 2, 3, 300]);
        assert_eq!(path(v).as_deref(), Some("nums[3]"));
        let mut v = ok.clone();
        v["list"] = serde_json::json!([{"x": 1}]);
        assert_eq!(path(v).as_deref(), Some("list[0]"), "a missing field: the object that lacks it");
        let mut v = ok;
        v["name"] = serde_json::json!(5);
        assert_eq!(path(v).as_deref(), Some("name"));
    }
}
