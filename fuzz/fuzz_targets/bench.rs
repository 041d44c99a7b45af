#![no_main]
//! `cargo +nightly fuzz run bench`: see `plcsh::fuzzing::bench`.
use libfuzzer_sys::fuzz_target;

fuzz_target!(|data: &[u8]| plcsh::fuzzing::bench(data));
