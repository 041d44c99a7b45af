//! FX operands bound to one model and one protocol: the grammar of [`super::operand`], the
//! model's device ranges ([`super::model`]) and what the protocol can address. An operand
//! the model lacks, or the protocol cannot reach, is refused here, before anything is sent,
//! with the range that does exist and what to try.
//!
//! The programming port reaches what the model's address table covers ([`port::Table::of`]):
//! the classic table (FX1S, FX1N, FX2N) D0–D7999, M0–M1535, X0–X177, Y0–Y177, S0–S999, T/C
//! 0–255, M8000–M8255 and D8000–D8255 (see [`super::operand::AREAS`]); the extended table of
//! the E-commands (FX3U) every ordinary device of the FX3U ([`port::EXTENDED`]). The computer
//! link reaches every device of the model except the timer and counter coils.

use super::model::{fx1s_counter, Model, MODELS};
use super::operand::{self, Area, FxOperand, Width, AREAS, SPECIAL, SPECIAL_COUNT};
use super::port::{self, Table};
use crate::core::{Candidate, Error, ErrorKind, Operand, OperandSpace, Result};
use crate::msg;

/// The protocol a device is reached through.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Proto {
    /// Programming port (`fx:`, `sim-fx:`).
    Port,
    /// Computer link (`fxlink:`, `sim-fx:…?protocol=link`).
    Link,
}

impl Proto {
    /// The protocol's name, in the current language.
    pub fn name(self) -> crate::core::msg::Msg {
        msg!(
            "fx-proto",
            proto = match self {
                Proto::Port => "port",
                Proto::Link => "link",
            }
        )
    }
}

/// FX operands for one model over one protocol.
#[derive(Clone, Copy, Debug)]
pub struct FxSpace {
    pub model: &'static Model,
    pub proto: Proto,
}

fn range_err(op: &FxOperand, msg: impl Into<crate::core::error::Text>) -> Error {
    Error::new(ErrorKind::Range, msg).operand(op.canonical())
}

impl FxSpace {
    pub fn new(model: &'static Model, proto: Proto) -> FxSpace {
        FxSpace { model, proto }
    }

    /// Ordinary devices of `area` on this model.
    pub fn count(&self, area: Area) -> u16 {
        let m = self.model;
        match area {
            Area::X => m.x,
            Area::Y => m.y,
            Area::M => m.m,
            Area::S => m.s,
            Area::TS | Area::TC | Area::TN => m.t,
            Area::CS | Area::CC | Area::CN => m.c,
            Area::D => m.d,
        }
    }

    /// The model's range of an area, as text (`D0–D7999, D8000–D8255`).
    pub fn range_text(&self, area: Area) -> String {
        let n = self.count(area);
        let name = area.name();
        let mut s = format!("{name}0–{name}{}", FxOperand::number_text(area, n - 1));
        if self.model.name == "FX1S" && matches!(area, Area::CS | Area::CC | Area::CN) {
            s = format!("{name}0–{name}31, {name}235–{name}255");
        }
        if area.has_special() {
            s.push_str(&format!(", {name}8000–{name}{}", SPECIAL + SPECIAL_COUNT - 1));
        }
        s
    }

    pub fn exists(&self, area: Area, index: u16) -> bool {
        if area.has_special() && (SPECIAL..SPECIAL + SPECIAL_COUNT).contains(&index) {
            return true;
        }
        if self.model.name == "FX1S" && matches!(area, Area::CS | Area::CC | Area::CN) && !fx1s_counter(index) {
            return false;
        }
        index < self.count(area)
    }

