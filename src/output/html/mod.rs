//! The `html` format: one self-contained page (`report.html` under `--out`)
//! that opens offline in a browser and shows the room, the person in each
//! task's posture where the base stood, the targets coloured by result, a
//! gaze's line of sight and what blocked it, maps as graded cells, and the
//! text report's facts beside the view. The scene is drawn by three.js
//! (`three/`, vendored from the npm registry and embedded at build time):
//! a well-kept WebGL library with orbit controls, rather than a renderer
//! of our own. The modules are embedded as text and loaded from blob URLs,
//! which a page opened from `file://` may import.
//!
//! Under `--out`, the page also loads `report-stamp.js` every second (a
//! script element re-inserted, which works over `file://` where `fetch`
//! does not) and reloads itself when the stamp changes, so a browser
//! beside `reach watch` follows the file as it is edited.

use super::view::{view_data, ViewData};
use crate::escape::markup;
use crate::plugin::{FormatPlugin, FormatScene, ParamSpec, Plugin};
use crate::report::Report;

const PAGE: &str = include_str!("page.html");
const APP: &str = include_str!("app.js");
const THREE_CORE: &str = include_str!("three/three.core.min.js");
const THREE_MODULE: &str = include_str!("three/three.module.min.js");
const ORBIT_CONTROLS: &str = include_str!("three/OrbitControls.js");
const THREE_LICENSE: &str = include_str!("three/LICENSE");

/// The name of the stamp file the page polls, beside it.
pub const STAMP_FILE: &str = "report-stamp.js";

pub struct Html;

impl Plugin for Html {
    fn name(&self) -> &'static str {
        "html"
    }

    fn doc(&self) -> &'static str {
        "one self-contained page: the room, the person in each task's posture, and the answers, in 3D"
    }

    fn params(&self) -> Vec<ParamSpec> {
        Vec::new()
    }
}

impl FormatPlugin for Html {
    /// The page, which polls the stamp beside it, and the stamp.
    fn files(&self, report: &Report, scene: &FormatScene<'_>) -> Vec<(String, Vec<u8>)> {
        let view = view_data(report, scene);
        let page = PageData::of(&view);
        vec![
            ("report.html".into(), page.page(true).into_bytes()),
            (STAMP_FILE.into(), page.stamp_script().into_bytes()),
        ]
    }

    /// The page alone, which polls nothing.
    fn render(&self, report: &Report, scene: &FormatScene<'_>) -> Option<String> {
        Some(PageData::of(&view_data(report, scene)).page(false))
    }
}

/// A view made page data once: its JSON and the stamp of that JSON, for
/// the page and the stamp file beside it.
pub struct PageData<'v> {
    view: &'v ViewData,
    json: String,
    stamp: String,
}

impl<'v> PageData<'v> {
    pub fn of(view: &'v ViewData) -> Self {
        let json = serde_json::to_string(view).expect("plain data");
        let stamp = stamp_of(&json);
        PageData { view, json, stamp }
    }

    /// The page; `live` when a stamp file is written beside it to poll.
    pub fn page(&self, live: bool) -> String {
        let settings = serde_json::json!({
            "live": live,
            "stamp": self.stamp,
            "stampFile": STAMP_FILE,
        });
        fill(
            PAGE,
            &[
                ("title", &markup(&self.view.title)),
                ("settings", &script_safe(&settings.to_string())),
                ("data", &script_safe(&self.json)),
                ("three_license", &markup(THREE_LICENSE)),
                ("three_core", THREE_CORE),
                ("three_module", THREE_MODULE),
                ("orbit_controls", ORBIT_CONTROLS),
                ("app", APP),
            ],
        )
    }

    /// The stamp file's text: it calls the page back with the stamp of the
    /// data the page would now show.
    pub fn stamp_script(&self) -> String {
        format!(
            "window.reachStamp && window.reachStamp(\"{}\");\n",
            self.stamp
        )
    }
}

/// `template` with each `{{key}}` replaced by its value, in one pass (so
/// a value that holds `{{...}}` stays as it is).
fn fill(template: &str, values: &[(&str, &str)]) -> String {
    let mut out =
        String::with_capacity(template.len() + values.iter().map(|v| v.1.len()).sum::<usize>());
    let mut rest = template;
    while let Some(start) = rest.find("{{") {
        out.push_str(&rest[..start]);
        let after = &rest[start + 2..];
        let key = after.find("}}").map(|end| &after[..end]);
        match key.and_then(|k| values.iter().find(|(name, _)| *name == k)) {
            Some((name, value)) => {
                out.push_str(value);
                rest = &after[name.len() + 2..];
            }
            None => {
                out.push_str("{{");
                rest = after;
            }
        }
    }
    out.push_str(rest);
    out
}

/// A 64-bit FNV-1a hash of the page's data, in hex: what changes when the
/// answers or the scene do.
fn stamp_of(data: &str) -> String {
    format!("{:016x}", crate::scene::fnv1a(0, data.bytes()))
}

/// JSON safe inside a `<script>` element: no `<` at all, so no `</script>`
/// or `<!--` can end or confuse it.
fn script_safe(json: &str) -> String {
    json.replace('<', "\\u003c")
}
