//! The `text` format: a table a person scans in seconds (each task's
//! answer), then each task's lines of detail (where the base stood, the
//! posture).

use std::fmt::Write;

use crate::escape::{escaped, escaped_keeping};
use crate::plugin::{FormatPlugin, FormatScene, ParamSpec, Plugin};
use crate::report::{Answer, Report, TaskReport, EVALUATING, WORK_LIMIT};

pub struct Text;

impl Plugin for Text {
    fn name(&self) -> &'static str {
        "text"
    }

    fn doc(&self) -> &'static str {
        "a readable table of results, then the posture of each task"
    }

    fn params(&self) -> Vec<ParamSpec> {
        Vec::new()
    }
}

impl FormatPlugin for Text {
    fn files(&self, report: &Report, scene: &FormatScene<'_>) -> Vec<(String, Vec<u8>)> {
        let text = self.render(report, scene).unwrap_or_default();
        vec![("report.txt".into(), text.into_bytes())]
    }

    fn render(&self, report: &Report, _: &FormatScene<'_>) -> Option<String> {
        let answers = report.answers();
        let mut out = String::new();
        let ok = answers.iter().filter(|a| a.ok).count();
        let file = escaped(&report.file);
        let noun = if answers.len() == 1 { "task" } else { "tasks" };
        let unrun = |why: &str| {
            (report.tasks.iter())
                .filter(|t| matches!(t, TaskReport::NotEvaluated(n) if n.reason == why))
                .count()
        };
        let unrun = match (unrun(WORK_LIMIT), unrun(EVALUATING)) {
            (0, 0) => String::new(),
            (0, n) => format!(", {n} evaluating"),
            (n, _) => format!(", {n} not evaluated (work limit)"),
        };
        let _ = writeln!(out, "{file}: {} {noun}, {} ok{unrun}\n", answers.len(), ok);
        out.push_str(&table(&answers));
        // Said under the table, before the details: they bear on every
        // answer above.
        if !report.notes.is_empty() {
            out.push('\n');
            for note in &report.notes {
                let _ = writeln!(out, "note: {note}");
            }
        }
        for task in &report.tasks {
            task.details(&mut out);
        }
        if !report.advised_together.is_empty() {
            out.push('\n');
            for together in &report.advised_together {
                let _ = writeln!(out, "advised together: {}", together.words());
            }
        }
        expectations(report, &mut out);
        // Names are escaped where they come from (files, URDFs); this
        // keeps the terminal safe whatever a report carries.
        Some(escaped_keeping(&out, |c| c == '\n').into_owned())
    }
}

/// The scenario's expectations, met or not and why.
fn expectations(report: &Report, out: &mut String) {
    let all = &report.expectations;
    if all.is_empty() {
        return;
    }
    let missed = all.iter().filter(|e| !e.met).count();
    let _ = writeln!(
        out,
        "\nexpectations: {} met, {missed} NOT met",
        all.len() - missed
    );
    for e in all {
        let mark = if e.met { "met    " } else { "NOT met" };
        let _ = writeln!(out, "  {mark}  {}: {} ({})", e.expect, e.because, e.at);
    }
}

/// One row per answer: the effector it was found with (which hand), its
/// verdict, and its distance, sweeps and comfort where it has them.
fn table(answers: &[Answer]) -> String {
    let header = [
        "task", "target", "person", "effector", "result", "distance", "sweeps", "comfort",
    ];
    // An answer with no posture (no place to approach the target from)
    // has no distance, sweeps or comfort to show.
    let shown = |a: &Answer, name: &str, show: fn(f64) -> String| {
        let placed = a.figure("distance").is_none_or(|f| f.value.is_finite());
        a.figure(name)
            .filter(|_| placed)
            .map_or("-".to_string(), |f| show(f.value))
    };
    let rows: Vec<[String; 8]> = answers
        .iter()
        .map(|a| {
            [
                a.task.to_string(),
                a.subject.clone(),
                a.person.clone(),
                a.effector.clone().unwrap_or_else(|| "-".into()),
                a.verdict.clone(),
                shown(a, "distance", |v| format!("{v:.1} mm")),
                shown(a, "sweeps", |v| format!("{v}")),
                shown(a, "comfort", |v| format!("{v:.2}")),
            ]
        })
        .collect();
    let mut widths = header.map(str::len);
    for row in &rows {
        for (w, cell) in widths.iter_mut().zip(row) {
            *w = (*w).max(cell.chars().count());
        }
    }
    let mut out = String::new();
    let line = |cells: &[String], out: &mut String| {
        let mut s = String::new();
        for (i, cell) in cells.iter().enumerate() {
            let pad = widths[i] - cell.chars().count();
            // Text columns to the left, numbers to the right.
            if i >= 5 {
                s.push_str(&" ".repeat(pad));
                s.push_str(cell);
            } else {
                s.push_str(cell);
                s.push_str(&" ".repeat(pad));
            }
            s.push_str("  ");
        }
        out.push_str(s.trim_end());
        out.push('\n');
    };
    line(&header.map(String::from), &mut out);
    for row in &rows {
        line(row, &mut out);
    }
    out
}
