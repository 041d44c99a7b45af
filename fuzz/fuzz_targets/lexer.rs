#![no_main]
//! `cargo +nightly fuzz run lexer`: see `plcsh::fuzzing::lexer`.
use libfuzzer_sys::fuzz_target;

fuzz_target!(|data: &[u8]| plcsh::fuzzing::lexer(data));
