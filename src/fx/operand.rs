//! FX device names: one data table ([`AREAS`]) says, for every device kind, its name, its
//! meaning, how it is numbered, and where each protocol finds it; the parser, the printer,
//! completion, `help`, both codecs and the simulator all read it.
//!
//! Names (`../shared/spec/fx-and-masterk.md` A and B, seed 004):
//! - bits `X0` `Y17` (octal numbers: X0–X7, X10 …; a digit 8 or 9 is an error that says so),
//!   `M500`, `M8000`, `S20`, timer and counter contacts `TS0` `CS10` and coils `TC0` `CC10`
//!   (the names public FX drivers use). A bare `T0` / `C10` is what FX programmers write
//!   (`LD T0`): it names the **contact**, `TS0` / `CS10`; the current value is `TN0` / `CN10`;
//! - words `D100` (INT; `/WORD` reads it unsigned), `D8000`+ special registers, current values
//!   `TN0` and `CN0`; `CN200`–`CN255` are the 32-bit counters;
//! - D pairs as 32-bit values: `D100/DINT` (also `/DWORD`, `/REAL`) is D100 (low word) with
//!   D101 (high word), as FX 32-bit instructions use them;
//! - bit groups `KnX0` `KnY0` `KnM0` `KnS0`, n = 1–8: 4·n consecutive bits as a number, the
//!   lowest-numbered bit least significant (spec A, seed 004). K1–K4 are 16-bit operands and
//!   read as INT, K5–K8 32-bit and read as DINT, as FX operations are signed; missing high bits
//!   are zero, so a K1–K3 (K5–K7) group is never negative. `/WORD` (`/DWORD`) reads a full
//!   group unsigned. A K1–K4 group also has a 32-bit view (`K4Y0/DINT`): its high 16 bits are
//!   zero, as when K4Y0 is used in a 32-bit operation — use `K8Y0` for 32 bits. A group should
//!   start at a number ending in 0 (X0, X10, M0, M10 …): others are accepted and `describe`
//!   warns.
//!
//! Ranges `D0..D9` and counts `D0[10]` step by the operand's size. Input is case-insensitive
//! and may start with `%`; output is canonical upper case.

use crate::core::msg::Msg;
use crate::core::{DataType, Error, ErrorKind, Operand, Result};
use crate::msg;

/// Longest range one expression may name.
pub use crate::core::operand::MAX_RANGE;
/// First special device number (M8000, D8000).
pub const SPECIAL: u16 = 8000;
/// Special devices the address tables cover: M8000–M8255, D8000–D8255.
pub const SPECIAL_COUNT: u16 = 256;

/// A kind of FX device.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash, PartialOrd, Ord)]
pub enum Area {
    X,
    Y,
    M,
    S,
    TS,
    TC,
    CS,
    CC,
    TN,
    CN,
    D,
}

/// Where the programming-port protocol finds an area (seed 004, "装置地址表"; the table
/// below is the one public FX drivers use: HslCommunication `MelsecFxSerialHelper`
/// (FxCalculateBoolStartAddress / FxCalculateWordStartAddress / BuildWriteBoolPacket) and
/// fox-edge `MitsubishiPlcAddress.java`, which agree on every base here).
#[derive(Clone, Copy, Debug)]
pub struct PortMap {
    /// Byte address of device 0 for read/write (commands 0 and 1). Bit areas pack 8
    /// devices per byte, lowest number in bit 0; word areas take 2 bytes per device, low
    /// byte first.
    pub byte: u16,
    /// Force address of device 0 (commands 7 and 8), or none: the area cannot be forced.
    pub force: Option<u16>,
    /// Devices the ordinary range of the table covers (device numbers 0 … n−1).
    pub count: u16,
    /// The special range (8000 …): its byte address and force address.
    pub special: Option<(u16, Option<u16>)>,
}

/// One row of the device table.
#[derive(Clone, Copy, Debug)]
pub struct AreaSpec {
    pub area: Area,
    /// The name as written (`X`, `TS`, `CN`).
    pub name: &'static str,
    /// A bit device (on/off) rather than a word device.
    pub bit: bool,
    /// Numbered in octal (X and Y).
    pub octal: bool,
    /// Accepts `set` (through force or write; coils follow the program and are read-only).
    pub writable: bool,
    /// Can form `Kn` groups.
    pub groups: bool,
    /// The programming-port address table.
    pub port: PortMap,
    /// The device code in computer-link frames (`X`, `TS`, `D`); digits fill it to 5 characters.
    pub link: &'static str,
}

