//! The legs of a mannequin, which no joint moves: its dimensions, and the
//! thighs, shanks and feet they give in the base frame (x forward, y to
//! the left, z up, origin at the hip point), seated on a seat or standing
//! on the floor. The base decides which and where the seat is.

use nalgebra::{Point3, Vector2, Vector3};

use crate::geometry::{Capsule, Shape, Solid};

/// Whether a mannequin sits or stands.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Stance {
    Seated,
    Standing,
}

impl Stance {
    pub fn word(self) -> &'static str {
        match self {
            Stance::Seated => "seated",
            Stance::Standing => "standing",
        }
    }
}

/// Leg dimensions, millimetres.
#[derive(Clone, Debug, PartialEq)]
pub struct Legs {
    /// Standing: the floor to the hip point, to the knee joint, to the
    /// ankle joint.
    pub hip_height_mm: f64,
    pub knee_height_mm: f64,
    pub ankle_height_mm: f64,
    /// Heel to toe.
    pub foot_mm: f64,
    /// Between the two hip joints.
    pub hip_width_mm: f64,
    pub thigh_radius_mm: f64,
    pub shank_radius_mm: f64,
    pub foot_radius_mm: f64,
    /// Seated: the hip point above the seat.
    pub hip_above_seat_mm: f64,
    /// The ball about the hip point where the trunk meets the seat and
    /// the thighs without counting as a collision: the pelvis and the
    /// abdomen, which fold as the trunk leans forward.
    pub pelvis_mm: f64,
}

/// The part of the foot behind the ankle joint.
const HEEL_FRACTION: f64 = 0.2;

impl Legs {
    pub fn thigh_mm(&self) -> f64 {
        self.hip_height_mm - self.knee_height_mm
    }

    pub fn shank_mm(&self) -> f64 {
        self.knee_height_mm - self.ankle_height_mm
    }

    /// Standing straight, feet flat and forward, in the base frame. Each
    /// thigh's solid starts a thigh radius below its hip joint, so that its
    /// rounded top ends at the joint's height: above it is the pelvis (the
    /// iliac crest and the waist), which the trunk bends over, not the
    /// thigh. (Started at the joint, a sideways bend within the trunk's
    /// range met the top of the thigh.)
    pub fn standing(&self) -> Vec<Solid> {
        self.standing_feet_moved(Vector2::zeros())
    }

    /// Standing with the feet moved `feet_mm` (forward, to the left) from
    /// under the hip point, legs straight and the hips at the same height:
    /// the legs lean about the ankles as the hips move back (or sideways)
    /// over the feet. A real person's hips drop by what the lean shortens
    /// the legs' height ([`Legs::hip_drop_mm`]).
    pub fn standing_feet_moved(&self, feet_mm: Vector2<f64>) -> Vec<Solid> {
        let knee_z = -self.thigh_mm();
        let ankle_z = knee_z - self.shank_mm();
        let thigh_top_z = (-self.thigh_radius_mm).max(knee_z);
        self.solids(|side| {
            let y = side * self.hip_width_mm / 2.0;
            let at = |z: f64| {
                let moved = feet_mm * (z / ankle_z);
                Point3::new(moved.x, y + moved.y, z)
            };
            [at(thigh_top_z), at(knee_z), at(ankle_z)]
        })
    }

    /// How much lower the hips of straight legs are with the feet moved
    /// `moved_mm` from under them than over them.
    pub fn hip_drop_mm(&self, moved_mm: f64) -> f64 {
        let legs_mm = self.hip_height_mm - self.ankle_height_mm;
        legs_mm - (legs_mm.powi(2) - moved_mm.powi(2)).max(0.0).sqrt()
    }

    /// Where the ankle joints are along the foot: the heel
    /// `HEEL_FRACTION` of the foot behind, the toe the rest ahead.
    pub fn heel_behind_ankle_mm(&self) -> f64 {
        HEEL_FRACTION * self.foot_mm
    }

    pub fn toe_ahead_of_ankle_mm(&self) -> f64 {
        (1.0 - HEEL_FRACTION) * self.foot_mm
    }

