//! The K2 Modbus map (manual §3.2.1; `../shared/spec/k2.md` §3), used in both directions:
//! the wire driver asks "where is `VW300`?" ([`locate_read`], [`locate_write`]) and the
//! simulator's Modbus server asks "what is holding register 250?" ([`resolve`]). One table,
//! [`REGIONS`], drives both, so they cannot drift apart.
//!
//! | table | PLC area | Modbus address |
//! |---|---|---|
//! | coils (FC 01, 05, 15) | Q, M | Q bit n → n; M byte b bit k → 320 + 8·b + k |
//! | discrete inputs (FC 02) | I, M | I bit n → n; M as for coils |
//! | holding registers (FC 03, 06, 16) | AQ, V | AQW2n → n; VW2n → 100 + n |
//! | input registers (FC 04) | AI, V | AIW2n → n; VW2n → 100 + n |
//!
//! Sizes come from the model ([`K2Space::area_len`]): a K205's V area (4 KB) is holding
//! registers 100…2147, its M area (1 KB) coils 320…8511.
//!
//! Register tables hold the S7 big-endian memory image a word at a time: register 100 + n
//! is `VW2n`, whose high byte is `VB2n`. A byte, a bit or an odd-address word therefore
//! lives inside the *enclosing* registers (`VB301` is the low byte of register 250;
//! `VW301` spans registers 250 and 251). 32-bit values span two registers; their word
//! order is a device setting ([`WordOrder`], default high word first, the S7 order; public
//! sources disagree, see `../shared/spec/kinco-public-notes.md`).
//!
//! Pure: no I/O. SM, T and C are not in the map; asking for them is an error that says so.

use super::operand::{Area, K2Operand, Width};
use super::space::K2Space;
use crate::core::{Error, ErrorKind, Result};
use crate::msg;

/// Per-request limits (manual §3.2.1): read bits 1600 (FC 01/02), write bits 800 (FC 15),
/// read words 100 (FC 03/04), write words 100 (FC 16).
pub const READ_BITS_MAX: u16 = 1600;
pub const WRITE_BITS_MAX: u16 = 800;
pub const READ_WORDS_MAX: u16 = 100;
pub const WRITE_WORDS_MAX: u16 = 100;

/// A Modbus data table.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash, PartialOrd, Ord)]
pub enum Table {
    Coils,
    DiscreteInputs,
    HoldingRegisters,
    InputRegisters,
}

impl Table {
    /// Bit tables (coils, discrete inputs) as opposed to 16-bit register tables.
    pub fn is_bits(self) -> bool {
        matches!(self, Table::Coils | Table::DiscreteInputs)
    }

    pub fn name(self) -> &'static str {
        match self {
            Table::Coils => "coils",
            Table::DiscreteInputs => "discrete inputs",
            Table::HoldingRegisters => "holding registers",
            Table::InputRegisters => "input registers",
        }
    }

    /// The one function code that reads this table.
    pub fn read_fc(self) -> u8 {
        match self {
            Table::Coils => 0x01,
            Table::DiscreteInputs => 0x02,
            Table::HoldingRegisters => 0x03,
            Table::InputRegisters => 0x04,
        }
    }

    /// Most units one read may ask for.
    pub fn read_limit(self) -> u16 {
        if self.is_bits() {
            READ_BITS_MAX
        } else {
            READ_WORDS_MAX
        }
    }

    /// Most units one write may carry (`None`: the table is read-only).
    pub fn write_limit(self) -> Option<u16> {
        match self {
            Table::Coils => Some(WRITE_BITS_MAX),
            Table::HoldingRegisters => Some(WRITE_WORDS_MAX),
            _ => None,
        }
    }

    /// The table a function code addresses, and whether it writes.
    pub fn of_fc(fc: u8) -> Option<(Table, bool)> {
        Some(match fc {
            0x01 => (Table::Coils, false),
            0x02 => (Table::DiscreteInputs, false),
            0x03 => (Table::HoldingRegisters, false),
            0x04 => (Table::InputRegisters, false),
            0x05 | 0x0F => (Table::Coils, true),
            0x06 | 0x10 => (Table::HoldingRegisters, true),
            _ => return None,
        })
    }
}

