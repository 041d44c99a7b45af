//! Names over operands (docs/tags.md, "How names appear"): one device's tag table resolved
//! through that device's operand grammar once, when the table is attached, so that a name is
//! an [`Operand`] like any other from then on.
//!
//! The design guide's rule ("names are a layer over operands, resolved where operands are
//! parsed") puts the one use of this table in [`crate::session::Session::resolve`] and the
//! Lua handle's operand cache: every command, the Lua bridge, `publish`, checklists and lab
//! criteria gain names by that single change; drivers, simulators and the guard never see a
//! name. The way back — an operand to its name, for output — is [`Names::of`]: a reading of
//! `VD200/REAL` carries the name of the tag that is exactly that operand, whichever way it
//! was typed.
//!
//! Names follow IEC 61131-3 identifiers (§6.1.2): case does not matter (`tank2_level` is
//! `Tank2_Level`), compared by Unicode lower case so that Cyrillic and Chinese names work the
//! same way; the table itself (its formats, its rules for names) is [`crate::tags`]'s.
//! A tag's type picks the view of its address (`REAL` on `VD200` reads `VD200/REAL`), by the
//! operand grammar's own view suffix.

use crate::core::text::edit_distance;
use crate::core::{Candidate, Operand, OperandSpace, Result};
use crate::tags::TagTable;
use std::collections::HashMap;
use std::sync::Arc;

/// A tag resolved on one device.
#[derive(Clone, Debug, PartialEq)]
pub struct Named {
    pub name: String,
    pub op: Operand,
    /// The operand's canonical text on the device (`VD200/REAL`).
    pub operand: String,
    pub comment: String,
}

/// A device's names: both ways, name → operand and operand → name. The names and their index
/// are the tag table's ([`TagTable::position`]); what this adds is the binding to the device's
/// operands, `list[i]` for the table's tag `i` (one place per table: `crate::tags` module docs).
#[derive(Debug, Default)]
pub struct Names {
    /// The file the table came from (for `help NAME` and messages).
    pub file: String,
    table: TagTable,
    list: Vec<Named>,
    by_op: HashMap<Operand, u32>,
    /// What let the table load but deserves a look (overlapping addresses), `file:line: …`.
    pub warnings: Vec<String>,
}

/// The IEC identifier's case fold (names are compared without case), as the table folds.
pub fn fold(name: &str) -> String {
    crate::tags::name::fold(name).into_owned()
}

impl Names {
    /// Resolves `table` on a device's operand grammar, after the checks that need the device
    /// and every family ([`crate::profile::tags::check`]: a name that reads as an operand, an
    /// address the device does not have, a type that does not fit). Any problem refuses the
    /// whole table, each with its `file:line:column`: a half-attached table would make a name
    /// mean nothing on one command and something on the next. Overlapping addresses let it
    /// load and are kept as [`Names::warnings`].
    pub fn resolve(table: TagTable, space: &dyn OperandSpace) -> Result<Names> {
        let origin = table.origin().to_string();
        let table = crate::profile::tags::check(table, space)
            .map_err(|p| p.into_error().hint(crate::msg!("names-hint-check", file = origin.as_str())))?;
        let mut n = Names { file: origin, ..Names::default() };
        n.warnings = table.warnings().iter().map(|w| w.to_string()).collect();
        n.list.reserve(table.len());
        for t in table.iter() {
            let op = t.resolve(space)?;
            let i = n.list.len() as u32;
            n.by_op.entry(op).or_insert(i);
            n.list.push(Named { name: t.name.clone(), op, operand: space.name(&op), comment: t.comment.clone() });
        }
        n.table = table;
        Ok(n)
    }

    /// The tag called `name` (any case): the table's index, then the operand bound to it — a
    /// lookup, no parse (benches/tags.rs, BENCHMARKS.md "Tags").
    pub fn get(&self, name: &str) -> Option<&Named> {
        if self.list.is_empty() {
            return None;
        }
        self.table.position(name).map(|i| &self.list[i])
    }

    /// The tag table the names come from (its tags in file order, with their lines).
    pub fn table(&self) -> &TagTable {
        &self.table
    }

    /// The tag that is exactly `op` (address and view), for output.
    pub fn of(&self, op: &Operand) -> Option<&Named> {
        self.by_op.get(op).map(|&i| &self.list[i as usize])
    }

    pub fn len(&self) -> usize {
        self.list.len()
    }

    pub fn is_empty(&self) -> bool {
        self.list.is_empty()
    }

    pub fn iter(&self) -> impl Iterator<Item = &Named> {
        self.list.iter()
    }

    /// An operand expression with names in it as the device's grammar reads it: a name
    /// (`Tank2_Level`), a count form from a name (`Tank2_Level[4]`), a range between names or
    /// a name and an operand (`Level_1..Level_4`). `None` when `body` names no tag.
    pub fn expand(&self, body: &str) -> Option<Expanded> {
        if self.list.is_empty() {
            return None;
        }
        let t = body.trim();
        if let Some(n) = self.get(t) {
            return Some(Expanded::One(n.op));
        }
        if let Some(open) = t.find('[') {
            let n = self.get(t[..open].trim())?;
            return Some(Expanded::Text(format!("{}{}", n.operand, &t[open..])));
        }
        if let Some((a, b)) = t.split_once("..") {
            let (na, nb) = (self.get(a.trim()), self.get(b.trim()));
            if na.is_none() && nb.is_none() {
                return None;
            }
            let side = |n: Option<&Named>, s: &str| n.map_or(s.trim().to_string(), |n| n.operand.clone());
            return Some(Expanded::Text(format!("{}..{}", side(na, a), side(nb, b))));
        }
        None
    }

