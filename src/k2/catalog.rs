//! The K2 model catalogue (`../shared/spec/k2.md` §1; manual §1.2, §2.1.2, §2.2.6, §3.4):
//! one table, used by the operand space (area bounds), the simulator (which channels
//! exist, how fast), the Modbus map (area sizes) and `help`.
//!
//! The manual's tables disagree in places. Each disagreement is recorded on the model as a
//! [`Discrepancy`] with both values and the sections, and the value we chose is the one in
//! the struct. Rule used: where two of the three tables agree, take their value (the
//! §2.1.2 table's last columns look shifted by one: its CPU204 column matches what §2.2.6
//! says of CPU209EA, and its CPU209EA column matches CPU209M).

use crate::core::msg::Msg;
use crate::msg;
use serde::Serialize;

/// A high-speed counter channel on a model.
#[derive(Clone, Copy, Debug, Serialize)]
pub struct HscSpec {
    pub channel: u8,
    /// Maximum single-phase counting frequency, Hz.
    pub max_hz_single: u32,
    /// Maximum A/B (quadrature) frequency, Hz.
    pub max_hz_ab: u32,
}

/// A pulse output (PTO/PWM) channel on a model.
#[derive(Clone, Copy, Debug, Serialize)]
pub struct PtoSpec {
    pub channel: u8,
    /// The output bit, `Q0.0` …
    pub output: &'static str,
    /// The direction output for position control.
    pub direction: &'static str,
    pub max_hz: u32,
}

/// Where the manual's tables disagree for this model.
#[derive(Clone, Copy, Debug, Serialize)]
pub struct Discrepancy {
    pub what: Phrase,
    pub chosen: Phrase,
    pub other: Phrase,
}

/// A text of the catalogue (`tables.ftl`, ids `tbl-model-…`), shown and serialised in the
/// current language.
#[derive(Clone, Copy)]
pub struct Phrase(pub fn() -> Msg);

impl std::fmt::Display for Phrase {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        f.write_str(&(self.0)().text)
    }
}

impl std::fmt::Debug for Phrase {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        f.write_str((self.0)().id)
    }
}

impl Serialize for Phrase {
    fn serialize<S: serde::Serializer>(&self, s: S) -> Result<S::Ok, S::Error> {
        s.serialize_str(&(self.0)().text)
    }
}

/// One K2 CPU model.
#[derive(Clone, Copy, Debug, Serialize)]
pub struct Model {
    pub name: &'static str,
    pub cpu: &'static str,
    pub di: u8,
    pub dout: u8,
    /// DIO channels (configurable in or out).
    pub dio: u8,
    pub ai: u8,
    pub ao: u8,
    /// Byte sizes of the areas (§2.1.2 "memory area").
    pub i_bytes: u32,
    pub q_bytes: u32,
    pub m_bytes: u32,
    pub v_bytes: u32,
    pub ai_bytes: u32,
    pub aq_bytes: u32,
    /// Relay outputs: no PTO/PWM (§2.2.6 note).
    pub relay: bool,
    pub ethernet: bool,
    pub serial: &'static str,
    pub program_kinstr: u32,
    /// Battery-retained range in bytes (§2.1.2 "retention range").
    pub retentive_bytes: u32,
    pub hsc: &'static [HscSpec],
    pub pto: &'static [PtoSpec],
    pub discrepancies: &'static [Discrepancy],
}

/// SM area size. The manual gives no size; the highest register it names is SMD262
/// (SMB262–SMB265). We use the S7-200's SMB0–SMB549, the layout the K2 follows.
pub const SM_BYTES: u32 = 550;
/// Timers T0–T255 and counters C0–C255 (§2.1.2).
pub const TIMERS: u32 = 256;
pub const COUNTERS: u32 = 256;
/// E2PROM backup area (§2.2.8): VB3648–VB4095, 448 bytes; VB3648–VB3902 by default.
pub const EEPROM_FIRST: u32 = 3648;
pub const EEPROM_LAST_DEFAULT: u32 = 3902;
pub const EEPROM_LAST_MAX: u32 = 4095;
/// The manual's E2PROM endurance (§2.2.8).
pub const EEPROM_ENDURANCE: u64 = 1_000_000;

