//! The K2 operand grammar (`../shared/spec/k2.md` §2, bit groups from
//! `../shared/spec/fx-and-masterk.md` A): a pure parser and printer, no model knowledge
//! (bounds are checked by [`super::space`]).
//!
//! Forms: bit `M10.3`; byte `VB301`; word `VW100`, `AIW0`; double word `VD3010`; timers and
//! counters `T5`, `C10`; bit groups `K1M0`…`K8M0` (4·n bits from any bit area, `K4M10.4`
//! starts mid-byte); an optional `%` prefix; a view suffix `/INT`, `/DINT`, `/REAL`, `/SINT`
//! (and `/BOOL` on a timer or counter: its bit, `T37/BOOL`, where `T37` is its value)
//! that reads the same bytes as another type of the same width. Ranges: `VW0..VW20`
//! (inclusive, step = operand size) and the count form `VW0[10]` (ten words from VW0) —
//! brackets cannot be mistaken for the `device:` prefix. Input is case-insensitive; output
//! is canonical upper case.

use crate::core::text::edit_distance;
use crate::core::{DataType, Error, ErrorKind, Result};
use crate::msg;

/// A K2 memory area.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash, PartialOrd, Ord, serde::Serialize, serde::Deserialize)]
pub enum Area {
    I,
    Q,
    M,
    V,
    SM,
    AI,
    AQ,
    T,
    C,
}

impl Area {
    pub const ALL: [Area; 9] = [Area::I, Area::Q, Area::M, Area::V, Area::SM, Area::AI, Area::AQ, Area::T, Area::C];

    pub fn name(self) -> &'static str {
        match self {
            Area::I => "I",
            Area::Q => "Q",
            Area::M => "M",
            Area::V => "V",
            Area::SM => "SM",
            Area::AI => "AI",
            Area::AQ => "AQ",
            Area::T => "T",
            Area::C => "C",
        }
    }

    pub fn meaning(self) -> String {
        msg!("k2-area-meaning", area = self.name()).into()
    }

    /// Areas that have bit, byte, word and double-word forms.
    pub fn is_bit_area(self) -> bool {
        matches!(self, Area::I | Area::Q | Area::M | Area::V | Area::SM)
    }

    fn index(self) -> u64 {
        Area::ALL.iter().position(|a| *a == self).unwrap() as u64
    }
}

/// How much of the area an operand covers.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum Width {
    Bit(u8),
    Byte,
    Word,
    DWord,
    /// `KnX`: 4·n bits starting at bit `bit` of the byte.
    Group {
        n: u8,
        bit: u8,
    },
    /// A timer or counter (`T5`): `byte` holds the element number.
    Element,
}

impl Width {
    /// Bytes spanned (bit operands: 1; groups: the bytes they touch).
    pub fn bytes(self) -> u32 {
        match self {
            Width::Bit(_) | Width::Byte => 1,
            Width::Word => 2,
            Width::DWord => 4,
            Width::Group { n, bit } => (bit as u32 + 4 * n as u32).div_ceil(8),
            Width::Element => 1,
        }
    }
    fn code(self) -> (u64, u64, u64) {
        match self {
            Width::Bit(b) => (0, b as u64, 0),
            Width::Byte => (1, 0, 0),
            Width::Word => (2, 0, 0),
            Width::DWord => (3, 0, 0),
            Width::Group { n, bit } => (4, bit as u64, n as u64),
            Width::Element => (5, 0, 0),
        }
    }
}

/// A parsed K2 operand.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub struct K2Operand {
    pub area: Area,
    pub width: Width,
    /// Byte address (or element number for T/C).
    pub byte: u32,
    /// The type the value is shown and written as.
    pub view: DataType,
}

impl K2Operand {
    pub fn new(area: Area, width: Width, byte: u32) -> K2Operand {
        K2Operand { area, width, byte, view: default_view_at(area, width, byte) }
    }
    pub fn bit(area: Area, byte: u32, bit: u8) -> K2Operand {
        K2Operand::new(area, Width::Bit(bit), byte)
    }
    pub fn byte(area: Area, byte: u32) -> K2Operand {
        K2Operand::new(area, Width::Byte, byte)
    }
    pub fn word(area: Area, byte: u32) -> K2Operand {
        K2Operand::new(area, Width::Word, byte)
    }
    pub fn dword(area: Area, byte: u32) -> K2Operand {
        K2Operand::new(area, Width::DWord, byte)
    }

