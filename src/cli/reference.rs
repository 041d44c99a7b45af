//! The tables of the guide's reference pages (docs/reference/*.md), made from the program's
//! own tables so the pages cannot drift from it: the command-line flags (clap's definition),
//! the exit statuses ([`crate::core::exit`]), the K2 Modbus map
//! ([`crate::k2::modbus_map::REGIONS`] and the same address lookup the driver uses), the K2
//! model catalogue ([`crate::k2::catalog::MODELS`]) and the error kinds
//! ([`crate::core::ErrorKind`]). Each page holds its table between
//! `<!-- generated: NAME … -->` and `<!-- end generated: NAME -->`; tests/reference_docs.rs
//! compares them (and `PLCSH_BLESS=1 cargo test --test reference_docs` rewrites them).

use crate::core::msg::Lang;
use crate::core::{exit, ErrorKind};
use crate::k2::catalog::{self, MODELS};
use crate::k2::modbus_map::{self, Table, REGIONS};
use crate::k2::operand::Area;
use crate::k2::space::K2Space;

/// One generated table: the page (relative to docs/), its name in the markers, its renderer.
pub struct Generated {
    pub page: &'static str,
    pub name: &'static str,
    pub render: fn() -> String,
}

/// Every generated table of the guide.
pub static GENERATED: &[Generated] = &[
    Generated { page: "reference/command-line.md", name: "flags", render: flags_markdown },
    Generated { page: "reference/command-line.md", name: "environment", render: environment_markdown },
    Generated { page: "reference/exit-status.md", name: "exit statuses", render: exit_markdown },
    Generated { page: "reference/modbus-addresses.md", name: "modbus map", render: modbus_map_markdown },
    Generated { page: "reference/modbus-addresses.md", name: "modbus examples", render: modbus_examples_markdown },
    Generated { page: "reference/k2-models.md", name: "k2 models", render: models_markdown },
    Generated { page: "reference/k2-models.md", name: "k2 areas", render: areas_markdown },
    Generated { page: "reference/errors.md", name: "error kinds", render: error_kinds_markdown },
    Generated { page: "reference/errors.md", name: "message ids", render: message_ids_markdown },
];

/// The opening marker of a generated table.
pub fn start_marker(name: &str) -> String {
    format!(
        "<!-- generated: {name}; made from the program's tables (PLCSH_BLESS=1 cargo test --test reference_docs) -->\n"
    )
}

/// The closing marker of a generated table.
pub fn end_marker(name: &str) -> String {
    format!("<!-- end generated: {name} -->")
}

/// Text for a table cell: one line, `|` escaped.
fn cell(s: &str) -> String {
    s.split_whitespace().collect::<Vec<_>>().join(" ").replace('|', "\\|")
}

/// Environment variables and the flag whose default they set (`None`: no flag).
pub static ENVIRONMENT: &[(&str, Option<&str>, &str)] = &[
    ("PLCSH_STATE", Some("--state"), "the simulator state file (`none`: keep nothing), when --state is not given"),
    ("PLCSH_CONFIG", Some("--config"), "the device profile file, when --config is not given"),
    ("PLCSH_LIB", None, "folders searched first for Lua modules (`require`), separated like PATH"),
    ("PLCSH_SNAPSHOTS", None, "the folder named snapshots are kept in (`sim snapshot save NAME`)"),
    ("PLCSH_MQTT_USERNAME", None, "`publish`: the broker user name (overrides the profile file's `[mqtt]`)"),
    ("PLCSH_MQTT_PASSWORD", None, "`publish`: the broker password (overrides the profile file's `[mqtt]`)"),
    (
        "PLCSH_CONSOLE_VT",
        None,
        "Windows: `off` treats the console as one that does not draw escape codes (plain output)",
    ),
    (
        "PLCSH_LANG",
        Some("--lang"),
        "the language of messages (`en`, `ru`, `zh-CN`), when --lang is not given; before LC_ALL, LC_MESSAGES, LANG",
    ),
    ("NO_COLOR", None, "any non-empty value: no colour, even on a terminal (no-color.org)"),
];

/// The environment variable that sets a flag's default, if any.
fn env_of(long: &str) -> Option<&'static str> {
    ENVIRONMENT.iter().find(|(_, flag, _)| *flag == Some(long)).map(|(var, _, _)| *var)
}

