//! Bench files.
