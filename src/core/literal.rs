//! IEC 61131-3 / KincoBuilder literals (`../shared/spec/k2.md` §2): `133`, `-5`, `16#85`,
//! `2#1010_0101`, `8#17`, `B#16#85`, `W#16#FFFF`, `DW#16#…`, `DI#100`, `INT#-3`,
//! `REAL#1.5`, `T#500ms`, and `TRUE`/`FALSE`/`ON`/`OFF` for bits.
//!
//! Parsing and fitting are two steps: [`parse_literal`] reads the text; [`Literal::fit`]
//! checks it against the operand it is written to. A value that does not fit is an error,
//! never a silent wrap: `300` into a byte fails, `-1` into a WORD fails unless it is written
//! as a signed type (`INT#-1`), and a bit pattern (`16#FFFF`) fills any operand of its width.

use super::msg::Msg;
use super::value::{mask, DataType, Value};
use crate::msg;

/// A parsed literal, not yet checked against an operand.
#[derive(Clone, Debug, PartialEq)]
pub struct Literal {
    pub value: Value,
    /// The type the literal was written as (`INT#-3` → INT, `W#16#FFFF` → WORD).
    pub declared: Option<DataType>,
    /// Written in a radix (`16#`, `2#`, `8#`): a bit pattern rather than a number.
    pub pattern: bool,
    /// The text as typed (for messages).
    pub text: String,
}

/// Why a literal did not parse; `column` is 0-based within the literal text.
#[derive(Clone, Debug, PartialEq)]
pub struct LiteralError {
    pub column: usize,
    pub message: Msg,
}

fn err(column: usize, message: Msg) -> LiteralError {
    LiteralError { column, message }
}

/// Parses one literal. Spaces around `#` are accepted (`B # 16 # 85`, as the manual's
/// scanned text writes it); other spaces are not.
pub fn parse_literal(text: &str) -> Result<Literal, LiteralError> {
    let trimmed = text.trim();
    if trimmed.is_empty() {
        return Err(err(0, msg!("literal-missing")));
    }
    let compact: String = squeeze_hash_spaces(trimmed);
    if let Some(pos) = compact.find(char::is_whitespace) {
        return Err(err(pos, msg!("literal-space", value = trimmed)));
    }
    let upper = compact.to_ascii_uppercase();
    let mut lit = match upper.as_str() {
        "TRUE" | "ON" => {
            Literal { value: Value::Bool(true), declared: Some(DataType::Bool), pattern: false, text: String::new() }
        }
        "FALSE" | "OFF" => {
            Literal { value: Value::Bool(false), declared: Some(DataType::Bool), pattern: false, text: String::new() }
        }
        _ => parse_typed(&upper).map_err(|mut e| {
            e.message.text = as_typed(&e.message.text, &upper, &compact);
            e
        })?,
    };
    lit.text = trimmed.to_string();
    Ok(lit)
}

/// Messages quote the value as typed, not upper-cased: every `quoted` piece of `msg` found in
/// `upper` is replaced by the same bytes of `typed` (ASCII upper-casing keeps byte offsets).
fn as_typed(msg: &str, upper: &str, typed: &str) -> String {
    let mut out = String::with_capacity(msg.len());
    let mut parts = msg.split('`');
    out.push_str(parts.next().unwrap_or(""));
    for (k, part) in parts.enumerate() {
        out.push('`');
        let quoted = k % 2 == 0;
        match upper.find(part).filter(|_| quoted && !part.is_empty()) {
            Some(at) if typed.is_char_boundary(at) && typed.is_char_boundary(at + part.len()) => {
                out.push_str(&typed[at..at + part.len()])
            }
            _ => out.push_str(part),
        }
    }
    out
}

fn squeeze_hash_spaces(s: &str) -> String {
    let mut out = String::with_capacity(s.len());
    let chars: Vec<char> = s.chars().collect();
    for (i, &c) in chars.iter().enumerate() {
        if c.is_whitespace() {
            let prev = chars[..i].iter().rev().find(|c| !c.is_whitespace());
            let next = chars[i + 1..].iter().find(|c| !c.is_whitespace());
            if prev == Some(&'#') || next == Some(&'#') {
                continue;
            }
        }
        out.push(c);
    }
    out
}

