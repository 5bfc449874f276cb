//! The format `advice`: for each target an `advise` task moves along a
//! line, the plot of who reaches it at each position (`advice_plot.rs`) as
//! SVG, and the shares as CSV, one column per group; for each advice over
//! a grid, its picture (`advice_grid_plot.rs`) and its shares as CSV, one
//! line per position (`advice-grid-TARGET-ZX-WHO`: along z, across x). Written by `--out`.

use std::fmt::Write;

use super::{advice_grid_plot, advice_plot};
use crate::plugin::{FormatPlugin, FormatScene, ParamSpec, Plugin};
use crate::report::{AdviceReport, Report};

/// The plugin `advice`.
pub struct AdviceFiles;

impl Plugin for AdviceFiles {
    fn name(&self) -> &'static str {
        "advice"
    }

    fn doc(&self) -> &'static str {
        "each advised target's plot (the share of each group who reach it at each position) as SVG, and its shares as CSV (--out only)"
    }

    fn params(&self) -> Vec<ParamSpec> {
        Vec::new()
    }
}

impl FormatPlugin for AdviceFiles {
    fn files(&self, report: &Report, _: &FormatScene<'_>) -> Vec<(String, Vec<u8>)> {
        let mut files = Vec::new();
        for (name, advices) in report.advices_by_target() {
            let stem = format!("advice-{}", clean(&name));
            files.push((
                format!("{stem}.svg"),
                advice_plot::svg(&advices).into_bytes(),
            ));
            files.push((format!("{stem}.csv"), csv(&advices).into_bytes()));
        }
        // `advice-grid-` keeps a grid's files apart from a line's (a
        // target's name has no `-`); two grids of one target by one group
        // along the same axes are numbered.
        let mut stems: Vec<String> = Vec::new();
        for grid in report.advice_grids() {
            let axes = format!(
                "{}{}",
                grid.along,
                grid.across.as_ref().map_or("", |a| a.axis)
            );
            let first = format!(
                "advice-grid-{}-{axes}-{}",
                clean(&grid.name),
                clean(&grid.who)
            );
            let mut stem = first.clone();
            for k in 2.. {
                if !stems.contains(&stem) {
                    break;
                }
                stem = format!("{first}-{k}");
            }
            stems.push(stem.clone());
            files.push((
                format!("{stem}.svg"),
                advice_grid_plot::svg(grid).into_bytes(),
            ));
            files.push((format!("{stem}.csv"), grid_csv(grid).into_bytes()));
        }
        files
    }

    fn render(&self, _: &Report, _: &FormatScene<'_>) -> Option<String> {
        None
    }

    fn prints(&self) -> bool {
        false
    }
}

fn clean(s: &str) -> String {
    s.replace(|c: char| !c.is_ascii_alphanumeric() && c != '_', "-")
}

/// One line per position of the first advice: the position, then each
/// group's share there (empty where its positions differ).
fn csv(advices: &[&AdviceReport]) -> String {
    let mut out = format!("{}_mm", advices[0].along);
    for a in advices {
        let _ = write!(out, ",{}", clean(&a.who));
    }
    out.push('\n');
    for point in &advices[0].points {
        let _ = write!(out, "{}", point.at_mm);
        for a in advices {
            let share = a.points.iter().find(|p| p.at_mm == point.at_mm);
            let _ = write!(
                out,
                ",{}",
                share.map_or(String::new(), |p| p.share.to_string())
            );
        }
        out.push('\n');
    }
    out
}

/// One line per position of the grid: across, along, how many reach it
/// there and the share.
fn grid_csv(grid: &AdviceReport) -> String {
    let across = grid.across.as_ref().map_or("across", |a| a.axis);
    let mut out = format!("{across}_mm,{}_mm,reached,share\n", grid.along);
    for row in &grid.rows {
        let at = row.across.as_ref().map_or(0.0, |a| a.at_mm);
        for p in &row.points {
            let _ = writeln!(out, "{at},{},{},{}", p.at_mm, p.reached, p.share);
        }
    }
    out
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::plugin::FormatScene;
    use crate::report::{Across, AdviceFrame, PositionAnswer, TaskReport};

    /// A grid of `name` by ann along `along`, across x.
    fn grid(name: &str, along: &'static str) -> TaskReport {
        let line = |at_mm: f64| {
            let frame = AdviceFrame {
                name: name.into(),
                base: "wheelchair".into(),
                carries: Vec::new(),
                along,
                target_mm: [300.0, 500.0, 900.0],
                declared_mm: 900.0,
                step_mm: 100.0,
                serves: 0.9,
                scan: "full",
                rescanned: 0,
                positions_mm: vec![800.0, 900.0],
                across: Some(Across {
                    axis: "x",
                    at_mm,
                    step_mm: 100.0,
                }),
            };
            let reached = PositionAnswer {
                reached: true,
                verdict: None,
            };
            AdviceReport::person(&frame, "ann", &[reached.clone(), reached])
        };
        TaskReport::Advice(Box::new(AdviceReport::grid(vec![line(200.0), line(300.0)])))
    }

    #[test]
    fn two_grids_of_one_target_by_one_person_are_written_apart() {
        let report = Report {
            schema: 1,
            file: "x".into(),
            notes: Vec::new(),
            tasks: vec![grid("jar", "z"), grid("jar", "z"), grid("jar", "y")],
            expectations: Vec::new(),
            advised_together: Vec::new(),
        };
        let files = AdviceFiles.files(&report, &FormatScene::empty());
        let names: Vec<&str> = files.iter().map(|(n, _)| n.as_str()).collect();
        assert_eq!(
            names,
            [
                "advice-grid-jar-zx-ann.svg",
                "advice-grid-jar-zx-ann.csv",
                "advice-grid-jar-zx-ann-2.svg",
                "advice-grid-jar-zx-ann-2.csv",
                "advice-grid-jar-yx-ann.svg",
                "advice-grid-jar-yx-ann.csv",
            ]
        );
    }
}
