//! The admissible region at one heading, worked out a tile at a time as it
//! is asked about: a placement asks only about the floor within an arm's
//! length of its target, so a large room costs what the floor near its
//! targets costs. Each tile (a square of the shrunk room, about a metre)
//! is `admissible_in` over the tile widened by a millimetre, so that a
//! point on a tile's edge is inside its own tile's piece; the pieces,
//! together, are the region `admissible` gives whole.

use std::cell::RefCell;
use std::collections::HashSet;
use std::sync::atomic::AtomicU64;
use std::sync::atomic::Ordering::Relaxed;
use std::sync::{Arc, OnceLock};

use geo::{Closest, ClosestPoint, Coord, MultiPolygon, Point, Rect};
use rayon::prelude::*;

use super::layer::overlap;
use super::obstacles::FloorObstacles;
use super::region::{admissible_in, obstacles_meeting, shrunk_room, Grown, Turned, Zone};
use super::shared_routes::Around;
use super::work::{unbounded, CutShort, Looked, Work};
use super::{DoorRoutes, Footprint, Inside};
use crate::allowance::Allowance;
use crate::kept::Memo;
use crate::once::get_or_compute;
use crate::scene::Room;

/// The side of a tile, for rooms up to `MAX_TILES` of them.
const TILE_MM: f64 = 1000.0;
const MAX_TILES: f64 = 4096.0;
/// How far each tile's piece reaches beyond the tile.
const OVERLAP_MM: f64 = 1.0;
/// Which pieces of floor, and which shapes grown for them, a search is
/// charged in full for: those not worked out for it before.
struct Fresh<'a> {
    piece: &'a dyn Fn(u64) -> bool,
    shape: &'a dyn Fn(u64) -> bool,
}

/// A tile's piece of the region, what working it out costs and the key
/// it is kept by (`region::Piece`).
struct Tile {
    inside: Inside,
    work: u64,
    key: u64,
    /// What looking at the tile costs where its piece was worked out
    /// before (finding its key, `region::Piece`, and its corners, a unit
    /// each, for the nearest point in it).
    again: u64,
    /// The shapes working its piece out grows, and what each costs
    /// (`region::Piece`).
    shapes: Looked,
    /// What finding which of its pieces the routes from the doors reach
    /// cost beyond the floor's (`DoorRoutes::piece_reached`), and the key
    /// a search is charged it by, once, whether or not the piece was
    /// paid for.
    reaching: (u64, u64),
    /// What the member's tighter groups' bounds and its own routes cost,
    /// where a piece here asked them (0 where none did): each charged
    /// once to a search, by [`TIGHTER_ROUTES`] and [`OWN_ROUTES`],
    /// however many tiles asked them.
    asked: Asked,
}

/// What a tile's pieces asked beyond the widest bounds: the member's
/// share of its tighter groups' bounds, and its own routes' work (each
/// the same for every piece of one member that asks it, or 0).
#[derive(Clone, Copy, Debug, Default)]
struct Asked {
    tighter: u64,
    own: u64,
}

/// The key a search is charged a member's own routes by
/// (`Tile::asked`): a search is one member's.
const OWN_ROUTES: u64 = 0x6f77_6e5f_726f_7574;

/// The key a search is charged a member's share of its tighter groups'
/// bounds by (`Tile::asked`).
const TIGHTER_ROUTES: u64 = 0x7469_6768_7465_7272;

/// Whether a region is empty, and what finding out cost (every tile its
/// search looked at, and those tiles' pieces).
#[derive(Clone, Debug, PartialEq, Eq)]
struct Emptiness {
    empty: bool,
    work: u64,
    looked: Looked,
}

/// The admissible region at one heading.
pub struct Region {
    turned: Turned,
    /// Each obstacle shape's grown outline at this heading.
    grown: Grown,
    obstacles: Arc<FloorObstacles>,
    /// The shrunk room (and zone), none if the footprint fits in neither.
    free: Option<Rect<f64>>,
    /// The zone, where it has an outline that cuts each tile's piece.
    zone: Option<Zone>,
    tile_mm: f64,
    nx: usize,
    ny: usize,
    tiles: Vec<OnceLock<Tile>>,
    empty: OnceLock<Emptiness>,
    /// The routes from the room's doors and the heading they are followed
    /// at, where only what they reach is kept.
    routes: Option<(Arc<DoorRoutes>, f64)>,
    /// Pieces paid for by the search of a room with more in it (this one
    /// is that with obstacles or doors taken away).
    paid: Looked,
    /// Where the tiles' pieces are kept for other regions and runs.
    memo: Arc<Memo>,
    /// The regions of the bounds of the group (a population) the
    /// footprint is one of, at the same heading, where it has them.
    bounds: Option<Bounds>,
}

