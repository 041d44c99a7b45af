//! The helper mailbox protocol: how plcsh reaches SM registers and PLC
//! instructions on a real K2, whose Modbus map covers only I, Q, M, AI, AQ and V
//! (`../shared/spec/k2.md` §3). A small PLC-side helper program (`lib/k2_agent.il`) runs
//! every scan and executes commands that plcsh leaves in a mailbox in V memory.
//! Pure: this module only lays out and interprets the mailbox's words; the simulator's
//! helper ([`execute_scan`]) and the wire driver's client use it from both sides.
//!
//! Layout (byte offsets from the mailbox base, default VB3400 — below the E2PROM backup
//! area VB3648, §2.2.8; every field is a V word, S7 big-endian):
//!
//! | offset | field | written by |
//! |---|---|---|
//! | +0 | signature 16#4B41 ("KA") | helper, every scan |
//! | +2 | protocol version | helper, every scan |
//! | +4 | heartbeat (+1 per scan) | helper |
//! | +6 | reply length in bytes | helper |
//! | +8, +10, +12 | ack 0: sequence, token, result (latest) | helper |
//! | +14 … +30 | acks 1–3 (older, shifted down on each execution) | helper |
//! | +32 … +95 | reply data (64 bytes) of ack 0 | helper |
//! | +96 | request sequence | client |
//! | +98 | request token | client |
//! | +100 | command | client |
//! | +102, +104, +106 | arguments 1–3 | client |
//! | +108 … +171 | request data (64 bytes) | client |
//!
//! A client writes the whole request (+96…) in ONE Modbus write and reads acks and reply
//! (+0…+95) in ONE read; the PLC serves a Modbus request between scans, so each is atomic
//! with respect to the helper. The helper executes when request sequence ≠ ack-0 sequence,
//! then records (sequence, token, result), newest first. Two clients that race with the same
//! sequence number are told apart by their tokens: the loser finds another token under its
//! sequence, knows its command never ran (the helper runs a sequence number once), and
//! retries; the four-entry ack history lets a client confirm its command even when another
//! client's command ran right after it.

use crate::k2::catalog::Model;
use crate::k2::sm_map::{self, PTO_REGS};
use std::fmt;

/// Mailbox base when the device does not say (`agent=VB3400`).
pub const DEFAULT_BASE: u32 = 3400;
/// Bytes the mailbox occupies (VB3400…VB3571 by default).
pub const SIZE: u32 = 172;
pub const SIGNATURE: u16 = 0x4B41;
/// Version 3: a refusal is read where the PLC reports it — after PLS the channel's status bit
/// 4 (§3.4.2.2), after PSTOP the emergency-stop latch (§3.4.3.1), after HSC the counter's
/// table-fault bit (§3.3.2) — and every result word carries its cause in the high byte
/// (docs/agent.md, "Versions"). Version 2 took the CR after PLS as its success, which the
/// manual says PLS leaves unchanged (§3.4.2), so it would report a refused PLS as done;
/// version 1 also ran a repeated PLS or PSTOP only the first time. plcsh refuses both with a
/// message saying so.
pub const VERSION: u16 = 3;
/// Largest data block of one command (SM bytes read or written at once).
pub const DATA_MAX: usize = 64;
/// Number of acknowledgements kept.
pub const ACKS: usize = 4;

pub const OFF_SIGNATURE: u32 = 0;
pub const OFF_VERSION: u32 = 2;
pub const OFF_HEARTBEAT: u32 = 4;
pub const OFF_REPLY_LEN: u32 = 6;
pub const OFF_ACKS: u32 = 8;
pub const OFF_REPLY: u32 = 32;
pub const OFF_REQUEST: u32 = 96;
pub const OFF_REQ_DATA: u32 = 108;
/// Words a client reads to see acks and reply in one request.
pub const STATUS_WORDS: u16 = (OFF_REQUEST / 2) as u16;
/// Words a client writes for one request (header and full data block).
pub const REQUEST_WORDS: u16 = ((SIZE - OFF_REQUEST) / 2) as u16;
/// Scratch words the helper program (`super::il`) uses, right after the client-visible block.
pub const OFF_SCRATCH: u32 = SIZE;
/// Bytes the helper program needs in all (mailbox + scratch).
pub const TOTAL_SIZE: u32 = SIZE + 16;

/// One past the highest SM byte the helper reaches: the end of the highest register the
/// manual names (SMD262, §3.4.3.1 — plcsh's SM table, [`sm_map::names`]). The manual gives
/// no SM size; the S7-200's SMB0…SMB549 is not assumed.
pub fn sm_end() -> u32 {
    sm_map::names()
        .iter()
        .map(|n| {
            n.byte
                + match n.size {
                    sm_map::SmSize::Bit(_) | sm_map::SmSize::Byte => 1,
                    sm_map::SmSize::Word => 2,
                    sm_map::SmSize::DWord => 4,
                }
        })
        .max()
        .unwrap_or(1)
}

