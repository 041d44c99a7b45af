//! The helper program's promises, checked on the program the PLC runs: a
//! simulated K2 executing `lib/k2_agent.il` in its scan engine, driven one scan at a time,
//! with every scan checked against the protocol. Its checks: the CPU stays in RUN, the
//! heartbeat moves once per scan, a waiting request is acknowledged in that scan — or, when
//! it repeats the instruction command of the request executed before it, in the next (it
//! waits a scan with every instruction's enable low: docs/agent.md) — with the verdict of
//! [`Command::decode`] (the Rust twin of the program's checks), the reply is what
//! the command asked for, and no memory outside the mailbox and the SM bytes the request
//! names changes. The fuzz target `agent_mailbox` and the mailbox property test both drive
//! the helper through this type, so a request that breaks a promise is a crash for the one
//! and a failure for the other.

use super::program::Mode;
use super::K2Sim;
use crate::core::Clock;
use crate::k2::agent::il::{REPEAT_WAITS, TOTAL_SIZE};
use crate::k2::agent::protocol::{self as p, Ack, Command, ResultCode, Status, DATA_MAX};
use crate::k2::instr::RtcTime;
use crate::k2::memory::Memory;
use crate::k2::sm_map::{self, HSC_REGS, PTO_REGS};
use std::time::Duration;

/// What the helper may answer to a request.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Verdict {
    /// Exactly this result.
    Is(ResultCode),
    /// Done, or this failure of the PLC instruction (which depends on the channel's state).
    OkOr(ResultCode),
    /// Done, or either of these failures (HSC: its ENO, or the table-fault bit, §3.3.2).
    OkOrEither(ResultCode, ResultCode),
}

impl Verdict {
    pub fn allows(self, r: ResultCode) -> bool {
        match self {
            Verdict::Is(x) => r == x,
            Verdict::OkOr(x) => r == ResultCode::Ok || r == x,
            Verdict::OkOrEither(x, y) => r == ResultCode::Ok || r == x || r == y,
        }
    }
}

/// A simulated K205-16DT running the helper, scan by scan.
pub struct AgentProbe {
    pub sim: K2Sim,
    clock: Clock,
    base: u32,
    token: u16,
    /// The command (one of [`REPEAT_WAITS`], low byte of its code) of the last request
    /// executed, if it was one that passed the checks: a request naming it waits one scan.
    last_instruction: Option<u8>,
    /// The last scan held a waiting request (the next one runs it).
    held: bool,
}

impl Default for AgentProbe {
    fn default() -> Self {
        Self::new()
    }
}

impl AgentProbe {
    /// The helper at the default base, after its first scan (it has announced itself).
    pub fn new() -> AgentProbe {
        let clock = Clock::stepped();
        let mut sim = super::open("K205-16DT", clock.clone()).expect("the default model");
        let base = p::DEFAULT_BASE;
        sim.enable_agent(base).expect("the default base");
        let mut probe = AgentProbe { sim, clock, base, token: 0x5AA5, last_instruction: None, held: false };
        probe.scan();
        probe
    }

    /// Runs exactly one scan: steps the virtual clock to the start of the next scan. A scan
    /// takes its cost-table time, at least the 1 ms minimum (one that runs HDEF about
    /// 1.2 ms), so a fixed step is not one scan.
    pub fn scan(&mut self) {
        let next = self.sim.plc().map_or(self.sim.last, |p| p.next_scan);
        let now = self.clock.now();
        let ack0 = self.word(p::OFF_ACKS);
        let code = self.word(p::OFF_REQUEST + 4);
        let holds = self.holds();
        self.clock.step(next.saturating_sub(now).max(Duration::from_nanos(1)));
        self.sim.advance();
        // Only the helper writes during a scan, and it executes only a request whose
        // sequence differs from ack 0's: ack 0 changed exactly when a request executed. An
        // instruction command that no check refused enabled its instruction.
        self.held = holds;
        if self.word(p::OFF_ACKS) != ack0 {
            let refused = p::checks(self.sim.model()).iter().any(|c| c.result == self.status().acks[0].result);
            let waits = (REPEAT_WAITS.0..=REPEAT_WAITS.1).contains(&code);
            self.last_instruction = (!refused && waits).then_some(code as u8);
        }
    }

