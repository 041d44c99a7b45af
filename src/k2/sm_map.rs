//! The K2's special-memory (SM) registers, per channel (`../shared/spec/k2.md` §4–§6, §8;
//! manual §3.3.2, §3.4.2.2, §3.4.3.1). One table of addresses per channel kind, used by
//! the simulator, the typed helpers, `help`, hints and completion — no SM address is
//! written anywhere else.

/// Registers of one pulse output channel (PTO/PWM, §3.4.2.2) and its position channel (§3.4.3.1).
#[derive(Clone, Copy, Debug)]
pub struct PtoRegs {
    pub channel: u8,
    /// SMB67 … control byte.
    pub control: u32,
    /// SMB66 … status byte.
    pub status: u32,
    /// SMW68 … cycle time.
    pub cycle: u32,
    /// SMW70 … PWM pulse width.
    pub width: u32,
    /// SMD72 … PTO pulse count.
    pub count: u32,
    /// SMW168 … multi-segment profile table start (odd V offset).
    pub profile: u32,
    /// SMD212 … position current value (read-only).
    pub pos_cv: u32,
    /// SMD208 … new current value.
    pub pos_new_cv: u32,
    /// SMB201 … position control byte.
    pub pos_control: u32,
}

/// PTO0 (Q0.0), PTO1 (Q0.1), PTO2 (Q0.4), PTO3 (Q0.5, K209M only).
/// The manual's text also names SMW268 for PTO2's profile start; its table says SMW218,
/// which we use (SMW268 would collide with nothing else, but the table is authoritative).
pub static PTO_REGS: [PtoRegs; 4] = [
    PtoRegs {
        channel: 0,
        control: 67,
        status: 66,
        cycle: 68,
        width: 70,
        count: 72,
        profile: 168,
        pos_cv: 212,
        pos_new_cv: 208,
        pos_control: 201,
    },
    PtoRegs {
        channel: 1,
        control: 77,
        status: 76,
        cycle: 78,
        width: 80,
        count: 82,
        profile: 178,
        pos_cv: 242,
        pos_new_cv: 238,
        pos_control: 231,
    },
    PtoRegs {
        channel: 2,
        control: 97,
        status: 96,
        cycle: 98,
        width: 100,
        count: 102,
        profile: 218,
        pos_cv: 262,
        pos_new_cv: 258,
        pos_control: 251,
    },
    PtoRegs {
        channel: 3,
        control: 107,
        status: 106,
        cycle: 108,
        width: 110,
        count: 112,
        profile: 248,
        pos_cv: 226,
        pos_new_cv: 222,
        pos_control: 221,
    },
];

/// The rule a refused PLS breaks, in the manual's words (§3.4.2.2, status bit 4: «Время
/// цикла и количество импульсов должны быть больше 1»). The simulator's refusal and the
/// helper's report of status bit 4 both quote it, so a user reads one explanation.
pub const PTO_INVALID_RULE: &str = "cycle and count must both be > 1, §3.4.2.2";

/// Why a write that meets `r`'s current value SMD212 … is refused (§3.4.3.1: «Только для
/// чтения»), and how to set it instead: (message, hint). `written` names what was written
/// (`SMD212`, `SMB212…SMB215`). In process and through the helper alike.
pub fn pos_cv_read_only(r: &PtoRegs, written: &str) -> (String, String) {
    let msg = if written == format!("SMD{}", r.pos_cv) {
        format!("SMD{} is the read-only current value of position channel {} (manual §3.4.3.1)", r.pos_cv, r.channel)
    } else {
        format!(
            "{written} overlaps SMD{}, the read-only current value of position channel {} (manual §3.4.3.1)",
            r.pos_cv, r.channel
        )
    };
    let hint = format!(
        "load a new value through SMD{} and SM{}.4 (set SMD{}=100, SM{}.4=1), or clear it with SM{}.6",
        r.pos_new_cv, r.pos_control, r.pos_new_cv, r.pos_control, r.pos_control
    );
    (msg, hint)
}