const fn pm(byte: u16, force: Option<u16>, count: u16, special: Option<(u16, Option<u16>)>) -> PortMap {
    PortMap { byte, force, count, special }
}

/// The device table. Programming-port bases: S 0x0000 (force 0x0000), X 0x0080 (0x0400),
/// Y 0x00A0 (0x0500), T contacts 0x00C0 (0x0600), M 0x0100 (0x0800), C contacts 0x01C0
/// (0x0E00), M8000 0x01E0 (0x0F00), T coils 0x02C0, C coils 0x03C0, T values 0x0800, C values
/// 0x0A00 (C200+ 32-bit at 0x0C00, 4 bytes each), D8000 0x0E00, D 0x1000 (seed: 0x1000 + 2·n).
/// Ordinary ranges of this classic table: X0–X177, Y0–Y177, S0–S999, T/C 0–255 (HslCommunication
/// `MelsecFxSerial` remarks), M0–M1535 (0100H–01BFH, up to the C contacts at 01C0H; force
/// 0800H–0DFFH, up to 0E00H) and D0–D7999 (1000H + 2n, the seed's formula, 1000H–4E7FH with
/// nothing else above 1000H) — the reach public drivers compute with these bases for any
/// number (node-fxplc `lib/registers.js`, KrystianD/fxplc `FXPLCClient.py`), cut where the next
/// area begins; plus M8000–M8255 and D8000–D8255. The model decides what of it exists.
pub static AREAS: [AreaSpec; 11] = [
    AreaSpec {
        area: Area::X,
        name: "X",
        bit: true,
        octal: true,
        writable: true,
        groups: true,
        port: pm(0x0080, Some(0x0400), 128, None),
        link: "X",
    },
    AreaSpec {
        area: Area::Y,
        name: "Y",
        bit: true,
        octal: true,
        writable: true,
        groups: true,
        port: pm(0x00A0, Some(0x0500), 128, None),
        link: "Y",
    },
    AreaSpec {
        area: Area::M,
        name: "M",
        bit: true,
        octal: false,
        writable: true,
        groups: true,
        port: pm(0x0100, Some(0x0800), 1536, Some((0x01E0, Some(0x0F00)))),
        link: "M",
    },
    AreaSpec {
        area: Area::S,
        name: "S",
        bit: true,
        octal: false,
        writable: true,
        groups: true,
        port: pm(0x0000, Some(0x0000), 1000, None),
        link: "S",
    },
    AreaSpec {
        area: Area::TS,
        name: "TS",
        bit: true,
        octal: false,
        writable: true,
        groups: false,
        port: pm(0x00C0, Some(0x0600), 256, None),
        link: "TS",
    },
    AreaSpec {
        area: Area::TC,
        name: "TC",
        bit: true,
        octal: false,
        writable: false,
        groups: false,
        port: pm(0x02C0, None, 256, None),
        link: "",
    },
    AreaSpec {
        area: Area::CS,
        name: "CS",
        bit: true,
        octal: false,
        writable: true,
        groups: false,
        port: pm(0x01C0, Some(0x0E00), 256, None),
        link: "CS",
    },
    AreaSpec {
        area: Area::CC,
        name: "CC",
        bit: true,
        octal: false,
        writable: false,
        groups: false,
        port: pm(0x03C0, None, 256, None),
        link: "",
    },
    AreaSpec {
        area: Area::TN,
        name: "TN",
        bit: false,
        octal: false,
        writable: true,
        groups: false,
        port: pm(0x0800, None, 256, None),
        link: "TN",
    },
    AreaSpec {
        area: Area::CN,
        name: "CN",
        bit: false,
        octal: false,
        writable: true,
        groups: false,
        port: pm(0x0A00, None, 256, None),
        link: "CN",
    },
    AreaSpec {
        area: Area::D,
        name: "D",
        bit: false,
        octal: false,
        writable: true,
        groups: false,
        port: pm(0x1000, None, 8000, Some((0x0E00, None))),
        link: "D",
    },
];

