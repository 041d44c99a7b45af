//! The FX programming-port protocol, pure (seed 004 second half; digest
//! `../shared/spec/fx-and-masterk.md` B): frames, the sum check, and the device-address
//! table that maps operands to byte and force addresses. No I/O here.
//!
//! - The PC sends ENQ (0x05); the PLC answers ACK (0x06) when ready, NAK (0x15) on error.
//! - Request: `STX cmd addr(4 hex) count(2 hex) [data hex] ETX sum(2 hex)`; commands `0`
//!   read (up to 64 bytes), `1` write, `7` force ON, `8` force OFF. A force frame carries only
//!   the force address, low byte first (`STX 7 F409 ETX sum` forces M500 = 0x09F4).
//! - The extended commands (FX3U and later; [`Table::Extended`]): `E00` read and `E10` write
//!   with the same address, count and data fields, and `E7`/`E8` force ON/OFF with a 4-digit
//!   force address, low byte first. `E01`/`E11` read and write program memory: decoded, so a
//!   PLC can refuse them by name. Public description of the command set ("Read
//!   Configuration E00, Write Configuration E10, Read Program E01, Write Program E11", with an
//!   FX1N's `STX E00 01C0 01 ETX DD`): `semicontinuity/fx-fiddle`
//!   `ref/doc/FX2N-HT32-COMMENTS/protocol/mitsubishi-fx-prog-port-comm-protocol.md`; the E00/E10
//!   frames of FX3U-era drivers: HslCommunication `MelsecFxSerialOverTcp`
//!   (`BuildReadWordCommand`/`BuildWriteWordCommand` with `isNewVersion`); the E7/E8 frame:
//!   fx-fiddle `cli/fx-fiddle/lib/protocol.py` (`set_bit`/`clear_bit`).
//! - Sum check: the sum of the ASCII codes from the command character through ETX, the
//!   lowest two hex digits (upper case).
//! - Replies: a read is answered `STX data(2·n hex) ETX sum`, its sum over the data and ETX;
//!   a write or force is answered ACK; a frame the PLC refuses (bad sum, address out of
//!   range) is answered NAK.
//!
//! Byte addresses come from two tables: the classic one every FX answers (commands 0/1/7/8,
//! [`super::operand::AREAS`], its sources cited there) and the extended one of the E-commands
//! ([`EXTENDED`]). Which one a PLC is read through is the model's ([`Table::of`]).

use super::model::Model;
use super::operand::{Area, FxOperand, PortMap, Width, CN32_BYTE, CN32_FIRST, SPECIAL, SPECIAL_COUNT};

pub const ENQ: u8 = 0x05;
pub const ACK: u8 = 0x06;
pub const NAK: u8 = 0x15;
pub const STX: u8 = 0x02;
pub const ETX: u8 = 0x03;
/// Most bytes one read or write frame carries (seed: "最多可以读取64个字节").
pub const MAX_BYTES: usize = 64;

/// Command characters.
pub mod cmd {
    pub const READ: u8 = b'0';
    pub const WRITE: u8 = b'1';
    pub const FORCE_ON: u8 = b'7';
    pub const FORCE_OFF: u8 = b'8';
}

/// The sum check: the low byte of the sum of `bytes`.
pub fn sum(bytes: &[u8]) -> u8 {
    bytes.iter().fold(0u8, |a, b| a.wrapping_add(*b))
}

const HEX: &[u8; 16] = b"0123456789ABCDEF";

/// Appends `b` as two upper-case hex digits.
pub fn push_hex2(out: &mut Vec<u8>, b: u8) {
    out.push(HEX[(b >> 4) as usize]);
    out.push(HEX[(b & 15) as usize]);
}

fn hex_val(c: u8) -> Option<u8> {
    match c {
        b'0'..=b'9' => Some(c - b'0'),
        b'A'..=b'F' => Some(c - b'A' + 10),
        b'a'..=b'f' => Some(c - b'a' + 10),
        _ => None,
    }
}

/// Two hex digits to a byte.
pub fn hex2(s: &[u8]) -> Option<u8> {
    Some(hex_val(*s.first()?)? << 4 | hex_val(*s.get(1)?)?)
}

/// The address table (and with it the command set) a frame uses.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum Table {
    /// Commands `0`, `1`, `7`, `8` and the table of [`super::operand::AREAS`]: every FX model
    /// and clone answers these.
    Classic,
    /// Commands `E00`, `E10`, `E7`, `E8` and the table of [`EXTENDED`] (FX3U and later): the
    /// FX3U's whole device ranges.
    Extended,
}

