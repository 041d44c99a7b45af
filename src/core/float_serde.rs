//! Saved state's `f64`s, infinities and NaN included: JSON has no number for them, and
//! serde_json writes a non-finite `f64` as `null`, which it then refuses to read back as a
//! number. A simulator's state holds such values on purpose (the last stretch of a planned
//! motion lasts forever: its duration is `+∞`), so a snapshot written that way could not be
//! restored.
//!
//! `#[serde(with = "crate::core::float_serde")]` on an `f64` field writes a finite value as
//! the JSON number it always was (files stay as they were) and a non-finite one as the
//! string `"inf"`, `"-inf"` or `"nan"`; it reads numbers and those strings. Submodules cover
//! the other shapes saved state has: [`option`] (`Option<f64>`), [`duration`] (an `f64`
//! duration, where an earlier plcsh's `null` can only have meant `+∞`), [`pairs`]
//! (`Vec<(f64, T)>`) and [`triples`] (`Vec<(f64, f64, T)>`).
//!
//! [`crate::snapshot`] also checks every file it writes by reading it back, so a field that
//! misses this attribute makes the save fail by name instead of writing a file that cannot
//! be restored.

use serde::de::{self, Deserializer, Unexpected, Visitor};
use serde::{Deserialize, Serialize, Serializer};

/// An `f64` as saved state writes it (see the module doc).
#[derive(Clone, Copy, Debug)]
pub struct Float(pub f64);

impl Serialize for Float {
    fn serialize<S: Serializer>(&self, s: S) -> Result<S::Ok, S::Error> {
        let x = self.0;
        if x.is_finite() {
            s.serialize_f64(x)
        } else if x.is_nan() {
            s.serialize_str("nan")
        } else if x > 0.0 {
            s.serialize_str("inf")
        } else {
            s.serialize_str("-inf")
        }
    }
}

/// Reads a number or one of the three words; `null` reads as `null_is` when given.
struct FloatVisitor {
    null_is: Option<f64>,
}

impl<'de> Visitor<'de> for FloatVisitor {
    type Value = f64;

    fn expecting(&self, f: &mut std::fmt::Formatter) -> std::fmt::Result {
        f.write_str("a number, \"inf\", \"-inf\" or \"nan\"")
    }
    fn visit_f64<E: de::Error>(self, v: f64) -> Result<f64, E> {
        Ok(v)
    }
    fn visit_i64<E: de::Error>(self, v: i64) -> Result<f64, E> {
        Ok(v as f64)
    }
    fn visit_u64<E: de::Error>(self, v: u64) -> Result<f64, E> {
        Ok(v as f64)
    }
    fn visit_str<E: de::Error>(self, v: &str) -> Result<f64, E> {
        match v {
            "inf" => Ok(f64::INFINITY),
            "-inf" => Ok(f64::NEG_INFINITY),
            "nan" => Ok(f64::NAN),
            _ => Err(E::invalid_value(Unexpected::Str(v), &self)),
        }
    }
    fn visit_unit<E: de::Error>(self) -> Result<f64, E> {
        self.null_is.ok_or_else(|| E::invalid_type(Unexpected::Unit, &self))
    }
}

impl<'de> Deserialize<'de> for Float {
    fn deserialize<D: Deserializer<'de>>(d: D) -> Result<Float, D::Error> {
        d.deserialize_any(FloatVisitor { null_is: None }).map(Float)
    }
}

pub fn serialize<S: Serializer>(v: &f64, s: S) -> Result<S::Ok, S::Error> {
    Float(*v).serialize(s)
}

pub fn deserialize<'de, D: Deserializer<'de>>(d: D) -> Result<f64, D::Error> {
    Float::deserialize(d).map(|f| f.0)
}

/// `Option<f64>`: `None` is `null`, a value as [`Float`].
pub mod option {
    use super::Float;
    use serde::{Deserialize, Deserializer, Serialize, Serializer};

    pub fn serialize<S: Serializer>(v: &Option<f64>, s: S) -> Result<S::Ok, S::Error> {
        v.map(Float).serialize(s)
    }

    pub fn deserialize<'de, D: Deserializer<'de>>(d: D) -> Result<Option<f64>, D::Error> {
        Ok(Option::<Float>::deserialize(d)?.map(|f| f.0))
    }
}

/// A duration in seconds that may be `+∞` (a stretch that never ends). Snapshots written
/// by an earlier plcsh hold such a duration as `null`, which reads as `+∞` here, so those
/// files restore too.
pub mod duration {
    use super::{Float, FloatVisitor};
    use serde::{Deserializer, Serialize, Serializer};

    pub fn serialize<S: Serializer>(v: &f64, s: S) -> Result<S::Ok, S::Error> {
        Float(*v).serialize(s)
    }

    pub fn deserialize<'de, D: Deserializer<'de>>(d: D) -> Result<f64, D::Error> {
        d.deserialize_any(FloatVisitor { null_is: Some(f64::INFINITY) })
    }
}

/// `Vec<(f64, T)>`: each pair's number as [`Float`].
pub mod pairs {
    use super::Float;
    use serde::{Deserialize, Deserializer, Serialize, Serializer};

    pub fn serialize<S: Serializer, T: Serialize>(v: &[(f64, T)], s: S) -> Result<S::Ok, S::Error> {
        s.collect_seq(v.iter().map(|(x, t)| (Float(*x), t)))
    }

    pub fn deserialize<'de, D: Deserializer<'de>, T: Deserialize<'de>>(d: D) -> Result<Vec<(f64, T)>, D::Error> {
        Ok(Vec::<(Float, T)>::deserialize(d)?.into_iter().map(|(x, t)| (x.0, t)).collect())
    }
}

