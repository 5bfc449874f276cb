//! Triangle meshes from the files CAD tools and scanners export: Wavefront
//! OBJ (`obj.rs`), STL binary and ASCII (`stl.rs`) and glTF 2.0, binary or
//! JSON (`gltf.rs`). Each reader gives the vertices in the file's own
//! units and axes and the triangles as vertex indices; the checker scales,
//! turns and places them. A broken file is a [`MeshFileError`] in words a
//! user can act on, never a panic.

mod gltf;
mod json_tally;
mod obj;
mod stl;

use std::fmt;
use std::path::Path;
use std::sync::Arc;

use nalgebra::Point3;

/// A mesh as read: vertices in the file's units and axes, triangles as
/// indices into them.
#[derive(Clone, Debug, Default, PartialEq)]
pub struct RawMesh {
    pub vertices: Vec<Point3<f64>>,
    pub triangles: Vec<[u32; 3]>,
}

/// The formats read, known by the file's extension.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum MeshFormat {
    Obj,
    Stl,
    Gltf,
}

/// Which axis of a mesh file points up.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum UpAxis {
    Z,
    /// y up, z towards the viewer (glTF's convention, and many scans').
    Y,
}

/// The extensions of the mesh files read: the file policy (`read.rs`)
/// admits these and no other, and each has its format
/// ([`MeshFormat::of`]).
pub const EXTENSIONS: [&str; 4] = ["obj", "stl", "glb", "gltf"];

impl MeshFormat {
    /// The format of `path`, by its extension (any case).
    pub fn of(path: &Path) -> Option<MeshFormat> {
        let ext = path.extension()?.to_str()?.to_ascii_lowercase();
        match ext.as_str() {
            "obj" => Some(MeshFormat::Obj),
            "stl" => Some(MeshFormat::Stl),
            "glb" | "gltf" => Some(MeshFormat::Gltf),
            _ => None,
        }
    }

    /// The up axis when the scenario does not say: glTF's is y by its
    /// specification; OBJ and STL carry none, and z is this tool's.
    pub fn default_up(self) -> UpAxis {
        match self {
            MeshFormat::Gltf => UpAxis::Y,
            MeshFormat::Obj | MeshFormat::Stl => UpAxis::Z,
        }
    }

    /// Whether the format fixes its unit at the metre (glTF does); OBJ
    /// and STL are in whatever unit their author used.
    pub fn in_metres(self) -> bool {
        self == MeshFormat::Gltf
    }
}

impl UpAxis {
    /// `p` in axes with z up: y up turns +90 degrees about x, so the file's
    /// y becomes z and its z (towards the viewer) becomes -y.
    pub fn to_z_up(self, p: Point3<f64>) -> Point3<f64> {
        match self {
            UpAxis::Z => p,
            UpAxis::Y => Point3::new(p.x, -p.z, p.y),
        }
    }
}

/// Why a mesh file gave no mesh.
#[derive(Clone, Debug, PartialEq, Eq)]
pub enum MeshFileError {
    /// The bytes are not a file of the format.
    Invalid {
        format: &'static str,
        reason: String,
    },
    /// The file has no triangle.
    NoFaces,
    /// A vertex is NaN or infinite.
    NotFinite,
    /// More triangles than the limit (a glTF's nodes can place one mesh
    /// many times).
    TooManyTriangles { limit: usize },
    /// A file the mesh refers to (a glTF's buffer) could not be read.
    Buffer { uri: String, reason: String },
}

impl fmt::Display for MeshFileError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            MeshFileError::Invalid { format, reason } => {
                write!(f, "not a valid {format} file: {reason}")
            }
            MeshFileError::NoFaces => f.write_str("it has no faces"),
            MeshFileError::NotFinite => f.write_str("a vertex is not a finite number"),
            MeshFileError::TooManyTriangles { limit } => write!(
                f,
                "it places more than {limit} triangles (the most a file within \
                 --max-file-bytes can hold)"
            ),
            MeshFileError::Buffer { uri, reason } => {
                write!(f, "its buffer `{uri}` cannot be read: {reason}")
            }
        }
    }
}

/// Reads a file a glTF refers to (an external buffer), by its URI: shared
/// bytes, so that buffers naming one file hold it once.
pub type ReadRelated<'a> = dyn FnMut(&str) -> Result<Arc<[u8]>, String> + 'a;

/// The mesh in `bytes`, a file of `format`. `max_triangles` bounds what
/// the file may place; `related` reads the files it refers to.
pub fn parse(
    format: MeshFormat,
    bytes: &[u8],
    max_triangles: usize,
    related: &mut ReadRelated<'_>,
) -> Result<RawMesh, MeshFileError> {
    let mesh = match format {
        MeshFormat::Obj => obj::parse(bytes)?,
        MeshFormat::Stl => stl::parse(bytes)?,
        MeshFormat::Gltf => gltf::parse(bytes, max_triangles, related)?,
    };
    if mesh.triangles.len() > max_triangles {
        return Err(MeshFileError::TooManyTriangles {
            limit: max_triangles,
        });
    }
    if mesh
        .vertices
        .iter()
        .any(|v| !v.coords.iter().all(|x| x.is_finite()))
    {
        return Err(MeshFileError::NotFinite);
    }
    if mesh.triangles.is_empty() {
        return Err(MeshFileError::NoFaces);
    }
    Ok(mesh)
}

/// `[x, y, z]` in single precision as a point.
fn point(c: [f32; 3]) -> Point3<f64> {
    Point3::new(f64::from(c[0]), f64::from(c[1]), f64::from(c[2]))
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn every_extension_admitted_has_a_format() {
        for ext in EXTENSIONS {
            let path = format!("room.{}", ext.to_uppercase());
            assert!(MeshFormat::of(Path::new(&path)).is_some(), "{ext}");
        }
        assert_eq!(MeshFormat::of(Path::new("room.ply")), None);
    }
}
