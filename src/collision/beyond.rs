//! A proof that no posture of a person reaches a point from one placement,
//! so that the search need not try again where nothing can succeed.
//!
//! The chain is cut after its trunk: the first joints, which turn about
//! axes through the hip point and carry the trunk (and the head), and the
//! arm beyond them. Whatever the arm does, the effector is no farther from
//! the shoulder's pivot than the arm's links laid end to end; and the
//! shoulder goes only where the trunk, within its joint limits, stays out
//! of the person's own legs and base (the check the search makes, the
//! pelvis's give included). A branch and bound over the trunk's joint
//! ranges looks for a box of trunk postures that may be clear of the body
//! and may bring the shoulder within the arm's length of the point; where
//! there is none, the point is out of reach.
//!
//! Each box is judged at its centre, with a bound on how far its postures
//! move a point `p`: the trunk's joints turn about axes `u_i` through the
//! hip point, so a change `d_i` of each moves `p` by at most
//! `sum |u_i x p| |d_i| + |p| (sum |d_i|)^2 / 2` (Taylor's theorem: the
//! second derivatives of a turned point are no longer than the point's
//! distance from the hip). A box that has a clear posture whose shoulder
//! is within the arm's length ends the proof at once: the cut cannot tell.
//!
//! The proof leaves out the room, the arm's own solids and its joint
//! limits, so it is sound but not complete: where it cannot decide within
//! its budget of boxes, the search tries as before. Made with the trunk's
//! limits alone (`decide_by_limits`, the body left out), it proves a point
//! beyond the trunk's reach and the arm's length: no posture comes within
//! the tolerance at all.

use std::cmp::Ordering;
use std::collections::BinaryHeap;

use nalgebra::{IsometryMatrix3, Point3, Vector3};

use crate::geometry::Capsule;
use crate::kinematics::{Chain, Joint, JointKind};
use crate::scene::OwnBody;

/// The cut of a chain after its trunk, for one person's own body.
pub struct OutOfReach<'a> {
    chain: &'a Chain,
    own: &'a OwnBody,
    /// How many joints the trunk has (the first ones of the chain).
    trunk_joints: usize,
    /// The shoulder's pivot in the frame of the trunk's last joint: a
    /// point the next joint does not move; where the shoulder girdle
    /// slides it, the line it slides along, from `pivot_mm` to
    /// `pivot_end_mm` (the same point where nothing slides it).
    pivot_mm: Point3<f64>,
    pivot_end_mm: Point3<f64>,
    /// The farthest the effector can be from the pivot.
    arm_mm: f64,
    /// The solids the trunk carries (the head, the neck): index of the
    /// rider.
    riders: Vec<usize>,
}

/// How many boxes of trunk postures [`OutOfReach::proves`] looks at
/// before it gives up (about half a millisecond).
pub const BOXES: usize = 1024;
/// The most trunk joints the proof splits.
const MOST_TRUNK_JOINTS: usize = 4;

/// A box of trunk postures: each joint's least and greatest value (the
/// first `OutOfReach::trunk_joints` are used).
type Ranges = [(f64, f64); MOST_TRUNK_JOINTS];

/// What a proof found.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Verdict {
    /// No posture reaches the point.
    Proved,
    /// A clear trunk posture brings the shoulder within the arm's length:
    /// the cut cannot rule the point out, however long it looks.
    Cannot,
    /// Not decided within the boxes it was given: more might.
    Undecided,
}

/// What a proof keeps the trunk within.
#[derive(Clone, Copy)]
enum Cut {
    /// The joint limits, and out of the person's own body and base.
    Body,
    /// The joint limits alone.
    Limits,
}

/// A box waiting to be looked at, and the nearest its parent's postures
/// may bring the shoulder to the point.
struct Boxed {
    nearest_mm: f64,
    ranges: Ranges,
}

impl PartialEq for Boxed {
    fn eq(&self, other: &Self) -> bool {
        self.cmp(other).is_eq()
    }
}

impl Eq for Boxed {}

impl PartialOrd for Boxed {
    fn partial_cmp(&self, other: &Self) -> Option<Ordering> {
        Some(self.cmp(other))
    }
}

impl Ord for Boxed {
    /// The nearer the greater (first out of the heap).
    fn cmp(&self, other: &Self) -> Ordering {
        other.nearest_mm.total_cmp(&self.nearest_mm)
    }
}

/// The trunk in one posture: each joint's axis through the hip point and
/// each joint's frame (the last the trunk's).
struct Trunk {
    joints: usize,
    axes: [Vector3<f64>; MOST_TRUNK_JOINTS],
    frames: [IsometryMatrix3<f64>; MOST_TRUNK_JOINTS],
}

impl Trunk {
    fn frame(&self) -> &IsometryMatrix3<f64> {
        &self.frames[self.joints - 1]
    }