/// Type prefixes: `B#`, `W#`, `DW#` are bit patterns; the others are typed numbers.
static TYPE_PREFIXES: &[(&str, DataType)] = &[
    ("DW", DataType::DWord),
    ("DWORD", DataType::DWord),
    ("W", DataType::Word),
    ("WORD", DataType::Word),
    ("B", DataType::Byte),
    ("BYTE", DataType::Byte),
    ("DI", DataType::DInt),
    ("DINT", DataType::DInt),
    ("INT", DataType::Int),
    ("I", DataType::Int),
    ("SINT", DataType::SInt),
    ("REAL", DataType::Real),
    ("R", DataType::Real),
    ("BOOL", DataType::Bool),
    ("UINT", DataType::Word),
    ("UDINT", DataType::DWord),
    ("USINT", DataType::Byte),
];

/// True when `word` can stand before `#` in a literal (`B`, `INT`, `T`, a radix `16`), so a
/// `#` after it — even spaced, `B # 16 # 85` as the manual's scanned text writes it — is part
/// of a value, not a comment.
pub fn is_literal_head(word: &str) -> bool {
    let w = word.trim().to_ascii_uppercase();
    TYPE_PREFIXES.iter().any(|(p, _)| *p == w) || ["T", "TIME", "2", "8", "10", "16"].contains(&w.as_str())
}

fn parse_typed(s: &str) -> Result<Literal, LiteralError> {
    // T#500ms / TIME#1s200ms
    if let Some(rest) = s.strip_prefix("T#").or_else(|| s.strip_prefix("TIME#")) {
        let ms =
            parse_duration_ms(rest).map_err(|m| err(s.len() - rest.len(), msg!("literal-duration", message = m)))?;
        return Ok(Literal { value: Value::Int(ms), declared: None, pattern: false, text: String::new() });
    }
    if let Some(hash) = s.find('#') {
        let head = &s[..hash];
        if let Some(&(_, t)) = TYPE_PREFIXES.iter().find(|(p, _)| *p == head) {
            let rest = &s[hash + 1..];
            let mut inner = parse_number(rest).map_err(|e| err(e.column + hash + 1, e.message))?;
            if t == DataType::Real {
                inner.value = Value::Real(inner.value.as_f64());
            } else if let Value::Real(_) = inner.value {
                return Err(err(hash + 1, msg!("literal-typed-integer", prefix = head, rest = rest)));
            }
            let is_pattern_type = matches!(t, DataType::Byte | DataType::Word | DataType::DWord);
            if t != DataType::Real {
                let (lo, hi) = t.int_range();
                let v = inner.value.as_i64();
                if v < lo || v > hi {
                    return Err(err(0, msg!("value-does-not-fit", value = v, dtype = t.name(), min = lo, max = hi)));
                }
            }
            return Ok(Literal {
                value: if t == DataType::Bool { Value::Bool(inner.value.as_i64() != 0) } else { inner.value },
                declared: Some(t),
                pattern: is_pattern_type || inner.pattern,
                text: String::new(),
            });
        }
        if head.chars().all(|c| c.is_ascii_digit() || c == '-') {
            return parse_number(s);
        }
        return Err(err(0, msg!("literal-unknown-prefix", prefix = head)));
    }
    parse_number(s)
}

