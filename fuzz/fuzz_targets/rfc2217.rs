#![no_main]
//! `cargo +nightly fuzz run rfc2217 -- -a`: see `plcsh::fuzzing::rfc2217`.
use libfuzzer_sys::fuzz_target;

fuzz_target!(|data: &[u8]| plcsh::fuzzing::rfc2217(data));
