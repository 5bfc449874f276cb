//! Free floor as building standards measure it, for their rule checks: the
//! floor not under an obstacle that comes down below a height (an
//! obstacle higher than a knee leaves knee clearance under it), whether a
//! rectangle of floor is free (a clear floor space), where a circle or a
//! T of floor fits (a turning space), and how wide a way is from a door to
//! a place (the widest disc that travels from one to the other).
//!
//! Each region is worked out over the whole room and charged to the run's
//! meter as the bases' floor is (`region::Piece`'s work, kept or not);
//! once the run is past its limit, no more are worked out (each is then
//! empty, and the run gives no answer).

use geo::{
    BooleanOps, BoundingRect, Contains, Coord, Distance, Euclidean, InteriorPoint, Intersects,
    LineString, MultiPolygon, Point, Polygon, Rect,
};
use nalgebra::Vector2;
use std::collections::hash_map::DefaultHasher;
use std::hash::{Hash, Hasher};
use std::sync::Arc;

use super::obstacles::FloorObstacles;
use super::region::{admissible_in, shrunk_room, Grown, Turned};
use super::work::CutShort;
use super::{FloorPart, Footprint};
use crate::allowance::Allowance;
use crate::kept::{Memo, Table};
use crate::scene::{BoxObstacle, Door, Room, Wall};

/// Sides of the polygon inscribed in a circle: its flats are within a
/// quarter of a millimetre of a 1.5 m circle, and a centre it finds is
/// then checked against the true circle.
const DISC_SIDES: usize = 128;
/// How far in from the wall a way from a door starts.
const DOORWAY_MM: f64 = 20.0;

/// The floor free of obstacles that come down below `below_mm`, and the
/// meter its looks are charged to.
pub struct FreeFloor<'m> {
    region: Arc<MultiPolygon<f64>>,
    /// What one look ([`FreeFloor::holds`]) costs the meter.
    look_units: u64,
    allowance: &'m dyn Allowance,
}

/// Units of the meter a look at the free floor costs for each of its
/// corners (a polygon held or not is related to every edge of the region,
/// about 4 ns a corner: 1,000 elements in a hall of 50 counters, 600 looks
/// each, took 66 s unmetered).
const UNITS_PER_CORNER: u64 = 12;

impl<'m> FreeFloor<'m> {
    pub fn new(room: &Room, below_mm: f64, allowance: &'m dyn Allowance) -> Self {
        // A point (a square a micrometre across) as the footprint.
        let h = 0.0005;
        let point = Footprint {
            parts: vec![part(
                [(h, h), (-h, h), (-h, -h), (h, -h)]
                    .map(|(x, y)| Vector2::new(x, y))
                    .to_vec(),
                below_mm,
            )],
        };
        let region = whole(room, &point, 0.0, allowance);
        FreeFloor {
            look_units: look_units(&region),
            region,
            allowance,
        }
    }

    /// Whether all of `polygon` is free floor (charged to the meter; none
    /// is, once the run is past its limit).
    pub fn holds(&self, polygon: &Polygon<f64>) -> bool {
        self.allowance.spend(self.look_units) && holds_within(&self.region, polygon)
    }
}

/// Whether `region` contains `polygon`, each piece of it asked with only
/// the holes near `polygon`: the pieces are apart, so a connected polygon
/// lies within one of them, and a hole whose bounds miss the polygon's
/// cannot meet it. The same answer as asking the whole region, whose
/// test builds a tree of all its edges at every look (a 30 m room of
/// 4,990 slats: 0.13 s a look, 13 s for one element's clear floor space).
fn holds_within(region: &MultiPolygon<f64>, polygon: &Polygon<f64>) -> bool {
    let Some(bounds) = polygon.bounding_rect() else {
        return region.contains(polygon);
    };
    region.0.iter().any(|piece| {
        let outer = piece.exterior().bounding_rect();
        if !outer.is_some_and(|o| o.intersects(&bounds)) {
            return false;
        }
        let near = (piece.interiors().iter())
            .filter(|hole| hole.bounding_rect().is_some_and(|h| h.intersects(&bounds)))
            .cloned()
            .collect();
        Polygon::new(piece.exterior().clone(), near).contains(polygon)
    })
}