/// Special devices with their meaning (FX programming manual, special device lists; the ones
/// every FX and clone has). `help`, hints and completion read this table.
pub static SPECIALS: &[(Area, u16)] = &[
    (Area::M, 8000),
    (Area::M, 8001),
    (Area::M, 8002),
    (Area::M, 8003),
    (Area::M, 8011),
    (Area::M, 8012),
    (Area::M, 8013),
    (Area::M, 8014),
    (Area::D, 8000),
    (Area::D, 8010),
    (Area::D, 8011),
    (Area::D, 8012),
    (Area::D, 8120),
    (Area::D, 8121),
];

/// Special devices the CPU drives every scan (FX PM, special device list): the RUN monitors
/// and initial pulses M8000–M8003, the clocks M8011–M8014, the scan times D8010–D8012. A
/// write to them changes nothing on a PLC; the driver refuses it with a message.
pub static SYSTEM_DRIVEN: &[(Area, u16, u16)] = &[(Area::M, 8000, 8003), (Area::M, 8011, 8014), (Area::D, 8010, 8012)];

/// Whether device `index` of `area` is one the CPU drives ([`SYSTEM_DRIVEN`]).
pub fn system_driven(area: Area, index: u16) -> bool {
    SYSTEM_DRIVEN.iter().any(|(a, lo, hi)| *a == area && (*lo..=*hi).contains(&index))
}

/// The meaning of a special device, if the table has it.
pub fn special_meaning(area: Area, index: u16) -> Option<Msg> {
    SPECIALS
        .iter()
        .find(|(a, i)| *a == area && *i == index)
        .map(|(a, i)| msg!("fx-special-meaning", device = format!("{}{i}", a.name())))
}

/// First 32-bit counter: CN200–CN255 hold 32-bit values (4 bytes each on the programming port).
pub const CN32_FIRST: u16 = 200;
/// Byte address of CN200 on the programming port.
pub const CN32_BYTE: u16 = 0x0C00;

impl Area {
    pub fn spec(self) -> &'static AreaSpec {
        &AREAS[self as usize]
    }
    pub fn name(self) -> &'static str {
        self.spec().name
    }
    /// What the area holds, in words.
    pub fn meaning(self) -> Msg {
        msg!("fx-area-meaning", area = self.name())
    }
    pub fn is_bit(self) -> bool {
        self.spec().bit
    }
    fn from_code(c: u8) -> Option<Area> {
        AREAS.get(c as usize).map(|s| s.area)
    }
    /// Whether `index` is in the special range (M8000+, D8000+).
    pub fn has_special(self) -> bool {
        matches!(self, Area::M | Area::D)
    }
}

/// The size of an operand.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum Width {
    /// One bit device.
    Bit,
    /// One 16-bit word.
    Word,
    /// 32 bits: a D pair (Dn low, Dn+1 high) or a 32-bit counter CN200+.
    Pair,
    /// A `Kn` group of 4·n bits.
    Group(u8),
}

/// A parsed FX operand (no model knowledge: bounds are checked by [`super::space`]).
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub struct FxOperand {
    pub area: Area,
    /// Device number (X/Y: the value of the octal number, X10 = 8).
    pub index: u16,
    pub width: Width,
    /// The type values are shown and written as.
    pub view: DataType,
}

fn type_code(t: DataType) -> u8 {
    DataType::ALL.iter().position(|x| *x == t).unwrap_or(0) as u8
}

impl FxOperand {
    /// The type an operand has without a `/TYPE` suffix.
    pub fn natural(width: Width) -> DataType {
        match width {
            Width::Bit => DataType::Bool,
            Width::Group(n) if n <= 4 => DataType::Int,
            Width::Group(_) => DataType::DInt,
            Width::Word => DataType::Int,
            Width::Pair => DataType::DInt,
        }
    }

    pub fn new(area: Area, index: u16, width: Width) -> FxOperand {
        FxOperand { area, index, width, view: FxOperand::natural(width) }
    }

    /// Bits the value has (16 or 32 for words, 4·n for groups, 1 for bits).
    pub fn bits(&self) -> u32 {
        match self.width {
            Width::Bit => 1,
            Width::Word => 16,
            Width::Pair => 32,
            Width::Group(n) => 4 * n as u32,
        }
    }

