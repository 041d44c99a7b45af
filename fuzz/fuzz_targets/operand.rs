#![no_main]
//! `cargo +nightly fuzz run operand`: see `plcsh::fuzzing::operand`.
use libfuzzer_sys::fuzz_target;

fuzz_target!(|data: &[u8]| plcsh::fuzzing::operand(data));
