#![no_main]
//! `cargo +nightly fuzz run fx_link`: see `plcsh::fuzzing::fx_link`.
use libfuzzer_sys::fuzz_target;

fuzz_target!(|data: &[u8]| plcsh::fuzzing::fx_link(data));
