//! The terminal's size, for output that must stay inside it: inline hints that would wrap
//! under the prompt are cut short, and a `watch` table taller than the screen scrolls inside
//! it instead of pushing the redraw off the top.

/// (columns, rows) of the terminal on standard output, or `None` when it is not a terminal.
pub fn size() -> Option<(usize, usize)> {
    // SAFETY: TIOCGWINSZ fills a `winsize` we own; a failing call leaves it zeroed.
    let mut ws: libc::winsize = unsafe { std::mem::zeroed() };
    let r = unsafe { libc::ioctl(libc::STDOUT_FILENO, libc::TIOCGWINSZ, &mut ws) };
    (r == 0 && ws.ws_col > 0 && ws.ws_row > 0).then_some((usize::from(ws.ws_col), usize::from(ws.ws_row)))
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
