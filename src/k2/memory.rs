//! The K2 memory image: every area sized per model, S7 byte order (big-endian: `VW100`'s
//! high byte is `VB100`, `VD100` spans VB100…VB103 most significant first; k2.md §2).
//!
//! Pure data: reads and writes raw bit patterns of already bounds-checked operands. The
//! simulator layers behaviour (system bits, PTO, HSC) on top of it.

use super::catalog::Model;
use super::operand::{Area, K2Operand, Width};
use super::space::K2Space;
use crate::core::DataType;

/// One K2's memory.
#[derive(Clone, Debug)]
pub struct Memory {
    pub i: Vec<u8>,
    pub q: Vec<u8>,
    pub m: Vec<u8>,
    pub v: Vec<u8>,
    pub sm: Vec<u8>,
    pub ai: Vec<u8>,
    pub aq: Vec<u8>,
    /// Timer and counter current values (INT).
    pub t: Vec<i16>,
    pub c: Vec<i16>,
    /// Timer and counter bits (0/1), set by the program's timer and counter instructions.
    pub tq: Vec<u8>,
    pub cq: Vec<u8>,
}

impl Memory {
    pub fn new(model: &'static Model) -> Memory {
        let s = K2Space::new(model);
        let z = |a: Area| vec![0u8; s.area_len(a) as usize];
        Memory {
            i: z(Area::I),
            q: z(Area::Q),
            m: z(Area::M),
            v: z(Area::V),
            sm: z(Area::SM),
            ai: z(Area::AI),
            aq: z(Area::AQ),
            t: vec![0; s.area_len(Area::T) as usize],
            c: vec![0; s.area_len(Area::C) as usize],
            tq: vec![0; s.area_len(Area::T) as usize],
            cq: vec![0; s.area_len(Area::C) as usize],
        }
    }

    /// The byte vector of a byte-addressed area.
    pub fn area(&self, a: Area) -> &[u8] {
        match a {
            Area::I => &self.i,
            Area::Q => &self.q,
            Area::M => &self.m,
            Area::V => &self.v,
            Area::SM => &self.sm,
            Area::AI => &self.ai,
            Area::AQ => &self.aq,
            Area::T | Area::C => &[],
        }
    }

    pub fn area_mut(&mut self, a: Area) -> &mut [u8] {
        match a {
            Area::I => &mut self.i,
            Area::Q => &mut self.q,
            Area::M => &mut self.m,
            Area::V => &mut self.v,
            Area::SM => &mut self.sm,
            Area::AI => &mut self.ai,
            Area::AQ => &mut self.aq,
            Area::T | Area::C => &mut [],
        }
    }

    /// Reads the raw pattern of an operand (bounds already checked).
    pub fn read(&self, op: &K2Operand) -> u32 {
        let b = op.byte as usize;
        match op.width {
            Width::Element if op.view == DataType::Bool => {
                (if op.area == Area::T { self.tq[b] } else { self.cq[b] }) as u32
            }
            Width::Element => (if op.area == Area::T { self.t[b] } else { self.c[b] }) as u16 as u32,
            Width::Bit(bit) => ((self.area(op.area)[b] >> bit) & 1) as u32,
            Width::Byte => self.area(op.area)[b] as u32,
            Width::Word => u16::from_be_bytes([self.area(op.area)[b], self.area(op.area)[b + 1]]) as u32,
            Width::DWord => {
                let a = self.area(op.area);
                u32::from_be_bytes([a[b], a[b + 1], a[b + 2], a[b + 3]])
            }
            Width::Group { n, bit } => {
                // Bit k of the group is bit (bit + k) counted from byte b's bit 0 upward.
                let a = self.area(op.area);
                let mut v = 0u32;
                for k in 0..(4 * n as u32) {
                    let abs = bit as u32 + k;
                    let byte = a[b + (abs / 8) as usize];
                    v |= (((byte >> (abs % 8)) & 1) as u32) << k;
                }
                v
            }
        }
    }

