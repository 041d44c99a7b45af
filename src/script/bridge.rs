//! The one bridge from Lua device methods to shell commands, and the one table that maps
//! them. `plc:pto(0, {freq=2000, count=1000})` becomes `pto 0 count=1000 freq=2000` run on
//! that device; the command's outcome comes back as a Lua table (the same data as `--json`).
//! A new shell helper becomes reachable from Lua by adding one row to [`BRIDGE`].
//!
//! How arguments become command text:
//! - the template's `{}` takes the next argument as a word; `{UNIT}` (`{ms}`, `{rpm}`) takes
//!   it with UNIT appended when it is a number (`5000` → `5000ms`; a string such as `"5s"`
//!   passes as typed); a part in `[…]` is optional and dropped when its argument is missing
//!   or nil (`wait event {} [timeout={ms}]`);
//! - the remaining arguments are appended in order: numbers, strings (quoted when they hold
//!   spaces, `,` or `;`), booleans; a list becomes `[a, b]`, a list of keyed tables
//!   `[(k=v, …), …]` (`profile`'s segments);
//! - a table with keys becomes options, sorted by key (Lua tables are unordered): `key=value`,
//!   `true` as the bare word `key` (`relative=true` → `relative`), `false` left out; the
//!   row's [`Opt`]s rename keys, give numbers a unit (also inside nested tables, so a
//!   segment's `cycle=500` is `cycle=500us`), or write `key value` (`at VB3009`).
//!
//! The command runs with the handle's device made current (as `use NAME; CMD; use BACK`), so
//! commands that act on "the current device" act on the handle's device.

use super::api;
use crate::core::{Error, Result};
use mlua::{Lua, Table, Value};

/// How one Lua option key is written in the command.
#[derive(Debug)]
pub struct Opt {
    /// The key in the Lua table (`rpm`).
    pub key: &'static str,
    /// The command's key (`speed`); empty for a bare value (`servo jog 100rpm`).
    pub to: &'static str,
    /// Appended to numbers (`rpm`, `us`).
    pub unit: &'static str,
    /// Written as `key value` (`at VB3009`) instead of `key=value`.
    pub spaced: bool,
}

/// `key=NUMBERunit`.
const fn unit(key: &'static str, unit: &'static str) -> Opt {
    Opt { key, to: key, unit, spaced: false }
}

/// `to=NUMBERunit` for Lua key `key`.
const fn rename(key: &'static str, to: &'static str, unit: &'static str) -> Opt {
    Opt { key, to, unit, spaced: false }
}

/// `key VALUE`.
const fn spaced(key: &'static str) -> Opt {
    Opt { key, to: key, unit: "", spaced: true }
}

/// One Lua method → shell command row.
#[derive(Debug)]
pub struct Bridge {
    /// The Lua method name (`plc:move_abs(…)`).
    pub method: &'static str,
    /// The device family it applies to (`k2`, `servo`; `k2/umpk` for either), or `""` for every family.
    pub family: &'static str,
    /// The command text; `{}`/`{UNIT}` take arguments in order, `[…]` is optional, the rest
    /// are appended.
    pub template: &'static str,
    /// How option keys are written (renames, units, `key value` forms).
    pub options: &'static [Opt],
}

impl Bridge {
    /// Whether the method applies to devices of `family`.
    pub fn applies_to(&self, family: &str) -> bool {
        self.family.is_empty() || self.family.split('/').any(|f| f == family)
    }
}

const fn row(method: &'static str, family: &'static str, template: &'static str) -> Bridge {
    Bridge { method, family, template, options: &[] }
}

const fn with(method: &'static str, family: &'static str, template: &'static str, options: &'static [Opt]) -> Bridge {
    Bridge { method, family, template, options }
}

/// Pulse timing: a number is microseconds, the manual's default time base (k2.md §5);
/// `freq` needs no unit (a number is Hz).
const PULSE: &[Opt] = &[unit("cycle", "us"), unit("width", "us")];

/// Sampling: numbers are milliseconds (the Lua unit for times).
const TRACE: &[Opt] = &[unit("every", "ms"), unit("for", "ms")];

/// `at VB3009` (the PV table address, k2.md §4).
const HSC: &[Opt] = &[spaced("at")];

