//! UMPK8 / UMPK16 teaching PLCs, everything in one room: the model table (`model`), the
//! terminal-protocol codec (`codec`), Intel HEX records (`hex`), the operand space
//! (`space`), the driver (`driver`) and the simulator (`sim`).
//! Manual: `../shared/seeds/003_…` (Russian); digest `../shared/spec/umpk.md`.

pub mod codec;
pub mod driver;
pub mod hex;
pub mod model;
pub mod sim;
pub mod space;
