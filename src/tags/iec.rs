//! Tag tables as IEC 61131-3 declarations (ed. 3 §6.5.1–§6.5.6): global variables with
//! direct addresses, as a project's variable list is exported and as an IL program exported
//! with symbols declares them at its top:
//!
//! ```text
//! VAR_GLOBAL
//!     Conveyor_Run AT %MX0.3 : BOOL;     (* belt running *)
//!     Tank2_Level  AT %VD200 : REAL := 0.0; // level, m
//! END_VAR
//! ```
//!
//! Every `VAR_GLOBAL` block of the text is read (`CONSTANT`, `RETAIN`, `NON_RETAIN` after it
//! are allowed); a declaration is `name AT %address : TYPE [:= initial value];` and its
//! comment is the `(* … *)` or `//` comment that follows its `;` on the same line. A variable
//! without `AT` has no place in the PLC's memory and is refused, as is `a, b AT …` (§6.5.5:
//! one name per located variable). Outside the blocks a tag file holds only comments;
//! [`blocks`] finds the blocks of an IL program, which the program's loader blanks out.
//!
//! One pass over the text (a hand-written lexer; block comments do not nest, as in the
//! standard), every token with its line and column.

use super::name::address_text;
use super::{Problems, Tag, TagType};
use crate::msg;

#[derive(Clone, Debug, PartialEq)]
enum Kind {
    /// A word: an identifier or keyword.
    Word,
    /// A direct address `%…`.
    Address,
    /// `:`, `;`, `,`, `:=`, or any other single character.
    Punct,
    /// A literal (number, string) in an initial value.
    Other,
    /// A comment's text (without its delimiters).
    Comment,
}

#[derive(Clone, Debug)]
struct Token {
    kind: Kind,
    text: String,
    line: usize,
    col: usize,
    /// Byte offsets of the token in the text.
    start: usize,
    end: usize,
}

/// Splits the text into tokens. An unclosed `(*` is a problem at its start; the rest of the
/// text is then that comment.
fn tokens(text: &str, problems: &mut Problems<'_>) -> Vec<Token> {
    let mut out = Vec::new();
    let mut it = text.char_indices().peekable();
    let (mut line, mut col) = (1usize, 1usize);
    let step = |c: char, line: &mut usize, col: &mut usize| {
        if c == '\n' {
            *line += 1;
            *col = 1;
        } else {
            *col += 1;
        }
    };
    while let Some((i, c)) = it.next() {
        let (l0, c0) = (line, col);
        step(c, &mut line, &mut col);
        if c.is_whitespace() {
            continue;
        }
        let mut end = i + c.len_utf8();
        let kind;
        if c == '(' && it.peek().map(|p| p.1) == Some('*') {
            let (j, star) = it.next().unwrap();
            step(star, &mut line, &mut col);
            let body = j + 1;
            let mut closed = None;
            let mut prev = ' ';
            for (k, d) in it.by_ref() {
                step(d, &mut line, &mut col);
                if prev == '*' && d == ')' {
                    closed = Some(k);
                    break;
                }
                prev = d;
            }
            let Some(k) = closed else {
                problems.add(l0, c0, msg!("tags-iec-unclosed-comment"));
                break;
            };
            out.push(Token {
                kind: Kind::Comment,
                text: text[body..k - 1].trim().to_string(),
                line: l0,
                col: c0,
                start: i,
                end: k + 1,
            });
            continue;
        }
        if c == '/' && it.peek().map(|p| p.1) == Some('/') {
            while let Some(&(k, d)) = it.peek() {
                if d == '\n' {
                    break;
                }
                it.next();
                step(d, &mut line, &mut col);
                end = k + d.len_utf8();
            }
            out.push(Token {
                kind: Kind::Comment,
                text: text[i + 2..end].trim().to_string(),
                line: l0,
                col: c0,
                start: i,
                end,
            });
            continue;
        }
        let word_char = |d: char| d.is_alphanumeric() || d == '_';
        if word_char(c) || c == '%' {
            kind = if c == '%' {
                Kind::Address
            } else if c.is_ascii_digit() {
                Kind::Other
            } else {
                Kind::Word
            };
            // Addresses and numbers take dots (`%MX0.3`, `1.5`); every token takes `#` (`16#FF`,
            // `T#5s`).
            let more = |d: char| word_char(d) || d == '#' || (kind != Kind::Word && d == '.');
            while let Some(&(k, d)) = it.peek() {
                if !more(d) {
                    break;
                }
                it.next();
                step(d, &mut line, &mut col);
                end = k + d.len_utf8();
            }
        } else if c == '\'' || c == '"' {
            kind = Kind::Other;
            for (k, d) in it.by_ref() {
                step(d, &mut line, &mut col);
                end = k + d.len_utf8();
                if d == c {
                    break;
                }
            }
        } else if c == ':' && it.peek().map(|p| p.1) == Some('=') {
            let (k, d) = it.next().unwrap();
            step(d, &mut line, &mut col);
            end = k + 1;
            kind = Kind::Punct;
        } else {
            kind = Kind::Punct;
        }
        out.push(Token { kind, text: text[i..end].to_string(), line: l0, col: c0, start: i, end });
    }
    out
}

