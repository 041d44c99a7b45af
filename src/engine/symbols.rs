//! IL programs with symbols: a program exported with symbolic addressing (`LD Start_Button`,
//! `ST Motor_Run`) loads unchanged when its tags are declared in the program
//! (`VAR_GLOBAL … Start_Button AT %I0.0 : BOOL; … END_VAR`, IEC 61131-3 ed. 3 §6.5.5) or come
//! from a tag file beside it (`sim program load FILE.il tags=TAGS.csv`), or both.
//!
//! How: the `VAR_GLOBAL` blocks are read ([`crate::tags::iec::blocks`]) and then blanked out
//! of the text (every character but line breaks becomes a space), so every line and column
//! the loader reports is still the file's. Operands are resolved through [`Symbolic`], a
//! family that looks a word up in the tag table first and hands the tag's address to the
//! real family; a word that is neither a tag nor an operand is refused naming the nearest
//! tags. The compiled program is the same as the one written with addresses (the
//! differential test in tests/tags.rs runs both). A program without `VAR_GLOBAL` and without
//! a tag file compiles exactly as before, without this layer.
//!
//! The tag's declared type is not applied as a view here: in IL the instruction decides the
//! type it works on (`MOVR` reads a double word as REAL), as it does for an address.

use super::compile::{self, Program};
use super::{CostTable, Element, Family, Loc, OperandError, Resolved, SpecialDef};
use crate::core::{Error, ErrorKind, Result};
use crate::msg;
use crate::tags::{iec, name, Problems, Tag, TagTable};

/// A family whose operands may also be the names of `tags`.
pub struct Symbolic<'a, F: Family + ?Sized> {
    pub fam: &'a F,
    pub tags: &'a TagTable,
}

impl<F: Family + ?Sized> Symbolic<'_, F> {
    /// The tag `text` names, if any (`%` never starts a name).
    fn tag(&self, text: &str) -> Option<&Tag> {
        if text.starts_with('%') {
            return None;
        }
        self.tags.get(text.trim())
    }

    /// Resolves `text` through `f`: a tag's address, or the text itself as an operand. A word
    /// that is neither, and reads as a name, is an unknown symbol with the nearest tags.
    fn through<T>(
        &self,
        text: &str,
        f: impl Fn(&str) -> std::result::Result<T, OperandError>,
    ) -> std::result::Result<T, OperandError> {
        if let Some(t) = self.tag(text) {
            return f(&t.address).map_err(|e| OperandError {
                message: msg!(
                    "tags-symbol-address",
                    name = t.name.as_str(),
                    address = t.address.as_str(),
                    problem = e.message.as_str()
                )
                .into(),
                hint: e.hint,
            });
        }
        f(text).map_err(|e| unknown_symbol(self.tags, text, e))
    }
}

/// A word of a program with symbols that is neither a tag of `tags` nor an operand (`e` is
/// the family's refusal): when it reads as a name, refused as an unknown symbol naming the
/// nearest tags; else the family's refusal as it is. For every loader with symbols (the
/// engine's families through [`Symbolic`], the FX front end before its translation).
pub fn unknown_symbol(tags: &TagTable, text: &str, e: OperandError) -> OperandError {
    let word = text.trim();
    let looks_like_name = name::check(word).is_ok() || !word.is_ascii();
    if !looks_like_name {
        return e;
    }
    let near = tags.suggest(word);
    if near.is_empty() {
        OperandError { message: msg!("tags-unknown-symbol", name = word).into(), hint: e.hint.or(Some(e.message)) }
    } else {
        OperandError {
            message: msg!("tags-unknown-symbol-near", name = word, nearest = near.join(", ")).into(),
            hint: None,
        }
    }
}

impl<F: Family + ?Sized> Family for Symbolic<'_, F> {
    fn operand(&self, text: &str) -> std::result::Result<Resolved, OperandError> {
        self.through(text, |t| self.fam.operand(t))
    }
    fn value_operand(&self, text: &str) -> std::result::Result<Resolved, OperandError> {
        self.through(text, |t| self.fam.value_operand(t))
    }
    fn element(&self, text: &str, want_timer: bool) -> std::result::Result<Element, OperandError> {
        self.through(text, |t| self.fam.element(t, want_timer))
    }
    fn pointer(&self, loc: Loc) -> Option<u32> {
        self.fam.pointer(loc)
    }
    fn specials(&self) -> &'static [SpecialDef] {
        self.fam.specials()
    }
    fn costs(&self) -> CostTable {
        self.fam.costs()
    }
    fn events(&self) -> u32 {
        self.fam.events()
    }
    fn event_exists(&self, n: u32) -> bool {
        self.fam.event_exists(n)
    }
    fn event_list(&self) -> String {
        self.fam.event_list()
    }
}

