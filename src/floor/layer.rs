//! The admissible region at one heading over a whole floor, worked out a
//! tile at a time, for following where a base can get to: each tile (a
//! square of a grid shared by every heading) is `admissible_in` over the
//! tile widened by a millimetre on each side, so that the pieces of two
//! neighbouring tiles overlap in a strip two millimetres wide wherever the
//! region runs on across their edge. A union of all the obstacles of a
//! large room in one boolean operation costs more than in proportion to
//! their number (500 posts: 27 s, 2,000: 158 s); tile by tile, each
//! operation meets only the obstacles near its tile.

use geo::{Area, BooleanOps, BoundingRect, Contains, Coord, Distance, Euclidean};
use geo::{InteriorPoint, MultiPolygon, Point, Polygon, Rect};
use rayon::prelude::*;

use super::obstacles::FloorObstacles;
use super::region::{admissible_joined, Grown, Turned};
use super::work::Looked;

/// The side of a tile, for floors up to `MAX_TILES` of them.
const TILE_MM: f64 = 2000.0;
const MAX_TILES: f64 = 4096.0;
/// How far each tile's pieces reach beyond the tile.
const OVERLAP_MM: f64 = 1.0;
/// A point of the strip two tiles share, found in one tile's pieces, is
/// looked for in the other's this far off at most (the two tiles' boolean
/// operations round alike but for a hair).
const SEAM_NEAR_MM: f64 = 0.01;
/// A point is looked for in a region this far off at most (a point a
/// boolean operation left on an edge).
const NEAR_MM: f64 = 1.0;

/// The tiles a floor is cut into: the same for every heading.
pub struct Tiling {
    origin: Coord<f64>,
    tile_mm: f64,
    nx: usize,
    ny: usize,
}

impl Tiling {
    /// Tiles over `floor`, about `TILE_MM` square.
    pub fn over(floor: Rect<f64>) -> Self {
        let (w, h) = (floor.width(), floor.height());
        let tile_mm = TILE_MM.max((w * h / MAX_TILES).sqrt());
        Tiling {
            origin: floor.min(),
            tile_mm,
            nx: (w / tile_mm).ceil().max(1.0) as usize,
            ny: (h / tile_mm).ceil().max(1.0) as usize,
        }
    }

    fn len(&self) -> usize {
        self.nx * self.ny
    }

    /// Tile `t` widened by `OVERLAP_MM`, within `within`.
    fn rect(&self, t: usize, within: Rect<f64>) -> Option<Rect<f64>> {
        let (i, j) = ((t % self.nx) as f64, (t / self.nx) as f64);
        let s = self.tile_mm;
        let lo = Coord {
            x: (self.origin.x + i * s - OVERLAP_MM).max(within.min().x),
            y: (self.origin.y + j * s - OVERLAP_MM).max(within.min().y),
        };
        let hi = Coord {
            x: (self.origin.x + (i + 1.0) * s + OVERLAP_MM).min(within.max().x),
            y: (self.origin.y + (j + 1.0) * s + OVERLAP_MM).min(within.max().y),
        };
        (lo.x < hi.x && lo.y < hi.y).then(|| Rect::new(lo, hi))
    }

    /// The tile `p` lies in (the nearest, for a point off the grid).
    fn of(&self, p: Point<f64>) -> usize {
        let at = |v: f64, o: f64, n: usize| {
            ((v - o) / self.tile_mm).floor().clamp(0.0, (n - 1) as f64) as usize
        };
        at(p.y(), self.origin.y, self.ny) * self.nx + at(p.x(), self.origin.x, self.nx)
    }

    /// The pairs of tiles side by side: each with the one to its right and
    /// the one above it.
    fn neighbours(&self) -> impl Iterator<Item = (usize, usize)> + '_ {
        (0..self.len()).flat_map(move |t| {
            let (i, j) = (t % self.nx, t / self.nx);
            let right = (i + 1 < self.nx).then_some((t, t + 1));
            let above = (j + 1 < self.ny).then_some((t, t + self.nx));
            right.into_iter().chain(above)
        })
    }
}

/// The admissible region at one heading, tile by tile, its pieces
/// numbered one after another from `first`.
pub struct Layer {
    pub heading_rad: f64,
    /// The floor the hip point keeps to at this heading (the floor shrunk
    /// by the footprint), none if the footprint fits nowhere on it.
    within: Option<Rect<f64>>,
    tiles: Vec<Vec<Polygon<f64>>>,
    /// The number of tile `t`'s first piece.
    starts: Vec<usize>,
    /// What working it out cost, in units of the meter.
    pub work: u64,
}

