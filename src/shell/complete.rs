//! Tab completion and inline hints for the REPL, as pure functions of (line, cursor, [`View`]).
//!
//! Everything a technician can type comes from the one place that defines it: command names,
//! usages and sub-commands from `commands::COMMANDS`, operands (with their meaning) from each
//! open device's `OperandSpace::complete/describe`, device names and `device:` prefixes from
//! the session, profile names from the profile file. So a command or device family added later
//! completes without touching this file. The rustyline glue lives in `helper.rs`; keeping the
//! logic here free of the editor and of the file system (file listing is injected) makes it
//! unit-testable on plain strings.

use super::commands::{find, forms, CommandSpec, COMMANDS};
use crate::core::OperandSpace;

/// An open device, as completion sees it.
pub struct DeviceView<'a> {
    pub name: &'a str,
    pub family: &'a str,
    pub model: &'a str,
    pub space: &'a dyn OperandSpace,
    /// The device's tag names (`crate::names`): completed beside its operands, their comments
    /// as hints.
    pub names: Option<&'a crate::names::Names>,
}

/// A device profile (from the profile file), as completion sees it.
pub struct ProfileView<'a> {
    pub name: &'a str,
    pub url: &'a str,
}

/// What completion may know about the session.
pub struct View<'a> {
    pub devices: Vec<DeviceView<'a>>,
    /// Index of the device operands without a prefix go to.
    pub current: Option<usize>,
    pub profiles: Vec<ProfileView<'a>>,
    /// Lists file-system paths starting with a prefix (injected so tests need no files).
    pub files: &'a dyn Fn(&str) -> Vec<String>,
}

/// One completion: the text that replaces the word under the cursor, and its meaning.
#[derive(Clone, Debug, PartialEq)]
pub struct Suggestion {
    pub text: String,
    pub meaning: String,
}

/// Completions for the word that starts at `start`.
#[derive(Clone, Debug, PartialEq)]
pub struct Completion {
    pub start: usize,
    pub items: Vec<Suggestion>,
}

/// An inline hint: text the user can accept (→) and a note shown after it.
#[derive(Clone, Debug, PartialEq, Default)]
pub struct Hint {
    pub insert: Option<String>,
    pub note: String,
}

/// Commands whose argument is a file (`run FILE`, `eeprom dump FILE`, `sim program load
/// FILE.il`): (command, the words before the file after an optional `[DEVICE]`).
/// Options named `to=`/`file=` complete paths for every command.
pub static FILE_ARGS: &[(&str, &[&str])] = &[
    ("run", &[]),
    ("source", &[]),
    ("eeprom", &["dump"]),
    ("eeprom", &["restore"]),
    ("eeprom", &["load"]),
    ("eeprom", &["save"]),
    ("sim", &["program", "load"]),
    ("umpk", &["program"]),
    ("data", &["save"]),
    ("data", &["diff"]),
    ("data", &["load"]),
    ("servo", &["params", "save"]),
    ("servo", &["params", "diff"]),
    ("servo", &["params", "load"]),
];

/// Option keys whose value is a path.
const PATH_KEYS: &[&str] = &["to", "file"];

/// What the word under the cursor is.
#[derive(Clone, Copy, Debug, PartialEq)]
enum Kind {
    Command,
    Subcommand,
    Devices,
    Profiles,
    Url,
    Operands,
    HelpTopic,
    Files,
    /// K2 model names (`models K209`).
    Models,
    /// DS402 operating modes (`servo mode p`).
    ServoModes,
    /// The options and words of the command's forms (`pto 0 fr` → `freq=`).
    Options,
    Nothing,
}

/// The command being typed and the word under the cursor.
struct Ctx<'l> {
    cmd: Option<&'static CommandSpec>,
    /// The first word, lower-cased (also when it is not a known command).
    name: String,
    /// Words between the command name and the word under the cursor.
    args: Vec<&'l str>,
    word: &'l str,
    start: usize,
}

fn is_break(c: char) -> bool {
    c == ' ' || c == ',' || c == '\t'
}

