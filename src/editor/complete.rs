//! What may be typed at a place in a scenario being written: keywords of
//! the block the place is in, names declared (in the files and in the
//! standard library, with the `use` they need), a plugin's options inside
//! its block (with their kind, default and doc) and the values an option
//! takes, units after a number. Read from the text about the place, not
//! from a parse: a file being typed seldom parses.

use super::outline::{Outline, SymbolKind};
use crate::options::{ParamKind, ParamSpec, PluginKind, Settings};
use crate::plugin::{Registry, SubjectKind};
use crate::scene::FACES;
use crate::syntax::code_bytes;

/// What a completion is, for the editor's icon.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum CompletionKind {
    Keyword,
    /// A declared name, of this kind.
    Name(SymbolKind),
    Plugin,
    Option,
    Unit,
    Module,
    Value,
}

/// One thing that may be typed.
#[derive(Clone, Debug, PartialEq)]
pub struct Completion {
    pub label: String,
    pub kind: CompletionKind,
    /// One line: the option's kind and default, the name's kind.
    pub detail: String,
    /// Markdown: an option's or plugin's doc.
    pub doc: Option<String>,
    /// The standard library module that declares it, where the text has
    /// no `use` of it yet.
    pub needs_use: Option<&'static str>,
    /// Where it is not a whole word: the byte its text replaces from to
    /// the place (a unit after a number's digits).
    pub replaces_from: Option<usize>,
}

/// The units a number may carry.
const UNITS: [(&str, &str); 8] = [
    ("mm", "millimetres"),
    ("cm", "centimetres: 10 mm"),
    ("m", "metres: 1000 mm"),
    ("in", "inches: 25.4 mm"),
    ("deg", "degrees"),
    ("rad", "radians: 57.3 deg"),
    ("arcmin", "minutes of arc: 1/60 deg"),
    ("%", "a share: the number divided by 100"),
];

/// The block a place is in.
#[derive(Clone, Debug)]
enum Block {
    Top,
    Room,
    Mannequin,
    /// A person's or a population's `mannequin NAME { ... }`, or a profile.
    Overrides,
    Person,
    Population,
    /// An option block (a plugin's, `vision`'s or `limits`'s), by its
    /// parameters.
    Options(Vec<ParamSpec>),
    Unknown,
}

/// What may be typed at byte `offset` of `text`.
pub fn completions(
    text: &str,
    offset: usize,
    outline: Option<&Outline>,
    registry: &Registry,
) -> Vec<Completion> {
    let offset = floor_boundary(text, offset);
    let before = &text[..offset];
    let word_start = before
        .char_indices()
        .rev()
        .find(|(_, c)| !(c.is_ascii_alphanumeric() || *c == '_'))
        .map_or(0, |(k, c)| k + c.len_utf8());
    let word = &before[word_start..];
    if !in_code(text, word_start) {
        return Vec::new();
    }
    if word.starts_with(|c: char| c.is_ascii_digit()) {
        // The unit replaces what follows the number's digits.
        let digits = word.len()
            - word
                .trim_start_matches(|c: char| c.is_ascii_digit() || c == '.')
                .len();
        let unit_part = &word[digits..];
        let mut out = units(word_start + digits);
        out.retain(|c| c.label.starts_with(unit_part));
        return out;
    }
    let head = &before[..word_start];
    if head.ends_with("std::") {
        return modules();
    }
    let found = Found {
        outline,
        registry,
        used: used_modules(text),
    };
    if let Some(whole) = head.strip_suffix('.') {
        return found.faces(whole);
    }
    // In a point or a call: the constants an expression may use.
    if in_parentheses(head) {
        let tokens = tokens_back(head);
        let kinds = match tokens.get(1).map(String::as_str) {
            Some("share") if tokens[0] == "(" => [SymbolKind::Population],
            _ => [SymbolKind::Constant],
        };
        let mut out = found.names(&kinds);
        out.retain(|c| c.label.starts_with(word) && c.label != word);
        return out;
    }
    let tokens = tokens_back(head);
    let block = block_at(head, registry, outline);
    let line_start = head
        .rsplit('\n')
        .next()
        .is_some_and(|l| l.trim().is_empty());
    let mut out = found.after(&tokens, &block, line_start);
    out.retain(|c| c.label.starts_with(word) && c.label != word);
    out
}

