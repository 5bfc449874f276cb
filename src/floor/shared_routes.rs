//! The routes from a room's doors as one member of a group asks them: its
//! own (`Routes`), or its group's bounds (`group.rs`) worked out once for
//! every member, its own only where they leave a piece of its floor
//! undecided. A piece of the member's floor (at one heading, in one tile:
//! a base there can drive anywhere in it) is reached where it overlaps
//! floor the outer bound reaches (the outer's way there is clear for the
//! member), and not reached where it overlaps none the inner bound reaches
//! (no way is clear for the inner, so none for the member); else, where
//! the piece runs on, in a window about it, into floor the outer reaches,
//! reached; else the next, tighter group's bounds tell in the same way
//! (a member is in a group of the whole population and in one of the
//! members most alike it), and past the last the member's own routes,
//! each worked out then, once. What the window, the tighter bounds and
//! the member's own routes cost is charged with the tile. Where the room
//! is one of those an element's moves make (`advise`), the outer's routes
//! are those of the sweep's room with the element over all its moves and
//! the inner's those of the room without it (`scene::Sweep`), worked out
//! once for every position; a base without a group is bounded so by its
//! own footprint. The answers are the member's own routes' (this file's
//! property tests compare them).

use std::sync::{Arc, OnceLock};

use geo::{BoundingRect, Coord, MultiPolygon, Polygon, Rect};

use super::group::{bounds_key, FloorGroup};
use super::routes::{needs_mm, pieces_overlap, Doorway, Entry, Routes, HAIR_MM};
use super::work::{unbounded, CutShort};
use super::Footprint;
use crate::kept::Memo;
use crate::once::get_or_compute;
use crate::scene::{Room, Sweep};

/// How far beyond a piece of floor the window its floor is followed in
/// reaches (where the bounds leave it undecided): a pocket beside a
/// counter's end or a post, cut off from the open floor by a tile's
/// edge, runs on into it within a metre or so.
const WINDOW_MM: f64 = 600.0;

/// The floor in a window of a footprint, facing the way a piece asked
/// about does, and its work (none where the window is outside the room).
pub type Around<'a> = dyn Fn(Rect<f64>, &Footprint) -> Option<(MultiPolygon<f64>, u64)> + 'a;

/// The routes a base's floor is cut to.
pub enum DoorRoutes {
    /// Worked out for the base's own footprint.
    Own(Arc<Routes>),
    /// Bounded by its group's.
    Shared(Arc<SharedRoutes>),
}

/// Whether a piece of floor is reached, and what finding out cost beyond
/// the floor's.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct Decided {
    pub reached: bool,
    /// The member's floor in a window about the piece.
    pub window_work: u64,
    /// The member's share of its tighter groups' bounds, where they were
    /// asked (0 where not): the same for every piece of one member that
    /// asks them.
    pub tighter_work: u64,
    /// The member's own routes, where they were asked (0 where not).
    pub own_work: u64,
}

/// A member's routes bounded by its group's.
pub struct SharedRoutes {
    outer: Arc<Routes>,
    inner: Arc<Routes>,
    /// What the bounds are kept by (`group::bounds_key`).
    key: u64,
    /// The room, its footprint and headings, for its own routes.
    room: Room,
    footprint: Footprint,
    /// The footprint a hair wider, as routes follow it.
    followed: Footprint,
    headings: Vec<f64>,
    memo: Arc<Memo>,
    own: OnceLock<Arc<Routes>>,
    /// The member's tighter groups, which tell (in order) where these
    /// bounds leave a piece undecided, and the sweep they are bounded by.
    tighter: Vec<Arc<FloorGroup>>,
    sweep: Option<Sweep>,
    /// The routes the tighter groups bound, and the member's share of
    /// their work, worked out once (where there are tighter groups).
    next: OnceLock<(DoorRoutes, u64)>,
    doors: Vec<Doorway>,
}