    /// Significant bits of the value.
    pub fn bits(&self) -> u32 {
        match self.width {
            Width::Group { n, .. } => 4 * n as u32,
            _ => self.view.bits(),
        }
    }

    /// Packs into the family-neutral operand key.
    pub fn key(&self) -> u64 {
        let (kind, bit, n) = self.width.code();
        let view = DataType::ALL.iter().position(|t| *t == self.view).unwrap() as u64;
        (self.byte as u64) | (self.area.index() << 32) | (kind << 36) | (bit << 40) | (n << 44) | (view << 48)
    }

    pub fn from_key(key: u64) -> K2Operand {
        let area = Area::ALL[((key >> 32) & 0xF) as usize];
        let bit = ((key >> 40) & 0xF) as u8;
        let n = ((key >> 44) & 0xF) as u8;
        let width = match (key >> 36) & 0xF {
            0 => Width::Bit(bit),
            1 => Width::Byte,
            2 => Width::Word,
            3 => Width::DWord,
            4 => Width::Group { n, bit },
            _ => Width::Element,
        };
        K2Operand { area, width, byte: key as u32, view: DataType::ALL[((key >> 48) & 0xF) as usize] }
    }

    pub fn to_core(&self) -> crate::core::Operand {
        crate::core::Operand { key: self.key(), dtype: self.view, bits: self.bits() as u8 }
    }

    /// The operand's canonical text (`VW100`, `M10.3`, `K4M0`, `VD100/REAL`).
    pub fn canonical(&self) -> String {
        let a = self.area.name();
        let mut s = match self.width {
            Width::Bit(b) => format!("{a}{}.{b}", self.byte),
            Width::Byte => format!("{a}B{}", self.byte),
            Width::Word => format!("{a}W{}", self.byte),
            Width::DWord => format!("{a}D{}", self.byte),
            Width::Group { n, bit: 0 } => format!("K{n}{a}{}", self.byte),
            Width::Group { n, bit } => format!("K{n}{a}{}.{bit}", self.byte),
            Width::Element => format!("{a}{}", self.byte),
        };
        if self.view != default_view_at(self.area, self.width, self.byte) {
            s.push('/');
            s.push_str(self.view.name());
        }
        s
    }

    /// The next operand of the same size (for ranges and counts).
    fn next(&self) -> K2Operand {
        let mut o = *self;
        match self.width {
            Width::Bit(7) => {
                o.byte += 1;
                o.width = Width::Bit(0);
            }
            Width::Bit(b) => o.width = Width::Bit(b + 1),
            Width::Group { n, bit } => {
                let abs = self.byte * 8 + bit as u32 + 4 * n as u32;
                o.byte = abs / 8;
                o.width = Width::Group { n, bit: (abs % 8) as u8 };
            }
            Width::Element => o.byte += 1,
            w => o.byte += w.bytes(),
        }
        o
    }

    /// Position in bits from the start of the area (orders operands of one size).
    fn ordinal(&self) -> u64 {
        match self.width {
            Width::Bit(b) | Width::Group { bit: b, .. } => self.byte as u64 * 8 + b as u64,
            _ => self.byte as u64 * 8,
        }
    }
}

/// The natural type of an operand: unsigned for bytes/words/dwords (as KincoBuilder
/// shows them), INT for analog words, timers and counters.
pub fn default_view(area: Area, width: Width) -> DataType {
    match (area, width) {
        (_, Width::Bit(_)) => DataType::Bool,
        (_, Width::Byte) => DataType::Byte,
        (Area::AI | Area::AQ, Width::Word) => DataType::Int,
        (_, Width::Word) => DataType::Word,
        (_, Width::DWord) => DataType::DWord,
        (_, Width::Group { n, .. }) if n <= 4 => DataType::Word,
        (_, Width::Group { .. }) => DataType::DWord,
        (_, Width::Element) => DataType::Int,
    }
}