/// One PLC area as it appears in one Modbus table.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct Region {
    pub table: Table,
    pub area: Area,
    /// Modbus address of the area's first bit or word.
    pub base: u16,
}

/// The K2 Modbus map (manual §3.2.1, k2.md §3). Index into this table = region id.
pub static REGIONS: &[Region] = &[
    Region { table: Table::Coils, area: Area::Q, base: 0 },
    Region { table: Table::Coils, area: Area::M, base: 320 },
    Region { table: Table::DiscreteInputs, area: Area::I, base: 0 },
    Region { table: Table::DiscreteInputs, area: Area::M, base: 320 },
    Region { table: Table::HoldingRegisters, area: Area::AQ, base: 0 },
    Region { table: Table::HoldingRegisters, area: Area::V, base: 100 },
    Region { table: Table::InputRegisters, area: Area::AI, base: 0 },
    Region { table: Table::InputRegisters, area: Area::V, base: 100 },
];

impl Region {
    /// Number of bits or registers this region has on a model (0: the model lacks the area).
    pub fn len(&self, space: &K2Space) -> u32 {
        let bytes = space.area_len(self.area);
        if self.table.is_bits() {
            bytes * 8
        } else {
            bytes / 2
        }
    }

    /// One past the last address on a model.
    pub fn end(&self, space: &K2Space) -> u32 {
        self.base as u32 + self.len(space)
    }
}

fn region_id(table: Table, area: Area) -> u8 {
    REGIONS.iter().position(|r| r.table == table && r.area == area).expect("region in the map") as u8
}

/// How the two registers of a 32-bit value are ordered on the wire.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub enum WordOrder {
    /// High word in the lower register (S7 order, the default).
    #[default]
    HighFirst,
    /// Low word in the lower register.
    LowFirst,
}

impl WordOrder {
    pub fn parse(s: &str) -> Result<WordOrder> {
        match s.to_ascii_lowercase().as_str() {
            "high-first" | "high" | "big" | "abcd" => Ok(WordOrder::HighFirst),
            "low-first" | "low" | "little" | "cdab" => Ok(WordOrder::LowFirst),
            _ => Err(Error::usage(msg!("tbl-modbus-word-order", value = s)).hint(msg!("tbl-modbus-word-order-hint"))),
        }
    }

    pub fn name(self) -> &'static str {
        match self {
            WordOrder::HighFirst => "high-first",
            WordOrder::LowFirst => "low-first",
        }
    }
}

/// Where an operand's value lives on the wire: `count` bits or registers from `start` in
/// region `region` (an index into [`REGIONS`]).
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash, PartialOrd, Ord)]
pub struct Span {
    pub region: u8,
    pub start: u16,
    pub count: u16,
}

impl Span {
    pub fn region(&self) -> &'static Region {
        &REGIONS[self.region as usize]
    }
    pub fn table(&self) -> Table {
        self.region().table
    }
    /// One past the last address.
    pub fn end(&self) -> u32 {
        self.start as u32 + self.count as u32
    }
    /// `holding registers 250…251`, `coil 3`.
    pub fn describe(&self) -> String {
        let t = self.table().name();
        if self.count == 1 {
            format!("{} {}", t.trim_end_matches('s'), self.start)
        } else {
            format!("{t} {}…{}", self.start, self.end() - 1)
        }
    }
}

/// First bit (relative to the area's bit 0) and number of bits an operand covers.
fn bit_extent(op: &K2Operand) -> (u32, u32) {
    let first = op.byte * 8;
    match op.width {
        Width::Bit(b) => (first + b as u32, 1),
        Width::Group { n, bit } => (first + bit as u32, 4 * n as u32),
        w => (first, w.bytes() * 8),
    }
}

/// The error for areas outside the map (SM, T, C).
fn not_in_map(op: &K2Operand) -> Error {
    Error::new(
        ErrorKind::Unsupported,
        msg!(
            "tbl-modbus-not-in-map",
            operand = op.canonical(),
            area = op.area.name(),
            meaning = op.area.meaning().to_string()
        ),
    )
    .operand(op.canonical())
    .hint(if op.area == Area::SM {
        msg!("tbl-modbus-not-in-map-sm-hint")
    } else {
        msg!("tbl-modbus-not-in-map-tc-hint")
    })
}

