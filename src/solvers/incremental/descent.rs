//! One descent of the incremental solver from one starting posture: sweeps
//! over the joints from the base outwards, each joint tried one increment
//! either way, until the target is within tolerance, the increments have
//! all shrunk below `min_rate`, `stall` sweeps in a row have not improved,
//! or `max_sweeps` is reached.
//!
//! With `steer_clear`, once the posture is clear of obstacles and of the
//! person's own body, a move that would take it into one is not made: the
//! descent goes round a board or the chair's backrest instead of through
//! it (each move it makes is checked, so it costs more per sweep).

use nalgebra::{Point3, Vector3};

use super::IncrementalSettings;
use crate::kinematics::{Chain, IncrementalFk, Posed, Step};
use crate::plugin::{IkProblem, IkSolution, Tally};

/// One descent from `q`.
pub(super) fn descend(s: &IncrementalSettings, problem: &IkProblem<'_>, q: Vec<f64>) -> IkSolution {
    let (chain, target) = (problem.chain, problem.target_mm);
    if s.incremental_fk {
        descend_with(s, problem, IncrementalFk::new(chain, q, target))
    } else {
        descend_with(s, problem, FullProduct { chain, q, target })
    }
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

impl Kinematics for IncrementalFk {
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

/// What keeps a descent clear: the problem's obstacles, and whether the
/// posture is clear of them yet.
struct Guard<'p, 'a> {
    problem: &'p IkProblem<'a>,
    clear: bool,
    posed: Posed<'a>,
    /// Postures checked since the allowance was last told.
    checks: u64,
}

impl<'p, 'a> Guard<'p, 'a> {
    /// A guard for a descent from `q`, when the settings ask for one and
    /// the problem has obstacles.
    fn new(s: &IncrementalSettings, problem: &'p IkProblem<'a>, q: &[f64]) -> Option<Self> {
        (s.steer_clear && problem.obstacles.is_some()).then(|| Guard {
            problem,
            clear: problem.collision(q).is_none(),
            posed: Posed::new(problem.chain, q),
            checks: 1,
        })
    }

    /// Whether joint `i` may move to `value`: always while the posture is
    /// not yet clear, and then only if it stays clear.
    fn allows(&mut self, i: usize, value: f64) -> bool {
        if !self.clear {
            return true;
        }
        self.checks += 1;
        self.problem
            .collision_of(self.posed.volumes_with(i, value))
            .is_none()
    }

    /// After joint `i` moved to `value`: note whether the posture has come
    /// clear.
    fn moved(&mut self, i: usize, value: f64) {
        self.posed.set(i, value);
        if !self.clear {
            self.checks += 1;
            self.clear = self.problem.collision_of(self.posed.volumes()).is_none();
        }
    }

    /// The work of the checks since the last call, in the allowance's units.
    fn take_work(&mut self) -> u64 {
        std::mem::take(&mut self.checks) * self.problem.check_units()
    }
}

fn descend_with(
    s: &IncrementalSettings,
    problem: &IkProblem<'_>,
    mut fk: impl Kinematics,
) -> IkSolution {
    let chain = problem.chain;
    let mut guard = Guard::new(s, problem, fk.q());
    let tolerance_sq = problem.tolerance_mm * problem.tolerance_mm;
    let mut d_sq = fk.distance_sq();
    let mut rate = s.rate;
    // Each joint's first try is up, or down for a joint drawn negated
    // (`Chain::mirror_of_twin`): a left hand descends as the right one
    // does in the mirror.
    let first_sign: Vec<f64> = (0..chain.dof())
        .map(|i| if chain.drawn_negated(i) { -1.0 } else { 1.0 })
        .collect();
    let mut sign = first_sign.clone();
    // Inc(i) = range * rate (section 5.3.1), then adapted per joint.
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
    let mut stalled = 0u32;
    let mut tally = Tally::new(problem.allowance);
    let joints = chain.dof() as u64;
    while d_sq > tolerance_sq && sweeps < u64::from(s.max_sweeps) && tally.within() {
        sweeps += 1;
        let before = d_sq.sqrt();
        for (i, joint) in chain.joints.iter().enumerate() {
            if steps[i].delta == 0.0 {
                continue;
            }
            let step = &steps[i];
            let interval = chain.interval(i, fk.q());
            if !s.sign_memory {
                sign[i] = first_sign[i];
            }
            let kept = try_joint(
                s,
                &mut fk,
                i,
                interval,
                step,
                &mut sign[i],
                &mut d_sq,
                guard.as_mut(),
            );
            let factor = if kept { s.grow } else { s.shrink };
            if let Some(g) = guard.as_mut() {
                tally.count(g.take_work());
            }
            if factor != 1.0 {
                let scaled = steps[i].scaled(factor);
                steps[i] = if scaled.delta > joint.range() {
                    Step::new(joint.range())
                } else {
                    scaled
                };
            }
        }
        tally.count(joints);
        if steps
            .iter()
            .zip(&min_steps)
            .all(|(st, min)| st.delta < *min)
        {
            break;
        }
        let improvement = before - d_sq.sqrt();
        // The paper's stop on a minimum distance variation: `stall` sweeps
        // in a row that each improve by less than `stall_ratio` of the distance.
        stalled = if improvement <= s.stall_ratio * before {
            stalled + 1
        } else {
            0
        };
        if stalled >= s.stall {
            break;
        }
        // Eq. 2: a sweep improving less than `threshold` divides the rate,
        // down to `min_rate`. With fixed increments (the paper's variants) a
        // sweep that can no longer lower it has nothing left to try.
        if improvement <= s.threshold_mm && s.gamma > 1.0 {
            if rate / s.gamma >= s.min_rate {
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
    if s.avoid_obstacles {
        tally.count(problem.check_units());
    }
    IkSolution {
        distance_mm: (chain.effector(&q) - problem.target_mm).norm(),
        collision: if s.avoid_obstacles {
            problem.collision(&q)
        } else {
            None
        },
        q,
        iterations: sweeps,
    }
}

/// How much of the squared distance a move may lose and still count as
/// no farther: far above its rounding (about 1e-13 of it), far below any
/// loss that matters.
const NO_FARTHER: f64 = 1e-11;

/// Try joint `i` one increment either way, by the paper's rule: the first
/// direction (`sign`: the remembered one, or the joint's first) if it brings the effector closer within
/// the joint's limits, else the other if it does. Eagerly, both are
/// evaluated before either is chosen, so the second does not wait for the
/// first comparison; lazily (the paper's cost), the second only if the
/// first did not help. Returns whether a move was kept.
/// With a `guard`, a move that takes a clear posture into an obstacle is
/// not made.
#[inline]
#[allow(clippy::too_many_arguments)]
fn try_joint<K: Kinematics>(
    s: &IncrementalSettings,
    fk: &mut K,
    i: usize,
    interval: (f64, f64),
    step: &Step,
    sign: &mut f64,
    d_sq: &mut f64,
    mut guard: Option<&mut Guard<'_, '_>>,
) -> bool {
    let lever = fk.lever(i);
    let first = *sign;
    let old = fk.q()[i];
    let (lo, hi) = interval;
    let limits = |v: f64| v >= lo && v <= hi;
    let within = |guard: &mut Option<&mut Guard<'_, '_>>, v: f64| {
        limits(v) && guard.as_deref_mut().is_none_or(|g| g.allows(i, v))
    };
    let (plus, minus) = (old + first * step.delta, old - first * step.delta);
    let (d_first, cs_first) = fk.distance_sq_moved(i, step, first, &lever);
    let second = s
        .eager_pair
        .then(|| fk.distance_sq_moved(i, step, -first, &lever));
    // A move is made where it brings the effector no farther, a tie
    // included: a joint that leaves the distance as it is (the forearm's
    // rotation, the grip on its axis) moves on, which lets the posture
    // slide round an obstacle, and the same every time, where a strict
    // comparison left the tie to the rounding of the distance (the mirror
    // image of a search, or the same search in a room turned, parted ways
    // there).
    let closer = |d: f64| d < *d_sq * (1.0 + NO_FARTHER);
    if closer(d_first) && within(&mut guard, plus) {
        *d_sq = d_first;
        fk.set_moved(i, plus, cs_first);
        if let Some(g) = guard {
            g.moved(i, plus);
        }
        return true;
    }
    let (d_second, cs_second) =
        second.unwrap_or_else(|| fk.distance_sq_moved(i, step, -first, &lever));
    if closer(d_second) && within(&mut guard, minus) {
        *d_sq = d_second;
        fk.set_moved(i, minus, cs_second);
        *sign = -first;
        if let Some(g) = guard {
            g.moved(i, minus);
        }
        return true;
    }
    false
}
