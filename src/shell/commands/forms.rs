//! The forms of every command, read from the registry's usage lines, and what is made from
//! them: `help COMMAND`, the guide's command card, Tab completion of options, and the one
//! strictness check every command goes through ([`check`]): a word after the end of every
//! form the command has is refused, with the form and the word's column, before the command
//! runs (`servo save x` never reaches the drive).
//!
//! The notation of a form: `WORD` (upper case, or starting with a digit: `I0.1`, `3902`) is a
//! placeholder for one word; lower-case words are themselves (`status`, `->`); `a|b` is one of
//! them; `[…]` is optional, and inside brackets `|` separates whole alternatives
//! (`[drive CODE|no-reply]`); `X…` or `…` takes any number of further words; `key=VALUE` is an
//! option (options are checked by the command, which knows their values); `[(…), …]` is a
//! bracketed list, one word.

use super::{CommandSpec, COMMANDS};
use crate::core::{Error, Result};
use crate::shell::{lex, Args};

/// One form of a command: `sim step DURATION`, `servo move abs|rel POS [speed=300rpm …]`.
#[derive(Clone, Debug, PartialEq)]
pub struct Form {
    /// The sub-command the form belongs to, if the command has sub-commands and the form
    /// names one (`hsc N status` → `status`).
    pub sub: Option<&'static str>,
    /// The form as `help` and the command card show it, starting with the command's name.
    pub text: String,
}

/// The usage line without its examples (`   e.g. …`) and remarks (`   (also …)`).
pub fn bare_usage(c: &CommandSpec) -> &'static str {
    c.usage.split("   ").next().unwrap_or(c.usage).trim()
}

/// The first sub-command among the words of a form (after the command's name).
fn sub_of(c: &CommandSpec, text: &str) -> Option<&'static str> {
    text.split_whitespace()
        .skip(1)
        .flat_map(|w| w.trim_matches(['[', ']']).split('|'))
        .find_map(|w| c.subcommands.iter().find(|s| **s == w).copied())
}

/// Every form of a command, in the order of its usage line. A usage of whole forms
/// separated by ` | ` (`sim time | sim step DURATION`) gives one form each; a compact one
/// (`servo [DEVICE] status|enable|move abs|rel POS`) starts a new form at each piece that
/// starts with a sub-command, any other piece continuing the last form.
pub fn of(c: &CommandSpec) -> Vec<Form> {
    let usage = bare_usage(c);
    let mut forms: Vec<Form> = Vec::new();
    if usage.contains(" | ") {
        for piece in usage.split(" | ").map(str::trim) {
            if piece.split_whitespace().next() == Some(c.name) {
                forms.push(Form { sub: sub_of(c, piece), text: piece.to_string() });
            }
        }
        return forms;
    }
    for piece in usage.split('|') {
        let words: Vec<&str> = piece.split_whitespace().collect();
        let lead = words.iter().take_while(|w| **w == c.name || **w == "[DEVICE]").count();
        let starts = words.get(lead).and_then(|w| c.subcommands.iter().find(|s| *s == w));
        match (starts, forms.last_mut()) {
            (Some(sub), _) => {
                forms.push(Form { sub: Some(sub), text: format!("{} {}", c.name, words[lead..].join(" ")) })
            }
            (None, Some(last)) => {
                last.text.push('|');
                last.text.push_str(piece.trim_end());
            }
            (None, None) => forms.push(Form { sub: sub_of(c, piece), text: piece.trim().to_string() }),
        }
    }
    for f in &mut forms {
        f.text = f.text.trim().to_string();
    }
    forms
}

/// One piece of a form's grammar.
#[derive(Clone, Debug, PartialEq)]
enum Node {
    /// A word typed as it stands (any case).
    Lit(String),
    /// Any one word.
    Any,
    /// Any number of words, none included.
    Rest,
    Opt(Vec<Node>),
    Alt(Vec<Vec<Node>>),
}

/// A form's tokens.
#[derive(Clone, Debug, PartialEq)]
enum Tok {
    Open,
    Close,
    Bar,
    Word(String),
    /// `key=VALUE`: the key and the value as the form shows it.
    Option(String, String),
    /// `[(…), …]`: a list in brackets, one word.
    List,
    Many,
}