/// The SM bytes the manual's rows give `model`, sorted: SMB0 (the system bits) and the
/// registers of its own pulse outputs (§3.4.2.2, §3.4.3.1) and counters (§3.3.2, §3.3.3),
/// as plcsh's SM table names them. The helper reads and writes these bytes only, each by its
/// fixed address.
pub fn sm_rows(model: &Model) -> Vec<u32> {
    let mut v = vec![0];
    for r in PTO_REGS.iter().filter(|r| model.pto(r.channel).is_some()) {
        v.extend([r.status, r.control, r.pos_control]);
        v.extend([r.cycle, r.width, r.profile].iter().flat_map(|&a| a..a + 2));
        v.extend([r.count, r.pos_cv, r.pos_new_cv].iter().flat_map(|&a| a..a + 4));
    }
    for r in sm_map::HSC_REGS.iter().filter(|r| model.hsc(r.channel).is_some()) {
        v.extend([r.status, r.control, r.mpv_control, r.segment]);
        v.extend(r.table..r.table + 2);
        v.extend([r.cv, r.pv].iter().flat_map(|&a| a..a + 4));
    }
    v.sort_unstable();
    v.dedup();
    v
}

/// The SM blocks of the mailbox's data area, (first byte, one past the last register's last
/// byte), in order, the same for every model (the bytes between two blocks are no register): SM byte b of block (s, e) travels in request or reply data byte b − s, so the
/// helper copies each byte by its fixed address (no pointer). Made greedily from the
/// registers of every channel (a register never straddles two blocks), each block at most
/// [`DATA_MAX`] bytes.
pub fn sm_blocks() -> Vec<(u32, u32)> {
    let mut regs: Vec<(u32, u32)> = sm_map::names()
        .iter()
        .filter(|n| !matches!(n.size, sm_map::SmSize::Bit(_)))
        .map(|n| {
            let len = match n.size {
                sm_map::SmSize::Word => 2,
                sm_map::SmSize::DWord => 4,
                _ => 1,
            };
            (n.byte, n.byte + len)
        })
        .collect();
    regs.sort_unstable();
    let mut blocks: Vec<(u32, u32)> = Vec::new();
    for (a, b) in regs {
        match blocks.last_mut() {
            Some(last) if a < last.1 => last.1 = last.1.max(b),
            Some(last) if b - last.0 <= DATA_MAX as u32 => last.1 = b,
            _ => blocks.push((a, b)),
        }
    }
    if let Some(first) = blocks.first_mut() {
        first.0 = 0;
    }
    blocks
}

/// The block (first, end) SM byte `b` travels in: the last that starts at or before it.
pub fn block_of(b: u32) -> (u32, u32) {
    let blocks = sm_blocks();
    *blocks.iter().rev().find(|(s, _)| *s <= b).unwrap_or(&blocks[0])
}

/// The bytes a read reply holds for `cmd` (the reply carries the whole block: SM byte b at
/// b − the block's first byte); other commands' replies as they are.
pub fn reply_of(cmd: &Command, reply: &[u8]) -> Option<Vec<u8>> {
    match cmd {
        Command::SmRead { start, len } => {
            let off = (*start as u32 - block_of(*start as u32).0) as usize;
            reply.get(off..off + *len as usize).map(<[u8]>::to_vec)
        }
        _ => Some(reply.to_vec()),
    }
}

/// Parses a mailbox base (`VB3400`, `3400`): even, with the mailbox and the helper's
/// scratch words below the E2PROM backup area (§2.2.8), so the helper never wears it.
pub fn parse_base(text: &str) -> Result<u32, String> {
    let t = text.trim().to_ascii_uppercase();
    let n: u32 = t
        .trim_start_matches('%')
        .trim_start_matches("VB")
        .parse()
        .map_err(|_| crate::msg!("agent-base-not-vb", text = text, base = DEFAULT_BASE).to_string())?;
    let total = TOTAL_SIZE;
    // `n + total` in u64: a base near u32::MAX must be refused, not wrap past the check.
    if !n.is_multiple_of(2) || n as u64 + total as u64 > crate::k2::catalog::EEPROM_FIRST as u64 {
        return Err(crate::msg!("agent-base-range", total = total, eeprom = crate::k2::catalog::EEPROM_FIRST, n = n)
            .to_string());
    }
    Ok(n)
}

/// Command codes.
#[derive(Clone, Debug, PartialEq, Eq)]
pub enum Command {
    /// Write `data` to SM bytes from `start`.
    SmWrite { start: u16, data: Vec<u8> },
    /// Read `len` SM bytes from `start`.
    SmRead { start: u16, len: u16 },
    /// Execute PLS for a pulse output channel.
    Pls(u8),
    /// Execute HDEF (counter, mode).
    Hdef { hsc: u8, mode: u8 },
    /// Execute HSC for a counter.
    Hsc(u8),
    /// Emergency stop of a position channel (PSTOP).
    Pstop(u8),
    /// SET_RTC with an 8-byte BCD buffer.
    SetRtc([u8; 8]),
    /// READ_RTC into an 8-byte BCD buffer.
    ReadRtc,
    /// Does nothing; proves the helper runs.
    Ping,
}

impl Command {
    pub fn code(&self) -> u16 {
        match self {
            Command::SmWrite { .. } => 1,
            Command::SmRead { .. } => 2,
            Command::Pls(_) => 3,
            Command::Hdef { .. } => 4,
            Command::Hsc(_) => 5,
            Command::Pstop(_) => 6,
            Command::SetRtc(_) => 7,
            Command::ReadRtc => 8,
            Command::Ping => 9,
        }
    }