/// Whether a place at byte `at` of `text` is in code: what comes just
/// before it is code (not a comment's or a string's), or a line's end.
fn in_code(text: &str, at: usize) -> bool {
    let Some(before) = text[..at].chars().next_back() else {
        return true;
    };
    let previous = at - before.len_utf8();
    before == '\n' || code_bytes(text).any(|(k, _)| k == previous)
}

/// Whether a place is inside parentheses (a point, a call's arguments):
/// where `before` leaves one open.
fn in_parentheses(before: &str) -> bool {
    let depth = code_bytes(before).fold(0i64, |depth, (_, b)| match b {
        b'(' => depth + 1,
        b')' => depth - 1,
        b'{' | b'}' => 0,
        _ => depth,
    });
    depth > 0
}

/// The last char boundary at or before `offset`.
fn floor_boundary(text: &str, offset: usize) -> usize {
    let mut offset = offset.min(text.len());
    while !text.is_char_boundary(offset) {
        offset -= 1;
    }
    offset
}

/// The units, each replacing the text from byte `from` (after the
/// number's digits) to the place.
fn units(from: usize) -> Vec<Completion> {
    UNITS
        .iter()
        .map(|(unit, what)| Completion {
            replaces_from: Some(from),
            ..plain(unit, CompletionKind::Unit, what)
        })
        .collect()
}

fn plain(label: &str, kind: CompletionKind, detail: &str) -> Completion {
    Completion {
        label: label.to_string(),
        kind,
        detail: detail.to_string(),
        doc: None,
        needs_use: None,
        replaces_from: None,
    }
}

fn modules() -> Vec<Completion> {
    crate::std_texts::MODULES
        .iter()
        .map(|(name, text)| Completion {
            label: name.to_string(),
            kind: CompletionKind::Module,
            detail: format!("std::{name}"),
            doc: Some(first_comment(text)),
            needs_use: None,
            replaces_from: None,
        })
        .collect()
}

/// The comment a module's text starts with, as one paragraph.
fn first_comment(text: &str) -> String {
    let lines: Vec<&str> = text
        .lines()
        .take_while(|l| l.starts_with("//"))
        .map(|l| l.trim_start_matches('/').trim())
        .collect();
    lines.join(" ")
}

/// The standard library modules `text` uses.
fn used_modules(text: &str) -> Vec<String> {
    text.lines()
        .filter_map(|l| l.trim().strip_prefix("use std::"))
        .map(|m| m.trim().to_string())
        .collect()
}

/// The code's words and marks before a place, last first (a few
/// statements' worth), comments and strings left out.
fn tokens_back(before: &str) -> Vec<String> {
    let start = before.len().saturating_sub(400);
    let start = (0..=start)
        .rev()
        .find(|&k| before.is_char_boundary(k))
        .unwrap_or(0);
    let code: String = code_bytes(&before[start..])
        .map(|(_, b)| b as char)
        .collect();
    let mut tokens = Vec::new();
    let mut word = String::new();
    for c in code.chars() {
        if c.is_ascii_alphanumeric() || c == '_' || c == '.' {
            word.push(c);
            continue;
        }
        if !word.is_empty() {
            tokens.push(std::mem::take(&mut word));
        }
        if !c.is_whitespace() {
            tokens.push(c.to_string());
        }
    }
    if !word.is_empty() {
        tokens.push(word);
    }
    tokens.reverse();
    tokens
}

/// The blocks open at the end of `before`, innermost last, as the
/// headers before their braces say.
fn block_at(before: &str, registry: &Registry, outline: Option<&Outline>) -> Block {
    let mut open: Vec<usize> = Vec::new();
    for (at, b) in code_bytes(before) {
        match b {
            b'{' => open.push(at),
            b'}' => {
                open.pop();
            }
            _ => {}
        }
    }
    let mut block = Block::Top;
    for &brace in &open {
        block = inner_block(&block, &header(&before[..brace]), registry, outline);
    }
    block
}

