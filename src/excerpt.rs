//! What a diagnostic shows of a file: the lines about its labels, each long
//! line cut to a window about what its labels point at, every control or
//! bidirectional character escaped, and the labels moved onto that text.
//! miette renders it as if it were the file: line numbers and the column in
//! the header stay the file's. Built from the file's line index, so each
//! diagnostic costs the lines it shows, however many diagnostics a file
//! has and however long its lines are (miette's columns are 16-bit).

use miette::{MietteError, MietteSpanContents, SourceCode, SourceSpan, SpanContents};

use crate::escape::push_escaped;
use crate::source::SourceFile;

/// Lines longer than this many characters are cut about their labels.
const LONGEST_LINE_CHARS: usize = 120;
/// Characters kept before a label's start on a cut line.
const BEFORE_LABEL_CHARS: usize = 40;
/// Lines shown before and after each label (miette's context).
pub const CONTEXT_LINES: usize = 1;

/// The shown part of a file, as miette's source code for one diagnostic.
#[derive(Clone, Debug)]
pub struct Excerpt {
    name: String,
    windows: Vec<Window>,
}

/// Consecutive lines of the file, as shown, at `base` in the excerpt's own
/// offsets (windows are apart, so that no span runs from one to the next).
#[derive(Clone, Debug)]
struct Window {
    base: usize,
    first_line: usize,
    text: String,
    /// Each label's start in the excerpt, with its column in the file.
    columns: Vec<(usize, usize)>,
}

/// One line as shown: where its kept part starts in the file, and for each
/// kept character boundary, its offset in the file and in the window.
struct ShownLine {
    text: String,
    boundaries: Vec<(usize, usize)>,
}

impl Excerpt {
    /// The excerpt of `file` about `labels` (byte ranges in the file), and
    /// those labels as ranges of the excerpt, in the same order.
    pub fn new(
        file: &SourceFile,
        name: &str,
        labels: &[(usize, usize)],
    ) -> (Self, Vec<SourceSpan>) {
        let lines = file.line_starts();
        let text = file.text.as_str();
        let line_of = |offset: usize| lines.partition_point(|&s| s <= offset).saturating_sub(1);
        let last_line = lines.len() - 1;
        // Line ranges to show, widened by the context and merged where they
        // touch, as miette merges the contexts it reads.
        let mut ranges: Vec<(usize, usize)> = labels
            .iter()
            .map(|&(start, end)| {
                let (a, b) = (line_of(start), line_of(end.max(start)));
                (
                    a.saturating_sub(CONTEXT_LINES),
                    (b + CONTEXT_LINES).min(last_line),
                )
            })
            .collect();
        ranges.sort_unstable();
        let mut merged: Vec<(usize, usize)> = Vec::new();
        for (a, b) in ranges {
            match merged.last_mut() {
                Some(last) if a <= last.1 + 1 => last.1 = last.1.max(b),
                _ => merged.push((a, b)),
            }
        }
        let mut windows = Vec::with_capacity(merged.len());
        let mut spans = vec![SourceSpan::from(0..0); labels.len()];
        let mut base = 0;
        for (first, last) in merged {
            let mut window = Window {
                base,
                first_line: first,
                text: String::new(),
                columns: Vec::new(),
            };
            let mut boundaries = Vec::new();
            for line in first..=last {
                let start = lines[line];
                let end = lines.get(line + 1).map_or(text.len(), |&s| s - 1);
                let content = text[start..end]
                    .strip_suffix('\r')
                    .unwrap_or(&text[start..end]);
                let focus = focus(labels, start, start + content.len());
                let shown = show_line(content, start, focus, base + window.text.len());
                window.text.push_str(&shown.text);
                boundaries.push(shown.boundaries);
                if line < last {
                    window.text.push('\n');
                }
            }
            let boundaries: Vec<(usize, usize)> = boundaries.into_iter().flatten().collect();
            for (i, &(start, end)) in labels.iter().enumerate() {
                if (first..=last).contains(&line_of(start)) {
                    let a = moved(&boundaries, start);
                    let b = moved(&boundaries, end.max(start)).max(a);
                    spans[i] = SourceSpan::from(a..b);
                    let column = text[lines[line_of(start)]..start.min(text.len())]
                        .chars()
                        .count();
                    window.columns.push((a, column));
                }
            }
            base += window.text.len() + 2;
            windows.push(window);
        }
        let excerpt = Excerpt {
            name: name.to_string(),
            windows,
        };
        (excerpt, spans)
    }
}

