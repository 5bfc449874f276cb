//! What a mesh blocks on the floor, whatever its shape: a raster of small
//! square cells over the room, each holding the heights at which some
//! triangle lies above it. The heights are the slabs between the ends of a
//! footprint's parts, and the planes between them (a flat face exactly at
//! a part's top or bottom touches it without blocking it, as a box's does).
//! A triangle marks a cell where its piece within a slab, seen from above,
//! overlaps the cell's inside; a vertical one (a wall, a cabinet's front),
//! whose piece is a segment, marks the cells it crosses. So an L-shaped
//! counter blocks an L, not its convex hull, and an open mesh (a scan)
//! blocks as well as a closed one. Triangles lying on the floor (below
//! `FLOOR_TOLERANCE_MM`) are floor and block nothing.
//!
//! For a part, the cells it is blocked by become rectangles (runs along x
//! stacked over rows while they stay the same, then stacked further where
//! a run only a cell in or out of the first covers at most two cells more:
//! a scan's ragged edge), which the region grows by the part like boxes:
//! exact where the mesh follows the cells, conservative by at most two
//! cells elsewhere.

use std::collections::HashMap;

use geo::Coord;
use nalgebra::{Point3, Vector3};

use super::Footprint;
use crate::scene::MeshObstacle;

/// The side of a cell, as long as the room allows (see `MAX_CELLS`).
pub const CELL_MM: f64 = 5.0;
/// Triangles whose every corner is this low lie on the floor: a scan's
/// floor, a mat, a threshold a wheelchair rolls over (ADA 2010 303.3: a
/// change in level of up to 1/2 inch is bevelled, not a step).
pub const FLOOR_TOLERANCE_MM: f64 = 13.0;
/// At most this many cells over the room (16 MiB of masks); a larger room
/// gets larger cells.
const MAX_CELLS: f64 = 2_097_152.0;
/// Slab boundaries kept at most: 32 slabs and 31 planes between them fit in
/// a 64-bit mask.
const MAX_BOUNDS: usize = 33;

/// The room's meshes, as cells over its floor, for one footprint's parts.
#[derive(Clone, Debug)]
pub struct MeshCells {
    cell_mm: f64,
    nx: usize,
    ny: usize,
    /// Slab boundaries, rising.
    bounds_mm: Vec<f64>,
    /// Per cell, row by row: bit `2k` for slab `k`, bit `2k - 1` for the
    /// plane `bounds_mm[k]` between slabs `k - 1` and `k`.
    masks: Vec<u64>,
    /// The rows and cells marking the triangles looked at (what it cost).
    visits: u64,
}

/// How many triangles are marked between two asks whether marking may go
/// on ([`MeshCells::new`]): a thin one across a room visits a few thousand
/// rows and cells, so 64 of them take a few milliseconds.
const TRIANGLES_BETWEEN_ASKS: usize = 64;

impl MeshCells {
    /// The cells of `meshes` over a floor of `size_mm` for the parts of
    /// `footprint`; none when there are no meshes. Every
    /// [`TRIANGLES_BETWEEN_ASKS`] triangles, `go_on` is asked whether
    /// marking may go on, given the triangles marked and the rows and
    /// cells visited so far; where it says no, marking stops with its
    /// answer.
    pub fn new<E>(
        meshes: &[MeshObstacle],
        size_mm: [f64; 2],
        footprint: &Footprint,
        go_on: &dyn Fn(usize, u64) -> Result<(), E>,
    ) -> Result<Option<Self>, E> {
        if meshes.is_empty() || footprint.parts.is_empty() {
            return Ok(None);
        }
        let (cell_mm, nx, ny) = grid(size_mm);
        let mut cells = MeshCells {
            cell_mm,
            nx,
            ny,
            bounds_mm: slab_bounds(footprint),
            masks: vec![0; nx * ny],
            visits: 0,
        };
        let mut crossings: Vec<Crossing> = Vec::new();
        let mut marked = 0_usize;
        for m in meshes {
            for t in &m.triangles {
                marked += 1;
                if marked.is_multiple_of(TRIANGLES_BETWEEN_ASKS) {
                    go_on(marked, cells.visits)?;
                }
                let v = t.map(|i| m.vertices_mm[i as usize]);
                if v.iter().all(|p| p.z <= FLOOR_TOLERANCE_MM) {
                    continue;
                }
                let normal = (v[1] - v[0]).cross(&(v[2] - v[0]));
                let vertical = normal.z.abs() <= 1e-9 * normal.norm();
                cells.mark_triangle(&v, &normal, vertical);
                if !vertical {
                    cells.cross_centres(&v, normal.z > 0.0, &mut crossings);
                }
            }
        }
        cells.fill_solids(crossings);
        Ok(Some(cells))
    }

    /// How many cells it has.
    pub fn len(&self) -> usize {
        self.masks.len()
    }

