//! A mannequin's joints as a tree: each joint follows a parent joint (or the
//! base), so a spine can carry two arms and a head, and each effector sits
//! on one joint. The chain of an effector is the path from the base to it,
//! which is what the solvers work on; several effectors share the joints
//! their paths have in common.

use nalgebra::{Point3, Vector3};

use super::chain::{Chain, Joint, Link, Rider};
use super::coupling::Coupling;
use super::legs::{Legs, Stance};
use super::mirror::flips_of_twin;

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
    /// What point of the body it is ("the centre of a power grasp"), as
    /// its mannequin says; empty where it says nothing.
    pub point: String,
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
    pub posture: Option<Stance>,
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
                point: chain.effector_point,
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

    /// The twin of effector `asked` on the other hand, where the body has
    /// one (`left_grip` for `grip`, and back).
    pub fn twin_of(&self, asked: usize) -> Option<usize> {
        self.effector_index(&twin_name(&self.effectors[asked].name))
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
    /// spheres and the links off its path that hold them to it
    /// ([`Body::holding_links`]), those joints at their neutral values.
    pub fn chain(&self, index: usize) -> Chain {
        self.chain_at(index, None)
    }

    /// [`Body::chain`], carrying the solids off its path where `q` (a
    /// value for each joint of the body) puts them: a hand's chain as it
    /// is while another task's joints (the eyes', turning the head) hold
    /// their own posture.
    pub fn chain_posed(&self, index: usize, q: &[f64]) -> Chain {
        self.chain_at(index, Some(q))
    }

    fn chain_at(&self, index: usize, q: Option<&[f64]>) -> Chain {
        let mut chain = self.own_chain_at(index, q);
        if hand_side(&chain.effector_name) == "left" {
            if let Some(twin) = self.twin_of(index) {
                chain.mirror_of_twin = flips_of_twin(&chain, &self.own_chain_at(twin, None));
            }
        }
        chain
    }

    /// The chain of effector `index`, drawing its own starts.
    fn own_chain_at(&self, index: usize, q: Option<&[f64]>) -> Chain {
        let effector = &self.effectors[index];
        let path = self.path(effector.joint);
        Chain {
            joints: path.iter().map(|&i| self.joints[i].clone()).collect(),
            effector_name: effector.name.clone(),
            effector_mm: effector.offset_mm,
            effector_link: effector.link.clone(),
            effector_point: effector.point.clone(),
            riders: self
                .riders_at(&path, q)
                .into_iter()
                .map(|(_, r)| r)
                .collect(),
            ballast: self.ballast_at(&path, q),
            couplings: self.couplings_on(&path),
            mirror_of_twin: Vec::new(),
        }
    }

    /// The solids a chain along `path` carries, in its order, each with
    /// the body joint it sits on (`None`: the base): the spheres, then the
    /// links that hold them to it.
    pub fn riders_on(&self, path: &[usize]) -> Vec<(Option<usize>, Rider)> {
        self.riders_at(path, None)
    }

    /// [`Body::riders_on`], the joints off `path` at `q`'s values (a value
    /// for each joint of the body; none: neutral).
    fn riders_at(&self, path: &[usize], q: Option<&[f64]>) -> Vec<(Option<usize>, Rider)> {
        let carry = Carry {
            body: self,
            path,
            q,
        };
        let spheres = self.spheres.iter().map(|s| (s.joint, carry.sphere(s)));
        let links = self.holding_links(path).into_iter();
        let links = links.filter_map(|j| Some((Some(j), carry.link(j)?)));
        spheres.chain(links).collect()
    }

    /// The links off `path` that a chain along it neither moves nor
    /// carries (the other arm), as it would carry them: where the body's
    /// mass is besides the chain's own solids.
    fn ballast_at(&self, path: &[usize], q: Option<&[f64]>) -> Vec<Rider> {
        let carry = Carry {
            body: self,
            path,
            q,
        };
        let held = self.holding_links(path);
        (0..self.joints.len())
            .filter(|j| !path.contains(j) && !held.contains(j))
            .filter_map(|j| carry.link(j))
            .collect()
    }

    /// The joints off `path` between it and a sphere (the neck's, under
    /// the head), each once, in body order: a chain along `path` carries
    /// their links, at their neutral values, with the spheres. Other
    /// branches (the other arm) are not carried.
    pub fn holding_links(&self, path: &[usize]) -> Vec<usize> {
        let mut joints: Vec<usize> = self
            .spheres
            .iter()
            .flat_map(|s| self.path(s.joint))
            .filter(|j| !path.contains(j))
            .collect();
        joints.sort_unstable();
        joints.dedup();
        joints
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

    /// The chain of the effector named, or of the first.
    pub fn chain_named(&self, effector: Option<&str>) -> Option<Chain> {
        let index = match effector {
            Some(name) => self.effector_index(name)?,
            None => 0,
        };
        Some(self.chain(index))
    }
}

/// How a chain along `path` carries the body's solids off it: the joints
/// between at `q`'s values (a value for each joint of the body), or at
/// their neutral ones.
struct Carry<'b> {
    body: &'b Body,
    path: &'b [usize],
    q: Option<&'b [f64]>,
}

