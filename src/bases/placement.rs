//! Placing a mobile base: where should the person stand or sit, and facing
//! which way, to reach a target? The person's capability map
//! (`capability.rs`) answers it backwards: each posture of the map whose
//! hand is near the target's height above the hip, turned by each heading
//! searched, puts the hip point where that hand would be on the target; the
//! candidates are those hip points inside the admissible region (at their
//! heading) and the approach, the most comfortable postures first, each
//! tried from its own posture. After them, for each heading, the
//! admissible point nearest to where the arm works best on average (so
//! that a target out of every sample's reach still gets tried and its
//! closest distance reported). The candidates are searched as every
//! base's are (`search.rs`).
//! This is the paper's idea (section 5.3.5: the target becomes the region of
//! target minus admissible base positions) made of samples, with the heading
//! theta_0 of section 5.3.6 searched over the headings the options allow.

use std::cell::OnceCell;
use std::collections::hash_map::DefaultHasher;
use std::collections::HashMap;
use std::hash::{Hash, Hasher};
use std::rc::Rc;
use std::sync::{Arc, Mutex, OnceLock, Weak};

use geo::{MultiPolygon, Point};
use nalgebra::{Point3, Rotation2, Vector2};

use super::bound_floor::{bound_floor, hash_zone, BoundFloor, Searched};
use super::capability::{Capability, Sample};
use super::face::face_normal;
use super::placing::{Approach, Placing, SIDE_SLACK_MM};
use super::search::{search, search_retrying_later, Candidate};
use crate::allowance::{Allowance, Unbounded, Unmetered};
use crate::floor::{
    emptiness_each, CutShort, DoorRoutes, Doorway, FloorGroup, FloorObstacles, Footprint, Looked,
    Misfit, Region, Routes, Shut, Work,
};
use crate::geometry::Solid;
use crate::kept::{Memo, Table};
use crate::kinematics::Chain;
use crate::plugin::{
    Asked, Base, BasePose, Fit, Hips, IkSolution, Placement, PreparedBase, ReachQuery, Solver,
    Tries,
};
use crate::scene::{column_solid, hash_bits, Blocked, OwnBody, Physique, Room, Sweep};

/// The admissible region at each heading searched (one region for every
/// heading when turning changes nothing).
type Regions = Vec<(f64, Arc<Region>)>;

/// Whether the base fits at one of `regions`' headings, each distinct
/// region (a base that does not turn has one for all) found out by
/// [`emptiness_each`].
fn any_fits(regions: &Regions, work: &mut Work<'_>) -> Result<bool, CutShort> {
    let mut distinct: Vec<&Region> = Vec::new();
    for (_, region) in regions {
        if !distinct.iter().any(|d| std::ptr::eq(*d, region.as_ref())) {
            distinct.push(region);
        }
    }
    Ok(emptiness_each(&distinct, work)?.contains(&false))
}

/// What is known of rooms related to the one a floor is worked out in.
#[derive(Clone, Copy, Default)]
struct Related<'a> {
    /// The room with more in it (obstacles or doors this one has taken
    /// away), whose floor is worked out: at each heading where the base
    /// fits there, it fits here, unsearched.
    wider: Option<&'a Room>,
    /// The bounds of the rooms of an element's moves, this one among them.
    sweep: Option<&'a Sweep>,
}

/// Where the base may be placed in one room, worked out once.
#[derive(Clone)]
struct Floor {
    /// The admissible region at each heading searched; where the room has
    /// doors, only the parts the base can get to from one.
    regions: Regions,
    /// How the base comes in by each door (none: the room has no door,
    /// and the base may be placed wherever it fits).
    doors: Option<Vec<Doorway>>,
    /// The routes from the doors (none: the room has no door, or the base
    /// fits nowhere).
    routes: Option<Arc<DoorRoutes>>,
    /// Whether it fits somewhere, doors aside.
    fits: bool,
    /// What working it out cost, in units of the meter
    /// ([`Base::floor_work`]): the searches for whether it fits anywhere
    /// and the routes.
    work: u64,
}

/// What `floor`, of a room with more in it, found at heading `k`: whether
/// the base fits there (then it fits here: taking obstacles or doors away
/// never takes floor away), and the pieces its search looked at.
fn found_there(floor: Option<&Floor>, k: usize) -> Option<(bool, Looked)> {
    let (_, region) = floor?.regions.get(k)?;
    let empty = region.known_empty()?;
    Some((!empty, region.looked()))
}

/// Two keys as one.
fn hash_pair(a: u64, b: u64) -> u64 {
    let mut h = DefaultHasher::new();
    (a, b).hash(&mut h);
    h.finish()
}

/// `region`, beside what a room with more in it found (`Region::beside`).
fn hinted(region: Region, there: Option<(bool, Looked)>) -> Arc<Region> {
    Arc::new(match there {
        Some((fits, paid)) => region.beside(fits, paid),
        None => region,
    })
}

/// `region` (at heading `k`), told by its group's bounds' floor where it
/// has one (`bound_floor.rs`): known to fit where the outer fits.
fn bounded(region: Region, bounds: Option<&BoundFloor>, k: usize) -> Region {
    let Some(bounds) = bounds else {
        return region;
    };
    let region = match bounds.regions.get(k) {
        Some(b) => region.bounded_by(b.clone()),
        None => region,
    };
    if bounds.outer_fits.get(k) == Some(&true) {
        region.beside(true, Looked::default())
    } else {
        region
    }
}

