//! The floor: where a base can stand. A footprint (a circle for a trolley,
//! a rectangle for a wheelchair, or the solids of a chair and legs) placed
//! in a room, the room's boxes and meshes as the footprint's parts meet
//! them, and the admissible region of hip points where it fits, computed
//! with the `geo` polygon library a tile at a time; where it fits nowhere,
//! by how much (`misfit.rs`).

mod clear;
mod footprint;
mod group;
mod inside;
mod layer;
mod mesh_cells;
mod misfit;
mod obstacles;
mod region;
mod routes;
mod shared_routes;
mod tiles;
mod work;

#[cfg(test)]
mod test_boxes;

pub use clear::{
    disc_centre, door_clear_width, knee_limited, route_width, t_space, FreeFloor, RouteFloor,
};
pub use footprint::{FloorPart, Footprint};
pub use group::{FloorGroup, GROUP_MARGIN_MM};
pub use inside::Inside;
pub use mesh_cells::{CELL_MM, FLOOR_TOLERANCE_MM};
pub use misfit::Misfit;
pub use obstacles::FloorObstacles;
pub use region::{admissible, Zone};
pub use routes::{Doorway, Entry, Routes, Shut};
pub use shared_routes::DoorRoutes;
pub use tiles::{emptiness_each, Bounds, Region};
pub use work::{unbounded, CutShort, Looked, Work};
