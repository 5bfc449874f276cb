//! The admissible region: every hip point where a footprint, at a given
//! heading, lies inside the room and overlaps no obstacle that reaches below
//! the base's clearance height. It is the room shrunk by the footprint,
//! minus each obstacle's footprint grown by the reflected base footprint
//! (their Minkowski sum: for convex outlines, the convex hull of the
//! pairwise differences of corners), optionally cut to a zone.

use geo::{
    BooleanOps, ConvexHull, Coord, LineString, MultiPoint, MultiPolygon, Point, Polygon, Rect,
};

use nalgebra::Vector2;

use super::Footprint;
use crate::scene::{BoxObstacle, MeshObstacle, Room};

/// A rectangle of the floor a user restricts the base to (an approach zone).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Zone {
    pub min: (f64, f64),
    pub max: (f64, f64),
}

/// The hip points where `footprint` fits in `room` at `heading_rad`.
pub fn admissible(
    room: &Room,
    footprint: &Footprint,
    heading_rad: f64,
    clearance_mm: f64,
    zone: Option<Zone>,
) -> MultiPolygon<f64> {
    let corners = footprint.corners(heading_rad);
    let Some(inside) = shrunk_room(room, &corners, zone) else {
        return MultiPolygon::new(Vec::new());
    };
    let grown: Vec<Polygon<f64>> = room
        .boxes
        .iter()
        .filter(|b| b.corner_mm.z < clearance_mm)
        .map(|b| minkowski_with_reflected(&box_outline(b), &corners))
        .chain(room.meshes.iter().filter_map(|m| {
            let outline = mesh_outline(m, clearance_mm)?;
            Some(minkowski_with_reflected(&outline, &corners))
        }))
        .collect();
    let blocked = geo::unary_union(&grown);
    MultiPolygon::new(vec![inside]).difference(&blocked)
}

/// Hip points keeping the whole footprint inside the room (and the zone).
fn shrunk_room(room: &Room, corners: &[Coord<f64>], zone: Option<Zone>) -> Option<Polygon<f64>> {
    let (mut x0, mut y0) = (0.0_f64, 0.0_f64);
    let (mut x1, mut y1) = (room.size_mm.x, room.size_mm.y);
    for c in corners {
        x0 = x0.max(-c.x);
        y0 = y0.max(-c.y);
        x1 = x1.min(room.size_mm.x - c.x);
        y1 = y1.min(room.size_mm.y - c.y);
    }
    if let Some(z) = zone {
        (x0, y0) = (x0.max(z.min.0), y0.max(z.min.1));
        (x1, y1) = (x1.min(z.max.0), y1.min(z.max.1));
    }
    (x0 < x1 && y0 < y1)
        .then(|| Rect::new(Coord { x: x0, y: y0 }, Coord { x: x1, y: y1 }).to_polygon())
}

/// A box obstacle's outline on the floor, turned about its corner.
fn box_outline(b: &BoxObstacle) -> Vec<Coord<f64>> {
    let (w, d) = (b.size_mm.x, b.size_mm.y);
    [(0.0, 0.0), (w, 0.0), (w, d), (0.0, d)]
        .into_iter()
        .map(|(x, y)| {
            let p = b.floor_point(Vector2::new(x, y));
            Coord { x: p.x, y: p.y }
        })
        .collect()
}

/// A mesh's footprint: the convex hull of its vertices below the
/// clearance height (a chair's legs and seat, a fridge's base), or none
/// when the whole mesh is above it.
fn mesh_outline(m: &MeshObstacle, clearance_mm: f64) -> Option<Vec<Coord<f64>>> {
    let low: Vec<Point<f64>> = m
        .vertices_mm
        .iter()
        .filter(|v| v.z < clearance_mm)
        .map(|v| Point::new(v.x, v.y))
        .collect();
    if low.is_empty() {
        return None;
    }
    let hull = MultiPoint::new(low).convex_hull();
    Some(hull.exterior().0.clone())
}

