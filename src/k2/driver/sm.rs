//! SM operands and PLC instructions on a wire K2, through the helper mailbox
//! (docs/agent.md) when the device has `agent=VB…`; without it they stay refused by the
//! Modbus map with a message naming the helper.
//!
//! Reads: the SM bytes the batch needs are fetched in runs of at most 64 bytes (one read
//! command each; small gaps are read through) into a shadow of the SM area, and every
//! operand is decoded from it. Reading copies SM bytes and disturbs nothing that runs.
//! Writes keep the user's order: each operand's bytes are encoded in the shadow and sent
//! as write commands, neighbouring operands merged into one command when they follow each
//! other in the batch and in memory. A bit (or bit group) is a read-modify-write of its byte,
//! through the helper, with the same race as bit writes over Modbus (README).

use super::{Failure, K2Wire};
use crate::core::{Error, ErrorKind, Operand, Result, Value};
use crate::k2::agent::client::{AgentClient, Registers};
use crate::k2::agent::protocol::{self, Command, ResultCode, StatusCause, DATA_MAX};
use crate::k2::instr::RtcTime;
use crate::k2::memory::Memory;
use crate::k2::modbus_map;
use crate::k2::operand::{Area, K2Operand, Width};
use crate::k2::sm_map::PTO_REGS;
use crate::msg;
use std::time::Duration;
use tokio_modbus::Request;

/// Gaps up to this many bytes are read through rather than split into two commands.
const READ_THROUGH: u32 = 8;

/// The shadow of the SM area the helper's replies are decoded from.
pub(super) fn shadow(len: u32) -> Memory {
    Memory {
        i: Vec::new(),
        q: Vec::new(),
        m: Vec::new(),
        v: Vec::new(),
        sm: vec![0; len as usize],
        ai: Vec::new(),
        aq: Vec::new(),
        t: Vec::new(),
        c: Vec::new(),
        tq: Vec::new(),
        cq: Vec::new(),
    }
}

/// The link's V words, for the mailbox client.
pub(super) struct VWords<'a>(pub(super) &'a mut K2Wire);

impl VWords<'_> {
    fn register(&self, vbyte: u32) -> Result<u16> {
        Ok(modbus_map::locate_read(&self.0.space, &K2Operand::word(Area::V, vbyte))?.start)
    }
    fn failed(&self, f: Failure, doing: &str) -> Error {
        match f {
            Failure::Link(e) => e,
            Failure::Exception(c) => Error::new(
                ErrorKind::Refused,
                msg!(
                    "k2-mailbox-refused",
                    doing = doing,
                    name = modbus_map::exception_name(c.into()),
                    code = format!("{:02}", u8::from(c))
                ),
            )
            .hint(match u8::from(c) {
                2 => msg!("k2-mailbox-refused-hint-2"),
                4 => msg!("k2-mailbox-refused-hint-4"),
                _ => msg!("k2-mailbox-refused-hint"),
            }),
        }
    }
}

impl Registers for VWords<'_> {
    fn read_v(&mut self, vbyte: u32, count: u16) -> Result<Vec<u16>> {
        let start = self.register(vbyte)?;
        match self.0.call(Request::ReadHoldingRegisters(start, count)) {
            Ok(tokio_modbus::Response::ReadHoldingRegisters(w)) if w.len() == count as usize => Ok(w),
            Ok(other) => Err(Error::link(msg!("k2-mailbox-unexpected-reply", reply = format!("{other:?}")))),
            Err(f) => Err(self.failed(f, "reading")),
        }
    }
    fn write_v(&mut self, vbyte: u32, words: &[u16]) -> Result<()> {
        let start = self.register(vbyte)?;
        self.0
            .call(Request::WriteMultipleRegisters(start, words.to_vec().into()))
            .map(|_| ())
            .map_err(|f| self.failed(f, "writing"))
    }
}

impl K2Wire {
    /// Runs one helper command, or explains that the device has no helper configured.
    pub(super) fn agent_run(&mut self, cmd: &Command, what: &str) -> Result<Vec<u8>> {
        let Some(mut client) = self.agent.take() else {
            return Err(Error::unsupported(msg!("k2-needs-helper", what = what)).hint(msg!("k2-needs-helper-hint")));
        };
        let poll = client.poll;
        let r = client.run(&mut VWords(self), cmd, &mut |_| std::thread::sleep(poll));
        self.agent = Some(client);
        r
    }

