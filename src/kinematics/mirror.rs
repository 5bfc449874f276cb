//! A left hand's chain as the mirror image of its right twin's: which of
//! its joints turn the other way (a joint whose axis lies in the body's
//! midplane, as turning and bending the trunk sideways), so that its
//! random starts, kicks and seeds can be drawn as the twin's seen in a
//! mirror, and a room mirrored left to right asks the same of the other
//! hand.
//!
//! The body's midplane is the base frame's x-z plane (y = 0): the base
//! frame has x forward, y to the left, z up, and its origin is the hip
//! point.

use nalgebra::{Point3, Vector3};

use super::chain::{Chain, JointKind};

/// How far each joint is turned (rad) or slid (mm) to see which way it
/// moves the effector.
const PROBE_RAD: f64 = 0.2;
const PROBE_MM: f64 = 20.0;
/// The chains are mirror images where the effectors' neutral points, and
/// every probe's move, agree within this in the mirror.
const AGREE_MM: f64 = 0.5;

/// `p` seen in the body's midplane.
pub fn mirrored(p: &Point3<f64>) -> Point3<f64> {
    Point3::new(p.x, -p.y, p.z)
}

/// The point a solve of `chain` takes its seed from for target
/// `target_mm` (in the base frame): the target, or for a chain drawn as
/// its twin's mirror image (`Chain::mirror_of_twin`), the target seen in
/// the midplane, so that the twin asked of the mirrored target draws the
/// same.
pub fn seed_point_mm(chain: &Chain, target_mm: &Point3<f64>) -> Point3<f64> {
    if chain.mirror_of_twin.is_empty() {
        *target_mm
    } else {
        mirrored(target_mm)
    }
}

/// For each joint of `left`, whether its value is the negated value of the
/// same joint of `right` in the mirror image of a posture; empty where
/// the chains are not mirror images of each other joint by joint (a
/// person whose arms differ, or chains of other lengths).
pub fn flips_of_twin(left: &Chain, right: &Chain) -> Vec<bool> {
    if left.dof() != right.dof() {
        return Vec::new();
    }
    let (rest_left, rest_right) = (left.neutral(), right.neutral());
    let (at_left, at_right) = (left.effector(&rest_left), right.effector(&rest_right));
    if (mirrored(&at_right) - at_left).norm() > AGREE_MM {
        return Vec::new();
    }
    let mut flips = Vec::with_capacity(left.dof());
    for i in 0..left.dof() {
        let probe = match left.joints[i].kind {
            JointKind::Revolute => PROBE_RAD,
            JointKind::Prismatic => PROBE_MM,
        };
        // The effector's move from `at`, where `rest` puts it.
        let moved = |chain: &Chain, (rest, at): (&[f64], &Point3<f64>), by: f64| -> Vector3<f64> {
            let mut q = rest.to_vec();
            q[i] += by;
            chain.effector(&q) - at
        };
        let (left_rest, right_rest) = ((&rest_left[..], &at_left), (&rest_right[..], &at_right));
        let want = mirrored(&Point3::from(moved(right, right_rest, probe))).coords;
        let same = (moved(left, left_rest, probe) - want).norm();
        let negated = (moved(left, left_rest, -probe) - want).norm();
        if same.min(negated) > AGREE_MM {
            return Vec::new();
        }
        flips.push(negated < same);
    }
    flips
}