/// The command line: one table per command (the top level, then every subcommand), each flag
/// with its value, default, environment variable and help, from clap's definition.
pub fn flags_markdown() -> String {
    use clap::CommandFactory;
    let cmd = super::Cli::command();
    let mut out = String::new();
    section(&mut out, "plcsh", &cmd, true);
    out
}

fn section(out: &mut String, path: &str, cmd: &clap::Command, top: bool) {
    let args: Vec<&clap::Arg> = cmd.get_arguments().filter(|a| !a.is_hide_set()).collect();
    if !args.is_empty() || top {
        let about = cmd.get_about().map(|a| a.to_string()).unwrap_or_default();
        if top {
            out.push_str("### Options of every command\n\n");
            out.push_str("Options marked *global* may also follow a subcommand (`plcsh sim serve --json`).\n\n");
        } else {
            out.push_str(&format!("### `{path}`\n\n{}\n\n", cell(&about)));
        }
        out.push_str("| flag | value | default | environment | what it does |\n|---|---|---|---|---|\n");
        for a in args {
            let value_names: Vec<String> =
                a.get_value_names().unwrap_or_default().iter().map(|v| v.to_string()).collect();
            let names = match (a.get_short(), a.get_long()) {
                (Some(s), Some(l)) => format!("`-{s}`, `--{l}`"),
                (None, Some(l)) => format!("`--{l}`"),
                (Some(s), None) => format!("`-{s}`"),
                (None, None) => {
                    let v =
                        if value_names.is_empty() { a.get_id().as_str().to_uppercase() } else { value_names.join(" ") };
                    format!("`{v}` (operand)")
                }
            };
            let takes = a.get_action().takes_values();
            let possible: Vec<String> = a.get_possible_values().iter().map(|p| p.get_name().to_string()).collect();
            let value = if !takes {
                if matches!(a.get_action(), clap::ArgAction::Count) {
                    "— (repeatable)".to_string()
                } else {
                    "—".to_string()
                }
            } else if !possible.is_empty() {
                possible.iter().map(|p| format!("`{p}`")).collect::<Vec<_>>().join(" \\| ")
            } else if a.get_long().is_some() || a.get_short().is_some() {
                format!("`{}`", value_names.join(" ").replace('|', "\\|"))
            } else {
                "—".to_string()
            };
            let default: Vec<String> =
                a.get_default_values().iter().map(|d| d.to_string_lossy().into_owned()).collect();
            let default =
                if default.is_empty() || !takes { "—".to_string() } else { format!("`{}`", default.join(" ")) };
            let env =
                a.get_long().and_then(|l| env_of(&format!("--{l}"))).map_or("—".to_string(), |e| format!("`{e}`"));
            let mut help = a.get_help().map(|h| h.to_string()).unwrap_or_default();
            if top && a.is_global_set() {
                help.push_str(" *(global)*");
            }
            out.push_str(&format!("| {names} | {value} | {default} | {env} | {} |\n", cell(&help)));
        }
        out.push('\n');
    }
    for sub in cmd.get_subcommands().filter(|s| !s.is_hide_set()) {
        section(out, &format!("{path} {}", sub.get_name()), sub, false);
    }
}

/// The environment variables plcsh reads.
pub fn environment_markdown() -> String {
    let mut t = String::from("| variable | what it sets | flag |\n|---|---|---|\n");
    for (var, flag, what) in ENVIRONMENT {
        let flag = flag.map_or("—".to_string(), |f| format!("`{f}`"));
        t.push_str(&format!("| `{var}` | {} | {flag} |\n", cell(what)));
    }
    t
}

/// The exit statuses ([`exit::STATUSES`]).
pub fn exit_markdown() -> String {
    let mut t = String::from("| status | name | when |\n|---|---|---|\n");
    for s in exit::STATUSES {
        t.push_str(&format!("| **{}** | {} | {} |\n", s.code, (s.name)(Lang::En), cell(&(s.when)(Lang::En))));
    }
    t
}

/// mbpoll's `-t` for a table (0 coils, 1 discrete inputs, 3 input registers, 4 holding registers).
fn mbpoll_type(t: Table) -> u8 {
    match t {
        Table::Coils => 0,
        Table::DiscreteInputs => 1,
        Table::InputRegisters => 3,
        Table::HoldingRegisters => 4,
    }
}

