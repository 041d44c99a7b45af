//! The PLC-side helper program in the simulator: with `--agent`, the simulated K2 runs
//! `lib/k2_agent.il` — the very text users load into KincoBuilder, generated for the
//! mailbox base by [`crate::k2::agent::il::program`] — in its scan engine, after the user
//! program every scan. Its PLS, HDEF, HSC, PSTOP, SET_RTC and READ_RTC are the
//! simulator's instructions, and its SM writes go through the same image as any program's.
//! So the whole path plcsh → Modbus → mailbox → IL → SM → PTO is exercised end to end
//! without hardware, and a mistake in the IL file shows up in the simulator.

use super::K2Sim;
use crate::k2::operand::{Area, K2Operand};

impl K2Sim {
    /// Installs the helper with its mailbox at VB`base` (even, inside V).
    pub fn enable_agent(&mut self, base: u32) -> Result<(), String> {
        let end = base + crate::k2::agent::il::TOTAL_SIZE;
        if !base.is_multiple_of(2) || end > self.mem.v.len() as u32 {
            return Err(crate::msg!(
                "k2-helper-mailbox-address",
                size = crate::k2::agent::il::TOTAL_SIZE,
                top = self.mem.v.len() - 1,
                base = base
            )
            .into());
        }
        let text = crate::k2::agent::il::program(self.model(), base);
        self.load_helper(&text, "k2_agent.il").map_err(|e| e.to_string())?;
        self.agent_base = Some(base);
        Ok(())
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
    use crate::k2::agent::protocol::{
        self, request_words, Command, ResultCode, Status, DEFAULT_BASE, OFF_REQUEST, STATUS_WORDS,
    };
    use crate::k2::instr::RtcTime;
    use crate::k2::sim::SCAN_TIME;
    use std::time::Duration;

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

    /// Steps until the CPU has run one more scan (a scan with a request takes longer
    /// than the 1 ms minimum: its cost-table time).
    fn scan(s: &mut K2Sim, clock: &Clock) {
        let before = s.plc().unwrap().stats.scans;
        for _ in 0..100 {
            clock.step(SCAN_TIME);
            s.advance();
            if s.plc().unwrap().stats.scans > before {
                return;
            }
        }
        panic!("no scan ran");
    }

    /// Scans until the request with sequence `seq` is acknowledged: in the next scan, or the
    /// one after when the scan before executed a request (docs/agent.md).
    fn acked(s: &mut K2Sim, clock: &Clock, seq: u16) {
        for _ in 0..2 {
            scan(s, clock);
            if status(s).acks[0].seq == seq {
                return;
            }
        }
        panic!("request {seq} was not acknowledged within two scans");
    }

    #[test]
    fn the_helper_announces_itself_every_scan() {
        let (mut s, clock) = sim();
        scan(&mut s, &clock);
        let a = status(&s);
        assert_eq!((a.signature, a.version), (protocol::SIGNATURE, protocol::VERSION));
        // The helper evaluates its instruction networks every scan, so its scans can take
        // longer than the 1 ms minimum: count the scans, not the milliseconds.
        let scans = s.plc().unwrap().stats.scans;
        clock.step(SCAN_TIME * 9);
        s.advance();
        let ran = s.plc().unwrap().stats.scans - scans;
        assert!(ran >= 5, "{ran} scans in 9 ms");
        assert_eq!(status(&s).heartbeat, a.heartbeat.wrapping_add(ran as u16), "one beat per scan");
    }

    #[test]
    fn a_pto_started_through_the_mailbox_runs_like_pls() {
        let (mut s, clock) = sim();
        // SMB67=16#85, SMW68=500, SMD72=1000 as one SM write, then PLS 0 (k2.md §5).
        request(&mut s, 1, &Command::SmWrite { start: 67, data: vec![0x85, 0x01, 0xF4, 0, 0, 0, 0, 0, 0x03, 0xE8] });
        acked(&mut s, &clock, 1);
        assert_eq!(status(&s).find(1, 0x1234).unwrap().1.result, ResultCode::Ok);
        request(&mut s, 2, &Command::Pls(0));
        acked(&mut s, &clock, 2);
        assert_eq!(status(&s).find(2, 0x1234).unwrap().1.result, ResultCode::Ok);
        assert!(!s.mem.sm_bit(66, 7), "PTO0 busy");
        clock.step(Duration::from_millis(500));
        s.advance();
        assert!(s.mem.sm_bit(66, 7), "PTO0 idle after 1000 × 500 µs");
        request(&mut s, 3, &Command::SmRead { start: 66, len: 1 });
        acked(&mut s, &clock, 3);
        let reply = protocol::reply_of(&Command::SmRead { start: 66, len: 1 }, &status(&s).reply);
        assert_eq!(reply, Some(vec![s.mem.sm_byte(66)]));
    }

    #[test]
    fn refusals_come_back_as_result_codes() {
        let (mut s, clock) = sim();
        request(&mut s, 1, &Command::Hdef { hsc: 0, mode: 5 });
        acked(&mut s, &clock, 1);
        assert_eq!(status(&s).acks[0].result, ResultCode::BadMode, "HSC0 has no mode 5 (§3.3.1)");
        request(&mut s, 2, &Command::SmWrite { start: 212, data: vec![1, 2, 3, 4] });
        acked(&mut s, &clock, 2);
        assert_eq!(status(&s).acks[0].result, ResultCode::ReadOnly, "SMD212 is read-only");
        request(&mut s, 3, &Command::SetRtc([0x26, 0x13, 0x01, 0, 0, 0, 0, 1]));
        acked(&mut s, &clock, 3);
        assert_eq!(status(&s).acks[0].result, ResultCode::BadClock, "month 13");
    }

    /// A refused PLS is read where the PLC reports it: PLS leaves the CR as it was (K2
    /// §3.4.2, «Это не повлияет на значение CR»), so the helper reads the channel's status
    /// bit 4, "cycle time or pulse count invalid" (§3.4.2.2), and its result names it; a write
    /// to SMD212 names the read-only current value and the way to set it (§3.4.3.1). The
    /// causes reach the user in the words the simulator uses in process.
    #[test]
    fn a_refused_pls_is_reported_from_its_status_bit_with_the_in_process_words() {
        let (mut s, clock) = sim();
        let model = s.model();
        // SMB67 = 16#85, SMW68 = 1000 µs, SMD72 = 1 pulse: below the manual's minimum of 2.
        request(&mut s, 1, &Command::SmWrite { start: 67, data: vec![0x85, 0x03, 0xE8, 0, 0, 0, 0, 0, 1] });
        acked(&mut s, &clock, 1);
        request(&mut s, 2, &Command::Pls(0));
        acked(&mut s, &clock, 2);
        let ack = status(&s).acks[0];
        assert_eq!((ack.result, ack.cause), (ResultCode::StatusBit, protocol::StatusCause::PtoInvalid as u8));
        assert!(s.mem.sm_bit(66, 4), "SM66.4");
        let (why, hint) = protocol::reason(model, &Command::Pls(0), ack.result, ack.cause);
        assert!(why.contains("SM66.4") && why.contains(crate::k2::sm_map::PTO_INVALID_RULE), "{why}");
        assert!(hint.unwrap().contains("SMD72"));
        // The same request with 10 pulses is done, and bit 4 is clear again.
        request(&mut s, 3, &Command::SmWrite { start: 72, data: vec![0, 0, 0, 10] });
        acked(&mut s, &clock, 3);
        request(&mut s, 4, &Command::Pls(0));
        acked(&mut s, &clock, 4);
        assert_eq!(status(&s).acks[0].result, ResultCode::Ok);
        assert!(!s.mem.sm_bit(66, 4));
        // SMD212: result 3 with the cause that names it, in the in-process words.
        let cmd = Command::SmWrite { start: 212, data: vec![0, 0, 0, 5] };
        request(&mut s, 5, &cmd);
        acked(&mut s, &clock, 5);
        let ack = status(&s).acks[0];
        assert_eq!(ack.result, ResultCode::ReadOnly);
        let row = &protocol::checks(model)[ack.cause as usize - 1];
        assert!(row.why.contains("SMD212"), "cause {}: {}", ack.cause, row.why);
        let (why, hint) = protocol::reason(model, &cmd, ack.result, ack.cause);
        let op = crate::k2::operand::K2Operand::new(Area::SM, crate::k2::operand::Width::DWord, 212);
        let local = s.check_writable(&op).unwrap_err();
        assert_eq!(why, local.message, "the same words as in process");
        assert!(hint.unwrap().contains("SMD208") && local.hint.clone().unwrap().contains("SM201.4"));
        // SMB0: result 3 again, another cause.
        request(&mut s, 6, &Command::SmWrite { start: 0, data: vec![1] });
        acked(&mut s, &clock, 6);
        let ack = status(&s).acks[0];
        assert_eq!(ack.result, ResultCode::ReadOnly);
        let (why, _) = protocol::reason(model, &Command::SmWrite { start: 0, data: vec![1] }, ack.result, ack.cause);
        assert!(why.contains("system status bits"), "{why}");
    }

    /// What a client that ignores the protocol can write: any command and arguments.
    fn raw_request(s: &mut K2Sim, seq: u16, code: u16, args: [u16; 3]) {
        let words = [seq, 0x1234, code, args[0], args[1], args[2]];
        for (i, w) in words.iter().enumerate() {
            s.mem.write(&K2Operand::word(Area::V, DEFAULT_BASE + OFF_REQUEST + 2 * i as u32), *w as u32);
        }
    }

    /// The helper compared words as signed INTs, so a start of 32768 or more (or a
    /// start + length that went negative) passed every check and the copy loop stopped the
    /// CPU with "bad indirect address"; start 100 with length 16#AAAA was acked done.
    #[test]
    fn out_of_range_words_are_refused_and_the_cpu_keeps_scanning() {
        use ResultCode::*;
        let cases: &[(u16, [u16; 3], ResultCode)] = &[
            (2, [40000, 1, 0], BadRange),
            (1, [40000, 1, 0], BadRange),
            (2, [32768, 1, 0], BadRange),
            (2, [65535, 64, 0], BadRange),
            (2, [32767, 64, 0], BadRange),
            (1, [100, 0xAAAA, 0], BadRange),
            (2, [100, 0xAAAA, 0], BadRange),
            (2, [500, 0xFFFF, 0], BadRange),
            (2, [549, 32768, 0], BadRange),
            (1, [0, 40000, 0], ReadOnly),
            (2, [265, 1, 0], Ok),
            (2, [258, 4, 0], Ok),
            (2, [258, 8, 0], BadRange),
            (2, [202, 64, 0], BadRange),
            (2, [266, 1, 0], BadRange),
            (2, [549, 1, 0], BadRange),
            (3, [40000, 0, 0], BadChannel),
            (5, [65535, 0, 0], BadChannel),
            (4, [32768, 0, 0], BadChannel),
            (40000, [0, 0, 0], UnknownCommand),
            (65535, [1, 1, 0], UnknownCommand),
        ];
        let (mut s, clock) = sim();
        for (i, &(code, args, want)) in cases.iter().enumerate() {
            let seq = i as u16 + 1;
            raw_request(&mut s, seq, code, args);
            let beat = status(&s).heartbeat;
            acked(&mut s, &clock, seq);
            let plc = s.plc().unwrap();
            assert!(plc.faults.is_empty(), "command {code} {args:?}: the CPU faulted: {:?}", plc.faults);
            assert_eq!(plc.mode, crate::k2::sim::program::Mode::Run, "command {code} {args:?}");
            let st = status(&s);
            assert_ne!(st.heartbeat, beat, "command {code} {args:?}: the heartbeat stopped");
            assert_eq!(st.acks[0].seq, seq, "command {code} {args:?} was not acknowledged");
            assert_eq!(st.acks[0].result, want, "command {code} {args:?}");
        }
    }

    #[test]
    fn the_clock_round_trips_through_the_mailbox() {
        let (mut s, clock) = sim();
        let t = RtcTime::parse("2026-11-22T10:00:00").unwrap();
        request(&mut s, 1, &Command::SetRtc(t.to_bcd8()));
        acked(&mut s, &clock, 1);
        request(&mut s, 2, &Command::ReadRtc);
        acked(&mut s, &clock, 2);
        let b: [u8; 8] = status(&s).reply.try_into().unwrap();
        assert_eq!(RtcTime::from_bcd8(&b).unwrap().to_string(), "2026-11-22T10:00:00");
    }

    #[test]
    fn without_the_helper_nothing_answers() {
        let clock = Clock::stepped();
        let mut s = crate::k2::sim::open("K205-16DT", clock.clone()).unwrap();
        request(&mut s, 1, &Command::Ping);
        clock.step(SCAN_TIME * 5);
        s.advance();
        assert_eq!(status(&s).signature, 0);
        assert!(s.enable_agent(4095).is_err());
    }
}
