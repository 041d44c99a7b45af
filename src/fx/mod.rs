//! FX-protocol PLCs (Mitsubishi FX and compatible clones), everything in one room: the device
//! table and operand grammar (`operand`), the model ranges (`model`), the timer and counter
//! numbering (`elements`), the operand space (`space`), the programming-port codec (`port`),
//! the computer-link codec (`link`), the driver for both (`driver`: the shared transaction,
//! the programming port, the computer link, the in-process simulator), and the simulator
//! whose two ports share one memory (`memory`, `sim`), with the CPU that makes it a PLC in
//! RUN (`cpu`: its state; `plc`: scans, special devices, timers and counters in virtual
//! time), the FX instruction lists it runs on the scan engine (`program`) and the PLC's
//! memory as the engine sees it during a scan (`machine`). Spec:
//! `../shared/spec/fx-and-masterk.md` (seed 004).
//!
//! The files depend on each other in one direction: `model`, `operand`, `elements` →
//! `port` → `link` → `space` → `program` → `cpu` → `memory` → `machine`, `plc`, `snapshot`,
//! `control` → `sim` → `driver`.
//!
//! The byte lines (serial port, device servers, served ptys and TCP ports, the shared-line
//! registry) are the family-neutral transport layer's, [`crate::core::link`].
//!
//! Reading and writing devices goes through the generic `get`/`set`/`read`/`watch`/`trace`
//! and Lua field access. Only the in-process simulator has operations of its own (`sim program
//! load`, `sim cpu run|stop`), reached through [`driver::ops`]; a real FX answers `None`
//! there, so there is nothing for the write guard to police beyond device writes.

pub mod control;
pub mod cpu;
pub mod driver;
pub mod elements;
pub mod link;
pub mod machine;
pub mod memory;
pub mod model;
pub mod operand;
pub mod plc;
pub mod port;
pub mod program;
pub mod sim;
pub mod snapshot;
pub mod space;
