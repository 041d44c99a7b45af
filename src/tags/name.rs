//! The rules for tag names and addresses, in one place: what a name may be, how two names
//! compare, which words are taken, how an address is written, and "did you mean".
//!
//! A name is an IEC 61131-3 identifier (ed. 3, §6.1.2): a letter or `_`, then letters,
//! digits and `_`; no two `_` in a row and none at the end ("multiple leading or multiple
//! embedded underlines are not allowed … trailing underlines are not allowed"). The
//! standard's letters are Latin; a PLC project in Russia or China names its variables in
//! Cyrillic or Chinese (KincoBuilder and CODESYS accept them), so a letter here is any
//! Unicode letter (`char::is_alphabetic`) and a digit any decimal digit of the name's script
//! (`char::is_numeric` is not used: `²` or `½` is no digit). Case does not matter (§6.1.2):
//! names compare by their Unicode lower case ([`fold`]).
//!
//! Taken words: a name may not be one of IEC 61131-3's keywords that a tag file or IL
//! program uses (the elementary type names, `AT`, `VAR_GLOBAL` …, the IL operators of
//! §7.2 ed. 2 / §8.2 ed. 3), nor a word of the shell's command language ([`COMMAND_WORDS`],
//! which tests/tags.rs keeps equal to the command registry and the program's sub-commands):
//! `get get` or `plc.watch` would read two ways.

use crate::core::msg::Msg;
use crate::msg;
use std::borrow::Cow;

/// The shell's command words and aliases and the program's sub-commands (tests/tags.rs
/// checks this list against `shell::commands::COMMANDS` and the CLI's sub-commands).
pub const COMMAND_WORDS: &[&str] = &[
    "agent",
    "close",
    "completions",
    "connect",
    "devices",
    "eeprom",
    "events",
    "exit",
    "g",
    "get",
    "hdef",
    "help",
    "hsc",
    "lab",
    "lua",
    "man",
    "models",
    "open",
    "paths",
    "plot",
    "pls",
    "ports",
    "probe",
    "profile",
    "pstop",
    "publish",
    "pto",
    "pwm",
    "q",
    "quit",
    "r",
    "read",
    "record",
    "replay",
    "rtc",
    "run",
    "s",
    "servo",
    "set",
    "sim",
    "tags",
    "trace",
    "umpk",
    "use",
    "wait",
    "watch",
];

/// IEC 61131-3 keywords a tag file or an IL program uses (the standard's table of keywords,
/// the parts that concern variables, types and the IL operators): never a tag's name.
pub const IEC_KEYWORDS: &[&str] = &[
    // Declarations.
    "AT",
    "VAR",
    "VAR_GLOBAL",
    "VAR_INPUT",
    "VAR_OUTPUT",
    "VAR_IN_OUT",
    "VAR_EXTERNAL",
    "VAR_TEMP",
    "END_VAR",
    "CONSTANT",
    "RETAIN",
    "NON_RETAIN",
    "PROGRAM",
    "END_PROGRAM",
    "FUNCTION",
    "END_FUNCTION",
    "FUNCTION_BLOCK",
    "END_FUNCTION_BLOCK",
    "TRUE",
    "FALSE", // Elementary types.
    "BOOL",
    "BYTE",
    "WORD",
    "DWORD",
    "LWORD",
    "SINT",
    "INT",
    "DINT",
    "LINT",
    "USINT",
    "UINT",
    "UDINT",
    "ULINT",
    "REAL",
    "LREAL",
    "TIME",
    "DATE",
    "STRING", // IL operators.
    "LD",
    "LDN",
    "ST",
    "STN",
    "S",
    "R",
    "AND",
    "ANDN",
    "OR",
    "ORN",
    "XOR",
    "XORN",
    "NOT",
    "ADD",
    "SUB",
    "MUL",
    "DIV",
    "MOD",
    "GT",
    "GE",
    "EQ",
    "NE",
    "LE",
    "LT",
    "JMP",
    "JMPC",
    "JMPCN",
    "CAL",
    "CALC",
    "CALCN",
    "RET",
    "RETC",
    "RETCN",
];

/// The key two names compare by: the Unicode lower case (IEC 61131-3 §6.1.2), borrowed when
/// the name has no capital letter (the common case costs no allocation).
pub fn fold(name: &str) -> Cow<'_, str> {
    let upper = if name.is_ascii() {
        name.bytes().any(|b| b.is_ascii_uppercase())
    } else {
        name.chars().any(|c| c.to_lowercase().next() != Some(c) || c.to_lowercase().nth(1).is_some())
    };
    if upper {
        Cow::Owned(name.to_lowercase())
    } else {
        Cow::Borrowed(name)
    }
}

