//! Splitting command lines: commands on `;`, items on `,`, words on spaces — never inside
//! brackets, parentheses, braces or quotes (so `profile 0 at VB3001 [(cycle=500us,
//! count=1000), …]` stays one argument). Every piece keeps its column for error carets.
//!
//! Quoting (docs/commands.md, "Quoting"; the rules are [`Quotes`]): `"…"` and `'…'` hold
//! spaces, `;`, `,`, `#` and brackets; inside double quotes `\"` and `\\` are escapes and every
//! other backslash is itself (`"C:\Users\Иванов\лаб 1"`); inside single quotes everything is
//! itself. Words keep their quotes (their columns stay those of the line); a command reads a
//! path, a name or a message with [`unquote`], and a line that carries a path is built with
//! [`quote`]. Every function here is one pass over its input.

use crate::core::text::{Quotes, Role};
use crate::core::{Error, Result};
use std::borrow::Cow;

/// The error for quoted text that is never closed, at its opening quote.
fn unclosed(at: usize, q: char) -> Error {
    Error::syntax(format!("unclosed {q}")).column(at).hint(crate::msg!("shell-hint-close-quote"))
}

/// Tracks brackets outside quotes; `Err` at an unbalanced closing one.
fn bracket(depth: &mut Vec<char>, c: char, at: usize) -> Result<()> {
    match c {
        '(' | '[' | '{' => depth.push(c),
        ')' | ']' | '}' => {
            let want = match c {
                ')' => '(',
                ']' => '[',
                _ => '{',
            };
            if depth.pop() != Some(want) {
                return Err(Error::syntax(format!("unbalanced `{c}`")).column(at));
            }
        }
        _ => {}
    }
    Ok(())
}

/// Splits `s` wherever `is_sep` holds for an unquoted character at nesting depth 0; returns
/// (column, piece) pairs, empty pieces included.
fn split_where(s: &str, is_sep: impl Fn(char) -> bool) -> Result<Vec<(usize, &str)>> {
    let mut out = Vec::new();
    let mut depth: Vec<char> = Vec::new();
    let mut quotes = Quotes::default();
    let mut start = 0;
    let mut it = s.char_indices().peekable();
    while let Some((i, c)) = it.next() {
        if quotes.feed(i, c, it.peek().map(|p| p.1)) != Role::Bare {
            continue;
        }
        if is_sep(c) && depth.is_empty() {
            out.push((start, &s[start..i]));
            start = i + c.len_utf8();
            continue;
        }
        bracket(&mut depth, c, i)?;
    }
    if let Some((at, q)) = quotes.open {
        return Err(unclosed(at, q));
    }
    if let Some(open) = depth.last() {
        return Err(Error::syntax(format!("unclosed `{open}`")).column(s.len()));
    }
    out.push((start, &s[start..]));
    Ok(out)
}

/// Splits on `sep` at nesting depth 0, outside quotes; returns (column, piece) pairs.
pub fn split_top(s: &str, sep: char) -> Result<Vec<(usize, &str)>> {
    split_where(s, |c| c == sep)
}

/// Splits a line into commands on `;`.
pub fn split_commands(line: &str) -> Result<Vec<(usize, &str)>> {
    split_top(line, ';')
}

/// Splits arguments into words on white space and commas (outside quotes and brackets),
/// non-empty. A word keeps its quotes: `to="a b.png"` is one word.
pub fn words(s: &str) -> Result<Vec<(usize, &str)>> {
    Ok(split_where(s, |c| c.is_whitespace() || c == ',')?.into_iter().filter(|w| !w.1.is_empty()).collect())
}

/// The words of a command's arguments, with columns in the whole line.
pub fn words_in<'a>(args: &super::Args<'a>) -> Result<Vec<Word<'a>>> {
    Ok(words(args.text).map_err(|e| e.shift(args.offset))?.into_iter().map(|(c, w)| (c + args.offset, w)).collect())
}

/// The text a word stands for: its quotes removed and escapes applied (`"a b.il"` → `a b.il`,
/// `'C:\lab'` → `C:\lab`, `"say \"hi\""` → `say "hi"`, `to="x y.png"` → `to=x y.png`); a
/// word without quotes is itself. Never fails: quoted text left open runs to the end.
pub fn unquote(word: &str) -> Cow<'_, str> {
    if !word.contains(['"', '\'']) {
        return Cow::Borrowed(word);
    }
    let mut out = String::with_capacity(word.len());
    for (_, c, role) in Quotes::roles(word) {
        if matches!(role, Role::Bare | Role::Quoted) {
            out.push(c);
        }
    }
    Cow::Owned(out)
}

