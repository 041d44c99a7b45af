//! The UMPK terminal protocol, pure: bytes in, typed values out, no I/O (manual §4.1,
//! digest `../shared/spec/umpk.md` §3–§4). The driver (computer side) and the simulator
//! (PLC side) both use it, so they cannot drift apart.
//!
//! - Commands `?NNCC` (§4.1, Table 6): every byte as two ASCII hex digits, NN + CC ≡ 0 mod
//!   256 (the listed `?0000` … `?0CF4`).
//! - Replies: `R`, an error letter (`E` checksum, `U` unknown command, `C` illegal
//!   character; during programming also `L`, `A`, `W`, `X`, §4.2), or a packet `#NN…CC`
//!   (NN data bytes as hex pairs, then a checksum). Program info (§4.1.5) is `#` and 22
//!   ASCII characters with neither length nor checksum.
//! - Echo (§4.1.2/§4.1.3): with echo on every received byte comes back and a reply ends in
//!   CR LF; with echo off neither. [`parse_exchange`] reads both, skipping real-time monitor
//!   packets that were already on their way and the `R` a reset or power-up sends.
//! - The real-time monitor packet (§4.1.11, Table 7): 30 binary bytes.
//!
//! Choices where the manual is silent (recorded here, used by both sides):
//! - Packet checksums ("контрольная сумма по модулю 256") use the commands' rule: the bytes
//!   from NN through CC sum to 0 mod 256. The monitor packet's byte 29 makes all 30 bytes
//!   sum to 0. A reader also accepts a plain sum mod 256 (with or without NN / the header),
//!   since the manual does not say which one the firmware computes.
//! - Bit order in the I/O, timer, counter and marker areas: the first byte holds the lowest
//!   numbers, bit 0 the lowest (I0 = byte 0 bit 0, I8 = byte 1 bit 0).
//! - The status word's bit positions (the manual gives only the order W H R E P T, high to
//!   low): [`StatusLayout`], default W=5 H=4 R=3 E=2 P=1 T=0, configurable.
//! - The error history (§4.1.8) lists the newest code first.

use crate::core::msg::Msg;
use crate::msg;
use std::fmt;

/// 57600 baud 8N1, no flow control (§3.6).
pub const BAUD: u32 = 57_600;
/// Time one byte takes on the line at 57600 baud 8N1 (10 bits), in nanoseconds.
pub const BYTE_NS: u64 = 10 * 1_000_000_000 / BAUD as u64;
/// The real-time monitor packet (Table 7).
pub const MONITOR_LEN: usize = 30;
pub const MONITOR_HEADER: u8 = 0xAA;
/// Program info length (§4.1.5, §4.2.4).
pub const INFO_LEN: usize = 22;
/// The timing figures' unit (§4.1.13): one count is 0.271 µs.
pub const TIMING_US_PER_COUNT: f64 = 0.271;

/// A terminal command (Table 6).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Command {
    Reset = 0x00,
    EchoOn = 0x01,
    EchoOff = 0x02,
    Info = 0x03,
    ProgramInfo = 0x04,
    Inputs = 0x05,
    Outputs = 0x06,
    Errors = 0x07,
    ClearErrors = 0x08,
    Programming = 0x09,
    MonitorStart = 0x0A,
    MonitorStop = 0x0B,
    Timing = 0x0C,
}

/// What a command's reply looks like.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Shape {
    /// `R` (or an error letter).
    Ack,
    /// `#NN…CC` with NN data bytes.
    Packet(u8),
    /// `#` and 22 ASCII characters.
    Text,
}

impl Command {
    pub const ALL: [Command; 13] = [
        Command::Reset,
        Command::EchoOn,
        Command::EchoOff,
        Command::Info,
        Command::ProgramInfo,
        Command::Inputs,
        Command::Outputs,
        Command::Errors,
        Command::ClearErrors,
        Command::Programming,
        Command::MonitorStart,
        Command::MonitorStop,
        Command::Timing,
    ];

    pub fn code(self) -> u8 {
        self as u8
    }

    pub fn from_code(code: u8) -> Option<Command> {
        Command::ALL.get(code as usize).copied()
    }

    /// The manual's name (Table 6), in the current language.
    pub fn name(self) -> Msg {
        let key = match self {
            Command::Reset => "reset",
            Command::EchoOn => "echo-on",
            Command::EchoOff => "echo-off",
            Command::Info => "info",
            Command::ProgramInfo => "program-info",
            Command::Inputs => "inputs",
            Command::Outputs => "outputs",
            Command::Errors => "errors",
            Command::ClearErrors => "clear-errors",
            Command::Programming => "programming",
            Command::MonitorStart => "monitor-start",
            Command::MonitorStop => "monitor-stop",
            Command::Timing => "timing",
        };
        msg!("umpk-command-name", command = key)
    }

