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

use crate::plugin::{IkProblem, IkSolution, Options, ParamSpec, Plugin, Solver, SolverPlugin};
use crate::solvers::starts::Starts;

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
}

impl Plugin for Incremental {
    fn name(&self) -> &'static str {
        "incremental"
    }

    fn doc(&self) -> &'static str {
        "incremental coordinate IK of the accessibility paper (sections 5.2-5.3)"
    }

    fn params(&self) -> Vec<ParamSpec> {
        use ParamSpec as P;
        vec![
            P::number(
                "rate",
                0.05,
                "first increment, as a fraction of each joint's range",
            )
            .range(1e-6, 1.0),
            P::number(
                "gamma",
                3.0,
                "eq. 2: divide the rate by this when a sweep stops improving (1: never)",
            )
            .range(1.0, 100.0),
            P::length(
                "threshold",
                1.0,
                "a sweep improving the distance less than this is not improving",
            )
            .range(0.0, 1000.0),
            P::number(
                "min_rate",
                1e-5,
                "stop once every increment is below this fraction of its range",
            )
            .range(1e-12, 1.0),
            P::boolean(
                "sign_memory",
                true,
                "try first the direction that last worked for each joint",
            ),
            P::number(
                "grow",
                2.0,
                "a joint's increment times this after a kept move (1: fixed)",
            )
            .range(1.0, 10.0),
            P::number(
                "shrink",
                0.5,
                "a joint's increment times this after a miss (1: fixed)",
            )
            .range(0.01, 1.0),
            P::boolean(
                "eager_pair",
                true,
                "evaluate both directions before choosing (same answer, faster)",
            ),
            P::boolean(
                "incremental_fk",
                true,
                "effector after a one-joint change at constant cost (eq. 6-8)",
            ),
            P::integer(
                "starts",
                6,
                "starting postures; the most comfortable that reaches is kept",
            )
            .range(1.0, 1000.0),
            P::boolean(
                "neutral_start",
                true,
                "the first start is the neutral posture, the others random",
            ),
            P::integer(
                "stall",
                10,
                "stop after this many sweeps in a row that did not improve",
            )
            .range(1.0, 1e6),
            P::number(
                "stall_ratio",
                0.001,
                "a sweep improving the distance by less than this fraction did not",
            )
            .range(0.0, 1.0),
            P::integer(
                "max_sweeps",
                1000,
                "stop after this many sweeps over all joints",
            )
            .range(1.0, 1e6),
            P::boolean(
                "avoid_obstacles",
                true,
                "a posture whose links pass through an obstacle does not count as reaching when choosing among starts",
            ),
        ]
    }
}

impl SolverPlugin for Incremental {
    fn build(&self, o: &Options) -> Box<dyn Solver> {
        Box::new(IncrementalSolver {
            settings: IncrementalSettings {
                rate: o.number("rate"),
                gamma: o.number("gamma"),
                threshold_mm: o.length_mm("threshold"),
                min_rate: o.number("min_rate"),
                sign_memory: o.boolean("sign_memory"),
                grow: o.number("grow"),
                shrink: o.number("shrink"),
                eager_pair: o.boolean("eager_pair"),
                incremental_fk: o.boolean("incremental_fk"),
                starts: o.integer("starts") as u32,
                neutral_start: o.boolean("neutral_start"),
                stall: o.integer("stall") as u32,
                stall_ratio: o.number("stall_ratio"),
                max_sweeps: o.integer("max_sweeps") as u32,
                avoid_obstacles: o.boolean("avoid_obstacles"),
            },
        })
    }
}

/// The configured solver.
pub struct IncrementalSolver {
    pub settings: IncrementalSettings,
}

impl Solver for IncrementalSolver {
    fn solve(&self, problem: &IkProblem<'_>) -> IkSolution {
        let starts = Starts::new(problem.chain, problem.seed, self.settings.neutral_start);
        let mut best: Option<(IkSolution, f64)> = None;
        for start in starts.take(self.settings.starts as usize) {
            let solution = descent::descend(&self.settings, problem, start);
            let comfort = problem.chain.discomfort(&solution.q);
            if best.as_ref().is_none_or(|(b, b_comfort)| {
                solution.preferred_to(comfort, b, *b_comfort, problem.tolerance_mm)
            }) {
                best = Some((solution, comfort));
            }
        }
        best.expect("at least one start").0
    }
}
