//! Small text helpers for messages: the "did you mean" suggestions every family's errors
//! and the shell's unknown-command message make, and word wrapping for help text.

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

/// Breaks `text` into lines of at most `width` characters at spaces (a word longer than the
/// width gets a line of its own). Used to keep help and hints inside an 80-column terminal.
pub fn wrap(text: &str, width: usize) -> Vec<String> {
    let mut lines = vec![String::new()];
    for word in text.split_whitespace() {
        let cur = lines.last_mut().expect("one line");
        let len = cur.chars().count();
        if len > 0 && len + 1 + word.chars().count() > width {
            lines.push(word.to_string());
        } else {
            if len > 0 {
                cur.push(' ');
            }
            cur.push_str(word);
        }
    }
    lines
}

#[cfg(test)]
mod tests {
    use super::*;

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
}
