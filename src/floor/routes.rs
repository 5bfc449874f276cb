//! Where a base that moves can get to from a room's doors: connectivity in
//! its configuration space. A base that turns with its footprint (a
//! wheelchair) moves in x, y and heading: at each of a set of headings
//! (every 22.5 degrees, the base's own and each door's inward one) the
//! floor where it fits falls into pieces it can drive about in; it can
//! turn from one heading to the next only where the floor holds what its
//! footprint sweeps while turning in place (`Footprint::swept`), which
//! joins a piece at one heading to a piece at the next. A base that does
//! not turn (a circle) moves in x and y: the pieces of its one region.
//!
//! It comes from outside: beyond each door a passage as wide as the door
//! runs straight out from the wall, long enough to hold the base (the rest
//! of the outside is solid), so a chair can be in the doorway while it
//! turns into the room, between the door's jambs, and can come in
//! forwards or backwards. The pieces joined to one that reaches the far
//! end of a passage are where it can get to; a place elsewhere in the room
//! is cut off.
//!
//! Each heading's floor is worked out a tile at a time (`layer.rs`), so
//! that the cost grows with the room's size, not faster: a piece of one
//! tile is joined to the pieces of the tiles beside it that it runs on
//! into.

use std::collections::hash_map::DefaultHasher;
use std::f64::consts::TAU;
use std::hash::Hasher;
use std::sync::Arc;

use geo::{ConvexHull, Distance, Euclidean, InteriorPoint, Intersects, LineString, MultiPoint};
use geo::{Coord, Point, Polygon, Rect};
use nalgebra::{Point3, Vector3};

use super::layer::{overlap, Layer, Tiling};
use super::obstacles::{box_outline, FloorObstacles};
use super::region::{shrunk, shrunk_room, Turned};
use super::work::{unbounded, CutShort, Work};
use super::Footprint;
use crate::kept::{Memo, Table};
use crate::scene::{hash_bits, BoxObstacle, Door, MeshObstacle, Room, Wall};

/// The headings a turning base is followed at, besides its own and the
/// doors': every 22.5 degrees.
const HEADINGS: usize = 16;
/// Turned boxes whose sides are this close in direction are followed at
/// one heading (about a degree).
const TURNED_MAX_APART_RAD: f64 = 0.02;
/// At most this many directions of turned boxes are followed (each adds
/// four headings).
const TURNED_MOST: usize = 4;
/// Headings closer than this are one.
const SAME_HEADING_RAD: f64 = 1e-9;
/// How much wider the base is followed than it is: a way must be wider
/// than the base by more than this.
pub(super) const HAIR_MM: f64 = 0.01;
/// Room to spare at the far end of a door's passage, beyond what holds
/// the base.
const SPARE_MM: f64 = 100.0;
/// Two pieces of floor overlap where they share more than this area (a
/// shared edge or corner, left by rounding, is none).
const OVERLAP_AREA_MM2: f64 = 1.0;

/// Whether two pieces of floor share more than a hair's area
/// ([`OVERLAP_AREA_MM2`]).
pub(super) fn pieces_overlap(a: &Polygon<f64>, b: &Polygon<f64>) -> bool {
    use geo::{Area, BooleanOps, BoundingRect};
    let (Some(ra), Some(rb)) = (a.bounding_rect(), b.bounding_rect()) else {
        return false;
    };
    overlap(ra, rb).is_some() && a.intersection(b).unsigned_area() > OVERLAP_AREA_MM2
}

/// How wide a base of `footprint` is across `door`'s opening, facing in.
pub fn needs_mm(footprint: &Footprint, door: &Door) -> f64 {
    let turned = Turned::new(footprint, door.inward_heading_rad());
    let along = |c: &Coord<f64>| match door.wall {
        Wall::XMin | Wall::XMax => c.y,
        _ => c.x,
    };
    let (lo, hi) = (turned.parts.iter().flatten())
        .map(along)
        .fold((f64::INFINITY, f64::NEG_INFINITY), |(a, b), v| {
            (a.min(v), b.max(v))
        });
    hi - lo
}

