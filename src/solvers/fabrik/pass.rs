//! One FABRIK solve from one starting posture (Aristidou and Lasenby): the
//! backward pass puts the effector on the target and each point at its
//! bone's length from the next, towards where it was; the forward pass
//! rebuilds the chain from the base, turning each bone's group of joints
//! so that the bone points at its next point from the backward pass.
//!
//! The forward pass works in joint space: within a group, each joint in
//! turn takes the angle (clamped to its limits) that best turns the bone's
//! end towards its goal, a few sweeps over the group. Joint limits hold
//! exactly after every update, posture and report are joint angles, and a
//! bone has no preferred axis, so there is no singularity at 90 degrees;
//! the paper's cone and twist constraints on bone directions are what
//! these per-joint limits become for a DH chain. A bone that then passes
//! through an obstacle is moved by `avoid.rs`.

use nalgebra::{IsometryMatrix3, Point3, Rotation3, Unit, Vector3};
use rand_chacha::ChaCha8Rng;

use super::avoid;
use super::bones::Bone;
use super::stall::{Next, Stalls};
use super::FabrikSettings;
use crate::kinematics::{Chain, JointKind};
use crate::plugin::{IkProblem, IkSolution, Tally};

/// The working state of one solve.
pub(super) struct Pass<'a> {
    pub settings: &'a FabrikSettings,
    pub problem: &'a IkProblem<'a>,
    pub bones: &'a [Bone],
    pub q: Vec<f64>,
    /// The base and each bone's end, in the base frame.
    pub points: Vec<Point3<f64>>,
    /// Where the backward pass wants each point.
    pub goals: Vec<Point3<f64>>,
    /// Joint axes of the group being aligned (scratch).
    axes: Vec<Vector3<f64>>,
    /// Work done since the allowance was last told, in its units
    /// ([`crate::allowance`]): a joint moved or carried, a bone placed.
    pub work: u64,
}

impl<'a> Pass<'a> {
    pub fn new(
        settings: &'a FabrikSettings,
        problem: &'a IkProblem<'a>,
        bones: &'a [Bone],
        q: Vec<f64>,
    ) -> Self {
        let n = bones.len() + 1;
        let mut pass = Pass {
            settings,
            problem,
            bones,
            q,
            points: vec![Point3::origin(); n],
            goals: vec![Point3::origin(); n],
            axes: Vec::new(),
            work: 0,
        };
        pass.forward_with(false, false);
        pass
    }

