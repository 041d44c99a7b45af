//! A progress indicator for long operations (waits with a timeout, `trace`, an E2PROM
//! restore, scripts that opt in): one self-overwriting line on stderr when stderr is a
//! terminal, nothing at all on a pipe, so piped output and JSON stay clean.
//!
//! ```no_run
//! use plcsh::shell::progress::Progress;
//! use std::time::Duration;
//! let mut p = Progress::new("trace", Some(Duration::from_secs(2)));
//! p.update(Duration::from_millis(500), "51 samples");
//! p.finish();
//! ```

use std::io::Write;
use std::time::{Duration, Instant};

/// A progress line; drawn at most every 100 ms.
pub struct Progress {
    label: String,
    total: Option<Duration>,
    enabled: bool,
    last: Option<Instant>,
    drawn: bool,
}

impl Progress {
    /// Shown only when stderr is a terminal.
    pub fn new(label: &str, total: Option<Duration>) -> Progress {
        Progress::with(label, total, crate::core::platform::escapes(crate::core::platform::Stream::Stderr))
    }

    /// A progress that is shown (or not) regardless of the terminal.
    pub fn with(label: &str, total: Option<Duration>, enabled: bool) -> Progress {
        Progress { label: label.to_string(), total, enabled, last: None, drawn: false }
    }

    pub fn enabled(&self) -> bool {
        self.enabled
    }

    /// Reports `done` of the total (or elapsed time when there is no total), with a note.
    pub fn update(&mut self, done: Duration, note: &str) {
        if !self.enabled || self.last.is_some_and(|l| l.elapsed() < Duration::from_millis(100)) {
            return;
        }
        self.last = Some(Instant::now());
        self.drawn = true;
        let line = line(&self.label, done, self.total, note);
        let mut e = std::io::stderr().lock();
        let _ = write!(e, "\r{line}\x1b[K");
        let _ = e.flush();
    }

    /// Clears the line.
    pub fn finish(&mut self) {
        if self.drawn {
            let mut e = std::io::stderr().lock();
            let _ = write!(e, "\r\x1b[K");
            let _ = e.flush();
            self.drawn = false;
        }
    }
}

impl Drop for Progress {
    fn drop(&mut self) {
        self.finish();
    }
}

/// The text of a progress line: `trace [██████░░░░░░░░░░░░░░] 30% 0.6s/2.0s 61 samples`.
pub fn line(label: &str, done: Duration, total: Option<Duration>, note: &str) -> String {
    match total {
        Some(t) if !t.is_zero() => {
            let f = (done.as_secs_f64() / t.as_secs_f64()).clamp(0.0, 1.0);
            format!(
                "{label} {} {:>3.0}% {:.1}s/{:.1}s {note}",
                bar(f, 20),
                f * 100.0,
                done.as_secs_f64(),
                t.as_secs_f64()
            )
        }
        _ => format!("{label} {:.1}s {note}", done.as_secs_f64()),
    }
}

/// A bar of `width` cells, `fraction` of them full.
pub fn bar(fraction: f64, width: usize) -> String {
    let full = ((fraction.clamp(0.0, 1.0) * width as f64).round() as usize).min(width);
    format!("[{}{}]", "█".repeat(full), "░".repeat(width - full))
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn bar_and_line() {
        assert_eq!(bar(0.0, 4), "[░░░░]");
        assert_eq!(bar(0.5, 4), "[██░░]");
        assert_eq!(bar(2.0, 4), "[████]");
        let l = line("trace", Duration::from_millis(600), Some(Duration::from_secs(2)), "61 samples");
        assert_eq!(l, "trace [██████░░░░░░░░░░░░░░]  30% 0.6s/2.0s 61 samples");
        assert_eq!(line("wait", Duration::from_millis(1500), None, ""), "wait 1.5s ");
    }

    #[test]
    fn a_hidden_progress_draws_nothing() {
        let mut p = Progress::with("x", None, false);
        p.update(Duration::from_secs(1), "");
        assert!(!p.drawn && !p.enabled());
    }
}
