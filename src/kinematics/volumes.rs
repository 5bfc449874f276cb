//! A posed chain's solids: each link that spans a distance is a capsule of
//! its radius about the segment between the frame origins it joins (the
//! last one, the effector's link, ends at the effector), and each sphere the
//! chain carries (the head) goes where its anchor frame takes it.
//!
//! Which of them may not meet each other: links two or more apart along the
//! chain (the hand and the trunk) may not overlap at all, nor a sphere and
//! the links two or more past its anchor (the head and the upper arm).
//! Neighbouring links (the forearm and the upper arm) must overlap near
//! their joint, and flesh gives where they fold (the forearm presses into
//! the biceps at full elbow flexion): what is refused is one passing
//! through the other, its axis entering the other's core (half its
//! radius) beyond the joint's own reach (the two radii summed). A
//! neighbouring link is therefore no licence for an upper arm through the
//! chest.

use nalgebra::{IsometryMatrix3, Point3};

use super::chain::Chain;
use crate::geometry::Capsule;

/// What a volume is: a link (by the index of the joint it ends at; the
/// chain's length for the effector's link) or a carried sphere.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Owner {
    Link(usize),
    Rider(usize),
}

/// The chain's solids in one posture, in the base frame.
#[derive(Clone, Debug)]
pub struct Volumes {
    pub capsules: Vec<Capsule>,
    pub owners: Vec<Owner>,
    /// Each volume's place along the chain: links count 0, 1, 2 from the
    /// base; a sphere takes the place of the link that ends at its anchor
    /// (-1 on the base itself).
    order: Vec<i64>,
}

/// How two of a chain's volumes may meet.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Contact {
    /// They may not overlap.
    Apart,
    /// Neighbouring links: the second may not pass through the first.
    NotThrough,
}

impl Volumes {
    /// The pairs of volumes that are checked against each other, by index
    /// (the earlier first), and how.
    pub fn self_pairs(&self) -> impl Iterator<Item = (usize, usize, Contact)> + '_ {
        let n = self.capsules.len();
        (0..n).flat_map(move |i| {
            (i + 1..n).filter_map(move |j| self.contact(i, j).map(|c| (i, j, c)))
        })
    }

    fn contact(&self, i: usize, j: usize) -> Option<Contact> {
        let lines = self.capsules[i].radius_mm <= 0.0 || self.capsules[j].radius_mm <= 0.0;
        let apart = (self.order[i] - self.order[j]).abs();
        match (self.owners[i], self.owners[j]) {
            _ if lines => None,
            (Owner::Rider(_), Owner::Rider(_)) => None,
            (Owner::Link(_), Owner::Link(_)) if apart == 1 => Some(Contact::NotThrough),
            _ => (apart >= 2).then_some(Contact::Apart),
        }
    }

    /// The first pair of volumes that meet as they may not.
    pub fn self_hit(&self) -> Option<(usize, usize)> {
        self.self_pairs()
            .find(|&(i, j, contact)| self.meet(i, j, contact))
            .map(|(i, j, _)| (i, j))
    }

    fn meet(&self, i: usize, j: usize, contact: Contact) -> bool {
        let (first, second) = (&self.capsules[i], &self.capsules[j]);
        let ([lo1, hi1], [lo2, hi2]) = (first.bounds(), second.bounds());
        if (0..3).any(|k| hi1[k] < lo2[k] || hi2[k] < lo1[k]) {
            return false;
        }
        match contact {
            Contact::Apart => first.overlaps(second),
            Contact::NotThrough => {
                // The second link starts where the first ends, at their
                // joint.
                let joint_reach = first.radius_mm + second.radius_mm;
                let axis = Capsule::new(second.a, second.b, 0.0);
                let core = Capsule::new(first.a, first.b, first.radius_mm / 2.0);
                axis.outside_ball(&second.a, joint_reach)
                    .is_some_and(|beyond| beyond.overlaps(&core))
            }
        }
    }
}

impl Chain {
    /// The name of a volume's part ("the right forearm", "the head").
    pub fn volume_name(&self, owner: Owner) -> &str {
        match owner {
            Owner::Link(j) if j < self.joints.len() => &self.joints[j].link.name,
            Owner::Link(_) => &self.effector_link.name,
            Owner::Rider(k) => &self.riders[k].name,
        }
    }

    /// The solids of posture `q`, in the base frame.
    pub fn volumes(&self, q: &[f64]) -> Volumes {
        self.volumes_of(
            self.joints
                .iter()
                .zip(q)
                .map(|(joint, &qj)| joint.transform(qj)),
        )
    }

