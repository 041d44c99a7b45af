#![no_main]
//! `cargo +nightly fuzz run modbus_rtu`: see `plcsh::fuzzing::modbus_rtu`.
use libfuzzer_sys::fuzz_target;

fuzz_target!(|data: &[u8]| plcsh::fuzzing::modbus_rtu(data));
