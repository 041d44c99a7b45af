//! Tag tables: the names of a PLC project (`Conveyor_Run`, `Tank2_Level`, `Мотор_1_Пуск`)
//! with the address, type and comment of each, read from the files people keep them in — a
//! CSV as KincoBuilder's global variable table exports it or a spreadsheet saves it
//! ([`csv`]), a TOML `[tags]` table ([`toml_table`]) and IEC 61131-3 declarations
//! (`VAR_GLOBAL … name AT %MW10 : INT; (* comment *) … END_VAR`, [`iec`]).
//!
//! Why a layer of its own: a name is resolved where an operand is parsed (design guide,
//! "Names are a layer over operands"), so the table knows no device family. A tag's address
//! is kept as text in the family's own spelling (`VD200`, `M0.3`; IEC's `%MW10` and
//! `%MX0.3` become `MW10` and `M0.3`, [`name::address_text`]) and turned into an operand by
//! the family's operand space ([`Tag::resolve`]); the checks that need the family — a name
//! that reads as one of its operands, a type that does not fit the address, two tags on
//! overlapping addresses — take the spaces as an argument ([`TagTable::check`]).
//!
//! Names follow IEC 61131-3's identifiers (ed. 3, §6.1.2: letters, digits and underscores,
//! starting with a letter or an underscore, no two underscores in a row, none at the end)
//! with the letters of any script, and are case-insensitive as that section says ("The case
//! of letters shall not have any significance in identifiers"): `conveyor_run` finds
//! `Conveyor_Run`, `мотор_1_пуск` finds `Мотор_1_Пуск` ([`name`]).
//!
//! One place per table: this module owns a table's names — the file's tags and the index by
//! name, family-free — and [`crate::names::Names`] owns the binding of those names to one
//! device's operands (each address resolved once, when the table is attached, and the way
//! back from an operand to its name), looking names up through this index rather than a copy
//! of it.
//!
//! Every parser here reads outside input: one pass, linear in the file, never panicking,
//! and every problem is one message with `file:line:column` ([`TagProblem`]).

pub mod check;
pub mod csv;
pub mod export;
pub mod iec;
pub mod name;
pub mod toml_table;

use crate::core::encoding::{self, Encoding};
use crate::core::msg::Msg;
use crate::core::{DataType, Error, ErrorKind, Operand, OperandSpace};
use crate::msg;
use std::collections::HashMap;
use std::fmt;
use std::path::Path;

/// The type a tag declares: an IEC type, or none (a spreadsheet without a type column), when
/// the address's own type is used.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum TagType {
    /// Declared: the value is shown and written as this type (`REAL` reads `VD200/REAL`).
    Of(DataType),
    /// Not declared: the type the family gives the address (`VD200` → DWORD).
    Natural,
}

impl TagType {
    /// The declared type, if any.
    pub fn data_type(self) -> Option<DataType> {
        match self {
            TagType::Of(t) => Some(t),
            TagType::Natural => None,
        }
    }
    /// The type's IEC name, empty when none is declared.
    pub fn name(self) -> &'static str {
        match self {
            TagType::Of(t) => t.name(),
            TagType::Natural => "",
        }
    }
    /// Reads a type name as tag files write it: the IEC names (`BOOL`, `INT`, `UINT` …, any
    /// case) and the short forms `DataType::from_name` knows; an empty text is [`TagType::Natural`].
    pub fn parse(text: &str) -> Option<TagType> {
        let t = text.trim();
        if t.is_empty() {
            return Some(TagType::Natural);
        }
        DataType::from_name(t).map(TagType::Of)
    }
}

/// One tag.
#[derive(Clone, Debug, PartialEq)]
pub struct Tag {
    /// The name as written in the file.
    pub name: String,
    /// The address as the family writes it (`VD200`, `M0.3`): upper case, without IEC's `%`
    /// and bit-size `X` ([`name::address_text`]).
    pub address: String,
    pub dtype: TagType,
    /// The comment, empty when there is none.
    pub comment: String,
    /// Where the tag is defined (1-based line and column of its name).
    pub line: usize,
    pub column: usize,
}

impl Tag {
    /// The operand text the family parses for this tag: the address, with the declared type
    /// as a view when it differs from the address's own (`VD200/REAL`).
    pub fn operand_text(&self, space: &dyn OperandSpace) -> crate::core::Result<String> {
        let op = parse_single(space, &self.address)?;
        Ok(match self.dtype {
            TagType::Of(t) if t != op.dtype => format!("{}/{}", self.address, t.name()),
            _ => self.address.clone(),
        })
    }

