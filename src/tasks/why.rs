//! Why a reach failed, found by searching again (the corrections of issue
//! 14), with the task's seed and placements, each time without one thing
//! that may have stopped it:
//!
//! - no candidate placement at all: the approach or heading allows none;
//! - without the room's obstacles in the arm's way: if the hand then
//!   reaches, each obstacle that posture met (the first three) and the two
//!   nearest the target are removed alone, and every one whose removal
//!   lets the hand reach is named (else all, together);
//! - without the person's own body too: the part whose removal alone lets
//!   it reach is named;
//! - in the room emptied of furniture, floor and all: the obstacles
//!   nearest the target whose removal lets the base come close enough;
//! - with every joint's limits widened by [`WIDENED_DEG`]: the joints that
//!   go beyond are named;
//! - else out of reach, with the closest the hand comes in the empty room.
//!
//! A search without a constraint may find a posture that keeps it after
//! all (a seed that the first search did not try): then the target is
//! reachable, and that placement is the answer.

use nalgebra::Point3;

use super::common::Reaching;
use crate::allowance::Allowance;
use crate::collision::{obstacle_bounds, Obstacles, PlacedObstacles, TOUCH_MARGIN_MM};
use crate::kinematics::{Chain, JointKind};
use crate::plugin::{Base, Placement, ReachQuery, Search, TaskInput};
use crate::report::{mm, Why, WIDENED_DEG};
use crate::scene::{Blocker, OwnBody, Room};

/// How many of the room's obstacles a failed reach met are each tried
/// without.
const TRIED_WITHOUT: usize = 3;
/// How many of the obstacles nearest the target are tried without as
/// well, where the room is in the way.
const NEAREST: usize = 2;

/// A reach that failed, and what it was asked.
pub(super) struct Failed<'a> {
    pub reaching: &'a Reaching,
    pub input: &'a TaskInput<'a>,
    pub chain: &'a Chain,
    pub target_mm: Point3<f64>,
    pub seed: u64,
    pub obstacles: Option<&'a Obstacles>,
    /// The failed search's kept placement.
    pub placement: &'a Placement,
}

/// What searching again found.
pub(super) enum Found {
    /// What stopped it: the room's obstacles alone; or the person's own
    /// body, the joints' limits, or both (each alone would let the hand
    /// reach); or neither (out of reach).
    Why(Vec<Why>),
    /// A posture that keeps every constraint after all: the target is
    /// reachable from this placement.
    Reached(Placement),
}

