//! Typed values that cross every layer: the data types a PLC or drive operand can hold
//! (IEC 61131-3 names, as KincoBuilder prints them) and the value itself.
//!
//! Devices store raw bit patterns; the shell and Lua see numbers. `DataType` is the one
//! place that knows how a raw pattern of a given width becomes a number and back.

use serde::Serialize;
use std::fmt;

/// The type an operand holds. Widths follow IEC 61131-3 (BYTE = 8 bits, WORD = 16 …).
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash, Serialize)]
#[serde(rename_all = "UPPERCASE")]
pub enum DataType {
    Bool,
    Byte,
    SInt,
    Word,
    Int,
    DWord,
    DInt,
    Real,
}

impl DataType {
    pub const ALL: [DataType; 8] = [
        DataType::Bool,
        DataType::Byte,
        DataType::SInt,
        DataType::Word,
        DataType::Int,
        DataType::DWord,
        DataType::DInt,
        DataType::Real,
    ];

    /// Width in bits.
    pub fn bits(self) -> u32 {
        match self {
            DataType::Bool => 1,
            DataType::Byte | DataType::SInt => 8,
            DataType::Word | DataType::Int => 16,
            DataType::DWord | DataType::DInt | DataType::Real => 32,
        }
    }

    pub fn is_signed(self) -> bool {
        matches!(self, DataType::SInt | DataType::Int | DataType::DInt)
    }

    /// The canonical upper-case name (`WORD`, `DINT` …).
    pub fn name(self) -> &'static str {
        match self {
            DataType::Bool => "BOOL",
            DataType::Byte => "BYTE",
            DataType::SInt => "SINT",
            DataType::Word => "WORD",
            DataType::Int => "INT",
            DataType::DWord => "DWORD",
            DataType::DInt => "DINT",
            DataType::Real => "REAL",
        }
    }

    /// Parses a type name: IEC names and the short `u8 i8 u16 i16 u32 i32 f32` forms.
    pub fn from_name(s: &str) -> Option<DataType> {
        Some(match s.to_ascii_uppercase().as_str() {
            "BOOL" | "BIT" => DataType::Bool,
            "BYTE" | "U8" | "USINT" => DataType::Byte,
            "SINT" | "I8" => DataType::SInt,
            "WORD" | "U16" | "UINT" => DataType::Word,
            "INT" | "I16" => DataType::Int,
            "DWORD" | "U32" | "UDINT" => DataType::DWord,
            "DINT" | "I32" => DataType::DInt,
            "REAL" | "F32" => DataType::Real,
            _ => return None,
        })
    }

    /// Smallest and largest integer this type holds (REAL: the integer range of f32 is not
    /// meaningful, so i64 bounds are returned).
    pub fn int_range(self) -> (i64, i64) {
        match self {
            DataType::Bool => (0, 1),
            DataType::Real => (i64::MIN, i64::MAX),
            t if t.is_signed() => {
                let b = t.bits();
                (-(1i64 << (b - 1)), (1i64 << (b - 1)) - 1)
            }
            t => (0, (1i64 << t.bits()) - 1),
        }
    }

    /// Turns a raw bit pattern (in the low `bits()` bits of `raw`) into a value.
    pub fn decode(self, raw: u32) -> Value {
        match self {
            DataType::Bool => Value::Bool(raw & 1 != 0),
            DataType::Byte => Value::Int((raw & 0xFF) as i64),
            DataType::SInt => Value::Int(raw as u8 as i8 as i64),
            DataType::Word => Value::Int((raw & 0xFFFF) as i64),
            DataType::Int => Value::Int(raw as u16 as i16 as i64),
            DataType::DWord => Value::Int(raw as i64),
            DataType::DInt => Value::Int(raw as i32 as i64),
            DataType::Real => Value::Real(real_as_read(f32::from_bits(raw))),
        }
    }

    /// Turns a value that already fits this type into its raw bit pattern.
    pub fn encode(self, v: &Value) -> u32 {
        match (self, v) {
            (DataType::Real, Value::Real(r)) => (*r as f32).to_bits(),
            (DataType::Real, Value::Int(i)) => (*i as f32).to_bits(),
            (_, Value::Bool(b)) => *b as u32,
            (_, Value::Int(i)) => (*i as u64 & mask(self.bits())) as u32,
            (_, Value::Real(r)) => (*r as i64 as u64 & mask(self.bits())) as u32,
        }
    }
}