/// Why PLS did nothing: the channel's enable bit (SM67.7 …) is clear and it is idle, so
/// there was nothing to stop and nothing started (§3.4.2.2): (message, hint). In process and
/// through the helper alike.
pub fn pls_did_nothing(r: &PtoRegs) -> (String, String) {
    (
        format!(
            "PLS {} did nothing: the enable bit SM{}.7 of the control byte SMB{} is clear and PTO{} is idle",
            r.channel, r.control, r.control, r.channel
        ),
        format!(
            "set SMB{}=16#85 (enable, PTO, update cycle and count), SMW{} and SMD{}, then PLS {}",
            r.control, r.cycle, r.count, r.channel
        ),
    )
}

/// Why a write to SMB0 is refused: (message, hint).
pub fn smb0_read_only(written: &str) -> (String, String) {
    (
        format!("{written} holds the system status bits and is read-only"),
        "SM0.0 is always on, SM0.1 marks the first scan, SM0.5 is the 1-second clock".to_string(),
    )
}

/// Registers of one high-speed counter (§3.3.2, §3.3.3).
#[derive(Clone, Copy, Debug)]
pub struct HscRegs {
    pub channel: u8,
    /// SMB37 … control byte.
    pub control: u32,
    /// SMB36 … status byte.
    pub status: u32,
    /// SMD38 … current value.
    pub cv: u32,
    /// SMD42 … preset value (single-PV mode).
    pub pv: u32,
    /// SMB141 … multi-PV control byte.
    pub mpv_control: u32,
    /// SMW142 … PV table start (odd V offset).
    pub table: u32,
    /// SMB140 … current PV segment number.
    pub segment: u32,
    /// First multi-PV "CV = PV" event number (§3.3.4): PV k raises `event_base + k − 1`.
    pub event_base: u8,
}

/// HSC0–HSC3. The manual prints SM57.3 for HSC3's direction bit; by the control-byte
/// table it is SM127.3, which we use.
pub static HSC_REGS: [HscRegs; 4] = [
    HscRegs {
        channel: 0,
        control: 37,
        status: 36,
        cv: 38,
        pv: 42,
        mpv_control: 141,
        table: 142,
        segment: 140,
        event_base: 64,
    },
    HscRegs {
        channel: 1,
        control: 47,
        status: 46,
        cv: 48,
        pv: 52,
        mpv_control: 151,
        table: 152,
        segment: 150,
        event_base: 96,
    },
    HscRegs {
        channel: 2,
        control: 57,
        status: 56,
        cv: 58,
        pv: 62,
        mpv_control: 161,
        table: 162,
        segment: 160,
        event_base: 128,
    },
    HscRegs {
        channel: 3,
        control: 127,
        status: 126,
        cv: 128,
        pv: 132,
        mpv_control: 171,
        table: 172,
        segment: 170,
        event_base: 160,
    },
];

/// SM double words that hold signed counts (DINT): the position channels' current and new
/// current values (§3.4.3.1: "DINT … +forward / −reverse") and the counters' current and
/// preset values (§3.3.2: a counter counting down goes below zero). Read as DINT by default.
pub fn is_signed_dword(byte: u32) -> bool {
    PTO_REGS.iter().any(|r| r.pos_cv == byte || r.pos_new_cv == byte)
        || HSC_REGS.iter().any(|r| r.cv == byte || r.pv == byte)
}

/// Size of a named SM register.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum SmSize {
    Bit(u8),
    Byte,
    Word,
    DWord,
}

/// A named SM register: canonical operand text, meaning and manual section.
#[derive(Clone, Debug)]
pub struct SmName {
    pub byte: u32,
    pub size: SmSize,
    pub meaning: String,
    pub section: &'static str,
}

