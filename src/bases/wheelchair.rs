//! The `wheelchair` base: a seated person. The hip point is at seated hip
//! height; the footprint is a rectangle whose place on the floor depends on
//! the heading theta_0 (section 5.3.6 of the paper).
//!
//! Defaults from ../shared/reference/human-data.md: a manual chair for a
//! large adult is 1065 mm long (plus about 150 mm for the toes) and 660 mm
//! wide (1991 ADA guidelines, fig. A3); manual seat height 495 mm (IDeA
//! Center, 2010); the hip point is taken 100 mm above the seat and 650 mm
//! behind the toes.

use nalgebra::Vector3;

use super::placement::Mobile;
use super::{zone, zone_params};
use crate::floor::Footprint;
use crate::plugin::{
    Base, BasePlugin, Options, ParamSpec, Params, Plugin, Settings, SettingsError,
};

/// The plugin `wheelchair`.
pub struct Wheelchair;

/// Its settings.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct WheelchairSettings {
    pub length_mm: f64,
    pub width_mm: f64,
    pub hip_to_front_mm: f64,
    pub seat_height_mm: f64,
    pub hip_above_seat_mm: f64,
    pub clearance_mm: f64,
    pub headings: u32,
    pub zone_mm: [Option<Vector3<f64>>; 2],
}

impl Settings for WheelchairSettings {
    fn visit(p: &mut Params<'_>) -> Self {
        WheelchairSettings {
            length_mm: p
                .length("length", 1215.0, "length with footrests and toes")
                .range(300.0, 3000.0)
                .get(),
            width_mm: p
                .length("width", 660.0, "overall width")
                .range(300.0, 2000.0)
                .get(),
            hip_to_front_mm: p
                .length(
                    "hip_to_front",
                    650.0,
                    "from the hip point forward to the front of the footprint",
                )
                .range(0.0, 3000.0)
                .get(),
            seat_height_mm: p
                .length("seat_height", 495.0, "seat height above the floor")
                .range(200.0, 1000.0)
                .get(),
            hip_above_seat_mm: p
                .length("hip_above_seat", 100.0, "hip point above the seat")
                .range(0.0, 400.0)
                .get(),
            clearance_mm: p
                .length(
                    "clearance",
                    1400.0,
                    "obstacles whose bottom is lower than this block the floor",
                )
                .range(0.0, 5000.0)
                .get(),
            headings: p
                .integer("headings", 16, "headings of the chair tried")
                .range(1.0, 360.0)
                .get() as u32,
            zone_mm: zone_params(p, "one corner of the floor zone the chair must stay in"),
        }
    }
}

impl Plugin for Wheelchair {
    fn name(&self) -> &'static str {
        "wheelchair"
    }

    fn doc(&self) -> &'static str {
        "seated in a wheelchair: a rectangle on the floor that turns with the chair"
    }

    fn params(&self) -> Vec<ParamSpec> {
        WheelchairSettings::params()
    }
}

impl BasePlugin for Wheelchair {
    fn build(&self, options: &Options) -> Result<Box<dyn Base>, SettingsError> {
        let s = WheelchairSettings::from_options(options)?;
        let front = s.hip_to_front_mm;
        Ok(Box::new(Mobile {
            footprint: Footprint::Rectangle {
                front_mm: front,
                back_mm: (s.length_mm - front).max(0.0),
                width_mm: s.width_mm,
            },
            hip_height_mm: s.seat_height_mm + s.hip_above_seat_mm,
            clearance_mm: s.clearance_mm,
            headings: s.headings,
            zone: zone(s.zone_mm)?,
        }))
    }
}