/// What one look at `region` (whether it holds or meets a polygon) costs
/// the meter: its corners.
fn look_units(region: &MultiPolygon<f64>) -> u64 {
    1 + geo::CoordsIter::coords_count(region) as u64 * UNITS_PER_CORNER
}

/// A footprint part of `outline` from the floor to `below_mm`.
fn part(outline_mm: Vec<Vector2<f64>>, below_mm: f64) -> FloorPart {
    FloorPart {
        outline_mm,
        z_mm: [0.0, below_mm],
    }
}

/// Where `footprint` fits in the whole room at `heading_rad`, its work
/// charged to `meter` (nowhere, worked out no more, once the run is past
/// its limit).
fn whole(
    room: &Room,
    footprint: &Footprint,
    heading_rad: f64,
    allowance: &dyn Allowance,
) -> Arc<MultiPolygon<f64>> {
    if allowance.exhausted() {
        return Arc::new(MultiPolygon::new(Vec::new()));
    }
    let mut h = DefaultHasher::new();
    footprint.hash_with_floor(room, &mut h);
    heading_rad.to_bits().hash(&mut h);
    let allows = |units: u64| allowance.would_stay_within(units);
    let memo = allowance.memo();
    let found = WHOLE.get_or_try(&memo, h.finish(), || {
        let (region, work) = worked_out(room, footprint, heading_rad, &allows, &memo)?;
        Ok::<_, CutShort>((Arc::new(region), work))
    });
    match found {
        Ok((region, work)) => {
            allowance.spend(work);
            region
        }
        // What it would have cost passes the limit: charged, the run stops.
        Err(cut) => {
            allowance.spend(cut.work);
            Arc::new(MultiPolygon::new(Vec::new()))
        }
    }
}

/// The regions [`whole`] worked out for a run or a watch session: watch
/// mode checks a standard's rules again at every save, and a route's
/// width is found by halving, each step a region (about 15 a clear floor
/// space); 512 holds those of a kitchen's elements several times.
const WHOLE: Table<(Arc<MultiPolygon<f64>>, u64)> = Table::new("free floor", 512);

/// Where `footprint`, turned to `heading_rad`, fits in `room`, worked out,
/// and what that cost; cut short where its obstacles would cost more than
/// `allows` allows.
fn worked_out(
    room: &Room,
    footprint: &Footprint,
    heading_rad: f64,
    allows: &dyn Fn(u64) -> bool,
    memo: &Memo,
) -> Result<(MultiPolygon<f64>, u64), CutShort> {
    let turned = Turned::new(footprint, heading_rad);
    Ok(match shrunk_room(room, &turned, None) {
        Some(within) => {
            let obstacles = FloorObstacles::with(room, footprint, &[], allows)?;
            let piece = admissible_in(within, &turned, &obstacles, &Grown::default(), memo);
            (piece.free, piece.work.saturating_add(obstacles.work()))
        }
        None => (MultiPolygon::new(Vec::new()), 0),
    })
}

/// A disc of `radius_mm` from the floor to `below_mm`, as the polygon
/// inscribed in it (so that where it fits holds every centre where the
/// disc does, and a little more).
fn disc(radius_mm: f64, below_mm: f64) -> Footprint {
    let outline = (0..DISC_SIDES)
        .map(|k| {
            let a = std::f64::consts::TAU * k as f64 / DISC_SIDES as f64;
            Vector2::new(radius_mm * a.cos(), radius_mm * a.sin())
        })
        .collect();
    Footprint {
        parts: vec![part(outline, below_mm)],
    }
}