impl Carry<'_> {
    /// Sphere `s` as the chain carries it.
    fn sphere(&self, s: &Sphere) -> Rider {
        let (anchor, centre) = self.carried(Point3::from(s.centre_mm), s.joint);
        Rider::sphere(&s.name, anchor, centre.coords, s.radius_mm)
    }

    /// The link of joint `j` (off the path) as the chain carries it: from
    /// its parent's frame origin to its own. None where it is not a solid
    /// (no radius, or no length).
    fn link(&self, j: usize) -> Option<Rider> {
        let body = self.body;
        let joint = &body.joints[j];
        let end = joint.transform(self.value(j)) * Point3::origin();
        if joint.link.radius_mm <= 0.0 || end.coords.norm() <= 1e-6 {
            return None;
        }
        let (anchor, from) = self.carried(Point3::origin(), body.parents[j]);
        let (_, to) = self.carried(end, body.parents[j]);
        Some(Rider {
            name: joint.link.name.clone(),
            anchor,
            from_mm: from.coords,
            to_mm: to.coords,
            radius_mm: joint.link.radius_mm,
        })
    }

    fn value(&self, j: usize) -> f64 {
        self.q.map_or(self.body.joints[j].neutral, |q| q[j])
    }

    /// Point `p` in the frame of `joint` as the chain carries it: in the
    /// frame of the last joint of the path among `joint`'s ancestors (its
    /// place on the chain).
    fn carried(&self, mut p: Point3<f64>, joint: Option<usize>) -> (Option<usize>, Point3<f64>) {
        let mut at = joint;
        while let Some(j) = at {
            if self.path.contains(&j) {
                break;
            }
            p = self.body.joints[j].transform(self.value(j)) * p;
            at = self.body.parents[j];
        }
        (at.and_then(|j| self.path.iter().position(|&q| q == j)), p)
    }
}

/// The prefix that names an effector of the left hand: `left_grip` is the
/// twin of `grip`.
pub const LEFT_PREFIX: &str = "left_";

/// The name of the twin of effector `name` on the other hand.
pub fn twin_name(name: &str) -> String {
    match name.strip_prefix(LEFT_PREFIX) {
        Some(right) => right.to_string(),
        None => format!("{LEFT_PREFIX}{name}"),
    }
}

/// Which hand effector `name` is on: `left` for `left_` and a name, else
/// `right`.
pub fn hand_side(name: &str) -> &'static str {
    if name.starts_with(LEFT_PREFIX) {
        "left"
    } else {
        "right"
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

    /// A spine carrying an arm to the grip and a neck to the eyes.
    fn spine_arm_neck() -> Body {
        Body {
            joints: ["spine", "arm", "hand", "neck"].map(joint).to_vec(),
            parents: vec![None, Some(0), Some(1), Some(0)],
            effectors: vec![
                Effector {
                    name: "grip".into(),
                    joint: Some(2),
                    offset_mm: Vector3::zeros(),
                    link: Link::named("hand"),
                    point: String::new(),
                },
                Effector {
                    name: "eyes".into(),
                    joint: Some(3),
                    offset_mm: Vector3::zeros(),
                    link: Link::named("look"),
                    point: String::new(),
                },
            ],
            spheres: Vec::new(),
            legs: None,
            posture: None,
            couplings: Vec::new(),
        }
    }

    #[test]
    fn two_effectors_share_the_spine() {
        let body = spine_arm_neck();
        let names = |c: Chain| c.joints.into_iter().map(|j| j.name).collect::<Vec<_>>();
        assert_eq!(names(body.chain(0)), ["spine", "arm", "hand"]);
        assert_eq!(
            names(body.chain_named(Some("eyes")).unwrap()),
            ["spine", "neck"]
        );
        assert!(body.chain_named(Some("feet")).is_none());
    }

    #[test]
    fn a_hand_carries_the_head_and_the_neck_that_holds_it_but_not_the_other_arm() {
        let mut body = spine_arm_neck();
        body.joints.push(joint("other_arm"));
        body.parents.push(Some(0));
        body.spheres.push(Sphere {
            name: "head".into(),
            joint: Some(3),
            centre_mm: Vector3::new(0.0, 0.0, 50.0),
            radius_mm: 90.0,
        });
        let hand = body.chain(0);
        let riders: Vec<&str> = hand.riders.iter().map(|r| r.name.as_str()).collect();
        assert_eq!(riders, ["head", "neck"], "the other arm is not carried");
        // The neck from the spine's end to its own, 100 mm on, in the
        // spine's frame; the head at the neck's end, 50 mm up.
        let neck = &hand.riders[1];
        assert_eq!(neck.anchor, Some(0));
        assert!(neck.from_mm.norm() < 1e-9);
        assert!((neck.to_mm - Vector3::new(100.0, 0.0, 0.0)).norm() < 1e-9);
        assert!((hand.riders[0].from_mm - Vector3::new(100.0, 0.0, 50.0)).norm() < 1e-9);
        // The eyes' chain moves the neck itself: it carries the head only.
        let eyes = body.chain(1);
        let riders: Vec<&str> = eyes.riders.iter().map(|r| r.name.as_str()).collect();
        assert_eq!(riders, ["head"]);
        // Posed: the neck turned a quarter turn carries its end round.
        let mut q = vec![0.0; body.joints.len()];
        q[3] = std::f64::consts::FRAC_PI_2;
        let turned = body.chain_posed(0, &q);
        assert!((turned.riders[1].to_mm - Vector3::new(0.0, 100.0, 0.0)).norm() < 1e-9);
        assert!((turned.riders[0].from_mm - Vector3::new(0.0, 100.0, 50.0)).norm() < 1e-9);
        // A link that is no solid is not carried.
        body.joints[3].link.radius_mm = 0.0;
        assert_eq!(body.chain(0).riders.len(), 1);
    }
}
