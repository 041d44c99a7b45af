//! The message catalogue: every text a person reads is looked up here by a stable id with
//! named arguments, in English, Russian or Simplified Chinese (Project Fluent; one `.ftl`
//! file per language in `lib/locales/`, compiled into the program). The id travels with the
//! text ([`Msg`]) so an error carries it as its JSON `code`.
//!
//! Why Fluent: plural rules per language (Russian has three forms, selected with
//! `{ $n -> [one] … [few] … *[many] … }`), named arguments, whole sentences per language
//! (no text glued from translated pieces), and a maintained Rust implementation
//! (fluent-bundle) that needs no system library.
//!
//! Cost: nothing at start-up. The language is decided on the first message only
//! ([`language`]), and a message parses only the catalogue file it is in ([`index`],
//! [`bundle`]); a one-shot that prints values and no message parses none. Unicode isolation marks around arguments are off, so an operand in a
//! message is the same bytes as the operand typed.
//!
//! The language, first match wins: `--lang` ([`set_choice`]), `PLCSH_LANG`, then the
//! system's (`LC_ALL`, `LC_MESSAGES`, `LANG` on Unix; the user's UI language on Windows:
//! `core::platform::ui_language`); English when none names a language plcsh speaks (`C`
//! and `POSIX` are English). The environment is consulted only in the program
//! ([`follow_system`]); the library used in-process speaks English unless told. A lab grades
//! in the language its `lab.toml` names ([`set_language`]).

use fluent_bundle::concurrent::FluentBundle;
use fluent_bundle::{FluentArgs, FluentResource, FluentValue};
use std::sync::atomic::{AtomicU8, Ordering};
use std::sync::OnceLock;

/// The files of one language's catalogue, by subject, in this order (tests/messages.rs reads
/// the same list): `plcsh` (the shell and its devices), `tags` (tag tables), `names` (names
/// where operands go), `data` (parameter and data sets), `report` (commissioning reports),
/// `shell` (commands and options of the shell and the command line), `devices` (the servo,
/// UMPK and FX drivers and simulators, and the links), `tables` (descriptions of SM bytes,
/// servo objects, instructions and elements), `lab` (labs, scripts, recordings), `agent` (the
/// PLC-side helper and its checks), `k2` (the K2's driver, simulator, helpers, wiring and
/// snapshots), `engine` (the IL scan engine and its compiler). One file per subject keeps a
/// subject's messages together and lets work on two subjects go on side by side.
pub const CATALOGUE_FILES: [&str; 12] =
    ["plcsh", "tags", "names", "data", "report", "shell", "devices", "tables", "lab", "agent", "k2", "engine"];

macro_rules! catalogue {
    ($lang:literal) => {
        [
            include_str!(concat!("../../lib/locales/", $lang, "/plcsh.ftl")),
            include_str!(concat!("../../lib/locales/", $lang, "/tags.ftl")),
            include_str!(concat!("../../lib/locales/", $lang, "/names.ftl")),
            include_str!(concat!("../../lib/locales/", $lang, "/data.ftl")),
            include_str!(concat!("../../lib/locales/", $lang, "/report.ftl")),
            include_str!(concat!("../../lib/locales/", $lang, "/shell.ftl")),
            include_str!(concat!("../../lib/locales/", $lang, "/devices.ftl")),
            include_str!(concat!("../../lib/locales/", $lang, "/tables.ftl")),
            include_str!(concat!("../../lib/locales/", $lang, "/lab.ftl")),
            include_str!(concat!("../../lib/locales/", $lang, "/agent.ftl")),
            include_str!(concat!("../../lib/locales/", $lang, "/k2.ftl")),
            include_str!(concat!("../../lib/locales/", $lang, "/engine.ftl")),
        ]
    };
}

/// A language plcsh speaks.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum Lang {
    En,
    Ru,
    ZhCn,
}

impl Lang {
    /// Every language, English (the reference) first.
    pub const ALL: &'static [Lang] = &[Lang::En, Lang::Ru, Lang::ZhCn];

