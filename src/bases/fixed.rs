//! The `fixed` base: the person's hip point at a given place and heading.

use nalgebra::Point3;

use super::search::search;
use crate::kinematics::Chain;
use crate::plugin::{
    Base, BasePlugin, BasePose, Options, ParamSpec, Placement, Plugin, PreparedBase, ReachQuery,
    Solver,
};
use crate::scene::Room;

/// The plugin `fixed`.
pub struct Fixed;

impl Plugin for Fixed {
    fn name(&self) -> &'static str {
        "fixed"
    }

    fn doc(&self) -> &'static str {
        "the base (hip point) stays where it is put"
    }

    fn params(&self) -> Vec<ParamSpec> {
        vec![
            ParamSpec::point(
                "at",
                "the hip point in the room: x, y on the floor and z its height",
            ),
            ParamSpec::angle(
                "heading",
                0.0,
                "the direction the person faces, counter-clockwise from the room's x axis",
            ),
        ]
    }
}

impl BasePlugin for Fixed {
    fn build(&self, o: &Options) -> Box<dyn Base> {
        Box::new(FixedBase {
            pose: BasePose {
                position_mm: Point3::from(o.point_mm("at")),
                heading_rad: o.angle_rad("heading"),
            },
        })
    }
}

struct FixedBase {
    pose: BasePose,
}

impl Base for FixedBase {
    /// The hip point must be inside the room.
    fn fits(&self, room: &Room) -> bool {
        room.contains(&self.pose.position_mm)
    }

    fn prepare<'a>(&'a self, _: &'a Room, chain: &'a Chain) -> Box<dyn PreparedBase + 'a> {
        Box::new(Prepared {
            pose: self.pose,
            chain,
        })
    }
}

struct Prepared<'a> {
    pose: BasePose,
    chain: &'a Chain,
}

impl PreparedBase for Prepared<'_> {
    fn reach(&self, query: &ReachQuery<'_>, solver: &dyn Solver) -> Placement {
        search(query, self.chain, &[self.pose], solver).expect("one pose gives one placement")
    }
}
