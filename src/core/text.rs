//! Small text helpers for messages and typed lines: the "did you mean" suggestions every
//! family's errors and the shell's unknown-command message make, word wrapping for help text,
//! the shell language's quoting rules ([`Quotes`]) and the K2 manual's spelling of operands
//! ([`fold_manual_spelling`]).

/// Levenshtein distance between two strings (by characters).
pub fn edit_distance(a: &str, b: &str) -> usize {
    let b: Vec<char> = b.chars().collect();
    let mut prev: Vec<usize> = (0..=b.len()).collect();
    for (i, ca) in a.chars().enumerate() {
        let mut cur = vec![i + 1];
        for (j, cb) in b.iter().enumerate() {
            cur.push((prev[j] + usize::from(ca != *cb)).min(prev[j + 1] + 1).min(cur[j] + 1));
        }
        prev = cur;
    }
    prev[b.len()]
}

/// Breaks `text` into lines of at most `width` terminal columns at spaces (a word longer than
/// the width gets a line of its own). Chinese text, written without spaces, may also break
/// between two of its characters (each two columns wide), never before a closing punctuation
/// mark (`，`, `。`, `）` …). Used to keep help and hints inside an 80-column terminal.
pub fn wrap(text: &str, width: usize) -> Vec<String> {
    use unicode_width::UnicodeWidthStr;
    let mut lines = vec![String::new()];
    for word in code_spans(text) {
        for (i, piece) in pieces(&word).into_iter().enumerate() {
            let cur = lines.last_mut().expect("one line");
            let len = cur.width();
            let gap = usize::from(i == 0 && len > 0);
            if len > 0 && len + gap + piece.width() > width {
                lines.push(piece.to_string());
            } else {
                if gap == 1 {
                    cur.push(' ');
                }
                cur.push_str(piece);
            }
        }
    }
    lines
}

/// The words of `text`, with a `code span` of several words kept as one (never broken).
fn code_spans(text: &str) -> Vec<String> {
    let mut out: Vec<String> = Vec::new();
    let mut open = false;
    for word in text.split_whitespace() {
        match out.last_mut() {
            Some(last) if open => {
                last.push(' ');
                last.push_str(word);
            }
            _ => out.push(word.to_string()),
        }
        if word.matches('`').count() % 2 == 1 {
            open = !open;
        }
    }
    out
}

/// The pieces a line may break between inside one word: each wide (Chinese) character with the
/// closing punctuation after it, and each run of other characters.
fn pieces(word: &str) -> Vec<&str> {
    use unicode_width::UnicodeWidthChar;
    const CLOSING: &[char] = &['，', '。', '、', '；', '：', '）', '」', '』', '！', '？', ')', ',', '.', ';', ':'];
    let mut out = Vec::new();
    let mut start = 0;
    let mut prev_wide = false;
    for (at, c) in word.char_indices() {
        let wide = c.width() == Some(2) && !CLOSING.contains(&c);
        // A break before a wide character, and after one unless punctuation closes it.
        if at > start && (wide || prev_wide && !CLOSING.contains(&c)) {
            out.push(&word[start..at]);
            start = at;
        }
        prev_wide = wide || (prev_wide && CLOSING.contains(&c));
    }
    out.push(&word[start..]);
    out
}

/// Cyrillic letters that look like the Latin ones operands and literals use. Text copied from
/// the K2 manual's machine-extracted Russian edition, or typed on a Russian layout, carries them
/// (`В#16#85`, `ВW0` with a Cyrillic В); the same edition writes operands with a space after
/// `%` (§3.4.3's PHOME example: `PHOME 0, % M0.0, … % VW2, % VW4, % VD6`).
const LOOK_ALIKES: &[(char, char)] = &[
    ('А', 'A'),
    ('а', 'a'),
    ('С', 'C'),
    ('с', 'c'),
    ('Е', 'E'),
    ('е', 'e'),
    ('К', 'K'),
    ('к', 'k'),
    ('М', 'M'),
    ('м', 'm'),
    ('О', 'O'),
    ('о', 'o'),
    ('Р', 'P'),
    ('р', 'p'),
    ('Т', 'T'),
    ('т', 't'),
    ('Х', 'X'),
    ('х', 'x'),
    ('І', 'I'),
    ('і', 'i'),
    ('Н', 'H'),
];

