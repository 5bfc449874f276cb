//! The format `advice`: for each target an `advise` task moves along a
//! line, the plot of who reaches it at each position (`advice_plot.rs`) as
//! SVG, and the shares as CSV, one column per group; for each advice over
//! a grid, its picture (`advice_grid_plot.rs`) and its shares as CSV, one
//! line per position. Written by `--out`.

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
        for grid in report.advice_grids() {
            let stem = format!("advice-{}-{}", clean(&grid.name), clean(&grid.who));
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
