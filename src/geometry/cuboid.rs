//! An oriented box: a centre, half its size along its own axes, and a turn
//! about the vertical (boards, counters, a chair's seat). The distance
//! from a segment to it is exact: the squared distance from a point moving
//! along the segment to the box is a sum of one convex piecewise quadratic
//! per axis, so its least value is at a break of one of them or where the
//! derivative of one quadratic piece is zero.

use nalgebra::{Point3, Rotation3, Vector3};

#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Cuboid {
    pub centre: Point3<f64>,
    /// Half the size along the box's own axes.
    pub half_mm: Vector3<f64>,
    /// The turn of the box's axes about the vertical.
    pub yaw_rad: f64,
}

impl Cuboid {
    /// A box from its corner of least coordinates (before turning) and its
    /// size, turned by `yaw_rad` about the vertical through that corner.
    pub fn from_corner(corner: Point3<f64>, size_mm: Vector3<f64>, yaw_rad: f64) -> Self {
        let turn = Rotation3::from_axis_angle(&Vector3::z_axis(), yaw_rad);
        Cuboid {
            centre: corner + turn * (size_mm / 2.0),
            half_mm: size_mm / 2.0,
            yaw_rad,
        }
    }

    /// A box not turned, from its least and greatest corners.
    pub fn between(min: Point3<f64>, max: Point3<f64>) -> Self {
        Cuboid {
            centre: nalgebra::center(&min, &max),
            half_mm: (max - min) / 2.0,
            yaw_rad: 0.0,
        }
    }

    fn local_of(&self, p: &Point3<f64>) -> Vector3<f64> {
        let d = p - self.centre;
        if self.yaw_rad == 0.0 {
            return d;
        }
        let (s, c) = self.yaw_rad.sin_cos();
        Vector3::new(c * d.x + s * d.y, -s * d.x + c * d.y, d.z)
    }

    /// Whether `p` is inside the box (its surface included).
    pub fn contains(&self, p: &Point3<f64>) -> bool {
        let l = self.local_of(p);
        (0..3).all(|i| l[i].abs() <= self.half_mm[i])
    }

    /// The least distance from the segment `a`-`b` to the box (zero where
    /// the segment enters it).
    pub fn distance_to_segment(&self, a: &Point3<f64>, b: &Point3<f64>) -> f64 {
        let (la, lb) = (self.local_of(a), self.local_of(b));
        segment_box_distance_sq(&la, &(lb - la), &self.half_mm).sqrt()
    }

    /// Corner `i` (0 to 7) of the box: bit 0 set for its own +x side,
    /// bit 1 for +y, bit 2 for +z (0 is the least corner before turning).
    pub fn corner(&self, i: usize) -> Point3<f64> {
        let side = |bit: usize| if i & bit == 0 { -1.0 } else { 1.0 };
        let local = Vector3::new(side(1), side(2), side(4)).component_mul(&self.half_mm);
        self.centre + Rotation3::from_axis_angle(&Vector3::z_axis(), self.yaw_rad) * local
    }

    /// Least and greatest corners of the box's axis-aligned bounds.
    pub fn bounds(&self) -> [Point3<f64>; 2] {
        let (s, c) = self.yaw_rad.sin_cos();
        let h = self.half_mm;
        let reach = Vector3::new(
            c.abs() * h.x + s.abs() * h.y,
            s.abs() * h.x + c.abs() * h.y,
            h.z,
        );
        [self.centre - reach, self.centre + reach]
    }
}

/// The squared distance from the segment `p + t d` (t in 0..1) to the box
/// `[-h, h]`, all in the box's frame.
fn segment_box_distance_sq(p: &Vector3<f64>, d: &Vector3<f64>, h: &Vector3<f64>) -> f64 {
    // Where each axis's piece changes: the segment crossing a face plane.
    let mut breaks = [0.0; 8];
    let mut n = 0;
    breaks[n] = 0.0;
    n += 1;
    breaks[n] = 1.0;
    n += 1;
    for i in 0..3 {
        if d[i].abs() > 1e-15 {
            for face in [-h[i], h[i]] {
                let t = (face - p[i]) / d[i];
                if t > 0.0 && t < 1.0 {
                    breaks[n] = t;
                    n += 1;
                }
            }
        }
    }
    let breaks = &mut breaks[..n];
    breaks.sort_by(f64::total_cmp);
    let at = |t: f64| point_box_distance_sq(&(p + d * t), h);
    let mut best = f64::INFINITY;
    for w in breaks.windows(2) {
        let (t0, t1) = (w[0], w[1]);
        best = best.min(at(t0)).min(at(t1));
        // Within the piece each axis is one quadratic: the derivative is
        // linear, zero at most once.
        let mid = 0.5 * (t0 + t1);
        let q = p + d * mid;
        let (mut slope, mut curve) = (0.0, 0.0);
        for i in 0..3 {
            let outside = if q[i] > h[i] {
                q[i] - h[i]
            } else if q[i] < -h[i] {
                q[i] + h[i]
            } else {
                continue;
            };
            // d/dt (outside + d_i (t - mid))^2 at mid, and its rate.
            slope += 2.0 * outside * d[i];
            curve += 2.0 * d[i] * d[i];
        }
        if curve > 0.0 {
            let t = (mid - slope / curve).clamp(t0, t1);
            best = best.min(at(t));
        }
    }
    best
}