    /// The tag as an operand of `space`: its address, read as its declared type. Refused
    /// (naming the tag) when the address is not an operand of the family or the type does not
    /// fit it.
    pub fn resolve(&self, space: &dyn OperandSpace) -> crate::core::Result<Operand> {
        let named = |e: Error| {
            Error::new(
                e.kind,
                msg!(
                    "tags-resolve-failed",
                    name = self.name.as_str(),
                    address = self.address.as_str(),
                    problem = e.message.as_str()
                ),
            )
            .operand(self.address.clone())
        };
        // The common case in one parse: the address read as the declared type.
        if let TagType::Of(t) = self.dtype {
            if let Ok(op) = parse_single(space, &format!("{}/{}", self.address, t.name())) {
                return Ok(op);
            }
        }
        let op = parse_single(space, &self.address).map_err(named)?;
        match self.dtype {
            TagType::Of(t) if t != op.dtype => {
                if t.bits() != op.bits as u32 {
                    return Err(Error::new(
                        ErrorKind::Operand,
                        msg!(
                            "tags-type-does-not-fit",
                            name = self.name.as_str(),
                            dtype = t.name(),
                            address = self.address.as_str(),
                            bits = op.bits as i64
                        ),
                    )
                    .operand(self.address.clone()));
                }
                parse_single(space, &format!("{}/{}", self.address, t.name())).map_err(named)
            }
            _ => Ok(op),
        }
    }
}

/// `text` as exactly one operand of `space` (a range or count is not an address).
fn parse_single(space: &dyn OperandSpace, text: &str) -> crate::core::Result<Operand> {
    let ops = space.parse(text)?;
    match ops.as_slice() {
        [one] => Ok(*one),
        _ => Err(Error::new(ErrorKind::Operand, msg!("tags-address-is-range", address = text)).operand(text)),
    }
}

/// The formats a tag file can be in.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum TagFormat {
    /// Columns name, address, type, comment; `,`, `;` or tab ([`csv`]).
    Csv,
    /// A `[tags]` table ([`toml_table`]).
    Toml,
    /// `VAR_GLOBAL … END_VAR` declarations ([`iec`]).
    Iec,
}

impl TagFormat {
    pub const ALL: [TagFormat; 3] = [TagFormat::Csv, TagFormat::Toml, TagFormat::Iec];

    pub fn name(self) -> &'static str {
        match self {
            TagFormat::Csv => "csv",
            TagFormat::Toml => "toml",
            TagFormat::Iec => "iec",
        }
    }

    pub fn from_name(s: &str) -> Option<TagFormat> {
        TagFormat::ALL.into_iter().find(|f| f.name().eq_ignore_ascii_case(s.trim()))
    }

    /// The format a file's name says (`.csv`/`.tsv`/`.txt`, `.toml`, `.st`/`.iec`/`.var`/`.il`
    /// /`.exp`), else what its text looks like: a `VAR_GLOBAL` is IEC, a `[tags]` line TOML,
    /// anything else CSV.
    pub fn detect(origin: &str, text: &str) -> TagFormat {
        let ext = Path::new(origin).extension().map(|e| e.to_string_lossy().to_ascii_lowercase()).unwrap_or_default();
        match ext.as_str() {
            "csv" | "tsv" | "txt" => return TagFormat::Csv,
            "toml" => return TagFormat::Toml,
            "st" | "iec" | "var" | "il" | "exp" => return TagFormat::Iec,
            _ => {}
        }
        if iec::find_keyword(text, "VAR_GLOBAL").is_some() {
            TagFormat::Iec
        } else if text.lines().any(|l| l.trim() == "[tags]") {
            TagFormat::Toml
        } else {
            TagFormat::Csv
        }
    }
}

/// One problem of a tag file, at `origin:line:column` (1-based; column counts characters;
/// line 0 when the problem is the whole file, which could not be read).
#[derive(Clone, Debug, PartialEq)]
pub struct TagProblem {
    pub origin: String,
    pub line: usize,
    pub column: usize,
    pub message: Msg,
}

impl fmt::Display for TagProblem {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        // Line 0: the file as a whole (it could not be read); the message names it.
        if self.line == 0 {
            return write!(f, "{}", encoding::printable(&self.message.text));
        }
        write!(f, "{}:{}:{}: {}", self.origin, self.line, self.column, encoding::printable(&self.message.text))
    }
}

/// Every problem of a tag file, in file order: what loading refuses with.
#[derive(Clone, Debug, PartialEq, Default)]
pub struct TagProblems(pub Vec<TagProblem>);

impl fmt::Display for TagProblems {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        for (i, p) in self.0.iter().enumerate() {
            if i > 0 {
                writeln!(f)?;
            }
            write!(f, "{p}")?;
        }
        Ok(())
    }
}

impl std::error::Error for TagProblems {}

