//! Where a base that moves can get to from a room's doors: connectivity in
//! its configuration space. A base that turns with its footprint (a
//! wheelchair) moves in x, y and heading: at each of a set of headings
//! (every 22.5 degrees, the base's own and each door's inward one) the
//! admissible region falls into pieces it can drive about in; it can turn
//! from one heading to the next only where the floor holds what its
//! footprint sweeps while turning in place (`Footprint::swept`), which
//! joins a piece at one heading to a piece at the next. A base that does
//! not turn (a circle) moves in x and y: the pieces of its one region.
//! It comes in through a door facing into the room, its whole width
//! within the opening, its back at the wall. The pieces joined to one it
//! comes in by are where it can get to; a placement elsewhere is cut off.

use std::f64::consts::TAU;

use geo::{
    Contains, ConvexHull, Coord, Distance, Euclidean, InteriorPoint, Intersects, LineString,
    MultiPoint, MultiPolygon, Point, Polygon, Rect,
};

use super::obstacles::{box_outline, FloorObstacles};
use super::region::{admissible_in, shrunk_room, Turned};
use super::Footprint;
use crate::scene::{Door, MeshObstacle, Room, Wall};

/// The headings a turning base is followed at, besides its own and the
/// doors': every 22.5 degrees.
const HEADINGS: usize = 16;
/// How far in from the wall a base that has just come in may stand.
const DOORWAY_MM: f64 = 20.0;
/// Headings closer than this are one.
const SAME_HEADING_RAD: f64 = 1e-9;

/// Where a base can get to in one room.
pub struct Routes {
    /// The headings followed, ascending in [0, 2 pi), each with its
    /// admissible region's pieces and whether each can be got to.
    headings: Vec<Pieces>,
    /// How the base comes in, door by door.
    pub doors: Vec<Doorway>,
}

/// The admissible region at one heading, piece by piece.
struct Pieces {
    heading_rad: f64,
    region: MultiPolygon<f64>,
    reached: Vec<bool>,
}

/// Whether a base comes in through a door.
#[derive(Clone, Debug, PartialEq)]
pub struct Doorway {
    pub name: String,
    pub width_mm: f64,
    /// How wide the base is across the opening.
    pub needs_mm: f64,
    pub comes_in: Entry,
}

/// A base the room's doors shut out: each door and whether the base comes
/// in by it; whether it was kept to a zone (which it then cannot get to);
/// its footprint's length and width.
#[derive(Clone, Debug, PartialEq)]
pub struct Shut {
    pub doors: Vec<Doorway>,
    pub in_zone: bool,
    pub footprint_mm: [f64; 2],
}

#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Entry {
    /// It fits through and has room just inside.
    Through,
    /// The opening is narrower than the base.
    TooNarrow,
    /// It fits through, but something stands just inside.
    Blocked,
}

impl Routes {
    /// Where a base of `footprint` can get to in `room` from its doors,
    /// followed at the base's `headings` too; none if the room has no
    /// door (then it may be placed wherever it fits).
    pub fn new(room: &Room, footprint: &Footprint, headings: &[f64]) -> Option<Routes> {
        if room.doors.is_empty() {
            return None;
        }
        let obstacles = FloorObstacles::new(room, footprint);
        let followed = followed_headings(footprint, headings, &room.doors);
        let mut pieces: Vec<Pieces> = followed
            .iter()
            .map(|&h| Pieces::at(room, footprint, h, &obstacles))
            .collect();
        let mut joined = Joined::new(&pieces);
        if footprint.turns() {
            join_turns(room, footprint, &obstacles, &pieces, &mut joined);
        }
        let mut doors = Vec::new();
        for door in &room.doors {
            let (doorway, starts) = come_in(room, footprint, door, &pieces);
            for (h, k) in starts {
                joined.start(h, k);
            }
            doors.push(doorway);
        }
        for (h, p) in pieces.iter_mut().enumerate() {
            p.reached = (0..p.region.0.len())
                .map(|k| joined.reached(h, k))
                .collect();
        }
        Some(Routes {
            headings: pieces,
            doors,
        })
    }

    /// Whether the base comes in through any door.
    pub fn enters(&self) -> bool {
        self.doors.iter().any(|d| d.comes_in == Entry::Through)
    }