    /// Checks an operand against the model and the protocol.
    pub fn check(&self, op: &FxOperand) -> Result<()> {
        let last = op.index as u32 + op.span() as u32 - 1;
        if last > u16::MAX as u32 || !self.exists(op.area, op.index) || !self.exists(op.area, last as u16) {
            return Err(range_err(
                op,
                msg!(
                    "fx-not-on-model",
                    operand = op.canonical(),
                    model = self.model.name,
                    range = self.range_text(op.area)
                ),
            ));
        }
        if (op.index >= SPECIAL) != (last as u16 >= SPECIAL) {
            return Err(range_err(op, msg!("fx-crosses-special", operand = op.canonical())));
        }
        match self.proto {
            Proto::Port => {
                let table = Table::of(self.model);
                if port::place(table, op).is_none() {
                    let p = table.map(op.area);
                    let name = op.area.name();
                    let mut reach = format!("{name}0–{name}{}", FxOperand::number_text(op.area, p.count - 1));
                    if p.special.is_some() {
                        reach.push_str(&format!(", {name}8000–{name}8255"));
                    }
                    let hint = match table {
                        Table::Classic => msg!("fx-hint-e-commands", model = self.model.name),
                        Table::Extended => msg!("fx-hint-nak-area"),
                    };
                    return Err(range_err(
                        op,
                        msg!(
                            "fx-past-port-table",
                            operand = op.canonical(),
                            model = self.model.name,
                            commands = table.commands(),
                            reach = reach
                        ),
                    )
                    .hint(hint));
                }
            }
            Proto::Link => {
                if op.area.spec().link.is_empty() {
                    return Err(Error::unsupported(msg!(
                        "fx-not-on-link",
                        operand = op.canonical(),
                        meaning = op.area.meaning().text
                    ))
                    .operand(op.canonical())
                    .hint(msg!("fx-hint-not-on-link")));
                }
            }
        }
        Ok(())
    }

    /// Parses and checks, returning FX operands.
    pub fn parse_fx(&self, text: &str) -> Result<Vec<FxOperand>> {
        let ops = operand::parse_expr(text)?;
        for o in &ops {
            self.check(o)?;
        }
        Ok(ops)
    }
}

