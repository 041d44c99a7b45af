//! Kinco servo drives: their 10-byte RS232 protocol over CANopen-style objects.
//! (The frame codec, object dictionary, units, driver and simulator live here.)

pub mod frame;
pub mod objects;
pub mod units;

/// Servo-specific capabilities (DS402 helpers are built on these).
pub trait ServoOps {}