impl Layer {
    /// Where `turned` (the footprint at `heading_rad`) fits among
    /// `obstacles` with its hip point within `within`, tile by tile on
    /// `grid`, its pieces numbered from `first`.
    pub fn new(
        grid: &Tiling,
        within: Option<Rect<f64>>,
        turned: &Turned,
        heading_rad: f64,
        obstacles: &FloorObstacles,
        first: usize,
    ) -> Self {
        let grown = Grown::default();
        // The tiles in parallel (each on its own; in the grid's order).
        type Worked = (Vec<Polygon<f64>>, u64, Looked);
        let worked: Vec<Worked> = (0..grid.len())
            .into_par_iter()
            .map(|t| match within.and_then(|w| grid.rect(t, w)) {
                Some(rect) => {
                    let (piece, work, shapes) = admissible_joined(rect, turned, obstacles, &grown);
                    (piece.0, work, shapes)
                }
                None => (Vec::new(), 0, Looked::default()),
            })
            .collect();
        // Each shape is grown once for the layer, whichever tile first.
        let growing = Looked::of(worked.iter().flat_map(|w| w.2.iter())).units();
        let work = (worked.iter()).fold(growing, |sum, (_, w, _)| sum.saturating_add(*w));
        let tiles: Vec<Vec<Polygon<f64>>> = worked.into_iter().map(|(p, _, _)| p).collect();
        let mut starts = Vec::with_capacity(tiles.len());
        let mut next = first;
        for pieces in &tiles {
            starts.push(next);
            next += pieces.len();
        }
        Layer {
            heading_rad,
            within,
            tiles,
            starts,
            work,
        }
    }

    /// The number after this layer's last piece.
    pub fn end(&self) -> usize {
        self.starts.last().map_or(0, |&s| s) + self.tiles.last().map_or(0, Vec::len)
    }

    /// Every piece with its number.
    pub fn pieces(&self) -> impl Iterator<Item = (usize, &Polygon<f64>)> {
        (self.tiles.iter().zip(&self.starts))
            .flat_map(|(pieces, &s)| pieces.iter().enumerate().map(move |(k, p)| (s + k, p)))
    }

    /// The number of the piece holding `p`, or of the nearest within
    /// `NEAR_MM`.
    pub fn piece_at(&self, grid: &Tiling, p: Point<f64>) -> Option<usize> {
        self.within?;
        let t = grid.of(p);
        piece_near(&self.tiles[t], p, NEAR_MM).map(|k| self.starts[t] + k)
    }

    /// The pairs of pieces of neighbouring tiles that overlap: the same
    /// piece of the region, cut by the tiles' edge.
    pub fn seams(&self, grid: &Tiling) -> Vec<(usize, usize)> {
        let Some(within) = self.within else {
            return Vec::new();
        };
        let mut joins = Vec::new();
        for (a, b) in grid.neighbours() {
            let (Some(ra), Some(rb)) = (grid.rect(a, within), grid.rect(b, within)) else {
                continue;
            };
            let Some(strip) = overlap(ra, rb) else {
                continue;
            };
            for (ka, kb) in seam(&self.tiles[a], &self.tiles[b], strip) {
                joins.push((self.starts[a] + ka, self.starts[b] + kb));
            }
        }
        joins
    }

    /// Whether one of the pieces `keep` says yes to overlaps `rect` (by
    /// more than a line).
    pub fn any_overlapping(&self, rect: Rect<f64>, keep: impl Fn(usize) -> bool) -> bool {
        let area = MultiPolygon::new(vec![rect.to_polygon()]);
        self.pieces().any(|(n, piece)| {
            let Some(bounds) = piece.bounding_rect() else {
                return false;
            };
            if !keep(n) || overlap(bounds, rect).is_none() {
                return false;
            }
            let inside = bounds.min().x > rect.min().x
                && bounds.min().y > rect.min().y
                && bounds.max().x < rect.max().x
                && bounds.max().y < rect.max().y;
            inside
                || !MultiPolygon::new(vec![piece.clone()])
                    .intersection(&area)
                    .0
                    .is_empty()
        })
    }
}

/// The rectangle two rectangles share, none if they share no area.
pub(super) fn overlap(a: Rect<f64>, b: Rect<f64>) -> Option<Rect<f64>> {
    let lo = Coord {
        x: a.min().x.max(b.min().x),
        y: a.min().y.max(b.min().y),
    };
    let hi = Coord {
        x: a.max().x.min(b.max().x),
        y: a.max().y.min(b.max().y),
    };
    (lo.x < hi.x && lo.y < hi.y).then(|| Rect::new(lo, hi))
}

