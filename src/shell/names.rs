//! Tag names in the command language (docs/tags.md, "How names appear"): a name works
//! wherever an operand does.
//!
//! Commands that read operands through [`crate::session::Session::resolve`] (`get`, `set`,
//! `read`, `watch`, `trace`, `plot`, `help`) take names there, with their columns as typed.
//! Every other command reads operand words with its family's own grammar (`sim input I0.1`,
//! `sim wire Q0.0 -> I0.1`, `umpk monitor`, `hsc … at VB3009`): for those the shell writes a
//! name as its operand before the command runs — one rule for every command, so a command
//! added later takes names without knowing about them (tests/names.rs walks the registry).
//! Text words (paths, names of devices and snapshots, Lua code, quoted words:
//! [`super::commands::text_words`]) and the words a command's forms spell out are never
//! names. A name is also never read in the K2 manual's spelling (`Мотор_1_Пуск` keeps its
//! Cyrillic letters: [`super::fold_operands`] leaves the words this module names alone), and
//! neither is a word that the spelling would not make an operand ([`unfolded_words`]): an
//! unknown word is first a possible misspelt name.

use super::commands::{self, forms, CommandSpec};
use super::edits::Edits;
use super::lex;
use crate::session::Session;

/// Commands that resolve operand words through the session themselves (names and all).
pub const RESOLVING: &[&str] = &["get", "set", "read", "watch", "trace", "plot", "help", "lua"];

/// The device whose names a command's words use: the device word of a command that reads
/// its own (`umpk trainer monitor …`), else the current device.
fn device_of(session: &Session, cmd: &str, words: &[(usize, &str)]) -> Option<usize> {
    if ["umpk", "servo", "agent"].contains(&cmd) {
        if let Some(i) = words.first().and_then(|w| session.index(w.1).ok()) {
            return Some(i);
        }
        // Without a device word, `servo …` and `umpk …` act on the current device if it is
        // of their family, else on the first open one that is.
        let family = if cmd == "agent" { "k2" } else { cmd };
        let of = |i: usize| session.entries()[i].device.info().family == family;
        if let Some(i) = session.current_index().ok().filter(|&i| of(i)) {
            return Some(i);
        }
        if let Some(i) = (0..session.entries().len()).find(|&i| of(i)) {
            return Some(i);
        }
    }
    session.current_index().ok()
}

/// The pieces of an operand word that may be names: `press:Level[4]=5` → the device index
/// and the byte ranges of `Level`; `A..B` gives both sides.
fn name_spans(session: &Session, default: Option<usize>, word: &str) -> Option<(usize, Vec<(usize, usize)>)> {
    let end = word.find('=').unwrap_or(word.len());
    let body = &word[..end];
    let (dev, from) = match body.find(':') {
        Some(c) => (session.index(&body[..c]).ok()?, c + 1),
        None => (default?, 0),
    };
    let names = session.names(dev);
    if names.is_empty() {
        return None;
    }
    let mut spans = Vec::new();
    let mut start = from;
    let text = &body[from..];
    let parts: Vec<&str> = text.split("..").collect();
    for (k, p) in parts.iter().enumerate() {
        let base = p.find('[').map_or(*p, |b| &p[..b]);
        if names.get(base).is_some() {
            spans.push((start, start + base.len()));
        }
        start += p.len() + if k + 1 < parts.len() { 2 } else { 0 };
    }
    (!spans.is_empty()).then_some((dev, spans))
}

/// For each of `words` (as [`lex::words`] splits a command's arguments): true when the K2
/// manual's spelling must not be read in it — a word that names a tag of its device, or one
/// that is no operand once read in that spelling ([`folds_to_no_operand`]). Those words reach
/// the command as typed, so a misspelt name (`Уровен_2` for `Уровень_2`) is searched among the
/// names and the operands as the person wrote it, and a refusal quotes what they typed.
pub fn unfolded_words(session: &Session, cmd: &str, words: &[(usize, &str)]) -> Vec<bool> {
    let default = device_of(session, cmd, words);
    words
        .iter()
        .map(|w| name_spans(session, default, w.1).is_some() || folds_to_no_operand(session, default, w.1))
        .collect()
}

/// True when `word`'s operand part (before `=`, after `device:`) has letters the K2 manual's
/// spelling would change (`Уровен_2` → `Уpoвeн_2`) and the changed text is still not an
/// operand of its device nor a value (`В#16#85`): the look-alike rule is for operands the
/// manual spells in Cyrillic (`ВW0`, `Т5`), and applies only when the folded word is one.
/// A device that cannot say yet (its link not up) is given the benefit of the doubt.
fn folds_to_no_operand(session: &Session, default: Option<usize>, word: &str) -> bool {
    if word.is_ascii() {
        return false;
    }
    let body = &word[..word.find('=').unwrap_or(word.len())];
    let (dev, body) = match body.find(':').map(|c| (session.index(&body[..c]), c)) {
        Some((Ok(i), c)) => (i, &body[c + 1..]),
        _ => match default {
            Some(i) => (i, body),
            None => return false,
        },
    };
    if body.is_ascii() {
        return false;
    }
    let Some((folded, _)) = crate::core::text::fold_manual_spelling(body) else { return false };
    // A value (`В#16#85`), or its head as the manual's scanned text spaces it (`В # 16 # 85`).
    if crate::core::literal::is_literal_head(&folded) || crate::core::literal::parse_literal(&folded).is_ok() {
        return false;
    }
    match session.entries()[dev].device.operands().parse(&folded) {
        Ok(_) => false,
        Err(e) => e.kind != crate::core::ErrorKind::Link,
    }
}

/// The arguments of `spec` with every name written as its operand (`sim input Start freq=1kHz`
/// → `sim input I0.1 freq=1kHz`), for the commands outside [`RESOLVING`], with where each
/// operand was typed (a refusal's column goes back to the name); `None` when no word names a
/// tag. Text words, the words the forms spell out and option keys are left alone.
pub fn operands_for(session: &Session, spec: &CommandSpec, text: &str) -> Option<(String, Edits)> {
    if RESOLVING.contains(&spec.name) || session.entries().iter().all(|e| e.names.is_empty()) {
        return None;
    }
    let words = lex::words(text).ok()?;
    let raw: Vec<&str> = words.iter().map(|w| w.1).collect();
    let mask = commands::text_words(spec.name, &raw);
    let literals = forms::literals(spec, None);
    let keys: Vec<String> = forms::options(spec, None).into_iter().map(|(k, _)| k).collect();
    let default = device_of(session, spec.name, &words);
    let mut out = String::with_capacity(text.len() + 16);
    let mut edits = Edits::default();
    let mut copied = 0;
    for (k, &(col, w)) in words.iter().enumerate() {
        if mask[k] || literals.iter().any(|l| l.eq_ignore_ascii_case(w)) {
            continue;
        }
        if w.split_once('=').is_some_and(|(key, _)| keys.iter().any(|k| k == key)) {
            continue;
        }
        let Some((dev, spans)) = name_spans(session, default, w) else { continue };
        let names = session.names(dev);
        for (a, b) in spans {
            let Some(n) = names.get(&w[a..b]) else { continue };
            out.push_str(&text[copied..col + a]);
            edits.replaced((col + a, col + b), (out.len(), out.len() + n.operand.len()), false);
            out.push_str(&n.operand);
            copied = col + b;
        }
    }
    if copied == 0 {
        return None;
    }
    out.push_str(&text[copied..]);
    Some((out, edits))
}