    /// The pieces of the admissible region at `heading_rad` (one of the
    /// headings given to `new`) the base can get to.
    pub fn reached(&self, heading_rad: f64) -> MultiPolygon<f64> {
        let Some(p) = self.pieces(heading_rad) else {
            return MultiPolygon::new(Vec::new());
        };
        let kept = (p.region.0.iter().zip(&p.reached))
            .filter(|(_, &r)| r)
            .map(|(poly, _)| poly.clone());
        MultiPolygon::new(kept.collect())
    }

    /// The pieces of the admissible region at `heading_rad` the base
    /// cannot get to.
    pub fn cut_off(&self, heading_rad: f64) -> MultiPolygon<f64> {
        let Some(p) = self.pieces(heading_rad) else {
            return MultiPolygon::new(Vec::new());
        };
        let kept = (p.region.0.iter().zip(&p.reached))
            .filter(|(_, &r)| !r)
            .map(|(poly, _)| poly.clone());
        MultiPolygon::new(kept.collect())
    }

    /// The room's obstacles (boxes, then meshes, by index) that close in
    /// the floor a base of `footprint` at `heading_rad` with its hip at
    /// `hip_mm` cannot get to from a door: those within the footprint's
    /// reach of that floor's edge, nearest first.
    pub fn enclosing(
        room: &Room,
        footprint: &Footprint,
        heading_rad: f64,
        hip_mm: (f64, f64),
    ) -> Vec<usize> {
        let Some(routes) = Routes::new(room, footprint, &[heading_rad]) else {
            return Vec::new();
        };
        let hip = Point::new(hip_mm.0, hip_mm.1);
        let cut_off = routes.cut_off(heading_rad);
        let piece = cut_off.0.iter().min_by(|a, b| {
            Euclidean
                .distance(*a, &hip)
                .total_cmp(&Euclidean.distance(*b, &hip))
        });
        let Some(piece) = piece else {
            return Vec::new();
        };
        let reach_mm = footprint.extent_mm() + DOORWAY_MM;
        let mut near: Vec<(f64, usize)> = room
            .boxes
            .iter()
            .enumerate()
            .map(|(i, b)| {
                let outline = Polygon::new(LineString::from(box_outline(b)), Vec::new());
                (Euclidean.distance(&outline, piece.exterior()), i)
            })
            .chain(room.meshes.iter().enumerate().map(|(k, m)| {
                let outline = mesh_outline(m);
                (
                    Euclidean.distance(&outline, piece.exterior()),
                    room.boxes.len() + k,
                )
            }))
            .filter(|(d, _)| *d <= reach_mm)
            .collect();
        near.sort_by(|a, b| a.0.total_cmp(&b.0).then(a.1.cmp(&b.1)));
        near.into_iter().map(|(_, i)| i).collect()
    }

    fn pieces(&self, heading_rad: f64) -> Option<&Pieces> {
        let h = normalized(heading_rad);
        self.headings
            .iter()
            .find(|p| (p.heading_rad - h).abs() <= SAME_HEADING_RAD)
    }
}

impl Pieces {
    fn at(
        room: &Room,
        footprint: &Footprint,
        heading_rad: f64,
        obstacles: &FloorObstacles,
    ) -> Self {
        let region = region_at(room, footprint, heading_rad, obstacles);
        Pieces {
            heading_rad,
            reached: vec![false; region.0.len()],
            region,
        }
    }

    /// The piece holding `p`, or the nearest within a millimetre (a point
    /// a boolean operation left on an edge).
    fn piece_at(&self, p: Point<f64>) -> Option<usize> {
        let polygons = &self.region.0;
        if let Some(k) = polygons.iter().position(|poly| poly.contains(&p)) {
            return Some(k);
        }
        polygons
            .iter()
            .map(|poly| Euclidean.distance(poly, &p))
            .enumerate()
            .filter(|(_, d)| *d <= 1.0)
            .min_by(|a, b| a.1.total_cmp(&b.1))
            .map(|(k, _)| k)
    }
}

/// Where `footprint` fits in the whole room at `heading_rad`.
fn region_at(
    room: &Room,
    footprint: &Footprint,
    heading_rad: f64,
    obstacles: &FloorObstacles,
) -> MultiPolygon<f64> {
    let turned = Turned::new(footprint, heading_rad);
    match shrunk_room(room, &turned, None) {
        Some(within) => admissible_in(within, &turned, obstacles),
        None => MultiPolygon::new(Vec::new()),
    }
}