    /// The solids of the posture whose joints' own transforms (each in its
    /// parent's frame, in chain order) are `locals`.
    pub fn volumes_of(&self, locals: impl Iterator<Item = IsometryMatrix3<f64>>) -> Volumes {
        let mut v = Volumes {
            capsules: Vec::with_capacity(self.joints.len() + 1 + self.riders.len()),
            owners: Vec::new(),
            order: Vec::new(),
        };
        let mut frame = IsometryMatrix3::identity();
        let mut frames = Vec::with_capacity(self.joints.len());
        let mut last = Point3::origin();
        let mut links: i64 = 0;
        // The place along the chain of the link ending at each joint.
        let mut order_at = Vec::with_capacity(self.joints.len());
        for (j, (joint, local)) in self.joints.iter().zip(locals).enumerate() {
            frame *= local;
            frames.push(frame);
            let origin = Point3::from(frame.translation.vector);
            if (origin - last).norm() > 1e-6 {
                v.push(
                    Capsule::new(last, origin, joint.link.radius_mm),
                    Owner::Link(j),
                    links,
                );
                links += 1;
                last = origin;
            }
            order_at.push(links - 1);
        }
        let effector = frame * Point3::from(self.effector_mm);
        if (effector - last).norm() > 1e-6 {
            let owner = Owner::Link(self.joints.len());
            v.push(
                Capsule::new(last, effector, self.effector_link.radius_mm),
                owner,
                links,
            );
        }
        for (k, rider) in self.riders.iter().enumerate() {
            let (at, place) = match rider.anchor {
                Some(a) => (frames[a], order_at[a]),
                None => (IsometryMatrix3::identity(), -1),
            };
            let centre = at * Point3::from(rider.centre_mm);
            v.push(
                Capsule::sphere(centre, rider.radius_mm),
                Owner::Rider(k),
                place,
            );
        }
        v
    }
}

/// A chain in one posture, each joint's own transform kept, so that the
/// solids of the posture with one joint moved cost one joint's sine and
/// cosine rather than every joint's (a descent that checks each move).
pub struct Posed<'c> {
    chain: &'c Chain,
    locals: Vec<IsometryMatrix3<f64>>,
}

impl<'c> Posed<'c> {
    pub fn new(chain: &'c Chain, q: &[f64]) -> Self {
        Posed {
            chain,
            locals: chain
                .joints
                .iter()
                .zip(q)
                .map(|(j, &qj)| j.transform(qj))
                .collect(),
        }
    }

    /// Joint `i` moved to `value`.
    pub fn set(&mut self, i: usize, value: f64) {
        self.locals[i] = self.chain.joints[i].transform(value);
    }

    /// The solids with joint `i` at `value`, the others as they are.
    pub fn volumes_with(&self, i: usize, value: f64) -> Volumes {
        let moved = self.chain.joints[i].transform(value);
        let locals = self.locals.iter().enumerate();
        self.chain
            .volumes_of(locals.map(|(k, local)| if k == i { moved } else { *local }))
    }

    /// The solids as they are.
    pub fn volumes(&self) -> Volumes {
        self.chain.volumes_of(self.locals.iter().copied())
    }
}

impl Volumes {
    fn push(&mut self, capsule: Capsule, owner: Owner, order: i64) {
        self.capsules.push(capsule);
        self.owners.push(owner);
        self.order.push(order);
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::kinematics::chain::revolute;
    use crate::kinematics::{Joint, Link, Rider};
    use nalgebra::Vector3;

    /// A planar arm of three links along x (100, 200, 300 mm), radius 10,
    /// a sphere on the base 50 mm up.
    fn arm() -> Chain {
        let joint = |name: &str, a_mm| Joint {
            link: Link {
                name: name.into(),
                radius_mm: 10.0,
            },
            ..revolute(name, 0.0, 0.0, 0.0, a_mm)
        };
        let mut chain = Chain::new(
            vec![
                joint("a", 100.0),
                joint("spin", 0.0),
                joint("b", 200.0),
                joint("c", 300.0),
            ],
            "tip",
            Vector3::zeros(),
        );
        chain.riders.push(Rider {
            name: "ball".into(),
            anchor: None,
            centre_mm: Vector3::new(0.0, 0.0, 50.0),
            radius_mm: 20.0,
        });
        chain
    }

    #[test]
    fn links_that_span_a_distance_are_capsules_and_riders_spheres() {
        let chain = arm();
        let v = chain.volumes(&[0.0; 4]);
        let names: Vec<&str> = v.owners.iter().map(|&o| chain.volume_name(o)).collect();
        assert_eq!(
            names,
            ["a", "b", "c", "ball"],
            "the joint that spins in place has no link"
        );
        assert!((v.capsules[2].b - Point3::new(600.0, 0.0, 0.0)).norm() < 1e-9);
        assert_eq!(v.capsules[3].a, Point3::new(0.0, 0.0, 50.0));
    }

    #[test]
    fn neighbours_along_the_chain_may_touch_others_may_not() {
        let v = arm().volumes(&[0.0; 4]);
        let pairs: Vec<(usize, usize, Contact)> = v.self_pairs().collect();
        // a-b and b-c neighbours; a-c (0, 2); the ball (on the base, place
        // -1) with b (1) and c (2).
        use Contact::{Apart, NotThrough};
        let expected = [
            (0, 1, NotThrough),
            (0, 2, Apart),
            (1, 2, NotThrough),
            (1, 3, Apart),
            (2, 3, Apart),
        ];
        assert_eq!(pairs, expected);
    }

    #[test]
    fn a_neighbour_may_fold_against_a_link_but_not_pass_through_it() {
        let chain = arm();
        // b folded back 150 degrees onto a: it presses into a near their
        // joint, as a forearm into the biceps.
        let folded = chain.volumes(&[0.0, 0.0, 150f64.to_radians(), 0.0]);
        assert!(folded.capsules[0].overlaps(&folded.capsules[1]));
        assert_eq!(folded.self_hit(), None);
        // Folded right back, b's axis runs down a's core.
        let through = chain.volumes(&[0.0, 0.0, 179f64.to_radians(), 0.0]);
        assert_eq!(through.self_hit(), Some((0, 1)));
    }
}
