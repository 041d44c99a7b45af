//! PLC data sets (`data save/diff/load`, docs/data-sets.md): the typed values of a device's
//! operands — named ranges, the K2's retentive ranges and its E2PROM backup area — kept in a
//! readable TOML file with the device's identity, compared with another set or with the
//! device, and written back: only what differs, through the device's write rules, each write
//! read back, stopping at the first refusal and naming it.
//!
//! Why a module of its own and not a family's: a set is operands and values, which every
//! family's operand space already parses and names (`get`'s path, [`crate::session::Session::resolve`]),
//! so one format serves the K2 (V, M, SM … and the backup area), the FX PLCs (D registers)
//! and the UMPK (read only: its terminal protocol writes nothing, so a load that has anything
//! to write is refused by the device, naming the operand). The K2's two areas that survive a
//! power cut are reached by name ([`areas`]).
//!
//! This module is the file: its format, its checks and the difference of two sets. Where the
//! values come from and go to is [`device`]. The convention follows `servo params` (the drive
//! parameter sets, `crate::servo::params`): identity table first, a refusal names the file and
//! the entry, a file from another family or model is refused before anything is sent.
//!
//! The file:
//! ```toml
//! [device]
//! family = "k2"
//! model = "K205-16DT"
//! name = "plc"
//! url = "sim:K205-16DT"
//! saved = "2026-12-07T23:10:00Z"
//! plcsh = "0.1.0"
//!
//! [set]
//! operands = ["VB0..VB3", "VD200/REAL", "eeprom"]
//! values = [
//!     { operand = "VB0", type = "BYTE", value = 7 },
//!     { operand = "VD200/REAL", type = "REAL", value = 2.5 },
//! ]
//! ```
//! One line per operand, the value in the operand's type (integers, `true`/`false`, REALs as
//! their shortest decimal that reads back to the same bits).

pub mod areas;
pub mod device;

use crate::core::{DataType, Error, ErrorKind, Result, Value};
use crate::msg;
use serde::{Deserialize, Serialize};
use std::collections::{HashMap, HashSet};

/// The file's `[device]` table: what the device is, and where and when the set was read.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
pub struct Identity {
    /// The device family (`k2`, `fx`, `umpk`): a set loads only onto its own family.
    pub family: String,
    /// The model the device reports (`K205-16DT`, `FX2N`): and only onto its own model.
    pub model: String,
    /// The name the device was open under.
    pub name: String,
    pub url: String,
    /// UTC, RFC 3339.
    pub saved: String,
    pub plcsh: String,
}

/// The model code of a device's model line (`DeviceInfo::model`): the families write it as the
/// code itself (`K205-16DT`, `UMPK16`) or with what reaches it around the code (`simulated FX2N
/// (programming port)`, `FX2N (computer link, station 0)`); a set names the code, so a set saved
/// from a simulator loads onto the real PLC of the same model.
pub fn model_code(line: &str) -> &str {
    let line = line.trim();
    let line = line.strip_prefix("simulated ").unwrap_or(line);
    line.split([' ', ',', '(']).next().unwrap_or(line)
}

/// A value as the file holds it: in the operand's type.
#[derive(Clone, Copy, Debug, PartialEq, Serialize, Deserialize)]
#[serde(untagged)]
pub enum FileValue {
    Bool(bool),
    Int(i64),
    Real(f64),
}

impl FileValue {
    /// The value of a reading of an operand of type `t`.
    pub fn of(t: DataType, v: Value) -> FileValue {
        match t {
            DataType::Bool => FileValue::Bool(v.as_bool()),
            DataType::Real => FileValue::Real(v.as_f64()),
            _ => FileValue::Int(v.as_i64()),
        }
    }

    /// The value to write to an operand of type `t`.
    pub fn value(self) -> Value {
        match self {
            FileValue::Bool(b) => Value::Bool(b),
            FileValue::Int(i) => Value::Int(i),
            FileValue::Real(r) => Value::Real(r),
        }
    }

    /// The bits an operand of type `t` holds for this value: two values are the same when
    /// these are (a REAL compares as the f32 the device stores).
    pub fn bits(self, t: DataType) -> u32 {
        t.encode(&self.value())
    }