/// The headings followed: one for a base that does not turn; else every
/// [`HEADINGS`]th of a turn, the base's own and each door's inward one,
/// ascending in [0, 2 pi).
fn followed_headings(footprint: &Footprint, headings: &[f64], doors: &[Door]) -> Vec<f64> {
    if !footprint.turns() {
        return vec![0.0];
    }
    let mut all: Vec<f64> = (0..HEADINGS)
        .map(|k| k as f64 * TAU / HEADINGS as f64)
        .chain(headings.iter().copied())
        .chain(doors.iter().map(Door::inward_heading_rad))
        .map(normalized)
        .collect();
    all.sort_by(f64::total_cmp);
    all.dedup_by(|a, b| (*a - *b).abs() <= SAME_HEADING_RAD);
    all
}

/// `heading_rad` in [0, 2 pi).
fn normalized(heading_rad: f64) -> f64 {
    let h = heading_rad.rem_euclid(TAU);
    if TAU - h <= SAME_HEADING_RAD {
        0.0
    } else {
        h
    }
}

/// Join each heading's pieces to the next heading's where the base can
/// turn between them: the pieces of the region where it fits what it
/// sweeps turning from the one to the other.
fn join_turns(
    room: &Room,
    footprint: &Footprint,
    obstacles: &FloorObstacles,
    pieces: &[Pieces],
    joined: &mut Joined,
) {
    let n = pieces.len();
    for h in 0..n {
        let next = (h + 1) % n;
        let from = pieces[h].heading_rad;
        let angle = (pieces[next].heading_rad - from).rem_euclid(TAU);
        let angle = if n == 1 { TAU } else { angle };
        let swept = footprint.swept(angle);
        let turning = region_at(room, &swept, from, obstacles);
        for poly in &turning.0 {
            let Some(p) = poly.interior_point() else {
                continue;
            };
            if let (Some(a), Some(b)) = (pieces[h].piece_at(p), pieces[next].piece_at(p)) {
                joined.union((h, a), (next, b));
            }
        }
    }
}

/// How a base comes in through `door`, and the pieces it comes in to
/// (heading, piece).
fn come_in(
    room: &Room,
    footprint: &Footprint,
    door: &Door,
    pieces: &[Pieces],
) -> (Doorway, Vec<(usize, usize)>) {
    let inward = door.inward_heading_rad();
    let turned = Turned::new(footprint, inward);
    let corners: Vec<Coord<f64>> = turned.parts.iter().flatten().copied().collect();
    // Along the wall (y for an x wall) and into the room.
    let along = |c: &Coord<f64>| match door.wall {
        Wall::XMin | Wall::XMax => c.y,
        _ => c.x,
    };
    let (lo, hi) = corners
        .iter()
        .map(along)
        .fold((f64::INFINITY, f64::NEG_INFINITY), |(a, b), v| {
            (a.min(v), b.max(v))
        });
    let needs_mm = hi - lo;
    let mut doorway = Doorway {
        name: door.name.clone(),
        width_mm: door.width_mm,
        needs_mm,
        comes_in: Entry::TooNarrow,
    };
    let [open_lo, open_hi] = door.span_mm();
    let (from, to) = (open_lo - lo, open_hi - hi);
    if from > to {
        return (doorway, Vec::new());
    }
    let Some(band) = doorway_band(room, door, &turned, from, to) else {
        doorway.comes_in = Entry::Blocked;
        return (doorway, Vec::new());
    };
    let h = pieces
        .iter()
        .position(|p| (p.heading_rad - normalized(inward)).abs() <= SAME_HEADING_RAD)
        .unwrap_or(0);
    let starts: Vec<(usize, usize)> = (pieces[h].region.0.iter().enumerate())
        .filter(|(_, poly)| poly.intersects(&band))
        .map(|(k, _)| (h, k))
        .collect();
    doorway.comes_in = if starts.is_empty() {
        Entry::Blocked
    } else {
        Entry::Through
    };
    (doorway, starts)
}

/// The hip points of a base just come in through `door` (its back at the
/// wall, within [`DOORWAY_MM`]), its hip between `from` and `to` along the
/// wall; none if the room has no such floor.
fn doorway_band(
    room: &Room,
    door: &Door,
    turned: &Turned,
    from: f64,
    to: f64,
) -> Option<Rect<f64>> {
    let within = shrunk_room(room, turned, None)?;
    let (lo, hi) = (within.min(), within.max());
    let rect = match door.wall {
        Wall::XMin => (lo.x, lo.x + DOORWAY_MM, from, to),
        Wall::XMax => (hi.x - DOORWAY_MM, hi.x, from, to),
        Wall::YMin => (from, to, lo.y, lo.y + DOORWAY_MM),
        _ => (from, to, hi.y - DOORWAY_MM, hi.y),
    };
    let (x0, x1, y0, y1) = rect;
    (x0 <= x1 && y0 <= y1).then(|| Rect::new(Coord { x: x0, y: y0 }, Coord { x: x1, y: y1 }))
}

