//! The `gaze` task: can this person see the target well enough to use it?
//! After the visibility paper: the eyes are an effector whose chain ends in
//! a look link, a prismatic joint along the line of sight, kept between the
//! nearest and farthest legible distances of an object of the task's `size`
//! (eq. 1-2). The solver drives the look link's end onto the target within
//! the neck and eye limits; then the acuity at the angle left between the
//! line of sight and the target (eq. 3) must reach the threshold, and a ray
//! from the eyes to the target must meet no obstacle.

use nalgebra::{Point3, Vector3};

use super::common::{common_params, mix_seed, Setup};
use crate::collision::{Obstacles, PlacedObstacles};
use crate::error::ErrorKind;
use crate::kinematics::{Chain, Joint, JointKind};
use crate::plugin::{
    Options, ParamSpec, Placement, Plugin, PluginKind, Search, SubjectKind, TaskContext,
    TaskPlugin, Value,
};
use crate::report::{Asked, GazeReport, Sight, TaskReport};
use crate::scene::Room;
use crate::vision::{self, ARCMIN_RAD};

/// The plugin `gaze`.
pub struct Gaze;

impl Plugin for Gaze {
    fn name(&self) -> &'static str {
        "gaze"
    }

    fn doc(&self) -> &'static str {
        "can the person see the target: legible distance, eye and neck limits, acuity, line of sight"
    }

    fn params(&self) -> Vec<ParamSpec> {
        gaze_params("target")
    }
}

/// The options of a gaze at a target or a point (`what`): the common ones
/// with the eyes as effector and fabrik as solver, and those of vision.
pub(super) fn gaze_params(what: &'static str) -> Vec<ParamSpec> {
    let mut params = common_params(
        what,
        "seeds the solver's random starts (mixed with subject and person)",
    );
    for p in &mut params {
        match p.name {
            "effector" => {
                *p = ParamSpec::name(
                    "effector",
                    "eyes",
                    "the effector whose chain ends in the look link",
                )
            }
            // FABRIK turns the neck and eyes before the trunk, as people
            // do; the incremental solver moves every joint alike.
            "solver" => {
                *p = ParamSpec::plugin(
                    "solver",
                    PluginKind::Solver,
                    "fabrik",
                    "the IK solver and its options",
                )
            }
            _ => {}
        }
    }
    params.extend(vision_params());
    params
}

/// The options of what the eyes must make out: the object's size, the
/// minimum angles of resolution, the near point and the acuity threshold.
/// But for the size, a task leaves them to the person's `vision`, and
/// that to the defaults of [`VISION_DEFAULTS`].
pub(super) fn vision_params() -> Vec<ParamSpec> {
    vec![
        ParamSpec::length("size", 20.0, "the object's size S (a letter's height, a dial)").range(0.01, 10_000.0),
        ParamSpec::optional_angle("mar_far", "minimum angle of resolution, far vision (eq. 1); default 1arcmin")
            .range(0.01 * ARCMIN_RAD, 600.0 * ARCMIN_RAD),
        ParamSpec::optional_angle(
            "mar_near",
            "minimum angle of resolution, near vision (eq. 2); if left out the nearest distance is `near_point`",
        )
        .range(0.01 * ARCMIN_RAD, 600.0 * ARCMIN_RAD),
        ParamSpec::optional_length("near_point", "the nearest distance the eyes focus at when `mar_near` is not given; default 250mm")
            .range(0.0, 10_000.0),
        ParamSpec::optional_number("acuity", "the least acuity e^(-7 |angle|) at which the target counts as seen (eq. 3); default 0.5")
            .range(0.001, 1.0),
    ]
}

/// The defaults of the vision options a task and a person may leave out.
pub const VISION_DEFAULTS: [(&str, Value); 3] = [
    ("mar_far", Value::Angle(ARCMIN_RAD)),
    ("near_point", Value::Length(250.0)),
    ("acuity", Value::Number(0.5)),
];

/// The options a person's `vision` may give: those of `vision_params`
/// but the object's size.
pub fn person_vision_params() -> Vec<ParamSpec> {
    vision_params()
        .into_iter()
        .filter(|p| p.name != "size")
        .collect()
}

