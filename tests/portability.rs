//! Windows is first-class by construction: platform code lives in the transport layer's two
//! corners (`src/core/link/{unix,windows}`, picked in `src/core/link/mod.rs`) and in
//! `src/core/platform/`. Everywhere else — device families, the engine, shell, Lua, CLI —
//! the same source builds for every system, so nothing a user does can work on one and
//! silently not exist on the other. This test reads the tree and names any line that breaks it.

use std::path::Path;

/// Where platform code may live.
const ALLOWED: &[&str] =
    &["src/core/link/unix/", "src/core/link/windows/", "src/core/link/mod.rs", "src/core/platform/"];

/// What only platform code may say.
const PLATFORM: &[&str] = &[
    "cfg(unix",
    "cfg(windows",
    "cfg(not(unix",
    "cfg(not(windows",
    "cfg(target_os",
    "cfg(target_family",
    "std::os::unix",
    "std::os::windows",
    "std::os::fd",
    "nix::",
    "libc::",
    "windows_sys::",
    "tokio::io::unix",
    "tokio::signal::unix",
    "tokio::signal::windows",
    "TTYPort",
    "COMPort",
];

#[path = "support/source_tree.rs"]
mod source_tree;
use source_tree::rust_files;

#[test]
fn platform_code_lives_in_the_transport_and_platform_modules_only() {
    let root = Path::new(env!("CARGO_MANIFEST_DIR"));
    let mut files = Vec::new();
    rust_files(&root.join("src"), &mut files);
    assert!(files.len() > 100, "the source tree was not found ({} files)", files.len());
    let mut found = Vec::new();
    for f in &files {
        let rel = f.strip_prefix(root).unwrap().to_string_lossy().replace('\\', "/");
        if ALLOWED.iter().any(|a| rel.starts_with(a)) {
            continue;
        }
        let text = std::fs::read_to_string(f).unwrap();
        for (n, line) in text.lines().enumerate() {
            let code = line.split("//").next().unwrap_or("");
            if let Some(word) = PLATFORM.iter().find(|w| code.contains(*w)) {
                found.push(format!("{rel}:{}: `{word}` in: {}", n + 1, line.trim()));
            }
        }
    }
    assert!(
        found.is_empty(),
        "platform code outside core/link/{{unix,windows}} and core/platform:\n{}",
        found.join("\n")
    );
}

/// The check itself finds what it looks for (a test that cannot fail proves nothing).
#[test]
fn the_check_sees_platform_code_where_it_is_allowed() {
    let root = Path::new(env!("CARGO_MANIFEST_DIR"));
    let unix = std::fs::read_to_string(root.join("src/core/platform/unix.rs")).unwrap();
    assert!(PLATFORM.iter().any(|w| unix.contains(w)));
    let windows = std::fs::read_to_string(root.join("src/core/platform/windows.rs")).unwrap();
    assert!(PLATFORM.iter().any(|w| windows.contains(w)));
}