impl DoorRoutes {
    /// The routes of `footprint` (a member of each of `groups`, the
    /// widest first, where it has any) in `room`, followed at `headings`;
    /// none where the room has no door. The bounds are shared where the
    /// first group has them (or, without a group, `sweep` bounds the
    /// room), the room has no meshes (whose copy would cost as much as the
    /// routes) and the outer bound comes in by every door (a member then
    /// does too); else the next group's, and past the last the
    /// footprint's own. Cut short as [`Routes::of`] is, the bounds counted
    /// at the member's share of their work. The work to charge the member
    /// comes with them.
    pub fn of(
        room: &Room,
        footprint: &Footprint,
        groups: &[Arc<FloorGroup>],
        sweep: Option<&Sweep>,
        headings: &[f64],
        within: &(dyn Fn(u64) -> bool + Sync),
        memo: &Arc<Memo>,
    ) -> Result<Option<(DoorRoutes, u64)>, CutShort> {
        let own = |within: &(dyn Fn(u64) -> bool + Sync)| {
            let routes = Routes::of(room, footprint, headings, within, memo)?;
            Ok(routes.map(|r| {
                let work = r.work;
                (DoorRoutes::Own(r), work)
            }))
        };
        if !room.meshes.is_empty() {
            return own(within);
        }
        // The bounds: the group's footprints (or the base's own, bounded
        // only by the sweep), the outer in the sweep's room with more in
        // it, the inner in the one with less.
        let (group, tighter) = match groups.split_first() {
            Some((first, tighter)) => (Some(&**first), tighter),
            None => (None, groups),
        };
        // Where these bounds do not serve, the tighter groups', or past
        // the last, the footprint's own.
        let next = |within: &(dyn Fn(u64) -> bool + Sync)| match tighter {
            [] => own(within),
            _ => Self::of(room, footprint, tighter, sweep, headings, within, memo),
        };
        let (outer_fp, inner_fp, members) = match (group, sweep) {
            (Some(g), _) => (&g.outer, &g.inner, g.members),
            (None, Some(_)) => (footprint, footprint, 1),
            (None, None) => return own(within),
        };
        let (more, less): (&Room, &Room) = sweep.map_or((room, room), |s| (&s.swept, &s.without));
        let n = members.max(1) as u64;
        let share = |units: u64| units.div_ceil(n);
        let shared = |units: u64| within(share(units));
        let bound = |f: &Footprint, r: &Room| Routes::of(r, f, headings, &shared, memo);
        let compute = || Ok::<_, CutShort>(bound(outer_fp, more)?.zip(bound(inner_fp, less)?));
        let key = bounds_key(outer_fp, more, inner_fp, less, headings);
        let bounds = match group {
            Some(group) => group.routes(key, compute)?,
            None => compute()?,
        };
        let Some((outer, inner)) = bounds else {
            return next(within);
        };
        let work = share(outer.work.saturating_add(inner.work));
        let through = |d: &Doorway| d.comes_in == Entry::Through;
        if !outer.doors.iter().all(through) {
            // Worked out, though they do not serve: charged all the same.
            let next = next(within)?;
            return Ok(next.map(|(routes, units)| (routes, units.saturating_add(work))));
        }
        let doors = (room.doors.iter().zip(&outer.doors))
            .map(|(door, bound)| Doorway {
                needs_mm: needs_mm(footprint, door),
                ..bound.clone()
            })
            .collect();
        let routes = SharedRoutes {
            outer,
            inner,
            key,
            room: room.clone(),
            footprint: footprint.clone(),
            followed: footprint.grown(HAIR_MM),
            headings: headings.to_vec(),
            memo: Arc::clone(memo),
            own: OnceLock::new(),
            tighter: tighter.to_vec(),
            sweep: sweep.cloned(),
            next: OnceLock::new(),
            doors,
        };
        Ok(Some((DoorRoutes::Shared(Arc::new(routes)), work)))
    }