    /// How many rows and cells marking the triangles looked at, each
    /// triangle in each slab it crosses and at the cell centres under it.
    pub fn visits(&self) -> u64 {
        self.visits
    }

    /// Where triangle `v`, not vertical, passes over cell centres: the
    /// height there, and whether it faces up (`up`). Row by row, only the
    /// centres within the triangle's cross-section at the row's sample
    /// line are tried (widened by `CROSS_SECTION_MARGIN_MM`, each tried
    /// exactly as before): a long thin triangle across the room tries its
    /// rows and the few centres under it, not every cell of its bounds.
    fn cross_centres(&mut self, v: &[Point3<f64>; 3], up: bool, out: &mut Vec<Crossing>) {
        let c = self.cell_mm;
        let (x_lo, x_hi) = min_max(v.iter().map(|p| p.x));
        let (y_lo, y_hi) = min_max(v.iter().map(|p| p.y));
        let first = |lo: f64| (lo / c - SAMPLE.0).ceil().max(0.0) as usize;
        let last = |hi: f64, n: usize| ((hi / c - SAMPLE.0).floor()).min(n as f64 - 1.0);
        let (i1, j1) = (last(x_hi, self.nx), last(y_hi, self.ny));
        if i1 < 0.0 || j1 < 0.0 {
            return;
        }
        let seen = project(v);
        for j in first(y_lo)..=j1 as usize {
            let y = (j as f64 + SAMPLE.1) * c;
            self.visits += 1;
            let Some((row_lo, row_hi)) = x_range_in_band(&seen, y, y) else {
                continue;
            };
            let (row_lo, row_hi) = (
                row_lo - CROSS_SECTION_MARGIN_MM,
                row_hi + CROSS_SECTION_MARGIN_MM,
            );
            let row_last = last(row_hi.min(x_hi), self.nx).min(i1);
            if row_last < 0.0 {
                continue;
            }
            for i in first(row_lo.max(x_lo))..=row_last as usize {
                self.visits += 1;
                // Off the centre by a hair no round coordinate shares, so
                // that an edge between two faces never passes through it
                // (which would count it twice).
                let x = (i as f64 + SAMPLE.0) * c;
                // The plane's height at (x, y), if (x, y) is in the triangle.
                if let Some(z_mm) = height_in(v, x, y) {
                    out.push(Crossing {
                        cell: (j * self.nx + i) as u32,
                        z_mm,
                        up,
                    });
                }
            }
        }
    }

    /// Marks the solid below each face that faces up, down to the face
    /// that faces down below it (the bottom of a closed mesh, the underside
    /// of a worktop over knee space) or to the floor (a scan's counter,
    /// which has no bottom): going down a column, a face up enters a solid
    /// and a face down leaves one, so solids that overlap stay filled.
    fn fill_solids(&mut self, mut crossings: Vec<Crossing>) {
        crossings.sort_unstable_by(|a, b| {
            (a.cell.cmp(&b.cell))
                .then(b.z_mm.total_cmp(&a.z_mm))
                .then(b.up.cmp(&a.up))
        });
        for column in crossings.chunk_by(|a, b| a.cell == b.cell) {
            let mut depth = 0_u32;
            let mut top_mm = f64::INFINITY;
            let mut mask = 0;
            for x in column {
                if x.up {
                    if depth == 0 {
                        top_mm = x.z_mm;
                    }
                    depth += 1;
                } else if depth > 0 {
                    depth -= 1;
                    if depth == 0 {
                        mask |= self.interval_mask([x.z_mm, top_mm]);
                    }
                }
            }
            if depth > 0 {
                mask |= self.interval_mask([f64::NEG_INFINITY, top_mm]);
            }
            self.masks[column[0].cell as usize] |= mask;
        }
    }

    /// The bits of the slabs and planes a solid spanning `z_mm` fills.
    fn interval_mask(&self, z_mm: [f64; 2]) -> u64 {
        if z_mm[0] < z_mm[1] {
            self.part_mask(z_mm)
        } else {
            0
        }
    }

    /// The bits of the slabs and planes a part spanning `z_mm` meets.
    fn part_mask(&self, [z0, z1]: [f64; 2]) -> u64 {
        let b = &self.bounds_mm;
        let mut mask = 0;
        for k in 0..b.len().saturating_sub(1) {
            if b[k] < z1 && z0 < b[k + 1] {
                mask |= 1 << (2 * k);
            }
            if k > 0 && z0 < b[k] && b[k] < z1 {
                mask |= 1 << (2 * k - 1);
            }
        }
        mask
    }