/// Servo speeds: `{rpm=300}` → `speed=300rpm`; a bare `speed`/`acc`/`dec` number is in rpm /
/// rps/s too (the unit rule, `servo::units::command_value`); `'2731dec'` is the raw value.
const SPEED: &[Opt] = &[rename("rpm", "speed", "rpm")];

/// `servo:jog{rpm=100}` → `servo jog 100rpm`.
const JOG: &[Opt] = &[Opt { key: "rpm", to: "", unit: "rpm", spaced: true }];

/// `{store=true}` → `--store`.
const STORE: &[Opt] = &[rename("store", "--store", "")];

/// `{with="servo2"}` → `--with servo2`.
const WITH: &[Opt] = &[Opt { key: "with", to: "--with", unit: "", spaced: true }];

/// Every device method that runs a shell command: the K2 helpers, the servo helpers, the
/// simulator's input signals.
pub static BRIDGE: &[Bridge] = &[
    // Any device.
    row("read", "", "read"),
    row("help", "", "help"),
    row("cmd", "", ""), // plc:cmd("pls 0; pls 1"): any command line, on this device
    // plc:trace("VW0", "Q0.0", {every=10, ["for"]=1000, to="t.csv"}): the samples (t_s, series).
    with("trace", "", "trace", TRACE),
    // K2 pulse outputs (k2.md §5, §6).
    row("pls", "k2", "pls {}"),
    row("pstop", "k2", "pstop {}"),
    with("pto", "k2", "pto {}", PULSE),
    row("pto_status", "k2", "pto {} status"),
    with("pwm", "k2", "pwm {}", PULSE),
    with("profile", "k2", "profile {} at {}", PULSE),
    // K2 high-speed counters (k2.md §4).
    row("hdef", "k2", "hdef {} {}"),
    with("hsc", "k2", "hsc {}", HSC),
    row("hsc_status", "k2", "hsc {} status"),
    // Interrupt events.
    row("events", "k2", "events"),
    row("wait_event", "k2", "wait event {} [timeout={ms}]"),
    // K2 real-time clock and E2PROM backup (k2.md §7).
    row("rtc", "k2", "rtc"),
    // The PLC-side helper program on a wire K2 (docs/agent.md).
    row("agent_status", "k2", "agent status"),
    row("rtc_set", "k2", "rtc set {}"),
    row("rtc_sync", "k2", "rtc sync"),
    row("eeprom_dump", "k2", "eeprom dump {}"),
    row("eeprom_restore", "k2", "eeprom restore {}"),
    row("eeprom_status", "k2", "eeprom status"),
    row("eeprom_area", "k2", "eeprom area {}"),
    // Data sets (dataset): plc:data_save("recipe.toml", "VB0..VB99", "eeprom"), data_diff(file
    // [, file2]), data_load(file); any PLC family whose operands `get` reads.
    row("data_save", "k2/fx/umpk", "data save {}"),
    row("data_diff", "k2/fx/umpk", "data diff {}"),
    row("data_load", "k2/fx/umpk", "data load {}"),
    // K2 simulator input signals.
    row("sim_input", "k2", "sim input {}"),
    row("sim_quad", "k2", "sim quad {} {}"),
    row("sim_off", "k2", "sim input {} off"),
    row("sim_inputs", "k2", "sim inputs"),
    row("inject_fault", "k2", "sim fault {}"),
    row("injected_faults", "k2", "sim faults"),
    // The simulated K2's CPU and its IL program (k2::sim::program).
    // … the simulated UMPK's IL lab program (umpk::sim::program), the simulated FX PLC's
    // instruction list (fx::program).
    row("program_load", "k2/umpk/fx", "sim program load {}"),
    row("program", "k2/umpk/fx", "sim program"),
    row("cpu", "k2/fx", "sim cpu {}"),
    row("scan", "k2", "sim scan [{}]"),
    row("breakpoint", "k2", "sim break {}"),
    row("step_instruction", "k2", "sim stepi [{}]"),
    row("step_network", "k2", "sim stepn"),
    // Kinco servo drive (kinco-servo.md).
    row("status", "servo", "servo status"),
    row("enable", "servo", "servo enable"),
    row("disable", "servo", "servo disable"),
    row("fault_reset", "servo", "servo fault-reset"),
    row("quickstop", "servo", "servo quickstop"),
    row("mode", "servo", "servo mode {}"),
    with("move_abs", "servo", "servo move abs {}", SPEED),
    with("move_rel", "servo", "servo move rel {}", SPEED),
    with("jog", "servo", "servo jog", JOG),
    row("home", "servo", "servo home"),
    row("halt", "servo", "servo halt"),
    row("wait_target", "servo", "servo wait target [timeout={ms}]"),
    row("save", "servo", "servo save"),
    // Parameter sets (servo::params): servo:params_load("x.toml", {store=true}).
    row("params_save", "servo", "servo params save {}"),
    // servo:params_diff(file [, file2]) or servo:params_diff{with="servo2"} (another drive).
    with("params_diff", "servo", "servo params diff", WITH),
    with("params_load", "servo", "servo params load {}", STORE),
    row("encoder", "servo", "servo encoder"),
    row("sim_fault", "servo", "servo sim fault"),
    row("sim_switch", "servo", "servo sim switch {}"),
    row("sim_pulses", "servo", "servo sim pulses"),
    // UMPK8/UMPK16 teaching PLCs (umpk.md): lab:umpk_monitor{count=50, every=100}.
    row("umpk_info", "umpk", "umpk info"),
    row("umpk_program_info", "umpk", "umpk program-info"),
    row("umpk_errors", "umpk", "umpk errors"),
    row("umpk_clear_errors", "umpk", "umpk errors clear"),
    row("umpk_timing", "umpk", "umpk timing"),
    row("umpk_reset", "umpk", "umpk reset"),
    row("umpk_echo", "umpk", "umpk echo {}"),
    with("umpk_monitor", "umpk", "umpk monitor quiet", UMPK_MONITOR),
    row("umpk_program", "umpk", "umpk program {}"),
    row("umpk_send", "umpk", "umpk send {}"),
    row("umpk_sim_input", "umpk", "umpk sim input {}"),
    row("umpk_sim_reference", "umpk", "umpk sim reference {}"),
];

