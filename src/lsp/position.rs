//! Places in a file as the Language Server Protocol counts them: a line
//! and a character offset in UTF-16 code units (what the protocol asks of
//! a server that does not negotiate another encoding), from the byte
//! offsets the checker's spans hold.

use lsp_types::{Position, Range};

/// The starts of a text's lines, to turn byte offsets into positions.
pub struct LineIndex<'t> {
    text: &'t str,
    /// The byte offset of each line's first byte.
    starts: Vec<usize>,
}

impl<'t> LineIndex<'t> {
    pub fn new(text: &'t str) -> Self {
        let starts = std::iter::once(0)
            .chain(text.match_indices('\n').map(|(i, _)| i + 1))
            .collect();
        LineIndex { text, starts }
    }

    /// The position of byte `offset` (past the end: the end; within a
    /// character: that character's start).
    pub fn position(&self, offset: usize) -> Position {
        let mut offset = offset.min(self.text.len());
        while !self.text.is_char_boundary(offset) {
            offset -= 1;
        }
        let line = self.starts.partition_point(|&s| s <= offset) - 1;
        let start = self.starts[line];
        let character = self.text[start..offset].encode_utf16().count();
        Position::new(line as u32, character as u32)
    }

    /// The byte offset of `position` (past a line's end: its end; past
    /// the last line: the text's end).
    pub fn offset(&self, position: Position) -> usize {
        let Some(&start) = self.starts.get(position.line as usize) else {
            return self.text.len();
        };
        let end =
            (self.starts.get(position.line as usize + 1)).map_or(self.text.len(), |&next| next - 1);
        let mut units = 0;
        for (k, c) in self.text[start..end].char_indices() {
            if units >= position.character as usize {
                return start + k;
            }
            units += c.len_utf16();
        }
        end
    }

    /// The range of bytes `start..end`.
    pub fn range(&self, start: usize, end: usize) -> Range {
        Range::new(self.position(start), self.position(end.max(start)))
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn characters_are_counted_in_utf16_code_units() {
        // `é` is two bytes and one unit; `😀` four bytes and two units.
        let text = "ab\ncé😀x\n\nlast";
        let index = LineIndex::new(text);
        let at = |needle: &str| index.position(text.find(needle).unwrap());
        assert_eq!(at("ab"), Position::new(0, 0));
        assert_eq!(at("c"), Position::new(1, 0));
        assert_eq!(at("😀"), Position::new(1, 2));
        assert_eq!(at("x"), Position::new(1, 4));
        assert_eq!(at("last"), Position::new(3, 0));
        assert_eq!(index.position(text.len() + 10), Position::new(3, 4));
        // Inside `😀`: its start.
        assert_eq!(
            index.position(text.find('😀').unwrap() + 1),
            Position::new(1, 2)
        );
        // And back.
        for needle in ["ab", "c", "😀", "x", "last"] {
            let offset = text.find(needle).unwrap();
            assert_eq!(index.offset(index.position(offset)), offset, "{needle}");
        }
        assert_eq!(index.offset(Position::new(0, 99)), 2, "past a line's end");
        assert_eq!(index.offset(Position::new(9, 0)), text.len());
        let x = text.find('x').unwrap();
        assert_eq!(
            index.range(x, x + 1),
            Range::new(Position::new(1, 4), Position::new(1, 5))
        );
    }
}