    pub fn shape(self) -> Shape {
        match self {
            Command::Info => Shape::Packet(6),
            Command::ProgramInfo => Shape::Text,
            Command::Inputs | Command::Outputs | Command::Timing => Shape::Packet(4),
            Command::Errors => Shape::Packet(8),
            _ => Shape::Ack,
        }
    }

    /// Available in Programming mode. Table 6 has two availability columns — «Раб»/«Ожид»
    /// (Work or Wait, one column) and «Прг» — and marks only the first four commands in
    /// the second: reset is how Programming mode is left (§3.2, §4.1.10), and program info
    /// answers in Wait (§4.1.5), so every command works in Work and Wait.
    pub fn in_programming(self) -> bool {
        matches!(self, Command::Reset | Command::EchoOn | Command::EchoOff | Command::Info)
    }

    /// Asking again changes nothing (the driver may repeat it after a garbled reply).
    pub fn repeatable(self) -> bool {
        !matches!(self, Command::Reset | Command::Programming | Command::ClearErrors | Command::MonitorStart)
    }

    /// The five ASCII bytes `?NNCC`.
    pub fn encode(self) -> [u8; 5] {
        command_bytes(self.code())
    }
}

/// `?NNCC` for any code (also unknown ones, for tests and raw sends).
pub fn command_bytes(code: u8) -> [u8; 5] {
    let mut b = [b'?', 0, 0, 0, 0];
    put_hex(&mut b[1..3], code);
    put_hex(&mut b[3..5], code.wrapping_neg());
    b
}

/// The two's complement of the byte sum: what makes a sequence sum to 0 mod 256.
pub fn complement(bytes: &[u8]) -> u8 {
    sum(bytes).wrapping_neg()
}

pub fn sum(bytes: &[u8]) -> u8 {
    bytes.iter().fold(0u8, |a, b| a.wrapping_add(*b))
}

const HEX: &[u8; 16] = b"0123456789ABCDEF";

fn put_hex(out: &mut [u8], b: u8) {
    out[0] = HEX[(b >> 4) as usize];
    out[1] = HEX[(b & 15) as usize];
}

/// Appends `b` as two upper-case hex digits.
pub fn push_hex(out: &mut Vec<u8>, b: u8) {
    out.push(HEX[(b >> 4) as usize]);
    out.push(HEX[(b & 15) as usize]);
}

/// The value of one hex digit (either case).
pub fn hex_digit(c: u8) -> Option<u8> {
    match c {
        b'0'..=b'9' => Some(c - b'0'),
        b'A'..=b'F' => Some(c - b'A' + 10),
        b'a'..=b'f' => Some(c - b'a' + 10),
        _ => None,
    }
}

/// Two hex digits as a byte.
pub fn hex_pair(p: &[u8]) -> Option<u8> {
    Some(hex_digit(*p.first()?)? << 4 | hex_digit(*p.get(1)?)?)
}

/// Checks that `text` has the form the UMPK reads before it answers (manual §4.1, §4.2;
/// spec §3, §5), so that a typing slip is refused here instead of being sent and met with
/// silence: a terminal command is `?` and exactly four characters (code and checksum), a
/// HEX record `:` and exactly 10 + 2 × RECLEN characters after it. What the controller
/// itself checks and answers — a checksum (`E`), an unknown code or record type (`U`), a
/// character that is not a hex digit (`C`) — is left to it. `Err` says what is wrong and
/// the right form.
pub fn check_form(text: &[u8]) -> Result<(), String> {
    let shown = String::from_utf8_lossy(text);
    match text.first() {
        Some(b'?') => {
            let body = &text[1..];
            if body.len() == 4 {
                return Ok(());
            }
            // A likely meaning: the code a short form names (`?3FD`: code 3, checksum FD).
            let digits: Option<Vec<u8>> = body.iter().map(|c| hex_digit(*c)).collect();
            let code = match digits.as_deref() {
                Some([c]) | Some([c, _, _]) => Some(*c),
                Some([h, l]) => Some(h << 4 | l),
                _ => None,
            };
            Err(match code.map(|c| (c, Command::from_code(c))) {
                Some((c, Some(cmd))) => msg!(
                    "umpk-form-short-command-like",
                    text = &*shown,
                    count = body.len(),
                    command = cmd.name().text,
                    bytes = String::from_utf8_lossy(&command_bytes(c)).into_owned()
                ),
                _ => msg!("umpk-form-short-command", text = &*shown, count = body.len()),
            }
            .text)
        }
        Some(b':') => {
            let Some(n) = text.get(1..3).and_then(hex_pair) else {
                return Err(msg!("umpk-form-no-reclen", text = &*shown).text);
            };
            let want = 11 + 2 * n as usize;
            if text.len() == want {
                Ok(())
            } else {
                Err(msg!(
                    "umpk-form-record-length",
                    text = &*shown,
                    count = text.len(),
                    reclen = format!("{n:02X}"),
                    want = want,
                    data = 2 * n as usize
                )
                .text)
            }
        }
        _ => Err(msg!("umpk-form-neither", text = &*shown).text),
    }
}

