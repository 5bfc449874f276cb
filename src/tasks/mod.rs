//! Tasks: what a scenario asks of a person, each a plugin. A task plugin
//! is configured from its options into a [`crate::plugin::Task`], which
//! runs on what the checker resolved.

mod advise;
mod common;
mod gaze;
mod gaze_map;
mod grid_settings;
mod hand;
mod map;
mod map_grid;
mod reach;
mod reach_and_gaze;
mod walk_in;
mod why;

pub use advise::Advise;
pub use common::{mix_seed, Common};
pub use gaze::Gaze;
pub use gaze_map::GazeMap;
pub use map::Map;
pub use reach::{Reach, ReachSettings};
pub use reach_and_gaze::ReachAndGaze;