/// A mesh's outline on the floor, for naming it: the convex hull of its
/// vertices from above.
fn mesh_outline(mesh: &MeshObstacle) -> Polygon<f64> {
    let points: Vec<Point<f64>> = mesh
        .vertices_mm
        .iter()
        .map(|v| Point::new(v.x, v.y))
        .collect();
    MultiPoint::new(points).convex_hull()
}

/// Which pieces are joined (a union-find over every heading's pieces),
/// and which are come in to.
struct Joined {
    /// Where each heading's pieces start in `parent`.
    first: Vec<usize>,
    parent: Vec<usize>,
    started: Vec<bool>,
}

impl Joined {
    fn new(pieces: &[Pieces]) -> Self {
        let mut first = Vec::with_capacity(pieces.len());
        let mut total = 0;
        for p in pieces {
            first.push(total);
            total += p.region.0.len();
        }
        Joined {
            first,
            parent: (0..total).collect(),
            started: vec![false; total],
        }
    }

    fn root(&mut self, mut i: usize) -> usize {
        while self.parent[i] != i {
            self.parent[i] = self.parent[self.parent[i]];
            i = self.parent[i];
        }
        i
    }

    fn union(&mut self, (h, a): (usize, usize), (g, b): (usize, usize)) {
        let (ra, rb) = (self.root(self.first[h] + a), self.root(self.first[g] + b));
        let (keep, gone) = (ra.min(rb), ra.max(rb));
        self.parent[gone] = keep;
        self.started[keep] |= self.started[gone];
    }

    fn start(&mut self, h: usize, k: usize) {
        let r = self.root(self.first[h] + k);
        self.started[r] = true;
    }

