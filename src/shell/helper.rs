//! The rustyline glue: completion, inline hints (the operand's meaning, the rest of a unique
//! name, the command's usage, a history continuation) and dimmed hint text. The logic is in
//! `complete.rs`; this file only adapts it to rustyline's traits.
//!
//! The helper holds the session while the editor reads a line (the REPL moves it in before
//! `readline` and takes it back after), so completion sees the devices as they are now,
//! without shared ownership or locks in the rest of the shell.

use super::complete::{self, DeviceView, ProfileView, View};
use crate::session::Session;
use rustyline::completion::{Completer, Pair};
use rustyline::highlight::Highlighter;
use rustyline::hint::{Hinter, HistoryHinter};
use rustyline::validate::Validator;
use rustyline::{Context, Helper};
use std::borrow::Cow;

/// The completion view of a session.
pub fn view_of<'a>(session: &'a Session, files: &'a dyn Fn(&str) -> Vec<String>) -> View<'a> {
    let current = session.current_name().and_then(|n| session.index(n).ok());
    View {
        devices: session
            .entries()
            .iter()
            .map(|e| DeviceView {
                name: &e.name,
                family: e.device.info().family,
                model: &e.device.info().model,
                space: e.device.operands(),
                names: (!e.names.is_empty()).then_some(&*e.names),
            })
            .collect(),
        current,
        profiles: session.profiles.list().iter().map(|p| ProfileView { name: &p.name, url: &p.url }).collect(),
        files,
    }
}

/// The REPL's rustyline helper.
pub struct ShellHelper {
    /// The session, lent to the helper while a line is read.
    pub session: Option<Session>,
    history: HistoryHinter,
    /// Dim hints (a terminal without NO_COLOR).
    pub color: bool,
    /// Width of the prompt the line is read after (hints are cut to fit the terminal).
    pub prompt_width: usize,
}

impl ShellHelper {
    pub fn new(color: bool) -> ShellHelper {
        ShellHelper { session: None, history: HistoryHinter::new(), color, prompt_width: 6 }
    }
}

/// A hint: `display` is shown after the cursor, `insert` is what → accepts.
pub struct ShellHint {
    display: String,
    insert: Option<String>,
}

impl rustyline::hint::Hint for ShellHint {
    fn display(&self) -> &str {
        &self.display
    }
    fn completion(&self) -> Option<&str> {
        self.insert.as_deref()
    }
}

impl Completer for ShellHelper {
    type Candidate = Pair;

    fn complete(&self, line: &str, pos: usize, _ctx: &Context<'_>) -> rustyline::Result<(usize, Vec<Pair>)> {
        let Some(s) = &self.session else { return Ok((pos, Vec::new())) };
        let c = complete::complete(line, pos, &view_of(s, &complete::list_paths));
        let width = c.items.iter().map(|s| super::term::width(&s.text)).max().unwrap_or(0);
        // rustyline lists candidates in columns two apart: a candidate with its meaning is
        // cut between words to fit the terminal (80 columns when its size is unknown).
        let cols = super::term::size().map_or(80, |(c, _)| c).max(20);
        let pairs = c
            .items
            .into_iter()
            .map(|s| Pair { display: menu_line(&s.text, &s.meaning, width, cols), replacement: s.text })
            .collect();
        Ok((c.start, pairs))
    }
}

/// One candidate as the completion menu shows it: the text, padded to `width`, then its
/// meaning, cut between words so the line fits `cols` columns with the menu's gap.
pub fn menu_line(text: &str, meaning: &str, width: usize, cols: usize) -> String {
    if meaning.is_empty() {
        return text.to_string();
    }
    let room = cols.saturating_sub(2);
    let w = super::term::width(text);
    if w + 4 > room {
        return text.to_string();
    }
    let pad = " ".repeat(width.saturating_sub(w));
    super::term::fit_words(&format!("{text}{pad}  {meaning}"), room)
}

impl Hinter for ShellHelper {
    type Hint = ShellHint;

    fn hint(&self, line: &str, pos: usize, ctx: &Context<'_>) -> Option<ShellHint> {
        let pure = self.session.as_ref().and_then(|s| complete::hint(line, pos, &view_of(s, &complete::list_paths)));
        let history = self.history.hint(line, pos, ctx).filter(|h| !h.is_empty());
        let hint = match (history, pure) {
            (Some(h), p) => {
                let note = p.map(|p| p.note).unwrap_or_default();
                Some(ShellHint { display: format!("{h}{note}"), insert: Some(h) })
            }
            (None, Some(p)) => Some(ShellHint {
                display: format!("{}{}", p.insert.clone().unwrap_or_default(), p.note),
                insert: p.insert,
            }),
            (None, None) => None,
        }?;
        // A hint longer than the rest of the terminal line would wrap under the prompt: cut it.
        let Some((cols, _)) = super::term::size() else { return Some(hint) };
        let room = cols.saturating_sub(self.prompt_width + super::term::width(line) + 1);
        Some(ShellHint { display: super::term::fit_words(&hint.display, room), insert: hint.insert })
    }
}

impl Highlighter for ShellHelper {
    fn highlight_hint<'h>(&self, hint: &'h str) -> Cow<'h, str> {
        if self.color {
            Cow::Owned(format!("\x1b[2m{hint}\x1b[0m"))
        } else {
            Cow::Borrowed(hint)
        }
    }
}

impl Validator for ShellHelper {}
impl Helper for ShellHelper {}

#[cfg(test)]
mod menu_tests {
    /// Every command's menu line fits 80 columns with the menu's gap and ends between words.
    #[test]
    fn menu_lines_fit_and_end_between_words() {
        let width = 7;
        for c in crate::shell::commands::COMMANDS {
            let summary = c.summary();
            let line = super::menu_line(c.name, &summary, width, 80);
            assert!(line.chars().count() <= 78, "{line}");
            let shown = line.trim_end_matches('…')[width + 2..].to_string();
            assert!(summary.starts_with(&shown), "{line}");
            let after = &summary[shown.len()..];
            assert!(after.is_empty() || after.starts_with([' ', ',', ';', ':']), "`{line}` cuts a word");
        }
        assert_eq!(super::menu_line("VW0", "", 5, 80), "VW0");
    }
}

#[cfg(test)]
mod session_tests {
    use super::*;
    use crate::core::Clock;

    /// The completer on the default session's real devices (the K2 simulator and the
    /// servo drive with its object dictionary), as the REPL builds it.
    #[test]
    fn completes_the_real_servo_objects_and_sm_registers() {
        let mut s = Session::new(Clock::stepped());
        s.open("plc", "sim:K205-16DT").unwrap();
        s.open("servo", "sim-servo:?id=1").unwrap();
        s.use_device("plc").unwrap();
        let no_files = |_: &str| Vec::new();
        let view = view_of(&s, &no_files);
        let c = crate::shell::complete::complete("get servo:targ", 14, &view);
        let texts: Vec<&str> = c.items.iter().map(|i| i.text.as_str()).collect();
        assert!(texts.contains(&"servo:target_position") && texts.contains(&"servo:target_velocity"), "{texts:?}");
        let c = crate::shell::complete::complete("set SMB6", 8, &view);
        assert!(c.items.iter().any(|i| i.text == "SMB67" && i.meaning.contains("control byte")));
    }
}
