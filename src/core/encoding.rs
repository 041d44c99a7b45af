//! Text files as users save them: IL programs come from Windows editors in UTF-8, in UTF-16
//! (Notepad's "Unicode", with a byte-order mark) or in the Russian ANSI code page
//! Windows-1251 (KincoBuilder exports and comments typed on a Russian Windows). The rule:
//! a UTF-16 byte-order mark (FF FE little-endian, FE FF big-endian) is UTF-16; so is a file
//! without one whose NUL bytes are the other half of ASCII text in UTF-16 (every NUL at an
//! odd offset: little-endian; every one at an even offset: big-endian; and at least a quarter
//! of the 16-bit units so), which is what editors and scripts write as "UTF-16LE" or
//! "Unicode (no BOM)" — NUL is valid UTF-8, so without this rule such a file would read as
//! ASCII with a NUL between every two characters; valid UTF-8 is UTF-8 (a UTF-8 byte-order
//! mark is dropped); anything else is Windows-1251, which maps every byte, so such a file
//! always loads and its comments show as written.
//!
//! Messages that quote a file's text pass it through [`printable`] first: a control
//! character (a NUL, an escape sequence, a carriage return) never reaches the terminal raw.
//!
//! The Windows-1251 table is the 64 entries 0x80–0xBF of the WHATWG Encoding Standard's
//! index (<https://encoding.spec.whatwg.org/index-windows-1251.txt>); 0xC0–0xFF are А–я
//! (U+0410–U+044F) and 0x00–0x7F ASCII. A hand-written table keeps the crate free of a
//! general encoding library for one code page. Decoding is one pass, linear in the input.

use std::path::Path;

/// The encoding a text was read in.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Encoding {
    Utf8,
    Utf16Le,
    Utf16Be,
    Windows1251,
}

/// Windows-1251 0x80–0xBF (WHATWG index; 0x98 is unassigned and maps to U+0098 as there).
const CP1251_80: [u16; 64] = [
    0x0402, 0x0403, 0x201A, 0x0453, 0x201E, 0x2026, 0x2020, 0x2021, 0x20AC, 0x2030, 0x0409, 0x2039, 0x040A, 0x040C,
    0x040B, 0x040F, 0x0452, 0x2018, 0x2019, 0x201C, 0x201D, 0x2022, 0x2013, 0x2014, 0x0098, 0x2122, 0x0459, 0x203A,
    0x045A, 0x045C, 0x045B, 0x045F, 0x00A0, 0x040E, 0x045E, 0x0408, 0x00A4, 0x0490, 0x00A6, 0x00A7, 0x0401, 0x00A9,
    0x0404, 0x00AB, 0x00AC, 0x00AD, 0x00AE, 0x0407, 0x00B0, 0x00B1, 0x0406, 0x0456, 0x0491, 0x00B5, 0x00B6, 0x00B7,
    0x0451, 0x2116, 0x0454, 0x00BB, 0x0458, 0x0405, 0x0455, 0x0457,
];

/// One Windows-1251 byte as a character.
pub fn cp1251_char(b: u8) -> char {
    let cp = match b {
        0x00..=0x7F => b as u32,
        0x80..=0xBF => CP1251_80[(b - 0x80) as usize] as u32,
        _ => 0x0410 + (b - 0xC0) as u32,
    };
    char::from_u32(cp).unwrap_or(char::REPLACEMENT_CHARACTER)
}

/// UTF-16 without a byte-order mark, told by where its NUL bytes are (the rule above).
fn bomless_utf16(bytes: &[u8]) -> Option<Encoding> {
    let (mut even, mut odd) = (0usize, 0usize);
    for (i, &b) in bytes.iter().enumerate() {
        if b == 0 {
            if i % 2 == 0 {
                even += 1;
            } else {
                odd += 1;
            }
        }
    }
    let units = bytes.len() / 2;
    let enough = |n: usize| n > 0 && n * 4 >= units;
    match (even, odd) {
        (0, n) if enough(n) => Some(Encoding::Utf16Le),
        (n, 0) if enough(n) => Some(Encoding::Utf16Be),
        _ => None,
    }
}