fn span_in(space: &K2Space, table: Table, op: &K2Operand) -> Result<Span> {
    let id = region_id(table, op.area);
    let region = &REGIONS[id as usize];
    let (first, count) = if table.is_bits() {
        bit_extent(op)
    } else {
        let end_byte = op.byte + op.width.bytes();
        (op.byte / 2, end_byte.div_ceil(2) - op.byte / 2)
    };
    if first + count > region.len(space) {
        // The operand space checks bounds first; this only fires for an unchecked operand.
        return Err(Error::new(
            ErrorKind::Range,
            msg!("tbl-modbus-past-end", operand = op.canonical(), area = op.area.name(), model = space.model.name),
        )
        .operand(op.canonical()));
    }
    Ok(Span { region: id, start: (region.base as u32 + first) as u16, count: count as u16 })
}

/// Where to read an operand: Q and M from coils (FC 01), I from discrete inputs (FC 02),
/// V and AQ from holding registers (FC 03), AI from input registers (FC 04).
pub fn locate_read(space: &K2Space, op: &K2Operand) -> Result<Span> {
    let table = match op.area {
        Area::Q | Area::M => Table::Coils,
        Area::I => Table::DiscreteInputs,
        Area::V | Area::AQ => Table::HoldingRegisters,
        Area::AI => Table::InputRegisters,
        Area::SM | Area::T | Area::C => return Err(not_in_map(op)),
    };
    span_in(space, table, op)
}

/// Where to write an operand: Q and M are coils (FC 05/15), V and AQ holding registers
/// (FC 06/16). I and AI are read-only over Modbus.
pub fn locate_write(space: &K2Space, op: &K2Operand) -> Result<Span> {
    let table = match op.area {
        Area::Q | Area::M => Table::Coils,
        Area::V | Area::AQ => Table::HoldingRegisters,
        Area::I | Area::AI => {
            return Err(Error::new(
                ErrorKind::Unsupported,
                msg!(
                    "tbl-modbus-read-only",
                    operand = op.canonical(),
                    meaning = op.area.meaning().to_string(),
                    table =
                        if op.area == Area::I { Table::DiscreteInputs.name() } else { Table::InputRegisters.name() }
                ),
            )
            .operand(op.canonical())
            .hint(msg!("tbl-modbus-read-only-hint")))
        }
        Area::SM | Area::T | Area::C => return Err(not_in_map(op)),
    };
    span_in(space, table, op)
}

/// True when writing the operand must first read its registers: it covers part of a
/// register (a byte, a bit, an odd-address word). Coils are written bit by bit, never.
pub fn write_needs_read(op: &K2Operand, span: &Span) -> bool {
    if span.table().is_bits() {
        return false;
    }
    let (first, bits) = bit_extent(op);
    first % 16 != 0 || bits % 16 != 0
}

