//! The `gaze` task: can this person see the target well enough to use it?
//! After the visibility paper: the eyes are an effector whose chain ends in
//! a look link, a prismatic joint along the line of sight, kept between the
//! nearest and farthest legible distances of an object of the task's `size`
//! (eq. 1-2). The solver drives the look link's end onto the target within
//! the neck and eye limits; then the acuity at the angle left between the
//! line of sight and the target (eq. 3) must reach the threshold, and a ray
//! from the eyes to the target must meet no obstacle.

use nalgebra::{Point3, Vector3};

use super::common::{chain_of, mix_seed, Common, CommonDecl, Reaching, MAP_RETRY, THOROUGH_RETRY};
use crate::collision::{Obstacles, PlacedObstacles};
use crate::error::ErrorKind;
use crate::kinematics::{Chain, Joint, JointKind};
use crate::plugin::{
    Dependence, EffectorNeed, Options, ParamSpec, Params, Placement, Plugin, Registry, Search,
    Settings, SettingsError, Subject, SubjectKind, Task, TaskInput, TaskPlugin, Tries,
};
use crate::report::{GazeReport, Names, Sight, TaskReport};
use crate::scene::{Blocker, OwnBody, Room, Vision};
use crate::vision;

/// The plugin `gaze`.
pub struct Gaze;

/// The options of a gaze at a target or a point: the common ones with the
/// eyes as effector and fabrik as solver, and what the eyes must make out.
#[derive(Clone, Debug, PartialEq)]
pub(super) struct GazeSettings {
    pub common: Common,
    pub looking: Looking,
}

impl GazeSettings {
    /// Declare and read them; `what` is `target` or `point`.
    pub fn visit(p: &mut Params<'_>, what: &'static str) -> Self {
        let common = Common::visit(
            p,
            &CommonDecl {
                what,
                seed_doc: "seeds the solver's random starts (mixed with where the subject is from where the person stands, never with names or where the room is)",
                // FABRIK turns the neck and eyes before the trunk, as people
                // do; the incremental solver moves every joint alike.
                solver: ("fabrik", "the IK solver and its options"),
                effector: Some(("eyes", "the effector whose chain ends in the look link")),
                retry: if what == "target" {
                    THOROUGH_RETRY
                } else {
                    MAP_RETRY
                },
            },
        );
        GazeSettings {
            common,
            looking: Looking::visit(p),
        }
    }
}

/// What the eyes must make out: the object's size, and the vision settings
/// a task leaves to the person's `vision`, and that to the defaults.
#[derive(Clone, Debug, PartialEq)]
pub(super) struct Looking {
    pub size_mm: f64,
    pub vision: Vision,
}

impl Settings for Looking {
    fn visit(p: &mut Params<'_>) -> Self {
        Looking {
            size_mm: p
                .length(
                    "size",
                    20.0,
                    "the object's size S (a letter's height, a dial)",
                )
                .range(0.01, 10_000.0)
                .get(),
            vision: Vision::visit(p),
        }
    }
}

impl Looking {
    /// Every setting filled in: the task's own, else the person's (if
    /// given), else the default.
    pub fn eyes(&self, person: Option<&Vision>) -> Eyes {
        let person = person.copied().unwrap_or_default();
        let v = self.vision.or(&person).or(&Vision::DEFAULT);
        Eyes {
            size_mm: self.size_mm,
            mar_far_rad: v.mar_far_rad.unwrap_or(vision::ARCMIN_RAD),
            mar_near_rad: v.mar_near_rad,
            near_point_mm: v.near_point_mm.unwrap_or(250.0),
            acuity: v.acuity.unwrap_or(0.5),
        }
    }
}

/// What the eyes must make out, every setting filled in.
#[derive(Clone, Copy, Debug, PartialEq)]
pub(super) struct Eyes {
    pub size_mm: f64,
    pub mar_far_rad: f64,
    pub mar_near_rad: Option<f64>,
    pub near_point_mm: f64,
    /// The least acuity at which a target counts as seen.
    pub acuity: f64,
}

impl Eyes {
    /// The legible range `[D_min, D_max]` (eq. 1-2).
    pub fn legible_mm(&self) -> [f64; 2] {
        let d_max = vision::d_max_mm(self.size_mm, self.mar_far_rad);
        let d_min = match self.mar_near_rad {
            Some(mar_near) => vision::d_min_mm(self.size_mm, mar_near),
            None => self.near_point_mm,
        };
        [d_min, d_max]
    }

