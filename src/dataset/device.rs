//! A data set against a device: read from it (`data save`), compared with it (`data diff`),
//! written to it (`data load`). Operands go the way `get`'s go ([`Session::resolve`]), so
//! whatever that path accepts — ranges, views, a device prefix, names where they exist — a
//! set accepts too; values go through the session's checks and the device's write rules
//! (the guard), which see every write.
//!
//! A load reads the device's values of every operand of the set in one batch, asks the
//! device's rules for all the writes it will make before making one (a read-only device or
//! a profile's allow list refuses the whole load, nothing sent), then writes one operand at
//! a time and reads it back, stopping at the first refusal or differing read-back and naming
//! the operand and how many writes were made. An operand whose value is already the set's is
//! never written. The same rule as `servo params load` (crate::servo::params).

use super::{areas, Body, DataSet, Entry, FileValue, Identity};
use crate::core::device::Change;
use crate::core::{Error, ErrorKind, Operand, Result, Value};
use crate::msg;
use crate::session::Session;
use serde::Serialize;

/// The operands one word of `data save` stands for on device `dev`: an area's name
/// ([`areas`]) or an operand expression, each range of it resolved as `get` resolves it.
pub fn operands(session: &mut Session, dev: usize, word: &str) -> Result<Vec<Operand>> {
    let texts = match areas::expand(session, dev, word) {
        Some(r) => r?,
        None => vec![word.to_string()],
    };
    let name = session.entries()[dev].name.clone();
    let mut out = Vec::new();
    for t in texts {
        // A word without a device prefix is this device's, whichever device is current.
        let text = if t.contains(':') { t.clone() } else { format!("{name}:{t}") };
        // Columns as typed: the prefix added here is not in the line.
        let added = if t.contains(':') { 0 } else { name.len() + 1 };
        let target = session.resolve(&text).map_err(|e| match e.column {
            Some(c) => e.column(c.saturating_sub(added)),
            None => e,
        })?;
        if target.device != dev {
            return Err(Error::usage(msg!("data-operand-elsewhere", operand = t.as_str(), device = name.as_str())));
        }
        out.extend(target.ops);
    }
    Ok(out)
}

/// What the file says the device is.
pub fn identity(session: &Session, dev: usize) -> Identity {
    let e = &session.entries()[dev];
    let info = e.device.info();
    Identity {
        family: info.family.to_string(),
        model: super::model_code(&info.model).to_string(),
        name: e.name.clone(),
        url: e.url.clone(),
        saved: crate::servo::params::utc_now(),
        plcsh: env!("CARGO_PKG_VERSION").to_string(),
    }
}

/// Reads `ops` of device `dev` into a set (`asked`: the words they came from). An operand
/// asked for twice is kept once, where it first came.
pub fn read(session: &mut Session, dev: usize, asked: Vec<String>, ops: &[Operand]) -> Result<DataSet> {
    let mut seen = std::collections::HashSet::new();
    let space = session.entries()[dev].device.operands();
    let ops: Vec<(Operand, String)> =
        ops.iter().map(|o| (*o, space.name(o))).filter(|(_, n)| seen.insert(n.clone())).collect();
    let only: Vec<Operand> = ops.iter().map(|(o, _)| *o).collect();
    let values = session.read_values(dev, &only)?;
    let values = ops
        .into_iter()
        .zip(values)
        .map(|((o, operand), v)| Entry {
            operand,
            dtype: o.dtype.name().to_string(),
            value: FileValue::of(o.dtype, v),
            name: session.tag_of(dev, &o).map(|t| t.name.clone()),
        })
        .collect();
    Ok(DataSet { device: identity(session, dev), set: Body { operands: asked, values } })
}

/// The set's entries as operands of device `dev`, each checked: one operand of the file's
/// type, and the file's value one the operand takes.
fn resolve(session: &Session, dev: usize, set: &DataSet, file: &str) -> Result<Vec<(Operand, Value)>> {
    let e = &session.entries()[dev];
    let space = e.device.operands();
    let mut out = Vec::with_capacity(set.set.values.len());
    for x in &set.set.values {
        let unknown = |reason: String| {
            Error::new(
                ErrorKind::Operand,
                msg!(
                    "data-unknown-operand",
                    file = file,
                    operand = x.operand.as_str(),
                    dtype = x.dtype.as_str(),
                    device = e.name.as_str(),
                    reason = reason
                ),
            )
            .operand(x.operand.as_str())
            .device(&e.name)
        };
        if x.operand.contains(':') {
            return Err(unknown(
                msg!("data-operand-elsewhere", operand = x.operand.as_str(), device = e.name.as_str()).into(),
            ));
        }
        // Saved by name: loads by name, where the device's tags put it now (an old file, or a
        // name the device does not have, goes by its operand).
        let by = x.name.as_deref().filter(|n| session.names(dev).get(n).is_some()).unwrap_or(&x.operand);
        let target = session.resolve(&format!("{}:{}", e.name, by)).map_err(|err| unknown(err.message.to_string()))?;
        let op = match target.ops.as_slice() {
            [op] if op.dtype == x.data_type() => *op,
            [op] => return Err(unknown(format!("{} is {}", x.operand, op.dtype.name()))),
            ops => return Err(unknown(format!("{} operands", ops.len()))),
        };
        let v = space.check(&op, x.value.value()).map_err(|err| unknown(err.message.to_string()))?;
        out.push((op, v));
    }
    Ok(out)
}

