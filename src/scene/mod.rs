//! The scene a checked scenario describes: rooms with obstacles, targets
//! and surfaces, persons with their bodies, and the plain data of answers
//! (base poses, postures, placements). Everything here is resolved and in
//! internal units (mm, rad). The scenario (`crate::scenario`) adds the
//! configured plugins and the tasks.

mod door;
mod fnv;
mod mesh;
mod person_parts;
mod placement;
mod population;
mod room_hash;
mod surface;
mod sweep;
mod vision;

pub use door::Door;
pub use fnv::fnv1a;
pub use mesh::{MeshObstacle, MeshPart, MeshShape, PART_TRIANGLES};
pub use person_parts::{column_solid, OwnBody, Physique};
pub use placement::{
    seed_in_base_frame, BasePose, Blocked, Blocker, Collision, HasSolution, IkSolution, Placement,
    Preferred, Wall,
};
pub use population::{Drawn, Population};
pub use room_hash::hash_bits;
pub use surface::{Grid, GridCell, Surface, FACES};
pub use sweep::Sweep;
pub use vision::Vision;

use nalgebra::{Point3, Rotation2, Vector2, Vector3};

use crate::geometry::Cuboid;
use crate::kinematics::Body;
use crate::options::PluginConfig;
use crate::units::Quantity;

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
    /// Its entrances; none: a base may be placed anywhere it fits.
    pub doors: Vec<Door>,
}

impl Room {
    pub fn contains(&self, p: &Point3<f64>) -> bool {
        (0..3).all(|i| p[i] >= 0.0 && p[i] <= self.size_mm[i])
    }

    /// This room with the boxes and targets named `names` moved by
    /// `by_mm`: an element moved as one (`advise`). Its name is another
    /// for each move (a base keeps its floor by the room's name, and the
    /// element may change the floor); it is never shown.
    pub fn moved(&self, names: &[&str], by_mm: Vector3<f64>) -> Room {
        let mut moved = self.clone();
        moved.name = format!(
            "{}\u{0}{names:?} moved by ({}, {}, {}) mm",
            self.name, by_mm.x, by_mm.y, by_mm.z
        );
        for b in moved
            .boxes
            .iter_mut()
            .filter(|b| names.contains(&b.name.as_str()))
        {
            b.corner_mm += by_mm;
        }
        for t in (moved.targets.iter_mut()).filter(|t| names.contains(&t.name.as_str())) {
            t.position_mm += by_mm;
        }
        moved
    }

    /// This room without the boxes named `names` (an element taken out,
    /// to tell whether it or the room keeps a base out). Its name is
    /// another, never shown, as [`Room::moved`]'s is.
    pub fn without_boxes(&self, names: &[String]) -> Room {
        let mut bare = self.clone();
        bare.name = format!("{}\u{0}without {names:?}", self.name);
        bare.boxes.retain(|b| !names.contains(&b.name));
        bare
    }

    /// The name of obstacle `index`: the boxes, then the meshes.
    pub fn obstacle_name(&self, index: usize) -> &str {
        match self.boxes.get(index) {
            Some(b) => &b.name,
            None => &self.meshes[index - self.boxes.len()].name,
        }
    }
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
    /// Whether the box comes within the heights `[z0, z1]` (a part of a
    /// base's footprint meets it on the floor only then).
    pub fn meets_band(&self, [z0, z1]: [f64; 2]) -> bool {
        self.corner_mm.z < z1 && z0 < self.corner_mm.z + self.size_mm.z
    }

    /// The box's own axes in the room's, on the floor: turned by its yaw.
    pub fn rotation(&self) -> Rotation2<f64> {
        Rotation2::new(self.yaw_rad)
    }

    /// A point of the floor given in the box's own axes (from its corner),
    /// in the room.
    pub fn floor_point(&self, local_mm: Vector2<f64>) -> Vector2<f64> {
        self.corner_mm.xy().coords + self.rotation() * local_mm
    }

    /// The box as a solid in the room.
    pub fn cuboid(&self) -> Cuboid {
        Cuboid::from_corner(self.corner_mm, self.size_mm, self.yaw_rad)
    }

    /// Whether `p` is inside the box and not on its surface (within a
    /// micrometre).
    pub fn holds_strictly(&self, p: &Point3<f64>) -> bool {
        let d = p - self.corner_mm;
        let xy = self.rotation().inverse() * d.xy();
        let local = Vector3::new(xy.x, xy.y, d.z);
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
    /// The whole body, every effector (the first is the default for tasks).
    pub body: Body,
    /// The base plugin and its validated options (the scenario holds it
    /// built).
    pub base: PluginConfig,
    /// The vision settings the person's `vision` gives (only those given):
    /// a gaze task's own come first, then these, then the defaults.
    pub vision: Vision,
    /// The measurements the body was built from: the parameters of the
    /// outermost mannequin with parameters (`measured`'s `stature`,
    /// `sitting_height`, ...) with their values, in declaration order;
    /// empty for a mannequin without parameters.
    pub measures: Vec<(String, Quantity)>,
}