    /// Whether the next scan holds the waiting request: it repeats the instruction command of
    /// the request executed before it and has not waited yet (the helper compares the
    /// command's low byte).
    fn holds(&self) -> bool {
        let waiting = self.word(p::OFF_REQUEST) != self.word(p::OFF_ACKS);
        waiting && !self.held && self.last_instruction == Some(self.word(p::OFF_REQUEST + 4) as u8)
    }

    /// Scans run so far.
    pub fn scans(&self) -> u64 {
        self.sim.plc().map_or(0, |p| p.stats.scans)
    }

    fn word(&self, off: u32) -> u16 {
        let at = (self.base + off) as usize;
        u16::from_be_bytes([self.sim.mem.v[at], self.sim.mem.v[at + 1]])
    }

    fn put(&mut self, off: u32, w: u16) {
        let at = (self.base + off) as usize;
        self.sim.mem.v[at..at + 2].copy_from_slice(&w.to_be_bytes());
    }

    /// The status block as a client reads it.
    pub fn status(&self) -> Status {
        let words: Vec<u16> = (0..p::STATUS_WORDS as u32).map(|i| self.word(2 * i)).collect();
        Status::parse(&words)
    }

    /// Writes bytes into the mailbox from its start, as a client may (any of them; at most
    /// the mailbox's size), then runs one checked scan.
    pub fn write_and_scan(&mut self, bytes: &[u8]) -> Result<Option<Ack>, String> {
        let n = bytes.len().min(p::SIZE as usize);
        let b = self.base as usize;
        self.sim.mem.v[b..b + n].copy_from_slice(&bytes[..n]);
        self.checked_scan()
    }

    /// Sends a request (the next sequence number, whatever the words say) and runs checked
    /// scans until it is acknowledged (two when the scan before executed one); returns the
    /// helper's result.
    pub fn request(&mut self, code: u16, args: [u16; 3], data: &[u8; DATA_MAX]) -> Result<ResultCode, String> {
        let seq = p::next_seq(self.word(p::OFF_ACKS));
        self.token = self.token.wrapping_mul(31).wrapping_add(7);
        let (token, o) = (self.token, p::OFF_REQUEST);
        for (k, w) in [seq, token, code, args[0], args[1], args[2]].into_iter().enumerate() {
            self.put(o + 2 * k as u32, w);
        }
        let at = (self.base + p::OFF_REQ_DATA) as usize;
        self.sim.mem.v[at..at + DATA_MAX].copy_from_slice(data);
        for _ in 0..2 {
            if let Some(a) = self.checked_scan()? {
                return Ok(a.result);
            }
        }
        Err(format!("request {code} {args:?} was not acknowledged"))
    }

    /// What the helper must answer to a request: [`Command::decode`]'s refusal, or for a
    /// command it accepts, what the PLC instruction does on this model.
    pub fn verdict(&self, code: u16, args: [u16; 3], data: &[u8; DATA_MAX]) -> Verdict {
        let model = self.sim.model();
        match Command::decode(model, code, args, data) {
            Err((r, _)) => Verdict::Is(r),
            Ok(Command::Hdef { hsc, mode }) => {
                let has = model.hsc.iter().any(|h| h.channel == hsc);
                Verdict::Is(if has && sm_map::hsc_mode(hsc, mode).is_some() {
                    ResultCode::Ok
                } else {
                    ResultCode::BadMode
                })
            }
            Ok(Command::Pls(ch)) if model.pto.iter().any(|c| c.channel == ch) => Verdict::OkOr(ResultCode::StatusBit),
            Ok(Command::Hsc(ch)) if model.hsc.iter().any(|h| h.channel == ch) => {
                Verdict::OkOrEither(ResultCode::InstructionFailed, ResultCode::StatusBit)
            }
            Ok(Command::Pls(_) | Command::Hsc(_)) => Verdict::Is(ResultCode::InstructionFailed),
            Ok(Command::SetRtc(b)) => {
                Verdict::Is(if RtcTime::from_bcd8(&b).is_ok() { ResultCode::Ok } else { ResultCode::BadClock })
            }
            Ok(_) => Verdict::Is(ResultCode::Ok),
        }
    }

