//! Loading a scenario: the root file and, depth first, every file it `use`s
//! (relative to the using file) or standard library module (`use std::x`).
//! Each file is read and parsed once; a `use` that leads back to a file still
//! being loaded is an import cycle.

use std::collections::HashMap;
use std::path::{Path, PathBuf};

use crate::error::{Diagnostics, Error, ErrorKind};
use crate::limits::Limits;
use crate::names::Suggestions;
use crate::read::{self, Allowed, FileKind, ReadError};
use crate::source::{Origin, Sources};
use crate::span::{FileId, Span};
use crate::std_modules;
use crate::syntax::ast::{File, Item, UseTarget};
use crate::syntax::parse_file_within;

/// One parsed file of the scenario.
#[derive(Debug)]
pub struct LoadedFile {
    pub id: FileId,
    pub ast: File,
}

/// The scenario's files, each after the files it uses; the root file last.
#[derive(Debug, Default)]
pub struct Loaded {
    pub sources: Sources,
    pub files: Vec<LoadedFile>,
}

/// Where the root of a scenario comes from.
pub enum Input<'a> {
    Path(&'a Path),
    Text {
        name: &'a str,
        text: &'a str,
    },
    /// A file on disk as an editor holds it, edits not yet saved: read
    /// as the file at `path` would be (its `use`s from its directory,
    /// under the same policy), with `text` in place of what is on disk.
    Edited {
        path: &'a Path,
        text: &'a str,
    },
}

/// Load the scenario. On failure the diagnostics come with the sources they
/// point into.
pub fn load(
    input: Input<'_>,
    limits: &Limits,
    also_allowed: &[PathBuf],
    suggestions: &Suggestions,
) -> (Sources, Result<Vec<LoadedFile>, Diagnostics>) {
    let mut loader = Loader {
        limits: *limits,
        suggestions,
        loaded: Loaded::default(),
        errors: Vec::new(),
        done: HashMap::new(),
        stack: Vec::new(),
    };
    let root = match input {
        Input::Path(path) | Input::Edited { path, .. } => Some(path),
        Input::Text { .. } => None,
    };
    loader.loaded.sources.allowed = Allowed::around(root, also_allowed);
    match input {
        Input::Path(path) => {
            let key = Key::Disk(canonical(path));
            loader.load_disk(path, key, None);
        }
        Input::Text { name, text } => {
            let id = loader.loaded.sources.add(
                name.to_string(),
                Origin::Memory,
                as_lines(text.to_string()),
            );
            loader.parse_and_follow(id, Key::Memory);
        }
        Input::Edited { path, text } => loader.load_edited(path, text),
    }
    let Loader { loaded, errors, .. } = loader;
    let result = if errors.is_empty() {
        Ok(loaded.files)
    } else {
        Err(Diagnostics { errors })
    };
    (loaded.sources, result)
}

#[derive(Clone, Debug, PartialEq, Eq, Hash)]
enum Key {
    Disk(PathBuf),
    Std(String),
    Memory,
}

struct Loader<'s> {
    /// The did-you-mean suggestions the check may still make.
    suggestions: &'s Suggestions,
    loaded: Loaded,
    errors: Vec<Error>,
    /// Files fully loaded, by identity.
    done: HashMap<Key, FileId>,
    /// Files being loaded, outermost first, with their display names.
    stack: Vec<(Key, String)>,
    limits: Limits,
}

/// Scenario text as the parser and diagnostics read it: without the
/// byte-order mark some editors save, and with a lone carriage return (old
/// Mac line endings) taken as a line feed, so that every line number agrees
/// (a line feed for a carriage return keeps every offset).
fn as_lines(mut text: String) -> String {
    if let Some(rest) = text.strip_prefix('\u{feff}') {
        text = rest.to_string();
    }
    if !text.contains('\r') {
        return text;
    }
    let mut bytes = text.into_bytes();
    for i in 0..bytes.len() {
        if bytes[i] == b'\r' && bytes.get(i + 1) != Some(&b'\n') {
            bytes[i] = b'\n';
        }
    }
    String::from_utf8(bytes).expect("a carriage return swapped for a line feed stays UTF-8")
}

fn canonical(path: &Path) -> PathBuf {
    path.canonicalize().unwrap_or_else(|_| path.to_path_buf())
}

