//! The FX dedicated computer-link protocol, pure (seed 004, "FX系列PLC专用协议通信指令格式详解";
//! digest `../shared/spec/fx-and-masterk.md` B, last item). Format 1 (and format 4, the same
//! with CR LF after every message).
//!
//! - Request: `ENQ station(2 hex) pc(2 hex, "FF") cmd(2) wait(1 hex) data [sum(2 hex)]`.
//!   The wait is 0–150 ms coded as one hex digit 0H–FH (10 ms steps; 100 ms is `A`). The sum
//!   check is the sum of the ASCII codes from the station number through the last data
//!   character, the low two hex digits; a PLC set up without sum check omits it both ways.
//! - Commands: `BR` read bits (1 point per character `0`/`1`), `WR` read words (4 hex per
//!   word; bit devices in groups of 16 points, the lowest device in bit 0), `BW` write bits,
//!   `WW` write words, `WT` write words at scattered devices (count, then device + value pairs).
//! - Device: the device code and its number filling 5 characters (`D0100`, `M0500`, `TN010`).
//!   The seed says the start address is written in decimal: so it is for M, S, T, C and D;
//!   X and Y are written with their own (octal) digits, `X0040` for X40, as Mitsubishi's
//!   computer-link manual and the public drivers (HslCommunication `MelsecFxLinksAddress`)
//!   do — the seed's `X0018` cannot be an octal X number, and real PLCs read `X0020` as X20.
//!   The seed's literal reading is a setting ([`Settings::decimal_xy`], URL `xy=decimal`).
//!   CN200–CN255 (32-bit) take 8 hex digits per point in WR/WW/WT.
//! - Replies: `STX station pc data ETX [sum]` (sum from the station through ETX), `ACK station
//!   pc` for writes, `NAK station pc code(2 hex)` with the error codes of [`nak_text`].

use super::operand::{Area, CN32_FIRST};
use super::port::{hex2, push_hex2, ACK, ENQ, ETX, NAK, STX};
use crate::msg;

pub const CR: u8 = 0x0D;
pub const LF: u8 = 0x0A;

/// Most points per frame: BR 256 bits, WR/WW 64 words (32 for 32-bit counters), WT 10 words.
pub const MAX_BITS: usize = 256;
pub const MAX_WORDS: usize = 64;
pub const MAX_WT: usize = 10;

/// NAK error codes.
pub mod code {
    pub const SUM: u8 = 0x02;
    pub const PROTOCOL: u8 = 0x03;
    pub const AREA: u8 = 0x06;
    pub const CHARACTER: u8 = 0x07;
    pub const PC_NUMBER: u8 = 0x0A;
}

/// An error code in words (FX computer-link error codes, as the public drivers list them).
pub fn nak_text(code: u8) -> String {
    let key = match code {
        0x02 | 0x03 | 0x06 | 0x07 | 0x0A | 0x18 => format!("c{code:02X}"),
        0x10 => "c0A".to_string(),
        _ => "other".to_string(),
    };
    msg!("fx-nak-meaning", code = key).text
}

/// What a `Malformed` key (`too-short`, …) says, in words.
pub fn malformed_text(key: &str) -> String {
    msg!("fx-malformed", what = key).text
}

/// Link settings both ends must agree on.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct Settings {
    /// Sum check on (the PLC's D8120 setting).
    pub sum: bool,
    /// Format 4: CR LF after every message.
    pub format4: bool,
    /// X and Y numbers written in decimal (`X0018` = X22) instead of their octal digits: the
    /// seed's literal reading, for a clone that wants it (`xy=decimal`).
    pub decimal_xy: bool,
}

impl Default for Settings {
    fn default() -> Settings {
        Settings { sum: true, format4: false, decimal_xy: false }
    }
}

/// Station, PC number and wait digit of a request.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct Header {
    pub station: u8,
    pub pc: u8,
    /// 0–15, in 10 ms steps.
    pub wait: u8,
}

/// A device as the link names it.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct Dev {
    pub area: Area,
    pub index: u16,
}

impl Dev {
    /// `D0100`, `X0040`, `TN010`.
    pub fn encode(&self) -> String {
        self.text(Settings::default())
    }

    /// The device as the link with settings `s` writes it.
    pub fn text(&self, s: Settings) -> String {
        let code = self.area.spec().link;
        let octal = self.area.spec().octal && !s.decimal_xy;
        let digits = if octal { format!("{:o}", self.index) } else { self.index.to_string() };
        format!("{code}{digits:0>width$}", width = 5 - code.len())
    }

