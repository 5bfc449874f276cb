//! Bases: where the person stands or sits, each a plugin. `fixed` stays
//! put; `trolley` and `wheelchair` move on the floor (`placement.rs`);
//! all search their candidate placements alike (`search.rs`). A
//! mobile base's candidates come from the person's capability map
//! (`capability.rs`) within what its options allow (`placing.rs`).

mod bound_floor;
mod capability;
#[cfg(test)]
mod descents_tests;
mod face;
mod fixed;
mod placement;
mod placing;
pub mod search;
mod trolley;
mod wheelchair;

pub use face::ON_FACE_MM;
pub use fixed::{Fixed, FixedSettings};
pub use placement::Mobile;
pub use placing::{Approach, Placing, PlacingSettings};
pub use search::retry;
pub use trolley::{Trolley, TrolleySettings};
pub use wheelchair::{Wheelchair, WheelchairSettings};