const fn hsc(channel: u8, s: u32, ab: u32) -> HscSpec {
    HscSpec { channel, max_hz_single: s, max_hz_ab: ab }
}

const HSC_K205: &[HscSpec] =
    &[hsc(0, 50_000, 50_000), hsc(1, 50_000, 50_000), hsc(2, 20_000, 10_000), hsc(3, 20_000, 10_000)];
const HSC_200K: &[HscSpec] =
    &[hsc(0, 200_000, 200_000), hsc(1, 200_000, 200_000), hsc(2, 200_000, 200_000), hsc(3, 200_000, 200_000)];
const HSC_K209EA: &[HscSpec] =
    &[hsc(0, 200_000, 100_000), hsc(1, 200_000, 100_000), hsc(2, 20_000, 10_000), hsc(3, 20_000, 10_000)];
const HSC_K209M: &[HscSpec] = &[hsc(0, 200_000, 200_000), hsc(1, 200_000, 200_000)];

const fn pto(channel: u8, output: &'static str, direction: &'static str, max_hz: u32) -> PtoSpec {
    PtoSpec { channel, output, direction, max_hz }
}

const PTO_K205: &[PtoSpec] =
    &[pto(0, "Q0.0", "Q0.2", 50_000), pto(1, "Q0.1", "Q0.3", 50_000), pto(2, "Q0.4", "Q0.5", 10_000)];
const PTO_200K: &[PtoSpec] =
    &[pto(0, "Q0.0", "Q0.2", 200_000), pto(1, "Q0.1", "Q0.3", 200_000), pto(2, "Q0.4", "Q0.5", 200_000)];
const PTO_K209EA: &[PtoSpec] =
    &[pto(0, "Q0.0", "Q0.2", 200_000), pto(1, "Q0.1", "Q0.3", 200_000), pto(2, "Q0.4", "Q0.5", 10_000)];
const PTO_K209M: &[PtoSpec] = &[
    pto(0, "Q0.0", "Q0.2", 200_000),
    pto(1, "Q0.1", "Q0.3", 200_000),
    pto(2, "Q0.4", "Q0.6", 200_000),
    pto(3, "Q0.5", "Q0.7", 10_000),
];

const D_K204ET: &[Discrepancy] = &[
    Discrepancy {
        what: Phrase(|| msg!("tbl-model-k204et-1-what")),
        chosen: Phrase(|| msg!("tbl-model-k204et-1-chosen")),
        other: Phrase(|| msg!("tbl-model-k204et-1-other")),
    },
    Discrepancy {
        what: Phrase(|| msg!("tbl-model-k204et-2-what")),
        chosen: Phrase(|| msg!("tbl-model-k204et-2-chosen")),
        other: Phrase(|| msg!("tbl-model-k204et-2-other")),
    },
];
const D_K209EA: &[Discrepancy] = &[
    Discrepancy {
        what: Phrase(|| msg!("tbl-model-k209ea-1-what")),
        chosen: Phrase(|| msg!("tbl-model-k209ea-1-chosen")),
        other: Phrase(|| msg!("tbl-model-k209ea-1-other")),
    },
    Discrepancy {
        what: Phrase(|| msg!("tbl-model-k209ea-2-what")),
        chosen: Phrase(|| msg!("tbl-model-k209ea-2-chosen")),
        other: Phrase(|| msg!("tbl-model-k209ea-2-other")),
    },
];
const D_K205EA: &[Discrepancy] = &[Discrepancy {
    what: Phrase(|| msg!("tbl-model-k205ea-1-what")),
    chosen: Phrase(|| msg!("tbl-model-k205ea-1-chosen")),
    other: Phrase(|| msg!("tbl-model-k205ea-1-other")),
}];