    /// The BCP 47 tag `--lang` and `lab.toml`'s `language` take: `en`, `ru`, `zh-CN`.
    pub fn tag(self) -> &'static str {
        match self {
            Lang::En => "en",
            Lang::Ru => "ru",
            Lang::ZhCn => "zh-CN",
        }
    }

    /// The language a tag or a POSIX locale names: `ru`, `ru_RU.UTF-8`, `zh-CN`, `zh_CN.GB2312`,
    /// `zh-Hans`, `en_GB`, `C`, `POSIX` (English). `None` for a language plcsh does not speak
    /// (`de_DE`) and for Traditional Chinese (`zh_TW`, `zh-Hant`): its readers get English
    /// rather than another script's characters.
    pub fn from_tag(tag: &str) -> Option<Lang> {
        // `ru_RU.UTF-8@euro` → `ru-ru`.
        let base = tag.trim().split(['.', '@']).next().unwrap_or("").replace('_', "-").to_ascii_lowercase();
        let mut parts = base.split('-');
        match parts.next().unwrap_or("") {
            "c" | "posix" if !base.contains('-') => Some(Lang::En),
            "en" => Some(Lang::En),
            "ru" => Some(Lang::Ru),
            "zh" => {
                let rest: Vec<&str> = parts.collect();
                let traditional = rest.iter().any(|p| matches!(*p, "tw" | "hk" | "mo" | "hant"));
                (!traditional).then_some(Lang::ZhCn)
            }
            _ => None,
        }
    }

    fn index(self) -> u8 {
        match self {
            Lang::En => 1,
            Lang::Ru => 2,
            Lang::ZhCn => 3,
        }
    }

    /// The whole catalogue of the language: its files ([`CATALOGUE_FILES`]) one after the other.
    fn source(self) -> &'static str {
        static JOINED: [OnceLock<String>; 3] = [OnceLock::new(), OnceLock::new(), OnceLock::new()];
        JOINED[self.index() as usize - 1].get_or_init(|| files(self).join("\n"))
    }
}

/// 0: not decided yet; otherwise [`Lang::index`].
static CURRENT: AtomicU8 = AtomicU8::new(0);
/// `--lang`, kept until the first message decides the language.
static CHOICE: OnceLock<Lang> = OnceLock::new();

/// Whether the environment (`PLCSH_LANG`, the system's language) may choose: set by the
/// program's entry point ([`follow_system`]). The library alone — tests that run commands
/// in-process, benchmarks — speaks English unless told otherwise, whatever the machine's locale.
static SYSTEM: std::sync::atomic::AtomicBool = std::sync::atomic::AtomicBool::new(false);

/// Lets `PLCSH_LANG` and the system's language choose (read on the first message).
pub fn follow_system() {
    SYSTEM.store(true, Ordering::Relaxed);
    CURRENT.store(0, Ordering::Relaxed);
}

/// `--lang`: wins over the environment. Cheap (no catalogue is read).
pub fn set_choice(lang: Lang) {
    let _ = CHOICE.set(lang);
    CURRENT.store(0, Ordering::Relaxed);
}

/// Makes `lang` the language of every later message (a lab's `language`).
pub fn set_language(lang: Lang) {
    CURRENT.store(lang.index(), Ordering::Relaxed);
}

/// The language messages are written in now (decided on the first call).
pub fn language() -> Lang {
    match CURRENT.load(Ordering::Relaxed) {
        1 => Lang::En,
        2 => Lang::Ru,
        3 => Lang::ZhCn,
        _ => {
            let lang = if SYSTEM.load(Ordering::Relaxed) {
                decide(CHOICE.get().copied(), |k| std::env::var(k).ok(), crate::core::platform::ui_language)
            } else {
                decide(CHOICE.get().copied(), |_| None, || None)
            };
            CURRENT.store(lang.index(), Ordering::Relaxed);
            lang
        }
    }
}

