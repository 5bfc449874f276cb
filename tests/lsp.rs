//! `reach lsp` driven over standard input and output with real Language
//! Server Protocol messages, as an editor sends them: the handshake, a
//! document opened with an error (its diagnostic at its place, in UTF-16,
//! with the CLI's code and help), changed until mended (its diagnostics
//! cleared), a document whose `use`d file has the error (published to that
//! file), a request it does not answer, and shutdown.

use std::io::{BufRead, BufReader, Write};
use std::path::Path;
use std::process::{Child, ChildStdin, Command, Stdio};
use std::sync::mpsc::{channel, Receiver};
use std::time::Duration;

use serde_json::{json, Value};

/// A client speaking to one `reach lsp` process.
struct Client {
    child: Child,
    stdin: ChildStdin,
    from_server: Receiver<Value>,
}

impl Client {
    fn start() -> Client {
        let mut child = Command::new(env!("CARGO_BIN_EXE_reach"))
            .arg("lsp")
            .stdin(Stdio::piped())
            .stdout(Stdio::piped())
            .stderr(Stdio::null())
            .spawn()
            .expect("reach lsp starts");
        let stdin = child.stdin.take().unwrap();
        let stdout = child.stdout.take().unwrap();
        let (to_client, from_server) = channel();
        std::thread::spawn(move || {
            let mut reader = BufReader::new(stdout);
            while let Some(message) = read_message(&mut reader) {
                if to_client.send(message).is_err() {
                    break;
                }
            }
        });
        let mut client = Client {
            child,
            stdin,
            from_server,
        };
        client.request(
            1,
            "initialize",
            json!({ "capabilities": {}, "processId": null }),
        );
        let answer = client.response(1);
        assert_eq!(
            answer["result"]["capabilities"]["textDocumentSync"]["change"], 1,
            "full sync: {answer}"
        );
        client.notify("initialized", json!({}));
        client
    }

    fn send(&mut self, message: Value) {
        let body = message.to_string();
        write!(self.stdin, "Content-Length: {}\r\n\r\n{body}", body.len()).unwrap();
        self.stdin.flush().unwrap();
    }

    fn request(&mut self, id: i64, method: &str, params: Value) {
        self.send(json!({ "jsonrpc": "2.0", "id": id, "method": method, "params": params }));
    }

    fn notify(&mut self, method: &str, params: Value) {
        self.send(json!({ "jsonrpc": "2.0", "method": method, "params": params }));
    }

    /// The next message from the server (within a minute: a check of a
    /// small file takes milliseconds).
    fn next(&self) -> Value {
        self.from_server
            .recv_timeout(Duration::from_secs(60))
            .expect("the server answers")
    }

    fn response(&self, id: i64) -> Value {
        loop {
            let message = self.next();
            if message["id"] == id && message.get("method").is_none() {
                return message;
            }
        }
    }

    /// The diagnostics next published for `uri`.
    fn diagnostics_for(&self, uri: &str) -> Vec<Value> {
        loop {
            let message = self.next();
            if message["method"] == "textDocument/publishDiagnostics"
                && message["params"]["uri"] == uri
            {
                return message["params"]["diagnostics"].as_array().unwrap().clone();
            }
        }
    }

    fn open(&mut self, uri: &str, text: &str) {
        let document = json!({ "uri": uri, "languageId": "reach", "version": 1, "text": text });
        self.notify("textDocument/didOpen", json!({ "textDocument": document }));
    }

    fn change(&mut self, uri: &str, version: i64, text: &str) {
        self.notify(
            "textDocument/didChange",
            json!({
                "textDocument": { "uri": uri, "version": version },
                "contentChanges": [{ "text": text }],
            }),
        );
    }

    /// `shutdown`, then `exit`: the process ends with status 0.
    fn stop(mut self) {
        self.request(99, "shutdown", Value::Null);
        let answer = self.response(99);
        assert!(answer.get("error").is_none(), "{answer}");
        self.notify("exit", Value::Null);
        let status = self.child.wait().unwrap();
        assert!(status.success(), "{status}");
    }
}

