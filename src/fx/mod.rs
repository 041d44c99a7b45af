//! FX-protocol PLCs (Mitsubishi FX and compatible clones), everything in one room: the device
//! table and operand grammar (`operand`), the model ranges (`model`), the operand space
//! (`space`), the programming-port codec (`port`), the computer-link codec (`link`), the
//! driver for both (`driver`), and the simulator whose two ports share one memory (`memory`,
//! `sim`). Spec: `../shared/spec/fx-and-masterk.md` (seed 004).
//!
//! The byte lines (serial port, device servers, served ptys and TCP ports, the shared-line
//! registry) are the family-neutral transport layer's, [`crate::core::link`].
//!
//! No family-specific shell commands or Lua methods: everything an FX user does goes through
//! the generic `get`/`set`/`read`/`watch`/`trace` and Lua field access, so FX needs no
//! `Device::family_ops` door (and the write guard has none to police).

pub mod driver;
pub mod link;
pub mod memory;
pub mod model;
pub mod operand;
pub mod plc;
pub mod port;
pub mod program;
pub mod sim;
pub mod space;
