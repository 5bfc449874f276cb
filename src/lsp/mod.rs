//! `reach lsp` (in the binary, beside `reach watch`): a Language Server
//! Protocol server over standard input and output, built on `lsp-server`
//! (rust-analyzer's transport: plain threads and channels, as the rest of
//! the tool is; no async runtime). Each open `.reach` document is checked
//! as `reach check` checks its file (the same limits and file policy; its
//! `use`s read from disk, from its directory) on every change, with the
//! editor's text in place of the file's, and its diagnostics are published
//! to the files they are in (`diagnostics.rs`), positions in UTF-16
//! (`position.rs`). Completion, hover, definition and references come from
//! the library's `editor` module (`document.rs`); the standard library's
//! modules are served read-only (`files.rs`). After a save the scenario
//! runs in the background (`runner.rs`) and its answers come back as code
//! lenses and inlay hints, and its unmet `expect`s as diagnostics.

mod diagnostics;
mod document;
mod files;
mod position;
mod published;
mod rename;
mod runner;
mod uri;

use std::collections::BTreeMap;
use std::error::Error as StdError;
use std::str::FromStr;
use std::sync::Arc;

use crossbeam_channel::{select, unbounded, Sender};
use lsp_server::{Connection, ErrorCode, Message, Notification, Request, RequestId, Response};
use lsp_types::notification::{
    DidChangeTextDocument, DidCloseTextDocument, DidOpenTextDocument, DidSaveTextDocument,
    LogMessage, Notification as _, PublishDiagnostics,
};
use lsp_types::request::{
    CodeLensRequest, Completion, GotoDefinition, HoverRequest, InlayHintRequest,
    PrepareRenameRequest, References, Rename, Request as _,
};
use lsp_types::{
    CodeLensOptions, CodeLensParams, CompletionOptions, CompletionParams,
    DidChangeTextDocumentParams, DidCloseTextDocumentParams, DidOpenTextDocumentParams,
    DidSaveTextDocumentParams, GotoDefinitionParams, HoverParams, HoverProviderCapability,
    InitializeParams, InitializeResult, InlayHintParams, LogMessageParams, MessageType, OneOf,
    PublishDiagnosticsParams, ReferenceParams, RenameOptions, SaveOptions, ServerCapabilities,
    ServerInfo, TextDocumentSyncCapability, TextDocumentSyncKind, TextDocumentSyncOptions,
    TextDocumentSyncSaveOptions, Uri,
};

use document::Document;
use published::Published;
use reach::plugin::Registry;
use reach::{Input, Session};
use runner::{Answers, Asked, Running};

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
/// until `shutdown`, the scenarios run on a thread beside.
pub fn serve(
    connection: &Connection,
    session: Session<'_>,
    registry: &Registry,
) -> Result<(), ServerError> {
    let (id, params) = connection.initialize_start()?;
    let params: InitializeParams = serde_json::from_value(params).unwrap_or_default();
    let result = InitializeResult {
        capabilities: capabilities(&params),
        server_info: Some(ServerInfo {
            name: "reach".into(),
            version: Some(env!("CARGO_PKG_VERSION").into()),
        }),
    };
    connection.initialize_finish(id, serde_json::to_value(result)?)?;
    let (ask, asked) = unbounded::<Asked>();
    let (answer, answers) = unbounded::<Answers>();
    let running = Running::default();
    std::thread::scope(|scope| {
        let runs = Arc::clone(&running);
        scope.spawn(move || runner::serve_runs(&asked, &answer, &runs, (session, registry)));
        let mut server = Server {
            connection,
            session,
            registry,
            open: BTreeMap::new(),
            published: Published::default(),
            ask,
            running,
            refresh: refreshes(&params),
            next_request: 0,
        };
        let served = server.serve(&answers);
        // The run thread ends once nothing more can be asked of it, and
        // its run in flight is cancelled.
        drop(server);
        served
    })
}

/// Whether the client shows code lenses: where it does, the answers are
/// lenses only (not inlay hints too, which VS Code would show beside
/// them on the same line).
fn shows_lenses(params: &InitializeParams) -> bool {
    let document = params.capabilities.text_document.as_ref();
    document.is_some_and(|d| d.code_lens.is_some())
}

/// Which of the client's views of the answers it asks the server to
/// refresh once a run is done: code lenses, inlay hints.
fn refreshes(params: &InitializeParams) -> (bool, bool) {
    let workspace = params.capabilities.workspace.as_ref();
    let lenses = workspace
        .and_then(|w| w.code_lens.as_ref())
        .and_then(|c| c.refresh_support)
        .unwrap_or(false);
    let hints = workspace
        .and_then(|w| w.inlay_hint.as_ref())
        .and_then(|c| c.refresh_support)
        .unwrap_or(false);
    (lenses, hints)
}

