//! The admissible region within a rectangle of floor: every hip point
//! where a base's footprint, at a given heading, lies inside the room and
//! where none of its parts overlaps an obstacle at the heights they share.
//! It is the rectangle minus, for each part, the outlines it meets near
//! the rectangle (`obstacles.rs`) grown by the reflected part (their
//! Minkowski sum: for convex outlines, the convex hull of the pairwise
//! differences of corners), each cut to the rectangle first; where many
//! outlines meet one rectangle, each obstacle's grown by the parts that
//! meet it are joined first, once per shape (`Grown`).

use std::collections::hash_map::DefaultHasher;
use std::collections::HashMap;
use std::hash::{Hash, Hasher};
use std::sync::{Arc, Mutex};

use geo::{BooleanOps, Coord, LineString, MultiPolygon, Polygon, Rect};

use super::obstacles::{bounds, FloorObstacles};
use super::work::Looked;
use super::Footprint;
use crate::kept::{Memo, Table};
use crate::scene::hash_bits;
use crate::scene::Room;

/// The floor a user restricts the base's hip point to (an approach zone):
/// a rectangle, or an outline (a polygon of floor points) and the
/// rectangle that bounds it.
#[derive(Clone, Debug, PartialEq)]
pub struct Zone {
    pub min: (f64, f64),
    pub max: (f64, f64),
    /// The outline, where the zone is not the whole rectangle.
    pub outline: Option<Arc<Polygon<f64>>>,
}

impl Zone {
    /// The rectangle from `min` to `max`.
    pub fn rectangle(min: (f64, f64), max: (f64, f64)) -> Self {
        Zone {
            min,
            max,
            outline: None,
        }
    }

    /// Whether the zone lies wholly outside a room of floor `x_mm` by
    /// `y_mm` (touching its walls at most): no hip point can be in both.
    pub fn outside(&self, (x_mm, y_mm): (f64, f64)) -> bool {
        self.max.0 <= 0.0 || self.max.1 <= 0.0 || self.min.0 >= x_mm || self.min.1 >= y_mm
    }

    /// The polygon `outline` (of at least three corners), in its bounds.
    pub fn outline(outline: Polygon<f64>) -> Option<Self> {
        use geo::BoundingRect;
        let bounds = outline.bounding_rect()?;
        Some(Zone {
            min: (bounds.min().x, bounds.min().y),
            max: (bounds.max().x, bounds.max().y),
            outline: Some(Arc::new(outline)),
        })
    }

    /// `region` (hip points) cut to the outline, if the zone has one (the
    /// rectangle is applied where the region is made).
    pub fn cut(&self, region: MultiPolygon<f64>) -> MultiPolygon<f64> {
        match &self.outline {
            Some(outline) if !region.0.is_empty() => {
                region.intersection(&MultiPolygon::new(vec![(**outline).clone()]))
            }
            _ => region,
        }
    }
}

/// A footprint turned to one heading: each part's corners about the hip
/// point, and the farthest any reaches along x and y.
pub struct Turned {
    pub parts: Vec<Vec<Coord<f64>>>,
    reach: Vec<(Coord<f64>, Coord<f64>)>,
    /// Each part's corners hashed bit for bit.
    hashes: Vec<u64>,
}

impl Turned {
    pub fn new(footprint: &Footprint, heading_rad: f64) -> Self {
        let parts: Vec<Vec<Coord<f64>>> = (0..footprint.parts.len())
            .map(|k| footprint.corners(k, heading_rad))
            .collect();
        let reach = parts.iter().map(|p| bounds(p)).collect();
        let hashes = (parts.iter())
            .map(|corners| {
                let mut h = DefaultHasher::new();
                hash_corners(corners, &mut h);
                h.finish()
            })
            .collect();
        Turned {
            parts,
            reach,
            hashes,
        }
    }
}

/// The hip points within `within` where `turned` fits among `obstacles`
/// (`within` already inside the room shrunk by the footprint), each
/// obstacle's outlines grown by the parts that meet it joined once per
/// shape (`grown` keeps them for `turned`). The same rectangle, footprint
/// and obstacles near give the same piece: kept in `memo` (a room with one
/// box moved or taken away, to learn why a reach failed or at a save in
/// watch mode, works out again only the pieces near it).
pub fn admissible_in(
    within: Rect<f64>,
    turned: &Turned,
    obstacles: &FloorObstacles,
    grown: &Grown,
    memo: &Memo,
) -> Piece {
    let met = obstacles_met(cut_of(within), turned, obstacles);
    if met.is_empty() {
        return Piece {
            free: MultiPolygon::new(vec![within.to_polygon()]),
            work: 0,
            key: 0,
            finding: 0,
            shapes: Looked::default(),
        };
    }
    let mut h = DefaultHasher::new();
    hash_corners(&[within.min(), within.max()], &mut h);
    // Only the parts that meet an obstacle here count: people whose
    // footprints differ only in parts that meet none (a population's
    // legs, far from a counter) share the piece.
    for m in &met {
        m.outline.len().hash(&mut h);
        hash_corners(m.outline, &mut h);
        m.parts.len().hash(&mut h);
        m.parts.iter().for_each(|&k| turned.hashes[k].hash(&mut h));
    }
    let pairs: usize = met.iter().map(|m| m.parts.len()).sum();
    let joined_first = pairs > JOIN_FROM;
    let key = h.finish();
    let finding = (met.iter())
        .map(|m| (m.outline.len() * m.parts.len()) as u64)
        .sum::<u64>()
        .saturating_mul(UNITS_PER_MET_CORNER);
    let kept = PIECES.get_or(memo, key, || {
        Arc::new(if joined_first {
            free_of_met(within, &met, turned, grown)
        } else {
            free_of_parts(within, &met, turned)
        })
    });
    let (free, crossings) = kept.as_ref();
    Piece {
        free: free.clone(),
        // The crossings measure crowded outlines, the corners many that
        // touch without crossing (a scan's floor cells).
        work: floor_work(*crossings).max(route_tile_work(&met, turned)),
        key,
        finding,
        shapes: if joined_first {
            shapes_grown(&met, turned)
        } else {
            Looked::default()
        },
    }
}

