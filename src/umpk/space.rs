//! UMPK operands: inputs `I0…`, outputs `Q0…`, markers `M0…`, timers `T0…`, counters
//! `C0…C3`, every one a BOOL (manual §3.3–§3.5, Tables 3 and 4), as one data table
//! ([`AREAS`]) bounded by the model ([`super::model`]). `I0..I7` is a range.
//!
//! Where the values come from: inputs and outputs from the `?05FB`/`?06FA` commands, timers,
//! counters and markers only from the real-time monitor (§4.1.11) — the terminal protocol has
//! no command that reads them, and none that writes anything, so `set` is refused.

use super::model::Model;
use crate::core::{Candidate, DataType, Error, ErrorKind, Operand, OperandSpace, Result};

/// One operand area.
#[derive(Clone, Copy, Debug)]
pub struct Area {
    pub letter: char,
    pub meaning: &'static str,
    /// Its size in the model.
    pub size: fn(&Model) -> u8,
    /// Where the value is read from.
    pub source: &'static str,
    /// Manual section.
    pub section: &'static str,
}

/// Every area, in the order the monitor packet carries them (Table 7).
pub static AREAS: &[Area] = &[
    Area {
        letter: 'I',
        meaning: "digital input",
        size: |m| m.inputs,
        source: "?05FB or the monitor",
        section: "§3.3, Table 3",
    },
    Area {
        letter: 'Q',
        meaning: "digital output (opto-relay, 48 V 0.3 A)",
        size: |m| m.outputs,
        source: "?06FA or the monitor",
        section: "§3.4, Table 4",
    },
    Area {
        letter: 'T',
        meaning: "on-delay timer output",
        size: |m| m.timers,
        source: "the real-time monitor",
        section: "§3.5, Table 5",
    },
    Area {
        letter: 'C',
        meaning: "counter output pulse",
        size: |m| m.counters,
        source: "the real-time monitor",
        section: "§3.5",
    },
    Area { letter: 'M', meaning: "marker", size: |m| m.markers, source: "the real-time monitor", section: "§3.4" },
];

/// A parsed UMPK operand.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct UmpkOperand {
    /// Index into [`AREAS`].
    pub area: usize,
    pub index: u8,
}

impl UmpkOperand {
    pub fn area(&self) -> &'static Area {
        &AREAS[self.area]
    }
    pub fn to_core(self) -> Operand {
        Operand { key: (self.area as u64) << 8 | self.index as u64, dtype: DataType::Bool, bits: 1 }
    }
    pub fn from_core(op: &Operand) -> UmpkOperand {
        UmpkOperand { area: (op.key >> 8) as usize % AREAS.len(), index: op.key as u8 }
    }
    pub fn name(&self) -> String {
        format!("{}{}", self.area().letter, self.index)
    }
}

/// The operand space of one model.
#[derive(Clone, Debug)]
pub struct UmpkSpace {
    pub model: &'static Model,
}

impl UmpkSpace {
    fn one(&self, text: &str, col: usize) -> Result<UmpkOperand> {
        let t = text.trim().to_ascii_uppercase();
        let mut chars = t.chars();
        let letter = chars.next().unwrap_or(' ');
        let area = AREAS.iter().position(|a| a.letter == letter).ok_or_else(|| {
            Error::new(ErrorKind::Operand, format!("`{text}` is not a UMPK operand"))
                .column(col)
                .hint("UMPK operands: I0…, Q0…, M0…, T0…, C0…C3 (help I0 tells more)")
        })?;
        let num = chars.as_str();
        let digits = !num.is_empty() && num.bytes().all(|b| b.is_ascii_digit());
        // Digits past u32 read as u32::MAX: past the end of every area, refused below.
        let index: u32 = num.parse().or_else(|e| if digits { Ok(u32::MAX) } else { Err(e) }).map_err(|_| {
            Error::new(ErrorKind::Operand, format!("`{text}`: a number must follow {letter} (e.g. {letter}0)"))
                .column(col)
        })?;
        let size = (AREAS[area].size)(self.model) as u32;
        if index >= size {
            return Err(Error::new(
                ErrorKind::Range,
                format!("{} is past the end: the {} has {letter}0…{letter}{}", t, self.model.name, size - 1),
            )
            .column(col));
        }
        Ok(UmpkOperand { area, index: index as u8 })
    }
}