impl Failed<'_> {
    pub fn why(&self) -> Found {
        if self.placement.solution.distance_mm.is_infinite() {
            // The base found no candidate placement at all.
            return Found::Why(vec![Why::NoApproach]);
        }
        let own = self.input.base.own_body();
        if let Some(why) = self.cut_off(own) {
            return Found::Why(vec![why]);
        }
        if self.zone_keeps_it_away(own) {
            return Found::Why(vec![Why::Zone]);
        }
        let mut closest_mm = self.placement.solution.distance_mm;
        let mut found = Vec::new();
        // Only a base that moves is kept away: a fixed base stands where
        // it is told, whatever the furniture (its search with the room
        // emptied is the search without obstacles again).
        let moves = self.input.base.footprint().is_some();
        if let Some(obstacles) = self.obstacles {
            let no_room = obstacles.none_of();
            let free = self.solve(self.chain, Some(&no_room), own);
            if self.reaches(&free) {
                return self.blocked_by_room(obstacles, &free);
            }
            let bare = self.solve(self.chain, None, &OwnBody::default());
            if self.reaches(&bare) {
                // The person's own body or chair is the cause only where the
                // placement is not the limit: where the base, the furniture
                // off the floor, comes close enough for the hand to reach
                // with the body as it is, the furniture keeps it away (else
                // the hand reaching "without the backrest" leans back
                // through where the backrest was).
                let closer = moves.then(|| self.solve_emptied(own));
                if let Some(closer) = closer.filter(|c| self.reaches(c)) {
                    return Found::Why(vec![self.kept_away(obstacles, &closer)]);
                }
                found.push(self.blocked_by_body(&no_room, &bare));
            } else {
                let roomy = moves.then(|| self.solve_emptied(&OwnBody::default()));
                if let Some(roomy) = &roomy {
                    if self.reaches(roomy) {
                        return Found::Why(vec![self.kept_away(obstacles, roomy)]);
                    }
                    closest_mm = roomy.solution.distance_mm;
                }
            }
        }
        let widened = widen(self.chain);
        let loose = self.solve(&widened, self.obstacles, own);
        if self.reaches(&loose) {
            let beyond = beyond_limits(self.chain, &loose.solution.q);
            if beyond.is_empty() && self.valid(&loose) {
                return Found::Reached(loose);
            }
            if !beyond.is_empty() {
                let q = &loose.solution.q;
                let coupled = self
                    .chain
                    .couplings
                    .iter()
                    .any(|c| !c.admits(&self.chain.joints, q));
                found.push(Why::JointLimits {
                    joints: beyond,
                    coupled,
                });
            }
        }
        if found.is_empty() {
            found.push(Why::OutOfReach {
                closest_mm: mm(closest_mm),
                below_the_knees: self.below_the_knees(own),
            });
        }
        Found::Why(found)
    }

    /// Whether the person stands and the target is lower than their knees
    /// (the floor their legs put below the hip point).
    fn below_the_knees(&self, own: &OwnBody) -> bool {
        let Some(balance) = own.balance.as_ref() else {
            return false;
        };
        let legs = balance.legs();
        let floor_mm = self.placement.pose.position_mm.z - legs.hip_height_mm;
        self.target_mm.z < floor_mm + legs.knee_height_mm
    }

    /// Where the room has doors and the base moves: whether the target is
    /// reached from floor the base cannot get to (the search again,
    /// every placement allowed), and what closes that floor in.
    fn cut_off(&self, own: &OwnBody) -> Option<Why> {
        let room = self.input.room;
        // Only a base that moves is cut off.
        self.input.base.footprint()?;
        if room.doors.is_empty() {
            return None;
        }
        let open = Room {
            name: format!("{}\u{0}without doors", room.name),
            doors: Vec::new(),
            ..room.clone()
        };
        let placed = self.solve_in(&open, self.chain, self.obstacles, own);
        if !self.valid(&placed) {
            return None;
        }
        let hip = (placed.pose.position_mm.x, placed.pose.position_mm.y);
        let names = (self.input.base)
            .enclosing(room, placed.pose.heading_rad, hip)
            .into_iter()
            .map(|i| room.obstacle_name(i).to_string())
            .collect();
        Some(Why::CannotGetThere { names })
    }

    /// Whether the base, kept to a zone, reaches the target from outside
    /// it: the same search with the zone left out, everything else kept.
    fn zone_keeps_it_away(&self, own: &OwnBody) -> bool {
        let Some(free) = self.input.base.unzoned() else {
            return false;
        };
        let query = self.query(self.chain, self.obstacles, own);
        charge_floor(free.as_ref(), self.input.room, None, self.input.allowance);
        let placed = free
            .prepare(self.input.room, self.chain, self.input.allowance)
            .reach(&query, self.reaching.solver.as_ref());
        self.valid(&placed)
    }

    /// The person's own body is in the way (`bare` reached without it and
    /// the room): which of its parts, each tried without alone (a part of
    /// the moving arm itself cannot be, and is named as met).
    fn blocked_by_body(&self, no_room: &Obstacles, bare: &Placement) -> Why {
        let own = self.input.base.own_body();
        let placed = PlacedObstacles {
            obstacles: no_room,
            own,
            base_pose: bare.pose,
        };
        let met = placed.posture_hits(self.chain, &bare.solution.q, self.tolerance());
        for &blocker in met.iter().take(TRIED_WITHOUT) {
            let Blocker::Own(i) = blocker else { continue };
            let mut solids = own.solids.clone();
            solids.remove(i);
            let without = OwnBody::new(solids, own.pelvis_mm);
            let tried = self.solve(self.chain, Some(no_room), &without);
            if self.reaches(&tried) {
                return Why::Body {
                    names: vec![self.name(blocker)],
                };
            }
        }
        Why::Body {
            names: met.into_iter().map(|b| self.name(b)).collect(),
        }
    }

    /// The room is in the way (`free` reached without it): which of the
    /// obstacles and sides it met.
    fn blocked_by_room(&self, obstacles: &Obstacles, free: &Placement) -> Found {
        if self.valid(free) {
            return Found::Reached(free.clone());
        }
        let own = self.input.base.own_body();
        let placed = PlacedObstacles {
            obstacles,
            own,
            base_pose: free.pose,
        };
        let mut met: Vec<Blocker> = placed
            .posture_hits(self.chain, &free.solution.q, self.tolerance())
            .into_iter()
            .filter(|b| matches!(b, Blocker::Obstacle(_) | Blocker::Wall(_)))
            .take(TRIED_WITHOUT)
            .collect();
        // The obstacles nearest the target too (a cabinet's door over the
        // board a cup stands on), which the free posture need not meet.
        for (_, i) in self.nearest_obstacles(NEAREST) {
            if !met.contains(&Blocker::Obstacle(i)) {
                met.push(Blocker::Obstacle(i));
            }
        }
        // Every one whose removal alone lets the hand reach: each is a
        // change that would do.
        let mut enough = Vec::new();
        for &blocker in &met {
            let without = obstacles.without(&[blocker]);
            let tried = self.solve(self.chain, Some(&without), own);
            if self.reaches(&tried) {
                if self.valid(&tried) {
                    return Found::Reached(tried);
                }
                enough.push(self.name(blocker));
            }
        }
        if !enough.is_empty() {
            return Found::Why(vec![Why::Obstacles {
                names: enough,
                together: false,
            }]);
        }
        let together = met.len() > 1;
        let names = met.into_iter().map(|b| self.name(b)).collect();
        Found::Why(vec![Why::Obstacles { names, together }])
    }

    /// The furniture keeps the base away (it reached with the room
    /// emptied, `roomy`): which obstacles, each removed alone from the
    /// floor and the arm's way, let the hand reach. Tried are the
    /// obstacles nearest the target that the footprint meets (what keeps
    /// the base back), the two nearest of all, and those `roomy`'s posture
    /// would pass through in the room as it is (what stands in the arm's
    /// way from nearer); where none alone does, all of them, together.
    fn kept_away(&self, obstacles: &Obstacles, roomy: &Placement) -> Why {
        let room = self.input.room;
        let own = self.input.base.own_body();
        let placed = PlacedObstacles {
            obstacles,
            own,
            base_pose: roomy.pose,
        };
        let hits = placed.posture_hits(self.chain, &roomy.solution.q, self.tolerance());
        let in_the_way = hits
            .into_iter()
            .take(TRIED_WITHOUT)
            .filter_map(|b| match b {
                Blocker::Obstacle(i) => Some(i),
                _ => None,
            });
        let near = self.nearest_floor_obstacles(TRIED_WITHOUT).into_iter();
        let near = near.chain(self.nearest_obstacles(NEAREST)).map(|(_, i)| i);
        let mut tried: Vec<usize> = Vec::new();
        for i in near.chain(in_the_way) {
            if !tried.contains(&i) {
                tried.push(i);
            }
        }
        let alone_enough = |i: usize| {
            let without = self.without_furniture(&[i]);
            // The obstacles by their indices in the room as it is (what
            // they touch is recorded by those).
            let obstacles = obstacles.without(&[Blocker::Obstacle(i)]);
            self.reaches(&self.solve_in(&without, self.chain, Some(&obstacles), own))
        };
        let enough: Vec<usize> = tried.iter().copied().filter(|&i| alone_enough(i)).collect();
        let together = enough.is_empty();
        let names = if together { tried } else { enough };
        Why::KeptAway {
            names: names
                .into_iter()
                .map(|i| room.obstacle_name(i).to_string())
                .collect(),
            together,
        }
    }

    /// The `n` obstacles of the room nearest the target, nearest first,
    /// with their distances.
    fn nearest_obstacles(&self, n: usize) -> Vec<(f64, usize)> {
        self.nearest_of(n, |_| true)
    }

    /// The `n` obstacles nearest the target that can keep the base away:
    /// those that come within the heights of its footprint (a wall
    /// cabinet over a counter keeps no chair back; the counter does).
    /// Meshes all count.
    fn nearest_floor_obstacles(&self, n: usize) -> Vec<(f64, usize)> {
        let bands = self
            .input
            .base
            .footprint()
            .map(|f| f.bands_mm())
            .unwrap_or_default();
        let room = self.input.room;
        self.nearest_of(n, |i| {
            room.boxes
                .get(i)
                .is_none_or(|b| bands.iter().any(|&band| b.meets_band(band)))
        })
    }

    /// The `n` obstacles `counts` takes, nearest the target first.
    fn nearest_of(&self, n: usize, counts: impl Fn(usize) -> bool) -> Vec<(f64, usize)> {
        let room = self.input.room;
        let mut near: Vec<(f64, usize)> = (0..room.boxes.len() + room.meshes.len())
            .filter(|&i| counts(i))
            .map(|i| (distance_to_obstacle(room, i, &self.target_mm), i))
            .collect();
        near.sort_by(|a, b| a.0.total_cmp(&b.0).then(a.1.cmp(&b.1)));
        near.truncate(n);
        self.note_nearest(&near, n, counts);
        near
    }

    /// For watch mode's cache: the obstacles were ranked (the answer may
    /// name one however far), and each obstacle `counts` takes that a move
    /// within the touch margin could bring among the `n` nearest (`near`)
    /// counts as touched. One whose bounds are farther than the farthest
    /// of them by twice the margin stays farther when its bounds move
    /// within the margin (by at most the margin times the root of three).
    fn note_nearest(&self, near: &[(f64, usize)], n: usize, counts: impl Fn(usize) -> bool) {
        let Some(touched) = self.input.touched else {
            return;
        };
        touched.mark_ranked();
        let farthest_mm = match near.last() {
            Some(&(d, _)) if near.len() == n => d,
            _ => f64::INFINITY,
        };
        let bounds = obstacle_bounds(self.input.room);
        for (i, b) in bounds.iter().enumerate().filter(|(i, _)| counts(*i)) {
            let close = b.is_none_or(|[lo, hi]| {
                let nearest = self.target_mm.sup(&lo).inf(&hi);
                (nearest - self.target_mm).norm() <= farthest_mm + 2.0 * TOUCH_MARGIN_MM
            });
            if close {
                touched.mark(i);
            }
        }
    }

    /// The task's room without the obstacles `removed` (all of them when
    /// empty), under a name of its own (a base keeps where it fits by
    /// room name).
    /// The search again with the room's furniture taken away (walls and
    /// doors kept) and no obstacle checked, the body and chair as `own`:
    /// whether the base, coming closer, lets the hand reach.
    fn solve_emptied(&self, own: &OwnBody) -> Placement {
        self.solve_in(&self.without_furniture(&[]), self.chain, None, own)
    }

    fn without_furniture(&self, removed: &[usize]) -> Room {
        let room = self.input.room;
        let all = removed.is_empty();
        let boxes = room.boxes.len();
        let keep = |i: usize| !all && !removed.contains(&i);
        let mut name = format!("{}\u{0}without", room.name);
        for &i in removed {
            name.push_str(&format!(" {i}"));
        }
        Room {
            name,
            boxes: (room.boxes.iter().enumerate())
                .filter(|(i, _)| keep(*i))
                .map(|(_, b)| b.clone())
                .collect(),
            meshes: (room.meshes.iter().enumerate())
                .filter(|(k, _)| keep(boxes + k))
                .map(|(_, m)| m.clone())
                .collect(),
            ..room.clone()
        }
    }

    /// The search the task made, with `chain`, `obstacles` and `own`.
    fn solve(&self, chain: &Chain, obstacles: Option<&Obstacles>, own: &OwnBody) -> Placement {
        self.solve_in(self.input.room, chain, obstacles, own)
    }

    /// The search the task made, in `room` (where the base fits).
    fn solve_in(
        &self,
        room: &Room,
        chain: &Chain,
        obstacles: Option<&Obstacles>,
        own: &OwnBody,
    ) -> Placement {
        let query = self.query(chain, obstacles, own);
        charge_floor(
            self.input.base,
            room,
            Some(self.input.room),
            self.input.allowance,
        );
        self.input
            .base
            .prepare(room, chain, self.input.allowance)
            .reach(&query, self.reaching.solver.as_ref())
    }

    /// The task's search again, with `chain`, `obstacles` and `own`: its
    /// solves kept for the task's next run as those ask for them, but not
    /// the placements sampled (the base may be prepared otherwise: in the
    /// room without doors or furniture, or without its zone).
    fn query<'q>(
        &'q self,
        chain: &Chain,
        obstacles: Option<&'q Obstacles>,
        own: &'q OwnBody,
    ) -> ReachQuery<'q> {
        let solves = (self.input.solves).map(|s| s.of(chain, obstacles, own).without_placements());
        ReachQuery {
            solves,
            ..self.reaching.query(
                self.target_mm,
                self.seed,
                Search::MostComfortable,
                obstacles,
                own,
                self.input.allowance,
            )
        }
    }

    fn tolerance(&self) -> f64 {
        self.reaching.common.tolerance_mm
    }

    fn reaches(&self, p: &Placement) -> bool {
        p.solution.reaches(self.tolerance())
    }

    /// Whether `p` keeps every constraint of the task: the chain's own
    /// limits, and clear of the room and the person's body.
    fn valid(&self, p: &Placement) -> bool {
        let within = beyond_limits(self.chain, &p.solution.q).is_empty();
        let clear = self.obstacles.is_none_or(|obstacles| {
            let placed = PlacedObstacles {
                obstacles,
                own: self.input.base.own_body(),
                base_pose: p.pose,
            };
            placed
                .posture_hit(self.chain, &p.solution.q, self.tolerance())
                .is_none()
        });
        within && clear && p.solution.distance_mm <= self.tolerance()
    }

    fn name(&self, b: Blocker) -> String {
        self.input.names(self.chain).blocker(b)
    }
}

