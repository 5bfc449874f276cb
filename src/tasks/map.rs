//! The `map` task: which points of a surface can this person reach? The
//! surface (a counter top, a cabinet front) is sampled at the centres of a
//! grid of cells `step` wide; each point is a reach from wherever the base
//! fits, solved in parallel. A map stops at the first placement that
//! reaches a point (in order of promise), where a reach task compares all.

use rayon::prelude::*;

use super::common::{common_params, mix_seed, Setup};
use crate::error::ErrorKind;
use crate::plugin::{
    Options, ParamSpec, Plugin, ReachQuery, Search, SubjectKind, TaskContext, TaskPlugin,
};
use crate::report::{MapCell, MapReport, TaskReport};
use crate::scene::Room;

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
        params.extend([
            ParamSpec::length("step", 50.0, "the grid's spacing on the surface")
                .range(1.0, 10_000.0),
            ParamSpec::integer(
                "max_points",
                100_000,
                "refuse maps with more points than this",
            )
            .range(1.0, 1e8),
        ]);
        params
    }
}

impl TaskPlugin for Map {
    fn subject(&self) -> SubjectKind {
        SubjectKind::Surface
    }

    fn validate(&self, room: &Room, subject: &str, options: &Options) -> Option<ErrorKind> {
        let surface = room.surface_named(subject)?;
        let (columns, rows) = surface.grid_size(options.length_mm("step"));
        let points = columns.saturating_mul(rows);
        let max = options.integer("max_points") as usize;
        (points > max).then(|| ErrorKind::TooLarge {
            what: format!("the map of `{subject}` ({points} points)"),
            limit: format!("{max} points: raise `max_points` or the `step`"),
        })
    }

    fn run(&self, ctx: &TaskContext<'_>) -> TaskReport {
        let task = ctx.task;
        let setup = Setup::new(ctx);
        let person = setup.person;
        let (room, surface) = ctx
            .scenario
            .surface(&task.subject)
            .expect("checked surface");
        let prepared = setup.base.prepare(room, &setup.chain);
        let obstacles = setup.obstacles(room);
        let step_mm = task.options.length_mm("step");
        let grid = surface.grid(step_mm);
        ctx.progress.add_work(grid.cells.len() as u64);
        let cells: Vec<MapCell> = grid
            .cells
            .par_iter()
            .map(|cell| {
                let (column, row) = (cell.column.to_string(), cell.row.to_string());
                let query = ReachQuery {
                    target_room_mm: cell.point_mm,
                    tolerance_mm: setup.tolerance_mm,
                    seed: mix_seed(setup.seed, &[&task.subject, &person.name, &column, &row]),
                    search: Search::FirstReaching,
                    obstacles: obstacles.as_ref(),
                };
                let placement = prepared.reach(&query, setup.solver.as_ref());
                ctx.progress.advance(1);
                MapCell::new(cell, &placement, &setup.chain, setup.tolerance_mm)
            })
            .collect();
        let report = MapReport::new(
            &surface,
            person,
            setup.solver_name,
            step_mm,
            setup.tolerance_mm,
            &grid,
            cells,
        );
        TaskReport::Map(report)
    }
}