/// A plain or radix number: `-5`, `1.5`, `16#85`, `2#1010_0101`, `8#17`.
fn parse_number(s: &str) -> Result<Literal, LiteralError> {
    let (neg, body, off) = match s.strip_prefix('-') {
        Some(r) => (true, r, 1),
        None => (false, s.strip_prefix('+').unwrap_or(s), usize::from(s.starts_with('+'))),
    };
    if body.is_empty() {
        return Err(err(off, msg!("literal-number-missing")));
    }
    // C-style radix prefixes, as mbpoll and most languages write them: say the IEC form.
    for (c, radix) in [("0X", "16#"), ("0B", "2#"), ("0O", "8#")] {
        if let Some(digits) = body.strip_prefix(c).filter(|d| !d.is_empty()) {
            let sign = if neg { "-" } else { "" };
            let typed = format!("{sign}{}{digits}", c.to_ascii_lowercase());
            return Err(err(off, msg!("literal-c-notation", typed = typed, iec = format!("{sign}{radix}{digits}"))));
        }
    }
    if let Some(hash) = body.find('#') {
        let radix: u32 = match &body[..hash] {
            "16" => 16,
            "8" => 8,
            "2" => 2,
            "10" => 10,
            r => return Err(err(off, msg!("literal-unknown-radix", radix = r))),
        };
        let digits: String = body[hash + 1..].chars().filter(|&c| c != '_').collect();
        if digits.is_empty() {
            return Err(err(off + hash + 1, msg!("literal-no-digits", radix = radix)));
        }
        if let Some((i, c)) = body[hash + 1..].char_indices().find(|&(_, c)| c != '_' && !c.is_digit(radix)) {
            return Err(err(
                off + hash + 1 + i,
                msg!("literal-not-digit-of-base", char = c.to_string(), radix = radix),
            ));
        }
        let v = u64::from_str_radix(&digits, radix).map_err(|_| err(off, msg!("literal-too-wide", value = s)))?;
        if v > u32::MAX as u64 {
            return Err(err(off, msg!("literal-too-wide", value = s)));
        }
        let v = if neg { -(v as i64) } else { v as i64 };
        return Ok(Literal { value: Value::Int(v), declared: None, pattern: radix != 10 && !neg, text: String::new() });
    }
    let digits: String = body.chars().filter(|&c| c != '_').collect();
    if digits.contains(['.', 'E', 'e']) {
        let f: f64 = digits.parse().map_err(|_| err(off, msg!("literal-not-number", value = s)))?;
        return Ok(Literal {
            value: Value::Real(if neg { -f } else { f }),
            declared: None,
            pattern: false,
            text: String::new(),
        });
    }
    if let Some((i, c)) = body.char_indices().find(|&(_, c)| !c.is_ascii_digit() && c != '_') {
        return Err(err(off + i, msg!("literal-not-digit", char = c.to_string(), value = s)));
    }
    let v: i64 =
        digits.parse().map_err(|_| err(off, msg!("literal-too-large", value = s, max = i64::MAX.to_string())))?;
    Ok(Literal { value: Value::Int(if neg { -v } else { v }), declared: None, pattern: false, text: String::new() })
}

/// `500ms`, `1s200ms`, `2.5s`, `1m30s`, `1h`, `250us` → milliseconds (µs are rounded down
/// only if exact; otherwise an error, since T# values are whole milliseconds).
pub fn parse_duration_ms(s: &str) -> Result<i64, String> {
    let us = parse_duration_us(s)?;
    if us % 1000 != 0 {
        return Err(msg!("duration-not-whole-ms", value = s).into());
    }
    Ok(us / 1000)
}

/// A duration given to a command or a Lua call (`every=`, `for=`, `timeout=`, `sim step`):
/// a bare number is milliseconds — the one unit rule for times (README "Units") — and a
/// number with a unit is that (`500ms`, `2s`, `250us`). In microseconds; refused past
/// [`i64::MAX`] µs, not saturated.
pub fn parse_option_duration_us(s: &str) -> Result<i64, String> {
    whole_us(option_duration_us(s)?, s)
}

/// [`parse_option_duration_us`] before the limit: µs as a float (syntax errors only).
fn option_duration_us(s: &str) -> Result<f64, String> {
    let t = s.trim().replace('_', "");
    match t.parse::<f64>() {
        Ok(ms) if ms.is_finite() && !t.is_empty() => Ok(ms * 1000.0),
        _ => duration_us(s),
    }
}

/// A duration in microseconds from text with a unit on every number: `500ms`, `1s200ms`,
/// `2.5s`, `250us`, `1h`. A bare number is refused (`T#5`, a unit-less option where no
/// rule says its unit): callers whose quantity has a unit for bare numbers use
/// [`parse_option_duration_us`] (milliseconds) or [`parse_pulse_time_us`] (microseconds).
/// Refused past [`i64::MAX`] µs (about 292 000 years), not saturated.
pub fn parse_duration_us(s: &str) -> Result<i64, String> {
    whole_us(duration_us(s)?, s)
}

