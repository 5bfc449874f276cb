//! A run's answers placed on the declarations that asked for them, for an
//! editor to show beside their lines: one short verdict for each answer
//! (`counter_front by ann: reachable 9.2 mm, comfort 3.76`), at the task
//! or standard it answers, and each `expect` the answers do not meet.

use crate::report::{Report, TaskReport};
use crate::scenario::Scenario;
use crate::span::Span;

/// One answer, at the declaration it answers.
#[derive(Clone, Debug, PartialEq)]
pub struct Verdict {
    /// The task's or the standard's declaration.
    pub span: Span,
    pub ok: bool,
    pub text: String,
}

/// An `expect` the answers do not meet, and why.
#[derive(Clone, Debug, PartialEq)]
pub struct Unmet {
    pub span: Span,
    pub text: String,
}

/// Each answer of `report` (a run of `scenario`), at its declaration, in
/// the report's order.
pub fn verdicts(scenario: &Scenario, report: &Report) -> Vec<Verdict> {
    let spans =
        (scenario.tasks.iter().map(|t| t.span)).chain(scenario.standards.iter().map(|s| s.span));
    spans
        .zip(&report.tasks)
        .map(|(span, entry)| Verdict {
            span,
            ok: entry.answer().ok,
            text: verdict_words(entry),
        })
        .collect()
}

/// The `expect`s of `scenario` that `report` does not meet.
pub fn unmet(scenario: &Scenario, report: &Report) -> Vec<Unmet> {
    (scenario.expectations.iter())
        .zip(&report.expectations)
        .filter(|(_, judged)| !judged.met)
        .map(|(spec, judged)| Unmet {
            span: spec.span,
            text: format!("expectation NOT met: {}: {}", judged.expect, judged.because),
        })
        .collect()
}

/// `counter_front by ann: reachable 9.2 mm, comfort 3.76`.
fn verdict_words(entry: &TaskReport) -> String {
    let answer = entry.answer();
    let mut text = format!("{}: {}", answer.label(), answer.verdict);
    let shown: Vec<String> = (answer.figures.iter())
        .filter(|f| matches!(f.name, "distance" | "comfort"))
        .map(|f| match f.name {
            "distance" => format!("{:.1} {}", f.value, f.unit),
            name => format!("{name} {:.2}", f.value),
        })
        .collect();
    if answer.ok && !shown.is_empty() {
        text.push_str(&format!(" {}", shown.join(", ")));
    }
    text
}