    /// (args, data) of the request block.
    fn args(&self) -> ([u16; 3], Vec<u8>) {
        match self {
            Command::SmWrite { start, data } => {
                // SM byte b travels at data byte b − its block's first byte.
                let off = (*start as u32 - block_of(*start as u32).0) as usize;
                let mut d = vec![0; off];
                d.extend_from_slice(data);
                ([*start, data.len() as u16, 0], d)
            }
            Command::SmRead { start, len } => ([*start, *len, 0], Vec::new()),
            Command::Pls(n) | Command::Hsc(n) | Command::Pstop(n) => ([*n as u16, 0, 0], Vec::new()),
            Command::Hdef { hsc, mode } => ([*hsc as u16, *mode as u16, 0], Vec::new()),
            Command::SetRtc(b) => ([0, 8, 0], b.to_vec()),
            Command::ReadRtc | Command::Ping => ([0, 0, 0], Vec::new()),
        }
    }

    /// Decodes a request block (the helper's side, for `model`): the request words are
    /// refused by the first row of [`checks`] that matches — the very rows the helper program
    /// is generated from ([`super::il`]), so the two give the same verdict on every request.
    /// A refusal comes with its cause: the row's number (1-based), as the helper writes it
    /// into the result word's high byte.
    pub fn decode(
        model: &Model,
        code: u16,
        args: [u16; 3],
        data: &[u8; DATA_MAX],
    ) -> Result<Command, (ResultCode, u8)> {
        if let Some((i, c)) = checks(model).iter().enumerate().find(|(_, c)| c.refuses(code, args)) {
            return Err((c.result, i as u8 + 1));
        }
        let len = args[1] as usize;
        Ok(match code {
            1 => {
                let off = (args[0] as u32 - block_of(args[0] as u32).0) as usize;
                let bytes = data.get(off..off + len).ok_or((ResultCode::BadRange, 0))?;
                Command::SmWrite { start: args[0], data: bytes.to_vec() }
            }
            2 => Command::SmRead { start: args[0], len: args[1] },
            3 => Command::Pls(args[0] as u8),
            4 => {
                Command::Hdef { hsc: args[0] as u8, mode: u8::try_from(args[1]).map_err(|_| (ResultCode::BadMode, 0))? }
            }
            5 => Command::Hsc(args[0] as u8),
            6 => Command::Pstop(args[0] as u8),
            7 => {
                let mut b = [0u8; 8];
                b.copy_from_slice(&data[..8]);
                Command::SetRtc(b)
            }
            8 => Command::ReadRtc,
            9 => Command::Ping,
            _ => return Err((ResultCode::UnknownCommand, 0)),
        })
    }
}

/// A request word a check reads.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Field {
    Command,
    Arg1,
    Arg2,
}

impl Field {
    fn of(self, code: u16, args: [u16; 3]) -> u16 {
        match self {
            Field::Command => code,
            Field::Arg1 => args[0],
            Field::Arg2 => args[1],
        }
    }

    /// Byte offset of the word in the mailbox.
    pub fn offset(self) -> u32 {
        match self {
            Field::Command => OFF_REQUEST + 4,
            Field::Arg1 => OFF_REQUEST + 6,
            Field::Arg2 => OFF_REQUEST + 8,
        }
    }

    pub fn name(self) -> &'static str {
        match self {
            Field::Command => "command",
            Field::Arg1 => "argument 1",
            Field::Arg2 => "argument 2",
        }
    }
}

/// What a check tests. Request words are unsigned (0…65535), and every bound is at most
/// [`INT_MAX`]: the helper has only the S7-200-style INT word compares (`LDW<` …), which
/// read a word of 32768 or more as a negative number, so it tests "below `lo`" with a signed
/// compare that also catches those, and adds words only once both are known to be small.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Test {
    /// The word equals the value.
    Is(Field, u16),
    /// The word is below `lo` or above `hi`.
    Outside(Field, u16, u16),
    /// ARG1 + ARG2 is above the value (both bounded by earlier rows: no overflow).
    EndAbove(u16),
    /// ARG1 … ARG1 + ARG2 − 1 overlaps `lo` … `hi` − 1.
    Overlaps(u16, u16),
    /// Every request of the row's commands (the model has no such channel at all).
    Always,
    /// ARG1 is in `lo` … `hi` and ARG1 + ARG2 is above `end`: the range runs out of its
    /// SM block (both bounded by earlier rows: no overflow).
    Span(u16, u16, u16),
}

/// The largest INT: every bound in [`checks`] stays at or below it.
pub const INT_MAX: u16 = i16::MAX as u16;

/// One refusal rule of the helper.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct Check {
    /// The command codes it applies to (first, last), or every command.
    pub commands: Option<(u16, u16)>,
    pub test: Test,
    pub result: ResultCode,
    /// Why, for the program's comments and docs/agent.md (ASCII: the program is pasted
    /// into KincoBuilder): always English, the program's language.
    pub why: String,
    /// The same reason in the current language, for a refusal a person reads ([`reason`]).
    pub said: String,
}

/// A row's reason: (English for the program and the docs, the current language for a person).
macro_rules! row_msg {
    ($id:literal $(, $k:ident = $v:expr)* $(,)?) => {
        (
            crate::msg!(lang: crate::core::msg::Lang::En, $id $(, $k = $v)*).text,
            crate::msg!($id $(, $k = $v)*).text,
        )
    };
}

impl Check {
    fn new(commands: Option<(u16, u16)>, test: Test, result: ResultCode, (why, said): (String, String)) -> Check {
        Check { commands, test, result, why, said }
    }
}

