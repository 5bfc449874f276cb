//! glTF 2.0, binary (`.glb`) or JSON (`.gltf`), parsed and validated by the
//! `gltf` crate. Buffers come from the GLB's binary chunk, from `data:`
//! URIs, or from files beside it (read through the caller, under the
//! scenario's file policy). Accessors are read here, every offset, stride
//! and count checked against its buffer, since a malformed accessor would
//! make the crate's own reader assert. Every mesh of the default scene (or
//! the first) is placed by its node's transform; a scene-less file gives
//! its meshes as they are.

use std::sync::Arc;

use base64::Engine as _;
use gltf::accessor::{DataType, Dimensions};
use gltf::mesh::{Mode, Semantic};
use gltf::{Accessor, Document, Node};
use nalgebra::{Matrix4, Point3};

use super::{point, MeshFileError, RawMesh, ReadRelated};

pub(super) fn parse(
    bytes: &[u8],
    max_triangles: usize,
    related: &mut ReadRelated<'_>,
) -> Result<RawMesh, MeshFileError> {
    check_glb_length(bytes)?;
    check_json_size(bytes)?;
    let gltf::Gltf { document, blob } =
        gltf::Gltf::from_slice_without_validation(bytes).map_err(|e| invalid(e.to_string()))?;
    let json = document.into_json();
    positions_exist(&json)?;
    let document = Document::from_json(json).map_err(|e| invalid(e.to_string()))?;
    let buffers = buffers(&document, blob, related)?;
    let mut reader = Reader {
        buffers,
        mesh: RawMesh::default(),
        max_triangles,
        placed: vec![false; document.nodes().len()],
    };
    match document
        .default_scene()
        .or_else(|| document.scenes().next())
    {
        Some(scene) => {
            for node in scene.nodes() {
                reader.node(node, &Matrix4::identity())?;
            }
        }
        None => {
            for mesh in document.meshes() {
                reader.mesh(mesh, &Matrix4::identity())?;
            }
        }
    }
    Ok(reader.mesh)
}

/// A GLB's header: `glTF`, a version and the file's length, which must be
/// at least the header's 12 bytes and at most the bytes there are (the
/// `gltf` crate subtracts without checking).
fn check_glb_length(bytes: &[u8]) -> Result<(), MeshFileError> {
    if !bytes.starts_with(b"glTF") {
        return Ok(());
    }
    let length = match bytes.get(8..12) {
        Some(b) => u32::from_le_bytes([b[0], b[1], b[2], b[3]]) as usize,
        None => return Err(invalid("its GLB header is cut short".into())),
    };
    if length < 12 || length > bytes.len() {
        return Err(invalid(format!(
            "its GLB header says {length} bytes and the file has {}",
            bytes.len()
        )));
    }
    Ok(())
}

/// That the JSON (a `.gltf` file, or a GLB's JSON chunk) holds no more
/// than the `gltf` crate may build (`json_tally.rs`).
fn check_json_size(bytes: &[u8]) -> Result<(), MeshFileError> {
    let json = if bytes.starts_with(b"glTF") {
        let glb = gltf::binary::Glb::from_slice(bytes).map_err(|e| invalid(e.to_string()))?;
        glb.json
    } else {
        std::borrow::Cow::Borrowed(bytes)
    };
    super::json_tally::tally(&json).map(|_| ()).map_err(invalid)
}

/// That every primitive's POSITION accessor exists: the `gltf` crate's
/// validation looks it up unchecked (and panics), so it is checked first.
fn positions_exist(json: &gltf::json::Root) -> Result<(), MeshFileError> {
    let attributes = json
        .meshes
        .iter()
        .flat_map(|m| &m.primitives)
        .flat_map(|p| &p.attributes);
    for (semantic, index) in attributes {
        let position = *semantic == gltf::json::validation::Checked::Valid(Semantic::Positions);
        if position && index.value() >= json.accessors.len() {
            return Err(invalid(format!(
                "a POSITION names accessor {}, and there are {}",
                index.value(),
                json.accessors.len()
            )));
        }
    }
    Ok(())
}

