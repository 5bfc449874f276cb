//! A posed chain's solids: each link that spans a distance is a capsule of
//! its radius about the segment between the frame origins it joins (the
//! last one, the effector's link, ends at the effector), and each solid the
//! chain carries (the head, the neck) goes where its anchor frame takes it.
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
#[derive(Clone, Debug, Default)]
pub struct Volumes {
    pub capsules: Vec<Capsule>,
    pub owners: Vec<Owner>,
    /// Each volume's place along the chain: links count 0, 1, 2 from the
    /// base; a sphere takes the place of the link that ends at its anchor
    /// (-1 on the base itself).
    order: Vec<i64>,
    /// How each volume moved since a posture known to be clear (all
    /// [`Motion::Moved`] when there is none): what a check may skip.
    pub motion: Vec<Motion>,
    /// The chain's ballast (`Chain::ballast`) where the posture carries
    /// it: for where the body's mass is, not checked against anything.
    pub ballast: Vec<Capsule>,
}

/// How a volume moved when one joint of a posture moved.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Motion {
    /// Not at all (a link before the joint).
    Still,
    /// With everything past the joint, as one rigid piece: two such
    /// volumes keep their distance.
    Rigid,
    /// Any other way, or unknown.
    Moved,
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
        self.pairs_where(|_, _| true)
    }

    /// The pairs of [`Volumes::self_pairs`] that `keep` keeps, asked before
    /// how they may meet.
    fn pairs_where<'a>(
        &'a self,
        keep: impl Fn(usize, usize) -> bool + Copy + 'a,
    ) -> impl Iterator<Item = (usize, usize, Contact)> + 'a {
        let n = self.capsules.len();
        (0..n).flat_map(move |i| {
            (i + 1..n).filter_map(move |j| {
                let contact = keep(i, j).then(|| self.contact(i, j))??;
                Some((i, j, contact))
            })
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

    /// The first pair of volumes that meet as they may not (of the pairs
    /// whose distance may have changed since a clear posture).
    pub fn self_hit(&self) -> Option<(usize, usize)> {
        // Whether a pair moved apart is asked first: most pairs of a
        // one-joint move did not.
        self.pairs_where(|i, j| self.moved_apart(i, j))
            .find(|&(i, j, contact)| self.meet(i, j, contact))
            .map(|(i, j, _)| (i, j))
    }

    /// Whether volumes `i` and `j` may have moved relative to each other:
    /// not if neither moved, nor if both moved as one piece.
    fn moved_apart(&self, i: usize, j: usize) -> bool {
        !matches!(
            (self.motion[i], self.motion[j]),
            (Motion::Still, Motion::Still) | (Motion::Rigid, Motion::Rigid)
        )
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
        let locals: Vec<IsometryMatrix3<f64>> = locals.collect();
        let mut walk = Walk::new(self.joints.len());
        let mut v = Volumes::default();
        self.walk(&locals, &mut walk, 0, &mut v, None);
        v
    }

    /// Make the solids of joints `from..` (their frames and marks into
    /// `walk`, which holds those of the joints before `from`), then the
    /// effector's link and the riders, onto `v` (which holds the volumes
    /// of the joints before `from`). With `moved` (the joint moved since a
    /// clear posture, `from` itself) each volume says how it moved.
    pub(super) fn walk(
        &self,
        locals: &[IsometryMatrix3<f64>],
        walk: &mut Walk,
        from: usize,
        v: &mut Volumes,
        moved: Option<usize>,
    ) {
        let mut mark = if from == 0 {
            Mark::START
        } else {
            walk.marks[from]
        };
        let mut frame = if from == 0 {
            IsometryMatrix3::identity()
        } else {
            walk.frames[from - 1]
        };
        // A volume starting at the origin of frame `start` (-1: the
        // base's) moves rigidly with the joints past `moved`.
        let motion = |start: i64| match moved {
            Some(i) if start >= i as i64 => Motion::Rigid,
            _ => Motion::Moved,
        };
        for (j, joint) in self.joints.iter().enumerate().skip(from) {
            mark.pushed = v.capsules.len();
            walk.marks[j] = mark;
            frame *= locals[j];
            walk.frames[j] = frame;
            let origin = Point3::from(frame.translation.vector);
            if (origin - mark.last).norm() > 1e-6 {
                v.push(
                    Capsule::new(mark.last, origin, joint.link.radius_mm),
                    Owner::Link(j),
                    mark.links,
                    motion(mark.start),
                );
                // A bare segment (radius 0) is no solid: the solids either
                // side of it are neighbours.
                if joint.link.radius_mm > 0.0 {
                    mark.links += 1;
                }
                mark.last = origin;
                mark.start = j as i64;
            }
            walk.order_at[j] = mark.links - 1;
        }
        let effector = frame * Point3::from(self.effector_mm);
        if (effector - mark.last).norm() > 1e-6 {
            let owner = Owner::Link(self.joints.len());
            let capsule = Capsule::new(mark.last, effector, self.effector_link.radius_mm);
            v.push(capsule, owner, mark.links, motion(mark.start));
        }
        for (k, rider) in self.riders.iter().enumerate() {
            let (at, place, motion) = match rider.anchor {
                Some(a) => {
                    let motion = match moved {
                        Some(i) if a < i => Motion::Still,
                        _ => motion(a as i64),
                    };
                    (walk.frames[a], walk.order_at[a], motion)
                }
                None if moved.is_some() => (IsometryMatrix3::identity(), -1, Motion::Still),
                None => (IsometryMatrix3::identity(), -1, Motion::Moved),
            };
            v.push(rider.capsule_at(&at), Owner::Rider(k), place, motion);
        }
        v.ballast.clear();
        for rider in &self.ballast {
            let at = rider
                .anchor
                .map_or_else(IsometryMatrix3::identity, |a| walk.frames[a]);
            v.ballast.push(rider.capsule_at(&at));
        }
    }
}

/// Where a walk along the chain stands before a joint: the volumes it has
/// made, the point the next link starts from and the frame whose origin it
/// is (-1: the base's), and the links made.
#[derive(Clone, Copy, Debug)]
pub(super) struct Mark {
    pub pushed: usize,
    last: Point3<f64>,
    start: i64,
    links: i64,
}

impl Mark {
    const START: Mark = Mark {
        pushed: 0,
        last: Point3::new(0.0, 0.0, 0.0),
        start: -1,
        links: 0,
    };
}

/// What a walk keeps per joint: its frame in the base frame, the place
/// along the chain of the link ending at it, and the mark before it.
#[derive(Clone, Debug)]
pub(super) struct Walk {
    pub frames: Vec<IsometryMatrix3<f64>>,
    pub order_at: Vec<i64>,
    pub marks: Vec<Mark>,
}

impl Walk {
    pub fn new(joints: usize) -> Self {
        Walk {
            frames: vec![IsometryMatrix3::identity(); joints],
            order_at: vec![0; joints],
            marks: vec![Mark::START; joints],
        }
    }

    /// Take `other`'s frames and places of the joints before `end`, and
    /// its marks up to the one before `end`: what a walk from `end` reads.
    pub fn copy_prefix(&mut self, other: &Walk, end: usize) {
        self.frames[..end].copy_from_slice(&other.frames[..end]);
        self.order_at[..end].copy_from_slice(&other.order_at[..end]);
        let marks = (end + 1).min(self.marks.len());
        self.marks[..marks].copy_from_slice(&other.marks[..marks]);
    }
}

impl Volumes {
    fn push(&mut self, capsule: Capsule, owner: Owner, order: i64, motion: Motion) {
        self.capsules.push(capsule);
        self.owners.push(owner);
        self.order.push(order);
        self.motion.push(motion);
    }

    /// Keep the first `n` volumes.
    pub(super) fn truncate(&mut self, n: usize) {
        self.capsules.truncate(n);
        self.owners.truncate(n);
        self.order.truncate(n);
        self.motion.truncate(n);
    }

    /// The first `n` of `other`'s volumes, each marked still.
    pub(super) fn copy_still(&mut self, other: &Volumes, n: usize) {
        self.truncate(0);
        self.capsules.extend_from_slice(&other.capsules[..n]);
        self.owners.extend_from_slice(&other.owners[..n]);
        self.order.extend_from_slice(&other.order[..n]);
        self.motion.resize(n, Motion::Still);
    }

    /// Mark every volume moved (a posture checked in full).
    pub(super) fn all_moved(&mut self) {
        self.motion.fill(Motion::Moved);
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
        chain.riders.push(Rider::sphere(
            "ball",
            None,
            Vector3::new(0.0, 0.0, 50.0),
            20.0,
        ));
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