/// The byte range of a line (`line_start..line_end` in the file) that the
/// labels point at, if any does.
fn focus(labels: &[(usize, usize)], line_start: usize, line_end: usize) -> Option<(usize, usize)> {
    labels
        .iter()
        .filter(|&&(a, b)| a <= line_end && b.max(a) >= line_start)
        .map(|&(a, b)| (a.max(line_start), b.max(a).min(line_end)))
        .reduce(|x, y| (x.0.min(y.0), x.1.max(y.1)))
}

/// A line (`content`, at `start` in the file) as shown at `at` in the
/// excerpt: cut about `focus` if long, its unsafe characters escaped (tabs
/// kept, miette expands them).
fn show_line(content: &str, start: usize, focus: Option<(usize, usize)>, at: usize) -> ShownLine {
    let chars: Vec<(usize, char)> = content.char_indices().collect();
    let (from, to) = if chars.len() <= LONGEST_LINE_CHARS {
        (0, chars.len())
    } else {
        let char_at = |offset: usize| chars.partition_point(|&(i, _)| start + i < offset);
        let first = focus.map_or(0, |(a, _)| char_at(a).saturating_sub(BEFORE_LABEL_CHARS));
        let from = first.min(chars.len() - LONGEST_LINE_CHARS);
        (from, from + LONGEST_LINE_CHARS)
    };
    let mut text = String::new();
    if from > 0 {
        text.push('…');
    }
    let mut boundaries = Vec::with_capacity(to - from + 1);
    for &(i, c) in &chars[from..to] {
        boundaries.push((start + i, at + text.len()));
        push_escaped(&mut text, c, |c| c == '\t');
    }
    let end = chars.get(to).map_or(content.len(), |&(i, _)| i);
    boundaries.push((start + end, at + text.len()));
    if to < chars.len() {
        text.push('…');
    }
    ShownLine { text, boundaries }
}

/// Where file offset `offset` lands in the excerpt: at the kept boundary at
/// or after it, or the last one (a label beyond the cut ends at the cut).
fn moved(boundaries: &[(usize, usize)], offset: usize) -> usize {
    let i = boundaries.partition_point(|&(file, _)| file < offset);
    boundaries
        .get(i)
        .or(boundaries.last())
        .map_or(0, |&(_, shown)| shown)
}

impl SourceCode for Excerpt {
    fn read_span<'a>(
        &'a self,
        span: &SourceSpan,
        context_lines_before: usize,
        context_lines_after: usize,
    ) -> Result<Box<dyn SpanContents<'a> + 'a>, MietteError> {
        let window = self
            .windows
            .iter()
            .rev()
            .find(|w| w.base <= span.offset())
            .ok_or(MietteError::OutOfBounds)?;
        let start = span.offset() - window.base;
        let len = span.len().min(window.text.len().saturating_sub(start));
        let local = SourceSpan::from(start..start + len);
        let inner =
            window
                .text
                .as_str()
                .read_span(&local, context_lines_before, context_lines_after)?;
        let column = window
            .columns
            .iter()
            .find(|&&(at, _)| at == span.offset())
            .map_or(inner.column(), |&(_, column)| column);
        let at = SourceSpan::from(
            inner.span().offset() + window.base
                ..inner.span().offset() + window.base + inner.span().len(),
        );
        Ok(Box::new(MietteSpanContents::new_named(
            self.name.clone(),
            inner.data(),
            at,
            inner.line() + window.first_line,
            column,
            inner.line_count(),
        )))
    }
}
