//! The checker's diagnostics as the protocol's: each error at its span in
//! its own file (a file the scenario `use`s gets its own), with the same
//! code, message, labels and help as `reach check` prints; an error in no
//! file (a root that cannot be read) at the start of the root.

use std::collections::BTreeMap;
use std::path::Path;

use lsp_types::{
    Diagnostic, DiagnosticRelatedInformation, DiagnosticSeverity, Location, NumberOrString, Range,
    Uri,
};

use super::position::LineIndex;
use super::uri::uri_of_path;
use reach::{Diagnostics, Error, Sources};

/// The diagnostics of one check of the document `root`, by the file each
/// is in (its URI as text: a map's key has no interior mutability, as
/// `Uri`'s parsed parts have).
pub fn by_file(
    root: &Uri,
    sources: &Sources,
    diagnostics: &Diagnostics,
) -> BTreeMap<String, Vec<Diagnostic>> {
    let mut out: BTreeMap<String, Vec<Diagnostic>> = BTreeMap::new();
    for error in &diagnostics.errors {
        let (uri, diagnostic) = one(root, sources, error);
        out.entry(uri.as_str().to_string())
            .or_default()
            .push(diagnostic);
    }
    out
}

/// `error` as a diagnostic, and the file it is in.
fn one(root: &Uri, sources: &Sources, error: &Error) -> (Uri, Diagnostic) {
    let placed = error.span().filter(|s| (s.file.0 as usize) < sources.len());
    let (uri, range, related) = match placed {
        Some(span) => {
            let file = sources.get(span.file);
            // The library's own modules and text given to the library
            // have no file of their own: shown at the root.
            let uri = file
                .path()
                .map_or_else(|| root.clone(), |path| uri_of(path, root));
            let index = LineIndex::new(&file.text);
            let range = index.range(span.start as usize, span.end as usize);
            let related = (error.placed_labels().into_iter())
                .filter(|(_, label)| !label.is_empty())
                .map(|(place, label)| DiagnosticRelatedInformation {
                    location: Location::new(
                        uri.clone(),
                        index.range(place.offset, place.offset + place.length),
                    ),
                    message: label,
                })
                .collect::<Vec<_>>();
            (uri, range, related)
        }
        None => (root.clone(), Range::default(), Vec::new()),
    };
    let mut message = error.to_string();
    if let Some(help) = miette::Diagnostic::help(error) {
        message.push_str(&format!("\nhelp: {help}"));
    }
    let diagnostic = Diagnostic {
        range,
        severity: Some(DiagnosticSeverity::ERROR),
        code: Some(NumberOrString::String(error.kind().code().to_string())),
        source: Some("reach".into()),
        message,
        related_information: (!related.is_empty()).then_some(related),
        ..Diagnostic::default()
    };
    (uri, diagnostic)
}

/// The URI of `path`, a file the check read (the root's where it has
/// none).
fn uri_of(path: &Path, root: &Uri) -> Uri {
    uri_of_path(path).unwrap_or_else(|| root.clone())
}
