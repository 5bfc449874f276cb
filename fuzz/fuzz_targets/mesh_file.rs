//! Fuzz the mesh readers alone (OBJ, STL, glTF/GLB): the first byte picks
//! the format, the rest is the file. No input may panic, hang or allocate
//! past what its size allows; a mesh that reads has finite vertices and
//! indices within them.
#![no_main]

use libfuzzer_sys::fuzz_target;
use reach::meshfile::{parse, MeshFormat};

fuzz_target!(|data: &[u8]| {
    let Some((&pick, bytes)) = data.split_first() else {
        return;
    };
    let formats = MeshFormat::EXTENSIONS;
    let (_, format) = formats[usize::from(pick) % formats.len()];
    let mut related = |_: &str| Err("no related files".to_string());
    if let Ok(mesh) = parse(format, bytes, 1 << 16, &mut related) {
        let n = mesh.vertices.len();
        assert!(mesh.triangles.iter().flatten().all(|&k| (k as usize) < n));
    }
});