/// `O + (-F)`: the hip points at which footprint `F` would overlap the
/// convex obstacle outline `O`.
fn minkowski_with_reflected(obstacle: &[Coord<f64>], footprint: &[Coord<f64>]) -> Polygon<f64> {
    let points: Vec<Point<f64>> = obstacle
        .iter()
        .flat_map(|o| {
            footprint
                .iter()
                .map(move |f| Point::new(o.x - f.x, o.y - f.y))
        })
        .collect();
    let hull = MultiPoint::new(points).convex_hull();
    Polygon::new(LineString::from(hull.exterior().0.clone()), Vec::new())
}

#[cfg(test)]
mod tests {
    use super::*;
    use geo::{Area, Contains};
    use nalgebra::{Point3, Vector3};

    fn room_with_counter() -> Room {
        Room {
            name: "k".into(),
            size_mm: Vector3::new(3000.0, 2000.0, 2500.0),
            boxes: vec![BoxObstacle {
                name: "counter".into(),
                corner_mm: Point3::new(0.0, 0.0, 0.0),
                size_mm: Vector3::new(600.0, 2000.0, 900.0),
                yaw_rad: 0.0,
            }],
            meshes: Vec::new(),
            targets: Vec::new(),
            surfaces: Vec::new(),
        }
    }

    #[test]
    fn a_circle_keeps_its_radius_from_walls_and_counter() {
        let region = admissible(
            &room_with_counter(),
            &Footprint::Circle { radius_mm: 300.0 },
            0.0,
            2000.0,
            None,
        );
        assert!(region.contains(&Point::new(1000.0, 1000.0)));
        assert!(
            !region.contains(&Point::new(850.0, 1000.0)),
            "too close to the counter"
        );
        assert!(
            !region.contains(&Point::new(1500.0, 250.0)),
            "too close to the wall"
        );
        // Free floor: 3000 - 600 - 2 * 300 wide, 2000 - 2 * 300 deep, give or take the polygon.
        let area = region.unsigned_area();
        assert!(
            (area - 1800.0 * 1400.0).abs() < 0.02 * 1800.0 * 1400.0,
            "{area}"
        );
    }

    #[test]
    fn obstacles_above_the_clearance_do_not_block() {
        let mut room = room_with_counter();
        room.boxes[0].corner_mm.z = 1450.0;
        let region = admissible(
            &room,
            &Footprint::Circle { radius_mm: 300.0 },
            0.0,
            1400.0,
            None,
        );
        assert!(region.contains(&Point::new(400.0, 1000.0)));
    }

    #[test]
    fn a_wheelchair_facing_the_counter_needs_its_front_clear() {
        let chair = Footprint::Rectangle {
            front_mm: 600.0,
            back_mm: 500.0,
            width_mm: 660.0,
        };
        let facing = admissible(
            &room_with_counter(),
            &chair,
            std::f64::consts::PI,
            2000.0,
            None,
        );
        let sideways = admissible(
            &room_with_counter(),
            &chair,
            std::f64::consts::FRAC_PI_2,
            2000.0,
            None,
        );
        // Facing the counter the hip stays 600 mm from it; side on, 330 mm.
        assert!(!facing.contains(&Point::new(1100.0, 1000.0)));
        assert!(facing.contains(&Point::new(1250.0, 1000.0)));
        assert!(sideways.contains(&Point::new(1000.0, 1000.0)));
    }

    #[test]
    fn a_zone_restricts_the_region() {
        let zone = Zone {
            min: (900.0, 800.0),
            max: (1200.0, 1200.0),
        };
        let region = admissible(
            &room_with_counter(),
            &Footprint::Circle { radius_mm: 300.0 },
            0.0,
            2000.0,
            Some(zone),
        );
        assert!(region.contains(&Point::new(1000.0, 1000.0)));
        assert!(!region.contains(&Point::new(1500.0, 1000.0)));
    }

    #[test]
    fn a_footprint_larger_than_the_room_fits_nowhere() {
        let region = admissible(
            &room_with_counter(),
            &Footprint::Circle { radius_mm: 5000.0 },
            0.0,
            2000.0,
            None,
        );
        assert!(region.0.is_empty());
    }
}
