//! Which obstacles a task can meet: those within its reach of one of the
//! placements its base may try, or (lines of sight) of the segment from
//! such a placement to the point looked at. Tested against each
//! obstacle's axis-aligned bounds grown by the reach, which holds every
//! point within the reach of the obstacle: an obstacle left out cannot
//! touch a link or a line of sight.

use nalgebra::{Point3, Vector3};

use crate::scene::{BoxObstacle, MeshObstacle, Room};

/// The placements (hips) tried for one point, and the point.
pub(super) struct Tried {
    pub point_mm: Point3<f64>,
    pub hips_mm: Vec<Point3<f64>>,
}

/// The indices (boxes, then meshes) of the room's obstacles within
/// `reach_mm` of a hip of `tried`, or with `sight_lines` of the segment
/// from a hip to its point.
pub(super) fn obstacles_within(
    room: &Room,
    tried: &[Tried],
    reach_mm: f64,
    sight_lines: bool,
) -> Vec<usize> {
    let bounds = room
        .boxes
        .iter()
        .map(box_bounds)
        .chain(room.meshes.iter().map(mesh_bounds));
    bounds
        .enumerate()
        .filter(|(_, b)| {
            let grown = b.grown(reach_mm);
            tried.iter().any(|t| {
                t.hips_mm.iter().any(|hip| {
                    let end = if sight_lines { t.point_mm } else { *hip };
                    grown.meets_segment(hip, &end)
                })
            })
        })
        .map(|(i, _)| i)
        .collect()
}

/// An axis-aligned box.
#[derive(Clone, Copy, Debug)]
struct Bounds {
    min: Point3<f64>,
    max: Point3<f64>,
}

impl Bounds {
    fn of(points: impl IntoIterator<Item = Point3<f64>>) -> Self {
        let mut b = Bounds {
            min: Point3::from(Vector3::repeat(f64::INFINITY)),
            max: Point3::from(Vector3::repeat(f64::NEG_INFINITY)),
        };
        for p in points {
            b.min = b.min.inf(&p);
            b.max = b.max.sup(&p);
        }
        b
    }

    fn grown(&self, by: f64) -> Self {
        Bounds {
            min: self.min - Vector3::repeat(by),
            max: self.max + Vector3::repeat(by),
        }
    }

    /// Whether the segment from `a` to `b` meets the box (slab test; a
    /// box that is not finite meets everything, to be safe).
    fn meets_segment(&self, a: &Point3<f64>, b: &Point3<f64>) -> bool {
        if !(self.min.coords.iter().chain(self.max.coords.iter())).all(|v| v.is_finite()) {
            return true;
        }
        let d = b - a;
        let (mut t0, mut t1) = (0.0_f64, 1.0_f64);
        for i in 0..3 {
            if d[i].abs() < 1e-12 {
                if a[i] < self.min[i] || a[i] > self.max[i] {
                    return false;
                }
                continue;
            }
            let (u, v) = ((self.min[i] - a[i]) / d[i], (self.max[i] - a[i]) / d[i]);
            t0 = t0.max(u.min(v));
            t1 = t1.min(u.max(v));
            if t0 > t1 {
                return false;
            }
        }
        true
    }
}

/// A box's bounds, turned by its yaw about its corner.
fn box_bounds(b: &BoxObstacle) -> Bounds {
    let (s, c) = b.yaw_rad.sin_cos();
    let corners = [(0.0, 0.0), (1.0, 0.0), (0.0, 1.0), (1.0, 1.0)]
        .into_iter()
        .flat_map(|(u, v)| {
            let (x, y) = (u * b.size_mm.x, v * b.size_mm.y);
            let at = b.corner_mm + Vector3::new(c * x - s * y, s * x + c * y, 0.0);
            [at, at + Vector3::new(0.0, 0.0, b.size_mm.z)]
        });
    Bounds::of(corners)
}

fn mesh_bounds(m: &MeshObstacle) -> Bounds {
    Bounds::of(m.vertices_mm.iter().copied())
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_segment_meets_a_box_it_crosses_and_misses_one_beside_it() {
        let b = Bounds::of([Point3::new(0.0, 0.0, 0.0), Point3::new(10.0, 10.0, 10.0)]);
        let (a, z) = (Point3::new(-5.0, 5.0, 5.0), Point3::new(15.0, 5.0, 5.0));
        assert!(b.meets_segment(&a, &z));
        assert!(!b.meets_segment(&Point3::new(-5.0, 20.0, 5.0), &Point3::new(15.0, 20.0, 5.0)));
        assert!(b
            .grown(10.0)
            .meets_segment(&Point3::new(-5.0, 20.0, 5.0), &Point3::new(15.0, 20.0, 5.0)));
        assert!(b.meets_segment(&Point3::new(5.0, 5.0, 5.0), &Point3::new(5.0, 5.0, 5.0)));
    }
}