    /// How far a point at `p` may move when each joint moves by up to
    /// `half_rad[i]`.
    fn moves_mm(&self, p: &Point3<f64>, half_rad: &[f64]) -> f64 {
        let spread: f64 = half_rad.iter().sum();
        let first: f64 = self
            .axes
            .iter()
            .zip(half_rad)
            .map(|(u, h)| u.cross(&p.coords).norm() * h)
            .sum();
        first + 0.5 * p.coords.norm() * spread * spread
    }
}

/// The shoulder's pivot in the frame of the trunk's last joint (the ends
/// of the line it slides along, or one point twice), how far the next
/// joints may carry the arm's start from it, and the first joint beyond
/// them. A revolute joint moves its frame's origin about its own z axis:
/// the part along the axis is the pivot's (in the frame it moves in, after
/// its `pre` frame). A slide first (the shoulder girdle rising with the
/// arm) carries that pivot along a line.
fn shoulder_pivot(joints: &[Joint], first: usize) -> ([Point3<f64>; 2], f64, usize) {
    let turn = |j: &Joint| {
        let offset = j.rest_offset_mm();
        let pivot = j.axis_frame() * Point3::new(0.0, 0.0, offset.z);
        (pivot, offset.x.hypot(offset.y))
    };
    let shoulder = &joints[first];
    match (shoulder.kind, joints.get(first + 1)) {
        (JointKind::Revolute, _) => {
            let (pivot, from) = turn(shoulder);
            ([pivot; 2], from, first + 1)
        }
        (JointKind::Prismatic, Some(next)) if next.kind == JointKind::Revolute => {
            let (pivot, from) = turn(next);
            let ends = [shoulder.min, shoulder.max].map(|q| shoulder.transform(q) * pivot);
            (ends, from, first + 2)
        }
        (JointKind::Prismatic, _) => {
            let pivot = shoulder.axis_frame() * Point3::origin();
            let slide = shoulder.longest_offset_mm() - pivot.coords.norm();
            ([pivot; 2], slide, first + 1)
        }
    }
}

/// The point of the line from `ends[0]` to `ends[1]` nearest `target`.
fn nearest_on(ends: [Point3<f64>; 2], target: &Point3<f64>) -> Point3<f64> {
    let along = ends[1] - ends[0];
    let length_sq = along.norm_squared();
    if length_sq == 0.0 {
        return ends[0];
    }
    let t = ((target - ends[0]).dot(&along) / length_sq).clamp(0.0, 1.0);
    ends[0] + along * t
}

impl<'a> OutOfReach<'a> {
    /// The cut of `chain` for a person whose own body and base are `own`;
    /// none where the chain has no trunk of this kind (joints that turn
    /// about the hip point, then a link with a solid) or there is no body
    /// to meet.
    pub fn of(chain: &'a Chain, own: &'a OwnBody) -> Option<Self> {
        if own.solids.is_empty() {
            return None;
        }
        let joints = &chain.joints;
        let last = joints.iter().position(|j| j.longest_offset_mm() > 1e-9)?;
        let trunk_joints = last + 1;
        let turning = joints[..trunk_joints]
            .iter()
            .all(|j| j.kind == JointKind::Revolute);
        let has_solid = joints[last].link.radius_mm > 0.0;
        joints.get(trunk_joints)?;
        if !turning || !has_solid || trunk_joints > MOST_TRUNK_JOINTS {
            return None;
        }
        let ([pivot_mm, pivot_end_mm], from_pivot_mm, next) = shoulder_pivot(joints, trunk_joints);
        let beyond_mm: f64 = joints[next..].iter().map(|j| j.longest_offset_mm()).sum();
        let riders = (0..chain.riders.len())
            .filter(|&k| chain.riders[k].anchor.is_some_and(|a| a <= last))
            .collect();
        Some(OutOfReach {
            chain,
            own,
            trunk_joints,
            pivot_mm,
            pivot_end_mm,
            arm_mm: from_pivot_mm + beyond_mm + chain.effector_mm.norm(),
            riders,
        })
    }

    /// Whether no posture within the joint limits that keeps the trunk
    /// out of the person's own body brings the effector within
    /// `tolerance_mm` of `target_mm` (in the base frame), looking at up to
    /// [`BOXES`] boxes. False where the proof cannot tell.
    pub fn proves(&self, target_mm: &Point3<f64>, tolerance_mm: f64) -> bool {
        self.decide(target_mm, tolerance_mm, BOXES) == Verdict::Proved
    }

    /// The proof that no posture within the joint limits that keeps the
    /// trunk out of the person's own body brings the effector within
    /// `tolerance_mm` of `target_mm` (in the base frame), looking at up to
    /// `boxes` boxes of trunk postures.
    pub fn decide(&self, target_mm: &Point3<f64>, tolerance_mm: f64, boxes: usize) -> Verdict {
        self.decide_looking(target_mm, tolerance_mm, boxes).0
    }