fn context(line: &str, pos: usize) -> (Ctx<'_>, bool) {
    let pos = pos.min(line.len());
    let head = &line[..pos];
    let seg_start = head.rfind(';').map(|i| i + 1).unwrap_or(0);
    let seg = &head[seg_start..];
    let wstart = seg.rfind(is_break).map(|i| i + 1).unwrap_or(0);
    let word = &seg[wstart..];
    let before: Vec<&str> = seg[..wstart].split(is_break).filter(|w| !w.is_empty()).collect();
    let at_command = before.is_empty();
    let name = before.first().map(|n| n.to_ascii_lowercase()).unwrap_or_default();
    let cmd = find(&name);
    let args = before.iter().skip(1).copied().collect();
    (Ctx { cmd, name, args, word, start: seg_start + wstart }, at_command)
}

fn kind(ctx: &Ctx, at_command: bool, view: &View) -> Kind {
    if at_command {
        return Kind::Command;
    }
    let n = ctx.args.len();
    let sub = ctx.args.first().copied().unwrap_or("");
    let rest = after_device(ctx, view);
    // File arguments by name, so `run FILE` completes paths even before `run` is registered.
    if FILE_ARGS.iter().any(|(c, words)| {
        *c == ctx.name && (rest.len() == words.len() && rest.iter().zip(*words).all(|(a, w)| a.eq_ignore_ascii_case(w)))
    }) {
        return Kind::Files;
    }
    if let Some((k, _)) = ctx.word.split_once('=') {
        if PATH_KEYS.contains(&k) {
            return Kind::Files;
        }
        if ctx.name != "set" {
            return Kind::Nothing;
        }
    }
    let Some(cmd) = ctx.cmd else { return Kind::Nothing };
    match cmd.name {
        "use" | "close" => {
            if n == 0 {
                Kind::Devices
            } else {
                Kind::Nothing
            }
        }
        "connect" => match n {
            0 => Kind::Profiles,
            1 if !view.profiles.iter().any(|p| p.name == sub) => Kind::Url,
            _ => Kind::Nothing,
        },
        "help" => {
            if n == 0 {
                Kind::HelpTopic
            } else {
                Kind::Nothing
            }
        }
        "devices" | "quit" | "paths" | "ports" => Kind::Nothing,
        "models" => {
            if n == 0 {
                Kind::Models
            } else {
                Kind::Nothing
            }
        }
        // A command whose sub-command comes first (`sim step`, `servo move`); `pto N status`
        // names its sub-command later, after the channel.
        _ if !cmd.subcommands.is_empty() && rest.is_empty() && !cmd.usage.starts_with(&format!("{} N", cmd.name)) => {
            Kind::Subcommand
        }
        "servo" if rest.len() == 1 && rest[0].eq_ignore_ascii_case("mode") => Kind::ServoModes,
        // What the command's forms take there: operands (`get`, `watch`, `servo read`), or
        // options and the forms' own words (`pto 0 freq=`, `servo move abs`).
        _ if forms::takes_operands(cmd, sub_of(cmd, rest)) => Kind::Operands,
        _ => Kind::Options,
    }
}

/// The sub-command among the words typed (`servo axis1 move …` → `move`), if the command has
/// sub-commands.
fn sub_of(cmd: &CommandSpec, rest: &[&str]) -> Option<&'static str> {
    rest.first().and_then(|r| cmd.subcommands.iter().find(|s| r.eq_ignore_ascii_case(s)).copied())
}

/// The words after the command, without a leading `[DEVICE]` (`servo axis2 mode` → `mode`)
/// for the commands whose usage has one.
fn after_device<'c>(ctx: &'c Ctx, view: &View) -> &'c [&'c str] {
    let takes_device = ctx.cmd.is_some_and(|c| c.usage.contains("[DEVICE]"));
    match ctx.args.first() {
        Some(first)
            if takes_device
                && !ctx.cmd.is_some_and(|c| c.subcommands.contains(first))
                && view.devices.iter().any(|d| d.name == *first) =>
        {
            &ctx.args[1..]
        }
        _ => &ctx.args,
    }
}

fn starts_with_ci(s: &str, prefix: &str) -> bool {
    s.len() >= prefix.len() && s.is_char_boundary(prefix.len()) && s[..prefix.len()].eq_ignore_ascii_case(prefix)
}