impl Check {
    /// Does this row refuse the request? Unsigned, in u32: nothing wraps.
    pub fn refuses(&self, code: u16, args: [u16; 3]) -> bool {
        if let Some((lo, hi)) = self.commands {
            if !(lo..=hi).contains(&code) {
                return false;
            }
        }
        let (a1, a2) = (args[0] as u32, args[1] as u32);
        match self.test {
            Test::Is(f, v) => f.of(code, args) == v,
            Test::Outside(f, lo, hi) => !(lo..=hi).contains(&f.of(code, args)),
            Test::EndAbove(limit) => a1 + a2 > limit as u32,
            Test::Overlaps(lo, hi) => a1 < hi as u32 && a1 + a2 > lo as u32,
            Test::Always => true,
            Test::Span(lo, hi, end) => (lo as u32..=hi as u32).contains(&a1) && a1 + a2 > end as u32,
        }
    }
}

/// The helper's refusals for `model`, in the order it makes them; the first that matches
/// gives the result. [`Command::decode`] and the helper program (il.rs) are both made from
/// this table, and docs/agent.md shows it for the default model ([`checks_markdown`]). Only
/// the channels and counters `model` has pass (§3.3.1, §3.4 tables), and only SM bytes of the
/// registers the manual names ([`sm_end`]).
pub fn checks(model: &Model) -> Vec<Check> {
    let end = sm_end() as u16;
    let sm_last = end - 1;
    let sm = Some((1, 2));
    let mut v = vec![
        Check::new(
            None,
            Test::Outside(Field::Command, 1, 9),
            ResultCode::UnknownCommand,
            row_msg!("agent-row-commands"),
        ),
        Check::new(Some((1, 1)), Test::Is(Field::Arg1, 0), ResultCode::ReadOnly, row_msg!("agent-row-smb0")),
        Check::new(
            sm,
            Test::Outside(Field::Arg2, 1, DATA_MAX as u16),
            ResultCode::BadRange,
            row_msg!("agent-row-length", max = DATA_MAX),
        ),
        Check::new(
            sm,
            Test::Outside(Field::Arg1, 0, sm_last),
            ResultCode::BadRange,
            row_msg!("agent-row-start", last = sm_last),
        ),
        Check::new(
            sm,
            Test::EndAbove(end),
            ResultCode::BadRange,
            row_msg!("agent-row-end", last = sm_last, dword = sm_last - 3),
        ),
    ];
    for (s, e) in sm_blocks() {
        if e < end as u32 {
            v.push(Check::new(
                sm,
                Test::Span(s as u16, e as u16 - 1, e as u16),
                ResultCode::BadRange,
                row_msg!("agent-row-block", first = s, last = e - 1),
            ));
        }
    }
    let rows = sm_rows(model);
    let mut b = 1;
    while b < end as u32 {
        if rows.contains(&b) {
            b += 1;
            continue;
        }
        let gap = b;
        while b < end as u32 && !rows.contains(&b) {
            b += 1;
        }
        let name = if b - gap == 1 { format!("SMB{gap}") } else { format!("SMB{gap}..SMB{}", b - 1) };
        v.push(Check::new(
            sm,
            Test::Overlaps(gap as u16, b as u16),
            ResultCode::BadRange,
            row_msg!("agent-row-gap", bytes = name.as_str(), model = model.name),
        ));
    }
    for r in PTO_REGS.iter().filter(|r| model.pto(r.channel).is_some()) {
        let at = r.pos_cv as u16;
        v.push(Check::new(
            Some((1, 1)),
            Test::Overlaps(at, at + 4),
            ResultCode::ReadOnly,
            row_msg!("agent-row-pos-cv", at = at),
        ));
    }
    // Pulse outputs (`pto`) or high-speed counters, 0..n-1.
    let channels = |n: usize, cmds: (u16, u16), pto: bool| {
        let m = model.name;
        let said = match (n, pto) {
            (0, true) => row_msg!("agent-row-no-pto", model = m),
            (0, false) => row_msg!("agent-row-no-hsc", model = m),
            (_, true) => row_msg!("agent-row-pto", model = m, last = n - 1),
            (_, false) => row_msg!("agent-row-hsc", model = m, last = n - 1),
        };
        let test = if n == 0 { Test::Always } else { Test::Outside(Field::Arg1, 0, n as u16 - 1) };
        Check::new(Some(cmds), test, ResultCode::BadChannel, said)
    };
    // The catalogue numbers channels and counters from 0 without gaps.
    debug_assert!(model.pto.iter().enumerate().all(|(i, c)| c.channel as usize == i));
    debug_assert!(model.hsc.iter().enumerate().all(|(i, c)| c.channel as usize == i));
    v.push(channels(model.pto.len(), (3, 3), true));
    v.push(channels(model.hsc.len(), (4, 5), false));
    v.push(channels(model.pto.len(), (6, 6), true));
    v
}

