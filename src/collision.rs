//! Obstacles as parry shapes, for the two questions the solvers and the
//! gaze task ask: does a link (a segment) pass through an obstacle, and
//! what does a line of sight hit first? All in the room frame, millimetres.

use nalgebra::{Isometry3, Point3, Translation3, UnitQuaternion, Vector3};
use parry3d_f64::query::Ray;
use parry3d_f64::shape::{Cuboid, SharedShape, TriMeshFlags};

use crate::scene::BasePose;
use crate::scene::{BoxObstacle, Room};

/// One obstacle: its shape posed in the room, and its name for reports.
#[derive(Clone)]
struct Obstacle {
    /// Its index among the room's obstacles (the boxes, then the meshes).
    index: usize,
    name: String,
    pose_room: Isometry3<f64>,
    shape: SharedShape,
    /// A mesh whose inside is known (closed, faces outwards): a point in
    /// it is in the obstacle. (A ray cast only finds the surface.)
    closed_mesh: bool,
}

impl Obstacle {
    /// Where along `ray` (0 to `max`) the obstacle begins; 0 from inside.
    fn entry(&self, ray: &Ray, max: f64) -> Option<f64> {
        if self.closed_mesh && self.shape.contains_point(&self.pose_room, &ray.origin) {
            return Some(0.0);
        }
        self.shape.cast_ray(&self.pose_room, ray, max, true)
    }
}

/// The obstacles of one room.
#[derive(Clone, Default)]
pub struct Obstacles {
    items: Vec<Obstacle>,
}

impl Obstacles {
    /// The room's boxes, each grown by `clearance_mm` on every side (a link
    /// closer than that to a box counts as touching it).
    /// Meshes come after the boxes, as is; a mesh is solid where its
    /// triangles close and face outwards, else only its surface counts.
    pub fn new(room: &Room, clearance_mm: f64) -> Self {
        let boxes = room.boxes.iter().enumerate().map(|(index, b)| Obstacle {
            index,
            name: b.name.clone(),
            pose_room: box_pose_room(b),
            shape: SharedShape::new(Cuboid::new(b.size_mm / 2.0 + Vector3::repeat(clearance_mm))),
            closed_mesh: false,
        });
        let first_mesh = room.boxes.len();
        let meshes = room.meshes.iter().enumerate().filter_map(|(k, m)| {
            let (vertices, triangles) = (m.vertices_mm.clone(), m.triangles.clone());
            let oriented = SharedShape::trimesh_with_flags(
                vertices.clone(),
                triangles.clone(),
                TriMeshFlags::ORIENTED,
            );
            let (shape, closed_mesh) = match oriented {
                Ok(shape) => (shape, true),
                Err(_) => (SharedShape::trimesh(vertices, triangles).ok()?, false),
            };
            Some(Obstacle {
                index: first_mesh + k,
                name: m.name.clone(),
                pose_room: Isometry3::identity(),
                shape,
                closed_mesh,
            })
        });
        Obstacles {
            items: boxes.chain(meshes).collect(),
        }
    }

    pub fn is_empty(&self) -> bool {
        self.items.is_empty()
    }

    /// The name of the room's obstacle `index` (as the hits give it).
    pub fn name(&self, index: usize) -> &str {
        self.items
            .iter()
            .find(|o| o.index == index)
            .map_or("", |o| o.name.as_str())
    }

    /// The first obstacle (in declaration order) the segment from `a` to
    /// `b` touches or lies in, by its index among the room's obstacles.
    pub fn segment_hit(&self, a: &Point3<f64>, b: &Point3<f64>) -> Option<usize> {
        let ray = Ray::new(*a, b - a);
        self.items
            .iter()
            .find(|o| o.entry(&ray, 1.0).is_some())
            .map(|o| o.index)
    }

