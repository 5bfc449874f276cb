//! The `text` format: a table a person scans in seconds, then one line of
//! detail per task (where the base stood, the posture).

use std::fmt::Write;

use crate::plugin::{FormatPlugin, ParamSpec, Plugin};
use crate::report::{BaseReport, GazeReport, MapReport, Posture, ReachReport, Report, TaskReport};

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
    fn render(&self, report: &Report) -> String {
        let mut out = String::new();
        let ok = report.tasks.iter().filter(|t| t.ok()).count();
        let _ = writeln!(
            out,
            "{}: {} tasks, {} ok\n",
            report.file,
            report.tasks.len(),
            ok
        );
        out.push_str(&table(report));
        for task in &report.tasks {
            match task {
                TaskReport::Reach(r) => detail(&mut out, r),
                TaskReport::Gaze(g) => gaze_detail(&mut out, g),
                TaskReport::ReachAndGaze(b) => {
                    detail(&mut out, &b.reach);
                    gaze_detail(&mut out, &b.gaze);
                }
                TaskReport::Map(m) => map_detail(&mut out, m),
            }
        }
        out
    }

    fn extension(&self) -> &'static str {
        "txt"
    }
}

fn table(report: &Report) -> String {
    let header = [
        "task", "target", "person", "result", "distance", "sweeps", "comfort",
    ];
    let rows: Vec<[String; 7]> = report
        .tasks
        .iter()
        .map(|t| match t {
            TaskReport::Reach(r) => [
                "reach".to_string(),
                r.name.clone(),
                r.person.clone(),
                if r.ok {
                    "reachable".into()
                } else {
                    "NOT reachable".into()
                },
                format!("{:.1} mm", r.distance_mm),
                r.iterations.to_string(),
                format!("{:.2}", r.comfort),
            ],
            TaskReport::ReachAndGaze(b) => [
                "reach+gaze".to_string(),
                b.name.clone(),
                b.person.clone(),
                format!(
                    "{}, {}",
                    if b.reach.ok {
                        "reachable"
                    } else {
                        "NOT reachable"
                    },
                    gaze_result(&b.gaze)
                ),
                format!("{:.1} mm", b.reach.distance_mm),
                b.reach.iterations.to_string(),
                format!("{:.2}", b.reach.comfort),
            ],
            TaskReport::Gaze(g) => [
                "gaze".to_string(),
                g.name.clone(),
                g.person.clone(),
                gaze_result(g),
                format!("{:.1} mm", g.distance_mm),
                "-".into(),
                format!("{:.2}", g.comfort),
            ],
            TaskReport::Map(m) => [
                if m.of == "gaze" { "gaze_map" } else { "map" }.to_string(),
                m.name.clone(),
                m.person.clone(),
                format!(
                    "{:.1} % of {} {}",
                    m.fraction * 100.0,
                    m.points,
                    if m.of == "gaze" { "seen" } else { "reached" }
                ),
                "-".into(),
                "-".into(),
                "-".into(),
            ],
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
            if i >= 4 {
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

/// `NAME VERB PERSON (SOLVER): KIND base at (x, y, z) mm, heading h deg`.
fn placed_line(out: &mut String, what: [&str; 4], b: &BaseReport) {
    let [name, verb, person, solver] = what;
    let _ = writeln!(
        out,
        "\n{name} {verb} {person} ({solver}): {} base at ({:.0}, {:.0}, {:.0}) mm, heading {:.0} deg",
        b.kind, b.x_mm, b.y_mm, b.z_mm, b.heading_deg
    );
}

/// `  posture (UNITS): joint value, ...`.
fn posture_line(out: &mut String, units: &str, posture: &Posture) {
    let values: Vec<String> = posture
        .0
        .iter()
        .map(|(j, v)| format!("{j} {v:.1}"))
        .collect();
    let _ = writeln!(out, "  posture ({units}): {}", values.join(", "));
}

fn detail(out: &mut String, r: &ReachReport) {
    placed_line(out, [&r.name, "by", &r.person, &r.solver], &r.base);
    posture_line(out, "deg", &r.posture);
    if let Some(obstacle) = &r.collision {
        let _ = writeln!(out, "  a link passes through `{obstacle}`");
    }
}

/// `visible`, or why not.
fn gaze_result(g: &GazeReport) -> String {
    match g.reason {
        None => "visible".into(),
        Some("occluded") => format!(
            "NOT visible: behind {}",
            g.occluded_by.as_deref().unwrap_or("?")
        ),
        Some(reason) => format!("NOT visible: {reason}"),
    }
}

fn gaze_detail(out: &mut String, g: &GazeReport) {
    placed_line(out, [&g.name, "seen by", &g.person, &g.solver], &g.base);
    let _ = writeln!(
        out,
        "  eyes at ({:.0}, {:.0}, {:.0}) mm, {:.0} mm from the target (legible for {:.0} mm from {:.0} to {:.0} mm), {:.1} deg off the line of sight (acuity {:.2}, needs {:.2})",
        g.eyes_mm[0],
        g.eyes_mm[1],
        g.eyes_mm[2],
        g.distance_mm,
        g.size_mm,
        g.legible_mm[0],
        g.legible_mm[1],
        g.off_axis_deg,
        g.acuity,
        g.acuity_threshold
    );
    if let Some(obstacle) = &g.occluded_by {
        let _ = writeln!(out, "  the line of sight meets `{obstacle}`");
    }
    posture_line(out, "deg; look in mm", &g.posture);
}

fn map_detail(out: &mut String, m: &MapReport) {
    let heights = match m.reachable_heights_mm {
        Some([lo, hi]) if m.of == "gaze" => format!("seen at heights {lo:.0} to {hi:.0} mm"),
        Some([lo, hi]) => format!("reachable heights {lo:.0} to {hi:.0} mm"),
        None if m.of == "gaze" => "nothing seen".to_string(),
        None => "nothing reachable".to_string(),
    };
    let retried = match m.retried {
        0 => String::new(),
        n => format!("; {n} only on the retry where obstacles blocked"),
    };
    let _ = writeln!(
        out,
        "\n{} by {} ({} base): {} of {} points {} ({:.1} %{}), {}; {} view, {} x {} cells of {:.0} mm",
        m.name,
        m.person,
        m.base,
        m.reachable,
        m.points,
        if m.of == "gaze" { "seen" } else { "reachable" },
        m.fraction * 100.0,
        retried,
        heights,
        m.view,
        m.columns,
        m.rows,
        m.step_mm
    );
}
