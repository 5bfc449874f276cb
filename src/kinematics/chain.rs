//! A serial chain of joints from the base (the hip) to one effector, with
//! each joint's limits, neutral value and comfort weight, and its forward
//! kinematics as the plain product of DH matrices (eq. 4-5).

use nalgebra::{IsometryMatrix3, Point3, Vector3};

use super::coupling::{Coupling, Limited};
use super::dh::Dh;
use crate::geometry::Capsule;

#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum JointKind {
    /// The variable is an angle added to theta (radians).
    Revolute,
    /// The variable is a length added to d (millimetres).
    Prismatic,
}

/// The solid of a link: a capsule about the segment the link spans, of
/// this radius, called this in reports ("the right forearm").
#[derive(Clone, Debug, PartialEq)]
pub struct Link {
    pub name: String,
    pub radius_mm: f64,
}

impl Link {
    /// The radius of a link whose mannequin gives none (DH and URDF
    /// mannequins without `radius`): assumed, about a forearm's.
    pub const DEFAULT_RADIUS_MM: f64 = 30.0;

    /// A link of the default radius.
    pub fn named(name: &str) -> Self {
        Link {
            name: name.to_string(),
            radius_mm: Self::DEFAULT_RADIUS_MM,
        }
    }
}

/// One joint. `min`, `max` and `neutral` are in radians for revolute joints
/// and millimetres for prismatic ones, relative to the DH table's values.
#[derive(Clone, Debug, PartialEq)]
pub struct Joint {
    pub name: String,
    pub kind: JointKind,
    pub dh: Dh,
    /// A joint not given by DH parameters (one read from URDF): it turns
    /// about (or slides along) the z axis of the previous frame, then this
    /// fixed pose follows; `dh` is then unused.
    pub fixed: Option<IsometryMatrix3<f64>>,
    /// A fixed frame between the previous joint's frame and this joint's
    /// motion (a mannequin's `fixed` joint folded in): the joint turns
    /// about (or slides along) the z axis of that frame.
    pub pre: Option<IsometryMatrix3<f64>>,
    pub min: f64,
    pub max: f64,
    /// The range no person's own limits may go beyond (the mannequin's
    /// `anatomical`); `None`: not said.
    pub anatomical: Option<(f64, f64)>,
    pub neutral: f64,
    pub weight: f64,
    /// The link from the previous joint's frame origin to this one's.
    pub link: Link,
}

impl Joint {
    /// A joint that cannot move: a fixed pose in a chain of joints.
    pub fn locked(name: &str, pose: IsometryMatrix3<f64>) -> Joint {
        Joint {
            name: name.to_string(),
            kind: JointKind::Revolute,
            dh: Dh::default(),
            fixed: Some(pose),
            pre: None,
            min: 0.0,
            max: 0.0,
            anatomical: None,
            neutral: 0.0,
            weight: 0.0,
            link: Link::named(name),
        }
    }

    /// The pose of this joint's frame in the previous one at value `q`.
    pub fn transform(&self, q: f64) -> IsometryMatrix3<f64> {
        match &self.pre {
            Some(pre) => pre * self.own_transform(q),
            None => self.own_transform(q),
        }
    }

    /// The pose of the frame the joint moves in (its axis is that frame's
    /// z) in the previous joint's frame: the identity unless it has a
    /// `pre` frame.
    pub fn axis_frame(&self) -> IsometryMatrix3<f64> {
        self.pre.unwrap_or_else(IsometryMatrix3::identity)
    }

    /// [`Joint::transform`] without the `pre` frame.
    fn own_transform(&self, q: f64) -> IsometryMatrix3<f64> {
        if let Some(fixed) = &self.fixed {
            let motion = match self.kind {
                JointKind::Revolute => IsometryMatrix3::rotation(Vector3::z() * q),
                JointKind::Prismatic => IsometryMatrix3::translation(0.0, 0.0, q),
            };
            return motion * fixed;
        }
        match self.kind {
            JointKind::Revolute => self.dh.transform(self.dh.theta_rad + q, self.dh.d_mm),
            JointKind::Prismatic => self.dh.transform(self.dh.theta_rad, self.dh.d_mm + q),
        }
    }

    /// Where this joint's frame origin is at value 0 in the frame the joint
    /// moves in (the previous frame, after its `pre` frame if it has one):
    /// `(a cos theta, a sin theta, d)` for a DH joint.
    pub fn rest_offset_mm(&self) -> Vector3<f64> {
        match &self.fixed {
            Some(fixed) => fixed.translation.vector,
            None => {
                let (s, c) = self.dh.theta_rad.sin_cos();
                Vector3::new(self.dh.a_mm * c, self.dh.a_mm * s, self.dh.d_mm)
            }
        }
    }

