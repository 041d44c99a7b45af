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
use crate::core::{Candidate, DataType, Error, ErrorKind, Operand, OperandSpace, Result};
use std::collections::HashMap;
use std::sync::Arc;

/// One tag as the table gives it, before it is resolved against a device.
#[derive(Clone, Debug, PartialEq)]
pub struct Source<'a> {
    pub name: &'a str,
    /// The address as written in the file (`VD200`, `%MW10`, `M0.3`).
    pub address: &'a str,
    /// The declared type, when the file gives one.
    pub dtype: Option<DataType>,
    pub comment: &'a str,
    /// The line of the file, for messages.
    pub line: usize,
}

/// A tag resolved on one device.
#[derive(Clone, Debug, PartialEq)]
pub struct Named {
    pub name: String,
    pub op: Operand,
    /// The operand's canonical text on the device (`VD200/REAL`).
    pub operand: String,
    pub comment: String,
}

/// A device's names: both ways, name → operand and operand → name.
#[derive(Debug, Default)]
pub struct Names {
    /// The file the table came from (for `help NAME` and messages).
    pub file: String,
    list: Vec<Named>,
    by_name: HashMap<String, u32>,
    by_op: HashMap<Operand, u32>,
}

/// The IEC identifier's case fold (names are compared without case).
pub fn fold(name: &str) -> String {
    if name.bytes().all(|b| b.is_ascii() && !b.is_ascii_uppercase()) {
        return name.to_string();
    }
    name.to_lowercase()
}

/// The most problems one load reports one by one (the rest are counted).
const SHOWN: usize = 20;

impl Names {
    /// Resolves `tags` (from `file`) through a device's operand grammar. Every address that the
    /// device does not have, or whose type does not fit, is one problem with `file:line`; any
    /// problem refuses the whole table (a half-attached table would make a name mean nothing
    /// on one command and something on the next).
    pub fn resolve<'a>(
        file: &str,
        tags: impl IntoIterator<Item = Source<'a>>,
        space: &dyn OperandSpace,
    ) -> Result<Names> {
        let mut n = Names { file: file.to_string(), ..Names::default() };
        let mut problems: Vec<String> = Vec::new();
        let mut count = 0usize;
        for t in tags {
            match resolve_one(&t, space) {
                Ok(op) => {
                    let key = fold(t.name);
                    if n.by_name.contains_key(&key) {
                        count += 1;
                        if problems.len() < SHOWN {
                            problems.push(format!(
                                "{file}:{}: {}",
                                t.line,
                                crate::msg!("names-duplicate", name = t.name)
                            ));
                        }
                        continue;
                    }
                    let i = n.list.len() as u32;
                    n.by_name.insert(key, i);
                    n.by_op.entry(op).or_insert(i);
                    n.list.push(Named {
                        name: t.name.to_string(),
                        op,
                        operand: space.name(&op),
                        comment: t.comment.to_string(),
                    });
                }
                Err(e) => {
                    count += 1;
                    if problems.len() < SHOWN {
                        problems.push(format!("{file}:{}: {}: {}", t.line, t.name, e.message));
                    }
                }
            }
        }
        if count == 0 {
            return Ok(n);
        }
        let more = count - problems.len();
        let mut message = problems.join("\n");
        if more > 0 {
            message.push('\n');
            message.push_str(&crate::msg!("names-more-problems", count = more).text);
        }
        Err(Error::new(ErrorKind::Syntax, crate::msg!("names-not-attached", file = file, count = count))
            .cause(message)
            .hint(crate::msg!("names-hint-check", file = file)))
    }

    /// The tag called `name` (any case).
    pub fn get(&self, name: &str) -> Option<&Named> {
        if self.list.is_empty() {
            return None;
        }
        self.by_name.get(&fold(name)).map(|&i| &self.list[i as usize])
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

/// One tag's operand: its address in the view of its type.
fn resolve_one(t: &Source, space: &dyn OperandSpace) -> Result<Operand> {
    let ops = space.parse(t.address)?;
    let [op] = ops[..] else {
        return Err(Error::new(ErrorKind::Operand, crate::msg!("names-not-one-operand", address = t.address)));
    };
    let Some(want) = t.dtype else { return Ok(op) };
    if op.dtype == want || (want == DataType::Bool && op.bits == 1) {
        return Ok(op);
    }
    let viewed = format!("{}/{}", t.address.trim(), want.name());
    match space.parse(&viewed) {
        Ok(v) if v.len() == 1 => Ok(v[0]),
        _ => Err(Error::new(
            ErrorKind::Operand,
            crate::msg!("names-type-does-not-fit", address = t.address, dtype = want.name(), bits = op.bits),
        )),
    }
}

/// A tag file as loaded, before it is resolved against a device: what a device entry keeps
/// until its operand grammar can be asked (a device not connected yet resolves it when it is).
#[derive(Clone, Debug, Default)]
pub struct Tags {
    pub file: String,
    pub items: Vec<Item>,
}

/// One tag of [`Tags`], owned.
#[derive(Clone, Debug, PartialEq)]
pub struct Item {
    pub name: String,
    pub address: String,
    pub dtype: Option<DataType>,
    pub comment: String,
    pub line: usize,
}

impl Tags {
    pub fn sources(&self) -> impl Iterator<Item = Source<'_>> {
        self.items.iter().map(|t| Source {
            name: &t.name,
            address: &t.address,
            dtype: t.dtype,
            comment: &t.comment,
            line: t.line,
        })
    }

    /// Resolves the table on a device's grammar ([`Names::resolve`]).
    pub fn resolve(&self, space: &dyn OperandSpace) -> Result<Names> {
        Names::resolve(&self.file, self.sources(), space)
    }
}

