//! The entry of a task the run did not evaluate: the work limit stopped
//! the run before it. A run stopped by the limit still reports the tasks
//! it finished (the longest run of them, in the order of the file, whose
//! work fits within the limit: the same on every run and thread count);
//! each task after them is this entry, so that a long study shows what it
//! found and says plainly what it did not look at. Watch mode's first
//! answers to a save mark the tasks still running with it too, as being
//! evaluated.

use std::fmt::Write as _;

use serde::Serialize;
use serde_json::Value;

use super::entry_kind::{text, Asks, EntryKind, Tolerance};
use super::{Answer, ReportKind};

/// A task not evaluated: the run's work limit stopped it first.
#[derive(Clone, Debug, PartialEq, Serialize, schemars::JsonSchema)]
pub struct NotEvaluatedReport {
    /// The task as the text report names it (`reach`, `map`, `standard`,
    /// ...).
    pub task: &'static str,
    /// The target, surface or standard.
    pub name: String,
    /// The person or population (a standard: `in` its room).
    pub person: String,
    /// Always false: nothing was found.
    pub ok: bool,
    /// Why it was not evaluated: `work limit`, or (watch mode's first
    /// answers) `evaluating`.
    pub reason: &'static str,
}

/// The reason of a task the work limit stopped the run before.
pub const WORK_LIMIT: &str = "work limit";
/// The reason of a task still running when watch mode shows the answers
/// it kept.
pub const EVALUATING: &str = "evaluating";

impl NotEvaluatedReport {
    pub fn new(task: &'static str, name: &str, person: &str) -> Self {
        NotEvaluatedReport {
            task,
            name: name.to_string(),
            person: person.to_string(),
            ok: false,
            reason: WORK_LIMIT,
        }
    }

    /// The entry of a task still running.
    pub fn evaluating(task: &'static str, name: &str, person: &str) -> Self {
        NotEvaluatedReport {
            reason: EVALUATING,
            ..Self::new(task, name, person)
        }
    }

    /// The verdict's words: `not evaluated: work limit`, `evaluating ...`.
    fn words(&self) -> String {
        match self.reason {
            EVALUATING => "evaluating ...".to_string(),
            reason => format!("not evaluated: {reason}"),
        }
    }
}

impl ReportKind for NotEvaluatedReport {
    fn answer(&self) -> Answer {
        Answer {
            task: self.task,
            subject: self.name.clone(),
            person: self.person.clone(),
            ok: false,
            verdict: self.words(),
            effector: None,
            figures: Vec::new(),
        }
    }

    fn details(&self, out: &mut String) {
        let answer = self.answer();
        let words = match self.reason {
            EVALUATING => "evaluating ...".to_string(),
            reason => format!("not evaluated ({reason})"),
        };
        let _ = writeln!(out, "\n{}: {words}", answer.label());
    }
}

impl EntryKind for NotEvaluatedReport {
    fn asks(entry: &Value) -> Asks {
        Asks::by_name(text(entry, "task"), entry, "person")
    }
    fn verdict_words(_: &Value) -> String {
        "not evaluated".into()
    }
    fn changes(_: &Value, _: &Value, _: &Answer, _: &str, _: Tolerance) -> Vec<String> {
        Vec::new()
    }
}