/// The rule of the module doc: `--lang`, `PLCSH_LANG`, then the system's language. An empty
/// variable counts as unset; a set one naming a language plcsh does not speak ends the search
/// with English (as gettext does for `LANG=de_DE`).
fn decide(choice: Option<Lang>, env: impl Fn(&str) -> Option<String>, system: impl Fn() -> Option<String>) -> Lang {
    if let Some(l) = choice {
        return l;
    }
    if let Some(v) = env("PLCSH_LANG").filter(|v| !v.trim().is_empty()) {
        return Lang::from_tag(&v).unwrap_or(Lang::En);
    }
    system().and_then(|s| Lang::from_tag(&s)).unwrap_or(Lang::En)
}

/// One parsed file of one language's catalogue, built on first use (index: language, then
/// [`CATALOGUE_FILES`]'s order).
type Bundle = FluentBundle<FluentResource>;
static BUNDLES: [[OnceLock<Bundle>; CATALOGUE_FILES.len()]; 3] =
    [const { [const { OnceLock::new() }; CATALOGUE_FILES.len()] }; 3];

/// How many catalogue files this process has parsed so far (tests: a one-shot that prints
/// values parses none).
pub fn catalogues_parsed() -> usize {
    BUNDLES.iter().flatten().filter(|b| b.get().is_some()).count()
}

/// The files of `lang`'s catalogue, as compiled in.
fn files(lang: Lang) -> [&'static str; CATALOGUE_FILES.len()] {
    match lang {
        Lang::En => catalogue!("en"),
        Lang::Ru => catalogue!("ru"),
        Lang::ZhCn => catalogue!("zh-CN"),
    }
}

/// Which file of `lang`'s catalogue defines each id: one pass over the text (a message starts
/// a line with `id =`; its other lines are indented, comments start with `#`), far cheaper than
/// parsing, so a message parses only the file it is in — a K2 error reads the K2's messages,
/// not the lab's or the servo's.
fn index(lang: Lang) -> &'static std::collections::HashMap<&'static str, u8> {
    static INDEX: [OnceLock<std::collections::HashMap<&'static str, u8>>; 3] =
        [OnceLock::new(), OnceLock::new(), OnceLock::new()];
    INDEX[lang.index() as usize - 1].get_or_init(|| {
        let files = files(lang);
        let lines: usize = files.iter().map(|t| t.len() / 64).sum();
        let mut map = std::collections::HashMap::with_capacity(lines);
        for (i, text) in files.into_iter().enumerate() {
            for line in text.lines() {
                // `id =` at the start of the line: lower-case letters, digits and `-`, then ` =`.
                let b = line.as_bytes();
                let n = b.iter().take_while(|c| c.is_ascii_lowercase() || c.is_ascii_digit() || **c == b'-').count();
                if n > 0 && b.get(n) == Some(&b' ') && b.get(n + 1) == Some(&b'=') {
                    map.insert(&line[..n], i as u8);
                }
            }
        }
        map
    })
}

/// The parsed file `file` of `lang`'s catalogue, built on first use.
fn bundle(lang: Lang, file: usize) -> &'static Bundle {
    BUNDLES[lang.index() as usize - 1][file].get_or_init(|| {
        // The catalogues are checked by the tests below: a parse error cannot ship.
        let text = files(lang)[file];
        let res = FluentResource::try_new(text.to_string()).unwrap_or_else(|(res, _)| res);
        let id: unic_langid::LanguageIdentifier = lang.tag().parse().unwrap_or_default();
        let mut b = FluentBundle::new_concurrent(vec![id]);
        b.set_use_isolating(false);
        let _ = b.add_resource(res);
        b
    })
}

/// One argument of a message: text as it is, or a whole number (which plural selectors read).
#[derive(Clone, Debug)]
pub enum Arg {
    Text(String),
    Int(i64),
}

