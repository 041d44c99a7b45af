#![no_main]
//! `cargo +nightly fuzz run servo_frame`: see `plcsh::fuzzing::servo_frame`.
use libfuzzer_sys::fuzz_target;

fuzz_target!(|data: &[u8]| plcsh::fuzzing::servo_frame(data));
