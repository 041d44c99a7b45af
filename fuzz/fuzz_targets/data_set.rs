#![no_main]
//! `cargo +nightly fuzz run data_set`: see `plcsh::fuzzing::data_set`.
use libfuzzer_sys::fuzz_target;

fuzz_target!(|data: &[u8]| plcsh::fuzzing::data_set(data));