fn commands(word: &str) -> Vec<Suggestion> {
    let mut v: Vec<Suggestion> = COMMANDS
        .iter()
        .filter(|c| starts_with_ci(c.name, word))
        .map(|c| Suggestion { text: c.name.to_string(), meaning: c.summary() })
        .collect();
    if v.is_empty() {
        for c in COMMANDS {
            for a in c.aliases.iter().filter(|a| starts_with_ci(a, word)) {
                v.push(Suggestion { text: a.to_string(), meaning: format!("= {}: {}", c.name, c.summary()) });
            }
        }
    }
    v
}

fn devices(word: &str, view: &View, suffix: &str) -> Vec<Suggestion> {
    view.devices
        .iter()
        .filter(|d| starts_with_ci(d.name, word))
        .map(|d| Suggestion { text: format!("{}{suffix}", d.name), meaning: format!("{} {}", d.family, d.model) })
        .collect()
}

fn from_space(d: &DeviceView, prefix: &str, word: &str) -> Vec<Suggestion> {
    let names = d.names.map(|n| n.complete(word)).unwrap_or_default();
    names
        .into_iter()
        .chain(d.space.complete(word))
        .map(|c| Suggestion { text: format!("{prefix}{}", c.text), meaning: c.meaning })
        .collect()
}

/// Operands of the device the word addresses (`dev:…` or the current one), plus `device:`
/// prefixes for an unprefixed word.
fn operands(word: &str, view: &View) -> Vec<Suggestion> {
    if let Some((dev, rest)) = word.split_once(':') {
        return match view.devices.iter().find(|d| d.name == dev) {
            Some(d) => from_space(d, &format!("{dev}:"), rest),
            None => Vec::new(),
        };
    }
    let mut v = match view.current.and_then(|i| view.devices.get(i)) {
        Some(d) => from_space(d, "", word),
        None => Vec::new(),
    };
    if !word.is_empty() {
        v.extend(devices(word, view, ":"));
    }
    v
}

