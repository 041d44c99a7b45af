#![no_main]
//! `cargo +nightly fuzz run il_encoding`: see `plcsh::fuzzing::il_encoding`.
use libfuzzer_sys::fuzz_target;

fuzz_target!(|data: &[u8]| plcsh::fuzzing::il_encoding(data));
