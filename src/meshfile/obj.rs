//! Wavefront OBJ, read with `tobj`: every object's polygons triangulated,
//! materials ignored.

use super::{point, MeshFileError, RawMesh};

pub(super) fn parse(bytes: &[u8]) -> Result<RawMesh, MeshFileError> {
    let options = tobj::LoadOptions {
        triangulate: true,
        single_index: true,
        ..Default::default()
    };
    let mut reader = std::io::Cursor::new(bytes);
    let (models, _materials) = tobj::load_obj_buf(&mut reader, &options, |_| {
        Err(tobj::LoadError::OpenFileFailed)
    })
    .map_err(|e| MeshFileError::Invalid {
        format: "OBJ",
        reason: e.to_string(),
    })?;
    let mut mesh = RawMesh::default();
    for model in &models {
        let base = mesh.vertices.len() as u32;
        let p = &model.mesh.positions;
        mesh.vertices
            .extend(p.chunks_exact(3).map(|c| point([c[0], c[1], c[2]])));
        mesh.triangles.extend(
            model
                .mesh
                .indices
                .chunks_exact(3)
                .map(|t| [base + t[0], base + t[1], base + t[2]]),
        );
    }
    Ok(mesh)
}
