//! The `wheelchair` base: a seated person. The hip point is at seated hip
//! height; the footprint is a rectangle whose place on the floor depends on
//! the heading theta_0 (section 5.3.6 of the paper).
//!
//! Defaults from ../shared/reference/human-data.md: a manual chair for a
//! large adult is 1065 mm long (plus about 150 mm for the toes) and 660 mm
//! wide (1991 ADA guidelines, fig. A3); manual seat height 495 mm (IDeA
//! Center, 2010); the hip point is taken 100 mm above the seat and 650 mm
//! behind the toes.

use super::placement::Mobile;
use super::zone;
use crate::floor::Footprint;
use crate::plugin::{BasePlugin, Options, ParamSpec, Plugin};

/// The plugin `wheelchair`.
pub struct Wheelchair;

impl Plugin for Wheelchair {
    fn name(&self) -> &'static str {
        "wheelchair"
    }

    fn doc(&self) -> &'static str {
        "seated in a wheelchair: a rectangle on the floor that turns with the chair"
    }

    fn params(&self) -> Vec<ParamSpec> {
        vec![
            ParamSpec::length("length", 1215.0, "length with footrests and toes")
                .range(300.0, 3000.0),
            ParamSpec::length("width", 660.0, "overall width").range(300.0, 2000.0),
            ParamSpec::length(
                "hip_to_front",
                650.0,
                "from the hip point forward to the front of the footprint",
            )
            .range(0.0, 3000.0),
            ParamSpec::length("seat_height", 495.0, "seat height above the floor")
                .range(200.0, 1000.0),
            ParamSpec::length("hip_above_seat", 100.0, "hip point above the seat")
                .range(0.0, 400.0),
            ParamSpec::length(
                "clearance",
                1400.0,
                "obstacles whose bottom is lower than this block the floor",
            )
            .range(0.0, 5000.0),
            ParamSpec::integer("headings", 16, "headings of the chair tried").range(1.0, 360.0),
            ParamSpec::optional_point(
                "zone_from",
                "one corner of the floor zone the chair must stay in",
            ),
            ParamSpec::optional_point("zone_to", "the opposite corner"),
        ]
    }
}

impl BasePlugin for Wheelchair {
    fn build(&self, o: &Options) -> Box<dyn crate::plugin::Base> {
        let front = o.length_mm("hip_to_front");
        Box::new(Mobile {
            footprint: Footprint::Rectangle {
                front_mm: front,
                back_mm: (o.length_mm("length") - front).max(0.0),
                width_mm: o.length_mm("width"),
            },
            hip_height_mm: o.length_mm("seat_height") + o.length_mm("hip_above_seat"),
            clearance_mm: o.length_mm("clearance"),
            headings: o.integer("headings") as u32,
            zone: zone(o),
        })
    }
}