    /// One scan, checked: see the module doc. The error names the broken promise.
    pub fn checked_scan(&mut self) -> Result<Option<Ack>, String> {
        let o = p::OFF_REQUEST;
        let (seq, token, code) = (self.word(o), self.word(o + 2), self.word(o + 4));
        let args = [self.word(o + 6), self.word(o + 8), self.word(o + 10)];
        let at = (self.base + p::OFF_REQ_DATA) as usize;
        let data: [u8; DATA_MAX] = self.sim.mem.v[at..at + DATA_MAX].try_into().expect("64 bytes");
        let before = self.status();
        let pending = seq != before.acks[0].seq && !self.holds();
        let verdict = pending.then(|| self.verdict(code, args, &data));
        let mem = self.sim.mem.clone();
        let scans = self.scans();
        self.scan();
        let what = format!("request {code} {args:?}");
        let plc = self.sim.plc().ok_or("no CPU")?;
        if plc.mode != Mode::Run || !plc.faults.is_empty() {
            return Err(format!("{what}: the CPU left RUN ({}): {:?}", plc.mode.name(), plc.faults));
        }
        if self.scans() != scans + 1 {
            return Err(format!("{what}: {} scans ran, not one", self.scans() - scans));
        }
        let after = self.status();
        if (after.signature, after.version) != (p::SIGNATURE, p::VERSION) {
            return Err(format!("{what}: the helper no longer announces itself"));
        }
        if after.heartbeat != before.heartbeat.wrapping_add(1) {
            return Err(format!("{what}: heartbeat {} after {}, not one beat", after.heartbeat, before.heartbeat));
        }
        let Some(verdict) = verdict else {
            if after.acks != before.acks {
                return Err(format!("{what}: acknowledged a request that was not waiting"));
            }
            return self.unchanged_outside(&mem, None).map(|_| None).map_err(|e| format!("{what}: {e}"));
        };
        let ack = after.acks[0];
        if (ack.seq, ack.token) != (seq, token) || after.acks[1..] != before.acks[..3] {
            return Err(format!("{what}: ack history {:?} after {:?}", after.acks, before.acks));
        }
        if !verdict.allows(ack.result) {
            return Err(format!("{what}: the helper answered {:?}, the protocol says {verdict:?}", ack.result));
        }
        let written = match (ack.result, code) {
            (ResultCode::Ok, 1) => Some((args[0] as usize, args[1] as usize)),
            _ => None,
        };
        self.reply_is_right(&what, ack.result, code, args, &data, written)?;
        if ack.result == ResultCode::Ok && (3..=7).contains(&code) {
            // A PLC instruction ran: its registers changed as it says; the rest of memory not.
            let all_sm = Some((0, crate::k2::catalog::SM_BYTES as usize));
            return self.unchanged_outside(&mem, all_sm).map(|_| Some(ack)).map_err(|e| format!("{what}: {e}"));
        }
        self.unchanged_outside(&mem, written).map(|_| Some(ack)).map_err(|e| format!("{what}: {e}"))
    }

    fn reply_is_right(
        &self,
        what: &str,
        result: ResultCode,
        code: u16,
        args: [u16; 3],
        data: &[u8; DATA_MAX],
        written: Option<(usize, usize)>,
    ) -> Result<(), String> {
        let reply = self.status().reply;
        let want_len = match (result, code) {
            (ResultCode::Ok, 2) => DATA_MAX,
            (ResultCode::Ok, 8) => 8,
            _ => 0,
        };
        if reply.len() != want_len {
            return Err(format!("{what}: a reply of {} bytes, not {want_len}", reply.len()));
        }
        let sm = &self.sim.mem.sm;
        let owned = cpu_owned();
        if result == ResultCode::Ok && code == 2 {
            // The reply is the block: SM byte b at b − the block's first byte.
            let start = args[0] as usize;
            let off = start - p::block_of(start as u32).0 as usize;
            for (k, b) in reply[off..off + args[1] as usize].iter().enumerate() {
                if !owned.contains(&(start + k)) && sm[start + k] != *b {
                    return Err(format!("{what}: reply byte {k} is {b}, SMB{} is {}", start + k, sm[start + k]));
                }
            }
        }
        if let Some((start, len)) = written {
            let off = start - p::block_of(start as u32).0 as usize;
            for (k, want) in data[off..off + len].iter().enumerate() {
                let byte = start + k;
                if !owned.contains(&byte) && !is_position_control(byte) && sm[byte] != *want {
                    return Err(format!("{what}: SMB{byte} is {}, the request wrote {want}", sm[byte]));
                }
            }
        }
        Ok(())
    }