/// A pulse cycle or width (`pto`/`pwm`/`profile` `cycle=`, `width=`): a bare number is
/// microseconds — the K2's default time base and the units table's rule — and a number with
/// a unit is that (`1ms`, `500us`, `0.5ms`). In microseconds.
pub fn parse_pulse_time_us(s: &str) -> Result<i64, String> {
    let t = s.trim().replace('_', "");
    match t.parse::<f64>() {
        Ok(us) if us.is_finite() && !t.is_empty() => whole_us(us, s),
        _ => parse_duration_us(s),
    }
}

/// Rounds to whole µs, refusing what an i64 cannot hold.
fn whole_us(us: f64, text: &str) -> Result<i64, String> {
    // `i64::MAX as f64` is 2^63: everything below it rounds to at most i64::MAX.
    if us.is_finite() && us.abs() < i64::MAX as f64 {
        Ok(us.round() as i64)
    } else {
        Err(msg!("duration-too-long", value = text.trim(), max = i64::MAX.to_string()).into())
    }
}

fn duration_us(s: &str) -> Result<f64, String> {
    let s = s.trim().to_ascii_lowercase();
    if s.is_empty() {
        return Err(msg!("duration-missing").into());
    }
    let mut total: f64 = 0.0;
    let mut rest = s.as_str();
    while !rest.is_empty() {
        let num_len = rest.find(|c: char| !(c.is_ascii_digit() || c == '.' || c == '_')).unwrap_or(rest.len());
        if num_len == 0 {
            return Err(msg!("duration-not-duration", value = s.as_str()).into());
        }
        let n: f64 = rest[..num_len]
            .replace('_', "")
            .parse()
            .map_err(|_| String::from(msg!("duration-not-duration", value = s.as_str())))?;
        rest = &rest[num_len..];
        let unit_len = rest.find(|c: char| c.is_ascii_digit()).unwrap_or(rest.len());
        let factor = match &rest[..unit_len] {
            "" => return Err(msg!("duration-needs-unit", value = s.as_str(), number = n.to_string()).into()),
            "d" => 86_400e6,
            "h" => 3_600e6,
            "m" | "min" => 60e6,
            "s" => 1e6,
            "ms" => 1e3,
            "us" | "µs" => 1.0,
            u => return Err(msg!("duration-unknown-unit", unit = u, value = s.as_str()).into()),
        };
        total += n * factor;
        rest = &rest[unit_len..];
    }
    Ok(total)
}

/// The longest link timeout (`timeout=` of a device URL or `device set`): a day. A link
/// that has not answered in a day is down; and a wait this long still fits every
/// platform's clock arithmetic (`Instant + timeout`), where a century would not.
pub const MAX_TIMEOUT: std::time::Duration = std::time::Duration::from_secs(86_400);

/// A link's `timeout=`: a bare number is milliseconds (README "Units"), or a duration with
/// a unit (`500ms`, `2s`); more than zero and at most [`MAX_TIMEOUT`].
pub fn parse_timeout(text: &str) -> Result<std::time::Duration, String> {
    let us = option_duration_us(text)?;
    if us.is_nan() || us <= 0.0 {
        return Err(msg!("timeout-not-positive", value = text).into());
    }
    if us < 0.5 {
        // It would round to no wait at all: every request would time out at once.
        return Err(msg!("timeout-too-short", value = text).into());
    }
    if us > MAX_TIMEOUT.as_micros() as f64 {
        return Err(msg!("timeout-too-long", value = text, max = MAX_TIMEOUT.as_millis() as u64).into());
    }
    Ok(std::time::Duration::from_micros(us.round() as u64))
}

/// A timeout in messages, to the microsecond `parse_timeout` keeps: `500 ms`, `0.5 ms`,
/// `2.25 ms` — never a user's `timeout=0.5` shown as `0 ms`. The number reads back as the
/// same `timeout=` (a bare number is milliseconds).
pub fn millis_text(d: std::time::Duration) -> String {
    let us = d.as_micros();
    let frac = format!("{:03}", us % 1000);
    match frac.trim_end_matches('0') {
        "" => format!("{} ms", us / 1000),
        f => format!("{}.{f} ms", us / 1000),
    }
}

