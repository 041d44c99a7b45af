//! `plcsh run --sandbox [--write-dir DIR]`: runs a script someone else wrote (a student's lab
//! submission) without the parts of Lua that reach outside plcsh: no processes (`os.execute`,
//! `io.popen`), no deleting or renaming files, no exit, no C libraries, no `debug` library, no
//! precompiled chunks; files open for writing only under the given directory (none without
//! `--write-dir`; commands that write files follow the same rule, `shell::files`). Reading
//! files stays allowed (a lab may read its own data).

use super::error::raise_at;
use crate::core::Error;
use mlua::{Lua, MultiValue, Table, Value};
use std::path::Path;

/// What a sandboxed run refuses, with the reason shown to the student.
static REFUSED: &[(&str, &str, &str)] = &[
    ("os", "execute", "runs a program"),
    ("os", "remove", "deletes a file"),
    ("os", "rename", "renames a file"),
    ("os", "exit", "ends plcsh"),
    ("os", "tmpname", "creates a file"),
    ("io", "popen", "runs a program"),
    ("package", "loadlib", "loads a C library"),
];

fn refused(lua: &Lua, what: String, why: &str) -> mlua::Result<mlua::Function> {
    let why = why.to_string();
    lua.create_function(move |lua, _: MultiValue| -> mlua::Result<()> {
        Err(raise_at(
            lua,
            Error::unsupported(format!("{what} is not available in a sandboxed run (it {why})"))
                .hint("plcsh run --sandbox allows devices, printing, checks and reading files; ask the lab for more"),
        ))
    })
}

/// Restricts `lua` for a sandboxed run; `write_dir` is where files may be written.
pub fn apply(lua: &Lua, write_dir: Option<&Path>) -> mlua::Result<()> {
    let g = lua.globals();
    for (lib, name, why) in REFUSED {
        let t: Table = g.get(*lib)?;
        t.set(*name, refused(lua, format!("{lib}.{name}"), why)?)?;
    }
    g.set("debug", Value::Nil)?;
    // C modules: no cpath, and only the Lua searchers (preload, Lua files).
    let package: Table = g.get("package")?;
    package.set("cpath", "")?;
    let searchers: Table = package.get("searchers")?;
    searchers.raw_set(3, Value::Nil)?;
    searchers.raw_set(4, Value::Nil)?;
    // Text chunks only: a precompiled (binary) chunk can crash the interpreter.
    let load: mlua::Function = g.get("load")?;
    g.set(
        "load",
        lua.create_function(move |_, (chunk, name, _mode, env): (Value, Value, Value, Value)| {
            load.call::<MultiValue>((chunk, name, "t", env))
        })?,
    )?;
    let loadfile: mlua::Function = g.get("loadfile")?;
    g.set(
        "loadfile",
        lua.create_function(move |_, (file, _mode, env): (Value, Value, Value)| {
            loadfile.call::<MultiValue>((file, "t", env))
        })?,
    )?;
    // Writes only under write_dir.
    let dir = write_dir.map(|d| d.canonicalize().unwrap_or_else(|_| d.to_path_buf()));
    let io: Table = g.get("io")?;
    let open: mlua::Function = io.get("open")?;
    let d = dir.clone();
    io.set(
        "open",
        lua.create_function(move |lua, (path, mode): (String, Option<String>)| {
            let m = mode.clone().unwrap_or_else(|| "r".into());
            if m.contains(['w', 'a', '+']) {
                check_write(lua, &path, d.as_deref())?;
            }
            open.call::<MultiValue>((path, mode))
        })?,
    )?;
    let output: mlua::Function = io.get("output")?;
    io.set(
        "output",
        lua.create_function(move |lua, file: Value| {
            if let Value::String(s) = &file {
                check_write(lua, &s.to_string_lossy(), dir.as_deref())?;
            }
            output.call::<MultiValue>(file)
        })?,
    )?;
    Ok(())
}

/// The session's rule (`shell::files`), raised at the script's line.
fn check_write(lua: &Lua, path: &str, dir: Option<&Path>) -> mlua::Result<()> {
    crate::shell::files::check_write(&Some(dir.map(Path::to_path_buf)), path).map_err(|e| raise_at(lua, e))
}