/// The distinct shapes among `met` that working out a piece from them
/// grows (`Grown::outline`: each part's outline grown, then joined; once
/// for each shape at each heading, kept), each by its key
/// ([`Met::shape_key`]) and its parts at this heading, with what growing
/// it costs: its crossings, as if each part's grown outline met each
/// other's.
fn shapes_grown(met: &[Met<'_>], turned: &Turned) -> Looked {
    Looked::of(met.iter().map(|m| {
        let mut h = DefaultHasher::new();
        m.shape_key().hash(&mut h);
        m.parts.iter().for_each(|&k| turned.hashes[k].hash(&mut h));
        let corners: usize = (m.parts.iter())
            .map(|&k| m.outline.len() + turned.parts[k].len())
            .sum();
        (h.finish(), floor_work(corners * m.parts.len()))
    }))
}

/// Units of the meter finding what a piece depends on costs, for each
/// corner of an outline met times the parts that meet it (the outlines
/// near each part looked up and hashed), whether or not the piece is kept.
const UNITS_PER_MET_CORNER: u64 = 1;

/// A rectangle's piece of the admissible region (`admissible_in`).
pub struct Piece {
    /// Where the base fits within the rectangle.
    pub free: MultiPolygon<f64>,
    /// What working it out costs ([`floor_work`]), whether or not it was
    /// kept in the memo.
    pub work: u64,
    /// What it depends on, hashed: the same key, the same piece, kept
    /// once (0: it meets no obstacle, and costs nothing).
    pub key: u64,
    /// What finding the key cost ([`UNITS_PER_MET_CORNER`]): the piece
    /// kept, its cost.
    pub finding: u64,
    /// The shapes working it out grows, by key, and what growing each
    /// costs (`shapes_grown`): charged once for each region's search.
    pub shapes: Looked,
}

/// Up to this many outlines grown part by part, a piece is worked out
/// from them as they are; beyond, each obstacle's are joined first
/// (`free_of_met`). The two differ only in the rounding of the boolean
/// operations, but a placement on a region's edge may change with it, so
/// the floors of kitchens and the like keep the outlines as they always
/// were; where obstacles crowd (posts 400 mm apart: 53 s for a run, 9 s
/// joined) each obstacle's twelve outlines cross each other and their
/// neighbours', and joining them first is what keeps the floor in hand.
const JOIN_FROM: usize = UNION_LEAF;

/// `within` less the outlines of the obstacles `met`, each grown by each
/// part of `turned` that meets it on its own and cut to `within`.
fn free_of_parts(
    within: Rect<f64>,
    met: &[Met<'_>],
    turned: &Turned,
) -> (MultiPolygon<f64>, usize) {
    let cut = cut_of(within);
    let mut grown: Vec<Polygon<f64>> = (met.iter())
        .flat_map(|m| grown_part_by_part(m, turned, cut))
        .collect();
    sort_canonically(&mut grown);
    free_of(MultiPolygon::new(vec![within.to_polygon()]), grown)
}

/// `met`'s outline grown by each of its parts on its own, each cut to
/// `cut` (none where nothing of it is left).
fn grown_part_by_part<'a>(
    met: &'a Met<'_>,
    turned: &'a Turned,
    cut: Rect<f64>,
) -> impl Iterator<Item = Polygon<f64>> + 'a {
    (met.parts.iter()).filter_map(move |&k| {
        clipped(
            &minkowski_with_reflected(met.outline, &turned.parts[k]),
            &cut,
        )
    })
}

/// `corners`, bit for bit.
fn hash_corners(corners: &[Coord<f64>], h: &mut impl Hasher) {
    hash_bits(corners.iter().flat_map(|c| [&c.x, &c.y]), h);
}

/// `within` widened by a millimetre: grown outlines are cut to it, so
/// that none ends exactly on the edge of `within`.
fn cut_of(within: Rect<f64>) -> Rect<f64> {
    let margin = Coord { x: 1.0, y: 1.0 };
    Rect::new(within.min() - margin, within.max() + margin)
}

/// The grown outline of each obstacle shape at one heading, about the
/// obstacle's first corner: the union of its outlines grown by each part
/// it meets. Shared by the tiles of one heading, which threads may work
/// out at once.
#[derive(Default)]
pub struct Grown {
    shapes: Mutex<HashMap<Vec<i64>, Arc<MultiPolygon<f64>>>>,
}

/// An obstacle's outline and the footprint's parts that meet it.
struct Met<'a> {
    outline: &'a [Coord<f64>],
    parts: Vec<usize>,
}