/// What one character of a typed line is, under the shell language's quoting rules
/// (docs/commands.md, "Quoting").
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Role {
    /// Outside quotes: separators, brackets, `#` comments and operands are read here.
    Bare,
    /// The quote that opens quoted text (`"` or `'`).
    Open,
    /// The quote that closes it.
    Close,
    /// A backslash that makes the next character literal inside double quotes (`\"`, `\\`).
    Escape,
    /// A character of quoted text, taken as it is.
    Quoted,
}

/// The shell language's quoting, one character at a time: `"…"` and `'…'` hold spaces, `;`,
/// `,`, `#` and brackets as text. Inside double quotes `\"` is a quote and `\\` a backslash;
/// every other backslash is itself, so `"C:\Users\Иванов\лаб 1"` is that path. Inside single
/// quotes every character is itself. Outside quotes a backslash is an ordinary character.
/// One pass, constant work per character.
#[derive(Clone, Copy, Debug, Default)]
pub struct Quotes {
    /// The open quote and its byte position, while inside quotes.
    pub open: Option<(usize, char)>,
    escaped: bool,
}

impl Quotes {
    /// The role of character `c` at byte `at`, given the character after it; moves the state on.
    pub fn feed(&mut self, at: usize, c: char, next: Option<char>) -> Role {
        match self.open {
            None if c == '"' || c == '\'' => {
                self.open = Some((at, c));
                Role::Open
            }
            None => Role::Bare,
            Some(_) if self.escaped => {
                self.escaped = false;
                Role::Quoted
            }
            Some((_, q)) if c == q => {
                self.open = None;
                Role::Close
            }
            Some((_, '"')) if c == '\\' && matches!(next, Some('"' | '\\')) => {
                self.escaped = true;
                Role::Escape
            }
            Some(_) => Role::Quoted,
        }
    }

    /// Every character of `s` with its byte position and role.
    pub fn roles(s: &str) -> impl Iterator<Item = (usize, char, Role)> + '_ {
        let mut q = Quotes::default();
        let mut it = s.char_indices().peekable();
        std::iter::from_fn(move || {
            let (i, c) = it.next()?;
            let next = it.peek().map(|p| p.1);
            Some((i, c, q.feed(i, c, next)))
        })
    }
}