/// A centre where a disc of `radius_mm` fits on the floor free of
/// obstacles below `below_mm` (and, given a route's floor, where that
/// floor meets it: a centre a route from a door can also be at), checked
/// against the true circle (the room's walls and each obstacle's outline
/// at least the radius away); none if there is none.
pub fn disc_centre(
    room: &Room,
    radius_mm: f64,
    below_mm: f64,
    on: Option<&RouteFloor>,
    allowance: &dyn Allowance,
) -> Option<Point<f64>> {
    let footprint = disc(radius_mm, below_mm);
    let region = on_route(whole(room, &footprint, 0.0, allowance), on);
    let allows = |units: u64| allowance.would_stay_within(units);
    // Cut short, what it would have cost passes the limit: charged, the
    // run stops.
    let obstacles = match FloorObstacles::with(room, &footprint, &[], &allows) {
        Ok(obstacles) => obstacles,
        Err(cut) => {
            allowance.spend(cut.work);
            return None;
        }
    };
    allowance.spend(obstacles.work());
    let clear = |c: Point<f64>| {
        let (x, y) = (c.x(), c.y());
        let walls = [x, y, room.size_mm.x - x, room.size_mm.y - y];
        let r = Coord {
            x: radius_mm,
            y: radius_mm,
        };
        let centre = Coord { x, y };
        walls.iter().all(|&d| d >= radius_mm)
            && obstacles.near(0, centre - r, centre + r).iter().all(|o| {
                let outline = Polygon::new(o.to_vec().into(), Vec::new());
                Euclidean.distance(&outline, &c) >= radius_mm && !outline.contains(&c)
            })
    };
    region
        .0
        .iter()
        .flat_map(|piece| {
            let middle = piece.bounding_rect().map(|r| Point::from(r.center()));
            piece.interior_point().into_iter().chain(middle)
        })
        .find(|&c| clear(c))
}

/// `region`'s parts a route's floor meets (all of it without one).
fn on_route(region: Arc<MultiPolygon<f64>>, on: Option<&RouteFloor>) -> Arc<MultiPolygon<f64>> {
    match on {
        Some(route) => Arc::new(region.intersection(&route.pieces)),
        None => region,
    }
}

/// Where a T-shaped turning space fits: within a square `square_mm` on a
/// side, its bar (`arm_mm` deep) across one side of the square and its
/// stem (`arm_mm` wide) from the bar's middle to the opposite side, on the
/// floor free of obstacles below `below_mm`: the square's centre and the
/// direction the stem points (0, 90, 180 or 270 degrees); none if it fits
/// nowhere.
pub fn t_space(
    room: &Room,
    square_mm: f64,
    arm_mm: f64,
    below_mm: f64,
    on: Option<&RouteFloor>,
    allowance: &dyn Allowance,
) -> Option<(Point<f64>, f64)> {
    let h = square_mm / 2.0;
    let a = arm_mm / 2.0;
    let rect = |x0: f64, x1: f64, y0: f64, y1: f64| {
        [(x1, y1), (x0, y1), (x0, y0), (x1, y0)]
            .map(|(x, y)| Vector2::new(x, y))
            .to_vec()
    };
    // About the square's centre, the stem pointing along +x.
    let t = Footprint {
        parts: vec![
            part(rect(-h, -h + arm_mm, -h, h), below_mm),
            part(rect(-h + arm_mm, h, -a, a), below_mm),
        ],
    };
    (0..4).find_map(|k| {
        let heading = f64::from(k) * std::f64::consts::FRAC_PI_2;
        let region = on_route(whole(room, &t, heading, allowance), on);
        let centre = region.0.iter().find_map(|p| p.interior_point())?;
        Some((centre, heading))
    })
}

/// How wide a way there is from `door` to `to` (a clear floor space) on
/// the floor free of obstacles below `below_mm`: the widest disc, rounded
/// to the millimetre, that can travel from just inside the door (its centre
/// within the opening's span) to overlap `to`, at most `most_mm`; 0 if not
/// even a 10 mm one can. The door's own width is not the way's: a
/// standard rules on doors apart.
pub fn route_width(
    room: &Room,
    door: &Door,
    to: &Polygon<f64>,
    below_mm: f64,
    most_mm: f64,
    allowance: &dyn Allowance,
) -> f64 {
    let Some(target) = to.bounding_rect() else {
        return 0.0;
    };
    let travels = |width_mm: f64| {
        let r = width_mm / 2.0;
        let Some(start) = doorway(room, door, r) else {
            return false;
        };
        let reach = Rect::new(
            target.min() - Coord { x: r, y: r },
            target.max() + Coord { x: r, y: r },
        );
        let region = whole(room, &disc(r, below_mm), 0.0, allowance);
        allowance.spend(look_units(&region))
            && (region.0.iter()).any(|piece| piece.intersects(&start) && piece.intersects(&reach))
    };
    let (mut lo, mut hi) = (10.0, most_mm);
    if !travels(lo) {
        return 0.0;
    }
    if travels(hi) {
        return hi;
    }
    while hi - lo > 0.05 {
        let mid = (lo + hi) / 2.0;
        if travels(mid) {
            lo = mid;
        } else {
            hi = mid;
        }
    }
    // The inscribed polygon lets a disc through a quarter of a millimetre
    // narrower than itself: to the millimetre, the way's width.
    lo.round()
}

