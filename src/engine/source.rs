//! IL source text → statements: the lexical half of loading a program, kept apart from
//! operand resolution so it knows no family.
//!
//! One pass over the text, linear in its length, never panicking: block comments
//! `(* … *)` (which may span lines), line comments `//`, labels `NAME:`, program
//! organisation unit headers (`PROGRAM`, `SUBROUTINE`/`SBR`, `INTERRUPT`/`INT`, each
//! optionally closed by `END_…`), network markers (`NETWORK n` or a comment that starts
//! with `Network n`, as KincoBuilder exports them) and instruction lines
//! `MNEMONIC operand, operand, …`. Every statement keeps its line and column so load
//! errors can name `file:line:column`.

use crate::msg;

/// Where a statement or operand came from (1-based line and column).
#[derive(Clone, Copy, Debug, PartialEq, Eq, Default, serde::Serialize, serde::Deserialize)]
pub struct Pos {
    pub line: u32,
    pub col: u32,
}

/// One operand as written (`%VW100`, `DI#100`, `*%VD4`), spaces around `#` removed.
#[derive(Clone, Debug, PartialEq)]
pub struct OperandText {
    pub text: String,
    pub pos: Pos,
}

/// One source statement.
#[derive(Clone, Debug, PartialEq)]
pub enum Stmt {
    /// A POU header: kind (`PROGRAM`, `SUBROUTINE`, `INTERRUPT`) and name.
    Pou {
        kind: PouKind,
        name: String,
        pos: Pos,
    },
    /// `END_PROGRAM`, `END_SUBROUTINE` …
    EndPou {
        pos: Pos,
    },
    Label {
        name: String,
        pos: Pos,
    },
    /// The start of network `n` (for breakpoints and stepping by network).
    Network {
        n: u32,
        pos: Pos,
    },
    Instr {
        mnemonic: String,
        operands: Vec<OperandText>,
        pos: Pos,
    },
}

/// Program organisation units.
#[derive(Clone, Copy, Debug, PartialEq, Eq, serde::Serialize, serde::Deserialize)]
pub enum PouKind {
    Program,
    Subroutine,
    Interrupt,
}

/// A lexical error: position and message.
#[derive(Clone, Debug, PartialEq)]
pub struct LexError {
    pub pos: Pos,
    pub message: String,
}

/// Longest line accepted (a guard against pathological input in one "line").
pub const MAX_LINE: usize = 4096;

/// Splits `text` into statements.
pub fn parse(text: &str) -> Result<Vec<Stmt>, LexError> {
    let mut out = Vec::new();
    // Pass 1 (linear): blank out comments, keeping line structure and columns, and note
    // network markers found in comments.
    let mut clean = String::with_capacity(text.len());
    let mut networks: Vec<(u32, Pos)> = Vec::new();
    let mut chars = text.char_indices().peekable();
    let (mut line, mut col) = (1u32, 1u32);
    while let Some((i, c)) = chars.next() {
        if c == '(' && text[i + 1..].starts_with('*') {
            let start = Pos { line, col };
            chars.next();
            clean.push_str("  ");
            col += 2;
            let body_start = i + 2;
            let mut closed = None;
            while let Some((j, d)) = chars.next() {
                if d == '*' && text[j + 1..].starts_with(')') {
                    chars.next();
                    closed = Some(j);
                    clean.push_str("  ");
                    col += 2;
                    break;
                }
                if d == '\n' {
                    clean.push('\n');
                    line += 1;
                    col = 1;
                } else {
                    clean.push(' ');
                    col += 1;
                }
            }
            let Some(end) = closed else {
                return Err(LexError { pos: start, message: msg!("engine-comment-unclosed").into() });
            };
            if let Some(n) = network_number(&text[body_start..end]) {
                networks.push((n, start));
            }
            continue;
        }
        if c == '/' && text[i + 1..].starts_with('/') {
            // Line comment: skip to the end of the line.
            while let Some(&(_, d)) = chars.peek() {
                if d == '\n' {
                    break;
                }
                chars.next();
            }
            continue;
        }
        if c == '\n' {
            line += 1;
            col = 1;
            clean.push('\n');
            continue;
        }
        // Columns count characters; keep one char per source char (tabs count as one).
        clean.push(if c == '\t' || c == '\r' { ' ' } else { c });
        col += 1;
    }
    let mut net_iter = networks.into_iter().peekable();
    for (idx, l) in clean.split('\n').enumerate() {
        let line = idx as u32 + 1;
        while let Some(&(n, p)) = net_iter.peek() {
            if p.line > line {
                break;
            }
            out.push(Stmt::Network { n, pos: p });
            net_iter.next();
        }
        if l.trim().chars().count() > MAX_LINE {
            return Err(LexError {
                pos: Pos { line, col: 1 },
                message: msg!("engine-line-too-long", max = MAX_LINE).into(),
            });
        }
        statement(l, line, &mut out)?;
    }
    Ok(out)
}