impl OperandSpace for FxSpace {
    fn family(&self) -> &'static str {
        "fx"
    }

    fn parse(&self, text: &str) -> Result<Vec<Operand>> {
        Ok(self.parse_fx(text)?.iter().map(|o| o.to_core()).collect())
    }

    fn name(&self, op: &Operand) -> String {
        FxOperand::from_key(op.key).canonical()
    }

    /// Bit devices by number (`K4M0` covers M0–M15, fx-and-masterk.md A); word devices by
    /// word (`D10/DINT` covers D10 and D11). A timer's or counter's contact and its current
    /// value are separate memories (`T5` the bit, the word form its value).
    fn span(&self, op: &Operand) -> Option<crate::core::Span> {
        let o = FxOperand::from_key(op.key);
        let word = matches!(o.width, Width::Word | Width::Pair);
        let area = (o.area as u32) * 2 + u32::from(word);
        let (unit, count) = if word { (16, o.span() as u64) } else { (1, o.span() as u64) };
        Some(crate::core::Span { area, first_bit: o.index as u64 * unit, bits: count * unit })
    }

    fn describe(&self, op: &Operand) -> Option<String> {
        let o = FxOperand::from_key(op.key);
        let mut s = match o.width {
            Width::Group(n) => {
                msg!(
                    "fx-describe-group",
                    bits = 4 * n,
                    meaning = o.area.meaning().text,
                    first = format!("{}{}", o.area.name(), FxOperand::number_text(o.area, o.index)),
                    last = format!("{}{}", o.area.name(), FxOperand::number_text(o.area, o.index + 4 * n as u16 - 1))
                )
                .text
            }
            Width::Pair if o.area == Area::D => msg!("fx-describe-pair", low = o.index, high = o.index + 1).text,
            Width::Bit | Width::Word if o.index >= SPECIAL => match operand::special_meaning(o.area, o.index) {
                Some(m) => m.text,
                None => msg!("fx-describe-special", meaning = o.area.meaning().text).text,
            },
            _ if o.index >= SPECIAL => msg!("fx-describe-special", meaning = o.area.meaning().text).text,
            _ => o.area.meaning().text,
        };
        if !o.group_aligned() {
            s.push_str(&msg!(
                "fx-describe-unaligned",
                first = format!("{}{}", o.area.name(), FxOperand::number_text(o.area, o.index)),
                area = o.area.name()
            ));
        }
        Some(s)
    }

    fn help(&self, text: &str) -> Result<String> {
        let ops = self.parse_fx(text)?;
        let o = ops[0];
        let core = o.to_core();
        let mut s = format!("{} — {}\n", o.canonical(), self.describe(&core).unwrap_or_default());
        let (lo, hi) = o.view.int_range();
        let range = match o.width {
            Width::Group(n) if 4 * n as u32 == o.view.bits() => format!("{lo}…{hi}"),
            Width::Group(n) => msg!("fx-help-group-range", max = (1u64 << (4 * n)) - 1).text,
            _ if o.view == crate::core::DataType::Real => "IEEE 754 single".into(),
            _ => format!("{lo}…{hi}"),
        };
        s.push_str(&msg!("fx-help-type", dtype = o.view.name(), bits = o.bits(), range = range));
        s.push('\n');
        s.push_str(&msg!("fx-help-on-model", model = self.model.name, range = self.range_text(o.area)));
        s.push('\n');
        if let Some(timer) = match o.area {
            Area::TS | Area::TC | Area::TN => Some(true),
            Area::CS | Area::CC | Area::CN => Some(false),
            _ => None,
        } {
            s.push_str(&super::elements::element_note(timer, o.index));
            s.push('\n');
        }
        match self.proto {
            Proto::Port => {
                let table = Table::of(self.model);
                if let Some(p) = port::place(table, &o) {
                    s.push_str(&msg!(
                        "fx-help-port",
                        commands = table.commands(),
                        address = format!("{:04X}", p.addr),
                        bytes = p.len
                    ));
                    if let Some(f) = port::force_address(table, o.area, o.index).filter(|_| o.width == Width::Bit) {
                        s.push_str(&msg!("fx-help-force", address = format!("{f:04X}")));
                    }
                    s.push('\n');
                }
            }
            Proto::Link => {
                let d = super::link::Dev { area: o.area, index: o.index };
                s.push_str(&msg!("fx-help-link", device = d.encode()));
                s.push('\n');
            }
        }
        s.push_str(&msg!("fx-help-manual"));
        s.push('\n');
        Ok(s)
    }

    fn complete(&self, prefix: &str) -> Vec<Candidate> {
        let p = prefix.trim_start_matches('%').to_ascii_uppercase();
        let mut out = Vec::new();
        for spec in AREAS.iter() {
            if self.proto == Proto::Link && spec.link.is_empty() {
                continue;
            }
            if spec.name.starts_with(&p) && p.len() < spec.name.len() + 1 {
                out.push(Candidate { text: spec.name.to_string(), meaning: spec.area.meaning().text });
            }
            if spec.groups {
                for n in [2u8, 4, 8] {
                    let t = format!("K{n}{}0", spec.name);
                    if t.starts_with(&p) && p.len() < t.len() {
                        out.push(Candidate {
                            text: t,
                            meaning: msg!("fx-complete-group", bits = 4 * n, meaning = spec.area.meaning().text).text,
                        });
                    }
                }
            }
        }
        for (area, index) in operand::SPECIALS {
            let t = format!("{}{index}", area.name());
            if t.starts_with(&p) && p.len() >= 2 {
                let meaning = operand::special_meaning(*area, *index).map(|m| m.text).unwrap_or_default();
                out.push(Candidate { text: t, meaning });
            }
        }
        out
    }
}

/// Model names for hints.
pub fn model_names() -> String {
    MODELS.iter().map(|m| m.name).collect::<Vec<_>>().join(", ")
}

#[cfg(test)]
mod tests {
    use super::*;

    fn space(m: &str, p: Proto) -> FxSpace {
        FxSpace::new(Model::find(m).unwrap(), p)
    }

    #[test]
    fn an_unaligned_group_is_described_with_its_warning() {
        // A group that does not start at a number ending in 0 (FX programming manual, KnX).
        let s = space("FX2N", Proto::Port);
        let op = s.parse("K2M3").unwrap();
        assert_eq!(
            s.describe(&op[0]).unwrap(),
            "8-bit group of auxiliary relay bits M3–M10 — warning: group starts at M3; the manual advises a number ending in 0 (M0, M10 …)"
        );
    }