/// The words of the statement a brace at the end of `before` opens: its
/// line, and the line before where it starts with `by`.
fn header(before: &str) -> Vec<String> {
    let line_start = before.rfind('\n').map_or(0, |k| k + 1);
    let mut words = tokens_back(&before[line_start..]);
    if words.last().is_some_and(|w| w == "by") || words.is_empty() {
        let above = &before[..line_start.saturating_sub(1)];
        let above_start = above.rfind('\n').map_or(0, |k| k + 1);
        words.extend(tokens_back(&above[above_start..]));
    }
    // From the last brace on: `person ann { base wheelchair {`.
    if let Some(brace) = words.iter().position(|w| w == "{" || w == "}") {
        words.truncate(brace);
    }
    words.reverse();
    words
}

/// The header's words from the last that starts a statement in `outer`
/// on: `mannequin m base wheelchair` in a person is `base wheelchair`.
fn statement_of<'h>(outer: &Block, header: &'h [String], registry: &Registry) -> &'h [String] {
    let starts = |word: &str| match outer {
        Block::Top => TOP.contains(&word) || registry.names(PluginKind::Task).contains(&word),
        Block::Person => PERSON.contains(&word),
        Block::Population => POPULATION.contains(&word),
        Block::Options(params) => params.iter().any(|p| p.name == word),
        _ => false,
    };
    let from = header.iter().rposition(|w| starts(w)).unwrap_or(0);
    &header[from..]
}

fn inner_block(
    outer: &Block,
    header: &[String],
    registry: &Registry,
    outline: Option<&Outline>,
) -> Block {
    let header = statement_of(outer, header, registry);
    let first = header.first().map(String::as_str).unwrap_or("");
    let plugin_after = |k: usize| header.get(k).cloned().unwrap_or_default();
    let options_of = |kind: PluginKind, name: &str| {
        registry
            .params(kind, name)
            .map_or(Block::Unknown, Block::Options)
    };
    match (outer, first) {
        (Block::Top, "room") => Block::Room,
        (Block::Top, "mannequin") => Block::Mannequin,
        (Block::Top, "profile") => Block::Overrides,
        (Block::Top, "person") => Block::Person,
        (Block::Top, "population") => Block::Population,
        (Block::Top, "limits") => Block::Options(crate::check::limits_params()),
        (_, "vision") => Block::Options(crate::scene::Vision::params()),
        (Block::Top, "standard") => options_of(PluginKind::Standard, &plugin_after(1)),
        (Block::Top, "base") => options_of(PluginKind::Base, &plugin_after(3)),
        (Block::Person | Block::Population, "mannequin") => Block::Overrides,
        (Block::Person | Block::Population, "base") => {
            options_of(PluginKind::Base, &base_plugin(&plugin_after(1), outline))
        }
        (Block::Top, kind) => {
            let task = match header.iter().position(|w| w == "and") {
                Some(k) => format!("{kind}_and_{}", plugin_after(k + 1)),
                None => kind.to_string(),
            };
            options_of(PluginKind::Task, &task)
        }
        (Block::Options(params), option) => {
            match params.iter().find(|p| p.name == option).map(|p| p.kind) {
                Some(ParamKind::Plugin(kind)) => options_of(kind, &plugin_after(1)),
                _ => Block::Unknown,
            }
        }
        _ => Block::Unknown,
    }
}

/// The plugin a person's `base NAME` is: a preset's plugin (in the
/// outline, or the standard library's text), else NAME.
fn base_plugin(name: &str, outline: Option<&Outline>) -> String {
    if let Some(plugin) = outline.and_then(|o| o.preset_plugin(name)) {
        return plugin;
    }
    let std_line = crate::std_texts::MODULES
        .iter()
        .flat_map(|(_, text)| text.lines())
        .find(|l| crate::std_texts::declares(l, "base", name));
    match std_line.and_then(|l| l.split_once('=')) {
        Some((_, rest)) => rest.split_whitespace().next().unwrap_or(name).to_string(),
        None => name.to_string(),
    }
}

/// What the candidates are drawn from.
struct Found<'a> {
    outline: Option<&'a Outline>,
    registry: &'a Registry,
    used: Vec<String>,
}