/// The words of `text` as text, quotes removed: for commands that match their words as a
/// list (`eeprom dump FILE [all]`, `lab grade LAB SUBMISSIONS…`).
pub fn unquoted_words(text: &str) -> Result<Vec<Cow<'_, str>>> {
    Ok(words(text)?.into_iter().map(|(_, w)| unquote(w)).collect())
}

/// The one path a command takes after the first `skip` words of its arguments, unquoted, with
/// its column in the line; `None` when there is none. Several words there are refused (a path
/// with spaces goes in quotes), never cut at the first space.
pub fn one_path(args: &super::Args, skip: usize, form: &str) -> Result<Option<(usize, String)>> {
    let words = words_in(args)?;
    match words.get(skip..).unwrap_or_default() {
        [] => Ok(None),
        [(c, w)] => Ok(Some((*c, unquote(w).into_owned()))),
        more => {
            let typed: Vec<&str> = more.iter().map(|w| w.1).collect();
            // A quoted path is one word already: the words after it are extra, not part of it.
            let hint = if typed[0].contains(['"', '\'']) {
                crate::msg!("shell-hint-one-file", line = format!("{form} {}", typed[0]))
            } else {
                crate::msg!("shell-hint-quote-path", line = format!("{form} {}", quote(&typed.join(" "))))
            };
            Err(Error::usage(crate::msg!(
                "shell-one-file-only",
                form = form,
                count = more.len(),
                words = typed.join("`, `")
            ))
            .hint(hint)
            .column(more[1].0))
        }
    }
}

/// A character that needs no quotes anywhere in a word.
fn plain(c: char) -> bool {
    c.is_ascii_alphanumeric() || "._-/:+@~\\".contains(c)
}

/// `text` as one word of the shell language, whatever it holds (spaces, quotes, `;`, `#`,
/// Cyrillic letters, backslashes): itself when it needs no quotes, else in single quotes, or
/// in double quotes with `"` and `\` escaped when it holds a single quote.
/// `unquote(quote(t)) == t` for every `t` (the lexer's property test).
pub fn quote(text: &str) -> Cow<'_, str> {
    if !text.is_empty() && text.chars().all(plain) {
        return Cow::Borrowed(text);
    }
    if !text.contains('\'') {
        return Cow::Owned(format!("'{text}'"));
    }
    let mut out = String::with_capacity(text.len() + 8);
    out.push('"');
    for c in text.chars() {
        if c == '"' || c == '\\' {
            out.push('\\');
        }
        out.push(c);
    }
    out.push('"');
    Cow::Owned(out)
}

/// A word with its column.
pub type Word<'a> = (usize, &'a str);
/// A `key=value` option with its column.
pub type Opt<'a> = (usize, &'a str, &'a str);

