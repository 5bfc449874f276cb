//! A blocked reach walked in from the open side. Where a target's search
//! came within the tolerance only through the room (the board over a
//! low shelf, the back of a deep one, a wall), points further out are searched
//! for, every [`SEARCHED_EVERY`] steps of [`STEP_MM`] up to [`STEPS_OUT`]
//! steps, along the floor towards where the base stood (then along the
//! room's two axes and their diagonals, each way), until one is reached.
//! From there the walk comes back in a step at a time: each point from
//! the posture the step before reached, where its base stood and then
//! moved with the point (a plain descent, then one steering clear), else
//! searched as the target was with that placement as the last resort. It
//! is how a map reaches into a shelf from its front row (`map_grid.rs`),
//! done for one target: without it a reach called points NOT reachable
//! that the map of the same shelf reaches. Where it came within the
//! tolerance only through the chair or the person's own legs (a hand
//! through the wheel beside it), the walk goes up and then down instead:
//! a little higher the hand clears the wheel, and comes down beside it.
//! A walk makes at most [`MOST_SEARCHES`] searches.
//!
//! What it finds is a posture checked like any other (within the
//! tolerance, clear of the room, the person's body and base): it can only
//! turn a miss into a reach. The placement it keeps is the first that
//! reaches, not the most comfortable of all.

use std::cell::Cell;

use nalgebra::{Point3, Vector2, Vector3};

use crate::kinematics::Chain;
use crate::plugin::{Placement, PreparedBase, ReachQuery, Search, Solver};
use crate::scene::Blocker;

/// How far apart the points of the walk are: half a map's usual step.
const STEP_MM: f64 = 50.0;
/// How many steps out the walk looks for a point reached, at most.
const STEPS_OUT: usize = 4;
/// Every how many steps out a point is searched for (the steps between
/// are only walked back through).
const SEARCHED_EVERY: usize = 2;
/// The most searches one walk makes, over all its directions (the points
/// out and the steps back that descents do not reach): a search costs as
/// much as the target's own, where descents cost a few hundredths of it.
const MOST_SEARCHES: usize = 12;

/// `query` searched for from `prepared` by `solver` as a reach searches,
/// and where the search is blocked, walked in ([`WalkIn`]); as the retry,
/// only where the query has one (obstacles are checked, and
/// `blocked_retries` is not 0).
pub(super) fn reach_walking_in(
    prepared: &dyn PreparedBase,
    query: &ReachQuery<'_>,
    chain: &Chain,
    solver: &dyn Solver,
) -> Placement {
    let placement = prepared.reach(query, solver);
    if query.retry.is_none() || placement.solution.reaches(query.tolerance_mm) {
        return placement;
    }
    let walk = WalkIn {
        prepared,
        chain,
        solver,
        query,
        searches: Cell::new(0),
    };
    walk.reached(&placement).unwrap_or(placement)
}

/// The walk for one target.
struct WalkIn<'a> {
    prepared: &'a dyn PreparedBase,
    chain: &'a Chain,
    solver: &'a dyn Solver,
    /// The target's query, as its search was asked.
    query: &'a ReachQuery<'a>,
    /// How many searches the walk has made.
    searches: Cell<usize>,
}