    /// Marks the cells under each piece of triangle `v` (of `normal`,
    /// `vertical` or not) in a slab.
    fn mark_triangle(&mut self, v: &[Point3<f64>; 3], normal: &Vector3<f64>, vertical: bool) {
        let (lo, hi) = min_max(v.iter().map(|p| p.z));
        // A vertical face, seen from above a segment, is moved 0.01 mm
        // behind itself (against its normal, towards the solid it bounds):
        // one on a cell's edge then marks the cell behind it, which the
        // solid's top already marks, not the free cell in front.
        let across = normal.xy().norm();
        let behind = (vertical && across > 0.0).then(|| {
            let step = -normal.xy() / across * (self.cell_mm * 2.0 * SNAP_CELLS);
            Coord {
                x: step.x,
                y: step.y,
            }
        });
        for k in 0..self.bounds_mm.len().saturating_sub(1) {
            let (s0, s1) = (self.bounds_mm[k], self.bounds_mm[k + 1]);
            if lo == hi {
                if s0 < lo && lo < s1 {
                    self.mark_piece(&project(v), 1 << (2 * k));
                } else if k > 0 && lo == s0 {
                    self.mark_piece(&project(v), 1 << (2 * k - 1));
                }
            } else if lo < s1 && s0 < hi {
                let mut piece = clip_to_slab(v, s0, s1);
                if let Some(behind) = behind {
                    for p in &mut piece {
                        *p = *p + behind;
                    }
                }
                if !piece.is_empty() {
                    self.mark_piece(&piece, 1 << (2 * k));
                }
            }
        }
    }

    /// Marks with `bit` the cells whose inside the convex polygon `piece`
    /// overlaps (the cells it crosses, when it is a segment or a point).
    fn mark_piece(&mut self, piece: &[Coord<f64>], bit: u64) {
        let c = self.cell_mm;
        let (y_lo, y_hi) = min_max(piece.iter().map(|p| p.y));
        let Some((j0, j1)) = span(y_lo / c, y_hi / c, self.ny) else {
            return;
        };
        for j in j0..=j1 {
            let (band0, band1) = (j as f64 * c, (j + 1) as f64 * c);
            let Some((x_lo, x_hi)) = x_range_in_band(piece, band0.max(y_lo), band1.min(y_hi))
            else {
                continue;
            };
            let Some((i0, i1)) = span(x_lo / c, x_hi / c, self.nx) else {
                continue;
            };
            let row = &mut self.masks[j * self.nx..(j + 1) * self.nx];
            self.visits += 1 + (i1 - i0 + 1) as u64;
            for m in &mut row[i0..=i1] {
                *m |= bit;
            }
        }
    }

    /// The rectangles of cells that block a part spanning `z_mm`, as
    /// outlines on the floor: the runs of each row stacked while they stay
    /// the same, then those stacked further where that covers at most
    /// `MAX_ADDED_CELLS` cells more (a scan's ragged edge).
    pub fn rectangles(&self, z_mm: [f64; 2]) -> Vec<Vec<Coord<f64>>> {
        let mask = self.part_mask(z_mm);
        if mask == 0 {
            return Vec::new();
        }
        let exact = self.exact_rectangles(mask);
        let merged = merge_ragged(exact);
        merged.iter().map(|r| r.outline(self.cell_mm)).collect()
    }

    /// The cells meeting `mask` as rectangles, each a run of cells the
    /// same in consecutive rows; by first row, then first cell.
    fn exact_rectangles(&self, mask: u64) -> Vec<Rectangle> {
        let mut done: Vec<Rectangle> = Vec::new();
        let mut open: Vec<Rectangle> = Vec::new();
        for j in 0..self.ny {
            let row = &self.masks[j * self.nx..(j + 1) * self.nx];
            let mut next: Vec<Rectangle> = Vec::new();
            // The previous row's rectangles, like its runs, by first cell.
            let mut above = open.into_iter().peekable();
            for (i0, i1) in runs(row, mask) {
                while let Some(ended) = above.next_if(|r| r.x[0] < i0) {
                    done.push(ended);
                }
                match above.next_if(|r| r.x == [i0, i1]) {
                    Some(mut r) => {
                        r.y[1] = j;
                        r.cells += i1 - i0 + 1;
                        next.push(r);
                    }
                    None => next.push(Rectangle::new([i0, i1], j)),
                }
            }
            done.extend(above);
            open = next;
        }
        done.append(&mut open);
        done.sort_by_key(|r| (r.y[0], r.x[0]));
        done
    }
}

/// The side of a floor's cells and how many there are along x and y.
fn grid(size_mm: [f64; 2]) -> (f64, usize, usize) {
    let cell_mm = CELL_MM.max((size_mm[0] * size_mm[1] / MAX_CELLS).sqrt());
    let nx = ((size_mm[0] / cell_mm).ceil() as usize).max(1);
    let ny = ((size_mm[1] / cell_mm).ceil() as usize).max(1);
    (cell_mm, nx, ny)
}