impl Table {
    /// The table a model is read and written through.
    pub fn of(model: &Model) -> Table {
        if model.extended {
            Table::Extended
        } else {
            Table::Classic
        }
    }

    /// Where this table finds an area.
    pub fn map(self, area: Area) -> PortMap {
        match self {
            Table::Classic => area.spec().port,
            Table::Extended => EXTENDED[area as usize],
        }
    }

    /// The commands, for messages and `help`.
    pub fn commands(self) -> &'static str {
        match self {
            Table::Classic => "commands 0/1/7/8",
            Table::Extended => "commands E00/E10/E7/E8",
        }
    }
}

const fn pm(byte: u16, force: Option<u16>, count: u16, special: Option<(u16, Option<u16>)>) -> PortMap {
    PortMap { byte, force, count, special }
}

/// The extended (E-command) address table, one row per [`Area`] in its order: X, Y, M, S,
/// TS, TC, CS, CC, TN, CN, D. Byte addresses (FX3U, as FX3U-era drivers use them —
/// HslCommunication `MelsecFxSerial` with `isNewVersion`, here as carried in FieldLink.PlcDrivers
/// `MelsecFxSerialAddressParser.cs`, `FxCalculateWordStartAddress`/`FxCalculateBoolStartAddress`):
/// D 4000H + 2n, D8000 8000H, T values 1000H, C values 0A00H (C200+ 0C00H, 4 bytes each),
/// M 8800H, M8000 8C00H, Y 8BC0H, X 8CA0H, S 8CE0H, C coils 92E0H, T coils 9300H, C contacts
/// 9340H, T contacts 9360H; bits 8 to a byte, lowest number in bit 0. Force addresses (E7/E8)
/// number the bits from 8000H: 8 × (byte address − 8000H) + bit — M0 is 4000H and Y0 5E00H, as
/// fx-fiddle `ref/doc/FX2N-HT32-COMMENTS/protocol/bit-addressing.md` shows them. Ordinary
/// ranges: the FX3U's (X0–X377, Y0–Y377, M0–M7679, S0–S4095, T0–T511, C0–C255, D0–D7999).
pub static EXTENDED: [PortMap; 11] = [
    pm(0x8CA0, Some(0x6500), 256, None),                          // X
    pm(0x8BC0, Some(0x5E00), 256, None),                          // Y
    pm(0x8800, Some(0x4000), 7680, Some((0x8C00, Some(0x6000)))), // M
    pm(0x8CE0, Some(0x6700), 4096, None),                         // S
    pm(0x9360, Some(0x9B00), 512, None),                          // TS
    pm(0x9300, None, 512, None),                                  // TC
    pm(0x9340, Some(0x9A00), 256, None),                          // CS
    pm(0x92E0, None, 256, None),                                  // CC
    pm(0x1000, None, 512, None),                                  // TN
    pm(0x0A00, None, 256, None),                                  // CN
    pm(0x4000, None, 8000, Some((0x8000, None))),                 // D
];

/// A request frame.
#[derive(Clone, Debug, PartialEq, Eq)]
pub enum Request {
    Read {
        table: Table,
        addr: u16,
        count: u8,
    },
    Write {
        table: Table,
        addr: u16,
        data: Vec<u8>,
    },
    Force {
        table: Table,
        on: bool,
        addr: u16,
    },
    /// `E01` (read `count` bytes) or `E11` (write `data`) of program memory.
    Program {
        write: bool,
        addr: u16,
        count: u8,
        data: Vec<u8>,
    },
}

fn push_addr(f: &mut Vec<u8>, addr: u16) {
    push_hex2(f, (addr >> 8) as u8);
    push_hex2(f, addr as u8);
}

