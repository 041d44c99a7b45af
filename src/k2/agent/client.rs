//! The plcsh side of the helper mailbox (docs/agent.md): one command at a time, written
//! whole in one Modbus write, acknowledged by (sequence, token) in one Modbus read. Generic
//! over [`Registers`] (V words on some link), so the protocol logic is tested without a
//! network and the wire driver only supplies the register access.

use super::protocol::{self as p, Command, ResultCode, Status};
use crate::core::{Error, ErrorKind, Result};
use std::time::{Duration, Instant};

/// V-word access on the device's link (holding registers on a K2).
pub trait Registers {
    /// Reads `count` V words starting at V byte `vbyte` (even), in one request.
    fn read_v(&mut self, vbyte: u32, count: u16) -> Result<Vec<u16>>;
    /// Writes V words starting at V byte `vbyte` (even), in one request.
    fn write_v(&mut self, vbyte: u32, words: &[u16]) -> Result<()>;
}

/// How many times a command is resent after another client's command won a race.
const RACE_RETRIES: u32 = 5;

/// One plcsh session's end of the mailbox.
#[derive(Clone, Debug)]
pub struct AgentClient {
    pub base: u32,
    /// Identifies this client's requests (random per session).
    token: u16,
    /// How long a command may wait for the helper (busy mailbox, then the acknowledgement).
    pub timeout: Duration,
    /// Pause between status reads (about a scan).
    pub poll: Duration,
    /// Commands sent (for messages and tests).
    pub commands: u64,
    /// The PLC's model: the helper's checks are the model's (`plcsh agent il --model`), and
    /// a refusal's cause names one of them.
    pub model: &'static crate::k2::catalog::Model,
    /// The result and cause of the last command, when the helper refused it (the caller may
    /// read registers back to word the refusal as in process).
    pub last_refusal: Option<(ResultCode, u8)>,
}

/// A token that differs between sessions and processes (never 0).
fn new_token() -> u16 {
    let nanos =
        std::time::SystemTime::now().duration_since(std::time::UNIX_EPOCH).map(|d| d.subsec_nanos()).unwrap_or(0);
    let mix = nanos ^ (std::process::id().rotate_left(16)) ^ (&nanos as *const u32 as usize as u32);
    let t = (mix ^ (mix >> 16)) as u16;
    if t == 0 {
        1
    } else {
        t
    }
}

fn describe(cmd: &Command) -> String {
    match cmd {
        Command::SmWrite { start, data } => {
            crate::msg!("agent-what-sm-write", start = *start, end = *start as usize + data.len() - 1).to_string()
        }
        Command::SmRead { start, len } => {
            crate::msg!("agent-what-sm-read", start = *start, end = start + len - 1).to_string()
        }
        Command::Pls(n) => format!("PLS {n}"),
        Command::Hdef { hsc, mode } => format!("HDEF {hsc}, {mode}"),
        Command::Hsc(n) => format!("HSC {n}"),
        Command::Pstop(n) => format!("PSTOP {n}"),
        Command::SetRtc(_) => "SET_RTC".into(),
        Command::ReadRtc => "READ_RTC".into(),
        Command::Ping => "ping".into(),
    }
}

impl AgentClient {
    pub fn new(base: u32) -> AgentClient {
        AgentClient {
            base,
            token: new_token(),
            timeout: Duration::from_secs(2),
            poll: Duration::from_millis(1),
            commands: 0,
            model: crate::k2::catalog::lookup(crate::k2::catalog::DEFAULT_MODEL).expect("the default model"),
            last_refusal: None,
        }
    }