/// The models each simulator scheme takes after its colon: (scheme, names, what).
fn sim_models() -> [(&'static str, Vec<&'static str>, &'static str); 3] {
    [
        ("sim:", crate::k2::catalog::MODELS.iter().map(|m| m.name).collect(), "simulated K2"),
        ("sim-fx:", crate::fx::model::MODELS.iter().map(|m| m.name).collect(), "simulated FX PLC"),
        ("sim-umpk:", crate::umpk::model::MODELS.iter().map(|m| m.name).collect(), "simulated UMPK"),
    ]
}

fn models(word: &str) -> Vec<Suggestion> {
    crate::k2::catalog::MODELS
        .iter()
        .filter(|m| starts_with_ci(m.name, word))
        .map(|m| Suggestion { text: m.name.to_string(), meaning: "K2 model".into() })
        .collect()
}

fn servo_modes(word: &str) -> Vec<Suggestion> {
    crate::servo::ds402::MODES
        .iter()
        .map(|n| crate::servo::ds402::mode_name(*n))
        .filter(|m| starts_with_ci(m, word))
        .map(|m| Suggestion { text: m.to_string(), meaning: crate::msg!("shell-complete-operating-mode").text })
        .collect()
}

fn urls(word: &str, view: &View) -> Vec<Suggestion> {
    let mut v: Vec<Suggestion> = Vec::new();
    for (scheme, names, what) in sim_models() {
        if starts_with_ci(word, scheme) {
            for name in names {
                let text = format!("{scheme}{name}");
                if starts_with_ci(&text, word) {
                    v.push(Suggestion { text, meaning: what.into() });
                }
            }
            return v;
        }
    }
    for (s, meaning, ..) in crate::session::SCHEMES {
        if starts_with_ci(s, word) {
            v.push(Suggestion { text: s.to_string(), meaning: meaning.to_string() });
        }
    }
    v.extend(profiles(word, view));
    v
}

fn profiles(word: &str, view: &View) -> Vec<Suggestion> {
    view.profiles
        .iter()
        .filter(|p| starts_with_ci(p.name, word))
        .map(|p| Suggestion { text: p.name.to_string(), meaning: format!("profile: {}", p.url) })
        .collect()
}

fn files(word: &str, view: &View) -> Vec<Suggestion> {
    let (key, path) = match word.split_once('=') {
        Some((k, p)) => (format!("{k}="), p),
        None => (String::new(), word),
    };
    (view.files)(path).into_iter().map(|p| Suggestion { text: format!("{key}{p}"), meaning: String::new() }).collect()
}

/// The option keys of the command's forms (`freq=`, with the form's example value as its
/// meaning) starting with `word`; with `words`, the forms' own words too (`strict`, `abs`).
fn options(cmd: &CommandSpec, rest: &[&str], word: &str, words: bool) -> Vec<Suggestion> {
    let sub = sub_of(cmd, rest);
    let typed = |k: &str| rest.iter().any(|r| r.split_once('=').is_some_and(|(t, _)| t.eq_ignore_ascii_case(k)));
    let mut v: Vec<Suggestion> = forms::options(cmd, sub)
        .into_iter()
        .filter(|(k, _)| starts_with_ci(k, word) && !typed(k))
        .map(|(k, e)| Suggestion { text: format!("{k}="), meaning: format!("option, e.g. {k}={e}") })
        .collect();
    if words {
        // A word typed, or one of its alternatives typed (`abs` for `rel`), is done.
        let rivals = forms::rivals(cmd, sub);
        let done = |w: &str| {
            rest.iter()
                .any(|r| r.eq_ignore_ascii_case(w) || rivals.iter().any(|(a, b)| a == w && b.eq_ignore_ascii_case(r)))
        };
        v.extend(
            forms::literals(cmd, sub)
                .into_iter()
                .filter(|w| starts_with_ci(w, word) && !done(w))
                .map(|w| Suggestion { meaning: format!("{} … {w}", cmd.name), text: w }),
        );
    }
    v
}

/// Completions for the word before `pos` in `line`.
pub fn complete(line: &str, pos: usize, view: &View) -> Completion {
    let (ctx, at_command) = context(line, pos);
    let word = ctx.word;
    let mut items = match kind(&ctx, at_command, view) {
        Kind::Command => commands(word),
        Kind::Subcommand => {
            let cmd = ctx.cmd.expect("a sub-command follows a command");
            cmd.subcommands
                .iter()
                .filter(|s| starts_with_ci(s, word))
                .map(|s| Suggestion { text: s.to_string(), meaning: format!("{} {s}", cmd.name) })
                .collect()
        }
        Kind::Devices => devices(word, view, ""),
        Kind::Profiles => {
            let mut v = profiles(word, view);
            v.extend(devices(word, view, "").into_iter().map(|mut s| {
                s.meaning = crate::msg!("shell-complete-open-device", profile = s.meaning.as_str()).text;
                s
            }));
            v
        }
        Kind::Url => urls(word, view),
        Kind::HelpTopic => {
            let mut v = commands(word);
            v.extend(operands(word, view));
            v
        }
        Kind::Operands => {
            if word.contains('=') {
                Vec::new()
            } else {
                let mut v = operands(word, view);
                if !word.is_empty() {
                    let rest = after_device(&ctx, view);
                    v.extend(options(ctx.cmd.expect("operands follow a command"), rest, word, false));
                }
                v
            }
        }
        Kind::Options => options(ctx.cmd.expect("options follow a command"), after_device(&ctx, view), word, true),
        Kind::Files => files(word, view),
        Kind::Models => models(word),
        Kind::ServoModes => servo_modes(word),
        Kind::Nothing => Vec::new(),
    };
    items.sort_by(|a, b| a.text.cmp(&b.text));
    items.dedup_by(|a, b| a.text == b.text);
    Completion { start: ctx.start, items }
}

/// The meaning of a complete operand (`SMB67` → `PTO0/PWM0 (Q0.0) control byte`), through
/// the device its prefix names.
fn meaning(word: &str, view: &View) -> Option<String> {
    let (d, body) = match word.split_once(':') {
        Some((dev, rest)) => (view.devices.iter().find(|d| d.name == dev)?, rest),
        None => (view.devices.get(view.current?)?, word),
    };
    let space = d.space;
    if let Some(n) = d.names.and_then(|n| n.get(body)) {
        return Some(if n.comment.is_empty() { n.operand.clone() } else { format!("{} · {}", n.operand, n.comment) });
    }
    let ops = space.parse(body).ok()?;
    let first = ops.first()?;
    let what = space.describe(first)?;
    Some(if ops.len() > 1 { format!("{} operands; {} — {what}", ops.len(), space.name(first)) } else { what })
}

/// The inline hint for the cursor at the end of `line`: the rest of a unique command or
/// operand, the usage after a bare command, or the meaning of the operand just typed.
pub fn hint(line: &str, pos: usize, view: &View) -> Option<Hint> {
    if pos != line.len() {
        return None;
    }
    let (ctx, at_command) = context(line, pos);
    let word = ctx.word;
    let k = kind(&ctx, at_command, view);
    if word.is_empty() {
        let cmd = ctx.cmd?;
        if !ctx.args.is_empty() || !line.ends_with(' ') {
            return None;
        }
        let usage = cmd.usage.split("   ").next().unwrap_or(cmd.usage);
        let rest = usage.split_once(' ').map(|(_, r)| r).unwrap_or("");
        return (!rest.is_empty()).then(|| Hint { insert: None, note: rest.to_string() });
    }
    if k == Kind::Command {
        let c = commands(word);
        return match c.as_slice() {
            [one] => {
                Some(Hint { insert: Some(one.text[word.len()..].to_string()), note: format!("  — {}", one.meaning) })
            }
            _ => None,
        };
    }
    if !matches!(k, Kind::Operands | Kind::HelpTopic | Kind::Options) {
        return None;
    }
    let operand = word.split_once('=').map(|(o, _)| o).unwrap_or(word);
    if let Some(m) = meaning(operand, view) {
        return Some(Hint { insert: None, note: format!("  — {m}") });
    }
    if word.contains('=') {
        return None;
    }
    let c = complete(line, pos, view);
    match c.items.as_slice() {
        [one] if starts_with_ci(&one.text, word) => {
            let note = if one.meaning.is_empty() { String::new() } else { format!("  — {}", one.meaning) };
            Some(Hint { insert: Some(one.text[word.len()..].to_string()), note })
        }
        _ => None,
    }
}

/// Lists paths starting with `prefix` (directories get a trailing `/`), for [`View::files`].
pub fn list_paths(prefix: &str) -> Vec<String> {
    let (dir, stem) = match prefix.rfind('/') {
        Some(i) => (&prefix[..=i], &prefix[i + 1..]),
        None => ("", prefix),
    };
    let read = if dir.is_empty() { std::fs::read_dir(".") } else { std::fs::read_dir(dir) };
    let Ok(entries) = read else { return Vec::new() };
    let mut v: Vec<String> = entries
        .filter_map(|e| e.ok())
        .filter_map(|e| {
            let name = e.file_name().into_string().ok()?;
            if !name.starts_with(stem) || (stem.is_empty() && name.starts_with('.')) {
                return None;
            }
            let slash = if e.file_type().ok()?.is_dir() { "/" } else { "" };
            Some(format!("{dir}{name}{slash}"))
        })
        .collect();
    v.sort();
    v
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::core::{Candidate, DataType, Error, Operand, Result};
    use crate::k2::{catalog, space::K2Space};

    /// A small servo-like operand space with named objects, so the `device:` prefix path is
    /// exercised with a family other than the K2 without depending on the servo table's
    /// contents (the real servo is tested in `helper.rs`).
    struct Objects;
    const OBJECTS: &[(&str, &str)] =
        &[("target_velocity", "target velocity (rpm)"), ("target_position", "target position"), ("controlword", "")];
    impl OperandSpace for Objects {
        fn family(&self) -> &'static str {
            "test"
        }
        fn parse(&self, text: &str) -> Result<Vec<Operand>> {
            let i = OBJECTS.iter().position(|(n, _)| *n == text).ok_or_else(|| Error::usage("unknown object"))?;
            Ok(vec![Operand { key: i as u64, dtype: DataType::DInt, bits: 32 }])
        }
        fn name(&self, op: &Operand) -> String {
            OBJECTS[op.key as usize].0.to_string()
        }
        fn describe(&self, op: &Operand) -> Option<String> {
            Some(OBJECTS[op.key as usize].1.to_string()).filter(|s| !s.is_empty())
        }
        fn help(&self, _text: &str) -> Result<String> {
            Ok(String::new())
        }
        fn complete(&self, prefix: &str) -> Vec<Candidate> {
            OBJECTS
                .iter()
                .filter(|(n, _)| n.starts_with(prefix))
                .map(|(n, m)| Candidate { text: n.to_string(), meaning: m.to_string() })
                .collect()
        }
    }

    fn fake_files(prefix: &str) -> Vec<String> {
        ["scripts/", "scripts/ramp.lua", "trend.csv"]
            .iter()
            .filter(|p| p.starts_with(prefix))
            .map(|p| p.to_string())
            .collect()
    }

    fn with_view<R>(f: impl FnOnce(&View) -> R) -> R {
        let k205 = K2Space::new(catalog::find("K205-16DT").unwrap());
        let k209 = K2Space::new(catalog::find("K209M-56DT").unwrap());
        let view = View {
            devices: vec![
                DeviceView { name: "plc", family: "k2", model: "K205-16DT", space: &k205, names: None },
                DeviceView { name: "press2", family: "k2", model: "K209M-56DT", space: &k209, names: None },
                DeviceView { name: "servo", family: "test", model: "FD124S", space: &Objects, names: None },
            ],
            current: Some(0),
            profiles: vec![
                ProfileView { name: "press1", url: "rtu:/dev/ttyUSB0?baud=115200&unit=3" },
                ProfileView { name: "axis1", url: "kinco:/dev/ttyUSB1?id=1" },
            ],
            files: &fake_files,
        };
        f(&view)
    }

    fn texts(line: &str) -> (usize, Vec<String>) {
        with_view(|v| {
            let c = complete(line, line.len(), v);
            (c.start, c.items.into_iter().map(|s| s.text).collect())
        })
    }

    #[test]
    fn command_names_and_sub_commands() {
        assert_eq!(texts("ge"), (0, vec!["get".to_string()]));
        let (_, all) = texts("");
        assert_eq!(all.len(), COMMANDS.len(), "every command is offered on an empty line");
        assert_eq!(texts("sim ti"), (4, vec!["time".to_string()]));
        assert_eq!(texts("sim sn").1, vec!["snapshot", "snapshots"]);
        let after = texts("get VW0; se").1;
        assert!(
            after.contains(&"set".to_string()) && after.iter().all(|c| c.starts_with("se")),
            "the command after `;`"
        );
        assert!(texts("exi").1.contains(&"exit".to_string()), "aliases when no name matches");
    }

    #[test]
    fn set_smb6_offers_the_pto_registers_with_meaning() {
        with_view(|v| {
            let c = complete("set SMB6", 8, v);
            assert_eq!(c.start, 4);
            let smb67 = c.items.iter().find(|s| s.text == "SMB67").expect("SMB67 offered");
            assert!(smb67.meaning.contains("PTO0") && smb67.meaning.contains("control"), "{smb67:?}");
            assert!(c.items.iter().all(|s| s.text.starts_with("SMB6")), "{:?}", c.items);
            // After a comma, the next item completes too; after `=` the value does not.
            let c = complete("set VW0=1, SMB6", 15, v);
            assert_eq!(c.start, 11);
            assert!(c.items.iter().any(|s| s.text == "SMB67"));
            assert!(complete("set SMB67=16", 12, v).items.is_empty());
        });
    }

    /// A device's tag names complete beside its operands, the operand and the comment as the
    /// meaning, also after its `device:` prefix; a whole name's hint is that meaning too.
    #[test]
    fn tag_names_complete_with_their_comments() {
        let k205 = K2Space::new(catalog::find("K205-16DT").unwrap());
        let table = crate::tags::TagTable::parse_text(
            "name,address,type,comment\nTank2_Level,VD200,REAL,level of tank 2\nМотор_1_Пуск,Q0.0,BOOL,\n",
            "t.csv",
            None,
        )
        .unwrap();
        let names = crate::names::Names::resolve(table, &k205).unwrap();
        let view = View {
            devices: vec![DeviceView {
                name: "plc",
                family: "k2",
                model: "K205-16DT",
                space: &k205,
                names: Some(&names),
            }],
            current: Some(0),
            profiles: vec![],
            files: &fake_files,
        };
        let c = complete("get tank", 8, &view);
        assert_eq!(
            c.items,
            vec![Suggestion { text: "Tank2_Level".into(), meaning: "VD200/REAL · level of tank 2".into() }]
        );
        let line = "watch plc:мот";
        let c = complete(line, line.len(), &view);
        assert_eq!(c.items.iter().map(|s| s.text.as_str()).collect::<Vec<_>>(), ["plc:Мотор_1_Пуск"]);
        assert_eq!(c.items[0].meaning, "Q0.0");
        assert_eq!(meaning("Tank2_Level", &view).as_deref(), Some("VD200/REAL · level of tank 2"));
    }

    #[test]
    fn device_prefix_completes_that_devices_operands() {
        let (start, items) = texts("get servo:targ");
        assert_eq!(start, 4);
        assert_eq!(items, vec!["servo:target_position".to_string(), "servo:target_velocity".to_string()]);
        assert_eq!(texts("get press2:SMB6").1.first().map(String::as_str), Some("press2:SMB66"));
        assert_eq!(texts("get pr").1, vec!["press2:".to_string()], "device prefixes for an unprefixed word");
        assert!(texts("get nosuch:V").1.is_empty());
    }

    #[test]
    fn use_and_connect_offer_devices_and_profiles() {
        assert_eq!(texts("use pr").1, vec!["press2".to_string()]);
        assert_eq!(texts("connect pr").1, vec!["press1".to_string(), "press2".to_string()]);
        assert!(texts("connect press1 ").1.is_empty(), "a profile needs no URL");
        let (_, urls) = texts("connect x sim:K209");
        assert!(urls.contains(&"sim:K209M-56DT".to_string()) && urls.iter().all(|u| u.starts_with("sim:K209")));
        assert!(texts("connect x ").1.contains(&"sim:".to_string()));
        assert_eq!(texts("close s").1, vec!["servo".to_string()]);
    }

    #[test]
    fn files_after_run_and_to() {
        assert_eq!(texts("run scr").1, vec!["scripts/".to_string(), "scripts/ramp.lua".to_string()]);
        assert_eq!(texts("trace VW0 to=tr").1, vec!["to=trend.csv".to_string()]);
        assert_eq!(texts("eeprom dump t").1, vec!["trend.csv".to_string()]);
        assert!(texts("eeprom t").1.is_empty(), "only after the sub-command that takes a file");
    }

    #[test]
    fn files_after_sim_program_load_and_umpk_program() {
        assert_eq!(texts("sim program load scr").1, vec!["scripts/".to_string(), "scripts/ramp.lua".to_string()]);
        assert_eq!(texts("umpk program tr").1, vec!["trend.csv".to_string()]);
        assert_eq!(texts("umpk plc program tr").1, vec!["trend.csv".to_string()], "after a [DEVICE]");
        assert!(texts("sim program tr").1.is_empty(), "`sim program` alone takes no file");
    }

    #[test]
    fn models_profiles_and_servo_modes() {
        let (_, m) = texts("models K209");
        assert!(m.contains(&"K209M-56DT".to_string()) && m.iter().all(|t| t.starts_with("K209")), "{m:?}");
        assert_eq!(texts("connect x sim-fx:FX2").1.first().map(String::as_str), Some("sim-fx:FX2N"));
        assert_eq!(texts("connect x sim-umpk:").1, vec!["sim-umpk:UMPK16".to_string(), "sim-umpk:UMPK8".to_string()]);
        assert_eq!(texts("connect p pr").1, vec!["press1".to_string()], "a profile under another name");
        assert_eq!(texts("servo mode p").1, vec!["position".to_string(), "pulse".to_string()]);
        assert_eq!(texts("servo servo mode h").1, vec!["homing".to_string()], "after a [DEVICE]");
        assert!(texts("servo move p").1.is_empty(), "a move's position is no operand");
        assert_eq!(texts("servo read servo:targ").1.len(), 2, "`servo read` takes objects");
    }

    /// Options and the forms' own words come from the registry's forms, in place of operand
    /// areas where a command takes none.
    #[test]
    fn options_come_from_the_forms() {
        assert_eq!(texts("pto 0 fr").1, vec!["freq=".to_string()]);
        let (_, all) = texts("pto 0 ");
        for want in ["freq=", "count=", "cycle=", "strict", "status"] {
            assert!(all.contains(&want.to_string()), "{want} in {all:?}");
        }
        assert!(!all.iter().any(|t| t == "VW" || t == "MD" || t.starts_with("VW")), "no operand areas: {all:?}");
        assert!(!texts("pto 0 freq=1kHz ").1.contains(&"freq=".to_string()), "an option typed is not offered again");
        assert_eq!(texts("servo move abs 100 sp").1, vec!["speed=".to_string()]);
        // One of `abs|rel` typed: the other is not offered.
        assert!(!texts("servo move abs 1000 ").1.contains(&"rel".to_string()), "{:?}", texts("servo move abs 1000 ").1);
        assert!(!texts("servo move rel 10 ").1.contains(&"abs".to_string()));
        assert_eq!(texts("servo servo move ").1, vec!["abs", "acc=", "dec=", "rel", "speed="]);
        assert_eq!(texts("hsc 0 mo").1, vec!["mode=".to_string()]);
        with_view(|v| {
            let c = complete("pto 0 cy", 8, v);
            assert!(c.items[0].meaning.contains("cycle=500us"), "{:?}", c.items);
            assert_eq!(hint("pto 0 fr", 8, v).and_then(|h| h.insert).as_deref(), Some("eq="));
        });
    }

    /// The command card, `help COMMAND` and completion are made from the same forms: every
    /// form is in the card's row and in `help`'s text, and every option of a form completes
    /// after that form's words.
    #[test]
    fn card_help_and_completion_agree() {
        let card = crate::shell::commands::help::card_markdown();
        with_view(|v| {
            for (c, f) in forms::all() {
                let help = crate::shell::commands::help::command_help(c).replace("\n    ", " ");
                assert!(help.lines().any(|l| l == f.text), "`help {}` lacks `{}`:\n{help}", c.name, f.text);
                let row = card.lines().find(|l| l.starts_with(&format!("| `{}` |", c.name))).expect(c.name);
                assert!(row.contains(&format!("`{}`", f.text.replace('|', "\\|"))), "the card lacks `{}`", f.text);
                let sub = f.sub.map(|s| format!(" {s}")).unwrap_or_default();
                let line = forms::longest_line(c, &f, "1").unwrap_or(format!("{}{sub}", c.name));
                for (key, _) in forms::options(c, f.sub) {
                    let typed = format!("{line} {}", &key[..1]);
                    let got = complete(&typed, typed.len(), v);
                    assert!(
                        got.items.iter().any(|s| s.text == format!("{key}=")),
                        "`{typed}` does not offer {key}=: {:?}",
                        got.items
                    );
                }
            }
        });
    }

    #[test]
    fn options_complete_as_keys() {
        assert!(texts("watch VW0 ev").1.contains(&"every=".to_string()));
        assert!(!texts("get VW0 ev").1.contains(&"every=".to_string()));
    }

    #[test]
    fn hints_show_meaning_rest_and_usage() {
        with_view(|v| {
            let h = hint("set SMB67", 9, v).unwrap();
            assert_eq!(h.note, "  — PTO0/PWM0 (Q0.0) control byte");
            assert_eq!(h.insert, None);
            let h = hint("set SMB67=16#85", 15, v).unwrap();
            assert!(h.note.contains("control byte"), "the operand's meaning stays while typing the value");
            let h = hint("get servo:target_v", 18, v).unwrap();
            assert_eq!(h.insert.as_deref(), Some("elocity"));
            assert!(h.note.contains("rpm"));
            let h = hint("wat", 3, v);
            if find("watch").is_some() {
                assert_eq!(h.unwrap().insert.as_deref(), Some("ch"));
            }
            let h = hint("get ", 4, v).unwrap();
            assert!(h.note.starts_with("OPERAND"), "{h:?}");
            assert!(hint("set SMB67", 3, v).is_none(), "only at the end of the line");
            assert!(hint("get QQ", 6, v).is_none());
        });
    }

    #[test]
    fn real_paths_are_listed_with_directory_slashes() {
        let dir = std::env::temp_dir().join(format!("plcsh-complete-{}", std::process::id()));
        std::fs::create_dir_all(dir.join("sub")).unwrap();
        std::fs::write(dir.join("a.csv"), "").unwrap();
        let p = format!("{}/", dir.display());
        assert_eq!(list_paths(&p), vec![format!("{p}a.csv"), format!("{p}sub/")]);
        assert_eq!(list_paths(&format!("{p}s")), vec![format!("{p}sub/")]);
        std::fs::remove_dir_all(&dir).unwrap();
    }
}
