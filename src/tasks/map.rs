//! The `map` task: which points of a surface can this person reach? The
//! surface (a counter top, a cabinet front) is sampled at the centres of a
//! grid of cells `step` wide; each point is a reach from wherever the base
//! fits, solved in parallel. A map stops at the first placement that
//! reaches a point (in order of promise), where a reach task compares all.

use nalgebra::{Point3, Vector3};
use rayon::prelude::*;

use super::common::{chain_of, mix_seed, Common, CommonDecl, Reaching, INCREMENTAL, MAP_RETRY};
use crate::collision::{KeptProofs, Obstacles};
use crate::error::ErrorKind;
use crate::kinematics::Chain;
use crate::plugin::{
    Dependence, EffectorNeed, Options, ParamSpec, Params, Placement, Plugin, ReachQuery, Registry,
    Search, Settings, SettingsError, Subject, SubjectKind, Task, TaskInput, TaskPlugin, Tries,
};
use crate::report::{MapCell, MapReport, TaskReport};
use crate::scene::{GridCell, Surface};

/// The plugin `map`.
pub struct Map;

/// The grid's options: `step`, `max_points` and `neighbour_starts`.
#[derive(Clone, Copy, Debug, PartialEq)]
pub(super) struct GridSettings {
    pub step_mm: f64,
    pub max_points: u64,
    /// Whether each point is first tried from where the point before it
    /// in its row was reached, before the search a reach would make.
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
                    "try each point first from the base and posture that reached the point before it in its row",
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

/// Its settings: the common ones and the grid's.
struct MapSettings(Common, GridSettings);

impl Settings for MapSettings {
    fn visit(p: &mut Params<'_>) -> Self {
        let common = Common::visit(
            p,
            &CommonDecl {
                what: "point",
                seed_doc: "seeds the solver's random starts (mixed with surface, person and cell)",
                solver: INCREMENTAL,
                effector: None,
                retry: MAP_RETRY,
            },
        );
        MapSettings(common, GridSettings::visit(p))
    }
}

impl Plugin for Map {
    fn name(&self) -> &'static str {
        "map"
    }

    fn doc(&self) -> &'static str {
        "which points of a surface the person can reach, on a grid"
    }

    fn params(&self) -> Vec<ParamSpec> {
        MapSettings::params()
    }
}

impl TaskPlugin for Map {
    fn subject(&self) -> SubjectKind {
        SubjectKind::Surface
    }

    fn configure(
        &self,
        options: &Options,
        plugins: &Registry,
    ) -> Result<Box<dyn Task>, SettingsError> {
        let MapSettings(common, grid) = MapSettings::from_options(options)?;
        Ok(Box::new(MapTask {
            reaching: Reaching::new(common, plugins)?,
            grid,
        }))
    }
}

/// A configured map.
struct MapTask {
    reaching: Reaching,
    grid: GridSettings,
}

impl Task for MapTask {
    fn effectors(&self) -> Vec<EffectorNeed> {
        vec![self.reaching.effector_need()]
    }

    fn validate(&self, subject: &Subject<'_>) -> Option<ErrorKind> {
        self.grid.too_large(subject)
    }

    fn points(&self, subject: &Subject<'_>) -> u64 {
        self.grid.points(subject)
    }

    fn starts_per_point(&self, placements: Tries) -> u64 {
        self.reaching.starts_per_point(placements)
    }

    fn dependence(&self, input: &TaskInput<'_>) -> Dependence {
        let chain = chain_of(input, 0);
        let lift = hand_lift(&input.subject, &chain);
        let points = self
            .grid
            .points_mm(&input.subject)
            .into_iter()
            .map(|p| p + lift)
            .collect();
        self.reaching.dependence(&chain, &[&chain], points, false)
    }

    fn run(&self, input: &TaskInput<'_>) -> TaskReport {
        let tolerance_mm = self.reaching.common.tolerance_mm;
        let chain = chain_of(input, 0);
        let obstacles = self.reaching.obstacles(input.room);
        let judge = |placement: &Placement, _| placement.solution.reaches(tolerance_mm);
        let asked = MapAsked {
            reaching: &self.reaching,
            grid: &self.grid,
            chain: &chain,
            obstacles: obstacles.as_ref(),
            of: "reach",
            lift_mm: hand_lift(&input.subject, &chain),
        };
        run_map(input, &asked, &judge)
    }
}

/// The most points of a row solved one after another, each from the
/// last: the rest of the row is another run, solved in parallel.
const RUN: usize = 32;

/// Where the hand's centre is when it touches a point of the surface: a
/// hand's radius out of it, on the side it is touched from (the hand lies
/// on a shelf; its centre, the grip, is above the board).
fn hand_lift(subject: &Subject<'_>, chain: &Chain) -> Vector3<f64> {
    match subject {
        Subject::Surface(s) => s.normal * chain.effector_link.radius_mm,
        Subject::Target(_) => Vector3::zeros(),
    }
}

/// Whether a point is reached (or seen), given where the base stood and
/// the posture found, and the point.
pub(super) type Judge<'a> = dyn Fn(&Placement, Point3<f64>) -> bool + Sync + 'a;

