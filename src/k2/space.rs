//! The K2 operand space bound to one model: the grammar of [`super::operand`] plus the
//! model's area sizes (`../shared/spec/k2.md` §1), SM register names for hints, `help` and
//! completion (from [`super::sm_map`]). An operand past the model's area is refused here,
//! before anything reaches a device, with the model and the area's last address.

use super::catalog::{self, Model};
use super::operand::{self, Area, K2Operand, Width};
use super::sm_map::{self, SmSize};
use crate::core::{Candidate, Error, ErrorKind, Operand, OperandSpace, Result};
use crate::msg;

/// K2 operands for one model.
#[derive(Clone, Copy, Debug)]
pub struct K2Space {
    pub model: &'static Model,
}

impl K2Space {
    pub fn new(model: &'static Model) -> K2Space {
        K2Space { model }
    }

    /// Size of an area on this model: bytes, or elements for T and C.
    pub fn area_len(&self, area: Area) -> u32 {
        let m = self.model;
        match area {
            Area::I => m.i_bytes,
            Area::Q => m.q_bytes,
            Area::M => m.m_bytes,
            Area::V => m.v_bytes,
            Area::SM => catalog::SM_BYTES,
            Area::AI => m.ai_bytes,
            Area::AQ => m.aq_bytes,
            Area::T => catalog::TIMERS,
            Area::C => catalog::COUNTERS,
        }
    }

    /// Checks an operand against the model's areas.
    pub fn check(&self, op: &K2Operand) -> Result<()> {
        let len = self.area_len(op.area);
        let name = op.canonical();
        if len == 0 {
            return Err(Error::new(
                ErrorKind::Range,
                msg!(
                    "k2-model-has-no-area",
                    model = self.model.name,
                    area = op.area.name(),
                    meaning = op.area.meaning()
                ),
            )
            .operand(name)
            .hint(self.models_with(op.area)));
        }
        let end = op.byte as u64 + op.width.bytes() as u64;
        if end > len as u64 {
            let message = match last_of(op, len) {
                Some(last) => msg!(
                    "k2-past-the-end",
                    operand = name.as_str(),
                    area = op.area.name(),
                    model = self.model.name,
                    size = kind_word(op.width),
                    last = last
                ),
                None => msg!(
                    "k2-area-too-small",
                    operand = name.as_str(),
                    area = op.area.name(),
                    model = self.model.name,
                    bits = len * 8,
                    size = kind_word(op.width)
                ),
            };
            return Err(Error::new(ErrorKind::Range, message).operand(name));
        }
        Ok(())
    }

    /// `Q9.9` on a K205: the grammar says bit 9 does not exist (naming `Q9.7`), but Q9 is not
    /// on this model either, so the message names the model's last valid bit (`Q1.7`).
    fn past_the_end_bit(&self, text: &str, e: Error) -> Error {
        let t = text.trim();
        let Some((head, bit)) = t.rsplit_once('.') else { return e };
        if bit.is_empty() || !bit.bytes().all(|b| b.is_ascii_digit()) || e.code != "k2-bit-too-large" {
            return e;
        }
        let Ok(ops) = operand::parse_expr(&format!("{head}.7")) else { return e };
        let [op] = ops.as_slice() else { return e };
        match self.check(op) {
            Ok(()) => e,
            Err(range) if self.area_len(op.area) == 0 => range,
            Err(_) => {
                let last = last_of(op, self.area_len(op.area)).unwrap_or_default();
                Error::new(
                    ErrorKind::Range,
                    msg!(
                        "k2-bit-and-byte-past-the-end",
                        operand = t,
                        bit = bit,
                        byte = op.byte,
                        area = op.area.name(),
                        model = self.model.name,
                        last = last.as_str()
                    ),
                )
                .operand(t.to_string())
                .hint(msg!(
                    "k2-hint-area-bits",
                    meaning = op.area.meaning(),
                    model = self.model.name,
                    first = format!("{}0.0", op.area.name()),
                    last = last.as_str()
                ))
            }
        }
    }

