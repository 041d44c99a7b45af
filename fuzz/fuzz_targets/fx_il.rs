#![no_main]
//! `cargo +nightly fuzz run fx_il`: see `plcsh::fuzzing::fx_il`.
use libfuzzer_sys::fuzz_target;

fuzz_target!(|data: &[u8]| plcsh::fuzzing::fx_il(data));