impl From<&str> for Arg {
    fn from(s: &str) -> Arg {
        Arg::Text(s.to_string())
    }
}
impl From<String> for Arg {
    fn from(s: String) -> Arg {
        Arg::Text(s)
    }
}
impl From<&String> for Arg {
    fn from(s: &String) -> Arg {
        Arg::Text(s.clone())
    }
}
macro_rules! int_arg {
    ($($t:ty)*) => {$(
        impl From<$t> for Arg {
            fn from(n: $t) -> Arg {
                Arg::Int(n as i64)
            }
        }
    )*};
}
int_arg!(i8 i16 i32 i64 u8 u16 u32 usize);
impl From<u64> for Arg {
    fn from(n: u64) -> Arg {
        i64::try_from(n).map(Arg::Int).unwrap_or_else(|_| Arg::Text(n.to_string()))
    }
}

impl Arg {
    fn value(&self) -> FluentValue<'_> {
        match self {
            Arg::Text(s) => FluentValue::from(s.as_str()),
            // Fluent's numbers are f64: beyond 2^53 a whole number would print rounded, so it
            // goes as text (plural rules then take the catch-all form, right for such numbers).
            Arg::Int(n) if n.unsigned_abs() <= 1 << 53 => FluentValue::from(*n),
            Arg::Int(n) => FluentValue::from(n.to_string()),
        }
    }
}

/// A message in the current language with its id (the JSON `code` of an error made from it).
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct Msg {
    pub id: &'static str,
    pub text: String,
}

impl Msg {
    /// Formats `id` with `args` in the current language.
    pub fn new(id: &'static str, args: &[(&'static str, Arg)]) -> Msg {
        Msg { id, text: format_in(language(), id, args) }
    }
}

/// Formats `id` in `lang`. An id missing from `lang` falls back to English, and one missing
/// from English shows the id itself (the tests keep both from shipping).
pub fn format_in(lang: Lang, id: &str, args: &[(&str, Arg)]) -> String {
    let mut fargs = FluentArgs::with_capacity(args.len());
    for (k, v) in args {
        fargs.set(*k, v.value());
    }
    for l in [lang, Lang::En] {
        let Some(&file) = index(l).get(id) else { continue };
        let b = bundle(l, file as usize);
        if let Some(p) = b.get_message(id).and_then(|m| m.value()) {
            let mut errors = Vec::new();
            return b.format_pattern(p, Some(&fargs), &mut errors).into_owned();
        }
    }
    id.to_string()
}

impl std::fmt::Display for Msg {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        f.write_str(&self.text)
    }
}
impl std::ops::Deref for Msg {
    type Target = str;
    fn deref(&self) -> &str {
        &self.text
    }
}
impl From<Msg> for String {
    fn from(m: Msg) -> String {
        m.text
    }
}
impl PartialEq<&str> for Msg {
    fn eq(&self, other: &&str) -> bool {
        self.text == *other
    }
}
impl PartialEq<str> for Msg {
    fn eq(&self, other: &str) -> bool {
        self.text == other
    }
}

/// `msg!("value-out-of-range", value = shown, what = name, max = m)`: the message `id` of the
/// catalogue in the current language, as a [`Msg`] (text and id). Argument names are the
/// Fluent variables (`$value` …). `msg!(lang: l, "id", …)` formats in a given language.
#[macro_export]
macro_rules! msg {
    (lang: $lang:expr, $id:literal $(, $k:ident = $v:expr)* $(,)?) => {
        $crate::core::msg::Msg {
            id: $id,
            text: $crate::core::msg::format_in($lang, $id, &[$((stringify!($k), $crate::core::msg::Arg::from($v))),*]),
        }
    };
    ($id:literal $(, $k:ident = $v:expr)* $(,)?) => {
        $crate::core::msg::Msg::new($id, &[$((stringify!($k), $crate::core::msg::Arg::from($v))),*])
    };
}

/// Every message id of `lang`'s catalogue, in file order (tests and the generated table of
/// docs/reference/errors.md).
pub fn ids(lang: Lang) -> Vec<String> {
    fluent_syntax::parser::parse(lang.source())
        .map(|r| {
            r.body
                .into_iter()
                .filter_map(|e| match e {
                    fluent_syntax::ast::Entry::Message(m) => Some(m.id.name.to_string()),
                    _ => None,
                })
                .collect()
        })
        .unwrap_or_default()
}

