#![no_main]
//! `cargo +nightly fuzz run literal`: see `plcsh::fuzzing::literal`.
use libfuzzer_sys::fuzz_target;

fuzz_target!(|data: &[u8]| plcsh::fuzzing::literal(data));
