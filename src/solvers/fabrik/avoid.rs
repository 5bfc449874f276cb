//! Obstacle avoidance in the forward pass, after the visibility paper: a
//! bone that passes through an obstacle once its group is turned is moved
//! to the nearest admissible place on the discretised set of places its
//! group can put its end (the joints' ranges sampled evenly), where
//! admissible is, in order of preference: (1) the bone is clear and (2) so
//! is the segment from its end to the next point's goal (so that the next
//! bone has somewhere to go), or (1) alone. Nearest is nearest to the
//! bone's goal from the backward pass. When no sample keeps the bone clear
//! the group is left as it was turned.

use nalgebra::{IsometryMatrix3, Point3};

use super::bones::Bone;
use crate::collision::PlacedObstacles;
use crate::geometry::Capsule;
use crate::kinematics::Chain;

/// How many of a group's joints are sampled (the first ones); the others
/// keep their values.
const SAMPLED_JOINTS: usize = 3;

/// What avoidance reads of a forward pass: the chain as bones, the
/// obstacles, and the pass's posture, points and goals.
pub(super) struct Bend<'a> {
    pub chain: &'a Chain,
    pub bones: &'a [Bone],
    pub obstacles: &'a PlacedObstacles<'a>,
    pub tolerance_mm: f64,
    /// Values per sampled joint.
    pub samples: u32,
    pub q: &'a [f64],
    /// The base and each bone's end, in the base frame.
    pub points: &'a [Point3<f64>],
    /// Where the backward pass wants each point.
    pub goals: &'a [Point3<f64>],
}

impl Bend<'_> {
    /// A posture that moves bone `k` (its group starting from frame
    /// `before`) out of the obstacles, if it passes through one and some
    /// sample is clear (`None` leaves the posture as it is); and the work
    /// that took, in the allowance's units.
    pub fn clear_posture(
        &self,
        k: usize,
        before: &IsometryMatrix3<f64>,
    ) -> (Option<Vec<f64>>, u64) {
        let root = self.points[k];
        let joints = self.bones[k].joints.len() as u64 + 1;
        let check = self.obstacles.capsule_units();
        if self.clear(root, self.end_with(k, before, self.q), k) {
            return (None, joints + check);
        }
        let goal = self.goals[k + 1];
        let next_goal = self.goals.get(k + 2).copied();
        let mut best: Option<(bool, f64, Vec<f64>)> = None;
        let samples = self.samples(k);
        let mut work = (samples.len() as u64 + 1) * (joints + check);
        for q in samples {
            let end = self.end_with(k, before, &q);
            if !self.clear(root, end, k) {
                continue;
            }
            work += check;
            let onward = next_goal.is_none_or(|g| self.clear(end, g, k + 1));
            let score = (end - goal).norm();
            let better = best
                .as_ref()
                .is_none_or(|(b_onward, b_score, _)| (onward, -score) > (*b_onward, -*b_score));
            if better {
                best = Some((onward, score, q));
            }
        }
        (best.map(|(_, _, q)| q), work)
    }

    /// Whether bone `bone` from `a` to `b` (a capsule of its link's
    /// radius) is clear of the room and the person's own legs and base; the
    /// effector's own bone may press by up to the tolerance into what it
    /// reaches, as `PlacedObstacles::posture_hit` lets it.
    fn clear(&self, a: Point3<f64>, b: Point3<f64>, bone: usize) -> bool {
        let mut capsule = Capsule::new(a, b, self.bones[bone].radius_mm);
        if bone == self.bones.len() - 1 {
            let radius = capsule.radius_mm - self.tolerance_mm;
            if radius > 0.0 {
                capsule.radius_mm = radius;
            } else {
                let gap = (-radius).max(1.0);
                let length = (b - a).norm();
                if length <= gap {
                    return true;
                }
                capsule = Capsule::new(a, a + (b - a) * (1.0 - gap / length), 0.0);
            }
        }
        self.obstacles.capsule_hit(&capsule).is_none()
    }

    /// Bone `k`'s end with posture `q`.
    fn end_with(&self, k: usize, before: &IsometryMatrix3<f64>, q: &[f64]) -> Point3<f64> {
        let bone = &self.bones[k];
        let frame = bone
            .joints
            .clone()
            .fold(*before, |f, j| f * self.chain.joints[j].transform(q[j]));
        bone.end_point(self.chain, &frame, q)
    }

    /// Postures that differ from the present one in the group's first
    /// joints, each sampled at `samples` values evenly across its range.
    fn samples(&self, k: usize) -> Vec<Vec<f64>> {
        let n = self.samples.max(2) as usize;
        let group: Vec<usize> = self.bones[k].joints.clone().take(SAMPLED_JOINTS).collect();
        let mut postures = vec![self.q.to_vec()];
        for &j in &group {
            let joint = &self.chain.joints[j];
            postures = postures
                .into_iter()
                .flat_map(|q| {
                    (0..n).map(move |i| {
                        let mut q = q.clone();
                        let v = joint.min + joint.range() * i as f64 / (n - 1) as f64;
                        q[j] = self.chain.clamp_joint(j, v, &q);
                        q
                    })
                })
                .collect();
        }
        postures
    }
}