/// The keywords that start a statement in each block.
const TOP: [&str; 13] = [
    "units",
    "use",
    "let",
    "room",
    "mannequin",
    "profile",
    "base",
    "vision",
    "person",
    "population",
    "standard",
    "limits",
    "expect",
];
const ROOM: [&str; 6] = ["size", "box", "mesh", "target", "surface", "door"];
const MANNEQUIN: [&str; 15] = [
    "joint",
    "effector",
    "sphere",
    "legs",
    "couple",
    "rhythm",
    "require",
    "seated",
    "standing",
    "limits",
    "anatomical",
    "neutral",
    "weight",
    "radius",
    "link",
];
const OVERRIDES: [&str; 4] = ["limits", "neutral", "weight", "profile"];
const PERSON: [&str; 3] = ["mannequin", "base", "vision"];
const POPULATION: [&str; 8] = [
    "size",
    "seed",
    "women",
    "draw",
    "profile",
    "mannequin",
    "base",
    "vision",
];

impl Found<'_> {
    /// The candidates after `tokens` (last first) in `block`.
    fn after(&self, tokens: &[String], block: &Block, line_start: bool) -> Vec<Completion> {
        let last = tokens.first().map(String::as_str).unwrap_or("");
        let second = tokens.get(1).map(String::as_str).unwrap_or("");
        let head = list_head(tokens);
        match (block, last) {
            (_, "by") => self.names(&[SymbolKind::Person, SymbolKind::Population]),
            (_, ",") if head == Some("by") => {
                self.names(&[SymbolKind::Person, SymbolKind::Population])
            }
            (_, "after" | "couple" | "with") => self.names(&[SymbolKind::Joint]),
            (_, ",") if head == Some("couple") => self.names(&[SymbolKind::Joint]),
            (Block::Overrides, "limits" | "limit" | "neutral" | "weight") => {
                self.names(&[SymbolKind::Joint])
            }
            (Block::Overrides | Block::Population, "profile") => self.names(&[SymbolKind::Profile]),
            (Block::Person | Block::Population, "mannequin") => {
                self.names(&[SymbolKind::Mannequin])
            }
            (Block::Person | Block::Population, "base") => {
                let mut out = self.names(&[SymbolKind::BasePreset]);
                out.extend(self.plugins(PluginKind::Base));
                out
            }
            (Block::Person | Block::Population, "vision") => {
                self.names(&[SymbolKind::VisionPreset])
            }
            (Block::Top, "=") if tokens.get(2).is_some_and(|t| t == "population") => {
                self.names(&[SymbolKind::Population])
            }
            (Block::Top, "=") if tokens.get(2).is_some_and(|t| t == "base") => {
                self.plugins(PluginKind::Base)
            }
            (Block::Top, "use") => ["std::", "\""]
                .map(|v| value(v, "a module, or a file in quotes"))
                .to_vec(),
            (Block::Top, "units") => units(usize::MAX)
                .into_iter()
                .map(|c| Completion {
                    replaces_from: None,
                    ..c
                })
                .collect(),
            (Block::Top, "standard" | "meets") => self.plugins(PluginKind::Standard),
            (Block::Top, "in") if tokens.get(2).is_some_and(|t| t == "standard") => {
                self.names(&[SymbolKind::Room])
            }
            (Block::Top, "expect") => {
                let mut out =
                    self.names(&[SymbolKind::Person, SymbolKind::Population, SymbolKind::Room]);
                out.extend(["share", "advise"].map(keyword));
                out
            }
            (Block::Top, "not") if tokens.get(2).is_some_and(|t| t == "expect") => {
                ["reaches", "sees", "covers"].map(keyword).to_vec()
            }
            (Block::Top, _) if second == "expect" && !line_start => {
                ["reaches", "sees", "covers", "not", "meets"]
                    .map(keyword)
                    .to_vec()
            }
            (Block::Top, "reaches" | "sees" | "advise") => self.subjects(SubjectKind::Target),
            (Block::Top, "covers") => self.subjects(SubjectKind::Surface),
            (Block::Top, "(") if second == "share" => self.names(&[SymbolKind::Population]),
            (Block::Top, "and") => self.plugins(PluginKind::Task),
            (Block::Top, word) if self.task(word).is_some() && !line_start => {
                self.subjects(self.task(word).unwrap_or(SubjectKind::Target))
            }
            (Block::Top, ",") if head.is_some_and(|h| self.task(h).is_some()) => self.subjects(
                head.and_then(|h| self.task(h))
                    .unwrap_or(SubjectKind::Target),
            ),
            // After a task's subjects: `by`, or `and` another task.
            (Block::Top, _) if !line_start && self.after_subjects(tokens) => {
                ["by", "and"].map(keyword).to_vec()
            }
            (Block::Options(params), _) if line_start => params.iter().map(option).collect(),
            (Block::Options(params), word) => self.in_options(params, word, second),
            (block, _) if line_start || starts_statement(last) => self.statement_start(block),
            _ => Vec::new(),
        }
    }

    /// Whether `tokens` (last first) end a task's subjects: `reach a`,
    /// `map t.top, b`.
    fn after_subjects(&self, tokens: &[String]) -> bool {
        let Some(first) = tokens.first() else {
            return false;
        };
        if !first.starts_with(|c: char| c.is_ascii_alphabetic() || c == '_') {
            return false;
        }
        match tokens.get(1).map(String::as_str) {
            Some(",") => list_head(&tokens[1..]).is_some_and(|h| self.task(h).is_some()),
            Some(word) => self.task(word).is_some(),
            None => false,
        }
    }

    /// The kind of subject task `word` takes, where it is a task.
    fn task(&self, word: &str) -> Option<SubjectKind> {
        self.registry.task(word).map(|t| t.subject())
    }

    /// The faces of the box before a `.`, where `before` ends in one's
    /// name.
    fn faces(&self, before: &str) -> Vec<Completion> {
        let name_start = before
            .rfind(|c: char| !(c.is_ascii_alphanumeric() || c == '_'))
            .map_or(0, |k| k + 1);
        let name = &before[name_start..];
        let is_box = self.outline.is_some_and(|o| {
            o.names_of(&[SymbolKind::Box, SymbolKind::Mesh])
                .iter()
                .any(|s| s.name == name)
        });
        if !is_box {
            return Vec::new();
        }
        FACES
            .iter()
            .map(|f| value(f, "a face of the box"))
            .collect()
    }

    fn statement_start(&self, block: &Block) -> Vec<Completion> {
        match block {
            Block::Top => {
                let mut out: Vec<Completion> = TOP.iter().map(|k| keyword(k)).collect();
                out.extend(self.plugins(PluginKind::Task));
                out
            }
            Block::Room => ROOM.iter().map(|k| keyword(k)).collect(),
            Block::Mannequin => MANNEQUIN.iter().map(|k| keyword(k)).collect(),
            Block::Overrides => OVERRIDES.iter().map(|k| keyword(k)).collect(),
            Block::Person => PERSON.iter().map(|k| keyword(k)).collect(),
            Block::Population => POPULATION.iter().map(|k| keyword(k)).collect(),
            Block::Options(params) => params.iter().map(option).collect(),
            Block::Unknown => Vec::new(),
        }
    }

    /// In an option block: the options at the start of one, or the values
    /// the option just named takes.
    fn in_options(&self, params: &[ParamSpec], last: &str, second: &str) -> Vec<Completion> {
        if let Some(param) = params.iter().find(|p| p.name == last) {
            return self.values(param);
        }
        // `carries [a, ` : more names.
        if last == "[" || (last == "," && second != "{") {
            return self.names(&[SymbolKind::Box, SymbolKind::Mesh, SymbolKind::Target]);
        }
        if starts_statement(last)
            || last
                .chars()
                .all(|c| c.is_ascii_alphanumeric() || c == '_' || c == '.' || c == ')' || c == '"')
        {
            return params.iter().map(option).collect();
        }
        Vec::new()
    }

    /// The values option `param` takes: `true` or `false`, a plugin, the
    /// words its doc names in backquotes (`either`, `right`, `left`), else
    /// for a name an effector (`effector`) or an element of the room.
    fn values(&self, param: &ParamSpec) -> Vec<Completion> {
        match param.kind {
            ParamKind::Bool => ["true", "false"].map(|v| value(v, "bool")).to_vec(),
            ParamKind::Plugin(k) => self.plugins(k),
            ParamKind::Name => match name_choices(param.name) {
                Some(words) => words.iter().map(|w| value(w, param.name)).collect(),
                None if param.name.contains("effector") || param.name == "eyes" => {
                    self.names(&[SymbolKind::Effector])
                }
                None => self.names(&[SymbolKind::Box, SymbolKind::Mesh]),
            },
            ParamKind::Names => {
                self.names(&[SymbolKind::Box, SymbolKind::Mesh, SymbolKind::Target])
            }
            _ => Vec::new(),
        }
    }

    /// What a task of this kind may be about: targets, or surfaces and
    /// boxes (whose faces follow a `.`).
    fn subjects(&self, kind: SubjectKind) -> Vec<Completion> {
        match kind {
            SubjectKind::Target => self.names(&[SymbolKind::Target]),
            SubjectKind::Surface => {
                self.names(&[SymbolKind::Surface, SymbolKind::Box, SymbolKind::Mesh])
            }
        }
    }

    /// The names of `kinds` the files declare, then those the standard
    /// library declares (with the `use` each needs, where it is not used).
    fn names(&self, kinds: &[SymbolKind]) -> Vec<Completion> {
        let mut out: Vec<Completion> = self
            .outline
            .map(|o| o.names_of(kinds))
            .unwrap_or_default()
            .into_iter()
            .map(|s| Completion {
                label: s.name.clone(),
                kind: CompletionKind::Name(s.kind),
                detail: match &s.container {
                    Some(c) => format!("{} in {c}", s.kind.word()),
                    None => s.kind.word().to_string(),
                },
                doc: None,
                needs_use: None,
                replaces_from: None,
            })
            .collect();
        for &kind in kinds {
            for (module, name) in std_declared(kind) {
                if out.iter().any(|c| c.label == name) {
                    continue;
                }
                let used = self.used.iter().any(|u| u == module);
                out.push(Completion {
                    label: name,
                    kind: CompletionKind::Name(kind),
                    detail: format!("{} in std::{module}", kind.word()),
                    doc: None,
                    needs_use: (!used).then_some(module),
                    replaces_from: None,
                });
            }
        }
        out
    }

    fn plugins(&self, kind: PluginKind) -> Vec<Completion> {
        self.registry
            .of_kind(kind)
            .into_iter()
            .map(|p| Completion {
                label: p.name().to_string(),
                kind: CompletionKind::Plugin,
                detail: format!("{} plugin", kind.noun()),
                doc: Some(p.doc().to_string()),
                needs_use: None,
                replaces_from: None,
            })
            .collect()
    }
}

