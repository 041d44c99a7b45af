#![no_main]
//! `cargo +nightly fuzz run modbus_tcp`: see `plcsh::fuzzing::modbus_tcp`.
use libfuzzer_sys::fuzz_target;

fuzz_target!(|data: &[u8]| plcsh::fuzzing::modbus_tcp(data));