    /// Checks the helper (signature, version, running heartbeat) and reports it.
    pub fn agent_status(&mut self) -> Result<String> {
        let Some(mut client) = self.agent.take() else {
            return Err(Error::unsupported(msg!("k2-no-helper")).hint(msg!("k2-no-helper-hint")));
        };
        let poll = client.poll;
        let r = client.check(&mut VWords(self), &mut |_| std::thread::sleep(poll));
        let base = client.base;
        self.agent = Some(client);
        let s = r?;
        Ok(msg!(
            "k2-helper-status",
            version = s.version.to_string(),
            base = base,
            heartbeat = s.heartbeat.to_string(),
            seq = s.acks[0].seq.to_string(),
            result = s.acks[0].result.to_string()
        )
        .into())
    }

    /// True when this batch needs the helper (it has SM operands and a helper is set).
    pub(super) fn uses_agent(&self, op: &K2Operand) -> bool {
        op.area == Area::SM && self.agent.is_some()
    }

    /// Reads SM operands through the helper.
    pub(super) fn read_sm(&mut self, ops: &[Operand]) -> Result<Vec<Value>> {
        let k2: Vec<K2Operand> = ops.iter().map(|o| K2Operand::from_key(o.key)).collect();
        let mut ranges: Vec<(u32, u32)> = k2.iter().map(|o| (o.byte, o.byte + o.width.bytes())).collect();
        ranges.sort();
        // The helper copies the bytes of the registers the manual gives the model, block by
        // block (docs/agent.md): a run stays in one block and reads through no other byte.
        let rows = protocol::sm_rows(self.space.model);
        let named = |s: u32, e: u32| (s..e).all(|b| rows.contains(&b));
        let mut runs: Vec<(u32, u32)> = Vec::new();
        for (s, e) in ranges {
            match runs.last_mut() {
                Some(last)
                    if s <= last.1 + READ_THROUGH
                        && e - last.0 <= DATA_MAX as u32
                        && protocol::block_of(last.0) == protocol::block_of(e.max(1) - 1)
                        && named(last.1.min(s), s.max(last.1)) =>
                {
                    last.1 = last.1.max(e)
                }
                _ => runs.push((s, e)),
            }
        }
        for (s, e) in runs {
            let mut at = s;
            while at < e {
                let block_end = protocol::block_of(at).1;
                let len = (e - at).min(DATA_MAX as u32).min(block_end.max(at + 1) - at);
                let what = format!("reading SMB{at}…SMB{}", at + len - 1);
                let bytes = self.agent_run(&Command::SmRead { start: at as u16, len: len as u16 }, &what)?;
                self.sm_shadow.sm[at as usize..(at + len) as usize].copy_from_slice(&bytes[..len as usize]);
                at += len;
            }
        }
        Ok(ops.iter().zip(&k2).map(|(o, k)| o.dtype.decode(self.sm_shadow.read(k))).collect())
    }

    /// Writes SM operands through the helper, in order.
    pub(super) fn write_sm(&mut self, items: &[(Operand, Value)]) -> Result<()> {
        // (start, bytes) commands, in order.
        let mut cmds: Vec<(u32, Vec<u8>)> = Vec::new();
        for (o, v) in items {
            let k = K2Operand::from_key(o.key);
            let (start, len) = (k.byte, k.width.bytes());
            if matches!(k.width, Width::Bit(_) | Width::Group { .. }) {
                // Only part of the byte(s) is written: fetch them first (read-modify-write).
                self.read_sm(&[K2Operand::new(Area::SM, Width::Byte, start).to_core()])?;
                if len > 1 {
                    self.read_sm(&[K2Operand::new(Area::SM, Width::Byte, start + len - 1).to_core()])?;
                }
            }
            self.sm_shadow.write(&k, o.dtype.encode(v));
            let bytes = self.sm_shadow.sm[start as usize..(start + len) as usize].to_vec();
            match cmds.last_mut() {
                Some((s, b))
                    if *s + b.len() as u32 == start
                        && b.len() + bytes.len() <= DATA_MAX
                        && protocol::block_of(*s) == protocol::block_of(start + len - 1) =>
                {
                    b.extend(bytes)
                }
                _ => cmds.push((start, bytes)),
            }
        }
        for (start, data) in cmds {
            // One command per block (an operand across two blocks, SMW61, is two commands).
            let (mut at, mut rest) = (start, &data[..]);
            while !rest.is_empty() {
                let n = ((protocol::block_of(at).1.max(at + 1) - at) as usize).min(rest.len());
                let what = format!("writing SMB{at}…SMB{}", at as usize + n - 1);
                if let Err(e) = self.agent_run(&Command::SmWrite { start: at as u16, data: rest[..n].to_vec() }, &what)
                {
                    // A read-only register, in the words the simulator uses for the operand written.
                    let read_only =
                        self.agent.as_ref().and_then(|c| c.last_refusal).is_some_and(|r| r.0 == ResultCode::ReadOnly);
                    let model = self.space.model;
                    let span = (at, at + n as u32);
                    let named = items.iter().map(|(o, _)| K2Operand::from_key(o.key)).find_map(|k| {
                        let hit = k.byte < span.1 && span.0 < k.byte + k.width.bytes();
                        if hit {
                            crate::k2::sim::sm_read_only(model, &k)
                        } else {
                            None
                        }
                    });
                    return Err(match named {
                        Some(w) if read_only => w,
                        _ => e,
                    });
                }
                at += n as u32;
                rest = &rest[n..];
            }
        }
        Ok(())
    }

