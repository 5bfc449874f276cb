//! Bases: where the person stands or sits, each a plugin. `fixed` stays
//! put; `trolley` and `wheelchair` move on the floor (`placement.rs`);
//! all search their candidate placements alike (`search.rs`).

mod fixed;
mod placement;
mod search;
mod trolley;
mod wheelchair;

pub use fixed::Fixed;
pub use placement::Mobile;
pub use trolley::Trolley;
pub use wheelchair::Wheelchair;

use crate::floor::Zone;
use crate::plugin::Options;

/// The zone given by options `zone_from` and `zone_to`, if both are.
fn zone(o: &Options) -> Option<Zone> {
    let (a, b) = (o.point_mm_opt("zone_from")?, o.point_mm_opt("zone_to")?);
    Some(Zone {
        min: (a.x.min(b.x), a.y.min(b.y)),
        max: (a.x.max(b.x), a.y.max(b.y)),
    })
}
