//! The two rooms that bound every room an element's moves make
//! (`advise`): the room with the element's boxes swept over all their
//! moves (each box stretched to hold every place it is moved to), which
//! has more in it than the room at any one position, and the room without
//! them, which has less. Taking obstacles away never takes floor away, so
//! a base gets to no more floor from the doors of the first than of any
//! moved room, and to no less of the second (`floor/shared_routes.rs`
//! asks its routes of these two once, instead of once for each position's
//! room).

use std::collections::hash_map::DefaultHasher;
use std::hash::{Hash, Hasher};
use std::sync::Arc;

use nalgebra::Vector3;

use super::{hash_bits, BoxObstacle, Room};

/// The rooms that bound the rooms of an element's moves.
#[derive(Clone, Debug)]
pub struct Sweep {
    /// Each of the element's boxes stretched over all its moves (shared
    /// by the copies of the sweep a population's members' routes keep).
    pub swept: Arc<Room>,
    /// Without the element's boxes.
    pub without: Arc<Room>,
    /// Both, hashed (what is worked out from them is kept by it).
    pub key: u64,
}

impl Sweep {
    /// The bounds of `room` with the boxes named `names` moved by each of
    /// `moves_mm`; none where there is no move, no box among `names`, or
    /// a turned one (the routes of the room without it would follow other
    /// headings than those of a room with it: `floor/routes.rs`,
    /// `followed_headings`), or where the room has meshes (whose routes
    /// are not bounded, `DoorRoutes::of`, and whose copies would cost).
    pub fn of(room: &Room, names: &[&str], moves_mm: &[Vector3<f64>]) -> Option<Sweep> {
        let first = moves_mm.first()?;
        let carried = |b: &&BoxObstacle| names.contains(&b.name.as_str());
        let boxes: Vec<&BoxObstacle> = room.boxes.iter().filter(carried).collect();
        let turned = boxes.iter().any(|b| b.yaw_rad != 0.0);
        if boxes.is_empty() || turned || !room.meshes.is_empty() {
            return None;
        }
        let (least, most) =
            (moves_mm.iter()).fold((*first, *first), |(lo, hi), m| (lo.inf(m), hi.sup(m)));
        let mut swept = room.clone();
        swept.name = format!("{}\u{0}{names:?} swept", room.name);
        for b in (swept.boxes.iter_mut()).filter(|b| names.contains(&b.name.as_str())) {
            b.corner_mm += least;
            b.size_mm += most - least;
        }
        let carried: Vec<String> = names.iter().map(|n| n.to_string()).collect();
        let without = room.without_boxes(&carried);
        let mut h = DefaultHasher::new();
        for r in [&swept, &without] {
            r.boxes.len().hash(&mut h);
            for b in &r.boxes {
                b.name.hash(&mut h);
                hash_bits(&[b.corner_mm.x, b.corner_mm.y, b.corner_mm.z], &mut h);
                hash_bits(&[b.size_mm.x, b.size_mm.y, b.size_mm.z, b.yaw_rad], &mut h);
            }
        }
        Some(Sweep {
            key: h.finish(),
            swept: Arc::new(swept),
            without: Arc::new(without),
        })
    }

    /// `room` (one of the rooms the sweep bounds) named for the sweep: a
    /// base keeps a room's floor by its name, and a floor bounded by one
    /// sweep costs other work than the same room's alone or bounded by
    /// another sweep (what is charged must not depend on which was worked
    /// out first).
    pub fn named(&self, mut room: Room) -> Room {
        room.name = format!("{}\u{0}within sweep {:x}", room.name, self.key);
        room
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::scene::BoxObstacle;
    use nalgebra::Point3;

    fn room(yaw_rad: f64) -> Room {
        let b = |name: &str, z: f64| BoxObstacle {
            name: name.into(),
            corner_mm: Point3::new(0.0, 2500.0, z),
            size_mm: Vector3::new(400.0, 500.0, 300.0),
            yaw_rad,
        };
        Room {
            name: "kitchen".into(),
            size_mm: Vector3::new(3600.0, 3000.0, 2500.0),
            boxes: vec![b("counter", 0.0), b("microwave", 1000.0)],
            meshes: Vec::new(),
            targets: Vec::new(),
            surfaces: Vec::new(),
            doors: Vec::new(),
        }
    }

    #[test]
    fn the_swept_box_holds_every_move_and_the_room_without_has_none() {
        let moves = [-300.0, 0.0, 450.0].map(|z| Vector3::new(0.0, 0.0, z));
        let sweep = Sweep::of(&room(0.0), &["microwave"], &moves).expect("a sweep");
        let swept = &sweep.swept.boxes[1];
        assert_eq!(swept.corner_mm, Point3::new(0.0, 2500.0, 700.0));
        assert_eq!(swept.size_mm, Vector3::new(400.0, 500.0, 1050.0));
        assert_eq!(sweep.swept.boxes[0], room(0.0).boxes[0]);
        let names: Vec<&str> = (sweep.without.boxes.iter())
            .map(|b| b.name.as_str())
            .collect();
        assert_eq!(names, ["counter"]);
        assert_ne!(sweep.swept.name, room(0.0).name);
    }

    #[test]
    fn a_turned_box_no_box_or_no_move_has_no_sweep() {
        let up = [0.0, 100.0].map(|z| Vector3::new(0.0, 0.0, z));
        let along = [0.0, 100.0].map(|x| Vector3::new(x, 0.0, 0.0));
        assert!(Sweep::of(&room(0.0), &["microwave"], &up).is_some());
        assert!(Sweep::of(&room(0.0), &["microwave"], &along).is_some());
        // Without it, the room's routes would not follow its headings.
        assert!(Sweep::of(&room(0.3), &["microwave"], &up).is_none());
        assert!(Sweep::of(&room(0.0), &["microwave"], &[]).is_none());
        assert!(Sweep::of(&room(0.0), &["a target"], &up).is_none());
    }

    #[test]
    fn a_room_named_for_a_sweep_is_named_for_no_other() {
        let up = |z: f64| [0.0, z].map(|z| Vector3::new(0.0, 0.0, z));
        let sweep = |z: f64| Sweep::of(&room(0.0), &["microwave"], &up(z)).expect("a sweep");
        let named = |s: &Sweep| s.named(room(0.0)).name;
        assert_ne!(named(&sweep(100.0)), named(&sweep(200.0)));
        assert_ne!(named(&sweep(100.0)), room(0.0).name);
    }
}
