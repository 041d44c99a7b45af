#![no_main]
//! `cargo +nightly fuzz run lab_toml`: see `plcsh::fuzzing::lab_toml`.
use libfuzzer_sys::fuzz_target;

fuzz_target!(|data: &[u8]| plcsh::fuzzing::lab_toml(data));
