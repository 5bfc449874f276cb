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

use nalgebra::{Point3, Vector3};

use crate::kinematics::{Chain, IncrementalFk, Step};
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
    pub grow: f64,
    pub shrink: f64,
    pub eager_pair: bool,
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
            ParamSpec::number("grow", 2.0, "a joint's increment is multiplied by this after a kept move (1: never)")
                .range(1.0, 10.0),
            ParamSpec::number("shrink", 0.5, "and by this after neither direction helped (1: never)").range(0.01, 1.0),
            ParamSpec::boolean(
                "eager_pair",
                true,
                "evaluate both directions before choosing (same answer; faster on pipelined processors)",
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
                grow: o.number("grow"),
                shrink: o.number("shrink"),
                eager_pair: o.boolean("eager_pair"),
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

/// Forward kinematics as the descent uses it: for joint i, something
/// computed once per visit (the lever), then the squared distance for each
/// step tried, and committing a move.
trait Kinematics {
    type Lever;
    fn lever(&mut self, i: usize) -> Self::Lever;
    /// The squared distance with joint i moved by `dir * step.delta`, and the
    /// cosine and sine of its new angle.
    fn distance_sq_moved(
        &mut self,
        i: usize,
        step: &Step,
        dir: f64,
        lever: &Self::Lever,
    ) -> (f64, (f64, f64));
    fn set_moved(&mut self, i: usize, qi: f64, cos_sin: (f64, f64));
    fn distance_sq(&mut self) -> f64;
    fn q(&self) -> &[f64];
    fn into_q(self) -> Vec<f64>;
}

impl Kinematics for IncrementalFk<'_> {
    type Lever = Vector3<f64>;
    fn lever(&mut self, i: usize) -> Vector3<f64> {
        IncrementalFk::lever(self, i)
    }
    #[inline]
    fn distance_sq_moved(
        &mut self,
        i: usize,
        step: &Step,
        dir: f64,
        lever: &Vector3<f64>,
    ) -> (f64, (f64, f64)) {
        IncrementalFk::distance_sq_moved(self, i, step, dir, lever)
    }
    fn set_moved(&mut self, i: usize, qi: f64, cos_sin: (f64, f64)) {
        IncrementalFk::set_moved(self, i, qi, cos_sin)
    }
    fn distance_sq(&mut self) -> f64 {
        IncrementalFk::distance_sq(self)
    }
    fn q(&self) -> &[f64] {
        IncrementalFk::q(self)
    }
    fn into_q(self) -> Vec<f64> {
        IncrementalFk::into_q(self)
    }
}

/// The full product of all link matrices for every evaluation (the paper's
/// variants A and B).
struct FullProduct<'a> {
    chain: &'a Chain,
    q: Vec<f64>,
    target: Point3<f64>,
}

impl Kinematics for FullProduct<'_> {
    type Lever = ();
    fn lever(&mut self, _: usize) {}
    fn distance_sq_moved(&mut self, i: usize, step: &Step, dir: f64, _: &()) -> (f64, (f64, f64)) {
        let old = self.q[i];
        self.q[i] = old + dir * step.delta;
        let p = self.chain.effector(&self.q);
        self.q[i] = old;
        ((p - self.target).norm_squared(), (1.0, 0.0))
    }
    fn set_moved(&mut self, i: usize, qi: f64, _: (f64, f64)) {
        self.q[i] = qi;
    }
    fn distance_sq(&mut self) -> f64 {
        (self.chain.effector(&self.q) - self.target).norm_squared()
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
        let (chain, target) = (problem.chain, problem.target_mm);
        if self.settings.incremental_fk {
            self.descend_with(problem, IncrementalFk::new(chain, q, target))
        } else {
            self.descend_with(problem, FullProduct { chain, q, target })
        }
    }

    fn descend_with(&self, problem: &IkProblem<'_>, mut fk: impl Kinematics) -> IkSolution {
        let s = &self.settings;
        let chain = problem.chain;
        let tolerance_sq = problem.tolerance_mm * problem.tolerance_mm;
        let mut d_sq = fk.distance_sq();
        let mut rate = s.rate;
        let mut sign = vec![1.0_f64; chain.dof()];
        // Each joint's increment: Inc(i) = range * rate (section 5.3.1), then
        // adapted per joint (the paper leaves the adaptation open): grown
        // after a kept move, shrunk after a miss, never beyond the range.
        let mut steps: Vec<Step> = chain
            .joints
            .iter()
            .map(|j| Step::new(j.range() * rate))
            .collect();
        let min_steps: Vec<f64> = chain
            .joints
            .iter()
            .map(|j| j.range() * s.min_rate)
            .collect();
        let mut sweeps = 0u64;
        while d_sq > tolerance_sq && sweeps < u64::from(s.max_sweeps) {
            sweeps += 1;
            let before = d_sq.sqrt();
            for (i, joint) in chain.joints.iter().enumerate() {
                if steps[i].delta == 0.0 {
                    continue;
                }
                let step = steps[i];
                let lever = fk.lever(i);
                let first = if s.sign_memory { sign[i] } else { 1.0 };
                let old = fk.q()[i];
                let within = |v: f64| v >= joint.min && v <= joint.max;
                let plus = old + first * step.delta;
                let minus = old - first * step.delta;
                // The paper's rule: the first direction if it helps, else the
                // other if it helps. Eagerly, both are evaluated before either
                // is chosen, so the second does not wait for the first
                // comparison; lazily (the paper's cost), the second only if
                // the first did not help.
                let (d_first, cs_first) = fk.distance_sq_moved(i, &step, first, &lever);
                let second = if s.eager_pair {
                    Some(fk.distance_sq_moved(i, &step, -first, &lever))
                } else {
                    None
                };
                let kept = if d_first < d_sq && within(plus) {
                    d_sq = d_first;
                    fk.set_moved(i, plus, cs_first);
                    true
                } else {
                    let (d_second, cs_second) =
                        second.unwrap_or_else(|| fk.distance_sq_moved(i, &step, -first, &lever));
                    if d_second < d_sq && within(minus) {
                        d_sq = d_second;
                        fk.set_moved(i, minus, cs_second);
                        sign[i] = -first;
                        true
                    } else {
                        false
                    }
                };
                let factor = if kept { s.grow } else { s.shrink };
                if factor != 1.0 {
                    let scaled = step.scaled(factor);
                    steps[i] = if scaled.delta > joint.range() {
                        Step::new(joint.range())
                    } else {
                        scaled
                    };
                }
            }
            if steps
                .iter()
                .zip(&min_steps)
                .all(|(st, min)| st.delta < *min)
            {
                break;
            }
            if before - d_sq.sqrt() <= s.threshold_mm {
                if s.gamma > 1.0 && rate / s.gamma >= s.min_rate {
                    rate /= s.gamma;
                    for st in &mut steps {
                        *st = st.scaled(1.0 / s.gamma);
                    }
                } else if s.grow == 1.0 && s.shrink == 1.0 {
                    break;
                }
            }
        }
        // The distance reported is that of the plain product of the chain,
        // whatever the descent computed on the way.
        let q = fk.into_q();
        IkSolution {
            distance_mm: (chain.effector(&q) - problem.target_mm).norm(),
            q,
            iterations: sweeps,
        }
    }
}