    fn models_with(&self, area: Area) -> String {
        let with: Vec<&str> =
            catalog::MODELS.iter().filter(|m| K2Space::new(m).area_len(area) > 0).map(|m| m.name).collect();
        msg!("k2-hint-models-with", area = area.name(), models = with.join(", ")).into()
    }

    /// Parses and bounds-checks, returning K2 operands.
    pub fn parse_k2(&self, text: &str) -> Result<Vec<K2Operand>> {
        let ops = operand::parse_expr(text).map_err(|e| self.past_the_end_bit(text, e))?;
        for o in &ops {
            self.check(o)?;
        }
        Ok(ops)
    }
}

/// The operand size as the messages' `$size` selector names it (`k2-past-the-end`).
fn kind_word(w: Width) -> &'static str {
    match w {
        Width::Bit(_) => "bit",
        Width::Byte => "byte",
        Width::Word => "word",
        Width::DWord => "dword",
        Width::Group { .. } => "group",
        Width::Element => "element",
    }
}

/// The last operand of the same size that fits an area of `len` (> 0) bytes; `None`
/// when not even one fits (a K3 group in an 8-bit input area).
fn last_of(op: &K2Operand, len: u32) -> Option<String> {
    let mut o = *op;
    match op.width {
        Width::Bit(_) => {
            o.byte = len - 1;
            o.width = Width::Bit(7);
        }
        Width::Element => o.byte = len - 1,
        Width::Group { n, .. } => {
            let bits = (len * 8).checked_sub(4 * n as u32)?;
            o.byte = bits / 8;
            o.width = Width::Group { n, bit: (bits % 8) as u8 };
        }
        w => o.byte = len.checked_sub(w.bytes())?,
    }
    if matches!(op.area, Area::AI | Area::AQ) && o.byte % 2 == 1 {
        o.byte -= 1;
    }
    Some(o.canonical())
}

/// The SM register name of an operand, when the table has one.
fn sm_name(op: &K2Operand) -> Option<&'static sm_map::SmName> {
    if op.area != Area::SM {
        return None;
    }
    let size = match op.width {
        Width::Bit(b) => SmSize::Bit(b),
        Width::Byte => SmSize::Byte,
        Width::Word => SmSize::Word,
        Width::DWord => SmSize::DWord,
        _ => return None,
    };
    sm_map::lookup(op.byte, size)
}