/// A decimal digit of any script (`0`–`9`, `٣`, `३` …): Unicode's Nd category, which
/// `char::to_digit` alone does not cover and `is_numeric` overshoots.
fn is_digit(c: char) -> bool {
    c.is_ascii_digit() || decimal_value(c)
}

/// Whether `c` is a decimal digit outside ASCII: the Unicode Nd runs of the scripts a PLC
/// project is likely to use (Arabic-Indic, Devanagari and the other Indic scripts, Thai, Lao,
/// Tibetan, Myanmar, Khmer, Mongolian, fullwidth). Other numeric characters (`²`, `½`, `Ⅻ`,
/// `〇`) are not digits.
fn decimal_value(c: char) -> bool {
    const ND_STARTS: &[u32] = &[
        0x0660, 0x06F0, 0x07C0, 0x0966, 0x09E6, 0x0A66, 0x0AE6, 0x0B66, 0x0BE6, 0x0C66, 0x0CE6, 0x0D66, 0x0DE6, 0x0E50,
        0x0ED0, 0x0F20, 0x1040, 0x1090, 0x17E0, 0x1810, 0xFF10,
    ];
    let cp = c as u32;
    ND_STARTS.iter().any(|&s| (s..s + 10).contains(&cp))
}

/// Checks a name against the rules above; the message says what is wrong with it.
pub fn check(name: &str) -> Result<(), Msg> {
    let mut chars = name.chars();
    let Some(first) = chars.next() else {
        return Err(msg!("tags-name-empty"));
    };
    if !(first.is_alphabetic() || first == '_') {
        return Err(msg!("tags-name-bad-start", name = name, char = first.to_string()));
    }
    let mut prev = first;
    for c in chars {
        if !(c.is_alphabetic() || is_digit(c) || c == '_') {
            return Err(msg!("tags-name-bad-char", name = name, char = c.to_string()));
        }
        if c == '_' && prev == '_' {
            return Err(msg!("tags-name-underscores", name = name));
        }
        prev = c;
    }
    if prev == '_' {
        return Err(msg!("tags-name-underscores", name = name));
    }
    if COMMAND_WORDS.iter().any(|w| w.eq_ignore_ascii_case(name)) {
        return Err(msg!("tags-name-is-command", name = name));
    }
    if IEC_KEYWORDS.iter().any(|w| w.eq_ignore_ascii_case(name)) {
        return Err(msg!("tags-name-is-keyword", name = name));
    }
    Ok(())
}

/// The address as the family writes it: trimmed, upper case, without IEC's `%` of a directly
/// represented variable, and without its bit-size letter `X` (`%MX0.3` → `M0.3`, `%IX0.0`
/// → `I0.0`; IEC 61131-3 ed. 3 §6.5.5.2, where `X` marks a single bit). `%MW10`, `%VD200`
/// and `%QB0` keep their size letters, which are the K2's own (K2 manual §3.2, "%" accepted
/// as in IL listings).
pub fn address_text(raw: &str) -> String {
    let t = raw.trim();
    let t = t.strip_prefix('%').unwrap_or(t);
    let up = t.to_uppercase();
    // `<letters>X<digits>.<digits>` → `<letters><digits>.<digits>` (letters: at least one).
    let letters = up.bytes().take_while(|b| b.is_ascii_uppercase()).count();
    if letters >= 2 && up.as_bytes()[letters - 1] == b'X' {
        let rest = &up[letters..];
        let (num, bit) = rest.split_once('.').unwrap_or((rest, ""));
        if !num.is_empty()
            && !bit.is_empty()
            && num.bytes().all(|b| b.is_ascii_digit())
            && bit.bytes().all(|b| b.is_ascii_digit())
        {
            return format!("{}{}", &up[..letters - 1], rest);
        }
    }
    up
}

/// The optimal-string-alignment distance (Levenshtein with a swap of two neighbours as one
/// edit: `Strat` is one edit from `Start`), by characters; O(|a|·|b|).
pub fn distance(a: &str, b: &str) -> usize {
    let a: Vec<char> = a.chars().collect();
    let b: Vec<char> = b.chars().collect();
    let w = b.len() + 1;
    let mut d = vec![0usize; (a.len() + 1) * w];
    for (j, cell) in d.iter_mut().enumerate().take(w) {
        *cell = j;
    }
    for i in 1..=a.len() {
        d[i * w] = i;
        for j in 1..=b.len() {
            let cost = usize::from(a[i - 1] != b[j - 1]);
            let mut v = (d[(i - 1) * w + j] + 1).min(d[i * w + j - 1] + 1).min(d[(i - 1) * w + j - 1] + cost);
            if i > 1 && j > 1 && a[i - 1] == b[j - 2] && a[i - 2] == b[j - 1] {
                v = v.min(d[(i - 2) * w + j - 2] + 1);
            }
            d[i * w + j] = v;
        }
    }
    d[a.len() * w + b.len()]
}