    /// The routes of the outer bound, where these are bounded, and what
    /// the bounds are kept by.
    pub fn outer_bound(&self) -> Option<(&Arc<Routes>, u64)> {
        match self {
            DoorRoutes::Own(_) => None,
            DoorRoutes::Shared(s) => Some((&s.outer, s.key)),
        }
    }

    /// Whether the base comes in through any door.
    pub fn enters(&self) -> bool {
        match self {
            DoorRoutes::Own(r) => r.enters(),
            // Through every door, as the outer bound.
            DoorRoutes::Shared(s) => !s.doors.is_empty(),
        }
    }

    /// How the base comes in, door by door.
    pub fn doors(&self) -> &[Doorway] {
        match self {
            DoorRoutes::Own(r) => &r.doors,
            DoorRoutes::Shared(s) => &s.doors,
        }
    }

    /// Whether the base facing `heading_rad` can get to `piece` of its
    /// floor, and the work of finding out beyond the floor's: that of the
    /// floor in a window about the piece, and that of the member's own
    /// routes where they were asked (worked out once, whoever asks). A
    /// piece is reached whole or not at all: it is where it overlaps (by
    /// more than a hair's area) floor the routes reach. (Asked at one
    /// point inside it, the point might fall in a sliver a boolean
    /// operation left, where the routes, followed a hair wider, have no
    /// floor.) `around` gives the floor in a window of a footprint at that
    /// heading, and its work (none where the window is outside the room).
    pub fn piece_reached(
        &self,
        heading_rad: f64,
        piece: &Polygon<f64>,
        around: &Around<'_>,
    ) -> Decided {
        match self {
            DoorRoutes::Own(r) => Decided {
                reached: r.reaches_into(heading_rad, piece) == Some(true),
                ..Decided::default()
            },
            DoorRoutes::Shared(s) => s.piece_reached(heading_rad, piece, around),
        }
    }

    /// The base's own routes (worked out now where they were not, and not
    /// charged: for why a target is cut off, and for pictures).
    pub fn own(&self) -> Arc<Routes> {
        match self {
            DoorRoutes::Own(r) => Arc::clone(r),
            DoorRoutes::Shared(s) => Arc::clone(s.own()),
        }
    }
}

impl SharedRoutes {
    /// [`DoorRoutes::piece_reached`]: by the bounds where they decide
    /// (the outer's reached floor overlaps the piece: reached; the
    /// inner's does not: not); else, where the piece runs on (facing the
    /// same way, in a window about it, followed a hair wider as the
    /// routes are) into floor the outer reaches, reached; else as the
    /// tighter groups' bounds or its own routes say.
    fn piece_reached(
        &self,
        heading_rad: f64,
        piece: &Polygon<f64>,
        around: &Around<'_>,
    ) -> Decided {
        let by_bounds = |reached| Decided {
            reached,
            ..Decided::default()
        };
        if !self.inner.follows(heading_rad) || !self.outer.follows(heading_rad) {
            return self.reached_past_bounds(heading_rad, piece, 0, around);
        }
        if self.outer.reaches_into(heading_rad, piece) == Some(true) {
            return by_bounds(true);
        }
        if self.inner.reaches_into(heading_rad, piece) != Some(true) {
            return by_bounds(false);
        }
        let found = window_about(piece).and_then(|window| around(window, &self.followed));
        let window_work = found.as_ref().map_or(0, |(_, units)| *units);
        if let Some((free, _)) = &found {
            let runs_on = free.0.iter().any(|q| {
                pieces_overlap(q, piece) && self.outer.reaches_into(heading_rad, q) == Some(true)
            });
            if runs_on {
                return Decided {
                    reached: true,
                    window_work,
                    ..Decided::default()
                };
            }
        }
        // The tighter bounds look in the same window (the same piece, the
        // same footprint): it is handed on, its work counted once.
        let seen = |_: Rect<f64>, _: &Footprint| found.as_ref().map(|(free, _)| (free.clone(), 0));
        self.reached_past_bounds(heading_rad, piece, window_work, &seen)
    }