impl Request {
    /// The frame's bytes, STX through the sum check.
    pub fn encode(&self) -> Vec<u8> {
        let mut f = vec![STX];
        let ext = |f: &mut Vec<u8>, t: &Table, code: &[u8]| {
            if *t == Table::Extended {
                f.push(b'E');
                f.extend_from_slice(code);
            } else {
                f.push(code[0]);
            }
        };
        match self {
            Request::Read { table, addr, count } => {
                ext(&mut f, table, b"00");
                push_addr(&mut f, *addr);
                push_hex2(&mut f, *count);
            }
            Request::Write { table, addr, data } => {
                ext(&mut f, table, b"10");
                push_addr(&mut f, *addr);
                push_hex2(&mut f, data.len() as u8);
                for b in data {
                    push_hex2(&mut f, *b);
                }
            }
            Request::Force { table, on, addr } => {
                ext(&mut f, table, if *on { b"7" } else { b"8" });
                // Force addresses go low byte first.
                push_hex2(&mut f, *addr as u8);
                push_hex2(&mut f, (addr >> 8) as u8);
            }
            Request::Program { write, addr, count, data } => {
                f.extend_from_slice(if *write { b"E11" } else { b"E01" });
                push_addr(&mut f, *addr);
                push_hex2(&mut f, if *write { data.len() as u8 } else { *count });
                for b in data {
                    push_hex2(&mut f, *b);
                }
            }
        }
        f.push(ETX);
        let s = sum(&f[1..]);
        push_hex2(&mut f, s);
        f
    }

    /// Bytes of the reply this request expects when it succeeds.
    pub fn reply_len(&self) -> usize {
        match self {
            Request::Read { count, .. } => 2 * *count as usize + 4,
            _ => 1,
        }
    }
}

/// Why a frame was refused (the simulator answers NAK to all of these).
#[derive(Clone, Debug, PartialEq, Eq)]
pub enum FrameError {
    BadSum {
        got: u8,
        want: u8,
    },
    /// What is wrong, as a key of [`crate::fx::link::malformed_text`] (`too-short`, …).
    Malformed(&'static str),
}

/// Decodes a complete request frame (`STX … ETX sum`), checking the sum first.
pub fn decode_request(f: &[u8]) -> Result<Request, FrameError> {
    let n = f.len();
    if n < 5 || f[0] != STX || f[n - 3] != ETX {
        return Err(FrameError::Malformed("not STX … ETX sum"));
    }
    let want = sum(&f[1..n - 2]);
    let got = hex2(&f[n - 2..]).ok_or(FrameError::Malformed("sum-not-hex"))?;
    if got != want {
        return Err(FrameError::BadSum { got, want });
    }
    let body = &f[1..n - 3];
    let (table, body) = match body.first() {
        Some(b'E') => (Table::Extended, &body[1..]),
        _ => (Table::Classic, body),
    };
    let word = |s: &[u8]| Some((hex2(s)? as u16) << 8 | hex2(&s[2..])? as u16);
    // Address, count and data after the command (`0`/`1`, or `00`/`10`/`01`/`11` after E).
    let fields = |rest: &[u8], write: bool| -> Result<(u16, u8, Vec<u8>), FrameError> {
        if rest.len() < 6 || (!write && rest.len() != 6) {
            return Err(FrameError::Malformed("unknown-command"));
        }
        let addr = word(&rest[..4]).ok_or(FrameError::Malformed("address-not-hex"))?;
        let count = hex2(&rest[4..6]).ok_or(FrameError::Malformed("count-not-hex"))?;
        let hex = &rest[6..];
        if write && hex.len() != 2 * count as usize {
            return Err(FrameError::Malformed("data-length"));
        }
        let data: Option<Vec<u8>> = hex.chunks(2).map(hex2).collect();
        Ok((addr, count, data.ok_or(FrameError::Malformed("data-not-hex"))?))
    };
    let code_len = if table == Table::Extended && matches!(body.first(), Some(b'0' | b'1')) { 2 } else { 1 };
    let (code, rest) = body.split_at(code_len.min(body.len()));
    match code {
        b"0" | b"00" => {
            let (addr, count, _) = fields(rest, false)?;
            Ok(Request::Read { table, addr, count })
        }
        b"1" | b"10" => {
            let (addr, _, data) = fields(rest, true)?;
            Ok(Request::Write { table, addr, data })
        }
        b"01" | b"11" => {
            let write = code == b"11";
            let (addr, count, data) = fields(rest, write)?;
            Ok(Request::Program { write, addr, count, data })
        }
        [c] if (*c == cmd::FORCE_ON || *c == cmd::FORCE_OFF) && rest.len() == 4 => {
            let lo = hex2(&rest[..2]).ok_or(FrameError::Malformed("address-not-hex"))?;
            let hi = hex2(&rest[2..]).ok_or(FrameError::Malformed("address-not-hex"))?;
            Ok(Request::Force { table, on: *c == cmd::FORCE_ON, addr: (hi as u16) << 8 | lo as u16 })
        }
        _ => Err(FrameError::Malformed("unknown-command")),
    }
}

/// The reply to a read: `STX data ETX sum`.
pub fn encode_read_reply(data: &[u8]) -> Vec<u8> {
    let mut f = vec![STX];
    for b in data {
        push_hex2(&mut f, *b);
    }
    f.push(ETX);
    let s = sum(&f[1..]);
    push_hex2(&mut f, s);
    f
}

/// Decodes a read reply of `count` bytes.
pub fn decode_read_reply(f: &[u8], count: usize) -> Result<Vec<u8>, FrameError> {
    if f.len() != 2 * count + 4 || f[0] != STX || f[f.len() - 3] != ETX {
        return Err(FrameError::Malformed("not-read-reply"));
    }
    let n = f.len();
    let want = sum(&f[1..n - 2]);
    let got = hex2(&f[n - 2..]).ok_or(FrameError::Malformed("sum-not-hex"))?;
    if got != want {
        return Err(FrameError::BadSum { got, want });
    }
    f[1..n - 3].chunks(2).map(|c| hex2(c).ok_or(FrameError::Malformed("data-not-hex"))).collect()
}

/// Where an operand lives in the byte address space: `len` bytes from `addr`, the value's
/// first bit at bit `bit` of the first byte (bit devices and groups).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct Place {
    pub addr: u16,
    pub len: u16,
    pub bit: u8,
}