fn point_box_distance_sq(q: &Vector3<f64>, h: &Vector3<f64>) -> f64 {
    (0..3)
        .map(|i| {
            let out = (q[i].abs() - h[i]).max(0.0);
            out * out
        })
        .sum()
}

#[cfg(test)]
mod tests {
    use super::*;

    fn unit_box() -> Cuboid {
        Cuboid::between(Point3::new(0.0, 0.0, 0.0), Point3::new(10.0, 10.0, 10.0))
    }

    /// The distance by sampling the segment finely, to check the exact one.
    fn sampled(c: &Cuboid, a: &Point3<f64>, b: &Point3<f64>) -> f64 {
        (0..=20_000)
            .map(|k| {
                let p = a + (b - a) * (f64::from(k) / 20_000.0);
                c.distance_to_segment(&p, &p)
            })
            .fold(f64::INFINITY, f64::min)
    }

    #[test]
    fn distances_from_segments_to_a_box() {
        let c = unit_box();
        let d =
            |a: [f64; 3], b: [f64; 3]| c.distance_to_segment(&Point3::from(a), &Point3::from(b));
        assert_eq!(d([-5.0, 5.0, 5.0], [15.0, 5.0, 5.0]), 0.0, "through");
        assert!(
            (d([-5.0, 15.0, 5.0], [15.0, 15.0, 5.0]) - 5.0).abs() < 1e-12,
            "beside"
        );
        assert!(
            (d([13.0, 14.0, 10.0], [13.0, 14.0, 10.0]) - 5.0).abs() < 1e-12,
            "a point"
        );
        assert!((d([20.0, 20.0, 20.0], [20.0, 20.0, 20.0]) - 300f64.sqrt()).abs() < 1e-12);
        // Passing a corner diagonally.
        let (a, b) = (Point3::new(-10.0, 12.0, 5.0), Point3::new(12.0, -10.0, 5.0));
        assert!((c.distance_to_segment(&a, &b) - sampled(&c, &a, &b)).abs() < 1e-6);
    }

    #[test]
    fn a_turned_box_measures_in_its_own_axes() {
        // Turned a quarter turn about its corner: it spans x from -10 to 0.
        let c = Cuboid::from_corner(
            Point3::origin(),
            Vector3::new(10.0, 10.0, 10.0),
            std::f64::consts::FRAC_PI_2,
        );
        let at =
            |x: f64| c.distance_to_segment(&Point3::new(x, 5.0, 5.0), &Point3::new(x, 5.0, 5.0));
        assert!(at(-5.0) < 1e-9);
        assert!((at(3.0) - 3.0).abs() < 1e-9);
        let [lo, hi] = c.bounds();
        assert!((lo.x + 10.0).abs() < 1e-9 && hi.x.abs() < 1e-9);
    }

    #[test]
    fn the_exact_distance_matches_sampling_on_random_segments() {
        let c = Cuboid::from_corner(
            Point3::new(1.0, 2.0, 3.0),
            Vector3::new(40.0, 10.0, 25.0),
            0.7,
        );
        let mut x = 12345u64;
        let mut next = || {
            x ^= x << 13;
            x ^= x >> 7;
            x ^= x << 17;
            (x % 10_000) as f64 / 100.0 - 30.0
        };
        for _ in 0..200 {
            let a = Point3::new(next(), next(), next());
            let b = Point3::new(next(), next(), next());
            let exact = c.distance_to_segment(&a, &b);
            assert!((exact - sampled(&c, &a, &b)).abs() < 1e-3, "{a} {b}");
        }
    }
}