    /// [`OutOfReach::decide`], and how many boxes it looked at.
    pub fn decide_looking(
        &self,
        target_mm: &Point3<f64>,
        tolerance_mm: f64,
        boxes: usize,
    ) -> (Verdict, usize) {
        self.branch_and_bound(target_mm, tolerance_mm, boxes, Cut::Body)
    }

    /// The proof that no posture within the trunk's joint limits, whether
    /// or not it keeps out of the person's own body, brings the effector
    /// within `tolerance_mm` of `target_mm`: the point is beyond the
    /// trunk's limits and the arm's length. Then no posture comes within
    /// the tolerance at all (a solver's posture there is not even blocked).
    pub fn decide_by_limits(
        &self,
        target_mm: &Point3<f64>,
        tolerance_mm: f64,
        boxes: usize,
    ) -> Verdict {
        self.decide_by_limits_looking(target_mm, tolerance_mm, boxes)
            .0
    }

    /// [`OutOfReach::decide_by_limits`], and how many boxes it looked at.
    pub fn decide_by_limits_looking(
        &self,
        target_mm: &Point3<f64>,
        tolerance_mm: f64,
        boxes: usize,
    ) -> (Verdict, usize) {
        self.branch_and_bound(target_mm, tolerance_mm, boxes, Cut::Limits)
    }

    fn branch_and_bound(
        &self,
        target_mm: &Point3<f64>,
        tolerance_mm: f64,
        boxes: usize,
        cut: Cut,
    ) -> (Verdict, usize) {
        let reach_mm = self.arm_mm + tolerance_mm;
        let n = self.trunk_joints;
        let mut root: Ranges = [(0.0, 0.0); MOST_TRUNK_JOINTS];
        for (range, joint) in root.iter_mut().zip(&self.chain.joints[..n]) {
            *range = (joint.min, joint.max);
        }
        // Most promising first (the nearest the shoulder may come): a clear
        // posture within reach, which ends the proof, is found soonest;
        // a proof looks at every box whatever the order.
        let mut waiting = BinaryHeap::from([Boxed {
            nearest_mm: 0.0,
            ranges: root,
        }]);
        let mut looked = 0;
        while let Some(Boxed { ranges, .. }) = waiting.pop() {
            looked += 1;
            if looked > boxes {
                return (Verdict::Undecided, boxes);
            }
            if !self.couplings_admit(&ranges[..n]) {
                // No posture of this box is within the coupled limits.
                continue;
            }
            let mut q = [0.0; MOST_TRUNK_JOINTS];
            let mut half = [0.0; MOST_TRUNK_JOINTS];
            for (i, (lo, hi)) in ranges[..n].iter().enumerate() {
                q[i] = 0.5 * (lo + hi);
                half[i] = 0.5 * (hi - lo);
            }
            let (q, half) = (&q[..n], &half[..n]);
            let trunk = self.trunk_at(q);
            let ends = [self.pivot_mm, self.pivot_end_mm].map(|p| trunk.frame() * p);
            let pivot = nearest_on(ends, target_mm);
            let to_target = pivot - target_mm;
            let centre_mm = to_target.norm();
            // How near the pivot may come within the box: a point's move
            // along the line to the target; where the pivot slides, the
            // better of two bounds: the line's nearest point less the
            // farthest either end moves (no point of the line moves
            // farther), and its middle's move along the line to the target
            // less half its length.
            let middle = Point3::from((ends[0].coords + ends[1].coords) / 2.0);
            let to_middle = middle - target_mm;
            let by_middle = to_middle.norm()
                - self.pivot_gain_mm(&trunk, &middle, &to_middle, half)
                - (ends[1] - ends[0]).norm() / 2.0;
            let nearest_mm = if ends[0] == ends[1] {
                by_middle
            } else {
                let moves = ends.iter().map(|e| trunk.moves_mm(e, half));
                by_middle.max(centre_mm - moves.fold(0.0, f64::max))
            };
            if nearest_mm > reach_mm {
                continue;
            }
            let solids = match cut {
                Cut::Body => self.solids(&trunk),
                Cut::Limits => Vec::new(),
            };
            if solids.iter().any(|c| self.always_meets(&trunk, c, half)) {
                continue;
            }
            let mut centre: Ranges = [(0.0, 0.0); MOST_TRUNK_JOINTS];
            for (c, &v) in centre.iter_mut().zip(q) {
                *c = (v, v);
            }
            if centre_mm <= reach_mm
                && self.couplings_admit(&centre[..n])
                && solids.iter().all(|c| self.own.hit(c).is_none())
            {
                // A clear trunk posture with the shoulder within the arm's
                // length: the cut cannot rule the point out.
                return (Verdict::Cannot, looked);
            }
            let widest = self.widest(&trunk, &pivot, half);
            let (lo, hi) = ranges[widest];
            let mid = 0.5 * (lo + hi);
            let (mut upper, mut lower) = (ranges, ranges);
            upper[widest].0 = mid;
            lower[widest].1 = mid;
            for ranges in [upper, lower] {
                waiting.push(Boxed { nearest_mm, ranges });
            }
        }
        (Verdict::Proved, looked)
    }

