//! The room's obstacles as one footprint's parts meet them on the floor:
//! for each part, the convex outlines of the boxes whose heights it shares
//! and of the cells its meshes block at those heights (`mesh_cells.rs`),
//! each in an R-tree by its bounding rectangle, so that a piece of floor
//! asks only for the obstacles near it. Built once per room and base, for
//! every heading: outlines do not turn with the base.

use std::sync::Arc;

use geo::Coord;
use nalgebra::Vector2;
use rayon::prelude::*;
use rstar::primitives::{GeomWithData, Rectangle};
use rstar::{RTree, AABB};

use super::mesh_cells::MeshCells;
use super::work::{unbounded, CutShort};
use super::Footprint;
use crate::scene::{BoxObstacle, Room};

/// An outline's bounding rectangle, with the outline's index.
type Entry = GeomWithData<Rectangle<[f64; 2]>, usize>;

/// The outlines one part meets.
#[derive(Debug)]
struct PartObstacles {
    outlines: Vec<Vec<Coord<f64>>>,
    tree: RTree<Entry>,
}

/// Every part's obstacles.
#[derive(Debug)]
pub struct FloorObstacles {
    parts: Vec<Arc<PartObstacles>>,
    work: u64,
}

impl FloorObstacles {
    /// The room's obstacles, however much marking its meshes' cells
    /// costs (tests, and where the work is charged after).
    pub fn new(room: &Room, footprint: &Footprint) -> Self {
        Self::with(room, footprint, &[], &unbounded)
            .unwrap_or_else(|_| unreachable!("nothing cuts short obstacles allowed any work"))
    }

    /// The room's obstacles and `extra` boxes (the walls round a room's
    /// doorways, where a route search lets a base come in from outside).
    /// Parts at the same heights meet the same outlines, found once and
    /// shared; the heights' outlines are found in parallel. Cut short
    /// where marking the meshes' cells would cost more than `allows`
    /// allows (thousands of thin triangles across a room: seconds).
    pub fn with(
        room: &Room,
        footprint: &Footprint,
        extra: &[BoxObstacle],
        allows: &dyn Fn(u64) -> bool,
    ) -> Result<Self, CutShort> {
        let marking = |triangles: usize, visits: u64| {
            let units = (triangles as u64).saturating_mul(UNITS_PER_TRIANGLE);
            let units = units.saturating_add(visits / VISITS_PER_UNIT);
            if allows(units) {
                Ok(())
            } else {
                Err(CutShort { work: units })
            }
        };
        let size = [room.size_mm.x, room.size_mm.y];
        let cells = MeshCells::new(&room.meshes, size, footprint, &marking)?;
        let bands = distinct_bands(footprint);
        let found: Vec<Arc<PartObstacles>> = (bands.par_iter())
            .map(|&z_mm| {
                let mut outlines: Vec<Vec<Coord<f64>>> = (room.boxes.iter())
                    .chain(extra)
                    .filter(|b| b.meets_band(z_mm))
                    .map(box_outline)
                    .collect();
                if let Some(cells) = &cells {
                    outlines.extend(cells.rectangles(z_mm));
                }
                Arc::new(PartObstacles::new(outlines))
            })
            .collect();
        let parts = (footprint.parts.iter())
            .map(|part| {
                let k = bands.iter().position(|z| same_band(*z, part.z_mm));
                Arc::clone(&found[k.expect("every part's band is among the distinct bands")])
            })
            .collect();
        let work = match &cells {
            Some(cells) => {
                let triangles: usize = room.meshes.iter().map(|m| m.triangles.len()).sum();
                let marked = (cells.visits() / VISITS_PER_UNIT) as usize;
                let outlines: usize = found.iter().map(|p| p.outlines.len()).sum();
                let looked = cells.len().saturating_mul(found.len()) / CELLS_PER_UNIT;
                [
                    (triangles, UNITS_PER_TRIANGLE),
                    (marked, 1),
                    (outlines, UNITS_PER_OUTLINE),
                    (looked, 1),
                ]
                .iter()
                .fold(0_u64, |w, &(n, units)| {
                    w.saturating_add((n as u64).saturating_mul(units))
                })
            }
            None => 0,
        };
        Ok(FloorObstacles { parts, work })
    }