/// Decodes a text file's bytes by the rule above. UTF-16 that is cut in the middle of a
/// unit or has a lone surrogate is refused naming the byte offset.
pub fn decode(bytes: &[u8]) -> Result<(String, Encoding), String> {
    let (enc, body, bom) = match bytes {
        [0xFF, 0xFE, rest @ ..] => (Encoding::Utf16Le, rest, true),
        [0xFE, 0xFF, rest @ ..] => (Encoding::Utf16Be, rest, true),
        _ => match bomless_utf16(bytes) {
            Some(enc) => (enc, bytes, false),
            None => {
                if let Ok(s) = std::str::from_utf8(bytes) {
                    return Ok((s.strip_prefix('\u{FEFF}').unwrap_or(s).to_string(), Encoding::Utf8));
                }
                return Ok((bytes.iter().map(|&b| cp1251_char(b)).collect(), Encoding::Windows1251));
            }
        },
    };
    let le = enc == Encoding::Utf16Le;
    // What the text is, as the messages name it (a noun phrase of the catalogue).
    let what = || {
        let kind = match (bom, le) {
            (true, true) => "bom-le",
            (true, false) => "bom-be",
            (false, true) => "le",
            (false, false) => "be",
        };
        crate::msg!("encoding-utf16-kind", kind = kind).text
    };
    let first = bytes.len() - body.len();
    if body.len() % 2 != 0 {
        return Err(crate::msg!("encoding-utf16-odd", what = what(), byte = bytes.len() - 1).into());
    }
    let units =
        body.chunks_exact(2).map(
            |c| {
                if le {
                    u16::from_le_bytes([c[0], c[1]])
                } else {
                    u16::from_be_bytes([c[0], c[1]])
                }
            },
        );
    let mut out = String::with_capacity(body.len() / 2);
    for (i, r) in char::decode_utf16(units).enumerate() {
        match r {
            Ok(c) => out.push(c),
            Err(e) => {
                return Err(crate::msg!(
                    "encoding-utf16-surrogate",
                    what = what(),
                    byte = first + 2 * i,
                    surrogate = format!("{:04X}", e.unpaired_surrogate())
                )
                .into())
            }
        }
    }
    Ok((out.strip_prefix('\u{FEFF}').unwrap_or(&out).to_string(), enc))
}

/// `s` with every control character written out (`\0`, `\t`, `\r`, `\n`, `\u{1B}`), and
/// the invisible characters that reorder or break a terminal line (bidirectional overrides
/// and isolates, the line and paragraph separators) as `\u{…}` too: safe to put in a
/// message that quotes a file's text.
pub fn printable(s: &str) -> std::borrow::Cow<'_, str> {
    let unsafe_char = |c: char| {
        c.is_control() || matches!(c, '\u{2028}' | '\u{2029}' | '\u{202A}'..='\u{202E}' | '\u{2066}'..='\u{2069}')
    };
    if !s.chars().any(unsafe_char) {
        return std::borrow::Cow::Borrowed(s);
    }
    let mut out = String::with_capacity(s.len() + 8);
    for c in s.chars() {
        match c {
            '\0' => out.push_str("\\0"),
            '\t' => out.push_str("\\t"),
            '\r' => out.push_str("\\r"),
            '\n' => out.push_str("\\n"),
            c if unsafe_char(c) => out.push_str(&format!("\\u{{{:X}}}", c as u32)),
            c => out.push(c),
        }
    }
    std::borrow::Cow::Owned(out)
}

/// `e` with its message, hint and causes made [`printable`]: for a loader's error, which
/// quotes the file's text (an unknown instruction, an operand).
pub fn printable_error(mut e: crate::core::Error) -> crate::core::Error {
    let fix = |t: &mut String| {
        if let std::borrow::Cow::Owned(p) = printable(t) {
            *t = p;
        }
    };
    fix(&mut e.message);
    if let Some(h) = e.hint.as_mut() {
        fix(h);
    }
    e.causes.iter_mut().for_each(fix);
    e
}