    /// The value as the file writes it (`7`, `true`, `2.5`, `nan`).
    pub fn text(self) -> String {
        match self {
            FileValue::Bool(b) => toml::Value::Boolean(b).to_string(),
            FileValue::Int(i) => i.to_string(),
            FileValue::Real(r) => toml::Value::Float(r).to_string(),
        }
    }

    /// Whether the value is one of type `t`: a BOOL is `true`/`false`, an integer type an
    /// integer within its range, a REAL a number (an integer is taken as that REAL).
    fn fits(self, t: DataType) -> bool {
        match (t, self) {
            (DataType::Bool, FileValue::Bool(_)) => true,
            (DataType::Real, FileValue::Real(_) | FileValue::Int(_)) => true,
            (DataType::Bool | DataType::Real, _) | (_, FileValue::Bool(_) | FileValue::Real(_)) => false,
            (_, FileValue::Int(i)) => {
                let (lo, hi) = t.int_range();
                (lo..=hi).contains(&i)
            }
        }
    }
}

/// One operand's value.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
pub struct Entry {
    /// The operand as its device names it (`VW100`, `VD200/REAL`, `D100`).
    pub operand: String,
    /// `BYTE`, `INT`, `REAL` … ([`DataType::name`]).
    #[serde(rename = "type")]
    pub dtype: String,
    pub value: FileValue,
    /// The operand's tag name when the device had one at saving (docs/tags.md): a set saved
    /// by name loads by name. Absent in files written before names, and for operands without
    /// a tag.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub name: Option<String>,
}

impl Entry {
    /// The entry's type (checked by [`DataSet::parse`]).
    pub fn data_type(&self) -> DataType {
        DataType::from_name(&self.dtype).unwrap_or(DataType::Int)
    }
}

/// The file's `[set]` table.
#[derive(Clone, Debug, Default, PartialEq, Serialize, Deserialize)]
pub struct Body {
    /// The operands as they were asked for (ranges, `eeprom`, `retained`).
    #[serde(default)]
    pub operands: Vec<String>,
    #[serde(default)]
    pub values: Vec<Entry>,
}

/// A data set file.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
pub struct DataSet {
    pub device: Identity,
    #[serde(default)]
    pub set: Body,
}

/// Longest operand text a file may hold (the longest name an operand space prints is far
/// shorter; a tag name fits too).
const MAX_OPERAND: usize = 128;

impl DataSet {
    /// The file's text: the identity, then one line per operand (module doc).
    pub fn to_toml(&self) -> String {
        #[derive(Serialize)]
        struct Head<'a> {
            device: &'a Identity,
        }
        let mut out = toml::to_string(&Head { device: &self.device }).expect("an identity is plain data");
        let list = |v: &[String]| v.iter().map(|s| toml::Value::String(s.clone()).to_string()).collect::<Vec<_>>();
        out.push_str("\n[set]\n");
        out.push_str(&format!("operands = [{}]\n", list(&self.set.operands).join(", ")));
        out.push_str("values = [\n");
        for e in &self.set.values {
            let name =
                e.name.as_ref().map(|n| format!(", name = {}", toml::Value::String(n.clone()))).unwrap_or_default();
            out.push_str(&format!(
                "    {{ operand = {}, type = {}, value = {}{name} }},\n",
                toml::Value::String(e.operand.clone()),
                toml::Value::String(e.dtype.clone()),
                e.value.text()
            ));
        }
        out.push_str("]\n");
        out
    }

    /// Reads a set file's text: TOML of the shape above, a family and model named, every
    /// entry's type a type plcsh knows and its value one of that type, no operand twice.
    /// Linear in the text; refuses with a message naming the file and the entry.
    pub fn parse(text: &str, file: &str) -> Result<DataSet> {
        let set: DataSet = toml::from_str(text)
            .map_err(|e| Error::syntax(msg!("data-bad-file", file = file, reason = e.message())))?;
        if set.device.family.trim().is_empty() || set.device.model.trim().is_empty() {
            return Err(Error::syntax(msg!("data-no-identity", file = file)));
        }
        let mut seen = HashSet::with_capacity(set.set.values.len());
        for e in &set.set.values {
            if e.operand.is_empty() || e.operand.len() > MAX_OPERAND || e.operand.contains(char::is_whitespace) {
                return Err(Error::new(
                    ErrorKind::Value,
                    msg!("data-bad-operand", file = file, operand = e.operand.as_str()),
                ));
            }
            let t = DataType::from_name(&e.dtype).filter(|t| t.name() == e.dtype);
            let Some(t) = t else {
                return Err(Error::new(
                    ErrorKind::Value,
                    msg!("data-bad-type", file = file, operand = e.operand.as_str(), dtype = e.dtype.as_str()),
                ));
            };
            if !e.value.fits(t) {
                return Err(Error::new(
                    ErrorKind::Value,
                    msg!(
                        "data-bad-value",
                        file = file,
                        operand = e.operand.as_str(),
                        dtype = e.dtype.as_str(),
                        value = e.value.text()
                    ),
                )
                .operand(e.operand.as_str()));
            }
            if !seen.insert(e.operand.as_str()) {
                return Err(Error::new(
                    ErrorKind::Value,
                    msg!("data-duplicate", file = file, operand = e.operand.as_str()),
                )
                .operand(e.operand.as_str()));
            }
        }
        Ok(set)
    }

    /// Refuses a set read from another family or model than `family`/`model` (device `name`).
    pub fn check_device(&self, file: &str, name: &str, family: &str, model: &str) -> Result<()> {
        let model = model_code(model);
        if self.device.family == family && model_code(&self.device.model).eq_ignore_ascii_case(model) {
            return Ok(());
        }
        Err(Error::new(
            ErrorKind::Value,
            msg!(
                "data-other-device",
                file = file,
                family = self.device.family.as_str(),
                model = self.device.model.as_str(),
                device = name,
                dfamily = family,
                dmodel = model
            ),
        )
        .device(name))
    }
}

