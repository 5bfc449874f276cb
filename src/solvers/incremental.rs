//! The incremental coordinate solver of the accessibility paper (section
//! 5.2): each joint in turn is nudged by +/-Inc(i) = (Max(i) - Min(i)) *
//! rate, and the move is kept only if the effector gets closer to the target
//! and the joint stays within its limits. With sign memory the direction
//! that worked last is tried first; when a sweep over all joints improves
//! the distance by less than `threshold`, the rate is divided by `gamma`
//! (eq. 2). Several starts (the neutral posture, then seeded random ones) are
//! solved and the kept solution is the most comfortable of those that reach
//! (section 5.3.4).

use rand_chacha::rand_core::{Rng, SeedableRng};
use rand_chacha::ChaCha8Rng;

use crate::kinematics::Chain;
use crate::plugin::{IkProblem, IkSolution, Options, ParamSpec, Plugin, Solver, SolverPlugin};

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
    pub starts: u32,
    pub neutral_start: bool,
    pub max_sweeps: u32,
}

impl Plugin for Incremental {
    fn name(&self) -> &'static str {
        "incremental"
    }

    fn doc(&self) -> &'static str {
        "incremental coordinate IK of the accessibility paper (section 5.2), seeded random starts"
    }

    fn params(&self) -> Vec<ParamSpec> {
        vec![
            ParamSpec::number(
                "rate",
                0.5,
                "first increment as a fraction of each joint's range",
            )
            .range(1e-6, 1.0),
            ParamSpec::number(
                "gamma",
                3.0,
                "the rate is divided by this when a sweep stops improving (1: never)",
            )
            .range(1.0, 100.0),
            ParamSpec::length(
                "threshold",
                1.0,
                "a sweep that improves less than this counts as not improving",
            )
            .range(0.0, 1000.0),
            ParamSpec::number("min_rate", 1e-5, "stop once the rate would fall below this")
                .range(1e-12, 1.0),
            ParamSpec::boolean(
                "sign_memory",
                true,
                "try first the direction that last worked for each joint",
            ),
            ParamSpec::integer(
                "starts",
                6,
                "random starts; the most comfortable reaching solution is kept",
            )
            .range(1.0, 1000.0),
            ParamSpec::boolean(
                "neutral_start",
                true,
                "the first start is the neutral posture, the others random",
            ),
            ParamSpec::integer(
                "max_sweeps",
                1000,
                "stop after this many sweeps over all joints",
            )
            .range(1.0, 1e6),
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
                starts: o.integer("starts") as u32,
                neutral_start: o.boolean("neutral_start"),
                max_sweeps: o.integer("max_sweeps") as u32,
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
        let mut rng = ChaCha8Rng::seed_from_u64(problem.seed);
        let mut best: Option<(IkSolution, f64)> = None;
        for k in 0..self.settings.starts {
            let start = if k == 0 && self.settings.neutral_start {
                problem.chain.neutral()
            } else {
                random_posture(problem.chain, &mut rng)
            };
            let solution = self.descend(problem, start);
            let reached = solution.distance_mm <= problem.tolerance_mm;
            let comfort = problem.chain.discomfort(&solution.q);
            let better = match &best {
                None => true,
                Some((b, b_comfort)) => {
                    let b_reached = b.distance_mm <= problem.tolerance_mm;
                    match (reached, b_reached) {
                        (true, false) => true,
                        (false, true) => false,
                        (true, true) => comfort < *b_comfort,
                        (false, false) => solution.distance_mm < b.distance_mm,
                    }
                }
            };
            if better {
                best = Some((solution, comfort));
            }
        }
        best.expect("at least one start").0
    }
}

/// A posture drawn uniformly within the joint limits.
pub fn random_posture(chain: &Chain, rng: &mut ChaCha8Rng) -> Vec<f64> {
    chain
        .joints
        .iter()
        .map(|j| j.min + unit_interval(rng) * j.range())
        .collect()
}

/// A uniform draw from [0, 1) with 53 random bits.
fn unit_interval(rng: &mut ChaCha8Rng) -> f64 {
    (rng.next_u64() >> 11) as f64 * (1.0 / (1u64 << 53) as f64)
}

impl IncrementalSolver {
    /// One descent from `q` (section 5.2 with the options of 5.3.1).
    fn descend(&self, problem: &IkProblem<'_>, mut q: Vec<f64>) -> IkSolution {
        let s = &self.settings;
        let chain = problem.chain;
        let distance = |q: &[f64]| (chain.effector(q) - problem.target_mm).norm();
        let mut d = distance(&q);
        let mut rate = s.rate;
        let mut sign = vec![1.0_f64; chain.dof()];
        let mut sweeps = 0u64;
        while d > problem.tolerance_mm && sweeps < u64::from(s.max_sweeps) {
            sweeps += 1;
            let before = d;
            for (i, joint) in chain.joints.iter().enumerate() {
                let inc = joint.range() * rate;
                if inc == 0.0 {
                    continue;
                }
                let first = if s.sign_memory { sign[i] } else { 1.0 };
                let old = q[i];
                for dir in [first, -first] {
                    let candidate = old + dir * inc;
                    if candidate < joint.min || candidate > joint.max {
                        continue;
                    }
                    q[i] = candidate;
                    let nd = distance(&q);
                    if nd < d {
                        d = nd;
                        sign[i] = dir;
                        break;
                    }
                    q[i] = old;
                }
            }
            if before - d < s.threshold_mm {
                if s.gamma > 1.0 && rate / s.gamma >= s.min_rate {
                    rate /= s.gamma;
                } else {
                    break;
                }
            }
        }
        IkSolution {
            q,
            distance_mm: d,
            iterations: sweeps,
        }
    }
}
