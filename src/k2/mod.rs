//! Everything about the Kinco K2 PLC family in one room: the model catalogue, the operand
//! grammar, SM register tables, the memory image and the simulator.

pub mod catalog;
pub mod coalesce;
pub mod driver;
pub mod memory;
pub mod modbus_map;
pub mod operand;
pub mod sim;
pub mod sm_map;
pub mod space;

use crate::core::Device;

/// K2-specific capabilities a device offers beyond reading and writing operands:
/// typed helpers (PTO, HSC, RTC, E2PROM) are built on these.
pub trait K2Ops {
    fn model(&self) -> &'static catalog::Model;
    /// The simulator behind this device, when it is one (simulation controls).
    fn as_sim(&mut self) -> Option<&mut sim::K2Sim> {
        None
    }
}

/// Opens a K2 device from a URL the session recognised as K2 (`sim:MODEL`).
pub fn open_sim(model: &str, clock: crate::core::Clock) -> crate::core::Result<Box<dyn Device>> {
    Ok(Box::new(sim::open(model, clock)?))
}

/// Opens a real K2 (or a served simulator) from `tcp://`, `rtu:` or `rtu+tcp://` URLs.
pub fn open_wire(url: &crate::core::url::DeviceUrl) -> crate::core::Result<Box<dyn Device>> {
    Ok(Box::new(driver::K2Wire::open(url)?))
}
