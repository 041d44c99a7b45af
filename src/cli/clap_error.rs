//! clap's own errors (`plcsh --bogus`, a missing value, an invalid value, an unknown
//! subcommand) in the language of messages. clap writes them in English only; this module
//! reads the facts clap keeps in the error (its kind and context: the argument, the value,
//! the valid values, the "did you mean" suggestion, the usage line) and writes the same
//! message from the catalogue (`cli-error-…` in shell.ftl), in clap's layout: the error, the
//! tips, the usage line, where to read more.
//!
//! English keeps clap's own text, byte for byte ([`render`] answers `None`), and so does an
//! error whose facts clap did not record (its I/O and formatting errors): those are printed
//! by clap as before. The exit status stays clap's (2: `core::exit::USAGE`).

use crate::core::msg::{language, Lang, Msg};
use crate::msg;
use clap::error::{ContextKind, ContextValue, ErrorKind};

/// The text of `e` in the current language, or `None` where clap's own text is the one to
/// show (English, help and version screens, errors without recorded facts).
pub fn render(e: &clap::Error) -> Option<String> {
    if language() == Lang::En || !e.use_stderr() {
        return None;
    }
    let text = |k: ContextKind| match e.get(k) {
        Some(ContextValue::String(s)) => Some(s.clone()),
        _ => None,
    };
    let list = |k: ContextKind| match e.get(k) {
        Some(ContextValue::Strings(v)) => v.clone(),
        Some(ContextValue::String(s)) => vec![s.clone()],
        _ => Vec::new(),
    };
    let number = |k: ContextKind| match e.get(k) {
        Some(ContextValue::Number(n)) => Some(*n as i64),
        _ => None,
    };
    let quoted = |v: &[String]| v.iter().map(|s| format!("'{s}'")).collect::<Vec<_>>().join(", ");
    let arg = text(ContextKind::InvalidArg);
    let value = text(ContextKind::InvalidValue);
    // Lines under the first: the valid values, the missing arguments.
    let mut lines: Vec<String> = Vec::new();
    let head = match e.kind() {
        ErrorKind::UnknownArgument => msg!("cli-error-unknown-argument", arg = arg?),
        ErrorKind::InvalidSubcommand => {
            msg!("cli-error-unknown-subcommand", subcommand = text(ContextKind::InvalidSubcommand)?)
        }
        ErrorKind::InvalidValue => {
            let (arg, value) = (arg?, value?);
            let valid = list(ContextKind::ValidValue);
            if !valid.is_empty() {
                lines.push(msg!("cli-error-possible-values", values = valid.join(", ")).text);
            }
            if value.is_empty() {
                msg!("cli-error-value-missing", arg = arg)
            } else {
                msg!("cli-error-invalid-value", arg = arg, value = value)
            }
        }
        ErrorKind::ValueValidation => {
            let (arg, value) = (arg?, value?);
            match std::error::Error::source(e) {
                Some(reason) => {
                    msg!("cli-error-value-refused", arg = arg, value = value, reason = reason.to_string())
                }
                None => msg!("cli-error-invalid-value", arg = arg, value = value),
            }
        }
        ErrorKind::NoEquals => msg!("cli-error-no-equals", arg = arg?),
        ErrorKind::TooManyValues => msg!("cli-error-too-many-values", arg = arg?, value = value?),
        ErrorKind::TooFewValues => msg!(
            "cli-error-too-few-values",
            arg = arg?,
            min = number(ContextKind::MinValues)?,
            given = number(ContextKind::ActualNumValues)?
        ),
        ErrorKind::WrongNumberOfValues => msg!(
            "cli-error-wrong-number-of-values",
            arg = arg?,
            expected = number(ContextKind::ExpectedNumValues)?,
            given = number(ContextKind::ActualNumValues)?
        ),
        ErrorKind::MissingRequiredArgument => {
            let missing = list(ContextKind::InvalidArg);
            if missing.is_empty() {
                return None;
            }
            let head = msg!("cli-error-missing-arguments", count = missing.len());
            lines.extend(missing);
            head
        }
        ErrorKind::MissingSubcommand => {
            let valid = list(ContextKind::ValidSubcommand);
            if !valid.is_empty() {
                lines.push(msg!("cli-error-subcommands", values = valid.join(", ")).text);
            }
            msg!("cli-error-missing-subcommand", command = text(ContextKind::InvalidSubcommand)?)
        }
        ErrorKind::ArgumentConflict => {
            let arg = arg.or_else(|| text(ContextKind::InvalidSubcommand))?;
            match e.get(ContextKind::PriorArg) {
                Some(ContextValue::String(prior)) if *prior == arg => msg!("cli-error-used-twice", arg = arg),
                Some(ContextValue::String(prior)) => {
                    msg!("cli-error-conflict", arg = arg, other = quoted(std::slice::from_ref(prior)))
                }
                Some(ContextValue::Strings(prior)) => msg!("cli-error-conflict", arg = arg, other = quoted(prior)),
                _ => msg!("cli-error-conflict-others", arg = arg),
            }
        }
        ErrorKind::InvalidUtf8 => msg!("cli-error-invalid-utf8"),
        _ => return None,
    };
    // The "did you mean" tips, as clap gives them.
    let mut tips: Vec<Msg> = Vec::new();
    for (kind, id) in
        [(ContextKind::SuggestedSubcommand, 0), (ContextKind::SuggestedArg, 1), (ContextKind::SuggestedValue, 2)]
    {
        let similar = list(kind);
        if similar.is_empty() {
            continue;
        }
        let (count, names) = (similar.len(), quoted(&similar));
        tips.push(match id {
            0 => msg!("cli-error-similar-subcommand", count = count, names = names),
            1 => msg!("cli-error-similar-argument", count = count, names = names),
            _ => msg!("cli-error-similar-value", count = count, names = names),
        });
    }
    if let Some(ContextValue::StyledStrs(more)) = e.get(ContextKind::Suggested) {
        for s in more {
            tips.push(suggestion(&s.to_string()));
        }
    }
    let mut out = msg!("cli-error", message = head.text).text;
    for l in &lines {
        out.push_str(&format!("\n  {l}"));
    }
    if !tips.is_empty() {
        out.push('\n');
        for t in &tips {
            out.push_str(&format!("\n  {t}"));
        }
    }
    if let Some(ContextValue::StyledStr(usage)) = e.get(ContextKind::Usage) {
        let usage = usage.to_string();
        let usage = usage.strip_prefix("Usage:").unwrap_or(&usage).trim_start();
        out.push_str(&format!("\n\n{} {usage}", msg!("cli-heading-usage")));
    }
    out.push_str(&format!("\n\n{}\n", msg!("cli-error-more", help = "--help")));
    Some(out)
}

/// clap's free-text tips: the two it writes (a word that looks like an option, given as a
/// value; `--` before a subcommand) in the catalogue's words, any other as clap wrote it.
fn suggestion(text: &str) -> Msg {
    let quoted = |s: &str| -> Vec<String> { s.split('\'').skip(1).step_by(2).map(str::to_string).collect() };
    // By their quoted words: 'ARG' … 'PREFIX -- ARG', and 'SUBCOMMAND' … '--'.
    let q = quoted(text);
    if let [arg, example] = q.as_slice() {
        if example.ends_with(&format!("-- {arg}")) {
            return msg!("cli-error-pass-as-value", arg = arg.as_str(), example = example.as_str());
        }
        if example == "--" {
            return msg!("cli-error-remove-dashes", subcommand = arg.as_str());
        }
    }
    msg!("cli-error-tip", tip = text)
}