/// A base that moves on the floor: its footprint, the person's own body
/// and the base's parts, and how it may be placed.
pub struct Mobile {
    pub footprint: Footprint,
    pub hip_height_mm: f64,
    pub placing: Placing,
    pub own: OwnBody,
    /// Where it may be placed in each room, worked out once.
    floors: ByRoom<Floor>,
    /// Where it fits nowhere, by how much, and what finding out cost.
    misfits: ByRoom<(Misfit, u64)>,
    /// The capability maps of the chains it was last prepared for, while
    /// something else holds them ([`Mobile::capability_of`]).
    capabilities: Mutex<Vec<(Chain, Weak<Capability>)>>,
    /// The bounds of the footprints of the groups (of a population) it is
    /// one of, the widest first, whose routes from the doors it shares
    /// ([`Base::join_floor_groups`]).
    groups: OnceLock<Vec<Arc<FloorGroup>>>,
}

/// How many chains' maps a base remembers it was prepared for.
const CAPABILITIES_REMEMBERED: usize = 4;

/// Something worked out once per room (by its name) and shared by every
/// task there, whichever thread asks first.
struct ByRoom<T>(Mutex<HashMap<String, Arc<OnceLock<T>>>>);

impl<T> Default for ByRoom<T> {
    fn default() -> Self {
        ByRoom(Mutex::default())
    }
}

impl<T> ByRoom<T> {
    /// `room`'s cell, to be filled by whoever asks first.
    fn cell(&self, room: &Room) -> Arc<OnceLock<T>> {
        let mut by_room = self.0.lock().unwrap_or_else(|e| e.into_inner());
        Arc::clone(by_room.entry(room.name.clone()).or_default())
    }
}

/// The floors worked out for a run or a watch session, by
/// [`Mobile::floor_key`]: watch
/// mode checks the scenario again at every save, and a target moved or a
/// task added leaves every base's floor as it was. 64: enough for the bases
/// of a scenario; a population's members each have their own.
const FLOORS: Table<Floor> = Table::new("floors", 64);

/// What a misfit's flight is keyed by, with its floor's key (the two
/// are worked out apart, and charged apart).
const MISFIT: u64 = 0x6d69_7366_6974;

/// The most candidates a reach takes from the capability map, and the most
/// placements it looks at to find them.
pub const SEEDED: usize = 16;
const SCANNED: usize = 256;

impl Mobile {
    pub fn new(footprint: Footprint, hip_height_mm: f64, placing: Placing, own: OwnBody) -> Self {
        Mobile {
            footprint,
            hip_height_mm,
            placing,
            own,
            floors: ByRoom::default(),
            misfits: ByRoom::default(),
            capabilities: Mutex::default(),
            groups: OnceLock::new(),
        }
    }

    /// The base with its parts and the person's legs (`solids`, in the
    /// base frame, the hip point `hip_height_mm` above the floor): the
    /// floor must find room for them and for the upright upper body, and
    /// links must stay out of them (but for the pelvis, `pelvis_mm` about
    /// the hip point).
    pub fn carrying(
        solids: Vec<Solid>,
        person: &Physique,
        pelvis_mm: f64,
        hip_height_mm: f64,
        placing: Placing,
    ) -> Self {
        let column = person.column_mm.map(|c| column_solid("the upper body", c));
        let footprint = Footprint::of_solids(solids.iter().chain(&column), hip_height_mm);
        Mobile::new(
            footprint,
            hip_height_mm,
            placing,
            OwnBody::new(solids, pelvis_mm),
        )
    }

    /// Where the base may be placed, worked out once per room (with what
    /// its routes cost told to `meter`; cut short once the run would pass
    /// its work: nowhere then, and kept by no other run).
    fn floor(&self, room: &Room, allowance: &dyn Allowance) -> Arc<OnceLock<Floor>> {
        self.floor_within(room, Related::default(), allowance)
    }

    /// `floor`, told what is known of rooms `related` to this one.
    fn floor_within(
        &self,
        room: &Room,
        related: Related<'_>,
        allowance: &dyn Allowance,
    ) -> Arc<OnceLock<Floor>> {
        let cell = self.floors.cell(room);
        // Not `get_or_init`: the routes work out a heading's tiles in
        // parallel, and a thread waiting for them may take up another task
        // of this person, which would ask for this cell from inside its own
        // initialisation (a deadlock). Two threads may both work the floor
        // out; the first kept stays (it measured 0.3 s slower on
        // kitchen_wheelchair, too).
        if cell.get().is_none() {
            let mut key = self.floor_key(room);
            if let Some(sweep) = related.sweep {
                // Its work depends on the sweep's bounds: kept apart.
                key = hash_pair(key, sweep.key);
            }
            let hint = related.wider.map(|w| {
                // Its work depends on the hint: kept apart.
                key = hash_pair(key, self.floor_key(w));
                self.floors.cell(w)
            });
            let hint = hint.as_ref().and_then(|c| c.get());
            let floor = FLOORS.get_or_try(&allowance.memo(), key, || {
                self.compute_floor(room, hint, related.sweep, key, allowance)
            });
            match floor {
                Ok(floor) => _ = cell.set(floor),
                Err(cut) => {
                    // Past the run's limit: the run stops. The floor cut
                    // short is this call's alone: a run after it (with
                    // more work left) works the floor out again.
                    allowance.spend(cut.work);
                    debug_assert!(allowance.exhausted(), "a floor cut short stops the run");
                    let alone = Arc::new(OnceLock::new());
                    let _ = alone.set(Floor {
                        regions: Vec::new(),
                        doors: None,
                        routes: None,
                        fits: false,
                        work: cut.work,
                    });
                    return alone;
                }
            }
        }
        cell
    }