impl SmName {
    /// The canonical operand (`SMB67`, `SM0.1`).
    pub fn operand(&self) -> String {
        match self.size {
            SmSize::Bit(b) => format!("SM{}.{}", self.byte, b),
            SmSize::Byte => format!("SMB{}", self.byte),
            SmSize::Word => format!("SMW{}", self.byte),
            SmSize::DWord => format!("SMD{}", self.byte),
        }
    }
    pub fn len(&self) -> u32 {
        match self.size {
            SmSize::Bit(_) | SmSize::Byte => 1,
            SmSize::Word => 2,
            SmSize::DWord => 4,
        }
    }
    pub fn is_empty(&self) -> bool {
        false
    }
}

/// The HSC operating modes per channel and their inputs (§3.3.1).
pub static HSC_MODES: &[(u8, u8, &str)] = &[
    (0, 0, "count I0.1, direction by SM37.3"),
    (0, 1, "count I0.1, reset I0.0, direction by SM37.3"),
    (0, 2, "count I0.1, reset I0.0, start I0.5, direction by SM37.3"),
    (0, 3, "count I0.1, direction input I0.5"),
    (0, 4, "count I0.1, direction input I0.5, reset I0.0"),
    (0, 6, "up I0.0 / down I0.1 (two-pulse)"),
    (0, 9, "A/B quadrature, A = I0.1, B = I0.0"),
    (1, 0, "count I0.3, direction by SM47.3"),
    (1, 1, "count I0.3, reset I0.4, direction by SM47.3"),
    (1, 2, "count I0.3, reset I0.4, start I0.6, direction by SM47.3"),
    (1, 3, "count I0.3, direction input I0.2"),
    (1, 4, "count I0.3, direction input I0.2, reset I0.4"),
    (1, 6, "up I0.2 / down I0.3 (two-pulse)"),
    (1, 7, "up I0.2 / down I0.3 (two-pulse), reset I0.4"),
    (1, 9, "A/B quadrature, A = I0.3, B = I0.2"),
    (1, 10, "A/B quadrature, A = I0.3, B = I0.2, reset I0.4"),
    (2, 0, "count I0.5, direction by SM57.3"),
    (2, 9, "A/B quadrature, A = I0.4, B = I0.5"),
    (3, 0, "count I0.7, direction by SM127.3"),
    (3, 9, "A/B quadrature, A = I0.6, B = I0.7"),
];

/// How a counter mode takes its count (§3.3.1).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum HscKind {
    /// One count input, direction from the control byte (SM37.3 …).
    InternalDir,
    /// One count input, direction from an input (1 = up).
    ExternalDir,
    /// Two inputs: one counts up, one counts down.
    TwoPulse,
    /// A/B quadrature (1x or 4x by SM37.2 …).
    Quadrature,
}

/// The inputs of one counter mode (§3.3.1), as bit addresses in the I area (byte, bit).
/// `count` is the count input (modes 0–4), the up input (modes 6/7) or A (modes 9/10);
/// `second` is the down input (6/7) or B (9/10).
#[derive(Clone, Copy, Debug)]
pub struct HscModeInputs {
    pub channel: u8,
    pub mode: u8,
    pub kind: HscKind,
    pub count: (u32, u8),
    pub second: Option<(u32, u8)>,
    pub dir: Option<(u32, u8)>,
    pub reset: Option<(u32, u8)>,
    pub start: Option<(u32, u8)>,
}

/// `pins` = [second, dir, reset, start] as bits of IB0.
const fn mi(channel: u8, mode: u8, kind: HscKind, count: u8, pins: [Option<u8>; 4]) -> HscModeInputs {
    let [second, dir, reset, start] = pins;
    // Every HSC input is in IB0 (§3.3.1).
    const fn pin(b: Option<u8>) -> Option<(u32, u8)> {
        match b {
            Some(b) => Some((0, b)),
            None => None,
        }
    }
    HscModeInputs {
        channel,
        mode,
        kind,
        count: (0, count),
        second: pin(second),
        dir: pin(dir),
        reset: pin(reset),
        start: pin(start),
    }
}

