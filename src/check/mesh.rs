//! Mesh obstacles: a Wavefront OBJ file (read with `tobj`, triangulated),
//! its coordinates in the file's length unit times `scale`, turned by
//! `rotate` about the vertical and moved to `at`. Triangles without an
//! area are dropped and closed pieces wound outwards
//! (`MeshObstacle::new`). A file that cannot be read or parsed,
//! or that has no triangle with an area, is a diagnostic at its name.

use std::path::{Path, PathBuf};

use nalgebra::{Point3, Rotation3, Vector3};

use super::Checker;
use crate::error::{Error, ErrorKind};
use crate::read::{self, FileKind};
use crate::scene::MeshObstacle;
use crate::source::Origin;
use crate::syntax::ast::MeshDecl;

/// An OBJ's vertices (in its own units) and triangles.
type ObjMesh = (Vec<Point3<f64>>, Vec<[u32; 3]>);

impl Checker<'_> {
    pub(super) fn mesh(&mut self, d: &MeshDecl) -> Option<MeshObstacle> {
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
        for (extra, what) in [
            (d.at.get(1).map(|v| v.span), "`at`"),
            (d.scale.get(1).map(|e| e.span), "`scale`"),
            (d.rotate.get(1).map(|e| e.span), "`rotate`"),
        ] {
            if let Some(span) = extra {
                self.error(Error::new(ErrorKind::Repeated { what: what.into() }, span));
            }
        }
        let (vertices, triangles) = self.read_obj(d)?;
        let (at, scale, yaw) = (at?, scale?, yaw?);
        if scale.is_nan() || scale <= 0.0 {
            self.out_of_range(
                d.scale[0].span,
                "a mesh's scale",
                "more than 0",
                &scale.to_string(),
            );
            return None;
        }
        let unit_mm = self.defaults.length.to_internal();
        let turn = Rotation3::from_axis_angle(&Vector3::z_axis(), yaw);
        let vertices_mm = vertices
            .into_iter()
            .map(|v| at + turn * (v.coords * scale * unit_mm))
            .collect();
        let mesh = MeshObstacle::new(d.name.value.clone(), vertices_mm, &triangles);
        if mesh.triangles.is_empty() {
            let n = triangles.len();
            self.bad_mesh(d, format!("none of its {n} triangles has an area"));
            return None;
        }
        Some(mesh)
    }

    /// The OBJ's vertices (in its own units) and triangles.
    fn read_obj(&mut self, d: &MeshDecl) -> Option<ObjMesh> {
        let path = self.relative_to_file(&d.path.value);
        self.data_files.push(path.clone());
        let bad = |c: &mut Self, reason: String| {
            c.bad_mesh(d, reason);
            None
        };
        let limit = self.limits.file_bytes;
        let bytes = match read::read(&path, FileKind::Mesh, &self.sources.allowed, limit) {
            Ok(bytes) => bytes,
            Err(e) => return bad(self, e.to_string()),
        };
        let options = tobj::LoadOptions {
            triangulate: true,
            single_index: true,
            ..Default::default()
        };
        let mut reader = std::io::Cursor::new(bytes);
        let models = match tobj::load_obj_buf(&mut reader, &options, |_| {
            Err(tobj::LoadError::OpenFileFailed)
        }) {
            Ok((models, _materials)) => models,
            Err(e) => return bad(self, format!("not a valid OBJ file: {e}")),
        };
        let mut vertices = Vec::new();
        let mut triangles = Vec::new();
        for model in &models {
            let base = vertices.len() as u32;
            let p = &model.mesh.positions;
            vertices.extend(
                p.chunks_exact(3)
                    .map(|c| Point3::new(f64::from(c[0]), f64::from(c[1]), f64::from(c[2]))),
            );
            triangles.extend(
                model
                    .mesh
                    .indices
                    .chunks_exact(3)
                    .map(|t| [base + t[0], base + t[1], base + t[2]]),
            );
        }
        if vertices
            .iter()
            .any(|v| !v.coords.iter().all(|x| x.is_finite()))
        {
            return bad(self, "a vertex is not a finite number".into());
        }
        if triangles.is_empty() {
            return bad(self, "it has no faces".into());
        }
        Some((vertices, triangles))
    }

    /// A diagnostic at the mesh's file name.
    fn bad_mesh(&mut self, d: &MeshDecl, reason: String) {
        let path = self.relative_to_file(&d.path.value).display().to_string();
        self.error(Error::new(ErrorKind::BadMesh { path, reason }, d.path.span));
    }

    /// `relative` against the directory of the file being checked (the
    /// working directory for text not read from disk).
    pub(super) fn relative_to_file(&self, relative: &str) -> PathBuf {
        let dir = match &self.sources.get(self.file).origin {
            Origin::Path(p) => p.parent().map(Path::to_path_buf).unwrap_or_default(),
            _ => PathBuf::new(),
        };
        dir.join(relative)
    }
}