    /// Everything the floor depends on, hashed: the room's size, obstacles
    /// and doors, the footprint, the headings and the zone.
    fn floor_key(&self, room: &Room) -> u64 {
        let mut h = DefaultHasher::new();
        self.footprint.hash_with_floor(room, &mut h);
        hash_bits(&self.placing.headings, &mut h);
        for group in self.groups.get().into_iter().flatten() {
            group.hash_into(&mut h);
        }
        hash_zone(self.placing.zone.as_ref(), &mut h);
        h.finish()
    }

    /// The admissible regions, one per heading searched; where the room
    /// has doors, cut to what the base can get to from one
    /// (`floor/routes.rs`). Where `hint` is the floor of this room with
    /// more in it, each heading it fits at is not searched; where `sweep`
    /// bounds the rooms of an element's moves, the routes are bounded by
    /// its two rooms' (`floor/shared_routes.rs`).
    fn compute_floor(
        &self,
        room: &Room,
        hint: Option<&Floor>,
        sweep: Option<&Sweep>,
        key: u64,
        allowance: &dyn Allowance,
    ) -> Result<Floor, CutShort> {
        let zone = self.placing.zone.as_ref();
        let headings = &self.placing.headings;
        let memo = allowance.memo();
        // Charged once done: in flight, counted with the others.
        let flight = allowance.flight(key);
        let within = |units: u64| flight.within(units);
        let mut work = Work::new(&within);
        let allows = |units: u64| work.allows(units);
        let obstacles = FloorObstacles::with(room, &self.footprint, &[], &allows)
            .map_err(|cut| work.cut_short_with(cut.work))?;
        let obstacles = Arc::new(obstacles);
        work.add(obstacles.work())?;
        let searched = Searched {
            room,
            headings,
            zone,
        };
        let groups = self.groups.get().map_or(&[][..], Vec::as_slice);
        // The bounds' floor is the tightest group's.
        let group = groups.last().map(Arc::as_ref);
        // In a room without doors a member's floor is its own: the bounds'
        // tiles cost more there than they save a population of tens
        // (bench_population's kitchen without its door, 10.4 -> 13.3 s).
        let bounded_by = group.filter(|_| !room.doors.is_empty());
        let bound = |routes: Option<(&Arc<Routes>, u64)>, work: &mut Work<'_>| {
            let Some(group) = bounded_by else {
                return Ok(None);
            };
            let left = |units: u64| work.allows(units);
            let found = bound_floor(&searched, group, routes, &left, &memo)
                .map_err(|cut| work.cut_short_with(cut.work))?;
            let Some((floor, share)) = found else {
                return Ok(None);
            };
            work.add(share)?;
            Ok::<_, CutShort>(Some(floor))
        };
        let outer = bound(None, &mut work)?;
        let region = |k: usize, h: f64| {
            let obstacles = Arc::clone(&obstacles);
            let region = Region::new(room, &self.footprint, h, zone, obstacles, &memo);
            hinted(bounded(region, outer.as_deref(), k), found_there(hint, k))
        };
        let regions: Regions = if self.footprint.turns() {
            (headings.iter().enumerate())
                .map(|(k, &h)| (h, region(k, h)))
                .collect()
        } else {
            let one = region(0, 0.0);
            headings.iter().map(|&h| (h, Arc::clone(&one))).collect()
        };
        let fits = any_fits(&regions, &mut work)?;
        let routes = if fits {
            let left = |units: u64| work.allows(units);
            DoorRoutes::of(room, &self.footprint, groups, sweep, headings, &left, &memo)
                .map_err(|cut| work.cut_short_with(cut.work))?
        } else {
            None
        };
        let Some((routes, routes_work)) = routes else {
            return Ok(Floor {
                regions,
                doors: None,
                routes: None,
                fits,
                work: work.done,
            });
        };
        work.add(routes_work)?;
        let outer = match routes.outer_bound() {
            Some(bound_routes) => bound(Some(bound_routes), &mut work)?,
            None => None,
        };
        let routes = Arc::new(routes);
        let reached = |k: usize, h: f64| {
            let obstacles = Arc::clone(&obstacles);
            let routes = Arc::clone(&routes);
            let region = Region::reached(room, &self.footprint, h, zone, obstacles, routes, &memo);
            // The pieces the search for whether it fits at all looked at
            // are those the routes cut: worked out once, charged once.
            let region = region.paid_by(&regions[k].1.looked());
            hinted(bounded(region, outer.as_deref(), k), found_there(hint, k))
        };
        let regions: Regions = (headings.iter().enumerate())
            .map(|(k, &h)| (h, reached(k, h)))
            .collect();
        any_fits(&regions, &mut work)?;
        Ok(Floor {
            regions,
            doors: Some(routes.doors().to_vec()),
            routes: Some(Arc::clone(&routes)),
            fits,
            work: work.done,
        })
    }

    /// Whether the base fits anywhere in the room (and can get there from
    /// a door, where the room has doors), and if not, by how much it
    /// misses or which doors shut it out (worked out once per room; its
    /// routes cut short where they would take the run past its work, and
    /// the run then stopped).
    pub fn fit(&self, room: &Room, allowance: &dyn Allowance) -> Fit {
        self.fit_within(room, Related::default(), allowance)
    }

    /// `fit`, told what is known of rooms `related` to this one
    /// ([`Mobile::floor_within`]).
    fn fit_within(&self, room: &Room, related: Related<'_>, allowance: &dyn Allowance) -> Fit {
        let cell = self.floor_within(room, related, allowance);
        let Some(floor) = cell.get() else {
            return Fit::Fits;
        };
        if allowance.exhausted() {
            // The task stops where it starts, and the run with it.
            return Fit::Fits;
        }
        if floor.regions.iter().any(|(_, r)| !r.is_empty()) {
            return Fit::Fits;
        }
        if let (true, Some(doors)) = (floor.fits, &floor.doors) {
            return Fit::Shut(Shut {
                doors: doors.clone(),
                in_zone: self.placing.zone.is_some(),
                footprint_mm: self.footprint.size_mm(),
            });
        }
        let cell = self.misfits.cell(room);
        if cell.get().is_none() {
            let flight = allowance.flight(hash_pair(self.floor_key(room), MISFIT));
            let within = |units: u64| flight.within(units);
            let mut work = Work::new(&within);
            let (headings, zone) = (&self.placing.headings, self.placing.zone.as_ref());
            let memo = allowance.memo();
            match Misfit::counted(room, &self.footprint, headings, zone, &mut work, &memo) {
                Ok(misfit) => {
                    let _ = cell.set((misfit, work.done));
                }
                Err(cut) => {
                    // Past the run's limit: the run stops.
                    allowance.spend(cut.work);
                    return Fit::Fits;
                }
            }
        }
        let Some(&(misfit, _)) = cell.get() else {
            return Fit::Fits;
        };
        Fit::Nowhere(misfit)
    }

    /// The capability map of `chain` and the person's own body: the one
    /// it was last prepared with for an equal chain, where that is still
    /// held (a task's search for why prepares it again for each room it
    /// tries, the chain unchanged), else the memo's
    /// ([`Capability::of`], which finds it by the chain's and the body's
    /// text: for a why-map of 96,000 points, a fifth of the run).
    fn capability_of(&self, chain: &Chain, memo: &Memo) -> Arc<Capability> {
        let lock = || self.capabilities.lock().unwrap_or_else(|e| e.into_inner());
        let held = (lock().iter())
            .find(|(c, _)| c == chain)
            .and_then(|(_, map)| map.upgrade());
        if let Some(map) = held {
            return map;
        }
        // Not under the lock: building a map may wait for other work.
        let map = Capability::of(chain, &self.own, memo);
        let mut remembered = lock();
        remembered.retain(|(c, map)| c != chain && map.strong_count() > 0);
        if remembered.len() >= CAPABILITIES_REMEMBERED {
            remembered.remove(0);
        }
        remembered.push((chain.clone(), Arc::downgrade(&map)));
        map
    }

    /// Ready for reaches in `room`: the regions, the capability map and the
    /// workspace centre are computed once.
    pub fn prepare<'a>(
        &'a self,
        room: &'a Room,
        chain: &'a Chain,
        allowance: &dyn Allowance,
    ) -> PreparedMobile<'a> {
        let memo = allowance.memo();
        PreparedMobile {
            mobile: self,
            room,
            chain,
            // Worked out and charged by `fit` before (unmetered here).
            floor: self.floor(room, &Unmetered(Arc::clone(&memo))),
            capability: self.capability_of(chain, &memo),
            half_width_mm: self.footprint.half_width_mm(),
        }
    }

    /// What finding how much smaller the base would fit in `room` cost
    /// (0 where it fits, or it was not looked for).
    fn misfit_work(&self, room: &Room) -> u64 {
        self.misfits.cell(room).get().map_or(0, |&(_, work)| work)
    }
}

