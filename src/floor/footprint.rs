//! The outline a base takes on the floor, in the base frame (x forward,
//! y to the left, origin at the hip point).

use geo::{Coord, LineString, Polygon};
use nalgebra::{Rotation2, Vector2};

/// Sides of the polygon that stands for a circle. It is circumscribed, so
/// a clearance check with it never lets the circle overlap an obstacle.
const CIRCLE_SIDES: usize = 24;

#[derive(Clone, Copy, Debug, PartialEq)]
pub enum Footprint {
    /// A circle about the hip point (a person with a trolley or rollator).
    Circle { radius_mm: f64 },
    /// A rectangle: `front_mm` ahead of the hip point, `back_mm` behind it,
    /// `width_mm` wide and centred (a wheelchair with its user).
    Rectangle {
        front_mm: f64,
        back_mm: f64,
        width_mm: f64,
    },
}

impl Footprint {
    /// The outline's corners in the base frame turned by `heading_rad`
    /// (counter-clockwise), relative to the hip point.
    pub fn corners(&self, heading_rad: f64) -> Vec<Coord<f64>> {
        let local: Vec<(f64, f64)> = match *self {
            Footprint::Circle { radius_mm } => {
                let r = radius_mm / (std::f64::consts::PI / CIRCLE_SIDES as f64).cos();
                (0..CIRCLE_SIDES)
                    .map(|k| {
                        let a = 2.0 * std::f64::consts::PI * k as f64 / CIRCLE_SIDES as f64;
                        (r * a.cos(), r * a.sin())
                    })
                    .collect()
            }
            Footprint::Rectangle {
                front_mm,
                back_mm,
                width_mm,
            } => {
                let h = width_mm / 2.0;
                vec![(front_mm, h), (-back_mm, h), (-back_mm, -h), (front_mm, -h)]
            }
        };
        let turn = Rotation2::new(heading_rad);
        local
            .into_iter()
            .map(|(x, y)| {
                let p = turn * Vector2::new(x, y);
                Coord { x: p.x, y: p.y }
            })
            .collect()
    }

    /// The outline as a polygon with the hip point at `(x, y)`.
    pub fn polygon_at(&self, x: f64, y: f64, heading_rad: f64) -> Polygon<f64> {
        let ring: Vec<Coord<f64>> = self
            .corners(heading_rad)
            .into_iter()
            .map(|c| Coord {
                x: c.x + x,
                y: c.y + y,
            })
            .collect();
        Polygon::new(LineString::from(ring), Vec::new())
    }

    /// Whether turning the base changes the outline (a circle does not).
    pub fn turns(&self) -> bool {
        matches!(self, Footprint::Rectangle { .. })
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_rectangle_turned_a_quarter_points_its_front_along_y() {
        let f = Footprint::Rectangle {
            front_mm: 600.0,
            back_mm: 400.0,
            width_mm: 600.0,
        };
        let corners = f.corners(std::f64::consts::FRAC_PI_2);
        let max_y = corners.iter().map(|c| c.y).fold(f64::MIN, f64::max);
        let min_y = corners.iter().map(|c| c.y).fold(f64::MAX, f64::min);
        assert!((max_y - 600.0).abs() < 1e-9 && (min_y + 400.0).abs() < 1e-9);
    }

    #[test]
    fn the_circle_polygon_contains_the_circle() {
        let f = Footprint::Circle { radius_mm: 400.0 };
        for c in f.corners(0.3) {
            assert!((c.x * c.x + c.y * c.y).sqrt() >= 400.0);
        }
    }
}
