#![no_main]
//! `cargo +nightly fuzz run il`: see `plcsh::fuzzing::il`.
use libfuzzer_sys::fuzz_target;

fuzz_target!(|data: &[u8]| plcsh::fuzzing::il(data));