/// The task's options with every vision option filled in: the task's own,
/// else the person's `vision`, else the default.
pub(super) fn effective_vision(options: &Options, person: Option<&Options>) -> Options {
    let mut out = options.clone();
    for spec in person_vision_params() {
        if out.get(spec.name).is_some() {
            continue;
        }
        let value = person.and_then(|p| p.get(spec.name)).cloned().or_else(|| {
            VISION_DEFAULTS
                .iter()
                .find(|(n, _)| *n == spec.name)
                .map(|(_, v)| v.clone())
        });
        if let Some(value) = value {
            out = out.set(spec.name, value);
        }
    }
    out
}

/// An object too small to be legible anywhere, by the options.
pub(super) fn illegible(options: &Options) -> Option<ErrorKind> {
    let [d_min, d_max] = legible_mm(options);
    (d_min >= d_max).then(|| ErrorKind::Illegible {
        size: format!("{}mm", options.length_mm("size")),
        d_min: format!("{d_min:.0}mm"),
        d_max: format!("{d_max:.0}mm"),
    })
}

/// The legible range `[D_min, D_max]` the options give.
pub(super) fn legible_mm(options: &Options) -> [f64; 2] {
    let size = options.length_mm("size");
    let d_max = vision::d_max_mm(size, options.angle_rad("mar_far"));
    let d_min = match options.number_opt("mar_near") {
        Some(mar_near) => vision::d_min_mm(size, mar_near),
        None => options.length_mm("near_point"),
    };
    [d_min, d_max]
}

impl TaskPlugin for Gaze {
    fn subject(&self) -> SubjectKind {
        SubjectKind::Target
    }

    fn validate(&self, _room: &Room, _subject: &str, options: &Options) -> Option<ErrorKind> {
        illegible(&effective_vision(options, None))
    }

    fn validate_chain(
        &self,
        person: &str,
        _: &str,
        chain: &Chain,
        _: &Options,
    ) -> Option<ErrorKind> {
        needs_look_link(person, chain)
    }

    fn run(&self, ctx: &TaskContext<'_>) -> TaskReport {
        let task = ctx.task;
        let setup = Setup::new(ctx);
        let (room, target) = ctx.scenario.target(&task.subject).expect("checked target");
        let options = effective_vision(&task.options, Some(&setup.person.vision));
        let legible = legible_mm(&options);
        let chain = with_look_range(&setup.chain, legible);
        // With collisions on, the look link is a link like any other: the
        // solver and the base prefer a posture whose line of sight is clear.
        let obstacles = GazeObstacles::new(room, &setup);
        let query = setup.query(
            target.position_mm,
            mix_seed(setup.seed, &[&task.subject, &setup.person.name, "gaze"]),
            Search::MostComfortable,
            obstacles.body.as_ref(),
        );
        let placement = setup
            .base
            .prepare(room, &chain)
            .reach(&query, setup.solver.as_ref());
        let sight = see(
            &chain,
            &placement,
            target.position_mm,
            &obstacles,
            &setup,
            &options,
        );
        let asked = Asked {
            task,
            person: setup.person,
            chain: &chain,
            solver: setup.solver_of(&placement),
            tolerance_mm: setup.tolerance_mm,
        };
        TaskReport::Gaze(GazeReport::new(
            &asked,
            &placement,
            target.position_mm,
            sight,
        ))
    }
}

/// The obstacles a gaze is checked against, built once per task: all of
/// them for the line of sight, and those the body must keep clear of
/// (grown by the clearance) when the task checks collisions.
pub(super) struct GazeObstacles {
    pub sight: Obstacles,
    pub body: Option<Obstacles>,
}

impl GazeObstacles {
    pub fn new(room: &Room, setup: &Setup<'_>) -> Self {
        GazeObstacles {
            sight: Obstacles::new(room, 0.0),
            body: setup.obstacles(room),
        }
    }
}

/// What the eyes of `chain` see of `target` in the placed posture, and if
/// not, why: the sight line is always checked, by a ray cast that names
/// the first obstacle it meets; the body's links when collisions are on.
pub(super) fn see(
    chain: &Chain,
    placement: &Placement,
    target: Point3<f64>,
    obstacles: &GazeObstacles,
    setup: &Setup<'_>,
    options: &Options,
) -> Sight {
    let size_mm = options.length_mm("size");
    let look = look(chain, placement, target, &obstacles.sight, size_mm);
    let sight = Sight {
        reason: None,
        occluded_by: look.occluded_by,
        body_collision: obstacles_met_by_body(chain, placement, obstacles.body.as_ref()),
        distance_mm: look.distance_mm,
        legible_mm: legible_mm(options),
        off_axis_rad: look.off_axis_rad,
        acuity_threshold: options.number("acuity"),
        size_mm,
        eyes_room_mm: look.eyes_room_mm,
    };
    let reason = sight.reason(setup.tolerance_mm, placement.solution.distance_mm);
    Sight { reason, ..sight }
}