    /// Whether some posture in the box of trunk joint `ranges` keeps every
    /// coupling of the trunk's joints (one that couples a joint beyond the
    /// trunk is left out: the box may then hold more than the limits let
    /// the trunk take, which keeps the proof sound).
    fn couplings_admit(&self, ranges: &[(f64, f64)]) -> bool {
        self.chain
            .couplings
            .iter()
            .all(|c| c.admits_some(&self.chain.joints, ranges))
    }

    /// The trunk at joint values `q`.
    fn trunk_at(&self, q: &[f64]) -> Trunk {
        let mut trunk = Trunk {
            joints: q.len(),
            axes: [Vector3::zeros(); MOST_TRUNK_JOINTS],
            frames: [IsometryMatrix3::identity(); MOST_TRUNK_JOINTS],
        };
        let mut frame = IsometryMatrix3::identity();
        for (i, (joint, &qj)) in self.chain.joints.iter().zip(q).enumerate() {
            trunk.axes[i] = (frame * joint.axis_frame()).rotation * Vector3::z();
            frame *= joint.transform(qj);
            trunk.frames[i] = frame;
        }
        trunk
    }

    /// How much nearer the target the pivot may come within the box: the
    /// first-order change along the line to the target, and the second-
    /// order bound.
    fn pivot_gain_mm(
        &self,
        trunk: &Trunk,
        pivot: &Point3<f64>,
        to_target: &Vector3<f64>,
        half_rad: &[f64],
    ) -> f64 {
        let along = to_target
            .try_normalize(1e-12)
            .unwrap_or_else(Vector3::zeros);
        let spread: f64 = half_rad.iter().sum();
        let first: f64 = trunk
            .axes
            .iter()
            .zip(half_rad)
            .map(|(u, h)| along.dot(&u.cross(&pivot.coords)).abs() * h)
            .sum();
        let directional = first + 0.5 * pivot.coords.norm() * spread * spread;
        directional.min(trunk.moves_mm(pivot, half_rad))
    }

    /// The trunk's solids in its posture, in the base frame, as the chain
    /// makes them: the link from the hip point to the last joint's origin
    /// and the solids it carries.
    fn solids(&self, trunk: &Trunk) -> Vec<Capsule> {
        let last = self.trunk_joints - 1;
        let top = Point3::from(trunk.frame().translation.vector);
        let mut solids = Vec::with_capacity(1 + self.riders.len());
        if top.coords.norm() > 1e-6 {
            let radius = self.chain.joints[last].link.radius_mm;
            solids.push(Capsule::new(Point3::origin(), top, radius));
        }
        for &k in &self.riders {
            let rider = &self.chain.riders[k];
            let frame = trunk.frames[rider.anchor.unwrap_or(last)];
            solids.push(rider.capsule_at(&frame));
        }
        solids
    }

    /// Whether every posture of the box runs `solid` (as the search checks
    /// it, the part within the pelvis cut away) into the person's own
    /// body: it overlaps a part at the box's centre by more than it can
    /// move.
    fn always_meets(&self, trunk: &Trunk, solid: &Capsule, half_rad: &[f64]) -> bool {
        let Some(cut) = self.own.outside_pelvis(solid) else {
            return false;
        };
        // The pelvis is a ball about the hip point, which the trunk turns
        // about: the cut turns with the solid.
        let moves_mm = trunk
            .moves_mm(&cut.a, half_rad)
            .max(trunk.moves_mm(&cut.b, half_rad));
        self.own.sunk_deeper_than(&cut, moves_mm)
    }

    /// The joint whose half of the box moves the pivot or the trunk's top
    /// the most: the one to split.
    fn widest(&self, trunk: &Trunk, pivot: &Point3<f64>, half_rad: &[f64]) -> usize {
        let top = Point3::from(trunk.frame().translation.vector);
        let reach = |i: usize| {
            let u = &trunk.axes[i];
            u.cross(&pivot.coords)
                .norm()
                .max(u.cross(&top.coords).norm())
                * half_rad[i]
                + 1e-9 * half_rad[i]
        };
        (0..half_rad.len())
            .max_by(|&a, &b| reach(a).total_cmp(&reach(b)))
            .unwrap_or(0)
    }
}
