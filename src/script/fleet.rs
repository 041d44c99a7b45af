//! `plcsh.fleet(NAME)` in Lua: a fleet from the profile file (`crate::profile::fleet`) as a table with
//! its `name`, its `devices` (member names) and `each(fn)`, which calls `fn(plc)` with a device
//! handle for every member in the fleet's order and returns one result per member:
//! `{device=, ok=true, value=<fn's first result>}` or `{device=, ok=false, kind=, error=}`.
//! One member's failure (it cannot be opened, `fn` raises) is its result; the others still run.
//! The results table's `ok` is true when every member succeeded, `failed` counts the others.
//!
//! Sequential by design: one Lua state is entered by one thread at a time, so `each` visits
//! the members one after another on the script's own session (a member is opened through the
//! profile path, [`crate::session::Session::open_profile`], with its write rules, and closed afterwards
//! unless it was open before). For concurrency a script runs on every member at once with
//! `plcsh run --fleet NAME SCRIPT.lua`, one Lua state per device.

use super::api::{interrupt_flag, with_shell};
use super::error::LuaFacing;
use mlua::{Function, Lua, Table, Value};
use std::sync::atomic::Ordering;

/// The error kind and message of a Lua error (a shell error keeps its kind).
fn describe(e: &mlua::Error) -> (String, String) {
    match e {
        mlua::Error::CallbackError { cause, .. } => describe(cause),
        mlua::Error::ExternalError(x) => match x.downcast_ref::<LuaFacing>() {
            Some(f) => (f.error.kind.name().to_string(), f.to_string()),
            None => ("script".into(), x.to_string()),
        },
        mlua::Error::RuntimeError(s) => ("script".into(), s.clone()),
        other => ("script".into(), other.to_string()),
    }
}

fn each(lua: &Lua, fleet: &crate::profile::fleet::Fleet, f: Function) -> mlua::Result<Table> {
    let out = lua.create_table()?;
    let mut failed = 0;
    for m in &fleet.members {
        let r = lua.create_table()?;
        r.set("device", m.name.as_str())?;
        let opened = with_shell(lua, |sh| {
            if sh.session.index(&m.name).is_ok() {
                return Ok(false);
            }
            let p = fleet.profile_of(m, &sh.session.profiles)?.clone();
            sh.session.open_profile(&m.name, &p)?;
            Ok(true)
        });
        let called = match &opened {
            Ok(_) => super::device::handle(lua, &m.name).and_then(|h| f.call::<Value>(h)),
            Err(e) => Err(e.clone()),
        };
        if let Ok(true) = opened {
            let name = m.name.clone();
            with_shell(lua, move |sh| sh.session.close(&name))?;
        }
        if interrupt_flag(lua)?.load(Ordering::Relaxed) {
            return Err(super::error::raise(super::api::interrupted_error()));
        }
        match called {
            Ok(v) => {
                r.set("ok", true)?;
                r.set("value", v)?;
            }
            Err(e) => {
                failed += 1;
                let (kind, message) = describe(&e);
                r.set("ok", false)?;
                r.set("kind", kind)?;
                r.set("error", message)?;
            }
        }
        out.push(r)?;
    }
    out.set("ok", failed == 0)?;
    out.set("failed", failed)?;
    Ok(out)
}

/// `plcsh.fleet(name)`.
pub fn register(lua: &Lua) -> mlua::Result<()> {
    let p: Table = lua.globals().get("plcsh")?;
    p.set(
        "fleet",
        lua.create_function(|lua, name: String| {
            let fleet = with_shell(lua, |sh| Ok(sh.session.profiles.fleet(&name)?.clone()))?;
            let t = lua.create_table()?;
            t.set("name", name)?;
            t.set("devices", fleet.members.iter().map(|m| m.name.clone()).collect::<Vec<_>>())?;
            t.set("each", lua.create_function(move |lua, (_this, f): (Table, Function)| each(lua, &fleet, f))?)?;
            Ok(t)
        })?,
    )?;
    Ok(())
}