impl Loader<'_> {
    fn load_disk(&mut self, path: &Path, key: Key, used_at: Option<Span>) {
        let shown = path.display().to_string();
        let limit = self.limits.file_bytes.min(self.limits.scenario_bytes);
        let read = match used_at {
            None => read::read_root(path, limit),
            Some(_) => read::read(
                path,
                FileKind::Scenario,
                &self.loaded.sources.allowed,
                limit,
            ),
        };
        let text = match read {
            Ok(bytes) => match String::from_utf8(bytes) {
                Ok(t) => t,
                Err(e) => return self.not_utf8(path, shown, e),
            },
            Err(ReadError::TooLarge { limit_bytes }) => {
                return self.too_large(&shown, limit_bytes, used_at);
            }
            Err(e) => {
                // Watched all the same: it may appear, or its directory.
                self.loaded.sources.add_data_files([path.to_path_buf()]);
                let reason = e.to_string();
                return self.fail(
                    ErrorKind::ReadFile {
                        path: shown,
                        reason,
                    },
                    used_at,
                );
            }
        };
        let id = self
            .loaded
            .sources
            .add(shown, Origin::Path(path.to_path_buf()), as_lines(text));
        self.parse_and_follow(id, key);
    }

    /// The root file at `path` with the editor's `text`, within the
    /// same bound on its size as the file on disk.
    fn load_edited(&mut self, path: &Path, text: &str) {
        let shown = path.display().to_string();
        let limit = self.limits.file_bytes.min(self.limits.scenario_bytes);
        if text.len() as u64 > limit {
            return self.too_large(&shown, limit, None);
        }
        let id = self.loaded.sources.add(
            shown,
            Origin::Path(path.to_path_buf()),
            as_lines(text.to_string()),
        );
        self.parse_and_follow(id, Key::Disk(canonical(path)));
    }

    /// Scenario file `shown` is larger than `limit_bytes`: the error
    /// names the option that raises the bound.
    fn too_large(&mut self, shown: &str, limit_bytes: u64, used_at: Option<Span>) {
        let flag = if self.limits.scenario_bytes < self.limits.file_bytes {
            "--max-scenario-bytes"
        } else {
            "--max-file-bytes"
        };
        let what = format!("`{shown}`");
        let limit = format!("{limit_bytes} bytes ({flag})");
        self.fail(ErrorKind::TooLarge { what, limit }, used_at);
    }

    /// Keep the file (invalid bytes replaced) so the diagnostic can show
    /// the line with the first invalid byte.
    fn not_utf8(&mut self, path: &Path, shown: String, e: std::string::FromUtf8Error) {
        let at = e.utf8_error().valid_up_to();
        let text = String::from_utf8_lossy(e.as_bytes()).into_owned();
        let replacement = text[at..].chars().next().map_or(0, char::len_utf8);
        let id = self
            .loaded
            .sources
            .add(shown.clone(), Origin::Path(path.to_path_buf()), text);
        let span = Span::new(id, at, at + replacement);
        self.errors
            .push(Error::new(ErrorKind::NotUtf8 { path: shown }, span));
    }

    fn fail(&mut self, kind: ErrorKind, at: Option<Span>) {
        self.errors.push(match at {
            Some(span) => Error::new(kind, span),
            None => Error::unplaced(kind),
        });
    }

    fn parse_and_follow(&mut self, id: FileId, key: Key) {
        let text = std::sync::Arc::clone(&self.loaded.sources.get(id).text);
        let ast = match parse_file_within(id, &text, &self.limits) {
            Ok(ast) => ast,
            Err(d) => {
                self.errors.extend(d.errors);
                return;
            }
        };
        let name = self.loaded.sources.get(id).name.clone();
        self.stack.push((key.clone(), name));
        for item in &ast.items {
            if let Item::Use(target) = item {
                self.follow(id, &target.value, target.span);
            }
        }
        self.stack.pop();
        self.done.insert(key, id);
        self.loaded.files.push(LoadedFile { id, ast });
    }

    fn follow(&mut self, from: FileId, target: &UseTarget, span: Span) {
        let (key, disk_path) = match target {
            UseTarget::Std(name) => (Key::Std(name.clone()), None),
            UseTarget::Path(rel) => {
                let path = self.relative_to(from, rel);
                (Key::Disk(canonical(&path)), Some(path))
            }
        };
        if self.done.contains_key(&key) {
            return;
        }
        if self.stack.len() >= self.limits.use_chain {
            let what = "the chain of files using each other".to_string();
            let limit = format!("{} files (--max-use-chain)", self.limits.use_chain);
            self.errors
                .push(Error::new(ErrorKind::TooLarge { what, limit }, span));
            return;
        }
        if let Some(pos) = self.stack.iter().position(|(k, _)| *k == key) {
            let mut chain: Vec<String> = self.stack[pos..].iter().map(|(_, n)| n.clone()).collect();
            chain.push(self.stack[pos].1.clone());
            let path = self.stack[pos].1.clone();
            self.errors
                .push(Error::new(ErrorKind::ImportCycle { path, chain }, span));
            return;
        }
        match (target, disk_path) {
            (_, Some(path)) => self.load_disk(&path, key, Some(span)),
            (UseTarget::Std(name), None) => self.load_std(name, key, span),
            _ => unreachable!("a path use always has a disk path"),
        }
    }

    fn load_std(&mut self, name: &str, key: Key, span: Span) {
        let Some(text) = std_modules::module(name) else {
            let names: Vec<&str> = std_modules::MODULES.iter().map(|(n, _)| *n).collect();
            self.errors.push(Error::new(
                ErrorKind::UnknownStdModule {
                    name: name.to_string(),
                    suggestion: self.suggestions.suggest(name, names.iter().copied()),
                    available: names.join(", "),
                },
                span,
            ));
            return;
        };
        let id = self.loaded.sources.add(
            format!("std::{name}"),
            Origin::Std(name.to_string()),
            text.to_string(),
        );
        self.parse_and_follow(id, key);
    }

    /// `rel` as seen from the directory of file `from`.
    fn relative_to(&self, from: FileId, rel: &str) -> PathBuf {
        let file = self.loaded.sources.get(from);
        let base = file.path().and_then(Path::parent).unwrap_or(Path::new(""));
        base.join(rel)
    }
}