/// What the PLC made of one received command (the simulator's side).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Parsed {
    Command(Command),
    /// A reply letter: `E`, `U` or `C`.
    Refused(u8),
}

/// Checks a complete five-byte terminal command as the PLC does: illegal characters
/// first (`C`), then the checksum (`E`), then the code (`U`).
pub fn parse_command(b: &[u8; 5]) -> Parsed {
    let (Some(code), Some(cc)) = (hex_pair(&b[1..3]), hex_pair(&b[3..5])) else {
        return Parsed::Refused(b'C');
    };
    if b[0] != b'?' {
        return Parsed::Refused(b'C');
    }
    if code.wrapping_add(cc) != 0 {
        return Parsed::Refused(b'E');
    }
    match Command::from_code(code) {
        Some(c) => Parsed::Command(c),
        None => Parsed::Refused(b'U'),
    }
}

/// A `#NN…CC` packet for `data`, with the complement checksum over NN and the data.
pub fn packet(data: &[u8]) -> Vec<u8> {
    let mut out = Vec::with_capacity(5 + 2 * data.len());
    out.push(b'#');
    let n = data.len() as u8;
    push_hex(&mut out, n);
    for &b in data {
        push_hex(&mut out, b);
    }
    push_hex(&mut out, complement(data).wrapping_sub(n));
    out
}

/// `#` and the 22 program-info characters.
pub fn text_packet(info: &[u8; INFO_LEN]) -> Vec<u8> {
    let mut out = vec![b'#'];
    out.extend_from_slice(info);
    out
}

/// True if `cc` is an accepted checksum for `lead` (NN or the header) and `data`: the
/// complement rule we send, or a plain sum, with or without the lead byte.
pub fn checksum_ok(lead: u8, data: &[u8], cc: u8) -> bool {
    let s = sum(data);
    let with = s.wrapping_add(lead);
    cc == with.wrapping_neg() || cc == with || cc == s || cc == s.wrapping_neg()
}

/// Which bit of the status word holds each flag (§4.1.4: W H R E P T, high to low; the
/// positions are ours). Configurable with `status_bits=W,H,R,E,P,T` in a URL.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct StatusLayout {
    pub bits: [u8; 6],
}

impl Default for StatusLayout {
    fn default() -> Self {
        StatusLayout { bits: [5, 4, 3, 2, 1, 0] }
    }
}

/// The status word's flags (§4.1.4).
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, serde::Serialize)]
pub struct Status {
    /// W: Work mode (a program is loaded and running).
    pub work: bool,
    /// H: the error history is not empty.
    pub errors: bool,
    /// R: the real-time monitor is on.
    pub monitor: bool,
    /// E: echo was switched off by a command.
    pub echo_off: bool,
    /// P: Programming mode.
    pub programming: bool,
    /// T: the LED blink phase (sent to the real-time monitor only).
    pub blink: bool,
}

impl StatusLayout {
    /// Parses `5,4,3,2,1,0` (bit numbers of W, H, R, E, P, T).
    pub fn parse(text: &str) -> Result<StatusLayout, String> {
        let v: Vec<u8> = text
            .split(',')
            .map(|s| s.trim().parse::<u8>().ok().filter(|b| *b < 8))
            .collect::<Option<_>>()
            .ok_or_else(|| msg!("umpk-status-bits-not-six", text = text).text)?;
        let bits: [u8; 6] = v.try_into().map_err(|_| msg!("umpk-status-bits-count", text = text).text)?;
        for (i, b) in bits.iter().enumerate() {
            if bits[..i].contains(b) {
                return Err(msg!("umpk-status-bits-twice", bit = *b, text = text).text);
            }
        }
        Ok(StatusLayout { bits })
    }

    pub fn encode(&self, s: &Status) -> u8 {
        let flags = [s.work, s.errors, s.monitor, s.echo_off, s.programming, s.blink];
        flags.iter().zip(self.bits).fold(0, |a, (f, b)| a | ((*f as u8) << b))
    }

    pub fn decode(&self, w: u8) -> Status {
        let f = |i: usize| w >> self.bits[i] & 1 != 0;
        Status { work: f(0), errors: f(1), monitor: f(2), echo_off: f(3), programming: f(4), blink: f(5) }
    }
}

/// The firmware version packed `SSSMMMLL` (§4.1.4): major 0–7, minor 0–7, letter A–D.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct Version(pub u8);