    /// Whether `piece` facing `heading_rad` is reached where these
    /// bounds leave it open: by the member's tighter groups' bounds where
    /// it has any (looking with `around`), and past them by its own
    /// routes; with their work and the window's.
    fn reached_past_bounds(
        &self,
        heading_rad: f64,
        piece: &Polygon<f64>,
        window_work: u64,
        around: &Around<'_>,
    ) -> Decided {
        if !self.tighter.is_empty() {
            let (routes, work) = self.tighter_routes();
            let decided = routes.piece_reached(heading_rad, piece, around);
            return Decided {
                reached: decided.reached,
                window_work: window_work.saturating_add(decided.window_work),
                tighter_work: work.saturating_add(decided.tighter_work),
                own_work: decided.own_work,
            };
        }
        let own = self.own();
        Decided {
            reached: own.reaches_into(heading_rad, piece) == Some(true),
            window_work,
            tighter_work: 0,
            own_work: own.work,
        }
    }

    /// The routes the member's tighter groups bound (or, where those do
    /// not serve, its own), and its share of their work (charged as its
    /// own routes' would be), worked out once.
    fn tighter_routes(&self) -> &(DoorRoutes, u64) {
        get_or_compute(&self.next, || {
            let routes = DoorRoutes::of(
                &self.room,
                &self.footprint,
                &self.tighter,
                self.sweep.as_ref(),
                &self.headings,
                &unbounded,
                &self.memo,
            );
            worked_out(routes)
        })
    }

    /// The member's own routes, worked out once.
    fn own(&self) -> &Arc<Routes> {
        get_or_compute(&self.own, || {
            let routes = Routes::of(
                &self.room,
                &self.footprint,
                &self.headings,
                &unbounded,
                &self.memo,
            );
            worked_out(routes)
        })
    }
}

/// Routes of a room with doors, allowed any work: there, never cut short
/// and never none.
fn worked_out<T>(routes: Result<Option<T>, CutShort>) -> T {
    match routes {
        Ok(Some(routes)) => routes,
        _ => unreachable!("the room has doors, and routes allowed any work are not cut short"),
    }
}

