//! The `plcsh` table: the command language (`plcsh.exec`), time (`sleep`, `now`,
//! `wait_until`), abort handlers, JSON, tables and printing through the shell's output.
//!
//! While a chunk runs, the shell (and with it the session) lives in the Lua state's app
//! data (see `script::Engine`); every function here borrows it for the length of one Rust
//! call and never while Lua code runs, so Lua callbacks can nest freely.

use super::error::{facing, raise, raise_cmd};
use crate::core::{Error, ErrorKind};
use crate::output::{self, Outcome};
use crate::shell::Shell;
use mlua::serde::SerializeOptions;
use mlua::{Function, Lua, LuaSerdeExt, MultiValue, Table, Value};
use std::io::Write;
use std::sync::atomic::{AtomicBool, Ordering};
use std::sync::Arc;
use std::time::Duration;

/// Where `print` and `plcsh.table` write: the shell's output (stdout, or a buffer in tests).
pub struct Sink(pub Box<dyn Write + Send>);

/// Registry key of the list of `plcsh.on_abort` handlers.
pub const ABORT_KEY: &str = "plcsh.on_abort";

/// Runs `f` with the shell the running chunk works on.
pub fn with_shell<R>(lua: &Lua, f: impl FnOnce(&mut Shell) -> crate::core::Result<R>) -> mlua::Result<R> {
    let mut sh = lua
        .try_app_data_mut::<Shell>()
        .map_err(|e| raise(Error::state(crate::msg!("script-session-busy", error = e.to_string()))))?
        .ok_or_else(|| raise(Error::state(crate::msg!("script-no-session"))))?;
    let r = f(&mut sh);
    drop(sh);
    r.map_err(|e| super::error::raise_at(lua, e))
}

/// The session index of device `name`, with an error a script user understands.
pub fn index(sh: &Shell, name: &str) -> crate::core::Result<usize> {
    sh.session.index(name).map_err(|e| {
        let mut err = Error::state(crate::msg!("script-device-not-open", device = name)).device(name);
        err.hint = e.hint.clone();
        err
    })
}

/// The interrupt flag (Ctrl-C) of the session.
pub fn interrupt_flag(lua: &Lua) -> mlua::Result<Arc<AtomicBool>> {
    with_shell(lua, |sh| Ok(sh.session.interrupt.clone()))
}

pub fn interrupted_error() -> Error {
    Error::new(ErrorKind::Interrupted, format!("interrupted ({})", crate::signals::cause()))
}

/// JSON → Lua (tables for objects and arrays; JSON null becomes nil).
pub fn json_to_lua(lua: &Lua, v: &serde_json::Value) -> mlua::Result<Value> {
    lua.to_value_with(v, SerializeOptions::new().serialize_none_to_null(false).serialize_unit_to_null(false))
}

/// Runs shell `line` (on device `device`, made current for the call) and returns one table
/// per command; a failed command raises its error.
/// Text of several lines runs line by line, in order, as a pasted block does in the REPL.
pub fn exec_on(lua: &Lua, device: Option<&str>, line: &str) -> mlua::Result<MultiValue> {
    let stop = interrupt_flag(lua)?;
    if stop.load(Ordering::Relaxed) {
        return Err(raise(interrupted_error()));
    }
    let results = with_shell(lua, |sh| {
        let back = sh.session.current_name().map(str::to_string);
        if let Some(d) = device {
            index(sh, d)?;
            sh.session.use_device(d)?;
        }
        let mut r = Vec::new();
        for l in line.lines().filter(|l| !l.trim().is_empty() && !l.trim_start().starts_with('#')) {
            r.extend(sh.exec(l));
            if r.last().is_some_and(|x| x.is_err()) {
                break;
            }
        }
        if let (Some(_), Some(b)) = (device, back) {
            let _ = sh.session.use_device(&b);
        }
        Ok(r)
    })?;
    let mut out = MultiValue::new();
    for r in results {
        match r {
            Ok(o) => out.push_back(json_to_lua(lua, &o.to_json())?),
            Err((cmd, e)) => {
                if e.kind == ErrorKind::Interrupted {
                    // The command saw Ctrl-C (and cleared the flag): keep the script aborting.
                    stop.store(true, Ordering::Relaxed);
                }
                return Err(raise_cmd(&cmd, e));
            }
        }
    }
    Ok(out)
}

/// Writes an outcome through the shell's output (honouring `--json`).
pub fn show(lua: &Lua, o: &Outcome) -> mlua::Result<()> {
    let style = with_shell(lua, |sh| Ok(sh.style))?;
    let mut sink = lua.app_data_mut::<Sink>().ok_or_else(|| raise(Error::state(crate::msg!("script-no-output"))))?;
    output::write_outcome(&mut *sink.0, style, o).and_then(|_| sink.0.flush()).map_err(|e| raise(e.into()))
}

