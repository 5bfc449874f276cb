//! Mesh obstacles: an OBJ, STL or glTF/GLB file (`crate::meshfile`), its
//! coordinates in its length unit (`unit`; by default the scenario's
//! length unit, or the metre for glTF) times `scale`, its up axis (`up`;
//! z, or y for glTF) turned to z, then turned by `rotate` about the
//! vertical and moved to `at`. Triangles without an area are dropped and
//! closed pieces wound outwards (`MeshObstacle::new`). A file that cannot
//! be read or parsed, or that has no triangle with an area, is a
//! diagnostic at its name.

use std::collections::HashMap;
use std::path::{Path, PathBuf};
use std::sync::Arc;

use nalgebra::{Point3, Rotation3, Vector3};

use super::Checker;
use crate::error::{thousands, Error, ErrorKind};
use crate::meshfile::{self, MeshFileError, MeshFormat, RawMesh, UpAxis};
use crate::read::{self, FileKind};
use crate::scene::MeshObstacle;
use crate::span::Spanned;
use crate::syntax::ast::MeshDecl;
use crate::units::Unit;

/// The fewest bytes a file can spend on one triangle (three 32-bit
/// indices), which bounds how many triangles a file within the byte limit
/// may place.
const MIN_BYTES_PER_TRIANGLE: u64 = 12;

/// The mesh files of one check, each read and parsed once.
#[derive(Default)]
pub(super) struct MeshFiles {
    /// The bytes of each file a mesh refers to, or why they cannot be read.
    related: HashMap<PathBuf, Result<Arc<[u8]>, String>>,
    /// Each mesh file parsed whole, by its path and the format it is read as.
    parsed: HashMap<(PathBuf, MeshFormat), Arc<RawMesh>>,
}

/// The key a file is known by: its canonical path where it has one.
fn file_key(path: &Path) -> PathBuf {
    std::fs::canonicalize(path).unwrap_or_else(|_| path.to_path_buf())
}

/// How a file's coordinates become the room's millimetres.
struct Frame {
    at: Point3<f64>,
    /// Millimetres per unit of the file, `scale` included.
    mm_per_unit: f64,
    up: UpAxis,
    yaw_rad: f64,
}

