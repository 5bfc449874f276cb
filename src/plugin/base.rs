//! Bases: where the person stands or sits. A configured base is prepared
//! for a room and a chain, then asked to reach: it chooses candidate
//! placements and asks a solver for the posture from each.

use std::cell::RefCell;
use std::fmt;
use std::hash::{Hash, Hasher};

use nalgebra::{Point3, Vector2};

use super::{Descents, IkProblem, Options, Plugin, SettingsError, Solver};
use crate::collision::{Obstacles, PlacedObstacles};
use crate::engine::{KeptProofs, SolvesFor};
use geo::MultiPolygon;

use crate::allowance::Allowance;
use crate::floor::{Footprint, Misfit, Shut};
use crate::kinematics::{Chain, Stance};
use crate::scene::{
    seed_in_base_frame, BasePose, Blocked, OwnBody, Physique, Placement, Room, Sweep,
};

/// How hard a base looks for a placement.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Search {
    /// Every candidate placement: the most comfortable that reaches.
    MostComfortable,
    /// Candidates in order of promise until one reaches (for maps).
    FirstReaching,
}

/// One reach question for a prepared base.
#[derive(Clone, Copy)]
pub struct ReachQuery<'a> {
    pub target_room_mm: Point3<f64>,
    pub tolerance_mm: f64,
    pub seed: u64,
    pub search: Search,
    /// The room's obstacles, when the posture must stay out of them (and
    /// out of the person's own body, `own`).
    pub obstacles: Option<&'a Obstacles>,
    pub own: &'a OwnBody,
    /// Where no placement reaches, a second solver to try again with.
    pub retry: Option<Retry<'a>>,
    /// Proofs that a placement cannot reach, kept across the queries of a
    /// map (for this chain and own body): a placement proved at the first
    /// look is not solved (`bases::search`). None: no placement is skipped,
    /// and the retry proves afresh.
    pub proofs: Option<&'a KeptProofs<'a>>,
    /// A placement and a posture to descend from after the base's own
    /// candidates, before the retry: a map's neighbour, where it was
    /// reached, moved as the point moved (`PreparedBase::moved`).
    pub last_resort: Option<(BasePose, &'a [f64])>,
    /// Whether a moving base also tries, last, the placements where the
    /// hand at rest would be at the target (a reach does; a map's point,
    /// reached from its neighbours, does not).
    pub from_rest: bool,
    /// The descents made for the queries before this one that it may
    /// reuse (a map's run of points); none: the search keeps its own.
    pub descents: Option<&'a RefCell<Descents>>,
    /// What the solves tell their work to.
    pub allowance: &'a dyn Allowance,
    /// Where the solves are kept for the task's next run, and taken from
    /// its last (watch mode), as this search's chain, obstacles and own
    /// body ask for them ([`crate::engine::KeptSolves::of`]).
    pub solves: Option<SolvesFor<'a>>,
}

/// The key a solve of `problem` at `pose` by `solver` from `start` (none:
/// the solver's own starts), searching as `search`, is kept by
/// ([`KeptSolves`]): none for a solver with no fingerprint.
fn solve_key(
    problem: &IkProblem<'_>,
    pose: BasePose,
    search: Search,
    solver: &dyn Solver,
    start: Option<&[f64]>,
) -> Option<u64> {
    let mut h = std::collections::hash_map::DefaultHasher::new();
    solver.fingerprint()?.hash(&mut h);
    (search == Search::FirstReaching).hash(&mut h);
    problem.seed.hash(&mut h);
    let target = problem.target_mm.coords.iter();
    let position = pose.position_mm.coords.iter();
    let numbers = [problem.tolerance_mm, pose.heading_rad];
    crate::scene::hash_bits(target.chain(position).chain(&numbers), &mut h);
    start.map(<[f64]>::len).hash(&mut h);
    crate::scene::hash_bits(start.into_iter().flatten(), &mut h);
    Some(h.finish())
}

/// A second try where the task's solver reaches from no placement (used
/// when obstacles are checked: a solver blind to them while it searches
/// can miss postures that go round them). From each blocked placement,
/// `solver` descends once from each of as many starts as it has, drawn
/// around the blocked posture (`solvers::Kicks`).
#[derive(Clone, Copy)]
pub struct Retry<'a> {
    pub solver: &'a dyn Solver,
    /// How many of the most promising blocked placements are tried again.
    pub placements: usize,
    /// How far a start may stray from the blocked posture, as a fraction
    /// of each joint's range.
    pub spread: f64,
}

