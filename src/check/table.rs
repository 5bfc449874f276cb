//! Named declarations of one kind, in declaration order, with duplicate
//! detection and did-you-mean lookups.

use std::collections::HashMap;

use crate::error::Error;
use crate::names::Suggestions;
use crate::span::{FileId, Name, Span};

pub struct Table<'a, T> {
    what: &'static str,
    entries: Vec<(String, Span, &'a T, FileId)>,
    /// Position in `entries` by name.
    index: HashMap<String, usize>,
}

impl<'a, T> Table<'a, T> {
    pub fn new(what: &'static str) -> Self {
        Table {
            what,
            entries: Vec::new(),
            index: HashMap::new(),
        }
    }

    /// Add a declaration; a second one of the same name is an error that
    /// points at both.
    pub fn insert(&mut self, name: &Name, decl: &'a T, file: FileId) -> Option<Error> {
        if let Some(&i) = self.index.get(&name.value) {
            return Some(Error::duplicate(self.what, name, self.entries[i].1));
        }
        self.index.insert(name.value.clone(), self.entries.len());
        self.entries
            .push((name.value.clone(), name.span, decl, file));
        None
    }

    pub fn get(&self, name: &str) -> Option<(&'a T, FileId)> {
        self.index
            .get(name)
            .map(|&i| (self.entries[i].2, self.entries[i].3))
    }

    /// Look up `name`, or the error for an unknown name with a suggestion.
    pub fn resolve(
        &self,
        name: &Name,
        suggestions: &Suggestions,
    ) -> Result<(&'a T, FileId), Error> {
        self.get(&name.value).ok_or_else(|| {
            Error::unknown(
                self.what,
                (&name.value, name.span),
                self.names(),
                suggestions,
            )
        })
    }

    pub fn names(&self) -> impl Iterator<Item = &str> {
        self.entries.iter().map(|(n, ..)| n.as_str())
    }

    pub fn iter(&self) -> impl Iterator<Item = (&str, &'a T, FileId)> + '_ {
        self.entries.iter().map(|(n, _, d, f)| (n.as_str(), *d, *f))
    }
}