/// The data of a span: bits (bit tables) or registers.
#[derive(Clone, Copy, Debug)]
pub enum Data<'a> {
    Bits(&'a [bool]),
    Words(&'a [u16]),
}

/// Mutable span data, for encoding writes in place.
#[derive(Debug)]
pub enum DataMut<'a> {
    Bits(&'a mut [bool]),
    Words(&'a mut [u16]),
}

/// Swaps the two 16-bit halves (word order of a 32-bit value).
fn swap_words(raw: u32) -> u32 {
    raw.rotate_left(16)
}

/// Reads an operand's raw pattern from the big-endian bytes it covers (starting at its
/// first byte).
fn raw_from_bytes(op: &K2Operand, bytes: &[u8], order: WordOrder) -> u32 {
    match op.width {
        Width::Bit(b) => ((bytes[0] >> b) & 1) as u32,
        Width::Byte => bytes[0] as u32,
        Width::Word => u16::from_be_bytes([bytes[0], bytes[1]]) as u32,
        Width::DWord => {
            let v = u32::from_be_bytes([bytes[0], bytes[1], bytes[2], bytes[3]]);
            if order == WordOrder::LowFirst {
                swap_words(v)
            } else {
                v
            }
        }
        Width::Group { n, bit } => {
            let mut v = 0;
            for k in 0..4 * n as u32 {
                let abs = bit as u32 + k;
                v |= (((bytes[(abs / 8) as usize] >> (abs % 8)) & 1) as u32) << k;
            }
            v
        }
        Width::Element => 0,
    }
}

/// Writes an operand's raw pattern into the big-endian bytes it covers.
fn raw_into_bytes(op: &K2Operand, raw: u32, bytes: &mut [u8], order: WordOrder) {
    match op.width {
        Width::Bit(b) => {
            if raw & 1 != 0 {
                bytes[0] |= 1 << b
            } else {
                bytes[0] &= !(1 << b)
            }
        }
        Width::Byte => bytes[0] = raw as u8,
        Width::Word => bytes[..2].copy_from_slice(&(raw as u16).to_be_bytes()),
        Width::DWord => {
            let v = if order == WordOrder::LowFirst { swap_words(raw) } else { raw };
            bytes[..4].copy_from_slice(&v.to_be_bytes())
        }
        Width::Group { n, bit } => {
            for k in 0..4 * n as u32 {
                let abs = bit as u32 + k;
                let m = 1u8 << (abs % 8);
                let byte = &mut bytes[(abs / 8) as usize];
                if (raw >> k) & 1 != 0 {
                    *byte |= m
                } else {
                    *byte &= !m
                }
            }
        }
        Width::Element => {}
    }
}

/// Most registers one operand spans (`VD301`: 3).
const MAX_SPAN_WORDS: usize = 4;

/// Registers → the big-endian bytes they hold (no allocation: an operand spans ≤ 3).
fn words_to_bytes(words: &[u16]) -> [u8; 2 * MAX_SPAN_WORDS] {
    assert!(words.len() <= MAX_SPAN_WORDS, "an operand spans at most {MAX_SPAN_WORDS} registers");
    let mut b = [0u8; 2 * MAX_SPAN_WORDS];
    for (i, w) in words.iter().enumerate() {
        b[2 * i..2 * i + 2].copy_from_slice(&w.to_be_bytes());
    }
    b
}

/// Decodes an operand's raw pattern from the data of exactly its span (as given by
/// [`locate_read`] or [`locate_write`]).
pub fn decode(op: &K2Operand, data: Data<'_>, order: WordOrder) -> u32 {
    match data {
        Data::Words(w) => {
            let bytes = words_to_bytes(w);
            raw_from_bytes(op, &bytes[(op.byte % 2) as usize..], order)
        }
        Data::Bits(bits) => {
            let mut v = 0u32;
            for (k, b) in bits.iter().enumerate().take(32) {
                v |= (*b as u32) << k;
            }
            match op.width {
                // Bit groups and single bits: bit k of the value is bit k of the span.
                Width::Bit(_) | Width::Group { .. } => v,
                // Bytes, words, double words: byte k of the area is bits 8k…8k+7; the value
                // is the bytes in S7 (big-endian) order.
                _ => {
                    let bytes = v.to_le_bytes(); // byte k of the span = bits 8k…8k+7
                    raw_from_bytes(op, &bytes, WordOrder::HighFirst)
                }
            }
        }
    }
}

/// Decodes an operand's raw pattern straight from a read reply's data as it travelled:
/// registers as big-endian bytes (which are the S7 memory image, so an operand's bytes are a
/// slice of the reply) or coils and inputs packed LSB first (`bits`); the operand's span
/// starts `off` units into the reply and is `count` units long. Equal to [`decode`] of the
/// span's words or bits; this is the driver's bulk path, with no copy per operand.
pub fn decode_reply(op: &K2Operand, bits: bool, data: &[u8], off: usize, count: usize, order: WordOrder) -> u32 {
    if !bits {
        return raw_from_bytes(op, &data[2 * off + (op.byte % 2) as usize..2 * (off + count)], order);
    }
    let mut v = 0u32;
    for k in 0..count.min(32) {
        let b = off + k;
        v |= (((data[b / 8] >> (b % 8)) & 1) as u32) << k;
    }
    match op.width {
        Width::Bit(_) | Width::Group { .. } => v,
        _ => raw_from_bytes(op, &v.to_le_bytes(), WordOrder::HighFirst),
    }
}

/// Encodes an operand's raw pattern into the data of exactly its span. For a register
/// span the bytes outside the operand keep their current value (the caller fills the span
/// with what it read first when [`write_needs_read`] says so).
pub fn encode(op: &K2Operand, raw: u32, data: DataMut<'_>, order: WordOrder) {
    match data {
        DataMut::Words(w) => {
            let mut bytes = words_to_bytes(w);
            raw_into_bytes(op, raw, &mut bytes[(op.byte % 2) as usize..], order);
            for (i, word) in w.iter_mut().enumerate() {
                *word = u16::from_be_bytes([bytes[2 * i], bytes[2 * i + 1]]);
            }
        }
        DataMut::Bits(bits) => {
            let v = match op.width {
                Width::Bit(_) | Width::Group { .. } => raw,
                _ => {
                    let mut be = [0u8; 4];
                    raw_into_bytes(op, raw, &mut be, WordOrder::HighFirst);
                    (0..op.width.bytes()).fold(0u32, |acc, k| acc | (be[k as usize] as u32) << (8 * k))
                }
            };
            for (k, b) in bits.iter_mut().enumerate() {
                *b = (v >> k) & 1 != 0;
            }
        }
    }
}

/// Modbus exception codes a K2 answers with (Modbus application protocol §7).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Exception {
    IllegalFunction = 1,
    IllegalDataAddress = 2,
    IllegalDataValue = 3,
    /// The device could not do what the request asked (the simulator: its state file
    /// could not be written, so the store cannot be acknowledged as kept).
    ServerDeviceFailure = 4,
}

/// The standard name of a Modbus exception code.
pub fn exception_name(code: u8) -> &'static str {
    match code {
        1 => "illegal function",
        2 => "illegal data address",
        3 => "illegal data value",
        4 => "server device failure",
        5 => "acknowledge",
        6 => "server device busy",
        8 => "memory parity error",
        0x0A => "gateway path unavailable",
        0x0B => "gateway target device failed to respond",
        _ => "unknown exception",
    }
}

