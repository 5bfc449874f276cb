//! Fuzz the output writers with hostile names: the bytes (as UTF-8, lossy)
//! name a URDF arm's elbow joint, its forearm link and the scenario's
//! file, which reach the report's text, JSON, page, glTF scene and each
//! map's CSV and SVG (why causes, tooltips, titles). No input may panic,
//! and every file of the set must stay what it claims to be: the checks of
//! tests/outputs.rs (`tests/output_checks.rs`, included here).
#![no_main]

use libfuzzer_sys::fuzz_target;

#[path = "../../tests/output_checks.rs"]
mod output_checks;

const URDF: &str = include_str!("../../tests/data/human_arm.urdf");

/// The page's `<script` tags with plain names.
static SCRIPTS: std::sync::OnceLock<usize> = std::sync::OnceLock::new();

fuzz_target!(|data: &[u8]| {
    let text = String::from_utf8_lossy(data);
    let mut parts = text.splitn(3, '\u{0}');
    let joint = parts.next().unwrap_or_default();
    let link = parts.next().unwrap_or("forearm");
    let file = parts.next().unwrap_or("fuzz");
    // Names the URDF or the file system refuse are other targets' inputs.
    let file: String = file.chars().filter(|&c| c != '/' && c != '\0').take(60).collect();
    if joint.is_empty() || link.is_empty() || joint == link || file.is_empty() {
        return;
    }
    let Ok(files) = output_checks::output_files(URDF, joint, link, &format!("{file}.reach")) else {
        return;
    };
    let scripts = *SCRIPTS.get_or_init(|| {
        let plain = output_checks::output_files(URDF, "elbow_flexion", "forearm", "plain.reach");
        let page = plain.expect("the plain scene").into_iter().find(|(n, _)| n == "report.html");
        page.map_or(0, |(_, page)| String::from_utf8_lossy(&page).matches("<script").count())
    });
    for (name, bytes) in &files {
        if let Some(problem) = output_checks::file_problem(name, bytes, scripts) {
            panic!("{problem}");
        }
    }
});