impl OperandSpace for UmpkSpace {
    fn family(&self) -> &'static str {
        "umpk"
    }

    fn parse(&self, text: &str) -> Result<Vec<Operand>> {
        let lead = text.len() - text.trim_start().len();
        let t = text.trim();
        if let Some((a, b)) = t.split_once("..") {
            let first = self.one(a, lead)?;
            let last = self.one(b, lead + a.len() + 2)?;
            if first.area != last.area || last.index < first.index {
                return Err(Error::new(ErrorKind::Operand, format!("`{t}` is not a range of one area (e.g. I0..I7)"))
                    .column(lead));
            }
            return Ok((first.index..=last.index)
                .map(|i| UmpkOperand { area: first.area, index: i }.to_core())
                .collect());
        }
        Ok(vec![self.one(t, lead)?.to_core()])
    }

    fn name(&self, op: &Operand) -> String {
        UmpkOperand::from_core(op).name()
    }

    /// Every UMPK operand is one bit of its area (manual §3.3–§3.5).
    fn span(&self, op: &Operand) -> Option<crate::core::Span> {
        let o = UmpkOperand::from_core(op);
        Some(crate::core::Span { area: o.area as u32, first_bit: o.index as u64, bits: 1 })
    }

    fn describe(&self, op: &Operand) -> Option<String> {
        let o = UmpkOperand::from_core(op);
        Some(format!("{} {} (read from {})", o.area().meaning, o.name(), o.area().source))
    }

    fn help(&self, text: &str) -> Result<String> {
        let o = self.one(text, 0)?;
        let a = o.area();
        Ok(format!(
            "{}: {} of the {} ({}{}…{}{}); BOOL; read from {}; manual {}. The UMPK terminal protocol has no write commands.",
            o.name(),
            a.meaning,
            self.model.name,
            a.letter,
            0,
            a.letter,
            (a.size)(self.model) - 1,
            a.source,
            a.section
        ))
    }

    fn complete(&self, prefix: &str) -> Vec<Candidate> {
        let p = prefix.to_ascii_uppercase();
        let mut out = Vec::new();
        for a in AREAS {
            for i in 0..(a.size)(self.model) {
                let text = format!("{}{i}", a.letter);
                if text.starts_with(&p) {
                    out.push(Candidate { text, meaning: a.meaning.to_string() });
                }
            }
        }
        out
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::umpk::model;

    #[test]
    fn bounds_follow_the_model() {
        let s8 = UmpkSpace { model: model::find("UMPK8").unwrap() };
        let s16 = UmpkSpace { model: model::find("UMPK16").unwrap() };
        assert_eq!(s8.parse("I7").unwrap().len(), 1);
        assert_eq!(s8.parse("I8").unwrap_err().kind, ErrorKind::Range);
        let e = s8.parse("I99999999999").unwrap_err();
        assert!(e.message.contains("I99999999999 is past the end") && e.message.contains("I0…I7"), "{e}");
        assert!(s16.parse("I15").is_ok() && s16.parse("Q7").is_ok() && s16.parse("M63").is_ok());
        assert!(s16.parse("T15").is_ok() && s16.parse("C3").is_ok());
        assert!(s8.parse("Q4").is_err() && s8.parse("M32").is_err() && s8.parse("T8").is_err());
        assert!(s16.parse("C4").is_err() && s16.parse("X1").is_err());
        let r = s16.parse("m0..m3").unwrap();
        assert_eq!(r.iter().map(|o| s16.name(o)).collect::<Vec<_>>(), ["M0", "M1", "M2", "M3"]);
        assert!(s16.parse("I0..Q3").is_err());
        assert!(s16.help("T3").unwrap().contains("Table 5"));
        assert_eq!(s8.complete("Q").len(), 4);
    }
}
