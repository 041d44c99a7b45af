//! The simulated FX PLC's memory as the scan engine sees it: [`FxMachine`] reads and writes
//! engine locations as FX devices of the PLC's image ([`Memory`]) and carries out the FX
//! family instructions (`OUT T`/`OUT C`/`RST`) by the CPU's timer and counter rules
//! ([`super::plc`]); [`Loaded::scan`] runs one scan of a loaded program on it. Apart from the
//! program front end ([`super::program`]), which compiles without any PLC, so that the
//! program can sit in the CPU's state below the image.

use super::memory::Memory;
use super::operand::{self, Area};
use super::program::{decode, id, Loaded};
use crate::core::DataType;
use crate::engine::{self, Fault, Loc, Machine, Opd, Width};

/// The PLC's memory during a scan.
pub struct FxMachine<'m> {
    pub mem: &'m mut Memory,
    pub now_ns: u64,
}

impl FxMachine<'_> {
    fn bit(&self, area: Area, n: u16) -> bool {
        self.mem.bit(area, n).unwrap_or(false)
    }

    /// A program's write: a special device the CPU drives is left alone.
    fn put_bit(&mut self, area: Area, n: u16, v: bool) {
        if !operand::system_driven(area, n) && self.mem.exists(area, n) {
            self.mem.set_plain_bit(area, n, v);
        }
    }
}

impl Machine for FxMachine<'_> {
    fn get(&self, l: Loc) -> u32 {
        let Some((area, n, groups)) = decode(l) else { return 0 };
        if groups > 0 {
            return (0..4 * groups as u16).fold(0u32, |a, i| a | (self.bit(area, n.wrapping_add(i)) as u32) << i);
        }
        match l.width {
            Width::Bit(_) => self.bit(area, n) as u32,
            Width::DWord if area == Area::D => {
                let lo = self.mem.word(area, n).unwrap_or(0);
                let hi = self.mem.word(area, n.wrapping_add(1)).unwrap_or(0);
                lo & 0xFFFF | hi << 16
            }
            _ => self.mem.word(area, n).unwrap_or(0),
        }
    }

    fn set(&mut self, l: Loc, v: u32) {
        let Some((area, n, groups)) = decode(l) else { return };
        if groups > 0 {
            for i in 0..4 * groups as u16 {
                self.put_bit(area, n.wrapping_add(i), v >> i & 1 != 0);
            }
            return;
        }
        match l.width {
            Width::Bit(_) => self.put_bit(area, n, v & 1 != 0),
            Width::DWord if area == Area::D => {
                for (k, w) in [(0u16, v & 0xFFFF), (1, v >> 16)] {
                    if !operand::system_driven(area, n.wrapping_add(k)) {
                        self.mem.set_plain_word(area, n.wrapping_add(k), w);
                    }
                }
            }
            _ => {
                if !operand::system_driven(area, n) {
                    self.mem.set_plain_word(area, n, v);
                }
            }
        }
    }

    fn deref(&self, _ptr: u32, _w: Width) -> Option<Loc> {
        None
    }

    fn special(&mut self, id: u16, inst: u32, args: &[Opd], types: &[DataType]) -> std::result::Result<bool, Fault> {
        self.element(id, inst, args, types, true)
    }

    fn special_off(
        &mut self,
        id: u16,
        inst: u32,
        args: &[Opd],
        types: &[DataType],
    ) -> std::result::Result<bool, Fault> {
        self.element(id, inst, args, types, false)
    }
}

impl FxMachine<'_> {
    /// Timers, counters and RST: act with the CR on or off and leave it as it was.
    fn element(
        &mut self,
        id: u16,
        _inst: u32,
        args: &[Opd],
        types: &[DataType],
        input: bool,
    ) -> std::result::Result<bool, Fault> {
        let target = match args.first() {
            Some(Opd::Loc(l)) => decode(*l),
            _ => None,
        };
        let Some((area, n, _)) = target else { return Ok(input) };
        let preset = |m: &Self| -> i64 {
            let (Some(o), Some(t)) = (args.get(1), types.get(1)) else { return 0 };
            let raw = engine::read(m, o, *t).unwrap_or(0);
            if t.bits() == 32 {
                raw as i32 as i64
            } else {
                raw as u16 as i16 as i64
            }
        };
        match id {
            id::TIMER => {
                let k = preset(self) as i32;
                self.mem.timer_coil(n, input, k, self.now_ns);
            }
            id::COUNTER | id::COUNTER32 => {
                let k = preset(self);
                self.mem.counter_coil(n, input, k);
            }
            _ if input => match area {
                Area::TS | Area::TN => self.mem.reset_element(true, n),
                Area::CS | Area::CN => self.mem.reset_element(false, n),
                _ => {
                    let (Some(o), Some(t)) = (args.first(), types.first()) else { return Ok(input) };
                    engine::write(self, o, *t, 0)?;
                }
            },
            _ => {}
        }
        Ok(input)
    }
}

impl Loaded {
    /// One scan at `now_ns`: the program's time (ns) and a fault that stops the PLC.
    pub fn scan(&mut self, mem: &mut Memory, now_ns: u64) -> (u64, Option<String>) {
        let mut m = FxMachine { mem, now_ns };
        let out = self.cpu.scan(&self.prog, &mut m, now_ns, u64::MAX, None);
        let fault = match out.exit {
            engine::exec::Exit::Fault(f) => Some(format!("line {}: {} ({})", f.line, f.message, f.instruction)),
            _ => None,
        };
        (out.cost_ns, fault)
    }
}