/// Where a base can get to in one room.
pub struct Routes {
    grid: Tiling,
    /// The headings followed, ascending in [0, 2 pi), each with the
    /// extended floor's admissible region tile by tile.
    layers: Vec<Layer>,
    /// Whether each piece (numbered across the layers) can be got to.
    reached: Vec<bool>,
    /// Each piece's set of joined pieces (a piece's number in it).
    sets: Vec<usize>,
    /// How the base comes in, door by door.
    pub doors: Vec<Doorway>,
    /// What working them out cost, in units of the meter
    /// ([`crate::meter`]): every run that uses them is charged it.
    pub work: u64,
}

/// Whether a base comes in through a door.
#[derive(Clone, Debug, PartialEq)]
pub struct Doorway {
    pub name: String,
    pub width_mm: f64,
    /// How wide the base is across the opening, facing in.
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
    /// It comes in and has room inside.
    Through,
    /// It cannot stand in the doorway's passage: the opening is narrower
    /// than the base at every heading.
    TooNarrow,
    /// It gets into the doorway, but something just inside stops it.
    Blocked,
}

/// Routes kept for a run or a watch session, by a hash of the room's
/// floor, the footprint and the headings.
const KEPT: Table<Option<Arc<Routes>>> = Table::new("routes", 16);

impl Routes {
    /// Where a base of `footprint` can get to in `room` from its doors,
    /// followed at the base's `headings` too; none if the room has no
    /// door (then it may be placed wherever it fits). Kept in `memo`: the
    /// same room, footprint and headings give the same routes. Cut
    /// short once their work would pass what `within` allows (what a run
    /// has left of its work; not kept then).
    pub fn of(
        room: &Room,
        footprint: &Footprint,
        headings: &[f64],
        within: &(dyn Fn(u64) -> bool + Sync),
        memo: &Memo,
    ) -> Result<Option<Arc<Routes>>, CutShort> {
        if room.doors.is_empty() {
            return Ok(None);
        }
        let mut h = DefaultHasher::new();
        footprint.hash_with_floor(room, &mut h);
        hash_bits(headings, &mut h);
        KEPT.get_or_try(memo, h.finish(), || {
            Routes::within(room, footprint, headings, within).map(|r| r.map(Arc::new))
        })
    }

    /// Like `of`, worked out afresh, whatever it costs.
    pub fn new(room: &Room, footprint: &Footprint, headings: &[f64]) -> Option<Routes> {
        Routes::within(room, footprint, headings, &unbounded)
            .unwrap_or_else(|_| unreachable!("nothing cuts short routes allowed any work"))
    }

    /// Like `new`, cut short once their work would pass what `within`
    /// allows.
    fn within(
        room: &Room,
        footprint: &Footprint,
        headings: &[f64],
        within: &(dyn Fn(u64) -> bool + Sync),
    ) -> Result<Option<Routes>, CutShort> {
        if room.doors.is_empty() {
            return Ok(None);
        }
        let given = footprint;
        // A way exactly as wide as the base is no way: followed with the
        // base a hair wider, it is closed wherever the tiles cut it (the
        // boolean operations of one tile may keep a channel of no width
        // open that those of another close).
        let footprint = &given.grown(HAIR_MM);
        let mut work = Work::new(within);
        let allows = |units: u64| work.allows(units);
        let space =
            Space::new(room, footprint, &allows).map_err(|cut| work.cut_short_with(cut.work))?;
        work.add(space.obstacles.work())?;
        let grid = Tiling::over(space.floor);
        let followed = followed_headings(footprint, headings, room);
        let mut layers: Vec<Layer> = Vec::with_capacity(followed.len());
        for &h in &followed {
            let first = layers.last().map_or(0, Layer::end);
            let layer = space.layer(&grid, footprint, h, first);
            work.add(layer.work)?;
            layers.push(layer);
        }
        let mut joined = Joined::new(layers.last().map_or(0, Layer::end));
        for layer in &layers {
            for (a, b) in layer.seams(&grid) {
                joined.union(a, b);
            }
        }
        if footprint.turns() {
            join_turns(&space, &grid, footprint, &layers, &mut joined, &mut work)?;
        }
        let ends: Vec<Vec<usize>> = (0..room.doors.len())
            .map(|d| door_ends(&layers, space.outside[d]))
            .collect();
        ends.iter().flatten().for_each(|&n| joined.start(n));
        let count = layers.last().map_or(0, Layer::end);
        let sets: Vec<usize> = (0..count).map(|n| joined.root(n)).collect();
        let reached = (0..count).map(|n| joined.reached(n)).collect();
        let mut routes = Routes {
            grid,
            layers,
            reached,
            sets,
            doors: Vec::new(),
            work: work.done,
        };
        routes.doors = (room.doors.iter().zip(&ends))
            .map(|(door, ends)| routes.doorway(room, door, given, ends))
            .collect();
        Ok(Some(routes))
    }

