//! The Lua side of a sandboxed run (`plcsh run --sandbox`, and every grader and submission
//! `plcsh lab` runs). The rules themselves are [`crate::confine::Confinement`], held by the
//! session (devices, snapshots and shell commands check them there); this module makes Lua
//! follow them:
//!
//! - the interpreter's globals lose what reaches outside plcsh: processes (`os.execute`,
//!   `io.popen`), deleting and renaming files, C libraries (`package.loadlib`, C searchers),
//!   `debug` except `debug.traceback`, precompiled chunks; `require` finds plcsh's built-in
//!   modules and the lab's (or the script's) own folder only;
//! - Lua's file functions (`io.open`, `io.lines`, `io.input`, `io.output`, `loadfile`,
//!   `dofile`) read only under the run's folders and write only under its write directory;
//! - a submission runs in an environment of its own ([`student_env`]): copies of the allowed
//!   libraries and of `plcsh`, so what it replaces there (`plcsh.assert_eq`, `string.format`)
//!   the grader never sees, and the grader's `lab` table is not in it at all. `load`,
//!   `loadfile` and `dofile` give chunks that environment.

use super::error::raise_at;
use crate::confine::Confinement;
use crate::core::Error;
use mlua::{Lua, MultiValue, Table, Value};
use std::sync::Arc;

/// What a sandboxed run refuses, with the reason shown to the student.
static REFUSED: &[(&str, &str, &str)] = &[
    ("os", "execute", "runs a program"),
    ("os", "remove", "deletes a file"),
    ("os", "rename", "renames a file"),
    ("os", "exit", "ends plcsh"),
    ("os", "tmpname", "creates a file"),
    ("os", "getenv", "reads the machine's environment"),
    ("io", "popen", "runs a program"),
    ("io", "tmpfile", "creates a file"),
    ("package", "loadlib", "loads a C library"),
];

/// Globals a submission's environment gets as they are (functions without side effects).
const PLAIN: &[&str] = &[
    "assert",
    "error",
    "ipairs",
    "next",
    "pairs",
    "pcall",
    "print",
    "rawequal",
    "rawget",
    "rawlen",
    "rawset",
    "select",
    "setmetatable",
    "tonumber",
    "tostring",
    "type",
    "xpcall",
    "_VERSION",
    "require",
];

/// Libraries a submission's environment gets a copy of (what it changes stays its own).
const LIBRARIES: &[&str] = &["string", "table", "math", "utf8", "coroutine", "plcsh", "io", "os", "debug"];

fn refused(lua: &Lua, what: String, why: &str) -> mlua::Result<mlua::Function> {
    let why = why.to_string();
    lua.create_function(move |lua, _: MultiValue| -> mlua::Result<()> {
        Err(raise_at(
            lua,
            Error::unsupported(format!("{what} is not available in a sandboxed run (it {why})"))
                .hint("the sandbox allows simulated devices, printing, checks and files in the lab's folders"),
        ))
    })
}

fn arg_str(args: &MultiValue, i: usize) -> Option<String> {
    match args.get(i) {
        Some(Value::String(s)) => Some(s.to_string_lossy()),
        _ => None,
    }
}

/// Restricts the globals of `lua` for a sandboxed run under `rules`.
pub fn apply(lua: &Lua, rules: Arc<Confinement>) -> mlua::Result<()> {
    let g = lua.globals();
    for (lib, name, why) in REFUSED {
        let t: Table = g.get(*lib)?;
        t.set(*name, refused(lua, format!("{lib}.{name}"), why)?)?;
    }
    // debug: the traceback only (the rest reaches into other functions' locals and upvalues;
    // plcsh's interpreter is opened without the library, so the traceback is mlua's).
    let only = lua.create_table()?;
    only.set(
        "traceback",
        lua.create_function(|lua, (msg, level): (Value, Option<usize>)| match msg {
            Value::String(s) => Ok(Value::String(lua.traceback(Some(&s.to_string_lossy()), level.unwrap_or(1))?)),
            Value::Nil => Ok(Value::String(lua.traceback(None, level.unwrap_or(1))?)),
            other => Ok(other),
        })?,
    )?;
    g.set("debug", only)?;
    // The string metatable is shared by every environment: nobody may reach it.
    if let Some(mt) = lua.load("return getmetatable('')").eval::<Option<Table>>()? {
        mt.set("__metatable", false)?;
    }
    // C modules: no cpath, and only the Lua searchers (preload, Lua files).
    let package: Table = g.get("package")?;
    package.set("cpath", "")?;
    package.set("path", "")?;
    let searchers: Table = package.get("searchers")?;
    searchers.raw_set(3, Value::Nil)?;
    searchers.raw_set(4, Value::Nil)?;
    // Files: reads under the run's folders, writes under its write directory.
    let io: Table = g.get("io")?;
    let open: mlua::Function = io.get("open")?;
    let r = rules.clone();
    io.set(
        "open",
        lua.create_function(move |lua, args: MultiValue| {
            let path = arg_str(&args, 0).unwrap_or_default();
            let mode = arg_str(&args, 1).unwrap_or_else(|| "r".into());
            if mode.contains(['w', 'a', '+']) {
                r.check_write(&path).map_err(|e| raise_at(lua, e))?;
            }
            if !mode.contains(['w', 'a']) {
                r.check_read(&path).map_err(|e| raise_at(lua, e))?;
            }
            open.call::<MultiValue>(args)
        })?,
    )?;
    for (name, write) in [("lines", false), ("input", false), ("output", true)] {
        let f: mlua::Function = io.get(name)?;
        let r = rules.clone();
        io.set(
            name,
            lua.create_function(move |lua, args: MultiValue| {
                if let Some(path) = arg_str(&args, 0) {
                    let checked = if write { r.check_write(&path) } else { r.check_read(&path) };
                    checked.map_err(|e| raise_at(lua, e))?;
                }
                f.call::<MultiValue>(args)
            })?,
        )?;
    }
    // Where the run may write: `plcsh.write_dir` (nil without one).
    let p: Table = g.get("plcsh")?;
    p.set("write_dir", rules.write.as_ref().map(|d| d.display().to_string()))?;
    install_loaders(lua, &g, rules)?;
    Ok(())
}