/// The regions of a group's bounds (`group.rs`) at one heading: where the
/// outer's (which holds every member's footprint) has a point, so does
/// each member's; where the inner's (which every member's holds) has
/// none, no member's has. The outer's is cut to its routes where the
/// member's is cut to its own.
#[derive(Clone)]
pub struct Bounds {
    pub outer: Arc<Region>,
    pub inner: Arc<Region>,
}

/// Whether each of `regions` is empty, each found out in full, in
/// parallel, so that the work, added to `work`, is the same whatever
/// comes first. Cut short where that work would pass what `work` allows:
/// each region tells what it has counted as it goes, and checks the sum.
pub fn emptiness_each(regions: &[&Region], work: &mut Work<'_>) -> Result<Vec<bool>, CutShort> {
    let counted = AtomicU64::new(0);
    let outer: &Work<'_> = work;
    let found: Vec<Result<bool, CutShort>> = regions
        .par_iter()
        .map(|region| {
            // The most this region has told: its work asked about so far.
            let told = AtomicU64::new(0);
            let allowed = |own: u64| {
                let more = own.saturating_sub(told.fetch_max(own, Relaxed));
                let all = counted.fetch_add(more, Relaxed).saturating_add(more);
                outer.allows(all)
            };
            region.emptiness(&mut Work::new(&allowed))
        })
        .collect();
    let total = counted.into_inner();
    if found.iter().any(Result::is_err) {
        return Err(work.cut_short_with(total));
    }
    work.add(total)?;
    Ok(found.into_iter().map(|f| f.unwrap_or(false)).collect())
}

/// The pieces of `region` a base facing `heading_rad` can get to by
/// `routes` (a piece is reached whole or not at all), and the work of
/// finding out beyond the floor's: the windows' about its pieces, and the
/// member's tighter groups' bounds' and own routes' where any piece asked
/// them (`DoorRoutes::piece_reached`).
fn reached_pieces(
    region: MultiPolygon<f64>,
    routes: &DoorRoutes,
    heading_rad: f64,
    around: &Around<'_>,
) -> (MultiPolygon<f64>, u64, Asked) {
    let (mut windows, mut asked) = (0u64, Asked::default());
    let mut kept = Vec::with_capacity(region.0.len());
    for piece in region.0 {
        let decided = routes.piece_reached(heading_rad, &piece, around);
        windows = windows.saturating_add(decided.window_work);
        asked.tighter = asked.tighter.max(decided.tighter_work);
        asked.own = asked.own.max(decided.own_work);
        if decided.reached {
            kept.push(piece);
        }
    }
    (MultiPolygon::new(kept), windows, asked)
}

impl Region {
    pub fn new(
        room: &Room,
        footprint: &Footprint,
        heading_rad: f64,
        zone: Option<&Zone>,
        obstacles: Arc<FloorObstacles>,
        memo: &Arc<Memo>,
    ) -> Self {
        let turned = Turned::new(footprint, heading_rad);
        let free = shrunk_room(room, &turned, zone);
        let (w, h) = free.map_or((0.0, 0.0), |r| (r.width(), r.height()));
        let tile_mm = TILE_MM.max((w * h / MAX_TILES).sqrt());
        let zone = zone.filter(|z| z.outline.is_some()).cloned();
        let nx = (w / tile_mm).ceil().max(1.0) as usize;
        let ny = (h / tile_mm).ceil().max(1.0) as usize;
        Region {
            turned,
            grown: Grown::default(),
            obstacles,
            free,
            zone,
            tile_mm,
            nx,
            ny,
            tiles: (0..nx * ny).map(|_| OnceLock::new()).collect(),
            empty: OnceLock::new(),
            routes: None,
            paid: Looked::default(),
            memo: Arc::clone(memo),
            bounds: None,
        }
    }

    /// The region, told by `bounds` where they decide whether it holds a
    /// point (its own tile is then not worked out).
    pub fn bounded_by(self, bounds: Bounds) -> Self {
        Region {
            bounds: Some(bounds),
            ..self
        }
    }

    /// Whether `(x, y)` is inside the region, where its bounds tell.
    fn by_bounds(&self, x: f64, y: f64) -> Option<bool> {
        let bounds = self.bounds.as_ref()?;
        if bounds.outer.contains(x, y) {
            return Some(true);
        }
        (!bounds.inner.contains(x, y)).then_some(false)
    }

