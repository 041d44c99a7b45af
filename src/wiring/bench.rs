//! Bench files: a simulated machine in one TOML file — its devices (simulators and their
//! models), the wiring between them, initial values, and program files — opened with
//! `plcsh --bench FILE` and served whole with `plcsh sim serve --bench FILE`.
//!
//! ```toml
//! name = "PTO axis with encoder feedback"
//! current = "plc"                       # the device commands act on (default: plc)
//!
//! [devices]                             # NAME = URL; simulators only
//! plc = "sim:K205-16DT"
//! servo = "sim-servo:?id=1"
//!
//! wires = [                             # as `sim wire`
//!   "plc:Q0.0 -> servo:pulse",
//!   "servo:encoder -> plc:I0.1,I0.0 lines=1250",
//! ]
//! init = [                              # DEVICE:OPERAND=VALUE, written in order, as `set`
//!   "servo:gear_factor=4",
//!   "servo:operating_mode=-4",
//! ]
//! [programs]                            # DEVICE = FILE (relative to the bench file)
//! plc = "machine.il"
//! [tags]                                # DEVICE = tag file: wires, init and faults may
//! plc = "machine.csv"                   # use its names (docs/tags.md)
//!
//! [[faults]]                            # injected when the bench opens, in order
//! device = "plc"                        # a PLC: the SPEC of `sim fault` / `sim serve --fault`
//! spec = "no-reply on VW100 after=1s times=1"
//! [[faults]]
//! device = "servo"                      # a drive: the words after `servo sim fault`
//! spec = "drive 16#7500 at=20000"       # a drive fault when its position crosses 20000
//! ```
//!
//! One path opens a bench for every front end ([`open`]): devices through the session's
//! URL list, wires through [`super::setup`], values through `Session::set` — so a bench
//! behaves exactly like typing its lines. A bench is a simulated machine: a device URL
//! that opens a real device is refused (a bench never writes to a machine). Program files
//! (IL) are loaded into the simulated K2's scan engine (`k2::sim::program`), as with
//! `sim program load`.

use crate::core::{Error, Result};
use crate::msg;
use crate::servo::ServoOps;
use crate::session::{Session, SetItem};
use serde::Deserialize;
use std::collections::BTreeMap;
use std::path::{Path, PathBuf};

/// A parsed bench file.
#[derive(Debug, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct Bench {
    #[serde(default)]
    pub name: Option<String>,
    #[serde(default)]
    pub current: Option<String>,
    pub devices: BTreeMap<String, String>,
    #[serde(default)]
    pub wires: Vec<String>,
    #[serde(default)]
    pub init: Vec<String>,
    #[serde(default)]
    pub programs: BTreeMap<String, String>,
    #[serde(default)]
    pub faults: Vec<BenchFault>,
    /// DEVICE = tag file (relative to the bench file): the device's names, attached before the
    /// wires, values and faults are read, so those may use them (docs/tags.md).
    #[serde(default)]
    pub tags: BTreeMap<String, String>,
    /// The file's directory (program paths are relative to it).
    #[serde(skip)]
    pub dir: PathBuf,
    #[serde(skip)]
    pub path: PathBuf,
}

/// One `[[faults]]` entry: a fault injected into a device when the bench opens.
#[derive(Debug, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct BenchFault {
    pub device: String,
    pub spec: String,
}