impl Base for Mobile {
    fn own_body(&self) -> &OwnBody {
        &self.own
    }

    /// A zone wholly outside the room: no hip point may be in both.
    fn outside(&self, room: &Room) -> bool {
        let floor = (room.size_mm.x, room.size_mm.y);
        self.placing.zone.as_ref().is_some_and(|z| z.outside(floor))
    }

    /// The person's capability map ([`Capability::build_work`]).
    fn prepare_work(&self, chain: &Chain) -> u64 {
        Capability::build_work(chain)
    }

    /// Its floor, and the face a target is on (`face.rs`).
    fn reads_room_through_floor(&self) -> bool {
        true
    }

    fn hip_height_mm(&self) -> Option<f64> {
        Some(self.hip_height_mm)
    }

    fn fit(&self, room: &Room, allowance: &dyn Allowance) -> Fit {
        Mobile::fit(self, room, allowance)
    }

    fn fit_beside(&self, room: &Room, beside: &Room, allowance: &dyn Allowance) -> Fit {
        let related = Related {
            wider: Some(beside),
            ..Related::default()
        };
        self.fit_within(room, related, allowance)
    }

    fn fit_in_sweep(&self, room: &Room, sweep: &Sweep, allowance: &dyn Allowance) -> Fit {
        let related = Related {
            sweep: Some(sweep),
            ..Related::default()
        };
        self.fit_within(room, related, allowance)
    }