impl TagProblems {
    /// As the shell's error: the first problem is the message (its id the JSON `code`), every
    /// problem a cause line.
    pub fn into_error(self) -> Error {
        let Some(first) = self.0.first() else {
            return Error::new(ErrorKind::Syntax, msg!("tags-empty", file = ""));
        };
        let mut e = Error::new(ErrorKind::Syntax, Msg { id: first.message.id, text: first.to_string() });
        for p in self.0.iter().skip(1) {
            e = e.cause(p);
        }
        e
    }
}

impl From<TagProblems> for Error {
    fn from(p: TagProblems) -> Error {
        p.into_error()
    }
}

/// Collects problems while a parser runs.
#[derive(Debug)]
pub struct Problems<'a> {
    origin: &'a str,
    pub list: Vec<TagProblem>,
}

impl<'a> Problems<'a> {
    pub fn new(origin: &'a str) -> Problems<'a> {
        Problems { origin, list: Vec::new() }
    }
    pub fn add(&mut self, line: usize, column: usize, message: Msg) {
        self.list.push(TagProblem { origin: self.origin.to_string(), line, column, message });
    }
}

/// A loaded tag table: its tags in file order and an index by name (case-insensitive).
#[derive(Clone, Debug, Default)]
pub struct TagTable {
    origin: String,
    format: Option<TagFormat>,
    encoding: Option<Encoding>,
    tags: Vec<Tag>,
    index: HashMap<Box<str>, u32>,
    /// What [`TagTable::checked`] found that does not stop the table from loading.
    warnings: Vec<TagProblem>,
}

impl TagTable {
    /// Reads a tag file (format by [`TagFormat::detect`]).
    pub fn load(path: &Path) -> Result<TagTable, TagProblems> {
        let origin = path.display().to_string();
        let bytes = std::fs::read(path).map_err(|e| {
            TagProblems(vec![TagProblem {
                origin: origin.clone(),
                line: 0,
                column: 0,
                message: msg!("tags-cannot-read", file = origin.as_str(), reason = e.to_string()),
            }])
        })?;
        TagTable::parse(&bytes, &origin, None)
    }

    /// Reads a tag file's bytes in any encoding IL files may have (UTF-8 with or without its
    /// byte-order mark, UTF-16, Windows-1251: [`crate::core::encoding::decode`]); `origin`
    /// names it in problems. `format` `None` detects it ([`TagFormat::detect`]).
    pub fn parse(bytes: &[u8], origin: &str, format: Option<TagFormat>) -> Result<TagTable, TagProblems> {
        let (t, p) = TagTable::read(bytes, origin, format);
        if p.is_empty() {
            Ok(t)
        } else {
            Err(TagProblems(p))
        }
    }

    /// [`TagTable::parse`] that keeps the good tags ([`TagTable::build`]): the table and the
    /// problems (a file that cannot be decoded is one problem and an empty table).
    pub fn read(bytes: &[u8], origin: &str, format: Option<TagFormat>) -> (TagTable, Vec<TagProblem>) {
        let (text, enc) = match encoding::decode(bytes) {
            Ok(d) => d,
            Err(m) => {
                let p = TagProblem {
                    origin: origin.to_string(),
                    line: 1,
                    column: 1,
                    message: msg!("tags-bad-encoding", problem = m),
                };
                return (TagTable { origin: origin.to_string(), ..TagTable::default() }, vec![p]);
            }
        };
        let (mut t, p) = TagTable::read_text(&text, origin, format);
        t.encoding = Some(enc);
        (t, p)
    }

    /// [`TagTable::parse`] for text already decoded.
    pub fn parse_text(text: &str, origin: &str, format: Option<TagFormat>) -> Result<TagTable, TagProblems> {
        let (t, p) = TagTable::read_text(text, origin, format);
        if p.is_empty() {
            Ok(t)
        } else {
            Err(TagProblems(p))
        }
    }

    /// [`TagTable::read`] for text already decoded.
    pub fn read_text(text: &str, origin: &str, format: Option<TagFormat>) -> (TagTable, Vec<TagProblem>) {
        let format = format.unwrap_or_else(|| TagFormat::detect(origin, text));
        let mut problems = Problems::new(origin);
        let tags = match format {
            TagFormat::Csv => csv::parse(text, &mut problems),
            TagFormat::Toml => toml_table::parse(text, &mut problems),
            TagFormat::Iec => iec::parse(text, &mut problems),
        };
        TagTable::build(tags, origin, Some(format), problems)
    }

    /// A table of `tags` already read (by a parser, or from a program's `VAR_GLOBAL` block):
    /// checks each name ([`name::check`]) and refuses duplicates; `problems` holds what the
    /// reader found before.
    pub fn from_tags(
        tags: Vec<Tag>,
        origin: &str,
        format: Option<TagFormat>,
        problems: Problems<'_>,
    ) -> Result<TagTable, TagProblems> {
        let (table, list) = TagTable::build(tags, origin, format, problems);
        if list.is_empty() {
            Ok(table)
        } else {
            Err(TagProblems(list))
        }
    }