/// The checks as a Markdown table (docs/agent.md holds it; a test keeps the two equal).
pub fn checks_markdown(model: &Model) -> String {
    let mut s =
        String::from("| # | commands | refused when (words unsigned) | result | why |\n|---|---|---|---|---|\n");
    for (i, c) in checks(model).iter().enumerate() {
        let cmds = match c.commands {
            None => "all".to_string(),
            Some((a, b)) if a == b => a.to_string(),
            Some((a, b)) if b == a + 1 => format!("{a}, {b}"),
            Some((a, b)) => format!("{a}…{b}"),
        };
        let test = match c.test {
            Test::Is(f, v) => format!("{} = {v}", f.name()),
            Test::Outside(f, lo, hi) => format!("{} not in {lo}…{hi}", f.name()),
            Test::EndAbove(l) => format!("argument 1 + argument 2 > {l}"),
            Test::Overlaps(lo, hi) => format!("bytes argument 1 … argument 1 + argument 2 − 1 meet {lo}…{}", hi - 1),
            Test::Always => "always".to_string(),
            Test::Span(lo, hi, e) => format!("argument 1 in {lo}…{hi} and argument 1 + argument 2 > {e}"),
        };
        s.push_str(&format!("| {} | {cmds} | {test} | {} {} | {} |\n", i + 1, c.result.code(), c.result.name(), c.why));
    }
    s
}

/// The helper's result codes.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum ResultCode {
    Ok,
    UnknownCommand,
    BadRange,
    ReadOnly,
    BadChannel,
    BadMode,
    InstructionFailed,
    BadClock,
    /// The instruction ran and the register the manual names for its outcome reports a
    /// refusal; the cause ([`StatusCause`]) says which register.
    StatusBit,
    Other(u16),
}

/// Which status register reported a refusal (the cause byte of [`ResultCode::StatusBit`]).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum StatusCause {
    /// After PLS: the channel's status bit 4, "cycle time or pulse count invalid" (§3.4.2.2).
    PtoInvalid = 1,
    /// After PSTOP: the emergency-stop bit SM201.7 … did not latch (§3.4.3.1).
    NotLatched = 2,
    /// After HSC: the counter's status bit 3, "multi-PV table fault" (§3.3.2).
    PvTable = 3,
    /// PLS found the channel's enable bit SM67.7 … clear and the channel idle (PTO and PWM
    /// idle bits SM66.7, SM66.3 …, §3.4.2.2): it had nothing to stop and started nothing. The
    /// manual calls this no error; plcsh reports it as it does in process.
    NothingToDo = 4,
}

impl ResultCode {
    pub fn code(self) -> u16 {
        match self {
            ResultCode::Ok => 0,
            ResultCode::UnknownCommand => 1,
            ResultCode::BadRange => 2,
            ResultCode::ReadOnly => 3,
            ResultCode::BadChannel => 4,
            ResultCode::BadMode => 5,
            ResultCode::InstructionFailed => 6,
            ResultCode::BadClock => 7,
            ResultCode::StatusBit => 8,
            ResultCode::Other(c) => c,
        }
    }

    /// A short name (docs/agent.md's table of checks).
    pub fn name(self) -> &'static str {
        match self {
            ResultCode::Ok => "done",
            ResultCode::UnknownCommand => "unknown command",
            ResultCode::BadRange => "bad range",
            ResultCode::ReadOnly => "read-only",
            ResultCode::BadChannel => "no such channel",
            ResultCode::BadMode => "no such mode",
            ResultCode::InstructionFailed => "instruction failed",
            ResultCode::BadClock => "bad date or time",
            ResultCode::StatusBit => "status bit",
            ResultCode::Other(_) => "other",
        }
    }

    pub fn from_code(c: u16) -> ResultCode {
        match c {
            0 => ResultCode::Ok,
            1 => ResultCode::UnknownCommand,
            2 => ResultCode::BadRange,
            3 => ResultCode::ReadOnly,
            4 => ResultCode::BadChannel,
            5 => ResultCode::BadMode,
            6 => ResultCode::InstructionFailed,
            7 => ResultCode::BadClock,
            8 => ResultCode::StatusBit,
            c => ResultCode::Other(c),
        }
    }
}

impl fmt::Display for ResultCode {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        let m = match self {
            ResultCode::Ok => crate::msg!("agent-result-done"),
            ResultCode::UnknownCommand => crate::msg!("agent-result-unknown-command"),
            ResultCode::BadRange => crate::msg!("agent-result-bad-range"),
            ResultCode::ReadOnly => crate::msg!("agent-result-read-only"),
            ResultCode::BadChannel => crate::msg!("agent-result-bad-channel"),
            ResultCode::BadMode => crate::msg!("agent-result-bad-mode"),
            ResultCode::InstructionFailed => crate::msg!("agent-result-instruction-failed"),
            ResultCode::BadClock => crate::msg!("agent-result-bad-clock"),
            ResultCode::StatusBit => crate::msg!("agent-result-status-bit"),
            ResultCode::Other(c) => crate::msg!("agent-result-other", code = *c),
        };
        f.write_str(&m)
    }
}

