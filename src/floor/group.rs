//! Footprints that bound a group's (a population's members'): one that
//! holds every member's (`outer`) and one that every member's holds
//! (`inner`), each a margin beyond. Where the outer can get to from a
//! door, every member can (the way it takes is clear for a smaller
//! footprint); where the inner cannot, no member can. So the routes from
//! the doors are worked out twice for the whole group, and a member's own
//! only where the two leave a place undecided (`shared_routes.rs`).

use std::any::Any;
use std::collections::hash_map::DefaultHasher;
use std::collections::HashMap;
use std::hash::Hasher;
use std::sync::{Arc, Mutex};

use nalgebra::Vector2;

use super::footprint::convex_hull;
use super::{FloorPart, Footprint, Routes};
use crate::scene::{hash_bits, Room};

/// How far the outer footprint lies outside every member's, and the inner
/// inside, on the floor and in height: far more than the rounding of the
/// floor's boolean operations (about a micrometre) and than the hair a
/// route is followed wider by (0.01 mm), so that what the bounds decide,
/// the member's own routes would decide alike.
pub const GROUP_MARGIN_MM: f64 = 1.0;

/// The bounds of a group's footprints, and their routes in each room.
pub struct FloorGroup {
    /// Holds every member's footprint, part by part, with the margin.
    pub outer: Footprint,
    /// Held by every member's footprint, part by part, with the margin.
    pub inner: Footprint,
    /// How many members share the bounds (each is charged its share of
    /// their routes' work).
    pub members: usize,
    /// What the members share, by key, of whatever type it is (the
    /// outer's and the inner's routes, by room and headings,
    /// [`FloorGroup::routes_key`]; the bounds' floor,
    /// `bases/bound_floor.rs`): worked out by the first member that asks
    /// (two at once may both), kept for the group's life
    /// ([`FloorGroup::shared`]).
    shared: Mutex<HashMap<u64, Arc<dyn Any + Send + Sync>>>,
}

impl std::fmt::Debug for FloorGroup {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        f.debug_struct("FloorGroup")
            .field("outer", &self.outer)
            .field("inner", &self.inner)
            .field("members", &self.members)
            .finish_non_exhaustive()
    }
}

/// The routes of a group's outer and inner bounds in one room.
pub type BoundRoutes = (Arc<Routes>, Arc<Routes>);

impl FloorGroup {
    /// The bounds of `members` (at least two, each with the same parts in
    /// the same order, all turning: one that does not turn is followed at
    /// one heading, which its floor's other headings do not ask); none
    /// otherwise.
    pub fn of(members: &[&Footprint]) -> Option<FloorGroup> {
        let first = members.first()?;
        let parts = first.parts.len();
        let alike = members.iter().all(|f| f.parts.len() == parts && f.turns());
        if members.len() < 2 || parts == 0 || !alike {
            return None;
        }
        let outer = Footprint {
            parts: (0..parts).map(|k| outer_part(members, k)).collect(),
        };
        let inner = Footprint {
            parts: (0..parts).filter_map(|k| inner_part(members, k)).collect(),
        };
        // A bound that does not turn alike would be followed at other
        // headings than the members are.
        (outer.turns() && inner.turns()).then_some(FloorGroup {
            outer,
            inner,
            members: members.len(),
            shared: Mutex::default(),
        })
    }

    /// What the bounds' routes in `room` at `headings` are kept by.
    pub fn routes_key(&self, room: &Room, headings: &[f64]) -> u64 {
        bounds_key(&self.outer, room, &self.inner, room, headings)
    }

    /// The bounds' routes kept by `key`, or `compute`'s, kept where they
    /// are worked out (not cut short).
    pub fn routes<E>(
        &self,
        key: u64,
        compute: impl FnOnce() -> Result<Option<BoundRoutes>, E>,
    ) -> Result<Option<BoundRoutes>, E> {
        let kept = self.shared(key, compute)?;
        Ok(kept.map(|routes| BoundRoutes::clone(&routes)))
    }

