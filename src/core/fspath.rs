//! Canonical paths a user and Lua can use: [`canonical`] resolves `..` and links like
//! `fs::canonicalize`, but gives `C:\labs\x` rather than Windows' verbatim `\\?\C:\labs\x`,
//! in which `/` is not a separator (`plcsh.write_dir .. '/out.txt'` would fail to open) and
//! which most programs do not expect. Every sandbox and lab path check compares paths made
//! here, so both sides of a comparison have the same form.

use std::path::{Path, PathBuf};

/// `path` resolved by the file system, without a verbatim prefix when an ordinary path says the same.
pub fn canonical(path: &Path) -> std::io::Result<PathBuf> {
    path.canonicalize().map(|p| plain(&p))
}

/// `\\?\C:\x` → `C:\x`, `\\?\UNC\server\share\x` → `\\server\share\x`; anything else unchanged.
/// Paths longer than the classic 260-character limit keep the prefix (they need it).
pub fn plain(path: &Path) -> PathBuf {
    let Some(s) = path.to_str() else { return path.to_path_buf() };
    if let Some(rest) = s.strip_prefix(r"\\?\UNC\") {
        if rest.len() + 2 < 260 {
            return PathBuf::from(format!(r"\\{rest}"));
        }
    } else if let Some(rest) = s.strip_prefix(r"\\?\") {
        let drive = rest.as_bytes();
        if drive.len() >= 3
            && drive[0].is_ascii_alphabetic()
            && drive[1] == b':'
            && drive[2] == b'\\'
            && rest.len() < 260
        {
            return PathBuf::from(rest);
        }
    }
    path.to_path_buf()
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn verbatim_prefixes_are_dropped_where_an_ordinary_path_says_the_same() {
        assert_eq!(plain(Path::new(r"\\?\C:\labs\x")), PathBuf::from(r"C:\labs\x"));
        assert_eq!(plain(Path::new(r"\\?\UNC\srv\share\x")), PathBuf::from(r"\\srv\share\x"));
        assert_eq!(plain(Path::new(r"\\?\GLOBALROOT\Device\x")), PathBuf::from(r"\\?\GLOBALROOT\Device\x"));
        assert_eq!(plain(Path::new("/tmp/x")), PathBuf::from("/tmp/x"));
        let long = format!(r"\\?\C:\{}", "a".repeat(300));
        assert_eq!(plain(Path::new(&long)), PathBuf::from(&long), "a long path needs its prefix");
    }

    #[test]
    fn canonical_resolves_dot_dot() {
        // A folder of this test's own: `x/..` resolves only where `x` exists.
        let d = std::env::temp_dir().join(format!("plcsh-fspath-{}", std::process::id()));
        std::fs::create_dir_all(d.join("x")).unwrap();
        let (up, direct) = (canonical(&d.join("x").join("..")), canonical(&d));
        let _ = std::fs::remove_dir_all(&d);
        assert_eq!(up.unwrap(), direct.unwrap());
    }
}