/// How far `p` is from the room's obstacle `i` (a mesh: from its bounds).
fn distance_to_obstacle(room: &Room, i: usize, p: &Point3<f64>) -> f64 {
    match room.boxes.get(i) {
        Some(b) => b.cuboid().distance_to_segment(p, p),
        None => {
            let mesh = &room.meshes[i - room.boxes.len()];
            let Some([lo, hi]) = mesh.vertex_bounds() else {
                return f64::INFINITY;
            };
            let outside = (lo - p).sup(&(p - hi)).sup(&nalgebra::Vector3::zeros());
            outside.norm()
        }
    }
}

/// `chain` with each revolute joint's limits [`WIDENED_DEG`] wider on
/// either side, and no coupling.
fn widen(chain: &Chain) -> Chain {
    let mut wide = chain.clone();
    wide.couplings.clear();
    let by = WIDENED_DEG.to_radians();
    for joint in &mut wide.joints {
        if joint.kind == JointKind::Revolute {
            joint.min -= by;
            joint.max += by;
        }
    }
    wide
}

/// The joints of `chain` whose value in `q` lies beyond their limits, or
/// in a coupling `q` breaks.
fn beyond_limits(chain: &Chain, q: &[f64]) -> Vec<String> {
    chain
        .beyond_limits(q)
        .into_iter()
        .map(|i| chain.joints[i].name.clone())
        .collect()
}

/// Work out where `base` may stand in `room` (a room the search is made
/// in again without something, `beside` the task's own where only the
/// base is the same), charging `meter` what that costs, kept or not:
/// the search's floor counts towards the run's work as the task's own
/// does, where the base's floor differs from the task's (and only for
/// what it searches afresh: wherever it fitted there, it fits here).
fn charge_floor(base: &dyn Base, room: &Room, beside: Option<&Room>, allowance: &dyn Allowance) {
    let work = match beside {
        Some(beside) => {
            base.fit_beside(room, beside, allowance);
            base.floor_work_beside(room, beside)
        }
        None => {
            base.fit(room, allowance);
            base.floor_work(room)
        }
    };
    allowance.spend(work);
}
