//! Wavefront OBJ, read with `tobj`: every object's polygons triangulated,
//! materials ignored.

use super::{point, MeshFileError, RawMesh};

pub(super) fn parse(bytes: &[u8]) -> Result<RawMesh, MeshFileError> {
    indices_small_enough(bytes)?;
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

/// Every index a face gives (of a position, a texture coordinate or a
/// normal) names one `tobj` can use: a relative (negative) index reaches
/// no further back than the positions, coordinates or normals before it,
/// and none is too large to multiply by three. `tobj` wraps a relative
/// index past the start to a huge one and multiplies it unchecked (a
/// panic where overflow is checked, found by fuzzing). Other indices past
/// the file's vertices are `tobj`'s to refuse, in its words.
fn indices_small_enough(bytes: &[u8]) -> Result<(), MeshFileError> {
    let text = String::from_utf8_lossy(bytes);
    // Positions, texture coordinates and normals so far.
    let mut seen = [0_i128; 3];
    for line in text.lines() {
        let mut words = line.split_whitespace();
        match words.next() {
            Some("v") => seen[0] += 1,
            Some("vt") => seen[1] += 1,
            Some("vn") => seen[2] += 1,
            Some("f") => {
                for corner in words {
                    for (kind, k) in corner.split('/').enumerate().take(3) {
                        let Ok(k) = k.parse::<i128>() else {
                            continue;
                        };
                        if k > LARGEST_INDEX || (k < 0 && -k > seen[kind]) {
                            return Err(MeshFileError::Invalid {
                                format: "OBJ",
                                reason: format!("a face gives index {k}, which names nothing"),
                            });
                        }
                    }
                }
            }
            _ => {}
        }
    }
    Ok(())
}

/// The largest index a face may give: far more than any file within the
/// limits holds, and three times it (and two more) still fits in 64 bits.
const LARGEST_INDEX: i128 = 1 << 60;

#[cfg(test)]
mod tests {
    #[test]
    fn a_face_index_that_names_nothing_is_refused_before_tobj_wraps_it() {
        let obj = "v 0 0 0\nv 1 0 0\nv 0 1 0\nvt 0 0\nf 1/4611686018427387904 2/1 3/1\n";
        let err = super::parse(obj.as_bytes()).unwrap_err().to_string();
        assert!(err.contains("which names nothing"), "{err}");
        let back = "v 0 0 0\nv 1 0 0\nv 0 1 0\nvt 0 0\nf 1/-2 2/1 3/1\n";
        let err = super::parse(back.as_bytes()).unwrap_err().to_string();
        assert!(err.contains("index -2, which names nothing"), "{err}");
        let fine = "v 0 0 0\nv 1 0 0\nv 0 1 0\nvt 0 0\nf 1/1 2/1 -1/1\n";
        assert_eq!(super::parse(fine.as_bytes()).unwrap().triangles.len(), 1);
    }
}