/// One framed message, or none at the end of the stream.
fn read_message(reader: &mut impl BufRead) -> Option<Value> {
    let mut length = None;
    loop {
        let mut line = String::new();
        if reader.read_line(&mut line).ok()? == 0 {
            return None;
        }
        let line = line.trim_end();
        if line.is_empty() {
            break;
        }
        if let Some(n) = line.strip_prefix("Content-Length: ") {
            length = n.parse::<usize>().ok();
        }
    }
    let mut body = vec![0; length?];
    reader.read_exact(&mut body).ok()?;
    serde_json::from_slice(&body).ok()
}

fn file_uri(path: &Path) -> String {
    url::Url::from_file_path(path).unwrap().to_string()
}

const KITCHEN: &str = "units mm
room kitchen {
  size 3000 x 3000 x 2500
  target cup at (400, 500, 900)
}
use std::body
person ann { mannequin upper_body base fixed { at (800, 250, 0) } }
reach cupp by ann
";

#[test]
fn a_documents_error_is_shown_where_it_is_and_cleared_once_mended() {
    let dir = tempfile::tempdir().unwrap();
    let uri = file_uri(&dir.path().join("kitchen.reach"));
    let mut client = Client::start();
    client.open(&uri, KITCHEN);
    let found = client.diagnostics_for(&uri);
    assert_eq!(found.len(), 1, "{found:?}");
    let d = &found[0];
    assert_eq!(d["code"], "reach::name");
    assert_eq!(d["severity"], 1);
    assert_eq!(d["source"], "reach");
    assert_eq!(d["range"]["start"], json!({ "line": 7, "character": 6 }));
    assert_eq!(d["range"]["end"], json!({ "line": 7, "character": 10 }));
    let message = d["message"].as_str().unwrap();
    assert!(message.contains("`cupp`"), "{message}");
    assert!(message.contains("help: did you mean `cup`?"), "{message}");
    // Characters are counted in UTF-16: `é` (two bytes) is one, `😀`
    // (four bytes) two.
    let wide = KITCHEN.replace("reach cupp by ann", "/* é😀 */ reach cupp by ann");
    client.change(&uri, 2, &wide);
    let found = client.diagnostics_for(&uri);
    let start = &found[0]["range"]["start"];
    assert_eq!(*start, json!({ "line": 7, "character": 16 }), "{found:?}");
    client.change(&uri, 3, &KITCHEN.replace("cupp", "cup"));
    assert!(client.diagnostics_for(&uri).is_empty());
    client.stop();
}

#[test]
fn an_error_in_a_used_file_is_shown_in_that_file() {
    let dir = tempfile::tempdir().unwrap();
    let parts = dir.path().join("parts.reach");
    std::fs::write(&parts, "units mm\nlet shelf_h = 1500 +\n").unwrap();
    let uri = file_uri(&dir.path().join("kitchen.reach"));
    let mut client = Client::start();
    client.open(
        &uri,
        &format!("use \"parts.reach\"\n{}", KITCHEN.replace("cupp", "cup")),
    );
    let found = client.diagnostics_for(&file_uri(&parts));
    assert_eq!(found.len(), 1, "{found:?}");
    assert_eq!(found[0]["code"], "reach::syntax");
    assert_eq!(found[0]["range"]["start"]["line"], 1);
    // Mended on disk and saved: the error is gone from the used file.
    std::fs::write(&parts, "units mm\nlet shelf_h = 1500\n").unwrap();
    client.notify(
        "textDocument/didSave",
        json!({ "textDocument": { "uri": file_uri(&parts) } }),
    );
    assert!(client.diagnostics_for(&file_uri(&parts)).is_empty());
    // A request the server does not answer is refused, not ignored.
    client.request(7, "textDocument/rename", json!({}));
    assert_eq!(client.response(7)["error"]["code"], -32601);
    client.stop();
}