impl<'a> ReachQuery<'a> {
    /// The query keeping its proofs in `proofs` (made for the chain it is
    /// asked of and its own body).
    pub fn keeping_proofs(self, proofs: &'a KeptProofs<'a>) -> Self {
        ReachQuery {
            proofs: Some(proofs),
            ..self
        }
    }

    /// The problem in the base frame of a base standing at `pose`.
    pub fn problem<'c>(&'c self, chain: &'c Chain, pose: BasePose) -> IkProblem<'c> {
        let target_mm = pose.to_base(&self.target_room_mm);
        IkProblem {
            chain,
            target_mm,
            tolerance_mm: self.tolerance_mm,
            seed: seed_in_base_frame(
                self.seed,
                &crate::kinematics::seed_point_mm(chain, &target_mm),
            ),
            obstacles: self.obstacles.map(|obstacles| PlacedObstacles {
                obstacles,
                own: self.own,
                base_pose: pose,
            }),
            allowance: self.allowance,
        }
    }

    /// Solve from `pose` (for a map, until a start reaches); the collision
    /// is checked here whatever the solver did, so that no solver can
    /// report a posture through a box.
    pub fn solve_at(&self, chain: &Chain, pose: BasePose, solver: &dyn Solver) -> Placement {
        self.solve_problem(&self.problem(chain, pose), pose, solver, None)
    }

    /// One solve from `pose` and posture `start` (a neighbouring point's on
    /// a map), its collision checked as `solve_at` checks it.
    pub fn solve_from_at(
        &self,
        chain: &Chain,
        pose: BasePose,
        solver: &dyn Solver,
        start: Vec<f64>,
    ) -> Placement {
        self.solve_problem(&self.problem(chain, pose), pose, solver, Some(start))
    }

    /// From posture `start` at `pose` (where a neighbouring point was
    /// reached): one descent of `solver` where `plain`, then, where
    /// `steering` and the query has a retry, one of the retry's solver,
    /// which steers clear (its placement marked retried); the first that
    /// `counts` takes.
    pub fn descended_from(
        &self,
        chain: &Chain,
        pose: BasePose,
        solver: &dyn Solver,
        start: &[f64],
        (plain, steering): (bool, bool),
        counts: &dyn Fn(&Placement) -> bool,
    ) -> Option<Placement> {
        if plain {
            let next = self.solve_from_at(chain, pose, solver, start.to_vec());
            if counts(&next) {
                return Some(next);
            }
        }
        let retry = self.retry.filter(|_| steering)?;
        let mut steered = self.solve_from_at(chain, pose, retry.solver, start.to_vec());
        steered.retried = true;
        counts(&steered).then_some(steered)
    }

    /// `problem` (this query's at `pose`, or one like it) solved from
    /// `start`, else from the solver's own starts, the collision checked.
    pub fn solve_problem(
        &self,
        problem: &IkProblem<'_>,
        pose: BasePose,
        solver: &dyn Solver,
        start: Option<Vec<f64>>,
    ) -> Placement {
        let kept = self.solves.and_then(|solves| {
            Some((
                solves,
                solve_key(problem, pose, self.search, solver, start.as_deref())?,
            ))
        });
        let search = self.search;
        let solve = move |problem: &IkProblem<'_>| match (start, search) {
            (Some(start), _) => solver.solve_from(problem, start),
            (None, Search::MostComfortable) => solver.solve(problem),
            (None, Search::FirstReaching) => solver.solve_until_reached(problem),
        };
        let mut solution = match kept {
            Some((solves, key)) => {
                solves.solve(key, problem.asked(), |asked| solve(&problem.asking(asked)))
            }
            None => solve(problem),
        };
        solution.collision = problem.collision_charged(&solution.q);
        Placement {
            pose,
            solution,
            retried: false,
        }
    }
}

/// How many placements one reach may try: `solved` with each of the
/// solver's starts, `seeded` with one descent from a posture known to
/// reach near the target, and `from_rest`, with each of the solver's
/// starts, where none of those reached and the query asks for them
/// (`ReachQuery::from_rest`).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct Tries {
    pub solved: u64,
    pub seeded: u64,
    pub from_rest: u64,
}

impl Tries {
    /// The tries of a search that does not ask for the placements from
    /// rest (a map's point).
    pub fn without_rest(self) -> Tries {
        Tries {
            from_rest: 0,
            ..self
        }
    }
}

