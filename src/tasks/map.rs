//! The `map` task: which points of a surface can this person reach? The
//! surface (a counter top, a cabinet front) is sampled at the centres of a
//! grid of cells `step` wide; each point is a reach from wherever the base
//! fits, solved in parallel (`map_grid.rs`). A map stops at the first
//! placement that reaches a point (in order of promise), where a reach task
//! compares all.

use nalgebra::Vector3;

use super::common::{Common, CommonDecl, Reaching, INCREMENTAL, MAP_RETRY};
use super::gaze::refuses_look_link;
use super::grid_settings::GridSettings;
use super::hand::{self, hands_of, Hand};
use super::map_grid::{map_report, MapAsked};
use crate::error::ErrorKind;
use crate::kinematics::{Body, Chain};
use crate::plugin::{
    Dependence, EffectorNeed, Options, ParamSpec, Params, Placement, Plugin, Registry, Settings,
    SettingsError, Subject, SubjectKind, Task, TaskInput, TaskPlugin, Tries,
};
use crate::report::{MapReport, TaskReport};

/// The plugin `map`.
pub struct Map;

/// Its settings: the common ones, the grid's, whether to find why each
/// point not reached was not, and which hand reaches.
struct MapSettings(Common, GridSettings, bool, Option<String>);

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
        MapSettings(common, grid, why, Hand::option(p, hand::HAND_DOC_FIRST))
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
        let MapSettings(mut common, grid, why, hand) = MapSettings::from_options(options)?;
        let either = Hand::resolve(hand.as_deref(), &mut common)?;
        Ok(Box::new(MapTask {
            reaching: Reaching::new(common, plugins)?,
            grid,
            why,
            either,
        }))
    }
}

/// A configured map: with the effector asked for alone, or `either`
/// hand (its twin too, where the mannequin has one, over the points the
/// first did not reach).
struct MapTask {
    reaching: Reaching,
    grid: GridSettings,
    why: bool,
    either: bool,
}

impl Task for MapTask {
    fn effectors(&self) -> Vec<EffectorNeed> {
        vec![self.reaching.effector_need()]
    }

    /// A hand's point: not a line of sight, whose look link would
    /// "reach" whatever is in view.
    fn validate_chain(&self, person: &str, _need: usize, chain: &Chain) -> Option<ErrorKind> {
        refuses_look_link(person, chain)
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

    /// Either hand: a search with each (the second only where the first
    /// did not reach, at most every point).
    fn searches(&self, body: &Body, effectors: &[usize]) -> u64 {
        hand::searches(body, effectors, self.either)
    }

    /// Its obstacles are asked about through `Reaching::obstacles` (and
    /// finding why marks those it ranks), its floor through its base.
    fn records_touches(&self) -> bool {
        true
    }

    fn dependence(&self, input: &TaskInput<'_>) -> Dependence {
        let chains: Vec<Chain> = self
            .hands(input)
            .map(|e| input.person.body.chain(e))
            .collect();
        let all: Vec<&Chain> = chains.iter().collect();
        let mut points = Vec::new();
        for chain in &chains {
            let lift = hand_lift(&input.subject, chain);
            points.extend(
                self.grid
                    .points_mm(&input.subject)
                    .into_iter()
                    .map(|p| p + lift),
            );
        }
        self.reaching.dependence(&chains[0], &all, points, false)
    }

    fn run(&self, input: &TaskInput<'_>) -> TaskReport {
        let Subject::Surface(surface) = input.subject else {
            unreachable!("the checker gives a map a surface")
        };
        let tolerance_mm = self.reaching.common.tolerance_mm;
        let obstacles = self.reaching.obstacles(input);
        let judge = |placement: &Placement, _| placement.solution.reaches(tolerance_mm);
        let mut report: Option<MapReport> = None;
        for effector in self.hands(input) {
            let chain = input.person.body.chain(effector);
            // The other hand maps what the first did not reach.
            let settled: Option<Vec<bool>> =
                (report.as_ref()).map(|r| r.cells.iter().map(|c| c.reachable).collect());
            let asked = MapAsked {
                reaching: &self.reaching,
                grid: &self.grid,
                chain: &chain,
                obstacles: obstacles.as_ref(),
                of: "reach",
                lift_mm: hand_lift(&input.subject, &chain),
                why: self.why,
                settled: settled.as_deref(),
            };
            let this = map_report(input, surface, &asked, &judge);
            report = Some(match report {
                None => this,
                Some(first) => first.with_other_hand(this),
            });
        }
        TaskReport::Map(report.expect("a map has at least one hand"))
    }
}

impl MapTask {
    /// The effectors (indices into the person's body) this map reaches
    /// with: the one asked for, and for `either` its twin.
    fn hands<'i>(&self, input: &'i TaskInput<'_>) -> impl Iterator<Item = usize> + 'i {
        let asked = input.effectors.first().copied().unwrap_or(0);
        hands_of(&input.person.body, asked, self.either).into_iter()
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
