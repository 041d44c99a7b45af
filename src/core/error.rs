//! The one error type that reaches users. Every message names the device, the operand
//! and what to try; the `kind` separates "the device refused" (a Modbus exception, a servo
//! 0x80 abort) from "the link failed" (timeout, checksum), because a user acts differently
//! on each. The JSON output carries `kind` and `code` so pipelines can branch on them:
//! `code` is the message id of the catalogue (`core::msg`) the text came from, e.g.
//! `value-out-of-range`; a message not yet in the catalogue has the code `kind-KIND`
//! (`kind-usage`), which names no more than its kind.

use super::msg::Msg;
use serde::Serialize;
use std::fmt;

/// What went wrong, in categories a user acts on.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Serialize)]
#[serde(rename_all = "snake_case")]
pub enum ErrorKind {
    /// The command line does not parse.
    Syntax,
    /// The operand is unknown or malformed.
    Operand,
    /// The value does not fit the operand.
    Value,
    /// The operand is past the end of the model's area.
    Range,
    /// The operand or command exists but this device or link cannot do it.
    Unsupported,
    /// The device answered with a refusal (Modbus exception, servo abort code, helper result).
    Refused,
    /// The link failed: no answer, timeout, bad checksum, dropped connection.
    Link,
    /// A wait ran out of time.
    Timeout,
    /// A command was used wrongly (missing argument, unknown command, unknown device).
    Usage,
    /// A Lua script failed.
    Script,
    /// A file or the operating system failed.
    Io,
    /// The operation was interrupted (Ctrl-C).
    Interrupted,
    /// The device is in a state where the command cannot run (e.g. a PTO busy).
    State,
}

impl ErrorKind {
    /// Every kind, in the order of the enum (the guide's error catalogue lists them so).
    pub const ALL: &'static [ErrorKind] = &[
        ErrorKind::Syntax,
        ErrorKind::Operand,
        ErrorKind::Value,
        ErrorKind::Range,
        ErrorKind::Unsupported,
        ErrorKind::Refused,
        ErrorKind::Link,
        ErrorKind::Timeout,
        ErrorKind::Usage,
        ErrorKind::Script,
        ErrorKind::Io,
        ErrorKind::Interrupted,
        ErrorKind::State,
    ];

    pub fn name(self) -> &'static str {
        match self {
            ErrorKind::Syntax => "syntax",
            ErrorKind::Operand => "operand",
            ErrorKind::Value => "value",
            ErrorKind::Range => "range",
            ErrorKind::Unsupported => "unsupported",
            ErrorKind::Refused => "refused",
            ErrorKind::Link => "link",
            ErrorKind::Timeout => "timeout",
            ErrorKind::Usage => "usage",
            ErrorKind::Script => "script",
            ErrorKind::Io => "io",
            ErrorKind::Interrupted => "interrupted",
            ErrorKind::State => "state",
        }
    }

    /// The code of an error whose message has no id in the catalogue yet: `kind-usage` …
    pub fn default_code(self) -> &'static str {
        match self {
            ErrorKind::Syntax => "kind-syntax",
            ErrorKind::Operand => "kind-operand",
            ErrorKind::Value => "kind-value",
            ErrorKind::Range => "kind-range",
            ErrorKind::Unsupported => "kind-unsupported",
            ErrorKind::Refused => "kind-refused",
            ErrorKind::Link => "kind-link",
            ErrorKind::Timeout => "kind-timeout",
            ErrorKind::Usage => "kind-usage",
            ErrorKind::Script => "kind-script",
            ErrorKind::Io => "kind-io",
            ErrorKind::Interrupted => "kind-interrupted",
            ErrorKind::State => "kind-state",
        }
    }
}

/// The text an error is made from: a catalogue message ([`Msg`], which brings its id as the
/// error's code) or plain text (code `kind-KIND`).
pub struct Text {
    code: Option<&'static str>,
    text: String,
}

impl From<Msg> for Text {
    fn from(m: Msg) -> Text {
        Text { code: Some(m.id), text: m.text }
    }
}
impl From<String> for Text {
    fn from(text: String) -> Text {
        Text { code: None, text }
    }
}
impl From<&String> for Text {
    fn from(text: &String) -> Text {
        Text { code: None, text: text.clone() }
    }
}
impl From<&str> for Text {
    fn from(text: &str) -> Text {
        Text { code: None, text: text.to_string() }
    }
}
impl From<std::borrow::Cow<'_, str>> for Text {
    fn from(text: std::borrow::Cow<'_, str>) -> Text {
        Text { code: None, text: text.into_owned() }
    }
}

/// An error with the context a user needs to act on it. Boxed, so `Result`s stay small
/// on the hot path (a read that succeeds costs no more than its value).
#[derive(Clone, Debug, PartialEq, Serialize)]
#[serde(transparent)]
pub struct Error {
    inner: Box<Details>,
}