    pub(super) fn instruction(&mut self, cmd: Command, what: &str) -> Result<String> {
        match self.agent_run(&cmd, what) {
            Ok(_) => Ok(msg!("k2-done-by-helper", what = what).into()),
            Err(e) => match self.agent.as_ref().and_then(|c| c.last_refusal) {
                // HSC ran and counts; its status bit 3 reports a fault in the multi-PV table
                // (manual §3.3.2), which the simulator notes in process: the same outcome
                // and the same note here.
                Some((ResultCode::StatusBit, cause)) if cause == StatusCause::PvTable as u8 => {
                    let Command::Hsc(n) = cmd else { return Err(e) };
                    match self.pv_table_note(n) {
                        Some(note) => Ok(msg!("agent-done-with-note", what = what, note = note).text),
                        None => Err(e),
                    }
                }
                Some((rc, cause)) => Err(self.in_process_words(&cmd, rc, cause).unwrap_or(e)),
                None => Err(e),
            },
        }
    }

    /// A refusal the helper reported, in the words the simulator uses in process for the
    /// same refusal, where the helper's result, its cause and registers read back after it
    /// give them: a channel or mode the model lacks (the catalogue's words); after PLS the
    /// control byte and the cycle and count PLS loaded (the update bits set: a value PLS
    /// kept from before is in no register) for status bit 4, and every channel's control
    /// byte for "did nothing". `None` leaves the helper's own words.
    fn in_process_words(&mut self, cmd: &Command, rc: ResultCode, cause: u8) -> Option<Error> {
        use crate::k2::sim::{self as sim, pto};
        let model = self.space.model;
        let byte = |at: u32| K2Operand::new(Area::SM, Width::Byte, at).to_core();
        match (rc, cmd) {
            (ResultCode::BadChannel, Command::Pls(n) | Command::Pstop(n)) => Some(sim::no_pulse_channel(model, *n)),
            (ResultCode::BadChannel, Command::Hdef { hsc: n, .. } | Command::Hsc(n)) => {
                Some(sim::no_counter(model, *n))
            }
            (ResultCode::BadMode | ResultCode::InstructionFailed, Command::Hdef { hsc, mode })
                if crate::k2::sm_map::hsc_mode(*hsc, *mode).is_none() =>
            {
                Some(sim::hsc::no_mode(*hsc, *mode))
            }
            (ResultCode::StatusBit, Command::Pls(n)) if cause == StatusCause::PtoInvalid as u8 => {
                let r = PTO_REGS.iter().find(|r| r.channel == *n)?;
                let spec = model.pto(*n)?;
                let ops = [
                    byte(r.control),
                    K2Operand::new(Area::SM, Width::Word, r.cycle).to_core(),
                    K2Operand::new(Area::SM, Width::DWord, r.count).to_core(),
                ];
                self.read_sm(&ops).ok()?;
                let m = &self.sm_shadow;
                let c = m.sm_byte(r.control);
                if c & pto::ctl::PWM == 0 && c & pto::ctl::MULTI != 0 {
                    // A multi-segment PTO: the table PLS read, SMW168 … through the helper and the
                    // table itself over Modbus (V), checked as in process.
                    self.read_sm(&[K2Operand::new(Area::SM, Width::Word, r.profile).to_core()]).ok()?;
                    let start = self.sm_shadow.sm_word(r.profile);
                    let v = self.profile_table(start).ok()?;
                    return pto::profile(r, spec, c, start, &v).err().map(|w| w.error(r));
                }
                Some(pto::explain(r, spec, c, m.sm_word(r.cycle), m.sm_dword(r.count)).error(r))
            }
            (ResultCode::StatusBit, Command::Pls(n)) if cause == StatusCause::NothingToDo as u8 => {
                let r = PTO_REGS.iter().find(|r| r.channel == *n)?;
                let spec = model.pto(*n)?;
                for p in model.pto {
                    self.read_sm(&[byte(PTO_REGS[p.channel as usize].control)]).ok()?;
                }
                let m = &self.sm_shadow;
                let others: Vec<_> = model
                    .pto
                    .iter()
                    .filter(|p| p.channel != *n)
                    .map(|p| {
                        let o = PTO_REGS[p.channel as usize];
                        (o, *p, m.sm_byte(o.control))
                    })
                    .collect();
                Some(pto::did_nothing(r, spec, m.sm_byte(r.control)).hint(sim::did_nothing_hint(r, &others)))
            }
            _ => None,
        }
    }

