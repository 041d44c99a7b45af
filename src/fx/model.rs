//! FX models and their device ranges: the one table the operand space bounds-checks against
//! and the simulator sizes its memory from.
//!
//! Sources (public): the FX Series Programming Manual's device tables (FX1S, FX1N, FX2N(C)
//! columns: auxiliary relays M0–M511 / M0–M1535 / M0–M3071, states S0–S127 / S0–S999,
//! timers T0–T63 / T0–T255, counters C0–C31 + C235–C255 / C0–C255, data registers D0–D255 /
//! D0–D7999, special M8000–M8255 and D8000–D8255) and the FX3U MELSEC-F computer-link device
//! list (X0–X377, Y0–Y377, D0–D7999, C200–C255 32-bit). The FX3U row has the FX3U's own ranges
//! (M0–M7679, S0–S4095, T0–T511, C0–C255, D0–D7999: the FX3U programming manual's device list,
//! the same ranges the E-command address table covers, [`super::port::EXTENDED`]) and the
//! E-commands; FX1S, FX1N and FX2N speak the classic commands 0/1/7/8.

/// One model family's device ranges (counts of the ordinary devices, numbers 0 … n−1).
#[derive(Clone, Copy, Debug)]
pub struct Model {
    pub name: &'static str,
    /// Other names that select this row.
    pub aliases: &'static [&'static str],
    /// X and Y: device count (the octal numbering's value, X0–X17 = 16).
    pub x: u16,
    pub y: u16,
    pub m: u16,
    pub s: u16,
    pub t: u16,
    /// Counters C0 … c−1 (C200 and up are 32-bit).
    pub c: u16,
    pub d: u16,
    /// Answers the extended programming-port commands (E00/E10, E7/E8) and is read through
    /// their address table ([`super::port::Table::Extended`]).
    pub extended: bool,
    pub summary: &'static str,
}

/// Every model family plcsh knows.
pub static MODELS: &[Model] = &[
    Model {
        name: "FX1S",
        aliases: &[],
        x: 16,
        y: 14,
        m: 512,
        s: 128,
        t: 64,
        c: 256,
        d: 256,
        extended: false,
        summary: "X0–X17, Y0–Y15, M0–M511, S0–S127, T0–T63, C0–C31 and C235–C255, D0–D255",
    },
    Model {
        name: "FX1N",
        aliases: &[],
        x: 128,
        y: 128,
        m: 1536,
        s: 1000,
        t: 256,
        c: 256,
        d: 8000,
        extended: false,
        summary: "X0–X177, Y0–Y177, M0–M1535, S0–S999, T0–T255, C0–C255, D0–D7999",
    },
    Model {
        name: "FX2N",
        aliases: &["FX2NC"],
        x: 256,
        y: 256,
        m: 3072,
        s: 1000,
        t: 256,
        c: 256,
        d: 8000,
        extended: false,
        summary: "X0–X377, Y0–Y377, M0–M3071, S0–S999, T0–T255, C0–C255, D0–D7999",
    },
    Model {
        name: "FX3U",
        aliases: &["FX3UC"],
        x: 256,
        y: 256,
        m: 7680,
        s: 4096,
        t: 512,
        c: 256,
        d: 8000,
        extended: true,
        summary: "X0–X377, Y0–Y377, M0–M7679, S0–S4095, T0–T511, C0–C255, D0–D7999; E-commands",
    },
];

/// Counters on an FX1S: C0–C31 and the high-speed counters C235–C255.
pub fn fx1s_counter(n: u16) -> bool {
    n < 32 || (235..=255).contains(&n)
}

impl Model {
    /// Finds a model by name or alias (case-insensitive).
    pub fn find(name: &str) -> Option<&'static Model> {
        let up = name.trim().to_ascii_uppercase();
        MODELS.iter().find(|m| m.name == up || m.aliases.contains(&up.as_str()))
    }

    /// Names, for messages.
    pub fn names() -> String {
        MODELS.iter().map(|m| m.name).collect::<Vec<_>>().join(", ")
    }
}
