//! One open document: the editor's text, its last check (with the outline
//! of its names), and the answers of its last run, marked stale once the
//! text has changed since; and what the editor asks of it (completion,
//! hover, definition, references, code lenses, inlay hints).

use lsp_types::{
    CodeLens, Command, CompletionItem, CompletionItemKind, CompletionTextEdit, Documentation,
    Hover, HoverContents, InlayHint, InlayHintLabel, Location, MarkupContent, MarkupKind, Position,
    Range, TextEdit, Uri,
};

use std::collections::BTreeMap;

use lsp_types::{Diagnostic, DiagnosticSeverity};

use super::files::{file_of_uri, uri_of_file};
use super::position::LineIndex;
use super::runner::Answers;
use reach::editor::{Analysis, CompletionKind, Found, Outline, RenameRefused, SymbolKind};
use reach::plugin::Registry;

pub struct Document {
    pub uri: Uri,
    pub text: String,
    /// Changes since it was opened: answers run at another are stale.
    pub edit: u64,
    pub analysis: Analysis,
    /// The outline of the last text that parsed: names to complete while
    /// the text being typed does not.
    pub last_outline: Option<Outline>,
    pub answers: Option<Answers>,
}

/// What a rename changes, as one document's check sees it.
pub struct Renamed {
    /// Every place the name is written.
    pub places: Vec<Location>,
    /// The name where the rename was asked.
    pub range: Range,
    pub name: String,
}

/// A span's file and bytes, as the editor's library gives them.
type Place = (usize, u32, u32);

impl Document {
    /// The file of this document in its check, and the byte `position`
    /// is at.
    fn here(&self, position: Position) -> Option<(usize, usize)> {
        self.here_of(&self.uri, &self.text, position)
    }

    /// The file `uri` (whose text the editor holds as `text`) in this
    /// document's check, and the byte `position` is at: none where the
    /// check did not read it, or read another text of it.
    fn here_of(&self, uri: &Uri, text: &str, position: Position) -> Option<(usize, usize)> {
        let sources = &self.analysis.sources;
        let file = file_of_uri(sources, uri, &self.uri)?;
        let (_, source) = sources.iter().nth(file)?;
        if source.text.as_str() != text {
            return None;
        }
        Some((file, LineIndex::new(text).offset(position)))
    }

    fn location(&self, (file, start, end): Place) -> Option<Location> {
        let sources = &self.analysis.sources;
        let uri = uri_of_file(sources, file, &self.uri)?;
        let (_, source) = sources.iter().nth(file)?;
        let range = LineIndex::new(&source.text).range(start as usize, end as usize);
        Some(Location::new(uri, range))
    }

    pub fn completion(&self, position: Position, registry: &Registry) -> Vec<CompletionItem> {
        let index = LineIndex::new(&self.text);
        let offset = index.offset(position);
        let outline = (self.analysis.outline.as_ref()).or(self.last_outline.as_ref());
        let found = reach::editor::completions(&self.text, offset, outline, registry);
        let use_line = Position::new(first_code_line(&self.text), 0);
        found
            .into_iter()
            .map(|c| {
                // A unit replaces what follows the number's digits; the
                // client filters it by the whole word (`5m` for `mm`).
                let edit = c.replaces_from.map(|from| {
                    let range = Range::new(index.position(from), index.position(offset));
                    CompletionTextEdit::Edit(TextEdit::new(range, c.label.clone()))
                });
                let filter = c.replaces_from.map(|from| {
                    let word_start = self.text[..from]
                        .rfind(|ch: char| !(ch.is_ascii_digit() || ch == '.'))
                        .map_or(0, |k| k + 1);
                    format!("{}{}", &self.text[word_start..from], c.label)
                });
                CompletionItem {
                    kind: Some(item_kind(c.kind)),
                    detail: Some(c.detail),
                    documentation: c.doc.map(|d| {
                        Documentation::MarkupContent(MarkupContent {
                            kind: MarkupKind::Markdown,
                            value: d,
                        })
                    }),
                    additional_text_edits: c.needs_use.map(|module| {
                        vec![TextEdit::new(
                            Range::new(use_line, use_line),
                            format!("use std::{module}\n"),
                        )]
                    }),
                    text_edit: edit,
                    filter_text: filter,
                    label: c.label,
                    ..CompletionItem::default()
                }
            })
            .collect()
    }

