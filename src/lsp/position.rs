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
        let x = text.find('x').unwrap();
        assert_eq!(
            index.range(x, x + 1),
            Range::new(Position::new(1, 4), Position::new(1, 5))
        );
    }
}
