//! The one bridge from Lua device methods to shell commands, and the one table that maps
//! them. `plc:pto(0, {freq=2000, count=1000})` becomes `pto 0 count=1000 freq=2000` run on
//! that device; the command's outcome comes back as a Lua table (the same data as `--json`).
//! A new shell helper becomes reachable from Lua by adding one row to [`BRIDGE`].
//!
//! How arguments become command text:
//! - the template's `{}` takes the next argument as a word, `{ms}` the next as a duration
//!   (a number is milliseconds, `5000` → `5000ms`; a string such as `"5s"` passes as typed);
//! - the remaining arguments are appended in order: numbers, strings (quoted when they hold
//!   spaces, `,` or `;`), booleans; a table with keys becomes `key=value` options (sorted by key,
//!   since Lua tables are unordered; renamed and given a unit by the row's `options`); a list
//!   becomes `[a, b]`, a list of keyed tables `[(k=v, …), …]` (`profile`'s segments).
//!
//! The command runs with the handle's device made current (as `use NAME; CMD; use BACK`), so
//! commands that act on "the current device" act on the handle's device.

use super::api;
use crate::core::{Error, Result};
use mlua::{Lua, Table, Value};

/// One Lua method → shell command row.
#[derive(Debug)]
pub struct Bridge {
    /// The Lua method name (`plc:move_abs(…)`).
    pub method: &'static str,
    /// The device family it applies to (`k2`, `servo`), or `""` for every family.
    pub family: &'static str,
    /// The command text; `{}` and `{ms}` take arguments in order, the rest are appended.
    pub template: &'static str,
    /// Option renames: (Lua key, command key, unit appended to numbers).
    pub options: &'static [(&'static str, &'static str, &'static str)],
}

const fn row(method: &'static str, family: &'static str, template: &'static str) -> Bridge {
    Bridge { method, family, template, options: &[] }
}

/// Servo speeds: `{rpm=300}` → `speed=300rpm`.
const SPEED: &[(&str, &str, &str)] = &[("rpm", "speed", "rpm"), ("speed", "speed", "")];

/// Every device method that runs a shell command. Commands of the K2 motion, servo and
/// simulator helpers (issues 3–6) are listed with the syntax their issues give.
pub const BRIDGE: &[Bridge] = &[
    // Any device.
    row("read", "", "read"),
    row("help", "", "help"),
    row("cmd", "", ""), // plc:cmd("pls 0; pls 1"): any command line, on this device
    // K2 pulse outputs and counters (PTO/PWM/HSC helpers).
    row("pls", "k2", "pls"),
    row("pto", "k2", "pto"),
    row("pwm", "k2", "pwm"),
    row("profile", "k2", "profile {} at {}"),
    row("hsc", "k2", "hsc"),
    row("hdef", "k2", "hdef"),
    row("pstop", "k2", "pstop"),
    row("events", "k2", "events"),
    row("wait_event", "k2", "wait event {} timeout={ms}"),
    // K2 real-time clock and E2PROM backup.
    row("rtc", "k2", "rtc"),
    row("rtc_set", "k2", "rtc set"),
    row("rtc_sync", "k2", "rtc sync"),
    row("eeprom_dump", "k2", "eeprom dump"),
    row("eeprom_restore", "k2", "eeprom restore"),
    // K2 simulator inputs.
    row("sim_input", "k2", "sim input"),
    row("sim_quad", "k2", "sim quad"),
    // Kinco servo drive.
    row("status", "servo", "servo status"),
    row("enable", "servo", "servo enable"),
    row("disable", "servo", "servo disable"),
    row("fault_reset", "servo", "servo fault-reset"),
    row("quickstop", "servo", "servo quickstop"),
    row("mode", "servo", "servo mode"),
    Bridge { method: "move_abs", family: "servo", template: "servo move abs", options: SPEED },
    Bridge { method: "move_rel", family: "servo", template: "servo move rel", options: SPEED },
    row("jog", "servo", "servo jog"),
    row("wait_target", "servo", "servo wait target timeout={ms}"),
    row("save", "servo", "servo save"),
];