    /// A table in V that PLS or HSC reads (a multi-segment profile, §3.4.2.1; a PV table,
    /// §3.3.3): a copy of the V area holding the count byte at the odd offset `start` and the
    /// `entry` bytes of each of its entries, read over Modbus (V is in the Modbus map, §3.2);
    /// the rest of the copy is 0. Nothing past the count byte is read when the start or the
    /// count breaks the table's rules (the check then names that).
    fn v_table(&mut self, start: u16, entry: u32, max: u8) -> Result<Vec<u8>> {
        let len = self.space.area_len(Area::V);
        let mut v = vec![0u8; len as usize];
        let start = start as u32;
        if start.is_multiple_of(2) || start >= len {
            return Ok(v);
        }
        let w = VWords(self).read_v(start - 1, 1)?;
        let n = w.first().map_or(0, |w| *w as u8);
        v[start as usize] = n;
        let end = start + 1 + entry * n as u32;
        if n == 0 || n > max || end > len {
            return Ok(v);
        }
        // Entries from the even byte after the count, at most 120 words a read.
        let mut at = start + 1;
        while at < end {
            let words = ((end - at).div_ceil(2)).min(120);
            let got = VWords(self).read_v(at, words as u16)?;
            for (k, w) in got.iter().enumerate() {
                let b = at as usize + 2 * k;
                for (i, x) in w.to_be_bytes().into_iter().enumerate() {
                    if let Some(slot) = v.get_mut(b + i) {
                        *slot = x;
                    }
                }
            }
            at += 2 * words;
        }
        Ok(v)
    }

    /// A multi-segment profile table at `start` (8 bytes a segment, §3.4.2.1).
    fn profile_table(&mut self, start: u16) -> Result<Vec<u8>> {
        self.v_table(start, 8, crate::k2::sim::pto::MAX_SEGMENTS)
    }

    /// HSC `n` ran and the helper found its multi-PV fault bit set (result 8, cause 3): the
    /// note the simulator adds in process, from the registers and the V table read back
    /// (manual §3.3.2: the status bit reports a fault in the table; the counter runs, as
    /// HSC started it). `None` when a read fails or the table reads as valid now.
    fn pv_table_note(&mut self, n: u8) -> Option<String> {
        use crate::k2::sim::hsc;
        let r = crate::k2::sm_map::HSC_REGS.iter().find(|r| r.channel == n)?;
        let ops = [
            K2Operand::new(Area::SM, Width::Byte, r.mpv_control).to_core(),
            K2Operand::new(Area::SM, Width::Word, r.table).to_core(),
        ];
        self.read_sm(&ops).ok()?;
        let (b, start) = (self.sm_shadow.sm_byte(r.mpv_control), self.sm_shadow.sm_word(r.table));
        if b & hsc::mpv::LOAD == 0 {
            return Some(hsc::no_table_note(r));
        }
        let v = self.v_table(start, 4, hsc::MAX_PVS).ok()?;
        hsc::read_table(&v, start as u32, b & hsc::mpv::RELATIVE != 0, b & hsc::mpv::CYCLIC != 0)
            .err()
            .map(|e| hsc::table_fault_note(r, &e))
    }

    pub(super) fn rtc_read(&mut self) -> Result<RtcTime> {
        let b = self.agent_run(&Command::ReadRtc, "READ_RTC")?;
        let buf: [u8; 8] =
            b.get(..8).and_then(|s| s.try_into().ok()).ok_or_else(|| Error::link(msg!("k2-rtc-reply-short")))?;
        RtcTime::from_bcd8(&buf).map_err(|m| Error::new(ErrorKind::Refused, msg!("k2-rtc-reads-as", value = m)))
    }
}

/// The helper client for `agent=VB…` (validated like `plcsh agent il --base`).
pub(super) fn client(text: &str, timeout: Duration, model: &'static crate::k2::catalog::Model) -> Result<AgentClient> {
    let base = crate::k2::agent::protocol::parse_base(text).map_err(Error::usage)?;
    let mut c = AgentClient::new(base);
    c.model = model;
    c.timeout = timeout.max(Duration::from_secs(1));
    Ok(c)
}