/// Checks a request's quantity against the manual's limits (`Err(IllegalDataValue)` for
/// zero or too many).
pub fn check_quantity(fc: u8, count: usize) -> std::result::Result<(), Exception> {
    let max = match fc {
        0x01 | 0x02 => READ_BITS_MAX,
        0x0F => WRITE_BITS_MAX,
        0x03 | 0x04 => READ_WORDS_MAX,
        0x10 => WRITE_WORDS_MAX,
        0x05 | 0x06 => 1,
        _ => return Err(Exception::IllegalFunction),
    };
    if count == 0 || count > max as usize {
        Err(Exception::IllegalDataValue)
    } else {
        Ok(())
    }
}

/// The reverse map, for the server: the region holding `count` units from `addr` in
/// `table`, and the offset of `addr` in it (bits or registers from the area's start).
/// A request that is not wholly inside one area is an illegal data address (the manual:
/// a request that runs past the end of an area is refused).
pub fn resolve(
    space: &K2Space,
    table: Table,
    addr: u16,
    count: u16,
) -> std::result::Result<(&'static Region, u32), Exception> {
    let end = addr as u32 + count as u32;
    REGIONS
        .iter()
        .filter(|r| r.table == table)
        .find(|r| r.base <= addr && end <= r.end(space) && r.len(space) > 0)
        .map(|r| (r, (addr - r.base) as u32))
        .ok_or(Exception::IllegalDataAddress)
}