impl WalkIn<'_> {
    /// The target reached by walking in from `blocked` (the failed
    /// search's kept placement), if it came within the tolerance through
    /// the room and the walk gets there.
    fn reached(&self, blocked: &Placement) -> Option<Placement> {
        let solution = &blocked.solution;
        if solution.distance_mm > self.query.tolerance_mm {
            return None;
        }
        let target = self.query.target_room_mm;
        match solution.collision.as_ref().map(|c| c.blocker) {
            Some(Blocker::Obstacle(_) | Blocker::Wall(_)) => {}
            // Through the chair or the person's own legs: the hand beside
            // a wheel or under the knees, a little higher or lower, where
            // it goes round them.
            Some(Blocker::Own(_)) => {
                let vertical = [Vector3::z(), -Vector3::z()];
                return vertical
                    .into_iter()
                    .find_map(|out| self.walked_along(target, out));
            }
            _ => return None,
        }
        let towards_base = (blocked.pose.position_mm - target).xy().try_normalize(1e-9);
        let d = std::f64::consts::FRAC_1_SQRT_2;
        let across = [
            (1.0, 0.0),
            (-1.0, 0.0),
            (0.0, 1.0),
            (0.0, -1.0),
            (d, d),
            (d, -d),
            (-d, d),
            (-d, -d),
        ]
        .map(|(x, y)| Vector2::new(x, y));
        towards_base
            .into_iter()
            .chain(across)
            .find_map(|out| self.walked_along(target, Vector3::new(out.x, out.y, 0.0)))
    }

    /// The target reached by walking in along `out` (a unit vector), if
    /// the walk gets there.
    fn walked_along(&self, target: Point3<f64>, out: Vector3<f64>) -> Option<Placement> {
        let along = |k: usize| target + out * (k as f64 * STEP_MM);
        // Not under the floor (a low target walked down).
        let (k, mut last) = (SEARCHED_EVERY..=STEPS_OUT)
            .step_by(SEARCHED_EVERY)
            .take_while(|&k| along(k).z >= 0.0)
            .find_map(|k| self.searched(along(k), k).map(|p| (k, p)))?;
        for j in (0..k).rev() {
            last = self.stepped(&last, along(j + 1), (along(j), j))?;
        }
        Some(last)
    }

    /// The query of the walk's point `point_mm`, `k` steps out: the
    /// first placement that reaches will do.
    fn query_at(&self, point_mm: Point3<f64>, k: usize) -> ReachQuery<'_> {
        ReachQuery {
            target_room_mm: point_mm,
            seed: self.query.seed ^ 0x5a1c_0000_0000_0000_u64.wrapping_add(k as u64),
            search: Search::FirstReaching,
            ..*self.query
        }
    }

    /// The walk's point `k` steps out, searched for as the target was but
    /// without the retry: a point out in the open is reached at once, and
    /// one that is not is no start for the walk.
    fn searched(&self, point_mm: Point3<f64>, k: usize) -> Option<Placement> {
        self.may_search()?;
        let query = ReachQuery {
            retry: None,
            ..self.query_at(point_mm, k)
        };
        let placement = self.prepared.reach(&query, self.solver);
        self.reaches(&placement).then_some(placement)
    }

    /// The walk's point `to_mm`, `k` steps out, one step in from `from_mm`
    /// where `last` reached: from `last`'s posture, where its base stood,
    /// then moved with the point.
    fn stepped(
        &self,
        last: &Placement,
        from_mm: Point3<f64>,
        (to_mm, k): (Point3<f64>, usize),
    ) -> Option<Placement> {
        let query = self.query_at(to_mm, k);
        let by_mm: Vector2<f64> = (to_mm - from_mm).xy();
        let moved = self.prepared.moved(&last.pose, by_mm);
        let start = &last.solution.q;
        let poses = [Some(last.pose), moved];
        let admitted = || {
            poses
                .into_iter()
                .flatten()
                .filter(|pose| self.prepared.admits(pose, &to_mm))
        };
        let reaches = |p: &Placement| self.reaches(p);
        let descended = admitted().find_map(|pose| {
            query.descended_from(self.chain, pose, self.solver, start, (true, true), &reaches)
        });
        descended.or_else(|| {
            // Searched as the target was, the step before's base and
            // posture its last resort.
            let pose = admitted().last()?;
            self.may_search()?;
            let query = ReachQuery {
                last_resort: Some((pose, start.as_slice())),
                ..query
            };
            let placement = self.prepared.reach(&query, self.solver);
            self.reaches(&placement).then_some(placement)
        })
    }

    /// Whether the walk may make one more search (counted), of
    /// [`MOST_SEARCHES`].
    fn may_search(&self) -> Option<()> {
        let made = self.searches.get();
        self.searches.set(made + 1);
        (made < MOST_SEARCHES).then_some(())
    }

    fn reaches(&self, placement: &Placement) -> bool {
        placement.solution.reaches(self.query.tolerance_mm)
    }
}