/// `load`, `loadfile` and `dofile` for environment `env`: text chunks only (a precompiled
/// chunk can crash the interpreter), files read under the run's folders, and a chunk without
/// an environment of its own gets `env` (as Lua's own do with the globals).
fn install_loaders(lua: &Lua, env: &Table, rules: Arc<Confinement>) -> mlua::Result<()> {
    // Lua's own loaders, kept where no script reaches them (the registry).
    let raw = |name: &str| -> mlua::Result<mlua::Function> {
        let key = format!("plcsh.sandbox.raw_{name}");
        if let Ok(f) = lua.named_registry_value::<mlua::Function>(&key) {
            return Ok(f);
        }
        let f: mlua::Function = lua.globals().get(name)?;
        lua.set_named_registry_value(&key, f.clone())?;
        Ok(f)
    };
    let raw_load = raw("load")?;
    let raw_loadfile = raw("loadfile")?;
    let e = env.clone();
    let load = lua.create_function(move |lua, args: MultiValue| {
        let mut v: Vec<Value> = args.into_iter().collect();
        v.resize(4.max(v.len()), Value::Nil);
        v[2] = Value::String(lua.create_string("t")?);
        if !matches!(v[3], Value::Table(_)) {
            v[3] = Value::Table(e.clone());
        }
        raw_load.call::<MultiValue>(MultiValue::from_iter(v))
    })?;
    let e = env.clone();
    let r = rules.clone();
    let rl = raw_loadfile.clone();
    let loadfile = lua.create_function(move |lua, args: MultiValue| {
        let path = arg_str(&args, 0).ok_or_else(|| {
            raise_at(lua, Error::unsupported("loadfile without a file reads the terminal: not in a sandboxed run"))
        })?;
        r.check_read(&path).map_err(|e| raise_at(lua, e))?;
        let env = match args.get(2) {
            Some(Value::Table(t)) => Value::Table(t.clone()),
            _ => Value::Table(e.clone()),
        };
        rl.call::<MultiValue>((path, "t", env))
    })?;
    let e = env.clone();
    let dofile = lua.create_function(move |lua, path: Option<String>| {
        let path = path.ok_or_else(|| {
            raise_at(lua, Error::unsupported("dofile without a file reads the terminal: not in a sandboxed run"))
        })?;
        rules.check_read(&path).map_err(|err| raise_at(lua, err))?;
        let (f, err): (Option<mlua::Function>, Option<String>) =
            raw_loadfile.call((path.as_str(), "t", Value::Table(e.clone())))?;
        match f {
            Some(f) => f.call::<MultiValue>(()),
            None => Err(mlua::Error::runtime(err.unwrap_or_default())),
        }
    })?;
    env.raw_set("load", load)?;
    env.raw_set("loadfile", loadfile)?;
    env.raw_set("dofile", dofile)?;
    Ok(())
}

/// A copy of `t` and the tables in it (a library's sub-tables: `plcsh.json`), so nothing a
/// submission changes reaches the grader's.
fn deep_copy(lua: &Lua, t: &Table, depth: usize) -> mlua::Result<Table> {
    let copy = lua.create_table()?;
    for pair in t.pairs::<Value, Value>() {
        let (k, v) = pair?;
        let v = match v {
            Value::Table(inner) if depth < 3 => Value::Table(deep_copy(lua, &inner, depth + 1)?),
            v => v,
        };
        copy.raw_set(k, v)?;
    }
    Ok(copy)
}

/// A fresh environment for a submission: its own copies of the allowed libraries and of
/// `plcsh`, the plain functions, the device globals, and loaders that give chunks this
/// environment. Call after [`apply`].
pub fn student_env(lua: &Lua, rules: Arc<Confinement>) -> mlua::Result<Table> {
    let g = lua.globals();
    let env = lua.create_table()?;
    for name in PLAIN {
        env.raw_set(*name, g.raw_get::<Value>(*name)?)?;
    }
    for lib in LIBRARIES {
        if let Value::Table(t) = g.raw_get::<Value>(*lib)? {
            env.raw_set(*lib, deep_copy(lua, &t, 0)?)?;
        }
    }
    // getmetatable: a table's only — the string and device metatables are shared with the grader.
    let gm: mlua::Function = lua
        .load("local gm, type = getmetatable, type\nreturn function(o) if type(o) == 'table' then return gm(o) end end")
        .set_name("=sandbox")
        .eval()?;
    env.raw_set("getmetatable", gm)?;
    // Device handles (`plc`, `servo`): the globals' userdata, looked up when used, so a
    // device opened later (or by the run's setup) is there too.
    let lookup: mlua::Function = lua
        .load("local G, rawget, type = ...\nreturn function(_, k) local v = rawget(G, k); if type(v) == 'userdata' then return v end end")
        .set_name("=sandbox")
        .call((g.clone(), g.raw_get::<Value>("rawget")?, g.raw_get::<Value>("type")?))?;
    let mt = lua.create_table()?;
    mt.raw_set("__index", lookup)?;
    mt.raw_set("__metatable", false)?;
    env.set_metatable(Some(mt))?;
    env.raw_set("_G", env.clone())?;
    install_loaders(lua, &env, rules)?;
    Ok(env)
}