/// The words an option that takes a name of the plugin's own takes
/// (the built-in plugins' `hand`, `along`, `across`, `approach`); none
/// where its name is of the scenario's (an effector, a box).
fn name_choices(option: &str) -> Option<&'static [&'static str]> {
    match option {
        "hand" => Some(&["either", "right", "left"]),
        "along" | "across" => Some(&["x", "y", "z"]),
        "approach" => Some(&["any", "forward", "side"]),
        _ => None,
    }
}

/// The word a list ends back at (`reach a, b, ` -> `reach`; `by ann, `
/// -> `by`): the token before its first item, where `tokens` (last first)
/// start with a `,`.
fn list_head(tokens: &[String]) -> Option<&str> {
    let mut k = 0;
    while tokens.get(k).is_some_and(|t| t == ",") {
        let item = tokens.get(k + 1)?;
        if !item.starts_with(|c: char| c.is_ascii_alphabetic() || c == '_') {
            return None;
        }
        k += 2;
    }
    (k > 0).then(|| tokens.get(k).map(String::as_str)).flatten()
}

/// Whether a statement or an option may start after this token.
fn starts_statement(last: &str) -> bool {
    matches!(last, "" | "{" | "}" | ")" | ",") || last.ends_with(|c: char| c.is_ascii_digit())
}