/// `print`'s line: Lua's bytes as stock Lua writes them, whatever their encoding (a CP1251
/// line a script read from a CSV file prints as those bytes, as `lua` prints it). Under
/// `--json` the line is a JSON string, so bytes that are not UTF-8 become U+FFFD there; and
/// where the output refuses bytes that are not UTF-8 (a Windows console through Rust's
/// standard output), the line is written the same way rather than lost.
fn print_bytes(lua: &Lua, bytes: &[u8]) -> mlua::Result<()> {
    if let Ok(text) = std::str::from_utf8(bytes) {
        return show(lua, &Outcome::new("print").text(text));
    }
    let lossy = || Outcome::new("print").text(String::from_utf8_lossy(bytes));
    if with_shell(lua, |sh| Ok(sh.style.json))? {
        return show(lua, &lossy());
    }
    let mut sink = lua.app_data_mut::<Sink>().ok_or_else(|| raise(Error::state(crate::msg!("script-no-output"))))?;
    let mut line = bytes.to_vec();
    line.push(b'\n');
    match sink.0.write_all(&line).and_then(|_| sink.0.flush()) {
        Err(e) if e.kind() == std::io::ErrorKind::InvalidData => {
            drop(sink);
            show(lua, &lossy())
        }
        r => r.map_err(|e| raise(e.into())),
    }
}

fn millis(ms: f64, what: &str) -> mlua::Result<Duration> {
    if !ms.is_finite() || ms < 0.0 {
        return Err(raise(Error::usage(crate::msg!("script-bad-millis", what = what, ms = ms.to_string()))));
    }
    Ok(Duration::from_secs_f64(ms / 1000.0))
}

/// Waits `d` of virtual time (instantly when the clock is stepped); raises on Ctrl-C.
fn sleep(lua: &Lua, d: Duration) -> mlua::Result<()> {
    // Session::sleep: real time when a device on a wire is open, even in stepped time.
    let ok = with_shell(lua, |sh| Ok(!sh.session.interrupted() && sh.session.sleep(d)))?;
    if !ok {
        return Err(raise(interrupted_error()));
    }
    Ok(())
}

fn now(lua: &Lua) -> mlua::Result<Duration> {
    with_shell(lua, |sh| Ok(sh.session.clock.now()))
}

fn truthy(v: &Value) -> bool {
    !matches!(v, Value::Nil | Value::Boolean(false))
}

/// Refuses a table JSON cannot hold without losing data: a sparse list (`{1, nil, 3}`) or one
/// mixing list items and keys (`{1, 2, x=3}`) — serde would drop or reorder them silently.
/// How deep `plcsh.json.encode` follows nested tables: deeper (or a table that holds itself)
/// is an error, never a stack overflow.
pub const JSON_DEPTH: usize = 128;

fn json_shape(lua: &Lua, v: &Value, path: &mut String) -> mlua::Result<()> {
    json_shape_at(lua, v, path, 0)
}

fn json_shape_at(lua: &Lua, v: &Value, path: &mut String, depth: usize) -> mlua::Result<()> {
    let Value::Table(t) = v else { return Ok(()) };
    if depth >= JSON_DEPTH {
        return Err(super::error::raise_at(
            lua,
            Error::new(ErrorKind::Value, crate::msg!("script-json-too-deep", depth = JSON_DEPTH))
                .hint(crate::msg!("script-hint-json-tree")),
        ));
    }
    let (mut ints, mut max, mut others) = (0usize, 0i64, 0usize);
    for pair in t.clone().pairs::<Value, Value>() {
        let (k, _) = pair?;
        match k {
            Value::Integer(i) if i >= 1 => {
                ints += 1;
                max = max.max(i);
            }
            _ => others += 1,
        }
    }
    let refuse = |msg: crate::core::msg::Msg| {
        Err(super::error::raise_at(lua, Error::new(ErrorKind::Value, msg).hint(crate::msg!("script-hint-json-split"))))
    };
    if ints > 0 && others > 0 {
        return refuse(crate::msg!("script-json-mixed", path = path.as_str()));
    }
    if ints > 0 && max as usize != ints {
        return refuse(crate::msg!("script-json-sparse", path = path.as_str(), items = ints, max = max));
    }
    for pair in t.clone().pairs::<Value, Value>() {
        let (k, item) = pair?;
        let len = path.len();
        match &k {
            _ if len > 200 => {}
            Value::Integer(i) => path.push_str(&format!("[{i}]")),
            Value::String(s) => path.push_str(&format!(".{}", s.to_string_lossy())),
            _ => path.push_str("[?]"),
        }
        // The path names the first levels only (it would grow with the square of the depth).
        json_shape_at(lua, &item, path, depth + 1)?;
        path.truncate(len);
    }
    Ok(())
}