    /// The range the look link is kept to: the legible range less the
    /// tolerance at each end (its middle if that leaves nothing), so that
    /// a look link ending within the tolerance of the target puts the eyes
    /// within the legible range itself.
    pub fn aimed_mm(&self, tolerance_mm: f64) -> [f64; 2] {
        let [d_min, d_max] = self.legible_mm();
        if d_max - d_min > 2.0 * tolerance_mm {
            [d_min + tolerance_mm, d_max - tolerance_mm]
        } else {
            let middle = 0.5 * (d_min + d_max);
            [middle, middle]
        }
    }

    /// An object too small to be legible anywhere.
    pub fn illegible(&self) -> Option<ErrorKind> {
        let [d_min, d_max] = self.legible_mm();
        (d_min >= d_max).then(|| ErrorKind::Illegible {
            size: format!("{}mm", self.size_mm),
            d_min: format!("{d_min:.0}mm"),
            d_max: format!("{d_max:.0}mm"),
        })
    }
}

/// The settings of `gaze`.
struct GazeTaskSettings(GazeSettings);

impl Settings for GazeTaskSettings {
    fn visit(p: &mut Params<'_>) -> Self {
        GazeTaskSettings(GazeSettings::visit(p, "target"))
    }
}

impl Plugin for Gaze {
    fn name(&self) -> &'static str {
        "gaze"
    }

    fn doc(&self) -> &'static str {
        "can the person see the target: legible distance, eye and neck limits, acuity, line of sight"
    }

    fn params(&self) -> Vec<ParamSpec> {
        GazeTaskSettings::params()
    }
}

impl TaskPlugin for Gaze {
    fn subject(&self) -> SubjectKind {
        SubjectKind::Target
    }

    fn configure(
        &self,
        options: &Options,
        plugins: &Registry,
    ) -> Result<Box<dyn Task>, SettingsError> {
        let GazeTaskSettings(settings) = GazeTaskSettings::from_options(options)?;
        Ok(Box::new(GazeTask {
            reaching: Reaching::new(settings.common, plugins)?,
            looking: settings.looking,
        }))
    }
}

/// A configured gaze.
struct GazeTask {
    reaching: Reaching,
    looking: Looking,
}

impl Task for GazeTask {
    fn effectors(&self) -> Vec<EffectorNeed> {
        vec![self.reaching.effector_need()]
    }

    fn validate(&self, _subject: &Subject<'_>) -> Option<ErrorKind> {
        self.looking.eyes(None).illegible()
    }

    fn validate_chain(&self, person: &str, _need: usize, chain: &Chain) -> Option<ErrorKind> {
        needs_look_link(person, chain)
    }

    fn starts_per_point(&self, placements: Tries) -> u64 {
        self.reaching.starts_per_point(placements)
    }

    /// Its obstacles are asked about through `Reaching::obstacles` (and
    /// finding why marks those it ranks), its floor through its base.
    fn records_touches(&self) -> bool {
        true
    }

    fn dependence(&self, input: &TaskInput<'_>) -> Dependence {
        let eyes = self.looking.eyes(Some(&input.person.vision));
        let chain = with_look_range(
            &chain_of(input, 0),
            eyes.aimed_mm(self.reaching.common.tolerance_mm),
        );
        let points = match input.subject {
            Subject::Target(t) => vec![t.position_mm],
            Subject::Surface(_) => Vec::new(),
        };
        self.reaching.dependence(&chain, &[&chain], points, true)
    }