    /// [`TagTable::from_tags`] that keeps the good tags: the table of every tag without a
    /// problem, and the problems in file order (so the family checks can still run on the rest
    /// and a file's every problem is reported at once).
    pub fn build(
        tags: Vec<Tag>,
        origin: &str,
        format: Option<TagFormat>,
        mut problems: Problems<'_>,
    ) -> (TagTable, Vec<TagProblem>) {
        let mut index: HashMap<Box<str>, u32> = HashMap::with_capacity(tags.len());
        let mut kept = Vec::with_capacity(tags.len());
        for tag in tags {
            if let Err(m) = name::check(&tag.name) {
                problems.add(tag.line, tag.column, m);
                continue;
            }
            let key: Box<str> = name::fold(&tag.name).into();
            if let Some(&first) = index.get(&key) {
                let f: &Tag = &kept[first as usize];
                problems.add(
                    tag.line,
                    tag.column,
                    msg!("tags-duplicate", name = tag.name.as_str(), first = f.name.as_str(), line = f.line as i64),
                );
                continue;
            }
            index.insert(key, kept.len() as u32);
            kept.push(tag);
        }
        if kept.is_empty() && problems.list.is_empty() {
            problems.add(1, 1, msg!("tags-empty", file = origin));
        }
        let mut list = problems.list;
        list.sort_by_key(|p| (p.line, p.column));
        (TagTable { origin: origin.to_string(), format, encoding: None, tags: kept, index, warnings: Vec::new() }, list)
    }

    /// The tag of this name: IEC 61131-3 identifiers are case-insensitive (§6.1.2), so
    /// `conveyor_run` finds `Conveyor_Run` and `МОТОР_1_ПУСК` finds `Мотор_1_Пуск`.
    pub fn get(&self, name: &str) -> Option<&Tag> {
        let key = name::fold(name);
        self.index.get(key.as_ref()).map(|&i| &self.tags[i as usize])
    }

    /// The index of the tag of this name in [`TagTable::iter`]'s order (case-insensitive, as
    /// [`TagTable::get`]).
    pub fn position(&self, name: &str) -> Option<usize> {
        self.index.get(name::fold(name).as_ref()).map(|&i| i as usize)
    }

    /// The tags in file order.
    pub fn iter(&self) -> std::slice::Iter<'_, Tag> {
        self.tags.iter()
    }

    pub fn len(&self) -> usize {
        self.tags.len()
    }

    pub fn is_empty(&self) -> bool {
        self.tags.is_empty()
    }

    /// Where the table came from (the file's path as given).
    pub fn origin(&self) -> &str {
        &self.origin
    }

    pub fn format(&self) -> Option<TagFormat> {
        self.format
    }

    /// The encoding the file was read in (`None` for a table made from text).
    pub fn encoding(&self) -> Option<Encoding> {
        self.encoding
    }

    /// "Did you mean": the names closest to `name` (case-insensitive edit distance at most a
    /// third of its length, at least 1; or names that start with it), nearest first, at most 3.
    pub fn suggest(&self, name: &str) -> Vec<&str> {
        name::nearest(name, self.tags.iter().map(|t| t.name.as_str()), 3)
    }

    /// The checks that need device families, as problems at each tag's line: a name that
    /// reads as an operand of any of `spaces`; an address that is not an operand of the
    /// first (the table's family), a type that does not fit it, and two tags on overlapping
    /// addresses of different sizes ([`check`]). Every problem, in file order.
    pub fn check(&self, spaces: &[&dyn OperandSpace]) -> Vec<TagProblem> {
        let (mut errors, overlaps) = check::check(self, spaces);
        errors.extend(overlaps);
        errors.sort_by_key(|p| (p.line, p.column));
        errors
    }

    /// [`TagTable::check`] as a result: the table, or the problems that stop it from loading.
    /// Overlapping addresses do not (a program reads `SMB0` and `SM0.0`, `VW100` and `VB101`
    /// on purpose): they are the table's [`TagTable::warnings`], for the loader to show.
    pub fn checked(mut self, spaces: &[&dyn OperandSpace]) -> Result<TagTable, TagProblems> {
        let (errors, overlaps) = check::check(&self, spaces);
        if errors.is_empty() {
            self.warnings = overlaps;
            Ok(self)
        } else {
            Err(TagProblems(errors))
        }
    }

    /// The problems found by [`TagTable::checked`] that let the table load (overlaps).
    pub fn warnings(&self) -> &[TagProblem] {
        &self.warnings
    }
}