/// Which of `a`'s pieces each of `b`'s overlaps within `strip` (the
/// rectangle both tiles cover): every part of `b`'s pieces in the strip is
/// in one of `a`'s.
fn seam(a: &[Polygon<f64>], b: &[Polygon<f64>], strip: Rect<f64>) -> Vec<(usize, usize)> {
    if a.is_empty() || b.is_empty() {
        return Vec::new();
    }
    let area = MultiPolygon::new(vec![strip.to_polygon()]);
    let mut joins = Vec::new();
    for (kb, piece) in b.iter().enumerate() {
        if piece
            .bounding_rect()
            .and_then(|r| overlap(r, strip))
            .is_none()
        {
            continue;
        }
        let parts = MultiPolygon::new(vec![piece.clone()]).intersection(&area);
        // A part thinner than a hundredth of a millimetre across the strip
        // is the rounding of a way exactly as wide as the base, not a way.
        let wide = |part: &&Polygon<f64>| part.unsigned_area() >= SEAM_NEAR_MM * strip_mm(strip);
        for part in parts.0.iter().filter(wide) {
            let ka = part
                .interior_point()
                .and_then(|p| piece_near(a, p, SEAM_NEAR_MM));
            if let Some(ka) = ka {
                joins.push((ka, kb));
            }
        }
    }
    joins.sort_unstable();
    joins.dedup();
    joins
}

/// The width of the strip two tiles share (its shorter side).
fn strip_mm(strip: Rect<f64>) -> f64 {
    strip.width().min(strip.height())
}

/// The piece of `pieces` holding `p`, or the nearest within `near_mm`.
pub fn piece_near(pieces: &[Polygon<f64>], p: Point<f64>, near_mm: f64) -> Option<usize> {
    if let Some(k) = pieces.iter().position(|poly| poly.contains(&p)) {
        return Some(k);
    }
    pieces
        .iter()
        .map(|poly| Euclidean.distance(poly, &p))
        .enumerate()
        .filter(|(_, d)| *d <= near_mm)
        .min_by(|a, b| a.1.total_cmp(&b.1))
        .map(|(k, _)| k)
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::floor::region::shrunk_room;
    use crate::floor::test_boxes::grid_of_boxes;
    use crate::floor::Footprint;
    use crate::scene::Room;
    use nalgebra::Vector3;

    /// A 10 m hall with 100 posts 1 m apart, each `side(k)` mm square.
    fn hall(side: &dyn Fn(usize) -> f64) -> Room {
        Room {
            name: "hall".into(),
            size_mm: Vector3::new(10_000.0, 10_000.0, 2500.0),
            boxes: grid_of_boxes([500.0, 500.0], 1000.0, &|k| [side(k), side(k)]),
            meshes: Vec::new(),
            targets: Vec::new(),
            surfaces: Vec::new(),
            doors: Vec::new(),
        }
    }

    /// The work of a layer of `room` for a chair, and the shapes its
    /// first tile grows.
    fn layer_work(room: &Room) -> (u64, Looked) {
        let chair = Footprint::rectangle(600.0, 500.0, 660.0, 1400.0);
        let turned = Turned::new(&chair, 0.3);
        let obstacles = FloorObstacles::new(room, &chair);
        let within = shrunk_room(room, &turned, None);
        let grid = Tiling::over(within.expect("the chair fits the hall"));
        let layer = Layer::new(&grid, within, &turned, 0.3, &obstacles, 0);
        let tile = grid.rect(0, within.unwrap()).unwrap();
        let (_, _, shapes) = admissible_joined(tile, &turned, &obstacles, &Grown::default());
        (layer.work, shapes)
    }

    /// A layer grows each distinct shape once, whatever tiles meet it:
    /// posts each of its own size cost a hundred shapes more than posts
    /// alike, not one for every tile that meets each.
    #[test]
    fn a_layer_pays_for_growing_each_shape_once() {
        let (alike, shapes) = layer_work(&hall(&|_| 50.0));
        assert_eq!(shapes.iter().count(), 1, "the posts alike are one shape");
        let unit = shapes.units();
        let (each, _) = layer_work(&hall(&|k| 50.0 + 0.5 * k as f64));
        let more = each - alike;
        assert!(
            more >= 90 * unit && more <= 110 * unit,
            "{more} units more, {unit} a shape"
        );
    }
}