/// `Network 3` / `Network * 0` (the manual's OCR) at the start of a comment body.
fn network_number(body: &str) -> Option<u32> {
    let t = body.trim_start().trim_start_matches('\\');
    let rest = t.get(..7).filter(|h| h.eq_ignore_ascii_case("network")).map(|_| &t[7..])?;
    let digits: String =
        rest.trim_start_matches([' ', '*', '\\']).chars().take_while(|c| c.is_ascii_digit()).take(9).collect();
    digits.parse().ok()
}

fn is_ident_start(c: char) -> bool {
    c.is_ascii_alphabetic() || c == '_'
}

fn is_ident(s: &str) -> bool {
    let mut it = s.chars();
    it.next().is_some_and(is_ident_start) && it.all(|c| c.is_ascii_alphanumeric() || c == '_')
}

/// Character index → column (1-based) of byte offset `b` in `l`.
fn col_of(l: &str, b: usize) -> u32 {
    l[..b].chars().count() as u32 + 1
}

fn statement(l: &str, line: u32, out: &mut Vec<Stmt>) -> Result<(), LexError> {
    let trimmed = l.trim_start();
    if trimmed.trim().is_empty() {
        return Ok(());
    }
    let lead = l.len() - trimmed.len();
    let pos = Pos { line, col: col_of(l, lead) };
    // Label: `NAME:` possibly followed by an instruction on the same line.
    if let Some(colon) = trimmed.find(':') {
        let name = trimmed[..colon].trim_end();
        if is_ident(name) && !trimmed[..colon].contains(char::is_whitespace) {
            out.push(Stmt::Label { name: name.to_ascii_uppercase(), pos });
            let rest = &trimmed[colon + 1..];
            if !rest.trim().is_empty() {
                let off = lead + colon + 1;
                return instruction(l, off, line, out);
            }
            return Ok(());
        }
    }
    instruction(l, lead, line, out)
}

fn instruction(l: &str, from: usize, line: u32, out: &mut Vec<Stmt>) -> Result<(), LexError> {
    let rest = &l[from..];
    let lead = rest.len() - rest.trim_start().len();
    let start = from + lead;
    let body = &l[start..];
    let pos = Pos { line, col: col_of(l, start) };
    // The mnemonic runs to the first space; an operand glued on after a mnemonic of letters
    // (`READ_RTC%VB0`) is split at the `%`.
    let mut end = body.find(char::is_whitespace).unwrap_or(body.len());
    if let Some(p) = body[..end].find('%').filter(|&p| p > 0) {
        end = p;
    }
    let mnemonic = body[..end].to_ascii_uppercase();
    let args = &body[end..];
    let head = mnemonic.as_str();
    // POU headers and ends.
    let kind = match head {
        "PROGRAM" | "ORGANIZATION_BLOCK" => Some(PouKind::Program),
        "SUBROUTINE" | "SBR" | "SUBROUTINE_BLOCK" | "FUNCTION" => Some(PouKind::Subroutine),
        "INTERRUPT" | "INTERRUPT_BLOCK" => Some(PouKind::Interrupt),
        _ => None,
    };
    if let Some(kind) = kind {
        let name = args.trim();
        let name = name.split([':', ' ']).next().unwrap_or("");
        if !is_ident(name) {
            return Err(LexError { pos, message: format!("{head} needs a name, e.g. `{head} MAIN`") });
        }
        out.push(Stmt::Pou { kind, name: name.to_ascii_uppercase(), pos });
        return Ok(());
    }
    if head.starts_with("END_") && args.trim().is_empty() {
        out.push(Stmt::EndPou { pos });
        return Ok(());
    }
    if head == "NETWORK" {
        let n = args.split_whitespace().next().and_then(|t| t.parse().ok()).unwrap_or(0);
        out.push(Stmt::Network { n, pos });
        return Ok(());
    }
    let mut operands = Vec::new();
    let args_off = start + end;
    if !args.trim().is_empty() {
        let mut off = 0usize;
        for part in args.split(',') {
            let t = part.trim();
            let lead = part.len() - part.trim_start().len();
            let at = Pos { line, col: col_of(l, args_off + off + lead) };
            if t.is_empty() {
                return Err(LexError { pos: at, message: msg!("engine-empty-operand", text = body.trim_end()).into() });
            }
            operands.push(OperandText { text: squeeze(t), pos: at });
            off += part.len() + 1;
        }
    }
    out.push(Stmt::Instr { mnemonic, operands, pos });
    Ok(())
}