/// A frequency option (`freq=`, a PTO's rate): `2kHz`, `500Hz`, `1.5khz`, `200k`, `1MHz` → Hz.
/// Positive and finite; the messages quote the text.
pub fn parse_freq_hz(text: &str) -> std::result::Result<f64, String> {
    let t = text.trim().to_ascii_lowercase();
    let num_len = t.find(|c: char| !(c.is_ascii_digit() || c == '.' || c == '_')).unwrap_or(t.len());
    let n: f64 =
        t[..num_len].replace('_', "").parse().map_err(|_| String::from(msg!("freq-not-frequency", value = text)))?;
    let f = match &t[num_len..] {
        "" | "hz" => 1.0,
        "k" | "khz" => 1e3,
        "m" | "mhz" => 1e6,
        u => return Err(msg!("freq-unknown-unit", unit = u, value = text).into()),
    };
    let hz = n * f;
    if hz <= 0.0 {
        return Err(msg!("freq-not-positive", value = text).into());
    }
    if !hz.is_finite() {
        return Err(msg!("freq-too-large", value = text, max = format!("{:e}", f64::MAX)).into());
    }
    Ok(hz)
}

impl Literal {
    /// Checks this literal against an operand of type `target` whose significant width is
    /// `bits` (equal to `target.bits()` except for bit groups such as `K1M0`, 4 bits), and
    /// returns the value in the operand's own type.
    pub fn fit(&self, target: DataType, bits: u32) -> Result<Value, Msg> {
        let shown = &self.text;
        match target {
            DataType::Bool => {
                return match self.value {
                    Value::Bool(b) => Ok(Value::Bool(b)),
                    Value::Int(0) => Ok(Value::Bool(false)),
                    Value::Int(1) => Ok(Value::Bool(true)),
                    _ => Err(msg!("value-not-bit", value = shown)),
                };
            }
            DataType::Real => {
                return match self.value {
                    Value::Bool(_) => Err(msg!("value-bit-not-real", value = shown)),
                    v if !fits_f32(v.as_f64()) => {
                        Err(msg!("value-not-real", value = shown, max = format!("{:e}", f32::MAX)))
                    }
                    v => Ok(Value::Real(v.as_f64())),
                };
            }
            _ => {}
        }
        let v = match self.value {
            Value::Bool(b) => b as i64,
            Value::Int(i) => i,
            Value::Real(r) => {
                if self.declared == Some(DataType::Real) && bits == 32 {
                    if !fits_f32(r) {
                        return Err(msg!("value-not-real", value = shown, max = format!("{:e}", f32::MAX)));
                    }
                    // REAL#1.5 into a 32-bit integer operand stores the IEEE pattern.
                    return Ok(target.decode((r as f32).to_bits()));
                }
                return Err(msg!("value-not-integer", value = shown, dtype = target.name()));
            }
        };
        let raw: u64 = match self.declared {
            Some(t) if t.is_signed() => {
                if t.bits() > bits {
                    return Err(msg!(
                        "value-type-too-wide",
                        value = shown,
                        dtype = t.name(),
                        bits = t.bits(),
                        width = bits
                    ));
                }
                v as u64 & mask(bits)
            }
            Some(t) if t != DataType::Bool && t.bits() > bits => {
                return Err(msg!(
                    "value-type-too-wide",
                    value = shown,
                    dtype = t.name(),
                    bits = t.bits(),
                    width = bits
                ));
            }
            // A bit group narrower than its type (an FX K4Y0 viewed as DINT) is zero-extended:
            // it is never negative.
            _ if self.pattern || !target.is_signed() || bits < target.bits() => {
                if v < 0 || v as u64 > mask(bits) {
                    let max = mask(bits);
                    let signed = match bits {
                        8 => "SINT",
                        16 => "INT",
                        _ => "DI",
                    };
                    let group = bits != target.bits();
                    return Err(match (v < 0 && !target.is_signed(), group) {
                        (false, false) => msg!("value-out-of-range", value = shown, dtype = target.name(), max = max),
                        (false, true) => msg!("value-out-of-range-group", value = shown, bits = bits, max = max),
                        (true, false) => msg!(
                            "value-out-of-range-signed",
                            value = shown,
                            dtype = target.name(),
                            max = max,
                            signed = signed,
                            number = v
                        ),
                        (true, true) => msg!(
                            "value-out-of-range-group-signed",
                            value = shown,
                            bits = bits,
                            max = max,
                            signed = signed,
                            number = v
                        ),
                    });
                }
                v as u64
            }
            _ => {
                let (lo, hi) = (-(1i64 << (bits - 1)), (1i64 << (bits - 1)) - 1);
                if v < lo || v > hi {
                    return Err(msg!("value-does-not-fit", value = shown, dtype = target.name(), min = lo, max = hi));
                }
                v as u64 & mask(bits)
            }
        };
        Ok(target.decode(raw as u32))
    }
}

