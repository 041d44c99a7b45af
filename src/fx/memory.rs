//! The simulated FX PLC's device memory: one image that both simulated ports (programming
//! port and computer link) read and write, sized from the model table. Devices the model
//! does not have are refused here, so each port answers NAK for them as a real PLC does.
//!
//! The image belongs to a CPU (its state [`super::cpu`], its scans [`super::plc`]): the
//! special devices it drives (M8000–M8003, the clock relays M8011–M8014, the scan times
//! D8010–D8012) are computed from its state and the image's time, not stored, so a write
//! cannot change them; D8000 (watchdog) starts at 200 ms. Every port locks the image and brings it to the present ([`Memory::advance`])
//! before answering.

use super::cpu::Cpu;
use super::model::{fx1s_counter, Model};
use super::operand::{Area, CN32_FIRST, SPECIAL, SPECIAL_COUNT};
use super::port::{self, Region, Table};
use crate::core::Clock;
use std::time::Duration;

/// The device memory of one simulated PLC.
#[derive(Clone, Debug)]
pub struct Memory {
    pub model: &'static Model,
    pub(super) bits: [Vec<bool>; 8],
    pub(super) tn: Vec<u16>,
    pub(super) cn: Vec<u32>,
    pub(super) d: Vec<u16>,
    pub(super) regions: Vec<Region>,
    /// The extended (E-command) table's regions.
    pub(super) ext_regions: Vec<Region>,
    /// Device writes made through either port (for tests and `devices`).
    pub writes: u64,
    /// The CPU that scans this image.
    pub cpu: Cpu,
    /// The virtual time the image shows (a scan's start while it runs).
    pub(super) at: Duration,
    /// Faults injected through the control channel: a silent line, stuck X inputs
    /// ([`super::control`]).
    pub faults: crate::core::sim_faults::Faults,
}

fn bit_slot(area: Area) -> Option<usize> {
    Some(match area {
        Area::X => 0,
        Area::Y => 1,
        Area::M => 2,
        Area::S => 3,
        Area::TS => 4,
        Area::TC => 5,
        Area::CS => 6,
        Area::CC => 7,
        _ => return None,
    })
}

impl Memory {
    /// A PLC in RUN on a stepped clock that nothing steps (tests of the image alone).
    pub fn new(model: &'static Model) -> Memory {
        Memory::with_clock(model, Clock::stepped())
    }

    /// A PLC in RUN from `clock`'s present time.
    pub fn with_clock(model: &'static Model, clock: Clock) -> Memory {
        let special = (SPECIAL + SPECIAL_COUNT) as usize;
        let bits = [
            vec![false; model.x as usize],
            vec![false; model.y as usize],
            vec![false; special],
            vec![false; model.s as usize],
            vec![false; model.t as usize],
            vec![false; model.t as usize],
            vec![false; model.c as usize],
            vec![false; model.c as usize],
        ];
        let mut m = Memory {
            model,
            bits,
            tn: vec![0; model.t as usize],
            cn: vec![0; model.c as usize],
            d: vec![0; special],
            regions: port::regions(Table::Classic),
            ext_regions: port::regions(Table::Extended),
            writes: 0,
            faults: Default::default(),
            at: clock.now(),
            cpu: Cpu::new(clock, model),
        };
        m.d[SPECIAL as usize] = 200; // D8000 watchdog, ms
        m
    }

    /// The virtual time the image shows.
    pub fn time(&self) -> Duration {
        self.at
    }

    /// Whether the model has device `index` of `area`.
    pub fn exists(&self, area: Area, index: u16) -> bool {
        let m = self.model;
        let special = area.has_special() && (SPECIAL..SPECIAL + SPECIAL_COUNT).contains(&index);
        let n = match area {
            Area::X => m.x,
            Area::Y => m.y,
            Area::M => m.m,
            Area::S => m.s,
            Area::TS | Area::TC | Area::TN => m.t,
            Area::CS | Area::CC | Area::CN => {
                if m.name == "FX1S" && !fx1s_counter(index) {
                    return false;
                }
                m.c
            }
            Area::D => m.d,
        };
        special || index < n
    }

