//! The language server's latency, end to end over stdio: `reach lsp` is
//! started, `examples/kitchen_wheelchair.reach` opened in it, then changed
//! again and again (a target moved 1 mm and back, then an unknown name
//! made and mended), each change timed from the start of writing
//! `didChange` to the `publishDiagnostics` it causes (a monotonic clock).
//! Prints each kind of change's least, median and greatest. Then, in a
//! server of its own, the time from `didOpen` to the code lenses of the
//! run it starts (the `codeLens` answer after the server's
//! `workspace/codeLens/refresh`), and from a `didSave` of the same text
//! (every answer then kept by the document's cache) to its lenses; beside
//! each, the run's own time as the server logs it (`window/logMessage`),
//! whose difference is what the server adds, and the same run in this
//! process (a fresh `TaskCache`, then the same cache again).
//!
//! `cargo build --release && cargo run --release --example bench_lsp -- [CHANGES]`
//! (20 changes of each kind by default).

use std::io::{BufRead, BufReader, Write};
use std::path::PathBuf;
use std::process::{Child, ChildStdin, Command, Stdio};
use std::sync::mpsc::{channel, Receiver};
use std::time::{Duration, Instant};

use serde_json::{json, Value};

fn main() {
    let changes: usize = std::env::args()
        .nth(1)
        .map_or(20, |n| n.parse().expect("CHANGES is a count"));
    let path = std::fs::canonicalize("examples/kitchen_wheelchair.reach")
        .expect("run from the repository's root");
    let text = std::fs::read_to_string(&path).unwrap();
    let uri = url::Url::from_file_path(&path).unwrap().to_string();
    let (child, mut stdin, from_server) = started(json!({}));
    let document = json!({ "uri": uri, "languageId": "reach", "version": 1, "text": text });
    send(
        &mut stdin,
        json!({ "jsonrpc": "2.0", "method": "textDocument/didOpen", "params": { "textDocument": document } }),
    );
    wait_for(&from_server, |m| {
        m["method"] == "textDocument/publishDiagnostics"
    });
    let (first_target, moved) = moved_target(&text);
    let broken = text.replacen(
        &format!("reach {first_target}"),
        &format!("reach {first_target}x"),
        1,
    );
    let kinds: [(&str, [&str; 2]); 2] = [
        ("a target moved 1 mm and back", [&moved, &text]),
        ("a name made unknown and mended", [&broken, &text]),
    ];
    let mut version = 1;
    for (kind, texts) in kinds {
        let mut times = Vec::new();
        for k in 0..2 * changes {
            version += 1;
            let change = json!({
                "jsonrpc": "2.0",
                "method": "textDocument/didChange",
                "params": {
                    "textDocument": { "uri": uri, "version": version },
                    "contentChanges": [{ "text": texts[k % 2] }],
                },
            });
            // What a run or an earlier change sent is not this change's.
            while from_server.try_recv().is_ok() {}
            // From before the write: the time includes it (from after
            // it, a quick answer can be in before the clock is read).
            let start = Instant::now();
            send(&mut stdin, change);
            let published = wait_for(&from_server, |m| {
                m["method"] == "textDocument/publishDiagnostics" && m["params"]["uri"] == uri
            });
            times.push(start.elapsed());
            // The unknown name is found, and the mended text is clean.
            let found = published["params"]["diagnostics"]
                .as_array()
                .map_or(0, Vec::len);
            assert_eq!(found > 0, texts[k % 2] == broken, "{published}");
        }
        times.sort();
        let ms = |d: Duration| d.as_secs_f64() * 1000.0;
        println!(
            "{kind}: {} changes, least {:.1} ms, median {:.1} ms, greatest {:.1} ms",
            times.len(),
            ms(times[0]),
            ms(times[times.len() / 2]),
            ms(times[times.len() - 1])
        );
    }
    stop(child, stdin, &from_server);
    lenses(&path, &uri, &text);
}

