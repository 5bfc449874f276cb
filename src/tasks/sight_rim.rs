//! The lines of sight to an object's rim. An object of size S (a letter's
//! height, a dial) is made out only where its middle is seen whole:
//! besides the line to its centre, lines from the eyes to eight points of
//! a circle of diameter S / 2 about it, square to the line of sight, must
//! meet nothing. A letter whose top or bottom quarter is hidden still
//! reads; one seen through a slit narrower than it does not (a 2 mm slit
//! half way to a sign of 20 mm letters shows a strip 4 mm high of them),
//! nor one whose line of sight clears a board's edge by a millimetre.
//!
//! Each rim line stops that circle's diameter short of its end, measured
//! along it, and leaves out the obstacles within half the object's size
//! of its centre: what is that close is what the object lies on or is
//! fixed to (a label on a cabinet's front, seen at a slant, would
//! otherwise be hidden by the cabinet at its rim), or something just in
//! front of it, which the line to its centre checks.

use nalgebra::{Point3, Vector3};

/// How many points of the rim are looked at.
const RIM_POINTS: usize = 8;

/// The rim's diameter, as a share of the object's size.
const RIM_SHARE: f64 = 0.5;

/// Where the lines of sight from `eye_mm` to the rim of the middle of an
/// object of `size_mm` at `object_mm` end; none where the object is within
/// the rim's diameter of the eyes (the line to its centre alone is
/// checked then).
pub(super) fn rim_ends(
    eye_mm: &Point3<f64>,
    object_mm: &Point3<f64>,
    size_mm: f64,
) -> Vec<Point3<f64>> {
    let rim_mm = RIM_SHARE * size_mm;
    let to_object = object_mm - eye_mm;
    let length = to_object.norm();
    if length <= rim_mm || rim_mm <= 0.0 {
        return Vec::new();
    }
    let along = to_object / length;
    let (u, v) = square_to(&along);
    (0..RIM_POINTS)
        .map(|k| {
            let angle = std::f64::consts::TAU * k as f64 / RIM_POINTS as f64;
            let rim = object_mm + (u * angle.cos() + v * angle.sin()) * (0.5 * rim_mm);
            let to_rim = rim - eye_mm;
            eye_mm + to_rim * (1.0 - rim_mm / to_rim.norm())
        })
        .collect()
}

/// How far from the object's centre an obstacle the rim lines leave out
/// may be: half its size.
pub(super) fn holding_mm(size_mm: f64) -> f64 {
    0.5 * size_mm
}

/// Two unit vectors square to `along` (a unit vector) and to each other.
fn square_to(along: &Vector3<f64>) -> (Vector3<f64>, Vector3<f64>) {
    let helper = if along.z.abs() < 0.9 {
        Vector3::z()
    } else {
        Vector3::x()
    };
    let u = along.cross(&helper).normalize();
    let v = along.cross(&u);
    (u, v)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_rim_lines_end_short_on_a_circle_of_half_the_size_about_the_line_of_sight() {
        let eye = Point3::new(0.0, 0.0, 1500.0);
        let object = Point3::new(2000.0, 0.0, 1500.0);
        let ends = rim_ends(&eye, &object, 100.0);
        assert_eq!(ends.len(), RIM_POINTS);
        for end in &ends {
            // 50 mm short of the object, off the line by about a quarter
            // of its size (scaled down by how far short the line stops).
            assert!(end.x < object.x - 49.0 && end.x > object.x - 51.0, "{end}");
            let off = (end.y.powi(2) + (end.z - 1500.0).powi(2)).sqrt();
            assert!((off - 25.0 * 1950.0 / 2000.0).abs() < 0.1, "{off}");
        }
        assert!(rim_ends(&eye, &Point3::new(40.0, 0.0, 1500.0), 100.0).is_empty());
    }
}
