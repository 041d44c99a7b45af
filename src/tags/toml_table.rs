//! Tag tables as TOML, beside devices.toml in the same language: a `[tags]` table whose keys
//! are the names, each an address or a table with `address`, `type` and `comment`:
//!
//! ```toml
//! [tags]
//! Conveyor_Run = "M0.3"
//! Tank2_Level = { address = "VD200", type = "REAL", comment = "level of tank 2, m" }
//! "Мотор_1_Пуск" = { address = "Q0.0", comment = "пуск мотора 1" }
//! ```
//!
//! A name in another script is a quoted key (TOML's bare keys are ASCII). Other top-level
//! tables are left alone, so the tags may sit in a file that holds more. The toml crate
//! reads the file (linear, spans kept); its syntax errors come back at their line and column.

use super::name::address_text;
use super::{Problems, Tag, TagType};
use crate::msg;
use serde::Deserialize;
use std::collections::BTreeMap;
use toml::Spanned;

#[derive(Deserialize)]
struct File {
    tags: Option<Spanned<BTreeMap<Spanned<String>, Spanned<toml::Value>>>>,
}

/// Byte offset → (line, column), both 1-based, the column in characters.
pub(crate) struct Lines<'a> {
    text: &'a str,
    starts: Vec<usize>,
}

impl<'a> Lines<'a> {
    pub(crate) fn new(text: &'a str) -> Lines<'a> {
        let mut starts = vec![0];
        starts.extend(text.match_indices('\n').map(|(i, _)| i + 1));
        Lines { text, starts }
    }
    pub(crate) fn at(&self, offset: usize) -> (usize, usize) {
        let offset = offset.min(self.text.len());
        let line = self.starts.partition_point(|&s| s <= offset).max(1);
        let start = self.starts[line - 1];
        let col = self.text.get(start..offset).map_or(offset - start, |s| s.chars().count()) + 1;
        (line, col)
    }
}

/// Reads a TOML tag table.
pub fn parse(text: &str, problems: &mut Problems<'_>) -> Vec<Tag> {
    let lines = Lines::new(text);
    let file: File = match toml::from_str(text) {
        Ok(f) => f,
        Err(e) => {
            let (l, c) = e.span().map_or((1, 1), |s| lines.at(s.start));
            let detail = e.message().trim().to_string();
            problems.add(l, c, msg!("tags-toml-syntax", detail = detail));
            return Vec::new();
        }
    };
    let Some(table) = file.tags else {
        problems.add(1, 1, msg!("tags-toml-no-table"));
        return Vec::new();
    };
    let mut entries: Vec<(Spanned<String>, Spanned<toml::Value>)> = table.into_inner().into_iter().collect();
    entries.sort_by_key(|(k, _)| k.span().start);
    let mut tags = Vec::with_capacity(entries.len());
    for (key, value) in entries {
        let (line, column) = lines.at(key.span().start);
        let name = key.get_ref().clone();
        let (vl, vc) = lines.at(value.span().start);
        let (address, dtype, comment) = match value.get_ref() {
            toml::Value::String(a) => (a.clone(), String::new(), String::new()),
            toml::Value::Table(t) => {
                let mut bad = false;
                for k in t.keys() {
                    if !matches!(k.as_str(), "address" | "type" | "comment") {
                        problems.add(vl, vc, msg!("tags-toml-unknown-key", name = name.as_str(), key = k.as_str()));
                        bad = true;
                    }
                }
                let text = |k: &str| -> Option<Result<String, ()>> {
                    t.get(k).map(|v| v.as_str().map(str::to_string).ok_or(()))
                };
                let mut field = |k: &str| match text(k) {
                    None => String::new(),
                    Some(Ok(s)) => s,
                    Some(Err(())) => {
                        problems.add(vl, vc, msg!("tags-toml-not-text", name = name.as_str(), key = k));
                        bad = true;
                        String::new()
                    }
                };
                let fields = (field("address"), field("type"), field("comment"));
                if bad {
                    continue;
                }
                fields
            }
            _ => {
                problems.add(vl, vc, msg!("tags-toml-entry", name = name.as_str()));
                continue;
            }
        };
        if address.trim().is_empty() {
            problems.add(vl, vc, msg!("tags-no-address", name = name.as_str()));
            continue;
        }
        if address.trim().contains(|c: char| c.is_whitespace() || c == '/') {
            problems.add(vl, vc, msg!("tags-bad-address", name = name.as_str(), address = address.trim()));
            continue;
        }
        let Some(dtype) = TagType::parse(&dtype) else {
            problems.add(vl, vc, msg!("tags-unknown-type", name = name.as_str(), dtype = dtype.trim()));
            continue;
        };
        tags.push(Tag {
            name,
            address: address_text(&address),
            dtype,
            comment: comment.trim().to_string(),
            line,
            column,
        });
    }
    tags
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::core::DataType;

    #[test]
    fn names_addresses_and_tables_in_file_order() {
        let text = "title = \"press 1\"\n[tags]\nZeta = \"M0.3\"\nTank2_Level = { address = \"%VD200\", type = \"real\", comment = \"m\" }\n\"Мотор_1_Пуск\" = { address = \"Q0.0\" }\n";
        let mut p = Problems::new("t.toml");
        let t = parse(text, &mut p);
        assert!(p.list.is_empty(), "{:?}", p.list);
        let names: Vec<&str> = t.iter().map(|t| t.name.as_str()).collect();
        assert_eq!(names, ["Zeta", "Tank2_Level", "Мотор_1_Пуск"]);
        assert_eq!(
            (t[1].address.as_str(), t[1].dtype, t[1].comment.as_str()),
            ("VD200", TagType::Of(DataType::Real), "m")
        );
        assert_eq!((t[2].line, t[2].column), (5, 1));
    }

    #[test]
    fn problems_at_their_place() {
        let mut p = Problems::new("t.toml");
        parse(
            "[tags]\nA = 3\nB = { address = \"VW0\", kind = \"x\" }\nC = { address = \"VW2\", type = \"FLOAT\" }\n",
            &mut p,
        );
        let got: Vec<String> = p.list.iter().map(|p| p.to_string()).collect();
        assert_eq!(got.len(), 3, "{got:?}");
        assert!(got[0].starts_with("t.toml:2:5: "), "{got:?}");
        assert!(got[1].starts_with("t.toml:3:5: ") && got[1].contains("kind"), "{got:?}");
        assert!(got[2].starts_with("t.toml:4:5: ") && got[2].contains("FLOAT"), "{got:?}");
        let mut p = Problems::new("t.toml");
        parse("[tags]\nA = \"VW0\n", &mut p);
        assert!(p.list[0].to_string().starts_with("t.toml:2:"), "{:?}", p.list);
        let mut p = Problems::new("t.toml");
        parse("[other]\nA = 1\n", &mut p);
        assert_eq!(p.list[0].message.id, "tags-toml-no-table");
    }
}
