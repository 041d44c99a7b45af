#![no_main]
//! `cargo +nightly fuzz run tags`: see `plcsh::fuzzing::tags`.
use libfuzzer_sys::fuzz_target;

fuzz_target!(|data: &[u8]| plcsh::fuzzing::tags(data));
