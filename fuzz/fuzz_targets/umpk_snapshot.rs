#![no_main]
//! `cargo +nightly fuzz run umpk_snapshot`: see `plcsh::fuzzing::umpk_snapshot`.
use libfuzzer_sys::fuzz_target;

fuzz_target!(|data: &[u8]| plcsh::fuzzing::umpk_snapshot(data));
