//! Bases: where the person stands or sits. A configured base is prepared
//! for a room and a chain, then asked to reach: it chooses candidate
//! placements and asks a solver for the posture from each.

use nalgebra::Point3;

use super::{IkProblem, Options, Plugin, SettingsError, Solver};
use crate::collision::{Obstacles, PlacedObstacles};
use crate::kinematics::Chain;
use crate::scene::{BasePose, Placement, Room};

/// How hard a base looks for a placement.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Search {
    /// Every candidate placement: the most comfortable that reaches.
    MostComfortable,
    /// Candidates in order of promise until one reaches (for maps).
    FirstReaching,
}

/// One reach question for a prepared base.
#[derive(Clone, Copy)]
pub struct ReachQuery<'a> {
    pub target_room_mm: Point3<f64>,
    pub tolerance_mm: f64,
    pub seed: u64,
    pub search: Search,
    /// The room's obstacles, when links must stay out of them.
    pub obstacles: Option<&'a Obstacles>,
    /// Where no placement reaches, a second solver to try again with.
    pub retry: Option<Retry<'a>>,
}

/// A second try where the task's solver reaches from no placement (used
/// when obstacles are checked: a solver blind to them while it searches
/// can miss postures that go round them).
#[derive(Clone, Copy)]
pub struct Retry<'a> {
    pub solver: &'a dyn Solver,
    /// How many of the most promising placements are tried again.
    pub placements: usize,
}

impl ReachQuery<'_> {
    /// The problem in the base frame of a base standing at `pose`.
    pub fn problem<'c>(&'c self, chain: &'c Chain, pose: BasePose) -> IkProblem<'c> {
        IkProblem {
            chain,
            target_mm: pose.to_base(&self.target_room_mm),
            tolerance_mm: self.tolerance_mm,
            seed: self.seed,
            obstacles: self.obstacles.map(|obstacles| PlacedObstacles {
                obstacles,
                base_pose: pose,
            }),
        }
    }

    /// Solve from `pose`; the collision is checked here whatever the
    /// solver did, so that no solver can report a posture through a box.
    pub fn solve_at(&self, chain: &Chain, pose: BasePose, solver: &dyn Solver) -> Placement {
        let problem = self.problem(chain, pose);
        let mut solution = solver.solve(&problem);
        solution.collision = problem.collision(&solution.q);
        Placement {
            pose,
            solution,
            retried: false,
        }
    }

    /// This query with another seed, so that a retry by the same solver
    /// starts from other postures.
    pub fn retried(&self) -> Self {
        ReachQuery {
            seed: self.seed ^ 0x7e72_1ed5_0000_0001,
            ..*self
        }
    }
}

/// A base configured from its option block: it decides where the person
/// stands (or sits).
pub trait Base: Send + Sync {
    /// Whether the base can be anywhere in the room at all; the checker
    /// refuses a task whose base fits nowhere.
    fn fits(&self, room: &Room) -> bool;
    /// Get ready for reaches in `room` with `chain` (caching what does not
    /// depend on the target, such as where the base fits).
    fn prepare<'a>(&'a self, room: &'a Room, chain: &'a Chain) -> Box<dyn PreparedBase + 'a>;
    /// The most candidate placements one reach may try (what the limit on
    /// solver starts counts).
    fn placements(&self) -> u64 {
        1
    }
}

/// A base ready for one room and one chain.
pub trait PreparedBase: Send + Sync {
    /// Place the base for the target and ask the solver for the posture.
    fn reach(&self, query: &ReachQuery<'_>, solver: &dyn Solver) -> Placement;
    /// The placements a reach of `target_room_mm` may try, the most
    /// promising first (what a cache compares to know that a change of
    /// the room leaves them alone).
    fn candidates(&self, target_room_mm: &Point3<f64>) -> Vec<BasePose>;
}

pub trait BasePlugin: Plugin {
    /// The base that validated `options` configure.
    fn build(&self, options: &Options) -> Result<Box<dyn Base>, SettingsError>;
}