    /// [`Self::read`] of the operand packed in `key` ([`K2Operand::key`]): bits, bytes,
    /// words and double words of the byte areas straight from the key (the simulator's
    /// read path); everything else through [`K2Operand::from_key`].
    #[inline]
    pub fn read_key(&self, key: u64) -> u32 {
        // Where SM sits in `Area::ALL` (the key's area field), tested first.
        const SM_INDEX: usize = 4;
        const _: () = assert!(matches!(Area::ALL[SM_INDEX], Area::SM));
        let b = key as u32 as usize;
        // Plain conditional branches (SM first: what pollers read), not jump tables.
        let area = ((key >> 32) & 0xF) as usize;
        let a: &[u8] = if area == SM_INDEX {
            &self.sm
        } else {
            match Area::ALL.get(area) {
                Some(Area::T | Area::C) | None => return self.read(&K2Operand::from_key(key)),
                Some(&area) => self.area(area),
            }
        };
        let width = (key >> 36) & 0xF;
        if width == 3 {
            let w = &a[b..b + 4];
            u32::from_be_bytes([w[0], w[1], w[2], w[3]])
        } else if width == 1 {
            a[b] as u32
        } else if width == 2 {
            u16::from_be_bytes([a[b], a[b + 1]]) as u32
        } else if width == 0 {
            ((a[b] >> ((key >> 40) & 0xF) as u8) & 1) as u32
        } else {
            self.read(&K2Operand::from_key(key))
        }
    }

    /// Writes the raw pattern of an operand (bounds already checked).
    pub fn write(&mut self, op: &K2Operand, raw: u32) {
        let b = op.byte as usize;
        match op.width {
            Width::Element if op.view == DataType::Bool => {
                let slot = if op.area == Area::T { &mut self.tq[b] } else { &mut self.cq[b] };
                *slot = (raw & 1) as u8;
            }
            Width::Element => {
                let slot = if op.area == Area::T { &mut self.t[b] } else { &mut self.c[b] };
                *slot = raw as u16 as i16;
            }
            Width::Bit(bit) => {
                let a = &mut self.area_mut(op.area)[b];
                if raw & 1 != 0 {
                    *a |= 1 << bit;
                } else {
                    *a &= !(1 << bit);
                }
            }
            Width::Byte => self.area_mut(op.area)[b] = raw as u8,
            Width::Word => self.area_mut(op.area)[b..b + 2].copy_from_slice(&(raw as u16).to_be_bytes()),
            Width::DWord => self.area_mut(op.area)[b..b + 4].copy_from_slice(&raw.to_be_bytes()),
            Width::Group { n, bit } => {
                let a = self.area_mut(op.area);
                for k in 0..(4 * n as u32) {
                    let abs = bit as u32 + k;
                    let byte = &mut a[b + (abs / 8) as usize];
                    let m = 1u8 << (abs % 8);
                    if (raw >> k) & 1 != 0 {
                        *byte |= m;
                    } else {
                        *byte &= !m;
                    }
                }
            }
        }
    }