/// The fields of an [`Error`] (reachable through `Deref`: `e.kind`, `e.message` …).
#[derive(Clone, Debug, PartialEq, Serialize)]
pub struct Details {
    pub kind: ErrorKind,
    /// The message id (`value-out-of-range`), or `kind-KIND` for a text not in the catalogue.
    pub code: &'static str,
    pub message: String,
    #[serde(skip_serializing_if = "Option::is_none")]
    pub device: Option<String>,
    #[serde(skip_serializing_if = "Option::is_none")]
    pub operand: Option<String>,
    /// What to try next.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub hint: Option<String>,
    /// 0-based column in the command line, where the error came from parsing.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub column: Option<usize>,
    /// Lower-level causes, outermost first (e.g. the I/O error under a link error).
    #[serde(skip_serializing_if = "Vec::is_empty")]
    pub causes: Vec<String>,
}

pub type Result<T, E = Error> = std::result::Result<T, E>;

impl std::ops::Deref for Error {
    type Target = Details;
    fn deref(&self) -> &Details {
        &self.inner
    }
}

impl std::ops::DerefMut for Error {
    fn deref_mut(&mut self) -> &mut Details {
        &mut self.inner
    }
}

impl Error {
    pub fn new(kind: ErrorKind, message: impl Into<Text>) -> Error {
        let Text { code, text } = message.into();
        Error {
            inner: Box::new(Details {
                kind,
                code: code.unwrap_or(kind.default_code()),
                message: text,
                device: None,
                operand: None,
                hint: None,
                column: None,
                causes: Vec::new(),
            }),
        }
    }
    pub fn device(mut self, d: impl Into<String>) -> Error {
        if self.device.is_none() {
            self.device = Some(d.into());
        }
        self
    }
    pub fn operand(mut self, o: impl Into<String>) -> Error {
        if self.operand.is_none() {
            self.operand = Some(o.into());
        }
        self
    }
    pub fn hint(mut self, h: impl Into<String>) -> Error {
        self.hint = Some(h.into());
        self
    }
    pub fn column(mut self, c: usize) -> Error {
        self.column = Some(c);
        self
    }
    /// Shifts the column by `offset` (when a sub-parser's error is placed in a longer line).
    pub fn shift(mut self, offset: usize) -> Error {
        if let Some(c) = self.column.as_mut() {
            *c += offset;
        }
        self
    }
    pub fn cause(mut self, c: impl fmt::Display) -> Error {
        self.causes.push(c.to_string());
        self
    }

    pub fn usage(m: impl Into<Text>) -> Error {
        Error::new(ErrorKind::Usage, m)
    }
    pub fn syntax(m: impl Into<Text>) -> Error {
        Error::new(ErrorKind::Syntax, m)
    }
    pub fn io(m: impl Into<Text>) -> Error {
        Error::new(ErrorKind::Io, m)
    }
    pub fn link(m: impl Into<Text>) -> Error {
        Error::new(ErrorKind::Link, m)
    }
    pub fn unsupported(m: impl Into<Text>) -> Error {
        Error::new(ErrorKind::Unsupported, m)
    }
    pub fn state(m: impl Into<Text>) -> Error {
        Error::new(ErrorKind::State, m)
    }
}

impl fmt::Display for Error {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        if let Some(d) = &self.device {
            write!(f, "{d}: ")?;
        }
        if let Some(o) = &self.operand {
            if !self.message.contains(o.as_str()) {
                write!(f, "{o}: ")?;
            }
        }
        f.write_str(&self.message)?;
        for c in &self.causes {
            write!(f, ": {c}")?;
        }
        if let Some(h) = &self.hint {
            write!(f, " — {h}")?;
        }
        Ok(())
    }
}

impl std::error::Error for Error {}

impl From<std::io::Error> for Error {
    fn from(e: std::io::Error) -> Error {
        let kind = match e.kind() {
            std::io::ErrorKind::TimedOut => ErrorKind::Link,
            std::io::ErrorKind::ConnectionRefused
            | std::io::ErrorKind::ConnectionReset
            | std::io::ErrorKind::ConnectionAborted
            | std::io::ErrorKind::BrokenPipe
            | std::io::ErrorKind::UnexpectedEof => ErrorKind::Link,
            _ => ErrorKind::Io,
        };
        Error::new(kind, e.to_string())
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn all_lists_every_kind_once_in_order() {
        // Exhaustive: a new kind does not compile here until it has its place in `ALL`.
        let place = |k: ErrorKind| match k {
            ErrorKind::Syntax => 0,
            ErrorKind::Operand => 1,
            ErrorKind::Value => 2,
            ErrorKind::Range => 3,
            ErrorKind::Unsupported => 4,
            ErrorKind::Refused => 5,
            ErrorKind::Link => 6,
            ErrorKind::Timeout => 7,
            ErrorKind::Usage => 8,
            ErrorKind::Script => 9,
            ErrorKind::Io => 10,
            ErrorKind::Interrupted => 11,
            ErrorKind::State => 12,
        };
        assert_eq!(ErrorKind::ALL.len(), 13);
        for (i, &k) in ErrorKind::ALL.iter().enumerate() {
            assert_eq!(place(k), i, "{}", k.name());
        }
    }

    #[test]
    fn display_names_device_operand_and_hint() {
        let e = Error::new(ErrorKind::Range, "past the end of V")
            .device("plc")
            .operand("VW5000")
            .hint("the last word is VW4094");
        assert_eq!(e.to_string(), "plc: VW5000: past the end of V — the last word is VW4094");
    }
}