/// The operand at a Modbus address (`VW300` for holding register 250, `M1.2` for coil
/// 330), for messages.
pub fn operand_at(space: &K2Space, table: Table, addr: u16) -> Option<String> {
    let (region, off) = resolve(space, table, addr, 1).ok()?;
    let op = if table.is_bits() {
        K2Operand::bit(region.area, off / 8, (off % 8) as u8)
    } else {
        K2Operand::word(region.area, off * 2)
    };
    Some(op.canonical())
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::k2::catalog;
    use crate::k2::operand::parse_one;

    fn space(m: &str) -> K2Space {
        K2Space::new(catalog::find(m).unwrap())
    }

    fn read_span(s: &K2Space, text: &str) -> (Table, u16, u16) {
        let sp = locate_read(s, &parse_one(text).unwrap()).unwrap();
        (sp.table(), sp.start, sp.count)
    }

    // Golden vectors: manual §3.2.1 (k2.md §3 register number table).
    #[test]
    fn golden_addresses_from_the_manual() {
        let s = space("K205-16DT");
        use Table::*;
        // Q0.0 … Q0.5 → coil 0 … 5.
        assert_eq!(read_span(&s, "Q0.0"), (Coils, 0, 1));
        assert_eq!(read_span(&s, "Q0.5"), (Coils, 5, 1));
        // I bit n → discrete input n.
        assert_eq!(read_span(&s, "I0.7"), (DiscreteInputs, 7, 1));
        assert_eq!(read_span(&s, "I1.0"), (DiscreteInputs, 8, 1));
        // M byte b bit k → 320 + 8·b + k; M0.0 = 320, M1023.7 = 8511.
        assert_eq!(read_span(&s, "M0.0"), (Coils, 320, 1));
        assert_eq!(read_span(&s, "M10.3"), (Coils, 320 + 83, 1));
        assert_eq!(read_span(&s, "M1023.7"), (Coils, 8511, 1));
        assert_eq!(read_span(&s, "MB10"), (Coils, 400, 8));
        assert_eq!(read_span(&s, "MW10"), (Coils, 400, 16));
        assert_eq!(read_span(&s, "K4M10.4"), (Coils, 404, 16));
        // VW2n → holding register 100 + n: VW0 = 100, VW4094 = 2147.
        assert_eq!(read_span(&s, "VW0"), (HoldingRegisters, 100, 1));
        assert_eq!(read_span(&s, "VW100"), (HoldingRegisters, 150, 1));
        assert_eq!(read_span(&s, "VW4094"), (HoldingRegisters, 2147, 1));
        // 32-bit: two registers; odd addresses need the enclosing registers.
        assert_eq!(read_span(&s, "VD100"), (HoldingRegisters, 150, 2));
        assert_eq!(read_span(&s, "VB301"), (HoldingRegisters, 250, 1));
        assert_eq!(read_span(&s, "VW301"), (HoldingRegisters, 250, 2));
        assert_eq!(read_span(&s, "VD301"), (HoldingRegisters, 250, 3));
        assert_eq!(read_span(&s, "V101.2"), (HoldingRegisters, 150, 1));
        // AIW2n → input register n, AQW2n → holding register n.
        let ea = space("K209EA-50DX");
        assert_eq!(read_span(&ea, "AIW0"), (InputRegisters, 0, 1));
        assert_eq!(read_span(&ea, "AIW10"), (InputRegisters, 5, 1));
        assert_eq!(read_span(&ea, "AQW2"), (HoldingRegisters, 1, 1));
        // V's last register follows the model: 16 KB on K209M.
        assert_eq!(read_span(&space("K209M-56DT"), "VW16382"), (HoldingRegisters, 100 + 8191, 1));
    }

    #[test]
    fn sm_t_c_are_not_in_the_map_and_inputs_are_read_only() {
        let s = space("K205-16DT");
        for t in ["SMB67", "SM0.0", "T5", "C10"] {
            let e = locate_read(&s, &parse_one(t).unwrap()).unwrap_err();
            assert_eq!(e.kind, ErrorKind::Unsupported);
            assert!(e.message.contains("not in the K2 Modbus map"), "{}", e.message);
            let hint = e.hint.as_deref().unwrap();
            if t.starts_with("SM") {
                assert!(hint.contains("helper program") && hint.contains("agent=VB3400"), "{hint}");
            } else {
                assert!(hint.contains("copy timers and counters to V"), "{hint}");
            }
        }
        assert!(locate_write(&s, &parse_one("I0.0").unwrap()).unwrap_err().message.contains("read-only"));
        assert_eq!(locate_write(&s, &parse_one("M0.1").unwrap()).unwrap().table(), Table::Coils);
    }

    #[test]
    fn reverse_map_finds_the_area_and_refuses_gaps_and_ends() {
        let s = space("K205-16DT");
        let (r, off) = resolve(&s, Table::HoldingRegisters, 250, 2).unwrap();
        assert_eq!((r.area, off), (Area::V, 150));
        let (r, off) = resolve(&s, Table::Coils, 403, 1).unwrap();
        assert_eq!((r.area, off), (Area::M, 83));
        assert_eq!(resolve(&s, Table::Coils, 8511, 1).unwrap().1, 8191);
        // Past the end of M, past the end of V, in the gap between Q and M.
        assert_eq!(resolve(&s, Table::Coils, 8511, 2), Err(Exception::IllegalDataAddress));
        assert_eq!(resolve(&s, Table::HoldingRegisters, 2147, 2), Err(Exception::IllegalDataAddress));
        assert_eq!(resolve(&s, Table::Coils, 16, 1), Err(Exception::IllegalDataAddress));
        // Q has 16 coils on the K205 (2 bytes): a read spanning Q and the gap is refused.
        assert!(resolve(&s, Table::Coils, 0, 16).is_ok());
        assert_eq!(resolve(&s, Table::Coils, 0, 17), Err(Exception::IllegalDataAddress));
        // No AI on the K205.
        assert_eq!(resolve(&s, Table::InputRegisters, 0, 1), Err(Exception::IllegalDataAddress));
        assert_eq!(operand_at(&s, Table::HoldingRegisters, 250).as_deref(), Some("VW300"));
        assert_eq!(operand_at(&s, Table::Coils, 330).as_deref(), Some("M1.2"));
    }

    #[test]
    fn limits_from_the_manual() {
        assert!(check_quantity(0x01, 1600).is_ok());
        assert_eq!(check_quantity(0x01, 1601), Err(Exception::IllegalDataValue));
        assert_eq!(check_quantity(0x0F, 801), Err(Exception::IllegalDataValue));
        assert!(check_quantity(0x0F, 800).is_ok());
        assert_eq!(check_quantity(0x03, 101), Err(Exception::IllegalDataValue));
        assert_eq!(check_quantity(0x10, 101), Err(Exception::IllegalDataValue));
        assert_eq!(check_quantity(0x04, 0), Err(Exception::IllegalDataValue));
        assert_eq!(check_quantity(0x08, 1), Err(Exception::IllegalFunction));
    }

    #[test]
    fn register_bytes_follow_s7_order() {
        let o = |t: &str| parse_one(t).unwrap();
        // Register 250 = VW300 = 0x1234: VB300 = 0x12, VB301 = 0x34 (S7 big-endian).
        assert_eq!(decode(&o("VB300"), Data::Words(&[0x1234]), WordOrder::HighFirst), 0x12);
        assert_eq!(decode(&o("VB301"), Data::Words(&[0x1234]), WordOrder::HighFirst), 0x34);
        assert_eq!(decode(&o("V300.1"), Data::Words(&[0x0200]), WordOrder::HighFirst), 1);
        assert_eq!(decode(&o("VW301"), Data::Words(&[0x1234, 0x5678]), WordOrder::HighFirst), 0x3456);
        assert_eq!(decode(&o("VD300"), Data::Words(&[0x1122, 0x3344]), WordOrder::HighFirst), 0x11223344);
        assert_eq!(decode(&o("VD300"), Data::Words(&[0x3344, 0x1122]), WordOrder::LowFirst), 0x11223344);
        assert_eq!(decode(&o("VD301"), Data::Words(&[0xAA11, 0x2233, 0x44BB]), WordOrder::HighFirst), 0x11223344);
    }

    #[test]
    fn decoding_from_a_reply_equals_decoding_the_span() {
        let s = space("K205-16DT");
        let texts = [
            "VB300",
            "VB301",
            "V300.1",
            "V301.7",
            "VW300",
            "VW301",
            "VD300",
            "VD301",
            "VD300/REAL",
            "K4V300.4",
            "M1.2",
            "MB1",
            "MW1",
            "MD3",
            "K3M0.5",
            "K8M1",
            "Q0.5",
            "QB1",
        ];
        for text in texts {
            let op = parse_one(text).unwrap();
            let span = locate_read(&s, &op).unwrap();
            let bits = span.table().is_bits();
            for off in [0usize, 1, 5, 9] {
                // A reply holding the span `off` units in, with data before and after it.
                let units = off + span.count as usize + 3;
                let pattern = |k: usize| (k * 0x9E37 + 0x5A) as u16;
                let (bytes, value) = if bits {
                    let all: Vec<bool> = (0..units).map(|k| pattern(k) & 0x40 != 0).collect();
                    let mut packed = vec![0u8; units.div_ceil(8)];
                    for (k, on) in all.iter().enumerate() {
                        packed[k / 8] |= (*on as u8) << (k % 8);
                    }
                    (packed, decode(&op, Data::Bits(&all[off..off + span.count as usize]), WordOrder::LowFirst))
                } else {
                    let all: Vec<u16> = (0..units).map(pattern).collect();
                    let bytes = all.iter().flat_map(|w| w.to_be_bytes()).collect();
                    (bytes, decode(&op, Data::Words(&all[off..off + span.count as usize]), WordOrder::LowFirst))
                };
                let from_reply = decode_reply(&op, bits, &bytes, off, span.count as usize, WordOrder::LowFirst);
                assert_eq!(from_reply, value, "{text} at {off}");
            }
        }
    }

    #[test]
    fn encode_keeps_the_rest_of_the_register() {
        let o = |t: &str| parse_one(t).unwrap();
        let mut w = [0x1234u16];
        encode(&o("VB301"), 0xAB, DataMut::Words(&mut w), WordOrder::HighFirst);
        assert_eq!(w, [0x12AB]);
        let mut w = [0xFFFFu16];
        encode(&o("V300.0"), 0, DataMut::Words(&mut w), WordOrder::HighFirst);
        assert_eq!(w, [0xFEFF], "V300.0 is bit 8 of register 250");
        let mut w = [0xAA00u16, 0x00BB, 0xCCCC];
        encode(&o("VD301"), 0x11223344, DataMut::Words(&mut w), WordOrder::HighFirst);
        assert_eq!(w, [0xAA11, 0x2233, 0x44CC]);
        let mut w = [0u16; 2];
        encode(&o("VD300"), 0x11223344, DataMut::Words(&mut w), WordOrder::LowFirst);
        assert_eq!(w, [0x3344, 0x1122]);
        let s = space("K205-16DT");
        for (t, rmw) in [("VW300", false), ("VD300", false), ("VB300", true), ("VW301", true), ("V300.0", true)] {
            let sp = locate_write(&s, &o(t)).unwrap();
            assert_eq!(write_needs_read(&o(t), &sp), rmw, "{t}");
        }
        assert!(!write_needs_read(&o("M0.0"), &locate_write(&s, &o("M0.0")).unwrap()));
    }

    #[test]
    fn coil_bytes_are_lsb_first_and_words_big_endian() {
        let o = |t: &str| parse_one(t).unwrap();
        // MB10 = 0b1000_0101: coils 400 (M10.0) and 402 (M10.2) and 407 (M10.7) on.
        let mut bits = [false; 8];
        encode(&o("MB10"), 0x85, DataMut::Bits(&mut bits), WordOrder::HighFirst);
        assert_eq!(bits, [true, false, true, false, false, false, false, true]);
        assert_eq!(decode(&o("MB10"), Data::Bits(&bits), WordOrder::HighFirst), 0x85);
        // MW10 = 0x1234: MB10 (coils 400…407) = 0x12, MB11 (408…415) = 0x34.
        let mut bits = [false; 16];
        encode(&o("MW10"), 0x1234, DataMut::Bits(&mut bits), WordOrder::LowFirst);
        assert!(bits[1] && bits[4] && !bits[0], "0x12 in the first eight coils");
        assert!(bits[8 + 2] && bits[8 + 4] && bits[8 + 5], "0x34 in the next eight");
        assert_eq!(decode(&o("MW10"), Data::Bits(&bits), WordOrder::HighFirst), 0x1234);
        let mut g = [false; 4];
        encode(&o("K1M0.4"), 0b1010, DataMut::Bits(&mut g), WordOrder::HighFirst);
        assert_eq!(g, [false, true, false, true]);
    }
}
