//! Where commands may write files (`trace … to=`, `plot … to=`, `profile … plan to=`,
//! `eeprom dump`). Unrestricted by default; a sandboxed run (`plcsh run --sandbox`) confines
//! them, and Lua's own `io.open`, to its `--write-dir` (or forbids them without one), so the
//! rule holds whichever path a script takes to write.

use crate::core::{Error, Result};
use std::path::{Path, PathBuf};

/// The rule: `None` writes anywhere; `Some(None)` nowhere; `Some(Some(dir))` only under `dir`.
pub type WriteRule = Option<Option<PathBuf>>;

/// Checks that `path` may be written under `rule` (after resolving `..` and symbolic links in
/// its directory).
pub fn check_write(rule: &WriteRule, path: &str) -> Result<()> {
    let Some(dir) = rule else { return Ok(()) };
    let Some(dir) = dir else {
        return Err(Error::unsupported(format!("writing {path} is not allowed in a sandboxed run"))
            .hint("give the run a directory for its files: plcsh run --sandbox --write-dir DIR"));
    };
    let dir = crate::core::fspath::canonical(dir).unwrap_or_else(|_| dir.clone());
    let p = Path::new(path);
    let parent = p.parent().filter(|p| !p.as_os_str().is_empty()).unwrap_or(Path::new("."));
    let resolved = crate::core::fspath::canonical(parent).ok().map(|d| d.join(p.file_name().unwrap_or_default()));
    match resolved {
        Some(r) if r.starts_with(&dir) && p.file_name().is_some() => Ok(()),
        _ => Err(Error::unsupported(format!("writing {path} is outside {}", dir.display()))
            .hint("a sandboxed run writes only under its --write-dir")),
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn writes_stay_under_the_directory() {
        let dir = std::env::temp_dir();
        assert!(check_write(&None, "/etc/x").is_ok());
        assert!(check_write(&Some(None), "x.csv").is_err());
        let rule = Some(Some(dir.clone()));
        assert!(check_write(&rule, dir.join("a.csv").to_str().unwrap()).is_ok());
        assert!(check_write(&rule, dir.join("../a.csv").to_str().unwrap()).is_err());
        assert!(check_write(&rule, "/etc/passwd").is_err());
    }
}
