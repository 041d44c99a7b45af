#![no_main]
//! `cargo +nightly fuzz run servo_units`: see `plcsh::fuzzing::servo_units`.
use libfuzzer_sys::fuzz_target;

fuzz_target!(|data: &[u8]| plcsh::fuzzing::servo_units(data));
