#![no_main]
//! `cargo +nightly fuzz run agent_base`: see `plcsh::fuzzing::agent_base`.
use libfuzzer_sys::fuzz_target;

fuzz_target!(|data: &[u8]| plcsh::fuzzing::agent_base(data));