    /// Nothing outside the mailbox (and the SM bytes `served`, start and length) changed,
    /// except what the CPU and the pulse and counter hardware own.
    fn unchanged_outside(&self, before: &Memory, served: Option<(usize, usize)>) -> Result<(), String> {
        let now = &self.sim.mem;
        let (lo, hi) = (self.base as usize, (self.base + TOTAL_SIZE) as usize);
        if let Some(i) = (0..now.v.len()).find(|&i| !(lo..hi).contains(&i) && now.v[i] != before.v[i]) {
            return Err(format!("VB{i} changed from {} to {}", before.v[i], now.v[i]));
        }
        for (name, a, b) in [("M", &now.m, &before.m), ("AI", &now.ai, &before.ai), ("AQ", &now.aq, &before.aq)] {
            if let Some(i) = (0..a.len()).find(|&i| a[i] != b[i]) {
                return Err(format!("{name}B{i} changed"));
            }
        }
        if now.t != before.t || now.c != before.c {
            return Err("a timer or counter value changed".into());
        }
        let owned = cpu_owned();
        let served = served.map_or(0..0, |(s, l)| s..s + l);
        if let Some(i) =
            (0..now.sm.len()).find(|&i| !served.contains(&i) && !owned.contains(&i) && now.sm[i] != before.sm[i])
        {
            return Err(format!("SMB{i} changed from {} to {} outside the request's range", before.sm[i], now.sm[i]));
        }
        Ok(())
    }
}

/// SM bytes the CPU and the hardware write on their own: SMB0 (system bits), SMB1
/// (arithmetic status), SMW22–SMW26 (scan times), and the pulse outputs' and counters'
/// status bytes and current values (they move between scans).
fn cpu_owned() -> Vec<usize> {
    let mut v: Vec<usize> = vec![0, 1, 22, 23, 24, 25, 26, 27];
    for r in PTO_REGS {
        v.push(r.status as usize);
        v.extend((r.pos_cv..r.pos_cv + 4).map(|b| b as usize));
    }
    for r in HSC_REGS {
        v.push(r.status as usize);
        v.push(r.segment as usize);
        v.extend((r.cv..r.cv + 4).map(|b| b as usize));
    }
    v
}

