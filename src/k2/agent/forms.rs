//! The instruction forms the generated helper (`super::il`) may use, each with its source:
//! the K2 manual's section and words where it shows the form, otherwise the convention it
//! comes from and the LD a user enters instead. One table: the program's header lists it,
//! docs/agent.md prints it ([`markdown`]), and the tests below generate the helper for every
//! model and hold every line to it — and every SM and V address to the model's rows.

/// What an operand is, as far as the form goes.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Kind {
    /// `%SM0.0`, `%V3584.1`.
    Bit,
    /// `%SMB66`, `%VB3413`.
    Byte,
    /// `%SMW68`, `%VW3400`.
    Word,
    /// `%SMD72`, `%VD3576`.
    DWord,
    /// `INT#3`.
    IntLit,
    /// `W#16#4B41`.
    WordLit,
    /// A plain number: a channel, counter or mode (`PLS 0`, `HDEF 0, 9`) or the bit count of
    /// `S`/`R` (`S %V3584.1, 1`).
    Const,
    /// `&SMB0`: a pointer.
    Pointer,
    /// `*%VD3576`: the memory a pointer designates.
    Indirect,
    /// A jump label.
    Label,
}

impl Kind {
    fn name(self) -> &'static str {
        match self {
            Kind::Bit => "bit",
            Kind::Byte => "byte",
            Kind::Word => "word",
            Kind::DWord => "dword",
            Kind::IntLit => "INT#n",
            Kind::WordLit => "W#16#n",
            Kind::Const => "n",
            Kind::Pointer => "&address",
            Kind::Indirect => "*pointer",
            Kind::Label => "label",
        }
    }

    /// The kind of one operand's text.
    pub fn of(text: &str) -> Kind {
        let t = text.trim();
        if t.starts_with("INT#") {
            return Kind::IntLit;
        }
        if t.starts_with("W#16#") {
            return Kind::WordLit;
        }
        if t.starts_with('&') {
            return Kind::Pointer;
        }
        if t.starts_with('*') {
            return Kind::Indirect;
        }
        if !t.is_empty() && t.bytes().all(|b| b.is_ascii_digit()) {
            return Kind::Const;
        }
        match address(t) {
            Some((_, Kind::Bit, _)) => Kind::Bit,
            Some((_, k, _)) => k,
            None => Kind::Label,
        }
    }
}

/// `%SMB66` → ("SM", Byte, 66); `%V3584.1` → ("V", Bit, 3584). Only the SM and V areas
/// (the helper addresses nothing else).
pub fn address(text: &str) -> Option<(&'static str, Kind, u32)> {
    let t = text.trim().trim_start_matches(['&', '*']).trim_start_matches('%');
    let (area, rest) = if let Some(r) = t.strip_prefix("SM") {
        ("SM", r)
    } else if let Some(r) = t.strip_prefix('V') {
        ("V", r)
    } else {
        return None;
    };
    let (kind, num) = match rest.chars().next()? {
        'B' => (Kind::Byte, &rest[1..]),
        'W' => (Kind::Word, &rest[1..]),
        'D' => (Kind::DWord, &rest[1..]),
        c if c.is_ascii_digit() => (Kind::Bit, rest),
        _ => return None,
    };
    let byte = match (kind, num.split_once('.')) {
        (Kind::Bit, Some((b, bit))) if bit.len() == 1 && bit.as_bytes()[0] <= b'7' => b.parse().ok()?,
        (Kind::Bit, _) => return None,
        (_, None) => num.parse().ok()?,
        (_, Some(_)) => return None,
    };
    Some((area, kind, byte))
}

/// One form: a mnemonic with its operand kinds, and where it comes from.
#[derive(Clone, Copy, Debug)]
pub struct Form {
    pub mnemonic: &'static str,
    pub operands: &'static [Kind],
    /// The K2 manual shows this form.
    pub manual: bool,
    /// The manual's section and words, or the convention the form follows.
    pub source: &'static str,
    /// For a form the manual does not show: what to enter in LD instead.
    pub ld: &'static str,
}

impl Form {
    /// `MOVE W#16#n, word`.
    pub fn shape(&self) -> String {
        let ops: Vec<&str> = self.operands.iter().map(|k| k.name()).collect();
        if ops.is_empty() {
            self.mnemonic.to_string()
        } else {
            format!("{} {}", self.mnemonic, ops.join(", "))
        }
    }
}

use Kind::*;