    /// Names near `text` (for "did you mean"), nearest first, at most three.
    pub fn near(&self, text: &str) -> Vec<&Named> {
        let want = fold(text.trim());
        if want.is_empty() {
            return Vec::new();
        }
        let limit = (want.chars().count() / 3).max(1);
        let mut best: Vec<(usize, usize)> = Vec::new();
        for (i, n) in self.list.iter().enumerate() {
            let key = fold(&n.name);
            // A prefix typed so far is as near as a letter wrong.
            let d = if key.starts_with(&want) { 1 } else { edit_distance(&want, &key) };
            if d <= limit {
                best.push((d, i));
            }
        }
        best.sort();
        best.into_iter().take(3).map(|(_, i)| &self.list[i]).collect()
    }

    /// Names that start with `prefix` (any case), with their comments (else their operands)
    /// as hints, for Tab.
    pub fn complete(&self, prefix: &str) -> Vec<Candidate> {
        let want = fold(prefix);
        self.list
            .iter()
            .filter(|n| fold(&n.name).starts_with(&want))
            .map(|n| Candidate {
                text: n.name.clone(),
                meaning: if n.comment.is_empty() {
                    n.operand.clone()
                } else {
                    format!("{} · {}", n.operand, n.comment)
                },
            })
            .collect()
    }
}

/// An expression after [`Names::expand`].
#[derive(Clone, Debug, PartialEq)]
pub enum Expanded {
    /// A name: its operand.
    One(Operand),
    /// Operand text for the device's grammar (names replaced by their operands).
    Text(String),
}

/// Reads tag file `path` ([`TagTable::read`]; its problems as one error, each with its line).
/// The device checks come when it is attached ([`Names::resolve`]).
pub fn load(path: &std::path::Path) -> Result<TagTable> {
    let origin = path.display().to_string();
    let bytes = std::fs::read(path).map_err(|e| {
        crate::core::Error::io(crate::msg!("tags-cannot-read", file = origin.as_str(), reason = e.to_string()))
    })?;
    let (table, problems) = TagTable::read(&bytes, &origin, None);
    if problems.is_empty() {
        Ok(table)
    } else {
        Err(crate::tags::TagProblems(problems).into_error())
    }
}

/// What a device's names are when it has none.
pub fn none() -> Arc<Names> {
    Arc::new(Names::default())
}

#[cfg(test)]
mod tests {
    use super::*;

    fn device() -> Box<dyn crate::core::Device> {
        crate::session::open_url("sim:K205-16DT", &crate::core::Clock::stepped()).unwrap()
    }

    fn table(text: &str) -> TagTable {
        TagTable::parse_text(text, "t.csv", None).unwrap()
    }

    #[test]
    fn names_resolve_both_ways_with_the_view_of_their_type() {
        let d = device();
        let t = table(
            "name,address,type,comment\nTank2_Level,VD200,REAL,уровень\nМотор_1_Пуск,M0.3,BOOL,\n电机,VW10,WORD,\n",
        );
        let n = Names::resolve(t, d.operands()).unwrap();
        let tank = n.get("tank2_level").unwrap();
        assert_eq!(tank.operand, "VD200/REAL");
        assert_eq!(tank.op.dtype, crate::core::DataType::Real);
        assert_eq!(n.get("МОТОР_1_ПУСК").unwrap().operand, "M0.3");
        assert_eq!(n.get("电机").unwrap().operand, "VW10");
        let op = d.operands().parse("VD200/REAL").unwrap()[0];
        assert_eq!(n.of(&op).unwrap().name, "Tank2_Level");
        let plain = d.operands().parse("VD200").unwrap()[0];
        assert!(n.of(&plain).is_none(), "another view is another operand");
        assert_eq!(n.expand("Tank2_Level[2]"), Some(Expanded::Text("VD200/REAL[2]".into())));
        assert_eq!(n.expand("VW0..电机"), Some(Expanded::Text("VW0..VW10".into())));
        assert_eq!(n.expand("VW0..VW2"), None);
        assert_eq!(n.near("Tank2_Levl")[0].name, "Tank2_Level");
        assert_eq!(n.complete("tan")[0].meaning, "VD200/REAL · уровень");
    }

    #[test]
    fn a_tag_the_device_does_not_have_refuses_the_table_with_its_line() {
        let d = device();
        let t = table("name,address,type\nA,VW0,INT\nB,VW99999,INT\nC,VB0,REAL\n");
        let e = Names::resolve(t, d.operands()).unwrap_err();
        let all = format!("{}\n{}", e.message, e.causes.join("\n"));
        assert!(all.contains("t.csv:3"), "{all}");
        assert!(all.contains("t.csv:4"), "{all}");
        assert!(!all.contains("t.csv:2"), "{all}");
    }
}