/// Splits `key=value` options (lower-case keys) from positional words. A value keeps its
/// quotes (`to="a b.png"` gives `"a b.png"`: [`unquote`] it); a word that starts with a quote
/// is never an option.
pub fn options<'a>(words: &[Word<'a>]) -> (Vec<Word<'a>>, Vec<Opt<'a>>) {
    let mut pos = Vec::new();
    let mut opts = Vec::new();
    for &(c, w) in words {
        match w.split_once('=') {
            Some((k, v))
                if !k.is_empty()
                    && k.chars().all(|ch| ch.is_ascii_alphanumeric() || ch == '_')
                    && k.chars().next().is_some_and(|ch| ch.is_ascii_lowercase()) =>
            {
                opts.push((c, k, v))
            }
            _ => pos.push((c, w)),
        }
    }
    (pos, opts)
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::core::test_rng::Rng;

    #[test]
    fn commands_split_on_semicolons_outside_brackets() {
        let v = split_commands("set VW0=1; get VW0 ; profile 0 [(a=1; b=2)]").unwrap();
        let texts: Vec<&str> = v.iter().map(|p| p.1.trim()).collect();
        assert_eq!(texts, vec!["set VW0=1", "get VW0", "profile 0 [(a=1; b=2)]"]);
        assert_eq!(v[1].0, 10);
    }

    #[test]
    fn words_keep_columns() {
        let v = words("VW0, VW2  SMB67").unwrap();
        assert_eq!(v, vec![(0, "VW0"), (5, "VW2"), (10, "SMB67")]);
        assert_eq!(words("a\tb").unwrap(), vec![(0, "a"), (2, "b")]);
    }

    #[test]
    fn unbalanced_is_a_syntax_error() {
        assert!(split_commands("get (VW0").is_err());
        assert!(split_commands("get VW0]").is_err());
        let e = split_commands("echo \"x").unwrap_err();
        assert_eq!(e.column, Some(5), "the caret points at the quote left open");
        assert!(split_commands("a 'b").is_err());
        assert!(split_commands(r#"a "b\""#).is_err(), "an escaped quote does not close");
    }

    #[test]
    fn options_split_lowercase_keys() {
        let w = words("0 freq=2kHz count=1000 SMB67=1").unwrap();
        let (p, o) = options(&w);
        assert_eq!(p.iter().map(|x| x.1).collect::<Vec<_>>(), vec!["0", "SMB67=1"]);
        assert_eq!(o.iter().map(|x| x.1).collect::<Vec<_>>(), vec!["freq", "count"]);
        let w = words(r#"to="my plot.svg" 'to=x'"#).unwrap();
        let (p, o) = options(&w);
        assert_eq!((o[0].1, unquote(o[0].2).as_ref()), ("to", "my plot.svg"));
        assert_eq!(p.iter().map(|x| unquote(x.1)).collect::<Vec<_>>(), vec!["to=x"]);
    }

    /// The documented rules (docs/commands.md, "Quoting"), one example each.
    #[test]
    fn quoted_words_are_one_word_and_reach_commands_unquoted() {
        let line = r#"sim program load "Проверка 1/светофор.il"; eeprom dump 'a;b #1.bin' # comment"#;
        let cmds = split_commands(line).unwrap();
        assert_eq!(cmds.len(), 2, "`;` inside quotes does not split");
        let w = words(cmds[0].1).unwrap();
        assert_eq!(w.len(), 4);
        assert_eq!(unquote(w[3].1), "Проверка 1/светофор.il");
        let w = words(cmds[1].1).unwrap();
        assert_eq!(unquote(w[2].1), "a;b #1.bin");
        for (word, text) in [
            (r#""C:\Users\Иванов\лаб 1""#, r"C:\Users\Иванов\лаб 1"),
            (r#""say \"hi\"""#, r#"say "hi""#),
            (r#""a\\b""#, r"a\b"),
            (r#""C:\dir\\""#, r"C:\dir\"),
            (r"'C:\x\'", r"C:\x\"),
            (r#"'it"s'"#, r#"it"s"#),
            (r"C:\plain\path", r"C:\plain\path"),
            (r#"to="x y.png""#, "to=x y.png"),
            (r#"a"b c"d"#, "ab cd"),
            ("''", ""),
        ] {
            assert_eq!(words(word).unwrap(), vec![(0, word)], "{word} is one word");
            assert_eq!(unquote(word), text, "{word}");
        }
    }

    /// Whatever a path holds, `quote` makes it one word the lexer gives back unchanged (the lab
    /// runner builds its `sim program load` line this way).
    #[test]
    fn quote_then_unquote_gives_the_text_back() {
        let alphabet: Vec<char> = " \t\"'\\;,#()[]{}=%aZ09._-/:Пр€😀".chars().collect();
        let mut rng = Rng(0x5eed_f11e_0a7e);
        for _ in 0..20_000 {
            let len = rng.below(12) as usize;
            let text: String = (0..len).map(|_| rng.pick(&alphabet)).collect();
            let q = quote(&text);
            let line = format!("sim program load {q}; get VW0");
            let cmds = split_commands(&line).unwrap_or_else(|e| panic!("{text:?} as {q}: {e}"));
            assert_eq!(cmds.len(), 2, "{text:?} as {q}");
            let w = words(cmds[0].1).unwrap();
            assert_eq!(w.len(), 4, "{text:?} as {q}: {w:?}");
            assert_eq!(unquote(w[3].1), text, "{text:?} as {q}");
        }
        assert_eq!(quote("prog.il"), "prog.il");
        assert_eq!(quote(r"C:\lab\prog.il"), r"C:\lab\prog.il");
        assert_eq!(quote("лаб 1/ref.il"), "'лаб 1/ref.il'");
        assert_eq!(quote("it's"), r#""it's""#);
    }

    /// Long inputs of the characters that change state are read in one pass.
    #[test]
    fn long_lines_take_linear_time() {
        for unit in ["\"\\\"", "'(", "((", "\\\\\"", "a, ", "# ;"] {
            let line = unit.repeat(200_000);
            let t = std::time::Instant::now();
            let _ = split_commands(&line);
            let _ = words(&line);
            let _ = unquote(&line);
            let _ = quote(&line);
            assert!(t.elapsed() < std::time::Duration::from_secs(10), "{unit:?}: {:?}", t.elapsed());
        }
    }
}