/// Where a route `width_mm` wide from the room's doors gets to: the
/// pieces of the floor (free below `below_mm`) where a disc that wide can
/// be, joined to just inside a door; and the meter its looks are charged
/// to.
pub struct RouteFloor<'m> {
    radius_mm: f64,
    pieces: MultiPolygon<f64>,
    look_units: u64,
    allowance: &'m dyn Allowance,
}

impl<'m> RouteFloor<'m> {
    /// None for a room without doors.
    pub fn new(
        room: &Room,
        width_mm: f64,
        below_mm: f64,
        allowance: &'m dyn Allowance,
    ) -> Option<Self> {
        if room.doors.is_empty() {
            return None;
        }
        let r = width_mm / 2.0;
        let starts: Vec<Rect<f64>> = (room.doors.iter())
            .filter_map(|d| doorway(room, d, r))
            .collect();
        let region = whole(room, &disc(r, below_mm), 0.0, allowance);
        allowance.spend(look_units(&region) * starts.len() as u64);
        let pieces = MultiPolygon::new(
            (region.0.iter())
                .filter(|piece| starts.iter().any(|s| piece.intersects(s)))
                .cloned()
                .collect(),
        );
        Some(RouteFloor {
            radius_mm: r,
            look_units: look_units(&pieces),
            pieces,
            allowance,
        })
    }

    /// Whether the route's disc gets to overlap `to` (a clear floor
    /// space), as `route_width` asks (charged to the meter; never, once
    /// the run is past its limit).
    pub fn reaches(&self, to: &Polygon<f64>) -> bool {
        let Some(target) = to.bounding_rect() else {
            return false;
        };
        if !self.allowance.spend(self.look_units) {
            return false;
        }
        let r = Coord {
            x: self.radius_mm,
            y: self.radius_mm,
        };
        let reach = Rect::new(target.min() - r, target.max() + r);
        self.pieces.0.iter().any(|piece| piece.intersects(&reach))
    }
}

/// The room with the floor deeper than `deepest_mm` under each raised
/// obstacle (one from `below_mm` up) taken: knee and toe clearance counts
/// as floor only so deep under an element (ADA 306.2.2, 306.3.2), from
/// each of its edges. Each such core is a box from the floor, named as
/// the obstacle it is under.
pub fn knee_limited(room: &Room, below_mm: f64, deepest_mm: f64) -> Room {
    let mut limited = room.clone();
    let cores = (room.boxes.iter())
        .filter(|b| b.corner_mm.z >= below_mm)
        .filter(|b| b.size_mm.x > 2.0 * deepest_mm && b.size_mm.y > 2.0 * deepest_mm)
        .map(|b| {
            let inset = b.rotation() * Vector2::new(deepest_mm, deepest_mm);
            let mut core = b.clone();
            core.corner_mm.x += inset.x;
            core.corner_mm.y += inset.y;
            core.corner_mm.z = 0.0;
            core.size_mm.x -= 2.0 * deepest_mm;
            core.size_mm.y -= 2.0 * deepest_mm;
            core.size_mm.z = b.corner_mm.z + b.size_mm.z;
            core
        })
        .collect::<Vec<BoxObstacle>>();
    limited.boxes.extend(cores);
    limited
}

