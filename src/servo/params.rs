//! Drive parameter sets: every parameter of the object dictionary ([`super::objects::OBJECTS`])
//! read into a TOML file with the drive's identity, two sets compared, and a set written back
//! to a drive — only what differs, each write read back, the drive's memory stored only when
//! asked (2FF0.01, the same object as `servo save`; seed §1, notes).
//!
//! Which objects are parameters: the table's read-write objects, except the commands
//! (controlword, targets, outputs, the store objects) and the line's own settings (drive id,
//! baud code, user password), which a set restored onto a swapped drive must not change.
//! The Kinco manual lists no parameter groups; plcsh groups objects by the CiA 301 index
//! ranges the drive follows: `ds402` (6000–6FFF, the drive profile) and `kinco`
//! (1000–5FFF, communication and manufacturer objects).
//!
//! A parameter the drive refuses to read (0x80 with an abort code) is kept in the file as
//! `status = "refused"` (or `"missing"` for abort code 16#06020000, "object does not
//! exist") with the drive's answer, never with a guessed value. Writes go through
//! [`ServoOps::write_raw`], which on a device is [`super::ServoAccess`]: the device's write
//! rules see every one of them.

use super::objects::{self, Access, ObjRef, Object, OBJECTS};
use super::{units, ServoOps};
use crate::core::{Error, ErrorKind, Result};
use crate::msg;
use serde::{Deserialize, Serialize};

/// What a set file says the drive is; a file saying anything else is refused on load.
pub const DRIVE_TYPE: &str = "Kinco servo";

/// Read-write objects that are commands or the line's settings, not parameters (module doc).
const NOT_PARAMETERS: &[&str] = &[
    "controlword",
    "target_position",
    "target_velocity",
    "target_torque",
    "target_speed_rpm",
    "digital_outputs",
    "din_simulate",
    "store_parameters",
    "store_motor_data",
    "drive_id",
    "baud_code",
    "user_password",
];

/// The groups `servo params save FILE GROUP…` takes (module doc).
pub const GROUPS: &[&str] = &["ds402", "kinco"];

/// The group of an object.
pub fn group_of(o: &Object) -> &'static str {
    if o.index >= 0x6000 {
        "ds402"
    } else {
        "kinco"
    }
}

/// Every parameter of the dictionary, in table order.
pub fn parameters() -> impl Iterator<Item = &'static Object> {
    OBJECTS.iter().filter(|o| o.access == Access::ReadWrite && !NOT_PARAMETERS.contains(&o.name))
}

/// The file's `[drive]` table: what the drive is and where and when the set was read.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
pub struct Identity {
    #[serde(rename = "type")]
    pub kind: String,
    /// What the drive reports about itself (the device's model line).
    pub model: String,
    pub id: u8,
    pub url: String,
    /// UTC, RFC 3339.
    pub saved: String,
    pub plcsh: String,
    /// Increments per revolution, for the engineering units of a diff.
    pub encoder_resolution: u32,
    #[serde(default)]
    pub groups: Vec<String>,
}

/// One `[[parameter]]`.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
pub struct Entry {
    pub name: String,
    /// `6081.00`.
    pub object: String,
    #[serde(rename = "type")]
    pub dtype: String,
    pub unit: String,
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub value: Option<i64>,
    /// `refused` or `missing` when there is no value.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub status: Option<String>,
    /// The drive's answer when it refused.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub note: Option<String>,
}

/// A parameter set file.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
pub struct ParamSet {
    pub drive: Identity,
    #[serde(default, rename = "parameter")]
    pub parameters: Vec<Entry>,
}

impl ParamSet {
    /// The file's text.
    pub fn to_toml(&self) -> String {
        toml::to_string(self).expect("a parameter set is plain data")
    }

