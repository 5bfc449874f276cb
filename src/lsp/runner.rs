//! The background run that puts the answers beside the lines: after a save
//! (and on opening), the checked scenario runs on a thread of its own
//! through the document's own answer cache (watch mode's `TaskCache`),
//! within the same limits; where the bound on work stops it, the answers
//! of the tasks before the stop (`Session::run_partly`, on the text
//! checked afresh). An edit cancels the run in flight ([`reach::Memo::cancel`]):
//! it stops as a run past its bound does and its answers are dropped. Of
//! several runs asked for before one starts, each document's last runs.

use std::collections::BTreeMap;
use std::path::PathBuf;
use std::sync::{Arc, Mutex};
use std::time::Instant;

use crossbeam_channel::{Receiver, Sender};
use lsp_types::{Diagnostic, DiagnosticSeverity, NumberOrString, Range};

use super::position::LineIndex;
use reach::plugin::Registry;
use reach::progress::NoProgress;
use reach::{Input, Memo, Scenario, Session, TaskCache};

/// A run asked for: the document, its edit count and text when checked,
/// and the scenario its check gave.
pub struct Asked {
    pub uri: String,
    pub edit: u64,
    pub path: Option<PathBuf>,
    pub text: String,
    pub scenario: Scenario,
}

/// A run's answers, placed on the lines of the text it ran.
pub struct Answers {
    pub uri: String,
    /// Each answer's verdict at its declaration's range.
    pub lenses: Vec<(Range, bool, String)>,
    /// The `expect`s not met, as diagnostics.
    pub unmet: Vec<Diagnostic>,
    /// Where the bound on work stopped the run, why.
    pub stopped: Option<String>,
    /// The text run, to move the answers with their lines after an edit.
    pub text: String,
    /// How long the run took (its cache's run, and the partial run after
    /// it where the bound stopped that), in ms.
    pub run_ms: f64,
}

/// What the run thread and the editor's share: each open document's edit
/// count as the editor's messages have it, and the document whose run is
/// in flight with the memo that cancels it. Under one lock, so that an
/// edit either comes before a run starts (which is then not started) or
/// finds it in flight (and cancels it).
#[derive(Default)]
pub struct Runs {
    pub edits: BTreeMap<String, u64>,
    pub in_flight: Option<(String, Arc<Memo>)>,
    /// Set at `shutdown`: no run starts.
    pub stopped: bool,
}

/// At `shutdown`: no run starts any more, and the one in flight is
/// cancelled.
pub fn stop(running: &Running) {
    let mut runs = lock(running);
    runs.stopped = true;
    if let Some((_, memo)) = &runs.in_flight {
        memo.cancel();
    }
}

pub type Running = Arc<Mutex<Runs>>;

/// Note document `uri`'s edit `edit`, and cancel its run in flight (run
/// on an earlier text).
pub fn edited(running: &Running, uri: &str, edit: u64) {
    let mut runs = lock(running);
    runs.edits.insert(uri.to_string(), edit);
    if let Some((flying, memo)) = &runs.in_flight {
        if flying == uri {
            memo.cancel();
        }
    }
}

/// Run what `asked` brings, one at a time, until it closes; the answers
/// go to `answers` (a cancelled run's are dropped).
pub fn serve_runs(
    asked: &Receiver<Asked>,
    answers: &Sender<Answers>,
    running: &Running,
    (session, registry): (Session<'_>, &Registry),
) {
    let mut caches: BTreeMap<String, TaskCache> = BTreeMap::new();
    while let Ok(first) = asked.recv() {
        // The last asked of each document.
        let mut latest: BTreeMap<String, Asked> = BTreeMap::new();
        latest.insert(first.uri.clone(), first);
        for more in asked.try_iter() {
            latest.insert(more.uri.clone(), more);
        }
        for (uri, one) in latest {
            let cache = caches.entry(uri.clone()).or_default();
            let memo = cache.memo();
            {
                let mut runs = lock(running);
                // Edited since it was asked, or the server is shutting
                // down: not run.
                if runs.stopped || runs.edits.get(&uri) != Some(&one.edit) {
                    continue;
                }
                runs.in_flight = Some((uri, Arc::clone(&memo)));
            }
            let ran = run_one(&one, cache, (session, registry));
            lock(running).in_flight = None;
            let cancelled = memo.cancelled();
            memo.resume();
            let Some(ran) = ran.filter(|_| !cancelled) else {
                continue;
            };
            if answers.send(ran).is_err() {
                return;
            }
        }
    }
}

fn lock(running: &Running) -> std::sync::MutexGuard<'_, Runs> {
    running.lock().unwrap_or_else(|e| e.into_inner())
}

/// Run one document's scenario: through its cache, or as far as the
/// bound allows; none where it was cancelled.
fn run_one(
    asked: &Asked,
    cache: &mut TaskCache,
    (session, registry): (Session<'_>, &Registry),
) -> Option<Answers> {
    let start = Instant::now();
    let (report, stopped) = match cache.run(&asked.scenario, &NoProgress) {
        Ok((report, _)) => (report, None),
        // Cancelled: no answers.
        Err(_) if cache.memo().cancelled() => return None,
        Err(_) => {
            let again = || {
                let input = match &asked.path {
                    Some(path) => Input::Edited {
                        path,
                        text: &asked.text,
                    },
                    None => Input::Text {
                        name: &asked.uri,
                        text: &asked.text,
                    },
                };
                session.check(input, registry).1.ok()
            };
            let ran = session.run_partly(&asked.scenario, &again);
            (ran.report, ran.stopped.map(|e| e.to_string()))
        }
    };
    let run_ms = start.elapsed().as_secs_f64() * 1000.0;
    let index = LineIndex::new(&asked.text);
    let range = |span: (u32, u32)| index.range(span.0 as usize, span.1 as usize);
    let root = root_file(&asked.scenario);
    let in_root = |file: u32| Some(file) == root;
    let lenses = reach::editor::verdicts(&asked.scenario, &report)
        .into_iter()
        .filter(|v| in_root(v.span.file.0))
        .map(|v| (first_line(range((v.span.start, v.span.end))), v.ok, v.text))
        .collect();
    let unmet = reach::editor::unmet(&asked.scenario, &report)
        .into_iter()
        .filter(|u| in_root(u.span.file.0))
        .map(|u| Diagnostic {
            range: range((u.span.start, u.span.end)),
            severity: Some(DiagnosticSeverity::ERROR),
            code: Some(NumberOrString::String("expectation".into())),
            source: Some("reach run".into()),
            message: u.text,
            ..Diagnostic::default()
        })
        .collect();
    Some(Answers {
        uri: asked.uri.clone(),
        lenses,
        unmet,
        stopped,
        text: asked.text.clone(),
        run_ms,
    })
}

/// The file the tasks are declared in (the root's: only its tasks run).
fn root_file(scenario: &Scenario) -> Option<u32> {
    let task = scenario.tasks.first().map(|t| t.span.file.0);
    task.or_else(|| scenario.standards.first().map(|s| s.span.file.0))
}

/// A range cut to its first line (a lens sits on a declaration's line).
fn first_line(range: Range) -> Range {
    if range.end.line == range.start.line {
        return range;
    }
    Range::new(range.start, range.start)
}
