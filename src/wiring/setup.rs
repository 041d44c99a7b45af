//! Declaring wires between a session's devices — the one path the shell (`sim wire`), Lua
//! (`plcsh.wire`) and bench files take: resolve each end's device and terminal, pick the
//! PLC simulator that hosts the wire, and hand it the drive as a [`Peer`].

use super::{Decl, Role};
use crate::core::{Error, Result};
use crate::k2::K2Ops;
use crate::msg;
use crate::servo::ServoOps;
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
    if let Some(mut k2) = crate::k2::ops(dev.as_mut()) {
        let sim = k2.as_sim().ok_or_else(|| {
            Error::unsupported(msg!("wire-real-plc", name = name.as_str()))
                .hint(msg!("wire-real-plc-hint"))
                .device(&name)
        })?;
        return Ok(End::Plc(i, sim.wire_terminal(&ep.terminal).map_err(|e| e.device(&name))?));
    }
    if let Some(mut servo) = crate::servo::ops(dev.as_mut()) {
        let id = servo.drive_id();
        let line = servo.simulator().ok_or_else(|| {
            Error::unsupported(msg!("wire-real-drive", name = name.as_str()))
                .hint(msg!("wire-real-drive-hint"))
                .device(&name)
        })?;
        return Ok(End::Drive(super::drive_terminal(ep).map_err(|e| e.device(&name))?, line, id));
    }
    Err(Error::unsupported(msg!("wire-cannot-wire", name = name.as_str())).device(&name))
}

/// Adds the wire `text` (`plc:Q0.0 -> servo:pulse`, …); returns its description.
pub fn wire(s: &mut Session, text: &str) -> Result<String> {
    let mut decl = super::parse(text)?;
    // A tag's name for a terminal (`plc:Motor_Out`) is its operand, as everywhere operands go
    // (Lua's `plcsh.wire`, a bench's `wires`; the shell writes names as operands before).
    for ep in [&mut decl.from, &mut decl.to] {
        if let Ok(i) = s.index(&ep.device) {
            if let Some(n) = s.names(i).get(&ep.terminal) {
                ep.terminal = n.operand.clone();
            }
        }
    }
    add(s, decl)
}

/// Adds a parsed wire.
pub fn add(s: &mut Session, decl: Decl) -> Result<String> {
    let from = resolve(s, &decl.from)?;
    let to = resolve(s, &decl.to)?;
    let (host, from_role, to_role, peer) = match (from, to) {
        (End::Plc(a, fr), End::Plc(b, tr)) => {
            if a != b {
                return Err(Error::unsupported(msg!("wire-two-plcs", wire = decl.to_string())));
            }
            (a, fr, tr, None)
        }
        (End::Plc(a, fr), End::Drive(tr, line, id)) => (a, fr, tr, Some((decl.to.device.clone(), line, id))),
        (End::Drive(fr, line, id), End::Plc(b, tr)) => (b, fr, tr, Some((decl.from.device.clone(), line, id))),
        (End::Drive(..), End::Drive(..)) => {
            return Err(
                Error::unsupported(msg!("wire-two-drives", wire = decl.to_string())).hint(msg!("wire-two-drives-hint"))
            )
        }
    };
    let host_name = s.entries()[host].name.clone();
    let sim = crate::k2::simulator(s.entry(host).device.as_mut()).expect("resolved as a simulator");
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
        if let Some(sim) = crate::k2::simulator(s.entry(i).device.as_mut()) {
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
        if let Some(sim) = crate::k2::simulator(s.entry(i).device.as_mut()) {
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
        return Err(last_err.unwrap_or_else(|| Error::usage(msg!("wire-nothing")).hint(msg!("wire-nothing-hint"))));
    }
    Ok(gone)
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::core::Clock;
    use crate::session::SetItem;
    use std::time::Duration;

    fn set(s: &mut Session, item: &str) {
        let (op, v) = item.split_once('=').unwrap();
        s.set(&[SetItem { operand: op.into(), value: v.into(), column: 0, value_column: 0 }]).unwrap();
    }

    fn get(s: &mut Session, op: &str) -> i64 {
        s.get(&[op]).unwrap()[0].1.value.as_i64()
    }

    /// Profile-position moves (ramps, a reversal): at every poll HSC0 holds exactly
    /// ⌊position × 4 · lines / resolution⌋ (of the position the drive reports rounded to whole
    /// increments, so within its half increment) — the counts never drift.
    #[test]
    fn ramps_and_reversals_count_exactly_at_every_poll() {
        let clock = Clock::stepped();
        let mut s = Session::new(clock.clone());
        s.open("plc", "sim:K205-16DT").unwrap();
        s.open("servo", "sim-servo:?id=1").unwrap();
        wire(&mut s, "servo:encoder -> plc:I0.1,I0.0 lines=1000").unwrap(); // 0.4 counts per increment
        for it in ["plc:SMB37=16#A4", "plc:SMD42/DINT=100000000"] {
            set(&mut s, it);
        }
        crate::k2::ops(s.device("plc").unwrap().as_mut()).unwrap().hdef(0, 9).unwrap();
        crate::k2::ops(s.device("plc").unwrap().as_mut()).unwrap().hsc(0).unwrap();
        for it in ["servo:operating_mode=1", "servo:controlword=6", "servo:controlword=7", "servo:controlword=15"] {
            set(&mut s, it);
        }
        let mut checked = 0;
        for (target, polls) in [(12_345, 40), (-7_777, 70), (3, 30)] {
            set(&mut s, &format!("servo:target_position={target}"));
            set(&mut s, "servo:controlword=15");
            set(&mut s, "servo:controlword=31"); // new set-point, absolute, immediately
            for _ in 0..polls {
                clock.step(Duration::from_micros(7_300));
                let cv = get(&mut s, "plc:SMD38") as i32 as i64;
                // The drive reports its position rounded to whole increments (6064.00).
                let p = get(&mut s, "servo:position_actual") as f64;
                let (lo, hi) = (((p - 0.5) * 0.4).floor() as i64, ((p + 0.5) * 0.4).floor() as i64);
                assert!((lo..=hi).contains(&cv), "position {p}: count {cv}, want {lo}..={hi}");
                checked += 1;
            }
            clock.step(Duration::from_secs(2));
            let p = get(&mut s, "servo:position_actual");
            assert_eq!(p, target, "the move ended at its target");
            assert_eq!(get(&mut s, "plc:SMD38") as i32 as i64, (target as f64 * 0.4).floor() as i64);
        }
        assert_eq!(checked, 140);
    }
}