    /// The outside world switches input X`index` (the control channel's `input`): stored as
    /// a client's write is, without counting as one.
    pub fn set_input(&mut self, index: u16, on: bool) {
        if let Some(b) = self.bits[0].get_mut(index as usize) {
            *b = on;
        }
    }

    pub fn bit(&self, area: Area, index: u16) -> Option<bool> {
        if !self.exists(area, index) {
            return None;
        }
        if area == Area::X {
            if let Some((_, on)) = self.faults.stuck(self.at).find(|(i, _)| *i == index) {
                return Some(on);
            }
        }
        if area == Area::M {
            if let Some(b) = self.cpu.system_bit(index, self.at) {
                return Some(b);
            }
        }
        self.bits[bit_slot(area)?].get(index as usize).copied()
    }

    /// A client's (or program's) write of a bit; one the CPU drives is accepted and ignored,
    /// as the PLC rewrites it every scan.
    pub fn set_bit(&mut self, area: Area, index: u16, v: bool) -> Option<()> {
        if !self.exists(area, index) {
            return None;
        }
        self.writes += 1;
        if area == Area::M && self.cpu.system_bit(index, self.at).is_some() {
            return Some(());
        }
        self.set_plain_bit(area, index, v)
    }

    /// Stores a bit (the CPU's own writes: coils, contacts, outputs off in STOP).
    pub(super) fn set_plain_bit(&mut self, area: Area, index: u16, v: bool) -> Option<()> {
        *self.bits[bit_slot(area)?].get_mut(index as usize)? = v;
        Some(())
    }

    /// A word device's value (CN200+ are 32-bit).
    pub fn word(&self, area: Area, index: u16) -> Option<u32> {
        if !self.exists(area, index) {
            return None;
        }
        if area == Area::D {
            if let Some(v) = self.cpu.system_word(index) {
                return Some(v as u32);
            }
        }
        match area {
            Area::D => self.d.get(index as usize).map(|v| *v as u32),
            Area::TN => self.tn.get(index as usize).map(|v| *v as u32),
            Area::CN if index >= CN32_FIRST => self.cn.get(index as usize).copied(),
            Area::CN => self.cn.get(index as usize).map(|v| *v & 0xFFFF),
            _ => None,
        }
    }

    /// A client's (or program's) write of a word; D8010–D8012 are accepted and ignored.
    pub fn set_word(&mut self, area: Area, index: u16, v: u32) -> Option<()> {
        if !self.exists(area, index) {
            return None;
        }
        self.writes += 1;
        if area == Area::D && self.cpu.system_word(index).is_some() {
            return Some(());
        }
        self.set_plain_word(area, index, v)
    }

    /// Stores a word (the CPU's own writes: timer and counter values).
    pub(super) fn set_plain_word(&mut self, area: Area, index: u16, v: u32) -> Option<()> {
        let i = index as usize;
        match area {
            Area::D => *self.d.get_mut(i)? = v as u16,
            Area::TN => *self.tn.get_mut(i)? = v as u16,
            Area::CN if index >= CN32_FIRST => *self.cn.get_mut(i)? = v,
            Area::CN => *self.cn.get_mut(i)? = v & 0xFFFF,
            _ => return None,
        }
        Some(())
    }

    fn regions_of(&self, table: Table) -> &[Region] {
        match table {
            Table::Classic => &self.regions,
            Table::Extended => &self.ext_regions,
        }
    }

    /// One byte of the programming port's classic address space, or `None` (NAK).
    pub fn port_byte(&self, addr: u16) -> Option<u8> {
        self.port_byte_in(Table::Classic, addr)
    }

