//! `plcsh.report`: what the commission runner (`lib/commission.lua`) and `plcsh run --report
//! FILE` use to make a commissioning report ([`crate::report`]).
//!
//! - `plcsh.report.begin()` starts the session's write log (the guard's,
//!   [`crate::guard::WriteLog`]) and notes the date and the session's time;
//! - `plcsh.report.write(record, path)` turns the runner's record into the report — adding
//!   every open device and what it is, the clock readings and the write log — and writes the
//!   HTML page and its JSON twin; it returns `{html = path, json = twin}`;
//! - `plcsh.report.path()` is the file `plcsh run --report FILE` asked for (nil otherwise).
//!
//! The runner's record arrives as a Lua table; keys are read in sorted order and empty tables
//! as empty lists, so the record is the same whatever order Lua iterates a table in.

use super::api::with_shell;
use super::error::raise;
use crate::core::Error;
use crate::report::{Context, Report, Run};
use crate::shell::Shell;
use mlua::{Lua, LuaSerdeExt, Table, Value};

/// Registry key of the run's start: `{date, start_ms}`.
const BEGIN_KEY: &str = "plcsh.report.begin";
/// Registry key of the report file `plcsh run --report` asked for.
pub const PATH_KEY: &str = "plcsh.report.path";
/// Registry key set once a report has been written in this run.
pub const WRITTEN_KEY: &str = "plcsh.report.written";

/// Where a run began, for the report.
#[derive(Clone, Debug)]
pub struct Begun {
    pub date: String,
    pub start_ms: f64,
}

/// Starts the write log and notes the start (also called by `plcsh run --report`).
pub fn begin(sh: &mut Shell) -> Begun {
    sh.session.write_log.start();
    Begun { date: crate::report::date_now(), start_ms: sh.session.clock.now().as_secs_f64() * 1e3 }
}

/// The report of `run` in the session of `sh`, begun at `begun`, written to `path`; returns the
/// JSON twin's path.
pub fn write(sh: &mut Shell, run: Run, begun: &Begun, path: &str) -> crate::core::Result<std::path::PathBuf> {
    let cannot = |reason: String| Error::io(crate::msg!("report-cannot-write", file = path, reason = reason));
    crate::shell::files::check_write(&sh.write_rule, path)?;
    let twin = crate::report::json_path(std::path::Path::new(path));
    crate::shell::files::check_write(&sh.write_rule, &twin.display().to_string())?;
    let (mut writes, writes_not_kept) = sh.session.write_log_entries();
    // Each write's tag name, from its device's names (the guard logs operands only).
    for w in &mut writes {
        let Ok(i) = sh.session.index(&w.device) else { continue };
        let Ok(ops) = sh.session.entries()[i].device.operands().parse(&w.operand) else { continue };
        if let [op] = ops.as_slice() {
            w.name = sh.session.tag_of(i, op).map(|t| t.name.clone());
        }
    }
    let devices = sh
        .session
        .entries()
        .iter()
        .map(|e| {
            let mut j = serde_json::to_value(e.device.info()).unwrap_or_default();
            j["name"] = e.name.clone().into();
            j["url"] = e.url.clone().into();
            j
        })
        .collect();
    let ctx = Context {
        devices,
        date: begun.date.clone(),
        stepped: sh.session.clock.is_stepped(),
        start_ms: begun.start_ms,
        end_ms: sh.session.clock.now().as_secs_f64() * 1e3,
        writes,
        writes_not_kept,
        lang: crate::core::msg::language(),
    };
    let report = Report::build(run, ctx);
    crate::report::write(&report, std::path::Path::new(path)).map_err(|e| cannot(e.message.to_string()))
}

/// The runner's record: a Lua table read with sorted keys, empty tables as lists (see the
/// module doc); the two maps of the record (`reports`, a trace's `units`) are objects even
/// when empty.
fn record(lua: &Lua, v: Value) -> mlua::Result<Run> {
    let opts = mlua::serde::DeserializeOptions::new()
        .sort_keys(true)
        .encode_empty_tables_as_array(true)
        .deny_unsupported_types(false)
        .deny_recursive_tables(false);
    let mut j: serde_json::Value = lua.from_value_with(v, opts)?;
    let as_map = |x: &mut serde_json::Value| {
        if x.as_array().is_some_and(|a| a.is_empty()) {
            *x = serde_json::json!({});
        }
    };
    if let Some(r) = j.get_mut("reports") {
        as_map(r);
    }
    if let Some(serde_json::Value::Array(ts)) = j.get_mut("traces") {
        for t in ts {
            if let Some(u) = t.get_mut("units") {
                as_map(u);
            }
        }
    }
    serde_json::from_value(j).map_err(|e| {
        raise(Error::new(crate::core::ErrorKind::Value, crate::msg!("report-bad-record", reason = e.to_string())))
    })
}

fn begun(lua: &Lua) -> mlua::Result<Option<Begun>> {
    let t: Option<Table> = lua.named_registry_value(BEGIN_KEY)?;
    Ok(match t {
        Some(t) => Some(Begun { date: t.get("date")?, start_ms: t.get("start_ms")? }),
        None => None,
    })
}

/// Notes a run's start in the Lua state (for `write`).
pub fn remember(lua: &Lua, b: &Begun) -> mlua::Result<()> {
    let t = lua.create_table()?;
    t.set("date", b.date.as_str())?;
    t.set("start_ms", b.start_ms)?;
    lua.set_named_registry_value(BEGIN_KEY, t)
}

/// The run's start noted in the Lua state, if a report was begun.
pub fn begun_in(lua: &Lua) -> Option<Begun> {
    begun(lua).ok().flatten()
}

/// Adds `plcsh.report` to the `plcsh` table.
pub fn register(lua: &Lua, p: &Table) -> mlua::Result<()> {
    let r = lua.create_table()?;
    r.set(
        "begin",
        lua.create_function(|lua, ()| {
            let b = with_shell(lua, |sh| Ok(begin(sh)))?;
            remember(lua, &b)
        })?,
    )?;
    r.set(
        "write",
        lua.create_function(|lua, (rec, path): (Value, String)| {
            let run = record(lua, rec)?;
            let b = match begun(lua)? {
                Some(b) => b,
                None => with_shell(lua, |sh| Ok(begin(sh)))?,
            };
            let twin = with_shell(lua, |sh| write(sh, run, &b, &path))?;
            lua.set_named_registry_value(WRITTEN_KEY, true)?;
            let out = lua.create_table()?;
            out.set("html", path)?;
            out.set("json", twin.display().to_string())?;
            Ok(out)
        })?,
    )?;
    r.set("path", lua.create_function(|lua, ()| lua.named_registry_value::<Option<String>>(PATH_KEY))?)?;
    p.set("report", r)
}