/// The device's values of the set's operands, as a set of the device (for `data diff FILE`).
pub fn current(session: &mut Session, dev: usize, set: &DataSet, file: &str) -> Result<DataSet> {
    let plan = resolve(session, dev, set, file)?;
    let ops: Vec<Operand> = plan.iter().map(|(o, _)| *o).collect();
    let values = session.read_values(dev, &ops)?;
    let values = set
        .set
        .values
        .iter()
        .zip(ops.iter().zip(values))
        .map(|(e, (o, v))| Entry {
            operand: e.operand.clone(),
            dtype: e.dtype.clone(),
            value: FileValue::of(o.dtype, v),
            name: session.tag_of(dev, o).map(|t| t.name.clone()),
        })
        .collect();
    Ok(DataSet { device: identity(session, dev), set: Body { operands: set.set.operands.clone(), values } })
}

/// One write of a load.
#[derive(Clone, Debug, PartialEq, Serialize)]
pub struct Written {
    pub operand: String,
    #[serde(rename = "type")]
    pub dtype: String,
    pub old: FileValue,
    pub new: FileValue,
}

/// What a load did.
#[derive(Clone, Debug, PartialEq, Serialize)]
pub struct Loaded {
    pub written: Vec<Written>,
    pub unchanged: usize,
}

/// Writes the set's values that differ from the device's (module doc). The set must come
/// from the device's family and model.
pub fn load(session: &mut Session, dev: usize, set: &DataSet, file: &str) -> Result<Loaded> {
    let (name, family, model) = {
        let e = &session.entries()[dev];
        (e.name.clone(), e.device.info().family, e.device.info().model.clone())
    };
    set.check_device(file, &name, family, &model)?;
    let plan = resolve(session, dev, set, file)?;
    let ops: Vec<Operand> = plan.iter().map(|(o, _)| *o).collect();
    let now = session.read_values(dev, &ops)?;
    let mut todo = Vec::new();
    for ((e, (op, v)), old) in set.set.values.iter().zip(&plan).zip(now) {
        if op.dtype.encode(&old) != op.dtype.encode(v) {
            todo.push((e, *op, *v, FileValue::of(op.dtype, old)));
        }
    }
    let unchanged = plan.len() - todo.len();
    let changes: Vec<Change> = todo.iter().map(|(_, op, _, _)| Change::Write(*op)).collect();
    session.entries()[dev].device.permits(&changes).map_err(|e| e.device(&name))?;
    let mut written = Vec::with_capacity(todo.len());
    for (e, op, v, old) in todo {
        let stop = |err: Error, done: usize| stopped(err, &e.operand, done);
        session.write_values(dev, &[(op, v)]).map_err(|err| stop(err, written.len()))?;
        let back = session.read_values(dev, &[op]).map_err(|err| stop(err, written.len()))?;
        let back = back.first().copied().unwrap_or(Value::Int(0));
        if op.dtype.encode(&back) != op.dtype.encode(&v) {
            return Err(Error::new(
                ErrorKind::Refused,
                msg!(
                    "data-read-back",
                    operand = e.operand.as_str(),
                    value = e.value.text(),
                    back = FileValue::of(op.dtype, back).text(),
                    written = written.len() as u64
                ),
            )
            .operand(e.operand.as_str())
            .device(&name));
        }
        written.push(Written { operand: e.operand.clone(), dtype: e.dtype.clone(), old, new: e.value });
    }
    Ok(Loaded { written, unchanged })
}

/// The error that stops a load at `operand` after `done` writes, keeping the cause's kind.
fn stopped(err: Error, operand: &str, done: usize) -> Error {
    let mut e = Error::new(
        err.kind,
        msg!("data-stopped", operand = operand, written = done as u64, reason = err.message.to_string()),
    )
    .operand(operand);
    if let Some(d) = &err.device {
        e = e.device(d.clone());
    }
    if let Some(h) = &err.hint {
        e = e.hint(h.clone());
    }
    e
}