impl Version {
    pub const fn new(major: u8, minor: u8, letter: char) -> Version {
        Version((major & 7) << 5 | (minor & 7) << 2 | ((letter as u8).wrapping_sub(b'A') & 3))
    }
    pub fn major(self) -> u8 {
        self.0 >> 5
    }
    pub fn minor(self) -> u8 {
        self.0 >> 2 & 7
    }
    pub fn letter(self) -> char {
        (b'A' + (self.0 & 3)) as char
    }
}

impl fmt::Display for Version {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        write!(f, "{}.{}{}", self.major(), self.minor(), self.letter())
    }
}

/// The controller-info packet `#06MMVVIIQQSSPPCC` (§4.1.4).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct Info {
    pub model: u8,
    pub version: Version,
    pub inputs: u8,
    pub outputs: u8,
    pub status: u8,
    pub microcode: u8,
}

impl Info {
    pub fn data(&self) -> [u8; 6] {
        [self.model, self.version.0, self.inputs, self.outputs, self.status, self.microcode]
    }
    pub fn from_data(d: &[u8]) -> Option<Info> {
        let d: &[u8; 6] = d.try_into().ok()?;
        Some(Info { model: d[0], version: Version(d[1]), inputs: d[2], outputs: d[3], status: d[4], microcode: d[5] })
    }
}

/// The timing packet `#04HHKKLLMMCC` (§4.1.13): the firmware's own time HHKK and the
/// longest cycle's total time LLMM, in 0.271 µs counts.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct Timing {
    pub firmware: u16,
    pub total: u16,
}

impl Timing {
    pub fn data(&self) -> [u8; 4] {
        let [h, k] = self.firmware.to_be_bytes();
        let [l, m] = self.total.to_be_bytes();
        [h, k, l, m]
    }
    pub fn from_data(d: &[u8]) -> Option<Timing> {
        let d: &[u8; 4] = d.try_into().ok()?;
        Some(Timing { firmware: u16::from_be_bytes([d[0], d[1]]), total: u16::from_be_bytes([d[2], d[3]]) })
    }
    /// T = ((LL·256 + MM) − (HH·256 + KK)) × 0.271 µs: the user program's execution time.
    pub fn program_us(&self) -> f64 {
        (self.total as f64 - self.firmware as f64) * TIMING_US_PER_COUNT
    }
    pub fn firmware_us(&self) -> f64 {
        self.firmware as f64 * TIMING_US_PER_COUNT
    }
    pub fn total_us(&self) -> f64 {
        self.total as f64 * TIMING_US_PER_COUNT
    }
}

/// System error codes (128–255) in the error history (§4.1.8). The manual names only 255;
/// the others are codes plcsh's simulator records for what the manual leaves unnamed.
pub mod syserr {
    /// Output buffer overflow: a command sent before the previous reply was complete (§4.1).
    pub const OUTPUT_OVERFLOW: u8 = 255;
    /// Simulator: the program did not finish within the 10 ms cycle and was stopped.
    pub const CYCLE_OVERRUN: u8 = 254;
    /// Simulator: the program stopped on another fault.
    pub const PROGRAM_FAULT: u8 = 253;
}

/// The meaning of an error-history code (§4.1.8).
pub fn error_code_text(code: u8) -> String {
    match code {
        0 => msg!("umpk-error-none").text,
        1..=127 => msg!("umpk-error-user", code = code).text,
        syserr::OUTPUT_OVERFLOW => msg!("umpk-error-output-overflow").text,
        syserr::CYCLE_OVERRUN => msg!("umpk-error-cycle-overrun").text,
        syserr::PROGRAM_FAULT => msg!("umpk-error-program-fault").text,
        _ => msg!("umpk-error-system", code = code).text,
    }
}

/// What each reply letter means, in words (§4.1, §4.2).
pub fn letter_text(letter: u8) -> Msg {
    let key = match letter {
        b'E' | b'U' | b'C' | b'L' | b'A' | b'W' | b'X' => (letter as char).to_string(),
        _ => "other".to_string(),
    };
    msg!("umpk-letter", letter = key)
}

/// The 30-byte real-time monitor packet (Table 7).
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct Monitor {
    pub status: u8,
    pub inputs: u32,
    pub outputs: u32,
    pub timers: u16,
    pub counters: u8,
    pub markers: u128,
}

impl Monitor {
    pub fn encode(&self) -> [u8; MONITOR_LEN] {
        let mut b = [0u8; MONITOR_LEN];
        b[0] = MONITOR_HEADER;
        b[1] = self.status;
        b[2..6].copy_from_slice(&self.inputs.to_le_bytes());
        b[6..10].copy_from_slice(&self.outputs.to_le_bytes());
        b[10..12].copy_from_slice(&self.timers.to_le_bytes());
        b[12] = self.counters;
        b[13..29].copy_from_slice(&self.markers.to_le_bytes());
        b[29] = complement(&b[..29]);
        b
    }