    /// Whether the base comes in through any door.
    pub fn enters(&self) -> bool {
        self.doors.iter().any(|d| d.comes_in == Entry::Through)
    }

    /// Whether the base, its hip at `(x, y)` and facing `heading_rad` (one
    /// of the headings given to `new`), is where it can get to from a
    /// door; none where it does not fit.
    pub fn reached_at(&self, heading_rad: f64, x: f64, y: f64) -> Option<bool> {
        let layer = self.layer(heading_rad)?;
        let n = layer.piece_at(&self.grid, Point::new(x, y))?;
        Some(self.reached[n])
    }

    /// Whether the base gets anywhere at `heading_rad`.
    pub fn reaches_any(&self, heading_rad: f64) -> bool {
        self.layer(heading_rad)
            .is_some_and(|l| l.pieces().any(|(n, _)| self.reached[n]))
    }

    /// The room's obstacles (boxes, then meshes, by index) that close in
    /// the floor a base of `footprint` (the routes' own) at `heading_rad`
    /// (one of the headings followed) with its hip at
    /// `hip_mm` cannot get to from a door: those within the footprint's
    /// reach of that floor's edge that come within the heights of its
    /// parts (a wall cabinet over the floor closes nothing in), nearest
    /// first.
    pub fn enclosing(
        &self,
        room: &Room,
        footprint: &Footprint,
        heading_rad: f64,
        hip_mm: (f64, f64),
    ) -> Vec<usize> {
        let hip = Point::new(hip_mm.0, hip_mm.1);
        let Some(piece) = self.cut_off_near(heading_rad, hip) else {
            return Vec::new();
        };
        let reach_mm = footprint.extent_mm() + SPARE_MM;
        let bands = footprint.bands_mm();
        let mut near: Vec<(f64, usize)> = room
            .boxes
            .iter()
            .enumerate()
            .filter(|(_, b)| bands.iter().any(|&band| b.meets_band(band)))
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
        // Nearest first by the millimetre, then in the room's order: two
        // obstacles that both bound the floor are both at about nothing,
        // and the rounding of the floor's edge must not order them.
        near.sort_by(|a, b| a.0.round().total_cmp(&b.0.round()).then(a.1.cmp(&b.1)));
        near.into_iter().map(|(_, i)| i).collect()
    }

    /// The floor at `heading_rad` the base cannot get to nearest `hip`, in
    /// one piece: the tiles' pieces of its set joined, the part nearest
    /// `hip`.
    fn cut_off_near(&self, heading_rad: f64, hip: Point<f64>) -> Option<Polygon<f64>> {
        let layer = self.layer(heading_rad)?;
        let distance = |p: &Polygon<f64>| Euclidean.distance(p, &hip);
        let (nearest, _) = (layer.pieces())
            .filter(|(n, _)| !self.reached[*n])
            .min_by(|a, b| distance(a.1).total_cmp(&distance(b.1)))?;
        let set = self.sets[nearest];
        let parts: Vec<Polygon<f64>> = (layer.pieces())
            .filter(|(n, _)| self.sets[*n] == set)
            .map(|(_, p)| p.clone())
            .collect();
        let whole = geo::unary_union(&parts);
        whole
            .0
            .into_iter()
            .min_by(|a, b| distance(a).total_cmp(&distance(b)))
    }

    /// Whether a piece of the floor at `heading_rad` (one of the headings
    /// followed) that the base can get to overlaps `piece` (by more than
    /// a hair's area); none where that heading is not followed.
    pub fn reaches_into(&self, heading_rad: f64, piece: &Polygon<f64>) -> Option<bool> {
        let layer = self.layer(heading_rad)?;
        Some((layer.pieces()).any(|(n, q)| self.reached[n] && pieces_overlap(q, piece)))
    }

