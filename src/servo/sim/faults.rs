//! Faults on a simulated servo line: what a flaky cable, a busy drive or a refusing object
//! look like to a master, injected on purpose so commissioning scripts can rehearse their
//! error handling. They sit in the line (the transport side of the simulator), so the
//! served pty and the in-process link show them alike.
//!
//! Each fault matches requests by drive id (any id when none is given) and, for an abort,
//! by object; it applies to the next `count` matching requests (`None`: until cleared).

use crate::msg;
use crate::servo::frame::abort_text_in;
use std::time::Duration;

/// What goes wrong.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum FaultKind {
    /// The drive stays silent and does not act on the request.
    NoReply,
    /// The reply goes out with its checksum byte corrupted (the request was acted on).
    BadChecksum,
    /// The reply goes out this much later than usual.
    Delay(Duration),
    /// Requests for this object get `0x80` with this abort code (not acted on).
    Abort { index: u16, sub: u8, code: u32 },
    /// In loop mode, the echo of the request is missing.
    DropEcho,
}

impl FaultKind {
    /// The fault in words, in the current language.
    pub fn describe(&self) -> String {
        self.describe_in(crate::core::msg::language())
    }

    /// The fault in words, in `lang` (JSON keeps English: scripts read it).
    pub fn describe_in(&self, lang: crate::core::msg::Lang) -> String {
        match self {
            FaultKind::NoReply => msg!(lang: lang, "servo-sim-fault-kind", kind = "no-reply").text,
            FaultKind::BadChecksum => msg!(lang: lang, "servo-sim-fault-kind", kind = "bad-checksum").text,
            FaultKind::Delay(d) => {
                msg!(lang: lang, "servo-sim-fault-kind", kind = "delay", ms = d.as_millis() as u64).text
            }
            FaultKind::Abort { index, sub, code } => {
                let meaning = abort_text_in(lang, *code);
                msg!(
                    lang: lang,
                    "servo-sim-fault-kind",
                    kind = "abort",
                    code = format!("{code:08X}"),
                    meaning = meaning,
                    object = format!("{index:04X}.{sub:02X}")
                )
                .text
            }
            FaultKind::DropEcho => msg!(lang: lang, "servo-sim-fault-kind", kind = "drop-echo").text,
        }
    }
}

/// One armed fault.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct LineFault {
    pub kind: FaultKind,
    /// The drive id it applies to (`None`: every id).
    pub id: Option<u8>,
    /// Requests it still applies to (`None`: until cleared).
    pub remaining: Option<u32>,
}

/// What the armed faults do to one request.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct Effects {
    pub no_reply: bool,
    pub bad_checksum: bool,
    pub delay: Duration,
    pub abort: Option<u32>,
    pub drop_echo: bool,
}

/// The faults armed on a line.
#[derive(Clone, Debug, Default)]
pub struct LineFaults {
    list: Vec<LineFault>,
}

impl LineFaults {
    pub fn add(&mut self, f: LineFault) {
        self.list.push(f);
    }
    pub fn clear(&mut self) {
        self.list.clear();
    }
    pub fn armed(&self) -> &[LineFault] {
        &self.list
    }

    /// The effects on a request for `id` and object `index.sub`, counting each matching
    /// fault down (and dropping the used-up ones).
    pub fn take(&mut self, id: u8, index: u16, sub: u8) -> Effects {
        let mut e = Effects::default();
        for f in &mut self.list {
            if f.id.is_some_and(|i| i != id) || f.remaining == Some(0) {
                continue;
            }
            match f.kind {
                FaultKind::NoReply => e.no_reply = true,
                FaultKind::BadChecksum => e.bad_checksum = true,
                FaultKind::Delay(d) => e.delay += d,
                FaultKind::Abort { index: i, sub: s, code } if (i, s) == (index, sub) => e.abort = Some(code),
                FaultKind::Abort { .. } => continue,
                FaultKind::DropEcho => e.drop_echo = true,
            }
            if let Some(n) = f.remaining.as_mut() {
                *n -= 1;
            }
        }
        self.list.retain(|f| f.remaining != Some(0));
        e
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn faults_match_by_id_and_object_and_count_down() {
        let mut l = LineFaults::default();
        l.add(LineFault { kind: FaultKind::NoReply, id: Some(2), remaining: Some(2) });
        let abort = FaultKind::Abort { index: 0x607A, sub: 0, code: 0x0609_0030 };
        l.add(LineFault { kind: abort, id: None, remaining: None });
        assert_eq!(l.take(1, 0x6041, 0), Effects::default(), "other id, other object");
        assert!(l.take(2, 0x6041, 0).no_reply);
        assert_eq!(l.take(1, 0x607A, 0).abort, Some(0x0609_0030));
        assert!(l.take(2, 0x6041, 0).no_reply);
        assert!(!l.take(2, 0x6041, 0).no_reply, "used up after two");
        assert_eq!(l.armed().len(), 1, "the abort stays until cleared");
        assert!(abort.describe().contains("value range"));
        l.clear();
        assert!(l.armed().is_empty());
    }
}