    fn status(&self, regs: &mut dyn Registers) -> Result<Status> {
        let words = regs.read_v(self.base, p::STATUS_WORDS)?;
        let s = Status::parse(&words);
        if s.signature != p::SIGNATURE {
            return Err(Error::new(
                ErrorKind::Unsupported,
                crate::msg!(
                    "agent-no-helper",
                    base = self.base,
                    last = self.base + p::SIZE - 1,
                    got = format!("{:04X}", s.signature),
                    want = format!("{:04X}", p::SIGNATURE)
                ),
            )
            .hint(crate::msg!("agent-no-helper-hint", base = self.base)));
        }
        if s.version == 2 {
            return Err(Error::new(ErrorKind::Unsupported, crate::msg!("agent-helper-v2"))
                .hint(crate::msg!("agent-helper-old-hint", version = p::VERSION)));
        }
        if s.version == 1 {
            return Err(Error::new(ErrorKind::Unsupported, crate::msg!("agent-helper-v1"))
                .hint(crate::msg!("agent-helper-old-hint", version = p::VERSION)));
        }
        if s.version != p::VERSION {
            return Err(Error::new(
                ErrorKind::Unsupported,
                crate::msg!("agent-helper-version", got = s.version, want = p::VERSION),
            )
            .hint(crate::msg!("agent-helper-version-hint")));
        }
        Ok(s)
    }

    /// Checks that the helper is installed and running (signature, version, heartbeat).
    pub fn check(&mut self, regs: &mut dyn Registers, sleep: &mut dyn FnMut(Duration)) -> Result<Status> {
        let a = self.status(regs)?;
        let start = Instant::now();
        loop {
            let b = self.status(regs)?;
            if b.heartbeat != a.heartbeat {
                return Ok(b);
            }
            if start.elapsed() > self.timeout {
                return Err(stopped(self.timeout));
            }
            sleep(self.poll);
        }
    }

    /// Runs one command and returns its reply data. `sleep` waits between status reads.
    pub fn run(&mut self, regs: &mut dyn Registers, cmd: &Command, sleep: &mut dyn FnMut(Duration)) -> Result<Vec<u8>> {
        let what = describe(cmd);
        let start = Instant::now();
        let mut races = 0;
        self.last_refusal = None;
        loop {
            // 1. Wait until the mailbox is idle (no other client's request pending).
            let mut s = self.status(regs)?;
            let mut pending = self.pending(regs)?;
            while pending != s.acks[0].seq {
                if start.elapsed() > self.timeout {
                    return Err(Error::new(ErrorKind::State, crate::msg!("agent-mailbox-busy", what = what.as_str()))
                        .hint(crate::msg!(
                            "agent-mailbox-busy-hint",
                            pending = pending,
                            ms = self.timeout.as_millis() as u64
                        )));
                }
                sleep(self.poll);
                s = self.status(regs)?;
                pending = self.pending(regs)?;
            }
            // 2. One write: the whole request.
            let seq = p::next_seq(s.acks[0].seq);
            regs.write_v(self.base + p::OFF_REQUEST, &p::request_words(seq, self.token, cmd))?;
            self.commands += 1;
            // 3. Wait for our (sequence, token) among the acks.
            let sent = Instant::now();
            let heartbeat = s.heartbeat;
            loop {
                sleep(self.poll);
                let s = self.status(regs)?;
                if let Some((i, ack)) = s.find(seq, self.token) {
                    return match ack.result {
                        ResultCode::Ok if i == 0 => p::reply_of(cmd, &s.reply)
                            .ok_or_else(|| Error::link(crate::msg!("agent-reply-short", what = what.as_str()))),
                        ResultCode::Ok if matches!(cmd, Command::SmRead { .. } | Command::ReadRtc) => break, // reply overwritten: read again
                        ResultCode::Ok => Ok(Vec::new()),
                        rc => {
                            self.last_refusal = Some((rc, ack.cause));
                            let (why, hint) = p::reason(self.model, cmd, rc, ack.cause);
                            let e = Error::new(
                                ErrorKind::Refused,
                                crate::msg!(
                                    "agent-refused",
                                    what = what.as_str(),
                                    why = why,
                                    result = rc.code(),
                                    cause = ack.cause
                                ),
                            );
                            Err(match hint {
                                Some(h) => e.hint(h),
                                None => e,
                            })
                        }
                    };
                }
                let lost = s.acks.iter().any(|a| a.seq == seq && a.token != self.token);
                if lost {
                    break; // another client's request ran under our sequence number: ours did not run.
                }
                if sent.elapsed() > self.timeout {
                    let hint = if s.heartbeat == heartbeat {
                        crate::msg!("agent-no-ack-stopped")
                    } else {
                        crate::msg!("agent-no-ack-busy")
                    };
                    return Err(Error::new(
                        ErrorKind::Timeout,
                        crate::msg!("agent-no-ack", what = what.as_str(), ms = self.timeout.as_millis() as u64),
                    )
                    .hint(hint));
                }
            }
            races += 1;
            if races > RACE_RETRIES {
                return Err(Error::new(
                    ErrorKind::State,
                    crate::msg!("agent-mailbox-races", what = what.as_str(), races = races),
                )
                .hint(crate::msg!("agent-mailbox-races-hint")));
            }
        }
    }