/// Reads operands and values as the K2 manual spells them: Cyrillic look-alikes become Latin
/// letters (`В` is `B` before `#` or after a letter — `В#16#85`, `VВ0` — and `V` where an area
/// starts, as the Russian text transliterates V), and `% VW2` becomes `%VW2`. Quoted text is
/// left alone. Returns the new text and the words that changed (`ВW0` → `VW0`), or `None` when
/// nothing did.
///
/// Only for operand words: the shell calls it on the words a command's grammar reads as
/// operands and values, never on file paths, names, messages or Lua code (the command
/// registry's `TEXT_ARGS` says which words those are), so `Проверка/светофор.il` stays as typed.
pub fn fold_manual_spelling(line: &str) -> Option<(String, Vec<(String, String)>)> {
    if line.is_ascii() && !line.contains('%') {
        return None;
    }
    let chars: Vec<(char, Role)> = Quotes::roles(line).map(|(_, c, r)| (c, r)).collect();
    let bare = |k: usize| chars.get(k).filter(|x| x.1 == Role::Bare).map(|x| x.0);
    let mut out = String::with_capacity(line.len());
    let mut i = 0;
    while i < chars.len() {
        let (c, role) = chars[i];
        if role != Role::Bare {
            out.push(c);
            i += 1;
            continue;
        }
        match c {
            '%' if bare(i + 1).is_some_and(char::is_whitespace) => {
                out.push('%');
                while bare(i + 1).is_some_and(char::is_whitespace) {
                    i += 1;
                }
            }
            'В' | 'в' => {
                let next_hash = bare(i + 1).is_some_and(|n| n == '#' || n.is_whitespace() && bare(i + 2) == Some('#'));
                let after_letter = i > 0 && chars[i - 1].0.is_ascii_alphabetic();
                let latin = if next_hash || after_letter { 'B' } else { 'V' };
                out.push(if c == 'в' { latin.to_ascii_lowercase() } else { latin });
            }
            _ => out.push(LOOK_ALIKES.iter().find(|(k, _)| *k == c).map_or(c, |(_, l)| *l)),
        }
        i += 1;
    }
    if out == line {
        return None;
    }
    let before: Vec<&str> = line.split_whitespace().collect();
    let after: Vec<&str> = out.split_whitespace().collect();
    let changed = if before.len() == after.len() {
        before.iter().zip(&after).filter(|(a, b)| a != b).map(|(a, b)| (a.to_string(), b.to_string())).collect()
    } else {
        vec![(line.trim().to_string(), out.trim().to_string())]
    };
    Some((out, changed))
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_manuals_cyrillic_spelling_reads_as_latin() {
        // The K2 manual (Russian text) prints `В#16#85` with a Cyrillic В, and `% VW2` with a space.
        let (line, changed) = fold_manual_spelling("set SMB67=В#16#85").unwrap();
        assert_eq!(line, "set SMB67=B#16#85");
        assert_eq!(changed, vec![("SMB67=В#16#85".to_string(), "SMB67=B#16#85".to_string())]);
        assert_eq!(fold_manual_spelling("get ВW0").unwrap().0, "get VW0");
        assert_eq!(fold_manual_spelling("get VВ0 СD0 МW0 Т5").unwrap().0, "get VB0 CD0 MW0 T5");
        assert_eq!(fold_manual_spelling("get % VW2").unwrap().0, "get %VW2");
        assert!(fold_manual_spelling("get VW0").is_none());
        assert_eq!(fold_manual_spelling("connect \"ВW0\"").as_ref().map(|f| f.0.as_str()), None);
        // Quoted text is text, whichever quotes hold it.
        assert_eq!(fold_manual_spelling("'ВW0' ВW0").unwrap().0, "'ВW0' VW0");
        assert_eq!(fold_manual_spelling(r#""a \" ВW0" ВW0"#).unwrap().0, r#""a \" ВW0" VW0"#);
    }

    #[test]
    fn quotes_follow_the_documented_rules() {
        let roles = |s: &str| Quotes::roles(s).map(|(_, _, r)| r).collect::<Vec<_>>();
        use Role::*;
        assert_eq!(roles(r#"a"b""#), [Bare, Open, Quoted, Close]);
        assert_eq!(roles(r#""\"x""#), [Open, Escape, Quoted, Quoted, Close]);
        assert_eq!(roles(r#""\\""#), [Open, Escape, Quoted, Close]);
        // Any other backslash is itself: a Windows path inside double quotes.
        assert_eq!(roles(r#""\U""#), [Open, Quoted, Quoted, Close]);
        // Inside single quotes, and outside quotes, nothing escapes.
        assert_eq!(roles(r#"'\'"#), [Open, Quoted, Close]);
        assert_eq!(roles(r#"\'x'"#), [Bare, Open, Quoted, Close]);
        assert_eq!(roles(r#"'"'"#), [Open, Quoted, Close]);
        let mut q = Quotes::default();
        for (i, c) in "'x".char_indices() {
            q.feed(i, c, None);
        }
        assert_eq!(q.open, Some((0, '\'')));
    }

    #[test]
    fn wrapping_keeps_words_whole() {
        assert_eq!(wrap("read a range as a table", 10), vec!["read a", "range as a", "table"]);
        assert_eq!(wrap("", 10), vec![""]);
    }

    #[test]
    fn distances() {
        assert_eq!(edit_distance("VX", "VW"), 1);
        assert_eq!(edit_distance("", "SM"), 2);
        assert_eq!(edit_distance("controlwrod", "controlword"), 2);
    }

    #[test]
    fn wrap_counts_columns_and_breaks_chinese_between_characters() {
        assert_eq!(wrap("read a range as a table", 12), vec!["read a range", "as a table"]);
        // Two columns a character: 10 columns hold five; the comma stays with its character.
        let lines = wrap("读取操作数，可用范围和前缀", 10);
        assert_eq!(lines, vec!["读取操作", "数，可用范", "围和前缀"]);
        for l in wrap("Kinco 伺服工具：DS402 状态机、运动、点动、回原点、等待、单位、原始报文", 20)
        {
            assert!(unicode_width::UnicodeWidthStr::width(l.as_str()) <= 20, "{l}");
            assert!(!l.starts_with(['，', '、', '：']), "{l}");
        }
        assert_eq!(wrap("运动、点动", 6), vec!["运动、", "点动"], "a break between characters adds no space");
        assert_eq!(wrap("运动 点动", 20), vec!["运动 点动"], "a space written stays");
        assert_eq!(
            wrap("Tab completes (`pto 0 fr` ⇥ `freq=`).", 20),
            vec!["Tab completes", "(`pto 0 fr` ⇥", "`freq=`)."]
        );
    }
}
