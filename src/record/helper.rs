//! Replaying sessions that went through the PLC-side helper (docs/agent.md): a real K2
//! answers SM registers and instructions only through the helper program in the PLC, so a
//! replay runs that helper (`lib/k2_agent.il`) in the simulated K2 too.
//!
//! - Which recordings: a recorded read whose reply starts with the helper's signature
//!   (`16#4B41`, "KA") and protocol version 1 or 2 is a read of the helper's status block; its
//!   first register is the mailbox base. `replay --agent VBn` names the base when the
//!   recording holds no such read (a capture started mid-session).
//! - The scans: the helper acts once per PLC scan, and its heartbeat word (+4) counts the
//!   scans, so a recording says how many scans ran between two status reads — whatever the
//!   recording PLC's scan time. The replay's clock follows the recorded heartbeat: before
//!   each status read the simulated PLC runs scans (`SCAN_TIME` each) until it has run
//!   exactly as many since the first status read as the PLC did, so the helper acknowledges
//!   each command at the same status read as in the recording. Requests between status reads
//!   leave the clock alone.
//! - What the wire cannot say: whether a scan between a status read and the command write
//!   after it ran before or after the write. The replay runs it after, so a value that counts
//!   time (SMD212's pulses, a counter) read back through the helper may differ by what one
//!   scan adds.
//! - The heartbeat itself counts from another start (the PLC's power-up): it is compared by
//!   how far it moved since the first status read, not by its value.

use super::decode::{self, Asked};
use crate::k2::modbus_map::{self, Table};
use crate::k2::space::K2Space;

/// The helper's signature, the first word of its status block; the second is its protocol
/// version (1 in recordings made before version 2, whose sessions replay the same way).
const SIGNATURE: u16 = 0x4B41;
const VERSIONS: [u16; 2] = [1, crate::k2::agent::protocol::VERSION];
/// The heartbeat's word offset in the status block (byte +4).
const HEARTBEAT_WORD: u16 = 2;

/// The helper of one replayed link.
#[derive(Clone, Debug)]
pub struct Helper {
    /// The mailbox base: a V byte address.
    pub vbyte: u32,
    /// The holding register of the base.
    reg: u16,
    /// The recorded heartbeat at the previous status read, and the scans since the first.
    recorded: Option<(u16, u64)>,
    /// The replayed heartbeat when last looked at, and the scans since the first status read.
    replayed: Option<(u16, u64)>,
}

/// Reply words of an FC3 read (a PDU `03 bc data…`).
fn words(pdu: &[u8]) -> Vec<u16> {
    match pdu {
        [3, bc, data @ ..] if data.len() == usize::from(*bc) => {
            data.chunks_exact(2).map(|c| u16::from_be_bytes([c[0], c[1]])).collect()
        }
        _ => Vec::new(),
    }
}

/// The V byte a holding register stands for (`VW3400` → 3400).
fn vbyte_of(space: &K2Space, reg: u16) -> Option<u32> {
    modbus_map::operand_at(space, Table::HoldingRegisters, reg)?.strip_prefix("VW")?.parse().ok()
}

/// The register of V byte `vbyte`.
fn reg_of(space: &K2Space, vbyte: u32) -> Option<u16> {
    let op = crate::k2::operand::K2Operand::word(crate::k2::operand::Area::V, vbyte);
    let span = modbus_map::locate_read(space, &op).ok()?;
    Some(span.start)
}

impl Helper {
    /// The helper a link's exchanges show (`pairs`: each request PDU with its recorded reply
    /// PDU), or the one `forced` names.
    pub fn detect(space: &K2Space, pairs: &[(Vec<u8>, Option<Vec<u8>>)], forced: Option<u32>) -> Option<Helper> {
        let make = |vbyte, reg| Helper { vbyte, reg, recorded: None, replayed: None };
        match forced {
            Some(vb) => reg_of(space, vb).map(|reg| make(vb, reg)),
            None => pairs.iter().find_map(|(q, r)| {
                let (fc, addr) = (*q.first()?, u16::from_be_bytes([*q.get(1)?, *q.get(2)?]));
                let w = words(r.as_deref()?);
                (fc == 3 && w.len() > usize::from(HEARTBEAT_WORD) && w[0] == SIGNATURE && VERSIONS.contains(&w[1]))
                    .then(|| vbyte_of(space, addr).map(|vb| make(vb, addr)))
                    .flatten()
            }),
        }
    }

    /// Where the heartbeat sits in the reply to `asked` (a word index), if it covers it.
    fn heartbeat_in(&self, asked: Option<Asked>) -> Option<usize> {
        let q = asked.filter(|q| q.fc == 3)?;
        let hb = self.reg.checked_add(HEARTBEAT_WORD)?;
        (q.addr <= hb && u32::from(hb) < u32::from(q.addr) + u32::from(q.count)).then(|| usize::from(hb - q.addr))
    }

    /// Before a request: how many scans since the first status read the simulated PLC must
    /// have run (`None`: this request is no status read; leave the clock).
    pub fn scans_before(&mut self, space: &K2Space, request: &[u8], recorded: Option<&[u8]>) -> Option<u64> {
        let (_, asked) = decode::modbus(space, 0, request, crate::core::trace::Dir::Sent, None);
        let i = self.heartbeat_in(asked)?;
        let h = *words(recorded?).get(i)?;
        let scans = match self.recorded {
            None => 0,
            // A heartbeat that went back (by half its range or more) is a PLC that restarted:
            // no scans to run for it (the replay then differs there).
            Some((prev, total)) => {
                let d = h.wrapping_sub(prev);
                total + if d < 0x8000 { u64::from(d) } else { 0 }
            }
        };
        self.recorded = Some((h, scans));
        Some(scans)
    }

