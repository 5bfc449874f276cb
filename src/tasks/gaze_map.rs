//! The `gaze_map` task: which points of a surface can this person see well
//! enough? A map (`map.rs`) whose points are gazes (`gaze.rs`): each
//! point of the grid is looked at from wherever the base fits, and counts
//! when an object of `size` there is legible, on the line of sight and
//! not hidden.

use super::common::Setup;
use super::gaze::{
    effective_vision, gaze_params, illegible, legible_mm, needs_look_link, see, with_look_range,
    GazeObstacles,
};
use super::map::{grid_params, grid_points, run_map, too_large};
use crate::error::ErrorKind;
use crate::kinematics::Chain;
use crate::plugin::{Options, ParamSpec, Placement, Plugin, SubjectKind, TaskContext, TaskPlugin};
use crate::report::TaskReport;
use crate::scene::Room;

/// The plugin `gaze_map`.
pub struct GazeMap;

impl Plugin for GazeMap {
    fn name(&self) -> &'static str {
        "gaze_map"
    }

    fn doc(&self) -> &'static str {
        "which points of a surface the person can see (legible, in sight, not hidden), on a grid"
    }

    fn params(&self) -> Vec<ParamSpec> {
        let mut params = gaze_params("point");
        params.extend(grid_params());
        params
    }
}

impl TaskPlugin for GazeMap {
    fn subject(&self) -> SubjectKind {
        SubjectKind::Surface
    }

    fn validate(&self, room: &Room, subject: &str, options: &Options) -> Option<ErrorKind> {
        illegible(&effective_vision(options, None)).or_else(|| too_large(room, subject, options))
    }

    fn points(&self, room: &Room, subject: &str, options: &Options) -> u64 {
        grid_points(room, subject, options)
    }

    fn validate_chain(
        &self,
        person: &str,
        _: &str,
        chain: &Chain,
        _: &Options,
    ) -> Option<ErrorKind> {
        needs_look_link(person, chain)
    }

    fn run(&self, ctx: &TaskContext<'_>) -> TaskReport {
        let setup = Setup::new(ctx);
        let options = &effective_vision(&ctx.task.options, Some(&setup.person.vision));
        let chain = with_look_range(&setup.chain, legible_mm(options));
        let (room, _) = ctx
            .scenario
            .surface(&ctx.task.subject)
            .expect("checked surface");
        let obstacles = GazeObstacles::new(room, &setup);
        let judge = |placement: &Placement, point| {
            see(&chain, placement, point, &obstacles, &setup, options)
                .reason
                .is_none()
        };
        run_map(ctx, &setup, &chain, obstacles.body.as_ref(), "gaze", &judge)
    }
}