/// The natural type of the operand at `byte`: [`default_view`], except the SM double words
/// the manual gives as DINT (position and counter values, `sm_map::is_signed_dword`).
pub fn default_view_at(area: Area, width: Width, byte: u32) -> DataType {
    if area == Area::SM && width == Width::DWord && super::sm_map::is_signed_dword(byte) {
        return DataType::DInt;
    }
    default_view(area, width)
}

/// Most operands a single range may expand to.
pub use crate::core::operand::MAX_RANGE;

fn op_err(col: usize, m: crate::core::msg::Msg) -> Error {
    Error::new(ErrorKind::Operand, m).column(col)
}

/// Parses an operand expression: one operand, a range `A..B`, or a count `A[n]`.
pub fn parse_expr(text: &str) -> Result<Vec<K2Operand>> {
    let lead = text.len() - text.trim_start().len();
    let t = text.trim();
    if let Some(dots) = t.find("..") {
        if let Some(more) = t[dots + 2..].find("..") {
            return Err(op_err(lead + dots + 2 + more, msg!("range-one-dots", example = &t[..dots + 2 + more])));
        }
        let a = parse_one(&t[..dots]).map_err(|e| e.shift(lead))?;
        let b = parse_one(&t[dots + 2..]).map_err(|e| e.shift(lead + dots + 2))?;
        if a.area != b.area || std::mem::discriminant(&a.width) != std::mem::discriminant(&b.width) || a.view != b.view
        {
            return Err(op_err(lead + dots + 2, msg!("range-mixed", first = a.canonical(), last = b.canonical())));
        }
        if let (Width::Group { n: na, .. }, Width::Group { n: nb, .. }) = (a.width, b.width) {
            if na != nb {
                return Err(op_err(lead, msg!("range-group-sizes")));
            }
        }
        if b.ordinal() < a.ordinal() {
            return Err(op_err(lead + dots + 2, msg!("range-backwards", last = b.canonical(), first = a.canonical())));
        }
        let mut out = vec![a];
        let mut cur = a;
        while cur.ordinal() < b.ordinal() {
            cur = cur.next();
            if cur.ordinal() > b.ordinal() {
                return Err(op_err(
                    lead + dots + 2,
                    msg!("range-off-step", last = b.canonical(), step = a.width.bytes(), first = a.canonical()),
                ));
            }
            out.push(cur);
            if out.len() > MAX_RANGE {
                return Err(op_err(lead, msg!("range-too-long", max = MAX_RANGE)));
            }
        }
        return Ok(out);
    }
    if let Some(open) = t.find('[') {
        return crate::core::operand::count_form(t, open, lead, "VW0[10]", parse_one, K2Operand::next);
    }
    Ok(vec![parse_one(t).map_err(|e| e.shift(lead))?])
}

/// Parses exactly one operand.
pub fn parse_one(text: &str) -> Result<K2Operand> {
    let lead = text.len() - text.trim_start().len();
    let t = text.trim();
    if t.is_empty() {
        return Err(op_err(lead, msg!("operand-missing")));
    }
    let (body, view) = match t.find('/') {
        Some(slash) => {
            let name = &t[slash + 1..];
            let v = DataType::from_name(name)
                .ok_or_else(|| op_err(lead + slash + 1, msg!("operand-unknown-type", name = name)))?;
            (&t[..slash], Some((v, slash + 1)))
        }
        None => (t, None),
    };
    let pct = usize::from(body.starts_with('%'));
    let s = body[pct..].to_ascii_uppercase();
    let base = lead + pct;
    let mut op = parse_body(&s, body).map_err(|e| e.shift(base))?;
    if let Some((v, col)) = view {
        // `T37/BOOL`, `C5/BOOL`: the timer's or counter's bit (the value is `T37`).
        let element_bit = v == DataType::Bool && op.width == Width::Element;
        if !element_bit && (v.bits() != op.view.bits() || matches!(op.width, Width::Group { .. })) {
            return Err(op_err(
                lead + col,
                msg!(
                    "operand-view-width",
                    operand = op.canonical(),
                    bits = op.bits(),
                    view = v.name(),
                    need = v.bits()
                ),
            ));
        }
        op.view = v;
    }
    Ok(op)
}

