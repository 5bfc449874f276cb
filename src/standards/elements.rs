//! What stands between the floor and an element (a target), approached
//! from one side: building standards measure a reach over an obstruction
//! by its depth (from the element to the obstruction's edge nearest the
//! person) and height (its top), and refuse a reach through something at
//! the element's own height. Boxes only: meshes are not measured.

use nalgebra::{Point3, Vector2};

use crate::scene::{BoxObstacle, Room};

/// An element approached from one side.
#[derive(Clone, Debug, PartialEq)]
pub struct Approached {
    /// From the element towards the person, a unit vector on the floor.
    pub toward: Vector2<f64>,
    /// How far the obstruction reaches from the element towards the person
    /// (0: nothing to reach over).
    pub depth_mm: f64,
    /// The obstruction's top (0: none).
    pub height_mm: f64,
    /// The boxes reached over, by index.
    pub under: Vec<usize>,
    /// The board the element rests on, left out of the obstruction: it
    /// stands over a lower one (a shelf over a counter), and the hand
    /// reaches onto it, not over it.
    pub support: Option<usize>,
    /// The boxes the way crosses at the element's own height: how far
    /// along the way each begins, and its index, nearest first.
    pub at_height: Vec<(f64, usize)>,
}

impl Approached {
    /// The first box at the element's height that stands where the hand
    /// must pass: between the element and the obstruction's edge, or, if it
    /// leaves the floor free (its underside at `free_above_mm` or higher),
    /// over the person's place, up to `person_mm` beyond that edge (a box
    /// on the floor there takes the person's floor space instead).
    pub fn blocked_by(&self, room: &Room, person_mm: f64, free_above_mm: f64) -> Option<usize> {
        self.at_height
            .iter()
            .find(|&&(t0, i)| {
                t0 <= self.depth_mm + TOUCHING_MM
                    || (room.boxes[i].corner_mm.z >= free_above_mm
                        && t0 < self.depth_mm + person_mm)
            })
            .map(|&(_, i)| i)
    }
}

/// Within this of each other, two distances along the way are one (an
/// element resting on a board, a board butting another).
const TOUCHING_MM: f64 = 1.0;
/// A board whose top is at most this far below an element above it is
/// what the element rests on (a mug's handle is some 60 mm above its
/// shelf).
const RESTING_MM: f64 = 150.0;
/// A board is a shelf over a lower box only with at least this much room
/// between the two (a hand, or a jar, goes under it); closer, the two are
/// one obstruction (a worktop on base units, a basin on its vanity).
const SHELF_GAP_MM: f64 = 100.0;

/// `at` approached from `toward` (a unit vector on the floor, from the
/// element towards the person): the boxes below the element that the
/// way crosses one after another from the element (its obstruction; the
/// board the element rests on left out where it stands over a lower
/// one), and the boxes the way crosses at the element's height.
pub fn approached(room: &Room, at: &Point3<f64>, toward: Vector2<f64>) -> Approached {
    let origin = at.xy().coords;
    let mut crossed: Vec<(f64, f64, usize)> = room
        .boxes
        .iter()
        .enumerate()
        .filter_map(|(i, b)| crossing(b, origin, toward).map(|(t0, t1)| (t0, t1, i)))
        .filter(|&(_, t1, _)| t1 > TOUCHING_MM)
        .collect();
    crossed.sort_by(|a, b| a.0.total_cmp(&b.0).then(a.2.cmp(&b.2)));
    let first = obstruction(room, at, toward, &crossed, None);
    match support(room, at, &first) {
        Some(board) => obstruction(room, at, toward, &crossed, Some(board)),
        None => first,
    }
}

/// The obstruction the way crosses (leaving out `skip`), and what it
/// crosses at the element's height.
fn obstruction(
    room: &Room,
    at: &Point3<f64>,
    toward: Vector2<f64>,
    crossed: &[(f64, f64, usize)],
    skip: Option<usize>,
) -> Approached {
    let mut approached = Approached {
        toward,
        depth_mm: 0.0,
        height_mm: 0.0,
        under: Vec::new(),
        support: skip,
        at_height: Vec::new(),
    };
    for &(t0, t1, i) in crossed.iter().filter(|c| Some(c.2) != skip) {
        let b = &room.boxes[i];
        let (bottom, top) = (b.corner_mm.z, b.corner_mm.z + b.size_mm.z);
        if top <= at.z + TOUCHING_MM {
            // Below the element: reached over, if it joins the boxes
            // before it.
            if t0 <= approached.depth_mm + TOUCHING_MM {
                approached.depth_mm = approached.depth_mm.max(t1);
                approached.height_mm = approached.height_mm.max(top);
                approached.under.push(i);
            }
        } else if bottom < at.z - TOUCHING_MM {
            approached.at_height.push((t0.max(0.0), i));
        }
    }
    approached
}