/// `{ms=500, every=100}` → `for=500ms every=100ms` (`for` is a Lua keyword).
const UMPK_MONITOR: &[Opt] = &[rename("ms", "for", "ms"), unit("every", "ms")];

fn usage(b: &Bridge, msg: crate::core::msg::Msg) -> Error {
    let hint = if b.template.is_empty() {
        crate::msg!("script-hint-runs-command-line", method = b.method)
    } else {
        crate::msg!("script-hint-runs-template", method = b.method, template = b.template)
    };
    Error::usage(crate::msg!("script-method-error", method = b.method, error = msg.text)).hint(hint)
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

fn is_number(v: &Value) -> bool {
    matches!(v, Value::Integer(_) | Value::Number(_))
}

/// One argument as a word of command text; `opts` apply inside keyed tables.
pub fn word(v: &Value, opts: &[Opt]) -> Result<String> {
    Ok(match v {
        Value::Integer(i) => i.to_string(),
        Value::Number(n) => number(*n),
        Value::Boolean(b) => b.to_string(),
        Value::String(s) => {
            let s = s.to_str().map_err(|_| Error::usage(crate::msg!("script-arg-not-utf8")))?.to_string();
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
                .map(|v| v.map_err(lua_err).and_then(|v| word(&v, opts)))
                .collect::<Result<_>>()?;
            format!("[{}]", items.join(", "))
        }
        Value::Table(t) => format!("({})", options(t, opts)?.join(", ")),
        other => return Err(Error::usage(crate::msg!("script-cannot-pass", kind = other.type_name()))),
    })
}

fn lua_err(e: mlua::Error) -> Error {
    Error::usage(e.to_string())
}

/// A keyed table as option words, sorted by key (see the module doc).
fn options(t: &Table, opts: &[Opt]) -> Result<Vec<String>> {
    let mut pairs = Vec::new();
    for p in t.pairs::<Value, Value>() {
        let (k, v) = p.map_err(lua_err)?;
        let key = match &k {
            Value::String(s) => {
                s.to_str().map_err(|_| Error::usage(crate::msg!("script-option-not-utf8")))?.to_string()
            }
            other => return Err(Error::usage(crate::msg!("script-option-not-string", kind = other.type_name()))),
        };
        pairs.push((key, v));
    }
    pairs.sort_by(|a, b| a.0.cmp(&b.0));
    let mut out = Vec::new();
    for (k, v) in pairs {
        let o = opts.iter().find(|o| o.key == k);
        let to = o.map_or(k.as_str(), |o| o.to);
        match v {
            Value::Boolean(true) => out.push(to.to_string()),
            Value::Boolean(false) => {}
            v => {
                let mut text = word(&v, opts)?;
                if let Some(o) = o.filter(|o| !o.unit.is_empty() && is_number(&v)) {
                    text.push_str(o.unit);
                }
                out.push(match o {
                    Some(o) if o.spaced && to.is_empty() => text,
                    Some(o) if o.spaced => format!("{to} {text}"),
                    _ => format!("{to}={text}"),
                });
            }
        }
    }
    Ok(out)
}

/// A placeholder's argument: `{}` as a word, `{UNIT}` with UNIT appended to a number.
fn placeholder(spec: &str, v: &Value) -> Result<String> {
    let mut text = word(v, &[])?;
    if !spec.is_empty() && is_number(v) {
        text.push_str(spec);
    }
    Ok(text)
}

/// Fills the placeholders of `part` (a piece of template without `[…]`) from `it`. Returns
/// None when an argument is missing or nil.
fn fill<'a>(part: &str, it: &mut std::iter::Peekable<impl Iterator<Item = &'a Value>>) -> Result<Option<String>> {
    let mut out = String::new();
    let mut rest = part;
    while let Some(open) = rest.find('{') {
        out.push_str(&rest[..open]);
        let close = rest[open..].find('}').map(|c| open + c).unwrap_or(rest.len() - 1);
        match it.peek() {
            None | Some(Value::Nil) => {
                it.next();
                return Ok(None);
            }
            Some(v) => out.push_str(&placeholder(&rest[open + 1..close], v)?),
        }
        it.next();
        rest = &rest[close + 1..];
    }
    out.push_str(rest);
    Ok(Some(out))
}

