//! Rename against every example: each name an example's own file
//! declares, renamed at every place `reach::editor` says it is written,
//! leaves a file that checks as cleanly as before (a use the outline
//! missed would be an unknown name; one it took wrongly, another error).

use std::path::Path;

use reach::editor::{may_rename_to, renamed_at, written_at};
use reach::plugin::Registry;
use reach::{Input, Session};

#[test]
fn every_name_an_example_declares_renames_to_a_file_that_still_checks() {
    let registry = Registry::builtin();
    let session = Session::default();
    let mut examples: Vec<_> = std::fs::read_dir("examples")
        .unwrap()
        .map(|e| e.unwrap().path())
        .filter(|p| p.extension().is_some_and(|e| e == "reach"))
        .collect();
    examples.sort();
    let mut renamed = 0;
    for path in &examples {
        renamed += renames_in(path, &session, &registry);
    }
    // Every example's names, not a handful.
    assert!(renamed > 100, "{renamed} names renamed");
}

/// Rename each name `path` declares (whose places are all in it), one at
/// a time, and check the text; how many were renamed.
fn renames_in(path: &Path, session: &Session<'_>, registry: &Registry) -> usize {
    let text = std::fs::read_to_string(path).unwrap();
    let analysis = session.analyse(Input::Path(path), registry);
    assert!(analysis.checked.is_ok(), "{} checks", path.display());
    let outline = analysis.outline.as_ref().expect("parses");
    let root = (analysis.sources.iter())
        .position(|(_, f)| {
            f.path()
                .is_some_and(|p| p.ends_with(path.file_name().unwrap()))
        })
        .expect("the example among its sources");
    let mut renamed = 0;
    for symbol in outline
        .symbols
        .iter()
        .filter(|s| s.span.file.0 as usize == root)
    {
        let (symbols, _) = renamed_at(outline, root, symbol.span.start as usize).unwrap();
        let places = written_at(outline, &symbols);
        if places.iter().any(|p| p.file.0 as usize != root) {
            continue;
        }
        let new = format!("{}_x", symbol.name);
        may_rename_to(outline, &symbols, &new).unwrap();
        let mut edited = text.clone();
        for place in places.iter().rev() {
            assert_eq!(
                &edited[place.start as usize..place.end as usize],
                symbol.name
            );
            edited.replace_range(place.start as usize..place.end as usize, &new);
        }
        let again = session.analyse(
            Input::Edited {
                path,
                text: &edited,
            },
            registry,
        );
        if let Err(d) = &again.checked {
            panic!(
                "{}: `{}` renamed `{new}` at {} places: {}",
                path.display(),
                symbol.name,
                places.len(),
                d.render(false)
            );
        }
        renamed += 1;
    }
    renamed
}