impl Met<'_> {
    /// Its shape: the outline's corners about its first, to the
    /// nanometre (a turned box's corners about its first differ in their
    /// last bits from place to place), and the parts that meet it.
    fn shape_key(&self) -> Vec<i64> {
        let origin = self.outline[0];
        let nm = |v: f64| (v * 1e6).round() as i64;
        (self.outline.iter())
            .flat_map(|&c| [nm(c.x - origin.x), nm(c.y - origin.y)])
            .chain(self.parts.iter().map(|&k| k as i64))
            .collect()
    }
}

impl Grown {
    /// `met`'s outline grown by each of its parts (of `turned`), joined,
    /// where it stands.
    fn outline(&self, met: &Met<'_>, turned: &Turned) -> Vec<Polygon<f64>> {
        use geo::Translate;
        let origin = met.outline[0];
        let relative: Vec<Coord<f64>> = met.outline.iter().map(|&c| c - origin).collect();
        let key = met.shape_key();
        let lock = || self.shapes.lock().unwrap_or_else(|e| e.into_inner());
        let kept = lock().get(&key).cloned();
        let shape = kept.unwrap_or_else(|| {
            let each: Vec<Polygon<f64>> = (met.parts.iter())
                .map(|&k| minkowski_with_reflected(&relative, &turned.parts[k]))
                .collect();
            let shape = Arc::new(geo::unary_union(&each));
            lock().insert(key, Arc::clone(&shape));
            shape
        });
        (shape.0.iter())
            .map(|p| p.translate(origin.x, origin.y))
            .collect()
    }
}

/// Like `admissible_in`, worked out afresh (not kept in a memo):
/// what a route search asks of every tile of a large floor at many
/// headings. And its work, in the units of the meter
/// ([`route_tile_work`]), and the shapes it grows (`Piece::shapes`: the
/// tiles of a layer share them, and pay for each once).
pub fn admissible_joined(
    within: Rect<f64>,
    turned: &Turned,
    obstacles: &FloorObstacles,
    grown: &Grown,
) -> (MultiPolygon<f64>, u64, Looked) {
    let met = obstacles_met(cut_of(within), turned, obstacles);
    let (free, crossings) = free_of_met(within, &met, turned, grown);
    let shapes = shapes_grown(&met, turned);
    // The corners measure posts' tiles, the crossings crowded ones.
    let work = route_tile_work(&met, turned).max(floor_work(crossings));
    (free, work, shapes)
}

/// Units of the meter a corner of the outlines a tile of routes is worked
/// out from costs: an obstacle's corners and a part's, for each part that
/// meets it. Calibrated on routes from a door (2 cores, release, a
/// layer's tiles in parallel), whose time is the tiles' and the joining
/// of their pieces and of the headings' as much: at 3 units a corner they
/// do 27,000 to 32,000 units a millisecond (5,000 posts 400 mm apart; 300
/// posts followed at 360 headings; 300 wheelchair users in a kitchen), as
/// the solvers do 20,000 to 40,000. (A tile's crossings, which measure a
/// tile of placements better, undercount them: 300 posts at 360 headings
/// with a door ran 11 s within the bound so counted.)
const UNITS_PER_CORNER: u64 = 3;