/// A finite number within a 32-bit float's range (it may lose precision, never overflow).
fn fits_f32(v: f64) -> bool {
    v.is_finite() && v.abs() <= f32::MAX as f64
}

#[cfg(test)]
mod tests {
    #[test]
    fn a_timeout_below_a_microsecond_is_refused_not_made_zero() {
        assert!(parse_timeout("0.0004").unwrap_err().contains("shorter than a microsecond"));
        assert_eq!(parse_timeout("0.001").unwrap(), std::time::Duration::from_micros(1));
    }

    use super::*;

    #[test]
    fn frequencies() {
        assert_eq!(parse_freq_hz("2kHz").unwrap(), 2000.0);
        assert_eq!(parse_freq_hz("1.5khz").unwrap(), 1500.0);
        assert_eq!(parse_freq_hz("200k").unwrap(), 200_000.0);
        assert_eq!(parse_freq_hz("50").unwrap(), 50.0);
        assert!(parse_freq_hz("fast").is_err());
        assert!(parse_freq_hz("2kV").is_err());
        assert!(parse_freq_hz("0Hz").is_err());
        assert!(parse_freq_hz(&format!("1{}kHz", "0".repeat(400))).unwrap_err().contains("too large"));
    }

    fn fit(s: &str, t: DataType) -> Result<Value, String> {
        parse_literal(s).map_err(|e| e.message.text)?.fit(t, t.bits()).map_err(String::from)
    }

    #[test]
    fn every_literal_form_parses() {
        let cases: &[(&str, Value)] = &[
            ("133", Value::Int(133)),
            ("-5", Value::Int(-5)),
            ("16#85", Value::Int(0x85)),
            ("2#1010_0101", Value::Int(0xA5)),
            ("8#17", Value::Int(15)),
            ("B#16#85", Value::Int(0x85)),
            ("b # 16 # 85", Value::Int(0x85)),
            ("W#16#FFFF", Value::Int(0xFFFF)),
            ("DW#16#DEADBEEF", Value::Int(0xDEAD_BEEF)),
            ("DI#100", Value::Int(100)),
            ("INT#-3", Value::Int(-3)),
            ("REAL#1.5", Value::Real(1.5)),
            ("1.5", Value::Real(1.5)),
            ("T#500ms", Value::Int(500)),
            ("T#1s200ms", Value::Int(1200)),
            ("TRUE", Value::Bool(true)),
            ("off", Value::Bool(false)),
        ];
        for (s, v) in cases {
            assert_eq!(parse_literal(s).unwrap().value, *v, "{s}");
        }
    }