/// Whether `text` may hold a `VAR_GLOBAL` block (a cheap test before the lexer runs).
fn mentions_var_global(text: &str) -> bool {
    text.as_bytes().windows(10).any(|w| w.eq_ignore_ascii_case(b"VAR_GLOBAL"))
}

/// `text` with the byte ranges `blocks` blanked: every character but `\n` and `\r` becomes
/// spaces of the same number of characters, so lines and columns stay.
fn blank(text: &str, blocks: &[std::ops::Range<usize>]) -> String {
    let mut out = String::with_capacity(text.len());
    let mut at = 0;
    for r in blocks {
        out.push_str(&text[at..r.start]);
        out.extend(text[r.clone()].chars().map(|c| if c == '\n' || c == '\r' { c } else { ' ' }));
        at = r.end;
    }
    out.push_str(&text[at..]);
    out
}

/// A program's symbols: its text with the `VAR_GLOBAL` blocks blanked (lines and columns
/// stay the file's) and the tags of those blocks merged with `tags` (a tag file given beside
/// the program). `None` for a program without either: it is an address program and loads
/// exactly as before. `address` says why a tag's address is not an operand of the family
/// (`Err(problem)`); such a tag is refused at its declaration, in the program or in the tag
/// file, as is a problem of the declarations (`file:line:column: …`, every problem a cause)
/// and a name declared in both.
pub fn declarations<'t>(
    text: &'t str,
    file: &str,
    tags: Option<&TagTable>,
    address: &dyn Fn(&str) -> std::result::Result<(), String>,
) -> Result<Option<(std::borrow::Cow<'t, str>, TagTable)>> {
    let declared = mentions_var_global(text);
    if !declared && tags.is_none_or(|t| t.is_empty()) {
        return Ok(None);
    }
    let mut problems = Problems::new(file);
    let (own, blocks) = if declared { iec::blocks(text, &mut problems) } else { (Vec::new(), Vec::new()) };
    let own_count = own.len();
    let own = if own.is_empty() && problems.list.is_empty() {
        TagTable::default()
    } else {
        TagTable::from_tags(own, file, None, problems)
            .map_err(|p| crate::core::encoding::printable_error(p.into_error()))?
    };
    let mut all: Vec<Tag> = own.iter().cloned().collect();
    if let Some(extra) = tags {
        for t in extra.iter() {
            if let Some(first) = own.get(&t.name) {
                return Err(Error::new(
                    ErrorKind::Syntax,
                    msg!(
                        "tags-declared-twice",
                        file = file,
                        line = first.line as i64,
                        column = first.column as i64,
                        name = first.name.as_str(),
                        tags = extra.origin(),
                        tag_line = t.line as i64
                    ),
                ));
            }
            all.push(t.clone());
        }
    }
    // The merged table: both parts are checked already and share no name.
    let table = TagTable::from_tags(all, file, None, Problems::new(file)).unwrap_or_default();
    // Every tag's address must be an operand of the family: refused at its declaration (in
    // the program or in the tag file).
    for (i, t) in table.iter().enumerate() {
        if let Err(problem) = address(&t.address) {
            let origin = if i < own_count { file } else { tags.map_or(file, |x| x.origin()) };
            return Err(Error::new(
                ErrorKind::Syntax,
                msg!(
                    "tags-declared-address",
                    file = origin,
                    line = t.line as i64,
                    column = t.column as i64,
                    name = t.name.as_str(),
                    address = t.address.as_str(),
                    problem = problem.as_str()
                ),
            )
            .operand(t.address.clone()));
        }
    }
    let text = if blocks.is_empty() {
        std::borrow::Cow::Borrowed(text)
    } else {
        std::borrow::Cow::Owned(blank(text, &blocks))
    };
    Ok(Some((text, table)))
}

/// Compiles IL `text` (named `file` in messages) for `fam`: the engine's loader
/// ([`compile::compile`]) with the program's own `VAR_GLOBAL` tags and those of `tags` (a tag
/// file given beside it), read by [`declarations`].
pub fn compile_with_tags<F: Family + ?Sized>(
    text: &str,
    file: &str,
    fam: &F,
    tags: Option<&TagTable>,
) -> Result<Program> {
    let address = |a: &str| fam.operand(a).map(|_| ()).map_err(|e| e.message);
    match declarations(text, file, tags, &address)? {
        None => compile::compile(text, file, fam),
        // Only a block without declarations: the program is an address program.
        Some((text, table)) if table.is_empty() => compile::compile(&text, file, fam),
        Some((text, table)) => compile::compile(&text, file, &Symbolic { fam, tags: &table }),
    }
}

/// [`compile_with_tags`] without a tag file: what every loader calls (`engine::compile`).
pub fn compile<F: Family + ?Sized>(text: &str, file: &str, fam: &F) -> Result<Program> {
    compile_with_tags(text, file, fam, None)
}
