//! The terminal's size, for output that must stay inside it: inline hints that would wrap
//! under the prompt are cut short, and a `watch` table taller than the screen scrolls inside
//! it instead of pushing the redraw off the top.

/// (columns, rows) of the terminal on standard output, or `None` when it is not a terminal.
pub fn size() -> Option<(usize, usize)> {
    crate::core::platform::terminal_size()
}

/// The columns `text` takes on a terminal: a Chinese character takes two (UAX #11, East
/// Asian Wide), a combining mark none. Everything that fits text to the terminal measures
/// with it, never with a count of characters.
pub fn width(text: &str) -> usize {
    unicode_width::UnicodeWidthStr::width(text)
}

/// The longest head of `text` that takes at most `cols` columns (a byte offset).
fn head_within(text: &str, cols: usize) -> usize {
    let mut used = 0;
    for (i, c) in text.char_indices() {
        let w = unicode_width::UnicodeWidthChar::width(c).unwrap_or(0);
        if used + w > cols {
            return i;
        }
        used += w;
    }
    text.len()
}

/// `text` cut to at most `width` columns, with `…` when something was cut.
pub fn fit(text: &str, width: usize) -> String {
    if self::width(text) <= width {
        return text.to_string();
    }
    format!("{}…", &text[..head_within(text, width.saturating_sub(1))])
}

/// `text` cut to at most `width` columns between two words, with `…` when something was
/// cut: a completion menu or hint never ends in half a word (Chinese, written without
/// spaces, is cut between characters when a phrase has no space to cut at).
pub fn fit_words(text: &str, width: usize) -> String {
    if self::width(text) <= width {
        return text.to_string();
    }
    let end = head_within(text, width.saturating_sub(1));
    let head = &text[..end];
    let at_boundary = text[end..].chars().next().is_some_and(char::is_whitespace);
    let kept = if at_boundary { head } else { head.rfind(' ').map_or(head, |i| &head[..i]) };
    format!("{}…", kept.trim_end())
}

#[cfg(test)]
mod tests {
    #[test]
    fn fit_words_cuts_between_words() {
        assert_eq!(super::fit_words("PTO0 control byte", 12), "PTO0…");
        assert_eq!(super::fit_words("PTO0 control byte", 14), "PTO0 control…");
        assert_eq!(super::fit_words("PTO0 control", 40), "PTO0 control");
        assert_eq!(super::fit_words("abcdefgh", 4), "abc…", "one long word is cut where it must be");
    }

    #[test]
    fn chinese_text_is_fitted_by_its_columns() {
        // Each Chinese character takes two columns: 10 columns hold four and the ellipsis.
        let t = "变量存储器的当前值";
        assert_eq!(super::width(t), 18);
        let cut = super::fit(t, 10);
        assert_eq!(cut, "变量存储…");
        assert!(super::width(&cut) <= 10);
        let line = "VW0 变量存储器 (当前值) 模拟量输入";
        for cols in 5..super::width(line) {
            let f = super::fit_words(line, cols);
            assert!(super::width(&f) <= cols, "{cols}: {f}");
        }
        assert_eq!(super::fit_words(line, 22), "VW0 变量存储器…");
    }

    #[test]
    fn fit_cuts_with_an_ellipsis() {
        assert_eq!(super::fit("abcdef", 4), "abc…");
        assert_eq!(super::fit("abc", 4), "abc");
    }
}
