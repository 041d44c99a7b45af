#![no_main]
//! `cargo +nightly fuzz run modbus_client`: see `plcsh::fuzzing::modbus_client`.
use libfuzzer_sys::fuzz_target;

fuzz_target!(|data: &[u8]| plcsh::fuzzing::modbus_client(data));
