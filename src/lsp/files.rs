//! Which file of a check a URI is, and the URI of each: a file on disk by
//! its path; text the editor holds without a path, by the document's URI;
//! a standard library module by a read-only copy of its text, written
//! once into the user's cache directory (`reach-std-VERSION/NAME.reach`),
//! so that go to definition opens it in any editor.

use std::path::{Path, PathBuf};

use lsp_types::Uri;

use super::uri::{path_of, uri_of_path};
use reach::Sources;

/// The directory the standard library's modules are served from.
fn std_dir() -> PathBuf {
    let cache = std::env::var_os("XDG_CACHE_HOME")
        .map(PathBuf::from)
        .or_else(|| std::env::var_os("HOME").map(|h| PathBuf::from(h).join(".cache")))
        .unwrap_or_else(std::env::temp_dir);
    cache.join(format!("reach-std-{}", env!("CARGO_PKG_VERSION")))
}

/// The read-only copy of module `name`, written where it is missing or
/// differs; none where it cannot be written.
fn served_module(name: &str, text: &str) -> Option<PathBuf> {
    let dir = std_dir();
    let path = dir.join(format!("{name}.reach"));
    if std::fs::read_to_string(&path).ok().as_deref() == Some(text) {
        return Some(path);
    }
    std::fs::create_dir_all(&dir).ok()?;
    if let Ok(meta) = std::fs::metadata(&path) {
        let mut writable = meta.permissions();
        #[allow(clippy::permissions_set_readonly_false)]
        writable.set_readonly(false);
        std::fs::set_permissions(&path, writable).ok()?;
    }
    std::fs::write(&path, text).ok()?;
    let mut read_only = std::fs::metadata(&path).ok()?.permissions();
    read_only.set_readonly(true);
    std::fs::set_permissions(&path, read_only).ok()?;
    Some(path)
}

/// The URI of file `index` of `sources`, a check of the document `root`.
pub fn uri_of_file(sources: &Sources, index: usize, root: &Uri) -> Option<Uri> {
    let (_, file) = sources.iter().nth(index)?;
    if let Some(path) = file.path() {
        return uri_of_path(path);
    }
    match file.std_module() {
        Some(module) => uri_of_path(&served_module(module, &file.text)?),
        None => Some(root.clone()),
    }
}

/// The index in `sources` (a check of the document `root`) of the file
/// `uri` names.
pub fn file_of_uri(sources: &Sources, uri: &Uri, root: &Uri) -> Option<usize> {
    let wanted = path_of(uri).map(|p| canonical(&p));
    sources
        .iter()
        .position(|(_, file)| match (file.path(), &wanted) {
            (Some(path), Some(wanted)) => canonical(path) == *wanted,
            (None, _) => match file.std_module() {
                Some(module) => wanted
                    .as_ref()
                    .is_some_and(|w| *w == canonical(&std_dir().join(format!("{module}.reach")))),
                None => uri == root,
            },
            _ => false,
        })
}

fn canonical(path: &Path) -> PathBuf {
    path.canonicalize().unwrap_or_else(|_| path.to_path_buf())
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_module_is_served_read_only_and_written_once() {
        let dir = std::env::temp_dir().join(format!("reach-served-{}", std::process::id()));
        std::env::set_var("XDG_CACHE_HOME", &dir);
        let path = served_module("people", "person p {}\n").unwrap();
        assert!(path.starts_with(&dir));
        assert!(std::fs::metadata(&path).unwrap().permissions().readonly());
        // Again, changed: rewritten, read-only again.
        let again = served_module("people", "person q {}\n").unwrap();
        assert_eq!(std::fs::read_to_string(&again).unwrap(), "person q {}\n");
        assert!(std::fs::metadata(&again).unwrap().permissions().readonly());
        let mut writable = std::fs::metadata(&again).unwrap().permissions();
        #[allow(clippy::permissions_set_readonly_false)]
        writable.set_readonly(false);
        std::fs::set_permissions(&again, writable).unwrap();
        std::fs::remove_dir_all(&dir).unwrap();
    }
}