/// What the server does for the client that sent `params`: the whole
/// text on every change (a scenario is checked whole anyway), and a word
/// on save (a file that others `use` changes on disk then; the scenario
/// runs); the answers as inlay hints only for a client that does not show
/// code lenses (Helix).
fn capabilities(params: &InitializeParams) -> ServerCapabilities {
    let lenses = shows_lenses(params);
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
        completion_provider: Some(CompletionOptions {
            trigger_characters: Some([" ", ":", "{", ",", "[", "."].map(String::from).to_vec()),
            ..CompletionOptions::default()
        }),
        hover_provider: Some(HoverProviderCapability::Simple(true)),
        definition_provider: Some(OneOf::Left(true)),
        references_provider: Some(OneOf::Left(true)),
        code_lens_provider: Some(CodeLensOptions {
            resolve_provider: Some(false),
        }),
        inlay_hint_provider: (!lenses).then_some(OneOf::Left(true)),
        rename_provider: Some(OneOf::Right(RenameOptions {
            prepare_provider: Some(true),
            work_done_progress_options: Default::default(),
        })),
        ..ServerCapabilities::default()
    }
}

struct Server<'c, 's> {
    connection: &'c Connection,
    session: Session<'s>,
    registry: &'s Registry,
    /// Each open document, by its URI.
    open: BTreeMap<String, Document>,
    published: Published,
    /// Runs asked of the run thread.
    ask: Sender<Asked>,
    running: Running,
    /// Whether to ask the client to refresh code lenses, inlay hints.
    refresh: (bool, bool),
    next_request: i32,
}

impl Server<'_, '_> {
    /// Each message of the editor's and each run's answers, until
    /// `shutdown`.
    fn serve(&mut self, answers: &crossbeam_channel::Receiver<Answers>) -> Result<(), ServerError> {
        let receiver = &self.connection.receiver;
        loop {
            select! {
                recv(receiver) -> message => {
                    let Ok(message) = message else { return Ok(()) };
                    match message {
                        Message::Request(request) if request.method == "shutdown" => {
                            return self.shut_down(request.id);
                        }
                        Message::Request(request) => self.answer(request)?,
                        Message::Notification(n) if n.method == "exit" => {
                            return Err("`exit` before `shutdown`".into());
                        }
                        Message::Notification(n) => self.notified(n)?,
                        Message::Response(_) => {}
                    }
                }
                recv(answers) -> ran => {
                    if let Ok(ran) = ran {
                        self.answered(ran)?;
                    }
                }
            }
        }
    }

    /// `shutdown`: no run starts any more and the one in flight is
    /// cancelled; answered, then every message until `exit` is let be (a
    /// client's late answer to a refresh, a `didClose`), a request
    /// refused.
    fn shut_down(&self, id: RequestId) -> Result<(), ServerError> {
        runner::stop(&self.running);
        let response = Response::new_ok(id, serde_json::Value::Null);
        self.connection.sender.send(response.into())?;
        for message in &self.connection.receiver {
            match message {
                Message::Notification(n) if n.method == "exit" => return Ok(()),
                Message::Request(request) => {
                    let refused = Response::new_err(
                        request.id,
                        ErrorCode::InvalidRequest as i32,
                        "reach lsp is shutting down".into(),
                    );
                    self.connection.sender.send(refused.into())?;
                }
                _ => {}
            }
        }
        Ok(())
    }