/// The board under the element that it rests on, where the obstruction
/// also holds a lower box, at least [`SHELF_GAP_MM`] below it, that
/// reaches as far towards the person (a shelf over a counter). Where the board reaches
/// farther than every box below it (a basin over a trap box against the
/// wall), the hand reaches over the board, and the space under it may be
/// knee space.
fn support(room: &Room, at: &Point3<f64>, a: &Approached) -> Option<usize> {
    let top = |i: usize| room.boxes[i].corner_mm.z + room.boxes[i].size_mm.z;
    let board = a
        .under
        .iter()
        .copied()
        .filter(|&i| box_holds(&room.boxes[i], at.xy().coords))
        .filter(|&i| top(i) >= at.z - RESTING_MM)
        .max_by(|&i, &j| top(i).total_cmp(&top(j)))?;
    let bottom = room.boxes[board].corner_mm.z;
    let reach = |i: usize| {
        crossing(&room.boxes[i], at.xy().coords, a.toward).map_or(f64::NEG_INFINITY, |c| c.1)
    };
    a.under
        .iter()
        .any(|&i| {
            i != board && top(i) <= bottom - SHELF_GAP_MM && reach(i) >= reach(board) - TOUCHING_MM
        })
        .then_some(board)
}

/// Whether the box's outline from above holds the point.
fn box_holds(b: &BoxObstacle, p: Vector2<f64>) -> bool {
    let local = b.rotation().inverse() * (p - b.corner_mm.xy().coords);
    (-TOUCHING_MM..=b.size_mm.x + TOUCHING_MM).contains(&local.x)
        && (-TOUCHING_MM..=b.size_mm.y + TOUCHING_MM).contains(&local.y)
}

/// Whether the way from `at` along `toward` crosses the box's outline
/// from above within `within_mm` of the element.
pub fn crossing_within(
    b: &BoxObstacle,
    at: &Point3<f64>,
    toward: Vector2<f64>,
    within_mm: f64,
) -> bool {
    crossing(b, at.xy().coords, toward).is_some_and(|(t0, t1)| t1 > 0.0 && t0 < within_mm)
}

/// Where the ray from `origin` along `dir` (on the floor) enters and
/// leaves the box's outline from above, if it meets it (distances along
/// the ray, the entry possibly behind the origin).
fn crossing(b: &BoxObstacle, origin: Vector2<f64>, dir: Vector2<f64>) -> Option<(f64, f64)> {
    // In the box's own axes, from its corner.
    let turn = b.rotation().inverse();
    let o = turn * (origin - b.corner_mm.xy().coords);
    let d = turn * dir;
    let (mut t0, mut t1) = (f64::NEG_INFINITY, f64::INFINITY);
    for (oi, di, size) in [(o.x, d.x, b.size_mm.x), (o.y, d.y, b.size_mm.y)] {
        if di.abs() < 1e-12 {
            if oi < 0.0 || oi > size {
                return None;
            }
            continue;
        }
        let (a, c) = ((0.0 - oi) / di, (size - oi) / di);
        t0 = t0.max(a.min(c));
        t1 = t1.min(a.max(c));
    }
    (t0 <= t1).then_some((t0, t1))
}

/// How high the space under the obstruction is at its front: the lowest
/// underside among the boxes reached over that the way crosses within
/// `front_mm` of the obstruction's edge nearest the person. A box further
/// back (a trap box against the wall under a basin) does not lower it; it
/// narrows the space instead ([`narrowings`]).
pub fn knee_height(room: &Room, at: &Point3<f64>, a: &Approached, front_mm: f64) -> f64 {
    let origin = at.xy().coords;
    a.under
        .iter()
        .map(|&i| &room.boxes[i])
        .filter(|b| {
            crossing(b, origin, a.toward)
                .is_some_and(|(_, t1)| t1 > a.depth_mm - front_mm + TOUCHING_MM)
        })
        .map(|b| b.corner_mm.z)
        .fold(f64::INFINITY, f64::min)
}

/// Where the space under an obstruction narrows: a box that comes down
/// into it (or the wall, from the floor up), how far back from the
/// obstruction's front edge it begins and how low it comes.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Narrowing {
    pub depth_mm: f64,
    pub bottom_mm: f64,
}

