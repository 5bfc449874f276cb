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
    /// The byte offset at which each line starts: 0, and each offset after
    /// a line feed.
    pub fn line_starts(&self) -> &[usize] {
        self.line_starts.get_or_init(|| {
            let after_feeds = self.text.match_indices('\n').map(|(i, _)| i + 1);
            std::iter::once(0).chain(after_feeds).collect()
        })
    }
}

/// All files loaded for one evaluation, indexed by [`FileId`].
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
