//! The parts of a person that no joint moves, for the base they stand or
//! sit on: the legs, and the upright trunk, head and shoulders as a column
//! (what the floor must find room for); and, once the base has placed
//! them, the person's own body and the base's parts as solids the links
//! must stay out of.

use nalgebra::Point3;

use crate::geometry::{Capsule, Cuboid, Shape, Solid};
use crate::kinematics::{upper_centre_mm, Balance, Body, Legs, Owner, Stance};

/// What a base needs to know of the person on it.
#[derive(Clone, Debug, PartialEq)]
pub struct Physique {
    pub legs: Option<Legs>,
    /// As the mannequin declares it (`None`: as the base has it).
    pub posture: Option<Stance>,
    /// The upright trunk, head and shoulders: least and greatest corners
    /// in the base frame, at the neutral posture.
    pub column_mm: Option<[Point3<f64>; 2]>,
    /// How far to the left of the midplane the centre of mass of the upper
    /// body's solids is at rest (`kinematics::Balance`).
    pub rest_left_mm: f64,
}

impl Physique {
    pub fn of(body: &Body) -> Self {
        Physique {
            legs: body.legs.clone(),
            posture: body.posture,
            column_mm: column(body),
            rest_left_mm: rest_left_mm(body),
        }
    }
}

/// How far to the left of the midplane the centre of mass of `body`'s
/// upper body is at rest: its first chain's solids and the rest of the
/// body carried as ballast.
fn rest_left_mm(body: &Body) -> f64 {
    if body.effectors.is_empty() {
        return 0.0;
    }
    let chain = body.chain(0);
    upper_centre_mm(&chain.volumes(&chain.neutral())).map_or(0.0, |c| c.y)
}

/// The upright column of `body`: the first link of its first chain (the
/// trunk), the shoulders level with the trunk's top, and the spheres (the
/// head), at the neutral posture, as wide to the left as to the right.
fn column(body: &Body) -> Option<[Point3<f64>; 2]> {
    let chain = body.chain(0);
    let v = chain.volumes(&chain.neutral());
    let trunk = v
        .owners
        .iter()
        .position(|o| matches!(o, Owner::Link(_)))
        .map(|i| v.capsules[i])?;
    let top = trunk.a.z.max(trunk.b.z) - 1.0;
    let parts = v.capsules.iter().zip(&v.owners).filter(|(c, o)| {
        matches!(o, Owner::Rider(_)) || (c.a.z >= top && c.b.z >= top) || **c == trunk
    });
    let mut bounds = trunk.bounds();
    for (c, _) in parts {
        let [lo, hi] = c.bounds();
        bounds = [bounds[0].inf(&lo), bounds[1].sup(&hi)];
    }
    let half_width = bounds[0].y.abs().max(bounds[1].y.abs());
    bounds[0].y = -half_width;
    bounds[1].y = half_width;
    Some(bounds)
}

/// The parts of a person and their base that no joint moves, in the base
/// frame: the legs, the chair or the rollator. A link must stay out of
/// them, but for the trunk's part within `pelvis_mm` of the hip point,
/// where the trunk meets the seat and the thighs.
#[derive(Clone, Debug, PartialEq, Default)]
pub struct OwnBody {
    pub solids: Vec<Solid>,
    pub pelvis_mm: f64,
    /// Each solid's axis-aligned bounds.
    bounds: Vec<[Point3<f64>; 2]>,
    /// Standing: the legs' balance, which every posture must keep.
    pub balance: Option<Balance>,
    /// Whether the base placed the legs clear of the room, as a base that
    /// moves does (a fixed base puts the hips where it is told, and the
    /// feet under them must be checked).
    pub feet_placed: bool,
}

impl OwnBody {
    pub fn new(solids: Vec<Solid>, pelvis_mm: f64) -> Self {
        OwnBody {
            bounds: solids.iter().map(|s| s.shape.bounds()).collect(),
            solids,
            pelvis_mm,
            balance: None,
            feet_placed: false,
        }
    }

    /// This body, of `person`, standing on their legs: every posture must
    /// keep its balance over them, the feet clear of the room.
    pub fn standing(mut self, person: &Physique) -> Self {
        let rest = person.rest_left_mm;
        self.balance = person.legs.clone().map(|l| Balance::new(l, rest));
        self
    }

    /// [`OwnBody::standing`], on a base that placed the legs clear of the
    /// room: the feet are checked only where the balance moves them.
    pub fn standing_placed(self, person: &Physique) -> Self {
        OwnBody {
            feet_placed: true,
            ..self.standing(person)
        }
    }

