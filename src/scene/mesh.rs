//! A mesh obstacle: its triangles in the room, cleaned when it is made,
//! and parry's shape of it (with its bounding volume tree), built once when
//! collisions are first checked and shared by every task after. A mesh
//! that is only a surface (a scan) is held as parts of at most
//! [`PART_TRIANGLES`] triangles near each other, each with its own tree:
//! a capsule meets the surface where it meets a part, and a ray's first
//! hit is the first of the parts', so the answers are the whole mesh's,
//! while building the trees never holds more than one part's scratch
//! space (parry's tree takes about 320 bytes a triangle while it is
//! built, 150 after). A closed mesh stays whole: whether a point is
//! inside it is a question about the whole.

use std::sync::{Arc, OnceLock};

use nalgebra::Point3;
use parry3d_f64::shape::{SharedShape, TriMeshFlags};

use crate::geometry::cleaned_triangles;

/// A triangle mesh obstacle, its vertices in the room: only triangles with
/// an area, closed pieces wound outwards ([`cleaned_triangles`]).
#[derive(Clone, Debug, PartialEq)]
pub struct MeshObstacle {
    pub name: String,
    pub vertices_mm: Vec<Point3<f64>>,
    pub triangles: Vec<[u32; 3]>,
    /// Whether every piece closes, found when the triangles were cleaned.
    encloses: bool,
    /// The box that holds every vertex (none without vertices).
    vertex_bounds: Option<[Point3<f64>; 2]>,
    shape: ShapeCache,
}

/// The most triangles in one part of a surface mesh.
pub const PART_TRIANGLES: usize = 32_768;

/// parry's shape of a mesh, in parts, and whether it is solid inside
/// (closed, faces outwards: then it is one part) or only a surface.
#[derive(Clone)]
pub struct MeshShape {
    pub parts: Vec<MeshPart>,
    pub solid: bool,
}

/// Some triangles of a mesh near each other, as parry's shape, and the
/// box that bounds them.
#[derive(Clone)]
pub struct MeshPart {
    pub shape: SharedShape,
    pub bounds: [Point3<f64>; 2],
}

impl MeshPart {
    fn new(shape: SharedShape) -> Self {
        let aabb = shape.compute_local_aabb();
        MeshPart {
            shape,
            bounds: [aabb.mins, aabb.maxs],
        }
    }
}

/// The shape, built when first asked; a cache, so never part of equality.
#[derive(Clone, Default)]
struct ShapeCache(Arc<OnceLock<Option<MeshShape>>>);

impl PartialEq for ShapeCache {
    fn eq(&self, _: &Self) -> bool {
        true
    }
}

impl std::fmt::Debug for ShapeCache {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        f.write_str("ShapeCache")
    }
}

impl MeshObstacle {
    /// The mesh of `triangles` (indices into `vertices_mm`), cleaned.
    pub fn new(name: String, vertices_mm: Vec<Point3<f64>>, triangles: &[[u32; 3]]) -> Self {
        let (triangles, encloses) = cleaned_triangles(&vertices_mm, triangles);
        let vertex_bounds = vertices_mm.first().map(|&first| {
            (vertices_mm.iter()).fold([first, first], |[lo, hi], v| [lo.inf(v), hi.sup(v)])
        });
        MeshObstacle {
            name,
            vertices_mm,
            triangles,
            encloses,
            vertex_bounds,
            shape: ShapeCache::default(),
        }
    }

    /// The box that holds every vertex, triangles without area included
    /// (none for a mesh without vertices).
    pub fn vertex_bounds(&self) -> Option<[Point3<f64>; 2]> {
        self.vertex_bounds
    }

    /// Whether the mesh encloses solids (every piece closed): then inside
    /// counts as well as the surface.
    pub fn encloses(&self) -> bool {
        self.encloses
    }

    /// Whether `p` is inside the mesh and not on its surface (within a
    /// thousandth of a millimetre), as [`BoxObstacle::holds_strictly`]
    /// says of a box: only a mesh that encloses has an inside.
    pub fn holds_strictly(&self, p: &Point3<f64>) -> bool {
        let Some([lo, hi]) = self.vertex_bounds else {
            return false;
        };
        if !(0..3).all(|i| lo[i] < p[i] && p[i] < hi[i]) {
            return false;
        }
        let Some(MeshShape { parts, solid: true }) = self.shape() else {
            return false;
        };
        let at = nalgebra::Isometry3::identity();
        parts.iter().any(|part| {
            part.shape.contains_point(&at, p) && part.shape.distance_to_point(&at, p, false) > 1e-3
        })
    }

