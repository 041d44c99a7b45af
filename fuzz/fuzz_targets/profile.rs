#![no_main]
//! `cargo +nightly fuzz run profile`: see `plcsh::fuzzing::profile`.
use libfuzzer_sys::fuzz_target;

fuzz_target!(|data: &[u8]| plcsh::fuzzing::profile(data));
