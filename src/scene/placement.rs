//! Where a person's base stands in the room and the posture a solver found
//! from there: plain data that the solvers and bases produce, collision
//! checks read and reports show.

use nalgebra::{Point3, Rotation2, Vector3};

use crate::kinematics::{Chain, Owner, Tipping};

/// Where the base stands: its origin (the hip point) in the room, and the
/// direction it faces, counter-clockwise from the room's x axis.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct BasePose {
    pub position_mm: Point3<f64>,
    pub heading_rad: f64,
}

impl BasePose {
    /// The base frame's axes in the room's: turned by the heading about
    /// the vertical.
    pub fn rotation(&self) -> Rotation2<f64> {
        turn_exact_at_quarters(self.heading_rad)
    }

    /// A point of the room in the base frame.
    pub fn to_base(&self, room_point: &Point3<f64>) -> Point3<f64> {
        let d = room_point - self.position_mm;
        let xy = self.rotation().inverse() * d.xy();
        Point3::new(xy.x, xy.y, d.z)
    }

    /// A direction of the base frame in the room.
    pub fn direction_to_room(&self, v: &Vector3<f64>) -> Vector3<f64> {
        let xy = self.rotation() * v.xy();
        Vector3::new(xy.x, xy.y, v.z)
    }

    /// A point of the base frame in the room.
    pub fn to_room(&self, base_point: &Point3<f64>) -> Point3<f64> {
        self.position_mm + self.direction_to_room(&base_point.coords)
    }

    /// Whether `target_room_mm` lies behind the person standing or sitting
    /// here: more than `BEHIND_BEARING_DEG` from the way the base faces,
    /// and more than `BEHIND_MIN_MM` from its vertical (a point above
    /// the hips is no more behind than in front).
    pub fn has_behind(&self, target_room_mm: &Point3<f64>) -> bool {
        let along = self.to_base(target_room_mm).coords.xy();
        along.norm() > BEHIND_MIN_MM
            && along.y.atan2(along.x).abs() > BEHIND_BEARING_DEG.to_radians()
    }
}

/// The turn by `rad` about the vertical, exact where it is a whole number
/// of quarter turns (facing along a wall): `Rotation2::new(PI)` has a sine
/// of 1.2e-16, which a scene turned or mirrored onto itself rounds
/// differently.
fn turn_exact_at_quarters(rad: f64) -> Rotation2<f64> {
    let quarters = rad / std::f64::consts::FRAC_PI_2;
    let whole = quarters.round();
    if (quarters - whole).abs() > 1e-12 {
        return Rotation2::new(rad);
    }
    let (sin, cos) = match (whole as i64).rem_euclid(4) {
        0 => (0.0, 1.0),
        1 => (1.0, 0.0),
        2 => (0.0, -1.0),
        _ => (-1.0, 0.0),
    };
    Rotation2::from_matrix_unchecked(nalgebra::Matrix2::new(cos, -sin, sin, cos))
}

/// How far round from the way the base faces a target is behind the
/// person: past a side approach (90 degrees, the target beside the hip)
/// by what turning the trunk and reaching back a little covers.
pub const BEHIND_BEARING_DEG: f64 = 110.0;

/// How far out from the base's vertical a target must be for its bearing
/// to count (the base's origin is the hips' point).
pub const BEHIND_MIN_MM: f64 = 150.0;

/// How finely a target in the base frame is told apart when it seeds a
/// solve: a thousandth of a millimetre, far above the rounding a rigid
/// motion of the whole scene leaves in it (about 1e-12 mm), far below any
/// distance that matters.
const SEED_GRID_MM: f64 = 1e-3;

/// The seed of a solve for a target at `target_base_mm` in the base frame
/// of the pose it is solved from, given the task's `seed`: it depends on
/// the scene only through where the target is from where the person
/// stands, so that moving the whole scenario, or turning it by a multiple
/// of 90 degrees, draws the same starts. (FNV-1a over the coordinates
/// rounded to [`SEED_GRID_MM`].)
pub fn seed_in_base_frame(seed: u64, target_base_mm: &Point3<f64>) -> u64 {
    let cells = target_base_mm
        .iter()
        .map(|c| (c / SEED_GRID_MM).round() as i64);
    super::fnv1a(seed, cells.flat_map(i64::to_le_bytes))
}

/// Where the base stood and the posture the solver found from there.
#[derive(Clone, Debug, PartialEq)]
pub struct Placement {
    pub pose: BasePose,
    pub solution: IkSolution,
    /// Found by the query's retry solver (`plugin::Retry`), after the task's own solver
    /// found no placement that reaches.
    pub retried: bool,
}

