//! `plcsh.wire("plc:Q0.0 -> servo:pulse")`, `plcsh.wires()`, `plcsh.unwire("plc:I0.0")`:
//! virtual wiring from Lua, the same declarations as `sim wire` (`crate::wiring::setup`).

use super::api::with_shell;
use mlua::{Lua, Table};

pub fn register(lua: &Lua, p: &Table) -> mlua::Result<()> {
    p.set(
        "wire",
        lua.create_function(|lua, text: String| {
            with_shell(lua, |sh| {
                sh.session.check_bench("sim wire")?;
                crate::wiring::setup::wire(&mut sh.session, &text)
            })
        })?,
    )?;
    p.set(
        "wires",
        lua.create_function(|lua, ()| {
            with_shell(lua, |sh| {
                sh.session.check_bench("sim wires")?;
                Ok(crate::wiring::setup::list(&mut sh.session))
            })
        })?,
    )?;
    p.set(
        "unwire",
        lua.create_function(|lua, text: String| {
            with_shell(lua, |sh| {
                sh.session.check_bench("sim unwire")?;
                crate::wiring::setup::unwire(&mut sh.session, &text)
            })
        })?,
    )?;
    Ok(())
}
