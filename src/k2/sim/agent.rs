//! The simulator's copy of the PLC-side helper program (issue 5): with `--agent`, once per
//! simulated scan the simulator runs exactly what `lib/k2_agent.il` runs on a real K2 —
//! [`protocol::execute_scan`] over the mailbox in V memory — with the commands carried out
//! by the simulator's own instructions (PLS, HDEF, HSC, PSTOP, SET_RTC, READ_RTC) and SM
//! writes going through the same checks as any other write. So the whole path plcsh →
//! Modbus → mailbox → SM → PTO is exercised end to end without hardware.

use super::{K2Sim, SCAN_TIME};
use crate::core::{Device, Value};
use crate::k2::agent::protocol::{self, Command, ResultCode, VMemory};
use crate::k2::instr::RtcTime;
use crate::k2::operand::{Area, K2Operand};
use crate::k2::K2Ops;
use std::time::Duration;

/// The helper's state in the simulator.
#[derive(Clone, Copy, Debug, serde::Serialize, serde::Deserialize)]
pub struct Agent {
    /// Mailbox base (V byte offset).
    pub base: u32,
    /// The last scan the helper ran in (`None` before its first scan).
    last_scan: Option<u128>,
}

/// The mailbox bytes, copied out of V for one scan.
struct Mailbox(Vec<u8>);

impl VMemory for Mailbox {
    fn v(&self) -> &[u8] {
        &self.0
    }
    fn v_mut(&mut self) -> &mut [u8] {
        &mut self.0
    }
}

impl K2Sim {
    /// Installs the helper with its mailbox at VB`base` (even, inside V).
    pub fn enable_agent(&mut self, base: u32) -> Result<(), String> {
        let end = base + crate::k2::agent::il::TOTAL_SIZE;
        if !base.is_multiple_of(2) || end > self.mem.v.len() as u32 {
            return Err(format!(
                "the helper's mailbox needs an even V address with {} bytes free up to VB{} (got VB{base})",
                crate::k2::agent::il::TOTAL_SIZE,
                self.mem.v.len() - 1
            ));
        }
        // A PLC in RUN has been scanning before any client looks: run the first scan now.
        self.agent = Some(Agent { base, last_scan: None });
        self.agent_scans(self.last);
        Ok(())
    }

    fn scan_number(&self, t: Duration) -> u128 {
        t.saturating_sub(self.start).as_micros() / SCAN_TIME.as_micros()
    }

    /// Runs the helper if a scan boundary has passed since it last ran (called as the
    /// simulation advances). One execution per call is enough: the helper acts on at most
    /// one request per scan and a client writes one request at a time.
    pub(super) fn agent_scans(&mut self, now: Duration) {
        let Some(a) = self.agent else { return };
        let scan = self.scan_number(now);
        if a.last_scan.is_some_and(|last| scan <= last) {
            return;
        }
        self.agent = Some(Agent { last_scan: Some(scan), ..a });
        let (b, n) = (a.base as usize, protocol::SIZE as usize);
        let mut mailbox = Mailbox(self.mem.v[b..b + n].to_vec());
        // The heartbeat counts every scan, as the PLC program's ADD does.
        let missed = a.last_scan.map_or(0, |last| (scan - last - 1).min(u16::MAX as u128) as u16);
        let hb = u16::from_be_bytes([mailbox.0[4], mailbox.0[5]]).wrapping_add(missed);
        mailbox.0[4..6].copy_from_slice(&hb.to_be_bytes());
        protocol::execute_scan(&mut mailbox, 0, &mut |cmd| self.agent_command(cmd));
        self.mem.v[b..b + n].copy_from_slice(&mailbox.0);
    }

    fn agent_command(&mut self, cmd: Command) -> Result<Vec<u8>, ResultCode> {
        let failed = |_| ResultCode::InstructionFailed;
        match cmd {
            Command::SmWrite { start, data } => {
                let items: Vec<_> = data
                    .iter()
                    .enumerate()
                    .map(|(i, b)| (K2Operand::byte(Area::SM, start as u32 + i as u32).to_core(), Value::Int(*b as i64)))
                    .collect();
                self.write(&items).map(|_| Vec::new()).map_err(|_| ResultCode::ReadOnly)
            }
            Command::SmRead { start, len } => {
                let (s, e) = (start as usize, start as usize + len as usize);
                Ok(self.mem.sm[s..e].to_vec())
            }
            Command::Pls(n) => self.pls(n).map(|_| Vec::new()).map_err(failed),
            Command::Hdef { hsc, mode } => {
                if self.model().hsc(hsc).is_none() {
                    return Err(ResultCode::BadChannel);
                }
                self.hdef(hsc, mode).map(|_| Vec::new()).map_err(|_| ResultCode::BadMode)
            }
            Command::Hsc(n) => {
                if self.model().hsc(n).is_none() {
                    return Err(ResultCode::BadChannel);
                }
                self.hsc(n).map(|_| Vec::new()).map_err(failed)
            }
            Command::Pstop(n) => {
                if self.model().pto(n).is_none() {
                    return Err(ResultCode::BadChannel);
                }
                self.pstop(n).map(|_| Vec::new()).map_err(failed)
            }
            Command::SetRtc(b) => {
                let t = RtcTime::from_bcd8(&b).map_err(|_| ResultCode::BadClock)?;
                self.set_rtc(t).map(|_| Vec::new()).map_err(|_| ResultCode::BadClock)
            }
            Command::ReadRtc => self.read_rtc().map(|t| t.to_bcd8().to_vec()).map_err(failed),
            Command::Ping => Ok(Vec::new()),
        }
    }
}