/// The function codes of a table: reads, then writes.
fn function_codes(t: Table) -> String {
    let fcs: Vec<String> = (1u8..=0x10)
        .filter(|&fc| modbus_map::Table::of_fc(fc).is_some_and(|(tt, _)| tt == t))
        .map(|fc| format!("{fc:02}"))
        .collect();
    fcs.join(", ")
}

/// The model the address examples are worked on (it has every area of the map).
pub const EXAMPLE_MODEL: &str = "K209EA-50DX";

fn example_model() -> &'static catalog::Model {
    catalog::find(EXAMPLE_MODEL).expect("the example model is in the catalogue")
}

/// The K2 Modbus map, one row per region ([`REGIONS`]), with the address of the area's first
/// element and its last one on each model size.
pub fn modbus_map_markdown() -> String {
    let mut t = String::from(
        "| PLC area | Modbus table | function codes | rule (0-based protocol address) | first address | mbpoll |\n|---|---|---|---|---|---|\n",
    );
    for r in REGIONS {
        let rule = match (r.area, r.table.is_bits()) {
            (Area::M, _) => format!("M byte b bit k → {} + 8·b + k", r.base),
            (_, true) => format!("{} byte b bit k → {} + 8·b + k", r.area.name(), r.base),
            (a, false) => format!("{}W2n → {} + n", a.name(), r.base),
        };
        t.push_str(&format!(
            "| {} ({}) | {} | {} | {} | {} | `-t {} -r {}` |\n",
            r.area.name(),
            r.area.meaning(),
            r.table.name(),
            function_codes(r.table),
            rule,
            r.base,
            mbpoll_type(r.table),
            r.base as u32 + 1
        ));
    }
    t
}

/// Operands and where they are on the wire: the driver's own lookup ([`modbus_map::locate_read`]).
pub fn modbus_examples_markdown() -> String {
    let model = example_model();
    let space = K2Space::new(model);
    let examples = [
        "VW0", "VW2", "VW100", "VB101", "VD100", "Q0.0", "Q1.2", "M0.0", "M10.3", "MW0", "I0.0", "AIW0", "AIW2", "AQW0",
    ];
    let mut t = String::from(
        "| operand | read from | function code | protocol address (0-based) | mbpoll (1-based `-r`) |\n|---|---|---|---|---|\n",
    );
    for text in examples {
        let op = crate::k2::operand::parse_one(text).expect("an example operand");
        let span = modbus_map::locate_read(&space, &op).expect("an example operand in the map");
        let table = span.table();
        let addresses =
            if span.count == 1 { span.start.to_string() } else { format!("{}…{}", span.start, span.end() - 1) };
        t.push_str(&format!(
            "| `{text}` | {} | {:02} | {addresses} | `mbpoll -t {} -r {} -c {}` |\n",
            table.name(),
            table.read_fc(),
            mbpoll_type(table),
            span.start as u32 + 1,
            span.count
        ));
    }
    t.push_str(&format!(
        "\n(Addresses as on a {}; the rules hold for every model, the last address differs.)\n",
        model.name
    ));
    t
}

/// The K2 models: I/O, analog channels, counters and pulse outputs ([`MODELS`]).
pub fn models_markdown() -> String {
    let khz = |hz: u32| if hz.is_multiple_of(1000) { format!("{}k", hz / 1000) } else { hz.to_string() };
    let mut t = String::from("| model | CPU | DI | DO | DIO | AI | AO | HSC (single-phase / A-B, Hz) | pulse outputs (output, max Hz) | links |\n|---|---|---|---|---|---|---|---|---|---|\n");
    for m in MODELS {
        let hsc: Vec<String> =
            m.hsc.iter().map(|h| format!("HSC{} {}/{}", h.channel, khz(h.max_hz_single), khz(h.max_hz_ab))).collect();
        let pto: Vec<String> =
            m.pto.iter().map(|p| format!("PTO{} {} {}", p.channel, p.output, khz(p.max_hz))).collect();
        let pto = if m.relay { "none (relay outputs)".to_string() } else { pto.join(", ") };
        let dout = if m.relay { format!("{} relay", m.dout) } else { m.dout.to_string() };
        let links = if m.ethernet && !m.serial.contains("Ethernet") {
            format!("{}, Ethernet (Modbus TCP)", m.serial)
        } else {
            m.serial.to_string()
        };
        let dash = |n: u8| if n == 0 { "—".to_string() } else { n.to_string() };
        t.push_str(&format!(
            "| {} | {} | {} | {dout} | {} | {} | {} | {} | {pto} | {} |\n",
            m.name,
            m.cpu,
            m.di,
            dash(m.dio),
            dash(m.ai),
            dash(m.ao),
            hsc.join(", "),
            cell(&links)
        ));
    }
    t
}