    /// The part of the region a base can get to from the room's doors
    /// (`routes`, followed at `heading_rad` among others): a tile's pieces
    /// the routes do not reach are left out of it.
    pub fn reached(
        room: &Room,
        footprint: &Footprint,
        heading_rad: f64,
        zone: Option<&Zone>,
        obstacles: Arc<FloorObstacles>,
        routes: Arc<DoorRoutes>,
        memo: &Arc<Memo>,
    ) -> Self {
        let region = Region::new(room, footprint, heading_rad, zone, obstacles, memo);
        let empty = OnceLock::new();
        if !routes.enters() {
            let _ = empty.set(Emptiness {
                empty: true,
                work: 0,
                looked: Looked::default(),
            });
        }
        Region {
            routes: Some((routes, heading_rad)),
            empty,
            ..region
        }
    }

    /// Tile `(i, j)`'s piece of the region, and its work.
    fn tile(&self, i: usize, j: usize) -> &Tile {
        get_or_compute(&self.tiles[j * self.nx + i], || {
            let piece = self
                .tile_rect(i, j)
                .map(|r| admissible_in(r, &self.turned, &self.obstacles, &self.grown, &self.memo));
            let (piece, work, key, finding, shapes) = match piece {
                Some(p) => (p.free, p.work, p.key, p.finding, p.shapes),
                None => (MultiPolygon::new(Vec::new()), 0, 0, 0, Looked::default()),
            };
            let piece = match &self.zone {
                Some(zone) => zone.cut(piece),
                None => piece,
            };
            // The floor of a footprint in a window about a piece, within
            // the shrunk room, facing the way the region does.
            let heading = self.routes.as_ref().map_or(0.0, |(_, h)| *h);
            let around = |window: Rect<f64>, footprint: &Footprint| {
                let within = overlap(window, self.free?)?;
                let turned = Turned::new(footprint, heading);
                let grown = Grown::default();
                let found = admissible_in(within, &turned, &self.obstacles, &grown, &self.memo);
                Some((found.free, found.work))
            };
            let (piece, windows, asked) = match &self.routes {
                Some((routes, heading_rad)) => reached_pieces(piece, routes, *heading_rad, &around),
                None => (piece, 0, Asked::default()),
            };
            let inside = Inside::new(piece);
            let corners = geo::CoordsIter::coords_count(inside.region()) as u64;
            let reaching_key = {
                use std::hash::{Hash, Hasher};
                let mut h = std::collections::hash_map::DefaultHasher::new();
                ("reaching", key, heading.to_bits(), i, j).hash(&mut h);
                h.finish()
            };
            Tile {
                inside,
                work,
                key,
                again: finding.saturating_add(corners),
                shapes,
                reaching: (reaching_key, windows),
                asked,
            }
        })
    }

    /// Tile `(i, j)` widened by `OVERLAP_MM`, within the shrunk room.
    fn tile_rect(&self, i: usize, j: usize) -> Option<Rect<f64>> {
        let free = self.free?;
        let t = self.tile_mm;
        let lo = Coord {
            x: (free.min().x + i as f64 * t - OVERLAP_MM).max(free.min().x),
            y: (free.min().y + j as f64 * t - OVERLAP_MM).max(free.min().y),
        };
        let hi = Coord {
            x: (free.min().x + (i + 1) as f64 * t + OVERLAP_MM).min(free.max().x),
            y: (free.min().y + (j + 1) as f64 * t + OVERLAP_MM).min(free.max().y),
        };
        (lo.x < hi.x && lo.y < hi.y).then(|| Rect::new(lo, hi))
    }

    /// The tile `(x, y)` lies in, if it is in the shrunk room.
    fn tile_of(&self, x: f64, y: f64) -> Option<(usize, usize)> {
        let free = self.free?;
        let fx = (x - free.min().x) / self.tile_mm;
        let fy = (y - free.min().y) / self.tile_mm;
        if !(fx >= 0.0 && fy >= 0.0 && x <= free.max().x && y <= free.max().y) {
            return None;
        }
        Some((
            (fx as usize).min(self.nx - 1),
            (fy as usize).min(self.ny - 1),
        ))
    }

    /// Whether `(x, y)` is inside the region, not on its boundary.
    pub fn contains(&self, x: f64, y: f64) -> bool {
        if let Some(known) = self.by_bounds(x, y) {
            return known;
        }
        self.tile_of(x, y)
            .is_some_and(|(i, j)| self.tile(i, j).inside.contains(x, y))
    }

    /// Like `contains`, for ruling points out quickly (a point on the
    /// boundary may go either way).
    pub fn roughly_contains(&self, x: f64, y: f64) -> bool {
        if let Some(known) = self.by_bounds(x, y) {
            return known;
        }
        self.tile_of(x, y)
            .is_some_and(|(i, j)| self.tile(i, j).inside.roughly_contains(x, y))
    }

    /// Whether the base fits nowhere at this heading (found out once).
    pub fn is_empty(&self) -> bool {
        let mut work = Work::new(&unbounded);
        self.emptiness(&mut work).unwrap_or(false)
    }