    pub fn hover(&self, position: Position, registry: &Registry) -> Option<Hover> {
        let (file, offset) = self.here(position)?;
        let analysis = &self.analysis;
        let text = reach::editor::hover(
            (&analysis.sources, file, offset),
            analysis.outline.as_ref(),
            analysis.checked.as_ref().ok(),
            registry,
        )?;
        Some(Hover {
            contents: HoverContents::Markup(MarkupContent {
                kind: MarkupKind::Markdown,
                value: text,
            }),
            range: None,
        })
    }

    pub fn definition(&self, position: Position) -> Vec<Location> {
        let Some((file, offset)) = self.here(position) else {
            return Vec::new();
        };
        let Some(outline) = &self.analysis.outline else {
            return Vec::new();
        };
        let places: Vec<Place> = match outline.at_index(file, offset) {
            Some(Found::Declaration(s)) => vec![(s.span.file.0 as usize, s.span.start, s.span.end)],
            Some(Found::Use(_, symbols)) => symbols
                .iter()
                .map(|s| (s.span.file.0 as usize, s.span.start, s.span.end))
                .collect(),
            Some(Found::Module(u)) => self.module_file(u).into_iter().collect(),
            _ => Vec::new(),
        };
        places
            .into_iter()
            .filter_map(|p| self.location(p))
            .collect()
    }

    /// The start of the file a `use` names, where this check loaded it.
    fn module_file(&self, used: &reach::editor::UseOf) -> Option<Place> {
        let wanted = match &used.target {
            reach::editor::UseTarget::Std(module) => format!("std::{module}"),
            reach::editor::UseTarget::Path(path) => path.clone(),
        };
        let sources = &self.analysis.sources;
        let file = sources.iter().position(|(_, f)| {
            f.name == wanted || f.path().is_some_and(|p| p.ends_with(&wanted))
        })?;
        Some((file, 0, 0))
    }

    /// The uses of the name at `position` of the file `uri` (whose text
    /// is `text`), as this document's check sees them: a file another
    /// open document uses finds that document's uses too.
    pub fn references(
        &self,
        (uri, text, position): (&Uri, &str, Position),
        with_declaration: bool,
    ) -> Vec<Location> {
        let Some((file, offset)) = self.here_of(uri, text, position) else {
            return Vec::new();
        };
        let Some(outline) = &self.analysis.outline else {
            return Vec::new();
        };
        let symbols = match outline.at_index(file, offset) {
            Some(Found::Declaration(s)) => vec![s],
            Some(Found::Use(_, symbols)) => symbols,
            _ => Vec::new(),
        };
        let mut places: Vec<Place> = Vec::new();
        for symbol in symbols {
            if with_declaration {
                places.push((
                    symbol.span.file.0 as usize,
                    symbol.span.start,
                    symbol.span.end,
                ));
            }
            for span in outline.uses_of(symbol) {
                places.push((span.file.0 as usize, span.start, span.end));
            }
        }
        places
            .into_iter()
            .filter_map(|p| self.location(p))
            .collect()
    }

