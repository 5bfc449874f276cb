//! The incremental coordinate solver of the accessibility paper (section
//! 5.2): each joint in turn is nudged by +/-Inc(i), Inc(i) = (Max(i) -
//! Min(i)) * rate, and a move is kept only if the effector gets closer to
//! the target and the joint stays within its limits. Every improvement of
//! section 5.3 is an option, on by default:
//! - `sign_memory`: the direction that worked last for a joint is tried first;
//! - `gamma`, `threshold`: eq. 2, the rate divided by gamma when a sweep
//!   improves the distance by less than the threshold;
//! - `incremental_fk`: the effector after a one-joint change at constant
//!   cost (eq. 6-8, [`crate::kinematics::IncrementalFk`]); off, the full
//!   product of the chain (the paper's variants A and B);
//! - `starts`: several starts (the neutral posture, then seeded random ones),
//!   keeping the most comfortable of those that reach (section 5.3.4).
//!
//! Two additions, both measured on the paper's chain (docs/benchmarks.md):
//! eq. 2 only ever shrinks the increment, and a descent whose sweeps improve
//! little stalls for good (53 % success from one start). The paper leaves
//! the adaptation open ("other adaptation functions could be applied"), so
//! each joint's increment also adapts on its own: times `grow` after a kept
//! move, times `shrink` after a miss (1 and 1 give the paper's behaviour).
//! And `eager_pair` evaluates both directions of a joint before choosing,
//! which gives the same answer but lets the processor overlap the two.
//! The descent itself is in `descent.rs`.

mod descent;

use crate::plugin::{
    fingerprint_of, work_ratio, IkProblem, IkSolution, Options, ParamSpec, Params, Plugin,
    Settings, SettingsError, Solver, SolverPlugin,
};
use crate::scene::Preferred;
use crate::solvers::starts::{neutral_start, Starts};

/// The plugin `incremental`.
pub struct Incremental;

/// The solver's settings, from its option block.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct IncrementalSettings {
    pub rate: f64,
    pub gamma: f64,
    pub threshold_mm: f64,
    pub min_rate: f64,
    pub sign_memory: bool,
    pub grow: f64,
    pub shrink: f64,
    pub eager_pair: bool,
    pub incremental_fk: bool,
    pub starts: u32,
    pub neutral_start: bool,
    pub stall: u32,
    pub stall_ratio: f64,
    pub max_sweeps: u32,
    pub avoid_obstacles: bool,
    pub steer_clear: bool,
}

impl Settings for IncrementalSettings {
    fn visit(p: &mut Params<'_>) -> Self {
        IncrementalSettings {
            rate: p
                .number("rate", 0.05, "first increment, as a fraction of each joint's range")
                .range(1e-6, 1.0)
                .get(),
            gamma: p
                .number(
                    "gamma",
                    3.0,
                    "eq. 2: divide the rate by this when a sweep stops improving (1: never)",
                )
                .range(1.0, 100.0)
                .get(),
            threshold_mm: p
                .length(
                    "threshold",
                    1.0,
                    "a sweep improving the distance less than this is not improving",
                )
                .range(0.0, 1000.0)
                .get(),
            min_rate: p
                .number(
                    "min_rate",
                    1e-5,
                    "stop once every increment is below this fraction of its range",
                )
                .range(1e-12, 1.0)
                .get(),
            sign_memory: p
                .boolean(
                    "sign_memory",
                    true,
                    "try first the direction that last worked for each joint",
                )
                .get(),
            grow: p
                .number(
                    "grow",
                    2.0,
                    "a joint's increment times this after a kept move (1: fixed)",
                )
                .range(1.0, 10.0)
                .get(),
            shrink: p
                .number(
                    "shrink",
                    0.5,
                    "a joint's increment times this after a miss (1: fixed)",
                )
                .range(0.01, 1.0)
                .get(),
            eager_pair: p
                .boolean(
                    "eager_pair",
                    true,
                    "evaluate both directions before choosing (same answer, faster)",
                )
                .get(),
            incremental_fk: p
                .boolean(
                    "incremental_fk",
                    true,
                    "effector after a one-joint change at constant cost (eq. 6-8)",
                )
                .get(),
            starts: p
                .integer(
                    "starts",
                    6,
                    "starting postures; the most comfortable that reaches is kept",
                )
                .range(1.0, 1000.0)
                .get() as u32,
            neutral_start: neutral_start(p),
            stall: p
                .integer(
                    "stall",
                    10,
                    "stop after this many sweeps in a row that did not improve",
                )
                .range(1.0, 1e5)
                .get() as u32,
            stall_ratio: p
                .number(
                    "stall_ratio",
                    0.001,
                    "a sweep improving the distance by less than this fraction did not",
                )
                .range(0.0, 1.0)
                .get(),
            max_sweeps: p
                .integer(
                    "max_sweeps",
                    1000,
                    "stop after this many sweeps over all joints",
                )
                .range(1.0, 1e5)
                .get() as u32,
            avoid_obstacles: p
                .boolean(
                    "avoid_obstacles",
                    true,
                    "a posture whose links pass through an obstacle does not count as reaching when choosing among starts",
                )
                .get(),
            steer_clear: p
                .boolean(
                    "steer_clear",
                    false,
                    "once a descent's posture is clear of obstacles and the body, it makes no move into one (slower per sweep)",
                )
                .get(),
        }
    }
}