/// The command text for a call of `b` with `args` (the arguments after the handle).
pub fn render(b: &Bridge, args: &[Value]) -> Result<String> {
    let mut out = String::new();
    let mut it = args.iter().peekable();
    let mut rest = b.template;
    while !rest.is_empty() {
        let (part, optional, next) = match rest.find('[') {
            Some(0) => {
                let close = rest.find(']').unwrap_or(rest.len() - 1);
                (&rest[1..close], true, &rest[close + 1..])
            }
            Some(open) => (&rest[..open], false, &rest[open..]),
            None => (rest, false, ""),
        };
        match fill(part, &mut it)? {
            Some(text) => out.push_str(&text),
            None if optional => {}
            None => {
                let spec = part.find('{').map(|o| &part[o..=part[o..].find('}').map_or(o, |c| o + c)]);
                return Err(usage(b, crate::msg!("script-missing-argument", spec = spec.unwrap_or("{}"))));
            }
        }
        rest = next;
    }
    let mut out = out.trim_end().to_string();
    // `cmd` (an empty template) takes command text as typed.
    let raw = b.template.is_empty();
    for arg in it {
        let words = match arg {
            Value::Table(t) if !is_list(t) => options(t, b.options)?,
            Value::Nil => continue,
            Value::String(s) if raw => {
                vec![s.to_str().map_err(|_| Error::usage(crate::msg!("script-command-not-utf8")))?.to_string()]
            }
            v => vec![word(v, b.options)?],
        };
        for w in words {
            if !out.is_empty() {
                out.push(' ');
            }
            out.push_str(&w);
        }
    }
    if out.trim().is_empty() {
        return Err(usage(b, crate::msg!("script-nothing-to-run")));
    }
    Ok(out)
}