const fn m(mnemonic: &'static str, operands: &'static [Kind], source: &'static str) -> Form {
    Form { mnemonic, operands, manual: true, source, ld: "" }
}
const fn x(mnemonic: &'static str, operands: &'static [Kind], source: &'static str, ld: &'static str) -> Form {
    Form { mnemonic, operands, manual: false, source, ld }
}

/// Every form a generated helper may use.
pub static FORMS: &[Form] = &[
    m("LD", &[Bit], "K2 §3.4.3.1: «LD %SM0.0», «LD %M0.4»"),
    m("ST", &[Bit], "K2 §3.4.3.1: «ST %SM201.6», «ST %SM201.4»"),
    m("MOVE", &[WordLit, Word], "K2 §3.4.3.1: «MOVE DI # 100, %SMD208»; typed literals as §3.4.2.3 «SMB67 = B # 16 # 85»"),
    m("MOVE", &[Word, Word], "K2 §3.4.3.1: «MOVE DI # 100, %SMD208» (MOVE takes the output's type)"),
    m("MOVE", &[Byte, Byte], "K2 §3.4.3.1: «MOVE DI # 100, %SMD208» (MOVE takes the output's type)"),
    m("PLS", &[Const], "K2 §3.4.2: «IL: PLS Q … Q: Константа (0,1 или 2)»; channel 3 (Q0.5, SMB107 …) only on the K209M, §3.4, §3.4.2.2"),
    m("HDEF", &[Const, Const], "K2 §3.3.5: «Использовать инструкцию HDEF для определения счета и его режима работы»; modes §3.3.1"),
    m("HSC", &[Const], "K2 §3.3.5: «Используйте инструкцию HSC, чтобы запустить высокоскоростной счетчик»"),
    m("PSTOP", &[Const, Bit, Bit, Word], "K2 §3.4.1 «PSTOP (аварийный останов)», §3.4.3.1; operands AXIS, EXEC, DONE, ERRID: KincoBuilder help"),
    m("SET_RTC", &[Byte], "K2 §2.2.9: «инструкции часов (READ_RTC, SET_RTC, RTC_W, RTC_R)»; 8-byte buffer: S7-200 layout"),
    m("READ_RTC", &[Byte], "K2 §2.2.9: «инструкции часов (READ_RTC, SET_RTC, RTC_W, RTC_R)»; 8-byte buffer: S7-200 layout"),
    x("LDN", &[Bit], "IEC 61131-3 IL; not in the K2 manual", "a normally closed contact"),
    x("A", &[Bit], "S7-200 IL (IEC: AND); not in the K2 manual", "a normally open contact in series"),
    x("AN", &[Bit], "S7-200 IL (IEC: ANDN); not in the K2 manual", "a normally closed contact in series"),
    x("ON", &[Bit], "S7-200 IL (IEC: ORN); not in the K2 manual", "a normally closed contact in parallel"),
    x("S", &[Bit, Const], "S7-200 IL (set N bits); not in the K2 manual", "a set coil -(S)- with N = 1"),
    x("R", &[Bit, Const], "S7-200 IL (reset N bits); not in the K2 manual", "a reset coil -(R)- with N = 1"),
    x("ALD", &[], "S7-200 IL; not in the K2 manual", "two contact groups in series"),
    x("ADD", &[IntLit, Word], "S7-200 IL (+I) / IEC ADD; not in the K2 manual", "an ADD box IN1 = the word, IN2 = 1, OUT = the word"),
    x("ADD", &[Word, Word], "S7-200 IL (+I) / IEC ADD; not in the K2 manual", "an ADD box IN1 = OUT, IN2 = the first operand"),
    x("LDW=", &[Word, IntLit], "S7-200 IL compare contact; not in the K2 manual", "a ==I compare contact"),
    x("LDW<>", &[Word, Word], "S7-200 IL compare contact; not in the K2 manual", "a <>I compare contact"),
    x("LDW<>", &[Word, IntLit], "S7-200 IL compare contact; not in the K2 manual", "a <>I compare contact"),
    x("LDW<", &[Word, IntLit], "S7-200 IL compare contact; not in the K2 manual", "a <I compare contact"),
    x("LDW>=", &[Word, IntLit], "S7-200 IL compare contact; not in the K2 manual", "a >=I compare contact"),
    x("AW=", &[Word, IntLit], "S7-200 IL compare contact; not in the K2 manual", "a ==I compare contact in series"),
    x("AW<", &[Word, IntLit], "S7-200 IL compare contact; not in the K2 manual", "a <I compare contact in series"),
    x("AW>", &[Word, IntLit], "S7-200 IL compare contact; not in the K2 manual", "a >I compare contact in series"),
    x("AW>=", &[Word, IntLit], "S7-200 IL compare contact; not in the K2 manual", "a >=I compare contact in series"),
    x("AW<=", &[Word, IntLit], "S7-200 IL compare contact; not in the K2 manual", "a <=I compare contact in series"),
    x("OW>", &[Word, IntLit], "S7-200 IL compare contact; not in the K2 manual", "a >I compare contact in parallel"),
    x("AB=", &[Byte, Byte], "S7-200 IL compare contact; not in the K2 manual", "a ==B compare contact in series"),
    x("JMPC", &[Label], "IEC 61131-3 IL; not in the K2 manual", "a JMP coil to the label, or drop it: it only skips the checks on scans without a request"),
    x("label:", &[], "IEC 61131-3 IL; not in the K2 manual", "a LBL at the network"),
];

