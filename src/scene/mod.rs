//! The checked scenario: rooms with obstacles and targets, persons with
//! their chains and bases, and the tasks to run. Everything here is
//! resolved and in internal units (mm, rad); spans remain only where a run
//! may still need to point back at the text.

mod placement;
mod surface;

pub use placement::{BasePose, IkSolution, Placement};
pub use surface::{Grid, GridCell, Surface, FACES};

use nalgebra::{Point3, Vector3};

use crate::kinematics::{Body, Chain};
use crate::options::{Options, PluginConfig};
use crate::span::Span;

#[derive(Clone, Debug, PartialEq)]
pub struct Scenario {
    /// The root file's name as given.
    pub file: String,
    pub rooms: Vec<Room>,
    pub persons: Vec<Person>,
    pub tasks: Vec<TaskSpec>,
}

impl Scenario {
    pub fn person(&self, name: &str) -> Option<&Person> {
        self.persons.iter().find(|p| p.name == name)
    }

    /// The target of this name and the room it is in.
    pub fn target(&self, name: &str) -> Option<(&Room, &Target)> {
        self.rooms
            .iter()
            .find_map(|r| r.targets.iter().find(|t| t.name == name).map(|t| (r, t)))
    }

    /// The surface a dotted subject names, and its room.
    pub fn surface(&self, subject: &str) -> Option<(&Room, Surface)> {
        self.rooms
            .iter()
            .find_map(|r| r.surface_named(subject).map(|s| (r, s)))
    }
}

/// A room: the box from the origin to `size_mm`, x and y on the floor, z up.
#[derive(Clone, Debug, PartialEq)]
pub struct Room {
    pub name: String,
    pub size_mm: Vector3<f64>,
    pub boxes: Vec<BoxObstacle>,
    /// Triangle meshes (from OBJ files), after the boxes in obstacle order.
    pub meshes: Vec<MeshObstacle>,
    pub targets: Vec<Target>,
    /// Rectangles declared with `surface`, for maps.
    pub surfaces: Vec<Surface>,
}

impl Room {
    pub fn contains(&self, p: &Point3<f64>) -> bool {
        (0..3).all(|i| p[i] >= 0.0 && p[i] <= self.size_mm[i])
    }

    /// The name of obstacle `index`: the boxes, then the meshes.
    pub fn obstacle_name(&self, index: usize) -> &str {
        match self.boxes.get(index) {
            Some(b) => &b.name,
            None => &self.meshes[index - self.boxes.len()].name,
        }
    }
}

/// A triangle mesh obstacle, its vertices in the room.
#[derive(Clone, Debug, PartialEq)]
pub struct MeshObstacle {
    pub name: String,
    pub vertices_mm: Vec<Point3<f64>>,
    pub triangles: Vec<[u32; 3]>,
}

/// A box obstacle: `corner_mm` is its corner of least x, y and z before
/// rotation; it is turned by `yaw_rad` about the vertical through that
/// corner.
#[derive(Clone, Debug, PartialEq)]
pub struct BoxObstacle {
    pub name: String,
    pub corner_mm: Point3<f64>,
    pub size_mm: Vector3<f64>,
    pub yaw_rad: f64,
}

impl BoxObstacle {
    /// Whether `p` is inside the box and not on its surface (within a
    /// micrometre).
    pub fn holds_strictly(&self, p: &Point3<f64>) -> bool {
        let d = p - self.corner_mm;
        let (s, c) = self.yaw_rad.sin_cos();
        let local = Vector3::new(c * d.x + s * d.y, -s * d.x + c * d.y, d.z);
        (0..3).all(|i| local[i] > 1e-3 && local[i] < self.size_mm[i] - 1e-3)
    }
}

#[derive(Clone, Debug, PartialEq)]
pub struct Target {
    pub name: String,
    pub position_mm: Point3<f64>,
}

/// A person: the mannequin's body with this person's limits, and a base.
#[derive(Clone, Debug, PartialEq)]
pub struct Person {
    pub name: String,
    pub mannequin: String,
    /// The whole body, every effector.
    pub body: Body,
    /// The chain of the body's first effector, the default for tasks.
    pub chain: Chain,
    pub base: PluginConfig,
    /// The vision options the person's `vision` gives (only those given):
    /// a gaze task's own options come first, then these, then defaults.
    pub vision: Options,
}

impl Person {
    /// The chain to the effector a task names (`None`: the first).
    pub fn chain_for(&self, effector: Option<&str>) -> Option<Chain> {
        match effector {
            None => Some(self.chain.clone()),
            Some(name) => self.body.chain_named(Some(name)),
        }
    }
}

/// One task to run: a task plugin on one subject by one person.
#[derive(Clone, Debug, PartialEq)]
pub struct TaskSpec {
    /// The task plugin's name (`reach`).
    pub kind: String,
    /// The subject: a target name for reach.
    pub subject: String,
    pub person: String,
    pub options: Options,
    pub span: Span,
}