    /// Decodes one packet; `None` if the header or the checksum is wrong.
    pub fn decode(b: &[u8]) -> Option<Monitor> {
        let b: &[u8; MONITOR_LEN] = b.get(..MONITOR_LEN)?.try_into().ok()?;
        if b[0] != MONITOR_HEADER || !checksum_ok(b[0], &b[1..29], b[29]) {
            return None;
        }
        Some(Monitor {
            status: b[1],
            inputs: u32::from_le_bytes(b[2..6].try_into().ok()?),
            outputs: u32::from_le_bytes(b[6..10].try_into().ok()?),
            timers: u16::from_le_bytes([b[10], b[11]]),
            counters: b[12],
            markers: u128::from_le_bytes(b[13..29].try_into().ok()?),
        })
    }
}

/// A decoded reply.
#[derive(Clone, Debug, PartialEq, Eq)]
pub enum Reply {
    /// `R`.
    Ok,
    /// A refusal letter (`E U C L A W X`).
    Letter(u8),
    /// A `#NN…CC` packet's data bytes.
    Packet(Vec<u8>),
    /// The 22 program-info characters.
    Text(Vec<u8>),
}

/// One command's exchange read off the line.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct Exchange {
    pub reply: Reply,
    /// The command came back as echo.
    pub echoed: bool,
    /// The reply ended in CR LF.
    pub crlf: bool,
    /// A `R` CR LF from a reset or power-up came first.
    pub reset_seen: bool,
    /// Monitor packets that were on their way.
    pub monitor: Vec<Monitor>,
    /// Bytes used from the buffer.
    pub consumed: usize,
}

/// The state of reading an exchange.
#[derive(Clone, Debug, PartialEq, Eq)]
pub enum Progress {
    /// Not complete yet: read more.
    NeedMore,
    Done(Exchange),
    /// Bytes that cannot be this exchange; the message says what came.
    Bad(String),
}

/// Reads the reply to `sent` (a command or a HEX record) from `buf`, as the manual frames
/// it: optional monitor packets and a reset's `R` CR LF first, then the echo of `sent` (if
/// echo is on), the reply of `shape`, then CR LF when `crlf` says so (`None`: when the
/// command was echoed). Linear in `buf`; never panics.
pub fn parse_exchange(buf: &[u8], sent: &[u8], shape: Shape, crlf: Option<bool>) -> Progress {
    let mut i = 0;
    let mut monitor = Vec::new();
    let mut reset_seen = false;
    loop {
        match buf.get(i) {
            None => return Progress::NeedMore,
            Some(&MONITOR_HEADER) => {
                if buf.len() < i + MONITOR_LEN {
                    return Progress::NeedMore;
                }
                match Monitor::decode(&buf[i..]) {
                    Some(m) => monitor.push(m),
                    None => {
                        return Progress::Bad(
                            msg!("umpk-bad-monitor-packet", bytes = show(&buf[i..i + MONITOR_LEN])).text,
                        )
                    }
                }
                i += MONITOR_LEN;
            }
            Some(b'R') if buf.get(i + 1) == Some(&b'\r') && !sent.is_empty() => {
                // `R` CR LF before the echo is a reset's or power-up's (§4.1): a reply `R`
                // comes after the echo, and without echo it has no CR LF.
                if buf.len() < i + 3 {
                    return Progress::NeedMore;
                }
                if buf[i + 2] != b'\n' {
                    return Progress::Bad(msg!("umpk-bad-r-cr", bytes = show(&buf[i + 2..i + 3])).text);
                }
                if buf.len() == i + 3 && shape == Shape::Ack && crlf != Some(false) {
                    // Either a reset's R or our echo-less reply with CR LF (after `?01FF`).
                    if sent[..] == Command::EchoOn.encode() || sent[..] == Command::Reset.encode() {
                        return done(Reply::Ok, false, true, reset_seen, monitor, i + 3);
                    }
                    return Progress::NeedMore;
                }
                reset_seen = true;
                i += 3;
            }
            Some(_) => break,
        }
    }
    let mut echoed = false;
    if buf[i] == sent.first().copied().unwrap_or(0) && !sent.is_empty() {
        let n = sent.len().min(buf.len() - i);
        if buf[i..i + n] != sent[..n] {
            return Progress::Bad(msg!("umpk-bad-echo", echo = show(&buf[i..i + n]), sent = show(sent)).text);
        }
        if n < sent.len() {
            return Progress::NeedMore;
        }
        echoed = true;
        i += n;
    }
    let Some(&first) = buf.get(i) else { return Progress::NeedMore };
    let (reply, end) = match first {
        b'R' => (Reply::Ok, i + 1),
        b'E' | b'U' | b'C' | b'L' | b'A' | b'W' | b'X' => (Reply::Letter(first), i + 1),
        b'#' => match shape {
            Shape::Text => {
                if buf.len() < i + 1 + INFO_LEN {
                    return Progress::NeedMore;
                }
                (Reply::Text(buf[i + 1..i + 1 + INFO_LEN].to_vec()), i + 1 + INFO_LEN)
            }
            Shape::Packet(_) | Shape::Ack => {
                let Some(nn_text) = buf.get(i + 1..i + 3) else { return Progress::NeedMore };
                let Some(nn) = hex_pair(nn_text) else {
                    return Progress::Bad(msg!("umpk-bad-length-field", bytes = show(&buf[i..])).text);
                };
                if let Shape::Packet(want) = shape {
                    if nn != want {
                        return Progress::Bad(msg!("umpk-bad-packet-length", got = nn, want = want).text);
                    }
                }
                let end = i + 3 + 2 * nn as usize + 2;
                if buf.len() < end {
                    return Progress::NeedMore;
                }
                let bytes: Option<Vec<u8>> = buf[i + 3..end].chunks(2).map(hex_pair).collect();
                let Some(bytes) = bytes else {
                    return Progress::Bad(msg!("umpk-bad-packet-hex", bytes = show(&buf[i..end])).text);
                };
                let (data, cc) = bytes.split_at(nn as usize);
                if !checksum_ok(nn, data, cc[0]) {
                    return Progress::Bad(
                        msg!(
                            "umpk-bad-packet-checksum",
                            bytes = show(&buf[i..end]),
                            expected = format!("{:02X}", complement(data).wrapping_sub(nn))
                        )
                        .text,
                    );
                }
                (Reply::Packet(data.to_vec()), end)
            }
        },
        _ => return Progress::Bad(msg!("umpk-bad-reply", bytes = show(&buf[i..buf.len().min(i + 40)])).text),
    };
    let want_crlf = crlf.unwrap_or(echoed);
    if !want_crlf {
        return done(reply, echoed, false, reset_seen, monitor, end);
    }
    match buf.get(end..end + 2) {
        Some(b"\r\n") => done(reply, echoed, true, reset_seen, monitor, end + 2),
        Some(_) => Progress::Bad(msg!("umpk-bad-crlf", bytes = show(&buf[i..])).text),
        None if buf.len() == end + 1 && buf[end] != b'\r' => {
            Progress::Bad(msg!("umpk-bad-crlf", bytes = show(&buf[i..])).text)
        }
        None => Progress::NeedMore,
    }
}