fn usage(b: &Bridge, msg: String) -> Error {
    let shown = if b.template.is_empty() { "a command line".to_string() } else { format!("`{}`", b.template) };
    Error::usage(format!("{}: {msg}", b.method))
        .hint(format!("{} runs {shown} with extra arguments appended", b.method))
}

fn number(n: f64) -> String {
    if n.fract() == 0.0 && n.abs() < 1e15 {
        format!("{n:.0}")
    } else {
        format!("{n}")
    }
}

/// A list (`{1, 2}`) rather than a table with keys.
fn is_list(t: &Table) -> bool {
    let n = t.raw_len();
    n > 0 && t.pairs::<Value, Value>().count() == n
}

/// One argument as a word of command text.
pub fn word(v: &Value) -> Result<String> {
    Ok(match v {
        Value::Integer(i) => i.to_string(),
        Value::Number(n) => number(*n),
        Value::Boolean(b) => b.to_string(),
        Value::String(s) => {
            let s = s.to_str().map_err(|_| Error::usage("argument is not UTF-8 text"))?.to_string();
            let plain = s.starts_with(['[', '(', '"', '\'']) || !s.contains([' ', '\t', ',', ';']);
            if plain {
                s
            } else if s.contains('"') {
                format!("'{s}'")
            } else {
                format!("\"{s}\"")
            }
        }
        Value::Table(t) if is_list(t) => {
            let items: Vec<String> = t
                .sequence_values::<Value>()
                .map(|v| v.map_err(lua_err).and_then(|v| word(&v)))
                .collect::<Result<_>>()?;
            format!("[{}]", items.join(", "))
        }
        Value::Table(t) => format!("({})", options(t, &[])?.join(", ")),
        other => return Err(Error::usage(format!("cannot pass a Lua {} to a command", other.type_name()))),
    })
}

fn lua_err(e: mlua::Error) -> Error {
    Error::usage(e.to_string())
}

/// A keyed table as `key=value` words, sorted by key, with renames and units.
fn options(t: &Table, renames: &[(&str, &str, &str)]) -> Result<Vec<String>> {
    let mut pairs = Vec::new();
    for p in t.pairs::<Value, Value>() {
        let (k, v) = p.map_err(lua_err)?;
        let key = match &k {
            Value::String(s) => s.to_str().map_err(|_| Error::usage("option name is not UTF-8"))?.to_string(),
            other => return Err(Error::usage(format!("option names are strings, not {}", other.type_name()))),
        };
        pairs.push((key, v));
    }
    pairs.sort_by(|a, b| a.0.cmp(&b.0));
    pairs
        .into_iter()
        .map(|(k, v)| {
            let (name, unit) = match renames.iter().find(|r| r.0 == k) {
                Some(&(_, to, unit)) => (to.to_string(), unit),
                None => (k, ""),
            };
            let mut text = word(&v)?;
            if !unit.is_empty() && matches!(v, Value::Integer(_) | Value::Number(_)) {
                text.push_str(unit);
            }
            Ok(format!("{name}={text}"))
        })
        .collect()
}

/// A duration argument: a number is milliseconds.
fn duration(v: &Value) -> Result<String> {
    match v {
        Value::Integer(_) | Value::Number(_) => Ok(format!("{}ms", word(v)?)),
        _ => word(v),
    }
}

/// The command text for a call of `b` with `args` (the arguments after the handle).
pub fn render(b: &Bridge, args: &[Value]) -> Result<String> {
    let mut out = String::new();
    let mut it = args.iter();
    let mut rest = b.template;
    while let Some(open) = rest.find('{') {
        out.push_str(&rest[..open]);
        let close = rest[open..].find('}').map(|c| open + c).unwrap_or(rest.len() - 1);
        let spec = &rest[open + 1..close];
        let Some(arg) = it.next() else {
            return Err(usage(b, format!("missing argument for `{{{spec}}}`")));
        };
        out.push_str(&if spec == "ms" { duration(arg)? } else { word(arg)? });
        rest = &rest[close + 1..];
    }
    out.push_str(rest);
    // `cmd` (an empty template) takes command text as typed.
    let raw = b.template.is_empty();
    for arg in it {
        let words = match arg {
            Value::Table(t) if !is_list(t) => options(t, b.options)?,
            Value::Nil => continue,
            Value::String(s) if raw => {
                vec![s.to_str().map_err(|_| Error::usage("command text is not UTF-8"))?.to_string()]
            }
            v => vec![word(v)?],
        };
        for w in words {
            if !out.is_empty() {
                out.push(' ');
            }
            out.push_str(&w);
        }
    }
    if out.trim().is_empty() {
        return Err(usage(b, "nothing to run".into()));
    }
    Ok(out)
}

