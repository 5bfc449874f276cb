//! Plugins: solvers, bases, tasks and output formats. Each implements
//! [`Plugin`] (a name, a one-line doc and declared parameters) and the trait
//! of its kind; all are registered by name in one [`Registry`].

mod registry;

pub use registry::Registry;
// The data the traits speak of, so that a plugin needs one `use`.
pub use crate::options::{Options, ParamKind, ParamSpec, PluginConfig, PluginKind, Value};
pub use crate::scene::{BasePose, IkSolution, Placement};

use nalgebra::Point3;

use crate::collision::{Obstacles, PlacedObstacles};
use crate::kinematics::Chain;
use crate::report::{Report, TaskReport};
use crate::scene::{Room, Scenario, TaskSpec};

/// What every plugin declares.
pub trait Plugin: Send + Sync {
    fn name(&self) -> &'static str;
    /// One line for `reach plugins`.
    fn doc(&self) -> &'static str;
    /// The options its block accepts.
    fn params(&self) -> Vec<ParamSpec>;
}

// ------------------------------------------------------------------ solvers

/// An inverse kinematics problem: bring the chain's effector to a point
/// given in the chain's base frame.
#[derive(Clone, Copy)]
pub struct IkProblem<'a> {
    pub chain: &'a Chain,
    pub target_mm: Point3<f64>,
    pub tolerance_mm: f64,
    /// Seeds every random choice the solver makes.
    pub seed: u64,
    /// The room's obstacles, when links must stay out of them.
    pub obstacles: Option<PlacedObstacles<'a>>,
}

impl IkProblem<'_> {
    /// The first obstacle a link of posture `q` passes through (none when
    /// obstacles are not checked).
    pub fn collision(&self, q: &[f64]) -> Option<usize> {
        let obstacles = self.obstacles.as_ref()?;
        // The effector may rest on the target's surface: the last link
        // stops a tolerance (at least a millimetre) short of it.
        let gap_mm = self.tolerance_mm.max(1.0);
        obstacles.polyline_hit(&self.chain.link_points(q), gap_mm)
    }
}

/// A solver configured from its option block.
pub trait Solver: Send + Sync {
    fn solve(&self, problem: &IkProblem<'_>) -> IkSolution;
}

pub trait SolverPlugin: Plugin {
    fn build(&self, options: &Options) -> Box<dyn Solver>;
    /// How many starts one solve with these options runs at most (what
    /// the limit on solver starts counts): the option `starts` where the
    /// solver declares one, else 1.
    fn starts(&self, options: &Options) -> u64 {
        match options.get("starts") {
            Some(Value::Integer(n)) => (*n).max(1) as u64,
            _ => 1,
        }
    }
}

// ------------------------------------------------------------------ bases

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
}

pub trait BasePlugin: Plugin {
    fn build(&self, options: &Options) -> Box<dyn Base>;
}

// ------------------------------------------------------------------ tasks

/// Everything a task needs to run.
pub struct TaskContext<'a> {
    pub scenario: &'a Scenario,
    pub task: &'a TaskSpec,
    pub registry: &'a Registry,
    /// Where a long task reports its progress.
    pub progress: &'a dyn crate::progress::Progress,
}

pub trait TaskPlugin: Plugin {
    /// Whether the task's subjects are targets (reach, gaze) or surfaces
    /// (map); the checker resolves them accordingly.
    fn subject(&self) -> SubjectKind;
    /// A check of the task on its resolved subject beyond its options (a
    /// map too large, say); the checker reports it at the subject.
    fn validate(
        &self,
        _room: &Room,
        _subject: &str,
        _options: &Options,
    ) -> Option<crate::error::ErrorKind> {
        None
    }
    /// The options that name effectors of the person's mannequin (left
    /// out: the first effector); the checker makes sure each exists.
    /// How many reaches the task asks of `subject` (a map: its points);
    /// what the limit on solver starts counts.
    fn points(&self, _room: &Room, _subject: &str, _options: &Options) -> u64 {
        1
    }
    fn effector_options(&self) -> &'static [&'static str] {
        &["effector"]
    }
    /// A check of the task for one person's chain to the effector that
    /// option `option` names (a gaze needs a look link); reported at the
    /// person's name.
    fn validate_chain(
        &self,
        _person: &str,
        _option: &str,
        _chain: &Chain,
        _options: &Options,
    ) -> Option<crate::error::ErrorKind> {
        None
    }
    fn run(&self, ctx: &TaskContext<'_>) -> TaskReport;
}

#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum SubjectKind {
    /// A named target of a room.
    Target,
    /// A surface: a `surface` of a room or a face of a box (`counter.top`).
    Surface,
}

// ------------------------------------------------------------------ formats

pub trait FormatPlugin: Plugin {
    fn render(&self, report: &Report) -> String;
    /// The file extension when written with `--out`.
    fn extension(&self) -> &'static str;
}