    /// The first solid (by index) that `capsule` (in the base frame)
    /// overlaps, but for its part within the pelvis.
    pub fn hit(&self, capsule: &Capsule) -> Option<usize> {
        self.hits(capsule).next()
    }

    /// Every part `capsule` overlaps, by index, as [`OwnBody::hit`] finds
    /// the first.
    pub fn hits<'a>(&'a self, capsule: &Capsule) -> impl Iterator<Item = usize> + 'a {
        // Most links are nowhere near the legs or the chair: the bounds
        // say so before the pelvis is cut away.
        let whole = capsule.bounds();
        let near = !self.bounds.iter().all(|b| apart(&whole, b));
        let cut = near.then(|| self.outside_pelvis(capsule)).flatten();
        cut.into_iter().flat_map(move |c| {
            let cut = c.bounds();
            self.solids
                .iter()
                .zip(&self.bounds)
                .enumerate()
                .filter(move |(_, (s, b))| {
                    !apart(&cut, b)
                        && s.shape.distance_to_segment(&c.a, &c.b) < c.radius_mm.max(1e-9)
                })
                .map(|(i, _)| i)
        })
    }

    /// Whether the capsule `cut` (in the base frame, its part within the
    /// pelvis already cut away) overlaps a part by more than `depth_mm`:
    /// a part is nearer its segment than its radius less the depth.
    pub fn sunk_deeper_than(&self, cut: &Capsule, depth_mm: f64) -> bool {
        let clear_mm = cut.radius_mm - depth_mm;
        if clear_mm <= 0.0 {
            return false;
        }
        let reach = nalgebra::Vector3::repeat(clear_mm);
        let near = [cut.a.inf(&cut.b) - reach, cut.a.sup(&cut.b) + reach];
        self.solids.iter().zip(&self.bounds).any(|(s, b)| {
            !apart(&near, b) && s.shape.distance_to_segment(&cut.a, &cut.b) < clear_mm
        })
    }

    /// The first solid the line from `a` to `b` (in the base frame) enters,
    /// and where along it (0 at `a`, 1 at `b`); the last `end_gap_mm` before
    /// `b` is not looked at.
    pub fn first_on_line(
        &self,
        a: &Point3<f64>,
        b: &Point3<f64>,
        end_gap_mm: f64,
    ) -> Option<(usize, f64)> {
        let length = (b - a).norm();
        if length <= end_gap_mm {
            return None;
        }
        let max = 1.0 - end_gap_mm / length;
        let at = |t: f64| a + (b - a) * t;
        let meets = |s: &Solid, t: f64| s.shape.distance_to_segment(a, &at(t)) <= 0.0;
        self.solids
            .iter()
            .enumerate()
            .filter(|(_, s)| meets(s, max))
            .map(|(i, s)| {
                // The distance from `a` to the part of the line up to t
                // falls with t: the entry is where it first reaches zero.
                let (mut lo, mut hi) = (0.0, max);
                for _ in 0..50 {
                    let mid = 0.5 * (lo + hi);
                    if meets(s, mid) {
                        hi = mid;
                    } else {
                        lo = mid;
                    }
                }
                (i, hi)
            })
            .min_by(|x, y| x.1.total_cmp(&y.1))
    }

    /// `capsule` (in the base frame, from its near end `a` to its far end
    /// `b`) without its part within the pelvis, where it starts there: the
    /// trunk, from the hip point, may press into the seat and thighs as
    /// flesh gives. A solid that starts outside the pelvis is kept whole:
    /// a forearm passing beside the hip may not go through the seat, a
    /// wheel or a thigh, however near the hip point it passes (it did,
    /// within 285 mm of the 95th-percentile man's, and reached into the
    /// slot between his seat and wheel).
    pub fn outside_pelvis(&self, capsule: &Capsule) -> Option<Capsule> {
        let starts_inside = capsule.a.coords.norm() < self.pelvis_mm;
        if !starts_inside {
            return Some(*capsule);
        }
        capsule.outside_ball(&Point3::origin(), self.pelvis_mm)
    }
}

/// Whether two axis-aligned bounds (least and greatest corners) have a gap
/// between them along some axis.
fn apart([lo, hi]: &[Point3<f64>; 2], b: &[Point3<f64>; 2]) -> bool {
    (0..3).any(|i| hi[i] < b[0][i] || lo[i] > b[1][i])
}

/// The column's corners as a box, a solid of that name.
pub fn column_solid(name: &str, [lo, hi]: [Point3<f64>; 2]) -> Solid {
    Solid::new(name, Shape::Cuboid(Cuboid::between(lo, hi)))
}