fn done(reply: Reply, echoed: bool, crlf: bool, reset_seen: bool, monitor: Vec<Monitor>, consumed: usize) -> Progress {
    Progress::Done(Exchange { reply, echoed, crlf, reset_seen, monitor, consumed })
}

/// Bytes for messages: printable ASCII as text, the rest as `<AA>`.
pub fn show(bytes: &[u8]) -> String {
    let mut s = String::from("`");
    for &b in bytes {
        match b {
            b'\r' => s.push_str("<CR>"),
            b'\n' => s.push_str("<LF>"),
            0x20..=0x7E => s.push(b as char),
            _ => s.push_str(&format!("<{b:02X}>")),
        }
    }
    s.push('`');
    s
}

#[cfg(test)]
mod tests {
    #[test]
    fn a_command_or_record_of_the_wrong_form_is_refused_with_the_right_one() {
        // What the controller answers itself (E, U, C) passes: ?03FE bad checksum, ?0DF3
        // unknown code, ?0G00 an illegal character, a record with a bad checksum.
        for ok in ["?03FD", "?03FE", "?0DF3", "?0G00", ":00000002FE", ":00000002FD", ":0100000Z00FF", ":020000040000FA"]
        {
            assert_eq!(check_form(ok.as_bytes()), Ok(()), "{ok}");
        }
        let e = check_form(b"?3FD").unwrap_err();
        assert!(e.contains("3 character(s) after ?") && e.contains("for controller info send ?03FD"), "{e}");
        let e = check_form(b"?3").unwrap_err();
        assert!(e.contains("send ?03FD"), "{e}");
        let e = check_form(b"?03FD0").unwrap_err();
        assert!(e.contains("5 character(s)") && !e.contains("send"), "{e}");
        let e = check_form(b"hello").unwrap_err();
        assert!(e.starts_with("`hello` is neither") && e.contains("?03FD") && e.contains(":00000002FE"), "{e}");
        let e = check_form(b":0000002FE").unwrap_err();
        assert!(e.contains("is 10 characters") && e.contains("RECLEN 00 is 11"), "{e}");
        let e = check_form(b":XY").unwrap_err();
        assert!(e.contains("record length"), "{e}");
        assert!(check_form(b"").is_err());
    }

    use super::*;