/// A door's clear width: the widest stretch of its opening that nothing
/// below `below_mm` stands in, within `depth_mm` inside the room.
pub fn door_clear_width(room: &Room, door: &Door, depth_mm: f64, below_mm: f64) -> f64 {
    let [lo, hi] = door.span_mm();
    let (sx, sy) = (room.size_mm.x, room.size_mm.y);
    let strip = match door.wall {
        Wall::XMin => Rect::new(Coord { x: 0.0, y: lo }, Coord { x: depth_mm, y: hi }),
        Wall::XMax => Rect::new(
            Coord {
                x: sx - depth_mm,
                y: lo,
            },
            Coord { x: sx, y: hi },
        ),
        Wall::YMin => Rect::new(Coord { x: lo, y: 0.0 }, Coord { x: hi, y: depth_mm }),
        _ => Rect::new(
            Coord {
                x: lo,
                y: sy - depth_mm,
            },
            Coord { x: hi, y: sy },
        ),
    };
    let along = |c: Coord<f64>| match door.wall {
        Wall::XMin | Wall::XMax => c.y,
        _ => c.x,
    };
    let strip = MultiPolygon::new(vec![strip.to_polygon()]);
    let mut taken: Vec<(f64, f64)> = (room.boxes.iter())
        .filter(|b| b.corner_mm.z < below_mm)
        .filter_map(|b| {
            let outline = Polygon::new(
                LineString::from(super::obstacles::box_outline(b)),
                Vec::new(),
            );
            let inside = strip.intersection(&MultiPolygon::new(vec![outline]));
            let rect = inside.bounding_rect()?;
            Some((along(rect.min()), along(rect.max())))
        })
        .collect();
    taken.sort_by(|a, b| a.0.total_cmp(&b.0));
    let (mut widest, mut at) = (0.0_f64, lo);
    for (from, to) in taken {
        widest = widest.max(from - at);
        at = at.max(to);
    }
    widest.max(hi - at)
}

