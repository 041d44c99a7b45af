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
//! Named snapshots live in the user's data directory (`…/plcsh/snapshots/NAME.json`);
//! a NAME with a `/` or ending in `.json` is a file path.

use crate::core::{Error, Result};
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
    serde_json::to_value(v).map_err(|e| Error::io("cannot encode the snapshot").cause(e))
}

fn dec<T: serde::de::DeserializeOwned>(v: &serde_json::Value, what: &str) -> Result<T> {
    serde_json::from_value(v.clone()).map_err(|e| {
        Error::usage(format!("the snapshot's {what} section is not valid")).cause(e).hint("the file may be damaged")
    })
}

/// The sections this plcsh knows, per family.
const KNOWN: &[(&str, &str)] = &[("k2", "k2"), ("k2", "wiring"), ("servo", "servo"), ("fx", "fx"), ("umpk", "umpk")];

/// The simulated UMPK behind a device, if it is one (`sim-umpk:`).
fn umpk_sim(
    dev: &mut Box<dyn crate::core::Device>,
) -> Option<std::sync::Arc<std::sync::Mutex<crate::umpk::sim::Umpk>>> {
    let ops = dev.family_ops_for(&[]).ok().flatten()?;
    ops.downcast_mut::<crate::umpk::driver::Driver>()?.simulator()
}

/// The simulated FX PLC behind a device, if it is one (`sim-fx:`).
fn fx_sim(dev: &mut Box<dyn crate::core::Device>) -> Option<crate::fx::sim::Plc> {
    let ops = dev.family_ops_for(&[]).ok().flatten()?;
    ops.downcast_mut::<crate::fx::driver::Driver>()?.sim.clone()
}

/// One wire in a snapshot's `wiring` section.
#[derive(Clone, Debug, Serialize, Deserialize)]
pub struct WireSnap {
    /// The declaration, as `sim wire` takes it.
    pub decl: String,
    pub state: crate::wiring::WireState,
}

/// The wires a simulated PLC hosts, with their state.
fn capture_wiring(sim: &crate::k2::sim::K2Sim) -> Vec<WireSnap> {
    sim.wiring
        .as_ref()
        .map(|h| h.wires.iter().map(|w| WireSnap { decl: w.decl.to_string(), state: w.state.clone() }).collect())
        .unwrap_or_default()
}

