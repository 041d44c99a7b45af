//! The K2's special-memory (SM) registers, per channel (`../shared/spec/k2.md` §4–§6, §8;
//! manual §3.3.2, §3.4.2.2, §3.4.3.1). One table of addresses per channel kind, used by
//! the simulator, the typed helpers, `help`, hints and completion — no SM address is
//! written anywhere else. The registers' meanings, the counter modes and the refusals are
//! read in the user's language from the catalogue (`tables.ftl`, ids `tbl-sm-…`, `tbl-hsc-mode-…`).

use crate::core::msg::{Lang, Msg};
use crate::msg;

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
        msg!("tbl-sm-pos-cv-read-only", cv = r.pos_cv, n = r.channel)
    } else {
        msg!("tbl-sm-pos-cv-overlap", written = written, cv = r.pos_cv, n = r.channel)
    };
    let hint = msg!("tbl-sm-pos-cv-read-only-hint", new = r.pos_new_cv, control = r.pos_control);
    (msg.text, hint.text)
}

/// Why PLS did nothing: the channel's enable bit (SM67.7 …) is clear and it is idle, so
/// there was nothing to stop and nothing started (§3.4.2.2): (message, hint). In process and
/// through the helper alike.
pub fn pls_did_nothing(r: &PtoRegs) -> (String, String) {
    (
        msg!("tbl-sm-pls-did-nothing", n = r.channel, control = r.control).text,
        msg!("tbl-sm-pls-did-nothing-hint", n = r.channel, control = r.control, cycle = r.cycle, count = r.count).text,
    )
}

