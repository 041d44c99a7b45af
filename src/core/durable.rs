//! Atomic, durable file writes, one helper for every file plcsh keeps (the simulators' state
//! files, snapshots, E2PROM images): the new content goes to a temporary file beside the
//! target, is fsync'd, renamed over the target and the directory fsync'd, so a crash at any
//! moment leaves the old or the new file, never half of one, and a returned `Ok` means the
//! new file is on disk.
//!
//! The temporary file is `.NAME.tmp` beside `NAME`. Where the system can create a file
//! without a name (Linux `O_TMPFILE`, [`crate::core::platform::unnamed_file`]) the content is
//! written and fsync'd before the file has one, and it is named `.NAME.tmp` only for the
//! rename that follows at once: a process killed while it writes (the long part, the fsync)
//! leaves nothing behind. Elsewhere, and on file systems without unnamed files, the named
//! temporary file is written directly. Either way it is removed when a write fails, and a
//! `.NAME.tmp` a killed process left is never read as state: readers read only `NAME`, and
//! the next owner removes the leftover when it opens the file ([`remove_stale`]).

use crate::core::{Error, Result};
use crate::msg;
use std::io::Write;
use std::path::{Path, PathBuf};

/// The directory of `path` and a sibling name `.NAME.suffix` in it.
pub fn sibling(path: &Path, suffix: &str) -> (PathBuf, PathBuf) {
    let dir = path.parent().filter(|d| !d.as_os_str().is_empty()).unwrap_or(Path::new(".")).to_path_buf();
    let name = path.file_name().map(|n| n.to_string_lossy().into_owned()).unwrap_or_else(|| "state".into());
    let s = dir.join(format!(".{name}.{suffix}"));
    (dir, s)
}

/// The temporary file a write of `path` goes through.
pub fn temporary(path: &Path) -> PathBuf {
    sibling(path, "tmp").1
}

/// Removes the temporary file a killed writer of `path` left, if any.
pub fn remove_stale(path: &Path) {
    let _ = std::fs::remove_file(temporary(path));
}

/// Writes `bytes` to `path` atomically and durably (module doc).
pub fn write_atomic(path: &Path, bytes: &[u8]) -> Result<()> {
    let (dir, tmp) = sibling(path, "tmp");
    std::fs::create_dir_all(&dir)
        .map_err(|e| Error::io(msg!("file-cannot-create", path = dir.display().to_string())).cause(e))?;
    let fail = |e: std::io::Error| {
        let _ = std::fs::remove_file(&tmp);
        Error::io(msg!("file-cannot-write", path = path.display().to_string())).cause(e)
    };
    let written = |f: &mut std::fs::File| f.write_all(bytes).and_then(|()| f.sync_all());
    match crate::core::platform::unnamed_file(&dir) {
        Some(mut f) => {
            written(&mut f).map_err(fail)?;
            // A leftover of a killed writer would stand in the way of the name.
            let _ = std::fs::remove_file(&tmp);
            crate::core::platform::name_file(&f, &tmp).map_err(fail)?;
        }
        None => {
            let mut f = std::fs::File::create(&tmp).map_err(fail)?;
            written(&mut f).map_err(fail)?;
        }
    }
    crate::core::platform::durable_rename(&tmp, path, &dir).map_err(fail)
}

#[cfg(test)]
mod tests {
    use super::*;

    fn scratch(tag: &str) -> PathBuf {
        let d = std::env::temp_dir().join(format!("plcsh-durable-{}-{tag}", std::process::id()));
        let _ = std::fs::remove_dir_all(&d);
        std::fs::create_dir_all(&d).unwrap();
        d
    }

    #[test]
    fn writes_replace_the_file_and_leave_nothing_beside_it() {
        let d = scratch("write");
        let p = d.join("state.json");
        // A leftover from a killed writer, in the way of the temporary name.
        std::fs::write(temporary(&p), b"half").unwrap();
        write_atomic(&p, b"one").unwrap();
        write_atomic(&p, b"two").unwrap();
        assert_eq!(std::fs::read(&p).unwrap(), b"two");
        let names: Vec<_> = std::fs::read_dir(&d).unwrap().map(|e| e.unwrap().file_name()).collect();
        assert_eq!(names, vec![std::ffi::OsString::from("state.json")]);
        std::fs::write(temporary(&p), b"half").unwrap();
        remove_stale(&p);
        assert!(!temporary(&p).exists());
    }

    #[test]
    fn a_failed_write_leaves_no_temporary_file() {
        let d = scratch("fail");
        // The target is a directory: the rename fails after the temporary file was written.
        let p = d.join("state.json");
        std::fs::create_dir(&p).unwrap();
        std::fs::write(p.join("inside"), b"x").unwrap();
        let e = write_atomic(&p, b"new").unwrap_err();
        assert!(e.to_string().contains("cannot write"), "{e}");
        assert!(!temporary(&p).exists());
    }
}