fn invalid(reason: String) -> MeshFileError {
    MeshFileError::Invalid {
        format: "glTF",
        reason,
    }
}

/// Each buffer's bytes, at least as many as it declares.
fn buffers(
    document: &Document,
    mut blob: Option<Vec<u8>>,
    related: &mut ReadRelated<'_>,
) -> Result<Vec<Arc<[u8]>>, MeshFileError> {
    let mut all = Vec::new();
    for buffer in document.buffers() {
        let data = match buffer.source() {
            gltf::buffer::Source::Bin => Arc::from(blob.take().ok_or_else(|| {
                invalid(format!(
                    "buffer {} is in a binary chunk the file lacks",
                    buffer.index()
                ))
            })?),
            gltf::buffer::Source::Uri(uri) => match uri.strip_prefix("data:") {
                Some(data) => Arc::from(data_uri(data).ok_or_else(|| {
                    invalid(format!(
                        "buffer {}'s data URI is not base64",
                        buffer.index()
                    ))
                })?),
                None => related(uri).map_err(|reason| MeshFileError::Buffer {
                    uri: uri.to_string(),
                    reason,
                })?,
            },
        };
        if data.len() < buffer.length() {
            return Err(invalid(format!(
                "buffer {} declares {} bytes but holds {}",
                buffer.index(),
                buffer.length(),
                data.len()
            )));
        }
        all.push(data);
    }
    Ok(all)
}

/// The bytes of a `data:` URI's text after `data:` (`...;base64,DATA`).
fn data_uri(data: &str) -> Option<Vec<u8>> {
    let (_, encoded) = data.split_once(";base64,")?;
    base64::engine::general_purpose::STANDARD
        .decode(encoded)
        .ok()
}

/// The mesh gathered while walking a scene's nodes.
struct Reader {
    buffers: Vec<Arc<[u8]>>,
    mesh: RawMesh,
    max_triangles: usize,
    /// Nodes already placed: a node has one parent, so a second visit is a
    /// cycle or a shared child, either of which the format forbids.
    placed: Vec<bool>,
}

impl Reader {
    /// Node `root` and the nodes below it, each placed by its parents'
    /// transforms, depth first in the file's order of children: from a
    /// stack, not by recursion (a file may nest hundreds of thousands of
    /// nodes, one inside the next).
    fn node(&mut self, root: Node<'_>, parent: &Matrix4<f64>) -> Result<(), MeshFileError> {
        let mut waiting = vec![(root, *parent)];
        while let Some((node, parent)) = waiting.pop() {
            if std::mem::replace(&mut self.placed[node.index()], true) {
                return Err(invalid(format!(
                    "node {} has two parents or is its own ancestor",
                    node.index()
                )));
            }
            let local = node.transform().matrix();
            let world = parent * Matrix4::from_fn(|r, c| f64::from(local[c][r]));
            if let Some(mesh) = node.mesh() {
                self.mesh(mesh, &world)?;
            }
            let children: Vec<Node<'_>> = node.children().collect();
            waiting.extend(children.into_iter().rev().map(|child| (child, world)));
        }
        Ok(())
    }

    fn mesh(&mut self, mesh: gltf::Mesh<'_>, world: &Matrix4<f64>) -> Result<(), MeshFileError> {
        for primitive in mesh.primitives() {
            if !matches!(
                primitive.mode(),
                Mode::Triangles | Mode::TriangleStrip | Mode::TriangleFan
            ) {
                continue;
            }
            let Some(positions) = primitive.get(&Semantic::Positions) else {
                continue;
            };
            let positions = self.positions(&positions)?;
            let indices = match primitive.indices() {
                Some(accessor) => self.indices(&accessor, positions.len())?,
                None => (0..positions.len() as u32).collect(),
            };
            if self.mesh.vertices.len() + positions.len() > 3 * self.max_triangles {
                return Err(MeshFileError::TooManyTriangles {
                    limit: self.max_triangles,
                });
            }
            let base = self.mesh.vertices.len() as u32;
            let flip = world.fixed_view::<3, 3>(0, 0).determinant() < 0.0;
            self.mesh
                .vertices
                .extend(positions.iter().map(|p| world.transform_point(p)));
            for [a, b, c] in triangles(primitive.mode(), &indices) {
                if self.mesh.triangles.len() == self.max_triangles {
                    return Err(MeshFileError::TooManyTriangles {
                        limit: self.max_triangles,
                    });
                }
                let (a, b) = if flip { (b, a) } else { (a, b) };
                self.mesh.triangles.push([base + a, base + b, base + c]);
            }
        }
        Ok(())
    }

