//! What a base takes up on the floor, as the floor sees it: each of its
//! solids (the chair's seat, wheels and footrests, the rollator's frame,
//! the person's legs and upright trunk) as a convex outline from above in
//! the base frame (x forward, y to the left, origin at the hip point) and
//! the heights it spans above the floor. An obstacle blocks a part only
//! where their heights overlap, so knees and toes go under a counter as far
//! as its knee and toe clearance allow.

use geo::{Coord, LineString, Polygon};
use nalgebra::{Rotation2, Vector2};

use crate::geometry::{Shape, Solid};
use crate::scene::{hash_bits, Room};

/// The largest step between the turned outlines of a swept footprint.
pub const SWEEP_STEP_RAD: f64 = 2.5 * std::f64::consts::PI / 180.0;

/// Sides of the polygon that stands for a circle. It is circumscribed, so
/// a clearance check with it never lets the circle overlap an obstacle.
const CIRCLE_SIDES: usize = 24;

/// One part: its outline from above and the heights it spans.
#[derive(Clone, Debug, PartialEq)]
pub struct FloorPart {
    /// Convex, in the base frame, millimetres.
    pub outline_mm: Vec<Vector2<f64>>,
    /// Lowest and highest, above the floor.
    pub z_mm: [f64; 2],
}

/// A base's parts as the floor sees them.
#[derive(Clone, Debug, PartialEq, Default)]
pub struct Footprint {
    pub parts: Vec<FloorPart>,
}

impl Footprint {
    /// How far its widest part reaches to either side of the hip point
    /// (the lines of its sides, for a forward or side approach).
    pub fn half_width_mm(&self) -> f64 {
        self.parts
            .iter()
            .flat_map(|p| p.outline_mm.iter())
            .map(|v| v.y.abs())
            .fold(0.0, f64::max)
    }

    /// The heights each part stands at, from the floor up.
    pub fn bands_mm(&self) -> Vec<[f64; 2]> {
        self.parts.iter().map(|p| p.z_mm).collect()
    }

    /// Its parts' outlines and heights, hashed bit for bit, and the floor
    /// of `room` as they meet it (`Room::hash_floor`): what a region where
    /// it fits depends on (for what is kept across runs, `crate::kept`).
    pub fn hash_with_floor(&self, room: &Room, h: &mut impl std::hash::Hasher) {
        room.hash_floor(&self.bands_mm(), h);
        self.hash_parts(h);
    }

    /// Its parts' outlines and heights, hashed bit for bit.
    pub fn hash_parts(&self, h: &mut impl std::hash::Hasher) {
        for part in &self.parts {
            part.outline_mm.iter().for_each(|p| hash_bits(p.iter(), h));
            hash_bits(&part.z_mm, h);
        }
    }

    /// One circle about the hip point, from the floor to `height_mm`.
    pub fn circle(radius_mm: f64, height_mm: f64) -> Self {
        Footprint {
            parts: vec![FloorPart {
                outline_mm: circle(Vector2::zeros(), radius_mm),
                z_mm: [0.0, height_mm],
            }],
        }
    }

    /// One rectangle, `front_mm` ahead of the hip point and `back_mm`
    /// behind it, `width_mm` wide, from the floor to `height_mm`.
    pub fn rectangle(front_mm: f64, back_mm: f64, width_mm: f64, height_mm: f64) -> Self {
        let h = width_mm / 2.0;
        let outline_mm = [(front_mm, h), (-back_mm, h), (-back_mm, -h), (front_mm, -h)]
            .map(|(x, y)| Vector2::new(x, y))
            .to_vec();
        Footprint {
            parts: vec![FloorPart {
                outline_mm,
                z_mm: [0.0, height_mm],
            }],
        }
    }

