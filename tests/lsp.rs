//! `reach lsp` driven over standard input and output with real Language
//! Server Protocol messages, as an editor sends them: the handshake, a
//! document opened with an error (its diagnostic at its place, in UTF-16,
//! with the CLI's code and help), changed until mended (its diagnostics
//! cleared), a document whose `use`d file has the error (published to that
//! file), a request it does not answer, and shutdown; completion, hover,
//! go to definition (into a used file and the standard library's text)
//! and references on a document that `use`s another; the answers of a run
//! after a save as code lenses and inlay hints, marked stale once the text
//! changes, and an `expect` not met as a diagnostic.

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
        Client::start_with(&[])
    }

    /// A server with these variables set (where it serves the standard
    /// library's text from), its client asking for refreshes.
    fn start_with(env: &[(&str, &Path)]) -> Client {
        let mut command = Command::new(env!("CARGO_BIN_EXE_reach"));
        for (name, value) in env {
            command.env(name, value);
        }
        let mut child = command
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
            json!({ "capabilities": { "workspace": { "codeLens": { "refreshSupport": true } } }, "processId": null }),
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

    /// Ask, and wait for the answer's result.
    fn ask(&mut self, id: i64, method: &str, params: Value) -> Value {
        self.request(id, method, params);
        self.response(id)["result"].clone()
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
        // A client's late word after `shutdown` is let be.
        self.notify("$/cancelRequest", json!({ "id": 5 }));
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
    client.request(7, "textDocument/formatting", json!({}));
    assert_eq!(client.response(7)["error"]["code"], -32601);
    client.stop();
}

const USING: &str = "units mm
use \"parts.reach\"
use std::people
room kitchen {
  size 3m x 3000 x 2500
  box counter at (0, 0, 0) size (600, 3000, cup_h)
  target cup at (300, 1500, 950)
  target jar at (100, 1500, 2400)
}
person ann { mannequin woman_5th_seated base wheelchair {  } }
reach cup, jar by ann
expect ann reaches jar
";

/// The file `USING` uses.
const PARTS: &str = "units mm\nlet cup_h = 900\n";

/// A directory holding `parts.reach` (`PARTS`), where `USING` is to be
/// `kitchen.reach`; and the path of `parts.reach`.
fn with_parts() -> (tempfile::TempDir, std::path::PathBuf) {
    let dir = tempfile::tempdir().unwrap();
    let parts = dir.path().join("parts.reach");
    std::fs::write(&parts, PARTS).unwrap();
    (dir, parts)
}

/// The position of the `k`-th (0-based) `needle` in `text`, plus `past`
/// characters (all ASCII here).
fn at(text: &str, needle: &str, k: usize, past: usize) -> Value {
    let offset = text.match_indices(needle).nth(k).unwrap().0 + past;
    let line = text[..offset].matches('\n').count();
    let character = offset - text[..offset].rfind('\n').map_or(0, |n| n + 1);
    json!({ "line": line, "character": character })
}

fn labels(items: &Value) -> Vec<String> {
    let items = items.as_array().cloned().unwrap_or_default();
    items
        .iter()
        .map(|i| i["label"].as_str().unwrap().to_string())
        .collect()
}

#[test]
fn completion_hover_definition_and_references_know_the_scenarios_names() {
    let (dir, parts) = with_parts();
    let path = dir.path().join("kitchen.reach");
    let uri = file_uri(&path);
    let cache = dir.path().join("cache");
    let mut client = Client::start_with(&[("XDG_CACHE_HOME", &cache)]);
    client.open(&uri, USING);
    let doc = json!({ "uri": uri });
    let position = |needle: &str, k: usize, past: usize| json!({ "textDocument": doc, "position": at(USING, needle, k, past) });
    // Names after `by`, units after a number, a plugin's options in its
    // block (with kind and default), keywords in a room.
    let by = client.ask(2, "textDocument/completion", position("by ann", 0, 3));
    assert!(labels(&by).contains(&"ann".to_string()), "{by}");
    let units = client.ask(3, "textDocument/completion", position("3000 x", 0, 4));
    let mm = units
        .as_array()
        .unwrap()
        .iter()
        .find(|i| i["label"] == "mm");
    let mm = mm.unwrap_or_else(|| panic!("mm in {units}"));
    // It goes after the digits, and is filtered by the whole word.
    assert_eq!(mm["textEdit"]["range"]["start"], at(USING, "3000 x", 0, 4));
    assert_eq!(mm["filterText"], "3000mm");
    let options = client.ask(
        4,
        "textDocument/completion",
        position("wheelchair {", 0, 13),
    );
    let seat = options
        .as_array()
        .unwrap()
        .iter()
        .find(|i| i["label"] == "seat_height");
    let seat = seat.unwrap_or_else(|| panic!("seat_height in {options}"));
    assert!(
        seat["detail"]
            .as_str()
            .unwrap()
            .starts_with("length, default"),
        "{seat}"
    );
    let room = client.ask(5, "textDocument/completion", position("  box", 0, 2));
    assert!(labels(&room).contains(&"target".to_string()), "{room}");
    // A mannequin of the standard library the file does not use yet
    // comes with the `use` it needs.
    let alone = "room r { size 3000 x 3000 x 2500 }\nperson p { mannequin  }\n";
    let alone_uri = file_uri(&dir.path().join("alone.reach"));
    client.open(&alone_uri, alone);
    let p =
        json!({ "textDocument": { "uri": alone_uri }, "position": at(alone, "mannequin ", 0, 10) });
    let mannequins = client.ask(6, "textDocument/completion", p);
    let woman = mannequins
        .as_array()
        .unwrap()
        .iter()
        .find(|i| i["label"] == "woman_5th_seated");
    let woman = woman.unwrap_or_else(|| panic!("woman_5th_seated in {mannequins}"));
    assert_eq!(
        woman["additionalTextEdits"][0]["newText"],
        "use std::people\n"
    );

    // Hover: a target's place, a person's body, a number's value.
    let cup = client.ask(7, "textDocument/hover", position("cup, jar", 0, 1));
    let cup = cup["contents"]["value"].as_str().unwrap().to_string();
    assert!(cup.contains("at (300, 1500, 950) mm"), "{cup}");
    let ann = client.ask(8, "textDocument/hover", position("person ann", 0, 8));
    let ann = ann["contents"]["value"].as_str().unwrap().to_string();
    assert!(
        ann.contains("woman_5th_seated") && ann.contains("elbow_flexion"),
        "{ann}"
    );
    assert!(
        ann.contains("base `wheelchair`") && ann.contains("seat_height"),
        "{ann}"
    );
    // Her stature and the measurements `measured` built her from.
    assert!(ann.contains("\n\nstature 1520 mm"), "{ann}");
    assert!(ann.contains("sitting_height 801.6 mm"), "{ann}");
    // A constant of the used file: its value.
    let height = client.ask(90, "textDocument/hover", position("cup_h", 0, 1));
    let height = height["contents"]["value"].as_str().unwrap().to_string();
    assert!(
        height.contains("= 900 (no unit: 900 mm as a length"),
        "{height}"
    );
    let metres = client.ask(9, "textDocument/hover", position("3m", 0, 1));
    assert_eq!(metres["contents"]["value"], "`3m` = 3000 mm");

    // Definition: a constant of the used file, a mannequin of the
    // standard library (served read-only).
    let found = client.ask(10, "textDocument/definition", position("cup_h", 0, 1));
    assert_eq!(found[0]["uri"], file_uri(&parts), "{found}");
    assert_eq!(
        found[0]["range"]["start"],
        json!({ "line": 1, "character": 4 })
    );
    let found = client.ask(
        11,
        "textDocument/definition",
        position("woman_5th_seated", 0, 1),
    );
    let std_uri = found[0]["uri"].as_str().unwrap().to_string();
    assert!(std_uri.ends_with("/people.reach"), "{found}");
    let std_path = url::Url::parse(&std_uri).unwrap().to_file_path().unwrap();
    assert!(std_path.starts_with(&cache), "{std_path:?}");
    assert!(std::fs::metadata(&std_path)
        .unwrap()
        .permissions()
        .readonly());
    let line = found[0]["range"]["start"]["line"].as_u64().unwrap() as usize;
    let std_text = std::fs::read_to_string(&std_path).unwrap();
    assert!(std_text
        .lines()
        .nth(line)
        .unwrap()
        .starts_with("mannequin woman_5th_seated"));

    // References: the declaration, the task and the expectation.
    let p = json!({
        "textDocument": doc,
        "position": at(USING, "target jar", 0, 8),
        "context": { "includeDeclaration": true },
    });
    let found = client.ask(12, "textDocument/references", p);
    let lines: Vec<u64> = found
        .as_array()
        .unwrap()
        .iter()
        .map(|l| l["range"]["start"]["line"].as_u64().unwrap())
        .collect();
    assert_eq!(lines, [7, 10, 11], "{found}");
    // From the used file, open too: its uses in the file that uses it.
    let parts_text = std::fs::read_to_string(&parts).unwrap();
    client.open(&file_uri(&parts), &parts_text);
    let p = json!({
        "textDocument": { "uri": file_uri(&parts) },
        "position": { "line": 1, "character": 5 },
        "context": { "includeDeclaration": false },
    });
    let found = client.ask(13, "textDocument/references", p);
    assert_eq!(found[0]["uri"], uri, "{found}");
    assert_eq!(found[0]["range"]["start"]["line"], 5, "{found}");
    client.stop();
}

#[test]
fn a_runs_answers_come_back_as_code_lenses_and_go_stale_on_an_edit() {
    let (dir, _) = with_parts();
    let uri = file_uri(&dir.path().join("kitchen.reach"));
    let mut client = Client::start();
    client.open(&uri, USING);
    client.notify(
        "textDocument/didSave",
        json!({ "textDocument": { "uri": uri } }),
    );
    // The run's answers: the `expect` not met published as a diagnostic
    // on its line, then the client asked to refresh its lenses.
    let mut unmet = Vec::new();
    let mut logged = String::new();
    loop {
        let message = client.next();
        if message["method"] == "window/logMessage" {
            logged = message["params"]["message"].as_str().unwrap().to_string();
        }
        if message["method"] == "textDocument/publishDiagnostics" {
            unmet = message["params"]["diagnostics"].as_array().unwrap().clone();
        }
        if message["method"] == "workspace/codeLens/refresh" {
            break;
        }
    }
    // The run logged with its time and answers.
    assert!(
        logged.starts_with("reach: ran kitchen.reach in "),
        "{logged}"
    );
    assert!(logged.ends_with(" ms: 2 answers"), "{logged}");
    assert_eq!(unmet.len(), 1, "{unmet:?}");
    assert_eq!(unmet[0]["range"]["start"]["line"], 11, "{unmet:?}");
    let message = unmet[0]["message"].as_str().unwrap();
    assert!(
        message.contains("expectation NOT met: ann reaches jar"),
        "{message}"
    );
    let doc = json!({ "textDocument": { "uri": uri } });
    let lenses = client.ask(2, "textDocument/codeLens", doc.clone());
    let titles: Vec<String> = lenses
        .as_array()
        .unwrap()
        .iter()
        .map(|l| l["command"]["title"].as_str().unwrap().to_string())
        .collect();
    assert_eq!(titles.len(), 2, "{lenses}");
    assert!(
        titles[0].starts_with("cup by ann: reachable "),
        "{titles:?}"
    );
    assert!(titles[0].contains(" mm, comfort "), "{titles:?}");
    assert!(
        titles[1].starts_with("✗ jar by ann: NOT reachable: out of reach"),
        "{titles:?}"
    );
    assert_eq!(lenses[0]["range"]["start"]["line"], 10);
    let hints = client.ask(3, "textDocument/inlayHint", json!({
        "textDocument": { "uri": uri },
        "range": { "start": { "line": 0, "character": 0 }, "end": { "line": 12, "character": 0 } },
    }));
    let label = hints[0]["label"].as_str().unwrap();
    assert!(
        label.contains("cup by ann: reachable") && label.contains("jar by ann"),
        "{hints}"
    );
    // An edit: the answers are stale until the next save's run, and move
    // with their lines.
    client.change(&uri, 2, &format!("// a line above\n{USING}"));
    let lenses = client.ask(4, "textDocument/codeLens", doc.clone());
    let title = lenses[0]["command"]["title"].as_str().unwrap();
    assert!(title.starts_with("(stale) cup by ann"), "{title}");
    assert_eq!(lenses[0]["range"]["start"]["line"], 11);
    // The edit undone: the text run, so its answers, are back.
    client.change(&uri, 3, USING);
    let lenses = client.ask(5, "textDocument/codeLens", doc.clone());
    let title = lenses[0]["command"]["title"].as_str().unwrap();
    assert!(title.starts_with("cup by ann"), "{title}");
    assert_eq!(lenses[0]["range"]["start"]["line"], 10);
    // Saved and shut down at once, as `:wq` does; a message between
    // `shutdown` and `exit` is let be, and the server exits 0.
    client.notify(
        "textDocument/didSave",
        json!({ "textDocument": { "uri": uri } }),
    );
    client.notify(
        "textDocument/didClose",
        json!({ "textDocument": { "uri": uri } }),
    );
    client.stop();
}

#[test]
fn rename_changes_every_place_a_name_is_written_or_says_why_not() {
    let (dir, parts) = with_parts();
    let path = dir.path().join("kitchen.reach");
    let uri = file_uri(&path);
    let mut client = Client::start();
    client.open(&uri, USING);
    client.open(&file_uri(&parts), PARTS);
    let doc = json!({ "uri": uri });
    let at = |needle: &str, past: usize| at(USING, needle, 0, past);
    // The name at the cursor, from its use.
    let prepared = client.ask(
        2,
        "textDocument/prepareRename",
        json!({ "textDocument": doc, "position": at("by ann", 4) }),
    );
    assert_eq!(prepared["placeholder"], "ann", "{prepared}");
    assert_eq!(prepared["range"]["start"], at("by ann", 3));
    // Its declaration and both uses.
    let rename = |client: &mut Client, id: i64, needle: &str, past: usize, new: &str| {
        let params = json!({ "textDocument": doc, "position": at(needle, past), "newName": new });
        client.request(id, "textDocument/rename", params);
        client.response(id)
    };
    let edit = rename(&mut client, 3, "person ann", 8, "bea");
    let edits = edit["result"]["changes"][uri.as_str()]
        .as_array()
        .unwrap()
        .clone();
    let starts: Vec<Value> = edits.iter().map(|e| e["range"]["start"].clone()).collect();
    assert_eq!(
        starts,
        [at("person ann", 7), at("by ann", 3), at("expect ann", 7)],
        "{edit}"
    );
    assert!(edits.iter().all(|e| e["newText"] == "bea"), "{edit}");
    // A constant of the used file: there and here.
    let edit = rename(&mut client, 4, "cup_h", 1, "cup_height");
    let changes = edit["result"]["changes"].as_object().unwrap();
    assert_eq!(changes.len(), 2, "{edit}");
    assert_eq!(
        changes[&file_uri(&parts)][0]["range"]["start"],
        json!({ "line": 1, "character": 4 })
    );
    // Refused, with why: a name declared already, a keyword, not a name,
    // the standard library's, a place with no name.
    for (id, needle, past, new, why) in [
        (
            5,
            "person ann",
            8,
            "cup",
            "is declared already (target in `kitchen`)",
        ),
        (6, "person ann", 8, "room", "is a keyword"),
        (7, "person ann", 8, "2ann", "is not a name"),
        (8, "woman_5th_seated", 1, "mum", "is the standard library's"),
        (9, "reach cup", 1, "run", "no declared name here"),
    ] {
        let refused = rename(&mut client, id, needle, past, new);
        let message = refused["error"]["message"].as_str().unwrap_or_default();
        assert!(message.contains(why), "{new}: {refused}");
    }
    client.stop();
}
