//! The files of one evaluation: the scenario file and everything it `use`s,
//! with the names under which diagnostics show them.

use std::path::PathBuf;
use std::sync::{Arc, OnceLock};

use crate::read::Allowed;
use crate::span::FileId;

/// Where a loaded file came from.
#[derive(Clone, Debug, PartialEq, Eq)]
pub enum Origin {
    /// A file on disk, by the path it was reached by.
    Path(PathBuf),
    /// A module of the embedded standard library, such as `std::arm`.
    Std(String),
    /// Text handed to the library directly (tests, fuzzing).
    Memory,
}

/// One loaded file.
#[derive(Debug)]
pub struct SourceFile {
    /// The name diagnostics show: the path as the user wrote it, or `std::x`.
    pub name: String,
    pub origin: Origin,
    pub text: Arc<String>,
    /// Where each line starts, found once when a diagnostic first needs it.
    line_starts: OnceLock<Vec<usize>>,
}

impl SourceFile {
    /// The file on disk it was read from (none for the standard
    /// library's modules and text handed to the library).
    pub fn path(&self) -> Option<&std::path::Path> {
        match &self.origin {
            Origin::Path(p) => Some(p),
            Origin::Std(_) | Origin::Memory => None,
        }
    }

    /// The standard library's module it is (`arm` for `std::arm`), if it
    /// is one.
    pub fn std_module(&self) -> Option<&str> {
        match &self.origin {
            Origin::Std(module) => Some(module),
            Origin::Path(_) | Origin::Memory => None,
        }
    }

    /// The byte offset at which each line starts: 0, and each offset after
    /// a line feed.
    pub fn line_starts(&self) -> &[usize] {
        self.line_starts.get_or_init(|| {
            let after_feeds = self.text.match_indices('\n').map(|(i, _)| i + 1);
            std::iter::once(0).chain(after_feeds).collect()
        })
    }

    /// The 1-based line and column (in characters) of the byte `offset`,
    /// as editors and CI annotations count them.
    pub fn line_column(&self, offset: usize) -> (usize, usize) {
        let offset = offset.min(self.text.len());
        let starts = self.line_starts();
        let line = starts.partition_point(|&s| s <= offset).max(1);
        let start = starts[line - 1];
        let before = (self.text.get(start..offset))
            .map(|t| t.chars().count())
            .unwrap_or(offset - start);
        (line, before + 1)
    }
}

/// Where a span of a file is, as editors count: 1-based lines and
/// columns (in characters), the end one past the span's last character.
#[derive(Clone, Debug, PartialEq, Eq, serde::Serialize)]
pub struct Place {
    pub file: String,
    pub line: usize,
    pub column: usize,
    pub end_line: usize,
    pub end_column: usize,
    /// The span in bytes from the start of the file.
    pub offset: usize,
    pub length: usize,
}

impl SourceFile {
    /// Where the bytes `start..end` are.
    pub fn place(&self, start: usize, end: usize) -> Place {
        let (line, column) = self.line_column(start);
        let (end_line, end_column) = self.line_column(end.max(start));
        Place {
            file: self.name.clone(),
            line,
            column,
            end_line,
            end_column,
            offset: start,
            length: end.saturating_sub(start),
        }
    }
}

/// All files loaded for one evaluation, indexed by `FileId`.
#[derive(Debug, Default)]
pub struct Sources {
    files: Vec<SourceFile>,
    /// Data files the scenario names (OBJ meshes, URDFs), read or not.
    data_files: Vec<PathBuf>,
    /// The directories its files may be read from.
    pub allowed: Allowed,
}

impl Sources {
    pub fn add(&mut self, name: String, origin: Origin, text: String) -> FileId {
        let id = FileId(self.files.len() as u32);
        self.files.push(SourceFile {
            name,
            origin,
            text: Arc::new(text),
            line_starts: OnceLock::new(),
        });
        id
    }

    pub fn get(&self, id: FileId) -> &SourceFile {
        &self.files[id.0 as usize]
    }

    pub fn len(&self) -> usize {
        self.files.len()
    }

    pub fn is_empty(&self) -> bool {
        self.files.is_empty()
    }

    /// Record data files the scenario names (meshes, URDFs).
    pub fn add_data_files(&mut self, paths: impl IntoIterator<Item = PathBuf>) {
        self.data_files.extend(paths);
    }

    /// The data files the scenario names (meshes, URDFs), as named.
    pub fn data_paths(&self) -> &[PathBuf] {
        &self.data_files
    }

    /// The files on disk this evaluation read or tried to read, scenario
    /// files and data files, as paths (watch mode watches them).
    pub fn disk_paths(&self) -> Vec<PathBuf> {
        self.files
            .iter()
            .filter_map(|f| match &f.origin {
                Origin::Path(p) => Some(p.clone()),
                _ => None,
            })
            .chain(self.data_files.iter().cloned())
            .collect()
    }

    pub fn iter(&self) -> impl Iterator<Item = (FileId, &SourceFile)> {
        self.files
            .iter()
            .enumerate()
            .map(|(i, f)| (FileId(i as u32), f))
    }
}
