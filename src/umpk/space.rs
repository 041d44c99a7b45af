//! UMPK operands: inputs `I0…`, outputs `Q0…`, markers `M0…`, timers `T0…`, counters
//! `C0…C3`, every one a BOOL (manual §3.3–§3.5, Tables 3 and 4), as one data table
//! ([`AREAS`]) bounded by the model ([`super::model`]). `I0..I7` is a range.
//!
//! Where the values come from: inputs and outputs from the `?05FB`/`?06FA` commands, timers,
//! counters and markers only from the real-time monitor (§4.1.11) — the terminal protocol has
//! no command that reads them, and none that writes anything, so `set` is refused.

use super::model::Model;
use crate::core::msg::Msg;
use crate::core::{Candidate, DataType, Error, ErrorKind, Operand, OperandSpace, Result};
use crate::msg;

/// One operand area.
#[derive(Clone, Copy, Debug)]
pub struct Area {
    pub letter: char,
    /// Its size in the model.
    pub size: fn(&Model) -> u8,
    /// Manual section.
    pub section: &'static str,
}

/// Every area, in the order the monitor packet carries them (Table 7).
pub static AREAS: &[Area] = &[
    Area { letter: 'I', size: |m| m.inputs, section: "§3.3, Table 3" },
    Area { letter: 'Q', size: |m| m.outputs, section: "§3.4, Table 4" },
    Area { letter: 'T', size: |m| m.timers, section: "§3.5, Table 5" },
    Area { letter: 'C', size: |m| m.counters, section: "§3.5" },
    Area { letter: 'M', size: |m| m.markers, section: "§3.4" },
];

impl Area {
    /// What the area holds, in words.
    pub fn meaning(&self) -> Msg {
        msg!("umpk-area-meaning", area = self.letter.to_string())
    }

    /// Where plcsh reads the value from.
    pub fn source(&self) -> Msg {
        msg!("umpk-area-source", area = self.letter.to_string())
    }
}

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
            Error::new(ErrorKind::Operand, msg!("umpk-not-operand", text = text))
                .column(col)
                .hint(msg!("umpk-hint-operands"))
        })?;
        let num = chars.as_str();
        let digits = !num.is_empty() && num.bytes().all(|b| b.is_ascii_digit());
        // Digits past u32 read as u32::MAX: past the end of every area, refused below.
        let index: u32 = num.parse().or_else(|e| if digits { Ok(u32::MAX) } else { Err(e) }).map_err(|_| {
            Error::new(ErrorKind::Operand, msg!("umpk-number-must-follow", text = text, letter = letter.to_string()))
                .column(col)
        })?;
        let size = (AREAS[area].size)(self.model) as u32;
        if index >= size {
            return Err(Error::new(
                ErrorKind::Range,
                msg!(
                    "umpk-past-end",
                    operand = &t,
                    model = self.model.name,
                    letter = letter.to_string(),
                    last = size - 1
                ),
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
                return Err(Error::new(ErrorKind::Operand, msg!("umpk-not-range", text = t)).column(lead));
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
        Some(
            msg!(
                "umpk-describe",
                meaning = o.area().meaning().text,
                operand = o.name(),
                source = o.area().source().text
            )
            .text,
        )
    }

    fn help(&self, text: &str) -> Result<String> {
        let o = self.one(text, 0)?;
        let a = o.area();
        Ok(msg!(
            "umpk-help-operand",
            operand = o.name(),
            meaning = a.meaning().text,
            model = self.model.name,
            letter = a.letter.to_string(),
            last = (a.size)(self.model) - 1,
            source = a.source().text,
            section = a.section
        )
        .text)
    }

    fn complete(&self, prefix: &str) -> Vec<Candidate> {
        let p = prefix.to_ascii_uppercase();
        let mut out = Vec::new();
        for a in AREAS {
            for i in 0..(a.size)(self.model) {
                let text = format!("{}{i}", a.letter);
                if text.starts_with(&p) {
                    out.push(Candidate { text, meaning: a.meaning().text });
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