/// Why a write to SMB0 is refused: (message, hint).
pub fn smb0_read_only(written: &str) -> (String, String) {
    (msg!("tbl-sm-smb0-read-only", written = written).text, msg!("tbl-sm-smb0-read-only-hint").text)
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

/// A named SM register: canonical operand text, meaning (in the language the table was
/// built in, and its catalogue id) and manual section.
#[derive(Clone, Debug)]
pub struct SmName {
    pub byte: u32,
    pub size: SmSize,
    pub meaning: String,
    pub meaning_id: &'static str,
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

/// The HSC operating modes per channel and their inputs (§3.3.1): (counter, mode, its
/// description in a language — `Lang::En` where the text goes into a program's comments).
#[allow(clippy::type_complexity)] // one table row: counter, mode, text
pub static HSC_MODES: &[(u8, u8, fn(Lang) -> Msg)] = &[
    (0, 0, |l| msg!(lang: l, "tbl-hsc-mode-0-0")),
    (0, 1, |l| msg!(lang: l, "tbl-hsc-mode-0-1")),
    (0, 2, |l| msg!(lang: l, "tbl-hsc-mode-0-2")),
    (0, 3, |l| msg!(lang: l, "tbl-hsc-mode-0-3")),
    (0, 4, |l| msg!(lang: l, "tbl-hsc-mode-0-4")),
    (0, 6, |l| msg!(lang: l, "tbl-hsc-mode-0-6")),
    (0, 9, |l| msg!(lang: l, "tbl-hsc-mode-0-9")),
    (1, 0, |l| msg!(lang: l, "tbl-hsc-mode-1-0")),
    (1, 1, |l| msg!(lang: l, "tbl-hsc-mode-1-1")),
    (1, 2, |l| msg!(lang: l, "tbl-hsc-mode-1-2")),
    (1, 3, |l| msg!(lang: l, "tbl-hsc-mode-1-3")),
    (1, 4, |l| msg!(lang: l, "tbl-hsc-mode-1-4")),
    (1, 6, |l| msg!(lang: l, "tbl-hsc-mode-1-6")),
    (1, 7, |l| msg!(lang: l, "tbl-hsc-mode-1-7")),
    (1, 9, |l| msg!(lang: l, "tbl-hsc-mode-1-9")),
    (1, 10, |l| msg!(lang: l, "tbl-hsc-mode-1-10")),
    (2, 0, |l| msg!(lang: l, "tbl-hsc-mode-2-0")),
    (2, 9, |l| msg!(lang: l, "tbl-hsc-mode-2-9")),
    (3, 0, |l| msg!(lang: l, "tbl-hsc-mode-3-0")),
    (3, 9, |l| msg!(lang: l, "tbl-hsc-mode-3-9")),
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

/// Every named SM register, generated from the channel tables above plus the system bits,
/// with the meanings in the current language (one table per language, built when first asked).
pub fn names() -> &'static [SmName] {
    use std::sync::OnceLock;
    static NAMES: [OnceLock<Vec<SmName>>; 3] = [OnceLock::new(), OnceLock::new(), OnceLock::new()];
    let at = Lang::ALL.iter().position(|l| *l == crate::core::msg::language()).unwrap_or(0);
    NAMES[at].get_or_init(build_names)
}

fn build_names() -> Vec<SmName> {
    let mut v = Vec::new();
    let mut add = |byte: u32, size: SmSize, meaning: Msg, section: &'static str| {
        v.push(SmName { byte, size, meaning_id: meaning.id, meaning: meaning.text, section })
    };
    // The first status byte: SM0.0 and SM0.1 as the manual's PTO/PWM examples use them
    // (§3.4.2.3, §3.4.2.4; the digest's §8), the rest by the S7-200 convention Kinco's public
    // notes follow. The texts are shown to users (`help SM0.1`): they cite what the user has.
    let ex = "§3.4.2.3, §3.4.2.4 (the manual's examples; S7-200 convention)";
    let s7 = "S7-200 convention (KincoBuilder's help)";
    add(0, SmSize::Byte, msg!("tbl-sm-smb0"), ex);
    add(0, SmSize::Bit(0), msg!("tbl-sm-sm0-0"), ex);
    add(0, SmSize::Bit(1), msg!("tbl-sm-sm0-1"), ex);
    add(0, SmSize::Bit(5), msg!("tbl-sm-sm0-5"), s7);
    add(0, SmSize::Bit(6), msg!("tbl-sm-sm0-6"), s7);
    for r in PTO_REGS {
        let n = r.channel;
        let q = ["Q0.0", "Q0.1", "Q0.4", "Q0.5"][n as usize];
        let s = "§3.4.2.2";
        add(r.control, SmSize::Byte, msg!("tbl-sm-pto-control", n = n, q = q), s);
        for (bit, m) in [
            (0, msg!("tbl-sm-pto-control-0", n = n)),
            (1, msg!("tbl-sm-pto-control-1", n = n)),
            (2, msg!("tbl-sm-pto-control-2", n = n)),
            (3, msg!("tbl-sm-pto-control-3", n = n)),
            (4, msg!("tbl-sm-pto-control-4", n = n)),
            (5, msg!("tbl-sm-pto-control-5", n = n)),
            (6, msg!("tbl-sm-pto-control-6", n = n)),
            (7, msg!("tbl-sm-pto-control-7", n = n)),
        ] {
            add(r.control, SmSize::Bit(bit), m, s);
        }
        add(r.status, SmSize::Byte, msg!("tbl-sm-pto-status", n = n, q = q), s);
        for (bit, m) in [
            (3, msg!("tbl-sm-pto-status-3", n = n)),
            (4, msg!("tbl-sm-pto-status-4", n = n)),
            (5, msg!("tbl-sm-pto-status-5", n = n)),
            (7, msg!("tbl-sm-pto-status-7", n = n)),
        ] {
            add(r.status, SmSize::Bit(bit), m, s);
        }
        add(r.cycle, SmSize::Word, msg!("tbl-sm-pto-cycle", n = n), s);
        add(r.width, SmSize::Word, msg!("tbl-sm-pwm-width", n = n), s);
        add(r.count, SmSize::DWord, msg!("tbl-sm-pto-count", n = n), s);
        add(r.profile, SmSize::Word, msg!("tbl-sm-pto-profile", n = n), s);
        let p = "§3.4.3.1";
        add(r.pos_cv, SmSize::DWord, msg!("tbl-sm-pos-cv", n = n), p);
        add(r.pos_new_cv, SmSize::DWord, msg!("tbl-sm-pos-new-cv", n = n, control = r.pos_control), p);
        add(r.pos_control, SmSize::Byte, msg!("tbl-sm-pos-control", n = n), p);
        for (bit, m) in [
            (7, msg!("tbl-sm-pos-control-7", n = n)),
            (6, msg!("tbl-sm-pos-control-6", n = n)),
            (4, msg!("tbl-sm-pos-control-4", n = n)),
            (3, msg!("tbl-sm-pos-control-3", n = n)),
        ] {
            add(r.pos_control, SmSize::Bit(bit), m, p);
        }
    }
    for r in HSC_REGS {
        let n = r.channel;
        let s = "§3.3.2";
        add(r.control, SmSize::Byte, msg!("tbl-sm-hsc-control", n = n), s);
        for (bit, m) in [
            (0, msg!("tbl-sm-hsc-control-0", n = n)),
            (1, msg!("tbl-sm-hsc-control-1", n = n)),
            (2, msg!("tbl-sm-hsc-control-2", n = n)),
            (3, msg!("tbl-sm-hsc-control-3", n = n)),
            (4, msg!("tbl-sm-hsc-control-4", n = n)),
            (5, msg!("tbl-sm-hsc-control-5", n = n)),
            (6, msg!("tbl-sm-hsc-control-6", n = n)),
            (7, msg!("tbl-sm-hsc-control-7", n = n)),
        ] {
            add(r.control, SmSize::Bit(bit), m, s);
        }
        add(r.status, SmSize::Byte, msg!("tbl-sm-hsc-status", n = n), s);
        for (bit, m) in [
            (3, msg!("tbl-sm-hsc-status-3", n = n)),
            (5, msg!("tbl-sm-hsc-status-5", n = n)),
            (6, msg!("tbl-sm-hsc-status-6", n = n)),
            (7, msg!("tbl-sm-hsc-status-7", n = n)),
        ] {
            add(r.status, SmSize::Bit(bit), m, s);
        }
        add(r.cv, SmSize::DWord, msg!("tbl-sm-hsc-cv", n = n), s);
        add(r.pv, SmSize::DWord, msg!("tbl-sm-hsc-pv", n = n), s);
        let t = "§3.3.3";
        add(r.mpv_control, SmSize::Byte, msg!("tbl-sm-hsc-mpv-control", n = n), t);
        for (bit, m) in [
            (0, msg!("tbl-sm-hsc-mpv-control-0", n = n)),
            (1, msg!("tbl-sm-hsc-mpv-control-1", n = n)),
            (2, msg!("tbl-sm-hsc-mpv-control-2", n = n)),
            (4, msg!("tbl-sm-hsc-mpv-control-4", n = n)),
            (5, msg!("tbl-sm-hsc-mpv-control-5", n = n)),
        ] {
            add(r.mpv_control, SmSize::Bit(bit), m, t);
        }
        add(r.table, SmSize::Word, msg!("tbl-sm-hsc-table", n = n), t);
        add(r.segment, SmSize::Byte, msg!("tbl-sm-hsc-segment", n = n), t);
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
            let text = text(Lang::En).text;
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
        assert!(HSC_MODES.iter().any(|m| m.0 == 0 && m.1 == 6 && m.2(Lang::En).starts_with("up I0.0")));
    }

    /// Every row's text is in every language, and every `tbl-sm-…`/`tbl-hsc-mode-…` id of the
    /// catalogue belongs to a row (or is one of the refusals above).
    #[test]
    fn every_row_has_its_text_in_every_language() {
        let mut used: Vec<&str> = names().iter().map(|n| n.meaning_id).collect();
        used.extend(HSC_MODES.iter().map(|m| m.2(Lang::En).id));
        for lang in Lang::ALL {
            let ids = crate::core::msg::ids(*lang);
            for id in &used {
                assert!(ids.iter().any(|i| i == id), "{id} has no text in {}", lang.tag());
            }
        }
        let refusals = [
            "tbl-sm-pos-cv-read-only",
            "tbl-sm-pos-cv-overlap",
            "tbl-sm-pos-cv-read-only-hint",
            "tbl-sm-pls-did-nothing",
            "tbl-sm-pls-did-nothing-hint",
            "tbl-sm-smb0-read-only",
            "tbl-sm-smb0-read-only-hint",
        ];
        for id in crate::core::msg::ids(Lang::En) {
            if id.starts_with("tbl-sm-") || id.starts_with("tbl-hsc-mode-") {
                assert!(used.contains(&id.as_str()) || refusals.contains(&id.as_str()), "{id} belongs to no row");
            }
        }
        let r = &PTO_REGS[0];
        assert_eq!(
            pos_cv_read_only(r, "SMD212").0,
            "SMD212 is the read-only current value of position channel 0 (manual §3.4.3.1)"
        );
        assert!(pls_did_nothing(r).1.starts_with("set SMB67=16#85"));
        assert!(smb0_read_only("SMB0").0.starts_with("SMB0 holds"));
    }

    #[test]
    fn overlap_finds_neighbours() {
        let o: Vec<String> = overlapping(67, 2).iter().map(|n| n.operand()).collect();
        assert!(o.contains(&"SMB67".to_string()) && o.contains(&"SMW68".to_string()), "{o:?}");
    }
}