    #[test]
    fn values_that_do_not_fit_are_errors_not_wraps() {
        assert_eq!(fit("300", DataType::Byte).unwrap_err(), "300 is out of range for BYTE (0…255)");
        assert!(fit("-1", DataType::Word).unwrap_err().contains("INT#-1"));
        assert_eq!(fit("INT#-1", DataType::Word), Ok(Value::Int(0xFFFF)));
        assert_eq!(fit("16#FFFF", DataType::Int), Ok(Value::Int(-1)));
        assert!(fit("W#16#FFFF", DataType::Byte).is_err());
        assert!(fit("DI#100", DataType::Word).is_err());
        assert_eq!(fit("INT#-3", DataType::DInt), Ok(Value::Int(-3)));
        assert_eq!(fit("-1", DataType::Int), Ok(Value::Int(-1)));
        assert!(fit("32768", DataType::Int).is_err());
        assert!(fit("1.5", DataType::DWord).unwrap_err().contains("REAL"));
        assert_eq!(fit("REAL#1.5", DataType::DWord), Ok(Value::Int(0x3FC0_0000)));
        assert_eq!(fit("2", DataType::Real), Ok(Value::Real(2.0)));
        assert!(fit("5e53", DataType::Real).unwrap_err().contains("does not fit a REAL"));
        assert!(fit("-3.5e38", DataType::Real).is_err());
        assert!(fit("3.4e38", DataType::Real).is_ok());
        assert!(fit("2", DataType::Bool).is_err());
        assert_eq!(fit("1", DataType::Bool), Ok(Value::Bool(true)));
        assert_eq!(
            parse_literal("16").unwrap().fit(DataType::Word, 4).unwrap_err(),
            "16 is out of range for a 4-bit group (0…15)"
        );
    }

    #[test]
    fn bad_literals_point_at_the_column() {
        let e = parse_literal("16#8G").unwrap_err();
        assert_eq!(e.column, 4);
        assert!(e.message.contains("base-16"));
        assert!(parse_literal("X#5").unwrap_err().message.contains("unknown type prefix"));
        assert_eq!(parse_literal("12a").unwrap_err().column, 2);
        assert!(parse_literal("").is_err());
        assert!(parse_literal("INT#40000").is_err());
        assert!(parse_literal("T#5parsecs").is_err());
    }

    #[test]
    fn durations() {
        assert_eq!(parse_duration_us("250us"), Ok(250));
        assert_eq!(parse_duration_us("2.5s"), Ok(2_500_000));
        assert_eq!(parse_duration_us("1m30s"), Ok(90_000_000));
        assert!(parse_duration_us("fast").is_err());
    }

    /// Durations past what an i64 of µs holds saturated (or wrapped, for a
    /// timeout in ms times 1000) instead of being refused.
    #[test]
    fn a_duration_too_long_to_hold_is_refused_naming_the_limit() {
        for text in ["9999999999999999999999h", "3000000000000000000000000000000000000000000s", "106751992d"] {
            let e = parse_duration_us(text).unwrap_err();
            assert!(e.contains("9223372036854775807 µs"), "{text}: {e}");
        }
        assert_eq!(parse_duration_us("106751991d"), Ok(106_751_991 * 86_400_000_000));
        let e = parse_option_duration_us("1e30").unwrap_err();
        assert!(e.contains("9223372036854775807 µs"), "{e}");
        assert_eq!(parse_option_duration_us("2.5"), Ok(2_500));
    }

    #[test]
    fn a_timeout_is_positive_and_at_most_a_day() {
        use std::time::Duration;
        assert_eq!(parse_timeout("200"), Ok(Duration::from_millis(200)));
        assert_eq!(parse_timeout("2s"), Ok(Duration::from_secs(2)));
        assert_eq!(parse_timeout("86400000"), Ok(MAX_TIMEOUT));
        // 18446744073709552 ms × 1000 wrapped to 384 µs.
        for text in ["18446744073709552", "86400001", "25h", "1e30"] {
            let e = parse_timeout(text).unwrap_err();
            assert!(e.contains("86400000 ms"), "{text}: {e}");
        }
        assert!(parse_timeout("0").unwrap_err().contains("more than zero"));
        assert!(parse_timeout("-5").is_err());
    }

    #[test]
    fn a_timeout_in_messages_reads_back_as_the_same_timeout() {
        for (given, shown) in
            [("500", "500 ms"), ("0.5", "0.5 ms"), ("2.25ms", "2.25 ms"), ("1s", "1000 ms"), ("1us", "0.001 ms")]
        {
            assert_eq!(millis_text(parse_timeout(given).unwrap()), shown, "{given}");
        }
        let mut rng = crate::core::test_rng::Rng(0x71_3E0C);
        for _ in 0..2000 {
            let us = 1 + rng.below(86_400_000_000);
            let d = std::time::Duration::from_micros(us);
            let text = millis_text(d);
            let back = parse_timeout(text.trim_end_matches(" ms")).unwrap();
            assert_eq!(back, d, "{text}");
        }
    }
}
