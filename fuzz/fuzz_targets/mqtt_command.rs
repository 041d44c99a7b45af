#![no_main]
//! `cargo +nightly fuzz run mqtt_command`: see `plcsh::fuzzing::mqtt_command`.
use libfuzzer_sys::fuzz_target;

fuzz_target!(|data: &[u8]| plcsh::fuzzing::mqtt_command(data));