/// The window about `piece` its floor is followed in: its bounds and
/// [`WINDOW_MM`] beyond on each side; none for an empty piece.
fn window_about(piece: &Polygon<f64>) -> Option<Rect<f64>> {
    let bounds = piece.bounding_rect()?;
    let beyond = Coord {
        x: WINDOW_MM,
        y: WINDOW_MM,
    };
    Some(Rect::new(bounds.min() - beyond, bounds.max() + beyond))
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::floor::{FloorGroup, FloorObstacles, FloorPart, Region};
    use crate::scene::{BoxObstacle, Door, Wall};
    use nalgebra::{Point3, Vector2, Vector3};
    use proptest::prelude::*;
    use std::f64::consts::FRAC_PI_2;

    /// A rectangle from `x0` to `x1` ahead of the hip point, `width_mm`
    /// wide.
    fn rectangle(x0: f64, x1: f64, width_mm: f64) -> Vec<Vector2<f64>> {
        let h = width_mm / 2.0;
        [(x0, -h), (x1, -h), (x1, h), (x0, h)]
            .map(|(x, y)| Vector2::new(x, y))
            .to_vec()
    }

    /// A chair from the floor to its seat and the knees and feet ahead of
    /// it at `knee_mm` and below.
    fn chair(front_mm: f64, back_mm: f64, width_mm: f64, knee_mm: f64) -> Footprint {
        Footprint {
            parts: vec![
                FloorPart {
                    outline_mm: rectangle(-back_mm, 150.0, width_mm),
                    z_mm: [0.0, 900.0],
                },
                FloorPart {
                    outline_mm: rectangle(150.0, front_mm, width_mm * 0.7),
                    z_mm: [60.0, knee_mm],
                },
            ],
        }
    }

    /// A 4.5 x 4 m room with a door in its near wall and `boxes` (corner,
    /// size and lowest and highest, each in mm).
    fn room(door_x: f64, boxes: &[([f64; 2], [f64; 2], [f64; 2])]) -> Room {
        Room {
            name: "r".into(),
            size_mm: Vector3::new(4500.0, 4000.0, 2500.0),
            boxes: (boxes.iter().enumerate())
                .map(|(k, (at, size, z))| BoxObstacle {
                    name: format!("b{k}"),
                    corner_mm: Point3::new(at[0], at[1], z[0]),
                    size_mm: Vector3::new(size[0], size[1], z[1] - z[0]),
                    yaw_rad: 0.0,
                })
                .collect(),
            meshes: Vec::new(),
            targets: Vec::new(),
            surfaces: Vec::new(),
            doors: vec![Door {
                name: "d".into(),
                wall: Wall::YMin,
                along_mm: door_x,
                width_mm: 1000.0,
            }],
        }
    }

    /// Each member's floor at four headings, cut to its routes: the same
    /// from the group's bounds as from its own routes, piece for piece,
    /// and from the bounds of the whole group and then of the half it is
    /// in (of at least two members); where `sweep` bounds the
    /// room, from those bounds in the sweep's rooms, and from its own in
    /// them, too. Whether the bounds were used for any member.
    fn same_floor(
        room: &Room,
        members: &[Footprint],
        sweep: Option<&Sweep>,
    ) -> Result<bool, TestCaseError> {
        let refs: Vec<&Footprint> = members.iter().collect();
        let group = Arc::new(FloorGroup::of(&refs).expect("alike chairs"));
        // Each half of at least two members.
        let (n, half) = (refs.len(), refs.len() / 2);
        let halves = [&refs[..half.max(2)], &refs[n - (n - half).max(2)..]]
            .map(|part| Arc::new(FloorGroup::of(part).expect("alike chairs")));
        let headings = [0.0, FRAC_PI_2, 2.0 * FRAC_PI_2, 3.0 * FRAC_PI_2];
        let memo = Arc::new(Memo::default());
        let mut shared_any = false;
        for (k, f) in members.iter().enumerate() {
            let of = |groups: &[Arc<FloorGroup>], sweep| {
                let routes = DoorRoutes::of(room, f, groups, sweep, &headings, &unbounded, &memo);
                routes.expect("unbounded").expect("a door").0
            };
            let own = Arc::new(of(&[], None));
            let tighter = Arc::clone(&halves[usize::from(k >= half)]);
            let mut bounded = vec![
                of(&[Arc::clone(&group)], sweep),
                of(&[Arc::clone(&group), tighter], sweep),
            ];
            bounded.extend(sweep.map(|s| of(&[], Some(s))));
            let obstacles = Arc::new(FloorObstacles::new(room, f));
            for shared in bounded {
                shared_any |= matches!(shared, DoorRoutes::Shared(_));
                prop_assert_eq!(own.doors(), shared.doors());
                let shared = Arc::new(shared);
                for h in headings {
                    let floor = |routes: &Arc<DoorRoutes>| {
                        let (obstacles, routes) = (Arc::clone(&obstacles), Arc::clone(routes));
                        Region::reached(room, f, h, None, obstacles, routes, &memo).whole()
                    };
                    prop_assert_eq!(floor(&own), floor(&shared), "heading {}", h.to_degrees());
                }
            }
        }
        Ok(shared_any)
    }

    /// Random boxes: (corner on the floor, size on the floor, whether high
    /// (700 to 900 mm, knee space under it) or from the floor to 1000 mm).
    type Boxes = Vec<((f64, f64), (f64, f64), bool)>;

    fn boxes() -> impl Strategy<Value = Boxes> {
        prop::collection::vec(
            (
                (0.0..4000.0f64, 300.0..3600.0f64),
                (200.0..1500.0f64, 200.0..900.0f64),
                prop::bool::ANY,
            ),
            2..7,
        )
    }

    fn placed(boxes: Boxes) -> Vec<([f64; 2], [f64; 2], [f64; 2])> {
        boxes
            .into_iter()
            .map(|((x, y), (w, d), high)| {
                let z = if high { [700.0, 900.0] } else { [0.0, 1000.0] };
                ([x, y], [w, d], z)
            })
            .collect()
    }

    type Sizes = Vec<(f64, f64, f64, f64)>;

    /// Four chairs' front, back, width and knee height.
    fn sizes() -> impl Strategy<Value = Sizes> {
        prop::collection::vec(
            (
                550.0..700.0f64,
                350.0..550.0f64,
                560.0..720.0f64,
                450.0..650.0f64,
            ),
            4,
        )
    }

    fn chairs(sizes: Sizes) -> Vec<Footprint> {
        sizes
            .into_iter()
            .map(|(front, back, width, knee)| chair(front, back, width, knee))
            .collect()
    }

    proptest! {
        #![proptest_config(ProptestConfig { cases: 24, ..ProptestConfig::default() })]

        /// Random rooms of counters (some with knee space under them) and
        /// blocks, and four chairs of different sizes. (400 cases, counted
        /// once: 5,358 pieces the bounds left undecided, 2,727 of them
        /// decided in a window about them, 2,631 by the member's own
        /// routes; every floor the same as from its own routes.)
        #[test]
        fn a_members_floor_from_the_groups_bounds_is_its_own(
            door_x in 700.0..3800.0f64,
            boxes in boxes(),
            sizes in sizes(),
        ) {
            same_floor(&room(door_x, &placed(boxes)), &chairs(sizes), None)?;
        }

        /// An element (a box 100 to 400 mm high) moved up and down among
        /// random boxes: at each of its heights, a member's floor from the
        /// bounds in the rooms of its sweep (the group's footprints' and
        /// its own) is its own.
        #[test]
        fn a_members_floor_from_the_bounds_of_an_elements_sweep_is_its_own(
            door_x in 700.0..3800.0f64,
            boxes in boxes(),
            element in ((0.0..4000.0f64, 300.0..3600.0f64), (200.0..1000.0f64, 200.0..800.0f64), 100.0..400.0f64),
            heights in prop::collection::vec(0.0..1200.0f64, 1..4),
            sizes in sizes(),
        ) {
            let ((x, y), (w, d), high) = element;
            let mut placed = placed(boxes);
            placed.push(([x, y], [w, d], [0.0, high]));
            let room = room(door_x, &placed);
            let name = format!("b{}", placed.len() - 1);
            let moves: Vec<Vector3<f64>> = heights.iter().map(|&z| Vector3::new(0.0, 0.0, z)).collect();
            let sweep = Sweep::of(&room, &[name.as_str()], &moves).expect("a sweep");
            let members = chairs(sizes);
            for by in moves {
                same_floor(&room.moved(&[name.as_str()], by), &members, Some(&sweep))?;
            }
        }
    }

    /// A room where the bounds decide nearly everything: an open floor with
    /// a counter and a pocket beside a post that only the smaller chairs
    /// fit in.
    #[test]
    fn the_bounds_are_used_where_the_outer_chair_comes_in() {
        let boxes = [
            ([0.0, 3400.0], [4500.0, 600.0], [0.0, 900.0]),
            ([3000.0, 2000.0], [300.0, 300.0], [0.0, 1000.0]),
        ];
        let members = [
            chair(600.0, 400.0, 600.0, 500.0),
            chair(650.0, 450.0, 700.0, 600.0),
            chair(620.0, 420.0, 640.0, 550.0),
        ];
        let shared = same_floor(&room(2000.0, &boxes), &members, None);
        assert!(matches!(shared, Ok(true)), "{shared:?}");
    }
}
