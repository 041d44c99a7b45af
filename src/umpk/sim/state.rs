//! What a simulated UMPK keeps through power loss: its flash (the programmed binary and
//! whether programming completed), the 22 program-info bytes, and the error history (which
//! our simulator also keeps through a reset). With a state file (`--umpk-state FILE`,
//! `sim-umpk:UMPK16?state=FILE`) every change is written — through a temporary file, fsync
//! and a rename — BEFORE the controller acknowledges it, so a page acknowledged with `R` is
//! still there after `kill -9` (acknowledged means durable). Programs the simulator executes
//! (an IL program) are loaded from their own files and are not part of this state.

use super::{Program, Umpk};
use crate::core::{Error, Result};
use crate::msg;
use crate::umpk::codec::INFO_LEN;
use serde::{Deserialize, Serialize};
use std::path::Path;

#[derive(Serialize, Deserialize)]
struct Saved {
    model: String,
    /// `none` or `binary`.
    program: String,
    info: String,
    errors: Vec<u8>,
    /// The flash as hex, two digits a byte.
    flash: String,
}

/// Writes the durable part of `u` to `path`.
pub fn save(u: &Umpk, path: &Path) -> Result<()> {
    let s = Saved {
        model: u.model.name.into(),
        program: if matches!(u.program, Program::Binary) { "binary" } else { "none" }.into(),
        info: String::from_utf8_lossy(&u.info).into_owned(),
        errors: u.errors.to_vec(),
        flash: u.flash.iter().map(|b| format!("{b:02X}")).collect(),
    };
    let text = serde_json::to_string_pretty(&s).map_err(|e| Error::io(msg!("umpk-state-cannot-encode")).cause(e))?;
    crate::core::durable::write_atomic(path, text.as_bytes())
}

/// Restores `u` from `path` if it exists (a controller powered up with its flash). A
/// temporary file a killed writer left beside it is removed, never read.
pub fn load(u: &mut Umpk, path: &Path) -> Result<()> {
    crate::core::durable::remove_stale(path);
    let text = match std::fs::read_to_string(path) {
        Ok(t) => t,
        Err(e) if e.kind() == std::io::ErrorKind::NotFound => return Ok(()),
        Err(e) => return Err(Error::io(msg!("umpk-state-cannot-read", file = path.display().to_string())).cause(e)),
    };
    let bad = |m: &str| {
        Error::io(msg!("umpk-state-bad-file", file = path.display().to_string(), reason = m))
            .hint(msg!("umpk-state-hint-remove"))
    };
    let s: Saved = serde_json::from_str(&text).map_err(|e| bad(&e.to_string()))?;
    if s.model != u.model.name {
        return Err(Error::usage(msg!(
            "umpk-state-other-model",
            file = path.display().to_string(),
            saved = &s.model,
            model = u.model.name
        ))
        .hint(msg!("umpk-state-hint-other-file")));
    }
    let flash: Option<Vec<u8>> = s.flash.as_bytes().chunks(2).map(crate::umpk::codec::hex_pair).collect::<Option<_>>();
    let flash = flash.filter(|f| f.len() == u.flash.len()).ok_or_else(|| bad(&msg!("umpk-snap-flash-size")))?;
    let info = s.info.as_bytes();
    if info.len() != INFO_LEN || s.errors.len() != 8 {
        return Err(bad(&msg!("umpk-state-info-size")));
    }
    u.flash = flash;
    u.info.copy_from_slice(info);
    u.errors.copy_from_slice(&s.errors);
    if s.program == "binary" {
        u.program = Program::Binary;
        u.mode = super::Mode::Work;
    }
    Ok(())
}
