//! `plcsh.snapshot_save(name)`, `plcsh.snapshot_restore(name)`, `plcsh.snapshots()`:
//! snapshots from Lua, the same files and names as `sim snapshot save|restore` and
//! `sim snapshots` ([`crate::snapshot`]) — so a lab script can set up its starting state
//! once and return to it between runs.

use super::api::with_shell;
use crate::snapshot::{self, Snapshot};
use mlua::{Lua, Table};

pub fn register(lua: &Lua, p: &Table) -> mlua::Result<()> {
    // Returns the file written.
    p.set(
        "snapshot_save",
        lua.create_function(|lua, name: String| {
            with_shell(lua, |sh| {
                let path = sh.session.snapshot_file(&name, true)?;
                Snapshot::capture(&mut sh.session)?.save(&path)?;
                Ok(path.display().to_string())
            })
        })?,
    )?;
    // Returns the virtual time restored, in seconds.
    p.set(
        "snapshot_restore",
        lua.create_function(|lua, name: String| {
            with_shell(lua, |sh| {
                let file = sh.session.snapshot_file(&name, false)?;
                sh.session.check_bench("sim snapshot")?;
                let snap = Snapshot::load(&file)?;
                snap.restore(&mut sh.session)?;
                Ok(snap.clock_us as f64 / 1e6)
            })
        })?,
    )?;
    p.set(
        "snapshots",
        lua.create_function(|lua, ()| {
            with_shell(lua, |sh| {
                if sh.session.confine.is_some() {
                    return Ok(Vec::new()); // a sandboxed run does not look into the data directory
                }
                Ok(snapshot::list().into_iter().map(|(n, _)| n).collect::<Vec<String>>())
            })
        })?,
    )?;
    Ok(())
}
