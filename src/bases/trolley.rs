//! The `trolley` base: a standing person with a trolley or rollator. The
//! hip point is at standing hip height; the footprint is a circle, so
//! turning does not change where it fits (section 4.3 of the paper).

use nalgebra::Vector3;

use super::placement::Mobile;
use super::{zone, zone_params};
use crate::floor::Footprint;
use crate::kinematics::Chain;
use crate::plugin::{
    Base, BasePlugin, Options, ParamSpec, Params, Plugin, PreparedBase, Settings, SettingsError,
};
use crate::scene::Room;

/// The plugin `trolley`.
pub struct Trolley;

/// Its settings.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct TrolleySettings {
    pub radius_mm: f64,
    pub hip_height_mm: f64,
    pub clearance_mm: f64,
    pub headings: u32,
    pub zone_mm: [Option<Vector3<f64>>; 2],
}

impl Settings for TrolleySettings {
    fn visit(p: &mut Params<'_>) -> Self {
        TrolleySettings {
            radius_mm: p
                .length("radius", 450.0, "the circle the person and trolley need")
                .range(100.0, 2000.0)
                .get(),
            // 0.530 x 1755 mm: hip height of the 50th-percentile man (human-data.md).
            hip_height_mm: p
                .length(
                    "hip_height",
                    930.0,
                    "height of the hip point (the chain's base)",
                )
                .range(200.0, 1500.0)
                .get(),
            clearance_mm: p
                .length(
                    "clearance",
                    1900.0,
                    "obstacles whose bottom is lower than this block the floor",
                )
                .range(0.0, 5000.0)
                .get(),
            headings: p
                .integer("headings", 16, "directions tried to face the target")
                .range(1.0, 360.0)
                .get() as u32,
            zone_mm: zone_params(p, "one corner of the floor zone the person must stay in"),
        }
    }
}

impl Plugin for Trolley {
    fn name(&self) -> &'static str {
        "trolley"
    }

    fn doc(&self) -> &'static str {
        "standing with a trolley or rollator: a circle on the floor, free to turn"
    }

    fn params(&self) -> Vec<ParamSpec> {
        TrolleySettings::params()
    }
}

impl BasePlugin for Trolley {
    fn build(&self, options: &Options) -> Result<Box<dyn Base>, SettingsError> {
        let s = TrolleySettings::from_options(options)?;
        Ok(Box::new(Mobile {
            footprint: Footprint::Circle {
                radius_mm: s.radius_mm,
            },
            hip_height_mm: s.hip_height_mm,
            clearance_mm: s.clearance_mm,
            headings: s.headings,
            zone: zone(s.zone_mm)?,
        }))
    }
}

impl Base for Mobile {
    fn fits(&self, room: &Room) -> bool {
        Mobile::fits(self, room)
    }

    fn prepare<'a>(&'a self, room: &'a Room, chain: &'a Chain) -> Box<dyn PreparedBase + 'a> {
        Box::new(Mobile::prepare(self, room, chain))
    }

    fn placements(&self) -> u64 {
        u64::from(self.headings)
    }
}
