//! What the server has told the editor: for each file, the diagnostics
//! each open document's last check found in it. A file that two open
//! documents use shows both's, once; a file no check finds anything in any
//! more is told so (an empty list), once.

use std::collections::BTreeMap;

use lsp_types::Diagnostic;

/// By file, then by the document whose check found them (each by its URI
/// as text).
#[derive(Default)]
pub struct Published(BTreeMap<String, BTreeMap<String, Vec<Diagnostic>>>);

impl Published {
    /// `root`'s check now finds `found`; the files whose diagnostics
    /// that changes.
    pub fn set(&mut self, root: &str, found: BTreeMap<String, Vec<Diagnostic>>) -> Vec<String> {
        let mut changed = Vec::new();
        for (file, by_root) in &mut self.0 {
            let was = by_root.get(root);
            let now = found.get(file);
            if was != now && was.is_some() {
                changed.push(file.clone());
            }
            by_root.remove(root);
        }
        for (file, diagnostics) in found {
            let entry = self.0.entry(file.clone()).or_default();
            if !changed.contains(&file) {
                changed.push(file.clone());
            }
            entry.insert(root.to_string(), diagnostics);
        }
        self.0.retain(|_, by_root| !by_root.is_empty());
        // Every file the check of an open document is about is told
        // again, even unchanged: the editor shows a document's own list
        // as soon as it is opened.
        if !changed.iter().any(|c| c == root) {
            changed.push(root.to_string());
        }
        changed.sort();
        changed
    }

    /// Every diagnostic now in `file`, each once.
    pub fn of(&self, file: &str) -> Vec<Diagnostic> {
        let mut out: Vec<Diagnostic> = Vec::new();
        for diagnostic in self
            .0
            .get(file)
            .into_iter()
            .flat_map(|m| m.values().flatten())
        {
            if !out.contains(diagnostic) {
                out.push(diagnostic.clone());
            }
        }
        out
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn uri(name: &str) -> String {
        format!("file:///{name}")
    }

    fn error(message: &str) -> Diagnostic {
        Diagnostic {
            message: message.into(),
            ..Diagnostic::default()
        }
    }

    #[test]
    fn a_used_file_shows_what_each_document_found_once_and_is_cleared_when_none_does() {
        let (a, b, used) = (uri("a"), uri("b"), uri("used"));
        let mut p = Published::default();
        let found = |e: &str| BTreeMap::from([(used.clone(), vec![error(e)])]);
        assert_eq!(p.set(&a, found("x")), [a.clone(), used.clone()]);
        assert_eq!(p.set(&b, found("x")), [b.clone(), used.clone()]);
        assert_eq!(p.of(&used), [error("x")]);
        assert!(p.of(&a).is_empty());
        // a is mended: used still shows b's.
        assert_eq!(p.set(&a, BTreeMap::new()), [a.clone(), used.clone()]);
        assert_eq!(p.of(&used), [error("x")]);
        // b too: used is told it has none.
        assert_eq!(p.set(&b, BTreeMap::new()), [b.clone(), used.clone()]);
        assert!(p.of(&used).is_empty());
        assert_eq!(p.set(&b, BTreeMap::new()), [b]);
    }
}
