//! Output formats, each a plugin, and the files `--out DIR` writes.

pub mod colours;
mod files;
pub mod glb;
pub mod html;
mod journal;
mod json;
pub mod json_layout;
pub mod map_files;
mod placing;
mod text;
pub mod view;

pub use files::{write_outputs, write_set};
pub use html::Html;
pub use json::Json;
pub use text::Text;