    #[test]
    fn bounds_follow_model_and_protocol() {
        let s = space("FX1S", Proto::Port);
        assert!(s.parse_fx("D255").is_ok());
        let e = s.parse_fx("D256").unwrap_err();
        assert_eq!(e.kind, ErrorKind::Range);
        assert!(e.message.contains("FX1S") && e.message.contains("D0–D255"), "{e}");
        assert!(s.parse_fx("X17").is_ok());
        assert!(s.parse_fx("X20").unwrap_err().message.contains("X0–X17"));
        assert!(s.parse_fx("CN235").is_ok() && s.parse_fx("CN40").is_err());
        assert!(s.parse_fx("D8000").is_ok());
        // The classic table reaches D0–D7999 and M0–M1535 of an FX2N; M1536 and up only the
        // E-commands of an FX3U or the computer link.
        let p = space("FX2N", Proto::Port);
        assert!(p.parse_fx("D600").is_ok() && p.parse_fx("D7999").is_ok() && p.parse_fx("M1535").is_ok());
        let e = p.parse_fx("M1536").unwrap_err();
        assert!(e.message.contains("programming-port address table") && e.message.contains("M0–M1535"), "{e}");
        assert!(e.hint.as_deref().unwrap().contains("model=FX3U"), "{e:?}");
        assert!(space("FX1N", Proto::Port).parse_fx("M1535").is_ok());
        assert!(space("FX1N", Proto::Port).parse_fx("D7999").is_ok());
        let u = space("FX3U", Proto::Port);
        for op in ["M7679", "S4095", "TN511", "TS511", "D7999", "D8255", "K8M7648"] {
            assert!(u.parse_fx(op).is_ok(), "{op}");
        }
        assert!(u.parse_fx("M7680").unwrap_err().message.contains("M0–M7679"));
        assert!(space("FX3UC", Proto::Port).parse_fx("S4095").is_ok(), "FX3UC names the FX3U row");
        assert!(space("FX2NC", Proto::Port).parse_fx("S4095").is_err(), "FX2NC names the FX2N row");
        let l = space("FX2N", Proto::Link);
        assert!(l.parse_fx("D600").is_ok() && l.parse_fx("D7999").is_ok() && l.parse_fx("D8000").is_ok());
        assert_eq!(l.parse_fx("TC0").unwrap_err().kind, ErrorKind::Unsupported);
        assert!(l.parse_fx("K8M3040").is_ok() && l.parse_fx("K8M3041").is_err());
        assert!(l.parse_fx("D7999/DINT").is_err(), "the pair needs D8000, which is special");
    }

    #[test]
    fn describe_warns_on_unaligned_groups_and_help_shows_addresses() {
        let s = space("FX2N", Proto::Port);
        let op = s.parse("K4M3").unwrap()[0];
        assert!(s.describe(&op).unwrap().contains("warning"), "{:?}", s.describe(&op));
        let op = s.parse("K4M10").unwrap()[0];
        assert!(!s.describe(&op).unwrap().contains("warning"));
        let h = s.help("M500").unwrap();
        assert!(h.contains("byte address 013EH") && h.contains("force address 09F4H"), "{h}");
        let h = space("FX3U", Proto::Port).help("M500").unwrap();
        assert!(
            h.contains("E00/E10/E7/E8") && h.contains("byte address 883EH") && h.contains("force address 41F4H"),
            "{h}"
        );
        assert!(space("FX2N", Proto::Link).help("D100").unwrap().contains("device D0100"));
        assert!(s.complete("k4").iter().any(|c| c.text == "K4M0"));
        assert!(s.complete("T").iter().any(|c| c.text == "TN"));
        assert!(s.complete("M80").iter().any(|c| c.text == "M8002" && c.meaning.contains("initial pulse")));
        let d = s.parse("D8000").unwrap()[0];
        assert_eq!(s.describe(&d).unwrap(), "watchdog time, ms");
        let m = s.parse("M8100").unwrap()[0];
        assert_eq!(s.describe(&m).unwrap(), "special auxiliary relay");
    }
}
