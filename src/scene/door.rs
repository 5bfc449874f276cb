//! An entrance on one of a room's walls: where a base that moves comes in.
//! Where a room has doors, a placement counts only if the base can travel
//! there from one of them (`crate::floor::Routes`).

use std::f64::consts::{FRAC_PI_2, PI};

use super::Wall;

/// A door: the middle of its opening on a wall, and its width.
#[derive(Clone, Debug, PartialEq)]
pub struct Door {
    pub name: String,
    /// The wall it is in: `XMin` (x = 0), `XMax` (x = the room's length),
    /// `YMin` (y = 0) or `YMax` (y = its width).
    pub wall: Wall,
    /// The middle of the opening along the wall: its y in an x wall, its x
    /// in a y wall.
    pub along_mm: f64,
    pub width_mm: f64,
}

impl Door {
    /// The heading of a base that comes in through it, facing into the
    /// room.
    pub fn inward_heading_rad(&self) -> f64 {
        match self.wall {
            Wall::XMax => PI,
            Wall::YMin => FRAC_PI_2,
            Wall::YMax => -FRAC_PI_2,
            _ => 0.0,
        }
    }

    /// The ends of the opening along the wall.
    pub fn span_mm(&self) -> [f64; 2] {
        [
            self.along_mm - self.width_mm / 2.0,
            self.along_mm + self.width_mm / 2.0,
        ]
    }
}
