//! Engineering units for servo objects (`../shared/spec/kinco-servo.md` §4).
//!
//! Drives take speeds and accelerations as internal "DEC" integers:
//! `DEC = rpm × 512 × R / 1875` and `DEC = rps/s × 65536 × R / 4 000 000`, where R is the
//! motor's feedback resolution (increments per revolution; Kinco motors mostly 10000 or
//! 65536). The manual's rounded factors (×2731, ×164 for R = 10000) are NOT used: the exact
//! formula is evaluated in integer arithmetic on the decimal the user typed and rounded
//! once, half away from zero (the manual's 四舍五入). Positions accept `rev` (× R).
//!
//! The resolution is per device: [`Resolution`] is a shared cell, so a device's operand
//! space (which parses `300rpm`) and its driver (which can read 6410.03 from the drive) see
//! the same value.

use crate::core::msg::Msg;
use crate::msg;
use std::sync::atomic::{AtomicU32, Ordering};
use std::sync::Arc;

/// Default feedback resolution (increments per revolution) when none is configured.
pub const DEFAULT_RESOLUTION: u32 = 10_000;

/// A device's encoder resolution, shared between its operand space and its driver.
#[derive(Clone, Debug)]
pub struct Resolution(Arc<AtomicU32>);

impl Default for Resolution {
    fn default() -> Self {
        Resolution::new(DEFAULT_RESOLUTION)
    }
}

impl Resolution {
    pub fn new(r: u32) -> Resolution {
        Resolution(Arc::new(AtomicU32::new(r)))
    }
    pub fn get(&self) -> u32 {
        self.0.load(Ordering::Relaxed)
    }
    /// Sets the resolution; zero is refused by the caller's validation ([`parse_resolution`]).
    pub fn set(&self, r: u32) {
        self.0.store(r.max(1), Ordering::Relaxed)
    }
}

/// Parses a resolution setting (`10000`, `65536`), refusing 0 and non-numbers.
pub fn parse_resolution(text: &str) -> Result<u32, Msg> {
    match text.trim().replace('_', "").parse::<u32>() {
        Ok(r) if r > 0 => Ok(r),
        _ => Err(msg!("tbl-unit-bad-resolution", text = text, max = u32::MAX.to_string())),
    }
}

/// The engineering unit an object's value can be written in and shown as.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Unit {
    /// No unit (codes, counts, ids).
    None,
    /// A bit field (controlword, statusword, inputs).
    Bits,
    /// Encoder increments; engineering form `rev`.
    Increments,
    /// Speed DEC; engineering form `rpm`.
    Speed,
    /// Acceleration DEC; engineering form `rps/s`.
    Accel,
    /// Kinco operating mode number.
    Mode,
    Ohm,
    Watt,
    Second,
}

impl Unit {
    /// The raw unit's label (`inc`, `DEC` …).
    pub fn raw_label(self) -> &'static str {
        match self {
            Unit::None | Unit::Mode => "",
            Unit::Bits => "bits",
            Unit::Increments => "inc",
            Unit::Speed | Unit::Accel => "DEC",
            Unit::Ohm => "Ω",
            Unit::Watt => "W",
            Unit::Second => "s",
        }
    }
    /// The engineering suffix a value can be written with (`rpm`, `rps/s`, `rev`).
    pub fn eng_label(self) -> Option<&'static str> {
        match self {
            Unit::Increments => Some("rev"),
            Unit::Speed => Some("rpm"),
            Unit::Accel => Some("rps/s"),
            _ => None,
        }
    }
}

/// A decimal number as typed: `mantissa / 10^scale` (exact, no float).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct Decimal {
    pub mantissa: i128,
    pub scale: u32,
}

/// Parses `300`, `-12.5`, `0.001` exactly.
pub fn parse_decimal(s: &str) -> Option<Decimal> {
    let s = s.trim();
    let (neg, body) = match s.strip_prefix('-') {
        Some(r) => (true, r),
        None => (false, s.strip_prefix('+').unwrap_or(s)),
    };
    let body = body.replace('_', "");
    let (int, frac) = body.split_once('.').unwrap_or((&body, ""));
    if (int.is_empty() && frac.is_empty()) || !int.chars().chain(frac.chars()).all(|c| c.is_ascii_digit()) {
        return None;
    }
    if int.len() + frac.len() > 30 {
        return None;
    }
    let digits = format!("{int}{frac}");
    let m: i128 = digits.parse().ok()?;
    Some(Decimal { mantissa: if neg { -m } else { m }, scale: frac.len() as u32 })
}

/// `round(n / d)`, half away from zero (d > 0).
fn div_round(n: i128, d: i128) -> i128 {
    let q = n / d;
    let r = n % d;
    if 2 * r.abs() >= d {
        q + n.signum()
    } else {
        q
    }
}