/// Reads a V word of the simulator (tests and diagnostics).
pub fn v_word(sim: &K2Sim, byte: u32) -> u16 {
    sim.mem.read(&K2Operand::word(Area::V, byte)) as u16
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::core::Clock;
    use crate::k2::agent::protocol::{request_words, Status, DEFAULT_BASE, OFF_REQUEST, STATUS_WORDS};

    fn sim() -> (K2Sim, Clock) {
        let clock = Clock::stepped();
        let mut s = crate::k2::sim::open("K205-16DT", clock.clone()).unwrap();
        s.enable_agent(DEFAULT_BASE).unwrap();
        (s, clock)
    }

    /// What a Modbus client does: one write of the request block.
    fn request(s: &mut K2Sim, seq: u16, cmd: &Command) {
        for (i, w) in request_words(seq, 0x1234, cmd).iter().enumerate() {
            s.mem.write(&K2Operand::word(Area::V, DEFAULT_BASE + OFF_REQUEST + 2 * i as u32), *w as u32);
        }
    }

    fn status(s: &K2Sim) -> Status {
        let w: Vec<u16> = (0..STATUS_WORDS as u32).map(|i| v_word(s, DEFAULT_BASE + 2 * i)).collect();
        Status::parse(&w)
    }

    fn scan(s: &mut K2Sim, clock: &Clock) {
        clock.step(SCAN_TIME);
        s.advance();
    }

    #[test]
    fn the_helper_announces_itself_every_scan() {
        let (mut s, clock) = sim();
        scan(&mut s, &clock);
        let a = status(&s);
        assert_eq!((a.signature, a.version), (protocol::SIGNATURE, protocol::VERSION));
        clock.step(SCAN_TIME * 9);
        s.advance();
        assert_eq!(status(&s).heartbeat, a.heartbeat.wrapping_add(9), "one beat per scan");
    }

    #[test]
    fn a_pto_started_through_the_mailbox_runs_like_pls() {
        let (mut s, clock) = sim();
        // SMB67=16#85, SMW68=500, SMD72=1000 as one SM write, then PLS 0 (k2.md §5).
        request(&mut s, 1, &Command::SmWrite { start: 67, data: vec![0x85, 0x01, 0xF4, 0, 0, 0, 0, 0, 0x03, 0xE8] });
        scan(&mut s, &clock);
        assert_eq!(status(&s).find(1, 0x1234).unwrap().1.result, ResultCode::Ok);
        request(&mut s, 2, &Command::Pls(0));
        scan(&mut s, &clock);
        assert_eq!(status(&s).find(2, 0x1234).unwrap().1.result, ResultCode::Ok);
        assert!(!s.mem.sm_bit(66, 7), "PTO0 busy");
        clock.step(Duration::from_millis(500));
        s.advance();
        assert!(s.mem.sm_bit(66, 7), "PTO0 idle after 1000 × 500 µs");
        request(&mut s, 3, &Command::SmRead { start: 66, len: 1 });
        scan(&mut s, &clock);
        assert_eq!(status(&s).reply, vec![s.mem.sm_byte(66)]);
    }

    #[test]
    fn refusals_come_back_as_result_codes() {
        let (mut s, clock) = sim();
        request(&mut s, 1, &Command::Hdef { hsc: 0, mode: 5 });
        scan(&mut s, &clock);
        assert_eq!(status(&s).acks[0].result, ResultCode::BadMode, "HSC0 has no mode 5 (§3.3.1)");
        request(&mut s, 2, &Command::SmWrite { start: 212, data: vec![1, 2, 3, 4] });
        scan(&mut s, &clock);
        assert_eq!(status(&s).acks[0].result, ResultCode::ReadOnly, "SMD212 is read-only");
        request(&mut s, 3, &Command::SetRtc([0x26, 0x13, 0x01, 0, 0, 0, 0, 1]));
        scan(&mut s, &clock);
        assert_eq!(status(&s).acks[0].result, ResultCode::BadClock, "month 13");
    }

    #[test]
    fn the_clock_round_trips_through_the_mailbox() {
        let (mut s, clock) = sim();
        let t = RtcTime::parse("2026-11-22T10:00:00").unwrap();
        request(&mut s, 1, &Command::SetRtc(t.to_bcd8()));
        scan(&mut s, &clock);
        request(&mut s, 2, &Command::ReadRtc);
        scan(&mut s, &clock);
        let b: [u8; 8] = status(&s).reply.try_into().unwrap();
        assert_eq!(RtcTime::from_bcd8(&b).unwrap().to_string(), "2026-11-22T10:00:00");
    }

    #[test]
    fn without_the_helper_nothing_answers() {
        let clock = Clock::stepped();
        let mut s = crate::k2::sim::open("K205-16DT", clock.clone()).unwrap();
        request(&mut s, 1, &Command::Ping);
        scan(&mut s, &clock);
        assert_eq!(status(&s).signature, 0);
        assert!(s.enable_agent(4095).is_err());
    }
}