    fn notified(&mut self, notification: Notification) -> Result<(), ServerError> {
        match notification.method.as_str() {
            DidOpenTextDocument::METHOD => {
                let p: DidOpenTextDocumentParams = serde_json::from_value(notification.params)?;
                let name = p.text_document.uri.as_str().to_string();
                let analysis = self.analyse(&p.text_document.uri, &p.text_document.text);
                let document = Document {
                    uri: p.text_document.uri,
                    text: p.text_document.text,
                    edit: 0,
                    last_outline: analysis.outline.clone(),
                    analysis,
                    answers: None,
                };
                self.open.insert(name.clone(), document);
                self.publish_check(&name)?;
                self.ask_run(&name);
                Ok(())
            }
            DidChangeTextDocument::METHOD => {
                let p: DidChangeTextDocumentParams = serde_json::from_value(notification.params)?;
                let name = p.text_document.uri.as_str().to_string();
                // Full sync: the last change is the whole text.
                if let Some(change) = p.content_changes.into_iter().last() {
                    if let Some(document) = self.open.get_mut(&name) {
                        document.text = change.text;
                        document.edit += 1;
                    }
                    self.cancel_run(&name);
                }
                self.check(&name)
            }
            DidSaveTextDocument::METHOD => {
                let p: DidSaveTextDocumentParams = serde_json::from_value(notification.params)?;
                // Another open document may use the file saved.
                let open: Vec<String> = self.open.keys().cloned().collect();
                open.iter().try_for_each(|uri| self.check(uri))?;
                self.ask_run(p.text_document.uri.as_str());
                Ok(())
            }
            DidCloseTextDocument::METHOD => {
                let p: DidCloseTextDocumentParams = serde_json::from_value(notification.params)?;
                let uri = p.text_document.uri.as_str();
                self.open.remove(uri);
                self.cancel_run(uri);
                let changed = self.published.set(uri, BTreeMap::new());
                self.publish(changed)
            }
            _ => Ok(()),
        }
    }

    /// A request: answered, or refused where the server does not know it.
    fn answer(&mut self, request: Request) -> Result<(), ServerError> {
        let id = request.id.clone();
        let result = match request.method.as_str() {
            PrepareRenameRequest::METHOD | Rename::METHOD => return self.answer_rename(request),
            Completion::METHOD => {
                let p: CompletionParams = serde_json::from_value(request.params)?;
                let at = p.text_document_position;
                let items = (self.document(&at.text_document.uri))
                    .map(|d| d.completion(at.position, self.registry))
                    .unwrap_or_default();
                serde_json::to_value(items)?
            }
            HoverRequest::METHOD => {
                let p: HoverParams = serde_json::from_value(request.params)?;
                let at = p.text_document_position_params;
                let hover = (self.document(&at.text_document.uri))
                    .and_then(|d| d.hover(at.position, self.registry));
                serde_json::to_value(hover)?
            }
            GotoDefinition::METHOD => {
                let p: GotoDefinitionParams = serde_json::from_value(request.params)?;
                let at = p.text_document_position_params;
                let found = (self.document(&at.text_document.uri))
                    .map(|d| d.definition(at.position))
                    .unwrap_or_default();
                serde_json::to_value(found)?
            }
            References::METHOD => {
                let p: ReferenceParams = serde_json::from_value(request.params)?;
                let at = p.text_document_position;
                let with = p.context.include_declaration;
                serde_json::to_value(self.references(&at.text_document.uri, at.position, with))?
            }
            CodeLensRequest::METHOD => {
                let p: CodeLensParams = serde_json::from_value(request.params)?;
                let lenses = (self.document(&p.text_document.uri))
                    .map(Document::code_lenses)
                    .unwrap_or_default();
                serde_json::to_value(lenses)?
            }
            InlayHintRequest::METHOD => {
                let p: InlayHintParams = serde_json::from_value(request.params)?;
                let hints = (self.document(&p.text_document.uri))
                    .map(Document::inlay_hints)
                    .unwrap_or_default();
                serde_json::to_value(hints)?
            }
            _ => return self.refuse(request),
        };
        let response = Response::new_ok(id, result);
        self.connection.sender.send(response.into())?;
        Ok(())
    }

    /// The uses of the name at `position` in `uri`, as every open
    /// document's check sees them, each once.
    fn references(
        &self,
        uri: &Uri,
        position: lsp_types::Position,
        with: bool,
    ) -> Vec<lsp_types::Location> {
        let Some(asked) = self.document(uri) else {
            return Vec::new();
        };
        let mut found: Vec<lsp_types::Location> = Vec::new();
        for document in self.open.values() {
            for location in document.references((uri, &asked.text, position), with) {
                if !found.contains(&location) {
                    found.push(location);
                }
            }
        }
        found.sort_by(|a, b| {
            (a.uri.as_str(), a.range.start.line, a.range.start.character).cmp(&(
                b.uri.as_str(),
                b.range.start.line,
                b.range.start.character,
            ))
        });
        found
    }

    fn document(&self, uri: &Uri) -> Option<&Document> {
        self.open.get(uri.as_str())
    }

    /// The check of `text` as the document `uri` (its `use`s from its
    /// directory where it is a file).
    fn analyse(&self, uri: &Uri, text: &str) -> reach::editor::Analysis {
        let path = uri::path_of(uri);
        let name = uri.as_str();
        let input = match &path {
            Some(path) => Input::Edited { path, text },
            None => Input::Text { name, text },
        };
        self.session.analyse(input, self.registry)
    }