/// `value × num / den`, exact until one final rounding. A product past i128 (30 typed
/// digits times a large resolution) saturates, so the object's range check refuses it.
fn scale(v: Decimal, num: i128, den: i128) -> i128 {
    match v.mantissa.checked_mul(num) {
        Some(n) => div_round(n, den * 10i128.pow(v.scale)),
        None => i128::MAX * v.mantissa.signum() * num.signum(),
    }
}

/// Speed DEC from rpm: `DEC = rpm × 512 × R / 1875`, rounded once.
pub fn rpm_to_dec(rpm: Decimal, r: u32) -> i128 {
    scale(rpm, 512 * r as i128, 1875)
}

/// Acceleration DEC from rps/s: `DEC = rps/s × 65536 × R / 4 000 000`, rounded once.
pub fn rps2_to_dec(rps2: Decimal, r: u32) -> i128 {
    scale(rps2, 65536 * r as i128, 4_000_000)
}

/// Increments from revolutions: `inc = rev × R`, rounded once.
pub fn rev_to_inc(rev: Decimal, r: u32) -> i128 {
    scale(rev, r as i128, 1)
}

pub fn dec_to_rpm(dec: i64, r: u32) -> f64 {
    dec as f64 * 1875.0 / (512.0 * r as f64)
}

pub fn dec_to_rps2(dec: i64, r: u32) -> f64 {
    dec as f64 * 4_000_000.0 / (65536.0 * r as f64)
}

/// Converts `number + suffix` text for an object of `unit` into its raw integer.
/// Returns `None` when the text has no engineering suffix (plain numbers and IEC
/// literals go through the normal literal parser). Errors name what the object takes.
pub fn parse_engineering(text: &str, unit: Unit, r: u32) -> Option<Result<i128, Msg>> {
    let t = text.trim();
    let lower = t.to_ascii_lowercase();
    const SUFFIXES: [&str; 5] = ["rps/s", "rpm", "rev", "inc", "dec"];
    let Some(suffix) = SUFFIXES.iter().find(|s| lower.ends_with(*s) && lower.len() > s.len()) else {
        // A number with a unit this object does not know (`300rps`): named as typed.
        let at = lower.find(|c: char| c.is_ascii_alphabetic() || c == '/')?;
        let (number, unit_text) = (&t[..at], &t[at..]);
        if parse_decimal(number).is_none() || !unit_text.chars().all(|c| c.is_ascii_alphabetic() || c == '/') {
            return None;
        }
        return Some(Err(match unit {
            Unit::Speed => msg!("tbl-unit-unknown-speed", unit = unit_text, number = number),
            Unit::Accel => msg!("tbl-unit-unknown-accel", unit = unit_text, number = number),
            Unit::Increments => msg!("tbl-unit-unknown-position", unit = unit_text, number = number),
            // Other objects read their own units (`5s`, `100W`) elsewhere.
            _ => return None,
        }));
    };
    let number = t[..t.len() - suffix.len()].trim();
    let Some(d) = parse_decimal(number) else {
        return Some(Err(msg!("tbl-unit-not-a-number", number = number, suffix = *suffix)));
    };
    let wanted = match *suffix {
        "rpm" => Unit::Speed,
        "rps/s" => Unit::Accel,
        "rev" | "inc" => Unit::Increments,
        _ => {
            // `dec` is the raw unit of speeds and accelerations.
            if matches!(unit, Unit::Speed | Unit::Accel) {
                unit
            } else {
                Unit::Speed
            }
        }
    };
    if wanted != unit {
        return Some(Err(match unit.eng_label() {
            Some(e) => msg!("tbl-unit-takes", raw = unit.raw_label(), eng = e, suffix = *suffix),
            None => msg!("tbl-unit-takes-plain", suffix = *suffix),
        }));
    }
    let exact_int = |d: Decimal| {
        if d.scale == 0 {
            Ok(d.mantissa)
        } else {
            Err(msg!("tbl-unit-not-whole", number = number, suffix = *suffix))
        }
    };
    Some(match *suffix {
        "rpm" => Ok(rpm_to_dec(d, r)),
        "rps/s" => Ok(rps2_to_dec(d, r)),
        "rev" => Ok(rev_to_inc(d, r)),
        _ => exact_int(d),
    })
}

/// The unit rule for servo *commands* and Lua methods (`servo move … speed=300 acc=100`,
/// `servo jog 300`, `servo:move_abs(p, {rpm=300, acc=100})`): a bare number is in engineering
/// units — rpm for speeds, rps/s for accelerations — and the drive's raw value is written
/// with its suffix (`speed=2731dec`). Register writes (`set servo:profile_velocity=…`) keep
/// the object's raw unit, as every register does. Positions stay in increments (`rev` for
/// revolutions). Returns the text with the engineering suffix added where it was bare.
pub fn command_value(text: &str, unit: Unit) -> std::borrow::Cow<'_, str> {
    let bare = parse_decimal(text.trim()).is_some();
    match (bare, unit) {
        (true, Unit::Speed) => format!("{}rpm", text.trim()).into(),
        (true, Unit::Accel) => format!("{}rps/s", text.trim()).into(),
        _ => text.into(),
    }
}