/// The form of one line of IL (comments already removed): its mnemonic and operand kinds.
pub fn form_of(line: &str) -> (String, Vec<Kind>) {
    let t = line.trim();
    if let Some(l) = t.strip_suffix(':') {
        if !l.contains(char::is_whitespace) {
            return ("label:".into(), Vec::new());
        }
    }
    let (mn, rest) = t.split_once(char::is_whitespace).unwrap_or((t, ""));
    let ops = if rest.trim().is_empty() { Vec::new() } else { rest.split(',').map(Kind::of).collect() };
    (mn.to_ascii_uppercase(), ops)
}

/// The table's row for a form, if any.
pub fn find(mnemonic: &str, ops: &[Kind]) -> Option<&'static Form> {
    FORMS.iter().find(|f| f.mnemonic == mnemonic && f.operands == ops)
}

/// The program's code lines: `(* … *)` comments (which may span lines) removed.
pub fn code_lines(il: &str) -> Vec<String> {
    let mut out = String::with_capacity(il.len());
    let mut rest = il;
    while let Some(a) = rest.find("(*") {
        out.push_str(&rest[..a]);
        rest = match rest[a..].find("*)") {
            Some(b) => &rest[a + b + 2..],
            None => "",
        };
    }
    out.push_str(rest);
    out.lines().map(str::trim).filter(|l| !l.is_empty()).map(String::from).collect()
}

/// The table as Markdown (docs/agent.md holds it; a test keeps the two equal).
pub fn markdown() -> String {
    let mut s = String::from("| form | in the K2 manual | source | LD instead |\n|---|---|---|---|\n");
    for f in FORMS {
        s.push_str(&format!(
            "| `{}` | {} | {} | {} |\n",
            f.shape(),
            if f.manual { "yes" } else { "no" },
            f.source,
            if f.ld.is_empty() { "—" } else { f.ld }
        ));
    }
    s
}

#[cfg(test)]
mod tests {
    use super::super::{il, protocol as p};
    use super::*;
    use crate::k2::catalog::{EEPROM_FIRST, MODELS};
    use crate::k2::sm_map::HSC_MODES;

    fn bases() -> Vec<u32> {
        vec![0, 2, 2000, p::DEFAULT_BASE, EEPROM_FIRST - il::TOTAL_SIZE]
    }

    /// Every line of every generated helper has a form in the table; every SM address is a
    /// row the manual gives the model, every V address lies in the mailbox; the channel,
    /// counter and mode operands are the model's.
    #[test]
    fn every_generated_helper_uses_only_the_tables_forms_and_the_models_rows() {
        for model in MODELS {
            let rows = p::sm_rows(model);
            for base in bases() {
                assert!(il::refuse(model, base).is_none(), "{} at VB{base}", model.name);
                let text = il::program(model, base);
                for line in code_lines(&text) {
                    let (mn, ops) = form_of(&line);
                    assert!(find(&mn, &ops).is_some(), "{} VB{base}: `{line}` has a form the table lacks", model.name);
                    let args: Vec<&str> =
                        line.split_once(char::is_whitespace).map_or(vec![], |(_, r)| r.split(',').collect());
                    for a in &args {
                        match address(a) {
                            Some(("SM", _, b)) => {
                                assert!(
                                    rows.contains(&b),
                                    "{} VB{base}: `{line}`: SMB{b} is not a row of this model",
                                    model.name
                                )
                            }
                            Some((_, k, b)) => {
                                let size = match k {
                                    Kind::Word => 2,
                                    Kind::DWord => 4,
                                    _ => 1,
                                };
                                assert!(
                                    b >= base && b + size <= base + il::TOTAL_SIZE,
                                    "{} VB{base}: `{line}`: V byte {b} is outside the mailbox",
                                    model.name
                                );
                            }
                            None => {}
                        }
                    }
                    let num = |i: usize| args[i].trim().parse::<u8>().unwrap();
                    match mn.as_str() {
                        "PLS" | "PSTOP" => assert!(model.pto(num(0)).is_some(), "{}: `{line}`", model.name),
                        "HSC" => assert!(model.hsc(num(0)).is_some(), "{}: `{line}`", model.name),
                        "HDEF" => assert!(
                            model.hsc(num(0)).is_some() && HSC_MODES.iter().any(|m| (m.0, m.1) == (num(0), num(1))),
                            "{}: `{line}`",
                            model.name
                        ),
                        _ => {}
                    }
                }
            }
        }
    }

