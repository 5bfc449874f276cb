//! Which obstacles a task can meet: those within its reach of one of the
//! placements its base may try, or (lines of sight) of the segment from
//! such a placement to the point looked at, or within the radius and the
//! reach of the point where the base may try any hip in a ball about it. Measured to each obstacle's
//! axis-aligned bounds, which hold the obstacle: an obstacle left out
//! cannot touch a link or a line of sight.

use nalgebra::{Isometry3, Point3, Translation3, Vector2, Vector3};
use parry3d_f64::query::{self, PointQuery};
use parry3d_f64::shape::{Cuboid, Segment};

use crate::plugin::Hips;
use crate::scene::{BoxObstacle, MeshObstacle, Room};

/// Where a base may put the hip for one point, and the point.
pub(super) struct Tried {
    pub point_mm: Point3<f64>,
    pub hips: Hips,
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
            tried.iter().any(|t| {
                let near_pose = t.hips.poses.iter().any(|pose| {
                    let hip = pose.position_mm;
                    let end = if sight_lines { t.point_mm } else { hip };
                    b.distance_to_segment(&hip, &end) <= reach_mm + MARGIN_MM
                });
                // A hip within the radius of the point: the segment from
                // it to the point, and all within reach of either, is
                // within the radius and the reach of the point.
                near_pose
                    || t.hips.around.is_some_and(|(centre, radius_mm)| {
                        b.distance_to_segment(&centre, &centre) <= radius_mm + reach_mm + MARGIN_MM
                    })
            })
        })
        .map(|(i, _)| i)
        .collect()
}

/// Added to the reach, against rounding in the distances.
const MARGIN_MM: f64 = 1.0;

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

    /// The distance from the segment `a`-`b` (a point if they are one)
    /// to the box; 0 where it meets it, and 0 (to be safe) for a box that
    /// is not finite.
    fn distance_to_segment(&self, a: &Point3<f64>, b: &Point3<f64>) -> f64 {
        let finite = self
            .min
            .iter()
            .chain(self.max.iter())
            .all(|v| v.is_finite());
        if !finite {
            return 0.0;
        }
        let half = (self.max - self.min) / 2.0;
        let pose = Isometry3::from_parts(
            Translation3::from(self.min.coords + half),
            Default::default(),
        );
        let cuboid = Cuboid::new(half);
        if (b - a).norm() < 1e-9 {
            return cuboid.distance_to_point(&pose, a, true);
        }
        query::distance(
            &Isometry3::identity(),
            &Segment::new(*a, *b),
            &pose,
            &cuboid,
        )
        .unwrap_or(0.0)
    }
}

/// A box's bounds, turned by its yaw about its corner.
fn box_bounds(b: &BoxObstacle) -> Bounds {
    let corners = [(0.0, 0.0), (1.0, 0.0), (0.0, 1.0), (1.0, 1.0)]
        .into_iter()
        .flat_map(|(u, v)| {
            let xy = b.floor_point(Vector2::new(u * b.size_mm.x, v * b.size_mm.y));
            let z = b.corner_mm.z;
            [
                Point3::new(xy.x, xy.y, z),
                Point3::new(xy.x, xy.y, z + b.size_mm.z),
            ]
        });
    Bounds::of(corners)
}

fn mesh_bounds(m: &MeshObstacle) -> Bounds {
    Bounds::of(m.vertex_bounds().into_iter().flatten())
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn distances_to_a_box_from_a_point_and_a_segment() {
        let b = Bounds::of([Point3::new(0.0, 0.0, 0.0), Point3::new(10.0, 10.0, 10.0)]);
        let at =
            |p: [f64; 3], q: [f64; 3]| b.distance_to_segment(&Point3::from(p), &Point3::from(q));
        assert!((at([13.0, 14.0, 5.0], [13.0, 14.0, 5.0]) - 5.0).abs() < 1e-9);
        assert!((at([-5.0, 20.0, 5.0], [15.0, 20.0, 5.0]) - 10.0).abs() < 1e-9);
        assert_eq!(at([-5.0, 5.0, 5.0], [15.0, 5.0, 5.0]), 0.0);
        // A corner: the distance, not the largest of the axes'.
        assert!((at([13.0, 14.0, 10.0], [13.0, 14.0, 10.0]) - 5.0).abs() < 1e-9);
        assert!((at([20.0, 20.0, 20.0], [20.0, 20.0, 20.0]) - 300f64.sqrt()).abs() < 1e-9);
    }
}