    /// What a rename at `position` of the file `uri` (whose text the
    /// editor holds as `text`) to `new` changes, as this document's check
    /// sees it: nothing where it did not read that file; refused where the
    /// name is not one, is the standard library's, or `new` may not be.
    pub fn rename_places(
        &self,
        (uri, text, position): (&Uri, &str, Position),
        new: Option<&str>,
    ) -> Result<Option<Renamed>, RenameRefused> {
        let Some((file, offset)) = self.here_of(uri, text, position) else {
            return Ok(None);
        };
        let outline = (self.analysis.outline.as_ref()).ok_or(RenameRefused::DoesNotParse)?;
        let (symbols, span) = reach::editor::renamed_at(outline, file, offset)?;
        let sources = &self.analysis.sources;
        let in_std = |s: &&reach::editor::Symbol| {
            let source = sources.iter().nth(s.span.file.0 as usize);
            source.is_some_and(|(_, f)| f.std_module().is_some())
        };
        if let Some(std) = symbols.iter().find(|s| in_std(s)) {
            return Err(RenameRefused::Std {
                name: std.name.clone(),
            });
        }
        if let Some(new) = new {
            reach::editor::may_rename_to(outline, &symbols, new)?;
        }
        let range = LineIndex::new(text).range(span.start as usize, span.end as usize);
        let places = reach::editor::written_at(outline, &symbols);
        let places = (places.into_iter())
            .filter_map(|s| self.location((s.file.0 as usize, s.start, s.end)))
            .collect();
        Ok(Some(Renamed {
            places,
            range,
            name: symbols[0].name.clone(),
        }))
    }

    /// Whether the answers shown were run on another text than this.
    /// (By the text, not the edit count: an edit undone brings the run's
    /// text, and its answers, back.)
    fn stale(&self) -> bool {
        self.answers.as_ref().is_some_and(|a| a.text != self.text)
    }

    /// The line of this text that line `line` of the text run is now: the
    /// same line where it reads the same, else the nearest that does;
    /// none where no line does (the declaration was edited).
    fn relocated(&self, answers: &Answers, line: u32) -> Option<u32> {
        let was = answers.text.lines().nth(line as usize)?;
        let now: Vec<&str> = self.text.lines().collect();
        if now.get(line as usize) == Some(&was) {
            return Some(line);
        }
        (now.iter().enumerate())
            .filter(|(_, l)| **l == was)
            .min_by_key(|(k, _)| k.abs_diff(line as usize))
            .map(|(k, _)| k as u32)
    }

    /// The answers by the line of this text they are on (moved with their
    /// declarations, where the text changed since the run), each with
    /// whether it is ok.
    fn answers_by_line(&self) -> BTreeMap<u32, Vec<(bool, &str)>> {
        let mut by_line: BTreeMap<u32, Vec<(bool, &str)>> = BTreeMap::new();
        let Some(answers) = &self.answers else {
            return by_line;
        };
        for (range, ok, text) in &answers.lenses {
            if let Some(line) = self.relocated(answers, range.start.line) {
                by_line.entry(line).or_default().push((*ok, text));
            }
        }
        by_line
    }

