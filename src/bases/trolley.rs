//! The `trolley` base: a standing person with a trolley or rollator. The
//! hip point is at standing hip height; the footprint is a circle, so
//! turning does not change where it fits (section 4.3 of the paper).

use super::placement::Mobile;
use super::zone;
use crate::floor::Footprint;
use crate::kinematics::Chain;
use crate::plugin::{Base, BasePlugin, Options, ParamSpec, Plugin, PreparedBase};
use crate::scene::Room;

/// The plugin `trolley`.
pub struct Trolley;

impl Plugin for Trolley {
    fn name(&self) -> &'static str {
        "trolley"
    }

    fn doc(&self) -> &'static str {
        "standing with a trolley or rollator: a circle on the floor, free to turn"
    }

    fn params(&self) -> Vec<ParamSpec> {
        vec![
            ParamSpec::length("radius", 450.0, "the circle the person and trolley need")
                .range(100.0, 2000.0),
            // 0.530 x 1755 mm: hip height of the 50th-percentile man (human-data.md).
            ParamSpec::length(
                "hip_height",
                930.0,
                "height of the hip point (the chain's base)",
            )
            .range(200.0, 1500.0),
            ParamSpec::length(
                "clearance",
                1900.0,
                "obstacles whose bottom is lower than this block the floor",
            )
            .range(0.0, 5000.0),
            ParamSpec::integer("headings", 16, "directions tried to face the target")
                .range(1.0, 360.0),
            ParamSpec::optional_point(
                "zone_from",
                "one corner of the floor zone the person must stay in",
            ),
            ParamSpec::optional_point("zone_to", "the opposite corner"),
        ]
    }
}

impl BasePlugin for Trolley {
    fn build(&self, o: &Options) -> Box<dyn Base> {
        Box::new(Mobile {
            footprint: Footprint::Circle {
                radius_mm: o.length_mm("radius"),
            },
            hip_height_mm: o.length_mm("hip_height"),
            clearance_mm: o.length_mm("clearance"),
            headings: o.integer("headings") as u32,
            zone: zone(o),
        })
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
