//! A serial line's character format and speed ([`LineSettings`]: `9600 8N1`), and the frame
//! times line-aware timeouts are computed from. A port is opened with them ([`super::serial`]),
//! an RFC 2217 server is told them ([`super::rfc2217`]), and a shared line refuses a second
//! open with other ones ([`super::line`]); they sit below all three so none names another.

use std::fmt;
use std::time::Duration;

/// Parity of a character.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Parity {
    None,
    Even,
    Odd,
}

impl Parity {
    /// `none`/`n`, `even`/`e`, `odd`/`o` (any case).
    pub fn parse(text: &str) -> Option<Parity> {
        match text.to_ascii_lowercase().as_str() {
            "none" | "n" => Some(Parity::None),
            "even" | "e" => Some(Parity::Even),
            "odd" | "o" => Some(Parity::Odd),
            _ => None,
        }
    }

    fn letter(self) -> char {
        match self {
            Parity::None => 'N',
            Parity::Even => 'E',
            Parity::Odd => 'O',
        }
    }
}

/// A line's character format and speed.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct LineSettings {
    pub baud: u32,
    /// 7 or 8.
    pub data_bits: u8,
    pub parity: Parity,
    /// 1 or 2.
    pub stop_bits: u8,
}

impl LineSettings {
    /// 8 data bits, no parity, one stop bit.
    pub fn n81(baud: u32) -> LineSettings {
        LineSettings { baud, data_bits: 8, parity: Parity::None, stop_bits: 1 }
    }

    /// Bits on the wire per character: start, data, parity, stop.
    pub fn char_bits(&self) -> u32 {
        1 + u32::from(self.data_bits) + u32::from(self.parity != Parity::None) + u32::from(self.stop_bits)
    }

    /// How long `chars` characters take on the wire (rounded up to a microsecond).
    pub fn time_of(&self, chars: usize) -> Duration {
        let bits = (chars as u64).saturating_mul(u64::from(self.char_bits()));
        Duration::from_micros(bits.saturating_mul(1_000_000).div_ceil(u64::from(self.baud.max(1))))
    }
}

impl fmt::Display for LineSettings {
    /// `9600 8N1`.
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        write!(f, "{} {}{}{}", self.baud, self.data_bits, self.parity.letter(), self.stop_bits)
    }
}
