//! Solid shapes and the distances between them, in millimetres: a capsule
//! (a segment with a radius: a limb, a link; a sphere is a capsule of
//! length zero) and an oriented box (a board, a chair's seat), each in any
//! one frame; and triangle meshes cleaned for collision. Plain geometry,
//! below the scene that places them.

mod capsule;
mod cuboid;
mod triangles;

pub use capsule::{segment_distance, Capsule};
pub use cuboid::Cuboid;
pub use triangles::cleaned as cleaned_triangles;
#[cfg(test)]
pub(crate) use triangles::unit_cube;

use nalgebra::Point3;

/// A named solid: a part of a person or of their base ("the left thigh",
/// "the wheelchair's backrest").
#[derive(Clone, Debug, PartialEq)]
pub struct Solid {
    pub name: String,
    pub shape: Shape,
}

impl Solid {
    pub fn new(name: impl Into<String>, shape: Shape) -> Self {
        Solid {
            name: name.into(),
            shape,
        }
    }
}

/// A solid's shape.
#[derive(Clone, Debug, PartialEq)]
pub enum Shape {
    Capsule(Capsule),
    Cuboid(Cuboid),
}

impl Shape {
    /// The least distance from the segment `a`-`b` to the shape's surface
    /// (zero where the segment enters it).
    pub fn distance_to_segment(&self, a: &Point3<f64>, b: &Point3<f64>) -> f64 {
        match self {
            Shape::Capsule(c) => (segment_distance(a, b, &c.a, &c.b) - c.radius_mm).max(0.0),
            Shape::Cuboid(c) => c.distance_to_segment(a, b),
        }
    }

    /// The shape's axis-aligned bounds: least and greatest corners.
    pub fn bounds(&self) -> [Point3<f64>; 2] {
        match self {
            Shape::Capsule(c) => c.bounds(),
            Shape::Cuboid(c) => c.bounds(),
        }
    }
}