    // Typed helpers for the simulator's own registers (addresses from sm_map).
    pub fn sm_byte(&self, byte: u32) -> u8 {
        self.sm[byte as usize]
    }
    pub fn set_sm_byte(&mut self, byte: u32, v: u8) {
        self.sm[byte as usize] = v;
    }
    pub fn sm_bit(&self, byte: u32, bit: u8) -> bool {
        self.sm[byte as usize] >> bit & 1 != 0
    }
    pub fn set_sm_bit(&mut self, byte: u32, bit: u8, on: bool) {
        let b = &mut self.sm[byte as usize];
        if on {
            *b |= 1 << bit
        } else {
            *b &= !(1 << bit)
        }
    }
    pub fn sm_word(&self, byte: u32) -> u16 {
        let b = byte as usize;
        u16::from_be_bytes([self.sm[b], self.sm[b + 1]])
    }
    pub fn set_sm_word(&mut self, byte: u32, v: u16) {
        let b = byte as usize;
        self.sm[b..b + 2].copy_from_slice(&v.to_be_bytes())
    }
    pub fn sm_dword(&self, byte: u32) -> u32 {
        let b = byte as usize;
        let w: [u8; 4] = self.sm[b..b + 4].try_into().expect("four bytes");
        u32::from_be_bytes(w)
    }
    pub fn set_sm_dword(&mut self, byte: u32, v: u32) {
        let b = byte as usize;
        self.sm[b..b + 4].copy_from_slice(&v.to_be_bytes())
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::k2::catalog;
    use crate::k2::operand::parse_one;

    fn mem() -> Memory {
        Memory::new(catalog::find("K205-16DT").unwrap())
    }

    #[test]
    fn s7_byte_order() {
        let mut m = mem();
        m.write(&parse_one("VW100").unwrap(), 0x1234);
        assert_eq!(m.read(&parse_one("VB100").unwrap()), 0x12, "VW100's high byte is VB100");
        assert_eq!(m.read(&parse_one("VB101").unwrap()), 0x34);
        m.write(&parse_one("VD200").unwrap(), 0xAABBCCDD);
        assert_eq!(m.read(&parse_one("VW200").unwrap()), 0xAABB);
        assert_eq!(m.read(&parse_one("VW202").unwrap()), 0xCCDD);
        assert_eq!(m.read(&parse_one("V203.0").unwrap()), 1);
    }

    #[test]
    fn read_key_reads_what_read_reads() {
        let mut m = mem();
        for (i, b) in m.v.iter_mut().enumerate().take(64) {
            *b = (i as u8).wrapping_mul(37) ^ 0x5A;
        }
        m.sm[30] = 0xA5;
        m.t[3] = -2;
        for text in
            ["VB7", "VW8", "VD9", "V10.3", "V11.7", "VD60", "SMB30", "SM30.0", "SM30.1", "K4V0", "T3", "VD10/REAL"]
        {
            let op = parse_one(text).unwrap();
            assert_eq!(m.read_key(op.key()), m.read(&op), "{text}");
        }
    }

    #[test]
    fn bits_leave_neighbours_alone() {
        let mut m = mem();
        m.write(&parse_one("MB10").unwrap(), 0b1010_0000);
        m.write(&parse_one("M10.3").unwrap(), 1);
        assert_eq!(m.read(&parse_one("MB10").unwrap()), 0b1010_1000);
        m.write(&parse_one("M10.7").unwrap(), 0);
        assert_eq!(m.read(&parse_one("MB10").unwrap()), 0b0010_1000);
    }

    #[test]
    fn bit_groups_read_low_bits_first() {
        let mut m = mem();
        m.write(&parse_one("K4M0").unwrap(), 0xBEEF);
        assert_eq!(m.read(&parse_one("MB0").unwrap()), 0xEF, "K4M0 = M0.0…M1.7, M0.0 least significant");
        assert_eq!(m.read(&parse_one("MB1").unwrap()), 0xBE);
        assert_eq!(m.read(&parse_one("K1M0").unwrap()), 0xF);
        assert_eq!(m.read(&parse_one("K1M0.4").unwrap()), 0xE);
        m.write(&parse_one("K1M0.2").unwrap(), 0);
        assert_eq!(m.read(&parse_one("MB0").unwrap()), 0xC3);
    }

    #[test]
    fn timer_and_counter_bits_are_the_bool_view() {
        let mut m = mem();
        m.tq[37] = 1;
        assert_eq!(m.read(&parse_one("T37/BOOL").unwrap()), 1);
        assert_eq!(parse_one("T37/BOOL").unwrap().canonical(), "T37/BOOL");
        m.write(&parse_one("C5/BOOL").unwrap(), 1);
        assert_eq!((m.cq[5], m.c[5]), (1, 0), "the bit, not the value");
        assert!(parse_one("VW0/BOOL").is_err());
    }

    #[test]
    fn timers_hold_signed_values() {
        let mut m = mem();
        m.write(&parse_one("T3").unwrap(), 0xFFFF);
        assert_eq!(m.t[3], -1);
    }
}