/// What a map (or a gaze map) asks of each point of its grid.
pub(super) struct MapAsked<'a> {
    pub reaching: &'a Reaching,
    pub grid: &'a GridSettings,
    /// The chain whose effector goes to each point.
    pub chain: &'a Chain,
    /// The obstacles its links keep out of.
    pub obstacles: Option<&'a Obstacles>,
    /// `reach` or `gaze`.
    pub of: &'static str,
    /// From each point of the surface to where the effector goes (a hand
    /// touches a point with its side, a hand's radius out of it; the eyes
    /// look at the point itself).
    pub lift_mm: Vector3<f64>,
}

/// A map of the task's surface: each point's placement found as for a
/// reach of the chain's effector, judged by `judge`.
pub(super) fn run_map(
    input: &TaskInput<'_>,
    asked: &MapAsked<'_>,
    judge: &Judge<'_>,
) -> TaskReport {
    let Subject::Surface(surface) = input.subject else {
        unreachable!("the checker gives a map a surface")
    };
    TaskReport::Map(map_report(input, surface, asked, judge))
}

/// The placement that reaches the point of `query` from where its
/// neighbour `last` stood and how it stood, if one does: one descent of
/// the task's solver; where the neighbour was reached only by the retry's
/// steering descents (round the body, not through it) and that descent
/// fails, one of those too.
fn from_neighbour(
    query: &ReachQuery<'_>,
    asked: &MapAsked<'_>,
    last: &Placement,
    counts: &dyn Fn(&Placement) -> bool,
) -> Option<Placement> {
    let solver = asked.reaching.solver.as_ref();
    let next = query.solve_from_at(asked.chain, last.pose, solver, last.solution.q.clone());
    if counts(&next) {
        return Some(next);
    }
    let retry = query.retry.filter(|_| last.retried)?;
    let start = last.solution.q.clone();
    let mut steered = query.solve_from_at(asked.chain, last.pose, retry.solver, start);
    steered.retried = true;
    counts(&steered).then_some(steered)
}

fn map_report(
    input: &TaskInput<'_>,
    surface: &Surface,
    asked: &MapAsked<'_>,
    judge: &Judge<'_>,
) -> MapReport {
    let person = input.person;
    let reaching = asked.reaching;
    let prepared = input.base.prepare(input.room, asked.chain);
    let grid = surface.grid(asked.grid.step_mm);
    input.progress.add_work(grid.cells.len() as u64);
    let solver = reaching.solver.as_ref();
    let proofs = KeptProofs::new(asked.chain, input.base.own_body());
    // Runs of a row in parallel; along a run, each point first tries on
    // from where the last point reached stood and how it stood (one solve,
    // few sweeps), then searches as a reach would. Runs, not whole rows,
    // so that a few hard rows (the lowest, where the legs are in the way)
    // do not keep one thread busy while the others wait.
    let runs: Vec<&[GridCell]> = grid
        .cells
        .chunks(grid.columns.max(1))
        .flat_map(|row| row.chunks(RUN))
        .collect();
    let cells: Vec<(MapCell, bool)> = runs
        .par_iter()
        // One run a piece of work: rayon splits a range only until it has
        // a few pieces per thread, and a piece not stolen is solved whole,
        // so the hard rows at the bottom could end on one thread.
        .with_max_len(1)
        .flat_map_iter(|row| {
            let mut last: Option<Placement> = None;
            row.iter()
                .map(|cell| {
                    let (column, row) = (cell.column.to_string(), cell.row.to_string());
                    let seed = mix_seed(
                        reaching.common.seed,
                        &[&surface.name, &person.name, &column, &row],
                    );
                    let query = reaching
                        .query(
                            cell.point_mm + asked.lift_mm,
                            seed,
                            Search::FirstReaching,
                            asked.obstacles,
                            input.base.own_body(),
                        )
                        .keeping_proofs(&proofs);
                    let on = last
                        .as_ref()
                        .filter(|_| asked.grid.neighbour_starts)
                        .filter(|p| prepared.admits(&p.pose, &query.target_room_mm))
                        .and_then(|p| {
                            from_neighbour(&query, asked, p, &|next| judge(next, cell.point_mm))
                        });
                    let placement = on.unwrap_or_else(|| prepared.reach(&query, solver));
                    input.progress.advance(1);
                    let counts = judge(&placement, cell.point_mm);
                    let retried = counts && placement.retried;
                    let cell = MapCell::new(cell, &placement, asked.chain, counts);
                    if counts {
                        last = Some(placement);
                    }
                    (cell, retried)
                })
                .collect::<Vec<_>>()
        })
        .collect();
    let retried = cells.iter().filter(|(_, retried)| *retried).count();
    let cells: Vec<MapCell> = cells.into_iter().map(|(cell, _)| cell).collect();
    let mut report = MapReport::new(
        surface,
        person,
        &reaching.common.solver.name,
        asked.grid.step_mm,
        reaching.common.tolerance_mm,
        &grid,
        cells,
    );
    report.of = asked.of;
    report.retried = retried;
    report
}