/// The variables (`$name`) each message of `lang` uses, sorted, by id: the catalogue is parsed
/// once (a check of every id is linear in the catalogue, not quadratic).
pub fn variables_by_id(lang: Lang) -> std::collections::BTreeMap<String, Vec<String>> {
    let Ok(res) = fluent_syntax::parser::parse(lang.source()) else { return Default::default() };
    let mut all = std::collections::BTreeMap::new();
    for e in res.body {
        if let fluent_syntax::ast::Entry::Message(m) = e {
            let mut out = Vec::new();
            if let Some(p) = &m.value {
                pattern_vars(p, &mut out);
            }
            out.sort();
            out.dedup();
            all.insert(m.id.name.to_string(), out);
        }
    }
    all
}

/// The variables (`$name`) a message of `lang` uses, sorted.
pub fn variables(lang: Lang, id: &str) -> Vec<String> {
    variables_by_id(lang).remove(id).unwrap_or_default()
}

fn pattern_vars(p: &fluent_syntax::ast::Pattern<&str>, out: &mut Vec<String>) {
    use fluent_syntax::ast::{Expression, InlineExpression, PatternElement};
    fn inline(e: &InlineExpression<&str>, out: &mut Vec<String>) {
        match e {
            InlineExpression::VariableReference { id } => out.push(id.name.to_string()),
            InlineExpression::Placeable { expression } => expr(expression, out),
            InlineExpression::FunctionReference { arguments, .. } => {
                arguments.positional.iter().for_each(|a| inline(a, out));
            }
            _ => {}
        }
    }
    fn expr(e: &Expression<&str>, out: &mut Vec<String>) {
        match e {
            Expression::Inline(i) => inline(i, out),
            Expression::Select { selector, variants } => {
                inline(selector, out);
                for v in variants {
                    pattern_vars(&v.value, out);
                }
            }
        }
    }
    for el in &p.elements {
        if let PatternElement::Placeable { expression } = el {
            expr(expression, out);
        }
    }
}