fn is_key(s: &str) -> bool {
    s.chars().next().is_some_and(|c| c.is_ascii_lowercase())
        && s.chars().all(|c| c.is_ascii_lowercase() || c.is_ascii_digit() || c == '_')
}

fn tokens(form: &str) -> Vec<Tok> {
    let b: Vec<char> = form.chars().collect();
    let mut out = Vec::new();
    let mut i = 0;
    while i < b.len() {
        let c = b[i];
        match c {
            ' ' | ',' => i += 1,
            '[' if b.get(i + 1) == Some(&'(') => {
                // A list typed in brackets: to the matching `]`.
                let mut depth = 0;
                while i < b.len() {
                    match b[i] {
                        '[' => depth += 1,
                        ']' => depth -= 1,
                        _ => {}
                    }
                    i += 1;
                    if depth == 0 {
                        break;
                    }
                }
                out.push(Tok::List);
            }
            '[' => {
                out.push(Tok::Open);
                i += 1;
            }
            ']' => {
                out.push(Tok::Close);
                i += 1;
            }
            '|' => {
                out.push(Tok::Bar);
                i += 1;
            }
            '…' => {
                out.push(Tok::Many);
                i += 1;
            }
            _ => {
                let start = i;
                while i < b.len() && !" ,[]|…=".contains(b[i]) {
                    i += 1;
                }
                let word: String = b[start..i].iter().collect();
                if b.get(i) == Some(&'=') && is_key(&word) {
                    // The value: to a space or a `]` that closes an outer bracket.
                    i += 1;
                    let from = i;
                    let mut depth = 0i32;
                    while i < b.len() {
                        match b[i] {
                            '[' | '(' => depth += 1,
                            ']' | ')' if depth == 0 => break,
                            ']' | ')' => depth -= 1,
                            ' ' if depth == 0 => break,
                            _ => {}
                        }
                        i += 1;
                    }
                    out.push(Tok::Option(word, b[from..i].iter().collect()));
                } else if b.get(i) == Some(&'=') {
                    // `OPERAND=VALUE`, `I3=1`: one positional word.
                    while i < b.len() && !" ,[]|…".contains(b[i]) {
                        i += 1;
                    }
                    out.push(Tok::Word(word));
                } else {
                    out.push(Tok::Word(word));
                }
            }
        }
    }
    out
}

/// A token word as a node: placeholders (upper case or digits) match any word.
fn word_node(w: &str) -> Node {
    if w.chars().any(|c| c.is_ascii_uppercase()) || w.starts_with(|c: char| c.is_ascii_digit()) {
        Node::Any
    } else {
        Node::Lit(w.to_string())
    }
}

/// Parses tokens up to a `]` (or the end); `in_brackets` makes `|` separate whole sequences.
/// Returns the nodes and the option keys seen.
fn parse(t: &[Tok], i: &mut usize, in_brackets: bool, keys: &mut Vec<String>) -> Vec<Node> {
    let mut seqs: Vec<Vec<Node>> = vec![Vec::new()];
    let mut tight = false;
    while *i < t.len() {
        let tok = t[*i].clone();
        *i += 1;
        let node = match tok {
            Tok::Close => break,
            Tok::Open => Node::Opt(parse(t, i, true, keys)),
            Tok::Bar if in_brackets => {
                seqs.push(Vec::new());
                continue;
            }
            Tok::Bar => {
                tight = true;
                continue;
            }
            Tok::Word(w) => word_node(&w),
            Tok::Option(k, _) => {
                keys.push(k);
                continue;
            }
            Tok::List => Node::Opt(vec![Node::Any]),
            Tok::Many => Node::Rest,
        };
        let seq = seqs.last_mut().expect("one sequence at least");
        if std::mem::take(&mut tight) {
            // `abs|rel`: one of the two words.
            let before = seq.pop().map(|n| match n {
                Node::Alt(a) => a,
                n => vec![vec![n]],
            });
            let mut alts = before.unwrap_or_default();
            alts.push(vec![node]);
            seq.push(Node::Alt(alts));
        } else {
            seq.push(node);
        }
    }
    if seqs.len() == 1 {
        seqs.pop().unwrap_or_default()
    } else {
        vec![Node::Alt(seqs)]
    }
}

