//! A DH chain seen as FABRIK sees it: points joined by bones. The points
//! are the base, every joint frame origin that lies away from the one
//! before it, and the effector. A bone's group is the joints whose axes
//! pass through its root and that turn it: a revolute joint that slides
//! its frame along its own axis (`a` = 0, `d` != 0) ends the bone before it
//! without turning it, and starts the next group, since its axis also
//! passes through that bone's end (the shoulder's flexion axis runs along
//! the shoulder's offset from the spine). A bone ending in a prismatic
//! joint (the eyes' look link) has a length between limits.

use nalgebra::{IsometryMatrix3, Point3, Vector3};

use crate::kinematics::{Chain, JointKind};

/// Where a bone ends.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum End {
    /// The origin of the frame after this joint.
    Frame(usize),
    /// The effector point.
    Effector,
}

/// One bone and the joints that turn it.
#[derive(Clone, Debug, PartialEq)]
pub struct Bone {
    /// Indices into the chain's joints, in order (may be empty: the bone
    /// is then placed by the joints of earlier bones alone).
    pub joints: std::ops::Range<usize>,
    pub end: End,
    /// The bone's length, or its least and greatest for a prismatic bone.
    pub length_mm: [f64; 2],
    /// The radius of the link it stands for.
    pub radius_mm: f64,
}

impl Bone {
    /// Where the bone ends, given the frame after its group and the
    /// posture `q`.
    pub fn end_point(
        &self,
        chain: &Chain,
        after_group: &IsometryMatrix3<f64>,
        q: &[f64],
    ) -> Point3<f64> {
        match self.end {
            // The joint that slides along its own axis starts the next group:
            // its offset is carried here, its turn is not needed for the end.
            End::Frame(j) if j == self.joints.end => Point3::from(
                (after_group * chain.joints[j].transform(q[j]))
                    .translation
                    .vector,
            ),
            End::Frame(_) => Point3::from(after_group.translation.vector),
            End::Effector => after_group * Point3::from(chain.effector_mm),
        }
    }
}

/// The bones of a chain, root first.
pub fn bones(chain: &Chain) -> Vec<Bone> {
    let mut bones = Vec::new();
    let mut start = 0;
    for (j, joint) in chain.joints.iter().enumerate() {
        // In the frame the joint moves in (a `pre` frame only turns it).
        let offset = joint.rest_offset_mm();
        let prismatic = joint.kind == JointKind::Prismatic;
        if !prismatic && offset.norm() < 1e-9 {
            continue;
        }
        let slides_along_axis = !prismatic && offset.xy().norm() < 1e-9;
        let length_mm = if prismatic {
            let at = |q: f64| (offset + Vector3::z() * q).norm();
            let (lo, hi) = (at(joint.min), at(joint.max));
            // The length is least where the slide passes nearest the root.
            let nearest = (-offset.z).clamp(joint.min, joint.max);
            [lo.min(hi).min(at(nearest)), lo.max(hi)]
        } else {
            [offset.norm(); 2]
        };
        let group_end = if slides_along_axis { j } else { j + 1 };
        bones.push(Bone {
            joints: start..group_end,
            end: End::Frame(j),
            length_mm,
            radius_mm: joint.link.radius_mm,
        });
        start = group_end;
    }
    let offset = chain.effector_mm.norm();
    if offset > 0.0 {
        bones.push(Bone {
            joints: start..chain.joints.len(),
            end: End::Effector,
            length_mm: [offset; 2],
            radius_mm: chain.effector_link.radius_mm,
        });
    }
    bones
}
