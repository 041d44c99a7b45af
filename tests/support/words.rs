//! Splitting a documented command line into words, as a POSIX shell and PowerShell both do for
//! the lines the guide shows: spaces separate words, double quotes group them. Shared by the
//! tests that run the guide's command lines (`tests/fx.rs`, `tests/windows_serial.rs`).

/// The words of `line`.
pub fn split(line: &str) -> Vec<String> {
    let (mut words, mut cur, mut quoted) = (Vec::new(), String::new(), false);
    for c in line.chars() {
        match c {
            '"' => quoted = !quoted,
            ' ' if !quoted => {
                if !cur.is_empty() {
                    words.push(std::mem::take(&mut cur));
                }
            }
            c => cur.push(c),
        }
    }
    if !cur.is_empty() {
        words.push(cur);
    }
    words
}