/// All-ones mask of `bits` width (1..=32).
pub fn mask(bits: u32) -> u64 {
    (1u64 << bits) - 1
}

impl fmt::Display for DataType {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.write_str(self.name())
    }
}

/// A value read from or written to a device.
#[derive(Clone, Copy, Debug, PartialEq, Serialize)]
#[serde(untagged)]
pub enum Value {
    Bool(bool),
    Int(i64),
    Real(f64),
}

impl Value {
    pub fn as_i64(&self) -> i64 {
        match *self {
            Value::Bool(b) => b as i64,
            Value::Int(i) => i,
            Value::Real(r) => r as i64,
        }
    }
    pub fn as_f64(&self) -> f64 {
        match *self {
            Value::Bool(b) => b as i64 as f64,
            Value::Int(i) => i as f64,
            Value::Real(r) => r,
        }
    }
    pub fn as_bool(&self) -> bool {
        match *self {
            Value::Bool(b) => b,
            Value::Int(i) => i != 0,
            Value::Real(r) => r != 0.0,
        }
    }
}

/// A REAL as people read it: the f64 nearest the shortest decimal that reads back to the same
/// f32 (`3.14`, not `3.140000104904175`), so the shell, JSON and Lua all show `3.14` and
/// writing it back stores the same bits. Falls back to the exact widening where the two
/// roundings would disagree.
pub fn real_as_read(f: f32) -> f64 {
    match f.to_string().parse::<f64>() {
        Ok(d) if (d as f32).to_bits() == f.to_bits() => d,
        _ => f as f64,
    }
}

impl fmt::Display for Value {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            Value::Bool(b) => write!(f, "{}", *b as u8),
            Value::Int(i) => write!(f, "{i}"),
            Value::Real(r) => write!(f, "{r}"),
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    // 3.14 is the value a user types (`VD8/REAL=3.14`), not an approximation of π.
    #[allow(clippy::approx_constant)]
    fn reals_read_as_their_shortest_text_and_round_trip() {
        for f in [3.14f32, 0.1, -2.5e-7, 1.0e30, 123456.79, f32::MAX, f32::MIN_POSITIVE, 0.0] {
            let v = DataType::Real.decode(f.to_bits());
            assert_eq!(v.to_string(), f.to_string());
            assert_eq!(DataType::Real.encode(&v), f.to_bits(), "{f} round-trips");
        }
        assert_eq!(DataType::Real.decode(3.14f32.to_bits()).to_string(), "3.14");
        assert_eq!(serde_json::to_string(&DataType::Real.decode(3.14f32.to_bits())).unwrap(), "3.14");
    }

    #[test]
    fn decode_sign_extends_only_signed_types() {
        assert_eq!(DataType::Word.decode(0xFFFF), Value::Int(65535));
        assert_eq!(DataType::Int.decode(0xFFFF), Value::Int(-1));
        assert_eq!(DataType::SInt.decode(0x80), Value::Int(-128));
        assert_eq!(DataType::DInt.decode(0xFFFF_FFFE), Value::Int(-2));
        assert_eq!(DataType::DWord.decode(0xFFFF_FFFE), Value::Int(4294967294));
    }

    #[test]
    fn encode_roundtrips_every_type() {
        for t in DataType::ALL {
            let (lo, hi) = t.int_range();
            if t == DataType::Real {
                let v = Value::Real(1.5);
                assert_eq!(t.decode(t.encode(&v)), v);
                continue;
            }
            for v in [lo, hi, (lo + hi) / 2] {
                let val = if t == DataType::Bool { Value::Bool(v != 0) } else { Value::Int(v) };
                assert_eq!(t.decode(t.encode(&val)), val, "{t} {v}");
            }
        }
    }

    #[test]
    fn names_parse_back() {
        for t in DataType::ALL {
            assert_eq!(DataType::from_name(t.name()), Some(t));
        }
        assert_eq!(DataType::from_name("u16"), Some(DataType::Word));
        assert_eq!(DataType::from_name("i32"), Some(DataType::DInt));
        assert_eq!(DataType::from_name("nope"), None);
    }
}