    fn reached(&mut self, h: usize, k: usize) -> bool {
        let r = self.root(self.first[h] + k);
        self.started[r]
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::scene::BoxObstacle;
    use geo::Contains;
    use nalgebra::{Point3, Vector3};
    use std::f64::consts::{FRAC_PI_2, PI};

    fn block(name: &str, corner: [f64; 2], size: [f64; 2]) -> BoxObstacle {
        BoxObstacle {
            name: name.into(),
            corner_mm: Point3::new(corner[0], corner[1], 0.0),
            size_mm: Vector3::new(size[0], size[1], 900.0),
            yaw_rad: 0.0,
        }
    }

    fn room(size: [f64; 2], boxes: Vec<BoxObstacle>, doors: Vec<Door>) -> Room {
        Room {
            name: "r".into(),
            size_mm: Vector3::new(size[0], size[1], 2500.0),
            boxes,
            meshes: Vec::new(),
            targets: Vec::new(),
            surfaces: Vec::new(),
            doors,
        }
    }

    fn door(wall: Wall, along_mm: f64, width_mm: f64) -> Door {
        Door {
            name: "d".into(),
            wall,
            along_mm,
            width_mm,
        }
    }

    /// A chair 1065 mm long (700 ahead of the hip, 365 behind) and 660 mm
    /// wide.
    fn chair() -> Footprint {
        Footprint::rectangle(700.0, 365.0, 660.0, 1400.0)
    }

    fn reaches(routes: &Routes, heading: f64, x: f64, y: f64) -> bool {
        routes.reached(heading).contains(&Point::new(x, y))
    }

    /// A 4 x 6 m room cut across at y = 3000 by two boxes with a gap of
    /// `gap` between them; the door in the near wall.
    fn divided(gap: f64) -> Room {
        let left = (4000.0 - gap) / 2.0;
        room(
            [4000.0, 6000.0],
            vec![
                block("left", [0.0, 2900.0], [left, 200.0]),
                block("right", [left + gap, 2900.0], [4000.0 - left - gap, 200.0]),
            ],
            vec![door(Wall::YMin, 2000.0, 900.0)],
        )
    }

    #[test]
    fn a_gap_a_millimetre_narrower_than_the_chair_closes_the_way_and_one_wider_opens_it() {
        let headings = [FRAC_PI_2];
        let far = (2000.0, 4500.0);
        let narrow = Routes::new(&divided(659.0), &chair(), &headings).unwrap();
        assert!(narrow.enters());
        assert!(reaches(&narrow, FRAC_PI_2, 2000.0, 1500.0), "the near side");
        assert!(
            !reaches(&narrow, FRAC_PI_2, far.0, far.1),
            "cut off at 659 mm"
        );
        let wide = Routes::new(&divided(661.0), &chair(), &headings).unwrap();
        assert!(reaches(&wide, FRAC_PI_2, far.0, far.1), "through at 661 mm");
    }

    #[test]
    fn a_pocket_closed_on_every_side_is_cut_off() {
        // An island of four boxes round a 1.5 m square of floor.
        let boxes = vec![
            block("north", [1000.0, 3500.0], [2000.0, 600.0]),
            block("south", [1000.0, 1400.0], [2000.0, 600.0]),
            block("west", [1000.0, 2000.0], [400.0, 1500.0]),
            block("east", [2600.0, 2000.0], [400.0, 1500.0]),
        ];
        let r = room(
            [4000.0, 5000.0],
            boxes,
            vec![door(Wall::YMin, 2000.0, 900.0)],
        );
        let routes = Routes::new(&r, &chair(), &[0.0, FRAC_PI_2]).unwrap();
        // Facing +x the chair fits in the pocket with its hip at x 1765 to
        // 1900 mm.
        let inside = routes.cut_off(0.0);
        assert!(inside.contains(&Point::new(1850.0, 2750.0)), "the pocket");
        assert!(!reaches(&routes, 0.0, 1850.0, 2750.0));
        assert!(
            reaches(&routes, FRAC_PI_2, 3500.0, 2750.0),
            "beside the island"
        );
    }

    #[test]
    fn a_chair_that_cannot_turn_in_a_galley_keeps_facing_in() {
        // A 900 mm galley, 5 m long, its door at one end: the chair comes
        // in facing down it and has nowhere to turn.
        let runs = |x0: f64| {
            vec![
                block("run_a", [x0, 0.0], [5000.0 - x0, 600.0]),
                block("run_b", [x0, 1500.0], [5000.0 - x0, 600.0]),
            ]
        };
        let galley = room(
            [5000.0, 2100.0],
            runs(0.0),
            vec![door(Wall::XMin, 1050.0, 900.0)],
        );
        let routes = Routes::new(&galley, &chair(), &[0.0, PI]).unwrap();
        assert!(
            reaches(&routes, 0.0, 4000.0, 1050.0),
            "facing in, down the galley"
        );
        assert!(
            !reaches(&routes, PI, 4000.0, 1050.0),
            "turned round in the galley"
        );
        assert!(routes.cut_off(PI).contains(&Point::new(4000.0, 1050.0)));
        // With a hall to turn in before it, it can back in.
        let with_hall = room(
            [5000.0, 2100.0],
            runs(2000.0),
            vec![door(Wall::XMin, 1050.0, 900.0)],
        );
        let routes = Routes::new(&with_hall, &chair(), &[0.0, PI]).unwrap();
        assert!(
            reaches(&routes, PI, 1000.0, 1050.0),
            "turned round in the hall"
        );
        assert!(
            reaches(&routes, PI, 4000.0, 1050.0),
            "backed into the galley"
        );
    }

    #[test]
    fn a_door_narrower_than_the_chair_lets_it_in_nowhere() {
        let r = room(
            [4000.0, 4000.0],
            Vec::new(),
            vec![door(Wall::YMin, 2000.0, 640.0)],
        );
        let routes = Routes::new(&r, &chair(), &[0.0]).unwrap();
        assert!(!routes.enters());
        assert_eq!(routes.doors[0].comes_in, Entry::TooNarrow);
        assert!((routes.doors[0].needs_mm - 660.0).abs() < 1e-6);
        assert!(routes.reached(0.0).0.is_empty());
        let blocked = room(
            [4000.0, 4000.0],
            vec![block("crate", [1500.0, 200.0], [1000.0, 500.0])],
            vec![door(Wall::YMin, 2000.0, 900.0)],
        );
        let routes = Routes::new(&blocked, &chair(), &[0.0]).unwrap();
        assert_eq!(routes.doors[0].comes_in, Entry::Blocked);
    }

    #[test]
    fn a_room_without_doors_has_no_routes() {
        assert!(Routes::new(
            &room([4000.0, 4000.0], Vec::new(), Vec::new()),
            &chair(),
            &[0.0]
        )
        .is_none());
    }
}