/// A position control byte (SMB201 …): its "clear" and "load" bits act and reset at once.
fn is_position_control(byte: usize) -> bool {
    PTO_REGS.iter().any(|r| r.pos_control as usize == byte)
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::k2::catalog::SM_BYTES;
    use std::time::Instant;

    use crate::core::test_rng::Rng;

    /// Every field at 0, 1, max − 1, max, max + 1 of every limit the table names, and at
    /// 32767, 32768, 65534, 65535.
    fn edges() -> Vec<u16> {
        let mut v =
            vec![0, 1, 2, 3, 4, 5, 6, 7, 8, 9, 10, 63, 64, 65, 255, 256, 32766, 32767, 32768, 32769, 65534, 65535];
        let sm = SM_BYTES as u16;
        v.extend([sm - 65, sm - 64, sm - 63, sm - 2, sm - 1, sm, sm + 1]);
        for r in PTO_REGS {
            let a = r.pos_cv as u16;
            v.extend([a - 64, a - 1, a, a + 3, a + 4]);
        }
        v.sort_unstable();
        v.dedup();
        v
    }

    /// Sums that land on both sides of the table's limit, of 32767 and of 65535.
    fn crossing(arg2: u16, d: u16) -> Vec<u16> {
        [SM_BYTES as u16, 32767, 32768, 0]
            .iter()
            .flat_map(|t| {
                [t.wrapping_sub(arg2).wrapping_sub(d), t.wrapping_sub(arg2), t.wrapping_sub(arg2).wrapping_add(d)]
            })
            .collect()
    }

    fn data(rng: &mut Rng, code: u16) -> [u8; DATA_MAX] {
        let mut d = [0u8; DATA_MAX];
        for b in d.iter_mut() {
            *b = rng.next_u64() as u8;
        }
        if code == 7 && rng.below(2) == 0 {
            let bcd = |n: u64| (((n / 10) << 4) | (n % 10)) as u8;
            let t = [rng.below(100), 1 + rng.below(12), 1 + rng.below(28), rng.below(24), rng.below(60), rng.below(60)];
            for (k, v) in t.iter().enumerate() {
                d[k] = bcd(*v);
            }
        }
        d
    }

    fn run(probe: &mut AgentProbe, code: u16, args: [u16; 3], data: &[u8; DATA_MAX]) {
        if let Err(e) = probe.request(code, args, data) {
            panic!("{e}");
        }
    }

    /// Every command code near the known ones and at the INT and word limits; for the
    /// commands that read both arguments (1, 2 and HDEF's 4) every pair of edges and every
    /// crossing sum, for the others every first argument with a few second ones.
    #[test]
    fn every_boundary_request_gets_the_protocols_verdict() {
        let start = Instant::now();
        let mut probe = AgentProbe::new();
        let mut rng = Rng(0x30);
        let edges = edges();
        let mut n = 0;
        for code in (0..=10).chain([32767, 32768, 65535]) {
            let both = matches!(code, 1 | 2 | 4);
            let seconds = if both { edges.clone() } else { vec![0, 1, 65535] };
            for &a2 in &seconds {
                let mut firsts = edges.clone();
                if both {
                    firsts.extend(crossing(a2, 1));
                }
                for a1 in firsts {
                    let d = data(&mut rng, code);
                    run(&mut probe, code, [a1, a2, rng.next_u64() as u16], &d);
                    n += 1;
                }
            }
        }
        assert!(n > 5_000, "{n} requests");
        eprintln!("{n} boundary requests in {:?}", start.elapsed());
    }

    /// Random and boundary requests in equal measure; returns the results seen.
    fn random_requests(seed: u64, count: usize) -> Vec<usize> {
        let mut probe = AgentProbe::new();
        let mut rng = Rng(seed);
        let edges = edges();
        let mut seen = vec![0usize; 8];
        for _ in 0..count {
            let code = match rng.below(4) {
                0 | 1 => 1 + rng.below(9) as u16,
                2 => rng.pick(&edges),
                _ => rng.next_u64() as u16,
            };
            let field = |rng: &mut Rng| match rng.below(3) {
                0 => rng.pick(&edges),
                1 => rng.below(600) as u16,
                _ => rng.next_u64() as u16,
            };
            let a2 = field(&mut rng);
            let a1 = if rng.below(4) == 0 {
                let sums = crossing(a2, 1 + rng.below(3) as u16);
                rng.pick(&sums)
            } else {
                field(&mut rng)
            };
            let d = data(&mut rng, code);
            let r =
                probe.request(code, [a1, a2, rng.next_u64() as u16], &d).unwrap_or_else(|e| panic!("seed {seed}: {e}"));
            seen[r.code().min(7) as usize] += 1;
        }
        seen
    }

    #[test]
    fn random_requests_get_the_protocols_verdict() {
        let start = Instant::now();
        let seen = random_requests(0x5EED_0030, 5_000);
        // Every result the helper gives was reached (the generator is not stuck in refusals).
        assert!(seen.iter().all(|n| *n > 0), "results seen: {seen:?}");
        eprintln!("5 000 requests in {:?}; results {seen:?}", start.elapsed());
    }

    /// The 100 000-request figure in BENCHMARKS.md: `cargo test --release --lib a_hundred_thousand -- --ignored`.
    #[test]
    #[ignore = "slow in a debug build: 100 000 scans"]
    fn a_hundred_thousand_random_requests_get_the_protocols_verdict() {
        let start = Instant::now();
        let seen = random_requests(0x5EED_0031, 100_000);
        eprintln!("100 000 requests in {:?}; results {seen:?}", start.elapsed());
    }

    /// The probe fails the helper that compared words as signed INTs (the program as it was
    /// before the fix): the same checks without the guards for words of 32768 and more.
    #[test]
    fn the_probe_catches_a_helper_that_reads_large_words_as_negative() {
        let il = crate::k2::agent::il::program(AgentProbe::new().sim.model(), p::DEFAULT_BASE);
        let arg1 = format!("%VW{}", p::DEFAULT_BASE + p::Field::Arg1.offset());
        let signed = il.replace(&format!("LDW<    {arg1}, INT#0 "), &format!("LDW<    {arg1}, INT#-32768 "));
        assert_ne!(signed, il);
        let mut probe = AgentProbe::new();
        probe.sim.load_helper(&signed, "signed.il").unwrap();
        // It copies no SM byte by pointer any more, so it no longer faults: it acknowledges
        // a read it should have refused.
        let e = probe.request(2, [40000, 1, 0], &[0; DATA_MAX]).unwrap_err();
        assert!(e.contains("the protocol says"), "{e}");
        let mut probe = AgentProbe::new();
        probe.sim.load_helper(&signed, "signed.il").unwrap();
        let e = probe.request(3, [40000, 0, 0], &[0; DATA_MAX]).unwrap_err();
        assert!(e.contains("the protocol says"), "{e}");
    }
}