    /// `PLS 3` and `PSTOP 3` only where a fourth pulse output exists (the K209M's Q0.5).
    #[test]
    fn a_fourth_channel_only_on_the_k209m() {
        for model in MODELS {
            let il = il::program(model, p::DEFAULT_BASE);
            assert_eq!(il.contains("\nPLS     3"), model.pto.len() == 4, "{}", model.name);
            assert_eq!(il.contains("\nPSTOP   3,"), model.pto.len() == 4, "{}", model.name);
            assert_eq!(model.pto.len() == 4, model.name.starts_with("K209M"), "{}", model.name);
        }
    }

    /// The default helper's forms are honest: no `=`, no untyped constant in a MOVE or a
    /// compare, one block-move mnemonic, and the header lists the table's forms.
    #[test]
    fn no_assignment_sign_no_untyped_move_and_a_truthful_header() {
        let model = crate::k2::catalog::lookup(crate::k2::catalog::DEFAULT_MODEL).unwrap();
        let il = il::program(model, p::DEFAULT_BASE);
        let lines = code_lines(&il);
        assert!(!lines.iter().any(|l| l.starts_with("= ") || l.starts_with("=\t")), "no `=`");
        assert!(!lines.iter().any(|l| l.starts_with("BLKMOVE") || l.starts_with("BMB")), "no block move");
        assert!(!lines.iter().any(|l| l.contains('&') || l.contains('*')), "no pointer");
        for l in &lines {
            let (mn, ops) = form_of(l);
            if mn == "MOVE" || mn.starts_with("LDW") || mn.starts_with("AW") || mn.starts_with("OW") {
                assert!(!ops.contains(&Kind::Const), "untyped constant: `{l}`");
            }
        }
        for f in FORMS {
            assert!(il.contains(&f.shape()), "the header names `{}`", f.shape());
        }
    }

    /// The table is exact: every form in it is used by some generated helper.
    #[test]
    fn every_form_of_the_table_is_used() {
        let mut used = std::collections::HashSet::new();
        for model in MODELS {
            for line in code_lines(&il::program(model, p::DEFAULT_BASE)) {
                let (mn, ops) = form_of(&line);
                if let Some(f) = find(&mn, &ops) {
                    used.insert(f.shape());
                }
            }
        }
        for f in FORMS {
            assert!(used.contains(&f.shape()), "`{}` is in the table but no helper uses it", f.shape());
        }
    }

    #[test]
    fn the_protocol_document_shows_the_forms_table() {
        let doc = include_str!("../../../docs/agent.md");
        let table = markdown();
        assert!(doc.contains(&table), "docs/agent.md lacks the current table of forms:\n{table}");
    }

    #[test]
    fn operand_kinds() {
        assert_eq!(Kind::of("%SM0.0"), Kind::Bit);
        assert_eq!(Kind::of(" %VW3400"), Kind::Word);
        assert_eq!(Kind::of("*%VD3576"), Kind::Indirect);
        assert_eq!(Kind::of("&SMB0"), Kind::Pointer);
        assert_eq!(Kind::of("INT#3"), Kind::IntLit);
        assert_eq!(Kind::of("W#16#4B41"), Kind::WordLit);
        assert_eq!(Kind::of("3"), Kind::Const);
        assert_eq!(Kind::of("CHECKED"), Kind::Label);
        assert_eq!(address("%V3584.1"), Some(("V", Kind::Bit, 3584)));
        assert_eq!(address("&SMB0"), Some(("SM", Kind::Byte, 0)));
        assert_eq!(form_of("CHECKED:").0, "label:");
    }
}