/// An operand whose value differs between two sets (or a set and a device).
#[derive(Clone, Debug, PartialEq, Serialize)]
pub struct Difference {
    pub operand: String,
    /// The operand's tag name, from either side (`data diff` shows it beside the operand).
    #[serde(skip_serializing_if = "Option::is_none")]
    pub name: Option<String>,
    #[serde(rename = "type")]
    pub dtype: String,
    /// `None` when the left set does not hold the operand.
    pub left: Option<FileValue>,
    pub right: Option<FileValue>,
}

impl Difference {
    /// A side as a table shows it (`—` when absent).
    pub fn shown(v: Option<FileValue>) -> String {
        v.map_or_else(|| "—".to_string(), |v| v.text())
    }
}

/// What differs between two sets: the left set's operands in its order, then those only the
/// right one holds. An operand the two hold as different types differs.
pub fn diff(left: &DataSet, right: &DataSet) -> Vec<Difference> {
    let r: HashMap<&str, &Entry> = right.set.values.iter().map(|e| (e.operand.as_str(), e)).collect();
    let l: HashSet<&str> = left.set.values.iter().map(|e| e.operand.as_str()).collect();
    let mut out = Vec::new();
    for e in &left.set.values {
        let t = e.data_type();
        match r.get(e.operand.as_str()) {
            Some(o) if o.dtype == e.dtype && o.value.bits(t) == e.value.bits(t) => {}
            other => out.push(Difference {
                operand: e.operand.clone(),
                name: e.name.clone().or_else(|| other.and_then(|o| o.name.clone())),
                dtype: e.dtype.clone(),
                left: Some(e.value),
                right: other.map(|o| o.value),
            }),
        }
    }
    for e in right.set.values.iter().filter(|e| !l.contains(e.operand.as_str())) {
        out.push(Difference {
            operand: e.operand.clone(),
            name: e.name.clone(),
            dtype: e.dtype.clone(),
            left: None,
            right: Some(e.value),
        });
    }
    out
}

#[cfg(test)]
mod tests {
    use super::*;

    fn file(values: &str) -> String {
        format!(
            "[device]\nfamily = \"k2\"\nmodel = \"K205-16DT\"\nname = \"plc\"\nurl = \"sim:K205-16DT\"\n\
             saved = \"2026-12-07T23:10:00Z\"\nplcsh = \"0.1.0\"\n\n[set]\noperands = [\"VB0\"]\nvalues = [\n{values}]\n"
        )
    }

