//! `sim fault KIND … [on OPERANDS] [at=|after=] [for=] [times=]`, `sim fault clear [ID]`,
//! `sim faults`: injected faults on the simulated K2 ([`crate::k2::sim::fault`]), in the
//! control language of [`crate::k2::sim::control`]: applied to an in-process simulator, or
//! sent to a served one's control channel when the device was opened with `control=PATH`.

use super::k2cmd;
use crate::core::link::control as channel;
use crate::core::Result;
use crate::output::Outcome;
use crate::shell::Shell;

pub fn run(sh: &mut Shell, sub: &str, rest: &str) -> Result<Outcome> {
    // Lua passes the spec as one quoted string.
    let rest = rest.strip_prefix('"').and_then(|r| r.strip_suffix('"')).unwrap_or(rest).trim();
    let line = if sub == "faults" { format!("faults {rest}") } else { format!("fault {rest}") };
    let dev = sh.session.current_index()?;
    let name = k2cmd::name(sh, dev);
    let (text, data) = if let Some(path) = sh.session.entries()[dev].control.clone() {
        channel::send(&path, &line).map_err(|e| e.device(&name))?
    } else {
        let sim = k2cmd::sim(sh, dev, "sim fault").map_err(|e| e.hint(crate::msg!("shell-hint-fault-served")))?;
        crate::k2::sim::control::answer(sim, &line, false).map_err(|e| e.device(&name))?
    };
    let mut o = Outcome::new("sim").text(text);
    if let serde_json::Value::Object(m) = data {
        for (k, v) in m {
            if !matches!(k.as_str(), "ok" | "text" | "time_us") {
                o = o.with(&k, v);
            }
        }
    }
    o.device = Some(name);
    Ok(o)
}