/// The operand areas per model: which operands exist, and the last of each.
pub fn areas_markdown() -> String {
    let mut t = String::from("| model | I | Q | M | V | AI | AQ |\n|---|---|---|---|---|---|---|\n");
    for m in MODELS {
        let bits = |area: &str, bytes: u32| {
            if bytes == 0 {
                "—".to_string()
            } else {
                format!("{area}0.0…{area}{}.7", bytes - 1)
            }
        };
        let words = |area: &str, bytes: u32| {
            if bytes == 0 {
                "—".to_string()
            } else {
                format!("{area}W0…{area}W{}", bytes - 2)
            }
        };
        t.push_str(&format!(
            "| {} | {} | {} | {} | VB0…VB{} | {} | {} |\n",
            m.name,
            bits("I", m.i_bytes),
            bits("Q", m.q_bytes),
            bits("M", m.m_bytes),
            m.v_bytes - 1,
            words("AI", m.ai_bytes),
            words("AQ", m.aq_bytes)
        ));
    }
    t.push_str(&format!(
        "\nEvery model also has SMB0…SMB{}, T0…T{} and C0…C{} (on a real K2 not in the Modbus map: they need the helper program).\n",
        catalog::SM_BYTES - 1,
        catalog::TIMERS - 1,
        catalog::COUNTERS - 1
    ));
    t
}

/// What an error kind means and what to do about it, from the catalogue's `error-kind-cause`
/// and `error-kind-fix` (a test checks that every kind has a text of its own there).
pub fn kind_text(kind: ErrorKind) -> (String, String) {
    // The guide's table is English; the catalogue has the same texts in every language.
    let en = crate::core::msg::Lang::En;
    (
        crate::msg!(lang: en, "error-kind-cause", kind = kind.name()).text,
        crate::msg!(lang: en, "error-kind-fix", kind = kind.name()).text,
    )
}

/// Every `error.kind`, with its meaning and what to do.
pub fn error_kinds_markdown() -> String {
    let mut t = String::from("| `kind` | what happened | what to do |\n|---|---|---|\n");
    for &k in ErrorKind::ALL {
        let (cause, fix) = kind_text(k);
        t.push_str(&format!("| `{}` | {} | {} |\n", k.name(), cell(&cause), cell(&fix)));
    }
    t
}

/// Every message id of the catalogue with its text in each language, arguments shown as
/// `$name` (a selector shows its catch-all form).
pub fn message_ids_markdown() -> String {
    use crate::core::msg::{self, Arg, Lang};
    let mut t = String::from("| id | en | ru | zh-CN |\n|---|---|---|---|\n");
    let mut variables = msg::variables_by_id(Lang::En);
    for id in msg::ids(Lang::En) {
        let vars = variables.remove(&id).unwrap_or_default();
        let args: Vec<(&str, Arg)> = vars.iter().map(|v| (v.as_str(), Arg::Text(format!("${v}")))).collect();
        let texts: Vec<String> = Lang::ALL.iter().map(|&l| cell(&msg::format_in(l, &id, &args))).collect();
        t.push_str(&format!("| `{id}` | {} |\n", texts.join(" | ")));
    }
    t
}

#[cfg(test)]
mod kind_tests {
    #[test]
    fn every_kind_has_its_own_text_in_every_language() {
        use crate::core::msg::{format_in, Lang};
        for &l in Lang::ALL {
            let mut seen = std::collections::BTreeSet::new();
            for &k in crate::core::ErrorKind::ALL {
                let cause = format_in(l, "error-kind-cause", &[("kind", k.name().into())]);
                let fix = format_in(l, "error-kind-fix", &[("kind", k.name().into())]);
                assert!(seen.insert(cause.clone()) && seen.insert(fix), "{}: `{}` shares its text", l.tag(), k.name());
            }
        }
    }
}