/// A raw value in engineering units, for display: `(300.0, "rpm")`.
pub fn engineering(unit: Unit, raw: i64, r: u32) -> Option<(f64, &'static str)> {
    match unit {
        Unit::Speed => Some((dec_to_rpm(raw, r), "rpm")),
        Unit::Accel => Some((dec_to_rps2(raw, r), "rps/s")),
        Unit::Increments => Some((raw as f64 / r as f64, "rev")),
        _ => None,
    }
}

/// Formats an engineering value with up to 3 decimals, trailing zeros trimmed.
pub fn show(v: f64) -> String {
    let s = format!("{v:.3}");
    let s = s.trim_end_matches('0').trim_end_matches('.');
    if s == "-0" {
        "0".into()
    } else {
        s.to_string()
    }
}

#[cfg(test)]
mod command_value_tests {
    use super::*;

    #[test]
    fn bare_command_numbers_are_engineering_units_and_raw_needs_its_suffix() {
        assert_eq!(command_value("300", Unit::Speed), "300rpm");
        assert_eq!(command_value("100", Unit::Accel), "100rps/s");
        assert_eq!(command_value("2731dec", Unit::Speed), "2731dec");
        assert_eq!(command_value("16#10", Unit::Speed), "16#10");
        assert_eq!(command_value("10000", Unit::Increments), "10000");
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn d(s: &str) -> Decimal {
        parse_decimal(s).unwrap()
    }

    #[test]
    fn exact_formulas_round_once() {
        // 300 rpm × 512 × 10000 / 1875 = 819200 exactly.
        assert_eq!(rpm_to_dec(d("300"), 10_000), 819_200);
        // 1 rpm = 2730.67 → 2731 (the manual's factor), but 100 rpm = 273066.67 → 273067,
        // not 100 × 2731 = 273100: the factor is not multiplied, the formula is.
        assert_eq!(rpm_to_dec(d("1"), 10_000), 2731);
        assert_eq!(rpm_to_dec(d("100"), 10_000), 273_067);
        assert_eq!(rpm_to_dec(d("1"), 65_536), 17_896);
        // Acceleration: 1 rps/s = 163.84 → 164; 100 rps/s = 16384 exactly.
        assert_eq!(rps2_to_dec(d("1"), 10_000), 164);
        assert_eq!(rps2_to_dec(d("100"), 10_000), 16_384);
        assert_eq!(rps2_to_dec(d("1"), 65_536), 1074);
        // Negative speeds round half away from zero; decimals are exact.
        assert_eq!(rpm_to_dec(d("-1"), 10_000), -2731);
        assert_eq!(rpm_to_dec(d("0.5"), 10_000), 1365); // 1365.33
        assert_eq!(rev_to_inc(d("2.5"), 10_000), 25_000);
        // 30 digits times a large resolution saturates instead of overflowing.
        let big = d("999999999999999999999999999999");
        assert!(rps2_to_dec(big, u32::MAX) > i64::MAX as i128);
        assert!(rpm_to_dec(Decimal { mantissa: -big.mantissa, scale: 0 }, u32::MAX) < i64::MIN as i128);
    }

    #[test]
    fn engineering_text_is_checked_against_the_unit() {
        assert_eq!(parse_engineering("300rpm", Unit::Speed, 10_000), Some(Ok(819_200)));
        assert_eq!(parse_engineering("100 rps/s", Unit::Accel, 10_000), Some(Ok(16_384)));
        assert_eq!(parse_engineering("1rev", Unit::Increments, 65_536), Some(Ok(65_536)));
        assert_eq!(parse_engineering("500", Unit::Speed, 10_000), None, "plain numbers are DEC");
        assert!(parse_engineering("300rpm", Unit::Accel, 10_000).unwrap().is_err());
        assert!(parse_engineering("300rpm", Unit::Bits, 10_000).unwrap().unwrap_err().contains("plain numbers"));
        assert!(parse_engineering("x1rpm", Unit::Speed, 10_000).unwrap().is_err());
        assert_eq!(parse_engineering("7dec", Unit::Accel, 10_000), Some(Ok(7)));
    }

    #[test]
    fn display_inverts_the_formula() {
        let (v, u) = engineering(Unit::Speed, 819_200, 10_000).unwrap();
        assert_eq!((show(v).as_str(), u), ("300", "rpm"));
        assert_eq!(show(dec_to_rps2(16_384, 10_000)), "100");
        assert_eq!(engineering(Unit::Bits, 5, 10_000), None);
        assert!(parse_resolution("0").is_err());
        assert_eq!(parse_resolution("65536"), Ok(65536));
    }
}
