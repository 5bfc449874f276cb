//! An advice over a grid (`advise ... { along z ... across x ... }`): the
//! element moved along one axis at each position across another, each
//! line along an advice of its own ([`AdviceReport::rows`]). The grid as a
//! whole is told by the line that serves the most: its ranges, best and
//! standards are the grid's, and every line is beside it.

use std::fmt::Write as _;

use serde::Serialize;

use super::advice::runs;
use super::population::percent;
use super::{AdviceReport, TaskReport};

/// Where a line of a grid lies across.
#[derive(Clone, Debug, PartialEq, Serialize, schemars::JsonSchema)]
pub struct Across {
    /// The room's second axis the element moves along: `x`, `y` or `z`.
    pub axis: &'static str,
    /// The target's coordinate on that axis.
    pub at_mm: f64,
    /// Between two lines.
    pub step_mm: f64,
}

impl AdviceReport {
    /// The grid of `rows` (each line along, in order across; at least
    /// one): the line that serves the most, with every line beside it.
    pub fn grid(rows: Vec<AdviceReport>) -> AdviceReport {
        let mut whole = rows[best_row(&rows)].clone();
        whole.rows = rows;
        whole
    }

    /// Whether some line of the grid (or the one line) serves at least
    /// `share` at every position from `from_mm` to `to_mm` (within half a
    /// step), in words: that line's, or where none does, the words of the
    /// line that serves the most.
    pub fn serves_between(&self, share: f64, from_mm: f64, to_mm: f64) -> (bool, String) {
        if self.rows.is_empty() {
            return self.line_serves_between(share, from_mm, to_mm);
        }
        let at = |row: &AdviceReport, words: String| match &row.across {
            Some(a) => format!("at {} {} mm: {words}", a.axis, a.at_mm),
            None => words,
        };
        for row in &self.rows {
            let (ok, words) = row.line_serves_between(share, from_mm, to_mm);
            if ok {
                return (true, at(row, words));
            }
        }
        let (_, words) = self.line_serves_between(share, from_mm, to_mm);
        (
            false,
            format!("no line across serves it; {}", at(self, words)),
        )
    }

    /// One line per line of the grid: where across, its served ranges and
    /// its best position.
    pub(super) fn rows_lines(&self, out: &mut String) {
        for row in &self.rows {
            let Some(across) = &row.across else { continue };
            let served = format!("served {}", row.ranges_words());
            let tail = match (row.population, &row.best) {
                (true, Some(b)) => format!("; most {} at {} mm", percent(b.share), b.at_mm),
                (true, None) => "; no one reaches it".to_string(),
                (false, _) => String::new(),
            };
            let _ = writeln!(
                out,
                "  at {} {} mm: {served}{tail}",
                across.axis, across.at_mm
            );
        }
        if let Some(across) = &self.across {
            let _ = writeln!(
                out,
                "  the line that serves the most, at {} {} mm:",
                across.axis, across.at_mm
            );
        }
    }
}

/// The answers of `answers` (a population's people, in draw order) line
/// by line where the first advice among them is a grid: for each line,
/// each person's advice on that line (an answer that is not an advice as
/// it is); none where it is not a grid.
pub fn rows_of(answers: &[TaskReport]) -> Option<Vec<Vec<TaskReport>>> {
    let lines = answers.iter().find_map(|a| match a {
        TaskReport::Advice(advice) if !advice.rows.is_empty() => Some(advice.rows.len()),
        _ => None,
    })?;
    let line = |k: usize| -> Vec<TaskReport> {
        (answers.iter())
            .map(|a| match a {
                TaskReport::Advice(advice) => match advice.rows.get(k) {
                    Some(row) => TaskReport::Advice(Box::new(row.clone())),
                    None => a.clone(),
                },
                other => other.clone(),
            })
            .collect()
    };
    Some((0..lines).map(line).collect())
}