    /// One byte of `table`'s address space, or `None` (NAK).
    pub fn port_byte_in(&self, table: Table, addr: u16) -> Option<u8> {
        let r = *port::region_of(self.regions_of(table), addr)?;
        let off = addr - r.start;
        if r.unit == 0 {
            let first = r.first + 8 * off;
            let mut b = 0u8;
            for i in 0..8 {
                // Bits past the model's end read as 0 within a byte that has some.
                if self.bit(r.area, first + i).unwrap_or(false) {
                    b |= 1 << i;
                }
            }
            return (0..8).any(|i| self.exists(r.area, first + i)).then_some(b);
        }
        let index = r.first + off / r.unit;
        let v = self.word(r.area, index)?;
        Some((v >> (8 * (off % r.unit))) as u8)
    }

    /// Writes one byte of the programming port's classic address space; `None` (NAK) when no
    /// device is there.
    pub fn set_port_byte(&mut self, addr: u16, b: u8) -> Option<()> {
        self.set_port_byte_in(Table::Classic, addr, b)
    }

    /// Writes one byte of `table`'s address space; `None` (NAK) when no device is there.
    pub fn set_port_byte_in(&mut self, table: Table, addr: u16, b: u8) -> Option<()> {
        let r = *port::region_of(self.regions_of(table), addr)?;
        let off = addr - r.start;
        if r.unit == 0 {
            let first = r.first + 8 * off;
            if !(0..8).any(|i| self.exists(r.area, first + i)) {
                return None;
            }
            for i in 0..8 {
                if self.exists(r.area, first + i) {
                    self.set_bit(r.area, first + i, b >> i & 1 != 0)?;
                }
            }
            return Some(());
        }
        let index = r.first + off / r.unit;
        let shift = 8 * (off % r.unit) as u32;
        let old = self.word(r.area, index)?;
        let v = (old & !(0xFF << shift)) | (b as u32) << shift;
        self.set_word(r.area, index, v)
    }

    /// Whether every byte in `addr … addr+len` is there (a read or write of them is answered).
    pub fn port_range_ok(&self, addr: u16, len: usize) -> bool {
        self.port_range_ok_in(Table::Classic, addr, len)
    }

    /// Whether every byte in `addr … addr+len` of `table` is there.
    pub fn port_range_ok_in(&self, table: Table, addr: u16, len: usize) -> bool {
        (0..len).all(|i| addr.checked_add(i as u16).is_some_and(|a| self.port_byte_in(table, a).is_some()))
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn port_bytes_follow_the_device_table() {
        let mut m = Memory::new(Model::find("FX2N").unwrap());
        m.set_word(Area::D, 123, 0x1234).unwrap();
        assert_eq!(m.port_byte(0x10F6), Some(0x34));
        assert_eq!(m.port_byte(0x10F7), Some(0x12));
        m.set_port_byte(0x10F8, 0xCD).unwrap();
        m.set_port_byte(0x10F9, 0xAB).unwrap();
        assert_eq!(m.word(Area::D, 124), Some(0xABCD));
        m.set_bit(Area::Y, 0o21, true).unwrap();
        assert_eq!(m.port_byte(0x00A2), Some(0b10));
        assert_eq!(m.port_byte(0x01E0), Some(1), "M8000 is on in RUN");
        assert_eq!(m.port_byte(0x0E00), Some(200), "D8000 watchdog");
        assert_eq!(m.port_byte(0x0090), None, "no device there");
        m.set_word(Area::CN, 200, 0x0102_0304).unwrap();
        assert_eq!(m.port_byte(0x0C03), Some(0x01));
    }

    #[test]
    fn model_ranges_decide_what_exists() {
        let m = Memory::new(Model::find("FX1S").unwrap());
        assert!(m.exists(Area::D, 255) && !m.exists(Area::D, 256));
        assert!(m.exists(Area::D, 8000));
        assert!(m.exists(Area::X, 0o17) && !m.exists(Area::X, 0o20));
        assert!(m.exists(Area::CN, 31) && !m.exists(Area::CN, 32) && m.exists(Area::CN, 235));
        assert_eq!(m.port_byte(0x1200), None, "D256 is past an FX1S");
    }
}
