//! The `fixed` base: the person's hip point at a given place and heading.

use nalgebra::{Point3, Vector3};

use super::search::{search, search_retrying_later, Candidate};
use crate::allowance::Allowance;
use crate::kinematics::{Chain, Stance};
use crate::plugin::{
    Base, BaseError, BasePlugin, BasePose, Fit, Hips, Options, ParamSpec, Params, Placement,
    Plugin, PreparedBase, ReachQuery, Settings, Solver,
};
use crate::scene::{Blocked, IkSolution, OwnBody, Physique, Room};

/// The plugin `fixed`.
pub struct Fixed;

/// Its settings.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct FixedSettings {
    pub at_mm: Vector3<f64>,
    pub heading_rad: f64,
}

impl Settings for FixedSettings {
    fn visit(p: &mut Params<'_>) -> Self {
        FixedSettings {
            at_mm: p
                .point(
                    "at",
                    "the hip point in the room: x, y on the floor and z its height",
                )
                .get(),
            heading_rad: p
                .angle(
                    "heading",
                    0.0,
                    "the direction the person faces, counter-clockwise from the room's x axis",
                )
                .get(),
        }
    }
}

impl Plugin for Fixed {
    fn name(&self) -> &'static str {
        "fixed"
    }

    fn doc(&self) -> &'static str {
        "the base (hip point) stays where it is put"
    }

    fn params(&self) -> Vec<ParamSpec> {
        FixedSettings::params()
    }
}

impl BasePlugin for Fixed {
    /// The person's legs as their mannequin has them: seated (on a seat
    /// their `hip_above_seat` below the hip point, feet forward), or
    /// standing.
    fn build(&self, options: &Options, person: &Physique) -> Result<Box<dyn Base>, BaseError> {
        let s = FixedSettings::from_options(options)?;
        let seated = person.posture == Some(Stance::Seated);
        let legs = person.legs.as_ref().map(|l| match seated {
            true => l.seated(20f64.to_radians()),
            false => l.standing(),
        });
        let pelvis = person.legs.as_ref().map_or(0.0, |l| l.pelvis_mm);
        let own = OwnBody::new(legs.unwrap_or_default(), pelvis);
        Ok(Box::new(FixedBase {
            pose: BasePose {
                position_mm: Point3::from(s.at_mm),
                heading_rad: s.heading_rad,
            },
            own: match seated {
                true => own,
                false => own.standing(person),
            },
        }))
    }
}

struct FixedBase {
    pose: BasePose,
    own: OwnBody,
}

impl Base for FixedBase {
    fn own_body(&self) -> &OwnBody {
        &self.own
    }

    /// Only the room's size, whether the hip point is in it.
    fn reads_room_through_floor(&self) -> bool {
        true
    }

    /// The hip point must be inside the room.
    fn fit(&self, room: &Room, _: &dyn Allowance) -> Fit {
        if self.outside(room) {
            Fit::Outside
        } else {
            Fit::Fits
        }
    }

    fn outside(&self, room: &Room) -> bool {
        !room.contains(&self.pose.position_mm)
    }

    fn prepare<'a>(
        &'a self,
        _: &'a Room,
        chain: &'a Chain,
        _: &dyn Allowance,
    ) -> Box<dyn PreparedBase + 'a> {
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

impl Prepared<'_> {
    /// Where nothing was solved: the neutral posture, infinitely far.
    fn unsolved(&self) -> Placement {
        Placement {
            pose: self.pose,
            solution: IkSolution::unsolved(self.chain),
            retried: false,
        }
    }
}

impl PreparedBase for Prepared<'_> {
    fn reach(&self, query: &ReachQuery<'_>, solver: &dyn Solver) -> Placement {
        search(query, self.chain, [Candidate::at(self.pose)], solver)
            .unwrap_or_else(|| self.unsolved())
    }

    fn reach_retrying_later(
        &self,
        query: &ReachQuery<'_>,
        solver: &dyn Solver,
    ) -> (Placement, Vec<Blocked>) {
        let candidates = [Candidate::at(self.pose)];
        let (kept, blocked) = search_retrying_later(query, self.chain, candidates, solver);
        (kept.unwrap_or_else(|| self.unsolved()), blocked)
    }

    fn hips(&self, _target_room_mm: &Point3<f64>, _tolerance_mm: f64) -> Hips {
        Hips {
            poses: vec![self.pose],
            around: None,
        }
    }
}
