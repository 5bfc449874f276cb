//! The incremental coordinate solver of the accessibility paper (section
//! 5.2): each joint in turn is nudged by +/-Inc(i) = (Max(i) - Min(i)) *
//! rate, and the move is kept only if the effector gets closer to the target
//! and the joint stays within its limits. With sign memory the direction
//! that worked last is tried first; when a sweep over all joints improves
//! the distance by less than `threshold`, the rate is divided by `gamma`
//! (eq. 2). With `incremental_fk` the effector after a one-joint change costs
//! a constant number of products (eq. 6-8, `kinematics::IncrementalFk`);
//! without it, the full product of the chain (the paper's variants A, B).
//! Several starts (the neutral posture, then seeded random ones) are
//! solved and the kept solution is the most comfortable of those that reach
//! (section 5.3.4).

use rand_chacha::rand_core::{Rng, SeedableRng};
use rand_chacha::ChaCha8Rng;

use nalgebra::Point3;

use crate::kinematics::{Chain, IncrementalFk};
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
    pub incremental_fk: bool,
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
            ParamSpec::boolean(
                "incremental_fk",
                true,
                "update the effector incrementally after each joint change (eq. 6-8)",
            ),
            ParamSpec::integer(
                "starts",
                6,
                "starting postures; the most comfortable reaching solution is kept",
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
                incremental_fk: o.boolean("incremental_fk"),
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

/// Forward kinematics as the descent uses it: the effector with one joint
/// moved, and committing a move.
trait Kinematics {
    fn effector_with(&mut self, i: usize, qi: f64) -> Point3<f64>;
    fn set(&mut self, i: usize, qi: f64);
    fn q(&self) -> &[f64];
    fn into_q(self) -> Vec<f64>;
}

impl Kinematics for IncrementalFk<'_> {
    fn effector_with(&mut self, i: usize, qi: f64) -> Point3<f64> {
        IncrementalFk::effector_with(self, i, qi)
    }
    fn set(&mut self, i: usize, qi: f64) {
        IncrementalFk::set(self, i, qi)
    }
    fn q(&self) -> &[f64] {
        IncrementalFk::q(self)
    }
    fn into_q(self) -> Vec<f64> {
        IncrementalFk::into_q(self)
    }
}

/// The full product of all link matrices for every evaluation.
struct FullProduct<'a> {
    chain: &'a Chain,
    q: Vec<f64>,
}

impl Kinematics for FullProduct<'_> {
    fn effector_with(&mut self, i: usize, qi: f64) -> Point3<f64> {
        let old = std::mem::replace(&mut self.q[i], qi);
        let p = self.chain.effector(&self.q);
        self.q[i] = old;
        p
    }
    fn set(&mut self, i: usize, qi: f64) {
        self.q[i] = qi;
    }
    fn q(&self) -> &[f64] {
        &self.q
    }
    fn into_q(self) -> Vec<f64> {
        self.q
    }
}

impl IncrementalSolver {
    /// One descent from `q` (section 5.2 with the options of 5.3.1-5.3.2).
    fn descend(&self, problem: &IkProblem<'_>, q: Vec<f64>) -> IkSolution {
        if self.settings.incremental_fk {
            self.descend_with(problem, IncrementalFk::new(problem.chain, q))
        } else {
            self.descend_with(
                problem,
                FullProduct {
                    chain: problem.chain,
                    q,
                },
            )
        }
    }

    fn descend_with(&self, problem: &IkProblem<'_>, mut fk: impl Kinematics) -> IkSolution {
        let s = &self.settings;
        let chain = problem.chain;
        let target = problem.target_mm;
        let tolerance_sq = problem.tolerance_mm * problem.tolerance_mm;
        let start = fk.effector_with(0, fk.q()[0]);
        let mut d_sq = (start - target).norm_squared();
        let mut rate = s.rate;
        let mut sign = vec![1.0_f64; chain.dof()];
        let mut sweeps = 0u64;
        while d_sq > tolerance_sq && sweeps < u64::from(s.max_sweeps) {
            sweeps += 1;
            let before = d_sq.sqrt();
            for (i, joint) in chain.joints.iter().enumerate() {
                let inc = joint.range() * rate;
                if inc == 0.0 {
                    continue;
                }
                let first = if s.sign_memory { sign[i] } else { 1.0 };
                let old = fk.q()[i];
                for dir in [first, -first] {
                    let candidate = old + dir * inc;
                    if candidate < joint.min || candidate > joint.max {
                        continue;
                    }
                    let nd_sq = (fk.effector_with(i, candidate) - target).norm_squared();
                    if nd_sq < d_sq {
                        d_sq = nd_sq;
                        fk.set(i, candidate);
                        sign[i] = dir;
                        break;
                    }
                }
            }
            if before - d_sq.sqrt() < s.threshold_mm {
                if s.gamma > 1.0 && rate / s.gamma >= s.min_rate {
                    rate /= s.gamma;
                } else {
                    break;
                }
            }
        }
        IkSolution {
            q: fk.into_q(),
            distance_mm: d_sq.sqrt(),
            iterations: sweeps,
        }
    }
}