    /// Device numbers this operand spans (bits for groups, words for D pairs, 1 otherwise).
    pub fn span(&self) -> u16 {
        match self.width {
            Width::Group(n) => 4 * n as u16,
            Width::Pair if self.area == Area::D => 2,
            _ => 1,
        }
    }

    pub fn to_core(&self) -> Operand {
        let w: u64 = match self.width {
            Width::Bit => 0,
            Width::Word => 1,
            Width::Pair => 2,
            Width::Group(n) => 3 | (n as u64) << 4,
        };
        let key = self.area as u64 | (self.index as u64) << 8 | w << 24 | (type_code(self.view) as u64) << 40;
        Operand { key, dtype: self.view, bits: self.bits() as u8 }
    }

    pub fn from_key(key: u64) -> FxOperand {
        let area = Area::from_code((key & 0xFF) as u8).unwrap_or(Area::D);
        let index = ((key >> 8) & 0xFFFF) as u16;
        let w = (key >> 24) & 0xFF;
        let width = match w & 0xF {
            0 => Width::Bit,
            1 => Width::Word,
            2 => Width::Pair,
            _ => Width::Group((w >> 4) as u8),
        };
        let view = DataType::ALL[((key >> 40) & 0xFF) as usize % DataType::ALL.len()];
        FxOperand { area, index, width, view }
    }

    /// The device number as written (`17` for X15 decimal, `500` for M500).
    pub fn number_text(area: Area, index: u16) -> String {
        if area.spec().octal {
            format!("{index:o}")
        } else {
            index.to_string()
        }
    }

    /// Canonical text: `X17`, `K4M0`, `D100/DINT`, `CN200`.
    pub fn canonical(&self) -> String {
        let mut s = match self.width {
            Width::Group(n) => format!("K{n}{}{}", self.area.name(), Self::number_text(self.area, self.index)),
            _ => format!("{}{}", self.area.name(), Self::number_text(self.area, self.index)),
        };
        let natural = FxOperand::natural(self.width);
        let shown_natural = match self.width {
            Width::Pair if self.area == Area::D => DataType::Word, // a pair always shows its type
            _ => natural,
        };
        if self.view != shown_natural || (self.width == Width::Pair && self.area == Area::D) {
            s.push('/');
            s.push_str(self.view.name());
        }
        s
    }

    /// The next operand of the same size (for ranges).
    pub fn next(&self) -> FxOperand {
        let mut o = *self;
        o.index = self.index.saturating_add(self.span());
        o
    }

    /// Whether a group starts where the manual advises (a number ending in 0).
    pub fn group_aligned(&self) -> bool {
        match self.width {
            Width::Group(_) if self.area.spec().octal => self.index.is_multiple_of(8),
            Width::Group(_) => self.index.is_multiple_of(10),
            _ => true,
        }
    }
}

fn op_err(col: usize, msg: impl Into<crate::core::error::Text>) -> Error {
    Error::new(ErrorKind::Operand, msg).column(col)
}

/// Parses an operand expression: one operand, a range `A..B`, or a count `A[n]`.
pub fn parse_expr(text: &str) -> Result<Vec<FxOperand>> {
    let lead = text.len() - text.trim_start().len();
    let t = text.trim();
    if let Some(dots) = t.find("..") {
        let a = parse_one(&t[..dots]).map_err(|e| e.shift(lead))?;
        let b = parse_one(&t[dots + 2..]).map_err(|e| e.shift(lead + dots + 2))?;
        if a.area != b.area || a.width != b.width || a.view != b.view {
            return Err(op_err(lead + dots + 2, msg!("fx-range-kind", first = a.canonical(), last = b.canonical())));
        }
        if b.index < a.index {
            return Err(op_err(
                lead + dots + 2,
                msg!("fx-range-reversed", last = b.canonical(), first = a.canonical()),
            ));
        }
        let step = a.span() as usize;
        let n = (b.index - a.index) as usize;
        if !n.is_multiple_of(step) {
            return Err(op_err(
                lead + dots + 2,
                msg!("fx-range-steps", last = b.canonical(), step = step, first = a.canonical()),
            ));
        }
        if n / step >= MAX_RANGE {
            return Err(op_err(lead, msg!("fx-range-long", max = MAX_RANGE)));
        }
        let mut out = vec![a];
        let mut cur = a;
        while cur.index < b.index {
            cur = cur.next();
            out.push(cur);
        }
        return Ok(out);
    }
    if let Some(open) = t.find('[') {
        return crate::core::operand::count_form(t, open, lead, "D0[10]", parse_one, FxOperand::next);
    }
    Ok(vec![parse_one(t).map_err(|e| e.shift(lead))?])
}

