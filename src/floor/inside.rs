//! Whether a floor point is in a region, fast: the region's edges sorted
//! into horizontal bands, so that a test counts the crossings of a ray
//! with the few edges of its band (even-odd, holes included) instead of
//! every edge. A placement search asks thousands of these per target.

use geo::{BoundingRect, Contains, MultiPolygon, Point, Rect};

/// A region with its edges by band.
#[derive(Clone, Debug)]
pub struct Inside {
    region: MultiPolygon<f64>,
    /// The region's bounding rectangle (none if it is empty).
    bounds: Option<Rect<f64>>,
    bottom_mm: f64,
    band_mm: f64,
    /// Each band's edges, `[x0, y0, x1, y1]`.
    bands: Vec<Vec<[f64; 4]>>,
}

/// About this many edges to a band, on average over the region's height.
const EDGES_PER_BAND: f64 = 2.0;

impl Inside {
    pub fn new(region: MultiPolygon<f64>) -> Self {
        let bounds = region.bounding_rect();
        let edges: Vec<[f64; 4]> = region
            .0
            .iter()
            .flat_map(|p| std::iter::once(p.exterior()).chain(p.interiors()))
            .flat_map(|ring| {
                ring.lines()
                    .map(|l| [l.start.x, l.start.y, l.end.x, l.end.y])
            })
            .filter(|e| e[1] != e[3])
            .collect();
        let bottom_mm = edges
            .iter()
            .map(|e| e[1].min(e[3]))
            .fold(f64::INFINITY, f64::min);
        let top_mm = edges
            .iter()
            .map(|e| e[1].max(e[3]))
            .fold(f64::NEG_INFINITY, f64::max);
        if edges.is_empty() {
            return Inside {
                region,
                bounds,
                bottom_mm: 0.0,
                band_mm: 1.0,
                bands: Vec::new(),
            };
        }
        let count = ((edges.len() as f64 / EDGES_PER_BAND).ceil() as usize).clamp(1, 4096);
        let band_mm = ((top_mm - bottom_mm) / count as f64).max(1e-6);
        let mut bands = vec![Vec::new(); count];
        for e in edges {
            let lo = ((e[1].min(e[3]) - bottom_mm) / band_mm).floor() as usize;
            let hi = ((e[1].max(e[3]) - bottom_mm) / band_mm).floor() as usize;
            for band in &mut bands[lo.min(count - 1)..=hi.min(count - 1)] {
                band.push(e);
            }
        }
        Inside {
            region,
            bounds,
            bottom_mm,
            band_mm,
            bands,
        }
    }

    /// How far `p` is from the region's bounding rectangle (0 inside
    /// it): no point of the region is nearer. None if it is empty.
    pub fn bounds_distance_mm(&self, p: Point<f64>) -> Option<f64> {
        let b = self.bounds?;
        let dx = (b.min().x - p.x()).max(p.x() - b.max().x).max(0.0);
        let dy = (b.min().y - p.y()).max(p.y() - b.max().y).max(0.0);
        Some(dx.hypot(dy))
    }

    /// The region.
    pub fn region(&self) -> &MultiPolygon<f64> {
        &self.region
    }

    /// Whether `(x, y)` is inside the region, not on its boundary: the
    /// crossings counted in its band, confirmed by `geo` when they say
    /// inside (so that a point within rounding of an edge is never let in).
    pub fn contains(&self, x: f64, y: f64) -> bool {
        self.roughly_contains(x, y) && self.region.contains(&Point::new(x, y))
    }

    /// Like [`Inside::contains`] without the confirmation: for ruling
    /// points out quickly (a point on the boundary may go either way).
    pub fn roughly_contains(&self, x: f64, y: f64) -> bool {
        let band = (y - self.bottom_mm) / self.band_mm;
        if band < 0.0 || band >= self.bands.len() as f64 {
            return false;
        }
        self.bands[band as usize]
            .iter()
            .filter(|&&[x0, y0, x1, y1]| {
                (y0 > y) != (y1 > y) && x < x0 + (y - y0) / (y1 - y0) * (x1 - x0)
            })
            .count()
            % 2
            == 1
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use geo::{LineString, Polygon};
    use rand_chacha::rand_core::{Rng, SeedableRng};
    use rand_chacha::ChaCha8Rng;

    fn ring(points: &[(f64, f64)]) -> LineString<f64> {
        LineString::from(points.to_vec())
    }

    #[test]
    fn agrees_with_geo_on_a_region_with_a_hole_and_two_parts() {
        let outer = ring(&[(0.0, 0.0), (1000.0, 0.0), (1000.0, 800.0), (0.0, 800.0)]);
        let hole = ring(&[(200.0, 200.0), (600.0, 250.0), (400.0, 600.0)]);
        let other = ring(&[(1200.0, 100.0), (1500.0, 400.0), (1200.0, 700.0)]);
        let region = MultiPolygon::new(vec![
            Polygon::new(outer, vec![hole]),
            Polygon::new(other, vec![]),
        ]);
        let inside = Inside::new(region.clone());
        let mut rng = ChaCha8Rng::seed_from_u64(7);
        for _ in 0..20_000 {
            let x = (rng.next_u32() % 1700) as f64 - 100.0 + 0.5;
            let y = (rng.next_u32() % 1000) as f64 - 100.0 + 0.25;
            let geo = region.contains(&Point::new(x, y));
            assert_eq!(inside.contains(x, y), geo, "({x}, {y})");
            assert_eq!(inside.roughly_contains(x, y), geo, "({x}, {y})");
        }
    }

    #[test]
    fn an_empty_region_contains_nothing() {
        let inside = Inside::new(MultiPolygon::new(vec![]));
        assert!(!inside.contains(0.0, 0.0));
        assert!(inside.region().0.is_empty());
    }
}