/// A form's grammar (after the command's name) and its option keys.
struct Grammar {
    nodes: Vec<Node>,
    keys: Vec<String>,
    text: String,
}

fn grammar(c: &CommandSpec, f: &Form) -> Grammar {
    let body = f.text.split_once(' ').map_or("", |(_, r)| r);
    let mut keys = Vec::new();
    let toks = tokens(body);
    let mut nodes = parse(&toks, &mut 0, false, &mut keys);
    // Commands that read their device word themselves: `servo axis1 save`.
    if super::OWN_DEVICE_WORD.contains(&c.name) && !matches!(nodes.first(), Some(Node::Opt(_))) {
        nodes.insert(0, Node::Opt(vec![Node::Any]));
    }
    Grammar { nodes, keys, text: f.text.clone() }
}

/// An optional part that starts with a word of its own (`[strict]`, `[at VB3009]`,
/// `[sync|async]`), never a placeholder.
fn keyword_led(n: &Node) -> bool {
    fn led(seq: &[Node]) -> bool {
        match seq.first() {
            Some(Node::Lit(_)) => true,
            Some(Node::Alt(a)) => a.iter().all(|s| led(s)),
            _ => false,
        }
    }
    matches!(n, Node::Opt(seq) if led(seq))
}

/// The positions in `words` a sequence can end at, from each of `from`.
fn reach(nodes: &[Node], words: &[&str], from: Vec<usize>) -> Vec<usize> {
    let mut at = from;
    let mut i = 0;
    while i < nodes.len() {
        let n = &nodes[i];
        i += 1;
        if keyword_led(n) {
            // A run of optional parts that each start with a word of their own is taken in
            // any order (`[relative] [cyclic] [at VB3009]`, `[force] [strict]`): as many
            // rounds as there are parts.
            let mut group = vec![n];
            while let Some(next) = nodes.get(i).filter(|m| keyword_led(m)) {
                group.push(next);
                i += 1;
            }
            for _ in 0..group.len() {
                let mut next = at.clone();
                for g in &group {
                    if let Node::Opt(seq) = g {
                        next.extend(reach(seq, words, at.clone()));
                    }
                }
                next.sort_unstable();
                next.dedup();
                if next == at {
                    break;
                }
                at = next;
            }
            continue;
        }
        if let (Node::Rest, Some(&first)) = (n, at.iter().min()) {
            // Any number of words: every position from the first reached (once, so a long
            // line costs its length, not its square).
            at = (first..=words.len()).collect();
            continue;
        }
        let mut next = Vec::new();
        for &p in &at {
            match n {
                Node::Lit(l) => {
                    if words.get(p).is_some_and(|w| w.eq_ignore_ascii_case(l)) {
                        next.push(p + 1)
                    }
                }
                Node::Any => {
                    if p < words.len() {
                        next.push(p + 1)
                    }
                }
                Node::Rest => next.extend(p..=words.len()),
                Node::Opt(seq) => {
                    next.push(p);
                    next.extend(reach(seq, words, vec![p]));
                }
                Node::Alt(seqs) => {
                    for s in seqs {
                        next.extend(reach(s, words, vec![p]));
                    }
                }
            }
        }
        next.sort_unstable();
        next.dedup();
        at = next;
        if at.is_empty() {
            break;
        }
    }
    at
}