    /// Seated: thighs level on the seat (`hip_above_seat` below the hip
    /// point), shanks down and `shank_forward_rad` forward of the vertical,
    /// feet level, in the base frame.
    pub fn seated(&self, shank_forward_rad: f64) -> Vec<Solid> {
        let thigh_z = -self.hip_above_seat_mm + self.thigh_radius_mm;
        let (s, c) = shank_forward_rad.sin_cos();
        self.solids(|side| {
            let y = side * self.hip_width_mm / 2.0;
            let knee = Point3::new(self.thigh_mm(), y, thigh_z);
            [
                Point3::new(0.0, y, thigh_z),
                knee,
                knee + Vector3::new(s, 0.0, -c) * self.shank_mm(),
            ]
        })
    }

    /// Thighs, shanks and feet from the hip, knee and ankle joints of each
    /// side (left is +1).
    fn solids(&self, joints: impl Fn(f64) -> [Point3<f64>; 3]) -> Vec<Solid> {
        let mut out = Vec::new();
        for (side, word) in [(1.0, "left"), (-1.0, "right")] {
            let [hip, knee, ankle] = joints(side);
            let heel = ankle - Vector3::x() * (HEEL_FRACTION * self.foot_mm);
            let toe =
                ankle + Vector3::x() * ((1.0 - HEEL_FRACTION) * self.foot_mm - self.foot_radius_mm);
            let capsule = |a, b, r| Shape::Capsule(Capsule::new(a, b, r));
            out.push(Solid::new(
                format!("the {word} thigh"),
                capsule(hip, knee, self.thigh_radius_mm),
            ));
            out.push(Solid::new(
                format!("the {word} shank"),
                capsule(knee, ankle, self.shank_radius_mm),
            ));
            out.push(Solid::new(
                format!("the {word} foot"),
                capsule(heel, toe, self.foot_radius_mm),
            ));
        }
        out
    }
}

#[cfg(test)]
pub(super) mod tests {
    use super::*;

    /// The 50th-percentile man's legs (Drillis & Contini fractions of
    /// 1755 mm; ANSUR II radii).
    pub(in crate::kinematics) fn legs() -> Legs {
        Legs {
            hip_height_mm: 930.0,
            knee_height_mm: 500.0,
            ankle_height_mm: 68.0,
            foot_mm: 270.0,
            hip_width_mm: 190.0,
            thigh_radius_mm: 99.0,
            shank_radius_mm: 62.0,
            foot_radius_mm: 40.0,
            hip_above_seat_mm: 100.0,
            pelvis_mm: 300.0,
        }
    }

    fn capsule(solids: &[Solid], name: &str) -> Capsule {
        match &solids.iter().find(|s| s.name == name).unwrap().shape {
            Shape::Capsule(c) => *c,
            s => panic!("{s:?}"),
        }
    }

    #[test]
    fn standing_legs_reach_from_the_hip_to_the_ankles() {
        let s = legs().standing();
        let shank = capsule(&s, "the right shank");
        assert!(
            (shank.b.z + 930.0 - 68.0).abs() < 1e-9,
            "ankle 68 mm above the floor"
        );
        assert_eq!(shank.b.y, -95.0);
        assert_eq!(s.len(), 6);
        let thigh = capsule(&s, "the left thigh");
        assert!(
            (thigh.a.z + thigh.radius_mm).abs() < 1e-9,
            "the thigh's rounded top at the hip joint's height"
        );
    }

    #[test]
    fn seated_thighs_lie_on_the_seat_and_shanks_lean_forward() {
        let s = legs().seated(20f64.to_radians());
        let thigh = capsule(&s, "the left thigh");
        // The thigh's underside is on the seat, 100 mm below the hip point.
        assert!((thigh.a.z - thigh.radius_mm + 100.0).abs() < 1e-9);
        assert!(
            (thigh.b.x - 430.0).abs() < 1e-9,
            "knee a thigh's length ahead"
        );
        let shank = capsule(&s, "the left shank");
        assert!(shank.b.x > shank.a.x && shank.b.z < shank.a.z);
        assert!(((shank.b - shank.a).norm() - 432.0).abs() < 1e-9);
    }
}
