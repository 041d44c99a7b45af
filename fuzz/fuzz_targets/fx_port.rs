#![no_main]
//! `cargo +nightly fuzz run fx_port`: see `plcsh::fuzzing::fx_port`.
use libfuzzer_sys::fuzz_target;

fuzz_target!(|data: &[u8]| plcsh::fuzzing::fx_port(data));