/// The strictness check of every command (run by the shell before the command): the
/// positional words of `args` (options aside) must fit one of the command's forms. When
/// every form that fits a beginning of them ends before the last word, the first word after
/// that end is refused, with the forms and its column. Words that fit no form at all are left
/// to the command, whose message knows what it expected there.
pub fn check(c: &CommandSpec, args: Args) -> Result<()> {
    if c.name == "lua" {
        return Ok(());
    }
    let Ok(all) = lex::words_in(&args) else { return Ok(()) };
    let (positional, opts) = lex::options(&all);
    let words: Vec<&str> = positional.iter().map(|w| w.1).collect();
    let grammars: Vec<Grammar> = of(c).iter().map(|f| grammar(c, f)).collect();
    let ends: Vec<Vec<usize>> = grammars.iter().map(|g| reach(&g.nodes, &words, vec![0])).collect();
    let n = words.len();
    let fits: Vec<&Grammar> = grammars.iter().zip(&ends).filter(|(_, e)| e.contains(&n)).map(|(g, _)| g).collect();
    if !fits.is_empty() {
        // Options to a command none of whose forms takes any: `devices all=1`.
        if grammars.iter().all(|g| g.keys.is_empty()) {
            if let Some(&(col, k, _)) = opts.first() {
                let forms: Vec<&str> = fits.iter().map(|g| g.text.as_str()).collect();
                return Err(Error::usage(crate::msg!("shell-no-options", forms = forms.join("` | `"), key = k))
                    .hint(crate::msg!("shell-hint-the-form", forms = forms.join(" | "), command = c.name))
                    .column(col));
            }
        }
        return Ok(());
    }
    let Some(end) = ends.iter().flatten().copied().filter(|&e| e < n).max() else { return Ok(()) };
    if ends.iter().flatten().any(|&e| e > end) {
        return Ok(()); // a longer form is still being typed: the command says what is missing
    }
    let mut forms: Vec<&str> =
        grammars.iter().zip(&ends).filter(|(_, e)| e.contains(&end)).map(|(g, _)| g.text.as_str()).collect();
    forms.dedup();
    let (col, extra) = positional[end];
    let typed: Vec<&str> = std::iter::once(c.name).chain(words[..end].iter().copied()).collect();
    let sub = forms.first().and_then(|f| of(c).into_iter().find(|g| g.text == *f)).and_then(|f| f.sub);
    let help = match sub {
        Some(s) => format!("help {} {s}", c.name),
        None => format!("help {}", c.name),
    };
    // A file or name with a space typed without quotes: the quoted form.
    let text_from = super::TEXT_ARGS.iter().filter(|t| t.cmd == c.name && t.what == super::Text::Rest).find_map(|t| {
        let n = t.after.len();
        (words.len() > n && t.after.iter().zip(&words).all(|(a, w)| a.eq_ignore_ascii_case(w))).then_some(n)
    });
    if let Some(n) = text_from.filter(|&n| n < end) {
        let head: Vec<&str> = std::iter::once(c.name).chain(words[..n].iter().copied()).collect();
        // A path typed in quotes is already one word: the word after it is the extra one
        // (never folded into the file name).
        let hint = if words[n..end].iter().any(|w| w.contains(['"', '\''])) {
            crate::msg!("shell-hint-nothing-after-files", files = end - n, help = help.as_str())
        } else {
            let path = words[n..].join(" ");
            crate::msg!("shell-hint-quote-name", line = format!("{} {}", head.join(" "), lex::quote(&path)))
        };
        return Err(Error::usage(crate::msg!(
            "shell-unexpected-after",
            extra = extra,
            typed = typed.join(" "),
            forms = forms.join(" | ")
        ))
        .hint(hint)
        .column(col));
    }
    // A number and its unit typed apart (`sim step 1 s`): the one word it should be.
    let unit = !extra.is_empty() && extra.chars().all(|ch| ch.is_ascii_alphabetic()) && extra.len() <= 4;
    if let Some(num) = end.checked_sub(1).map(|i| words[i]).filter(|w| unit && w.parse::<f64>().is_ok()) {
        let fixed: Vec<String> = std::iter::once(c.name.to_string())
            .chain(words[..end - 1].iter().map(|w| w.to_string()))
            .chain(std::iter::once(format!("{num}{extra}")))
            .collect();
        return Err(Error::usage(crate::msg!(
            "shell-unexpected-after",
            extra = extra,
            typed = typed.join(" "),
            forms = forms.join(" | ")
        ))
        .hint(crate::msg!("shell-hint-number-and-unit", line = fixed.join(" ")))
        .column(col));
    }
    let message = if forms == [c.name] {
        crate::msg!("shell-no-arguments", extra = extra, command = c.name)
    } else {
        crate::msg!("shell-unexpected-after", extra = extra, typed = typed.join(" "), forms = forms.join(" | "))
    };
    Err(Error::usage(message).hint(crate::msg!("shell-hint-nothing-after", help = help.as_str())).column(col))
}