/// The work of a tile of routes whose footprint parts meet the obstacles
/// `met`.
fn route_tile_work(met: &[Met<'_>], turned: &Turned) -> u64 {
    let corners: usize = (met.iter())
        .map(|m| (m.parts.iter()).map(|&k| m.outline.len() + turned.parts[k].len()))
        .map(Iterator::sum::<usize>)
        .sum();
    (corners as u64).saturating_mul(UNITS_PER_CORNER)
}

/// Units of the meter ([`crate::meter`]) two of a tile's crossings cost
/// (see `crossing_pairs`: each pair of outlines whose bounds overlap, by
/// the corners of the two). Measured tile by tile on one thread
/// (release): the crossings predict a tile's time within a factor of two,
/// 12 to 24 a microsecond, from posts 400 mm apart to 5,000 boxes of 3 mm
/// crowded round one target, where the outlines' corners alone went from
/// 2.3 to 17 a microsecond (the boolean operations meet every crossing of
/// edges, and crowded outlines cross pairwise). At three units for two,
/// the crowded floor did about 37,000 units a millisecond on two cores
/// and posts about 66,000 (the solvers do 20,000 to 40,000), but 4,990
/// thin posts turned at random, ringing 100 targets and searched at 64
/// headings, only 24,000: stopped after 10.6-10.9 s. At four for two,
/// 8.4 s: a room at the bound stops within about 10 s however its
/// obstacles crowd, and one of posts sooner than it need.
const UNITS_PER_TWO_CROSSINGS: u64 = 4;

/// The work of a tile whose outlines made `crossings`.
fn floor_work(crossings: usize) -> u64 {
    (crossings as u64).saturating_mul(UNITS_PER_TWO_CROSSINGS) / 2
}

/// An obstacle whose grown outline reaches beyond a tile by more than this
/// (or than the tile's size) is grown part by part and cut to the tile.
const FAR_MM: f64 = 100_000.0;

/// `within` less the outlines of the obstacles `met` grown by the parts
/// of `turned` that meet them. An obstacle whose grown outline reaches far
/// beyond `within` (a box far bigger than any room) is grown part by
/// part, each outline cut to `within` first: the boolean operations round
/// to a grid the size of all they join (100 m across: a tenth of a micron).
fn free_of_met(
    within: Rect<f64>,
    met: &[Met<'_>],
    turned: &Turned,
    grown: &Grown,
) -> (MultiPolygon<f64>, usize) {
    let free = MultiPolygon::new(vec![within.to_polygon()]);
    if met.is_empty() {
        return (free, 0);
    }
    let cut = cut_of(within);
    let reach = cut.width().max(cut.height()).max(FAR_MM);
    let far = Rect::new(
        cut.min() - Coord { x: reach, y: reach },
        cut.max() + Coord { x: reach, y: reach },
    );
    let mut outlines: Vec<Polygon<f64>> = Vec::new();
    for m in met {
        if inside(grown_bounds(m, turned), far) {
            outlines.extend(grown.outline(m, turned));
        } else {
            outlines.extend(grown_part_by_part(m, turned, cut));
        }
    }
    // In an order of their own (neighbours first, so that each union of
    // `union` joins outlines near each other), not the order the R-tree
    // of this room happens to give them in.
    sort_canonically(&mut outlines);
    free_of(free, outlines)
}

/// The bounds of `met`'s outline grown by its parts.
fn grown_bounds(met: &Met<'_>, turned: &Turned) -> Rect<f64> {
    let (lo, hi) = bounds(met.outline);
    let corners: Vec<Coord<f64>> = (met.parts.iter())
        .flat_map(|&k| {
            let (l, h) = turned.reach[k];
            [l, h]
        })
        .collect();
    let (plo, phi) = bounds(&corners);
    Rect::new(lo - phi, hi - plo)
}

/// Whether `a` lies within `b`.
fn inside(a: Rect<f64>, b: Rect<f64>) -> bool {
    a.min().x >= b.min().x
        && a.min().y >= b.min().y
        && a.max().x <= b.max().x
        && a.max().y <= b.max().y
}

/// The obstacles any part of `turned` meets with its hip point in `cut`,
/// each once with the parts that meet it, in the order of their corners.
/// How many obstacles meet the floor `within` for some part of the
/// footprint `turned` (those a piece of floor there is cut by).
pub fn obstacles_meeting(within: Rect<f64>, turned: &Turned, obstacles: &FloorObstacles) -> usize {
    obstacles_met(cut_of(within), turned, obstacles).len()
}

fn obstacles_met<'a>(
    cut: Rect<f64>,
    turned: &Turned,
    obstacles: &'a FloorObstacles,
) -> Vec<Met<'a>> {
    let mut found: Vec<(&'a [Coord<f64>], usize)> = Vec::new();
    for k in 0..turned.parts.len() {
        let (lo, hi) = turned.reach[k];
        let near = obstacles.near(k, cut.min() + lo, cut.max() + hi);
        found.extend(near.into_iter().map(|outline| (outline, k)));
    }
    // By corners, then part: the same outline in two parts' lists is one.
    found.sort_by(|(a, ka), (b, kb)| corner_bits_order(a, b).then(ka.cmp(kb)));
    let mut met: Vec<Met<'a>> = Vec::new();
    for (outline, k) in found {
        match met.last_mut() {
            Some(last) if corner_bits_order(last.outline, outline).is_eq() => last.parts.push(k),
            _ => met.push(Met {
                outline,
                parts: vec![k],
            }),
        }
    }
    met
}

/// Outlines ordered by their corners' bits, x then y, corner by corner;
/// where one's corners begin the other's, the one with fewer first.
fn corner_bits_order(a: &[Coord<f64>], b: &[Coord<f64>]) -> std::cmp::Ordering {
    let bits = |c: &Coord<f64>| (c.x.to_bits(), c.y.to_bits());
    corner_by_corner(a, b, |p, q| bits(p).cmp(&bits(q)))
}

/// Two lists of corners compared in turn by `by`; where one's corners
/// begin the other's, the one with fewer first.
fn corner_by_corner(
    a: &[Coord<f64>],
    b: &[Coord<f64>],
    by: impl Fn(&Coord<f64>, &Coord<f64>) -> std::cmp::Ordering,
) -> std::cmp::Ordering {
    (a.iter().zip(b))
        .map(|(p, q)| by(p, q))
        .find(|o| o.is_ne())
        .unwrap_or(a.len().cmp(&b.len()))
}

/// The region grown part by part, each part's outline on its own (what
/// `admissible_joined` leaves the same, but for rounding).
#[cfg(test)]
fn admissible_part_by_part(
    within: Rect<f64>,
    turned: &Turned,
    obstacles: &FloorObstacles,
) -> MultiPolygon<f64> {
    let met = obstacles_met(cut_of(within), turned, obstacles);
    free_of_parts(within, &met, turned).0
}

/// Pieces of admissible region kept in a memo, by a hash of their
/// rectangle, the obstacles near it and the corners of the parts that
/// meet each, with the crossings working each out met.
const PIECES: Table<Arc<(MultiPolygon<f64>, usize)>> = Table::new("floor pieces", 16_384);

/// `free` less the union of the `grown` outlines, and the crossings the
/// unions on the way met (`crossing_pairs`: what they cost).
fn free_of(free: MultiPolygon<f64>, grown: Vec<Polygon<f64>>) -> (MultiPolygon<f64>, usize) {
    let mut crossings = 0;
    if grown.len() > UNION_LEAF && covered_by_a_few(&free, &grown, &mut crossings) {
        return (MultiPolygon::new(Vec::new()), crossings);
    }
    (free.difference(&union(&grown, &mut crossings)), crossings)
}

/// The fewest outlines tried first, and how many times more each try
/// takes.
const FIRST_FEW: usize = 64;
const MORE: usize = 4;

/// Whether a spread-out few of the `grown` outlines (sorted by x) already
/// cover `free`: 64, then 256, ..., while they are at most a quarter of
/// them. Where boxes crowd round a target, a few cover the floor and the
/// union of all of them is not needed (the region is then empty whatever
/// the others are); elsewhere the tries cost at most a third more.
fn covered_by_a_few(
    free: &MultiPolygon<f64>,
    grown: &[Polygon<f64>],
    crossings: &mut usize,
) -> bool {
    let mut few = FIRST_FEW;
    while few * MORE <= grown.len() {
        let stride = grown.len() / few;
        let some: Vec<Polygon<f64>> = grown.iter().step_by(stride).cloned().collect();
        if free.difference(&union(&some, crossings)).0.is_empty() {
            return true;
        }
        few *= MORE;
    }
    false
}

/// `polygons` ordered by their leftmost x, then corner by corner (a
/// stable sort: equal outlines keep their order). Each polygon's leftmost
/// x is found once, not at every comparison.
fn sort_canonically(polygons: &mut Vec<Polygon<f64>>) {
    let mut keyed: Vec<(f64, Polygon<f64>)> =
        polygons.drain(..).map(|p| (left_of(&p), p)).collect();
    let x_then_y = |p: &Coord<f64>, q: &Coord<f64>| p.x.total_cmp(&q.x).then(p.y.total_cmp(&q.y));
    keyed.sort_by(|(la, a), (lb, b)| {
        let corners = || corner_by_corner(&a.exterior().0, &b.exterior().0, x_then_y);
        la.total_cmp(lb).then_with(corners)
    });
    polygons.extend(keyed.into_iter().map(|(_, p)| p));
}

/// The least x of a polygon's corners.
fn left_of(p: &Polygon<f64>) -> f64 {
    p.exterior()
        .0
        .iter()
        .map(|c| c.x)
        .fold(f64::INFINITY, f64::min)
}

/// The most outlines joined in one call of the boolean union. A kitchen's
/// tile has a few dozen; they are joined in one call, in the room's order,
/// as they always were (the operations round to a grid that depends on
/// what they join, and a placement on a region's edge may change with it).
const UNION_LEAF: usize = 64;

/// The union of `polygons`, joined in halves: where outlines crowd (a
/// thousand small boxes within a footprint's reach), their grown outlines
/// overlap nearly all pairwise, and one sweep over all of them meets
/// every crossing of their edges (5,000 boxes near one target took 19
/// s); the union of half of them has only the edges of its outline, so
/// that joining halves costs what their outlines do. Counted in
/// `crossings`: each sweep's `crossing_pairs`, and the corners of every
/// union made.
fn union(polygons: &[Polygon<f64>], crossings: &mut usize) -> MultiPolygon<f64> {
    let joined = if polygons.len() <= UNION_LEAF {
        *crossings += crossing_pairs(polygons);
        geo::unary_union(polygons)
    } else {
        let (left, right) = polygons.split_at(polygons.len() / 2);
        union(left, crossings).union(&union(right, crossings))
    };
    *crossings += geo::CoordsIter::coords_count(&joined);
    joined
}

/// What one sweep over `polygons` costs: for each pair whose bounds
/// overlap (where their edges may cross), the corners of the two. At most
/// `UNION_LEAF` polygons: a few thousand pairs, against a sweep's
/// milliseconds.
fn crossing_pairs(polygons: &[Polygon<f64>]) -> usize {
    use geo::{BoundingRect, Intersects};
    let boxes: Vec<(Rect<f64>, usize)> = (polygons.iter())
        .filter_map(|p| Some((p.bounding_rect()?, p.exterior().0.len())))
        .collect();
    let mut n = 0;
    for (i, (a, ca)) in boxes.iter().enumerate() {
        for (b, cb) in &boxes[i + 1..] {
            if a.intersects(b) {
                n += ca + cb;
            }
        }
    }
    n
}

/// The hip points where `footprint` fits in `room` at `heading_rad`, as
/// one region over the whole room (`Region` gives the same, piece by piece,
/// as it is asked).
pub fn admissible(
    room: &Room,
    footprint: &Footprint,
    heading_rad: f64,
    zone: Option<&Zone>,
) -> MultiPolygon<f64> {
    let turned = Turned::new(footprint, heading_rad);
    let Some(within) = shrunk_room(room, &turned, zone) else {
        return MultiPolygon::new(Vec::new());
    };
    let obstacles = FloorObstacles::new(room, footprint);
    let region = admissible_in(
        within,
        &turned,
        &obstacles,
        &Grown::default(),
        &Memo::forgetting(),
    )
    .free;
    match zone {
        Some(z) => z.cut(region),
        None => region,
    }
}

/// The convex polygon `p` cut to `rect` (Sutherland-Hodgman), none if
/// nothing is left.
fn clipped(p: &Polygon<f64>, rect: &Rect<f64>) -> Option<Polygon<f64>> {
    use geo::BoundingRect;
    let (lo, hi) = (rect.min(), rect.max());
    let bounds = p.bounding_rect()?;
    let (b0, b1) = (bounds.min(), bounds.max());
    if b0.x >= lo.x && b0.y >= lo.y && b1.x <= hi.x && b1.y <= hi.y {
        // Inside already: kept exactly as it was.
        return Some(p.clone());
    }
    if b1.x <= lo.x || b1.y <= lo.y || b0.x >= hi.x || b0.y >= hi.y {
        return None;
    }
    let mut points: Vec<Coord<f64>> = p.exterior().0.clone();
    points.dedup();
    if points.len() > 1 && points.first() == points.last() {
        points.pop();
    }
    // Each side of the rectangle: which coordinate, its value, and
    // whether points keep above (true) or below it.
    let sides = [
        (0, lo.x, true),
        (0, hi.x, false),
        (1, lo.y, true),
        (1, hi.y, false),
    ];
    for (axis, at, above) in sides {
        let get = |c: &Coord<f64>| if axis == 0 { c.x } else { c.y };
        let keeps = |c: &Coord<f64>| if above { get(c) >= at } else { get(c) <= at };
        let mut next = Vec::with_capacity(points.len() + 1);
        for (i, a) in points.iter().enumerate() {
            let b = &points[(i + 1) % points.len()];
            if keeps(a) {
                next.push(*a);
            }
            if keeps(a) != keeps(b) {
                let t = (at - get(a)) / (get(b) - get(a));
                next.push(Coord {
                    x: a.x + t * (b.x - a.x),
                    y: a.y + t * (b.y - a.y),
                });
            }
        }
        points = next;
        if points.len() < 3 {
            return None;
        }
    }
    Some(Polygon::new(LineString::from(points), Vec::new()))
}

/// Hip points keeping the whole footprint inside the room (and the zone).
pub fn shrunk_room(room: &Room, turned: &Turned, zone: Option<&Zone>) -> Option<Rect<f64>> {
    let floor = Rect::new(
        Coord { x: 0.0, y: 0.0 },
        Coord {
            x: room.size_mm.x,
            y: room.size_mm.y,
        },
    );
    shrunk(floor, turned, zone)
}

/// Hip points keeping the whole footprint inside `floor` (and the zone).
pub fn shrunk(floor: Rect<f64>, turned: &Turned, zone: Option<&Zone>) -> Option<Rect<f64>> {
    let (mut x0, mut y0) = (floor.min().x, floor.min().y);
    let (mut x1, mut y1) = (floor.max().x, floor.max().y);
    for c in turned.parts.iter().flatten() {
        x0 = x0.max(floor.min().x - c.x);
        y0 = y0.max(floor.min().y - c.y);
        x1 = x1.min(floor.max().x - c.x);
        y1 = y1.min(floor.max().y - c.y);
    }
    if let Some(z) = zone {
        (x0, y0) = (x0.max(z.min.0), y0.max(z.min.1));
        (x1, y1) = (x1.min(z.max.0), y1.min(z.max.1));
    }
    (x0 < x1 && y0 < y1).then(|| Rect::new(Coord { x: x0, y: y0 }, Coord { x: x1, y: y1 }))
}

/// `O + (-F)`: the hip points at which footprint `F` would overlap the
/// convex obstacle outline `O`.
fn minkowski_with_reflected(obstacle: &[Coord<f64>], footprint: &[Coord<f64>]) -> Polygon<f64> {
    let points: Vec<Coord<f64>> = obstacle
        .iter()
        .flat_map(|o| {
            footprint.iter().map(move |f| Coord {
                x: o.x - f.x,
                y: o.y - f.y,
            })
        })
        .collect();
    Polygon::new(LineString::from(convex_hull(points)), Vec::new())
}

/// The convex hull of `points`, counter-clockwise from the lowest-leftmost
/// corner and closed (Andrew's monotone chain: a few dozen points here, so
/// sorting them is cheaper than a general hull's partitions).
fn convex_hull(mut points: Vec<Coord<f64>>) -> Vec<Coord<f64>> {
    points.sort_by(|a, b| a.x.total_cmp(&b.x).then(a.y.total_cmp(&b.y)));
    points.dedup();
    if points.len() < 3 {
        let mut ring = points;
        if let Some(&first) = ring.first() {
            ring.push(first);
        }
        return ring;
    }
    let cross = |o: Coord<f64>, a: Coord<f64>, b: Coord<f64>| {
        (a.x - o.x) * (b.y - o.y) - (a.y - o.y) * (b.x - o.x)
    };
    let mut hull: Vec<Coord<f64>> = Vec::with_capacity(points.len() + 1);
    for &p in &points {
        while hull.len() >= 2 && cross(hull[hull.len() - 2], hull[hull.len() - 1], p) <= 0.0 {
            hull.pop();
        }
        hull.push(p);
    }
    let lower = hull.len() + 1;
    for &p in points.iter().rev().skip(1) {
        while hull.len() >= lower && cross(hull[hull.len() - 2], hull[hull.len() - 1], p) <= 0.0 {
            hull.pop();
        }
        hull.push(p);
    }
    // The last point pushed is the first: the ring is closed.
    hull
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::scene::BoxObstacle;
    use geo::{Area, Contains, Point};

    #[test]
    fn clipping_keeps_what_is_inside_and_drops_what_is_outside() {
        let rect = Rect::new(Coord { x: 0.0, y: 0.0 }, Coord { x: 10.0, y: 10.0 });
        let square = |x0: f64, y0: f64, size: f64| {
            Rect::new(
                Coord { x: x0, y: y0 },
                Coord {
                    x: x0 + size,
                    y: y0 + size,
                },
            )
            .to_polygon()
        };
        let inner = square(2.0, 2.0, 3.0);
        assert_eq!(clipped(&inner, &rect).unwrap().unsigned_area(), 9.0);
        assert!(clipped(&square(1e15, 1e15, 5.0), &rect).is_none());
        let huge = square(-1e15, 5.0, 2e15);
        assert_eq!(clipped(&huge, &rect).unwrap().unsigned_area(), 50.0);
    }
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
            doors: Vec::new(),
        }
    }

    /// 100 small boxes crowded in one tile (more outlines than are grown
    /// part by part): boxes of one size are one shape, grown once and
    /// charged once; boxes each of its own size are a hundred.
    #[test]
    fn a_piece_names_each_shape_it_grows_once() {
        use crate::floor::test_boxes::grid_of_boxes;
        let shapes = |size: &dyn Fn(usize) -> f64| {
            let mut room = room_with_counter();
            room.boxes = grid_of_boxes([1000.0, 500.0], 60.0, &|k| [size(k), 20.0]);
            let chair = Footprint::circle(300.0, 900.0);
            let turned = Turned::new(&chair, 0.0);
            let within = shrunk_room(&room, &turned, None).expect("the chair fits the room");
            let obstacles = FloorObstacles::new(&room, &chair);
            admissible_in(
                within,
                &turned,
                &obstacles,
                &Grown::default(),
                &Memo::default(),
            )
            .shapes
        };
        let alike = shapes(&|_| 20.0);
        assert_eq!(alike.iter().count(), 1);
        let each = shapes(&|k| 10.0 + 0.25 * k as f64);
        assert_eq!(each.iter().count(), 100);
        assert!(each.iter().all(|(_, units)| units == alike.units()));
    }

    #[test]
    fn a_circle_keeps_its_radius_from_walls_and_counter() {
        let region = admissible(
            &room_with_counter(),
            &Footprint::circle(300.0, 2000.0),
            0.0,
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
        let region = admissible(&room, &Footprint::circle(300.0, 1400.0), 0.0, None);
        assert!(region.contains(&Point::new(400.0, 1000.0)));
    }

    #[test]
    fn a_wheelchair_facing_the_counter_needs_its_front_clear() {
        let chair = Footprint::rectangle(600.0, 500.0, 660.0, 2000.0);
        let facing = admissible(&room_with_counter(), &chair, std::f64::consts::PI, None);
        let sideways = admissible(
            &room_with_counter(),
            &chair,
            std::f64::consts::FRAC_PI_2,
            None,
        );
        // Facing the counter the hip stays 600 mm from it; side on, 330 mm.
        assert!(!facing.contains(&Point::new(1100.0, 1000.0)));
        assert!(facing.contains(&Point::new(1250.0, 1000.0)));
        assert!(sideways.contains(&Point::new(1000.0, 1000.0)));
    }

    #[test]
    fn a_zone_restricts_the_region() {
        let zone = Zone::rectangle((900.0, 800.0), (1200.0, 1200.0));
        let region = admissible(
            &room_with_counter(),
            &Footprint::circle(300.0, 2000.0),
            0.0,
            Some(&zone),
        );
        assert!(region.contains(&Point::new(1000.0, 1000.0)));
        assert!(!region.contains(&Point::new(1500.0, 1000.0)));
    }

    #[test]
    fn knees_go_under_a_counter_that_clears_them_and_no_further() {
        // A sink counter: its front 600 mm from the wall, 700 to 900 mm
        // high (knee space under it); a chair whose knees (500 to 690 mm)
        // reach 500 mm ahead of the hip and whose body (700 to 1400 mm)
        // reaches 130 mm ahead of it.
        let mut room = room_with_counter();
        room.boxes[0].corner_mm.z = 700.0;
        room.boxes[0].size_mm.z = 200.0;
        let mut chair = Footprint::rectangle(500.0, 100.0, 400.0, 690.0);
        chair.parts.push(
            Footprint::rectangle(130.0, 130.0, 400.0, 1400.0)
                .parts
                .remove(0),
        );
        chair.parts[1].z_mm = [700.0, 1400.0];
        let facing = admissible(&room, &chair, std::f64::consts::PI, None);
        // Facing the wall (x falls ahead): the knees go under the counter;
        // the body stops at its front.
        assert!(facing.contains(&Point::new(600.0 + 131.0, 1000.0)));
        assert!(!facing.contains(&Point::new(600.0 + 129.0, 1000.0)));
        // The same chair with its knees at the counter's height cannot.
        chair.parts[0].z_mm = [0.0, 800.0];
        let blocked = admissible(&room, &chair, std::f64::consts::PI, None);
        assert!(!blocked.contains(&Point::new(600.0 + 131.0, 1000.0)));
        assert!(blocked.contains(&Point::new(600.0 + 501.0, 1000.0)));
    }

    #[test]
    fn a_footprint_larger_than_the_room_fits_nowhere() {
        let region = admissible(
            &room_with_counter(),
            &Footprint::circle(5000.0, 2000.0),
            0.0,
            None,
        );
        assert!(region.0.is_empty());
    }
}

