//! Splitting command lines: commands on `;`, items on `,`, words on spaces — never inside
//! brackets, parentheses, braces or quotes (so `profile 0 at VB3001 [(cycle=500us,
//! count=1000), …]` stays one argument). Every piece keeps its column for error carets.

use crate::core::{Error, Result};

/// Splits on `sep` at nesting depth 0; returns (column, piece) pairs.
pub fn split_top(s: &str, sep: char) -> Result<Vec<(usize, &str)>> {
    let mut out = Vec::new();
    let mut depth: Vec<char> = Vec::new();
    let mut quote: Option<char> = None;
    let mut start = 0;
    for (i, c) in s.char_indices() {
        if let Some(q) = quote {
            if c == q {
                quote = None;
            }
            continue;
        }
        match c {
            '"' | '\'' => quote = Some(c),
            '(' | '[' | '{' => depth.push(c),
            ')' | ']' | '}' => {
                let want = match c {
                    ')' => '(',
                    ']' => '[',
                    _ => '{',
                };
                if depth.pop() != Some(want) {
                    return Err(Error::syntax(format!("unbalanced `{c}`")).column(i));
                }
            }
            c if c == sep && depth.is_empty() => {
                out.push((start, &s[start..i]));
                start = i + c.len_utf8();
            }
            _ => {}
        }
    }
    if let Some(q) = quote {
        return Err(Error::syntax(format!("unclosed {q}")).column(s.len()));
    }
    if let Some(open) = depth.last() {
        return Err(Error::syntax(format!("unclosed `{open}`")).column(s.len()));
    }
    out.push((start, &s[start..]));
    Ok(out)
}

/// Splits a line into commands on `;`.
pub fn split_commands(line: &str) -> Result<Vec<(usize, &str)>> {
    split_top(line, ';')
}

/// Splits arguments into words on spaces and commas (top level), trimmed, non-empty.
pub fn words(s: &str) -> Result<Vec<(usize, &str)>> {
    let mut out = Vec::new();
    for (off, piece) in split_top(s, ',')? {
        let mut pos = 0;
        for w in split_top(piece, ' ')? {
            let t = w.1.trim();
            if !t.is_empty() {
                let lead = w.1.len() - w.1.trim_start().len();
                out.push((off + w.0 + lead, t));
            }
            pos = w.0;
        }
        let _ = pos;
    }
    Ok(out)
}

/// The words of a command's arguments, with columns in the whole line.
pub fn words_in<'a>(args: &super::Args<'a>) -> Result<Vec<Word<'a>>> {
    Ok(words(args.text).map_err(|e| e.shift(args.offset))?.into_iter().map(|(c, w)| (c + args.offset, w)).collect())
}

/// A word with its column.
pub type Word<'a> = (usize, &'a str);
/// A `key=value` option with its column.
pub type Opt<'a> = (usize, &'a str, &'a str);

/// Splits `key=value` options (lower-case keys) from positional words.
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
    }

    #[test]
    fn unbalanced_is_a_syntax_error() {
        assert!(split_commands("get (VW0").is_err());
        assert!(split_commands("get VW0]").is_err());
        assert!(split_commands("echo \"x").is_err());
    }

    #[test]
    fn options_split_lowercase_keys() {
        let w = words("0 freq=2kHz count=1000 SMB67=1").unwrap();
        let (p, o) = options(&w);
        assert_eq!(p.iter().map(|x| x.1).collect::<Vec<_>>(), vec!["0", "SMB67=1"]);
        assert_eq!(o.iter().map(|x| x.1).collect::<Vec<_>>(), vec!["freq", "count"]);
    }
}
