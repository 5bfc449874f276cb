//! STL, binary or ASCII, read with `stl_io` (which joins equal vertices,
//! so a closed solid's pieces are found). A binary file's header states
//! its triangle count; a file whose length disagrees with it is refused
//! rather than read short or with trailing bytes ignored.

use super::{MeshFileError, RawMesh};

/// A binary STL: 80 bytes of header, a count, 50 bytes per triangle.
const HEADER_BYTES: usize = 84;
const TRIANGLE_BYTES: usize = 50;

pub(super) fn parse(bytes: &[u8]) -> Result<RawMesh, MeshFileError> {
    let invalid = |reason: String| MeshFileError::Invalid {
        format: "STL",
        reason,
    };
    if !is_ascii(bytes) {
        check_binary_count(bytes).map_err(invalid)?;
    }
    let mut reader = std::io::Cursor::new(bytes);
    let indexed = stl_io::read_stl(&mut reader).map_err(|e| invalid(e.to_string()))?;
    let vertices = indexed.vertices.iter().map(|v| super::point(v.0)).collect();
    let triangles = indexed
        .faces
        .iter()
        .map(|f| f.vertices.map(|k| k as u32))
        .collect();
    Ok(RawMesh {
        vertices,
        triangles,
    })
}

/// An ASCII STL starts with `solid` and is text; some binary files also
/// start with `solid` in their header, so the length decides between them.
fn is_ascii(bytes: &[u8]) -> bool {
    let text = bytes.trim_ascii_start();
    text.starts_with(b"solid") && check_binary_count(bytes).is_err()
}

/// That a binary STL's length is what its triangle count says.
fn check_binary_count(bytes: &[u8]) -> Result<(), String> {
    if bytes.len() < HEADER_BYTES {
        return Err(format!(
            "{} bytes, shorter than a binary STL's header ({HEADER_BYTES})",
            bytes.len()
        ));
    }
    let count = u32::from_le_bytes([bytes[80], bytes[81], bytes[82], bytes[83]]) as usize;
    let held = (bytes.len() - HEADER_BYTES) / TRIANGLE_BYTES;
    let exact = (bytes.len() - HEADER_BYTES).is_multiple_of(TRIANGLE_BYTES);
    if count != held || !exact {
        return Err(format!(
            "its header says {count} triangles but its {} bytes hold {held}{}",
            bytes.len(),
            if exact { "" } else { " and a part of one" }
        ));
    }
    Ok(())
}