    #[test]
    fn every_command_of_table_6_byte_for_byte() {
        // Table 6 lists ?0000 ?01FF ?02FE ?03FD ?04FC ?05FB ?06FA ?07F9 ?08F8 ?09F7 ?0AF6 ?0BF5 ?0CF4.
        let listed = [
            "?0000", "?01FF", "?02FE", "?03FD", "?04FC", "?05FB", "?06FA", "?07F9", "?08F8", "?09F7", "?0AF6", "?0BF5",
            "?0CF4",
        ];
        for (c, text) in Command::ALL.iter().zip(listed) {
            assert_eq!(&c.encode(), text.as_bytes(), "{}", c.name());
            assert_eq!(parse_command(text.as_bytes().try_into().unwrap()), Parsed::Command(*c));
        }
    }

    #[test]
    fn command_errors_in_the_manuals_order() {
        let p = |s: &str| parse_command(s.as_bytes().try_into().unwrap());
        assert_eq!(p("?03FE"), Parsed::Refused(b'E'), "checksum");
        assert_eq!(p("?0DF3"), Parsed::Refused(b'U'), "unknown code with a right checksum");
        assert_eq!(p("?0GFD"), Parsed::Refused(b'C'), "illegal character");
        assert_eq!(p("?03fd"), Parsed::Command(Command::Info), "lower-case hex from a person's terminal");
    }

    #[test]
    #[allow(clippy::unusual_byte_groupings)] // grouped as the manual packs it: SSS MMM LL
    fn controller_info_packet_and_firmware_version() {
        // #06 MM=10 VV=2A (001 010 10: 1.2C) II=10 QQ=08 SS=20 (W) PP=03, CC makes the sum 0.
        let info =
            Info { model: 0x10, version: Version::new(1, 2, 'C'), inputs: 16, outputs: 8, status: 0x20, microcode: 3 };
        assert_eq!(info.version.0, 0b001_010_10);
        let p = packet(&info.data());
        assert_eq!(p, b"#06102A1008200385");
        assert_eq!(sum(&[0x06, 0x10, 0x2A, 0x10, 0x08, 0x20, 0x03, 0x85]), 0);
        assert_eq!(Version(0xFF).to_string(), "7.7D");
        assert_eq!(Version(0x00).to_string(), "0.0A");
        assert_eq!(Version(0b011_101_01).to_string(), "3.5B");
        match parse_exchange(&p, b"?03FD", Shape::Packet(6), None) {
            Progress::Done(x) => {
                assert_eq!(
                    Info::from_data(match &x.reply {
                        Reply::Packet(d) => d,
                        r => panic!("{r:?}"),
                    }),
                    Some(info)
                );
                assert!(!x.echoed && !x.crlf);
            }
            p => panic!("{p:?}"),
        }
    }

    #[test]
    fn echo_on_framing_and_partial_input() {
        let mut wire = b"?03FD".to_vec();
        wire.extend_from_slice(b"#06102A1008200385\r\n");
        for cut in 0..wire.len() {
            assert_eq!(parse_exchange(&wire[..cut], b"?03FD", Shape::Packet(6), None), Progress::NeedMore, "{cut}");
        }
        let Progress::Done(x) = parse_exchange(&wire, b"?03FD", Shape::Packet(6), None) else { panic!() };
        assert!(x.echoed && x.crlf);
        assert_eq!(x.consumed, wire.len());
        // Echo off: `?02FE` is echoed (echo was on when it arrived), R has no CR LF.
        let Progress::Done(x) = parse_exchange(b"?02FER", b"?02FE", Shape::Ack, Some(false)) else { panic!() };
        assert_eq!((x.reply, x.echoed, x.crlf), (Reply::Ok, true, false));
        // Echo on from off: no echo, then R CR LF.
        let Progress::Done(x) = parse_exchange(b"R\r\n", b"?01FF", Shape::Ack, Some(true)) else { panic!() };
        assert_eq!((x.reply, x.echoed, x.crlf, x.reset_seen), (Reply::Ok, false, true, false));
    }

    #[test]
    fn reset_r_and_monitor_packets_are_skipped() {
        let m =
            Monitor { status: 0x28, inputs: 0x0001, outputs: 0x80, timers: 0x8001, counters: 0x0F, markers: 1 << 63 };
        let mut wire = m.encode().to_vec();
        wire.extend_from_slice(b"R\r\n?05FB#0401000000FB\r\n");
        let Progress::Done(x) = parse_exchange(&wire, b"?05FB", Shape::Packet(4), None) else { panic!() };
        assert!(x.reset_seen);
        assert_eq!(x.monitor, vec![m]);
        assert_eq!(x.reply, Reply::Packet(vec![1, 0, 0, 0]));
        assert_eq!(x.consumed, wire.len());
    }