/// Injects `f` into its device: a simulated PLC takes a `sim fault` SPEC, a simulated drive
/// the words after `servo sim fault`. Returns the description.
fn inject(s: &mut Session, f: &BenchFault) -> Result<String> {
    let i = s.index(&f.device)?;
    // The device's tag names in the spec as their operands (`no-reply on Tank_Level`).
    let names = s.names(i);
    let spec: String = if names.is_empty() {
        f.spec.clone()
    } else {
        let words: Vec<&str> = f.spec.split_whitespace().collect();
        words.iter().map(|w| names.get(w).map_or(*w, |n| n.operand.as_str())).collect::<Vec<_>>().join(" ")
    };
    let f = &BenchFault { device: f.device.clone(), spec };
    let dev = &mut s.entry(i).device;
    if let Some(sim) = crate::k2::simulator(dev.as_mut()) {
        let spec =
            crate::k2::sim::fault::parse(&f.spec).map_err(|m| Error::usage(m).hint(crate::k2::sim::fault::USAGE))?;
        sim.advance();
        let now = sim.last;
        sim.faults.add(&spec, now);
        return Ok(sim.faults.list.last().map(|x| x.describe()).unwrap_or_default());
    }
    if let Some(mut servo) = crate::servo::ops(dev.as_mut()) {
        let id = servo.drive_id();
        if let Some(line) = servo.simulator() {
            use crate::servo::sim::control;
            let text = format!("fault {}", f.spec);
            let req = control::parse(&control::words(&text))?;
            let mut l = line.lock().unwrap_or_else(|p| p.into_inner());
            return Ok(control::apply(&mut l, &req, Some(id))?.0);
        }
    }
    Err(Error::unsupported(msg!("bench-no-faults", device = f.device.as_str())))
}

/// Prefixes an error's message with where in the bench it arose.
fn within(mut e: Error, at: String) -> Error {
    e.message = format!("{at}: {}", e.message);
    e
}

fn line_of(text: &str, at: usize) -> usize {
    text[..at.min(text.len())].matches('\n').count() + 1
}

impl Bench {
    /// Parses bench text; `path` names it in messages.
    pub fn parse(text: &str, path: &Path) -> Result<Bench> {
        let mut b: Bench = toml::from_str(text).map_err(|e| {
            let line = e.span().map(|s| format!(":{}", line_of(text, s.start))).unwrap_or_default();
            Error::usage(format!("bench {}{line}: {}", path.display(), e.message())).hint(msg!("bench-shape-hint"))
        })?;
        if b.devices.is_empty() {
            return Err(Error::usage(msg!("bench-no-devices", file = path.display().to_string()))
                .hint("e.g. [devices] plc = \"sim:K205-16DT\""));
        }
        b.path = path.to_path_buf();
        b.dir = path.parent().map(Path::to_path_buf).unwrap_or_default();
        Ok(b)
    }

    /// Reads and parses a bench file.
    pub fn load(path: &Path) -> Result<Bench> {
        let text = std::fs::read_to_string(path)
            .map_err(|e| Error::io(msg!("bench-cannot-read", file = path.display().to_string())).cause(e))?;
        Bench::parse(&text, path)
    }
}

