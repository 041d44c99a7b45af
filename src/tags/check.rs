//! The checks of a tag table that need device families (what `plcsh tags check` and a
//! loader run after reading): a name that reads as an operand of a family (`VW1`, `X0`,
//! `T37`), an address that is not an operand of the table's family, a type that does not
//! fit its address (`REAL` on `VW0`: 32 bits on 16), and two tags on overlapping memory
//! that are not the same operand (`Level AT VD200` and `Flags AT VW202`; two names of one
//! address, such as `T5` and `T5/BOOL`, are aliases and allowed).
//!
//! Overlaps: the spans ([`crate::core::Span`]) sorted by area and first bit, then one sweep
//! that keeps the farthest end seen so far — O(n log n) for n tags.

use super::{Tag, TagProblem, TagTable};
use crate::core::{OperandSpace, Span};
use crate::msg;

/// Every family problem of `table`, in file order: (the problems that stop it from loading,
/// the overlaps). `spaces[0]` is the family the addresses are read in; a name is refused if
/// it parses as an operand of any of `spaces`.
pub fn check(table: &TagTable, spaces: &[&dyn OperandSpace]) -> (Vec<TagProblem>, Vec<TagProblem>) {
    let mut out = Vec::new();
    let mut overlaps = Vec::new();
    let problem =
        |t: &Tag, message| TagProblem { origin: table.origin().to_string(), line: t.line, column: t.column, message };
    let mut spans: Vec<(Span, usize)> = Vec::new();
    for (i, t) in table.iter().enumerate() {
        if let Some(s) = spaces.iter().find(|s| s.parse(&t.name).is_ok_and(|ops| !ops.is_empty())) {
            out.push(problem(
                t,
                msg!("tags-name-is-operand", name = t.name.as_str(), family = s.family().to_ascii_uppercase()),
            ));
            continue;
        }
        let Some(space) = spaces.first() else { continue };
        let op = match t.resolve(*space) {
            Ok(op) => op,
            Err(e) => {
                out.push(problem(t, crate::core::msg::Msg { id: e.code, text: e.message.clone() }));
                continue;
            }
        };
        if let Some(span) = space.span(&op) {
            spans.push((span, i));
        }
    }
    spans.sort();
    let tags: Vec<&Tag> = table.iter().collect();
    // The span reaching farthest so far in the current area, and its tag.
    let mut reach: Option<(Span, usize)> = None;
    for &(s, i) in &spans {
        if let Some((r, j)) = reach {
            if r.area == s.area && s.first_bit < r.first_bit + r.bits && s != r {
                let (a, b) = (tags[j], tags[i]);
                // Report at the later of the two in the file.
                let (first, second) = if a.line <= b.line { (a, b) } else { (b, a) };
                overlaps.push(problem(
                    second,
                    msg!(
                        "tags-overlap",
                        name = second.name.as_str(),
                        address = second.address.as_str(),
                        other = first.name.as_str(),
                        other_address = first.address.as_str(),
                        line = first.line as i64
                    ),
                ));
            }
            if r.area != s.area || s.first_bit + s.bits > r.first_bit + r.bits {
                reach = Some((s, i));
            }
        } else {
            reach = Some((s, i));
        }
    }
    out.sort_by_key(|p| (p.line, p.column));
    overlaps.sort_by_key(|p| (p.line, p.column));
    (out, overlaps)
}