/// Removes spaces around `#` and after `%` (`DI # 100` → `DI#100`, the manual's OCR form)
/// and any other inner spaces that cannot be part of an operand.
fn squeeze(t: &str) -> String {
    let mut s = String::with_capacity(t.len());
    let chars: Vec<char> = t.chars().collect();
    for (i, &c) in chars.iter().enumerate() {
        if c.is_whitespace() {
            let prev = s.chars().last();
            let next = chars[i + 1..].iter().find(|c| !c.is_whitespace()).copied();
            if prev == Some('#') || next == Some('#') || prev == Some('%') {
                continue;
            }
        }
        s.push(c);
    }
    s
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn statements_labels_and_comments() {
        let src = "(* Network 1: start *)\nLD %SM0.0 // always\nLOOP: MOVE DI # 100, %SMD208\n  (* a\n  two-line comment *) ST %Q0.0\nJMPC LOOP\n";
        let s = parse(src).unwrap();
        assert_eq!(s[0], Stmt::Network { n: 1, pos: Pos { line: 1, col: 1 } });
        assert!(
            matches!(&s[1], Stmt::Instr { mnemonic, operands, .. } if mnemonic == "LD" && operands[0].text == "%SM0.0")
        );
        assert!(matches!(&s[2], Stmt::Label { name, .. } if name == "LOOP"));
        match &s[3] {
            Stmt::Instr { mnemonic, operands, pos } => {
                assert_eq!(mnemonic, "MOVE");
                assert_eq!(operands[0].text, "DI#100", "the manual's spaced literal");
                assert_eq!(operands[1].pos, Pos { line: 3, col: 22 });
                assert_eq!(*pos, Pos { line: 3, col: 7 });
            }
            o => panic!("{o:?}"),
        }
        assert!(matches!(&s[4], Stmt::Instr { mnemonic, pos, .. } if mnemonic == "ST" && pos.line == 5));
    }

    #[test]
    fn headers_and_glued_operands() {
        let s = parse("SUBROUTINE AGENT\nREAD_RTC%VB0\nEND_SUBROUTINE\nINTERRUPT INT_0\nRET").unwrap();
        assert!(matches!(&s[0], Stmt::Pou { kind: PouKind::Subroutine, name, .. } if name == "AGENT"));
        assert!(
            matches!(&s[1], Stmt::Instr { mnemonic, operands, .. } if mnemonic == "READ_RTC" && operands[0].text == "%VB0")
        );
        assert!(matches!(s[2], Stmt::EndPou { .. }));
        assert!(matches!(&s[3], Stmt::Pou { kind: PouKind::Interrupt, .. }));
    }

    #[test]
    fn bad_input_is_an_error_not_a_panic() {
        assert!(parse("(* never closed").unwrap_err().message.contains("never closed"));
        assert!(parse("MOVE 1,,%VW0").unwrap_err().message.contains("empty operand"));
        for junk in ["\u{0}\u{1}ä:ö", ":", "(*)", "*)", "LD ,", "ÄÖ%%%,", "(", "END_", "PROGRAM"] {
            let _ = parse(junk);
        }
    }

    #[test]
    fn time_is_linear_in_the_input() {
        // 200 000 comment openers inside one comment and a long instruction stream.
        let big = format!("(*{}*)\n{}", "(*".repeat(200_000), "LD %M0.0\n".repeat(100_000));
        let t = std::time::Instant::now();
        assert_eq!(parse(&big).unwrap().len(), 100_000);
        // Quadratic work on 200 000 openers is some 10^10 steps (minutes); linear is well under
        // a second. The bound is generous so a busy machine cannot fail it, and still far below
        // what a quadratic parser takes.
        assert!(t.elapsed() < std::time::Duration::from_secs(60), "{:?}", t.elapsed());
    }
}
