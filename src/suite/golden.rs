//! A run's answers against a golden report (the JSON of an earlier run a
//! person signed off): about answers, not bytes. Tasks are matched by what
//! they ask (the task, its target or surface, its person, population or
//! room), so adding a task shifts nothing; for each, what counts as a
//! change, in words:
//!
//! - a verdict that flipped ("kettle: ann reachable -> NOT reachable, now
//!   blocked by `upper_cabinet`"), or an unreached answer whose reason
//!   changed;
//! - where the base stood, moved more than the tolerance (default 1 mm,
//!   0.1 deg), and how far short an unreached answer falls;
//! - a map's points that flipped; a population's share or who it leaves
//!   out; a standard's rules that flipped;
//! - a task the golden report has and the run does not, or the reverse.
//!
//! Postures, comfort and iterations are not compared: the same answer may
//! be found by another posture. A golden report of another schema version
//! is not compared at all: it must be written again (`--update`). What
//! each kind of entry asks and what counts as its change is the kind's own
//! (`report::EntryKind`); an entry of a kind this build does not know is
//! a change, said so.

use serde_json::Value;

use crate::report::{Answer, Asks, Kind, TaskReport, SCHEMA_VERSION};

pub use crate::report::Tolerance;

/// How a run compares with its golden report.
#[derive(Clone, Debug, PartialEq)]
pub enum Compared {
    /// The same answers.
    Same,
    /// What changed, in words, one line each.
    Changed(Vec<String>),
    /// Written by a reach of another schema version: not comparable.
    OtherSchema { golden: u64 },
    /// Not a report (not JSON, or no tasks).
    Unreadable(String),
}

/// One entry of the run: its kind, its JSON, its answer and what it
/// asks (worked out once, for every golden entry it is matched against).
struct Entry {
    kind: Kind,
    value: Value,
    answer: Answer,
    asks: Asks,
}

/// `new` (the run's entries and their JSON) against `golden` (the text of a
/// golden report).
pub fn compare(golden: &str, new: &[TaskReport], tolerance: Tolerance) -> Compared {
    let golden: Value = match serde_json::from_str(golden) {
        Ok(v) => v,
        Err(e) => return Compared::Unreadable(format!("not JSON: {e}")),
    };
    let schema = golden["schema"].as_u64().unwrap_or(0);
    if schema != u64::from(SCHEMA_VERSION) {
        return Compared::OtherSchema { golden: schema };
    }
    let Some(old_tasks) = golden["tasks"].as_array() else {
        return Compared::Unreadable("no `tasks`".into());
    };
    let entries: Vec<Entry> = new
        .iter()
        .map(|t| {
            let kind = Kind::of_report(t);
            let value = serde_json::to_value(t).unwrap_or(Value::Null);
            Entry {
                asks: kind.asks(&value),
                kind,
                value,
                answer: t.answer(),
            }
        })
        .collect();
    let mut changes = Vec::new();
    let mut matched = vec![false; entries.len()];
    for old in old_tasks {
        let Some(old_kind) = Kind::of(old) else {
            changes.push(format!(
                "an entry of kind `{}` in the golden report, which this reach does not know",
                old["kind"].as_str().unwrap_or_default()
            ));
            continue;
        };
        let asks = old_kind.asks(old);
        let found = (entries.iter().enumerate()).find(|(k, e)| !matched[*k] && e.asks == asks);
        match found {
            Some((k, entry)) => {
                matched[k] = true;
                changes.extend(entry_changes((old_kind, old), entry, tolerance));
            }
            None => changes.push(format!(
                "{}: in the golden report, no longer asked",
                asks.words()
            )),
        }
    }
    for (k, entry) in entries.iter().enumerate() {
        if !matched[k] {
            changes.push(format!(
                "{}: not in the golden report (`reach test --update` signs it off)",
                entry.asks.words()
            ));
        }
    }
    if changes.is_empty() {
        Compared::Same
    } else {
        Compared::Changed(changes)
    }
}

/// What changed between one entry of the golden report and the run's: a
/// verdict that flipped (or an entry of another kind), else what the
/// kind counts as a change.
fn entry_changes((old_kind, old): (Kind, &Value), new: &Entry, tol: Tolerance) -> Vec<String> {
    let who = format!("{}: {}", new.asks.subject, new.asks.who);
    let old_ok = old["ok"].as_bool().unwrap_or(false);
    if old_ok != new.answer.ok || old_kind != new.kind {
        let was = old_kind.verdict_words(old);
        return vec![format!("{who} {was} -> {}", new.answer.verdict)];
    }
    new.kind.changes((old, &new.value), &new.answer, &who, tol)
}