impl Plugin for Incremental {
    fn name(&self) -> &'static str {
        "incremental"
    }

    fn doc(&self) -> &'static str {
        "incremental coordinate IK of the accessibility paper (sections 5.2-5.3)"
    }

    fn params(&self) -> Vec<ParamSpec> {
        IncrementalSettings::params()
    }
}

impl SolverPlugin for Incremental {
    fn build(&self, options: &Options) -> Result<Box<dyn Solver>, SettingsError> {
        Ok(Box::new(IncrementalSolver::new(
            IncrementalSettings::from_options(options)?,
        )))
    }
}

/// The configured solver.
pub struct IncrementalSolver {
    pub settings: IncrementalSettings,
    /// [`Solver::fingerprint`], worked out once.
    fingerprint: u64,
}

impl IncrementalSolver {
    /// The solver of `settings`.
    pub fn new(settings: IncrementalSettings) -> Self {
        IncrementalSolver {
            settings,
            fingerprint: fingerprint_of("incremental", &settings),
        }
    }
}

impl IncrementalSolver {
    /// The most comfortable posture that reaches over the starts, or the
    /// closest; with `first`, the first that reaches.
    fn over_starts(&self, problem: &IkProblem<'_>, first: bool) -> IkSolution {
        let starts = Starts::new(problem.chain, problem.seed, self.settings.neutral_start);
        let mut best = Preferred::new(problem.tolerance_mm);
        for start in starts.take(self.settings.starts as usize) {
            let solution = descent::descend(&self.settings, problem, start);
            let comfort = problem.chain.discomfort(&solution.q);
            best.offer(solution, comfort);
            if first && best.reaches() {
                break;
            }
        }
        best.into_kept()
            .unwrap_or_else(|| IkSolution::unsolved(problem.chain))
    }
}

impl Solver for IncrementalSolver {
    fn solve(&self, problem: &IkProblem<'_>) -> IkSolution {
        self.over_starts(problem, false)
    }

    fn solve_until_reached(&self, problem: &IkProblem<'_>) -> IkSolution {
        self.over_starts(problem, true)
    }

    fn solve_from(&self, problem: &IkProblem<'_>, mut start: Vec<f64>) -> IkSolution {
        // A start from elsewhere (a neighbour's posture, a sample) is
        // moved within this chain's limits and couplings first.
        problem.chain.pull_in(&mut start);
        descent::descend(&self.settings, problem, start)
    }

    fn starts(&self) -> u64 {
        u64::from(self.settings.starts.max(1))
    }

    fn work_per_start(&self) -> u64 {
        work_ratio(&[(f64::from(self.settings.max_sweeps), 1000.0)])
    }

    fn steers_clear(&self) -> bool {
        self.settings.steer_clear
    }

    /// Blind unless it steers clear: a plain descent looks at the room
    /// only to judge the posture it ends at.
    fn blind_to_room(&self) -> bool {
        !self.settings.steer_clear
    }

    /// One start, the neutral posture: no seed is drawn from.
    fn seeded(&self) -> bool {
        self.settings.starts > 1 || !self.settings.neutral_start
    }

    fn fingerprint(&self) -> Option<u64> {
        Some(self.fingerprint)
    }
}
