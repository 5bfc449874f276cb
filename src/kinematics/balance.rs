//! Standing balance: a standing person holds a posture only while their
//! centre of mass stays over their feet. The legs have no joints; they
//! lean about the ankles instead, the feet up to [`LEAN_MAX_RAD`] ahead of
//! or behind the hips, as a person moves the hips back to lean forward.
//! A posture is held where some such lean puts the support under the
//! centre of mass: within [`SUPPORT_SHARE`] of the way from the ankles to
//! the toes, the heels or the feet's outer edges.
//!
//! The mass: the legs carry [`LEGS_MASS_SHARE`] of it (Dempster's
//! segments, via Winter), the rest is spread over the chain's solids and
//! its ballast (the other arm) by their volumes, each at its middle.

use nalgebra::Vector2;

use super::legs::Legs;
use super::volumes::Volumes;
use crate::geometry::{Capsule, Shape, Solid};

/// The legs' share of the body's mass: 0.161 each (Dempster, via Winter,
/// *Biomechanics and Motor Control of Human Movement*, table 4.1).
pub const LEGS_MASS_SHARE: f64 = 0.322;

/// How far the centre of mass may go from the ankles towards the edge of
/// the feet (the toes, the heels, the outer edges), as a share of the
/// way: fitted so that the standing people reach forwards as far as
/// measured people do (functional reach, Duncan et al. 1990;
/// docs/calibration.md).
pub const SUPPORT_SHARE: f64 = 0.6;

/// The most the straight legs lean from the vertical about the ankles,
/// forwards or back (assumed: the hips then drop at most 1.5 % of the
/// legs' height, 13 mm for the 50th-percentile man, which the model does
/// not lower them by).
pub const LEAN_MAX_RAD: f64 = 10.0 * std::f64::consts::PI / 180.0;

/// A standing person's legs and feet, for the balance of a posture.
#[derive(Clone, Debug, PartialEq)]
pub struct Balance {
    legs: Legs,
    /// The legs' solids standing straight, the feet under the hips: made
    /// once, since every posture checked with its feet there asks for them.
    upright: Vec<Solid>,
    /// How far to the left of the midplane the upper body's centre of
    /// mass is at rest: a posture's is taken from there, since a person
    /// standing at rest is balanced side to side whatever the mannequin
    /// models of them (`std::arm` has one arm).
    rest_left_mm: f64,
    /// The legs' centre of mass (x, y) with the feet under the hips, and
    /// how far it moves forward per millimetre the feet move forward.
    legs_centre_mm: Vector2<f64>,
    legs_follow: f64,
}

/// Why a standing posture is not held: no lean of the legs puts the
/// feet under the centre of mass (it tips one way), or the feet have no
/// room where it needs them.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum Tipping {
    Forward,
    Back,
    Sideways,
    /// The feet meet the room (or the moving arm) where the balance needs
    /// them: a plinth at the toes, a box stood in.
    NoFooting,
}

impl Tipping {
    /// In words, after "their balance".
    pub fn words(self) -> &'static str {
        match self {
            Tipping::Forward => "tipping forwards",
            Tipping::Back => "tipping backwards",
            Tipping::Sideways => "tipping sideways",
            Tipping::NoFooting => "no room for the feet where it needs them",
        }
    }
}

impl Balance {
    /// The balance over `legs` of an upper body whose centre of mass at
    /// rest is `rest_left_mm` to the left of the midplane.
    pub fn new(legs: Legs, rest_left_mm: f64) -> Self {
        const PROBE_MM: f64 = 100.0;
        let at = |feet_mm: f64| {
            let moved = Vector2::new(feet_mm, 0.0);
            centre(legs.standing_feet_moved(moved).iter().map(solid))
        };
        let under = at(0.0).unwrap_or_else(Vector2::zeros);
        let forward = at(PROBE_MM).unwrap_or_else(Vector2::zeros);
        Balance {
            legs_follow: (forward.x - under.x) / PROBE_MM,
            legs_centre_mm: under,
            upright: legs.standing(),
            legs,
            rest_left_mm,
        }
    }