    /// What building them cost, in units of the meter ([`crate::meter`]):
    /// each mesh triangle marked in the cells it lies over
    /// (`UNITS_PER_TRIANGLE`, and a unit for each row and cell marking
    /// looked at: a long thin triangle across the room crosses many rows
    /// of cells), each cell looked at for each distinct band
    /// of heights (`CELLS_PER_UNIT`), and each outline found and put in a
    /// band's R-tree (`UNITS_PER_OUTLINE`); nothing where the room has no
    /// meshes (a box's outline costs what looking it up does).
    pub fn work(&self) -> u64 {
        self.work
    }

    /// The outlines part `part` meets that overlap the rectangle from `lo`
    /// to `hi`, in the order they were found in the room.
    pub fn near(&self, part: usize, lo: Coord<f64>, hi: Coord<f64>) -> Vec<&[Coord<f64>]> {
        let p = &self.parts[part];
        let envelope = AABB::from_corners([lo.x, lo.y], [hi.x, hi.y]);
        let mut found: Vec<usize> = p
            .tree
            .locate_in_envelope_intersecting(&envelope)
            .map(|e| e.data)
            .collect();
        found.sort_unstable();
        found.iter().map(|&k| p.outlines[k].as_slice()).collect()
    }
}

impl PartObstacles {
    fn new(outlines: Vec<Vec<Coord<f64>>>) -> Self {
        let entries = outlines
            .iter()
            .enumerate()
            .map(|(k, o)| {
                let (lo, hi) = bounds(o);
                GeomWithData::new(Rectangle::from_corners([lo.x, lo.y], [hi.x, hi.y]), k)
            })
            .collect();
        PartObstacles {
            outlines,
            tree: RTree::bulk_load(entries),
        }
    }
}

/// Units of the meter a mesh triangle costs the floor's obstacles, an
/// outline found (a rectangle of cells), and how many cells a band's look
/// costs one. Measured (release, 2 cores) on 200,000 small triangles in a
/// 7 x 7 m room (1,960,000 cells; a wheelchair's 12 parts at 8 distinct
/// heights, 1,140,000 outlines in all): marking 0.31 s, the bands' outlines
/// and R-trees 0.51 s on two cores, about 1.5 us a triangle and 0.9 us an
/// outline of one core's time, counted 37 M units; on a kitchen of boxes
/// with one small mesh (480,000 cells, 8 bands, a few dozen outlines) 6-14
/// ms, about 1.5 ns a cell and band, counted 0.24 M. The solvers do 20,000
/// to 40,000 units a millisecond.
const UNITS_PER_TRIANGLE: u64 = 40;
/// Rows and cells marking looks at for a unit: 20,000 slivers 1 mm thin
/// across a 6 m room's diagonal are 65 M visits, 1.9 s (29 ns each).
const VISITS_PER_UNIT: u64 = 1;
const UNITS_PER_OUTLINE: u64 = 24;
const CELLS_PER_UNIT: usize = 16;

/// The footprint's parts' distinct bands of heights, in the order of the
/// parts.
fn distinct_bands(footprint: &Footprint) -> Vec<[f64; 2]> {
    let mut bands: Vec<[f64; 2]> = Vec::new();
    for part in &footprint.parts {
        if !bands.iter().any(|z| same_band(*z, part.z_mm)) {
            bands.push(part.z_mm);
        }
    }
    bands
}

/// Whether two bands are the same to the bit.
fn same_band(a: [f64; 2], b: [f64; 2]) -> bool {
    a[0].to_bits() == b[0].to_bits() && a[1].to_bits() == b[1].to_bits()
}

/// The least and greatest corner of `points`.
pub fn bounds(points: &[Coord<f64>]) -> (Coord<f64>, Coord<f64>) {
    points.iter().fold(
        (
            Coord {
                x: f64::INFINITY,
                y: f64::INFINITY,
            },
            Coord {
                x: f64::NEG_INFINITY,
                y: f64::NEG_INFINITY,
            },
        ),
        |(lo, hi), c| {
            (
                Coord {
                    x: lo.x.min(c.x),
                    y: lo.y.min(c.y),
                },
                Coord {
                    x: hi.x.max(c.x),
                    y: hi.y.max(c.y),
                },
            )
        },
    )
}

/// A box obstacle's outline on the floor, turned about its corner.
pub(super) fn box_outline(b: &BoxObstacle) -> Vec<Coord<f64>> {
    let (w, d) = (b.size_mm.x, b.size_mm.y);
    [(0.0, 0.0), (w, 0.0), (w, d), (0.0, d)]
        .into_iter()
        .map(|(x, y)| {
            let p = b.floor_point(Vector2::new(x, y));
            Coord { x: p.x, y: p.y }
        })
        .collect()
}