/// Cells a merge of two rectangles may cover that neither does.
const MAX_ADDED_CELLS: usize = 2;

/// `exact` (by first row) with each stacked on the one just below it
/// where their ends are within a cell of where that began and the
/// rectangle round both covers at most `MAX_ADDED_CELLS` cells more: a
/// ragged edge, a cell in or out from row to row, becomes one rectangle,
/// while an edge that moves for good (where two boxes meet) stays exact.
fn merge_ragged(exact: Vec<Rectangle>) -> Vec<Rectangle> {
    let mut done: Vec<Rectangle> = Vec::new();
    let mut open: Vec<Rectangle> = Vec::new();
    // Where `exact`'s current row begins, and the open rectangles ending
    // in the row below it by their first cell (their places in `open`,
    // rising: a row's stacking neither removes nor reorders any).
    let mut row = None;
    let mut below: HashMap<usize, Vec<usize>> = HashMap::new();
    for e in exact {
        if row != Some(e.y[0]) {
            row = Some(e.y[0]);
            let (ended, still): (Vec<Rectangle>, Vec<Rectangle>) =
                open.into_iter().partition(|r| r.y[1] + 1 < e.y[0]);
            done.extend(ended);
            open = still;
            below.clear();
            for (k, r) in open.iter().enumerate() {
                if r.y[1] + 1 == e.y[0] {
                    below.entry(r.first[0]).or_default().push(k);
                }
            }
        }
        // `takes` asks for a first cell within one of e's.
        let mut near: Vec<usize> = (e.x[0].saturating_sub(1)..=e.x[0] + 1)
            .filter_map(|x| below.get(&x))
            .flatten()
            .copied()
            .collect();
        near.sort_unstable();
        let joins = |&k: &usize| open[k].y[1] + 1 == e.y[0] && open[k].takes(&e);
        match near.into_iter().find(joins) {
            Some(k) => open[k].stack(&e),
            None => open.push(e),
        }
    }
    done.extend(open);
    done.sort_by_key(|r| (r.y[0], r.x[0]));
    done
}
/// How far beyond a triangle's cross-section at a row's sample line a
/// cell centre is still tried (the exact test decides): far more than
/// the rounding of either.
const CROSS_SECTION_MARGIN_MM: f64 = 0.01;

/// Where in a cell (in cells from its corner) faces are sampled.
const SAMPLE: (f64, f64) = (0.500_000_314_159, 0.500_000_271_828);

/// A face passing over a cell's centre.
struct Crossing {
    cell: u32,
    z_mm: f64,
    up: bool,
}

/// The height of triangle `v`'s plane at `(x, y)`, if `(x, y)` is in the
/// triangle seen from above (its edges included).
fn height_in(v: &[Point3<f64>; 3], x: f64, y: f64) -> Option<f64> {
    let (a, b, c) = (v[0], v[1], v[2]);
    let d = (b.y - c.y) * (a.x - c.x) + (c.x - b.x) * (a.y - c.y);
    let l0 = ((b.y - c.y) * (x - c.x) + (c.x - b.x) * (y - c.y)) / d;
    let l1 = ((c.y - a.y) * (x - c.x) + (a.x - c.x) * (y - c.y)) / d;
    let l2 = 1.0 - l0 - l1;
    // Within the corners' heights, so that a flat face's height is exact.
    let (lo, hi) = min_max([a.z, b.z, c.z].into_iter());
    (l0 >= 0.0 && l1 >= 0.0 && l2 >= 0.0).then(|| (l0 * a.z + l1 * b.z + l2 * c.z).clamp(lo, hi))
}

/// Cells `[x0, x1]` over rows `[y0, y1]`, inclusive; `first` is the run it
/// began with, `cells` how many of its cells are blocked.
#[derive(Debug, PartialEq)]
struct Rectangle {
    first: [usize; 2],
    x: [usize; 2],
    y: [usize; 2],
    cells: usize,
}

impl Rectangle {
    /// The run `x` in row `j`.
    fn new(x: [usize; 2], j: usize) -> Self {
        Rectangle {
            first: x,
            x,
            y: [j, j],
            cells: x[1] - x[0] + 1,
        }
    }

    /// The cells of its outline.
    fn area(&self) -> usize {
        (self.x[1] - self.x[0] + 1) * (self.y[1] - self.y[0] + 1)
    }

    /// The rectangle round it and `e`, the rows just below it.
    fn round(&self, e: &Rectangle) -> Rectangle {
        Rectangle {
            first: self.first,
            x: [self.x[0].min(e.x[0]), self.x[1].max(e.x[1])],
            y: [self.y[0], e.y[1]],
            cells: self.cells + e.cells,
        }
    }

