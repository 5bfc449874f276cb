//! Tasks: what a scenario asks of a person, each a plugin.

mod common;
mod gaze;
mod gaze_map;
mod map;
mod reach;
mod reach_and_gaze;

pub use common::mix_seed;
pub use gaze::{person_vision_params, Gaze};
pub use gaze_map::GazeMap;
pub use map::Map;
pub use reach::Reach;
pub use reach_and_gaze::ReachAndGaze;