    /// Parses 5 characters; `None` when the device code or the digits are wrong.
    pub fn decode(s: &[u8]) -> Option<Dev> {
        Dev::decode_in(s, Settings::default())
    }

    /// Parses 5 characters as the link with settings `settings` writes them.
    pub fn decode_in(s: &[u8], settings: Settings) -> Option<Dev> {
        if s.len() != 5 {
            return None;
        }
        let text = std::str::from_utf8(s).ok()?;
        let spec = super::operand::AREAS.iter().filter(|a| !a.link.is_empty()).find(|a| {
            text.starts_with(a.link) && (a.link.len() == 2 || !text[1..2].chars().all(|c| c.is_ascii_alphabetic()))
        })?;
        let digits = &text[spec.link.len()..];
        if !digits.bytes().all(|b| b.is_ascii_digit()) {
            return None;
        }
        let octal = spec.octal && !settings.decimal_xy;
        let index = if octal { u16::from_str_radix(digits, 8).ok()? } else { digits.parse().ok()? };
        Some(Dev { area: spec.area, index })
    }

    /// Hex characters per point in WR/WW/WT.
    pub fn unit(&self) -> usize {
        if self.area == Area::CN && self.index >= CN32_FIRST {
            8
        } else {
            4
        }
    }
}

/// A request's command and data.
#[derive(Clone, Debug, PartialEq, Eq)]
pub enum Cmd {
    Br {
        dev: Dev,
        count: usize,
    },
    Wr {
        dev: Dev,
        count: usize,
    },
    Bw {
        dev: Dev,
        bits: Vec<bool>,
    },
    /// Values: 16-bit words, or 32-bit for CN200+.
    Ww {
        dev: Dev,
        values: Vec<u32>,
    },
    Wt {
        items: Vec<(Dev, u32)>,
    },
}

fn push_value(out: &mut Vec<u8>, v: u32, unit: usize) {
    for i in (0..unit / 2).rev() {
        push_hex2(out, (v >> (8 * i)) as u8);
    }
}

fn count_byte(n: usize) -> u8 {
    (n % 256) as u8 // 256 points are written 00
}

/// The request's bytes.
pub fn encode_request(h: Header, c: &Cmd, s: Settings) -> Vec<u8> {
    let mut f = vec![ENQ];
    push_hex2(&mut f, h.station);
    push_hex2(&mut f, h.pc);
    let (name, rest): (&str, Vec<u8>) = match c {
        Cmd::Br { dev, count } | Cmd::Wr { dev, count } => {
            let mut r = dev.text(s).into_bytes();
            push_hex2(&mut r, count_byte(*count));
            (if matches!(c, Cmd::Br { .. }) { "BR" } else { "WR" }, r)
        }
        Cmd::Bw { dev, bits } => {
            let mut r = dev.text(s).into_bytes();
            push_hex2(&mut r, count_byte(bits.len()));
            r.extend(bits.iter().map(|b| if *b { b'1' } else { b'0' }));
            ("BW", r)
        }
        Cmd::Ww { dev, values } => {
            let mut r = dev.text(s).into_bytes();
            push_hex2(&mut r, count_byte(values.len()));
            for v in values {
                push_value(&mut r, *v, dev.unit());
            }
            ("WW", r)
        }
        Cmd::Wt { items } => {
            let mut r = Vec::new();
            push_hex2(&mut r, items.len() as u8);
            for (d, v) in items {
                r.extend(d.text(s).into_bytes());
                push_value(&mut r, *v, d.unit());
            }
            ("WT", r)
        }
    };
    f.extend(name.as_bytes());
    f.push(b"0123456789ABCDEF"[(h.wait & 15) as usize]);
    f.extend(rest);
    if s.sum {
        let sum = super::port::sum(&f[1..]);
        push_hex2(&mut f, sum);
    }
    if s.format4 {
        f.extend([CR, LF]);
    }
    f
}

/// A reply.
#[derive(Clone, Debug, PartialEq, Eq)]
pub enum Reply {
    /// The characters between the PC number and ETX.
    Data(Vec<u8>),
    Ack,
    Nak(u8),
}