/// Reads a source file (an IL program) in any of the encodings above; the error is an I/O
/// error whose text says what was wrong, for the caller to prefix with the file's name.
pub fn read_source(path: impl AsRef<Path>) -> std::io::Result<String> {
    let bytes = std::fs::read(path)?;
    decode(&bytes).map(|(s, _)| s).map_err(|m| std::io::Error::new(std::io::ErrorKind::InvalidData, m))
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn utf8_utf16_and_windows_1251_decode_by_the_rule() {
        let text = "LD %I0.0 // Пуск насоса №1\n";
        assert_eq!(decode(text.as_bytes()).unwrap(), (text.to_string(), Encoding::Utf8));
        let bom8 = [&[0xEF, 0xBB, 0xBF][..], text.as_bytes()].concat();
        assert_eq!(decode(&bom8).unwrap().0, text, "a UTF-8 BOM is dropped");
        let le: Vec<u8> = [0xFF, 0xFE].into_iter().chain(text.encode_utf16().flat_map(|u| u.to_le_bytes())).collect();
        assert_eq!(decode(&le).unwrap(), (text.to_string(), Encoding::Utf16Le));
        let be: Vec<u8> = [0xFE, 0xFF].into_iter().chain(text.encode_utf16().flat_map(|u| u.to_be_bytes())).collect();
        assert_eq!(decode(&be).unwrap(), (text.to_string(), Encoding::Utf16Be));
        // The same line as a Russian Windows saves it (bytes written out, not encoded here):
        // "Пуск насоса №1" = CF F3 F1 EA 20 ED E0 F1 EE F1 E0 20 B9 31.
        let mut cp = b"LD %I0.0 // ".to_vec();
        cp.extend([0xCF, 0xF3, 0xF1, 0xEA, 0x20, 0xED, 0xE0, 0xF1, 0xEE, 0xF1, 0xE0, 0x20, 0xB9, 0x31, b'\n']);
        assert_eq!(decode(&cp).unwrap(), (text.to_string(), Encoding::Windows1251));
        // Ё ё, the quotes and the euro sign from the 0x80–0xBF table.
        assert_eq!(decode(&[0xA8, 0xB8, 0xAB, 0xBB, 0x88, 0xFF]).unwrap().0, "Ёё«»€я");
    }

    #[test]
    fn broken_utf16_is_refused_naming_the_byte() {
        let e = decode(&[0xFF, 0xFE, b'L', 0, b'D']).unwrap_err();
        assert!(e.contains("byte 4"), "{e}");
        let e = decode(&[0xFF, 0xFE, b'L', 0, 0x00, 0xDC]).unwrap_err();
        assert!(e.contains("byte 4") && e.contains("DC00"), "{e}");
        assert!(decode(&[0xFF]).is_ok(), "a lone FF is Windows-1251 (я)");
    }

    #[test]
    fn utf16_without_a_byte_order_mark_is_told_by_its_nul_bytes() {
        let text = "(* Пуск *)\nLD %SM0.0 // Пуск насоса\r\nINC %VW0\n";
        let le: Vec<u8> = text.encode_utf16().flat_map(|u| u.to_le_bytes()).collect();
        let be: Vec<u8> = text.encode_utf16().flat_map(|u| u.to_be_bytes()).collect();
        assert_eq!(decode(&le).unwrap(), (text.to_string(), Encoding::Utf16Le));
        assert_eq!(decode(&be).unwrap(), (text.to_string(), Encoding::Utf16Be));
        // Every cut of a whole file: ASCII-heavy prefixes decode as the prefix, an odd cut is
        // refused naming the last byte; never a NUL in the text.
        for n in 1..le.len() {
            for (bytes, enc) in [(&le[..n], Encoding::Utf16Le), (&be[..n], Encoding::Utf16Be)] {
                match decode(bytes) {
                    Ok((t, e)) => {
                        assert!(!t.contains('\0'), "{n}: {t:?}");
                        if e == enc {
                            assert!(text.starts_with(&t), "{n}: {t:?}");
                        }
                    }
                    Err(m) => {
                        assert!(n % 2 == 1 && m.contains("without a byte-order mark"), "{n}: {m}");
                        assert!(m.contains(&format!("at byte {}", n - 1)), "{n}: {m}");
                    }
                }
            }
        }
        // A lone surrogate is named at its byte, counted from the start of the file.
        let mut bad = le.clone();
        bad[4..6].copy_from_slice(&[0x01, 0xDC]);
        let e = decode(&bad).unwrap_err();
        assert!(e.contains("little-endian") && e.contains("at byte 4") && e.contains("DC01"), "{e}");
        // A stray NUL in UTF-8 or Windows-1251 text is not UTF-16: too few to be the other
        // half of the text, or on both sides.
        assert_eq!(decode(b"LD %I0.0\0 // x\n").unwrap().1, Encoding::Utf8);
        assert_eq!(decode(b"\0\0LD X0\n").unwrap().1, Encoding::Utf8);
        let mut cp = vec![0xCF, 0xF3, 0xF1, 0xEA, 0];
        cp.extend_from_slice(b" LD X0 // a stray NUL\n");
        assert_eq!(decode(&cp).unwrap().1, Encoding::Windows1251);
    }

    #[test]
    fn printable_writes_control_characters_out() {
        assert!(matches!(printable("LD %I0.0 // Пуск"), std::borrow::Cow::Borrowed(_)));
        assert_eq!(printable("(\0*\0\t\r\n\u{1b}[31m\u{7f}\u{85}"), "(\\0*\\0\\t\\r\\n\\u{1B}[31m\\u{7F}\\u{85}");
        assert_eq!(printable("a\u{202E}b\u{2066}c\u{2028}"), "a\\u{202E}b\\u{2066}c\\u{2028}");
        // Over every character of the first 0x3000: the result has no control character, and
        // a character left alone is printed as itself.
        for cp in 0..0x3000u32 {
            let Some(c) = char::from_u32(cp) else { continue };
            let s = format!("x{c}y");
            let p = printable(&s);
            assert!(!p.chars().any(|c| c.is_control()), "{cp:#X}: {p:?}");
            assert!(p == s || p.starts_with("x\\"), "{cp:#X}: {p:?}");
        }
    }
}