    /// What the members share kept by `key` (a key for one type of
    /// value), or `compute`'s, kept where it is worked out (not cut
    /// short; two threads asking at once may both work it out, and the
    /// first kept stays).
    pub fn shared<T: Any + Send + Sync, E>(
        &self,
        key: u64,
        compute: impl FnOnce() -> Result<Option<T>, E>,
    ) -> Result<Option<Arc<T>>, E> {
        let lock = || self.shared.lock().unwrap_or_else(|e| e.into_inner());
        let found = lock().get(&key).cloned();
        if let Some(found) = found.and_then(|f| f.downcast::<T>().ok()) {
            return Ok(Some(found));
        }
        let Some(found) = compute()? else {
            return Ok(None);
        };
        let kept = Arc::clone(lock().entry(key).or_insert_with(|| Arc::new(found)));
        Ok(kept.downcast::<T>().ok())
    }

    /// A member's share of `units` of the group's work (each member is
    /// charged alike, whichever works it out).
    pub fn share(&self, units: u64) -> u64 {
        units.div_ceil(self.members.max(1) as u64)
    }

    /// Hashed bit for bit (what a member's floor depends on).
    pub fn hash_into(&self, h: &mut impl std::hash::Hasher) {
        use std::hash::Hash;
        for f in [&self.outer, &self.inner] {
            f.hash_parts(h);
            f.parts.len().hash(h);
        }
        self.members.hash(h);
    }
}

/// What the routes of bounds are kept by: footprint `outer`'s in room
/// `more`, `inner`'s in room `less` (the same room, but where an
/// element's moves are bounded, `scene::Sweep`), at `headings`.
pub fn bounds_key(
    outer: &Footprint,
    more: &Room,
    inner: &Footprint,
    less: &Room,
    headings: &[f64],
) -> u64 {
    let mut h = DefaultHasher::new();
    outer.hash_with_floor(more, &mut h);
    inner.hash_with_floor(less, &mut h);
    hash_bits(headings, &mut h);
    h.finish()
}

/// Part `k` of every member held: the convex hull of their outlines with
/// each corner pushed out by the margin in eight directions (an octagon
/// about a circle of the margin's radius), their heights spanned and
/// widened by the margin.
fn outer_part(members: &[&Footprint], k: usize) -> FloorPart {
    let reach = GROUP_MARGIN_MM / (std::f64::consts::PI / 8.0).cos();
    let around: Vec<Vector2<f64>> = (0..8)
        .map(|i| {
            let a = f64::from(i) * std::f64::consts::FRAC_PI_4;
            Vector2::new(a.cos(), a.sin()) * reach
        })
        .collect();
    let corners = (members.iter())
        .flat_map(|f| &f.parts[k].outline_mm)
        .flat_map(|c| around.iter().map(move |d| c + d));
    let lo = members
        .iter()
        .map(|f| f.parts[k].z_mm[0])
        .fold(f64::INFINITY, f64::min);
    let hi = (members.iter())
        .map(|f| f.parts[k].z_mm[1])
        .fold(f64::NEG_INFINITY, f64::max);
    FloorPart {
        outline_mm: convex_hull(corners),
        z_mm: [lo - GROUP_MARGIN_MM, hi + GROUP_MARGIN_MM],
    }
}

/// Part `k` held by every member: their outlines' common part, each side
/// moved in by the margin, over the heights they all span less the
/// margin; none where that is empty.
fn inner_part(members: &[&Footprint], k: usize) -> Option<FloorPart> {
    let lo = (members.iter())
        .map(|f| f.parts[k].z_mm[0])
        .fold(f64::NEG_INFINITY, f64::max);
    let hi = members
        .iter()
        .map(|f| f.parts[k].z_mm[1])
        .fold(f64::INFINITY, f64::min);
    let z_mm = [lo + GROUP_MARGIN_MM, hi - GROUP_MARGIN_MM];
    if z_mm[0] >= z_mm[1] {
        return None;
    }
    let mut common: Vec<Vector2<f64>> = members[0].parts[k].outline_mm.clone();
    for f in members {
        let outline = counter_clockwise(&f.parts[k].outline_mm);
        for (a, b) in outline.iter().zip(outline.iter().cycle().skip(1)) {
            common = clipped(&common, *a, *b, GROUP_MARGIN_MM);
            if common.len() < 3 {
                return None;
            }
        }
    }
    Some(FloorPart {
        outline_mm: convex_hull(common),
        z_mm,
    })
}

