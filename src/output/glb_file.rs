//! The format `glb`: `scene.glb`, the scene of the 3D page as one binary
//! glTF file (`glb/`), written by `--out` (binary: nothing for standard
//! output).

use super::glb::glb;
use super::view::view_data;
use crate::plugin::{FormatPlugin, FormatScene, ParamSpec, Plugin};
use crate::report::Report;

/// The plugin `glb`.
pub struct GlbFile;

impl Plugin for GlbFile {
    fn name(&self) -> &'static str {
        "glb"
    }

    fn doc(&self) -> &'static str {
        "scene.glb: the rooms and each task's person in its posture as binary glTF, one scene per task (--out only)"
    }

    fn params(&self) -> Vec<ParamSpec> {
        Vec::new()
    }
}

impl FormatPlugin for GlbFile {
    fn files(&self, report: &Report, scene: &FormatScene<'_>) -> Vec<(String, Vec<u8>)> {
        vec![("scene.glb".into(), glb(&view_data(report, scene)))]
    }

    fn render(&self, _: &Report, _: &FormatScene<'_>) -> Option<String> {
        None
    }

    fn prints(&self) -> bool {
        false
    }
}