/// Where the centre of a disc of radius `r` can be just inside `door`:
/// within the opening's span along the wall, the disc wholly in the room.
fn doorway(room: &Room, door: &Door, r: f64) -> Option<Rect<f64>> {
    let [from, to] = door.span_mm();
    let (depth0, depth1) = (r, r + DOORWAY_MM);
    let (x0, x1, y0, y1) = match door.wall {
        Wall::XMin => (depth0, depth1, from, to),
        Wall::XMax => (room.size_mm.x - depth1, room.size_mm.x - depth0, from, to),
        Wall::YMin => (from, to, depth0, depth1),
        _ => (from, to, room.size_mm.y - depth1, room.size_mm.y - depth0),
    };
    Some(Rect::new(Coord { x: x0, y: y0 }, Coord { x: x1, y: y1 }))
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::allowance::Unbounded;
    use crate::scene::BoxObstacle;
    use geo::LineString;
    use nalgebra::{Point3, Vector3};

    fn square(x: f64, y: f64, side: f64) -> Polygon<f64> {
        Rect::new(
            Coord { x, y },
            Coord {
                x: x + side,
                y: y + side,
            },
        )
        .to_polygon()
    }

    proptest::proptest! {
        /// Asking each piece with only the holes near the polygon answers
        /// as asking the whole region (fails with the holes' bounds
        /// shrunk: a hole just touching the polygon is then left out).
        #[test]
        fn a_region_holds_a_polygon_as_its_nearby_holes_say(
            posts in proptest::collection::vec((0.0..2900.0f64, 0.0..2900.0f64, 5.0..300.0f64), 1..40),
            split in 0.0..3000.0f64,
            rects in proptest::collection::vec((0.0..2800.0f64, 0.0..2800.0f64, 10.0..600.0f64), 1..20),
        ) {
            let floor = MultiPolygon::new(vec![square(0.0, 0.0, 3000.0)]);
            let wall = Rect::new(Coord { x: split, y: -1.0 }, Coord { x: split + 20.0, y: 3001.0 });
            let mut region = floor.difference(&MultiPolygon::new(vec![wall.to_polygon()]));
            for (x, y, side) in posts {
                region = region.difference(&MultiPolygon::new(vec![square(x, y, side)]));
            }
            for (x, y, side) in rects {
                let r = square(x, y, side);
                proptest::prop_assert_eq!(holds_within(&region, &r), region.contains(&r));
            }
        }
    }

    fn block(name: &str, corner: [f64; 3], size: [f64; 3]) -> BoxObstacle {
        BoxObstacle {
            name: name.into(),
            corner_mm: Point3::from(corner),
            size_mm: Vector3::from(size),
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

    #[test]
    fn a_1525_mm_circle_needs_1525_mm_of_floor() {
        // A corridor between two counters, `gap` wide.
        let corridor = |gap: f64| {
            room(
                [5000.0, 4000.0],
                vec![
                    block("a", [0.0, 0.0, 0.0], [5000.0, 1000.0, 900.0]),
                    block("b", [0.0, 1000.0 + gap, 0.0], [5000.0, 3000.0 - gap, 900.0]),
                ],
                Vec::new(),
            )
        };
        assert!(disc_centre(&corridor(1526.0), 762.5, 685.0, None, &Unbounded).is_some());
        assert!(disc_centre(&corridor(1524.0), 762.5, 685.0, None, &Unbounded).is_none());
        // A counter with knee space under it (from 700 mm) leaves the floor.
        let mut raised = corridor(1000.0);
        raised.boxes[1].corner_mm.z = 700.0;
        assert!(disc_centre(&raised, 762.5, 685.0, None, &Unbounded).is_some());
    }

    #[test]
    fn a_t_fits_where_its_arms_do() {
        // A T in a 1525 mm square with 915 mm arms fits where a square
        // does; a 915 mm corridor crossing a 1525 mm one makes a T too.
        let open = room([1525.5, 1525.5], Vec::new(), Vec::new());
        assert!(t_space(&open, 1525.0, 915.0, 685.0, None, &Unbounded).is_some());
        // Fill the square's corners beside the stem: still a T.
        let corners = room(
            [1525.5, 1525.5],
            vec![
                block("c1", [915.5, 0.0, 0.0], [610.0, 305.0, 900.0]),
                block("c2", [915.5, 1220.5, 0.0], [610.0, 305.0, 900.0]),
            ],
            Vec::new(),
        );
        assert!(t_space(&corners, 1525.0, 915.0, 685.0, None, &Unbounded).is_some());
        // Narrow the stem below 915 mm: no T.
        let narrow = room(
            [1525.5, 1525.5],
            vec![
                block("c1", [915.5, 0.0, 0.0], [610.0, 306.0, 900.0]),
                block("c2", [915.5, 1219.5, 0.0], [610.0, 306.0, 900.0]),
            ],
            Vec::new(),
        );
        let found = t_space(&narrow, 1525.0, 915.0, 685.0, None, &Unbounded);
        assert!(found.is_none(), "{found:?}");
    }

    #[test]
    fn a_route_is_as_wide_as_its_narrowest_passage() {
        // From a door in the wall y = 0 to the far end of the room, past
        // two counters that leave `gap` between them.
        let r = room(
            [4000.0, 6000.0],
            vec![
                block("left", [0.0, 2900.0, 0.0], [1600.0, 200.0, 900.0]),
                block("right", [2400.0, 2900.0, 0.0], [1600.0, 200.0, 900.0]),
            ],
            vec![Door {
                name: "d".into(),
                wall: Wall::YMin,
                along_mm: 2000.0,
                width_mm: 1000.0,
            }],
        );
        let far = Polygon::new(
            LineString::from(vec![
                (1500.0, 5000.0),
                (2500.0, 5000.0),
                (2500.0, 5500.0),
                (1500.0, 5500.0),
            ]),
            Vec::new(),
        );
        let width = route_width(&r, &r.doors[0], &far, 2030.0, 3000.0, &Unbounded);
        assert!((width - 800.0).abs() <= 2.0, "{width}");
        // Wider than the door: the door is ruled on apart.
        let mut wide = r.clone();
        wide.boxes[1].corner_mm.x = 3400.0;
        let width = route_width(&wide, &wide.doors[0], &far, 2030.0, 3000.0, &Unbounded);
        assert!((width - 1800.0).abs() <= 2.0, "{width}");
        let free = FreeFloor::new(&r, 685.0, &Unbounded);
        assert!(free.holds(&far));
        let on_counter = Polygon::new(
            LineString::from(vec![
                (100.0, 2950.0),
                (500.0, 2950.0),
                (500.0, 3500.0),
                (100.0, 3500.0),
            ]),
            Vec::new(),
        );
        assert!(!free.holds(&on_counter));
    }
}