impl Checker<'_> {
    pub(super) fn mesh(&mut self, d: &MeshDecl) -> Option<MeshObstacle> {
        let path = self.relative_to_file(&d.path.value);
        let format = MeshFormat::of(&path);
        let frame = self.mesh_frame(d, format);
        let raw = self.read_mesh(d, path, format)?;
        let frame = frame?;
        let turn = Rotation3::from_axis_angle(&Vector3::z_axis(), frame.yaw_rad);
        let vertices_mm = raw
            .vertices
            .iter()
            .map(|&v| frame.at + turn * (frame.up.to_z_up(v).coords * frame.mm_per_unit))
            .collect();
        let mesh = MeshObstacle::new(d.name.value.clone(), vertices_mm, &raw.triangles);
        if mesh.triangles.is_empty() {
            let n = raw.triangles.len();
            self.bad_mesh(d, format!("none of its {n} triangles has an area"));
            return None;
        }
        Some(mesh)
    }

    /// `at`, `scale`, `rotate`, `unit` and `up`, each given at most once.
    fn mesh_frame(&mut self, d: &MeshDecl, format: Option<MeshFormat>) -> Option<Frame> {
        let at = match d.at.first() {
            Some(v) => self.point(v).map(Point3::from),
            None => Some(Point3::origin()),
        };
        let scale = match d.scale.first() {
            Some(e) => self.number(e),
            None => Some(1.0),
        };
        let yaw = match d.rotate.first() {
            Some(e) => self.angle(e),
            None => Some(0.0),
        };
        let unit_mm = self.mesh_unit_mm(d.unit.first(), format);
        let up = self.mesh_up(d.up.first(), format);
        for (extra, what) in [
            (d.at.get(1).map(|v| v.span), "`at`"),
            (d.scale.get(1).map(|e| e.span), "`scale`"),
            (d.rotate.get(1).map(|e| e.span), "`rotate`"),
            (d.unit.get(1).map(|w| w.span), "`unit`"),
            (d.up.get(1).map(|w| w.span), "`up`"),
        ] {
            if let Some(span) = extra {
                self.error(Error::new(ErrorKind::Repeated { what: what.into() }, span));
            }
        }
        let (at, scale, yaw_rad, unit_mm, up) = (at?, scale?, yaw?, unit_mm?, up?);
        if scale.is_nan() || scale <= 0.0 {
            let shown = scale.to_string();
            self.out_of_range(d.scale[0].span, "a mesh's scale", "more than 0", &shown);
            return None;
        }
        Some(Frame {
            at,
            mm_per_unit: scale * unit_mm,
            up,
            yaw_rad,
        })
    }

    /// Millimetres per unit of the file: `unit` as written, else glTF's
    /// metre, else the scenario's length unit.
    fn mesh_unit_mm(
        &mut self,
        unit: Option<&Spanned<String>>,
        format: Option<MeshFormat>,
    ) -> Option<f64> {
        match unit {
            Some(w) => match Unit::parse(&w.value).filter(|u| u.is_length()) {
                Some(u) => Some(u.to_internal()),
                None => {
                    self.bad_mesh_setting(w, "unit", "a length unit: mm, cm, m or in");
                    None
                }
            },
            None if format.is_some_and(MeshFormat::in_metres) => Some(Unit::M.to_internal()),
            None => Some(self.cx.defaults.length.to_internal()),
        }
    }

    /// The file's up axis: `up` as written, else its format's.
    fn mesh_up(
        &mut self,
        up: Option<&Spanned<String>>,
        format: Option<MeshFormat>,
    ) -> Option<UpAxis> {
        match up.map(|w| (w, w.value.as_str())) {
            Some((_, "z")) => Some(UpAxis::Z),
            Some((_, "y")) => Some(UpAxis::Y),
            Some((w, _)) => {
                self.bad_mesh_setting(w, "up axis", "`z` or `y`");
                None
            }
            None => Some(format.map_or(UpAxis::Z, MeshFormat::default_up)),
        }
    }

    fn bad_mesh_setting(
        &mut self,
        w: &Spanned<String>,
        what: &'static str,
        expected: &'static str,
    ) {
        let kind = ErrorKind::BadMeshSetting {
            what,
            expected,
            found: w.value.clone(),
        };
        self.error(Error::new(kind, w.span));
    }

    /// The file's vertices (in its own units and axes) and triangles,
    /// shared with every other `mesh` line that names the file.
    fn read_mesh(
        &mut self,
        d: &MeshDecl,
        path: PathBuf,
        format: Option<MeshFormat>,
    ) -> Option<Arc<RawMesh>> {
        self.cx.data_files.push(path.clone());
        let left = self
            .cx
            .limits
            .triangles
            .saturating_sub(self.cx.triangles_read);
        let key = format.map(|format| (file_key(&path), format));
        if let Some(mesh) = key.as_ref().and_then(|k| self.cx.mesh_files.parsed.get(k)) {
            let mesh = Arc::clone(mesh);
            return self.counted(d, Ok(mesh), left, usize::MAX);
        }
        let limit = self.cx.limits.file_bytes;
        let bytes = match read::read(&path, FileKind::Mesh, &self.cx.sources.allowed, limit) {
            Ok(bytes) => bytes,
            Err(e) => {
                self.bad_mesh(d, e.to_string());
                return None;
            }
        };
        // `read` admits only `meshfile::EXTENSIONS`, each with a format.
        let format = format?;
        let dir = path.parent().map(Path::to_path_buf).unwrap_or_default();
        let mut buffers = Vec::new();
        let allowed = &self.cx.sources.allowed;
        let read_before = &mut self.cx.mesh_files.related;
        let mut related = |uri: &str| {
            let buffer = dir.join(uri);
            buffers.push(buffer.clone());
            let read = || read::read(&buffer, FileKind::MeshBuffer, allowed, limit);
            (read_before.entry(file_key(&buffer)))
                .or_insert_with(|| read().map(Arc::from).map_err(|e| e.to_string()))
                .clone()
        };
        let in_file = usize::try_from(limit / MIN_BYTES_PER_TRIANGLE).unwrap_or(usize::MAX);
        let parsed = meshfile::parse(format, &bytes, in_file.min(left), &mut related).map(Arc::new);
        self.cx.data_files.extend(buffers);
        if let (Ok(mesh), Some(key)) = (&parsed, key) {
            (self.cx.mesh_files.parsed).insert(key, Arc::clone(mesh));
        }
        self.counted(d, parsed, left, in_file)
    }

    /// A mesh parsed (or taken from one parsed before), its triangles
    /// counted against the scenario's bound (`left` of it before this one;
    /// `in_file`, the most one file within the byte limit may place).
    fn counted(
        &mut self,
        d: &MeshDecl,
        parsed: Result<Arc<RawMesh>, MeshFileError>,
        left: usize,
        in_file: usize,
    ) -> Option<Arc<RawMesh>> {
        let parsed = match parsed {
            Ok(mesh) if mesh.triangles.len() > left => {
                Err(MeshFileError::TooManyTriangles { limit: left })
            }
            other => other,
        };
        match parsed {
            Ok(mesh) => {
                self.cx.triangles_read += mesh.triangles.len();
                Some(mesh)
            }
            Err(MeshFileError::TooManyTriangles { .. }) if left < in_file => {
                let most = thousands(self.cx.limits.triangles as u64);
                let kind = ErrorKind::TooLarge {
                    what: "the count of triangles in this mesh and the meshes before it".into(),
                    limit: format!("{most} in a scenario (--max-triangles)"),
                };
                self.error(Error::new(kind, d.path.span));
                None
            }
            Err(e) => {
                self.bad_mesh(d, e.to_string());
                None
            }
        }
    }

    /// A diagnostic at the mesh's file name.
    fn bad_mesh(&mut self, d: &MeshDecl, reason: String) {
        let path = self.relative_to_file(&d.path.value).display().to_string();
        self.error(Error::new(ErrorKind::BadMesh { path, reason }, d.path.span));
    }

    /// `relative` against the directory of the file being checked (the
    /// working directory for text not read from disk).
    pub(super) fn relative_to_file(&self, relative: &str) -> PathBuf {
        let file = self.cx.sources.get(self.cx.file);
        let dir = file.path().and_then(Path::parent).unwrap_or(Path::new(""));
        dir.join(relative)
    }
}