/// Runs row `b` on device `name` with `args`; returns one table per command result.
pub fn call(lua: &Lua, name: &str, b: &Bridge, args: &[Value]) -> mlua::Result<mlua::MultiValue> {
    let line = render(b, args).map_err(super::error::raise)?;
    if !b.family.is_empty() {
        let family = api::with_shell(lua, |sh| {
            let i = super::device::index(sh, name)?;
            Ok(sh.session.entries()[i].device.info().family)
        })?;
        if family != b.family {
            return Err(super::error::raise(
                Error::unsupported(format!("`{}` is a {} method; `{name}` is a {family} device", b.method, b.family))
                    .device(name),
            ));
        }
    }
    api::exec_on(lua, Some(name), &line)
}

#[cfg(test)]
mod tests {
    use super::*;

    fn find(method: &str) -> Option<&'static Bridge> {
        BRIDGE.iter().find(|b| b.method == method)
    }

    fn render_lua(method: &str, args: &str) -> Result<String> {
        let lua = Lua::new();
        let v: mlua::MultiValue = lua.load(format!("return {args}")).eval().unwrap();
        render(find(method).unwrap(), &v.into_iter().collect::<Vec<_>>())
    }

    #[test]
    fn options_tables_and_lists_become_command_text() {
        assert_eq!(render_lua("pls", "0").unwrap(), "pls 0");
        assert_eq!(render_lua("pto", "0, {freq=2000, count=1000}").unwrap(), "pto 0 count=1000 freq=2000");
        assert_eq!(render_lua("move_abs", "10000, {rpm=300}").unwrap(), "servo move abs 10000 speed=300rpm");
        assert_eq!(render_lua("enable", "").unwrap(), "servo enable");
        assert_eq!(render_lua("fault_reset", "").unwrap(), "servo fault-reset");
        assert_eq!(
            render_lua("profile", "0, 'VB3000', {{cycle='500us', count=1000}, {cycle='250us', count=2000}}").unwrap(),
            "profile 0 at VB3000 [(count=1000, cycle=500us), (count=2000, cycle=250us)]"
        );
        assert_eq!(render_lua("hsc", "0, {mode=9, pv={100, 200}}").unwrap(), "hsc 0 mode=9 pv=[100, 200]");
        assert_eq!(render_lua("wait_event", "28, 5000").unwrap(), "wait event 28 timeout=5000ms");
        assert_eq!(render_lua("wait_event", "28, '2s'").unwrap(), "wait event 28 timeout=2s");
        assert_eq!(render_lua("eeprom_dump", "'my backup.bin'").unwrap(), "eeprom dump \"my backup.bin\"");
        assert_eq!(render_lua("pto", "0, {freq=2000.0}").unwrap(), "pto 0 freq=2000");
        assert_eq!(render_lua("cmd", "'get VW0'").unwrap(), "get VW0");
    }

    #[test]
    fn a_missing_template_argument_is_a_usage_error() {
        let e = render_lua("wait_event", "28").unwrap_err();
        assert!(e.message.contains("missing argument"), "{e}");
        assert!(e.hint.clone().unwrap().contains("wait event {} timeout={ms}"));
        assert!(render_lua("cmd", "").is_err());
    }

    #[test]
    fn method_names_are_unique() {
        for (i, b) in BRIDGE.iter().enumerate() {
            assert!(BRIDGE[i + 1..].iter().all(|o| o.method != b.method), "{} twice", b.method);
        }
    }
}
