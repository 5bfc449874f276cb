//! One open document: the editor's text, its last check (with the outline
//! of its names), and the answers of its last run, marked stale once the
//! text has changed since; and what the editor asks of it (completion,
//! hover, definition, references, code lenses, inlay hints).

use lsp_types::{
    CodeLens, Command, CompletionItem, CompletionItemKind, Documentation, Hover, HoverContents,
    InlayHint, InlayHintLabel, Location, MarkupContent, MarkupKind, Position, Range, TextEdit, Uri,
};

use super::files::{file_of_uri, uri_of_file};
use super::position::LineIndex;
use super::runner::Answers;
use reach::editor::{Analysis, CompletionKind, Found, Outline, SymbolKind};
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

/// A span's file and bytes, as the editor's library gives them.
type Place = (usize, u32, u32);

impl Document {
    /// The file of this document in its check, and the byte `position`
    /// is at.
    fn here(&self, position: Position) -> Option<(usize, usize)> {
        let sources = &self.analysis.sources;
        let file = file_of_uri(sources, &self.uri, &self.uri)?;
        let (_, source) = sources.iter().nth(file)?;
        if source.text.as_str() != self.text {
            return None;
        }
        Some((file, LineIndex::new(&self.text).offset(position)))
    }

    fn location(&self, (file, start, end): Place) -> Option<Location> {
        let sources = &self.analysis.sources;
        let uri = uri_of_file(sources, file, &self.uri)?;
        let (_, source) = sources.iter().nth(file)?;
        let range = LineIndex::new(&source.text).range(start as usize, end as usize);
        Some(Location::new(uri, range))
    }

    pub fn completion(&self, position: Position, registry: &Registry) -> Vec<CompletionItem> {
        let offset = LineIndex::new(&self.text).offset(position);
        let outline = self
            .analysis
            .outline
            .as_ref()
            .or(self.last_outline.as_ref());
        let found = reach::editor::completions(&self.text, offset, outline, registry);
        found
            .into_iter()
            .map(|c| CompletionItem {
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
                        Range::new(Position::new(0, 0), Position::new(0, 0)),
                        format!("use std::{module}\n"),
                    )]
                }),
                label: c.label,
                ..CompletionItem::default()
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

    pub fn references(&self, position: Position, with_declaration: bool) -> Vec<Location> {
        let Some((file, offset)) = self.here(position) else {
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

    /// Whether the answers shown were run on another text than this.
    fn stale(&self) -> bool {
        self.answers.as_ref().is_some_and(|a| a.edit != self.edit)
    }

    pub fn code_lenses(&self) -> Vec<CodeLens> {
        let Some(answers) = &self.answers else {
            return Vec::new();
        };
        let mark = if self.stale() { "(stale) " } else { "" };
        let mut out: Vec<CodeLens> = answers
            .lenses
            .iter()
            .map(|(range, ok, text)| CodeLens {
                range: *range,
                command: Some(Command::new(
                    format!("{mark}{}{text}", if *ok { "" } else { "✗ " }),
                    String::new(),
                    None,
                )),
                data: None,
            })
            .collect();
        if let Some(stopped) = &answers.stopped {
            out.push(CodeLens {
                range: Range::default(),
                command: Some(Command::new(
                    format!("{mark}run stopped: {stopped}"),
                    String::new(),
                    None,
                )),
                data: None,
            });
        }
        out
    }

    /// One hint at the end of each declaration's line: its answers, in
    /// short.
    pub fn inlay_hints(&self) -> Vec<InlayHint> {
        let Some(answers) = &self.answers else {
            return Vec::new();
        };
        let mark = if self.stale() { "(stale) " } else { "" };
        let mut by_line: std::collections::BTreeMap<u32, Vec<&str>> = Default::default();
        for (range, _, text) in &answers.lenses {
            by_line.entry(range.start.line).or_default().push(text);
        }
        let lines: Vec<&str> = self.text.lines().collect();
        by_line
            .into_iter()
            .map(|(line, texts)| {
                let end = lines
                    .get(line as usize)
                    .map_or(0, |l| l.encode_utf16().count());
                InlayHint {
                    position: Position::new(line, end as u32),
                    label: InlayHintLabel::String(format!("  {mark}{}", texts.join("; "))),
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
