//! Fixed frames folded into the joints after them: a mannequin's `fixed`
//! joint has no motion, only a turn of the axes (the shoulder girdle's
//! slide runs up the trunk, whose frame has its z axis across it), so
//! the body keeps no joint for it. Each joint that follows one takes the
//! turn as its `pre` frame; an effector or a sphere on one is carried by
//! the moving joint before it, its point turned.

use nalgebra::{IsometryMatrix3, Point3, Vector3};

use super::chain::Joint;

/// A joint as declared: one that moves, or a fixed frame (its pose in
/// the previous frame).
pub enum Declared {
    Moving(Box<Joint>),
    Fixed(IsometryMatrix3<f64>),
}

/// Declared joints with their fixed frames folded in.
pub struct Folded {
    /// The moving joints, a fixed frame before one as its `pre`.
    pub joints: Vec<Joint>,
    /// The moving joint each follows (`None`: the base).
    pub parents: Vec<Option<usize>>,
    /// For each declared joint, the moving joint whose frame its own frame
    /// is fixed in (itself, if it moves; `None`: the base) and its pose
    /// there.
    anchors: Vec<(Option<usize>, IsometryMatrix3<f64>)>,
    /// For each declared joint, its index among the moving ones.
    index: Vec<Option<usize>>,
}

impl Folded {
    /// Fold `declared` (each following `parents[i]`, declared before it).
    pub fn new(declared: Vec<Declared>, parents: &[Option<usize>]) -> Self {
        let mut folded = Folded {
            joints: Vec::new(),
            parents: Vec::new(),
            anchors: Vec::with_capacity(declared.len()),
            index: Vec::with_capacity(declared.len()),
        };
        for (i, d) in declared.into_iter().enumerate() {
            let (anchor, pose) = folded.anchor_of(parents[i]);
            match d {
                Declared::Moving(joint) => {
                    let mut joint = *joint;
                    if pose != IsometryMatrix3::identity() {
                        joint.pre = Some(pose * joint.axis_frame());
                    }
                    let k = folded.joints.len();
                    folded.joints.push(joint);
                    folded.parents.push(anchor);
                    folded.anchors.push((Some(k), IsometryMatrix3::identity()));
                    folded.index.push(Some(k));
                }
                Declared::Fixed(frame) => {
                    folded.anchors.push((anchor, pose * frame));
                    folded.index.push(None);
                }
            }
        }
        folded
    }

    /// The moving joint a point on declared joint `parent`'s frame rides on
    /// (`None`: the base), and that frame's pose in the moving joint's.
    fn anchor_of(&self, parent: Option<usize>) -> (Option<usize>, IsometryMatrix3<f64>) {
        match parent {
            None => (None, IsometryMatrix3::identity()),
            Some(p) => self.anchors[p],
        }
    }

    /// Point `at_mm` of declared joint `joint`'s frame, on the moving joint
    /// that carries it.
    pub fn point_on(
        &self,
        joint: Option<usize>,
        at_mm: Vector3<f64>,
    ) -> (Option<usize>, Vector3<f64>) {
        let (anchor, pose) = self.anchor_of(joint);
        (anchor, (pose * Point3::from(at_mm)).coords)
    }

    /// The index among the moving joints of declared joint `i` (`None`: it
    /// is fixed).
    pub fn moving_index(&self, i: usize) -> Option<usize> {
        self.index[i]
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::kinematics::{revolute, Chain};
    use std::f64::consts::FRAC_PI_2;

    /// A frame turning the axes a quarter turn between two joints moves
    /// the effector as the same turn written as a zero-range joint would.
    #[test]
    fn a_fixed_frame_turns_the_joints_after_it() {
        let turn = revolute("turn", FRAC_PI_2, 0.0, FRAC_PI_2, 0.0).transform(0.0);
        let declared = vec![
            Declared::Moving(Box::new(revolute("a", 0.0, 0.0, 0.0, 100.0))),
            Declared::Fixed(turn),
            Declared::Moving(Box::new(revolute("b", 0.0, 0.0, 0.0, 50.0))),
        ];
        let folded = Folded::new(declared, &[None, Some(0), Some(1)]);
        assert_eq!(folded.parents, vec![None, Some(0)]);
        assert_eq!(folded.moving_index(1), None);
        let (anchor, tip) = folded.point_on(Some(2), Vector3::new(10.0, 0.0, 0.0));
        assert_eq!(anchor, Some(1));
        let chain = Chain::new(folded.joints, "tip", tip);
        let mut frame_joint = revolute("turn", FRAC_PI_2, 0.0, FRAC_PI_2, 0.0);
        frame_joint.min = 0.0;
        frame_joint.max = 0.0;
        let written = Chain::new(
            vec![
                revolute("a", 0.0, 0.0, 0.0, 100.0),
                frame_joint,
                revolute("b", 0.0, 0.0, 0.0, 50.0),
            ],
            "tip",
            Vector3::new(10.0, 0.0, 0.0),
        );
        for (qa, qb) in [(0.0, 0.0), (0.4, -1.2), (-2.0, 0.7)] {
            let got = chain.effector(&[qa, qb]);
            let want = written.effector(&[qa, 0.0, qb]);
            assert!((got - want).norm() < 1e-9, "{got} {want}");
        }
    }
}