/// The at most `n` names of `names` nearest to `name` (case-insensitive), nearest first: an
/// edit distance of at most a third of the name's length (at least 1), or a name that starts
/// with it. Linear in the number of names; each distance is bounded by the names' lengths.
pub fn nearest<'a>(name: &str, names: impl Iterator<Item = &'a str>, n: usize) -> Vec<&'a str> {
    let key = fold(name);
    let len = key.chars().count();
    let limit = (len / 3).max(1);
    let mut found: Vec<(usize, &'a str)> = Vec::new();
    for cand in names {
        let c = fold(cand);
        // A cheap bound first: lengths that differ by more than the limit cannot be near.
        let clen = c.chars().count();
        let prefix = !key.is_empty() && c.starts_with(key.as_ref());
        if !prefix && clen.abs_diff(len) > limit {
            continue;
        }
        let d = if prefix { 0 } else { distance(&key, &c) };
        if d <= limit {
            found.push((d, cand));
        }
    }
    found.sort_by(|a, b| a.0.cmp(&b.0).then_with(|| a.1.cmp(b.1)));
    found.into_iter().take(n).map(|(_, s)| s).collect()
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn iec_identifiers_with_letters_of_any_script() {
        for ok in ["Conveyor_Run", "_x", "Tank2_Level", "Мотор_1_Пуск", "电机_启动", "a1", "x٣"] {
            assert!(check(ok).is_ok(), "{ok}: {:?}", check(ok));
        }
        for (bad, id) in [
            ("", "tags-name-empty"),
            ("1abc", "tags-name-bad-start"),
            ("a-b", "tags-name-bad-char"),
            ("a b", "tags-name-bad-char"),
            ("Q0.0", "tags-name-bad-char"),
            ("a__b", "tags-name-underscores"),
            ("__a", "tags-name-underscores"),
            ("a_", "tags-name-underscores"),
            ("_", "tags-name-underscores"),
            ("x²", "tags-name-bad-char"),
            ("Watch", "tags-name-is-command"),
            ("end_var", "tags-name-is-keyword"),
            ("Real", "tags-name-is-keyword"),
        ] {
            assert_eq!(check(bad).unwrap_err().id, id, "{bad}");
        }
    }

    #[test]
    fn names_compare_without_case_in_every_script() {
        assert_eq!(fold("Conveyor_Run"), "conveyor_run");
        assert_eq!(fold("МОТОР_1_Пуск"), "мотор_1_пуск");
        assert!(matches!(fold("already_lower"), Cow::Borrowed(_)));
        assert!(matches!(fold("电机"), Cow::Borrowed(_)));
    }

    #[test]
    fn iec_addresses_become_the_family_form() {
        assert_eq!(address_text(" %MX0.3 "), "M0.3");
        assert_eq!(address_text("%IX1.7"), "I1.7");
        assert_eq!(address_text("%MW10"), "MW10");
        assert_eq!(address_text("vd200"), "VD200");
        assert_eq!(address_text("%SMX0.1"), "SM0.1");
        assert_eq!(address_text("X0"), "X0", "an FX input keeps its letter");
        assert_eq!(address_text("%QX0"), "QX0", "no bit: not the IEC bit form");
    }

    #[test]
    fn nearest_names_first() {
        let names = ["Conveyor_Run", "Conveyor_Stop", "Tank2_Level", "Мотор_1_Пуск"];
        assert_eq!(nearest("conveyor_rn", names.iter().copied(), 3), vec!["Conveyor_Run"]);
        assert_eq!(nearest("Conveyor", names.iter().copied(), 3), vec!["Conveyor_Run", "Conveyor_Stop"]);
        assert_eq!(nearest("мотор_1_пуcк", names.iter().copied(), 3), vec!["Мотор_1_Пуск"], "Latin c for Cyrillic с");
        assert!(nearest("xyz", names.iter().copied(), 3).is_empty());
        assert_eq!(nearest("Tnak2_Level", names.iter().copied(), 3), vec!["Tank2_Level"], "a swap is one edit");
        assert_eq!(distance("Strat", "Start"), 1);
        assert_eq!(distance("", "ab"), 2);
    }
}
