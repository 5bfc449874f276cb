//! The `gaze_map` task: which points of a surface can this person see well
//! enough? A map (`map.rs`) whose points are gazes (`gaze.rs`): each
//! point of the grid is looked at from wherever the base fits, and counts
//! when an object of `size` there is legible, on the line of sight and
//! not hidden.

use super::common::{chain_of, Reaching};
use super::gaze::{needs_look_link, with_look_range, GazeObstacles, GazeSettings, Looked, Looking};
use super::grid_settings::GridSettings;
use super::map_grid::{run_map, MapAsked};
use crate::error::ErrorKind;
use crate::kinematics::Chain;
use crate::plugin::{
    Dependence, EffectorNeed, Options, ParamSpec, Params, Placement, Plugin, Registry, Settings,
    SettingsError, Subject, SubjectKind, Task, TaskInput, TaskPlugin, Tries,
};
use crate::report::TaskReport;

/// The plugin `gaze_map`.
pub struct GazeMap;

/// Its settings: a gaze's at each point, and the grid's.
struct GazeMapSettings(GazeSettings, GridSettings);

impl Settings for GazeMapSettings {
    fn visit(p: &mut Params<'_>) -> Self {
        let gaze = GazeSettings::visit(p, "point");
        GazeMapSettings(gaze, GridSettings::visit(p))
    }
}

impl Plugin for GazeMap {
    fn name(&self) -> &'static str {
        "gaze_map"
    }

    fn doc(&self) -> &'static str {
        "which points of a surface the person can see (legible, in sight, not hidden), on a grid"
    }

    fn params(&self) -> Vec<ParamSpec> {
        GazeMapSettings::params()
    }
}

impl TaskPlugin for GazeMap {
    fn subject(&self) -> SubjectKind {
        SubjectKind::Surface
    }

    fn configure(
        &self,
        options: &Options,
        plugins: &Registry,
    ) -> Result<Box<dyn Task>, SettingsError> {
        let GazeMapSettings(gaze, grid) = GazeMapSettings::from_options(options)?;
        Ok(Box::new(GazeMapTask {
            reaching: Reaching::new(gaze.common, plugins)?,
            looking: gaze.looking,
            grid,
        }))
    }
}

/// A configured gaze map.
struct GazeMapTask {
    reaching: Reaching,
    looking: Looking,
    grid: GridSettings,
}

impl Task for GazeMapTask {
    fn effectors(&self) -> Vec<EffectorNeed> {
        vec![self.reaching.effector_need()]
    }

    fn validate(&self, subject: &Subject<'_>) -> Option<ErrorKind> {
        self.looking
            .eyes(None)
            .illegible()
            .or_else(|| self.grid.too_large(subject))
    }

    fn validate_chain(&self, person: &str, _need: usize, chain: &Chain) -> Option<ErrorKind> {
        needs_look_link(person, chain)
    }

    fn points(&self, subject: &Subject<'_>) -> u64 {
        self.grid.points(subject)
    }

    fn starts_per_point(&self, placements: Tries) -> u64 {
        self.reaching.starts_per_point(placements.without_rest())
    }

    /// Its obstacles are asked about through `Reaching::obstacles` (and
    /// finding why marks those it ranks), its floor through its base.
    fn records_touches(&self) -> bool {
        true
    }

    fn dependence(&self, input: &TaskInput<'_>) -> Dependence {
        let eyes = self.looking.eyes(Some(&input.person.vision));
        let chain = with_look_range(
            &chain_of(input, 0),
            eyes.aimed_mm(self.reaching.common.tolerance_mm),
        );
        let points = self.grid.points_mm(&input.subject);
        self.reaching.dependence(&chain, &[&chain], points, true)
    }

    fn run(&self, input: &TaskInput<'_>) -> TaskReport {
        let eyes = self.looking.eyes(Some(&input.person.vision));
        let chain = with_look_range(
            &chain_of(input, 0),
            eyes.aimed_mm(self.reaching.common.tolerance_mm),
        );
        let obstacles = GazeObstacles::new(input, &self.reaching);
        let tolerance_mm = self.reaching.common.tolerance_mm;
        let judge = |placement: &Placement, target| {
            let looked = Looked {
                chain: &chain,
                placement,
                target,
            };
            looked.see(&obstacles, tolerance_mm, &eyes).reason.is_none()
        };
        let asked = MapAsked {
            reaching: &self.reaching,
            grid: &self.grid,
            chain: &chain,
            obstacles: obstacles.body.as_ref(),
            of: "gaze",
            lift_mm: nalgebra::Vector3::zeros(),
            why: false,
            settled: None,
        };
        run_map(input, &asked, &judge)
    }
}