    /// Whether the base fits nowhere at this heading, where that is known
    /// (none before it is found out).
    pub fn known_empty(&self) -> Option<bool> {
        self.empty.get().map(|found| found.empty)
    }

    /// The region of a room that is another with obstacles or doors
    /// taken away, whose search at this heading looked at the pieces
    /// `paid` and found that the base `fits` there: then it fits here,
    /// unsearched; else the search here is charged for the pieces that
    /// one did not look at, and for looking again at those it did (and
    /// it fits unsearched if that was known already).
    pub fn beside(self, fits: bool, paid: Looked) -> Self {
        let empty = OnceLock::new();
        // A fit already known (from a group's bounds) stays known.
        if fits || self.known_empty() == Some(false) {
            let _ = empty.set(Emptiness {
                empty: false,
                work: 0,
                looked: Looked::default(),
            });
        }
        Region { empty, ..self }.paid_by(&paid)
    }

    /// The region, its pieces of `paid` (looked at by the search of the
    /// same floor before its pieces were cut to the routes from the doors:
    /// the same pieces, worked out once) charged for looking at again.
    pub fn paid_by(self, paid: &Looked) -> Self {
        Region {
            paid: self.paid.with(paid),
            ..self
        }
    }

    /// The pieces the search for whether the base fits anywhere here
    /// looked at (none before it was made).
    pub fn looked(&self) -> Looked {
        self.empty
            .get()
            .map_or_else(Looked::default, |found| found.looked.clone())
    }

    /// Whether the base fits nowhere at this heading, the work of finding
    /// out (every tile its search looked at, each at what working it out
    /// costs, whether or not it is worked out now) added to `work`: cut
    /// short where `work` would pass what it is allowed (then nothing is
    /// kept).
    pub fn emptiness(&self, work: &mut Work<'_>) -> Result<bool, CutShort> {
        let found = match self.empty.get() {
            Some(found) => (found.empty, found.work),
            None => {
                let allowed = |units: u64| work.allows(units);
                let mut own = Work::looking(&allowed);
                let fresh = |key: u64| !self.paid.contains(key);
                // Each shape is grown once at this heading.
                let grown = RefCell::new(HashSet::new());
                let grows = |shape: u64| grown.borrow_mut().insert(shape);
                let fresh = Fresh {
                    piece: &fresh,
                    shape: &grows,
                };
                let empty = (self.any_piece(&fresh, &mut own))
                    .map_err(|cut| work.cut_short_with(cut.work))?
                    .is_none();
                let found = Emptiness {
                    empty,
                    work: own.done,
                    looked: own.looked(),
                };
                let kept = self.empty.get_or_init(|| found);
                (kept.empty, kept.work)
            }
        };
        let (empty, units) = found;
        work.add(units)?;
        Ok(empty)
    }

    /// A tile whose piece is not empty, none if the region is: the tiles
    /// no obstacle meets first (whose piece is the whole tile, at no cost),
    /// then the rest, each group from the room's middle outwards, ring by
    /// ring, in rows, each charged as the nearest point's search charges
    /// it. So clutter costs nothing where some floor is clear of it, and
    /// elsewhere the tiles looked at are those the placements near the
    /// middle look at too (which tiles are looked at changes the work,
    /// never whether the region is empty).
    fn any_piece(
        &self,
        fresh: &Fresh<'_>,
        work: &mut Work<'_>,
    ) -> Result<Option<(usize, usize)>, CutShort> {
        let Some(free) = self.free else {
            return Ok(None);
        };
        let (ci, cj) = self
            .tile_of(free.center().x, free.center().y)
            .unwrap_or((0, 0));
        let mut order: Vec<(usize, usize, usize, usize)> = (0..self.ny)
            .flat_map(|j| (0..self.nx).map(move |i| (i, j)))
            .filter_map(|(i, j)| {
                let rect = self.tile_rect(i, j)?;
                let crowded = obstacles_meeting(rect, &self.turned, &self.obstacles) > 0;
                Some((
                    usize::from(crowded),
                    i.abs_diff(ci).max(j.abs_diff(cj)),
                    j,
                    i,
                ))
            })
            .collect();
        order.sort_unstable();
        let at_once = TILES_A_THREAD * rayon::current_num_threads().max(1);
        for (k, &(_, _, j, i)) in order.iter().enumerate() {
            if k % at_once == 0 {
                let next: Vec<(usize, usize)> = (order[k..order.len().min(k + at_once)].iter())
                    .map(|&(_, _, j, i)| (i, j))
                    .collect();
                self.work_out(&next);
            }
            let tile = self.tile(i, j);
            charge(tile, Some(fresh), work)?;
            // Not empty as the nearest point's search finds a piece not
            // empty: it has a point nearest the middle.
            let middle = Point::from(free.center());
            let nearest = (tile.inside.bounds_distance_mm(middle))
                .and_then(|near_mm| closest(tile.inside.region(), near_mm, middle));
            if nearest.is_some() {
                return Ok(Some((i, j)));
            }
        }
        Ok(None)
    }