/// The reply's bytes, for the station and PC number of `h`.
pub fn encode_reply(h: Header, r: &Reply, s: Settings) -> Vec<u8> {
    let lead = match r {
        Reply::Data(_) => STX,
        Reply::Ack => ACK,
        Reply::Nak(_) => NAK,
    };
    let mut f = vec![lead];
    push_hex2(&mut f, h.station);
    push_hex2(&mut f, h.pc);
    match r {
        Reply::Data(d) => {
            f.extend(d);
            f.push(ETX);
            if s.sum {
                let sum = super::port::sum(&f[1..]);
                push_hex2(&mut f, sum);
            }
        }
        Reply::Ack => {}
        Reply::Nak(c) => push_hex2(&mut f, *c),
    }
    if s.format4 {
        f.extend([CR, LF]);
    }
    f
}

/// True for a character a reply can start with (STX, ACK, NAK). Anything else in front of a
/// reply is noise: 00H is what a serial port delivers for a character with a parity or
/// framing error, and a stray character is the tail of an earlier frame.
pub fn reply_start(b: u8) -> bool {
    matches!(b, STX | ACK | NAK)
}

/// Characters of a data reply carrying `data` characters: `STX station pc data ETX [sum]
/// [CR LF]`.
pub fn data_reply_chars(data: usize, s: Settings) -> usize {
    1 + 4 + data + 1 + if s.sum { 2 } else { 0 } + if s.format4 { 2 } else { 0 }
}

/// Characters of an ACK reply: `ACK station pc [CR LF]`.
pub fn ack_chars(s: Settings) -> usize {
    5 + if s.format4 { 2 } else { 0 }
}

/// Length of the complete reply at the start of `buf`, if it is all there. A byte that
/// cannot start a reply ([`reply_start`]) counts as one byte on its own (the driver sets
/// such bytes aside as noise before it asks).
pub fn reply_len(buf: &[u8], s: Settings) -> Option<usize> {
    let tail = if s.format4 { 2 } else { 0 };
    let n = match *buf.first()? {
        ACK => 5,
        NAK => 7,
        STX => buf.iter().position(|b| *b == ETX)? + 1 + if s.sum { 2 } else { 0 },
        _ => return Some(1),
    } + tail;
    (buf.len() >= n).then_some(n)
}