    pub fn chain(&self) -> &'a Chain {
        self.problem.chain
    }

    /// Iterate until the effector is within tolerance (and clear of
    /// obstacles), or stops improving; when it stalls short of the target,
    /// the posture is kicked (every joint moved by up to `kick` of its
    /// range, seeded) and the passes go on, up to `kicks` times. The best
    /// posture seen is returned.
    pub fn run(mut self, rng: &mut ChaCha8Rng) -> IkSolution {
        let s = self.settings;
        let tolerance = self.problem.tolerance_mm;
        let avoiding = s.avoid_obstacles && self.problem.obstacles.is_some();
        let mut best: Option<(bool, f64, Vec<f64>)> = None;
        let mut stalls = Stalls::new();
        let mut iterations = 0;
        let mut tally = Tally::new(self.problem.allowance);
        let check = if avoiding {
            self.problem.check_units()
        } else {
            0
        };
        while iterations < s.max_iterations {
            let work = std::mem::take(&mut self.work);
            if !tally.add(work + check) && best.is_some() {
                break;
            }
            let d = self.effector_distance();
            let clear = !avoiding || self.problem.collision(&self.q).is_none();
            let reaches = d <= tolerance && clear;
            if best
                .as_ref()
                .is_none_or(|(b_reaches, b_d, _)| (reaches, -d) > (*b_reaches, -*b_d))
            {
                best = Some((reaches, d, self.q.clone()));
            }
            if reaches {
                break;
            }
            match stalls.next(s, d, d <= tolerance) {
                Next::Stop => break,
                Next::Kick => self.kick(rng),
                Next::Pass => {
                    self.backward();
                    self.forward(avoiding);
                    if s.ccd {
                        self.ccd_sweep();
                    }
                    iterations += 1;
                }
            }
        }
        let (_, _, q) = best.expect("at least one posture seen");
        tally.count(std::mem::take(&mut self.work) + check);
        let chain = self.chain();
        IkSolution {
            distance_mm: (chain.effector(&q) - self.problem.target_mm).norm(),
            collision: if s.avoid_obstacles {
                self.problem.collision(&q)
            } else {
                None
            },
            q,
            iterations: u64::from(iterations),
        }
    }

    /// Kick the posture (see [`kick`]) and rebuild the points.
    fn kick(&mut self, rng: &mut ChaCha8Rng) {
        let chain = self.chain();
        self.work += chain.dof() as u64;
        kick(&mut self.q, chain, self.settings.kick, rng);
        self.forward_with(false, false);
    }

    pub fn effector_distance(&self) -> f64 {
        (self.points[self.points.len() - 1] - self.problem.target_mm).norm()
    }

    /// Goals from the target back to the base, each at its bone's length
    /// from the next goal, towards the point's present place.
    fn backward(&mut self) {
        self.backward_from(self.bones.len(), self.problem.target_mm);
    }

    /// Goals from point `last` (put at `goal`) back to the base.
    pub fn backward_from(&mut self, last: usize, goal: Point3<f64>) {
        self.work += last as u64;
        self.goals[last] = goal;
        for k in (0..last).rev() {
            let from = self.goals[k + 1];
            let towards = self.points[k] - from;
            let distance = towards.norm();
            let [lo, hi] = self.bones[k].length_mm;
            self.goals[k] = if distance > 1e-12 {
                from + towards * (distance.clamp(lo, hi) / distance)
            } else {
                self.points[k]
            };
        }
    }

    /// Rebuild the points from the base, each group first turning its bone
    /// towards its goal (and, `avoiding`, away from obstacles).
    fn forward(&mut self, avoiding: bool) {
        self.forward_bones(0..self.bones.len(), true, avoiding);
    }

    /// Rebuild the points from the base; with `align`, turning each group.
    pub fn forward_with(&mut self, align: bool, avoiding: bool) {
        self.forward_bones(0..self.bones.len(), align, avoiding);
    }

    /// Rebuild the points up to the end of `bones`, turning (with `align`)
    /// only the groups of `bones`.
    pub fn forward_bones(&mut self, bones: std::ops::Range<usize>, align: bool, avoiding: bool) {
        let mut frame = IsometryMatrix3::identity();
        for k in 0..bones.end {
            if align && bones.contains(&k) && !self.bones[k].joints.is_empty() {
                self.align(k, &frame);
                if avoiding {
                    self.avoid(k, &frame);
                }
            }
            frame = self.advance(k, &frame);
        }
    }

    /// The frame after bone `k`'s group, from the frame before it; records
    /// the bone's end in `points[k + 1]`.
    pub fn advance(&mut self, k: usize, before: &IsometryMatrix3<f64>) -> IsometryMatrix3<f64> {
        let bone = &self.bones[k];
        let chain = self.chain();
        self.work += bone.joints.len() as u64 + 1;
        let frame = bone
            .joints
            .clone()
            .fold(*before, |f, j| f * chain.joints[j].transform(self.q[j]));
        self.points[k + 1] = bone.end_point(chain, &frame, &self.q);
        frame
    }

    /// Move bone `k` out of the obstacles if it passes through one
    /// (`avoid.rs`).
    fn avoid(&mut self, k: usize, before: &IsometryMatrix3<f64>) {
        let Some(obstacles) = self.problem.obstacles.as_ref() else {
            return;
        };
        let bend = avoid::Bend {
            chain: self.chain(),
            bones: self.bones,
            obstacles,
            tolerance_mm: self.problem.tolerance_mm,
            samples: self.settings.samples,
            q: &self.q,
            points: &self.points,
            goals: &self.goals,
        };
        let (moved, work) = bend.clear_posture(k, before);
        self.work += work;
        if let Some(q) = moved {
            self.q = q;
        }
    }

    /// Turn bone `k`'s group so that the bone's end comes nearest its goal.
    fn align(&mut self, k: usize, before: &IsometryMatrix3<f64>) {
        let chain = self.chain();
        let bone = &self.bones[k];
        let mut frame = *before;
        self.axes.clear();
        for j in bone.joints.clone() {
            let joint = &chain.joints[j];
            self.axes
                .push((frame * joint.axis_frame()).rotation * Vector3::z());
            frame *= joint.transform(self.q[j]);
        }
        let end = bone.end_point(chain, &frame, &self.q);
        self.turn_group(k, end, self.goals[k + 1]);
    }

    /// Turn bone `k`'s group (its axes in `axes`) so that `end`, a point
    /// carried rigidly by the group, comes nearest `goal`: each joint in
    /// turn takes its best value within its limits, `sweeps` times.
    /// Returns where `end` went.
    fn turn_group(&mut self, k: usize, mut end: Point3<f64>, goal: Point3<f64>) -> Point3<f64> {
        let chain = self.chain();
        let pivot = self.points[k];
        let joints = self.bones[k].joints.clone();
        self.work += u64::from(self.settings.sweeps) * joints.len() as u64;
        for _ in 0..self.settings.sweeps {
            for (i, j) in joints.clone().enumerate() {
                let joint = &chain.joints[j];
                let axis = self.axes[i];
                let moved = match joint.kind {
                    JointKind::Revolute => best_turn(axis, end - pivot, goal - pivot),
                    JointKind::Prismatic => axis.dot(&(goal - end)),
                };
                let q = chain.clamp_joint(j, self.q[j] + moved, &self.q);
                let step = q - self.q[j];
                self.q[j] = q;
                match joint.kind {
                    JointKind::Prismatic => end += axis * step,
                    JointKind::Revolute => {
                        let turn = Rotation3::from_axis_angle(&Unit::new_unchecked(axis), step);
                        end = pivot + turn * (end - pivot);
                        for later in &mut self.axes[i + 1..] {
                            *later = turn * *later;
                        }
                    }
                }
            }
        }
        end
    }

    /// One sweep from the effector's group back to the base, each group
    /// turning the effector itself towards the target (cyclic coordinate
    /// descent by groups). It passes on to the root what the tip's joint
    /// limits refuse, which FABRIK's passes do not: the backward pass puts
    /// every point where its bone's length allows, and a look link of
    /// variable length, or a wrist at its limit, then asks nothing of the
    /// joints above it.
    pub fn ccd_sweep(&mut self) {
        self.ccd_sweep_from(0);
    }

    /// [`Self::ccd_sweep`] over the groups of bones `first..` only.
    pub fn ccd_sweep_from(&mut self, first: usize) {
        let chain = self.chain();
        let mut befores = Vec::with_capacity(self.bones.len());
        let mut frame = IsometryMatrix3::identity();
        for k in 0..self.bones.len() {
            befores.push(frame);
            frame = self.advance(k, &frame);
        }
        let mut effector = self.points[self.bones.len()];
        let target = self.problem.target_mm;
        for k in (first..self.bones.len()).rev() {
            let mut f = befores[k];
            self.axes.clear();
            for j in self.bones[k].joints.clone() {
                let joint = &chain.joints[j];
                self.axes
                    .push((f * joint.axis_frame()).rotation * Vector3::z());
                f *= joint.transform(self.q[j]);
            }
            effector = self.turn_group(k, effector, target);
        }
        self.forward_with(false, false);
    }
}