    /// Whether `heading_rad` is one of the headings followed.
    pub fn follows(&self, heading_rad: f64) -> bool {
        self.layer(heading_rad).is_some()
    }

    fn layer(&self, heading_rad: f64) -> Option<&Layer> {
        let h = normalized(heading_rad);
        self.layers
            .iter()
            .find(|l| (l.heading_rad - h).abs() <= SAME_HEADING_RAD)
    }

    /// How a base fares at `door`: through if a piece its passage's far
    /// end reaches (`ends`) is joined to floor in the room; blocked if it
    /// only gets into the doorway; too narrow if it cannot stand in the
    /// passage at all.
    fn doorway(&self, room: &Room, door: &Door, footprint: &Footprint, ends: &[usize]) -> Doorway {
        let sets: Vec<usize> = ends.iter().map(|&n| self.sets[n]).collect();
        // Whether a piece joined to this door's ends lies in the room.
        let inside = self.layers.iter().any(|layer| {
            let turned = Turned::new(footprint, layer.heading_rad);
            shrunk_room(room, &turned, None)
                .is_some_and(|r| layer.any_overlapping(r, |n| sets.contains(&self.sets[n])))
        });
        Doorway {
            name: door.name.clone(),
            width_mm: door.width_mm,
            needs_mm: needs_mm(footprint, door),
            comes_in: if ends.is_empty() {
                Entry::TooNarrow
            } else if inside {
                Entry::Through
            } else {
                Entry::Blocked
            },
        }
    }
}

/// The pieces, of every layer, that reach the far end of a door's
/// passage (`end`).
fn door_ends(layers: &[Layer], end: Rect<f64>) -> Vec<usize> {
    (layers.iter())
        .flat_map(|layer| layer.pieces())
        .filter(|(_, p)| p.intersects(&end))
        .map(|(n, _)| n)
        .collect()
}

/// The floor a route search follows: the room grown on every side by a
/// band that is solid (the walls) but for a passage straight out from
/// each door, as wide as its opening and long enough to hold the base.
struct Space {
    floor: Rect<f64>,
    obstacles: FloorObstacles,
    /// For each door, the far end of its passage: where a base's hip point
    /// is when all of it is outside the room.
    outside: Vec<Rect<f64>>,
}

impl Space {
    /// Cut short where its obstacles would cost more than `allows` allows.
    fn new(
        room: &Room,
        footprint: &Footprint,
        allows: &dyn Fn(u64) -> bool,
    ) -> Result<Self, CutShort> {
        let reach = footprint.extent_mm();
        let depth = 2.0 * reach + SPARE_MM;
        let (sx, sy) = (room.size_mm.x, room.size_mm.y);
        let floor = Rect::new(
            Coord {
                x: -depth,
                y: -depth,
            },
            Coord {
                x: sx + depth,
                y: sy + depth,
            },
        );
        let walls = walls_round(room, depth);
        let outside = room
            .doors
            .iter()
            .map(|d| {
                let [lo, hi] = d.span_mm();
                let (near, far) = (reach + SPARE_MM / 2.0, depth);
                let (x0, x1, y0, y1) = match d.wall {
                    Wall::XMin => (-far, -near, lo, hi),
                    Wall::XMax => (sx + near, sx + far, lo, hi),
                    Wall::YMin => (lo, hi, -far, -near),
                    _ => (lo, hi, sy + near, sy + far),
                };
                Rect::new(Coord { x: x0, y: y0 }, Coord { x: x1, y: y1 })
            })
            .collect();
        Ok(Space {
            floor,
            obstacles: FloorObstacles::with(room, footprint, &walls, allows)?,
            outside,
        })
    }

    /// Where `footprint` fits on this floor at `heading_rad`, tile by
    /// tile on `grid`, its pieces numbered from `first`.
    fn layer(&self, grid: &Tiling, footprint: &Footprint, heading_rad: f64, first: usize) -> Layer {
        let turned = Turned::new(footprint, heading_rad);
        let within = shrunk(self.floor, &turned, None);
        Layer::new(grid, within, &turned, heading_rad, &self.obstacles, first)
    }
}