/// Reads a decimal number at the start of `s`; returns it and its length. Digits past
/// u32 read as u32::MAX: every caller refuses that ([`MAX_ADDRESS`], bits 0…7).
fn number(s: &str) -> Option<(u32, usize)> {
    let len = s.find(|c: char| !c.is_ascii_digit()).unwrap_or(s.len());
    if len == 0 {
        return None;
    }
    Some((s[..len].parse().unwrap_or(u32::MAX), len))
}

/// The largest byte (or element) address the grammar reads. Far above every area of every
/// model (the model's own limit is checked next, `K2Space::check`), and small enough that
/// stepping through a range or count (`VD65532[4096]`) and bit arithmetic (`× 8`) never
/// overflow.
pub const MAX_ADDRESS: u32 = 65_535;

/// Refuses an address past [`MAX_ADDRESS`], quoting the operand as typed.
fn address(n: u32, col: usize, original: &str) -> Result<u32> {
    if n <= MAX_ADDRESS {
        return Ok(n);
    }
    let largest = crate::k2::catalog::MODELS.iter().map(|m| m.v_bytes).max().unwrap_or(1);
    Err(op_err(col, msg!("k2-address-too-large", operand = original, max = MAX_ADDRESS, last = largest - 1)))
}

fn parse_body(s: &str, original: &str) -> Result<K2Operand> {
    if let Some(rest) = s.strip_prefix('K') {
        if rest.starts_with(|c: char| c.is_ascii_digit()) {
            return parse_group(rest, original);
        }
    }
    let (area, alen) = if s.starts_with("SM") {
        (Area::SM, 2)
    } else if s.starts_with("AI") {
        (Area::AI, 2)
    } else if s.starts_with("AQ") {
        (Area::AQ, 2)
    } else {
        match s.chars().next() {
            Some('I') => (Area::I, 1),
            Some('Q') => (Area::Q, 1),
            Some('M') => (Area::M, 1),
            Some('V') => (Area::V, 1),
            Some('T') => (Area::T, 1),
            Some('C') => (Area::C, 1),
            _ => return Err(unknown_area(s, original)),
        }
    };
    let rest = &s[alen..];
    let trailing = |used: usize| -> Result<()> {
        if used < rest.len() {
            Err(op_err(
                alen + used,
                msg!("operand-unexpected-after", rest = &original[alen + used..], head = &original[..alen + used]),
            ))
        } else {
            Ok(())
        }
    };
    match area {
        Area::T | Area::C => {
            let (n, len) =
                number(rest).ok_or_else(|| op_err(alen, msg!("k2-element-needs-number", area = area.name())))?;
            trailing(len)?;
            let n = address(n, alen, original)?;
            Ok(K2Operand::new(area, Width::Element, n))
        }
        Area::AI | Area::AQ => {
            let Some(r) = rest.strip_prefix('W') else {
                return Err(op_err(alen, msg!("k2-analog-words", area = area.name())));
            };
            let (n, len) =
                number(r).ok_or_else(|| op_err(alen + 1, msg!("k2-analog-needs-address", area = area.name())))?;
            trailing(len + 1)?;
            let n = address(n, alen + 1, original)?;
            if n % 2 != 0 {
                let a = area.name();
                let m = if n < MAX_ADDRESS {
                    msg!("k2-analog-even", below = format!("{a}W{}", n - 1), above = format!("{a}W{}", n + 1))
                } else {
                    msg!("k2-analog-even-last", below = format!("{a}W{}", n - 1))
                };
                return Err(op_err(alen + 1, m));
            }
            Ok(K2Operand::word(area, n))
        }
        _ => {
            let width = match rest.chars().next() {
                Some('B') => Some(Width::Byte),
                Some('W') => Some(Width::Word),
                Some('D') => Some(Width::DWord),
                _ => None,
            };
            if let Some(w) = width {
                let (n, len) = number(&rest[1..]).ok_or_else(|| {
                    op_err(alen + 1, msg!("k2-needs-byte-address", operand = format!("{}{}", area.name(), &rest[..1])))
                })?;
                if rest[1 + len..].starts_with('.') {
                    let bit = format!("{}{n}.{}", area.name(), &rest[2 + len..]);
                    let m = if w == Width::Byte {
                        msg!("k2-byte-has-no-bit", bit = bit)
                    } else {
                        msg!("k2-word-has-no-bit", bit = bit)
                    };
                    return Err(op_err(alen + 1 + len, m));
                }
                trailing(len + 1)?;
                let n = address(n, alen + 1, original)?;
                return Ok(K2Operand::new(area, w, n));
            }
            let (n, len) =
                number(rest).ok_or_else(|| op_err(alen, msg!("k2-needs-bit-or-size", area = area.name())))?;
            let after = &rest[len..];
            let Some(b) = after.strip_prefix('.') else {
                if after.is_empty() {
                    return Err(op_err(alen + len, msg!("k2-byte-needs-bit-or-size", area = area.name(), byte = n)));
                }
                return trailing(len).map(|_| unreachable!());
            };
            let (bit, blen) = number(b).ok_or_else(|| op_err(alen + len + 1, msg!("k2-bit-missing")))?;
            if bit > 7 {
                return Err(op_err(
                    alen + len + 1,
                    msg!("k2-bit-too-large", bit = bit, last = format!("{}{n}.7", area.name())),
                ));
            }
            trailing(len + 1 + blen)?;
            let n = address(n, alen, original)?;
            Ok(K2Operand::bit(area, n, bit as u8))
        }
    }
}