impl OperandSpace for K2Space {
    fn family(&self) -> &'static str {
        "k2"
    }

    fn parse(&self, text: &str) -> Result<Vec<Operand>> {
        Ok(self.parse_k2(text)?.iter().map(|o| o.to_core()).collect())
    }

    fn name(&self, op: &Operand) -> String {
        K2Operand::from_key(op.key).canonical()
    }

    /// Bit areas by byte and bit (K2 manual §3.2: `VB0`, `VW0`, `VD0`, `V0.0` share bytes);
    /// a timer or counter is one element whatever its view (`T5`, `T5/BOOL`).
    fn span(&self, op: &Operand) -> Option<crate::core::Span> {
        let k = K2Operand::from_key(op.key);
        let area = Area::ALL.iter().position(|a| *a == k.area)? as u32;
        let (first_bit, bits) = match k.width {
            Width::Bit(b) => (k.byte as u64 * 8 + b as u64, 1),
            Width::Group { n, bit } => (k.byte as u64 * 8 + bit as u64, 4 * n as u64),
            Width::Element => (k.byte as u64 * 64, 64),
            w => (k.byte as u64 * 8, w.bytes() as u64 * 8),
        };
        Some(crate::core::Span { area, first_bit, bits })
    }

    fn describe(&self, op: &Operand) -> Option<String> {
        let k = K2Operand::from_key(op.key);
        if let Some(n) = sm_name(&k) {
            return Some(n.meaning.clone());
        }
        if k.area == Area::SM {
            let over = sm_map::overlapping(k.byte, k.width.bytes());
            if !over.is_empty() {
                let names: Vec<String> = over.iter().map(|n| format!("{} ({})", n.operand(), n.meaning)).collect();
                return Some(msg!("k2-describe-overlaps", names = names.join(", ")).into());
            }
        }
        if k.area == Area::Q {
            for p in self.model.pto {
                if let (Width::Bit(b), Some(spec)) = (k.width, Some(p)) {
                    if format!("Q{}.{}", k.byte, b) == spec.output {
                        return Some(
                            msg!("k2-describe-pulse-output", channel = p.channel, khz = p.max_hz / 1000).into(),
                        );
                    }
                    if format!("Q{}.{}", k.byte, b) == spec.direction {
                        return Some(msg!("k2-describe-direction-output", channel = p.channel).into());
                    }
                }
            }
        }
        if k.area == Area::V && k.byte >= catalog::EEPROM_FIRST {
            return Some(msg!("k2-describe-v-backup").into());
        }
        Some(k.area.meaning().to_string())
    }

    fn help(&self, text: &str) -> Result<String> {
        let ops = self.parse_k2(text)?;
        let k = ops[0];
        let core = k.to_core();
        let mut s = format!("{} — {}\n", k.canonical(), self.describe(&core).unwrap_or_default());
        let (lo, hi) = k.view.int_range();
        let range = match k.width {
            Width::Group { n, .. } => format!("0…{}", (1u64 << (4 * n)) - 1),
            _ if k.view == crate::core::DataType::Real => "IEEE 754 single".into(),
            _ => format!("{lo}…{hi}"),
        };
        s.push_str(&format!("{}\n", msg!("k2-help-type", dtype = k.view.name(), bits = k.bits(), range = range)));
        let unit = if matches!(k.area, Area::T | Area::C) { "elements" } else { "bytes" };
        s.push_str(&format!(
            "{}\n",
            msg!(
                "k2-help-area",
                area = k.area.name(),
                meaning = k.area.meaning(),
                n = self.area_len(k.area),
                unit = unit,
                model = self.model.name
            )
        ));
        match sm_name(&k) {
            Some(n) if n.section.starts_with('§') => {
                s.push_str(&format!("{}\n", msg!("k2-help-manual", section = n.section)))
            }
            Some(n) => s.push_str(&format!("{}\n", msg!("k2-help-source", source = n.section))),
            None => s.push_str(&format!("{}\n", msg!("k2-help-written-as"))),
        }
        Ok(s)
    }

    fn complete(&self, prefix: &str) -> Vec<Candidate> {
        let p = prefix.trim_start_matches('%').to_ascii_uppercase();
        let mut out: Vec<Candidate> = Vec::new();
        if p.starts_with('S') {
            for n in sm_map::names() {
                let name = n.operand();
                if name.starts_with(&p) {
                    out.push(Candidate { text: name, meaning: n.meaning.clone() });
                }
            }
            return out;
        }
        for form in
            ["I", "IB", "Q", "QB", "M", "MB", "MW", "MD", "V", "VB", "VW", "VD", "SM", "AIW", "AQW", "T", "C", "K4M"]
        {
            if form.starts_with(&p) && p.len() < form.len() {
                out.push(Candidate { text: form.to_string(), meaning: msg!("k2-complete-form", form = form).into() });
            }
        }

        out
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn space(m: &str) -> K2Space {
        K2Space::new(catalog::find(m).unwrap())
    }

    /// `help OPERAND` cites what a user has — the K2 manual's sections, KincoBuilder — never a
    /// file of the project's own notes (`k2.md`, `kinco-public-notes`).
    #[test]
    fn operand_help_cites_only_what_the_user_has() {
        let s = space("K209EA-50DX");
        let mut texts: Vec<String> =
            crate::k2::sm_map::names().iter().filter_map(|n| s.help(&n.operand()).ok()).collect();
        texts.extend(["VW100", "I0.0", "SMB67", "SM0.1", "T5"].iter().map(|o| s.help(o).unwrap()));
        assert!(texts.len() > 50, "{}", texts.len());
        for t in &texts {
            assert!(!t.contains(".md") && !t.contains("public-notes") && !t.contains("digest"), "{t}");
        }
    }

    #[test]
    fn a_bit_past_7_in_a_byte_past_the_area_names_the_models_last_bit() {
        // K205: Q0.0–Q1.7 (k2.md §1). Q9.9 is wrong twice; the message names Q1.7, not Q9.7.
        let s = space("K205-16DT");
        let e = s.parse_k2("Q9.9").unwrap_err();
        assert!(e.message.contains("Q1.7") && !e.message.contains("Q9.7"), "{}", e.message);
        assert!(e.message.contains("K205-16DT") && e.message.contains("bit 9"), "{}", e.message);
        let e = s.parse_k2("%Q9.9").unwrap_err();
        assert!(e.message.contains("Q1.7"), "{}", e.message);
        // Inside the area only the bit is wrong: Q0.9 → Q0.7 is the last bit of that byte.
        assert!(s.parse_k2("Q0.9").unwrap_err().message.contains("Q0.7"));
        assert!(s.parse_k2("I7.8").unwrap_err().message.contains("I1.7"));
        let fx = sim_compile_error("LD %SM0.0\nST %Q9.9");
        assert!(fx.contains("Q1.7"), "a program load names it too: {fx}");
    }

    fn sim_compile_error(text: &str) -> String {
        let sim = crate::k2::sim::open("K205-16DT", crate::core::Clock::stepped()).unwrap();
        sim.compile(text, "q.il").unwrap_err().message.clone()
    }

    #[test]
    fn bounds_follow_the_model() {
        let s = space("K205-16DT");
        assert!(s.parse_k2("VW4094").is_ok());
        let e = s.parse_k2("VW4095").unwrap_err();
        assert_eq!(e.kind, ErrorKind::Range);
        assert!(e.message.contains("K205-16DT") && e.message.contains("VW4094"), "{}", e.message);
        assert!(s.parse_k2("VB4096").unwrap_err().message.contains("VB4095"));
        assert!(s.parse_k2("I1.7").is_ok());
        assert!(s.parse_k2("I2.0").unwrap_err().message.contains("I1.7"));
        assert!(s.parse_k2("AIW0").unwrap_err().hint.clone().unwrap().contains("K205EA-18DT"));
        assert!(s.parse_k2("T256").unwrap_err().message.contains("T255"));
        assert!(s.parse_k2("MD1020").is_ok());
        assert!(s.parse_k2("MD1021").unwrap_err().message.contains("MD1020"));
        let big = space("K209M-56DT");
        assert!(big.parse_k2("VW16382").is_ok());
        assert!(space("K209EA-50DX").parse_k2("AIW10").is_ok());
        assert!(space("K209EA-50DX").parse_k2("AIW12").unwrap_err().message.contains("AIW10"));
        // A group wider than the whole area: no "last valid" one to suggest, and no underflow.
        let e = space("K204ET-16DT").parse_k2("K3I0.0").unwrap_err();
        assert_eq!(e.kind, ErrorKind::Range);
        assert!(e.message.contains("does not fit the I area") && !e.message.contains("K3I5"), "{}", e.message);
    }

    #[test]
    fn describe_uses_the_sm_table() {
        let s = space("K205-16DT");
        let op = s.parse("SMB67").unwrap()[0];
        assert_eq!(s.describe(&op).unwrap(), "PTO0/PWM0 (Q0.0) control byte");
        let odd = s.parse("SMW67").unwrap()[0];
        assert!(s.describe(&odd).unwrap().contains("SMB67"));
        let q = s.parse("Q0.0").unwrap()[0];
        assert!(s.describe(&q).unwrap().contains("PTO0"));
        assert!(s.help("SMD72").unwrap().contains("§3.4.2.2"));
    }

    #[test]
    fn completion_lists_sm_names_with_meaning() {
        let s = space("K205-16DT");
        let c = s.complete("SMB6");
        assert!(c.iter().any(|c| c.text == "SMB67" && c.meaning.contains("control")), "{c:?}");
        assert!(c.iter().all(|c| c.text.starts_with("SMB6")));
        assert!(s.complete("v").iter().any(|c| c.text == "VW"));
    }
}
