//! `reach lsp` (in the binary, beside `reach watch`): a Language Server
//! Protocol server over standard input and
//! output, built on `lsp-server` (rust-analyzer's transport: plain
//! threads and channels, as the rest of the tool is; no async runtime).
//! Each open `.reach` document is checked as `reach check` checks its file
//! (the same limits and file policy; its `use`s read from disk, from its
//! directory) on every change, with the editor's text in place of the
//! file's, and its diagnostics are published to the files they are in
//! (`diagnostics.rs`), positions in UTF-16 (`position.rs`).

mod diagnostics;
mod position;
mod published;
mod uri;

use std::collections::BTreeMap;
use std::error::Error as StdError;
use std::str::FromStr;

use lsp_server::{Connection, ErrorCode, Message, Notification, Request, Response};
use lsp_types::notification::{
    DidChangeTextDocument, DidCloseTextDocument, DidOpenTextDocument, DidSaveTextDocument,
    Notification as _, PublishDiagnostics,
};
use lsp_types::{
    DidChangeTextDocumentParams, DidCloseTextDocumentParams, DidOpenTextDocumentParams,
    InitializeResult, PublishDiagnosticsParams, SaveOptions, ServerCapabilities, ServerInfo,
    TextDocumentSyncCapability, TextDocumentSyncKind, TextDocumentSyncOptions,
    TextDocumentSyncSaveOptions, Uri,
};

use published::Published;
use reach::plugin::Registry;
use reach::{Input, Session};

/// What went wrong with the connection (not with a document: those are
/// diagnostics).
pub type ServerError = Box<dyn StdError + Send + Sync>;

/// Serve over standard input and output until the client says `exit`.
pub fn serve_stdio(session: Session<'_>, registry: &Registry) -> Result<(), ServerError> {
    let (connection, io) = Connection::stdio();
    serve(&connection, session, registry)?;
    drop(connection);
    io.join()?;
    Ok(())
}

/// Serve over `connection`: the handshake, then each message in turn
/// until `shutdown`.
pub fn serve(
    connection: &Connection,
    session: Session<'_>,
    registry: &Registry,
) -> Result<(), ServerError> {
    let (id, _params) = connection.initialize_start()?;
    let result = InitializeResult {
        capabilities: capabilities(),
        server_info: Some(ServerInfo {
            name: "reach".into(),
            version: Some(env!("CARGO_PKG_VERSION").into()),
        }),
    };
    connection.initialize_finish(id, serde_json::to_value(result)?)?;
    let mut server = Server {
        connection,
        session,
        registry,
        open: BTreeMap::new(),
        published: Published::default(),
    };
    for message in &connection.receiver {
        match message {
            Message::Request(request) => {
                if connection.handle_shutdown(&request)? {
                    return Ok(());
                }
                server.refuse(request)?;
            }
            Message::Notification(notification) => server.notified(notification)?,
            Message::Response(_) => {}
        }
    }
    Ok(())
}

/// The whole text on every change (a scenario is checked whole anyway),
/// and a word on save (a file that others `use` changes on disk then).
fn capabilities() -> ServerCapabilities {
    ServerCapabilities {
        text_document_sync: Some(TextDocumentSyncCapability::Options(
            TextDocumentSyncOptions {
                open_close: Some(true),
                change: Some(TextDocumentSyncKind::FULL),
                save: Some(TextDocumentSyncSaveOptions::SaveOptions(SaveOptions {
                    include_text: Some(false),
                })),
                ..TextDocumentSyncOptions::default()
            },
        )),
        ..ServerCapabilities::default()
    }
}

struct Server<'c, 's> {
    connection: &'c Connection,
    session: Session<'s>,
    registry: &'s Registry,
    /// Each open document's text, as the editor holds it, by its URI.
    open: BTreeMap<String, String>,
    published: Published,
}

impl Server<'_, '_> {
    fn notified(&mut self, notification: Notification) -> Result<(), ServerError> {
        match notification.method.as_str() {
            DidOpenTextDocument::METHOD => {
                let p: DidOpenTextDocumentParams = serde_json::from_value(notification.params)?;
                let uri = p.text_document.uri.as_str().to_string();
                self.open.insert(uri.clone(), p.text_document.text);
                self.check(&uri)
            }
            DidChangeTextDocument::METHOD => {
                let p: DidChangeTextDocumentParams = serde_json::from_value(notification.params)?;
                // Full sync: the last change is the whole text.
                let uri = p.text_document.uri.as_str().to_string();
                if let Some(change) = p.content_changes.into_iter().last() {
                    self.open.insert(uri.clone(), change.text);
                }
                self.check(&uri)
            }
            DidSaveTextDocument::METHOD => {
                // Another open document may use the file saved.
                let open: Vec<String> = self.open.keys().cloned().collect();
                open.iter().try_for_each(|uri| self.check(uri))
            }
            DidCloseTextDocument::METHOD => {
                let p: DidCloseTextDocumentParams = serde_json::from_value(notification.params)?;
                let uri = p.text_document.uri.as_str();
                self.open.remove(uri);
                let changed = self.published.set(uri, BTreeMap::new());
                self.publish(changed)
            }
            _ => Ok(()),
        }
    }

    /// Check the open document `uri` and publish what changed.
    fn check(&mut self, name: &str) -> Result<(), ServerError> {
        let Some(text) = self.open.get(name) else {
            return Ok(());
        };
        let uri = Uri::from_str(name)?;
        let path = uri::path_of(&uri);
        let input = match &path {
            Some(path) => Input::Edited { path, text },
            None => Input::Text { name, text },
        };
        let (sources, checked) = self.session.check(input, self.registry);
        let found = match checked {
            Ok(_) => BTreeMap::new(),
            Err(d) => diagnostics::by_file(&uri, &sources, &d),
        };
        let changed = self.published.set(name, found);
        self.publish(changed)
    }

    /// Send each file's diagnostics, as every open document's checks now
    /// have them.
    fn publish(&self, files: Vec<String>) -> Result<(), ServerError> {
        for file in files {
            let params = PublishDiagnosticsParams {
                diagnostics: self.published.of(&file),
                uri: Uri::from_str(&file)?,
                version: None,
            };
            let notification = Notification::new(PublishDiagnostics::METHOD.into(), params);
            self.connection.sender.send(notification.into())?;
        }
        Ok(())
    }

    /// A request this server does not answer.
    fn refuse(&self, request: Request) -> Result<(), ServerError> {
        let response = Response::new_err(
            request.id,
            ErrorCode::MethodNotFound as i32,
            format!("reach lsp does not answer `{}`", request.method),
        );
        self.connection.sender.send(response.into())?;
        Ok(())
    }
}
