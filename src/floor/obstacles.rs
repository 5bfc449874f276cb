//! The room's obstacles as one footprint's parts meet them on the floor:
//! for each part, the convex outlines of the boxes whose heights it shares
//! and of the cells its meshes block at those heights (`mesh_cells.rs`),
//! each in an R-tree by its bounding rectangle, so that a piece of floor
//! asks only for the obstacles near it. Built once per room and base, for
//! every heading: outlines do not turn with the base.

use geo::Coord;
use nalgebra::Vector2;
use rstar::primitives::{GeomWithData, Rectangle};
use rstar::{RTree, AABB};

use super::mesh_cells::MeshCells;
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
    parts: Vec<PartObstacles>,
}

impl FloorObstacles {
    pub fn new(room: &Room, footprint: &Footprint) -> Self {
        Self::with(room, footprint, &[])
    }

    /// The room's obstacles and `extra` boxes (the walls round a room's
    /// doorways, where a route search lets a base come in from outside).
    pub fn with(room: &Room, footprint: &Footprint, extra: &[BoxObstacle]) -> Self {
        let cells = MeshCells::new(&room.meshes, [room.size_mm.x, room.size_mm.y], footprint);
        let parts = footprint
            .parts
            .iter()
            .map(|part| {
                let mut outlines: Vec<Vec<Coord<f64>>> = room
                    .boxes
                    .iter()
                    .chain(extra)
                    .filter(|b| b.meets_band(part.z_mm))
                    .map(box_outline)
                    .collect();
                if let Some(cells) = &cells {
                    outlines.extend(cells.rectangles(part.z_mm));
                }
                PartObstacles::new(outlines)
            })
            .collect();
        FloorObstacles { parts }
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
