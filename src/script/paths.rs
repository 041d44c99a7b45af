//! Where `require` finds Lua modules, in this order:
//! 1. every directory in `PLCSH_LIB` (`:`-separated),
//! 2. the user's config directory (`~/.config/plcsh/lib` on Linux, via `directories`),
//! 3. the project's `lib/`: on disk next to the executable (`target/release/plcsh` → `lib/`
//!    two levels up, or `../lib` of an unpacked release), else the copy built into the binary
//!    ([`BUILT_IN`]), so a `cargo install`ed plcsh needs no source checkout;
//! 4. for `plcsh run`, the script's own directory;
//!
//! then Lua's defaults (`package.path`).
//! One searcher (in the place of Lua's file searcher, so the sandbox's list of searchers is
//! unchanged) walks this list; the directories are visible to scripts as `plcsh.lib_dirs`, and
//! a module found in the binary reports `plcsh:lib/NAME.lua` as its loader data. The
//! directories of 1–3 are computed by [`crate::paths::lib_dirs`], where `plcsh paths` reads
//! them too.

use mlua::chunk::ChunkMode;
use mlua::{Lua, MultiValue, Table, Value};
use std::path::{Path, PathBuf};
use std::sync::{Arc, Mutex};

/// The modules of `lib/` built into the binary: (module name, source).
pub const BUILT_IN: &[(&str, &str)] = &[("commission", include_str!("../../lib/commission.lua"))];

use crate::paths::lib_dirs;

/// The search list of one interpreter: directories before the built-in modules, then the
/// script's directory (set by `plcsh run`).
#[derive(Default)]
struct Search {
    dirs: Vec<PathBuf>,
    script_dir: Option<PathBuf>,
    /// A sandboxed run: only the built-in modules and the script's (the lab's) own folder.
    confined: bool,
}

#[derive(Clone)]
struct Shared(Arc<Mutex<Search>>);

fn candidates(dir: &Path, name: &str) -> [PathBuf; 2] {
    let rel = name.replace('.', "/");
    [dir.join(format!("{rel}.lua")), dir.join(&rel).join("init.lua")]
}

/// Loads a module's text as a chunk (text only: a binary chunk can crash the interpreter).
fn load(lua: &Lua, name: &str, code: &[u8], chunk_name: &str, from: &str) -> mlua::Result<MultiValue> {
    let f = lua
        .load(super::file_chunk(code))
        .set_name(chunk_name)
        .set_mode(ChunkMode::Text)
        .into_function()
        .map_err(|e| mlua::Error::runtime(format!("error loading module '{name}' from {from}:\n\t{e}")))?;
    Ok(MultiValue::from_iter([Value::Function(f), Value::String(lua.create_string(from)?)]))
}

fn search(lua: &Lua, shared: &Shared, name: &str) -> mlua::Result<MultiValue> {
    let (dirs, script_dir, confined) = {
        let s = shared.0.lock().unwrap_or_else(|p| p.into_inner());
        (s.dirs.clone(), s.script_dir.clone(), s.confined)
    };
    let mut tried = Vec::new();
    let in_dir = |dir: &Path, tried: &mut Vec<String>| -> mlua::Result<Option<MultiValue>> {
        for file in candidates(dir, name) {
            if let Ok(code) = std::fs::read(&file) {
                let shown = file.display().to_string();
                return load(lua, name, &code, &format!("@{shown}"), &shown).map(Some);
            }
            tried.push(format!("no file '{}'", file.display()));
        }
        Ok(None)
    };
    for d in &dirs {
        if let Some(found) = in_dir(d, &mut tried)? {
            return Ok(found);
        }
    }
    if let Some((_, code)) = BUILT_IN.iter().find(|(n, _)| *n == name) {
        let from = format!("plcsh:lib/{name}.lua");
        return load(lua, name, code.as_bytes(), &format!("@{from}"), &from);
    }
    tried.push(crate::msg!("script-no-built-in-module", name = name).text);
    if let Some(d) = &script_dir {
        if let Some(found) = in_dir(d, &mut tried)? {
            return Ok(found);
        }
    }
    if confined {
        tried.push(crate::msg!("script-sandbox-modules").text);
        return Ok(MultiValue::from_iter([Value::String(lua.create_string(tried.join("\n\t"))?)]));
    }
    // Lua's defaults last, as its own file searcher would do them.
    let package: Table = lua.globals().get("package")?;
    let path: String = package.get("path")?;
    let searchpath: mlua::Function = package.get("searchpath")?;
    let (file, why): (Option<String>, Option<String>) = searchpath.call((name, path))?;
    if let Some(file) = file {
        let code = std::fs::read(&file)
            .map_err(|e| mlua::Error::runtime(format!("error loading module '{name}' from file '{file}': {e}")))?;
        return load(lua, name, &code, &format!("@{file}"), &file);
    }
    let mut text = tried.join("\n\t");
    if let Some(w) = why {
        text.push_str("\n\t");
        text.push_str(w.trim_start_matches(['\n', '\t']));
    }
    Ok(MultiValue::from_iter([Value::String(lua.create_string(text)?)]))
}