    #[test]
    fn error_letters_program_info_and_bad_replies() {
        for l in *b"EUCLAWX" {
            let Progress::Done(x) = parse_exchange(&[l], b"?0DF3", Shape::Ack, None) else { panic!() };
            assert_eq!(x.reply, Reply::Letter(l));
            assert!(!letter_text(l).starts_with("an unknown"));
        }
        let mut wire = b"#".to_vec();
        wire.extend_from_slice(&[b' '; INFO_LEN]);
        let Progress::Done(x) = parse_exchange(&wire, b"?04FC", Shape::Text, None) else { panic!() };
        assert_eq!(x.reply, Reply::Text(vec![b' '; 22]), "Wait mode: 22 spaces (§4.1.5)");
        assert!(
            matches!(parse_exchange(b"#0401000000FA", b"?05FB", Shape::Packet(4), None), Progress::Bad(m) if m.contains("checksum"))
        );
        assert!(
            matches!(parse_exchange(b"?05FC", b"?05FB", Shape::Packet(4), None), Progress::Bad(m) if m.contains("echo"))
        );
        assert!(matches!(parse_exchange(b"Z", b"?05FB", Shape::Packet(4), None), Progress::Bad(_)));
        // A plain-sum checksum is accepted too (the manual does not say which rule).
        assert!(matches!(parse_exchange(b"#040100000001", b"?05FB", Shape::Packet(4), None), Progress::Done(_)));
    }

    #[test]
    fn input_output_and_error_history_packets() {
        // I0, I3 and I15 on: byte 0 = 0x09, byte 1 = 0x80.
        assert_eq!(packet(&[0x09, 0x80, 0, 0]), b"#040980000073");
        assert_eq!(packet(&[0xFF, 0, 0, 0]), b"#04FF000000FD");
        // Error history, newest first: 255 then user error 5.
        let p = packet(&[0xFF, 5, 0, 0, 0, 0, 0, 0]);
        assert_eq!(p, b"#08FF05000000000000F4");
        assert!(error_code_text(255).contains("output buffer overflow"));
        assert!(error_code_text(7).contains("user"));
        assert!(error_code_text(130).contains("system"));
    }

    #[test]
    fn timing_formula() {
        // HHKK = 0x0100 (256 counts of firmware), LLMM = 0x0164 (356 counts in all):
        // T = (356 − 256) × 0.271 µs = 27.1 µs.
        let t = Timing { firmware: 0x0100, total: 0x0164 };
        assert_eq!(packet(&t.data()), b"#040100016496");
        assert!((t.program_us() - 27.1).abs() < 1e-9);
        assert_eq!(Timing::from_data(&[0x01, 0x00, 0x01, 0x64]), Some(t));
    }

    #[test]
    fn monitor_packet_layout() {
        let m = Monitor {
            status: 0b10_1001,
            inputs: 0x0000_8001,
            outputs: 0x0000_0081,
            timers: 0x8001,
            counters: 0b1001,
            markers: 1 | 1 << 63,
        };
        let b = m.encode();
        assert_eq!(b.len(), 30);
        assert_eq!(b[0], 0xAA);
        assert_eq!(b[1], 0x29);
        assert_eq!(b[2..6], [0x01, 0x80, 0, 0], "I0 and I15");
        assert_eq!(b[6..10], [0x81, 0, 0, 0], "Q0 and Q7");
        assert_eq!(b[10..12], [0x01, 0x80], "T0 and T15");
        assert_eq!(b[12], 0x09, "C0 and C3");
        assert_eq!(b[13], 0x01, "M0");
        assert_eq!(b[20], 0x80, "M63");
        assert_eq!(sum(&b), 0, "checksum makes the 30 bytes sum to 0");
        assert_eq!(Monitor::decode(&b), Some(m));
        let mut bad = b;
        bad[5] ^= 1;
        assert_eq!(Monitor::decode(&bad), None);
    }

    #[test]
    fn status_layout_default_and_configured() {
        let l = StatusLayout::default();
        let s = Status { work: true, monitor: true, ..Status::default() };
        assert_eq!(l.encode(&s), 0b10_1000);
        assert_eq!(l.decode(0b10_1000), s);
        let msb = StatusLayout::parse("7,6,5,4,3,2").unwrap();
        assert_eq!(msb.encode(&Status { work: true, blink: true, ..Status::default() }), 0x84);
        assert!(StatusLayout::parse("7,6,5").is_err());
        assert!(StatusLayout::parse("7,7,5,4,3,2").is_err());
        assert!(StatusLayout::parse("8,6,5,4,3,2").is_err());
    }

    #[test]
    fn parser_is_total_on_garbage() {
        let mut seed = 0x1234_5678u32;
        for len in 0..200 {
            let buf: Vec<u8> = (0..len)
                .map(|_| {
                    seed = seed.wrapping_mul(1_103_515_245).wrapping_add(12345);
                    (seed >> 16) as u8
                })
                .collect();
            for shape in [Shape::Ack, Shape::Packet(6), Shape::Text] {
                let _ = parse_exchange(&buf, b"?03FD", shape, None);
            }
        }
    }
}
