//! Declaring wires between a session's devices — the one path the shell (`sim wire`), Lua
//! (`plcsh.wire`) and bench files take: resolve each end's device and terminal, pick the
//! PLC simulator that hosts the wire, and hand it the drive as a [`Peer`].

use super::{Decl, Role};
use crate::core::{Error, Result};
use crate::session::Session;

/// What one end of a wire is.
enum End {
    /// A K2 simulator (session index) and the role of the terminal.
    Plc(usize, Role),
    /// A simulated drive, its role and how to reach it.
    Drive(Role, std::sync::Arc<std::sync::Mutex<crate::servo::sim::SimLine>>, u8),
}

fn resolve(s: &mut Session, ep: &super::Endpoint) -> Result<End> {
    let i = s.index(&ep.device)?;
    let name = ep.device.clone();
    let dev = &mut s.entry(i).device;
    if let Some(k2) = dev.as_k2() {
        let sim = k2.as_sim().ok_or_else(|| {
            Error::unsupported(format!("{name} is a real PLC: wires join simulated devices"))
                .hint("open a simulator, e.g. connect plc sim:K205-16DT")
                .device(&name)
        })?;
        return Ok(End::Plc(i, sim.wire_terminal(&ep.terminal).map_err(|e| e.device(&name))?));
    }
    if let Some(servo) = dev.as_servo() {
        let id = servo.drive_id();
        let line = servo.simulator().ok_or_else(|| {
            Error::unsupported(format!("{name} is a real drive: wires join simulated devices"))
                .hint("open a simulated drive, e.g. connect servo sim-servo:?id=1")
                .device(&name)
        })?;
        return Ok(End::Drive(super::drive_terminal(ep).map_err(|e| e.device(&name))?, line, id));
    }
    Err(Error::unsupported(format!("{name} cannot be wired (only simulated K2 PLCs and drives can)")).device(&name))
}

/// Adds the wire `text` (`plc:Q0.0 -> servo:pulse`, …); returns its description.
pub fn wire(s: &mut Session, text: &str) -> Result<String> {
    let decl = super::parse(text)?;
    add(s, decl)
}

/// Adds a parsed wire.
pub fn add(s: &mut Session, decl: Decl) -> Result<String> {
    let from = resolve(s, &decl.from)?;
    let to = resolve(s, &decl.to)?;
    let (host, from_role, to_role, peer) = match (from, to) {
        (End::Plc(a, fr), End::Plc(b, tr)) => {
            if a != b {
                return Err(Error::unsupported(format!(
                    "{decl}: wires between two PLCs are not simulated; a PLC output wires back to its own inputs"
                )));
            }
            (a, fr, tr, None)
        }
        (End::Plc(a, fr), End::Drive(tr, line, id)) => (a, fr, tr, Some((decl.to.device.clone(), line, id))),
        (End::Drive(fr, line, id), End::Plc(b, tr)) => (b, fr, tr, Some((decl.from.device.clone(), line, id))),
        (End::Drive(..), End::Drive(..)) => {
            return Err(Error::unsupported(format!("{decl}: drive-to-drive wiring is not simulated"))
                .hint("wire drives to a simulated PLC"))
        }
    };
    let host_name = s.entries()[host].name.clone();
    let sim = s.entry(host).device.as_k2().and_then(|k| k.as_sim()).expect("resolved as a simulator");
    let peer = peer.map(|(name, line, id)| {
        let make: super::MakePeer = Box::new(move || Box::new(crate::servo::sim::wired::DrivePeer::new(line, id)));
        (name, make)
    });
    match peer {
        Some((name, make)) => sim.add_wire(decl, from_role, to_role, Some((&name, make))),
        None => sim.add_wire(decl, from_role, to_role, None),
    }
    .map_err(|e| e.device(&host_name))
}

/// Every wire in the session, described (hosted by each simulated PLC).
pub fn list(s: &mut Session) -> Vec<String> {
    let mut out = Vec::new();
    for i in 0..s.entries().len() {
        if let Some(sim) = s.entry(i).device.as_k2().and_then(|k| k.as_sim()) {
            out.extend(sim.wires());
        }
    }
    out
}

/// Removes the wires touching `which` (a terminal, a whole declaration, or `all`).
pub fn unwire(s: &mut Session, which: &str) -> Result<Vec<String>> {
    let mut gone = Vec::new();
    let mut last_err = None;
    for i in 0..s.entries().len() {
        if let Some(sim) = s.entry(i).device.as_k2().and_then(|k| k.as_sim()) {
            if sim.wiring.is_none() {
                continue;
            }
            match sim.unwire(which) {
                Ok(g) => gone.extend(g),
                Err(e) => last_err = Some(e),
            }
        }
    }
    if gone.is_empty() {
        return Err(last_err.unwrap_or_else(|| {
            Error::usage("nothing is wired")
                .hint("sim wire FROM -> TO adds a wire, e.g. sim wire plc:Q0.0 -> servo:pulse")
        }));
    }
    Ok(gone)
}
