//! The face a target is on, which an approach is measured against: a
//! point on a wall or on a cabinet's front is approached forward by a
//! chair facing that face, and from the side by a chair parallel to it
//! (ADA 308.2 and 308.3), whatever the angle from the hip point to the
//! point. Boxes and the room's sides only; a target on no vertical face
//! (on a counter top, in the open) has none, and its approach is judged
//! from the base alone (`placing::Approach::admits`).

use nalgebra::{Point3, Vector2};

use crate::scene::{BoxObstacle, Room};

/// How far in front of a vertical face a target may be and still be on
/// it (a switch, a handle, a label stand out from the face).
pub const ON_FACE_MM: f64 = 50.0;
/// How far behind the face's plane (inside the box or wall) it may be.
const INSIDE_MM: f64 = 1.0;

/// The outward normal, on the floor, of the vertical face `target_mm` is
/// on: the nearest such face of a box or of the room's sides, where the
/// target lies within the face's width and height and at most
/// [`ON_FACE_MM`] in front of it.
pub fn face_normal(room: &Room, target_mm: &Point3<f64>) -> Option<Vector2<f64>> {
    let mut faces: Vec<(f64, Vector2<f64>)> = room_sides(room, target_mm);
    faces.extend(room.boxes.iter().filter_map(|b| box_face(b, target_mm)));
    faces
        .into_iter()
        .min_by(|a, b| a.0.total_cmp(&b.0))
        .map(|(_, normal)| normal)
}

/// The room's sides the target is on, as (distance, inward normal).
fn room_sides(room: &Room, t: &Point3<f64>) -> Vec<(f64, Vector2<f64>)> {
    let size = room.size_mm;
    let within_height = (0.0..=size.z).contains(&t.z);
    [
        (t.x, Vector2::x()),
        (size.x - t.x, -Vector2::x()),
        (t.y, Vector2::y()),
        (size.y - t.y, -Vector2::y()),
    ]
    .into_iter()
    .filter(|(d, _)| within_height && (-INSIDE_MM..=ON_FACE_MM).contains(d))
    .collect()
}

/// The face of `b` the target is on, if any, as (distance, outward
/// normal in the room).
fn box_face(b: &BoxObstacle, t: &Point3<f64>) -> Option<(f64, Vector2<f64>)> {
    let (bottom, top) = (b.corner_mm.z, b.corner_mm.z + b.size_mm.z);
    if !(bottom..=top).contains(&t.z) {
        return None;
    }
    let local = b.rotation().inverse() * (t.xy() - b.corner_mm.xy());
    let (sx, sy) = (b.size_mm.x, b.size_mm.y);
    let along = |v: f64, size: f64| (0.0..=size).contains(&v);
    let faces = [
        (-local.x, -Vector2::x(), along(local.y, sy)),
        (local.x - sx, Vector2::x(), along(local.y, sy)),
        (-local.y, -Vector2::y(), along(local.x, sx)),
        (local.y - sy, Vector2::y(), along(local.x, sx)),
    ];
    faces
        .into_iter()
        .filter(|&(d, _, within)| within && (-INSIDE_MM..=ON_FACE_MM).contains(&d))
        .min_by(|a, b| a.0.total_cmp(&b.0))
        .map(|(d, normal, _)| (d, b.rotation() * normal))
}

#[cfg(test)]
mod tests {
    use super::*;
    use nalgebra::Vector3;

    fn room(boxes: Vec<BoxObstacle>) -> Room {
        Room {
            name: "r".into(),
            size_mm: Vector3::new(3000.0, 2000.0, 2500.0),
            boxes,
            meshes: Vec::new(),
            targets: Vec::new(),
            surfaces: Vec::new(),
            doors: Vec::new(),
        }
    }

    #[test]
    fn a_point_on_a_wall_or_a_front_has_its_face_one_on_a_top_none() {
        let counter = BoxObstacle {
            name: "counter".into(),
            corner_mm: Point3::new(0.0, 0.0, 0.0),
            size_mm: Vector3::new(600.0, 2000.0, 900.0),
            yaw_rad: 0.0,
        };
        let r = room(vec![counter]);
        let wall = face_normal(&r, &Point3::new(3000.0, 1000.0, 380.0));
        assert_eq!(wall, Some(-Vector2::x()));
        let front = face_normal(&r, &Point3::new(605.0, 1000.0, 850.0));
        assert_eq!(front, Some(Vector2::x()));
        assert_eq!(face_normal(&r, &Point3::new(300.0, 1000.0, 950.0)), None);
        assert_eq!(face_normal(&r, &Point3::new(1500.0, 1000.0, 1000.0)), None);
    }
}
