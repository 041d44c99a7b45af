//! Family-neutral building blocks: values, literals, operands, the device trait, errors
//! and the virtual clock. Nothing here knows a PLC model or a wire protocol.

pub mod budget;
pub mod civil;
pub mod clock;
pub mod device;
pub mod durable;
pub mod encoding;
pub mod error;
pub mod exit;
pub mod float_serde;
pub mod fspath;
pub mod link;
pub mod literal;
pub mod msg;
pub mod operand;
pub mod platform;
pub mod signal;
pub mod sim_faults;
#[cfg(test)]
pub mod test_rng;
pub mod text;
pub mod trace;
pub mod url;
pub mod value;
pub mod wiring;

pub use clock::Clock;
pub use device::{Device, DeviceInfo};
pub use error::{Error, ErrorKind, Result};
pub use operand::{Candidate, Operand, OperandSpace, Span};
pub use value::{DataType, Value};