/// Opens `bench` in the session: devices, wires, values, programs. Returns notes for the user.
pub fn open(s: &mut Session, bench: &Bench) -> Result<Vec<String>> {
    let file = bench.path.display().to_string();
    let mut notes = Vec::new();
    for (name, url) in &bench.devices {
        // Refused before anything is opened: a bench never reaches for a real port or address.
        if !url.trim_start().starts_with("sim") {
            return Err(Error::usage(msg!("bench-not-simulator", file = file.as_str(), name = name, url = url))
                .hint(msg!("bench-not-simulator-hint")));
        }
        s.open(name, url).map_err(|e| within(e, msg!("bench-at-device", file = file.as_str(), name = name).into()))?;
        if !s.device(name)?.info().simulated {
            s.close(name)?;
            return Err(Error::usage(msg!("bench-not-simulator", file = file.as_str(), name = name, url = url))
                .hint(msg!("bench-not-simulator-hint")));
        }
    }
    for (dev, file_name) in &bench.tags {
        let at = || crate::msg!("tags-bench-tags", file = file.as_str(), device = dev.as_str()).to_string();
        let i = s.index(dev).map_err(|e| within(e, at()))?;
        s.load_tags(i, &bench.dir.join(file_name)).map_err(|e| within(e, at()))?;
    }
    for (i, w) in bench.wires.iter().enumerate() {
        super::setup::wire(s, w)
            .map_err(|e| within(e, msg!("bench-at-wire", file = file.as_str(), n = i + 1, wire = w).into()))?;
    }
    for (i, item) in bench.init.iter().enumerate() {
        let (op, value) = item.split_once('=').ok_or_else(|| {
            Error::usage(msg!("bench-init-shape", file = file.as_str(), n = i + 1, item = item))
                .hint("e.g. init = [\"servo:gear_factor=4\", \"plc:VW0=100\"]")
        })?;
        let it =
            SetItem { operand: op.trim().to_string(), value: value.trim().to_string(), column: 0, value_column: 0 };
        s.set(&[it])
            .map_err(|e| within(e, msg!("bench-at-init", file = file.as_str(), n = i + 1, item = item).into()))?;
    }
    for (i, f) in bench.faults.iter().enumerate() {
        let what = inject(s, f).map_err(|e| {
            within(e, msg!("bench-at-fault", file = file.as_str(), n = i + 1, fault = f.spec.as_str()).into())
        })?;
        notes.push(msg!("bench-fault-on", device = f.device.as_str(), what = what).into());
    }
    for (dev, prog) in &bench.programs {
        s.index(dev).map_err(|e| within(e, msg!("bench-at-program", file = file.as_str(), device = dev).into()))?;
        let p = bench.dir.join(prog);
        if !p.is_file() {
            return Err(Error::usage(msg!(
                "bench-program-missing",
                file = file.as_str(),
                program = p.display().to_string(),
                device = dev
            )));
        }
        let text = std::fs::read_to_string(&p).map_err(|e| {
            Error::io(msg!(
                "bench-program-unreadable",
                file = file.as_str(),
                program = p.display().to_string(),
                error = e.to_string()
            ))
        })?;
        let i = s.index(dev)?;
        let sim = crate::k2::simulator(s.entry(i).device.as_mut()).ok_or_else(|| {
            Error::usage(msg!("bench-program-not-k2", file = file.as_str(), device = dev))
                .hint(msg!("bench-program-not-k2-hint"))
        })?;
        let msg = sim
            .load_program(&text, &p.display().to_string())
            .map_err(|e| within(e, msg!("bench-at-program", file = file.as_str(), device = dev).into()))?;
        notes.push(format!("{dev}: {msg}"));
    }
    let current = bench.current.clone().unwrap_or_else(|| "plc".to_string());
    if s.index(&current).is_ok() {
        s.use_device(&current)?;
    } else if let Some(first) = bench.devices.keys().next() {
        s.use_device(first)?;
    }
    let name = bench.name.clone().unwrap_or_else(|| file.clone());
    notes.insert(
        0,
        msg!(
            "bench-opened",
            name = name,
            devices = bench.devices.len(),
            wires = bench.wires.len(),
            values = bench.init.len()
        )
        .into(),
    );
    Ok(notes)
}

/// What `sim serve --bench` serves.
pub type ServeParts =
    (Option<crate::k2::sim::K2Sim>, Option<std::sync::Arc<std::sync::Mutex<crate::servo::sim::SimLine>>>, Vec<String>);

