//! Tasks: what a scenario asks of a person, each a plugin.

mod map;
mod reach;

pub use map::Map;
pub use reach::Reach;