    pub fn range(&self) -> f64 {
        self.max - self.min
    }

    /// The farthest this joint's frame origin can be from the previous
    /// frame's origin, at any value within the limits.
    pub fn longest_offset_mm(&self) -> f64 {
        let pre_mm = self.pre.map_or(0.0, |p| p.translation.vector.norm());
        pre_mm + self.own_longest_offset_mm()
    }

    /// [`Joint::longest_offset_mm`] from the origin of the frame the joint
    /// moves in.
    fn own_longest_offset_mm(&self) -> f64 {
        let slide_mm = match self.kind {
            JointKind::Revolute => 0.0,
            JointKind::Prismatic => self.min.abs().max(self.max.abs()),
        };
        match &self.fixed {
            Some(fixed) => fixed.translation.vector.norm() + slide_mm,
            None if self.kind == JointKind::Prismatic => {
                self.dh.a_mm.hypot(self.dh.d_mm.abs() + slide_mm)
            }
            None => self.dh.a_mm.hypot(self.dh.d_mm),
        }
    }

    /// `q` moved into the limits.
    pub fn clamp(&self, q: f64) -> f64 {
        q.clamp(self.min, self.max)
    }

    /// The comfort cost of value `q`: weight times distance from neutral,
    /// radians for revolute joints and metres for prismatic ones.
    pub fn discomfort(&self, q: f64) -> f64 {
        let scale = match self.kind {
            JointKind::Revolute => 1.0,
            JointKind::Prismatic => 1e-3,
        };
        self.weight * (self.neutral - q).abs() * scale
    }
}

impl Limited for Joint {
    fn limits(&self) -> (f64, f64) {
        (self.min, self.max)
    }
}

/// A chain of joints ending in an effector.
#[derive(Clone, Debug, PartialEq)]
pub struct Chain {
    pub joints: Vec<Joint>,
    pub effector_name: String,
    /// The effector point in the frame of the last joint.
    pub effector_mm: Vector3<f64>,
    /// The link from the last joint's frame origin to the effector.
    pub effector_link: Link,
    /// What point of the body the effector is (its mannequin's `point`);
    /// empty where it says nothing.
    pub effector_point: String,
    /// Solids of the body the chain carries (a head and neck on the
    /// spine).
    pub riders: Vec<Rider>,
    /// The body's other solids (the other arm), carried as riders are but
    /// not solids of the chain: nothing is checked against them. They
    /// count only for where the body's mass is (standing balance).
    pub ballast: Vec<Rider>,
    /// Joints of the chain whose ranges are not independent.
    pub couplings: Vec<Coupling>,
    /// Empty: the chain draws its starts and kicks as they come. Else it
    /// is a left hand's chain drawn as the mirror image of its right
    /// twin's (`mirror.rs`): for each joint, whether its value is drawn
    /// negated (a joint turning about an axis in the body's midplane), and
    /// its seeds come from the target seen in the midplane.
    pub mirror_of_twin: Vec<bool>,
}

/// A solid of the body carried by a chain though no joint of the chain
/// moves it on its own: a sphere (the head), or a link off the chain that
/// holds a sphere to it (the neck). Its segment is in the frame of the
/// chain's joint `anchor` (`None`: the base), the joints between that one
/// and the solid's own, off the chain, at their neutral values; a sphere's
/// two ends are one point.
#[derive(Clone, Debug, PartialEq)]
pub struct Rider {
    pub name: String,
    pub anchor: Option<usize>,
    pub from_mm: Vector3<f64>,
    pub to_mm: Vector3<f64>,
    pub radius_mm: f64,
}

impl Rider {
    /// A sphere of `radius_mm` about `centre_mm` in the frame of `anchor`.
    pub fn sphere(
        name: &str,
        anchor: Option<usize>,
        centre_mm: Vector3<f64>,
        radius_mm: f64,
    ) -> Self {
        Rider {
            name: name.to_string(),
            anchor,
            from_mm: centre_mm,
            to_mm: centre_mm,
            radius_mm,
        }
    }

    /// The solid where the anchor's frame is `frame` (in the base frame).
    pub fn capsule_at(&self, frame: &IsometryMatrix3<f64>) -> Capsule {
        Capsule::new(
            frame * Point3::from(self.from_mm),
            frame * Point3::from(self.to_mm),
            self.radius_mm,
        )
    }

    /// The farthest its surface is from its anchor's origin.
    pub fn extent_mm(&self) -> f64 {
        self.from_mm.norm().max(self.to_mm.norm()) + self.radius_mm
    }
}