    /// The admissible point nearest to `p` (itself if admissible), found
    /// tile by tile outwards from `p`'s, none if the region is empty.
    pub fn nearest(&self, p: Point<f64>) -> Option<Point<f64>> {
        let mut work = Work::new(&unbounded);
        self.nearest_counted(p, None, &mut work).unwrap_or(None)
    }

    /// Like `nearest`, `meter` charged every tile looked at (`nearest_counted`);
    /// none once the run is past its
    /// limit. A tile's piece is charged what working it out costs (and
    /// each shape it grows, the first time the task grows it) the first
    /// time the task looks at it, and only what looking again costs after
    /// that, or where the search for whether the base fits anywhere
    /// looked at it (and the floor paid for it).
    pub fn nearest_metered(&self, p: Point<f64>, allowance: &dyn Allowance) -> Option<Point<f64>> {
        let allowed = |units: u64| allowance.would_stay_within(units);
        let mut work = Work::new(&allowed);
        let searched = self.empty.get().map(|found| &found.looked);
        let fresh = |key: u64| {
            !self.paid.contains(key)
                && !searched.is_some_and(|s| s.contains(key))
                && allowance.first_look(key)
        };
        let grows = |shape: u64| allowance.first_look(shape);
        let fresh = Fresh {
            piece: &fresh,
            shape: &grows,
        };
        let found = self.nearest_counted(p, Some(&fresh), &mut work);
        match found {
            Ok(found) => {
                allowance.spend(work.done);
                found
            }
            Err(cut) => {
                allowance.spend(cut.work);
                None
            }
        }
    }

    /// `nearest`, `work` charged each tile looked at, those round `p`
    /// too (each task pays for them the first time it looks, though the
    /// process works each out once: left uncounted, 500 targets among
    /// 5,000 thin posts ran 14 s counted as 33 million units): where its
    /// piece is `fresh` (all are, if none is given), what working it out
    /// costs, and growing each shape it grows that is fresh too; what
    /// looking at it again costs otherwise.
    fn nearest_counted(
        &self,
        p: Point<f64>,
        fresh: Option<&Fresh<'_>>,
        work: &mut Work<'_>,
    ) -> Result<Option<Point<f64>>, CutShort> {
        let Some(free) = self.free else {
            return Ok(None);
        };
        let clamped = Point::new(
            p.x().clamp(free.min().x, free.max().x),
            p.y().clamp(free.min().y, free.max().y),
        );
        let Some((ci, cj)) = self.tile_of(clamped.x(), clamped.y()) else {
            return Ok(None);
        };
        let mut best: Option<(f64, Point<f64>)> = None;
        for ring in 0..self.nx.max(self.ny) {
            // Every tile's piece in this ring is at least this far from `p`.
            let bound = (ring.saturating_sub(1) as f64 * self.tile_mm - OVERLAP_MM).max(0.0);
            if best.is_some_and(|(d, _)| d <= bound) {
                break;
            }
            let tiles: Vec<(usize, usize)> = ring_tiles(ci, cj, ring, self.nx, self.ny).collect();
            // Worked out a few at once (four a thread: fewer left the
            // cores idle; 16 worked out too many past where the run's
            // limit cuts the search short), then charged and looked at in
            // turn as before: the same work, the same answer.
            let at_once = TILES_A_THREAD * rayon::current_num_threads().max(1);
            for (k, &(i, j)) in tiles.iter().enumerate() {
                if k % at_once == 0 {
                    self.work_out(&tiles[k..tiles.len().min(k + at_once)]);
                }
                let tile = self.tile(i, j);
                charge(tile, fresh, work)?;
                // A piece whose bounds are no nearer than the best cannot
                // be nearer (nor, by a tie, replace it).
                let Some(near_mm) = tile.inside.bounds_distance_mm(p) else {
                    continue;
                };
                if best.is_some_and(|(d, _)| near_mm >= d) {
                    continue;
                }
                let Some(q) = closest(tile.inside.region(), near_mm, p) else {
                    continue;
                };
                let d = (q.x() - p.x()).hypot(q.y() - p.y());
                if best.is_none_or(|(b, _)| d < b) {
                    best = Some((d, q));
                }
            }
        }
        Ok(best.map(|(_, q)| q))
    }

    /// Work out `tiles` (those not yet), in parallel: the search looks at
    /// each in turn, charging it as before, but need not wait for each.
    fn work_out(&self, tiles: &[(usize, usize)]) {
        use rayon::prelude::*;
        if tiles.len() > 1 {
            tiles.par_iter().for_each(|&(i, j)| _ = self.tile(i, j));
        }
    }

