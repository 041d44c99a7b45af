//! The UMPK models and their sizes, as one data table (manual Table 1, §3.3–§3.5; digest
//! `../shared/spec/umpk.md` §1). Every bound elsewhere — operand ranges, program memory in
//! HEX validation and in the simulated flash, the controller-info counts — derives from
//! [`MODELS`].
//!
//! The manual contradicts itself on the UMPK8's inputs: Table 1 says 16 for both models,
//! §3.3 says "УМПК8 имеет 8". We follow §3.3 (8), as the digest does: the UMPK8 board
//! has eight input terminals.
//!
//! The model code MM in the controller-info reply (§4.1.4) is only given for the "ТК-2-64"
//! (02). We report 0x08 for the UMPK8 and 0x10 for the UMPK16 (our choice) and identify a
//! real controller by its input count II, which the manual does define.

/// Flash page size: the unit a data record should carry (§4.2.1).
pub const PAGE: usize = 64;

/// One model's sizes.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct Model {
    pub name: &'static str,
    /// The MM byte our simulator reports (see the module doc).
    pub code: u8,
    pub inputs: u8,
    pub outputs: u8,
    pub markers: u8,
    pub timers: u8,
    pub counters: u8,
    /// User program memory in bytes (Table 1 row 10).
    pub program_bytes: usize,
}

/// Both models (Table 1; §3.3 for the UMPK8's inputs).
pub static MODELS: &[Model] = &[
    Model {
        name: "UMPK8",
        code: 0x08,
        inputs: 8,
        outputs: 4,
        markers: 32,
        timers: 8,
        counters: 4,
        program_bytes: 2048,
    },
    Model {
        name: "UMPK16",
        code: 0x10,
        inputs: 16,
        outputs: 8,
        markers: 64,
        timers: 16,
        counters: 4,
        program_bytes: 3072,
    },
];

/// The model called `name` (case-insensitive; `umpk16`, `UMPK16`, `16`).
pub fn find(name: &str) -> Option<&'static Model> {
    let n = name.trim().to_ascii_uppercase();
    let n = n.strip_prefix("UMPK").unwrap_or(&n);
    MODELS.iter().find(|m| &m.name[4..] == n)
}

/// The model a controller-info reply describes: by its input count, then by our MM code.
pub fn from_info(code: u8, inputs: u8) -> Option<&'static Model> {
    MODELS.iter().find(|m| m.inputs == inputs).or_else(|| MODELS.iter().find(|m| m.code == code))
}

/// `UMPK8, UMPK16` for messages.
pub fn names() -> String {
    MODELS.iter().map(|m| m.name).collect::<Vec<_>>().join(", ")
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn sizes_follow_table_1_and_section_3_3() {
        let m8 = find("umpk8").unwrap();
        assert_eq!((m8.inputs, m8.outputs, m8.markers, m8.timers, m8.counters), (8, 4, 32, 8, 4));
        assert_eq!(m8.program_bytes, 2 * 1024);
        let m16 = find("UMPK16").unwrap();
        assert_eq!((m16.inputs, m16.outputs, m16.markers, m16.timers, m16.counters), (16, 8, 64, 16, 4));
        assert_eq!(m16.program_bytes, 3 * 1024);
        assert!(find("UMPK32").is_none());
        assert_eq!(from_info(0x02, 16).unwrap().name, "UMPK16", "identified by II, whatever MM says");
    }
}