/// The walls round `room`: a band `depth` wide outside each of its sides,
/// but for a passage out of each door, as boxes as high as the room.
fn walls_round(room: &Room, depth: f64) -> Vec<BoxObstacle> {
    let (sx, sy, sz) = (room.size_mm.x, room.size_mm.y, room.size_mm.z);
    // Each side: its wall, the band's extent along it, and the rectangle
    // of a stretch [a, b] along it.
    type Stretch = fn(f64, f64, f64, f64, f64) -> ([f64; 2], [f64; 2]);
    let sides: [(Wall, f64, f64, Stretch); 4] = [
        (Wall::YMin, -depth, sx + depth, |a, b, d, _, _| {
            ([a, -d], [b - a, d])
        }),
        (Wall::YMax, -depth, sx + depth, |a, b, d, _, sy| {
            ([a, sy], [b - a, d])
        }),
        (Wall::XMin, 0.0, sy, |a, b, d, _, _| ([-d, a], [d, b - a])),
        (Wall::XMax, 0.0, sy, |a, b, d, sx, _| ([sx, a], [d, b - a])),
    ];
    let mut walls = Vec::new();
    for (wall, from, to, stretch) in sides {
        let mut openings: Vec<[f64; 2]> = room
            .doors
            .iter()
            .filter(|d| d.wall == wall)
            .map(Door::span_mm)
            .collect();
        openings.sort_by(|a, b| a[0].total_cmp(&b[0]));
        let mut at = from;
        for [lo, hi] in openings.into_iter().chain([[to, to]]) {
            if lo > at {
                let (corner, size) = stretch(at, lo, depth, sx, sy);
                walls.push(BoxObstacle {
                    name: "the wall".into(),
                    corner_mm: Point3::new(corner[0], corner[1], 0.0),
                    size_mm: Vector3::new(size[0], size[1], sz),
                    yaw_rad: 0.0,
                });
            }
            at = at.max(hi);
        }
    }
    walls
}