    /// What the line of sight from `eye` to `target` hits first (its index
    /// among the room's obstacles), and where
    /// along it (0 at the eye, 1 at the target; 0 for a box that holds the
    /// eye). The last `end_gap_mm` before the target is not checked, so
    /// that an object resting on a shelf is not hidden by the shelf.
    pub fn first_on_sight_line(
        &self,
        eye: &Point3<f64>,
        target: &Point3<f64>,
        end_gap_mm: f64,
    ) -> Option<(usize, f64)> {
        let length = (target - eye).norm();
        if length <= end_gap_mm {
            return None;
        }
        let ray = Ray::new(*eye, target - eye);
        let max = 1.0 - end_gap_mm / length;
        self.items
            .iter()
            .filter_map(|o| o.entry(&ray, max).map(|toi| (o.index, toi)))
            .min_by(|a, b| a.1.total_cmp(&b.1).then(a.0.cmp(&b.0)))
    }
}

/// A box's centre pose in the room: turned by its yaw about the vertical
/// through its corner.
fn box_pose_room(b: &BoxObstacle) -> Isometry3<f64> {
    let rotation = UnitQuaternion::from_axis_angle(&Vector3::z_axis(), b.yaw_rad);
    let centre = b.corner_mm + rotation * (b.size_mm / 2.0);
    Isometry3::from_parts(Translation3::from(centre.coords), rotation)
}

/// Obstacles seen from a placed person: links come in the chain's base
/// frame and are carried into the room by the base pose.
#[derive(Clone, Copy)]
pub struct PlacedObstacles<'a> {
    pub obstacles: &'a Obstacles,
    pub base_pose: BasePose,
}