/// The byte address of device `index` of `area` in `table` (its ordinary or special range),
/// for one device; `None` when the table does not reach it.
pub fn device_byte(table: Table, area: Area, index: u16) -> Option<(u16, u8)> {
    let p = table.map(area);
    let (base, rel) = if index >= SPECIAL && area.has_special() {
        let (b, _) = p.special?;
        if index - SPECIAL >= SPECIAL_COUNT {
            return None;
        }
        (b, index - SPECIAL)
    } else if index < p.count {
        (p.byte, index)
    } else {
        return None;
    };
    if area.is_bit() {
        Some((base + rel / 8, (rel % 8) as u8))
    } else if area == Area::CN && index >= CN32_FIRST {
        Some((CN32_BYTE + 4 * (index - CN32_FIRST), 0))
    } else {
        Some((base + 2 * rel, 0))
    }
}

/// Where an operand's bytes are in `table`, or `None` when part of it is past the table.
pub fn place(table: Table, op: &FxOperand) -> Option<Place> {
    let (addr, bit) = device_byte(table, op.area, op.index)?;
    match op.width {
        Width::Bit => Some(Place { addr, len: 1, bit }),
        Width::Group(n) => {
            let last = op.index + 4 * n as u16 - 1;
            let (end, _) = device_byte(table, op.area, last)?;
            // Both ends in one range (no crossing from M1535 into M8000).
            if (op.index >= SPECIAL) != (last >= SPECIAL) {
                return None;
            }
            Some(Place { addr, len: end - addr + 1, bit })
        }
        Width::Word => Some(Place { addr, len: 2, bit: 0 }),
        Width::Pair if op.area == Area::CN => Some(Place { addr, len: 4, bit: 0 }),
        Width::Pair => {
            device_byte(table, op.area, op.index + 1)?;
            // Both words in one range (no pair of D7999 and D8000).
            if (op.index >= SPECIAL) != (op.index + 1 >= SPECIAL) {
                return None;
            }
            Some(Place { addr, len: 4, bit: 0 })
        }
    }
}

/// The force address of a bit device in `table`, or `None` (coils, words, past the table).
pub fn force_address(table: Table, area: Area, index: u16) -> Option<u16> {
    let p = table.map(area);
    if index >= SPECIAL && area.has_special() {
        let (_, f) = p.special?;
        return (index - SPECIAL < SPECIAL_COUNT).then_some(f? + (index - SPECIAL));
    }
    (index < p.count).then_some(p.force? + index)
}

/// One contiguous stretch of the byte address space and what it holds (the reverse of the
/// table, for the simulator).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct Region {
    pub area: Area,
    pub start: u16,
    pub len: u16,
    /// Device number at `start`.
    pub first: u16,
    /// Bytes per device (0 for bit areas: 8 devices per byte).
    pub unit: u16,
}