/// The line that serves the most: the highest best share, then the most
/// positions served; of lines as good, the middle of the longest run of
/// them (the first where two are as long).
fn best_row(rows: &[AdviceReport]) -> usize {
    let key = |row: &AdviceReport| {
        let best = row.best.as_ref().map_or(0, |b| b.reached);
        let served: usize = (row.ranges.iter())
            .map(|r| {
                (row.points.iter())
                    .filter(|p| p.at_mm >= r.from_mm && p.at_mm <= r.to_mm)
                    .count()
            })
            .sum();
        (best, served)
    };
    let Some(most) = rows.iter().map(key).max() else {
        return 0;
    };
    let longest = runs(rows.len(), |k| key(&rows[k]) == most)
        .into_iter()
        .fold(None::<(usize, usize)>, |kept, run| match kept {
            Some(k) if k.1 - k.0 >= run.1 - run.0 => Some(k),
            _ => Some(run),
        });
    longest.map_or(0, |(a, b)| (a + b) / 2)
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::report::advice::tests::frame;
    use crate::report::{AdviceFrame, PositionAnswer, ReportKind};

    fn line(at_mm: f64, bits: &[&str]) -> AdviceReport {
        let positions = [600.0, 700.0, 800.0, 900.0];
        let frame = AdviceFrame {
            across: Some(Across {
                axis: "x",
                at_mm,
                step_mm: 100.0,
            }),
            ..frame(&positions, 0.5)
        };
        let members: Vec<(String, Vec<PositionAnswer>)> = (bits.iter().enumerate())
            .map(|(k, b)| {
                let answers = (b.chars())
                    .map(|c| PositionAnswer {
                        reached: c == '1',
                        verdict: None,
                    })
                    .collect();
                (format!("p#{}", k + 1), answers)
            })
            .collect();
        AdviceReport::population(&frame, "p", &members)
    }

    #[test]
    fn a_grid_is_told_by_the_line_that_serves_the_most_and_every_line_is_beside_it() {
        let rows = vec![
            line(100.0, &["0110", "0010"]),
            line(200.0, &["0111", "0110"]),
            line(300.0, &["0111", "0111"]),
            line(400.0, &["0111", "0111"]),
            line(500.0, &["0000", "0000"]),
        ];
        let grid = AdviceReport::grid(rows);
        // 300 and 400 mm both serve everyone at three positions: the
        // first of the two middles.
        assert_eq!(grid.across.as_ref().unwrap().at_mm, 300.0);
        assert_eq!(grid.rows.len(), 5);
        assert_eq!(grid.best_target_mm(), Some([300.0, 500.0, 800.0]));
        // 700-800 mm serves 100 % somewhere across; 600 mm nowhere.
        assert!(grid.serves_between(1.0, 700.0, 900.0).0);
        let (ok, words) = grid.serves_between(0.5, 600.0, 700.0);
        assert!(!ok, "{words}");
        assert!(words.starts_with("no line across serves it"), "{words}");
        let mut out = String::new();
        grid.details(&mut out);
        assert!(out.contains("and across x in steps of 100 mm"), "{out}");
        assert!(out.contains("at x 500 mm: served nowhere"), "{out}");
        assert!(
            out.contains("the line that serves the most, at x 300 mm:"),
            "{out}"
        );
        let json = serde_json::to_value(&grid).unwrap();
        assert_eq!(json["rows"].as_array().unwrap().len(), 5);
        assert!(json["rows"][0].get("rows").is_none());
    }

    #[test]
    fn a_population_s_answers_are_split_line_by_line() {
        let person = |bits: &[&str]| {
            let rows = (bits.iter().zip([100.0, 200.0]))
                .map(|(b, at)| line(at, &[b]))
                .collect();
            TaskReport::Advice(Box::new(AdviceReport::grid(rows)))
        };
        let answers = vec![person(&["0110", "1111"]), person(&["0000", "0001"])];
        let lines = rows_of(&answers).unwrap();
        assert_eq!(lines.len(), 2);
        let TaskReport::Advice(second) = &lines[1][1] else {
            panic!("an advice")
        };
        assert_eq!(second.across.as_ref().unwrap().at_mm, 200.0);
        assert!(second.rows.is_empty());
        let one = line(100.0, &["0110"]);
        assert!(rows_of(&[TaskReport::Advice(Box::new(one))]).is_none());
    }
}
