#![no_main]
//! `cargo +nightly fuzz run control`: see `plcsh::fuzzing::control`.
use libfuzzer_sys::fuzz_target;

fuzz_target!(|data: &[u8]| plcsh::fuzzing::control(data));
