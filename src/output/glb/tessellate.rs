//! Solids as triangles, for a glTF scene: capsules (a sphere is one of
//! length zero), boxes turned about the vertical, quads. Millimetres in the
//! room's frame, z up; faces wound outwards.

use nalgebra::{Point3, Vector3};

use crate::geometry::Cuboid;

/// Triangles: vertices and indices into them.
#[derive(Clone, Debug, Default, PartialEq)]
pub struct Triangles {
    pub vertices: Vec<Point3<f64>>,
    pub indices: Vec<u32>,
}

/// Around a capsule, and from its equator to a pole.
const AROUND: usize = 16;
const TO_POLE: usize = 4;

impl Triangles {
    fn add_quad(&mut self, corners: [Point3<f64>; 4]) {
        let base = self.vertices.len() as u32;
        self.vertices.extend(corners);
        self.indices
            .extend([base, base + 1, base + 2, base, base + 2, base + 3]);
    }

    /// A capsule from `a` to `b` of radius `r`.
    pub fn capsule(a: Point3<f64>, b: Point3<f64>, r: f64) -> Self {
        let axis = b - a;
        let w = axis.try_normalize(1e-9).unwrap_or_else(Vector3::z);
        let helper = if w.z.abs() < 0.9 {
            Vector3::z()
        } else {
            Vector3::x()
        };
        let u = w.cross(&helper).normalize();
        let v = w.cross(&u);
        let mut t = Triangles::default();
        // Rings from the pole at `a` to the pole at `b`: the lower half
        // about `a`, the upper about `b`.
        let rings: Vec<(Point3<f64>, f64)> = (0..=TO_POLE)
            .map(|i| {
                (
                    a,
                    -std::f64::consts::FRAC_PI_2 * (1.0 - i as f64 / TO_POLE as f64),
                )
            })
            .chain(
                (0..=TO_POLE).map(|i| (b, std::f64::consts::FRAC_PI_2 * i as f64 / TO_POLE as f64)),
            )
            .collect();
        for (centre, latitude) in &rings {
            for k in 0..AROUND {
                let phi = std::f64::consts::TAU * k as f64 / AROUND as f64;
                let out = latitude.cos() * (phi.cos() * u + phi.sin() * v) + latitude.sin() * w;
                t.vertices.push(centre + r * out);
            }
        }
        for ring in 0..rings.len() - 1 {
            for k in 0..AROUND {
                let at = |ring: usize, k: usize| (ring * AROUND + k % AROUND) as u32;
                let (p, q) = (at(ring, k), at(ring, k + 1));
                let (s, e) = (at(ring + 1, k), at(ring + 1, k + 1));
                t.indices.extend([p, q, e, p, e, s]);
            }
        }
        t
    }

    /// A box's six faces.
    pub fn cuboid(c: &Cuboid) -> Self {
        let mut t = Triangles::default();
        for face in [
            [0, 2, 3, 1],
            [4, 5, 7, 6],
            [0, 1, 5, 4],
            [1, 3, 7, 5],
            [3, 2, 6, 7],
            [2, 0, 4, 6],
        ] {
            t.add_quad(face.map(|k| c.corner(k)));
        }
        t
    }

    /// A flat square of side `side` about `centre`, along `u` and `v`.
    pub fn square(centre: Point3<f64>, u: Vector3<f64>, v: Vector3<f64>, side: f64) -> Self {
        let (du, dv) = (u.normalize() * side / 2.0, v.normalize() * side / 2.0);
        let mut t = Triangles::default();
        t.add_quad([
            centre - du - dv,
            centre + du - dv,
            centre + du + dv,
            centre - du + dv,
        ]);
        t
    }

    pub fn append(&mut self, other: &Triangles) {
        let base = self.vertices.len() as u32;
        self.vertices.extend(&other.vertices);
        self.indices.extend(other.indices.iter().map(|k| k + base));
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_capsule_stays_within_its_radius_of_its_segment() {
        let (a, b, r) = (
            Point3::new(0.0, 0.0, 0.0),
            Point3::new(100.0, 50.0, 20.0),
            30.0,
        );
        let t = Triangles::capsule(a, b, r);
        let ab = b - a;
        for p in &t.vertices {
            let s = ((p - a).dot(&ab) / ab.norm_squared()).clamp(0.0, 1.0);
            let d = (p - (a + s * ab)).norm();
            assert!((d - r).abs() < 1e-9, "{d}");
        }
        assert!(t.indices.iter().all(|&k| (k as usize) < t.vertices.len()));
    }

    #[test]
    fn a_capsule_faces_outwards() {
        let (a, b) = (Point3::new(10.0, 0.0, 0.0), Point3::new(10.0, 80.0, 40.0));
        let t = Triangles::capsule(a, b, 20.0);
        let ab = b - a;
        for tri in t.indices.chunks(3) {
            let [p, q, s] = [0, 1, 2].map(|k| t.vertices[tri[k] as usize]);
            let normal = (q - p).cross(&(s - p));
            if normal.norm() < 1e-9 {
                continue; // at a pole, where a ring is one point
            }
            let mid = Point3::from((p.coords + q.coords + s.coords) / 3.0);
            let along = ((mid - a).dot(&ab) / ab.norm_squared()).clamp(0.0, 1.0);
            assert!(normal.dot(&(mid - (a + along * ab))) > 0.0);
        }
    }

    #[test]
    fn a_box_faces_outwards() {
        let centre = Point3::new(1.0, 2.0, 3.0);
        let t = Triangles::cuboid(&Cuboid {
            centre,
            half_mm: Vector3::new(1.0, 2.0, 3.0),
            yaw_rad: 0.3,
        });
        for tri in t.indices.chunks(3) {
            let [p, q, s] = [0, 1, 2].map(|k| t.vertices[tri[k] as usize]);
            let normal = (q - p).cross(&(s - p));
            assert!(normal.dot(&(p - centre)) > 0.0);
        }
    }
}