/// Every region of `table`'s byte address space, in address order.
pub fn regions(table: Table) -> Vec<Region> {
    let mut v = Vec::new();
    for spec in super::operand::AREAS.iter() {
        let p = table.map(spec.area);
        let (unit, ord_len) = if spec.bit { (0, p.count / 8) } else { (2, p.count * 2) };
        if spec.area == Area::CN {
            v.push(Region { area: Area::CN, start: p.byte, len: 2 * CN32_FIRST, first: 0, unit: 2 });
            v.push(Region { area: Area::CN, start: CN32_BYTE, len: 4 * (p.count - CN32_FIRST), first: 200, unit: 4 });
            continue;
        }
        v.push(Region { area: spec.area, start: p.byte, len: ord_len, first: 0, unit });
        if let Some((b, _)) = p.special {
            let len = if spec.bit { SPECIAL_COUNT / 8 } else { SPECIAL_COUNT * 2 };
            v.push(Region { area: spec.area, start: b, len, first: SPECIAL, unit });
        }
    }
    v.sort_by_key(|r| r.start);
    v
}

/// The region holding byte `addr`.
pub fn region_of(regions: &[Region], addr: u16) -> Option<&Region> {
    regions.iter().find(|r| addr >= r.start && addr < r.start + r.len)
}