/// The area named at the start of `s` (longest name first), with its length.
fn area_prefix(s: &str) -> Option<(Area, usize)> {
    let up = s.as_bytes();
    let two = if up.len() >= 2 { Some([up[0].to_ascii_uppercase(), up[1].to_ascii_uppercase()]) } else { None };
    for spec in AREAS.iter().filter(|a| a.name.len() == 2) {
        if two == Some([spec.name.as_bytes()[0], spec.name.as_bytes()[1]]) {
            return Some((spec.area, 2));
        }
    }
    let c = up.first()?.to_ascii_uppercase();
    AREAS.iter().find(|a| a.name.len() == 1 && a.name.as_bytes()[0] == c).map(|a| (a.area, 1))
}

/// Parses a device number in the area's numbering; `col` is where the digits start.
fn parse_number(area: Area, digits: &str, col: usize, whole: &str) -> Result<u16> {
    if digits.is_empty() {
        return Err(op_err(col, msg!("fx-number-missing", text = whole, area = area.name())));
    }
    if let Some((i, c)) = digits.char_indices().find(|(_, c)| !c.is_ascii_digit()) {
        return Err(op_err(col + i, msg!("fx-not-digit", char = c.to_string(), text = whole)));
    }
    if digits.len() > 5 {
        return Err(op_err(col, msg!("fx-number-long", digits = digits)));
    }
    if area.spec().octal {
        if let Some((i, c)) = digits.char_indices().find(|(_, c)| *c == '8' || *c == '9') {
            return Err(op_err(col + i, msg!("fx-not-octal", area = area.name(), char = c.to_string(), text = whole)));
        }
        return u16::from_str_radix(digits, 8).map_err(|_| op_err(col, msg!("fx-number-large-octal", digits = digits)));
    }
    digits.parse().map_err(|_| op_err(col, msg!("fx-number-large", digits = digits, max = u16::MAX)))
}

/// Parses exactly one operand.
pub fn parse_one(text: &str) -> Result<FxOperand> {
    let lead = text.len() - text.trim_start().len();
    let t0 = text.trim();
    if t0.is_empty() {
        return Err(op_err(lead, msg!("fx-operand-missing")));
    }
    let (t, lead) = match t0.strip_prefix('%') {
        Some(r) => (r, lead + 1),
        None => (t0, lead),
    };
    let (body, view) = match t.find('/') {
        Some(slash) => {
            let name = &t[slash + 1..];
            let v = DataType::from_name(name)
                .ok_or_else(|| op_err(lead + slash + 1, msg!("fx-unknown-type", name = name)))?;
            (&t[..slash], Some((v, lead + slash + 1)))
        }
        None => (t, None),
    };
    let upper = body.to_ascii_uppercase();
    // Kn groups.
    let (group, rest, col) = if upper.starts_with('K') && upper.len() > 1 && upper.as_bytes()[1].is_ascii_digit() {
        let n = upper.as_bytes()[1] - b'0';
        if !(1..=8).contains(&n) {
            return Err(op_err(lead + 1, msg!("fx-group-digits", n = n)));
        }
        (Some(n), &upper[2..], lead + 2)
    } else {
        (None, &upper[..], lead)
    };
    let Some((area, len)) = area_prefix(rest).or_else(|| bare_t_or_c(rest)) else {
        return Err(op_err(col, msg!("fx-unknown-device", text = body)).hint(msg!("fx-hint-devices")));
    };
    let digits = &rest[len..];
    let index = parse_number(area, digits, col + len, body)?;
    let width = match group {
        Some(n) => {
            if !area.spec().groups {
                return Err(op_err(lead, msg!("fx-group-area", n = n, area = area.name())));
            }
            Width::Group(n)
        }
        None if area.is_bit() => Width::Bit,
        None if area == Area::CN && index >= CN32_FIRST => Width::Pair,
        None => Width::Word,
    };
    let mut op = FxOperand::new(area, index, width);
    if let Some((v, vcol)) = view {
        op = apply_view(op, v, vcol)?;
    }
    Ok(op)
}

