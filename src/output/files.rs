//! What `--out DIR` writes: `DIR/report.json` and, for each map, its CSV
//! and SVG (`map_files.rs`), each written atomically, so that a reader
//! (a browser, a diff in watch mode) sees the old file or the new one,
//! never half of one.

use std::io::Write;
use std::path::Path;

use super::map_files;
use super::Json;
use crate::error::{Error, ErrorKind};
use crate::plugin::FormatPlugin;
use crate::report::Report;

/// `DIR/report.json`, and a CSV and an SVG for each map.
pub fn write_outputs(report: &Report, dir: &Path) -> Result<(), Error> {
    write_atomically(&dir.join("report.json"), Json.render(report).as_bytes())?;
    for task in &report.tasks {
        if let Some(m) = task.map() {
            let stem = map_files::file_stem(m);
            write_atomically(
                &dir.join(format!("{stem}.csv")),
                map_files::csv(m).as_bytes(),
            )?;
            write_atomically(
                &dir.join(format!("{stem}.svg")),
                map_files::svg(m).as_bytes(),
            )?;
        }
    }
    Ok(())
}

/// Write `bytes` to a temporary file beside `path`, then rename it over
/// `path`: a reader sees the old file or the new one, never half of one.
fn write_atomically(path: &Path, bytes: &[u8]) -> Result<(), Error> {
    let fail = |e: std::io::Error| {
        Error::unplaced(ErrorKind::WriteFile {
            path: path.display().to_string(),
            reason: e.to_string(),
        })
    };
    let dir = path.parent().unwrap_or(Path::new("."));
    std::fs::create_dir_all(dir).map_err(fail)?;
    let mut tmp = tempfile::NamedTempFile::new_in(dir).map_err(fail)?;
    tmp.write_all(bytes).map_err(fail)?;
    tmp.as_file().sync_all().map_err(fail)?;
    tmp.persist(path).map_err(|e| fail(e.error))?;
    Ok(())
}
