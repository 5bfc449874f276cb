//! A mannequin's joints as a tree: each joint follows a parent joint (or the
//! base), so a spine can carry two arms and a head, and each effector sits
//! on one joint. The chain of an effector is the path from the base to it,
//! which is what the solvers work on; several effectors share the joints
//! their paths have in common.

use nalgebra::{Point3, Vector3};

use super::chain::{Chain, Joint, Link, Rider};
use super::coupling::Coupling;
use super::legs::{Legs, Posture};

/// One end of the body: a hand's grip point, or the eyes' look point.
#[derive(Clone, Debug, PartialEq)]
pub struct Effector {
    pub name: String,
    /// The joint it sits on (`None`: on the base itself).
    pub joint: Option<usize>,
    /// The effector point in that joint's frame.
    pub offset_mm: Vector3<f64>,
    /// The link from that joint's frame origin to the effector (the hand).
    pub link: Link,
}

/// A sphere on a joint of the body: the head.
#[derive(Clone, Debug, PartialEq)]
pub struct Sphere {
    pub name: String,
    /// The joint it sits on (`None`: on the base itself).
    pub joint: Option<usize>,
    /// Its centre in that joint's frame.
    pub centre_mm: Vector3<f64>,
    pub radius_mm: f64,
}

/// Joints in declaration order; a parent always comes before its children.
#[derive(Clone, Debug, PartialEq)]
pub struct Body {
    pub joints: Vec<Joint>,
    /// `parents[i]`: the joint joint `i` follows (`None`: the base).
    pub parents: Vec<Option<usize>>,
    /// At least one; the first is the default for tasks.
    pub effectors: Vec<Effector>,
    pub spheres: Vec<Sphere>,
    /// The legs, which no joint moves: placed by the base (seated or
    /// standing). `None`: the mannequin declares none.
    pub legs: Option<Legs>,
    /// Whether the mannequin sits or stands (`None`: as its base has it).
    pub posture: Option<Posture>,
    /// Joints whose ranges are coupled, by body index.
    pub couplings: Vec<Coupling>,
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
                link: chain.effector_link,
            }],
            joints: chain.joints,
            spheres: Vec::new(),
            legs: None,
            posture: None,
            couplings: chain.couplings,
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

    /// The chain from the base to effector `index`, carrying the body's
    /// spheres.
    pub fn chain(&self, index: usize) -> Chain {
        let effector = &self.effectors[index];
        let path = self.path(effector.joint);
        Chain {
            joints: path.iter().map(|&i| self.joints[i].clone()).collect(),
            effector_name: effector.name.clone(),
            effector_mm: effector.offset_mm,
            effector_link: effector.link.clone(),
            riders: self.spheres.iter().map(|s| self.rider(s, &path)).collect(),
            couplings: self.couplings_on(&path),
        }
    }

    /// The couplings whose joints all lie on `joints` (body indices, in
    /// chain order), renumbered as the chain of those joints numbers them.
    pub fn couplings_on(&self, joints: &[usize]) -> Vec<Coupling> {
        let index = |j: usize| joints.iter().position(|&p| p == j);
        self.couplings
            .iter()
            .filter_map(|c| c.renumbered(index))
            .collect()
    }

    /// Sphere `s` as a chain along `path` carries it: its centre in the
    /// frame of the last joint of `path` among its joint's ancestors, the
    /// joints between at their neutral values.
    fn rider(&self, s: &Sphere, path: &[usize]) -> Rider {
        let mut centre = Point3::from(s.centre_mm);
        let mut at = s.joint;
        while let Some(j) = at {
            if path.contains(&j) {
                break;
            }
            let joint = &self.joints[j];
            centre = joint.transform(joint.neutral) * centre;
            at = self.parents[j];
        }
        Rider {
            name: s.name.clone(),
            anchor: at.and_then(|j| path.iter().position(|&p| p == j)),
            centre_mm: centre.coords,
            radius_mm: s.radius_mm,
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
    use crate::kinematics::chain::revolute;

    fn joint(name: &str) -> Joint {
        Joint {
            min: -1.0,
            max: 1.0,
            ..revolute(name, 0.0, 0.0, 0.0, 100.0)
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
                    link: Link::named("hand"),
                },
                Effector {
                    name: "eyes".into(),
                    joint: Some(3),
                    offset_mm: Vector3::zeros(),
                    link: Link::named("look"),
                },
            ],
            spheres: Vec::new(),
            legs: None,
            posture: None,
            couplings: Vec::new(),
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