/// The time from `didOpen`, then from a `didSave`, to the lenses, each
/// beside the run's own time as the server logs it, and the same run in
/// this process.
fn lenses(path: &std::path::Path, uri: &str, text: &str) {
    let capabilities = json!({ "workspace": { "codeLens": { "refreshSupport": true } } });
    let (child, mut stdin, from_server) = started(capabilities);
    let mut id = 10;
    let mut to_lenses = |stdin: &mut ChildStdin, start: Instant| {
        let logged = wait_for(&from_server, |m| m["method"] == "window/logMessage");
        let run_ms = logged_run_ms(&logged);
        wait_for(&from_server, |m| {
            m["method"] == "workspace/codeLens/refresh"
        });
        id += 1;
        send(
            stdin,
            json!({ "jsonrpc": "2.0", "id": id, "method": "textDocument/codeLens", "params": { "textDocument": { "uri": uri } } }),
        );
        let lenses = wait_for(&from_server, |m| m["id"] == id);
        let count = lenses["result"].as_array().map_or(0, Vec::len);
        assert!(count > 0, "{lenses}");
        (start.elapsed(), count, run_ms)
    };
    let document = json!({ "uri": uri, "languageId": "reach", "version": 1, "text": text });
    send(
        &mut stdin,
        json!({ "jsonrpc": "2.0", "method": "textDocument/didOpen", "params": { "textDocument": document } }),
    );
    let (opened, count, opened_run_ms) = to_lenses(&mut stdin, Instant::now());
    send(
        &mut stdin,
        json!({ "jsonrpc": "2.0", "method": "textDocument/didSave", "params": { "textDocument": { "uri": uri } } }),
    );
    let (saved, _, saved_run_ms) = to_lenses(&mut stdin, Instant::now());
    stop(child, stdin, &from_server);
    let (run_cold, run_kept) = run_alone(path);
    let ms = |d: Duration| d.as_secs_f64() * 1000.0;
    println!(
        "didOpen to its {count} lenses: {:.1} ms; the server's run (logged): {opened_run_ms:.0} ms; added {:.0} ms",
        ms(opened),
        ms(opened) - opened_run_ms
    );
    println!(
        "  the same run alone in this process (a fresh cache): {:.1} ms",
        ms(run_cold)
    );
    println!(
        "didSave of the same text to its lenses: {:.1} ms; the server's run (logged): {saved_run_ms:.0} ms; added {:.0} ms",
        ms(saved),
        ms(saved) - saved_run_ms
    );
    println!(
        "  the same run alone in this process (answers kept): {:.1} ms",
        ms(run_kept)
    );
}

/// The run's time the server logs with its answers (`reach: ran FILE in
/// 412 ms: ...`), in ms.
fn logged_run_ms(logged: &Value) -> f64 {
    let message = logged["params"]["message"].as_str().unwrap_or_default();
    let ms = message
        .split(" in ")
        .nth(1)
        .and_then(|rest| rest.split(" ms").next());
    ms.and_then(|ms| ms.parse().ok())
        .unwrap_or_else(|| panic!("a run's time in {logged}"))
}

/// The scenario's run in this process, after the server has stopped: the
/// first in the process, as the server's is in its own (a second run in
/// one process finds what the first set up once, and is quicker: 3.9 s
/// against 4.7 s here), with a fresh cache; then that cache again.
fn run_alone(path: &std::path::Path) -> (Duration, Duration) {
    let registry = reach::plugin::Registry::builtin();
    let (_, checked) = reach::check(reach::Input::Path(path), &registry);
    let scenario = checked.expect("the example checks");
    let progress = &reach::progress::NoProgress;
    let mut cache = reach::TaskCache::default();
    let start = Instant::now();
    cache.run(&scenario, progress).expect("within the bound");
    let cold = start.elapsed();
    let start = Instant::now();
    cache.run(&scenario, progress).expect("within the bound");
    (cold, start.elapsed())
}

