//! Everything about the Kinco K2 PLC family in one room: the model catalogue, the operand
//! grammar, SM register tables, the memory image, the simulator and the typed helpers.

pub mod access;
pub mod agent;
pub mod catalog;
pub mod changes;
pub mod coalesce;
pub mod driver;
pub mod helpers;
pub mod instr;
pub mod memory;
pub mod modbus_map;
pub mod operand;
pub mod probe;
pub mod sim;
pub mod sm_map;
pub mod space;

use crate::core::{Device, Error, Result};
use crate::msg;
pub use access::{ops, simulator, K2Access};
pub use instr::{Event, EventKind, EventMatch, RtcTime};

/// The K2's special instructions (manual §3.3, §3.4, §2.2.9) and event access, as a device
/// offers them beyond reading and writing operands.
///
/// The trait is about instructions and their results, not about how they run: the
/// simulator executes them directly; a wire driver can execute the same calls through a
/// PLC-side helper program (a mailbox in V memory), because every method maps onto one
/// instruction (PLS, HDEF, HSC, PSTOP, SET_RTC, READ_RTC) or onto an event ring the helper
/// fills from ATCHed interrupt routines. Simulation-only controls (input signal sources,
/// retention settings) go through [`K2Ops::as_sim`] and [`simulator`].
///
/// Every method has a default that refuses, so a device that cannot run instructions yet
/// (the Modbus driver before its helper exists) implements only `model`.
pub trait K2Ops {
    fn model(&self) -> &'static catalog::Model;

    /// `PLS q`: loads the channel's SM configuration (control byte SMB67 …, cycle, width,
    /// count, profile table) as the update bits say and starts or stops the output.
    /// A refusal (invalid cycle or count, frequency above the channel's limit) sets the
    /// status byte's bit 4 and comes back as an error. The instruction methods return a
    /// one-line report of what the device did.
    fn pls(&mut self, channel: u8) -> Result<String> {
        let _ = channel;
        Err(not_here("PLS"))
    }
    /// `HDEF counter, mode` (§3.3.5 step 2).
    fn hdef(&mut self, counter: u8, mode: u8) -> Result<String> {
        let _ = (counter, mode);
        Err(not_here("HDEF"))
    }
    /// `HSC counter` (§3.3.5 step 4): applies the control byte's update bits and starts or
    /// stops counting.
    fn hsc(&mut self, counter: u8) -> Result<String> {
        let _ = counter;
        Err(not_here("HSC"))
    }
    /// `PSTOP` (§3.4.1): emergency stop of a pulse channel; latches SM201.7 ….
    fn pstop(&mut self, channel: u8) -> Result<String> {
        let _ = channel;
        Err(not_here("PSTOP"))
    }
    /// `READ_RTC`.
    fn read_rtc(&mut self) -> Result<RtcTime> {
        Err(not_here("READ_RTC"))
    }
    /// `SET_RTC`.
    fn set_rtc(&mut self, t: RtcTime) -> Result<()> {
        let _ = t;
        Err(not_here("SET_RTC"))
    }
    /// The interrupt events raised so far, oldest first; `clear` empties the log after
    /// reading it.
    fn events(&mut self, clear: bool) -> Result<Vec<Event>> {
        let _ = clear;
        Err(not_here(msg!("k2-what-event-access").text))
    }
    /// Removes and returns the oldest logged event that matches, if any (`wait event`).
    fn take_event(&mut self, m: &EventMatch) -> Result<Option<Event>> {
        let _ = m;
        Err(not_here(msg!("k2-what-event-access").text))
    }
    /// The E2PROM backup area as configured, first and last V byte (§2.2.8).
    fn backup_area(&self) -> (u32, u32) {
        (catalog::EEPROM_FIRST, catalog::EEPROM_LAST_DEFAULT)
    }
    /// The state of the PLC-side helper program this connection uses for SM registers and
    /// instructions (docs/agent.md).
    fn helper_status(&mut self) -> Result<String> {
        Err(not_here(msg!("k2-what-helper-status").text))
    }
    /// The simulator behind this device, when it is one (simulation controls).
    fn as_sim(&mut self) -> Option<&mut sim::K2Sim> {
        None
    }
}

fn not_here(what: impl Into<String>) -> Error {
    Error::unsupported(msg!("k2-not-here", what = what.into())).hint(msg!("k2-not-here-hint"))
}

/// Opens a K2 device from a URL the session recognised as K2 (`sim:MODEL`).
pub fn open_sim(model: &str, clock: crate::core::Clock) -> crate::core::Result<Box<dyn Device>> {
    Ok(Box::new(sim::open(model, clock)?))
}

/// Opens a real K2 (or a served simulator) from `tcp://`, `rtu:` or `rtu+tcp://` URLs.
pub fn open_wire(url: &crate::core::url::DeviceUrl) -> crate::core::Result<Box<dyn Device>> {
    Ok(Box::new(driver::K2Wire::open(url)?))
}
