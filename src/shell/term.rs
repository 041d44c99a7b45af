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

#[cfg(test)]
mod tests {
    #[test]
    fn fit_cuts_with_an_ellipsis() {
        assert_eq!(super::fit("abcdef", 4), "abc…");
        assert_eq!(super::fit("abc", 4), "abc");
    }
}
