//! A mesh obstacle: its triangles in the room, cleaned when it is made,
//! and parry's shape of it (with its bounding volume tree), built once when
//! collisions are first checked and shared by every task after.

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
    shape: ShapeCache,
}

/// parry's shape of a mesh, and whether it is solid inside (closed, faces
/// outwards) or only a surface.
#[derive(Clone)]
pub struct MeshShape {
    pub shape: SharedShape,
    pub solid: bool,
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
        MeshObstacle {
            name,
            vertices_mm,
            triangles,
            encloses,
            shape: ShapeCache::default(),
        }
    }

    /// Whether the mesh encloses solids (every piece closed): then inside
    /// counts as well as the surface.
    pub fn encloses(&self) -> bool {
        self.encloses
    }

    /// parry's shape of the mesh, built on the first call; none if parry
    /// refuses the triangles.
    pub fn shape(&self) -> Option<&MeshShape> {
        self.shape.0.get_or_init(|| self.build_shape()).as_ref()
    }

    fn build_shape(&self) -> Option<MeshShape> {
        // One copy of the triangles at a time: parry takes them by value.
        let copy = || (self.vertices_mm.clone(), self.triangles.clone());
        // Solid only where it encloses: parry's orientation alone would
        // take one sheet for the edge of a solid half-space.
        if self.encloses {
            let (vertices, triangles) = copy();
            let oriented =
                SharedShape::trimesh_with_flags(vertices, triangles, TriMeshFlags::ORIENTED);
            if let Ok(shape) = oriented {
                return Some(MeshShape { shape, solid: true });
            }
        }
        let (vertices, triangles) = copy();
        let shape = SharedShape::trimesh(vertices, triangles).ok()?;
        Some(MeshShape {
            shape,
            solid: false,
        })
    }
}
