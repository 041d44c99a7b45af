//! The terminal's size, for output that must stay inside it: inline hints that would wrap
//! under the prompt are cut short, and a `watch` table taller than the screen scrolls inside
//! it instead of pushing the redraw off the top.

/// (columns, rows) of the terminal on standard output, or `None` when it is not a terminal.
pub fn size() -> Option<(usize, usize)> {
    crate::core::platform::terminal_size()
}

/// `text` cut to at most `width` characters, with `…` when something was cut.
pub fn fit(text: &str, width: usize) -> String {
    if text.chars().count() <= width {
        return text.to_string();
    }
    let mut s: String = text.chars().take(width.saturating_sub(1)).collect();
    s.push('…');
    s
}

/// `text` cut to at most `width` characters between two words, with `…` when something was
/// cut: a completion menu or hint never ends in half a word.
pub fn fit_words(text: &str, width: usize) -> String {
    if text.chars().count() <= width {
        return text.to_string();
    }
    let head: String = text.chars().take(width.saturating_sub(1)).collect();
    let at_boundary = text.chars().nth(head.chars().count()).is_some_and(char::is_whitespace);
    let kept = if at_boundary { head.as_str() } else { head.rfind(' ').map_or(head.as_str(), |i| &head[..i]) };
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
    fn fit_cuts_with_an_ellipsis() {
        assert_eq!(super::fit("abcdef", 4), "abc…");
        assert_eq!(super::fit("abc", 4), "abc");
    }
}