/// Why the helper answered `result` with `cause` to `cmd` on `model`: (message, hint), in
/// the words plcsh uses for the same refusal in process (the simulator's messages and the
/// manual's sections), so a refusal reads the same whichever way the command went.
pub fn reason(model: &Model, cmd: &Command, result: ResultCode, cause: u8) -> (String, Option<String>) {
    let pto = |n: u8| PTO_REGS.iter().find(|r| r.channel == n);
    match (result, cmd) {
        (ResultCode::StatusBit, Command::Pls(n)) if cause == StatusCause::PtoInvalid as u8 => match pto(*n) {
            Some(r) => (
                // The rule in the message is sm_map::PTO_INVALID_RULE's, in each language.
                crate::msg!("agent-pls-invalid", status = r.status, n = *n).to_string(),
                Some(
                    crate::msg!("agent-pls-invalid-hint", cycle = r.cycle, control = r.control, count = r.count)
                        .to_string(),
                ),
            ),
            None => (result.to_string(), None),
        },
        (ResultCode::StatusBit, Command::Pls(n)) if cause == StatusCause::NothingToDo as u8 => match pto(*n) {
            Some(r) => {
                let (m, h) = sm_map::pls_did_nothing(r);
                (m, Some(h))
            }
            None => (result.to_string(), None),
        },
        (ResultCode::StatusBit, Command::Pstop(n)) if cause == StatusCause::NotLatched as u8 => match pto(*n) {
            Some(r) => (
                crate::msg!("agent-pstop-not-latched", control = r.pos_control, n = *n).to_string(),
                Some(crate::msg!("agent-pstop-not-latched-hint").to_string()),
            ),
            None => (result.to_string(), None),
        },
        (ResultCode::StatusBit, Command::Hsc(n)) if cause == StatusCause::PvTable as u8 => {
            match sm_map::HSC_REGS.iter().find(|r| r.channel == *n) {
                Some(r) => (
                    crate::msg!("agent-hsc-pv-table", status = r.status, n = *n).to_string(),
                    Some(crate::msg!("agent-hsc-pv-table-hint", table = r.table).to_string()),
                ),
                None => (result.to_string(), None),
            }
        }
        (ResultCode::ReadOnly, Command::SmWrite { start, data }) => {
            let (s, e) = (*start as u32, *start as u32 + data.len().max(1) as u32);
            let written = if e - s == 1 { format!("SMB{s}") } else { format!("SMB{s}…SMB{}", e - 1) };
            if s == 0 {
                let (m, h) = sm_map::smb0_read_only(&written);
                return (m, Some(h));
            }
            match PTO_REGS.iter().find(|r| s < r.pos_cv + 4 && r.pos_cv < e) {
                Some(r) => {
                    let named = if s == r.pos_cv && e == s + 4 { format!("SMD{s}") } else { written };
                    let (m, h) = sm_map::pos_cv_read_only(r, &named);
                    (m, Some(h))
                }
                None => (result.to_string(), None),
            }
        }
        _ => match checks(model).get((cause as usize).wrapping_sub(1)) {
            Some(c) if c.result == result => (
                crate::msg!("agent-result-because", result = result.to_string(), why = c.said.replace("..", "…")).text,
                None,
            ),
            _ => (result.to_string(), None),
        },
    }
}

/// The words of a request block (written at base + OFF_REQUEST in one Modbus write).
pub fn request_words(seq: u16, token: u16, cmd: &Command) -> Vec<u16> {
    let (args, data) = cmd.args();
    let mut w = vec![seq, token, cmd.code(), args[0], args[1], args[2]];
    let mut bytes = data;
    bytes.resize(DATA_MAX, 0);
    w.extend(bytes.chunks(2).map(|c| u16::from_be_bytes([c[0], c[1]])));
    w
}

/// One acknowledgement.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct Ack {
    pub seq: u16,
    pub token: u16,
    pub result: ResultCode,
    /// Why (the result word's high byte): for a refused request the row of [`checks`]
    /// (1-based), for [`ResultCode::StatusBit`] a [`StatusCause`]; 0 when the result has
    /// one cause.
    pub cause: u8,
}

/// The result word the helper writes: the code in the low byte, the cause in the high one.
pub fn result_word(result: ResultCode, cause: u8) -> u16 {
    (result.code() & 0xFF) | (cause as u16) << 8
}

/// What a client sees in one status read (words from base + 0).
#[derive(Clone, Debug, PartialEq)]
pub struct Status {
    pub signature: u16,
    pub version: u16,
    pub heartbeat: u16,
    pub acks: [Ack; ACKS],
    /// Reply data of `acks[0]`.
    pub reply: Vec<u8>,
}

impl Status {
    /// Parses the words read from base + 0 (at least STATUS_WORDS of them).
    pub fn parse(words: &[u16]) -> Status {
        let ack = |i: usize| {
            let o = (OFF_ACKS / 2) as usize + 3 * i;
            let r = words[o + 2];
            Ack { seq: words[o], token: words[o + 1], result: ResultCode::from_code(r & 0xFF), cause: (r >> 8) as u8 }
        };
        let len = (words[(OFF_REPLY_LEN / 2) as usize] as usize).min(DATA_MAX);
        let reply: Vec<u8> = words[(OFF_REPLY / 2) as usize..(OFF_REQUEST / 2) as usize]
            .iter()
            .flat_map(|w| w.to_be_bytes())
            .take(len)
            .collect();
        Status {
            signature: words[0],
            version: words[1],
            heartbeat: words[2],
            acks: [ack(0), ack(1), ack(2), ack(3)],
            reply,
        }
    }

    /// The acknowledgement of (seq, token), if the history still has it.
    pub fn find(&self, seq: u16, token: u16) -> Option<(usize, Ack)> {
        self.acks.iter().enumerate().find(|(_, a)| a.seq == seq && a.token == token).map(|(i, a)| (i, *a))
    }
}

