//! FX-protocol PLCs (Mitsubishi FX and compatible clones), everything in one room: the device
//! table and operand grammar (`operand`), the model ranges (`model`), the operand space
//! (`space`), the programming-port codec (`port`), the computer-link codec (`link`), the
//! driver for both (`driver`), and the simulator whose two ports share one memory (`memory`,
//! `sim`). Spec: `../shared/spec/fx-and-masterk.md` (seed 004).

pub mod driver;
pub mod link;
pub mod memory;
pub mod model;
pub mod operand;
pub mod port;
pub mod sim;
pub mod space;