/// For `plcsh sim serve --bench FILE`: opens the bench in a session on `clock` (the same path
/// as `--bench`), then takes out the simulated PLC, to be served on Modbus, and the drives'
/// line, to be served on a pty — still wired to each other. A served bench has one PLC and
/// one drive line.
pub fn serve_parts(path: &Path, clock: &crate::core::Clock) -> Result<ServeParts> {
    let bench = Bench::load(path)?;
    let mut s = Session::new(clock.clone());
    let notes = open(&mut s, &bench)?;
    let (mut k2, mut line) = (None, None);
    for i in 0..s.entries().len() {
        let name = s.entries()[i].name.clone();
        let dev = &mut s.entry(i).device;
        if let Some(sim) = crate::k2::simulator(dev.as_mut()) {
            if k2.is_some() {
                return Err(Error::unsupported(msg!(
                    "bench-second-plc",
                    file = path.display().to_string(),
                    name = name.as_str()
                )));
            }
            let fresh = crate::k2::sim::K2Sim::new(sim.model(), clock.clone());
            k2 = Some(std::mem::replace(sim, fresh));
        } else if let Some(l) = crate::servo::simulator(dev.as_mut()) {
            match &line {
                Some(prev) if !std::sync::Arc::ptr_eq(prev, &l) => {
                    return Err(Error::unsupported(msg!(
                        "bench-second-line",
                        file = path.display().to_string(),
                        name = name.as_str()
                    ))
                    .hint(msg!("bench-second-line-hint")))
                }
                _ => line = Some(l),
            }
        }
    }
    Ok((k2, line, notes))
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::core::Clock;

    const BENCH: &str = r#"
name = "axis"
[devices]
plc = "sim:K205-16DT"
servo = "sim-servo:?id=1"
wires = ["plc:Q0.0 -> servo:pulse"]
"#;

    #[test]
    fn a_bench_parses_and_bad_ones_name_file_and_line() {
        // `wires` after [devices] belongs to that table: a device named wires with a list.
        let e = Bench::parse(BENCH, Path::new("m.toml")).unwrap_err();
        assert!(e.to_string().contains("m.toml"), "{e}");
        let good = "wires = [\"plc:Q0.0 -> servo:pulse\"]\ninit = [\"servo:gear_factor=4\"]\n[devices]\nplc = \"sim:K205-16DT\"\nservo = \"sim-servo:?id=1\"\n";
        let b = Bench::parse(good, Path::new("m.toml")).unwrap();
        assert_eq!(b.devices.len(), 2);
        assert_eq!(b.wires.len(), 1);
        let e = Bench::parse("[devices]\nplc = 5\n", Path::new("x.toml")).unwrap_err();
        assert!(e.to_string().contains("x.toml:2"), "{e}");
        assert!(Bench::parse("wire = []\n[devices]\nplc=\"sim:\"\n", Path::new("x")).is_err(), "unknown key");
        assert!(Bench::parse("[devices]\n", Path::new("x")).is_err(), "no devices");
    }

    #[test]
    fn opening_a_bench_wires_and_sets() {
        let text = "wires = [\"plc:Q0.0 -> servo:pulse\"]\ninit = [\"servo:gear_factor=4\", \"plc:VW0=7\"]\n[devices]\nplc = \"sim:K205-16DT\"\nservo = \"sim-servo:?id=1\"\n";
        let b = Bench::parse(text, Path::new("m.toml")).unwrap();
        let mut s = Session::new(Clock::stepped());
        let notes = open(&mut s, &b).unwrap();
        assert!(notes[0].contains("2 device(s), 1 wire(s), 2 value(s)"), "{notes:?}");
        assert_eq!(super::super::setup::list(&mut s).len(), 1);
        let v = s.get(&["plc:VW0", "servo:gear_factor"]).unwrap();
        assert_eq!((v[0].1.value.as_i64(), v[1].1.value.as_i64()), (7, 4));
        let bad = "init = [\"plc:VW0\"]\n[devices]\nplc = \"sim:K205-16DT\"\n";
        let e =
            open(&mut Session::new(Clock::stepped()), &Bench::parse(bad, Path::new("m.toml")).unwrap()).unwrap_err();
        assert!(e.to_string().contains("init 1"), "{e}");
        let real = "[devices]\nplc = \"tcp://127.0.0.1:1?model=K205-16DT\"\n";
        let e = open(&mut Session::new(Clock::stepped()), &Bench::parse(real, Path::new("m.toml")).unwrap());
        assert!(e.is_err());
    }
}