    fn floor_key(&self, room: &Room) -> Option<u64> {
        Some(Mobile::floor_key(self, room))
    }

    fn floor_work(&self, room: &Room) -> u64 {
        let cell = self.floors.cell(room);
        let floor = cell.get().map_or(0, |floor| floor.work);
        floor.saturating_add(self.misfit_work(room))
    }

    fn floor_work_beside(&self, room: &Room, beside: &Room) -> u64 {
        if self.floor_key(room) == self.floor_key(beside) {
            return 0;
        }
        self.floor_work(room)
    }

    fn prepare<'a>(
        &'a self,
        room: &'a Room,
        chain: &'a Chain,
        allowance: &dyn Allowance,
    ) -> Box<dyn PreparedBase + 'a> {
        Box::new(Mobile::prepare(self, room, chain, allowance))
    }

    fn placements(&self) -> Tries {
        Tries {
            solved: self.placing.headings.len() as u64,
            seeded: SEEDED as u64,
            from_rest: self.placing.headings.len() as u64,
        }
    }

    fn footprint(&self) -> Option<&Footprint> {
        Some(&self.footprint)
    }

    fn unzoned(&self) -> Option<Box<dyn Base>> {
        self.placing.zone.as_ref()?;
        let placing = Placing {
            zone: None,
            ..self.placing.clone()
        };
        Some(Box::new(Mobile::new(
            self.footprint.clone(),
            self.hip_height_mm,
            placing,
            self.own.clone(),
        )))
    }

    fn join_floor_groups(&self, groups: &[Arc<FloorGroup>]) {
        let _ = self.groups.set(groups.to_vec());
    }

    fn enclosing(&self, room: &Room, heading_rad: f64, hip_mm: (f64, f64)) -> Vec<usize> {
        // The routes the placement followed, with the room's floor.
        let cell = self.floor(room, &Unbounded);
        match cell.get().and_then(|floor| floor.routes.as_ref()) {
            Some(routes) => (routes.own()).enclosing(room, &self.footprint, heading_rad, hip_mm),
            None => Vec::new(),
        }
    }

    fn reached_floor(&self, room: &Room, heading_rad: f64) -> Option<MultiPolygon<f64>> {
        let cell = self.floor(room, &Unbounded);
        let floor = cell.get()?;
        floor.doors.as_ref()?;
        let (_, region) = floor.regions.iter().min_by(|a, b| {
            let off = |h: f64| (h - heading_rad).rem_euclid(std::f64::consts::TAU);
            let near = |h: f64| off(h).min(std::f64::consts::TAU - off(h));
            near(a.0).total_cmp(&near(b.0))
        })?;
        Some(region.whole())
    }
}

/// A mobile base ready for one room and chain.
pub struct PreparedMobile<'a> {
    mobile: &'a Mobile,
    room: &'a Room,
    chain: &'a Chain,
    floor: Arc<OnceLock<Floor>>,
    /// The chain's map, with where it would rather have a target
    /// ([`Capability::centre_mm`]) and its hand at rest.
    capability: Arc<Capability>,
    /// The lines of the footprint's sides, either side of the hip point
    /// (what the approach measures).
    half_width_mm: f64,
}

/// Two sampled placements at one heading closer than this are one.
const APART_MM: f64 = 40.0;
/// A heading the base may face, as a turn and in radians, and its
/// region.
type Facing<'a> = (Rotation2<f64>, f64, &'a Region);

/// The heights below and above a target's within which samples are first
/// taken, and how they are widened while fewer than `FEW` are found: up
/// first (a hand above the target need only come down to it), then down.
const NEAR_HEIGHT_MM: [[f64; 2]; 4] = [[30.0, 30.0], [30.0, 120.0], [60.0, 240.0], [120.0, 240.0]];
const FEW: usize = 24;

