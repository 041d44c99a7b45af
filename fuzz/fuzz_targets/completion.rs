#![no_main]
//! `cargo +nightly fuzz run completion`: see `plcsh::fuzzing::completion`.
use libfuzzer_sys::fuzz_target;

fuzz_target!(|data: &[u8]| plcsh::fuzzing::completion(data));