impl Chain {
    /// A chain of `joints` ending in effector `name` at `effector_mm` in the
    /// last joint's frame, its last link of the default radius, carrying
    /// nothing.
    pub fn new(joints: Vec<Joint>, name: &str, effector_mm: Vector3<f64>) -> Self {
        Chain {
            joints,
            effector_name: name.to_string(),
            effector_mm,
            effector_link: Link::named(name),
            effector_point: String::new(),
            riders: Vec::new(),
            ballast: Vec::new(),
            couplings: Vec::new(),
            mirror_of_twin: Vec::new(),
        }
    }

    /// Whether joint `i` is drawn negated, as its twin's seen in a mirror.
    pub fn drawn_negated(&self, i: usize) -> bool {
        self.mirror_of_twin.get(i).copied().unwrap_or(false)
    }

    /// What a reported distance is measured to: the effector's `point`,
    /// or its name.
    pub fn measured_to(&self) -> String {
        if self.effector_point.is_empty() {
            format!("the effector `{}`", self.effector_name)
        } else {
            self.effector_point.clone()
        }
    }

    pub fn dof(&self) -> usize {
        self.joints.len()
    }

    /// The most solids a posture of the chain has (`Chain::volumes`): a
    /// link for each joint and the effector, and the spheres it carries.
    /// What the meter counts a check of a posture by, without posing it.
    pub fn solids_at_most(&self) -> usize {
        self.joints.len() + 1 + self.riders.len()
    }

    /// The pose of the last frame in the base frame: `DH_0,n`.
    pub fn end_frame(&self, q: &[f64]) -> IsometryMatrix3<f64> {
        // From the first link's own pose rather than the identity times it
        // (the same numbers, one product fewer).
        let mut links = self.joints.iter().zip(q).map(|(j, &qi)| j.transform(qi));
        let first = links.next().unwrap_or_else(IsometryMatrix3::identity);
        links.fold(first, |acc, link| acc * link)
    }

    /// No posture puts a link point (a joint's frame origin or the
    /// effector) farther than this from the base origin: the sum of the
    /// links' longest lengths.
    pub fn reach_bound_mm(&self) -> f64 {
        let links_mm: f64 = self.joints.iter().map(Joint::longest_offset_mm).sum();
        links_mm + self.effector_mm.norm()
    }

    /// The largest radius of a link or a sphere the chain carries (a sphere
    /// may sit off the links: its centre's distance from its anchor
    /// counts too).
    pub fn thickest_mm(&self) -> f64 {
        let links = self
            .joints
            .iter()
            .map(|j| &j.link)
            .chain([&self.effector_link])
            .map(|l| l.radius_mm);
        let riders = self.riders.iter().map(Rider::extent_mm);
        links.chain(riders).fold(0.0, f64::max)
    }

    /// The effector point in the base frame (eq. 5).
    pub fn effector(&self, q: &[f64]) -> Point3<f64> {
        self.end_frame(q) * Point3::from(self.effector_mm)
    }

    /// The comfort criterion `C = sum_i w_i |theta_i^N - theta_i|` of
    /// section 5.3.4: smaller is more comfortable.
    pub fn discomfort(&self, q: &[f64]) -> f64 {
        self.joints
            .iter()
            .zip(q)
            .map(|(j, &qi)| j.discomfort(qi))
            .sum()
    }

    /// Whether every joint is given by DH parameters (the incremental
    /// kinematics of eq. 6-8 needs them).
    pub fn is_dh(&self) -> bool {
        self.joints.iter().all(|j| j.fixed.is_none())
    }

    /// Whether `q` keeps every joint within its limits and every coupling.
    pub fn within_limits(&self, q: &[f64]) -> bool {
        let each = self
            .joints
            .iter()
            .zip(q)
            .all(|(j, &qi)| qi >= j.min && qi <= j.max);
        each && self.couplings.iter().all(|c| c.admits(&self.joints, q))
    }

    /// The range joint `i` may take with the other joints where `q` has
    /// them: its limits, narrowed by the couplings it is in.
    pub fn interval(&self, i: usize, q: &[f64]) -> (f64, f64) {
        let joint = &self.joints[i];
        self.couplings
            .iter()
            .fold((joint.min, joint.max), |(lo, hi), c| {
                let (l, h) = c.interval(&self.joints, q, i);
                (lo.max(l), hi.min(h))
            })
    }

    /// Value `v` of joint `i` moved into its interval given the rest of `q`.
    pub fn clamp_joint(&self, i: usize, v: f64, q: &[f64]) -> f64 {
        if self.couplings.is_empty() {
            return self.joints[i].clamp(v);
        }
        let (lo, hi) = self.interval(i, q);
        v.clamp(lo, hi.max(lo))
    }

    /// `q` moved within every joint's limits, then every coupling's
    /// ellipse (each coupled group drawn in towards its centre).
    pub fn pull_in(&self, q: &mut [f64]) {
        for (qi, j) in q.iter_mut().zip(&self.joints) {
            *qi = j.clamp(*qi);
        }
        for c in &self.couplings {
            c.pull_in(&self.joints, q);
        }
    }