fn parse_group(rest: &str, original: &str) -> Result<K2Operand> {
    let n = rest.as_bytes()[0] - b'0';
    if !(1..=8).contains(&n) || rest.as_bytes().get(1).is_some_and(|c| c.is_ascii_digit()) {
        return Err(op_err(1, msg!("k2-group-size")));
    }
    let inner = &rest[1..];
    // A group of a group is never an operand; refusing it here keeps parsing linear (the
    // retry below would otherwise double the work for every nested `K1`).
    if inner.starts_with('K') {
        return Err(op_err(2, msg!("k2-group-nested", group = format!("K{n}"))));
    }
    let typed = &original[original.len() - inner.len()..];
    // `K4M0` names a byte without a bit: read it as bit 0. Tried first, so the usual form
    // makes no error on the way (a message costs a catalogue look-up); a text without a bit
    // that is not a byte of a bit area (`K4MB0`, `K4T5`) gets the first form's message.
    let as_bit = (!inner.contains('.')).then(|| parse_body(&format!("{inner}.0"), &format!("{typed}.0")));
    let body = match as_bit {
        Some(Ok(op)) => Ok(op),
        _ => parse_body(inner, typed).or_else(|e| {
            if inner.contains('.') {
                // A bit was given: the first error is the one to report.
                return Err(e);
            }
            parse_body(&format!("{inner}.0"), &format!("{typed}.0"))
        }),
    };
    let op = body.map_err(|e| e.shift(2))?;
    let Width::Bit(bit) = op.width else {
        return Err(op_err(
            2,
            msg!("k2-group-needs-bit", group = format!("K{n}"), example = format!("K{n}{}{}", op.area.name(), op.byte)),
        ));
    };
    if !op.area.is_bit_area() {
        return Err(op_err(2, msg!("k2-group-area", group = format!("K{n}"))));
    }
    Ok(K2Operand::new(op.area, Width::Group { n, bit }, op.byte))
}

