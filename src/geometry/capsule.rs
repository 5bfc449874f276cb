//! A capsule: the points within a radius of a segment. Limbs and links are
//! capsules, a head a capsule whose ends coincide (a sphere).

use nalgebra::{Point3, Vector3};

#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Capsule {
    pub a: Point3<f64>,
    pub b: Point3<f64>,
    pub radius_mm: f64,
}

impl Capsule {
    pub fn new(a: Point3<f64>, b: Point3<f64>, radius_mm: f64) -> Self {
        Capsule { a, b, radius_mm }
    }

    /// A sphere: a capsule whose ends coincide.
    pub fn sphere(centre: Point3<f64>, radius_mm: f64) -> Self {
        Capsule::new(centre, centre, radius_mm)
    }

    /// Whether the two capsules overlap (touching is not overlapping).
    pub fn overlaps(&self, other: &Capsule) -> bool {
        segment_distance(&self.a, &self.b, &other.a, &other.b) < self.radius_mm + other.radius_mm
    }

    /// Least and greatest corners of the capsule's axis-aligned bounds.
    pub fn bounds(&self) -> [Point3<f64>; 2] {
        let r = Vector3::repeat(self.radius_mm);
        [self.a.inf(&self.b) - r, self.a.sup(&self.b) + r]
    }

    /// The capsule with the part of its segment within `radius_mm` of
    /// `centre` taken away (none if all of it is), for the parts of a link
    /// next to a joint that touch what the joint joins.
    pub fn outside_ball(&self, centre: &Point3<f64>, radius_mm: f64) -> Option<Capsule> {
        let d = self.b - self.a;
        let length_sq = d.norm_squared();
        let inside = |p: &Point3<f64>| (p - centre).norm() < radius_mm;
        match (inside(&self.a), inside(&self.b)) {
            (false, false) => Some(*self),
            (true, true) => None,
            (a_in, _) => {
                // Where the segment crosses the ball's surface.
                let f = self.a - centre;
                let (qa, qb, qc) = (
                    length_sq,
                    2.0 * f.dot(&d),
                    f.norm_squared() - radius_mm * radius_mm,
                );
                let root = (qb * qb - 4.0 * qa * qc).max(0.0).sqrt();
                if a_in {
                    let t = (-qb + root) / (2.0 * qa);
                    Some(Capsule::new(self.a + d * t, self.b, self.radius_mm))
                } else {
                    let t = (-qb - root) / (2.0 * qa);
                    Some(Capsule::new(self.a, self.a + d * t, self.radius_mm))
                }
            }
        }
    }
}

/// The least distance between segments `p1`-`q1` and `p2`-`q2` (either may
/// be a point), after Ericson, *Real-Time Collision Detection*, 5.1.9.
pub fn segment_distance(
    p1: &Point3<f64>,
    q1: &Point3<f64>,
    p2: &Point3<f64>,
    q2: &Point3<f64>,
) -> f64 {
    const EPS: f64 = 1e-12;
    let (d1, d2, r) = (q1 - p1, q2 - p2, p1 - p2);
    let (a, e, f) = (d1.norm_squared(), d2.norm_squared(), d2.dot(&r));
    let (s, t) = if a <= EPS && e <= EPS {
        (0.0, 0.0)
    } else if a <= EPS {
        (0.0, (f / e).clamp(0.0, 1.0))
    } else {
        let c = d1.dot(&r);
        if e <= EPS {
            ((-c / a).clamp(0.0, 1.0), 0.0)
        } else {
            let b = d1.dot(&d2);
            let denom = a * e - b * b;
            let mut s = if denom > EPS {
                ((b * f - c * e) / denom).clamp(0.0, 1.0)
            } else {
                0.0
            };
            let mut t = (b * s + f) / e;
            if t < 0.0 {
                t = 0.0;
                s = (-c / a).clamp(0.0, 1.0);
            } else if t > 1.0 {
                t = 1.0;
                s = ((b - c) / a).clamp(0.0, 1.0);
            }
            (s, t)
        }
    };
    ((p1 + d1 * s) - (p2 + d2 * t)).norm()
}

#[cfg(test)]
mod tests {
    use super::*;

    fn p(x: f64, y: f64, z: f64) -> Point3<f64> {
        Point3::new(x, y, z)
    }

    #[test]
    fn distances_between_segments_and_points() {
        // Crossing at right angles, 5 apart.
        let d = segment_distance(
            &p(-1.0, 0.0, 0.0),
            &p(1.0, 0.0, 0.0),
            &p(0.0, -1.0, 5.0),
            &p(0.0, 1.0, 5.0),
        );
        assert!((d - 5.0).abs() < 1e-12);
        // Parallel, overlapping, 3 apart.
        let d = segment_distance(
            &p(0.0, 0.0, 0.0),
            &p(10.0, 0.0, 0.0),
            &p(5.0, 3.0, 0.0),
            &p(15.0, 3.0, 0.0),
        );
        assert!((d - 3.0).abs() < 1e-12);
        // End to end, in line.
        let d = segment_distance(
            &p(0.0, 0.0, 0.0),
            &p(1.0, 0.0, 0.0),
            &p(4.0, 0.0, 0.0),
            &p(9.0, 0.0, 0.0),
        );
        assert!((d - 3.0).abs() < 1e-12);
        // A point and a segment; two points.
        let d = segment_distance(
            &p(5.0, 4.0, 0.0),
            &p(5.0, 4.0, 0.0),
            &p(0.0, 0.0, 0.0),
            &p(10.0, 0.0, 0.0),
        );
        assert!((d - 4.0).abs() < 1e-12);
        assert!(
            (segment_distance(
                &p(0.0, 0.0, 0.0),
                &p(0.0, 0.0, 0.0),
                &p(3.0, 4.0, 0.0),
                &p(3.0, 4.0, 0.0)
            ) - 5.0)
                .abs()
                < 1e-12
        );
    }

    #[test]
    fn capsules_overlap_when_their_axes_are_nearer_than_their_radii() {
        let arm = Capsule::new(p(0.0, 0.0, 0.0), p(300.0, 0.0, 0.0), 50.0);
        assert!(arm.overlaps(&Capsule::sphere(p(150.0, 0.0, 120.0), 80.0)));
        assert!(!arm.overlaps(&Capsule::sphere(p(150.0, 0.0, 140.0), 80.0)));
    }

    #[test]
    fn a_ball_takes_away_the_part_of_the_segment_inside_it() {
        let c = Capsule::new(p(0.0, 0.0, 0.0), p(500.0, 0.0, 0.0), 10.0);
        let cut = c.outside_ball(&p(0.0, 0.0, 0.0), 300.0).unwrap();
        assert!((cut.a - p(300.0, 0.0, 0.0)).norm() < 1e-9 && cut.b == c.b);
        let cut = c.outside_ball(&p(500.0, 0.0, 0.0), 100.0).unwrap();
        assert!((cut.b - p(400.0, 0.0, 0.0)).norm() < 1e-9 && cut.a == c.a);
        assert!(c.outside_ball(&p(250.0, 0.0, 0.0), 300.0).is_none());
        assert_eq!(c.outside_ball(&p(0.0, 900.0, 0.0), 300.0), Some(c));
    }
}