/// `T5` / `C5` as FX programmers write them (`LD T5`): the timer's or counter's contact,
/// [`Area::TS`] / [`Area::CS`] (FX Series Programming Manual, "Timers" and "Counters": the
/// contact of T5 is written T5). The current value is `TN5` / `CN5`.
fn bare_t_or_c(rest: &str) -> Option<(Area, usize)> {
    let b = rest.as_bytes();
    let area = match b.first()? {
        b'T' => Area::TS,
        b'C' => Area::CS,
        _ => return None,
    };
    b.get(1).is_some_and(u8::is_ascii_digit).then_some((area, 1))
}

/// Whether `/TYPE` may view a group of `n` digits: a 16-bit type for K1–K4 (the group
/// zero-extended to 16 bits), a 32-bit integer for any group (zero-extended: `K4Y0/DINT` has
/// its high 16 bits zero, spec A), REAL only for a full K8.
fn group_view_ok(n: u8, v: DataType) -> bool {
    match v.bits() {
        16 => n <= 4 && v != DataType::Bool,
        32 if v == DataType::Real => n == 8,
        32 => true,
        _ => false,
    }
}

fn apply_view(op: FxOperand, v: DataType, col: usize) -> Result<FxOperand> {
    let mut o = op;
    let bad = || op_err(col, msg!("fx-view", operand = op.canonical(), dtype = v.name())).hint(msg!("fx-hint-view"));
    match op.width {
        Width::Bit => {
            if v != DataType::Bool {
                return Err(bad());
            }
        }
        Width::Word if op.area == Area::D => {
            if v.bits() == 32 {
                o.width = Width::Pair;
            } else if v.bits() != 16 {
                return Err(bad());
            }
        }
        Width::Group(n) => {
            if !group_view_ok(n, v) {
                return Err(bad());
            }
        }
        Width::Word | Width::Pair => {
            if v.bits() != op.bits() || v == DataType::Bool {
                return Err(bad());
            }
        }
    }
    o.view = v;
    Ok(o)
}

#[cfg(test)]
mod tests {
    use super::*;

    fn p(s: &str) -> FxOperand {
        parse_one(s).unwrap_or_else(|e| panic!("{s}: {e}"))
    }

    #[test]
    fn device_numbers_past_u16_name_the_limit() {
        assert!(parse_one("D70000").unwrap_err().message.contains("up to 65535"));
    }

    #[test]
    fn octal_x_and_y() {
        assert_eq!(p("X0").index, 0);
        assert_eq!(p("X7").index, 7);
        assert_eq!(p("X10").index, 8);
        assert_eq!(p("y37").index, 31);
        assert_eq!(p("X17").canonical(), "X17");
        let e = parse_one("X8").unwrap_err();
        assert!(e.message.contains("octal") && e.message.contains("`8`"), "{e}");
        assert_eq!(e.column, Some(1));
        let e = parse_one("Y19").unwrap_err();
        assert!(e.message.contains("`9` is not an octal digit"), "{e}");
        assert_eq!(e.column, Some(2));
        // M is decimal: M8 and M19 are fine.
        assert_eq!(p("M19").index, 19);
    }

    #[test]
    fn canonical_round_trip() {
        for s in [
            "X0",
            "X177",
            "Y10",
            "M500",
            "M8000",
            "S20",
            "TS0",
            "TC3",
            "CS10",
            "CC255",
            "TN5",
            "CN10",
            "CN200",
            "D100",
            "D8014",
            "D100/DINT",
            "D100/REAL",
            "D100/WORD",
            "D0/DWORD",
            "K4M0",
            "K8M0",
            "K2X10",
            "K1Y0",
            "K4S0/WORD",
            "K8M0/DWORD",
            "K4Y0/DINT",
            "K2X0/DWORD",
            "K8M0/REAL",
        ] {
            let o = p(s);
            assert_eq!(o.canonical(), s);
            assert_eq!(FxOperand::from_key(o.to_core().key), o, "{s}");
        }
        assert_eq!(p("%d100").canonical(), "D100");
        assert_eq!(p("k4m0").canonical(), "K4M0");
        assert_eq!(p("D100/INT").canonical(), "D100");
        assert_eq!(p("K4M0/INT").canonical(), "K4M0");
        assert_eq!(p("t7").canonical(), "TS7");
        assert_eq!(p("C200").canonical(), "CS200");
    }

