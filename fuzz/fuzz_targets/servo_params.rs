#![no_main]
//! `cargo +nightly fuzz run servo_params`: see `plcsh::fuzzing::servo_params`.
use libfuzzer_sys::fuzz_target;

fuzz_target!(|data: &[u8]| plcsh::fuzzing::servo_params(data));