#[cfg(test)]
mod union_tests {
    use super::super::FloorPart;
    use super::*;
    use crate::scene::BoxObstacle;
    use geo::Area;
    use nalgebra::{Point3, Vector3};
    use proptest::prelude::*;

    proptest! {
        /// The hull of a few points (a box's corners less a chair's) is
        /// geo's convex hull: the same area, every point within it.
        #[test]
        fn the_monotone_chain_hull_is_the_convex_hull(
            points in prop::collection::vec((-500.0..500.0f64, -500.0..500.0f64), 3..40),
        ) {
            use geo::{ConvexHull, Contains, MultiPoint, Point};
            let coords: Vec<Coord<f64>> = points.iter().map(|&(x, y)| Coord { x, y }).collect();
            let ring = convex_hull(coords.clone());
            prop_assert_eq!(ring.first(), ring.last());
            let ours = Polygon::new(LineString::from(ring), Vec::new());
            let theirs = MultiPoint::from(coords.iter().map(|&c| Point::from(c)).collect::<Vec<_>>()).convex_hull();
            prop_assert!((ours.unsigned_area() - theirs.unsigned_area()).abs() < 1e-6 * (1.0 + theirs.unsigned_area()));
            // Counter-clockwise: a positive signed area.
            prop_assert!(ours.signed_area() >= 0.0);
            for c in &coords {
                let grown = ours.exterior().0.iter().any(|v| (v.x - c.x).hypot(v.y - c.y) < 1e-9);
                prop_assert!(grown || ours.contains(&Point::from(*c)) || ours.exterior().contains(&Point::from(*c)));
            }
        }
    }