/// The same modes as [`HSC_MODES`], structured for the simulator (§3.3.1 tables; the
/// unit test below keeps the two in step). HSC0 mode 6: up I0.0, down I0.1; HSC1 mode 6:
/// up I0.2, down I0.3 (the manual's columns "Счёт вверх"/"Счёт вниз").
pub static HSC_MODE_INPUTS: &[HscModeInputs] = {
    use HscKind::*;
    &[
        mi(0, 0, InternalDir, 1, [None, None, None, None]),
        mi(0, 1, InternalDir, 1, [None, None, Some(0), None]),
        mi(0, 2, InternalDir, 1, [None, None, Some(0), Some(5)]),
        mi(0, 3, ExternalDir, 1, [None, Some(5), None, None]),
        mi(0, 4, ExternalDir, 1, [None, Some(5), Some(0), None]),
        mi(0, 6, TwoPulse, 0, [Some(1), None, None, None]),
        mi(0, 9, Quadrature, 1, [Some(0), None, None, None]),
        mi(1, 0, InternalDir, 3, [None, None, None, None]),
        mi(1, 1, InternalDir, 3, [None, None, Some(4), None]),
        mi(1, 2, InternalDir, 3, [None, None, Some(4), Some(6)]),
        mi(1, 3, ExternalDir, 3, [None, Some(2), None, None]),
        mi(1, 4, ExternalDir, 3, [None, Some(2), Some(4), None]),
        mi(1, 6, TwoPulse, 2, [Some(3), None, None, None]),
        mi(1, 7, TwoPulse, 2, [Some(3), None, Some(4), None]),
        mi(1, 9, Quadrature, 3, [Some(2), None, None, None]),
        mi(1, 10, Quadrature, 3, [Some(2), None, Some(4), None]),
        mi(2, 0, InternalDir, 5, [None, None, None, None]),
        mi(2, 9, Quadrature, 4, [Some(5), None, None, None]),
        mi(3, 0, InternalDir, 7, [None, None, None, None]),
        mi(3, 9, Quadrature, 6, [Some(7), None, None, None]),
    ]
};

/// The inputs of counter `channel` in `mode`, if the manual lists that mode.
pub fn hsc_mode(channel: u8, mode: u8) -> Option<&'static HscModeInputs> {
    HSC_MODE_INPUTS.iter().find(|m| m.channel == channel && m.mode == mode)
}

/// The modes the manual lists for counter `channel`.
pub fn hsc_modes_of(channel: u8) -> Vec<u8> {
    HSC_MODE_INPUTS.iter().filter(|m| m.channel == channel).map(|m| m.mode).collect()
}

/// Every named SM register, generated from the channel tables above plus the system bits.
pub fn names() -> &'static [SmName] {
    use std::sync::OnceLock;
    static NAMES: OnceLock<Vec<SmName>> = OnceLock::new();
    NAMES.get_or_init(build_names)
}

