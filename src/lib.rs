//! plcsh: a shell for commissioning and debugging Kinco K2 PLCs and Kinco servo drives.
//!
//! Layers (see `../shared/design.md`): `core` ← device families (`k2`, `servo`) ←
//! `session` ← front ends (`shell`, `cli`, `script`). `output` renders core values only.

pub mod cli;
pub mod confine;
pub mod core;
pub mod dataset;
pub mod engine;
pub mod fleet;
pub mod fuzzing;
pub mod fx;
pub mod guard;
pub mod k2;
pub mod lab;
pub mod names;
pub mod output;
pub mod paths;
pub mod pending;
pub mod plot;
pub mod profile;
pub mod publish;
pub mod record;
pub mod report;
pub mod schemes;
pub mod script;
pub mod servo;
pub mod session;
pub mod shell;
pub mod signals;
pub mod snapshot;
pub mod tags;
pub mod umpk;
pub mod wiring;
