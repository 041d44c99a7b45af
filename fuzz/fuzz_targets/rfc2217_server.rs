#![no_main]
//! `cargo +nightly fuzz run rfc2217_server -- -a`: see `plcsh::fuzzing::rfc2217_server`.
use libfuzzer_sys::fuzz_target;

fuzz_target!(|data: &[u8]| plcsh::fuzzing::rfc2217_server(data));
