//! Loading a tag file for a device: the family-neutral reader ([`crate::tags`]) followed by
//! the family checks ([`crate::tags::TagTable::check`]) against the device's operand space
//! and one space of every family, so a table never holds a name that reads as an operand of
//! any PLC plcsh speaks to. `plcsh tags`, `sim program load … tags=FILE` and a device's
//! `tags = "…"` all load through here, which sits beside the profiles because it is the first
//! layer that knows every family.

use crate::core::{Error, OperandSpace};
use crate::tags::{TagFormat, TagProblem, TagProblems, TagTable};
use std::path::Path;

/// The operand space of a model of any family (`K209M`, `FX2N`, `UMPK16`); the simulated
/// K2's (`K205-16DT`) when `model` is `None`.
pub fn space_for(model: Option<&str>) -> crate::core::Result<Box<dyn OperandSpace>> {
    let name = model.unwrap_or(crate::k2::catalog::DEFAULT_MODEL);
    if let Some(m) = crate::k2::catalog::find(name) {
        return Ok(Box::new(crate::k2::space::K2Space::new(m)));
    }
    if let Some(m) = crate::fx::model::Model::find(name) {
        return Ok(Box::new(crate::fx::space::FxSpace::new(m, crate::fx::space::Proto::Port)));
    }
    if name.to_ascii_uppercase().starts_with("UMPK") {
        if let Some(m) = crate::umpk::model::find(name) {
            return Ok(Box::new(crate::umpk::space::UmpkSpace { model: m }));
        }
    }
    Err(Error::usage(crate::msg!("tags-unknown-model", model = name)))
}

/// One space of every family, the largest model of each: the operands a name must not read as.
pub fn every_family() -> Vec<Box<dyn OperandSpace>> {
    let mut out: Vec<Box<dyn OperandSpace>> = Vec::new();
    if let Some(m) = crate::k2::catalog::MODELS.last() {
        out.push(Box::new(crate::k2::space::K2Space::new(m)));
    }
    if let Some(m) = crate::fx::model::MODELS.last() {
        out.push(Box::new(crate::fx::space::FxSpace::new(m, crate::fx::space::Proto::Port)));
    }
    if let Some(m) = crate::umpk::model::MODELS.last() {
        out.push(Box::new(crate::umpk::space::UmpkSpace { model: m }));
    }
    out
}

/// Checks a table read already for `space`'s family (and names against every family); the
/// overlaps it finds are the table's warnings ([`TagTable::checked`]).
pub fn check(table: TagTable, space: &dyn OperandSpace) -> Result<TagTable, TagProblems> {
    check_after(table, Vec::new(), space)
}

/// [`check`] of the good tags of a file whose reading found `problems` already: every
/// problem of the file at once.
fn check_after(
    table: TagTable,
    mut problems: Vec<TagProblem>,
    space: &dyn OperandSpace,
) -> Result<TagTable, TagProblems> {
    let others = every_family();
    let mut spaces: Vec<&dyn OperandSpace> = vec![space];
    spaces.extend(others.iter().map(|b| b.as_ref()));
    match table.checked(&spaces) {
        Ok(t) if problems.is_empty() => Ok(t),
        Ok(_) => Err(TagProblems(problems)),
        Err(p) => {
            problems.extend(p.0);
            problems.sort_by_key(|p| (p.line, p.column));
            Err(TagProblems(problems))
        }
    }
}

/// Reads a tag file (`format` `None`: told by its name and text) and checks it for `space`'s
/// family: the table, or every problem.
pub fn load(path: &Path, format: Option<TagFormat>, space: &dyn OperandSpace) -> Result<TagTable, TagProblems> {
    let origin = path.display().to_string();
    let bytes = std::fs::read(path).map_err(|e| {
        TagProblems(vec![TagProblem {
            origin: origin.clone(),
            line: 0,
            column: 0,
            message: crate::msg!("tags-cannot-read", file = origin.as_str(), reason = e.to_string()),
        }])
    })?;
    let (table, problems) = TagTable::read(&bytes, &origin, format);
    check_after(table, problems, space)
}