/// Runs row `b` on device `name` with `args`; returns one table per command result.
pub fn call(lua: &Lua, name: &str, b: &Bridge, args: &[Value]) -> mlua::Result<mlua::MultiValue> {
    let line = render(b, args).map_err(super::error::raise)?;
    if !b.family.is_empty() {
        let family = api::with_shell(lua, |sh| {
            let i = api::index(sh, name)?;
            Ok(sh.session.entries()[i].device.info().family)
        })?;
        if !b.applies_to(family) {
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
        assert_eq!(render_lua("pto", "0, {cycle=500, count=1000}").unwrap(), "pto 0 count=1000 cycle=500us");
        assert_eq!(render_lua("pto", "0, {cycle='1ms', count=10}").unwrap(), "pto 0 count=10 cycle=1ms");
        assert_eq!(
            render_lua("pwm", "0, {cycle=1000, width=250}, 'async'").unwrap(),
            "pwm 0 cycle=1000us width=250us async"
        );
        assert_eq!(render_lua("move_abs", "10000, {rpm=300}").unwrap(), "servo move abs 10000 speed=300rpm");
        assert_eq!(
            render_lua("move_rel", "-5, {speed='10rpm', acc='100rps/s'}").unwrap(),
            "servo move rel -5 acc=100rps/s speed=10rpm"
        );
        assert_eq!(render_lua("jog", "{rpm=-50}").unwrap(), "servo jog -50rpm");
        assert_eq!(render_lua("jog", "'100rpm'").unwrap(), "servo jog 100rpm");
        assert_eq!(render_lua("enable", "").unwrap(), "servo enable");
        assert_eq!(render_lua("fault_reset", "").unwrap(), "servo fault-reset");
        assert_eq!(render_lua("home", "{method=35}").unwrap(), "servo home method=35");
        assert_eq!(
            render_lua(
                "profile",
                "0, 'VB3000', {{cycle='500us', count=1000}, {cycle=250, count=2000}, {freq=4000, count=9}}"
            )
            .unwrap(),
            "profile 0 at VB3000 [(count=1000, cycle=500us), (count=2000, cycle=250us), (count=9, freq=4000)]"
        );
        assert_eq!(
            render_lua("profile", "0, 'VB3001', {{cycle=500, count=2}}, {force=true, plan=false}").unwrap(),
            "profile 0 at VB3001 [(count=2, cycle=500us)] force"
        );
        assert_eq!(
            render_lua("hsc", "0, {mode=9, pv={100, 200}, relative=true, cyclic=true, at='VB3009', cv=100}").unwrap(),
            "hsc 0 at VB3009 cv=100 cyclic mode=9 pv=[100, 200] relative"
        );
        assert_eq!(render_lua("hdef", "1, 12").unwrap(), "hdef 1 12");
        assert_eq!(render_lua("wait_event", "28, 5000").unwrap(), "wait event 28 timeout=5000ms");
        assert_eq!(render_lua("wait_event", "28, '2s'").unwrap(), "wait event 28 timeout=2s");
        assert_eq!(render_lua("wait_event", "28").unwrap(), "wait event 28", "the timeout is optional");
        assert_eq!(render_lua("wait_target", "").unwrap(), "servo wait target");
        assert_eq!(render_lua("wait_target", "1500").unwrap(), "servo wait target timeout=1500ms");
        assert_eq!(render_lua("events", "{keep=true}").unwrap(), "events keep");
        assert_eq!(render_lua("eeprom_dump", "'my backup.bin'").unwrap(), "eeprom dump \"my backup.bin\"");
        assert_eq!(
            render_lua("sim_quad", "'I0.1', 'I0.0', {freq='1kHz', dir='up'}").unwrap(),
            "sim quad I0.1 I0.0 dir=up freq=1kHz"
        );
        assert_eq!(render_lua("sim_off", "'I0.1'").unwrap(), "sim input I0.1 off");
        assert_eq!(render_lua("pto", "0, {freq=2000.0}").unwrap(), "pto 0 freq=2000");
        assert_eq!(render_lua("cmd", "'get VW0'").unwrap(), "get VW0");
        assert_eq!(render_lua("params_diff", "'a.toml'").unwrap(), "servo params diff a.toml");
        assert_eq!(render_lua("params_diff", "{with='servo2'}").unwrap(), "servo params diff --with servo2");
        assert_eq!(
            render_lua("data_save", "'r.toml', 'VB0..VB9', 'eeprom'").unwrap(),
            "data save r.toml VB0..VB9 eeprom"
        );
    }

    #[test]
    fn a_missing_template_argument_is_a_usage_error() {
        let e = render_lua("profile", "0").unwrap_err();
        assert!(e.message.contains("missing argument for `{}`"), "{e}");
        assert!(e.hint.clone().unwrap().contains("profile {} at {}"));
        assert!(render_lua("pls", "").is_err());
        assert!(render_lua("rtc_set", "nil").is_err());
        assert!(render_lua("cmd", "").is_err());
    }
    #[test]
    fn method_names_are_unique() {
        for (i, b) in BRIDGE.iter().enumerate() {
            assert!(BRIDGE[i + 1..].iter().all(|o| o.method != b.method), "{} twice", b.method);
        }
    }
}