impl PreparedMobile<'_> {
    fn regions(&self) -> impl Iterator<Item = &(f64, Arc<Region>)> {
        self.floor
            .get()
            .into_iter()
            .flat_map(|f| &f.regions)
            .filter(|(_, r)| !r.is_empty())
    }

    /// Candidate placements for `query`, the most promising first: from
    /// the capability map, then the nearest to where the arm works best at
    /// each heading (worked out only if the search gets that far).
    pub fn candidates<'q>(
        &'q self,
        query: &'q ReachQuery<'_>,
    ) -> impl Iterator<Item = Candidate> + 'q {
        // A nearest placement is kept even beside a sampled one: that is
        // descended from one seed, this from the solver's own starts.
        // Worked out once, for itself and to leave out of the last ones.
        let near: Rc<OnceCell<Vec<BasePose>>> = Rc::default();
        let near_too = Rc::clone(&near);
        let nearest = move || {
            near_too
                .get_or_init(|| {
                    self.nearest(
                        &query.target_room_mm,
                        self.capability.centre_mm,
                        query.allowance,
                    )
                })
                .clone()
        };
        // Last, where the hand at rest would be at the target: the
        // reaching shoulder in front of it, the base as close as it fits
        // (a low point on a wall, reached leaning forward over the knees).
        // For a reach; a map's points are reached from their neighbours.
        let at_rest = std::iter::once_with(move || {
            if !query.from_rest {
                return Vec::new();
            }
            let near = near.get_or_init(|| {
                self.nearest(
                    &query.target_room_mm,
                    self.capability.centre_mm,
                    query.allowance,
                )
            });
            let mut rest = self.nearest(
                &query.target_room_mm,
                self.capability.at_rest_mm,
                query.allowance,
            );
            rest.retain(|p| !near.iter().any(|n| same_place(n, p)));
            rest
        });
        let nearest = std::iter::once_with(nearest);
        self.sampled(query)
            .into_iter()
            .chain(nearest.flatten().map(Candidate::at))
            .chain(at_rest.flatten().map(Candidate::fallback))
    }

    /// Up to `SEEDED` placements from the capability map whose posture is
    /// clear of the room (where the query checks it), of the first
    /// `SCANNED` that the region and the approach admit; kept for the
    /// task's next run where the query keeps its solves.
    fn sampled(&self, query: &ReachQuery<'_>) -> Vec<Candidate> {
        let Some(solves) = query.solves else {
            return self.sampled_here(query);
        };
        let face = self.face(&query.target_room_mm);
        let mut h = DefaultHasher::new();
        "sampled".hash(&mut h);
        query.obstacles.is_some().hash(&mut h);
        let target = query.target_room_mm.coords.iter();
        hash_bits(target.chain(face.iter().flat_map(|f| f.iter())), &mut h);
        face.is_some().hash(&mut h);
        let sample = |asked: Asked<'_>| {
            let query = ReachQuery {
                obstacles: asked.obstacles,
                allowance: asked.allowance,
                ..*query
            };
            let found = self.sampled_here(&query).into_iter();
            found
                .map(|c| (c.pose, c.start.unwrap_or_default()))
                .collect()
        };
        let asked = Asked {
            obstacles: query.obstacles,
            allowance: query.allowance,
        };
        let placements = solves.placements(h.finish(), asked, sample);
        (placements.into_iter())
            .map(|(pose, q)| Candidate {
                start: Some(q),
                ..Candidate::at(pose)
            })
            .collect()
    }

    /// [`PreparedMobile::sampled`], sampled here.
    fn sampled_here(&self, query: &ReachQuery<'_>) -> Vec<Candidate> {
        let target = &query.target_room_mm;
        let z_mm = target.z - self.mobile.hip_height_mm;
        let capability = &self.capability;
        let mut near = Vec::new();
        for [below, above] in NEAR_HEIGHT_MM {
            near = capability.near_height(z_mm, below, above);
            if capability.clear_at_least(&near, FEW) {
                break;
            }
        }
        let approach = self.mobile.placing.approach;
        let face = self.face(target);
        // The headings that face the target as the approach asks, each
        // turned once for every sample.
        let facing: Vec<Facing<'_>> = (self.regions())
            .filter(|(heading, _)| approach.faces(*heading, face))
            .map(|(heading, region)| (Rotation2::new(*heading), *heading, &**region))
            .collect();
        let mut scanned: Vec<BasePose> = Vec::new();
        let mut found: Vec<Candidate> = Vec::new();
        for sample in near {
            if !approach.admits(&sample.effector_mm, self.half_width_mm) {
                continue;
            }
            // A sample's headings are taken all or none, so that which
            // placements are tried does not depend on which heading comes
            // first (the room turned by 90 degrees tries the same). A
            // sample that puts the base nowhere new adds nothing, clear or
            // not: whether its posture is clear of the body (the costlier
            // test) is asked only of one that does.
            let here_scanned = self.sample_at_headings(query, sample, &facing, &scanned);
            if here_scanned.is_empty() || !capability.clear(sample) {
                continue;
            }
            let here_found = self.clear_of_room(query, sample, &here_scanned);
            if found.len() + here_found.len() > SEEDED
                || scanned.len() + here_scanned.len() > SCANNED
            {
                break;
            }
            scanned.extend(here_scanned);
            found.extend(here_found);
            if found.len() == SEEDED || scanned.len() == SCANNED {
                break;
            }
        }
        found
    }

    /// The placements of capability sample `sample` at each heading of
    /// `facing` that the floor admits, not at a place of `scanned`.
    fn sample_at_headings(
        &self,
        query: &ReachQuery<'_>,
        sample: &Sample,
        facing: &[Facing<'_>],
        scanned: &[BasePose],
    ) -> Vec<BasePose> {
        let target = &query.target_room_mm;
        let hand = sample.effector_mm.xy();
        let mut looked = Vec::new();
        for (turn, heading, region) in facing {
            let offset = turn * hand;
            let (x, y) = (target.x - offset.x, target.y - offset.y);
            let pose = self.pose_at(x, y, *heading);
            // The quick count first, the exact test (which would count
            // again) only for a new point it lets in.
            if !region.roughly_contains(x, y)
                || scanned.iter().chain(&looked).any(|p| same_place(p, &pose))
                || !region.contains(x, y)
            {
                continue;
            }
            looked.push(pose);
        }
        looked
    }

    /// The placements of `looked` (of capability sample `sample`) whose
    /// posture is clear of the room, each a candidate started from it.
    fn clear_of_room(
        &self,
        query: &ReachQuery<'_>,
        sample: &Sample,
        looked: &[BasePose],
    ) -> Vec<Candidate> {
        let q = self.capability.q(sample);
        // The sample's solids, worked out once for every heading.
        let mut volumes = None;
        let mut clear = |pose: BasePose| {
            query.obstacles.is_none() || {
                let v = volumes.get_or_insert_with(|| self.chain.volumes(q));
                let problem = query.problem(self.chain, pose);
                problem.collision_of_charged(v).is_none()
            }
        };
        (looked.iter().copied())
            .filter(|&pose| clear(pose))
            .map(|pose| Candidate {
                start: Some(q.to_vec()),
                ..Candidate::at(pose)
            })
            .collect()
    }

    /// For each heading that faces the target as the approach asks, the
    /// admissible point nearest to where the arm would rather have it
    /// (`hint`, turned into the approach), or where that point is outside
    /// the approach, the nearest along its line; the nearest first. The
    /// search for floor far from the target is charged to `meter`.
    fn nearest(
        &self,
        target: &Point3<f64>,
        hint: Vector2<f64>,
        allowance: &dyn Allowance,
    ) -> Vec<BasePose> {
        let hint = toward(hint, self.mobile.placing.approach, self.half_width_mm);
        let face = self.face(target);
        let mut scored: Vec<(f64, BasePose)> = self
            .regions()
            .filter(|(heading, _)| self.mobile.placing.approach.faces(*heading, face))
            .filter_map(|(heading, region)| {
                let offset = Rotation2::new(*heading) * hint;
                let preferred = Point::new(target.x - offset.x, target.y - offset.y);
                let p = region.nearest_metered(preferred, allowance)?;
                let pose = self.pose_at(p.x(), p.y(), *heading);
                let pose = if self.admitted(&pose, target) {
                    pose
                } else {
                    self.along_approach(target, *heading, hint, region)?
                };
                let pose = snapped(pose, target);
                let p = pose.position_mm;
                Some(((p.x - preferred.x()).hypot(p.y - preferred.y()), pose))
            })
            .collect();
        scored.sort_by(|a, b| a.0.total_cmp(&b.0));
        scored.into_iter().map(|(_, pose)| pose).collect()
    }

    /// The vertical face `target` is on, where the approach measures
    /// against one (not `any`).
    fn face(&self, target: &Point3<f64>) -> Option<Vector2<f64>> {
        match self.mobile.placing.approach {
            Approach::Any => None,
            _ => face_normal(self.room, target),
        }
    }

    fn pose_at(&self, x: f64, y: f64, heading_rad: f64) -> BasePose {
        BasePose {
            position_mm: Point3::new(x, y, self.mobile.hip_height_mm),
            heading_rad,
        }
    }

    /// Whether the approach admits `target` from `pose` (its face left
    /// to the caller).
    fn admitted(&self, pose: &BasePose, target: &Point3<f64>) -> bool {
        let approach = self.mobile.placing.approach;
        approach.admits_pose(pose, target, self.half_width_mm)
    }

    /// Where the free point nearest the preferred one lies outside the
    /// approach (round the end of an island, beside what a forward
    /// approach should face), the nearest free point the approach admits
    /// along its line: the hip moved back from the preferred point
    /// straight away from the target (forward) or out to the side (side),
    /// in steps of [`ALONG_STEP_MM`], as far as the arm and the footprint
    /// could matter.
    fn along_approach(
        &self,
        target: &Point3<f64>,
        heading_rad: f64,
        hint: Vector2<f64>,
        region: &Region,
    ) -> Option<BasePose> {
        let turn = Rotation2::new(heading_rad);
        let away = match self.mobile.placing.approach {
            Approach::Side => Vector2::new(0.0, hint.y.signum()),
            _ => Vector2::new(1.0, 0.0),
        };
        let farthest_mm =
            self.chain.reach_bound_mm() + self.mobile.footprint.extent_mm() + ALONG_STEP_MM;
        let steps = (farthest_mm / ALONG_STEP_MM).ceil() as usize;
        (0..=steps).find_map(|k| {
            let offset = turn * (hint + away * (k as f64 * ALONG_STEP_MM));
            let (x, y) = (target.x - offset.x, target.y - offset.y);
            let pose = self.pose_at(x, y, heading_rad);
            (region.contains(x, y) && self.admitted(&pose, target)).then_some(pose)
        })
    }
}