/// The forms of `c` that `text` (the words after the command's name) fits, options aside.
pub fn fitting(c: &CommandSpec, text: &str) -> Vec<String> {
    let Ok(all) = lex::words(text) else { return Vec::new() };
    let (positional, _) = lex::options(&all);
    let words: Vec<&str> = positional.iter().map(|w| w.1).collect();
    of(c)
        .iter()
        .map(|f| grammar(c, f))
        .filter(|g| reach(&g.nodes, &words, vec![0]).contains(&words.len()))
        .map(|g| g.text)
        .collect()
}

/// The option keys of a command's forms (`pto` → `freq`, `cycle`, `count`), with the value
/// each form shows (`freq=2kHz`), in the order of the forms, once each; `sub` narrows them to
/// one sub-command's forms.
pub fn options(c: &CommandSpec, sub: Option<&str>) -> Vec<(String, String)> {
    let mut out: Vec<(String, String)> = Vec::new();
    for f in of(c).iter().filter(|f| sub.is_none() || f.sub.is_none() || f.sub == sub) {
        let body = f.text.split_once(' ').map_or("", |(_, r)| r);
        for tok in tokens(body) {
            if let Tok::Option(k, v) = tok {
                if !out.iter().any(|(o, _)| *o == k) {
                    out.push((k, v));
                }
            }
        }
    }
    out
}

/// The words that stand for each other in a form (`abs|rel`: one of the two), as pairs in
/// both orders; `sub` narrows them to one sub-command's forms. Once one is typed, completion
/// offers none of the others (`servo move abs 1000 ⇥` never offers `rel`).
pub fn rivals(c: &CommandSpec, sub: Option<&str>) -> Vec<(String, String)> {
    let mut out = Vec::new();
    for f in of(c).iter().filter(|f| sub.is_none() || f.sub.is_none() || f.sub == sub) {
        let body = f.text.split_once(' ').map_or("", |(_, r)| r);
        let toks = tokens(body);
        let mut run: Vec<String> = Vec::new();
        let mut i = 0;
        while i < toks.len() {
            if let Tok::Word(w) = &toks[i] {
                run.push(w.clone());
                if matches!(toks.get(i + 1), Some(Tok::Bar)) && matches!(toks.get(i + 2), Some(Tok::Word(_))) {
                    i += 2;
                    continue;
                }
            }
            for a in &run {
                for b in run.iter().filter(|b| *b != a) {
                    out.push((a.clone(), b.clone()));
                }
            }
            run.clear();
            i += 1;
        }
    }
    out
}

/// The words a command's forms spell out (`pto` → `strict`, `status`; `servo move` → `abs`,
/// `rel`), for completion; `sub` narrows them to one sub-command's forms, whose own name is
/// left out.
pub fn literals(c: &CommandSpec, sub: Option<&str>) -> Vec<String> {
    let mut out: Vec<String> = Vec::new();
    for f in of(c).iter().filter(|f| sub.is_none() || f.sub.is_none() || f.sub == sub) {
        let body = f.text.split_once(' ').map_or("", |(_, r)| r);
        for tok in tokens(body) {
            if let Tok::Word(w) = tok {
                let plain = w.chars().all(|ch| ch.is_ascii_lowercase() || ch == '-');
                if plain && Some(w.as_str()) != sub && !out.contains(&w) {
                    out.push(w);
                }
            }
        }
    }
    out
}

/// Whether a command's forms (or one sub-command's) take operands: a placeholder `OPERAND`,
/// `RANGE` or `OBJ` (`get`, `watch`, `servo read`).
pub fn takes_operands(c: &CommandSpec, sub: Option<&str>) -> bool {
    of(c)
        .iter()
        .filter(|f| sub.is_none() || f.sub == sub)
        .any(|f| f.text.contains("OPERAND") || f.text.contains("RANGE") || f.text.contains("OBJ…"))
}