    /// The whole region, every tile worked out and the pieces (which
    /// overlap by `OVERLAP_MM`) united (for pictures and tests).
    pub fn whole(&self) -> MultiPolygon<f64> {
        let mut pieces = Vec::new();
        for j in 0..self.ny {
            for i in 0..self.nx {
                pieces.extend(self.tile(i, j).inside.region().0.iter().cloned());
            }
        }
        geo::unary_union(&pieces)
    }
}

/// Charge `work` for looking at `tile` (`fresh`: the pieces and shapes a
/// search is charged in full for; none: every tile in full).
fn charge(tile: &Tile, fresh: Option<&Fresh<'_>>, work: &mut Work<'_>) -> Result<(), CutShort> {
    let (reaching_key, reaching) = tile.reaching;
    let units = match fresh {
        Some(fresh) if !(fresh.piece)(tile.key) => tile.again,
        Some(fresh) => (tile.shapes.iter())
            .filter(|&(shape, _)| (fresh.shape)(shape))
            .fold(tile.work, |sum, (_, units)| sum.saturating_add(units)),
        None => tile.work,
    };
    let reaching = match fresh {
        Some(fresh) if reaching > 0 && !(fresh.shape)(reaching_key) => 0,
        _ => reaching,
    };
    // Each once to a search, whichever tile asked it first.
    let once = |units: u64, key: u64| match fresh {
        Some(fresh) if units > 0 && !(fresh.shape)(key) => 0,
        _ => units,
    };
    let asked =
        once(tile.asked.tighter, TIGHTER_ROUTES).saturating_add(once(tile.asked.own, OWN_ROUTES));
    let units = units.saturating_add(reaching).saturating_add(asked);
    work.add_piece(tile.key, units)
}

/// How many tiles of a ring, for each thread, a search works out at once
/// before it looks at them.
const TILES_A_THREAD: usize = 4;

/// The tiles `ring` steps (in the larger of x and y) from `(ci, cj)`, in
/// rows, within `nx` by `ny`.
fn ring_tiles(
    ci: usize,
    cj: usize,
    ring: usize,
    nx: usize,
    ny: usize,
) -> impl Iterator<Item = (usize, usize)> {
    let (ci, cj, r) = (ci as i64, cj as i64, ring as i64);
    (cj - r..=cj + r)
        .flat_map(move |j| (ci - r..=ci + r).map(move |i| (i, j)))
        .filter(move |&(i, j)| (i - ci).abs().max((j - cj).abs()) == r)
        .filter(move |&(i, j)| i >= 0 && j >= 0 && i < nx as i64 && j < ny as i64)
        .map(|(i, j)| (i as usize, j as usize))
}