/// The step along an approach's line in [`PreparedMobile::along_approach`].
const ALONG_STEP_MM: f64 = 10.0;

/// Whether two poses are one candidate: the same heading, close.
/// The grid a placement found on the floor is put on, from the target:
/// the floor's outlines are worked out by boolean operations that round
/// their corners to a grid of the room's own (about a micrometre), so the
/// nearest free point moves by that much when the whole scenario moves.
/// Put on a grid of a thousandth of a millimetre from the target (which
/// turns onto itself by multiples of 90 degrees), the placement is where
/// it was from the target: the same search, whatever the room's place.
const PLACEMENT_GRID_MM: f64 = 1e-3;

/// `pose` put on the grid of [`PLACEMENT_GRID_MM`] from `target`: it
/// moves by at most 0.7 µm.
fn snapped(pose: BasePose, target: &Point3<f64>) -> BasePose {
    let snap =
        |from: f64, at: f64| from + ((at - from) / PLACEMENT_GRID_MM).round() * PLACEMENT_GRID_MM;
    let p = pose.position_mm;
    BasePose {
        position_mm: Point3::new(snap(target.x, p.x), snap(target.y, p.y), p.z),
        ..pose
    }
}

fn same_place(a: &BasePose, b: &BasePose) -> bool {
    a.heading_rad == b.heading_rad && (a.position_mm - b.position_mm).xy().norm() < APART_MM
}