/// `reach lsp` started and initialized by a client of these
/// capabilities: the process, its input and its messages.
fn started(capabilities: Value) -> (Child, ChildStdin, Receiver<Value>) {
    let mut child = Command::new(reach_binary())
        .arg("lsp")
        .stdin(Stdio::piped())
        .stdout(Stdio::piped())
        .spawn()
        .expect("target/release/reach runs (cargo build --release)");
    let mut stdin = child.stdin.take().unwrap();
    let from_server = messages(BufReader::new(child.stdout.take().unwrap()));
    let params = json!({ "capabilities": capabilities });
    send(
        &mut stdin,
        json!({ "jsonrpc": "2.0", "id": 1, "method": "initialize", "params": params }),
    );
    wait_for(&from_server, |m| m["id"] == 1);
    send(
        &mut stdin,
        json!({ "jsonrpc": "2.0", "method": "initialized", "params": {} }),
    );
    (child, stdin, from_server)
}

/// `shutdown`, then `exit`, and the process waited for.
fn stop(mut child: Child, mut stdin: ChildStdin, from_server: &Receiver<Value>) {
    send(
        &mut stdin,
        json!({ "jsonrpc": "2.0", "id": 2, "method": "shutdown" }),
    );
    wait_for(from_server, |m| m["id"] == 2);
    send(&mut stdin, json!({ "jsonrpc": "2.0", "method": "exit" }));
    child.wait().unwrap();
}

/// The first target's declaration moved 1 mm along x: its name and the
/// text so changed.
fn moved_target(text: &str) -> (String, String) {
    let line = (text.lines())
        .find(|l| l.trim_start().starts_with("target "))
        .expect("the kitchen has a target");
    let name = line.split_whitespace().nth(1).unwrap().to_string();
    let open = line.find('(').unwrap();
    let comma = open + line[open..].find(',').unwrap();
    let x: f64 = line[open + 1..comma].trim().parse().unwrap();
    let moved = format!("{}{}{}", &line[..open + 1], x + 1.0, &line[comma..]);
    (name, text.replacen(line, &moved, 1))
}

fn send(stdin: &mut ChildStdin, message: Value) {
    let body = message.to_string();
    write!(stdin, "Content-Length: {}\r\n\r\n{body}", body.len()).unwrap();
    stdin.flush().unwrap();
}

/// Wait (a minute at most) for a message `wanted` picks.
fn wait_for(from_server: &Receiver<Value>, wanted: impl Fn(&Value) -> bool) -> Value {
    loop {
        let message = from_server
            .recv_timeout(Duration::from_secs(60))
            .expect("the server answers");
        if wanted(&message) {
            return message;
        }
    }
}

/// The server's messages, read on a thread of their own.
fn messages(mut reader: impl BufRead + Send + 'static) -> Receiver<Value> {
    let (to, from) = channel();
    std::thread::spawn(move || loop {
        let mut length = None;
        loop {
            let mut line = String::new();
            if reader.read_line(&mut line).unwrap_or(0) == 0 {
                return;
            }
            let line = line.trim_end();
            if line.is_empty() {
                break;
            }
            if let Some(n) = line.strip_prefix("Content-Length: ") {
                length = n.parse::<usize>().ok();
            }
        }
        let mut body = vec![0; length.unwrap_or(0)];
        if reader.read_exact(&mut body).is_err() {
            return;
        }
        if to.send(serde_json::from_slice(&body).unwrap()).is_err() {
            return;
        }
    });
    from
}

/// The `reach` binary beside this example's directory
/// (`target/release/reach`).
fn reach_binary() -> PathBuf {
    let exe = std::env::current_exe().expect("the example's path");
    let dir = exe
        .parent()
        .and_then(|d| d.parent())
        .expect("target/release");
    dir.join(format!("reach{}", std::env::consts::EXE_SUFFIX))
}