/// Loads tag file `path` with the tag-table parsers ([`crate::tags`]).
pub fn load(path: &std::path::Path) -> Result<Tags> {
    Err(Error::unsupported(format!("{}: tag files cannot be read yet", path.display())))
}

/// What a device's names are when it has none.
pub fn none() -> Arc<Names> {
    Arc::new(Names::default())
}

#[cfg(test)]
mod tests {
    use super::*;

    fn space() -> Box<dyn crate::core::Device> {
        crate::session::open_url("sim:K205-16DT", &crate::core::Clock::stepped()).unwrap()
    }

    fn src<'a>(name: &'a str, address: &'a str, dtype: Option<DataType>, comment: &'a str) -> Source<'a> {
        Source { name, address, dtype, comment, line: 1 }
    }

    #[test]
    fn names_resolve_both_ways_with_the_view_of_their_type() {
        let d = space();
        let n = Names::resolve(
            "t.csv",
            [
                src("Tank2_Level", "VD200", Some(DataType::Real), "уровень"),
                src("Мотор_1_Пуск", "M0.3", Some(DataType::Bool), ""),
                src("电机", "VW10", Some(DataType::Word), ""),
            ],
            d.operands(),
        )
        .unwrap();
        let t = n.get("tank2_level").unwrap();
        assert_eq!(t.operand, "VD200/REAL");
        assert_eq!(t.op.dtype, DataType::Real);
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
    fn a_bad_tag_refuses_the_table_with_its_line() {
        let d = space();
        let e = Names::resolve(
            "t.csv",
            [
                Source { name: "A", address: "VW0", dtype: None, comment: "", line: 3 },
                Source { name: "a", address: "VW2", dtype: None, comment: "", line: 4 },
                Source { name: "B", address: "VW99999", dtype: None, comment: "", line: 5 },
                Source { name: "C", address: "VB0", dtype: Some(DataType::Real), comment: "", line: 6 },
            ],
            d.operands(),
        )
        .unwrap_err();
        let all = e.causes.join("\n");
        assert!(all.contains("t.csv:4:"), "{all}");
        assert!(all.contains("t.csv:5: B"), "{all}");
        assert!(all.contains("t.csv:6: C"), "{all}");
        assert!(e.message.contains('3'), "{e}");
    }
}