/// Where the arm would rather have the target, `hint`, moved if it must
/// be into the approach, keeping what it can: for a forward approach, its
/// sideways offset kept within the base's sides (`half_width_mm`) and
/// brought at least as far ahead as aside (a hand at rest beside the hip
/// puts the shoulder in line with the target); for a side one, out past
/// the base's side, and not behind.
fn toward(hint: Vector2<f64>, approach: Approach, half_width_mm: f64) -> Vector2<f64> {
    if approach.admits(&hint.push(0.0), half_width_mm) {
        return hint;
    }
    let inside = (half_width_mm - 2.0 * SIDE_SLACK_MM).max(0.0);
    match approach {
        Approach::Side => {
            let sign = if hint.y > 0.0 { 1.0 } else { -1.0 };
            let y = sign * hint.y.abs().max(half_width_mm);
            Vector2::new(hint.x.max(-y.abs()), y)
        }
        _ => {
            let y = hint.y.clamp(-inside, inside);
            Vector2::new(hint.x.max(y.abs()).max(1.0), y)
        }
    }
}

impl PreparedBase for PreparedMobile<'_> {
    fn reach(&self, query: &ReachQuery<'_>, solver: &dyn Solver) -> Placement {
        search(query, self.chain, self.candidates(query), solver)
            .unwrap_or_else(|| nowhere(self.room, self.chain))
    }

    fn reach_retrying_later(
        &self,
        query: &ReachQuery<'_>,
        solver: &dyn Solver,
    ) -> (Placement, Vec<Blocked>) {
        let candidates = self.candidates(query);
        let (kept, blocked) = search_retrying_later(query, self.chain, candidates, solver);
        (
            kept.unwrap_or_else(|| nowhere(self.room, self.chain)),
            blocked,
        )
    }

    /// The nearest points of each heading's region, and the hip points
    /// within the chain's reach of the target (where the search keeps its
    /// candidates) grown by the footprint's extent (what decides whether
    /// the base fits there) and by how far a sample's hand may be below or
    /// above the target.
    fn hips(&self, target_room_mm: &Point3<f64>, tolerance_mm: f64) -> Hips {
        let radius_mm = self.chain.reach_bound_mm()
            + tolerance_mm
            + self.mobile.footprint.extent_mm()
            + NEAR_HEIGHT_MM[NEAR_HEIGHT_MM.len() - 1][1];
        // Watch mode's key, worked out before the run (not metered).
        let unmetered = &Unbounded;
        let mut poses = self.nearest(target_room_mm, self.capability.centre_mm, unmetered);
        poses.extend(self.nearest(target_room_mm, self.capability.at_rest_mm, unmetered));
        Hips {
            poses,
            around: Some((*target_room_mm, radius_mm)),
        }
    }

    fn admits(&self, pose: &BasePose, target_room_mm: &Point3<f64>) -> bool {
        let approach = self.mobile.placing.approach;
        self.admitted(pose, target_room_mm)
            && approach.faces(pose.heading_rad, self.face(target_room_mm))
    }

    fn moved(&self, pose: &BasePose, by_mm: Vector2<f64>) -> Option<BasePose> {
        let (_, region) = self
            .regions()
            .find(|(heading, _)| *heading == pose.heading_rad)?;
        let to = pose.position_mm + by_mm.push(0.0);
        on_floor(region, to.x, to.y).then_some(BasePose {
            position_mm: to,
            heading_rad: pose.heading_rad,
        })
    }
}

/// How far outside `region` a base moved along the floor may be and still
/// stand on it: rounding. A placement nearest the preferred point lies on
/// the region's edge (a wheelchair's side against the shelves it reaches
/// into); moved along that edge, as a map's next point is tried from it, it
/// stays on the edge, where the base stands as well as it did.
const ON_EDGE_MM: f64 = 1e-6;

/// Whether a base may stand at `(x, y)` of `region`: inside it, or on its
/// edge (within [`ON_EDGE_MM`]).
fn on_floor(region: &Region, x: f64, y: f64) -> bool {
    region.contains(x, y)
        || region
            .nearest(Point::new(x, y))
            .is_some_and(|n| (n.x() - x).hypot(n.y() - y) <= ON_EDGE_MM)
}

/// What is reported when no candidate placement is left (a task whose
/// base fits nowhere is answered before it runs, so this is a last
/// resort): no distance, the neutral posture.
fn nowhere(room: &Room, chain: &Chain) -> Placement {
    Placement {
        pose: BasePose {
            position_mm: Point3::new(room.size_mm.x / 2.0, room.size_mm.y / 2.0, 0.0),
            heading_rad: 0.0,
        },
        solution: IkSolution::unsolved(chain),
        retried: false,
    }
}