    /// Whether `e`, the rows just below, may be stacked on it: its ends
    /// are within a cell of the run it began with, and the rectangle round
    /// both covers at most `MAX_ADDED_CELLS` cells neither is blocked at.
    fn takes(&self, e: &Rectangle) -> bool {
        let near = e.x[0].abs_diff(self.first[0]) <= 1 && e.x[1].abs_diff(self.first[1]) <= 1;
        let round = self.round(e);
        near && round.area() - round.cells <= self.area() - self.cells + MAX_ADDED_CELLS
    }

    /// `e` stacked on it.
    fn stack(&mut self, e: &Rectangle) {
        *self = self.round(e);
    }

    fn outline(&self, cell_mm: f64) -> Vec<Coord<f64>> {
        let (x0, x1) = (self.x[0] as f64 * cell_mm, (self.x[1] + 1) as f64 * cell_mm);
        let (y0, y1) = (self.y[0] as f64 * cell_mm, (self.y[1] + 1) as f64 * cell_mm);
        vec![
            Coord { x: x0, y: y0 },
            Coord { x: x1, y: y0 },
            Coord { x: x1, y: y1 },
            Coord { x: x0, y: y1 },
        ]
    }
}

/// The runs of cells in `row` that meet `mask`, as inclusive index pairs.
fn runs(row: &[u64], mask: u64) -> Vec<(usize, usize)> {
    let mut out = Vec::new();
    let mut start = None;
    for (i, m) in row.iter().enumerate() {
        match (m & mask != 0, start) {
            (true, None) => start = Some(i),
            (false, Some(s)) => {
                out.push((s, i - 1));
                start = None;
            }
            _ => {}
        }
    }
    if let Some(s) = start {
        out.push((s, row.len() - 1));
    }
    out
}

/// The cell boundaries of the slabs: the ends of every part, rising, at
/// most `MAX_BOUNDS` of them (every other one dropped until they fit, which
/// only widens slabs: conservative).
fn slab_bounds(footprint: &Footprint) -> Vec<f64> {
    let mut b: Vec<f64> = footprint.parts.iter().flat_map(|p| p.z_mm).collect();
    b.sort_by(f64::total_cmp);
    b.dedup();
    while b.len() > MAX_BOUNDS {
        let last = b[b.len() - 1];
        b = b.iter().copied().step_by(2).collect();
        if b.last() != Some(&last) {
            b.push(last);
        }
    }
    b
}

/// How far (in cells) within a cell's edge a coordinate counts as on it: a
/// mesh in metres read as 32-bit floats puts 0.6 m at 600.00002 mm.
const SNAP_CELLS: f64 = 1e-3;

/// The cells `[a, b]` (in cell units) overlap inside, clamped to `0..n`:
/// those whose inside they overlap, or the one they touch when they have
/// no length. None when all are outside.
fn span(a: f64, b: f64, n: usize) -> Option<(usize, usize)> {
    if b < 0.0 || a > n as f64 {
        return None;
    }
    let first = (a + SNAP_CELLS).floor().max(0.0);
    let last = ((b - SNAP_CELLS).ceil() - 1.0)
        .max(first)
        .min(n as f64 - 1.0);
    (first <= last).then_some((first as usize, last as usize))
}

fn min_max(values: impl Iterator<Item = f64>) -> (f64, f64) {
    values.fold((f64::INFINITY, f64::NEG_INFINITY), |(a, b), v| {
        (a.min(v), b.max(v))
    })
}

/// The x extent of convex polygon `piece` between heights `y0 <= y1` on
/// the floor (its vertices there and its edges' crossings of them).
fn x_range_in_band(piece: &[Coord<f64>], y0: f64, y1: f64) -> Option<(f64, f64)> {
    let mut xs: Vec<f64> = Vec::new();
    for (k, a) in piece.iter().enumerate() {
        if (y0..=y1).contains(&a.y) {
            xs.push(a.x);
        }
        let b = piece[(k + 1) % piece.len()];
        for y in [y0, y1] {
            if (a.y < y) != (b.y < y) && a.y != b.y {
                xs.push(a.x + (y - a.y) / (b.y - a.y) * (b.x - a.x));
            }
        }
    }
    (!xs.is_empty()).then(|| min_max(xs.into_iter()))
}

/// The triangle's corners seen from above.
fn project(v: &[Point3<f64>; 3]) -> Vec<Coord<f64>> {
    v.iter().map(|p| Coord { x: p.x, y: p.y }).collect()
}

