#![no_main]
//! `cargo +nightly fuzz run pulse`: see `plcsh::fuzzing::pulse`.
use libfuzzer_sys::fuzz_target;

fuzz_target!(|data: &[u8]| plcsh::fuzzing::pulse(data));