    #[test]
    fn a_set_writes_one_line_per_operand_and_reads_back_the_same() {
        let text = file(
            "{ operand = \"VB0\", type = \"BYTE\", value = 255 },\n\
             { operand = \"VW2\", type = \"INT\", value = -5 },\n\
             { operand = \"VD4/REAL\", type = \"REAL\", value = 3.14 },\n\
             { operand = \"M0.0\", type = \"BOOL\", value = true },\n",
        );
        let set = DataSet::parse(&text, "a.toml").unwrap();
        assert_eq!(set.set.values.len(), 4);
        let again = set.to_toml();
        assert!(again.contains("    { operand = \"VD4/REAL\", type = \"REAL\", value = 3.14 },\n"), "{again}");
        assert_eq!(DataSet::parse(&again, "b.toml").unwrap(), set);
        assert!(diff(&set, &set).is_empty());
    }

    #[test]
    fn a_value_outside_its_type_a_type_plcsh_does_not_know_and_a_twice_listed_operand_are_refused() {
        for (values, code) in [
            ("{ operand = \"VB0\", type = \"BYTE\", value = 256 },\n", "data-bad-value"),
            ("{ operand = \"VB0\", type = \"BYTE\", value = 1.5 },\n", "data-bad-value"),
            ("{ operand = \"M0.0\", type = \"BOOL\", value = 1 },\n", "data-bad-value"),
            ("{ operand = \"VB0\", type = \"byte\", value = 1 },\n", "data-bad-type"),
            ("{ operand = \"VB0\", type = \"U8\", value = 1 },\n", "data-bad-type"),
            ("{ operand = \"VB0\", type = \"BYTE\", value = 1 },\n{ operand = \"VB0\", type = \"BYTE\", value = 2 },\n", "data-duplicate"),
            ("{ operand = \"V B0\", type = \"BYTE\", value = 1 },\n", "data-bad-operand"),
            ("{ operand = \"VB0\", type = \"BYTE\" },\n", "data-bad-file"),
        ] {
            let e = DataSet::parse(&file(values), "x.toml").unwrap_err();
            assert_eq!(e.code, code, "{values}: {e}");
            assert!(e.message.contains("x.toml"), "{e}");
        }
        assert_eq!(DataSet::parse("[device\n", "x.toml").unwrap_err().code, "data-bad-file");
    }

    #[test]
    fn a_set_is_refused_by_a_device_of_another_family_or_model() {
        let set = DataSet::parse(&file(""), "x.toml").unwrap();
        set.check_device("x.toml", "plc", "k2", "k205-16dt").unwrap();
        let e = set.check_device("x.toml", "plc2", "k2", "K209M-56DT").unwrap_err();
        assert_eq!(e.code, "data-other-device");
        assert!(e.message.contains("K205-16DT") && e.message.contains("K209M-56DT"), "{e}");
        assert_eq!(set.check_device("x.toml", "fx", "fx", "FX2N").unwrap_err().code, "data-other-device");
        assert_eq!(model_code("simulated FX2N (programming port)"), "FX2N");
        assert_eq!(model_code("FX2N (computer link, station 0)"), "FX2N");
        assert_eq!(model_code("K205-16DT"), "K205-16DT");
    }

    #[test]
    fn the_difference_names_changed_missing_and_retyped_operands_in_order() {
        let a = DataSet::parse(
            &file(
                "{ operand = \"VB0\", type = \"BYTE\", value = 1 },\n\
                 { operand = \"VB1\", type = \"BYTE\", value = 2 },\n\
                 { operand = \"VD4/REAL\", type = \"REAL\", value = 0.1 },\n\
                 { operand = \"VW6\", type = \"INT\", value = 1 },\n",
            ),
            "a",
        )
        .unwrap();
        let b = DataSet::parse(
            &file(
                "{ operand = \"VW8\", type = \"INT\", value = 9 },\n\
                 { operand = \"VB1\", type = \"BYTE\", value = 3 },\n\
                 { operand = \"VD4/REAL\", type = \"REAL\", value = 0.10000000149011612 },\n\
                 { operand = \"VW6\", type = \"WORD\", value = 1 },\n",
            ),
            "b",
        )
        .unwrap();
        let d = diff(&a, &b);
        let names: Vec<&str> = d.iter().map(|x| x.operand.as_str()).collect();
        // 0.1 and the f32 nearest it are the same REAL; VB0 only left, VW8 only right.
        assert_eq!(names, ["VB0", "VB1", "VW6", "VW8"]);
        assert_eq!((d[0].right, d[3].left), (None, None));
        assert_eq!(d[1].right, Some(FileValue::Int(3)));
    }
}