/// Refuses keys of an options table that `what` does not know (`{timout=50}` would otherwise
/// be ignored and wait for ever), naming the nearest known key — as shell commands do.
pub fn check_keys(lua: &Lua, t: &Table, known: &[&str], what: &str) -> mlua::Result<()> {
    for pair in t.clone().pairs::<Value, Value>() {
        let (k, _) = pair?;
        let key = match &k {
            Value::String(s) => s.to_string_lossy(),
            other => format!("[{}]", other.type_name()),
        };
        if known.contains(&key.as_str()) {
            continue;
        }
        let near = known.iter().map(|c| (crate::core::text::edit_distance(&key, c), *c)).min();
        let hint = match near {
            Some((d, c)) if d <= 2 => {
                crate::msg!("script-hint-did-you-mean-option", near = c, what = what, options = known.join(", "))
            }
            _ => crate::msg!("script-hint-options", what = what, options = known.join(", ")),
        };
        return Err(super::error::raise_at(
            lua,
            Error::usage(crate::msg!("script-unknown-option", what = what, key = key.as_str())).hint(hint),
        ));
    }
    Ok(())
}

/// `plcsh.wait_until(fn, {timeout=ms, every=ms, what="…"})` (or a number: the timeout).
fn wait_until(lua: &Lua, (f, opts): (Function, Value)) -> mlua::Result<Value> {
    let (mut timeout, mut every, mut what) = (None, Duration::from_millis(10), None::<String>);
    match &opts {
        Value::Nil => {}
        Value::Integer(_) | Value::Number(_) => timeout = Some(millis(lua.unpack(opts.clone())?, "timeout")?),
        Value::Table(t) => {
            check_keys(lua, t, &["timeout", "every", "what"], "wait_until")?;
            if let Some(ms) = t.get::<Option<f64>>("timeout")? {
                timeout = Some(millis(ms, "timeout")?);
            }
            if let Some(ms) = t.get::<Option<f64>>("every")? {
                every = millis(ms, "every")?.max(Duration::from_micros(1));
            }
            what = t.get::<Option<String>>("what")?;
        }
        other => return Err(raise(Error::usage(crate::msg!("script-wait-until-options", kind = other.type_name())))),
    }
    let start = now(lua)?;
    loop {
        let v: Value = f.call(())?;
        if truthy(&v) {
            return Ok(v);
        }
        let waited = now(lua)? - start;
        let step = match timeout {
            Some(t) if waited >= t => {
                let m = match what {
                    Some(w) => crate::msg!("script-wait-until-timeout-what", what = w, time = format!("{t:?}")),
                    None => crate::msg!("script-wait-until-timeout", time = format!("{t:?}")),
                };
                return Err(raise(Error::new(ErrorKind::Timeout, m).hint(crate::msg!("script-hint-wait-until"))));
            }
            Some(t) => every.min(t - waited),
            None => every,
        };
        sleep(lua, step)?;
    }
}

/// `plcsh.errinfo(e)`: the fields of an error caught with `pcall`.
fn errinfo(lua: &Lua, e: Value) -> mlua::Result<Value> {
    let t = lua.create_table()?;
    match e {
        Value::Error(err) => match facing(&err) {
            Some(f) => {
                let j = serde_json::to_value(&f.error).unwrap_or_default();
                let t = json_to_lua(lua, &j)?;
                if let (Value::Table(t), Some(c)) = (&t, &f.cmd) {
                    t.set("cmd", c.as_str())?;
                }
                return Ok(t);
            }
            None => {
                t.set("kind", "script")?;
                t.set("message", err.to_string())?;
            }
        },
        Value::Table(t) => return Ok(Value::Table(t)),
        other => {
            t.set("kind", "script")?;
            t.set("message", lua.coerce_string(other)?.map(|s| s.to_string_lossy()).unwrap_or_default())?;
        }
    }
    Ok(Value::Table(t))
}

/// A cell of `plcsh.table`.
fn cell(lua: &Lua, v: &Value) -> mlua::Result<String> {
    Ok(match v {
        Value::Nil => String::new(),
        Value::Table(_) => serde_json::to_string(&lua.from_value::<serde_json::Value>(v.clone())?).unwrap_or_default(),
        Value::Number(n) if n.fract() == 0.0 && n.abs() < 1e15 => format!("{n:.1}"),
        other => lua.coerce_string(other.clone())?.map(|s| s.to_string_lossy()).unwrap_or_else(|| format!("{other:?}")),
    })
}

