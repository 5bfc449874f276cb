//! Output formats, each a plugin that makes its files of a report, and
//! the set of all of them that `--out DIR` writes.

mod advice_files;
mod advice_grid_plot;
mod advice_plot;
pub mod colours;
mod files;
pub mod glb;
mod glb_file;
pub mod html;
mod journal;
mod json;
pub mod json_layout;
pub mod map_files;
mod maps;
mod placing;
mod seal;
mod text;
mod ticks;
pub mod view;

pub use advice_files::AdviceFiles;
pub use files::{output_set, write_outputs, write_set, Written};
pub use glb_file::GlbFile;
pub use html::Html;
pub use json::Json;
pub use maps::Maps;
pub use text::Text;