    /// The parts of `solids` (in the base frame) with the hip point
    /// `hip_height_mm` above the floor.
    pub fn of_solids<'a>(solids: impl IntoIterator<Item = &'a Solid>, hip_height_mm: f64) -> Self {
        Footprint {
            parts: solids
                .into_iter()
                .map(|s| part_of(&s.shape, hip_height_mm))
                .collect(),
        }
    }

    /// The outline of part `part` turned by `heading_rad`
    /// (counter-clockwise), relative to the hip point.
    /// The farthest any part reaches from the hip point, on the floor.
    pub fn extent_mm(&self) -> f64 {
        self.parts
            .iter()
            .flat_map(|p| &p.outline_mm)
            .map(|c| c.norm())
            .fold(0.0, f64::max)
    }

    pub fn corners(&self, part: usize, heading_rad: f64) -> Vec<Coord<f64>> {
        let turn = Rotation2::new(heading_rad);
        self.parts[part]
            .outline_mm
            .iter()
            .map(|p| {
                let q = turn * p;
                Coord { x: q.x, y: q.y }
            })
            .collect()
    }

    /// Part `part` as a polygon with the hip point at `(x, y)`.
    pub fn polygon_at(&self, part: usize, x: f64, y: f64, heading_rad: f64) -> Polygon<f64> {
        let ring: Vec<Coord<f64>> = self
            .corners(part, heading_rad)
            .into_iter()
            .map(|c| Coord {
                x: c.x + x,
                y: c.y + y,
            })
            .collect();
        Polygon::new(LineString::from(ring), Vec::new())
    }

    /// Each part's outline pushed `by_mm` outwards, corner by corner (away
    /// from the part's centre): a base that fits this clears each obstacle
    /// by at least a hair.
    pub fn grown(&self, by_mm: f64) -> Footprint {
        let parts = (self.parts.iter())
            .map(|part| {
                let n = part.outline_mm.len().max(1) as f64;
                let centre = part.outline_mm.iter().sum::<Vector2<f64>>() / n;
                let outline_mm = (part.outline_mm.iter())
                    .map(|&v| {
                        let out = v - centre;
                        let norm = out.norm();
                        if norm > 0.0 {
                            v + out * (by_mm / norm)
                        } else {
                            v
                        }
                    })
                    .collect();
                FloorPart {
                    outline_mm,
                    z_mm: part.z_mm,
                }
            })
            .collect();
        Footprint { parts }
    }

    /// What the footprint covers while it turns in place about the hip
    /// point from its heading to `angle_rad` more (counter-clockwise):
    /// each part the convex hull of its outline at steps of at most
    /// [`SWEEP_STEP_RAD`], grown about the hip point by 1 / cos(step / 2)
    /// so that the arcs its corners trace between steps lie inside. A base
    /// that fits this at a point can turn there through that angle.
    pub fn swept(&self, angle_rad: f64) -> Footprint {
        let steps = (angle_rad.abs() / SWEEP_STEP_RAD).ceil().max(1.0) as usize;
        let step = angle_rad / steps as f64;
        let grow = 1.0 / (step / 2.0).cos();
        let parts = self
            .parts
            .iter()
            .map(|part| {
                let turned = (0..=steps).flat_map(|k| {
                    let turn = Rotation2::new(step * k as f64);
                    part.outline_mm.iter().map(move |c| turn * c * grow)
                });
                FloorPart {
                    outline_mm: convex_hull(turned),
                    z_mm: part.z_mm,
                }
            })
            .collect();
        Footprint { parts }
    }

    /// Whether turning the base changes where it fits (parts other than
    /// circles about the hip point do).
    pub fn turns(&self) -> bool {
        self.parts.iter().any(|p| {
            let r0 = p.outline_mm.first().map_or(0.0, |c| c.norm());
            p.outline_mm.iter().any(|c| (c.norm() - r0).abs() > 1e-9)
                || p.outline_mm.len() != CIRCLE_SIDES
        })
    }
}

/// A solid's outline from above and its heights.
fn part_of(shape: &Shape, hip_height_mm: f64) -> FloorPart {
    let [lo, hi] = shape.bounds();
    let z_mm = [lo.z + hip_height_mm, hi.z + hip_height_mm];
    let outline_mm = match shape {
        Shape::Capsule(c) => {
            let (a, b) = (c.a.xy().coords, c.b.xy().coords);
            convex_hull(
                circle(a, c.radius_mm)
                    .into_iter()
                    .chain(circle(b, c.radius_mm)),
            )
        }
        Shape::Cuboid(c) => {
            let turn = Rotation2::new(c.yaw_rad);
            let h = c.half_mm;
            [(1.0, 1.0), (-1.0, 1.0), (-1.0, -1.0), (1.0, -1.0)]
                .map(|(sx, sy)| c.centre.xy().coords + turn * Vector2::new(sx * h.x, sy * h.y))
                .to_vec()
        }
    };
    FloorPart { outline_mm, z_mm }
}

/// A circumscribed polygon about the circle of `radius_mm` at `centre`.
fn circle(centre: Vector2<f64>, radius_mm: f64) -> Vec<Vector2<f64>> {
    let r = radius_mm / (std::f64::consts::PI / CIRCLE_SIDES as f64).cos();
    (0..CIRCLE_SIDES)
        .map(|k| {
            let a = 2.0 * std::f64::consts::PI * k as f64 / CIRCLE_SIDES as f64;
            centre + Vector2::new(r * a.cos(), r * a.sin())
        })
        .collect()
}

