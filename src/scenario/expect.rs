//! The scenario's expectations, resolved by the checker to the report's
//! entries they are about, and judged against a run's answers.

use super::Scenario;
use crate::report::{ExpectationReport, Figure, TaskReport};
use crate::syntax::ast::Comparison;

/// One `expect`, resolved.
#[derive(Clone, Debug)]
pub struct ExpectSpec {
    /// As written (`ann reaches kettle`).
    pub text: String,
    /// `file:line` where it is written.
    pub at: String,
    pub check: ExpectCheck,
    /// The `expect` declaration.
    pub span: crate::span::Span,
}

/// What an expectation asks of which report entries (by index: the tasks,
/// then the standards).
#[derive(Clone, Debug)]
pub enum ExpectCheck {
    /// Each entry reaches (or, `sees`, sees) the target, or (`wanted`
    /// false) does not.
    Answers {
        entries: Vec<usize>,
        sees: bool,
        wanted: bool,
    },
    /// Each map covers (a person's: the share of points reached; a
    /// population's: the mean of its points' shares) as compared.
    Covers {
        entries: Vec<usize>,
        comparison: Comparison,
        bound: f64,
    },
    /// Each population task's share, as compared.
    Share {
        entries: Vec<usize>,
        comparison: Comparison,
        bound: f64,
    },
    /// Each standard's rules all hold.
    Meets { entries: Vec<usize> },
    /// Each advice serves at least `share` at every position from
    /// `from_mm` to `to_mm`.
    Serves {
        entries: Vec<usize>,
        share: f64,
        from_mm: f64,
        to_mm: f64,
    },
}

impl Scenario {
    /// Every expectation judged against `reports` (the tasks', then the
    /// standards').
    pub fn judge(&self, reports: &[TaskReport]) -> Vec<ExpectationReport> {
        self.expectations.iter().map(|e| e.judge(reports)).collect()
    }
}

impl ExpectCheck {
    /// The report entries the expectation is about.
    pub fn entries(&self) -> &[usize] {
        match self {
            ExpectCheck::Answers { entries, .. }
            | ExpectCheck::Covers { entries, .. }
            | ExpectCheck::Share { entries, .. }
            | ExpectCheck::Meets { entries }
            | ExpectCheck::Serves { entries, .. } => entries,
        }
    }
}

impl ExpectSpec {
    pub(super) fn judge(&self, reports: &[TaskReport]) -> ExpectationReport {
        let (met, because) = match &self.check {
            ExpectCheck::Answers {
                entries,
                sees,
                wanted,
            } => all(entries, reports, |r| answered(r, *sees, *wanted)),
            ExpectCheck::Covers {
                entries,
                comparison,
                bound,
            } => all(entries, reports, |r| {
                let (value, words) = covers(r);
                (comparison.holds(value, *bound), words)
            }),
            ExpectCheck::Share {
                entries,
                comparison,
                bound,
            } => all(entries, reports, |r| {
                let value = r.share().unwrap_or(0.0);
                (comparison.holds(value, *bound), r.answer().verdict)
            }),
            ExpectCheck::Meets { entries } => all(entries, reports, meets),
            ExpectCheck::Serves {
                entries,
                share,
                from_mm,
                to_mm,
            } => all(entries, reports, |r| match r {
                TaskReport::Advice(a) => a.serves_between(*share, *from_mm, *to_mm),
                other => (false, other.answer().verdict),
            }),
        };
        ExpectationReport {
            expect: self.text.clone(),
            at: self.at.clone(),
            met,
            because,
        }
    }
}

/// Whether `judged` holds for every entry, and the words of the first that
/// does not (or of the first, if all do).
fn all(
    entries: &[usize],
    reports: &[TaskReport],
    judged: impl Fn(&TaskReport) -> (bool, String),
) -> (bool, String) {
    let results: Vec<(bool, String)> = entries
        .iter()
        .filter_map(|&k| reports.get(k))
        .map(|r| match r {
            // Nothing was found: no expectation of it is met, whatever
            // it wanted.
            TaskReport::NotEvaluated(_) => (false, r.answer().verdict),
            _ => judged(r),
        })
        .collect();
    match results.iter().find(|(ok, _)| !ok) {
        Some((_, words)) => (false, words.clone()),
        None => (
            !results.is_empty(),
            results.into_iter().next().map_or_else(String::new, |r| r.1),
        ),
    }
}

/// Whether `report` reaches (or sees) its target as `wanted`, and its
/// verdict with the distance left.
fn answered(report: &TaskReport, sees: bool, wanted: bool) -> (bool, String) {
    let answer = report.answer_of(sees);
    // How far short, where it is not reached (or seen).
    let words = match answer.figure("distance") {
        Some(Figure { value, .. }) if !answer.ok && value.is_finite() => {
            format!("{} ({value:.1} mm away)", answer.verdict)
        }
        _ => answer.verdict.clone(),
    };
    (answer.ok == wanted, words)
}

/// How much a map covers (0 to 1), in words (an entry with no points:
/// nothing, and its verdict).
fn covers(report: &TaskReport) -> (f64, String) {
    report
        .coverage()
        .unwrap_or_else(|| (0.0, report.answer().verdict))
}

/// Whether a standard's rules all hold, and which fail (an entry with no
/// rules: not, and its verdict).
fn meets(report: &TaskReport) -> (bool, String) {
    report
        .rules_met()
        .unwrap_or_else(|| (false, report.answer().verdict))
}