/// The part of triangle `v` between heights `z0` and `z1`, seen from above
/// (a convex polygon; a segment for a vertical triangle).
fn clip_to_slab(v: &[Point3<f64>; 3], z0: f64, z1: f64) -> Vec<Coord<f64>> {
    let mut points: Vec<Point3<f64>> = v.to_vec();
    for (at, keep_above) in [(z0, true), (z1, false)] {
        let keeps = |p: &Point3<f64>| if keep_above { p.z >= at } else { p.z <= at };
        let mut next = Vec::with_capacity(points.len() + 2);
        for (k, a) in points.iter().enumerate() {
            let b = &points[(k + 1) % points.len()];
            if keeps(a) {
                next.push(*a);
            }
            if keeps(a) != keeps(b) {
                let t = (at - a.z) / (b.z - a.z);
                next.push(a + (b - a) * t);
            }
        }
        points = next;
        if points.is_empty() {
            return Vec::new();
        }
    }
    points.iter().map(|p| Coord { x: p.x, y: p.y }).collect()
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The cells, however long marking them takes.
    fn all_cells(meshes: &[MeshObstacle], size_mm: [f64; 2], f: &Footprint) -> MeshCells {
        let go_on = |_: usize, _: u64| Ok::<(), ()>(());
        MeshCells::new(meshes, size_mm, f, &go_on).unwrap().unwrap()
    }
    use geo::{Area, BooleanOps, LineString, MultiPolygon, Polygon};

    fn mesh(quads: &[[[f64; 3]; 4]]) -> MeshObstacle {
        let mut vertices = Vec::new();
        let mut triangles = Vec::new();
        for q in quads {
            let base = vertices.len() as u32;
            vertices.extend(q.iter().map(|p| Point3::new(p[0], p[1], p[2])));
            triangles.push([base, base + 1, base + 2]);
            triangles.push([base, base + 2, base + 3]);
        }
        MeshObstacle::new("m".into(), vertices, &triangles)
    }

    #[test]
    fn marking_stops_once_told_to_and_is_asked_as_it_goes() {
        // 1,000 thin triangles across a 6 m room, 1 m up: thousands of rows
        // and cells each.
        let mut vertices = Vec::new();
        let mut triangles = Vec::new();
        for k in 0..1000_u32 {
            let y = 10.0 + 5.0 * f64::from(k);
            vertices.extend([
                Point3::new(10.0, y, 1000.0),
                Point3::new(5990.0, y + 700.0, 1000.0),
                Point3::new(5990.0, y + 701.0, 1000.0),
            ]);
            triangles.push([3 * k, 3 * k + 1, 3 * k + 2]);
        }
        let slivers = MeshObstacle::new("slivers".into(), vertices, &triangles);
        let f = Footprint::circle(300.0, 1400.0);
        let whole = all_cells(std::slice::from_ref(&slivers), [6000.0, 6000.0], &f);
        let asked = std::cell::Cell::new(0_usize);
        let until = |marked: usize, visits: u64| {
            asked.set(asked.get() + 1);
            if visits > whole.visits() / 4 {
                Err(marked)
            } else {
                Ok(())
            }
        };
        let stopped = MeshCells::new(&[slivers], [6000.0, 6000.0], &f, &until);
        let marked = stopped.expect_err("marking stops once told to");
        assert!(marked < 500, "stopped after {marked} of 1,000 triangles");
        assert_eq!(asked.get(), marked / TRIANGLES_BETWEEN_ASKS);
    }

    fn top(x0: f64, y0: f64, x1: f64, y1: f64, z: f64) -> [[f64; 3]; 4] {
        [[x0, y0, z], [x1, y0, z], [x1, y1, z], [x0, y1, z]]
    }

    fn area(outlines: &[Vec<Coord<f64>>]) -> f64 {
        let polygons: Vec<Polygon<f64>> = outlines
            .iter()
            .map(|o| Polygon::new(LineString::from(o.clone()), vec![]))
            .collect();
        geo::unary_union(&polygons)
            .union(&MultiPolygon::new(vec![]))
            .unsigned_area()
    }

    #[test]
    fn an_l_shaped_top_blocks_an_l_not_its_hull() {
        // Two counter tops 600 mm deep along two walls, at 900 mm.
        let m = mesh(&[
            top(0.0, 0.0, 3000.0, 600.0, 900.0),
            top(0.0, 600.0, 600.0, 2000.0, 900.0),
        ]);
        let mut f = Footprint::circle(300.0, 1400.0);
        for z_mm in [[0.0, 900.0], [900.0, 1400.0]] {
            let mut part = f.parts[0].clone();
            part.z_mm = z_mm;
            f.parts.push(part);
        }
        let cells = all_cells(&[m], [4000.0, 3000.0], &f);
        let blocked = area(&cells.rectangles([0.0, 1400.0]));
        let l = 3000.0 * 600.0 + 600.0 * 1400.0;
        assert!((blocked - l).abs() < 1.0, "{blocked} against {l}");
        // A part above the top is not blocked; one below it is (a top
        // with nothing under it is a scan's counter, solid to the floor).
        assert!(cells.rectangles([900.0, 1400.0]).is_empty());
        assert!((area(&cells.rectangles([0.0, 900.0])) - l).abs() < 1.0);
    }

    #[test]
    fn a_wall_marks_the_cells_it_stands_on_and_the_floor_marks_none() {
        let wall = [
            [1000.0, 0.0, 0.0],
            [1000.0, 2000.0, 0.0],
            [1000.0, 2000.0, 2000.0],
            [1000.0, 0.0, 2000.0],
        ];
        let floor = top(0.0, 0.0, 4000.0, 3000.0, 8.0);
        let f = Footprint::circle(300.0, 1400.0);
        let cells = all_cells(&[mesh(&[wall, floor])], [4000.0, 3000.0], &f);
        let rects = cells.rectangles([0.0, 1400.0]);
        let blocked = area(&rects);
        assert!((blocked - 2000.0 * CELL_MM).abs() < 1.0, "{blocked}");
    }

    #[test]
    fn a_sloping_triangle_blocks_only_where_it_is_within_the_heights() {
        // A wedge's top rising from 0 at x = 0 to 1000 mm at x = 1000 mm:
        // above 500 mm it lies over x > 500; below 500 mm the wedge fills
        // all of it.
        let ramp = [
            [0.0, 0.0, 0.0],
            [1000.0, 0.0, 1000.0],
            [1000.0, 1000.0, 1000.0],
            [0.0, 1000.0, 0.0],
        ];
        let mut f = Footprint::circle(300.0, 500.0);
        f.parts
            .push(Footprint::circle(300.0, 1400.0).parts.remove(0));
        f.parts[1].z_mm = [500.0, 1400.0];
        let cells = all_cells(&[mesh(&[ramp])], [4000.0, 3000.0], &f);
        let low = area(&cells.rectangles([0.0, 500.0]));
        assert!((low - 1000.0 * 1000.0).abs() < 1.0, "{low}");
        let high = area(&cells.rectangles([500.0, 1400.0]));
        assert!((high - 500.0 * 1000.0).abs() < 1.0, "{high}");
    }

    #[test]
    fn two_tops_that_meet_in_one_row_block_their_cells_not_a_cell_more() {
        // A counter whose end overlaps a narrower one's by a row of cells,
        // and one cell further out: the rows past the overlap stay exact.
        let quads = [
            top(1420.0, 1600.0, 2175.0, 2180.0, 20.0),
            top(1415.0, 735.0, 1465.0, 1605.0, 20.0),
        ];
        let f = Footprint::circle(250.0, 300.0);
        let cells = all_cells(&[mesh(&quads)], [4000.0, 3200.0], &f);
        let rects = cells.rectangles([0.0, 300.0]);
        let union = 755.0 * 580.0 + 50.0 * 870.0 - 45.0 * 5.0;
        assert!((area(&rects) - union).abs() < 1.0, "{}", area(&rects));
    }

    #[test]
    fn a_row_of_noisy_runs_merges_into_one_rectangle_a_cell_wider() {
        let mut quads = Vec::new();
        for j in 0..40 {
            let wobble = if j % 2 == 0 { 0.0 } else { CELL_MM };
            let y = j as f64 * CELL_MM;
            quads.push(top(0.0, y, 600.0 + wobble, y + CELL_MM, 900.0));
        }
        let f = Footprint::circle(300.0, 1400.0);
        let cells = all_cells(&[mesh(&quads)], [4000.0, 3000.0], &f);
        let rects = cells.rectangles([0.0, 1400.0]);
        assert_eq!(rects.len(), 1);
        assert_eq!(rects[0][2], Coord { x: 605.0, y: 200.0 });
    }
}