    /// Reads a set file's text: TOML, the drive type plcsh knows, every object named as the
    /// dictionary names it (same object and type) and every value within its type.
    pub fn parse(text: &str, file: &str) -> Result<ParamSet> {
        let set: ParamSet = toml::from_str(text)
            .map_err(|e| Error::syntax(msg!("servo-params-bad-file", file = file, reason = e.message())))?;
        if set.drive.kind != DRIVE_TYPE {
            return Err(Error::new(
                ErrorKind::Value,
                msg!("servo-params-other-drive", file = file, kind = set.drive.kind.as_str(), expected = DRIVE_TYPE),
            ));
        }
        for (i, e) in set.parameters.iter().enumerate() {
            if set.parameters[..i].iter().any(|x| x.name == e.name) {
                return Err(Error::new(
                    ErrorKind::Value,
                    msg!("servo-params-duplicate", file = file, name = e.name.as_str()),
                ));
            }
            let o = objects::by_name(&e.name).filter(|o| {
                o.address() == e.object && objects::short_type(o.dtype) == e.dtype && parameters().any(|p| p == *o)
            });
            let Some(o) = o else {
                return Err(Error::new(
                    ErrorKind::Value,
                    msg!(
                        "servo-params-unknown-object",
                        file = file,
                        name = e.name.as_str(),
                        object = e.object.as_str(),
                        dtype = e.dtype.as_str()
                    ),
                ));
            };
            if let Some(v) = e.value {
                if !fits(o, v) {
                    return Err(Error::new(
                        ErrorKind::Value,
                        msg!("servo-params-out-of-range", file = file, name = o.name, value = v.to_string()),
                    ));
                }
            }
        }
        Ok(set)
    }

    fn find(&self, name: &str) -> Option<&Entry> {
        self.parameters.iter().find(|e| e.name == name)
    }
}

/// Whether `v` is a value of the object's type.
fn fits(o: &Object, v: i64) -> bool {
    let (lo, hi) = o.dtype.int_range();
    (lo..=hi).contains(&v)
}

/// Reads the parameters of `groups` (all groups when empty). A refusal is listed in the set;
/// a link failure ends the reading with its error.
pub fn read_set(ops: &mut dyn ServoOps, groups: &[&str], mut drive: Identity) -> Result<ParamSet> {
    drive.groups = groups.iter().map(|g| g.to_string()).collect();
    drive.encoder_resolution = ops.resolution().get();
    let mut parameters = Vec::new();
    for o in parameters_of(groups) {
        let (value, status, note) = match ops.read_raw(ObjRef::of(o)) {
            Ok(raw) => (Some(o.dtype.decode(raw).as_i64()), None, None),
            Err(e) if e.kind == ErrorKind::Refused => {
                // Abort code 16#06020000: "object does not exist in the object dictionary".
                let status = if e.message.contains("06020000") { "missing" } else { "refused" };
                (None, Some(status.to_string()), Some(e.message.clone()))
            }
            Err(e) => return Err(e),
        };
        parameters.push(Entry {
            name: o.name.to_string(),
            object: o.address(),
            dtype: objects::short_type(o.dtype).to_string(),
            unit: o.unit.raw_label().to_string(),
            value,
            status,
            note,
        });
    }
    Ok(ParamSet { drive, parameters })
}

fn parameters_of<'a>(groups: &'a [&'a str]) -> impl Iterator<Item = &'static Object> + 'a {
    parameters().filter(move |o| groups.is_empty() || groups.contains(&group_of(o)))
}

/// A group name `servo params save` takes, or the error naming the groups.
pub fn check_group(g: &str) -> Result<()> {
    if GROUPS.contains(&g) {
        Ok(())
    } else {
        Err(Error::usage(msg!("servo-params-unknown-group", group = g, groups = GROUPS.join(", "))))
    }
}

/// One side of a difference.
#[derive(Clone, Debug, PartialEq, Serialize)]
pub struct Side {
    #[serde(skip_serializing_if = "Option::is_none")]
    pub value: Option<i64>,
    /// `value`, `refused`, `missing` or `absent` (not in the set).
    pub status: String,
    /// The value with its unit and engineering value (`819200 DEC = 300 rpm`).
    pub shown: String,
}

/// A parameter whose value differs between two sets.
#[derive(Clone, Debug, PartialEq, Serialize)]
pub struct Difference {
    pub name: String,
    pub object: String,
    pub unit: String,
    pub left: Side,
    pub right: Side,
}

fn side(set: &ParamSet, o: &Object) -> Side {
    match set.find(o.name) {
        None => Side { value: None, status: "absent".into(), shown: "—".into() },
        Some(Entry { value: Some(v), .. }) => {
            let mut shown = format!("{v} {}", o.unit.raw_label()).trim_end().to_string();
            if let Some((e, u)) = units::engineering(o.unit, *v, set.drive.encoder_resolution.max(1)) {
                shown.push_str(&format!(" = {} {u}", units::show(e)));
            }
            Side { value: Some(*v), status: "value".into(), shown }
        }
        Some(e) => {
            let status = e.status.clone().unwrap_or_else(|| "refused".into());
            Side { value: None, shown: status.clone(), status }
        }
    }
}