    fn run(&self, input: &TaskInput<'_>) -> TaskReport {
        let reaching = &self.reaching;
        let Subject::Target(target) = input.subject else {
            unreachable!("the checker gives a gaze a target")
        };
        let eyes = self.looking.eyes(Some(&input.person.vision));
        let chain = with_look_range(
            &chain_of(input, 0),
            eyes.aimed_mm(self.reaching.common.tolerance_mm),
        );
        // With collisions on, the look link is a link like any other: the
        // solver and the base prefer a posture whose line of sight is clear.
        let obstacles = GazeObstacles::new(input, reaching);
        let query = reaching.query(
            target.position_mm,
            mix_seed(reaching.common.seed, "gaze"),
            Search::MostComfortable,
            obstacles.body.as_ref(),
            input.base.own_body(),
            input.allowance,
        );
        let placement = input
            .base
            .prepare(input.room, &chain, input.allowance)
            .reach(&query, reaching.solver.as_ref());
        let looked = Looked {
            chain: &chain,
            placement: &placement,
            target: target.position_mm,
        };
        let sight = looked.see(&obstacles, reaching.common.tolerance_mm, &eyes);
        let asked = reaching.asked(&target.name, input, &chain, &placement);
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
/// (grown by the clearance) when the task checks collisions; the person's
/// own legs and base, which may hide a target too.
pub(super) struct GazeObstacles<'a> {
    pub sight: Obstacles,
    pub body: Option<Obstacles>,
    pub room: &'a Room,
    pub own: &'a OwnBody,
}

impl<'a> GazeObstacles<'a> {
    /// The obstacles of `input`'s room and its person's own body and
    /// base, recording what the questions touch where `input` asks.
    pub fn new(input: &TaskInput<'a>, reaching: &Reaching) -> Self {
        GazeObstacles {
            sight: Obstacles::new(input.room, 0.0)
                .recording(input.touched)
                .charging(input.allowance),
            body: reaching.obstacles(input),
            room: input.room,
            own: input.base.own_body(),
        }
    }
}

/// How far short of the target the line of sight stops: the surface the
/// target lies on does not hide it, but a board in front of it does,
/// however large the object (it stopped half the object's size short
/// before, and a board 50 mm in front of a sign of 200 mm letters hid
/// nothing).
const SIGHT_END_GAP_MM: f64 = 1.0;

/// A posture placed to look at `target`, with `chain` the eyes' chain.
pub(super) struct Looked<'a> {
    pub chain: &'a Chain,
    pub placement: &'a Placement,
    pub target: Point3<f64>,
}

impl Looked<'_> {
    /// What the eyes see of the target, and if not, why: the sight line is
    /// always checked, against the room and the person's own legs and
    /// base, naming the first thing it meets; the body's parts when
    /// collisions are on.
    pub fn see(&self, obstacles: &GazeObstacles<'_>, tolerance_mm: f64, eyes: &Eyes) -> Sight {
        let look = self.look(obstacles);
        let sight = Sight {
            reason: None,
            occluded_by: look.occluded_by,
            body_collision: self.obstacle_met_by_body(obstacles, tolerance_mm),
            distance_mm: look.distance_mm,
            legible_mm: eyes.legible_mm(),
            off_axis_rad: look.off_axis_rad,
            acuity_threshold: eyes.acuity,
            size_mm: eyes.size_mm,
            eyes_room_mm: look.eyes_room_mm,
        };
        let reason = sight.reason(tolerance_mm, self.placement.solution.distance_mm);
        Sight { reason, ..sight }
    }

    fn names<'n>(&'n self, obstacles: &'n GazeObstacles<'_>) -> Names<'n> {
        Names {
            room: obstacles.room,
            own: obstacles.own,
            chain: self.chain,
        }
    }

    /// Where the eyes are in the placed posture, and what lies between
    /// them and the target.
    fn look(&self, obstacles: &GazeObstacles<'_>) -> Look {
        let q = &self.placement.solution.q;
        let pose = &self.placement.pose;
        // The eyes: the frame before the look link, looking along its z axis.
        let eye_frame = self.chain.end_frame(&q[..q.len() - 1]);
        let eyes_base = Point3::from(eye_frame.translation.vector);
        let eyes_room = pose.to_room(&eyes_base);
        let look_room = pose.direction_to_room(&(eye_frame.rotation * Vector3::z()));
        let to_target = self.target - eyes_room;
        let gap = SIGHT_END_GAP_MM;
        let room_hit = obstacles
            .sight
            .first_on_sight_line(&eyes_room, &self.target, gap);
        let own_hit = obstacles
            .own
            .first_on_line(&eyes_base, &pose.to_base(&self.target), gap)
            .map(|(i, t)| (Blocker::Own(i), t));
        let first = room_hit
            .into_iter()
            .chain(own_hit)
            .min_by(|a, b| a.1.total_cmp(&b.1));
        Look {
            eyes_room_mm: eyes_room,
            distance_mm: to_target.norm(),
            off_axis_rad: look_room.angle(&to_target),
            occluded_by: first.map(|(b, _)| self.names(obstacles).blocker(b)),
        }
    }

    /// The first thing the body's parts (all but the look link) run into,
    /// when collisions are checked.
    fn obstacle_met_by_body(
        &self,
        obstacles: &GazeObstacles<'_>,
        tolerance_mm: f64,
    ) -> Option<String> {
        let room = obstacles.body.as_ref()?;
        let (body, q) = without_look(self.chain, &self.placement.solution.q);
        let placed = PlacedObstacles {
            obstacles: room,
            own: obstacles.own,
            base_pose: self.placement.pose,
        };
        let hit = placed.posture_hit(&body, q, tolerance_mm)?;
        Some(self.names(obstacles).blocker(hit.blocker))
    }
}