/// `plcsh.table(rows [, headers])`: rows are lists or keyed tables.
fn table(lua: &Lua, (rows, headers): (Table, Option<Vec<String>>)) -> mlua::Result<()> {
    let rows: Vec<Table> = rows.sequence_values::<Table>().collect::<mlua::Result<_>>()?;
    let keyed = rows.first().is_some_and(|r| r.raw_len() == 0);
    let headers = match headers {
        Some(h) => h,
        None if keyed => {
            let mut keys: Vec<String> = Vec::new();
            for r in &rows {
                for p in r.pairs::<String, Value>() {
                    let k = p?.0;
                    if !keys.contains(&k) {
                        keys.push(k);
                    }
                }
            }
            keys.sort();
            keys
        }
        None => (1..=rows.iter().map(|r| r.raw_len()).max().unwrap_or(0)).map(|i| i.to_string()).collect(),
    };
    let mut cells = Vec::new();
    let mut json: Vec<Vec<serde_json::Value>> = Vec::new();
    for r in &rows {
        let (mut line, mut values) = (Vec::new(), Vec::new());
        for (i, h) in headers.iter().enumerate() {
            let v: Value = if keyed { r.get(h.as_str())? } else { r.get(i + 1)? };
            let shown = cell(lua, &v)?;
            // In JSON a number stays a number and a boolean a boolean; the rest as shown.
            values.push(match v {
                Value::Integer(n) => n.into(),
                Value::Number(n) => serde_json::Number::from_f64(n).map_or(shown.clone().into(), Into::into),
                Value::Boolean(b) => b.into(),
                _ => shown.clone().into(),
            });
            line.push(shown);
        }
        cells.push(line);
        json.push(values);
    }
    let hs: Vec<&str> = headers.iter().map(String::as_str).collect();
    show(lua, &Outcome::new("table").table(&hs, cells).with("headers", &headers).with("rows", json))
}

/// The `plcsh` table with the functions of this file (`script::Engine` adds wiring and
/// snapshots and sets it as a global; device functions are added by `device::register`).
pub fn plcsh_table(lua: &Lua) -> mlua::Result<Table> {
    let p = lua.create_table()?;
    p.set("exec", lua.create_function(|lua, line: String| exec_on(lua, None, &line))?)?;
    // One word of a shell line for any text (a path with spaces or quotes), read back unchanged.
    p.set("quote", lua.create_function(|_, text: String| Ok(crate::shell::lex::quote(&text).into_owned()))?)?;
    p.set("sleep", lua.create_function(|lua, ms: f64| sleep(lua, millis(ms, "sleep")?))?)?;
    p.set("now", lua.create_function(|lua, ()| Ok(now(lua)?.as_secs_f64() * 1000.0))?)?;
    p.set("stepped", lua.create_function(|lua, ()| with_shell(lua, |sh| Ok(sh.session.clock.is_stepped())))?)?;
    p.set("wait_until", lua.create_function(wait_until)?)?;
    p.set("_interrupted", lua.create_function(|lua, ()| Ok(interrupt_flag(lua)?.load(Ordering::Relaxed)))?)?;
    p.set("errinfo", lua.create_function(errinfo)?)?;
    p.set("_explain", lua.create_function(super::error::explain)?)?;
    p.set("table", lua.create_function(table)?)?;
    p.set("_write", lua.create_function(|lua, text: mlua::LuaString| print_bytes(lua, &text.as_bytes()))?)?;
    lua.set_named_registry_value(ABORT_KEY, lua.create_table()?)?;
    p.set(
        "on_abort",
        lua.create_function(|lua, f: Function| {
            let list: Table = lua.named_registry_value(ABORT_KEY)?;
            list.push(f)
        })?,
    )?;
    let json = lua.create_table()?;
    json.set(
        "encode",
        lua.create_function(|lua, (v, opts): (Value, Option<Table>)| {
            json_shape(lua, &v, &mut String::from("value"))?;
            let j: serde_json::Value = lua.from_value(v)?;
            if let Some(o) = &opts {
                check_keys(lua, o, &["pretty"], "plcsh.json.encode")?;
            }
            let pretty = opts.map(|o| o.get::<Option<bool>>("pretty")).transpose()?.flatten().unwrap_or(false);
            let s = if pretty { serde_json::to_string_pretty(&j) } else { serde_json::to_string(&j) };
            s.map_err(mlua::Error::external)
        })?,
    )?;
    json.set(
        "decode",
        lua.create_function(|lua, s: String| {
            let j: serde_json::Value =
                serde_json::from_str(&s).map_err(|e| raise(Error::new(ErrorKind::Value, format!("not JSON: {e}"))))?;
            json_to_lua(lua, &j)
        })?,
    )?;
    p.set("json", json)?;
    Ok(p)
}
