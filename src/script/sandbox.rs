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
use std::path::PathBuf;
use std::sync::Arc;

/// What a sandboxed run refuses, with the reason shown to the student (the `$why` selector
/// of the catalogue's `script-sandbox-refused`).
static REFUSED: &[(&str, &str, &str)] = &[
    ("os", "execute", "program"),
    ("os", "remove", "delete"),
    ("os", "rename", "rename"),
    ("os", "exit", "exit"),
    ("os", "tmpname", "create"),
    ("os", "getenv", "environment"),
    ("io", "popen", "program"),
    ("io", "tmpfile", "create"),
    ("package", "loadlib", "library"),
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
            Error::unsupported(crate::msg!("script-sandbox-refused", what = what.as_str(), why = why.as_str()))
                .hint(crate::msg!("script-hint-sandbox")),
        ))
    })
}

fn arg_str(args: &MultiValue, i: usize) -> Option<String> {
    match args.get(i) {
        Some(Value::String(s)) => Some(s.to_string_lossy()),
        _ => None,
    }
}

/// A traceback without the frames of files named by an absolute path (the grader's, the lab's
/// modules: `/home/teacher/labs/…`, `C:\\Users\\…`, or Lua's shortened `...tail` of one):
/// such a frame reads `(a frame of the lab's)`, so no folder of the grader's reaches a run.
fn no_folders(t: &str) -> String {
    let mut out = String::with_capacity(t.len());
    let mut after = false;
    for (i, line) in t.split('\n').enumerate() {
        if i > 0 {
            out.push('\n');
        }
        let frame = line.trim_start();
        let b = frame.as_bytes();
        let absolute = frame.starts_with('/')
            || frame.starts_with("...")
            || frame.starts_with("\\\\")
            || (b.len() > 2 && b[0].is_ascii_alphabetic() && b[1] == b':' && (b[2] == b'\\' || b[2] == b'/'));
        if after && absolute {
            out.push('\t');
            out.push_str(&crate::msg!("script-lab-frame"));
        } else {
            out.push_str(line);
        }
        after |= line == "stack traceback:";
    }
    out
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
    wrap_io(lua, &io, rules.clone())?;
    // Where the run may write: `plcsh.write_dir` (nil without one).
    let p: Table = g.get("plcsh")?;
    p.set("write_dir", rules.write.as_ref().map(|d| d.display().to_string()))?;
    install_loaders(lua, &g, rules)?;
    Ok(())
}