    /// After a request: the replayed heartbeat in `replayed` is set to the recorded one when
    /// it moved as far since the first status read as the recorded one did.
    pub fn match_heartbeat(&mut self, space: &K2Space, request: &[u8], recorded: Option<&[u8]>, replayed: &mut [u8]) {
        let (_, asked) = decode::modbus(space, 0, request, crate::core::trace::Dir::Sent, None);
        let (Some(i), Some(rec)) = (self.heartbeat_in(asked), recorded) else { return };
        let (Some(&h), Some(&r)) = (words(rec).get(i), words(replayed).get(i)) else { return };
        let (prev, total) = *self.replayed.get_or_insert((r, 0));
        let moved = total + u64::from(r.wrapping_sub(prev));
        self.replayed = Some((r, moved));
        if Some(moved) == self.recorded.map(|(_, total)| total) {
            replayed[2 + 2 * i..4 + 2 * i].copy_from_slice(&h.to_be_bytes());
        }
    }

    /// Runs the simulated PLC's scans, one scan time at a time, until it has run `scans`
    /// since the first status read (a scan that runs a command may take longer than one
    /// scan time, as on a PLC). The first call takes the baseline.
    pub fn catch_up(&mut self, sim: &mut crate::k2::sim::K2Sim, clock: &crate::core::Clock, scans: u64) {
        let heartbeat = |s: &crate::k2::sim::K2Sim| crate::k2::sim::agent::v_word(s, self.vbyte + 4);
        sim.advance();
        let mut steps = 0;
        let mut limit = None;
        loop {
            let hb = heartbeat(sim);
            let (prev, total) = *self.replayed.get_or_insert((hb, 0));
            let total = total + u64::from(hb.wrapping_sub(prev));
            self.replayed = Some((hb, total));
            // A helper that stopped counting never catches up: at most four scan times per
            // missing scan.
            let limit = *limit.get_or_insert(4 * scans.saturating_sub(total) + 16);
            if total >= scans || steps >= limit {
                return;
            }
            clock.step(crate::k2::sim::SCAN_TIME);
            sim.advance();
            steps += 1;
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn status_read(space: &K2Space) -> (Vec<u8>, u16) {
        let reg = reg_of(space, 3400).unwrap();
        let mut q = vec![3];
        q.extend_from_slice(&reg.to_be_bytes());
        q.extend_from_slice(&48u16.to_be_bytes());
        (q, reg)
    }

    fn reply(heartbeat: u16) -> Vec<u8> {
        let mut r = vec![3, 96];
        for w in [0x4B41, 1, heartbeat] {
            r.extend_from_slice(&u16::to_be_bytes(w));
        }
        r.resize(98, 0);
        r
    }

    #[test]
    fn the_clock_follows_the_recorded_heartbeat_and_the_heartbeat_is_compared_by_its_motion() {
        let space = K2Space::new(crate::k2::catalog::lookup("K205-16DT").unwrap());
        let (q, _) = status_read(&space);
        let pairs = vec![(q.clone(), Some(reply(65530)))];
        let mut h = Helper::detect(&space, &pairs, None).unwrap();
        assert_eq!(h.vbyte, 3400);
        // Recorded heartbeats 65530, 65534, 2 (wrapped): 0, 4 and 8 scans since the first read.
        assert_eq!(h.scans_before(&space, &q, Some(&reply(65530))), Some(0));
        let mut replayed = reply(7);
        h.match_heartbeat(&space, &q, Some(&reply(65530)), &mut replayed);
        assert_eq!(replayed, reply(65530));
        assert_eq!(h.scans_before(&space, &q, Some(&reply(65534))), Some(4));
        let mut replayed = reply(11);
        h.match_heartbeat(&space, &q, Some(&reply(65534)), &mut replayed);
        assert_eq!(replayed, reply(65534), "moved 4 as recorded");
        assert_eq!(h.scans_before(&space, &q, Some(&reply(2))), Some(8));
        let mut replayed = reply(16);
        h.match_heartbeat(&space, &q, Some(&reply(2)), &mut replayed);
        assert_eq!(replayed, reply(16), "moved 9, recorded 8: left to differ");
        // A read of other registers leaves the clock alone.
        assert_eq!(h.scans_before(&space, &[3, 0, 100, 0, 1], Some(&[3, 2, 0, 0])), None);
        assert!(Helper::detect(&space, &[(q, Some(vec![3, 2, 0, 0]))], None).is_none());
    }

    #[test]
    fn the_simulated_plc_catches_up_every_scan_however_many() {
        let clock = crate::core::Clock::stepped();
        let mut sim = crate::k2::sim::open("K205-16DT", clock.clone()).unwrap();
        sim.enable_agent(3400).unwrap();
        let space = K2Space::new(sim.model());
        let mut h = Helper::detect(&space, &[], Some(3400)).unwrap();
        h.catch_up(&mut sim, &clock, 0);
        let (start, _) = h.replayed.unwrap();
        for target in [1, 2, 500, 501, 70_000] {
            h.catch_up(&mut sim, &clock, target);
            let hb = crate::k2::sim::agent::v_word(&sim, 3404);
            assert_eq!(u64::from(hb.wrapping_sub(start)), target % 65536, "{target}");
            assert_eq!(h.replayed.unwrap().1, target);
        }
    }
}