/// `Vec<(f64, f64, T)>`: each triple's numbers as [`Float`].
pub mod triples {
    use super::Float;
    use serde::{Deserialize, Deserializer, Serialize, Serializer};

    pub fn serialize<S: Serializer, T: Serialize>(v: &[(f64, f64, T)], s: S) -> Result<S::Ok, S::Error> {
        s.collect_seq(v.iter().map(|(x, y, t)| (Float(*x), Float(*y), t)))
    }

    pub fn deserialize<'de, D: Deserializer<'de>, T: Deserialize<'de>>(d: D) -> Result<Vec<(f64, f64, T)>, D::Error> {
        Ok(Vec::<(Float, Float, T)>::deserialize(d)?.into_iter().map(|(x, y, t)| (x.0, y.0, t)).collect())
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::core::test_rng::Rng;

    #[derive(Debug, Serialize, Deserialize)]
    struct S {
        #[serde(with = "super")]
        x: f64,
        #[serde(with = "super::option")]
        o: Option<f64>,
        #[serde(with = "super::duration")]
        d: f64,
        #[serde(with = "super::pairs")]
        p: Vec<(f64, u16)>,
        #[serde(with = "super::triples")]
        t: Vec<(f64, f64, u16)>,
    }

    /// Same value, NaN equal to NaN and -0 apart from +0.
    fn same(a: f64, b: f64) -> bool {
        a.to_bits() == b.to_bits() || (a.is_nan() && b.is_nan())
    }

    fn round_trip(s: &S) -> (String, S) {
        let text = serde_json::to_string(s).unwrap();
        // Through text (a file) and through a `serde_json::Value` (a snapshot section).
        let back: S = serde_json::from_str(&text).unwrap_or_else(|e| panic!("{text}: {e}"));
        let via: S = serde_json::from_value(serde_json::to_value(s).unwrap()).unwrap();
        assert_eq!(serde_json::to_string(&via).unwrap(), text);
        (text, back)
    }

    #[test]
    fn non_finite_values_are_written_as_words_and_read_back() {
        let s = S {
            x: f64::INFINITY,
            o: Some(f64::NEG_INFINITY),
            d: f64::NAN,
            p: vec![(f64::INFINITY, 7)],
            t: vec![(f64::NAN, f64::NEG_INFINITY, 9)],
        };
        let (text, back) = round_trip(&s);
        assert_eq!(
            text, r#"{"x":"inf","o":"-inf","d":"nan","p":[["inf",7]],"t":[["nan","-inf",9]]}"#,
            "finite numbers stay numbers, the rest are words"
        );
        assert!(same(back.x, s.x) && same(back.o.unwrap(), s.o.unwrap()) && same(back.d, s.d));
        assert!(same(back.p[0].0, f64::INFINITY) && back.p[0].1 == 7);
        assert!(same(back.t[0].0, f64::NAN) && same(back.t[0].1, f64::NEG_INFINITY) && back.t[0].2 == 9);
    }

    #[test]
    fn finite_values_keep_their_json_and_integers_read_as_numbers() {
        let s = S { x: 1.5, o: None, d: 2.0, p: vec![], t: vec![] };
        assert_eq!(round_trip(&s).0, r#"{"x":1.5,"o":null,"d":2.0,"p":[],"t":[]}"#);
        let back: S = serde_json::from_str(r#"{"x":3,"o":-4,"d":5,"p":[[6,1]],"t":[[7,-8,2]]}"#).unwrap();
        assert_eq!((back.x, back.o, back.d, back.p[0].0, back.t[0].1), (3.0, Some(-4.0), 5.0, 6.0, -8.0));
    }

    /// An earlier plcsh wrote an endless duration as `null`: it reads as +∞; anywhere else
    /// `null` is not a number, and words other than the three are refused.
    #[test]
    fn null_is_an_endless_duration_and_nothing_else() {
        let back: S = serde_json::from_str(r#"{"x":0,"o":null,"d":null,"p":[],"t":[]}"#).unwrap();
        assert_eq!(back.d, f64::INFINITY);
        let e = serde_json::from_str::<S>(r#"{"x":null,"o":null,"d":0,"p":[],"t":[]}"#).unwrap_err();
        assert!(e.to_string().contains("expected a number, \"inf\", \"-inf\" or \"nan\""), "{e}");
        let e = serde_json::from_str::<S>(r#"{"x":"infinity","o":null,"d":0,"p":[],"t":[]}"#).unwrap_err();
        assert!(e.to_string().contains("infinity"), "{e}");
    }

    /// Every f64 comes back bit for bit, through a file's text and through a JSON value:
    /// random bit patterns (all exponents, subnormals, -0) and the special values.
    #[test]
    fn every_f64_round_trips_exactly() {
        let seed = 0x5EED_F10A_7000_0001;
        let mut rng = Rng(seed);
        let mut values = vec![0.0, -0.0, f64::MIN_POSITIVE, f64::MAX, f64::MIN, 5e-324, 0.1, 1.0 / 3.0];
        values.extend((0..20_000).map(|_| f64::from_bits(rng.next_u64())));
        for x in values {
            let s = S { x, o: Some(x), d: x, p: vec![(x, 1)], t: vec![(x, x, 2)] };
            let (text, back) = round_trip(&s);
            let ok =
                [back.x, back.o.unwrap(), back.d, back.p[0].0, back.t[0].0, back.t[0].1].iter().all(|b| same(*b, x));
            assert!(ok, "seed {seed:#x}: {x:e} ({:#018x}) came back changed from {text}", x.to_bits());
        }
    }
}