    pub fn legs(&self) -> &Legs {
        &self.legs
    }

    /// The legs' solids standing straight, the feet under the hips
    /// ([`Legs::standing`]).
    pub fn upright_legs(&self) -> &[Solid] {
        &self.upright
    }

    /// The most the feet move from under the hips, any way.
    pub fn feet_shift_max_mm(&self) -> f64 {
        (self.legs.hip_height_mm - self.legs.ankle_height_mm) * LEAN_MAX_RAD.sin()
    }

    /// Where the feet must be, moved from under the hip point (forward, to
    /// the left), for the body in the posture of `v` to keep its balance:
    /// the least lean of the legs that does; or which way it tips.
    pub fn feet_moved_mm(&self, v: &Volumes) -> Result<Vector2<f64>, Tipping> {
        let mut upper = upper_centre_mm(v).unwrap_or_else(Vector2::zeros);
        upper.y -= self.rest_left_mm;
        let share = LEGS_MASS_SHARE;
        let body = upper * (1.0 - share) + self.legs_centre_mm * share;
        // The centre's place over the feet moved `s` is `body - s * gain`
        // (the legs' own centre follows the feet part of the way).
        let gain = 1.0 - share * self.legs_follow;
        let legs = &self.legs;
        let side_mm = legs.hip_width_mm / 2.0 + legs.foot_radius_mm;
        let forward = least_move(
            body.x,
            legs.toe_ahead_of_ankle_mm(),
            legs.heel_behind_ankle_mm(),
            gain,
        );
        let sideways = least_move(body.y, side_mm, side_mm, gain);
        let moved = Vector2::new(forward, sideways);
        if moved.norm() <= self.feet_shift_max_mm() {
            Ok(moved)
        } else if forward.abs() < sideways.abs() {
            Err(Tipping::Sideways)
        } else if forward > 0.0 {
            Err(Tipping::Forward)
        } else {
            Err(Tipping::Back)
        }
    }
}

/// The least move of the feet along one axis that puts a centre of mass at
/// `at_mm` (with the feet under the hips; it moves back `gain` of each
/// millimetre the feet move) within [`SUPPORT_SHARE`] of the way to the
/// edges `ahead_mm` and `behind_mm` from the ankles.
fn least_move(at_mm: f64, ahead_mm: f64, behind_mm: f64, gain: f64) -> f64 {
    let least = (at_mm - SUPPORT_SHARE * ahead_mm) / gain;
    let most = (at_mm + SUPPORT_SHARE * behind_mm) / gain;
    0f64.max(least).min(most)
}

/// Where the centre of mass of a posture's solids `v` (the chain's and
/// its ballast) is, seen from above (none where they have no volume).
pub fn upper_centre_mm(v: &Volumes) -> Option<Vector2<f64>> {
    centre(v.capsules.iter().chain(&v.ballast).map(capsule))
}

/// A solid's volume and its middle, for the mass it stands for.
fn solid(s: &Solid) -> (f64, Vector2<f64>) {
    match &s.shape {
        Shape::Capsule(c) => capsule(c),
        other => {
            let [lo, hi] = other.bounds();
            let size = hi - lo;
            let middle = (lo.coords + hi.coords) / 2.0;
            (size.x * size.y * size.z, middle.xy())
        }
    }
}

fn capsule(c: &Capsule) -> (f64, Vector2<f64>) {
    use std::f64::consts::PI;
    let r = c.radius_mm;
    let volume = PI * r * r * ((c.b - c.a).norm() + 4.0 / 3.0 * r);
    (volume, nalgebra::center(&c.a, &c.b).coords.xy())
}

/// The volume-weighted middle of `parts` (none where they have no volume).
fn centre(parts: impl Iterator<Item = (f64, Vector2<f64>)>) -> Option<Vector2<f64>> {
    let (mass, moment) = parts.fold((0.0, Vector2::zeros()), |(m, s), (v, p)| (m + v, s + p * v));
    (mass > 0.0).then(|| moment / mass)
}

