//! Output formats, each a plugin, and the files written for each map.

mod json;
pub mod json_layout;
pub mod map_files;
mod text;

pub use json::Json;
pub use text::Text;
