//! Teaching labs.
pub mod budget;