    /// The joints of `q` outside their limits, or in a coupling `q` breaks.
    pub fn beyond_limits(&self, q: &[f64]) -> Vec<usize> {
        let mut beyond: Vec<usize> = (0..self.joints.len())
            .filter(|&i| q[i] < self.joints[i].min || q[i] > self.joints[i].max)
            .collect();
        for c in self.couplings.iter().filter(|c| !c.admits(&self.joints, q)) {
            beyond.extend(c.joints());
        }
        beyond.sort_unstable();
        beyond.dedup();
        beyond
    }

    /// The neutral posture, drawn within the couplings if it breaks one
    /// (each joint's neutral lies within its own limits).
    pub fn neutral(&self) -> Vec<f64> {
        let mut q: Vec<f64> = self.joints.iter().map(|j| j.neutral).collect();
        for c in &self.couplings {
            c.pull_in(&self.joints, &mut q);
        }
        q
    }
}

/// For tests: a revolute joint of these DH parameters, limits +/-3 rad,
/// neutral 0, weight 1, its link of the default radius.
#[cfg(test)]
pub(crate) fn revolute(name: &str, theta_rad: f64, d_mm: f64, alpha_rad: f64, a_mm: f64) -> Joint {
    Joint {
        name: name.into(),
        kind: JointKind::Revolute,
        dh: Dh::new(theta_rad, d_mm, alpha_rad, a_mm),
        fixed: None,
        pre: None,
        min: -3.0,
        max: 3.0,
        anatomical: None,
        neutral: 0.0,
        weight: 1.0,
        link: Link::named(name),
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use std::f64::consts::FRAC_PI_2;

    /// A planar two-link arm (both axes along z, links 300 and 200 mm):
    /// the effector is at (300 cos q1 + 200 cos(q1 + q2), 300 sin q1 +
    /// 200 sin(q1 + q2), 0), worked out by hand.
    fn planar() -> Chain {
        Chain::new(
            vec![
                revolute("j1", 0.0, 0.0, 0.0, 300.0),
                revolute("j2", 0.0, 0.0, 0.0, 200.0),
            ],
            "tip",
            Vector3::zeros(),
        )
    }

    #[test]
    fn planar_arm_matches_the_closed_form() {
        let chain = planar();
        for &(q1, q2) in &[(0.0, 0.0), (0.5, -0.3), (FRAC_PI_2, FRAC_PI_2), (-1.2, 2.5)] {
            let p = chain.effector(&[q1, q2]);
            let x = 300.0 * f64::cos(q1) + 200.0 * f64::cos(q1 + q2);
            let y = 300.0 * f64::sin(q1) + 200.0 * f64::sin(q1 + q2);
            assert!((p - Point3::new(x, y, 0.0)).norm() < 1e-9, "{q1} {q2}: {p}");
        }
    }

    #[test]
    fn effector_offset_is_carried_by_the_last_frame() {
        let mut chain = planar();
        chain.effector_mm = Vector3::new(50.0, 0.0, 10.0);
        let p = chain.effector(&[0.0, FRAC_PI_2]);
        // The last frame points along +y at (300, 200, 0).
        assert!((p - Point3::new(300.0, 250.0, 10.0)).norm() < 1e-9, "{p}");
    }

    #[test]
    fn prismatic_joint_slides_along_z() {
        let mut j = revolute("slide", 0.0, 100.0, 0.0, 0.0);
        j.kind = JointKind::Prismatic;
        let chain = Chain::new(vec![j], "tip", Vector3::zeros());
        assert!((chain.effector(&[25.0]) - Point3::new(0.0, 0.0, 125.0)).norm() < 1e-12);
    }

    #[test]
    fn reach_bound_is_the_sum_of_the_links() {
        assert_eq!(planar().reach_bound_mm(), 500.0);
        let mut chain = planar();
        chain.joints[1].kind = JointKind::Prismatic;
        chain.joints[1].dh.d_mm = 30.0;
        chain.joints[1].min = -50.0;
        chain.joints[1].max = 40.0;
        // 300 + hypot(200, 30 + 50)
        assert!((chain.reach_bound_mm() - (300.0 + 200.0f64.hypot(80.0))).abs() < 1e-9);
    }

    #[test]
    fn discomfort_is_the_weighted_distance_from_neutral() {
        let mut chain = planar();
        chain.joints[1].weight = 2.0;
        chain.joints[1].neutral = 0.5;
        assert!((chain.discomfort(&[-0.25, 1.0]) - (0.25 + 2.0 * 0.5)).abs() < 1e-15);
    }
}
