//! The floor of a population member's base, told by its floor group's
//! bounds (`floor/group.rs`) where they decide. The outer footprint holds
//! every member's: where it fits, each member's fits, and where it gets
//! there from a door, each member's gets there by the same way. The inner
//! is held by every member's: where it does not fit, no member's does.
//! So the member's own search for whether it fits anywhere at a heading
//! (its floor tile by tile, from the room's middle out) is not made where
//! the outer fits there, and whether a place is on its floor is asked of
//! its own tile only where the bounds leave it open (`Region::bounded_by`).
//! The bounds' floor is worked out once for the group, each member
//! charged its share. The answers are the member's own either way
//! (tests/population.rs compares a population with its members alone).

use std::collections::hash_map::DefaultHasher;
use std::hash::{Hash, Hasher};
use std::sync::Arc;

use crate::floor::{
    emptiness_each, Bounds, CutShort, DoorRoutes, FloorGroup, FloorObstacles, Footprint, Region,
    Routes, Work, Zone,
};
use crate::kept::Memo;
use crate::scene::{hash_bits, Room};

/// The floor of a group's bounds in one room: their regions at each
/// heading searched (in heading order), whether the outer's is not empty
/// at each, and what finding out cost the whole group.
pub struct BoundFloor {
    pub regions: Vec<Bounds>,
    pub outer_fits: Vec<bool>,
    pub work: u64,
}

/// The room, headings and zone a member's floor is searched in.
pub struct Searched<'a> {
    pub room: &'a Room,
    pub headings: &'a [f64],
    pub zone: Option<&'a Zone>,
}

/// The floor of `group`'s bounds at each of `searched`'s headings; the
/// outer's cut to `routes` (its own routes from the doors, or those of a
/// room with more in it, which reach no farther; with their key) where
/// they are given. With the member's share of the work; cut short where that share
/// would pass what `within` allows.
pub fn bound_floor(
    searched: &Searched<'_>,
    group: &FloorGroup,
    routes: Option<(&Arc<Routes>, u64)>,
    within: &(dyn Fn(u64) -> bool + Sync),
    memo: &Arc<Memo>,
) -> Result<Option<(Arc<BoundFloor>, u64)>, CutShort> {
    let shared = |units: u64| within(group.share(units));
    let routes_key = routes.map(|(_, key)| key);
    let routes = routes.map(|(routes, _)| routes);
    let floor = group
        .shared(key(searched, group, routes_key), || {
            worked_out(searched, group, routes, &shared, memo).map(Some)
        })
        .map_err(|cut| CutShort {
            work: group.share(cut.work),
        })?;
    Ok(floor.map(|f| {
        let share = group.share(f.work);
        (f, share)
    }))
}

/// What the bounds' floor is kept by in its group: the room, and the
/// bounds' routes it is cut to, by their key, where it is.
fn key(searched: &Searched<'_>, group: &FloorGroup, routed: Option<u64>) -> u64 {
    let mut h = DefaultHasher::new();
    "the bounds' floor".hash(&mut h);
    group
        .routes_key(searched.room, searched.headings)
        .hash(&mut h);
    hash_zone(searched.zone, &mut h);
    routed.hash(&mut h);
    h.finish()
}

/// A zone (its rectangle and outline), hashed bit for bit.
pub fn hash_zone(zone: Option<&Zone>, h: &mut impl Hasher) {
    if let Some(zone) = zone {
        hash_bits(&[zone.min.0, zone.min.1, zone.max.0, zone.max.1], h);
        if let Some(outline) = &zone.outline {
            let corners = outline.exterior().coords().flat_map(|c| [c.x, c.y]);
            hash_bits(&corners.collect::<Vec<f64>>(), h);
        }
    }
}

/// The bounds' regions, one of each per heading, the outer's searched in
/// full for whether it is empty (the inner's tiles are worked out only
/// where a member asks).
fn worked_out(
    searched: &Searched<'_>,
    group: &FloorGroup,
    routes: Option<&Arc<Routes>>,
    within: &(dyn Fn(u64) -> bool + Sync),
    memo: &Arc<Memo>,
) -> Result<BoundFloor, CutShort> {
    let mut work = Work::new(within);
    let outer = regions(searched, &group.outer, routes, &mut work, memo)?;
    let inner = regions(searched, &group.inner, None, &mut work, memo)?;
    let empty = emptiness_each(&outer.iter().collect::<Vec<_>>(), &mut work)?;
    let regions = (outer.into_iter().zip(inner))
        .map(|(outer, inner)| Bounds {
            outer: Arc::new(outer),
            inner: Arc::new(inner),
        })
        .collect();
    Ok(BoundFloor {
        regions,
        outer_fits: empty.iter().map(|e| !e).collect(),
        work: work.done,
    })
}

/// The regions of `footprint` at each heading searched, cut to `routes`
/// where given; its obstacles' work added to `work`.
fn regions(
    searched: &Searched<'_>,
    footprint: &Footprint,
    routes: Option<&Arc<Routes>>,
    work: &mut Work<'_>,
    memo: &Arc<Memo>,
) -> Result<Vec<Region>, CutShort> {
    let Searched {
        room,
        headings,
        zone,
    } = *searched;
    let allows = |units: u64| work.allows(units);
    let obstacles = FloorObstacles::with(room, footprint, &[], &allows)
        .map_err(|cut| work.cut_short_with(cut.work))?;
    let obstacles = Arc::new(obstacles);
    work.add(obstacles.work())?;
    let routes = routes.map(|r| Arc::new(DoorRoutes::Own(Arc::clone(r))));
    Ok((headings.iter())
        .map(|&h| {
            let obstacles = Arc::clone(&obstacles);
            match &routes {
                None => Region::new(room, footprint, h, zone, obstacles, memo),
                Some(r) => {
                    Region::reached(room, footprint, h, zone, obstacles, Arc::clone(r), memo)
                }
            }
        })
        .collect())
}
