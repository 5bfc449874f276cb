//! The `map` task: which points of a surface can this person reach? The
//! surface (a counter top, a cabinet front) is sampled at the centres of a
//! grid of cells `step` wide; each point is a reach from wherever the base
//! fits, solved in parallel. A map stops at the first placement that
//! reaches a point (in order of promise), where a reach task compares all.

use rayon::prelude::*;

use super::common::{common_params, mix_seed, Setup};
use crate::collision::Obstacles;
use crate::error::ErrorKind;
use crate::kinematics::Chain;
use crate::plugin::Placement;
use crate::plugin::{Options, ParamSpec, Plugin, Search, SubjectKind, TaskContext, TaskPlugin};
use crate::report::{MapCell, MapReport, TaskReport};
use crate::scene::Room;
use nalgebra::Point3;

/// The plugin `map`.
pub struct Map;

impl Plugin for Map {
    fn name(&self) -> &'static str {
        "map"
    }

    fn doc(&self) -> &'static str {
        "which points of a surface the person can reach, on a grid"
    }

    fn params(&self) -> Vec<ParamSpec> {
        let mut params = common_params(
            "point",
            "seeds the solver's random starts (mixed with surface, person and cell)",
        );
        params.extend(grid_params());
        params
    }
}

/// The grid's options: `step` and `max_points`.
pub(super) fn grid_params() -> [ParamSpec; 2] {
    [
        ParamSpec::length("step", 50.0, "the grid's spacing on the surface").range(1.0, 10_000.0),
        ParamSpec::integer(
            "max_points",
            100_000,
            "refuse maps with more points than this",
        )
        .range(1.0, 1e8),
    ]
}

/// How many points the grid of a map of `subject` has (1 if `subject` is
/// not a surface of `room`).
pub(super) fn grid_points(room: &Room, subject: &str, options: &Options) -> u64 {
    room.surface_named(subject).map_or(1, |surface| {
        let (columns, rows) = surface.grid_size(options.length_mm("step"));
        (columns as u64).saturating_mul(rows as u64)
    })
}

/// A map whose grid would have more than `max_points` points.
pub(super) fn too_large(room: &Room, subject: &str, options: &Options) -> Option<ErrorKind> {
    let points = grid_points(room, subject, options);
    let max = options.integer("max_points") as u64;
    (points > max).then(|| ErrorKind::TooLarge {
        what: format!("the map of `{subject}` ({points} points)"),
        limit: format!("{max} points: raise `max_points` or the `step`"),
    })
}

impl TaskPlugin for Map {
    fn subject(&self) -> SubjectKind {
        SubjectKind::Surface
    }

    fn validate(&self, room: &Room, subject: &str, options: &Options) -> Option<ErrorKind> {
        too_large(room, subject, options)
    }

    fn points(&self, room: &Room, subject: &str, options: &Options) -> u64 {
        grid_points(room, subject, options)
    }

    fn run(&self, ctx: &TaskContext<'_>) -> TaskReport {
        let setup = Setup::new(ctx);
        let tolerance_mm = setup.tolerance_mm;
        let (room, _) = ctx
            .scenario
            .surface(&ctx.task.subject)
            .expect("checked surface");
        let obstacles = setup.obstacles(room);
        let judge = |placement: &Placement, _| placement.solution.reaches(tolerance_mm);
        run_map(
            ctx,
            &setup,
            &setup.chain,
            obstacles.as_ref(),
            "reach",
            &judge,
        )
    }
}

/// Whether a point is reached (or seen), given where the base stood and
/// the posture found, and the point.
pub(super) type Judge<'a> = dyn Fn(&Placement, Point3<f64>) -> bool + Sync + 'a;

/// A map of the task's surface with `chain`: each point's placement found
/// as for a reach of `chain`'s effector (links kept out of `obstacles`),
/// judged by `judge`.
pub(super) fn run_map(
    ctx: &TaskContext<'_>,
    setup: &Setup<'_>,
    chain: &Chain,
    obstacles: Option<&Obstacles>,
    of: &'static str,
    judge: &Judge<'_>,
) -> TaskReport {
    let task = ctx.task;
    let person = setup.person;
    let (room, surface) = ctx
        .scenario
        .surface(&task.subject)
        .expect("checked surface");
    let prepared = setup.base.prepare(room, chain);
    let step_mm = task.options.length_mm("step");
    let grid = surface.grid(step_mm);
    ctx.progress.add_work(grid.cells.len() as u64);
    let cells: Vec<(MapCell, bool)> = grid
        .cells
        .par_iter()
        .map(|cell| {
            let (column, row) = (cell.column.to_string(), cell.row.to_string());
            let query = setup.query(
                cell.point_mm,
                mix_seed(setup.seed, &[&task.subject, &person.name, &column, &row]),
                Search::FirstReaching,
                obstacles,
            );
            let placement = prepared.reach(&query, setup.solver.as_ref());
            ctx.progress.advance(1);
            let counts = judge(&placement, cell.point_mm);
            let cell = MapCell::new(cell, &placement, chain, counts);
            (cell, counts && placement.retried)
        })
        .collect();
    let retried = cells.iter().filter(|(_, retried)| *retried).count();
    let cells: Vec<MapCell> = cells.into_iter().map(|(cell, _)| cell).collect();
    let mut report = MapReport::new(
        &surface,
        person,
        setup.solver_name,
        step_mm,
        setup.tolerance_mm,
        &grid,
        cells,
    );
    report.of = of;
    report.retried = retried;
    TaskReport::Map(report)
}