fn build_names() -> Vec<SmName> {
    let mut v = Vec::new();
    let mut add = |byte: u32, size: SmSize, meaning: String, section: &'static str| {
        v.push(SmName { byte, size, meaning, section })
    };
    // The first status byte: SM0.0 and SM0.1 as the manual's PTO/PWM examples use them
    // (§3.4.2.3, §3.4.2.4; the digest's §8), the rest by the S7-200 convention Kinco's public
    // notes follow. The texts are shown to users (`help SM0.1`): they cite what the user has.
    let ex = "§3.4.2.3, §3.4.2.4 (the manual's examples; S7-200 convention)";
    add(0, SmSize::Byte, "system status bits (read-only)".into(), ex);
    add(0, SmSize::Bit(0), "always on".into(), ex);
    add(0, SmSize::Bit(1), "on during the first scan only".into(), ex);
    add(0, SmSize::Bit(5), "1-second clock (0.5 s on, 0.5 s off)".into(), "S7-200 convention (KincoBuilder's help)");
    add(0, SmSize::Bit(6), "toggles every scan".into(), "S7-200 convention (KincoBuilder's help)");
    for r in PTO_REGS {
        let n = r.channel;
        let q = ["Q0.0", "Q0.1", "Q0.4", "Q0.5"][n as usize];
        let s = "§3.4.2.2";
        add(r.control, SmSize::Byte, format!("PTO{n}/PWM{n} ({q}) control byte"), s);
        for (bit, m) in [
            (0, "update cycle time"),
            (1, "update pulse width (PWM)"),
            (2, "update pulse count (PTO)"),
            (3, "time base: 0 = 1 µs, 1 = 1 ms"),
            (4, "PWM update: 0 async, 1 sync"),
            (5, "PTO mode: 0 single, 1 multi-segment"),
            (6, "function: 0 PTO, 1 PWM"),
            (7, "enable"),
        ] {
            add(r.control, SmSize::Bit(bit), format!("PTO{n} control: {m}"), s);
        }
        add(r.status, SmSize::Byte, format!("PTO{n}/PWM{n} ({q}) status byte"), s);
        for (bit, m) in [
            (3, "PWM idle"),
            (4, "cycle time or pulse count invalid (must be > 1)"),
            (5, "profile aborted by user command"),
            (7, "PTO idle"),
        ] {
            add(r.status, SmSize::Bit(bit), format!("PTO{n} status: {m}"), s);
        }
        add(r.cycle, SmSize::Word, format!("PTO{n}/PWM{n} cycle time (2…65535, in the time base)"), s);
        add(r.width, SmSize::Word, format!("PWM{n} pulse width (0…65535, in the time base)"), s);
        add(r.count, SmSize::DWord, format!("PTO{n} pulse count (≥ 2)"), s);
        add(r.profile, SmSize::Word, format!("PTO{n} multi-segment profile table start (odd V offset)"), s);
        let p = "§3.4.3.1";
        add(r.pos_cv, SmSize::DWord, format!("position channel {n} current value, pulses (read-only)"), p);
        add(
            r.pos_new_cv,
            SmSize::DWord,
            format!("position channel {n} new current value (loaded by bit 4 of SMB{})", r.pos_control),
            p,
        );
        add(r.pos_control, SmSize::Byte, format!("position channel {n} control byte"), p);
        for (bit, m) in [
            (7, "emergency stop latched (set by PSTOP)"),
            (6, "clear current value"),
            (4, "load the new current value"),
            (3, "direction output disable"),
        ] {
            add(r.pos_control, SmSize::Bit(bit), format!("position channel {n} control: {m}"), p);
        }
    }
    for r in HSC_REGS {
        let n = r.channel;
        let s = "§3.3.2";
        add(r.control, SmSize::Byte, format!("HSC{n} control byte"), s);
        for (bit, m) in [
            (0, "reset active level (0 high, 1 low)"),
            (1, "start active level (0 high, 1 low)"),
            (2, "quadrature rate (0 = 1x, 1 = 4x)"),
            (3, "count direction (0 down, 1 up)"),
            (4, "write the count direction"),
            (5, "write the new preset value"),
            (6, "write the new current value"),
            (7, "enable"),
        ] {
            add(r.control, SmSize::Bit(bit), format!("HSC{n} control: {m}"), s);
        }
        add(r.status, SmSize::Byte, format!("HSC{n} status byte"), s);
        for (bit, m) in [(3, "multi-PV table fault"), (5, "current direction (1 up)"), (6, "CV = PV"), (7, "CV > PV")] {
            add(r.status, SmSize::Bit(bit), format!("HSC{n} status: {m}"), s);
        }
        add(r.cv, SmSize::DWord, format!("HSC{n} current value (CV)"), s);
        add(r.pv, SmSize::DWord, format!("HSC{n} preset value (PV, single-PV mode)"), s);
        let t = "§3.3.3";
        add(r.mpv_control, SmSize::Byte, format!("HSC{n} multi-PV control byte"), t);
        for (bit, m) in [
            (0, "use multiple PVs"),
            (1, "PV type (0 absolute, 1 relative)"),
            (2, "cyclic CV=PV interrupts (relative only)"),
            (4, "load the PV table"),
            (5, "reset interrupt variable (0 yes, 1 no)"),
        ] {
            add(r.mpv_control, SmSize::Bit(bit), format!("HSC{n} multi-PV control: {m}"), t);
        }
        add(r.table, SmSize::Word, format!("HSC{n} PV table start (odd V offset)"), t);
        add(r.segment, SmSize::Byte, format!("HSC{n} current PV segment number (from 0)"), t);
    }
    v
}

