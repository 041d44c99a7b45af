//! The PLC-side helper ("agent") that gives plcsh SM registers and PLC instructions on a
//! real K2 over Modbus: its mailbox protocol, shared by the simulator and the wire driver.

pub mod check;
pub mod client;
pub mod forms;
pub mod il;
pub mod protocol;
