#![no_main]
//! `cargo +nightly fuzz run agent_mailbox`: see `plcsh::fuzzing::agent_mailbox`.
use libfuzzer_sys::fuzz_target;

fuzz_target!(|data: &[u8]| plcsh::fuzzing::agent_mailbox(data));