/// The named register that is exactly this operand, if any.
pub fn lookup(byte: u32, size: SmSize) -> Option<&'static SmName> {
    names().iter().find(|n| n.byte == byte && n.size == size)
}

/// Named registers (bytes, words, double words) that overlap `byte..byte+len`.
pub fn overlapping(byte: u32, len: u32) -> Vec<&'static SmName> {
    names()
        .iter()
        .filter(|n| !matches!(n.size, SmSize::Bit(_)))
        .filter(|n| n.byte < byte + len && byte < n.byte + n.len())
        .collect()
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn pto0_registers_match_the_manual() {
        assert_eq!(lookup(67, SmSize::Byte).unwrap().meaning, "PTO0/PWM0 (Q0.0) control byte");
        assert!(lookup(72, SmSize::DWord).unwrap().meaning.contains("pulse count"));
        assert!(lookup(66, SmSize::Bit(7)).unwrap().meaning.contains("idle"));
        assert!(lookup(127, SmSize::Bit(3)).unwrap().meaning.contains("HSC3"));
    }

    #[test]
    fn no_two_registers_of_one_size_share_an_address() {
        let n = names();
        for (i, a) in n.iter().enumerate() {
            for b in &n[i + 1..] {
                assert!(!(a.byte == b.byte && a.size == b.size), "{} twice", a.operand());
            }
        }
    }

    #[test]
    fn structured_modes_match_the_text_table() {
        assert_eq!(HSC_MODES.len(), HSC_MODE_INPUTS.len());
        for &(ch, mode, text) in HSC_MODES {
            let m = hsc_mode(ch, mode).unwrap_or_else(|| panic!("HSC{ch} mode {mode} missing"));
            let pin = |p: (u32, u8)| format!("I{}.{}", p.0, p.1);
            assert!(text.contains(&pin(m.count)), "HSC{ch} mode {mode}: {text}");
            for p in [m.second, m.dir, m.reset, m.start].into_iter().flatten() {
                assert!(text.contains(&pin(p)), "HSC{ch} mode {mode}: {text} lacks {}", pin(p));
            }
            let word = match m.kind {
                HscKind::InternalDir => "direction by",
                HscKind::ExternalDir => "direction input",
                HscKind::TwoPulse => "two-pulse",
                HscKind::Quadrature => "quadrature",
            };
            assert!(text.contains(word), "HSC{ch} mode {mode}: {text}");
        }
        // Mode 6's up input is listed first in the text.
        assert!(HSC_MODES.iter().any(|m| m.0 == 0 && m.1 == 6 && m.2.starts_with("up I0.0")));
    }

    #[test]
    fn overlap_finds_neighbours() {
        let o: Vec<String> = overlapping(67, 2).iter().map(|n| n.operand()).collect();
        assert!(o.contains(&"SMB67".to_string()) && o.contains(&"SMW68".to_string()), "{o:?}");
    }
}