/// The convex hull of `points`, counter-clockwise (Andrew's monotone chain).
pub(super) fn convex_hull(points: impl IntoIterator<Item = Vector2<f64>>) -> Vec<Vector2<f64>> {
    let mut p: Vec<Vector2<f64>> = points.into_iter().collect();
    p.sort_by(|a, b| a.x.total_cmp(&b.x).then(a.y.total_cmp(&b.y)));
    p.dedup();
    if p.len() < 3 {
        return p;
    }
    let cross = |o: &Vector2<f64>, a: &Vector2<f64>, b: &Vector2<f64>| {
        (a.x - o.x) * (b.y - o.y) - (a.y - o.y) * (b.x - o.x)
    };
    let mut hull: Vec<Vector2<f64>> = Vec::with_capacity(2 * p.len());
    for pass in [&p[..], &p.iter().rev().copied().collect::<Vec<_>>()[..]] {
        let start = hull.len();
        for q in pass {
            while hull.len() >= start + 2
                && cross(&hull[hull.len() - 2], &hull[hull.len() - 1], q) <= 0.0
            {
                hull.pop();
            }
            hull.push(*q);
        }
        hull.pop();
    }
    hull
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::geometry::{Capsule, Cuboid};
    use nalgebra::Point3;

    #[test]
    fn a_rectangle_turned_a_quarter_points_its_front_along_y() {
        let f = Footprint::rectangle(600.0, 400.0, 600.0, 1400.0);
        let corners = f.corners(0, std::f64::consts::FRAC_PI_2);
        let max_y = corners.iter().map(|c| c.y).fold(f64::MIN, f64::max);
        let min_y = corners.iter().map(|c| c.y).fold(f64::MAX, f64::min);
        assert!((max_y - 600.0).abs() < 1e-9 && (min_y + 400.0).abs() < 1e-9);
        assert!(f.turns());
    }

    #[test]
    fn a_swept_footprint_holds_the_footprint_at_every_angle_of_the_turn() {
        use geo::{Contains, Distance, Point};
        let f = Footprint::rectangle(700.0, 350.0, 660.0, 1400.0);
        let angle = 0.4;
        let swept = f.swept(angle);
        let hull = Polygon::new(LineString::from(swept.corners(0, 0.0)), Vec::new());
        // Every corner of the rectangle, and the points between, at many
        // angles of the turn (not only the steps).
        for k in 0..=200 {
            let a = angle * k as f64 / 200.0;
            for c in f.corners(0, a) {
                let inside = hull.contains(&Point::new(c.x, c.y))
                    || geo::Euclidean.distance(&hull, &Point::new(c.x, c.y)) < 1e-9;
                assert!(inside, "corner {c:?} at {a} rad");
            }
        }
        // And it is not much larger than it must be.
        use geo::Area;
        let one = Polygon::new(LineString::from(f.corners(0, 0.0)), Vec::new());
        assert!(hull.unsigned_area() < 1.5 * one.unsigned_area());
    }

    #[test]
    fn the_circle_polygon_contains_the_circle() {
        let f = Footprint::circle(400.0, 1900.0);
        for c in f.corners(0, 0.3) {
            assert!((c.x * c.x + c.y * c.y).sqrt() >= 400.0);
        }
        assert!(!f.turns());
    }

    #[test]
    fn solids_give_outlines_and_heights_above_the_floor() {
        let thigh = Solid::new(
            "the left thigh",
            Shape::Capsule(Capsule::new(
                Point3::new(0.0, 95.0, 0.0),
                Point3::new(430.0, 95.0, 0.0),
                99.0,
            )),
        );
        let seat = Solid::new(
            "the seat",
            Shape::Cuboid(Cuboid::between(
                Point3::new(-140.0, -230.0, -160.0),
                Point3::new(290.0, 230.0, -100.0),
            )),
        );
        let f = Footprint::of_solids([&thigh, &seat], 595.0);
        assert_eq!(f.parts[0].z_mm, [496.0, 694.0]);
        let xs: Vec<f64> = f.parts[0].outline_mm.iter().map(|c| c.x).collect();
        let reach = xs.iter().copied().fold(f64::MIN, f64::max);
        assert!((529.0..535.0).contains(&reach), "knee front {reach}");
        assert_eq!(f.parts[1].z_mm, [435.0, 495.0]);
        assert_eq!(f.parts[1].outline_mm.len(), 4);
    }
}