/// A base configured from its option block: it decides where the person
/// stands (or sits).
pub trait Base: Send + Sync {
    /// The person's legs and the base's own parts (the chair's seat and
    /// wheels, the rollator's frame), in the base frame, which the person's
    /// links must stay out of.
    fn own_body(&self) -> &OwnBody;
    /// The height of the hip point above the floor, where it is the base's
    /// to say (`None`: a fixed base, which puts it where it is told).
    fn hip_height_mm(&self) -> Option<f64> {
        None
    }
    /// Whether the base can be anywhere in the room at all: a task whose
    /// base fits nowhere is answered "does not fit". Where working that
    /// out would take the run past what `allowance` allows, it is cut
    /// short and the run stopped.
    fn fit(&self, room: &Room, allowance: &dyn Allowance) -> Fit;
    /// [`Base::fit`] in `room`, which is `beside` with obstacles or doors
    /// taken away (as finding why a reach failed tries it), where
    /// `beside`'s has been found: the base fits wherever it fitted there,
    /// which need not be searched again.
    fn fit_beside(&self, room: &Room, _beside: &Room, allowance: &dyn Allowance) -> Fit {
        self.fit(room, allowance)
    }
    /// [`Base::fit`] in `room`, one of the rooms an element's moves make
    /// (`advise`), which `sweep` bounds: what the base gets to from the
    /// doors in every one of them is bounded by what it gets to in the
    /// sweep's two rooms, worked out once (the answer is `fit`'s).
    fn fit_in_sweep(&self, room: &Room, _sweep: &Sweep, allowance: &dyn Allowance) -> Fit {
        self.fit(room, allowance)
    }
    /// What working out where the base may stand in `room` cost, in units
    /// of work ([`Allowance`]), once [`Base::fit`] has: for a mobile
    /// base, the search at each heading for floor it fits on, the routes
    /// from the doors, and where it fits nowhere, the search for how much
    /// smaller it would fit. The run charges it to the first task
    /// of the scenario that places the person in the room.
    fn floor_work(&self, _room: &Room) -> u64 {
        0
    }
    /// What working out where the base may stand in `room`, a room the
    /// task's `beside` with something taken away, adds to what `beside`'s
    /// cost (nothing where the base's floor is the same in both, as when a
    /// wall cabinet is taken away), once [`Base::fit`] has.
    fn floor_work_beside(&self, room: &Room, _beside: &Room) -> u64 {
        self.floor_work(room)
    }
    /// What the base's floor in `room` depends on, hashed (none: it has
    /// no floor): two rooms with the same key have the same floor, and
    /// its work is done once ([`Base::floor_work`]).
    fn floor_key(&self, _room: &Room) -> Option<u64> {
        None
    }
    /// Whether the scenario puts the base outside the room, which the
    /// checker refuses: asked before the run, so cheaply (no floor is
    /// worked out).
    fn outside(&self, _room: &Room) -> bool {
        false
    }
    /// What getting ready for reaches with `chain` costs beyond where the
    /// base fits ([`Base::floor_work`]), in units of work: a mobile
    /// base's capability map of the person. The run charges it to the
    /// first task by the person with those effectors.
    fn prepare_work(&self, _chain: &Chain) -> u64 {
        0
    }
    /// Get ready for reaches in `room` with `chain` (caching what does not
    /// depend on the target, such as where the base fits, in the memo of
    /// `allowance`, which is not charged: [`Base::prepare_work`] is).
    fn prepare<'a>(
        &'a self,
        room: &'a Room,
        chain: &'a Chain,
        allowance: &dyn Allowance,
    ) -> Box<dyn PreparedBase + 'a>;
    /// The most candidate placements one reach may try (what the limit on
    /// solver starts counts).
    fn placements(&self) -> Tries {
        Tries {
            solved: 1,
            seeded: 0,
            from_rest: 0,
        }
    }
    /// What a base that moves keeps off the floor's obstacles (none for a
    /// fixed base).
    fn footprint(&self) -> Option<&Footprint> {
        None
    }
    /// Whether the base reads the room only through its floor (what
    /// `Room::hash_floor` holds for its footprint's bands) and the faces
    /// of boxes within 50 mm of a target (where an approach is measured):
    /// then watch mode may keep a task's answer when an obstacle the
    /// task's questions did not come near moves a little. False (the
    /// default) for a base that may read more.
    fn reads_room_through_floor(&self) -> bool {
        false
    }
    /// The same base free of the zone it is kept to, if it has one (to
    /// learn whether the zone is what keeps a target out of reach).
    fn unzoned(&self) -> Option<Box<dyn Base>> {
        None
    }
    /// Join the groups (of a population's members) whose footprints
    /// `groups` bound, the widest first: a base that moves then shares
    /// the routes from a room's doors with each group's other members,
    /// its answers its own (`floor/shared_routes.rs`). Nothing for a base
    /// that does not move.
    fn join_floor_groups(&self, _groups: &[std::sync::Arc<crate::floor::FloorGroup>]) {}
    /// Where the room has doors, the obstacles (boxes, then meshes, by
    /// index) that close in the floor the base, facing `heading_rad` (one
    /// of its headings) with its hip at `hip_mm`, cannot get to from a
    /// door, nearest first; none where it can, where the room has no door
    /// or the base does not move.
    fn enclosing(&self, _room: &Room, _heading_rad: f64, _hip_mm: (f64, f64)) -> Vec<usize> {
        Vec::new()
    }
    /// Where the room has doors, the floor where the hip point can be at
    /// `heading_rad` (one of the base's headings) having come from a door
    /// (for pictures); none where the room has no door or the base does
    /// not move.
    fn reached_floor(&self, _room: &Room, _heading_rad: f64) -> Option<MultiPolygon<f64>> {
        None
    }
}