/// The parse errors of `lang`'s catalogue (none ship: tested).
pub fn parse_errors(lang: Lang) -> Vec<String> {
    match fluent_syntax::parser::parse(lang.source()) {
        Ok(_) => Vec::new(),
        Err((_, errs)) => errs.iter().map(|e| format!("{e:?}")).collect(),
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn tags_and_locales_name_languages() {
        for (tag, want) in [
            ("en", Some(Lang::En)),
            ("C", Some(Lang::En)),
            ("POSIX", Some(Lang::En)),
            ("C.UTF-8", Some(Lang::En)),
            ("en_GB.UTF-8", Some(Lang::En)),
            ("ru", Some(Lang::Ru)),
            ("ru_RU.UTF-8", Some(Lang::Ru)),
            ("RU-ru", Some(Lang::Ru)),
            ("zh-CN", Some(Lang::ZhCn)),
            ("zh_CN.GB2312", Some(Lang::ZhCn)),
            ("zh", Some(Lang::ZhCn)),
            ("zh-Hans", Some(Lang::ZhCn)),
            ("zh_SG", Some(Lang::ZhCn)),
            ("zh_TW.UTF-8", None),
            ("zh-Hant-HK", None),
            ("de_DE", None),
            ("", None),
        ] {
            assert_eq!(Lang::from_tag(tag), want, "{tag}");
        }
        for &l in Lang::ALL {
            assert_eq!(Lang::from_tag(l.tag()), Some(l));
        }
    }

    #[test]
    fn the_choice_goes_flag_then_plcsh_lang_then_system() {
        let env = |vars: &'static [(&'static str, &'static str)]| {
            move |k: &str| vars.iter().find(|(n, _)| *n == k).map(|(_, v)| v.to_string())
        };
        let ru = || Some("ru_RU.UTF-8".to_string());
        assert_eq!(decide(Some(Lang::ZhCn), env(&[("PLCSH_LANG", "ru")]), ru), Lang::ZhCn);
        assert_eq!(decide(None, env(&[("PLCSH_LANG", "zh-CN")]), ru), Lang::ZhCn);
        assert_eq!(decide(None, env(&[("PLCSH_LANG", "")]), ru), Lang::Ru);
        assert_eq!(decide(None, env(&[("PLCSH_LANG", "de")]), ru), Lang::En);
        assert_eq!(decide(None, env(&[]), ru), Lang::Ru);
        assert_eq!(decide(None, env(&[]), || Some("C".into())), Lang::En);
        assert_eq!(decide(None, env(&[]), || None), Lang::En);
    }

    #[test]
    fn every_catalogue_parses_and_has_every_id_of_the_others() {
        let en = ids(Lang::En);
        assert!(en.len() > 20, "{}", en.len());
        for &l in Lang::ALL {
            assert_eq!(parse_errors(l), Vec::<String>::new(), "{}", l.tag());
            let mine = ids(l);
            let mut sorted = mine.clone();
            sorted.sort();
            sorted.dedup();
            assert_eq!(sorted.len(), mine.len(), "{}: an id twice", l.tag());
            for id in &en {
                assert!(mine.contains(id), "{}: missing `{id}`", l.tag());
            }
            for id in &mine {
                assert!(en.contains(id), "{}: `{id}` is not in the English catalogue", l.tag());
            }
        }
    }

    #[test]
    fn every_message_uses_the_same_arguments_in_every_language() {
        let en = variables_by_id(Lang::En);
        for &l in &Lang::ALL[1..] {
            let other = variables_by_id(l);
            for (id, vars) in &en {
                assert_eq!(other.get(id), Some(vars), "{}: `{id}` uses other arguments than English", l.tag());
            }
        }
    }

    #[test]
    fn the_argument_check_sees_a_difference() {
        // The check above is only as good as `variables`: it must see into selectors.
        let src = "a = { $n ->\n    [one] one { $x }\n   *[other] { $y }\n}\n";
        let res = fluent_syntax::parser::parse(src).unwrap();
        let mut out = Vec::new();
        if let fluent_syntax::ast::Entry::Message(m) = &res.body[0] {
            pattern_vars(m.value.as_ref().unwrap(), &mut out);
        }
        out.sort();
        assert_eq!(out, vec!["n", "x", "y"]);
    }

    #[test]
    fn russian_plurals_take_three_forms() {
        let n = |l: Lang, k: i64| format_in(l, "link-attempts", &[("message", "x".into()), ("attempts", Arg::Int(k))]);
        assert_eq!(n(Lang::Ru, 1), "x (1 попытка)");
        assert_eq!(n(Lang::Ru, 3), "x (3 попытки)");
        assert_eq!(n(Lang::Ru, 5), "x (5 попыток)");
        assert_eq!(n(Lang::Ru, 11), "x (11 попыток)");
        assert_eq!(n(Lang::Ru, 21), "x (21 попытка)");
        assert_eq!(n(Lang::Ru, 22), "x (22 попытки)");
        assert_eq!(n(Lang::En, 1), "x (1 attempt)");
        assert_eq!(n(Lang::En, 2), "x (2 attempts)");
    }

    #[test]
    fn arguments_come_out_as_given_without_isolation_marks() {
        let t = format_in(
            Lang::En,
            "value-out-of-range",
            &[("value", "300".into()), ("dtype", "BYTE".into()), ("max", Arg::Int(255))],
        );
        assert_eq!(t, "300 is out of range for BYTE (0…255)");
        assert!(!t.contains('\u{2068}'));
        let big = format_in(
            Lang::En,
            "value-out-of-range",
            &[("value", "1".into()), ("dtype", "x".into()), ("max", Arg::from(u64::MAX))],
        );
        assert!(big.contains("18446744073709551615"), "{big}");
    }

    #[test]
    fn a_missing_id_falls_back_to_english_then_to_the_id() {
        assert_eq!(format_in(Lang::Ru, "no-such-message", &[]), "no-such-message");
    }
}