/// Every catalogued model (§1.2).
pub static MODELS: &[Model] = &[
    Model {
        name: "K205-16DT",
        cpu: "CPU205",
        di: 6,
        dout: 6,
        dio: 4,
        ai: 0,
        ao: 0,
        i_bytes: 2,
        q_bytes: 2,
        m_bytes: 1024,
        v_bytes: 4096,
        ai_bytes: 0,
        aq_bytes: 0,
        relay: false,
        ethernet: false,
        serial: "2×RS485 (PORT1, PORT2)",
        program_kinstr: 4,
        retentive_bytes: 4096,
        hsc: HSC_K205,
        pto: PTO_K205,
        discrepancies: &[],
    },
    Model {
        name: "K205-16DR",
        cpu: "CPU205",
        di: 6,
        dout: 6,
        dio: 4,
        ai: 0,
        ao: 0,
        i_bytes: 2,
        q_bytes: 2,
        m_bytes: 1024,
        v_bytes: 4096,
        ai_bytes: 0,
        aq_bytes: 0,
        relay: true,
        ethernet: false,
        serial: "2×RS485 (PORT1, PORT2)",
        program_kinstr: 4,
        retentive_bytes: 4096,
        hsc: HSC_K205,
        pto: &[],
        discrepancies: &[],
    },
    Model {
        name: "K205EA-18DT",
        cpu: "CPU205EA",
        di: 8,
        dout: 8,
        dio: 0,
        ai: 1,
        ao: 1,
        i_bytes: 1,
        q_bytes: 1,
        m_bytes: 1024,
        v_bytes: 4096,
        ai_bytes: 2,
        aq_bytes: 2,
        relay: false,
        ethernet: false,
        serial: "2×RS485 (PORT1, PORT2)",
        program_kinstr: 4,
        retentive_bytes: 4096,
        hsc: HSC_200K,
        pto: PTO_200K,
        discrepancies: D_K205EA,
    },
    Model {
        name: "K205EX-22DT",
        cpu: "CPU205EX",
        di: 8,
        dout: 8,
        dio: 6,
        ai: 0,
        ao: 0,
        i_bytes: 2,
        q_bytes: 2,
        m_bytes: 1024,
        v_bytes: 4096,
        ai_bytes: 0,
        aq_bytes: 0,
        relay: false,
        ethernet: false,
        serial: "2×RS485 (PORT1, PORT2)",
        program_kinstr: 4,
        retentive_bytes: 4096,
        hsc: HSC_K205,
        pto: PTO_K205,
        discrepancies: &[],
    },
    Model {
        name: "K204ET-16DT",
        cpu: "CPU204",
        di: 8,
        dout: 6,
        dio: 0,
        ai: 1,
        ao: 1,
        i_bytes: 1,
        q_bytes: 1,
        m_bytes: 1024,
        v_bytes: 4096,
        ai_bytes: 2,
        aq_bytes: 2,
        relay: false,
        ethernet: true,
        serial: "2×RS485 (PORT1, PORT2); Ethernet (Modbus TCP server)",
        program_kinstr: 4,
        retentive_bytes: 2048,
        hsc: HSC_200K,
        pto: PTO_200K,
        discrepancies: D_K204ET,
    },
    Model {
        name: "K209EA-50DX",
        cpu: "CPU209EA",
        di: 22,
        dout: 20,
        dio: 0,
        ai: 6,
        ao: 2,
        i_bytes: 3,
        q_bytes: 3,
        m_bytes: 1024,
        v_bytes: 4096,
        ai_bytes: 12,
        aq_bytes: 4,
        relay: false,
        ethernet: false,
        serial: "RS232 (PORT0) + 2×RS485 (PORT1, PORT2)",
        program_kinstr: 4,
        retentive_bytes: 4096,
        hsc: HSC_K209EA,
        pto: PTO_K209EA,
        discrepancies: D_K209EA,
    },
    Model {
        name: "K209M-56DT",
        cpu: "CPU209M",
        di: 32,
        dout: 24,
        dio: 0,
        ai: 0,
        ao: 0,
        i_bytes: 4,
        q_bytes: 3,
        m_bytes: 4096,
        v_bytes: 16384,
        ai_bytes: 0,
        aq_bytes: 0,
        relay: false,
        ethernet: false,
        serial: "2×RS485 (PORT1, PORT2), 2×CAN; up to 14 expansion modules",
        program_kinstr: 8,
        retentive_bytes: 256,
        hsc: HSC_K209M,
        pto: PTO_K209M,
        discrepancies: &[],
    },
];