/// The eyes' chain without its look link (ending at the eyes), and the
/// posture of its joints.
fn without_look<'q>(chain: &Chain, q: &'q [f64]) -> (Chain, &'q [f64]) {
    let mut body = chain.clone();
    body.joints.pop();
    body.effector_mm = Vector3::zeros();
    body.effector_link.radius_mm = 0.0;
    (body, &q[..q.len().saturating_sub(1)])
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

/// An error where `chain` (of `person`) ends in a look link but is asked
/// to bring a hand to a target (a reach, a map, the hand of a reach and
/// gaze): the look link stretches to whatever it is aimed at.
pub(super) fn refuses_look_link(person: &str, chain: &Chain) -> Option<ErrorKind> {
    needs_look_link(person, chain)
        .is_none()
        .then(|| ErrorKind::LookLinkReaches {
            effector: chain.effector_name.clone(),
            person: person.to_string(),
        })
}

/// The chain with its look link limited to `legible_mm` (the aimed range).
pub(super) fn with_look_range(chain: &Chain, legible_mm: [f64; 2]) -> Chain {
    let mut chain = chain.clone();
    if let Some(look) = chain.joints.last_mut() {
        limit_look(look, legible_mm);
    }
    chain
}

/// Keep look link `look` (its end) within `[d_min, d_max]` (the range
/// `Eyes::aimed_mm` gives), its neutral value moved inside.
pub(super) fn limit_look(look: &mut Joint, [d_min, d_max]: [f64; 2]) {
    look.min = d_min - look.rest_offset_mm().z;
    look.max = d_max - look.rest_offset_mm().z;
    look.neutral = look.neutral.clamp(look.min, look.max);
}

/// Where the eyes are, and what lies between them and the target.
struct Look {
    eyes_room_mm: Point3<f64>,
    distance_mm: f64,
    off_axis_rad: f64,
    occluded_by: Option<String>,
}

impl Sight {
    /// Why the target is not seen, the first that applies, or `None`.
    fn reason(&self, tolerance_mm: f64, solver_distance_mm: f64) -> Option<&'static str> {
        // The legible range is the eye's, not the solver's: the eyes'
        // distance to the target is held to it exactly, whatever the
        // tolerance lets the look link's end miss by.
        let [d_min, d_max] = self.legible_mm;
        if self.distance_mm < d_min {
            Some("too near")
        } else if self.distance_mm > d_max {
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

#[cfg(test)]
mod tests {
    use super::*;

    fn sight(distance_mm: f64) -> Sight {
        Sight {
            reason: None,
            occluded_by: None,
            body_collision: None,
            distance_mm,
            // A 2 mm label at 1 arcmin: legible up to 1,375 mm.
            legible_mm: [250.0, vision::d_max_mm(2.0, (1.0f64 / 60.0).to_radians())],
            off_axis_rad: 0.0,
            acuity_threshold: 0.5,
            size_mm: 2.0,
            eyes_room_mm: Point3::origin(),
        }
    }

    /// A label 8 mm beyond its legible range is too far, though a reach
    /// tolerance of 10 mm would cover the 8 mm.
    #[test]
    fn the_reach_tolerance_does_not_widen_the_legible_range() {
        let d_max = sight(0.0).legible_mm[1];
        assert!((d_max - 1375.1).abs() < 0.1, "{d_max}");
        assert_eq!(sight(d_max + 8.0).reason(10.0, 0.0), Some("too far"));
        assert_eq!(sight(d_max - 1.0).reason(10.0, 0.0), None);
        assert_eq!(sight(245.0).reason(10.0, 0.0), Some("too near"));
    }
}