/// Every command and its forms (the registry walked once).
pub fn all() -> impl Iterator<Item = (&'static CommandSpec, Form)> {
    COMMANDS.iter().flat_map(|c| of(c).into_iter().map(move |f| (c, f)))
}

/// A line made from a form, each optional part and alternative at its fullest: placeholders
/// become `fill` words, literals themselves; `None` when the form takes any number of words
/// (nothing can follow its end).
pub fn longest_line(c: &CommandSpec, f: &Form, fill: &str) -> Option<String> {
    fn walk(nodes: &[Node], fill: &str, out: &mut Vec<String>) -> bool {
        for n in nodes {
            match n {
                Node::Lit(l) => out.push(l.clone()),
                Node::Any => out.push(fill.to_string()),
                Node::Rest => return false,
                Node::Opt(seq) => {
                    if !walk(seq, fill, out) {
                        return false;
                    }
                }
                Node::Alt(seqs) => {
                    // The longest alternative.
                    let mut best: Option<Vec<String>> = None;
                    for s in seqs {
                        let mut v = Vec::new();
                        if !walk(s, fill, &mut v) {
                            return false;
                        }
                        if best.as_ref().is_none_or(|b| v.len() > b.len()) {
                            best = Some(v);
                        }
                    }
                    out.extend(best.unwrap_or_default());
                }
            }
        }
        true
    }
    let g = grammar(c, f);
    let mut words = vec![c.name.to_string()];
    let nodes = if super::OWN_DEVICE_WORD.contains(&c.name) { &g.nodes[1..] } else { &g.nodes[..] };
    walk(nodes, fill, &mut words).then(|| words.join(" "))
}

#[cfg(test)]
mod tests {
    use super::*;

    fn line_check(line: &str) -> Result<()> {
        let (name, rest) = line.split_once(' ').unwrap_or((line, ""));
        let c = super::super::find(name).unwrap();
        check(c, Args { text: rest, offset: name.len() + 1 })
    }

    #[test]
    fn forms_of_commands_whose_sub_command_comes_later() {
        let hsc = super::super::find("hsc").unwrap();
        let f = of(hsc);
        assert_eq!(f.len(), 4, "{f:?}");
        assert_eq!(f[2], Form { sub: Some("status"), text: "hsc N status".into() });
        let events = of(super::super::find("events").unwrap());
        assert_eq!(events, vec![Form { sub: Some("keep"), text: "events [keep]".into() }]);
    }

    #[test]
    fn a_word_after_every_form_is_refused_at_its_column() {
        let e = line_check("sim step 1 s").unwrap_err();
        assert_eq!(e.column, Some(11));
        assert!(e.message.contains("sim step DURATION"), "{e}");
        for ok in ["sim step 1s", "servo move abs 100", "servo axis1 save", "sim cpu stop", "pto 0 freq=1kHz count=5"] {
            line_check(ok).unwrap_or_else(|e| panic!("{ok}: {e}"));
        }
        let e = line_check("servo save x").unwrap_err();
        assert_eq!(e.column, Some(11), "{e}");
        let e = line_check("servo sim fault no-reply x").unwrap_err();
        assert_eq!(e.column, Some(25), "{e}");
        let e = line_check("devices all=1").unwrap_err();
        assert_eq!(e.column, Some(8), "{e}");
    }

    /// The check is linear in the words of a line.
    #[test]
    fn long_lines_are_checked_in_linear_time() {
        for cmd in ["get", "set", "sim fault", "umpk monitor", "servo raw", "sim step", "hsc 0"] {
            let line = format!("{cmd} {}", "VW0 ".repeat(100_000));
            let t = std::time::Instant::now();
            let _ = line_check(line.trim());
            assert!(t.elapsed() < std::time::Duration::from_secs(10), "{cmd}: {:?}", t.elapsed());
        }
    }

    #[test]
    fn option_keys_come_from_the_forms() {
        let pto = super::super::find("pto").unwrap();
        let keys: Vec<String> = options(pto, None).into_iter().map(|k| format!("{}={}", k.0, k.1)).collect();
        assert_eq!(keys, vec!["freq=2kHz", "count=1000", "cycle=500us"]);
    }
}