    /// The request sequence currently in the mailbox.
    fn pending(&self, regs: &mut dyn Registers) -> Result<u16> {
        Ok(regs.read_v(self.base + p::OFF_REQUEST, 1)?[0])
    }
}

fn stopped(t: Duration) -> Error {
    Error::new(ErrorKind::State, crate::msg!("agent-heartbeat-stopped", ms = t.as_millis() as u64))
        .hint(crate::msg!("agent-heartbeat-stopped-hint"))
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::core::Clock;
    use crate::k2::operand::{Area, K2Operand};
    use crate::k2::sim::{self, K2Sim, SCAN_TIME};

    /// V words of a simulator whose clock moves one scan per sleep.
    struct SimRegs {
        sim: K2Sim,
        clock: Clock,
        writes: u32,
    }

    impl Registers for SimRegs {
        fn read_v(&mut self, vbyte: u32, count: u16) -> Result<Vec<u16>> {
            self.sim.advance();
            Ok((0..count as u32).map(|i| self.sim.mem.read(&K2Operand::word(Area::V, vbyte + 2 * i)) as u16).collect())
        }
        fn write_v(&mut self, vbyte: u32, words: &[u16]) -> Result<()> {
            self.sim.advance();
            self.writes += 1;
            for (i, w) in words.iter().enumerate() {
                self.sim.mem.write(&K2Operand::word(Area::V, vbyte + 2 * i as u32), *w as u32);
            }
            Ok(())
        }
    }

    fn regs(agent: bool) -> SimRegs {
        let clock = Clock::stepped();
        let mut s = sim::open("K205-16DT", clock.clone()).unwrap();
        if agent {
            s.enable_agent(p::DEFAULT_BASE).unwrap();
        }
        clock.step(SCAN_TIME);
        s.advance();
        SimRegs { sim: s, clock, writes: 0 }
    }

    #[test]
    fn commands_run_and_replies_come_back() {
        let mut r = regs(true);
        let clock = r.clock.clone();
        let mut c = AgentClient::new(p::DEFAULT_BASE);
        let mut tick = |_d: Duration| clock.step(SCAN_TIME);
        c.check(&mut r, &mut tick).unwrap();
        c.run(&mut r, &Command::SmWrite { start: 67, data: vec![0x85] }, &mut tick).unwrap();
        assert_eq!(r.sim.mem.sm_byte(67), 0x85);
        let reply = c.run(&mut r, &Command::SmRead { start: 66, len: 2 }, &mut tick).unwrap();
        assert_eq!(reply, vec![r.sim.mem.sm_byte(66), 0x85]);
        let e = c.run(&mut r, &Command::Hdef { hsc: 0, mode: 5 }, &mut tick).unwrap_err();
        assert_eq!(e.kind, ErrorKind::Refused);
        assert!(e.message.contains("HDEF 0, 5") && e.message.contains("mode"), "{e}");
        assert_eq!(r.writes, 3, "one write per command");
    }

    #[test]
    fn a_missing_helper_is_one_clear_error() {
        let mut r = regs(false);
        let clock = r.clock.clone();
        let mut c = AgentClient::new(p::DEFAULT_BASE);
        let e = c.run(&mut r, &Command::Pls(0), &mut |_| clock.step(SCAN_TIME)).unwrap_err();
        assert_eq!(e.kind, ErrorKind::Unsupported);
        assert!(e.hint.clone().unwrap().contains("plcsh agent il"), "{e}");
        assert_eq!(r.writes, 0, "nothing was written to a mailbox nobody reads");
    }

    #[test]
    fn a_version_1_helper_is_refused_by_what_it_gets_wrong() {
        // A PLC still running the version-1 helper: signature and version words, no program.
        let mut r = regs(false);
        r.write_v(p::DEFAULT_BASE, &[p::SIGNATURE, 1, 0]).unwrap();
        let clock = r.clock.clone();
        let mut c = AgentClient::new(p::DEFAULT_BASE);
        let e = c.run(&mut r, &Command::Pls(0), &mut |_| clock.step(SCAN_TIME)).unwrap_err();
        assert_eq!(e.kind, ErrorKind::Unsupported);
        assert!(e.message.contains("version 1") && e.message.contains("only the first time"), "{e}");
        assert!(e.hint.clone().unwrap().contains("plcsh agent il"), "{e}");
        assert_eq!(r.writes, 1, "only the test's own write: no request reached the old helper");
    }

    #[test]
    fn a_stopped_plc_is_told_apart() {
        let mut r = regs(true);
        let mut c = AgentClient::new(p::DEFAULT_BASE);
        c.timeout = Duration::from_millis(5);
        // The clock never moves: no scan, no heartbeat.
        let e = c.check(&mut r, &mut |d| std::thread::sleep(d)).unwrap_err();
        assert!(e.message.contains("heartbeat"), "{e}");
        let e = c.run(&mut r, &Command::Ping, &mut |d| std::thread::sleep(d)).unwrap_err();
        assert_eq!(e.kind, ErrorKind::Timeout);
        assert!(e.hint.clone().unwrap().contains("STOP"), "{e}");
    }

    #[test]
    fn a_lost_race_is_retried_and_the_winner_is_untouched() {
        let mut r = regs(true);
        let clock = r.clock.clone();
        let mut a = AgentClient::new(p::DEFAULT_BASE);
        let mut b = AgentClient::new(p::DEFAULT_BASE);
        b.token = a.token.wrapping_add(1).max(1);
        // B's write lands between A's write and the helper's scan, under the same sequence.
        let b_words = p::request_words(1, b.token, &Command::SmWrite { start: 77, data: vec![0x81] });
        let mut injected = false;
        let base = p::DEFAULT_BASE;
        let mut tick = |_d: Duration| clock.step(SCAN_TIME);
        struct Racer<'a> {
            inner: &'a mut SimRegs,
            inject: Option<Vec<u16>>,
            done: &'a mut bool,
            base: u32,
        }
        impl Registers for Racer<'_> {
            fn read_v(&mut self, v: u32, n: u16) -> Result<Vec<u16>> {
                self.inner.read_v(v, n)
            }
            fn write_v(&mut self, v: u32, w: &[u16]) -> Result<()> {
                self.inner.write_v(v, w)?;
                if let Some(bw) = self.inject.take() {
                    *self.done = true;
                    self.inner.write_v(self.base + p::OFF_REQUEST, &bw)?;
                }
                Ok(())
            }
        }
        let mut racer = Racer { inner: &mut r, inject: Some(b_words), done: &mut injected, base };
        a.run(&mut racer, &Command::SmWrite { start: 67, data: vec![0x85] }, &mut tick).unwrap();
        assert!(injected);
        assert_eq!(r.sim.mem.sm_byte(77), 0x81, "B's command ran, intact");
        assert_eq!(r.sim.mem.sm_byte(67), 0x85, "A's command ran after its retry");
    }
}
