//! The `map` task: which points of a surface can this person reach? The
//! surface (a counter top, a cabinet front) is sampled at the centres of a
//! grid of cells `step` wide; each point is a reach from wherever the base
//! fits, solved in parallel (`map_grid.rs`). A map stops at the first
//! placement that reaches a point (in order of promise), where a reach task
//! compares all.

use nalgebra::Vector3;

use super::common::{chain_of, Common, CommonDecl, Reaching, INCREMENTAL, MAP_RETRY};
use super::grid_settings::GridSettings;
use super::map_grid::{run_map, MapAsked};
use crate::error::ErrorKind;
use crate::kinematics::Chain;
use crate::plugin::{
    Dependence, EffectorNeed, Options, ParamSpec, Params, Placement, Plugin, Registry, Settings,
    SettingsError, Subject, SubjectKind, Task, TaskInput, TaskPlugin, Tries,
};
use crate::report::TaskReport;

/// The plugin `map`.
pub struct Map;

/// Its settings: the common ones, the grid's, and whether to find why
/// each point not reached was not.
struct MapSettings(Common, GridSettings, bool);

impl Settings for MapSettings {
    fn visit(p: &mut Params<'_>) -> Self {
        let common = Common::visit(
            p,
            &CommonDecl {
                what: "point",
                seed_doc: "seeds the solver's random starts (mixed with where each point is from where the person stands, never with names or where the room is)",
                solver: INCREMENTAL,
                effector: None,
                retry: MAP_RETRY,
            },
        );
        let grid = GridSettings::visit(p);
        let why = p
            .boolean(
                "why",
                false,
                "find why each point not reached was not, as a reach's why is found (searched again without what may have stopped it): each such point costs about as much as a reach that fails",
            )
            .get();
        MapSettings(common, grid, why)
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
        let MapSettings(common, grid, why) = MapSettings::from_options(options)?;
        Ok(Box::new(MapTask {
            reaching: Reaching::new(common, plugins)?,
            grid,
            why,
        }))
    }
}

/// A configured map.
struct MapTask {
    reaching: Reaching,
    grid: GridSettings,
    why: bool,
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
        self.reaching.starts_per_point(placements.without_rest())
    }

    /// Its obstacles are asked about through `Reaching::obstacles` (and
    /// finding why marks those it ranks), its floor through its base.
    fn records_touches(&self) -> bool {
        true
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
        let obstacles = self.reaching.obstacles(input);
        let judge = |placement: &Placement, _| placement.solution.reaches(tolerance_mm);
        let asked = MapAsked {
            reaching: &self.reaching,
            grid: &self.grid,
            chain: &chain,
            obstacles: obstacles.as_ref(),
            of: "reach",
            lift_mm: hand_lift(&input.subject, &chain),
            why: self.why,
        };
        run_map(input, &asked, &judge)
    }
}

/// Where the hand's centre is when it touches a point of the surface: a
/// hand's radius out of it, on the side it is touched from (the hand lies
/// on a shelf; its centre, the grip, is above the board).
fn hand_lift(subject: &Subject<'_>, chain: &Chain) -> Vector3<f64> {
    match subject {
        Subject::Surface(s) => s.normal * chain.effector_link.radius_mm,
        Subject::Target(_) => Vector3::zeros(),
    }
}
