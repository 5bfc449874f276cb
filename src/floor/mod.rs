//! The floor: where a base can stand. A footprint (a circle for a trolley,
//! a rectangle for a wheelchair) placed in a room, and the admissible region
//! of hip points where it fits, computed with the `geo` polygon library.

mod footprint;
mod inside;
mod region;

pub use footprint::{FloorPart, Footprint};
pub use inside::Inside;
pub use region::{admissible, Zone};
