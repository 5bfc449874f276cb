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

use super::pass::{bone_end, Pass};

/// How many of a group's joints are sampled (the first ones); the others
/// keep their values.
const SAMPLED_JOINTS: usize = 3;

/// Move bone `k` out of the obstacles if it passes through one.
pub(super) fn avoid(pass: &mut Pass<'_>, k: usize, before: &IsometryMatrix3<f64>) {
    let Some(obstacles) = pass.problem.obstacles else {
        return;
    };
    let last = pass.bones.len() - 1;
    // The effector's own bone may end on the target's surface.
    let gap = |bone: usize| {
        if bone == last {
            pass.problem.tolerance_mm.max(1.0)
        } else {
            0.0
        }
    };
    let clear = |a: Point3<f64>, b: Point3<f64>, bone: usize| {
        obstacles.polyline_hit(&[a, b], gap(bone)).is_none()
    };
    let root = pass.points[k];
    let end = end_with(pass, k, before, &pass.q);
    if clear(root, end, k) {
        return;
    }
    let goal = pass.goals[k + 1];
    let next_goal = pass.goals.get(k + 2).copied();
    let mut best: Option<(bool, f64, Vec<f64>)> = None;
    for q in samples(pass, k) {
        let end = end_with(pass, k, before, &q);
        if !clear(root, end, k) {
            continue;
        }
        let onward = next_goal.is_none_or(|g| clear(end, g, k + 1));
        let score = (end - goal).norm();
        let better = best
            .as_ref()
            .is_none_or(|(b_onward, b_score, _)| (onward, -score) > (*b_onward, -*b_score));
        if better {
            best = Some((onward, score, q));
        }
    }
    if let Some((_, _, q)) = best {
        pass.q = q;
    }
}

/// Bone `k`'s end with posture `q`.
fn end_with(pass: &Pass<'_>, k: usize, before: &IsometryMatrix3<f64>, q: &[f64]) -> Point3<f64> {
    let chain = pass.chain();
    let bone = &pass.bones[k];
    let frame = bone
        .joints
        .clone()
        .fold(*before, |f, j| f * chain.joints[j].transform(q[j]));
    bone_end(chain, bone, &frame, q)
}

/// Postures that differ from the present one in the group's first joints,
/// each sampled at `samples` values evenly across its range.
fn samples(pass: &Pass<'_>, k: usize) -> Vec<Vec<f64>> {
    let chain = pass.chain();
    let n = pass.settings.samples.max(2) as usize;
    let group: Vec<usize> = pass.bones[k].joints.clone().take(SAMPLED_JOINTS).collect();
    let mut postures = vec![pass.q.clone()];
    for &j in &group {
        let joint = &chain.joints[j];
        postures = postures
            .into_iter()
            .flat_map(|q| {
                (0..n).map(move |i| {
                    let mut q = q.clone();
                    q[j] = joint.min + joint.range() * i as f64 / (n - 1) as f64;
                    q
                })
            })
            .collect();
    }
    postures
}