/// `outline` with its corners counter-clockwise.
fn counter_clockwise(outline: &[Vector2<f64>]) -> Vec<Vector2<f64>> {
    let twice_area: f64 = (outline.iter().zip(outline.iter().cycle().skip(1)))
        .map(|(a, b)| a.x * b.y - b.x * a.y)
        .sum();
    let mut out = outline.to_vec();
    if twice_area < 0.0 {
        out.reverse();
    }
    out
}

/// The convex polygon `poly` cut to the side left of the line from `a` to
/// `b`, `inset_mm` in from it (Sutherland-Hodgman, one edge).
fn clipped(
    poly: &[Vector2<f64>],
    a: Vector2<f64>,
    b: Vector2<f64>,
    inset_mm: f64,
) -> Vec<Vector2<f64>> {
    let along = b - a;
    let length = along.norm();
    if length == 0.0 {
        return poly.to_vec();
    }
    // How far left of the moved line a point lies.
    let side =
        |p: &Vector2<f64>| (along.x * (p.y - a.y) - along.y * (p.x - a.x)) / length - inset_mm;
    let mut out = Vec::with_capacity(poly.len() + 1);
    for (p, q) in poly.iter().zip(poly.iter().cycle().skip(1)) {
        let (sp, sq) = (side(p), side(q));
        if sp >= 0.0 {
            out.push(*p);
        }
        if (sp >= 0.0) != (sq >= 0.0) {
            out.push(p + (q - p) * (sp / (sp - sq)));
        }
    }
    out
}

#[cfg(test)]
mod tests {
    use super::*;
    use geo::{Contains, Coord, LineString, Polygon};

    fn polygon(outline: &[Vector2<f64>]) -> Polygon<f64> {
        let ring: Vec<Coord<f64>> = outline.iter().map(|v| Coord { x: v.x, y: v.y }).collect();
        Polygon::new(LineString::from(ring), Vec::new())
    }

    fn chair(front_mm: f64, width_mm: f64, height_mm: f64) -> Footprint {
        Footprint::rectangle(front_mm, 500.0, width_mm, height_mm)
    }

    /// Each member's parts hold the inner's and lie in the outer's, with
    /// the margin to spare, in outline and in height.
    #[test]
    fn the_bounds_hold_and_are_held_by_every_member() {
        let members = [
            chair(400.0, 640.0, 900.0),
            chair(460.0, 600.0, 1000.0),
            chair(430.0, 700.0, 950.0),
        ];
        let refs: Vec<&Footprint> = members.iter().collect();
        let group = FloorGroup::of(&refs).expect("alike footprints");
        for m in &members {
            for (k, part) in m.parts.iter().enumerate() {
                let shrunk = part
                    .outline_mm
                    .iter()
                    .map(|v| v * 0.999)
                    .collect::<Vec<_>>();
                let outer = polygon(&group.outer.parts[k].outline_mm);
                assert!(outer.contains(&polygon(&m.grown(0.9).parts[k].outline_mm)));
                let inner = &group.inner.parts[k];
                assert!(polygon(&shrunk).contains(&polygon(&inner.outline_mm)));
                assert!(group.outer.parts[k].z_mm[0] < part.z_mm[0]);
                assert!(group.outer.parts[k].z_mm[1] > part.z_mm[1]);
                assert!(inner.z_mm[0] > part.z_mm[0] && inner.z_mm[1] < part.z_mm[1]);
            }
        }
        // The common outline is the smallest front and width, less 1 mm.
        let inner = polygon(&group.inner.parts[0].outline_mm);
        assert!(inner.contains(&geo::Point::new(398.5, 298.5)));
        assert!(!inner.contains(&geo::Point::new(399.5, 0.0)));
        assert!(!inner.contains(&geo::Point::new(0.0, 299.5)));
    }

    #[test]
    fn one_member_or_unlike_parts_make_no_group() {
        let one = chair(400.0, 640.0, 900.0);
        assert!(FloorGroup::of(&[&one]).is_none());
        let mut two_parts = chair(400.0, 640.0, 900.0);
        two_parts.parts.push(two_parts.parts[0].clone());
        assert!(FloorGroup::of(&[&one, &two_parts]).is_none());
    }
}