/// What the standard library declares as `kind`, with its module.
fn std_declared(kind: SymbolKind) -> Vec<(&'static str, String)> {
    let keyword = match kind {
        SymbolKind::Mannequin => "mannequin",
        SymbolKind::Profile => "profile",
        SymbolKind::BasePreset => "base",
        SymbolKind::VisionPreset => "vision",
        SymbolKind::Population => "population",
        _ => return Vec::new(),
    };
    let mut out = Vec::new();
    for (module, text) in crate::std_texts::MODULES {
        for line in text.lines() {
            let Some(rest) = line.strip_prefix(keyword).and_then(|r| r.strip_prefix(' ')) else {
                continue;
            };
            let name: String = rest
                .trim_start()
                .chars()
                .take_while(|c| c.is_ascii_alphanumeric() || *c == '_')
                .collect();
            if !name.is_empty() && !out.iter().any(|(_, n)| *n == name) {
                out.push((*module, name));
            }
        }
    }
    out
}

fn keyword(word: &str) -> Completion {
    plain(word, CompletionKind::Keyword, "keyword")
}

fn value(word: &str, what: &str) -> Completion {
    plain(word, CompletionKind::Value, what)
}

/// An option, with its kind, default and doc.
fn option(param: &ParamSpec) -> Completion {
    let default = param.default_words();
    Completion {
        label: param.name.to_string(),
        kind: CompletionKind::Option,
        detail: format!("{}, {default}", param.kind.short()),
        doc: Some(param.doc.to_string()),
        needs_use: None,
        replaces_from: None,
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The labels offered where `|` is.
    fn offered(text: &str) -> Vec<String> {
        let offset = text.find('|').unwrap();
        let text = text.replace('|', "");
        let registry = Registry::builtin();
        let labels = completions(&text, offset, None, &registry);
        labels.into_iter().map(|c| c.label).collect()
    }

    /// Each place, and a label that must be offered there and one that
    /// must not.
    #[test]
    fn each_place_offers_what_may_be_typed_there() {
        let cases = [
            ("|", "room", "box"),
            ("room r {\n  |\n}", "target", "room"),
            ("room r { size 3|", "mm", "room"),
            ("room r { size 3m|", "mm", "deg"),
            ("use std::|", "people", "room"),
            ("use |", "std::", "room"),
            ("person p { |", "mannequin", "room"),
            ("person p { mannequin |", "woman_5th_seated", "room"),
            (
                "person p { mannequin m base wheelchair { seat_h| } }",
                "seat_height",
                "at",
            ),
            ("reach a by p { solver |", "incremental", "reach"),
            ("reach a by p { hand |", "left", "a"),
            ("advise a by p { along |", "z", "a"),
            ("use std::arm\n|", "room", "arm"),
            ("standard ada2010 in kitchen\n|", "expect", "kitchen"),
            ("reach a by p, q\n|", "person", "p"),
            ("reach a |", "by", "room"),
            ("expect ann |", "reaches", "room"),
            ("// café |", "", "room"),
            ("// a list, |", "", "room"),
            ("room r { box b at (0, |", "", "size"),
            ("reach a by p { effector |", "", "a"),
        ];
        for (place, wanted, unwanted) in cases {
            let found = offered(place);
            let offered_wanted = wanted.is_empty() || found.iter().any(|l| l == wanted);
            assert!(offered_wanted, "{place:?}: {wanted} in {found:?}");
            assert!(
                !found.iter().any(|l| l == unwanted),
                "{place:?}: {unwanted} in {found:?}"
            );
        }
    }

    /// Completion is asked as the user types, anywhere: at every place of
    /// a text with characters of several bytes, it answers.
    #[test]
    fn every_place_of_a_text_answers() {
        let text = "// café, 90°, 3 × 4 😀\nunits mm\nroom r { size 3000 x 3000 x 2500 target é at (1, 2, 3) }\nreach é, x by p { hand l }\n\"ü\" ";
        let registry = Registry::builtin();
        for offset in 0..=text.len() + 2 {
            completions(text, offset, None, &registry);
        }
    }
}