/// Why a reply could not be used.
#[derive(Clone, Debug, PartialEq, Eq)]
pub enum ReplyError {
    BadSum {
        got: u8,
        want: u8,
    },
    /// A well-formed header with another station or PC number: another station's reply, or
    /// one from a station set to the same number as another.
    Station {
        station: u8,
        pc: u8,
    },
    /// What is wrong, as a key of [`malformed_text`] (`too-short`, …).
    Malformed(&'static str),
}

/// Decodes a complete reply, checking the station and PC number against `h`.
pub fn decode_reply(f: &[u8], h: Header, s: Settings) -> Result<Reply, ReplyError> {
    let f = if s.format4 { f.strip_suffix(&[CR, LF]).ok_or(ReplyError::Malformed("no-crlf"))? } else { f };
    if f.len() < 5 {
        return Err(ReplyError::Malformed("too-short"));
    }
    let (Some(station), Some(pc)) = (hex2(&f[1..3]), hex2(&f[3..5])) else {
        return Err(ReplyError::Malformed("station-not-hex"));
    };
    if station != h.station || pc != h.pc {
        return Err(ReplyError::Station { station, pc });
    }
    match f[0] {
        ACK if f.len() == 5 => Ok(Reply::Ack),
        NAK if f.len() == 7 => Ok(Reply::Nak(hex2(&f[5..7]).ok_or(ReplyError::Malformed("code-not-hex"))?)),
        STX => {
            let etx = f.iter().position(|b| *b == ETX).ok_or(ReplyError::Malformed("no ETX"))?;
            if s.sum {
                if f.len() != etx + 3 {
                    return Err(ReplyError::Malformed("length-after-etx"));
                }
                let want = super::port::sum(&f[1..=etx]);
                let got = hex2(&f[etx + 1..]).ok_or(ReplyError::Malformed("sum-not-hex"))?;
                if got != want {
                    return Err(ReplyError::BadSum { got, want });
                }
            } else if f.len() != etx + 1 {
                return Err(ReplyError::Malformed("bytes-after-etx"));
            }
            Ok(Reply::Data(f[5..etx].to_vec()))
        }
        _ => Err(ReplyError::Malformed("not STX, ACK or NAK")),
    }
}

/// Parses hex values of `unit` characters each.
pub fn parse_values(d: &[u8], unit: usize) -> Option<Vec<u32>> {
    if !d.len().is_multiple_of(unit) {
        return None;
    }
    d.chunks(unit).map(|c| c.chunks(2).try_fold(0u32, |acc, p| Some(acc << 8 | hex2(p)? as u32))).collect()
}

/// What the simulator found at the start of its input.
#[derive(Clone, Debug, PartialEq, Eq)]
pub enum Parsed {
    /// More bytes are needed.
    Need,
    /// A complete request of `len` bytes.
    Request { len: usize, header: Header, cmd: Cmd },
    /// A complete or hopeless request of `len` bytes, to be answered NAK `code` (`header`
    /// when known).
    Refused { len: usize, header: Option<Header>, code: u8 },
}

/// Parses the request at the start of `buf` (which starts with ENQ). Time is linear in the
/// input; nothing is trusted: counts bound how much is read.
pub fn parse_request(buf: &[u8], s: Settings) -> Parsed {
    if buf.len() < 8 {
        return Parsed::Need;
    }
    let refuse = |len: usize, header: Option<Header>, code: u8| Parsed::Refused { len, header, code };
    let (Some(station), Some(pc)) = (hex2(&buf[1..3]), hex2(&buf[3..5])) else {
        return refuse(8, None, code::PROTOCOL);
    };
    let wait = match (buf[7] as char).to_digit(16) {
        Some(w) => w as u8,
        None => return refuse(8, Some(Header { station, pc, wait: 0 }), code::AREA),
    };
    let header = Header { station, pc, wait };
    let name = [buf[5], buf[6]];
    let mut at = 8;
    let need = |n: usize| buf.len() < n;
    let dev_count = |at: usize| -> Option<(Option<Dev>, usize)> {
        let d = Dev::decode_in(&buf[at..at + 5], s);
        let c = hex2(&buf[at + 5..at + 7])? as usize;
        Some((d, if c == 0 { 256 } else { c }))
    };
    let cmd = match &name {
        b"BR" | b"WR" | b"BW" | b"WW" => {
            if need(at + 7) {
                return Parsed::Need;
            }
            let Some((dev, count)) = dev_count(at) else { return refuse(at + 7, Some(header), code::AREA) };
            at += 7;
            let Some(dev) = dev else { return refuse(at, Some(header), code::AREA) };
            match &name {
                b"BR" => Cmd::Br { dev, count },
                b"WR" => Cmd::Wr { dev, count },
                b"BW" => {
                    if need(at + count) {
                        return Parsed::Need;
                    }
                    let chars = &buf[at..at + count];
                    at += count;
                    if !chars.iter().all(|c| *c == b'0' || *c == b'1') {
                        return refuse(at + if s.sum { 2 } else { 0 }, Some(header), code::CHARACTER);
                    }
                    Cmd::Bw { dev, bits: chars.iter().map(|c| *c == b'1').collect() }
                }
                _ => {
                    let n = count * dev.unit();
                    if need(at + n) {
                        return Parsed::Need;
                    }
                    let values = parse_values(&buf[at..at + n], dev.unit());
                    at += n;
                    match values {
                        Some(values) => Cmd::Ww { dev, values },
                        None => return refuse(at + if s.sum { 2 } else { 0 }, Some(header), code::CHARACTER),
                    }
                }
            }
        }
        b"WT" => {
            if need(at + 2) {
                return Parsed::Need;
            }
            let Some(count) = hex2(&buf[at..at + 2]) else { return refuse(at + 2, Some(header), code::AREA) };
            at += 2;
            let mut items = Vec::new();
            for _ in 0..count {
                if need(at + 5) {
                    return Parsed::Need;
                }
                let Some(dev) = Dev::decode_in(&buf[at..at + 5], s) else {
                    return refuse(at + 5, Some(header), code::AREA);
                };
                at += 5;
                if need(at + dev.unit()) {
                    return Parsed::Need;
                }
                let Some(v) = parse_values(&buf[at..at + dev.unit()], dev.unit()) else {
                    return refuse(at + dev.unit(), Some(header), code::CHARACTER);
                };
                at += dev.unit();
                items.push((dev, v[0]));
            }
            Cmd::Wt { items }
        }
        _ => return refuse(8, Some(header), code::AREA),
    };
    if s.sum {
        if need(at + 2) {
            return Parsed::Need;
        }
        let want = super::port::sum(&buf[1..at]);
        if hex2(&buf[at..at + 2]) != Some(want) {
            return refuse(at + 2 + if s.format4 { 2 } else { 0 }, Some(header), code::SUM);
        }
        at += 2;
    }
    if s.format4 {
        if need(at + 2) {
            return Parsed::Need;
        }
        if buf[at..at + 2] != [CR, LF] {
            return refuse(at, Some(header), code::PROTOCOL);
        }
        at += 2;
    }
    Parsed::Request { len: at, header, cmd }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn h() -> Header {
        Header { station: 0, pc: 0xFF, wait: 0 }
    }
    fn s() -> Settings {
        Settings::default()
    }
    fn dev(a: Area, i: u16) -> Dev {
        Dev { area: a, index: i }
    }

    #[test]
    fn device_names_fill_five_characters() {
        assert_eq!(dev(Area::D, 100).encode(), "D0100");
        assert_eq!(dev(Area::X, 0o40).encode(), "X0040");
        assert_eq!(dev(Area::TN, 10).encode(), "TN010");
        assert_eq!(dev(Area::CS, 5).encode(), "CS005");
        assert_eq!(Dev::decode(b"M0500"), Some(dev(Area::M, 500)));
        assert_eq!(Dev::decode(b"X0040"), Some(dev(Area::X, 32)));
        assert_eq!(Dev::decode(b"X0018"), None, "X numbers are octal digits");
        assert_eq!(Dev::decode(b"CN200"), Some(dev(Area::CN, 200)));
        assert_eq!(Dev::decode(b"Q0000"), None);
        assert_eq!(Dev::decode(b"TC000"), None, "coils are not in the link's table");
        // The seed's literal reading, as an option: X0018 is X22 (device 18).
        let dec = Settings { decimal_xy: true, ..Settings::default() };
        assert_eq!(Dev::decode_in(b"X0018", dec), Some(dev(Area::X, 18)));
        assert_eq!(dev(Area::X, 18).text(dec), "X0018");
        assert_eq!(dev(Area::X, 18).encode(), "X0022");
    }

    // BR, station 00, PC FF, wait 0, X0040, 5 points. Sum over "00FFBR0X004005":
    // 0x30+0x30+0x46+0x46+0x42+0x52+0x30+0x58+0x30+0x30+0x34+0x30+0x30+0x35 = 0x331 → "31".
    #[test]
    fn golden_br() {
        let f = encode_request(h(), &Cmd::Br { dev: dev(Area::X, 0o40), count: 5 }, s());
        assert_eq!(f, b"\x0500FFBR0X00400531".to_vec());
        let Parsed::Request { len, cmd, .. } = parse_request(&f, s()) else { panic!() };
        assert_eq!((len, cmd), (f.len(), Cmd::Br { dev: dev(Area::X, 32), count: 5 }));
    }

    // WR D0100, 2 words, wait 3 (30 ms). Sum over "00FFWR3D010002" = 0x30+0x30+0x46+0x46+
    // 0x57+0x52+0x33+0x44+0x30+0x31+0x30+0x30+0x30+0x32 = 0x32F → "2F".
    #[test]
    fn golden_wr() {
        let f = encode_request(Header { wait: 3, ..h() }, &Cmd::Wr { dev: dev(Area::D, 100), count: 2 }, s());
        assert_eq!(f, b"\x0500FFWR3D0100022F".to_vec());
    }

    // BW M0500, 2 points "10" (the seed: "M寄存器100单元置1" writes bits as characters). Sum over
    // "00FFBW0M05000210" = 0x30+0x30+0x46+0x46+0x42+0x57+0x30+0x4D+0x30+0x35+0x30+0x30+0x30
    // +0x32+0x31+0x30 = 0x38A → "8A".
    #[test]
    fn golden_bw() {
        let f = encode_request(h(), &Cmd::Bw { dev: dev(Area::M, 500), bits: vec![true, false] }, s());
        assert_eq!(f, b"\x0500FFBW0M05000210".iter().chain(b"8A").copied().collect::<Vec<u8>>());
    }

    // WW D0000, 2 words 1234 ABCD (4 hex per word, most significant digit first). Sum over
    // "00FFWW0D0000021234ABCD" = 0x504 → "04".
    #[test]
    fn golden_ww() {
        let f = encode_request(h(), &Cmd::Ww { dev: dev(Area::D, 0), values: vec![0x1234, 0xABCD] }, s());
        assert_eq!(f, b"\x0500FFWW0D0000021234ABCD04".to_vec());
        let Parsed::Request { cmd, .. } = parse_request(&f, s()) else { panic!() };
        assert_eq!(cmd, Cmd::Ww { dev: dev(Area::D, 0), values: vec![0x1234, 0xABCD] });
    }

    #[test]
    fn wt_and_32_bit_counters() {
        let c = Cmd::Wt { items: vec![(dev(Area::D, 5), 7), (dev(Area::CN, 200), 0x0001_0000)] };
        let f = encode_request(h(), &c, s());
        assert_eq!(&f[..f.len() - 2], &b"\x0500FFWT002D00050007CN20000010000"[..]);
        let Parsed::Request { cmd, .. } = parse_request(&f, s()) else { panic!() };
        assert_eq!(cmd, c);
    }

    #[test]
    fn replies_with_sum_ack_and_nak() {
        let r = encode_reply(h(), &Reply::Data(b"1234".to_vec()), s());
        // Sum over "00FF1234" ETX = 0x30+0x30+0x46+0x46+0x31+0x32+0x33+0x34+0x03 = 0x1B9 → "B9".
        assert_eq!(r, b"\x0200FF1234\x03B9".to_vec());
        assert_eq!(reply_len(&r, s()), Some(r.len()));
        assert_eq!(reply_len(&r[..r.len() - 1], s()), None);
        assert_eq!(decode_reply(&r, h(), s()), Ok(Reply::Data(b"1234".to_vec())));
        let mut bad = r.clone();
        bad[11] = b'8';
        assert!(matches!(decode_reply(&bad, h(), s()), Err(ReplyError::BadSum { .. })));
        assert_eq!(encode_reply(h(), &Reply::Ack, s()), b"\x0600FF".to_vec());
        let n = encode_reply(h(), &Reply::Nak(2), s());
        assert_eq!(n, b"\x1500FF02".to_vec());
        assert_eq!(decode_reply(&n, h(), s()), Ok(Reply::Nak(2)));
        assert_eq!(
            decode_reply(&n, Header { station: 1, ..h() }, s()),
            Err(ReplyError::Station { station: 0, pc: 0xFF }),
            "another station's reply"
        );
        assert_eq!(data_reply_chars(4, s()), r.len());
        assert_eq!(ack_chars(s()), 5);
        assert!(reply_start(STX) && reply_start(ACK) && reply_start(NAK));
        assert!(!reply_start(0x00) && !reply_start(b'3') && !reply_start(0x86), "noise and stray characters");
        assert_eq!(reply_len(&[0x00, 0x02], s()), Some(1), "one stray byte at a time");
        let f4 = Settings { format4: true, sum: false, decimal_xy: false };
        let r4 = encode_reply(h(), &Reply::Data(b"01".to_vec()), f4);
        assert_eq!(r4, b"\x0200FF01\x03\r\n".to_vec());
        assert_eq!(decode_reply(&r4, h(), f4), Ok(Reply::Data(b"01".to_vec())));
        assert_eq!(data_reply_chars(2, f4), r4.len());
        assert_eq!(ack_chars(f4), encode_reply(h(), &Reply::Ack, f4).len());
        assert!(nak_text(6).contains("device number"));
    }

    #[test]
    fn hostile_requests_are_refused_not_panicked_on() {
        let bad_sum = b"\x0500FFBR0X00400500";
        assert!(matches!(parse_request(bad_sum, s()), Parsed::Refused { code: code::SUM, .. }));
        assert_eq!(parse_request(b"\x0500FFBR0X0", s()), Parsed::Need);
        assert!(matches!(parse_request(b"\x0500FFZZ0X004005", s()), Parsed::Refused { code: code::AREA, .. }));
        assert!(matches!(parse_request(b"\x05G0FFBR0X004005", s()), Parsed::Refused { .. }));
        let ww_bad = encode_request(h(), &Cmd::Ww { dev: dev(Area::D, 0), values: vec![1] }, s());
        let mut w = ww_bad.clone();
        w[15] = b'G';
        assert!(matches!(parse_request(&w, s()), Parsed::Refused { .. }));
        // Every prefix of a valid frame asks for more; none panics.
        let f = encode_request(h(), &Cmd::Wt { items: vec![(dev(Area::D, 5), 7)] }, s());
        for i in 0..f.len() {
            assert_eq!(parse_request(&f[..i], s()), Parsed::Need, "{i}");
        }
    }
}
