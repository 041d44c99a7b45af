#![no_main]
//! `cargo +nightly fuzz run url`: see `plcsh::fuzzing::url`.
use libfuzzer_sys::fuzz_target;

fuzz_target!(|data: &[u8]| plcsh::fuzzing::url(data));
