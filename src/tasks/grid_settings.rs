//! A map's grid and its options (`step`, `max_points`,
//! `neighbour_starts`), shared by the `map` and `gaze_map` tasks.

use nalgebra::Point3;

use crate::error::ErrorKind;
use crate::plugin::{Params, Settings, Subject};

/// The grid's options: `step`, `max_points` and `neighbour_starts`.
#[derive(Clone, Copy, Debug, PartialEq)]
pub(super) struct GridSettings {
    pub step_mm: f64,
    pub max_points: u64,
    /// Whether each point is first tried from where the point before it
    /// in its row was reached, before the search a reach would make (and
    /// a point missed between two reached ones from each of them).
    pub neighbour_starts: bool,
}

impl Settings for GridSettings {
    fn visit(p: &mut Params<'_>) -> Self {
        GridSettings {
            step_mm: p
                .length("step", 50.0, "the grid's spacing on the surface")
                .range(1.0, 10_000.0)
                .get(),
            max_points: p
                .integer(
                    "max_points",
                    100_000,
                    "refuse maps with more points than this",
                )
                .range(1.0, 1e6)
                .get() as u64,
            neighbour_starts: p
                .boolean(
                    "neighbour_starts",
                    true,
                    "try each point first from the base and posture that reached the point before it in its row, and a point missed between two reached ones from each of them",
                )
                .get(),
        }
    }
}

impl GridSettings {
    /// How many points the grid of `subject` has (1 if it is not a
    /// surface), at most `u64::MAX`.
    pub fn points(&self, subject: &Subject<'_>) -> u64 {
        u64::try_from(self.exact_points(subject)).unwrap_or(u64::MAX)
    }

    /// The points counted in 128 bits, so that a message never shows a
    /// saturated count.
    fn exact_points(&self, subject: &Subject<'_>) -> u128 {
        let Subject::Surface(surface) = subject else {
            return 1;
        };
        let (columns, rows) = surface.grid_size(self.step_mm);
        columns as u128 * rows as u128
    }

    /// A map whose grid would have more than `max_points` points.
    pub fn too_large(&self, subject: &Subject<'_>) -> Option<ErrorKind> {
        let max = self.max_points;
        let points = self.exact_points(subject);
        (points > u128::from(max)).then(|| ErrorKind::TooLarge {
            what: format!("the map of `{}` ({points} points)", subject.name()),
            limit: format!("{max} points: raise `max_points` or the `step`"),
        })
    }

    /// The grid's points on `subject`.
    pub fn points_mm(&self, subject: &Subject<'_>) -> Vec<Point3<f64>> {
        match subject {
            Subject::Surface(s) => s
                .grid(self.step_mm)
                .cells
                .iter()
                .map(|c| c.point_mm)
                .collect(),
            Subject::Target(t) => vec![t.position_mm],
        }
    }
}