    fn mark(&self) -> &'static str {
        if self.stale() {
            "(stale) "
        } else {
            ""
        }
    }

    /// A lens for each answer on a declaration of a few; for more, a
    /// count, then those not ok (three at most).
    pub fn code_lenses(&self) -> Vec<CodeLens> {
        let mark = self.mark();
        let lens = |line: u32, title: String| CodeLens {
            range: Range::new(Position::new(line, 0), Position::new(line, 0)),
            command: Some(Command::new(format!("{mark}{title}"), String::new(), None)),
            data: None,
        };
        let mut out = Vec::new();
        for (line, answers) in self.answers_by_line() {
            let titled = |(ok, text): &(bool, &str)| {
                if *ok {
                    text.to_string()
                } else {
                    format!("✗ {text}")
                }
            };
            if answers.len() <= MAX_LENSES {
                out.extend(answers.iter().map(|a| lens(line, titled(a))));
                continue;
            }
            out.push(lens(line, count(&answers)));
            let not_ok: Vec<&(bool, &str)> = answers.iter().filter(|(ok, _)| !ok).collect();
            out.extend(not_ok.iter().take(3).map(|a| lens(line, titled(a))));
            if not_ok.len() > 3 {
                out.push(lens(
                    line,
                    format!("and {} more not ok (reach run)", not_ok.len() - 3),
                ));
            }
        }
        if let Some(stopped) = self.answers.as_ref().and_then(|a| a.stopped.as_ref()) {
            out.push(lens(0, format!("run stopped: {stopped}")));
        }
        out
    }

    /// One hint at the end of each declaration's line: its answers, in
    /// short (a count and those not ok, where there are more than a few).
    pub fn inlay_hints(&self) -> Vec<InlayHint> {
        let mark = self.mark();
        let lines: Vec<&str> = self.text.lines().collect();
        self.answers_by_line()
            .into_iter()
            .map(|(line, answers)| {
                let end = lines
                    .get(line as usize)
                    .map_or(0, |l| l.encode_utf16().count());
                let shown: Vec<String> = if answers.len() <= MAX_LENSES {
                    answers
                        .iter()
                        .map(|(ok, t)| format!("{}{t}", if *ok { "" } else { "✗ " }))
                        .collect()
                } else {
                    let not_ok = answers
                        .iter()
                        .filter(|(ok, _)| !ok)
                        .map(|(_, t)| format!("✗ {t}"));
                    std::iter::once(count(&answers))
                        .chain(not_ok.take(3))
                        .collect()
                };
                let mut label = format!("{mark}{}", shown.join("; "));
                if label.chars().count() > MAX_HINT_CHARS {
                    label = label.chars().take(MAX_HINT_CHARS - 1).collect::<String>() + "…";
                }
                InlayHint {
                    position: Position::new(line, end as u32),
                    label: InlayHintLabel::String(label),
                    kind: None,
                    text_edits: None,
                    tooltip: None,
                    padding_left: Some(true),
                    padding_right: None,
                    data: None,
                }
            })
            .collect()
    }

    /// The run's unmet `expect`s, moved with their lines; stale ones as
    /// warnings that say so.
    pub fn unmet(&self) -> Vec<Diagnostic> {
        let Some(answers) = &self.answers else {
            return Vec::new();
        };
        let stale = self.stale();
        let lines: Vec<&str> = self.text.lines().collect();
        answers
            .unmet
            .iter()
            .filter_map(|d| {
                let line = self.relocated(answers, d.range.start.line)?;
                let mut d = d.clone();
                let end = lines
                    .get(line as usize)
                    .map_or(0, |l| l.encode_utf16().count() as u32);
                d.range = Range::new(Position::new(line, 0), Position::new(line, end));
                if stale {
                    d.message = format!("(stale) {}", d.message);
                    d.severity = Some(DiagnosticSeverity::WARNING);
                }
                Some(d)
            })
            .collect()
    }
}

/// At most this many answers of one declaration are lenses of their own.
const MAX_LENSES: usize = 4;
/// An inlay hint is cut to this many characters.
const MAX_HINT_CHARS: usize = 160;

/// `16 answers: 11 ok, 5 not`.
fn count(answers: &[(bool, &str)]) -> String {
    let ok = answers.iter().filter(|(ok, _)| *ok).count();
    format!(
        "{} answers: {ok} ok, {} not",
        answers.len(),
        answers.len() - ok
    )
}

fn item_kind(kind: CompletionKind) -> CompletionItemKind {
    match kind {
        CompletionKind::Keyword => CompletionItemKind::KEYWORD,
        CompletionKind::Name(SymbolKind::Constant) => CompletionItemKind::CONSTANT,
        CompletionKind::Name(SymbolKind::Room | SymbolKind::Mannequin | SymbolKind::Population) => {
            CompletionItemKind::STRUCT
        }
        CompletionKind::Name(SymbolKind::Parameter | SymbolKind::Draw) => {
            CompletionItemKind::VARIABLE
        }
        CompletionKind::Name(_) => CompletionItemKind::REFERENCE,
        CompletionKind::Plugin => CompletionItemKind::MODULE,
        CompletionKind::Option => CompletionItemKind::PROPERTY,
        CompletionKind::Unit => CompletionItemKind::UNIT,
        CompletionKind::Module => CompletionItemKind::MODULE,
        CompletionKind::Value => CompletionItemKind::VALUE,
    }
}

/// The first line after the comments and blank lines a file starts with:
/// where a `use` added goes.
fn first_code_line(text: &str) -> u32 {
    let skipped = text
        .lines()
        .take_while(|l| l.trim().is_empty() || l.trim_start().starts_with("//"))
        .count();
    skipped as u32
}