    /// A POSITION accessor's points (three 32-bit floats each).
    fn positions(&self, accessor: &Accessor<'_>) -> Result<Vec<Point3<f64>>, MeshFileError> {
        if accessor.data_type() != DataType::F32 || accessor.dimensions() != Dimensions::Vec3 {
            return Err(invalid(format!(
                "accessor {}'s positions are not three 32-bit floats",
                accessor.index()
            )));
        }
        let items = self.items(accessor, 12)?;
        Ok(items
            .map(|b| {
                let f = |k: usize| f32::from_le_bytes([b[k], b[k + 1], b[k + 2], b[k + 3]]);
                point([f(0), f(4), f(8)])
            })
            .collect())
    }

    /// An index accessor's indices, each checked against the vertex count.
    fn indices(&self, accessor: &Accessor<'_>, vertices: usize) -> Result<Vec<u32>, MeshFileError> {
        let size = match (accessor.data_type(), accessor.dimensions()) {
            (DataType::U8, Dimensions::Scalar) => 1,
            (DataType::U16, Dimensions::Scalar) => 2,
            (DataType::U32, Dimensions::Scalar) => 4,
            _ => {
                return Err(invalid(format!(
                    "accessor {}'s indices are not unsigned integers",
                    accessor.index()
                )))
            }
        };
        // The count is checked against the bytes that back it (`items`)
        // before anything is allocated for it: a count of 2^40 in a small
        // file aborted the process.
        let items = self.items(accessor, size)?;
        let mut indices = Vec::new();
        for b in items {
            let k = match size {
                1 => u32::from(b[0]),
                2 => u32::from(u16::from_le_bytes([b[0], b[1]])),
                _ => u32::from_le_bytes([b[0], b[1], b[2], b[3]]),
            };
            if k as usize >= vertices {
                return Err(invalid(format!(
                    "accessor {} has index {k}, past its {vertices} vertices",
                    accessor.index()
                )));
            }
            indices.push(k);
        }
        Ok(indices)
    }

    /// The `item`-byte slices of an accessor, its whole extent checked to lie
    /// in its buffer view and the view in its buffer.
    fn items<'b>(
        &'b self,
        accessor: &Accessor<'_>,
        item: usize,
    ) -> Result<impl Iterator<Item = &'b [u8]> + 'b, MeshFileError> {
        let what = || format!("accessor {}", accessor.index());
        if accessor.sparse().is_some() {
            return Err(invalid(format!("{} is sparse, which is not read", what())));
        }
        let view = accessor
            .view()
            .ok_or_else(|| invalid(format!("{} has no buffer view", what())))?;
        let stride = view.stride().unwrap_or(item);
        let buffer = &self.buffers[view.buffer().index()];
        let view_bytes = view
            .offset()
            .checked_add(view.length())
            .and_then(|end| buffer.get(view.offset()..end))
            .ok_or_else(|| {
                invalid(format!(
                    "buffer view {} runs past the end of buffer {} ({} bytes)",
                    view.index(),
                    view.buffer().index(),
                    buffer.len()
                ))
            })?;
        let count = accessor.count();
        let extent = match count {
            0 => Some(0),
            n => (n - 1)
                .checked_mul(stride)
                .and_then(|x| x.checked_add(item))
                .and_then(|x| x.checked_add(accessor.offset())),
        };
        let data = match extent {
            Some(end) if stride >= item && end <= view_bytes.len() => {
                &view_bytes[accessor.offset()..]
            }
            _ => {
                return Err(invalid(format!(
                    "{} ({count} items of {item} bytes, {stride} apart) runs past its buffer view \
                     ({} bytes)",
                    what(),
                    view_bytes.len()
                )))
            }
        };
        Ok((0..count).map(move |k| &data[k * stride..k * stride + item]))
    }
}