/// Whether a base can be anywhere in a room.
#[derive(Clone, Debug, PartialEq)]
pub enum Fit {
    Fits,
    /// The scenario puts it outside the room (a fixed base's position): a
    /// mistake in the input.
    Outside,
    /// It fits nowhere, by this much: the person's answer.
    Nowhere(Misfit),
    /// It fits somewhere, but cannot get there from any of the room's
    /// doors: the person's answer.
    Shut(Shut),
}

/// A base ready for one room and one chain.
pub trait PreparedBase: Send + Sync {
    /// Place the base for the target and ask the solver for the posture.
    fn reach(&self, query: &ReachQuery<'_>, solver: &dyn Solver) -> Placement;
    /// As [`PreparedBase::reach`], but where no placement reaches, the
    /// retry is left to the caller: the placement, and the blocked
    /// placements a retry (`bases::search::retry`) would start from. By
    /// default `reach`, retry and all, and none left.
    fn reach_retrying_later(
        &self,
        query: &ReachQuery<'_>,
        solver: &dyn Solver,
    ) -> (Placement, Vec<Blocked>) {
        (self.reach(query, solver), Vec::new())
    }
    /// Where a reach of `target_room_mm`, counted within `tolerance_mm`,
    /// may put the hip point (what a cache compares to know that a change
    /// of the room leaves the answer alone).
    fn hips(&self, target_room_mm: &Point3<f64>, tolerance_mm: f64) -> Hips;
    /// Whether a base at `pose` may reach `target_room_mm` from there (a
    /// map's next point tried from where the last one was reached): a base
    /// told to approach from the side may not face it.
    fn admits(&self, _pose: &BasePose, _target_room_mm: &Point3<f64>) -> bool {
        true
    }
    /// `pose` moved along the floor by `by_mm`, its heading kept, if the
    /// base may stand there (a map's next point tried from where the last
    /// one was reached, moved as the point moved); none for a base that
    /// does not move.
    fn moved(&self, _pose: &BasePose, _by_mm: Vector2<f64>) -> Option<BasePose> {
        None
    }
}

/// Where a base may put the hip point for one target: at these poses, and
/// anywhere within `around`'s radius of its point (a base that searches the
/// floor: the floor's obstacles within that radius decide where it fits,
/// and the room's, within reach of it, what it reaches).
#[derive(Clone, Debug, Default, PartialEq)]
pub struct Hips {
    pub poses: Vec<BasePose>,
    pub around: Option<(Point3<f64>, f64)>,
}

pub trait BasePlugin: Plugin {
    /// The base that validated `options` configure for a person of
    /// `physique` (their legs, posture and upright trunk).
    fn build(&self, options: &Options, physique: &Physique) -> Result<Box<dyn Base>, BaseError>;
}

/// Why a base cannot be built for a person.
#[derive(Clone, Debug, PartialEq)]
pub enum BaseError {
    /// Its options cannot be used.
    Settings(SettingsError),
    /// The person does not suit it: a mannequin that stands in a
    /// wheelchair, or a standing base without a hip height for a mannequin
    /// without legs.
    Unfit(String),
}

impl fmt::Display for BaseError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            BaseError::Settings(e) => e.fmt(f),
            BaseError::Unfit(reason) => f.write_str(reason),
        }
    }
}

impl std::error::Error for BaseError {}

impl From<SettingsError> for BaseError {
    fn from(e: SettingsError) -> Self {
        BaseError::Settings(e)
    }
}

impl BaseError {
    /// The error for a mannequin whose declared posture is not the base's.
    pub fn posture(base: &str, declared: Stance, needed: Stance) -> Self {
        BaseError::Unfit(format!(
            "the mannequin is {}, and a {base} needs one {}: write `{}` after the mannequin's name (`mannequin NAME {}`), or give the person a base for a {} person",
            declared.word(),
            needed.word(),
            needed.word(),
            needed.word(),
            declared.word()
        ))
    }
}