/// A gaze effector's chain must end in its look link.
pub(super) fn needs_look_link(person: &str, chain: &Chain) -> Option<ErrorKind> {
    let ends_in_look = chain
        .joints
        .last()
        .is_some_and(|j| j.kind == JointKind::Prismatic);
    (!ends_in_look).then(|| ErrorKind::NoLookLink {
        effector: chain.effector_name.clone(),
        person: person.to_string(),
    })
}

/// The chain with its look link limited to the legible range.
pub(super) fn with_look_range(chain: &Chain, legible_mm: [f64; 2]) -> Chain {
    let mut chain = chain.clone();
    if let Some(look) = chain.joints.last_mut() {
        limit_look(look, legible_mm);
    }
    chain
}

/// Keep look link `look` (its end) within the legible range
/// `[D_min, D_max]`, its neutral value moved inside.
pub(super) fn limit_look(look: &mut Joint, [d_min, d_max]: [f64; 2]) {
    look.min = d_min - look.rest_offset_mm().z;
    look.max = d_max - look.rest_offset_mm().z;
    look.neutral = look.neutral.clamp(look.min, look.max);
}

/// Where the eyes are in the placed posture, and what lies between them
/// and the target.
struct Look {
    eyes_room_mm: Point3<f64>,
    distance_mm: f64,
    off_axis_rad: f64,
    occluded_by: Option<String>,
}

fn look(
    chain: &Chain,
    placement: &Placement,
    target: Point3<f64>,
    obstacles: &Obstacles,
    size_mm: f64,
) -> Look {
    let q = &placement.solution.q;
    // The eyes: the frame before the look link, looking along its z axis.
    let eye_frame = chain.end_frame(&q[..q.len() - 1]);
    let eyes_room = placement
        .pose
        .to_room(&Point3::from(eye_frame.translation.vector));
    let look_room = placement
        .pose
        .direction_to_room(&(eye_frame.rotation * Vector3::z()));
    let to_target = target - eyes_room;
    Look {
        eyes_room_mm: eyes_room,
        distance_mm: to_target.norm(),
        off_axis_rad: look_room.angle(&to_target),
        occluded_by: obstacles
            .first_on_sight_line(&eyes_room, &target, size_mm / 2.0)
            .map(|(i, _)| obstacles.name(i).to_string()),
    }
}

/// The first obstacle the body's links (all but the look link) pass
/// through, when collisions are checked.
fn obstacles_met_by_body(
    chain: &Chain,
    placement: &Placement,
    obstacles: Option<&Obstacles>,
) -> Option<String> {
    let obstacles = obstacles?;
    let mut points = chain.link_points(&placement.solution.q);
    points.pop();
    let placed = PlacedObstacles {
        obstacles,
        base_pose: placement.pose,
    };
    placed
        .polyline_hit(&points, 0.0)
        .map(|i| obstacles.name(i).to_string())
}

impl Sight {
    /// Why the target is not seen, the first that applies, or `None`.
    fn reason(&self, tolerance_mm: f64, solver_distance_mm: f64) -> Option<&'static str> {
        // Distances, like the look link's end, count within the tolerance.
        let [d_min, d_max] = self.legible_mm;
        if self.distance_mm < d_min - tolerance_mm {
            Some("too near")
        } else if self.distance_mm > d_max + tolerance_mm {
            Some("too far")
        } else if vision::acuity(self.off_axis_rad) < self.acuity_threshold {
            // The solver could not bring the line of sight onto the target:
            // the neck and eyes stop short; else it was near enough for the
            // solver but not for the eyes.
            if solver_distance_mm > tolerance_mm {
                Some("beyond the neck and eye limits")
            } else {
                Some("too peripheral")
            }
        } else if self.occluded_by.is_some() {
            Some("occluded")
        } else if self.body_collision.is_some() {
            Some("the head or trunk passes through an obstacle")
        } else {
            None
        }
    }
}
