#![no_main]
//! `cargo +nightly fuzz run umpk_hex`: see `plcsh::fuzzing::umpk_hex`.
use libfuzzer_sys::fuzz_target;

fuzz_target!(|data: &[u8]| plcsh::fuzzing::umpk_hex(data));
