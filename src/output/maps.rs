//! The format `maps`: for each map (a person's, or a population's by the
//! share of its people who reach each point) its points as CSV and its
//! picture as SVG (`map_files.rs`), written by `--out` (a file for each
//! map: nothing for standard output).

use super::map_files::{self, Picture};
use super::view::room_views;
use crate::plugin::{FormatPlugin, FormatScene, ParamSpec, Plugin};
use crate::report::{Report, TaskReport};

/// The plugin `maps`.
pub struct Maps;

impl Plugin for Maps {
    fn name(&self) -> &'static str {
        "maps"
    }

    fn doc(&self) -> &'static str {
        "each map's points as CSV and its picture (plan or elevation) as SVG, named after the surface and the person (--out only)"
    }

    fn params(&self) -> Vec<ParamSpec> {
        Vec::new()
    }
}

impl FormatPlugin for Maps {
    fn files(&self, report: &Report, scene: &FormatScene<'_>) -> Vec<(String, Vec<u8>)> {
        let mut files = Vec::new();
        if !report.tasks.iter().any(|t| map_file_parts(t).is_some()) {
            return files;
        }
        // The rooms as the page draws them, for the furniture beside a map.
        let rooms = room_views(scene.rooms);
        let mut stems: Vec<String> = Vec::new();
        for (index, task) in report.tasks.iter().enumerate() {
            let Some((base, csv, picture)) = map_file_parts(task) else {
                continue;
            };
            // Two maps of one surface by one person (a reach and a gaze
            // map, or two option sets) get distinct names, in the order of
            // tasks.
            let taken = stems.iter().filter(|s| s.as_str() == base).count();
            stems.push(base.clone());
            let stem = match taken {
                0 => base,
                n => format!("{base}-{}", n + 1),
            };
            files.push((format!("{stem}.csv"), csv.into_bytes()));
            let room = scene.tasks.get(index).and_then(|t| rooms.get(t.room));
            let svg = map_files::picture_svg(&picture, room);
            files.push((format!("{stem}.svg"), svg.into_bytes()));
        }
        files
    }

    fn render(&self, _: &Report, _: &FormatScene<'_>) -> Option<String> {
        None
    }

    fn prints(&self) -> bool {
        false
    }
}

/// A map's file stem, CSV and picture: a person's map, or a population's
/// (by the share of its people who reach each point).
fn map_file_parts(task: &TaskReport) -> Option<(String, String, Picture)> {
    if let Some(m) = task.map() {
        return Some((
            map_files::file_stem(m),
            map_files::csv(m),
            Picture::of_map(m),
        ));
    }
    let TaskReport::Population(p) = task else {
        return None;
    };
    let (grid, cells) = (p.grid.as_ref()?, p.cells.as_ref()?);
    Some((
        map_files::population_stem(p, grid),
        map_files::population_csv(p, cells),
        Picture::of_population(p, grid, cells),
    ))
}