/// The narrowings of the space under the obstruction, from `front_mm`
/// along the way (its edge nearest the person) back towards and past the
/// element: each box whose underside is below `below_mm` that the way
/// back crosses (from its edge, 0 where it stands at the front), and the
/// room's wall.
pub fn narrowings(
    room: &Room,
    at: &Point3<f64>,
    toward: Vector2<f64>,
    front_mm: f64,
    below_mm: f64,
) -> Vec<Narrowing> {
    let origin = at.xy().coords + toward * front_mm;
    let back = -toward;
    let mut found: Vec<Narrowing> = (room.boxes.iter())
        .filter(|b| b.corner_mm.z < below_mm)
        .filter_map(|b| {
            let (t0, t1) = crossing(b, origin, back)?;
            (t1 > TOUCHING_MM).then_some(Narrowing {
                depth_mm: t0.max(0.0),
                bottom_mm: b.corner_mm.z,
            })
        })
        .collect();
    found.push(Narrowing {
        depth_mm: wall_distance(room, origin, back),
        bottom_mm: 0.0,
    });
    found
}

/// How far from `origin` along `dir` the room's wall is.
pub fn wall_distance(room: &Room, origin: Vector2<f64>, dir: Vector2<f64>) -> f64 {
    let mut t = f64::INFINITY;
    for (o, d, size) in [
        (origin.x, dir.x, room.size_mm.x),
        (origin.y, dir.y, room.size_mm.y),
    ] {
        if d > 1e-12 {
            t = t.min((size - o) / d);
        } else if d < -1e-12 {
            t = t.min(-o / d);
        }
    }
    t
}

#[cfg(test)]
mod tests {
    use super::*;
    use nalgebra::Vector3;

    fn block(name: &str, corner: [f64; 3], size: [f64; 3]) -> BoxObstacle {
        BoxObstacle {
            name: name.into(),
            corner_mm: Point3::from(corner),
            size_mm: Vector3::from(size),
            yaw_rad: 0.0,
        }
    }

    fn kitchen() -> Room {
        Room {
            name: "k".into(),
            size_mm: Vector3::new(4000.0, 3000.0, 2500.0),
            boxes: vec![
                block("counter", [0.0, 0.0, 0.0], [600.0, 3000.0, 900.0]),
                block("wall_cabinet", [0.0, 0.0, 1450.0], [350.0, 3000.0, 700.0]),
                block("sink", [0.0, 0.0, 700.0], [600.0, 800.0, 200.0]),
            ],
            meshes: Vec::new(),
            targets: Vec::new(),
            surfaces: Vec::new(),
            doors: Vec::new(),
        }
    }

    #[test]
    fn a_cup_on_a_counter_is_reached_over_the_counter() {
        let room = kitchen();
        let cup = Point3::new(300.0, 1500.0, 960.0);
        let from_room = approached(&room, &cup, Vector2::x());
        assert!((from_room.depth_mm - 300.0).abs() < 1e-9);
        assert_eq!(from_room.height_mm, 900.0);
        assert_eq!(from_room.under, [0]);
        assert_eq!(from_room.blocked_by(&room, 1220.0, 685.0), None);
        // From the wall's side the wall is in the way: nothing is crossed.
        let from_wall = approached(&room, &cup, -Vector2::x());
        assert!((from_wall.depth_mm - 300.0).abs() < 1e-9);
    }

    #[test]
    fn a_shelf_inside_a_cabinet_is_behind_its_front() {
        let room = kitchen();
        // Inside the wall cabinet, at its height: the cabinet is in the way.
        let inside = Point3::new(200.0, 1500.0, 1600.0);
        let a = approached(&room, &inside, Vector2::x());
        assert_eq!(a.blocked_by(&room, 1220.0, 685.0), Some(1));
        // A handle on the counter's front: nothing to reach over.
        let handle = Point3::new(600.0, 1500.0, 700.0);
        let a = approached(&room, &handle, Vector2::x());
        assert_eq!(
            (a.depth_mm, a.blocked_by(&room, 1220.0, 685.0)),
            (0.0, None)
        );
    }

    #[test]
    fn the_knee_space_under_a_sink_runs_to_the_wall() {
        let room = kitchen();
        let tap = Point3::new(300.0, 400.0, 960.0);
        let a = approached(&room, &tap, Vector2::x());
        // The counter and the sink are both reached over.
        assert!((a.depth_mm - 300.0).abs() < 1e-9);
        // Under the sink (from 700 mm) there is knee space, but the counter
        // box under it comes to the floor at its front: none.
        let first = |n: Vec<Narrowing>| n.iter().map(|n| n.depth_mm).fold(f64::INFINITY, f64::min);
        assert!(first(narrowings(&room, &tap, Vector2::x(), a.depth_mm, 685.0)) < 1e-9);
        let mut open = kitchen();
        open.boxes[0].corner_mm.y = 800.0;
        open.boxes[0].size_mm.y = 2200.0;
        let a = approached(&open, &tap, Vector2::x());
        let depth = first(narrowings(&open, &tap, Vector2::x(), a.depth_mm, 685.0));
        assert!((depth - 600.0).abs() < 1e-9, "{depth}");
    }