fn is_word(t: &Token, w: &str) -> bool {
    t.kind == Kind::Word && t.text.eq_ignore_ascii_case(w)
}

/// The byte offset of `keyword` as a word outside comments, if the text has it.
pub fn find_keyword(text: &str, keyword: &str) -> Option<usize> {
    let mut scratch = Problems::new("");
    tokens(text, &mut scratch).into_iter().find(|t| is_word(t, keyword)).map(|t| t.start)
}

/// The `VAR_GLOBAL … END_VAR` blocks of a text (an IL program with symbols): the tags they
/// declare and the byte range of each block (for the loader to blank out); problems as
/// [`parse`] reports them. Text outside the blocks is not looked at.
pub fn blocks(text: &str, problems: &mut Problems<'_>) -> (Vec<Tag>, Vec<std::ops::Range<usize>>) {
    read(text, problems, false)
}

/// Reads a file of IEC declarations: its `VAR_GLOBAL` blocks, with nothing but comments
/// outside them.
pub fn parse(text: &str, problems: &mut Problems<'_>) -> Vec<Tag> {
    let (tags, found) = read(text, problems, true);
    if found.is_empty() && problems.list.is_empty() {
        problems.add(1, 1, msg!("tags-iec-no-block"));
    }
    tags
}

fn read(text: &str, problems: &mut Problems<'_>, strict: bool) -> (Vec<Tag>, Vec<std::ops::Range<usize>>) {
    let toks = tokens(text, problems);
    let mut tags = Vec::new();
    let mut ranges = Vec::new();
    let mut i = 0;
    while i < toks.len() {
        let t = &toks[i];
        if t.kind == Kind::Comment {
            i += 1;
            continue;
        }
        if !is_word(t, "VAR_GLOBAL") {
            if strict {
                problems.add(
                    t.line,
                    t.col,
                    msg!("tags-iec-expected", expected = "VAR_GLOBAL", found = t.text.as_str()),
                );
                // Go on at the next block, so one stray word is one problem.
                while i < toks.len() && !is_word(&toks[i], "VAR_GLOBAL") {
                    i += 1;
                }
            } else {
                i += 1;
            }
            continue;
        }
        let start = t.start;
        i += 1;
        while i < toks.len() && ["CONSTANT", "RETAIN", "NON_RETAIN", "PERSISTENT"].iter().any(|w| is_word(&toks[i], w))
        {
            i += 1;
        }
        let mut closed = false;
        while i < toks.len() {
            if toks[i].kind == Kind::Comment {
                i += 1;
                continue;
            }
            if is_word(&toks[i], "END_VAR") {
                ranges.push(start..toks[i].end);
                closed = true;
                i += 1;
                break;
            }
            i = declaration(&toks, i, &mut tags, problems);
        }
        if !closed {
            problems.add(t.line, t.col, msg!("tags-iec-unclosed-block"));
        }
    }
    (tags, ranges)
}

