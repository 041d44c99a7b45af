#![no_main]
//! `cargo +nightly fuzz run umpk_reply`: see `plcsh::fuzzing::umpk_reply`.
use libfuzzer_sys::fuzz_target;

fuzz_target!(|data: &[u8]| plcsh::fuzzing::umpk_reply(data));