/// The next sequence number after `seq` (never 0, so a cleared mailbox is never "acked").
pub fn next_seq(seq: u16) -> u16 {
    match seq.wrapping_add(1) {
        0 => 1,
        s => s,
    }
}

/// Byte access to the V area the helper runs in (the simulator's memory, or a test buffer).
pub trait VMemory {
    fn v(&self) -> &[u8];
    fn v_mut(&mut self) -> &mut [u8];
}

fn word(v: &[u8], at: usize) -> u16 {
    u16::from_be_bytes([v[at], v[at + 1]])
}

fn put(v: &mut [u8], at: usize, w: u16) {
    v[at..at + 2].copy_from_slice(&w.to_be_bytes());
}

/// One scan of the helper program, as `lib/k2_agent.il` does it: refresh signature,
/// version and heartbeat; if a new request is waiting, run it through `exec` and record
/// the acknowledgement. `exec` returns reply data or a result code.
pub fn execute_scan(
    model: &Model,
    mem: &mut dyn VMemory,
    base: u32,
    exec: &mut dyn FnMut(Command) -> Result<Vec<u8>, ResultCode>,
) -> Option<Ack> {
    let b = base as usize;
    let v = mem.v_mut();
    put(v, b, SIGNATURE);
    put(v, b + 2, VERSION);
    let hb = word(v, b + 4).wrapping_add(1);
    put(v, b + 4, hb);
    let req = b + OFF_REQUEST as usize;
    let seq = word(v, req);
    let ack0 = word(v, b + OFF_ACKS as usize);
    if seq == ack0 {
        return None;
    }
    let token = word(v, req + 2);
    let code = word(v, req + 4);
    let args = [word(v, req + 6), word(v, req + 8), word(v, req + 10)];
    let mut data = [0u8; DATA_MAX];
    data.copy_from_slice(&v[b + OFF_REQ_DATA as usize..b + SIZE as usize]);
    let ((result, cause), reply) = match Command::decode(model, code, args, &data) {
        Ok(cmd) => {
            let read = match cmd {
                Command::SmRead { start, .. } => Some(start as u32 - block_of(start as u32).0),
                _ => None,
            };
            match exec(cmd) {
                // A read's reply is the whole block: SM byte b at b − the block's first byte.
                Ok(r) => match read {
                    Some(off) => {
                        let mut full = vec![0; DATA_MAX];
                        full[off as usize..off as usize + r.len()].copy_from_slice(&r);
                        ((ResultCode::Ok, 0), full)
                    }
                    None => ((ResultCode::Ok, 0), r),
                },
                Err(rc) => ((rc, 0), Vec::new()),
            }
        }
        Err(rc) => (rc, Vec::new()),
    };
    let v = mem.v_mut();
    // Shift the history down (ack 3 falls off), newest first.
    let acks = b + OFF_ACKS as usize;
    v.copy_within(acks..acks + 18, acks + 6);
    let mut r = reply;
    r.truncate(DATA_MAX);
    put(v, b + OFF_REPLY_LEN as usize, r.len() as u16);
    let rep = b + OFF_REPLY as usize;
    v[rep..rep + r.len()].copy_from_slice(&r);
    v[rep + r.len()..rep + DATA_MAX].fill(0);
    put(v, acks + 2, token);
    put(v, acks + 4, result_word(result, cause));
    put(v, acks, seq);
    Some(Ack { seq, token, result, cause })
}

#[cfg(test)]
mod tests {
    use super::*;

