#![no_main]
//! `cargo +nightly fuzz run pcapng`: see `plcsh::fuzzing::pcapng`.
use libfuzzer_sys::fuzz_target;

fuzz_target!(|data: &[u8]| plcsh::fuzzing::pcapng(data));
