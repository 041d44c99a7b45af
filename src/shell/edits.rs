//! Where a word of a rewritten command line was typed. Before a command runs, the shell may
//! rewrite its arguments — the K2 manual's Cyrillic spelling read as Latin letters
//! (`ВW0` → `VW0`, [`super::fold_operands`]) and tag names written as their operands
//! (`Start_Button` → `I0.1`, [`super::names::operands_for`]) — and the command's refusal
//! then carries a column in the rewritten text. [`Edits`] keeps what was replaced by what, so
//! the shell can move that column back to the text the person typed (a caret under their
//! word, not under a shorter or longer one they never saw).

/// The replacements that made a new text from an old one, in text order.
#[derive(Clone, Debug, Default, PartialEq)]
pub struct Edits {
    segs: Vec<Seg>,
}

#[derive(Clone, Debug, PartialEq)]
struct Seg {
    /// Byte range in the old text.
    old: (usize, usize),
    /// Byte range in the new text.
    new: (usize, usize),
    /// Character for character (a spelling fold): a column inside maps to the same character;
    /// else (a name for its operand) to the start of the old piece.
    charwise: bool,
}

impl Edits {
    /// Records that `old` (a byte range of the old text) became `new` (of the new text).
    /// Calls come in text order.
    pub fn replaced(&mut self, old: (usize, usize), new: (usize, usize), charwise: bool) {
        self.segs.push(Seg { old, new, charwise });
    }

    pub fn is_empty(&self) -> bool {
        self.segs.is_empty()
    }

    /// Byte position `p` of `new` as a position of `old`: inside a replaced piece, where that
    /// piece was typed; after it, shifted by the difference in length.
    pub fn typed(&self, old: &str, new: &str, p: usize) -> usize {
        let mut delta: isize = 0;
        for s in &self.segs {
            if p < s.new.0 {
                break;
            }
            if p < s.new.1 {
                if !s.charwise {
                    return s.old.0;
                }
                let n = new.get(s.new.0..p).map_or(0, |t| t.chars().count());
                let piece = old.get(s.old.0..s.old.1).unwrap_or("");
                return s.old.0 + piece.char_indices().nth(n).map_or(piece.len(), |(i, _)| i);
            }
            delta = s.old.1 as isize - s.new.1 as isize;
        }
        (p as isize + delta).clamp(0, old.len() as isize) as usize
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_column_in_the_new_text_moves_back_to_what_was_typed() {
        // `sim input Start_Button freq=x` → `sim input I0.1 freq=x`.
        let (old, new) = ("Start_Button freq=x", "I0.1 freq=x");
        let mut e = Edits::default();
        e.replaced((0, 12), (0, 4), false);
        assert_eq!(e.typed(old, new, 0), 0);
        assert_eq!(e.typed(old, new, 2), 0, "inside the operand: the name's start");
        assert_eq!(e.typed(old, new, 5), 13, "after it: shifted");
        assert_eq!(&old[e.typed(old, new, 5)..], "freq=x");
        // A fold, character for character: `ВW0 VW99999x` → `VW0 VW99999x`.
        let (old, new) = ("ВW0 VW9x", "VW0 VW9x");
        let mut e = Edits::default();
        e.replaced((0, 4), (0, 3), true);
        assert_eq!(e.typed(old, new, 1), 2, "the W after the Cyrillic В");
        assert_eq!(&old[e.typed(old, new, 4)..], "VW9x");
        assert_eq!(Edits::default().typed(old, new, 3), 3);
    }
}