    /// parry's shape of the mesh, built on the first call; none if parry
    /// refuses the triangles.
    pub fn shape(&self) -> Option<&MeshShape> {
        self.shape.0.get_or_init(|| self.build_shape()).as_ref()
    }

    fn build_shape(&self) -> Option<MeshShape> {
        // Solid only where it encloses: parry's orientation alone would
        // take one sheet for the edge of a solid half-space.
        if self.encloses {
            // parry takes the triangles by value.
            let (vertices, triangles) = (self.vertices_mm.clone(), self.triangles.clone());
            let oriented =
                SharedShape::trimesh_with_flags(vertices, triangles, TriMeshFlags::ORIENTED);
            if let Ok(shape) = oriented {
                return Some(MeshShape {
                    parts: vec![MeshPart::new(shape)],
                    solid: true,
                });
            }
        }
        // Triangle indices in the order of the parts, and each part's
        // length; the centroids that ordered them are dropped before any
        // tree is built, so they never add to the trees' peak.
        let (order, lengths) = {
            let mut order: Vec<u32> = (0..self.triangles.len() as u32).collect();
            let centroids: Vec<Point3<f64>> = (self.triangles.iter())
                .map(|t| {
                    Point3::from(
                        t.iter()
                            .map(|&i| self.vertices_mm[i as usize].coords)
                            .sum::<nalgebra::Vector3<f64>>()
                            / 3.0,
                    )
                })
                .collect();
            let lengths: Vec<usize> = split_near(&mut order, &centroids, PART_TRIANGLES)
                .iter()
                .map(|part| part.len())
                .collect();
            (order, lengths)
        };
        let mut parts = Vec::with_capacity(lengths.len());
        let mut rest = &order[..];
        for length in lengths {
            let (part, after) = rest.split_at(length);
            rest = after;
            let (vertices, triangles) = self.part(part);
            parts.push(MeshPart::new(
                SharedShape::trimesh(vertices, triangles).ok()?,
            ));
        }
        Some(MeshShape {
            parts,
            solid: false,
        })
    }

    /// The triangles `part` (indices of triangles) with their own vertices.
    /// Both exactly as long as they need be: parry keeps them.
    fn part(&self, part: &[u32]) -> (Vec<Point3<f64>>, Vec<[u32; 3]>) {
        let mut index_of = std::collections::HashMap::new();
        let mut vertices = Vec::new();
        let triangles: Vec<[u32; 3]> = part
            .iter()
            .map(|&t| {
                self.triangles[t as usize].map(|v| {
                    *index_of.entry(v).or_insert_with(|| {
                        vertices.push(self.vertices_mm[v as usize]);
                        (vertices.len() - 1) as u32
                    })
                })
            })
            .collect();
        vertices.shrink_to_fit();
        (vertices, triangles)
    }
}

/// `order` (indices of `centroids`) cut into runs of at most `most`, each
/// of points near each other: halved at the median of the longest side of
/// their bounds until small enough. Deterministic.
fn split_near<'a>(
    order: &'a mut [u32],
    centroids: &[Point3<f64>],
    most: usize,
) -> Vec<&'a mut [u32]> {
    if order.len() <= most {
        return vec![order];
    }
    let (mut lo, mut hi) = (
        Point3::from([f64::INFINITY; 3]),
        Point3::from([f64::NEG_INFINITY; 3]),
    );
    for &i in order.iter() {
        lo = lo.inf(&centroids[i as usize]);
        hi = hi.sup(&centroids[i as usize]);
    }
    let axis = (hi - lo).imax();
    let middle = order.len() / 2;
    order.select_nth_unstable_by(middle, |&a, &b| {
        centroids[a as usize][axis]
            .total_cmp(&centroids[b as usize][axis])
            .then(a.cmp(&b))
    });
    let (first, second) = order.split_at_mut(middle);
    let mut runs = split_near(first, centroids, most);
    runs.extend(split_near(second, centroids, most));
    runs
}