fn unknown_area(s: &str, original: &str) -> Error {
    let head: String = s.chars().take_while(|c| c.is_ascii_alphabetic()).collect();
    let mut near: Vec<(usize, &str)> = [
        "I", "Q", "M", "V", "SM", "AI", "AQ", "T", "C", "VB", "VW", "VD", "MB", "MW", "MD", "SMB", "SMW", "SMD", "AIW",
        "AQW", "IB", "QB",
    ]
    .iter()
    .map(|c| (edit_distance(&head, c), *c))
    .collect();
    near.sort();
    let tail = &s[head.len()..];
    let suggestions: Vec<String> = if head.is_empty() {
        Vec::new()
    } else {
        near.iter().map(|(_, c)| format!("{c}{tail}")).filter(|s| parse_body(s, s).is_ok()).take(3).collect()
    };
    // The message quotes the operand as typed; the hint always names something to try.
    let typed_head: String = original.chars().take_while(|c| c.is_alphabetic()).collect();
    let what = if typed_head.is_empty() {
        msg!("k2-not-operand-no-area", operand = original)
    } else {
        msg!("k2-not-operand-unknown-area", operand = original, area = typed_head)
    };
    let hint = if !suggestions.is_empty() {
        msg!("k2-hint-did-you-mean", suggestions = suggestions.join(", "))
    } else if head.starts_with("DB") {
        msg!("k2-hint-no-data-blocks")
    } else if original.starts_with('-') {
        msg!("k2-hint-no-options")
    } else {
        msg!("k2-hint-areas")
    };
    op_err(0, what).hint(hint)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn nested_groups_are_refused_in_linear_time() {
        // Each nested K1 used to double the work (22 took about 2 s); 500 must be instant.
        let text = format!("{}M0", "K1".repeat(500));
        let e = parse_expr(&text).unwrap_err();
        assert!(e.message.contains("do not nest"), "{}", e.message);
        assert!(parse_expr("K1K1M0").is_err());
        assert_eq!(canon("K1M0"), "K1M0");
    }

    /// Addresses near the top of u32 overflowed the range iterator (`byte +=
    /// 4`), the group arithmetic (`byte * 8`) and the odd-analog hint (`n + 1`).
    #[test]
    fn addresses_past_every_area_are_refused_naming_the_limit() {
        for text in [
            "VD4294967292[2]",
            "VD4294967292..VD4294967295",
            "AIW4294967295",
            "K8M536870912.0[2]",
            "T4294967295[2]",
            "VB65536",
            "M70000.0",
        ] {
            let e = parse_expr(text).unwrap_err();
            assert!(e.message.contains("65535"), "{text}: {e}");
        }
        assert_eq!(canon("VB65535"), "VB65535", "the grammar's limit; the model's comes later");
        let e = parse_expr("AIW65535").unwrap_err();
        assert!(e.message.contains("AIW65534") && !e.message.contains("65536"), "{e}");
        assert!(parse_expr("AIW7").unwrap_err().message.contains("AIW6 or AIW8"));
    }

    fn canon(s: &str) -> String {
        let ops = parse_expr(s).unwrap_or_else(|e| panic!("{s}: {e}"));
        ops.iter().map(|o| o.canonical()).collect::<Vec<_>>().join(" ")
    }

    /// Golden vectors: every area and form (k2.md §2).
    #[test]
    fn golden_every_area_and_form() {
        let cases = [
            ("I0.0", "I0.0"),
            ("q0.5", "Q0.5"),
            ("M10.3", "M10.3"),
            ("SM0.1", "SM0.1"),
            ("V100.2", "V100.2"),
            ("IB0", "IB0"),
            ("QB0", "QB0"),
            ("MB1", "MB1"),
            ("MW0", "MW0"),
            ("MD4", "MD4"),
            ("vb301", "VB301"),
            ("VW100", "VW100"),
            ("VD3010", "VD3010"),
            ("SMB67", "SMB67"),
            ("smw68", "SMW68"),
            ("SMD72", "SMD72"),
            ("%SMD208", "SMD208"),
            ("%vw0", "VW0"),
            ("AIW0", "AIW0"),
            ("AQW2", "AQW2"),
            ("T5", "T5"),
            ("c255", "C255"),
            ("IW0", "IW0"),
            ("QD0", "QD0"),
            ("K1M0", "K1M0"),
            ("K4M0", "K4M0"),
            ("k8m0", "K8M0"),
            ("K2Q0", "K2Q0"),
            ("K4M10.4", "K4M10.4"),
            ("K1I0.0", "K1I0"),
            ("VD100/real", "VD100/REAL"),
            ("VW0/INT", "VW0/INT"),
            ("VB0/sint", "VB0/SINT"),
            ("VD4/DWORD", "VD4"),
        ];
        for (input, want) in cases {
            assert_eq!(canon(input), want, "{input}");
        }
    }

    #[test]
    fn natural_types() {
        let t = |s: &str| parse_one(s).unwrap().view;
        assert_eq!(t("M0.0"), DataType::Bool);
        assert_eq!(t("VB0"), DataType::Byte);
        assert_eq!(t("VW0"), DataType::Word);
        assert_eq!(t("VD0"), DataType::DWord);
        assert_eq!(t("AIW0"), DataType::Int);
        assert_eq!(t("T0"), DataType::Int);
        assert_eq!(t("K4M0"), DataType::Word);
        assert_eq!(t("K5M0"), DataType::DWord);
        assert_eq!(parse_one("K1M0").unwrap().bits(), 4);
    }

    #[test]
    fn round_trip_is_canonical_and_stable() {
        for s in ["%vw100", "m10.3", "smb67", "k4m10.4", "vd0/real", "aqw0", "c7", "%SM0.1"] {
            let a = parse_one(s).unwrap();
            let printed = a.canonical();
            let b = parse_one(&printed).unwrap();
            assert_eq!(a, b, "{s}");
            assert_eq!(b.canonical(), printed);
            assert_eq!(K2Operand::from_key(a.key()), a, "key round trip {s}");
        }
    }

    #[test]
    fn ranges_step_by_size_inclusive() {
        assert_eq!(canon("VW0..VW6"), "VW0 VW2 VW4 VW6");
        assert_eq!(canon("VW0[3]"), "VW0 VW2 VW4");
        assert_eq!(canon("M0.6..M1.1"), "M0.6 M0.7 M1.0 M1.1");
        assert_eq!(canon("I0.0[3]"), "I0.0 I0.1 I0.2");
        assert_eq!(canon("VD0..VD8"), "VD0 VD4 VD8");
        assert_eq!(canon("T0..T2"), "T0 T1 T2");
        assert_eq!(canon("K1M0[3]"), "K1M0 K1M0.4 K1M1");
        assert_eq!(parse_expr("VW0..VW20").unwrap().len(), 11);
    }

    #[test]
    fn bad_input_is_an_error_with_a_column() {
        let e = |s: &str| parse_expr(s).unwrap_err();
        assert_eq!(e("XW0").kind, ErrorKind::Operand);
        assert!(e("XW0").hint.clone().unwrap().contains("areas are"));
        let b = e("M10.9");
        assert_eq!(b.column, Some(4));
        assert!(b.message.contains("bits are 0…7"));
        assert!(e("M10").message.contains("needs a bit"));
        assert!(e("VW10.3").message.contains("has no bit"));
        assert!(e("AIW1").message.contains("even"));
        assert!(e("AIB0").message.contains("words"));
        assert!(e("VW0..VB4").message.contains("one area and size"));
        assert!(e("VW4..VW0").message.contains("before"));
        assert!(e("VW0..VW3").message.contains("step"));
        assert!(e("VW0[0]").message.contains("count"));
        assert!(e("VW0[x]").message.contains("not a count"));
        assert!(e("VW0[3").message.contains("missing `]`"));
        assert!(e("K9M0").message.contains("K1…K8"));
        assert!(e("K4VW0").message.contains("groups bits"));
        assert!(e("K4T0").message.contains("groups bits"));
        assert!(e("VW0/REAL").message.contains("16 bits"));
        assert!(e("VW0/FOO").message.contains("unknown type"));
        let t = e("VW10x");
        assert_eq!(t.column, Some(4));
        assert!(t.message.contains("unexpected `x`"));
        assert_eq!(e("  %VW10x").column, Some(7));
        assert!(e("").message.contains("missing"));
        assert!(e("VW0..VW10000").message.contains("longer"));
    }
}