/// Lua's own file functions (`io.open`, `io.lines`, `io.input`, `io.output`), kept in the
/// registry the first time (no script reaches them there), set in `io` checked against `rules`.
fn wrap_io(lua: &Lua, io: &Table, rules: Arc<Confinement>) -> mlua::Result<()> {
    let raw = |name: &str| -> mlua::Result<mlua::Function> {
        let key = format!("plcsh.sandbox.raw_io_{name}");
        if let Ok(f) = lua.named_registry_value::<mlua::Function>(&key) {
            return Ok(f);
        }
        let f: mlua::Function = io.get(name)?;
        lua.set_named_registry_value(&key, f.clone())?;
        Ok(f)
    };
    let open = raw("open")?;
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
        let f = raw(name)?;
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
            raise_at(lua, Error::unsupported(crate::msg!("script-sandbox-terminal", function = "loadfile")))
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
            raise_at(lua, Error::unsupported(crate::msg!("script-sandbox-terminal", function = "dofile")))
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
    // getmetatable: a table's, and a string's as stock Lua gives it (its `__metatable` field:
    // `false`, the string metatable being protected), never a device's (shared with the
    // grader). One value, always, as Lua's own returns: `type(getmetatable(1))` is "nil".
    let gm: mlua::Function = lua
        .load("local gm, type = getmetatable, type\nreturn function(o) local t = type(o); if t == 'table' or t == 'string' then return gm(o) end; return nil end")
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

/// What a graded submission's `require` finds, and nothing else: a folder submission's own
/// modules (`NAME/main.lua` requires `NAME/util.lua`), the modules the lab shares
/// (`shared = ["helpers.lua"]` in its `lab.toml`) and plcsh's built-in modules. Each is loaded
/// afresh for the submission, in its environment: never the grader's table.
#[derive(Clone, Debug, Default)]
pub struct World {
    /// A folder submission's folder: (resolved, as messages name it).
    pub own: Option<(PathBuf, String)>,
    /// The lab's shared modules: (module name, file, as messages name it).
    pub shared: Vec<(String, PathBuf, String)>,
}

/// A module name `require` looks for as a file: letters (any alphabet's: `модуль`), digits,
/// `_` and `-` between dots — never a path separator, `..`, a drive or a control character.
fn module_name_ok(name: &str) -> bool {
    name.len() <= 200
        && name.split('.').all(|p| !p.is_empty() && p.chars().all(|c| c.is_alphanumeric() || c == '_' || c == '-'))
}

impl World {
    /// The module's text, its chunk name and how messages name its file.
    fn find(&self, name: &str) -> Option<(Vec<u8>, String)> {
        if module_name_ok(name) {
            if let Some((dir, shown)) = &self.own {
                let rel = name.replace('.', "/");
                for cand in [format!("{rel}.lua"), format!("{rel}/init.lua")] {
                    let file = dir.join(&cand);
                    let Ok(real) = crate::core::fspath::canonical(&file) else { continue };
                    if !real.starts_with(dir) || !real.is_file() {
                        continue;
                    }
                    // Never through a link: the module is the submission's own file.
                    if let Ok(code) = crate::core::platform::read_no_follow(&file, 16 << 20) {
                        let sep = if shown.is_empty() || shown.ends_with(['/', '\\']) { "" } else { "/" };
                        return Some((code, format!("{shown}{sep}{cand}")));
                    }
                }
            }
        }
        if let Some((_, file, shown)) = self.shared.iter().find(|(n, _, _)| n == name) {
            return std::fs::read(file).ok().map(|code| (code, shown.clone()));
        }
        super::paths::BUILT_IN
            .iter()
            .find(|(n, _)| *n == name)
            .map(|(_, code)| (code.as_bytes().to_vec(), format!("plcsh:lib/{name}.lua")))
    }

    /// Why `name` was not found, naming only what the submission may see.
    fn not_found(&self, name: &str) -> crate::core::msg::Msg {
        let names: Vec<&str> = self.shared.iter().map(|(n, _, _)| n.as_str()).collect();
        crate::msg!(
            "script-module-not-found",
            name = name,
            own = if self.own.is_some() { "folder" } else { "single" },
            path = name.replace('.', "/"),
            shared = if names.is_empty() { "none" } else { "some" },
            modules = names.join(", "),
        )
    }
}

/// A Lua file's text as a submission's or grader's chunk: UTF-16 (Notepad's "Unicode") read by
/// the IL files' rule ([`crate::core::encoding`]) as UTF-8, any other bytes as they are (Lua's
/// strings are bytes: a Windows-1251 file's strings stay as written), without a UTF-8
/// byte-order mark or a `#!` line ([`super::file_chunk`]).
pub fn lua_text(code: Vec<u8>) -> Result<Vec<u8>, String> {
    use crate::core::encoding::{decode, Encoding};
    let utf16 = code.starts_with(b"\xFF\xFE") || code.starts_with(b"\xFE\xFF") || code.contains(&0);
    let code = if utf16 {
        match decode(&code) {
            Ok((text, Encoding::Utf16Le | Encoding::Utf16Be)) => text.into_bytes(),
            Ok(_) => code,
            Err(e) => return Err(e.replace("save the file as UTF-8", "save it as UTF-8")),
        }
    } else {
        code
    };
    Ok(super::file_chunk(&code).to_vec())
}

/// `require` for a submission's environment `env` (see [`World`]).
fn submission_require(lua: &Lua, env: &Table, world: World) -> mlua::Result<mlua::Function> {
    let loaded = lua.create_table()?;
    let loading = Arc::new(std::sync::Mutex::new(Vec::<String>::new()));
    let env = env.clone();
    lua.create_function(move |lua, name: Value| -> mlua::Result<MultiValue> {
        let name = match &name {
            Value::String(s) => s.to_string_lossy(),
            Value::Integer(_) | Value::Number(_) => {
                lua.coerce_string(name.clone())?.map(|s| s.to_string_lossy()).unwrap_or_default()
            }
            other => {
                return Err(raise_at(
                    lua,
                    Error::usage(crate::msg!("script-require-not-string", kind = other.type_name())),
                ))
            }
        };
        let done: Value = loaded.raw_get(name.as_str())?;
        if !done.is_nil() {
            return Ok(MultiValue::from_iter([done]));
        }
        if loading.lock().unwrap_or_else(|p| p.into_inner()).contains(&name) {
            return Err(raise_at(lua, Error::usage(crate::msg!("script-require-loop", name = name.as_str()))));
        }
        let Some((code, shown)) = world.find(&name) else {
            return Err(raise_at(lua, Error::usage(world.not_found(&name)).hint(crate::msg!("script-hint-require"))));
        };
        let code = lua_text(code)
            .map_err(|why| raise_at(lua, Error::usage(format!("error loading module '{name}' from {shown}: {why}"))))?;
        let f = lua
            .load(code)
            .set_name(format!("@{shown}"))
            .set_mode(mlua::chunk::ChunkMode::Text)
            .set_environment(env.clone())
            .into_function()
            .map_err(|e| mlua::Error::runtime(format!("error loading module '{name}' from {shown}:\n\t{e}")))?;
        loading.lock().unwrap_or_else(|p| p.into_inner()).push(name.clone());
        let r = f.call::<Value>((name.as_str(), shown.as_str()));
        loading.lock().unwrap_or_else(|p| p.into_inner()).retain(|n| n != &name);
        let v = match r? {
            Value::Nil => Value::Boolean(true),
            v => v,
        };
        loaded.raw_set(name.as_str(), v.clone())?;
        Ok(MultiValue::from_iter([v, Value::String(lua.create_string(&shown)?)]))
    })
}

/// A graded submission's environment: [`student_env`] with Lua's file functions checked
/// against the submission's own `rules` (its files, the lab's shared and starter files, the
/// write directory: never the grader's), the `require` of [`World`], no `__gc` finalizers
/// (a finalizer runs where no instruction is counted), and `pcall`, `xpcall`,
/// `coroutine.resume` and `coroutine.close` that give back no limit: `stop(err)` says whether
/// the run is over (it notes a memory error as the memory limit) and the verdict is raised
/// again.
pub fn submission_env(lua: &Lua, rules: Arc<Confinement>, world: World, stop: mlua::Function) -> mlua::Result<Table> {
    let env = student_env(lua, rules.clone())?;
    let io: Table = env.raw_get("io")?;
    wrap_io(lua, &io, rules)?;
    env.raw_set("require", submission_require(lua, &env, world)?)?;
    // The lab's folder is not the submission's to know: not in `plcsh.lib_dirs`, not in a
    // traceback's frames.
    let debug: Table = env.raw_get("debug")?;
    let traceback: mlua::Function = debug.raw_get("traceback")?;
    debug.raw_set(
        "traceback",
        lua.create_function(move |lua, args: MultiValue| match traceback.call::<Value>(args)? {
            Value::String(t) => Ok(Value::String(lua.create_string(no_folders(&t.to_string_lossy()))?)),
            other => Ok(other),
        })?,
    )?;
    let p: Table = env.raw_get("plcsh")?;
    p.raw_set("lib_dirs", lua.create_table()?)?;
    hold_limits(lua, &env, &stop)?;
    // A `__close` metamethod runs as the submission, and it cannot hide a limit: the error
    // it is closed with goes to `stop` first (a "not enough memory" is the memory limit for
    // good), whatever the handler then raises in its place — Lua 5.4 lets it replace the
    // error. Set through `setmetatable`, assigned later to a metatable (the sandbox keeps a
    // watch on each: a `__newindex` of its own) or `rawset`.
    let (setmt, rawset): (mlua::Function, mlua::Function) = lua
        .load(
            r#"
local setmetatable, getmetatable, error, rawget, rawset, type, stop = ...
local watched = setmetatable({}, { __mode = "k" })
local function guarded(f)
  if type(f) ~= "function" then return f end
  return function(o, e, ...)
    if e ~= nil then
      local v = stop(e)
      if v then error(v, 0) end
    end
    return f(o, e, ...)
  end
end
local watch = {
  __newindex = function(t, k, v)
    if k == "__close" then v = guarded(v) end
    rawset(t, k, v)
  end,
  __metatable = false,
}
local function setmt(t, mt)
  if type(mt) == "table" then
    if rawget(mt, "__gc") ~= nil then
      error("setmetatable: a __gc finalizer is not available in a graded run (finalizers run outside the instruction count)", 2)
    end
    if not watched[mt] then
      local c = rawget(mt, "__close")
      if c ~= nil then rawset(mt, "__close", guarded(c)) end
      -- A metatable with a metatable of its own (inheritance: `{__index = Base}`) keeps it;
      -- its `__close` is guarded now and through `rawset`.
      if getmetatable(mt) == nil then setmetatable(mt, watch) end
      watched[mt] = true
    end
  end
  return setmetatable(t, mt)
end
local function rawset_(t, k, v)
  if k == "__close" and watched[t] then v = guarded(v) end
  return rawset(t, k, v)
end
return setmt, rawset_
"#,
        )
        .set_name("=sandbox")
        .call((
            env.raw_get::<Value>("setmetatable")?,
            lua.globals().raw_get::<Value>("getmetatable")?,
            env.raw_get::<Value>("error")?,
            env.raw_get::<Value>("rawget")?,
            env.raw_get::<Value>("rawset")?,
            env.raw_get::<Value>("type")?,
            stop,
        ))?;
    env.raw_set("setmetatable", setmt)?;
    env.raw_set("rawset", rawset)?;
    Ok(env)
}

/// `pcall`, `xpcall`, `coroutine.resume`, `coroutine.close` and `load` in `t` (the globals,
/// or a submission's environment) that give back no limit: when one of them would return an
/// error, `stop(err)` says whether the run is over (it notes a "not enough memory" as the
/// memory limit) and then the verdict is raised again instead.
pub fn hold_limits(lua: &Lua, t: &Table, stop: &mlua::Function) -> mlua::Result<()> {
    let co: Table = t.raw_get("coroutine")?;
    let (pcall, xpcall, resume, close, load): (Value, Value, Value, Value, Value) = lua
        .load(
            r#"
local pcall, xpcall, resume, close, load, stop, error = ...
local function pass(ok, ...)
  if not ok then
    local v = stop((...))
    if v then error(v, 0) end
  end
  return ok, ...
end
local function loaded(f, ...)
  if f == nil then
    local v = stop((...))
    if v then error(v, 0) end
  end
  return f, ...
end
return function(f, ...) return pass(pcall(f, ...)) end,
  function(f, h, ...)
    return pass(xpcall(f, function(e) local v = stop(e); if v then return v end; return h(e) end, ...))
  end,
  function(c, ...) return pass(resume(c, ...)) end,
  function(c) return pass(close(c)) end,
  load and function(...) return loaded(load(...)) end
"#,
        )
        .set_name("=sandbox")
        .call((
            t.raw_get::<Value>("pcall")?,
            t.raw_get::<Value>("xpcall")?,
            co.raw_get::<Value>("resume")?,
            co.raw_get::<Value>("close")?,
            t.raw_get::<Value>("load")?,
            stop.clone(),
            t.raw_get::<Value>("error")?,
        ))?;
    t.raw_set("pcall", pcall)?;
    t.raw_set("xpcall", xpcall)?;
    co.raw_set("resume", resume)?;
    co.raw_set("close", close)?;
    if !load.is_nil() {
        t.raw_set("load", load)?;
    }
    Ok(())
}

/// 2026-01-01 00:00:00 UTC: what `os.time()` reads at simulated time zero in a graded run.
pub const EPOCH: i64 = 1_767_225_600;

/// Simulated nanoseconds per Lua instruction in `os.clock()`: a busy loop advances it.
const NS_PER_INSTRUCTION: f64 = 10.0;

/// Days from 1970-01-01 to `y-m-d` (the proleptic Gregorian calendar; `m` and `d` may be out
/// of range and carry over, as C's `mktime` does).
fn days_from_civil(y: i64, m: i64, d: i64) -> i64 {
    let y = y + (m - 1).div_euclid(12);
    let m = (m - 1).rem_euclid(12) + 1;
    let y = if m <= 2 { y - 1 } else { y };
    let era = y.div_euclid(400);
    let yoe = y - era * 400;
    let mp = (m + 9) % 12;
    let doy = (153 * mp + 2) / 5;
    let doe = yoe * 365 + yoe / 4 - yoe / 100 + doy;
    era * 146_097 + doe - 719_468 + (d - 1)
}

/// The same graded run gives the same bytes on every machine: `os.time`, `os.clock` and
/// `os.date` read simulated time (UTC, from [`EPOCH`]; `os.clock` adds a figure from the Lua
/// instructions run, so a busy loop advances it), `math.random` starts from `seed` and
/// `math.randomseed()` without a number starts there again, and `tostring`, `print` and
/// `string.format` show no memory address (`table`, `function`; `%p` is refused). Set in the
/// globals, before a submission's environment copies them.
pub fn deterministic(
    lua: &Lua,
    clock: crate::core::Clock,
    budget: Arc<crate::core::budget::Budget>,
    seed: i64,
) -> mlua::Result<()> {
    let g = lua.globals();
    let os: Table = g.get("os")?;
    let start = budget.start;
    let now_s = {
        let clock = clock.clone();
        move || clock.now().saturating_sub(start).as_secs_f64()
    };
    let n = now_s.clone();
    os.set(
        "time",
        lua.create_function(move |lua, t: Option<Table>| -> mlua::Result<i64> {
            let Some(t) = t else { return Ok(EPOCH + n().floor() as i64) };
            let field = |k: &str, default: Option<i64>| -> mlua::Result<i64> {
                match (t.get::<Option<f64>>(k)?, default) {
                    (Some(v), _) => Ok(v.floor() as i64),
                    (None, Some(d)) => Ok(d),
                    (None, None) => {
                        Err(raise_at(lua, Error::usage(crate::msg!("script-date-field-missing", field = k))))
                    }
                }
            };
            let days = days_from_civil(field("year", None)?, field("month", None)?, field("day", None)?);
            Ok(days * 86_400 + field("hour", Some(12))? * 3600 + field("min", Some(0))? * 60 + field("sec", Some(0))?)
        })?,
    )?;
    let b = budget.clone();
    let n = now_s.clone();
    os.set(
        "clock",
        lua.create_function(move |_, ()| Ok(n() + b.instructions_used() as f64 * NS_PER_INSTRUCTION * 1e-9))?,
    )?;
    let raw_date: mlua::Function = os.get("date")?;
    let n = now_s;
    os.set(
        "date",
        lua.create_function(move |lua, (fmt, t): (Option<String>, Option<f64>)| {
            let fmt = fmt.unwrap_or_else(|| "%c".into());
            let fmt = if fmt.starts_with('!') { fmt } else { format!("!{fmt}") };
            let t = t.map_or_else(|| EPOCH + n().floor() as i64, |t| t.floor() as i64);
            raw_date.call::<Value>((lua.create_string(&fmt)?, t))
        })?,
    )?;
    // math.random from the seed; math.randomseed() without a number starts there again.
    let math: Table = g.get("math")?;
    let raw_seed: mlua::Function = math.get("randomseed")?;
    raw_seed.call::<()>((seed, 0))?;
    math.set(
        "randomseed",
        lua.create_function(move |_, args: MultiValue| {
            if args.is_empty() {
                raw_seed.call::<MultiValue>((seed, 0))
            } else {
                raw_seed.call::<MultiValue>(args)
            }
        })?,
    )?;
    let string: Table = g.get("string")?;
    let (tostring, print, format): (Value, Value, Value) = lua
        .load(
            r##"
local tostring, print, format, type, select, gsub, find, error, unpack = ...
local function safe(v)
  local s = tostring(v)
  local t = type(v)
  if t == "table" or t == "function" or t == "thread" or t == "userdata" then
    s = gsub(s, ": 0x%x+$", "")
    s = gsub(s, ": %x%x%x%x%x%x%x%x+$", "")
  end
  return s
end
local function print_(...)
  local a, n = { ... }, select("#", ...)
  for i = 1, n do
    if type(a[i]) ~= "table" then a[i] = safe(a[i]) end
  end
  return print(unpack(a, 1, n))
end
local function format_(fmt, ...)
  if type(fmt) == "string" and find((gsub(fmt, "%%%%", "")), "%%[-+ #0]*%d*%.?%d*p") then
    error("string.format: %p (an address) is not available in a graded run", 2)
  end
  local a, n = { ... }, select("#", ...)
  for i = 1, n do
    local t = type(a[i])
    if t == "table" or t == "function" or t == "thread" or t == "userdata" then a[i] = safe(a[i]) end
  end
  return format(fmt, unpack(a, 1, n))
end
return safe, print_, format_
"##,
        )
        .set_name("=sandbox")
        .call((
            g.get::<Value>("tostring")?,
            g.get::<Value>("print")?,
            string.get::<Value>("format")?,
            g.get::<Value>("type")?,
            g.get::<Value>("select")?,
            string.get::<Value>("gsub")?,
            string.get::<Value>("find")?,
            g.get::<Value>("error")?,
            g.get::<Table>("table")?.get::<Value>("unpack")?,
        ))?;
    g.set("tostring", tostring)?;
    g.set("print", print)?;
    string.set("format", format)?;
    // plcsh.show (and print of a table, which shows it) took Lua's own `tostring` when the
    // prelude loaded: what it writes loses its addresses here.
    let p: Table = g.get("plcsh")?;
    let show: mlua::Function = lua
        .load(
            r##"
local show, gsub, ipairs = ...
local names = { "table", "function", "thread", "userdata" }
return function(...)
  local s = show(...)
  for _, n in ipairs(names) do
    s = gsub(s, n .. ": builtin: 0x%x+", n)
    s = gsub(s, n .. ": builtin: %x%x%x%x%x%x%x%x+", n)
    s = gsub(s, n .. ": 0x%x+", n)
    s = gsub(s, n .. ": %x%x%x%x%x%x%x%x+", n)
  end
  return s
end
"##,
        )
        .set_name("=sandbox")
        .call((p.get::<Value>("show")?, string.get::<Value>("gsub")?, g.get::<Value>("ipairs")?))?;
    p.set("show", show.clone())?;
    let print_tables: mlua::Function = lua
        .load(
            r##"
local print, show, type, select, getmetatable, rawget, unpack, out, pcall = ...
return function(...)
  -- What io.write left in the C library's buffer goes out first: output stays in order.
  pcall(out.flush, out)
  local a, n = { ... }, select("#", ...)
  for i = 1, n do
    local mt = type(a[i]) == "table" and getmetatable(a[i])
    if type(a[i]) == "table" and not (type(mt) == "table" and rawget(mt, "__tostring")) then a[i] = show(a[i]) end
  end
  return print(unpack(a, 1, n))
end
"##,
        )
        .set_name("=sandbox")
        .call((
            g.get::<Value>("print")?,
            show,
            g.get::<Value>("type")?,
            g.get::<Value>("select")?,
            g.get::<Value>("getmetatable")?,
            g.get::<Value>("rawget")?,
            g.get::<Table>("table")?.get::<Value>("unpack")?,
            g.get::<Table>("io")?.get::<Value>("stdout")?,
            g.get::<Value>("pcall")?,
        ))?;
    g.set("print", print_tables)?;
    // One locale: the C library's "C" (a decimal point, not a comma). Asking for another
    // fails as stock Lua's does on a system without it (nil), so `tostring(0.5)` reads
    // `0.5` on every machine whatever the teacher's locale.
    os.set(
        "setlocale",
        lua.create_function(|lua, (loc, _cat): (Option<mlua::LuaString>, Option<String>)| {
            Ok(match loc {
                None => Some(lua.create_string("C")?),
                Some(l) if matches!(&*l.as_bytes(), b"C" | b"POSIX" | b"") => Some(lua.create_string("C")?),
                Some(_) => None,
            })
        })?,
    )?;
    charge_for_bytes(lua, &clock, &budget)?;
    Ok(())
}

/// Bytes a C function of Lua's may produce for one counted instruction: copying memory costs
/// about this much per byte as one instruction of the interpreter, so work done inside
/// `string.rep` or `table.concat` counts like the loop that would make it.
pub const BYTES_PER_INSTRUCTION: usize = 16;

/// The string functions that make large results (`string.rep`, `string.format`,
/// `string.gsub`, `table.concat`, `string.upper`, `string.lower`, `string.reverse`) charge the
/// instruction budget by the bytes they produce, so a run's verdict does not depend on the
/// machine's speed; `string.rep` is refused before it allocates past the memory limit (a
/// `<close>` handler cannot then turn the memory limit into a plain error). Concatenation
/// with `..` is the interpreter's own and counts one instruction.
fn charge_for_bytes(
    lua: &Lua,
    clock: &crate::core::Clock,
    budget: &Arc<crate::core::budget::Budget>,
) -> mlua::Result<()> {
    use crate::core::ErrorKind;
    let charge = {
        let (clock, budget) = (clock.clone(), budget.clone());
        move |bytes: usize| -> mlua::Result<()> {
            let n = (bytes / BYTES_PER_INSTRUCTION) as u64;
            if n == 0 {
                return Ok(());
            }
            match budget.tick(n, &clock) {
                Some(v) => Err(super::error::raise(Error::new(ErrorKind::Interrupted, v))),
                None => Ok(()),
            }
        }
    };
    let size = |v: &MultiValue| -> usize {
        v.iter().map(|x| if let Value::String(s) = x { s.as_bytes().len() } else { 0 }).sum()
    };
    let g = lua.globals();
    for (lib, name) in [
        ("string", "format"),
        ("string", "gsub"),
        ("string", "upper"),
        ("string", "lower"),
        ("string", "reverse"),
        ("table", "concat"),
    ] {
        let t: Table = g.get(lib)?;
        let raw: mlua::Function = t.get(name)?;
        let charge = charge.clone();
        let b = budget.clone();
        t.set(
            name,
            lua.create_function(move |lua, args: MultiValue| {
                // table.concat's result is its items' bytes (and the separators'): refused
                // before it would allocate past the memory limit, as string.rep is.
                if name == "concat" {
                    if let (Some(Value::Table(items)), Some(limit)) = (args.front(), b.memory) {
                        let sep = match args.get(1) {
                            Some(Value::String(s)) => s.as_bytes().len(),
                            _ => 0,
                        };
                        let mut bytes = 0usize;
                        for v in items.clone().sequence_values::<Value>().flatten() {
                            bytes = bytes.saturating_add(match v {
                                Value::String(s) => s.as_bytes().len() + sep,
                                _ => 24 + sep,
                            });
                        }
                        if bytes > limit.saturating_sub(lua.used_memory()) {
                            b.exceed_memory();
                            let v = b.exceeded().unwrap_or_default();
                            return Err(super::error::raise(Error::new(ErrorKind::Interrupted, v)));
                        }
                    }
                }
                let r = raw.call::<MultiValue>(args)?;
                charge(size(&r))?;
                Ok(r)
            })?,
        )?;
    }
    let string: Table = g.get("string")?;
    let raw_rep: mlua::Function = string.get("rep")?;
    let b = budget.clone();
    string.set(
        "rep",
        lua.create_function(move |lua, args: MultiValue| {
            let len = |i: usize| match args.get(i) {
                Some(Value::String(s)) => s.as_bytes().len() as f64,
                Some(Value::Integer(n)) => n.to_string().len() as f64,
                Some(Value::Number(n)) => format!("{n}").len() as f64,
                _ => 0.0,
            };
            let n = match args.get(1) {
                Some(Value::Integer(n)) => *n as f64,
                Some(Value::Number(n)) => *n,
                _ => 0.0,
            };
            if n > 0.0 {
                let bytes = len(0) * n + len(2) * (n - 1.0);
                if let Some(limit) = b.memory {
                    if bytes > limit.saturating_sub(lua.used_memory()) as f64 {
                        b.exceed_memory();
                        let v = b.exceeded().unwrap_or_default();
                        return Err(super::error::raise(Error::new(ErrorKind::Interrupted, v)));
                    }
                }
            }
            let r = raw_rep.call::<MultiValue>(args)?;
            charge(size(&r))?;
            Ok(r)
        })?,
    )?;
    Ok(())
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn module_names_take_any_alphabet_and_never_a_path() {
        for ok in ["mine", "pkg.util", "модуль", "модуль.часть", "a-b_c2"] {
            assert!(module_name_ok(ok), "{ok}");
        }
        for bad in ["../lab/reference", "a/b", "a\\b", "..", "a..b", "", "C:x", "a\u{0}b", "x y"] {
            assert!(!module_name_ok(bad), "{bad:?}");
        }
    }

    #[test]
    fn utf16_lua_text_loads_as_utf8_and_a_cut_one_is_refused() {
        let mut le = vec![0xFF, 0xFE];
        le.extend("x = \"Привет\"\n".encode_utf16().flat_map(|u| u.to_le_bytes()));
        assert_eq!(lua_text(le).unwrap(), "x = \"Привет\"\n".as_bytes());
        let mut cut = vec![0xFE, 0xFF];
        cut.extend("x = 1\n".encode_utf16().flat_map(|u| u.to_be_bytes()));
        cut.push(0);
        assert!(lua_text(cut).unwrap_err().contains("save it as UTF-8"));
        // Windows-1251 bytes stay as written (Lua's strings are bytes).
        let cp = b"s = \"\xcf\xf0\xe8\xe2\xe5\xf2\"\n".to_vec();
        assert_eq!(lua_text(cp.clone()).unwrap(), cp);
    }

    #[test]
    fn a_traceback_shows_no_absolute_folder() {
        let t = "here\nstack traceback:\n\t[C]: in ?\n\tsubs/a.lua:2: in main chunk\n\t/home/t/labs/l1/grade.lua:5: in main chunk\n\t...abs/l1/grade.lua:5: in x\n\tC:\\Users\\t\\g.lua:1: in y";
        let s = no_folders(t);
        assert!(
            s.contains("subs/a.lua:2") && !s.contains("/home/") && !s.contains("Users") && !s.contains("...abs"),
            "{s}"
        );
        assert_eq!(s.matches("(a frame of the lab's)").count(), 3, "{s}");
    }
}