/// A primitive's triangles from its indices, by its mode.
fn triangles(mode: Mode, indices: &[u32]) -> Vec<[u32; 3]> {
    let n = indices.len();
    match mode {
        Mode::TriangleStrip => (2..n)
            .map(|k| match k % 2 {
                0 => [indices[k - 2], indices[k - 1], indices[k]],
                _ => [indices[k - 1], indices[k - 2], indices[k]],
            })
            .collect(),
        Mode::TriangleFan => (2..n)
            .map(|k| [indices[0], indices[k - 1], indices[k]])
            .collect(),
        _ => indices
            .chunks_exact(3)
            .map(|t| [t[0], t[1], t[2]])
            .collect(),
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// A glTF (JSON) of one triangle, its buffer as a data URI; `edit`
    /// changes the JSON before it is written.
    fn gltf_with(edit: impl FnOnce(&mut serde_json::Value)) -> Vec<u8> {
        gltf_indexed([0, 1, 2], edit)
    }

    /// [`gltf_with`], the triangle's corners given by `indices`.
    fn gltf_indexed(indices: [u16; 3], edit: impl FnOnce(&mut serde_json::Value)) -> Vec<u8> {
        let mut bin = Vec::new();
        for c in [0f32, 0., 0., 1., 0., 0., 0., 1., 0.] {
            bin.extend(c.to_le_bytes());
        }
        bin.extend(indices.iter().flat_map(|k| k.to_le_bytes()));
        bin.extend([0, 0]);
        let uri = format!(
            "data:application/octet-stream;base64,{}",
            base64::engine::general_purpose::STANDARD.encode(&bin)
        );
        let mut json = serde_json::json!({
            "asset": {"version": "2.0"},
            "scene": 0,
            "scenes": [{"nodes": [0]}],
            "nodes": [{"mesh": 0}],
            "meshes": [{"primitives": [{"attributes": {"POSITION": 0}, "indices": 1}]}],
            "accessors": [
                {"bufferView": 0, "componentType": 5126, "count": 3, "type": "VEC3",
                 "min": [0, 0, 0], "max": [1, 1, 0]},
                {"bufferView": 1, "componentType": 5123, "count": 3, "type": "SCALAR"}
            ],
            "bufferViews": [
                {"buffer": 0, "byteOffset": 0, "byteLength": 36},
                {"buffer": 0, "byteOffset": 36, "byteLength": 6}
            ],
            "buffers": [{"byteLength": 44, "uri": uri}]
        });
        edit(&mut json);
        serde_json::to_vec(&json).unwrap()
    }

    fn read(bytes: &[u8]) -> Result<RawMesh, MeshFileError> {
        let mut related = |_: &str| Err("none".to_string());
        super::super::parse(super::super::MeshFormat::Gltf, bytes, 1000, &mut related)
    }

    #[test]
    fn one_triangle_reads() {
        let mesh = read(&gltf_with(|_| {})).unwrap();
        assert_eq!(mesh.triangles, vec![[0, 1, 2]]);
        assert_eq!(mesh.vertices[1], Point3::new(1.0, 0.0, 0.0));
    }

    /// 200,000 nodes each the child of the one before (a file of 5 MB)
    /// are walked without recursion (it overflowed the stack), each
    /// moving the next by 1 along x, the mesh at the end; and children
    /// are walked in the file's order.
    #[test]
    fn nodes_nested_two_hundred_thousand_deep_are_read() {
        let depth = 200_000;
        let mesh = read(&gltf_with(|j| {
            let mut nodes: Vec<serde_json::Value> = (1..depth)
                .map(|k| serde_json::json!({"children": [k], "translation": [1, 0, 0]}))
                .collect();
            nodes.push(serde_json::json!({"mesh": 0}));
            j["nodes"] = serde_json::Value::Array(nodes);
        }))
        .unwrap();
        assert_eq!(
            mesh.vertices[0],
            Point3::new(f64::from(depth - 1), 0.0, 0.0)
        );
        let siblings = read(&gltf_with(|j| {
            j["scenes"][0]["nodes"] = serde_json::json!([0]);
            j["nodes"] = serde_json::json!([
                {"children": [1, 2]},
                {"mesh": 0, "translation": [5, 0, 0]},
                {"mesh": 0, "translation": [7, 0, 0]}
            ]);
        }))
        .unwrap();
        assert_eq!(siblings.vertices[0].x, 5.0);
        assert_eq!(siblings.vertices[3].x, 7.0);
    }

    /// An index accessor that claims 2^40 indices in a 44-byte buffer is an
    /// error in words, before anything is allocated for them.
    #[test]
    fn an_index_count_past_its_bytes_is_refused_before_allocating() {
        let err = read(&gltf_indexed([0, 1, 2], |j| {
            j["accessors"][1]["count"] = serde_json::json!(1u64 << 40);
        }))
        .unwrap_err();
        assert!(
            err.to_string().contains("runs past its buffer view"),
            "{err}"
        );
    }

    #[test]
    fn a_mirroring_node_keeps_the_faces_outwards() {
        let mesh = read(&gltf_with(|j| {
            j["nodes"][0]["scale"] = serde_json::json!([-1, 1, 1])
        }))
        .unwrap();
        assert_eq!(mesh.triangles, vec![[1, 0, 2]]);
        assert_eq!(mesh.vertices[1], Point3::new(-1.0, 0.0, 0.0));
    }

    /// Each malformed file is an error in words, never a panic: the cases
    /// on which the `gltf` crate's own reader would assert or slice out of
    /// bounds.
    #[test]
    fn malformed_accessors_are_errors() {
        type Edit = fn(&mut serde_json::Value);
        let cases: [(Edit, &str); 9] = [
            (
                |j| j["meshes"][0]["primitives"][0]["attributes"]["POSITION"] = 5.into(),
                "POSITION names accessor 5",
            ),
            (
                |j| j["accessors"][0]["type"] = "SCALAR".into(),
                "not three 32-bit floats",
            ),
            (
                |j| j["accessors"][0]["componentType"] = 5121.into(),
                "not three 32-bit floats",
            ),
            (
                |j| j["accessors"][1]["componentType"] = 5126.into(),
                "not unsigned integers",
            ),
            (
                |j| j["accessors"][0]["count"] = 4.into(),
                "runs past its buffer view",
            ),
            (
                |j| j["bufferViews"][0]["byteStride"] = 4.into(),
                "runs past its buffer view",
            ),
            (
                |j| j["bufferViews"][1]["byteOffset"] = 40.into(),
                "runs past the end of buffer",
            ),
            (
                |j| j["buffers"][0]["byteLength"] = 4400.into(),
                "declares 4400 bytes",
            ),
            (
                |j| j["nodes"][0]["children"] = serde_json::json!([0]),
                "two parents",
            ),
        ];
        for (edit, says) in cases {
            let err = read(&gltf_with(edit)).unwrap_err().to_string();
            assert!(err.contains(says), "{err}");
        }
        let past = gltf_indexed([0, 1, 7], |_| {});
        assert!(read(&past)
            .unwrap_err()
            .to_string()
            .contains("index 7, past its 3 vertices"));
    }

    #[test]
    fn a_glb_header_shorter_than_itself_is_an_error() {
        let mut glb = b"glTF".to_vec();
        glb.extend(2u32.to_le_bytes());
        glb.extend(4u32.to_le_bytes());
        glb.extend([0u8; 20]);
        let err = read(&glb).unwrap_err().to_string();
        assert!(err.contains("GLB header says 4 bytes"), "{err}");
        assert!(read(b"glTF\x02\0")
            .unwrap_err()
            .to_string()
            .contains("cut short"));
    }

    #[test]
    fn strips_and_fans_become_triangles() {
        assert_eq!(
            triangles(Mode::TriangleStrip, &[0, 1, 2, 3]),
            vec![[0, 1, 2], [2, 1, 3]]
        );
        assert_eq!(
            triangles(Mode::TriangleFan, &[0, 1, 2, 3]),
            vec![[0, 1, 2], [0, 2, 3]]
        );
    }
}