/// The rectangles as first written (each run matched by a scan of the row
/// above, every open rectangle looked at for each one stacked): quadratic
/// in a row's runs, which a cluttered scan has thousands of, and kept here
/// as the reference the sweeps must agree with rectangle for rectangle.
#[cfg(test)]
mod reference {
    use super::{runs, MeshCells, Rectangle};

    pub fn exact_rectangles(cells: &MeshCells, mask: u64) -> Vec<Rectangle> {
        let mut done: Vec<Rectangle> = Vec::new();
        let mut open: Vec<Rectangle> = Vec::new();
        for j in 0..cells.ny {
            let row = &cells.masks[j * cells.nx..(j + 1) * cells.nx];
            let mut next: Vec<Rectangle> = Vec::new();
            for (i0, i1) in runs(row, mask) {
                match open.iter().position(|r| r.x == [i0, i1]) {
                    Some(k) => {
                        let mut r = open.swap_remove(k);
                        r.y[1] = j;
                        r.cells += i1 - i0 + 1;
                        next.push(r);
                    }
                    None => next.push(Rectangle::new([i0, i1], j)),
                }
            }
            done.append(&mut open);
            open = next;
        }
        done.append(&mut open);
        done.sort_by_key(|r| (r.y[0], r.x[0]));
        done
    }