impl Snapshot {
    /// Captures every simulator in the session (real devices have no simulated state).
    pub fn capture(s: &mut Session) -> Result<Snapshot> {
        let clock = s.clock.clone();
        let mut devices = BTreeMap::new();
        for i in 0..s.entries().len() {
            let e = s.entry(i);
            let name = e.name.clone();
            let dev = &mut e.device;
            if let Some(sim) = dev.as_k2().and_then(|k| k.as_sim()) {
                sim.advance();
                let mut sections = BTreeMap::new();
                sections.insert("k2".to_string(), enc(sim.snapshot_state())?);
                let wires = capture_wiring(sim);
                if !wires.is_empty() {
                    sections.insert("wiring".to_string(), enc(wires)?);
                }
                devices.insert(name, DeviceSnap { family: "k2".into(), sections });
            } else if let Some(line) = dev.as_servo().and_then(|sv| sv.simulator()) {
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
                    Error::unsupported(format!("cannot snapshot `{name}`: {why}"))
                        .hint("a snapshot holds every simulated device or none")
                })?;
                let mut sections = BTreeMap::new();
                sections.insert("umpk".to_string(), enc(st)?);
                devices.insert(name, DeviceSnap { family: "umpk".into(), sections });
            } else if dev.info().simulated {
                let family = dev.info().family;
                return Err(Error::unsupported(format!(
                    "cannot snapshot `{name}`: a simulated {family} device's state is not kept in snapshots"
                ))
                .hint("close it before saving, or save without it"));
            }
        }
        if devices.is_empty() {
            return Err(Error::usage("no simulated device is open: nothing to snapshot").hint(
                "snapshots hold simulator state (sim:MODEL, sim-servo:, sim-fx:, sim-umpk:); a real device's state is its own",
            ));
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
            let i = s.index(name).map_err(|e| e.cause("the snapshot has this device"))?;
            let dev = &mut s.entry(i).device;
            let ok = match d.family.as_str() {
                "k2" => dev.as_k2().and_then(|k| k.as_sim()).is_some(),
                "servo" => dev.as_servo().and_then(|sv| sv.simulator()).is_some(),
                "fx" => fx_sim(dev).is_some(),
                "umpk" => umpk_sim(dev).is_some(),
                _ => false,
            };
            if !ok {
                return Err(Error::usage(format!(
                    "`{name}` is not a simulated {} device, as it was when the snapshot was saved",
                    d.family
                ))
                .hint("open the same simulators under the same names (e.g. --device plc=sim:MODEL)"));
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
            if let Some(v) = d.sections.get("k2") {
                let st: crate::k2::sim::snapshot::K2State = dec(v, "k2")?;
                let sim = s.entry(i).device.as_k2().and_then(|k| k.as_sim()).expect("checked above");
                if st.model != sim.model().name {
                    return Err(Error::usage(format!(
                        "cannot restore `{name}`: the snapshot is of a {}, this simulator is a {}",
                        st.model,
                        sim.model().name
                    ))
                    .hint(format!("open it as {name}=sim:{}", st.model)));
                }
                k2.push((i, name, st));
                let wires: Vec<WireSnap> = match d.sections.get("wiring") {
                    Some(v) => dec(v, "wiring")?,
                    None => Vec::new(),
                };
                for w in &wires {
                    crate::wiring::parse(&w.decl).map_err(|e| e.cause("a wire in the snapshot"))?;
                }
                // Version 1 did not save wires: its PLCs keep theirs.
                if self.version >= 2 {
                    wiring.push((i, name.clone(), wires));
                }
            }
            if let Some(v) = d.sections.get("servo") {
                let drives: Vec<crate::servo::sim::drive::Drive> = dec(v, "servo")?;
                servo.push((i, drives));
            }
            if let Some(v) = d.sections.get("fx") {
                let st: crate::fx::snapshot::FxState = dec(v, "fx")?;
                let plc = fx_sim(&mut s.entry(i).device).expect("checked above");
                let model = plc.lock().unwrap_or_else(|p| p.into_inner()).model.name;
                if st.model != model {
                    return Err(Error::usage(format!(
                        "cannot restore `{name}`: the snapshot is of an {}, this simulator is an {model}",
                        st.model
                    ))
                    .hint(format!("open it as {name}=sim-fx:{}", st.model)));
                }
                fx.push((i, name, st));
            }
            if let Some(v) = d.sections.get("umpk") {
                let st: crate::umpk::sim::snapshot::UmpkState = dec(v, "umpk")?;
                let u = umpk_sim(&mut s.entry(i).device).expect("checked above");
                let model = u.lock().unwrap_or_else(|p| p.into_inner()).model.name;
                if st.model != model {
                    return Err(Error::usage(format!(
                        "cannot restore `{name}`: the snapshot is of a {}, this simulator is a {model}",
                        st.model
                    ))
                    .hint(format!("open it as {name}=sim-umpk:{}", st.model)));
                }
                umpk.push((i, name, st));
            }
        }
        // Wires first: declaring one touches the PLC and the drive, whose saved states follow.
        for (i, name, wires) in &wiring {
            let sim = s.entry(*i).device.as_k2().and_then(|k| k.as_sim()).expect("checked above");
            if sim.wiring.as_ref().is_some_and(|h| !h.wires.is_empty()) {
                sim.unwire("all")?;
            }
            for w in wires {
                crate::wiring::setup::wire(s, &w.decl)
                    .map_err(|e| e.cause(format!("restoring `{name}`'s wire `{}`", w.decl)))?;
            }
        }
        s.clock.set(Duration::from_micros(self.clock_us));
        for (i, name, st) in k2 {
            let sim = s.entry(i).device.as_k2().and_then(|k| k.as_sim()).expect("checked above");
            sim.restore_snapshot(&st).map_err(|m| Error::usage(format!("cannot restore `{name}`: {m}")))?;
        }
        for (i, drives) in servo {
            let line = s.entry(i).device.as_servo().and_then(|sv| sv.simulator()).expect("checked above");
            line.lock().unwrap_or_else(|p| p.into_inner()).restore_drives(drives);
        }
        for (i, name, st) in fx {
            let plc = fx_sim(&mut s.entry(i).device).expect("checked above");
            let mut m = plc.lock().unwrap_or_else(|p| p.into_inner());
            m.restore_state(&st).map_err(|e| Error::usage(format!("cannot restore `{name}`: {e}")))?;
        }
        for (i, name, st) in umpk {
            let u = umpk_sim(&mut s.entry(i).device).expect("checked above");
            let mut m = u.lock().unwrap_or_else(|p| p.into_inner());
            m.restore_snapshot(&st).map_err(|e| Error::usage(format!("cannot restore `{name}`: {e}")))?;
        }
        for (i, name, wires) in wiring {
            let sim = s.entry(i).device.as_k2().and_then(|k| k.as_sim()).expect("checked above");
            let h = sim.wiring.get_or_insert_with(Default::default);
            if h.wires.len() != wires.len() {
                return Err(Error::state(format!("restoring `{name}`: its wires did not come back as saved")));
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
            return Err(Error::usage(format!("not a plcsh snapshot (format `{}`)", self.format)));
        }
        if self.version > VERSION {
            return Err(Error::usage(format!(
                "the snapshot is version {}, this plcsh reads up to version {VERSION}",
                self.version
            ))
            .hint("restore it with the newer plcsh that saved it"));
        }
        for (name, d) in &self.devices {
            for section in d.sections.keys() {
                if !KNOWN.iter().any(|(f, s)| *f == d.family && s == section) {
                    return Err(Error::usage(format!(
                        "the snapshot's `{name}` has a `{section}` section this plcsh cannot restore"
                    ))
                    .hint("it was saved by a newer plcsh; restoring without it would not give the same state"));
                }
            }
        }
        Ok(())
    }

    /// Writes the snapshot to `path` (atomically: a crash leaves the old file or the new).
    pub fn save(&self, path: &Path) -> Result<()> {
        let text = serde_json::to_string(self).map_err(|e| Error::io("cannot encode the snapshot").cause(e))?;
        crate::core::durable::write_atomic(path, text.as_bytes())
    }

    pub fn load(path: &Path) -> Result<Snapshot> {
        let text = std::fs::read_to_string(path).map_err(|e| {
            Error::io(format!("cannot read the snapshot {}", path.display()))
                .cause(e)
                .hint("list saved snapshots with `sim snapshots`")
        })?;
        let s: Snapshot = serde_json::from_str(&text)
            .map_err(|e| Error::usage(format!("{} is not a plcsh snapshot", path.display())).cause(e))?;
        s.check()?;
        Ok(s)
    }

    /// Restores the K2 section of the only (or first) K2 device onto `sim` (replay).
    pub fn restore_k2(&self, sim: &mut crate::k2::sim::K2Sim) -> Result<()> {
        let v = self
            .devices
            .values()
            .find_map(|d| d.sections.get("k2"))
            .ok_or_else(|| Error::usage("the snapshot holds no simulated K2"))?;
        let st: crate::k2::sim::snapshot::K2State = dec(v, "k2")?;
        sim.clock.set(Duration::from_micros(self.clock_us));
        sim.restore_snapshot(&st).map_err(Error::usage)
    }
}

/// The directory named snapshots live in (`PLCSH_SNAPSHOTS` overrides).
pub fn dir() -> Option<PathBuf> {
    crate::paths::snapshots()
}

/// The file of snapshot `name` (a path when it has a `/` or ends in `.json`).
pub fn locate(name: &str) -> Result<PathBuf> {
    if name.contains('/') || name.ends_with(".json") {
        return Ok(PathBuf::from(name));
    }
    if name.is_empty() || !name.chars().all(|c| c.is_ascii_alphanumeric() || "_-.".contains(c)) {
        return Err(Error::usage(format!("`{name}` is not a snapshot name (letters, digits, _ - .)"))
            .hint("or give a file path ending in .json"));
    }
    let d =
        dir().ok_or_else(|| Error::io("no data directory for snapshots").hint("give a file path ending in .json"))?;
    Ok(d.join(format!("{name}.json")))
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
