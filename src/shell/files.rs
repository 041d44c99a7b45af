//! Where commands may write files (`trace … to=`, `plot … to=`, `profile … plan to=`,
//! `eeprom dump`). Unrestricted by default; a sandboxed run (`plcsh run --sandbox`) confines
//! them, and Lua's own `io.open`, to its `--write-dir` (or forbids them without one), so the
//! rule holds whichever path a script takes to write. The rule is the sandbox's
//! ([`crate::confine`]), below the shell, so the session's confinement and the shell's
//! commands check writes the same way.

pub use crate::confine::{check_write, WriteRule};