    pub fn merge_ragged(exact: Vec<Rectangle>) -> Vec<Rectangle> {
        let mut done: Vec<Rectangle> = Vec::new();
        let mut open: Vec<Rectangle> = Vec::new();
        for e in exact {
            let (ended, still): (Vec<Rectangle>, Vec<Rectangle>) =
                open.into_iter().partition(|r| r.y[1] + 1 < e.y[0]);
            done.extend(ended);
            open = still;
            let joins = |r: &Rectangle| r.y[1] + 1 == e.y[0] && r.takes(&e);
            match open.iter().position(joins) {
                Some(k) => open[k].stack(&e),
                None => open.push(e),
            }
        }
        done.extend(open);
        done.sort_by_key(|r| (r.y[0], r.x[0]));
        done
    }
}

#[cfg(test)]
mod sweeps {
    use super::*;
    use proptest::prelude::*;

    fn cells(nx: usize, ny: usize, masks: Vec<u64>) -> MeshCells {
        MeshCells {
            cell_mm: CELL_MM,
            nx,
            ny,
            bounds_mm: vec![0.0, 100.0],
            masks,
            visits: 0,
        }
    }

    /// The centres `cross_centres` finds, tried over every cell of the
    /// triangle's bounds (as first written).
    fn crossings_over_bounds(cells: &MeshCells, v: &[Point3<f64>; 3]) -> Vec<(u32, u64)> {
        let c = cells.cell_mm;
        let (x_lo, x_hi) = min_max(v.iter().map(|p| p.x));
        let (y_lo, y_hi) = min_max(v.iter().map(|p| p.y));
        let first = |lo: f64| (lo / c - SAMPLE.0).ceil().max(0.0) as usize;
        let last = |hi: f64, n: usize| ((hi / c - SAMPLE.0).floor()).min(n as f64 - 1.0);
        let (i1, j1) = (last(x_hi, cells.nx), last(y_hi, cells.ny));
        let mut out = Vec::new();
        if i1 < 0.0 || j1 < 0.0 {
            return out;
        }
        for j in first(y_lo)..=j1 as usize {
            for i in first(x_lo)..=i1 as usize {
                let (x, y) = ((i as f64 + SAMPLE.0) * c, (j as f64 + SAMPLE.1) * c);
                if let Some(z) = height_in(v, x, y) {
                    out.push(((j * cells.nx + i) as u32, z.to_bits()));
                }
            }
        }
        out
    }

    proptest! {
        /// Triangles of every shape over a small floor (long thin slivers,
        /// nearly on edge, corners off the floor) cross the same cell
        /// centres at the same heights as a search of their whole bounds.
        #[test]
        fn a_triangle_crosses_the_centres_a_search_of_its_bounds_finds(
            corners in proptest::array::uniform3((-20.0..220.0f64, -20.0..220.0f64, 0.0..100.0f64)),
            thin in 0.0..1.0f64,
        ) {
            let mut v = corners.map(|(x, y, z)| Point3::new(x, y, z));
            // Pull the third corner towards the first edge: slivers.
            v[2] = v[0] + (v[1] - v[0]) * 0.5 + (v[2] - v[0] - (v[1] - v[0]) * 0.5) * (1.0 - thin).powi(8);
            let mut grid = cells(40, 40, vec![0; 1600]);
            let mut found = Vec::new();
            grid.cross_centres(&v, true, &mut found);
            let found: Vec<(u32, u64)> = found.iter().map(|x| (x.cell, x.z_mm.to_bits())).collect();
            prop_assert_eq!(found, crossings_over_bounds(&grid, &v));
        }

        /// Ragged, noisy rasters (each cell blocked with the odds given,
        /// rows often repeating the one below) give the same rectangles,
        /// exact and merged, as the reference.
        #[test]
        fn the_sweeps_give_the_rectangles_the_reference_gives(
            nx in 1usize..40,
            rows in proptest::collection::vec((proptest::collection::vec(0u8..4, 40), any::<bool>()), 1..40),
        ) {
            let mut masks: Vec<u64> = Vec::new();
            for (j, (row, repeat)) in rows.iter().enumerate() {
                if *repeat && j > 0 {
                    let above = masks[(j - 1) * nx..j * nx].to_vec();
                    masks.extend(above);
                } else {
                    masks.extend(row[..nx].iter().map(|&b| u64::from(b == 0) | (u64::from(b == 1) << 2)));
                }
            }
            let cells = cells(nx, rows.len(), masks);
            for mask in [1, 4, 5] {
                let exact = cells.exact_rectangles(mask);
                let expected = reference::exact_rectangles(&cells, mask);
                prop_assert_eq!(&exact, &expected);
                prop_assert_eq!(merge_ragged(exact), reference::merge_ragged(expected));
            }
        }
    }
}
