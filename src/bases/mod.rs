//! Bases: where the person stands or sits, each a plugin. `fixed` stays
//! put; `trolley` and `wheelchair` move on the floor (`placement.rs`);
//! all search their candidate placements alike (`search.rs`).

mod fixed;
mod placement;
mod search;
mod trolley;
mod wheelchair;

pub use fixed::{Fixed, FixedSettings};
pub use placement::Mobile;
pub use trolley::{Trolley, TrolleySettings};
pub use wheelchair::{Wheelchair, WheelchairSettings};

use nalgebra::Vector3;

use crate::floor::Zone;
use crate::plugin::{Params, SettingsError};

/// The options `zone_from` and `zone_to` of a mobile base: two opposite
/// corners of the floor zone, `what` standing for who stays in it.
fn zone_params(p: &mut Params<'_>, what: &'static str) -> [Option<Vector3<f64>>; 2] {
    [
        p.optional_point("zone_from", what).get(),
        p.optional_point("zone_to", "the opposite corner").get(),
    ]
}

/// The zone two corners give: both or neither must be given.
fn zone(corners: [Option<Vector3<f64>>; 2]) -> Result<Option<Zone>, SettingsError> {
    match corners {
        [Some(a), Some(b)] => Ok(Some(Zone {
            min: (a.x.min(b.x), a.y.min(b.y)),
            max: (a.x.max(b.x), a.y.max(b.y)),
        })),
        [None, None] => Ok(None),
        [Some(_), None] => Err(SettingsError::invalid(
            "zone_from",
            "a zone needs `zone_to` too, its opposite corner",
        )),
        [None, Some(_)] => Err(SettingsError::invalid(
            "zone_to",
            "a zone needs `zone_from` too, its opposite corner",
        )),
    }
}