    /// A square of side `side_mm` at (x, y).
    fn square(x: f64, y: f64, side_mm: f64) -> Polygon<f64> {
        Rect::new(
            Coord { x, y },
            Coord {
                x: x + side_mm,
                y: y + side_mm,
            },
        )
        .to_polygon()
    }

    proptest! {
        #![proptest_config(ProptestConfig::with_cases(24))]

        /// The union joined in halves, and the answer "covered" from a few
        /// outlines, leave the floor the one union of all of them leaves:
        /// crowded squares (up to 600, so that the tries of a few run),
        /// sparse ones, and sizes between.
        #[test]
        fn the_region_is_the_floor_minus_the_union_of_all_outlines(
            corners in prop::collection::vec((0.0..1000.0f64, 0.0..1000.0f64), 1..600),
            side_mm in 5.0..200.0f64,
        ) {
            let within = Rect::new(Coord { x: 100.0, y: 100.0 }, Coord { x: 900.0, y: 900.0 });
            let free = MultiPolygon::new(vec![within.to_polygon()]);
            let mut grown: Vec<Polygon<f64>> =
                corners.iter().map(|&(x, y)| square(x, y, side_mm)).collect();
            let plain = free.difference(&geo::unary_union(&grown));
            grown.sort_by(|a, b| left_of(a).total_cmp(&left_of(b)));
            let halved = free.difference(&union(&grown, &mut 0));
            let apart = plain.difference(&halved).unsigned_area() + halved.difference(&plain).unsigned_area();
            // The boolean operations round to their own grid, which
            // depends on what they join: slivers of a hundredth of a
            // square millimetre, a millionth of the floor, may differ.
            prop_assert!(apart < 1e-6 * within.to_polygon().unsigned_area(), "the regions differ by {apart} mm2");
            if covered_by_a_few(&free, &grown, &mut 0) {
                prop_assert!(plain.unsigned_area() < 1e-9, "called covered, {} mm2 free", plain.unsigned_area());
            }
        }

        /// Each obstacle's grown outlines joined first, once per shape,
        /// leave the floor the outlines grown part by part leave: random
        /// boxes of a few sizes (so that shapes repeat), some turned, at
        /// heights that meet some of a chair's three parts and not others,
        /// at a random heading.
        #[test]
        fn joining_each_obstacles_outlines_first_leaves_the_same_floor(
            boxes in prop::collection::vec(
                (0.0..3000.0f64, 0.0..3000.0f64, 0usize..3, 0usize..4, 0usize..3), 1..80),
            heading_rad in 0.0..std::f64::consts::TAU,
        ) {
            let sizes = [(100.0, 100.0), (600.0, 400.0), (50.0, 900.0)];
            let yaws = [0.0, 0.0, 0.5, 1.2];
            let heights = [(0.0, 300.0), (500.0, 900.0), (0.0, 2000.0)];
            let room = Room {
                boxes: boxes.iter().enumerate().map(|(i, &(x, y, s, w, h))| BoxObstacle {
                    name: format!("b{i}"),
                    corner_mm: Point3::new(x, y, heights[h].0),
                    size_mm: Vector3::new(sizes[s].0, sizes[s].1, heights[h].1 - heights[h].0),
                    yaw_rad: yaws[w],
                }).collect(),
                size_mm: Vector3::new(3500.0, 3500.0, 2500.0),
                name: "r".into(),
                meshes: Vec::new(),
                targets: Vec::new(),
                surfaces: Vec::new(),
                doors: Vec::new(),
            };
            let part = |front: f64, back: f64, half: f64, z: [f64; 2]| FloorPart {
                outline_mm: [(front, half), (-back, half), (-back, -half), (front, -half)]
                    .map(|(x, y)| nalgebra::Vector2::new(x, y)).to_vec(),
                z_mm: z,
            };
            let chair = Footprint { parts: vec![
                part(300.0, 150.0, 330.0, [0.0, 600.0]),
                part(700.0, 300.0, 200.0, [100.0, 250.0]),
                part(100.0, 200.0, 250.0, [400.0, 1400.0]),
            ] };
            let turned = Turned::new(&chair, heading_rad);
            let obstacles = FloorObstacles::new(&room, &chair);
            let within = shrunk_room(&room, &turned, None).unwrap();
            let part_by_part = admissible_part_by_part(within, &turned, &obstacles);
            let (joined, _, _) = admissible_joined(within, &turned, &obstacles, &Grown::default());
            let apart = part_by_part.difference(&joined).unsigned_area()
                + joined.difference(&part_by_part).unsigned_area();
            prop_assert!(apart < 1e-6 * within.to_polygon().unsigned_area(), "the regions differ by {apart} mm2");
        }
    }
}
