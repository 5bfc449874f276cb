//! Fuzz the mesh readers alone (OBJ, STL, glTF/GLB): the first byte picks
//! the format, the rest is the file. No input may panic, hang or allocate
//! past what its size allows; a mesh that reads has finite vertices and
//! indices within them.
#![no_main]

use libfuzzer_sys::fuzz_target;
use reach::meshfile::{parse, MeshFormat, EXTENSIONS};

fuzz_target!(|data: &[u8]| {
    let Some((&pick, bytes)) = data.split_first() else {
        return;
    };
    let ext = EXTENSIONS[usize::from(pick) % EXTENSIONS.len()];
    let Some(format) = MeshFormat::of(std::path::Path::new(&format!("m.{ext}"))) else {
        return;
    };
    let mut related = |_: &str| Err("no related files".to_string());
    if let Ok(mesh) = parse(format, bytes, 1 << 16, &mut related) {
        let n = mesh.vertices.len();
        assert!(mesh.triangles.iter().flatten().all(|&k| (k as usize) < n));
    }
});