/// The headings followed: one for a base that does not turn; else every
/// [`HEADINGS`]th of a turn, the base's own, each door's inward one, and
/// the sides of the room's turned boxes (a counter set at 30 degrees makes
/// a way at 30 degrees), ascending in [0, 2 pi).
fn followed_headings(footprint: &Footprint, headings: &[f64], room: &Room) -> Vec<f64> {
    if !footprint.turns() {
        return vec![0.0];
    }
    let quarter = TAU / 4.0;
    let mut yaws: Vec<f64> = (room.boxes.iter())
        .map(|b| b.yaw_rad.rem_euclid(quarter))
        .filter(|y| *y > SAME_HEADING_RAD && quarter - *y > SAME_HEADING_RAD)
        .collect();
    yaws.sort_by(f64::total_cmp);
    yaws.dedup_by(|a, b| (*a - *b).abs() <= TURNED_MAX_APART_RAD);
    yaws.truncate(TURNED_MOST);
    let turned = yaws
        .into_iter()
        .flat_map(|y| (0..4).map(move |k| y + f64::from(k) * quarter));
    let mut all: Vec<f64> = (0..HEADINGS)
        .map(|k| k as f64 * TAU / HEADINGS as f64)
        .chain(headings.iter().copied())
        .chain(room.doors.iter().map(Door::inward_heading_rad))
        .chain(turned)
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
/// turn between them: the pieces of the floor where it fits what it
/// sweeps turning from the one to the other.
fn join_turns(
    space: &Space,
    grid: &Tiling,
    footprint: &Footprint,
    layers: &[Layer],
    joined: &mut Joined,
    work: &mut Work<'_>,
) -> Result<(), CutShort> {
    let n = layers.len();
    for h in 0..n {
        let next = (h + 1) % n;
        let (from, to) = (layers[h].heading_rad, layers[next].heading_rad);
        let angle = if n == 1 {
            TAU
        } else {
            (to - from).rem_euclid(TAU)
        };
        let turning = space.layer(grid, &footprint.swept(angle), from, 0);
        work.add(turning.work)?;
        for (_, poly) in turning.pieces() {
            let Some(p) = poly.interior_point() else {
                continue;
            };
            let a = layers[h].piece_at(grid, p);
            let b = layers[next].piece_at(grid, p);
            if let (Some(a), Some(b)) = (a, b) {
                joined.union(a, b);
            }
        }
    }
    Ok(())
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

/// Which pieces are joined (a union-find over every layer's pieces), and
/// which are come in to.
struct Joined {
    parent: Vec<usize>,
    started: Vec<bool>,
}

impl Joined {
    fn new(count: usize) -> Self {
        Joined {
            parent: (0..count).collect(),
            started: vec![false; count],
        }
    }

    fn root(&mut self, mut i: usize) -> usize {
        while self.parent[i] != i {
            self.parent[i] = self.parent[self.parent[i]];
            i = self.parent[i];
        }
        i
    }

    fn union(&mut self, a: usize, b: usize) {
        let (ra, rb) = (self.root(a), self.root(b));
        let (keep, gone) = (ra.min(rb), ra.max(rb));
        self.parent[gone] = keep;
        self.started[keep] |= self.started[gone];
    }

    fn start(&mut self, n: usize) {
        let r = self.root(n);
        self.started[r] = true;
    }

    fn reached(&mut self, n: usize) -> bool {
        let r = self.root(n);
        self.started[r]
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::scene::BoxObstacle;
    use nalgebra::{Point3, Vector2, Vector3};
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
        routes.reached_at(heading, x, y) == Some(true)
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

    /// `divided`, its wall at `y` and its gap's centre at `x`.
    fn divided_at(gap: f64, x: f64, y: f64) -> Room {
        let left = x - gap / 2.0;
        room(
            [4000.0, 6000.0],
            vec![
                block("left", [0.0, y - 100.0], [left, 200.0]),
                block(
                    "right",
                    [left + gap, y - 100.0],
                    [4000.0 - left - gap, 200.0],
                ),
            ],
            vec![door(Wall::YMin, 2000.0, 900.0)],
        )
    }

    #[test]
    fn a_narrow_way_is_followed_wherever_the_tiles_cut_it() {
        // The floor is worked out in 2 m tiles: a gap 1 mm wider than the
        // chair opens the way, and 1 mm narrower or exactly as wide closes
        // it, wherever the tiles' edges cross the gap.
        let headings = [FRAC_PI_2];
        for k in 0..12 {
            let x = 700.0 + 230.0 * f64::from(k);
            let y = 2500.0 + 330.0 * f64::from(k % 5);
            let far = (2000.0, 5200.0);
            let wide = Routes::new(&divided_at(661.0, x, y), &chair(), &headings).unwrap();
            assert!(
                reaches(&wide, FRAC_PI_2, far.0, far.1),
                "661 mm at ({x}, {y})"
            );
            let narrow = Routes::new(&divided_at(659.0, x, y), &chair(), &headings).unwrap();
            assert!(
                !reaches(&narrow, FRAC_PI_2, far.0, far.1),
                "659 mm at ({x}, {y})"
            );
            // Exactly as wide as the chair: no way, whatever the rounding.
            let exact = Routes::new(&divided_at(660.0, x, y), &chair(), &headings).unwrap();
            assert!(
                !reaches(&exact, FRAC_PI_2, far.0, far.1),
                "660 mm at ({x}, {y})"
            );
        }
    }

    /// A room cut across by a wall set at 30 degrees, with a channel
    /// `width` wide through it along 120 degrees (between the 112.5 and
    /// 135 degrees every chair is followed at).
    fn slanted(width: f64) -> Room {
        let yaw = PI / 6.0;
        let n = Vector2::new(yaw.cos(), yaw.sin());
        let u = Vector2::new(-yaw.sin(), yaw.cos());
        let centre = Vector2::new(2000.0, 3000.0);
        let (big, long) = (5000.0, 1500.0);
        let turned = |name: &str, corner: Vector2<f64>| BoxObstacle {
            name: name.into(),
            corner_mm: Point3::new(corner.x, corner.y, 0.0),
            size_mm: Vector3::new(big, long, 900.0),
            yaw_rad: yaw,
        };
        room(
            [4000.0, 6000.0],
            vec![
                turned("right", centre + n * (width / 2.0) - u * (long / 2.0)),
                turned("left", centre - n * (width / 2.0 + big) - u * (long / 2.0)),
            ],
            vec![door(Wall::YMin, 2000.0, 900.0)],
        )
    }

    #[test]
    fn a_way_between_turned_boxes_is_followed_at_their_heading() {
        // 700 mm: the 660 mm chair fits along the channel, and 7.5 degrees
        // off it needs 793 mm.
        let routes = Routes::new(&slanted(700.0), &chair(), &[FRAC_PI_2]).unwrap();
        assert!(reaches(&routes, FRAC_PI_2, 2000.0, 1000.0), "the near side");
        assert!(reaches(&routes, FRAC_PI_2, 2000.0, 5200.0), "through");
        let closed = Routes::new(&slanted(650.0), &chair(), &[FRAC_PI_2]).unwrap();
        assert!(!reaches(&closed, FRAC_PI_2, 2000.0, 5200.0), "too narrow");
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
        assert_eq!(
            routes.reached_at(0.0, 1850.0, 2750.0),
            Some(false),
            "the pocket"
        );
        assert!(!reaches(&routes, 0.0, 1850.0, 2750.0));
        assert!(
            reaches(&routes, FRAC_PI_2, 3500.0, 2750.0),
            "beside the island"
        );
    }

    #[test]
    fn a_chair_turns_only_where_it_has_room() {
        // A 900 mm corridor from a door in the wall x = 0 along x to a
        // corner, then along y: at the corner the chair must turn a
        // quarter. With `corner` of floor there, it can only if `corner`
        // holds its sweep.
        let l_corridor = |corner: f64| {
            let boxes = vec![
                // Below the first leg, and the block inside the bend.
                block("below", [0.0, 0.0], [5000.0, 1000.0]),
                block("inside", [0.0, 1900.0], [5000.0 - corner, 4100.0]),
                // Beyond the far leg's outer side.
                block(
                    "outside",
                    [5000.0 - corner + 900.0, 1000.0 + corner],
                    [corner - 900.0, 5000.0 - corner],
                ),
            ];
            room(
                [5000.0, 6000.0],
                boxes,
                vec![door(Wall::XMin, 1450.0, 900.0)],
            )
        };
        let far = (5000.0 - 450.0, 5200.0);
        let tight = Routes::new(&l_corridor(900.0), &chair(), &[0.0, FRAC_PI_2]).unwrap();
        assert!(tight.enters());
        assert!(reaches(&tight, 0.0, 2000.0, 1450.0), "along the first leg");
        assert!(
            !reaches(&tight, FRAC_PI_2, far.0, far.1),
            "round a 900 mm corner"
        );
        let roomy = Routes::new(&l_corridor(1700.0), &chair(), &[0.0, FRAC_PI_2]).unwrap();
        assert!(
            reaches(&roomy, FRAC_PI_2, 5000.0 - 1700.0 + 450.0, 5200.0),
            "round a 1700 mm corner"
        );
    }

    #[test]
    fn a_chair_comes_into_a_galley_forwards_or_backwards_but_never_sideways() {
        // A 900 mm galley, 5 m long, its door at one end: the chair cannot
        // turn in it, so it faces down it or back up it (reversed in).
        let galley = room(
            [5000.0, 2100.0],
            vec![
                block("run_a", [0.0, 0.0], [5000.0, 600.0]),
                block("run_b", [0.0, 1500.0], [5000.0, 600.0]),
            ],
            vec![door(Wall::XMin, 1050.0, 900.0)],
        );
        let routes = Routes::new(&galley, &chair(), &[0.0, PI, FRAC_PI_2]).unwrap();
        assert!(
            reaches(&routes, 0.0, 4000.0, 1050.0),
            "forwards, down the galley"
        );
        assert!(reaches(&routes, PI, 4000.0, 1050.0), "backed in");
        assert!(!routes.reaches_any(FRAC_PI_2), "sideways: it does not fit");
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
        assert!(!routes.reaches_any(0.0));
        let blocked = room(
            [4000.0, 4000.0],
            vec![block("crate", [1000.0, 0.0], [2000.0, 400.0])],
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
