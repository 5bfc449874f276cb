//! Output formats, each a plugin.

mod json;
mod text;

pub use json::Json;
pub use text::Text;