    #[test]
    fn a_trap_box_at_the_wall_shortens_the_knee_space_not_its_height() {
        // A basin 550 deep, its underside at 720 mm, open below; a trap box
        // 150 deep against the wall from the floor to 500 mm.
        let mut room = kitchen();
        room.boxes = vec![
            block("basin", [0.0, 1000.0, 720.0], [550.0, 600.0, 150.0]),
            block("trap_box", [0.0, 1150.0, 0.0], [150.0, 300.0, 500.0]),
        ];
        let tap = Point3::new(100.0, 1300.0, 900.0);
        let a = approached(&room, &tap, Vector2::x());
        assert!((a.depth_mm - 450.0).abs() < 1e-9, "{a:?}");
        assert_eq!(a.under, [0, 1]);
        // The front 280 mm are open up to the basin's underside.
        assert_eq!(knee_height(&room, &tap, &a, 280.0), 720.0);
        // The space runs back from the basin's front to the trap box, up
        // to 500 mm, and to the wall above it.
        let n = narrowings(&room, &tap, Vector2::x(), a.depth_mm, 685.0);
        let trap = Narrowing {
            depth_mm: 400.0,
            bottom_mm: 0.0,
        };
        let wall = Narrowing {
            depth_mm: 550.0,
            bottom_mm: 0.0,
        };
        assert_eq!(n, [trap, wall]);
        // A vanity cabinet as deep as the basin, from the floor, leaves
        // no knee space.
        room.boxes[1].size_mm = Vector3::new(550.0, 300.0, 700.0);
        let a = approached(&room, &tap, Vector2::x());
        assert_eq!(knee_height(&room, &tap, &a, 280.0), 0.0);
    }

    #[test]
    fn only_what_stands_where_the_hand_passes_blocks() {
        let mut room = kitchen();
        // A tall cupboard across the room, 2 m from the counter, at the
        // cup's height: not in the way.
        room.boxes.push(block(
            "cupboard",
            [2600.0, 0.0, 0.0],
            [600.0, 3000.0, 2000.0],
        ));
        let cup = Point3::new(300.0, 1500.0, 960.0);
        let a = approached(&room, &cup, Vector2::x());
        assert_eq!(a.at_height.len(), 1);
        assert_eq!(a.blocked_by(&room, 1220.0, 685.0), None);
        // A shelf hung at the cup's height over where the person sits
        // (the floor under it free): in the way.
        room.boxes
            .push(block("hung", [900.0, 0.0, 900.0], [200.0, 3000.0, 200.0]));
        let a = approached(&room, &cup, Vector2::x());
        assert_eq!(a.blocked_by(&room, 1220.0, 685.0), Some(4));
    }

    #[test]
    fn a_shelf_over_a_counter_is_reached_onto_not_over() {
        let mut room = kitchen();
        room.boxes
            .push(block("board", [0.0, 0.0, 1100.0], [350.0, 3000.0, 20.0]));
        // A jar on the board, 60 mm up: the obstruction is the counter.
        let jar = Point3::new(175.0, 1500.0, 1180.0);
        let a = approached(&room, &jar, Vector2::x());
        assert_eq!(a.support, Some(3));
        assert_eq!(a.under, [0]);
        assert_eq!(a.height_mm, 900.0);
        assert!((a.depth_mm - 425.0).abs() < 1e-9);
        // A worktop 2 mm above its base units is no shelf: the jar on it
        // is reached over both, 900 mm high.
        let mut worktop = kitchen();
        worktop.boxes[0].size_mm.z = 860.0;
        worktop.boxes[2] = block("top", [0.0, 0.0, 862.0], [600.0, 3000.0, 40.0]);
        let jar = Point3::new(300.0, 1500.0, 960.0);
        let a = approached(&worktop, &jar, Vector2::x());
        assert_eq!((a.support, a.height_mm), (None, 902.0));
        // A cup on the counter itself: the counter is the obstruction.
        let cup = Point3::new(300.0, 1500.0, 960.0);
        assert_eq!(approached(&room, &cup, Vector2::x()).support, None);
    }
}