/// Move every joint by a seeded random amount, up to `fraction` of its
/// range, within its limits and couplings.
pub fn kick(q: &mut [f64], chain: &Chain, fraction: f64, rng: &mut ChaCha8Rng) {
    for i in 0..chain.dof() {
        let u = crate::solvers::starts::unit_interval(rng);
        let by = crate::solvers::starts::kick_by(chain, i, u, fraction);
        q[i] = chain.clamp_joint(i, q[i] + by, q);
    }
}

/// The turn about unit `axis` that brings direction `from` nearest
/// direction `to` (both seen from a point on the axis): the angle between
/// their projections on the plane across the axis.
fn best_turn(axis: Vector3<f64>, from: Vector3<f64>, to: Vector3<f64>) -> f64 {
    let a = from - axis * axis.dot(&from);
    let b = to - axis * axis.dot(&to);
    if a.norm_squared() < 1e-18 || b.norm_squared() < 1e-18 {
        return 0.0;
    }
    axis.dot(&a.cross(&b)).atan2(a.dot(&b))
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn best_turn_is_the_signed_angle_across_the_axis() {
        let z = Vector3::z();
        let t = best_turn(z, Vector3::x(), Vector3::new(0.0, 2.0, 5.0));
        assert!((t - std::f64::consts::FRAC_PI_2).abs() < 1e-12);
        assert_eq!(
            best_turn(z, z, Vector3::x()),
            0.0,
            "along the axis: no turn"
        );
    }
}
