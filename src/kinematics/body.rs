//! A mannequin's joints as a tree: each joint follows a parent joint (or the
//! base), so a spine can carry two arms and a head, and each effector sits
//! on one joint. The chain of an effector is the path from the base to it,
//! which is what the solvers work on; several effectors share the joints
//! their paths have in common.

use nalgebra::Vector3;

use super::chain::{Chain, Joint};

/// One end of the body: a hand's grip point, or the eyes' look point.
#[derive(Clone, Debug, PartialEq)]
pub struct Effector {
    pub name: String,
    /// The joint it sits on (`None`: on the base itself).
    pub joint: Option<usize>,
    /// The effector point in that joint's frame.
    pub offset_mm: Vector3<f64>,
}

/// Joints in declaration order; a parent always comes before its children.
#[derive(Clone, Debug, PartialEq)]
pub struct Body {
    pub joints: Vec<Joint>,
    /// `parents[i]`: the joint joint `i` follows (`None`: the base).
    pub parents: Vec<Option<usize>>,
    /// At least one; the first is the default for tasks.
    pub effectors: Vec<Effector>,
}

impl Body {
    /// A body that is one chain, its effector on the last joint.
    pub fn from_chain(chain: Chain) -> Self {
        let n = chain.joints.len();
        Body {
            parents: (0..n).map(|i| i.checked_sub(1)).collect(),
            effectors: vec![Effector {
                name: chain.effector_name,
                joint: n.checked_sub(1),
                offset_mm: chain.effector_mm,
            }],
            joints: chain.joints,
        }
    }

    pub fn effector_index(&self, name: &str) -> Option<usize> {
        self.effectors.iter().position(|e| e.name == name)
    }

    /// The joints from the base to `joint`, in order.
    pub fn path(&self, joint: Option<usize>) -> Vec<usize> {
        let mut path = Vec::new();
        let mut at = joint;
        while let Some(i) = at {
            path.push(i);
            at = self.parents[i];
        }
        path.reverse();
        path
    }

    /// The joints on the paths to the given effectors, each once, in body
    /// order.
    pub fn joints_to(&self, effectors: &[usize]) -> Vec<usize> {
        let mut joints: Vec<usize> = effectors
            .iter()
            .flat_map(|&e| self.path(self.effectors[e].joint))
            .collect();
        joints.sort_unstable();
        joints.dedup();
        joints
    }

    /// The chain from the base to effector `index`.
    pub fn chain(&self, index: usize) -> Chain {
        let effector = &self.effectors[index];
        Chain {
            joints: self
                .path(effector.joint)
                .into_iter()
                .map(|i| self.joints[i].clone())
                .collect(),
            effector_name: effector.name.clone(),
            effector_mm: effector.offset_mm,
        }
    }

    /// The chain of the effector named, or of the first.
    pub fn chain_named(&self, effector: Option<&str>) -> Option<Chain> {
        let index = match effector {
            Some(name) => self.effector_index(name)?,
            None => 0,
        };
        Some(self.chain(index))
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::kinematics::{Dh, JointKind};

    fn joint(name: &str) -> Joint {
        Joint {
            name: name.into(),
            kind: JointKind::Revolute,
            dh: Dh {
                theta_rad: 0.0,
                d_mm: 0.0,
                alpha_rad: 0.0,
                a_mm: 100.0,
            },
            fixed: None,
            min: -1.0,
            max: 1.0,
            neutral: 0.0,
            weight: 1.0,
        }
    }

    #[test]
    fn two_effectors_share_the_spine() {
        let body = Body {
            joints: ["spine", "arm", "hand", "neck"].map(joint).to_vec(),
            parents: vec![None, Some(0), Some(1), Some(0)],
            effectors: vec![
                Effector {
                    name: "grip".into(),
                    joint: Some(2),
                    offset_mm: Vector3::zeros(),
                },
                Effector {
                    name: "eyes".into(),
                    joint: Some(3),
                    offset_mm: Vector3::zeros(),
                },
            ],
        };
        let names = |c: Chain| c.joints.into_iter().map(|j| j.name).collect::<Vec<_>>();
        assert_eq!(names(body.chain(0)), ["spine", "arm", "hand"]);
        assert_eq!(
            names(body.chain_named(Some("eyes")).unwrap()),
            ["spine", "neck"]
        );
        assert!(body.chain_named(Some("feet")).is_none());
    }
}
