#![no_main]
//! `cargo +nightly fuzz run fx_operand`: see `plcsh::fuzzing::fx_operand`.
use libfuzzer_sys::fuzz_target;

fuzz_target!(|data: &[u8]| plcsh::fuzzing::fx_operand(data));