/// Reads one declaration starting at token `i`; returns the index after it (after its `;`
/// and its comment, or where reading stopped on a problem: the next `;` or `END_VAR`).
fn declaration(toks: &[Token], mut i: usize, tags: &mut Vec<Tag>, problems: &mut Problems<'_>) -> usize {
    let skip_to_end = |mut i: usize| {
        while i < toks.len() && !is_word(&toks[i], "END_VAR") {
            if toks[i].text == ";" && toks[i].kind == Kind::Punct {
                return i + 1;
            }
            i += 1;
        }
        i
    };
    let code = |i: usize| toks.get(i).filter(|t| t.kind != Kind::Comment);
    let next_code = |mut i: usize| {
        while toks.get(i).is_some_and(|t| t.kind == Kind::Comment) {
            i += 1;
        }
        i
    };
    let name = &toks[i];
    if name.kind != Kind::Word {
        problems.add(
            name.line,
            name.col,
            msg!("tags-iec-expected", expected = "NAME AT %ADDRESS : TYPE;", found = name.text.as_str()),
        );
        return skip_to_end(i + 1).max(i + 1);
    }
    i = next_code(i + 1);
    if code(i).is_some_and(|t| t.text == ",") {
        problems.add(toks[i].line, toks[i].col, msg!("tags-iec-one-name", name = name.text.as_str()));
        return skip_to_end(i);
    }
    let mut address = None;
    if code(i).is_some_and(|t| is_word(t, "AT")) {
        i = next_code(i + 1);
        match code(i) {
            Some(t) if t.kind == Kind::Address => {
                address = Some(t);
                i = next_code(i + 1);
            }
            other => {
                let (l, c, f) = other.map_or((name.line, name.col, ""), |t| (t.line, t.col, t.text.as_str()));
                problems.add(l, c, msg!("tags-iec-expected", expected = "%ADDRESS", found = f));
                return skip_to_end(i);
            }
        }
    }
    if code(i).is_none_or(|t| t.text != ":") {
        let (l, c, f) = code(i).map_or((name.line, name.col, ""), |t| (t.line, t.col, t.text.as_str()));
        problems.add(l, c, msg!("tags-iec-expected", expected = ":", found = f));
        return skip_to_end(i);
    }
    i = next_code(i + 1);
    let Some(ty) = code(i).filter(|t| t.kind == Kind::Word) else {
        let (l, c, f) = code(i).map_or((name.line, name.col, ""), |t| (t.line, t.col, t.text.as_str()));
        problems.add(l, c, msg!("tags-iec-expected", expected = "TYPE", found = f));
        return skip_to_end(i);
    };
    i = next_code(i + 1);
    // An initial value: every token up to the `;`.
    if code(i).is_some_and(|t| t.text == ":=") {
        while i < toks.len() && !(toks[i].text == ";" && toks[i].kind == Kind::Punct) && !is_word(&toks[i], "END_VAR") {
            i += 1;
        }
    }
    let Some(semi) = code(i).filter(|t| t.text == ";") else {
        let (l, c, f) = code(i).map_or((ty.line, ty.col, ""), |t| (t.line, t.col, t.text.as_str()));
        problems.add(l, c, msg!("tags-iec-expected", expected = ";", found = f));
        return skip_to_end(i);
    };
    i += 1;
    let mut comment = String::new();
    if let Some(c) = toks.get(i).filter(|t| t.kind == Kind::Comment && t.line == semi.line) {
        comment = c.text.clone();
        i += 1;
    }
    let Some(address) = address else {
        problems.add(name.line, name.col, msg!("tags-iec-no-address", name = name.text.as_str()));
        return i;
    };
    let Some(dtype) = TagType::parse(&ty.text) else {
        problems.add(ty.line, ty.col, msg!("tags-unknown-type", name = name.text.as_str(), dtype = ty.text.as_str()));
        return i;
    };
    tags.push(Tag {
        name: name.text.clone(),
        address: address_text(&address.text),
        dtype,
        comment,
        line: name.line,
        column: name.col,
    });
    i
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::core::DataType;

    fn read(text: &str) -> (Vec<Tag>, Vec<String>) {
        let mut p = Problems::new("t.st");
        let t = parse(text, &mut p);
        (t, p.list.iter().map(|p| p.to_string()).collect())
    }

    #[test]
    fn declarations_with_addresses_types_and_comments() {
        let (t, p) = read(
            "(* press 1 *)\nVAR_GLOBAL RETAIN\n  Conveyor_Run AT %MX0.3 : BOOL; (* belt running *)\n  Tank2_Level AT %VD200 : REAL := 1.5; // level, m\n  电机_启动 AT %Q0.0:BOOL;\nEND_VAR\nvar_global\n  Мотор_1 AT %VW10 : INT;\nend_var\n",
        );
        assert!(p.is_empty(), "{p:?}");
        assert_eq!(t.len(), 4);
        assert_eq!(
            (t[0].name.as_str(), t[0].address.as_str(), t[0].comment.as_str()),
            ("Conveyor_Run", "M0.3", "belt running")
        );
        assert_eq!(
            (t[1].dtype, t[1].comment.as_str(), t[1].line, t[1].column),
            (TagType::Of(DataType::Real), "level, m", 4, 3)
        );
        assert_eq!((t[2].address.as_str(), t[2].comment.as_str()), ("Q0.0", ""));
        assert_eq!(t[3].dtype, TagType::Of(DataType::Int));
    }

    #[test]
    fn one_problem_per_declaration_and_reading_goes_on() {
        let (t, p) = read(
            "VAR_GLOBAL\n  A AT %VW0 : FLOAT;\n  B : INT;\n  C, D AT %VW2 : INT;\n  E AT VW4 : INT;\n  F AT %VW6 INT;\n  G AT %VW8 : INT;\nEND_VAR\nstray\n",
        );
        assert_eq!(t.len(), 1, "{p:?}");
        assert_eq!(t[0].name, "G");
        let at: Vec<&str> = p.iter().map(|p| p.split(": ").next().unwrap()).collect();
        assert_eq!(at, ["t.st:2:15", "t.st:3:3", "t.st:4:4", "t.st:5:8", "t.st:6:13", "t.st:9:1"], "{p:?}");
        let (_, p) = read("VAR_GLOBAL\n A AT %VW0 : INT; (* open\n");
        assert_eq!(p.len(), 2, "{p:?}");
        let (_, p) = read("(* nothing *)\n");
        assert_eq!(p, ["t.st:1:1: no VAR_GLOBAL … END_VAR block in the file"]);
    }

    #[test]
    fn blocks_of_a_program_are_found_with_their_ranges() {
        let text = "VAR_GLOBAL\n Start AT %I0.0 : BOOL;\nEND_VAR\nLD Start\nST %Q0.0\n";
        let mut p = Problems::new("p.il");
        let (t, r) = blocks(text, &mut p);
        assert!(p.list.is_empty());
        assert_eq!(t[0].address, "I0.0");
        assert_eq!(&text[r[0].clone()], "VAR_GLOBAL\n Start AT %I0.0 : BOOL;\nEND_VAR");
        assert_eq!(find_keyword("(* VAR_GLOBAL *) x", "VAR_GLOBAL"), None);
    }
}