/// A placement whose posture reached the target through something (an
/// obstacle, the person's own body, their chair): where a retry starts.
#[derive(Clone, Debug, PartialEq)]
pub struct Blocked {
    pub pose: BasePose,
    /// The posture that reached through it.
    pub q: Vec<f64>,
}

/// A solver's answer: a posture within the joint limits and how far its
/// effector is from the target.
#[derive(Clone, Debug, PartialEq)]
pub struct IkSolution {
    /// Joint values in chain order (rad or mm).
    pub q: Vec<f64>,
    pub distance_mm: f64,
    /// Sweeps over all joints (or solver iterations), summed over starts.
    pub iterations: u64,
    /// The first thing a part of the posture runs into, if any.
    pub collision: Option<Collision>,
}

/// What a posture runs into: which part of the person, and what.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Collision {
    /// A volume of the chain (a link, or the head it carries).
    pub part: Owner,
    pub blocker: Blocker,
}

/// What a part of a person runs into.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Blocker {
    /// An obstacle of the room, by index: its boxes, then its meshes.
    Obstacle(usize),
    /// A wall, the floor or the ceiling.
    Wall(Wall),
    /// A part of the person or their base that no joint moves, by index
    /// in their [`crate::scene::OwnBody`] (a thigh, the chair's backrest).
    Own(usize),
    /// Another part of the person's moving body (a volume of the chain).
    Body(Owner),
    /// The person's balance, standing: no lean of the legs puts the feet
    /// under the centre of mass, or the feet cannot go where it would
    /// (`kinematics::Balance`).
    Balance(Tipping),
}

/// The room's six sides.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum Wall {
    Floor,
    Ceiling,
    /// x = 0, x = the room's length, y = 0, y = its width.
    XMin,
    XMax,
    YMin,
    YMax,
}

impl IkSolution {
    /// Within `tolerance_mm` of the target and clear of obstacles.
    pub fn reaches(&self, tolerance_mm: f64) -> bool {
        self.distance_mm <= tolerance_mm && self.collision.is_none()
    }

    /// Whether this solution, of discomfort `comfort`, is kept over `other`:
    /// one that reaches (within `tolerance_mm`, clear of obstacles) beats
    /// one that does not; of
    /// two that reach, the more comfortable (section 5.3.4); of two that do
    /// not, the closer.
    pub fn preferred_to(
        &self,
        comfort: f64,
        other: &IkSolution,
        other_comfort: f64,
        tolerance_mm: f64,
    ) -> bool {
        match (self.reaches(tolerance_mm), other.reaches(tolerance_mm)) {
            (true, false) => true,
            (false, true) => false,
            (true, true) => comfort < other_comfort,
            (false, false) => self.distance_mm < other.distance_mm,
        }
    }
}

impl IkSolution {
    /// The neutral posture, infinitely far: what a solve that ran no start
    /// gives (a solver always runs at least one).
    pub fn unsolved(chain: &Chain) -> Self {
        IkSolution {
            q: chain.neutral(),
            distance_mm: f64::INFINITY,
            iterations: 0,
            collision: None,
        }
    }
}

/// What holds a solution: a solution, or a placement.
pub trait HasSolution {
    fn solution(&self) -> &IkSolution;
}

impl HasSolution for IkSolution {
    fn solution(&self) -> &IkSolution {
        self
    }
}

impl HasSolution for Placement {
    fn solution(&self) -> &IkSolution {
        &self.solution
    }
}

/// The preferred of several solutions (or placements) offered one by one,
/// by [`IkSolution::preferred_to`]: one that reaches over one that does
/// not, the more comfortable of two that reach, the closer of two that do
/// not; the first of equals stays.
pub struct Preferred<T> {
    tolerance_mm: f64,
    kept: Option<(T, f64)>,
}

impl<T: HasSolution> Preferred<T> {
    pub fn new(tolerance_mm: f64) -> Self {
        Preferred {
            tolerance_mm,
            kept: None,
        }
    }

    /// Keep `candidate`, of discomfort `comfort`, if it is preferred to the
    /// one kept.
    pub fn offer(&mut self, candidate: T, comfort: f64) {
        let better = self.kept.as_ref().is_none_or(|(kept, kept_comfort)| {
            candidate.solution().preferred_to(
                comfort,
                kept.solution(),
                *kept_comfort,
                self.tolerance_mm,
            )
        });
        if better {
            self.kept = Some((candidate, comfort));
        }
    }

    /// Whether the one kept reaches.
    pub fn reaches(&self) -> bool {
        self.kept
            .as_ref()
            .is_some_and(|(kept, _)| kept.solution().reaches(self.tolerance_mm))
    }

    pub fn into_kept(self) -> Option<T> {
        self.kept.map(|(kept, _)| kept)
    }
}