/// The point of `region` nearest to `p`, none if it is empty; `near_mm`
/// is how far `p` is from its bounds (if not 0, `p` is outside it).
fn closest(region: &MultiPolygon<f64>, near_mm: f64, p: Point<f64>) -> Option<Point<f64>> {
    use geo::Contains;
    if region.0.is_empty() {
        return None;
    }
    if near_mm == 0.0 && region.contains(&p) {
        return Some(p);
    }
    match region.closest_point(&p) {
        Closest::Intersection(q) | Closest::SinglePoint(q) => Some(q),
        Closest::Indeterminate => region
            .0
            .first()
            .and_then(|poly| poly.exterior().0.first())
            .map(|c| Point::new(c.x, c.y)),
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The region of `chair` at `heading_rad` in `room`, its pieces kept
    /// in no memo.
    fn unkept(room: &Room, chair: &Footprint, heading_rad: f64, zone: Option<&Zone>) -> Region {
        let obstacles = Arc::new(FloorObstacles::new(room, chair));
        Region::new(
            room,
            chair,
            heading_rad,
            zone,
            obstacles,
            &Arc::new(Memo::forgetting()),
        )
    }
    use crate::floor::admissible;
    use crate::scene::BoxObstacle;
    use geo::{Area, BooleanOps};
    use nalgebra::{Point3, Vector3};

    /// A 5 x 4 m room with an island across a tile edge and a counter.
    fn room() -> Room {
        let block = |name: &str, corner: [f64; 3], size: [f64; 3]| BoxObstacle {
            name: name.into(),
            corner_mm: Point3::from(corner),
            size_mm: Vector3::from(size),
            yaw_rad: 0.3,
        };
        Room {
            name: "r".into(),
            size_mm: Vector3::new(5000.0, 4000.0, 2500.0),
            boxes: vec![
                block("island", [1800.0, 1500.0, 0.0], [1400.0, 700.0, 900.0]),
                block("counter", [0.0, 0.0, 0.0], [600.0, 4000.0, 900.0]),
            ],
            meshes: Vec::new(),
            targets: Vec::new(),
            surfaces: Vec::new(),
            doors: Vec::new(),
        }
    }

    /// A 6 x 6 m hall full of posts 300 mm apart but for a strip along
    /// one wall, where a chair of 600 mm fits.
    fn crowded() -> Room {
        let mut boxes = Vec::new();
        for i in 0..15 {
            for j in 0..19 {
                boxes.push(BoxObstacle {
                    name: format!("p{i}_{j}"),
                    corner_mm: Point3::new(300.0 * f64::from(i + 1), 300.0 * f64::from(j), 0.0),
                    size_mm: Vector3::new(50.0, 50.0, 900.0),
                    yaw_rad: 0.0,
                });
            }
        }
        Room {
            name: "hall".into(),
            size_mm: Vector3::new(6000.0, 6000.0, 2500.0),
            boxes,
            ..room()
        }
    }

    /// The crowded hall's region for a chair of 600 mm, facing along x.
    fn crowded_region() -> Region {
        let room = crowded();
        let chair = Footprint::circle(300.0, 900.0);
        unkept(&room, &chair, 0.0, None)
    }

    /// The same, with posts a metre apart against the wall of the strip,
    /// between which the chair still fits: no tile of floor is clear of
    /// every obstacle, so finding whether the chair fits costs work.
    fn crowded_to_the_wall_region() -> Region {
        let mut room = crowded();
        room.boxes.extend((0..6).map(|k| BoxObstacle {
            name: format!("w{k}"),
            corner_mm: Point3::new(5950.0, 1000.0 * f64::from(k), 0.0),
            size_mm: Vector3::new(50.0, 50.0, 900.0),
            yaw_rad: 0.0,
        }));
        let chair = Footprint::circle(300.0, 900.0);
        unkept(&room, &chair, 0.0, None)
    }

    /// Where some tile of floor is clear of every obstacle, finding
    /// whether a base fits costs nothing (the clear tile is looked at
    /// first); the nearest floor to the middle would have cost the
    /// crowded tiles round it.
    #[test]
    fn a_tile_clear_of_every_obstacle_answers_whether_a_base_fits_at_no_cost() {
        let region = crowded_region();
        let mut work = Work::new(&unbounded);
        assert_eq!(region.emptiness(&mut work), Ok(false));
        assert_eq!(work.done, 0);
        let mut nearest = Work::new(&unbounded);
        let middle = Point::new(3000.0, 3000.0);
        assert!(crowded_region()
            .nearest_counted(middle, None, &mut nearest)
            .is_ok());
        assert!(nearest.done > 10_000, "{}", nearest.done);
    }

    /// Finding out whether a base fits anywhere counts every tile the
    /// search looks at, and is cut short (nothing kept) where that work
    /// would pass what it is allowed; found out, it is charged the same
    /// again without being worked out again.
    #[test]
    fn emptiness_counts_the_tiles_it_looks_at_and_is_cut_short_past_its_allowance() {
        let region = crowded_to_the_wall_region();
        let mut whole = Work::new(&unbounded);
        assert_eq!(region.emptiness(&mut whole), Ok(false));
        assert!(whole.done > 10_000, "{}", whole.done);
        let short = |units: u64| units < whole.done;
        let fresh = crowded_to_the_wall_region();
        let mut before = Work::new(&short);
        before.add(7).expect("allowed");
        let cut = fresh.emptiness(&mut before).expect_err("cut short");
        assert!(!short(cut.work), "all the work counted: {}", cut.work);
        assert!(fresh.empty.get().is_none(), "nothing kept when cut short");
        let mut again = Work::new(&unbounded);
        assert_eq!(region.emptiness(&mut again), Ok(false));
        assert_eq!(again.done, whole.done);
    }

    /// A room that is another with obstacles taken away: where the base
    /// fits in that one, it fits here, unsearched and uncharged; where it
    /// fits nowhere there, the search here is charged in full only for the
    /// pieces that one did not look at, and for looking at the others.
    #[test]
    fn a_room_with_less_in_it_is_searched_only_where_the_wider_found_nothing() {
        let wider = crowded_to_the_wall_region();
        let mut whole = Work::new(&unbounded);
        assert_eq!(wider.emptiness(&mut whole), Ok(false));
        let fits = crowded_to_the_wall_region().beside(true, wider.looked());
        let mut none = Work::new(&unbounded);
        assert_eq!(fits.emptiness(&mut none), Ok(false));
        assert_eq!(none.done, 0);
        let searched = crowded_to_the_wall_region().beside(false, wider.looked());
        let mut looking = Work::new(&unbounded);
        assert_eq!(searched.emptiness(&mut looking), Ok(false));
        assert!(
            looking.done > 0 && looking.done * 4 < whole.done,
            "{} of {}",
            looking.done,
            whole.done
        );
    }

    /// A search for the nearest floor is charged the tiles it looks at
    /// beyond the target's own and those around it: nothing where the
    /// base fits beside the target, the tiles crossed where it fits only
    /// far off; once the run is past its limit, it finds nothing.
    #[test]
    fn a_search_for_far_floor_is_charged_and_a_near_one_is_not() {
        use crate::meter::{Meter, RunWork};
        let region = crowded_region();
        let run = RunWork::new(u64::MAX / 2);
        let allowance = Meter::of(&run);
        let near = region.nearest_metered(Point::new(5500.0, 3000.0), &allowance);
        assert_eq!(near, region.nearest(Point::new(5500.0, 3000.0)));
        assert_eq!(allowance.spent(), 0);
        let far = region.nearest_metered(Point::new(1000.0, 3000.0), &allowance);
        assert_eq!(far, region.nearest(Point::new(1000.0, 3000.0)));
        assert!(far.is_some_and(|p| p.x() > 4500.0), "{far:?}");
        assert!(allowance.spent() > 1_000, "{}", allowance.spent());
        let spent = allowance.spent();
        let tight = Meter::of(&RunWork::new(spent / 2));
        assert_eq!(
            region.nearest_metered(Point::new(1000.0, 3000.0), &tight),
            None
        );
        assert!(tight.exceeded());
    }

    /// An L-shaped outline zone: the region is the floor's admissible
    /// region within the L, whole or tile by tile; the corner the L leaves
    /// out of its bounding square is out, though a chair fits there.
    #[test]
    fn an_outline_zone_leaves_out_what_it_does_not_enclose() {
        use geo::{Contains, Coord, LineString, Polygon};
        let corners = [
            (1000.0, 300.0),
            (1700.0, 300.0),
            (1700.0, 700.0),
            (1300.0, 700.0),
            (1300.0, 1300.0),
            (1000.0, 1300.0),
        ];
        let ring: Vec<Coord<f64>> = corners.iter().map(|&(x, y)| Coord { x, y }).collect();
        let outline = Polygon::new(LineString::from(ring), Vec::new());
        let zone = Zone::outline(outline.clone()).unwrap();
        assert_eq!((zone.min, zone.max), ((1000.0, 300.0), (1700.0, 1300.0)));
        let room = room();
        let chair = Footprint::circle(300.0, 2000.0);
        let free = admissible(&room, &chair, 0.0, None);
        let zoned = admissible(&room, &chair, 0.0, Some(&zone));
        let tiled = unkept(&room, &chair, 0.0, Some(&zone));
        let notch = Point::new(1500.0, 1000.0);
        assert!(free.contains(&notch), "the notch is free floor");
        for x in (900..=1800).step_by(50) {
            for y in (200..=1400).step_by(50) {
                let p = Point::new(f64::from(x) + 0.5, f64::from(y) + 0.5);
                let inside = free.contains(&p) && outline.contains(&p);
                assert_eq!(zoned.contains(&p), inside, "{p:?}");
                assert_eq!(tiled.contains(p.x(), p.y()), inside, "{p:?}, tiled");
            }
        }
    }

    #[test]
    fn the_tiles_together_are_the_whole_region() {
        let room = room();
        let chair = Footprint::rectangle(600.0, 500.0, 660.0, 1400.0);
        let heading = 0.7;
        let whole = admissible(&room, &chair, heading, None);
        let tiled = unkept(&room, &chair, heading, None);
        let differ = whole.xor(&tiled.whole()).unsigned_area();
        assert!(differ < 1.0, "{differ} mm2");
    }

    #[test]
    fn the_nearest_point_is_the_whole_region_s() {
        use geo::Contains;
        let room = room();
        let chair = Footprint::rectangle(600.0, 500.0, 660.0, 1400.0);
        let whole = admissible(&room, &chair, 0.0, None);
        let tiled = unkept(&room, &chair, 0.0, None);
        for (x, y) in [
            (2500.0, 1850.0),
            (300.0, 2000.0),
            (4990.0, 10.0),
            (9000.0, -50.0),
        ] {
            let p = Point::new(x, y);
            let q = tiled.nearest(p).expect("the chair fits");
            let expected = closest(&whole, 0.0, p).expect("the chair fits");
            let (d, e) = (
                (q.x() - x).hypot(q.y() - y),
                (expected.x() - x).hypot(expected.y() - y),
            );
            assert!((d - e).abs() < 1e-6, "({x}, {y}): {d} against {e}");
            assert_eq!(whole.contains(&p), tiled.contains(x, y), "({x}, {y})");
        }
    }
}