    fn model() -> &'static Model {
        crate::k2::catalog::lookup(crate::k2::catalog::DEFAULT_MODEL).unwrap()
    }

    #[test]
    fn a_base_near_the_top_of_u32_is_refused_not_wrapped() {
        assert!(parse_base("VB4294967110").is_err());
        assert!(parse_base("VB4294967294").is_err());
        assert_eq!(parse_base("VB3400"), Ok(3400));
    }

    struct Buf(Vec<u8>);
    impl VMemory for Buf {
        fn v(&self) -> &[u8] {
            &self.0
        }
        fn v_mut(&mut self) -> &mut [u8] {
            &mut self.0
        }
    }

    fn write_request(m: &mut Buf, seq: u16, token: u16, cmd: &Command) {
        for (i, w) in request_words(seq, token, cmd).iter().enumerate() {
            put(&mut m.0, (DEFAULT_BASE + OFF_REQUEST) as usize + 2 * i, *w);
        }
    }

    fn status(m: &Buf) -> Status {
        let b = DEFAULT_BASE as usize;
        let words: Vec<u16> = (0..STATUS_WORDS as usize).map(|i| word(&m.0, b + 2 * i)).collect();
        Status::parse(&words)
    }

    #[test]
    fn layout_fits_below_the_backup_area_and_in_one_request() {
        const { assert!(DEFAULT_BASE + SIZE <= crate::k2::catalog::EEPROM_FIRST) };
        // One FC03 read and one FC16 write each (k2.md §3: at most 100 words per request).
        const { assert!(STATUS_WORDS <= 100 && REQUEST_WORDS <= 100) };
        assert_eq!(request_words(1, 2, &Command::Ping).len(), REQUEST_WORDS as usize);
    }

    #[test]
    fn a_scan_executes_a_new_request_once() {
        let mut m = Buf(vec![0; 4096]);
        let mut ran = Vec::new();
        let cmd = Command::SmWrite { start: 67, data: vec![0x85] };
        write_request(&mut m, 1, 0xBEEF, &cmd);
        let ack = execute_scan(model(), &mut m, DEFAULT_BASE, &mut |c| {
            ran.push(c);
            Ok(Vec::new())
        });
        assert_eq!(ack, Some(Ack { seq: 1, token: 0xBEEF, result: ResultCode::Ok, cause: 0 }));
        assert!(execute_scan(model(), &mut m, DEFAULT_BASE, &mut |_| panic!("ran twice")).is_none());
        assert_eq!(ran, vec![cmd]);
        let s = status(&m);
        assert_eq!((s.signature, s.version, s.heartbeat), (SIGNATURE, VERSION, 2));
        assert_eq!(s.find(1, 0xBEEF).unwrap().1.result, ResultCode::Ok);
    }

    #[test]
    fn reply_data_and_history() {
        let mut m = Buf(vec![0; 4096]);
        write_request(&mut m, 1, 7, &Command::SmRead { start: 66, len: 3 });
        execute_scan(model(), &mut m, DEFAULT_BASE, &mut |_| Ok(vec![0x80, 1, 2]));
        let cmd = Command::SmRead { start: 66, len: 3 };
        assert_eq!(reply_of(&cmd, &status(&m).reply), Some(vec![0x80, 1, 2]), "at SMB66's place in its block");
        write_request(&mut m, 2, 9, &Command::Pls(0));
        execute_scan(model(), &mut m, DEFAULT_BASE, &mut |_| Ok(Vec::new()));
        let s = status(&m);
        assert_eq!(s.acks[0].seq, 2);
        assert_eq!(s.find(1, 7).map(|x| x.0), Some(1), "the older ack is still found");
        assert!(s.reply.is_empty());
    }

    #[test]
    fn a_racing_client_is_told_apart_by_its_token() {
        let mut m = Buf(vec![0; 4096]);
        // A and B both saw ack 0 and chose sequence 1; B's write landed last.
        write_request(&mut m, 1, 0xA, &Command::Pls(0));
        write_request(&mut m, 1, 0xB, &Command::Pls(1));
        let mut ran = Vec::new();
        execute_scan(model(), &mut m, DEFAULT_BASE, &mut |c| {
            ran.push(c);
            Ok(vec![])
        });
        let s = status(&m);
        assert!(s.find(1, 0xA).is_none(), "A learns its command did not run");
        assert!(s.find(1, 0xB).is_some());
        assert_eq!(ran, vec![Command::Pls(1)], "only B's command ran, intact");
    }

    #[test]
    fn bad_requests_get_result_codes_not_execution() {
        let mut m = Buf(vec![0; 4096]);
        write_request(&mut m, 1, 1, &Command::Pls(9));
        let a = execute_scan(model(), &mut m, DEFAULT_BASE, &mut |_| panic!("must not run")).unwrap();
        assert_eq!(a.result, ResultCode::BadChannel);
        put(&mut m.0, (DEFAULT_BASE + OFF_REQUEST + 4) as usize, 77);
        put(&mut m.0, (DEFAULT_BASE + OFF_REQUEST) as usize, 2);
        let a = execute_scan(model(), &mut m, DEFAULT_BASE, &mut |_| panic!("must not run")).unwrap();
        assert_eq!(a.result, ResultCode::UnknownCommand);
        assert!(ResultCode::BadRange.to_string().contains("64 bytes"));
        write_request(&mut m, 3, 1, &Command::SmWrite { start: 0, data: vec![1] });
        assert_eq!(
            execute_scan(model(), &mut m, DEFAULT_BASE, &mut |_| panic!("SMB0")).unwrap().result,
            ResultCode::ReadOnly
        );
        write_request(&mut m, 4, 1, &Command::SmRead { start: 260, len: 20 });
        assert_eq!(
            execute_scan(model(), &mut m, DEFAULT_BASE, &mut |_| panic!("past")).unwrap().result,
            ResultCode::BadRange
        );
    }

    #[test]
    fn the_protocol_document_shows_the_checks_the_helper_makes() {
        let doc = include_str!("../../../docs/agent.md");
        let table = checks_markdown(model());
        assert!(doc.contains(&table), "docs/agent.md lacks the current table of checks:\n{table}");
    }

    /// The blocks run in order over SMB0…SMB265, none is longer than the data area, and no register of
    /// any channel straddles two of them.
    #[test]
    fn sm_blocks_tile_the_window_and_hold_whole_registers() {
        let blocks = sm_blocks();
        assert_eq!(blocks.first().unwrap().0, 0);
        assert_eq!(blocks.last().unwrap().1, sm_end());
        for w in blocks.windows(2) {
            assert!(w[0].1 <= w[1].0, "{w:?}");
        }
        for (s, e) in &blocks {
            assert!(e - s <= DATA_MAX as u32, "SMB{s}..SMB{e}");
        }
        for n in sm_map::names() {
            let len = match n.size {
                sm_map::SmSize::Word => 2,
                sm_map::SmSize::DWord => 4,
                _ => 1,
            };
            assert_eq!(block_of(n.byte), block_of(n.byte + len - 1), "SM byte {} ({})", n.byte, n.meaning);
        }
    }

    #[test]
    fn sequence_numbers_skip_zero() {
        assert_eq!(next_seq(u16::MAX), 1);
        assert_eq!(next_seq(5), 6);
    }
}
