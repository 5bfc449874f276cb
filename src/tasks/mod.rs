//! Tasks: what a scenario asks of a person, each a plugin.

mod reach;

pub use reach::Reach;