    /// Check the open document `name` again and publish what changed.
    fn check(&mut self, name: &str) -> Result<(), ServerError> {
        let Some(document) = self.open.get(name) else {
            return Ok(());
        };
        let analysis = self.analyse(&document.uri, &document.text);
        if let Some(document) = self.open.get_mut(name) {
            if analysis.outline.is_some() {
                document.last_outline = analysis.outline.clone();
            }
            document.analysis = analysis;
        }
        self.publish_check(name)
    }

    /// Publish the diagnostics of `name`'s last check, and its last run's
    /// unmet `expect`s (moved with their lines, marked stale after an
    /// edit).
    fn publish_check(&mut self, name: &str) -> Result<(), ServerError> {
        let Some(document) = self.open.get(name) else {
            return Ok(());
        };
        let mut found = match &document.analysis.checked {
            Ok(_) => BTreeMap::new(),
            Err(d) => diagnostics::by_file(&document.uri, &document.analysis.sources, d),
        };
        let unmet = document.unmet();
        if !unmet.is_empty() {
            found.entry(name.to_string()).or_default().extend(unmet);
        }
        let changed = self.published.set(name, found);
        self.publish(changed)
    }

    /// Ask the run thread to run `name`'s scenario, where its check
    /// passed (cancelling its run in flight).
    fn ask_run(&mut self, name: &str) {
        self.cancel_run(name);
        let Some(document) = self.open.get(name) else {
            return;
        };
        let Ok(scenario) = &document.analysis.checked else {
            return;
        };
        let _ = self.ask.send(Asked {
            uri: name.to_string(),
            edit: document.edit,
            path: uri::path_of(&document.uri),
            text: document.text.clone(),
            scenario: scenario.clone(),
        });
    }

    /// Tell the run thread that `name` is at its edit now: its run in
    /// flight, or asked and not started, is cancelled.
    fn cancel_run(&self, name: &str) {
        let edit = self.open.get(name).map_or(u64::MAX, |d| d.edit);
        runner::edited(&self.running, name, edit);
    }

    /// A run's answers: kept with their document, its unmet `expect`s
    /// published, the client asked to show them again.
    fn answered(&mut self, ran: Answers) -> Result<(), ServerError> {
        let name = ran.uri.clone();
        let Some(document) = self.open.get_mut(&name) else {
            return Ok(());
        };
        let message = ran_message(&ran);
        document.answers = Some(ran);
        let log = LogMessageParams {
            typ: MessageType::LOG,
            message,
        };
        let log = Notification::new(LogMessage::METHOD.into(), log);
        self.connection.sender.send(log.into())?;
        self.publish_check(&name)?;
        let (lenses, hints) = self.refresh;
        if lenses {
            self.request_of_client("workspace/codeLens/refresh")?;
        }
        if hints {
            self.request_of_client("workspace/inlayHint/refresh")?;
        }
        Ok(())
    }

    fn request_of_client(&mut self, method: &str) -> Result<(), ServerError> {
        self.next_request += 1;
        let id = RequestId::from(format!("reach-{}", self.next_request));
        let request = Request::new(id, method.to_string(), serde_json::Value::Null);
        self.connection.sender.send(request.into())?;
        Ok(())
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

/// The line a run's answers are logged with (`window/logMessage`): the
/// file, the run's time and its answers (`reach: ran kitchen.reach in 412
/// ms: 6 answers`), and where the bound stopped it, why.
fn ran_message(ran: &Answers) -> String {
    let file = ran.uri.rsplit('/').next().unwrap_or(&ran.uri);
    let answers = match ran.lenses.len() {
        1 => "1 answer".to_string(),
        n => format!("{n} answers"),
    };
    let mut message = format!("reach: ran {file} in {:.0} ms: {answers}", ran.run_ms);
    if let Some(why) = &ran.stopped {
        message.push_str(&format!(" (stopped: {why})"));
    }
    message
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_answers_are_inlay_hints_only_for_a_client_without_code_lenses() {
        let client = |shows: serde_json::Value| {
            let params = serde_json::json!({ "capabilities": shows });
            let params: InitializeParams = serde_json::from_value(params).unwrap();
            capabilities(&params).inlay_hint_provider.is_some()
        };
        // VS Code and Neovim show lenses; Helix shows hints only.
        assert!(!client(
            serde_json::json!({ "textDocument": { "codeLens": {} } })
        ));
        assert!(client(
            serde_json::json!({ "textDocument": { "inlayHint": {} } })
        ));
    }
}