/// The model a plain `plcsh` simulates.
pub const DEFAULT_MODEL: &str = "K205-16DT";

/// Finds a model by name, case-insensitively; a unique prefix also matches (`k209m`).
pub fn find(name: &str) -> Option<&'static Model> {
    let n = name.to_ascii_uppercase();
    if let Some(m) = MODELS.iter().find(|m| m.name == n) {
        return Some(m);
    }
    let mut it = MODELS.iter().filter(|m| m.name.starts_with(&n));
    match (it.next(), it.next()) {
        (Some(m), None) => Some(m),
        _ => None,
    }
}

/// `find`, with an error that lists the catalogue.
pub fn lookup(name: &str) -> crate::core::Result<&'static Model> {
    find(name).ok_or_else(|| {
        crate::core::Error::usage(msg!("tbl-model-unknown", name = name))
            .hint(msg!("tbl-model-unknown-hint", models = MODELS.iter().map(|m| m.name).collect::<Vec<_>>().join(", ")))
    })
}

impl Model {
    pub fn hsc(&self, ch: u8) -> Option<&HscSpec> {
        self.hsc.iter().find(|h| h.channel == ch)
    }
    pub fn pto(&self, ch: u8) -> Option<&PtoSpec> {
        self.pto.iter().find(|p| p.channel == ch)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Every discrepancy's three texts are in every language, and every `tbl-model-k…` id of
    /// the catalogue belongs to a model's discrepancy.
    #[test]
    fn every_discrepancy_has_its_text_in_every_language() {
        use crate::core::msg::Lang;
        let used: Vec<&str> = MODELS
            .iter()
            .flat_map(|m| m.discrepancies)
            .flat_map(|d| [d.what, d.chosen, d.other])
            .map(|p| (p.0)().id)
            .collect();
        for lang in Lang::ALL {
            let ids = crate::core::msg::ids(*lang);
            for id in &used {
                assert!(ids.iter().any(|i| i == id), "{id} has no text in {}", lang.tag());
            }
        }
        for id in crate::core::msg::ids(Lang::En) {
            if id.starts_with("tbl-model-k") {
                assert!(used.contains(&id.as_str()), "{id} belongs to no discrepancy");
            }
        }
        assert_eq!(
            find("K205EA-18DT").unwrap().discrepancies[0].other.to_string(),
            "§2.2.6 and §3.4 do not list CPU205EA"
        );
    }

    #[test]
    fn relay_models_have_no_pulse_outputs() {
        for m in MODELS {
            assert_eq!(m.relay, m.pto.is_empty(), "{}", m.name);
            assert_eq!(m.relay, m.name.ends_with('R'), "{}", m.name);
        }
    }

    #[test]
    fn k209m_has_four_pulse_outputs_and_two_counters() {
        let m = find("K209M-56DT").unwrap();
        assert_eq!(m.pto.len(), 4);
        assert_eq!(m.pto(3).unwrap().output, "Q0.5");
        assert_eq!(m.hsc.len(), 2);
        assert_eq!(m.v_bytes, 16384);
    }

    #[test]
    fn disagreements_are_recorded_for_k204et_and_k209ea() {
        assert!(!find("K204ET-16DT").unwrap().discrepancies.is_empty());
        assert_eq!(find("K209EA-50DX").unwrap().pto(2).unwrap().max_hz, 10_000);
    }

    #[test]
    fn lookup_by_prefix_and_case() {
        assert_eq!(find("k205-16dt").unwrap().name, "K205-16DT");
        assert_eq!(find("K209M").unwrap().name, "K209M-56DT");
        assert!(find("K205").is_none(), "ambiguous prefix");
        assert!(lookup("K999").unwrap_err().hint.clone().unwrap().contains("K205-16DT"));
    }
}
