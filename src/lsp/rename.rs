//! Rename: `prepareRename` (the name at the cursor, or why it is not
//! renamed) and `rename` (an edit of every place the name is written in
//! every open document's check, refused where the new name may not be or
//! where it would leave the document with an error it did not have).

use std::collections::HashMap;

use lsp_server::{ErrorCode, Request, Response};
use lsp_types::request::{PrepareRenameRequest, Request as _};
use lsp_types::{
    PrepareRenameResponse, RenameParams, TextDocumentPositionParams, TextEdit, Uri, WorkspaceEdit,
};
use reach::editor::RenameRefused;

use super::document::Renamed;
use super::position::LineIndex;
use super::{Server, ServerError};

/// Why a rename is not made: the library's reasons, and an error the
/// renamed text would have.
enum Refused {
    Name(RenameRefused),
    Breaks(String),
}

impl From<RenameRefused> for Refused {
    fn from(refused: RenameRefused) -> Self {
        Refused::Name(refused)
    }
}

impl Server<'_, '_> {
    /// Answer `prepareRename` or `rename`: the answer, or an error
    /// response that says why not.
    pub(super) fn answer_rename(&mut self, request: Request) -> Result<(), ServerError> {
        let id = request.id.clone();
        let answer = if request.method == PrepareRenameRequest::METHOD {
            let p: TextDocumentPositionParams = serde_json::from_value(request.params)?;
            self.renamed(&p, None)
                .map(|renamed| PrepareRenameResponse::RangeWithPlaceholder {
                    range: renamed.range,
                    placeholder: renamed.name,
                })
                .map(serde_json::to_value)
        } else {
            let p: RenameParams = serde_json::from_value(request.params)?;
            self.rename(&p).map(serde_json::to_value)
        };
        let response = match answer {
            Ok(value) => Response::new_ok(id, value?),
            Err(refused) => {
                let message = match refused {
                    Refused::Name(why) => why.to_string(),
                    Refused::Breaks(error) => {
                        format!("renamed, the file would have an error: {error}")
                    }
                };
                Response::new_err(id, ErrorCode::RequestFailed as i32, message)
            }
        };
        self.connection.sender.send(response.into())?;
        Ok(())
    }

    /// What a rename at `at` (to `new`, where given) changes: the places
    /// from every open document's check, each once.
    fn renamed(
        &self,
        at: &TextDocumentPositionParams,
        new: Option<&str>,
    ) -> Result<Renamed, Refused> {
        let uri = &at.text_document.uri;
        let asked = self
            .document(uri)
            .ok_or(Refused::Name(RenameRefused::NotAName))?;
        let here = (uri, asked.text.as_str(), at.position);
        let mut renamed =
            (asked.rename_places(here, new)?).ok_or(Refused::Name(RenameRefused::NotAName))?;
        for document in self.open.values().filter(|d| d.uri != *uri) {
            let more = match document.rename_places(here, new) {
                Ok(more) => more.map(|r| r.places).unwrap_or_default(),
                // Another document that does not parse: its uses are not
                // known (its check will say the name is unknown).
                Err(RenameRefused::DoesNotParse) => continue,
                Err(refused) => return Err(refused.into()),
            };
            for location in more {
                if !renamed.places.contains(&location) {
                    renamed.places.push(location);
                }
            }
        }
        Ok(renamed)
    }

    /// The edit of a rename; refused where the renamed text of the
    /// document asked would have more errors than it has (where every
    /// place is in it: a rename across files is checked name by name
    /// only).
    // `WorkspaceEdit::changes` is lsp-types' map by `Uri` (whose parsed
    // parts are cached inside it); the map is only filled and sent.
    #[allow(clippy::mutable_key_type)]
    fn rename(&self, p: &RenameParams) -> Result<WorkspaceEdit, Refused> {
        let at = &p.text_document_position;
        let renamed = self.renamed(at, Some(&p.new_name))?;
        let mut changes: HashMap<Uri, Vec<TextEdit>> = HashMap::new();
        for place in &renamed.places {
            let edit = TextEdit::new(place.range, p.new_name.clone());
            changes.entry(place.uri.clone()).or_default().push(edit);
        }
        let uri = &at.text_document.uri;
        if changes.keys().all(|u| u == uri) {
            if let Some(error) = self.new_error(uri, &changes[uri]) {
                return Err(Refused::Breaks(error));
            }
        }
        Ok(WorkspaceEdit {
            changes: Some(changes),
            ..WorkspaceEdit::default()
        })
    }

    /// The first error the document `uri` would have with `edits` made
    /// that it does not have now, if it would have more than now.
    fn new_error(&self, uri: &Uri, edits: &[TextEdit]) -> Option<String> {
        let document = self.document(uri)?;
        let index = LineIndex::new(&document.text);
        let mut spans: Vec<(usize, usize, &str)> = (edits.iter())
            .map(|e| {
                (
                    index.offset(e.range.start),
                    index.offset(e.range.end),
                    e.new_text.as_str(),
                )
            })
            .collect();
        spans.sort_by_key(|s| std::cmp::Reverse(s.0));
        let mut text = document.text.clone();
        for (start, end, new) in spans {
            text.replace_range(start..end, new);
        }
        let errors = |checked: &Result<reach::Scenario, reach::Diagnostics>| match checked {
            Ok(_) => Vec::new(),
            Err(d) => d.errors.iter().map(|e| e.to_string()).collect(),
        };
        let before = errors(&document.analysis.checked);
        let after = errors(&self.analyse(uri, &text).checked);
        if after.len() <= before.len() {
            return None;
        }
        let first_new = after.iter().find(|e| !before.contains(e));
        Some(first_new.unwrap_or(&after[0]).clone())
    }
}