/// What differs between two sets, in table order: a value against another value, a value
/// against a refusal, a parameter one set has and the other has not.
pub fn diff(left: &ParamSet, right: &ParamSet) -> Vec<Difference> {
    parameters()
        .filter(|o| left.find(o.name).is_some() || right.find(o.name).is_some())
        .filter_map(|o| {
            let (l, r) = (side(left, o), side(right, o));
            (l.value != r.value || l.status != r.status).then(|| Difference {
                name: o.name.to_string(),
                object: o.address(),
                unit: o.unit.raw_label().to_string(),
                left: l,
                right: r,
            })
        })
        .collect()
}

/// One write of a load.
#[derive(Clone, Debug, PartialEq, Serialize)]
pub struct Written {
    pub name: String,
    pub object: String,
    pub old: i64,
    pub new: i64,
}

/// What a load did.
#[derive(Clone, Debug, PartialEq, Serialize)]
pub struct Loaded {
    pub written: Vec<Written>,
    pub unchanged: usize,
    /// Parameters the file lists as refused or missing (not written).
    pub skipped: Vec<String>,
    pub stored: bool,
}

/// Writes the set's values that differ from the drive's, each read back; stops at the first
/// refusal (or differing read-back) naming the parameter; stores (2FF0.01 = 1) when `store`.
/// Every write is declared to the device's write rules before the first is made.
pub fn load(ops: &mut dyn ServoOps, set: &ParamSet, store: bool) -> Result<Loaded> {
    let mut todo = Vec::new();
    let mut unchanged = 0;
    let mut skipped = Vec::new();
    for e in &set.parameters {
        let o = objects::named(&e.name);
        let Some(v) = e.value else {
            skipped.push(e.name.clone());
            continue;
        };
        let r = ObjRef::of(o);
        let old = ops.read_raw(r).map_err(|err| stopped(&err, o, 0))?;
        let old = o.dtype.decode(old).as_i64();
        if old == v {
            unchanged += 1;
        } else {
            todo.push((o, old, v));
        }
    }
    let mut changes: Vec<_> = todo.iter().map(|(o, _, _)| super::changes::write(ObjRef::of(o))).collect();
    if store {
        changes.push(super::changes::write(ObjRef::of(objects::named("store_parameters"))));
    }
    ops.permits(&changes)?;
    let mut written = Vec::new();
    for (o, old, v) in todo {
        let r = ObjRef::of(o);
        ops.write_raw(r, o.dtype.encode(&crate::core::Value::Int(v))).map_err(|err| stopped(&err, o, written.len()))?;
        let back = o.dtype.decode(ops.read_raw(r).map_err(|err| stopped(&err, o, written.len()))?).as_i64();
        if back != v {
            return Err(Error::new(
                ErrorKind::Refused,
                msg!(
                    "servo-params-read-back",
                    name = o.name,
                    object = o.address(),
                    value = v.to_string(),
                    back = back.to_string()
                ),
            )
            .operand(o.name));
        }
        written.push(Written { name: o.name.to_string(), object: o.address(), old, new: v });
    }
    if store {
        super::ds402::save(ops)?;
    }
    Ok(Loaded { written, unchanged, skipped, stored: store })
}

/// The error that stops a load at `o`, after `done` writes, keeping the cause's kind.
fn stopped(err: &Error, o: &Object, done: usize) -> Error {
    let mut e = Error::new(
        err.kind,
        msg!(
            "servo-params-stopped",
            name = o.name,
            object = o.address(),
            written = done as u64,
            reason = err.message.as_str()
        ),
    )
    .operand(o.name);
    if let Some(h) = &err.hint {
        e = e.hint(h.clone());
    }
    e
}

/// Now as RFC 3339 UTC (`2026-12-07T21:08:13Z`), `SOURCE_DATE_EPOCH` when set
/// ([`crate::core::civil::utc_now`]).
pub fn utc_now() -> String {
    crate::core::civil::utc_now()
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn parameters_leave_out_commands_and_line_settings() {
        let names: Vec<&str> = parameters().map(|o| o.name).collect();
        assert!(names.contains(&"profile_velocity") && names.contains(&"gear_divider"));
        for n in NOT_PARAMETERS {
            assert!(objects::by_name(n).is_some(), "{n} is in the table");
            assert!(!names.contains(n), "{n}");
        }
        assert!(!names.contains(&"statusword"), "read-only objects are state, not parameters");
    }

    #[test]
    fn the_clock_text_is_rfc3339() {
        let t = utc_now();
        assert_eq!(t.len(), 20, "{t}");
        assert!(t.ends_with('Z') && t.as_bytes()[10] == b'T', "{t}");
    }
}
