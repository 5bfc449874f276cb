//! Renaming a declared name: which declarations a place in the text
//! renames (the name declared there, or the declarations a use there is
//! to), every place the name is written (the declarations and their
//! uses), and whether a new name may take its place: a name the grammar
//! takes, not a keyword (`syntax::is_name`, `syntax::is_keyword`), and
//! no name declared already (of any kind, anywhere the check read, the
//! standard library included), so that the rename can neither fail to
//! parse nor make a use mean another declaration.

use std::fmt;

use super::outline::{Found, Outline, Symbol};
use crate::span::Span;
use crate::syntax::{is_keyword, is_name};

/// Why a name is not renamed.
#[derive(Clone, Debug, PartialEq)]
pub enum RenameRefused {
    /// The place is no declared name, nor a use of one.
    NotAName,
    /// The file does not parse, so its names are not known.
    DoesNotParse,
    /// The name is the standard library's, which is read-only.
    Std {
        name: String,
    },
    NotAnIdentifier {
        new: String,
    },
    Keyword {
        new: String,
    },
    /// A declaration of that name exists already.
    Taken {
        new: String,
        kind: &'static str,
        container: Option<String>,
    },
}

impl fmt::Display for RenameRefused {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            RenameRefused::NotAName => write!(f, "there is no declared name here to rename"),
            RenameRefused::DoesNotParse => {
                write!(f, "the file does not parse: mend it, then rename")
            }
            RenameRefused::Std { name } => write!(
                f,
                "`{name}` is the standard library's, which is read-only: to call it otherwise, declare one of your own in this file (a mannequin, for one: `mannequin mine = {name}`)"
            ),
            RenameRefused::NotAnIdentifier { new } => write!(
                f,
                "`{new}` is not a name: a name is a letter or `_`, then letters, digits and `_`"
            ),
            RenameRefused::Keyword { new } => {
                write!(f, "`{new}` is a keyword of the language, not a name")
            }
            RenameRefused::Taken {
                new,
                kind,
                container,
            } => {
                let within = (container.as_ref())
                    .map(|c| format!(" in `{c}`"))
                    .unwrap_or_default();
                write!(
                    f,
                    "`{new}` is declared already ({kind}{within}): choose a name not declared, so that no use comes to mean another declaration"
                )
            }
        }
    }
}

/// The declarations renamed from byte `offset` of the file of index
/// `file` (in the check's sources), and the span of the name there.
pub fn renamed_at(
    outline: &Outline,
    file: usize,
    offset: usize,
) -> Result<(Vec<&Symbol>, Span), RenameRefused> {
    match outline.at_index(file, offset) {
        Some(Found::Declaration(symbol)) => Ok((vec![symbol], symbol.span)),
        Some(Found::Use(reference, symbols)) if !symbols.is_empty() => {
            Ok((symbols, reference.span))
        }
        _ => Err(RenameRefused::NotAName),
    }
}

/// Every place the declarations `symbols` are written: each declaration's
/// name and each of its uses, in the order of the files, each once.
pub fn written_at(outline: &Outline, symbols: &[&Symbol]) -> Vec<Span> {
    let mut spans: Vec<Span> = Vec::new();
    for symbol in symbols {
        spans.push(symbol.span);
        spans.extend(outline.uses_of(symbol));
    }
    spans.sort_by_key(place);
    // (`Span`'s equality ignores where it is.)
    spans.dedup_by_key(|s| place(s));
    spans
}

/// Whether `new` may replace the name of `symbols` (all of one name).
pub fn may_rename_to(
    outline: &Outline,
    symbols: &[&Symbol],
    new: &str,
) -> Result<(), RenameRefused> {
    if is_keyword(new) {
        return Err(RenameRefused::Keyword { new: new.into() });
    }
    if !is_name(new) {
        return Err(RenameRefused::NotAnIdentifier { new: new.into() });
    }
    let renamed = |s: &Symbol| symbols.iter().any(|r| place(&r.span) == place(&s.span));
    let taken = (outline.symbols.iter()).find(|s| s.name == new && !renamed(s));
    if let Some(taken) = taken {
        return Err(RenameRefused::Taken {
            new: new.into(),
            kind: taken.kind.word(),
            container: taken.container.clone(),
        });
    }
    Ok(())
}

/// Where a span is: its file and bytes.
fn place(span: &Span) -> (u32, u32, u32) {
    (span.file.0, span.start, span.end)
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::plugin::Registry;
    use crate::span::FileId;
    use crate::syntax::parse_file;

    const TEXT: &str = "units mm
room kitchen {
  size 3000 x 3000 x 2500
  box counter at (0, 0, 0) size (600, 3000, 900)
  target cup at (300, 1500, 950)
}
mannequin arm {
  joint shoulder dh(theta 0, d 0, alpha 90deg, a 0) limits(-90deg, 90deg)
  effector hand at (200, 0, 0)
}
person ann { mannequin arm base none }
reach cup by ann
";

    fn outline() -> Outline {
        let file = parse_file(FileId(0), TEXT).expect("parses");
        Outline::of([(FileId(0), &file)], &Registry::builtin())
    }

    /// A byte `past` bytes into the first `needle`.
    fn at(needle: &str, past: usize) -> usize {
        TEXT.find(needle).unwrap() + past
    }

    #[test]
    fn a_declaration_and_a_use_rename_the_same_places() {
        let outline = outline();
        for offset in [at("person ann", 8), at("by ann", 4)] {
            let (symbols, span) = renamed_at(&outline, 0, offset).unwrap();
            assert_eq!(&TEXT[span.start as usize..span.end as usize], "ann");
            let places = written_at(&outline, &symbols);
            let texts: Vec<&str> = (places.iter())
                .map(|s| &TEXT[s.start as usize..s.end as usize])
                .collect();
            assert_eq!(texts, ["ann", "ann"]);
            assert_eq!(places[1].start as usize, TEXT.rfind("ann").unwrap());
        }
    }

    #[test]
    fn a_new_name_is_an_identifier_no_keyword_and_not_taken() {
        let outline = outline();
        let (ann, _) = renamed_at(&outline, 0, at("person ann", 7)).unwrap();
        assert_eq!(may_rename_to(&outline, &ann, "bea_2"), Ok(()));
        let refused = |new: &str| may_rename_to(&outline, &ann, new).unwrap_err();
        for bad in ["", "2ann", "an-n", "ann b", "é"] {
            assert!(
                matches!(refused(bad), RenameRefused::NotAnIdentifier { .. }),
                "{bad}"
            );
        }
        assert!(matches!(refused("room"), RenameRefused::Keyword { .. }));
        // Any declaration's name, of whatever kind.
        for taken in ["cup", "counter", "kitchen", "shoulder", "arm"] {
            assert!(
                matches!(refused(taken), RenameRefused::Taken { .. }),
                "{taken}"
            );
        }
        // Its own name is no conflict.
        assert_eq!(may_rename_to(&outline, &ann, "ann"), Ok(()));
    }

    #[test]
    fn a_keyword_or_an_unknown_name_is_not_renamed() {
        let outline = outline();
        let refused = |offset| renamed_at(&outline, 0, offset).unwrap_err();
        assert_eq!(refused(at("reach cup", 1)), RenameRefused::NotAName);
        assert_eq!(refused(at("units", 1)), RenameRefused::NotAName);
    }
}
