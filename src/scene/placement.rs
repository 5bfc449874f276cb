//! Where a person's base stands in the room and the posture a solver found
//! from there: plain data that the solvers and bases produce, collision
//! checks read and reports show.

use nalgebra::{Point3, Vector3};

/// Where the base stands: its origin (the hip point) in the room, and the
/// direction it faces, counter-clockwise from the room's x axis.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct BasePose {
    pub position_mm: Point3<f64>,
    pub heading_rad: f64,
}

impl BasePose {
    /// A point of the room in the base frame.
    pub fn to_base(&self, room_point: &Point3<f64>) -> Point3<f64> {
        let d = room_point - self.position_mm;
        let (s, c) = self.heading_rad.sin_cos();
        Point3::new(c * d.x + s * d.y, -s * d.x + c * d.y, d.z)
    }

    /// A direction of the base frame in the room.
    pub fn direction_to_room(&self, v: &Vector3<f64>) -> Vector3<f64> {
        let (s, c) = self.heading_rad.sin_cos();
        Vector3::new(c * v.x - s * v.y, s * v.x + c * v.y, v.z)
    }

    /// A point of the base frame in the room.
    pub fn to_room(&self, base_point: &Point3<f64>) -> Point3<f64> {
        let (s, c) = self.heading_rad.sin_cos();
        let p = base_point;
        self.position_mm + Vector3::new(c * p.x - s * p.y, s * p.x + c * p.y, p.z)
    }
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

/// A solver's answer: a posture within the joint limits and how far its
/// effector is from the target.
#[derive(Clone, Debug, PartialEq)]
pub struct IkSolution {
    /// Joint values in chain order (rad or mm).
    pub q: Vec<f64>,
    pub distance_mm: f64,
    /// Sweeps over all joints (or solver iterations), summed over starts.
    pub iterations: u64,
    /// The first obstacle (by index in the room) a link passes through.
    pub collision: Option<usize>,
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