impl PlacedObstacles<'_> {
    /// The first obstacle any link of the polyline `points_base` (in the
    /// base frame) passes through. The last link stops `end_gap_mm` short
    /// of the effector, which may rest on a surface: touching the target's
    /// shelf is not a collision.
    pub fn polyline_hit(&self, points_base: &[Point3<f64>], end_gap_mm: f64) -> Option<usize> {
        let room: Vec<Point3<f64>> = points_base
            .iter()
            .map(|p| self.base_pose.to_room(p))
            .collect();
        let last = room.len().checked_sub(2)?;
        room.windows(2).enumerate().find_map(|(i, w)| {
            let mut end = w[1];
            if i == last {
                let link = w[1] - w[0];
                let length = link.norm();
                if length <= end_gap_mm {
                    return None;
                }
                end = w[0] + link * (1.0 - end_gap_mm / length);
            }
            self.obstacles.segment_hit(&w[0], &end)
        })
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn room_with(boxes: Vec<BoxObstacle>) -> Room {
        Room {
            name: "r".into(),
            size_mm: Vector3::new(4000.0, 4000.0, 2500.0),
            boxes,
            meshes: Vec::new(),
            targets: vec![],
            surfaces: vec![],
        }
    }

    fn block(name: &str, corner: [f64; 3], size: [f64; 3], yaw_rad: f64) -> BoxObstacle {
        BoxObstacle {
            name: name.into(),
            corner_mm: Point3::from(corner),
            size_mm: Vector3::from(size),
            yaw_rad,
        }
    }

    #[test]
    fn a_segment_through_a_box_hits_it_and_one_beside_it_does_not() {
        let o = Obstacles::new(
            &room_with(vec![block("b", [0.0, 0.0, 0.0], [100.0; 3], 0.0)]),
            0.0,
        );
        let hit = |a: [f64; 3], b: [f64; 3]| o.segment_hit(&Point3::from(a), &Point3::from(b));
        assert_eq!(hit([-50.0, 50.0, 50.0], [150.0, 50.0, 50.0]), Some(0));
        assert_eq!(
            hit([50.0, 50.0, 50.0], [60.0, 60.0, 60.0]),
            Some(0),
            "inside"
        );
        assert_eq!(hit([-50.0, 50.0, 150.0], [150.0, 50.0, 150.0]), None);
        assert_eq!(
            hit([-50.0, 50.0, 50.0], [-10.0, 50.0, 50.0]),
            None,
            "stops short"
        );
    }

    /// A closed cube of side 100 mm at the origin, faces outwards.
    fn cube_mesh() -> crate::scene::MeshObstacle {
        let v: Vec<Point3<f64>> = (0..8)
            .map(|i| {
                Point3::new(
                    f64::from(i >> 2) * 100.0,
                    f64::from((i >> 1) & 1) * 100.0,
                    f64::from(i & 1) * 100.0,
                )
            })
            .collect();
        let quads = [
            [0, 2, 6, 4],
            [1, 5, 7, 3],
            [0, 4, 5, 1],
            [2, 3, 7, 6],
            [0, 1, 3, 2],
            [4, 6, 7, 5],
        ];
        let triangles = quads
            .iter()
            .flat_map(|q| [[q[0], q[1], q[2]], [q[0], q[2], q[3]]])
            .collect();
        crate::scene::MeshObstacle {
            name: "cube".into(),
            vertices_mm: v,
            triangles,
        }
    }

    #[test]
    fn a_mesh_is_hit_through_and_within() {
        let mut room = room_with(vec![block("b", [1000.0; 3], [10.0; 3], 0.0)]);
        room.meshes.push(cube_mesh());
        let o = Obstacles::new(&room, 0.0);
        let hit = |a: [f64; 3], b: [f64; 3]| o.segment_hit(&Point3::from(a), &Point3::from(b));
        assert_eq!(
            hit([-50.0, 50.0, 50.0], [150.0, 50.0, 50.0]),
            Some(1),
            "through"
        );
        assert_eq!(
            hit([40.0, 50.0, 50.0], [60.0, 50.0, 50.0]),
            Some(1),
            "inside"
        );
        assert_eq!(
            hit([-50.0, 50.0, 150.0], [150.0, 50.0, 150.0]),
            None,
            "above"
        );
        assert_eq!(o.name(1), "cube");
    }

    #[test]
    fn a_turned_box_is_turned_about_its_corner() {
        // Turned 90 degrees, the box spans x from -100 to 0.
        let b = block(
            "b",
            [0.0, 0.0, 0.0],
            [100.0, 10.0, 100.0],
            std::f64::consts::FRAC_PI_2,
        );
        let o = Obstacles::new(&room_with(vec![b]), 0.0);
        let at = |x: f64, y: f64| o.segment_hit(&Point3::new(x, y, 0.0), &Point3::new(x, y, 50.0));
        assert_eq!(at(-5.0, 50.0), Some(0));
        assert_eq!(at(5.0, 50.0), None);
    }

    #[test]
    fn the_sight_line_names_the_nearest_blocker_and_spares_the_shelf_under_the_target() {
        let room = room_with(vec![
            block("far", [200.0, -50.0, 0.0], [10.0, 100.0, 100.0], 0.0),
            block("near", [100.0, -50.0, 0.0], [10.0, 100.0, 100.0], 0.0),
            block("shelf", [300.0, -50.0, 0.0], [100.0, 100.0, 50.0], 0.0),
        ]);
        let o = Obstacles::new(&room, 0.0);
        let eye = Point3::new(0.0, 0.0, 50.0);
        let (i, _) = o
            .first_on_sight_line(&eye, &Point3::new(350.0, 0.0, 50.0), 10.0)
            .unwrap();
        assert_eq!(o.name(i), "near");
        let above_shelf = Point3::new(350.0, 0.0, 55.0);
        let from_above = Point3::new(350.0, 0.0, 500.0);
        assert_eq!(o.first_on_sight_line(&from_above, &above_shelf, 10.0), None);
        let inside = Point3::new(105.0, 0.0, 50.0);
        let (i, at) = o
            .first_on_sight_line(&inside, &Point3::new(0.0, 0.0, 50.0), 10.0)
            .unwrap();
        assert_eq!(
            (o.name(i), at),
            ("near", 0.0),
            "an eye inside a box sees nothing"
        );
    }
}