#[cfg(test)]
mod tests {
    use super::super::legs::tests::legs;
    use super::*;
    use crate::geometry::Capsule;
    use nalgebra::Point3;

    /// A trunk 430 mm long of radius 126 mm leaning forwards by `lean`,
    /// a head on it, and both arms (600 mm, radius 50 mm) from its top,
    /// raised forwards by `arms_deg` from hanging.
    fn body(lean_deg: f64, arms_deg: f64) -> Volumes {
        let (s, c) = lean_deg.to_radians().sin_cos();
        let top = Point3::new(430.0 * s, 0.0, 430.0 * c);
        let (a, b) = arms_deg.to_radians().sin_cos();
        let hand = top + nalgebra::Vector3::new(600.0 * a, 0.0, -600.0 * b);
        let mut v = Volumes::default();
        v.capsules.push(Capsule::new(Point3::origin(), top, 126.0));
        v.capsules.push(Capsule::new(top * 1.15, top * 1.15, 89.0));
        v.capsules.push(Capsule::new(top, hand, 50.0));
        v.ballast.push(Capsule::new(top, hand, 50.0));
        v
    }

    #[test]
    fn upright_the_feet_stay_under_the_hips() {
        let b = Balance::new(legs(), 0.0);
        assert_eq!(b.feet_moved_mm(&body(0.0, 0.0)), Ok(Vector2::zeros()));
        assert_eq!(b.feet_moved_mm(&body(0.0, 180.0)), Ok(Vector2::zeros()));
    }

    #[test]
    fn leaning_forwards_the_feet_go_ahead_and_too_far_it_tips() {
        let b = Balance::new(legs(), 0.0);
        let mut last = 0.0;
        let mut tipped = None;
        for lean in (0..=90).step_by(5) {
            match b.feet_moved_mm(&body(lean as f64, 90.0)) {
                Ok(s) => {
                    assert!(tipped.is_none(), "held again at {lean} deg");
                    assert!(s.x >= last && s.norm() <= b.feet_shift_max_mm() + 1e-9);
                    assert_eq!(s.y, 0.0);
                    last = s.x;
                }
                Err(t) => {
                    assert_eq!(t, Tipping::Forward);
                    tipped.get_or_insert(lean);
                }
            }
        }
        assert!(last > 0.0, "the feet moved forward as it leaned");
        // A load held far ahead (a heavy pan at arm's length) tips it.
        let mut laden = body(45.0, 90.0);
        let pan = Point3::new(1200.0, 0.0, 0.0);
        laden.ballast.push(Capsule::new(pan, pan, 120.0));
        assert_eq!(b.feet_moved_mm(&laden), Err(Tipping::Forward));
    }

    #[test]
    fn leaning_back_or_sideways_tips_the_other_way() {
        let b = Balance::new(legs(), 0.0);
        assert_eq!(b.feet_moved_mm(&body(-90.0, -90.0)), Err(Tipping::Back));
        // Leaning sideways the feet go the other way, up to a point.
        let mut side = body(0.0, 0.0);
        for c in side.capsules.iter_mut().chain(&mut side.ballast) {
            (c.a.y, c.a.z, c.b.y, c.b.z) = (c.a.z, c.a.y, c.b.z, c.b.y);
        }
        let moved = b.feet_moved_mm(&side).expect("held, the feet moved");
        assert!(moved.y > 0.0 && moved.x == 0.0, "{moved}");
        let pan = Point3::new(0.0, 1200.0, 0.0);
        side.ballast.push(Capsule::new(pan, pan, 120.0));
        assert_eq!(b.feet_moved_mm(&side), Err(Tipping::Sideways));
    }

    #[test]
    fn the_hips_drop_as_the_legs_lean() {
        let l = legs();
        assert_eq!(l.hip_drop_mm(0.0), 0.0);
        let max = Balance::new(l.clone(), 0.0).feet_shift_max_mm();
        let drop = l.hip_drop_mm(max);
        assert!(
            (drop - 862.0 * (1.0 - LEAN_MAX_RAD.cos())).abs() < 1e-6,
            "{drop}"
        );
    }
}