    #[test]
    fn types_and_widths() {
        assert_eq!(p("D0").view, DataType::Int);
        assert_eq!(p("D0/DINT").width, Width::Pair);
        assert_eq!(p("D0/DINT").span(), 2);
        assert_eq!(p("CN200").width, Width::Pair);
        assert_eq!(p("CN200").view, DataType::DInt);
        assert_eq!(p("CN199").width, Width::Word);
        // FX 16-bit operations are signed: K4 reads as INT, K8 as DINT (spec A).
        assert_eq!(p("K4M0").view, DataType::Int);
        assert_eq!(p("K3M0").view, DataType::Int);
        assert_eq!(p("K3M0").bits(), 12);
        assert_eq!(p("K5M0").view, DataType::DInt);
        assert_eq!(p("K8M0").view, DataType::DInt);
        assert_eq!(p("K8M0").bits(), 32);
        assert_eq!(p("K4M0/WORD").view, DataType::Word);
        // A 16-bit group in a 32-bit operation: high 16 bits zero (K4Y0/DINT), 16 bits wide.
        let k = p("K4Y0/DINT");
        assert_eq!((k.view, k.bits(), k.span()), (DataType::DInt, 16, 16));
        assert!(parse_one("K5M0/INT").is_err(), "20 bits do not fit 16");
        assert!(parse_one("K4M0/REAL").is_err() && parse_one("K7M0/REAL").is_err());
        assert!(parse_one("K4M0/BOOL").is_err());
        assert!(parse_one("K9M0").is_err());
        assert!(parse_one("K0M0").is_err());
        assert!(parse_one("K4D0").is_err());
        assert!(parse_one("K4TS0").is_err());
        assert!(parse_one("M0/INT").is_err());
        assert!(parse_one("Q0").is_err());
    }

    #[test]
    fn bare_timer_and_counter_names_are_their_contacts() {
        // FX programmers write `LD T0`: the contact. The value is TN0 / CN0.
        assert_eq!(p("T0"), p("TS0"));
        assert_eq!(p("%c10"), p("CS10"));
        assert_eq!(p("T0").width, Width::Bit);
        assert!(parse_one("T0/INT").is_err(), "a contact is a bit; the value is TN0");
        assert!(parse_one("T").unwrap_err().message.contains("unknown FX device"));
        assert!(parse_one("TX5").is_err() && parse_one("\u{e9}5").is_err() && parse_one("\u{3a7}").is_err());
        assert!(parse_one("K4T0").unwrap_err().message.contains("groups are made of"));
    }

    #[test]
    fn octal_errors_name_the_area_they_are_about() {
        let e = parse_one("Y8").unwrap_err();
        assert!(e.message.contains("Y numbers are octal (Y0–Y7, Y10–Y17"), "{e}");
        let e = parse_one("X19").unwrap_err();
        assert!(e.message.contains("X numbers are octal (X0–X7, X10–X17"), "{e}");
    }

    #[test]
    fn ranges_and_counts() {
        let r = parse_expr("D0..D3").unwrap();
        assert_eq!(r.len(), 4);
        let r = parse_expr("D0/DINT..D6/DINT").unwrap();
        assert_eq!(r.iter().map(|o| o.index).collect::<Vec<_>>(), vec![0, 2, 4, 6]);
        assert!(parse_expr("D0/DINT..D5/DINT").is_err());
        let r = parse_expr("X0[10]").unwrap();
        assert_eq!(r[9].canonical(), "X11");
        let r = parse_expr("K4M0[2]").unwrap();
        assert_eq!(r[1].canonical(), "K4M16");
        assert!(parse_expr("D5..D1").is_err());
        assert!(parse_expr("D0..M5").is_err());
    }

    #[test]
    fn group_alignment() {
        assert!(p("K4M0").group_aligned());
        assert!(p("K4M10").group_aligned());
        assert!(!p("K4M3").group_aligned());
        assert!(p("K2X10").group_aligned());
        assert!(!p("K2X4").group_aligned());
    }
}
