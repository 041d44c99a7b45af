//! `sim fault KIND … [on OPERANDS] [at=|after=] [for=] [times=]`, `sim fault clear [ID]`,
//! `sim faults`: injected faults on the simulated K2 ([`crate::k2::sim::fault`]).

use super::k2cmd;
use crate::core::{Error, Result};
use crate::k2::sim::fault::{self, USAGE};
use crate::output::Outcome;
use crate::shell::Shell;

pub fn run(sh: &mut Shell, sub: &str, rest: &str) -> Result<Outcome> {
    // Lua passes the spec as one quoted string.
    let rest = rest.strip_prefix('"').and_then(|r| r.strip_suffix('"')).unwrap_or(rest).trim();
    let dev = sh.session.current_index()?;
    let name = k2cmd::name(sh, dev);
    let sim = k2cmd::sim(sh, dev, "sim fault")?;
    sim.advance();
    if sub == "faults" {
        let list: Vec<String> = sim.faults.list.iter().map(|f| f.describe()).collect();
        return Ok(Outcome::new("sim faults")
            .text(if list.is_empty() { "no injected faults".into() } else { list.join("\n") })
            .with("faults", &sim.faults.list));
    }
    if let Some(arg) = rest.strip_prefix("clear") {
        let id = match arg.trim() {
            "" | "all" => None,
            n => Some(n.parse::<u32>().map_err(|_| Error::usage(format!("`{n}` is not a fault id")).hint(USAGE))?),
        };
        let n = sim.clear_faults(id);
        if id.is_some() && n == 0 {
            return Err(Error::usage(format!("{name} has no fault {}", id.unwrap_or(0)))
                .hint("sim faults lists them")
                .device(&name));
        }
        return Ok(Outcome::new("sim fault").text(format!("cleared {n} fault(s)")).with("cleared", n));
    }
    let spec = fault::parse(rest).map_err(|m| Error::usage(m).hint(USAGE).device(&name))?;
    let now = sim.last;
    let id = sim.faults.add(&spec, now);
    let f = sim.faults.list.last().expect("just added");
    let note = if f.kind.in_process() {
        String::new()
    } else {
        " (acts when the simulator is served: sim serve --fault …)".to_string()
    };
    Ok(Outcome::new("sim fault").text(format!("{}{note}", f.describe())).with("id", id).with("fault", f))
}
