//! Where `require` finds Lua modules: `package.path` gets, in this order,
//! 1. every directory in `PLCSH_LIB` (`:`-separated),
//! 2. the user's config directory (`~/.config/plcsh/lib` on Linux, via `directories`),
//! 3. the project's `lib/` — next to the executable (`target/release/plcsh` → `lib/` two
//!    levels up, or `../lib` of an installed tree), else the source tree it was built from;
//!
//! 4. for `plcsh run`, the script's own directory;
//!
//! then Lua's defaults.
//! The list is visible to scripts as `plcsh.lib_dirs`.

use mlua::{Lua, Table};
use std::path::{Path, PathBuf};

/// The directories searched, most specific first (only those that exist).
pub fn lib_dirs() -> Vec<PathBuf> {
    let mut dirs: Vec<PathBuf> = Vec::new();
    if let Some(v) = std::env::var_os("PLCSH_LIB") {
        dirs.extend(std::env::split_paths(&v).filter(|p| !p.as_os_str().is_empty()));
    }
    if let Some(d) = directories::ProjectDirs::from("", "", "plcsh") {
        dirs.push(d.config_dir().join("lib"));
    }
    let mut project = Vec::new();
    if let Ok(exe) = std::env::current_exe() {
        for up in [2usize, 1, 0] {
            let mut p = exe.parent().map(Path::to_path_buf);
            for _ in 0..up {
                p = p.and_then(|x| x.parent().map(Path::to_path_buf));
            }
            if let Some(p) = p {
                project.push(p.join("lib"));
            }
        }
    }
    project.push(Path::new(env!("CARGO_MANIFEST_DIR")).join("lib"));
    if let Some(found) = project.into_iter().find(|p| p.join("commission.lua").is_file()) {
        dirs.push(found);
    }
    dirs.retain(|d| d.is_dir());
    dirs.dedup();
    dirs
}

fn patterns(dir: &Path) -> String {
    let d = dir.display();
    format!("{d}/?.lua;{d}/?/init.lua;")
}

/// Prepends `dirs` to `package.path`.
fn prepend(lua: &Lua, dirs: &[PathBuf]) -> mlua::Result<()> {
    let package: Table = lua.globals().get("package")?;
    let old: String = package.get("path")?;
    let new: String = dirs.iter().map(|d| patterns(d)).collect::<String>() + &old;
    package.set("path", new)
}

pub fn register(lua: &Lua) -> mlua::Result<()> {
    let dirs = lib_dirs();
    prepend(lua, &dirs)?;
    let p: Table = lua.globals().get("plcsh")?;
    p.set("lib_dirs", dirs.iter().map(|d| d.display().to_string()).collect::<Vec<_>>())?;
    Ok(())
}

/// `plcsh run` finds modules next to the script too — after the directories above, as the
/// README gives the order — and lists it last in `plcsh.lib_dirs`.
pub fn add_script_dir(lua: &Lua, script: &Path) -> mlua::Result<()> {
    let dir = match script.parent() {
        Some(d) if !d.as_os_str().is_empty() => d.to_path_buf(),
        _ => PathBuf::from("."),
    };
    let package: Table = lua.globals().get("package")?;
    let old: String = package.get("path")?;
    let libs: String = lib_dirs().iter().map(|d| patterns(d)).collect();
    let rest = old.strip_prefix(libs.as_str()).unwrap_or(&old);
    package.set("path", format!("{libs}{}{rest}", patterns(&dir)))?;
    let p: Table = lua.globals().get("plcsh")?;
    let listed: Table = p.get("lib_dirs")?;
    listed.push(dir.display().to_string())
}