/// The (area, device) a force address of `table` names.
pub fn force_target(table: Table, addr: u16) -> Option<(Area, u16)> {
    for spec in super::operand::AREAS.iter() {
        let p = table.map(spec.area);
        if let Some(f) = p.force {
            if addr >= f && addr < f + p.count {
                return Some((spec.area, addr - f));
            }
        }
        if let Some((_, Some(f))) = p.special {
            if addr >= f && addr < f + SPECIAL_COUNT {
                return Some((spec.area, SPECIAL + addr - f));
            }
        }
    }
    None
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::fx::operand::parse_one;

    fn hex(s: &str) -> Vec<u8> {
        s.split_whitespace().map(|b| u8::from_str_radix(b, 16).unwrap()).collect()
    }

    fn addr(s: &str) -> u16 {
        place(Table::Classic, &parse_one(s).unwrap()).unwrap().addr
    }

    // Seed 004, "例子：从D123開始读取4个字节数据": D123 is at 0x1000 + 2·123 = 0x10F6.
    // Sum: '0'+'1'+'0'+'F'+'6'+'0'+'4'+ETX = 0x30+0x31+0x30+0x46+0x36+0x30+0x34+0x03 = 0x174 → "74".
    #[test]
    fn golden_read_4_bytes_from_d123() {
        assert_eq!(addr("D123"), 0x10F6);
        let f = Request::Read { table: Table::Classic, addr: 0x10F6, count: 4 }.encode();
        assert_eq!(f, hex("02 30 31 30 46 36 30 34 03 37 34"));
        assert_eq!(decode_request(&f).unwrap(), Request::Read { table: Table::Classic, addr: 0x10F6, count: 4 });
    }

    // Seed 004, "向D123开始的两个存储器中写入1234,ABCD": data low byte first per word:
    // 34 12 CD AB. Sum 0x31+0x31+0x30+0x46+0x36+0x30+0x34+0x33+0x34+0x31+0x32+0x43+0x44+0x41
    // +0x42+0x03 = 0x349 → "49".
    #[test]
    fn golden_write_1234_abcd_to_d123() {
        let f = Request::Write { table: Table::Classic, addr: 0x10F6, data: vec![0x34, 0x12, 0xCD, 0xAB] }.encode();
        assert_eq!(f, hex("02 31 31 30 46 36 30 34 33 34 31 32 43 44 41 42 03 34 39"));
    }

    // Seed 004, "对辅助线圈M500置位": force address 0x0800 + 500 = 0x09F4, sent low byte first
    // "F409"; sum 0x37+0x46+0x34+0x30+0x39+0x03 = 0x11D → "1D".
    #[test]
    fn golden_force_on_m500() {
        assert_eq!(force_address(Table::Classic, Area::M, 500), Some(0x09F4));
        let f = Request::Force { table: Table::Classic, on: true, addr: 0x09F4 }.encode();
        assert_eq!(f, hex("02 37 46 34 30 39 03 31 44"));
        assert_eq!(decode_request(&f).unwrap(), Request::Force { table: Table::Classic, on: true, addr: 0x09F4 });
    }

    // Seed 004, "对开关量Y10复位": Y10 is octal (device 8), force address 0x0500 + 8 = 0x0508,
    // "0805"; sum 0x38+0x30+0x38+0x30+0x35+0x03 = 0x108 → "08".
    #[test]
    fn golden_force_off_y10() {
        assert_eq!(force_address(Table::Classic, Area::Y, 8), Some(0x0508));
        assert_eq!(
            Request::Force { table: Table::Classic, on: false, addr: 0x0508 }.encode(),
            hex("02 38 30 38 30 35 03 30 38")
        );
    }

    // Seed 004, "对定时器T0线圈置位": the timer force address 0x0600 (T0), "0006"; sum
    // 0x37+0x30+0x30+0x30+0x36+0x03 = 0x100 → "00".
    #[test]
    fn golden_force_on_t0() {
        assert_eq!(force_address(Table::Classic, Area::TS, 0), Some(0x0600));
        assert_eq!(
            Request::Force { table: Table::Classic, on: true, addr: 0x0600 }.encode(),
            hex("02 37 30 30 30 36 03 30 30")
        );
    }

    // Seed 004, FX2 article fig. 6: Y20–Y37 "查装置地址表为00A2，读取2字节数据".
    // Sum 0x30+0x30+0x30+0x41+0x32+0x30+0x32+0x03 = 0x168 → "68".
    #[test]
    fn golden_read_y20_to_y37_at_00a2() {
        assert_eq!(addr("Y20"), 0x00A2);
        let k = place(Table::Classic, &parse_one("K4Y20").unwrap()).unwrap();
        assert_eq!((k.addr, k.len, k.bit), (0x00A2, 2, 0));
        assert_eq!(
            Request::Read { table: Table::Classic, addr: 0x00A2, count: 2 }.encode(),
            hex("02 30 30 30 41 32 30 32 03 36 38")
        );
    }

    // Seed 004's worked list: "将常数10写入数据单元D20" (0x1028) and "将常数0写入数据单元D8014",
    // whose address the seed does not print: D8000+ are at 0x0E00 + 2·(n − 8000) in the public
    // table (HslCommunication FxCalculateWordStartAddress, fox-edge PLC_D_Special_Base_AddRess =
    // 3584 = 0x0E00), so D8014 is 0x0E1C.
    #[test]
    fn golden_writes_to_d20_and_d8014() {
        assert_eq!(addr("D20"), 0x1028);
        // Sum 0x31+0x31+0x30+0x32+0x38+0x30+0x32+0x30+0x41+0x30+0x30+0x03 = 0x232 → "32".
        assert_eq!(
            Request::Write { table: Table::Classic, addr: 0x1028, data: vec![0x0A, 0x00] }.encode(),
            hex("02 31 31 30 32 38 30 32 30 41 30 30 03 33 32")
        );
        assert_eq!(addr("D8014"), 0x0E1C);
    }

    #[test]
    fn address_table() {
        assert_eq!(addr("S0"), 0x0000);
        assert_eq!(addr("S999"), 0x007C);
        assert_eq!(addr("X0"), 0x0080);
        assert_eq!(addr("X177"), 0x008F);
        assert_eq!(addr("TS0"), 0x00C0);
        assert_eq!(addr("M0"), 0x0100);
        assert_eq!(addr("M1023"), 0x017F);
        assert_eq!(addr("CS0"), 0x01C0);
        assert_eq!(addr("M8000"), 0x01E0);
        assert_eq!(addr("TC0"), 0x02C0);
        assert_eq!(addr("CC0"), 0x03C0);
        assert_eq!(addr("TN0"), 0x0800);
        assert_eq!(addr("CN0"), 0x0A00);
        assert_eq!(addr("CN200"), 0x0C00);
        assert_eq!(addr("CN201"), 0x0C04);
        assert_eq!(addr("D8000"), 0x0E00);
        assert_eq!(addr("D0"), 0x1000);
        assert_eq!(addr("D511"), 0x13FE);
        // D1000 and D7999 by the seed's 1000H + 2n, as node-fxplc and fxplc compute them.
        assert_eq!(addr("D1000"), 0x17D0);
        assert_eq!(addr("D7999"), 0x4E7E);
        assert!(place(Table::Classic, &parse_one("D8256").unwrap()).is_none());
        assert!(place(Table::Classic, &parse_one("D7999/DINT").unwrap()).is_none(), "D8000 is special");
        // M1535 is the last bit before the C contacts at 01C0H; its force address the last
        // before theirs at 0E00H.
        assert_eq!(addr("M1535"), 0x01BF);
        assert_eq!(force_address(Table::Classic, Area::M, 1535), Some(0x0DFF));
        assert!(place(Table::Classic, &parse_one("M1536").unwrap()).is_none());
        assert!(place(Table::Classic, &parse_one("D8256").unwrap()).is_none());
        assert_eq!(force_address(Table::Classic, Area::X, 0), Some(0x0400));
        assert_eq!(force_address(Table::Classic, Area::S, 5), Some(0x0005));
        assert_eq!(force_address(Table::Classic, Area::CS, 3), Some(0x0E03));
        assert_eq!(force_address(Table::Classic, Area::M, 8002), Some(0x0F02));
        assert_eq!(force_address(Table::Classic, Area::TC, 0), None);
        assert_eq!(force_address(Table::Classic, Area::D, 0), None);
        assert_eq!(force_target(Table::Classic, 0x09F4), Some((Area::M, 500)));
        assert_eq!(force_target(Table::Classic, 0x0F02), Some((Area::M, 8002)));
        assert_eq!(force_target(Table::Classic, 0x0508), Some((Area::Y, 8)));
        assert_eq!(force_target(Table::Classic, 0x0700), None);
    }

    #[test]
    fn regions_do_not_overlap_and_cover_every_device() {
        let r = regions(Table::Classic);
        for w in r.windows(2) {
            assert!(w[0].start + w[0].len <= w[1].start, "{:?} overlaps {:?}", w[0], w[1]);
        }
        for (s, a) in [("D511", 0x13FE), ("CN255", 0x0CDC), ("M8255", 0x01FF), ("TN255", 0x09FE)] {
            let reg = region_of(&r, a).unwrap_or_else(|| panic!("{s}"));
            assert_eq!(reg.area, parse_one(s).unwrap().area);
        }
        assert!(region_of(&r, 0x0090).is_none(), "X200 and up are not in the table");
        let e = regions(Table::Extended);
        for w in e.windows(2) {
            assert!(w[0].start + w[0].len <= w[1].start, "{:?} overlaps {:?}", w[0], w[1]);
        }
    }

    fn ext(s: &str) -> Place {
        place(Table::Extended, &parse_one(s).unwrap()).unwrap_or_else(|| panic!("{s}"))
    }

    // The E-command table (FieldLink.PlcDrivers `MelsecFxSerialAddressParser.cs`, new version):
    // D 4000H + 2n, D8000 8000H, TN 1000H, M 8800H + n/8, M8000 8C00H, Y 8BC0H, X 8CA0H,
    // S 8CE0H, CC 92E0H, TC 9300H, CS 9340H, TS 9360H.
    #[test]
    fn extended_table() {
        assert_eq!(ext("D0").addr, 0x4000);
        assert_eq!(ext("D1000").addr, 0x47D0);
        assert_eq!(ext("D7999").addr, 0x7E7E);
        assert_eq!(ext("D8000").addr, 0x8000);
        assert_eq!(ext("D8255").addr, 0x81FE);
        assert_eq!(ext("TN511").addr, 0x13FE);
        assert_eq!(ext("CN200").addr, 0x0C00);
        assert_eq!((ext("M1535").addr, ext("M1535").bit), (0x88BF, 7));
        assert_eq!(ext("M7679").addr, 0x8BBF);
        assert_eq!(ext("M8000").addr, 0x8C00);
        assert_eq!(ext("Y0").addr, 0x8BC0);
        assert_eq!(ext("X377").addr, 0x8CBF);
        assert_eq!(ext("S4095").addr, 0x8EDF);
        assert_eq!(ext("CC0").addr, 0x92E0);
        assert_eq!(ext("TC511").addr, 0x933F);
        assert_eq!(ext("CS255").addr, 0x935F);
        assert_eq!(ext("TS0").addr, 0x9360);
        assert!(place(Table::Extended, &parse_one("M7680").unwrap()).is_none());
        assert!(place(Table::Extended, &parse_one("D8256").unwrap()).is_none());
        // Force addresses: 8 × (byte − 8000H) + bit; M0 4000H, Y0 5E00H (fx-fiddle bit-addressing.md).
        assert_eq!(force_address(Table::Extended, Area::M, 0), Some(0x4000));
        assert_eq!(force_address(Table::Extended, Area::Y, 0), Some(0x5E00));
        assert_eq!(force_address(Table::Extended, Area::M, 1535), Some(0x45FF));
        assert_eq!(force_address(Table::Extended, Area::M, 8002), Some(0x6002));
        for (area, byte) in [(Area::X, 0x8CA0), (Area::S, 0x8CE0), (Area::CS, 0x9340), (Area::TS, 0x9360)] {
            assert_eq!(force_address(Table::Extended, area, 0), Some(8 * (byte - 0x8000)), "{area:?}");
        }
        assert_eq!(force_address(Table::Extended, Area::TC, 0), None);
        assert_eq!(force_target(Table::Extended, 0x45FF), Some((Area::M, 1535)));
        assert_eq!(force_target(Table::Extended, 0x5E07), Some((Area::Y, 7)));
    }

    // The E-command frames, re-created from their public descriptions (sum over everything
    // from the command's "E" through ETX).
    #[test]
    fn golden_e_command_frames() {
        // HslCommunication `BuildReadWordCommand(isNewVersion)`: STX "E00" "47D0" "02" ETX sum
        // reads D1000. Sum 0x45+0x30+0x30+0x34+0x37+0x44+0x30+0x30+0x32+0x03 = 0x1E9 → "E9".
        let f = Request::Read { table: Table::Extended, addr: 0x47D0, count: 2 }.encode();
        assert_eq!(f, b"\x02E0047D002\x03E9".to_vec());
        assert_eq!(decode_request(&f).unwrap(), Request::Read { table: Table::Extended, addr: 0x47D0, count: 2 });
        // E10: write 1234H to D7999 (7E7EH), low byte first: "E10" "7E7E" "02" "3412".
        let f = Request::Write { table: Table::Extended, addr: 0x7E7E, data: vec![0x34, 0x12] }.encode();
        assert_eq!(&f[..14], b"\x02E107E7E023412");
        assert_eq!(
            decode_request(&f).unwrap(),
            Request::Write { table: Table::Extended, addr: 0x7E7E, data: vec![0x34, 0x12] }
        );
        // fx-fiddle `set_bit`: "E7" and the address low byte first: M0 = 4000H → "E70040".
        // Sum 0x45+0x37+0x30+0x30+0x34+0x30+0x03 = 0x143 → "43".
        let f = Request::Force { table: Table::Extended, on: true, addr: 0x4000 }.encode();
        assert_eq!(f, b"\x02E70040\x0343".to_vec());
        assert_eq!(decode_request(&f).unwrap(), Request::Force { table: Table::Extended, on: true, addr: 0x4000 });
        // The FX1N example of the public write-up: STX "E00" "01C0" "01" ETX "DD".
        assert_eq!(
            decode_request(b"\x02E0001C001\x03DD").unwrap(),
            Request::Read { table: Table::Extended, addr: 0x01C0, count: 1 }
        );
        // ... and its program-memory pair: E11 "805C" 06 bytes, E01 "805C" 06 ("69", "EF").
        assert_eq!(
            decode_request(b"\x02E11805C06022403C50F00\x0369").unwrap(),
            Request::Program { write: true, addr: 0x805C, count: 6, data: vec![0x02, 0x24, 0x03, 0xC5, 0x0F, 0x00] }
        );
        assert_eq!(
            decode_request(b"\x02E01805C06\x03EF").unwrap(),
            Request::Program { write: false, addr: 0x805C, count: 6, data: vec![] }
        );
        assert!(decode_request(b"\x02E2\x0377").is_err());
    }

    #[test]
    fn replies_decode_and_bad_sums_are_caught() {
        let f = encode_read_reply(&[0x34, 0x12]);
        // STX "3412" ETX, sum 0x33+0x34+0x31+0x32+0x03 = 0xCD.
        assert_eq!(f, hex("02 33 34 31 32 03 43 44"));
        assert_eq!(decode_read_reply(&f, 2).unwrap(), vec![0x34, 0x12]);
        let mut bad = f.clone();
        bad[7] = b'E';
        assert_eq!(decode_read_reply(&bad, 2), Err(FrameError::BadSum { got: 0xCE, want: 0xCD }));
        assert!(decode_read_reply(&f, 3).is_err());
        let mut req = Request::Read { table: Table::Classic, addr: 0x10F6, count: 4 }.encode();
        req[10] = b'5';
        assert!(matches!(decode_request(&req), Err(FrameError::BadSum { .. })));
        assert!(decode_request(b"\x02\x39\x03\x33\x43").is_err(), "unknown command 9");
        assert!(decode_request(&[]).is_err());
    }
}