pub fn register(lua: &Lua) -> mlua::Result<()> {
    let dirs = lib_dirs();
    let shared = Shared(Arc::new(Mutex::new(Search { dirs: dirs.clone(), script_dir: None, confined: false })));
    let s = shared.clone();
    let searcher = lua.create_function(move |lua, (name, _extra): (String, Value)| search(lua, &s, &name))?;
    let package: Table = lua.globals().get("package")?;
    let searchers: Table = package.get("searchers")?;
    searchers.raw_set(2, searcher)?;
    lua.set_app_data(shared);
    let p: Table = lua.globals().get("plcsh")?;
    p.set("lib_dirs", dirs.iter().map(|d| d.display().to_string()).collect::<Vec<_>>())?;
    Ok(())
}

/// `plcsh run` finds modules next to the script too — after the directories and modules
/// above, as the README gives the order — and lists it last in `plcsh.lib_dirs`.
/// A sandboxed run: `require` finds the built-in modules and the modules in `dir` (the lab's
/// folder; the script's folder when `None`) only.
pub fn confine(lua: &Lua, dir: Option<&Path>) -> mlua::Result<()> {
    if let Some(shared) = lua.app_data_ref::<Shared>() {
        let mut s = shared.0.lock().unwrap_or_else(|p| p.into_inner());
        s.dirs.clear();
        s.confined = true;
        if let Some(d) = dir {
            s.script_dir = Some(d.to_path_buf());
        }
    }
    let p: Table = lua.globals().get("plcsh")?;
    p.set("lib_dirs", dir.map(|d| vec![d.display().to_string()]).unwrap_or_default())
}

/// Sets the folder of the script being run (searched by `require`), unless a sandbox fixed it.
pub fn add_script_dir(lua: &Lua, script: &Path) -> mlua::Result<()> {
    let dir = match script.parent() {
        Some(d) if !d.as_os_str().is_empty() => d.to_path_buf(),
        _ => PathBuf::from("."),
    };
    if let Some(shared) = lua.app_data_ref::<Shared>() {
        let mut s = shared.0.lock().unwrap_or_else(|p| p.into_inner());
        if s.confined && s.script_dir.is_some() {
            return Ok(());
        }
        s.script_dir = Some(dir.clone());
    }
    let p: Table = lua.globals().get("plcsh")?;
    let listed: Table = p.get("lib_dirs")?;
    listed.push(dir.display().to_string())
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Every module in `lib/` is built in (a new one is added to [`BUILT_IN`]).
    #[test]
    fn every_lib_module_is_built_in() {
        let lib = Path::new(env!("CARGO_MANIFEST_DIR")).join("lib");
        let mut on_disk: Vec<String> = std::fs::read_dir(&lib)
            .unwrap()
            .filter_map(|e| e.ok()?.file_name().to_str()?.strip_suffix(".lua").map(str::to_string))
            .collect();
        on_disk.sort();
        let mut built: Vec<String> = BUILT_IN.iter().map(|(n, _)| n.to_string()).collect();
        built.sort();
        assert_eq!(on_disk, built);
        for (name, code) in BUILT_IN {
            assert_eq!(std::fs::read_to_string(lib.join(format!("{name}.lua"))).unwrap(), *code);
        }
    }
}
