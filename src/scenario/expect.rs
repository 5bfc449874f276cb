//! The scenario's expectations, resolved by the checker to the report's
//! entries they are about, and judged against a run's answers.

use super::Scenario;
use crate::report::{fixed, ExpectationReport, Figure, ReportKind, TaskReport};
use crate::syntax::ast::Comparison;

/// One `expect`, resolved.
#[derive(Clone, Debug)]
pub struct ExpectSpec {
    /// As written (`ann reaches kettle`).
    pub text: String,
    /// `file:line` where it is written.
    pub at: String,
    pub check: ExpectCheck,
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
}

impl Scenario {
    /// Every expectation judged against `reports` (the tasks', then the
    /// standards').
    pub fn judge(&self, reports: &[TaskReport]) -> Vec<ExpectationReport> {
        self.expectations.iter().map(|e| e.judge(reports)).collect()
    }
}

impl ExpectSpec {
    fn judge(&self, reports: &[TaskReport]) -> ExpectationReport {
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
                let value = match r {
                    TaskReport::Population(p) => p.share,
                    _ => 0.0,
                };
                (comparison.holds(value, *bound), r.answer().verdict)
            }),
            ExpectCheck::Meets { entries } => all(entries, reports, meets),
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
        .map(judged)
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
    let answer = match (report, sees) {
        (TaskReport::ReachAndGaze(rg), false) => rg.reach.answer(),
        (TaskReport::ReachAndGaze(rg), true) => rg.gaze.answer(),
        _ => report.answer(),
    };
    // How far short, where it is not reached (or seen).
    let words = match answer.figure("distance") {
        Some(Figure { value, .. }) if !answer.ok && value.is_finite() => {
            format!("{} ({value:.1} mm away)", answer.verdict)
        }
        _ => answer.verdict.clone(),
    };
    (answer.ok == wanted, words)
}

/// How much a map covers (0 to 1), in words.
fn covers(report: &TaskReport) -> (f64, String) {
    match report {
        TaskReport::Map(m) => (
            m.fraction,
            format!(
                "covers {:.1} % ({} of {} points)",
                m.fraction * 100.0,
                m.reachable,
                m.points
            ),
        ),
        TaskReport::Population(p) => {
            let cells = p.cells.as_deref().unwrap_or_default();
            let mean = cells.iter().map(|c| c.share).sum::<f64>() / cells.len().max(1) as f64;
            let mean = fixed(mean, 4);
            (
                mean,
                format!(
                    "covers {:.1} % (the mean of its points' shares)",
                    mean * 100.0
                ),
            )
        }
        other => (0.0, other.answer().verdict),
    }
}

/// Whether a standard's rules all hold, and which fail.
fn meets(report: &TaskReport) -> (bool, String) {
    let TaskReport::Standard(s) = report else {
        return (false, report.answer().verdict);
    };
    if s.ok {
        return (true, s.answer().verdict);
    }
    let failing: Vec<String> = s
        .room_rules
        .iter()
        .map(|r| (r, None))
        .chain(
            s.elements
                .iter()
                .flat_map(|e| e.rules.iter().map(move |r| (r, Some(e.name.as_str())))),
        )
        .filter(|(r, _)| !r.ok)
        .map(|(r, element)| match element {
            Some(e) => format!("{} {} at `{e}`", r.section, r.rule),
            None => format!("{} {}", r.section, r.rule),
        })
        .collect();
    let shown = failing
        .iter()
        .take(3)
        .cloned()
        .collect::<Vec<_>>()
        .join("; ");
    let more = match failing.len() {
        n if n > 3 => format!("; and {} more", n - 3),
        _ => String::new(),
    };
    (
        false,
        format!("{} of {} checks FAIL: {shown}{more}", s.failed, s.checks),
    )
}
